//! The exact predicates against an exact rational oracle (`num-rational`'s `BigRational`, which
//! converts every finite double exactly), on adversarial inputs: points a few ulps off a line,
//! nearly cocircular points, magnitudes near 1e300, 1e200, 1e-140 and 1e-300, subnormals, and
//! mixed magnitudes in one call.

use compgeo::geometry::{
    cmp_dist, cmp_lex, cmp_line_dist, cmp_rect_area, cmp_rect_perimeter, cross_sign, incircle,
    orient2d, InCircle, Orientation, Point2,
};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use std::cmp::Ordering;

// ---------------------------------------------------------------- oracle

fn q(v: f64) -> BigRational {
    BigRational::from_float(v).expect("finite")
}

fn sign(x: &BigRational) -> i32 {
    if x.is_zero() {
        0
    } else if x.is_positive() {
        1
    } else {
        -1
    }
}

fn exact_orient(a: Point2, b: Point2, c: Point2) -> i32 {
    let (ax, ay, bx, by, cx, cy) = (q(a.x), q(a.y), q(b.x), q(b.y), q(c.x), q(c.y));
    sign(&((&bx - &ax) * (&cy - &ay) - (&by - &ay) * (&cx - &ax)))
}

fn exact_cross(a: Point2, b: Point2, c: Point2, d: Point2) -> i32 {
    let (ax, ay, bx, by) = (q(a.x), q(a.y), q(b.x), q(b.y));
    let (cx, cy, dx, dy) = (q(c.x), q(c.y), q(d.x), q(d.y));
    sign(&((bx - ax) * (dy - cy) - (by - ay) * (dx - cx)))
}

fn exact_dist(a: Point2, b: Point2, c: Point2, d: Point2) -> i32 {
    let sq = |p: Point2, r: Point2| {
        let dx = q(r.x) - q(p.x);
        let dy = q(r.y) - q(p.y);
        &dx * &dx + &dy * &dy
    };
    sign(&(sq(a, b) - sq(c, d)))
}

/// The 3x3 determinant with rows (p - d, |p - d|^2) for p = a, b, c: positive when d is inside
/// the circle through the counter-clockwise a, b, c. Written independently of the library.
fn exact_incircle(a: Point2, b: Point2, c: Point2, d: Point2) -> i32 {
    let row = |p: Point2| {
        let x = q(p.x) - q(d.x);
        let y = q(p.y) - q(d.y);
        let l = &x * &x + &y * &y;
        [x, y, l]
    };
    let [r0, r1, r2] = [row(a), row(b), row(c)];
    let det = &r0[0] * (&r1[1] * &r2[2] - &r1[2] * &r2[1])
        - &r0[1] * (&r1[0] * &r2[2] - &r1[2] * &r2[0])
        + &r0[2] * (&r1[0] * &r2[1] - &r1[1] * &r2[0]);
    sign(&det)
}

/// `(b - a) x (d - c)` and `(b - a) · (d - c)`, exactly.
fn exact_forms(a: Point2, b: Point2, c: Point2, d: Point2) -> (BigRational, BigRational) {
    let (ux, uy) = (q(b.x) - q(a.x), q(b.y) - q(a.y));
    let (vx, vy) = (q(d.x) - q(c.x), q(d.y) - q(c.y));
    (&ux * &vy - &uy * &vx, ux * vx + uy * vy)
}

/// dist(p, ab)² vs dist(q, cd)², denominators cleared: cross1² |cd|² − cross2² |ab|².
fn exact_line_dist(a: Point2, b: Point2, p: Point2, c: Point2, d: Point2, r: Point2) -> i32 {
    let (c1, _) = exact_forms(a, b, a, p);
    let (c2, _) = exact_forms(c, d, c, r);
    let (_, l1) = exact_forms(a, b, a, b);
    let (_, l2) = exact_forms(c, d, c, d);
    sign(&(&c1 * &c1 * l2 - &c2 * &c2 * l1))
}

