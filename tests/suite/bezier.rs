//! Properties of the Bernstein basis and of Bézier curves, checked exactly on the rational
//! back end (so every identity holds with `==`), plus the `f64` path against it, the
//! convex-hull property with exact orientations, degenerate and bad input, and the CLI.

use crate::spline_common::{q, Q};
use compgeo::count::Counts;
use compgeo::geometry::Point2;
use compgeo::hull::{monotone_chain, HullOptions};
use compgeo::spline::{
    bernstein, bernstein_all, bernstein_derivative, intersections, Bezier, Curve, CurveDerivative,
    Finite, Point, Scalar,
};
use compgeo::Error;
use proptest::prelude::*;

fn qp<const D: usize>(c: [(i64, i64); D]) -> Point<Q, D> {
    Point::new(c.map(|(n, d)| q(n, d)))
}

/// A rational in [-range, range] with a small denominator.
fn rational(range: i64) -> impl Strategy<Value = Q> {
    (1i64..=12).prop_flat_map(move |d| (-range * d..=range * d).prop_map(move |n| q(n, d)))
}

/// A parameter: mostly in [0, 1], sometimes outside.
fn parameter() -> impl Strategy<Value = Q> {
    prop_oneof![
        3 => (0i64..=24, 1i64..=24).prop_map(|(n, d)| q(n.min(d), d)),
        1 => rational(3),
    ]
}

fn rational_curve(max_degree: usize) -> impl Strategy<Value = Bezier<Q, 2>> {
    prop::collection::vec((rational(20), rational(20)), 1..=max_degree + 1).prop_map(|pts| {
        Bezier::new(pts.into_iter().map(|(x, y)| Point::new([x, y])).collect()).unwrap()
    })
}

fn f64_curve(max_degree: usize) -> impl Strategy<Value = Bezier<f64, 2>> {
    prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 1..=max_degree + 1).prop_map(|pts| {
        Bezier::new(pts.into_iter().map(|(x, y)| Point::new([x, y])).collect()).unwrap()
    })
}

