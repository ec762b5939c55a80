//! `compgeo diameter`: the two points farthest apart, by rotating calipers over the hull or
//! by brute force, and the counts; also the width and the minimum-area enclosing rectangle
//! from the same calipers.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::calipers::{
    antipodal_pairs, diameter_brute_force_with, diameter_with, min_area_rectangle, width,
    Rectangle, Width,
};
use crate::count::Counts;
use crate::hull::{akl_toussaint, HullOptions};
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

/// `{"pair": [a, b] or null, "points": [[x, y], [x, y]], "distance": d or null,
/// "antipodal_pairs": [[i, j], ...], "counts": {...},
/// "width": {"edge": [i, j], "vertex": k, "width": w} or null, "rectangle": {"edge": [i, j],
/// "support": [right, top, left], "corners": [{"x": .., "y": ..}, ...], "area": a} or null}`.
/// The counts are the diameter's; the antipodal pairs are those of the hull (ARCHITECTURE's
/// contract: `pair`, `distance`, `antipodal_pairs`).
#[derive(Debug, Serialize)]
struct DiameterOutput {
    pair: Option<[usize; 2]>,
    points: Vec<[f64; 2]>,
    distance: Option<f64>,
    antipodal_pairs: Vec<[usize; 2]>,
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
    let hull = akl_toussaint(&points, HullOptions::default())?;
    print_json(&DiameterOutput {
        pair: d.map(|d| [d.a, d.b]),
        points: d
            .map(|d| [d.a, d.b].map(|i| [points[i].x, points[i].y]).to_vec())
            .unwrap_or_default(),
        distance: d.map(|d| d.length),
        antipodal_pairs: antipodal_pairs(&points, &hull)?
            .into_iter()
            .map(|(i, j)| [i, j])
            .collect(),
        counts,
        width: width(&points)?,
        rectangle: min_area_rectangle(&points)?,
    })
}
