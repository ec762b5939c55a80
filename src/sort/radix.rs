//! Radix sort for `f64` keys in the IEEE 754 total order, without comparing floats.
//!
//! A float's bits, read as an unsigned integer after flipping the sign bit of non-negative
//! values and every bit of negative ones, order exactly as [`f64::total_cmp`] orders the
//! floats: −NaN < −∞ < … < −0.0 < +0.0 < … < +∞ < +NaN. The sort turns the floats into those
//! 64-bit keys in place, sorts the keys by their bits, and turns them back.
//!
//! Large inputs are first partitioned in place, most significant bits first (an "American
//! flag" pass on the top eight bits in which the keys differ), until every part holds at most
//! 2^16 keys and fits, with a scratch buffer of its size, in a 1 MiB L2 cache. Each part of m
//! keys is then sorted on its top ⌊log₂ m⌋ + 9 varying bits by stable counting passes of one
//! byte each, least significant first; on random input a key shares all those bits with
//! another with probability below 1/256, so one insertion pass finishes the part. If the
//! insertion pass meets too many inversions (keys that agree on their top bits and differ
//! below, as an adversary can arrange), the part is sorted on all its varying bits by counting
//! passes instead, so the sort stays linear. Not in the course; it is compgeo's fast path for
//! sorting coordinates, measured against `sort_unstable_by(f64::total_cmp)` in
//! `benches/sort.rs` (groups `radix-f64-mixed` and `radix-f64-unit`).
//!
//! Why this shape: the eight-pass LSD radix sort it replaces made eight passes over the whole
//! array plus a fresh n-float buffer, whose first-touch page faults alone cost about 3 ms per
//! million keys on the benchmark machine. This version allocates at most 2^16 floats of scratch
//! and does all but one or two passes on cache-resident parts; its partition sweeps over the
//! unplaced slots instead of following one cycle at a time, so its cache misses overlap.
//!
//! Invariants the tests check: the output equals `sort_unstable_by(f64::total_cmp)` bit for
//! bit (signed zeros, subnormals, infinities, NaNs of both signs and any payload), on random
//! and on adversarial inputs that force the fallback; the counts stay within the linear bounds
//! stated on [`radix_sort_f64_with`].

use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::util::{from_order_key, order_key};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(crate) const DECLARATION: Declaration = Declaration {
    problem: "sort",
    name: "radix-f64",
    function: "sort::radix_sort_f64",
    file: "src/sort/radix.rs",
    summary: "most-significant-digit radix sort of the keys' order bits",
    time: "O(n)",
    space: "O(n)",
    operation: Some(Operation::Moves),
    counts: "at most 24n moves and 7.5n key comparisons",
    source: "[RD, §2.1]",
    claims: &[on("random-f64", Bound::Linear, Operation::Moves)],
};

/// Parts longer than this are partitioned in place first. 2^16 keys and their scratch take
/// 512 KiB each: together they fit a 1 MiB L2 cache.
const PART_MAX: usize = 1 << 16;
/// Parts this short are sorted by insertion alone.
const TINY: usize = 16;
/// A part of m keys is sorted by counting passes on its top `bit_length(m) + EXTRA_BITS`
/// varying bits before the insertion pass: keys tie on all of them with probability about
/// 2^-EXTRA_BITS per element on random input.
const EXTRA_BITS: u32 = 8;
/// The most sweeps of a partition before its remaining keys follow their cycles.
const SWEEPS: usize = 8;
/// Bits per digit of a counting pass, and its number of buckets.
const DIGIT_BITS: u32 = 8;
const RADIX: usize = 1 << DIGIT_BITS;
/// The most digits a part's counting passes use: `bit_length(PART_MAX) + EXTRA_BITS` bits.
const MAX_TOP_DIGITS: usize = 4;

/// Sorts `v` in the IEEE 754 total order ([`f64::total_cmp`]) with a radix sort.
///
/// The result is the same, bit for bit, as `v.sort_unstable_by(f64::total_cmp)` (in that
/// order distinct bit patterns never compare equal, so the sorted sequence is unique).
/// See [`radix_sort_f64_with`] for the algorithm and its complexity.
///
/// ```
/// let mut v = [2.0, -0.0, f64::NAN, 0.0, -f64::INFINITY, 5e-324];
/// compgeo::sort::radix_sort_f64(&mut v);
/// assert_eq!(v[..5], [f64::NEG_INFINITY, -0.0, 0.0, 5e-324, 2.0]);
/// assert!(v[1].is_sign_negative() && v[2].is_sign_positive() && v[5].is_nan());
/// ```
pub fn radix_sort_f64(v: &mut [f64]) {
    radix_sort_f64_with(v, &mut NoCount);
}

