//! `compgeo diameter`: the two points farthest apart, by rotating calipers over the hull or
//! by brute force, and the counts; also the width and the minimum-area enclosing rectangle
//! from the same calipers.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::calipers::{
    diameter_brute_force_with, diameter_with, min_area_rectangle, width, Rectangle, Width,
};
use crate::count::Counts;
use clap::Args;
use serde::Serialize;

/// Arguments of `compgeo diameter`.
#[derive(Debug, Args)]
pub(super) struct DiameterArgs {
    /// Compare every pair (O(n²)) instead of rotating calipers over the hull
    #[arg(long)]
    brute_force: bool,
    #[command(flatten)]
    input: PointInput,
}

/// `{"pair": [a, b] or null, "points": [[x, y], [x, y]], "length": d, "counts": {...},
/// "width": {"edge": [i, j], "vertex": k, "width": w} or null, "rectangle": {"edge": [i, j],
/// "support": [right, top, left], "corners": [{"x": .., "y": ..}, ...], "area": a} or null}`.
/// The counts are the diameter's.
#[derive(Debug, Serialize)]
struct DiameterOutput {
    pair: Option<[usize; 2]>,
    points: Vec<[f64; 2]>,
    length: Option<f64>,
    counts: Counts,
    width: Option<Width>,
    rectangle: Option<Rectangle>,
}

/// Runs `compgeo diameter`.
pub(super) fn run(args: DiameterArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let mut counts = Counts::default();
    let d = if args.brute_force {
        diameter_brute_force_with(&points, &mut counts)?
    } else {
        diameter_with(&points, &mut counts)?
    };
    print_json(&DiameterOutput {
        pair: d.map(|d| [d.a, d.b]),
        points: d
            .map(|d| [d.a, d.b].map(|i| [points[i].x, points[i].y]).to_vec())
            .unwrap_or_default(),
        length: d.map(|d| d.length),
        counts,
        width: width(&points)?,
        rectangle: min_area_rectangle(&points)?,
    })
}
