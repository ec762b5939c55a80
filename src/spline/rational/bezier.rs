//! Rational Bézier curves: control points with positive weights, evaluated as the projection
//! of a polynomial Bézier curve in homogeneous coordinates.
//!
//! A rational Bézier curve of degree n in R^D with control points b₀, …, bₙ and weights
//! w₀, …, wₙ > 0 is r(t) = Σ wᵢ·bᵢ·Bᵢⁿ(t) / Σ wᵢ·Bᵢⁿ(t), t ∈ [0, 1]: the polynomial curve
//! with the homogeneous control points (wᵢ·bᵢ, wᵢ) ∈ R^{D+1}, its first D coordinates divided
//! by the last [SPL, §14]. The numerator a(t) = Σ wᵢ·bᵢ·Bᵢⁿ(t) and the denominator
//! w(t) = Σ wᵢ·Bᵢⁿ(t) are kept as two [`Bezier`] curves, so evaluation, derivatives and
//! every linear operation run the polynomial code on them. With all weights equal the curve is
//! the polynomial Bézier curve of the same control points.
//!
//! **Domain.** With positive weights, w(t) ≥ min wᵢ > 0 on [0, 1] (the Bernstein polynomials
//! are non-negative and sum to one there), so the division is always defined; outside [0, 1]
//! w may vanish. The domain is therefore the interval [0, 1], not the whole line as for
//! polynomial Bézier curves.
//!
//! Follows [SPL, §14] (rational curves as projections of polynomial ones; the course's
//! rational Bézier curves are its "tema anterior") and Piegl and Tiller, *The NURBS Book*
//! (2nd ed., 1997), §1.4 (rational Bézier curves) and §4.3 (their derivatives).
//!
//! # Complexity
//!
//! Θ(nD) to build; Θ(n²D) per point (two de Casteljau schemes), Θ(k·n²D + k²D) for the k-th
//! derivative at a parameter, Θ(n²D) for the derivative curve of degree 2n.
//!
//! Invariants the tests check (exactly on rationals): the point is the quotient of the
//! weighted Bernstein sums, equal weights give the polynomial curve, the rational Bézier
//! curve equals the NURBS curve with the same data on the knots 0, …, 0, 1, …, 1, the
//! derivatives equal those of the quotient of polynomials, and the derivative curve evaluates
//! to the derivative.

use super::quotient::quotient_derivatives;
use super::weights::{homogeneous, project, validate_weights};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::Bezier;
use crate::spline::curve::{Curve, CurveDerivative, Domain};
use crate::spline::scalar::{binomial, validate_points, Point, Scalar};
use crate::{limits, Error, Result};

/// The rational de Casteljau evaluation, declared.
pub(crate) const RATIONAL_DE_CASTELJAU: Declaration = Declaration {
    problem: "rational-bezier",
    name: "de-casteljau",
    function: "spline::RationalBezier::de_casteljau",
    file: "src/spline/rational/bezier.rs",
    summary: "de Casteljau's scheme on the homogeneous control points, then one division",
    time: "Θ(n²D)",
    space: "O(nD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1) affine combinations per point: n(n + 1)/2 on the weighted points and as many on the weights",
    source: "[SPL, §14]",
    claims: &[on("random-degree", Bound::Quadratic, Operation::ArithmeticOperations)],
};

