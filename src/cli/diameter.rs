//! `compgeo diameter`: the two points farthest apart, by rotating calipers over the hull or
//! by brute force, and the counts.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::calipers::{diameter_brute_force_with, diameter_with};
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

/// `{"pair": [a, b] or null, "points": [[x, y], [x, y]], "length": d, "counts": {...}}`.
#[derive(Debug, Serialize)]
struct DiameterOutput {
    pair: Option<[usize; 2]>,
    points: Vec<[f64; 2]>,
    length: Option<f64>,
    counts: Counts,
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
    })
}
