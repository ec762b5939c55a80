//! Rational Bézier and NURBS curves, checked exactly on the rational back end against
//! independent oracles: the point against the quotient of the weighted basis (or Bernstein)
//! sums; all weights equal against the B-spline (or Bézier) curve; knot insertion against the
//! curve itself; the derivatives of every order against the symbolic quotient rule applied to
//! the polynomial pieces of the numerator and the denominator (interpolated from their
//! values, so neither the basis derivatives nor the recurrence of the library is used); the
//! rational Bézier curve against the NURBS curve on the knots 0, …, 0, 1, …, 1; subsegments
//! against the curve on their interval. The exact
//! circle and arcs: x² + y² = r² with `==` at random rational parameters, and the tangent
//! orthogonal to the radius. Then the counts, the weights' validation errors (index and
//! value), the `f64` path against the exact one (also with coordinates near 1e300 and weights
//! near 1e300 or subnormal), and overflow as a named error.

use crate::bspline_basis::{knot_vector, parameter};
use crate::spline_common::bspline::{point, samples};
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{
    BSpline, Bezier, ConicKind, Curve, CurveDerivative, KnotVector, Nurbs, Point, RationalBezier,
    Scalar, Subsegment,
};
use compgeo::Error;
use proptest::prelude::*;

/// A positive rational weight k/4, k = 1, …, 16 (repeats and ratios up to 16 included).
fn weight() -> impl Strategy<Value = Q> {
    (1i64..=16).prop_map(|k| q(k, 4))
}

/// An exact NURBS curve on a random knot vector of degree 0..=4 with random positive weights.
fn nurbs() -> impl Strategy<Value = Nurbs<Q, 2>> {
    knot_vector().prop_flat_map(|t| {
        let n = t.control_points();
        (
            Just(t),
            prop::collection::vec((-20i64..=20, -20i64..=20), n),
            prop::collection::vec(weight(), n),
        )
            .prop_map(|(t, c, w)| Nurbs::new(c.into_iter().map(point).collect(), w, t).unwrap())
    })
}

fn nurbs_and_parameter() -> impl Strategy<Value = (Nurbs<Q, 2>, Q)> {
    nurbs().prop_flat_map(|s| {
        let u = parameter(s.knots());
        (Just(s), u)
    })
}

/// An exact rational Bézier curve of degree 0..=5.
fn rational_bezier() -> impl Strategy<Value = RationalBezier<Q, 2>> {
    (1usize..=6).prop_flat_map(|n| {
        (
            prop::collection::vec((-20i64..=20, -20i64..=20), n),
            prop::collection::vec(weight(), n),
        )
            .prop_map(|(c, w)| RationalBezier::new(c.into_iter().map(point).collect(), w).unwrap())
    })
}

/// Σ wᵢ cᵢ Nᵢ(u) / Σ wᵢ Nᵢ(u) from the basis and the data as given.
fn basis_quotient(s: &Nurbs<Q, 2>, u: &Q) -> Point<Q, 2> {
    let b = s.knots().basis(u).unwrap();
    let (mut num, mut den) = (Point::zero(), qi(0));
    for (k, n) in b.values().iter().enumerate() {
        let i = b.first() + k;
        let wn = s.weights()[i].clone() * n;
        num += &(s.control()[i].clone() * &wn);
        den += &wn;
    }
    num / &den
}

// Polynomials in the power basis, coefficients from the constant term up.
type Poly = Vec<Q>;

fn eval(p: &[Q], x: &Q) -> Q {
    p.iter().rev().fold(qi(0), |acc, c| acc * x + c)
}

fn mul(p: &[Q], r: &[Q]) -> Poly {
    let mut out = vec![qi(0); p.len() + r.len() - 1];
    for (i, a) in p.iter().enumerate() {
        for (j, b) in r.iter().enumerate() {
            out[i + j] += a.clone() * b;
        }
    }
    out
}

fn sub(p: &[Q], r: &[Q]) -> Poly {
    let mut out = vec![qi(0); p.len().max(r.len())];
    for (i, a) in p.iter().enumerate() {
        out[i] += a;
    }
    for (i, b) in r.iter().enumerate() {
        out[i] -= b;
    }
    out
}

fn scale(p: &[Q], c: &Q) -> Poly {
    p.iter().map(|a| a.clone() * c).collect()
}

