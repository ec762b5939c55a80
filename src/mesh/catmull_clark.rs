//! Catmull–Clark subdivision: k rounds on a polygon mesh of any face sizes, with crease
//! rules on the boundary.
//!
//! The problem: a sequence of ever finer quadrilateral meshes that converges to a smooth
//! surface, the bicubic uniform B-spline surface wherever the mesh is a regular grid. The
//! idea [PPB, §16.1]: split every face of n corners into n quadrilaterals joining its centre,
//! its edges' midpoints and its corners, and place the new points by fixed affine
//! combinations of the old ones (the rules, with the boundary's crease rules, are on
//! [`catmull_clark_with`]).
//!
//! # The midpoint scheme M₃
//!
//! [PPB, §16.1] describes Catmull–Clark as the midpoint scheme M₃ = A²R: refine with R, then
//! twice replace the mesh by its mesh of face centroids (A). On a regular quadrilateral grid
//! both are bicubic B-spline subdivision, the same rules. Elsewhere they differ: A²R moves
//! a vertex of valence n to v/2 + (Σ wⱼ + Σ fⱼ)/(4n), which equals the rule above only for
//! n = 4, and an edge next to a face that is not a quadrilateral to
//! (10v + 10w + 4f₁ + 4f₂ + u + x + y + z)/32 (u, x, y, z the other ends of the four edges
//! that continue the edge vw in its two faces), which equals (v + w + f₁ + f₂)/4 when both
//! faces are quadrilaterals. [`midpoint_cubic`](super::midpoint_cubic) runs M₃ with the same
//! boundary rules; the rules here are Catmull and Clark's, whose limit surface has the
//! closed-form limit positions of [`catmull_clark_limit`](super::catmull_clark_limit).
//!
//! # Complexity
//!
//! Θ(4ᵏ·H·D) time and space for k rounds on a mesh of H corners (the sum of the face sizes)
//! in R^D: round j works on 4^{j−1}·H corners and builds 4ʲ·H, and the rounds sum to less
//! than 4/3 of the last. The connectivity of each round is built from the previous one by
//! index arithmetic (see `quad_split.rs`), the positions in three passes over flat arrays.
//!
//! Invariants the tests check: on the interior of a regular grid, one round equals bicubic
//! uniform B-spline subdivision of the rows and then the columns (exactly, on rationals); the
//! boundary is the cubic B-spline subdivision of the boundary polygon; the counts V, E, F
//! and the Euler characteristic after each round; the limit positions are unchanged by a
//! round; the operation counts below.

use super::polygon_mesh::PolygonMesh;
use super::quad_split::{quad_split, General, Layout, Quads};
use super::topology::{MeshTopology, NONE};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::{limits, Result};

/// Catmull–Clark subdivision, declared.
pub(crate) const CATMULL_CLARK: Declaration = Declaration {
    problem: "mesh-subdivision",
    name: "catmull-clark",
    function: "mesh::catmull_clark",
    file: "src/mesh/catmull_clark.rs",
    summary: "k rounds of Catmull–Clark subdivision on faces of any size, crease rules on the boundary",
    time: "Θ(4ᵏ·H·D) for k rounds on H corners",
    space: "Θ(4ᵏ·H·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "point additions and scalings: exactly 3H + 3Vᵢ + 4V_b + 4Eᵢ + 2E_b per round (interior and boundary vertices and edges; corners cost nothing)",
    source: "[PPB, §16.1]",
    claims: &[
        on("quad-torus", Bound::Linear, Operation::ArithmeticOperations),
        on(
            "irregular-torus",
            Bound::Linear,
            Operation::ArithmeticOperations,
        ),
    ],
};

/// `rounds` rounds of Catmull–Clark subdivision. See [`catmull_clark_with`].
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
/// use compgeo::gen::cube;
/// use compgeo::mesh::catmull_clark;
///
/// let fine = catmull_clark(&cube(), 2)?;
/// assert_eq!(fine.face_count(), 6 * 16);
/// assert_eq!(fine.euler_characteristic(), 2);
/// assert!(fine.topology().is_quad_mesh());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn catmull_clark<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
) -> Result<PolygonMesh<S, D>> {
    catmull_clark_with(mesh, rounds, &mut NoCount)
}