fn sum<const D: usize>(points: impl IntoIterator<Item = Point<Q, D>>) -> Point<Q, D> {
    points.into_iter().fold(Point::zero(), |a, b| a + b)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn bernstein_is_a_symmetric_partition_of_unity(n in 0usize..12, t in parameter()) {
        let all = bernstein_all(n, &t).unwrap();
        let total = all.iter().cloned().fold(Q::zero(), |a, b| a + b);
        prop_assert_eq!(total, Q::one());
        let mirrored = bernstein_all(n, &(Q::one() - &t)).unwrap();
        for i in 0..=n {
            prop_assert_eq!(&all[i], &mirrored[n - i]);
            prop_assert_eq!(&all[i], &bernstein(n, i, &t).unwrap());
        }
    }

    #[test]
    fn bernstein_derivative_is_the_difference_of_lower_degree(
        n in 1usize..10, i in 0usize..10, t in parameter()
    ) {
        // d/dt Bᵢⁿ = n (Bᵢ₋₁ⁿ⁻¹ − Bᵢⁿ⁻¹), and the second derivative applies it twice.
        let lower = |k: isize, m: usize| if k < 0 { Q::zero() } else { bernstein(m, k as usize, &t).unwrap() };
        let ii = i as isize;
        let expected = Q::from_i64(n as i64) * (lower(ii - 1, n - 1) - lower(ii, n - 1));
        prop_assert_eq!(bernstein_derivative(n, i, 1, &t).unwrap(), expected);
        if n >= 2 {
            let second = Q::from_i64((n * (n - 1)) as i64)
                * (lower(ii - 2, n - 2) - lower(ii - 1, n - 2) - lower(ii - 1, n - 2) + lower(ii, n - 2));
            prop_assert_eq!(bernstein_derivative(n, i, 2, &t).unwrap(), second);
        }
    }

    #[test]
    fn de_casteljau_equals_horner_equals_the_bernstein_sum(b in rational_curve(7), t in parameter()) {
        let n = b.degree();
        let basis = bernstein_all(n, &t).unwrap();
        let direct = sum(b.control().iter().zip(&basis).map(|(p, w)| p.clone() * w));
        let mut dc = Counts::default();
        let mut ho = Counts::default();
        prop_assert_eq!(&b.de_casteljau_with(&t, &mut dc).unwrap(), &direct);
        prop_assert_eq!(&b.horner_with(&t, &mut ho).unwrap(), &direct);
        prop_assert_eq!(&b.eval(&t).unwrap(), &direct);
        prop_assert_eq!(dc.arithmetic_operations, (n * (n + 1) / 2) as u64);
        prop_assert_eq!(ho.arithmetic_operations, (n + 1) as u64);
    }

    #[test]
    fn batch_and_prevalidated_evaluation_equal_eval(
        b in rational_curve(5), ts in prop::collection::vec(parameter(), 0..12),
        fb in f64_curve(5), fts in prop::collection::vec(-3.0f64..4.0, 0..12),
    ) {
        let mut got = Vec::new();
        b.eval_each(&ts, |p| got.push(p)).unwrap();
        let want: Vec<_> = ts.iter().map(|t| b.eval(t).unwrap()).collect();
        prop_assert_eq!(got, want);
        let mut got = Vec::new();
        fb.eval_each(&fts, |p| got.push(p)).unwrap();
        for (p, t) in got.iter().zip(&fts) {
            prop_assert_eq!(*p, fb.eval(t).unwrap());
            prop_assert_eq!(*p, fb.at(&Finite::new(*t, "t").unwrap()));
        }
    }

    #[test]
    fn endpoints_are_interpolated_and_reversal_mirrors(b in rational_curve(7), t in parameter()) {
        let n = b.degree();
        prop_assert_eq!(&b.eval(&Q::zero()).unwrap(), &b.control()[0]);
        prop_assert_eq!(&b.eval(&Q::one()).unwrap(), &b.control()[n]);
        prop_assert_eq!(b.reversed().eval(&(Q::one() - &t)).unwrap(), b.eval(&t).unwrap());
    }

    #[test]
    fn affine_maps_commute_with_evaluation(
        b in rational_curve(6), t in parameter(),
        m in prop::array::uniform4(rational(3)), c in prop::array::uniform2(rational(5)),
    ) {
        let map = |p: &Point<Q, 2>| Point::new([
            m[0].clone() * &p[0] + m[1].clone() * &p[1] + &c[0],
            m[2].clone() * &p[0] + m[3].clone() * &p[1] + &c[1],
        ]);
        let image = Bezier::new(b.control().iter().map(map).collect()).unwrap();
        prop_assert_eq!(image.eval(&t).unwrap(), map(&b.eval(&t).unwrap()));
    }

    #[test]
    fn split_pieces_evaluate_to_the_original(b in rational_curve(7), c in parameter(), s in parameter()) {
        let (left, right) = b.split(&c).unwrap();
        prop_assert_eq!(left.eval(&s).unwrap(), b.eval(&(c.clone() * &s)).unwrap());
        let on_right = c.clone() + (Q::one() - &c) * &s;
        prop_assert_eq!(right.eval(&s).unwrap(), b.eval(&on_right).unwrap());
        prop_assert_eq!(left.degree(), b.degree());
        prop_assert_eq!(&left.control()[b.degree()], &right.control()[0]);
    }

    #[test]
    fn restriction_and_reparametrisation_agree_with_the_curve(
        b in rational_curve(6), lo in rational(2), width in (1i64..=40).prop_map(|k| q(k, 8)),
        s in parameter(),
    ) {
        let hi = lo.clone() + &width;
        let r = b.restrict(&lo, &hi).unwrap();
        let u = (Q::one() - &s) * &lo + s.clone() * &hi;
        prop_assert_eq!(r.eval(&s).unwrap(), b.eval(&u).unwrap());
        // Reparametrised to [lo, hi], the point at the global u is the curve's at local s,
        // and derivatives scale by 1/(hi − lo)^r.
        let on = b.clone().reparametrise(lo.clone(), hi.clone()).unwrap();
        prop_assert_eq!(on.eval(&u).unwrap(), b.eval(&s).unwrap());
        for order in 0..3u32 {
            let scale = num_traits::pow(width.clone(), order as usize);
            prop_assert_eq!(
                on.derivative_at(&u, order as usize).unwrap() * &scale,
                b.derivative_at(&s, order as usize).unwrap()
            );
        }
    }

    #[test]
    fn elevation_leaves_the_curve_unchanged(b in rational_curve(6), extra in 0usize..5, t in parameter()) {
        let once = b.elevate().unwrap();
        prop_assert_eq!(once.degree(), b.degree() + 1);
        prop_assert_eq!(once.eval(&t).unwrap(), b.eval(&t).unwrap());
        let m = b.degree() + extra;
        let zhou = b.elevate_to(m).unwrap();
        prop_assert_eq!(zhou.degree(), m);
        prop_assert_eq!(zhou.eval(&t).unwrap(), b.eval(&t).unwrap());
        prop_assert_eq!(b.elevate_to(b.degree() + 1).unwrap(), once);
        prop_assert_eq!(b.elevate_to(b.degree()).unwrap(), b.clone());
    }

    #[test]
    fn monomial_conversion_round_trips(b in rational_curve(7), t in parameter()) {
        let a = b.to_monomial();
        // Σ aᵢ tⁱ by Horner's rule in the power basis.
        let mut value = Point::zero();
        for ai in a.iter().rev() {
            value = value * &t + ai;
        }
        prop_assert_eq!(&value, &b.eval(&t).unwrap());
        prop_assert_eq!(Bezier::from_monomial(&a).unwrap(), b);
    }

    #[test]
    fn blossom_is_symmetric_multi_affine_and_the_curve_on_its_diagonal(
        b in rational_curve(6), args in prop::collection::vec(parameter(), 6),
        v in parameter(), alpha in parameter(), rot in 0usize..6,
    ) {
        let n = b.degree();
        let args = &args[..n];
        let value = b.blossom(args).unwrap();
        let mut permuted = args.to_vec();
        permuted.reverse();
        if n > 0 {
            permuted.rotate_left(rot % n);
        }
        prop_assert_eq!(&b.blossom(&permuted).unwrap(), &value);
        if n > 0 {
            // Affine in the first argument (hence in each, by symmetry).
            let mut with_v = args.to_vec();
            with_v[0] = v.clone();
            let mut mixed = args.to_vec();
            mixed[0] = alpha.clone() * &args[0] + (Q::one() - &alpha) * &v;
            let lhs = b.blossom(&mixed).unwrap();
            let rhs = Point::combine(&value, &alpha, &b.blossom(&with_v).unwrap(), &(Q::one() - &alpha));
            prop_assert_eq!(lhs, rhs);
        }
        let diagonal = vec![v.clone(); n];
        prop_assert_eq!(b.blossom(&diagonal).unwrap(), b.eval(&v).unwrap());
        // The fundamental theorem: bᵢ = b[0, …, 0, 1, …, 1] with i ones.
        for i in 0..=n {
            let mut corner = vec![Q::zero(); n - i];
            corner.extend(std::iter::repeat_n(Q::one(), i));
            prop_assert_eq!(&b.blossom(&corner).unwrap(), &b.control()[i]);
        }
    }

    #[test]
    fn derivative_identities(b in rational_curve(7), t in parameter(), r in 0usize..5) {
        let n = b.degree();
        // The tetrahedral algorithm agrees with the derivative curve at every order.
        prop_assert_eq!(b.derivative_at(&t, r).unwrap(), b.derivative(r).unwrap().eval(&t).unwrap());
        // The hodograph is the derivative of order one, with end values n Δb₀ and n Δbₙ₋₁.
        let h = b.hodograph().unwrap();
        prop_assert_eq!(&h, &b.derivative(1).unwrap());
        if n >= 1 {
            let nq = Q::from_i64(n as i64);
            let c = b.control();
            prop_assert_eq!(h.eval(&Q::zero()).unwrap(), (c[1].clone() - &c[0]) * &nq);
            prop_assert_eq!(h.eval(&Q::one()).unwrap(), (c[n].clone() - &c[n - 1]) * &nq);
        }
        // Differentiating twice is the second derivative; the integral differentiates back.
        prop_assert_eq!(b.derivative(1).unwrap().derivative(1).unwrap(), b.derivative(2).unwrap());
        let integral = b.integral(Point::zero()).unwrap();
        prop_assert_eq!(integral.hodograph().unwrap(), b.clone());
        prop_assert_eq!(integral.eval(&Q::one()).unwrap(), b.definite_integral());
    }

    #[test]
    fn forward_differences_equal_evaluation(b in rational_curve(6), start in rational(2), step in rational(1), count in 0usize..20) {
        let points = b.forward_differences(&start, &step, count).unwrap();
        prop_assert_eq!(points.len(), count);
        for (i, p) in points.iter().enumerate() {
            let t = start.clone() + Q::from_i64(i as i64) * &step;
            prop_assert_eq!(p, &b.eval(&t).unwrap());
        }
    }

    #[test]
    fn bounding_box_contains_the_curve_segment(b in rational_curve(7), t in (0i64..=16).prop_map(|k| q(k, 16))) {
        let (lo, hi) = b.bounding_box();
        let p = b.eval(&t).unwrap();
        for j in 0..2 {
            prop_assert!(lo[j] <= p[j] && p[j] <= hi[j]);
        }
    }

    /// The convex-hull property, with the hull from `compgeo::hull` and exact orientations:
    /// the curve's exact value at an `f64` parameter in [0, 1] is left of or on every hull edge.
    #[test]
    fn curve_segment_lies_in_the_convex_hull_of_its_polygon(b in f64_curve(7), t in 0.0f64..=1.0) {
        let pts: Vec<Point2> = b.control().iter().map(|&p| p.into()).collect();
        let hull = monotone_chain(&pts, HullOptions::default()).unwrap();
        let exact = Bezier::<Q, 2>::from_f64(&b);
        let p = exact.eval(&Q::from_f64(t).unwrap()).unwrap();
        let v: Vec<Point<Q, 2>> = hull.iter().map(|&i| exact.control()[i].clone()).collect();
        match v.len() {
            1 => prop_assert_eq!(&p, &v[0]),
            _ => {
                for k in 0..v.len() {
                    let (a, c) = (&v[k], &v[(k + 1) % v.len()]);
                    let cross = (c[0].clone() - &a[0]) * (p[1].clone() - &a[1])
                        - (c[1].clone() - &a[1]) * (p[0].clone() - &a[0]);
                    if v.len() == 2 {
                        prop_assert!(cross == Q::zero());
                    } else {
                        prop_assert!(cross >= Q::zero(), "edge {k} has the point on its right");
                    }
                }
                let (lo, hi) = exact.bounding_box();
                prop_assert!(lo[0] <= p[0] && p[0] <= hi[0] && lo[1] <= p[1] && p[1] <= hi[1]);
            }
        }
    }

    /// The f64 path is within rounding of the exact value, for both evaluation schemes.
    #[test]
    fn f64_evaluation_is_close_to_exact(b in f64_curve(7), t in -0.5f64..1.5) {
        let exact = Bezier::<Q, 2>::from_f64(&b).eval(&Q::from_f64(t).unwrap()).unwrap().to_f64();
        let scale = b.control().iter().map(|p| p[0].abs().max(p[1].abs())).fold(1.0, f64::max)
            * 3f64.powi(b.degree() as i32);
        for p in [b.eval(&t).unwrap(), b.de_casteljau(&t).unwrap()] {
            for j in 0..2 {
                prop_assert!((p[j] - exact[j]).abs() <= 1e-13 * scale, "{} vs {}", p[j], exact[j]);
            }
        }
    }

    /// The flattened polyline is within the tolerance of the curve (Euclidean distance ≤ √2
    /// times the sup-norm bound of the course).
    #[test]
    fn flattening_is_within_tolerance(b in f64_curve(5), tol in 0.05f64..20.0) {
        let poly = b.flatten(&tol).unwrap();
        prop_assert_eq!(poly[0], b.control()[0]);
        prop_assert_eq!(*poly.last().unwrap(), b.control()[b.degree()]);
        for k in 0..=200 {
            let p = b.eval(&(k as f64 / 200.0)).unwrap();
            let d = poly.windows(2).map(|w| segment_distance(p, w[0], w[1])).fold(f64::INFINITY, f64::min);
            let d = if poly.len() == 1 { segment_distance(p, poly[0], poly[0]) } else { d };
            prop_assert!(d <= tol * std::f64::consts::SQRT_2 * (1.0 + 1e-9) + 1e-9, "distance {d} > {tol}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// A cubic against a horizontal line: every reported hit is on both curves, and every
    /// clear sign change of b_y − y₀ on a grid (an oracle independent of subdivision) has a
    /// hit in its cell.
    #[test]
    fn intersections_with_a_line_are_found_and_lie_on_both_curves(
        b in f64_curve(4).prop_filter("degree ≥ 1", |b| b.degree() >= 1),
        y0 in -500.0f64..500.0,
    ) {
        let line = Bezier::new(vec![Point::new([-2e3, y0]), Point::new([2e3, y0])]).unwrap();
        let tol = 1e-7;
        let hits = intersections(&b, &line, tol).unwrap();
        for h in &hits {
            let p = b.eval(&h.s).unwrap();
            prop_assert!((p[1] - y0).abs() <= 1e-4, "hit off the line: {p:?} vs {y0}");
            let q = line.eval(&h.t).unwrap();
            prop_assert!((q[0] - p[0]).abs() <= 1e-4, "{q:?} vs {p:?}");
        }
        let grid = 400;
        let f = |k: usize| b.eval(&(k as f64 / grid as f64)).unwrap()[1] - y0;
        for k in 0..grid {
            let (a, z) = (f(k), f(k + 1));
            if a.abs() > 1e-3 && z.abs() > 1e-3 && (a < 0.0) != (z < 0.0) {
                let (lo, hi) = (k as f64 / grid as f64, (k + 1) as f64 / grid as f64);
                prop_assert!(
                    hits.iter().any(|h| h.s >= lo - 1e-6 && h.s <= hi + 1e-6),
                    "no hit in [{lo}, {hi}]: {hits:?}"
                );
            }
        }
    }
}

#[test]
fn intersections_of_lines_boxes_and_overlaps() {
    let l1 = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([4.0, 4.0])]).unwrap();
    let l2 = Bezier::new(vec![Point::new([0.0, 4.0]), Point::new([4.0, 0.0])]).unwrap();
    let hits = intersections(&l1, &l2, 1e-9).unwrap();
    assert_eq!(hits.len(), 1);
    assert_eq!((hits[0].s, hits[0].t), (0.5, 0.5));
    assert_eq!(hits[0].point, Point::new([2.0, 2.0]));
    // Disjoint boxes: nothing, even for curved pieces.
    let far = Bezier::new(vec![
        Point::new([10.0, 0.0]),
        Point::new([11.0, 5.0]),
        Point::new([12.0, 0.0]),
    ])
    .unwrap();
    assert!(intersections(&l1, &far, 1e-9).unwrap().is_empty());
    // Two cubics crossing in three points: the S-curve and the diagonal through its middle.
    let s_curve = Bezier::new(vec![
        Point::new([0.0, 0.0]),
        Point::new([0.0, 3.0]),
        Point::new([3.0, -3.0]),
        Point::new([3.0, 0.0]),
    ])
    .unwrap();
    let axis = Bezier::new(vec![Point::new([-1.0, 0.0]), Point::new([4.0, 0.0])]).unwrap();
    let hits = intersections(&s_curve, &axis, 1e-12).unwrap();
    let s: Vec<f64> = hits.iter().map(|h| h.s).collect();
    // y(s) = 9s(1−s)² − 9s²(1−s) = 9s(1−s)(1−2s): roots 0, 1/2, 1.
    assert_eq!(s.len(), 3, "{hits:?}");
    for (got, want) in s.iter().zip([0.0, 0.5, 1.0]) {
        assert!((got - want).abs() < 1e-9, "{s:?}");
    }
    // A curve against itself overlaps everywhere: an error, not an endless search.
    assert!(matches!(
        intersections(&s_curve, &s_curve, 1e-12),
        Err(Error::InvalidParameter {
            name: "tolerance",
            ..
        })
    ));
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(intersections(&l1, &l2, bad).is_err());
    }
}

