//! Tensor-product and triangular surfaces, generic over the scalar (`f64`, exact rationals) and the
//! dimension, sharing traits as the curves of [`spline`](crate::spline) do.
//!
//! A tensor-product surface moves the control points of a curve along curves of their own
//! [FJ-surfaces, §1–2]: with a net of points c_{i,j} (i along u, j along v), each row is the
//! control polygon of a curve in v, and the points of those curves at v are the control
//! polygon of the curve of the surface at that v. Every algorithm on a surface is an
//! algorithm on curves, row by row and column by column, and the surface types run the curve
//! code of [`spline`](crate::spline) rather than a second copy of it.
//!
//! | type | domain | what it is |
//! |---|---|---|
//! | [`BezierPatch`] | the whole plane (the net describes [0, 1]²) | Σ c_{i,j} Bᵢᵐ(u) Bⱼⁿ(v) [FJ-surfaces, §2], [PPB, §9.2] |
//! | [`BezierPatchGrid`] | the rectangle of its grid | Bézier patches over the cells of a grid (the Bézier form of a spline surface) |
//! | [`BSplineSurface`] | the rectangle of the knot vectors' domains | Σ c_{i,j} Nᵢᵖ(u) Nⱼ^q(v) [PPB, §9.1] |
//! | [`NurbsSurface`] | the same | Σ w_{i,j} c_{i,j} NᵢNⱼ / Σ w_{i,j} NᵢNⱼ [SPL, §14] |
//! | [`TriangularPatch`] | the whole plane (the net describes a triangle p q r) | Σ b_{ijk} B^n_{ijk}(u, v, w) in barycentric coordinates [PPB, §10.2] |
//!
//! | file | what it holds |
//! |---|---|
//! | `traits.rs` | [`Surface`] (a [`SurfaceDomain`] and evaluation), [`SurfaceDerivative`] (partial derivatives of any orders) |
//! | `net.rs` | [`ControlNet`]: a rectangular grid of finite points, validated once |
//! | `bezier.rs` | [`BezierPatch`]: evaluation rows first, columns first and by the tensor de Casteljau algorithm, isoparametric curves, partial derivatives through the curve code [FJ-surfaces, §2, §5], [PPB, §9.2, §9.5] |
//! | `blossom.rs` | [`BezierPatch::blossom`]: the tensor polar form b[u₁…u_m; v₁…v_n] [PPB, §9.3], [FJ-surfaces, §4] |
//! | `subdivide.rs` | [`BezierPatch::restrict`] to [a, b] × [c, d], [`BezierPatch::split_u`], [`BezierPatch::split_v`], [`BezierPatch::split`] into four, by the curve code's subdivision [FJ-surfaces, §4], [PPB, §9.5] |
//! | `elevate.rs` | [`BezierPatch::elevate_u`], [`BezierPatch::elevate_v`], [`BezierPatch::elevate_to`] [FJ-surfaces, §5], [PPB, §3.12] |
//! | `derivative.rs` | [`BezierPatch::derivative_net`], [`BezierPatch::twist_net`]: the hodograph nets m!n!/((m − r)!(n − s)!) Δ^{r,s}c [FJ-surfaces, §6], [PPB, §9.6] |
//! | `normal.rs` | [`normal`] of any [`SurfaceDerivative`] in R³: c_u × c_v, or [`Normal::Degenerate`] with the first-order terms where it vanishes [FJ-surfaces, §6] |
//! | `monomial.rs` | [`BezierPatch::to_monomial`], [`BezierPatch::from_monomial`] [PPB, §9.4] |
//! | `bounds.rs` | [`BezierPatch::bounding_box`] of the net [PPB, §9.2, Obs. 4] |
//! | `join.rs` | [`BezierPatch::join_u`], [`BezierPatch::join_v`] (Cʳ checks), [`BezierPatch::extend_cr_u`], [`BezierPatch::extend_cr_v`] (Cʳ continuations) [FJ-surfaces, §6], [PPB, §9.7] |
//! | `direction.rs` | [`Direction`]: u or v, for the operations in one parameter |
//! | `bezier_grid.rs` | [`BezierPatchGrid`]: patches over grid cells, evaluation and derivatives by the chain rule |
//! | `bspline.rs` | [`BSplineSurface`]: validation, evaluation by de Boor on the rows, partial derivatives [PPB, §9.1] |
//! | `bspline_insert.rs` | [`BSplineSurface::insert`], [`BSplineSurface::refine`]: Boehm's insertion on every row or column [PPB, §6.1] |
//! | `bspline_to_bezier.rs` | [`BSplineSurface::to_bezier`]: rows, then columns, to Bézier pieces [PPB, §5.10] |
//! | `bspline_elevate.rs` | [`BSplineSurface::elevate`]: the curves' elevation on every row or column [PPB, §6.4–6.5] |
//! | `bspline_iso.rs` | [`BSplineSurface::isocurve`]: the isoparametric curves as B-splines |
//! | `tensor_grid.rs` | [`BSplineSurface::eval_grid`], [`NurbsSurface::eval_grid`]: every pair of two parameter lists, each basis once [FJ-surfaces, §1–2] |
//! | `nurbs.rs` | [`NurbsSurface`]: the homogeneous form, every operation on both halves, the quotient rule [SPL, §14] |
//! | `interpolate.rs` | [`BSplineSurface::interpolate_at`], [`BSplineSurface::interpolate`], [`BezierPatch::interpolate`]: rows, then columns [FJ-surfaces, §7] |
//! | `least_squares.rs` | [`BSplineSurface::fit`], [`BezierPatch::fit`]: normal equations with a rank check [FJ-surfaces, §7] |
//! | `loft.rs` | [`BezierPatch::bilinear`], [`BSplineSurface::loft`]: through compatible curves [RD, §3.3] |
//! | `bicubic.rs` | [`BezierPatchGrid::bicubic_c1`]: piecewise bicubic C¹ interpolation [PPB, §9.8] |
//! | `lane_riesenfeld.rs` | [`ControlNet::lane_riesenfeld`]: k rounds of tensor Lane–Riesenfeld subdivision of bidegree (p, q) on a regular net, the curve algorithm on the rows then the columns; [`ControlNet::limit_points`] [PPB, §15.1–15.2] |
//! | `tessellate.rs` | [`tessellate`], [`tessellate_at_with`]: any surface in R³ as a [`TriangleMesh`] with unit normals |
//! | `export.rs` | [`TriangleMesh::write_obj`] (Wavefront OBJ), [`TriangleMesh::write_stl`] (ASCII STL) |
//! | `triangle/` | [`TriangularPatch`]: triangular Bézier patches, one algorithm per file (its own table in [`triangle`]) [PPB, ch. 10–11] |
//!
//! Sources are cited as `[KEY, §section]` (see `docs/references.md`): FJ-surfaces is
//! L. Fernández Jambrina, *Tema 5: Superficies*; PPB is M. Paluszny, H. Prautzsch, W. Boehm,
//! *Métodos de Bézier y B-splines*; SPL the lecture notes *Curvas spline*; RD is I. Ruiz
//! Donaire, *Resumen de la asignatura Geometría Aplicada*.

