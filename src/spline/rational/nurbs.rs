//! NURBS curves: B-spline curves with positive weights, as the projection of a B-spline curve
//! in homogeneous coordinates.
//!
//! A NURBS curve of degree d with control points c₀, …, c_{n−1} ∈ R^D, weights
//! w₀, …, w_{n−1} > 0 and knots t₀ ≤ … ≤ t_{n+d} is
//! c(u) = Σ wᵢ·cᵢ·Nᵢ(u) / Σ wᵢ·Nᵢ(u) on the domain [t_d, t_n] [SPL, §14]. The curve keeps
//! its homogeneous form as two B-spline curves on the same [`KnotVector`]: the numerator
//! a = Σ wᵢ·cᵢ·Nᵢ (a [`BSpline<S, D>`] of the weighted points) and the denominator
//! w = Σ wᵢ·Nᵢ (a [`BSpline<S, 1>`] of the weights). Every linear operation of B-spline
//! curves then carries over by applying it to both, with no copy of its code: "knot
//! insertion, degree elevation and the control polygons of the pieces carry over to rational
//! curves by adding the extra coordinate and projecting afterwards" [SPL, §14]. Evaluation is
//! de Boor's algorithm on both and one division, knot insertion is [`BSpline::insert`] on both
//! (the same knots give the same α's, so this is exactly Boehm's insertion in R^{D+1}), and
//! the derivatives come from the basis derivatives by the quotient rule.
//!
//! **The denominator is positive.** On the domain [t_d, t_n] the basis functions are
//! non-negative and sum to one (for clamped and unclamped knot vectors alike, in this crate's
//! convention), so w(u) = Σ wᵢ·Nᵢ(u) ≥ min wᵢ > 0, and the division is always defined.
//! Insertion keeps the weights positive (each new weight is a convex combination of two).
//!
//! Degree elevation and the conversion to rational Bézier pieces are the B-spline operations
//! applied to [`Nurbs::homogeneous`], put back together by [`Nurbs::from_homogeneous`]
//! (respectively [`RationalBezier::from_homogeneous`](super::RationalBezier::from_homogeneous)
//! for each piece).
//!
//! Follows [SPL, §7 (the end), §14] and Piegl and Tiller, *The NURBS Book* (2nd ed., 1997),
//! §4.2–4.3 (NURBS curves, their derivatives) and §5.2 (knot insertion in homogeneous form).
//!
//! # Complexity
//!
//! Θ(nD) to build; Θ(d²D) per point after the span search; O(d² + d·K² + (d + k)D + k²D) for
//! the k-th derivative at a parameter (K = min(k, d)); Θ((n + d + rd)D) to insert a knot r
//! times.
//!
//! Invariants the tests check (exactly on rationals): the point is the quotient of the
//! weighted basis sums, all weights 1 give the B-spline curve, insertion leaves the curve
//! identical, the derivatives equal those of the quotient of the polynomial pieces, and a
//! NURBS curve on the knots 0, …, 0, 1, …, 1 is the rational Bézier curve of its data.

use super::quotient::quotient_derivatives;
use super::weights::{homogeneous, project, validate_weights};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bspline::{BSpline, KnotVector};
use crate::spline::curve::{Curve, CurveDerivative, Domain};
use crate::spline::scalar::{Point, Scalar};
use crate::{limits, Error, Result};

/// The NURBS evaluation, declared.
pub(crate) const NURBS_DE_BOOR: Declaration = Declaration {
    problem: "nurbs",
    name: "de-boor",
    function: "spline::Nurbs::de_boor",
    file: "src/spline/rational/nurbs.rs",
    summary: "de Boor's algorithm on the homogeneous control points, then one division",
    time: "Θ(d²D)",
    space: "O(dD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly d(d + 1) affine combinations per point off the knots, (d − r)(d − r + 1) at a knot of multiplicity r",
    source: "[SPL, §14]",
    claims: &[on("random-degree", Bound::Quadratic, Operation::ArithmeticOperations)],
};

