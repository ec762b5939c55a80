//! `compgeo surface eval|derivative|normal|restrict|elevate|tessellate`: one operation on a
//! tensor-product surface given by its control net (a Bézier patch, a B-spline surface or a
//! NURBS surface), and `compgeo surface interpolate|fit|loft`: a B-spline surface from data;
//! in `f64` or (with `--exact`) in exact rationals.
//!
//! The net is JSON `[[[x, y, z], ...], ...]`: a list of rows, row i holding the points
//! c_{i,0}, …, c_{i,n} (so m + 1 rows of n + 1 points give bidegree (m, n)), in any
//! dimension from 1 to 4; numbers are JSON numbers or strings such as `"47/18"`, read as
//! `bezier` reads them (with `--exact`, `0.1` is 1/10 and every number prints as a string).
//! With none of `--degree-u`, `--degree-v`, `--knots-u`, `--knots-v`, `--weights` the net is
//! a Bézier patch; with any of them a B-spline surface (degrees default to 3, or one less than
//! the points that way; knots to clamped and uniform on [0, 1]), and with `--weights` (a grid
//! `[[w, ...], ...]` of the net's shape) a NURBS surface. Errors name the row, the column and
//! the coordinate that is wrong, the knot, the weight, or the parameter.
//!
//! Surfaces print as `{"bidegree": [m, n], "net": [[[x, y, z], ...], ...]}`, with
//! `"knots_u"`, `"knots_v"` for B-spline surfaces and `"weights"` for NURBS. `normal` and
//! `tessellate` need points in three dimensions; `tessellate` writes the mesh as Wavefront
//! OBJ (`--obj`) and ASCII STL (`--stl`), printing its size, or prints the mesh itself.

use super::bezier::{point, points, read_number, scalars, JsonScalar};
use super::input::{inline_or_stdin, parse_number_arrays, parse_number_grid};
use super::interpolate::{read_scalars, to_points, Knots};
use super::output::{print_json, write_file};
use super::CliError;
use crate::count::Counts;
use crate::spline::{parse_scalar, BSpline, KnotVector, Point, Scalar};
use crate::surface::{
    normal, tessellate, BSplineSurface, BezierPatch, ControlNet, Direction, Normal, NurbsSurface,
    Surface, SurfaceDerivative, SurfaceDomain, TriangleMesh,
};
use clap::{Args, Subcommand, ValueEnum};
use num_rational::BigRational;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// Arguments of `compgeo surface`.
#[derive(Debug, Args)]
pub(super) struct SurfaceArgs {
    #[command(subcommand)]
    op: Op,
}

