//! LSD radix sort for `f64` keys in the IEEE 754 total order, without comparisons.
//!
//! A float's bits, read as an unsigned integer after flipping the sign bit of non-negative
//! values and every bit of negative ones, order exactly as [`f64::total_cmp`] orders the
//! floats: −NaN < −∞ < … < −0.0 < +0.0 < … < +∞ < +NaN. Sorting those 64-bit keys by their
//! bytes, least significant first, with a stable counting sort per byte sorts the floats.
//! One pass over the input builds all eight byte histograms; a byte on which every key agrees
//! (the sign and high exponent bits of data of one sign and magnitude, say) is skipped.
//! Not in the seed; it is compgeo's candidate fast path for sorting coordinates, measured
//! against `sort_unstable_by(f64::total_cmp)` in `benches/sort.rs` (group `radix-f64`).
//!
//! Invariants the tests check: the output equals `sort_unstable_by(f64::total_cmp)` bit for
//! bit (signed zeros, subnormals, infinities, NaNs of both signs and any payload); moves are
//! n per pass made.

use crate::count::{Counter, NoCount};

/// Bits per digit: eight passes of one byte, 256 buckets.
const DIGIT_BITS: u32 = 8;
const BUCKETS: usize = 1 << DIGIT_BITS;
const PASSES: usize = (u64::BITS / DIGIT_BITS) as usize;

/// Sorts `v` in the IEEE 754 total order ([`f64::total_cmp`]) with an LSD radix sort.
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

/// Sorts `v` like [`radix_sort_f64`], recording its element moves in `counter`.
///
/// Idea: map each float to the 64-bit key that orders as [`f64::total_cmp`] (flip the sign
/// bit of non-negative floats, every bit of negative ones), count the keys' bytes in one
/// pass, then for each byte from the least significant up distribute the elements stably
/// into 256 buckets between `v` and one buffer, skipping bytes on which all keys agree. The
/// first pass turns floats into keys, the middle ones move keys, and the last turns keys back
/// into floats as it writes them, so no pass recomputes a key.
///
/// Not in the seed; it sorts what [`super::merge_sort_by`] or [`super::quick_sort_by`] with
/// `f64::total_cmp` sort, in linear time.
///
/// # Errors
///
/// None: every `f64`, NaN included, has its place in the total order.
///
/// # Complexity
///
/// With n = `v.len()`, d = 8 passes of b = 256 buckets: time O(d(n + b)) = O(n); auxiliary
/// space n floats plus d·b counters.
///
/// # Counts
///
/// No comparisons. moves: n for every pass made (a pass writes each element once into its
/// bucket), plus n when an odd number of passes leaves the result in the buffer and it is
/// copied back; so at most 8n, and 0 when all elements share their bit pattern.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::sort::radix_sort_f64_with;
///
/// // Only the lowest byte differs: one pass, then the copy back.
/// let mut v = [1.0 + 3.0 * f64::EPSILON, 1.0, 1.0 + f64::EPSILON];
/// let mut counts = Counts::default();
/// radix_sort_f64_with(&mut v, &mut counts);
/// assert_eq!(v, [1.0, 1.0 + f64::EPSILON, 1.0 + 3.0 * f64::EPSILON]);
/// assert_eq!((counts.comparisons, counts.moves), (0, 6));
/// ```
pub fn radix_sort_f64_with<C: Counter>(v: &mut [f64], counter: &mut C) {
    let n = v.len();
    if n < 2 {
        return;
    }
    let mut histograms = [[0usize; BUCKETS]; PASSES];
    for &x in v.iter() {
        let k = key(x);
        for (pass, histogram) in histograms.iter_mut().enumerate() {
            histogram[digit(k, pass as u32 * DIGIT_BITS)] += 1;
        }
    }

    let passes: Vec<usize> = (0..PASSES)
        .filter(|&pass| !histograms[pass].contains(&n))
        .collect();
    let Some(&last) = passes.last() else {
        return;
    };
    // One buffer; between passes the elements travel as their keys' bit patterns, so no pass
    // recomputes a key, and the last pass turns keys back into floats as it writes them.
    let mut buffer = vec![0.0f64; n];
    for (i, &pass) in passes.iter().enumerate() {
        let mut next = bucket_starts(&histograms[pass]);
        let shift = pass as u32 * DIGIT_BITS;
        let out = |k: u64| {
            if pass == last {
                float(k)
            } else {
                f64::from_bits(k)
            }
        };
        if i == 0 {
            for &x in v.iter() {
                let k = key(x);
                scatter(&mut buffer, &mut next, shift, k, out(k));
            }
        } else if i % 2 == 1 {
            for &x in buffer.iter() {
                let k = x.to_bits();
                scatter(v, &mut next, shift, k, out(k));
            }
        } else {
            for &x in v.iter() {
                let k = x.to_bits();
                scatter(&mut buffer, &mut next, shift, k, out(k));
            }
        }
        moves(counter, n);
    }
    if passes.len() % 2 == 1 {
        v.copy_from_slice(&buffer);
        moves(counter, n);
    }
}

