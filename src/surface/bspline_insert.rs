//! Knot insertion and refinement of a B-spline surface in u or in v, through the curve code.
//!
//! The problem: the same surface on a knot vector with more knots in one parameter. The idea
//! [PPB, §6.1, §9.1]: inserting a knot in v changes only the basis in v, so it is Boehm's
//! insertion ([`BSpline::insert_with`]) on every row of the net, all rows on the same knots
//! and so with the same new knot vector; in u, the same on every column. Refinement inserts
//! many knots at once ([`BSpline::refine_with`]) the same way.
//!
//! # Complexity
//!
//! In v: M times the curve's cost, Θ(M(N + q + rq)D) for a knot inserted r times and
//! O(M(m log m + log N + (N + m + mq)D)) to refine by m knots; in u the same with the roles
//! exchanged, plus Θ(MN·D) to build the columns.

use super::bspline::{rename, BSplineSurface};
use super::direction::Direction;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::Scalar;
use crate::Result;

/// Knot insertion into a B-spline surface, declared.
pub(crate) const SURFACE_INSERT: Declaration = Declaration {
    problem: "bspline-surface",
    name: "insert",
    function: "surface::BSplineSurface::insert",
    file: "src/surface/bspline_insert.rs",
    summary: "Boehm's insertion on every row (v) or every column (u) of the net",
    time: "Θ(M(N + q + rq)D) in v",
    space: "Θ(M(N + r)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "M times the curve's r(q − s) − r(r − 1)/2 affine combinations in v (N times, with p, in u)",
    source: "[PPB, §6.1, §9.1]",
    claims: &[on(
        "random-net",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// Knot refinement of a B-spline surface, declared.
pub(crate) const SURFACE_REFINE: Declaration = Declaration {
    problem: "bspline-surface",
    name: "refine",
    function: "surface::BSplineSurface::refine",
    file: "src/surface/bspline_insert.rs",
    summary: "Boehm's insertions of many knots in one pass on every row (v) or column (u)",
    time: "O(M(m log m + log N + (N + m + mq)D)) in v",
    space: "Θ(M(N + m)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "M times the curve refinement's affine combinations in v (N times in u)",
    source: "[PPB, §6.1–6.2, §9.1]",
    claims: &[on(
        "random-net",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The same surface with the knot `t` inserted `times` times in `direction`. See
    /// [`BSplineSurface::insert_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::insert`](crate::spline::BSpline::insert), with the parameter named `"u"`
    /// or `"v"`: [`Error::InvalidParameter`](crate::Error::InvalidParameter) for a knot that
    /// is NaN, infinite or outside the domain, or a multiplicity past the degree + 1;
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded),
    /// [`Error::Overflow`](crate::Error::Overflow).
    ///
    /// # Complexity
    ///
    /// Θ(M(N + q + rq)D) in v, Θ(N(M + p + rp)D + MN·D) in u; Θ(M(N + r)D) space in v.
    pub fn insert(&self, direction: Direction, t: &S, times: usize) -> Result<Self> {
        self.insert_with(direction, t, times, &mut NoCount)
    }

    /// The same surface with the knot `t` inserted `times` times in `direction`, counting
    /// the affine combinations.
    ///
    /// Idea: Boehm's insertion on every curve of that direction (the rows for v, the columns
    /// for u), all on the same knots, so all get the same new knots [PPB, §6.1, §9.1].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::insert`].
    ///
    /// # Complexity
    ///
    /// Θ(M(N + q + rq)D) in v, Θ(N(M + p + rp)D + MN·D) in u.
    ///
    /// # Counts
    ///
    /// Those of [`BSpline::insert_with`](crate::spline::BSpline::insert_with) on each curve.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Direction, Surface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64, (i * j) as f64])).collect()).collect())?;
    /// let s = BSplineSurface::new(net, KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?, KnotVector::clamped_uniform(3, 4, 0.0, 1.0)?)?;
    /// let mut c = Counts::default();
    /// let r = s.insert_with(Direction::V, &0.5, 1, &mut c)?;
    /// assert_eq!((r.net().rows(), r.net().columns()), (3, 5));
    /// assert_eq!(c.arithmetic_operations, 3 * 3); // three per row
    /// assert_eq!(r.eval(&0.25, &0.75)?, s.eval(&0.25, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn insert_with<C: Counter>(
        &self,
        direction: Direction,
        t: &S,
        times: usize,
        counter: &mut C,
    ) -> Result<Self> {
        let curves = self
            .curves(direction)?
            .iter()
            .map(|c| rename(c.insert_with(t, times, counter), direction.name()))
            .collect::<Result<Vec<_>>>()?;
        self.with_curves(direction, curves)
    }

    /// The same surface with the knots `new_knots` (sorted or not, repeats allowed) inserted
    /// in `direction`. See [`BSplineSurface::refine_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::refine`](crate::spline::BSpline::refine), with the knots named `"u"` or
    /// `"v"`.
    ///
    /// # Complexity
    ///
    /// O(M(m log m + log N + (N + m + mq)D)) in v for m new knots; in u the roles exchanged
    /// plus Θ(MN·D); Θ(M(N + m)D) space in v.
    pub fn refine(&self, direction: Direction, new_knots: &[S]) -> Result<Self> {
        self.refine_with(direction, new_knots, &mut NoCount)
    }

    /// The same surface with the knots `new_knots` inserted in `direction`, counting the
    /// affine combinations.
    ///
    /// Idea: the curve refinement ([`BSpline::refine_with`](crate::spline::BSpline::refine_with))
    /// on every curve of that direction [PPB, §6.1–6.2, §9.1].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::refine`].
    ///
    /// # Complexity
    ///
    /// As [`BSplineSurface::refine`].
    ///
    /// # Counts
    ///
    /// Those of the curve refinement on each curve.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Direction, Surface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64, (i + j) as f64])).collect()).collect())?;
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = BSplineSurface::new(net, t.clone(), t)?;
    /// let r = s.refine_with(Direction::U, &[0.25, 0.5, 0.5], &mut Counts::default())?;
    /// assert_eq!(r.u_knots().knots(), [0.0, 0.0, 0.0, 0.25, 0.5, 0.5, 1.0, 1.0, 1.0]);
    /// assert_eq!(r.eval(&0.375, &0.5)?, s.eval(&0.375, &0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn refine_with<C: Counter>(
        &self,
        direction: Direction,
        new_knots: &[S],
        counter: &mut C,
    ) -> Result<Self> {
        let curves = self
            .curves(direction)?
            .iter()
            .map(|c| rename(c.refine_with(new_knots, counter), direction.name()))
            .collect::<Result<Vec<_>>>()?;
        self.with_curves(direction, curves)
    }
}
