//! Splitting a B-spline curve at a parameter: two curves on [t_d, u] and [u, t_n] whose
//! union is the curve.
//!
//! The problem: control points and knots of the two pieces. The idea: raise the multiplicity
//! of u to d by Boehm's insertion [PPB, §6.1]; then the curve passes through the control
//! point ĉ_{a−1} (a the index of the first copy of u), the basis functions left of u use only
//! ĉ₀, …, ĉ_{a−1} and those right of it only ĉ_{a−1}, …, so the arrays can be cut there
//! (de Casteljau's subdivision is the case of a single Bézier segment [PPB, §6.1]). Where u
//! already has multiplicity d + 1 (the curve may jump there) nothing is inserted and the
//! pieces take the left and the right limit.
//!
//! The pieces' knot vectors: the left one is t₀, …, t_{a−1} (as refined) followed by d + 1
//! copies of u, the right one d + 1 copies of u followed by the knots above u. So the cut
//! ends are clamped, and the outer ends are what they were: a clamped vector gives two
//! clamped pieces, an unclamped one keeps its first (last) d knots before t_d (after t_n)
//! on the left (right) piece. Knots are compared exactly: a parameter a few ulps from an
//! existing knot is a new knot with its own tiny span, and the piece between them is kept.
//!
//! Follows [PPB, §6.1] (insertion up to multiplicity d, Obs. 1) and Piegl and Tiller,
//! *The NURBS Book* (2nd ed., 1997), §5.3 (curve splitting).
//!
//! # Complexity
//!
//! The insertion of d − s copies, Θ((n + d + d²)D), and the copy of the two arrays: Θ((n + d²)D)
//! time and space.
//!
//! Invariants the tests check (exactly on rationals): each piece evaluates to the curve on its
//! half, and the pieces meet at s(u).

use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::curve::{check_interval, Subsegment};
use crate::spline::scalar::{validate_parameter, Scalar};
use crate::{Error, Result};

/// Splitting, declared.
pub(crate) const SPLIT: Declaration = Declaration {
    problem: "bspline",
    name: "split",
    function: "spline::BSpline::split",
    file: "src/spline/bspline/split.rs",
    summary: "the curve as two curves on [t_d, u] and [u, t_n], by inserting u up to multiplicity d",
    time: "Θ((n + d²)D)",
    space: "O((n + d²)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (d − s)(d − s + 1)/2 affine combinations, s ≤ d the multiplicity of u (none at d + 1)",
    source: "[PPB, §6.1]",
    claims: &[on("random-degree", Bound::Quadratic, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The curve split at `u` into the pieces on [t_d, u] and [u, t_n]. See
    /// [`BSpline::split_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN, infinite or not inside the
    /// domain (t_d, t_n) (at an end one piece would have an empty domain);
    /// [`Error::LimitExceeded`] beyond [`MAX_KNOTS`](crate::limits::MAX_KNOTS);
    /// [`Error::Overflow`] if, with `f64`, a new control point rounds beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((n + d²)D) time, O((n + d²)D) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?;
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([3.0, 2.0]),
    ///              Point::new([4.0, 0.0])];
    /// let s = BSpline::new(c, t)?;
    /// let (left, right) = s.split(&0.5)?;
    /// assert_eq!(left.knots().knots(), [0.0, 0.0, 0.0, 0.5, 0.5, 0.5]);
    /// assert_eq!(right.knots().knots(), [0.5, 0.5, 0.5, 1.0, 2.0, 2.0, 2.0]);
    /// assert_eq!(left.eval(&0.25)?, s.eval(&0.25)?);
    /// assert_eq!(right.eval(&1.5)?, s.eval(&1.5)?);
    /// assert_eq!(left.control().last(), right.control().first());
    /// assert!(s.split(&2.0).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split(&self, u: &S) -> Result<(Self, Self)> {
        self.split_with(u, &mut NoCount)
    }

    /// The curve split at `u`, counting the affine combinations of the insertion.
    ///
    /// Idea: insert u until its multiplicity is d (none if it is d or d + 1 already), find
    /// the first copy t_a = u and the last t_b = u, and cut: the left piece has ĉ₀, …, ĉ_{a−1}
    /// on t₀, …, t_{a+d−1}, u; the right piece ĉ_{b−d}, …, ĉ_{n̂−1} on u, t_{b−d+1}, …
    /// (ĉ_{b−d} = ĉ_{a−1} = s(u) at multiplicity d, and the right limit at multiplicity
    /// d + 1) [PPB, §6.1].
    ///
    /// Follows [PPB, §6.1].
    ///
    /// # Errors
    ///
    /// As [`BSpline::split`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d²)D) time, O((n + d²)D) space.
    ///
    /// # Counts
    ///
    /// Those of [`BSpline::insert_with`] inserting d − s copies of a knot of multiplicity s:
    /// (d − s)(d − s + 1)/2 [`arithmetic_operation`](Counter::arithmetic_operation)s (d(d + 1)/2
    /// at a parameter that is not a knot, none at a knot of multiplicity d or more), and the
    /// span search's [`comparison`](Counter::comparison)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 6, 0.0, 3.0)?;
    /// let s = BSpline::new((0..6).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let (l, r) = s.split_with(&0.5, &mut c)?;
    /// assert_eq!((c.arithmetic_operations, l.control().len(), r.control().len()), (6, 4, 6));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_with<C: Counter>(&self, u: &S, counter: &mut C) -> Result<(Self, Self)> {
        validate_parameter(u, "u")?;
        let knots = self.knots();
        let (start, end) = knots.bounds();
        if u <= start || u >= end {
            return Err(Error::InvalidParameter {
                name: "u",
                reason: format!(
                    "a split needs a parameter inside the domain ({}, {}), got {} (at an end \
                     one piece would be empty)",
                    start.to_f64(),
                    end.to_f64(),
                    u.to_f64()
                ),
            });
        }
        let d = self.degree();
        let s = knots.multiplicity(u);
        let refined = self.insert_with(u, d.saturating_sub(s), counter)?;
        let t = refined.knots().knots();
        let c = refined.control();
        let a = t.partition_point(|k| k < u);
        let b = t.partition_point(|k| k <= u) - 1;

        let mut left_knots = t[..a + d].to_vec();
        left_knots.push(u.clone());
        let left = BSpline::derived(
            c[..a].to_vec(),
            KnotVector::new(d, left_knots)?,
            "B-spline split",
        )?;
        let mut right_knots = Vec::with_capacity(t.len() - b + d);
        right_knots.push(u.clone());
        right_knots.extend_from_slice(&t[b + 1 - d..]);
        let right = BSpline::derived(
            c[b - d..].to_vec(),
            KnotVector::new(d, right_knots)?,
            "B-spline split",
        )?;
        Ok((left, right))
    }
}

