//! The three public evaluations of a Bézier curve (`eval`, `at`, `eval_each`) against the
//! plain algorithms, over coordinates of every magnitude and parameters far outside [0, 1]:
//! whichever path an evaluation takes (the closed forms within the curve's overflow bound, the
//! checked path beyond it), the point is Horner's when that is finite and de Casteljau's when
//! Horner's scheme overflows.

use compgeo::spline::{Bezier, Curve, Finite, Point};
use compgeo::Error;
use proptest::prelude::*;

/// A coordinate of any magnitude: a mantissa in [−1, 1] times 10^e, e in [−300, 308].
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => -1e3f64..1e3,
        1 => (-1.0f64..1.0, -300i32..=308).prop_map(|(m, e)| m * 10f64.powi(e)),
    ]
}

/// A parameter: mostly near [0, 1], sometimes huge.
fn parameter() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => -2.0f64..3.0,
        1 => (-1.0f64..1.0, 0i32..=200).prop_map(|(m, e)| m * 10f64.powi(e)),
    ]
}

fn curve<const D: usize>(max_degree: usize) -> impl Strategy<Value = Bezier<f64, D>> {
    prop::collection::vec(
        prop::array::uniform::<_, D>(coordinate()),
        1..=max_degree + 1,
    )
    .prop_map(|pts| Bezier::new(pts.into_iter().map(Point::new).collect()).unwrap())
}

/// Horner's point if it is finite, else de Casteljau's: what `eval` promises.
fn expected<const D: usize>(b: &Bezier<f64, D>, t: f64) -> Point<f64, D> {
    let h = b.horner(&t).unwrap();
    if h.is_finite() {
        h
    } else {
        b.de_casteljau(&t).unwrap()
    }
}

/// Equal coordinates, NaN equal to NaN (a value beyond the range may come out ∞ − ∞).
fn same<const D: usize>(p: &Point<f64, D>, q: &Point<f64, D>) -> bool {
    (0..D).all(|i| p[i] == q[i] || (p[i].is_nan() && q[i].is_nan()))
}

fn check_all_paths<const D: usize>(b: &Bezier<f64, D>, ts: &[f64]) -> Result<(), TestCaseError> {
    let mut batch = Vec::new();
    b.eval_each(ts, |p| batch.push(p)).unwrap();
    prop_assert_eq!(batch.len(), ts.len());
    for (&t, p) in ts.iter().zip(&batch) {
        let want = expected(b, t);
        let e = b.eval(&t).unwrap();
        let a = b.at(&Finite::new(t, "t").unwrap());
        prop_assert!(same(&e, &want), "eval at t = {}: {:?} vs {:?}", t, e, want);
        prop_assert!(same(&a, &want), "at at t = {}: {:?} vs {:?}", t, a, want);
        prop_assert!(
            same(p, &want),
            "eval_each at t = {}: {:?} vs {:?}",
            t,
            p,
            want
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(192))]

    #[test]
    fn every_evaluation_is_horner_or_its_de_casteljau_fallback_in_the_plane(
        b in curve::<2>(6), ts in prop::collection::vec(parameter(), 0..10),
    ) {
        check_all_paths(&b, &ts)?;
    }

    #[test]
    fn every_evaluation_is_horner_or_its_de_casteljau_fallback_in_space(
        b in curve::<3>(4), ts in prop::collection::vec(parameter(), 0..10),
    ) {
        check_all_paths(&b, &ts)?;
    }

    #[test]
    fn a_bad_parameter_stops_the_batch_where_it_stands(
        b in curve::<2>(5),
        mut ts in prop::collection::vec(parameter(), 1..12),
        at in 0usize..12,
        bad in prop::sample::select(vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY]),
    ) {
        let at = at % ts.len();
        ts[at] = bad;
        let mut seen = Vec::new();
        match b.eval_each(&ts, |p| seen.push(p)) {
            Err(Error::InvalidParameter { name: "t", reason }) => {
                prop_assert!(reason.contains(&format!("parameter {at} ")), "{}", reason)
            }
            other => prop_assert!(false, "expected an error, got {:?}", other),
        }
        prop_assert_eq!(seen.len(), at);
        for (p, &t) in seen.iter().zip(&ts) {
            prop_assert!(same(p, &expected(&b, t)));
        }
        prop_assert!(b.eval(&bad).is_err());
    }
}

#[test]
fn curves_near_the_top_of_the_range_take_the_checked_path() {
    // 3·1.7e308 overflows in Horner's first step: every t goes through the fallback.
    let big = Bezier::new(vec![
        Point::new([1.7e308]),
        Point::new([-1.7e308]),
        Point::new([1.7e308]),
        Point::new([-1.0]),
    ])
    .unwrap();
    let ts = [0.0, 0.3, 0.5, 1.0, 2.0];
    let mut batch = Vec::new();
    big.eval_each(&ts, |p| batch.push(p)).unwrap();
    for (&t, p) in ts.iter().zip(&batch) {
        let dc = big.de_casteljau(&t).unwrap();
        assert_eq!(*p, dc, "t = {t}");
        assert_eq!(big.eval(&t).unwrap(), dc, "t = {t}");
        assert_eq!(big.at(&Finite::new(t, "t").unwrap()), dc, "t = {t}");
    }
    assert!(big.eval(&0.5).unwrap().is_finite());
}
