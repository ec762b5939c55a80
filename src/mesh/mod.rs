//! Polygon meshes and subdivision surfaces on them.
//!
//! A [`PolygonMesh`] is a list of vertex positions (generic over the [`Scalar`](crate::spline::Scalar)
//! and the dimension, as the curves and surfaces are) and faces of any number of corners,
//! validated once into flat half-edge arrays, a [`MeshTopology`], in the style of
//! delaunator's `triangles` / `halfedges`: half-edge `h` is corner `h` of its face, so
//! origin, next, previous and face are index arithmetic, and only the twins, the edges and
//! one outgoing half-edge per vertex are stored. Every scheme reads its neighbourhoods from
//! these arrays and builds the refined mesh's arrays directly from the coarse ones.
//!
//! The validation is the promise every algorithm here relies on: the mesh is an oriented
//! 2-manifold, possibly with boundary. Each way a face list can break it is its own
//! [`MeshError`] naming the face (or vertex): an index out of range, a face with fewer than
//! three corners or a repeated vertex, an edge with a third face, two faces running along an
//! edge in the same direction, a vertex whose faces do not form one fan, a vertex no face
//! uses; non-finite coordinates are [`Error::NonFinite`](crate::Error::NonFinite).
//!
//! | file | what it holds |
//! |---|---|
//! | `error.rs` | [`MeshError`], [`ObjProblem`]: every violation and every malformed OBJ line, named |
//! | `topology.rs` | [`MeshTopology`]: the half-edge arrays, their validation and their invariant checker [`MeshTopology::check`], one-ring walks ([`OneRing`]), valence, boundary loops, Euler characteristic |
//! | `polygon_mesh.rs` | [`PolygonMesh`]: positions and topology |
//! | `obj.rs` | [`read_obj`], [`write_obj`]: Wavefront OBJ text |
//! | `quad_split.rs` | the connectivity of one round of quad refinement (every n-gon into n quadrilaterals), by index arithmetic on the coarse arrays |
//! | `triangle_split.rs` | the connectivity of one round of triangle refinement (every triangle into four), by index arithmetic on the coarse arrays |
//! | `catmull_clark.rs` | [`catmull_clark`]: k rounds on faces of any size, crease rules on the boundary [PPB, §16.1] |
//! | `midpoint_cubic.rs` | [`midpoint_cubic`]: the midpoint scheme M₃ = A²R, which differs from Catmull–Clark at extraordinary vertices [PPB, §16.1] |
//! | `doo_sabin.rs` | [`doo_sabin`]: k rounds of the midpoint scheme M₂ = 𝒜𝓡 (Doo–Sabin) on faces of any size, with the corrected weights [`doo_sabin_weights`] (b = 2 + 4/m, the erratum of [PPB, §16.4]); [`doo_sabin_limit_points`] [PPB, §16.1, §16.4] |
//! | `loop_subdivision.rs` | [`loop_subdivision`]: k rounds of Loop's scheme on triangle meshes (Loop's or Warren's weights, [`LoopWeights`]), boundary as cubic B-spline curves; [`loop_limit_points`] [PPB, §15.7–15.8, §16.9] |
//! | `scheme.rs` | [`Scheme`]: the schemes by name (`--scheme`), [`subdivide`] |
//! | `catmull_clark_limit.rs` | [`catmull_clark_limit`]: limit positions in closed form [PPB, §16.4] |
//!
//! Seeded meshes for tests and benchmarks (grids, a cube, tori, an irregular mesh with
//! extraordinary vertices) are in [`gen`](crate::gen) ([`gen::mesh`](crate::gen::mesh)).

mod catmull_clark;
mod catmull_clark_limit;
mod doo_sabin;
mod error;
mod loop_subdivision;
mod midpoint_cubic;
mod obj;
mod polygon_mesh;
mod quad_split;
mod scheme;
mod topology;
mod triangle_split;

/// The mesh algorithms outside the [`Scheme`] family, declared.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 3] = [
    &catmull_clark_limit::CATMULL_CLARK_LIMIT,
    &loop_subdivision::LOOP_LIMIT,
    &doo_sabin::DOO_SABIN_LIMIT,
];

/// The declarations the catalog's entries measure, by name.
pub(crate) mod declarations {
    pub(crate) use super::catmull_clark::CATMULL_CLARK;
    pub(crate) use super::catmull_clark_limit::CATMULL_CLARK_LIMIT;
    pub(crate) use super::doo_sabin::{DOO_SABIN, DOO_SABIN_LIMIT};
    pub(crate) use super::loop_subdivision::{LOOP, LOOP_LIMIT};
    pub(crate) use super::midpoint_cubic::MIDPOINT_CUBIC;
}

pub use catmull_clark::{catmull_clark, catmull_clark_with};
pub use catmull_clark_limit::{catmull_clark_limit, catmull_clark_limit_with};
pub use doo_sabin::{
    doo_sabin, doo_sabin_limit_points, doo_sabin_limit_points_with, doo_sabin_weights,
    doo_sabin_with,
};
pub use loop_subdivision::{
    loop_limit_points, loop_limit_points_with, loop_subdivision, loop_subdivision_weighted,
    loop_subdivision_weighted_with, loop_subdivision_with, LoopWeights,
};
pub use midpoint_cubic::{midpoint_cubic, midpoint_cubic_with};
pub use scheme::{subdivide, subdivide_with, Scheme};

pub use error::{MeshError, ObjProblem};
pub use obj::{read_obj, write_obj};
pub use polygon_mesh::PolygonMesh;
pub use topology::{MeshTopology, OneRing, NONE};
