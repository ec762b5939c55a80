//! B-spline curves, checked exactly on the rational back end against independent oracles: de
//! Boor's algorithm against Σ cᵢ Nᵢ(u) from the basis (`bspline_basis.rs` checks the basis
//! against the divided-difference definition); Boehm's insertion, single and r-fold, against
//! the curve itself at every knot and at rational parameters between them, and the r-fold
//! insertion against r single ones; a clamped curve without interior knots against the Bézier
//! curve of the same control points; the derivative curve and the extended de Boor algorithm's
//! derivatives against the derivatives of the basis, and its Taylor expansion against the piece.
//! Then the counts, the `f64` path against the exact one (also on knots a few ulps apart, near
//! 1e300 and subnormal), bad input as named errors, and [PPB, §5.12, Ex. 7].

use crate::bspline_basis::{knot_vector, parameter};
use crate::spline_common::bspline::{exact, point, samples};
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{BSpline, Bezier, Curve, CurveDerivative, Domain, KnotVector, Point, Scalar};
use compgeo::Error;
use proptest::prelude::*;

/// An exact curve on a random knot vector of degree 0..=4 (repeated knots included).
fn curve() -> impl Strategy<Value = BSpline<Q, 2>> {
    knot_vector().prop_flat_map(|t| {
        let n = t.control_points();
        (
            Just(t),
            prop::collection::vec((-20i64..=20, -20i64..=20), n),
        )
            .prop_map(|(t, c)| BSpline::new(c.into_iter().map(point).collect(), t).unwrap())
    })
}

/// A curve and a parameter of its domain (an end, a knot, or a rational in between).
fn curve_and_parameter() -> impl Strategy<Value = (BSpline<Q, 2>, Q)> {
    curve().prop_flat_map(|s| {
        let u = parameter(s.knots());
        (Just(s), u)
    })
}

/// Σ cᵢ Nᵢ(u) from the basis.
fn basis_sum(s: &BSpline<Q, 2>, u: &Q) -> Point<Q, 2> {
    let b = s.knots().basis(u).unwrap();
    let mut sum = Point::zero();
    for (k, n) in b.values().iter().enumerate() {
        sum += &(s.control()[b.first() + k].clone() * n);
    }
    sum
}

