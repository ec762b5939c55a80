//! Catalog entries of [`crate::sort`]: every comparison sort on random keys, plus the inputs
//! where a sort's behaviour differs (both sequential insertion sorts on sorted and reversed
//! keys, quicksort on sorted keys).
//!
//! The counted operation is comparisons, except where the quadratic cost is in the shifts:
//! both insertions by bisection make O(n log n) comparisons but one move per inversion. The
//! two sequential insertion sorts mirror each other. [`crate::sort::insertion_sort`] scans
//! from the back: reversed keys cost n(n − 1)/2 comparisons, sorted keys n − 1 (its linear best
//! case, claimed O(n)). The seed's [`crate::sort::course_insertion_sort`] scans from the front:
//! n − 1 comparisons on reversed keys but n(n − 1)/2 moves, and n(n − 1)/2 comparisons on
//! sorted keys, so it has no linear best case and both its entries claim O(n²), each on the
//! operation that carries the cost.
//!
//! The radix sort for `f64` keys compares keys only in the insertion passes that finish its
//! parts; its entry counts moves (at most 24n), O(n).

use crate::complexity::{Bound, Entry, Workload};
use crate::count::{Counter, Operation};
use crate::error::Result;
use crate::gen::{sequence, sequence_f64, SequenceKind};
use crate::sort::{radix_sort_f64_with, Algorithm};

/// One comparison sort on one kind of generated `i64` sequence.
struct SortKeys {
    algorithm: Algorithm,
    kind: SequenceKind,
}

/// The sorting entries.
pub(super) fn entries() -> Vec<Entry> {
    let quadratic = [
        Algorithm::Bubble,
        Algorithm::Selection,
        Algorithm::Insertion,
        Algorithm::CourseInsertion,
        Algorithm::BinaryInsertion,
        Algorithm::CourseBinaryInsertion,
    ];
    let mut out: Vec<Entry> = Algorithm::ALL
        .into_iter()
        .map(|algorithm| {
            let by_bisection = [Algorithm::BinaryInsertion, Algorithm::CourseBinaryInsertion];
            let operation = if by_bisection.contains(&algorithm) {
                Operation::Moves
            } else {
                Operation::Comparisons
            };
            if quadratic.contains(&algorithm) {
                quadratic_sizes(entry(
                    algorithm,
                    SequenceKind::Random,
                    Bound::Quadratic,
                    operation,
                ))
            } else {
                n_log_n_sizes(entry(
                    algorithm,
                    SequenceKind::Random,
                    Bound::NLogN,
                    operation,
                ))
            }
        })
        .collect();
    out.push(n_log_n_sizes(entry(
        Algorithm::Insertion,
        SequenceKind::Sorted,
        Bound::Linear,
        Operation::Comparisons,
    )));
    out.push(quadratic_sizes(entry(
        Algorithm::Insertion,
        SequenceKind::Reversed,
        Bound::Quadratic,
        Operation::Comparisons,
    )));
    out.push(quadratic_sizes(entry(
        Algorithm::CourseInsertion,
        SequenceKind::Sorted,
        Bound::Quadratic,
        Operation::Comparisons,
    )));
    out.push(quadratic_sizes(entry(
        Algorithm::CourseInsertion,
        SequenceKind::Reversed,
        Bound::Quadratic,
        Operation::Moves,
    )));
    out.push(n_log_n_sizes(entry(
        Algorithm::Quick,
        SequenceKind::Sorted,
        Bound::NLogN,
        Operation::Comparisons,
    )));
    out.push(
        Entry::new("sort/radix-f64", Bound::Linear, Operation::Moves, RadixKeys)
            .input("random-f64")
            .quick(256, 1 << 20)
            .full(256, 1 << 23),
    );
    out
}

/// Quadratic sorts: 8 doublings in the quick profile (about a second for bubble sort).
fn quadratic_sizes(e: Entry) -> Entry {
    e.quick(64, 1 << 13).full(64, 1 << 15)
}

/// O(n log n) sorts start at 256, where lower-order terms no longer tilt the fit.
fn n_log_n_sizes(e: Entry) -> Entry {
    e.quick(256, 1 << 20).full(256, 1 << 23)
}

fn entry(algorithm: Algorithm, kind: SequenceKind, bound: Bound, operation: Operation) -> Entry {
    let id = format!("sort/{}", algorithm.name());
    Entry::new(&id, bound, operation, SortKeys { algorithm, kind }).input(kind.name())
}

impl Workload for SortKeys {
    type Input = Vec<i64>;
    type Output = ();

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<i64>> {
        Ok(sequence(self.kind, n, seed))
    }

    fn run<C: Counter>(&self, keys: &mut Vec<i64>, counter: &mut C) -> Result<()> {
        self.algorithm.sort_with(keys, i64::cmp, counter);
        Ok(())
    }
}

/// The radix sort on random `f64` keys of mixed signs and magnitudes.
struct RadixKeys;

impl Workload for RadixKeys {
    type Input = Vec<f64>;
    type Output = ();

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<f64>> {
        Ok(sequence_f64(n, seed))
    }

    fn run<C: Counter>(&self, keys: &mut Vec<f64>, counter: &mut C) -> Result<()> {
        radix_sort_f64_with(keys, counter);
        Ok(())
    }
}