fn segment_distance(p: Point<f64, 2>, a: Point<f64, 2>, b: Point<f64, 2>) -> f64 {
    let ab = b - a;
    let len2 = ab.norm_squared();
    let s = if len2 == 0.0 {
        0.0
    } else {
        ((p - a).dot(&ab) / len2).clamp(0.0, 1.0)
    };
    let closest = a + ab * s;
    (p - closest).norm_squared().sqrt()
}

/// [RD, §3.2]: moving P₁ of a cubic moves the curve by at most 4/9 of the displacement, because
/// max B₁³ on [0, 1] is 4/9, attained at t = 1/3.
#[test]
fn max_of_b13_on_the_unit_interval_is_four_ninths() {
    let third = q(1, 3);
    assert_eq!(bernstein(3, 1, &third).unwrap(), q(4, 9));
    assert_eq!(bernstein_derivative(3, 1, 1, &third).unwrap(), Q::zero());
    // B₁³ increases before 1/3 and decreases after, and stays below 4/9 on a fine grid.
    assert!(bernstein_derivative(3, 1, 1, &q(1, 4)).unwrap() > Q::zero());
    assert!(bernstein_derivative(3, 1, 1, &q(1, 2)).unwrap() < Q::zero());
    for k in 0..=300 {
        let t = q(k, 300);
        assert!(bernstein(3, 1, &t).unwrap() <= q(4, 9), "t = {k}/300");
    }
    // The consequence for curves: the difference of two cubics that differ in P₁.
    let base = [(0, 1), (5, 1), (3, 1), (9, 1)];
    let c = Bezier::new(base.iter().map(|&(x, d)| qp([(x, d), (0, 1)])).collect()).unwrap();
    let mut moved = c.control().to_vec();
    moved[1] = qp([(5, 1), (9, 1)]);
    let m = Bezier::new(moved).unwrap();
    assert_eq!(
        m.eval(&third).unwrap() - &c.eval(&third).unwrap(),
        qp([(0, 1), (4, 1)])
    );
}