#[inline(always)]
fn key(x: f64) -> u64 {
    let bits = x.to_bits();
    // All ones for negative floats, only the sign bit for the others.
    let flip = (((bits as i64) >> 63) as u64) | (1 << 63);
    bits ^ flip
}

#[inline(always)]
fn float(key: u64) -> f64 {
    // Keys with the top bit set came from non-negative floats: undo the flips of `key`.
    let flip = if key >> 63 == 1 { 1 << 63 } else { u64::MAX };
    f64::from_bits(key ^ flip)
}

#[inline(always)]
fn digit(key: u64, shift: u32) -> usize {
    ((key >> shift) as usize) & (BUCKETS - 1)
}

/// Bucket d's first free slot: the number of keys with a smaller digit.
fn bucket_starts(histogram: &[usize; BUCKETS]) -> [usize; BUCKETS] {
    let mut next = [0usize; BUCKETS];
    let mut sum = 0;
    for (slot, &count) in next.iter_mut().zip(histogram) {
        *slot = sum;
        sum += count;
    }
    next
}

/// Writes `value` into the next free slot of `key`'s bucket.
#[inline(always)]
fn scatter<T>(dst: &mut [T], next: &mut [usize; BUCKETS], shift: u32, key: u64, value: T) {
    let d = digit(key, shift);
    dst[next[d]] = value;
    next[d] += 1;
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

    #[test]
    fn keys_order_as_total_cmp() {
        let xs = [
            f64::from_bits(0xFFF8_0000_0000_0001), // negative NaN with a payload
            -f64::NAN,
            f64::NEG_INFINITY,
            f64::MIN,
            -1.0,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            f64::MIN_POSITIVE,
            1.0,
            f64::MAX,
            f64::INFINITY,
            f64::NAN,
        ];
        for a in xs {
            for b in xs {
                assert_eq!(key(a).cmp(&key(b)), a.total_cmp(&b), "{a:e} vs {b:e}");
            }
        }
    }

    #[test]
    fn equal_bit_patterns_make_no_pass() {
        let mut v = vec![-3.25; 100];
        let mut counts = Counts::default();
        radix_sort_f64_with(&mut v, &mut counts);
        assert_eq!(counts.moves, 0);
    }

    #[test]
    fn two_differing_bytes_make_two_passes_and_no_copy() {
        // One binade: the keys differ in byte 0 (last mantissa bit) and byte 6 only.
        let e = f64::EPSILON;
        let mut v = vec![1.75 + e, 1.5, 1.75, 1.5 + e];
        let mut counts = Counts::default();
        radix_sort_f64_with(&mut v, &mut counts);
        assert_eq!(v, [1.5, 1.5 + e, 1.75, 1.75 + e]);
        assert_eq!(counts.moves, 2 * 4);
    }
}