mod bezier;
mod bezier_grid;
mod bicubic;
mod blossom;
mod bounds;
mod bspline;
mod bspline_elevate;
mod bspline_insert;
mod bspline_iso;
mod bspline_to_bezier;
mod derivative;
mod direction;
mod elevate;
mod export;
mod interpolate;
mod join;
mod lane_riesenfeld;
mod least_squares;
mod loft;
mod monomial;
mod net;
mod normal;
mod nurbs;
mod subdivide;
mod tensor_grid;
mod tessellate;
mod traits;
pub mod triangle;

/// The surface algorithms, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 34] = [
    &bezier::ROWS_FIRST,
    &bezier::COLUMNS_FIRST,
    &bezier::TENSOR_DE_CASTELJAU,
    &blossom::BLOSSOM,
    &subdivide::RESTRICT,
    &subdivide::SPLIT_U,
    &subdivide::SPLIT_V,
    &subdivide::SPLIT,
    &elevate::ELEVATE_TO,
    &derivative::DERIVATIVE_NET,
    &monomial::TO_MONOMIAL,
    &monomial::FROM_MONOMIAL,
    &bounds::BOUNDING_BOX,
    &join::JOIN_U,
    &join::JOIN_V,
    &join::EXTEND_CR_U,
    &join::EXTEND_CR_V,
    &normal::NORMAL,
    &tessellate::TESSELLATE,
    &bspline::TENSOR_DE_BOOR,
    &bspline_insert::SURFACE_INSERT,
    &bspline_insert::SURFACE_REFINE,
    &bspline_to_bezier::SURFACE_TO_BEZIER,
    &bspline_elevate::SURFACE_ELEVATE,
    &bspline_iso::SURFACE_ISOCURVE,
    &nurbs::NURBS_SURFACE_EVAL,
    &tensor_grid::BSPLINE_GRID,
    &tensor_grid::NURBS_GRID,
    &interpolate::SURFACE_INTERPOLATE,
    &least_squares::SURFACE_FIT,
    &loft::LOFT,
    &bicubic::BICUBIC_C1,
    &lane_riesenfeld::NET_LANE_RIESENFELD,
    &lane_riesenfeld::NET_LIMIT_POINTS,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::bezier::{COLUMNS_FIRST, ROWS_FIRST, TENSOR_DE_CASTELJAU};
    pub(crate) use super::bicubic::BICUBIC_C1;
    pub(crate) use super::blossom::BLOSSOM;
    pub(crate) use super::bounds::BOUNDING_BOX;
    pub(crate) use super::bspline::TENSOR_DE_BOOR;
    pub(crate) use super::bspline_elevate::SURFACE_ELEVATE;
    pub(crate) use super::bspline_insert::{SURFACE_INSERT, SURFACE_REFINE};
    pub(crate) use super::bspline_iso::SURFACE_ISOCURVE;
    pub(crate) use super::bspline_to_bezier::SURFACE_TO_BEZIER;
    pub(crate) use super::derivative::DERIVATIVE_NET;
    pub(crate) use super::elevate::ELEVATE_TO;
    pub(crate) use super::interpolate::SURFACE_INTERPOLATE;
    pub(crate) use super::join::{EXTEND_CR_U, EXTEND_CR_V, JOIN_U, JOIN_V};
    pub(crate) use super::lane_riesenfeld::{NET_LANE_RIESENFELD, NET_LIMIT_POINTS};
    pub(crate) use super::least_squares::SURFACE_FIT;
    pub(crate) use super::loft::LOFT;
    pub(crate) use super::monomial::{FROM_MONOMIAL, TO_MONOMIAL};
    pub(crate) use super::normal::NORMAL;
    pub(crate) use super::nurbs::NURBS_SURFACE_EVAL;
    pub(crate) use super::subdivide::{RESTRICT, SPLIT, SPLIT_U, SPLIT_V};
    pub(crate) use super::tensor_grid::{BSPLINE_GRID, NURBS_GRID};
    pub(crate) use super::tessellate::TESSELLATE;
}

pub use bezier::BezierPatch;
pub use bezier_grid::BezierPatchGrid;
pub use bspline::BSplineSurface;
pub use direction::Direction;
pub use net::ControlNet;
pub use normal::{normal, normal_with, Normal};
pub use nurbs::NurbsSurface;
pub use tessellate::{tessellate, tessellate_at_with, TriangleMesh};
pub use traits::{Surface, SurfaceDerivative, SurfaceDomain};
pub use triangle::{Barycentric, BarycentricVector, TriangularPatch};
