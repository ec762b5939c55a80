//! The constructions against exact rational oracles written from their definitions, on
//! hostile triangles and lines: the certified path and the exact path each within the stated
//! error, and the range decided exactly.

use super::*;
use crate::geometry::{orient2d, Orientation};
use num_bigint::BigInt as Z;
use num_rational::BigRational as Q;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point2 {
    Point2::new(x, y)
}

fn q(v: f64) -> Q {
    Q::from_float(v).expect("finite")
}

fn pow2q(e: i32) -> Q {
    let one = Z::one();
    if e >= 0 {
        Q::from_integer(one << e as usize)
    } else {
        Q::new(one.clone(), one << (-e) as usize)
    }
}

/// The exact value of a `WideFloat` coordinate: the double itself in range, else its
/// 17-digit decimal text (whose own rounding, below 2^-53 relative, the check allows for).
fn value(w: WideFloat) -> Q {
    if let Some(v) = w.to_f64() {
        return q(v);
    }
    let text = w.to_string();
    let (mantissa, exponent) = text.split_once('e').expect("scientific notation");
    let negative = mantissa.starts_with('-');
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let fraction = mantissa.split_once('.').map_or(0, |(_, f)| f.len());
    let ten = |k: i64| num_traits::pow(Q::from_integer(Z::from(10)), k.unsigned_abs() as usize);
    let e = exponent.parse::<i64>().unwrap() - fraction as i64;
    let m = Q::from_integer(digits.parse::<Z>().unwrap());
    let v = if e >= 0 { m * ten(e) } else { m / ten(e) };
    if negative {
        -v
    } else {
        v
    }
}

/// Panics unless `got` is within `relative · max(|x|, |y|) + 2^-1075` of the exact `(x, y)`
/// and beyond the range exactly when a coordinate is at least `2^1024 − 2^970`, where the
/// beyond-range coordinates are at least 2^1024 (never printed as a finite double).
fn check(got: ConstructedPoint, (x, y): &(Q, Q), relative: &Q, what: &str) {
    let threshold = pow2q(1024) - pow2q(970);
    let beyond = x.abs() >= threshold || y.abs() >= threshold;
    assert_eq!(got.is_beyond_range(), beyond, "{what}: {got:?}");
    let m = x.abs().max(y.abs());
    let [gx, gy] = got.wide();
    for (g, e) in [(gx, x), (gy, y)] {
        let decimal = if g.to_f64().is_none() {
            e.abs() * pow2q(-53)
        } else {
            Q::zero()
        };
        let bound = relative * &m + pow2q(-1075) + decimal;
        let err = (value(g) - e).abs();
        assert!(err <= bound, "{what}: {got:?} off by {err} > {bound}");
    }
    if got.is_beyond_range() {
        let big = WideFloat::scaled(1.0, 1024);
        for (g, e) in [(gx, x), (gy, y)] {
            assert_eq!(g.abs() >= big, e.abs() >= threshold, "{what}: {got:?}");
        }
    }
}

fn stated() -> Q {
    q(ConstructedPoint::RELATIVE_ERROR)
}

/// The exact path's own bound: 1.5 units of 2^-52, written as 3 · 2^-53 and a little more
/// for the products of the relative errors.
fn exact_path() -> Q {
    q(3.01 * f64::EPSILON / 2.0)
}

fn circumcentre_q(a: Point2, b: Point2, c: Point2) -> (Q, Q) {
    let (ax, ay) = (q(a.x), q(a.y));
    let (bx, by) = (q(b.x) - &ax, q(b.y) - &ay);
    let (cx, cy) = (q(c.x) - &ax, q(c.y) - &ay);
    let lb = &bx * &bx + &by * &by;
    let lc = &cx * &cx + &cy * &cy;
    let d = (&bx * &cy - &by * &cx) * Q::from_integer(Z::from(2));
    (
        ax + (&cy * &lb - &by * &lc) / &d,
        ay + (&bx * &lc - &cx * &lb) / &d,
    )
}

