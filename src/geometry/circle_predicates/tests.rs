//! Against an exact rational oracle written from the definitions: the circumcentre as
//! the solution of `|X − a|² = |X − b|² = |X − c|²` (Cramer's rule on absolute
//! coordinates), the crossing parameter as `((m − p) · u) / ((q − p) · u)`, squared
//! radii as squared distances from the exact centre.

use super::radius::{cmp_products, Approx, Circle, GridFactors};
use super::*;
use crate::geometry::extended::scale_by_pow2;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

type Q = BigRational;

fn q(v: f64) -> Q {
    Q::from_float(v).expect("finite")
}

fn qp(p: Point2) -> (Q, Q) {
    (q(p.x), q(p.y))
}

fn sign(x: &Q) -> Ordering {
    x.cmp(&Q::zero())
}

fn cross(o: &(Q, Q), a: &(Q, Q), b: &(Q, Q)) -> Q {
    (&a.0 - &o.0) * (&b.1 - &o.1) - (&a.1 - &o.1) * (&b.0 - &o.0)
}

fn dist2(a: &(Q, Q), b: &(Q, Q)) -> Q {
    let (dx, dy) = (&a.0 - &b.0, &a.1 - &b.1);
    &dx * &dx + &dy * &dy
}

/// 2 (b − a) · X = |b|² − |a|², 2 (c − a) · X = |c|² − |a|², by Cramer's rule.
fn circumcentre_q(t: [Point2; 3]) -> (Q, Q) {
    let [a, b, c] = t.map(qp);
    let two = Q::from_integer(2.into());
    let norm = |p: &(Q, Q)| &p.0 * &p.0 + &p.1 * &p.1;
    let (m11, m12) = (&two * (&b.0 - &a.0), &two * (&b.1 - &a.1));
    let (m21, m22) = (&two * (&c.0 - &a.0), &two * (&c.1 - &a.1));
    let (r1, r2) = (norm(&b) - norm(&a), norm(&c) - norm(&a));
    let det = &m11 * &m22 - &m12 * &m21;
    (
        (&r1 * &m22 - &m12 * &r2) / &det,
        (&m11 * &r2 - &r1 * &m21) / &det,
    )
}

fn orient_oracle(t: [Point2; 3], p: Point2, r: Point2) -> Orientation {
    let x = circumcentre_q(t);
    Orientation::from_sign(sign(&cross(&qp(p), &qp(r), &x)) as i32)
}

/// `(q − p) · (w − s)` and `t = ((m − p) · u) / ((q − p) · u)`.
fn crossing_q(p: Point2, r: Point2, s: Point2, w: Point2) -> (Q, Q) {
    let [p, r, s, w] = [p, r, s, w].map(qp);
    let two = Q::from_integer(2.into());
    let (ux, uy) = (&w.0 - &s.0, &w.1 - &s.1);
    let (mx, my) = ((&s.0 + &w.0) / &two, (&s.1 + &w.1) / &two);
    let den = (&r.0 - &p.0) * &ux + (&r.1 - &p.1) * &uy;
    let num = (mx - &p.0) * &ux + (my - &p.1) * &uy;
    let t = if den.is_zero() { Q::zero() } else { num / &den };
    (den, t)
}

fn crossing_point_q(p: Point2, r: Point2, t: &Q) -> (Q, Q) {
    let (p, r) = (qp(p), qp(r));
    (&p.0 + t * (&r.0 - &p.0), &p.1 + t * (&r.1 - &p.1))
}

/// A candidate for the oracle: its exact squared radius.
fn radius_q(c: &Circle) -> Q {
    match *c {
        Circle::Point => Q::zero(),
        Circle::Circumcircle(t) => dist2(&circumcentre_q(t), &qp(t[0])),
        Circle::Crossing([p, r, s, w]) => {
            let (_, t) = crossing_q(p, r, s, w);
            dist2(&crossing_point_q(p, r, &t), &qp(s))
        }
    }
}