/// The number of knots t_j = u at or below the span of u (capped at d): the levels de Boor's
/// scheme skips.
fn skipped(t: &KnotVector<Q>, u: &Q) -> usize {
    let mu = t.span(u).unwrap();
    let k = t.knots();
    (0..t.degree()).take_while(|&j| k[mu - j] == *u).count()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn de_boor_is_the_basis_sum_exactly((s, u) in curve_and_parameter()) {
        let d = s.degree();
        let mut c = Counts::default();
        let p = s.de_boor_with(&u, &mut c).unwrap();
        prop_assert_eq!(&p, &basis_sum(&s, &u));
        prop_assert_eq!(&s.eval(&u).unwrap(), &p);
        let r = skipped(s.knots(), &u);
        prop_assert_eq!(c.arithmetic_operations, ((d - r) * (d - r + 1) / 2) as u64);
        let net = s.de_boor_trace(&u).unwrap();
        let last = net.last().unwrap();
        prop_assert_eq!(&last.step.points, std::slice::from_ref(&p));
        prop_assert_eq!(last.counts, c);
        let level0 = &net[0].step;
        prop_assert_eq!(level0.multiplicity, r);
        prop_assert_eq!(level0.span, s.knots().span(&u).unwrap());
        prop_assert_eq!(&level0.points[..], &s.control()[level0.first()..=level0.span - r]);
        for (k, f) in net.iter().enumerate() {
            prop_assert_eq!(f.step.level, k);
            prop_assert_eq!(f.step.points.len(), d - r + 1 - k);
            prop_assert_eq!(f.step.first(), level0.first() + k);
        }
    }

    #[test]
    fn insertion_leaves_the_curve_identical((s, u) in curve_and_parameter(), times in 1usize..=4) {
        let d = s.degree();
        let before = s.knots().multiplicity(&u);
        let mut c = Counts::default();
        match s.insert_with(&u, times, &mut c) {
            Ok(r) => {
                prop_assert!(before + times <= d);
                prop_assert_eq!(r.knots().multiplicity(&u), before + times);
                prop_assert_eq!(r.knots().knots().len(), s.knots().knots().len() + times);
                prop_assert_eq!(r.knots().domain(), s.knots().domain());
                for v in samples(s.knots()) {
                    prop_assert_eq!(r.eval(&v).unwrap(), s.eval(&v).unwrap(), "u = {}", v);
                }
                // r single insertions give the same control points (the representation on
                // a knot vector is unique).
                let mut one = s.clone();
                for _ in 0..times {
                    one = one.insert(&u, 1).unwrap();
                }
                prop_assert_eq!(&one, &r);
                // The new control points are the borders of the first r levels of the de
                // Boor net at u [PPB, §6.1].
                let net = s.de_boor_trace(&u).unwrap();
                let (mu, m) = (net[0].step.span, net[0].step.multiplicity);
                for frame in &net[1..=times] {
                    let (k, level) = (frame.step.level, &frame.step.points);
                    prop_assert_eq!(&r.control()[mu - d + k], &level[0]);
                    prop_assert_eq!(&r.control()[mu + times - k - m], level.last().unwrap());
                }
                let sm = if s.knots().knots()[s.knots().span(&u).unwrap()] == u { before } else { 0 };
                let want = times * (d - sm) - times * (times - 1) / 2;
                prop_assert_eq!(c.arithmetic_operations, want as u64);
            }
            Err(e) => {
                prop_assert!(before + times > d, "{}", e);
                let is_times = matches!(e, Error::InvalidParameter { name: "times", .. });
                prop_assert!(is_times, "{}", e);
            }
        }
    }

    #[test]
    fn the_derivative_curve_is_the_derivative((s, u) in curve_and_parameter()) {
        let d = s.degree();
        let mut curve = s.clone();
        for k in 1..=d + 1 {
            curve = curve.derivative_curve().unwrap();
            prop_assert_eq!(curve.domain(), s.domain());
            prop_assert_eq!(curve.degree(), d.saturating_sub(k));
            let want = s.derivative_at(&u, k).unwrap();
            prop_assert_eq!(curve.eval(&u).unwrap(), want, "order {}", k);
        }
    }

    #[test]
    fn the_extended_de_boor_derivatives_are_the_basis_derivatives(
        (s, u) in curve_and_parameter(),
        extra in 0usize..=2,
    ) {
        // [PPB, §5.9]: the tetrahedral scheme against Σ cᵢ Nᵢ⁽ʳ⁾(u), every order at once,
        // with its exact count.
        let d = s.degree();
        let mut counts = Counts::default();
        let all = s.derivatives_with(&u, d + extra, &mut counts).unwrap();
        prop_assert_eq!(all.len(), d + extra + 1);
        for (r, got) in all.iter().enumerate() {
            prop_assert_eq!(got, &s.derivative_at(&u, r).unwrap(), "order {}", r);
        }
        let want = d * (d + 1) / 2 + d * (d + 1) * (d + 2) / 6;
        prop_assert_eq!(counts.arithmetic_operations, want as u64);
    }

    #[test]
    fn the_taylor_expansion_is_the_piece((s, u) in curve_and_parameter(), j in 0i64..=8) {
        // s_μ(v) = Σ s⁽ʳ⁾(u)(v − u)ʳ/r! at every v of the span of u [PPB, §5.9], its ends
        // included (the piece's limit at the right end, by evaluating the piece's Bézier form).
        let t = s.knots();
        let mu = t.span(&u).unwrap();
        let (a, b) = (t.knots()[mu].clone(), t.knots()[mu + 1].clone());
        let v = a.clone() + (b.clone() - &a) * q(j, 8);
        let all = s.derivatives(&u, s.degree()).unwrap();
        let h = v.clone() - &u;
        let (mut taylor, mut power) = (Point::<Q, 2>::zero(), qi(1));
        for (r, dr) in all.iter().enumerate() {
            if r > 0 {
                power = power * &h / qi(r as i64);
            }
            taylor += &(dr.clone() * &power);
        }
        let piece = s.blossom_in_span(mu, &vec![v.clone(); s.degree()]).unwrap();
        prop_assert_eq!(taylor, piece);
    }

    #[test]
    fn clamped_without_interior_knots_is_the_bezier_curve(
        c in prop::collection::vec((-20i64..=20, -20i64..=20), 1..=8),
        (a, w) in (-3i64..=3, 1i64..=4),
        us in prop::collection::vec(0i64..=48, 8),
    ) {
        // On [a, a + w]: the Bézier curve in the local parameter (u − a)/w.
        let d = c.len() - 1;
        let control: Vec<Point<Q, 2>> = c.into_iter().map(point).collect();
        let t = KnotVector::clamped_uniform(d, d + 1, qi(a), qi(a + w)).unwrap();
        let s = BSpline::new(control.clone(), t).unwrap();
        let b = Bezier::new(control).unwrap();
        for k in us {
            let local = q(k, 48);
            let u = qi(a) + local.clone() * qi(w);
            prop_assert_eq!(s.eval(&u).unwrap(), b.eval(&local).unwrap());
        }
    }

    #[test]
    fn f64_agrees_with_exact(
        d in 0usize..=4,
        steps in prop::collection::vec(0i64..=12, 14),
        c in prop::collection::vec((-20i64..=20, -20i64..=20), 14),
        ks in prop::collection::vec(0i64..=64, 6),
    ) {
        // Knots in eighths (exact in f64): cumulative steps, 0 repeats a knot.
        let mut knots = Vec::new();
        let mut x = -1.0;
        for s in &steps {
            x += *s as f64 / 8.0;
            knots.push(x);
        }
        let len = (2 * d + 2).max(knots.len() - 2);
        knots.truncate(len);
        let Ok(tf) = KnotVector::new(d, knots.clone()) else { return Ok(()) };
        let n = tf.control_points();
        let cf: Vec<Point<f64, 2>> = c[..n].iter().copied().map(point).collect();
        let sf = BSpline::new(cf.clone(), tf).unwrap();
        let tq = KnotVector::new(d, knots.iter().map(|k| Q::from_f64(*k).unwrap()).collect()).unwrap();
        let sq = BSpline::new(c[..n].iter().copied().map(point).collect(), tq).unwrap();
        // |s(u)| ≤ max |cᵢ| (convex hull); each of the d levels rounds a convex combination.
        let m = cf.iter().flat_map(|p| p.coords().iter().map(|x| x.abs())).fold(1.0, f64::max);
        let bound = 1e-14 * m;
        let (a, b) = (*sf.knots().bounds().0, *sf.knots().bounds().1);
        for k in &ks {
            let u = a + (b - a) * (*k as f64 / 64.0);
            let uq = Q::from_f64(u).unwrap();
            let exact = sq.eval(&uq).unwrap().to_f64();
            let got = sf.eval(&u).unwrap();
            for j in 0..2 {
                prop_assert!((got[j] - exact[j]).abs() <= bound, "u = {}: {:?} vs {:?}", u, got, exact);
            }
            // The extended de Boor derivatives: order r divides r times by a width of at
            // least 1/8 and multiplies by at most d, so |s⁽ʳ⁾| ≤ (16d)ʳ·m and the rounding
            // error grows alike.
            let all_f = sf.derivatives(&u, d).unwrap();
            let all_q = sq.derivatives(&uq, d).unwrap();
            for (r, (g, e)) in all_f.iter().zip(&all_q).enumerate() {
                let e = e.to_f64();
                let scale = (16.0 * d.max(1) as f64).powi(r as i32);
                for j in 0..2 {
                    prop_assert!((g[j] - e[j]).abs() <= 1e-13 * scale * m, "order {} at {}: {:?} vs {:?}", r, u, g, e);
                }
            }
            if sf.knots().multiplicity(&u) < d {
                let rf = sf.insert(&u, 1).unwrap();
                let rq = sq.insert(&uq, 1).unwrap();
                for (p, e) in rf.control().iter().zip(rq.control()) {
                    let e = e.to_f64();
                    for j in 0..2 {
                        prop_assert!((p[j] - e[j]).abs() <= bound, "insert {}: {:?} vs {:?}", u, p, e);
                    }
                }
            }
        }
    }
}