/// Sorts `v` like [`radix_sort_f64`], recording its element moves and key comparisons in
/// `counter`.
///
/// Idea: map each float, in place, to the 64-bit key that orders as [`f64::total_cmp`] (flip
/// the sign bit of non-negative floats, every bit of negative ones). While a part of the array
/// is longer than 2^16 keys, partition it in place into 256 buckets by the eight bits below the
/// highest bit on which its keys differ (sweeps over the unplaced slots swap keys into their
/// buckets, then the last few follow their cycles). A part of m ≤ 2^16 keys is sorted into a scratch buffer and back by stable counting
/// passes, one per byte of its top ⌊log₂ m⌋ + 9 varying bits, least significant byte
/// first (a byte on which all keys agree is skipped); then an insertion pass orders the keys
/// that tie on those bits. If that pass has to shift more than m keys, the part is sorted by
/// counting passes on all its varying bits instead. Keys become floats again part by part.
///
/// Not in the course; it sorts what [`super::merge_sort_by`] or [`super::quick_sort_by`] with
/// `f64::total_cmp` sort, in linear time.
///
/// # Errors
///
/// None: every `f64`, NaN included, has its place in the total order.
///
/// # Complexity
///
/// With n = `v.len()`, w = 64 key bits and b = 256 buckets: time O(n·w/8 + b·p) = O(n) for
/// p ≤ n parts: at most w/8 partition levels over the whole array, and per part at most
/// w/8 counting passes, one insertion pass of at most 2m shifts and, if it gives up, w/8 more
/// counting passes. Auxiliary space: min(n, 2^16) floats of scratch plus O(w/8 · b) counters.
/// Random input of up to 2^16 keys takes no partition level and three or four counting
/// passes; 10^6 random keys take one level and three passes per part (5 moves per key).
///
/// # Counts
///
/// - moves: between n and 2n per partition level (a key placed by a sweep costs two writes,
///   one placed by following a cycle one), m per counting pass over a part of m keys, m when a
///   part's result is copied back from the scratch buffer, and one per key shifted by an
///   insertion pass (putting the key into the gap is not counted, as in
///   [`super::insertion_sort_with`]). After L ≤ 8 partition levels (at most 2Ln moves) a
///   part's keys differ in at most 64 − 8L bits, so it takes at most 4 counting passes, fewer
///   than 2m shifts before the insertion pass gives up, 8 − L fallback passes and 2 copies: at
///   most 2L + 16 − L ≤ 24 moves per key in all (a part of at most 16 keys, sorted by insertion
///   alone, shifts at most 7.5 keys per key), and 0 when all elements share their bit pattern;
/// - comparisons: the insertion passes' comparisons of two keys (as unsigned integers): at most
///   one per shift plus one per key, and at most m(m − 1)/2 in a part of m ≤ 16 keys, so at
///   most 7.5n; 0 when the counting passes alone sort every part.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::radix_sort_f64_with;
///
/// // Three keys: a tiny part, sorted by insertion alone.
/// let mut v = [1.0 + 3.0 * f64::EPSILON, 1.0, 1.0 + f64::EPSILON];
/// let mut counts = Counts::default();
/// radix_sort_f64_with(&mut v, &mut counts);
/// assert_eq!(v, [1.0, 1.0 + f64::EPSILON, 1.0 + 3.0 * f64::EPSILON]);
/// // 1.0 passes one key (1 comparison, 1 shift); 1 + ε passes one and stops at 1.0 (2, 1).
/// assert_eq!((counts.comparisons, counts.moves), (3, 2));
/// ```
pub fn radix_sort_f64_with<C: Counter>(v: &mut [f64], counter: &mut C) {
    #[cfg(feature = "parallel")]
    if C::DISCARDS && v.len() >= PAR_MIN && crate::parallel::enabled(v.len()) {
        par_sort(v);
        return;
    }
    sequential_sort(v, counter);
}

