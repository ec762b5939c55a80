//! The incremental builder on large inputs (from [`SPLIT_MIN`] = 2^19 points), in two
//! halves: the points split by a vertical line (lexicographically), each half triangulated
//! by insertion (on two threads with the `parallel` feature), and the halves stitched
//! together along the seam.
//!
//! The problem: the insertion of [`incremental`](super::incremental) is one sequential chain
//! of walks and flips, so a second core cannot help it, and at 10^6 points and more its
//! triangle arrays no longer fit the cache.
//!
//! The idea: every point left of the split precedes every point right of it in
//! lexicographic order, which is what Guibas and Stolfi's merge needs (the course's divide
//! and conquer, [RD, §2.4]): from the lower common tangent of the two hulls, climb the seam,
//! each step adding the triangle on the current cross edge whose circle is empty and
//! deleting the edges of either half whose circle holds a point of the other. The merge
//! runs on the builder's own arrays, ghosts included, and leaves the halves' entries as
//! they were while it climbs: the candidates around a vertex are found by rotating through
//! them and skipping the edges deleted so far (kept in a set), as the quad-edge rings would
//! be walked. After the climb, the triangles with a deleted edge and the ghosts between the
//! two tangents are removed, the new triangles (two of them ghosts closing the merged hull)
//! are linked in and fill the freed slots. Each half is built in its own insertion order,
//! and the split depends on the points only, so the triangulation is the same with and
//! without `parallel`, on any number of threads, and with a recording counter (which
//! builds the halves one after the other).
//!
//! # Complexity
//! The split: O(n), after a sort of a 1023-point random sample. The halves: as the
//! builder, each on its own points, in its own insertion order (BRIO and Hilbert order over
//! the whole set's box). The merge: O(h + s) orientation and in-circle tests, where h is the
//! number of hull vertices of the halves and s the number of triangles the seam deletes and
//! creates; s is O(n) in the worst case and about √n on uniform input. Both halves' arrays
//! are one allocation, so the merge copies nothing: O(s) auxiliary space beyond the mesh.

use super::hilbert::{brio_order, brio_order_labelled, curve_bounds};
use super::incremental::{
    build, first_triangle, ghost_real_edge, insert_all, mesh_size, next, prev, Ghosted, Part, GHOST,
};
use crate::count::Counter;
use crate::gen::Rng;
use crate::geometry::{
    cmp_lex, BoundingBox, BoxPredicates, InCircle, Orientation, Point2, PointSet,
};
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};

/// Inputs with at least this many points are built in two halves. Below it the split cost
/// the sequential build about a tenth of its time (3·10^5 points), from 10^6 nothing
/// measurable; with two threads it gains 1.6 times at 3·10^5 points.
pub(super) const SPLIT_MIN: usize = 1 << 19;

/// Points of the random sample whose lexicographic median splits the set.
const SAMPLE: usize = 1023;

/// The seed of the sample (any fixed value: the split must not depend on anything but the
/// points).
const PIVOT_SEED: u64 = 0x5EED_5E1F_0000_0001;

/// The first vertex of a triangle the merge removed (or of a slot no half filled).
const DEAD: u32 = GHOST - 1;

