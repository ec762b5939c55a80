//! `compgeo triangle eval|subdivide|elevate|tessellate`: one operation on a triangular Bézier
//! patch given by its control points, in `f64` or (with `--exact`) in exact rationals.
//!
//! The control points are JSON `[[x, y, z], ...]` in any dimension from 1 to 4, flat, in the
//! storage order of [`TriangularPatch`]: the rows of constant k from k = 0 to n, each by
//! increasing j (b_{n00}, b_{n−1,1,0}, …, b_{0n0}, b_{n−1,0,1}, …, b_{00n}). The degree is
//! `--degree n` or found from the count, (n + 1)(n + 2)/2. Numbers are read as `bezier` reads
//! them (with `--exact`, `0.1` is 1/10 and every number prints as a string). A point of the
//! triangle is `--u U --v V`, with w = 1 − u − v, or with `--w W` as well, in which case
//! u + v + w must be exactly 1 (an error otherwise).
//!
//! Patches print as `{"degree": n, "control": [[x, y, z], ...]}` in the same order.
//! `tessellate` needs points in three dimensions and writes the mesh as Wavefront OBJ
//! (`--obj`) and ASCII STL (`--stl`), printing its size, or prints the mesh itself.

use super::bezier::{point, points, JsonScalar};
use super::input::{inline_or_stdin, parse_number_arrays};
use super::interpolate::to_points;
use super::output::print_json;
use super::surface::write_mesh;
use super::CliError;
use crate::count::Counts;
use crate::spline::parse_scalar;
use crate::surface::{Barycentric, TriangularPatch};
use clap::{Args, Subcommand, ValueEnum};
use num_rational::BigRational;
use serde_json::{json, Value};
use std::path::PathBuf;

/// Arguments of `compgeo triangle`.
#[derive(Debug, Args)]
pub(super) struct TriangleArgs {
    #[command(subcommand)]
    op: Op,
}

/// The operations.
#[derive(Debug, Subcommand)]
enum Op {
    /// The point b(u, v, w), by de Casteljau's algorithm or the Bernstein sum, with its counts
    Eval {
        #[command(flatten)]
        patch: PatchArgs,
        #[command(flatten)]
        at: PointArgs,
        /// How to evaluate
        #[arg(long, value_enum, default_value = "de-casteljau")]
        algorithm: Evaluation,
    },
    /// The patches over x q r, p x r and p q x for a point x (--u, --v, --w), or with
    /// --midpoints over the four triangles of the edge midpoints a, b, c: p c b, c q a, b a r
    /// and a b c
    Subdivide {
        #[command(flatten)]
        patch: PatchArgs,
        /// Split into four at the midpoints of the edges instead of three at a point
        #[arg(long, conflicts_with_all = ["u", "v", "w"])]
        midpoints: bool,
        /// The barycentric coordinate u of the point: a decimal or a fraction such as 1/3
        #[arg(
            long = "u",
            value_name = "U",
            allow_hyphen_values = true,
            required_unless_present = "midpoints"
        )]
        u: Option<String>,
        /// The coordinate v
        #[arg(
            long = "v",
            value_name = "V",
            allow_hyphen_values = true,
            required_unless_present = "midpoints"
        )]
        v: Option<String>,
        /// The coordinate w [default: 1 − u − v]; given, u + v + w must be exactly 1
        #[arg(long = "w", value_name = "W", allow_hyphen_values = true)]
        w: Option<String>,
    },
    /// The same patch with its degree raised to --to, or by --by (default by one)
    Elevate {
        #[command(flatten)]
        patch: PatchArgs,
        /// The target degree, at least the patch's [default: its degree plus --by]
        #[arg(long, conflicts_with = "by")]
        to: Option<usize>,
        /// How many degrees to raise
        #[arg(long, default_value_t = 1)]
        by: usize,
    },
    /// A triangle mesh with unit normals on the uniform refinement of the triangle, written
    /// as OBJ and/or STL
    Tessellate {
        #[command(flatten)]
        patch: PatchArgs,
        /// Segments per edge: (m + 1)(m + 2)/2 vertices, m² triangles
        #[arg(long, default_value_t = 16)]
        segments: usize,
        /// Write the mesh as Wavefront OBJ to this file
        #[arg(long, value_name = "PATH")]
        obj: Option<PathBuf>,
        /// Write the mesh as ASCII STL to this file
        #[arg(long, value_name = "PATH")]
        stl: Option<PathBuf>,
    },
}

/// The evaluation algorithms.
#[derive(Debug, Clone, Copy, ValueEnum)]
enum Evaluation {
    /// n levels of three-point affine combinations
    DeCasteljau,
    /// Σ b_{ijk} B^n_{ijk}(u, v, w), one multiply-add per term
    Bernstein,
}

/// The patch and the arithmetic, shared by the operations.
#[derive(Debug, Args)]
pub(super) struct PatchArgs {
    /// The control points as JSON [[x, y, z], ...] (dimension 1 to 4), rows of constant k
    /// first, each by increasing j; or `-` to read them from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    pub(super) control: String,
    /// The degree n [default: found from the count (n + 1)(n + 2)/2]
    #[arg(long)]
    degree: Option<usize>,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    pub(super) exact: bool,
}

