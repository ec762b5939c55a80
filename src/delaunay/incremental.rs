//! The fast builder: incremental insertion in a spatial order, with a walk to locate each
//! point and Lawson flips to restore the Delaunay property.

use super::hilbert::{brio_order, curve_bounds};
use super::partition::{build_split, SPLIT_MIN};
use super::triangulation::{find_duplicates, rotate_to_lex_min, Triangulation, EMPTY};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{BoxPredicates, CountedPredicates, InCircle, Orientation, Point2, PointSet};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "delaunay",
    name: "incremental",
    function: "delaunay::incremental",
    file: "src/delaunay/incremental.rs",
    summary: "BRIO + Hilbert order, walking location, Lawson flips",
    time: "O(n log n) expected on every input",
    space: "O(n)",
    operation: Some(Operation::IncircleTests),
    counts: "about 9 in-circle and 7 orientation tests per point on uniform input",
    source: "[RD, §2.4]",
    claims: &[
        on("uniform-square", Bound::NLogN, Operation::IncircleTests),
        on("clustered", Bound::NLogN, Operation::IncircleTests),
        on("grid", Bound::NLogN, Operation::IncircleTests),
        on("parabola", Bound::NLogN, Operation::IncircleTests),
    ],
};

/// The Delaunay triangulation of `points` by incremental insertion (Lawson's flips), the
/// crate's fast builder.
///
/// The idea: keep a Delaunay triangulation of the points inserted so far and add the
/// others one at a time. A walk from the previous point's triangle finds the triangle that
/// holds the new point; it is split into three (or, on an edge, the two neighbours into
/// four); then every edge opposite the new point whose far vertex sees it inside its
/// circumcircle is flipped, the two new edges opposite it are tested in turn, and so on.
/// Points outside the current hull use the same code: the hull's outside is covered by
/// "ghost" triangles with a vertex at infinity, whose circumcircle is the open half-plane
/// beyond their hull edge (an orientation test). The insertion order is a biased
/// randomized order (BRIO) sorted along a Hilbert curve in each round, so the walks are
/// short and the expected number of flips is O(n) on every input. Every test is exact; what
/// the whole set allows is worked out once (the orientation and in-circle filters' error
/// bounds for the bounding box the point set recorded, and plain floating point for
/// small-integer sets, where it is exact), and
/// the conversion to the 64-bit result frees the builder's 32-bit arrays as it goes.
///
/// From 2^19 points the set is split by a vertical line (lexicographically, at the median
/// of a random sample), each half is triangulated this way, and the two are merged along
/// the seam by Guibas and Stolfi's merge (the divide and conquer's), run on the builder's
/// own arrays. With the `parallel` feature the halves are built on two threads (measured:
/// 1.8 to 1.9 times faster on 2 cores at 10^6 and 10^7 points); the split never depends on
/// the threads, so the triangulation is the same with and without the feature.
///
/// It computes the triangulation the course defines ([RD, §2.4]
/// "Triangulación de Delaunay", Definition 2.34 and Theorem 2.35) without building the
/// Voronoi diagram; the course's own construction is the divide and conquer.
///
/// Degenerate input follows the [module conventions](super): duplicates are merged and
/// reported, collinear input and fewer than three distinct points give no triangles, and
/// cocircular points get one of their valid triangulations.
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or infinite coordinate;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) for more than
/// [`MAX_TRIANGULATION_POINTS`](crate::limits::MAX_TRIANGULATION_POINTS) = 2^29 points (the
/// builder stores 32-bit indices).
///
/// # Complexity
/// For n points, O(n log n) expected on every input: O(n log n) for the order (sorts of 64-bit keys); O(n) expected flips and
/// in-circle tests on every input, because each BRIO round is a random sample (Amenta, Choi
/// and Rote); the walks take O(1) steps per point on uniform-like input after the Hilbert
/// sort and are not bounded in the worst case (measured: O(log n) steps per point on points
/// on a parabola, so O(n log n) there). From 2^19 points, the split is O(n) and the merge
/// O(n) in the worst case (about √n tests on uniform input). O(n) auxiliary space.
///
/// # Counts
/// Orientation tests (the walk, the hull side of ghost triangles) and in-circle tests (the
/// flips); see [`incremental_with`].
///
/// ```
/// use compgeo::delaunay::{check_delaunay, incremental};
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (1.0, 1.0), (4.0, 0.0)]
///     .map(Point2::from);
/// let t = incremental(&pts)?;
/// assert_eq!(t.triangle_count(), 4); // 2n - 2 - h with n = 5 distinct points, h = 4
/// assert_eq!(t.hull, [0, 1, 2, 3]);
/// assert_eq!(t.duplicates, [[5, 1]]);
/// assert!(check_delaunay(&pts, &t).is_ok());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn incremental(points: &[Point2]) -> Result<Triangulation> {
    incremental_with(&PointSet::new(points)?, &mut NoCount)
}