/// The ghost mesh of `points` by insertion, in two halves stitched by the merge; the whole
/// set at once when a half has no three non-collinear points. `None` if the set has none.
pub(super) fn build_split<C: Counter>(
    points: &PointSet<'_>,
    filter: BoxPredicates,
    counter: &mut C,
) -> Option<Ghosted> {
    let (left, right) = split_input(points);
    let bounds = curve_bounds(points, points.bounding_box());
    let (mut left, mut right) = both(
        || half_order(points, left, bounds),
        || half_order(points, right, bounds),
    );
    let (Some(left_first), Some(right_first)) = (
        first_triangle(points, &mut left, counter),
        first_triangle(points, &mut right, counter),
    ) else {
        return build(points, brio_order(points, bounds), filter, counter);
    };
    let split = left.len();
    let mut order = left;
    order.extend_from_slice(&right);
    drop(right);
    let local = gather(points, &order);
    // Both halves' arrays in one allocation, the left's first, with room after them for
    // the seam's new triangles (a zeroed allocation takes no memory until written).
    let (left_size, right_size) = (mesh_size(split), mesh_size(local.len() - split));
    let room = left_size + right_size + 3 * seam_allowance(local.len());
    let mut triangles = vec![0; room];
    let mut halfedges = vec![0; room];
    let (left_part, right_part) = {
        let (tl, tr) = triangles.split_at_mut(left_size);
        let (hl, hr) = halfedges.split_at_mut(left_size);
        let (pl, pr) = local.split_at(split);
        insert_halves(
            (pl, left_first, tl, hl),
            (pr, right_first, tr, hr),
            filter,
            counter,
        )
    };
    // The right half's ids follow the left's; the slots neither half filled are holes.
    let vertex_shift = split as u32;
    let edge_shift = left_size as u32;
    let right_end = left_size + right_part.len;
    shift(&mut triangles[left_size..right_end], |v| {
        if v == GHOST {
            GHOST
        } else {
            v + vertex_shift
        }
    });
    shift(&mut halfedges[left_size..right_end], |e| e + edge_shift);
    triangles.truncate(right_end);
    halfedges.truncate(right_end);
    let mut holes = Vec::new();
    for t in (left_part.len / 3..left_size / 3).map(|t| t as u32) {
        triangles[3 * t as usize] = DEAD;
        holes.push(t);
    }
    let mut duplicates = left_part.duplicates;
    duplicates.extend(
        right_part
            .duplicates
            .iter()
            .map(|&[d, k]| [d + vertex_shift, k + vertex_shift]),
    );
    let mesh = Ghosted {
        points: local,
        order,
        triangles,
        halfedges,
        duplicates,
    };
    Some(stitch(mesh, (left_size / 3) as u32, holes, filter, counter))
}

/// Slots for the triangles the merge creates before it fills the removed ones: about the
/// seam's length on uniform input. More only costs a reallocation.
fn seam_allowance(n: usize) -> usize {
    64 + 16 * n.isqrt()
}

/// One half to insert: its points, first triangle and arrays.
type Half<'a> = (&'a [Point2], [u32; 3], &'a mut [u32], &'a mut [u32]);

/// The two halves inserted: on two threads when the counter discards its counts and the
/// `parallel` feature has more than one thread to give.
fn insert_halves<C: Counter>(
    (pl, fl, tl, hl): Half<'_>,
    (pr, fr, tr, hr): Half<'_>,
    filter: BoxPredicates,
    counter: &mut C,
) -> (Part, Part) {
    #[cfg(feature = "parallel")]
    if C::DISCARDS && crate::parallel::enabled(pl.len() + pr.len()) {
        use crate::count::NoCount;
        return rayon::join(
            || insert_all(pl, fl, tl, hl, filter, &mut NoCount),
            || insert_all(pr, fr, tr, hr, filter, &mut NoCount),
        );
    }
    let left = insert_all(pl, fl, tl, hl, filter, counter);
    let right = insert_all(pr, fr, tr, hr, filter, counter);
    (left, right)
}

/// The points `order` lists, in that order.
fn gather(points: &[Point2], order: &[u32]) -> Vec<Point2> {
    #[cfg(feature = "parallel")]
    if crate::parallel::enabled(order.len()) {
        use rayon::prelude::*;
        return order.par_iter().map(|&i| points[i as usize]).collect();
    }
    order.iter().map(|&i| points[i as usize]).collect()
}

/// `entries` mapped in place.
fn shift(entries: &mut [u32], map: impl Fn(u32) -> u32 + Sync + Send) {
    #[cfg(feature = "parallel")]
    if crate::parallel::enabled(entries.len()) {
        use rayon::prelude::*;
        entries.par_iter_mut().for_each(|x| *x = map(*x));
        return;
    }
    for x in entries {
        *x = map(*x);
    }
}

