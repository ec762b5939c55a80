//! Normal deviates from correctly rounded arithmetic only.
//!
//! `f64::ln` comes from the platform's libm and may differ by an ulp between machines, which
//! would make seeded point sets differ. This module samples standard normal pairs with
//! Marsaglia's polar method and evaluates the logarithm it needs with `+ - * /` and exact
//! bit manipulation, every one of which IEEE 754 rounds identically everywhere (Rust never
//! contracts `a * b + c` into a fused multiply-add on its own). `sqrt` is also correctly
//! rounded by IEEE 754, so it is safe to use.

use super::rng::Rng;

/// ln 2 split so that `e * LN2_HI` is exact for every binary exponent `e` of an `f64`
/// (its low 11 significand bits are zero) and `LN2_LO` carries the rest.
const LN2_HI: f64 = 6.931_471_803_691_238e-1;
const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;

/// Terms of the atanh series beyond the first; enough for |z| <= 3 - 2*sqrt(2).
const SERIES_TERMS: i32 = 11;

/// A pair of independent standard normal deviates (mean 0, standard deviation 1).
///
/// Marsaglia's polar method: draw `(u, v)` uniform in the square `[-1, 1)^2` until
/// `0 < s = u^2 + v^2 < 1`, then return `(u, v) * sqrt(-2 ln s / s)`.
pub(crate) fn normal_pair(rng: &mut Rng) -> (f64, f64) {
    loop {
        let u = rng.symmetric_unit();
        let v = rng.symmetric_unit();
        let s = u * u + v * v;
        if s > 0.0 && s < 1.0 {
            let factor = (-2.0 * ln(s) / s).sqrt();
            return (u * factor, v * factor);
        }
    }
}

/// Natural logarithm of a positive finite `x`, using only correctly rounded operations.
///
/// Write `x = m * 2^e` with `m` in `[sqrt(1/2), sqrt(2))` (exact, from the bits), then
/// `ln x = e ln 2 + 2 atanh(z)` with `z = (m - 1) / (m + 1)`, `|z| <= 0.1716`, and the atanh
/// series `z + z^3/3 + z^5/5 + ...` evaluated by Horner's rule. The error is a few ulps,
/// and, more importantly here, the result is the same on every IEEE 754 machine.
pub(crate) fn ln(x: f64) -> f64 {
    debug_assert!(x > 0.0 && x.is_finite());
    let (mut m, mut e) = split(x);
    if m > std::f64::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    let z = (m - 1.0) / (m + 1.0);
    let z2 = z * z;
    let mut sum = 1.0 / f64::from(2 * SERIES_TERMS + 1);
    for k in (0..SERIES_TERMS).rev() {
        sum = sum * z2 + 1.0 / f64::from(2 * k + 1);
    }
    let e = f64::from(e);
    e * LN2_HI + (2.0 * z * sum + e * LN2_LO)
}

/// `x = m * 2^e` with `m` in `[1, 2)`, for positive finite `x` (subnormals included).
fn split(x: f64) -> (f64, i32) {
    const MANTISSA: u64 = (1 << 52) - 1;
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: scaling by 2^64 is exact and makes it normal.
        let (m, e) = split(x * 18_446_744_073_709_551_616.0);
        return (m, e - 64);
    }
    let m = f64::from_bits((bits & MANTISSA) | (1023 << 52));
    (m, biased - 1023)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 4.0 * f64::EPSILON * b.abs().max(1e-300)
    }

    #[test]
    fn ln_matches_libm_to_a_few_ulps() {
        // The platform ln is the oracle here: we only need agreement to a few ulps.
        let mut rng = Rng::new(2);
        for _ in 0..20_000 {
            let x = rng.unit();
            if x > 0.0 {
                assert!(close(ln(x), x.ln()), "ln({x}) = {} vs {}", ln(x), x.ln());
            }
        }
        for x in [
            1.0,
            2.0,
            0.5,
            std::f64::consts::SQRT_2,
            1.0 - f64::EPSILON,
            1e-300,
            5e-324,
            1e300,
            f64::MAX,
            f64::MIN_POSITIVE,
        ] {
            let (ours, theirs) = (ln(x), x.ln());
            assert!(
                (ours - theirs).abs() <= 4.0 * f64::EPSILON * theirs.abs().max(f64::EPSILON),
                "ln({x}) = {ours} vs {theirs}"
            );
        }
        assert_eq!(ln(1.0), 0.0);
    }

    #[test]
    fn ln2_split_is_exact_in_its_high_part() {
        // e * LN2_HI must be exact for |e| < 2^11: the low 11 significand bits are zero.
        assert_eq!(LN2_HI.to_bits() & 0x7ff, 0);
        assert_eq!(LN2_HI + LN2_LO, std::f64::consts::LN_2);
        assert!(LN2_LO.abs() < 1e-9);
    }

    #[test]
    fn split_is_exact() {
        for x in [1.0, 3.0, 0.75, 5e-324, 1e-310, f64::MAX] {
            let (m, e) = split(x);
            assert!((1.0..2.0).contains(&m));
            // m * 2^e reassembled through powi on exact powers of two.
            let back = if e >= -1000 {
                m * 2f64.powi(e)
            } else {
                m * 2f64.powi(e + 100) * 2f64.powi(-100)
            };
            assert_eq!(back, x);
        }
    }

    #[test]
    fn normal_pairs_have_unit_variance_and_no_correlation() {
        let mut rng = Rng::new(9);
        let n = 50_000;
        let (mut sx, mut sy, mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
        for _ in 0..n {
            let (x, y) = normal_pair(&mut rng);
            sx += x;
            sy += y;
            sxx += x * x;
            syy += y * y;
            sxy += x * y;
        }
        let n = f64::from(n);
        // Standard errors are about 1/sqrt(n) = 0.0045 for the mean and 0.0063 for the
        // variance; these bounds sit at about five of them.
        assert!((sx / n).abs() < 0.025 && (sy / n).abs() < 0.025);
        assert!((sxx / n - 1.0).abs() < 0.035 && (syy / n - 1.0).abs() < 0.035);
        assert!((sxy / n).abs() < 0.025);
    }
}
