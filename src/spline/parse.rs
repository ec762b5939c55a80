//! Reading numbers from text into a [`Scalar`]: integers, decimals with an exponent and
//! fractions, exactly for rationals (the command line's `--exact` relies on it).

use super::scalar::Scalar;
use crate::{Error, Result};

/// Parses a number written as an integer (`-3`), a decimal with an optional exponent
/// (`2.5`, `1e-3`, `-0.125E2`) or a fraction of two such numbers (`47/18`, `1.5/4`) into the
/// scalar `S`.
///
/// The text is read exactly as a rational first, so for `BigRational` the result is the exact
/// value written (`0.1` is 1/10, not the double nearest to it); for `f64` it is the double
/// nearest to that rational, rounded once (with feature `exact`) or as `str::parse` rounds
/// decimals and then one division (without it).
///
/// # Errors
///
/// [`Error::InvalidParameter`] naming `name` if the text is not such a number, the
/// denominator is zero, or the value is not finite as an `f64` (`1e400`).
///
/// ```
/// use compgeo::spline::parse_scalar;
///
/// assert_eq!(parse_scalar::<f64>("3/4", "t").unwrap(), 0.75);
/// assert!(parse_scalar::<f64>("1/0", "t").is_err());
/// assert!(parse_scalar::<f64>("nan", "t").is_err());
/// ```
pub fn parse_scalar<S: Scalar + ParseScalar>(text: &str, name: &'static str) -> Result<S> {
    S::parse_scalar(text.trim()).map_err(|reason| Error::InvalidParameter {
        name,
        reason: format!("{reason} (got {text:?})"),
    })
}

/// How a [`Scalar`] reads itself from text; see [`parse_scalar`].
pub trait ParseScalar: Sized {
    /// Reads the value, or says why the text is not a valid finite number.
    fn parse_scalar(text: &str) -> std::result::Result<Self, String>;
}

impl ParseScalar for f64 {
    fn parse_scalar(text: &str) -> std::result::Result<Self, String> {
        #[cfg(feature = "exact")]
        {
            let r = <num_rational::BigRational as ParseScalar>::parse_scalar(text)?;
            let x = Scalar::to_f64(&r);
            if x.is_finite() {
                Ok(x)
            } else {
                Err("the number is outside the range of f64".to_string())
            }
        }
        #[cfg(not(feature = "exact"))]
        {
            let (num, den) = split_fraction(text)?;
            let n = parse_plain_f64(num)?;
            let x = match den {
                None => n,
                Some(d) => {
                    let d = parse_plain_f64(d)?;
                    if d == 0.0 {
                        return Err("the denominator is zero".to_string());
                    }
                    n / d
                }
            };
            if x.is_finite() {
                Ok(x)
            } else {
                Err("the number is outside the range of f64".to_string())
            }
        }
    }
}

#[cfg(feature = "exact")]
impl ParseScalar for num_rational::BigRational {
    fn parse_scalar(text: &str) -> std::result::Result<Self, String> {
        let (num, den) = split_fraction(text)?;
        let n = parse_decimal_exact(num)?;
        let value = match den {
            None => n,
            Some(d) => {
                let d = parse_decimal_exact(d)?;
                if Scalar::is_zero(&d) {
                    return Err("the denominator is zero".to_string());
                }
                n / d
            }
        };
        if Scalar::to_f64(&value).is_finite() {
            Ok(value)
        } else {
            Err("the number is outside the range of f64".to_string())
        }
    }
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

#[cfg(not(feature = "exact"))]
fn parse_plain_f64(text: &str) -> std::result::Result<f64, String> {
    check_decimal_syntax(text)?;
    text.parse::<f64>().map_err(|e| e.to_string())
}

/// Checks `[+-]digits[.digits][(e|E)[+-]digits]` with at least one mantissa digit, so that
/// `inf`, `nan` and hexadecimal never pass.
fn check_decimal_syntax(text: &str) -> std::result::Result<(), String> {
    let bad = || "expected an integer, a decimal or a fraction p/q".to_string();
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
    if let Some(e) = exponent {
        let e = e.strip_prefix(['+', '-']).unwrap_or(e);
        if e.is_empty() || !digits(e) {
            return Err(bad());
        }
    }
    Ok(())
}

#[cfg(feature = "exact")]
fn parse_decimal_exact(text: &str) -> std::result::Result<num_rational::BigRational, String> {
    use num_bigint::BigInt;
    use num_rational::BigRational;
    check_decimal_syntax(text)?;
    let (negative, s) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text.strip_prefix('+').unwrap_or(text)),
    };
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], &s[i + 1..]),
        None => (s, ""),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let exponent: i64 = if exponent.is_empty() {
        0
    } else {
        exponent
            .parse()
            .map_err(|_| "the exponent is too large".to_string())?
    };
    // Beyond this the value is 0 or infinite as an f64 anyway; refuse before building
    // a huge power of ten.
    let shift = exponent - frac.len() as i64;
    if shift.abs() > 2000 {
        return Err("the number is outside the range of f64".to_string());
    }
    let digits: BigInt = format!("{int}{frac}")
        .parse()
        .map_err(|_| "expected digits".to_string())?;
    let ten = BigInt::from(10);
    let pow = num_traits::pow(ten, shift.unsigned_abs() as usize);
    let mut value = if shift >= 0 {
        BigRational::from_integer(digits * pow)
    } else {
        BigRational::new(digits, pow)
    };
    if negative {
        value = -value;
    }
    Ok(value)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_syntax_rejects_words_and_accepts_forms() {
        for good in ["0", "-3", "+2.5", ".5", "5.", "1e-3", "-0.125E+2"] {
            assert!(check_decimal_syntax(good).is_ok(), "{good}");
        }
        for bad in ["", "-", ".", "inf", "NaN", "0x10", "1e", "1.2.3", "1 2"] {
            assert!(check_decimal_syntax(bad).is_err(), "{bad}");
        }
    }

    #[cfg(feature = "exact")]
    #[test]
    fn exact_parsing_keeps_decimals_exact() {
        use num_bigint::BigInt;
        use num_rational::BigRational;
        let r = |n: i64, d: i64| BigRational::new(BigInt::from(n), BigInt::from(d));
        let p = |s: &str| <BigRational as ParseScalar>::parse_scalar(s).unwrap();
        assert_eq!(p("0.1"), r(1, 10));
        assert_eq!(p("47/18"), r(47, 18));
        assert_eq!(p("-1.5e2/4"), r(-75, 2));
        assert_eq!(p("2.5E-1"), r(1, 4));
        assert!(<BigRational as ParseScalar>::parse_scalar("3/0").is_err());
        assert!(<BigRational as ParseScalar>::parse_scalar("1e5000").is_err());
        assert_eq!(
            <f64 as ParseScalar>::parse_scalar("1/3").unwrap(),
            1.0 / 3.0
        );
    }
}