#[test]
fn de_boor_counts_exactly_d_d_plus_1_over_2_off_the_knots() {
    for d in 0..=6 {
        let t = KnotVector::uniform(d, d + 5, 0.0, 1.0).unwrap();
        let s = BSpline::new((0..d + 5).map(|i| point((i as i64, 0))).collect(), t).unwrap();
        for k in 0..40 {
            let u = (k as f64 + 0.5) / 40.0; // never one of the knots i/5
            let mut c = Counts::default();
            s.de_boor_with(&u, &mut c).unwrap();
            assert_eq!(
                c.arithmetic_operations,
                (d * (d + 1) / 2) as u64,
                "d = {d}, u = {u}"
            );
        }
    }
}

#[test]
fn the_exercise_of_ppb_5_12_7() {
    // [PPB, §5.12, Ex. 7]: s = Σ cᵢ Nᵢ³ on the knots 0, 1, …, 7 with c₀, …, c₃ = 4, 7, −2, 1;
    // s, s′, s″, s‴ at u = 3 and the Bézier representation over [3, 4]. The text states no
    // answers; these were computed by hand from the uniform cubic B-spline's pieces (at the
    // start of a span its four functions take the values 1/6, 2/3, 1/6, 0, first derivatives
    // −1/2, 0, 1/2, 0, second 1, −2, 1, 0 and third −1, 3, −3, 1), and the Bézier points of a
    // uniform span are (c₀ + 4c₁ + c₂)/6, (2c₁ + c₂)/3, (c₁ + 2c₂)/3, (c₁ + 4c₂ + c₃)/6.
    let t = KnotVector::new(3, (0..=7).map(qi).collect()).unwrap();
    let s: BSpline<Q, 1> =
        BSpline::new([4, 7, -2, 1].map(|c| Point::new([qi(c)])).to_vec(), t).unwrap();
    assert_eq!(
        s.domain(),
        Domain::Interval {
            start: qi(3),
            end: qi(4)
        }
    );
    let want = [5, -3, -12, 24, 0];
    for (k, w) in want.iter().enumerate() {
        assert_eq!(
            s.derivative_at(&qi(3), k).unwrap(),
            Point::new([qi(*w)]),
            "order {k}"
        );
    }
    // The same by the extended de Boor algorithm [PPB, §5.9], all orders at once.
    let all = s.derivatives(&qi(3), 4).unwrap();
    assert_eq!(all, want.map(|w| Point::new([qi(w)])));
    // Inserting 3 and 4 twice each (4 is the closed end of the domain) leaves the Bézier
    // points 5, 4, 1, 0 as c₂, …, c₅.
    let r = s.insert(&qi(3), 2).unwrap().insert(&qi(4), 2).unwrap();
    let k: Vec<Q> = [0, 1, 2, 3, 3, 3, 4, 4, 4, 5, 6, 7].map(qi).to_vec();
    assert_eq!(r.knots().knots(), k);
    let bez: Vec<Point<Q, 1>> = [5, 4, 1, 0].map(|c| Point::new([qi(c)])).to_vec();
    assert_eq!(&r.control()[2..6], bez);
    let b = Bezier::new(bez).unwrap();
    for j in 0..=8 {
        let u = qi(3) + q(j, 8);
        assert_eq!(s.eval(&u).unwrap(), b.eval(&q(j, 8)).unwrap());
    }
}

