//! Tensor-product Bézier patches: the type, evaluation in either order and by the tensor de
//! Casteljau algorithm, isoparametric curves, and partial derivatives through the curve code.
//!
//! The problem: c(u, v) = Σᵢ Σⱼ c_{i,j} Bᵢᵐ(u) Bⱼⁿ(v) for a net of (m + 1) × (n + 1) points
//! [FJ-surfaces, §2, eq. (1)], [PPB, §9.2]. The idea: with v fixed, each row i of the net is
//! the control polygon of a Bézier curve in v, whose point at v is the i-th control point of
//! the curve c(·, v) of degree m in u; so the patch is evaluated by n-curves on the rows and
//! one m-curve on the results (rows first), or the other way round (columns first): the same
//! point, by the symmetry of the double sum (exactly equal with rationals). The tensor de
//! Casteljau algorithm [PPB, §9.5] instead runs min(m, n) levels of bilinear interpolation on
//! the whole net, then finishes the longer direction with univariate levels.
//!
//! The isoparametric curves are Bézier curves of the crate ([`BezierPatch::curve_at_u`],
//! [`BezierPatch::curve_at_v`]), and partial derivatives are derivatives of those curves
//! [FJ-surfaces, §5]: ∂^{r+s}c/∂u^r∂v^s(u, v) is the r-th derivative in u of the curve whose
//! control points are the s-th derivatives in v of the rows.
//!
//! # Complexity
//!
//! For bidegree (m, n) in R^D: [`Surface::eval`] is the tensor de Casteljau algorithm; rows
//! first by de Casteljau Θ((m + 1)n² + m²)·D, columns
//! first Θ((n + 1)m² + n²)·D, the tensor de Casteljau Θ(mn·min(m, n) + |m − n|²)·D; O((m +
//! n)D) auxiliary space beyond a copy of the net.
//!
//! Invariants the tests check (exactly on rationals): both orders and the tensor scheme
//! agree; the isoparametric curves interpolate the surface; the partial derivatives equal
//! differences of blossoms.

use super::net::ControlNet;
use super::traits::{Surface, SurfaceDerivative, SurfaceDomain};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::de_casteljau_levels;
use crate::spline::{validate_parameter, Bezier, CurveDerivative, Domain, Point, Scalar};
use crate::{limits, Error, Result};

