//! Sequential insertion sort, as the course does it: the sorted prefix is scanned from the front.
//!
//! Step `k` (from 1 to n − 1) inserts `x_{k+1}` into the sorted list `x_1, …, x_k`. The course
//! ([RD, §2.1] "Inserción secuencial") finds the place by comparing the
//! new element with the sorted elements from the smallest up — its table for {7, 3, 5, 1, 4, 6}
//! reads "1 3 4 5 7 pues 4 > 1, 4 > 3 y 4 < 5" — and stops at the first larger element. This
//! file follows the course, so its cost profile is the mirror image of the common textbook
//! variant that scans from the back ([`super::insertion_sort`]): nondecreasing input is its worst case (every element is
//! compared with the whole prefix, n(n−1)/2 comparisons, no moves) and strictly decreasing
//! input its best (one comparison per step, n − 1 in total, but n(n−1)/2 moves).
//!
//! [`super::trace`] of [`super::Algorithm::CourseInsertion`] reproduces the course's table with
//! its "pues" clauses; use [`super::insertion_sort`] when you want the usual cost profile.
//!
//! Invariants the tests check: the comparisons of each step are exactly those the course lists
//! (one per prefix element up to and including the first larger one); moves equal the
//! inversions of the input; stable; the course's table.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "course-insertion",
    function: "sort::course_insertion_sort",
    file: "src/sort/course_insertion.rs",
    summary: "sequential insertion as the course's table does it, from the front",
    time: "Θ(n²)",
    space: "O(1)",
    operation: Some(Operation::Comparisons),
    counts: "n(n − 1)/2 comparisons on sorted input, as many moves on reversed input",
    source: "[RD, §2.1]",
    claims: &[
        on("random", Bound::Quadratic, Operation::Comparisons),
        on("sorted", Bound::Quadratic, Operation::Comparisons),
        on("reversed", Bound::Quadratic, Operation::Moves),
    ],
};

/// Sorts `v` in increasing order with the course's sequential insertion sort.
///
/// See [`course_insertion_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1, 4, 6];
/// compgeo::sort::course_insertion_sort(&mut v);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// ```
pub fn course_insertion_sort<T: Ord>(v: &mut [T]) {
    course_insertion_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with the course's sequential insertion sort; stable.
///
/// For floats pass `f64::total_cmp`. See [`course_insertion_sort_with`].
///
/// ```
/// let mut v = [3.0, f64::NEG_INFINITY, 1e-310, 0.0];
/// compgeo::sort::course_insertion_sort_by(&mut v, f64::total_cmp);
/// assert_eq!(v, [f64::NEG_INFINITY, 0.0, 1e-310, 3.0]);
/// ```
pub fn course_insertion_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    course_insertion_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with the course's sequential insertion sort, recording its operations in
/// `counter`.
///
/// Idea: for `k = 1, …, n − 1`, the prefix `v[..k]` is sorted; compare `x = v[k]` with
/// `v[0], v[1], …` until the first `v[p]` with `x < v[p]` (or the end, `p = k`), then shift
/// `v[p..k]` one place right and put `x` at `p`. Stopping only at a strictly larger element
/// keeps equal elements in input order (stable).
///
/// Follows [RD, §2.1] "Inserción secuencial" (the scan from the front is
/// the course's, see the module docs) and "Complejidad de los algoritmos de ordenación".
///
/// # Errors
///
/// None: every slice, empty included, is valid input. `cmp` should be a total order; if it is
/// not, the result is some permutation of `v`.
///
/// # Complexity
///
/// With n = `v.len()`: time Θ(n²) for every input (step `k` costs k + 1 comparisons and moves
/// together, or k when `x` goes last); auxiliary space O(1).
///
/// # Counts
///
/// - comparisons: step `k` makes p + 1 comparisons, or k when `x` is not smaller than any
///   prefix element; in total at most 1 + 2 + … + (n − 1) = n(n−1)/2, the course's bound,
///   reached on nondecreasing input; n − 1 on strictly decreasing input;
/// - moves: one per element shifted one place right (the course's "desplazar"), k − p in step
///   `k`; in total the number of inversions of the input, at most n(n−1)/2. Putting `x`
///   into the gap is not counted.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::course_insertion_sort_with;
///
/// let mut v = [7, 3, 5, 1, 4, 6];
/// let mut counts = Counts::default();
/// course_insertion_sort_with(&mut v, i32::cmp, &mut counts);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// assert_eq!(counts.comparisons, 1 + 2 + 1 + 3 + 5); // the course's "pues" clauses
/// assert_eq!(counts.moves, 8); // the inversions of 7 3 5 1 4 6
/// ```
pub fn course_insertion_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    course_insertion(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn course_insertion<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    for k in 1..v.len() {
        let mut pos = 0;
        while pos < k && !ops.less(&v[k], &v[pos]) {
            pos += 1;
        }
        if pos < k {
            v[pos..=k].rotate_right(1);
            ops.moves(k - pos);
        }
        obs.step(v, Step::Inserted { k, pos });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    #[test]
    fn nondecreasing_input_is_the_comparison_worst_case() {
        for n in 0..25u64 {
            let mut v: Vec<u64> = (0..n).map(|i| i / 3).collect();
            let mut c = Counts::default();
            course_insertion_sort_with(&mut v, u64::cmp, &mut c);
            assert_eq!(c.comparisons, n * n.saturating_sub(1) / 2);
            assert_eq!(c.moves, 0);
        }
    }

    #[test]
    fn decreasing_input_is_the_move_worst_case() {
        for n in 0..25u64 {
            let mut v: Vec<u64> = (0..n).rev().collect();
            let mut c = Counts::default();
            course_insertion_sort_with(&mut v, u64::cmp, &mut c);
            assert_eq!(c.comparisons, n.saturating_sub(1));
            assert_eq!(c.moves, n * n.saturating_sub(1) / 2);
            assert_eq!(v, (0..n).collect::<Vec<_>>());
        }
    }
}