/// `rounds` rounds of Catmull–Clark subdivision of `mesh` (faces of any size, boundaries
/// by crease rules), counting one [`arithmetic_operation`](Counter::arithmetic_operation)
/// per point addition or scaling.
///
/// The rules [PPB, §16.1]:
///
/// - face point: the centroid of the face's corners;
/// - edge point: (v + w + f₁ + f₂)/4 for an edge vw between the faces with face points
///   f₁, f₂;
/// - vertex point of an interior vertex v of valence n: (Q + 2R + (n − 3)v)/n, with Q the
///   average of the face points around v and R the average of the midpoints of its edges;
///   equivalently ((n − 2)/n)·v + (Σ wⱼ + Σ fⱼ)/n² over its neighbours wⱼ and face points
///   fⱼ.
///
/// Boundary (crease) rules, so that the boundary polygon is refined as a cubic B-spline
/// curve on its own: a boundary edge point is the edge's midpoint; a boundary vertex goes to
/// (v₋ + 6v + v₊)/8 with v₋, v₊ its boundary neighbours; a boundary vertex of valence 2 (a
/// corner: one face) stays where it is, so the corners of a grid are interpolated and its
/// boundary curves end there.
///
/// These are Catmull and Clark's rules; the midpoint scheme M₃ = A²R of [PPB, §16.1] agrees
/// with them on regular grids and differs at extraordinary vertices and next to faces that
/// are not quadrilaterals (see [`midpoint_cubic_with`](super::midpoint_cubic_with)).
///
/// Child vertex numbering of one round (V, E, F the coarse counts): vertex `v` is the vertex
/// point of `v`, `V + e` the edge point of edge `e`, `V + E + f` the face point of face `f`;
/// child face `h` is the quadrilateral at coarse corner `h`. So V' = V + E + F,
/// E' = 2E + H, F' = H for H corners, and from the second round on F' = 4F.
///
/// # Errors
///
/// As [`catmull_clark`].
///
/// # Complexity
///
/// Θ(4ᵏ·H·D) time and space for k rounds on H corners in R^D; per round exactly
/// 3H + 3Vᵢ + 4V_b + 4Eᵢ + 2E_b point operations (Vᵢ, Eᵢ interior vertices and edges, V_b
/// boundary vertices of valence at least 3, E_b boundary edges, all of the coarse mesh).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::quad_torus;
/// use compgeo::mesh::catmull_clark_with;
///
/// let torus = quad_torus(10, 10)?;
/// let mut counts = Counts::default();
/// let fine = catmull_clark_with(&torus, 1, &mut counts)?;
/// assert_eq!((fine.vertex_count(), fine.face_count()), (100 + 200 + 100, 400));
/// // Closed: 3H + 3V + 4E with H = 400, V = 100, E = 200.
/// assert_eq!(counts.arithmetic_operations, 1200 + 300 + 800);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn catmull_clark_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    subdivide_rounds(mesh, rounds, Rules::CatmullClark, counter)
}

/// Which vertex and edge rules a round of quad refinement applies: Catmull and Clark's, or
/// those of the midpoint scheme M₃ = A²R (the face rule and the boundary rules are shared).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Rules {
    CatmullClark,
    Midpoint,
}

/// `rounds` rounds with `rules`, the limit checked before the first.
pub(crate) fn subdivide_rounds<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
    rules: Rules,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    check_rounds(mesh.topology(), rounds)?;
    if rounds == 0 {
        return Ok(mesh.clone());
    }
    let mut current = one_round(mesh, rules, counter);
    for _ in 1..rounds {
        current = one_round(&current, rules, counter);
    }
    Ok(current)
}

/// One round: the child positions, then the child connectivity.
fn one_round<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    rules: Rules,
    counter: &mut C,
) -> PolygonMesh<S, D> {
    let (positions, topology) = (mesh.positions(), mesh.topology());
    let child_positions = if topology.is_quad_mesh() {
        round(positions, topology, Quads, rules, counter)
    } else {
        round(positions, topology, General(topology), rules, counter)
    };
    PolygonMesh::from_parts_unchecked(child_positions, quad_split(topology))
}

/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) unless H·4ᵏ ≤
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS).
pub(crate) fn check_rounds(t: &MeshTopology, rounds: usize) -> Result<()> {
    let mut corners = t.halfedge_count() as u128;
    for _ in 0..rounds {
        corners *= 4;
        if corners > limits::MAX_MESH_CORNERS as u128 {
            break;
        }
    }
    limits::MESH_CORNERS.check(corners)?;
    Ok(())
}

/// Counts `n` point operations.
#[inline(always)]
fn count<C: Counter>(c: &mut C, n: usize) {
    for _ in 0..n {
        c.arithmetic_operation();
    }
}