fn squared_radius(c: &Circle) -> SquaredRadius {
    match *c {
        Circle::Point => SquaredRadius::zero(),
        Circle::Circumcircle([a, b, c]) => Circumcentre::new(a, b, c).squared_radius(),
        Circle::Crossing([p, r, s, w]) => SquaredRadius::crossing(p, r, s, w),
    }
}

// ------------------------------------------------------------ adversarial inputs

/// Moves `v` by `k` ulps, staying finite.
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

/// Magnitudes: ordinary, far outside every window, subnormal.
fn scale() -> impl Strategy<Value = f64> {
    prop::sample::select(vec![
        1.0,
        2f64.powi(-40),
        2f64.powi(60),
        1e200,
        1e300,
        1e-300,
        1e-310,
        5e-324,
    ])
}

/// A coordinate near the given magnitude: small integers times it (ties), uniform, or
/// nudged by ulps.
fn coordinate(s: f64) -> impl Strategy<Value = f64> {
    prop_oneof![
        (-8i32..=8).prop_map(move |k| k as f64 * s),
        (-1.0f64..1.0).prop_map(move |t| t * s),
        (-1.0f64..1.0, -3i32..4).prop_map(move |(t, k)| ulps(t * s, k)),
    ]
    .prop_map(|v| if v.is_finite() { v } else { 0.0 })
}

/// A point whose two coordinates pick their own magnitudes (mixed in one call).
fn point() -> BoxedStrategy<Point2> {
    (
        scale().prop_flat_map(coordinate),
        scale().prop_flat_map(coordinate),
    )
        .prop_map(|(x, y)| Point2::new(x, y))
        .boxed()
}

/// A point with both coordinates near one magnitude.
fn point_at(s: f64) -> BoxedStrategy<Point2> {
    (coordinate(s), coordinate(s))
        .prop_map(|(x, y)| Point2::new(x, y))
        .boxed()
}

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

fn bits_point() -> BoxedStrategy<Point2> {
    (any_finite(), any_finite())
        .prop_map(|(x, y)| Point2::new(x, y))
        .boxed()
}

/// `N` points: mostly of one magnitude per call (the filters' ground, and near ties for
/// the exact stage), a quarter with magnitudes mixed point by point or from arbitrary
/// bit patterns (the exact stage on numbers of thousands of bits, which is slow in a
/// debug build, hence the weights).
fn points<const N: usize>() -> BoxedStrategy<[Point2; N]> {
    prop_oneof![
        6 => scale().prop_flat_map(|s| proptest::array::uniform::<_, N>(point_at(s))),
        1 => proptest::array::uniform::<_, N>(point()),
        1 => proptest::array::uniform::<_, N>(bits_point()),
    ]
    .boxed()
}

/// Three points, not collinear, as [`points`].
fn triangle() -> BoxedStrategy<[Point2; 3]> {
    points::<3>()
        .prop_filter("collinear", |[a, b, c]| {
            super::super::orient2d(*a, *b, *c) != Orientation::Collinear
        })
        .boxed()
}

/// Integer points on x² + y² = 65²: any three are a triangle with centre 0.
const LATTICE: [(f64, f64); 12] = [
    (65.0, 0.0),
    (63.0, 16.0),
    (60.0, 25.0),
    (56.0, 33.0),
    (52.0, 39.0),
    (39.0, 52.0),
    (33.0, -56.0),
    (-25.0, 60.0),
    (-16.0, -63.0),
    (0.0, 65.0),
    (-60.0, -25.0),
    (-65.0, 0.0),
];

/// `(x + tx, y + ty) · 2^e`: exact for the lattice's small integers at every `e`.
fn place(v: (f64, f64), t: (i32, i32), e: i32) -> Point2 {
    let s = |x: f64| scale_by_pow2(x, e);
    Point2::new(s(v.0 + t.0 as f64), s(v.1 + t.1 as f64))
}

fn exponent_choice() -> impl Strategy<Value = i32> {
    prop::sample::select(vec![0, -3, 40, -60, 900, -1000, -1066])
}

