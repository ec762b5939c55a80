//! Naive Lawson flipping: any triangulation, then edge flips until every edge is locally
//! Delaunay. The teaching baseline whose quadratic growth the report shows.

use super::divide_conquer::sorted_distinct;
use super::{next_halfedge, prev_halfedge, Triangulation, EMPTY};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, InCircle, Orientation, Point2, PointSet};
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "delaunay",
    name: "lawson",
    function: "delaunay::lawson",
    file: "src/delaunay/lawson.rs",
    summary: "a sweep triangulation, then Lawson's flips (for teaching)",
    time: "O(n²) in the worst case",
    space: "O(n)",
    operation: Some(Operation::IncircleTests),
    counts: "one per edge check, Θ(n²) on a parabola",
    source: "[RD, §2.4]",
    claims: &[on("parabola", Bound::Quadratic, Operation::IncircleTests)],
};

/// A step of Lawson's algorithm, as [`lawson_trace`] records it. Vertices are indices into
/// the input; `triangles` lists three per triangle, counter-clockwise, in the layout of
/// [`Triangulation::triangles`] (a flip rewrites two triangles in place).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LawsonStep {
    /// The sweep triangulation the flips start from.
    Swept {
        /// Its triangles.
        triangles: Vec<usize>,
    },
    /// The edge `removed` was not locally Delaunay (the vertex across it lay strictly inside
    /// the circle through one of its triangles) and was flipped to `added`.
    Flip {
        /// The flipped edge's ends.
        removed: [usize; 2],
        /// The new edge's ends.
        added: [usize; 2],
        /// The triangles after the flip.
        triangles: Vec<usize>,
    },
    /// No edge is left to flip: the result of [`lawson`].
    Done {
        /// The triangulation, as [`lawson`] returns it.
        triangulation: Triangulation,
    },
}

impl TraceSize for LawsonStep {
    fn entries(&self) -> usize {
        match self {
            LawsonStep::Swept { triangles } | LawsonStep::Flip { triangles, .. } => triangles.len(),
            LawsonStep::Done { triangulation } => {
                triangulation.triangles.len() + triangulation.hull.len()
            }
        }
    }
}

/// The Delaunay triangulation of `points` by Lawson's flips from a sweep triangulation.
/// See [`lawson_with`].
///
/// ```
/// use compgeo::delaunay::lawson;
/// use compgeo::geometry::Point2;
///
/// // The sweep cuts the quadrilateral along 0-2, but 3 is inside the circle through
/// // 0, 1, 2: Lawson flips 0-2 to 1-3.
/// let pts = [(0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, -0.8)].map(Point2::from);
/// let t = lawson(&pts)?;
/// let mut tris: Vec<[usize; 3]> = (0..t.triangle_count()).map(|k| t.triangle(k)).collect();
/// for tri in &mut tris {
///     let m = (0..3).min_by_key(|&i| tri[i]).unwrap();
///     tri.rotate_left(m);
/// }
/// tris.sort();
/// assert_eq!(tris, [[0, 3, 1], [1, 3, 2]]); // counter-clockwise, from the smallest index
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lawson(points: &[Point2]) -> Result<Triangulation> {
    lawson_with(&PointSet::new(points)?, &mut NoCount)
}