/// The operations.
#[derive(Debug, Subcommand)]
enum Op {
    /// The point c(u, v), by a chosen algorithm, with its counts
    Eval {
        #[command(flatten)]
        surface: NetArgs,
        /// The parameter u: a decimal or a fraction such as 1/3
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// The parameter v
        #[arg(long = "v", value_name = "V", allow_hyphen_values = true)]
        v: String,
        /// How to evaluate a Bézier patch [default: de-casteljau]; B-spline and NURBS
        /// surfaces use de Boor's algorithm on the rows that matter
        #[arg(long, value_enum)]
        algorithm: Option<Evaluation>,
    },
    /// The partial derivative ∂^{r+s}c/∂u^r∂v^s at (u, v) (r = s = 1: the twist)
    Derivative {
        #[command(flatten)]
        surface: NetArgs,
        /// The parameter u
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// The parameter v
        #[arg(long = "v", value_name = "V", allow_hyphen_values = true)]
        v: String,
        /// The order r in u
        #[arg(long, default_value_t = 1)]
        order_u: usize,
        /// The order s in v
        #[arg(long, default_value_t = 0)]
        order_v: usize,
    },
    /// The normal c_u × c_v at (u, v) (not normalised), or its first-order behaviour where
    /// it vanishes
    Normal {
        #[command(flatten)]
        surface: NetArgs,
        /// The parameter u
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// The parameter v
        #[arg(long = "v", value_name = "V", allow_hyphen_values = true)]
        v: String,
    },
    /// The same Bézier patch over [u0, u1] × [v0, v1], as a patch on [0, 1]²
    Restrict {
        #[command(flatten)]
        surface: NetArgs,
        /// The start of the u interval
        #[arg(long, value_name = "U0", allow_hyphen_values = true)]
        u0: String,
        /// The end of the u interval, above u0
        #[arg(long, value_name = "U1", allow_hyphen_values = true)]
        u1: String,
        /// The start of the v interval
        #[arg(long, value_name = "V0", allow_hyphen_values = true)]
        v0: String,
        /// The end of the v interval, above v0
        #[arg(long, value_name = "V1", allow_hyphen_values = true)]
        v1: String,
    },
    /// The same surface with its degrees raised by --by-u and --by-v
    Elevate {
        #[command(flatten)]
        surface: NetArgs,
        /// How many degrees to raise in u
        #[arg(long, default_value_t = 1)]
        by_u: usize,
        /// How many degrees to raise in v
        #[arg(long, default_value_t = 1)]
        by_v: usize,
    },
    /// A triangle mesh with unit normals on a uniform grid over the domain ([0, 1]² for a
    /// Bézier patch), written as OBJ and/or STL
    Tessellate {
        #[command(flatten)]
        surface: NetArgs,
        /// Grid cells along u
        #[arg(long, default_value_t = 16)]
        u_segments: usize,
        /// Grid cells along v
        #[arg(long, default_value_t = 16)]
        v_segments: usize,
        /// Write the mesh as Wavefront OBJ to this file
        #[arg(long, value_name = "PATH")]
        obj: Option<PathBuf>,
        /// Write the mesh as ASCII STL to this file
        #[arg(long, value_name = "PATH")]
        stl: Option<PathBuf>,
    },
    /// The B-spline surface of bidegree (p, q) through a grid of points (rows, then
    /// columns; averaged knots)
    Interpolate {
        /// The data as a grid JSON [[[x, y, z], ...], ...], or `-` for stdin
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        points: String,
        /// How to choose the parameters of the rows and columns
        #[arg(long, value_enum, default_value = "chord-length")]
        parameterisation: Knots,
        #[command(flatten)]
        data: DataArgs,
    },
    /// The least-squares B-spline surface (clamped uniform knots on [0, 1]²) of scattered
    /// points at given parameters
    Fit {
        /// The points, JSON [[x, y, z], ...]
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        points: String,
        /// Their parameters, JSON [[u, v], ...], in [0, 1]
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        params: String,
        /// Control points along u
        #[arg(long)]
        control_u: usize,
        /// Control points along v
        #[arg(long)]
        control_v: usize,
        #[command(flatten)]
        data: DataArgs,
    },
    /// The B-spline surface through curves in v placed at uniform u in [0, 1] (each row a
    /// control polygon of degree q on clamped uniform knots over [0, 1]; lofted with degree p
    /// on averaged knots)
    Loft {
        /// The curves' control polygons, one per row: JSON [[[x, y, z], ...], ...]
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        curves: String,
        #[command(flatten)]
        data: DataArgs,
    },
}

/// The evaluation algorithms of a Bézier patch.
#[derive(Debug, Clone, Copy, ValueEnum)]
enum Evaluation {
    /// De Casteljau on every row, then on the column of results
    RowsFirst,
    /// De Casteljau on every column, then on the row of results
    ColumnsFirst,
    /// The tensor de Casteljau algorithm: bilinear steps, then the longer direction
    DeCasteljau,
}

