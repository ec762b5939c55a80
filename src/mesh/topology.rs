//! [`MeshTopology`]: the connectivity of a polygon mesh in flat half-edge arrays, built once
//! from a face list and validated there (the layout and its invariants are on the type).

use crate::error::Violation;
use crate::mesh::MeshError;
use crate::{limits, Error, Result};
use std::ops::Range;

/// The stored value of a missing half-edge: the twin of a boundary half-edge.
pub const NONE: u32 = u32::MAX;

/// The connectivity of a [`PolygonMesh`](super::PolygonMesh): faces, half-edges, edges and
/// vertices as flat `u32` arrays.
///
/// Half-edge `h` is corner `h` of its face: the faces' corner lists are stored one after the
/// other (`corners`, with face `f` at `face_offsets[f]..face_offsets[f + 1]`), and the
/// half-edge of corner `h` runs from that corner's vertex to the next corner's vertex, with
/// its face on its left (faces are counter-clockwise seen from outside). So `origin`, `next`,
/// `prev` and `face` are index arithmetic; `twin` (the half-edge running the other way along
/// the same edge, in the neighbouring face) is stored, with [`NONE`] on the boundary, as is
/// the edge of every half-edge and one outgoing half-edge per vertex.
///
/// Indices are stored as `u32` (a mesh has at most
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) half-edges); the accessors taking
/// one element take and return `usize`, and the raw slices ([`corners`](Self::corners),
/// [`twins`](Self::twins), ...) are there for loops that run over all of them.
///
/// # Invariants (checked by [`MeshTopology::check`])
///
/// - every face has at least three corners, no vertex twice, and every vertex index is in
///   range;
/// - `twins` is an involution between half-edges running in opposite directions between the
///   same two vertices; a half-edge without twin is a boundary half-edge;
/// - edge `e` has the half-edges `edge_halfedges[e]` and its twin; `edge_halfedges[e]` is the
///   boundary half-edge of a boundary edge and the smaller index of the pair otherwise;
/// - every vertex has outgoing half-edges; `outgoing[v]` is one of them, the boundary one
///   (without twin) for a boundary vertex, and the faces around `v` form one fan: from
///   `outgoing[v]`, `h ↦ twin(prev(h))` visits every outgoing half-edge of `v`,
///   counter-clockwise, ending at [`NONE`] on the boundary or back at the start inside;
/// - the boundary half-edges form the boundary loops, each followed in the direction of its
///   half-edges (the surface on the left).
///
/// # Complexity
///
/// Building: O(H log d) time for H half-edges (the sum of the face sizes) and d the largest
/// number of half-edges leaving one vertex, O(V + H) space. Every accessor is O(1) except
/// the one-ring walks, O(valence).
///
/// ```
/// use compgeo::mesh::PolygonMesh;
/// use compgeo::spline::Point;
///
/// // Two triangles sharing the edge 0 – 2 of a square.
/// let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
/// let mesh = PolygonMesh::new(
///     vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)],
///     &[[0, 1, 2], [0, 2, 3]],
/// )?;
/// let t = mesh.topology();
/// assert_eq!((t.vertex_count(), t.edge_count(), t.face_count()), (4, 5, 2));
/// assert_eq!(t.twin(2), Some(3)); // 2 → 0 in face 0, 0 → 2 in face 1
/// assert_eq!(t.twin(0), None); // 0 → 1 is on the boundary
/// assert_eq!((t.origin(4), t.destination(4), t.face(4)), (2, 3, 1));
/// assert_eq!(t.valence(0), 3);
/// assert_eq!(t.neighbours(0).collect::<Vec<_>>(), [1, 2, 3]);
/// assert_eq!(t.boundary_loop_count(), 1);
/// assert_eq!(t.euler_characteristic(), 1); // a disk
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MeshTopology {
    /// The number of vertices.
    pub(crate) vertex_count: usize,
    /// Face `f`'s corners are `face_offsets[f]..face_offsets[f + 1]` (F + 1 entries).
    pub(crate) face_offsets: Vec<u32>,
    /// The vertex at each corner: the origin of half-edge `h`.
    pub(crate) corners: Vec<u32>,
    /// The opposite half-edge, or [`NONE`] on the boundary.
    pub(crate) twins: Vec<u32>,
    /// The face of each half-edge.
    pub(crate) halfedge_faces: Vec<u32>,
    /// The edge of each half-edge.
    pub(crate) halfedge_edges: Vec<u32>,
    /// One half-edge per edge: the boundary one, or the smaller index of the pair.
    pub(crate) edge_halfedges: Vec<u32>,
    /// One outgoing half-edge per vertex: the boundary one for a boundary vertex.
    pub(crate) outgoing: Vec<u32>,
    /// Boundary loop `i` is `boundary_halfedges[boundary_offsets[i]..boundary_offsets[i + 1]]`.
    pub(crate) boundary_offsets: Vec<u32>,
    /// The boundary half-edges, loop after loop, each loop in the order of its half-edges.
    pub(crate) boundary_halfedges: Vec<u32>,
}

