//! Reading numbers from text into a [`Scalar`]: integers, decimals with an exponent and
//! fractions, exactly for rationals (the command line's `--exact` relies on it).
//!
//! The bound on exact reading, which keeps every value small and every parse linear in the
//! text, is documented on [`parse_scalar`] ("Bounded parsing").

use super::scalar::Scalar;
use crate::util::quote;
use crate::{Error, Result};

/// The most significant digits (leading and trailing zeros not counted) of a decimal read
/// exactly; see [Bounded parsing](parse_scalar#bounded-parsing).
pub const MAX_EXACT_DIGITS: usize = 1000;

/// A decimal read exactly is zero or has a magnitude of at least 10^−`MAX_EXACT_EXPONENT`
/// and below 10^`MAX_EXACT_EXPONENT`; see [Bounded parsing](parse_scalar#bounded-parsing).
pub const MAX_EXACT_EXPONENT: i32 = 400;

/// Parses a number written as an integer (`-3`), a decimal with an optional exponent
/// (`2.5`, `1e-3`, `-0.125E2`) or a fraction of two such numbers (`47/18`, `1.5/4`) into the
/// scalar `S`.
///
/// For `BigRational` the result is the exact value written (`0.1` is 1/10, not the double
/// nearest to it); for `f64` a plain decimal is rounded as IEEE 754 rounds it and a fraction
/// is the double nearest to its exact value (rounded once with feature `exact`, else each
/// part rounded and then divided). Exact reading is bounded, and parsing takes time linear in
/// the text: see below.
///
/// # Bounded parsing
///
/// Reading a decimal exactly builds the rational it writes, and `1e-9223372036854775808`
/// writes a denominator of 10^(2^63): no text may ask for a value that size. A decimal read
/// exactly (every number for `BigRational`; the numerator and the denominator of a fraction
/// `p/q` for either scalar) is therefore zero or has
///
/// - at most [`MAX_EXACT_DIGITS`] = 1000 significant digits, not counting leading and trailing
///   zeros (the exponent absorbs them: `1000e-3` is 1, `0.000125` has three), and
/// - a magnitude of at least 1e−400 and below 1e400 ([`MAX_EXACT_EXPONENT`] = 400);
///
/// other decimals are rejected, with an error naming the bound they break, before any big
/// integer is built. Every finite `f64` fits: its exact decimal expansion has at most 767
/// significant digits and a magnitude between 4.9·10^−324 and 1.8·10^308, so an exact reader
/// takes back any double written out in full. Within the bound a decimal's numerator and
/// denominator are below 10^1400 (4651 bits), a fraction's below 10^2400 (7973 bits).
///
/// `f64` reads a plain decimal (no `/`) as IEEE 754 does: correctly rounded, with no bound on
/// digits or exponent, so a huge negative exponent gives 0 or a subnormal (`1e-400` is 0) and
/// a huge positive one infinity, which is rejected as outside the range of `f64`. A fraction
/// is read exactly and rounded once, so its two parts obey the exact bound (without feature
/// `exact` each part is rounded and then divided, two roundings).
///
/// The two scalars therefore accept the same plain decimals, except that beyond 1000
/// significant digits or below 1e−400 in magnitude `f64` rounds where `BigRational` refuses.
/// Both refuse values beyond the range of `f64` (`1e309`): exact values are kept within it so
/// that a command takes the same inputs with and without `--exact`.
///
/// Every parse is linear in the length of the text: the digits are scanned once, leading and
/// trailing zeros are counted rather than stored, the exponent is read saturating, and the
/// bound is checked before the (at most 1000-digit) integer is built.
///
/// # Errors
///
/// [`Error::InvalidParameter`] naming `name` if the text is not such a number, the
/// denominator is zero, the value is not finite as an `f64` (`1e400`), or a decimal read
/// exactly breaks the bound; the reason quotes the text (cut to 40 characters, control
/// characters escaped).
///
/// ```
/// use compgeo::spline::parse_scalar;
/// use num_rational::BigRational;
///
/// assert_eq!(parse_scalar::<f64>("3/4", "t").unwrap(), 0.75);
/// assert_eq!(parse_scalar::<f64>("1e-400", "t").unwrap(), 0.0);
/// assert!(parse_scalar::<BigRational>("1e-400", "t").is_ok());
/// assert!(parse_scalar::<BigRational>("1e-401", "t").is_err());
/// assert!(parse_scalar::<f64>("1/0", "t").is_err());
/// assert!(parse_scalar::<f64>("nan", "t").is_err());
/// ```
pub fn parse_scalar<S: Scalar + ParseScalar>(text: &str, name: &'static str) -> Result<S> {
    read_scalar(text).map_err(|reason| Error::InvalidParameter { name, reason })
}

