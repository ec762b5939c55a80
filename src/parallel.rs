//! The shared pieces of the `parallel` feature: the test that sends a batch to the threads,
//! and the parallel distribution of items into buckets that the parallel lexicographic sort
//! starts with (the `f64` radix sort partitions in place instead, `src/sort/radix.rs`).
//!
//! The problem: distribute n items into b buckets by a digit of their key, as the stable
//! counting pass of a radix sort does, with every thread doing an equal share and no `unsafe`.
//!
//! The idea ([`scatter`]): cut the input into chunks, a few per thread; each chunk counts its
//! items per bucket, in parallel. The output is then cut, by those counts, into one sub-slice
//! per bucket and chunk, bucket-major and chunk-minor (bucket 0 of chunk 0, bucket 0 of chunk
//! 1, ..., bucket 1 of chunk 0, ...), with `split_at_mut`; each chunk then writes its items
//! into its own sub-slices, in parallel. The sub-slices are disjoint, so the borrow checker
//! accepts the writes, and each bucket receives its items in input order: the distribution is
//! stable. A sort that partitions by its top digit this way and then sorts the buckets
//! independently (each on one thread) needs no merge pass. Not in the course; it is the
//! classical parallel counting-sort pass (Zagha and Blelloch's parallel radix sort).
//!
//! # Complexity
//!
//! With n items, b buckets, p threads and c = 4p chunks: time O(n / p + b·c) with p threads,
//! work O(n + b·c); auxiliary space O(b·c) for the counts and the sub-slices.
//!
//! Invariants the tests check (`tests/suite/parallel.rs` and the tests below): every parallel
//! path returns what its sequential path returns, on inputs on both sides of [`THRESHOLD`];
//! [`scatter`] equals a stable sort by bucket.

use rayon::prelude::*;

/// Inputs with fewer items than this stay sequential: below it the threads' start-up costs
/// more than half the work.
pub(crate) const THRESHOLD: usize = 1 << 16;

/// Chunks of [`scatter`] per thread: more than one, so a thread that is slowed down (by
/// another process, or by a chunk whose buckets miss the cache) leaves the rest of its share
/// to be stolen.
const CHUNKS_PER_THREAD: usize = 4;

/// Whether a batch of `len` items takes a parallel path: from [`THRESHOLD`] items, and only
/// with more than one thread in the pool (a 1-thread pool takes the sequential path itself).
pub(crate) fn enabled(len: usize) -> bool {
    len >= THRESHOLD && rayon::current_num_threads() > 1
}

/// Distributes the items of `src` into `dst` (as long as `src`) by bucket, stably: `place`
/// maps an item to its bucket (below `buckets`) and the value to write. Returns each bucket's
/// end in `dst`. `place` is called twice per item (once to count, once to write), so it must
/// be a function of the item.
pub(crate) fn scatter<S, T, P>(src: &[S], dst: &mut [T], buckets: usize, place: P) -> Vec<usize>
where
    S: Sync,
    T: Send,
    P: Fn(&S) -> (usize, T) + Sync,
{
    assert_eq!(
        src.len(),
        dst.len(),
        "scatter needs an output as long as its input"
    );
    let chunks = rayon::current_num_threads() * CHUNKS_PER_THREAD;
    let chunk_len = src.len().div_ceil(chunks).max(1);
    let counts: Vec<Vec<usize>> = src
        .par_chunks(chunk_len)
        .map(|chunk| {
            let mut count = vec![0usize; buckets];
            for x in chunk {
                count[place(x).0] += 1;
            }
            count
        })
        .collect();
    // The sub-slices, bucket-major and chunk-minor, handed to their chunks.
    let mut slots: Vec<Vec<&mut [T]>> =
        counts.iter().map(|_| Vec::with_capacity(buckets)).collect();
    let mut ends = Vec::with_capacity(buckets);
    let mut rest = dst;
    let mut end = 0;
    for d in 0..buckets {
        for (count, slot) in counts.iter().zip(slots.iter_mut()) {
            let (head, tail) = std::mem::take(&mut rest).split_at_mut(count[d]);
            slot.push(head);
            rest = tail;
            end += count[d];
        }
        ends.push(end);
    }
    src.par_chunks(chunk_len)
        .zip(slots.into_par_iter())
        .for_each(|(chunk, mut slot)| {
            let mut next = vec![0usize; buckets];
            for x in chunk {
                let (d, value) = place(x);
                slot[d][next[d]] = value;
                next[d] += 1;
            }
        });
    ends
}

/// The bucket ranges of `ends` (as [`scatter`] returns them), cut out of `a` and `b` side by
/// side: one pair of equal sub-slices per bucket, for sorting the buckets in parallel.
pub(crate) fn split_buckets<'a, S, T>(
    mut a: &'a mut [S],
    mut b: &'a mut [T],
    ends: &[usize],
) -> Vec<(&'a mut [S], &'a mut [T])> {
    let mut start = 0;
    let mut parts = Vec::with_capacity(ends.len());
    for &end in ends {
        let (a_head, a_tail) = std::mem::take(&mut a).split_at_mut(end - start);
        let (b_head, b_tail) = std::mem::take(&mut b).split_at_mut(end - start);
        parts.push((a_head, b_head));
        (a, b) = (a_tail, b_tail);
        start = end;
    }
    parts
}

/// The vectors of `parts` one after another, copied into place in parallel (each part into
/// its own sub-slice of the output, cut with `split_at_mut`).
pub(crate) fn concatenate<T: Copy + Default + Send + Sync>(parts: Vec<Vec<T>>) -> Vec<T> {
    let total = parts.iter().map(Vec::len).sum();
    let mut out = vec![T::default(); total];
    let mut slots = Vec::with_capacity(parts.len());
    let mut rest = out.as_mut_slice();
    for part in &parts {
        let (slot, tail) = std::mem::take(&mut rest).split_at_mut(part.len());
        slots.push(slot);
        rest = tail;
    }
    slots
        .into_par_iter()
        .zip(parts.par_iter())
        .for_each(|(slot, part)| slot.copy_from_slice(part));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::Rng;

    #[test]
    fn scatter_equals_a_stable_sort_by_bucket() {
        let mut rng = Rng::new(3);
        for (n, buckets) in [(0, 4), (1, 1), (7, 256), (100_000, 256), (70_000, 3)] {
            // Items (value, position): the positions show the order within a bucket.
            let v: Vec<(u64, usize)> = (0..n).map(|i| (rng.next_u64(), i)).collect();
            let bucket = |x: &(u64, usize)| (x.0 % buckets as u64) as usize;
            let mut out = vec![(0, 0); n];
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(3)
                .build()
                .unwrap();
            let ends = pool.install(|| scatter(&v, &mut out, buckets, |x| (bucket(x), *x)));
            let mut expected = v.clone();
            expected.sort_by_key(bucket);
            assert_eq!(out, expected, "{n} items, {buckets} buckets");
            assert_eq!(ends.len(), buckets);
            for (d, &end) in ends.iter().enumerate() {
                assert_eq!(end, expected.partition_point(|x| bucket(x) <= d));
            }
        }
    }

    #[test]
    fn split_buckets_cuts_both_slices_at_the_ends() {
        let mut a = [0u8; 10];
        let mut b = [0u16; 10];
        let parts = split_buckets(&mut a, &mut b, &[3, 3, 9, 10]);
        let lens: Vec<(usize, usize)> = parts.iter().map(|(x, y)| (x.len(), y.len())).collect();
        assert_eq!(lens, [(3, 3), (0, 0), (6, 6), (1, 1)]);
    }
}