/// |cross| · |dot| / |ab|² for each rectangle, denominators cleared.
fn exact_rect_area(first: [Point2; 5], second: [Point2; 5]) -> i32 {
    let side = |[a, b, p, l, r]: [Point2; 5]| {
        let (height, _) = exact_forms(a, b, a, p);
        let (_, length) = exact_forms(a, b, l, r);
        let (_, norm) = exact_forms(a, b, a, b);
        (height.abs() * length.abs(), norm)
    };
    let ((n1, d1), (n2, d2)) = (side(first), side(second));
    sign(&(n1 * d2 - n2 * d1))
}

/// (|cross| + |dot|)² / |ab|² for each rectangle (half the perimeter, squared),
/// denominators cleared.
fn exact_rect_perimeter(first: [Point2; 5], second: [Point2; 5]) -> i32 {
    let side = |[a, b, p, l, r]: [Point2; 5]| {
        let (height, _) = exact_forms(a, b, a, p);
        let (_, length) = exact_forms(a, b, l, r);
        let (_, norm) = exact_forms(a, b, a, b);
        let half = height.abs() + length.abs();
        (&half * &half, norm)
    };
    let ((n1, d1), (n2, d2)) = (side(first), side(second));
    sign(&(n1 * d2 - n2 * d1))
}

fn orient_sign(o: Orientation) -> i32 {
    match o {
        Orientation::CounterClockwise => 1,
        Orientation::Clockwise => -1,
        Orientation::Collinear => 0,
    }
}

fn incircle_sign(o: InCircle) -> i32 {
    match o {
        InCircle::Inside => 1,
        InCircle::Outside => -1,
        InCircle::On => 0,
    }
}

fn ord_sign(o: Ordering) -> i32 {
    o as i32
}

// ---------------------------------------------------------------- adversarial inputs

/// Moves `v` by `k` ulps (towards +inf for k > 0), staying finite.
fn ulps(v: f64, k: i32) -> f64 {
    let mut v = v;
    for _ in 0..k.unsigned_abs() {
        let next = if k > 0 { v.next_up() } else { v.next_down() };
        if next.is_finite() {
            v = next;
        }
    }
    v
}

/// Magnitudes the kernel must handle: ordinary ones, both ends of the safe windows, far
/// outside them, and subnormals.
fn scale() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(1.0),
        Just(1e15),
        Just(1e-15),
        Just(2f64.powi(199)),
        Just(2f64.powi(-141)),
        Just(2f64.powi(399)),
        Just(2f64.powi(-299)),
        Just(1e200),
        Just(1e300),
        Just(1e-140),
        Just(1e-300),
        Just(1e-310),
        Just(5e-324),
    ]
}

/// A finite coordinate of roughly the given magnitude (integers times the scale, so many
/// values coincide or differ by a few ulps).
fn coordinate(s: f64) -> impl Strategy<Value = f64> {
    prop_oneof![
        (-1000i32..1000).prop_map(move |k| k as f64 * s),
        (-1.0f64..1.0).prop_map(move |t| t * s),
        (-1.0f64..1.0, -4i32..5).prop_map(move |(t, k)| ulps(t * s, k)),
    ]
    .prop_map(|v| if v.is_finite() { v } else { 0.0 })
}

fn point_at(s: f64) -> impl Strategy<Value = Point2> {
    (coordinate(s), coordinate(s)).prop_map(|(x, y)| Point2::new(x, y))
}

/// Any point: each one picks its own magnitude, so one call can mix 1e300 and 1e-300.
fn point() -> impl Strategy<Value = Point2> {
    scale().prop_flat_map(point_at)
}

/// Any finite double, from its bit pattern.
fn any_finite() -> impl Strategy<Value = f64> {
    any::<u64>().prop_map(|b| {
        let v = f64::from_bits(b);
        if v.is_finite() {
            v
        } else {
            0.0
        }
    })
}

/// Three points of which the third lies within a few ulps of the line through the first two.
fn nearly_collinear() -> impl Strategy<Value = (Point2, Point2, Point2)> {
    (point(), point(), -1.0f64..2.0, -3i32..4, -3i32..4).prop_map(|(a, b, t, kx, ky)| {
        let c = Point2::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
        let c = if c.is_finite() { c } else { a };
        (a, b, Point2::new(ulps(c.x, kx), ulps(c.y, ky)))
    })
}

