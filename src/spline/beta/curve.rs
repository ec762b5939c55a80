//! Cubic Beta-spline curves: a control polygon and shape parameters, evaluated segment by
//! segment.
//!
//! The problem: the point of an open, uniformly shaped cubic Beta-spline with control points
//! P₀, …, P_{n−1} (n ≥ 4) at a parameter u of its domain [0, m], m = n − 3 segments. The
//! idea: segment i (i = 0, …, m − 1) is Qᵢ(t) = Σⱼ Bⱼ(t) P_{i+j}, t in [0, 1], so u is split
//! into the segment i = ⌊u⌋ (the last segment for u = m), found by bisection over the
//! integers, and the local t = u − i; the four basis values are combined with the four
//! points [CCKS, §3].
//!
//! Follows [CCKS, §3].
//!
//! # Complexity
//!
//! O(log m) comparisons to find the segment, then O(D) (exactly 20 arithmetic operations
//! and D coordinates per point); O(D) space.
//!
//! Invariants the tests check (exactly on rationals): with β₁ = 1, β₂ = 0 the curve is the
//! uniform cubic B-spline of [`BSpline`](crate::spline::BSpline); consecutive segments join
//! with β-continuity.

use super::{is_beta_continuous, BetaParameters};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::curve::{Curve, Domain};
use crate::spline::scalar::{validate_parameter, validate_points, Point, Scalar};
use crate::{Error, Result};

/// Evaluation, declared.
pub(crate) const EVAL: Declaration = Declaration {
    problem: "beta-spline",
    name: "eval",
    function: "spline::BetaSpline::eval",
    file: "src/spline/beta/curve.rs",
    summary: "the point at u: the segment ⌊u⌋ by bisection, then the four basis values times the four control points",
    time: "O(log m + D)",
    space: "O(D)",
    operation: Some(Operation::Comparisons),
    counts: "⌊lg m⌋ or ⌈lg m⌉ comparisons to find the segment, then exactly 20 arithmetic operations",
    source: "[CCKS, §3]",
    claims: &[on("random-control", Bound::Log, Operation::Comparisons)],
};

/// An open cubic Beta-spline: a control polygon of n ≥ 4 points of R^D and its shape
/// parameters; segment i uses the points i, …, i + 3 [CCKS, §3].
///
/// ```
/// use compgeo::spline::{BetaParameters, BetaSpline, Point};
///
/// let p = BetaParameters::new(1.0, 0.0)?;
/// let s = BetaSpline::new(p, [0.0, 6.0, 12.0, 18.0, 24.0].map(|x| Point::new([x])).to_vec())?;
/// assert_eq!(s.segments(), 2);
/// assert_eq!(s.eval(&1.0)?, Point::new([12.0])); // a straight polygon: linear precision
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BetaSpline<S, const D: usize> {
    parameters: BetaParameters<S>,
    control: Vec<Point<S, D>>,
}

impl<S: Scalar, const D: usize> BetaSpline<S, D> {
    /// The curve with these parameters and control points.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] or [`Error::TooFew`] (`"Beta-spline control polygon"`) for fewer than
    /// four points; [`Error::NonFinite`] naming the first point with a NaN or infinite
    /// coordinate.
    pub fn new(parameters: BetaParameters<S>, control: Vec<Point<S, D>>) -> Result<Self> {
        validate_points(&control, "Beta-spline control polygon")?;
        if control.len() < 4 {
            return Err(Error::TooFew {
                what: "Beta-spline control polygon",
                needed: 4,
                got: control.len(),
            });
        }
        Ok(BetaSpline {
            parameters,
            control,
        })
    }

    /// The shape parameters.
    pub fn parameters(&self) -> &BetaParameters<S> {
        &self.parameters
    }

    /// The control points.
    pub fn control(&self) -> &[Point<S, D>] {
        &self.control
    }

    /// The number of segments, m = n − 3; the domain is [0, m].
    pub fn segments(&self) -> usize {
        self.control.len() - 3
    }

    /// The four control points of segment `i`.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"segment"` if `i ≥ m`.
    pub fn segment(&self, i: usize) -> Result<[Point<S, D>; 4]> {
        if i >= self.segments() {
            return Err(Error::InvalidParameter {
                name: "segment",
                reason: format!("the curve has {} segments, got index {i}", self.segments()),
            });
        }
        Ok(std::array::from_fn(|j| self.control[i + j].clone()))
    }

    /// Qᵢ(t) = Σⱼ Bⱼ(t) P_{i+j}, segment `i` at its local parameter `t` (any finite t; on
    /// [0, 1] the segment itself).
    ///
    /// # Errors
    ///
    /// As [`BetaSpline::segment`]; [`Error::InvalidParameter`] named `"t"` if `t` is NaN or
    /// infinite.
    pub fn eval_segment(&self, i: usize, t: &S) -> Result<Point<S, D>> {
        self.eval_segment_with(i, t, &mut NoCount)
    }

    fn eval_segment_with<C: Counter>(
        &self,
        i: usize,
        t: &S,
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        let polygon = self.segment(i)?;
        let b = self.parameters.basis_with(t, counter)?;
        let mut p = Point::zero();
        for (w, q) in b.iter().zip(&polygon) {
            counter.arithmetic_operation();
            p += &(q.clone() * w);
        }
        Ok(p)
    }

