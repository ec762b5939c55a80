//! Sorting: the course's quadratic sorts, the O(n log n) references, and a radix sort for `f64`.
//!
//! The course ([RD, §2.1] "Algoritmos de ordenación" and "Complejidad de
//! los algoritmos de ordenación") teaches bubble sort, selection sort and insertion sort
//! (sequential and by bisection) and measures them by counting comparisons and exchanges.
//! Merge sort, heap sort and quicksort are here so that growth plots can contrast O(n²) with
//! O(n log n); [`radix_sort_f64`] sorts `f64` keys in linear time by their bits.
//!
//! Insertion comes twice. The course's worked tables scan the sorted prefix from the front and
//! bisect with a repeated last comparison; those are the `course_` variants, whose traces
//! reproduce the tables line by line. [`insertion_sort`] and [`binary_insertion_sort`] are the
//! usual forms, with the cost profile of the course's complexity paragraph: sequential insertion
//! is worst on decreasing input, and bisection makes at most ⌈log₂ k⌉ comparisons per step.
//!
//! | algorithm | comparisons (worst) | stable | file |
//! |---|---|---|---|
//! | [`bubble_sort`] | n(n−1)/2, always | yes | `bubble.rs` |
//! | [`selection_sort`] | n(n−1)/2, always | no | `selection.rs` |
//! | [`insertion_sort`] | n(n−1)/2 (decreasing input) | yes | `insertion.rs` |
//! | [`course_insertion_sort`] | n(n−1)/2 (nondecreasing input) | yes | `course_insertion.rs` |
//! | [`binary_insertion_sort`] | Σ_{k=2}^{n} ⌈log₂ k⌉ | yes | `binary_insertion.rs` |
//! | [`course_binary_insertion_sort`] | Σ_{k=1}^{n−1} (⌈log₂ k⌉ + 1) | yes | `course_binary_insertion.rs` |
//! | [`merge_sort`] | n⌈log₂ n⌉ − 2^⌈log₂ n⌉ + 1 | yes | `merge.rs` |
//! | [`heap_sort`] | 2n log₂ n | no | `heap.rs` |
//! | [`quick_sort`] | 6n log₂ n + n (introsort) | no | `quick.rs` |
//! | [`radix_sort_f64`] | at most 7.5n, of integer keys in its insertion passes; O(n) time | — | `radix.rs` |
//!
//! # Three entry points per comparison sort
//!
//! Each comparison sort `X` comes as `X_sort(v)` (by [`Ord`]), `X_sort_by(v, cmp)` and
//! `X_sort_with(v, cmp, counter)`. The algorithm is written once, behind `X_sort_with`; the
//! other two call it with [`NoCount`], which compiles the counting
//! away. [`Algorithm`] names the nine comparison sorts for callers that pick one at run time
//! (the command line, the complexity report), through [`sort`], [`sort_by`] and [`sort_with`].
//!
//! # Counting conventions
//!
//! Comparisons are counted at the boundary: every call of the caller's comparator is one
//! [`Counter::comparison`], nothing else is. Exchanges of two elements are
//! [`Counter::swap`]; single-element moves (insertion sort's shifts, merge sort's placements,
//! radix sort's distributions) are [`Counter::element_move`]. Each algorithm's docs say which of these it records and which
//! numbers the course states for it.
//!
//! # Sorting floats
//!
//! `f64` is not [`Ord`] (NaN), so the float path is `X_sort_by(v, f64::total_cmp)`: the IEEE 754
//! total order, −NaN < −∞ < … < −0.0 < +0.0 < … < +∞ < +NaN. It never panics and agrees with
//! `v.sort_by(f64::total_cmp)`. [`radix_sort_f64`] sorts in the same order.
//!
//! ```
//! use compgeo::sort::{insertion_sort_by, merge_sort};
//!
//! let mut v = vec![7, 3, 5, 1, 4, 6];
//! merge_sort(&mut v);
//! assert_eq!(v, [1, 3, 4, 5, 6, 7]);
//!
//! let mut x = [0.5, -0.0, f64::NAN, 0.0, -1.5];
//! insertion_sort_by(&mut x, f64::total_cmp);
//! assert_eq!(x[..2], [-1.5, -0.0]);
//! assert!(x[1].is_sign_negative() && x[2].is_sign_positive() && x[4].is_nan());
//! ```
//!
//! [`trace`] prints the course's step tables from the real algorithms.

use crate::complexity::{algorithm_family, Declaration};
use crate::count::{Counter, NoCount};
use std::cmp::Ordering;

mod binary_insertion;
mod bubble;
mod course_binary_insertion;
mod course_insertion;
mod heap;
mod insertion;
mod merge;
mod quick;
mod radix;
mod selection;
mod trace;