/// Four points of a circle of the given radius and centre, rounded, then nudged by ulps.
fn nearly_cocircular() -> impl Strategy<Value = [Point2; 4]> {
    (
        scale(),
        point(),
        proptest::array::uniform4(0.0f64..std::f64::consts::TAU),
        proptest::array::uniform4((-2i32..3, -2i32..3)),
    )
        .prop_map(|(r, centre, angles, nudges)| {
            let mut angles = angles;
            angles[..3].sort_by(f64::total_cmp);
            let mut pts = [Point2::default(); 4];
            for (i, (t, (kx, ky))) in angles.iter().zip(nudges).enumerate() {
                let x = centre.x + r * t.cos();
                let y = centre.y + r * t.sin();
                let (x, y) = if x.is_finite() && y.is_finite() {
                    (x, y)
                } else {
                    (r * t.cos(), r * t.sin())
                };
                pts[i] = Point2::new(ulps(x, kx), ulps(y, ky));
            }
            pts
        })
}

/// Integer points exactly on x^2 + y^2 = 65^2 (65 = 5 * 13 has 12 lattice points per
/// quadrant axis pair), scaled by an exact power of two and translated by an integer multiple
/// of the same power: still exactly cocircular at any magnitude.
fn exactly_cocircular() -> impl Strategy<Value = [Point2; 4]> {
    const LATTICE: [(f64, f64); 12] = [
        (65.0, 0.0),
        (63.0, 16.0),
        (60.0, 25.0),
        (56.0, 33.0),
        (52.0, 39.0),
        (39.0, 52.0),
        (33.0, 56.0),
        (25.0, 60.0),
        (16.0, 63.0),
        (0.0, 65.0),
        (-16.0, 63.0),
        (-65.0, 0.0),
    ];
    (
        proptest::sample::subsequence(LATTICE.to_vec(), 4),
        -1060i32..960,
        -50i32..50,
        -50i32..50,
    )
        .prop_map(|(pts, e, tx, ty)| {
            let s = 2f64.powi(e.max(-1022)) * if e < -1022 { 2f64.powi(e + 1022) } else { 1.0 };
            let mut out = [Point2::default(); 4];
            for (o, (x, y)) in out.iter_mut().zip(pts) {
                *o = Point2::new((x + tx as f64) * s, (y + ty as f64) * s);
            }
            out
        })
}

fn cases(n: u32) -> ProptestConfig {
    ProptestConfig {
        cases: n,
        ..ProptestConfig::default()
    }
}

// ---------------------------------------------------------------- properties

