//! The properties every curve type must have, written once over the curve traits
//! ([`Curve`], [`CurveDerivative`], [`Subsegment`]) and run on every implementor through a
//! [`Family`]: a curve type built from the same data in any scalar.
//!
//! For each generated curve, over a window [a, b] (the domain, or [−1, 2] for a curve defined
//! on the whole line) sampled at the 17 parameters a + k(b − a)/16:
//!
//! 1. **f64 agrees with the exact back end**: the `f64` curve built from the same data (every
//!    number is a multiple of 1/8, exact in both) evaluates within `Family::TOLERANCE · M` of
//!    the exact value rounded, where M ≥ 1 is the largest coordinate of the exact curve's
//!    Bézier points over [a, b] (a bound on the curve's magnitude there, by the convex-hull
//!    property). Both also reject NaN.
//! 2. **Subsegments reproduce the curve exactly**: cut at c, the pieces over [a, c] and
//!    [c, b] evaluate with `==` to the curve at every sample on their side, and their Bézier
//!    polygons meet at the curve's point at c (the families build continuous curves; where
//!    a piecewise curve's pieces do not meet, a piece ending at the knot ends with the left
//!    piece, which `tests/bezier.rs` checks on its own). Empty, reversed and (for bounded
//!    domains) out-of-domain intervals are errors, and so is evaluation outside a bounded
//!    domain.
//! 3. **Derivatives are differences of blossoms**: on each polynomial piece `B` of degree n
//!    over [a_k, b_k] (from the subsegment over [a, b]) at the local parameter s,
//!    `p'(t) = n (B[s, …, s, 1] − B[s, …, s, 0]) / (b_k − a_k)` and
//!    `p''(t) = n (n − 1) (B[s, …, 1, 1] − 2 B[s, …, 0, 1] + B[s, …, 0, 0]) / (b_k − a_k)²`
//!    [PPB, §3.9], exactly, for `derivative_at` and for the derivative curve.

use super::Q;
use compgeo::spline::{
    BSpline, Bezier, CompositeBezier, Curve, CurveDerivative, Domain, Point, Reparametrised,
    Scalar, Subsegment,
};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use std::fmt::Debug;

/// A curve type built from the same data in any scalar.
pub trait Family {
    /// The data a curve is built from (numbers in eighths, so exact in `f64`).
    type Data: Clone + Debug;
    /// The curve type over the scalar `S`.
    type Curve<S: Scalar>: CurveDerivative<S, 2> + Subsegment<S, 2, Segment: Pieces<S>> + Debug;
    /// The relative tolerance of the `f64` evaluation (see the module docs).
    const TOLERANCE: f64;
    /// Valid data.
    fn data() -> BoxedStrategy<Self::Data>;
    /// The curve of the data.
    fn build<S: Scalar>(data: &Self::Data) -> Self::Curve<S>;
}

/// The Bézier pieces of a subsegment, each with its interval.
pub trait Pieces<S> {
    /// `(a_k, b_k, B_k)`: the piece `B_k` over [a_k, b_k], in its local parameter.
    fn pieces(&self) -> Vec<(S, S, Bezier<S, 2>)>;
}

impl<S: Scalar> Pieces<S> for Reparametrised<S, 2> {
    fn pieces(&self) -> Vec<(S, S, Bezier<S, 2>)> {
        let (a, b) = self.interval();
        vec![(a.clone(), b.clone(), self.curve().clone())]
    }
}

impl<S: Scalar> Pieces<S> for CompositeBezier<S, 2> {
    fn pieces(&self) -> Vec<(S, S, Bezier<S, 2>)> {
        self.partition()
            .windows(2)
            .zip(self.pieces())
            .map(|(w, b)| (w[0].clone(), w[1].clone(), b.clone()))
            .collect()
    }
}

impl<S: Scalar> Pieces<S> for BSpline<S, 2> {
    fn pieces(&self) -> Vec<(S, S, Bezier<S, 2>)> {
        Pieces::pieces(
            &self
                .to_bezier()
                .expect("the Bézier pieces of a valid B-spline"),
        )
    }
}

