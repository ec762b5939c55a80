//! Knot manipulation of B-spline curves, checked exactly on the rational back end: the
//! refinement (one backward pass of Boehm's insertions, and the Oslo algorithm) against the
//! same knots inserted one by one with Boehm's algorithm (identical
//! control points) and against the curve at rational parameters; insert-then-remove giving the
//! identical control points back; a removal that succeeds exactly when the derivative of order
//! d − s + 1 is continuous at the knot (from both sides, by the basis derivatives of the curve
//! and of its left piece); split pieces against the curve on their halves. Then the `f64` path
//! against the exact one (knots a few ulps apart, 1e300 and subnormal coordinates) and bad input
//! as named errors.

use crate::bspline_basis::{knot_vector, parameter};
use crate::spline_common::bspline::{exact, point};
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{BSpline, Curve, CurveDerivative, KnotVector, Point, Scalar};
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

/// A curve and up to five parameters of its domain (ends, knots, rationals), in random order.
fn curve_and_knots() -> impl Strategy<Value = (BSpline<Q, 2>, Vec<Q>)> {
    curve().prop_flat_map(|s| {
        let us = prop::collection::vec(parameter(s.knots()), 0..=5);
        (Just(s), us)
    })
}

/// A curve and a parameter strictly inside its domain (a knot or a rational).
fn curve_and_inner() -> impl Strategy<Value = (BSpline<Q, 2>, Q)> {
    curve().prop_flat_map(|s| {
        let (a, b) = (s.knots().bounds().0.clone(), s.knots().bounds().1.clone());
        let inner: Vec<Q> = s
            .knots()
            .knots()
            .iter()
            .filter(|k| **k > a && **k < b)
            .cloned()
            .collect();
        let between = (1i64..60).prop_map(move |k| a.clone() + (b.clone() - &a) * q(k, 60));
        let u = if inner.is_empty() {
            between.boxed()
        } else {
            prop_oneof![1 => prop::sample::select(inner), 2 => between].boxed()
        };
        (Just(s), u)
    })
}

/// Every knot of [lo, hi] and 13 rationals across it.
fn samples(t: &KnotVector<Q>, lo: &Q, hi: &Q) -> Vec<Q> {
    let mut us: Vec<Q> = (0..=12)
        .map(|k| lo.clone() + (hi.clone() - lo) * q(k, 12))
        .collect();
    us.extend(t.knots().iter().filter(|k| *k >= lo && *k <= hi).cloned());
    us
}

