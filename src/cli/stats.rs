//! `compgeo stats`: size, distinct count and bounding box of a point set.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::geometry::{cmp_lex, PointSet};
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
    let points = args.input.read()?;
    print_json(&stats(&PointSet::new(&points)?))
}

/// Distinct points are counted after a lexicographic sort with [`cmp_lex`], under which
/// `-0.0 == 0.0`; the bounding box is the set's own (the first of equal extremes).
fn stats(points: &PointSet<'_>) -> Stats {
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
    Stats {
        points: points.len(),
        distinct,
        bbox: points
            .bounding_box()
            .map(|b| [[b.min.x, b.min.y], [b.max.x, b.max.y]]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Point2;

    fn stats_of(points: &[Point2]) -> Stats {
        stats(&PointSet::new(points).unwrap())
    }

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
            assert_eq!(stats_of(&pts).distinct, oracle, "{kind}");
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
            stats_of(&pts),
            Stats {
                points: 3,
                distinct: 3,
                bbox: Some([[-2.0, -1e300], [1e300, 3.0]]),
            }
        );
        assert_eq!(
            stats_of(&[]),
            Stats {
                points: 0,
                distinct: 0,
                bbox: None
            }
        );
    }
}
