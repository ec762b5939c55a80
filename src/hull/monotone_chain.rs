//! Andrew's monotone chain: the seed's "variante" of Graham's scan, which sorts
//! lexicographically instead of by angle and scans the lower and upper chains.

use super::{chains, finish, lex_sorted_items, HullOptions};
use crate::count::{Counter, NoCount};
use crate::error::Result;
use crate::geometry::{validate, Point2};

/// The convex hull of `points` by the monotone chain. See [`monotone_chain_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{monotone_chain, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(monotone_chain(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn monotone_chain(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    monotone_chain_with(points, options, &mut NoCount)
}

/// The convex hull of `points` by Andrew's monotone chain, recording its operations in
/// `counter`.
///
/// Idea: sort the points lexicographically (merging duplicates); the hull's boundary is the
/// lower chain from the first to the last point plus the upper chain back. The points
/// strictly below the line from first to last belong to the lower chain, those strictly
/// above to the upper. Each chain is
/// Graham's scan over the sorted list: push a point after popping every point that does
/// not make a strict left turn with it.
///
/// Follows `003_5b666ee3e15e6353.txt`, §2.2 "Scan de Graham - Variante" (steps 1–4).
///
/// Output convention and degenerate inputs: see the [module docs](super). `keep_collinear`
/// inserts the boundary points afterwards (a binary search per point over the hull).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and h the number of hull vertices: time O(n log n) (the sort),
/// the scans O(n); auxiliary space O(n).
///
/// # Counts
///
/// Comparisons: those of the lexicographic sort, O(n log n), plus n − 1 to merge duplicates.
/// Orientation tests: m − 2 for m distinct points to split them between the chains, then at
/// most 2k − 3 for a chain of k points (each test pops a point or ends a push), at most
/// 3m in all. `keep_collinear` adds O(n log h) comparisons
/// and at most 2n orientation tests.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{monotone_chain_with, HullOptions};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.2)].map(Point2::from);
/// let mut counts = Counts::default();
/// assert_eq!(monotone_chain_with(&pts, HullOptions::default(), &mut counts)?, [0, 1, 2]);
/// assert!(counts.orientation_tests <= 3 * 4);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn monotone_chain_with<C: Counter>(
    points: &[Point2],
    options: HullOptions,
    counter: &mut C,
) -> Result<Vec<usize>> {
    validate(points)?;
    let sorted = lex_sorted_items(points, 0..points.len(), counter);
    let strict = chains(&sorted, counter);
    Ok(finish(
        points,
        sorted.iter().map(|s| s.1),
        strict,
        options,
        counter,
    ))
}
