//! Catalog entries of [`crate::sort`]: every comparison sort on random keys, plus the inputs
//! where a sort's behaviour differs (both sequential insertion sorts on sorted and reversed
//! keys, quicksort on sorted keys).
//!
//! The counted operation is comparisons, except where the quadratic cost is in the shifts:
//! both insertions by bisection make O(n log n) comparisons but one move per inversion. The
//! two sequential insertion sorts mirror each other. [`crate::sort::insertion_sort`] scans
//! from the back: reversed keys cost n(n − 1)/2 comparisons, sorted keys n − 1 (its linear best
//! case, claimed O(n)). The course's [`crate::sort::course_insertion_sort`] scans from the front:
//! n − 1 comparisons on reversed keys but n(n − 1)/2 moves, and n(n − 1)/2 comparisons on
//! sorted keys, so it has no linear best case and both its entries claim O(n²), each on the
//! operation that carries the cost.
//!
//! The radix sort for `f64` keys compares keys only in the insertion passes that finish its
//! parts; its entry counts moves (at most 24n), O(n).

use super::claimed_entries;
use crate::complexity::{Bound, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{sequence, sequence_f64, SequenceKind};
use crate::sort::{radix_sort_f64_with, sort_with, Algorithm};

/// One comparison sort on one kind of generated `i64` sequence.
struct SortKeys {
    algorithm: Algorithm,
    kind: SequenceKind,
}

/// The sorting entries: every claim the sorts declare, each on its input.
pub(super) fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    for algorithm in Algorithm::ALL {
        let claims = claimed_entries(algorithm.declaration(), |kind| SortKeys { algorithm, kind });
        for (_, entry) in claims {
            let bound = entry.info.bound;
            out.push(sizes(entry, bound));
        }
    }
    out.push(
        Entry::declared(crate::sort::RADIX, "random-f64", RadixKeys)
            .quick(256, 1 << 20)
            .full(256, 1 << 23),
    );
    out
}

/// Quadratic claims: 8 doublings in the quick profile (about a second for bubble sort).
/// Others start at 256, where lower-order terms no longer tilt the fit.
fn sizes(e: Entry, bound: Bound) -> Entry {
    if bound == Bound::Quadratic {
        e.quick(64, 1 << 13).full(64, 1 << 15)
    } else {
        e.quick(256, 1 << 20).full(256, 1 << 23)
    }
}

impl Workload for SortKeys {
    type Input = Vec<i64>;
    type Output = ();

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<i64>> {
        sequence(self.kind, n, seed)
    }

    fn run<C: Counter>(&self, keys: &mut Vec<i64>, counter: &mut C) -> Result<()> {
        sort_with(keys, self.algorithm, i64::cmp, counter);
        Ok(())
    }
}

/// The radix sort on random `f64` keys of mixed signs and magnitudes.
struct RadixKeys;

impl Workload for RadixKeys {
    type Input = Vec<f64>;
    type Output = ();

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<f64>> {
        sequence_f64(n, seed)
    }

    fn run<C: Counter>(&self, keys: &mut Vec<f64>, counter: &mut C) -> Result<()> {
        radix_sort_f64_with(keys, counter);
        Ok(())
    }
}