/// [`radix_sort_f64_with`] on all the threads (feature `parallel`, counting nothing), in
/// place like the sequential sort: the floats turned into keys in parallel, the keys
/// partitioned in place by the eight bits below the highest bit in which they differ, with
/// the permutation shared by the threads ([`par_partition`]), then the 256 parts sorted
/// independently, in parallel, each by the sequential sort (or by this step again if it
/// holds more than an eighth of the keys). No merge pass and no n-float buffer: the parts
/// are in order, and the only scratch is one part's worth per thread. In the total order only
/// equal bit patterns compare equal, so the result is the sequential one bit for bit.
#[cfg(feature = "parallel")]
fn par_sort(v: &mut [f64]) {
    use rayon::prelude::*;
    let first = order_key(v[0]);
    let diff = v
        .par_chunks_mut(PAR_CHUNK)
        .map(|chunk| to_keys_against(chunk, first))
        .reduce(|| 0, |a, b| a | b);
    if diff == 0 {
        v.par_chunks_mut(PAR_CHUNK).for_each(to_floats);
        return;
    }
    let grain = (v.len() / 8).max(crate::parallel::THRESHOLD);
    par_sort_keys(v, diff, grain);
}

/// Inputs shorter than this stay sequential even with the `parallel` feature. On the
/// benchmark machine's two threads the parallel sort gained nothing up to 10⁶ keys (0.85 to
/// 1.03 times the sequential time at 5·10⁵ and 10⁶, when the keys and the parts fit the
/// shared cache) and 1.4 to 1.7 times from 2·10⁶ keys.
#[cfg(feature = "parallel")]
pub(crate) const PAR_MIN: usize = 1 << 21;

/// Chunks of the parallel passes over the whole input.
#[cfg(feature = "parallel")]
const PAR_CHUNK: usize = 1 << 16;

/// Sorts the keys of `v`, which differ exactly in the bits of `diff` (not 0), and turns them
/// into floats: partitioned by [`par_partition`], then each part sorted in parallel, by this
/// function again if it holds more than `grain` keys, else by the sequential sort.
#[cfg(feature = "parallel")]
fn par_sort_keys(v: &mut [f64], diff: u64, grain: usize) {
    use rayon::prelude::*;
    let shift = bit_length(diff).saturating_sub(DIGIT_BITS);
    let ends = par_partition(v, shift, SWEEPS);
    let mut parts = Vec::with_capacity(RADIX);
    let mut rest = v;
    let mut start = 0;
    for end in ends {
        let (part, tail) = std::mem::take(&mut rest).split_at_mut(end - start);
        parts.push(part);
        rest = tail;
        start = end;
    }
    parts.into_par_iter().for_each_init(
        // One scratch per split of the work, not per part.
        || vec![0.0f64; PART_MAX],
        |scratch, part| match varying_bits(part) {
            // The part's keys agree on every bit from `shift` up, so it sorts on fewer bits.
            0 => to_floats(part),
            d if part.len() > grain => par_sort_keys(part, d, grain),
            d => sort_keys(part, d, scratch, &mut NoCount),
        },
    );
}

/// [`partition`] shared by the threads: the keys of `v` partitioned in place by their digit
/// at `shift`, with at most `sweeps` sweeps per thread; returns each bucket's end.
///
/// The digits are counted in parallel. Each bucket's final range is cut into one stripe per
/// thread, in proportion, and each thread permutes the keys of its own stripes among its own
/// stripes ([`permute_stripes`]): a key whose bucket has no free slot left in the thread's
/// stripe stays behind, at the end of the stripe it was in. On input in random order each
/// thread's stripes hold about the share of every bucket its stripes have room for, so few
/// keys stay behind; they are gathered, and written back, bucket by bucket, into the slots
/// left behind (as many in each bucket's range as that bucket has keys among them).
#[cfg(feature = "parallel")]
fn par_partition(v: &mut [f64], shift: u32, sweeps: usize) -> [usize; RADIX] {
    use rayon::prelude::*;
    let counts = v
        .par_chunks(PAR_CHUNK)
        .map(|chunk| {
            let mut counts = [0usize; RADIX];
            for x in chunk {
                counts[digit(x.to_bits(), shift)] += 1;
            }
            counts
        })
        .reduce(
            || [0usize; RADIX],
            |mut a, b| {
                a.iter_mut().zip(b).for_each(|(a, b)| *a += b);
                a
            },
        );
    let threads = rayon::current_num_threads();
    let mut stripes: Vec<Vec<&mut [f64]>> =
        (0..threads).map(|_| Vec::with_capacity(RADIX)).collect();
    let mut ends = [0usize; RADIX];
    let mut rest = v;
    let mut end = 0;
    for (d, &count) in counts.iter().enumerate() {
        for (t, own) in stripes.iter_mut().enumerate() {
            let len = count * (t + 1) / threads - count * t / threads;
            let (stripe, tail) = std::mem::take(&mut rest).split_at_mut(len);
            own.push(stripe);
            rest = tail;
        }
        end += count;
        ends[d] = end;
    }
    let placed: Vec<[usize; RADIX]> = stripes
        .par_iter_mut()
        .map(|own| permute_stripes(own, shift, sweeps))
        .collect();
    // The keys left behind, bucket by bucket (by the range they are in), and back into
    // the slots they leave, now by their own digit.
    let mut behind = Vec::new();
    for d in 0..RADIX {
        for (own, placed) in stripes.iter().zip(&placed) {
            behind.extend_from_slice(&own[d][placed[d]..]);
        }
    }
    let mut next: Vec<[usize; RADIX]> = placed.clone();
    let mut stripe_of = [0usize; RADIX];
    for x in behind {
        let d = digit(x.to_bits(), shift);
        loop {
            let t = stripe_of[d];
            let slot = &mut next[t][d];
            if let Some(free) = stripes[t][d].get_mut(*slot) {
                *free = x;
                *slot += 1;
                break;
            }
            stripe_of[d] += 1;
        }
    }
    ends
}

