//! Integration of Bézier curves: the antiderivative as a Bézier curve of one degree more,
//! and the integral over [0, 1].
//!
//! The problem: ∫ b. The idea: the antiderivative of `Σ bᵢ Bᵢⁿ` has the control points
//! `cᵢ = cᵢ₋₁ + bᵢ₋₁/(n + 1)` (the inverse of the hodograph), and ∫₀¹ Bᵢⁿ = 1/(n + 1).
//!
//! Follows [PPB, §2.7] (with the interval [0, 1]).
//!
//! # Complexity
//!
//! Θ(nD) time and space.
//!
//! Invariants the tests check (exactly on rationals): the antiderivative's hodograph is the
//! curve, and its value at 1 is the definite integral.

use super::curve::Bezier;
use crate::spline::scalar::{validate_points, Point, Scalar};
use crate::Result;

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The antiderivative with value `start` at t = 0, a curve of degree n + 1:
    /// `c₀ = start`, `cᵢ = cᵢ₋₁ + bᵢ₋₁/(n + 1)`.
    ///
    /// Follows [PPB, §2.7] (with the interval [0, 1]).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`](crate::Error::NonFinite) if `start` has a NaN or infinite
    /// coordinate; [`Error::Overflow`](crate::Error::Overflow) if a control point is beyond the
    /// range of `f64`; [`Error::LimitExceeded`](crate::Error::LimitExceeded) for a curve
    /// already of degree [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([2.0])])?; // 2t
    /// let c = b.integral(Point::new([0.0]))?; // t²
    /// assert_eq!(c.control(), [Point::new([0.0]), Point::new([0.0]), Point::new([1.0])]);
    /// assert_eq!(b.definite_integral(), Point::new([1.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn integral(&self, start: Point<S, D>) -> Result<Self> {
        validate_points(std::slice::from_ref(&start), "integration constant")?;
        let den = S::from_i64(self.control().len() as i64);
        let mut control = Vec::with_capacity(self.control().len() + 1);
        let mut c = start;
        control.push(c.clone());
        for b in self.control() {
            c += &(b.clone() / &den);
            control.push(c.clone());
        }
        Bezier::derived(control, "integration")
    }

    /// `∫₀¹ b(t) dt = (b₀ + ⋯ + bₙ)/(n + 1)`.
    ///
    /// Follows [PPB, §2.7].
    ///
    /// # Complexity
    ///
    /// Θ(nD) time, O(D) auxiliary space.
    pub fn definite_integral(&self) -> Point<S, D> {
        let mut sum = Point::zero();
        for b in self.control() {
            sum += b;
        }
        sum / S::from_i64(self.control().len() as i64)
    }
}
