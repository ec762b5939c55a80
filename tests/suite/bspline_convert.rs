//! B-splines to piecewise Bézier and back, and degree elevation, checked exactly on the
//! rational back end: every Bézier piece against de Boor's evaluation of the spline and
//! against the control points after inserting each knot up to multiplicity d by Boehm's
//! insertion; the round trip through `from_bezier`; the elevated curve against the original
//! at every knot and at rationals between, its knot multiplicities against the rule, two
//! elevations by one against one by two, a curve without interior knots against Bézier
//! elevation, and Micchelli's formula (with the seed's erratum) against the Cox–de Boor
//! recursion; the antiderivative against the curve and the Bézier pieces' integrals. Then the
//! counts, `f64` against exact (knots a few ulps apart, 1e300 and
//! subnormal coordinates), bad input as named errors, and exercises of [PPB, §5.12, §6.9].

use crate::bspline_basis::knot_vector;
use crate::spline_common::bspline::{exact, point, samples};
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{
    BSpline, Bezier, CompositeBezier, Curve, CurveDerivative, KnotVector, Point, Scalar,
};
use compgeo::Error;
use proptest::prelude::*;

/// An exact curve on a random knot vector of degree 0..=4 (repeated knots, clamped or not).
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

/// The distinct knots of the domain [t_d, t_n] with their multiplicities.
fn domain_knots(t: &KnotVector<Q>) -> Vec<(Q, usize)> {
    let (a, b) = t.bounds();
    t.multiplicities()
        .into_iter()
        .filter(|(v, _)| v >= a && v <= b)
        .collect()
}

