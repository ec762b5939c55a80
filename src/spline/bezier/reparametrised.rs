//! A Bézier curve over a global parameter interval [a, b]: reparametrisation.
//!
//! The problem: a curve whose parameter runs over [a, b] instead of [0, 1] (a piece of a
//! composite curve, the piece of a polynomial over an interval). The idea: the point at u is
//! the Bézier curve's point at the local parameter t = (u − a)/(b − a), and by the chain rule
//! the r-th derivative in u is the local one divided by (b − a)ʳ.
//!
//! Follows [RD, §3.2] ("Reparametrización"), [PPB, §2.2] (local and global parameter) and
//! [PPB, §2.4] (the derivative with respect to the global parameter).
//!
//! # Complexity
//!
//! The Bézier curve's costs plus O(1) scalar operations for the change of parameter.

use super::curve::Bezier;
use crate::spline::curve::{check_interval, Curve, CurveDerivative, Domain, Subsegment};
use crate::spline::scalar::{power, Point, Scalar};
use crate::Result;

/// A Bézier curve over a global parameter interval [a, b], a < b: the point at u is the
/// curve's point at the local parameter t = (u − a)/(b − a), and its r-th derivative with
/// respect to u is the local one divided by (b − a)ʳ. Like the Bézier curve it carries, it
/// evaluates at every real u ([`Domain::Real`]); [a, b] is the segment its control polygon
/// describes.
///
/// Follows [RD, §3.2] ("Reparametrización") and [PPB, §2.2, §2.4].
///
/// ```
/// use compgeo::spline::{Bezier, Curve, CurveDerivative, Point};
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
    /// The pair, for callers that have checked a < b, both finite.
    pub(crate) fn new_unchecked(curve: Bezier<S, D>, a: S, b: S) -> Self {
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
        (u.clone() - &self.a) / self.width()
    }

    /// b − a.
    fn width(&self) -> S {
        self.b.clone() - &self.a
    }
}

impl<S: Scalar, const D: usize> Curve<S, D> for Reparametrised<S, D> {
    /// [`Domain::Real`], as for the Bézier curve.
    fn domain(&self) -> Domain<S> {
        Domain::Real
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
    fn eval(&self, u: &S) -> Result<Point<S, D>> {
        self.domain().check(u, "u")?;
        self.curve.eval(&self.local(u))
    }
}

/// Derivatives with respect to the global parameter.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for Reparametrised<S, D> {
    type Derivative = Reparametrised<S, D>;

    /// The hodograph divided by b − a, over the same interval.
    ///
    /// # Complexity
    ///
    /// Θ(nD).
    fn derivative_curve(&self) -> Result<Self> {
        let width = self.width();
        let scaled = self
            .curve
            .hodograph()?
            .into_control()
            .into_iter()
            .map(|p| p / &width)
            .collect();
        Ok(Reparametrised {
            curve: Bezier::derived(scaled, "derivative")?,
            a: self.a.clone(),
            b: self.b.clone(),
        })
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
    fn derivative_at(&self, u: &S, r: usize) -> Result<Point<S, D>> {
        self.domain().check(u, "u")?;
        let local = self.curve.derivative_at(&self.local(u), r)?;
        Ok(local / power(&self.width(), r))
    }
}

/// The piece over [c, d] keeps the global parameter: the local restriction to
/// [t(c), t(d)], reparametrised over [c, d] (Θ(n³D)).
impl<S: Scalar, const D: usize> Subsegment<S, D> for Reparametrised<S, D> {
    type Segment = Reparametrised<S, D>;

    fn subsegment(&self, c: &S, d: &S) -> Result<Self> {
        check_interval(&self.domain(), c, d)?;
        Ok(Reparametrised {
            curve: self.curve.restrict(&self.local(c), &self.local(d))?,
            a: c.clone(),
            b: d.clone(),
        })
    }
}
