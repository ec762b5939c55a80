//! Conversion between the Bézier and the monomial (power) form of a polynomial curve.
//!
//! The problem: the coefficients aᵢ of `b(t) = Σ aᵢ tⁱ` from the control points, and back.
//! The idea: the Taylor expansion at t = 0, whose derivatives are differences of the control
//! points, `aᵢ = C(n, i) Δⁱb₀`; the inverse sums `bⱼ = Σ_{i ≤ j} C(j, i)/C(n, i) · aᵢ`.
//!
//! Follows [PPB, §2.8] (to the Bézier form) and [PPB, §2.9] (to the monomial form).
//!
//! # Complexity
//!
//! Θ(n²D) time either way, O(nD) space.
//!
//! Invariants the tests check (exactly on rationals): the power form evaluates to the curve,
//! and the conversion round-trips.

use super::curve::{check_degree, Bezier};
use super::derivative::difference;
use crate::count::{Counter, NoCount};
use crate::spline::scalar::{binomial, validate_points, Point, Scalar};
use crate::Result;

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The coefficients a₀, …, aₙ of the power form `b(t) = Σᵢ aᵢ tⁱ`:
    /// `aᵢ = C(n, i) Δⁱb₀`.
    ///
    /// Idea: the Taylor expansion at t = 0, whose derivatives are differences of the control
    /// points (the course writes the power basis scaled by C(n, i); here the plain monomials tⁱ).
    ///
    /// Follows [PPB, §2.9].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time (the difference table), O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// // Bézier points 0, 0, 1 are t².
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// assert_eq!(b.to_monomial(), [Point::new([0.0]), Point::new([0.0]), Point::new([1.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_monomial(&self) -> Vec<Point<S, D>> {
        to_monomial_counted(self.control(), &mut NoCount)
    }

    /// The Bézier curve of the power form `Σᵢ aᵢ tⁱ` (degree n = `coefficients.len() − 1`):
    /// `bⱼ = Σ_{i ≤ j} C(j, i)/C(n, i) · aᵢ`.
    ///
    /// Follows [PPB, §2.8] (with aᵢ there being aᵢ/C(n, i) here).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`](crate::Error::Empty) for no coefficients;
    /// [`Error::NonFinite`](crate::Error::NonFinite) naming the first coefficient with a NaN or
    /// infinite coordinate; [`Error::Overflow`](crate::Error::Overflow) if a control point is
    /// beyond the range of `f64`; [`Error::LimitExceeded`](crate::Error::LimitExceeded) for
    /// more than [`MAX_DEGREE`](crate::limits::MAX_DEGREE) + 1 coefficients.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, Θ(nD) space for the result.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::from_monomial(&[Point::new([1.0]), Point::new([2.0])])?; // 1 + 2t
    /// assert_eq!(b.control(), [Point::new([1.0]), Point::new([3.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_monomial(coefficients: &[Point<S, D>]) -> Result<Self> {
        // Before the Θ(n²) conversion, not after it.
        check_degree(coefficients.len())?;
        validate_points(coefficients, "monomial coefficients")?;
        let control = from_monomial_counted(coefficients, &mut NoCount);
        Bezier::derived(control, "conversion from the monomial form")
    }
}

/// The power-form coefficients of the polygon `control` (not empty), counting one
/// [`arithmetic_operation`](Counter::arithmetic_operation) per difference or scaling of a
/// point: exactly n(n + 1)/2 + n + 1 for n + 1 points.
pub(crate) fn to_monomial_counted<S: Scalar, const D: usize, C: Counter>(
    control: &[Point<S, D>],
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let n = control.len() - 1;
    let mut q = control.to_vec();
    let mut out = Vec::with_capacity(n + 1);
    for i in 0..=n {
        out.push(q[0].clone() * binomial::<S>(n, i));
        counter.arithmetic_operation();
        for _ in 1..q.len() {
            counter.arithmetic_operation();
        }
        difference(&mut q);
    }
    out
}

/// The Bézier points of the power form with these coefficients (not empty, finite),
/// counting one [`arithmetic_operation`](Counter::arithmetic_operation) per scaling or
/// multiply-add of a point: exactly (n + 1) + (n + 1)(n + 2)/2. The points may be non-finite
/// with `f64`: the caller checks.
pub(crate) fn from_monomial_counted<S: Scalar, const D: usize, C: Counter>(
    coefficients: &[Point<S, D>],
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let n = coefficients.len() - 1;
    let scaled: Vec<Point<S, D>> = coefficients
        .iter()
        .enumerate()
        .map(|(i, a)| {
            counter.arithmetic_operation();
            a.clone() / binomial::<S>(n, i)
        })
        .collect();
    (0..=n)
        .map(|j| {
            let mut b = Point::zero();
            for (i, a) in scaled.iter().enumerate().take(j + 1) {
                b += &(a.clone() * binomial::<S>(j, i));
                counter.arithmetic_operation();
            }
            b
        })
        .collect()
}
