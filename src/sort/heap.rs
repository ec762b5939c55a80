//! Heap sort on an implicit binary max-heap: O(n log n) worst case, in place.
//!
//! The slice is viewed as a complete binary tree (children of `i` at `2i + 1`, `2i + 2`).
//! Bottom-up heap construction makes every parent at least as large as its children; then the
//! maximum at the root is exchanged with the last element of the heap, the heap shrinks by
//! one and the new root sifts down. Not in the course, whose sorting section stops at the
//! quadratic sorts ([RD, §2.1] "Algoritmos de ordenación"); it is the
//! in-place O(n log n) reference and [`super::quick_sort`]'s guard against bad pivots.
//!
//! Invariants the tests check: comparisons at most 2(n − s(n)) + 2 Σ_{m=1}^{n−1} ⌊log₂ m⌋
//! (s(n) = number of one bits of n), which is at most 2n log₂ n; agreement with `sort`.

use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "heap",
    function: "sort::heap_sort",
    file: "src/sort/heap.rs",
    summary: "heap sort on a binary max-heap",
    time: "O(n log n) worst case",
    space: "O(1)",
    operation: Some(Operation::Comparisons),
    counts: "at most 2n log₂ n comparisons",
    source: "[RD, §2.1]",
    claims: &[on("random", Bound::NLogN, Operation::Comparisons)],
};

/// Sorts `v` in increasing order with heap sort.
///
/// See [`heap_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1, 4, 6];
/// compgeo::sort::heap_sort(&mut v);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// ```
pub fn heap_sort<T: Ord>(v: &mut [T]) {
    heap_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with heap sort; not stable.
///
/// For floats pass `f64::total_cmp`. See [`heap_sort_with`].
///
/// ```
/// let mut v = [1.0, f64::INFINITY, -4e-320, -0.0];
/// compgeo::sort::heap_sort_by(&mut v, f64::total_cmp);
/// assert_eq!(v.map(f64::to_bits), [-4e-320, -0.0, 1.0, f64::INFINITY].map(f64::to_bits));
/// ```
pub fn heap_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    heap_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with heap sort, recording its operations in `counter`.
///
/// Idea: build a max-heap bottom up (sift down every parent, last parent first); then for
/// `end = n − 1, …, 1` exchange the root with `v[end]` and sift the new root down in
/// `v[..end]`. A sift-down step compares the two children with each other (when there are
/// two) and the larger child with the parent, and exchanges them if the parent is smaller.
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
/// With n = `v.len()`: time O(n log n) worst case (Θ(n) when all elements are equal);
/// auxiliary space O(1).
///
/// # Counts
///
/// - comparisons: at most 2 per level of each sift-down, so at most 2(n − s(n)) for the
///   construction (the heights of the nodes of a heap of n nodes sum to n − s(n), s(n) the
///   number of one bits of n) plus 2⌊log₂ m⌋ for the sift-down in a heap of m elements,
///   m = n − 1, …, 1; in total at most 2n log₂ n;
/// - swaps: one per sift-down exchange plus one per root extraction (n − 1).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::heap_sort_with;
///
/// let mut v: Vec<u32> = (0..100).rev().collect();
/// let mut counts = Counts::default();
/// heap_sort_with(&mut v, u32::cmp, &mut counts);
/// assert!(v.windows(2).all(|w| w[0] <= w[1]));
/// assert!(counts.comparisons as f64 <= 2.0 * 100.0 * 100f64.log2());
/// ```
pub fn heap_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    heap(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`]; also quicksort's fallback.
pub(crate) fn heap<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    let n = v.len();
    if n < 2 {
        return;
    }
    for root in (0..n / 2).rev() {
        sift_down(v, root, n, ops);
    }
    obs.step(v, Step::HeapBuilt);
    for end in (1..n).rev() {
        ops.swap(v, 0, end);
        sift_down(v, 0, end, ops);
        obs.step(v, Step::Extracted { end });
    }
}

/// Restores the heap order of `v[..end]` below `root`, assuming both subtrees of `root` are
/// heaps.
fn sift_down<T, F, C>(v: &mut [T], mut root: usize, end: usize, ops: &mut Counted<'_, F, C>)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    loop {
        let mut child = 2 * root + 1;
        if child >= end {
            return;
        }
        if child + 1 < end && ops.less(&v[child], &v[child + 1]) {
            child += 1;
        }
        if !ops.less(&v[root], &v[child]) {
            return;
        }
        ops.swap(v, root, child);
        root = child;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    struct HeapChecker {
        rows: usize,
    }

    impl Observer<i32> for HeapChecker {
        fn step(&mut self, v: &[i32], step: Step<'_>) {
            let end = match step {
                Step::HeapBuilt => v.len(),
                Step::Extracted { end } => end,
                _ => panic!("heap sort reported {step:?}"),
            };
            for i in 1..end {
                assert!(v[(i - 1) / 2] >= v[i], "heap order broken at {i} in {v:?}");
            }
            for i in end..v.len() {
                assert!(v[..end].iter().all(|x| *x <= v[i]), "{v:?}");
                assert!(i + 1 == v.len() || v[i] <= v[i + 1], "{v:?}");
            }
            self.rows += 1;
        }
    }

    #[test]
    fn every_step_keeps_a_heap_below_a_sorted_suffix() {
        let mut v: Vec<i32> = (0..50).map(|i| (i * 37) % 23).collect();
        let mut counts = Counts::default();
        let mut checker = HeapChecker { rows: 0 };
        heap(
            &mut v,
            &mut Counted::new(i32::cmp, &mut counts),
            &mut checker,
        );
        assert_eq!(checker.rows, 50);
        assert!(v.windows(2).all(|w| w[0] <= w[1]));
    }

    #[test]
    fn equal_elements_cost_linear_comparisons() {
        for n in 2..100u64 {
            let mut v = vec![7u8; n as usize];
            let mut c = Counts::default();
            heap_sort_with(&mut v, u8::cmp, &mut c);
            // Each sift-down stops after one level: at most 2 comparisons and no exchange.
            assert!(c.comparisons <= 2 * (n / 2 + n - 1));
            assert_eq!(c.swaps, n - 1);
        }
    }
}