pub use binary_insertion::{
    binary_insertion_sort, binary_insertion_sort_by, binary_insertion_sort_with,
};
pub use bubble::{bubble_sort, bubble_sort_by, bubble_sort_with};
pub use course_binary_insertion::{
    course_binary_insertion_sort, course_binary_insertion_sort_by,
    course_binary_insertion_sort_with,
};
pub use course_insertion::{
    course_insertion_sort, course_insertion_sort_by, course_insertion_sort_with,
};
pub use heap::{heap_sort, heap_sort_by, heap_sort_with};
pub use insertion::{insertion_sort, insertion_sort_by, insertion_sort_with};
pub use merge::{merge_sort, merge_sort_by, merge_sort_with};
pub use quick::{quick_sort, quick_sort_by, quick_sort_with};
pub use radix::{radix_sort_f64, radix_sort_f64_with};
pub use selection::{selection_sort, selection_sort_by, selection_sort_with};
pub use trace::{trace, TRACE_MAX_LEN};

/// The radix sort's declaration (the one sort that is not a comparison sort).
pub(crate) const RADIX: &Declaration = &radix::DECLARATION;

/// The sorts that are not a choice among comparison sorts: the radix sort.
pub(crate) const DECLARATIONS: [&Declaration; 1] = [RADIX];

algorithm_family! {
    /// The comparison sorts of this module, for callers that choose one at run time
    /// ([`sort`], [`sort_by`], [`sort_with`]).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::sort::{sort_with, Algorithm};
    ///
    /// let algorithm: Algorithm = "binary-insertion".parse()?;
    /// let mut v = [5, 2, 4, 1];
    /// let mut counts = Counts::default();
    /// sort_with(&mut v, algorithm, i32::cmp, &mut counts);
    /// assert_eq!(v, [1, 2, 4, 5]);
    /// assert!(counts.comparisons > 0);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum Algorithm ("sorting algorithm") {
        /// [`bubble_sort`]: the course's bubble sort, n(n−1)/2 comparisons.
        Bubble = bubble::DECLARATION => bubble_sort_with,
        /// [`selection_sort`]: the course's selection sort, n(n−1)/2 comparisons.
        Selection = selection::DECLARATION => selection_sort_with,
        /// [`insertion_sort`]: sequential insertion scanning from the back.
        Insertion = insertion::DECLARATION => insertion_sort_with,
        /// [`course_insertion_sort`]: sequential insertion as the course's table does it.
        CourseInsertion = course_insertion::DECLARATION => course_insertion_sort_with,
        /// [`binary_insertion_sort`]: insertion by bisection, at most ⌈log₂(k + 1)⌉
        /// comparisons.
        BinaryInsertion = binary_insertion::DECLARATION => binary_insertion_sort_with,
        /// [`course_binary_insertion_sort`]: insertion by bisection as the course's table
        /// does it.
        CourseBinaryInsertion = course_binary_insertion::DECLARATION
            => course_binary_insertion_sort_with,
        /// [`merge_sort`]: top-down merge sort.
        Merge = merge::DECLARATION => merge_sort_with,
        /// [`heap_sort`]: heap sort on a binary max-heap.
        Heap = heap::DECLARATION => heap_sort_with,
        /// [`quick_sort`]: median-of-three quicksort with a heap-sort guard (introsort).
        Quick = quick::DECLARATION => quick_sort_with,
    }
    fn run_with[T, F: FnMut(&T, &T) -> Ordering, C: Counter](v: &mut [T], cmp: F, counter: &mut C)
        -> ();
}

impl Algorithm {
    /// Whether the algorithm keeps equal elements in their input order.
    pub fn is_stable(self) -> bool {
        matches!(
            self,
            Algorithm::Bubble
                | Algorithm::Insertion
                | Algorithm::CourseInsertion
                | Algorithm::BinaryInsertion
                | Algorithm::CourseBinaryInsertion
                | Algorithm::Merge
        )
    }
}

