//! The Frenet frame, curvature and torsion of a parametric curve, and G¹ / G² checks at the
//! joins of composite curves.
//!
//! The problem: the moving frame and the curvatures of a curve at a parameter, from its
//! derivatives there. The idea: orthogonalise the derivatives `x', x'', …` (Gram–Schmidt); the
//! lengths of the residuals give the curvatures.
//!
//! Follows [RD, §3.1] ("Triedro de Frenet": `t = α'/‖α'‖`, `b = α'×α''/‖α'×α''‖`, `n = b×t`;
//! `κ = ‖α'×α''‖/‖α'‖³`, `τ = det(α', α'', α''')/‖α'×α''‖²`; Def. 3.2–3.3: G¹ is a continuous
//! unit tangent, G² a continuous curvature vector `κ n`) and [PPB, §7.6] (the frame in R^d by
//! Gram–Schmidt of `x', ..., x⁽ᵈ⁾` with `f_iᵀ x⁽ⁱ⁾ > 0`, positively oriented, and the
//! curvatures `κ_1, ..., κ_{d−1}`).
//!
//! # Exact and rounded parts
//!
//! The Gram–Schmidt residuals `e_i = x⁽ⁱ⁾ − Σ_{j<i} (x⁽ⁱ⁾·e_j / e_j·e_j) e_j` and their squared
//! lengths `E_i² = e_i·e_i` are rational functions of the derivatives, so they are computed in
//! the scalar field: with `BigRational` the rank of the derivatives (where the frame stops)
//! and the sign of the last curvature are decided exactly. The unit vectors and the
//! curvatures need square roots and are returned as `f64`:
//! `f_i = e_i / E_i` and `κ_i = E_{i+1} / (E_1 E_i)` (for d = 3, `κ_1 = ‖x'×x''‖/‖x'‖³` and
//! `κ_2 = det(x', x'', x''')/‖x'×x''‖²`, the course's formulas).
//!
//! The curvature vector `κ n = (‖x'‖² x'' − (x'·x'') x') / ‖x'‖⁴` needs no square root, so
//! [`curvature_vector`] is exact with rationals and the G² check built on it too.
//!
//! # Complexity
//!
//! Θ(r²D + D³) for a frame from r ≤ D derivatives in R^D (Gram–Schmidt and one determinant),
//! plus the derivatives themselves (Θ(D·n²D) for a Bézier curve of degree n); Θ(D) for a
//! curvature vector, Θ(n²D) for a G² check of pieces of degree n.

use super::bezier::nearly_equal;
use super::curve::CurveDerivative;
use super::interpolate::{eliminate_below, pivot};
use super::scalar::{pow2_scale, validate_points, Point, Scalar};
use super::{Bezier, CompositeBezier};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::{Error, Result};

