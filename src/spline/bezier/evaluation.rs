//! The evaluation schemes of a Bézier curve, for callers that choose one at run time (the
//! command line, the complexity report): de Casteljau's algorithm and the Horner-type scheme.
//!
//! The problem: the point b(t) of a Bézier curve of degree n. De Casteljau's algorithm forms
//! n(n + 1)/2 affine combinations (Θ(n²), every step a convex combination for t ∈ [0, 1]);
//! the Horner-type scheme n + 1 point operations (Θ(n)). Both accept any finite t.
//!
//! Follows [PPB, §2.3] (de Casteljau's algorithm, and Obs. 4 for the Horner-type scheme).
//!
//! # Complexity
//!
//! That of the chosen scheme: Θ(n²D) or Θ(nD) time, O(nD) or O(D) auxiliary space.

use super::curve::Bezier;
use super::{de_casteljau, horner};
use crate::complexity::algorithm_family;
use crate::count::{Counter, NoCount};
use crate::spline::scalar::{Point, Scalar};
use crate::Result;

algorithm_family! {
    /// The evaluation schemes of a Bézier curve, for callers that choose one at run time
    /// ([`evaluate`]).
    ///
    /// ```
    /// use compgeo::spline::bezier::Evaluation;
    ///
    /// let e: Evaluation = "horner".parse()?;
    /// assert_eq!(e, Evaluation::Horner);
    /// assert_eq!(e.name(), "horner");
    /// assert_eq!(Evaluation::DeCasteljau.to_string(), "de-casteljau");
    /// assert!("bernstein".parse::<Evaluation>().is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum Evaluation ("Bézier evaluation") {
        /// [`Bezier::de_casteljau_with`]: n(n + 1)/2 affine combinations, Θ(n²).
        DeCasteljau = de_casteljau::DECLARATION => Bezier::de_casteljau_with,
        /// [`Bezier::horner_with`]: the Horner-type scheme, n + 1 point operations, Θ(n).
        Horner = horner::DECLARATION => Bezier::horner_with,
    }
    fn run_with[S: Scalar, const D: usize, C: Counter](
        curve: &Bezier<S, D>,
        t: &S,
        counter: &mut C,
    ) -> Result<Point<S, D>>;
}

/// The point b(t) of `curve` by the chosen scheme: the same as calling its method.
///
/// # Errors
///
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `t` is NaN or infinite.
///
/// # Complexity
///
/// That of the chosen scheme: Θ(n²D) time and O(nD) space for de Casteljau's, Θ(nD) and
/// O(D) for Horner's.
///
/// ```
/// use compgeo::spline::bezier::{evaluate, Evaluation};
/// use compgeo::spline::{Bezier, Point};
///
/// let b = Bezier::new(vec![Point::new([0.0]), Point::new([4.0]), Point::new([0.0])])?;
/// for scheme in Evaluation::ALL {
///     assert_eq!(evaluate(&b, &0.5, scheme)?, Point::new([2.0]));
/// }
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn evaluate<S: Scalar, const D: usize>(
    curve: &Bezier<S, D>,
    t: &S,
    algorithm: Evaluation,
) -> Result<Point<S, D>> {
    evaluate_with(curve, t, algorithm, &mut NoCount)
}

/// [`evaluate`], recording the scheme's point operations in `counter`.
///
/// # Errors
///
/// As [`evaluate`].
///
/// # Complexity
///
/// As [`evaluate`].
///
/// # Counts
///
/// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination or
/// point operation: n(n + 1)/2 for de Casteljau, n + 1 for Horner.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::bezier::{evaluate_with, Evaluation};
/// use compgeo::spline::{Bezier, Point};
///
/// let b = Bezier::new((0..5).map(|i| Point::new([i as f64])).collect())?;
/// let mut c = Counts::default();
/// evaluate_with(&b, &0.25, Evaluation::DeCasteljau, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 10);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn evaluate_with<S: Scalar, const D: usize, C: Counter>(
    curve: &Bezier<S, D>,
    t: &S,
    algorithm: Evaluation,
    counter: &mut C,
) -> Result<Point<S, D>> {
    algorithm.run_with(curve, t, counter)
}
