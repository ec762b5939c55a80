//! The weights of a rational curve: validated once, and the homogeneous points they make.
//!
//! A rational curve with control points cᵢ ∈ R^D and weights wᵢ is the projection of the
//! polynomial curve with the homogeneous control points (wᵢ·cᵢ, wᵢ) ∈ R^{D+1}: the first D
//! coordinates divided by the last [SPL, §14]. Its weights must be finite and strictly
//! positive: then the denominator Σ wᵢ·Bᵢ(t) is a positive combination of basis functions
//! that are non-negative and sum to one on the domain, so it is at least min wᵢ > 0 there and
//! the division is always defined. A zero weight would let the denominator vanish, a negative
//! one let it change sign (a curve through infinity); both are refused.
//!
//! Multiplying every weight by the same factor does not change the curve. With `f64` the
//! homogeneous points are built from the weights times the power of two 2^−e that brings the
//! largest weight into [1, 2) (or as near as a normal power of two can, |e| ≤ 1020): an exact
//! scaling, so weights near 1e300 or subnormal ones give the same curve as weights near 1, and
//! |wᵢ·cᵢ| stays below twice the largest coordinate. Exact scalars use the weights as given.

use crate::spline::scalar::{pow2_scale, Point, Scalar};
use crate::{Error, Result};

/// The homogeneous control points of a rational curve: `points[i] = s·wᵢ·cᵢ` and
/// `weights[i] = s·wᵢ` with the scale s of the module docs.
pub(crate) struct Homogeneous<S, const D: usize> {
    pub(crate) points: Vec<Point<S, D>>,
    pub(crate) weights: Vec<Point<S, 1>>,
    pub(crate) scale: S,
}

/// Checks that there is one weight per control point and that every weight is finite and
/// strictly positive.
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"weights"`: naming both counts if they differ, or the
/// index and value of the first weight that is NaN, infinite, zero or negative.
pub(crate) fn validate_weights<S: Scalar>(weights: &[S], points: usize) -> Result<()> {
    if weights.len() != points {
        return Err(Error::InvalidParameter {
            name: "weights",
            reason: format!(
                "{points} control points need {points} weights, got {}",
                weights.len()
            ),
        });
    }
    for (i, w) in weights.iter().enumerate() {
        if !w.is_finite() || *w <= S::zero() {
            return Err(Error::InvalidParameter {
                name: "weights",
                reason: format!(
                    "weight {i} is {}; weights must be finite and positive",
                    w.to_f64()
                ),
            });
        }
    }
    Ok(())
}

/// The homogeneous points of validated control points and weights (same length, weights
/// positive).
///
/// # Errors
///
/// [`Error::Overflow`] if, with `f64`, a weighted coordinate is beyond the double range (a
/// coordinate above 2^1023 in absolute value) or the weights span so many orders of magnitude
/// that the smallest, scaled, is zero (a ratio beyond 2^1074).
pub(crate) fn homogeneous<S: Scalar, const D: usize>(
    control: &[Point<S, D>],
    weights: &[S],
) -> Result<Homogeneous<S, D>> {
    debug_assert_eq!(control.len(), weights.len());
    let as_points: Vec<Point<S, 1>> = weights.iter().map(|w| Point::new([w.clone()])).collect();
    let scale = pow2_scale(&as_points.iter().collect::<Vec<_>>());
    let weights: Vec<Point<S, 1>> = as_points.into_iter().map(|w| w * &scale).collect();
    if weights.iter().any(|w| w[0].is_zero()) {
        return Err(Error::Overflow {
            what: "scaling the weights (their ratio is beyond the double range)",
        });
    }
    let points: Vec<Point<S, D>> = control
        .iter()
        .zip(&weights)
        .map(|(c, w)| c.clone() * &w[0])
        .collect();
    if !points.iter().all(Point::is_finite) {
        return Err(Error::Overflow {
            what: "the weighted control points",
        });
    }
    Ok(Homogeneous {
        points,
        weights,
        scale,
    })
}

/// The control points cᵢ = (wᵢ·cᵢ)/wᵢ of homogeneous points with positive weights.
pub(crate) fn project<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    weights: &[Point<S, 1>],
) -> Vec<Point<S, D>> {
    points
        .iter()
        .zip(weights)
        .map(|(p, w)| p.clone() / &w[0])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f64_weights_are_scaled_by_a_power_of_two_only() {
        let c = [Point::new([3.0]), Point::new([-1.0])];
        let h = homogeneous(&c, &[1e300, 3e299]).unwrap();
        assert!(h.weights[0][0] >= 1.0 && h.weights[0][0] < 2.0);
        assert_eq!(h.weights[0][0] / h.scale, 1e300);
        assert_eq!(h.weights[1][0] / h.scale, 3e299);
        assert_eq!(project(&h.points, &h.weights), c);
        let tiny = f64::from_bits(1);
        let h = homogeneous(&c, &[tiny, 3.0 * tiny]).unwrap();
        assert_eq!(
            (h.weights[0][0], h.weights[1][0]),
            (2f64.powi(-54), 3.0 * 2f64.powi(-54))
        );
        assert!(matches!(
            homogeneous(&c, &[tiny, 1e300]),
            Err(Error::Overflow { .. })
        ));
        let big = [Point::new([f64::MAX]), Point::new([0.0])];
        assert!(matches!(
            homogeneous(&big, &[1.5, 1.0]),
            Err(Error::Overflow { .. })
        ));
    }
}