/// [`incremental`], recording its orientation tests and in-circle tests in `counter`.
///
/// # Errors
/// As [`incremental`].
///
/// # Complexity
/// As [`incremental`]. Measured on uniform input: about 7 orientation tests and 9 in-circle
/// tests per point, at every size from 10^3 to 10^6.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::delaunay::incremental_with;
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::PointSet;
///
/// let pts = points(PointKind::UniformSquare, 1000, 1)?;
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// let t = incremental_with(&set, &mut counts)?;
/// assert!(counts.incircle_tests > 0 && counts.incircle_tests < 20 * 1000);
/// assert_eq!(t.triangle_count(), 2 * 1000 - 2 - t.hull.len());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn incremental_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<Triangulation> {
    Ok(match incremental_local(points, counter)? {
        Some(local) => local.into_triangulation(points),
        None => degenerate(points),
    })
}

/// The builder's triangulation in its own vertex numbering: vertex `j` is `points[j]`, the
/// `j`-th point inserted. [`voronoi`](super::voronoi) builds the dual from this directly,
/// with no renumbered copy: the 32-bit arrays are half the memory of a [`Triangulation`]'s.
pub(super) struct LocalTriangulation {
    /// The input points in insertion order.
    pub(super) points: Vec<Point2>,
    /// The input index of each vertex; for the vertex kept from a group of equal points,
    /// the smallest input index of the group.
    pub(super) order: Vec<u32>,
    /// Three vertex ids per triangle, counter-clockwise.
    pub(super) triangles: Vec<u32>,
    /// The opposite of every half-edge, [`NO_TWIN`] on the hull.
    pub(super) halfedges: Vec<u32>,
    /// `[dropped, kept]` input indices, as [`Triangulation::duplicates`].
    pub(super) duplicates: Vec<[usize; 2]>,
    /// The hull's boundary as vertex ids, counter-clockwise.
    hull: Vec<u32>,
}

/// [`LocalTriangulation::halfedges`] of a hull half-edge.
pub(super) const NO_TWIN: u32 = u32::MAX;

/// [`incremental_with`] up to the renumbering: the triangulation in insertion order, or
/// `None` if the points have no three non-collinear ones (see [`degenerate`]).
pub(super) fn incremental_local<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<Option<LocalTriangulation>> {
    crate::limits::TRIANGULATION_POINTS.check(points.len() as u128)?;
    let filter = BoxPredicates::for_set(points);
    let built = if points.len() >= SPLIT_MIN {
        build_split(points, filter, counter)
    } else {
        build(
            points,
            brio_order(points, curve_bounds(points, points.bounding_box())),
            filter,
            counter,
        )
    };
    let Some(built) = built else {
        return Ok(None);
    };
    let t = built.finish();
    // The cheap postcondition; tests run the full exact checker.
    debug_assert!(t
        .halfedges
        .iter()
        .enumerate()
        .all(|(e, &f)| f == NO_TWIN || t.halfedges[f as usize] == e as u32));
    Ok(Some(t))
}

/// The ghost mesh of the points `order` lists, inserted in that order; `None` if they have
/// no three non-collinear points.
pub(super) fn build<C: Counter>(
    points: &[Point2],
    mut order: Vec<u32>,
    filter: BoxPredicates,
    counter: &mut C,
) -> Option<Ghosted> {
    let first = first_triangle(points, &mut order, counter)?;
    let local: Vec<Point2> = order.iter().map(|&i| points[i as usize]).collect();
    let size = mesh_size(local.len());
    let mut triangles = vec![0; size];
    let mut halfedges = vec![0; size];
    let part = insert_all(
        &local,
        first,
        &mut triangles,
        &mut halfedges,
        filter,
        counter,
    );
    triangles.truncate(part.len);
    halfedges.truncate(part.len);
    Some(Ghosted {
        points: local,
        order,
        triangles,
        halfedges,
        duplicates: part.duplicates,
    })
}

