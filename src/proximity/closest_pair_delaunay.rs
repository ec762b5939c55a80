//! The closest pair as the shortest Delaunay edge.

use super::{at_least_two, delaunay_edges, pair_of, ClosestPair};
use crate::count::{Counter, NoCount};
use crate::delaunay::incremental_with;
use crate::error::Result;
use crate::geometry::{CountedPredicates, Point2};
use std::cmp::Ordering;

/// The closest pair of `points` via the Delaunay triangulation; see
/// [`closest_pair_with`].
///
/// # Errors
/// As [`closest_pair_with`].
///
/// # Complexity
/// O(n log n) expected time, O(n) space.
///
/// ```
/// use compgeo::proximity::closest_pair;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (9.0, 9.0), (3.5, 5.0)].map(Point2::from);
/// let c = closest_pair(&pts)?;
/// assert_eq!(c.pair, [1, 3]);
/// assert_eq!(c.distance, 1.25f64.sqrt());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closest_pair(points: &[Point2]) -> Result<ClosestPair> {
    closest_pair_with(points, &mut NoCount)
}

/// The closest pair of `points`: the shortest Delaunay edge, counting the triangulation's
/// predicates and the distance evaluations.
///
/// The idea (`003_5b666ee3e15e6353.txt`, §2.4, problem 3 "El par más cercano": linear time
/// once the nearest neighbours are known): the closest pair are each other's nearest
/// neighbours, so their segment is a Delaunay edge; the shortest edge is found with the
/// exact [`cmp_dist`](crate::geometry::cmp_dist). With duplicates the answer is the first
/// duplicate pair (distance zero). Ties: any closest pair may be returned. The classic
/// divide and conquer is [`closest_pair_divide_and_conquer`](super::closest_pair_divide_and_conquer).
///
/// # Errors
/// [`Error::TooFew`] for fewer than two points; [`Error::NonFinite`] for a NaN or infinite
/// coordinate.
///
/// # Complexity
/// O(n log n) expected time (the triangulation; the scan is O(n)), O(n) space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests and one distance evaluation per
/// Delaunay edge.
pub fn closest_pair_with<C: Counter>(points: &[Point2], counter: &mut C) -> Result<ClosestPair> {
    at_least_two(points)?;
    let t = incremental_with(points, counter)?;
    if let Some(&[dropped, kept]) = t.duplicates.first() {
        return Ok(pair_of(points, kept, dropped));
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
    Ok(pair_of(points, best[0], best[1]))
}
