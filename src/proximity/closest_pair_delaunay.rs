//! The closest pair as the shortest Delaunay edge.

use super::{at_least, delaunay_edges};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::delaunay::incremental_with;
use crate::error::Result;
use crate::geometry::{CountedPredicates, Point2, PointPair, PointSet};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "closest-pair",
    name: "delaunay",
    function: "proximity::closest_pair_delaunay",
    file: "src/proximity/closest_pair_delaunay.rs",
    summary: "the shortest edge of the Delaunay triangulation",
    time: "O(n log n) expected",
    space: "O(n)",
    operation: Some(Operation::IncircleTests),
    counts: "those of the triangulation, then one distance evaluation per Delaunay edge",
    source: "[RD, §2.4]",
    claims: &[on("uniform-square", Bound::NLogN, Operation::IncircleTests)],
};

/// The closest pair of `points` via the Delaunay triangulation; see
/// [`closest_pair_delaunay_with`].
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::TooFew`](crate::Error::TooFew) for fewer than two points.
///
/// # Complexity
/// O(n log n) expected time, O(n) space.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::proximity::closest_pair_delaunay;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (9.0, 9.0), (3.5, 5.0)].map(Point2::from);
/// let c = closest_pair_delaunay(&pts)?;
/// assert_eq!(c.pair, [1, 3]);
/// assert_eq!(c.distance, 1.25f64.sqrt());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closest_pair_delaunay(points: &[Point2]) -> Result<PointPair> {
    closest_pair_delaunay_with(&PointSet::new(points)?, &mut NoCount)
}

/// The closest pair of `points`: the shortest Delaunay edge, counting the triangulation's
/// predicates and the distance evaluations.
///
/// The idea ([RD, §2.4], problem 3 "El par más cercano": linear time
/// once the nearest neighbours are known): the closest pair are each other's nearest
/// neighbours, so their segment is a Delaunay edge; the shortest edge is found with the
/// exact [`cmp_dist`](crate::geometry::cmp_dist). With duplicates the answer is the first
/// duplicate pair (distance zero). Ties: any closest pair may be returned. The classic
/// divide and conquer is [`closest_pair_divide_and_conquer`](super::closest_pair_divide_and_conquer).
///
/// # Errors
/// [`Error::TooFew`](crate::Error::TooFew) for fewer than two points; the triangulation's
/// size limit.
///
/// # Complexity
/// O(n log n) expected time (the triangulation; the scan is O(n)), O(n) space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests and one distance evaluation per
/// Delaunay edge.
pub fn closest_pair_delaunay_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<PointPair> {
    at_least(2, points.len())?;
    let t = incremental_with(points, counter)?;
    if let Some(&[dropped, kept]) = t.duplicates.first() {
        return Ok(PointPair::new(points, kept, dropped));
    }
    let mut edges = delaunay_edges(&t).into_iter();
    let first = edges.next().expect("two distinct points have an edge");
    let best = edges.fold(first, |[a, b], [c, d]| {
        if counter.cmp_dist(points[c], points[d], points[a], points[b]) == Ordering::Less {
            [c, d]
        } else {
            [a, b]
        }
    });
    Ok(PointPair::new(points, best[0], best[1]))
}
