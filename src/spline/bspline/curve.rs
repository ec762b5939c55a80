//! The B-spline curve type: control points on a knot vector, validated once, with the curve
//! traits.
//!
//! A curve of degree d with n control points c₀, …, c_{n−1} in R^D on the knots
//! t₀ ≤ … ≤ t_{n+d} (a [`KnotVector`]) is s(u) = Σ cᵢ Nᵢ(u) on its domain [t_d, t_n] (the
//! convention of the [module](super)). Its [`Curve`] implementation is de Boor's algorithm
//! (`de_boor.rs`); its [`CurveDerivative`] implementation the derivative curve
//! s′(u) = Σ d·(cᵢ − cᵢ₋₁)/(t_{i+d} − tᵢ)·N_i^{d−1}(u) on the knots without the two end ones
//! [PPB, §5.6, eq. (1)], and derivatives of any order at a parameter from the derivatives of
//! the basis ([`KnotVector::basis_derivatives`]).
//!
//! Follows [PPB, §5.4] (the B-spline curve and its control points) and [PPB, §5.6]
//! (derivatives).
//!
//! # Complexity
//!
//! Θ(nD) to build (the knot vector is already validated) and Θ((n + d)D) for the derivative
//! curve; a derivative of order k at a parameter takes O(d² + d·K² + dD) with K = min(k, d).
//!
//! Invariants the tests check (exactly on rationals): the derivative curve evaluates to the
//! derivative at every parameter; a clamped curve without interior knots is the Bézier curve
//! of the same control points.

use super::basis::quotient;
use super::KnotVector;
use crate::spline::curve::{Curve, CurveDerivative, Domain};
use crate::spline::scalar::{validate_points, Point, Scalar};
use crate::{Error, Result};

/// A B-spline curve of degree d: n control points in R^D on a [`KnotVector`] of n + d + 1
/// knots, over the scalar `S`.
///
/// Construct with [`BSpline::new`], which checks that the counts match and every coordinate is
/// finite; the fields are private, so a `BSpline` is always valid.
///
/// ```
/// use compgeo::spline::{BSpline, Curve, Domain, KnotVector, Point};
///
/// // A clamped quadratic with one interior knot: it starts at c₀ and ends at c₃.
/// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
/// let c = vec![
///     Point::new([0.0, 0.0]),
///     Point::new([1.0, 2.0]),
///     Point::new([3.0, 2.0]),
///     Point::new([4.0, 0.0]),
/// ];
/// let s = BSpline::new(c, t)?;
/// assert_eq!(s.domain(), Domain::Interval { start: 0.0, end: 2.0 });
/// assert_eq!(s.eval(&0.0)?, Point::new([0.0, 0.0]));
/// assert_eq!(s.eval(&1.0)?, Point::new([2.0, 2.0])); // the midpoint of c₁c₂
/// assert_eq!(s.eval(&2.0)?, Point::new([4.0, 0.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BSpline<S, const D: usize> {
    control: Vec<Point<S, D>>,
    knots: KnotVector<S>,
}

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The curve with control points c₀, …, c_{n−1} on `knots` (which must serve exactly n
    /// control points: n + d + 1 knots).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no control points; [`Error::InvalidParameter`] named `"knots"` if
    /// the knot vector serves another number of control points (naming both counts);
    /// [`Error::NonFinite`] naming the first control point with a NaN or infinite coordinate.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time to check the points, no auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(1, 3, 0.0, 1.0)?;
    /// let e = BSpline::new(vec![Point::new([0.0]), Point::new([1.0])], t.clone()).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid knots: 2 control points of degree 1 need 4 knots, got 5");
    /// let c = vec![Point::new([0.0]), Point::new([f64::NAN]), Point::new([1.0])];
    /// let e = BSpline::new(c, t).unwrap_err();
    /// assert_eq!(e.to_string(), "point 1 has a non-finite coordinate (NaN)");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn new(control: Vec<Point<S, D>>, knots: KnotVector<S>) -> Result<Self> {
        if control.is_empty() {
            return Err(Error::Empty {
                what: "B-spline control polygon",
            });
        }
        knots.check_control_points(control.len())?;
        validate_points(&control, "B-spline control polygon")?;
        Ok(BSpline { control, knots })
    }

    /// The control points c₀, …, c_{n−1}.
    ///
    /// ```
    /// # use compgeo::spline::{BSpline, KnotVector, Point};
    /// let s = BSpline::new(vec![Point::new([1.0]), Point::new([2.0])], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// assert_eq!(s.control(), [Point::new([1.0]), Point::new([2.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn control(&self) -> &[Point<S, D>] {
        &self.control
    }

    /// The knot vector.
    ///
    /// ```
    /// # use compgeo::spline::{BSpline, KnotVector, Point};
    /// let s = BSpline::new(vec![Point::new([1.0]), Point::new([2.0])], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// assert_eq!(s.knots().knots(), [0.0, 0.0, 1.0, 1.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn knots(&self) -> &KnotVector<S> {
        &self.knots
    }

    /// The degree d.
    ///
    /// ```
    /// # use compgeo::spline::{BSpline, KnotVector, Point};
    /// let s = BSpline::new(vec![Point::new([1.0]), Point::new([2.0])], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// assert_eq!(s.degree(), 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The control points and the knot vector, by value.
    ///
    /// ```
    /// # use compgeo::spline::{BSpline, KnotVector, Point};
    /// let s = BSpline::new(vec![Point::new([1.0]), Point::new([2.0])], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// let (c, t) = s.into_parts();
    /// assert_eq!((c.len(), t.degree()), (2, 1));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn into_parts(self) -> (Vec<Point<S, D>>, KnotVector<S>) {
        (self.control, self.knots)
    }

    /// A curve computed from a valid one (the counts match by construction): an error if,
    /// with `f64`, a control point overflowed.
    pub(super) fn derived(
        control: Vec<Point<S, D>>,
        knots: KnotVector<S>,
        what: &'static str,
    ) -> Result<Self> {
        debug_assert_eq!(control.len(), knots.control_points());
        if control.iter().all(Point::is_finite) {
            Ok(BSpline { control, knots })
        } else {
            Err(Error::Overflow { what })
        }
    }

    /// [`BSpline::derived`] for a curve whose control points outside `computed` are copies of
    /// a valid curve's: only the computed ones are checked.
    pub(super) fn derived_in(
        control: Vec<Point<S, D>>,
        knots: KnotVector<S>,
        computed: std::ops::Range<usize>,
        what: &'static str,
    ) -> Result<Self> {
        debug_assert_eq!(control.len(), knots.control_points());
        if control[computed].iter().all(Point::is_finite) {
            debug_assert!(control.iter().all(Point::is_finite));
            Ok(BSpline { control, knots })
        } else {
            Err(Error::Overflow { what })
        }
    }
}

