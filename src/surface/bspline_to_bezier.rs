//! The Bézier patches of a B-spline surface, through the curve code.
//!
//! The problem: the polynomial pieces of a B-spline surface over the cells of its distinct
//! knots, each as a [`BezierPatch`]. The idea [PPB, §5.10, §9.2]: convert every row to its
//! Bézier pieces in v ([`BSpline::to_bezier_with`]); for each piece in v the rows' pieces
//! form a net whose columns are B-spline curves in u on the u knots; convert each of those
//! to its Bézier pieces in u. The control points of piece a in u of column j of piece b in v
//! are column j of patch (a, b).
//!
//! # Complexity
//!
//! For P × Q cells: Θ(M(N + Q·q)·D) plus the curve conversions of the M rows in v and of the
//! Q(q + 1) columns in u: O((M·N·q² + Q·q·M·p²)D) in all.

use super::bezier::BezierPatch;
use super::bezier_grid::BezierPatchGrid;
use super::bspline::BSplineSurface;
use super::net::ControlNet;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{BSpline, Point, Scalar};
use crate::Result;

/// Conversion of a B-spline surface to Bézier patches, declared.
pub(crate) const SURFACE_TO_BEZIER: Declaration = Declaration {
    problem: "bspline-surface",
    name: "to-bezier",
    function: "surface::BSplineSurface::to_bezier",
    file: "src/surface/bspline_to_bezier.rs",
    summary:
        "every row to Bézier pieces in v, then every column of each piece to Bézier pieces in u",
    time: "O((M·N·q² + Q·q·M·p²)D)",
    space: "Θ(P·Q·(p + 1)(q + 1)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "those of the curve conversion on the M rows, then on the Q(q + 1) columns of the pieces",
    source: "[PPB, §5.10, §9.2]",
    claims: &[on(
        "random-net",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSplineSurface<S, D> {
    /// The surface as a grid of Bézier patches over the cells of its distinct knots. See
    /// [`BSplineSurface::to_bezier_with`].
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS) points; [`Error::Overflow`](crate::Error::Overflow)
    /// if, with `f64`, a Bézier point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// O((M·N·q² + Q·q·M·p²)D) time, Θ(P·Q·(p + 1)(q + 1)D) space for P × Q cells.
    pub fn to_bezier(&self) -> Result<BezierPatchGrid<S, D>> {
        self.to_bezier_with(&mut NoCount)
    }

    /// The grid of Bézier patches, counting the arithmetic.
    ///
    /// Idea: rows to Bézier pieces in v, then the columns of each piece to Bézier pieces in
    /// u, both by [`BSpline::to_bezier_with`] [PPB, §5.10, §9.2].
    ///
    /// # Errors
    ///
    /// As [`BSplineSurface::to_bezier`].
    ///
    /// # Complexity
    ///
    /// As [`BSplineSurface::to_bezier`].
    ///
    /// # Counts
    ///
    /// Those of the curve conversions.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Point};
    /// use compgeo::surface::{BSplineSurface, ControlNet, Surface};
    ///
    /// let net = ControlNet::new((0..4).map(|i| (0..3).map(|j| Point::new([i as f64, j as f64, (i * j % 3) as f64])).collect()).collect())?;
    /// let s = BSplineSurface::new(net, KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?, KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?)?;
    /// let g = s.to_bezier_with(&mut Counts::default())?;
    /// assert_eq!(g.u_partition(), [0.0, 1.0, 2.0]);
    /// assert_eq!(g.v_partition(), [0.0, 1.0]);
    /// assert_eq!(g.eval(&1.5, &0.25)?, s.eval(&1.5, &0.25)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_bezier_with<C: Counter>(&self, counter: &mut C) -> Result<BezierPatchGrid<S, D>> {
        let rows = self
            .row_curves()
            .iter()
            .map(|row| row.to_bezier_with(counter))
            .collect::<Result<Vec<_>>>()?;
        let v_partition = rows[0].partition().to_vec();
        let pieces_v = v_partition.len() - 1;
        let q = self.bidegree().1;
        // patches[a][b], filled column by column of the pieces in v.
        let mut columns_of: Vec<Vec<Vec<Vec<Point<S, D>>>>> = Vec::with_capacity(pieces_v);
        let mut u_partition = Vec::new();
        for b in 0..pieces_v {
            // Column j of piece b: the j-th Bézier point of every row's piece b.
            let mut per_column = Vec::with_capacity(q + 1);
            for j in 0..=q {
                let control: Vec<Point<S, D>> = rows
                    .iter()
                    .map(|r| r.pieces()[b].control()[j].clone())
                    .collect();
                let column = BSpline::new(control, self.u_knots().clone())?;
                let pieces = column.to_bezier_with(counter)?;
                u_partition = pieces.partition().to_vec();
                per_column.push(
                    pieces
                        .pieces()
                        .iter()
                        .map(|c| c.control().to_vec())
                        .collect::<Vec<_>>(),
                );
            }
            columns_of.push(per_column);
        }
        let pieces_u = u_partition.len() - 1;
        let p = self.bidegree().0;
        let mut patches = Vec::with_capacity(pieces_u);
        for a in 0..pieces_u {
            let mut row = Vec::with_capacity(pieces_v);
            for per_column in &columns_of {
                // Patch (a, b): point (i, j) is point i of column j's piece a.
                let points = (0..=p)
                    .flat_map(|i| per_column.iter().map(move |col| col[a][i].clone()))
                    .collect();
                row.push(BezierPatch::new(ControlNet::from_rows(
                    p + 1,
                    q + 1,
                    points,
                )?)?);
            }
            patches.push(row);
        }
        BezierPatchGrid::new(u_partition, v_partition, patches)
    }
}
