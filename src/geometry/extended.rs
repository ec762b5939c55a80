//! The slow path of the predicates, for operands outside the safe exponent window.
//!
//! Every predicate here is a homogeneous polynomial in the coordinates, so multiplying every
//! operand by the same power of two leaves its sign unchanged. When the nonzero operands'
//! exponents span less than the window's width, they are rescaled into the window (exactly:
//! a power-of-two factor changes only the exponent) and the fast kernel answers. When they
//! span more (1e300 next to 1e-300, say), every double is written as `m * 2^e` with integer
//! `m`, all are brought to the smallest exponent, and the polynomial is evaluated exactly in
//! big integers.

use super::bigint::BigInt;
use super::predicates::{pow2, sign_in_window, Window, DEGREE_2, DEGREE_4};

/// The predicates that have a slow path, with their polynomials.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Predicate {
    /// `(b - a) x (c - a)`, operands `[ax, ay, bx, by, cx, cy]`.
    Orient2d,
    /// The lifted in-circle determinant, operands `[ax, ay, ..., dx, dy]`.
    Incircle,
    /// `|ab|^2 - |cd|^2`, operands `[ax, ay, ..., dx, dy]`.
    CmpDist,
    /// `(b - a) x (d - c)`, operands `[ax, ay, ..., dx, dy]`.
    CrossSign,
}

impl Predicate {
    /// The safe exponent window of the predicate's exact floating-point stage.
    pub(crate) fn window(self) -> Window {
        match self {
            Predicate::Incircle => DEGREE_4,
            Predicate::Orient2d | Predicate::CmpDist | Predicate::CrossSign => DEGREE_2,
        }
    }
}

/// The exact sign (-1, 0, 1) of `predicate` on finite operands of any magnitude.
#[cold]
pub(crate) fn sign(predicate: Predicate, coords: &[f64]) -> i32 {
    let mut scaled = [0.0; 8];
    let scaled = &mut scaled[..coords.len()];
    if rescale_into(predicate.window(), coords, scaled) {
        sign_in_window(predicate, scaled)
    } else {
        big_sign(predicate, coords)
    }
}

/// Writes `coords * 2^s` into `out` for a shift `s` that puts every nonzero operand inside
/// `window`, or returns false if their exponents span too much for one shift.
fn rescale_into(window: Window, coords: &[f64], out: &mut [f64]) -> bool {
    let exponents = coords.iter().filter(|v| **v != 0.0).map(|&v| exponent(v));
    let (lo, hi) = exponents.fold((i32::MAX, i32::MIN), |(lo, hi), e| (lo.min(e), hi.max(e)));
    if lo > hi {
        out.copy_from_slice(coords);
        return true;
    }
    if hi - lo > window.max_exp - window.min_exp {
        return false;
    }
    let shift = window.min_exp - lo;
    for (o, &v) in out.iter_mut().zip(coords) {
        *o = scale_by_pow2(v, shift);
    }
    true
}

/// `floor(log2 |v|)` for finite nonzero `v`, subnormals included.
pub(crate) fn exponent(v: f64) -> i32 {
    let bits = v.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        let fraction = bits & ((1 << 52) - 1);
        63 - fraction.leading_zeros() as i32 - 1074
    } else {
        biased - 1023
    }
}

/// `v * 2^shift`, exact when the result is a normal double: each step moves monotonically
/// from `v` towards the result, so no intermediate overflows or becomes subnormal.
pub(crate) fn scale_by_pow2(mut v: f64, mut shift: i32) -> f64 {
    while shift != 0 {
        let step = shift.clamp(-1000, 1000);
        v *= pow2(step);
        shift -= step;
    }
    v
}

/// `v = (-1)^negative * mantissa * 2^exp` with integer mantissa, for finite `v`.
pub(crate) fn decompose(v: f64) -> (bool, u64, i32) {
    let bits = v.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1 << 52) - 1);
    if biased == 0 {
        (negative, fraction, -1074)
    } else {
        (negative, fraction | (1 << 52), biased - 1075)
    }
}

/// `v = (-1)^negative * m * 2^e` with `m` odd (or zero): grid and lattice coordinates
/// become small integers.
fn odd_parts(v: f64) -> (bool, u64, i32) {
    let (negative, m, e) = decompose(v);
    let zeros = if m == 0 { 0 } else { m.trailing_zeros() };
    (negative, m >> zeros, e + zeros as i32)
}

/// Each coordinate's odd parts (sign, odd mantissa, exponent) and the least exponent among
/// the non-zero ones (0 if all are zero): the power of two that scales them all to integers.
pub(crate) fn odd_parts_and_base(coords: &[f64]) -> (Vec<(bool, u64, i32)>, i32) {
    let parts: Vec<(bool, u64, i32)> = coords.iter().map(|&v| odd_parts(v)).collect();
    let base = parts
        .iter()
        .filter(|&&(_, m, _)| m != 0)
        .map(|&(_, _, e)| e)
        .min()
        .unwrap_or(0);
    (parts, base)
}

