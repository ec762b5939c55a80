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

/// `items` (finite points with their indices, given in increasing runs such as Chan's
/// group hulls) sorted lexicographically, ties by index, each distinct point kept once by
/// its smallest index: the runs are found (s − 1 comparisons) and merged pairwise, so k runs
/// cost O(s log k) comparisons, each counted.
pub(super) fn lex_merged_items<C: Counter>(
    items: Vec<(Point2, usize)>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    let mut keyed: Vec<(u128, usize, Point2)> =
        items.into_iter().map(|(p, i)| (lex_key(p), i, p)).collect();
    let mut bounds = vec![0];
    for i in 1..keyed.len() {
        counter.comparison();
        if (keyed[i].0, keyed[i].1) < (keyed[i - 1].0, keyed[i - 1].1) {
            bounds.push(i);
        }
    }
    bounds.push(keyed.len());
    let mut merged = Vec::with_capacity(keyed.len());
    while bounds.len() > 2 {
        merged.clear();
        let mut next = vec![0];
        for pair in bounds.windows(3).step_by(2) {
            merge(
                &keyed[pair[0]..pair[1]],
                &keyed[pair[1]..pair[2]],
                &mut merged,
                counter,
            );
            next.push(merged.len());
        }
        if bounds.len() % 2 == 0 {
            // An odd number of runs: the last one waits for the next pass.
            merged.extend_from_slice(&keyed[bounds[bounds.len() - 2]..]);
            next.push(merged.len());
        }
        std::mem::swap(&mut keyed, &mut merged);
        bounds = next;
    }
    let sorted = keyed.into_iter().map(|(_, i, p)| (p, i)).collect();
    without_duplicates(sorted, counter)
}

/// Appends the merge of the increasing runs `a` and `b` to `out`, the first of equals from `a`.
fn merge<C: Counter>(
    a: &[(u128, usize, Point2)],
    b: &[(u128, usize, Point2)],
    out: &mut Vec<(u128, usize, Point2)>,
    counter: &mut C,
) {
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        counter.comparison();
        if (b[j].0, b[j].1) < (a[i].0, a[i].1) {
            out.push(b[j]);
            j += 1;
        } else {
            out.push(a[i]);
            i += 1;
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
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