fn domain_samples(t: &KnotVector<Q>) -> Vec<Q> {
    let (a, b) = t.bounds();
    samples(t, a, b)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn refinement_is_the_single_insertions_exactly((s, us) in curve_and_knots()) {
        // Both algorithms, the backward pass of Boehm's insertions and the Oslo algorithm,
        // against the same knots inserted one by one, in the order given.
        let d = s.degree();
        let mut c = Counts::default();
        let result = s.refine_with(&us, &mut c);
        let mut c_oslo = Counts::default();
        let oslo = s.oslo_with(&us, &mut c_oslo);
        let mut one = Ok(s.clone());
        let mut c_one = Counts::default();
        for u in &us {
            one = one.and_then(|r: BSpline<Q, 2>| r.insert_with(u, 1, &mut c_one));
        }
        match (result, oslo) {
            (Ok(r), Ok(o)) => {
                let one = one.unwrap();
                prop_assert_eq!(&r, &one);
                prop_assert_eq!(&o, &one);
                prop_assert_eq!(r.knots().knots().len(), s.knots().knots().len() + us.len());
                for v in domain_samples(s.knots()) {
                    prop_assert_eq!(r.eval(&v).unwrap(), s.eval(&v).unwrap(), "u = {}", v);
                }
                // The backward pass makes exactly Σ r(d − s) − r(r − 1)/2 combinations over the
                // distinct new knots (r new copies, s old ones), also at t_n, where a single
                // insertion combines with the copies above it too (and counts d).
                let mut want = 0u64;
                let mut distinct = us.clone();
                distinct.sort();
                distinct.dedup();
                for v in &distinct {
                    let r = us.iter().filter(|w| *w == v).count() as u64;
                    let old = s.knots().multiplicity(v) as u64;
                    want += r * (d as u64 - old) - r * (r - 1) / 2;
                }
                prop_assert_eq!(c.arithmetic_operations, want);
                prop_assert!(c.arithmetic_operations <= c_one.arithmetic_operations);
                // Oslo: each computed point costs d(d + 1)/2 + d + 1; at most md are computed
                // (all of them for degree 0).
                let per = (d * (d + 1) / 2 + d + 1) as u64;
                prop_assert_eq!(c_oslo.arithmetic_operations % per, 0);
                let most = if d == 0 { r.control().len() } else { us.len() * d };
                prop_assert!(c_oslo.arithmetic_operations <= per * most as u64);
            }
            (Err(e), Err(e_oslo)) => {
                // Refused exactly when some knot would pass multiplicity d.
                prop_assert!(one.is_err(), "{}", e);
                let over = us.iter().any(|u| {
                    s.knots().multiplicity(u) + us.iter().filter(|v| *v == u).count() > d
                });
                prop_assert!(over, "{}", e);
                for e in [e, e_oslo] {
                    let named = matches!(e, Error::InvalidParameter { name: "new_knots", .. });
                    prop_assert!(named, "{}", e);
                }
            }
            (r, o) => prop_assert!(false, "refine {:?} but oslo {:?}", r.is_ok(), o.is_ok()),
        }
    }

    #[test]
    fn insert_then_remove_gives_the_control_points_back(
        (s, u) in curve_and_inner(),
        times in 1usize..=4,
    ) {
        let Ok(r) = s.insert(&u, times) else { return Ok(()) };
        let back = r.remove(&u, times).unwrap();
        prop_assert_eq!(&back, &s);
        prop_assert_eq!(&r.remove_within(&u, times, &qi(0)).unwrap(), &s);
        // Removing fewer copies: the curve is unchanged and has the knot times − k times more.
        for k in 1..times {
            let part = r.remove(&u, k).unwrap();
            prop_assert_eq!(part.knots().multiplicity(&u), s.knots().multiplicity(&u) + times - k);
            for v in domain_samples(s.knots()) {
                prop_assert_eq!(part.eval(&v).unwrap(), s.eval(&v).unwrap());
            }
        }
        // Refine-then-remove too.
        let refined = s.refine(&vec![u.clone(); times]).unwrap();
        prop_assert_eq!(&refined, &r);
    }

    #[test]
    fn a_knot_is_removable_exactly_where_the_curve_is_smoother((s, u) in curve_and_inner()) {
        let d = s.degree();
        let m = s.knots().multiplicity(&u);
        prop_assume!(m > 0);
        // The derivative of order k = d − m + 1 from both sides of u: from the right on the
        // curve, from the left at the end of its left piece.
        let k = d + 1 - m;
        let (left, _) = s.split(&u).unwrap();
        let continuous = left.derivative_at(&u, k).unwrap() == s.derivative_at(&u, k).unwrap();
        match s.remove(&u, 1) {
            Ok(r) => {
                prop_assert!(continuous);
                prop_assert_eq!(r.knots().multiplicity(&u), m - 1);
                for v in domain_samples(s.knots()) {
                    prop_assert_eq!(r.eval(&v).unwrap(), s.eval(&v).unwrap());
                }
            }
            Err(e) => {
                prop_assert!(!continuous, "{}", e);
                let named = matches!(e, Error::InvalidParameter { name: "times", .. });
                prop_assert!(named, "{}", e);
                let msg = e.to_string();
                let want = format!("the curve is C^{} there, not C^{}", k as i64 - 1, k);
                prop_assert!(msg.contains("0 of 1 removals succeeded"), "{}", msg);
                prop_assert!(msg.contains(&want), "{}", msg);
            }
        }
    }

    #[test]
    fn split_pieces_are_the_curve_on_their_halves((s, u) in curve_and_inner()) {
        let d = s.degree();
        let mut c = Counts::default();
        let (left, right) = s.split_with(&u, &mut c).unwrap();
        let (a, b) = (s.knots().bounds().0.clone(), s.knots().bounds().1.clone());
        prop_assert_eq!(left.knots().bounds(), (&a, &u));
        prop_assert_eq!(right.knots().bounds(), (&u, &b));
        let m = s.knots().multiplicity(&u);
        for v in samples(s.knots(), &a, &u) {
            if v < u || m <= d {
                prop_assert_eq!(left.eval(&v).unwrap(), s.eval(&v).unwrap(), "left {}", v);
            }
        }
        for v in samples(s.knots(), &u, &b) {
            prop_assert_eq!(right.eval(&v).unwrap(), s.eval(&v).unwrap(), "right {}", v);
        }
        // The knot vectors: the original knots below (above) u, then d + 1 copies of u.
        let lk = left.knots().knots();
        let rk = right.knots().knots();
        prop_assert!(lk[lk.len() - d - 1..].iter().all(|k| *k == u));
        prop_assert!(rk[..=d].iter().all(|k| *k == u));
        let below: Vec<&Q> = s.knots().knots().iter().filter(|k| **k < u).collect();
        let above: Vec<&Q> = s.knots().knots().iter().filter(|k| **k > u).collect();
        prop_assert_eq!(lk.iter().filter(|k| **k < u).collect::<Vec<_>>(), below);
        prop_assert_eq!(rk.iter().filter(|k| **k > u).collect::<Vec<_>>(), above);
        let r = d.saturating_sub(m);
        prop_assert_eq!(c.arithmetic_operations, (r * (r + 1) / 2) as u64);
    }

    #[test]
    fn f64_agrees_with_exact(
        d in 1usize..=4,
        steps in prop::collection::vec(1i64..=12, 12),
        c in prop::collection::vec((-20i64..=20, -20i64..=20), 12),
        new in prop::collection::vec(1i64..=63, 1..=6),
    ) {
        // Distinct knots in eighths (exact in f64), clamped.
        let mut inner = Vec::new();
        let mut x = 0.0;
        for s in &steps[..12 - 2 * d - 2] {
            x += *s as f64 / 8.0;
            inner.push(x);
        }
        let end = x + 1.0;
        let mut knots = vec![0.0; d + 1];
        knots.extend(&inner);
        knots.extend(vec![end; d + 1]);
        let tf = KnotVector::new(d, knots.clone()).unwrap();
        let n = tf.control_points();
        let sf = BSpline::new(c[..n].iter().copied().map(point).collect(), tf).unwrap();
        let sq = exact(&sf);
        let new_f: Vec<f64> = new.iter().map(|k| end * (*k as f64 / 64.0)).collect();
        let new_q: Vec<Q> = new_f.iter().map(|x| Q::from_f64(*x).unwrap()).collect();
        let bound = 1e-12 * 20.0;
        if let Ok(rf) = sf.refine(&new_f) {
            let rq = sq.refine(&new_q).unwrap();
            close_all(rf.control(), rq.control(), bound);
        }
        let uf = new_f[0];
        let uq = &new_q[0];
        let (lf, rf) = sf.split(&uf).unwrap();
        let (lq, rq) = sq.split(uq).unwrap();
        close_all(lf.control(), lq.control(), bound);
        close_all(rf.control(), rq.control(), bound);
        // Insert, then remove within a tolerance well above the rounding.
        if let Ok(inserted) = sf.insert(&uf, 1) {
            let back = inserted.remove_within(&uf, 1, &1e-9).unwrap();
            close_all(back.control(), sq.control(), 1e-9);
        }
    }
}

