//! Numbers beyond the range of `f64`: the lengths, areas and sums that overflow.
//!
//! Every input coordinate is a finite `f64`, but a value built from them need not be: the
//! distance between `(-f64::MAX, -f64::MAX)` and `(f64::MAX, f64::MAX)` is about `2.8 · 2^1024`,
//! and the area of a rectangle or the total weight of a spanning tree can be larger still.
//! [`WideFloat`] holds such a value with the precision of an `f64` and a wider exponent, so a
//! result is never a wrong finite number, an infinity or a NaN: it is either representable
//! ([`WideFloat::to_f64`] gives it) or it says that it is not and still gives its value.

use super::bigint::BigInt;
use super::extended::{exponent, scale_by_pow2};
use super::Point2;
use std::cmp::Ordering;
use std::fmt;

/// A finite real number `significand · 2^exponent`, with an `f64` significand in `[1, 2)`
/// (or zero) and an `i32` exponent: the precision of an `f64` over a range far beyond it.
///
/// The crate returns lengths, areas and sums as `WideFloat`, so a value larger than
/// `f64::MAX` keeps its magnitude instead of becoming infinite. [`to_f64`](Self::to_f64) gives
/// the `f64` (rounded once) or `None` when the value exceeds `f64::MAX`; [`Display`](fmt::Display)
/// prints an `f64`'s own text when it fits and the decimal value otherwise; with the `serde`
/// feature a `WideFloat` serialises as a JSON number when it fits and as a decimal string
/// (`"2.8284271247461901e308"`) when it does not, the rule the command line prints by.
///
/// ```
/// use compgeo::geometry::{Point2, WideFloat};
///
/// let far = WideFloat::distance(
///     Point2::new(-f64::MAX, -f64::MAX),
///     Point2::new(f64::MAX, f64::MAX),
/// );
/// assert_eq!(far.to_f64(), None);
/// assert_eq!(far.to_string(), "5.0846440246145847e308");
///
/// let near = WideFloat::distance(Point2::new(0.0, 0.0), Point2::new(3.0, 4.0));
/// assert_eq!(near.to_f64(), Some(5.0));
/// assert_eq!(near.to_string(), "5");
/// ```
#[derive(Clone, Copy, Debug)]
pub struct WideFloat {
    /// Zero (positive), or `1 <= |significand| < 2`.
    significand: f64,
    /// Zero for zero.
    exponent: i32,
}

impl WideFloat {
    /// Zero.
    pub const ZERO: WideFloat = WideFloat {
        significand: 0.0,
        exponent: 0,
    };

    /// The value of a finite `f64` (exactly), or `None` for NaN and infinities.
    pub fn from_f64(v: f64) -> Option<WideFloat> {
        v.is_finite().then(|| WideFloat::scaled(v, 0))
    }

    /// `v · 2^shift` for finite `v`, exactly (the exponent saturates at the `i32` range).
    pub(crate) fn scaled(v: f64, shift: i32) -> WideFloat {
        debug_assert!(v.is_finite());
        if v == 0.0 {
            return WideFloat::ZERO;
        }
        let e = exponent(v);
        WideFloat {
            significand: scale_by_pow2(v, -e),
            exponent: e.saturating_add(shift),
        }
    }

    /// The value as an `f64`, rounded once to nearest (to a subnormal or zero below the normal
    /// range), or `None` if its magnitude exceeds `f64::MAX`.
    pub fn to_f64(self) -> Option<f64> {
        if self.exponent > 1023 {
            return None;
        }
        Some(scale_by_pow2(self.significand, self.exponent.max(-1100)))
    }

    /// `(significand, exponent)` with `self = significand · 2^exponent` exactly: the
    /// significand is zero or in `[1, 2)` in magnitude, with the value's sign (the exponent
    /// is 0 for zero). The exact value for callers that need it, e.g. in rational arithmetic.
    ///
    /// ```
    /// use compgeo::geometry::WideFloat;
    ///
    /// assert_eq!(WideFloat::from(-6.0).to_parts(), (-1.5, 2));
    /// let big = WideFloat::from(f64::MAX).mul(WideFloat::from(4.0));
    /// assert_eq!(big.to_parts(), (2.0 - f64::EPSILON, 1025));
    /// ```
    pub fn to_parts(self) -> (f64, i32) {
        (self.significand, self.exponent)
    }

