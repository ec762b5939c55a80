//! Lexicographic sorts of points: one function for the monotone chain, Akl–Toussaint, Chan,
//! the brute-force hull, the divide-and-conquer and Lawson triangulations, Fortune's sweep (by
//! y, then x) and `find_duplicates`, which takes a radix sort when nobody counts.
//!
//! The problem: the items `(points[i], i)` of some indices `i`, ordered by their points, x
//! then y ([`cmp_lex`]) or y then x, equal points by index, so there is one right answer
//! whichever sort finds it. A finite point's 128-bit key, the order-preserving integer keys
//! ([`order_key`]) of its two coordinates side by side after `-0.0` becomes `0.0`, orders as
//! the points do, so both sorts compare or split integers.
//!
//! The radix sort: one pass finds the bits in which the keys differ. The bits of each half
//! from its highest to its lowest varying bit, x's then as many of y's as fit, make a 64-bit
//! prefix that orders as the key wherever it tells two keys apart: the bits every key shares
//! (the sign and most exponent bits of bounded data, the low zero bits of small integers) are
//! left out. The `(prefix, index)` pairs are sorted by stable counting passes of up to 11 bits
//! each, least significant first, on the prefix's top ⌊log₂ n⌋ + 9 bits (on all of it when
//! the prefix is exact and a pass or two longer); a digit on which every key agrees is
//! skipped. On random input two keys share those top bits with probability about 2⁻⁸ per
//! item, so the sort is then finished by sorting the few runs of items with equal top bits by
//! comparisons (on their full keys and indices). The last pass writes the items, points
//! gathered from the input, so no pass moves more than 16 bytes per item before it.
//! Not in the course; it is the least-significant-digit radix sort with the prefix trick of
//! the `f64` radix sort ([`crate::sort::radix_sort_f64`]).
//!
//! # Counting
//!
//! The radix sort counts nothing, so only runs with [`NoCount`](crate::count::NoCount) take it
//! ([`Counter::DISCARDS`]). A counter that records gets the comparison sort whose comparisons
//! the catalog measures: `sort_unstable_by` on `(key, index)` pairs, one comparison per
//! comparison of two pairs (as many as sorting `(point, index)` items by [`cmp_lex`] and
//! index: both orders are the same total order on the same kind of elements). Both paths give
//! the same order, so no result depends on the counter.
//!
//! # Complexity
//!
//! With n items and w = 64 prefix bits: the radix path takes time O(n · w / 11) = O(n) for the
//! passes plus O(r log r) for each run of r items tied on the sorted bits: O(n) on random
//! input, O(n log n) at worst (every key tied on its top bits), the comparison sort's bound.
//! Auxiliary space O(n) (the pairs and a buffer for them) plus O(2¹¹) counters per pass.
//! The comparison path: O(n log n) time, O(n) space.
//!
//! Invariants the tests check: the radix path's order equals `sort_unstable_by` on `(key,
//! index)` for arbitrary finite bit patterns (signed zeros, subnormals, `f64::MAX`,
//! duplicates, indices in any order) and for every generator kind, both keys; the comparison
//! path counts exactly the comparisons of sorting `(point, index)` by [`cmp_lex`] and index;
//! the keys order as [`cmp_lex`].
//!
//! [`cmp_lex`]: crate::geometry::cmp_lex
//! [`Counter::DISCARDS`]: crate::count::Counter::DISCARDS

use super::Point2;
use crate::count::{Counter, Silent};
use crate::util::order_key;

/// Inputs shorter than this take the comparison sort even with `NoCount`: on fewer items the
/// radix sort's fixed costs (the key pass, the histograms, a buffer) outweigh the comparisons
/// it saves. Measured (interleaved runs, median of the per-run ratios): at 256 points the
/// radix sort is 1.01–1.10 times as fast on uniform, gaussian and clustered input but 0.94 on
/// a grid, at 384 points 1.00 on the grid and 1.16–1.21 on the others; at 64 points 0.6–0.8.
pub(crate) const CUTOFF: usize = 384;
/// The most bits of a digit: at most 2^11 counters per pass, and as many write positions,
/// which stay in the L2 cache.
const MAX_DIGIT_BITS: u32 = 11;
/// Sorted bits beyond ⌊log₂ n⌋ + 1: with 8, random keys tie on all of them with probability
/// about 2⁻⁸ per item.
const EXTRA_BITS: u32 = 8;

