//! Bézier curves: the Bernstein basis, the [`Bezier`] type and its algorithms, one per file,
//! curves over a global interval ([`Reparametrised`]) and composite curves
//! ([`CompositeBezier`]) with their join checks.
//!
//! Every type implements the curve traits of [`crate::spline`] ([`Curve`](super::Curve),
//! [`CurveDerivative`](super::CurveDerivative), [`Subsegment`](super::Subsegment)); the
//! kernels are generic over the scalar (`f64`, or exact `BigRational` with the feature
//! `exact`) and the dimension. The sources are [PPB, ch. 2–3] and [RD, §3.2].
//!
//! | file | problem | time (degree n, D coordinates) |
//! |---|---|---|
//! | `bernstein.rs` | [`bernstein`], [`bernstein_all`], [`bernstein_derivative`]: the basis [PPB, §2.1] | Θ(n), Θ(n²), O(n² + r²) |
//! | `curve.rs` | the [`Bezier`] type: control polygon, reversal, bounding box [PPB, §2.2] | Θ(nD) |
//! | `horner.rs` | the fast evaluation ([`Curve::eval`](super::Curve::eval), [`Bezier::at`], [`Bezier::eval_each`], [`Bezier::horner_with`]) [PPB, §2.3, Obs. 4] | Θ(nD) per point |
//! | `de_casteljau.rs` | [`Bezier::de_casteljau_with`], its scaffolding [`Bezier::de_casteljau_trace`], [`Bezier::split`], [`Bezier::restrict`], [`Bezier::blossom`], the subsegment [PPB, §2.3, §3.1–3.3] | Θ(n²D); restrict Θ(n³D) |
//! | `evaluation.rs` | [`Evaluation`], [`evaluate`], [`evaluate_with`]: the scheme chosen at run time | as the scheme |
//! | `derivative.rs` | [`Bezier::derivative`], [`Bezier::hodograph`], the tetrahedral algorithm [PPB, §2.4, §2.6] | Θ(r·nD), Θ(n²D) |
//! | `elevation.rs` | [`Bezier::elevate`], [`Bezier::elevate_to`] (Zhou) [PPB, §3.11–3.12] | Θ(nD), Θ(mnD) |
//! | `monomial.rs` | [`Bezier::to_monomial`], [`Bezier::from_monomial`] [PPB, §2.8–2.9] | Θ(n²D) |
//! | `integral.rs` | [`Bezier::integral`], [`Bezier::definite_integral`] [PPB, §2.7] | Θ(nD) |
//! | `flatten.rs` | [`Bezier::flatten`] by recursive subdivision [PPB, §3.5] | Θ(s·n²D), s segments |
//! | `forward_differences.rs` | [`Bezier::forward_differences`] on a uniform grid [PPB, §3.6] | Θ((n² + k·n)D), k points |
//! | `intersect.rs` | [`intersections`] of two planar curves [PPB, §3.7] | O(k·d·(m² + n²)) |
//! | `reparametrised.rs` | [`Reparametrised`]: a curve over [a, b] [RD, §3.2] | as the curve |
//! | `composite.rs` | [`CompositeBezier`]: pieces over a partition [RD, §3.2] | O(log m + nD) per point |
//! | `joins.rs` | [`Join`], C⁰/G¹/Cʳ checks, [`CompositeBezier::push_cr`], [`c1_partition`] [RD, §3.2], [PPB, §3.10] | Θ(n²D) per join |

mod bernstein;
mod composite;
mod curve;
mod de_casteljau;
mod derivative;
mod elevation;
mod evaluation;
mod flatten;
mod forward_differences;
mod horner;
mod integral;
mod intersect;
mod joins;
mod monomial;
mod reparametrised;

/// The Bézier operations that are not an evaluation scheme, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 5] = [
    &declarations::SPLIT,
    &declarations::BLOSSOM,
    &declarations::ELEVATE_TO,
    &declarations::FLATTEN,
    &declarations::INTERSECTIONS,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::de_casteljau::{BLOSSOM, SPLIT};
    pub(crate) use super::elevation::ELEVATE_TO;
    pub(crate) use super::flatten::FLATTEN;
    pub(crate) use super::intersect::INTERSECTIONS;
}

pub use bernstein::{bernstein, bernstein_all, bernstein_derivative};
pub use composite::CompositeBezier;
pub use curve::Bezier;
pub use de_casteljau::CasteljauLevel;
pub use evaluation::{evaluate, evaluate_with, Evaluation};
pub use flatten::MAX_FLATTEN_SEGMENTS;
pub use intersect::{intersections, intersections_with, Intersection, MAX_INTERSECTION_PAIRS};
pub use joins::{c1_partition, Join};
pub use reparametrised::Reparametrised;

pub(crate) use curve::bounding_box_counted;
pub(crate) use de_casteljau::de_casteljau_levels;
pub(crate) use derivative::difference;
pub(crate) use elevation::elevated_polygon;
pub(crate) use joins::nearly_equal;
pub(crate) use monomial::{from_monomial_counted, to_monomial_counted};
