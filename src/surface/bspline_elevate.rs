//! Degree elevation of a B-spline surface in u or in v, through the curve code.
//!
//! The problem: the same surface with the degree in one parameter raised by t. The idea
//! [PPB, §6.4–6.5, §9.1]: elevation in v changes only the basis in v, so it is the curves'
//! degree elevation ([`BSpline::elevate_with`]) on every row, all on the same knots and so
//! with the same new knots; in u the same on every column.
//!
//! # Complexity
//!
//! In v: Θ(M(N + Q·t)(q + t)²·D) for Q non-empty spans; in u the roles exchanged plus
//! Θ(MN·D) to build the columns.

use super::bspline::BSplineSurface;
use super::direction::Direction;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::Scalar;
use crate::Result;

/// Degree elevation of a B-spline surface, declared.
pub(crate) const SURFACE_ELEVATE: Declaration = Declaration {
    problem: "bspline-surface",
    name: "elevate",
    function: "surface::BSplineSurface::elevate",
    file: "src/surface/bspline_elevate.rs",
    summary: "the curves' degree elevation on every row (v) or column (u)",
    time: "Θ(M(N + Q·t)(q + t)²·D) in v",
    space: "Θ(M(N + Q·t)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "M times the curve elevation's in v (N times in u)",
    source: "[PPB, §6.4–6.5, §9.1]",
    claims: &[on(
        "random-net",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The same surface with the degree in `direction` raised by `times`. See
    /// [`BSplineSurface::elevate_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::elevate`](crate::spline::BSpline::elevate):
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded),
    /// [`Error::Overflow`](crate::Error::Overflow).
    ///
    /// # Complexity
    ///
    /// Θ(M(N + Q·t)(q + t)²·D) in v; in u the roles exchanged plus Θ(MN·D). Θ(M(N + Q·t)D)
    /// space in v.
    pub fn elevate(&self, direction: Direction, times: usize) -> Result<Self> {
        self.elevate_with(direction, times, &mut NoCount)
    }

    /// The same surface with the degree in `direction` raised by `times`, counting the
    /// arithmetic.
    ///
    /// Idea: the curves' elevation on every curve of that direction [PPB, §6.4–6.5, §9.1].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::elevate`].
    ///
    /// # Complexity
    ///
    /// As [`BSplineSurface::elevate`].
    ///
    /// # Counts
    ///
    /// Those of [`BSpline::elevate_with`](crate::spline::BSpline::elevate_with) on each curve.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Direction, Surface};
    ///
    /// let net = ControlNet::new((0..3).map(|i| (0..2).map(|j| Point::new([i as f64, j as f64, (i * j) as f64])).collect()).collect())?;
    /// let s = BSplineSurface::new(net, KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?, KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// let e = s.elevate_with(Direction::V, 2, &mut Counts::default())?;
    /// assert_eq!(e.bidegree(), (2, 3));
    /// assert_eq!(e.eval(&0.5, &0.5)?, s.eval(&0.5, &0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_with<C: Counter>(
        &self,
        direction: Direction,
        times: usize,
        counter: &mut C,
    ) -> Result<Self> {
        let curves = self
            .curves(direction)?
            .iter()
            .map(|c| c.elevate_with(times, counter))
            .collect::<Result<Vec<_>>>()?;
        self.with_curves(direction, curves)
    }
}
