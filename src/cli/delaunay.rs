//! `compgeo delaunay`: the Delaunay triangulation of a point set with a chosen builder.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::delaunay::{triangulate_with, Algorithm};
use crate::geometry::PointSet;
use clap::Args;
use serde::Serialize;

/// Arguments of `compgeo delaunay`.
#[derive(Debug, Args)]
pub(super) struct DelaunayArgs {
    #[arg(long, short, default_value = "incremental", help = Algorithm::names(),
        long_help = Algorithm::help())]
    algorithm: Algorithm,
    #[command(flatten)]
    input: PointInput,
}

/// `{"algorithm": "...", "triangles": [[a, b, c], ...], "hull": [...],
/// "duplicates": [[dropped, kept], ...], "counts": {...}}`, triangles counter-clockwise.
#[derive(Debug, Serialize)]
struct DelaunayOutput {
    algorithm: &'static str,
    triangles: Vec<[usize; 3]>,
    hull: Vec<usize>,
    duplicates: Vec<[usize; 2]>,
    counts: Counts,
}

/// Runs `compgeo delaunay`.
pub(super) fn run(args: DelaunayArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let mut counts = Counts::default();
    let t = triangulate_with(&PointSet::new(&points)?, args.algorithm, &mut counts)?;
    print_json(&DelaunayOutput {
        algorithm: args.algorithm.name(),
        triangles: (0..t.triangle_count()).map(|k| t.triangle(k)).collect(),
        hull: t.hull,
        duplicates: t.duplicates,
        counts,
    })
}