/// The surface and the arithmetic, shared by the operations.
#[derive(Debug, Args)]
pub(super) struct NetArgs {
    /// The control net as JSON [[[x, y, z], ...], ...] (rows of points, dimension 1 to 4),
    /// or `-` to read it from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    net: String,
    /// The degree p in u (along the columns): a B-spline surface [default: 3, or rows − 1]
    #[arg(long)]
    degree_u: Option<usize>,
    /// The degree q in v (along the rows): a B-spline surface [default: 3, or columns − 1]
    #[arg(long)]
    degree_v: Option<usize>,
    /// The u knots, JSON [0, 0, 0, 0, "1/2", 1, 1, 1, 1]: rows + p + 1 of them [default:
    /// clamped and uniform on [0, 1]]
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    knots_u: Option<String>,
    /// The v knots: columns + q + 1 of them [default: clamped and uniform on [0, 1]]
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    knots_v: Option<String>,
    /// The weights as JSON [[w, ...], ...], one per control point, positive: a NURBS surface
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    weights: Option<String>,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    pub(super) exact: bool,
}

impl NetArgs {
    /// The net's rows of points of number texts.
    pub(super) fn grid(&self) -> Result<Vec<Vec<Vec<String>>>, CliError> {
        parse_number_grid(&inline_or_stdin(&self.net)?)
    }

    /// Whether the arguments describe a B-spline or NURBS surface rather than a Bézier patch.
    fn is_spline(&self) -> bool {
        self.degree_u.is_some()
            || self.degree_v.is_some()
            || self.knots_u.is_some()
            || self.knots_v.is_some()
            || self.weights.is_some()
    }
}

/// The degrees of `interpolate`, `fit` and `loft`, and the arithmetic.
#[derive(Debug, Args)]
struct DataArgs {
    /// The degree p in u
    #[arg(long, default_value_t = 3)]
    degree_u: usize,
    /// The degree q in v
    #[arg(long, default_value_t = 3)]
    degree_v: usize,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    exact: bool,
}

/// Runs `compgeo surface`.
pub(super) fn run(args: SurfaceArgs) -> Result<(), CliError> {
    let net = match &args.op {
        Op::Eval { surface, .. }
        | Op::Derivative { surface, .. }
        | Op::Normal { surface, .. }
        | Op::Restrict { surface, .. }
        | Op::Elevate { surface, .. }
        | Op::Tessellate { surface, .. } => surface,
        Op::Interpolate { points, data, .. } => {
            let grid = parse_number_grid(&inline_or_stdin(points)?)?;
            let d = grid[0][0].len();
            let value =
                by_scalar_and_dimension!(data.exact, d, "points", construct(&args.op, &grid))?;
            return print_json(&value);
        }
        Op::Fit { points, data, .. } => {
            let rows = parse_number_arrays(points)?;
            let d = rows[0].len();
            let grid = [rows];
            let value =
                by_scalar_and_dimension!(data.exact, d, "points", construct(&args.op, &grid))?;
            return print_json(&value);
        }
        Op::Loft { curves, data } => {
            let grid = parse_number_grid(curves)?;
            let d = grid[0][0].len();
            let value = by_scalar_and_dimension!(
                data.exact,
                d,
                "control points",
                construct(&args.op, &grid)
            )?;
            return print_json(&value);
        }
    };
    let grid = parse_number_grid(&inline_or_stdin(&net.net)?)?;
    let d = grid[0][0].len();
    if let Op::Tessellate {
        u_segments,
        v_segments,
        obj,
        stl,
        ..
    } = &args.op
    {
        if d != 3 {
            return Err(CliError::Shape(format!(
                "a tessellation needs points in three dimensions; the net's have {d}"
            )));
        }
        let mesh = if net.exact {
            tessellate(
                &surface_of::<BigRational, 3>(net, &grid)?,
                *u_segments,
                *v_segments,
            )?
        } else {
            tessellate(&surface_of::<f64, 3>(net, &grid)?, *u_segments, *v_segments)?
        };
        return print_json(&write_mesh(&mesh, obj.as_deref(), stl.as_deref())?);
    }
    if let Op::Normal { u, v, .. } = &args.op {
        if d != 3 {
            return Err(CliError::Shape(format!(
                "a normal needs points in three dimensions; the net's have {d}"
            )));
        }
        let value = if net.exact {
            normal_json::<BigRational>(net, &grid, u, v)?
        } else {
            normal_json::<f64>(net, &grid, u, v)?
        };
        return print_json(&value);
    }
    let value = by_scalar_and_dimension!(
        net.exact,
        d,
        "control points",
        run_typed(&args.op, net, &grid)
    )?;
    print_json(&value)
}