/// The array entries of the ghost mesh of `n` points: 3 per triangle, 2n - 2 triangles.
///
/// With the ghosts, n vertices and the vertex at infinity triangulate a sphere: exactly
/// 2 (n + 1) - 4 = 2n - 2 triangles once every point is in (fewer if some are merged
/// duplicates), so the arrays never grow.
pub(super) fn mesh_size(n: usize) -> usize {
    3 * (2 * n).saturating_sub(2)
}

/// What [`insert_all`] filled: the entries in use and the merged duplicates.
pub(super) struct Part {
    /// The entries of the arrays in use, from the start.
    pub(super) len: usize,
    /// `[dropped vertex id, kept vertex id]`.
    pub(super) duplicates: Vec<[u32; 2]>,
}

/// The ghost mesh of `points` (vertex `j` is `points[j]`) by inserting them in order, from
/// the counter-clockwise triangle `first` of vertices 0, 1 and 2, written into `triangles`
/// and `halfedges` (at least [`mesh_size`] entries each).
pub(super) fn insert_all<C: Counter>(
    points: &[Point2],
    first: [u32; 3],
    triangles: &mut [u32],
    halfedges: &mut [u32],
    filter: BoxPredicates,
    counter: &mut C,
) -> Part {
    let mut mesh = Mesh::new(points, first, triangles, halfedges, filter, counter);
    for k in 3..points.len() as u32 {
        mesh.insert(k);
    }
    Part {
        len: mesh.len,
        duplicates: mesh.duplicates,
    }
}

/// The triangulation of points with no three non-collinear ones: no triangles.
pub(super) fn degenerate(points: &PointSet<'_>) -> Triangulation {
    Triangulation::without_triangles(points, find_duplicates(points))
}

impl LocalTriangulation {
    /// Renumbers the vertices with their input indices.
    ///
    /// At 10^7 points this step sets the builder's peak memory, so it frees as it goes: the
    /// point copies first, then each 32-bit array while its 64-bit replacement fills (see
    /// [`widen`]).
    pub(super) fn into_triangulation(self, points: &[Point2]) -> Triangulation {
        let LocalTriangulation {
            points: local,
            order,
            triangles,
            halfedges,
            duplicates,
            hull,
        } = self;
        drop(local);
        let mut hull: Vec<usize> = hull.iter().map(|&v| order[v as usize] as usize).collect();
        rotate_to_lex_min(points, &mut hull);
        let triangles = widen(triangles, |v| order[v as usize] as usize);
        drop(order);
        let halfedges = widen(halfedges, |f| if f == NO_TWIN { EMPTY } else { f as usize });
        Triangulation {
            triangles,
            halfedges,
            hull,
            duplicates,
        }
    }
}

/// Slices of [`widen`]: 2^18 entries, one megabyte of the 32-bit source.
const WIDEN_SLICE: usize = 1 << 18;

/// `source` mapped entry by entry into a 64-bit array, releasing the source from its end one
/// slice at a time. The result is allocated zeroed, and a large zeroed allocation takes no
/// memory until written, so the two arrays are never both resident in full: the peak is
/// about the larger of them (the 64-bit one), not their sum.
fn widen(mut source: Vec<u32>, map: impl Fn(u32) -> usize + Sync) -> Vec<usize> {
    if source.len() <= WIDEN_SLICE {
        return source.iter().map(|&x| map(x)).collect();
    }
    let mut out = vec![0usize; source.len()];
    while !source.is_empty() {
        let end = source.len();
        let start = end.saturating_sub(WIDEN_SLICE);
        widen_slice(&mut out[start..end], &source[start..], &map);
        source.truncate(start);
        source.shrink_to_fit();
    }
    out
}

/// One slice of [`widen`]: on every thread with the `parallel` feature (the writes are
/// most of the conversion's time at 10^7 points).
fn widen_slice(out: &mut [usize], source: &[u32], map: &(impl Fn(u32) -> usize + Sync)) {
    #[cfg(feature = "parallel")]
    if crate::parallel::enabled(source.len()) {
        use rayon::prelude::*;
        out.par_iter_mut()
            .zip(source)
            .for_each(|(o, &x)| *o = map(x));
        return;
    }
    for (o, &x) in out.iter_mut().zip(source) {
        *o = map(x);
    }
}

/// The seed of the walk's coin flips (any fixed non-zero value).
const WALK_SEED: u32 = 0x0DE1_A0A7;