proptest! {
    #![proptest_config(cases(3000))]

    #[test]
    fn orient2d_is_exact_on_mixed_magnitudes(a in point(), b in point(), c in point()) {
        prop_assert_eq!(orient_sign(orient2d(a, b, c)), exact_orient(a, b, c));
    }

    #[test]
    fn orient2d_is_exact_a_few_ulps_off_a_line((a, b, c) in nearly_collinear()) {
        prop_assert_eq!(orient_sign(orient2d(a, b, c)), exact_orient(a, b, c));
    }

    #[test]
    fn orient2d_is_exact_on_arbitrary_bit_patterns(v in proptest::array::uniform6(any_finite())) {
        let [ax, ay, bx, by, cx, cy] = v;
        let (a, b, c) = (Point2::new(ax, ay), Point2::new(bx, by), Point2::new(cx, cy));
        prop_assert_eq!(orient_sign(orient2d(a, b, c)), exact_orient(a, b, c));
    }

    #[test]
    fn cross_sign_is_exact(a in point(), b in point(), c in point(), d in point()) {
        prop_assert_eq!(orient_sign(cross_sign(a, b, c, d)), exact_cross(a, b, c, d));
    }

    #[test]
    fn cross_sign_is_exact_on_nearly_parallel_edges(
        (a, b, _) in nearly_collinear(), (c, d, _) in nearly_collinear(),
        k in -3i32..4,
    ) {
        // d - c nearly parallel to b - a: translate the first edge and nudge it.
        let shift = Point2::new(c.x - a.x, c.y - a.y);
        let c2 = Point2::new(a.x + shift.x, a.y + shift.y);
        let d2 = Point2::new(ulps(b.x + shift.x, k), b.y + shift.y);
        for (p, r) in [(c, d), (c2, d2)] {
            if p.is_finite() && r.is_finite() {
                prop_assert_eq!(orient_sign(cross_sign(a, b, p, r)), exact_cross(a, b, p, r));
            }
        }
    }

    #[test]
    fn cross_sign_is_exact_on_arbitrary_bit_patterns(v in proptest::array::uniform8(any_finite())) {
        let p = |i: usize| Point2::new(v[2 * i], v[2 * i + 1]);
        prop_assert_eq!(orient_sign(cross_sign(p(0), p(1), p(2), p(3))), exact_cross(p(0), p(1), p(2), p(3)));
    }

    #[test]
    fn cmp_dist_is_exact(a in point(), b in point(), c in point(), d in point()) {
        prop_assert_eq!(ord_sign(cmp_dist(a, b, c, d)), exact_dist(a, b, c, d));
    }

    #[test]
    fn cmp_dist_is_exact_on_near_ties(a in point(), b in point(), kx in -3i32..4, ky in -3i32..4, swap in any::<bool>()) {
        // |ab| vs |a b'| where b' is b reflected through a's axes and nudged by ulps.
        let r = Point2::new(ulps(2.0 * a.x - b.x, kx), ulps(2.0 * a.y - b.y, ky));
        let r2 = if swap { Point2::new(a.x + (b.y - a.y), a.y + (b.x - a.x)) } else { r };
        for r in [r, r2] {
            if r.is_finite() {
                prop_assert_eq!(ord_sign(cmp_dist(a, b, a, r)), exact_dist(a, b, a, r));
            }
        }
    }

    #[test]
    fn cmp_dist_is_exact_on_arbitrary_bit_patterns(v in proptest::array::uniform8(any_finite())) {
        let p = |i: usize| Point2::new(v[2 * i], v[2 * i + 1]);
        prop_assert_eq!(ord_sign(cmp_dist(p(0), p(1), p(2), p(3))), exact_dist(p(0), p(1), p(2), p(3)));
    }

    #[test]
    fn cmp_lex_matches_rational_order(a in point(), b in point()) {
        let expected = q(a.x).cmp(&q(b.x)).then(q(a.y).cmp(&q(b.y)));
        prop_assert_eq!(cmp_lex(a, b), expected);
    }
}

proptest! {
    // The rational oracle for a degree-4 determinant is the slowest part of the suite.
    #![proptest_config(cases(2000))]

    #[test]
    fn incircle_is_exact_on_mixed_magnitudes(a in point(), b in point(), c in point(), d in point()) {
        prop_assert_eq!(incircle_sign(incircle(a, b, c, d)), exact_incircle(a, b, c, d));
    }

    #[test]
    fn incircle_is_exact_on_nearly_cocircular_points(p in nearly_cocircular()) {
        let [a, b, c, d] = p;
        prop_assert_eq!(incircle_sign(incircle(a, b, c, d)), exact_incircle(a, b, c, d));
    }

    #[test]
    fn incircle_is_exact_on_arbitrary_bit_patterns(v in proptest::array::uniform8(any_finite())) {
        let p = |i: usize| Point2::new(v[2 * i], v[2 * i + 1]);
        prop_assert_eq!(incircle_sign(incircle(p(0), p(1), p(2), p(3))), exact_incircle(p(0), p(1), p(2), p(3)));
    }

    #[test]
    fn exactly_cocircular_points_are_on_at_every_scale(p in exactly_cocircular()) {
        let [a, b, c, d] = p;
        prop_assert_eq!(exact_incircle(a, b, c, d), 0);
        prop_assert_eq!(incircle(a, b, c, d), InCircle::On);
    }
}