/// Any of the surfaces the command reads, behind the surface traits.
pub(super) enum AnySurface<S, const D: usize> {
    Bezier(BezierPatch<S, D>),
    BSpline(BSplineSurface<S, D>),
    Nurbs(NurbsSurface<S, D>),
}

impl<S: Scalar, const D: usize> AnySurface<S, D> {
    /// The control net.
    pub(super) fn net(&self) -> &ControlNet<S, D> {
        match self {
            AnySurface::Bezier(s) => s.net(),
            AnySurface::BSpline(s) => s.net(),
            AnySurface::Nurbs(s) => s.net(),
        }
    }

    /// What kind of surface it is.
    pub(super) fn kind(&self) -> &'static str {
        match self {
            AnySurface::Bezier(_) => "Bézier patch",
            AnySurface::BSpline(_) => "B-spline surface",
            AnySurface::Nurbs(_) => "NURBS surface",
        }
    }
}

impl<S: Scalar, const D: usize> Surface<S, D> for AnySurface<S, D> {
    fn domain(&self) -> SurfaceDomain<S> {
        match self {
            AnySurface::Bezier(s) => s.domain(),
            AnySurface::BSpline(s) => s.domain(),
            AnySurface::Nurbs(s) => s.domain(),
        }
    }

    fn eval(&self, u: &S, v: &S) -> crate::Result<Point<S, D>> {
        match self {
            AnySurface::Bezier(s) => s.eval(u, v),
            AnySurface::BSpline(s) => s.eval(u, v),
            AnySurface::Nurbs(s) => s.eval(u, v),
        }
    }
}

impl<S: Scalar, const D: usize> SurfaceDerivative<S, D> for AnySurface<S, D> {
    fn partial_at(&self, u: &S, v: &S, r: usize, t: usize) -> crate::Result<Point<S, D>> {
        match self {
            AnySurface::Bezier(s) => s.partial_at(u, v, r, t),
            AnySurface::BSpline(s) => s.partial_at(u, v, r, t),
            AnySurface::Nurbs(s) => s.partial_at(u, v, r, t),
        }
    }
}

/// The surface the arguments describe: a Bézier patch, or a B-spline or NURBS surface.
pub(super) fn surface_of<S: JsonScalar, const D: usize>(
    args: &NetArgs,
    grid: &[Vec<Vec<String>>],
) -> Result<AnySurface<S, D>, CliError> {
    let net = net_of::<S, D>(grid, "control point")?;
    if !args.is_spline() {
        return Ok(AnySurface::Bezier(BezierPatch::new(net)?));
    }
    let (rows, columns) = (net.rows(), net.columns());
    let knots = |text: &Option<String>, degree: Option<usize>, count: usize, name: &str| {
        let degree = degree.unwrap_or(3.min(count - 1));
        match text {
            Some(text) => Ok::<_, CliError>(KnotVector::new(
                degree,
                read_scalars::<S>(text, &format!("{name} knot"), &format!("{name} knots"))?,
            )?),
            None => Ok(KnotVector::clamped_uniform(
                degree,
                count,
                S::zero(),
                S::one(),
            )?),
        }
    };
    let tu = knots(&args.knots_u, args.degree_u, rows, "u")?;
    let tv = knots(&args.knots_v, args.degree_v, columns, "v")?;
    let Some(text) = &args.weights else {
        return Ok(AnySurface::BSpline(BSplineSurface::new(net, tu, tv)?));
    };
    let shape = |why: &str| {
        CliError::Shape(format!(
            "the weights must form a grid of {rows} rows of {columns}, the net's shape{why}"
        ))
    };
    let weights = parse_number_arrays(text).map_err(|e| match e {
        CliError::Shape(m) => shape(&format!(" ({m})")),
        other => other,
    })?;
    if weights.len() != rows || weights.iter().any(|row| row.len() != columns) {
        return Err(shape(""));
    }
    let weights = weights
        .iter()
        .enumerate()
        .flat_map(|(i, row)| row.iter().enumerate().map(move |(j, w)| (i, j, w)))
        .map(|(i, j, w)| read_number::<S>(w, || format!("weight ({i}, {j})")))
        .collect::<Result<Vec<S>, _>>()?;
    Ok(AnySurface::Nurbs(NurbsSurface::new(net, weights, tu, tv)?))
}