/// One thread's share of [`par_partition`]: permutes the keys of `stripes` (its stripe of
/// every bucket, in bucket order) so that each stripe starts with keys of its own bucket;
/// returns how many each stripe has. The rest of each stripe holds keys whose bucket's
/// stripe here was already full.
///
/// As in [`partition`]: sweeps over the unplaced slots first, so that cache misses overlap,
/// a key whose stripe is full staying where it is; then cycles from each stripe's first
/// unplaced slot, a key whose stripe is full going to the end of the unplaced slots of the
/// stripe the cycle started in (the cycle then carries on with the key it finds there).
/// Each step places a key for good or sets one aside, so the work is linear.
#[cfg(feature = "parallel")]
fn permute_stripes(stripes: &mut [&mut [f64]], shift: u32, sweeps: usize) -> [usize; RADIX] {
    let mut head = [0usize; RADIX];
    let mut tail = [0usize; RADIX];
    for (t, stripe) in tail.iter_mut().zip(stripes.iter()) {
        *t = stripe.len();
    }
    for _ in 0..sweeps {
        let mut unplaced = false;
        for d in 0..RADIX {
            for i in head[d]..tail[d] {
                let x = stripes[d][i];
                let k = digit(x.to_bits(), shift);
                if head[k] < tail[k] {
                    // Slot head[k] is unplaced (or is i itself): x goes there, its key here.
                    let parked = std::mem::replace(&mut stripes[k][head[k]], x);
                    stripes[d][i] = parked;
                    head[k] += 1;
                }
            }
            unplaced |= head[d] < tail[d];
        }
        if !unplaced {
            return head;
        }
    }
    for d in 0..RADIX {
        while head[d] < tail[d] {
            // A hole at head[d]: carry its key until a key of bucket d fills the hole.
            let mut x = stripes[d][head[d]];
            let mut k = digit(x.to_bits(), shift);
            loop {
                if k == d {
                    stripes[d][head[d]] = x;
                    head[d] += 1;
                    break;
                }
                if head[k] < tail[k] {
                    std::mem::swap(&mut x, &mut stripes[k][head[k]]);
                    head[k] += 1;
                } else {
                    // No room for x here: it stays behind at the end of d's unplaced slots.
                    tail[d] -= 1;
                    if tail[d] == head[d] {
                        stripes[d][head[d]] = x;
                        break;
                    }
                    std::mem::swap(&mut x, &mut stripes[d][tail[d]]);
                }
                k = digit(x.to_bits(), shift);
            }
        }
    }
    head
}

/// The sequential body of [`radix_sort_f64_with`].
fn sequential_sort<C: Counter>(v: &mut [f64], counter: &mut C) {
    if v.len() < 2 {
        return;
    }
    let diff = to_keys(v);
    if diff == 0 {
        to_floats(v);
        return;
    }
    let mut scratch = vec![0.0f64; v.len().min(PART_MAX)];
    sort_keys(v, diff, &mut scratch, counter);
}

