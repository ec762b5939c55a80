//! Catalog entries of the B-spline and NURBS surfaces and the surface constructions of
//! [`crate::surface`].
//!
//! `random-bidegree`: one evaluation of a B-spline (or NURBS) surface of bidegree (n, n) on
//! clamped knots with one interior knot in each direction, at a random (u, v): Θ(n³).
//!
//! `random-net`: a bicubic surface with n rows and 8 columns (clamped uniform knots), so the
//! work is linear in n: a knot inserted in v (every row), the midpoints of the five spans in
//! v inserted in one refinement (every row), the conversion to Bézier patches, the degree
//! raised by one in v, and the isoparametric curve at a random v (de Boor on every row).
//!
//! `random-columns`: the bicubic surface with 8 rows and n columns, and its isoparametric
//! curve at a random u: the basis in u applied to the four rows that matter, linear in n.
//!
//! `random-grid`: n × 8 data points at uniform parameters, interpolated bicubically (tensor
//! interpolation) and by the piecewise bicubic C¹ scheme: linear in n.
//!
//! `random-scattered`: n data points at random parameters, fitted by a bicubic surface with a
//! fixed 6 × 6 net: the normal equations take Θ(n) to assemble, the solve a constant.
//!
//! `random-curves`: n cubic curves with 8 control points on the same knots, lofted by a cubic
//! in the lofting direction: linear in n.
//!
//! `grid-rows`: a bicubic surface of 8 × 8 points (B-spline, or NURBS with weights 1, 2, 3)
//! on the grid of n uniform u parameters by 8 uniform v parameters: linear in n.
//!
//! Points are uniform in the unit cube (x and y from one seeded point set, z from a second).

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::{BSpline, KnotVector, Point};
use crate::surface::{BSplineSurface, BezierPatchGrid, ControlNet, Direction, NurbsSurface};

/// The surface entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::surface::declarations as s;
    let net = |declaration: &'static Declaration, run: Run| {
        Entry::declared(declaration, "random-net", Net(run))
            .quick(16, 1024)
            .full(16, 8192)
    };
    vec![
        Entry::declared(
            &s::TENSOR_DE_BOOR,
            "random-bidegree",
            Evaluate { nurbs: false },
        )
        .quick(2, 32)
        .full(2, 64),
        Entry::declared(
            &s::NURBS_SURFACE_EVAL,
            "random-bidegree",
            Evaluate { nurbs: true },
        )
        .quick(2, 32)
        .full(2, 64),
        net(&s::SURFACE_INSERT, Run::Insert),
        net(&s::SURFACE_TO_BEZIER, Run::ToBezier),
        net(&s::SURFACE_ELEVATE, Run::Elevate),
        net(&s::SURFACE_REFINE, Run::Refine),
        net(&s::SURFACE_ISOCURVE, Run::IsocurveV),
        Entry::declared(&s::SURFACE_ISOCURVE, "random-columns", Net(Run::IsocurveU))
            .quick(16, 1024)
            .full(16, 8192),
        Entry::declared(
            &s::SURFACE_INTERPOLATE,
            "random-grid",
            Grid { bicubic: false },
        )
        .quick(16, 1024)
        .full(16, 8192),
        Entry::declared(&s::BICUBIC_C1, "random-grid", Grid { bicubic: true })
            .quick(16, 1024)
            .full(16, 8192),
        Entry::declared(&s::SURFACE_FIT, "random-scattered", Scattered)
            .quick(64, 4096)
            .full(64, 32768),
        Entry::declared(&s::LOFT, "random-curves", Loft)
            .quick(16, 1024)
            .full(16, 8192),
        Entry::declared(&s::BSPLINE_GRID, "grid-rows", GridRows { nurbs: false })
            .quick(16, 4096)
            .full(16, 65536),
        Entry::declared(&s::NURBS_GRID, "grid-rows", GridRows { nurbs: true })
            .quick(16, 4096)
            .full(16, 65536),
    ]
}

/// `count` points uniform in the unit cube.
fn cube_points(count: usize, seed: u64) -> Result<Vec<Point<f64, 3>>> {
    let xy = points(PointKind::UniformSquare, count, seed)?;
    let z = points(PointKind::UniformSquare, count, seed ^ 1)?;
    Ok(xy
        .iter()
        .zip(&z)
        .map(|(a, b)| Point::new([a.x, a.y, b.x]))
        .collect())
}

/// A random surface of `rows` × `columns` points of bidegree (p, q) on clamped uniform knots
/// over [0, 1].
fn random_surface(
    rows: usize,
    columns: usize,
    (p, q): (usize, usize),
    seed: u64,
) -> Result<BSplineSurface<f64, 3>> {
    let net = ControlNet::from_rows(rows, columns, cube_points(rows * columns, seed)?)?;
    BSplineSurface::new(
        net,
        KnotVector::clamped_uniform(p, rows, 0.0, 1.0)?,
        KnotVector::clamped_uniform(q, columns, 0.0, 1.0)?,
    )
}

/// One evaluation of a surface of bidegree (n, n) with n + 2 points per direction.
struct Evaluate {
    nurbs: bool,
}

impl Workload for Evaluate {
    type Input = (
        BSplineSurface<f64, 3>,
        Option<NurbsSurface<f64, 3>>,
        f64,
        f64,
    );
    type Output = Point<f64, 3>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let s = random_surface(n + 2, n + 2, (n, n), seed)?;
        let first = points(PointKind::UniformSquare, 1, seed)?[0];
        let nurbs = if self.nurbs {
            let count = s.net().points().len();
            let weights = (0..count).map(|k| 1.0 + (k % 3) as f64).collect();
            Some(NurbsSurface::new(
                s.net().clone(),
                weights,
                s.u_knots().clone(),
                s.v_knots().clone(),
            )?)
        } else {
            None
        };
        Ok((s, nurbs, first.x, first.y))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (s, nurbs, u, v) = input;
        match nurbs {
            Some(n) => n.de_boor_with(u, v, c),
            None => s.de_boor_with(u, v, c),
        }
    }
}