/// The NURBS knot insertion, declared.
pub(crate) const NURBS_INSERT: Declaration = Declaration {
    problem: "nurbs",
    name: "insert",
    function: "spline::Nurbs::insert",
    file: "src/spline/rational/nurbs.rs",
    summary: "Boehm's insertion on the weighted points and on the weights (the same α's)",
    time: "Θ((n + d + rd)D)",
    space: "O((n + d + r)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "exactly 2(r(d − s) − r(r − 1)/2) affine combinations, s the knot's multiplicity before",
    source: "[SPL, §14]",
    claims: &[on(
        "random-degree",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// A NURBS curve of degree d: n control points in R^D with positive weights on a
/// [`KnotVector`] of n + d + 1 knots, over the scalar `S`.
///
/// Construct with [`Nurbs::new`] (control points, weights, knots) or
/// [`Nurbs::from_homogeneous`] (the weighted points and the weights as two B-spline curves);
/// both validate once, and the fields are private, so every `Nurbs` has finite control points
/// and finite, strictly positive weights.
///
/// ```
/// use compgeo::spline::{Curve, KnotVector, Nurbs, Point};
///
/// // A clamped quadratic with one interior knot; the weight 2 pulls it towards c₁.
/// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
/// let c = vec![
///     Point::new([0.0, 0.0]),
///     Point::new([1.0, 2.0]),
///     Point::new([3.0, 2.0]),
///     Point::new([4.0, 0.0]),
/// ];
/// let s = Nurbs::new(c, vec![1.0, 2.0, 1.0, 1.0], t)?;
/// assert_eq!(s.eval(&0.0)?, Point::new([0.0, 0.0]));
/// assert_eq!(s.eval(&1.0)?, Point::new([5.0 / 3.0, 2.0])); // (2·c₁ + c₂)/3
/// assert_eq!(s.eval(&2.0)?, Point::new([4.0, 0.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Nurbs<S, const D: usize> {
    control: Vec<Point<S, D>>,
    weights: Vec<S>,
    /// Σ s·wᵢ·cᵢ·Nᵢ, with the power of two s of `weights.rs` (one for exact scalars).
    numerator: BSpline<S, D>,
    /// Σ s·wᵢ·Nᵢ on the same knots.
    denominator: BSpline<S, 1>,
    /// s.
    scale: S,
}

impl<S: Scalar, const D: usize> Nurbs<S, D> {
    /// The curve with control points c₀, …, c_{n−1} and weights w₀, …, w_{n−1} on `knots`
    /// (which must serve exactly n control points: n + d + 1 knots).
    ///
    /// # Errors
    ///
    /// As [`BSpline::new`] for the control points and the knots ([`Error::Empty`],
    /// [`Error::InvalidParameter`] named `"knots"`, [`Error::NonFinite`]);
    /// [`Error::InvalidParameter`] named `"weights"` if there are not n weights, or naming the
    /// index and value of the first weight that is NaN, infinite, zero or negative;
    /// [`Error::Overflow`] if, with `f64`, a weighted coordinate is beyond the double range
    /// (the weights are scaled by a power of two first, see the [module](super) docs).
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space.
    ///
    /// ```
    /// use compgeo::spline::{KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(1, 3, 0.0, 1.0)?;
    /// let c = vec![Point::new([0.0]), Point::new([1.0]), Point::new([2.0])];
    /// let e = Nurbs::new(c.clone(), vec![1.0, -0.5, 1.0], t.clone()).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid weights: weight 1 is -0.5; weights must be finite and positive");
    /// let e = Nurbs::new(c, vec![1.0, 1.0, f64::INFINITY], t).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid weights: weight 2 is inf; weights must be finite and positive");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn new(control: Vec<Point<S, D>>, weights: Vec<S>, knots: KnotVector<S>) -> Result<Self> {
        // Validates the count and the coordinates, and is dropped again.
        let control = BSpline::new(control, knots.clone())?.into_parts().0;
        validate_weights(&weights, control.len())?;
        let h = homogeneous(&control, &weights)?;
        Ok(Nurbs {
            numerator: BSpline::new(h.points, knots.clone())?,
            denominator: BSpline::new(h.weights, knots)?,
            control,
            weights,
            scale: h.scale,
        })
    }

    /// The curve whose homogeneous form is `numerator` = Σ wᵢ·cᵢ·Nᵢ and `denominator` =
    /// Σ wᵢ·Nᵢ, on the same knots: weights wᵢ (the denominator's control points) and control
    /// points cᵢ = (wᵢ·cᵢ)/wᵢ. The way back from a linear operation of B-spline curves
    /// applied to both halves of [`Nurbs::homogeneous`] (degree elevation, say).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"knots"` if the two curves have different knot
    /// vectors; [`Error::InvalidParameter`] named `"weights"` naming the index and value of
    /// the first weight that is not strictly positive; [`Error::Overflow`] as for
    /// [`Nurbs::new`], or if, with `f64`, a control point (a quotient) is beyond the double
    /// range.
    ///
    /// # Complexity
    ///
    /// Θ((n + d)D) time and space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
    /// let num = BSpline::new(vec![Point::new([0.0]), Point::new([4.0])], t.clone())?;
    /// let den = BSpline::new(vec![Point::new([1.0]), Point::new([2.0])], t)?;
    /// let s = Nurbs::from_homogeneous(num, den)?;
    /// assert_eq!(s.control(), [Point::new([0.0]), Point::new([2.0])]);
    /// assert_eq!(s.weights(), [1.0, 2.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_homogeneous(numerator: BSpline<S, D>, denominator: BSpline<S, 1>) -> Result<Self> {
        if numerator.knots() != denominator.knots() {
            return Err(Error::InvalidParameter {
                name: "knots",
                reason: "the weighted points and the weights are on different knot vectors"
                    .to_string(),
            });
        }
        let weights: Vec<S> = denominator.control().iter().map(|w| w[0].clone()).collect();
        validate_weights(&weights, numerator.control().len())?;
        let control = project(numerator.control(), denominator.control());
        if !control.iter().all(Point::is_finite) {
            return Err(Error::Overflow {
                what: "the control points of a NURBS curve",
            });
        }
        let (_, knots) = numerator.into_parts();
        Nurbs::new(control, weights, knots)
    }

    /// The control points c₀, …, c_{n−1}.
    ///
    /// ```
    /// # use compgeo::spline::{KnotVector, Nurbs, Point};
    /// let s = Nurbs::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 4.0], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// assert_eq!(s.control(), [Point::new([1.0]), Point::new([2.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn control(&self) -> &[Point<S, D>] {
        &self.control
    }

    /// The weights w₀, …, w_{n−1}, as given (for a curve computed from another, such as an
    /// insertion, in the same units as the original's).
    ///
    /// ```
    /// # use compgeo::spline::{KnotVector, Nurbs, Point};
    /// let s = Nurbs::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 4.0], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// assert_eq!(s.weights(), [1.0, 4.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn weights(&self) -> &[S] {
        &self.weights
    }

    /// The knot vector.
    ///
    /// ```
    /// # use compgeo::spline::{KnotVector, Nurbs, Point};
    /// let s = Nurbs::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 4.0], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// assert_eq!(s.knots().knots(), [0.0, 0.0, 1.0, 1.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn knots(&self) -> &KnotVector<S> {
        self.numerator.knots()
    }

    /// The degree d.
    ///
    /// ```
    /// # use compgeo::spline::{KnotVector, Nurbs, Point};
    /// let s = Nurbs::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 4.0], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// assert_eq!(s.degree(), 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn degree(&self) -> usize {
        self.numerator.degree()
    }

    /// The homogeneous form: the numerator Σ s·wᵢ·cᵢ·Nᵢ and the denominator Σ s·wᵢ·Nᵢ as
    /// B-spline curves on the knots, where s is one for exact scalars and, for `f64`, the
    /// power of two that brings the largest weight into [1, 2) (an exact scaling that leaves
    /// the curve unchanged; see the [module](super) docs).
    ///
    /// ```
    /// # use compgeo::spline::{KnotVector, Nurbs, Point};
    /// let s = Nurbs::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 1.5], KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?)?;
    /// let (num, den) = s.homogeneous();
    /// assert_eq!(num.control(), [Point::new([1.0]), Point::new([3.0])]);
    /// assert_eq!(den.control(), [Point::new([1.0]), Point::new([1.5])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn homogeneous(&self) -> (&BSpline<S, D>, &BSpline<S, 1>) {
        (&self.numerator, &self.denominator)
    }

    /// The point c(u) by de Boor's algorithm in homogeneous coordinates. See
    /// [`Nurbs::de_boor_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN, infinite or outside the domain
    /// [t_d, t_n].
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time after the O(log(n − d)) span search, O(dD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
    /// let s = Nurbs::new(vec![Point::new([0.0]), Point::new([3.0])], vec![1.0, 2.0], t)?;
    /// assert_eq!(s.de_boor(&0.5)?, Point::new([2.0])); // (0·1 + 3·2)/(1 + 2)
    /// assert!(s.de_boor(&1.5).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_boor(&self, u: &S) -> Result<Point<S, D>> {
        self.de_boor_with(u, &mut NoCount)
    }

    /// The point c(u) by de Boor's algorithm in homogeneous coordinates, counting its affine
    /// combinations.
    ///
    /// Idea: run de Boor's algorithm ([`BSpline::de_boor_with`]) on the weighted points and
    /// on the weights (the scheme in R^{D+1}, the weights as its last coordinate), and divide
    /// a(u) by w(u) ≥ min wᵢ > 0 [SPL, §7 (the end), §14].
    ///
    /// # Errors
    ///
    /// As [`Nurbs::de_boor`].
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time after the O(log(n − d)) span search, O(dD) auxiliary space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// either scheme: exactly d(d + 1) when u is not a knot (and at the end of the domain),
    /// (d − r)(d − r + 1) at a knot of multiplicity r; and both span searches'
    /// [`comparison`](Counter::comparison)s. The division is not counted.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::uniform(3, 8, 0.0, 1.0)?;
    /// let s = Nurbs::new((0..8).map(|i| Point::new([i as f64])).collect(), vec![1.0; 8], t)?;
    /// let mut c = Counts::default();
    /// s.de_boor_with(&0.3, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 12); // 2 · 3·4/2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_boor_with<C: Counter>(&self, u: &S, counter: &mut C) -> Result<Point<S, D>> {
        let a = self.numerator.de_boor_with(u, counter)?;
        let w = self.denominator.de_boor_with(u, counter)?;
        Ok(a / &w[0])
    }

    /// The same curve with the knot `u` inserted `times` times. See [`Nurbs::insert_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::insert`]: [`Error::InvalidParameter`] named `"u"` or `"times"`,
    /// [`Error::LimitExceeded`], [`Error::Overflow`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d + rd)D) time, O((n + d + r)D) space for the new curve (r = `times`).
    ///
    /// ```
    /// use compgeo::spline::{Curve, KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])];
    /// let s = Nurbs::new(c, vec![1.0, 2.0, 1.0], t)?;
    /// let r = s.insert(&0.5, 1)?;
    /// assert_eq!(r.knots().knots(), [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]);
    /// assert_eq!(r.weights(), [1.0, 1.5, 1.5, 1.0]);
    /// assert_eq!(r.eval(&0.25)?, s.eval(&0.25)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn insert(&self, u: &S, times: usize) -> Result<Self> {
        self.insert_with(u, times, &mut NoCount)
    }

    /// The same curve with the knot `u` inserted `times` times, counting the affine
    /// combinations.
    ///
    /// Idea: insert u into the numerator and into the denominator with
    /// [`BSpline::insert_with`]. Both are on the same knots, so both use the same α's: this is
    /// Boehm's insertion of the homogeneous control points (wᵢ·cᵢ, wᵢ) in R^{D+1}, and the
    /// new weights are convex combinations of the old ones, positive again
    /// [SPL, §14], [PPB, §6.1].
    ///
    /// # Errors
    ///
    /// As [`Nurbs::insert`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d + rd)D) time, O((n + d + r)D) space (r = `times`).
    ///
    /// # Counts
    ///
    /// Those of [`BSpline::insert_with`], twice: exactly 2(r(d − s) − r(r − 1)/2)
    /// [`arithmetic_operation`](Counter::arithmetic_operation)s, s the multiplicity of u
    /// before as the knot t_μ, and both span searches' [`comparison`](Counter::comparison)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 6, 0.0, 3.0)?;
    /// let s = Nurbs::new((0..6).map(|i| Point::new([i as f64])).collect(), vec![1.0; 6], t)?;
    /// let mut c = Counts::default();
    /// s.insert_with(&0.5, 1, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn insert_with<C: Counter>(&self, u: &S, times: usize, counter: &mut C) -> Result<Self> {
        let numerator = self.numerator.insert_with(u, times, counter)?;
        let denominator = self.denominator.insert_with(u, times, counter)?;
        self.derived(numerator, denominator)
    }

    /// A curve from the homogeneous form of one computed from this curve (same scale s,
    /// positive weights by construction): its weights in the units of this curve's.
    fn derived(&self, numerator: BSpline<S, D>, denominator: BSpline<S, 1>) -> Result<Self> {
        let control = project(numerator.control(), denominator.control());
        let weights: Vec<S> = denominator
            .control()
            .iter()
            .map(|w| w[0].clone() / &self.scale)
            .collect();
        if !control.iter().all(Point::is_finite) || !weights.iter().all(S::is_finite) {
            return Err(Error::Overflow {
                what: "the control points of a NURBS curve",
            });
        }
        validate_weights(&weights, control.len())?;
        Ok(Nurbs {
            control,
            weights,
            numerator,
            denominator,
            scale: self.scale.clone(),
        })
    }

    /// The derivatives c, c′, …, c⁽ᵏ⁾ at u (checked): the derivatives of the numerator and
    /// the denominator from one table of basis derivatives, then the quotient rule.
    fn derivatives(&self, u: &S, k: usize) -> Result<Vec<Point<S, D>>> {
        limits::DEGREE.check(k as u128)?;
        let d = self.degree();
        let b = self.knots().basis_derivatives(u, k.min(d))?;
        let mut a = vec![Point::zero(); k + 1];
        let mut w = vec![S::zero(); k + 1];
        for j in 0..=k.min(d) {
            for (i, n) in b.order(j).iter().enumerate() {
                let index = b.first() + i;
                a[j] += &(self.numerator.control()[index].clone() * n);
                w[j] += &(self.denominator.control()[index][0].clone() * n);
            }
        }
        if !a.iter().all(Point::is_finite) || !w.iter().all(S::is_finite) {
            return Err(Error::Overflow {
                what: "NURBS derivative",
            });
        }
        quotient_derivatives(&a, &w)
    }
}