fn deriv(p: &[Q]) -> Poly {
    if p.len() == 1 {
        return vec![qi(0)];
    }
    (1..p.len()).map(|i| p[i].clone() * qi(i as i64)).collect()
}

/// The polynomial of degree < xs.len() through (xs[i], ys[i]) (Lagrange, expanded).
fn interpolate(xs: &[Q], ys: &[Q]) -> Poly {
    let mut out = vec![qi(0)];
    for (i, xi) in xs.iter().enumerate() {
        let mut term = vec![ys[i].clone()];
        for (j, xj) in xs.iter().enumerate() {
            if i != j {
                let inv = qi(1) / (xi.clone() - xj);
                term = mul(&term, &[-(xj.clone() * &inv), inv]);
            }
        }
        out = sub(&out, &scale(&term, &qi(-1)));
    }
    out
}

/// The k-th derivative of a/w at x by the symbolic quotient rule: (a/w)⁽ᵏ⁾ = N_k/w^{k+1} with
/// N₀ = a and N_{k+1} = N_k′·w − (k + 1)·N_k·w′.
fn symbolic_derivative(a: &[Q], w: &[Q], k: usize, x: &Q) -> Q {
    let dw = deriv(w);
    let mut n = a.to_vec();
    for j in 0..k {
        n = sub(
            &mul(&deriv(&n), w),
            &scale(&mul(&n, &dw), &qi(j as i64 + 1)),
        );
    }
    let wx = eval(w, x);
    let mut power = qi(1);
    for _ in 0..=k {
        power *= &wx;
    }
    eval(&n, x) / power
}

/// The polynomial pieces (per coordinate and of the weight) of a homogeneous curve on
/// [lo, hi], from its values at degree + 1 points inside (not at the ends, where the next
/// piece may take over).
fn pieces(f: impl Fn(&Q) -> (Point<Q, 2>, Q), degree: usize, lo: &Q, hi: &Q) -> [Poly; 3] {
    let xs: Vec<Q> = (0..=degree)
        .map(|j| lo.clone() + (hi.clone() - lo) * q(j as i64 + 1, degree as i64 + 2))
        .collect();
    let values: Vec<(Point<Q, 2>, Q)> = xs.iter().map(&f).collect();
    let coordinate = |c: usize| -> Vec<Q> { values.iter().map(|(p, _)| p[c].clone()).collect() };
    let weights: Vec<Q> = values.iter().map(|(_, w)| w.clone()).collect();
    [
        interpolate(&xs, &coordinate(0)),
        interpolate(&xs, &coordinate(1)),
        interpolate(&xs, &weights),
    ]
}

