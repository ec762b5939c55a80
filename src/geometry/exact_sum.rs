//! The exact sum of many numbers, rounded once: the total weight of a spanning tree, the
//! total length of a Euclidean one.
//!
//! A running `f64` sum overflows past `f64::MAX` and, with mixed signs, can lose everything
//! (`1e308 + -1e308 + 1` summed left to right is `1`, but `1e308 + 1 + -1e308` is `0`). This
//! accumulator instead adds every term exactly into a fixed-point number that spans every
//! bit a term can have, from the last bit of the smallest subnormal's `WideFloat` distance
//! (2^-1126) up to 2^1165, in 32-bit chunks with room for carries: each addition is a few
//! integer additions, and the total is rounded once, correctly, when read.

use super::bigint::BigInt;
use super::extended::decompose;
use super::WideFloat;

/// The weight of chunk 0's lowest bit: the last significand bit of a `WideFloat` at
/// `2^-1074` (the least subnormal; no nonzero distance between doubles is smaller).
const BOTTOM: i32 = -1074 - 52;

/// The largest `WideFloat` exponent a term may have (distances stay below 2^1026).
const TOP_EXPONENT: i32 = 1100;

/// 32-bit chunks: a term's last bit is at most `TOP_EXPONENT − 52 − BOTTOM = 2174` bits up,
/// so it touches chunks up to 69; the carries of up to 2^64 terms reach bit 2291, chunk 71.
const CHUNKS: usize = 72;

/// Additions between carry propagations: each changes a chunk by less than 2^32, so 2^30 of
/// them keep every chunk below 2^63 in magnitude.
const BATCH: u32 = 1 << 30;

/// An exact sum of finite `f64`s and of `WideFloat`s with exponents at most 1100 (lengths),
/// read as a correctly rounded [`WideFloat`].
///
/// The value is `Σ chunks[i] · 2^(BOTTOM + 32 i)`; between propagations a chunk may hold
/// any `i64`, so positive and negative terms are added alike.
#[derive(Debug, Clone)]
pub(crate) struct ExactSum {
    chunks: [i64; CHUNKS],
    pending: u32,
}

impl ExactSum {
    /// Zero.
    pub(crate) fn new() -> ExactSum {
        ExactSum {
            chunks: [0; CHUNKS],
            pending: 0,
        }
    }

    /// Adds a finite `v` exactly.
    ///
    /// # Panics
    /// If `v` is NaN or infinite (callers pass validated values).
    pub(crate) fn add_f64(&mut self, v: f64) {
        assert!(v.is_finite(), "ExactSum of a non-finite value ({v})");
        let (negative, m, e) = decompose(v);
        self.add_parts(negative, m, e);
    }

    /// Adds `w` exactly.
    ///
    /// # Panics
    /// If `w`'s exponent exceeds 1100 (no length of the crate comes near).
    pub(crate) fn add(&mut self, w: WideFloat) {
        let (negative, m, e) = w.integer_parts();
        assert!(
            m == 0 || (BOTTOM..=TOP_EXPONENT - 52).contains(&e),
            "ExactSum term {w:?} out of range"
        );
        self.add_parts(negative, m, e);
    }

    /// The sum, correctly rounded (relative error at most 2^-53).
    pub(crate) fn value(&self) -> WideFloat {
        let mut c = self.chunks;
        propagate(&mut c);
        // Now every chunk but the last is in [0, 2^32) and the last carries the sign.
        let last = CHUNKS - 1;
        let mut total = BigInt::from_parts(c[last] < 0, c[last].unsigned_abs(), 32 * last as u32);
        for (i, &chunk) in c[..last].iter().enumerate() {
            if chunk != 0 {
                total = total.add(&BigInt::from_parts(false, chunk as u64, 32 * i as u32));
            }
        }
        WideFloat::from_big(&total).scale_pow2(BOTTOM)
    }

    /// Adds `±m · 2^e` (`m < 2^53`, `e >= BOTTOM`).
    fn add_parts(&mut self, negative: bool, m: u64, e: i32) {
        if m == 0 {
            return;
        }
        let position = (e - BOTTOM) as u32;
        let (i, shift) = ((position / 32) as usize, position % 32);
        // 53 bits shifted by at most 31 span at most three chunks.
        let wide = u128::from(m) << shift;
        for (k, piece) in [wide as u32, (wide >> 32) as u32, (wide >> 64) as u32]
            .into_iter()
            .enumerate()
        {
            let piece = i64::from(piece);
            self.chunks[i + k] += if negative { -piece } else { piece };
        }
        self.pending += 1;
        if self.pending == BATCH {
            propagate(&mut self.chunks);
            self.pending = 0;
        }
    }
}

