//! Catalog entries of [`crate::hull`] and [`crate::calipers`]: each hull algorithm on the
//! input that shows its bound, Jarvis's march and Chan's algorithm on both sides of their
//! output sensitivity (few vertices in a disk, every point a vertex on a circle), and the
//! diameter by brute force and by calipers over a convex polygon.
//!
//! The counted operation is the orientation test, the course's "signed area" (quickhull's
//! farthest-point test and the calipers' direction test are signed areas too); the monotone
//! chain and the Akl–Toussaint filter are measured on comparisons, where their cost lies.

use crate::calipers::{antipodal_pairs_with, diameter_brute_force_with};
use crate::complexity::{Bound, Entry, Workload};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::geometry::Point2;
use crate::hull::{monotone_chain_with, Algorithm, HullOptions};

/// One hull algorithm on one kind of generated point set.
struct Hull {
    algorithm: Algorithm,
    kind: PointKind,
}

/// The diameter of generated points by comparing all pairs.
struct BruteDiameter;

/// The antipodal pairs of a convex polygon: the hull of points on a circle, computed while
/// preparing, so only the calipers are measured.
struct Calipers;

/// The hull and diameter entries.
pub(super) fn entries() -> Vec<Entry> {
    vec![
        hull(
            Algorithm::BruteForce,
            PointKind::UniformSquare,
            Bound::Cubic,
            Operation::OrientationTests,
        )
        .quick(8, 128)
        .full(8, 512),
        hull(
            Algorithm::Jarvis,
            PointKind::UniformDisk,
            Bound::NH,
            Operation::OrientationTests,
        )
        .quick(256, 1 << 14)
        .full(256, 1 << 18),
        hull(
            Algorithm::Jarvis,
            PointKind::Cocircular,
            Bound::NH,
            Operation::OrientationTests,
        )
        .quick(64, 2048)
        .full(64, 1 << 14),
        hull(
            Algorithm::Graham,
            PointKind::UniformDisk,
            Bound::NLogN,
            Operation::OrientationTests,
        )
        .quick(256, 1 << 15)
        .full(256, 1 << 19),
        hull(
            Algorithm::Graham,
            PointKind::Cocircular,
            Bound::NLogN,
            Operation::OrientationTests,
        )
        .quick(256, 1 << 15)
        .full(256, 1 << 18),
        hull(
            Algorithm::MonotoneChain,
            PointKind::UniformDisk,
            Bound::NLogN,
            Operation::Comparisons,
        )
        .quick(256, 1 << 15)
        .full(256, 1 << 19),
        hull(
            Algorithm::AklToussaint,
            PointKind::UniformSquare,
            Bound::Linear,
            Operation::Comparisons,
        )
        .quick(256, 1 << 16)
        .full(256, 1 << 20),
        hull(
            Algorithm::Chan,
            PointKind::UniformDisk,
            Bound::NLogH,
            Operation::OrientationTests,
        )
        .quick(256, 1 << 15)
        .full(256, 1 << 19),
        hull(
            Algorithm::Chan,
            PointKind::Cocircular,
            Bound::NLogH,
            Operation::OrientationTests,
        )
        .quick(256, 1 << 15)
        .full(256, 1 << 18),
        hull(
            Algorithm::Quickhull,
            PointKind::UniformDisk,
            Bound::NLogN,
            Operation::OrientationTests,
        )
        .quick(256, 1 << 15)
        .full(256, 1 << 19),
        Entry::new(
            "diameter/brute-force",
            Bound::Quadratic,
            Operation::DistanceEvaluations,
            BruteDiameter,
        )
        .input(PointKind::UniformDisk.name())
        .quick(64, 2048)
        .full(64, 1 << 13),
        Entry::new(
            "diameter/calipers",
            Bound::Linear,
            Operation::OrientationTests,
            Calipers,
        )
        .input("convex-polygon")
        .quick(256, 1 << 15)
        .full(256, 1 << 18),
    ]
}

fn hull(algorithm: Algorithm, kind: PointKind, bound: Bound, operation: Operation) -> Entry {
    let id = format!("hull/{}", algorithm.name());
    Entry::new(&id, bound, operation, Hull { algorithm, kind }).input(kind.name())
}

impl Workload for Hull {
    type Input = Vec<Point2>;
    type Output = Vec<usize>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n, seed)
    }

    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<Vec<usize>> {
        self.algorithm
            .hull_with(pts, HullOptions::default(), counter)
    }

    fn output_size(&self, _input: &Vec<Point2>, hull: &Vec<usize>) -> Option<usize> {
        Some(hull.len())
    }
}

impl Workload for BruteDiameter {
    type Input = Vec<Point2>;
    type Output = ();

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(PointKind::UniformDisk, n, seed)
    }

    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<()> {
        diameter_brute_force_with(pts, counter).map(drop)
    }
}

impl Workload for Calipers {
    /// The points and their hull, counter-clockwise.
    type Input = (Vec<Point2>, Vec<usize>);
    type Output = Vec<(usize, usize)>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = points(PointKind::Cocircular, n, seed)?;
        let hull = monotone_chain_with(&pts, HullOptions::default(), &mut NoCount)?;
        Ok((pts, hull))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, counter: &mut C) -> Result<Self::Output> {
        antipodal_pairs_with(&input.0, &input.1, counter)
    }

    fn output_size(&self, input: &Self::Input, _pairs: &Self::Output) -> Option<usize> {
        Some(input.1.len())
    }
}
