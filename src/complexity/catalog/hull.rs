//! Catalog entries of [`crate::hull`] and [`crate::calipers`]: each hull algorithm on the
//! input that shows its bound, Jarvis's march and Chan's algorithm on both sides of their
//! output sensitivity (few vertices in a disk, every point a vertex on a circle), the
//! diameter by brute force, and the calipers over a convex polygon (every point of a circle a
//! vertex, so h = n): the antipodal pairs, the diameter, the width and the minimum-area
//! rectangle, each Θ(h) after the hull.
//!
//! The counted operation is the orientation test, the course's "signed area" (quickhull's
//! farthest-point test and the calipers' direction test are signed areas too); the monotone
//! chain and the Akl–Toussaint filter are measured on comparisons, where their cost lies.

use super::claimed_entries;
use crate::calipers::{
    diameter_with, ConvexPolygon, DiameterAlgorithm, ANTIPODAL_PAIRS, MIN_AREA_RECTANGLE,
    MIN_PERIMETER_RECTANGLE, WIDTH,
};
use crate::complexity::{Entry, Workload};
use crate::count::{Counter, NoCount};
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::geometry::{Point2, PointSet};
use crate::hull::{convex_hull_with, monotone_chain_with, Algorithm, HullOptions};

/// One hull algorithm on one kind of generated point set.
struct Hull {
    algorithm: Algorithm,
    kind: PointKind,
}

/// The diameter of generated points by comparing all pairs.
struct BruteDiameter;

/// A caliper algorithm on a convex polygon: the hull of points on a circle, computed while
/// preparing, so only the calipers are measured (the check of the polygon included, as the
/// calipers' own validation was before the polygon type existed).
struct Calipers(Caliper);

/// What the calipers compute.
#[derive(Debug, Clone, Copy)]
enum Caliper {
    /// The antipodal pairs (orientation tests).
    AntipodalPairs,
    /// The diameter: the farthest antipodal pair (distance evaluations).
    Diameter,
    /// The width (orientation tests of the three calipers).
    Width,
    /// The minimum-area enclosing rectangle (orientation tests of the four calipers).
    MinAreaRectangle,
    /// The minimum-perimeter enclosing rectangle (the same calipers).
    MinPerimeterRectangle,
}

/// The hull and diameter entries: every claim the hull algorithms declare, each on its input.
pub(super) fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    for algorithm in Algorithm::ALL {
        let claims = claimed_entries(algorithm.declaration(), |kind| Hull { algorithm, kind });
        for (kind, entry) in claims {
            out.push(match algorithm {
                Algorithm::BruteForce => entry.quick(8, 128).full(8, 512),
                Algorithm::Jarvis if kind == PointKind::Cocircular => {
                    entry.quick(64, 2048).full(64, 1 << 14)
                }
                Algorithm::Jarvis => entry.quick(256, 1 << 14).full(256, 1 << 18),
                Algorithm::AklToussaint => entry.quick(256, 1 << 16).full(256, 1 << 20),
                _ if kind == PointKind::Cocircular => entry.quick(256, 1 << 15).full(256, 1 << 18),
                _ => entry.quick(256, 1 << 15).full(256, 1 << 19),
            });
        }
    }
    out.push(
        Entry::declared(
            DiameterAlgorithm::BruteForce.declaration(),
            PointKind::UniformDisk.name(),
            BruteDiameter,
        )
        .quick(64, 2048)
        .full(64, 1 << 13),
    );
    let calipers = [
        (ANTIPODAL_PAIRS, Caliper::AntipodalPairs),
        (DiameterAlgorithm::Calipers.declaration(), Caliper::Diameter),
        (WIDTH, Caliper::Width),
        (MIN_AREA_RECTANGLE, Caliper::MinAreaRectangle),
        (MIN_PERIMETER_RECTANGLE, Caliper::MinPerimeterRectangle),
    ];
    for (declaration, caliper) in calipers {
        out.push(
            Entry::declared(declaration, "convex-polygon", Calipers(caliper))
                .quick(256, 1 << 14)
                .full(256, 1 << 18),
        );
    }
    out
}

impl Workload for Hull {
    type Input = Vec<Point2>;
    type Output = Vec<usize>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n, seed)
    }

    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<Vec<usize>> {
        let set = PointSet::new(pts)?;
        Ok(convex_hull_with(
            &set,
            self.algorithm,
            HullOptions::default(),
            counter,
        ))
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
        let set = PointSet::new(pts)?;
        diameter_with(&set, DiameterAlgorithm::BruteForce, counter).map(drop)
    }
}

impl Workload for Calipers {
    /// The points and their hull, counter-clockwise.
    type Input = (Vec<Point2>, Vec<usize>);
    /// The pairs, or the indices the answer names.
    type Output = Vec<[usize; 2]>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = points(PointKind::Cocircular, n, seed)?;
        let hull = monotone_chain_with(&PointSet::new(&pts)?, HullOptions::default(), &mut NoCount);
        Ok((pts, hull))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, counter: &mut C) -> Result<Self::Output> {
        let set = PointSet::new(&input.0)?;
        let polygon = ConvexPolygon::new(&set, input.1.clone())?;
        Ok(match self.0 {
            Caliper::AntipodalPairs => polygon.antipodal_pairs_with(counter),
            Caliper::Diameter => vec![polygon.diameter_with(counter)?.pair],
            Caliper::Width => vec![polygon.width_with(counter)?.edge],
            Caliper::MinAreaRectangle => vec![polygon.min_area_rectangle_with(counter)?.edge],
            Caliper::MinPerimeterRectangle => {
                vec![polygon.min_perimeter_rectangle_with(counter)?.edge]
            }
        })
    }

    fn output_size(&self, input: &Self::Input, _pairs: &Self::Output) -> Option<usize> {
        Some(input.1.len())
    }
}
