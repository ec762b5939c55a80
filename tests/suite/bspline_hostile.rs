//! Hostile input for B-splines and NURBS in `f64` (issue 14): knots a few ulps apart, knot
//! spacing below the normal range, coordinates at 1e300, near `f64::MAX` and subnormal. Every
//! operation is compared with the exact `BigRational` back end on the same values: within a
//! stated bound, or a named error where the value is beyond the double range. The fuzz target
//! `bspline` (`compgeo::fuzzing::bspline`) runs the same comparisons on arbitrary bytes.

use crate::spline_common::bspline::exact;
use crate::spline_common::Q;
use compgeo::spline::{BSpline, Curve, KnotVector, Nurbs, Point};
use compgeo::Error;
use num_traits::{Signed, ToPrimitive, Zero};

const MAX: f64 = f64::MAX;
const TINY: f64 = 5e-324;

fn q(x: f64) -> Q {
    Q::from_float(x).unwrap()
}

fn curve(degree: usize, knots: &[f64], control: &[[f64; 2]]) -> BSpline<f64, 2> {
    let t = KnotVector::new(degree, knots.to_vec()).unwrap();
    BSpline::new(control.iter().map(|&c| Point::new(c)).collect(), t).unwrap()
}

/// |got − want| ≤ tol, compared exactly.
fn assert_close(what: &str, got: f64, want: &Q, tol: f64) {
    assert!(got.is_finite(), "{what}: {got}");
    let err = (q(got) - want).abs();
    assert!(
        err <= q(tol),
        "{what}: {got:e} is {:e} from the exact {:e} (tolerance {tol:e})",
        err.to_f64().unwrap(),
        want.to_f64().unwrap()
    );
}

fn assert_points_close(what: &str, got: &[Point<f64, 2>], want: &[Point<Q, 2>], tol: f64) {
    assert_eq!(got.len(), want.len(), "{what}");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        for j in 0..2 {
            assert_close(&format!("{what} point {i}.{j}"), g[j], &w[j], tol);
        }
    }
}

fn same_knots(got: &KnotVector<f64>, want: &KnotVector<Q>) {
    let g: Vec<Q> = got.knots().iter().map(|&t| q(t)).collect();
    assert_eq!(g, want.knots());
}

/// The convex operations' bound: a few dozen roundings of the largest coordinate, plus a
/// few subnormal units.
fn convex_tol(largest: f64) -> f64 {
    64.0 * f64::EPSILON * largest + 64.0 * TINY
}

/// A quadratic whose knots 1 and 1 + 2ε (one and two ulps from 1) bound spans of width ε.
fn ulps_apart() -> BSpline<f64, 2> {
    let one = 1.0f64;
    let knots = [
        0.0,
        0.0,
        0.0,
        one,
        one.next_up(),
        one.next_up().next_up(),
        3.0,
        3.0,
        3.0,
    ];
    let c = [
        [0.0, 7.0],
        [3.0, -1.0],
        [-2.0, 5.0],
        [4.0, 4.0],
        [1.0, -6.0],
        [9.0, 2.0],
    ];
    curve(2, &knots, &c)
}

/// A cubic with a span of subnormal width next to 1e300 coordinates.
fn subnormal_spacing() -> BSpline<f64, 2> {
    let knots = [0.0, 0.0, 0.0, 0.0, 5e-324, 1e-323, 1.0, 1.0, 1.0, 1.0];
    let c = [
        [1e300, -1e300],
        [3e-310, 0.0],
        [-7e299, 2.0],
        [0.0, 0.0],
        [1e300, 1.0],
        [5e-324, -3.0],
    ];
    curve(3, &knots, &c)
}

/// A quadratic with every coordinate near f64::MAX, on non-dyadic knots (so the weights
/// round).
fn near_max() -> BSpline<f64, 2> {
    let knots = [0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0];
    let c = [
        [MAX, -MAX],
        [MAX, -MAX],
        [MAX.next_down(), -MAX],
        [MAX, -MAX.next_down()],
        [MAX, -MAX],
    ];
    curve(2, &knots, &c)
}

