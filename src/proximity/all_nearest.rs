//! All nearest neighbours from the Delaunay edges.

use super::{at_least, delaunay_edges};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::delaunay::{incremental_with, EMPTY};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Point2, PointSet};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "all-nearest-neighbours",
    name: "delaunay",
    function: "proximity::all_nearest_neighbours",
    file: "src/proximity/all_nearest.rs",
    summary: "the nearer end of every Delaunay edge, for both ends",
    time: "O(n log n) expected",
    space: "O(n)",
    operation: Some(Operation::IncircleTests),
    counts: "those of the triangulation, then two distance evaluations per Delaunay edge",
    source: "[RD, §2.4]",
    claims: &[on("uniform-square", Bound::NLogN, Operation::IncircleTests)],
};

/// For every point, the index of a nearest other point; see
/// [`all_nearest_neighbours_with`].
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::TooFew`](crate::Error::TooFew) for fewer than two points.
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
    all_nearest_neighbours_with(&PointSet::new(points)?, &mut NoCount)
}

/// For every point, the index of a nearest other point, from the Delaunay edges, counting
/// the triangulation's predicates and the distance evaluations.
///
/// The idea ([RD, §2.4], problem 2 "Todos los vecinos más cercanos"
/// and Theorem 2.31): a nearest neighbour of a site shares an edge of its Voronoi cell, so
/// it is a Delaunay neighbour. One pass over the edges keeps, for each end, the nearer of
/// its current best and the other end (exact [`cmp_dist`](crate::geometry::cmp_dist)).
/// Ties: any nearest point may be returned. A point equal to another has that one as its
/// nearest neighbour (distance zero).
///
/// # Errors
/// [`Error::TooFew`](crate::Error::TooFew) for fewer than two points; the triangulation's
/// size limit.
///
/// # Complexity
/// O(n log n) expected time (the triangulation; the pass over the edges is O(n)), O(n)
/// auxiliary space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests, and two distance evaluations per
/// Delaunay edge.
pub fn all_nearest_neighbours_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<Vec<usize>> {
    at_least(2, points.len())?;
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
