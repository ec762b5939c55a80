//! The linear operations of a NURBS curve, by the B-spline operations on its homogeneous form:
//! degree elevation, the conversion to rational Bézier pieces and the piece over an interval.
//!
//! Both are linear in the control points and depend on the knots only, so applied to the
//! weighted points Σ wᵢcᵢNᵢ and to the weights Σ wᵢNᵢ (the two halves of
//! [`Nurbs::homogeneous`]) they give the homogeneous form of the same rational curve in the
//! new representation [SPL, §14]. The weights of the result stay positive: knot insertion
//! makes each new weight a convex combination of old ones, and elevation on clamped ends an
//! average of blossom values of the weight function inside the domain (on unclamped ends it
//! would extrapolate, so it is refused there).
//!
//! # Complexity
//!
//! Twice the B-spline operation: [`BSpline::elevate`](crate::spline::BSpline::elevate) and
//! [`BSpline::to_bezier`](crate::spline::BSpline::to_bezier), once with D coordinates and once
//! with one.

use super::{Nurbs, RationalBezier};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::curve::Subsegment;
use crate::spline::scalar::Scalar;
use crate::{Error, Result};

/// NURBS degree elevation, declared.
pub(crate) const NURBS_ELEVATE: Declaration = Declaration {
    problem: "nurbs",
    name: "elevate",
    function: "spline::Nurbs::elevate",
    file: "src/spline/rational/linear.rs",
    summary: "the same rational curve in a higher degree, by B-spline elevation of both homogeneous halves",
    time: "Θ((n + p·t)(d + t)²·D)",
    space: "O((n + p·(d + t))D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "B-spline elevation's count for D + 1 coordinates, as two curves",
    source: "[SPL, §14]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

/// NURBS to rational Bézier pieces, declared.
pub(crate) const NURBS_TO_BEZIER: Declaration = Declaration {
    problem: "nurbs",
    name: "to-bezier",
    function: "spline::Nurbs::to_bezier",
    file: "src/spline/rational/linear.rs",
    summary: "the rational Bézier pieces of a NURBS curve, one per non-empty span of the domain",
    time: "Θ(n + d + p·d·D) plus O(n·d²·D)",
    space: "Θ(p·d·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "B-spline conversion's count, as two curves",
    source: "[SPL, §14]",
    claims: &[on(
        "random-control",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// NURBS knot refinement, declared.
pub(crate) const NURBS_REFINE: Declaration = Declaration {
    problem: "nurbs",
    name: "refine",
    function: "spline::Nurbs::refine",
    file: "src/spline/rational/linear.rs",
    summary: "the same rational curve with m knots added, by B-spline refinement of both homogeneous halves",
    time: "O(m log m + log n + (n + m + md)D)",
    space: "O((n + m)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "B-spline refinement's count, as two curves",
    source: "[SPL, §14]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> Nurbs<S, D> {
    /// The same curve with all of `new_knots` added (any order, repeats allowed): the
    /// B-spline refinement ([`BSpline::refine`](crate::spline::BSpline::refine), one
    /// backward pass of Boehm's insertions) of both homogeneous halves. The new weights are
    /// convex combinations of the old ones.
    ///
    /// # Errors
    ///
    /// As [`BSpline::refine`](crate::spline::BSpline::refine); [`Error::Overflow`] if, with
    /// `f64`, a control point (a quotient) is beyond the double range.
    ///
    /// # Complexity
    ///
    /// O(m log m + log n + (n + m + md)D) time, O((n + m)D) space for m new knots.
    ///
    /// ```
    /// use compgeo::spline::{Curve, Nurbs, Point};
    ///
    /// let c = Nurbs::circle(Point::new([0.0, 0.0]), 1.0)?;
    /// let r = c.refine(&[0.5, 2.5])?;
    /// assert_eq!(r.control().len(), c.control().len() + 2);
    /// let (p, q) = (r.eval(&0.25)?, c.eval(&0.25)?);
    /// assert!((p[0] - q[0]).abs() < 1e-15 && (p[1] - q[1]).abs() < 1e-15);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn refine(&self, new_knots: &[S]) -> Result<Self> {
        self.refine_with(new_knots, &mut NoCount)
    }

    /// [`Nurbs::refine`], counting what
    /// [`BSpline::refine_with`](crate::spline::BSpline::refine_with) counts for the weighted
    /// points and for the weights.
    ///
    /// # Errors
    ///
    /// As [`Nurbs::refine`].
    ///
    /// # Complexity
    ///
    /// O(m log m + log n + (n + m + md)D) time, O((n + m)D) space for m new knots.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 1.0]), Point::new([2.0, 0.0])];
    /// let s = Nurbs::new(c, vec![1.0, 2.0, 1.0], t)?;
    /// let mut n = Counts::default();
    /// s.refine_with(&[0.5], &mut n)?;
    /// assert_eq!(n.arithmetic_operations, 2 * 2); // d combinations per half
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn refine_with<C: Counter>(&self, new_knots: &[S], counter: &mut C) -> Result<Self> {
        let (numerator, denominator) = self.homogeneous();
        Nurbs::from_homogeneous(
            numerator.refine_with(new_knots, counter)?,
            denominator.refine_with(new_knots, counter)?,
        )
    }

    /// The same curve of degree d + `times`. See [`Nurbs::elevate_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"knots"` unless the ends are clamped
    /// (t₁ = … = t_d and t_n = … = t_{n+d−1}; t₀ and t_{n+d} are free): on other knot vectors
    /// the B-spline elevation extrapolates the end pieces beyond the domain, where the
    /// weights may turn negative; otherwise as
    /// [`BSpline::elevate`](crate::spline::BSpline::elevate), and [`Error::Overflow`] if, with
    /// `f64`, a control point (a quotient) is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((n + p·t)(d + t)²·D) time and O((n + p·(d + t))D) space for p non-empty spans and
    /// t = `times`: twice B-spline elevation.
    ///
    /// ```
    /// use compgeo::spline::{Curve, Nurbs, Point};
    ///
    /// let c = Nurbs::circle(Point::new([0.0, 0.0]), 5.0)?;
    /// let e = c.elevate(1)?;
    /// assert_eq!(e.degree(), 3);
    /// let p = e.eval(&2.5)?;
    /// assert!((p[0] + 3.0).abs() < 1e-12 && (p[1] + 4.0).abs() < 1e-12);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate(&self, times: usize) -> Result<Self> {
        self.elevate_with(times, &mut NoCount)
    }

    /// [`Nurbs::elevate`], counting what
    /// [`BSpline::elevate_with`](crate::spline::BSpline::elevate_with) counts for the weighted
    /// points and for the weights.
    ///
    /// # Errors
    ///
    /// As [`Nurbs::elevate`].
    ///
    /// # Complexity
    ///
    /// As [`Nurbs::elevate`].
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 1.0]), Point::new([2.0, 0.0])];
    /// let s = Nurbs::new(c, vec![1.0, 2.0, 1.0], t)?;
    /// let mut n = Counts::default();
    /// assert_eq!(s.elevate_with(1, &mut n)?.control().len(), 4);
    /// assert!(n.arithmetic_operations > 0);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_with<C: Counter>(&self, times: usize, counter: &mut C) -> Result<Self> {
        let (d, t) = (self.degree(), self.knots().knots());
        let n = t.len() - d - 1;
        // B-spline elevation extends the end pieces beyond the domain where the knots there
        // are not all at its ends; the weights of those control points, extrapolated, may
        // turn negative. With t₁ = … = t_d and t_n = … = t_{n+d−1} every new weight is an
        // average of blossom values inside the domain: positive.
        if d > 0 && (t[1] != t[d] || t[n] != t[n + d - 1]) {
            return Err(Error::InvalidParameter {
                name: "knots",
                reason: "elevating a NURBS curve needs clamped ends (t_1 = … = t_d and t_n = … = t_{n+d−1}): beyond the domain the elevated weights may turn negative".to_string(),
            });
        }
        let (numerator, denominator) = self.homogeneous();
        let numerator = numerator.elevate_with(times, counter)?;
        let denominator = denominator.elevate_with(times, counter)?;
        Nurbs::from_homogeneous(numerator, denominator)
    }

    /// The rational Bézier pieces, one per non-empty span [t_i, t_{i+1}] of the domain, each
    /// on [0, 1] (the piece over [a, b] at s is the curve at a + s(b − a)). See
    /// [`Nurbs::to_bezier_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::to_bezier`](crate::spline::BSpline::to_bezier);
    /// [`Error::Overflow`](crate::Error::Overflow) if, with `f64`, a control point is beyond
    /// the double range.
    ///
    /// # Complexity
    ///
    /// Θ(n + d + p·d·D) plus O(n·d²·D) time and Θ(p·d·D) space for p pieces: twice B-spline
    /// conversion.
    ///
    /// ```
    /// use compgeo::spline::{Curve, Nurbs, Point};
    ///
    /// let c = Nurbs::circle(Point::new([0.0, 0.0]), 1.0)?;
    /// let (breaks, quarters) = c.to_bezier()?;
    /// assert_eq!(breaks, [0.0, 1.0, 2.0, 3.0, 4.0]);
    /// assert_eq!(quarters.len(), 4);
    /// assert_eq!(quarters[0].eval(&0.5)?, c.eval(&0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_bezier(&self) -> Result<(Vec<S>, Vec<RationalBezier<S, D>>)> {
        self.to_bezier_with(&mut NoCount)
    }

    /// [`Nurbs::to_bezier`], counting what
    /// [`BSpline::to_bezier_with`](crate::spline::BSpline::to_bezier_with) counts for the
    /// weighted points and for the weights. Returns the breakpoints (the distinct knots of
    /// the domain) and the pieces between them.
    ///
    /// # Errors
    ///
    /// As [`Nurbs::to_bezier`].
    ///
    /// # Complexity
    ///
    /// As [`Nurbs::to_bezier`].
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let c = vec![Point::new([0.0]), Point::new([1.0]), Point::new([3.0]), Point::new([4.0])];
    /// let mut n = Counts::default();
    /// let (breaks, pieces) = Nurbs::new(c, vec![1.0, 3.0, 3.0, 1.0], t)?.to_bezier_with(&mut n)?;
    /// assert_eq!((breaks.len(), pieces.len()), (3, 2));
    /// assert_eq!(n.arithmetic_operations, 2); // one affine combination per half
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_bezier_with<C: Counter>(
        &self,
        counter: &mut C,
    ) -> Result<(Vec<S>, Vec<RationalBezier<S, D>>)> {
        let (numerator, denominator) = self.homogeneous();
        let numerator = numerator.to_bezier_with(counter)?;
        let denominator = denominator.to_bezier_with(counter)?;
        let pieces = numerator
            .pieces()
            .iter()
            .zip(denominator.pieces())
            .map(|(a, w)| RationalBezier::from_homogeneous(a.clone(), w.clone()))
            .collect::<Result<Vec<_>>>()?;
        Ok((numerator.partition().to_vec(), pieces))
    }
}