fn corner_q(a: Point2, b: Point2, p: Point2, r: Point2) -> (Q, Q) {
    let (ax, ay) = (q(a.x), q(a.y));
    let (gx, gy) = (q(b.x) - &ax, q(b.y) - &ay);
    let along = (q(p.x) - &ax) * &gx + (q(p.y) - &ay) * &gy;
    let across = &gx * (q(r.y) - &ay) - &gy * (q(r.x) - &ax);
    let n = &gx * &gx + &gy * &gy;
    (
        ax + (&along * &gx - &across * &gy) / &n,
        ay + (&along * &gy + &across * &gx) / &n,
    )
}

fn crossing_q(p: Point2, r: Point2, s: Point2, w: Point2) -> (Q, Q) {
    let (px, py) = (q(p.x), q(p.y));
    let (gx, gy) = (q(r.x) - &px, q(r.y) - &py);
    let (ux, uy) = (q(w.x) - q(s.x), q(w.y) - q(s.y));
    // t = ((m − p) · u) / (g · u) for the midpoint m of s and w.
    let two = Q::from_integer(Z::from(2));
    let (mx, my) = ((q(s.x) + q(w.x)) / &two, (q(s.y) + q(w.y)) / &two);
    let t = ((mx - &px) * &ux + (my - &py) * &uy) / (&gx * &ux + &gy * &uy);
    (px + &t * gx, py + t * gy)
}

/// A hostile coordinate: magnitudes from subnormal to `f64::MAX`, with random mantissas.
fn coordinate() -> impl Strategy<Value = f64> {
    let exponents = vec![
        -1074, -1070, -1040, -1022, -1000, -600, -300, -52, 0, 1, 52, 300, 600, 1000, 1020, 1023,
    ];
    prop_oneof![
        (
            any::<bool>(),
            1u64..(1 << 53),
            prop::sample::select(exponents)
        )
            .prop_map(|(negative, m, e)| {
                let v = crate::geometry::extended::scale_by_pow2(m as f64, e - 52);
                let v = if v.is_finite() { v } else { f64::MAX };
                if negative {
                    -v
                } else {
                    v
                }
            }),
        -4.0..4.0f64,
        prop::sample::select(vec![
            0.0,
            5e-324,
            -5e-324,
            f64::MAX,
            -f64::MAX,
            1e300,
            -1e-300
        ]),
        any::<f64>().prop_filter("finite", |v| v.is_finite()),
    ]
}

fn point() -> impl Strategy<Value = Point2> {
    (coordinate(), coordinate()).prop_map(|(x, y)| p(x, y))
}

/// `v` moved by `k` units in the last place.
fn nudge(v: f64, k: i32) -> f64 {
    let mut v = v;
    for _ in 0..k.unsigned_abs() {
        v = if k > 0 { v.next_up() } else { v.next_down() };
    }
    if v.is_finite() {
        v
    } else {
        f64::MAX.copysign(v)
    }
}