/// Every coordinate as an exact big integer, all scaled by `2^-base` for the least exponent
/// `base` of their last nonzero bits (0 if all are zero): integer coordinates stay
/// themselves, so the products stay short. Returns the integers and `base`.
pub(crate) fn exact_integers(coords: &[f64]) -> (Vec<BigInt>, i32) {
    let (parts, base) = odd_parts_and_base(coords);
    let ints = parts
        .iter()
        .map(|&(negative, m, e)| {
            BigInt::from_parts(negative, m, if m == 0 { 0 } else { (e - base) as u32 })
        })
        .collect();
    (ints, base)
}

/// [`exact_integers`] of a fixed number of coordinates, as an array to destructure.
pub(crate) fn exact_coords<const N: usize>(coords: [f64; N]) -> ([BigInt; N], i32) {
    let (ints, base) = exact_integers(&coords);
    let ints: [BigInt; N] = ints
        .try_into()
        .unwrap_or_else(|_| unreachable!("one integer per coordinate"));
    (ints, base)
}

fn big_sign(predicate: Predicate, coords: &[f64]) -> i32 {
    let parts: Vec<(bool, u64, i32)> = coords.iter().map(|&v| decompose(v)).collect();
    let base = parts
        .iter()
        .filter(|(_, m, _)| *m != 0)
        .map(|(_, _, e)| *e)
        .min()
        .unwrap_or(0);
    let v: Vec<BigInt> = parts
        .iter()
        .map(|&(neg, m, e)| BigInt::from_parts(neg, m, if m == 0 { 0 } else { (e - base) as u32 }))
        .collect();
    let d = |i: usize, j: usize| v[i].sub(&v[j]);
    let det = match predicate {
        // (bx - ax)(cy - ay) - (by - ay)(cx - ax)
        Predicate::Orient2d => d(2, 0).mul(&d(5, 1)).sub(&d(3, 1).mul(&d(4, 0))),
        // (bx - ax)(dy - cy) - (by - ay)(dx - cx)
        Predicate::CrossSign => d(2, 0).mul(&d(7, 5)).sub(&d(3, 1).mul(&d(6, 4))),
        // (bx - ax)^2 + (by - ay)^2 - (dx - cx)^2 - (dy - cy)^2
        Predicate::CmpDist => {
            let sq = |x: BigInt| x.mul(&x);
            sq(d(2, 0))
                .add(&sq(d(3, 1)))
                .sub(&sq(d(6, 4)))
                .sub(&sq(d(7, 5)))
        }
        // Rows (px - dx, py - dy, |p - d|^2) for p = a, b, c, expanded along the lift column.
        Predicate::Incircle => {
            let (adx, ady) = (d(0, 6), d(1, 7));
            let (bdx, bdy) = (d(2, 6), d(3, 7));
            let (cdx, cdy) = (d(4, 6), d(5, 7));
            let lift = |x: &BigInt, y: &BigInt| x.mul(x).add(&y.mul(y));
            let minor =
                |x1: &BigInt, y1: &BigInt, x2: &BigInt, y2: &BigInt| x1.mul(y2).sub(&x2.mul(y1));
            lift(&adx, &ady)
                .mul(&minor(&bdx, &bdy, &cdx, &cdy))
                .add(&lift(&bdx, &bdy).mul(&minor(&cdx, &cdy, &adx, &ady)))
                .add(&lift(&cdx, &cdy).mul(&minor(&adx, &ady, &bdx, &bdy)))
        }
    };
    det.signum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponent_and_decompose_cover_subnormals() {
        assert_eq!(exponent(1.0), 0);
        assert_eq!(exponent(-0.75), -1);
        assert_eq!(exponent(f64::MAX), 1023);
        assert_eq!(exponent(5e-324), -1074);
        assert_eq!(exponent(f64::MIN_POSITIVE), -1022);
        assert_eq!(decompose(-3.0), (true, 3 << 51, -51));
        assert_eq!(decompose(5e-324), (false, 1, -1074));
    }

    #[test]
    fn rescaling_is_exact_across_the_whole_range() {
        for v in [5e-324, 1e-310, f64::MIN_POSITIVE, 1.0, 1e300, f64::MAX] {
            let e = exponent(v);
            let scaled = scale_by_pow2(v, -e);
            assert!((1.0..2.0).contains(&scaled), "{v:e}");
            assert_eq!(scale_by_pow2(scaled, e), v, "{v:e}");
        }
    }

    #[test]
    fn wide_spreads_fall_back_to_big_integers() {
        let coords = [0.0, 0.0, 1e300, 1e300, 1e-300, 1e-300];
        let mut out = [0.0; 6];
        assert!(!rescale_into(DEGREE_2, &coords, &mut out));
        assert_eq!(sign(Predicate::Orient2d, &coords), 0);
    }
}