/// Σ over the distinct knots of the domain of (d − m)(d − m + 1)/2, m capped at d.
fn conversion_count(t: &KnotVector<Q>) -> u64 {
    let d = t.degree();
    domain_knots(t)
        .into_iter()
        .map(|(_, m)| {
            let r = (d - m.min(d)) as u64;
            r * (r + 1) / 2
        })
        .sum()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn bezier_pieces_are_the_spline(s in curve()) {
        let d = s.degree();
        let mut c = Counts::default();
        let b = s.to_bezier_with(&mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, conversion_count(s.knots()));
        let knots: Vec<Q> = domain_knots(s.knots()).into_iter().map(|(v, _)| v).collect();
        prop_assert_eq!(b.partition(), &knots[..]);
        // The oracle: each knot of the domain inserted up to multiplicity d by Boehm's
        // algorithm; the Bézier points of span μ are then the control points μ − d, …, μ.
        let mut r = s.clone();
        for (v, m) in domain_knots(s.knots()) {
            if m < d {
                r = r.insert(&v, d - m).unwrap();
            }
        }
        let rt = r.knots().knots();
        let spans: Vec<usize> = (d..r.control().len()).filter(|&mu| rt[mu] < rt[mu + 1]).collect();
        prop_assert_eq!(spans.len(), b.pieces().len());
        for (i, (piece, &mu)) in b.pieces().iter().zip(&spans).enumerate() {
            prop_assert_eq!(piece.degree(), d);
            prop_assert_eq!(piece.control(), &r.control()[mu - d..=mu], "piece {}", i);
            // And against de Boor at rationals of the span (the right end only where the
            // spline is continuous: it is right-continuous at a jump).
            let (lo, hi) = (&b.partition()[i], &b.partition()[i + 1]);
            let continuous = i + 1 == b.pieces().len() || s.knots().multiplicity(hi) <= d;
            for k in 0..=12 {
                if k == 12 && !continuous {
                    continue;
                }
                let local = q(k, 12);
                let u = lo.clone() + (hi.clone() - lo) * &local;
                prop_assert_eq!(piece.eval(&local).unwrap(), s.de_boor(&u).unwrap());
            }
        }
    }

    #[test]
    fn from_bezier_of_to_bezier_is_the_same_curve(s in curve()) {
        let b = s.to_bezier().unwrap();
        let d = s.degree();
        match BSpline::from_bezier(&b) {
            Ok(back) => {
                prop_assert_eq!(back.degree(), d);
                for u in samples(s.knots()) {
                    prop_assert_eq!(back.eval(&u).unwrap(), s.eval(&u).unwrap());
                }
                // Interior knots of multiplicity d (1 for degree 0), ends d + 1.
                let m = back.knots().multiplicities();
                prop_assert_eq!(m.len(), b.partition().len());
                for (k, (v, mult)) in m.iter().enumerate() {
                    prop_assert_eq!(v, &b.partition()[k]);
                    let end = k == 0 || k + 1 == m.len();
                    prop_assert_eq!(*mult, if end { d + 1 } else { d.max(1) });
                }
                // Its own pieces are the same pieces.
                prop_assert_eq!(back.to_bezier().unwrap(), b);
            }
            Err(e) => {
                // Only a jump (an interior knot of multiplicity d + 1) breaks the joins.
                prop_assert!(matches!(e, Error::InvalidParameter { name: "pieces", .. }), "{}", e);
                let jump = b.pieces().windows(2).any(|w| w[0].control()[d] != w[1].control()[0]);
                prop_assert!(jump, "{}", e);
            }
        }
    }

    #[test]
    fn elevation_preserves_the_curve_and_raises_every_knot(s in curve(), times in 1usize..=3) {
        let d = s.degree();
        let mut c = Counts::default();
        let e = s.elevate_with(times, &mut c).unwrap();
        prop_assert_eq!(e.degree(), d + times);
        prop_assert_eq!(e.knots().bounds(), s.knots().bounds());
        for u in samples(s.knots()) {
            prop_assert_eq!(e.eval(&u).unwrap(), s.eval(&u).unwrap(), "u = {}", u);
        }
        let before = domain_knots(s.knots());
        let after = domain_knots(e.knots());
        prop_assert_eq!(before.len(), after.len());
        for ((v, m), (w, k)) in before.iter().zip(&after) {
            prop_assert_eq!(v, w);
            prop_assert_eq!(*k, m + times);
        }
        let k = before.len();
        prop_assert_eq!(e.control().len(), s.control().len() + times * (k - 1));
        // d + t knots on each side of the domain.
        let (a, b) = e.knots().bounds();
        let t = e.knots().knots();
        prop_assert_eq!(&t[d + times], a);
        prop_assert_eq!(&t[t.len() - 1 - (d + times)], b);
        let p = (k - 1) as u64;
        let dt = (d + times) as u64;
        let want = conversion_count(s.knots())
            + p * (d as u64 + 1) * (times as u64 + 1)
            + e.control().len() as u64 * dt * (dt + 1) / 2;
        prop_assert_eq!(c.arithmetic_operations, want);
    }

    #[test]
    fn elevating_twice_by_one_is_elevating_by_two(s in curve()) {
        let twice = s.elevate(1).unwrap().elevate(1).unwrap();
        prop_assert_eq!(twice, s.elevate(2).unwrap());
    }

    #[test]
    fn without_interior_knots_elevation_is_bezier_elevation(
        c in prop::collection::vec((-20i64..=20, -20i64..=20), 1..=6),
        times in 0usize..=4,
        (lo, w) in (-5i64..=5, 1i64..=4),
    ) {
        let d = c.len() - 1;
        let control: Vec<Point<Q, 2>> = c.into_iter().map(point).collect();
        let t = KnotVector::clamped_uniform(d, d + 1, qi(lo), qi(lo + w)).unwrap();
        let s = BSpline::new(control.clone(), t).unwrap();
        let e = s.elevate(times).unwrap();
        let b = Bezier::new(control).unwrap();
        let zhou = b.elevate_to(d + times).unwrap();
        prop_assert_eq!(e.control(), zhou.control());
        let mut by_one = b;
        for _ in 0..times {
            by_one = by_one.elevate().unwrap();
        }
        prop_assert_eq!(e.control(), by_one.control());
        // And its one piece is that Bézier curve.
        let pieces = e.to_bezier().unwrap();
        prop_assert_eq!(pieces.pieces(), &[by_one][..]);
    }

    #[test]
    fn the_integral_is_the_antiderivative_and_the_sum_of_the_bezier_integrals(s in curve()) {
        // The antiderivative's derivative is s on the whole domain (right-continuous at a
        // jump, as s), it starts at 0, and its value at t_n is Σ (b − a)∫₀¹ of the Bézier
        // pieces (an independent oracle), [PPB, §5.12, Ex. 2] on a clamped vector.
        let d = s.degree();
        let mut c = Counts::default();
        let big_s = s.integral_with(&mut c).unwrap();
        prop_assert_eq!(big_s.degree(), d + 1);
        prop_assert_eq!(big_s.domain(), s.domain());
        let (start, end) = (s.knots().bounds().0.clone(), s.knots().bounds().1.clone());
        prop_assert_eq!(big_s.eval(&start).unwrap(), Point::zero());
        for u in samples(s.knots()) {
            prop_assert_eq!(big_s.derivative_at(&u, 1).unwrap(), s.eval(&u).unwrap(), "at {}", u);
        }
        let n = s.control().len() as u64;
        let t = s.knots().knots();
        let clamped_start = t[0] == t[d];
        let want = if clamped_start { n } else { n + (d + 1) as u64 * (d + 2) as u64 / 2 + n + 1 };
        // (de Boor at t_d skips the levels of t_d's multiplicity; an upper bound then.)
        prop_assert!(c.arithmetic_operations <= want);
        if clamped_start {
            prop_assert_eq!(c.arithmetic_operations, n);
        }
        let b = s.to_bezier().unwrap();
        let mut oracle = Point::<Q, 2>::zero();
        for (i, piece) in b.pieces().iter().enumerate() {
            let width = b.partition()[i + 1].clone() - &b.partition()[i];
            oracle += &(piece.definite_integral() * &width);
        }
        prop_assert_eq!(s.definite_integral().unwrap(), oracle.clone());
        prop_assert_eq!(big_s.eval(&end).unwrap(), oracle.clone());
        if s.knots().is_clamped() {
            let order = qi(d as i64 + 1);
            let mut formula = Point::<Q, 2>::zero();
            for (i, ci) in s.control().iter().enumerate() {
                formula += &(ci.clone() * &((t[i + d + 1].clone() - &t[i]) / &order));
            }
            prop_assert_eq!(formula, oracle);
        }
    }

    #[test]
    fn f64_agrees_with_exact(
        d in 0usize..=4,
        times in 1usize..=2,
        steps in prop::collection::vec(0i64..=12, 14),
        c in prop::collection::vec((-20i64..=20, -20i64..=20), 14),
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
        let Ok(tf) = KnotVector::new(d, knots) else { return Ok(()) };
        let n = tf.control_points();
        let sf = BSpline::new(c[..n].iter().copied().map(point).collect(), tf).unwrap();
        let sq = exact(&sf);
        let m = 20.0;
        // The conversion is convex combinations, d levels: a few ulps of the largest
        // coordinate.
        let bf = sf.to_bezier().unwrap();
        let bq = sq.to_bezier().unwrap();
        for (pf, pq) in bf.pieces().iter().zip(bq.pieces()) {
            close(pf.control(), pq.control(), 1e-14 * m)?;
        }
        // The elevation's blossoms extrapolate the widest piece under a support by weights
        // of size at most d + t + 1, so rounding can grow by up to (2(d + t) + 3) per level:
        // the bound below, which the observed errors stay far within.
        let ef = sf.elevate(times).unwrap();
        let eq = sq.elevate(times).unwrap();
        prop_assert_eq!(ef.knots().knots().len(), eq.knots().knots().len());
        let dt = (d + times) as i32;
        let bound = 1e-15 * m * (2.0 * dt as f64 + 3.0).powi(dt) * (dt as f64 + 1.0);
        close(ef.control(), eq.control(), bound)?;
    }
}

