//! Derivatives of Bézier curves: the derivative curves (hodographs) from forward differences
//! of the control points, and the r-th derivative at one parameter by the tetrahedral
//! algorithm.
//!
//! The problem: b⁽ʳ⁾ as a curve, and b⁽ʳ⁾(t) at one t. The idea: the derivative of
//! `Σ bᵢ Bᵢⁿ` is `n Σ Δbᵢ Bᵢⁿ⁻¹`, so the r-th derivative curve has the control points
//! `n (n − 1) ⋯ (n − r + 1) Δʳbᵢ`; since differences commute with de Casteljau steps, n − r
//! steps at t followed by r differences of the r + 1 points left give b⁽ʳ⁾(t).
//!
//! Follows [PPB, §2.4] (derivatives), [PPB, §2.6] (the tetrahedral algorithm) and [RD, §3.2]
//! ("Derivadas").
//!
//! # Complexity
//!
//! Θ(r·nD) for the r-th derivative curve, Θ(n²D) for a derivative at one parameter; O(nD)
//! space.
//!
//! Invariants the tests check (exactly on rationals): the tetrahedral algorithm agrees with
//! the derivative curve at every order, the hodograph's end values are n Δb₀ and n Δbₙ₋₁,
//! differentiating twice is the second derivative, the integral differentiates back, and the
//! derivative is the difference of blossoms `n (b[t, …, t, 1] − b[t, …, t, 0])` [PPB, §3.9].

use super::curve::Bezier;
use super::de_casteljau::de_casteljau_levels;
use crate::count::NoCount;
use crate::spline::curve::{Curve, CurveDerivative};
use crate::spline::scalar::{falling_factorial, Point, Scalar};
use crate::Result;

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The hodograph: the first derivative as a Bézier curve of degree n − 1 with control
    /// points n·Δbᵢ = n(bᵢ₊₁ − bᵢ). See [`Bezier::derivative`].
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`](crate::Error::Overflow) as for [`Bezier::derivative`].
    pub fn hodograph(&self) -> Result<Self> {
        self.derivative(1)
    }

    /// The r-th derivative curve: degree n − r with control points
    /// `n (n − 1) ⋯ (n − r + 1) Δʳbᵢ` (the zero curve of degree 0 when r > n).
    ///
    /// Follows [PPB, §2.4] and [RD, §3.2] ("Derivadas").
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`](crate::Error::Overflow) if a control point of the derivative is
    /// beyond the range of `f64` (differences of coordinates near ±1.8e308).
    ///
    /// # Complexity
    ///
    /// Θ(r·nD) time (r rounds of differences), O(nD) space for the result.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// // b(t) = t² has Bézier points 0, 0, 1; b' = 2t has 0, 2; b'' = 2.
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// assert_eq!(b.derivative(1)?.control(), [Point::new([0.0]), Point::new([2.0])]);
    /// assert_eq!(b.derivative(2)?.control(), [Point::new([2.0])]);
    /// assert_eq!(b.derivative(3)?.control(), [Point::new([0.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn derivative(&self, r: usize) -> Result<Self> {
        let n = self.degree();
        if r > n {
            return Ok(Bezier::with_control(vec![Point::zero()]));
        }
        let mut q = self.control().to_vec();
        for _ in 0..r {
            difference(&mut q);
        }
        let factor: S = falling_factorial(n, r);
        for p in &mut q {
            *p = p.clone() * &factor;
        }
        Bezier::derived(q, "derivative")
    }
}

/// The derivative of a Bézier curve is a Bézier curve; its derivatives at a parameter come
/// from the tetrahedral algorithm.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for Bezier<S, D> {
    type Derivative = Bezier<S, D>;

    /// The hodograph ([`Bezier::hodograph`]).
    fn derivative_curve(&self) -> Result<Self> {
        self.hodograph()
    }

    /// The r-th derivative b⁽ʳ⁾(t) at one parameter, by the tetrahedral algorithm.
    ///
    /// Idea: differences commute with de Casteljau steps, so run n − r steps of de Casteljau,
    /// take r forward differences of the r + 1 points left and multiply by
    /// n (n − 1) ⋯ (n − r + 1). Zero when r > n.
    ///
    /// Follows [PPB, §2.6].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `t` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, CurveDerivative, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// assert_eq!(b.derivative_at(&0.75, 1)?, Point::new([1.5])); // (t²)' = 2t
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn derivative_at(&self, t: &S, r: usize) -> Result<Point<S, D>> {
        self.domain().check(t, "t")?;
        let n = self.degree();
        if r > n {
            return Ok(Point::zero());
        }
        let mut q = self.control().to_vec();
        de_casteljau_levels(&mut q, std::iter::repeat_n(t, n - r), &mut NoCount);
        q.truncate(r + 1);
        for _ in 0..r {
            difference(&mut q);
        }
        Ok(q.swap_remove(0) * falling_factorial::<S>(n, r))
    }
}

/// Replaces the points `q₀, …, qₖ` by their forward differences `Δqᵢ = qᵢ₊₁ − qᵢ`, one fewer
/// (`q` must not be empty).
pub(crate) fn difference<S: Scalar, const D: usize>(q: &mut Vec<Point<S, D>>) {
    for i in 0..q.len() - 1 {
        q[i] = q[i + 1].clone() - &q[i];
    }
    q.pop();
}