/// The exact curve of an `f64` one.
fn exact(s: &Nurbs<f64, 2>) -> Nurbs<Q, 2> {
    let k = s
        .knots()
        .knots()
        .iter()
        .map(|k| Q::from_f64(*k).unwrap())
        .collect();
    let t = KnotVector::new(s.degree(), k).unwrap();
    let c = s
        .control()
        .iter()
        .map(|p| Point::from_f64(p).unwrap())
        .collect();
    let w = s
        .weights()
        .iter()
        .map(|w| Q::from_f64(*w).unwrap())
        .collect();
    Nurbs::new(c, w, t).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn de_boor_is_the_quotient_of_the_weighted_basis_sums((s, u) in nurbs_and_parameter()) {
        let d = s.degree();
        let mut c = Counts::default();
        let p = s.de_boor_with(&u, &mut c).unwrap();
        prop_assert_eq!(&p, &basis_quotient(&s, &u));
        prop_assert_eq!(&s.eval(&u).unwrap(), &p);
        prop_assert_eq!(&s.derivative_at(&u, 0).unwrap(), &p);
        let (mu, t) = (s.knots().span(&u).unwrap(), s.knots().knots());
        let r = (0..d).take_while(|&j| t[mu - j] == u).count();
        prop_assert_eq!(c.arithmetic_operations, ((d - r) * (d - r + 1)) as u64);
    }

    #[test]
    fn all_weights_equal_give_the_b_spline_curve((s, u) in nurbs_and_parameter(), k in 1i64..=9) {
        let b = BSpline::new(s.control().to_vec(), s.knots().clone()).unwrap();
        let n = s.control().len();
        let ones = Nurbs::new(s.control().to_vec(), vec![qi(1); n], s.knots().clone()).unwrap();
        let same = Nurbs::new(s.control().to_vec(), vec![q(k, 3); n], s.knots().clone()).unwrap();
        for v in samples(s.knots()).iter().chain([&u]) {
            prop_assert_eq!(ones.eval(v).unwrap(), b.eval(v).unwrap());
            prop_assert_eq!(same.eval(v).unwrap(), b.eval(v).unwrap());
        }
        for r in 1..=s.degree() + 1 {
            prop_assert_eq!(ones.derivative_at(&u, r).unwrap(), b.derivative_at(&u, r).unwrap());
        }
    }

    #[test]
    fn insertion_leaves_the_curve_identical((s, u) in nurbs_and_parameter(), times in 1usize..=3) {
        let d = s.degree();
        let before = s.knots().multiplicity(&u);
        let mut c = Counts::default();
        match s.insert_with(&u, times, &mut c) {
            Ok(r) => {
                prop_assert_eq!(r.knots().multiplicity(&u), before + times);
                prop_assert_eq!(r.control().len(), s.control().len() + times);
                for v in samples(s.knots()) {
                    prop_assert_eq!(r.eval(&v).unwrap(), s.eval(&v).unwrap(), "u = {}", v);
                }
                prop_assert!(r.weights().iter().all(|w| *w > qi(0)));
                // The homogeneous form is the B-spline insertion of each half.
                let (num, den) = s.homogeneous();
                prop_assert_eq!(r.homogeneous().0, &num.insert(&u, times).unwrap());
                prop_assert_eq!(r.homogeneous().1, &den.insert(&u, times).unwrap());
                // And the weighted points are the weights times the new control points.
                for ((p, w), h) in r.control().iter().zip(r.weights()).zip(r.homogeneous().0.control()) {
                    prop_assert_eq!(&(p.clone() * w), h);
                }
                let mut one = s.clone();
                for _ in 0..times {
                    one = one.insert(&u, 1).unwrap();
                }
                prop_assert_eq!(&one, &r);
                let t = s.knots().knots();
                let sm = if t[s.knots().span(&u).unwrap()] == u { before } else { 0 };
                let want = 2 * (times * (d - sm) - times * (times - 1) / 2);
                prop_assert_eq!(c.arithmetic_operations, want as u64);
            }
            Err(e) => {
                prop_assert!(before + times > d, "{}", e);
                prop_assert!(matches!(e, Error::InvalidParameter { name: "times", .. }), "{}", e);
            }
        }
    }

    #[test]
    fn refinement_is_the_single_insertions((s, u) in nurbs_and_parameter(), k in 1i64..=7) {
        let (start, end) = (s.knots().bounds().0.clone(), s.knots().bounds().1.clone());
        let v = start.clone() + (end - &start) * q(k, 8);
        let new = [v.clone(), u.clone()];
        let one = s.insert(&v, 1).and_then(|r| r.insert(&u, 1));
        match (s.refine(&new), one) {
            (Ok(r), Ok(one)) => {
                prop_assert_eq!(&r, &one);
                prop_assert!(r.weights().iter().all(|w| *w > qi(0)));
            }
            (Err(e), Err(_)) => {
                prop_assert!(matches!(e, Error::InvalidParameter { name: "new_knots", .. }), "{}", e);
            }
            (r, one) => prop_assert!(false, "refine {:?}, insertions {:?}", r.is_ok(), one.is_ok()),
        }
    }

    #[test]
    fn subsegments_are_the_curve_on_their_interval((s, u) in nurbs_and_parameter(), k in 1i64..=7) {
        // The piece over [a, b] (a = u, or the start of the domain when u is its end) equals
        // the curve at every sample inside, with positive weights; a reversed or empty
        // interval is an error.
        let (start, end) = (s.knots().bounds().0.clone(), s.knots().bounds().1.clone());
        let a = if u < end { u.clone() } else { start.clone() };
        let b = a.clone() + (end.clone() - &a) * q(k, 8);
        let piece = s.subsegment(&a, &b).unwrap();
        prop_assert_eq!(piece.degree(), s.degree());
        prop_assert!(piece.weights().iter().all(|w| *w > qi(0)));
        for v in samples(s.knots()) {
            if v >= a && v <= b {
                let at_b_from_left = v == b && s.knots().multiplicity(&b) > s.degree();
                if !at_b_from_left {
                    prop_assert_eq!(piece.eval(&v).unwrap(), s.eval(&v).unwrap(), "u = {}", v);
                }
            } else {
                prop_assert!(piece.eval(&v).is_err());
            }
        }
        prop_assert!(s.subsegment(&b, &a).is_err());
        prop_assert!(s.subsegment(&a, &a).is_err());
    }

    #[test]
    fn derivatives_are_the_symbolic_quotient_rule_on_the_pieces((s, u) in nurbs_and_parameter()) {
        let d = s.degree();
        let t = s.knots().knots();
        let mu = s.knots().span(&u).unwrap();
        let (lo, hi) = (t[mu].clone(), t[mu + 1].clone());
        let (num, den) = s.homogeneous();
        let [ax, ay, w] = pieces(|x| (num.eval(x).unwrap(), den.eval(x).unwrap()[0].clone()), d, &lo, &hi);
        let mut curve = s.derivative_curve().unwrap();
        for k in 0..=d + 2 {
            let want = Point::new([symbolic_derivative(&ax, &w, k, &u), symbolic_derivative(&ay, &w, k, &u)]);
            prop_assert_eq!(s.derivative_at(&u, k).unwrap(), want.clone(), "order {}", k);
            if k >= 1 {
                prop_assert_eq!(curve.order(), k);
                prop_assert_eq!(curve.eval(&u).unwrap(), want.clone());
                prop_assert_eq!(curve.derivative_at(&u, 1).unwrap(), s.derivative_at(&u, k + 1).unwrap());
                curve = curve.derivative_curve().unwrap();
            }
        }
    }

    #[test]
    fn rational_bezier_is_the_nurbs_curve_on_bezier_knots(
        r in rational_bezier(),
        ts in prop::collection::vec(0i64..=36, 4),
    ) {
        let n = r.degree();
        let knots = KnotVector::clamped_uniform(n, n + 1, qi(0), qi(1)).unwrap();
        let s = Nurbs::new(r.control().to_vec(), r.weights().to_vec(), knots).unwrap();
        let mut c = Counts::default();
        for k in ts {
            let t = q(k, 36);
            prop_assert_eq!(r.de_casteljau_with(&t, &mut c).unwrap(), s.eval(&t).unwrap());
            for order in 1..=n + 2 {
                prop_assert_eq!(r.derivative_at(&t, order).unwrap(), s.derivative_at(&t, order).unwrap());
            }
        }
        prop_assert_eq!(c.arithmetic_operations, 4 * (n * (n + 1)) as u64);
    }

    #[test]
    fn rational_bezier_derivatives_are_the_symbolic_quotient_rule(
        r in rational_bezier(),
        k in 0i64..=24,
    ) {
        let n = r.degree();
        let t = q(k, 24);
        let (num, den) = r.homogeneous();
        let [ax, ay, w] = pieces(|x| (num.eval(x).unwrap(), den.eval(x).unwrap()[0].clone()), n, &qi(0), &qi(1));
        for order in 0..=n + 2 {
            let want = Point::new([
                symbolic_derivative(&ax, &w, order, &t),
                symbolic_derivative(&ay, &w, order, &t),
            ]);
            prop_assert_eq!(r.derivative_at(&t, order).unwrap(), want, "order {}", order);
        }
        // The derivative curve of degree 2n, twice.
        let dr = r.derivative_curve().unwrap();
        prop_assert_eq!(dr.degree(), 2 * n);
        prop_assert!(dr.weights().iter().all(|w| *w > qi(0)));
        prop_assert_eq!(dr.eval(&t).unwrap(), r.derivative_at(&t, 1).unwrap());
        if n <= 3 {
            let ddr = dr.derivative_curve().unwrap();
            prop_assert_eq!(ddr.eval(&t).unwrap(), r.derivative_at(&t, 2).unwrap());
        }
    }

    #[test]
    fn the_circle_is_exact(
        (x0, y0) in (-30i64..=30, -30i64..=30),
        (rn, rd) in (1i64..=50, 1i64..=7),
        (k, m) in (0i64..=400, 1i64..=100),
    ) {
        let (centre, r) = (Point::new([q(x0, 3), q(y0, 5)]), q(rn, rd));
        let c = Nurbs::circle(centre.clone(), r.clone()).unwrap();
        let u = qi(4) * q(k.min(100 * m), 100 * m);
        let p = c.eval(&u).unwrap();
        let radius = p.clone() - &centre;
        prop_assert_eq!(radius.norm_squared(), r.clone() * &r, "u = {}", u);
        // The tangent is orthogonal to the radius, and nonzero.
        let tangent = c.derivative_at(&u, 1).unwrap();
        prop_assert_eq!(tangent.dot(&radius), qi(0));
        prop_assert!(tangent.norm_squared() > qi(0));
        // Counter-clockwise: the tangent is the radius turned left, up to a positive factor.
        let cross = radius[0].clone() * &tangent[1] - radius[1].clone() * &tangent[0];
        prop_assert!(cross > qi(0));
    }

    #[test]
    fn circular_arcs_are_exact(
        (mn, md) in (1i64..=40, 1i64..=12),
        k in 0i64..=30,
        rn in 1i64..=9,
    ) {
        let (m, r) = (q(mn, md), qi(rn));
        let centre = Point::new([qi(2), qi(-1)]);
        let a = RationalBezier::circular_arc(centre.clone(), r.clone(), m.clone()).unwrap();
        let t = q(k, 30);
        let p = a.eval(&t).unwrap() - &centre;
        prop_assert_eq!(p.norm_squared(), r.clone() * &r);
        // The point at t is r·((1 − m²t²)/(1 + m²t²), 2mt/(1 + m²t²)).
        let s = m.clone() * &t;
        let den = qi(1) + s.clone() * &s;
        let want = Point::new([(qi(1) - s.clone() * &s) / &den, qi(2) * &s / &den]) * &r;
        prop_assert_eq!(p, want);
        prop_assert_eq!(a.conic_kind(), Some(ConicKind::Ellipse));
        let dp = a.derivative_at(&t, 1).unwrap();
        prop_assert_eq!(dp.dot(&(a.eval(&t).unwrap() - &centre)), qi(0));
    }

    #[test]
    fn conics_are_classified_by_the_weight(
        c in prop::collection::vec((-20i64..=20, -20i64..=20), 3),
        (wn, wd) in (1i64..=12, 1i64..=12),
        k in 0i64..=16,
    ) {
        let w = q(wn, wd);
        let pts: Vec<Point<Q, 2>> = c.into_iter().map(point).collect();
        let arc = RationalBezier::conic(pts[0].clone(), pts[1].clone(), pts[2].clone(), w.clone()).unwrap();
        let want = if w < qi(1) { ConicKind::Ellipse } else if w == qi(1) { ConicKind::Parabola } else { ConicKind::Hyperbola };
        prop_assert_eq!(arc.conic_kind(), Some(want));
        // Scaling the weights to 1, λw, λ² (a reparametrisation) keeps the kind.
        let lambda = q(wd + 1, wn + 2);
        let same = RationalBezier::new(pts.clone(), vec![qi(1), lambda.clone() * &w, lambda.clone() * &lambda]).unwrap();
        prop_assert_eq!(same.conic_kind(), Some(want));
        if w == qi(1) {
            let b = Bezier::new(pts).unwrap();
            prop_assert_eq!(arc.eval(&q(k, 16)).unwrap(), b.eval(&q(k, 16)).unwrap());
        }
    }

    #[test]
    fn f64_agrees_with_exact(
        d in 0usize..=4,
        steps in prop::collection::vec(1i64..=12, 14),
        c in prop::collection::vec((-20i64..=20, -20i64..=20), 14),
        w in prop::collection::vec(1i64..=64, 14),
        ks in prop::collection::vec(0i64..=64, 6),
        magnitude in prop::sample::select(vec![1.0, 1e300, 1e-300, f64::from_bits(1) * 4096.0]),
    ) {
        let mut knots = Vec::new();
        let mut x = -1.0;
        for s in &steps {
            x += *s as f64 / 8.0;
            knots.push(x);
        }
        knots.truncate((2 * d + 2).max(knots.len() - 2));
        let t = KnotVector::new(d, knots).unwrap();
        let n = t.control_points();
        let cf: Vec<Point<f64, 2>> = c[..n].iter().copied().map(point).collect();
        let wf: Vec<f64> = w[..n].iter().map(|k| *k as f64 / 8.0 * magnitude).collect();
        let sf = Nurbs::new(cf, wf, t).unwrap();
        let sq = exact(&sf);
        let (a, b) = (*sf.knots().bounds().0, *sf.knots().bounds().1);
        for k in &ks {
            let u = a + (b - a) * (*k as f64 / 64.0);
            let e = sq.eval(&Q::from_f64(u).unwrap()).unwrap().to_f64();
            let got = sf.eval(&u).unwrap();
            for j in 0..2 {
                prop_assert!((got[j] - e[j]).abs() <= 1e-13 * 20.0, "u = {}: {:?} vs {:?}", u, got, e);
            }
        }
    }
}