/// The point s(u) by de Boor's algorithm ([`BSpline::de_boor`]), on the domain [t_d, t_n].
impl<S: Scalar, const D: usize> Curve<S, D> for BSpline<S, D> {
    fn domain(&self) -> Domain<S> {
        self.knots.domain()
    }

    fn eval(&self, t: &S) -> Result<Point<S, D>> {
        self.de_boor(t)
    }
}

/// The derivative curve of degree d − 1 [PPB, §5.6, eq. (1)], and derivatives at a parameter
/// from the basis derivatives: from the right at interior knots, from the left at the end of
/// the domain.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for BSpline<S, D> {
    type Derivative = BSpline<S, D>;

    /// The derivative s′ as a B-spline of degree d − 1 on t₁, …, t_{n+d−1} (the knots without
    /// the two end ones, so the domain is the same), with the n − 1 control points
    /// dᵢ = d·(cᵢ − cᵢ₋₁)/(t_{i+d} − tᵢ), i = 1, …, n − 1 [PPB, §5.6, eq. (1)].
    ///
    /// Where an interior knot has multiplicity d + 1 (the curve may jump there), the term with
    /// t_{i+d} = tᵢ belongs to a basis function with an empty support: it and one copy of the
    /// knot are dropped, so the knot keeps multiplicity d, the most degree d − 1 allows, and the
    /// derivative is still the derivative of each piece. A curve of degree 0 has the zero
    /// curve of degree 0 on the same knots as its derivative.
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if, with `f64`, a control point of the derivative is beyond the
    /// double range (knots a subnormal distance apart, or coordinates near the top of the
    /// range).
    ///
    /// # Complexity
    ///
    /// Θ((n + d)D) time and space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, CurveDerivative, KnotVector, Point};
    ///
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let c = vec![Point::new([0.0]), Point::new([1.0]), Point::new([3.0]), Point::new([4.0])];
    /// let ds = BSpline::new(c, t)?.derivative_curve()?;
    /// assert_eq!(ds.degree(), 1);
    /// assert_eq!(ds.knots().knots(), [0.0, 0.0, 1.0, 2.0, 2.0]);
    /// assert_eq!(ds.control(), [Point::new([2.0]), Point::new([2.0]), Point::new([2.0])]);
    /// assert_eq!(ds.eval(&0.5)?, Point::new([2.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn derivative_curve(&self) -> Result<BSpline<S, D>> {
        let d = self.degree();
        let t = self.knots.knots();
        if d == 0 {
            let zero = vec![Point::zero(); self.control.len()];
            return BSpline::derived(zero, self.knots.clone(), "B-spline derivative");
        }
        let n = self.control.len();
        let factor = S::from_i64(d as i64);
        let mut control = Vec::with_capacity(n - 1);
        // One copy of each knot of multiplicity d + 1 whose function has an empty support.
        let mut dropped = Vec::new();
        for i in 1..n {
            let (lo, hi) = (&t[i], &t[i + d]);
            if lo == hi {
                dropped.push(lo);
                continue;
            }
            let diff = self.control[i].clone() - &self.control[i - 1];
            control.push(Point::new(std::array::from_fn(|j| {
                quotient(factor.clone() * &diff[j], lo, hi)
            })));
        }
        // N_i^{d−1} on t_i, …, t_{i+d} is the derivative knots' function i − 1 (t′_j = t_{j+1}).
        let mut knots = Vec::with_capacity(n + d - 1);
        let mut pending = dropped.into_iter().peekable();
        for k in &t[1..n + d] {
            if pending.next_if(|v| *v == k).is_none() {
                knots.push(k.clone());
            }
        }
        let knots = KnotVector::new(d - 1, knots)?;
        BSpline::derived(control, knots, "B-spline derivative")
    }

    /// The r-th derivative s⁽ʳ⁾(u) = Σ cᵢ Nᵢ⁽ʳ⁾(u) from the basis derivatives
    /// ([`KnotVector::basis_derivatives`]); zero for r > d. From the right at an interior
    /// knot, from the left at the end of the domain.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] as [`Curve::eval`]; [`Error::Overflow`] if, with `f64`, the
    /// derivative is beyond the double range.
    ///
    /// # Complexity
    ///
    /// O(d² + d·K² + dD) time with K = min(r, d), O((r + 1)(d + 1)) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, CurveDerivative, KnotVector, Point};
    ///
    /// // s(u) = u² on [0, 1] as a clamped quadratic: c = 0, 0, 1.
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = BSpline::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])], t)?;
    /// assert_eq!(s.derivative_at(&0.5, 1)?, Point::new([1.0]));
    /// assert_eq!(s.derivative_at(&0.5, 2)?, Point::new([2.0]));
    /// assert_eq!(s.derivative_at(&0.5, 7)?, Point::new([0.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn derivative_at(&self, t: &S, r: usize) -> Result<Point<S, D>> {
        if r == 0 {
            return self.eval(t);
        }
        let d = self.degree();
        if r > d {
            self.knots.domain().check(t, "u")?;
            return Ok(Point::zero());
        }
        let b = self.knots.basis_derivatives(t, r)?;
        let mut sum = Point::zero();
        for (k, n) in b.order(r).iter().enumerate() {
            sum += &(self.control[b.first() + k].clone() * n);
        }
        if sum.is_finite() {
            Ok(sum)
        } else {
            Err(Error::Overflow {
                what: "B-spline derivative",
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line() -> BSpline<f64, 1> {
        let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).unwrap();
        let c = [0.0, 1.0, 5.0, 6.0].map(|x| Point::new([x])).to_vec();
        BSpline::new(c, t).unwrap()
    }

    #[test]
    fn a_knot_of_multiplicity_d_plus_one_keeps_the_derivative_valid() {
        // Degree 1, a jump at 1: pieces 0→1 on [0, 1] and 5→6 on [1, 2], both of slope 1.
        let s = line();
        let ds = s.derivative_curve().unwrap();
        assert_eq!(ds.knots().knots(), [0.0, 1.0, 2.0]);
        assert_eq!(ds.control(), [Point::new([1.0]), Point::new([1.0])]);
        for u in [0.0, 0.5, 1.0, 1.5, 2.0] {
            assert_eq!(ds.eval(&u).unwrap(), Point::new([1.0]), "{u}");
            assert_eq!(s.derivative_at(&u, 1).unwrap(), Point::new([1.0]), "{u}");
        }
        assert_eq!(s.eval(&1.0).unwrap(), Point::new([5.0])); // right-continuous
    }

    #[test]
    fn degree_zero_differentiates_to_zero() {
        let t = KnotVector::new(0, vec![0.0, 1.0, 2.0]).unwrap();
        let s = BSpline::new(vec![Point::new([3.0]), Point::new([4.0])], t).unwrap();
        let ds = s.derivative_curve().unwrap();
        assert_eq!(ds.control(), [Point::new([0.0]), Point::new([0.0])]);
        assert_eq!(s.derivative_at(&1.5, 1).unwrap(), Point::new([0.0]));
        assert!(s.derivative_at(&2.5, 1).is_err());
    }

    #[test]
    fn subnormal_knot_distances_overflow_the_derivative_as_an_error() {
        let tiny = f64::from_bits(1);
        let t = KnotVector::new(1, vec![0.0, 0.0, tiny, 1.0, 1.0]).unwrap();
        let c = [0.0, 1.0, 2.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        assert!(matches!(s.derivative_curve(), Err(Error::Overflow { .. })));
        assert!(matches!(
            s.derivative_at(&0.0, 1),
            Err(Error::Overflow { .. })
        ));
        assert_eq!(s.eval(&tiny).unwrap(), Point::new([1.0]));
    }
}