/// A rational Bézier curve of degree n: n + 1 control points in R^D with positive weights,
/// over the scalar `S`, on the domain [0, 1].
///
/// Construct with [`RationalBezier::new`] (control points and weights) or
/// [`RationalBezier::from_homogeneous`] (the weighted points and the weights as two Bézier
/// curves); both validate once, and the fields are private, so every `RationalBezier` has
/// finite control points and finite, strictly positive weights.
///
/// ```
/// use compgeo::spline::{Curve, Point, RationalBezier};
///
/// // The quarter of the unit circle ((1 − t²)/(1 + t²), 2t/(1 + t²)): weights 1, 1, 2.
/// let c = vec![Point::new([1.0, 0.0]), Point::new([1.0, 1.0]), Point::new([0.0, 1.0])];
/// let r = RationalBezier::new(c, vec![1.0, 1.0, 2.0])?;
/// assert_eq!(r.eval(&0.5)?, Point::new([0.6, 0.8]));
/// assert_eq!(r.eval(&1.0)?, Point::new([0.0, 1.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBezier<S, const D: usize> {
    control: Vec<Point<S, D>>,
    weights: Vec<S>,
    /// Σ s·wᵢ·bᵢ·Bᵢⁿ, with the power of two s of `weights.rs` (one for exact scalars).
    numerator: Bezier<S, D>,
    /// Σ s·wᵢ·Bᵢⁿ.
    denominator: Bezier<S, 1>,
}

