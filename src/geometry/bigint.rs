//! A minimal signed big integer: just enough (add, subtract, multiply, sign) to evaluate a
//! predicate's polynomial exactly on the binary values of doubles of any magnitude.
//!
//! Only the slow path of the predicates uses it, for operand sets whose exponents span more
//! than the floating-point kernel can handle, so it favours plainness over speed (schoolbook
//! multiplication on 32-bit limbs).

use std::cmp::Ordering;

/// Sign and magnitude; `mag` is little-endian with no high zero limbs, and zero is never
/// negative.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct BigInt {
    negative: bool,
    mag: Vec<u32>,
}

impl BigInt {
    /// `(-1)^negative * mantissa * 2^shift`.
    pub(crate) fn from_parts(negative: bool, mantissa: u64, shift: u32) -> BigInt {
        let limb_shift = (shift / 32) as usize;
        let bit_shift = shift % 32;
        let mut mag = vec![0u32; limb_shift];
        // The mantissa has at most 64 bits, so the shifted value spans at most three limbs.
        let wide = (mantissa as u128) << bit_shift;
        mag.extend([wide as u32, (wide >> 32) as u32, (wide >> 64) as u32]);
        BigInt::normalized(negative, mag)
    }

    /// -1, 0 or 1.
    pub(crate) fn signum(&self) -> i32 {
        if self.mag.is_empty() {
            0
        } else if self.negative {
            -1
        } else {
            1
        }
    }

    /// The absolute value.
    pub(crate) fn abs(&self) -> BigInt {
        BigInt::normalized(false, self.mag.clone())
    }

    pub(crate) fn add(&self, other: &BigInt) -> BigInt {
        if self.negative == other.negative {
            return BigInt::normalized(self.negative, add_mag(&self.mag, &other.mag));
        }
        match cmp_mag(&self.mag, &other.mag) {
            Ordering::Equal => BigInt::normalized(false, Vec::new()),
            Ordering::Greater => BigInt::normalized(self.negative, sub_mag(&self.mag, &other.mag)),
            Ordering::Less => BigInt::normalized(other.negative, sub_mag(&other.mag, &self.mag)),
        }
    }

    pub(crate) fn sub(&self, other: &BigInt) -> BigInt {
        self.add(&other.negated())
    }

    pub(crate) fn mul(&self, other: &BigInt) -> BigInt {
        BigInt::normalized(
            self.negative != other.negative,
            mul_mag(&self.mag, &other.mag),
        )
    }

    /// `(negative, top, shift)` with `|self| ≈ top · 2^shift`: `top` holds the leading 64
    /// bits, exact when the magnitude has at most 64 bits; otherwise its lowest bit is also
    /// set when any discarded bit is (a sticky bit), so rounding `top` to fewer bits rounds
    /// the whole integer correctly.
    pub(crate) fn top_bits(&self) -> (bool, u64, i32) {
        let Some(&high) = self.mag.last() else {
            return (false, 0, 0);
        };
        let bits = self.mag.len() as u64 * 32 - u64::from(high.leading_zeros());
        if bits <= 64 {
            let low = self.mag.first().copied().unwrap_or(0) as u64;
            let top = low | (self.mag.get(1).copied().unwrap_or(0) as u64) << 32;
            return (self.negative, top, 0);
        }
        let shift = bits - 64;
        let bit = |i: u64| (self.mag[(i / 32) as usize] >> (i % 32)) & 1 == 1;
        let mut top = 0u64;
        for i in (shift..bits).rev() {
            top = top << 1 | u64::from(bit(i));
        }
        let whole_limbs = (shift / 32) as usize;
        let sticky = self.mag[..whole_limbs].iter().any(|&l| l != 0)
            || (shift % 32 != 0 && self.mag[whole_limbs] & ((1u32 << (shift % 32)) - 1) != 0);
        (self.negative, top | u64::from(sticky), shift as i32)
    }

    /// The decimal digits of the magnitude, most significant first (`[0]` for zero).
    pub(crate) fn decimal_digits(&self) -> Vec<u8> {
        const CHUNK: u64 = 1_000_000_000;
        let mut mag = self.mag.clone();
        let mut chunks = Vec::new();
        while !mag.is_empty() {
            // One long division by 10^9, most significant limb first.
            let mut rem = 0u64;
            for limb in mag.iter_mut().rev() {
                let cur = rem << 32 | u64::from(*limb);
                *limb = (cur / CHUNK) as u32;
                rem = cur % CHUNK;
            }
            while mag.last() == Some(&0) {
                mag.pop();
            }
            chunks.push(rem as u32);
        }
        let mut digits = Vec::new();
        for (i, chunk) in chunks.iter().rev().enumerate() {
            let text = if i == 0 {
                chunk.to_string()
            } else {
                format!("{chunk:09}")
            };
            digits.extend(text.bytes().map(|b| b - b'0'));
        }
        if digits.is_empty() {
            digits.push(0);
        }
        digits
    }