/// Sorts the keys of `v`, which differ exactly in the bits set in `diff` (not 0), and turns
/// them into floats.
fn sort_keys<C: Counter>(v: &mut [f64], diff: u64, scratch: &mut [f64], counter: &mut C) {
    let m = v.len();
    if m <= PART_MAX {
        sort_part(v, &mut scratch[..m], diff, counter);
        return;
    }
    let shift = bit_length(diff).saturating_sub(DIGIT_BITS);
    let ends = partition(v, shift, SWEEPS, counter);
    let mut start = 0;
    for end in ends {
        let part = &mut v[start..end];
        // The part's keys agree on every bit from `shift` up, so it recurses on fewer bits.
        match varying_bits(part) {
            0 => to_floats(part),
            d => sort_keys(part, d, scratch, counter),
        }
        start = end;
    }
}

/// Partitions the keys of `v` in place by their digit at `shift`; returns each bucket's end.
///
/// Sweeps first: each sweep walks every bucket's unplaced slots once, putting the key found
/// into its bucket's next free slot and parking the key from there in its place. Unlike
/// following one cycle (where each load waits for the previous one), a sweep's loads are
/// independent, so many cache misses overlap; on 10^6 random keys that is 2 ms instead of 7.
/// Each step places one key for good, and after `sweeps` sweeps the few keys left follow
/// their cycles.
fn partition<C: Counter>(
    v: &mut [f64],
    shift: u32,
    sweeps: usize,
    counter: &mut C,
) -> [usize; RADIX] {
    let mut counts = [0usize; RADIX];
    for x in v.iter() {
        counts[digit(x.to_bits(), shift)] += 1;
    }
    let mut heads = [0usize; RADIX];
    let mut ends = [0usize; RADIX];
    let mut sum = 0;
    for d in 0..RADIX {
        heads[d] = sum;
        sum += counts[d];
        ends[d] = sum;
    }
    let mut swept = 0;
    for _ in 0..sweeps {
        let mut unplaced = false;
        for d in 0..RADIX {
            let (start, end) = (heads[d], ends[d]);
            for i in start..end {
                let x = v[i];
                let slot = &mut heads[digit(x.to_bits(), shift)];
                // slot lies in x's bucket at or past its placed keys, or is i itself.
                v[i] = v[*slot];
                v[*slot] = x;
                *slot += 1;
            }
            swept += end - start;
            unplaced |= heads[d] < end;
        }
        if !unplaced {
            break;
        }
    }
    for d in 0..RADIX {
        while heads[d] < ends[d] {
            // Follow the cycle through heads[d]: each key displaced goes to its own bucket.
            let mut x = v[heads[d]];
            let mut home = digit(x.to_bits(), shift);
            while home != d {
                let slot = heads[home];
                heads[home] += 1;
                std::mem::swap(&mut x, &mut v[slot]);
                home = digit(x.to_bits(), shift);
            }
            v[heads[d]] = x;
            heads[d] += 1;
        }
    }
    // A swept key costs two writes (its slot and the parked key), any other key one.
    moves(counter, v.len() + swept);
    ends
}

/// Sorts the keys of `v` (at most [`PART_MAX`]), which differ exactly in the bits of `diff`
/// (not 0), with `tmp` (as long as `v`) as scratch; leaves floats in `v`.
fn sort_part<C: Counter>(v: &mut [f64], tmp: &mut [f64], diff: u64, counter: &mut C) {
    let m = v.len();
    if m <= TINY {
        insertion(v, usize::MAX, counter);
        to_floats(v);
        return;
    }
    let hi = bit_length(diff);
    let wanted = (bit_length(m as u64) + EXTRA_BITS).min(hi);
    let digits = wanted.div_ceil(DIGIT_BITS) as usize;
    let lo = hi.saturating_sub(DIGIT_BITS * digits as u32);
    let in_tmp = counting_passes::<MAX_TOP_DIGITS, C>(v, tmp, lo, digits, counter);
    let (keys, other) = if in_tmp { (tmp, v) } else { (v, tmp) };
    // Sorted on bits lo.. now; with lo = 0 that is all of them.
    if lo > 0 && !insertion(keys, m, counter) {
        counting_sort(keys, other, hi, counter);
    }
    if in_tmp {
        for (out, &k) in other.iter_mut().zip(keys.iter()) {
            *out = from_order_key(k.to_bits());
        }
        moves(counter, m);
    } else {
        to_floats(keys);
    }
}