/// The Delaunay triangulation of `points` by Lawson's flips, recording its operations in
/// `counter`.
///
/// Idea: first any triangulation. Sort the points lexicographically (merging duplicates)
/// and sweep them from left to right, keeping the lower and upper hull chains of the points
/// seen so far as in the monotone-chain hull: each new point is joined to the previous one
/// and to every chain edge it sees (it is strictly on the outer side), and those edges leave
/// the chains. This gives a triangulation of the hull with every boundary point on it.
/// Then flip: an interior edge whose opposite vertex lies strictly inside the circle through
/// the other triangle is not locally Delaunay; replacing it by the other diagonal of its
/// (then convex) quadrilateral and re-checking the four edges around it ends: lift every
/// point to (x, y, x² + y²); each flip strictly lowers the lifted surface of the
/// triangulation, so no triangulation comes back, and there are finitely many. When no edge
/// is left to flip, every edge is locally Delaunay, so the triangulation is Delaunay.
///
/// Not in the course as an algorithm: [RD, §2.4] "Triangulación" asks
/// for a triangulation and answers "Considerar la Triangulación de Delaunay"; the sweep is
/// the course's §2.2 "Scan de Graham - Variante" with the popped chain edges turned into
/// triangles, and Lawson's flips (Lawson, 1977) turn that triangulation into Delaunay's.
///
/// Degenerate input: duplicates are merged (reported in `duplicates`, the smallest index
/// kept), collinear input gives no triangles and the hull as the sorted distinct points,
/// and among cocircular points any valid triangulation is kept (only strictly non-Delaunay
/// edges are flipped). All decisions are exact predicates.
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()`: time O(n²) in the worst case (the sweep is O(n log n), but a
/// sweep triangulation can be Θ(n²) flips away from Delaunay's, e.g. for points on a
/// parabola); auxiliary space O(n).
///
/// # Counts
///
/// Comparisons of the sort and duplicate merge; orientation tests of the sweep (at most
/// about 4n); in-circle tests, one per edge check: the initial interior edges plus four per
/// flip, O(n²) in the worst case.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::delaunay::lawson_with;
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::PointSet;
///
/// let pts = points(PointKind::Parabola, 40, 0)?;
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// let t = lawson_with(&set, &mut counts)?;
/// assert_eq!(t.triangle_count(), 2 * 40 - 2 - 40);
/// assert!(counts.incircle_tests >= t.triangle_count() as u64);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lawson_with<C: Counter>(points: &PointSet<'_>, counter: &mut C) -> Result<Triangulation> {
    lawson_observed(points, counter, &mut NoObserver)
}

/// The frames of Lawson's algorithm on `points`: its own run, step by step.
///
/// The run is [`lawson_with`]'s, told about each step: [`LawsonStep::Swept`] with the sweep
/// triangulation, one [`LawsonStep::Flip`] per flip with the triangles after it, and last
/// [`LawsonStep::Done`] with the triangulation [`lawson`] returns. Each frame carries the
/// operations counted so far (the in-circle tests of the edge checks among them); the last
/// frame's are those of [`lawson_with`] with [`Counts`](crate::count::Counts).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the frames
/// would hold more than [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES) entries.
///
/// # Complexity
///
/// That of [`lawson_with`] plus O(n) per flip for the frames: O(n³) time and space in the
/// worst case (Θ(n²) flips).
///
/// ```
/// use compgeo::delaunay::{lawson, lawson_trace, LawsonStep};
/// use compgeo::geometry::Point2;
///
/// // The sweep cuts the quadrilateral along 0-2; 3 lies inside the circle through 0, 1, 2.
/// let pts = [(0.0, 0.0), (1.0, 1.0), (2.0, 1.0), (3.0, -0.8)].map(Point2::from);
/// let frames = lawson_trace(&pts)?;
/// assert_eq!(frames.len(), 3);
/// let LawsonStep::Flip { removed, added, .. } = &frames[1].step else { panic!() };
/// let (mut removed, mut added) = (*removed, *added);
/// removed.sort();
/// added.sort();
/// assert_eq!((removed, added), ([0, 2], [1, 3]));
/// assert_eq!(frames[2].step, LawsonStep::Done { triangulation: lawson(&pts)? });
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lawson_trace(points: &[Point2]) -> Result<Vec<Frame<LawsonStep>>> {
    let points = PointSet::new(points)?;
    record(|counts, recorder| {
        let triangulation = lawson_observed(&points, counts, recorder)?;
        Ok(LawsonStep::Done { triangulation })
    })
}

/// Lawson's algorithm, telling `obs` about the sweep and each flip.
fn lawson_observed<C: Counter, O: Observer<LawsonStep, C>>(
    points: &PointSet<'_>,
    counter: &mut C,
    obs: &mut O,
) -> Result<Triangulation> {
    let (sorted, index, duplicates) = sorted_distinct(points, counter);
    let (mut triangles, mut halfedges, hull) = sweep(&sorted, counter);
    obs.step(counter, || LawsonStep::Swept {
        triangles: triangles.iter().map(|&v| index[v]).collect(),
    });
    flip_until_delaunay(
        &sorted,
        &index,
        &mut triangles,
        &mut halfedges,
        counter,
        obs,
    );
    let hull = if triangles.is_empty() {
        index.clone()
    } else {
        hull.into_iter().map(|v| index[v]).collect()
    };
    for v in &mut triangles {
        *v = index[*v];
    }
    Ok(Triangulation {
        triangles,
        halfedges,
        hull,
        duplicates,
    })
}

/// A chain vertex and the half-edge, inside the triangulation, of the chain edge from this
/// vertex to the next one ([`EMPTY`] while no triangle has that edge).
#[derive(Clone, Copy)]
struct ChainVertex {
    vertex: usize,
    inner: usize,
}