fn hostile() -> Vec<(&'static str, BSpline<f64, 2>)> {
    vec![
        ("ulps apart", ulps_apart()),
        ("subnormal spacing", subnormal_spacing()),
        ("near MAX", near_max()),
    ]
}

fn largest(s: &BSpline<f64, 2>) -> f64 {
    s.control()
        .iter()
        .flat_map(|p| [p[0].abs(), p[1].abs()])
        .fold(0.0, f64::max)
}

/// Parameters at every knot of the domain, one ulp on either side, and between.
fn parameters(s: &BSpline<f64, 2>) -> Vec<f64> {
    let (a, b) = (*s.knots().bounds().0, *s.knots().bounds().1);
    let mut u = vec![a, b, a.next_up(), b.next_down(), (a + b) / 3.0];
    for &t in s.knots().knots() {
        if t > a && t < b {
            u.extend([t, t.next_down(), t.next_up()]);
        }
    }
    u.sort_by(f64::total_cmp);
    u.dedup();
    u
}

#[test]
fn de_boor_and_batch_evaluation_are_within_the_convex_bound() {
    for (name, s) in hostile() {
        let e = exact(&s);
        let u = parameters(&s);
        let batch = s.eval_sorted(&u).unwrap();
        for (x, p) in u.iter().zip(&batch) {
            let got = s.de_boor(x).unwrap();
            assert_eq!(*p, got, "{name}: batch and de Boor at {x:e}");
            let want = e.de_boor(&q(*x)).unwrap();
            assert_points_close(
                &format!("{name}: de_boor({x:e})"),
                &[got],
                &[want],
                convex_tol(largest(&s)),
            );
        }
        assert!(matches!(
            s.de_boor(&f64::NAN),
            Err(Error::InvalidParameter { .. })
        ));
    }
}

#[test]
fn a_convex_combination_near_max_does_not_round_to_infinity() {
    // All coordinates MAX: the exact curve is MAX everywhere, and so is the f64 one.
    let knots = [0.0, 0.0, 0.0, 0.3, 0.7, 1.0, 1.0, 1.0];
    let s = curve(2, &knots, &[[MAX, -MAX]; 5]);
    let want = [q(MAX), q(-MAX)];
    let near = |p: &Point<f64, 2>, what: &str| {
        for j in 0..2 {
            assert_close(what, p[j], &want[j], convex_tol(MAX));
        }
    };
    for k in 1..100 {
        let u = f64::from(k) / 100.0;
        near(&s.de_boor(&u).unwrap(), &format!("de_boor({u})"));
        near(&s.eval(&u).unwrap(), &format!("eval({u})"));
    }
    for r in [
        s.insert(&0.1, 2).unwrap(),
        s.refine(&[0.1, 0.2, 0.9]).unwrap(),
        s.oslo(&[0.1, 0.2, 0.9]).unwrap(),
    ] {
        for p in r.control() {
            near(p, "a new control point");
        }
    }
}

