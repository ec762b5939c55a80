//! The three public evaluations of a Bézier curve (`eval`, `at`, `eval_each`) against the
//! plain algorithms, over coordinates of every magnitude and parameters far outside [0, 1]:
//! whichever path an evaluation takes (the closed forms within the curve's overflow bound, the
//! checked path beyond it), the point is Horner's when that is finite and de Casteljau's when
//! Horner's scheme overflows, as `horner` itself gives it.

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

/// Horner's point if it is finite, else de Casteljau's: what `eval` promises, and what
/// `horner` returns (it falls back the same way).
fn expected<const D: usize>(b: &Bezier<f64, D>, t: f64) -> Point<f64, D> {
    let h = b.horner(&t).unwrap();
    if h.is_finite() {
        h
    } else {
        let dc = b.de_casteljau(&t).unwrap();
        assert!(
            same(&h, &dc),
            "horner at t = {t}: {h:?}, not de Casteljau's {dc:?}"
        );
        dc
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

/// The exact value of the `f64` curve `b` at the `f64` parameter `t`, rounded to nearest.
fn exact_value<const D: usize>(b: &Bezier<f64, D>, t: f64) -> Point<f64, D> {
    use compgeo::spline::Scalar;
    use num_rational::BigRational;
    let q = Bezier::<BigRational, D>::from_f64(b);
    let t = BigRational::from_float(t).unwrap();
    let p = q.eval(&t).unwrap();
    Point::new(std::array::from_fn(|i| p[i].to_f64()))
}

/// Every evaluation of `b` at `t`, named: `eval`, `at`, `eval_each`, `horner`.
fn every_evaluation<const D: usize>(
    b: &Bezier<f64, D>,
    t: f64,
) -> [(&'static str, Point<f64, D>); 4] {
    let mut batch = Vec::new();
    b.eval_each(&[t], |p| batch.push(p)).unwrap();
    [
        ("eval", b.eval(&t).unwrap()),
        ("at", b.at(&Finite::new(t, "t").unwrap())),
        ("eval_each", batch[0]),
        ("horner", b.horner(&t).unwrap()),
    ]
}

/// The fuzz finding `bezier/horner-power-underflow`: the cubic's closed form multiplied 3b₂
/// by t², which is 0 at t = 1.76e-243, although 3b₂t²(1 − t) is a normal number: x was 0.
/// De Casteljau's x is the exact value rounded; Horner's scheme is within a few roundings
/// of it (one unit in the last place here, from the stored 3b₂, itself rounded).
#[test]
fn a_cubic_keeps_its_term_where_t_squared_underflows() {
    let b = Bezier::new(vec![
        Point::new([0.0, 0.0]),
        Point::new([0.0, 0.0]),
        Point::new([1.129605583483287e221, -100.0]),
        Point::new([0.0, 60.0]),
    ])
    .unwrap();
    let t = 1.7575886160127266e-243;
    let dc = b.de_casteljau(&t).unwrap();
    assert_eq!(dc[0], 1.0468453952056338e-264);
    assert_eq!(exact_value(&b, t), dc);
    for (name, p) in every_evaluation(&b, t) {
        // y is −300t² + 360t³ ≈ −9e-484: 0 in f64 by every scheme.
        assert_eq!(p[1], 0.0, "{name}");
        assert!(
            (p[0] - dc[0]).abs() <= 4.0 * f64::EPSILON * dc[0],
            "{name}: x = {:e}, exact {:e}",
            p[0],
            dc[0]
        );
    }
}

/// Every degree: one control point bₖ = 1e250 (the others 0) at t = ±1e-150, where tᵏ alone
/// underflows from k = 3 on but C(n, k) tᵏ (1 − t)ⁿ⁻ᵏ bₖ is normal for k ≤ 3; within a few
/// roundings of the exact value, by every evaluation (degree 4 and more: both nestings of
/// the loop, as t < 0 takes the mirrored one).
#[test]
fn no_power_of_a_tiny_t_underflows_on_its_own() {
    for n in 2..=7 {
        for k in 2..=n.min(3) {
            let mut control = vec![Point::new([0.0, 1.0]); n + 1];
            control[k] = Point::new([1e250, 1.0]);
            let b = Bezier::new(control).unwrap();
            for t in [1e-150, -1e-150] {
                let want = exact_value(&b, t);
                assert!(want[0] != 0.0 && want[0].is_normal(), "n = {n}, k = {k}");
                for (name, p) in every_evaluation(&b, t) {
                    for i in 0..2 {
                        let err = (p[i] - want[i]).abs();
                        assert!(
                            err <= 16.0 * f64::EPSILON * want[i].abs(),
                            "{name}, n = {n}, k = {k}, t = {t:e}: {:e}, exact {:e}",
                            p[i],
                            want[i]
                        );
                    }
                }
            }
        }
    }
}

/// The loop of degree 4 and more nests in u = 1 − t where |t| > |u| and in t elsewhere: both
/// agree with the exact value within the bound of a sum of products (a few roundings times
/// the sum of the terms' magnitudes), inside and outside [0, 1], and count n + 1 operations.
#[test]
fn both_nestings_of_the_loop_are_right_and_count_n_plus_1() {
    use compgeo::count::Counts;
    for n in 4..=9 {
        let control: Vec<Point<f64, 2>> = (0..=n)
            .map(|i| {
                let i = i as f64;
                Point::new([(i * 1.7).sin() * 10.0, i * i - 3.0])
            })
            .collect();
        let b = Bezier::new(control.clone()).unwrap();
        for t in [-3.0, -0.25, 0.0, 0.2, 0.5, 0.75, 1.0, 1.5, 7.0] {
            let want = exact_value(&b, t);
            let mut c = Counts::default();
            let got = b.horner_with(&t, &mut c).unwrap();
            assert_eq!(c.arithmetic_operations, n as u64 + 1, "n = {n}, t = {t}");
            let (at, au) = (f64::abs(t), f64::abs(1.0 - t));
            for i in 0..2 {
                // Σ C(n, j) |t|ʲ |1 − t|ⁿ⁻ʲ |bⱼ|.
                let s: f64 = control
                    .iter()
                    .enumerate()
                    .map(|(j, p)| {
                        compgeo::spline::binomial::<f64>(n, j)
                            * at.powi(j as i32)
                            * au.powi((n - j) as i32)
                            * p[i].abs()
                    })
                    .sum();
                let err = (got[i] - want[i]).abs();
                assert!(
                    err <= 4.0 * (3 * n + 3) as f64 * f64::EPSILON * s,
                    "n = {n}, t = {t}: {:e}, exact {:e}",
                    got[i],
                    want[i]
                );
            }
        }
    }
}

/// The fuzz finding `bezier/horner-power-overflow`: the zero quadratic at t = 1.55e231,
/// where t² overflows. `horner` was NaN (∞ · 0); multiplied by t step by step, the zero
/// curve of every degree is 0 far outside [0, 1].
#[test]
fn the_zero_curve_is_zero_where_powers_of_t_overflow() {
    for n in 1..=7 {
        let b = Bezier::new(vec![Point::new([0.0, 0.0]); n + 1]).unwrap();
        for t in [1.552518092300709e231, -1e300, 1e200] {
            for (name, p) in every_evaluation(&b, t) {
                assert_eq!(p, Point::new([0.0, 0.0]), "{name}, n = {n}, t = {t:e}");
            }
        }
    }
}

/// The fuzz finding `bezier/horner-scaled-overflow`: a cubic whose stored 3b₁ overflows.
/// At t = 1 Horner's scheme forms ∞ · 0; `horner` now falls back to de Casteljau's
/// algorithm as `eval` does, giving b₃ exactly, and counts its 3·4/2 combinations as well.
#[test]
fn horner_falls_back_where_a_scaled_point_overflows() {
    use compgeo::count::Counts;
    let b = Bezier::new(vec![
        Point::new([0.0, -2.0]),
        Point::new([1e308, 1.0]),
        Point::new([-1e308, 0.5]),
        Point::new([5.0, 3.0]),
    ])
    .unwrap();
    for (name, p) in every_evaluation(&b, 1.0) {
        assert_eq!(p, Point::new([5.0, 3.0]), "{name}");
    }
    for (name, p) in every_evaluation(&b, 0.0) {
        assert_eq!(p, Point::new([0.0, -2.0]), "{name}");
    }
    let mut c = Counts::default();
    let p = b.horner_with(&0.25, &mut c).unwrap();
    assert_eq!(p, b.de_casteljau(&0.25).unwrap());
    assert_eq!(c.arithmetic_operations, 4 + 6);
    let want = exact_value(&b, 0.25);
    for i in 0..2 {
        assert!(
            (p[i] - want[i]).abs() <= 1e-15 * 1e308,
            "{:e} vs {:e}",
            p[i],
            want[i]
        );
    }
}
