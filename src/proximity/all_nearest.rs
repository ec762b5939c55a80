//! All nearest neighbours from the Delaunay edges.

use super::{at_least_two, delaunay_edges};
use crate::count::{Counter, NoCount};
use crate::delaunay::{incremental_with, EMPTY};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Point2};
use std::cmp::Ordering;

/// For every point, the index of a nearest other point; see
/// [`all_nearest_neighbours_with`].
///
/// # Errors
/// As [`all_nearest_neighbours_with`].
///
/// # Complexity
/// O(n log n) expected time, O(n) space.
///
/// ```
/// use compgeo::proximity::all_nearest_neighbours;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (5.0, 0.0), (5.0, 2.5), (1.0, 0.0)].map(Point2::from);
/// let nn = all_nearest_neighbours(&pts)?;
/// assert_eq!(nn, [1, 4, 3, 2, 1]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn all_nearest_neighbours(points: &[Point2]) -> Result<Vec<usize>> {
    all_nearest_neighbours_with(points, &mut NoCount)
}

/// For every point, the index of a nearest other point, from the Delaunay edges, counting
/// the triangulation's predicates and the distance evaluations.
///
/// The idea (`003_5b666ee3e15e6353.txt`, §2.4, problem 2 "Todos los vecinos más cercanos"
/// and Theorem 2.31): a nearest neighbour of a site shares an edge of its Voronoi cell, so
/// it is a Delaunay neighbour. One pass over the edges keeps, for each end, the nearer of
/// its current best and the other end (exact [`cmp_dist`](crate::geometry::cmp_dist)).
/// Ties: any nearest point may be returned. A point equal to another has that one as its
/// nearest neighbour (distance zero).
///
/// # Errors
/// [`Error::TooFew`] for fewer than two points; [`Error::NonFinite`] for a NaN or infinite
/// coordinate.
///
/// # Complexity
/// O(n log n) expected time (the triangulation; the pass over the edges is O(n)), O(n)
/// auxiliary space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests, and two distance evaluations per
/// Delaunay edge.
pub fn all_nearest_neighbours_with<C: Counter>(
    points: &[Point2],
    counter: &mut C,
) -> Result<Vec<usize>> {
    at_least_two(points)?;
    let t = incremental_with(points, counter)?;
    let mut best = vec![EMPTY; points.len()];
    let closer = |a: usize, b: usize, best: &mut [usize], c: &mut C| {
        if best[a] == EMPTY
            || c.cmp_dist(points[a], points[b], points[a], points[best[a]]) == Ordering::Less
        {
            best[a] = b;
        }
    };
    for [a, b] in delaunay_edges(&t) {
        closer(a, b, &mut best, counter);
        closer(b, a, &mut best, counter);
    }
    for &[dropped, kept] in &t.duplicates {
        best[dropped] = kept;
    }
    for &[dropped, kept] in t.duplicates.iter().rev() {
        best[kept] = dropped;
    }
    Ok(best)
}