#[test]
fn insertion_refinement_and_splitting_are_within_the_convex_bound() {
    for (name, s) in hostile() {
        let e = exact(&s);
        let tol = convex_tol(largest(&s));
        for x in parameters(&s) {
            match (s.insert(&x, 2), e.insert(&q(x), 2)) {
                (Ok(g), Ok(w)) => {
                    same_knots(g.knots(), w.knots());
                    assert_points_close(
                        &format!("{name}: insert({x:e})"),
                        g.control(),
                        w.control(),
                        tol,
                    );
                    // Insert then evaluate: the same curve.
                    let back = g.de_boor(&x).unwrap();
                    assert_points_close(
                        &format!("{name}: inserted at {x:e}"),
                        &[back],
                        &[e.de_boor(&q(x)).unwrap()],
                        tol,
                    );
                }
                (Err(Error::InvalidParameter { .. }), Err(Error::InvalidParameter { .. })) => {}
                (g, w) => panic!("{name}: insert({x:e}): {g:?} against {w:?}"),
            }
            match (s.split(&x), e.split(&q(x))) {
                (Ok((gl, gr)), Ok((wl, wr))) => {
                    assert_points_close(
                        &format!("{name}: split({x:e}) left"),
                        gl.control(),
                        wl.control(),
                        tol,
                    );
                    assert_points_close(
                        &format!("{name}: split({x:e}) right"),
                        gr.control(),
                        wr.control(),
                        tol,
                    );
                }
                (Err(Error::InvalidParameter { .. }), Err(Error::InvalidParameter { .. })) => {}
                (g, w) => panic!("{name}: split({x:e}): {g:?} against {w:?}"),
            }
        }
        let new: Vec<f64> = parameters(&s)
            .into_iter()
            .filter(|u| s.knots().multiplicity(u) == 0)
            .take(4)
            .collect();
        let want = e
            .refine(&new.iter().map(|&u| q(u)).collect::<Vec<_>>())
            .unwrap();
        let got = s.refine(&new).unwrap();
        same_knots(got.knots(), want.knots());
        assert_points_close(
            &format!("{name}: refine"),
            got.control(),
            want.control(),
            tol,
        );
        let bz = s.to_bezier().unwrap();
        let wz = e.to_bezier().unwrap();
        for (i, (g, w)) in bz.pieces().iter().zip(wz.pieces()).enumerate() {
            assert_points_close(
                &format!("{name}: Bézier piece {i}"),
                g.control(),
                w.control(),
                tol,
            );
        }
    }
}

#[test]
fn blossoms_of_a_constant_stay_constant_beyond_a_subnormal_span() {
    // The span [5e-324, 1e-323) is one subnormal unit wide: arguments at 0.5 and 1 make the
    // weights ±1e323, beyond the range. The blossom of a constant is that constant for any
    // arguments; the zero coordinate once gave ∞·0 = NaN, reported as an overflow.
    let knots = [0.0, 0.0, 0.0, 5e-324, 1e-323, 1.0, 1.0, 1.0];
    let s = curve(2, &knots, &[[3.0, 0.0]; 5]);
    let e = exact(&s);
    for args in [[0.5, 1.0], [1.0, 1.0], [0.0, 0.5], [-1e3, 1e3]] {
        let got = s.blossom_in_span(3, &args).unwrap();
        let want = e.blossom_in_span(3, &args.map(q)).unwrap();
        assert_eq!(got, Point::new([3.0, 0.0]), "{args:?}");
        assert_eq!(want, Point::new([q(3.0), Q::zero()]));
    }
}

#[test]
fn elevation_next_to_subnormal_knots_is_exact_where_the_exact_result_is_small() {
    // Degree elevation takes each new point as a blossom of a piece; a piece of subnormal
    // width extrapolated to the far knots overflowed the weights (∞·0 = NaN).
    let knots = [0.0, 0.0, 0.0, 5e-324, 1.0, 1.0, 1.0];
    let s = curve(2, &knots, &[[1.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 0.0]]);
    let e = s.elevate(1).unwrap();
    let w = exact(&s).elevate(1).unwrap();
    same_knots(e.knots(), w.knots());
    assert!(
        e.control().iter().all(|p| *p == Point::new([1.0, 0.0])),
        "{e:?}"
    );
    // A non-constant curve: each point within the growth of its blossom (here the
    // extrapolation factor is at most 2^1074·2, so only overflow or closeness is asserted
    // where the exact value is far inside the range).
    let s = curve(2, &knots, &[[0.0, 1.0], [1.0, 1.0], [2.0, 1.0], [3.0, 1.0]]);
    let w = exact(&s).elevate(1).unwrap();
    match s.elevate(1) {
        Ok(e) => {
            same_knots(e.knots(), w.knots());
            for (g, x) in e.control().iter().zip(w.control()) {
                assert_eq!(g[1], 1.0);
                assert_close("elevated x", g[0], &x[0], 1e-12);
            }
        }
        Err(err) => panic!("elevation of a small curve: {err}"),
    }
}