/// The Frenet frame, declared: its name, bounds, counts, source and claims (in the dimension
/// D, with r = D derivatives).
pub(crate) const FRENET: Declaration = Declaration {
    problem: "frenet",
    name: "frame",
    function: "spline::frenet_frame",
    file: "src/spline/frenet.rs",
    summary: "the Frenet frame and curvatures by Gram–Schmidt on the derivatives",
    time: "Θ(r²·D)",
    space: "Θ(r·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per projection of a residual, 2·Σ i = r(r − 1) for r independent derivatives, and with r = D one per entry changed by the orientation's elimination, (D − 1)D(D + 1)/3",
    source: "[PPB, §7.6]",
    claims: &[on(
        "random-dimension",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// The Frenet frame of a curve in R^D at one parameter: orthonormal vectors `f_1, ..., f_k`
/// and curvatures `κ_1, ..., κ_{k−1}`, where k is the number of linearly independent
/// derivatives among `x', ..., x⁽ᴰ⁾` that were given.
///
/// For a space curve (D = 3, general position) `f_1, f_2, f_3` are the tangent, normal and
/// binormal, `κ_1` the curvature and `κ_2` the torsion. When k = D the frame is positively
/// oriented and the last curvature carries a sign: a plane curve's curvature is positive when
/// it turns counter-clockwise, a space curve's torsion is the sign of `det(x', x'', x''')`.
/// The other curvatures are positive.
#[derive(Clone, Debug, PartialEq)]
pub struct FrenetFrame<const D: usize> {
    vectors: Vec<Point<f64, D>>,
    curvatures: Vec<f64>,
}

impl<const D: usize> FrenetFrame<D> {
    /// The orthonormal vectors `f_1, ..., f_k`.
    pub fn vectors(&self) -> &[Point<f64, D>] {
        &self.vectors
    }

    /// The curvatures `κ_1, ..., κ_{k−1}`.
    pub fn curvatures(&self) -> &[f64] {
        &self.curvatures
    }

    /// The unit tangent `f_1 = x'/‖x'‖`.
    pub fn tangent(&self) -> Point<f64, D> {
        self.vectors[0]
    }

    /// The unit normal `f_2`, if `x''` is not parallel to `x'`.
    pub fn normal(&self) -> Option<Point<f64, D>> {
        self.vectors.get(1).copied()
    }

    /// The binormal `f_3`, if the first three derivatives are independent.
    pub fn binormal(&self) -> Option<Point<f64, D>> {
        self.vectors.get(2).copied()
    }

    /// The curvature `κ_1` (0 where `x''` is parallel to `x'`).
    pub fn curvature(&self) -> f64 {
        self.curvatures.first().copied().unwrap_or(0.0)
    }

    /// The torsion `κ_2` (0 where the first three derivatives are dependent, e.g. for every
    /// plane curve).
    pub fn torsion(&self) -> f64 {
        self.curvatures.get(1).copied().unwrap_or(0.0)
    }
}

/// The Frenet frame and curvatures from the derivatives `x', x'', ..., x⁽ʳ⁾` of a curve at one
/// parameter (at most D of them are used).
///
/// The idea ([PPB, §7.6]): Gram–Schmidt orthogonalisation of the derivatives gives the frame;
/// the lengths `E_i` of the orthogonal residuals give the curvatures `κ_i = E_{i+1}/(E_1 E_i)`.
/// The frame stops at the first derivative that depends on the previous ones. See the module
/// doc for what is exact.
///
/// # Errors
///
/// [`Error::Empty`] for no derivatives; [`Error::NonFinite`] for a bad coordinate;
/// [`Error::InvalidParameter`] (`"derivatives"`) if `x' = 0` (the curve is not regular there
/// and has no tangent).
///
/// # Complexity
///
/// Θ(r²·D) time and Θ(r·D) auxiliary space for r ≤ D derivatives (plus a Θ(D³) determinant
/// when r = D).
///
/// ```
/// use compgeo::spline::{frenet_frame, Point};
///
/// // The helix (cos t, sin t, t) at t = 0: κ = τ = 1/2.
/// let d = [Point::new([0.0, 1.0, 1.0]), Point::new([-1.0, 0.0, 0.0]), Point::new([0.0, -1.0, 0.0])];
/// let f = frenet_frame(&d)?;
/// assert!((f.curvature() - 0.5).abs() < 1e-15 && (f.torsion() - 0.5).abs() < 1e-15);
/// assert_eq!(f.normal(), Some(Point::new([-1.0, 0.0, 0.0])));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn frenet_frame<S: Scalar, const D: usize>(
    derivatives: &[Point<S, D>],
) -> Result<FrenetFrame<D>> {
    frenet_frame_with(derivatives, &mut NoCount)
}

/// [`frenet_frame`], counting one [`arithmetic_operation`](Counter::arithmetic_operation)
/// per projection of a residual on an earlier one (each derivative is projected twice on
/// every residual before it: r(r − 1) for r independent derivatives) and, for a full frame
/// (r = D ≥ 2), one per entry changed by the elimination that decides the orientation,
/// Σ (D − 1 − c)(D − c) = (D − 1)D(D + 1)/3 when no entry below a pivot vanishes.
///
/// # Errors
///
/// As [`frenet_frame`].
///
/// # Complexity
///
/// Θ(r²·D) time and Θ(r·D) auxiliary space for r ≤ D derivatives (plus a Θ(D³) determinant
/// when r = D).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{frenet_frame_with, Point};
///
/// let d = [Point::new([0.0, 1.0, 1.0]), Point::new([-1.0, 0.0, 0.0]), Point::new([0.0, -1.0, 0.0])];
/// let mut c = Counts::default();
/// frenet_frame_with(&d, &mut c)?;
/// // Projections 0 + 2 + 4; the orientation's elimination changes at most 2·3 + 1·2 entries.
/// assert!(c.arithmetic_operations >= 6 && c.arithmetic_operations <= 6 + 8);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn frenet_frame_with<S: Scalar, const D: usize, C: Counter>(
    derivatives: &[Point<S, D>],
    counter: &mut C,
) -> Result<FrenetFrame<D>> {
    validate_points(derivatives, "derivatives")?;
    let r = derivatives.len().min(D);
    // Scaling the curve by s scales every curvature by 1/s: work at unit scale in f64.
    let refs: Vec<&Point<S, D>> = derivatives[..r].iter().collect();
    let s = pow2_scale(&refs);
    let derivatives: Vec<Point<S, D>> = derivatives[..r].iter().map(|d| d.clone() * &s).collect();
    if derivatives[0].norm_squared().is_zero() {
        return Err(not_regular());
    }
    // Orthogonal residuals e_i and their squared lengths, in S.
    let mut residuals: Vec<Point<S, D>> = Vec::with_capacity(r);
    let mut squares: Vec<S> = Vec::with_capacity(r);
    for x in &derivatives[..r] {
        // Modified Gram–Schmidt, run twice: in f64 one classical pass loses orthogonality
        // when the derivatives are nearly dependent ("twice is enough"); with rationals the
        // second pass subtracts exact zeros.
        let mut e = x.clone();
        for _ in 0..2 {
            for (ej, sj) in residuals.iter().zip(&squares) {
                let c = e.dot(ej) / sj;
                e -= &(ej.clone() * &c);
                counter.arithmetic_operation();
            }
        }
        let s = e.norm_squared();
        if s.is_zero() {
            break;
        }
        residuals.push(e);
        squares.push(s);
    }
    let k = residuals.len();
    // With a full frame (D ≥ 2) the last vector completes a positive orientation; on a line
    // the frame is just the unit tangent.
    let sign = if D >= 2 && k == D && determinant_is_negative(&derivatives, counter) {
        -1.0
    } else {
        1.0
    };
    let mut vectors: Vec<Point<f64, D>> = residuals
        .iter()
        .zip(&squares)
        .map(|(e, s)| e.to_f64() / s.to_f64().sqrt())
        .collect();
    let unscale = s.to_f64();
    let mut curvatures: Vec<f64> = (1..k)
        .map(|i| {
            let ratio = squares[i].clone() / (squares[0].clone() * &squares[i - 1]);
            ratio.to_f64().sqrt() * unscale
        })
        .collect();
    if sign < 0.0 {
        vectors[k - 1] = -vectors[k - 1];
        if let Some(last) = curvatures.last_mut() {
            *last = -*last;
        }
    }
    Ok(FrenetFrame {
        vectors,
        curvatures,
    })
}

/// The Frenet frame of a Bézier curve at `t`, from its derivatives (hodographs) of orders
/// `1..=min(D, n)`.
///
/// # Errors
///
/// [`Error::InvalidParameter`] for a non-finite `t` or a singular point (`b'(t) = 0`).
///
/// # Complexity
///
/// Θ(D·n²·D) time for degree n (one de Casteljau scheme per derivative).
///
/// ```
/// use compgeo::spline::{bezier_frenet, Bezier, Point};
///
/// // The parabola (t, t²) has curvature 2 at its vertex, turning counter-clockwise.
/// let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([0.5, 0.0]), Point::new([1.0, 1.0])])?;
/// assert_eq!(bezier_frenet(&b, &0.0)?.curvature(), 2.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bezier_frenet<S: Scalar, const D: usize>(
    curve: &Bezier<S, D>,
    t: &S,
) -> Result<FrenetFrame<D>> {
    let r = D.min(curve.degree()).max(1);
    let derivatives = (1..=r)
        .map(|k| curve.derivative_at(t, k))
        .collect::<Result<Vec<_>>>()?;
    frenet_frame(&derivatives)
}