/// The vertex at infinity of the ghost triangles.
pub(super) const GHOST: u32 = u32::MAX;

/// Where the walk ended.
enum Location {
    /// Strictly inside this real triangle.
    Inside(u32),
    /// In the interior of this half-edge of a real triangle.
    OnEdge(u32),
    /// Strictly beyond the hull edge of this ghost triangle.
    Outside(u32),
    /// Equal to this vertex.
    Vertex(u32),
}

/// The triangulation under construction: a closed surface of real and ghost triangles, so
/// every half-edge has an opposite.
struct Mesh<'a, 'c, C> {
    /// The points in insertion order; vertex ids index this.
    points: &'a [Point2],
    /// Three vertex ids per triangle, counter-clockwise; [`GHOST`] for the vertex at infinity.
    triangles: &'a mut [u32],
    /// The opposite of every half-edge.
    halfedges: &'a mut [u32],
    /// The entries of `triangles` and `halfedges` in use.
    len: usize,
    /// Triangles whose edge opposite the new point (at position 0) awaits its flip test.
    stack: Vec<u32>,
    /// A triangle that had the last inserted point as a vertex: the walk starts there.
    last: u32,
    /// The state of the walk's coin flips (a 32-bit xorshift: the walk needs only to not
    /// follow a fixed rule, not good randomness).
    coin: u32,
    /// The orientation and in-circle filters' bounds for the points' bounding box.
    filter: BoxPredicates,
    /// `[dropped vertex id, kept vertex id]`.
    duplicates: Vec<[u32; 2]>,
    counter: &'c mut C,
}

impl<'a, 'c, C: Counter> Mesh<'a, 'c, C> {
    /// The triangle of the first three vertices (ids 0, 1, 2, counter-clockwise) and its three
    /// ghosts.
    fn new(
        points: &'a [Point2],
        [a, b, c]: [u32; 3],
        triangles: &'a mut [u32],
        halfedges: &'a mut [u32],
        filter: BoxPredicates,
        counter: &'c mut C,
    ) -> Self {
        // Real (a, b, c); ghosts (b, a, G), (c, b, G), (a, c, G) beyond a->b, b->c, c->a.
        triangles[..12].copy_from_slice(&[a, b, c, b, a, GHOST, c, b, GHOST, a, c, GHOST]);
        halfedges[..12].copy_from_slice(&[3, 6, 9, 0, 11, 7, 1, 5, 10, 2, 8, 4]);
        Mesh {
            points,
            triangles,
            halfedges,
            len: 12,
            stack: Vec::with_capacity(64),
            last: 0,
            coin: WALK_SEED,
            filter,
            duplicates: Vec::new(),
            counter,
        }
    }

    /// Inserts vertex `v` (a point not inserted yet) and restores the Delaunay property.
    fn insert(&mut self, v: u32) {
        let p = self.points[v as usize];
        match self.locate(p) {
            Location::Vertex(kept) => {
                self.duplicates.push([v, kept]);
                return;
            }
            Location::Inside(t) | Location::Outside(t) => self.split_triangle(t, v),
            Location::OnEdge(e) => self.split_edge(e, v),
        }
        self.legalize(v);
    }

    #[inline(always)]
    fn point(&self, v: u32) -> Point2 {
        self.points[v as usize]
    }

    #[inline(always)]
    fn is_ghost(&self, t: u32) -> bool {
        is_ghost(self.triangles, t)
    }