/// Lattice points of the circle of radius 65 about `t · 2^e` (`k` of them, distinct),
/// the centre's translation and the exponent.
fn lattice_circle(k: usize) -> impl Strategy<Value = (Vec<Point2>, (i32, i32), i32)> {
    (
        proptest::sample::subsequence(LATTICE.to_vec(), k).prop_shuffle(),
        (-40i32..40, -40i32..40),
        exponent_choice(),
    )
        .prop_map(|(pts, t, e)| (pts.into_iter().map(|v| place(v, t, e)).collect(), t, e))
}

fn cases(n: u32) -> ProptestConfig {
    ProptestConfig {
        cases: n,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(cases(300))]

    #[test]
    fn circumcentre_side_matches_the_oracle(t in triangle(), [p, r] in points::<2>()) {
        let x = Circumcentre::new(t[0], t[1], t[2]);
        prop_assert_eq!(x.orient(p, r), orient_oracle(t, p, r));
    }

    #[test]
    fn circumcentre_side_on_arbitrary_bit_patterns(
        t in triangle(), p in bits_point(), r in bits_point(),
    ) {
        let x = Circumcentre::new(t[0], t[1], t[2]);
        prop_assert_eq!(x.orient(p, r), orient_oracle(t, p, r));
    }

    #[test]
    fn circumcentre_side_a_few_ulps_from_the_line(
        t in triangle(), [r] in points::<1>(), kx in -3i32..4, ky in -3i32..4,
    ) {
        // The line through the rounded centre (moved by ulps) and another point: the
        // exact centre is within a few rounding errors of it.
        let x = Circumcentre::new(t[0], t[1], t[2]);
        prop_assume!(x.err_x.is_finite());
        let p = Point2::new(ulps(x.x, kx), ulps(x.y, ky));
        prop_assert_eq!(x.orient(p, r), orient_oracle(t, p, r));
        prop_assert_eq!(x.orient(r, p), orient_oracle(t, r, p));
    }

    #[test]
    fn circumcentre_exactly_on_the_line(
        (pts, t, e) in lattice_circle(4), k in -3i32..4, far in 1i32..50, nudge in -2i32..3,
    ) {
        // The centre t · 2^e of a lattice circle, on the line through a lattice point
        // and its reflection through the centre scaled by `far`: collinear exactly,
        // and a nudged endpoint makes a near tie.
        let centre = place((0.0, 0.0), t, e);
        let v = pts[3];
        let (dx, dy) = (v.x - centre.x, v.y - centre.y);
        let r = Point2::new(centre.x - far as f64 * dx, centre.y - far as f64 * dy);
        prop_assume!(r.is_finite());
        let x = Circumcentre::new(pts[0], pts[1], pts[2]);
        prop_assert_eq!(x.orient(v, r), Orientation::Collinear);
        let r = Point2::new(ulps(r.x, k), ulps(r.y, nudge));
        prop_assert_eq!(x.orient(v, r), orient_oracle([pts[0], pts[1], pts[2]], v, r));
    }

    #[test]
    fn dot_sign_matches_the_oracle([a, b, c, d] in points::<4>(), perp in any::<bool>()) {
        // Half of the cases perpendicular exactly: d − c = rot(b − a) when that is exact.
        let d = if perp { Point2::new(c.x - (b.y - a.y), c.y + (b.x - a.x)) } else { d };
        prop_assume!(d.is_finite());
        let [a, b, c, d] = [a, b, c, d].map(qp);
        let exact = (&b.0 - &a.0) * (&d.0 - &c.0) + (&b.1 - &a.1) * (&d.1 - &c.1);
        let [a, b, c, d] = [a, b, c, d].map(|(x, y)| {
            Point2::new(num_traits::ToPrimitive::to_f64(&x).unwrap(), num_traits::ToPrimitive::to_f64(&y).unwrap())
        });
        prop_assert_eq!(dot_sign(a, b, c, d), sign(&exact));
    }

    #[test]
    fn bisector_crossings_match_the_oracle(
        [p, r, s, w, v] in points::<5>(),
    ) {
        let ((dw, tw), (dv, tv)) = (crossing_q(p, r, s, w), crossing_q(p, r, s, v));
        prop_assume!(dw.is_positive() && dv.is_positive());
        prop_assert_eq!(cmp_bisector_crossings(p, r, s, w, v), tw.cmp(&tv));
        prop_assert_eq!(cmp_bisector_crossings(p, r, s, v, w), tv.cmp(&tw));
    }

    #[test]
    fn bisector_crossings_tie_at_a_voronoi_vertex_on_the_edge(
        (pts, t, e) in lattice_circle(3), dir in 0usize..12, len in 1i32..200,
        nudge in -2i32..3,
    ) {
        // s, w, v on a lattice circle whose centre is on the line p → r: both
        // bisectors cross it at the centre; nudging r by ulps breaks the tie.
        let centre = place((0.0, 0.0), t, e);
        let (dx, dy) = (LATTICE[dir].0 * len as f64, LATTICE[dir].1 * len as f64);
        let p = Point2::new(centre.x - scale_by_pow2(dx, e), centre.y - scale_by_pow2(dy, e));
        let r = Point2::new(centre.x + scale_by_pow2(dx, e), centre.y + scale_by_pow2(dy, e));
        let [s, w, v] = [pts[0], pts[1], pts[2]];
        let (p, r) = if crossing_q(p, r, s, w).0.is_positive() { (p, r) } else { (r, p) };
        prop_assume!(crossing_q(p, r, s, v).0.is_positive());
        prop_assert_eq!(cmp_bisector_crossings(p, r, s, w, v), Ordering::Equal);
        let r = Point2::new(ulps(r.x, nudge), r.y);
        let ((dw, tw), (dv, tv)) = (crossing_q(p, r, s, w), crossing_q(p, r, s, v));
        prop_assume!(dw.is_positive() && dv.is_positive());
        prop_assert_eq!(cmp_bisector_crossings(p, r, s, w, v), tw.cmp(&tv));
    }

    #[test]
    fn squared_radii_match_the_oracle(
        t1 in triangle(), t2 in triangle(), [p, r, s, w] in points::<4>(),
        kinds in (0usize..3, 0usize..3),
    ) {
        let crossing = if crossing_q(p, r, s, w).0.is_positive() {
            Circle::Crossing([p, r, s, w])
        } else {
            Circle::Crossing([r, p, s, w])
        };
        prop_assume!(!crossing_q(p, r, s, w).0.is_zero());
        let pick = |k: usize, t: [Point2; 3]| match k {
            0 => Circle::Circumcircle(t),
            1 => crossing,
            _ => Circle::Point,
        };
        let (c1, c2) = (pick(kinds.0, t1), pick(kinds.1, t2));
        let (a, b) = (squared_radius(&c1), squared_radius(&c2));
        let expected = radius_q(&c1).cmp(&radius_q(&c2));
        prop_assert_eq!(a.cmp(&b), expected);
        prop_assert_eq!(b.cmp(&a), expected.reverse());
    }
}