/// A bicubic surface of 8 × 8 points on the grid of n × 8 uniform parameters.
struct GridRows {
    nurbs: bool,
}

impl Workload for GridRows {
    type Input = (NurbsSurface<f64, 3>, Vec<f64>, Vec<f64>);
    /// The sum of the points' z coordinates.
    type Output = f64;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let s = random_surface(8, 8, (3, 3), seed)?;
        let weights = (0..64)
            .map(|k| {
                if self.nurbs {
                    1.0 + (k % 3) as f64
                } else {
                    1.0
                }
            })
            .collect();
        let nurbs = NurbsSurface::new(
            s.net().clone(),
            weights,
            s.u_knots().clone(),
            s.v_knots().clone(),
        )?;
        let uniform = |k: usize| (0..k).map(|i| i as f64 / (k - 1) as f64).collect();
        Ok((nurbs, uniform(n.max(2)), uniform(8)))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (s, us, vs) = input;
        let grid = if self.nurbs {
            s.eval_grid_with(us, vs, c)?
        } else {
            s.homogeneous().0.eval_grid_with(us, vs, c)?
        };
        Ok(grid.iter().map(|p| p[2]).sum())
    }
}

/// Which operation runs on the n × 8 bicubic surface.
#[derive(Clone, Copy, Debug)]
enum Run {
    Insert,
    ToBezier,
    Elevate,
    Refine,
    /// The curve at a fixed v, on n rows.
    IsocurveV,
    /// The curve at a fixed u, on n columns.
    IsocurveU,
}

/// An operation on a bicubic surface of n × 8 points.
struct Net(Run);

impl Workload for Net {
    type Input = BSplineSurface<f64, 3>;
    /// The number of control points (or patches) made.
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        match self.0 {
            Run::IsocurveU => random_surface(8, n.max(4), (3, 3), seed),
            _ => random_surface(n.max(4), 8, (3, 3), seed),
        }
    }

    fn run<C: Counter>(&self, s: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        Ok(match self.0 {
            Run::Insert => s
                .insert_with(Direction::V, &0.3, 1, c)?
                .net()
                .points()
                .len(),
            Run::ToBezier => s.to_bezier_with(c)?.patches().len(),
            Run::Elevate => s.elevate_with(Direction::V, 1, c)?.net().points().len(),
            Run::Refine => {
                let t = s.v_knots().knots();
                let mids: Vec<f64> = (3..8).map(|i| (t[i] + t[i + 1]) / 2.0).collect();
                s.refine_with(Direction::V, &mids, c)?.net().points().len()
            }
            Run::IsocurveV => s.isocurve_with(Direction::V, &0.3, c)?.control().len(),
            Run::IsocurveU => s.isocurve_with(Direction::U, &0.3, c)?.control().len(),
        })
    }
}

/// n × 8 data points at uniform parameters.
struct Grid {
    bicubic: bool,
}

impl Workload for Grid {
    type Input = (ControlNet<f64, 3>, Vec<f64>, Vec<f64>);
    /// The number of control points (or patches) made.
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let rows = n.max(4);
        let net = ControlNet::from_rows(rows, 8, cube_points(rows * 8, seed)?)?;
        let uniform = |k: usize| (0..k).map(|i| i as f64 / (k - 1) as f64).collect();
        Ok((net, uniform(rows), uniform(8)))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (data, us, vs) = input;
        if self.bicubic {
            return Ok(BezierPatchGrid::bicubic_c1_with(data, us, vs, c)?
                .patches()
                .len());
        }
        let tu = KnotVector::averaged(3, us)?;
        let tv = KnotVector::averaged(3, vs)?;
        Ok(
            BSplineSurface::interpolate_at_with(data, us, vs, tu, tv, c)?
                .net()
                .points()
                .len(),
        )
    }
}

/// n scattered data points, fitted by a bicubic surface of 6 × 6 control points.
struct Scattered;

impl Workload for Scattered {
    type Input = (Vec<Point<f64, 3>>, Vec<f64>, Vec<f64>);
    type Output = BSplineSurface<f64, 3>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = cube_points(n, seed)?;
        // The parameters: the data's x and y, which are uniform in [0, 1).
        let us = pts.iter().map(|p| p[0]).collect();
        let vs = pts.iter().map(|p| p[1]).collect();
        Ok((pts, us, vs))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (pts, us, vs) = input;
        let t = KnotVector::clamped_uniform(3, 6, 0.0, 1.0)?;
        BSplineSurface::fit_with(pts, us, vs, t.clone(), t, c)
    }
}

/// n cubic curves of 8 control points on one knot vector, lofted by a cubic.
struct Loft;

impl Workload for Loft {
    type Input = (Vec<BSpline<f64, 3>>, Vec<f64>, KnotVector<f64>);
    type Output = BSplineSurface<f64, 3>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let count = n.max(4);
        let knots = KnotVector::clamped_uniform(3, 8, 0.0, 1.0)?;
        let pts = cube_points(count * 8, seed)?;
        let curves = pts
            .chunks(8)
            .map(|c| BSpline::new(c.to_vec(), knots.clone()))
            .collect::<Result<Vec<_>>>()?;
        let params: Vec<f64> = (0..count).map(|i| i as f64 / (count - 1) as f64).collect();
        let along = KnotVector::averaged(3, &params)?;
        Ok((curves, params, along))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (curves, params, knots) = input;
        BSplineSurface::loft_with(curves, Direction::V, params, knots.clone(), c)
    }
}
