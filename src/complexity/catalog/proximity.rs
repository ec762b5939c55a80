//! Catalog entries of the Voronoi diagram ([`crate::delaunay`]) and the proximity problems
//! ([`crate::proximity`]): all nearest neighbours, the closest pair (via Delaunay and by
//! divide and conquer), the Euclidean minimum spanning tree and the largest empty circle.
//!
//! The algorithms built on the triangulation are measured on its in-circle tests (their
//! dominant cost) or, where their own work is the point, on the operation they add:
//! distance evaluations for the spanning tree's exact length sort, orientation tests for
//! the empty circle's hull tests. The divide and conquer is measured on distance
//! evaluations (strip tests and candidate pairs), on uniform points and on a grid where
//! every distance ties.

use super::claimed_entries;
use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::delaunay::voronoi_with;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::geometry::{Point2, PointSet};
use crate::proximity::{
    all_nearest_neighbours_with, closest_pair_with, euclidean_mst_with, largest_empty_circle_with,
    ClosestPairAlgorithm,
};

/// The problems measured here.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Problem {
    Voronoi,
    AllNearest,
    ClosestPair(ClosestPairAlgorithm),
    Emst,
    EmptyCircle,
}

/// One proximity algorithm on one kind of generated point set.
struct Proximity {
    problem: Problem,
    kind: PointKind,
}

/// The proximity entries: every claim of the Voronoi diagram and the proximity problems,
/// each on its input.
pub(super) fn entries() -> Vec<Entry> {
    let mut problems: Vec<(Problem, &'static Declaration)> = vec![
        (Problem::Voronoi, crate::delaunay::VORONOI),
        (Problem::AllNearest, crate::proximity::ALL_NEAREST),
    ];
    for a in ClosestPairAlgorithm::ALL {
        problems.push((Problem::ClosestPair(a), a.declaration()));
    }
    problems.push((Problem::Emst, crate::proximity::EMST));
    problems.push((Problem::EmptyCircle, crate::proximity::EMPTY_CIRCLE));
    let mut out = Vec::new();
    for (problem, declaration) in problems {
        for (_, entry) in claimed_entries(declaration, |kind| Proximity { problem, kind }) {
            out.push(entry.quick(256, 1 << 14).full(256, 1 << 19));
        }
    }
    out
}

impl Workload for Proximity {
    type Input = Vec<Point2>;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n, seed)
    }

    /// Runs the algorithm and returns the size of its answer, so nothing is optimised away.
    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<usize> {
        let set = PointSet::new(pts)?;
        Ok(match self.problem {
            Problem::Voronoi => voronoi_with(&set, counter)?.cell_count(),
            Problem::AllNearest => all_nearest_neighbours_with(&set, counter)?.len(),
            Problem::ClosestPair(a) => closest_pair_with(&set, a, counter)?.pair[1],
            Problem::Emst => euclidean_mst_with(&set, counter)?.edges.len(),
            Problem::EmptyCircle => largest_empty_circle_with(&set, counter)?.sites.len(),
        })
    }
}