    /// The value as an `f64`, saturating at `±f64::MAX` instead of giving `None`.
    pub fn to_f64_saturating(self) -> f64 {
        self.to_f64().unwrap_or(f64::MAX.copysign(self.significand))
    }

    /// `a − b` for finite `a` and `b`, rounded once (correctly): a difference that
    /// overflows `f64` is formed from the halves, which are exact there.
    ///
    /// ```
    /// use compgeo::geometry::WideFloat;
    ///
    /// assert_eq!(WideFloat::difference(3.0, -1.5), 4.5);
    /// let span = WideFloat::difference(f64::MAX, -f64::MAX);
    /// assert_eq!(span.to_f64(), None);
    /// assert_eq!(span.to_string(), "3.5953862697246314e308");
    /// ```
    ///
    /// # Complexity
    /// O(1).
    pub fn difference(a: f64, b: f64) -> WideFloat {
        debug_assert!(a.is_finite() && b.is_finite());
        let d = a - b;
        if d.is_finite() {
            WideFloat::scaled(d, 0)
        } else {
            // |a − b| > f64::MAX needs both magnitudes above 2^970: halving them is exact.
            WideFloat::scaled(a / 2.0 - b / 2.0, 1)
        }
    }

    /// `self · 2^shift`, exactly (the exponent saturates at the `i32` range).
    pub(crate) fn scale_pow2(self, shift: i32) -> WideFloat {
        if self.is_zero() {
            return self;
        }
        WideFloat {
            exponent: self.exponent.saturating_add(shift),
            ..self
        }
    }

    /// `(negative, m, e)` with `self = ±m · 2^e` and `m < 2^53` an integer (zero for zero):
    /// the significand's bits as an integer and the weight of its last bit.
    pub(super) fn integer_parts(self) -> (bool, u64, i32) {
        if self.is_zero() {
            return (false, 0, 0);
        }
        // The significand has 53 bits, the first at 2^0: scaling by 2^52 makes it an
        // integer, exactly.
        let m = scale_by_pow2(self.significand.abs(), 52) as u64;
        (self.is_negative(), m, self.exponent.saturating_sub(52))
    }

    /// Whether the value is zero.
    pub fn is_zero(self) -> bool {
        self.significand == 0.0
    }

    /// Whether the value is below zero.
    pub fn is_negative(self) -> bool {
        self.significand < 0.0
    }

    /// The absolute value.
    pub fn abs(self) -> WideFloat {
        WideFloat {
            significand: self.significand.abs(),
            ..self
        }
    }

    /// `self · other`, rounded once.
    #[allow(clippy::should_implement_trait)]
    pub fn mul(self, other: WideFloat) -> WideFloat {
        if self.is_zero() || other.is_zero() {
            return WideFloat::ZERO;
        }
        // Both significands are below 2 in magnitude, so the product is below 4: no overflow.
        WideFloat::scaled(
            self.significand * other.significand,
            self.exponent.saturating_add(other.exponent),
        )
    }

    /// `self / other` for nonzero `other`, rounded once; `None` if `other` is zero.
    pub fn checked_div(self, other: WideFloat) -> Option<WideFloat> {
        if other.is_zero() {
            return None;
        }
        if self.is_zero() {
            return Some(WideFloat::ZERO);
        }
        Some(WideFloat::scaled(
            self.significand / other.significand,
            self.exponent.saturating_sub(other.exponent),
        ))
    }

    /// `self + other`, rounded once (to within an ulp: the smaller operand is aligned to the
    /// larger one's exponent first, exactly unless it falls more than 1074 binades below).
    #[allow(clippy::should_implement_trait)]
    pub fn add(self, other: WideFloat) -> WideFloat {
        if self.is_zero() {
            return other;
        }
        if other.is_zero() {
            return self;
        }
        let top = self.exponent.max(other.exponent);
        let align = |w: WideFloat| {
            let shift = i64::from(w.exponent) - i64::from(top);
            // Below 2^-1100 relative, the operand no longer changes the rounded sum.
            scale_by_pow2(w.significand, shift.max(-1100) as i32)
        };
        // Each aligned term is below 2 in magnitude: the sum cannot overflow.
        WideFloat::scaled(align(self) + align(other), top)
    }

