//! The working structure of the divide-and-conquer builder: the primal half of Guibas and
//! Stolfi's quad-edge structure.
//!
//! An undirected edge is a pair of half-edges `2k` and `2k + 1` (so `sym(e) = e ^ 1`). Each
//! half-edge knows its origin and its neighbours in the counter-clockwise ring of half-edges
//! leaving that origin (`onext`, `oprev`). The dual rings of the full quad-edge structure
//! are never needed: the left face of `e` is walked with `lnext(e) = oprev(sym(e))`.
//! Indices are `u32` and the three fields of a half-edge sit together (with its twin's next
//! to them), which keeps the memory traffic of the merge walks low; the builder refuses
//! inputs too large for `u32`.

/// A half-edge id.
pub(super) type Edge = u32;

/// One half-edge.
#[derive(Debug, Clone, Copy)]
struct Half {
    /// Origin vertex, `u32::MAX` once deleted.
    org: u32,
    /// Next half-edge counter-clockwise around the origin.
    onext: Edge,
    /// Next half-edge clockwise around the origin.
    oprev: Edge,
}

/// Half-edge rings over vertices `0..n` (positions in the builder's sorted array).
#[derive(Debug, Default)]
pub(super) struct Mesh {
    /// The half-edges; `2k` and `2k + 1` are the two directions of edge `k`.
    half: Vec<Half>,
    /// Even ids of deleted edges, reused by `make_edge`.
    free: Vec<Edge>,
}

impl Mesh {
    /// An empty mesh with room for `edges` undirected edges.
    pub(super) fn with_capacity(edges: usize) -> Self {
        Mesh {
            half: Vec::with_capacity(2 * edges),
            free: Vec::new(),
        }
    }

    /// Number of half-edge slots, live or deleted.
    pub(super) fn slots(&self) -> usize {
        self.half.len()
    }

    /// Whether half-edge `e` belongs to a live edge.
    pub(super) fn is_live(&self, e: Edge) -> bool {
        self.half[e as usize].org != u32::MAX
    }

    /// The origin of `e`.
    #[inline]
    pub(super) fn org(&self, e: Edge) -> u32 {
        self.half[e as usize].org
    }

    /// The destination of `e`.
    #[inline]
    pub(super) fn dest(&self, e: Edge) -> u32 {
        self.half[(e ^ 1) as usize].org
    }

    /// The same edge in the opposite direction.
    #[inline]
    pub(super) fn sym(e: Edge) -> Edge {
        e ^ 1
    }

    /// The next half-edge counter-clockwise around `org(e)`.
    #[inline]
    pub(super) fn onext(&self, e: Edge) -> Edge {
        self.half[e as usize].onext
    }

    /// The next half-edge clockwise around `org(e)`.
    #[inline]
    pub(super) fn oprev(&self, e: Edge) -> Edge {
        self.half[e as usize].oprev
    }

    /// The half-edge after `e` on the boundary of its left face, counter-clockwise.
    #[inline]
    pub(super) fn lnext(&self, e: Edge) -> Edge {
        self.oprev(Self::sym(e))
    }

    /// The half-edge before `e` on the boundary of its right face, i.e. the next one
    /// counter-clockwise around `dest(e)` seen from there.
    #[inline]
    pub(super) fn rprev(&self, e: Edge) -> Edge {
        self.onext(Self::sym(e))
    }

    /// A new isolated edge from `a` to `b`; returns the half-edge `a -> b`.
    pub(super) fn make_edge(&mut self, a: u32, b: u32) -> Edge {
        let e = self.free.pop().unwrap_or(self.half.len() as Edge);
        let lone = |org: u32, h: Edge| Half {
            org,
            onext: h,
            oprev: h,
        };
        let pair = [lone(a, e), lone(b, e + 1)];
        let i = e as usize;
        if i == self.half.len() {
            self.half.extend(pair);
        } else {
            self.half[i..i + 2].copy_from_slice(&pair);
        }
        e
    }

    /// Guibas and Stolfi's splice on the origin rings: if `a` and `b` leave the same vertex
    /// it splits their ring between them, otherwise it joins the two rings.
    pub(super) fn splice(&mut self, a: Edge, b: Edge) {
        let (an, bn) = (self.onext(a), self.onext(b));
        self.half[a as usize].onext = bn;
        self.half[b as usize].onext = an;
        self.half[bn as usize].oprev = a;
        self.half[an as usize].oprev = b;
    }

    /// A new edge from `dest(a)` to `org(b)` such that `a`, the new edge and `b` bound the
    /// same left face; returns the new half-edge.
    pub(super) fn connect(&mut self, a: Edge, b: Edge) -> Edge {
        let e = self.make_edge(self.dest(a), self.org(b));
        let an = self.lnext(a);
        self.splice(e, an);
        self.splice(Self::sym(e), b);
        e
    }

    /// Removes the edge of `e` from both rings and frees its slots.
    pub(super) fn delete_edge(&mut self, e: Edge) {
        let op = self.oprev(e);
        self.splice(e, op);
        let s = Self::sym(e);
        let sp = self.oprev(s);
        self.splice(s, sp);
        let even = e & !1;
        self.half[even as usize].org = u32::MAX;
        self.half[even as usize + 1].org = u32::MAX;
        self.free.push(even);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Walks the left face of `e` and returns its vertices.
    fn left_face(m: &Mesh, e: Edge) -> Vec<u32> {
        let mut out = vec![m.org(e)];
        let mut f = m.lnext(e);
        while f != e {
            out.push(m.org(f));
            f = m.lnext(f);
            assert!(out.len() < 100, "face does not close");
        }
        out
    }

    #[test]
    fn connect_closes_a_triangle_and_delete_reopens_it() {
        // Triangle 0, 1, 2 counter-clockwise, built as Guibas and Stolfi's base case does.
        let mut m = Mesh::with_capacity(3);
        let a = m.make_edge(0, 1);
        let b = m.make_edge(1, 2);
        m.splice(Mesh::sym(a), b);
        let c = m.connect(b, a);
        assert_eq!((m.org(c), m.dest(c)), (2, 0));
        assert_eq!(left_face(&m, a), [0, 1, 2]);
        assert_eq!(left_face(&m, Mesh::sym(a)), [1, 0, 2]);
        // Around vertex 0: the ring holds a and sym(c), each the other's onext and oprev.
        assert_eq!(m.onext(a), Mesh::sym(c));
        assert_eq!(m.oprev(a), Mesh::sym(c));
        m.delete_edge(c);
        assert!(!m.is_live(c));
        assert_eq!(left_face(&m, a), [0, 1, 2, 1]);
        // The freed slots are reused.
        let d = m.make_edge(0, 2);
        assert_eq!(d & !1, c & !1);
        assert_eq!(m.slots(), 6);
    }

    #[test]
    fn splice_twice_restores_the_rings() {
        let mut m = Mesh::with_capacity(3);
        let a = m.make_edge(0, 1);
        let b = m.make_edge(0, 2);
        let c = m.make_edge(0, 3);
        m.splice(a, b);
        m.splice(b, c);
        let ring = |m: &Mesh| {
            let mut r = vec![a];
            let mut e = m.onext(a);
            while e != a {
                r.push(e);
                e = m.onext(e);
            }
            r
        };
        assert_eq!(ring(&m).len(), 3);
        for e in [a, b, c] {
            assert_eq!(m.oprev(m.onext(e)), e);
        }
        m.splice(b, c);
        assert_eq!(ring(&m).len(), 2);
        m.splice(a, b);
        assert_eq!(ring(&m), [a]);
    }
}
