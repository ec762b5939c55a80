//! Error-free transformations and a small fixed-capacity floating-point expansion.
//!
//! An expansion is a sum of doubles whose exact real value is the quantity of interest; the
//! components do not overlap and grow in magnitude, so the sign of the sum is the sign of the
//! last (largest) component. The transformations are exact only while no intermediate value
//! overflows or underflows, which the callers guarantee by keeping operands inside the safe
//! exponent window of [`super::predicates`].

/// Veltkamp's splitter, 2^27 + 1: splits a double into two halves of at most 26 bits each.
const SPLITTER: f64 = 134_217_729.0;

/// `a + b` as `(sum, error)` with `sum + error == a + b` exactly.
#[inline]
pub(crate) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let x = a + b;
    let b_virtual = x - a;
    let a_virtual = x - b_virtual;
    (x, (a - a_virtual) + (b - b_virtual))
}

/// `a - b` as `(difference, error)` with `difference + error == a - b` exactly.
#[inline]
pub(crate) fn two_diff(a: f64, b: f64) -> (f64, f64) {
    let x = a - b;
    let b_virtual = a - x;
    let a_virtual = x + b_virtual;
    (x, (a - a_virtual) + (b_virtual - b))
}

#[inline]
fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let big = c - a;
    let hi = c - big;
    (hi, a - hi)
}

/// `a * b` as `(product, error)` with `product + error == a * b` exactly (Dekker's product;
/// no fused multiply-add, which is slow where the hardware lacks it).
#[inline]
pub(crate) fn two_product(a: f64, b: f64) -> (f64, f64) {
    let x = a * b;
    let (a_hi, a_lo) = split(a);
    let (b_hi, b_lo) = split(b);
    let err1 = x - a_hi * b_hi;
    let err2 = err1 - a_lo * b_hi;
    let err3 = err2 - a_hi * b_lo;
    (x, a_lo * b_lo - err3)
}

/// An exact sum of up to `CAPACITY` doubles, kept as a nonoverlapping expansion.
pub(crate) struct Expansion {
    parts: [f64; Expansion::CAPACITY],
    len: usize,
}

impl Expansion {
    /// Each added double can lengthen the expansion by at most one component.
    pub(crate) const CAPACITY: usize = 32;

    pub(crate) fn new() -> Self {
        Expansion {
            parts: [0.0; Expansion::CAPACITY],
            len: 0,
        }
    }

    /// Adds `b` exactly (Shewchuk's GROW-EXPANSION with zero elimination).
    pub(crate) fn add(&mut self, b: f64) {
        let mut q = b;
        let mut out = 0;
        for i in 0..self.len {
            let (sum, err) = two_sum(q, self.parts[i]);
            q = sum;
            if err != 0.0 {
                self.parts[out] = err;
                out += 1;
            }
        }
        if q != 0.0 {
            self.parts[out] = q;
            out += 1;
        }
        self.len = out;
    }

    /// Adds the exact product `a * b`.
    pub(crate) fn add_product(&mut self, a: f64, b: f64) {
        let (p, e) = two_product(a, b);
        self.add(e);
        self.add(p);
    }

    /// Adds the exact product `(a_hi + a_lo) * (b_hi + b_lo)`.
    pub(crate) fn add_product2(&mut self, (a_hi, a_lo): (f64, f64), (b_hi, b_lo): (f64, f64)) {
        self.add_product(a_lo, b_lo);
        self.add_product(a_lo, b_hi);
        self.add_product(a_hi, b_lo);
        self.add_product(a_hi, b_hi);
    }

    /// The sign of the exact sum: -1, 0 or 1.
    pub(crate) fn signum(&self) -> i32 {
        match self.len {
            0 => 0,
            n if self.parts[n - 1] > 0.0 => 1,
            _ => -1,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_product_recovers_the_rounding_error() {
        let a = 1.0 + f64::EPSILON;
        let (p, e) = two_product(a, a);
        // (1 + eps)^2 = 1 + 2 eps + eps^2; the eps^2 term is lost in p and kept in e.
        assert_eq!(p, 1.0 + 2.0 * f64::EPSILON);
        assert_eq!(e, f64::EPSILON * f64::EPSILON);
    }

    #[test]
    fn expansion_sign_survives_cancellation() {
        let mut x = Expansion::new();
        x.add(1e100);
        x.add(1.0);
        x.add(-1e100);
        assert_eq!(x.signum(), 1);
        x.add(-1.0);
        assert_eq!(x.signum(), 0);
        x.add(-1e-300);
        assert_eq!(x.signum(), -1);
    }
}