/// The positions of one round: vertex points, then edge points, then face points.
fn round<S: Scalar, const D: usize, L: Layout, C: Counter>(
    positions: &[Point<S, D>],
    t: &MeshTopology,
    layout: L,
    rules: Rules,
    c: &mut C,
) -> Vec<Point<S, D>> {
    let (v_count, e_count, f_count) = (t.vertex_count(), t.edge_count(), t.face_count());
    let corners = t.corners();
    let twins = t.twins();
    let offsets = t.face_offsets();
    let reciprocal = Reciprocals::<S>::new(64);
    let weights = VertexWeights::<S>::new(rules, 32);

    // Face points, and for every vertex the sum of its neighbours and of its face points
    // (one pass over the corners: each half-edge leaving v ends at a neighbour of v and
    // lies in a face of v).
    let mut face_points: Vec<Point<S, D>> = Vec::with_capacity(f_count);
    let mut sums: Vec<Point<S, D>> = vec![Point::zero(); v_count];
    let mut valence = vec![0u32; v_count];
    for f in 0..f_count {
        let (a, b) = (offsets[f] as usize, offsets[f + 1] as usize);
        let mut centre = positions[corners[a] as usize].clone();
        for &v in &corners[a + 1..b] {
            centre += &positions[v as usize];
        }
        let centre = centre * reciprocal.get(b - a);
        count(c, b - a);
        for h in a..b {
            let v = corners[h] as usize;
            let w = corners[layout.next(h)] as usize;
            sums[v] += &positions[w];
            sums[v] += &centre;
            valence[v] += 1;
        }
        count(c, 2 * (b - a));
        face_points.push(centre);
    }

    let mut out: Vec<Point<S, D>> = Vec::with_capacity(v_count + e_count + f_count);
    // Vertex points of interior vertices; boundary vertices are placed below.
    for (v, sum) in sums.into_iter().enumerate() {
        let p = &positions[v];
        if twins[t.outgoing()[v] as usize] == NONE {
            out.push(p.clone());
            continue;
        }
        let n = valence[v] as usize;
        let (own, others) = weights.get(n);
        let point = p.clone() * own + &(sum * others);
        count(c, 3);
        out.push(point);
    }
    let six = S::from_i64(6);
    for i in 0..t.boundary_loop_count() {
        let lp = t.boundary_loop(i);
        let mut before = lp[lp.len() - 1] as usize;
        for &h in lp {
            let h = h as usize;
            let v = corners[h] as usize;
            if valence[v] > 1 {
                let a = &positions[corners[before] as usize];
                let b = &positions[corners[layout.next(h)] as usize];
                out[v] = (positions[v].clone() * &six + a + b) * reciprocal.get(8);
                count(c, 4);
            }
            before = h;
        }
    }

    // Edge points.
    let quarter = reciprocal.get(4);
    let half = reciprocal.get(2);
    let (ten, four, thirty_second) = (S::from_i64(10), S::from_i64(4), reciprocal.get(32));
    for &h in t.edge_halfedges() {
        let h = h as usize;
        let tw = twins[h];
        let v = &positions[corners[h] as usize];
        let w = &positions[corners[layout.next(h)] as usize];
        if tw == NONE {
            out.push((v.clone() + w) * &half);
            count(c, 2);
            continue;
        }
        let tw = tw as usize;
        let f1 = &face_points[layout.face(h)];
        let f2 = &face_points[layout.face(tw)];
        let point = match rules {
            Rules::CatmullClark => {
                count(c, 4);
                (v.clone() + w + f1 + f2) * &quarter
            }
            Rules::Midpoint => {
                // The other ends of the edges continuing vw in both faces.
                let far = |g: usize| &positions[corners[layout.next(layout.next(g))] as usize];
                let near = |g: usize| &positions[corners[layout.prev(g)] as usize];
                count(c, 10);
                ((v.clone() + w) * &ten
                    + &((f1.clone() + f2) * &four)
                    + near(h)
                    + far(h)
                    + near(tw)
                    + far(tw))
                    * &thirty_second
            }
        };
        out.push(point);
    }
    out.extend(face_points);
    out
}

/// The two weights of an interior vertex point of valence n, a·v + b·(Σ wⱼ + Σ fⱼ):
/// ((n − 2)/n, 1/n²) for Catmull–Clark, (1/2, 1/(4n)) for M₃; a table for small n.
struct VertexWeights<S> {
    rules: Rules,
    table: Vec<(S, S)>,
}

impl<S: Scalar> VertexWeights<S> {
    fn new(rules: Rules, size: usize) -> Self {
        let mut table = vec![(S::zero(), S::zero())];
        table.extend((1..size).map(|n| Self::compute(rules, n)));
        VertexWeights { rules, table }
    }

    fn compute(rules: Rules, n: usize) -> (S, S) {
        let n = n as i64;
        match rules {
            Rules::CatmullClark => (S::from_ratio(n - 2, n), S::from_ratio(1, n * n)),
            Rules::Midpoint => (S::from_ratio(1, 2), S::from_ratio(1, 4 * n)),
        }
    }

    #[inline]
    fn get(&self, n: usize) -> (S, S) {
        match self.table.get(n) {
            Some(w) => w.clone(),
            None => Self::compute(self.rules, n),
        }
    }
}

/// 1/n for small n, computed once per round (exact for rationals, and one division saved
/// per use in `f64`).
struct Reciprocals<S> {
    table: Vec<S>,
}

impl<S: Scalar> Reciprocals<S> {
    fn new(size: usize) -> Self {
        let mut table = vec![S::zero()];
        table.extend((1..size).map(|n| S::from_ratio(1, n as i64)));
        Reciprocals { table }
    }

    /// 1/n.
    #[inline]
    fn get(&self, n: usize) -> S {
        match self.table.get(n) {
            Some(r) => r.clone(),
            None => S::from_ratio(1, n as i64),
        }
    }
}