/// Moves every chunk's bits above 32 into the next one (the value is unchanged), leaving
/// the chunks below the last in `[0, 2^32)`.
fn propagate(c: &mut [i64; CHUNKS]) {
    for i in 0..CHUNKS - 1 {
        // An arithmetic shift: floor division, so the remainder is non-negative.
        let carry = c[i] >> 32;
        c[i] -= carry << 32;
        c[i + 1] += carry;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::wide::tests::finite;
    use crate::geometry::Point2;
    use num_bigint::BigInt as Oracle;
    use num_rational::BigRational;
    use num_traits::{Signed, Zero};
    use proptest::prelude::*;

    fn q(v: f64) -> BigRational {
        BigRational::from_float(v).unwrap()
    }

    /// The exact value of a `WideFloat`.
    fn exact(w: WideFloat) -> BigRational {
        let (negative, m, e) = w.integer_parts();
        let two = BigRational::from_integer(Oracle::from(2));
        let p = num_traits::pow(two, e.unsigned_abs() as usize);
        let v = BigRational::from_integer(Oracle::from(m));
        let v = if e >= 0 { v * p } else { v / p };
        if negative {
            -v
        } else {
            v
        }
    }

    /// Whether `w` is within half a unit in its last place of `x`: the bound of a correctly
    /// rounded result (relative error at most 2^-53).
    fn within_half_ulp(w: WideFloat, x: &BigRational) -> bool {
        if x.is_zero() {
            return w.is_zero();
        }
        let err = (exact(w) - x).abs();
        // Half a unit in the last place of w: 2^(e − 1) for w = m · 2^e.
        let (_, m, e) = w.integer_parts();
        let two = BigRational::from_integer(Oracle::from(2));
        let half_ulp = if e >= 1 {
            num_traits::pow(two, (e - 1) as usize)
        } else {
            BigRational::from_integer(Oracle::from(1)) / num_traits::pow(two, (1 - e) as usize)
        };
        // At a power of two the step below is half as large; the bound above still holds.
        m >= 1 << 52 && err <= half_ulp
    }

    #[test]
    fn cancellation_leaves_the_exact_remainder() {
        let mut s = ExactSum::new();
        for v in [1e308, 1.0, -1e308] {
            s.add_f64(v);
        }
        assert_eq!(s.value(), WideFloat::from(1.0));
        let mut s = ExactSum::new();
        for v in [f64::MAX, f64::MAX, 5e-324, -f64::MAX, -f64::MAX] {
            s.add_f64(v);
        }
        assert_eq!(s.value().to_f64(), Some(5e-324));
        assert!(ExactSum::new().value().is_zero());
    }

    #[test]
    fn carries_survive_many_terms() {
        // Ten thousand terms at the top of the range carry into the chunks above them;
        // `propagate` is checked directly on a chunk near the i64 limit.
        let mut s = ExactSum::new();
        for _ in 0..10_000 {
            s.add_f64(f64::MAX);
        }
        let expected = q(f64::MAX) * BigRational::from_integer(Oracle::from(10_000));
        assert!(within_half_ulp(s.value(), &expected));
        let mut c = [0i64; CHUNKS];
        c[0] = i64::MAX;
        c[1] = -5;
        propagate(&mut c);
        assert!(c[..CHUNKS - 1].iter().all(|&v| (0..1 << 32).contains(&v)));
        let value = |c: &[i64; CHUNKS]| {
            c.iter()
                .enumerate()
                .map(|(i, &v)| Oracle::from(v) << (32 * i))
                .sum::<Oracle>()
        };
        assert_eq!(value(&c), Oracle::from(i64::MAX) - (Oracle::from(5) << 32));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        #[test]
        fn sums_of_doubles_are_correctly_rounded(values in prop::collection::vec(finite(), 0..12)) {
            let mut s = ExactSum::new();
            for &v in &values {
                s.add_f64(v);
            }
            let expected = values.iter().map(|&v| q(v)).fold(BigRational::zero(), |a, b| a + b);
            prop_assert!(within_half_ulp(s.value(), &expected), "{:?}", s.value());
        }

        #[test]
        fn sums_of_distances_are_correctly_rounded(
            coords in prop::collection::vec((finite(), finite(), finite(), finite()), 0..8),
        ) {
            let mut s = ExactSum::new();
            let mut expected = BigRational::zero();
            for &(ax, ay, bx, by) in &coords {
                let d = WideFloat::distance(Point2::new(ax, ay), Point2::new(bx, by));
                s.add(d);
                expected += exact(d);
            }
            prop_assert!(within_half_ulp(s.value(), &expected), "{:?}", s.value());
        }
    }
}