/// Every `f64` point finite and within `bound` of the exact one, coordinate by coordinate.
fn close_all(got: &[Point<f64, 2>], want: &[Point<Q, 2>], bound: f64) {
    assert_eq!(got.len(), want.len());
    for (a, b) in got.iter().zip(want) {
        let b = b.to_f64();
        for j in 0..2 {
            assert!(a[j].is_finite(), "{a:?}");
            assert!((a[j] - b[j]).abs() <= bound, "{a:?} vs {b:?}");
        }
    }
}

/// `close_all` relative to the largest coordinate of `want`.
fn close_relative(got: &[Point<f64, 2>], want: &[Point<Q, 2>], rel: f64) {
    let m = want
        .iter()
        .flat_map(|p| p.to_f64().0)
        .fold(0.0f64, |m, x| m.max(x.abs()));
    close_all(got, want, rel * m);
}

fn up(x: f64, k: u64) -> f64 {
    f64::from_bits(x.to_bits() + k)
}

/// A cubic with a triple knot at 1 and 9 control points.
fn triple_knot_cubic(scale: f64) -> BSpline<f64, 2> {
    let knots = vec![
        0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0,
    ];
    let t = KnotVector::new(3, knots).unwrap();
    let c = (0..t.control_points())
        .map(|i| {
            let (x, y) = (((i * 3) % 7) as f64, i as f64 - 4.0);
            Point::new([x * scale, y * scale])
        })
        .collect();
    BSpline::new(c, t).unwrap()
}

