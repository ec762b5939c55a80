//! The lexicographic order the hull algorithms start from: the smallest point, and the
//! points sorted with their duplicates dropped.

use crate::count::Counter;
use crate::geometry::lex_sort::{lex_key, sorted_items_with};
use crate::geometry::{CountedPredicates, Point2};
use std::cmp::Ordering;

/// The index of the lexicographically smallest point, the first one among equals.
/// `points` must not be empty.
pub(super) fn lex_min<C: Counter>(points: &[Point2], counter: &mut C) -> usize {
    let mut best = 0;
    for i in 1..points.len() {
        if counter.cmp_lex(points[i], points[best]) == Ordering::Less {
            best = i;
        }
    }
    best
}

/// The points of `indices` with their indices, sorted lexicographically, each distinct point
/// kept once by its smallest index. The sort is [`sorted_items_with`]: with a counter that
/// records, `sort_unstable_by` on integer keys that order as
/// [`cmp_lex`](crate::geometry::cmp_lex) does, twice as fast as comparing the coordinates on
/// circle inputs, each key comparison counted as one comparison, so the counts are those of
/// sorting by `cmp_lex`; with `NoCount`, from 256 points up, a radix sort that is 1.5 to 4
/// times faster again (the `lex-sort` groups of `benches/hull.rs`) and gives the same order.
/// Merging the duplicates counts one comparison per point after the first. `points` must be
/// finite.
pub(super) fn lex_sorted_items<C: Counter>(
    points: &[Point2],
    indices: impl ExactSizeIterator<Item = usize>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    let mut sorted = sorted_items_with(points, indices, lex_key, counter);
    // Finite coordinates are equal as floats exactly when cmp_lex calls them equal.
    sorted.dedup_by(|b, a| {
        counter.comparison();
        a.0 == b.0
    });
    sorted
}
