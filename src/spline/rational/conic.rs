//! Exact conics: circles and circular arcs whose every point has rational coordinates on
//! rational parameters, and conic arcs from three control points and a weight.
//!
//! The problem: a circle as a NURBS curve such that, on the exact back end, every point
//! satisfies (x − x₀)² + (y − y₀)² = r² exactly. The usual construction (four quarters of
//! weights 1, √2/2, 1) needs an irrational weight. The idea: a rational quadratic arc with
//! weights w₀, w₁, w₂ keeps its shape under the rational reparametrisations that scale the
//! weights to w₀, λw₁, λ²w₂, which leave the invariant κ = w₁²/(w₀w₂) unchanged; a circular
//! arc of angle θ between its end tangents has κ = cos²(θ/2), for a quarter 1/2, which the
//! rational weights 1, 1, 2 also have. With them the quarter over (1, 0), (1, 1), (0, 1) is
//! t ↦ ((1 − t²)/(1 + t²), 2t/(1 + t²)), the classical rational parametrisation of the circle
//! (by the lines through (−1, 0) of slope t), rational at every rational t. Four such
//! quarters, alternately read backwards (weights 1, 1, 2 then 2, 1, 1, so that the weights
//! of the shared end points agree), make the whole circle.
//!
//! A general arc of angle 2·arctan m (0 < m, any angle below π) is the same map over
//! [0, m], t = s/m: control points (1, 0), (1, m), ((1 − m²)/(1 + m²), 2m/(1 + m²)) and
//! weights 1, 1, 1 + m², all rational for rational m.
//!
//! A rational quadratic arc with weights 1, w, 1 and control points not on a line is an arc
//! of an ellipse for w < 1, a parabola for w = 1 and a hyperbola for w > 1 (by the invariant
//! κ = w²) [Piegl and Tiller, §7.2–7.3].
//!
//! Follows [SPL, §14] (rational curves) and Piegl and Tiller, *The NURBS Book* (2nd ed.,
//! 1997), §7.2–7.3 (conic arcs as rational quadratics, the classification by the weight, the
//! reparametrisation invariant) and §7.5 (circles as NURBS).
//!
//! # Complexity
//!
//! O(1) for each construction (a fixed number of control points in R²).
//!
//! Invariants the tests check (exactly on rationals): every point of the circle and of the
//! arcs at random rational parameters is at distance exactly r from the centre, the circle
//! passes through its four axis points at the knots, and the classification follows the weight.

use super::{Nurbs, RationalBezier};
use crate::spline::bspline::KnotVector;
use crate::spline::scalar::{Point, Scalar};
use crate::{Error, Result};

/// The kind of conic a rational quadratic arc lies on (its control points not on a line).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ConicKind {
    /// κ = w₁²/(w₀w₂) < 1.
    Ellipse,
    /// κ = 1.
    Parabola,
    /// κ > 1.
    Hyperbola,
}