/// Evaluation of a Bézier patch row by row, declared.
pub(crate) const ROWS_FIRST: Declaration = Declaration {
    problem: "bezier-patch",
    name: "rows-first",
    function: "surface::BezierPatch::rows_first",
    file: "src/surface/bezier.rs",
    summary: "de Casteljau in v on every row, then in u on the row points",
    time: "Θ(((m + 1)n² + m²)D)",
    space: "O((m + n)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (m + 1)n(n + 1)/2 + m(m + 1)/2 affine combinations",
    source: "[FJ-surfaces, §2], [PPB, §9.2]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// Evaluation of a Bézier patch column by column, declared.
pub(crate) const COLUMNS_FIRST: Declaration = Declaration {
    problem: "bezier-patch",
    name: "columns-first",
    function: "surface::BezierPatch::columns_first",
    file: "src/surface/bezier.rs",
    summary: "de Casteljau in u on every column, then in v on the column points",
    time: "Θ(((n + 1)m² + n²)D)",
    space: "O((m + n)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)m(m + 1)/2 + n(n + 1)/2 affine combinations",
    source: "[FJ-surfaces, §2], [PPB, §9.2]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// The tensor de Casteljau algorithm, declared.
pub(crate) const TENSOR_DE_CASTELJAU: Declaration = Declaration {
    problem: "bezier-patch",
    name: "de-casteljau",
    function: "surface::BezierPatch::de_casteljau",
    file: "src/surface/bezier.rs",
    summary: "min(m, n) levels of bilinear interpolation on the net, then univariate levels in the longer direction",
    time: "Θ((mn·min(m, n) + |m − n|²)D)",
    space: "Θ(mn·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "three affine combinations per bilinear step, Σₖ₌₁ᵏ (m − k + 1)(n − k + 1) steps for k = min(m, n), then the univariate ones",
    source: "[PPB, §9.5]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// A tensor-product Bézier patch of bidegree (m, n) in R^D: the surface of a
/// [`ControlNet`] of (m + 1) × (n + 1) points, defined for every real (u, v).
///
/// ```
/// use compgeo::spline::Point;
/// use compgeo::surface::{BezierPatch, ControlNet, Surface};
///
/// // Bidegree (2, 1): the rows are lines in v, the columns parabolas in u.
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let net = ControlNet::new(vec![
///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
///     vec![p(1.0, 0.0, 2.0), p(1.0, 1.0, 2.0)],
///     vec![p(2.0, 0.0, 0.0), p(2.0, 1.0, 0.0)],
/// ])?;
/// let s = BezierPatch::new(net)?;
/// assert_eq!(s.bidegree(), (2, 1));
/// assert_eq!(s.eval(&0.5, &0.5)?, p(1.0, 0.5, 1.0));
/// assert_eq!(s.rows_first(&0.5, &0.5)?, s.columns_first(&0.5, &0.5)?);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BezierPatch<S, const D: usize> {
    net: ControlNet<S, D>,
}

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The patch of a control net, of bidegree (rows − 1, columns − 1).
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if a degree exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
    pub fn new(net: ControlNet<S, D>) -> Result<Self> {
        limits::DEGREE.check(net.rows() as u128 - 1)?;
        limits::DEGREE.check(net.columns() as u128 - 1)?;
        Ok(BezierPatch { net })
    }

    /// The control net.
    pub fn net(&self) -> &ControlNet<S, D> {
        &self.net
    }

    /// The bidegree (m, n): m in u, n in v.
    pub fn bidegree(&self) -> (usize, usize) {
        (self.net.rows() - 1, self.net.columns() - 1)
    }

    /// The point c(u, v) by de Casteljau's algorithm in v on every row, then in u on the
    /// m + 1 row points. See [`BezierPatch::rows_first_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` or `"v"` if a parameter is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(((m + 1)n² + m²)D) time, O((m + n)D) space.
    pub fn rows_first(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        self.rows_first_with(u, v, &mut NoCount)
    }

    /// The point c(u, v) rows first, counting the affine combinations.
    ///
    /// Idea: row i is the control polygon of the Bézier curve in v whose value is the i-th
    /// control point of the curve c(·, v) in u [FJ-surfaces, §2]; de Casteljau's algorithm
    /// [PPB, §2.3] gives the m + 1 row values, and once more on them the point.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::rows_first`].
    ///
    /// # Complexity
    ///
    /// Θ(((m + 1)n² + m²)D) time, O((m + n)D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// exactly (m + 1)n(n + 1)/2 + m(m + 1)/2.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// assert_eq!(s.rows_first_with(&0.5, &0.25, &mut c)?, Point::new([1.0, 0.75]));
    /// assert_eq!(c.arithmetic_operations, 3 * 6 + 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn rows_first_with<C: Counter>(
        &self,
        u: &S,
        v: &S,
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        validate_parameter(v, "v")?;
        let (m, n) = self.bidegree();
        let mut scratch = Vec::with_capacity(n + 1);
        let mut values = Vec::with_capacity(m + 1);
        for i in 0..=m {
            scratch.clear();
            scratch.extend_from_slice(self.net.row(i));
            de_casteljau_levels(&mut scratch, std::iter::repeat_n(v, n), counter);
            values.push(scratch.swap_remove(0));
        }
        de_casteljau_levels(&mut values, std::iter::repeat_n(u, m), counter);
        Ok(values.swap_remove(0))
    }

    /// The point c(u, v) by de Casteljau's algorithm in u on every column, then in v on the
    /// n + 1 column points. See [`BezierPatch::columns_first_with`].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::rows_first`].
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + n²)D) time, O((m + n)D) space.
    pub fn columns_first(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        self.columns_first_with(u, v, &mut NoCount)
    }

    /// The point c(u, v) columns first, counting the affine combinations.
    ///
    /// Idea: the mirror of [`BezierPatch::rows_first_with`]: column j is the control polygon
    /// of a curve in u whose value is the j-th control point of c(u, ·) [FJ-surfaces, §2].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::rows_first`].
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + n²)D) time, O((m + n)D) space.
    ///
    /// # Counts
    ///
    /// Exactly (n + 1)m(m + 1)/2 + n(n + 1)/2
    /// [`arithmetic_operation`](Counter::arithmetic_operation)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// assert_eq!(s.columns_first_with(&0.5, &0.25, &mut c)?, Point::new([1.0, 0.75]));
    /// assert_eq!(c.arithmetic_operations, 4 * 3 + 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn columns_first_with<C: Counter>(
        &self,
        u: &S,
        v: &S,
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        validate_parameter(v, "v")?;
        let (m, n) = self.bidegree();
        let mut scratch = Vec::with_capacity(m + 1);
        let mut values = Vec::with_capacity(n + 1);
        for j in 0..=n {
            scratch.clear();
            scratch.extend(self.net.points().iter().skip(j).step_by(n + 1).cloned());
            de_casteljau_levels(&mut scratch, std::iter::repeat_n(u, m), counter);
            values.push(scratch.swap_remove(0));
        }
        de_casteljau_levels(&mut values, std::iter::repeat_n(v, n), counter);
        Ok(values.swap_remove(0))
    }

    /// The point c(u, v) by the tensor de Casteljau algorithm. See
    /// [`BezierPatch::de_casteljau_with`].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::rows_first`].
    ///
    /// # Complexity
    ///
    /// Θ((mn·min(m, n) + |m − n|²)D) time, Θ(mn·D) space.
    pub fn de_casteljau(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        self.de_casteljau_with(u, v, &mut NoCount)
    }

    /// The point c(u, v) by the tensor de Casteljau algorithm, counting its affine
    /// combinations.
    ///
    /// Idea: level k replaces each c_{i,j} of the current net by the bilinear interpolation
    /// of c_{i,j}, c_{i,j+1}, c_{i+1,j}, c_{i+1,j+1} at (u, v) (three affine combinations),
    /// shrinking the net by one in each direction [PPB, §9.5]; after k = min(m, n) levels one
    /// row or one column is left, a Bézier polygon in the remaining direction, finished by
    /// univariate de Casteljau.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::rows_first`].
    ///
    /// # Complexity
    ///
    /// Θ((mn·min(m, n) + |m − n|²)D) time, Θ(mn·D) space.
    ///
    /// # Counts
    ///
    /// Three [`arithmetic_operation`](Counter::arithmetic_operation)s per bilinear step,
    /// Σ (m − k + 1)(n − k + 1) steps over the levels k = 1, …, min(m, n), then
    /// |m − n|(|m − n| + 1)/2 univariate combinations.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// assert_eq!(s.de_casteljau_with(&0.5, &0.25, &mut c)?, Point::new([1.0, 0.75]));
    /// assert_eq!(c.arithmetic_operations, 3 * (2 * 3 + 1 * 2) + 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_casteljau_with<C: Counter>(
        &self,
        u: &S,
        v: &S,
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        validate_parameter(v, "v")?;
        let (m, n) = self.bidegree();
        let width = n + 1;
        let mut q = self.net.points().to_vec();
        let levels = m.min(n);
        for k in 1..=levels {
            // The net of level k − 1 has (m − k + 2) × (n − k + 2) points, stored with the
            // original row width; level k overwrites its first (m − k + 1) × (n − k + 1).
            for i in 0..=m - k {
                for j in 0..=n - k {
                    let low = Point::lerp(&q[i * width + j], &q[i * width + j + 1], v);
                    let high = Point::lerp(&q[(i + 1) * width + j], &q[(i + 1) * width + j + 1], v);
                    q[i * width + j] = Point::lerp(&low, &high, u);
                    counter.arithmetic_operation();
                    counter.arithmetic_operation();
                    counter.arithmetic_operation();
                }
            }
        }
        // One row (m ≤ n: a polygon in v) or one column (a polygon in u) is left.
        let mut last: Vec<Point<S, D>> = if m <= n {
            q[..=n - levels].to_vec()
        } else {
            (0..=m - levels).map(|i| q[i * width].clone()).collect()
        };
        let (rest, t) = if m <= n { (n - m, v) } else { (m - n, u) };
        de_casteljau_levels(&mut last, std::iter::repeat_n(t, rest), counter);
        Ok(last.swap_remove(0))
    }

    /// The isoparametric curve c(u₀, ·): the Bézier curve of degree n in v whose control
    /// points are the values at u₀ of the columns' curves [FJ-surfaces, §2].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u₀` is NaN or infinite;
    /// [`Error::Overflow`] if, with `f64`, a control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((n + 1)m²·D) time, Θ((n + m)D) space.
    ///
    /// ```
    /// use compgeo::spline::{Curve, Point};
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, (i * j) as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?;
    /// let c = s.curve_at_u(&0.5)?;
    /// assert_eq!(c.degree(), 3);
    /// assert_eq!(c.eval(&0.75)?, s.eval(&0.5, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn curve_at_u(&self, u: &S) -> Result<Bezier<S, D>> {
        validate_parameter(u, "u")?;
        let (m, n) = self.bidegree();
        let mut scratch = Vec::with_capacity(m + 1);
        let control = (0..=n)
            .map(|j| {
                scratch.clear();
                scratch.extend(self.net.points().iter().skip(j).step_by(n + 1).cloned());
                de_casteljau_levels(&mut scratch, std::iter::repeat_n(u, m), &mut NoCount);
                scratch[0].clone()
            })
            .collect();
        Bezier::derived(control, "isoparametric curve")
    }

    /// The isoparametric curve c(·, v₀): the Bézier curve of degree m in u whose control
    /// points are the values at v₀ of the rows' curves [FJ-surfaces, §2].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"v"` if `v₀` is NaN or infinite;
    /// [`Error::Overflow`] if, with `f64`, a control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)n²·D) time, Θ((m + n)D) space.
    ///
    /// ```
    /// use compgeo::spline::{Curve, Point};
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, (i * j) as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?;
    /// let c = s.curve_at_v(&0.75)?;
    /// assert_eq!(c.degree(), 2);
    /// assert_eq!(c.eval(&0.5)?, s.eval(&0.5, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn curve_at_v(&self, v: &S) -> Result<Bezier<S, D>> {
        validate_parameter(v, "v")?;
        let (m, n) = self.bidegree();
        let mut scratch = Vec::with_capacity(n + 1);
        let control = (0..=m)
            .map(|i| {
                scratch.clear();
                scratch.extend_from_slice(self.net.row(i));
                de_casteljau_levels(&mut scratch, std::iter::repeat_n(v, n), &mut NoCount);
                scratch[0].clone()
            })
            .collect();
        Bezier::derived(control, "isoparametric curve")
    }

    /// The patch of `rows` × `columns` points computed from a valid patch (row after row):
    /// [`Error::Overflow`] naming `what` if, with `f64`, a point came out non-finite.
    pub(super) fn derived(
        rows: usize,
        columns: usize,
        points: Vec<Point<S, D>>,
        what: &'static str,
    ) -> Result<Self> {
        if !points.iter().all(Point::is_finite) {
            return Err(Error::Overflow { what });
        }
        BezierPatch::new(ControlNet::from_rows(rows, columns, points)?)
    }

    /// The curves of the columns, c_{0,j}, …, c_{m,j} as Bézier curves in u (each a valid
    /// polygon: finite, of degree m within the limit).
    pub(super) fn column_curves(&self) -> Vec<Bezier<S, D>> {
        (0..self.net.columns())
            .map(|j| Bezier::new(self.net.column(j)).expect("a column of a valid net"))
            .collect()
    }

    /// The curves of the rows, c_{i,0}, …, c_{i,n} as Bézier curves in v.
    pub(super) fn row_curves(&self) -> Result<Vec<Bezier<S, D>>> {
        (0..self.net.rows())
            .map(|i| Bezier::new(self.net.row(i).to_vec()))
            .collect()
    }
}

