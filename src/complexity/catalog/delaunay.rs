//! Catalog entries of [`crate::delaunay`]: each builder on uniform, clustered, grid
//! (cocircular quadruples everywhere) and parabola input (points in convex position in x
//! order, the order that makes naive incremental insertion quadratic).
//!
//! The counted operation is the in-circle test, the Delaunay builders' characteristic
//! predicate (the flips' test).

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

/// The Delaunay entries: every builder of [`Algorithm::ALL`] on every input.
pub(super) fn entries() -> Vec<Entry> {
    let kinds = [
        PointKind::UniformSquare,
        PointKind::Clustered,
        PointKind::Grid,
        PointKind::Parabola,
    ];
    Algorithm::ALL
        .into_iter()
        .flat_map(|algorithm| kinds.map(|kind| (algorithm, kind)))
        .map(|(algorithm, kind)| {
            let id = format!("delaunay/{}", algorithm.name());
            Entry::new(
                &id,
                Bound::NLogN,
                Operation::IncircleTests,
                Delaunay { algorithm, kind },
            )
            .input(kind.name())
            .quick(256, 1 << 15)
            .full(256, 1 << 20)
        })
        .collect()
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