impl MeshTopology {
    /// Builds and validates the connectivity of faces given as corner lists: face `f` is
    /// `corners[face_offsets[f]..face_offsets[f + 1]]` (vertex indices below `vertex_count`).
    /// `face_offsets` starts at 0, does not decrease and ends at `corners.len()` (callers
    /// build it so).
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] beyond [`MAX_MESH_VERTICES`](crate::limits::MAX_MESH_VERTICES)
    /// vertices or [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners;
    /// [`Error::Empty`] without faces; otherwise the first violation as an [`Error::Mesh`]:
    /// faces are checked in order (too few corners, a vertex out of range, a vertex twice),
    /// then half-edges in order (an edge's third use, two faces along an edge in the same
    /// direction), then vertices in order (isolated, non-manifold).
    pub(crate) fn from_faces(
        vertex_count: usize,
        face_offsets: &[usize],
        corners: &[usize],
    ) -> Result<MeshTopology> {
        limits::MESH_VERTICES.check(vertex_count as u128)?;
        limits::MESH_CORNERS.check(corners.len() as u128)?;
        let faces = face_offsets.len().saturating_sub(1);
        if faces == 0 {
            return Err(Error::Empty {
                what: "polygon mesh",
            });
        }
        debug_assert_eq!(face_offsets[faces], corners.len());
        // Faces: size, range, repetition (a stamp per vertex: the last face that used it).
        let mut seen = vec![NONE; vertex_count];
        let mut halfedge_faces = Vec::with_capacity(corners.len());
        for f in 0..faces {
            let face = &corners[face_offsets[f]..face_offsets[f + 1]];
            if face.len() < 3 {
                return Err(mesh_error(MeshError::TooFewCorners {
                    face: f,
                    corners: face.len(),
                }));
            }
            for &v in face {
                if v >= vertex_count {
                    return Err(mesh_error(MeshError::VertexOutOfRange {
                        face: f,
                        vertex: v,
                        vertices: vertex_count,
                    }));
                }
                if seen[v] == f as u32 {
                    return Err(mesh_error(MeshError::RepeatedVertex { face: f, vertex: v }));
                }
                seen[v] = f as u32;
            }
            halfedge_faces.extend(std::iter::repeat_n(f as u32, face.len()));
        }
        drop(seen);
        let face_offsets: Vec<u32> = face_offsets.iter().map(|&o| o as u32).collect();
        let corners: Vec<u32> = corners.iter().map(|&v| v as u32).collect();
        let mut t = MeshTopology {
            vertex_count,
            face_offsets,
            corners,
            twins: Vec::new(),
            halfedge_faces,
            halfedge_edges: Vec::new(),
            edge_halfedges: Vec::new(),
            outgoing: Vec::new(),
            boundary_offsets: Vec::new(),
            boundary_halfedges: Vec::new(),
        };
        let (starts, out) = t.outgoing_lists();
        t.link_twins(&starts, &out)?;
        t.number_edges();
        t.choose_outgoing(&starts, &out)?;
        t.find_boundary_loops();
        Ok(t)
    }

    /// The connectivity from arrays a subdivision scheme built by index arithmetic; the
    /// boundary loops are found here. Nothing is validated (the scheme's construction
    /// guarantees the invariants); debug builds run [`check`](Self::check).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_parts_unchecked(
        vertex_count: usize,
        face_offsets: Vec<u32>,
        corners: Vec<u32>,
        twins: Vec<u32>,
        halfedge_faces: Vec<u32>,
        halfedge_edges: Vec<u32>,
        edge_halfedges: Vec<u32>,
        outgoing: Vec<u32>,
    ) -> MeshTopology {
        let mut t = MeshTopology {
            vertex_count,
            face_offsets,
            corners,
            twins,
            halfedge_faces,
            halfedge_edges,
            edge_halfedges,
            outgoing,
            boundary_offsets: Vec::new(),
            boundary_halfedges: Vec::new(),
        };
        t.find_boundary_loops();
        debug_assert_eq!(t.check(), Ok(()));
        t
    }

    /// [`from_parts_unchecked`](Self::from_parts_unchecked) with the boundary loops too
    /// (a scheme derives them from the coarse loops without a pass over all half-edges).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn from_parts_with_boundary_unchecked(
        vertex_count: usize,
        face_offsets: Vec<u32>,
        corners: Vec<u32>,
        twins: Vec<u32>,
        halfedge_faces: Vec<u32>,
        halfedge_edges: Vec<u32>,
        edge_halfedges: Vec<u32>,
        outgoing: Vec<u32>,
        boundary_offsets: Vec<u32>,
        boundary_halfedges: Vec<u32>,
    ) -> MeshTopology {
        let t = MeshTopology {
            vertex_count,
            face_offsets,
            corners,
            twins,
            halfedge_faces,
            halfedge_edges,
            edge_halfedges,
            outgoing,
            boundary_offsets,
            boundary_halfedges,
        };
        debug_assert_eq!(t.check(), Ok(()));
        t
    }

    /// The number of vertices V.
    #[inline]
    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// The number of faces F.
    #[inline]
    pub fn face_count(&self) -> usize {
        self.face_offsets.len() - 1
    }

    /// The number of edges E.
    #[inline]
    pub fn edge_count(&self) -> usize {
        self.edge_halfedges.len()
    }

    /// The number of half-edges H (the sum of the face sizes).
    #[inline]
    pub fn halfedge_count(&self) -> usize {
        self.corners.len()
    }

    /// The Euler characteristic V − E + F: 2 for a closed surface of genus 0 (a cube),
    /// 0 for a torus, 1 for a disk.
    pub fn euler_characteristic(&self) -> i64 {
        self.vertex_count as i64 - self.edge_count() as i64 + self.face_count() as i64
    }

    /// The vertices of face `f`, counter-clockwise.
    #[inline]
    pub fn face_vertices(&self, f: usize) -> &[u32] {
        &self.corners[self.face_halfedges(f)]
    }

    /// The half-edges of face `f`: corner `h` of the range is half-edge `h`.
    #[inline]
    pub fn face_halfedges(&self, f: usize) -> Range<usize> {
        self.face_offsets[f] as usize..self.face_offsets[f + 1] as usize
    }

    /// The number of corners of face `f`.
    #[inline]
    pub fn face_size(&self, f: usize) -> usize {
        (self.face_offsets[f + 1] - self.face_offsets[f]) as usize
    }

    /// The vertex half-edge `h` starts at.
    #[inline]
    pub fn origin(&self, h: usize) -> usize {
        self.corners[h] as usize
    }

    /// The vertex half-edge `h` ends at: the origin of its next half-edge.
    #[inline]
    pub fn destination(&self, h: usize) -> usize {
        self.corners[self.next(h)] as usize
    }

    /// The face of half-edge `h` (on its left).
    #[inline]
    pub fn face(&self, h: usize) -> usize {
        self.halfedge_faces[h] as usize
    }

    /// The edge of half-edge `h`.
    #[inline]
    pub fn edge(&self, h: usize) -> usize {
        self.halfedge_edges[h] as usize
    }

    /// The next half-edge around the face of `h` (counter-clockwise).
    #[inline]
    pub fn next(&self, h: usize) -> usize {
        let f = self.halfedge_faces[h] as usize;
        if h + 1 == self.face_offsets[f + 1] as usize {
            self.face_offsets[f] as usize
        } else {
            h + 1
        }
    }

    /// The previous half-edge around the face of `h`.
    #[inline]
    pub fn prev(&self, h: usize) -> usize {
        let f = self.halfedge_faces[h] as usize;
        if h == self.face_offsets[f] as usize {
            self.face_offsets[f + 1] as usize - 1
        } else {
            h - 1
        }
    }

    /// The half-edge running the other way along the edge of `h`, or `None` if `h` is on the
    /// boundary.
    #[inline]
    pub fn twin(&self, h: usize) -> Option<usize> {
        let t = self.twins[h];
        (t != NONE).then_some(t as usize)
    }

    /// The stored half-edge of edge `e`: the boundary one of a boundary edge, else the
    /// smaller index of its two.
    #[inline]
    pub fn edge_halfedge(&self, e: usize) -> usize {
        self.edge_halfedges[e] as usize
    }

    /// The two ends of edge `e`, as its stored half-edge runs.
    #[inline]
    pub fn edge_vertices(&self, e: usize) -> [usize; 2] {
        let h = self.edge_halfedge(e);
        [self.origin(h), self.destination(h)]
    }

    /// `true` if edge `e` has only one face.
    #[inline]
    pub fn is_boundary_edge(&self, e: usize) -> bool {
        self.twins[self.edge_halfedges[e] as usize] == NONE
    }

    /// `true` if half-edge `h` has no twin.
    #[inline]
    pub fn is_boundary_halfedge(&self, h: usize) -> bool {
        self.twins[h] == NONE
    }

    /// The stored outgoing half-edge of vertex `v`: the boundary one (without twin) for a
    /// boundary vertex, so that [`one_ring`](Self::one_ring) starting there sees every face.
    #[inline]
    pub fn outgoing_halfedge(&self, v: usize) -> usize {
        self.outgoing[v] as usize
    }

    /// `true` if vertex `v` is on the boundary.
    #[inline]
    pub fn is_boundary_vertex(&self, v: usize) -> bool {
        self.twins[self.outgoing[v] as usize] == NONE
    }

    /// The half-edges leaving vertex `v`, counter-clockwise around it, from
    /// [`outgoing_halfedge`](Self::outgoing_halfedge): one per face at `v`. A boundary
    /// vertex's walk starts at its boundary half-edge and ends at the face whose previous
    /// half-edge is the incoming boundary one.
    #[inline]
    pub fn one_ring(&self, v: usize) -> OneRing<'_> {
        let start = self.outgoing[v];
        OneRing {
            topology: self,
            start,
            current: start,
        }
    }

    /// The vertices joined to `v` by an edge, counter-clockwise: the destinations of the
    /// [`one_ring`](Self::one_ring) half-edges, then for a boundary vertex the origin of the
    /// incoming boundary half-edge.
    pub fn neighbours(&self, v: usize) -> impl Iterator<Item = usize> + '_ {
        let last = self.is_boundary_vertex(v).then(|| {
            let last_out = self.one_ring(v).last().unwrap_or(self.outgoing[v] as usize);
            self.origin(self.prev(last_out))
        });
        self.one_ring(v).map(|h| self.destination(h)).chain(last)
    }

    /// The number of edges at vertex `v` (its faces, plus one on the boundary).
    pub fn valence(&self, v: usize) -> usize {
        self.one_ring(v).count() + usize::from(self.is_boundary_vertex(v))
    }

    /// `true` if no edge is on the boundary.
    pub fn is_closed(&self) -> bool {
        self.boundary_halfedges.is_empty()
    }

    /// The number of boundary loops (0 for a closed surface).
    pub fn boundary_loop_count(&self) -> usize {
        self.boundary_offsets.len().saturating_sub(1)
    }

    /// The half-edges of boundary loop `i`, in order: each ends where the next starts.
    pub fn boundary_loop(&self, i: usize) -> &[u32] {
        &self.boundary_halfedges
            [self.boundary_offsets[i] as usize..self.boundary_offsets[i + 1] as usize]
    }

    /// `true` if every face is a triangle.
    pub fn is_triangle_mesh(&self) -> bool {
        self.corners.len() == 3 * self.face_count()
    }

    /// `true` if every face is a quadrilateral.
    pub fn is_quad_mesh(&self) -> bool {
        self.corners.len() == 4 * self.face_count()
    }

    /// The face offsets: face `f`'s half-edges are `face_offsets()[f]..face_offsets()[f + 1]`
    /// (F + 1 entries, from 0 to H).
    #[inline]
    pub fn face_offsets(&self) -> &[u32] {
        &self.face_offsets
    }

    /// The vertex of every corner (the origin of every half-edge), face after face.
    #[inline]
    pub fn corners(&self) -> &[u32] {
        &self.corners
    }

    /// The twin of every half-edge, [`NONE`] on the boundary.
    #[inline]
    pub fn twins(&self) -> &[u32] {
        &self.twins
    }

    /// The face of every half-edge.
    #[inline]
    pub fn halfedge_faces(&self) -> &[u32] {
        &self.halfedge_faces
    }

    /// The edge of every half-edge.
    #[inline]
    pub fn halfedge_edges(&self) -> &[u32] {
        &self.halfedge_edges
    }

    /// The stored half-edge of every edge (see [`edge_halfedge`](Self::edge_halfedge)).
    #[inline]
    pub fn edge_halfedges(&self) -> &[u32] {
        &self.edge_halfedges
    }

    /// The stored outgoing half-edge of every vertex (see
    /// [`outgoing_halfedge`](Self::outgoing_halfedge)).
    #[inline]
    pub fn outgoing(&self) -> &[u32] {
        &self.outgoing
    }

    /// Checks every invariant listed on [`MeshTopology`] from the arrays alone: the
    /// postcondition of every subdivision round in the tests.
    ///
    /// # Errors
    ///
    /// The first broken invariant, with the indices involved.
    ///
    /// # Complexity
    ///
    /// O(V + H) time and space.
    pub fn check(&self) -> std::result::Result<(), Violation> {
        let bad = |s: String| Err(Violation::new(s));
        let h_count = self.corners.len();
        let f_count = self.face_offsets.len().wrapping_sub(1);
        if self.face_offsets.first() != Some(&0)
            || *self.face_offsets.last().unwrap_or(&0) as usize != h_count
        {
            return bad("face offsets do not run from 0 to the half-edge count".into());
        }
        for array in [&self.twins, &self.halfedge_faces, &self.halfedge_edges] {
            if array.len() != h_count {
                return bad("a half-edge array has the wrong length".into());
            }
        }
        if self.outgoing.len() != self.vertex_count {
            return bad("the outgoing array has the wrong length".into());
        }
        let mut stamp = vec![NONE; self.vertex_count];
        for f in 0..f_count {
            let (a, b) = (self.face_offsets[f], self.face_offsets[f + 1]);
            if b < a + 3 {
                return bad(format!("face {f} has fewer than 3 corners"));
            }
            for h in a as usize..b as usize {
                let v = self.corners[h] as usize;
                if v >= self.vertex_count || stamp[v] == f as u32 {
                    return bad(format!("face {f}: corner {h} is out of range or repeated"));
                }
                stamp[v] = f as u32;
                if self.halfedge_faces[h] != f as u32 {
                    return bad(format!("half-edge {h} is not marked as in face {f}"));
                }
            }
        }
        let mut seen = vec![0u8; self.edge_halfedges.len()];
        for h in 0..h_count {
            let e = self.halfedge_edges[h] as usize;
            if e >= seen.len() {
                return bad(format!("half-edge {h} names edge {e} out of range"));
            }
            seen[e] += 1;
            let t = self.twins[h];
            let stored = self.edge_halfedges[e];
            if t == NONE {
                if stored != h as u32 {
                    return bad(format!(
                        "boundary half-edge {h} is not its edge's stored one"
                    ));
                }
                continue;
            }
            let t = t as usize;
            if t >= h_count || self.twins[t] != h as u32 || self.halfedge_edges[t] as usize != e {
                return bad(format!("half-edge {h} and its twin {t} do not pair"));
            }
            if self.origin(t) != self.destination(h) || self.destination(t) != self.origin(h) {
                return bad(format!(
                    "half-edge {h} and its twin {t} do not run opposite"
                ));
            }
            if stored != h.min(t) as u32 {
                return bad(format!(
                    "edge {e} does not store the smaller of {h} and {t}"
                ));
            }
        }
        if let Some(e) = seen.iter().position(|&n| n == 0) {
            return bad(format!("edge {e} has no half-edge"));
        }
        let mut out_degree = vec![0u32; self.vertex_count];
        for &v in &self.corners {
            out_degree[v as usize] += 1;
        }
        let mut boundary_out = vec![0u32; self.vertex_count];
        for h in 0..h_count {
            if self.twins[h] == NONE {
                boundary_out[self.corners[h] as usize] += 1;
            }
        }
        for v in 0..self.vertex_count {
            let h = self.outgoing[v] as usize;
            if h >= h_count || self.origin(h) != v {
                return bad(format!("vertex {v}'s outgoing half-edge does not leave it"));
            }
            if boundary_out[v] > 1 || (boundary_out[v] == 1 && self.twins[h] != NONE) {
                return bad(format!(
                    "vertex {v} is a boundary vertex without one boundary start"
                ));
            }
            let walked = self.one_ring(v).take(h_count + 1).count();
            if walked != out_degree[v] as usize {
                return bad(format!("vertex {v}'s faces do not form one fan"));
            }
        }
        let mut on_loop = 0;
        for i in 0..self.boundary_loop_count() {
            let lp = self.boundary_loop(i);
            for (k, &h) in lp.iter().enumerate() {
                let following = lp[(k + 1) % lp.len()] as usize;
                if self.twins[h as usize] != NONE
                    || self.destination(h as usize) != self.origin(following)
                {
                    return bad(format!("boundary loop {i} is broken at half-edge {h}"));
                }
            }
            on_loop += lp.len();
        }
        if on_loop != boundary_out.iter().sum::<u32>() as usize {
            return bad("the boundary loops miss a boundary half-edge".into());
        }
        Ok(())
    }

    /// The half-edges leaving each vertex (a counting sort by origin), each vertex's list
    /// sorted by destination and then index: `out[starts[v]..starts[v + 1]]`.
    fn outgoing_lists(&self) -> (Vec<u32>, Vec<u32>) {
        let n = self.vertex_count;
        let mut starts = vec![0u32; n + 1];
        for &v in &self.corners {
            starts[v as usize + 1] += 1;
        }
        for v in 0..n {
            starts[v + 1] += starts[v];
        }
        let mut fill = starts.clone();
        let mut out = vec![0u32; self.corners.len()];
        for (h, &v) in self.corners.iter().enumerate() {
            out[fill[v as usize] as usize] = h as u32;
            fill[v as usize] += 1;
        }
        for v in 0..n {
            let list = &mut out[starts[v] as usize..starts[v + 1] as usize];
            if list.len() > 1 {
                list.sort_unstable_by_key(|&h| (self.destination(h as usize), h));
            }
        }
        (starts, out)
    }

    /// Pairs every half-edge with the one running the other way, in half-edge order,
    /// stopping at the first edge used a third time or twice in one direction.
    fn link_twins(&mut self, starts: &[u32], out: &[u32]) -> Result<()> {
        let h_count = self.corners.len();
        let mut twins = vec![NONE; h_count];
        for h in 0..h_count {
            let (u, w) = (self.origin(h), self.destination(h));
            let same = self.earlier_along(starts, out, u, w, h);
            let reverse = self.earlier_along(starts, out, w, u, h);
            let face = self.face(h);
            if same.len() + reverse.len() >= 2 {
                return Err(mesh_error(MeshError::NonManifoldEdge {
                    face,
                    from: u,
                    to: w,
                }));
            }
            if let Some(&other) = same.first() {
                return Err(mesh_error(MeshError::InconsistentOrientation {
                    face,
                    other: self.face(other as usize),
                    from: u,
                    to: w,
                }));
            }
            if let Some(&t) = reverse.first() {
                twins[h] = t;
                twins[t as usize] = h as u32;
            }
        }
        self.twins = twins;
        Ok(())
    }

    /// Up to two half-edges from `u` to `w` with an index below `h` (from the sorted lists
    /// of [`outgoing_lists`](Self::outgoing_lists)).
    fn earlier_along(&self, starts: &[u32], out: &[u32], u: usize, w: usize, h: usize) -> Vec2 {
        let list = &out[starts[u] as usize..starts[u + 1] as usize];
        let first = list.partition_point(|&g| self.destination(g as usize) < w);
        let mut found = Vec2::default();
        for &g in &list[first..] {
            if self.destination(g as usize) != w || g as usize >= h || found.len() == 2 {
                break;
            }
            found.push(g);
        }
        found
    }

    /// Numbers the edges in the order of their stored half-edges (the boundary one or the
    /// smaller index).
    fn number_edges(&mut self) {
        (self.halfedge_edges, self.edge_halfedges) = edges_of_twins(&self.twins);
    }

    /// Picks each vertex's outgoing half-edge (its boundary one, or its first) and checks
    /// that its faces form one fan; reports isolated and non-manifold vertices.
    fn choose_outgoing(&mut self, starts: &[u32], out: &[u32]) -> Result<()> {
        let mut outgoing = vec![NONE; self.vertex_count];
        for v in 0..self.vertex_count {
            let list = &out[starts[v] as usize..starts[v + 1] as usize];
            if list.is_empty() {
                return Err(mesh_error(MeshError::IsolatedVertex { vertex: v }));
            }
            let mut boundary = list.iter().filter(|&&h| self.twins[h as usize] == NONE);
            let first_boundary = boundary.next();
            if let Some(&second) = boundary.next() {
                return Err(mesh_error(MeshError::NonManifoldVertex {
                    vertex: v,
                    face: self.face(second as usize),
                }));
            }
            let start = match first_boundary {
                Some(&h) => h,
                None => *list.iter().min().unwrap_or(&list[0]),
            };
            // Walk the fan; it ends at the boundary or back at the start.
            let mut visited = Vec::with_capacity(list.len());
            let mut h = start as usize;
            let mut open = false;
            loop {
                visited.push(h as u32);
                let t = self.twins[self.prev(h)];
                if t == NONE {
                    open = true;
                    break;
                }
                h = t as usize;
                if h == start as usize || visited.len() > list.len() {
                    break;
                }
            }
            if visited.len() != list.len() || (open && first_boundary.is_none()) {
                let stray = list
                    .iter()
                    .find(|h| !visited.contains(h))
                    .map_or(self.face(self.prev(h)), |&h| self.face(h as usize));
                return Err(mesh_error(MeshError::NonManifoldVertex {
                    vertex: v,
                    face: stray,
                }));
            }
            outgoing[v] = start;
        }
        self.outgoing = outgoing;
        Ok(())
    }

    /// Collects the boundary loops: after the boundary half-edge `h`, the loop goes on with
    /// the boundary half-edge leaving the end of `h` (the stored outgoing one there).
    fn find_boundary_loops(&mut self) {
        let mut offsets = Vec::new();
        let mut loops = Vec::new();
        let mut done = vec![false; self.corners.len()];
        for h in 0..self.corners.len() {
            if self.twins[h] != NONE || done[h] {
                continue;
            }
            offsets.push(loops.len() as u32);
            let mut g = h;
            while !done[g] {
                done[g] = true;
                loops.push(g as u32);
                g = self.outgoing[self.destination(g)] as usize;
            }
        }
        if !loops.is_empty() {
            offsets.push(loops.len() as u32);
        }
        self.boundary_offsets = offsets;
        self.boundary_halfedges = loops;
    }
}

