//! Insertion sort by bisection, with the fewest comparisons a bisection can make.
//!
//! Step `k` (from 1 to n − 1) inserts `x = v[k]` into the sorted prefix `v[..k]` and finds its
//! place by bisection (the course, [RD, §2.1] "Inserción por bisección"):
//! compare `x` with the middle element of the candidate run and keep the half on `x`'s side.
//! Here the compared element leaves the run, so a run of m elements leaves at most ⌊m/2⌋
//! candidates and a step costs at most ⌊log₂ k⌋ + 1 = ⌈log₂(k + 1)⌉ comparisons: the
//! information-theoretic minimum for choosing one of k + 1 gaps. In total at most
//! ⌈log₂ 2⌉ + ⌈log₂ 3⌉ + … + ⌈log₂ n⌉, the course's bound log₂ 2 + … + log₂ n with each term
//! rounded up.
//!
//! The course's worked table keeps the compared element in the right half and therefore ends
//! with a comparison that can repeat an earlier one; that variant, which reproduces the table
//! row for row, is [`super::course_binary_insertion_sort`].
//!
//! Invariants the tests check: per step between ⌊log₂ k⌋ and ⌈log₂(k + 1)⌉ comparisons;
//! totals at most Σ_{k=2}^{n} ⌈log₂ k⌉; moves equal the inversions; stable.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "binary-insertion",
    function: "sort::binary_insertion_sort",
    file: "src/sort/binary_insertion.rs",
    summary: "insertion by bisection",
    time: "O(n²) worst case",
    space: "O(1)",
    operation: Some(Operation::Moves),
    counts: "at most ⌈log₂ k⌉ comparisons per step, one move per inversion",
    source: "[RD, §2.1]",
    claims: &[on("random", Bound::Quadratic, Operation::Moves)],
};

/// Sorts `v` in increasing order with insertion sort by bisection.
///
/// See [`binary_insertion_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1, 4, 6];
/// compgeo::sort::binary_insertion_sort(&mut v);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// ```
pub fn binary_insertion_sort<T: Ord>(v: &mut [T]) {
    binary_insertion_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with insertion sort by bisection; stable.
///
/// For floats pass `f64::total_cmp`. See [`binary_insertion_sort_with`].
///
/// ```
/// let mut v = [1.0, -f64::NAN, f64::MIN_POSITIVE, -0.5];
/// compgeo::sort::binary_insertion_sort_by(&mut v, f64::total_cmp);
/// assert!(v[0].is_nan() && v[0].is_sign_negative());
/// assert_eq!(v[1..], [-0.5, f64::MIN_POSITIVE, 1.0]);
/// ```
pub fn binary_insertion_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    binary_insertion_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with insertion sort by bisection, recording its operations in
/// `counter`.
///
/// Idea: for `k = 1, …, n − 1`, the place of `x = v[k]` lies in the gap range `lo..=hi`,
/// initially `0..=k`. While `lo < hi`, compare `x` with `v[mid]`, `mid = lo + ⌊(hi − lo)/2⌋`:
/// if `x < v[mid]` the place is at most `mid` (`hi = mid`), otherwise after it
/// (`lo = mid + 1`). Then shift `v[lo..k]` one place right and put `x` at `lo`. Equal
/// elements send `x` right, after them (stable).
///
/// Follows [RD, §2.1] "Inserción por bisección" and "Complejidad de los
/// algoritmos de ordenación" (see the module docs for how it differs from the course's table).
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
/// - comparisons: between ⌊log₂ k⌋ and ⌊log₂ k⌋ + 1 = ⌈log₂(k + 1)⌉ in step `k`; in total at
///   most Σ_{k=2}^{n} ⌈log₂ k⌉ ≤ (n − 1)⌈log₂ n⌉;
/// - moves: one per element shifted one place right, as in [`super::insertion_sort_with`]:
///   the number of inversions of the input, at most n(n−1)/2 (the course: "O(n²) igual que en
///   la inserción secuencial").
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::binary_insertion_sort_with;
///
/// let mut v = [7, 3, 5, 1, 4, 6];
/// let mut counts = Counts::default();
/// binary_insertion_sort_with(&mut v, i32::cmp, &mut counts);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// assert!(counts.comparisons <= 1 + 2 + 2 + 3 + 3); // Σ ⌈log₂ k⌉ for k = 2..=6
/// assert_eq!(counts.moves, 8);
/// ```
pub fn binary_insertion_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    binary_insertion(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn binary_insertion<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    for k in 1..v.len() {
        let (mut lo, mut hi) = (0, k);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            obs.step(v, Step::Probe { k, lo, mid, hi });
            if ops.less(&v[k], &v[mid]) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        if lo < k {
            v[lo..=k].rotate_right(1);
            ops.moves(k - lo);
        }
        obs.step(v, Step::Inserted { k, pos: lo });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    /// Each single insertion into a sorted prefix of length k, at every position.
    #[test]
    fn one_step_costs_floor_log_or_one_more() {
        for k in 1..70u64 {
            for p in 0..=k {
                // Prefix 0, 2, 4, ..., then x = 2p - 1 goes to position p.
                let mut v: Vec<i64> = (0..k as i64).map(|i| 2 * i).collect();
                v.push(2 * p as i64 - 1);
                let mut prefix = v[..k as usize].to_vec();
                let mut c = Counts::default();
                binary_insertion(
                    &mut prefix,
                    &mut Counted::new(i64::cmp, &mut c),
                    &mut NoObserver,
                );
                let made = c.comparisons;
                binary_insertion(&mut v, &mut Counted::new(i64::cmp, &mut c), &mut NoObserver);
                assert!(v.windows(2).all(|w| w[0] <= w[1]));
                let step = c.comparisons - 2 * made;
                let floor = u64::from(k.ilog2());
                assert!(
                    step == floor || step == floor + 1,
                    "k={k} p={p} step={step}"
                );
                assert_eq!(c.moves, k - p);
            }
        }
    }
}
