//! Rational curves: rational Bézier curves and NURBS (non-uniform rational B-splines), as the
//! projections of polynomial curves in homogeneous coordinates, and exact conics.
//!
//! A rational curve with control points cᵢ ∈ R^D and weights wᵢ > 0 is the polynomial (or
//! spline) curve with the control points (wᵢ·cᵢ, wᵢ) ∈ R^{D+1}, its first D coordinates
//! divided by the last [SPL, §14]. Both types keep that homogeneous form as two polynomial
//! curves of the crate, the weighted points in R^D and the weights in R¹ ([`Bezier`]s for
//! [`RationalBezier`], [`BSpline`]s on one knot vector for [`Nurbs`]), so every linear
//! operation is the polynomial one applied to both, not a copy of it. The weights are
//! validated once, finite and strictly positive; then the denominator is at least the
//! smallest weight on the domain ([0, 1], respectively [t_d, t_n]) and the division is always
//! defined. With `f64` the homogeneous form is built from the weights scaled by a power of
//! two (exact, the curve does not change), so weights near 1e300 or subnormal ones work as
//! well as weights near 1.
//!
//! | file | problem | time |
//! |---|---|---|
//! | `weights.rs` | validation of the weights, the homogeneous points | Θ(nD) |
//! | `quotient.rs` | the quotient rule of any order, c⁽ᵏ⁾ from a⁽ⁱ⁾ and w⁽ⁱ⁾ [Piegl and Tiller, eq. (4.8)] | Θ(k²D) |
//! | `bezier.rs` | [`RationalBezier`]: validation, [`de_casteljau`](RationalBezier::de_casteljau) in homogeneous coordinates, the curve traits, the derivative curve of degree 2n [SPL, §14] | Θ(n²D) |
//! | `nurbs.rs` | [`Nurbs`]: validation, [`de_boor`](Nurbs::de_boor), [`insert`](Nurbs::insert), the curve traits, [`NurbsDerivative`] [SPL, §14] | Θ(d²D); Θ((n + d + rd)D) |
//! | `linear.rs` | [`Nurbs::refine`], [`Nurbs::elevate`], [`Nurbs::to_bezier`] (and `_with`), the piece over an interval ([`Subsegment`](crate::spline::Subsegment)): the B-spline operations on both homogeneous halves [SPL, §14] | twice the B-spline operation |
//! | `conic.rs` | exact conics: [`Nurbs::circle`], [`RationalBezier::circular_arc`], [`RationalBezier::conic`], [`ConicKind`] [Piegl and Tiller, §7.2–7.5] | O(1) |
//!
//! Degree elevation and the conversion of a NURBS curve to rational Bézier pieces
//! ([`Nurbs::elevate`], [`Nurbs::to_bezier`]) are the B-spline operations on the two halves
//! of [`Nurbs::homogeneous`], put back together with [`Nurbs::from_homogeneous`] and
//! [`RationalBezier::from_homogeneous`].
//!
//! ```
//! use compgeo::spline::{Curve, Nurbs, Point};
//!
//! // The circle of radius 5 about the origin: rational points at rational parameters.
//! let c = Nurbs::circle(Point::new([0.0, 0.0]), 5.0)?;
//! let p = c.eval(&2.5)?;
//! assert_eq!(p, Point::new([-3.0, -4.0]));
//! assert_eq!(p[0] * p[0] + p[1] * p[1], 25.0);
//! # Ok::<(), compgeo::Error>(())
//! ```
//!
//! [`Bezier`]: crate::spline::Bezier
//! [`BSpline`]: crate::spline::BSpline

mod bezier;
mod conic;
mod linear;
mod nurbs;
mod quotient;
pub(crate) mod weights;

/// The rational curve algorithms, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 6] = [
    &bezier::RATIONAL_DE_CASTELJAU,
    &nurbs::NURBS_DE_BOOR,
    &nurbs::NURBS_INSERT,
    &linear::NURBS_REFINE,
    &linear::NURBS_ELEVATE,
    &linear::NURBS_TO_BEZIER,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::bezier::RATIONAL_DE_CASTELJAU;
    pub(crate) use super::linear::{NURBS_ELEVATE, NURBS_REFINE, NURBS_TO_BEZIER};
    pub(crate) use super::nurbs::NURBS_INSERT;
}

pub use bezier::RationalBezier;
pub use conic::ConicKind;
/// NURBS evaluation, declared: the catalog measures it.
pub(crate) use nurbs::NURBS_DE_BOOR;
pub use nurbs::{Nurbs, NurbsDerivative};