#[test]
fn splitting_a_few_ulps_from_a_triple_knot_keeps_the_tiny_piece() {
    let s = triple_knot_cubic(1.0);
    let e = exact(&s);
    for u in [
        up(1.0, 1),
        up(1.0, 3),
        f64::from_bits(1.0f64.to_bits() - 2),
        1.0,
    ] {
        let (l, r) = s.split(&u).unwrap();
        let uq = Q::from_f64(u).unwrap();
        let (lq, rq) = e.split(&uq).unwrap();
        assert_eq!(l.knots(), &lq.knots().clone().map_f64());
        assert_eq!(r.knots(), &rq.knots().clone().map_f64());
        close_relative(l.control(), lq.control(), 1e-14);
        close_relative(r.control(), rq.control(), 1e-14);
        assert_eq!(*l.knots().bounds().1, u);
        assert_eq!(*r.knots().bounds().0, u);
        // The pieces meet at s(u); the tiny piece between 1 and u is kept.
        let su = s.eval(&u).unwrap();
        for p in [l.eval(&u).unwrap(), r.eval(&u).unwrap()] {
            assert!((p[0] - su[0]).abs() <= 1e-13 && (p[1] - su[1]).abs() <= 1e-13);
        }
        if u != 1.0 {
            assert_eq!(s.knots().multiplicity(&1.0), 3);
            let piece = if u > 1.0 { &l } else { &r };
            assert_eq!(piece.knots().multiplicity(&1.0), 3, "u = {u:e}");
        }
    }
}

/// The knot vector with each knot converted to `f64` (exact for knots that came from `f64`).
trait MapF64 {
    fn map_f64(self) -> KnotVector<f64>;
}

impl MapF64 for KnotVector<Q> {
    fn map_f64(self) -> KnotVector<f64> {
        KnotVector::new(self.degree(), self.knots().iter().map(Q::to_f64).collect()).unwrap()
    }
}

#[test]
fn ulp_close_knots_refine_and_remove_exactly_and_in_f64() {
    let s = triple_knot_cubic(1.0);
    let e = exact(&s);
    let new = [
        up(1.0, 1),
        up(1.0, 1),
        f64::from_bits(1.0f64.to_bits() - 1),
        0.75,
        up(1.0, 2),
    ];
    let r = s.refine(&new).unwrap();
    let newq: Vec<Q> = new.iter().map(|x| Q::from_f64(*x).unwrap()).collect();
    let rq = e.refine(&newq).unwrap();
    assert_eq!(r.knots(), &rq.knots().clone().map_f64());
    assert_eq!(r.knots().multiplicity(&up(1.0, 1)), 2);
    close_relative(r.control(), rq.control(), 1e-12);
    // Exactly: the refinement removes again, knot by knot, to the identical curve.
    let mut back = rq.clone();
    for x in &newq {
        back = back.remove(x, 1).unwrap();
    }
    assert_eq!(back, e);
    // In f64, a removal within a small tolerance of the coordinates' size.
    let mut back = r.clone();
    for x in &new {
        back = back.remove_within(x, 1, &1e-9).unwrap();
    }
    close_relative(back.control(), e.control(), 1e-9);
    // The triple knot itself cannot lose a copy: the curve is only C⁰ there.
    let err = e.remove(&Q::from_f64(1.0).unwrap(), 1).unwrap_err();
    assert!(
        err.to_string().contains("the curve is C^0 there, not C^1"),
        "{err}"
    );
}