/// A point of the triangle.
#[derive(Debug, Args)]
struct PointArgs {
    /// The barycentric coordinate u: a decimal or a fraction such as 1/3
    #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
    u: String,
    /// The coordinate v
    #[arg(long = "v", value_name = "V", allow_hyphen_values = true)]
    v: String,
    /// The coordinate w [default: 1 − u − v]; given, u + v + w must be exactly 1
    #[arg(long = "w", value_name = "W", allow_hyphen_values = true)]
    w: Option<String>,
}

/// Runs `compgeo triangle`.
pub(super) fn run(args: TriangleArgs) -> Result<(), CliError> {
    let patch = match &args.op {
        Op::Eval { patch, .. }
        | Op::Subdivide { patch, .. }
        | Op::Elevate { patch, .. }
        | Op::Tessellate { patch, .. } => patch,
    };
    let rows = parse_number_arrays(&inline_or_stdin(&patch.control)?)?;
    let d = rows[0].len();
    if let Op::Tessellate {
        segments, obj, stl, ..
    } = &args.op
    {
        if d != 3 {
            return Err(CliError::Shape(format!(
                "a tessellation needs points in three dimensions; the control points have {d}"
            )));
        }
        let mesh = if patch.exact {
            patch_of::<BigRational, 3>(patch, &rows)?.tessellate(*segments)?
        } else {
            patch_of::<f64, 3>(patch, &rows)?.tessellate(*segments)?
        };
        return print_json(&write_mesh(&mesh, obj.as_deref(), stl.as_deref())?);
    }
    let value = by_scalar_and_dimension!(
        patch.exact,
        d,
        "control points",
        run_typed(&args.op, patch, &rows)
    )?;
    print_json(&value)
}

/// The patch the arguments describe, each point named in errors as `control point i`.
pub(super) fn patch_of<S: JsonScalar, const D: usize>(
    args: &PatchArgs,
    rows: &[Vec<String>],
) -> Result<TriangularPatch<S, D>, CliError> {
    let control = to_points::<S, D>(rows, |i| format!("control point {i}"))?;
    Ok(match args.degree {
        Some(n) => TriangularPatch::with_degree(n, control)?,
        None => TriangularPatch::new(control)?,
    })
}

/// The point (u, v, w) of the arguments, w = 1 − u − v when it is not given.
fn point_of<S: JsonScalar>(u: &str, v: &str, w: Option<&str>) -> Result<Barycentric<S>, CliError> {
    let (u, v): (S, S) = (parse_scalar(u, "u")?, parse_scalar(v, "v")?);
    Ok(match w {
        Some(w) => Barycentric::new(u, v, parse_scalar(w, "w")?)?,
        None => Barycentric::from_uv(u, v)?,
    })
}

/// A patch as printed, the field `name` naming it in errors.
fn patch_json<S: JsonScalar, const D: usize>(
    b: &TriangularPatch<S, D>,
    name: &str,
) -> Result<Value, CliError> {
    Ok(json!({"degree": b.degree(), "control": points(b.points(), name)?}))
}

fn run_typed<S: JsonScalar, const D: usize>(
    op: &Op,
    args: &PatchArgs,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let b = patch_of::<S, D>(args, rows)?;
    let mut counts = Counts::default();
    Ok(match op {
        Op::Eval { at, algorithm, .. } => {
            let x = point_of::<S>(&at.u, &at.v, at.w.as_deref())?;
            let (p, name) = match algorithm {
                Evaluation::DeCasteljau => (b.de_casteljau_with(&x, &mut counts), "de-casteljau"),
                Evaluation::Bernstein => (b.bernstein_sum_with(&x, &mut counts), "bernstein"),
            };
            let printed = point(&p, "point").map_err(|_| {
                CliError::Usage(
                    "the point is beyond the range of f64 (or its evaluation overflows); use --exact"
                        .to_string(),
                )
            })?;
            json!({
                "point": printed,
                "degree": b.degree(),
                "algorithm": name,
                "counts": counts,
            })
        }
        Op::Subdivide {
            midpoints, u, v, w, ..
        } => {
            let pieces: Vec<TriangularPatch<S, D>> = if *midpoints {
                b.split_four_with(&mut counts)?.to_vec()
            } else {
                // clap requires --u and --v without --midpoints.
                let (Some(u), Some(v)) = (u, v) else {
                    return Err(CliError::Usage(
                        "subdivide needs --u and --v, or --midpoints".to_string(),
                    ));
                };
                let x = point_of::<S>(u, v, w.as_deref())?;
                b.subdivide_with(&x, &mut counts)?.to_vec()
            };
            let patches = pieces
                .iter()
                .enumerate()
                .map(|(k, piece)| patch_json(piece, &format!("patches[{k}].control")))
                .collect::<Result<Vec<_>, _>>()?;
            json!({"patches": patches, "counts": counts})
        }
        Op::Elevate { to, by, .. } => {
            let m = to.unwrap_or(b.degree().saturating_add(*by));
            let e = b.elevate_to_with(m, &mut counts)?;
            let mut out = patch_json(&e, "control")?;
            out["counts"] = json!(counts);
            out
        }
        Op::Tessellate { .. } => unreachable!("tessellate runs in three dimensions before"),
    })
}
