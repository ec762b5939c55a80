//! Triangular Bézier patches: polynomial surfaces over a triangle in barycentric
//! coordinates, generic over the scalar (`f64`, exact rationals) and the dimension.
//!
//! A patch of degree n over the reference triangle p q r is
//! b(u, v, w) = Σ b_{ijk} B^n_{ijk}(u, v, w), i + j + k = n, with the bivariate Bernstein
//! polynomials B^n_{ijk} = n!/(i! j! k!) uⁱ vʲ wᵏ and u + v + w = 1 [PPB, §10.1–10.2]. Every
//! algorithm here comes from the blossom, the symmetric multi-affine b[x₁, …, x_n] whose
//! diagonal is the patch and whose values b[p^i q^j r^k] are the control points
//! [PPB, §11.1–11.2]: de Casteljau's scheme computes it, subdivision reads it off the scheme,
//! derivatives put directions among its arguments.
//!
//! Points of the domain are [`Barycentric`] (u + v + w = 1, checked exactly), directions
//! [`BarycentricVector`] (the coordinates sum to 0). The control points are stored flat, the
//! rows of constant k first to last, each by increasing j ([`storage_index`]).
//!
//! | file | what it holds |
//! |---|---|
//! | `barycentric.rs` | [`Barycentric`], [`BarycentricVector`]: validated once |
//! | `patch.rs` | [`TriangularPatch`]: validation, the storage order ([`storage_index`], [`multi_indices`]), the [`Surface`](crate::surface::Surface) traits in (u, v) with w = 1 − u − v |
//! | `basis.rs` | [`bernstein_basis`], [`TriangularPatch::bernstein_sum`] [PPB, §10.1–10.2] |
//! | `de_casteljau.rs` | [`TriangularPatch::de_casteljau`], the level every algorithm runs [PPB, §10.4] |
//! | `blossom.rs` | [`TriangularPatch::blossom`]: b[x₁, …, x_n] [PPB, §11.1–11.2] |
//! | `derivative.rs` | [`TriangularPatch::directional_derivative`] of any order: n!/(n − r)! b[d₁ … d_r x … x] [PPB, §10.5, §11.6] |
//! | `subdivide.rs` | [`TriangularPatch::subdivide`] at a point into three patches [PPB, §11.3] |
//! | `split.rs` | [`TriangularPatch::split_four`]: the four midpoint triangles by repeated bisection [PPB, §11.5, Figs. 11.6–11.7] |
//! | `elevate.rs` | [`TriangularPatch::elevate`], [`TriangularPatch::elevate_to`] [PPB, §11.8] |
//! | `join.rs` | [`TriangularPatch::join_order`] (the Cʳ check across an edge), [`TriangularPatch::extend_cr`] (the Cʳ continuation) [PPB, §11.7] |
//! | `to_tensor.rs` | [`TriangularPatch::to_tensor`]: a [`BezierPatch`](crate::surface::BezierPatch) of bidegree (n, n) over a degenerate square [PPB, §11.10] |
//! | `tessellate.rs` | [`TriangularPatch::tessellate`]: the uniform refinement of the triangle as a [`TriangleMesh`](crate::surface::TriangleMesh) with normals, for the OBJ and STL writers [PPB, §10.3–10.5] |
//! | `from_tensor.rs` | [`TriangularPatch::from_tensor`]: the two halves of a tensor patch of bidegree (m, n), degree m + n [PPB, §11.11] |
//!
//! Sources are cited as `[KEY, §section]` (see `docs/references.md`); PPB is M. Paluszny,
//! H. Prautzsch, W. Boehm, *Métodos de Bézier y B-splines*, chapters 10 and 11.

mod barycentric;
mod basis;
mod blossom;
mod de_casteljau;
mod derivative;
mod elevate;
mod from_tensor;
mod join;
mod patch;
mod split;
mod subdivide;
mod tessellate;
mod to_tensor;

/// The triangular-patch algorithms, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 12] = [
    &de_casteljau::DE_CASTELJAU,
    &basis::BERNSTEIN_SUM,
    &blossom::BLOSSOM,
    &derivative::DIRECTIONAL_DERIVATIVE,
    &subdivide::SUBDIVIDE,
    &split::SPLIT_FOUR,
    &elevate::ELEVATE_TO,
    &join::JOIN_ORDER,
    &join::EXTEND_CR,
    &to_tensor::TO_TENSOR,
    &from_tensor::FROM_TENSOR,
    &tessellate::TESSELLATE,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::basis::BERNSTEIN_SUM;
    pub(crate) use super::blossom::BLOSSOM;
    pub(crate) use super::de_casteljau::DE_CASTELJAU;
    pub(crate) use super::derivative::DIRECTIONAL_DERIVATIVE;
    pub(crate) use super::elevate::ELEVATE_TO;
    pub(crate) use super::from_tensor::FROM_TENSOR;
    pub(crate) use super::join::{EXTEND_CR, JOIN_ORDER};
    pub(crate) use super::split::SPLIT_FOUR;
    pub(crate) use super::subdivide::SUBDIVIDE;
    pub(crate) use super::tessellate::TESSELLATE;
    pub(crate) use super::to_tensor::TO_TENSOR;
}

pub use barycentric::{Barycentric, BarycentricVector};
pub use basis::bernstein_basis;
pub use patch::{multi_indices, storage_index, TriangularPatch};