/// `f64` evaluation, insertion and first derivative agree with the exact ones at `us`, each
/// coordinate within `rel` times the largest control coordinate, and nothing is NaN.
fn agrees_with_exact(s: &BSpline<f64, 2>, us: &[f64], rel: f64) {
    let e = exact(s);
    let m = s
        .control()
        .iter()
        .flat_map(|p| p.coords().iter().map(|x| x.abs()))
        .fold(f64::MIN_POSITIVE, f64::max);
    let close = |a: &Point<f64, 2>, b: &Point<Q, 2>, what: &str| {
        let b = b.to_f64();
        for j in 0..2 {
            assert!(a[j].is_finite(), "{what}: {a:?}");
            assert!((a[j] - b[j]).abs() <= rel * m, "{what}: {a:?} vs {b:?}");
        }
    };
    for u in us {
        let uq = Q::from_f64(*u).unwrap();
        close(
            &s.eval(u).unwrap(),
            &e.eval(&uq).unwrap(),
            &format!("eval {u}"),
        );
        if s.knots().multiplicity(u) < s.degree() {
            let r = s.insert(u, 1).unwrap();
            let rq = e.insert(&uq, 1).unwrap();
            assert_eq!(r.knots().knots().len(), s.knots().knots().len() + 1);
            for (a, b) in r.control().iter().zip(rq.control()) {
                close(a, b, &format!("insert {u}"));
            }
            for v in us {
                close(
                    &r.eval(v).unwrap(),
                    &e.eval(&Q::from_f64(*v).unwrap()).unwrap(),
                    "after",
                );
            }
        }
    }
}

