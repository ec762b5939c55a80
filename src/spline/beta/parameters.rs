//! The shape parameters of a cubic Beta-spline, validated once.
//!
//! A uniformly shaped cubic Beta-spline [CCKS, §3] has two parameters: the bias β₁ and the
//! tension β₂. Its basis functions are cubic polynomials divided by the normaliser
//! δ = 2β₁³ + 4β₁² + 4β₁ + β₂ + 2 (the seed prints 1/(β₂ + 12), which is δ only for β₁ = 1:
//! see `docs/design.md`, "Beta-splines"). Barsky and Beatty take β₁ > 0 and β₂ ≥ 0, where
//! every basis function is non-negative on [0, 1]; [`BetaParameters::new`] accepts exactly
//! that range. The seed's third example uses β₂ = −10, which
//! [`BetaParameters::allowing_negative_tension`] accepts for reproducing it: the matrices of
//! the construction exist for every β₁ > 0 and β₂ except where they divide by zero.
//!
//! The construction divides by δ and inverts the Bernstein coefficient matrix C, whose
//! determinant is 4β₁³(2β₁² + 2β₁ + β₂)/δ³; so the parameters that break it are β₁ = 0,
//! β₂ = −2β₁(β₁ + 1) and δ = 0 (never reached with β₁ > 0 and β₂ ≥ 0, except in `f64` when β₁³
//! underflows or δ overflows, which is rejected too).

use crate::spline::scalar::{validate_parameter, Scalar};
use crate::{Error, Result};

/// The bias β₁ and tension β₂ of a cubic Beta-spline, with its normaliser δ: valid values,
/// checked once [CCKS, §3].
///
/// ```
/// use compgeo::spline::BetaParameters;
///
/// let p = BetaParameters::new(1.0, 0.0)?;
/// assert_eq!(*p.delta(), 12.0); // 2 + 4 + 4 + 0 + 2
/// assert!(BetaParameters::new(0.0, 1.0).is_err()); // the bias must be positive
/// assert!(BetaParameters::new(1.0, -10.0).is_err()); // negative tension needs the opt-in
/// assert!(BetaParameters::allowing_negative_tension(1.0, -10.0).is_ok());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BetaParameters<S> {
    beta1: S,
    beta2: S,
    delta: S,
}

impl<S: Scalar> BetaParameters<S> {
    /// The parameters β₁ (bias) and β₂ (tension), in the range of Barsky and Beatty: β₁ > 0
    /// and β₂ ≥ 0, both finite.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"beta1"` or `"beta2"`, with the value, if it is NaN
    /// or infinite, if β₁ ≤ 0, if β₂ < 0, or if in `f64` the construction would divide by zero
    /// (β₁³ underflows or δ overflows).
    ///
    /// # Complexity
    ///
    /// O(1).
    pub fn new(beta1: S, beta2: S) -> Result<Self> {
        validate_parameter(&beta2, "beta2")?;
        if beta2 < S::zero() {
            return Err(Error::InvalidParameter {
                name: "beta2",
                reason: format!(
                    "the tension β₂ must be non-negative, got {} (negative values need \
                     BetaParameters::allowing_negative_tension, or --allow-negative-tension)",
                    beta2.to_f64()
                ),
            });
        }
        Self::allowing_negative_tension(beta1, beta2)
    }