#[test]
fn huge_and_subnormal_coordinates_refine_split_and_remove() {
    for scale in [1e300, f64::from_bits(1) * 16.0] {
        let s = triple_knot_cubic(scale);
        let e = exact(&s);
        let new = [0.25, 0.5, 1.25, 1.75, 1.75];
        let r = s.refine(&new).unwrap();
        let newq: Vec<Q> = new.iter().map(|x| Q::from_f64(*x).unwrap()).collect();
        let rq = e.refine(&newq).unwrap();
        // Subnormal coordinates carry few bits: compare within a few units of the scale.
        let rel = if scale > 1.0 { 1e-13 } else { 0.5 };
        close_relative(r.control(), rq.control(), rel);
        let (l, rr) = s.split(&0.3).unwrap();
        let (lq, rrq) = e.split(&Q::from_f64(0.3).unwrap()).unwrap();
        close_relative(l.control(), lq.control(), rel);
        close_relative(rr.control(), rrq.control(), rel);
        let inserted = s.insert(&1.25, 1).unwrap();
        let back = inserted.remove_within(&1.25, 1, &(scale * 1e-9)).unwrap();
        close_relative(
            back.control(),
            e.control(),
            if scale > 1.0 { 1e-12 } else { 0.5 },
        );
    }
    // Coordinates near the top of the range: the refinement is finite or an Overflow error.
    let s = triple_knot_cubic(f64::MAX / 8.0);
    match s.refine(&[0.25, 1.5]) {
        Ok(r) => assert!(r.control().iter().all(Point::is_finite)),
        Err(e) => assert!(matches!(e, Error::Overflow { .. }), "{e}"),
    }
}

#[test]
fn f64_removal_succeeds_when_the_arithmetic_reproduces_exactly() {
    // Dyadic knots and integer points: inserting and removing 0.5 is exact in f64.
    let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]).unwrap();
    let s: BSpline<f64, 2> =
        BSpline::new([(0, 0), (2, 4), (4, 4), (6, 0)].map(point).to_vec(), t).unwrap();
    let r = s.insert(&0.5, 1).unwrap();
    assert_eq!(r.remove(&0.5, 1).unwrap(), s);
    let r = s.refine(&[0.5, 1.5, 1.5]).unwrap();
    assert_eq!(r.remove(&1.5, 2).unwrap().remove(&0.5, 1).unwrap(), s);
    // The counts of one removal at a simple knot of a quadratic: 1 solved point, 2 to check.
    let mut c = Counts::default();
    s.insert(&0.5, 1)
        .unwrap()
        .remove_with(&0.5, 1, &mut c)
        .unwrap();
    assert_eq!(c.arithmetic_operations, 3);
}

