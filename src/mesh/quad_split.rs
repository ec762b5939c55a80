//! The connectivity of one round of Catmull–Clark-type refinement (the refinement operator R
//! of [PPB, §16.1]): every face of n corners becomes n quadrilaterals joining each corner to
//! the midpoints of its two edges and the face's centre. Built from the coarse half-edge
//! arrays by index arithmetic alone: no search, no hashing, no allocation per face.
//!
//! Numbering (V, E, F, H the coarse counts):
//!
//! - child vertices: `v` for the vertex point of coarse vertex `v`, `V + e` for the edge
//!   point of edge `e`, `V + E + f` for the face point of face `f`;
//! - child face `h` is the quadrilateral of coarse corner `h` (half-edge `h` from `v`, `p`
//!   the previous half-edge of its face): [v, edge point of h, face point, edge point of p];
//! - its half-edges are `4h, 4h + 1, 4h + 2, 4h + 3`, so the child mesh is a quad mesh with
//!   face offsets 4f, and its twins follow from the coarse twins: 4h pairs with
//!   4·next(twin(h)) + 3, 4h + 1 with 4·next(h) + 2;
//! - child edges: `2e` and `2e + 1` are the halves of coarse edge `e` at the origin and at
//!   the end of its stored half-edge, `2E + h` joins the edge point of h to the face point.
//!
//! So V' = V + E + F, E' = 2E + H, F' = H, H' = 4H, and V' − E' + F' = V − E + F.
//!
//! # Complexity
//!
//! Θ(H) time and space.

use super::topology::{MeshTopology, NONE};

/// The child connectivity of one round (see the module docs for the numbering).
pub(crate) fn quad_split(t: &MeshTopology) -> MeshTopology {
    if t.is_quad_mesh() {
        split_with(t, Quads)
    } else {
        split_with(t, General(t))
    }
}

/// How to step around a coarse face: by bit arithmetic on a quad mesh, by the face offsets
/// otherwise. The schemes are written once over it and compiled for both.
pub(crate) trait Layout: Copy {
    /// The next half-edge of `h` in its face.
    fn next(self, h: usize) -> usize;
    /// The previous half-edge of `h` in its face.
    fn prev(self, h: usize) -> usize;
    /// The face of `h`.
    fn face(self, h: usize) -> usize;
}

/// Every face a quadrilateral: face f is half-edges 4f..4f + 4.
#[derive(Clone, Copy)]
pub(crate) struct Quads;

impl Layout for Quads {
    #[inline(always)]
    fn next(self, h: usize) -> usize {
        (h & !3) | ((h + 1) & 3)
    }
    #[inline(always)]
    fn prev(self, h: usize) -> usize {
        (h & !3) | (h.wrapping_sub(1) & 3)
    }
    #[inline(always)]
    fn face(self, h: usize) -> usize {
        h >> 2
    }
}

/// Faces of any size, through the topology's offsets.
#[derive(Clone, Copy)]
pub(crate) struct General<'a>(pub(crate) &'a MeshTopology);

impl Layout for General<'_> {
    #[inline(always)]
    fn next(self, h: usize) -> usize {
        self.0.next(h)
    }
    #[inline(always)]
    fn prev(self, h: usize) -> usize {
        self.0.prev(h)
    }
    #[inline(always)]
    fn face(self, h: usize) -> usize {
        self.0.face(h)
    }
}

fn split_with<L: Layout>(t: &MeshTopology, layout: L) -> MeshTopology {
    let (v_count, e_count, f_count) = (t.vertex_count(), t.edge_count(), t.face_count());
    let h_count = t.halfedge_count();
    let ep = v_count as u32; // edge points start here
    let fp = (v_count + e_count) as u32; // face points start here
    let interior = 2 * e_count as u32; // the edges inside coarse faces start here
    let twins = t.twins();
    let edges = t.halfedge_edges();
    let offsets = t.face_offsets();

    let mut corners = vec![0u32; 4 * h_count];
    let mut child_twins = vec![NONE; 4 * h_count];
    let mut child_edges = vec![0u32; 4 * h_count];
    let mut faces = vec![0u32; 4 * h_count];
    for f in 0..f_count {
        let (a, b) = (offsets[f] as usize, offsets[f + 1] as usize);
        let mut p = b - 1;
        for h in a..b {
            let next = if h + 1 == b { a } else { h + 1 };
            let k = 4 * h;
            let (e, ep_prev) = (edges[h], edges[p]);
            corners[k] = t.corners()[h];
            corners[k + 1] = ep + e;
            corners[k + 2] = fp + f as u32;
            corners[k + 3] = ep + ep_prev;
            let th = twins[h];
            if th != NONE {
                child_twins[k] = 4 * layout.next(th as usize) as u32 + 3;
            }
            child_twins[k + 1] = 4 * next as u32 + 2;
            child_twins[k + 2] = 4 * p as u32 + 1;
            let tp = twins[p];
            if tp != NONE {
                child_twins[k + 3] = 4 * tp;
            }
            // The half of e at the origin of h: 2e if h is e's stored half-edge.
            child_edges[k] = 2 * e + u32::from(!stored(h, th));
            child_edges[k + 1] = interior + h as u32;
            child_edges[k + 2] = interior + p as u32;
            child_edges[k + 3] = 2 * ep_prev + u32::from(stored(p, tp));
            faces[k..k + 4].fill(h as u32);
            p = h;
        }
    }
    let mut edge_halfedges = vec![0u32; 2 * e_count + h_count];
    for (e, &h) in t.edge_halfedges().iter().enumerate() {
        let h = h as usize;
        edge_halfedges[2 * e] = 4 * h as u32;
        edge_halfedges[2 * e + 1] = 4 * layout.next(h) as u32 + 3;
    }
    for h in 0..h_count {
        let across = child_twins[4 * h + 1];
        edge_halfedges[2 * e_count + h] = (4 * h as u32 + 1).min(across);
    }
    let mut outgoing = Vec::with_capacity(v_count + e_count + f_count);
    outgoing.extend(t.outgoing().iter().map(|&h| 4 * h));
    outgoing.extend(
        t.edge_halfedges()
            .iter()
            .map(|&h| 4 * layout.next(h as usize) as u32 + 3),
    );
    outgoing.extend(offsets[..f_count].iter().map(|&a| 4 * a + 2));
    // Each coarse boundary half-edge h becomes its two halves, 4h and 4·next(h) + 3.
    let mut boundary = Vec::with_capacity(2 * t.boundary_halfedges.len());
    for &h in &t.boundary_halfedges {
        boundary.push(4 * h);
        boundary.push(4 * layout.next(h as usize) as u32 + 3);
    }
    let boundary_offsets = t.boundary_offsets.iter().map(|&o| 2 * o).collect();
    let face_offsets = (0..=h_count as u32).map(|c| 4 * c).collect();
    MeshTopology::from_parts_with_boundary_unchecked(
        v_count + e_count + f_count,
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

/// `true` if `h` is the stored half-edge of its edge: its twin is missing or larger.
#[inline(always)]
pub(crate) fn stored(h: usize, twin: u32) -> bool {
    twin == NONE || (h as u32) < twin
}
