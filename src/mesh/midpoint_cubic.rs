//! The midpoint scheme M₃ = A²R of [PPB, §16.1]: refine every face into quadrilaterals
//! through its centre and its edges' midpoints (R), then twice replace the mesh by the mesh
//! of its face centroids (A). On a regular quadrilateral grid it is bicubic uniform B-spline
//! subdivision, exactly as Catmull–Clark; at a vertex of valence n ≠ 4 and at an edge next
//! to a face that is not a quadrilateral its rules differ.
//!
//! Composed into one round, the rules are those written on [`midpoint_cubic_with`]; on
//! the boundary they are Catmull–Clark's crease rules.
//!
//! # Complexity
//!
//! Θ(4ᵏ·H·D) time and space for k rounds on H corners in R^D, as Catmull–Clark; the edge rule
//! reads four more points.
//!
//! Invariants the tests check: it equals Catmull–Clark on meshes of quadrilaterals whose
//! interior vertices all have valence 4, and differs at extraordinary vertices by exactly
//! the difference of the two vertex rules.

use super::catmull_clark::{subdivide_rounds, Rules};
use super::polygon_mesh::PolygonMesh;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::Scalar;
use crate::Result;

/// The midpoint scheme M₃, declared.
pub(crate) const MIDPOINT_CUBIC: Declaration = Declaration {
    problem: "mesh-subdivision",
    name: "midpoint-cubic",
    function: "mesh::midpoint_cubic",
    file: "src/mesh/midpoint_cubic.rs",
    summary: "k rounds of the midpoint scheme M₃ = A²R (refine, then average twice), crease rules on the boundary",
    time: "Θ(4ᵏ·H·D) for k rounds on H corners",
    space: "Θ(4ᵏ·H·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "point additions and scalings: exactly 3H + 3Vᵢ + 4V_b + 10Eᵢ + 2E_b per round",
    source: "[PPB, §16.1]",
    claims: &[on(
        "irregular-torus",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// `rounds` rounds of the midpoint scheme M₃. See [`midpoint_cubic_with`].
///
/// # Errors
///
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the result would have more than
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners (checked before the first
/// round).
///
/// # Complexity
///
/// Θ(4ᵏ·H·D) for k rounds on H corners in time, Θ(4ᵏ·H·D) in space (in R^D).
///
/// ```
/// use compgeo::gen::{cube, quad_grid};
/// use compgeo::mesh::{catmull_clark, midpoint_cubic};
///
/// // The same rules where every interior vertex has valence 4 (integer coordinates, so
/// // both sets of rules compute exactly in f64) ...
/// let grid = quad_grid(4, 3)?;
/// assert_eq!(midpoint_cubic(&grid, 2)?, catmull_clark(&grid, 2)?);
/// // ... different ones at the cube's corners of valence 3.
/// let (m, c) = (midpoint_cubic(&cube(), 1)?, catmull_clark(&cube(), 1)?);
/// assert_eq!(m.topology(), c.topology());
/// assert_ne!(m.position(0), c.position(0));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn midpoint_cubic<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
) -> Result<PolygonMesh<S, D>> {
    midpoint_cubic_with(mesh, rounds, &mut NoCount)
}

/// `rounds` rounds of the midpoint scheme M₃ = A²R of `mesh`, counting one
/// [`arithmetic_operation`](Counter::arithmetic_operation) per point addition or scaling.
/// The connectivity and its numbering are those of
/// [`catmull_clark_with`](super::catmull_clark_with).
///
/// M₃ refines every face into quadrilaterals through its centre and its edges' midpoints
/// (R), then twice replaces the mesh by the mesh of its face centroids (A) [PPB, §16.1].
/// Composed into one round:
///
/// - face point: the centroid, as in Catmull–Clark;
/// - edge point of an interior edge vw: (10v + 10w + 4f₁ + 4f₂ + u + x + y + z)/32, where
///   f₁, f₂ are the face points of its two faces and u, x, y, z the far ends of the four
///   edges that continue vw in them; when both faces are quadrilaterals this is
///   Catmull–Clark's (v + w + f₁ + f₂)/4;
/// - vertex point of an interior vertex of valence n: v/4 + R/2 + Q/4 =
///   v/2 + (Σ wⱼ + Σ fⱼ)/(4n) over its neighbours and face points; Catmull–Clark's
///   (Q + 2R + (n − 3)v)/n is the same only for n = 4.
///
/// So both are bicubic B-spline subdivision on a regular grid and differ at extraordinary
/// vertices. A has no boundary (the centroids of the faces of a mesh with boundary span a
/// smaller mesh), so boundary vertices and edges take Catmull–Clark's crease rules.
///
/// # Errors
///
/// As [`midpoint_cubic`].
///
/// # Complexity
///
/// Θ(4ᵏ·H·D) time and space; per round exactly 3H + 3Vᵢ + 4V_b + 10Eᵢ + 2E_b point
/// operations (as [`catmull_clark_with`](super::catmull_clark_with), with ten for an
/// interior edge point).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::cube;
/// use compgeo::mesh::midpoint_cubic_with;
///
/// let mut counts = Counts::default();
/// midpoint_cubic_with(&cube(), 1, &mut counts)?;
/// // H = 24, V = 8, E = 12, all interior.
/// assert_eq!(counts.arithmetic_operations, 3 * 24 + 3 * 8 + 10 * 12);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn midpoint_cubic_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    subdivide_rounds(mesh, rounds, Rules::Midpoint, counter)
}