#[test]
fn knots_a_few_ulps_apart_are_distinct_and_exact() {
    let one = 1.0f64;
    let up = |k: u64| f64::from_bits(one.to_bits() + k);
    // A triple knot at 1, then knots 1 ulp and 2 ulps above it (degree 3).
    let knots = vec![
        0.0,
        0.0,
        0.0,
        0.0,
        0.5,
        one,
        one,
        one,
        up(1),
        up(2),
        2.0,
        2.0,
        2.0,
        2.0,
    ];
    let t = KnotVector::new(3, knots).unwrap();
    let n = t.control_points();
    let c = (0..n)
        .map(|i| point(((i * 3 % 7) as i64, i as i64)))
        .collect();
    let s = BSpline::new(c, t).unwrap();
    let us = [0.25, 0.75, one, up(1), up(2), up(3), 1.5, 2.0];
    agrees_with_exact(&s, &us, 1e-14);
    // Inserting 1 ulp below the triple knot really inserts a new knot.
    let below = f64::from_bits(one.to_bits() - 1);
    let r = s.insert(&below, 1).unwrap();
    assert_eq!(r.knots().multiplicity(&below), 1);
    assert_eq!(r.knots().multiplicity(&one), 3);
    // A fourth copy of 1 would exceed the degree: refused, not merged or ignored.
    let e = s.insert(&one, 1).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "times", .. }),
        "{e}"
    );
    // The knot 1 ulp above 1 can be raised to multiplicity 3, next to the triple knot.
    let r = s.insert(&up(1), 2).unwrap();
    assert_eq!(
        (r.knots().multiplicity(&up(1)), r.knots().multiplicity(&one)),
        (3, 3)
    );
    let (e, re) = (
        exact(&s),
        exact(&s).insert(&Q::from_f64(up(1)).unwrap(), 2).unwrap(),
    );
    for (a, b) in r.control().iter().zip(re.control()) {
        let b = b.to_f64();
        assert!((a[0] - b[0]).abs() <= 1e-14 * 9.0 && (a[1] - b[1]).abs() <= 1e-14 * 9.0);
    }
    for u in us {
        let u = Q::from_f64(u).unwrap();
        assert_eq!(re.eval(&u).unwrap(), e.eval(&u).unwrap());
    }
}

#[test]
fn huge_and_subnormal_coordinates_and_knots_give_the_exact_curve() {
    let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 3.0, 4.0, 4.0, 4.0]).unwrap();
    let us = [0.0, 0.3, 1.0, 2.5, 3.0, 4.0];
    // Coordinates near 1e300.
    let c = [(1, -1), (-3, 2), (2, 5), (-1, 1), (4, -2)]
        .map(|(x, y)| Point::new([x as f64 * 1e300, y as f64 * 1e300]))
        .to_vec();
    agrees_with_exact(&BSpline::new(c, t.clone()).unwrap(), &us, 1e-14);
    // Subnormal coordinates.
    let tiny = f64::from_bits(1);
    let c = [(1, 3), (5, 2), (2, 7), (9, 1), (4, 4)]
        .map(|(x, y)| Point::new([x as f64 * tiny, y as f64 * tiny]))
        .to_vec();
    let s = BSpline::new(c, t.clone()).unwrap();
    for u in us {
        let p = s.eval(&u).unwrap();
        assert!(p[0].is_finite() && p[1].is_finite() && p[0] >= 0.0 && p[1] >= 0.0);
    }
    // Knots near ±1e300 (widths beyond the double range) and a subnormal distance apart.
    let big = vec![-1e308, -1e308, -1e308, 0.0, 1e308, 1e308, 1e308];
    let c = [(0, 0), (1, 2), (3, 1), (4, 0)].map(point).to_vec();
    let s = BSpline::new(c.clone(), KnotVector::new(2, big).unwrap()).unwrap();
    agrees_with_exact(&s, &[-1e308, -5e307, 0.0, 3e307, 1e308], 1e-14);
    let small = vec![0.0, 0.0, 0.0, tiny, 2.0 * tiny, 2.0 * tiny, 2.0 * tiny];
    let s = BSpline::new(c, KnotVector::new(2, small).unwrap()).unwrap();
    agrees_with_exact(&s, &[0.0, tiny, 2.0 * tiny], 1e-14);
    // Its derivative is beyond the double range: a named error, not infinity.
    assert!(matches!(s.derivative_curve(), Err(Error::Overflow { .. })));
}