/// The point c(u) by [`Nurbs::de_boor`], on the domain [t_d, t_n].
impl<S: Scalar, const D: usize> Curve<S, D> for Nurbs<S, D> {
    fn domain(&self) -> Domain<S> {
        self.knots().domain()
    }

    fn eval(&self, t: &S) -> Result<Point<S, D>> {
        self.de_boor(t)
    }
}

/// Derivatives by the quotient rule of any order, from the right at interior knots and from
/// the left at the end of the domain; the derivative curve is a [`NurbsDerivative`].
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for Nurbs<S, D> {
    type Derivative = NurbsDerivative<S, D>;

    /// The first derivative as a [`NurbsDerivative`] (which evaluates by the quotient rule).
    ///
    /// # Errors
    ///
    /// None: the derivative is evaluated when asked for.
    ///
    /// # Complexity
    ///
    /// Θ((n + d)D) time and space (one copy of the curve).
    ///
    /// ```
    /// use compgeo::spline::{Curve, CurveDerivative, KnotVector, Nurbs, Point};
    ///
    /// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
    /// let s = Nurbs::new(vec![Point::new([0.0]), Point::new([1.0])], vec![1.0, 2.0], t)?;
    /// // c(u) = 2u/(1 + u), c′(u) = 2/(1 + u)².
    /// let ds = s.derivative_curve()?;
    /// assert_eq!(ds.eval(&1.0)?, Point::new([0.5]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn derivative_curve(&self) -> Result<NurbsDerivative<S, D>> {
        Ok(NurbsDerivative {
            curve: self.clone(),
            order: 1,
        })
    }

    /// The r-th derivative c⁽ʳ⁾(u) by the quotient rule of any order:
    /// c⁽ᵏ⁾ = (a⁽ᵏ⁾ − Σ_{i=1}^{k} C(k, i)·w⁽ⁱ⁾·c⁽ᵏ⁻ⁱ⁾)/w for k = 1, …, r, with the derivatives
    /// of the numerator a and the denominator w from one table of basis derivatives
    /// ([`KnotVector::basis_derivatives`]); a and w have no derivatives above the degree d,
    /// the curve has. From the right at an interior knot, from the left at the end of the
    /// domain.
    ///
    /// Follows Piegl and Tiller, *The NURBS Book*, §4.3, eq. (4.8).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` as for [`Curve::eval`];
    /// [`Error::LimitExceeded`] if `r` exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE);
    /// [`Error::Overflow`] if, with `f64`, a derivative is beyond the double range.
    ///
    /// # Complexity
    ///
    /// O(d² + d·K² + (d + r)D + r²D) time with K = min(r, d), O((r + 1)(d + 1) + rD) space.
    ///
    /// ```
    /// use compgeo::spline::{CurveDerivative, KnotVector, Nurbs, Point};
    ///
    /// // c(u) = 2u/(1 + u): c′ = 2/(1 + u)², c″ = −4/(1 + u)³.
    /// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
    /// let s = Nurbs::new(vec![Point::new([0.0]), Point::new([1.0])], vec![1.0, 2.0], t)?;
    /// assert_eq!(s.derivative_at(&0.0, 1)?, Point::new([2.0]));
    /// assert_eq!(s.derivative_at(&1.0, 2)?, Point::new([-0.5]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn derivative_at(&self, t: &S, r: usize) -> Result<Point<S, D>> {
        Ok(self.derivatives(t, r)?.swap_remove(r))
    }
}

