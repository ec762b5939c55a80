//! Bernstein polynomials: values, the whole basis of one degree, derivatives.
//!
//! The Bernstein polynomials of degree n are `Bᵢⁿ(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ`, i = 0, …, n
//! (and `Bᵢⁿ ≡ 0` for i outside 0..=n). They form a partition of unity for every real t, are
//! symmetric (`Bᵢⁿ(t) = Bₙ₋ᵢⁿ(1 − t)`), positive on (0, 1), and satisfy the recurrence
//! `Bᵢⁿ⁺¹(t) = t·Bᵢ₋₁ⁿ(t) + (1 − t)·Bᵢⁿ(t)`; the derivative is
//! `d/dt Bᵢⁿ(t) = n (Bᵢ₋₁ⁿ⁻¹(t) − Bᵢⁿ⁻¹(t))`.
//!
//! Follows [PPB, §2.1] (properties, the triangular scheme of Obs. 1), [PPB, §2.4] (derivative)
//! and [RD, §3.2] ("Polinomios De Bernstein").
//!
//! # Complexity
//!
//! O(n) field operations for one value, Θ(n²) for the whole basis of degree n, O(n² + r²) for
//! an r-th derivative; O(n) space.

use crate::spline::scalar::{binomial, falling_factorial, validate_parameter, Scalar};
use crate::{limits, Result};

/// The value `Bᵢⁿ(t) = C(n, i) tⁱ (1 − t)ⁿ⁻ⁱ` (zero when `i > n`), for any t.
///
/// Idea: the closed form, with the powers taken by repeated multiplication.
///
/// Follows [PPB, §2.1] (definition).
///
/// # Errors
///
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `t` is NaN or infinite;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `n` exceeds
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
///
/// # Complexity
///
/// O(n) field operations, O(1) auxiliary space. Counts nothing.
///
/// ```
/// use compgeo::spline::bernstein;
///
/// // B₁³(t) = 3t(1 − t)² is largest at t = 1/3, where it is 4/9.
/// let b = bernstein(3, 1, &(1.0 / 3.0))?;
/// assert!((b - 4.0 / 9.0).abs() < 1e-15);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bernstein<S: Scalar>(n: usize, i: usize, t: &S) -> Result<S> {
    validate_parameter(t, "t")?;
    limits::DEGREE.check(n as u128)?;
    if i > n {
        return Ok(S::zero());
    }
    let s = S::one() - t;
    let mut v: S = binomial(n, i);
    for _ in 0..i {
        v = v * t;
    }
    for _ in i..n {
        v = v * &s;
    }
    Ok(v)
}

/// All `n + 1` values `B₀ⁿ(t), …, Bₙⁿ(t)`, by the triangular recurrence.
///
/// Idea: start from `B₀⁰ = 1` and raise the degree one step at a time with
/// `Bᵢᵏ⁺¹ = t·Bᵢ₋₁ᵏ + (1 − t)·Bᵢᵏ`, in place, right to left: no binomial coefficients and no
/// powers, only multiplications by t and 1 − t.
///
/// Follows [PPB, §2.1, Obs. 1] (the triangular scheme).
///
/// # Errors
///
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `t` is NaN or infinite;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `n` exceeds
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
///
/// # Complexity
///
/// Θ(n²) field operations (n(n + 1)/2 steps of two products and a sum), O(n) space for the
/// output and nothing more. Counts nothing.
///
/// ```
/// use compgeo::spline::bernstein_all;
///
/// assert_eq!(bernstein_all(2, &0.5)?, [0.25, 0.5, 0.25]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bernstein_all<S: Scalar>(n: usize, t: &S) -> Result<Vec<S>> {
    validate_parameter(t, "t")?;
    limits::DEGREE.check(n as u128)?;
    Ok(all_values(n, t))
}

/// The r-th derivative `dʳ/dtʳ Bᵢⁿ(t)` (zero when `i > n` or `r > n`).
///
/// Idea: applying `d/dt Bᵢⁿ = n (Bᵢ₋₁ⁿ⁻¹ − Bᵢⁿ⁻¹)` r times gives
/// `n!/(n − r)! · Σⱼ (−1)ʲ C(r, j) Bᵢ₋ᵣ₊ⱼⁿ⁻ʳ(t)`: an r-th backward difference of the basis of
/// degree n − r, which is computed once with [`bernstein_all`]'s recurrence.
///
/// Follows [PPB, §2.4] (derivative of a Bernstein polynomial) and [RD, §3.2] ("Derivada").
///
/// # Errors
///
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `t` is NaN or infinite;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `n` exceeds
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
///
/// # Complexity
///
/// O(n² + r²) field operations (the basis of degree n − r and the binomials of r), O(n)
/// auxiliary space. Counts nothing.
///
/// ```
/// use compgeo::spline::bernstein_derivative;
///
/// // d/dt 3t(1 − t)² = 3(1 − t)(1 − 3t) vanishes at t = 1/3 and is 3 at t = 0.
/// assert_eq!(bernstein_derivative(3, 1, 1, &0.0)?, 3.0);
/// // The second derivative of t³ is 6t.
/// assert_eq!(bernstein_derivative(3, 3, 2, &0.5)?, 3.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bernstein_derivative<S: Scalar>(n: usize, i: usize, r: usize, t: &S) -> Result<S> {
    validate_parameter(t, "t")?;
    limits::DEGREE.check(n as u128)?;
    if i > n || r > n {
        return Ok(S::zero());
    }
    let lower = all_values(n - r, t);
    let mut sum = S::zero();
    for j in 0..=r {
        // Index of the lower-degree basis function, i − r + j, must lie in 0..=n − r.
        let Some(k) = (i + j).checked_sub(r) else {
            continue;
        };
        let Some(b) = lower.get(k) else { continue };
        let term = binomial::<S>(r, j) * b;
        if j % 2 == 0 {
            sum += term;
        } else {
            sum -= term;
        }
    }
    Ok(falling_factorial::<S>(n, r) * sum)
}

/// The triangular scheme of Obs. 1, without validation.
pub(crate) fn all_values<S: Scalar>(n: usize, t: &S) -> Vec<S> {
    let s = S::one() - t;
    let mut b = Vec::with_capacity(n + 1);
    b.push(S::one());
    for k in 1..=n {
        // Right to left so that b[i - 1] still holds degree k − 1 when b[i] is updated.
        b.push(S::zero());
        for i in (1..=k).rev() {
            b[i] = b[i - 1].clone() * t + s.clone() * &b[i];
        }
        b[0] = b[0].clone() * &s;
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recurrence_matches_closed_form() {
        for n in 0..12 {
            for &t in &[-1.5, 0.0, 0.3, 0.5, 1.0, 2.25] {
                let all = bernstein_all(n, &t).unwrap();
                for (i, v) in all.iter().enumerate() {
                    let closed: f64 = bernstein(n, i, &t).unwrap();
                    assert!(
                        (v - closed).abs() <= 1e-12 * (1.0 + closed.abs()),
                        "{n} {i} {t}"
                    );
                }
            }
        }
    }

    #[test]
    fn derivative_of_degree_zero_order_is_the_value() {
        for i in 0..=4 {
            let v: f64 = bernstein(4, i, &0.7).unwrap();
            let d = bernstein_derivative(4, i, 0, &0.7).unwrap();
            assert!((d - v).abs() < 1e-15, "{i}: {d} vs {v}");
        }
        assert_eq!(bernstein_derivative(3, 1, 4, &0.2).unwrap(), 0.0);
        assert!(bernstein(3, 1, &f64::NAN).is_err());
    }
}
