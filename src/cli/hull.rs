//! `compgeo hull`: the convex hull of a point set with a chosen algorithm, and its counts.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::geometry::PointSet;
use crate::hull::{convex_hull_with, Algorithm, HullOptions};
use clap::Args;
use serde::Serialize;

/// Arguments of `compgeo hull`.
#[derive(Debug, Args)]
pub(super) struct HullArgs {
    #[arg(long, short, default_value = "akl-toussaint", help = Algorithm::names(),
        long_help = Algorithm::help())]
    algorithm: Algorithm,
    /// Also list the points in the middle of hull edges, in boundary order
    #[arg(long)]
    keep_collinear: bool,
    #[command(flatten)]
    input: PointInput,
}

/// `{"algorithm": "...", "hull": [i, ...], "vertices": [[x, y], ...], "counts": {...}}`.
#[derive(Debug, Serialize)]
struct HullOutput {
    algorithm: &'static str,
    hull: Vec<usize>,
    vertices: Vec<[f64; 2]>,
    counts: Counts,
}

/// Runs `compgeo hull`.
pub(super) fn run(args: HullArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let mut counts = Counts::default();
    let options = HullOptions {
        keep_collinear: args.keep_collinear,
    };
    let hull = convex_hull_with(
        &PointSet::new(&points)?,
        args.algorithm,
        options,
        &mut counts,
    );
    let vertices = hull.iter().map(|&i| [points[i].x, points[i].y]).collect();
    print_json(&HullOutput {
        algorithm: args.algorithm.name(),
        hull,
        vertices,
        counts,
    })
}