/// The k-th derivative c⁽ᵏ⁾ (k ≥ 1) of a NURBS curve, as a curve on the same domain.
///
/// The derivative of a rational spline of degree d is a rational spline of degree 2d with
/// the denominator w², whose B-spline form needs products of splines; this type does not
/// build it, it evaluates c⁽ᵏ⁾ by the quotient rule ([`Nurbs`]'s
/// [`derivative_at`](CurveDerivative::derivative_at)) when asked.
///
/// ```
/// use compgeo::spline::{Curve, CurveDerivative, KnotVector, Nurbs, Point};
///
/// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
/// let s = Nurbs::new(vec![Point::new([0.0]), Point::new([1.0])], vec![1.0, 2.0], t)?;
/// let d2 = s.derivative_curve()?.derivative_curve()?;
/// assert_eq!(d2.order(), 2);
/// assert_eq!(d2.eval(&1.0)?, s.derivative_at(&1.0, 2)?);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct NurbsDerivative<S, const D: usize> {
    curve: Nurbs<S, D>,
    order: usize,
}

impl<S: Scalar, const D: usize> NurbsDerivative<S, D> {
    /// The curve this is a derivative of.
    pub fn curve(&self) -> &Nurbs<S, D> {
        &self.curve
    }

    /// The order k of the derivative.
    pub fn order(&self) -> usize {
        self.order
    }
}

/// c⁽ᵏ⁾(u) by the quotient rule, on the curve's domain.
impl<S: Scalar, const D: usize> Curve<S, D> for NurbsDerivative<S, D> {
    fn domain(&self) -> Domain<S> {
        self.curve.domain()
    }

    fn eval(&self, t: &S) -> Result<Point<S, D>> {
        self.curve.derivative_at(t, self.order)
    }
}

/// The derivative of c⁽ᵏ⁾ is c⁽ᵏ⁺¹⁾.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for NurbsDerivative<S, D> {
    type Derivative = NurbsDerivative<S, D>;

    fn derivative_curve(&self) -> Result<NurbsDerivative<S, D>> {
        let order = self.order + 1;
        limits::DEGREE.check(order as u128)?;
        Ok(NurbsDerivative {
            curve: self.curve.clone(),
            order,
        })
    }

    fn derivative_at(&self, t: &S, r: usize) -> Result<Point<S, D>> {
        self.curve.derivative_at(t, self.order.saturating_add(r))
    }
}
