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
//! | `reparametrised.rs` | [`Reparametrised`]: a curve over a global interval [a, b] |
//! | `bezier_ops.rs` | batch evaluation, degree elevation (Zhou), monomial conversion, integral, flattening, forward differences |
//! | `intersect.rs` | [`intersections`] of two planar curves by subdivision with box pruning |

mod bernstein;
mod bezier;
mod bezier_ops;
mod intersect;
mod reparametrised;
mod scalar;

pub use bernstein::{bernstein, bernstein_all, bernstein_derivative};
pub use bezier::Bezier;
pub use bezier_ops::MAX_FLATTEN_SEGMENTS;
pub use intersect::{intersections, Intersection, MAX_INTERSECTION_PAIRS};
pub use reparametrised::Reparametrised;
pub use scalar::{
    binomial, parse_scalar, validate_parameter, validate_points, Finite, ParseScalar, Point, Scalar,
};