/// Runs the properties on `cases` curves of the family.
pub fn check<F: Family>(cases: u32) {
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner = TestRunner::new(config);
    let result = runner.run(&(F::data(), 1i64..16), |(data, cut)| {
        check_one::<F>(&data, cut)
    });
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// One `#[test]` per family: `curve_property_tests! { test_name: Family, cases; ... }` runs
/// [`check`] on `cases` curves of the family. (Allowed unused: not every test crate that
/// includes `spline_common` checks curve families.)
#[allow(unused_macros)]
macro_rules! curve_property_tests {
    ($($name:ident: $family:ty, $cases:expr;)*) => {
        $(
            #[test]
            fn $name() {
                $crate::spline_common::curve_properties::check::<$family>($cases);
            }
        )*
    };
}
#[allow(unused_imports)]
pub(crate) use curve_property_tests;

/// The number n/8 in `S`.
pub fn eighths<S: Scalar>(n: i64) -> S {
    S::from_ratio(n, 8)
}

/// The point (x/8, y/8).
pub fn point<S: Scalar>((x, y): (i64, i64)) -> Point<S, 2> {
    Point::new([eighths(x), eighths(y)])
}

/// The points of a list of pairs of eighths.
pub fn points<S: Scalar>(pairs: &[(i64, i64)]) -> Vec<Point<S, 2>> {
    pairs.iter().copied().map(point).collect()
}

fn check_one<F: Family>(data: &F::Data, cut: i64) -> Result<(), TestCaseError> {
    let exact: F::Curve<Q> = F::build(data);
    let rounded: F::Curve<f64> = F::build(data);
    let domain = exact.domain();
    let (a, b) = match domain.bounds() {
        Some((a, b)) => (a.clone(), b.clone()),
        None => (Q::from_i64(-1), Q::from_i64(2)),
    };
    let at = |k: i64| a.clone() + (b.clone() - &a) * Q::from_ratio(k, 16);
    let samples: Vec<Q> = (0..=16).map(at).collect();
    let whole = exact.subsegment(&a, &b).map_err(fail)?.pieces();

    // 1. f64 against the exact values.
    let magnitude = whole
        .iter()
        .flat_map(|(_, _, piece)| piece.control().iter())
        .flat_map(|p| p.coords().iter())
        .fold(1.0f64, |m, c| m.max(c.to_f64().abs()));
    for t in &samples {
        let want = exact.eval(t).map_err(fail)?.to_f64();
        let got = rounded.eval(&t.to_f64()).map_err(fail)?;
        for j in 0..2 {
            prop_assert!(
                (got[j] - want[j]).abs() <= F::TOLERANCE * magnitude,
                "f64 {:?} vs exact {:?} at t = {}",
                got,
                want,
                t
            );
        }
    }
    prop_assert!(rounded.eval(&f64::NAN).is_err());

    // 2. The two subsegments at c reproduce the curve on their sides.
    let c = at(cut);
    let left = exact.subsegment(&a, &c).map_err(fail)?;
    let right = exact.subsegment(&c, &b).map_err(fail)?;
    for t in &samples {
        let want = exact.eval(t).map_err(fail)?;
        if *t <= c {
            prop_assert_eq!(&left.eval(t).map_err(fail)?, &want, "left at {}", t);
        }
        if *t >= c {
            prop_assert_eq!(&right.eval(t).map_err(fail)?, &want, "right at {}", t);
        }
    }
    let (left_pieces, right_pieces) = (left.pieces(), right.pieces());
    let left_end = left_pieces
        .last()
        .unwrap()
        .2
        .control()
        .last()
        .unwrap()
        .clone();
    let right_start = right_pieces[0].2.control()[0].clone();
    prop_assert_eq!(&left_end, &right_start);
    prop_assert_eq!(&left_end, &exact.eval(&c).map_err(fail)?);
    prop_assert!(exact.subsegment(&c, &c).is_err());
    prop_assert!(exact.subsegment(&b, &a).is_err());
    if let Domain::Interval { end, .. } = &domain {
        let beyond = end.clone() + Q::one();
        prop_assert!(exact.eval(&beyond).is_err());
        prop_assert!(exact.subsegment(&a, &beyond).is_err());
    }

    // 3. Derivatives against differences of blossoms, piece by piece.
    let derivative = exact.derivative_curve().map_err(fail)?;
    for (lo, hi, piece) in &whole {
        let h = hi.clone() - lo;
        let n = piece.degree();
        for k in 0..4 {
            let s = Q::from_ratio(k, 4);
            let t = lo.clone() + &(h.clone() * &s);
            let blossom = |tail: [i64; 2], order: usize| -> Result<Point<Q, 2>, TestCaseError> {
                let mut args = vec![s.clone(); n - order];
                args.extend(tail[..order].iter().map(|&x| Q::from_i64(x)));
                piece.blossom(&args).map_err(fail)
            };
            let first = if n >= 1 {
                (blossom([1, 0], 1)? - &blossom([0, 0], 1)?) * Q::from_i64(n as i64) / &h
            } else {
                Point::zero()
            };
            let second = if n >= 2 {
                let d = blossom([1, 1], 2)? - &(blossom([0, 1], 2)? * Q::from_i64(2))
                    + &blossom([0, 0], 2)?;
                d * Q::from_i64((n * (n - 1)) as i64) / &(h.clone() * &h)
            } else {
                Point::zero()
            };
            prop_assert_eq!(
                &exact.derivative_at(&t, 1).map_err(fail)?,
                &first,
                "p' at {}",
                t
            );
            prop_assert_eq!(
                &derivative.eval(&t).map_err(fail)?,
                &first,
                "p' curve at {}",
                t
            );
            prop_assert_eq!(
                &exact.derivative_at(&t, 2).map_err(fail)?,
                &second,
                "p'' at {}",
                t
            );
            prop_assert_eq!(
                &derivative.derivative_at(&t, 1).map_err(fail)?,
                &second,
                "p'' curve at {}",
                t
            );
            prop_assert_eq!(
                &exact.derivative_at(&t, 0).map_err(fail)?,
                &exact.eval(&t).map_err(fail)?
            );
        }
    }
    Ok(())
}

fn fail(e: compgeo::Error) -> TestCaseError {
    TestCaseError::fail(e.to_string())
}