/// The sweep triangulation of `p` (sorted, distinct): triangles, their half-edges and the
/// hull (lower chain then upper chain) as positions in `p`.
fn sweep<C: Counter>(p: &[Point2], counter: &mut C) -> (Vec<usize>, Vec<usize>, Vec<usize>) {
    let mut triangles = Vec::new();
    let mut halfedges = Vec::new();
    let mut lower: Vec<ChainVertex> = Vec::new();
    let mut upper: Vec<ChainVertex> = Vec::new();
    for j in 0..p.len() {
        let start = ChainVertex {
            vertex: j,
            inner: EMPTY,
        };
        if j == 0 {
            lower.push(start);
            upper.push(start);
            continue;
        }
        // While all points so far are collinear the two chains are the same path, and the
        // fan that j closes on one side is the other side's inner triangles too.
        let fan_is_shared = triangles.is_empty();
        // Upper chain: edge u -> w has its triangle below, as the half-edge w -> u. A new
        // triangle [u, w, j] takes the half-edges u -> w, w -> j, j -> u.
        let mut first_up = EMPTY; // half-edge q -> j of the first upper triangle
        let mut link = EMPTY; // half-edge j -> w of the previous upper triangle
        while upper.len() >= 2 {
            let (u, w) = (upper[upper.len() - 2], upper[upper.len() - 1]);
            if counter.orient2d(p[u.vertex], p[w.vertex], p[j]) != Orientation::CounterClockwise {
                break;
            }
            let e = add_triangle(&mut triangles, &mut halfedges, [u.vertex, w.vertex, j]);
            pair(&mut halfedges, e, u.inner);
            if fan_is_shared {
                lower[upper.len() - 2].inner = e;
            }
            if link == EMPTY {
                first_up = e + 1;
            } else {
                pair(&mut halfedges, e + 1, link);
            }
            link = e + 2;
            upper.pop();
        }
        // Lower chain: edge u -> w has its triangle above, as the half-edge u -> w. A new
        // triangle [w, u, j] takes the half-edges w -> u, u -> j, j -> w.
        let mut first_low = EMPTY; // half-edge j -> q of the first lower triangle
        let mut lower_link = EMPTY; // half-edge u -> j of the previous lower triangle
        while lower.len() >= 2 {
            let (u, w) = (lower[lower.len() - 2], lower[lower.len() - 1]);
            if counter.orient2d(p[u.vertex], p[w.vertex], p[j]) != Orientation::Clockwise {
                break;
            }
            let e = add_triangle(&mut triangles, &mut halfedges, [w.vertex, u.vertex, j]);
            pair(&mut halfedges, e, u.inner);
            if fan_is_shared {
                upper[lower.len() - 2].inner = e;
            }
            if lower_link == EMPTY {
                first_low = e + 2;
            } else {
                pair(&mut halfedges, e + 2, lower_link);
            }
            lower_link = e + 1;
            lower.pop();
        }
        // The edge from the previous point q to j, between the two fans.
        if first_up != EMPTY && first_low != EMPTY {
            pair(&mut halfedges, first_up, first_low);
        }
        upper
            .last_mut()
            .expect("chains keep their first point")
            .inner = if link != EMPTY { link } else { first_low };
        lower
            .last_mut()
            .expect("chains keep their first point")
            .inner = if lower_link != EMPTY {
            lower_link
        } else {
            first_up
        };
        upper.push(start);
        lower.push(start);
    }
    let mut hull: Vec<usize> = lower.iter().map(|c| c.vertex).collect();
    if upper.len() > 2 {
        hull.extend(upper[1..upper.len() - 1].iter().rev().map(|c| c.vertex));
    }
    (triangles, halfedges, hull)
}

/// Lawson's flips until every interior edge of the triangulation is locally Delaunay,
/// telling `obs` about each flip (with the vertices as `index` maps them to the input).
fn flip_until_delaunay<C: Counter, O: Observer<LawsonStep, C>>(
    p: &[Point2],
    index: &[usize],
    triangles: &mut [usize],
    halfedges: &mut [usize],
    counter: &mut C,
    obs: &mut O,
) {
    let mut stack: Vec<usize> = (0..triangles.len())
        .filter(|&e| halfedges[e] != EMPTY && halfedges[e] < e)
        .collect();
    while let Some(e) = stack.pop() {
        let f = halfedges[e];
        if f == EMPTY {
            continue;
        }
        // Triangle a, b, c on e = a -> b; d opposite across it.
        let (e1, e2) = (next_halfedge(e), prev_halfedge(e));
        let (f1, f2) = (next_halfedge(f), prev_halfedge(f));
        let (a, b, c, d) = (triangles[e], triangles[e1], triangles[e2], triangles[f2]);
        if counter.incircle(p[a], p[b], p[c], p[d]) != InCircle::Inside {
            continue;
        }
        // Flip a-b to d-c: [a, b, c] becomes [d, b, c] and [b, a, d] becomes [c, a, d].
        triangles[e] = d;
        triangles[f] = c;
        let (hf2, he2) = (halfedges[f2], halfedges[e2]);
        pair(halfedges, e, hf2);
        pair(halfedges, f, he2);
        pair(halfedges, e2, f2);
        obs.step(counter, || LawsonStep::Flip {
            removed: [index[a], index[b]],
            added: [index[d], index[c]],
            triangles: triangles.iter().map(|&v| index[v]).collect(),
        });
        stack.extend([e, e1, f, f1]);
    }
}

/// Appends triangle `t` with unlinked half-edges; returns its first half-edge.
fn add_triangle(triangles: &mut Vec<usize>, halfedges: &mut Vec<usize>, t: [usize; 3]) -> usize {
    let e = triangles.len();
    triangles.extend(t);
    halfedges.extend([EMPTY; 3]);
    e
}

/// Makes `a` and `b` each other's opposite; `b` may be [`EMPTY`] (then `a` is on the hull).
fn pair(halfedges: &mut [usize], a: usize, b: usize) {
    halfedges[a] = b;
    if b != EMPTY {
        halfedges[b] = a;
    }
}