    /// A visibility walk from `self.last`: cross an edge that has `p` strictly on its far side
    /// (trying the edges in a random order, so the walk cannot cycle) until none has.
    ///
    /// After the first triangle the walk enters each triangle through an edge that has `p`
    /// strictly inside, so only the other two edges are tested, and they share the one new
    /// vertex: each step loads one vertex and one point and makes at most two orientation
    /// tests.
    fn locate(&mut self, p: Point2) -> Location {
        let mut t = self.last;
        if self.is_ghost(t) {
            t = self.halfedges[3 * t as usize + self.ghost_real_edge(t)] / 3;
        }
        let mut e = match self.first_crossing(t, p) {
            Ok(e) => e,
            Err(found) => return found,
        };
        // `e` = a -> b has `p` strictly on its right, and `pa`, `pb` are its ends.
        let mut pa = self.point(self.triangles[e as usize]);
        let mut pb = self.point(self.triangles[next(e) as usize]);
        loop {
            // The triangle across is (b, a, c): edges f = b -> a (`p` strictly inside),
            // next(f) = a -> c and prev(f) = c -> b.
            let f = self.halfedges[e as usize];
            let c = self.triangles[prev(f) as usize];
            if c == GHOST {
                return Location::Outside(f / 3);
            }
            let pc = self.point(c);
            let (to_c, from_c);
            if self.coin_bit() {
                to_c = self.filter.orient2d_with(pa, pc, p, self.counter);
                if to_c == Orientation::Clockwise {
                    (e, pb) = (next(f), pc);
                    continue;
                }
                from_c = self.filter.orient2d_with(pc, pb, p, self.counter);
                if from_c == Orientation::Clockwise {
                    (e, pa) = (prev(f), pc);
                    continue;
                }
            } else {
                from_c = self.filter.orient2d_with(pc, pb, p, self.counter);
                if from_c == Orientation::Clockwise {
                    (e, pa) = (prev(f), pc);
                    continue;
                }
                to_c = self.filter.orient2d_with(pa, pc, p, self.counter);
                if to_c == Orientation::Clockwise {
                    (e, pb) = (next(f), pc);
                    continue;
                }
            }
            // `p` is strictly inside b -> a, so it is neither a nor b: on one of the other
            // edges it is in that edge's interior, on both it is c.
            return match (to_c, from_c) {
                (Orientation::Collinear, Orientation::Collinear) => Location::Vertex(c),
                (Orientation::Collinear, _) => Location::OnEdge(next(f)),
                (_, Orientation::Collinear) => Location::OnEdge(prev(f)),
                _ => Location::Inside(f / 3),
            };
        }
    }

    /// The first edge of real triangle `t` (from a random one) that has `p` strictly on its
    /// far side, or where `p` is in `t` if no edge has.
    fn first_crossing(&mut self, t: u32, p: Point2) -> std::result::Result<u32, Location> {
        let base = 3 * t;
        let start = self.flip3();
        let mut collinear = 0u32;
        for k in 0..3 {
            let e = base + (start + k) % 3;
            let a = self.triangles[e as usize];
            let b = self.triangles[next(e) as usize];
            match self
                .filter
                .orient2d_with(self.point(a), self.point(b), p, self.counter)
            {
                Orientation::Clockwise => return Ok(e),
                Orientation::Collinear => collinear = collinear * 4 + 1 + e - base,
                Orientation::CounterClockwise => {}
            }
        }
        // At most one collinear edge unless `p` is a vertex; `collinear` encodes it as
        // 1 + its position.
        if collinear == 0 {
            return Err(Location::Inside(t));
        }
        for e in base..base + 3 {
            let v = self.triangles[e as usize];
            if self.point(v) == p {
                return Err(Location::Vertex(v));
            }
        }
        Err(Location::OnEdge(base + collinear - 1))
    }

    /// A pseudo-random choice between two (the top bit of the next xorshift state).
    #[inline(always)]
    fn coin_bit(&mut self) -> bool {
        let mut x = self.coin;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.coin = x;
        x >> 31 == 1
    }

    /// A pseudo-random edge position, 0, 1 or 2 (the high bits of the next xorshift state,
    /// scaled to three).
    #[inline(always)]
    fn flip3(&mut self) -> u32 {
        let mut x = self.coin;
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        self.coin = x;
        ((u64::from(x) * 3) >> 32) as u32
    }

    fn ghost_real_edge(&self, t: u32) -> usize {
        ghost_real_edge(self.triangles, t)
    }

    /// Splits triangle `t` = (a, b, c) into (v, a, b), (v, b, c), (v, c, a).
    fn split_triangle(&mut self, t: u32, v: u32) {
        let b0 = 3 * t as usize;
        let [a, b, c] = [
            self.triangles[b0],
            self.triangles[b0 + 1],
            self.triangles[b0 + 2],
        ];
        let [ha, hb, hc] = [
            self.halfedges[b0],
            self.halfedges[b0 + 1],
            self.halfedges[b0 + 2],
        ];
        let t1 = (self.len / 3) as u32;
        let t2 = t1 + 1;
        let (e0, e1, e2) = (3 * t, 3 * t1, 3 * t2);
        self.set(t, [v, a, b], [e2 + 2, ha, e1]);
        self.push(t1, [v, b, c], [e0 + 2, hb, e2]);
        self.push(t2, [v, c, a], [e1 + 2, hc, e0]);
        self.halfedges[ha as usize] = e0 + 1;
        self.halfedges[hb as usize] = e1 + 1;
        self.halfedges[hc as usize] = e2 + 1;
        self.stack.extend_from_slice(&[t, t1, t2]);
        self.last = t;
    }

