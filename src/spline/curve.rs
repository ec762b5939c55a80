//! The capabilities every curve type shares, as small traits in the spirit of kurbo's
//! `ParamCurve` family: a parametric curve has a [`Domain`] and evaluates on it ([`Curve`]);
//! where it is differentiable it has a derivative curve and derivatives of any order at a
//! parameter ([`CurveDerivative`]); where it can be cut it gives the piece over a
//! subinterval ([`Subsegment`]). Property tests, pictures and the Frenet frame are written
//! once over these traits.
//!
//! The conventions every implementation follows are stated on [`Curve`].

use super::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// The parameters at which a curve is defined.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Domain<S> {
    /// Every real parameter (a polynomial curve).
    Real,
    /// The closed interval [start, end], start < end (a piecewise curve over its partition).
    Interval {
        /// The first parameter, u₀.
        start: S,
        /// The last parameter, u_m.
        end: S,
    },
}

impl<S: Scalar> Domain<S> {
    /// The ends of an interval domain; `None` for [`Domain::Real`].
    pub fn bounds(&self) -> Option<(&S, &S)> {
        match self {
            Domain::Real => None,
            Domain::Interval { start, end } => Some((start, end)),
        }
    }

    /// `true` if `t` is a finite parameter of the domain (exact comparisons).
    ///
    /// ```
    /// use compgeo::spline::Domain;
    ///
    /// let d = Domain::Interval { start: 0.0, end: 2.0 };
    /// assert!(d.contains(&2.0) && !d.contains(&2.5) && !d.contains(&f64::NAN));
    /// assert!(Domain::Real.contains(&-1e300) && !Domain::<f64>::Real.contains(&f64::INFINITY));
    /// ```
    pub fn contains(&self, t: &S) -> bool {
        t.is_finite()
            && match self {
                Domain::Real => true,
                Domain::Interval { start, end } => start <= t && t <= end,
            }
    }

    /// Checks that `t` is a parameter of the domain.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming `name` if `t` is NaN or infinite, or outside the
    /// interval.
    pub fn check(&self, t: &S, name: &'static str) -> Result<()> {
        validate_parameter(t, name)?;
        match self {
            Domain::Interval { start, end } if t < start || t > end => {
                Err(Error::InvalidParameter {
                    name,
                    reason: format!(
                        "{} is outside [{}, {}]",
                        t.to_f64(),
                        start.to_f64(),
                        end.to_f64()
                    ),
                })
            }
            _ => Ok(()),
        }
    }
}

/// A parametric curve in R^D over the scalar field `S`: its domain and its points.
///
/// # Conventions
///
/// - **Parameters are values of the scalar field** `S` and are compared exactly (no epsilon):
///   with `BigRational` the knot a parameter falls on is decided exactly.
/// - **Evaluation returns `Result`**, for every type: an `f64` parameter can be NaN or
///   infinite, and a piecewise curve is only defined on its partition. A parameter outside the
///   [`Domain`] is an [`Error::InvalidParameter`]. Evaluation does not fail for overflow: with
///   `f64`, a point beyond the double range comes out with infinite coordinates (exact
///   scalars never overflow).
/// - **The domain is a closed interval or the whole line** ([`Domain`]). A polynomial curve
///   (a Bézier curve in its local parameter, a polynomial interpolant in any of its forms)
///   evaluates at every real parameter: its domain is [`Domain::Real`], and the control
///   polygon of a Bézier curve describes its segment over [0, 1] without limiting where it
///   can be evaluated. A piecewise curve (composite Bézier curves, splines, B-splines and
///   NURBS on [t_d, t_n]) is defined on its partition [u₀, u_m]: [`Domain::Interval`]. A
///   rational Bézier curve is defined on [0, 1] only, where its weights keep the denominator
///   positive.
/// - **A subsegment keeps the parameter**: the piece over [a, b] evaluates at u ∈ [a, b] to
///   the curve's point at u, so halves cut at c reproduce the curve on both sides of c.
///   Polynomial curves give their piece as a [`Reparametrised`](super::Reparametrised)
///   Bézier curve over [a, b] (the Bézier form of the polynomial on that interval), piecewise
///   curves as the same piecewise type over the cut partition.
/// - **Derivatives are with respect to the curve's own parameter**; at an interior knot of a
///   piecewise curve they are taken from the right (from the left at the domain's end).
///
/// # Example
///
/// ```
/// use compgeo::spline::{Bezier, Curve, CurveDerivative, Domain, Point, Subsegment};
///
/// // b(t) = (t, t²) as a Bézier parabola.
/// let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([0.5, 0.0]), Point::new([1.0, 1.0])])?;
/// assert_eq!(b.domain(), Domain::Real);
/// assert_eq!(b.eval(&3.0)?, Point::new([3.0, 9.0]));
/// assert_eq!(b.derivative_at(&3.0, 1)?, Point::new([1.0, 6.0]));
/// // The piece over [1, 2] keeps the parameter: at u = 1.5 it is b(1.5).
/// let piece = b.subsegment(&1.0, &2.0)?;
/// assert_eq!(piece.eval(&1.5)?, Point::new([1.5, 2.25]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub trait Curve<S: Scalar, const D: usize> {
    /// The parameters at which the curve is defined.
    fn domain(&self) -> Domain<S>;

    /// The point at the parameter `t`.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `t` is NaN, infinite, or outside the
    /// [`domain`](Curve::domain).
    fn eval(&self, t: &S) -> Result<Point<S, D>>;
}

