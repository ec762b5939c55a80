//! B-splines: knot vectors, the B-spline basis, and B-spline curves with de Boor's algorithm,
//! Boehm's knot insertion, the Oslo refinement, knot removal, splitting, conversion to and
//! from Bézier pieces, degree elevation, interpolation and least-squares fitting.
//!
//! # The knot convention
//!
//! One convention, used by every item of this module: a spline of **degree d with n control
//! points** c₀, …, c_{n−1} lives on **n + d + 1 knots** t₀ ≤ t₁ ≤ … ≤ t_{n+d}; the basis
//! function N_i (i = 0, …, n − 1) has support [t_i, t_{i+d+1}], and the spline
//! s(u) = Σ c_i N_i(u) is defined on its **domain [t_d, t_n]**, where the basis functions sum
//! to one. The domain is the same formula for clamped vectors (t₀ = … = t_d and
//! t_n = … = t_{n+d}, whose curves start and end at their end control points) and for
//! unclamped ones (uniform vectors, whose first and last d knots lie outside the domain). This
//! is [PPB, §5.7]'s convention (m + 1 B-splines N₀, …, N_m on knots a₀, …, a_{m+n+1}, on
//! [a_n, a_{m+1}]).
//!
//! The course's lecture notes [SPL, §7, §12] count differently: n + N control points of
//! degree n on 2n + N − 1 knots u₀, …, u_{2n+N−2}, that is control points + degree − 1
//! knots, without the two end knots t₀ and t_{n+d}, which influence no basis function on the
//! domain. [`KnotVector::from_spl`] and [`KnotVector::to_spl`] convert (tᵢ₊₁ = uᵢ); a test
//! checks that both give the same basis.
//!
//! # Exactness
//!
//! Knots and parameters are compared exactly, never with a tolerance: a knot a few ulps from
//! another is a distinct knot, with its own (tiny) span, and the multiplicity of a knot is the
//! number of times that very number occurs. A tolerance would merge distinct knots until a
//! multiplicity passes d + 1, and would decide differently for `f64` and for the exact
//! back end; with exact comparisons both decide the same, and with `BigRational` every value
//! is exact (the partition of unity holds with `==`).
//!
//! Values are right-continuous, with the closed last interval: at u = t_n the last non-empty
//! span is used. In the Cox–de Boor recursion a term whose denominator (a support width) is
//! zero is zero, the convention 0/0 = 0 of [PPB, §5.3].
//!
//! | file | problem | time |
//! |---|---|---|
//! | `knots.rs` | [`KnotVector`]: validation, [`clamped_uniform`](KnotVector::clamped_uniform), [`uniform`](KnotVector::uniform), [`averaged`](KnotVector::averaged), [`from_spl`](KnotVector::from_spl), [`multiplicities`](KnotVector::multiplicities), [`domain`](KnotVector::domain), [`span`](KnotVector::span) [PPB, §5.1, §5.4, §5.7], [SPL, §12] | Θ(n + d); span O(log(n − d)) |
//! | `basis.rs` | [`KnotVector::basis`] ([`Basis`]), [`KnotVector::basis_derivatives`] ([`BasisDerivatives`]) [PPB, §5.3, §5.7] | Θ(d²); O(d² + d·K²) |
//! | `curve.rs` | [`BSpline`]: validation, the curve traits, the derivative curve [PPB, §5.6] | Θ(nD); Θ((n + d)D) |
//! | `de_boor.rs` | [`BSpline::de_boor`], [`BSpline::de_boor_with`], the net [`BSpline::de_boor_trace`] ([`DeBoorLevel`] frames) [PPB, §5.4] | Θ(d²D) |
//! | `derivatives.rs` | [`BSpline::derivatives`], [`BSpline::derivatives_with`]: s(u), s′(u), …, s⁽ᵏ⁾(u) at once by the extended de Boor algorithm (the tetrahedral scheme) [PPB, §5.9] | Θ((d² + K³)D) |
//! | `insert.rs` | [`BSpline::insert`], [`BSpline::insert_with`]: Boehm's insertion, once or r times [PPB, §6.1] | Θ((n + d + rd)D) |
//! | `to_bezier.rs` | [`BSpline::to_bezier`], [`BSpline::to_bezier_with`] (a [`CompositeBezier`](crate::spline::CompositeBezier) over the distinct knots of the domain), [`BSpline::from_bezier`] (interior knots of multiplicity d) [PPB, §5.10] | Θ(n + d + p·d·D) plus O(n·d²·D); Θ(p·d·D) |
//! | `elevate.rs` | [`BSpline::elevate`], [`BSpline::elevate_with`]: degree d → d + t, every knot t more times, by blossoms of the elevated Bézier pieces [PPB, §6.4, §6.5] | Θ((n + p·t)(d + t)²·D) |
//! | `blossom.rs` | [`BSpline::blossom`], [`BSpline::blossom_in_span`] (and `_with`): the polar form of a piece by the extended de Boor algorithm [PPB, §5.5, §5.9], [SPL, §6–7] | Θ(d²D) |
//! | `greville.rs` | [`KnotVector::greville`], [`KnotVector::marsden`] (Marsden's identity), [`BSpline::graph`] [PPB, §5.8, §5.12 Ex. 4] | Θ(nd) |
//! | `integral.rs` | [`BSpline::integral`], [`BSpline::integral_with`] (the antiderivative of degree d + 1), [`BSpline::definite_integral`] [PPB, §5.6, §5.12 Ex. 2] | Θ((n + d)D) |
//! | `batch.rs` | [`BSpline::eval_sorted`], [`BSpline::eval_sorted_with`], [`BSpline::eval_sorted_into`]: de Boor at sorted parameters with a forward span walk [PPB, §5.4] | Θ(m·d²D + n) |
//! | `refine.rs` | [`BSpline::refine`], [`BSpline::refine_with`]: m knots at once by Boehm's insertions in one backward pass, each point written once [PPB, §6.1–6.2] | O(m log m + log n + (n + m + md)D) |
//! | `oslo.rs` | [`BSpline::oslo`], [`BSpline::oslo_with`]: the Oslo algorithm, m knots at once by the discrete B-splines [PPB, §6.2] | O(m log m + (n + m)D + md(d² + dD + log n)) |
//! | `remove.rs` | [`BSpline::remove`], [`BSpline::remove_within`] and their `_with` forms: knot removal, exact or within a distance, checked by re-insertion [PPB, §6.1] | O(r²(n + d)D) |
//! | `split.rs` | [`BSpline::split`], [`BSpline::split_with`]: the two pieces at a parameter, clamped at the cut [PPB, §6.1] | Θ((n + d²)D) |
//! | `banded.rs` | [`BandMatrix`]: banded Gaussian elimination without pivoting, every pivot checked [PPB, §6.7] | Θ(n·l·(u + D)) |
//! | `interpolate.rs` | [`BSpline::interpolate`], [`BSpline::interpolate_at`] (and `_with`): collocation after [`KnotVector::check_schoenberg_whitney`] [PPB, §6.7, §4.5] | Θ(n d² + n D d) |
//! | `fit.rs` | [`BSpline::fit`], [`BSpline::fit_with`]: least squares after [`KnotVector::check_fit_rank`]; [`BSpline::fit_improved`] ([`ParameterFit`]) [PPB, §4.7–4.8] | Θ(m d² + m d D + n d² + m log m) |
//! | `cubic.rs` | [`BSpline::cubic_spline`]: the C² cubic spline as a B-spline (natural, clamped, Bessel) [SPL, §3] | Θ(N·D) |
//!
//! ```
//! use compgeo::spline::KnotVector;
//!
//! // 5 control points of degree 2: 8 knots, domain [t₂, t₅] = [0, 3].
//! let t = KnotVector::clamped_uniform(2, 5, 0.0, 3.0)?;
//! assert_eq!(t.knots().len(), 5 + 2 + 1);
//! let b = t.basis(&1.5)?;
//! assert_eq!(b.values().iter().sum::<f64>(), 1.0);
//! # Ok::<(), compgeo::Error>(())
//! ```