/// An item: a point and its index in the caller's input.
pub(crate) type Item = (Point2, usize);

/// A pair of the radix sort: an item's key prefix and its index.
type Pair = (u64, usize);

/// The 128-bit key of a finite point whose integer order is [`cmp_lex`](super::cmp_lex): the
/// order keys of x, then y, after mapping `-0.0` to `0.0` (which `cmp_lex` treats as equal).
#[inline(always)]
pub(crate) fn lex_key(p: Point2) -> u128 {
    u128::from(order_key(p.x + 0.0)) << 64 | u128::from(order_key(p.y + 0.0))
}

/// The 128-bit key of a finite point ordering by y, then x (Fortune's sweep order).
#[inline(always)]
pub(crate) fn yx_key(p: Point2) -> u128 {
    lex_key(Point2::new(p.y, p.x))
}

/// The items `(points[i], i)` of `indices`, sorted by `key` of their points, equal keys by
/// index: the order of `sort_unstable_by` on `(key(point), index)`. `key` is [`lex_key`] or
/// [`yx_key`]; the points must be finite.
///
/// With [`NoCount`](crate::count::NoCount) and at least [`CUTOFF`] items, a radix sort that
/// counts nothing; otherwise `sort_unstable_by` on `(key, index)` pairs, each comparison of
/// two pairs counted as one comparison. See the [module docs](self).
pub(crate) fn sorted_items_with<C, K>(
    points: &[Point2],
    indices: impl ExactSizeIterator<Item = usize>,
    key: K,
    counter: &mut C,
) -> Vec<Item>
where
    C: Counter,
    K: Fn(Point2) -> u128 + Copy + Sync,
{
    if C::DISCARDS && indices.len() >= CUTOFF {
        #[cfg(feature = "parallel")]
        if crate::parallel::enabled(indices.len()) {
            return par_radix_sorted(points, indices, key);
        }
        return radix_sorted(points, indices, key);
    }
    compared_items_with(points, indices, key, counter)
}

/// The items of [`sorted_items_with`] by the comparison sort whatever the counter: for a
/// caller that measured no gain from the radix sort (Akl–Toussaint's survivors).
pub(crate) fn compared_items_with<C, K>(
    points: &[Point2],
    indices: impl Iterator<Item = usize>,
    key: K,
    counter: &mut C,
) -> Vec<Item>
where
    C: Counter,
    K: Fn(Point2) -> u128,
{
    let mut keyed: Vec<(u128, usize)> = indices.map(|i| (key(points[i]), i)).collect();
    keyed.sort_unstable_by(|a, b| {
        counter.comparison();
        a.cmp(b)
    });
    keyed.into_iter().map(|(_, i)| (points[i], i)).collect()
}

/// The lexicographic order (x, then y; equal points by index) of `points` as items, by the
/// radix sort whatever their number. For the benchmarks (`benches/hull.rs`, group
/// `lex-sort`) only: not part of the API.
#[doc(hidden)]
pub fn radix_sorted_lex(points: &[Point2]) -> Vec<(Point2, usize)> {
    radix_sorted(points, 0..points.len(), lex_key)
}

/// The same order as [`radix_sorted_lex`] by the parallel radix sort (feature `parallel`;
/// the sequential one below its threshold or in a 1-thread pool). For the benchmarks and
/// tests only: not part of the API.
#[cfg(feature = "parallel")]
#[doc(hidden)]
pub fn parallel_sorted_lex(points: &[Point2]) -> Vec<(Point2, usize)> {
    if crate::parallel::enabled(points.len()) {
        par_radix_sorted(points, 0..points.len(), lex_key)
    } else {
        radix_sorted(points, 0..points.len(), lex_key)
    }
}