proptest! {
    // Each case compares up to 25 pairs of circles.
    #![proptest_config(cases(120))]

    #[test]
    fn squared_radii_tie_exactly(
        (pts, t, e) in lattice_circle(6), shift in (-30i32..30, -30i32..30),
        dir in 0usize..12, len in 1i32..100, nudge in -2i32..3,
    ) {
        // One lattice circle through several triples, a translate (integer offsets:
        // exact) and a crossing at its centre all have radius 65 · 2^e; a nudged
        // vertex breaks the tie by a few ulps.
        let tri = [pts[0], pts[1], pts[2]];
        let other = [pts[3], pts[4], pts[5]];
        let moved = tri.map(|v| Point2::new(
            v.x + scale_by_pow2(shift.0 as f64, e),
            v.y + scale_by_pow2(shift.1 as f64, e),
        ));
        let centre = place((0.0, 0.0), t, e);
        let (dx, dy) = (LATTICE[dir].0 * len as f64, LATTICE[dir].1 * len as f64);
        let p = Point2::new(centre.x - scale_by_pow2(dx, e), centre.y - scale_by_pow2(dy, e));
        let r = Point2::new(centre.x + scale_by_pow2(dx, e), centre.y + scale_by_pow2(dy, e));
        let (p, r) = if crossing_q(p, r, pts[0], pts[1]).0.is_positive() { (p, r) } else { (r, p) };
        let mut circles = vec![Circle::Circumcircle(tri), Circle::Circumcircle(other)];
        if moved.iter().all(|v| v.is_finite()) {
            circles.push(Circle::Circumcircle(moved));
        }
        if !crossing_q(p, r, pts[0], pts[1]).0.is_zero() {
            circles.push(Circle::Crossing([p, r, pts[0], pts[1]]));
        }
        let nudged = [pts[0], pts[1], Point2::new(ulps(pts[2].x, nudge), pts[2].y)];
        if super::super::orient2d(nudged[0], nudged[1], nudged[2]) != Orientation::Collinear {
            circles.push(Circle::Circumcircle(nudged));
        }
        for c1 in &circles {
            for c2 in &circles {
                let expected = radius_q(c1).cmp(&radius_q(c2));
                prop_assert_eq!(squared_radius(c1).cmp(&squared_radius(c2)), expected);
            }
        }
        prop_assert_eq!(squared_radius(&circles[0]).cmp(&squared_radius(&circles[1])), Ordering::Equal);
    }
}