    /// The square root of a non-negative value, rounded once; `None` for a negative one.
    pub fn sqrt(self) -> Option<WideFloat> {
        if self.is_negative() {
            return None;
        }
        if self.is_zero() {
            return Some(WideFloat::ZERO);
        }
        // Make the exponent even (`div_euclid` also rounds negative odd ones down).
        let odd = self.exponent.rem_euclid(2);
        let significand = self.significand * if odd == 1 { 2.0 } else { 1.0 };
        Some(WideFloat::scaled(
            significand.sqrt(),
            (self.exponent - odd).div_euclid(2),
        ))
    }

    /// The Euclidean distance `|ab|` between two finite points, with relative error below
    /// 2^-51 (two units of 2^-52) for every pair: the differences are rounded once (halved
    /// first when they would overflow) and scaled by a power of two before `hypot`.
    ///
    /// # Complexity
    /// O(1).
    pub fn distance(a: Point2, b: Point2) -> WideFloat {
        let (mut dx, mut dy) = (b.x - a.x, b.y - a.y);
        let mut shift = 0;
        if !(dx.is_finite() && dy.is_finite()) {
            // Both coordinates are at least 2^1022 in magnitude here, so halving is exact.
            (dx, dy) = (b.x / 2.0 - a.x / 2.0, b.y / 2.0 - a.y / 2.0);
            shift = 1;
        }
        let m = dx.abs().max(dy.abs());
        if m == 0.0 {
            return WideFloat::ZERO;
        }
        let e = exponent(m);
        let h = scale_by_pow2(dx, -e).hypot(scale_by_pow2(dy, -e));
        WideFloat::scaled(h, e + shift)
    }

    /// The correctly rounded value of a big integer.
    pub(crate) fn from_big(v: &BigInt) -> WideFloat {
        let (negative, top, shift) = v.top_bits();
        if top == 0 {
            return WideFloat::ZERO;
        }
        // `top` has its lowest bit set if any discarded bit was (a sticky bit), so the one
        // rounding of u64 -> f64 is the correct rounding of the whole integer.
        let m = top as f64;
        WideFloat::scaled(if negative { -m } else { m }, shift)
    }

    /// The value's decimal text with 17 significant digits, from its exact binary value: used
    /// for values beyond `f64`, which an `f64`'s shortest text cannot give.
    ///
    /// The exact conversion costs time quadratic in the exponent, so beyond 2^16384 (values
    /// the crate's results never reach; only chained arithmetic does) the digits come from
    /// a fixed-point logarithm instead: 16 significant digits, the last one within a unit.
    fn exact_decimal(self) -> String {
        let sign = if self.is_negative() { "-" } else { "" };
        if self.exponent > EXACT_DECIMAL_MAX_EXPONENT {
            let (digits, decimal_exponent) = self.logarithmic_digits();
            return format!("{sign}{}.{}e{decimal_exponent}", &digits[..1], &digits[1..]);
        }
        // significand · 2^exponent = m · 2^(exponent − 52) with a 53-bit integer m; values
        // beyond f64 have exponent > 1023, so this is an integer.
        let m = scale_by_pow2(self.significand.abs(), 52) as u64;
        let shift = self.exponent - 52;
        debug_assert!(shift > 0);
        let digits = BigInt::from_parts(false, m, shift as u32).decimal_digits();
        let (mantissa, decimal_exponent) = round_digits(&digits, 17);
        format!(
            "{sign}{}.{}e{decimal_exponent}",
            &mantissa[..1],
            &mantissa[1..]
        )
    }
}

/// Beyond `2^EXACT_DECIMAL_MAX_EXPONENT` the decimal text is computed from logarithms.
const EXACT_DECIMAL_MAX_EXPONENT: i32 = 16384;

impl WideFloat {
    /// 16 significant decimal digits and the decimal exponent of a large positive exponent's
    /// value, from `log10(2)` in 96-bit fixed point (so `exponent · log10(2)` keeps its
    /// fraction to about 2^-64 for every `i32` exponent).
    fn logarithmic_digits(self) -> (String, i64) {
        const LOG10_2_FIXED: i128 = 23_850_053_418_134_191_015_272_426_710; // log10(2) · 2^96
        let scaled = i128::from(self.exponent) * LOG10_2_FIXED;
        let whole = scaled >> 96;
        let fraction = (scaled & ((1i128 << 96) - 1)) as f64 / 2f64.powi(96);
        let log = fraction + self.significand.abs().log10();
        let (mut carry, mut frac) = (log.floor() as i64, log - log.floor());
        let mut lead = 10f64.powf(frac);
        if lead >= 9.999_999_999_999_999 {
            (carry, frac) = (carry + 1, 0.0);
            lead = 10f64.powf(frac);
        }
        let digits = format!("{:.15}", lead).replace('.', "");
        (digits[..16].to_string(), whole as i64 + carry)
    }
}