/// Sorts the keys of `v` on bits `0..hi` (all the bits where they differ) by counting passes
/// through `tmp`; the keys end in `v`.
fn counting_sort<C: Counter>(v: &mut [f64], tmp: &mut [f64], hi: u32, counter: &mut C) {
    const ALL_DIGITS: usize = (u64::BITS / DIGIT_BITS) as usize;
    let digits = hi.div_ceil(DIGIT_BITS) as usize;
    if counting_passes::<ALL_DIGITS, C>(v, tmp, 0, digits, counter) {
        v.copy_from_slice(tmp);
        moves(counter, v.len());
    }
}

/// Sorts the keys of `v` on their `digits` ≤ `D` bytes from bit `lo` up by stable counting
/// passes between `v` and `tmp`, least significant first, skipping bytes on which every key
/// agrees; returns whether the keys ended in `tmp`.
fn counting_passes<const D: usize, C: Counter>(
    v: &mut [f64],
    tmp: &mut [f64],
    lo: u32,
    digits: usize,
    counter: &mut C,
) -> bool {
    let m = v.len();
    let mut histograms = [[0u32; RADIX]; D];
    for x in v.iter() {
        let k = x.to_bits() >> lo;
        for (p, histogram) in histograms[..digits].iter_mut().enumerate() {
            histogram[digit(k, DIGIT_BITS * p as u32)] += 1;
        }
    }
    let mut in_tmp = false;
    for (p, histogram) in histograms[..digits].iter().enumerate() {
        if histogram.contains(&(m as u32)) {
            continue;
        }
        let shift = lo + DIGIT_BITS * p as u32;
        if in_tmp {
            counting_pass(tmp, v, histogram, shift);
        } else {
            counting_pass(v, tmp, histogram, shift);
        }
        moves(counter, m);
        in_tmp = !in_tmp;
    }
    in_tmp
}

/// Distributes the keys of `src` stably into `dst` by their digit at `shift`.
fn counting_pass(src: &[f64], dst: &mut [f64], histogram: &[u32; RADIX], shift: u32) {
    let mut next = [0usize; RADIX];
    let mut sum = 0;
    for (slot, &count) in next.iter_mut().zip(histogram) {
        *slot = sum;
        sum += count as usize;
    }
    for &x in src {
        let d = digit(x.to_bits(), shift);
        dst[next[d]] = x;
        next[d] += 1;
    }
}

/// Insertion sort of the keys of `v`; gives up (returning false, `v` some permutation of its
/// keys) once it has shifted more than `budget` keys.
fn insertion<C: Counter>(v: &mut [f64], budget: usize, counter: &mut C) -> bool {
    let mut shifts = 0;
    for i in 1..v.len() {
        let x = v[i];
        let k = x.to_bits();
        let mut j = i;
        while j > 0 {
            counter.comparison();
            if v[j - 1].to_bits() <= k {
                break;
            }
            v[j] = v[j - 1];
            counter.element_move();
            j -= 1;
        }
        v[j] = x;
        shifts += i - j;
        if shifts > budget {
            return false;
        }
    }
    true
}

/// Turns the floats of `v` into keys in place; returns the bits in which the keys differ.
fn to_keys(v: &mut [f64]) -> u64 {
    to_keys_against(v, order_key(v[0]))
}

/// Turns the floats of `v` into keys in place; returns the bits in which they differ from
/// the key `first`.
fn to_keys_against(v: &mut [f64], first: u64) -> u64 {
    let mut diff = 0;
    for x in v.iter_mut() {
        let k = order_key(*x);
        diff |= k ^ first;
        *x = f64::from_bits(k);
    }
    diff
}

fn to_floats(v: &mut [f64]) {
    for x in v.iter_mut() {
        *x = from_order_key(x.to_bits());
    }
}

/// The bits in which the keys of `v` differ (none for an empty or one-key `v`).
fn varying_bits(v: &[f64]) -> u64 {
    let first = v.first().map_or(0, |x| x.to_bits());
    v.iter().fold(0, |diff, x| diff | (x.to_bits() ^ first))
}

/// The number of bits up to the highest set one: bits `0..bit_length(x)` hold all of `x`.
fn bit_length(x: u64) -> u32 {
    u64::BITS - x.leading_zeros()
}

#[inline(always)]
fn digit(key: u64, shift: u32) -> usize {
    ((key >> shift) as usize) & (RADIX - 1)
}