/// The same order as [`radix_sorted_lex`] by the comparison sort (`sort_unstable_by` on
/// `(key, index)` pairs), as a counted run sorts but counting nothing. For the benchmarks
/// only: not part of the API.
#[doc(hidden)]
pub fn comparison_sorted_lex(points: &[Point2]) -> Vec<(Point2, usize)> {
    sorted_items_with(points, 0..points.len(), lex_key, &mut Silent)
}

/// The radix path of [`sorted_items_with`] on all the threads (feature `parallel`): one
/// parallel pass finds the bits in which the keys differ, the `(prefix, index)` pairs are
/// distributed by the top bits of their prefixes into buckets ([`crate::parallel::scatter`]),
/// and the buckets are sorted independently, in parallel, by the sequential passes
/// ([`sort_pairs`]), each into its own stretch of the items. No merge pass: the buckets are in
/// order. `(key, index)` is a strict total order, so the result is the sequential one.
#[cfg(feature = "parallel")]
pub(crate) fn par_radix_sorted<K>(
    points: &[Point2],
    indices: impl Iterator<Item = usize>,
    key: K,
) -> Vec<Item>
where
    K: Fn(Point2) -> u128 + Copy + Sync,
{
    use rayon::prelude::*;
    let indices: Vec<usize> = indices.collect();
    let Some(&i0) = indices.first() else {
        return Vec::new();
    };
    let n = indices.len();
    let first = key(points[i0]);
    let diff = indices
        .par_iter()
        .map(|&i| key(points[i]) ^ first)
        .reduce(|| 0, |a, b| a | b);
    let prefix = Prefix::new(diff);
    // Buckets of about 2^12 items: each one's pairs and their buffer stay in the L2 cache.
    let top_bits = (usize::BITS - n.leading_zeros())
        .saturating_sub(12)
        .clamp(8, MAX_DIGIT_BITS)
        .min(prefix.width);
    let shift = prefix.width - top_bits;
    let mut pairs = vec![(0u64, 0usize); n];
    let ends = crate::parallel::scatter(&indices, &mut pairs, 1 << top_bits, |&i| {
        let p = prefix.of(key(points[i]));
        ((p >> shift) as usize, (p, i))
    });
    let mut items = vec![(Point2::default(), 0); n];
    crate::parallel::split_buckets(&mut pairs, &mut items, &ends)
        .into_par_iter()
        .for_each(|(pairs, out)| {
            let Some(&(p0, _)) = pairs.first() else {
                return;
            };
            // The bucket's prefixes agree from their highest differing bit up.
            let diff = pairs.iter().fold(0, |d, &(p, _)| d | (p ^ p0));
            let width = u64::BITS - diff.leading_zeros();
            sort_pairs::<false, K>(points, pairs, out, &prefix, width, key);
        });
    items
}

/// The radix path of [`sorted_items_with`], for any number of items.
fn radix_sorted<K: Fn(Point2) -> u128 + Copy>(
    points: &[Point2],
    mut indices: impl Iterator<Item = usize>,
    key: K,
) -> Vec<Item> {
    let Some(i0) = indices.next() else {
        return Vec::new();
    };
    // The pairs, their prefixes filled in once the varying bits are known.
    let first = key(points[i0]);
    let mut diff = 0;
    let mut pairs: Vec<(u64, usize)> = Vec::with_capacity(indices.size_hint().0 + 1);
    pairs.push((0, i0));
    for i in indices {
        diff |= key(points[i]) ^ first;
        pairs.push((0, i));
    }
    let prefix = Prefix::new(diff);
    let mut items = vec![(Point2::default(), 0); pairs.len()];
    sort_pairs::<true, K>(points, &mut pairs, &mut items, &prefix, prefix.width, key);
    items
}