impl<S: Scalar, const D: usize> RationalBezier<S, D> {
    /// The curve with control points b₀, …, bₙ and weights w₀, …, wₙ.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no control points; [`Error::NonFinite`] naming the first control
    /// point with a NaN or infinite coordinate; [`Error::InvalidParameter`] named `"weights"`
    /// if there are not n + 1 weights, or naming the index and value of the first weight that
    /// is NaN, infinite, zero or negative; [`Error::LimitExceeded`] beyond
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE); [`Error::Overflow`] if, with `f64`, a
    /// weighted coordinate is beyond the double range (see the [module](super) docs on the
    /// scaling of the weights).
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space.
    ///
    /// ```
    /// use compgeo::spline::{Point, RationalBezier};
    ///
    /// let c = vec![Point::new([0.0]), Point::new([1.0]), Point::new([2.0])];
    /// let e = RationalBezier::new(c.clone(), vec![1.0, 0.0, 1.0]).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid weights: weight 1 is 0; weights must be finite and positive");
    /// let e = RationalBezier::new(c.clone(), vec![1.0, 1.0, f64::NAN]).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid weights: weight 2 is NaN; weights must be finite and positive");
    /// let e = RationalBezier::new(c, vec![1.0, 2.0]).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid weights: 3 control points need 3 weights, got 2");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn new(control: Vec<Point<S, D>>, weights: Vec<S>) -> Result<Self> {
        validate_points(&control, "rational Bézier control polygon")?;
        limits::DEGREE.check(control.len() as u128 - 1)?;
        validate_weights(&weights, control.len())?;
        let h = homogeneous(&control, &weights)?;
        Ok(RationalBezier {
            control,
            weights,
            numerator: Bezier::new(h.points)?,
            denominator: Bezier::new(h.weights)?,
        })
    }

    /// The curve whose homogeneous form is `numerator` = Σ wᵢ·bᵢ·Bᵢⁿ and `denominator` =
    /// Σ wᵢ·Bᵢⁿ: weights wᵢ (the denominator's control points) and control points
    /// bᵢ = (wᵢ·bᵢ)/wᵢ. The way back from the linear operations of polynomial Bézier curves
    /// (subdivision, degree elevation) applied to both.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"weights"` if the two curves have different degrees,
    /// or naming the index and value of the first weight that is not strictly positive;
    /// [`Error::Overflow`] as for [`RationalBezier::new`], or if, with `f64`, a control point
    /// (a quotient) is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point, RationalBezier};
    ///
    /// let num = Bezier::new(vec![Point::new([0.0]), Point::new([2.0]), Point::new([2.0])])?;
    /// let den = Bezier::new(vec![Point::new([1.0]), Point::new([2.0]), Point::new([1.0])])?;
    /// let r = RationalBezier::from_homogeneous(num, den)?;
    /// assert_eq!(r.control(), [Point::new([0.0]), Point::new([1.0]), Point::new([2.0])]);
    /// assert_eq!(r.weights(), [1.0, 2.0, 1.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_homogeneous(numerator: Bezier<S, D>, denominator: Bezier<S, 1>) -> Result<Self> {
        let weights: Vec<S> = denominator.control().iter().map(|w| w[0].clone()).collect();
        validate_weights(&weights, numerator.control().len())?;
        let control = project(numerator.control(), denominator.control());
        if !control.iter().all(Point::is_finite) {
            return Err(Error::Overflow {
                what: "the control points of a rational Bézier curve",
            });
        }
        RationalBezier::new(control, weights)
    }

    /// The control points b₀, …, bₙ.
    ///
    /// ```
    /// # use compgeo::spline::{Point, RationalBezier};
    /// let r = RationalBezier::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 3.0])?;
    /// assert_eq!(r.control(), [Point::new([1.0]), Point::new([2.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn control(&self) -> &[Point<S, D>] {
        &self.control
    }

    /// The weights w₀, …, wₙ, as given.
    ///
    /// ```
    /// # use compgeo::spline::{Point, RationalBezier};
    /// let r = RationalBezier::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 3.0])?;
    /// assert_eq!(r.weights(), [1.0, 3.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn weights(&self) -> &[S] {
        &self.weights
    }

    /// The degree n.
    ///
    /// ```
    /// # use compgeo::spline::{Point, RationalBezier};
    /// let r = RationalBezier::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 3.0])?;
    /// assert_eq!(r.degree(), 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn degree(&self) -> usize {
        self.control.len() - 1
    }

    /// The homogeneous form: the numerator Σ s·wᵢ·bᵢ·Bᵢⁿ and the denominator Σ s·wᵢ·Bᵢⁿ as
    /// Bézier curves, where s is one for exact scalars and, for `f64`, the power of two
    /// that brings the largest weight into [1, 2) (an exact scaling that leaves the curve
    /// unchanged; see the [module](super) docs).
    ///
    /// ```
    /// # use compgeo::spline::{Point, RationalBezier};
    /// let r = RationalBezier::new(vec![Point::new([1.0]), Point::new([2.0])], vec![1.0, 1.5])?;
    /// let (num, den) = r.homogeneous();
    /// assert_eq!(num.control(), [Point::new([1.0]), Point::new([3.0])]);
    /// assert_eq!(den.control(), [Point::new([1.0]), Point::new([1.5])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn homogeneous(&self) -> (&Bezier<S, D>, &Bezier<S, 1>) {
        (&self.numerator, &self.denominator)
    }

    /// The point r(t) by de Casteljau's algorithm in homogeneous coordinates. See
    /// [`RationalBezier::de_casteljau_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"t"` if `t` is NaN, infinite or outside [0, 1].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Point, RationalBezier};
    ///
    /// // Weights 1, 2, 1 pull the parabola towards its middle control point.
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])];
    /// let r = RationalBezier::new(c, vec![1.0, 2.0, 1.0])?;
    /// assert_eq!(r.de_casteljau(&0.5)?, Point::new([1.0, 4.0 / 3.0]));
    /// assert!(r.de_casteljau(&1.5).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_casteljau(&self, t: &S) -> Result<Point<S, D>> {
        self.de_casteljau_with(t, &mut NoCount)
    }

    /// The point r(t) by de Casteljau's algorithm in homogeneous coordinates, counting its
    /// affine combinations.
    ///
    /// Idea: run de Casteljau's scheme on the weighted points wᵢ·bᵢ and on the weights (the
    /// scheme in R^{D+1}, one coordinate at a time), and divide the point a(t) by the weight
    /// w(t) > 0. For t ∈ [0, 1] every step is a convex combination, of points and of positive
    /// weights.
    ///
    /// Follows [SPL, §14] and [PPB, §2.3].
    ///
    /// # Errors
    ///
    /// As [`RationalBezier::de_casteljau`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, O(nD) auxiliary space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// exactly n(n + 1), n(n + 1)/2 on the weighted points and as many on the weights (the
    /// division is not counted).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Point, RationalBezier};
    ///
    /// let r = RationalBezier::new((0..4).map(|i| Point::new([i as f64])).collect(), vec![1.0; 4])?;
    /// let mut c = Counts::default();
    /// assert_eq!(r.de_casteljau_with(&0.25, &mut c)?, Point::new([0.75]));
    /// assert_eq!(c.arithmetic_operations, 12); // 2 · 3·4/2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_casteljau_with<C: Counter>(&self, t: &S, counter: &mut C) -> Result<Point<S, D>> {
        self.domain().check(t, "t")?;
        let a = self.numerator.de_casteljau_with(t, counter)?;
        let w = self.denominator.de_casteljau_with(t, counter)?;
        Ok(a / &w[0])
    }

    /// The derivatives r, r′, …, r⁽ᵏ⁾ at t (checked), by the quotient rule on the
    /// derivatives of the numerator and the denominator.
    fn derivatives(&self, t: &S, k: usize) -> Result<Vec<Point<S, D>>> {
        self.domain().check(t, "t")?;
        limits::DEGREE.check(k as u128)?;
        let mut a = Vec::with_capacity(k + 1);
        let mut w = Vec::with_capacity(k + 1);
        for j in 0..=k {
            a.push(self.numerator.derivative_at(t, j)?);
            w.push(self.denominator.derivative_at(t, j)?[0].clone());
        }
        quotient_derivatives(&a, &w)
    }
}

