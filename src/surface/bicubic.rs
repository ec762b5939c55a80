//! Piecewise bicubic C¹ interpolation of a grid of points, as a grid of bicubic Bézier
//! patches.
//!
//! The problem [PPB, §9.8]: points p_{i,j} at parameters (u_i, v_j), i = 0, …, m,
//! j = 0, …, n; find a piecewise bicubic C¹ surface with s(u_i, v_j) = p_{i,j}, one bicubic
//! patch over each cell [u_i, u_{i+1}] × [v_j, v_{j+1}]. The idea [PPB, §9.8]: a linear
//! C¹ cubic interpolation scheme for curves (here the piecewise cubic Hermite interpolant
//! with the tangents of the parabolas through consecutive points [PPB, §4.5], the crate's
//! [`estimate_tangents`] and [`hermite`]) maps m + 1 points to the 3m + 1 Bézier points
//! of a C¹ composite cubic, A = Sᵗ·P; applied to every column of P (in u), then to every
//! row of the result (in v), it gives the (3m + 1) × (3n + 1) Bézier points B = Sᵗ·P·T.
//! Because the scheme is linear, the two steps commute: every column of B is also a C¹
//! interpolant in u, so the surface is C¹ in both parameters, and b_{3i,3j} = p_{i,j}.
//!
//! # Complexity
//!
//! Θ(mn·D) time and space.

use super::bezier::BezierPatch;
use super::bezier_grid::BezierPatchGrid;
use super::interpolate::check_parameters;
use super::net::ControlNet;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{estimate_tangents, hermite, Point, Scalar};
use crate::{limits, Error, Result};

/// Piecewise bicubic C¹ interpolation, declared.
pub(crate) const BICUBIC_C1: Declaration = Declaration {
    problem: "surface-construct",
    name: "bicubic-c1",
    function: "surface::BezierPatchGrid::bicubic_c1",
    file: "src/surface/bicubic.rs",
    summary: "the C¹ cubic Hermite scheme with estimated tangents on every column, then on every row of the Bézier points",
    time: "Θ(mn·D)",
    space: "Θ(mn·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per Bézier point the curve scheme produces, (3m + 1)(n + 1) + (3m + 1)(3n + 1)",
    source: "[PPB, §9.8, §4.5]",
    claims: &[on("random-grid", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BezierPatchGrid<S, D> {
    /// The piecewise bicubic C¹ surface through `data` at (`u_params[i]`, `v_params[j]`). See
    /// [`BezierPatchGrid::bicubic_c1_with`].
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`] for fewer than two rows or columns; [`Error::InvalidParameter`] named
    /// `"u parameters"` or `"v parameters"` for another number of parameters, a NaN or
    /// infinite one, or one not above its predecessor; [`Error::LimitExceeded`] if the
    /// (3m + 1)(3n + 1) Bézier points exceed [`MAX_POINTS`](crate::limits::MAX_POINTS);
    /// [`Error::Overflow`] if, with `f64`, a Bézier point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(mn·D) time and space.
    pub fn bicubic_c1(data: &ControlNet<S, D>, u_params: &[S], v_params: &[S]) -> Result<Self> {
        Self::bicubic_c1_with(data, u_params, v_params, &mut NoCount)
    }

    /// The piecewise bicubic C¹ interpolant, counting the Bézier points made.
    ///
    /// Idea: the C¹ cubic Hermite scheme with tangents from the parabolas through
    /// consecutive points on every column of the data (A = Sᵗ·P), then on every row of A
    /// (B = A·T); patch (a, b) is B's block of rows 3a, …, 3a + 3 and columns
    /// 3b, …, 3b + 3 [PPB, §9.8].
    ///
    /// # Errors
    ///
    /// As [`BezierPatchGrid::bicubic_c1`].
    ///
    /// # Complexity
    ///
    /// Θ(mn·D) time and space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per Bézier point a curve
    /// scheme produces (each a fixed number of operations): (3m + 1)(n + 1) + (3m + 1)(3n + 1).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatchGrid, ControlNet, Surface};
    ///
    /// let data = ControlNet::new((0..3).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64, ((i * j) % 2) as f64])).collect()).collect())?;
    /// let mut c = Counts::default();
    /// let s = BezierPatchGrid::bicubic_c1_with(&data, &[0.0, 1.0, 2.0], &[0.0, 0.5, 1.0], &mut c)?;
    /// assert_eq!(s.eval(&1.0, &0.5)?, Point::new([1.0, 1.0, 1.0]));
    /// assert_eq!(s.eval(&2.0, &0.5)?, Point::new([2.0, 1.0, 0.0]));
    /// assert_eq!(c.arithmetic_operations, 7 * 3 + 7 * 7);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bicubic_c1_with<C: Counter>(
        data: &ControlNet<S, D>,
        u_params: &[S],
        v_params: &[S],
        counter: &mut C,
    ) -> Result<Self> {
        let (rows, columns) = (data.rows(), data.columns());
        if rows < 2 || columns < 2 {
            return Err(Error::TooFew {
                what: "bicubic interpolation data (rows and columns)",
                needed: 2,
                got: rows.min(columns),
            });
        }
        check_parameters(u_params, rows, "u parameters")?;
        check_parameters(v_params, columns, "v parameters")?;
        let (m, n) = (rows - 1, columns - 1);
        // The Bézier points are about nine times the data: refuse before allocating them.
        limits::POINTS.check((3 * m as u128 + 1) * (3 * n as u128 + 1))?;
        // A: column j of the data through the scheme in u, 3m + 1 Bézier points each.
        let mut a_columns = Vec::with_capacity(columns);
        for j in 0..columns {
            let column = c1_scheme(u_params, &data.column(j), counter)?;
            a_columns.push(column);
        }
        // B: row r of A through the scheme in v.
        let mut b = Vec::with_capacity(3 * m + 1);
        for r in 0..=3 * m {
            let row: Vec<Point<S, D>> = a_columns.iter().map(|c| c[r].clone()).collect();
            b.push(c1_scheme(v_params, &row, counter)?);
        }
        let mut patches = Vec::with_capacity(m);
        for a in 0..m {
            let mut row = Vec::with_capacity(n);
            for c in 0..n {
                let points = (0..4)
                    .flat_map(|i| b[3 * a + i][3 * c..3 * c + 4].iter().cloned())
                    .collect();
                row.push(BezierPatch::new(ControlNet::from_rows(4, 4, points)?)?);
            }
            patches.push(row);
        }
        BezierPatchGrid::new(u_params.to_vec(), v_params.to_vec(), patches)
    }
}

/// The 3m + 1 Bézier points of the C¹ cubic Hermite interpolant with estimated tangents
/// [PPB, §4.5], one count per point.
fn c1_scheme<S: Scalar, const D: usize, C: Counter>(
    params: &[S],
    points: &[Point<S, D>],
    counter: &mut C,
) -> Result<Vec<Point<S, D>>> {
    let tangents = estimate_tangents(params, points)?;
    let curve = hermite(params, points, &tangents)?;
    let mut out = Vec::with_capacity(3 * curve.pieces().len() + 1);
    for (k, piece) in curve.pieces().iter().enumerate() {
        let skip = usize::from(k > 0);
        out.extend(piece.control()[skip..].iter().cloned());
    }
    if !out.iter().all(Point::is_finite) {
        return Err(Error::Overflow {
            what: "bicubic interpolation",
        });
    }
    for _ in &out {
        counter.arithmetic_operation();
    }
    Ok(out)
}
