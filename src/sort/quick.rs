//! Quicksort with sampled pivots and a heap-sort guard (introsort): O(n log n) worst case.
//!
//! Each range is partitioned around a pivot sampled from its interior — the median of the
//! elements at m/4, m/2 and 3m/4, or on ranges of at least 64 elements Tukey's ninther, the
//! median of three such medians of nine evenly spaced elements — and the two sides are sorted
//! recursively (the smaller one first, so the stack stays O(log n)). Equal elements stop both
//! partition scans and are exchanged, so runs of equal keys split evenly instead of
//! degrading to n²; sorted, reversed and organ-pipe inputs get near-exact medians. Inputs
//! built against any fixed pivot rule still exist (McIlroy's adversary builds them), so after
//! 2⌊log₂ n⌋ levels of partitioning a range is handed to [`super::heap_sort`] (Musser's
//! introsort). Not in the course ([RD, §2.1] stops at the quadratic
//! sorts).
//!
//! Invariants the tests check: at most 6n log₂ n + n comparisons on every input, McIlroy's
//! adversarial comparator included (which does reach the heap-sort guard); no guard and
//! under 1.5 n log₂ n comparisons on sorted, reversed, few-distinct, sawtooth and organ-pipe
//! input; each partition leaves smaller-or-equal elements left of the pivot and
//! larger-or-equal ones right of it.

use super::heap::heap;
use super::{Counted, NoObserver, Observer, Step};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "quick",
    function: "sort::quick_sort",
    file: "src/sort/quick.rs",
    summary: "median-of-three quicksort with a heap-sort guard (introsort)",
    time: "O(n log n) worst case",
    space: "O(log n)",
    operation: Some(Operation::Comparisons),
    counts: "at most 6n log₂ n + n comparisons",
    source: "[RD, §2.1]",
    claims: &[
        on("random", Bound::NLogN, Operation::Comparisons),
        on("sorted", Bound::NLogN, Operation::Comparisons),
    ],
};

/// Ranges at least this long take their pivot as Tukey's ninther (the median of three medians
/// of three) instead of the median of three.
const NINTHER_MIN: usize = 64;

/// Sorts `v` in increasing order with introsort (median-of-three quicksort).
///
/// See [`quick_sort_with`] for the algorithm, its complexity and what it counts.
///
/// ```
/// let mut v = [7, 3, 5, 1, 4, 6];
/// compgeo::sort::quick_sort(&mut v);
/// assert_eq!(v, [1, 3, 4, 5, 6, 7]);
/// ```
pub fn quick_sort<T: Ord>(v: &mut [T]) {
    quick_sort_with(v, T::cmp, &mut NoCount);
}