/// The curvature vector `κ n = (‖x'‖² x'' − (x'·x'') x') / ‖x'‖⁴` from the first two
/// derivatives: the component of `x''` normal to the tangent, over `‖x'‖²`. Exact with
/// rationals (no square root).
///
/// # Errors
///
/// [`Error::NonFinite`] for a bad coordinate; [`Error::InvalidParameter`] (`"derivatives"`)
/// if `x' = 0`.
///
/// ```
/// use compgeo::spline::{curvature_vector, Point};
///
/// // A circle of radius 2 at (2, 0), moving up: κ n = (−1/2, 0).
/// let k = curvature_vector(&Point::new([0.0, 2.0]), &Point::new([-2.0, 0.0]))?;
/// assert_eq!(k, Point::new([-0.5, 0.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn curvature_vector<S: Scalar, const D: usize>(
    first: &Point<S, D>,
    second: &Point<S, D>,
) -> Result<Point<S, D>> {
    validate_points(&[first.clone(), second.clone()], "derivatives")?;
    // κn of the curve scaled by s is κn / s: compute at unit scale (f64), then scale back.
    let s = pow2_scale(&[first, second]);
    let (first, second) = (first.clone() * &s, second.clone() * &s);
    let speed2 = first.norm_squared();
    if speed2.is_zero() {
        return Err(not_regular());
    }
    let normal_part = second.clone() * &speed2 - &(first.clone() * first.dot(&second));
    Ok(normal_part / (speed2.clone() * &speed2) * &s)
}