/// The first `keep` digits of `digits` (most significant first, no leading zero), rounded to
/// nearest with ties to even, and the decimal exponent of the first digit.
fn round_digits(digits: &[u8], keep: usize) -> (String, usize) {
    let mut exponent = digits.len() - 1;
    let mut kept: Vec<u8> = digits.iter().take(keep).copied().collect();
    if digits.len() > keep {
        let next = digits[keep];
        let rest_nonzero = digits[keep + 1..].iter().any(|&d| d != 0);
        let odd = kept.last().is_some_and(|d| d % 2 == 1);
        if next > 5 || (next == 5 && (rest_nonzero || odd)) {
            let mut i = kept.len();
            loop {
                if i == 0 {
                    // 99..9 rounded up: one more digit in front.
                    kept.insert(0, 1);
                    kept.pop();
                    exponent += 1;
                    break;
                }
                i -= 1;
                if kept[i] == 9 {
                    kept[i] = 0;
                } else {
                    kept[i] += 1;
                    break;
                }
            }
        }
    }
    while kept.len() < keep {
        kept.push(0);
    }
    (
        kept.iter().map(|d| char::from(b'0' + d)).collect(),
        exponent,
    )
}

impl From<f64> for WideFloat {
    /// The value of a finite `f64`.
    ///
    /// # Panics
    /// In debug builds, if `v` is not finite (release builds treat it as unspecified input
    /// and give some finite value); use [`WideFloat::from_f64`] for untrusted values.
    fn from(v: f64) -> WideFloat {
        if v.is_finite() {
            WideFloat::scaled(v, 0)
        } else {
            debug_assert!(false, "WideFloat from a non-finite f64 ({v})");
            WideFloat::ZERO
        }
    }
}