impl<S: Scalar> Nurbs<S, 2> {
    /// The circle of centre `centre` and radius `radius` as a closed quadratic NURBS curve:
    /// nine control points (the corners and edge midpoints of the square around the circle,
    /// from (x₀ + r, y₀) counter-clockwise), weights 1, 1, 2, 1, 1, 1, 2, 1, 1, knots
    /// 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4. Quarter k is the arc over [k, k + 1], which starts
    /// at angle k·90°. With `BigRational` every point at a rational parameter is a rational
    /// point of the circle, exactly at distance r from the centre.
    ///
    /// Why these weights: the textbook quarter has weights 1, √2/2, 1, irrational. A rational
    /// quadratic arc keeps its shape when its weights w₀, w₁, w₂ become w₀, λw₁, λ²w₂ (a
    /// rational change of parameter), which leaves κ = w₁²/(w₀w₂) unchanged; a circular arc
    /// of angle θ has κ = cos²(θ/2), 1/2 for a quarter, and so do the weights 1, 1, 2. With
    /// them the quarter over (1, 0), (1, 1), (0, 1) is t ↦ ((1 − t²)/(1 + t²), 2t/(1 + t²)),
    /// the classical rational parametrisation of the circle. The quarters alternate between
    /// 1, 1, 2 and 2, 1, 1 (read backwards), so the weights of the shared points agree
    /// [Piegl and Tiller, *The NURBS Book*, §7.3, §7.5].
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] for a centre with a NaN or infinite coordinate;
    /// [`Error::InvalidParameter`] named `"radius"` unless the radius is finite and positive;
    /// [`Error::Overflow`] if, with `f64`, a control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// O(1).
    ///
    /// ```
    /// use compgeo::spline::{Curve, Nurbs, Point};
    ///
    /// let c = Nurbs::circle(Point::new([1.0, 2.0]), 5.0)?;
    /// assert_eq!(c.eval(&0.0)?, Point::new([6.0, 2.0]));
    /// assert_eq!(c.eval(&1.0)?, Point::new([1.0, 7.0]));
    /// assert_eq!(c.eval(&0.5)?, Point::new([4.0, 6.0])); // the centre + 5·(3/5, 4/5)
    /// assert_eq!(c.eval(&4.0)?, Point::new([6.0, 2.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn circle(centre: Point<S, 2>, radius: S) -> Result<Self> {
        check_centre_and_radius(&centre, &radius)?;
        let at = |x: i64, y: i64| {
            let offset = Point::new([S::from_i64(x), S::from_i64(y)]) * &radius;
            centre.clone() + &offset
        };
        let control = vec![
            at(1, 0),
            at(1, 1),
            at(0, 1),
            at(-1, 1),
            at(-1, 0),
            at(-1, -1),
            at(0, -1),
            at(1, -1),
            at(1, 0),
        ];
        check_finite(&control)?;
        let weights = [1, 1, 2, 1, 1, 1, 2, 1, 1].map(S::from_i64).to_vec();
        let knots = [0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]
            .map(S::from_i64)
            .to_vec();
        Nurbs::new(control, weights, KnotVector::new(2, knots)?)
    }
}

impl<S: Scalar> RationalBezier<S, 2> {
    /// The circular arc of centre `centre` and radius `radius` from the point at angle 0,
    /// (x₀ + r, y₀), counter-clockwise through the angle 2·arctan m, as a rational quadratic:
    /// control points centre + r·(1, 0), centre + r·(1, m), centre + r·((1 − m²)/(1 + m²),
    /// 2m/(1 + m²)) and weights 1, 1, 1 + m². m = 1 is the quarter circle; any m > 0 gives an
    /// arc below a half circle. The point at t is centre + r·((1 − m²t²)/(1 + m²t²),
    /// 2mt/(1 + m²t²)), rational for rational m and t: the parametrisation of
    /// [`Nurbs::circle`]'s quarters over [0, m], s = mt, in Bézier form.
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] for a centre with a NaN or infinite coordinate;
    /// [`Error::InvalidParameter`] named `"radius"` or `"m"` unless the value is finite and
    /// positive; [`Error::Overflow`] if, with `f64`, a control point or weight is beyond the
    /// double range.
    ///
    /// # Complexity
    ///
    /// O(1).
    ///
    /// ```
    /// use compgeo::spline::{Curve, Point, RationalBezier};
    ///
    /// // m = 1/2: the arc from (1, 0) to (3/5, 4/5), through (15/17, 8/17) at t = 1/2.
    /// let a = RationalBezier::circular_arc(Point::new([0.0, 0.0]), 5.0, 0.5)?;
    /// assert_eq!(a.eval(&1.0)?, Point::new([3.0, 4.0]));
    /// assert_eq!(a.weights(), [1.0, 1.0, 1.25]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn circular_arc(centre: Point<S, 2>, radius: S, m: S) -> Result<Self> {
        check_centre_and_radius(&centre, &radius)?;
        if !m.is_finite() || m <= S::zero() {
            return Err(Error::InvalidParameter {
                name: "m",
                reason: format!("must be finite and positive, got {}", m.to_f64()),
            });
        }
        let m2 = m.clone() * &m;
        let w2 = S::one() + &m2;
        let end = Point::new([(S::one() - &m2) / &w2, (S::from_i64(2) * &m) / &w2]);
        let control: Vec<Point<S, 2>> = [
            Point::new([S::one(), S::zero()]),
            Point::new([S::one(), m]),
            end,
        ]
        .into_iter()
        .map(|p| centre.clone() + &(p * &radius))
        .collect();
        check_finite(&control)?;
        if !w2.is_finite() {
            return Err(Error::Overflow {
                what: "the weights of a circular arc",
            });
        }
        RationalBezier::new(control, vec![S::one(), S::one(), w2])
    }
}