    /// Splits the two triangles of half-edge `e` = u -> v, with `p` in its interior:
    /// (u, v, w) and (v, u, x) become (p, v, w), (p, w, u), (p, u, x), (p, x, v).
    fn split_edge(&mut self, e: u32, p: u32) {
        let f = self.halfedges[e as usize];
        let (ta, tc) = (e / 3, f / 3);
        let u = self.triangles[e as usize];
        let v = self.triangles[next(e) as usize];
        let w = self.triangles[prev(e) as usize];
        let x = self.triangles[prev(f) as usize];
        let h_vw = self.halfedges[next(e) as usize];
        let h_wu = self.halfedges[prev(e) as usize];
        let h_ux = self.halfedges[next(f) as usize];
        let h_xv = self.halfedges[prev(f) as usize];
        let tb = (self.len / 3) as u32;
        let td = tb + 1;
        let (a, b, c, d) = (3 * ta, 3 * tb, 3 * tc, 3 * td);
        self.set(ta, [p, v, w], [d + 2, h_vw, b]);
        self.push(tb, [p, w, u], [a + 2, h_wu, c]);
        self.set(tc, [p, u, x], [b + 2, h_ux, d]);
        self.push(td, [p, x, v], [c + 2, h_xv, a]);
        self.halfedges[h_vw as usize] = a + 1;
        self.halfedges[h_wu as usize] = b + 1;
        self.halfedges[h_ux as usize] = c + 1;
        self.halfedges[h_xv as usize] = d + 1;
        self.stack.extend_from_slice(&[ta, tb, tc, td]);
        self.last = ta;
    }

    /// Lawson's flips: every stacked triangle (p, u, v) has the new point `p` at position 0;
    /// if `p` conflicts with the triangle across u -> v, that edge flips to p -> w.
    fn legalize(&mut self, p: u32) {
        let pp = self.point(p);
        while let Some(t1) = self.stack.pop() {
            let b1 = 3 * t1;
            let e = b1 + 1;
            let f = self.halfedges[e as usize];
            let u = self.triangles[e as usize];
            let v = self.triangles[b1 as usize + 2];
            let w = self.triangles[prev(f) as usize];
            if !self.conflicts(u, v, w, pp) {
                continue;
            }
            // (p, u, v) and (v, u, w) become (p, u, w) and (p, w, v).
            let t2 = f / 3;
            let b2 = 3 * t2;
            let h_uw = self.halfedges[next(f) as usize];
            let h_wv = self.halfedges[prev(f) as usize];
            let h_vp = self.halfedges[b1 as usize + 2];
            self.triangles[e as usize] = u;
            self.triangles[b1 as usize + 2] = w;
            self.halfedges[e as usize] = h_uw;
            self.halfedges[b1 as usize + 2] = b2;
            self.set(t2, [p, w, v], [b1 + 2, h_wv, h_vp]);
            self.halfedges[h_uw as usize] = e;
            self.halfedges[h_wv as usize] = b2 + 1;
            self.halfedges[h_vp as usize] = b2 + 2;
            self.stack.push(t1);
            self.stack.push(t2);
        }
    }

    /// Whether `p`, at the apex of a triangle (p, u, v), conflicts with the triangle
    /// (v, u, w) across u -> v: for a real one, `p` strictly inside its circumcircle; for a
    /// ghost, `p` strictly beyond its hull edge. A ghost across a real triangle's edge never
    /// conflicts: `p` is strictly inside that edge's half-plane.
    #[inline]
    fn conflicts(&mut self, u: u32, v: u32, w: u32, p: Point2) -> bool {
        if u == GHOST {
            // Ghost (w, v, G): hull edge v -> w.
            let (pv, pw) = (self.point(v), self.point(w));
            self.filter.orient2d_with(pv, pw, p, self.counter) == Orientation::Clockwise
        } else if v == GHOST {
            // Ghost (u, w, G): hull edge w -> u.
            let (pw, pu) = (self.point(w), self.point(u));
            self.filter.orient2d_with(pw, pu, p, self.counter) == Orientation::Clockwise
        } else if w == GHOST {
            false
        } else {
            let (pv, pu, pw) = (self.point(v), self.point(u), self.point(w));
            self.filter.incircle_with(pv, pu, pw, p, self.counter) == InCircle::Inside
        }
    }

