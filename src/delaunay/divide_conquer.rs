//! The course's divide-and-conquer Delaunay triangulation, with Guibas and Stolfi's merge.

use super::quad_edge::{Edge, Mesh};
use super::{Triangulation, EMPTY};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::lex_sort::{lex_key, sorted_items_with};
use crate::geometry::{CountedPredicates, InCircle, Orientation, Point2, PointSet};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "delaunay",
    name: "divide-and-conquer",
    function: "delaunay::divide_and_conquer",
    file: "src/delaunay/divide_conquer.rs",
    summary: "the course's divide and conquer with Guibas and Stolfi's merge",
    time: "O(n log n) in the worst case",
    space: "O(n)",
    operation: Some(Operation::IncircleTests),
    counts: "about 29 in-circle tests per point at 10⁵ uniform points",
    source: "[RD, §2.4]",
    claims: &[
        on("uniform-square", Bound::NLogN, Operation::IncircleTests),
        on("parabola", Bound::NLogN, Operation::IncircleTests),
    ],
};

/// The Delaunay triangulation of `points` by divide and conquer. See
/// [`divide_and_conquer_with`].
///
/// ```
/// use compgeo::delaunay::divide_and_conquer;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (1.0, 1.0)].map(Point2::from);
/// let t = divide_and_conquer(&pts)?;
/// assert_eq!(t.triangles.len() / 3, 4);
/// assert_eq!(t.hull, [0, 1, 2, 3]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn divide_and_conquer(points: &[Point2]) -> Result<Triangulation> {
    divide_and_conquer_with(&PointSet::new(points)?, &mut NoCount)
}

/// The Delaunay triangulation of `points` by divide and conquer, recording its operations
/// in `counter`.
///
/// Idea: sort the points lexicographically and merge duplicates. Split the sorted points
/// into a left and a right half of (nearly) equal size, triangulate each half recursively
/// (two points are an edge, three a triangle or a path), and merge: walk the two halves'
/// hulls from their facing extreme points down to the lower common tangent, which is the
/// first cross edge (the "base line"). Then climb: the next cross edge joins an endpoint of
/// the base line to the best candidate of either side, the one whose circle through the base
/// line is empty; candidate edges of a half whose circle holds the next candidate of the
/// same half are not Delaunay any more and are deleted first. The climb stops when neither
/// side has a candidate above the base line, which is then the upper common tangent.
/// The working structure is the primal half of Guibas and Stolfi's quad-edge
/// structure (half-edge rings around each vertex).
///
/// Follows [RD, §2.4] "Algoritmos", 1. "Divide y vencerás" (steps
/// 1–4, on the dual: the merge step builds the Delaunay edges that cross the dividing
/// chain σ), with the merge of Guibas and Stolfi (1985), which the course's reference
/// (Preparata and Shamos, pp. 205–214) describes for the Voronoi diagram.
///
/// Every decision is an exact [`orient2d`](crate::geometry::orient2d) or
/// [`incircle`](crate::geometry::incircle), so the result is a valid Delaunay triangulation
/// for every finite input: duplicates are merged (reported in `duplicates`, the smallest
/// index kept), collinear input gives no triangles and the hull as the sorted distinct
/// points, and among cocircular points (grids, lattice circles) one valid triangulation is
/// chosen (an edge is deleted, and the right candidate preferred, only when a point is
/// strictly inside the circle in question).
/// The ordering of the lexicographic sort stands in for a vertical split line, so points
/// with equal x need no special case.
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or infinite coordinate;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `points` has more than
/// [`MAX_TRIANGULATION_POINTS`](crate::limits::MAX_TRIANGULATION_POINTS) = 2^29 points (the
/// working structure indexes its half-edges with `u32`).
///
/// # Complexity
///
/// With n = `points.len()`: time O(n log n) in the worst case (the sort, and O(m) work per
/// merge of m points at each of log2 n levels); auxiliary space O(n). With [`NoCount`] the
/// sort is a radix sort from 384 points up (the same order; 2 to 11 % faster overall).
///
/// # Counts
///
/// Comparisons of the lexicographic sort (O(n log n)) and of the duplicate merge (n − 1);
/// orientation tests of the tangent walks and of the candidates' validity; in-circle tests
/// of the candidate deletions and choices. Both test counts are O(n log n) in the worst
/// case. On uniform input the vertical cuts make thin strips whose merges are as long as
/// the strips are tall, so the counts keep their log n factor: about 29 in-circle and 19
/// orientation tests per point at n = 10^5, 36 and 23 at n = 10^6.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::delaunay::divide_and_conquer_with;
/// use compgeo::geometry::{Point2, PointSet};
///
/// // A 3 x 3 grid: every unit square is cocircular, any diagonal is valid.
/// let pts: Vec<Point2> = (0..9).map(|i| Point2::new((i % 3) as f64, (i / 3) as f64)).collect();
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// let t = divide_and_conquer_with(&set, &mut counts)?;
/// assert_eq!(t.triangles.len() / 3, 8);
/// assert!(counts.incircle_tests > 0 && counts.orientation_tests > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn divide_and_conquer_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<Triangulation> {
    crate::limits::TRIANGULATION_POINTS.check(points.len() as u128)?;
    let (sorted, index, duplicates) = sorted_distinct(points, counter);
    let m = sorted.len();
    if m < 3 {
        return Ok(Triangulation {
            triangles: Vec::new(),
            halfedges: Vec::new(),
            hull: index,
            duplicates,
        });
    }
    let mut builder = Builder {
        mesh: Mesh::with_capacity(3 * m),
        points: &sorted,
        counter,
    };
    let (ldo, _) = builder.triangulate(0, m);
    let mesh = builder.mesh;
    Ok(extract(&mesh, ldo, index, duplicates))
}