/// [`parse_scalar`] without the name, for callers that name the value themselves (the
/// command line's "control point 2, coordinate 1"): the value, or why the text is not one,
/// ending with the quoted text.
pub(crate) fn read_scalar<S: ParseScalar>(text: &str) -> std::result::Result<S, String> {
    S::parse_scalar(text.trim()).map_err(|reason| format!("{reason} (got {})", quote(text)))
}

/// How a [`Scalar`] reads itself from text; see [`parse_scalar`].
pub trait ParseScalar: Sized {
    /// Reads the value, or says why the text is not a valid finite number.
    fn parse_scalar(text: &str) -> std::result::Result<Self, String>;
}

const OUT_OF_RANGE: &str = "the number is outside the range of f64";

impl ParseScalar for f64 {
    fn parse_scalar(text: &str) -> std::result::Result<Self, String> {
        let (num, den) = split_fraction(text)?;
        let x = match den {
            None => parse_plain_f64(num)?,
            Some(d) => fraction_f64(num, d)?,
        };
        if x.is_finite() {
            Ok(x)
        } else {
            Err(OUT_OF_RANGE.to_string())
        }
    }
}

/// `n/d` exactly, rounded once.
#[cfg(feature = "exact")]
fn fraction_f64(n: &str, d: &str) -> std::result::Result<f64, String> {
    Ok(Scalar::to_f64(&exact_fraction(n, d)?))
}

/// `n/d` with each part rounded, then divided.
#[cfg(not(feature = "exact"))]
fn fraction_f64(n: &str, d: &str) -> std::result::Result<f64, String> {
    let n = parse_plain_f64(n)?;
    if Decimal::scan(d)?.digits == 0 {
        return Err("the denominator is zero".to_string());
    }
    let d = parse_plain_f64(d)?;
    if d == 0.0 {
        return Err("the denominator rounds to 0 as an f64".to_string());
    }
    Ok(n / d)
}

#[cfg(feature = "exact")]
impl ParseScalar for num_rational::BigRational {
    fn parse_scalar(text: &str) -> std::result::Result<Self, String> {
        let (num, den) = split_fraction(text)?;
        let value = match den {
            None => Decimal::scan(num)?.exact()?,
            Some(d) => exact_fraction(num, d)?,
        };
        if Scalar::to_f64(&value).is_finite() {
            Ok(value)
        } else {
            Err(OUT_OF_RANGE.to_string())
        }
    }
}

#[cfg(feature = "exact")]
fn exact_fraction(n: &str, d: &str) -> std::result::Result<num_rational::BigRational, String> {
    let n = Decimal::scan(n)?.exact()?;
    let d = Decimal::scan(d)?.exact()?;
    if Scalar::is_zero(&d) {
        return Err("the denominator is zero".to_string());
    }
    Ok(n / d)
}

fn split_fraction(text: &str) -> std::result::Result<(&str, Option<&str>), String> {
    if text.is_empty() {
        return Err("expected a number".to_string());
    }
    match text.split_once('/') {
        None => Ok((text, None)),
        Some((n, d)) if !d.contains('/') => Ok((n.trim(), Some(d.trim()))),
        Some(_) => Err("a fraction has one '/'".to_string()),
    }
}