/// Writes the items of `pairs` (not empty) into `out` (as long), sorted by `(key, index)`:
/// the pairs' prefixes (filled in first from the keys if `FILL`) agree on every bit from
/// `width` up. Counting passes on the top bits below `width`, the last writing the items,
/// then the runs of items tied on those bits sorted by comparisons.
fn sort_pairs<const FILL: bool, K: Fn(Point2) -> u128 + Copy>(
    points: &[Point2],
    pairs: &mut [Pair],
    out: &mut [Item],
    prefix: &Prefix,
    width: u32,
    key: K,
) {
    let n = pairs.len();
    // The sorted bits: all of an exact prefix if that takes at most two more digits than
    // the wanted bits, else the wanted bits rounded up to whole digits.
    let bit_length = usize::BITS - n.leading_zeros();
    let digit_bits = bit_length.saturating_sub(2).clamp(8, MAX_DIGIT_BITS);
    let wanted = bit_length + EXTRA_BITS;
    let (digits, bits) = if prefix.exact && width <= wanted + 2 * digit_bits {
        (width.div_ceil(digit_bits), width)
    } else {
        let digits = wanted.div_ceil(digit_bits);
        (digits, (digits * digit_bits).min(width))
    };
    let lo = width - bits;
    let dw = bits.div_ceil(digits.max(1));
    let radix = 1usize << dw;
    let mask = radix as u64 - 1;
    let digit = |p: u64, d: usize| ((p >> (lo + dw * d as u32)) & mask) as usize;
    // One pass fills the prefixes and every digit's histogram.
    let mut histograms = vec![0usize; digits as usize * radix];
    for pair in pairs.iter_mut() {
        if FILL {
            pair.0 = prefix.of(key(points[pair.1]));
        }
        for d in 0..digits as usize {
            histograms[d * radix + digit(pair.0, d)] += 1;
        }
    }
    // Digits on which every key agrees take no pass; the others' counts become positions.
    let passes: Vec<usize> = (0..digits as usize)
        .filter(|&d| !histograms[d * radix..(d + 1) * radix].contains(&n))
        .collect();
    for &d in &passes {
        let mut sum = 0;
        for slot in &mut histograms[d * radix..(d + 1) * radix] {
            let count = *slot;
            *slot = sum;
            sum += count;
        }
    }
    match passes.split_last() {
        None => {
            for (item, &(_, i)) in out.iter_mut().zip(pairs.iter()) {
                *item = (points[i], i);
            }
        }
        Some((&last, inner)) => {
            let mut buffer = if inner.is_empty() {
                Vec::new()
            } else {
                vec![(0u64, 0usize); n]
            };
            let mut in_buffer = false;
            for &d in inner {
                let next = &mut histograms[d * radix..(d + 1) * radix];
                let (from, to): (&[Pair], &mut [Pair]) = if in_buffer {
                    (&buffer, pairs)
                } else {
                    (pairs, &mut buffer)
                };
                for &pair in from.iter() {
                    let slot = &mut next[digit(pair.0, d)];
                    to[*slot] = pair;
                    *slot += 1;
                }
                in_buffer = !in_buffer;
            }
            // The last pass writes the items themselves.
            let from: &[Pair] = if in_buffer { &buffer } else { pairs };
            let next = &mut histograms[last * radix..(last + 1) * radix];
            for &(p, i) in from.iter() {
                let slot = &mut next[digit(p, last)];
                out[*slot] = (points[i], i);
                *slot += 1;
            }
        }
    }
    // Runs of items tied on the sorted bits: by full key, then index.
    let sorted_bits = |p: Point2| prefix.of(key(p)) >> lo;
    let mut start = 0;
    let mut run = sorted_bits(out[0].0);
    for k in 1..=n {
        let next = if k < n { sorted_bits(out[k].0) } else { !run };
        if next != run {
            if k - start > 1 {
                out[start..k].sort_unstable_by(|a, b| key(a.0).cmp(&key(b.0)).then(a.1.cmp(&b.1)));
            }
            start = k;
            run = next;
        }
    }
}