proptest! {
    // Degree 6 and 8: the rational oracle and the big-integer path are slower still.
    #![proptest_config(cases(600))]

    #[test]
    fn cmp_line_dist_is_exact_on_mixed_magnitudes(
        a in point(), b in point(), p in point(), c in point(), d in point(), r in point(),
    ) {
        prop_assert_eq!(ord_sign(cmp_line_dist(a, b, p, c, d, r)), exact_line_dist(a, b, p, c, d, r));
    }

    #[test]
    fn cmp_line_dist_is_exact_on_near_ties(
        (a, b, _) in nearly_collinear(), p in point(), t in -2.0f64..2.0,
        kx in -3i32..4, ky in -3i32..4, reverse in any::<bool>(),
    ) {
        // The same line (maybe reversed) and p slid along it, then nudged by ulps.
        let slid = Point2::new(p.x + t * (b.x - a.x), p.y + t * (b.y - a.y));
        let r = Point2::new(ulps(slid.x, kx), ulps(slid.y, ky));
        let (c, d) = if reverse { (b, a) } else { (a, b) };
        for r in [r, p] {
            if r.is_finite() {
                prop_assert_eq!(ord_sign(cmp_line_dist(a, b, p, c, d, r)), exact_line_dist(a, b, p, c, d, r));
            }
        }
    }

    #[test]
    fn cmp_line_dist_is_exact_on_arbitrary_bit_patterns(v in proptest::array::uniform12(any_finite())) {
        let p = |i: usize| Point2::new(v[2 * i], v[2 * i + 1]);
        prop_assert_eq!(
            ord_sign(cmp_line_dist(p(0), p(1), p(2), p(3), p(4), p(5))),
            exact_line_dist(p(0), p(1), p(2), p(3), p(4), p(5))
        );
    }

    #[test]
    fn cmp_rect_area_is_exact_on_mixed_magnitudes(
        first in proptest::array::uniform5(point()), second in proptest::array::uniform5(point()),
    ) {
        prop_assert_eq!(ord_sign(cmp_rect_area(first, second)), exact_rect_area(first, second));
    }

    #[test]
    fn cmp_rect_area_is_exact_on_near_ties(
        first in proptest::array::uniform5(point()), k in proptest::array::uniform5((-2i32..3, -2i32..3)),
    ) {
        // The same rectangle described from the other end of its line (an exact tie),
        // then with every point nudged by a few ulps.
        let [a, b, p, l, r] = first;
        let mirrored = [b, a, p, r, l];
        let mut nudged = mirrored;
        for (x, (kx, ky)) in nudged.iter_mut().zip(k) {
            *x = Point2::new(ulps(x.x, kx), ulps(x.y, ky));
        }
        prop_assert_eq!(cmp_rect_area(first, mirrored), Ordering::Equal);
        prop_assert_eq!(ord_sign(cmp_rect_area(first, nudged)), exact_rect_area(first, nudged));
    }

    #[test]
    fn cmp_rect_area_is_exact_on_arbitrary_bit_patterns(
        first in proptest::array::uniform5((any_finite(), any_finite())),
        second in proptest::array::uniform5((any_finite(), any_finite())),
    ) {
        let (first, second) = (first.map(Point2::from), second.map(Point2::from));
        prop_assert_eq!(ord_sign(cmp_rect_area(first, second)), exact_rect_area(first, second));
    }
}