#[test]
fn the_circle_in_f64_is_round_and_passes_the_axis_points() {
    let c = Nurbs::circle(Point::new([0.5, -0.25]), 3.0).unwrap();
    let want = [
        (3.5, -0.25),
        (0.5, 2.75),
        (-2.5, -0.25),
        (0.5, -3.25),
        (3.5, -0.25),
    ];
    for (k, (x, y)) in want.iter().enumerate() {
        assert_eq!(c.eval(&(k as f64)).unwrap(), Point::new([*x, *y]));
    }
    for k in 0..=400 {
        let p = c.eval(&(k as f64 / 100.0)).unwrap() - Point::new([0.5, -0.25]);
        assert!(
            (p.norm_squared().sqrt() - 3.0).abs() <= 2e-15 * 3.0,
            "{k}: {p:?}"
        );
    }
    // Far from the origin and at 1e300: still round to a few ulps.
    let big = Nurbs::circle(Point::new([1e300, -1e300]), 1e300).unwrap();
    let p = big.eval(&0.5).unwrap();
    assert!(
        (p[0] - 1.6e300).abs() <= 1e285 && (p[1] + 0.2e300).abs() <= 1e285,
        "{p:?}"
    );
    assert!(matches!(
        Nurbs::circle(Point::new([1e308, 0.0]), 1e308),
        Err(Error::Overflow { .. })
    ));
}

