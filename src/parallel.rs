//! The shared pieces of the `parallel` feature: a sort that splits its input among the
//! threads and merges the sorted parts in parallel, and the size below which the batch paths
//! stay sequential.
//!
//! The problem: sort n items whose order is a strict total order (no two distinct items
//! compare equal, or items that compare equal are identical), so that the sorted sequence is
//! unique and the parallel result equals the sequential one bit for bit.
//!
//! The idea: cut the input into two halves, sort them at the same time (each with the
//! sequential sort, or recursively while threads remain), then merge them. The merge is split
//! too: the middle item of the longer run is located in the other run by binary search, which
//! cuts both runs and the output into a left and a right part that can be merged
//! independently ([`merge`]), so every thread writes its own part of the output and no
//! `unsafe` is needed. Not in the course; it is the classical parallel merge sort (the
//! sequential sort of the leaves is the caller's: a radix sort here).
//!
//! # Complexity
//!
//! With n items, p threads and a leaf sort of time T(n): time T(n / p) + O(n / p + log² n)
//! with p threads, work p · T(n / p) + O(n log p); auxiliary space O(n) for the output.
//!
//! Invariants the tests check (`tests/suite/parallel.rs`): every parallel path returns what
//! its sequential path returns, on inputs on both sides of [`THRESHOLD`].

/// Inputs with fewer items than this stay sequential: below it the threads' start-up and the
/// extra merge pass cost more than half the sort.
pub(crate) const THRESHOLD: usize = 1 << 16;

/// Merges in parallel pieces of at least this many output items; shorter ones sequentially.
const MERGE_GRAIN: usize = 1 << 14;

/// How many times the input may still be halved: ⌈log₂ p⌉ for p threads.
pub(crate) fn depth() -> u32 {
    rayon::current_num_threads()
        .next_power_of_two()
        .trailing_zeros()
}

/// The items of `input`, sorted: `leaf` maps a slice of the input to its items sorted, the
/// halves of `input` go to `leaf` at the same time (recursively, `depth` times), and the
/// sorted halves are merged by [`merge`] under `less`. `less` must be a strict total order on
/// the items (or identify items that compare equal) and `leaf` must sort by it, so the result
/// is the unique sorted sequence whatever the split.
pub(crate) fn sorted<I, T, L, F>(input: &[I], depth: u32, leaf: &L, less: &F) -> Vec<T>
where
    I: Sync,
    T: Copy + Send + Sync + Default,
    L: Fn(&[I]) -> Vec<T> + Sync,
    F: Fn(&T, &T) -> bool + Sync,
{
    if depth == 0 || input.len() < THRESHOLD {
        return leaf(input);
    }
    let (left, right) = input.split_at(input.len() / 2);
    let (left, right) = rayon::join(
        || sorted(left, depth - 1, leaf, less),
        || sorted(right, depth - 1, leaf, less),
    );
    let mut out = vec![T::default(); left.len() + right.len()];
    merge(&left, &right, &mut out, less);
    out
}

/// Merges the sorted runs `a` and `b` into `out` (of length `a.len() + b.len()`), items of
/// `a` before equal items of `b`, splitting the work among the threads.
///
/// The split: with `a` the longer run, its middle item `a[m]` goes to `out[m + k]`, where
/// k is the number of items of `b` less than `a[m]`; everything before it in the output
/// comes from `a[..m]` and `b[..k]`, everything after from `a[m + 1..]` and `b[k..]`. When
/// `b` is the longer run, its middle item `b[m]` follows the k items of `a` not greater than
/// it.
pub(crate) fn merge<T, F>(a: &[T], b: &[T], out: &mut [T], less: &F)
where
    T: Copy + Send + Sync,
    F: Fn(&T, &T) -> bool + Sync,
{
    debug_assert_eq!(a.len() + b.len(), out.len());
    if out.len() < MERGE_GRAIN || a.is_empty() || b.is_empty() {
        merge_sequential(a, b, out, less);
        return;
    }
    let (a_left, pivot, a_right, b_left, b_right) = if a.len() >= b.len() {
        let m = a.len() / 2;
        let k = b.partition_point(|x| less(x, &a[m]));
        (&a[..m], a[m], &a[m + 1..], &b[..k], &b[k..])
    } else {
        let m = b.len() / 2;
        let k = a.partition_point(|x| !less(&b[m], x));
        (&a[..k], b[m], &a[k..], &b[..m], &b[m + 1..])
    };
    let (out_left, rest) = out.split_at_mut(a_left.len() + b_left.len());
    let (slot, out_right) = rest.split_at_mut(1);
    slot[0] = pivot;
    // The pivot from `b` sits after the equal items of `a` on its left and before those on
    // its right; the pivot from `a`, before the equal items of `b` on its right.
    rayon::join(
        || merge(a_left, b_left, out_left, less),
        || merge(a_right, b_right, out_right, less),
    );
}

/// The sequential merge of [`merge`].
fn merge_sequential<T: Copy, F: Fn(&T, &T) -> bool>(a: &[T], b: &[T], out: &mut [T], less: &F) {
    let (mut i, mut j) = (0, 0);
    for slot in out.iter_mut() {
        let take_b = j < b.len() && (i == a.len() || less(&b[j], &a[i]));
        if take_b {
            *slot = b[j];
            j += 1;
        } else {
            *slot = a[i];
            i += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::Rng;

    #[test]
    fn merge_equals_the_sorted_concatenation_with_ties() {
        let mut rng = Rng::new(3);
        for (na, nb) in [(0, 5), (7, 0), (40_000, 3), (3, 40_000), (50_000, 60_000)] {
            // Items (value, source): values repeat, so ties between the runs are common.
            let mut a: Vec<(u32, u32)> = (0..na)
                .map(|_| ((rng.next_u64() % 997) as u32, 0))
                .collect();
            let mut b: Vec<(u32, u32)> = (0..nb)
                .map(|_| ((rng.next_u64() % 997) as u32, 1))
                .collect();
            a.sort();
            b.sort();
            let mut out = vec![(0, 0); na + nb];
            merge(&a, &b, &mut out, &|x: &(u32, u32), y: &(u32, u32)| {
                x.0 < y.0
            });
            let mut expected = [a, b].concat();
            // A stable sort by value keeps a's items before b's equal ones.
            expected.sort_by_key(|x| x.0);
            assert_eq!(out, expected, "{na} + {nb}");
        }
    }

    #[test]
    fn sorted_equals_the_sequential_sort() {
        let mut rng = Rng::new(4);
        for n in [0, 1, THRESHOLD - 1, THRESHOLD, 3 * THRESHOLD + 7] {
            let v: Vec<u64> = (0..n).map(|_| rng.next_u64() % 100_000).collect();
            let mut expected = v.clone();
            expected.sort_unstable();
            let leaf = |part: &[u64]| {
                let mut part = part.to_vec();
                part.sort_unstable();
                part
            };
            assert_eq!(sorted(&v, 3, &leaf, &|a, b| a < b), expected, "n = {n}");
        }
    }
}