#[test]
fn linear_precision_and_the_seeds_conversion_formula() {
    // [PPB, §2.8, Obs. 8]: a linear polynomial a₀ + a₁t has Bézier points a₀ + (j/n) a₁, here
    // elevated to degree 4 they are evenly spaced.
    let line = Bezier::from_monomial(&[qp([(1, 1), (2, 1)]), qp([(4, 1), (-8, 1)])]).unwrap();
    let e = line.elevate_to(4).unwrap();
    for (j, p) in e.control().iter().enumerate() {
        assert_eq!(p, &qp([(1 + j as i64, 1), (2 - 2 * j as i64, 1)]));
    }
}

/// Zhou's formula term by term, `dₖ = Σᵢ bᵢ C(n, i) C(m − n, k − i) / C(m, k)`, with exact
/// binomial coefficients: the oracle of [`Bezier::elevate_to`], which never forms them.
fn zhou_by_binomials(b: &Bezier<Q, 2>, m: usize) -> Vec<Point<Q, 2>> {
    let n = b.degree();
    let c = |n: usize, k: usize| -> Q {
        if k > n {
            return q(0, 1);
        }
        (0..k).fold(q(1, 1), |acc, j| acc * q((n - j) as i64, (j + 1) as i64))
    };
    (0..=m)
        .map(|k| {
            let mut d = Point::<Q, 2>::zero();
            for (i, bi) in b.control().iter().enumerate().take(k.min(n) + 1) {
                d += &(bi.clone() * (c(n, i) * c(m - n, k - i) / c(m, k)));
            }
            d
        })
        .collect()
}