impl<S: Scalar, const D: usize> RationalBezier<S, D> {
    /// The conic arc with control points `p0`, `p1`, `p2` and weights 1, `w`, 1: an arc of
    /// an ellipse (w < 1), a parabola (w = 1) or a hyperbola (w > 1) from p0 to p2, tangent
    /// to p0p1 and p1p2 at its ends. See [`RationalBezier::conic_kind`].
    ///
    /// # Errors
    ///
    /// As [`RationalBezier::new`]: [`Error::NonFinite`] naming the control point,
    /// [`Error::InvalidParameter`] named `"weights"` (weight 1) unless w is finite and
    /// positive.
    ///
    /// # Complexity
    ///
    /// O(D).
    ///
    /// ```
    /// use compgeo::spline::{ConicKind, Curve, Point, RationalBezier};
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// let arc = RationalBezier::conic(p(0.0, 0.0), p(1.0, 1.0), p(2.0, 0.0), 3.0)?;
    /// assert_eq!(arc.conic_kind(), Some(ConicKind::Hyperbola));
    /// assert_eq!(arc.eval(&0.5)?, p(1.0, 0.75)); // (¼·p₀ + 3·½·p₁ + ¼·p₂)/(¼ + 3·½ + ¼)
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn conic(p0: Point<S, D>, p1: Point<S, D>, p2: Point<S, D>, w: S) -> Result<Self> {
        RationalBezier::new(vec![p0, p1, p2], vec![S::one(), w, S::one()])
    }

    /// For a quadratic curve, the kind of conic it lies on by the invariant
    /// κ = w₁²/(w₀w₂) (compared exactly with 1; `f64` rounds the products): an ellipse below
    /// 1, a parabola at 1, a hyperbola above [Piegl and Tiller, §7.3]. `None` unless the
    /// degree is 2. Control points on a line give a degenerate conic (a segment or a line),
    /// which the invariant does not see.
    ///
    /// # Complexity
    ///
    /// O(1).
    ///
    /// ```
    /// use compgeo::spline::{ConicKind, Point, RationalBezier};
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// let quarter = RationalBezier::new(vec![p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)], vec![1.0, 1.0, 2.0])?;
    /// assert_eq!(quarter.conic_kind(), Some(ConicKind::Ellipse)); // κ = 1/2
    /// let parabola = RationalBezier::conic(p(0.0, 0.0), p(1.0, 2.0), p(2.0, 0.0), 1.0)?;
    /// assert_eq!(parabola.conic_kind(), Some(ConicKind::Parabola));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn conic_kind(&self) -> Option<ConicKind> {
        let [w0, w1, w2] = self.weights() else {
            return None;
        };
        let (square, product) = (w1.clone() * w1, w0.clone() * w2);
        Some(if square < product {
            ConicKind::Ellipse
        } else if square == product {
            ConicKind::Parabola
        } else {
            ConicKind::Hyperbola
        })
    }
}

/// Checks a centre (finite) and a radius (finite and positive).
fn check_centre_and_radius<S: Scalar>(centre: &Point<S, 2>, radius: &S) -> Result<()> {
    crate::spline::scalar::validate_points(std::slice::from_ref(centre), "centre")?;
    if !radius.is_finite() || *radius <= S::zero() {
        return Err(Error::InvalidParameter {
            name: "radius",
            reason: format!("must be finite and positive, got {}", radius.to_f64()),
        });
    }
    Ok(())
}

/// [`Error::Overflow`] if a constructed control point is not finite (`f64` only).
fn check_finite<S: Scalar>(control: &[Point<S, 2>]) -> Result<()> {
    if control.iter().all(Point::is_finite) {
        Ok(())
    } else {
        Err(Error::Overflow {
            what: "the control points of a conic",
        })
    }
}
