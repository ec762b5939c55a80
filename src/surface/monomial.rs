//! Conversion between the Bézier net and the monomial (power) form of a polynomial patch.
//!
//! The problem: the coefficients a_{k,l} of c(u, v) = Σ_k Σ_l a_{k,l} u^k v^l from the net,
//! and back. The idea: the conversion for curves, applied twice [PPB, §9.4]: every column's
//! curve in u to its power form turns the net into a grid whose row k holds the Bézier points
//! in v of the coefficient of u^k; every such row converted in v gives the a_{k,l}. The
//! inverse runs the curve's inverse the same way. The grid of coefficients is returned as a
//! [`ControlNet`] (row k, column l), which keeps it rectangular and finite.
//!
//! [PPB, §9.4] writes the power basis scaled, Σ a_{k,l} C(m, k) C(n, l) u^k v^l; here the
//! plain monomials u^k v^l, as for curves.
//!
//! # Complexity
//!
//! Θ(((n + 1)m² + (m + 1)n²)D) time either way, Θ(mnD) space.
//!
//! Invariants the tests check (exactly on rationals): the power form evaluates to the patch,
//! the conversion round-trips, and the worked example of [FJ-surfaces, §2] and the patches of
//! [FJ-surfaces, §6] have the printed parametrisations.

use super::bezier::BezierPatch;
use super::net::ControlNet;
use super::subdivide::from_columns;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::{from_monomial_counted, to_monomial_counted};
use crate::spline::{Point, Scalar};
use crate::{limits, Error, Result};