#[test]
fn elevation_equals_zhous_binomial_formula_exactly() {
    for n in 0..6usize {
        let b = Bezier::new(
            (0..=n)
                .map(|i| qp([(3 * i as i64 - 4, 7), ((i * i) as i64 + 1, 5)]))
                .collect(),
        )
        .unwrap();
        for m in n..n + 10 {
            assert_eq!(
                b.elevate_to(m).unwrap().control(),
                zhou_by_binomials(&b, m),
                "n = {n}, m = {m}"
            );
        }
    }
}

#[test]
fn elevation_to_a_high_degree_stays_finite_and_on_the_curve() {
    // The binomial coefficients overflow f64 (a cubic to degree 1024 used to fail); the
    // weights never form them.
    let b = Bezier::new(vec![
        Point::new([0.0, 0.0]),
        Point::new([1.0, 2.0]),
        Point::new([3.0, 2.0]),
        Point::new([4.0, 0.0]),
    ])
    .unwrap();
    let e = b.elevate_to(5000).unwrap();
    assert_eq!(e.degree(), 5000);
    assert_eq!(
        (e.control()[0], e.control()[5000]),
        (b.control()[0], b.control()[3])
    );
    for k in 0..=20 {
        let t = k as f64 / 20.0;
        let (p, r) = (e.eval(&t).unwrap(), b.eval(&t).unwrap());
        for j in 0..2 {
            assert!(
                (p[j] - r[j]).abs() <= 1e-12 * 4.0,
                "t = {t}: {p:?} vs {r:?}"
            );
        }
    }
    // Every elevated point lies in the convex hull of the polygon: here in [0, 4] x [0, 2].
    assert!(e
        .control()
        .iter()
        .all(|p| (0.0..=4.0).contains(&p[0]) && (0.0..=2.0).contains(&p[1])));
}

#[test]
fn degrees_beyond_the_limit_are_errors_before_allocating() {
    use compgeo::limits::MAX_DEGREE;
    let line = Bezier::new(vec![Point::new([0.0]), Point::new([1.0])]).unwrap();
    assert_eq!(line.elevate_to(MAX_DEGREE).unwrap().degree(), MAX_DEGREE);
    for m in [MAX_DEGREE + 1, 1 << 32, usize::MAX] {
        match line.elevate_to(m) {
            Err(Error::LimitExceeded {
                limit: "MAX_DEGREE",
                value,
                max,
                ..
            }) => {
                assert_eq!((value, max), (m as u128, MAX_DEGREE))
            }
            other => panic!("m = {m}: {other:?}"),
        }
    }
    // Elevating a curve already at the limit, building one beyond it, the Bernstein basis,
    // derivative orders of a composite curve and sample counts.
    let top = line.elevate_to(MAX_DEGREE).unwrap();
    assert!(matches!(
        top.elevate(),
        Err(Error::LimitExceeded {
            limit: "MAX_DEGREE",
            ..
        })
    ));
    assert!(matches!(
        top.integral(Point::new([0.0])),
        Err(Error::LimitExceeded {
            limit: "MAX_DEGREE",
            ..
        })
    ));
    let too_many = vec![Point::new([0.0]); MAX_DEGREE + 2];
    assert!(matches!(
        Bezier::new(too_many),
        Err(Error::LimitExceeded {
            limit: "MAX_DEGREE",
            ..
        })
    ));
    assert!(matches!(
        bernstein_all(usize::MAX, &0.5),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        bernstein(usize::MAX, 3, &0.5),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        bernstein_derivative(MAX_DEGREE + 1, 3, 1, &0.5),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        line.forward_differences(&0.0, &0.1, usize::MAX),
        Err(Error::LimitExceeded {
            limit: "MAX_SAMPLES",
            ..
        })
    ));
    let composite =
        compgeo::spline::CompositeBezier::new(vec![0.0, 1.0], vec![line.control().to_vec()])
            .unwrap();
    assert!(matches!(
        composite.end_derivatives(0, true, usize::MAX),
        Err(Error::LimitExceeded {
            limit: "MAX_DEGREE",
            ..
        })
    ));
    assert_eq!(composite.end_derivatives(0, true, 3).unwrap().len(), 4);
}