/// A plain decimal as IEEE 754 rounds it; `inf`, `nan` and hexadecimal do not pass.
fn parse_plain_f64(text: &str) -> std::result::Result<f64, String> {
    Ok(Decimal::scan(text)?.to_f64())
}

/// A decimal `[+-]digits[.digits][(e|E)[+-]digits]` rounded to the nearest `f64` (ties to
/// even), at any length and exponent, in time linear in the text; ±∞ beyond the range, `None`
/// if the text is not such a decimal. The readers of points, numbers and arguments use it
/// rather than `str::parse`, which loses track of an exponent of more than six digits
/// (`0.000…0001e1000001` with a million zeros is 1, and `str::parse` gives 0).
#[cfg_attr(not(feature = "cli"), allow(dead_code))]
pub(crate) fn parse_f64(text: &str) -> Option<f64> {
    Decimal::scan(text).ok().map(|d| d.to_f64())
}

/// [`parse_f64`], or for the words Rust's `f64::from_str` also takes (`inf`, `infinity`,
/// `nan` in any letter case, signed) their value, so that the caller can name a non-finite
/// value instead of reporting a syntax error.
#[cfg_attr(not(feature = "cli"), allow(dead_code))]
pub(crate) fn parse_f64_or_word(text: &str) -> Option<f64> {
    let word = text.strip_prefix(['+', '-']).unwrap_or(text);
    if word.bytes().all(|b| b.is_ascii_alphabetic()) {
        text.parse().ok()
    } else {
        parse_f64(text)
    }
}

/// Significant digits kept when rounding to `f64`: more than the 768 that a midpoint between
/// two doubles can have, so cutting the rest (and leaving a nonzero digit after the cut,
/// below) never moves a value across a midpoint.
const F64_DIGITS: usize = 800;

/// A decimal `[+-]digits[.digits][(e|E)[+-]digits]` (at least one mantissa digit), taken
/// apart without building its value: `±D·10^shift`, where `D` is the integer of the
/// significant digits (leading and trailing zeros stripped).
#[derive(Debug, PartialEq)]
#[cfg_attr(not(feature = "exact"), allow(dead_code))]
struct Decimal<'a> {
    negative: bool,
    /// The mantissa from its first to its last nonzero digit (it may hold the `.`); empty
    /// for zero.
    significant: &'a str,
    /// How many digits `significant` holds.
    digits: usize,
    /// The power of ten that scales `D`. An `i128` holds any exponent text: the exponent is
    /// read saturating at `i64` and the mantissa is shorter than `2^64`.
    shift: i128,
}

impl<'a> Decimal<'a> {
    /// Checks the syntax and finds the parts, in one pass over the text.
    fn scan(text: &'a str) -> std::result::Result<Self, String> {
        let bad = || "expected an integer, a decimal or a fraction p/q".to_string();
        let negative = text.starts_with('-');
        let s = text.strip_prefix(['+', '-']).unwrap_or(text);
        let (mantissa, exponent) = match s.find(['e', 'E']) {
            Some(i) => (&s[..i], Some(&s[i + 1..])),
            None => (s, None),
        };
        let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let digits = |d: &str| d.bytes().all(|b| b.is_ascii_digit());
        if int.len() + frac.len() == 0 || !digits(int) || !digits(frac) {
            return Err(bad());
        }
        let exponent: i64 = match exponent {
            None => 0,
            Some(e) => {
                let (sign, e) = match e.strip_prefix('-') {
                    Some(rest) => (-1, rest),
                    None => (1, e.strip_prefix('+').unwrap_or(e)),
                };
                if e.is_empty() || !digits(e) {
                    return Err(bad());
                }
                // Saturating: anything near i64::MAX is far beyond every bound anyway.
                sign * e.bytes().fold(0i64, |acc, b| {
                    acc.saturating_mul(10).saturating_add(i64::from(b - b'0'))
                })
            }
        };
        let nonzero = |b: &u8| *b != b'0' && *b != b'.';
        let Some(first) = mantissa.bytes().position(|b| nonzero(&b)) else {
            return Ok(Decimal {
                negative,
                significant: "",
                digits: 0,
                shift: 0,
            });
        };
        let last = mantissa.bytes().rposition(|b| nonzero(&b)).unwrap_or(first);
        let significant = &mantissa[first..=last];
        let has_dot = significant.contains('.');
        // The zero digits after the last significant one (the dot, if it comes after
        // that digit, is not one of them); they move into the shift.
        let dot_after = mantissa.len() > int.len() && int.len() > last;
        let trailing = mantissa.len() - 1 - last - usize::from(dot_after);
        let shift = i128::from(exponent) - frac.len() as i128 + trailing as i128;
        Ok(Decimal {
            negative,
            significant,
            digits: significant.len() - usize::from(has_dot),
            shift,
        })
    }

