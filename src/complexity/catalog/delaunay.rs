//! Catalog entries of [`crate::delaunay`]: the incremental builder on uniform, clustered,
//! grid (cocircular quadruples everywhere) and parabola input (points in convex position in
//! x order, the order that makes naive incremental insertion quadratic); the course's divide
//! and conquer on uniform and parabola input; Lawson's flips on the parabola, where they are
//! quadratic, at small sizes; Fortune's sweep on uniform and parabola input.
//!
//! The counted operation is the in-circle test, the Delaunay builders' characteristic
//! predicate (the flips' test), except for Fortune's sweep, which makes none: its entries
//! count comparisons (the sort, the event queue and the beach-line breakpoint tests).

use super::claimed_entries;
use crate::complexity::{Entry, Workload};
use crate::count::Counter;
use crate::delaunay::{triangulate_with, Algorithm, Triangulation};
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::geometry::{Point2, PointSet};

/// One Delaunay builder on one kind of generated point set.
struct Delaunay {
    algorithm: Algorithm,
    kind: PointKind,
}

/// The Delaunay entries: every claim the builders declare, each on its input. Lawson's flips
/// are quadratic on the parabola, where the sweep fans every point from the first one (on
/// uniform input the flips grow about as n^1.3, so the quadratic bound would not be tight
/// there); the others run to 2^15 (quick) and 2^20 (full) points.
pub(super) fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    for algorithm in Algorithm::ALL {
        let claims = claimed_entries(algorithm.declaration(), |kind| Delaunay { algorithm, kind });
        for (_, entry) in claims {
            out.push(match algorithm {
                Algorithm::Lawson => entry.quick(64, 4096).full(64, 1 << 14),
                _ => entry.quick(256, 1 << 15).full(256, 1 << 20),
            });
        }
    }
    out
}

impl Workload for Delaunay {
    type Input = Vec<Point2>;
    type Output = Triangulation;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n, seed)
    }

    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<Triangulation> {
        triangulate_with(&PointSet::new(pts)?, self.algorithm, counter)
    }

    fn output_size(&self, _input: &Vec<Point2>, t: &Triangulation) -> Option<usize> {
        Some(t.hull.len())
    }
}