#[test]
fn unclamped_vectors_split_and_refine_like_insertion() {
    let t = KnotVector::new(2, (0..=8).map(qi).collect()).unwrap();
    let s: BSpline<Q, 2> = BSpline::new(
        [(0, 0), (1, 3), (4, 4), (6, 1), (8, 5), (9, 0)]
            .map(point)
            .to_vec(),
        t,
    )
    .unwrap();
    // The domain [2, 6]; the ends of the domain are knots too and may be refined.
    let us = [qi(2), qi(6), q(5, 2), qi(4), q(5, 2)];
    let r = s.refine(&us).unwrap();
    let mut one = s.clone();
    for u in &us {
        one = one.insert(u, 1).unwrap();
    }
    assert_eq!(r, one);
    let (l, rr) = s.split(&q(7, 2)).unwrap();
    // The outer ends stay unclamped: the left piece starts with the original 0, 1, 2.
    assert_eq!(&l.knots().knots()[..3], [qi(0), qi(1), qi(2)]);
    assert_eq!(
        &rr.knots().knots()[rr.knots().knots().len() - 3..],
        [qi(6), qi(7), qi(8)]
    );
    assert!(!l.knots().is_clamped() && !rr.knots().is_clamped());
    for k in 0..=8 {
        let v = qi(2) + q(3 * k, 16);
        assert_eq!(l.eval(&v).unwrap(), s.eval(&v).unwrap());
        let w = q(7, 2) + q(5 * k, 16);
        assert_eq!(rr.eval(&w).unwrap(), s.eval(&w).unwrap());
    }
    // Removing an end of an unclamped domain would change the domain: refused.
    let e = s.remove(&qi(2), 1).unwrap_err();
    assert!(e.to_string().contains("would change the domain"), "{e}");
}

#[test]
fn bad_input_is_a_named_error() {
    let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0]).unwrap();
    let s: BSpline<f64, 2> = BSpline::new(
        [(0, 0), (1, 1), (2, 0), (3, 1), (4, 0), (5, 1)]
            .map(point)
            .to_vec(),
        t,
    )
    .unwrap();
    let name = |e: &Error| match e {
        Error::InvalidParameter { name, .. } => *name,
        other => panic!("{other}"),
    };
    // Refinement: non-finite and outside values by index, multiplicities by knot.
    let e = s.refine(&[0.5, f64::INFINITY]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid new_knots: new knot 1 is not finite (inf)"
    );
    let e = s.refine(&[f64::NAN]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid new_knots: new knot 0 is not finite (NaN)"
    );
    let e = s.refine(&[0.5, 3.5]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid new_knots: new knot 1 (3.5) is outside the domain [0, 3]"
    );
    let e = s.refine(&[2.0, 0.5]).unwrap_err(); // 2 has multiplicity 2 = d already
    assert_eq!(
        e.to_string(),
        "invalid new_knots: knot 2 would have multiplicity 3 (2 old, 1 new), more than the \
         degree 2 (the curve would break there)"
    );
    assert_eq!(name(&s.refine(&[0.0]).unwrap_err()), "new_knots");
    assert_eq!(name(&s.refine(&[1.5, 1.5, 1.5]).unwrap_err()), "new_knots");
    // Removal: not a knot, the clamped ends, too many times, not removable, bad tolerance.
    for u in [f64::NAN, f64::NEG_INFINITY] {
        assert_eq!(name(&s.remove(&u, 1).unwrap_err()), "u");
    }
    let e = s.remove(&0.5, 1).unwrap_err();
    assert_eq!(e.to_string(), "invalid u: 0.5 is not a knot");
    let e = s.remove(&up(1.0, 1), 1).unwrap_err();
    assert!(e.to_string().contains("is not a knot"), "{e}");
    for end in [0.0, 3.0] {
        let e = s.remove(&end, 1).unwrap_err();
        assert!(e.to_string().contains("end of the clamped domain"), "{e}");
        assert_eq!(name(&e), "u");
    }
    let e = s.remove(&2.0, 3).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid times: cannot remove the knot 2 3 times: its multiplicity is 2"
    );
    let e = s.remove(&1.0, 1).unwrap_err();
    assert_eq!(name(&e), "times");
    assert!(
        e.to_string()
            .contains("knot 1 (multiplicity 1): 0 of 1 removals succeeded"),
        "{e}"
    );
    for tol in [-1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(
            name(&s.remove_within(&1.0, 1, &tol).unwrap_err()),
            "tolerance"
        );
    }
    assert_eq!(s.remove(&1.0, 0).unwrap(), s);
    // Splitting: outside the open domain.
    for u in [f64::NAN, 0.0, 3.0, -1.0, 4.0] {
        assert_eq!(name(&s.split(&u).unwrap_err()), "u");
    }
    let e = s.split(&3.0).unwrap_err();
    assert!(e.to_string().contains("inside the domain (0, 3)"), "{e}");
}