#[test]
fn huge_and_subnormal_coordinates_evaluate_finitely() {
    let b = Bezier::new(vec![
        Point::new([1e307, 5e-324]),
        Point::new([-1.5e307, 1e307]),
        Point::new([1.7e307, -1e-310]),
        Point::new([1e307, 1.7e307]),
        Point::new([-1e307, 0.0]),
        Point::new([1.6e307, 1e300]),
        Point::new([1e307, -1.7e307]),
        Point::new([-1.7e307, 5e-324]),
    ])
    .unwrap();
    let exact = Bezier::<Q, 2>::from_f64(&b);
    for k in 0..=16 {
        let t = k as f64 / 16.0;
        let p = b.eval(&t).unwrap();
        assert!(p.is_finite(), "t = {t}: {p:?}");
        let e = exact.eval(&Q::from_f64(t).unwrap()).unwrap().to_f64();
        for j in 0..2 {
            assert!((p[j] - e[j]).abs() <= 1e294, "t = {t}");
        }
    }
    assert_eq!(b.eval(&0.0).unwrap(), b.control()[0]);
    assert_eq!(b.eval(&1.0).unwrap(), b.control()[7]);
    // A cubic whose Horner steps overflow (3·1.7e308): the batch path must notice.
    let big = Bezier::new(vec![
        Point::new([0.0, 1.7e308]),
        Point::new([1.7e308, -1.7e308]),
        Point::new([-1.7e308, 1.7e308]),
        Point::new([1.0, 0.0]),
    ])
    .unwrap();
    let ts = [0.0, 0.25, 0.5, 0.75, 1.0];
    let mut got = Vec::new();
    big.eval_each(&ts, |p| got.push(p)).unwrap();
    for (p, t) in got.iter().zip(ts) {
        assert!(p.is_finite(), "t = {t}: {p:?}");
        assert_eq!(*p, big.de_casteljau(&t).unwrap());
        assert_eq!(*p, big.eval(&t).unwrap());
    }
    // Its derivative's control points 3Δbᵢ are beyond the double range: an error, not ±∞.
    assert_eq!(
        big.derivative(1),
        Err(Error::Overflow { what: "derivative" })
    );
    assert!(matches!(big.split(&1e300), Err(Error::Overflow { .. })));
    assert!(big.split(&0.5).is_ok());
    match big.eval_each(&[0.5, f64::NAN], |_| {}) {
        Err(Error::InvalidParameter { name: "t", reason }) => {
            assert!(reason.contains("parameter 1"))
        }
        other => panic!("{other:?}"),
    }
    // A bad parameter past the first chunk: f sees exactly the parameters before it, each
    // evaluated as `eval` evaluates it (try_for_each semantics).
    let cubic = Bezier::new(vec![
        Point::new([0.0, 1.0]),
        Point::new([2.0, -1.0]),
        Point::new([-3.0, 4.0]),
        Point::new([1.0, 0.5]),
    ])
    .unwrap();
    let mut ts: Vec<f64> = (0..3000).map(|i| f64::from(i) / 997.0 - 0.5).collect();
    ts[1500] = f64::INFINITY;
    let mut got = Vec::new();
    match cubic.eval_each(&ts, |p| got.push(p)) {
        Err(Error::InvalidParameter { name: "t", reason }) => {
            assert!(reason.contains("parameter 1500"), "{reason}")
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(got.len(), 1500);
    for (p, t) in got.iter().zip(&ts) {
        assert_eq!(*p, cubic.eval(t).unwrap(), "t = {t}");
    }
}

#[test]
fn curves_in_one_and_three_dimensions() {
    let b1 = Bezier::new(vec![qp([(0, 1)]), qp([(1, 1)]), qp([(3, 1)])]).unwrap();
    assert_eq!(b1.eval(&q(1, 2)).unwrap(), qp([(5, 4)]));
    let b3 = Bezier::new(vec![
        qp([(0, 1), (0, 1), (0, 1)]),
        qp([(1, 1), (2, 1), (3, 1)]),
    ])
    .unwrap();
    assert_eq!(b3.eval(&q(1, 3)).unwrap(), qp([(1, 3), (2, 3), (1, 1)]));
    assert_eq!(
        b3.hodograph().unwrap().control(),
        [qp([(1, 1), (2, 1), (3, 1)])]
    );
}

#[test]
fn flattening_a_straight_polygon_gives_its_chord_and_tiny_tolerances_are_refused() {
    let line = Bezier::new(
        (0..4)
            .map(|i| Point::new([i as f64, 2.0 * i as f64]))
            .collect(),
    )
    .unwrap();
    assert_eq!(
        line.flatten(&1e-9).unwrap(),
        [Point::new([0.0, 0.0]), Point::new([3.0, 6.0])]
    );
    let wide = Bezier::new(vec![
        Point::new([0.0, 0.0]),
        Point::new([1e300, 1e300]),
        Point::new([0.0, 1.0]),
    ])
    .unwrap();
    assert!(matches!(
        wide.flatten(&1e-300),
        Err(Error::InvalidParameter {
            name: "tolerance",
            ..
        })
    ));
}

#[test]
fn bad_input_is_an_error_never_a_panic() {
    assert_eq!(
        Bezier::<f64, 2>::new(vec![]),
        Err(Error::Empty {
            what: "control polygon"
        })
    );
    match Bezier::new(vec![
        Point::new([0.0, 1.0]),
        Point::new([2.0, f64::INFINITY]),
    ]) {
        Err(Error::NonFinite { index: 1, value }) => assert_eq!(value, f64::INFINITY),
        other => panic!("{other:?}"),
    }
    let b = Bezier::new(vec![
        Point::new([0.0, 1.0]),
        Point::new([2.0, 3.0]),
        Point::new([4.0, 1.0]),
    ])
    .unwrap();
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(
            b.eval(&bad),
            Err(Error::InvalidParameter { name: "t", .. })
        ));
        assert!(b.de_casteljau(&bad).is_err());
        assert!(b.horner(&bad).is_err());
        assert!(b.split(&bad).is_err());
        assert!(b.restrict(&0.0, &bad).is_err());
        assert!(b.derivative_at(&bad, 1).is_err());
        assert!(b.flatten(&bad).is_err());
        assert!(b.forward_differences(&0.0, &bad, 4).is_err());
        assert!(b.blossom(&[0.5, bad]).is_err());
        assert!(bernstein(3, 1, &bad).is_err());
    }
    assert!(b.flatten(&0.0).is_err());
    assert!(b.flatten(&-1.0).is_err());
    assert!(matches!(
        b.elevate_to(1),
        Err(Error::InvalidParameter { name: "degree", .. })
    ));
    assert!(b.blossom(&[0.5]).is_err());
    assert!(b.clone().reparametrise(2.0, 2.0).is_err());
    assert!(b.clone().reparametrise(3.0, 2.0).is_err());
    assert!(b.clone().reparametrise(f64::NAN, 2.0).is_err());
    assert!(b.integral(Point::new([f64::NAN, 0.0])).is_err());
    assert!(Bezier::<f64, 2>::from_monomial(&[]).is_err());
}