/// Each coordinate of `a` within `bound` of the exact `b`, and finite.
fn close(a: &[Point<f64, 2>], b: &[Point<Q, 2>], bound: f64) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.len(), b.len());
    for (p, e) in a.iter().zip(b) {
        let e = e.to_f64();
        for j in 0..2 {
            prop_assert!(p[j].is_finite(), "{:?}", p);
            prop_assert!(
                (p[j] - e[j]).abs() <= bound,
                "{:?} vs {:?} (bound {})",
                p,
                e,
                bound
            );
        }
    }
    Ok(())
}

/// The largest absolute coordinate of the control points.
fn largest(s: &BSpline<f64, 2>) -> f64 {
    s.control()
        .iter()
        .flat_map(|p| p.coords().iter().map(|x| x.abs()))
        .fold(0.0, f64::max)
}

/// The conversion and the elevation of `s` in `f64` agree with the exact ones within `rel`
/// times the largest coordinate, the elevated knots are the exact ones, and the `f64`
/// curves evaluate as the exact original at `us`.
fn agrees_with_exact(s: &BSpline<f64, 2>, times: usize, us: &[f64], rel: f64) {
    let e = exact(s);
    let bound = rel * largest(s);
    close(
        &s.to_bezier()
            .unwrap()
            .pieces()
            .iter()
            .flat_map(|p| p.control().to_vec())
            .collect::<Vec<_>>(),
        &e.to_bezier()
            .unwrap()
            .pieces()
            .iter()
            .flat_map(|p| p.control().to_vec())
            .collect::<Vec<_>>(),
        bound,
    )
    .unwrap();
    let (ef, eq) = (s.elevate(times).unwrap(), e.elevate(times).unwrap());
    let kq: Vec<Q> = ef
        .knots()
        .knots()
        .iter()
        .map(|k| Q::from_f64(*k).unwrap())
        .collect();
    assert_eq!(kq, eq.knots().knots());
    close(ef.control(), eq.control(), bound).unwrap();
    for u in us {
        let want = e.eval(&Q::from_f64(*u).unwrap()).unwrap();
        close(&[ef.eval(u).unwrap()], &[want], 4.0 * bound).unwrap();
    }
}