/// The 64-bit prefix of keys that differ in the bits of `diff`: the bits of the key's x half
/// from its highest to its lowest varying one, then as many of the y half's from its highest
/// varying one down as fit. It orders as the keys, ties aside.
struct Prefix {
    /// The lowest varying bit of the x half.
    x_low: u32,
    /// The bits of each half in the prefix.
    x_bits: u32,
    y_bits: u32,
    /// The bit just above the y half's highest varying one.
    y_high: u32,
    /// `x_bits + y_bits`: the prefix's bits, its lowest ones.
    width: u32,
    /// Whether every varying bit is in the prefix, so equal prefixes mean equal keys.
    exact: bool,
}

impl Prefix {
    fn new(diff: u128) -> Prefix {
        // The lowest varying bit and one past the highest; (0, 0) for a constant half.
        let range = |d: u64| match d {
            0 => (0, 0),
            _ => (d.trailing_zeros(), u64::BITS - d.leading_zeros()),
        };
        let (x_low, x_high) = range((diff >> 64) as u64);
        let (y_low, y_high) = range(diff as u64);
        let x_bits = x_high - x_low;
        let y_bits = (y_high - y_low).min(u64::BITS - x_bits);
        Prefix {
            x_low,
            x_bits,
            y_bits,
            y_high,
            width: x_bits + y_bits,
            exact: y_bits == y_high - y_low,
        }
    }