/// The ids of `points` split into those lexicographically below the median of a random
/// sample and the others, each in increasing order. Equal points fall on one side.
fn split_input(points: &[Point2]) -> (Vec<u32>, Vec<u32>) {
    let mut rng = Rng::new(PIVOT_SEED);
    let mut sample: Vec<Point2> = (0..SAMPLE)
        .map(|_| points[rng.index(points.len())])
        .collect();
    sample.sort_unstable_by(|a, b| cmp_lex(*a, *b));
    let pivot = sample[SAMPLE / 2];
    let split = |from: usize, part: &[Point2]| {
        let (mut left, mut right) = (
            Vec::with_capacity(part.len()),
            Vec::with_capacity(part.len()),
        );
        for (i, p) in (from as u32..).zip(part) {
            if cmp_lex(*p, pivot) == Ordering::Less {
                left.push(i);
            } else {
                right.push(i);
            }
        }
        (left, right)
    };
    #[cfg(feature = "parallel")]
    if crate::parallel::enabled(points.len()) {
        use crate::parallel::concatenate;
        use rayon::prelude::*;
        let chunk = points.len().div_ceil(4 * rayon::current_num_threads());
        let (left, right): (Vec<Vec<u32>>, Vec<Vec<u32>>) = points
            .par_chunks(chunk)
            .enumerate()
            .map(|(c, part)| split(c * chunk, part))
            .unzip();
        return (concatenate(left), concatenate(right));
    }
    split(0, points)
}

/// The ids `ids` of `points` in the builder's insertion order (BRIO, Hilbert order inside
/// each round, over `bounds`).
fn half_order(points: &[Point2], ids: Vec<u32>, bounds: Option<BoundingBox>) -> Vec<u32> {
    let half: Vec<Point2> = ids.iter().map(|&i| points[i as usize]).collect();
    // The ids increase (the split keeps the input order), so they can label the keys.
    brio_order_labelled(&half, bounds, &|k| ids[k])
}

/// `a` and `b`, on two threads with the `parallel` feature (and more than one thread in
/// the pool).
fn both<A: Send, B: Send>(a: impl FnOnce() -> A + Send, b: impl FnOnce() -> B + Send) -> (A, B) {
    #[cfg(feature = "parallel")]
    if rayon::current_num_threads() > 1 {
        return rayon::join(a, b);
    }
    (a(), b())
}

/// The two halves of `mesh` (triangles from `right_start` on are the right half's, vertices
/// from its first point) merged along the seam, then the removed triangles and `holes`
/// (slots no half filled, marked [`DEAD`]) filled.
fn stitch<C: Counter>(
    mesh: Ghosted,
    right_start: u32,
    mut holes: Vec<u32>,
    filter: BoxPredicates,
    counter: &mut C,
) -> Ghosted {
    let left_ring = mesh.ghost_ring(0);
    let right_ring = mesh.ghost_ring(right_start);
    let mut seam = Seam {
        mesh,
        filter,
        counter,
        deleted: HashSet::new(),
        pending: Vec::new(),
    };
    holes.extend(seam.merge(&left_ring, &right_ring));
    let mut mesh = seam.mesh;
    mesh.fill_holes(&holes, |triangles, t| triangles[3 * t as usize] == DEAD);
    mesh
}

/// The merge's state: the two halves in one ghost mesh, the left half's vertices and
/// triangles first.
///
/// The halves' arrays are left as they were until the climb ends: the rotations around a
/// vertex follow them, skipping the edges the merge has deleted (as Guibas and Stolfi's
/// edge rings would), and the new triangles' links to them are applied after.
struct Seam<'c, C> {
    mesh: Ghosted,
    filter: BoxPredicates,
    counter: &'c mut C,
    /// The deleted edges, as both their half-edges.
    deleted: HashSet<u32>,
    /// (new half-edge, a halves' half-edge of the same edge the other way), to be linked.
    pending: Vec<(u32, u32)>,
}

/// No half-edge.
const NONE: u32 = u32::MAX;

