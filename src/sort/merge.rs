//! Top-down merge sort: the O(n log n) worst-case reference, stable.
//!
//! Split the input into a left half of ⌊m/2⌋ and a right half of ⌈m/2⌉ elements, sort both
//! recursively, merge. Not in the course, whose sorting section stops at the quadratic sorts
//! ([RD, §2.1] "Algoritmos de ordenación"); it is here so that growth
//! plots contrast their n² with n log n.
//!
//! The elements are generic and may be neither `Copy` nor `Clone`, and compgeo forbids
//! `unsafe`, so the merges work on *positions*: a permutation of `0..n` is merge-sorted by
//! comparing the elements it points at, and the elements themselves are then moved once, by
//! following the cycles of that permutation with exchanges. The comparisons are exactly those
//! of a direct merge sort.
//!
//! Invariants the tests check: comparisons at most the worst case W(n) = n⌈log₂ n⌉ −
//! 2^⌈log₂ n⌉ + 1 and exactly the best case on sorted input; moves exactly M(n); swaps at most
//! n − 1; stable.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "merge",
    function: "sort::merge_sort",
    file: "src/sort/merge.rs",
    summary: "top-down merge sort",
    time: "Θ(n log n)",
    space: "O(n)",
    operation: Some(Operation::Comparisons),
    counts: "at most n⌈log₂ n⌉ comparisons",
    source: "[RD, §2.1]",
    claims: &[on("random", Bound::NLogN, Operation::Comparisons)],
};

/// Sorts `v` in increasing order with merge sort.
///
/// See [`merge_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1, 4, 6];
/// compgeo::sort::merge_sort(&mut v);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// ```
pub fn merge_sort<T: Ord>(v: &mut [T]) {
    merge_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with merge sort; stable.
///
/// For floats pass `f64::total_cmp`. See [`merge_sort_with`].
///
/// ```
/// let mut v = [f64::NAN, 2.0, f64::NEG_INFINITY, -0.0];
/// compgeo::sort::merge_sort_by(&mut v, f64::total_cmp);
/// assert_eq!(v[..3], [f64::NEG_INFINITY, -0.0, 2.0]);
/// assert!(v[3].is_nan());
/// ```
pub fn merge_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    merge_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with top-down merge sort, recording its operations in `counter`.
///
/// Idea: a run of m ≥ 2 elements is split after its first ⌊m/2⌋, both halves are sorted
/// recursively and then merged: repeatedly take the smaller front element, the left one on a
/// tie (stable). The merges act on a permutation of positions (see the module docs), which is
/// applied to `v` at the end by exchanges along its cycles.
///
/// Not in the course ([RD, §2.1] stops at the quadratic sorts); the
/// counting follows the course's conventions.
///
/// # Errors
///
/// None: every slice, empty included, is valid input. `cmp` should be a total order; if it is
/// not, the result is some permutation of `v`.
///
/// # Complexity
///
/// With n = `v.len()`: time Θ(n log n) for every input; auxiliary space O(n): 3n/2
/// positions (`usize`) plus O(log n) recursion stack.
///
/// # Counts
///
/// - comparisons: at most W(n) = n⌈log₂ n⌉ − 2^⌈log₂ n⌉ + 1 ≤ n⌈log₂ n⌉ (the recurrence
///   W(m) = W(⌊m/2⌋) + W(⌈m/2⌉) + m − 1); on already sorted input exactly
///   B(m) = B(⌊m/2⌋) + B(⌈m/2⌉) + ⌊m/2⌋;
/// - moves: every merge of a run of m elements places m positions, so exactly
///   M(m) = M(⌊m/2⌋) + M(⌈m/2⌉) + m, at most n⌈log₂ n⌉ (these are moves of positions, not of
///   elements, see above);
/// - swaps: the exchanges that finally put the elements in place: n minus the number of
///   cycles of the sorting permutation, at most n − 1.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::merge_sort_with;
///
/// let mut v = [4, 3, 2, 1];
/// let mut counts = Counts::default();
/// merge_sort_with(&mut v, i32::cmp, &mut counts);
/// assert_eq!(v, [1, 2, 3, 4]);
/// assert_eq!(counts.comparisons, 4); // 1 + 1 + 2: each merge stops when the right run ends
/// assert_eq!(counts.moves, 8); // 2 + 2 + 4
/// assert_eq!(counts.swaps, 2); // the cycles (0 3) and (1 2)
/// ```
pub fn merge_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    merge(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn merge<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    let n = v.len();
    if n < 2 {
        return;
    }
    let mut order: Vec<usize> = (0..n).collect();
    let mut scratch = vec![0; n / 2];
    sort_positions(v, &mut order, &mut scratch, ops, obs);
    permute(v, &mut order, ops);
}

/// Sorts `run`, positions into `v`, by the elements they point at; `scratch` holds at least
/// `run.len() / 2` positions.
fn sort_positions<T, F, C, O>(
    v: &[T],
    run: &mut [usize],
    scratch: &mut [usize],
    ops: &mut Counted<'_, F, C>,
    obs: &mut O,
) where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    let m = run.len();
    if m < 2 {
        return;
    }
    let half = m / 2;
    sort_positions(v, &mut run[..half], scratch, ops, obs);
    sort_positions(v, &mut run[half..], scratch, ops, obs);

    // Only the left run is copied out: the merged output never overtakes the unread part of
    // the right run, which can therefore stay where it is.
    let left = &mut scratch[..half];
    left.copy_from_slice(&run[..half]);
    obs.step(
        v,
        Step::Merging {
            left,
            right: &run[half..],
        },
    );
    let (mut i, mut j) = (0, half);
    let mut out = 0;
    while i < half && j < m {
        if ops.less(&v[run[j]], &v[left[i]]) {
            run[out] = run[j];
            j += 1;
        } else {
            run[out] = left[i];
            i += 1;
        }
        out += 1;
    }
    run[out..out + half - i].copy_from_slice(&left[i..]);
    ops.moves(m);
    obs.step(v, Step::Merged { run });
}

/// Rearranges `v` so that `v[i]` becomes the old `v[order[i]]`, one exchange per element out
/// of place and cycle; `order` is consumed (left as the identity).
fn permute<T, F, C: Counter>(v: &mut [T], order: &mut [usize], ops: &mut Counted<'_, F, C>) {
    for start in 0..v.len() {
        let mut hole = start;
        loop {
            let from = order[hole];
            order[hole] = hole;
            if from == start {
                break;
            }
            ops.swap(v, hole, from);
            hole = from;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    #[test]
    fn permute_applies_the_permutation_with_n_minus_cycles_swaps() {
        // order = [2, 0, 1, 3, 5, 4]: cycles (0 2 1), (3), (4 5): 6 - 3 = 3 swaps.
        let mut v = ['a', 'b', 'c', 'd', 'e', 'f'];
        let mut order = vec![2, 0, 1, 3, 5, 4];
        let mut counts = Counts::default();
        permute(
            &mut v,
            &mut order,
            &mut Counted::new(char::cmp, &mut counts),
        );
        assert_eq!(v, ['c', 'a', 'b', 'd', 'f', 'e']);
        assert_eq!(counts.swaps, 3);
        assert_eq!(order, [0, 1, 2, 3, 4, 5]);
    }

    #[test]
    fn non_clone_elements_are_sorted() {
        #[derive(Debug, PartialEq, Eq, PartialOrd, Ord)]
        struct Token(u32);
        let mut v: Vec<Token> = [5, 1, 4, 1, 3].into_iter().map(Token).collect();
        merge_sort(&mut v);
        assert_eq!(v, [1, 1, 3, 4, 5].map(Token));
    }
}
