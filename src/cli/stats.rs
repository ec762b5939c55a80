//! `compgeo stats`: size, distinct count and bounding box of a point set.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::geometry::{cmp_lex, Point2};
use clap::Args;
use serde::Serialize;
use std::cmp::Ordering;

/// Arguments of `compgeo stats`.
#[derive(Debug, Args)]
pub(super) struct StatsArgs {
    #[command(flatten)]
    input: PointInput,
}

/// `{"points": n, "distinct": d, "bbox": [[xmin, ymin], [xmax, ymax]] or null}`.
#[derive(Debug, PartialEq, Serialize)]
struct Stats {
    points: usize,
    distinct: usize,
    bbox: Option<[[f64; 2]; 2]>,
}

/// Runs `compgeo stats`.
pub(super) fn run(args: StatsArgs) -> Result<(), CliError> {
    print_json(&stats(&args.input.read()?))
}

/// Distinct points are counted after a lexicographic sort with [`cmp_lex`], under which
/// `-0.0 == 0.0`; the bounding box keeps the first of equal extremes.
fn stats(points: &[Point2]) -> Stats {
    let mut sorted = points.to_vec();
    sorted.sort_unstable_by(|&a, &b| cmp_lex(a, b));
    let distinct = if sorted.is_empty() {
        0
    } else {
        1 + sorted
            .windows(2)
            .filter(|w| cmp_lex(w[0], w[1]) != Ordering::Equal)
            .count()
    };
    let bbox = points.split_first().map(|(&first, rest)| {
        let (mut lo, mut hi) = (first, first);
        for &p in rest {
            // Coordinates are validated finite, so `<` is a total order here.
            if p.x < lo.x {
                lo.x = p.x;
            }
            if p.y < lo.y {
                lo.y = p.y;
            }
            if p.x > hi.x {
                hi.x = p.x;
            }
            if p.y > hi.y {
                hi.y = p.y;
            }
        }
        [[lo.x, lo.y], [hi.x, hi.y]]
    });
    Stats {
        points: points.len(),
        distinct,
        bbox,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_distinct_points_against_a_quadratic_oracle() {
        use crate::gen::{points, PointKind};
        for kind in [PointKind::NearDuplicates, PointKind::Grid, PointKind::Tiny] {
            let mut pts = points(kind, 300, 3).unwrap();
            // Exact duplicates and signed zeros on top of the generated set.
            pts.extend_from_within(..40);
            pts.push(Point2::new(0.0, -0.0));
            pts.push(Point2::new(-0.0, 0.0));
            let oracle = (0..pts.len())
                .filter(|&i| (0..i).all(|j| !(pts[j].x == pts[i].x && pts[j].y == pts[i].y)))
                .count();
            assert_eq!(stats(&pts).distinct, oracle, "{kind}");
        }
    }

    #[test]
    fn bbox_of_extremes_and_empty() {
        let pts = [
            Point2::new(1e300, -1e300),
            Point2::new(5e-324, 1e-300),
            Point2::new(-2.0, 3.0),
        ];
        assert_eq!(
            stats(&pts),
            Stats {
                points: 3,
                distinct: 3,
                bbox: Some([[-2.0, -1e300], [1e300, 3.0]]),
            }
        );
        assert_eq!(
            stats(&[]),
            Stats {
                points: 0,
                distinct: 0,
                bbox: None
            }
        );
    }
}