#[test]
fn bad_input_is_a_named_error() {
    let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0).unwrap();
    let c: Vec<Point<f64, 2>> = [(0, 0), (1, 1), (2, 0), (3, 1)].map(point).to_vec();
    for (i, bad) in [
        (1, 0.0),
        (2, -1.0),
        (3, f64::NAN),
        (0, f64::INFINITY),
        (1, -0.0),
    ] {
        let mut w = vec![1.0; 4];
        w[i] = bad;
        let e = Nurbs::new(c.clone(), w.clone(), t.clone()).unwrap_err();
        let shown = bad.to_string();
        assert_eq!(
            e.to_string(),
            format!("invalid weights: weight {i} is {shown}; weights must be finite and positive")
        );
        let e = RationalBezier::new(c.clone(), w).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidParameter {
                    name: "weights",
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains(&format!("weight {i} is")), "{e}");
    }
    let e = Nurbs::new(c.clone(), vec![1.0; 3], t.clone()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid weights: 4 control points need 4 weights, got 3"
    );
    let e = Nurbs::new(c[..3].to_vec(), vec![1.0; 3], t.clone()).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "knots", .. }),
        "{e}"
    );
    let mut bad = c.clone();
    bad[2] = Point::new([f64::NAN, 0.0]);
    assert!(matches!(
        Nurbs::new(bad.clone(), vec![1.0; 4], t.clone()),
        Err(Error::NonFinite { index: 2, .. })
    ));
    assert!(matches!(
        RationalBezier::new(bad, vec![1.0; 4]),
        Err(Error::NonFinite { index: 2, .. })
    ));
    assert!(matches!(
        RationalBezier::<f64, 2>::new(vec![], vec![]),
        Err(Error::Empty { .. })
    ));
    // Homogeneous halves on different knots, and a weighted coordinate beyond f64.
    let other = KnotVector::new(2, vec![0.0, 0.0, 0.0, 0.25, 1.0, 1.0, 1.0]).unwrap();
    let num = BSpline::new(c.clone(), t.clone()).unwrap();
    let den = BSpline::new(vec![Point::new([1.0]); 4], other).unwrap();
    assert!(matches!(
        Nurbs::from_homogeneous(num, den),
        Err(Error::InvalidParameter { name: "knots", .. })
    ));
    let huge = vec![Point::new([f64::MAX, 0.0]), Point::new([0.0, 1.0])];
    assert!(matches!(
        RationalBezier::new(huge, vec![1.5, 1.0]),
        Err(Error::Overflow { .. })
    ));
    // Parameters outside the domain, NaN, and derivative orders beyond the limit.
    let s = Nurbs::new(c.clone(), vec![1.0, 2.0, 3.0, 1.0], t).unwrap();
    let r = RationalBezier::new(c, vec![1.0, 2.0, 3.0, 1.0]).unwrap();
    for u in [f64::NAN, f64::INFINITY, -0.5, 1.5] {
        for e in [
            s.eval(&u).unwrap_err(),
            s.derivative_at(&u, 3).unwrap_err(),
            s.insert(&u, 1).unwrap_err(),
        ] {
            assert!(
                matches!(e, Error::InvalidParameter { name: "u", .. }),
                "{u}: {e}"
            );
        }
        for e in [r.eval(&u).unwrap_err(), r.derivative_at(&u, 3).unwrap_err()] {
            assert!(
                matches!(e, Error::InvalidParameter { name: "t", .. }),
                "{u}: {e}"
            );
        }
    }
    assert!(matches!(
        s.derivative_at(&0.5, usize::MAX),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        r.derivative_at(&0.5, usize::MAX),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        s.insert(&0.0, 1),
        Err(Error::InvalidParameter { name: "times", .. })
    ));
    for (radius, name) in [(0.0, "radius"), (-1.0, "radius"), (f64::NAN, "radius")] {
        let e = Nurbs::circle(Point::new([0.0, 0.0]), radius).unwrap_err();
        assert!(
            matches!(e, Error::InvalidParameter { name: n, .. } if n == name),
            "{e}"
        );
    }
    assert!(matches!(
        Nurbs::circle(Point::new([f64::NAN, 0.0]), 1.0),
        Err(Error::NonFinite { index: 0, .. })
    ));
    for m in [0.0, -1.0, f64::NAN] {
        let e = RationalBezier::circular_arc(Point::new([0.0, 0.0]), 1.0, m).unwrap_err();
        assert!(
            matches!(e, Error::InvalidParameter { name: "m", .. }),
            "{e}"
        );
    }
}