/// The point r(t) by [`RationalBezier::de_casteljau`], on the domain [0, 1].
impl<S: Scalar, const D: usize> Curve<S, D> for RationalBezier<S, D> {
    fn domain(&self) -> Domain<S> {
        Domain::Interval {
            start: S::zero(),
            end: S::one(),
        }
    }

    fn eval(&self, t: &S) -> Result<Point<S, D>> {
        self.de_casteljau(t)
    }
}

/// The derivative of a rational Bézier curve of degree n is a rational Bézier curve of
/// degree 2n; derivatives at a parameter come from the quotient rule of any order.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for RationalBezier<S, D> {
    type Derivative = RationalBezier<S, D>;

    /// The derivative r′ = (a′w − aw′)/w² as a rational Bézier curve of degree 2n: its
    /// denominator is w², whose Bernstein coefficients Σ_{i+j=k} C(n, i)·C(n, j)/C(2n, k)·wᵢ·wⱼ
    /// are positive, so they are valid weights; its numerator a′w − aw′ has degree 2n − 1
    /// (the terms of degree 2n cancel) and is raised to degree 2n. The products of Bernstein
    /// forms use (Σ pᵢBᵢᵐ)(Σ qⱼBⱼⁿ) = Σₖ Σ_{i+j=k} C(m, i)·C(n, j)/C(m + n, k)·pᵢqⱼ·Bₖᵐ⁺ⁿ.
    /// A curve of degree 0 has the zero curve of degree 0 as its derivative.
    ///
    /// Follows Piegl and Tiller, *The NURBS Book*, §4.3 (the derivative of a rational curve)
    /// and [PPB, §2.4, §3.11] (hodographs, degree elevation).
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if 2n exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE);
    /// [`Error::Overflow`] if, with `f64`, a control point or weight of the derivative is
    /// beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, Θ(nD) space.
    ///
    /// ```
    /// use compgeo::spline::{Curve, CurveDerivative, Point, RationalBezier};
    ///
    /// let c = vec![Point::new([1.0, 0.0]), Point::new([1.0, 1.0]), Point::new([0.0, 1.0])];
    /// let r = RationalBezier::new(c, vec![1.0, 1.0, 2.0])?;
    /// let dr = r.derivative_curve()?;
    /// assert_eq!(dr.degree(), 4);
    /// // ((1 − t²)/(1 + t²), 2t/(1 + t²))′ = (−4t, 2 − 2t²)/(1 + t²)².
    /// assert_eq!(dr.eval(&0.0)?, Point::new([0.0, 2.0]));
    /// assert_eq!(dr.eval(&1.0)?, Point::new([-1.0, 0.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn derivative_curve(&self) -> Result<RationalBezier<S, D>> {
        let n = self.degree();
        limits::DEGREE.check(2 * n as u128)?;
        let (a, w) = (&self.numerator, &self.denominator);
        let (da, dw) = (a.hodograph()?, w.hodograph()?);
        let scalars =
            |b: &Bezier<S, 1>| -> Vec<S> { b.control().iter().map(|p| p[0].clone()).collect() };
        let (ws, dws) = (scalars(w), scalars(&dw));
        let left = Bezier::new(product(da.control(), &ws))?.elevate_to(2 * n)?;
        let right = Bezier::new(product(a.control(), &dws))?.elevate_to(2 * n)?;
        let numerator: Vec<Point<S, D>> = left
            .control()
            .iter()
            .zip(right.control())
            .map(|(l, r)| l.clone() - r)
            .collect();
        let square: Vec<Point<S, 1>> = product(w.control(), &ws);
        if !numerator.iter().all(Point::is_finite) || !square.iter().all(Point::is_finite) {
            return Err(Error::Overflow {
                what: "rational Bézier derivative",
            });
        }
        RationalBezier::from_homogeneous(Bezier::new(numerator)?, Bezier::new(square)?)
    }

    /// The r-th derivative r⁽ʳ⁾(t) by the quotient rule of any order:
    /// r⁽ᵏ⁾ = (a⁽ᵏ⁾ − Σ_{i=1}^{k} C(k, i)·w⁽ⁱ⁾·r⁽ᵏ⁻ⁱ⁾)/w for k = 1, …, r, with the derivatives
    /// of the numerator a and the denominator w from the tetrahedral algorithm
    /// ([`Bezier::derivative_at`](CurveDerivative::derivative_at)). Unlike a polynomial curve's,
    /// the derivatives of every order can be nonzero.
    ///
    /// Follows Piegl and Tiller, *The NURBS Book*, eq. (4.8).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"t"` as for [`Curve::eval`];
    /// [`Error::LimitExceeded`] if `r` exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE);
    /// [`Error::Overflow`] if, with `f64`, a derivative is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(r·n²D + r²D) time, O((n + r)D) space.
    ///
    /// ```
    /// use compgeo::spline::{CurveDerivative, Point, RationalBezier};
    ///
    /// // 1/(1 + t) as the rational line with weights 1, 2 through 1 and 1/2.
    /// let r = RationalBezier::new(vec![Point::new([1.0]), Point::new([0.5])], vec![1.0, 2.0])?;
    /// assert_eq!(r.derivative_at(&0.0, 1)?, Point::new([-1.0]));
    /// assert_eq!(r.derivative_at(&0.0, 2)?, Point::new([2.0]));
    /// assert_eq!(r.derivative_at(&1.0, 3)?, Point::new([-0.375])); // −6/(1 + t)⁴
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    fn derivative_at(&self, t: &S, r: usize) -> Result<Point<S, D>> {
        Ok(self.derivatives(t, r)?.swap_remove(r))
    }
}

/// The Bernstein coefficients of the product of two polynomials in Bernstein form, of degrees
/// m = `p.len() − 1` and n = `q.len() − 1`: degree m + n.
fn product<S: Scalar, const D: usize>(p: &[Point<S, D>], q: &[S]) -> Vec<Point<S, D>> {
    let (m, n) = (p.len() - 1, q.len() - 1);
    let mut out = vec![Point::zero(); m + n + 1];
    for (i, pi) in p.iter().enumerate() {
        for (j, qj) in q.iter().enumerate() {
            let c = binomial::<S>(m, i) * binomial::<S>(n, j) / binomial::<S>(m + n, i + j);
            out[i + j] += &(pi.clone() * (c * qj));
        }
    }
    out
}
