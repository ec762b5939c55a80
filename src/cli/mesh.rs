//! `compgeo mesh subdivide --scheme S --rounds k IN.obj [--out OUT.obj] [--exact]`: k rounds
//! of a subdivision scheme on a polygon mesh read from Wavefront OBJ (a path, or `-` for
//! standard input).
//!
//! Output, by `--out`:
//!
//! - `--out PATH`: the refined mesh is written to PATH as OBJ, and stdout gets one JSON
//!   object: `{"scheme", "rounds", "input": {...}, "output": {...}, "counts": {...},
//!   "out": PATH}`, where `input` and `output` hold `vertices`, `edges`, `faces`,
//!   `boundary_loops` and `euler_characteristic`;
//! - no `--out`: the same object, with the refined mesh in it as `"positions"` (`[[x, y, z],
//!   ...]`) and `"faces"` (`[[v, ...], ...]`, 0-based, counter-clockwise), so that the
//!   command keeps the one-JSON-object contract;
//! - `--out -`: the OBJ text on stdout and nothing else, for pipes
//!   (`compgeo mesh subdivide --rounds 2 in.obj --out - > fine.obj`).
//!
//! With `--exact` the coordinates are read as exact rationals (`0.1` is 1/10), the rounds
//! are computed exactly, and the JSON prints every coordinate as a string such as `"47/18"`;
//! OBJ output rounds them to the nearest `f64`. A malformed OBJ line or a mesh that is not
//! an oriented manifold exits with code 2 and one `error:` line naming the line or the face.

use super::bezier::{points, JsonScalar};
use super::input::read_text;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::mesh::{read_obj, subdivide_with, write_obj, PolygonMesh, Scheme};
use clap::{Args, Subcommand};
use num_rational::BigRational;
use serde_json::{json, Value};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Arguments of `compgeo mesh`.
#[derive(Debug, Args)]
pub(super) struct MeshArgs {
    #[command(subcommand)]
    op: Op,
}

/// The operations.
#[derive(Debug, Subcommand)]
enum Op {
    /// k rounds of a subdivision scheme on a mesh read from OBJ, written as OBJ (--out) or
    /// printed as JSON
    Subdivide {
        /// The mesh: a Wavefront OBJ file, or - for standard input
        #[arg(value_name = "IN")]
        input: PathBuf,
        /// The scheme
        #[arg(long, default_value = "catmull-clark", value_parser = parse_scheme,
              long_help = scheme_help())]
        scheme: Scheme,
        /// How many rounds
        #[arg(long, default_value_t = 1)]
        rounds: usize,
        /// Write the refined mesh as OBJ to this file (- for stdout, instead of the JSON);
        /// without it the mesh is printed in the JSON
        #[arg(long, value_name = "PATH")]
        out: Option<PathBuf>,
        /// Read and compute in exact rationals; JSON coordinates print as strings "p/q"
        #[arg(long)]
        exact: bool,
    },
}

pub(super) fn parse_scheme(s: &str) -> Result<Scheme, String> {
    s.parse::<Scheme>().map_err(|e| e.to_string())
}

pub(super) fn scheme_help() -> String {
    format!("The scheme:\n{}", Scheme::help())
}

/// Runs `compgeo mesh`.
pub(super) fn run(args: MeshArgs) -> Result<(), CliError> {
    match args.op {
        Op::Subdivide {
            input,
            scheme,
            rounds,
            out,
            exact,
        } => {
            if exact {
                run_subdivide::<BigRational>(&input, scheme, rounds, out.as_deref())
            } else {
                run_subdivide::<f64>(&input, scheme, rounds, out.as_deref())
            }
        }
    }
}

fn run_subdivide<S: JsonScalar>(
    input: &Path,
    scheme: Scheme,
    rounds: usize,
    out: Option<&Path>,
) -> Result<(), CliError> {
    let text = read_text(input)?;
    let mesh: PolygonMesh<S, 3> = read_obj(text.as_bytes())?;
    let mut counts = Counts::default();
    let fine = subdivide_with(&mesh, scheme, rounds, &mut counts)?;
    let mut summary = json!({
        "scheme": scheme.name(),
        "rounds": rounds,
        "input": sizes(&mesh),
        "output": sizes(&fine),
        "counts": counts,
    });
    match out {
        Some(path) if path == Path::new("-") => {
            let stdout = std::io::stdout();
            let mut w = BufWriter::new(stdout.lock());
            write_obj(&fine, &mut w)
                .and_then(|()| w.flush())
                .map_err(CliError::Output)
        }
        Some(path) => {
            let failed = |source| CliError::Write {
                path: crate::util::quote(&path.display().to_string()),
                source,
            };
            let mut w = BufWriter::new(File::create(path).map_err(failed)?);
            write_obj(&fine, &mut w)
                .and_then(|()| w.flush())
                .map_err(failed)?;
            summary["out"] = json!(path.display().to_string());
            print_json(&summary)
        }
        None => {
            summary["positions"] = points(fine.positions(), "positions")?;
            let t = fine.topology();
            summary["faces"] = Value::Array(
                (0..t.face_count())
                    .map(|f| json!(t.face_vertices(f)))
                    .collect(),
            );
            print_json(&summary)
        }
    }
}

/// The counts of a mesh as the JSON prints them.
fn sizes<S: JsonScalar>(mesh: &PolygonMesh<S, 3>) -> Value {
    let t = mesh.topology();
    json!({
        "vertices": t.vertex_count(),
        "edges": t.edge_count(),
        "faces": t.face_count(),
        "boundary_loops": t.boundary_loop_count(),
        "euler_characteristic": t.euler_characteristic(),
    })
}