/// The piece over [a, b] by two splits: at a (unless it is t_d) keeping the right part, then
/// at b (unless it is t_n) keeping the left part. Knots stay where they were (the parameter
/// is kept); the cut ends are clamped.
impl<S: Scalar, const D: usize> Subsegment<S, D> for BSpline<S, D> {
    type Segment = BSpline<S, D>;

    /// The piece over [a, b] ⊆ [t_d, t_n] as a B-spline of the same degree on the knots of
    /// [a, b], d + 1 copies of a cut end: [`BSpline::split`] at a and at b. At a knot of
    /// multiplicity d + 1 (a jump), the piece starting there starts with the right limit and
    /// the piece ending there ends with the left one.
    ///
    /// # Errors
    ///
    /// As [`Subsegment::subsegment`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d²)D) time and space, two splits.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point, Subsegment};
    ///
    /// let t = KnotVector::clamped_uniform(2, 5, 0.0, 3.0)?;
    /// let c = [0.0, 2.0, -1.0, 3.0, 1.0].map(|x| Point::new([x])).to_vec();
    /// let s = BSpline::new(c, t)?;
    /// let piece = s.subsegment(&0.5, &2.0)?;
    /// assert_eq!(piece.knots().knots(), [0.5, 0.5, 0.5, 1.0, 2.0, 2.0, 2.0]);
    /// assert_eq!(piece.eval(&1.25)?, s.eval(&1.25)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn subsegment(&self, a: &S, b: &S) -> Result<Self> {
        check_interval(&self.knots().domain(), a, b)?;
        let (start, end) = self.knots().bounds();
        let from_a = if a > start {
            self.split(a)?.1
        } else {
            self.clone()
        };
        if b < end {
            Ok(from_a.split(b)?.0)
        } else {
            Ok(from_a)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::{Curve, Point};

    #[test]
    fn a_jump_knot_splits_into_the_two_limits() {
        let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).unwrap();
        let c = [0.0, 1.0, 5.0, 6.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        let (l, r) = s.split(&1.0).unwrap();
        assert_eq!(l.control(), [0.0, 1.0].map(|x| Point::new([x])));
        assert_eq!(r.control(), [5.0, 6.0].map(|x| Point::new([x])));
        assert_eq!(l.eval(&1.0).unwrap(), Point::new([1.0]));
        assert_eq!(r.eval(&1.0).unwrap(), Point::new([5.0]));
        // Degree 0: no insertion, the pieces are the two sides.
        let t = KnotVector::new(0, vec![0.0, 1.0, 2.0, 3.0]).unwrap();
        let s = BSpline::new([4.0, 5.0, 6.0].map(|x| Point::new([x])).to_vec(), t).unwrap();
        let (l, r) = s.split(&1.5).unwrap();
        assert_eq!(l.knots().knots(), [0.0, 1.0, 1.5]);
        assert_eq!(r.knots().knots(), [1.5, 2.0, 3.0]);
        assert_eq!(l.control().len() + r.control().len(), 4);
        assert!(s.split(&f64::NAN).is_err() && s.split(&0.0).is_err());
    }
}