/// Whether pieces `i − 1` and `i` of a composite curve meet with G² continuity at `u_i`
/// ([RD, §3.1, Def. 3.3]): G¹ and equal curvature vectors `κ n` from both sides.
///
/// `tolerance` is relative as in [`CompositeBezier::join`]; with rationals pass zero for an
/// exact answer.
///
/// # Errors
///
/// [`Error::InvalidParameter`] (`"join"`) if `i` is not an interior knot index.
///
/// ```
/// use compgeo::spline::{is_g2_join, CompositeBezier, Point};
///
/// // [RD, §3.1]: (t, 0, 0) then (2t, 4t², 0) is G¹ but neither C¹ nor G².
/// let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
/// let c = CompositeBezier::new(
///     vec![-1.0, 0.0, 0.5],
///     vec![vec![p(-1.0, 0.0), p(-0.5, 0.0), p(0.0, 0.0)], vec![p(0.0, 0.0), p(0.5, 0.0), p(1.0, 1.0)]],
/// )?;
/// assert!(c.join(1, &0.0)?.g1 && c.join(1, &0.0)?.parametric == Some(0));
/// assert!(!is_g2_join(&c, 1, &0.0)?);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn is_g2_join<S: Scalar, const D: usize>(
    curve: &CompositeBezier<S, D>,
    i: usize,
    tolerance: &S,
) -> Result<bool> {
    if !curve.join(i, tolerance)?.g1 {
        return Ok(false);
    }
    let left = curve.end_derivatives(i - 1, true, 2)?;
    let right = curve.end_derivatives(i, false, 2)?;
    let second = |d: &[Point<S, D>]| d.get(2).cloned().unwrap_or_else(Point::zero);
    let kl = curvature_vector(&left[1], &second(&left))?;
    let kr = curvature_vector(&right[1], &second(&right))?;
    Ok(nearly_equal(&kl, &kr, tolerance))
}

/// `true` if every join of the composite curve is G² (see [`is_g2_join`]).
pub fn is_g2<S: Scalar, const D: usize>(curve: &CompositeBezier<S, D>, tolerance: &S) -> bool {
    (1..curve.pieces().len()).all(|i| is_g2_join(curve, i, tolerance).unwrap_or(false))
}

fn not_regular() -> Error {
    Error::InvalidParameter {
        name: "derivatives",
        reason: "the first derivative is zero: the curve is not regular there".to_string(),
    }
}

/// Whether `det[x_1, ..., x_D] < 0`, by Gaussian elimination in S (exact for rationals; the
/// pivot is the first nonzero entry, or the largest one for rounded scalars): the sign of
/// the product of the pivots, flipped once per row swap.
fn determinant_is_negative<S: Scalar, const D: usize, C: Counter>(
    columns: &[Point<S, D>],
    counter: &mut C,
) -> bool {
    let mut a: Vec<Vec<S>> = (0..D)
        .map(|row| columns.iter().map(|c| c[row].clone()).collect())
        .collect();
    let mut negative = false;
    for col in 0..D {
        let Some(p) = pivot(&a, col) else {
            return false;
        };
        if p != col {
            a.swap(p, col);
            negative = !negative;
        }
        if a[col][col] < S::zero() {
            negative = !negative;
        }
        eliminate_below(&mut a, col, |_, _| {
            for _ in col..D {
                counter.arithmetic_operation();
            }
        });
    }
    negative
}