proptest! {
    #[test]
    fn cmp_rect_perimeter_is_exact_on_mixed_magnitudes(
        first in proptest::array::uniform5(point()), second in proptest::array::uniform5(point()),
    ) {
        prop_assert_eq!(ord_sign(cmp_rect_perimeter(first, second)), exact_rect_perimeter(first, second));
    }

    #[test]
    fn cmp_rect_perimeter_is_exact_on_near_ties(
        first in proptest::array::uniform5(point()), k in proptest::array::uniform5((-2i32..3, -2i32..3)),
    ) {
        let [a, b, p, l, r] = first;
        let mirrored = [b, a, p, r, l];
        let mut nudged = mirrored;
        for (x, (kx, ky)) in nudged.iter_mut().zip(k) {
            *x = Point2::new(ulps(x.x, kx), ulps(x.y, ky));
        }
        prop_assert_eq!(cmp_rect_perimeter(first, mirrored), Ordering::Equal);
        prop_assert_eq!(ord_sign(cmp_rect_perimeter(first, nudged)), exact_rect_perimeter(first, nudged));
    }

    #[test]
    fn cmp_rect_perimeter_is_exact_on_arbitrary_bit_patterns(
        first in proptest::array::uniform5((any_finite(), any_finite())),
        second in proptest::array::uniform5((any_finite(), any_finite())),
    ) {
        let (first, second) = (first.map(Point2::from), second.map(Point2::from));
        prop_assert_eq!(ord_sign(cmp_rect_perimeter(first, second)), exact_rect_perimeter(first, second));
    }
}

#[test]
fn perimeter_ties_at_every_scale() {
    // A 3 × 3 box on the x-axis and a 1 × 5 box on the y-axis: half-perimeters 6 and 6;
    // a 4 × 2 box against a 3√2 × √2 one on the diagonal: 6 against 4√2. Powers of two
    // scale every coordinate exactly, so the ties stay ties from subnormals to near overflow.
    for e in [-1074, -1000, -465, 0, 50, 664, 1019] {
        let s = 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
        let p = |x: f64, y: f64| Point2::new(x * s, y * s);
        let square = [
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(0.0, 3.0),
            p(0.0, 0.0),
            p(3.0, 0.0),
        ];
        let long = [
            p(0.0, 0.0),
            p(0.0, 1.0),
            p(-1.0, 0.0),
            p(0.0, 0.0),
            p(0.0, 5.0),
        ];
        assert_eq!(cmp_rect_perimeter(square, long), Ordering::Equal, "{s:e}");
        let flat = [
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(0.0, 2.0),
            p(0.0, 0.0),
            p(4.0, 0.0),
        ];
        let tilted = [
            p(0.0, 0.0),
            p(1.0, 1.0),
            p(0.0, 2.0),
            p(0.0, 0.0),
            p(3.0, 3.0),
        ];
        assert_eq!(cmp_rect_perimeter(flat, tilted), Ordering::Greater, "{s:e}");
        assert_eq!(cmp_rect_perimeter(tilted, flat), Ordering::Less, "{s:e}");
    }
}

#[test]
fn line_distance_and_area_ties_at_every_scale() {
    // (0, 4) and (3, 8) are both 12/5 from the line through (0, 0) and (3, 4), (4, 2) is
    // 2; a 3 × 4 box described from two of its sides has area 12 both ways.
    for s in [5e-324, 1e-300, 1e-140, 1.0, 1e15, 1e200, 1e300] {
        let p = |x: f64, y: f64| Point2::new(x * s, y * s);
        let (o, h) = (p(0.0, 0.0), p(3.0, 4.0));
        assert_eq!(
            cmp_line_dist(o, h, p(0.0, 4.0), h, o, p(3.0, 8.0)),
            Ordering::Equal,
            "{s:e}"
        );
        assert_eq!(
            cmp_line_dist(o, h, p(0.0, 4.0), o, h, p(4.0, 2.0)),
            Ordering::Greater,
            "{s:e}"
        );
        let legs = [
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(0.0, 4.0),
            p(0.0, 0.0),
            p(3.0, 0.0),
        ];
        let upright = [
            p(0.0, 0.0),
            p(0.0, -1.0),
            p(3.0, 0.0),
            p(0.0, 4.0),
            p(0.0, 0.0),
        ];
        assert_eq!(cmp_rect_area(legs, upright), Ordering::Equal, "{s:e}");
    }
}

/// Integers near the edge of the kernel's small-integer stage (magnitude below 2^29) and
/// just past it, plus small ones that make ties (collinear and cocircular sets) common.
fn integer_coordinate() -> impl Strategy<Value = f64> {
    let edge = (1i64 << 29) as f64;
    prop_oneof![
        (-3i64..=3).prop_map(|v| v as f64),
        (-(1i64 << 29) + 1..(1i64 << 29)).prop_map(|v| v as f64),
        (-4i64..=4).prop_map(move |k| edge + k as f64),
        (-4i64..=4).prop_map(move |k| -edge + k as f64),
        Just(-0.0),
    ]
}