/// Sorts `v` by the comparator `cmp` with introsort; not stable.
///
/// For floats pass `f64::total_cmp`. See [`quick_sort_with`].
///
/// ```
/// let mut v = [f64::NAN, -f64::NAN, 0.0, -0.0];
/// compgeo::sort::quick_sort_by(&mut v, f64::total_cmp);
/// assert!(v[0].is_nan() && v[0].is_sign_negative() && v[3].is_nan());
/// assert_eq!([v[1].to_bits(), v[2].to_bits()], [(-0.0f64).to_bits(), 0]);
/// ```
pub fn quick_sort_by<T, F>(v: &mut [T], cmp: F)
where
    F: FnMut(&T, &T) -> Ordering,
{
    quick_sort_with(v, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with introsort, recording its operations in `counter`.
///
/// Idea: a range of m ≥ 4 elements takes as pivot the median of three interior samples (the
/// ninther of nine when m ≥ 64), moves it to the front and partitions the rest with two
/// scans that stop at elements not smaller (left scan) and not larger (right scan) than the
/// pivot and exchange them; the pivot then goes between the two sides. Ranges of two or
/// three elements are sorted directly by compare-exchange; a range met after 2⌊log₂ n⌋
/// levels of partitioning is heap-sorted.
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
/// With n = `v.len()`: time O(n log n) worst case (the guard); on random input about
/// 1.04 n log₂ n comparisons (measured at n = 10⁵); auxiliary space O(log n) stack.
///
/// # Counts
///
/// - comparisons: at most m + 1 for the scans of a range of m elements, plus 3 (median of
///   three) or 12 (ninther) for its pivot, so at most 2m; at most 3 for a short range; heap
///   sort's count for guarded ranges. As the ranges partitioned at one level are disjoint,
///   in total at most 2n · 2⌊log₂ n⌋ + 2n log₂ n + n ≤ 6n log₂ n + n;
/// - swaps: the exchanges that bring the pivot to the front, of the partition scans, of the
///   pivot placement, of short ranges and of any guarded heap sort; O(n log n).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::quick_sort_with;
///
/// let n = 1000u64;
/// let mut v: Vec<u64> = (0..n).rev().collect();
/// let mut counts = Counts::default();
/// quick_sort_with(&mut v, u64::cmp, &mut counts);
/// assert_eq!(v, (0..n).collect::<Vec<_>>());
/// // Far below the n(n-1)/2 = 499500 of a first-element pivot.
/// assert!(counts.comparisons < 2 * n * 10);
/// ```
pub fn quick_sort_with<T, F, C>(v: &mut [T], cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    quick(v, &mut Counted::new(cmp, counter), &mut NoObserver);
}

/// The algorithm, with an observer for [`super::trace`].
pub(crate) fn quick<T, F, C, O>(v: &mut [T], ops: &mut Counted<'_, F, C>, obs: &mut O)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    let n = v.len();
    if n < 2 {
        return;
    }
    quick_range(v, 0, n, 2 * n.ilog2(), ops, obs);
}

/// Sorts `v[lo..hi]`, allowing `depth` more levels of partitioning before heap sort.
fn quick_range<T, F, C, O>(
    v: &mut [T],
    mut lo: usize,
    mut hi: usize,
    mut depth: u32,
    ops: &mut Counted<'_, F, C>,
    obs: &mut O,
) where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
    O: Observer<T>,
{
    loop {
        let m = hi - lo;
        if m <= 3 {
            if m >= 2 {
                sort_short(&mut v[lo..hi], ops);
                obs.step(v, Step::ShortSorted { lo, hi });
            }
            return;
        }
        if depth == 0 {
            heap(&mut v[lo..hi], ops, &mut NoObserver);
            obs.step(v, Step::HeapFallback { lo, hi });
            return;
        }
        depth -= 1;
        let pivot = lo + partition(&mut v[lo..hi], ops);
        obs.step(v, Step::Partitioned { lo, hi, pivot });
        // Recurse into the smaller side and loop on the larger: O(log n) stack.
        if pivot - lo < hi - pivot - 1 {
            quick_range(v, lo, pivot, depth, ops, obs);
            lo = pivot + 1;
        } else {
            quick_range(v, pivot + 1, hi, depth, ops, obs);
            hi = pivot;
        }
    }
}

/// Partitions `s` (at least 4 elements) around a sampled pivot; returns the pivot's final
/// position `p`: `s[..p] <= s[p] <= s[p + 1..]`.
fn partition<T, F, C>(s: &mut [T], ops: &mut Counted<'_, F, C>) -> usize
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    let m = s.len();
    // Samples avoid the ends: a partition leaves an extreme element at the front of its left
    // side (the pivot's exchange partner), and sampling it would bias the next pivot.
    let pivot = if m < NINTHER_MIN {
        median_of_three(s, m / 4, m / 2, 3 * m / 4, ops)
    } else {
        let at = |k: usize| (2 * k + 1) * m / 18;
        let a = median_of_three(s, at(0), at(1), at(2), ops);
        let b = median_of_three(s, at(3), at(4), at(5), ops);
        let c = median_of_three(s, at(6), at(7), at(8), ops);
        median_of_three(s, a, b, c, ops)
    };
    ops.swap(s, 0, pivot);

    // Invariant: s[1..i] <= pivot <= s[j + 1..]; both scans stop on elements equal to the
    // pivot, which keeps runs of equal keys balanced.
    let (mut i, mut j) = (1, m - 1);
    loop {
        while i <= j && ops.less(&s[i], &s[0]) {
            i += 1;
        }
        while i <= j && ops.less(&s[0], &s[j]) {
            j -= 1;
        }
        if i >= j {
            break;
        }
        ops.swap(s, i, j);
        i += 1;
        j -= 1;
    }
    if j != 0 {
        ops.swap(s, 0, j);
    }
    j
}

/// The position, among `a`, `b`, `c`, of the median of `s[a]`, `s[b]`, `s[c]`: two or three
/// comparisons.
fn median_of_three<T, F, C>(
    s: &[T],
    a: usize,
    b: usize,
    c: usize,
    ops: &mut Counted<'_, F, C>,
) -> usize
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    if ops.less(&s[b], &s[a]) {
        if ops.less(&s[c], &s[b]) {
            b
        } else if ops.less(&s[c], &s[a]) {
            c
        } else {
            a
        }
    } else if ops.less(&s[c], &s[a]) {
        a
    } else if ops.less(&s[c], &s[b]) {
        c
    } else {
        b
    }
}

/// Sorts a slice of two or three elements by compare-exchange.
fn sort_short<T, F, C>(s: &mut [T], ops: &mut Counted<'_, F, C>)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    compare_exchange(s, 0, 1, ops);
    if s.len() == 3 {
        compare_exchange(s, 1, 2, ops);
        compare_exchange(s, 0, 1, ops);
    }
}

/// Puts `s[a]` and `s[b]` (`a < b`) in order.
fn compare_exchange<T, F, C>(s: &mut [T], a: usize, b: usize, ops: &mut Counted<'_, F, C>)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    if ops.less(&s[b], &s[a]) {
        ops.swap(s, a, b);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;
    use std::cell::Cell;

    /// Counts the guarded ranges and checks every partition.
    #[derive(Default)]
    struct Watch {
        fallbacks: usize,
        partitions: usize,
    }

    impl<T: Ord + std::fmt::Debug> Observer<T> for Watch {
        fn step(&mut self, v: &[T], step: Step<'_>) {
            match step {
                Step::Partitioned { lo, hi, pivot } => {
                    assert!(v[lo..pivot].iter().all(|x| *x <= v[pivot]));
                    assert!(v[pivot + 1..hi].iter().all(|x| *x >= v[pivot]));
                    self.partitions += 1;
                }
                Step::HeapFallback { lo, hi } => {
                    assert!(v[lo..hi].windows(2).all(|w| w[0] <= w[1]));
                    self.fallbacks += 1;
                }
                Step::ShortSorted { lo, hi } => {
                    assert!(v[lo..hi].windows(2).all(|w| w[0] <= w[1]));
                }
                _ => panic!("quicksort reported {step:?}"),
            }
        }
    }

    fn bound(n: usize) -> f64 {
        6.0 * n as f64 * (n as f64).log2() + n as f64
    }

    fn run(v: &mut [u32]) -> (Counts, Watch) {
        let mut counts = Counts::default();
        let mut watch = Watch::default();
        quick(v, &mut Counted::new(u32::cmp, &mut counts), &mut watch);
        assert!(v.windows(2).all(|w| w[0] <= w[1]));
        (counts, watch)
    }

    #[test]
    fn benign_patterns_never_reach_the_guard() {
        let n = 3000u32;
        let patterns: [Vec<u32>; 8] = [
            (0..n).collect(),
            (0..n).rev().collect(),
            vec![5; n as usize],
            (0..n).map(|i| i % 3).collect(),
            (0..n).map(|i| i % 64).collect(),
            (0..n).map(|i| i.min(n - i)).collect(),
            (0..n).map(|i| n - i.min(n - i)).collect(),
            (0..n).map(|i| if i == 0 { n } else { i }).collect(),
        ];
        for mut v in patterns {
            let head = v[..4].to_vec();
            let (counts, watch) = run(&mut v);
            assert_eq!(watch.fallbacks, 0, "input starting {head:?}");
            assert!(watch.partitions > 0);
            // Balanced partitions: about n log2 n, far below the guarded bound.
            assert!((counts.comparisons as f64) < 1.5 * n as f64 * (n as f64).log2());
        }
    }

    /// McIlroy's "killer adversary for quicksort": the comparator decides the values of the
    /// elements lazily, always so that the current pivot candidate is as small as possible.
    /// Its answers are consistent with the values it finally assigns.
    #[test]
    fn mcilroy_adversary_reaches_the_guard_and_stays_n_log_n() {
        for n in [100usize, 1000, 3000] {
            let gas = n;
            let val: Vec<Cell<usize>> = (0..n).map(|_| Cell::new(gas)).collect();
            let solid = Cell::new(0);
            let candidate = Cell::new(0);
            let freeze = |x: usize| {
                val[x].set(solid.get());
                solid.set(solid.get() + 1);
            };
            let cmp = |&x: &usize, &y: &usize| {
                if val[x].get() == gas && val[y].get() == gas {
                    freeze(if x == candidate.get() { x } else { y });
                }
                if val[x].get() == gas {
                    candidate.set(x);
                } else if val[y].get() == gas {
                    candidate.set(y);
                }
                val[x].get().cmp(&val[y].get())
            };
            let mut items: Vec<usize> = (0..n).collect();
            let mut counts = Counts::default();
            quick(
                &mut items,
                &mut Counted::new(cmp, &mut counts),
                &mut NoObserver,
            );
            assert!((counts.comparisons as f64) < bound(n), "n={n}: {counts:?}");

            // Replay the input the adversary built as plain values: same comparisons, and
            // the guard is what kept them n log n.
            let mut replay: Vec<u32> = (0..n).map(|i| val[i].get() as u32).collect();
            let (replayed, watch) = run(&mut replay);
            assert_eq!(replayed.comparisons, counts.comparisons);
            assert!(
                watch.fallbacks > 0,
                "n={n}: the adversary never hit the guard"
            );
        }
    }
}
