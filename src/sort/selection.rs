//! Selection sort, as the course states it: select the minimum of the rest, exchange it forward.
//!
//! Step `i` (from 1 to n − 1) finds the smallest of `x_i, …, x_n` with a linear scan and
//! exchanges it with `x_i`; when the minimum already is `x_i` nothing is exchanged ("no se
//! hace ninguna operación"). After step `i` the first `i` elements are the `i` smallest, in
//! order. Seed: [RD, §2.1] "Algoritmo de ordenación por Selección".
//!
//! Invariants the tests check: exactly n(n−1)/2 comparisons; at most n − 1 swaps and at least
//! n − c (c = cycles of the permutation, distinct keys); the course's table for
//! {1, 3, 2, 9, 5, 4}.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "selection",
    function: "sort::selection_sort",
    file: "src/sort/selection.rs",
    summary: "the course's selection sort",
    time: "Θ(n²)",
    space: "O(1)",
    operation: Some(Operation::Comparisons),
    counts: "exactly n(n − 1)/2 comparisons",
    source: "[RD, §2.1]",
    claims: &[on("random", Bound::Quadratic, Operation::Comparisons)],
};

/// Sorts `v` in increasing order with the course's selection sort.
///
/// See [`selection_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [1, 3, 2, 9, 5, 4];
/// compgeo::sort::selection_sort(&mut v);
/// assert_eq!(v, [1, 2, 3, 4, 5, 9]);
/// ```
pub fn selection_sort<T: Ord>(v: &mut [T]) {
    selection_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with the course's selection sort; not stable.
///
/// For floats pass `f64::total_cmp`. See [`selection_sort_with`].
///
/// ```
/// let mut v = [0.0, -0.0, -2.0];
/// compgeo::sort::selection_sort_by(&mut v, f64::total_cmp);
/// assert_eq!(v.map(f64::to_bits), [-2.0, -0.0, 0.0].map(f64::to_bits));
/// ```
pub fn selection_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    selection_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with the course's selection sort, recording its operations in `counter`.
///
/// Idea: for `i = 0, …, n − 2`, scan `v[i + 1..]` for the first position `m` of the minimum of
/// `v[i..]` (a linear scan, n − 1 − i comparisons) and exchange `v[i]` with `v[m]` when
/// `m ≠ i`. Not stable: the exchange can carry `v[i]` past an equal element.
///
/// Follows [RD, §2.1] "Algoritmo de ordenación por Selección" and
/// "Complejidad de los algoritmos de ordenación".
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
/// - comparisons: exactly n(n−1)/2 (the course: n − 1 linear minimum searches, "cuadrático");
/// - swaps: one per step whose minimum is not already in place, so at most n − 1.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::selection_sort_with;
///
/// let mut v = [1, 3, 2, 9, 5, 4];
/// let mut counts = Counts::default();
/// selection_sort_with(&mut v, i32::cmp, &mut counts);
/// assert_eq!(v, [1, 2, 3, 4, 5, 9]);
/// assert_eq!(counts.comparisons, 15); // 6 * 5 / 2
/// assert_eq!(counts.swaps, 2); // the course's steps 2 and 4
/// ```
pub fn selection_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    selection(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn selection<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    let n = v.len();
    for i in 0..n.saturating_sub(1) {
        let mut min = i;
        for j in i + 1..n {
            if ops.less(&v[j], &v[min]) {
                min = j;
            }
        }
        if min != i {
            ops.swap(v, i, min);
        }
        obs.step(v, Step::Selected { i, min });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    #[test]
    fn sorted_input_needs_no_swap() {
        for n in 0..20u64 {
            let mut v: Vec<u64> = (0..n).collect();
            let mut c = Counts::default();
            selection_sort_with(&mut v, u64::cmp, &mut c);
            assert_eq!(c.comparisons, n * n.saturating_sub(1) / 2);
            assert_eq!(c.swaps, 0);
        }
    }

    #[test]
    fn reversed_input_swaps_only_in_the_first_half() {
        // Exchanging the ends of a reversed run leaves a reversed run two shorter.
        for n in 0..20u64 {
            let mut v: Vec<u64> = (0..n).rev().collect();
            let mut c = Counts::default();
            selection_sort_with(&mut v, u64::cmp, &mut c);
            assert_eq!(c.swaps, n / 2);
            assert_eq!(v, (0..n).collect::<Vec<_>>());
        }
    }
}