#[test]
fn filters_decide_ordinary_input_without_the_exact_stage() {
    // Triangles of ordinary shape at ordinary and extreme magnitudes: the filters'
    // bounds are finite and tight (the centre's up to the absolute slack 2^-1000,
    // which is why the algorithm scales its input to magnitudes near 1 first), so the
    // exact stage is not needed.
    for s in [
        1.0,
        2f64.powi(-400),
        1e300,
        1e-300,
        scale_by_pow2(1.0, -1060),
    ] {
        let p = |x: f64, y: f64| Point2::new(x * s, y * s);
        let x = Circumcentre::new(p(0.1, 0.2), p(3.7, -1.1), p(2.0, 5.5));
        let tight = |err: f64, v: f64| err <= 1e-14 * v.abs() + 2.0 * SLACK;
        assert!(tight(x.err_x, x.x) && tight(x.err_y, x.y), "{x:?}");
        if s == 1.0 {
            let (o, q) = (Point2::new(0.0, 0.0), Point2::new(1.0, 0.0));
            let det = |v: f64| v.abs() > 1e-13;
            assert!(det(x.x) && det(x.y));
            // Decided by the filter: the bound is far below |det|.
            assert_eq!(x.orient(o, q), Orientation::from_sign(x.y.signum() as i32));
        }
        let r2 = x.squared_radius().approx.expect("filtered");
        assert!(r2.rel < 1e-14);
        let c = SquaredRadius::crossing(p(0.0, 0.0), p(4.0, 0.0), p(1.0, 1.0), p(3.0, 2.0));
        assert!(c.approx.expect("filtered").rel < 1e-14);
    }
    // A triangle whose determinant (an ulp's worth, 2^-52 / 3) is below its rounding
    // bound gives up: its bounds are infinite, never wrong, and the exact stage
    // answers. The angle at b is nearly straight, so the centre is far on the other
    // side of a c from b: left of the diagonal, on which b lies.
    let t = [
        (0.0, 0.0),
        (1.0 / 3.0, 1.0 / 3.0),
        (1.0, 1.0 + f64::EPSILON),
    ];
    let [a, b, c] = t.map(Point2::from);
    let flat = Circumcentre::new(a, b, c);
    assert!(flat.err_x.is_infinite() && flat.squared_radius().approx.is_none());
    let (o, diagonal) = (Point2::new(0.0, 0.0), Point2::new(1.0, 1.0));
    assert_eq!(flat.orient(o, diagonal), Orientation::CounterClockwise);
    assert_eq!(
        flat.orient(o, diagonal),
        orient_oracle([a, b, c], o, diagonal)
    );
}

