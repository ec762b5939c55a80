//! The difference schemes of a subdivision scheme: the tools of the convergence analysis.
//!
//! The problem: decide whether the polygons C_k of a scheme converge, and how smooth the
//! limit is. The idea [PPB, §8.6–8.8]: the polygons converge uniformly to a continuous curve
//! if and only if their differences ∇C_k tend to zero, and to a C^r curve if the divided
//! differences 2^{kr}∇^{r+1}C_k do. In polynomials the differences of b(z) = c(z²)α(z) are
//! ∇b(z) = (1 − z)b(z) = ∇c(z²)·α(z)/(1 + z), so the differences are refined by the scheme
//! β(z) = α(z)/(1 + z) (the **difference scheme**), which exists when α(−1) = 0, that is when
//! the even and the odd coefficients have the same sum. The divided differences 2^k∇C_k are
//! refined by 2β(z) = 2α(z)/(1 + z) (the **divided difference scheme**), whose own difference
//! scheme 2β(z)/(1 + z) governs C¹ [PPB, §8.10].
//!
//! A scheme S shrinks the polygons it refines, in the largest norm of their vertices, by at
//! most its norm ‖S‖ = max(Σ_i |α_{2i}|, Σ_i |α_{2i+1}|), the larger sum of absolute values
//! over the two parities ([`Mask::norm`]); a difference scheme of norm below 1 makes ∇C_k
//! tend to zero geometrically. For the four-point scheme ‖β‖ = ½ + 2|w| < 1 when |w| < ¼
//! [PPB, §8.10].
//!
//! With `f64` the test α(−1) = 0 is exact, as every decision of the crate: a mask whose
//! coefficients are rounded (the four-point mask of w = 0.1) may not pass it; its exact
//! rational form does.
//!
//! # Complexity
//!
//! Θ(L) time and space for a mask of length L.
//!
//! Invariants the tests check (exactly, on rationals): (1 + z)·β = α coefficient by
//! coefficient; the Lane–Riesenfeld mask of degree d has the difference scheme ½ times the
//! one of degree d − 1 [PPB, §8.8, Obs. 5]; the four-point scheme's β and 2β/(1 + z) are
//! those of [PPB, §8.10] (the latter with the factor 2 the course loses).

use super::Mask;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::Scalar;
use crate::{Error, Result};