    fn negated(&self) -> BigInt {
        BigInt::normalized(!self.negative, self.mag.clone())
    }

    fn normalized(negative: bool, mut mag: Vec<u32>) -> BigInt {
        while mag.last() == Some(&0) {
            mag.pop();
        }
        BigInt {
            negative: negative && !mag.is_empty(),
            mag,
        }
    }
}

fn cmp_mag(a: &[u32], b: &[u32]) -> Ordering {
    a.len()
        .cmp(&b.len())
        .then_with(|| a.iter().rev().cmp(b.iter().rev()))
}

fn add_mag(a: &[u32], b: &[u32]) -> Vec<u32> {
    let (long, short) = if a.len() >= b.len() { (a, b) } else { (b, a) };
    let mut out = Vec::with_capacity(long.len() + 1);
    let mut carry = 0u64;
    for (i, &x) in long.iter().enumerate() {
        let sum = x as u64 + short.get(i).copied().unwrap_or(0) as u64 + carry;
        out.push(sum as u32);
        carry = sum >> 32;
    }
    out.push(carry as u32);
    out
}

/// `a - b` for `|a| >= |b|`.
fn sub_mag(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(a.len());
    let mut borrow = 0i64;
    for (i, &x) in a.iter().enumerate() {
        let mut diff = x as i64 - b.get(i).copied().unwrap_or(0) as i64 - borrow;
        borrow = 0;
        if diff < 0 {
            diff += 1 << 32;
            borrow = 1;
        }
        out.push(diff as u32);
    }
    out
}

fn mul_mag(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut out = vec![0u32; a.len() + b.len()];
    for (i, &x) in a.iter().enumerate() {
        let mut carry = 0u64;
        for (j, &y) in b.iter().enumerate() {
            let t = x as u64 * y as u64 + out[i + j] as u64 + carry;
            out[i + j] = t as u32;
            carry = t >> 32;
        }
        out[i + b.len()] = carry as u32;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::BigInt as Oracle;
    use proptest::prelude::*;

    fn oracle(x: &BigInt) -> Oracle {
        let sign = if x.negative {
            num_bigint::Sign::Minus
        } else {
            num_bigint::Sign::Plus
        };
        Oracle::from_slice(sign, &x.mag)
    }

    fn big(negative: bool, mantissa: u64, shift: u32) -> (BigInt, Oracle) {
        let ours = BigInt::from_parts(negative, mantissa, shift);
        let mut expected = Oracle::from(mantissa) << shift;
        if negative {
            expected = -expected;
        }
        (ours, expected)
    }

    proptest! {
        #[test]
        fn arithmetic_agrees_with_num_bigint(
            (na, ma, sa) in (any::<bool>(), any::<u64>(), 0u32..300),
            (nb, mb, sb) in (any::<bool>(), any::<u64>(), 0u32..300),
        ) {
            let (a, oa) = big(na, ma, sa);
            let (b, ob) = big(nb, mb, sb);
            prop_assert_eq!(oracle(&a), oa.clone());
            prop_assert_eq!(oracle(&a.add(&b)), &oa + &ob);
            prop_assert_eq!(oracle(&a.sub(&b)), &oa - &ob);
            prop_assert_eq!(oracle(&a.mul(&b)), &oa * &ob);
            let expected_sign = match (&oa - &ob).sign() {
                num_bigint::Sign::Minus => -1,
                num_bigint::Sign::NoSign => 0,
                num_bigint::Sign::Plus => 1,
            };
            prop_assert_eq!(a.sub(&b).signum(), expected_sign);
        }
    }

    proptest! {
        #[test]
        fn decimal_digits_and_top_bits_agree_with_num_bigint(
            m in any::<u64>(), shift in 0u32..700,
        ) {
            let (ours, expected) = big(false, m, shift);
            let text: String = ours.decimal_digits().iter().map(|d| char::from(b'0' + d)).collect();
            prop_assert_eq!(text, expected.to_string());
            let (_, top, s) = ours.top_bits();
            // top · 2^s brackets the value within one unit of top's last bit.
            let approx = Oracle::from(top) << s;
            let unit = Oracle::from(1u8) << s;
            prop_assert!(approx.clone() <= expected.clone() + &unit && expected <= approx + unit);
        }
    }

    #[test]
    fn equal_values_cancel_to_unsigned_zero() {
        let (a, _) = big(true, 12345, 70);
        let zero = a.sub(&a);
        assert_eq!(zero.signum(), 0);
        assert_eq!(zero, BigInt::from_parts(false, 0, 0));
    }
}