proptest! {
    #![proptest_config(cases(300))]

    #[test]
    fn products_of_exact_doubles_compare_exactly(
        // Full 53-bit mantissas (the limbs) or small odd parts (one u128).
        v in proptest::array::uniform10(prop_oneof![1u64..1 << 53, 1u64..40]),
        e in proptest::array::uniform10(-1074i32..971),
        same in any::<bool>(),
    ) {
        // Positive doubles m · 2^e, the right side a permutation of the left (equal
        // products) or arbitrary; the exponents of both sides are offset freely.
        let x = |i: usize| scale_by_pow2(v[i] as f64, e[i].max(-1074 - 52 + 53) - 52);
        let lhs = [x(0), x(1), x(2), x(3), x(4)];
        let rhs = if same { [x(3), x(0), x(4), x(2), x(1)] } else { [x(5), x(6), x(7), x(8), x(9)] };
        prop_assume!(lhs.iter().chain(&rhs).all(|&d| d > 0.0 && d.is_finite()));
        let (e1, e2) = (e[5] % 300, e[6] % 300);
        let exact = |f: [f64; 5], k: i32| {
            f.iter().fold(q(1.0), |acc, &d| acc * q(d)) * q(2.0).pow(k)
        };
        prop_assert_eq!(cmp_products(lhs, e1, rhs, e2), exact(lhs, e1).cmp(&exact(rhs, e2)));
    }

    #[test]
    fn grid_triangles_compare_exactly_without_big_integers(
        t in proptest::array::uniform6(-(1i64 << 24)..(1 << 24)),
        u in proptest::array::uniform6(-(1i64 << 24)..(1 << 24)),
        small in any::<bool>(),
        e in exponent_choice(),
        shift in proptest::array::uniform2(-(1i64 << 30)..(1 << 30)),
    ) {
        // Integer triangles, spread up to 2^25 (the frame's spacing then reaches the
        // 2^-24 limit) or within a few units, scaled by 2^e and translated by a
        // multiple of it (exact).
        let tri = |v: [i64; 6]| {
            let r = |k: i64| if small { k % 7 } else { k };
            let p = |x: i64, y: i64| Point2::new(
                scale_by_pow2((r(x) + shift[0]) as f64, e),
                scale_by_pow2((r(y) + shift[1]) as f64, e),
            );
            [p(v[0], v[1]), p(v[2], v[3]), p(v[4], v[5])]
        };
        let (t1, t2) = (tri(t), tri(u));
        for t in [t1, t2] {
            prop_assume!(super::super::orient2d(t[0], t[1], t[2]) != Orientation::Collinear);
        }
        let expected = radius_q(&Circle::Circumcircle(t1)).cmp(&radius_q(&Circle::Circumcircle(t2)));
        if let (Some(f1), Some(f2)) = (GridFactors::new(t1), GridFactors::new(t2)) {
            prop_assert_eq!(f1.cmp(&f2), expected);
        } else {
            // Only spreads beyond the 2^-24 spacing leave the grid path.
            prop_assert!(!small);
        }
        let (a, b) = (squared_radius(&Circle::Circumcircle(t1)), squared_radius(&Circle::Circumcircle(t2)));
        prop_assert_eq!(a.cmp(&b), expected);
    }
}

