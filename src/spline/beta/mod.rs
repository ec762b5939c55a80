//! Cubic Beta-splines: the basis with bias β₁ and tension β₂, curves over a control polygon,
//! their subdivision matrices for any c in (0, 1), recursive subdivision, and the β-continuity
//! conditions at a joint.
//!
//! A cubic Beta-spline generalises the uniform cubic B-spline (β₁ = 1, β₂ = 0): consecutive
//! segments meet with geometric (G²) rather than parametric (C²) continuity, β₁ skewing and β₂
//! tightening the curve [CCKS, §3]. The subdivision matrices are those of [CCKS, §2], which
//! follows Goldman and DeRose: S_L = C⁻¹·S_Lᴮ·C and S_R = C⁻¹·S_Rᴮ·C, with C the basis in
//! Bernstein form.
//!
//! # The seed's errata
//!
//! Three misprints of the seed are settled here (`docs/design.md`, "Beta-splines", has the
//! details): the normaliser is δ = 2β₁³ + 4β₁² + 4β₁ + β₂ + 2 (the seed writes γ = 1/(β₂ + 12),
//! correct only for β₁ = 1, and multiplies by 1/γ where it divides); B₂'s third coefficient is
//! (6β₁² + 3β₂)t² (the seed loses the t²); and S_R is computed from eq. (8), never as the
//! reversal of S_L, which it equals only for β₁ = 1 (and c = ½). With those read right, the
//! seed's printed matrices (β₁ = 1, c = ½, β₂ = 0, 5, −10) are reproduced exactly.
//!
//! | file | problem | time |
//! |---|---|---|
//! | `parameters.rs` | [`BetaParameters`]: β₁ > 0, β₂ ≥ 0 (or any β₂ with [`BetaParameters::allowing_negative_tension`]), δ, rejection of the degenerate values | O(1) |
//! | `basis.rs` | [`BetaParameters::basis`], [`BetaParameters::basis_derivatives`], [`BetaParameters::monomial_matrix`], [`BetaParameters::bernstein_matrix`] (C) and its inverse [CCKS, §3] | O(1) |
//! | `curve.rs` | [`BetaSpline`]: open control polygon, segment i on points i..i + 3, [`BetaSpline::eval`] [CCKS, §3] | O(log m + D) |
//! | `matrices.rs` | [`SubdivisionMatrices`] by eq. (7)–(8) and by Lemma 1, the convex-hull predicate (Lemma 4) [CCKS, §2] | O(1) |
//! | `subdivide.rs` | [`BetaSpline::subdivide`]: k rounds, m·2ᵏ polygons [CCKS, §2–3] | Θ(m·2ᵏ·D) |
//! | `continuity.rs` | [`is_beta_continuous`], [`BetaSpline::joins_beta_continuously`]: the G² conditions with β₁, β₂ [CCKS, §3] | O(D) |
//!
//! ```
//! use compgeo::spline::{BetaParameters, BetaSpline, Point};
//! use num_rational::BigRational as Q;
//!
//! let q = |n: i64, d: i64| Q::new(n.into(), d.into());
//! // The seed's second example: β₁ = 1, β₂ = 5, c = ½.
//! let m = BetaParameters::new(q(1, 1), q(5, 1))?.subdivision_matrices(&q(1, 2))?;
//! assert_eq!(m.left()[0], [q(79, 153), q(39, 68), q(-55, 612), q(0, 1)]);
//! assert!(!m.keeps_convex_hull());
//! # Ok::<(), compgeo::Error>(())
//! ```

mod basis;
mod continuity;
mod curve;
mod matrices;
mod parameters;
mod subdivide;

pub use continuity::{is_beta_continuous, is_beta_continuous_with};
pub use curve::BetaSpline;
pub use matrices::SubdivisionMatrices;
pub use parameters::BetaParameters;

/// A 4 × 4 matrix, row by row: the basis and subdivision matrices of a cubic segment.
pub type Matrix4<S> = [[S; 4]; 4];

/// The Beta-spline algorithms, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 5] = [
    &basis::BASIS,
    &curve::EVAL,
    &matrices::MATRICES,
    &subdivide::SUBDIVIDE,
    &continuity::CONTINUITY,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::basis::BASIS;
    pub(crate) use super::continuity::CONTINUITY;
    pub(crate) use super::curve::EVAL;
    pub(crate) use super::matrices::MATRICES;
    pub(crate) use super::subdivide::SUBDIVIDE;
}