/// The piece over [a, b] by the B-spline subsegment of both homogeneous halves.
impl<S: Scalar, const D: usize> Subsegment<S, D> for Nurbs<S, D> {
    type Segment = Nurbs<S, D>;

    /// The piece over [a, b] ⊆ [t_d, t_n] as a NURBS curve of the same degree on the knots
    /// of [a, b] (the cut ends clamped): [`BSpline::subsegment`](crate::spline::BSpline)
    /// of the weighted points and of the weights. The new weights are convex combinations of
    /// the old ones (knot insertion), so they stay positive.
    ///
    /// # Errors
    ///
    /// As [`Subsegment::subsegment`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d²)D) time and space: two splits of each half.
    ///
    /// ```
    /// use compgeo::spline::{Curve, Nurbs, Point, Subsegment};
    ///
    /// // A quarter of the unit circle, exactly: the parameters 0 to 1 of the full circle.
    /// let c = Nurbs::circle(Point::new([0.0, 0.0]), 1.0)?;
    /// let quarter = c.subsegment(&0.0, &1.0)?;
    /// assert_eq!(quarter.eval(&0.5)?, c.eval(&0.5)?);
    /// assert_eq!(quarter.control().len(), 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn subsegment(&self, a: &S, b: &S) -> Result<Self> {
        let (numerator, denominator) = self.homogeneous();
        Nurbs::from_homogeneous(numerator.subsegment(a, b)?, denominator.subsegment(a, b)?)
    }
}