impl<C: Counter> Seam<'_, C> {
    /// Guibas and Stolfi's merge of the two halves, whose hulls are `left_ring` and
    /// `right_ring` (ghosts in hull order, [`Ghosted::ghost_ring`]); returns the removed
    /// triangles, marked [`DEAD`].
    ///
    /// From the lower common tangent, the base edge l -> r climbs. The left candidates are
    /// the edges out of l counter-clockwise from the base, the right ones the edges into r
    /// clockwise from it; a candidate whose circle through the base holds the next
    /// candidate of its side is deleted. The new triangle takes the candidate of either side
    /// whose circle holds no candidate of the other, and its edge across becomes the base,
    /// until the base is the upper common tangent. The triangles with a deleted edge and the
    /// ghosts between the tangents are removed; the new ones cover them.
    fn merge(&mut self, left_ring: &[u32], right_ring: &[u32]) -> Vec<u32> {
        let nr = right_ring.len();
        let (i0, j0) = self.tangent(left_ring, right_ring, Orientation::Clockwise);
        let (i1, j1) = self.tangent(left_ring, right_ring, Orientation::CounterClockwise);
        let (l0, r0) = (self.origin(left_ring[i0]), self.origin(right_ring[j0]));
        let (l1, r1) = (self.origin(left_ring[i1]), self.origin(right_ring[j1]));
        let bottom = self.push([r0, l0, GHOST]);
        let top = self.push([l1, r1, GHOST]);
        // The first candidates: the hull edges out of l0 (counter-clockwise) and into r0
        // (clockwise), as half-edges of their real triangles.
        let mut lc = self.real_twin(left_ring[i0]);
        let mut rc = self.real_twin(right_ring[before(j0, nr)]);
        // The edge each side's deletions stop at: past it come the new triangles.
        let (mut left_stop, mut right_stop) = (NONE, NONE);
        let mut below = 3 * bottom;
        let (mut l, mut r) = (l0, r0);
        while (l, r) != (l1, r1) {
            let mut c = self.mesh.triangles[next(lc) as usize];
            let mut left_valid = self.above(l, r, c);
            if left_valid {
                while let Some(e) = self.next_out(lc, left_stop) {
                    let c2 = self.mesh.triangles[next(e) as usize];
                    if !self.inside(l, r, c, c2) {
                        break;
                    }
                    self.delete(lc);
                    (lc, c) = (e, c2);
                }
                left_valid = self.above(l, r, c);
            }
            let mut d = self.mesh.triangles[rc as usize];
            let mut right_valid = self.above(l, r, d);
            if right_valid {
                while let Some(e) = self.next_into(rc, right_stop) {
                    let d2 = self.mesh.triangles[e as usize];
                    if !self.inside(l, r, d, d2) {
                        break;
                    }
                    self.delete(rc);
                    (rc, d) = (e, d2);
                }
                right_valid = self.above(l, r, d);
            }
            assert!(
                left_valid || right_valid,
                "the merge climbs until the upper tangent"
            );
            if !left_valid || (right_valid && self.inside(l, r, c, d)) {
                // (l, r, d): r -> d is the right half's edge d -> r, d -> l the next base.
                let t = self.push([l, r, d]);
                self.link(3 * t, below);
                self.pending.push((3 * t + 1, rc));
                below = 3 * t + 2;
                r = d;
                right_stop = self.mesh.halfedges[rc as usize];
                rc = self.first_into(right_stop);
            } else {
                // (l, r, c): c -> l is the left half's edge l -> c, r -> c the next base.
                let t = self.push([l, r, c]);
                self.link(3 * t, below);
                self.pending.push((3 * t + 2, lc));
                below = 3 * t + 1;
                l = c;
                left_stop = self.mesh.halfedges[lc as usize];
                lc = self.first_out(left_stop);
            }
        }
        self.link(3 * top, below);
        self.close(left_ring, right_ring, [i0, j0, i1, j1], [bottom, top])
    }

    /// After the climb: removes the triangles with a deleted edge and the ghosts between
    /// the tangents (ring positions `[i0, j0, i1, j1]`), links the new triangles to the
    /// halves', and the new ghosts `[bottom, top]` into the ring. Returns the removed ones.
    fn close(
        &mut self,
        left_ring: &[u32],
        right_ring: &[u32],
        [i0, j0, i1, j1]: [usize; 4],
        [bottom, top]: [u32; 2],
    ) -> Vec<u32> {
        let (nl, nr) = (left_ring.len(), right_ring.len());
        // A half whose tangents meet at one vertex has its whole hull on the seam: the
        // merged hull passes that vertex once, and the two new ghosts meet there.
        let left_seam = if i1 == i0 { nl } else { (i1 + nl - i0) % nl };
        let right_seam = if j1 == j0 { nr } else { (j0 + nr - j1) % nr };
        let mut dead = Vec::with_capacity(self.deleted.len() + left_seam + right_seam);
        let mut kill = |triangles: &mut [u32], t: u32| {
            if triangles[3 * t as usize] != DEAD {
                triangles[3 * t as usize] = DEAD;
                dead.push(t);
            }
        };
        let mut deleted: Vec<u32> = self.deleted.iter().copied().collect();
        deleted.sort_unstable();
        for &e in &deleted {
            kill(&mut self.mesh.triangles, e / 3);
        }
        for s in 0..left_seam {
            kill(&mut self.mesh.triangles, left_ring[(i0 + s) % nl]);
        }
        for s in 0..right_seam {
            kill(&mut self.mesh.triangles, right_ring[(j1 + s) % nr]);
        }
        // A halves' edge with removed triangles on both sides has new ones on both.
        let pending = std::mem::take(&mut self.pending);
        let new_of: HashMap<u32, u32> = pending.iter().map(|&(n, o)| (o, n)).collect();
        for &(n, o) in &pending {
            if self.mesh.triangles[3 * (o / 3) as usize] != DEAD {
                self.link(n, o);
            } else {
                let across = new_of[&self.mesh.halfedges[o as usize]];
                self.mesh.halfedges[n as usize] = across;
            }
        }
        if left_seam == nl {
            self.link(3 * bottom + 1, 3 * top + 2);
        } else {
            self.link(
                3 * bottom + 1,
                self.ghost_edge(left_ring[before(i0, nl)], 2),
            );
            self.link(3 * top + 2, self.ghost_edge(left_ring[i1], 1));
        }
        if right_seam == nr {
            self.link(3 * top + 1, 3 * bottom + 2);
        } else {
            self.link(3 * bottom + 2, self.ghost_edge(right_ring[j0], 1));
            self.link(3 * top + 1, self.ghost_edge(right_ring[before(j1, nr)], 2));
        }
        dead
    }

    /// The next edge of the left half counter-clockwise around the origin of `e` that the
    /// merge has not deleted, as a half-edge out of it; `None` from `stop` (the left end's
    /// edge to the previous left end: past it come the new triangles) or at the vertex at
    /// infinity (past a hull edge: the same).
    fn next_out(&self, e: u32, stop: u32) -> Option<u32> {
        if e == stop {
            return None;
        }
        let mut e = e;
        loop {
            e = self.mesh.halfedges[prev(e) as usize];
            if self.mesh.triangles[next(e) as usize] == GHOST {
                return None;
            }
            if e == stop || !self.deleted.contains(&e) {
                return Some(e);
            }
        }
    }

    /// The next edge of the right half clockwise around the destination of `e` that the
    /// merge has not deleted, as a half-edge into it; `None` as for [`Seam::next_out`].
    fn next_into(&self, e: u32, stop: u32) -> Option<u32> {
        if e == stop {
            return None;
        }
        let mut e = e;
        loop {
            e = self.mesh.halfedges[next(e) as usize];
            if self.mesh.triangles[e as usize] == GHOST {
                return None;
            }
            if e == stop || !self.deleted.contains(&e) {
                return Some(e);
            }
        }
    }

    /// The first edge counter-clockwise around the origin of `open` after it that the merge
    /// has not deleted, as a half-edge out of it: the next left candidate when the base's
    /// left end moves along `open`'s edge. Passes the vertex at infinity (a hull vertex's
    /// outside); `open` itself if every other edge is deleted.
    fn first_out(&self, open: u32) -> u32 {
        let mut e = open;
        loop {
            e = self.mesh.halfedges[prev(e) as usize];
            if e == open
                || (self.mesh.triangles[next(e) as usize] != GHOST && !self.deleted.contains(&e))
            {
                return e;
            }
        }
    }

    /// The first edge clockwise around the destination of `open` after it that the merge
    /// has not deleted, as a half-edge into it: the next right candidate, as
    /// [`Seam::first_out`].
    fn first_into(&self, open: u32) -> u32 {
        let mut e = open;
        loop {
            e = self.mesh.halfedges[next(e) as usize];
            if e == open || (self.mesh.triangles[e as usize] != GHOST && !self.deleted.contains(&e))
            {
                return e;
            }
        }
    }

    /// Deletes the edge of half-edge `e` (both its half-edges).
    fn delete(&mut self, e: u32) {
        self.deleted.insert(e);
        self.deleted.insert(self.mesh.halfedges[e as usize]);
    }

    /// Ring positions of a common tangent's ends, the lower one for `Clockwise` and the
    /// upper one for `CounterClockwise`: from the left hull's lexicographically last vertex
    /// and the right hull's first, step along either hull while its next vertex that way is
    /// strictly on that side of the line through the two. With collinear points on the
    /// tangent, the innermost two.
    fn tangent(
        &mut self,
        left_ring: &[u32],
        right_ring: &[u32],
        side: Orientation,
    ) -> (usize, usize) {
        let (nl, nr) = (left_ring.len(), right_ring.len());
        let extreme = |s: &Self, ring: &[u32], want: Ordering| {
            (1..ring.len()).fold(0, |best, i| {
                let (p, q) = (s.point(s.origin(ring[i])), s.point(s.origin(ring[best])));
                if cmp_lex(p, q) == want {
                    i
                } else {
                    best
                }
            })
        };
        let mut i = extreme(self, left_ring, Ordering::Greater);
        let mut j = extreme(self, right_ring, Ordering::Less);
        let lower = side == Orientation::Clockwise;
        loop {
            let (l, r) = (self.origin(left_ring[i]), self.origin(right_ring[j]));
            let i_next = if lower { before(i, nl) } else { (i + 1) % nl };
            if self.orient(l, r, self.origin(left_ring[i_next])) == side {
                i = i_next;
                continue;
            }
            let j_next = if lower { (j + 1) % nr } else { before(j, nr) };
            if self.orient(l, r, self.origin(right_ring[j_next])) == side {
                j = j_next;
                continue;
            }
            return (i, j);
        }
    }

    /// The origin of ghost `g`'s hull edge: ghost (x, y, G) lies beyond hull edge y -> x.
    fn origin(&self, g: u32) -> u32 {
        self.mesh.triangles[self.ghost_edge(g, 1) as usize]
    }

    /// The half-edge `k` places after the real edge of ghost `g`: 0 the real edge x -> y,
    /// 1 the edge y -> G, 2 the edge G -> x.
    fn ghost_edge(&self, g: u32, k: usize) -> u32 {
        let real = ghost_real_edge(&self.mesh.triangles, g);
        3 * g + ((real + k) % 3) as u32
    }

    /// The real triangle's half-edge of ghost `g`'s hull edge.
    fn real_twin(&self, g: u32) -> u32 {
        self.mesh.halfedges[self.ghost_edge(g, 0) as usize]
    }

    fn point(&self, v: u32) -> Point2 {
        self.mesh.points[v as usize]
    }

    /// Whether `c` is a point strictly left of the base line l -> r (a candidate from a
    /// ghost outside the seam is the vertex at infinity: never).
    fn above(&mut self, l: u32, r: u32, c: u32) -> bool {
        c != GHOST && self.orient(l, r, c) == Orientation::CounterClockwise
    }

    fn orient(&mut self, a: u32, b: u32, c: u32) -> Orientation {
        let (pa, pb, pc) = (self.point(a), self.point(b), self.point(c));
        self.filter.orient2d_with(pa, pb, pc, self.counter)
    }

    /// Whether `d` is strictly inside the circle through l, r, c (counter-clockwise).
    fn inside(&mut self, l: u32, r: u32, c: u32, d: u32) -> bool {
        let (pl, pr, pc, pd) = (self.point(l), self.point(r), self.point(c), self.point(d));
        self.filter.incircle_with(pl, pr, pc, pd, self.counter) == InCircle::Inside
    }

    /// Appends a triangle, its links to be set; returns its id.
    fn push(&mut self, vertices: [u32; 3]) -> u32 {
        let t = (self.mesh.triangles.len() / 3) as u32;
        self.mesh.triangles.extend_from_slice(&vertices);
        self.mesh.halfedges.extend_from_slice(&[u32::MAX; 3]);
        t
    }

    fn link(&mut self, a: u32, b: u32) {
        self.mesh.halfedges[a as usize] = b;
        self.mesh.halfedges[b as usize] = a;
    }
}

