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

use crate::complexity::{Bound, Entry, Workload};
use crate::count::{Counter, Operation};
use crate::delaunay::voronoi_with;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::geometry::Point2;
use crate::proximity::{
    all_nearest_neighbours_with, closest_pair_divide_and_conquer_with, closest_pair_with,
    euclidean_mst_with, largest_empty_circle_with,
};

/// The proximity problems, by catalog name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Problem {
    Voronoi,
    AllNearest,
    ClosestPairDelaunay,
    ClosestPairDivideAndConquer,
    Emst,
    EmptyCircle,
}

/// One proximity algorithm on one kind of generated point set.
struct Proximity {
    problem: Problem,
    kind: PointKind,
}

/// The proximity entries.
pub(super) fn entries() -> Vec<Entry> {
    use Operation::{DistanceEvaluations, IncircleTests, OrientationTests};
    use PointKind::{Grid, UniformDisk, UniformSquare};
    [
        (
            Problem::Voronoi,
            "voronoi/delaunay-dual",
            UniformSquare,
            IncircleTests,
        ),
        (
            Problem::AllNearest,
            "all-nearest-neighbours/delaunay",
            UniformSquare,
            IncircleTests,
        ),
        (
            Problem::ClosestPairDelaunay,
            "closest-pair/delaunay",
            UniformSquare,
            IncircleTests,
        ),
        (
            Problem::ClosestPairDivideAndConquer,
            "closest-pair/divide-and-conquer",
            UniformSquare,
            DistanceEvaluations,
        ),
        (
            Problem::ClosestPairDivideAndConquer,
            "closest-pair/divide-and-conquer",
            Grid,
            DistanceEvaluations,
        ),
        (
            Problem::Emst,
            "emst/delaunay-kruskal",
            UniformSquare,
            DistanceEvaluations,
        ),
        (
            Problem::EmptyCircle,
            "empty-circle/voronoi",
            UniformDisk,
            OrientationTests,
        ),
    ]
    .into_iter()
    .map(|(problem, id, kind, operation)| {
        Entry::new(id, Bound::NLogN, operation, Proximity { problem, kind })
            .input(kind.name())
            .quick(256, 1 << 14)
            .full(256, 1 << 19)
    })
    .collect()
}

impl Workload for Proximity {
    type Input = Vec<Point2>;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n, seed)
    }

    /// Runs the algorithm and returns the size of its answer, so nothing is optimised away.
    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<usize> {
        Ok(match self.problem {
            Problem::Voronoi => voronoi_with(pts, counter)?.cell_count(),
            Problem::AllNearest => all_nearest_neighbours_with(pts, counter)?.len(),
            Problem::ClosestPairDelaunay => closest_pair_with(pts, counter)?.pair[1],
            Problem::ClosestPairDivideAndConquer => {
                closest_pair_divide_and_conquer_with(pts, counter)?.pair[1]
            }
            Problem::Emst => euclidean_mst_with(pts, counter)?.edges.len(),
            Problem::EmptyCircle => largest_empty_circle_with(pts, counter)?.sites.len(),
        })
    }
}