/// The grid's points as a net, each named in errors as `what (i, j)`.
fn net_of<S: JsonScalar, const D: usize>(
    grid: &[Vec<Vec<String>>],
    what: &str,
) -> Result<ControlNet<S, D>, CliError> {
    let rows = grid
        .iter()
        .enumerate()
        .map(|(i, row)| to_points::<S, D>(row, |j| format!("{what} ({i}, {j})")))
        .collect::<Result<Vec<Vec<Point<S, D>>>, _>>()?;
    Ok(ControlNet::new(rows)?)
}

fn run_typed<S: JsonScalar, const D: usize>(
    op: &Op,
    args: &NetArgs,
    grid: &[Vec<Vec<String>>],
) -> Result<Value, CliError> {
    let surface = surface_of::<S, D>(args, grid)?;
    Ok(match op {
        Op::Eval {
            u, v, algorithm, ..
        } => {
            let (u, v): (S, S) = (parse_scalar(u, "u")?, parse_scalar(v, "v")?);
            let mut counts = Counts::default();
            let p = match (&surface, algorithm) {
                (AnySurface::Bezier(patch), Some(Evaluation::RowsFirst)) => {
                    patch.rows_first_with(&u, &v, &mut counts)?
                }
                (AnySurface::Bezier(patch), Some(Evaluation::ColumnsFirst)) => {
                    patch.columns_first_with(&u, &v, &mut counts)?
                }
                (AnySurface::Bezier(patch), _) => patch.de_casteljau_with(&u, &v, &mut counts)?,
                (_, Some(_)) => {
                    return Err(CliError::Usage(
                        "--algorithm chooses among a Bézier patch's algorithms; B-spline and NURBS surfaces are evaluated by de Boor's algorithm".to_string(),
                    ))
                }
                (AnySurface::BSpline(s), None) => s.de_boor_with(&u, &v, &mut counts)?,
                (AnySurface::Nurbs(s), None) => s.de_boor_with(&u, &v, &mut counts)?,
            };
            json!({
                "point": point(&p, "point")?,
                "bidegree": bidegree(&surface),
                "counts": counts,
            })
        }
        Op::Derivative {
            u,
            v,
            order_u,
            order_v,
            ..
        } => {
            let (u, v): (S, S) = (parse_scalar(u, "u")?, parse_scalar(v, "v")?);
            let p = surface.partial_at(&u, &v, *order_u, *order_v)?;
            json!({
                "derivative": point(&p, "derivative")?,
                "orders": [order_u, order_v],
                "bidegree": bidegree(&surface),
            })
        }
        Op::Restrict { u0, u1, v0, v1, .. } => {
            let AnySurface::Bezier(patch) = &surface else {
                return Err(CliError::Usage(
                    "restrict works on Bézier patches (a net without degrees, knots or weights)"
                        .to_string(),
                ));
            };
            let [a, b, c, d] = [(u0, "u0"), (u1, "u1"), (v0, "v0"), (v1, "v1")]
                .map(|(text, name)| parse_scalar::<S>(text, name));
            let mut counts = Counts::default();
            let r = patch.restrict_with(&a?, &b?, &c?, &d?, &mut counts)?;
            let mut out = surface_json(&AnySurface::Bezier(r))?;
            out["counts"] = json!(counts);
            out
        }
        Op::Elevate { by_u, by_v, .. } => match &surface {
            AnySurface::Bezier(patch) => {
                let (m, n) = patch.bidegree();
                let mut counts = Counts::default();
                let r = patch.elevate_to_with(
                    m.saturating_add(*by_u),
                    n.saturating_add(*by_v),
                    &mut counts,
                )?;
                let mut out = surface_json(&AnySurface::Bezier(r))?;
                out["counts"] = json!(counts);
                out
            }
            AnySurface::BSpline(s) => {
                let r = s
                    .elevate(Direction::U, *by_u)?
                    .elevate(Direction::V, *by_v)?;
                surface_json(&AnySurface::BSpline(r))?
            }
            AnySurface::Nurbs(s) => {
                let r = s
                    .elevate(Direction::U, *by_u)?
                    .elevate(Direction::V, *by_v)?;
                surface_json(&AnySurface::Nurbs(r))?
            }
        },
        Op::Normal { .. } | Op::Tessellate { .. } => {
            unreachable!("normal and tessellate run in three dimensions before")
        }
        Op::Interpolate { .. } | Op::Fit { .. } | Op::Loft { .. } => {
            unreachable!("the constructions read no net and run before")
        }
    })
}