/// Sorts `v` (by [`Ord`]) with `algorithm`.
///
/// # Complexity
/// That of the chosen algorithm ([`Algorithm::declaration`]).
///
/// ```
/// use compgeo::sort::{sort, Algorithm};
///
/// let mut v = [3, 1, 2];
/// sort(&mut v, Algorithm::Heap);
/// assert_eq!(v, [1, 2, 3]);
/// ```
pub fn sort<T: Ord>(v: &mut [T], algorithm: Algorithm) {
    sort_with(v, algorithm, T::cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with `algorithm`.
///
/// # Complexity
/// That of the chosen algorithm ([`Algorithm::declaration`]).
pub fn sort_by<T, F: FnMut(&T, &T) -> Ordering>(v: &mut [T], algorithm: Algorithm, cmp: F) {
    sort_with(v, algorithm, cmp, &mut NoCount);
}

/// Sorts `v` by `cmp` with `algorithm`, recording its operations in `counter`: the same as
/// calling the algorithm's `X_sort_with`.
///
/// # Complexity
/// That of the chosen algorithm ([`Algorithm::declaration`]).
pub fn sort_with<T, F, C>(v: &mut [T], algorithm: Algorithm, cmp: F, counter: &mut C)
where
    F: FnMut(&T, &T) -> Ordering,
    C: Counter,
{
    algorithm.run_with(v, cmp, counter)
}

/// The caller's comparator and counter together: the one place where sorting operations are
/// counted, so that algorithm bodies hold no counting code.
pub(crate) struct Counted<'c, F, C> {
    cmp: F,
    counter: &'c mut C,
}

impl<'c, F, C: Counter> Counted<'c, F, C> {
    pub(crate) fn new(cmp: F, counter: &'c mut C) -> Self {
        Counted { cmp, counter }
    }

    /// One counted comparison.
    #[inline(always)]
    pub(crate) fn cmp<T>(&mut self, a: &T, b: &T) -> Ordering
    where
        F: FnMut(&T, &T) -> Ordering,
    {
        self.counter.comparison();
        (self.cmp)(a, b)
    }

    /// One counted comparison: is `a` strictly before `b`?
    #[inline(always)]
    pub(crate) fn less<T>(&mut self, a: &T, b: &T) -> bool
    where
        F: FnMut(&T, &T) -> Ordering,
    {
        self.cmp(a, b) == Ordering::Less
    }

    /// One counted exchange of `v[i]` and `v[j]`.
    #[inline(always)]
    pub(crate) fn swap<T>(&mut self, v: &mut [T], i: usize, j: usize) {
        self.counter.swap();
        v.swap(i, j);
    }

    /// Records `count` single-element moves.
    #[inline(always)]
    pub(crate) fn moves(&mut self, count: usize) {
        for _ in 0..count {
            self.counter.element_move();
        }
    }
}

/// A point in an algorithm where [`trace`] prints a row. Positions are 0-based indices into
/// the slice being sorted.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Step<'a> {
    /// Bubble sort compared `v[j]` with `v[j + 1]` and exchanged them if out of order.
    Compared { j: usize },
    /// Bubble sort finished its pass number `pass` (from 1).
    PassDone { pass: usize },
    /// Selection sort found the minimum of `v[i..]` at `min` and exchanged it into `v[i]`
    /// (no exchange when `min == i`).
    Selected { i: usize, min: usize },
    /// Insertion by bisection is about to compare `v[k]` with `v[mid]` while searching the
    /// sorted run `v[lo..hi]`.
    Probe {
        k: usize,
        lo: usize,
        mid: usize,
        hi: usize,
    },
    /// Insertion sort (either kind) moved the element that was at `k` to `pos`; `v[..=k]` is
    /// sorted.
    Inserted { k: usize, pos: usize },
    /// Merge sort is about to merge two sorted runs, given as positions into the input.
    Merging {
        left: &'a [usize],
        right: &'a [usize],
    },
    /// Merge sort merged them into this run (positions into the input).
    Merged { run: &'a [usize] },
    /// Heap sort made `v` a max-heap.
    HeapBuilt,
    /// Heap sort moved the maximum of `v[..=end]` to `end` and restored the heap `v[..end]`.
    Extracted { end: usize },
    /// Quicksort partitioned `v[lo..hi]` around the pivot now at `pivot`.
    Partitioned { lo: usize, hi: usize, pivot: usize },
    /// Quicksort sorted the short range `v[lo..hi]` (at most three elements) directly.
    ShortSorted { lo: usize, hi: usize },
    /// Quicksort hit its depth limit and heap-sorted `v[lo..hi]`.
    HeapFallback { lo: usize, hi: usize },
}

/// Watches an algorithm's steps; [`trace`] implements it, [`NoObserver`] ignores everything.
pub(crate) trait Observer<T> {
    /// Called at each [`Step`] with the slice as it is at that moment.
    fn step(&mut self, v: &[T], step: Step<'_>);
}

/// The observer that watches nothing (what every public sorting function uses).
pub(crate) struct NoObserver;

impl<T> Observer<T> for NoObserver {
    #[inline(always)]
    fn step(&mut self, _v: &[T], _step: Step<'_>) {}
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    #[test]
    fn names_round_trip_and_are_distinct() {
        for a in Algorithm::ALL {
            assert_eq!(a.name().parse::<Algorithm>(), Ok(a));
            assert_eq!(a.to_string(), a.name());
        }
        let mut names = Algorithm::ALL.map(Algorithm::name).to_vec();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), Algorithm::ALL.len());
    }

    #[test]
    fn unknown_name_lists_valid_names() {
        let e = "bogo".parse::<Algorithm>().unwrap_err();
        let msg = e.to_string();
        assert!(msg.contains("`bogo`"), "{msg}");
        for a in Algorithm::ALL {
            assert!(msg.contains(a.name()), "{msg}");
        }
    }

    #[test]
    fn counted_counts_each_operation_once() {
        let mut counts = Counts::default();
        let mut ops = Counted::new(i32::cmp, &mut counts);
        let mut v = [2, 1];
        assert!(ops.less(&v[1], &v[0]));
        assert_eq!(ops.cmp(&v[0], &v[0]), Ordering::Equal);
        ops.swap(&mut v, 0, 1);
        ops.moves(3);
        assert_eq!(v, [1, 2]);
        assert_eq!((counts.comparisons, counts.swaps, counts.moves), (2, 1, 3));
    }
}
