//! Catalog entries of [`crate::delaunay`]: the incremental builder on uniform, clustered,
//! grid (cocircular quadruples everywhere) and parabola input (points in convex position in
//! x order, the order that makes naive incremental insertion quadratic); the seed's divide
//! and conquer on uniform and parabola input; Lawson's flips on the parabola, where they are
//! quadratic, at small sizes; Fortune's sweep on uniform and parabola input.
//!
//! The counted operation is the in-circle test, the Delaunay builders' characteristic
//! predicate (the flips' test), except for Fortune's sweep, which makes none: its entries
//! count comparisons (the sort, the event queue and the beach-line breakpoint tests).

use crate::complexity::{Bound, Entry, Workload};
use crate::count::{Counter, Operation};
use crate::delaunay::{Algorithm, Triangulation};
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::geometry::Point2;

/// One Delaunay builder on one kind of generated point set.
struct Delaunay {
    algorithm: Algorithm,
    kind: PointKind,
}

/// The Delaunay entries: the incremental builder on four inputs, divide and conquer on
/// uniform and parabola input, Lawson's flips on the parabola (its quadratic case),
/// Fortune's sweep on uniform and parabola input.
pub(super) fn entries() -> Vec<Entry> {
    let mut out: Vec<Entry> = [
        PointKind::UniformSquare,
        PointKind::Clustered,
        PointKind::Grid,
        PointKind::Parabola,
    ]
    .into_iter()
    .map(|kind| {
        delaunay(Algorithm::Incremental, kind, Bound::NLogN)
            .quick(256, 1 << 15)
            .full(256, 1 << 20)
    })
    .collect();
    // The seed's divide and conquer: O(n log n) in the worst case, also on the parabola.
    for kind in [PointKind::UniformSquare, PointKind::Parabola] {
        out.push(
            delaunay(Algorithm::DivideAndConquer, kind, Bound::NLogN)
                .quick(256, 1 << 15)
                .full(256, 1 << 20),
        );
    }
    // Lawson's flips from a sweep triangulation: quadratic on the parabola, where the sweep
    // fans every point from the first one (on uniform input the flips grow about as n^1.3,
    // so the quadratic bound would not be tight there).
    out.push(
        delaunay(Algorithm::Lawson, PointKind::Parabola, Bound::Quadratic)
            .quick(64, 4096)
            .full(64, 1 << 14),
    );
    // Fortune's sweep: O(n log n) expected on every input, also on the parabola, where
    // insertion in x order goes quadratic.
    for kind in [PointKind::UniformSquare, PointKind::Parabola] {
        out.push(
            Entry::new(
                "delaunay/fortune",
                Bound::NLogN,
                Operation::Comparisons,
                Delaunay {
                    algorithm: Algorithm::Fortune,
                    kind,
                },
            )
            .input(kind.name())
            .quick(256, 1 << 15)
            .full(256, 1 << 20),
        );
    }
    out
}

fn delaunay(algorithm: Algorithm, kind: PointKind, bound: Bound) -> Entry {
    let id = format!("delaunay/{}", algorithm.name());
    Entry::new(
        &id,
        bound,
        Operation::IncircleTests,
        Delaunay { algorithm, kind },
    )
    .input(kind.name())
}

impl Workload for Delaunay {
    type Input = Vec<Point2>;
    type Output = Triangulation;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n, seed)
    }

    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<Triangulation> {
        self.algorithm.triangulate_with(pts, counter)
    }

    fn output_size(&self, _input: &Vec<Point2>, t: &Triangulation) -> Option<usize> {
        Some(t.hull.len())
    }
}