/// The recursion's state: the mesh over positions in `points` (sorted, distinct).
struct Builder<'a, C> {
    mesh: Mesh,
    points: &'a [Point2],
    counter: &'a mut C,
}

impl<C: Counter> Builder<'_, C> {
    /// Triangulates the points `lo..hi` (at least two) and returns `(le, re)`: `le` the
    /// counter-clockwise hull edge out of the first (leftmost) point, `re` the clockwise hull
    /// edge out of the last (rightmost) one.
    fn triangulate(&mut self, lo: usize, hi: usize) -> (Edge, Edge) {
        let n = hi - lo;
        let (s0, s1) = (lo as u32, lo as u32 + 1);
        if n == 2 {
            let a = self.mesh.make_edge(s0, s1);
            return (a, Mesh::sym(a));
        }
        if n == 3 {
            let s2 = s1 + 1;
            let a = self.mesh.make_edge(s0, s1);
            let b = self.mesh.make_edge(s1, s2);
            self.mesh.splice(Mesh::sym(a), b);
            return match self.orient(s0, s1, s2) {
                Orientation::CounterClockwise => {
                    self.mesh.connect(b, a);
                    (a, Mesh::sym(b))
                }
                Orientation::Clockwise => {
                    let c = self.mesh.connect(b, a);
                    (Mesh::sym(c), c)
                }
                Orientation::Collinear => (a, Mesh::sym(b)),
            };
        }
        let mid = lo + n / 2;
        let (mut ldo, mut ldi) = self.triangulate(lo, mid);
        let (mut rdi, mut rdo) = self.triangulate(mid, hi);

        // The lower common tangent. The strict tests stop at the innermost points when
        // several lie on the tangent line, so the base line crosses no point.
        loop {
            if self.left_of(self.mesh.org(rdi), ldi) {
                ldi = self.mesh.lnext(ldi);
            } else if self.right_of(self.mesh.org(ldi), rdi) {
                rdi = self.mesh.rprev(rdi);
            } else {
                break;
            }
        }
        let mut basel = self.mesh.connect(Mesh::sym(rdi), ldi);
        if self.mesh.org(ldi) == self.mesh.org(ldo) {
            ldo = Mesh::sym(basel);
        }
        if self.mesh.org(rdi) == self.mesh.org(rdo) {
            rdo = basel;
        }

        loop {
            // A deletion only happens when the next candidate is strictly inside the circle,
            // so strictly above the base line (see `in_basel_circle`): a valid candidate
            // stays valid and needs no second test.
            let mut lcand = self.mesh.onext(Mesh::sym(basel));
            let left_ok = self.valid(lcand, basel);
            if left_ok {
                loop {
                    let next = self.mesh.onext(lcand);
                    // Back at the base line: its own endpoint is on the circle, and the
                    // exact stage would be needed to say so.
                    if next == Mesh::sym(basel)
                        || !self.in_basel_circle(basel, self.mesh.dest(lcand), self.mesh.dest(next))
                    {
                        break;
                    }
                    self.mesh.delete_edge(lcand);
                    lcand = next;
                }
            }
            let mut rcand = self.mesh.oprev(basel);
            let right_ok = self.valid(rcand, basel);
            if right_ok {
                loop {
                    let next = self.mesh.oprev(rcand);
                    if next == basel
                        || !self.in_basel_circle(basel, self.mesh.dest(rcand), self.mesh.dest(next))
                    {
                        break;
                    }
                    self.mesh.delete_edge(rcand);
                    rcand = next;
                }
            }
            if !left_ok && !right_ok {
                break;
            }
            let take_right = !left_ok
                || (right_ok && {
                    let (a, b) = (self.mesh.dest(lcand), self.mesh.org(lcand));
                    let (c, d) = (self.mesh.org(rcand), self.mesh.dest(rcand));
                    self.incircle(a, b, c, d) == InCircle::Inside
                });
            basel = if take_right {
                self.mesh.connect(rcand, Mesh::sym(basel))
            } else {
                self.mesh.connect(Mesh::sym(basel), Mesh::sym(lcand))
            };
        }
        (ldo, rdo)
    }

    fn orient(&mut self, a: u32, b: u32, c: u32) -> Orientation {
        let p = self.points;
        self.counter
            .orient2d(p[a as usize], p[b as usize], p[c as usize])
    }

    fn incircle(&mut self, a: u32, b: u32, c: u32, d: u32) -> InCircle {
        let p = self.points;
        self.counter
            .incircle(p[a as usize], p[b as usize], p[c as usize], p[d as usize])
    }

    /// Whether vertex `x` is strictly left of the directed edge `e`.
    fn left_of(&mut self, x: u32, e: Edge) -> bool {
        let (a, b) = (self.mesh.org(e), self.mesh.dest(e));
        self.orient(a, b, x) == Orientation::CounterClockwise
    }

    /// Whether vertex `x` is strictly right of the directed edge `e`.
    fn right_of(&mut self, x: u32, e: Edge) -> bool {
        let (a, b) = (self.mesh.org(e), self.mesh.dest(e));
        self.orient(a, b, x) == Orientation::Clockwise
    }

    /// Whether candidate `e` (leaving an endpoint of the base line) ends strictly above the
    /// base line, i.e. right of the base line's direction (right to left).
    fn valid(&mut self, e: Edge, basel: Edge) -> bool {
        self.right_of(self.mesh.dest(e), basel)
    }

    /// Whether `y` is strictly inside the circle through the base line's endpoints and `x`
    /// (a valid candidate's end, so the three are counter-clockwise). A `y` below the base
    /// line is never strictly inside: the triangle under the base line has an empty circle
    /// that holds this circle's lower part.
    fn in_basel_circle(&mut self, basel: Edge, x: u32, y: u32) -> bool {
        let (a, b) = (self.mesh.dest(basel), self.mesh.org(basel));
        self.incircle(a, b, x, y) == InCircle::Inside
    }
}

