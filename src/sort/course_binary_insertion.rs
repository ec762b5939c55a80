//! Insertion sort by bisection, exactly as the course's table does it.
//!
//! Step `k` (from 1 to n − 1) inserts `x = v[k]` into the sorted prefix `v[..k]`, found by
//! bisection: the course ([RD, §2.1] "Inserción por bisección") splits the
//! current run into a left half of ⌈m/2⌉ and a right half of ⌊m/2⌋ elements
//! ("4 ↦ {1, 3 | 5, 7}"), compares `x` with the first element of the right half, keeps the
//! left half if `x` is smaller and the right half (that element included) otherwise, and when
//! one element `e` is left compares once more to put `x` before or after it. Because the
//! compared element stays in the right half, that last comparison can repeat one already made
//! — the course's own table shows it: "4 > 3 ⇒ 4 ↦ {3} : 4 > 3 ⇒ {3, 4}" — and this file
//! keeps it, so that [`super::trace`] reproduces the table row for row.
//!
//! A step into a prefix of length k therefore costs between ⌊log₂ k⌋ + 1 comparisons (always
//! right: nondecreasing input) and ⌈log₂ k⌉ + 1 (always left: strictly decreasing input).
//! The course bounds the total by log₂ 2 + … + log₂ n ≤ (n − 1) log₂ n; with the repeated
//! comparison the exact worst case is Σ_{k=1}^{n−1} (⌈log₂ k⌉ + 1), which exceeds the optimal
//! Σ ⌈log₂(k + 1)⌉ of a bisection without the repeat ([`super::binary_insertion_sort`]) by at
//! most one per step. The course's own table is an instance: 12 comparisons for six elements,
//! above its stated bound log₂ 2 + … + log₂ 6 = log₂ 720 ≈ 9.49 (the optimal bisection makes
//! at most 1 + 2 + 2 + 3 + 3 = 11).
//!
//! Invariants the tests check: those per-step counts (exact on monotone inputs, bounds
//! otherwise); moves equal the inversions; stable; the course's table.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "course-binary-insertion",
    function: "sort::course_binary_insertion_sort",
    file: "src/sort/course_binary_insertion.rs",
    summary: "insertion by bisection as the course's table does it",
    time: "O(n²) worst case",
    space: "O(1)",
    operation: Some(Operation::Moves),
    counts: "⌈log₂ k⌉ + 1 comparisons per step, one move per inversion",
    source: "[RD, §2.1]",
    claims: &[on("random", Bound::Quadratic, Operation::Moves)],
};

