//! Curves for geometric modelling: Bézier curves and the scalar and point types they compute
//! with.
//!
//! The kernels are generic over the field ([`Scalar`]: `f64`, or exact `BigRational` with the
//! feature `exact`) and over the dimension of the control points ([`Point<S, D>`], R^D for any
//! `D`). The `f64` path is compiled per scalar and dimension, with closed forms for degrees 1
//! to 3 (the `spline` benchmark compares it with a hand-written cubic, kurbo and lyon_geom).
//!
//! | file | what it holds |
//! |---|---|
//! | `scalar.rs` | [`Scalar`], [`Point`], exact parsing of numbers, validation helpers |
//! | `bernstein.rs` | [`bernstein`], [`bernstein_all`], [`bernstein_derivative`] |
//! | `bezier.rs` | [`Bezier`]: de Casteljau, Horner, derivatives, split, restrict, blossom, box |
//! | `horner.rs` | Horner's scheme behind [`Bezier::eval`]: closed forms, inline polygons, the overflow bound |
//! | `reparametrised.rs` | [`Reparametrised`]: a curve over a global interval [a, b] |
//! | `bezier_ops.rs` | batch evaluation, degree elevation (Zhou), monomial conversion, integral, flattening, forward differences |
//! | `intersect.rs` | [`intersections`] of two planar curves by subdivision with box pruning |
//! | `composite.rs` | [`CompositeBezier`]: pieces over a partition, C⁰/G¹/Cʳ join checks, Cʳ builder, [`c1_partition`] |
//! | `frenet.rs` | [`FrenetFrame`], [`frenet_frame`], [`bezier_frenet`], [`curvature_vector`], G² checks [`is_g2_join`], [`is_g2`] |
//! | `hermite.rs` | piecewise cubic [`hermite`] interpolation, [`estimate_tangents`], [`parameterise`] |
//! | `interpolate.rs` | [`Polynomial`], [`vandermonde`], [`vandermonde_hermite`] |
//! | `lagrange.rs` | [`lagrange_basis`], [`lagrange`], [`aitken`] |
//! | `newton.rs` | divided differences: [`newton`], [`newton_hermite`] (confluent nodes) |
//! | `quadratic_spline.rs` | C¹ parabolic splines: [`quadratic_spline`], [`closed_quadratic_spline`] |
//! | `least_squares.rs` | least-squares Bézier fitting, weighted and end-clamped: [`fit_bezier`] |
//! | `cubic_spline.rs` | C² [`cubic_spline`]: natural, clamped, Bessel, periodic ([`EndCondition`]) |

mod bernstein;
mod bezier;
mod bezier_ops;
mod composite;
mod cubic_spline;
mod frenet;
mod hermite;
mod horner;
mod interpolate;
mod intersect;
mod lagrange;
mod least_squares;
mod newton;
mod quadratic_spline;
mod reparametrised;
mod scalar;

/// The curve algorithms the report measures, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 4] = [
    &bezier::DE_CASTELJAU,
    &bezier::HORNER,
    &cubic_spline::NATURAL,
    &cubic_spline::PERIODIC,
];

pub use bernstein::{bernstein, bernstein_all, bernstein_derivative};
pub use bezier::Bezier;
pub use bezier_ops::MAX_FLATTEN_SEGMENTS;
pub use composite::{c1_partition, CompositeBezier, Join};
pub use cubic_spline::{
    cubic_spline, cubic_spline_tangents, cubic_spline_tangents_with, EndCondition,
};
pub use frenet::{bezier_frenet, curvature_vector, frenet_frame, is_g2, is_g2_join, FrenetFrame};
pub use hermite::{estimate_tangents, hermite, parameterise, Parameterisation};
pub use interpolate::{vandermonde, vandermonde_hermite, HermiteNode, Polynomial};
pub use intersect::{intersections, Intersection, MAX_INTERSECTION_PAIRS};
pub use lagrange::{aitken, lagrange, lagrange_basis};
pub use least_squares::{fit_bezier, FitOptions};
pub use newton::{newton, newton_hermite, NewtonForm};
pub use quadratic_spline::{closed_quadratic_spline, quadratic_spline};
pub use reparametrised::Reparametrised;
pub use scalar::{
    binomial, parse_scalar, validate_parameter, validate_points, Finite, ParseScalar, Point, Scalar,
};