/// Lattice points of x² + y² = R² for R the product of the primes `a² + b²` given by
/// their Gaussian factors `a + b i`: `Π (a + ε b i)²` for every choice of signs ε.
fn lattice_circle_of(primes: &[(i64, i64)]) -> (Vec<Point2>, i64) {
    let r = primes.iter().map(|&(a, b)| a * a + b * b).product::<i64>();
    let pts = (0..1u32 << primes.len())
        .map(|signs| {
            let (mut x, mut y) = (1i64, 0i64);
            for (i, &(a, b)) in primes.iter().enumerate() {
                let b = if signs >> i & 1 == 1 { -b } else { b };
                // (a + b i)² = (a² − b²) + 2ab i
                let (u, v) = (a * a - b * b, 2 * a * b);
                (x, y) = (x * u - y * v, x * v + y * u);
            }
            assert_eq!(
                x as i128 * x as i128 + y as i128 * y as i128,
                (r as i128).pow(2)
            );
            (x as f64, y as f64)
        })
        // Every such point has x odd and y even or the other way round, the same for
        // all; their mirror images in y = x have the other parity, so differences
        // between the two kinds are odd: the finest spacing.
        .flat_map(|(x, y)| [Point2::new(x, y), Point2::new(y, x)])
        .collect();
    (pts, r)
}

/// Triangles of points of one lattice circle, every one with the circle's radius.
fn circle_triangles(pts: &[Point2]) -> Vec<[Point2; 3]> {
    let n = pts.len();
    let triangles: Vec<[Point2; 3]> = (0..n / 3)
        .map(|i| [pts[i], pts[i + n / 3 + 1], pts[i + 2 * n / 3]])
        .filter(|t| super::super::orient2d(t[0], t[1], t[2]) != Orientation::Collinear)
        .collect();
    assert!(triangles.len() >= 5);
    triangles
}

#[test]
fn circles_through_lattice_circles_tie() {
    // R = 5 · 13 · 17 · 29 · 37 (about 2^20): differences within the grid path's
    // spacing, which must find every tie by itself.
    let (pts, r) = lattice_circle_of(&[(2, 1), (3, 2), (4, 1), (5, 2), (6, 1)]);
    let triangles = circle_triangles(&pts);
    let f0 = GridFactors::new(triangles[0]).expect("on the grid path");
    for t in &triangles {
        assert_eq!(radius_q(&Circle::Circumcircle(*t)), q((r * r) as f64));
        let f = GridFactors::new(*t).expect("on the grid path");
        assert_eq!(f.cmp(&f0), Ordering::Equal, "{t:?}");
    }
    // R = 5 · 13 · 17 · 29 · 37 · 41 (about 2^25.5): differences up to 2^26.5, beyond
    // the spacing (where squared lengths would round), so the exact stage answers.
    let (pts, r) = lattice_circle_of(&[(2, 1), (3, 2), (4, 1), (5, 2), (6, 1), (5, 4)]);
    let triangles = circle_triangles(&pts);
    let first = squared_radius(&Circle::Circumcircle(triangles[0]));
    for t in &triangles {
        let c = Circle::Circumcircle(*t);
        assert_eq!(radius_q(&c), q(r as f64) * q(r as f64));
        assert_eq!(squared_radius(&c).cmp(&first), Ordering::Equal, "{t:?}");
    }
}

proptest! {
    #![proptest_config(cases(1000))]

    #[test]
    fn grid_factors_agree_from_every_vertex(
        a in proptest::array::uniform2(-(1i64 << 30)..(1 << 30)),
        b in proptest::array::uniform2(-(1i64 << 26)..(1 << 26)),
        c in proptest::array::uniform2(-(1i64 << 26)..(1 << 26)),
        flat in any::<bool>(),
    ) {
        // One triangle listed from each vertex: three frames, one radius. Differences
        // up to 2^26 reach beyond the spacing limit; `flat` makes the angle at `a`
        // nearly straight, where |b − c|² is largest in the frame.
        let c = if flat { [-b[0] + c[0] % 64, -b[1] + c[1] % 64] } else { c };
        let p = |d: [i64; 2]| Point2::new((a[0] + d[0]) as f64, (a[1] + d[1]) as f64);
        let t = [p([0, 0]), p(b), p(c)];
        prop_assume!(super::super::orient2d(t[0], t[1], t[2]) != Orientation::Collinear);
        let rotations = [t, [t[1], t[2], t[0]], [t[2], t[0], t[1]], [t[0], t[2], t[1]]];
        let mut found = Vec::new();
        for [a, b, c] in rotations {
            let Some(f) = GridFactors::new([a, b, c]) else { continue };
            // Every factor is the exact value in the frame.
            let frame = q(2.0).pow(2 * f.k);
            let [a, b, c] = [a, b, c].map(qp);
            let mut l = [dist2(&b, &c), dist2(&a, &b), dist2(&a, &c)].map(|v| v * &frame);
            l.sort();
            prop_assert_eq!(f.l.map(q), l);
            prop_assert_eq!(q(f.hd), cross(&a, &b, &c).abs() * &frame);
            found.push(f);
        }
        for f in &found {
            prop_assert_eq!(f.cmp(&found[0]), Ordering::Equal);
        }
    }
}