    /// The parameters with any finite tension β₂ (also negative, as in the seed's example
    /// β₂ = −10), as long as the construction is defined: β₁ > 0, δ ≠ 0 and
    /// β₂ ≠ −2β₁(β₁ + 1). With β₂ < 0 the basis may take negative values and the
    /// subdivision matrices negative entries.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"beta1"` (NaN, infinite, β₁ ≤ 0, or β₁³ zero or
    /// δ infinite in `f64`) or `"beta2"` (NaN, infinite, δ = 0, or β₂ = −2β₁(β₁ + 1), where C
    /// is singular), with the value.
    ///
    /// # Complexity
    ///
    /// O(1).
    pub fn allowing_negative_tension(beta1: S, beta2: S) -> Result<Self> {
        validate_parameter(&beta1, "beta1")?;
        validate_parameter(&beta2, "beta2")?;
        if beta1 <= S::zero() {
            return Err(Error::InvalidParameter {
                name: "beta1",
                reason: format!("the bias β₁ must be positive, got {}", beta1.to_f64()),
            });
        }
        let b1 = &beta1;
        let cube = b1.clone() * b1 * b1;
        let square = b1.clone() * b1;
        let delta = cube.clone() * S::from_i64(2)
            + square.clone() * S::from_i64(4)
            + b1.clone() * S::from_i64(4)
            + &beta2
            + S::from_i64(2);
        if cube.is_zero() || !delta.is_finite() {
            return Err(Error::InvalidParameter {
                name: "beta1",
                reason: format!(
                    "β₁ = {} makes β₁³ or δ = 2β₁³ + 4β₁² + 4β₁ + β₂ + 2 leave the range of \
                     the scalar; the construction would divide by zero",
                    b1.to_f64()
                ),
            });
        }
        if delta.is_zero() {
            return Err(Error::InvalidParameter {
                name: "beta2",
                reason: format!(
                    "β₂ = {} makes the normaliser δ = 2β₁³ + 4β₁² + 4β₁ + β₂ + 2 zero",
                    beta2.to_f64()
                ),
            });
        }
        let det_factor = square * S::from_i64(2) + b1.clone() * S::from_i64(2) + &beta2;
        if det_factor.is_zero() {
            return Err(Error::InvalidParameter {
                name: "beta2",
                reason: format!(
                    "β₂ = {} = −2β₁(β₁ + 1) makes the Bernstein coefficient matrix C singular \
                     (det C = 4β₁³(2β₁² + 2β₁ + β₂)/δ³)",
                    beta2.to_f64()
                ),
            });
        }
        Ok(BetaParameters {
            beta1,
            beta2,
            delta,
        })
    }

    /// The bias β₁.
    pub fn beta1(&self) -> &S {
        &self.beta1
    }

    /// The tension β₂.
    pub fn beta2(&self) -> &S {
        &self.beta2
    }

    /// The normaliser δ = 2β₁³ + 4β₁² + 4β₁ + β₂ + 2.
    pub fn delta(&self) -> &S {
        &self.delta
    }

    /// The parameters in `f64` (rounded), if they are valid there.
    ///
    /// # Errors
    ///
    /// As [`BetaParameters::allowing_negative_tension`], for the rounded values.
    pub fn to_f64(&self) -> Result<BetaParameters<f64>> {
        BetaParameters::allowing_negative_tension(self.beta1.to_f64(), self.beta2.to_f64())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_degenerate_value_is_named() {
        let name = |r: Result<BetaParameters<f64>>| match r {
            Err(Error::InvalidParameter { name, reason }) => (name, reason),
            other => panic!("{other:?}"),
        };
        assert_eq!(name(BetaParameters::new(0.0, 1.0)).0, "beta1");
        assert_eq!(name(BetaParameters::new(-1.0, 1.0)).0, "beta1");
        assert_eq!(name(BetaParameters::new(f64::NAN, 1.0)).0, "beta1");
        assert_eq!(name(BetaParameters::new(1.0, f64::INFINITY)).0, "beta2");
        assert_eq!(name(BetaParameters::new(1.0, -0.5)).0, "beta2");
        assert_eq!(name(BetaParameters::new(1e200, 0.0)).0, "beta1");
        assert_eq!(name(BetaParameters::new(1e-200, 0.0)).0, "beta1");
        // β₁ = 1: δ = β₂ + 12, and C is singular at β₂ = −4.
        let (n, r) = name(BetaParameters::allowing_negative_tension(1.0, -12.0));
        assert_eq!(n, "beta2");
        assert!(r.contains("-12") && r.contains("δ"), "{r}");
        let (n, r) = name(BetaParameters::allowing_negative_tension(1.0, -4.0));
        assert_eq!(n, "beta2");
        assert!(r.contains("-4") && r.contains("singular"), "{r}");
        assert!(BetaParameters::allowing_negative_tension(1.0, -10.0).is_ok());
    }
}