#[test]
fn elevation_blossoms_and_integrals_of_hostile_curves_are_close_or_overflow() {
    for (name, s) in hostile() {
        let e = exact(&s);
        match (s.integral(), e.integral()) {
            (Ok(g), Ok(w)) => {
                same_knots(g.knots(), w.knots());
                assert_points_close(
                    &format!("{name}: integral"),
                    g.control(),
                    w.control(),
                    convex_tol(largest(&s)) * 8.0,
                );
            }
            (Err(Error::Overflow { .. }), Ok(_)) => assert!(largest(&s) > 1e307, "{name}"),
            (g, w) => panic!("{name}: integral {g:?} against {w:?}"),
        }
        match (s.elevate(1), e.elevate(1)) {
            (Ok(g), Ok(w)) => {
                same_knots(g.knots(), w.knots());
                assert!(g.control().iter().all(Point::is_finite));
            }
            (Err(Error::Overflow { .. }), Ok(w)) => {
                // Only where an exact point is beyond the range or a blossom extrapolates.
                let big = w
                    .control()
                    .iter()
                    .any(|p| p[0].abs() > q(1e300) || p[1].abs() > q(1e300));
                assert!(
                    big || name == "subnormal spacing",
                    "{name}: elevation overflows"
                );
            }
            (g, w) => panic!("{name}: elevate {g:?} against {w:?}"),
        }
    }
}

#[test]
fn derivatives_are_close_or_a_named_overflow() {
    // Order r divides by r knot widths: near ulp-wide spans f64 keeps no digit of it, and
    // the values beyond the range are an Error::Overflow, never a non-finite Ok.
    for (name, s) in hostile() {
        let e = exact(&s);
        for x in parameters(&s) {
            match s.derivatives(&x, 3) {
                Ok(d) => {
                    assert!(d.iter().all(Point::is_finite), "{name}: {d:?}");
                    let want = e.de_boor(&q(x)).unwrap();
                    assert_points_close(
                        &format!("{name}: derivative 0 at {x:e}"),
                        &d[..1],
                        &[want],
                        convex_tol(largest(&s)),
                    );
                }
                Err(Error::Overflow { .. }) => {}
                Err(err) => panic!("{name}: derivatives({x:e}): {err}"),
            }
        }
    }
}

#[test]
fn nurbs_with_hostile_weights_evaluate_inside_the_hull() {
    let s = ulps_apart();
    let w = vec![1e-150, 1.0, 1e150, 3.0, 1e-100, 2.0];
    let n = Nurbs::new(s.control().to_vec(), w.clone(), s.knots().clone()).unwrap();
    let wq: Vec<Q> = w.iter().map(|&x| q(x)).collect();
    let e = exact(&s);
    let nq = Nurbs::new(e.control().to_vec(), wq, e.knots().clone()).unwrap();
    for x in parameters(&s) {
        let got = n.de_boor(&x).unwrap();
        assert!(got.is_finite());
        let want = nq.de_boor(&q(x)).unwrap();
        // Inside the control hull exactly (the weights are positive).
        for j in 0..2 {
            let lo = s.control().iter().map(|p| p[j]).fold(MAX, f64::min);
            let hi = s.control().iter().map(|p| p[j]).fold(-MAX, f64::max);
            assert!(got[j] >= lo && got[j] <= hi, "NURBS at {x:e}: {got:?}");
            assert!(want[j] >= q(lo) && want[j] <= q(hi));
        }
        // The insertion keeps the curve.
        let r = n.insert(&x, 1);
        if let Ok(r) = r {
            assert!(r.weights().iter().all(|w| w.is_finite() && *w > 0.0));
            assert!(r.control().iter().all(Point::is_finite));
        }
    }
    let bad = Nurbs::new(
        s.control().to_vec(),
        vec![1.0, 0.0, 1.0, 1.0, 1.0, 1.0],
        s.knots().clone(),
    );
    assert!(matches!(
        bad,
        Err(Error::InvalidParameter {
            name: "weights",
            ..
        })
    ));
    match n.elevate(1) {
        Ok(e) => assert!(e.weights().iter().all(|w| w.is_finite() && *w > 0.0)),
        Err(Error::Overflow { .. }) => {}
        Err(err) => panic!("NURBS elevation: {err}"),
    }
}