/// The difference scheme of a mask, declared.
pub(crate) const DIFFERENCE: Declaration = Declaration {
    problem: "subdivision",
    name: "difference",
    function: "spline::subdivision::Mask::difference",
    file: "src/spline/subdivision/difference.rs",
    summary: "the difference scheme β(z) = α(z)/(1 + z) of a mask, by synthetic division, refused unless α(−1) = 0",
    time: "Θ(L)",
    space: "Θ(L)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per coefficient of the quotient and one for the remainder: L",
    source: "[PPB, §8.8]",
    claims: &[on(
        "random-mask",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar> Mask<S> {
    /// The difference scheme β(z) = α(z)/(1 + z) [PPB, §8.8]. See [`Mask::difference_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming `"mask"` if α(−1) ≠ 0 (the even and odd
    /// coefficients have different sums, so 1 + z does not divide α), or if α is a single
    /// coefficient.
    ///
    /// # Complexity
    ///
    /// Θ(L) time and space.
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// // The cubic B-spline's ⅛(1 + z)⁴ has the difference scheme ⅛(1 + z)³.
    /// let beta = Mask::<f64>::lane_riesenfeld(3)?.difference()?;
    /// assert_eq!(beta.coefficients(), [1.0, 3.0, 3.0, 1.0].map(|a| a / 8.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn difference(&self) -> Result<Mask<S>> {
        self.difference_with(&mut NoCount)
    }

    /// [`Mask::difference`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per coefficient of the
    /// quotient and one for the remainder (L in all).
    ///
    /// Idea: synthetic division from the lowest exponent, β_start = α_start and
    /// β_k = α_k − β_{k−1}; the remainder α_end − β_{end−1} must be zero.
    ///
    /// # Errors
    ///
    /// As [`Mask::difference`].
    ///
    /// # Complexity
    ///
    /// Θ(L) time and space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// let mut c = Counts::default();
    /// let beta = Mask::four_point(&0.0625)?.difference_with(&mut c)?;
    /// assert_eq!(beta.coefficients(), [-1.0, 1.0, 8.0, 8.0, 1.0, -1.0].map(|a| a / 16.0));
    /// assert_eq!(c.arithmetic_operations, 7);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn difference_with<C: Counter>(&self, counter: &mut C) -> Result<Mask<S>> {
        let a = self.coefficients();
        if a.len() < 2 {
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: "a single coefficient has no difference scheme (α(−1) ≠ 0)".to_string(),
            });
        }
        let mut beta: Vec<S> = Vec::with_capacity(a.len() - 1);
        let mut previous = S::zero();
        for coefficient in &a[..a.len() - 1] {
            let b = coefficient.clone() - &previous;
            counter.arithmetic_operation();
            beta.push(b.clone());
            previous = b;
        }
        let remainder = a[a.len() - 1].clone() - &previous;
        counter.arithmetic_operation();
        if !remainder.is_zero() {
            let (even, odd) = self.parity_sums();
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: format!(
                    "α(−1) ≠ 0: its even coefficients sum to {} and its odd ones to {}, so \
                     1 + z does not divide it and it has no difference scheme",
                    even.to_f64(),
                    odd.to_f64()
                ),
            });
        }
        Mask::new(self.start(), beta)
    }

    /// The divided difference scheme 2α(z)/(1 + z), which refines the divided differences
    /// 2^k∇C_k [PPB, §8.7, §8.10]. Its own [`difference`](Mask::difference) decides C¹.
    ///
    /// # Errors
    ///
    /// As [`Mask::difference`].
    ///
    /// # Complexity
    ///
    /// Θ(L) time and space.
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// // The four-point scheme: 2β/(1 + z) = −2w + 4wz + (1 − 4w)z² + 4wz³ − 2wz⁴, shifted.
    /// let w = 0.0625;
    /// let gamma = Mask::four_point(&w)?.divided_difference()?.difference()?;
    /// assert_eq!(gamma.coefficients(), [-2.0 * w, 4.0 * w, 1.0 - 4.0 * w, 4.0 * w, -2.0 * w]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn divided_difference(&self) -> Result<Mask<S>> {
        let beta = self.difference()?;
        let two = S::from_i64(2);
        Mask::new(
            beta.start(),
            beta.coefficients()
                .iter()
                .map(|b| b.clone() * &two)
                .collect(),
        )
    }

    /// The sums of the even and of the odd coefficients, Σ_i α_{2i} and Σ_i α_{2i+1}: both
    /// 1 for a scheme that commutes with affine maps [PPB, §8.5].
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// assert_eq!(Mask::<f64>::lane_riesenfeld(4)?.parity_sums(), (1.0, 1.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn parity_sums(&self) -> (S, S) {
        let mut sums = [S::zero(), S::zero()];
        for (t, a) in self.coefficients().iter().enumerate() {
            let k = self.start() as i128 + t as i128;
            sums[k.rem_euclid(2) as usize] += a;
        }
        let [even, odd] = sums;
        (even, odd)
    }

    /// The norm of the scheme in the largest vertex norm: max(Σ_i |α_{2i}|, Σ_i |α_{2i+1}|).
    /// A difference scheme of norm below 1 makes the differences tend to zero, so the
    /// polygons converge [PPB, §8.10].
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// // ½ + 2|w| for the four-point scheme's difference scheme.
    /// let beta = Mask::four_point(&0.125)?.difference()?;
    /// assert_eq!(beta.norm(), 0.75);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn norm(&self) -> S {
        let mut sums = [S::zero(), S::zero()];
        for (t, a) in self.coefficients().iter().enumerate() {
            let k = self.start() as i128 + t as i128;
            sums[k.rem_euclid(2) as usize] += &a.abs();
        }
        let [even, odd] = sums;
        if even < odd {
            odd
        } else {
            even
        }
    }
}
