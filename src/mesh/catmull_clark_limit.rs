//! The limit positions of Catmull–Clark subdivision: where each vertex of a quadrilateral
//! mesh ends up after infinitely many rounds, in closed form.
//!
//! The problem: the point of the limit surface that a control vertex converges to, without
//! subdividing. The idea: the limit of a vertex is a fixed affine combination of its
//! one-ring (the left eigenvector of the subdivision matrix for the eigenvalue 1 [PPB,
//! §16.4]); for Catmull–Clark on a quadrilateral mesh, an interior vertex v of valence n with
//! edge neighbours eⱼ and diagonal neighbours fⱼ (the corner of each quadrilateral opposite
//! v) goes to
//!
//! (n²·v + 4 Σ eⱼ + Σ fⱼ) / (n(n + 5)),
//!
//! which for n = 4 is the bicubic B-spline's (16v + 4 Σ eⱼ + Σ fⱼ)/36, the tensor product of
//! the cubic curve's (1, 4, 1)/6. Under the crease rules a boundary vertex follows the cubic
//! B-spline curve of the boundary polygon and goes to (v₋ + 4v + v₊)/6; a corner of valence 2
//! stays fixed.
//!
//! Because the stencil is an eigenvector, applying it after one round of
//! [`catmull_clark`](super::catmull_clark) gives exactly the same points as applying it
//! before: the tests check this identity on rationals for every valence.
//!
//! # Complexity
//!
//! Θ(H·D) time for H corners in R^D, Θ(V·D) space for the V positions.

use super::polygon_mesh::PolygonMesh;
use super::topology::NONE;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::{Error, Result};

/// Catmull–Clark limit positions, declared.
pub(crate) const CATMULL_CLARK_LIMIT: Declaration = Declaration {
    problem: "mesh-subdivision",
    name: "catmull-clark-limit",
    function: "mesh::catmull_clark_limit",
    file: "src/mesh/catmull_clark_limit.rs",
    summary: "the limit position of every vertex of a quadrilateral mesh from its one-ring stencil",
    time: "Θ(H·D) for H corners",
    space: "Θ(V·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "point additions and scalings: exactly 2n + 5 for an interior vertex of valence n, 4 for a boundary vertex, none for a corner",
    source: "[PPB, §16.4]",
    claims: &[on(
        "irregular-torus",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The limit positions of the vertices of a quadrilateral mesh under Catmull–Clark
/// subdivision. See [`catmull_clark_limit_with`].
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"mesh"` if a face is not a quadrilateral (one round of
/// [`catmull_clark`](super::catmull_clark) makes every face one).
///
/// # Complexity
///
/// Θ(H·D) for H corners in time, Θ(V·D) in space (V vertices in R^D).
///
/// ```
/// use compgeo::gen::quad_grid;
/// use compgeo::mesh::catmull_clark_limit;
/// use compgeo::spline::Point;
///
/// let grid = quad_grid(2, 2)?; // integer points in the plane z = 0
/// let limit = catmull_clark_limit(&grid)?;
/// assert_eq!(limit[4], Point::new([1.0, 1.0, 0.0])); // the centre: symmetric stencil
/// assert_eq!(limit[0], *grid.position(0)); // a corner stays
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn catmull_clark_limit<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
) -> Result<Vec<Point<S, D>>> {
    catmull_clark_limit_with(mesh, &mut NoCount)
}

/// The limit positions of the vertices of a quadrilateral mesh, vertex by vertex in the
/// mesh's order, counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// point addition or scaling: (n²·v + 4 Σ eⱼ + Σ fⱼ)/(n(n + 5)) inside,
/// (v₋ + 4v + v₊)/6 on the boundary, v at a corner of valence 2 (see the module docs).
///
/// # Errors
///
/// As [`catmull_clark_limit`].
///
/// # Complexity
///
/// Θ(H·D) time, Θ(V·D) space; exactly 2n + 5 point operations for an interior vertex of
/// valence n, 4 for a boundary vertex, none for a corner.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::cube;
/// use compgeo::mesh::catmull_clark_limit_with;
///
/// let mut counts = Counts::default();
/// let limit = catmull_clark_limit_with(&cube(), &mut counts)?;
/// // Vertex 0 = (−1, −1, −1) of valence 3: (9v + 4 Σ eⱼ + Σ fⱼ)/24, with every coordinate
/// // of Σ eⱼ equal to −1 and of Σ fⱼ equal to 1.
/// assert_eq!(limit[0].0, [-0.5; 3]);
/// assert_eq!(counts.arithmetic_operations, 8 * (2 * 3 + 5));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn catmull_clark_limit_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    c: &mut C,
) -> Result<Vec<Point<S, D>>> {
    let t = mesh.topology();
    if let Some(f) = (0..t.face_count()).find(|&f| t.face_size(f) != 4) {
        return Err(Error::InvalidParameter {
            name: "mesh",
            reason: format!(
                "limit positions need a quadrilateral mesh, but face {f} has {} corners \
                 (one round of Catmull–Clark makes every face a quadrilateral)",
                t.face_size(f)
            ),
        });
    }
    let p = mesh.positions();
    let corner = |h: usize| &p[t.corners()[h] as usize];
    let four = S::from_i64(4);
    let sixth = S::from_ratio(1, 6);
    let mut out = Vec::with_capacity(t.vertex_count());
    for (v, position) in p.iter().enumerate() {
        let first = t.outgoing_halfedge(v);
        if t.twins()[first] == NONE {
            let last = t.one_ring(v).last().unwrap_or(first);
            if last == first {
                out.push(position.clone()); // a corner of valence 2
            } else {
                let before = corner(t.prev(last));
                let after = corner(t.next(first));
                out.push((position.clone() * &four + before + after) * &sixth);
                for _ in 0..4 {
                    c.arithmetic_operation();
                }
            }
            continue;
        }
        let mut edges = Point::zero();
        let mut diagonals = Point::zero();
        let mut n = 0i64;
        for h in t.one_ring(v) {
            let next = t.next(h);
            edges += corner(next);
            diagonals += corner(t.next(next));
            n += 1;
            c.arithmetic_operation();
            c.arithmetic_operation();
        }
        let point = (position.clone() * S::from_i64(n * n) + &(edges * &four) + &diagonals)
            * S::from_ratio(1, n * (n + 5));
        for _ in 0..5 {
            c.arithmetic_operation();
        }
        out.push(point);
    }
    Ok(out)
}
