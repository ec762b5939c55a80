//! Doo–Sabin subdivision as the midpoint scheme M₂ = 𝒜𝓡 of [PPB, §16.1]: on polygon meshes
//! of any face sizes, with the corrected weights of [PPB, §16.4].
//!
//! The problem: a sequence of ever finer meshes converging to a smooth surface, the
//! biquadratic uniform B-spline surface wherever the mesh is a regular quadrilateral grid.
//! The idea [PPB, §16.1]: the refinement 𝓡 joins every corner of a face to the midpoints of
//! its two edges and to the face's centroid (an m-gon becomes m quadrilaterals), and the
//! averaging 𝒜 replaces a mesh by the mesh of its faces' centroids, joined across shared
//! edges (its dual). One round of 𝒜𝓡 puts one new point in each quadrilateral of 𝓡, so one
//! per corner of the coarse mesh: for corner i of an m-gon with corners v₀, …, v_{m−1} and
//! centroid c = (1/m)Σv_k, the centroid of the quadrilateral vᵢ, ½(vᵢ + vᵢ₊₁), c,
//! ½(vᵢ₋₁ + vᵢ) is
//!
//! pᵢ = ¼(2vᵢ + ½vᵢ₋₁ + ½vᵢ₊₁ + c) = (a·vᵢ + b·(vᵢ₋₁ + vᵢ₊₁) + (4/m)·Σ_{others} v_k)/16,
//!
//! with **a = 8 + 4/m and b = 2 + 4/m**. [PPB, §16.4, Obs. 3] prints b = 4 + 4/m, an
//! erratum (SCOPE.md §9, 000 l.5529): the weights of a row of the subdivision matrix must
//! sum to 16 (an affine combination), and a + 2b + (m − 3)·4/m = 12 + 4 = 16 only with
//! b = 2 + 4/m (with 4 + 4/m the row sums to 20). For m = 4 the weights are 9, 3, 1, 3
//! over 16, the biquadratic masks of [PPB, §15.2, Obs. 3]. [`doo_sabin_weights`] gives them;
//! the rounds compute pᵢ in the cheaper centroid form above.
//!
//! The new faces are the faces of 𝒜's dual, one per inner vertex of 𝓡's mesh: a
//! **face-face** for each coarse face (its corners' new points, same order), an
//! **edge-face** (a quadrilateral) for each inner coarse edge, and a **vertex-face** for each
//! inner coarse vertex (its corners' new points around it, counter-clockwise). So on a
//! closed mesh F′ = F + E + V, V′ = H (the coarse corners) and E′ = 2E + H.
//!
//! # Boundaries
//!
//! 𝒜𝓡 is applied as it stands: 𝒜 makes a face only around an inner vertex of 𝓡's mesh, so a
//! boundary edge gets no edge-face and a boundary vertex no vertex-face, and every round
//! moves the boundary inwards. This is the crate's convention for open B-spline subdivision
//! ([`lane_riesenfeld`](crate::spline::subdivision::lane_riesenfeld) keeps the control points
//! whose B-splines meet the domain): on an open regular grid of m × n vertices one round is
//! exactly the open biquadratic tensor Lane–Riesenfeld round
//! ([`ControlNet::lane_riesenfeld`](crate::surface::ControlNet::lane_riesenfeld)), whose
//! (2m − 2) × (2n − 2) points are the 4(m − 1)(n − 1) corners. In general
//! F′ = F + E_inner + V_inner and E′ = 2E_inner + H, and the Euler characteristic is kept.
//!
//! An inner vertex of valence 2 (two faces folded along two edges) would give a vertex-face
//! of two corners; its two edges are merged instead (the two edge-faces are joined along
//! one edge), so every face of the result has at least three corners.
//!
//! # Limit points
//!
//! The centroid of a face-face is the centroid c of its coarse face (Σpᵢ/m = ½c + ¼c + ¼c),
//! and face f's face-face is face f of the next mesh, so every face's centroid is a point of
//! the limit surface: the point its face-faces shrink to ([`doo_sabin_limit_points`]).
//!
//! # Complexity
//!
//! One round on a mesh of H corners: Θ(H·D) time and space; k rounds Θ(4ᵏ·H·D) (after the
//! first round every vertex has valence 4, so the corners grow by a factor of 4 per round).
//!
//! Invariants the tests check (exactly, on rationals): every new point is the centroid of its
//! quadrilateral of 𝓡 (an oracle building 𝓡 and 𝒜 from [PPB, §16.1]'s definitions), and the
//! weights form, whose rows sum to 1 with the erratum and to 5/4 without it; on a regular
//! quadrilateral grid, closed (a torus) or open, every round is biquadratic tensor
//! Lane–Riesenfeld subdivision; the counts above and the Euler characteristic for closed and
//! bounded meshes; the half-edge invariants of every result; face centroids are kept.