    /// The nearest `f64`. Far beyond the range the answer is known from the magnitude
    /// alone; otherwise at most [`F64_DIGITS`] digits and a short exponent go to Rust's
    /// correctly rounded parser, so its limits on exponents never matter.
    fn to_f64(&self) -> f64 {
        let sign = if self.negative { -1.0 } else { 1.0 };
        if self.digits == 0 {
            return sign * 0.0;
        }
        // 10^(magnitude - 1) <= |value| < 10^magnitude.
        let magnitude = self.digits as i128 + self.shift;
        if magnitude > 310 {
            // |value| >= 1e310 > f64::MAX.
            return sign * f64::INFINITY;
        }
        if magnitude < -323 {
            // |value| < 1e-324, below half the smallest subnormal (2.47e-324).
            return sign * 0.0;
        }
        let mut text: String = self
            .significant
            .chars()
            .filter(|&c| c != '.')
            .take(F64_DIGITS)
            .collect();
        if self.digits > F64_DIGITS {
            // The cut digits end in a nonzero one (`significant` does): a sticky digit
            // keeps the value strictly between the same two neighbours of the cut.
            text.push('1');
        }
        let exponent = magnitude - text.len() as i128;
        text.push('e');
        text.push_str(&exponent.to_string());
        sign * text
            .parse::<f64>()
            .expect("at most 801 digits and an exponent of four are a valid float")
    }

