//! The Bézier curve type: construction, its control polygon, conversion between scalars,
//! reversal, the bounding box, and the global parameter of [`Bezier::reparametrise`].
//!
//! A curve of degree n in R^D is `b(t) = Σᵢ bᵢ Bᵢⁿ(t)` with control points b₀, …, bₙ and
//! the Bernstein polynomials Bᵢⁿ ([`bernstein`](super::bernstein())); t is the local
//! parameter, b₀ = b(0) and bₙ = b(1), and every operation accepts any real t, also
//! outside [0, 1]. The algorithms on the type live one per file beside this one (see the
//! [module map](super)); its [`Curve`](crate::spline::Curve) implementation is Horner's
//! scheme (`horner.rs`), [`CurveDerivative`](crate::spline::CurveDerivative) the hodograph and
//! the tetrahedral algorithm (`derivative.rs`), [`Subsegment`](crate::spline::Subsegment) the
//! restriction by blossoming (`de_casteljau.rs`).
//!
//! Follows [PPB, §2.2] (the Bézier representation, its symmetry and the convex-hull property,
//! Obs. 2) and [RD, §3.2] ("Curvas de Bézier").
//!
//! # Complexity
//!
//! Θ(nD) to build, reverse or box a curve of degree n in R^D.

use super::horner::{horner_limit, Polygon};
use super::reparametrised::Reparametrised;
use crate::spline::curve::{check_interval, Domain};
use crate::spline::scalar::{validate_points, Point, Scalar};
use crate::{limits, Error, Result};
use std::fmt::Debug;

/// A Bézier curve of degree n (n + 1 control points in R^D, over the scalar `S`).
///
/// Construct with [`Bezier::new`], which validates the control polygon; the fields are
/// private so a `Bezier` always has at least one control point, all finite.
///
/// ```
/// use compgeo::spline::{Bezier, Curve, Point};
///
/// let b = Bezier::new(vec![
///     Point::new([0.0, 0.0]),
///     Point::new([1.0, 2.0]),
///     Point::new([3.0, 2.0]),
///     Point::new([4.0, 0.0]),
/// ])?;
/// assert_eq!(b.degree(), 3);
/// assert_eq!(b.eval(&0.5)?, Point::new([2.0, 1.5]));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone)]
pub struct Bezier<S, const D: usize> {
    pub(super) control: Polygon<S, D>,
    /// A bound on |t| under which Horner's scheme provably stays within the `f64` range
    /// (negative if there is none; unused for exact scalars); see [`horner_limit`].
    pub(super) horner_limit: f64,
}

impl<S: PartialEq, const D: usize> PartialEq for Bezier<S, D> {
    fn eq(&self, other: &Self) -> bool {
        // The limit is a function of the control points.
        self.control.as_slice() == other.control.as_slice()
    }
}