#[test]
fn knots_a_few_ulps_apart_stay_distinct_pieces_and_exact() {
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
    let b = s.to_bezier().unwrap();
    // Two pieces one ulp wide, not merged.
    assert_eq!(b.partition(), [0.0, 0.5, one, up(1), up(2), 2.0]);
    let us = [0.25, 0.75, one, up(1), up(2), up(3), 1.5, 2.0];
    agrees_with_exact(&s, 1, &us, 1e-13);
    agrees_with_exact(&s, 2, &us, 1e-13);
    let e = s.elevate(1).unwrap();
    let mult = |x: f64| e.knots().multiplicity(&x);
    assert_eq!(
        (mult(0.0), mult(0.5), mult(one), mult(up(1)), mult(up(2))),
        (5, 2, 4, 2, 2)
    );
}

#[test]
fn huge_and_subnormal_coordinates_give_the_exact_conversion_and_elevation() {
    let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 3.0, 4.0, 4.0, 4.0]).unwrap();
    let us = [0.0, 0.3, 1.0, 2.5, 3.0, 4.0];
    let pairs = [(1, -1), (-3, 2), (2, 5), (-1, 1), (4, -2)];
    // Coordinates near 1e300.
    let c = pairs
        .map(|(x, y)| Point::new([x as f64 * 1e300, y as f64 * 1e300]))
        .to_vec();
    agrees_with_exact(&BSpline::new(c, t.clone()).unwrap(), 2, &us, 1e-13);
    // Unclamped, near 1e300.
    let u = KnotVector::uniform(2, 5, 0.0, 3.0).unwrap();
    let c = pairs
        .map(|(x, y)| Point::new([x as f64 * 1e300, y as f64 * 1e300]))
        .to_vec();
    agrees_with_exact(
        &BSpline::new(c, u).unwrap(),
        1,
        &[0.0, 0.5, 2.0, 3.0],
        1e-13,
    );
    // Subnormal coordinates: finite, and within a few units of the smallest subnormal.
    let tiny = f64::from_bits(1);
    let c: Vec<Point<f64, 2>> = [(1, 3), (5, 2), (2, 7), (9, 1), (4, 4)]
        .map(|(x, y)| Point::new([x as f64 * tiny, y as f64 * tiny]))
        .to_vec();
    let s = BSpline::new(c, t).unwrap();
    let e = exact(&s);
    let quanta = |a: &[Point<f64, 2>], b: &[Point<Q, 2>]| close(a, b, 8.0 * tiny).unwrap();
    let (bf, bq) = (s.to_bezier().unwrap(), e.to_bezier().unwrap());
    for (pf, pq) in bf.pieces().iter().zip(bq.pieces()) {
        quanta(pf.control(), pq.control());
    }
    quanta(
        s.elevate(1).unwrap().control(),
        e.elevate(1).unwrap().control(),
    );
}

