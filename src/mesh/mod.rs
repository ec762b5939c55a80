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
//!
//! Seeded meshes for tests and benchmarks (grids, a cube, tori, an irregular mesh with
//! extraordinary vertices) are in [`gen`](crate::gen) ([`gen::mesh`](crate::gen::mesh)).

mod error;
mod obj;
mod polygon_mesh;
mod topology;

pub use error::{MeshError, ObjProblem};
pub use obj::{read_obj, write_obj};
pub use polygon_mesh::PolygonMesh;
pub use topology::{MeshTopology, OneRing, NONE};