impl PartialEq for WideFloat {
    fn eq(&self, other: &WideFloat) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for WideFloat {}

impl PartialOrd for WideFloat {
    fn partial_cmp(&self, other: &WideFloat) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for WideFloat {
    fn cmp(&self, other: &WideFloat) -> Ordering {
        let sign = |w: &WideFloat| {
            if w.is_zero() {
                0
            } else if w.is_negative() {
                -1
            } else {
                1
            }
        };
        let by_sign = sign(self).cmp(&sign(other));
        if by_sign != Ordering::Equal || self.is_zero() {
            return by_sign;
        }
        // Same nonzero sign: compare magnitudes, then flip for negatives.
        let magnitude = self
            .exponent
            .cmp(&other.exponent)
            .then_with(|| self.significand.abs().total_cmp(&other.significand.abs()));
        if self.is_negative() {
            magnitude.reverse()
        } else {
            magnitude
        }
    }
}

impl Default for WideFloat {
    /// Zero.
    fn default() -> WideFloat {
        WideFloat::ZERO
    }
}

/// Exact comparison with an `f64`: equal when the values are (NaN equals nothing, an
/// infinity no `WideFloat`).
impl PartialEq<f64> for WideFloat {
    fn eq(&self, other: &f64) -> bool {
        WideFloat::from_f64(*other).is_some_and(|o| *self == o)
    }
}

/// Exact order against an `f64`: every `WideFloat` lies strictly between `-inf` and `inf`;
/// NaN is unordered.
impl PartialOrd<f64> for WideFloat {
    fn partial_cmp(&self, other: &f64) -> Option<Ordering> {
        match WideFloat::from_f64(*other) {
            Some(o) => Some(self.cmp(&o)),
            None if other.is_nan() => None,
            None if *other > 0.0 => Some(Ordering::Less),
            None => Some(Ordering::Greater),
        }
    }
}

impl fmt::Display for WideFloat {
    /// An `f64`'s own text when the value fits (`5`, `0.1`, `1e300`), else its decimal value
    /// with 17 significant digits (`2.8284271247461901e308`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.to_f64() {
            Some(v) if v.abs() >= 1e16 || (v != 0.0 && v.abs() < 1e-5) => write!(f, "{v:e}"),
            Some(v) => write!(f, "{v}"),
            None => f.write_str(&self.exact_decimal()),
        }
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for WideFloat {
    /// A JSON number when the value fits in `f64`, else its decimal text as a string.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self.to_f64() {
            Some(v) => serializer.serialize_f64(v),
            None => serializer.serialize_str(&self.exact_decimal()),
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use num_bigint::BigInt as Oracle;
    use num_rational::BigRational;
    use num_traits::{One, Signed, Zero};
    use proptest::prelude::*;

    /// The exact value of a `WideFloat`.
    fn exact(w: WideFloat) -> BigRational {
        if w.is_zero() {
            return BigRational::zero();
        }
        let m = BigRational::from_float(w.significand).unwrap();
        let two = BigRational::from_integer(Oracle::from(2));
        let p = num_traits::pow(two, w.exponent.unsigned_abs() as usize);
        if w.exponent >= 0 {
            m * p
        } else {
            m / p
        }
    }

    fn q(v: f64) -> BigRational {
        BigRational::from_float(v).unwrap()
    }

    /// |approx − exact| ≤ ulps · 2^-52 · |exact|.
    fn within(approx: WideFloat, expected: &BigRational, ulps: i64) -> bool {
        let err = (exact(approx) - expected).abs();
        let bound = expected.abs() * BigRational::new(Oracle::from(ulps), Oracle::one() << 52);
        err <= bound
    }

    /// Any finite double, with the extremes and small values drawn often.
    pub(in crate::geometry) fn finite() -> impl Strategy<Value = f64> {
        prop_oneof![
            any::<f64>().prop_filter("finite", |v| v.is_finite()),
            -1e3f64..1e3,
            Just(f64::MAX),
            Just(-f64::MAX),
            Just(5e-324),
            Just(-5e-324),
        ]
    }

    #[test]
    fn values_in_range_round_trip_and_print_as_f64() {
        for v in [0.0, 1.0, -2.5, 0.1, 1e300, -1e-300, 5e-324, f64::MAX] {
            let w = WideFloat::from(v);
            assert_eq!(w.to_f64(), Some(v));
            assert_eq!(w.to_f64().unwrap().to_bits(), v.to_bits(), "{v:e}");
        }
        assert_eq!(WideFloat::from(-0.0).to_f64().unwrap().to_bits(), 0);
        assert_eq!(WideFloat::from(0.1).to_string(), "0.1");
        assert_eq!(WideFloat::from(1e300).to_string(), "1e300");
        assert_eq!(WideFloat::from_f64(f64::NAN), None);
        assert_eq!(WideFloat::from_f64(f64::INFINITY), None);
    }

    #[test]
    fn twice_the_largest_double_is_beyond_f64_and_prints_exactly() {
        let two_max = WideFloat::from(f64::MAX).add(WideFloat::from(f64::MAX));
        assert_eq!(two_max.to_f64(), None);
        assert_eq!(two_max.to_f64_saturating(), f64::MAX);
        // 2 · (2 − 2^-52) · 2^1023 = 359538626972463141629054847463408713596141135051689993197834953606314521560057077521179117265533756343080917907028764928468642653778928365536935093407075033972099821153102564152490980180778657888151737016910267884609166473806445896331617118664246696549595652408289446337476354361838599762500808052368249716736
        assert_eq!(two_max.to_string(), "3.5953862697246314e308");
        assert_eq!(two_max.abs(), two_max);
        assert!(WideFloat::ZERO
            .add(two_max)
            .sub_for_tests(two_max)
            .is_zero());
    }

    #[test]
    fn huge_exponents_print_fast_from_logarithms() {
        // 2^16385 and 2^(2^31 - 1): the exact conversion would take seconds to hours.
        let at = |e: i32| WideFloat::scaled(1.0, e).to_string();
        // 2^16385 = 2.3794629907144635…e4932.
        assert!(at(16385).starts_with("2.37946299071446"), "{}", at(16385));
        assert!(at(16385).ends_with("e4932"), "{}", at(16385));
        // 2^(2^31 − 1) = 8.8080652584198167…e646456992.
        assert!(
            at(i32::MAX).starts_with("8.80806525841"),
            "{}",
            at(i32::MAX)
        );
        assert!(at(i32::MAX).ends_with("e646456992"), "{}", at(i32::MAX));
        // Just below the threshold the exact path agrees in its first 15 digits.
        let exact = WideFloat::scaled(1.5, EXACT_DECIMAL_MAX_EXPONENT).to_string();
        let (digits, e) = WideFloat::scaled(1.5, EXACT_DECIMAL_MAX_EXPONENT).logarithmic_digits();
        assert_eq!(
            exact[..16].replace('.', ""),
            digits[..15],
            "{exact} vs {digits}"
        );
        assert!(exact.ends_with(&format!("e{e}")), "{exact} vs {e}");
    }

    #[test]
    fn ties_round_to_even_and_carries_add_a_digit() {
        let digits = |s: &str| s.bytes().map(|b| b - b'0').collect::<Vec<u8>>();
        assert_eq!(round_digits(&digits("125"), 2), ("12".to_string(), 2));
        assert_eq!(round_digits(&digits("135"), 2), ("14".to_string(), 2));
        assert_eq!(round_digits(&digits("1251"), 2), ("13".to_string(), 3));
        assert_eq!(round_digits(&digits("996"), 2), ("10".to_string(), 3));
        assert_eq!(round_digits(&digits("7"), 3), ("700".to_string(), 0));
    }

    #[test]
    fn order_is_by_value() {
        let big = WideFloat::from(f64::MAX).mul(WideFloat::from(4.0));
        let values = [
            big.mul(WideFloat::from(-1.0)),
            WideFloat::from(-1.0),
            WideFloat::ZERO,
            WideFloat::from(5e-324),
            WideFloat::from(1.0),
            WideFloat::from(f64::MAX),
            big,
        ];
        for (i, a) in values.iter().enumerate() {
            for (j, b) in values.iter().enumerate() {
                assert_eq!(a.cmp(b), i.cmp(&j), "{a:?} vs {b:?}");
            }
        }
    }

    impl WideFloat {
        fn sub_for_tests(self, other: WideFloat) -> WideFloat {
            self.add(other.mul(WideFloat::from(-1.0)))
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        #[test]
        fn arithmetic_is_within_an_ulp_of_the_exact_value(a in finite(), b in finite(), c in finite()) {
            let (wa, wb, wc) = (WideFloat::from(a), WideFloat::from(b), WideFloat::from(c));
            // Products of three doubles reach 2^3072 and 2^-3222: far beyond f64.
            let product = wa.mul(wb).mul(wc);
            prop_assert!(within(product, &(q(a) * q(b) * q(c)), 2));
            let sum = wa.mul(wb).add(wc);
            let exact_sum = q(a) * q(b) + q(c);
            // The sum rounds the product first; relative to the terms, not the sum.
            let scale = (q(a) * q(b)).abs() + q(c).abs();
            let err = (exact(sum) - &exact_sum).abs();
            prop_assert!(err <= scale * BigRational::new(Oracle::from(2), Oracle::one() << 52));
            if !b.is_nan() && b != 0.0 {
                let quotient = wa.checked_div(wb).unwrap();
                prop_assert!(within(quotient, &(q(a) / q(b)), 1));
            }
            let square = wa.mul(wa);
            let root = square.sqrt().unwrap();
            prop_assert!(within(root, &q(a.abs()), 2));
            prop_assert_eq!(product.cmp(&WideFloat::ZERO), (q(a) * q(b) * q(c)).cmp(&BigRational::zero()));
        }

        #[test]
        fn distance_squares_to_the_exact_squared_distance(
            ax in finite(), ay in finite(), bx in finite(), by in finite(),
        ) {
            let d = WideFloat::distance(Point2::new(ax, ay), Point2::new(bx, by));
            let (dx, dy) = (q(bx) - q(ax), q(by) - q(ay));
            let squared = &dx * &dx + &dy * &dy;
            // |d|² within 5 ulps of the exact squared distance: d within about 2.5 ulps.
            prop_assert!(within(d.mul(d), &squared, 5), "{:?}", d);
        }

        #[test]
        fn big_integers_round_correctly(negative in any::<bool>(), m in any::<u64>(), shift in 0u32..1200) {
            let v = BigInt::from_parts(negative, m, shift);
            let w = WideFloat::from_big(&v);
            let mut expected = BigRational::from_integer(Oracle::from(m) << shift);
            if negative { expected = -expected; }
            prop_assert!(within(w, &expected, 1));
        }
    }
}