    /// Overwrites triangle `t`.
    #[inline(always)]
    fn set(&mut self, t: u32, vertices: [u32; 3], opposite: [u32; 3]) {
        let b = 3 * t as usize;
        self.triangles[b..b + 3].copy_from_slice(&vertices);
        self.halfedges[b..b + 3].copy_from_slice(&opposite);
    }

    /// Appends triangle `t` (the next free id).
    #[inline(always)]
    fn push(&mut self, t: u32, vertices: [u32; 3], opposite: [u32; 3]) {
        debug_assert_eq!(self.len, 3 * t as usize);
        let b = self.len;
        self.triangles[b..b + 3].copy_from_slice(&vertices);
        self.halfedges[b..b + 3].copy_from_slice(&opposite);
        self.len += 3;
    }
}

/// A finished ghost mesh: the triangulation of its points with the ghost triangles that
/// close it into a sphere, before [`Ghosted::finish`] drops them.
pub(super) struct Ghosted {
    /// The points in insertion order; vertex ids index this.
    pub(super) points: Vec<Point2>,
    /// The input index of each vertex.
    pub(super) order: Vec<u32>,
    /// Three vertex ids per triangle, counter-clockwise; [`GHOST`] for the vertex at infinity.
    pub(super) triangles: Vec<u32>,
    /// The opposite of every half-edge.
    pub(super) halfedges: Vec<u32>,
    /// `[dropped vertex id, kept vertex id]`.
    pub(super) duplicates: Vec<[u32; 2]>,
}

impl Ghosted {
    /// Drops the ghosts, reads the hull off them, and maps each kept vertex of a merged group
    /// to the smallest input index of the group.
    pub(super) fn finish(mut self) -> LocalTriangulation {
        let duplicates = self.resolve_duplicates();
        let ghosts = self.ghost_ring(0);
        let hull = ghosts
            .iter()
            .map(|&g| {
                let b = 3 * g as usize;
                self.triangles[b + (ghost_real_edge(&self.triangles, g) + 1) % 3]
            })
            .collect();
        self.compact(&ghosts);
        LocalTriangulation {
            points: self.points,
            order: self.order,
            triangles: self.triangles,
            halfedges: self.halfedges,
            duplicates,
            hull,
        }
    }

    /// The `[dropped, kept]` input indices of the merged points, sorted by `dropped`;
    /// `order` is updated so that each kept vertex maps to the smallest input index of its
    /// group (the vertex was inserted first, but a copy may come earlier in the input).
    fn resolve_duplicates(&mut self) -> Vec<[usize; 2]> {
        let order = &mut self.order;
        // (vertex, input index) for every member of every group, the vertex's own included.
        let mut members: Vec<(u32, u32)> = self
            .duplicates
            .iter()
            .flat_map(|&[d, k]| [(k, order[d as usize]), (k, order[k as usize])])
            .collect();
        members.sort_unstable();
        members.dedup();
        let mut out = Vec::with_capacity(self.duplicates.len());
        for group in members.chunk_by(|a, b| a.0 == b.0) {
            let (vertex, smallest) = group[0];
            order[vertex as usize] = smallest;
            out.extend(
                group[1..]
                    .iter()
                    .map(|&(_, i)| [i as usize, smallest as usize]),
            );
        }
        out.sort_unstable();
        out
    }

    /// The ghost triangles in hull order, from the first ghost at or after triangle `start`:
    /// ghost (x, y, G) lies beyond hull edge y -> x, and the opposite of its half-edge G -> x
    /// is in the ghost of the next hull edge x -> z.
    pub(super) fn ghost_ring(&self, start: u32) -> Vec<u32> {
        let count = (self.triangles.len() / 3) as u32;
        let first = (start..count)
            .find(|&t| is_ghost(&self.triangles, t))
            .expect("a triangulation with triangles has ghosts");
        let mut ring = vec![first];
        loop {
            let g = *ring.last().expect("the ring starts non-empty");
            let b = 3 * g as usize;
            let next = self.halfedges[b + (ghost_real_edge(&self.triangles, g) + 2) % 3] / 3;
            if next == first {
                return ring;
            }
            ring.push(next);
        }
    }