impl<S: Debug, const D: usize> Debug for Bezier<S, D> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Bezier")
            .field("control", &self.control.as_slice())
            .finish()
    }
}

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The curve with the given control points b₀, …, bₙ (degree n = `control.len() − 1`).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no control points; [`Error::NonFinite`] naming the first control
    /// point with a NaN or infinite coordinate; [`Error::LimitExceeded`] for a degree above
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) (more than 65 537 control points).
    ///
    /// # Complexity
    ///
    /// O(nD) to validate the points and to bound their coordinates (for the overflow check of
    /// the evaluations), plus O(D) for the scaled points of a cubic; no auxiliary space.
    pub fn new(control: Vec<Point<S, D>>) -> Result<Self> {
        check_degree(control.len())?;
        validate_points(&control, "control polygon")?;
        Ok(Bezier::with_control(control))
    }

    /// The control points b₀, …, bₙ.
    #[inline]
    pub fn control(&self) -> &[Point<S, D>] {
        self.control.as_slice()
    }

    /// The control points, by value.
    pub fn into_control(self) -> Vec<Point<S, D>> {
        self.control.into_vec()
    }

    /// The degree n (the number of control points minus one).
    #[inline]
    pub fn degree(&self) -> usize {
        self.control().len() - 1
    }

    /// The same curve with `f64` coordinates (each rounded to the nearest double).
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if a coordinate is beyond the range of `f64`.
    pub fn to_f64(&self) -> Result<Bezier<f64, D>> {
        Bezier::derived(self.control().iter().map(Point::to_f64).collect(), "to_f64")
    }

    /// The curve of an `f64` curve's exact values in `S` (exact for rationals).
    pub fn from_f64(curve: &Bezier<f64, D>) -> Self {
        let control = curve
            .control()
            .iter()
            .map(|p| Point::from_f64(p).expect("a Bezier's control points are finite"))
            .collect();
        Bezier::with_control(control)
    }

    /// The same curve traversed backwards: control points in reverse order, so the new curve
    /// at t is the old one at 1 − t.
    ///
    /// Follows [PPB, §2.2] (symmetry of the Bézier representation).
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space for the copy.
    pub fn reversed(&self) -> Self {
        let mut control = self.control().to_vec();
        control.reverse();
        Bezier::with_control(control)
    }

    /// This curve over the global interval [a, b]; see [`Reparametrised`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `a` or `b` is NaN or infinite, or if `a ≥ b`.
    pub fn reparametrise(self, a: S, b: S) -> Result<Reparametrised<S, D>> {
        check_interval(&Domain::Real, &a, &b)?;
        Ok(Reparametrised::new_unchecked(self, a, b))
    }

    /// The axis-aligned box `[min bᵢ, max bᵢ]` (coordinate-wise) of the control points, which
    /// contains the curve segment b[0, 1] by the convex-hull property. Returns (min, max).
    ///
    /// Follows [PPB, §2.2, Obs. 2].
    ///
    /// # Complexity
    ///
    /// Θ(nD) comparisons, O(D) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0, 1.0]), Point::new([2.0, -1.0])])?;
    /// assert_eq!(b.bounding_box(), (Point::new([0.0, -1.0]), Point::new([2.0, 1.0])));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bounding_box(&self) -> (Point<S, D>, Point<S, D>) {
        bounding_box_of(self.control())
    }

    /// A curve computed from a valid one: non-empty by construction, finite unless the
    /// computation overflowed `f64`, and of a degree within
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) unless the computation raised it (elevation,
    /// integration).
    pub(crate) fn derived(control: Vec<Point<S, D>>, what: &'static str) -> Result<Self> {
        debug_assert!(!control.is_empty());
        check_degree(control.len())?;
        if control.iter().all(Point::is_finite) {
            Ok(Bezier::with_control(control))
        } else {
            Err(Error::Overflow { what })
        }
    }

    /// The curve with these control points (at least one, all finite), with its Horner
    /// bound.
    pub(super) fn with_control(control: Vec<Point<S, D>>) -> Self {
        Bezier {
            horner_limit: horner_limit(&control),
            control: Polygon::new(control),
        }
    }
}

/// Checks that `points` control points (degree `points − 1`) are within
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE); no points is left to the caller's emptiness
/// check.
pub(crate) fn check_degree(points: usize) -> Result<()> {
    limits::DEGREE.check(points.saturating_sub(1) as u128)?;
    Ok(())
}

/// The coordinate-wise minimum and maximum of a non-empty list of points.
pub(crate) fn bounding_box_of<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
) -> (Point<S, D>, Point<S, D>) {
    bounding_box_counted(points, &mut crate::count::NoCount)
}

/// [`bounding_box_of`], counting two [`comparison`](crate::count::Counter::comparison)s per
/// coordinate of every point after the first: exactly 2D(N − 1) for N points.
pub(crate) fn bounding_box_counted<S: Scalar, const D: usize, C: crate::count::Counter>(
    points: &[Point<S, D>],
    counter: &mut C,
) -> (Point<S, D>, Point<S, D>) {
    let mut lo = points[0].clone();
    let mut hi = points[0].clone();
    for p in &points[1..] {
        for j in 0..D {
            counter.comparison();
            counter.comparison();
            if p[j] < lo[j] {
                lo[j] = p[j].clone();
            }
            if p[j] > hi[j] {
                hi[j] = p[j].clone();
            }
        }
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::{Curve, CurveDerivative};

    #[test]
    fn degree_zero_curve_is_constant() {
        let b = Bezier::new(vec![Point::new([2.0, -1.0])]).unwrap();
        for t in [-3.0, 0.0, 0.4, 1.0, 7.5] {
            assert_eq!(b.eval(&t).unwrap(), Point::new([2.0, -1.0]));
            assert_eq!(b.de_casteljau(&t).unwrap(), Point::new([2.0, -1.0]));
        }
        assert_eq!(b.hodograph().unwrap().control(), [Point::new([0.0, 0.0])]);
        assert_eq!(
            b.derivative_curve().unwrap().control(),
            [Point::new([0.0, 0.0])]
        );
        assert_eq!(b.blossom(&[]).unwrap(), Point::new([2.0, -1.0]));
    }

    #[test]
    fn bad_parameters_are_errors() {
        let b = Bezier::new(vec![Point::new([0.0]), Point::new([1.0])]).unwrap();
        assert!(b.eval(&f64::NAN).is_err());
        assert!(b.split(&f64::INFINITY).is_err());
        assert!(b.blossom(&[0.5, 0.5]).is_err());
        assert!(b.clone().reparametrise(1.0, 1.0).is_err());
        assert!(b.reparametrise(2.0, 1.0).is_err());
        assert!(Bezier::<f64, 1>::new(vec![]).is_err());
    }
}