use super::polygon_mesh::PolygonMesh;
use super::topology::{edges_of_twins, MeshTopology, NONE};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::{limits, Error, Result};

/// Doo–Sabin subdivision, declared.
pub(crate) const DOO_SABIN: Declaration = Declaration {
    problem: "mesh-subdivision",
    name: "doo-sabin",
    function: "mesh::doo_sabin",
    file: "src/mesh/doo_sabin.rs",
    summary: "k rounds of the midpoint scheme M₂ = AR (Doo–Sabin) on faces of any size: a new point per corner, (a·vᵢ + b(vᵢ₋₁ + vᵢ₊₁) + 4/m·Σ others)/16 with a = 8 + 4/m, b = 2 + 4/m; face-, edge- and vertex-faces",
    time: "Θ(4ᵏ·H·D) for k rounds on H corners",
    space: "Θ(4ᵏ·H·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per stencil term: m per face for its centroid and 4 per corner, 5H per round",
    source: "[PPB, §16.1, §16.4 (b = 2 + 4/m, erratum)]",
    claims: &[
        on("quad-torus", Bound::Linear, Operation::ArithmeticOperations),
        on(
            "irregular-torus",
            Bound::Linear,
            Operation::ArithmeticOperations,
        ),
    ],
};

/// Doo–Sabin's limit points, declared.
pub(crate) const DOO_SABIN_LIMIT: Declaration = Declaration {
    problem: "mesh-subdivision",
    name: "doo-sabin-limit",
    function: "mesh::doo_sabin_limit_points",
    file: "src/mesh/doo_sabin.rs",
    summary: "the points of the Doo–Sabin limit surface that each face's face-faces shrink to: the face centroids",
    time: "Θ(H·D)",
    space: "Θ(F·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per corner: H",
    source: "[PPB, §16.1, §16.4]",
    claims: &[on(
        "irregular-torus",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The weights of Doo–Sabin's rule for corner 0 of an m-gon over its corners v₀, …, v_{m−1}:
/// (a, b, 4/m, …, 4/m, b)/16 with a = 8 + 4/m and b = 2 + 4/m (the erratum to [PPB, §16.4],
/// which prints b = 4 + 4/m); corner i's weights are these rotated by i. They sum to 1.
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"corners"` for m < 3;
/// [`Error::LimitExceeded`] beyond [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS).
///
/// # Complexity
///
/// Θ(m) time and space.
///
/// ```
/// use compgeo::mesh::doo_sabin_weights;
///
/// let w = doo_sabin_weights::<f64>(4)?;
/// assert_eq!(w, [9.0 / 16.0, 3.0 / 16.0, 1.0 / 16.0, 3.0 / 16.0]);
/// assert_eq!(doo_sabin_weights::<f64>(3)?.iter().sum::<f64>(), 1.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn doo_sabin_weights<S: Scalar>(m: usize) -> Result<Vec<S>> {
    if m < 3 {
        return Err(Error::InvalidParameter {
            name: "corners",
            reason: format!("a face has at least 3 corners, not {m}"),
        });
    }
    limits::MESH_CORNERS.check(m as u128)?;
    let sixteenth = S::from_ratio(1, 16);
    let others = S::from_ratio(4, m as i64) * &sixteenth;
    let a = (S::from_i64(8) + S::from_ratio(4, m as i64)) * &sixteenth;
    let b = (S::from_i64(2) + S::from_ratio(4, m as i64)) * &sixteenth;
    let mut w = vec![others; m];
    w[0] = a;
    w[1] = b.clone();
    w[m - 1] = b;
    Ok(w)
}

/// `rounds` rounds of Doo–Sabin subdivision (the midpoint scheme M₂ = 𝒜𝓡). See
/// [`doo_sabin_with`].
///
/// The child of a round has one vertex per coarse corner (half-edge h becomes vertex h);
/// its faces are the face-faces (child face f for coarse face f, its corners in order), then
/// the edge-faces of the inner edges in edge order, then the vertex-faces of the inner
/// vertices in vertex order.
///
/// # Errors
///
/// [`Error::LimitExceeded`] naming [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS)
/// if H·2^k passes it for H corners and k rounds (checked before the first round: a round
/// at least about doubles the corners of a mesh two of whose faces share an edge, and this
/// also bounds the rounds on a mesh whose faces share no edge, which a round does not
/// enlarge), or if a round would make more corners or vertices than the limits allow
/// (checked before that round builds anything); [`Error::Overflow`] if, with `f64`, a point
/// overflows.
///
/// # Complexity
///
/// Θ(4ᵏ·H·D) for k rounds on H corners in R^D; Θ(4ᵏ·H·D) space.
///
/// ```
/// use compgeo::gen::cube;
/// use compgeo::mesh::doo_sabin;
///
/// let cube = cube(); // V = 8, E = 12, F = 6
/// let once = doo_sabin(&cube, 1)?;
/// assert_eq!((once.vertex_count(), once.face_count()), (24, 6 + 12 + 8));
/// assert_eq!(once.euler_characteristic(), 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn doo_sabin<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
) -> Result<PolygonMesh<S, D>> {
    doo_sabin_with(mesh, rounds, &mut NoCount)
}

/// [`doo_sabin`], counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// stencil term.
///
/// Idea [PPB, §16.1]: each face's centroid c once, then each corner's point
/// ½vᵢ + ⅛(vᵢ₋₁ + vᵢ₊₁) + ¼c (the centroid of its quadrilateral of 𝓡); the child faces and
/// half-edges by index arithmetic from the coarse half-edges, one walk around each inner
/// vertex for its vertex-face.
///
/// # Errors
///
/// As [`doo_sabin`].
///
/// # Complexity
///
/// Θ(4ᵏ·H·D) for k rounds on H corners in R^D; Θ(4ᵏ·H·D) space.
///
/// # Counts
///
/// Per round: m per face of m corners for its centroid and 4 per corner, 5H in all.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::quad_torus;
/// use compgeo::mesh::doo_sabin_with;
///
/// let torus = quad_torus(4, 5)?; // 20 vertices, 40 edges, 20 faces, 80 corners
/// let mut c = Counts::default();
/// let once = doo_sabin_with(&torus, 1, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 5 * 80);
/// assert_eq!((once.vertex_count(), once.face_count()), (80, 20 + 40 + 20));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn doo_sabin_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    rounds: usize,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    let corners = mesh.topology().halfedge_count() as u128;
    limits::MESH_CORNERS.check(corners << rounds.min(64))?;
    let mut current = mesh.clone();
    for _ in 0..rounds {
        current = doo_sabin_round(&current, counter)?;
    }
    Ok(current)
}