/// The points sorted lexicographically without repeats, the input index of each (the
/// smallest among equal points), and the duplicates as `[dropped, kept]` sorted by
/// `dropped`.
pub(super) fn sorted_distinct<C: Counter>(
    points: &[Point2],
    counter: &mut C,
) -> (Vec<Point2>, Vec<usize>, Vec<[usize; 2]>) {
    // One comparison per comparison of two items, as sorting them by cmp_lex and index;
    // a radix sort with NoCount (see crate::geometry::lex_sort).
    let items = sorted_items_with(points, 0..points.len(), lex_key, counter);
    let mut sorted = Vec::with_capacity(items.len());
    let mut index = Vec::with_capacity(items.len());
    let mut duplicates = Vec::new();
    for (p, i) in items {
        if let Some(&last) = sorted.last() {
            if counter.cmp_lex(last, p) == Ordering::Equal {
                duplicates.push([i, *index.last().expect("index follows sorted")]);
                continue;
            }
        }
        sorted.push(p);
        index.push(i);
    }
    duplicates.sort_unstable();
    (sorted, index, duplicates)
}

/// Turns the finished mesh into the shared arrays. `ldo` is the counter-clockwise hull edge
/// out of the first sorted point; its right face is the outer face, every other face is a
/// counter-clockwise triangle (the merge triangulates everything it encloses). `index` maps
/// sorted positions to input indices.
fn extract(
    mesh: &Mesh,
    ldo: Edge,
    index: Vec<usize>,
    duplicates: Vec<[usize; 2]>,
) -> Triangulation {
    const OUTER: u32 = u32::MAX - 1;
    const UNSEEN: u32 = u32::MAX;
    // slot[e]: the position of half-edge e in `triangles`, or OUTER.
    let mut slot = vec![UNSEEN; mesh.slots()];
    let mut hull = Vec::new();
    let outer = Mesh::sym(ldo);
    let mut e = outer;
    loop {
        slot[e as usize] = OUTER;
        hull.push(index[mesh.org(e) as usize]);
        e = mesh.lnext(e);
        if e == outer {
            break;
        }
    }
    let mut triangles = Vec::with_capacity(2 * index.len() * 3);
    for e in 0..mesh.slots() as Edge {
        if slot[e as usize] != UNSEEN || !mesh.is_live(e) {
            continue;
        }
        let f = mesh.lnext(e);
        let g = mesh.lnext(f);
        debug_assert_eq!(mesh.lnext(g), e, "a bounded face is not a triangle");
        for h in [e, f, g] {
            slot[h as usize] = triangles.len() as u32;
            triangles.push(index[mesh.org(h) as usize]);
        }
    }
    let mut halfedges = vec![EMPTY; triangles.len()];
    for e in 0..mesh.slots() as Edge {
        let s = slot[e as usize];
        if s < OUTER {
            let t = slot[Mesh::sym(e) as usize];
            if t < OUTER {
                halfedges[s as usize] = t as usize;
            }
        }
    }
    if triangles.is_empty() {
        // All points on one line: the hull is the sorted distinct points.
        hull = index;
    } else {
        // The outer face runs clockwise from the second hull vertex; reverse it so that it
        // runs counter-clockwise from the first sorted point.
        hull.rotate_left(1);
        hull.reverse();
        hull.rotate_right(1);
    }
    Triangulation {
        triangles,
        halfedges,
        hull,
        duplicates,
    }
}