proptest! {
    #![proptest_config(cases(2000))]

    #[test]
    fn orient2d_and_incircle_are_exact_on_integer_coordinates(v in proptest::array::uniform8(integer_coordinate())) {
        let p = |i: usize| Point2::new(v[2 * i], v[2 * i + 1]);
        prop_assert_eq!(orient_sign(orient2d(p(0), p(1), p(2))), exact_orient(p(0), p(1), p(2)));
        prop_assert_eq!(incircle_sign(incircle(p(0), p(1), p(2), p(3))), exact_incircle(p(0), p(1), p(2), p(3)));
    }
}

// ---------------------------------------------------------------- hand-picked cases

fn naive_orient(a: Point2, b: Point2, c: Point2) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

fn naive_sign(x: f64) -> i32 {
    if x.is_nan() {
        i32::MIN
    } else {
        (x > 0.0) as i32 - (x < 0.0) as i32
    }
}

/// Shewchuk's classic picture: a point within a few ulps of (0.5, 0.5) against the line
/// through (12, 12) and (24, 24). The naive formula gets many of these signs wrong.
#[test]
fn orient2d_where_the_naive_formula_fails() {
    let (b, c) = (Point2::new(12.0, 12.0), Point2::new(24.0, 24.0));
    let mut naive_wrong = 0;
    for i in 0..64 {
        for j in 0..64 {
            let a = Point2::new(ulps(0.5, i), ulps(0.5, j));
            let exact = exact_orient(a, b, c);
            assert_eq!(orient_sign(orient2d(a, b, c)), exact, "{a:?}");
            naive_wrong += (naive_sign(naive_orient(a, b, c)) != exact) as usize;
        }
    }
    assert!(naive_wrong > 100, "only {naive_wrong} naive failures");
}

#[test]
fn orient2d_pinned_cases() {
    // a one ulp above the diagonal: naive says collinear.
    let a = Point2::new(0.5, ulps(0.5, 1));
    let (b, c) = (Point2::new(12.0, 12.0), Point2::new(24.0, 24.0));
    assert_eq!(naive_sign(naive_orient(a, b, c)), 0);
    assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
    // Near 1e200 the naive products overflow to inf and the difference is NaN.
    let s = 1e200;
    let (a, b, c) = (
        Point2::new(0.0, 0.0),
        Point2::new(3.0 * s, s),
        Point2::new(s, 3.0 * s),
    );
    assert!(naive_orient(a, b, c).is_nan());
    assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
    // Near 1e-200 the naive products underflow to zero.
    let s = 1e-200;
    let (a, b, c) = (
        Point2::new(0.0, 0.0),
        Point2::new(3.0 * s, s),
        Point2::new(s, 3.0 * s),
    );
    assert_eq!(naive_orient(a, b, c), 0.0);
    assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
    // Subnormals and 1e300 in one call: (0,0), (1e300, 1e300) and a point one subnormal
    // step right of the diagonal's start.
    let (a, b) = (Point2::new(0.0, 0.0), Point2::new(1e300, 1e300));
    assert_eq!(
        orient2d(a, b, Point2::new(5e-324, 0.0)),
        Orientation::Clockwise
    );
    assert_eq!(
        orient2d(a, b, Point2::new(0.0, 5e-324)),
        Orientation::CounterClockwise
    );
    assert_eq!(
        orient2d(a, b, Point2::new(5e-324, 5e-324)),
        Orientation::Collinear
    );
}