/// Sorts `v` in increasing order with the course's insertion sort by bisection.
///
/// See [`course_binary_insertion_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1, 4, 6];
/// compgeo::sort::course_binary_insertion_sort(&mut v);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// ```
pub fn course_binary_insertion_sort<T: Ord>(v: &mut [T]) {
    course_binary_insertion_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with the course's insertion sort by bisection; stable.
///
/// For floats pass `f64::total_cmp`. See [`course_binary_insertion_sort_with`].
///
/// ```
/// let mut v = [1.0, -f64::NAN, f64::MIN_POSITIVE, -0.5];
/// compgeo::sort::course_binary_insertion_sort_by(&mut v, f64::total_cmp);
/// assert!(v[0].is_nan() && v[0].is_sign_negative());
/// assert_eq!(v[1..], [-0.5, f64::MIN_POSITIVE, 1.0]);
/// ```
pub fn course_binary_insertion_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    course_binary_insertion_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with the course's insertion sort by bisection, recording its operations
/// in `counter`.
///
/// Idea: for `k = 1, …, n − 1`, search the sorted prefix `v[..k]` for the place of
/// `x = v[k]`: while the run `v[lo..hi]` has two or more elements, compare `x` with
/// `v[mid]`, `mid = lo + ⌈(hi − lo)/2⌉`, and keep `v[lo..mid]` if `x < v[mid]`, else
/// `v[mid..hi]`; at one element compare once more. Then shift the larger elements one place
/// right and put `x` in the gap. Equal elements send `x` right, after them (stable).
///
/// Follows [RD, §2.1] "Inserción por bisección" and "Complejidad de los
/// algoritmos de ordenación" (see the module docs for the course's repeated comparison).
///
/// # Errors
///
/// None: every slice, empty included, is valid input. `cmp` should be a total order; if it is
/// not, the result is some permutation of `v`.
///
/// # Complexity
///
/// With n = `v.len()`: O(n log n) comparisons but Θ(n²) moves in the worst case, so time
/// O(n²) worst case (Θ(n log n) on nondecreasing input); auxiliary space O(1).
///
/// # Counts
///
/// - comparisons: between ⌊log₂ k⌋ + 1 and ⌈log₂ k⌉ + 1 in step `k`; in total at most
///   Σ_{k=1}^{n−1} (⌈log₂ k⌉ + 1), reached exactly on strictly decreasing input, and exactly
///   Σ_{k=1}^{n−1} (⌊log₂ k⌋ + 1) on nondecreasing input;
/// - moves: one per element shifted one place right, as in [`insertion_sort_with`]: the
///   number of inversions of the input, at most n(n−1)/2 (the course: "O(n²) igual que en la
///   inserción secuencial").
///
/// [`insertion_sort_with`]: super::course_insertion_sort_with
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::course_binary_insertion_sort_with;
///
/// let mut v = [7, 3, 5, 1, 4, 6];
/// let mut counts = Counts::default();
/// course_binary_insertion_sort_with(&mut v, i32::cmp, &mut counts);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// assert_eq!(counts.comparisons, 1 + 2 + 3 + 3 + 3); // the course's table
/// assert_eq!(counts.moves, 8);
/// ```
pub fn course_binary_insertion_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    course_binary_insertion(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn course_binary_insertion<T, F, C, O>(
    v: &mut [T],
    ops: &mut Counted<'_, F, C>,
    obs: &mut O,
) where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    for k in 1..v.len() {
        let (mut lo, mut hi) = (0, k);
        while hi - lo > 1 {
            let mid = lo + (hi - lo).div_ceil(2);
            obs.step(v, Step::Probe { k, lo, mid, hi });
            if ops.less(&v[k], &v[mid]) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        obs.step(v, Step::Probe { k, lo, mid: lo, hi });
        let pos = if ops.less(&v[k], &v[lo]) { lo } else { lo + 1 };
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

    fn ceil_log2(k: u64) -> u64 {
        u64::from(k.next_power_of_two().trailing_zeros())
    }

    fn floor_log2(k: u64) -> u64 {
        u64::from(k.ilog2())
    }

    /// Each single insertion into a sorted prefix of length k, at every position.
    #[test]
    fn one_step_costs_between_floor_and_ceil_log_plus_one() {
        for k in 1..40u64 {
            for p in 0..=k {
                // Prefix 0, 2, 4, ..., then x = 2p - 1 goes to position p.
                let mut v: Vec<i64> = (0..k as i64).map(|i| 2 * i).collect();
                v.push(2 * p as i64 - 1);
                let mut c = Counts::default();
                let mut ops = Counted::new(i64::cmp, &mut c);
                course_binary_insertion(&mut v, &mut ops, &mut NoObserver);
                assert!(v.windows(2).all(|w| w[0] <= w[1]));
                // The increasing prefix's own steps always go right: ⌊log₂ j⌋ + 1 each.
                let made: u64 = (1..k).map(|j| floor_log2(j) + 1).sum::<u64>();
                let step = c.comparisons - made;
                assert!(step > floor_log2(k), "k={k} p={p} step={step}");
                assert!(step <= ceil_log2(k) + 1, "k={k} p={p} step={step}");
                assert_eq!(c.moves, k - p);
            }
        }
    }
}