/// The outgoing half-edges of a vertex counter-clockwise: see
/// [`MeshTopology::one_ring`].
#[derive(Clone, Debug)]
pub struct OneRing<'a> {
    topology: &'a MeshTopology,
    start: u32,
    current: u32,
}

impl Iterator for OneRing<'_> {
    type Item = usize;

    #[inline]
    fn next(&mut self) -> Option<usize> {
        if self.current == NONE {
            return None;
        }
        let h = self.current as usize;
        let t = self.topology.twins[self.topology.prev(h)];
        self.current = if t == self.start { NONE } else { t };
        Some(h)
    }
}

/// At most two half-edge indices, without allocating.
#[derive(Default)]
struct Vec2 {
    items: [u32; 2],
    len: usize,
}

impl Vec2 {
    fn push(&mut self, h: u32) {
        self.items[self.len] = h;
        self.len += 1;
    }
    fn len(&self) -> usize {
        self.len
    }
    fn first(&self) -> Option<&u32> {
        self.items[..self.len].first()
    }
}

/// The edge of every half-edge and the stored half-edge of every edge, numbered in the
/// order of their stored half-edges (the boundary one, or the smaller index of a pair), from
/// the twins alone: the numbering of a validated mesh, shared by the schemes that build
/// their twins first (Doo–Sabin).
pub(crate) fn edges_of_twins(twins: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let mut halfedge_edges = vec![NONE; twins.len()];
    let mut edge_halfedges = Vec::with_capacity(twins.len() / 2 + 1);
    for (h, &t) in twins.iter().enumerate() {
        if t == NONE || (h as u32) < t {
            let e = edge_halfedges.len() as u32;
            edge_halfedges.push(h as u32);
            halfedge_edges[h] = e;
            if t != NONE {
                halfedge_edges[t as usize] = e;
            }
        }
    }
    (halfedge_edges, edge_halfedges)
}

fn mesh_error(e: MeshError) -> Error {
    Error::Mesh(e)
}