/// A curve with derivatives: a derivative curve, and derivatives of any order at a parameter.
pub trait CurveDerivative<S: Scalar, const D: usize>: Curve<S, D> {
    /// The type of the first derivative (a Bézier curve's is a Bézier curve of one degree
    /// less, a polynomial form's a polynomial in the power basis).
    type Derivative: CurveDerivative<S, D>;

    /// The first derivative as a curve with the same domain.
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if, with `f64`, a coefficient of the derivative is beyond the
    /// double range.
    fn derivative_curve(&self) -> Result<Self::Derivative>;

    /// The r-th derivative at `t` (order 0 is the point itself).
    ///
    /// The default differentiates the curve r times and evaluates the last derivative (which
    /// has the same domain, so it checks `t` as [`Curve::eval`] does); types with a direct
    /// scheme (the tetrahedral algorithm of Bézier curves) override it.
    ///
    /// # Errors
    ///
    /// As [`Curve::eval`], and as [`derivative_curve`](CurveDerivative::derivative_curve).
    fn derivative_at(&self, t: &S, r: usize) -> Result<Point<S, D>> {
        if r == 0 {
            return self.eval(t);
        }
        self.derivative_curve()?.derivative_at(t, r - 1)
    }
}

/// A curve that can be cut: the piece over a subinterval of its domain, with the same
/// parameter.
pub trait Subsegment<S: Scalar, const D: usize>: Curve<S, D> {
    /// The type of a piece.
    type Segment: Curve<S, D>;

    /// The piece over [a, b], a < b both in the domain: a curve that agrees with this one at
    /// every u ∈ [a, b] (the parameter is kept, see [`Curve`]). The one exception is a
    /// piecewise curve whose pieces do not meet at an interior knot b: the curve takes the
    /// right piece's value there, the piece over [a, b] ends with the left piece's end.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `a` or `b` is not a parameter of the domain, or if
    /// `a ≥ b`; [`Error::Overflow`] if, with `f64`, a control point of the piece is beyond the
    /// double range.
    fn subsegment(&self, a: &S, b: &S) -> Result<Self::Segment>;
}

/// Checks the arguments of [`Subsegment::subsegment`]: both in `domain`, `a < b`.
pub(crate) fn check_interval<S: Scalar>(domain: &Domain<S>, a: &S, b: &S) -> Result<()> {
    domain.check(a, "a")?;
    domain.check(b, "b")?;
    if a >= b {
        return Err(Error::InvalidParameter {
            name: "interval",
            reason: format!("needs a < b, got a = {} and b = {}", a.to_f64(), b.to_f64()),
        });
    }
    Ok(())
}