    /// Removes the ghosts in O(h) moves: real triangles' links to ghosts become [`NO_TWIN`],
    /// then the ghosts' slots are filled (see [`Ghosted::fill_holes`]).
    fn compact(&mut self, ghosts: &[u32]) {
        for &g in ghosts {
            let r = 3 * g as usize + ghost_real_edge(&self.triangles, g);
            let twin = self.halfedges[r] as usize;
            self.halfedges[twin] = NO_TWIN;
        }
        self.fill_holes(ghosts, is_ghost);
    }

    /// Removes the triangles `holes` (distinct ids, none linked from a kept triangle) in
    /// O(|holes|) moves: kept triangles from the tail fill the holes below the kept count,
    /// and their neighbours' links follow them. `is_hole` tells the holes in the tail apart.
    pub(super) fn fill_holes(&mut self, holes: &[u32], is_hole: impl Fn(&[u32], u32) -> bool) {
        let count = self.triangles.len() / 3;
        let kept = count - holes.len();
        let mut below = holes.iter().filter(|&&h| (h as usize) < kept);
        for t in kept..count {
            if is_hole(&self.triangles, t as u32) {
                continue;
            }
            let hole = *below
                .next()
                .expect("as many holes below as kept triangles above")
                as usize;
            for k in 0..3 {
                let (from, to) = (3 * t + k, 3 * hole + k);
                self.triangles[to] = self.triangles[from];
                let f = self.halfedges[from];
                self.halfedges[to] = f;
                if f != NO_TWIN {
                    self.halfedges[f as usize] = to as u32;
                }
            }
        }
        self.triangles.truncate(3 * kept);
        self.halfedges.truncate(3 * kept);
    }
}

/// Whether triangle `t` has the vertex at infinity.
#[inline(always)]
pub(super) fn is_ghost(triangles: &[u32], t: u32) -> bool {
    let b = 3 * t as usize;
    triangles[b] == GHOST || triangles[b + 1] == GHOST || triangles[b + 2] == GHOST
}

/// The position (0, 1 or 2) of the half-edge of ghost `t` that joins two real vertices.
pub(super) fn ghost_real_edge(triangles: &[u32], t: u32) -> usize {
    let b = 3 * t as usize;
    let g = (0..3).find(|&k| triangles[b + k] == GHOST).unwrap_or(0);
    (g + 1) % 3
}

#[inline(always)]
pub(super) fn next(e: u32) -> u32 {
    if e % 3 == 2 {
        e - 2
    } else {
        e + 1
    }
}

#[inline(always)]
pub(super) fn prev(e: u32) -> u32 {
    if e % 3 == 0 {
        e + 2
    } else {
        e - 1
    }
}

/// Moves three points that form a triangle to the front of `order` (counter-clockwise) and
/// returns them as vertex ids `[0, 1, 2]` in counter-clockwise order; `None` if there are no
/// three non-collinear points.
pub(super) fn first_triangle<C: Counter>(
    points: &[Point2],
    order: &mut [u32],
    counter: &mut C,
) -> Option<[u32; 3]> {
    if order.len() < 3 {
        return None;
    }
    let at = |order: &[u32], k: usize| points[order[k] as usize];
    let a = at(order, 0);
    let ib = (1..order.len()).find(|&k| at(order, k) != a)?;
    order.swap(1, ib);
    let b = at(order, 1);
    let ic = (2..order.len())
        .find(|&k| counter.orient2d(a, b, at(order, k)) != Orientation::Collinear)?;
    order.swap(2, ic);
    if counter.orient2d(a, b, at(order, 2)) == Orientation::Clockwise {
        order.swap(1, 2);
    }
    Some([0, 1, 2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widen_maps_every_entry_in_order_across_slices() {
        for len in [0, 1, WIDEN_SLICE, WIDEN_SLICE + 1, 3 * WIDEN_SLICE + 7] {
            let source: Vec<u32> = (0..len as u32)
                .map(|i| {
                    if i % 11 == 0 {
                        NO_TWIN
                    } else {
                        i.wrapping_mul(2_654_435_761)
                    }
                })
                .collect();
            let map = |x: u32| if x == NO_TWIN { EMPTY } else { x as usize + 1 };
            let expected: Vec<usize> = source.iter().map(|&x| map(x)).collect();
            assert_eq!(widen(source, map), expected, "length {len}");
        }
    }
}