#[test]
fn bad_input_is_a_named_error() {
    let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0).unwrap();
    let c: Vec<Point<f64, 2>> = [(0, 0), (1, 1), (2, 0), (3, 1)].map(point).to_vec();
    let e = BSpline::new(c[..3].to_vec(), t.clone()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid knots: 3 control points of degree 2 need 6 knots, got 7"
    );
    assert!(matches!(
        BSpline::<f64, 2>::new(vec![], t.clone()),
        Err(Error::Empty { .. })
    ));
    let mut bad = c.clone();
    bad[2] = Point::new([1.0, f64::NAN]);
    assert!(matches!(
        BSpline::new(bad, t.clone()),
        Err(Error::NonFinite { index: 2, .. })
    ));
    let mut bad = c.clone();
    bad[3] = Point::new([f64::NEG_INFINITY, 0.0]);
    assert!(matches!(
        BSpline::new(bad, t.clone()),
        Err(Error::NonFinite { index: 3, .. })
    ));
    let s = BSpline::new(c, t).unwrap();
    for u in [f64::NAN, f64::INFINITY, -0.5, 1.5] {
        for e in [
            s.eval(&u).unwrap_err(),
            s.de_boor_trace(&u).unwrap_err(),
            s.derivative_at(&u, 1).unwrap_err(),
            s.derivative_at(&u, 5).unwrap_err(),
            s.insert(&u, 1).unwrap_err(),
        ] {
            assert!(
                matches!(e, Error::InvalidParameter { name: "u", .. }),
                "{u}: {e}"
            );
        }
    }
    let e = s.insert(&0.0, 1).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid times: inserting 0 1 times gives multiplicity 4, more than the degree 2 (the \
         curve would break there)"
    );
    let e = s.insert(&0.5, 3).unwrap_err();
    assert!(e.to_string().contains("multiplicity 4"), "{e}");
    assert!(s.insert(&0.5, usize::MAX).is_err());
}

/// The curve traits' properties (`spline_common::curve_properties`) on B-splines: f64 against
/// exact, subsegments reproducing the curve, derivatives as differences of blossoms.
mod traits {
    use crate::spline_common::curve_properties::{curve_property_tests, eighths, points, Family};
    use compgeo::spline::{BSpline, KnotVector, Scalar};
    use proptest::prelude::*;

    /// Continuous B-splines of degree 1 to 4, clamped or not, knots and coordinates in
    /// eighths.
    struct Continuous;

    impl Family for Continuous {
        /// The degree, the knot increments (in eighths) and the control points.
        type Data = (usize, Vec<i64>, Vec<(i64, i64)>);
        type Curve<S: Scalar> = BSpline<S, 2>;
        const TOLERANCE: f64 = 1e-12;
        fn data() -> BoxedStrategy<Self::Data> {
            (1usize..=4, 0usize..=5)
                .prop_flat_map(|(d, extra)| {
                    let n = d + 1 + extra;
                    (
                        Just(d),
                        prop::collection::vec(0i64..=3, n + d),
                        prop::collection::vec((-80i64..=80, -80i64..=80), n),
                    )
                })
                .prop_map(|(d, mut steps, c)| {
                    // At most d − 1 zero steps in a row (multiplicity at most d: continuous),
                    // and a non-empty domain [t_d, t_n].
                    let mut zeros = 0;
                    for step in &mut steps {
                        zeros = if *step == 0 { zeros + 1 } else { 0 };
                        if zeros >= d {
                            (*step, zeros) = (1, 0);
                        }
                    }
                    let n = c.len();
                    if steps[d..n].iter().all(|s| *s == 0) {
                        steps[d] = 1;
                    }
                    (d, steps, c)
                })
                .boxed()
        }
        fn build<S: Scalar>((d, steps, c): &Self::Data) -> BSpline<S, 2> {
            let mut knots = vec![eighths::<S>(0)];
            let mut sum = 0;
            for step in steps {
                sum += step;
                knots.push(eighths(sum));
            }
            BSpline::new(points(c), KnotVector::new(*d, knots).unwrap()).unwrap()
        }
    }

    curve_property_tests! {
        continuous_b_splines: Continuous, 48;
    }
}
