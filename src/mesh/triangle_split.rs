//! The connectivity of one round of triangle refinement (the linear refinement 𝓡 of
//! [PPB, §15.7, Obs. 9], the topology of Loop's scheme): every triangle becomes four, the
//! three at its corners and the one joining its edges' midpoints. Built from the coarse
//! half-edge arrays by index arithmetic alone: no search, no hashing, no allocation per face.
//!
//! Numbering (V, E, F the coarse counts, H = 3F the coarse half-edges; coarse half-edge
//! h = 3f + c is corner c of triangle f):
//!
//! - child vertices: `v` for coarse vertex `v`, `V + e` for the point on edge `e`;
//! - child triangle `4f + c` is the corner triangle of coarse corner h = 3f + c:
//!   [v, edge point of h, edge point of prev(h)]; child triangle `4f + 3` is the middle one,
//!   [edge point of 3f, of 3f + 1, of 3f + 2];
//! - child triangle g has the half-edges 3g, 3g + 1, 3g + 2 (the child is a triangle mesh
//!   with face offsets 3g). Coarse half-edge h splits into its first half 4h − c (in the
//!   corner triangle of h) and its second half 4·next(h) − c′ + 2 (in the corner triangle of
//!   next(h), c′ its corner), and the first half of h pairs with the second half of twin(h);
//!   the inner half-edge 4h − c + 1 of a corner triangle pairs with the middle triangle's;
//! - child edges: `2e` and `2e + 1` are the halves of coarse edge `e` at the origin and at
//!   the end of its stored half-edge, `2E + h` is the inner edge of the corner triangle of h
//!   (the numbering of the Catmull–Clark split's child edges, so the two schemes
//!   share their conventions).
//!
//! So V′ = V + E, E′ = 2E + H, F′ = 4F, H′ = 4H, and V′ − E′ + F′ = V − E + F (H = 3F).
//!
//! # Complexity
//!
//! Θ(H) time and space.

use super::quad_split::stored;
use super::topology::{MeshTopology, NONE};

/// The first half of coarse half-edge `h` (at its origin), in the corner triangle of h.
#[inline(always)]
fn first_half(h: usize) -> u32 {
    (4 * h - h % 3) as u32
}

/// The next half-edge of `h` in its triangle.
#[inline(always)]
fn next(h: usize) -> usize {
    if h % 3 == 2 {
        h - 2
    } else {
        h + 1
    }
}

/// The previous half-edge of `h` in its triangle.
#[inline(always)]
fn prev(h: usize) -> usize {
    if h % 3 == 0 {
        h + 2
    } else {
        h - 1
    }
}

/// The second half of coarse half-edge `h` (at its end), in the corner triangle of next(h).
#[inline(always)]
fn second_half(h: usize) -> u32 {
    first_half(next(h)) + 2
}

/// The child connectivity of one round of a triangle mesh (see the module docs for the
/// numbering). `t` must be a triangle mesh.
pub(crate) fn triangle_split(t: &MeshTopology) -> MeshTopology {
    debug_assert!(t.is_triangle_mesh());
    let (v_count, e_count, f_count) = (t.vertex_count(), t.edge_count(), t.face_count());
    let h_count = 3 * f_count;
    let ep = v_count as u32; // edge points start here
    let inner = 2 * e_count as u32; // the edges inside coarse triangles start here
    let (coarse_corners, twins, edges) = (t.corners(), t.twins(), t.halfedge_edges());

    let mut corners = vec![0u32; 4 * h_count];
    let mut child_twins = vec![NONE; 4 * h_count];
    let mut child_edges = vec![0u32; 4 * h_count];
    let mut faces = vec![0u32; 4 * h_count];
    for f in 0..f_count {
        let middle = 3 * (4 * f + 3);
        for c in 0..3 {
            let h = 3 * f + c;
            let p = prev(h);
            let k = first_half(h) as usize; // = 3(4f + c)
            let (e, e_prev) = (edges[h], edges[p]);
            corners[k] = coarse_corners[h];
            corners[k + 1] = ep + e;
            corners[k + 2] = ep + e_prev;
            corners[middle + c] = ep + e;
            let (th, tp) = (twins[h], twins[p]);
            if th != NONE {
                child_twins[k] = second_half(th as usize);
            }
            // The inner half-edge, from the point on h to the point on p, pairs with the
            // middle triangle's half-edge from the point on p (corner c − 1) to the one on h.
            let across = (middle + (c + 2) % 3) as u32;
            child_twins[k + 1] = across;
            child_twins[across as usize] = k as u32 + 1;
            if tp != NONE {
                child_twins[k + 2] = first_half(tp as usize);
            }
            child_edges[k] = 2 * e + u32::from(!stored(h, th));
            child_edges[k + 1] = inner + h as u32;
            child_edges[across as usize] = inner + h as u32;
            child_edges[k + 2] = 2 * e_prev + u32::from(stored(p, tp));
            faces[k..k + 3].fill((4 * f + c) as u32);
        }
        faces[middle..middle + 3].fill((4 * f + 3) as u32);
    }
    let mut edge_halfedges = vec![0u32; 2 * e_count + h_count];
    for (e, &s) in t.edge_halfedges().iter().enumerate() {
        let s = s as usize;
        let ts = twins[s];
        // Boundary: the halves of the boundary half-edge; inside: the smaller of each pair.
        let (mut first, mut second) = (first_half(s), second_half(s));
        if ts != NONE {
            first = first.min(second_half(ts as usize));
            second = second.min(first_half(ts as usize));
        }
        edge_halfedges[2 * e] = first;
        edge_halfedges[2 * e + 1] = second;
    }
    for h in 0..h_count {
        // The corner triangle's inner half-edge comes before the middle triangle's.
        edge_halfedges[2 * e_count + h] = first_half(h) + 1;
    }
    let mut outgoing = Vec::with_capacity(v_count + e_count);
    outgoing.extend(t.outgoing().iter().map(|&h| first_half(h as usize)));
    // From an edge point, the second half of the stored half-edge: the boundary one on a
    // boundary edge.
    outgoing.extend(t.edge_halfedges().iter().map(|&s| second_half(s as usize)));
    // Each coarse boundary half-edge h becomes its two halves, in the same loop.
    let mut boundary = Vec::with_capacity(2 * t.boundary_halfedges.len());
    for &h in &t.boundary_halfedges {
        boundary.push(first_half(h as usize));
        boundary.push(second_half(h as usize));
    }
    let boundary_offsets = t.boundary_offsets.iter().map(|&o| 2 * o).collect();
    let face_offsets = (0..=4 * f_count as u32).map(|g| 3 * g).collect();
    MeshTopology::from_parts_with_boundary_unchecked(
        v_count + e_count,
        face_offsets,
        corners,
        child_twins,
        faces,
        child_edges,
        edge_halfedges,
        outgoing,
        boundary_offsets,
        boundary,
    )
}

/// The coarse vertices of half-edge `h` of a triangle mesh: its origin, its end and the
/// vertex opposite it in its triangle.
#[inline(always)]
pub(crate) fn triangle_corners(corners: &[u32], h: usize) -> [usize; 3] {
    [
        corners[h] as usize,
        corners[next(h)] as usize,
        corners[prev(h)] as usize,
    ]
}