/// The position before `i` in a ring of `len`.
fn before(i: usize, len: usize) -> usize {
    if i == 0 {
        len - 1
    } else {
        i - 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::delaunay::{check_delaunay, Triangulation};
    use crate::gen::{points, PointKind, Rng};
    use crate::geometry::PointSet;

    /// The split build of `pts` (whatever their number) and the whole one, as
    /// triangulations, when both halves have triangles (so the two were stitched).
    fn both_builds(pts: &[Point2]) -> Option<(Triangulation, Triangulation)> {
        let set = PointSet::new(pts).expect("finite points");
        let bounds = curve_bounds(&set, set.bounding_box());
        let filter = BoxPredicates::for_set(&set);
        let (left, right) = split_input(&set);
        build(&set, half_order(&set, left, bounds), filter, &mut NoCount)?;
        build(&set, half_order(&set, right, bounds), filter, &mut NoCount)?;
        let done = |g: Ghosted| g.finish().into_triangulation(&set);
        let split = build_split(&set, filter, &mut NoCount).map(done)?;
        let whole = build(&set, brio_order(&set, bounds), filter, &mut NoCount).map(done)?;
        Some((split, whole))
    }

    /// Triangles as sorted vertex triples, sorted.
    fn triangle_set(t: &Triangulation) -> Vec<[usize; 3]> {
        let mut out: Vec<[usize; 3]> = t
            .triangles
            .chunks(3)
            .map(|c| {
                let mut c = [c[0], c[1], c[2]];
                c.sort_unstable();
                c
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// The stitched halves are a Delaunay triangulation (the exact checker) of every kind of
    /// input, with the whole build's hull, duplicates and triangle count; in general
    /// position (no four cocircular points) they are the whole build's triangles.
    #[test]
    fn split_builds_are_delaunay_and_match_the_whole_build() {
        let mut stitched = 0;
        for kind in PointKind::ALL {
            for (n, seed) in [
                (6, 1),
                (7, 2),
                (12, 3),
                (40, 4),
                (101, 5),
                (500, 6),
                (3000, 7),
            ] {
                let pts = points(kind, n, seed).expect("a generator's points");
                let Some((split, whole)) = both_builds(&pts) else {
                    continue;
                };
                let what = format!("{kind}, n = {n}");
                assert_eq!(check_delaunay(&pts, &split), Ok(()), "{what}");
                assert_eq!(split.hull, whole.hull, "{what}");
                assert_eq!(split.duplicates, whole.duplicates, "{what}");
                assert_eq!(split.triangles.len(), whole.triangles.len(), "{what}");
                if matches!(kind, PointKind::UniformSquare | PointKind::Gaussian) {
                    assert_eq!(triangle_set(&split), triangle_set(&whole), "{what}");
                }
                stitched += 1;
            }
        }
        assert!(stitched > 50, "only {stitched} inputs stitched");
    }

    const CASES: usize = 10000;

    /// Random small integer sets (many duplicates, collinear and cocircular points, halves
    /// of three points, tangents meeting at one vertex) against the exact checker.
    #[test]
    fn split_builds_of_small_integer_sets_are_delaunay() {
        let mut rng = Rng::new(0x5EA4);
        let mut stitched = 0;
        for case in 0..CASES {
            let n = 6 + rng.below(40) as usize;
            let width = 2 + rng.below(12);
            let height = 1 + rng.below(12);
            let pts: Vec<Point2> = (0..n)
                .map(|_| Point2::new(rng.below(width) as f64, rng.below(height) as f64))
                .collect();
            let Some((split, whole)) = both_builds(&pts) else {
                continue;
            };
            assert_eq!(check_delaunay(&pts, &split), Ok(()), "case {case}: {pts:?}");
            assert_eq!(split.hull, whole.hull, "case {case}");
            assert_eq!(split.duplicates, whole.duplicates, "case {case}");
            assert_eq!(split.triangles.len(), whole.triangles.len(), "case {case}");
            stitched += 1;
        }
        assert!(stitched > CASES / 2, "only {stitched} of {CASES} stitched");
    }
}