#[test]
fn incircle_where_the_naive_formula_fails() {
    // Points of the circle of radius 1 about (0.5, 0.5) nudged by ulps, and the same at
    // extreme magnitudes, where the naive determinant overflows or underflows.
    let naive = |a: Point2, b: Point2, c: Point2, d: Point2| {
        let r = |p: Point2| {
            let (x, y) = (p.x - d.x, p.y - d.y);
            (x, y, x * x + y * y)
        };
        let (ax, ay, al) = r(a);
        let (bx, by, bl) = r(b);
        let (cx, cy, cl) = r(c);
        ax * (by * cl - bl * cy) - ay * (bx * cl - bl * cx) + al * (bx * cy - by * cx)
    };
    let mut naive_wrong = 0;
    for s in [1.0, 1e200, 1e-200, 1e300, 1e-300] {
        let (a, b, c) = (
            Point2::new(s, 0.0),
            Point2::new(0.0, s),
            Point2::new(-s, 0.0),
        );
        for i in -8..=8 {
            for j in -8..=8 {
                let d = Point2::new(ulps(0.0 * s, 0) + ulps(0.6 * s, i), ulps(0.8 * s, j));
                let exact = exact_incircle(a, b, c, d);
                assert_eq!(
                    incircle_sign(incircle(a, b, c, d)),
                    exact,
                    "s = {s:e}, {d:?}"
                );
                naive_wrong += (naive_sign(naive(a, b, c, d)) != exact) as usize;
            }
        }
    }
    assert!(naive_wrong > 50, "only {naive_wrong} naive failures");
}

#[test]
fn cmp_dist_and_cross_sign_where_the_naive_formula_fails() {
    let o = Point2::new(0.0, 0.0);
    // |o - (1, 2^-30)|^2 = 1 + 2^-60, which rounds to 1 = |o - (1, 0)|^2 in f64.
    let p = Point2::new(1.0, 2f64.powi(-30));
    let r = Point2::new(1.0, 0.0);
    assert_eq!(
        (p.x * p.x + p.y * p.y).total_cmp(&(r.x * r.x)),
        Ordering::Equal
    );
    assert_eq!(cmp_dist(o, p, o, r), Ordering::Greater);
    // At 2^664 (about 1e200) the squared distances overflow; at 2^-664 they underflow.
    for s in [2f64.powi(664), 2f64.powi(-664)] {
        let a = Point2::new(3.0 * s, 4.0 * s);
        let b = Point2::new(5.0 * s, 0.0);
        assert_eq!(cmp_dist(o, a, o, b), Ordering::Equal, "{s:e}");
        let b2 = Point2::new(ulps(5.0 * s, 1), 0.0);
        assert_eq!(cmp_dist(o, a, o, b2), Ordering::Less, "{s:e}");
    }
    // Edges from points a few ulps off (0.5, 0.5) towards (12, 12), against the diagonal
    // direction (0.25, 0.25) -> (24.25, 24.25): the rounded differences lose the ulps.
    let (b, c, d) = (
        Point2::new(12.0, 12.0),
        Point2::new(0.25, 0.25),
        Point2::new(24.25, 24.25),
    );
    let mut naive_wrong = 0;
    for i in 0..32 {
        for j in 0..32 {
            let a = Point2::new(ulps(0.5, i), ulps(0.5, j));
            let naive = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
            let exact = exact_cross(a, b, c, d);
            assert_eq!(orient_sign(cross_sign(a, b, c, d)), exact, "{a:?}");
            naive_wrong += (naive_sign(naive) != exact) as usize;
        }
    }
    assert!(naive_wrong > 50, "only {naive_wrong} naive failures");
}

#[test]
fn oracle_helpers_agree_on_a_trivial_case() {
    // Guards the oracle itself: a unit right triangle and the unit circle.
    let p = |x: i64, y: i64| Point2::new(x as f64, y as f64);
    assert_eq!(exact_orient(p(0, 0), p(1, 0), p(0, 1)), 1);
    assert_eq!(exact_incircle(p(1, 0), p(0, 1), p(-1, 0), p(0, 0)), 1);
    assert_eq!(exact_incircle(p(1, 0), p(0, 1), p(-1, 0), p(0, -1)), 0);
    assert_eq!(exact_dist(p(0, 0), p(3, 4), p(0, 0), p(5, 0)), 0);
    assert!(BigInt::from(1).is_positive());
}
