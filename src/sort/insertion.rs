//! Sequential insertion sort, scanning the sorted prefix from the back.
//!
//! Step `k` (from 1 to n − 1) inserts `x = v[k]` into the sorted prefix `v[..k]` (the course,
//! [RD, §2.1] "Inserción secuencial": "se inserta x_{k+1} en la lista
//! parcialmente ordenada {x_1, …, x_k}"). This is the usual textbook variant: `x` is compared
//! with the prefix from its largest element down and every larger element is shifted one
//! place right as soon as it has been compared, so comparisons and moves go together. Its cost
//! profile is the one the course's complexity paragraph describes: strictly decreasing input is
//! the worst case (step `k` compares with all k prefix elements and shifts them all:
//! n(n−1)/2 comparisons and moves), nondecreasing input the best (n − 1 comparisons, no
//! moves).
//!
//! The course's worked table scans from the front instead ("4 > 1, 4 > 3 y 4 < 5"), which
//! mirrors the profile; that variant is [`super::course_insertion_sort`], and its trace
//! reproduces the table with its reasons.
//!
//! Invariants the tests check: comparisons are n(n−1)/2 on strictly decreasing input and
//! n − 1 on nondecreasing input; moves equal the inversions; comparisons exceed moves by at
//! most n − 1; stable.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "insertion",
    function: "sort::insertion_sort",
    file: "src/sort/insertion.rs",
    summary: "sequential insertion scanning the sorted prefix from the back",
    time: "Θ(n²) in the worst case and Θ(n) on sorted input",
    space: "O(1)",
    operation: Some(Operation::Comparisons),
    counts: "at most n(n − 1)/2 comparisons, n − 1 on sorted input",
    source: "[RD, §2.1]",
    claims: &[
        on("random", Bound::Quadratic, Operation::Comparisons),
        on("sorted", Bound::Linear, Operation::Comparisons),
        on("reversed", Bound::Quadratic, Operation::Comparisons),
    ],
};

/// Sorts `v` in increasing order with sequential insertion sort.
///
/// See [`insertion_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1, 4, 6];
/// compgeo::sort::insertion_sort(&mut v);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// ```
pub fn insertion_sort<T: Ord>(v: &mut [T]) {
    insertion_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with sequential insertion sort; stable.
///
/// For floats pass `f64::total_cmp`. See [`insertion_sort_with`].
///
/// ```
/// let mut v = [3.0, f64::NEG_INFINITY, 1e-310, 0.0];
/// compgeo::sort::insertion_sort_by(&mut v, f64::total_cmp);
/// assert_eq!(v, [f64::NEG_INFINITY, 0.0, 1e-310, 3.0]);
/// ```
pub fn insertion_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    insertion_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with sequential insertion sort, recording its operations in `counter`.
///
/// Idea: for `k = 1, …, n − 1`, the prefix `v[..k]` is sorted; compare `x = v[k]` with
/// `v[k − 1], v[k − 2], …` while `x` is smaller, stopping at the first element not larger
/// than `x` (or the front), then shift the larger elements one place right and put `x` in the
/// gap. Stopping at an equal element keeps equal elements in input order (stable).
///
/// Follows [RD, §2.1] "Inserción secuencial" and "Complejidad de los
/// algoritmos de ordenación" (see the module docs for the direction of the scan).
///
/// # Errors
///
/// None: every slice, empty included, is valid input. `cmp` should be a total order; if it is
/// not, the result is some permutation of `v`.
///
/// # Complexity
///
/// With n = `v.len()`: time Θ(n + I) for I the number of inversions of the input, so Θ(n²)
/// in the worst case and Θ(n) on sorted input; auxiliary space O(1).
///
/// # Counts
///
/// - comparisons: step `k` makes `k − p + 1` comparisons when `x` lands at position `p > 0`
///   and `k` when it lands at the front; in total between n − 1 (nondecreasing input) and
///   1 + 2 + … + (n − 1) = n(n−1)/2 (strictly decreasing input), the course's bound;
/// - moves: one per element shifted one place right (the course's "desplazar"), `k − p` in step
///   `k`; in total the number of inversions of the input. Putting `x` into the gap is not
///   counted.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::insertion_sort_with;
///
/// let mut v = [6, 5, 4, 3, 2, 1];
/// let mut counts = Counts::default();
/// insertion_sort_with(&mut v, i32::cmp, &mut counts);
/// assert_eq!(v, [1, 2, 3, 4, 5, 6]);
/// assert_eq!((counts.comparisons, counts.moves), (15, 15)); // n(n−1)/2 each
/// ```
pub fn insertion_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    insertion(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn insertion<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    for k in 1..v.len() {
        let mut pos = k;
        while pos > 0 && ops.less(&v[k], &v[pos - 1]) {
            pos -= 1;
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
    fn each_step_compares_once_more_than_it_moves_unless_x_goes_first() {
        for k in 1..30usize {
            for p in 0..=k {
                // Prefix 0, 2, 4, ..., then x = 2p - 1 belongs at position p.
                let mut v: Vec<i64> = (0..k as i64).map(|i| 2 * i).collect();
                v.push(2 * p as i64 - 1);
                let mut c = Counts::default();
                insertion(&mut v, &mut Counted::new(i64::cmp, &mut c), &mut NoObserver);
                assert!(v.windows(2).all(|w| w[0] <= w[1]));
                // The increasing prefix costs one comparison per step.
                let step = c.comparisons - (k as u64 - 1);
                let expected = if p == 0 { k } else { k - p + 1 };
                assert_eq!(step, expected as u64, "k={k} p={p}");
                assert_eq!(c.moves, (k - p) as u64);
            }
        }
    }
}
