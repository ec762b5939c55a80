//! Andrew's monotone chain: the course's "variante" of Graham's scan, which sorts
//! lexicographically instead of by angle and scans the lower and upper chains.

use super::collinear::finish;
use super::graham::push_left_turn;
use super::lex::lex_sorted_items;
use super::HullOptions;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "hull",
    name: "monotone-chain",
    function: "hull::monotone_chain",
    file: "src/hull/monotone_chain.rs",
    summary: "lexicographic sort, then the lower and upper chains",
    time: "O(n log n)",
    space: "O(n)",
    operation: Some(Operation::Comparisons),
    counts: "those of the sort, plus n − 1 to merge duplicates",
    source: "[RD, §2.2]",
    claims: &[on("uniform-disk", Bound::NLogN, Operation::Comparisons)],
};

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
    Ok(monotone_chain_with(
        &PointSet::new(points)?,
        options,
        &mut NoCount,
    ))
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
/// Follows [RD, §2.2] "Scan de Graham - Variante" (steps 1–4).
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
/// the scans O(n); auxiliary space O(n). With [`NoCount`] the sort is a radix sort from 384
/// points up (the same order, O(n) on random input, 1.2 to 1.9 times faster overall at 10³ to
/// 10⁶ points); a counter that records gets the comparison sort the counts below describe.
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
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{monotone_chain_with, HullOptions};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.2)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// assert_eq!(monotone_chain_with(&set, HullOptions::default(), &mut counts), [0, 1, 2]);
/// assert!(counts.orientation_tests <= 3 * 4);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn monotone_chain_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    let points = points.points();
    let sorted = lex_sorted_items(points, 0..points.len(), counter);
    let strict = chains(&sorted, counter);
    finish(points, sorted.iter().map(|s| s.1), strict, options, counter)
}

/// Andrew's chains over `sorted`, distinct points in lexicographic order: the strictly
/// convex hull, counter-clockwise from `sorted[0]`, as indices into the input.
///
/// The points strictly below the line from the first to the last point go to the lower
/// chain, those strictly above to the upper one, the rest (on the line) to neither: each
/// chain scans only its own points.
pub(super) fn chains<C: Counter>(sorted: &[(Point2, usize)], counter: &mut C) -> Vec<usize> {
    let m = sorted.len();
    if m <= 2 {
        return sorted.iter().map(|s| s.1).collect();
    }
    let (a, b) = (sorted[0].0, sorted[m - 1].0);
    // Sized up front: growing by pushes reallocates, which dominates on Chan's small groups.
    let mut lower = Vec::with_capacity(m);
    let mut upper = Vec::with_capacity(m);
    lower.push(sorted[0]);
    upper.push(sorted[m - 1]);
    for &item in &sorted[1..m - 1] {
        match counter.orient2d(a, b, item.0) {
            Orientation::Clockwise => lower.push(item),
            Orientation::CounterClockwise => upper.push(item),
            Orientation::Collinear => {}
        }
    }
    lower.push(sorted[m - 1]);
    upper.push(sorted[0]);
    let upper_last = upper.len() - 1;
    upper[1..upper_last].reverse();
    let mut hull = scan_chain(&lower, counter);
    hull.pop();
    let mut top = scan_chain(&upper, counter);
    top.pop();
    hull.extend(top);
    hull
}

/// Graham's scan over one chain whose points are all on one side of its end-to-end line:
/// the chain's strictly convex vertices, both ends included. The stack holds the points
/// themselves, so the scan reads them sequentially.
fn scan_chain<C: Counter>(chain: &[(Point2, usize)], counter: &mut C) -> Vec<usize> {
    let mut stack: Vec<(Point2, usize)> = Vec::with_capacity(chain.len());
    for &item in chain {
        push_left_turn(&mut stack, 2, item, |s| s.0, counter);
    }
    stack.into_iter().map(|s| s.1).collect()
}
