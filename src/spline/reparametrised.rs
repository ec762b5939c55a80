//! A Bézier curve over a global parameter interval [a, b]: reparametrisation.
//!
//! Follows `003_5b666ee3e15e6353.txt` §3.2 ("Reparametrización") and
//! `000_f3201fe9758fe02a.txt` §2.2 (local and global parameter) and §2.4 (the derivative
//! with respect to the global parameter).

use super::bezier::Bezier;
use super::scalar::{validate_parameter, Point, Scalar};
use crate::Result;

/// A Bézier curve over a global parameter interval [a, b], a < b: the point at u is the
/// curve's point at the local parameter t = (u − a)/(b − a), and its r-th derivative with
/// respect to u is the local one divided by (b − a)ʳ.
///
/// Follows `003_5b666ee3e15e6353.txt` §3.2 ("Reparametrización") and
/// `000_f3201fe9758fe02a.txt` §2.2 (local and global parameter) and §2.4.
///
/// ```
/// use compgeo::spline::{Bezier, Point};
///
/// let line = Bezier::new(vec![Point::new([0.0]), Point::new([10.0])])?;
/// let on = line.reparametrise(2.0, 4.0)?;
/// assert_eq!(on.eval(&3.0)?, Point::new([5.0]));
/// assert_eq!(on.derivative_at(&3.0, 1)?, Point::new([5.0])); // 10 / (4 − 2)
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Reparametrised<S, const D: usize> {
    curve: Bezier<S, D>,
    a: S,
    b: S,
}

impl<S: Scalar, const D: usize> Reparametrised<S, D> {
    /// The pair, for [`Bezier::reparametrise`], which has checked a < b.
    pub(super) fn new_unchecked(curve: Bezier<S, D>, a: S, b: S) -> Self {
        Reparametrised { curve, a, b }
    }

    /// The curve in its local parameter t ∈ [0, 1].
    pub fn curve(&self) -> &Bezier<S, D> {
        &self.curve
    }

    /// The interval [a, b].
    pub fn interval(&self) -> (&S, &S) {
        (&self.a, &self.b)
    }

    /// The local parameter t = (u − a)/(b − a) of the global parameter u.
    pub fn local(&self, u: &S) -> S {
        (u.clone() - &self.a) / (self.b.clone() - &self.a)
    }

    /// The point at the global parameter u (any u, also outside [a, b]).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `u` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time (Horner), O(D) auxiliary space.
    pub fn eval(&self, u: &S) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        self.curve.eval(&self.local(u))
    }

    /// The r-th derivative with respect to the global parameter u: the local derivative
    /// divided by (b − a)ʳ.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `u` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²D + r) time, O(nD) auxiliary space.
    pub fn derivative_at(&self, u: &S, r: usize) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        let local = self.curve.derivative_at(&self.local(u), r)?;
        let width = self.b.clone() - &self.a;
        let mut scale = S::one();
        for _ in 0..r {
            scale = scale * &width;
        }
        Ok(local / scale)
    }
}
