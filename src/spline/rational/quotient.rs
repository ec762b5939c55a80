//! The quotient rule of any order: the derivatives of a rational curve c = a/w from those of
//! its homogeneous numerator a and denominator w.
//!
//! The problem: c⁽ᵏ⁾(t) for c = a/w, where a (in R^D) and w (scalar, positive) are polynomial
//! or piecewise polynomial and their derivatives are cheap. The idea: differentiate a = w·c
//! k times by Leibniz's rule, a⁽ᵏ⁾ = Σᵢ C(k, i)·w⁽ⁱ⁾·c⁽ᵏ⁻ⁱ⁾, and solve for the one term with
//! i = 0: c⁽ᵏ⁾ = (a⁽ᵏ⁾ − Σ_{i=1}^{k} C(k, i)·w⁽ⁱ⁾·c⁽ᵏ⁻ⁱ⁾)/w, from the lower orders up. For
//! k = 1 it is the quotient rule c′ = (a′ − w′·c)/w = (a′w − aw′)/w².
//!
//! Follows Piegl and Tiller, *The NURBS Book* (2nd ed., 1997), eq. (4.8) and §4.3, with
//! [SPL, §14] (a rational curve as the projection of a polynomial one).
//!
//! # Complexity
//!
//! Θ(k²D) field operations for the orders 0, …, k, O(kD) space.

use crate::spline::scalar::{binomial, Point, Scalar};
use crate::{Error, Result};

/// c, c′, …, c⁽ᵏ⁾ at one parameter from a⁽⁰⁾, …, a⁽ᵏ⁾ and w⁽⁰⁾, …, w⁽ᵏ⁾ there (the same
/// number of each, w⁽⁰⁾ > 0).
///
/// # Errors
///
/// [`Error::Overflow`] if, with `f64`, a derivative is beyond the double range.
pub(super) fn quotient_derivatives<S: Scalar, const D: usize>(
    a: &[Point<S, D>],
    w: &[S],
) -> Result<Vec<Point<S, D>>> {
    debug_assert_eq!(a.len(), w.len());
    let mut c: Vec<Point<S, D>> = Vec::with_capacity(a.len());
    for k in 0..a.len() {
        let mut sum = a[k].clone();
        for i in 1..=k {
            let factor = binomial::<S>(k, i) * &w[i];
            sum -= &(c[k - i].clone() * &factor);
        }
        let ck = sum / &w[0];
        if !ck.is_finite() {
            return Err(Error::Overflow {
                what: "rational curve derivative",
            });
        }
        c.push(ck);
    }
    Ok(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_quotient_of_t_over_one_plus_t() {
        // c = t/(1 + t) at t = 1: c = 1/2, c′ = 1/(1 + t)² = 1/4, c″ = −2/(1 + t)³ = −1/4,
        // c‴ = 6/(1 + t)⁴ = 3/8.
        let a = [1.0, 1.0, 0.0, 0.0].map(|x| Point::new([x]));
        let w = [2.0, 1.0, 0.0, 0.0];
        let c = quotient_derivatives(&a, &w).unwrap();
        let want = [0.5, 0.25, -0.25, 0.375].map(|x| Point::new([x]));
        assert_eq!(c, want);
    }
}