#[test]
fn the_conversion_counts_only_the_missing_copies() {
    // Clamped with interior knots of multiplicity d: nothing to insert.
    let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]).unwrap();
    let s = BSpline::new([0, 1, 3, 2, 5].map(|x| point((x, 0))).to_vec(), t).unwrap();
    let mut c = Counts::default();
    let b = s.to_bezier_with(&mut c).unwrap();
    assert_eq!(c.arithmetic_operations, 0);
    assert_eq!(b.pieces()[1].control(), &s.control()[2..]);
    // A uniform cubic with 5 spans: 6 simple knots in the domain, each raised to
    // multiplicity 3 by 2 + 1 affine combinations (a double Boehm insertion).
    let t = KnotVector::uniform(3, 8, 0.0, 5.0).unwrap();
    let s = BSpline::new((0..8).map(|i| point((i, i * i))).collect(), t).unwrap();
    let mut c = Counts::default();
    assert_eq!(s.to_bezier_with(&mut c).unwrap().pieces().len(), 5);
    assert_eq!(c.arithmetic_operations, 6 * 3);
}

#[test]
fn bad_input_gives_named_errors() {
    let p = |x: f64| Point::new([x, 0.0]);
    // Degrees differ.
    let b = CompositeBezier::new(
        vec![0.0, 1.0, 2.0],
        vec![vec![p(0.0), p(1.0), p(2.0)], vec![p(2.0), p(3.0)]],
    )
    .unwrap();
    let e = BSpline::from_bezier(&b).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "pieces", .. })
            && e.to_string()
                .contains("piece 1 has degree 1, piece 0 has degree 2"),
        "{e}"
    );
    // Ends one ulp apart do not match: compared exactly.
    let next = f64::from_bits(2.0f64.to_bits() + 1);
    let b = CompositeBezier::new(
        vec![0.0, 1.0, 2.0, 3.0],
        vec![
            vec![p(0.0), p(2.0)],
            vec![p(2.0), p(4.0)],
            vec![p(next * 2.0), p(5.0)],
        ],
    )
    .unwrap();
    let e = BSpline::from_bezier(&b).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "pieces", .. })
            && e.to_string().contains("piece 2 starts at"),
        "{e}"
    );
    // Degree 0: steps, joined by simple knots.
    let b = CompositeBezier::new(vec![0.0, 1.0, 3.0], vec![vec![p(1.0)], vec![p(7.0)]]).unwrap();
    let s = BSpline::from_bezier(&b).unwrap();
    assert_eq!(s.knots().knots(), [0.0, 1.0, 3.0]);
    assert_eq!(
        (s.eval(&0.5).unwrap(), s.eval(&1.0).unwrap()),
        (p(1.0), p(7.0))
    );
    // Degrees beyond the limit, and knots beyond the limit, before any allocation.
    let t = KnotVector::clamped_uniform(1, 3, 0.0, 1.0).unwrap();
    let s = BSpline::new(vec![p(0.0), p(1.0), p(3.0)], t).unwrap();
    assert!(matches!(
        s.elevate(usize::MAX),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        s.elevate(compgeo::limits::MAX_DEGREE),
        Err(Error::LimitExceeded { .. })
    ));
    let t = KnotVector::clamped_uniform(1, 3000, 0.0, 1.0).unwrap();
    let s = BSpline::new(vec![p(0.0); 3000], t).unwrap();
    let e = s.elevate(60_000).unwrap_err();
    assert!(
        matches!(
            e,
            Error::LimitExceeded {
                limit: "MAX_KNOTS",
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(s.elevate(0).unwrap(), s);
}

#[test]
fn micchelli_s_formula_with_the_erratum() {
    // [PPB, §6.5, eq. (1)] for n = 1 with a, b, c = 0, 1, 3: the seed prints
    // N¹(u|abc) = ⅓(N²(u|abc) + N²(u|abb) + N²(u|abcc)) (000 l.2242); the formula itself gives
    // N¹(u|abc) = ½(N²(u|aabc) + N²(u|abbc) + N²(u|abcc)) (SCOPE §9). Checked against the
    // Cox–de Boor recursion at rationals across [a, c]; the printed version fails.
    let (a, b, c) = (qi(0), qi(1), qi(3));
    let k = |v: &[&Q]| v.iter().map(|x| (*x).clone()).collect::<Vec<Q>>();
    let mut printed_fails = false;
    for j in 0..24 {
        let u = q(j, 8);
        let left = single(&k(&[&a, &b, &c]), &u);
        let right = (single(&k(&[&a, &a, &b, &c]), &u)
            + single(&k(&[&a, &b, &b, &c]), &u)
            + single(&k(&[&a, &b, &c, &c]), &u))
            * q(1, 2);
        assert_eq!(left, right, "u = {u}");
        let printed = (single(&k(&[&a, &b, &c]), &u)
            + single(&k(&[&a, &b, &b]), &u)
            + single(&k(&[&a, &b, &c, &c]), &u))
            * q(1, 3);
        printed_fails |= printed != left;
    }
    assert!(printed_fails);
    // And the same for n = 2 on 0, 1, 3, 4: five terms, each knot doubled in turn, over 3.
    let knots = [0, 1, 3, 4].map(qi);
    for j in 0..32 {
        let u = q(j, 8);
        let mut sum = qi(0);
        for i in 0..4 {
            let mut doubled = knots.to_vec();
            doubled.insert(i, knots[i].clone());
            sum += single(&doubled, &u);
        }
        assert_eq!(single(&knots, &u), sum * q(1, 3), "u = {u}");
    }
}

/// The B-spline of degree `knots.len() − 2` on `knots` at u, by the Cox–de Boor recursion
/// (right-continuous, 0/0 = 0), as [PPB, §5.3] defines it.
fn single(knots: &[Q], u: &Q) -> Q {
    if knots.len() == 2 {
        let inside = &knots[0] <= u && u < &knots[1];
        return if inside { qi(1) } else { qi(0) };
    }
    let n = knots.len() - 2;
    let mut v = qi(0);
    if knots[n] != knots[0] {
        v += (u.clone() - &knots[0]) / (knots[n].clone() - &knots[0]) * single(&knots[..=n], u);
    }
    if knots[n + 1] != knots[1] {
        v += (knots[n + 1].clone() - u) / (knots[n + 1].clone() - &knots[1])
            * single(&knots[1..], u);
    }
    v
}

#[test]
fn the_bezier_pieces_of_ppb_5_12_7() {
    // [PPB, §5.12, Ex. 7 d)]: the Bézier representation over [3, 4] of s = Σ cᵢ Nᵢ³ on the
    // knots 0, 1, …, 7 with c = 4, 7, −2, 1. The text states no answer; by the uniform span's
    // Bézier points (c₀ + 4c₁ + c₂)/6, (2c₁ + c₂)/3, (c₁ + 2c₂)/3, (c₁ + 4c₂ + c₃)/6 it is
    // 5, 4, 1, 0 (the hand computation of bspline_curve.rs's test of the same exercise).
    let t = KnotVector::new(3, (0..=7).map(qi).collect()).unwrap();
    let s: BSpline<Q, 1> =
        BSpline::new([4, 7, -2, 1].map(|c| Point::new([qi(c)])).to_vec(), t).unwrap();
    let b = s.to_bezier().unwrap();
    assert_eq!(b.partition(), [qi(3), qi(4)]);
    let want: Vec<Point<Q, 1>> = [5, 4, 1, 0].map(|c| Point::new([qi(c)])).to_vec();
    assert_eq!(b.pieces()[0].control(), want);
}

#[test]
fn the_bezier_ordinates_of_ppb_5_12_3() {
    // [PPB, §5.12, Ex. 3]: the Bézier ordinates of the cubic B-spline on 0, 1, 2, 3, 4 (the
    // text asks for them without stating them; these are the classical values 0, 0, 0, 1/6 |
    // 1/6, 1/3, 2/3, 2/3 | 2/3, 2/3, 1/3, 1/6 | 1/6, 0, 0, 0, the uniform B-spline's).
    // N₃ of the knots −3, …, 7 is that B-spline, and [0, 4] is the domain.
    let t = KnotVector::new(3, (-3..=7).map(qi).collect()).unwrap();
    let c = (0..7)
        .map(|i| Point::new([if i == 3 { qi(1) } else { qi(0) }]))
        .collect();
    let s: BSpline<Q, 1> = BSpline::new(c, t).unwrap();
    let b = s.to_bezier().unwrap();
    let want = [
        [q(0, 1), q(0, 1), q(0, 1), q(1, 6)],
        [q(1, 6), q(1, 3), q(2, 3), q(2, 3)],
        [q(2, 3), q(2, 3), q(1, 3), q(1, 6)],
        [q(1, 6), q(0, 1), q(0, 1), q(0, 1)],
    ];
    assert_eq!(b.partition(), (0..=4).map(qi).collect::<Vec<_>>());
    for (piece, w) in b.pieces().iter().zip(want) {
        let got: Vec<Q> = piece.control().iter().map(|p| p[0].clone()).collect();
        assert_eq!(got, w);
    }
    // [PPB, §6.9, Ex. 5]: a Bézier curve of degree n as a B-spline on 0, …, n, m + 1, …,
    // m + n + 1 becomes its degree-m Bézier points after inserting n + 1, …, m (here n = 2,
    // m = 5), as Zhou's formula gives them.
    let (n, m) = (2usize, 5usize);
    let knots: Vec<Q> = (0..=n)
        .chain(m + 1..=m + n + 1)
        .map(|k| qi(k as i64))
        .collect();
    let pts: Vec<Point<Q, 2>> = [(0, 0), (3, 6), (9, -3)].map(point).to_vec();
    let mut s = BSpline::new(pts.clone(), KnotVector::new(n, knots).unwrap()).unwrap();
    for k in n + 1..=m {
        s = s.insert(&qi(k as i64), 1).unwrap();
    }
    assert_eq!(
        s.control(),
        Bezier::new(pts).unwrap().elevate_to(m).unwrap().control()
    );
}