/// The bidegree of any surface.
fn bidegree<S: Scalar, const D: usize>(s: &AnySurface<S, D>) -> (usize, usize) {
    match s {
        AnySurface::Bezier(p) => p.bidegree(),
        AnySurface::BSpline(s) => s.bidegree(),
        AnySurface::Nurbs(s) => s.bidegree(),
    }
}

/// A net printed row by row as the output field `name`.
fn net_json<S: JsonScalar, const D: usize>(
    net: &ControlNet<S, D>,
    name: &str,
) -> Result<Value, CliError> {
    (0..net.rows())
        .map(|i| points(net.row(i), &format!("{name}[{i}]")))
        .collect::<Result<Vec<_>, _>>()
        .map(Value::Array)
}

/// A surface as printed: its bidegree and net, with knots and weights where it has them.
fn surface_json<S: JsonScalar, const D: usize>(s: &AnySurface<S, D>) -> Result<Value, CliError> {
    Ok(match s {
        AnySurface::Bezier(p) => {
            json!({"bidegree": p.bidegree(), "net": net_json(p.net(), "net")?})
        }
        AnySurface::BSpline(s) => json!({
            "bidegree": s.bidegree(),
            "knots_u": scalars(s.u_knots().knots(), "knots_u")?,
            "knots_v": scalars(s.v_knots().knots(), "knots_v")?,
            "net": net_json(s.net(), "net")?,
        }),
        AnySurface::Nurbs(s) => {
            let columns = s.net().columns();
            let weights = s
                .weights()
                .chunks(columns)
                .enumerate()
                .map(|(i, row)| scalars(row, &format!("weights[{i}]")))
                .collect::<Result<Vec<_>, _>>()?;
            json!({
                "bidegree": s.bidegree(),
                "knots_u": scalars(s.u_knots().knots(), "knots_u")?,
                "knots_v": scalars(s.v_knots().knots(), "knots_v")?,
                "net": net_json(s.net(), "net")?,
                "weights": weights,
            })
        }
    })
}

