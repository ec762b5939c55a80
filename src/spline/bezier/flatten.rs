//! Flattening a Bézier curve: a polyline within a tolerance, by recursive subdivision.
//!
//! The problem: draw the curve segment b[0, 1] with straight lines no farther than a
//! tolerance from it. The idea: the chord b₀bₙ is within `n(n − 1)/8 · max ‖Δ²bᵢ‖∞` of the
//! curve; while that bound exceeds the tolerance, split at 1/2 and recurse, else emit the
//! chord.
//!
//! Follows [PPB, §3.5] (the program PLOT BÉZIER, its flatness test and the error bound of the
//! linear interpolant).
//!
//! # Complexity
//!
//! Θ(s·n²D) time for s output segments, s = O(√(bound/tolerance)); O(kn·D) auxiliary space
//! for a recursion of depth k.
//!
//! Invariants the tests check: the polyline starts and ends at b₀ and bₙ and is within the
//! tolerance of the curve; a straight polygon gives its chord.

use super::curve::Bezier;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// Flattening, declared: its name, bounds, counts, source and claims, in each of its sizes
/// (the degree n for four segments; the number s of segments of a cubic).
pub(crate) const FLATTEN: Declaration = Declaration {
    problem: "bezier",
    name: "flatten",
    function: "spline::Bezier::flatten",
    file: "src/spline/bezier/flatten.rs",
    summary: "a polyline within a tolerance by recursive subdivision",
    time: "Θ(s·n²D)",
    space: "O(kn·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (s − 1)·n(n + 1)/2 affine combinations: one split at ½ per segment but one",
    source: "[PPB, §3.5]",
    claims: &[
        on(
            "parabola-degree",
            Bound::Quadratic,
            Operation::ArithmeticOperations,
        ),
        on(
            "parabola-segments",
            Bound::Linear,
            Operation::ArithmeticOperations,
        ),
    ],
};

pub use crate::limits::MAX_FLATTEN_SEGMENTS;

/// The deepest recursion of [`Bezier::flatten`].
const MAX_FLATTEN_DEPTH: usize = 40;

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// A polyline within `tolerance` of the curve segment b[0, 1], by recursive subdivision.
    ///
    /// Idea: the chord b₀bₙ is within `n(n − 1)/8 · max ‖Δ²bᵢ‖∞` of the curve; while that
    /// bound exceeds the tolerance, split at 1/2 and recurse on both halves, else emit the
    /// chord. Each halving divides the second differences by four, so a uniform depth of
    /// ⌈log₄(bound/tolerance)⌉ always suffices; the recursion never goes deeper (on `f64`,
    /// rounding may keep the bound just above a tolerance near the coordinates' precision).
    ///
    /// Follows [PPB, §3.5] (the program PLOT BÉZIER, its flatness test and
    /// the error bound of the linear interpolant).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `tolerance` is not a positive finite number, or if the
    /// polyline would need more than [`MAX_FLATTEN_SEGMENTS`] segments.
    ///
    /// # Complexity
    ///
    /// Θ(s·n²D) time for s output segments (each subdivision is a de Casteljau triangle);
    /// s ≤ 2ᵏ with k = ⌈log₄(n(n − 1) max ‖Δ²bᵢ‖ / (8·tolerance))⌉, i.e. s = O(√(bound /
    /// tolerance)); O(kn·D) auxiliary space for the recursion.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])])?;
    /// let poly = b.flatten(&0.01)?;
    /// assert_eq!(poly.first(), Some(&Point::new([0.0, 0.0])));
    /// assert_eq!(poly.last(), Some(&Point::new([2.0, 0.0])));
    /// assert!(poly.len() > 4);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn flatten(&self, tolerance: &S) -> Result<Vec<Point<S, D>>> {
        self.flatten_with(tolerance, &mut NoCount)
    }

    /// [`Bezier::flatten`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of the
    /// subdivisions: a polyline of s segments took s − 1 splits at ½, so exactly
    /// (s − 1)·n(n + 1)/2. (The flatness bounds are bookkeeping, not counted.)
    ///
    /// # Errors
    ///
    /// As [`Bezier::flatten`].
    ///
    /// # Complexity
    ///
    /// Θ(s·n²D) time for s output segments, O(kn·D) auxiliary space for a recursion of
    /// depth k.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])])?;
    /// let mut c = Counts::default();
    /// let poly = b.flatten_with(&0.01, &mut c)?;
    /// let segments = poly.len() as u64 - 1;
    /// assert_eq!(c.arithmetic_operations, (segments - 1) * 3); // n = 2: three per split
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn flatten_with<C: Counter>(
        &self,
        tolerance: &S,
        counter: &mut C,
    ) -> Result<Vec<Point<S, D>>> {
        validate_parameter(tolerance, "tolerance")?;
        if *tolerance <= S::zero() {
            return Err(Error::InvalidParameter {
                name: "tolerance",
                reason: format!("must be positive, got {}", tolerance.to_f64()),
            });
        }
        let bound = flatness_bound(self.control());
        let depth = if bound <= *tolerance {
            0
        } else {
            // A cap on the recursion, not a geometric decision: f64 is fine here.
            let ratio = bound.to_f64() / tolerance.to_f64();
            if !ratio.is_finite() {
                return Err(too_many_segments());
            }
            ((ratio.log2() / 2.0).ceil() as usize + 1).min(MAX_FLATTEN_DEPTH)
        };
        let mut out = vec![self.control()[0].clone()];
        flatten_into(self, tolerance, depth, &mut out, counter)?;
        Ok(out)
    }
}

/// `n(n − 1)/8 · max ‖Δ²bᵢ‖∞`, the course's bound on the distance from the curve to its chord.
pub(crate) fn flatness_bound<S: Scalar, const D: usize>(b: &[Point<S, D>]) -> S {
    let n = b.len() - 1;
    let mut max = S::zero();
    for w in b.windows(3) {
        let second = w[2].clone() - &w[1] - &w[1] + &w[0];
        for c in second.coords() {
            let a = c.abs();
            if a > max {
                max = a;
            }
        }
    }
    max * S::from_ratio((n * n.saturating_sub(1)) as i64, 8)
}

fn flatten_into<S: Scalar, const D: usize, C: Counter>(
    curve: &Bezier<S, D>,
    tolerance: &S,
    depth: usize,
    out: &mut Vec<Point<S, D>>,
    counter: &mut C,
) -> Result<()> {
    if depth == 0 || flatness_bound(curve.control()) <= *tolerance {
        if out.len() > MAX_FLATTEN_SEGMENTS {
            return Err(too_many_segments());
        }
        out.push(curve.control()[curve.degree()].clone());
        return Ok(());
    }
    let (left, right) = curve.split_counted(&S::from_ratio(1, 2), counter);
    flatten_into(&left, tolerance, depth - 1, out, counter)?;
    flatten_into(&right, tolerance, depth - 1, out, counter)
}

fn too_many_segments() -> Error {
    Error::InvalidParameter {
        name: "tolerance",
        reason: format!(
            "too small for this curve: the polyline would need more than MAX_FLATTEN_SEGMENTS = {MAX_FLATTEN_SEGMENTS} segments"
        ),
    }
}
