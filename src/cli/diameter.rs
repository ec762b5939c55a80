//! `compgeo diameter`: the two points farthest apart (by rotating calipers over the hull, or
//! by brute force) and the counts; the antipodal pairs, the width and the minimum-area and
//! minimum-perimeter enclosing rectangles from the same calipers. The hull is computed once.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::calipers::{diameter_with, ConvexPolygon, DiameterAlgorithm, Rectangle, Width};
use crate::count::Counts;
use crate::geometry::{PointSet, WideFloat};
use clap::Args;
use serde::Serialize;

/// Arguments of `compgeo diameter`.
#[derive(Debug, Args)]
pub(super) struct DiameterArgs {
    #[arg(long, short, default_value = "calipers", help = DiameterAlgorithm::names(),
        long_help = DiameterAlgorithm::help())]
    algorithm: DiameterAlgorithm,
    #[command(flatten)]
    input: PointInput,
}

/// `{"algorithm": "...", "pair": [a, b], "points": [[x, y], [x, y]], "distance": d,
/// "antipodal_pairs": [[i, j], ...], "counts": {...}, "width": {"edge": [i, j], "vertex": k,
/// "width": w}, "rectangle": {"edge": [i, j], "support": [right, top, left], "corners":
/// [{"x": .., "y": ..}, ...], "area": a, "perimeter": p}, "perimeter_rectangle": {the same
/// keys}}`, a corner's coordinate beyond the range of `f64` as a JSON string holding its
/// decimal value. The counts are the diameter's (with the calipers, the hull's and theirs);
/// the antipodal pairs, width and rectangles come from the same hull
/// (ARCHITECTURE's contract: `pair`, `distance`, `antipodal_pairs`).
#[derive(Debug, Serialize)]
struct DiameterOutput {
    algorithm: &'static str,
    pair: [usize; 2],
    points: [[f64; 2]; 2],
    distance: WideFloat,
    antipodal_pairs: Vec<[usize; 2]>,
    counts: Counts,
    width: Width,
    rectangle: Rectangle,
    perimeter_rectangle: Rectangle,
}

/// Runs `compgeo diameter`.
pub(super) fn run(args: DiameterArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let set = PointSet::new(&points)?;
    let mut counts = Counts::default();
    let (d, hull) = match args.algorithm {
        DiameterAlgorithm::Calipers => {
            let hull = ConvexPolygon::hull_with(&set, &mut counts);
            (hull.diameter_with(&mut counts)?, hull)
        }
        algorithm => (
            diameter_with(&set, algorithm, &mut counts)?,
            ConvexPolygon::hull(&set),
        ),
    };
    print_json(&DiameterOutput {
        algorithm: args.algorithm.name(),
        pair: d.pair,
        points: d.pair.map(|i| [points[i].x, points[i].y]),
        distance: d.distance,
        antipodal_pairs: hull.antipodal_pairs(),
        counts,
        width: hull.width()?,
        rectangle: hull.min_area_rectangle()?,
        perimeter_rectangle: hull.min_perimeter_rectangle()?,
    })
}