    #[inline(always)]
    fn of(&self, key: u128) -> u64 {
        let low_bits = |v: u64, bits: u32| v & (u64::MAX >> (u64::BITS - bits));
        let (kx, ky) = ((key >> 64) as u64, key as u64);
        let x = match self.x_bits {
            0 => 0,
            // y_bits < 64 here: it is at most 64 - x_bits.
            b => low_bits(kx >> self.x_low, b) << self.y_bits,
        };
        let y = match self.y_bits {
            0 => 0,
            b => low_bits(ky >> (self.y_high - b), b),
        };
        x | y
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::{Counts, NoCount};
    use crate::gen::{points, PointKind, Rng};
    use crate::geometry::cmp_lex;

    /// The key order is `cmp_lex` on signed zeros, subnormals, huge values and neighbours.
    #[test]
    fn keys_order_as_cmp_lex() {
        let values = [
            -f64::MAX,
            -1e300,
            -1.0,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            1e-310,
            f64::MIN_POSITIVE,
            1.0,
            1.0 + f64::EPSILON,
            1e300,
            f64::MAX,
        ];
        for &a in &values {
            for &b in &values {
                for &c in &values {
                    let (p, q) = (Point2::new(a, b), Point2::new(a, c));
                    let (r, s) = (Point2::new(a, b), Point2::new(c, b));
                    assert_eq!(lex_key(p).cmp(&lex_key(q)), cmp_lex(p, q), "{p:?} {q:?}");
                    assert_eq!(lex_key(r).cmp(&lex_key(s)), cmp_lex(r, s), "{r:?} {s:?}");
                    let (t, u) = (Point2::new(b, a), Point2::new(c, a));
                    assert_eq!(yx_key(p).cmp(&yx_key(q)), cmp_lex(t, u), "{p:?} {q:?}");
                }
            }
        }
    }

    /// The oracle: `(point, index)` items by `cmp_lex` (on swapped coordinates for y, x) and
    /// index, with the comparator calls counted; bit patterns, to tell -0.0 from 0.0.
    fn by_cmp_lex(points: &[Point2], indices: &[usize], yx: bool) -> (Vec<[u64; 3]>, u64) {
        let swap = |p: Point2| if yx { Point2::new(p.y, p.x) } else { p };
        let mut items: Vec<Item> = indices.iter().map(|&i| (points[i], i)).collect();
        let mut calls = 0;
        items.sort_unstable_by(|a, b| {
            calls += 1;
            cmp_lex(swap(a.0), swap(b.0)).then(a.1.cmp(&b.1))
        });
        (bits(&items), calls)
    }

    fn bits(items: &[Item]) -> Vec<[u64; 3]> {
        items
            .iter()
            .map(|(p, i)| [p.x.to_bits(), p.y.to_bits(), *i as u64])
            .collect()
    }

    fn check(points: &[Point2], indices: &[usize], what: &str) {
        for (yx, key) in [(false, lex_key as fn(Point2) -> u128), (true, yx_key)] {
            let (expected, calls) = by_cmp_lex(points, indices, yx);
            let radix = radix_sorted(points, indices.iter().copied(), key);
            assert_eq!(bits(&radix), expected, "radix, {what}, yx {yx}");
            let mut counts = Counts::default();
            let compared = sorted_items_with(points, indices.iter().copied(), key, &mut counts);
            assert_eq!(bits(&compared), expected, "comparisons, {what}, yx {yx}");
            assert_eq!(counts.comparisons, calls, "{what}, yx {yx}");
            let fast = sorted_items_with(points, indices.iter().copied(), key, &mut NoCount);
            assert_eq!(bits(&fast), expected, "NoCount, {what}, yx {yx}");
        }
    }

    #[test]
    fn both_paths_equal_the_cmp_lex_sort_on_every_generator_kind() {
        for kind in PointKind::ALL {
            for n in [0, 1, 2, 300, 5000] {
                let pts = points(kind, n, 5).unwrap();
                let all: Vec<usize> = (0..n).collect();
                check(&pts, &all, &format!("{kind}, n = {n}"));
                // A subset in decreasing order, as a filter might hand it over.
                let some: Vec<usize> = (0..n).rev().filter(|i| i % 3 != 1).collect();
                check(&pts, &some, &format!("{kind}, n = {n}, subset"));
            }
        }
    }

    #[test]
    fn radix_path_equals_the_comparison_sort_on_mixed_magnitudes_and_duplicates() {
        let mut rng = Rng::new(11);
        let coordinate = |s: u64| {
            let v = match s % 6 {
                0 => f64::from_bits(s >> 2) * if s & 2 == 0 { 1.0 } else { -1.0 },
                1 => ((s >> 8) % 5) as f64 - 2.0, // repeats, both zeros
                2 => -0.0,
                3 => f64::from_bits(s >> 14), // subnormals and tiny normals
                4 => f64::MAX * if s & 64 == 0 { 1.0 } else { -1.0 },
                _ => (s >> 11) as f64 / (1u64 << 53) as f64,
            };
            if v.is_finite() {
                v
            } else {
                1.5
            }
        };
        for n in [300, 4000, 70_000] {
            let pts: Vec<Point2> = (0..n)
                .map(|_| Point2::new(coordinate(rng.next_u64()), coordinate(rng.next_u64())))
                .collect();
            let indices: Vec<usize> = (0..n).rev().collect();
            check(&pts, &indices, &format!("mixed, n = {n}"));
        }
    }

    #[test]
    fn prefixes_keep_the_varying_bits_in_order() {
        // x varies in bits 3..10 of its half, y in bits 60..62: exact, 10 bits.
        let p = Prefix::new((0x7F8u128 << 64) | (0b11 << 60));
        assert_eq!((p.width, p.exact), (10, true));
        // x bits 3..10 of 0x2A8 are 0101_0101, then y's two bits 10.
        assert_eq!(
            p.of((0x2A8u128 << 64) | (0b10 << 60)),
            (0b0101_0101 << 2) | 0b10
        );
        // x varies in all 64 bits: y is left out.
        let p = Prefix::new((u128::from(u64::MAX) << 64) | 1);
        assert_eq!((p.width, p.exact), (64, false));
        assert_eq!(p.of((5u128 << 64) | 1), 5);
        // Only y varies.
        let p = Prefix::new(0xF0);
        assert_eq!((p.width, p.exact), (4, true));
        assert_eq!(p.of((7u128 << 64) | 0xA5), 0xA);
    }
}
