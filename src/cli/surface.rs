//! `compgeo surface eval|derivative|normal|restrict|elevate|tessellate`: one operation on a
//! tensor-product Bézier patch given by its control net, in `f64` or (with `--exact`) in
//! exact rationals.
//!
//! The net is JSON `[[[x, y, z], ...], ...]`: a list of rows, row i holding the points
//! c_{i,0}, …, c_{i,n} (so m + 1 rows of n + 1 points give bidegree (m, n)), in any
//! dimension from 1 to 4; numbers are JSON numbers or strings such as `"47/18"`, read as
//! `bezier` reads them (with `--exact`, `0.1` is 1/10 and every number prints as a string).
//! Errors name the row, the column and the coordinate that is wrong, or the parameter.
//! Patches print as `{"bidegree": [m, n], "net": [[[x, y, z], ...], ...]}`. `normal` and
//! `tessellate` need points in three dimensions; `tessellate` writes the mesh as Wavefront
//! OBJ (`--obj`) and ASCII STL (`--stl`), printing its size, or prints the mesh itself.

use super::bezier::{point, points, JsonScalar};
use super::input::{parse_number_grid, read_text};
use super::interpolate::to_points;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::spline::{parse_scalar, Point};
use crate::surface::{
    normal, tessellate, BezierPatch, ControlNet, Normal, SurfaceDerivative, TriangleMesh,
};
use clap::{Args, Subcommand, ValueEnum};
use num_rational::BigRational;
use serde_json::{json, Value};
use std::fs::File;
use std::io::{BufWriter, Write};
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
        /// How to evaluate the patch
        #[arg(long, value_enum, default_value = "de-casteljau")]
        algorithm: Evaluation,
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
    /// The same surface over [u0, u1] × [v0, v1], as a patch on [0, 1]²
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
struct NetArgs {
    /// The control net as JSON [[[x, y, z], ...], ...] (rows of points, dimension 1 to 4),
    /// or `-` to read it from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    net: String,
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
    };
    let text = if net.net == "-" {
        read_text(Path::new("-"))?
    } else {
        net.net.clone()
    };
    let grid = parse_number_grid(&text)?;
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
            mesh::<BigRational>(&grid, *u_segments, *v_segments)?
        } else {
            mesh::<f64>(&grid, *u_segments, *v_segments)?
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
            normal_json::<BigRational>(&grid, u, v)?
        } else {
            normal_json::<f64>(&grid, u, v)?
        };
        return print_json(&value);
    }
    let value =
        by_scalar_and_dimension!(net.exact, d, "control points", run_typed(&args.op, &grid))?;
    print_json(&value)
}

/// The patch the grid describes, every point named in errors by its row and column.
fn patch_of<S: JsonScalar, const D: usize>(
    grid: &[Vec<Vec<String>>],
) -> Result<BezierPatch<S, D>, CliError> {
    let rows = grid
        .iter()
        .enumerate()
        .map(|(i, row)| to_points::<S, D>(row, |j| format!("control point ({i}, {j})")))
        .collect::<Result<Vec<Vec<Point<S, D>>>, _>>()?;
    Ok(BezierPatch::new(ControlNet::new(rows)?)?)
}

fn run_typed<S: JsonScalar, const D: usize>(
    op: &Op,
    grid: &[Vec<Vec<String>>],
) -> Result<Value, CliError> {
    let patch = patch_of::<S, D>(grid)?;
    let (m, n) = patch.bidegree();
    Ok(match op {
        Op::Eval {
            u, v, algorithm, ..
        } => {
            let (u, v): (S, S) = (parse_scalar(u, "u")?, parse_scalar(v, "v")?);
            let mut counts = Counts::default();
            let p = match algorithm {
                Evaluation::RowsFirst => patch.rows_first_with(&u, &v, &mut counts)?,
                Evaluation::ColumnsFirst => patch.columns_first_with(&u, &v, &mut counts)?,
                Evaluation::DeCasteljau => patch.de_casteljau_with(&u, &v, &mut counts)?,
            };
            json!({
                "point": point(&p, "point")?,
                "bidegree": [m, n],
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
            let p = patch.partial_at(&u, &v, *order_u, *order_v)?;
            json!({
                "derivative": point(&p, "derivative")?,
                "orders": [order_u, order_v],
                "bidegree": [m, n],
            })
        }
        Op::Restrict { u0, u1, v0, v1, .. } => {
            let [a, b, c, d] = [(u0, "u0"), (u1, "u1"), (v0, "v0"), (v1, "v1")]
                .map(|(text, name)| parse_scalar::<S>(text, name));
            let mut counts = Counts::default();
            let r = patch.restrict_with(&a?, &b?, &c?, &d?, &mut counts)?;
            let mut out = patch_json(&r)?;
            out["counts"] = json!(counts);
            out
        }
        Op::Elevate { by_u, by_v, .. } => {
            let (p, q) = (m.saturating_add(*by_u), n.saturating_add(*by_v));
            let mut counts = Counts::default();
            let r = patch.elevate_to_with(p, q, &mut counts)?;
            let mut out = patch_json(&r)?;
            out["counts"] = json!(counts);
            out
        }
        Op::Normal { .. } | Op::Tessellate { .. } => {
            unreachable!("normal and tessellate run in three dimensions before")
        }
    })
}

/// A patch as printed: its bidegree and its net, row by row.
fn patch_json<S: JsonScalar, const D: usize>(p: &BezierPatch<S, D>) -> Result<Value, CliError> {
    let net = p.net();
    let rows = (0..net.rows())
        .map(|i| points(net.row(i), &format!("net[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(json!({"bidegree": p.bidegree(), "net": rows}))
}

/// `normal`: the normal at (u, v), or its derivatives where it vanishes.
fn normal_json<S: JsonScalar>(
    grid: &[Vec<Vec<String>>],
    u: &str,
    v: &str,
) -> Result<Value, CliError> {
    let patch = patch_of::<S, 3>(grid)?;
    let (u, v): (S, S) = (parse_scalar(u, "u")?, parse_scalar(v, "v")?);
    Ok(match normal(&patch, &u, &v)? {
        Normal::Regular(n) => json!({"regular": true, "normal": point(&n, "normal")?}),
        Normal::Degenerate { along_u, along_v } => json!({
            "regular": false,
            "along_u": point(&along_u, "along_u")?,
            "along_v": point(&along_v, "along_v")?,
        }),
    })
}

/// The mesh of the patch on a uniform grid of `nu` × `nv` cells over its domain.
fn mesh<S: JsonScalar>(
    grid: &[Vec<Vec<String>>],
    nu: usize,
    nv: usize,
) -> Result<TriangleMesh, CliError> {
    Ok(tessellate(&patch_of::<S, 3>(grid)?, nu, nv)?)
}

/// Writes the mesh to the files asked for and says what was written; without files, the
/// mesh itself.
fn write_mesh(
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

/// Creates `path` and lets `write` fill it, naming the path if either fails.
fn write_file(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> std::io::Result<()>,
) -> Result<(), CliError> {
    let failed = |source| CliError::Write {
        path: crate::util::quote(&path.display().to_string()),
        source,
    };
    let mut w = BufWriter::new(File::create(path).map_err(failed)?);
    write(&mut w).map_err(failed)?;
    w.flush().map_err(failed)
}
