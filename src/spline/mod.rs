//! Curves for geometric modelling: Bézier curves, interpolation, the Frenet frame, and the
//! scalar and point types they compute with.
//!
//! The kernels are generic over the field ([`Scalar`]: `f64`, or exact `BigRational` with the
//! feature `exact`) and over the dimension of the points ([`Point<S, D>`], R^D for any `D`).
//! The `f64` path is compiled per scalar and dimension, with closed forms for degrees 1 to 3
//! (the `spline` benchmark compares it with a hand-written cubic, kurbo and lyon_geom).
//!
//! Every curve type implements the traits of `curve.rs`: [`Curve`] (a [`Domain`] and one
//! evaluation convention, `Result<Point<S, D>>`), [`CurveDerivative`] (a derivative curve and
//! derivatives of any order at a parameter) and [`Subsegment`] (the piece over an interval,
//! keeping the parameter):
//!
//! | type | domain | derivative | subsegment |
//! |---|---|---|---|
//! | [`Bezier`] | the real line | [`Bezier`] (hodograph) | [`Reparametrised`] |
//! | [`Reparametrised`] | the real line | [`Reparametrised`] | [`Reparametrised`] |
//! | [`CompositeBezier`] (also Hermite curves and splines) | [u₀, u_m] | [`CompositeBezier`] | [`CompositeBezier`] |
//! | [`Polynomial`], [`NewtonForm`], [`LagrangeForm`] | the real line | [`Polynomial`] | [`Reparametrised`] |
//! | [`BSpline`] | [t_d, t_n] | [`BSpline`] (degree d − 1) | [`BSpline`] (cut ends clamped) |
//! | [`RationalBezier`] | [0, 1] | [`RationalBezier`] (degree 2n) | not yet |
//! | [`Nurbs`] | [t_d, t_n] | [`NurbsDerivative`] (by the quotient rule) | [`Nurbs`] (cut ends clamped) |
//! | [`BetaSpline`] | [0, m], m = n − 3 segments | not yet (segment derivatives: [`BetaSpline::segment_derivatives`]) | not yet (subdivision: [`BetaSpline::subdivide`]) |
//!
//! | module or file | what it holds |
//! |---|---|
//! | `scalar.rs` | [`Scalar`], [`Point`], [`Finite`], validation, [`binomial`] and the shared numeric helpers |
//! | `parse.rs` | [`parse_scalar`]: exact reading of integers, decimals and fractions, bounded by [`MAX_EXACT_DIGITS`] and [`MAX_EXACT_EXPONENT`] |
//! | `curve.rs` | the curve traits and [`Domain`] |
//! | [`bezier`] | Bernstein basis, [`Bezier`] and its algorithms (one per file), [`Reparametrised`], [`CompositeBezier`] and its joins, intersection, the evaluation schemes ([`BezierEvaluation`]) |
//! | [`bspline`] | [`KnotVector`] (validation, builders, multiplicities, domain, span search, the SPL adapter), the basis ([`Basis`], [`BasisDerivatives`]), [`BSpline`] curves with de Boor's algorithm (its net as [`DeBoorLevel`] frames) and Boehm's insertion |
//! | [`beta`] | cubic Beta-splines: [`BetaParameters`] (β₁, β₂, the normaliser δ), the basis and its Bernstein matrix C, [`BetaSpline`] curves, [`SubdivisionMatrices`] S_L = C⁻¹S_Lᴮ C and S_R = C⁻¹S_Rᴮ C at any c, recursive subdivision, the β-continuity check [`is_beta_continuous`] |
//! | [`rational`] | [`RationalBezier`] and [`Nurbs`] in homogeneous coordinates (de Casteljau, de Boor, insertion, derivatives by the quotient rule), exact conics ([`Nurbs::circle`], [`RationalBezier::circular_arc`], [`ConicKind`]) |
//! | [`interpolate`] | polynomial, Lagrange/Aitken, Newton and Hermite interpolation, cubic and quadratic splines, least squares, parameterisations |
//! | [`subdivision`] | uniform subdivision of open and closed polygons: [`lane_riesenfeld`] of any degree ([`chaikin`] is degree 2), the [`four_point`] scheme, subdivision masks ([`Mask`]) with their difference schemes, [`limit_points`] |
//! | `frenet.rs` | [`FrenetFrame`], [`frenet_frame`], [`bezier_frenet`], [`curvature_vector`], G² checks [`is_g2_join`], [`is_g2`] |
//!
//! Every item is also re-exported here, flat (`compgeo::spline::Bezier`,
//! `compgeo::spline::cubic_spline`, ...).
//!
//! Sources are cited as `[KEY, §section]`: PPB is M. Paluszny, H. Prautzsch, W. Boehm,
//! *Métodos de Bézier y B-splines*; SPL the lecture notes *Curvas spline*; RD I. Ruiz
//! Donaire, *Resumen de la asignatura Geometría Aplicada*; CCKS L. Castro, S. Castro,
//! S. Kahnert, D. Salgado, *Matrices de subdivisión para curvas Beta-spline cúbicas*.