#[cfg(feature = "cli")]
#[test]
fn cli_evaluates_splits_elevates_and_differentiates_exactly() {
    use crate::common::run_json;
    let cubic = r#"[[0, 0], ["1/3", 2], [3, 2], [4, 0]]"#;
    let v = run_json(
        &[
            "bezier",
            "eval",
            "--control",
            cubic,
            "--t",
            "1/3",
            "--exact",
        ],
        None,
    );
    // The library's exact value, computed independently through the Bernstein sum.
    let b = Bezier::new(vec![
        qp([(0, 1), (0, 1)]),
        qp([(1, 3), (2, 1)]),
        qp([(3, 1), (2, 1)]),
        qp([(4, 1), (0, 1)]),
    ])
    .unwrap();
    let basis = bernstein_all(3, &q(1, 3)).unwrap();
    let expected = sum(b.control().iter().zip(&basis).map(|(p, w)| p.clone() * w));
    assert_eq!(v["point"][0], expected[0].to_string());
    assert_eq!(v["point"][1], expected[1].to_string());
    assert_eq!(v["counts"]["arithmetic_operations"], 6);
    let h = run_json(
        &[
            "bezier",
            "eval",
            "--control",
            cubic,
            "--t",
            "1/3",
            "--exact",
            "--algorithm",
            "horner",
        ],
        None,
    );
    assert_eq!(h["point"], v["point"]);
    assert_eq!(h["counts"]["arithmetic_operations"], 4);

    // Decimal input is exact with --exact: 0.1 is 1/10, not the nearest double.
    let s = run_json(
        &[
            "bezier",
            "split",
            "--control",
            "[0.1, 0.3]",
            "--t",
            "0.5",
            "--exact",
        ],
        None,
    );
    assert_eq!(s["left"], serde_json::json!([["1/10"], ["1/5"]]));
    assert_eq!(s["right"], serde_json::json!([["1/5"], ["3/10"]]));

    let e = run_json(
        &[
            "bezier",
            "elevate",
            "--control",
            "[[0, 0, 0], [3, 6, 9]]",
            "--degree",
            "3",
        ],
        None,
    );
    assert_eq!(
        e["control"],
        serde_json::json!([
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 3.0],
            [2.0, 4.0, 6.0],
            [3.0, 6.0, 9.0]
        ])
    );

    let d = run_json(
        &[
            "bezier",
            "derivative",
            "--control",
            "[[0], [0], [1]]",
            "--order",
            "1",
            "--t",
            "-0.5",
        ],
        None,
    );
    assert_eq!(d["control"], serde_json::json!([[0.0], [2.0]]));
    assert_eq!(d["point"], serde_json::json!([-1.0]));

    // f64 results print as numbers that round-trip.
    let f = run_json(
        &[
            "bezier",
            "eval",
            "--control",
            "[[0, 0], [1, 2], [3, 2], [4, 0]]",
            "--t",
            "0.5",
        ],
        None,
    );
    assert_eq!(f["point"], serde_json::json!([2.0, 1.5]));
}

#[cfg(feature = "cli")]
#[test]
fn cli_rejects_bad_input_with_exit_code_2() {
    use crate::common::assert_rejected;
    let ok = "[[0, 0], [1, 1]]";
    for (args, needle) in [
        (
            vec!["bezier", "eval", "--control", "[]", "--t", "0.5"],
            "empty",
        ),
        (
            vec!["bezier", "eval", "--control", "[[0, 0], [1]]", "--t", "0.5"],
            "point 1",
        ),
        (
            vec!["bezier", "eval", "--control", "[[0, NaN]]", "--t", "0.5"],
            "control point",
        ),
        (
            vec!["bezier", "eval", "--control", "[[0, 1e999]]", "--t", "0.5"],
            "range",
        ),
        (
            vec![
                "bezier",
                "eval",
                "--control",
                "[[0, 0], [1, 1]",
                "--t",
                "0.5",
            ],
            "JSON",
        ),
        (vec!["bezier", "eval", "--control", ok, "--t", "nan"], "t"),
        (
            vec!["bezier", "eval", "--control", ok, "--t", "1/0"],
            "denominator",
        ),
        (
            vec!["bezier", "split", "--control", ok, "--t", "x", "--exact"],
            "t",
        ),
        (
            vec!["bezier", "elevate", "--control", ok, "--degree", "0"],
            "degree",
        ),
        (
            vec!["bezier", "eval", "--control", "[[1,2,3,4,5]]", "--t", "0"],
            "1 to 4",
        ),
        (
            vec![
                "bezier",
                "eval",
                "--control",
                "[[1e308], [-1e308]]",
                "--t",
                "-1e10",
            ],
            "range",
        ),
        (vec!["bezier", "eval", "--control", ok], "--t"),
    ] {
        let line = assert_rejected(&args, None);
        assert!(line.contains(needle), "{args:?}: {line}");
    }
}