/// The limit points of the face centroids: point f is the centroid of face f, the point of
/// the Doo–Sabin limit surface that face f's face-faces shrink to. See
/// [`doo_sabin_limit_points_with`].
///
/// # Errors
///
/// [`Error::Overflow`] if, with `f64`, a centroid overflows.
///
/// # Complexity
///
/// Θ(H·D) time, Θ(F·D) space.
///
/// ```
/// use compgeo::gen::cube;
/// use compgeo::mesh::{doo_sabin, doo_sabin_limit_points};
///
/// let cube = cube();
/// let limits = doo_sabin_limit_points(&cube)?;
/// // Face f of every round is the face-face of face f, with the same centroid.
/// let twice = doo_sabin(&cube, 2)?;
/// assert_eq!(doo_sabin_limit_points(&twice)?[..6], limits[..]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn doo_sabin_limit_points<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
) -> Result<Vec<Point<S, D>>> {
    doo_sabin_limit_points_with(mesh, &mut NoCount)
}

/// [`doo_sabin_limit_points`], counting one
/// [`arithmetic_operation`](Counter::arithmetic_operation) per corner.
///
/// Idea [PPB, §16.1, §16.4]: the centroid of a face-face is that of its coarse face, so the
/// centroids stay fixed as the face-faces shrink.
///
/// # Errors
///
/// As [`doo_sabin_limit_points`].
///
/// # Complexity
///
/// Θ(H·D) time, Θ(F·D) space.
///
/// # Counts
///
/// H, one per corner.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::cube;
/// use compgeo::mesh::doo_sabin_limit_points_with;
///
/// let mut c = Counts::default();
/// doo_sabin_limit_points_with(&cube(), &mut c)?;
/// assert_eq!(c.arithmetic_operations, 24);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn doo_sabin_limit_points_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    counter: &mut C,
) -> Result<Vec<Point<S, D>>> {
    finite(centroids(mesh, counter))
}

