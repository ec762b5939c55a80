//! The lexicographic order the hull algorithms start from: the smallest point, and the
//! points sorted with their duplicates dropped.

use crate::count::Counter;
use crate::geometry::lex_sort::{compared_items_with, lex_key, sorted_items_with};
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
/// sorting by `cmp_lex`; with `NoCount`, from 384 points up, a radix sort that gives the same
/// order 1.2 to 3 times faster (the `lex-sort` groups of `benches/hull.rs`). Merging the
/// duplicates counts one comparison per point after the first. `points` must be finite.
pub(super) fn lex_sorted_items<C: Counter>(
    points: &[Point2],
    indices: impl ExactSizeIterator<Item = usize>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    let sorted = sorted_items_with(points, indices, lex_key, counter);
    without_duplicates(sorted, counter)
}

/// [`lex_sorted_items`] by the comparison sort whatever the counter, for Akl–Toussaint's
/// survivors: there the radix sort measured no faster (see `akl_toussaint_with`).
pub(super) fn lex_sorted_items_by_comparisons<C: Counter>(
    points: &[Point2],
    indices: impl Iterator<Item = usize>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    let sorted = compared_items_with(points, indices, lex_key, counter);
    without_duplicates(sorted, counter)
}

/// `sorted` with each run of equal points cut to its first item, one comparison counted per
/// item after the first.
fn without_duplicates<C: Counter>(
    mut sorted: Vec<(Point2, usize)>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    // Finite coordinates are equal as floats exactly when cmp_lex calls them equal.
    sorted.dedup_by(|b, a| {
        counter.comparison();
        a.0 == b.0
    });
    sorted
}