fn moves<C: Counter>(counter: &mut C, n: usize) {
    for _ in 0..n {
        counter.element_move();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;
    use crate::gen::Rng;

    fn bits(v: &[f64]) -> Vec<u64> {
        v.iter().map(|x| x.to_bits()).collect()
    }

    fn sorted_by_std(v: &[f64]) -> Vec<u64> {
        let mut expected = v.to_vec();
        expected.sort_unstable_by(f64::total_cmp);
        bits(&expected)
    }

    #[test]
    fn equal_bit_patterns_make_no_pass() {
        let mut v = vec![-3.25; 100_000];
        let mut counts = Counts::default();
        radix_sort_f64_with(&mut v, &mut counts);
        assert_eq!((counts.moves, counts.comparisons), (0, 0));
        assert!(v.iter().all(|x| x.to_bits() == (-3.25f64).to_bits()));
    }

    #[test]
    fn keys_differing_in_their_low_byte_take_one_pass_and_no_comparison() {
        // One binade, only the lowest byte varies: one counting pass sorts the part, and the
        // result comes back from the scratch buffer.
        let one = 1.0f64.to_bits();
        let mut v: Vec<f64> = (0..1000u64)
            .map(|i| f64::from_bits(one + (i * 37) % 256))
            .collect();
        let expected = sorted_by_std(&v);
        let mut counts = Counts::default();
        radix_sort_f64_with(&mut v, &mut counts);
        assert_eq!(bits(&v), expected);
        assert_eq!((counts.moves, counts.comparisons), (2 * 1000, 0));
    }

    #[test]
    fn ties_on_the_top_bits_fall_back_to_counting_passes() {
        // One outlier makes the top bits vary; the others tie on them and differ only in
        // their low 16 bits, so the insertion pass would need about m^2/4 shifts. The
        // fallback keeps the moves within the linear bound.
        let one = 1.0f64.to_bits();
        let mut rng = Rng::new(0x2545_F491_4F6C_DD1D);
        let mut v: Vec<f64> = (0..4000)
            .map(|_| {
                let s = rng.next_u64();
                f64::from_bits(one + (s & 0xFFFF))
            })
            .collect();
        v[1234] = f64::from_bits(one + (1 << 40));
        let expected = sorted_by_std(&v);
        let mut counts = Counts::default();
        radix_sort_f64_with(&mut v, &mut counts);
        assert_eq!(bits(&v), expected);
        assert!(counts.moves <= 16 * 4000, "{counts:?}");
        assert!(counts.comparisons <= 3 * 4000, "{counts:?}");
    }

    #[test]
    fn partition_levels_sort_large_inputs_of_mixed_magnitudes() {
        // Above PART_MAX: partitions in place first. Signs, binades, duplicates, signed zeros
        // and NaNs mixed.
        let mut rng = Rng::new(0x9E37_79B9_7F4A_7C15);
        let mut v: Vec<f64> = (0..3 * PART_MAX)
            .map(|i| {
                let s = rng.next_u64();
                match i % 5 {
                    0 => f64::from_bits(s),
                    1 => (s >> 11) as f64 / (1u64 << 53) as f64,
                    2 => ((s % 7) as f64) * if s & 8 == 0 { 1.0 } else { -1.0 },
                    3 => f64::from_bits(s >> 20), // subnormals and tiny normals
                    _ => -((s % 1000) as f64) * 1e300,
                }
            })
            .collect();
        let expected = sorted_by_std(&v);
        let n = v.len() as u64;
        let mut counts = Counts::default();
        radix_sort_f64_with(&mut v, &mut counts);
        assert_eq!(bits(&v), expected);
        assert!(counts.moves <= 24 * n && 2 * counts.comparisons <= 15 * n);
    }

    #[test]
    fn empty_buckets_of_a_partition_are_skipped() {
        // Integers below 2^17 in reverse: few exponents, so most of the 256 buckets of the
        // first partition are empty.
        let mut v: Vec<f64> = (0..2 * PART_MAX).rev().map(|i| i as f64).collect();
        let mut counts = Counts::default();
        radix_sort_f64_with(&mut v, &mut counts);
        assert!(v.iter().enumerate().all(|(i, &x)| x == i as f64));
    }

    #[cfg(feature = "parallel")]
    fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a small pool")
            .install(f)
    }

    /// Keys for the parallel partition and sort: skewed digits at bit 56, one bucket only,
    /// and keys laid out so that a 2-thread partition leaves a quarter of them behind (each
    /// thread's stripes hold twice the keys of one bucket its stripe of it has room for).
    #[cfg(feature = "parallel")]
    fn parallel_inputs(n: usize, rng: &mut Rng) -> Vec<(&'static str, Vec<f64>)> {
        let skewed = (0..n)
            .map(|_| {
                let s = rng.next_u64();
                f64::from_bits(if s & 1 == 0 { s & 0x00FF_FFFF } else { s })
            })
            .collect();
        let one_bucket = (0..n)
            .map(|_| f64::from_bits((7 << 56) | (rng.next_u64() >> 8)))
            .collect();
        let halves = (0..n)
            .map(|i| {
                let top = if (4 * i / n) % 2 == 0 { 1 } else { 2 };
                f64::from_bits((top << 56) | (rng.next_u64() >> 8))
            })
            .collect();
        vec![
            ("skewed", skewed),
            ("one bucket", one_bucket),
            ("halves", halves),
        ]
    }

    #[cfg(feature = "parallel")]
    #[test]
    fn parallel_partition_places_every_key_in_its_bucket() {
        let mut rng = Rng::new(0x9A27);
        for n in [1, 2, 1000, 20_000] {
            for (what, keys) in parallel_inputs(n, &mut rng) {
                let mut expected = keys.clone();
                expected.sort_unstable_by_key(|x| x.to_bits());
                for threads in [2, 3] {
                    for sweeps in [0, 1, SWEEPS] {
                        let mut v = keys.clone();
                        let ends = in_pool(threads, || par_partition(&mut v, 56, sweeps));
                        let mut start = 0;
                        for (d, &end) in ends.iter().enumerate() {
                            assert!(v[start..end].iter().all(|x| digit(x.to_bits(), 56) == d));
                            start = end;
                        }
                        assert_eq!(start, n);
                        v.sort_unstable_by_key(|x| x.to_bits());
                        assert_eq!(
                            bits(&v),
                            bits(&expected),
                            "{what}, n = {n}, {threads} threads, {sweeps} sweeps"
                        );
                    }
                }
            }
        }
    }

    /// The parallel sort below [`PAR_MIN`] too (called directly), against the standard sort.
    #[cfg(feature = "parallel")]
    #[test]
    fn parallel_sort_equals_the_standard_sort_in_every_pool() {
        let mut rng = Rng::new(0x9A28);
        for n in [70_000, 300_000] {
            let mut inputs = parallel_inputs(n, &mut rng);
            inputs.push(("mixed", crate::gen::sequence_f64(n, 5).expect("n is small")));
            inputs.push(("all equal", vec![-0.0; n]));
            for (what, v) in inputs {
                let expected = sorted_by_std(&v);
                for threads in [2, 3] {
                    let mut w = v.clone();
                    in_pool(threads, || par_sort(&mut w));
                    assert_eq!(bits(&w), expected, "{what}, n = {n}, {threads} threads");
                }
            }
        }
    }

    #[test]
    fn partition_places_every_key_in_its_bucket_with_or_without_sweeps() {
        let mut rng = Rng::new(0x0123_4567_89AB_CDEF);
        let keys: Vec<f64> = (0..20_000)
            .map(|_| {
                let s = rng.next_u64();
                // Skewed digits: bucket 0 gets about half the keys.
                f64::from_bits(if s & 1 == 0 { s & 0x00FF_FFFF } else { s })
            })
            .collect();
        let mut expected = keys.clone();
        expected.sort_unstable_by_key(|x| x.to_bits());
        for sweeps in [0, 1, 2, SWEEPS, 1000] {
            let mut v = keys.clone();
            let mut counts = Counts::default();
            let ends = partition(&mut v, 56, sweeps, &mut counts);
            let mut start = 0;
            for (d, &end) in ends.iter().enumerate() {
                assert!(v[start..end].iter().all(|x| digit(x.to_bits(), 56) == d));
                start = end;
            }
            assert_eq!(start, v.len());
            v.sort_unstable_by_key(|x| x.to_bits());
            assert_eq!(
                bits(&v),
                bits(&expected),
                "{sweeps} sweeps lost or duplicated keys"
            );
            let n = keys.len() as u64;
            assert!(
                counts.moves >= n && counts.moves <= 2 * n,
                "{sweeps}: {counts:?}"
            );
            if sweeps == 0 {
                assert_eq!(counts.moves, n, "following cycles writes each key once");
            }
        }
    }
}