/// The centroid of every face.
fn centroids<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let t = mesh.topology();
    let pos = mesh.positions();
    let corners = t.corners();
    t.face_offsets()
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0] as usize, w[1] as usize);
            let mut sum = Point::zero();
            for &v in &corners[a..b] {
                counter.arithmetic_operation();
                sum += &pos[v as usize];
            }
            sum / S::from_i64((b - a) as i64)
        })
        .collect()
}

/// One round: the corner points, then the dual connectivity.
fn doo_sabin_round<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    let t = mesh.topology();
    let child = dual_split(t)?;
    let pos = mesh.positions();
    let corners = t.corners();
    let offsets = t.face_offsets();
    let centres = centroids(mesh, counter);
    let (half, eighth, quarter) = (
        S::from_ratio(1, 2),
        S::from_ratio(1, 8),
        S::from_ratio(1, 4),
    );
    let mut points = Vec::with_capacity(corners.len());
    for (f, c) in centres.iter().enumerate() {
        let (a, b) = (offsets[f] as usize, offsets[f + 1] as usize);
        let at = |h: usize| &pos[corners[h] as usize];
        for h in a..b {
            let before = if h == a { b - 1 } else { h - 1 };
            let after = if h + 1 == b { a } else { h + 1 };
            for _ in 0..4 {
                counter.arithmetic_operation();
            }
            let sides = (at(before).clone() + at(after)) * &eighth;
            points.push(at(h).clone() * &half + &sides + &(c.clone() * &quarter));
        }
    }
    let points = finite(points)?;
    Ok(PolygonMesh::from_parts_unchecked(points, child))
}