    /// The exact value, if it is within the bound of [`parse_scalar`]'s "Bounded parsing".
    #[cfg(feature = "exact")]
    fn exact(&self) -> std::result::Result<num_rational::BigRational, String> {
        use num_bigint::BigInt;
        use num_rational::BigRational;
        if self.digits == 0 {
            return Ok(<BigRational as num_traits::Zero>::zero());
        }
        if self.digits > MAX_EXACT_DIGITS {
            return Err(format!(
                "an exact number has at most {MAX_EXACT_DIGITS} significant digits; this one has {}",
                self.digits
            ));
        }
        // 10^(magnitude - 1) <= |value| < 10^magnitude.
        let magnitude = self.digits as i128 + self.shift;
        if magnitude > i128::from(MAX_EXACT_EXPONENT) {
            return Err(OUT_OF_RANGE.to_string());
        }
        if magnitude <= -i128::from(MAX_EXACT_EXPONENT) {
            return Err(format!(
                "the number is nonzero and below 1e-{MAX_EXACT_EXPONENT} in magnitude, the bound \
                 for exact numbers"
            ));
        }
        let digits: String = self.significant.chars().filter(|&c| c != '.').collect();
        let d: BigInt = digits.parse().map_err(|_| "expected digits".to_string())?;
        // |shift| < MAX_EXACT_DIGITS + MAX_EXACT_EXPONENT here.
        let pow = num_traits::pow(BigInt::from(10), self.shift.unsigned_abs() as usize);
        let value = if self.shift >= 0 {
            BigRational::from_integer(d * pow)
        } else {
            BigRational::new(d, pow)
        };
        Ok(if self.negative { -value } else { value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_syntax_rejects_words_and_accepts_forms() {
        for good in [
            "0",
            "-3",
            "+2.5",
            ".5",
            "5.",
            "1e-3",
            "-0.125E+2",
            "00.00e-0",
        ] {
            assert!(Decimal::scan(good).is_ok(), "{good}");
        }
        for bad in [
            "", "-", ".", "inf", "NaN", "0x10", "1e", "1e+", "1.2.3", "1 2", "+-1", "1e5e5", "١",
        ] {
            assert!(Decimal::scan(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn decimals_split_into_significant_digits_and_shift() {
        fn parts(s: &str) -> (bool, &str, usize, i128) {
            let d = Decimal::scan(s).unwrap();
            (d.negative, d.significant, d.digits, d.shift)
        }
        assert_eq!(parts("1000"), (false, "1", 1, 3));
        assert_eq!(parts("-12.50"), (true, "12.5", 3, -1));
        assert_eq!(parts("10.0"), (false, "1", 1, 1));
        assert_eq!(parts("5."), (false, "5", 1, 0));
        assert_eq!(parts(".5"), (false, "5", 1, -1));
        assert_eq!(parts("0.000125"), (false, "125", 3, -6));
        assert_eq!(parts("+007.0300e2"), (false, "7.03", 3, 0));
        assert_eq!(parts("0.00e-99999999999999999999999"), (false, "", 0, 0));
        // A saturated exponent stays far beyond every bound, without overflow.
        let (_, _, _, shift) = parts("1e-9223372036854775808");
        assert_eq!(shift, -i128::from(i64::MAX));
        let (_, _, _, shift) = parts(&format!("0.5e{}", "9".repeat(100)));
        assert_eq!(shift, i128::from(i64::MAX) - 1);
    }

    #[test]
    fn f64_rounds_as_ieee_at_any_exponent_and_length() {
        let p = |s: &str| <f64 as ParseScalar>::parse_scalar(s);
        for (text, want) in [
            ("1e-400", 0.0),
            ("-1e-400", -0.0),
            ("1e-9223372036854775808", 0.0),
            ("3e-9223372036854775808", 0.0),
            ("4.9406564584124654e-324", 5e-324),
            ("2.4703282292062328e-324", 5e-324),
            ("1.7976931348623157e308", f64::MAX),
            ("0.1", 0.1),
            ("1/3", 1.0 / 3.0),
        ] {
            assert_eq!(p(text).unwrap().to_bits(), f64::to_bits(want), "{text}");
        }
        // Ten thousand digits, and a million zeros before a 1: rounded, not refused.
        let third = format!("0.{}", "3".repeat(10_000));
        assert_eq!(p(&third).unwrap(), 1.0 / 3.0);
        let tiny = format!("0.{}1", "0".repeat(1_000_000));
        assert_eq!(p(&tiny).unwrap(), 0.0);
        // Many digits and a long exponent that cancel: str::parse gets both wrong.
        let one = format!("1{}e-1000000", "0".repeat(1_000_000));
        assert_eq!(p(&one).unwrap(), 1.0);
        let one = format!("0.{}1e1000001", "0".repeat(1_000_000));
        assert_eq!(p(&one).unwrap(), 1.0);
        let big = format!("{}e-999990", "3".repeat(1_000_000));
        assert_eq!(p(&big).unwrap(), 1e10 / 3.0);
        for huge in [
            "1e309",
            "1e9223372036854775808",
            "-1e99999999999999999999999",
            &"9".repeat(1_000_000),
        ] {
            assert_eq!(
                p(huge).unwrap_err(),
                OUT_OF_RANGE,
                "{}",
                &huge[..huge.len().min(30)]
            );
        }
    }

    #[test]
    fn errors_quote_the_text_short_and_escaped() {
        let long = "x".repeat(1_000_000);
        let e = read_scalar::<f64>(&long).unwrap_err();
        assert!(e.len() < 200, "{e}");
        assert!(e.ends_with("(1000000 characters))"), "{e}");
        let e = read_scalar::<f64>("1\u{1b}[2J").unwrap_err();
        assert!(e.contains("\\u{1b}") && !e.contains('\u{1b}'), "{e}");
        let e = parse_scalar::<f64>("1/0", "t").unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid t: the denominator is zero (got \"1/0\")"
        );
    }

    #[cfg(feature = "exact")]
    mod exact {
        use super::super::*;
        use num_bigint::BigInt;
        use num_rational::BigRational;
        use proptest::prelude::*;

        fn r(n: i64, d: i64) -> BigRational {
            BigRational::new(BigInt::from(n), BigInt::from(d))
        }

        fn p(s: &str) -> std::result::Result<BigRational, String> {
            <BigRational as ParseScalar>::parse_scalar(s)
        }

        fn ten_to(k: u32) -> BigInt {
            BigInt::from(10).pow(k)
        }

        #[test]
        fn exact_parsing_keeps_decimals_exact() {
            assert_eq!(p("0.1").unwrap(), r(1, 10));
            assert_eq!(p("47/18").unwrap(), r(47, 18));
            assert_eq!(p("-1.5e2/4").unwrap(), r(-75, 2));
            assert_eq!(p("2.5E-1").unwrap(), r(1, 4));
            assert_eq!(p("-0.0e-9223372036854775808").unwrap(), r(0, 1));
            assert!(p("3/0").is_err());
            assert!(p("3/0e-99999999999").is_err());
            assert_eq!(p("1e5000").unwrap_err(), OUT_OF_RANGE);
            assert_eq!(p("1e309").unwrap_err(), OUT_OF_RANGE);
            assert_eq!(
                <f64 as ParseScalar>::parse_scalar("1/3").unwrap(),
                1.0 / 3.0
            );
        }

        #[test]
        fn the_bound_accepts_its_edges_exactly_and_refuses_beyond() {
            // The smallest magnitude, written three ways.
            let smallest = BigRational::new(BigInt::from(1), ten_to(400));
            assert_eq!(p("1e-400").unwrap(), smallest);
            assert_eq!(p(&format!("0.{}1", "0".repeat(399))).unwrap(), smallest);
            assert_eq!(
                p(&format!("-{}e-800", "1".to_owned() + &"0".repeat(400))).unwrap(),
                -smallest.clone()
            );
            for below in ["1e-401", "9.99e-401", &format!("0.{}1", "0".repeat(400))] {
                let e = p(below).unwrap_err();
                assert!(e.contains("below 1e-400"), "{below}: {e}");
            }
            // Fractions reach the top of the magnitude bound in either part.
            let top = format!("{}e-1", "9".repeat(400)); // 10^399 - 1/10, below 1e400
            let want = BigRational::new(ten_to(400) - BigInt::from(1), BigInt::from(10))
                / BigRational::from_integer(ten_to(399));
            assert_eq!(p(&format!("{top}/1e399")).unwrap(), want);
            assert_eq!(p("1e400/1e399").unwrap_err(), OUT_OF_RANGE);
            // Digits: 1000 significant digits are taken, 1001 refused, trailing and
            // leading zeros not counted.
            let thousand = "1234567890".repeat(100);
            let value = BigRational::from_integer(thousand.parse::<BigInt>().unwrap());
            assert_eq!(
                p(&format!("{thousand}e-700")).unwrap(),
                value.clone() / BigRational::from_integer(ten_to(700))
            );
            assert_eq!(
                p(&format!("000.{thousand}0000e-100")).unwrap(),
                value.clone() / BigRational::from_integer(ten_to(1100))
            );
            let e = p(&format!("{thousand}3e-700")).unwrap_err();
            assert_eq!(
                e,
                "an exact number has at most 1000 significant digits; this one has 1001"
            );
            // A million zeros cost nothing: the exponent absorbs them.
            let one = format!("1{}e-1000000", "0".repeat(1_000_000));
            assert_eq!(p(&one).unwrap(), r(1, 1));
            // The hangs of issue 22: refused at once.
            assert!(p("1e-9223372036854775808").unwrap_err().contains("below"));
            assert!(p("3e-9223372036854775808").unwrap_err().contains("below"));
            assert_eq!(p("1e9223372036854775807").unwrap_err(), OUT_OF_RANGE);
            // Fractions in f64 are exact, so their parts obey the bound.
            assert!(<f64 as ParseScalar>::parse_scalar("1e-401/1").is_err());
            assert_eq!(
                <f64 as ParseScalar>::parse_scalar("1e-400/1e300").unwrap(),
                0.0
            );
        }

        /// The exact decimal expansion of `x` (Rust prints exactly at any precision).
        fn full_decimal(x: f64) -> String {
            format!("{x:.800e}")
        }

        #[test]
        fn every_extreme_double_written_in_full_reads_back_exactly() {
            let largest_subnormal = f64::from_bits(0x000F_FFFF_FFFF_FFFF);
            for x in [
                5e-324,
                largest_subnormal,
                f64::MIN_POSITIVE,
                f64::MAX,
                -f64::MAX,
                0.1,
            ] {
                let want = BigRational::from_float(x).unwrap();
                assert_eq!(p(&full_decimal(x)).unwrap(), want, "{x:e}");
                // And the f64 reading rounds it back to x.
                assert_eq!(
                    <f64 as ParseScalar>::parse_scalar(&full_decimal(x)).unwrap(),
                    x
                );
            }
            assert_eq!(
                p(&format!("{:.0}", f64::MAX)).unwrap(),
                BigRational::from_float(f64::MAX).unwrap()
            );
            // The expansion of the largest subnormal has 767 significant digits, the most.
            let digits = Decimal::scan(&full_decimal(largest_subnormal))
                .unwrap()
                .digits;
            assert_eq!(digits, 767);
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(200))]

            #[test]
            fn every_finite_double_reads_back_exactly(bits in any::<u64>()) {
                let x = f64::from_bits(bits);
                prop_assume!(x.is_finite());
                prop_assert_eq!(p(&full_decimal(x)).unwrap(), BigRational::from_float(x).unwrap());
            }

            #[test]
            fn f64_rounding_agrees_with_str_parse_on_short_exponents(
                negative in any::<bool>(),
                lead in "[0-9]{0,3}",
                digits in "[0-9]{1,1200}",
                exponent in -1200i32..400,
            ) {
                // str::parse is correct while the exponent has at most five digits.
                let text = format!("{}{lead}.{digits}e{exponent}", if negative { "-" } else { "" });
                let want: f64 = text.parse().unwrap();
                prop_assert_eq!(parse_f64(&text).unwrap().to_bits(), want.to_bits(), "{}", text);
            }

            #[test]
            fn f64_and_exact_agree_within_the_bound(
                negative in any::<bool>(),
                digits in "[0-9]{1,40}",
                point in 0usize..41,
                exponent in -420i32..420,
            ) {
                let point = point.min(digits.len());
                let text = format!(
                    "{}{}.{}e{exponent}",
                    if negative { "-" } else { "" },
                    &digits[..point],
                    &digits[point..]
                );
                let float = <f64 as ParseScalar>::parse_scalar(&text);
                match p(&text) {
                    // `==`: the exact zero has no sign.
                    Ok(exact) => prop_assert!(float.clone().unwrap() == Scalar::to_f64(&exact), "{}: {:?}", text, float),
                    // Refused exactly: out of the f64 range for both, or below 1e-400,
                    // where the double is 0.
                    Err(e) if e == OUT_OF_RANGE => prop_assert_eq!(float.unwrap_err(), OUT_OF_RANGE),
                    Err(_) => prop_assert_eq!(float.unwrap(), 0.0),
                }
            }
        }
    }
}