/// The curve traits' properties (`spline_common::curve_properties`) on the Bézier types.
mod traits {
    use super::Q;
    use crate::spline_common::curve_properties::{curve_property_tests, eighths, points, Family};
    use compgeo::spline::{
        Bezier, CompositeBezier, Curve, Point, Reparametrised, Scalar, Subsegment,
    };
    use proptest::prelude::*;

    /// Control polygons of degree 0 to `max`, coordinates in eighths within ±10.
    fn polygon(max: usize) -> impl Strategy<Value = Vec<(i64, i64)>> {
        prop::collection::vec((-80i64..=80, -80i64..=80), 1..=max + 1)
    }

    struct Bezier6;

    impl Family for Bezier6 {
        type Data = Vec<(i64, i64)>;
        type Curve<S: Scalar> = Bezier<S, 2>;
        const TOLERANCE: f64 = 1e-12;
        fn data() -> BoxedStrategy<Self::Data> {
            polygon(6).boxed()
        }
        fn build<S: Scalar>(data: &Self::Data) -> Bezier<S, 2> {
            Bezier::new(points(data)).unwrap()
        }
    }

    struct OverAnInterval;

    impl Family for OverAnInterval {
        /// The polygon, a and b − a in eighths.
        type Data = (Vec<(i64, i64)>, i64, i64);
        type Curve<S: Scalar> = Reparametrised<S, 2>;
        const TOLERANCE: f64 = 1e-12;
        fn data() -> BoxedStrategy<Self::Data> {
            (polygon(5), -8i64..=8, 1i64..=16).boxed()
        }
        fn build<S: Scalar>((polygon, a, width): &Self::Data) -> Reparametrised<S, 2> {
            Bezier::new(points(polygon))
                .unwrap()
                .reparametrise(eighths(*a), eighths(a + width))
                .unwrap()
        }
    }

    struct Composite;

    impl Family for Composite {
        /// The first knot, then (gap, polygon) per piece, in eighths; each piece after the
        /// first starts where the previous one ends (a C⁰ curve: where pieces do not meet, a
        /// subsegment ending at the knot ends with the left piece, see
        /// `subsegments_end_with_the_left_piece_where_pieces_do_not_meet`).
        type Data = (i64, Vec<(i64, Vec<(i64, i64)>)>);
        type Curve<S: Scalar> = CompositeBezier<S, 2>;
        const TOLERANCE: f64 = 1e-12;
        fn data() -> BoxedStrategy<Self::Data> {
            (
                -8i64..=0,
                prop::collection::vec((1i64..=12, polygon(4)), 1..=3),
            )
                .prop_map(|(start, mut pieces)| {
                    for i in 1..pieces.len() {
                        let end = *pieces[i - 1].1.last().unwrap();
                        pieces[i].1[0] = end;
                    }
                    (start, pieces)
                })
                .boxed()
        }
        fn build<S: Scalar>((start, pieces): &Self::Data) -> CompositeBezier<S, 2> {
            let mut knots = vec![*start];
            for (gap, _) in pieces {
                knots.push(knots.last().unwrap() + gap);
            }
            CompositeBezier::new(
                knots.into_iter().map(eighths).collect(),
                pieces.iter().map(|(_, p)| points(p)).collect(),
            )
            .unwrap()
        }
    }

    /// At an interior knot where the pieces do not meet the curve is the right piece (as
    /// `derivative_at` is), but a subsegment ending there is the left piece up to its end:
    /// the proptest's reproduction on closed intervals holds wherever the curve is
    /// continuous.
    #[test]
    fn subsegments_end_with_the_left_piece_where_pieces_do_not_meet() {
        let p = |x: i64, y: i64| Point::new([Q::from_i64(x), Q::from_i64(y)]);
        let (zero, one, two) = (Q::from_i64(0), Q::from_i64(1), Q::from_i64(2));
        let c = CompositeBezier::new(
            vec![zero.clone(), one.clone(), two.clone()],
            vec![vec![p(0, 0), p(1, 1)], vec![p(5, 5), p(6, 4)]],
        )
        .unwrap();
        assert_eq!(c.eval(&one).unwrap(), p(5, 5));
        let left = c.subsegment(&zero, &one).unwrap();
        assert_eq!(left.partition(), [zero.clone(), one.clone()]);
        assert_eq!(left.eval(&one).unwrap(), p(1, 1));
        let right = c.subsegment(&one, &two).unwrap();
        assert_eq!(right.pieces(), &c.pieces()[1..]);
        assert_eq!(right.eval(&one).unwrap(), p(5, 5));
    }

    curve_property_tests! {
        bezier_curves_have_the_curve_properties: Bezier6, 48;
        reparametrised_curves_have_the_curve_properties: OverAnInterval, 32;
        composite_curves_have_the_curve_properties: Composite, 32;
    }
}