pub mod beta;
pub mod bezier;
pub mod bspline;
mod curve;
mod frenet;
pub mod interpolate;
mod parse;
pub mod rational;
mod scalar;
pub mod subdivision;

/// The curve algorithms that are not a choice among evaluation schemes, declared: the Bézier
/// operations, interpolation and fitting, the B-spline knots and basis, the Frenet frame.
pub(crate) fn declarations() -> impl Iterator<Item = &'static crate::complexity::Declaration> {
    bezier::DECLARATIONS
        .into_iter()
        .chain(interpolate::DECLARATIONS)
        .chain(bspline::DECLARATIONS)
        .chain(rational::DECLARATIONS)
        .chain(subdivision::DECLARATIONS)
        .chain(beta::DECLARATIONS)
        .chain([FRENET])
}

/// The Frenet frame, declared: the catalog measures it.
pub(crate) const FRENET: &crate::complexity::Declaration = &frenet::FRENET;

pub use beta::{
    is_beta_continuous, is_beta_continuous_with, BetaParameters, BetaSpline, Matrix4,
    SubdivisionMatrices,
};
pub use bezier::{
    bernstein, bernstein_all, bernstein_derivative, c1_partition, intersections,
    intersections_with, Bezier, CasteljauLevel, CompositeBezier, Evaluation as BezierEvaluation,
    Intersection, Join, Reparametrised, MAX_FLATTEN_SEGMENTS, MAX_INTERSECTION_PAIRS,
};
pub use bspline::{
    BSpline, BandMatrix, Basis, BasisDerivatives, DeBoorLevel, KnotVector, ParameterFit,
};
pub use curve::{Curve, CurveDerivative, Domain, Subsegment};
pub use frenet::{
    bezier_frenet, curvature_vector, frenet_frame, frenet_frame_with, is_g2, is_g2_join,
    FrenetFrame,
};
pub use interpolate::{
    closed_quadratic_spline, closed_quadratic_spline_with, cubic_spline, cubic_spline_tangents,
    cubic_spline_tangents_with, cubic_spline_with, estimate_tangents, fit_bezier, fit_bezier_with,
    hermite, hermite_with, lagrange, lagrange_basis, lagrange_with, newton, newton_hermite,
    newton_hermite_with, newton_with, parameterise, quadratic_spline, quadratic_spline_with,
    vandermonde, vandermonde_hermite, vandermonde_hermite_with, vandermonde_with, EndCondition,
    FitOptions, HermiteNode, LagrangeForm, NewtonForm, Parameterisation, Polynomial,
};
pub(crate) use parse::read_scalar;
#[cfg(feature = "cli")]
pub(crate) use parse::{parse_f64, parse_f64_or_word};
pub use parse::{parse_scalar, ParseScalar, MAX_EXACT_DIGITS, MAX_EXACT_EXPONENT};
pub use rational::{ConicKind, Nurbs, NurbsDerivative, RationalBezier};
pub use scalar::{binomial, validate_parameter, validate_points, Finite, Point, Scalar};
pub(crate) use scalar::{falling_factorial, power};
pub use subdivision::{
    chaikin, four_point, lane_riesenfeld, limit_points, limit_stencil, Mask, Topology,
};