#[test]
fn products_with_equal_leading_bits_compare_by_their_tails() {
    // a · 2^0 against b · 2^s for small odd a, b (the u128 path) and for mantissas
    // of 53 bits (the limbs): the leading bits often coincide while the exponents
    // differ, so the alignment decides.
    for wide in [false, true] {
        for a in (1u64..64).step_by(2) {
            for b in (1u64..64).step_by(2) {
                for s in -3i32..=3 {
                    // Three 53-bit factors exceed the u128.
                    let m = |v: u64| if wide { (v << 47) + 1 } else { v } as f64;
                    let lhs = [m(a), m(5), 1.0, m(3), 1.0];
                    let rhs = [m(b), m(3), 1.0, m(5), 1.0];
                    let expected = (q(m(a))).cmp(&(q(m(b)) * q(2.0).pow(s)));
                    assert_eq!(cmp_products(lhs, 0, rhs, s), expected, "{a} {b} {s} {wide}");
                    assert_eq!(cmp_products(rhs, s, lhs, 0), expected.reverse());
                }
            }
        }
    }
}

#[test]
fn grid_factors_take_lattices_and_refuse_rounded_differences() {
    let p = |x: f64, y: f64| Point2::new(x, y);
    // A unit right triangle far from the origin: r² = 1/2 exactly.
    let t = [p(1e15, 7.0), p(1e15 + 1.0, 7.0), p(1e15, 8.0)];
    let f = GridFactors::new(t).expect("lattice");
    assert_eq!((f.l, f.hd), ([1.0, 1.0, 2.0], 1.0));
    // 1 − 2^-60 is not representable: the difference rounds, so no grid factors.
    assert!(GridFactors::new([p(1.0, 0.0), p(2f64.powi(-60), 0.0), p(0.0, 1.0)]).is_none());
    // A difference below 2^-24 of the largest cannot be a multiple of the spacing.
    assert!(GridFactors::new([p(0.0, 0.0), p(1.0, 0.0), p(0.5, 2f64.powi(-30))]).is_none());
}

#[test]
fn approximations_compare_across_exponents() {
    let a = Approx::new(1.5, 10, 0.2).unwrap();
    let b = Approx::new(1.0, 12, 0.2).unwrap();
    assert_eq!(a.cmp(&b), Some(Ordering::Less));
    assert_eq!(b.cmp(&a), Some(Ordering::Greater));
    // 1.5 · 2^11 = 3 · 2^10 against 1.5 · 2^10 within 20 %: decided.
    let c = Approx::new(3.0, 10, 0.2).unwrap();
    assert_eq!(c.exp, 11);
    assert_eq!(c.cmp(&a), Some(Ordering::Greater));
    // Overlapping enclosures decide nothing, also one binade apart: 2 · 2^10 (stored
    // as 1 · 2^11) against 1.9 · 2^10.
    let d = Approx::new(1.6, 10, 0.2).unwrap();
    assert_eq!(d.cmp(&a), None);
    let (e, f) = (
        Approx::new(2.0, 10, 0.01).unwrap(),
        Approx::new(1.9, 10, 0.1).unwrap(),
    );
    assert_eq!((e.exp, e.cmp(&f), f.cmp(&e)), (11, None, None));
    assert!(Approx::new(0.0, 0, 0.0).is_none() && Approx::new(1.0, 0, 0.3).is_none());
}