/// A polynomial patch evaluates on the whole plane; [`Surface::eval`] is the tensor de
/// Casteljau algorithm, Θ((mn·min(m, n) + |m − n|²)D).
impl<S: Scalar, const D: usize> Surface<S, D> for BezierPatch<S, D> {
    fn domain(&self) -> SurfaceDomain<S> {
        SurfaceDomain {
            u: Domain::Real,
            v: Domain::Real,
        }
    }

    /// The tensor de Casteljau algorithm ([`BezierPatch::de_casteljau`]): in place in one
    /// scratch net, with no curve built per row, which made the curves' Horner scheme per
    /// row seven times slower on bicubic patches (`benches/surface.rs`).
    fn eval(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        self.de_casteljau(u, v)
    }
}

/// ∂^{r+s}c/∂u^r∂v^s(u, v) through the curve code: the s-th derivative in v of every row's
/// curve (the tetrahedral algorithm of [`Bezier`]), then the r-th derivative in u of the
/// curve of those vectors [FJ-surfaces, §5]: Θ((m + 1)n² + m²)·D.
impl<S: Scalar, const D: usize> SurfaceDerivative<S, D> for BezierPatch<S, D> {
    fn partial_at(&self, u: &S, v: &S, r: usize, s: usize) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        validate_parameter(v, "v")?;
        let values = self
            .row_curves()?
            .iter()
            .map(|row| row.derivative_at(v, s))
            .collect::<Result<Vec<_>>>()?;
        Bezier::new(values)
            .or(Err(Error::Overflow {
                what: "Bézier patch derivative",
            }))?
            .derivative_at(u, r)
    }
}