    /// Qᵢ(t), Qᵢ′(t) and Qᵢ″(t): segment `i`'s point and first two derivatives at `t`.
    ///
    /// # Errors
    ///
    /// As [`BetaSpline::eval_segment`].
    pub fn segment_derivatives(&self, i: usize, t: &S) -> Result<[Point<S, D>; 3]> {
        let polygon = self.segment(i)?;
        let d = self.parameters.basis_derivatives(t)?;
        Ok(d.map(|row| {
            let mut p = Point::zero();
            for (w, q) in row.iter().zip(&polygon) {
                p += &(q.clone() * w);
            }
            p
        }))
    }

    /// The point at `u` in [0, m]. See [`BetaSpline::eval_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN, infinite or outside [0, m].
    ///
    /// # Complexity
    ///
    /// O(log m + D) time, O(D) space.
    ///
    /// ```
    /// use compgeo::spline::{BetaParameters, BetaSpline, Point};
    ///
    /// let p = BetaParameters::new(2.0, 1.0)?;
    /// let c = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0), (5.0, 1.0)];
    /// let s = BetaSpline::new(p, c.map(|(x, y)| Point::new([x, y])).to_vec())?;
    /// assert_eq!(s.eval(&1.0)?, s.eval_segment(1, &0.0)?);
    /// assert!(s.eval(&2.5).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval(&self, u: &S) -> Result<Point<S, D>> {
        self.eval_with(u, &mut NoCount)
    }

    /// The point at `u`, counting the bisection's comparisons and the arithmetic.
    ///
    /// Idea: bisection over the integers 0, …, m finds the segment i with i ≤ u < i + 1
    /// (i = m − 1 at u = m), then segment i is evaluated at t = u − i [CCKS, §3].
    ///
    /// Follows [CCKS, §3].
    ///
    /// # Errors
    ///
    /// As [`BetaSpline::eval`].
    ///
    /// # Complexity
    ///
    /// O(log m + D) time, O(D) space.
    ///
    /// # Counts
    ///
    /// ⌊lg m⌋ or ⌈lg m⌉ [`comparison`](Counter::comparison)s (none for one segment), then
    /// exactly 20 [`arithmetic_operation`](Counter::arithmetic_operation)s (16 for the basis,
    /// 4 point combinations).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BetaParameters, BetaSpline, Point};
    ///
    /// let p = BetaParameters::new(1.0, 2.0)?;
    /// let s = BetaSpline::new(p, (0..11).map(|i| Point::new([i as f64])).collect())?;
    /// let mut c = Counts::default();
    /// s.eval_with(&5.5, &mut c)?;
    /// assert_eq!((c.comparisons, c.arithmetic_operations), (3, 20)); // m = 8 segments
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_with<C: Counter>(&self, u: &S, counter: &mut C) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        let m = self.segments();
        let end = S::from_i64(m as i64);
        if *u < S::zero() || *u > end {
            return Err(Error::InvalidParameter {
                name: "u",
                reason: format!("must lie in the domain [0, {m}], got {}", u.to_f64()),
            });
        }
        // Invariant: lo ≤ u, and u < hi or hi = m.
        let (mut lo, mut hi) = (0usize, m);
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            counter.comparison();
            if *u >= S::from_i64(mid as i64) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let t = u.clone() - S::from_i64(lo as i64);
        self.eval_segment_with(lo, &t, counter)
    }

    /// `true` if the end of this curve (its last segment at t = 1) and the start of `next`
    /// (its first segment at t = 0) meet with β-continuity for this curve's parameters: see
    /// [`is_beta_continuous`]. Exact for rationals; in `f64` the comparison is exact too, so
    /// rounding can make a continuous join fail.
    ///
    /// # Errors
    ///
    /// None in practice (both segments exist); the `Result` is that of the derivatives.
    ///
    /// ```
    /// use compgeo::spline::{BetaParameters, BetaSpline, Point};
    /// use num_rational::BigRational as Q;
    ///
    /// let q = |n: i64| Q::from_integer(n.into());
    /// let p = BetaParameters::new(q(2), q(3))?;
    /// let pts: Vec<_> = [0, 1, 4, 9, 16].iter().map(|&y| Point::new([q(y), q(y * y)])).collect();
    /// let whole = BetaSpline::new(p.clone(), pts.clone())?;
    /// // Two curves sharing three control points join as the segments of one curve do.
    /// let a = BetaSpline::new(p.clone(), pts[..4].to_vec())?;
    /// let b = BetaSpline::new(p, pts[1..].to_vec())?;
    /// assert!(a.joins_beta_continuously(&b)?);
    /// assert!(!b.joins_beta_continuously(&a)?);
    /// # let _ = whole;
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn joins_beta_continuously(&self, next: &Self) -> Result<bool> {
        let left = self.segment_derivatives(self.segments() - 1, &S::one())?;
        let right = next.segment_derivatives(0, &S::zero())?;
        Ok(is_beta_continuous(&left, &right, &self.parameters))
    }
}

/// The curve traits' view: the domain [0, m] and [`BetaSpline::eval`].
///
/// ```
/// use compgeo::spline::{BetaParameters, BetaSpline, Curve, Domain, Point};
///
/// let p = BetaParameters::new(1.0, 1.0)?;
/// let s = BetaSpline::new(p, (0..6).map(|i| Point::new([i as f64, 0.0])).collect())?;
/// assert_eq!(Curve::domain(&s), Domain::Interval { start: 0.0, end: 3.0 });
/// # Ok::<(), compgeo::Error>(())
/// ```
impl<S: Scalar, const D: usize> Curve<S, D> for BetaSpline<S, D> {
    fn domain(&self) -> Domain<S> {
        Domain::Interval {
            start: S::zero(),
            end: S::from_i64(self.segments() as i64),
        }
    }

    fn eval(&self, t: &S) -> Result<Point<S, D>> {
        BetaSpline::eval(self, t)
    }
}