/// Conversion to the monomial form, declared.
pub(crate) const TO_MONOMIAL: Declaration = Declaration {
    problem: "bezier-patch",
    name: "to-monomial",
    function: "surface::BezierPatch::to_monomial",
    file: "src/surface/monomial.rs",
    summary: "every column to its power form in u, then every row of that in v",
    time: "Θ(((n + 1)m² + (m + 1)n²)D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)(m + 1)(m + 2)/2 + (m + 1)(n + 1)(n + 2)/2 differences and scalings",
    source: "[PPB, §9.4], [PPB, §2.9]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// Conversion from the monomial form, declared.
pub(crate) const FROM_MONOMIAL: Declaration = Declaration {
    problem: "bezier-patch",
    name: "from-monomial",
    function: "surface::BezierPatch::from_monomial",
    file: "src/surface/monomial.rs",
    summary: "every column of coefficients to Bézier points in u, then every row in v",
    time: "Θ(((n + 1)m² + (m + 1)n²)D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)(m + 1)(m + 4)/2 + (m + 1)(n + 1)(n + 4)/2 scalings and multiply-adds",
    source: "[PPB, §9.4], [PPB, §2.8]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The coefficients a_{k,l} of c(u, v) = Σ a_{k,l} u^k v^l as a grid: row k (power of
    /// u), column l (power of v). See [`BezierPatch::to_monomial_with`].
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if, with `f64`, a coefficient is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + (m + 1)n²)D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// // The bilinear patch of z = uv: its only z coefficient is that of uv.
    /// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    /// let s = BezierPatch::new(ControlNet::new(vec![
    ///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
    ///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
    /// ])?)?;
    /// let a = s.to_monomial()?;
    /// assert_eq!(a.row(0), [p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)]); // 1, v
    /// assert_eq!(a.row(1), [p(1.0, 0.0, 0.0), p(0.0, 0.0, 1.0)]); // u, uv
    /// assert_eq!(BezierPatch::from_monomial(&a)?, s);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_monomial(&self) -> Result<ControlNet<S, D>> {
        self.to_monomial_with(&mut NoCount)
    }

    /// The monomial coefficients, counting point operations.
    ///
    /// Idea: the power form of each column's curve, a_k = C(m, k) Δ^k c_0 [PPB, §2.9], gives
    /// row k of Bézier points in v of the coefficient of u^k; the power form of each such
    /// row gives the a_{k,l} [PPB, §9.4].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::to_monomial`].
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + (m + 1)n²)D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per difference or scaling
    /// of a point: a curve of degree d costs (d + 1)(d + 2)/2, so exactly
    /// (n + 1)(m + 1)(m + 2)/2 + (m + 1)(n + 1)(n + 2)/2.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let mut c = Counts::default();
    /// let a = BezierPatch::new(ControlNet::new(rows)?)?.to_monomial_with(&mut c)?;
    /// assert_eq!(a.get(1, 0), &Point::new([2.0, 0.0])); // x = 2u
    /// assert_eq!(c.arithmetic_operations, 4 * 6 + 3 * 10);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_monomial_with<C: Counter>(&self, counter: &mut C) -> Result<ControlNet<S, D>> {
        let (m, n) = self.bidegree();
        let columns: Vec<Vec<Point<S, D>>> = (0..=n)
            .map(|j| to_monomial_counted(&self.net().column(j), counter))
            .collect();
        let half = from_columns(&columns);
        let points: Vec<Point<S, D>> = half
            .chunks(n + 1)
            .flat_map(|row| to_monomial_counted(row, counter))
            .collect();
        if !points.iter().all(Point::is_finite) {
            return Err(Error::Overflow {
                what: "monomial coefficient",
            });
        }
        ControlNet::from_rows(m + 1, n + 1, points)
    }

    /// The patch of c(u, v) = Σ a_{k,l} u^k v^l, of bidegree (rows − 1, columns − 1) of the
    /// grid `coefficients` (row k, column l). See [`BezierPatch::from_monomial_with`].
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if a degree exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE),
    /// before anything is computed; [`Error::Overflow`] if, with `f64`, a point is beyond the
    /// double range.
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + (m + 1)n²)D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, Surface};
    ///
    /// // 1 + uv.
    /// let a = ControlNet::new(vec![
    ///     vec![Point::new([1.0]), Point::new([0.0])],
    ///     vec![Point::new([0.0]), Point::new([1.0])],
    /// ])?;
    /// let s = BezierPatch::from_monomial(&a)?;
    /// assert_eq!(s.eval(&0.5, &0.5)?, Point::new([1.25]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_monomial(coefficients: &ControlNet<S, D>) -> Result<Self> {
        Self::from_monomial_with(coefficients, &mut NoCount)
    }

    /// The patch of a monomial form, counting point operations.
    ///
    /// Idea: the Bézier points of each column of coefficients as a curve in u,
    /// b_i = Σ_{k ≤ i} C(i, k)/C(m, k) a_k [PPB, §2.8], then the same along every row in v
    /// [PPB, §9.4].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::from_monomial`].
    ///
    /// # Complexity
    ///
    /// Θ(((n + 1)m² + (m + 1)n²)D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per scaling or
    /// multiply-add of a point: a curve of degree d costs (d + 1) + (d + 1)(d + 2)/2, so
    /// exactly (n + 1)(m + 1)(m + 4)/2 + (m + 1)(n + 1)(n + 4)/2.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let a = ControlNet::new(vec![vec![Point::new([1.0]), Point::new([2.0])]])?; // 1 + 2v
    /// let mut c = Counts::default();
    /// let s = BezierPatch::from_monomial_with(&a, &mut c)?;
    /// assert_eq!(s.net().row(0), [Point::new([1.0]), Point::new([3.0])]);
    /// assert_eq!(c.arithmetic_operations, 2 * 2 + 5);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_monomial_with<C: Counter>(
        coefficients: &ControlNet<S, D>,
        counter: &mut C,
    ) -> Result<Self> {
        let (rows, columns) = (coefficients.rows(), coefficients.columns());
        limits::DEGREE.check(rows as u128 - 1)?;
        limits::DEGREE.check(columns as u128 - 1)?;
        let converted: Vec<Vec<Point<S, D>>> = (0..columns)
            .map(|l| from_monomial_counted(&coefficients.column(l), counter))
            .collect();
        let half = from_columns(&converted);
        let points: Vec<Point<S, D>> = half
            .chunks(columns)
            .flat_map(|row| from_monomial_counted(row, counter))
            .collect();
        BezierPatch::derived(rows, columns, points, "conversion from the monomial form")
    }
}
