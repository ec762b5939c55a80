//! Bubble sort, exactly as the course states it: n − 1 passes, no early exit.
//!
//! Pass `i` (from 1) compares `x_j` with `x_{j+1}` for `j = 1, …, n − i` and exchanges them
//! when `x_j > x_{j+1}`; after it, the `i` largest elements are in their final places. The
//! seed ([RD, §2.1] "Algoritmo de ordenación de Burbuja") runs every
//! pass even when the list is already sorted, and its complexity section counts
//! (n−1) + (n−2) + … + 1 = n(n−1)/2 comparisons; so does this implementation, for every input.
//!
//! Invariants the tests check: exactly n(n−1)/2 comparisons; the number of swaps equals the
//! number of inversions (pairs `i < j` with `v[i] > v[j]`); stable; the course's pass-by-pass
//! table for {7, 3, 5, 1}.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "bubble",
    function: "sort::bubble_sort",
    file: "src/sort/bubble.rs",
    summary: "the course's bubble sort",
    time: "Θ(n²)",
    space: "O(1)",
    operation: Some(Operation::Comparisons),
    counts: "exactly n(n − 1)/2 comparisons",
    source: "[RD, §2.1]",
    claims: &[on("random", Bound::Quadratic, Operation::Comparisons)],
};

/// Sorts `v` in increasing order with the course's bubble sort.
///
/// See [`bubble_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1];
/// compgeo::sort::bubble_sort(&mut v);
/// assert_eq!(v, [1, 3, 5, 7]);
/// ```
pub fn bubble_sort<T: Ord>(v: &mut [T]) {
    bubble_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with the course's bubble sort; stable.
///
/// For floats pass `f64::total_cmp`. See [`bubble_sort_with`].
///
/// ```
/// let mut v = [2.5, -0.0, f64::INFINITY, -1.0];
/// compgeo::sort::bubble_sort_by(&mut v, f64::total_cmp);
/// assert_eq!(v, [-1.0, -0.0, 2.5, f64::INFINITY]);
/// ```
pub fn bubble_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    bubble_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with the course's bubble sort, recording its operations in `counter`.
///
/// Idea: pass `i = 1, …, n − 1` walks `j` over `0..n − i`, exchanging neighbours `v[j]`,
/// `v[j + 1]` that are out of order, so the largest remaining element bubbles up to position
/// `n − i`. There is no early exit: the course's version makes every pass.
///
/// Follows [RD, §2.1] "Algoritmo de ordenación de Burbuja" and
/// "Complejidad de los algoritmos de ordenación". Stable: only strictly out-of-order
/// neighbours are exchanged.
///
/// # Errors
///
/// None: every slice, empty included, is valid input. `cmp` should be a total order; if it is
/// not, the result is some permutation of `v`.
///
/// # Complexity
///
/// With n = `v.len()`: time Θ(n²) for every input; auxiliary space O(1).
///
/// # Counts
///
/// - comparisons: exactly n(n−1)/2, the course's count;
/// - swaps: one per exchange, equal to the number of inversions of the input; the course's
///   worst case is n(n−1)/2 ("después de cada comparación habrá un intercambio"), reached on
///   strictly decreasing input.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::bubble_sort_with;
///
/// let mut v = [7, 3, 5, 1];
/// let mut counts = Counts::default();
/// bubble_sort_with(&mut v, i32::cmp, &mut counts);
/// assert_eq!(v, [1, 3, 5, 7]);
/// assert_eq!(counts.comparisons, 6); // 4 * 3 / 2
/// assert_eq!(counts.swaps, 5); // the inversions 7>3, 7>5, 7>1, 3>1, 5>1
/// ```
pub fn bubble_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    bubble(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn bubble<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    let n = v.len();
    for pass in 1..n {
        for j in 0..n - pass {
            if ops.less(&v[j + 1], &v[j]) {
                ops.swap(v, j, j + 1);
            }
            obs.step(v, Step::Compared { j });
        }
        obs.step(v, Step::PassDone { pass });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    #[test]
    fn sorted_input_still_makes_every_pass() {
        for n in 0..20u64 {
            let mut v: Vec<u64> = (0..n).collect();
            let mut c = Counts::default();
            bubble_sort_with(&mut v, u64::cmp, &mut c);
            assert_eq!(c.comparisons, n * n.saturating_sub(1) / 2);
            assert_eq!(c.swaps, 0);
            assert!(v.windows(2).all(|w| w[0] <= w[1]));
        }
    }

    #[test]
    fn reversed_input_swaps_after_every_comparison() {
        for n in 0..20u64 {
            let mut v: Vec<u64> = (0..n).rev().collect();
            let mut c = Counts::default();
            bubble_sort_with(&mut v, u64::cmp, &mut c);
            assert_eq!(c.swaps, c.comparisons);
            assert_eq!(v, (0..n).collect::<Vec<_>>());
        }
    }
}