#[test]
fn huge_and_subnormal_weights_give_the_same_curve() {
    // Scaling every weight by a power of two changes nothing, also at the ends of the range.
    let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 3.0, 4.0, 4.0, 4.0]).unwrap();
    let c: Vec<Point<f64, 2>> = [(1, -1), (-3, 2), (2, 5), (-1, 1), (4, -2)]
        .map(point)
        .to_vec();
    let w = [1.0, 3.0, 0.5, 2.0, 1.25];
    let base = Nurbs::new(c.clone(), w.to_vec(), t.clone()).unwrap();
    let tiny = f64::from_bits(1);
    for factor in [2f64.powi(1000), 2f64.powi(-1000), tiny * 64.0] {
        let scaled: Vec<f64> = w.iter().map(|x| x * factor).collect();
        let s = Nurbs::new(c.clone(), scaled.clone(), t.clone()).unwrap();
        assert_eq!(s.weights(), scaled);
        for k in 0..=16 {
            let u = k as f64 / 4.0;
            assert_eq!(s.eval(&u).unwrap(), base.eval(&u).unwrap(), "{factor}: {u}");
            assert_eq!(
                s.derivative_at(&u, 2).unwrap(),
                base.derivative_at(&u, 2).unwrap()
            );
        }
        let r = s.insert(&2.0, 2).unwrap();
        let rb = base.insert(&2.0, 2).unwrap();
        assert_eq!(r.control(), rb.control());
        // The new weights in the units of the given ones: exact, but subnormal weights keep
        // only the few bits a subnormal has (here 6).
        for (x, want) in r.weights().iter().zip(rb.weights()) {
            let err = (x / factor - want).abs();
            assert!(
                err <= if factor < 1e-300 { want / 32.0 } else { 0.0 },
                "{x} vs {want}"
            );
        }
    }
    // Coordinates near 1e300 with weights near 1e300: the exact curve, rounded.
    let big: Vec<Point<f64, 2>> = c.iter().map(|p| *p * 1e300).collect();
    let s = Nurbs::new(big, w.iter().map(|x| x * 1e300).collect(), t.clone()).unwrap();
    let e = exact(&s);
    for k in 0..=16 {
        let u = k as f64 / 4.0;
        let (got, want) = (
            s.eval(&u).unwrap(),
            e.eval(&Q::from_f64(u).unwrap()).unwrap().to_f64(),
        );
        for j in 0..2 {
            assert!(
                (got[j] - want[j]).abs() <= 1e-14 * 5e300,
                "{u}: {got:?} vs {want:?}"
            );
        }
    }
    // Subnormal coordinates: the weighted points round to multiples of 2^−1074, so only
    // finiteness and a bound (the box, times the ratio of the weights) are promised.
    let small: Vec<Point<f64, 2>> = [(1, 3), (5, 2), (2, 7), (9, 1), (4, 4)]
        .map(|(x, y)| Point::new([x as f64 * tiny, y as f64 * tiny]))
        .to_vec();
    let s = Nurbs::new(small, w.to_vec(), t).unwrap();
    for k in 0..=16 {
        let p = s.eval(&(k as f64 / 4.0)).unwrap();
        assert!(
            p[0] >= 0.0 && p[0] <= 60.0 * tiny && p[1] >= 0.0 && p[1] <= 60.0 * tiny,
            "{p:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Elevation and the rational Bézier pieces leave the rational curve identical at every
    /// sample, exactly; the pieces' breakpoints are the distinct knots of the domain.
    #[test]
    fn elevation_and_bezier_pieces_keep_the_curve(s in nurbs(), times in 1usize..=2) {
        let (d, t) = (s.degree(), s.knots().knots());
        let n = t.len() - d - 1;
        let clamped = d == 0 || (t[1] == t[d] && t[n] == t[n + d - 1]);
        let e = match s.elevate(times) {
            Ok(e) => e,
            Err(Error::InvalidParameter { name: "knots", reason }) if !clamped => {
                prop_assert!(reason.contains("clamped ends"), "{}", reason);
                s.clone()
            }
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        };
        if clamped {
            prop_assert_eq!(e.degree(), s.degree() + times);
            prop_assert!(e.weights().iter().all(|w| *w > qi(0)));
        }
        let (breaks, pieces) = s.to_bezier().unwrap();
        prop_assert_eq!(breaks.len(), pieces.len() + 1);
        for u in samples(s.knots()) {
            let want = s.eval(&u).unwrap();
            prop_assert_eq!(&e.eval(&u).unwrap(), &want);
            // The piece over [a, b] containing u, at the local parameter (u − a)/(b − a); at
            // a breakpoint both neighbours give the point (the curve is continuous for
            // multiplicities up to d).
            for (k, w) in breaks.windows(2).enumerate() {
                if w[0] <= u && u <= w[1] && s.knots().multiplicity(&w[0]) <= s.degree()
                    && s.knots().multiplicity(&w[1]) <= s.degree()
                {
                    let local = (u.clone() - &w[0]) / (w[1].clone() - &w[0]);
                    prop_assert_eq!(&pieces[k].eval(&local).unwrap(), &want, "piece {}", k);
                }
            }
        }
    }
}

#[test]
fn the_elevated_circle_is_still_exactly_round() {
    let r = q(5, 2);
    let c = Nurbs::circle(Point::new([qi(1), q(-1, 3)]), r.clone()).unwrap();
    let e = c.elevate(1).unwrap();
    let (_, quarters) = c.to_bezier().unwrap();
    assert_eq!(quarters.len(), 4);
    for k in 0..=32 {
        let u = q(k, 8);
        let p = e.eval(&u).unwrap();
        let (x, y) = (p[0].clone() - qi(1), p[1].clone() + q(1, 3));
        assert_eq!(x.clone() * &x + y.clone() * &y, r.clone() * &r, "at {u}");
        let piece = usize::try_from(k.min(31) / 8).unwrap();
        let local = u - qi(i64::try_from(piece).unwrap());
        assert_eq!(
            quarters[piece].eval(&local).unwrap(),
            c.eval(&q(k, 8)).unwrap()
        );
    }
}
