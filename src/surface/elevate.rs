//! Degree elevation of a Bézier patch in u, in v, or to any bidegree.
//!
//! The problem: the net of bidegree (p, q) ≥ (m, n) that describes the same surface. The
//! idea: elevating in u is elevating every column's curve, in v every row's
//! [FJ-surfaces, §5, eqs. (14)–(15)], [PPB, §9.2]; the curve code does it in one step to
//! any degree by Zhou's formula [PPB, §3.12] (to one degree more that is the familiar
//! c_{i,j}^{1,0} = (1 − i/(m + 1)) c_{i,j} + i/(m + 1) c_{i−1,j}).
//!
//! # Complexity
//!
//! Θ(((n + 1)(m + 1)(p − m + 1) + (p + 1)(n + 1)(q − n + 1))D) time to bidegree (p, q), each
//! direction only if its degree grows; Θ(pqD) space for the result.
//!
//! Invariants the tests check (exactly on rationals): the elevated patch evaluates to the
//! original, and elevating a bilinear patch reproduces its values at (i/p, j/q) (bilinear
//! precision, [PPB, §9.4, Obs. 5]).

use super::bezier::BezierPatch;
use super::subdivide::from_columns;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::Scalar;
use crate::{limits, Error, Result};

/// Degree elevation to a bidegree, declared.
pub(crate) const ELEVATE_TO: Declaration = Declaration {
    problem: "bezier-patch",
    name: "elevate-to",
    function: "surface::BezierPatch::elevate_to",
    file: "src/surface/elevate.rs",
    summary: "every column elevated to degree p, then every row to q (Zhou's formula)",
    time: "Θ(((n + 1)(m + 1)(p − m + 1) + (p + 1)(n + 1)(q − n + 1))D)",
    space: "Θ(pqD)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "exactly (n + 1)(m + 1)(p − m + 1) terms if p > m, plus (p + 1)(n + 1)(q − n + 1) if q > n",
    source: "[FJ-surfaces, §5], [PPB, §3.12]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The same surface with bidegree (m + 1, n): every column elevated by one
    /// [FJ-surfaces, §5, eq. (14)]. See [`BezierPatch::elevate_to_with`].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::elevate_to`].
    ///
    /// # Complexity
    ///
    /// Θ(mnD) time and space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..2).map(|i| (0..2).map(|j| Point::new([(2 * i) as f64, j as f64])).collect()).collect();
    /// let e = BezierPatch::new(ControlNet::new(rows)?)?.elevate_u()?;
    /// assert_eq!(e.bidegree(), (2, 1));
    /// assert_eq!(e.net().get(1, 1), &Point::new([1.0, 1.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_u(&self) -> Result<Self> {
        self.elevate_u_with(&mut NoCount)
    }

    /// [`BezierPatch::elevate_u`], counting as [`BezierPatch::elevate_to_with`]: exactly
    /// 2(n + 1)(m + 1) terms.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::elevate_to`].
    ///
    /// # Complexity
    ///
    /// Θ(mnD) time and space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let mut c = Counts::default();
    /// BezierPatch::new(ControlNet::new(rows)?)?.elevate_u_with(&mut c)?;
    /// assert_eq!(c.arithmetic_operations, 2 * 4 * 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_u_with<C: Counter>(&self, counter: &mut C) -> Result<Self> {
        let (m, n) = self.bidegree();
        self.elevate_to_with(m + 1, n, counter)
    }

    /// The same surface with bidegree (m, n + 1): every row elevated by one
    /// [FJ-surfaces, §5, eq. (15)]. See [`BezierPatch::elevate_to_with`].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::elevate_to`].
    ///
    /// # Complexity
    ///
    /// Θ(mnD) time and space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..2).map(|i| (0..2).map(|j| Point::new([i as f64, (2 * j) as f64])).collect()).collect();
    /// let e = BezierPatch::new(ControlNet::new(rows)?)?.elevate_v()?;
    /// assert_eq!(e.bidegree(), (1, 2));
    /// assert_eq!(e.net().get(0, 1), &Point::new([0.0, 1.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_v(&self) -> Result<Self> {
        self.elevate_v_with(&mut NoCount)
    }

    /// [`BezierPatch::elevate_v`], counting as [`BezierPatch::elevate_to_with`]: exactly
    /// 2(m + 1)(n + 1) terms.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::elevate_to`].
    ///
    /// # Complexity
    ///
    /// Θ(mnD) time and space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let mut c = Counts::default();
    /// BezierPatch::new(ControlNet::new(rows)?)?.elevate_v_with(&mut c)?;
    /// assert_eq!(c.arithmetic_operations, 2 * 3 * 4);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_v_with<C: Counter>(&self, counter: &mut C) -> Result<Self> {
        let (m, n) = self.bidegree();
        self.elevate_to_with(m, n + 1, counter)
    }

    /// The same surface with bidegree (p, q), p ≥ m and q ≥ n. See
    /// [`BezierPatch::elevate_to_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"degree"` if p < m or q < n (that would be degree
    /// reduction, an approximation); [`Error::LimitExceeded`] if p or q exceeds
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) or the net would exceed
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS), before anything is computed;
    /// [`Error::Overflow`] if, with `f64`, rounding carries a point beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)(m + 1)(p − m + 1) + (p + 1)(n + 1)(q − n + 1))D) time, Θ(pqD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let rows = (0..2).map(|i| (0..3).map(|j| Point::new([i as f64, (j * j) as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?;
    /// let e = s.elevate_to(3, 4)?;
    /// assert_eq!(e.bidegree(), (3, 4));
    /// assert_eq!(e.eval(&0.5, &0.25)?, s.eval(&0.5, &0.25)?);
    /// assert!(s.elevate_to(0, 4).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_to(&self, p: usize, q: usize) -> Result<Self> {
        self.elevate_to_with(p, q, &mut NoCount)
    }

    /// The same surface with bidegree (p, q), counting the terms of Zhou's formula.
    ///
    /// Idea: the columns are curves of degree m in u; elevated to degree p by the curve
    /// code they are the columns of a net of bidegree (p, n) of the same surface (the
    /// Bernstein polynomials in v are untouched); then every row of that net is elevated to
    /// q in v [FJ-surfaces, §5], [PPB, §3.12].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::elevate_to`].
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)(m + 1)(p − m + 1) + (p + 1)(n + 1)(q − n + 1))D) time, Θ(pqD) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per term of Zhou's sums: a
    /// curve of degree n elevated to m has (n + 1)(m − n + 1); so exactly
    /// (n + 1)(m + 1)(p − m + 1) if p > m (none otherwise), plus (p + 1)(n + 1)(q − n + 1)
    /// if q > n.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let mut c = Counts::default();
    /// BezierPatch::new(ControlNet::new(rows)?)?.elevate_to_with(4, 3, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 4 * 3 * 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_to_with<C: Counter>(&self, p: usize, q: usize, counter: &mut C) -> Result<Self> {
        let (m, n) = self.bidegree();
        if p < m || q < n {
            return Err(Error::InvalidParameter {
                name: "degree",
                reason: format!("cannot elevate a patch of bidegree ({m}, {n}) to ({p}, {q})"),
            });
        }
        limits::DEGREE.check(p as u128)?;
        limits::DEGREE.check(q as u128)?;
        limits::POINTS.check((p as u128 + 1) * (q as u128 + 1))?;
        let mut patch = self.clone();
        if p > m {
            let columns: Vec<_> = patch
                .column_curves()
                .iter()
                .map(|column| column.elevate_to_counted(p, counter))
                .collect();
            patch = BezierPatch::derived(p + 1, n + 1, from_columns(&columns), "degree elevation")?;
        }
        if q > n {
            let points = patch
                .row_curves()?
                .iter()
                .flat_map(|row| row.elevate_to_counted(q, counter))
                .collect();
            patch = BezierPatch::derived(p + 1, q + 1, points, "degree elevation")?;
        }
        Ok(patch)
    }
}