/// The child connectivity of one round: vertex h for corner h; the face-faces (their
/// half-edges are the coarse ones, same numbers), the edge-faces [next(s), s, next(t), t]
/// of the inner edges with stored half-edge s and twin t, the vertex-faces of the inner
/// vertices (their corners' outgoing half-edges counter-clockwise); an inner vertex of
/// valence 2 gets no face and its two edge-faces are joined.
///
/// # Errors
///
/// [`Error::LimitExceeded`] if the child would pass the mesh limits (checked before
/// anything is allocated).
fn dual_split(t: &MeshTopology) -> Result<MeshTopology> {
    let (h_count, f_count) = (t.halfedge_count(), t.face_count());
    let twins = t.twins();
    let edge_halfedges = t.edge_halfedges();
    // Inner edges: the first half-edge of each edge-face.
    let mut edge_face = vec![NONE; t.edge_count()];
    let mut next_half = h_count as u32;
    for (e, &s) in edge_halfedges.iter().enumerate() {
        if twins[s as usize] != NONE {
            edge_face[e] = next_half;
            next_half += 4;
        }
    }
    let edge_faces_end = next_half as usize;
    let mut inner_half_edges = 0usize;
    for v in 0..t.vertex_count() {
        if !t.is_boundary_vertex(v) {
            let n = t.one_ring(v).count();
            if n >= 3 {
                inner_half_edges += n;
            }
        }
    }
    let total = edge_faces_end + inner_half_edges;
    limits::MESH_VERTICES.check(h_count as u128)?;
    limits::MESH_CORNERS.check(total as u128)?;
    let mut face_offsets: Vec<u32> =
        Vec::with_capacity(f_count + t.edge_count() + t.vertex_count() + 1);
    face_offsets.extend_from_slice(t.face_offsets());
    let mut corners = Vec::with_capacity(total);
    corners.extend((0..h_count).map(|h| h as u32));
    let mut child_twins = vec![NONE; total];
    let mut faces = Vec::with_capacity(total);
    faces.extend_from_slice(t.halfedge_faces());
    // Edge-faces.
    for (e, &s) in edge_halfedges.iter().enumerate() {
        let base = edge_face[e];
        if base == NONE {
            continue;
        }
        let s = s as usize;
        let tw = twins[s] as usize;
        let face = (face_offsets.len() - 1) as u32;
        corners.extend([t.next(s), s, t.next(tw), tw].map(|h| h as u32));
        faces.extend([face; 4]);
        face_offsets.push(base + 4);
        // next(s) → s and next(t) → t run against the face-faces' s → next(s), t → next(t).
        child_twins[base as usize] = s as u32;
        child_twins[s] = base;
        child_twins[base as usize + 2] = tw as u32;
        child_twins[tw] = base + 2;
    }
    // The edge-face half-edge between two corners of vertex v: from h_{k+1} to h_k across
    // the coarse edge of prev(h_k), which is +3 of its edge-face if prev(h_k) is the edge's
    // stored half-edge (h_k = next(s), h_{k+1} = t) and +1 otherwise (h_{k+1} = s,
    // h_k = next(t)).
    let across = |h: usize| {
        let p = t.prev(h);
        let e = t.edge(p);
        edge_face[e] as usize
            + if edge_halfedges[e] as usize == p {
                3
            } else {
                1
            }
    };
    // Vertex-faces.
    let mut ring = Vec::new();
    for v in 0..t.vertex_count() {
        if t.is_boundary_vertex(v) {
            continue;
        }
        ring.clear();
        ring.extend(t.one_ring(v));
        if ring.len() == 2 {
            // No face of two corners: the edge-faces on either side become neighbours.
            let (x, y) = (across(ring[0]), across(ring[1]));
            child_twins[x] = y as u32;
            child_twins[y] = x as u32;
            continue;
        }
        let base = corners.len();
        let face = (face_offsets.len() - 1) as u32;
        let n = ring.len();
        for (k, &h) in ring.iter().enumerate() {
            corners.push(h as u32);
            faces.push(face);
            let x = across(h);
            child_twins[base + k] = x as u32;
            child_twins[x] = (base + k) as u32;
        }
        face_offsets.push((base + n) as u32);
    }
    debug_assert_eq!(corners.len(), total);
    // Outgoing: the face-face half-edge h, unless h's edge is inner and its vertex on the
    // boundary, where the boundary half-edge leaving corner h is its edge-face's.
    let outgoing = (0..h_count)
        .map(|h| {
            let e = t.edge(h);
            if edge_face[e] != NONE && t.is_boundary_vertex(t.origin(h)) {
                edge_face[e]
                    + if edge_halfedges[e] as usize == h {
                        1
                    } else {
                        3
                    }
            } else {
                h as u32
            }
        })
        .collect();
    let (halfedge_edges, child_edge_halfedges) = edges_of_twins(&child_twins);
    Ok(MeshTopology::from_parts_unchecked(
        h_count,
        face_offsets,
        corners,
        child_twins,
        faces,
        halfedge_edges,
        child_edge_halfedges,
        outgoing,
    ))
}

/// `points` if every coordinate is finite, else [`Error::Overflow`].
fn finite<S: Scalar, const D: usize>(points: Vec<Point<S, D>>) -> Result<Vec<Point<S, D>>> {
    if S::EXACT || points.iter().all(Point::is_finite) {
        Ok(points)
    } else {
        Err(Error::Overflow {
            what: "Doo–Sabin subdivision",
        })
    }
}