/// Triangles: three hostile points; nearly collinear (the third near a point of the line
/// through the first two); nearly coincident (two points a few ulps apart).
fn triangle() -> impl Strategy<Value = [Point2; 3]> {
    prop_oneof![
        [point(), point(), point()],
        (point(), point(), 0.0..1.0f64, -3i32..=3, -3i32..=3).prop_map(|(a, b, t, i, j)| {
            let on = p(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
            let on = if on.is_finite() { on } else { midpoint(a, b) };
            [a, b, p(nudge(on.x, i), nudge(on.y, j))]
        }),
        (point(), point(), -4i32..=4, -4i32..=4).prop_map(|(a, c, i, j)| [
            a,
            p(nudge(a.x, i), nudge(a.y, j)),
            c
        ]),
    ]
}

fn proper(t: &[Point2; 3]) -> bool {
    orient2d(t[0], t[1], t[2]) != Orientation::Collinear
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn circumcentres_are_within_the_stated_error(t in triangle()) {
        prop_assume!(proper(&t));
        let [a, b, c] = t;
        let exact_centre = circumcentre_q(a, b, c);
        check(circumcentre(a, b, c), &exact_centre, &stated(), "circumcentre");
        // Each path on its own: the certified one when it accepts, the exact one always.
        if let Some(r) = circumcentre_rounded(a, b, c) {
            check(ConstructedPoint::Finite(r), &exact_centre, &stated(), "certified");
        }
        check(circumcentre_exact(a, b, c), &exact_centre, &exact_path(), "exact path");
        // The range is decided exactly, so every order of the vertices agrees on it.
        prop_assert_eq!(
            circumcentre(b, c, a).is_beyond_range(),
            circumcentre(a, b, c).is_beyond_range()
        );
    }

    #[test]
    fn rectangle_corners_are_within_the_stated_error(
        [a, b, r, s] in [point(), point(), point(), point()],
    ) {
        prop_assume!(a != b);
        let exact_corner = corner_q(a, b, r, s);
        check(rectangle_corner(a, b, r, s), &exact_corner, &stated(), "corner");
        check(rectangle_corner_exact(a, b, r, s), &exact_corner, &exact_path(), "exact corner");
        let foot = corner_q(a, b, r, a);
        check(rectangle_corner(a, b, r, a), &foot, &stated(), "foot");
    }

    #[test]
    fn bisector_crossings_are_within_the_stated_error(
        [a, b, s, w] in [point(), point(), point(), point()],
    ) {
        let (g, u) = ((q(b.x) - q(a.x), q(b.y) - q(a.y)), (q(w.x) - q(s.x), q(w.y) - q(s.y)));
        prop_assume!(!(g.0 * u.0 + g.1 * u.1).is_zero());
        let exact_crossing = crossing_q(a, b, s, w);
        check(bisector_crossing(a, b, s, w), &exact_crossing, &stated(), "crossing");
        check(bisector_crossing_exact(a, b, s, w), &exact_crossing, &exact_path(), "exact crossing");
    }
}

#[test]
fn the_range_is_decided_exactly_at_the_rounding_threshold() {
    let one = BigInt::from_parts(false, 1, 0);
    let zero = BigInt::from_parts(false, 0, 0);
    // 2^1024 − 2^970 rounds to infinity (a tie, to the even 2^1024); one less rounds to MAX.
    let threshold = BigInt::from_parts(false, (1 << 54) - 1, 970);
    let below = threshold.sub(&one);
    let at = rational_point(&threshold, &zero, &one, 0, "test");
    assert!(at.is_beyond_range());
    assert_eq!(at.wide()[0].to_f64(), None);
    assert_eq!(at.wide()[1].to_f64(), Some(0.0));
    assert_eq!(
        rational_point(&below, &zero, &one, 0, "test"),
        ConstructedPoint::Finite(p(f64::MAX, 0.0))
    );
    // The same through a denominator and a power of two: (threshold · 3) / 3 · 2^-5 · 2^5.
    let three = BigInt::from_parts(false, 3, 0);
    let n = threshold.mul(&three);
    let w = three.mul(&BigInt::from_parts(false, 1, 5));
    assert!(rational_point(&zero, &n, &w, 5, "test").is_beyond_range());
    assert!(!rational_point(&zero, &n.sub(&one), &w, 5, "test").is_beyond_range());
    let negative = BigInt::from_parts(true, ((1 << 54) - 1) * 3, 975);
    let [x, _] = rational_point(&negative, &zero, &three, -5, "test").wide();
    assert!(x.is_negative() && x.to_f64().is_none());
}

#[test]
fn circumcentre_of_a_right_triangle_is_the_hypotenuse_midpoint() {
    let finite = |c: ConstructedPoint| c.finite().expect("in range");
    assert_eq!(
        finite(circumcentre(p(0.0, 0.0), p(4.0, 0.0), p(0.0, 2.0))),
        p(2.0, 1.0)
    );
    // The same triangle at 2^996 and at 2^-1060: the certified path at the first, the exact
    // one at the second (below 2^-950, the filter's underflow slack is too coarse).
    let s = 2f64.powi(996);
    assert_eq!(
        finite(circumcentre(p(0.0, 0.0), p(4.0 * s, 0.0), p(0.0, 2.0 * s))),
        p(2.0 * s, s)
    );
    let s = crate::geometry::extended::scale_by_pow2(1.0, -1060);
    assert_eq!(
        finite(circumcentre(p(0.0, 0.0), p(4.0 * s, 0.0), p(0.0, 2.0 * s))),
        p(2.0 * s, s)
    );
}

#[test]
fn overflowing_differences_go_exact() {
    let m = f64::MAX;
    let c = circumcentre(p(-m, -m), p(m, -m), p(-m, m));
    assert_eq!(c, ConstructedPoint::Finite(p(0.0, 0.0)));
    // The rectangle on the diagonal of (±MAX, ±MAX) through (MAX, −MAX): the foot of the
    // perpendicular is the origin, and the corner above (−MAX, −MAX) is (0, −2 MAX).
    let corner = rectangle_corner(p(-m, -m), p(m, m), p(m, -m), p(-m, -m));
    assert_eq!(corner, ConstructedPoint::Finite(p(0.0, 0.0)));
    let beyond = rectangle_corner(p(-m, -m), p(m, m), p(-m, -m), p(m, -m));
    assert!(beyond.is_beyond_range(), "{beyond:?}");
    assert_eq!(beyond.saturating(), p(0.0, -f64::MAX));
    assert_eq!(midpoint(p(m, m), p(m, -m)), p(m, 0.0));
    assert_eq!(unit_direction(p(-m, 0.0), p(m, 0.0)), p(1.0, 0.0));
}

#[test]
fn a_short_edge_beside_a_long_one_keeps_its_centre() {
    // Isosceles about y = x with apex (1e300, 1e300): the centre is near (5e299, 5e299).
    let c = circumcentre(p(1e-300, 0.0), p(1e300, 1e300), p(0.0, 1e-300));
    let c = c.finite().unwrap();
    assert!((c.x / 5e299 - 1.0).abs() < 1e-15, "{c:?}");
    assert!((c.y / 5e299 - 1.0).abs() < 1e-15, "{c:?}");
}

#[test]
fn a_flat_triangle_far_away_is_beyond_the_range() {
    // Centre (1, −(1 − 1e-600) / 2e-300), about −5e299: in range.
    let c = circumcentre(p(0.0, 0.0), p(2.0, 0.0), p(1.0, 1e-300));
    let c = c.finite().unwrap();
    assert_eq!(c.x, 1.0);
    assert!(c.y < -4.9e299 && c.y > -5.1e299, "{c:?}");
    // At scale 1e10 the centre is 1e20 times farther: beyond.
    let c = circumcentre(p(0.0, 0.0), p(2e10, 0.0), p(1e10, 1e-300));
    assert!(c.is_beyond_range());
    assert_eq!(c.wide()[0].to_f64(), Some(1e10));
}

#[test]
fn the_certified_path_serves_ordinary_input() {
    // On the generators' Delaunay triangles the exact path is rare (measured: 68, 17 and 2
    // of about 40,000; the hull's slivers, whose centres are far away and conditioned
    // badly): count it.
    use crate::delaunay::incremental;
    use crate::gen::{points, PointKind};
    for kind in [
        PointKind::UniformSquare,
        PointKind::Clustered,
        PointKind::Grid,
    ] {
        let pts = points(kind, 20_000, 7).unwrap();
        let t = incremental(&pts).unwrap();
        let exact = t
            .triangles
            .chunks_exact(3)
            .filter(|c| circumcentre_rounded(pts[c[0]], pts[c[1]], pts[c[2]]).is_none())
            .count();
        let all = t.triangles.len() / 3;
        println!("{kind}: exact path for {exact} of {all} circumcentres");
        assert!(exact * 100 <= all, "{kind}: {exact} of {all}");
    }
}