/// `interpolate`, `fit` and `loft`: a B-spline surface from data.
fn construct<S: JsonScalar, const D: usize>(
    op: &Op,
    grid: &[Vec<Vec<String>>],
) -> Result<Value, CliError> {
    let s = match op {
        Op::Interpolate {
            parameterisation,
            data,
            ..
        } => {
            let net = net_of::<S, D>(grid, "point")?;
            BSplineSurface::interpolate(
                &net,
                (data.degree_u, data.degree_v),
                parameterisation.kind(),
            )?
        }
        Op::Fit {
            params,
            control_u,
            control_v,
            data,
            ..
        } => {
            let pts: Vec<Point<S, D>> = to_points(&grid[0], |i| format!("point {i}"))?;
            let uv: Vec<Point<S, 2>> = to_points(&parse_number_arrays(params)?, |i| {
                format!("parameter pair {i}")
            })?;
            let us: Vec<S> = uv.iter().map(|p| p[0].clone()).collect();
            let vs: Vec<S> = uv.iter().map(|p| p[1].clone()).collect();
            let tu = KnotVector::clamped_uniform(data.degree_u, *control_u, S::zero(), S::one())?;
            let tv = KnotVector::clamped_uniform(data.degree_v, *control_v, S::zero(), S::one())?;
            BSplineSurface::fit(&pts, &us, &vs, tu, tv)?
        }
        Op::Loft { data, .. } => {
            let curves = grid
                .iter()
                .enumerate()
                .map(|(k, row)| {
                    let control: Vec<Point<S, D>> =
                        to_points(row, |j| format!("control point ({k}, {j})"))?;
                    let n = control.len();
                    let t = KnotVector::clamped_uniform(data.degree_v, n, S::zero(), S::one())?;
                    Ok(BSpline::new(control, t)?)
                })
                .collect::<Result<Vec<_>, CliError>>()?;
            let k = curves.len();
            // A count of curves read from text fits in i64.
            let last = S::from_i64(k.saturating_sub(1).max(1) as i64);
            let params: Vec<S> = (0..k).map(|i| S::from_i64(i as i64) / &last).collect();
            let knots = KnotVector::averaged(data.degree_u, &params)?;
            BSplineSurface::loft(&curves, Direction::U, &params, knots)?
        }
        _ => unreachable!("only the constructions come here"),
    };
    surface_json(&AnySurface::BSpline(s))
}

/// `normal`: the normal at (u, v), or its derivatives where it vanishes.
fn normal_json<S: JsonScalar>(
    args: &NetArgs,
    grid: &[Vec<Vec<String>>],
    u: &str,
    v: &str,
) -> Result<Value, CliError> {
    let surface = surface_of::<S, 3>(args, grid)?;
    let (u, v): (S, S) = (parse_scalar(u, "u")?, parse_scalar(v, "v")?);
    Ok(match normal(&surface, &u, &v)? {
        Normal::Regular(n) => json!({"regular": true, "normal": point(&n, "normal")?}),
        Normal::Degenerate { along_u, along_v } => json!({
            "regular": false,
            "along_u": point(&along_u, "along_u")?,
            "along_v": point(&along_v, "along_v")?,
        }),
    })
}

/// Writes the mesh to the files asked for and says what was written; without files, the
/// mesh itself.
pub(super) fn write_mesh(
    mesh: &TriangleMesh,
    obj: Option<&Path>,
    stl: Option<&Path>,
) -> Result<Value, CliError> {
    let mut out = json!({
        "vertices": mesh.positions.len(),
        "triangles": mesh.triangles.len(),
    });
    if let Some(path) = obj {
        write_file(path, |w| mesh.write_obj(w))?;
        out["obj"] = json!(path.display().to_string());
    }
    if let Some(path) = stl {
        write_file(path, |w| mesh.write_stl("compgeo_surface", w))?;
        out["stl"] = json!(path.display().to_string());
    }
    if obj.is_none() && stl.is_none() {
        out["positions"] = json!(mesh.positions);
        out["normals"] = json!(mesh.normals);
        out["indices"] = json!(mesh.triangles);
    }
    Ok(out)
}