mod banded;
mod basis;
mod batch;
mod blossom;
mod cubic;
mod curve;
mod de_boor;
mod derivatives;
mod elevate;
mod fit;
mod greville;
mod insert;
mod integral;
mod interpolate;
mod knots;
mod oslo;
mod refine;
mod remove;
mod split;
mod to_bezier;

/// The B-spline algorithms, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 22] = [
    &knots::SPAN,
    &basis::BASIS,
    &basis::BASIS_DERIVATIVES,
    &de_boor::DE_BOOR,
    &derivatives::DERIVATIVES,
    &insert::INSERT,
    &to_bezier::TO_BEZIER,
    &to_bezier::FROM_BEZIER,
    &elevate::ELEVATE,
    &blossom::BLOSSOM,
    &greville::GREVILLE,
    &greville::MARSDEN,
    &integral::INTEGRAL,
    &batch::EVAL_SORTED,
    &refine::REFINE,
    &oslo::OSLO,
    &remove::REMOVE,
    &split::SPLIT,
    &banded::BANDED,
    &interpolate::INTERPOLATE,
    &fit::FIT,
    &cubic::CUBIC_SPLINE,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::banded::BANDED;
    pub(crate) use super::basis::{BASIS, BASIS_DERIVATIVES};
    pub(crate) use super::batch::EVAL_SORTED;
    pub(crate) use super::blossom::BLOSSOM;
    pub(crate) use super::cubic::CUBIC_SPLINE;
    pub(crate) use super::de_boor::DE_BOOR;
    pub(crate) use super::derivatives::DERIVATIVES;
    pub(crate) use super::elevate::ELEVATE;
    pub(crate) use super::fit::FIT;
    pub(crate) use super::greville::{GREVILLE, MARSDEN};
    pub(crate) use super::insert::INSERT;
    pub(crate) use super::integral::INTEGRAL;
    pub(crate) use super::interpolate::INTERPOLATE;
    pub(crate) use super::knots::SPAN;
    pub(crate) use super::oslo::OSLO;
    pub(crate) use super::refine::REFINE;
    pub(crate) use super::remove::REMOVE;
    pub(crate) use super::split::SPLIT;
    pub(crate) use super::to_bezier::{FROM_BEZIER, TO_BEZIER};
}

pub use banded::BandMatrix;
pub use basis::{Basis, BasisDerivatives};
pub use curve::BSpline;
pub use de_boor::DeBoorLevel;
pub use fit::ParameterFit;
pub use knots::KnotVector;
