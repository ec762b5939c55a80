//! The generators' random source: ChaCha8 and integer-only derivations from it.
//!
//! Every random value a generator uses comes from [`Rng::next_u64`] and is turned into an
//! integer or a dyadic `f64` with exact operations only, so a seed produces the same bits on
//! every platform. Bounded integers use our own rejection method rather than `rand`'s range
//! sampling, so the output does not depend on how a `rand` release implements ranges.

use rand_chacha::rand_core::{RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// 2^-53: the spacing of the unit-interval samples.
const TWO_POW_MINUS_53: f64 = 1.0 / 9_007_199_254_740_992.0;

/// A seeded, portable random source: the one random source of the crate (the generators, the
/// incremental builder's insertion order and walks, the sweep's treap priorities, the tabu
/// search).
#[derive(Debug, Clone)]
pub(crate) struct Rng(ChaCha8Rng);

impl Rng {
    /// The stream for `seed` (ChaCha8 keyed by `seed_from_u64`, stream 0).
    pub(crate) fn new(seed: u64) -> Self {
        Rng(ChaCha8Rng::seed_from_u64(seed))
    }

    /// Like [`Rng::new`] but on ChaCha's independent stream number `stream`, so that two
    /// consumers of the same seed (a graph and its weights) do not see the same bits.
    pub(crate) fn with_stream(seed: u64, stream: u64) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(stream);
        Rng(rng)
    }

    /// 64 uniformly random bits.
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// A uniform integer in `0..n`; `n` must be positive.
    ///
    /// Multiply-shift with rejection of the biased low products (Lemire's method): exact and
    /// unbiased.
    pub(crate) fn below(&mut self, n: u64) -> u64 {
        debug_assert!(n > 0, "below(0) has no value to return");
        // 2^64 mod n: products whose low half falls below it would bias the result.
        let threshold = n.wrapping_neg() % n;
        loop {
            let product = u128::from(self.next_u64()) * u128::from(n);
            if (product as u64) >= threshold {
                return (product >> 64) as u64;
            }
        }
    }

    /// A uniform index in `0..n`; `n` must be positive.
    pub(crate) fn index(&mut self, n: usize) -> usize {
        // usize fits in u64 on every supported platform, and the result is below n.
        self.below(n as u64) as usize
    }

    /// A uniform integer in `lo..=hi`; requires `lo <= hi`.
    pub(crate) fn range_i64(&mut self, lo: i64, hi: i64) -> i64 {
        debug_assert!(lo <= hi);
        let span = hi.wrapping_sub(lo) as u64;
        let offset = if span == u64::MAX {
            self.next_u64()
        } else {
            self.below(span + 1)
        };
        lo.wrapping_add(offset as i64)
    }

    /// A uniform multiple of 2^-53 in `[0, 1)`: exact, 53 random bits.
    pub(crate) fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * TWO_POW_MINUS_53
    }

    /// A uniform multiple of 2^-52 in `[-1, 1)`; exact (`2u` and `2u - 1` are representable).
    pub(crate) fn symmetric_unit(&mut self) -> f64 {
        2.0 * self.unit() - 1.0
    }

    /// A fair coin.
    pub(crate) fn coin(&mut self) -> bool {
        self.next_u64() >> 63 == 1
    }

    /// Shuffles `items` uniformly (Fisher–Yates).
    pub(crate) fn shuffle<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.index(i + 1);
            items.swap(i, j);
        }
    }

    /// Moves a uniform random `k`-subset of `items`, in uniform random order, to the front
    /// (the first `k` steps of Fisher–Yates). Requires `k <= items.len()`.
    pub(crate) fn partial_shuffle<T>(&mut self, items: &mut [T], k: usize) {
        let len = items.len();
        for i in 0..k.min(len) {
            let j = i + self.index(len - i);
            items.swap(i, j);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn below_stays_in_range_and_hits_every_value() {
        let mut rng = Rng::new(7);
        let mut seen = [0u32; 7];
        for _ in 0..7000 {
            let v = rng.below(7);
            assert!(v < 7);
            seen[v as usize] += 1;
        }
        // Each bucket expects 1000; a fair sampler is far inside these bounds.
        assert!(seen.iter().all(|&c| (800..1200).contains(&c)), "{seen:?}");
    }

    #[test]
    fn below_handles_extreme_bounds() {
        let mut rng = Rng::new(1);
        for _ in 0..100 {
            assert_eq!(rng.below(1), 0);
            let big = u64::MAX - 1;
            assert!(rng.below(big) < big);
        }
    }

    #[test]
    fn range_i64_covers_inclusive_bounds_and_full_range() {
        let mut rng = Rng::new(3);
        let mut lo_seen = false;
        let mut hi_seen = false;
        for _ in 0..1000 {
            let v = rng.range_i64(-2, 2);
            assert!((-2..=2).contains(&v));
            lo_seen |= v == -2;
            hi_seen |= v == 2;
        }
        assert!(lo_seen && hi_seen);
        let mut signs = [false; 2];
        for _ in 0..100 {
            signs[usize::from(rng.range_i64(i64::MIN, i64::MAX) < 0)] = true;
        }
        assert_eq!(signs, [true, true]);
    }

    #[test]
    fn unit_samples_are_dyadic_and_in_range() {
        let mut rng = Rng::new(11);
        for _ in 0..1000 {
            let u = rng.unit();
            assert!((0.0..1.0).contains(&u));
            // A multiple of 2^-53 times 2^53 is an integer.
            assert_eq!((u * 9_007_199_254_740_992.0).fract(), 0.0);
            let s = rng.symmetric_unit();
            assert!((-1.0..1.0).contains(&s));
        }
    }

    #[test]
    fn streams_of_one_seed_differ() {
        let a: Vec<u64> = (0..4)
            .map({
                let mut r = Rng::new(8);
                move |_| r.next_u64()
            })
            .collect();
        let b: Vec<u64> = (0..4)
            .map({
                let mut r = Rng::with_stream(8, 1);
                move |_| r.next_u64()
            })
            .collect();
        let c: Vec<u64> = (0..4)
            .map({
                let mut r = Rng::with_stream(8, 0);
                move |_| r.next_u64()
            })
            .collect();
        assert_ne!(a, b);
        assert_eq!(a, c);
    }

    #[test]
    fn shuffles_are_permutations() {
        let mut rng = Rng::new(5);
        let mut v: Vec<usize> = (0..50).collect();
        rng.shuffle(&mut v);
        assert_ne!(v, (0..50).collect::<Vec<_>>());
        let mut sorted = v.clone();
        sorted.sort_unstable();
        assert_eq!(sorted, (0..50).collect::<Vec<_>>());

        let mut w: Vec<usize> = (0..50).collect();
        rng.partial_shuffle(&mut w, 10);
        w.sort_unstable();
        assert_eq!(w, (0..50).collect::<Vec<_>>());
    }
}
