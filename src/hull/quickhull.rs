//! Quickhull: split by the farthest point from each hull edge, recursively.

use super::collinear::finish;
use super::lex::lex_min;
use super::HullOptions;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "hull",
    name: "quickhull",
    function: "hull::quickhull",
    file: "src/hull/quickhull.rs",
    summary: "divide by the farthest point from each edge",
    time: "O(nh) worst case, O(n log n) expected",
    space: "O(n)",
    operation: Some(Operation::OrientationTests),
    counts: "",
    source: "[RD, §2.2]",
    claims: &[on(
        "uniform-disk",
        Bound::NLogN,
        Operation::OrientationTests,
    )],
};

/// The convex hull of `points` by Quickhull. See [`quickhull_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{quickhull, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(quickhull(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn quickhull(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    Ok(quickhull_with(
        &PointSet::new(points)?,
        options,
        &mut NoCount,
    ))
}

/// The convex hull of `points` by Quickhull, recording its operations in `counter`.
///
/// Idea: the lexicographically smallest and largest points `a`, `b` are vertices; the
/// points strictly right of `a -> b` hold the lower chain, those strictly left the upper.
/// For an edge `a -> b` with points strictly to its right, the farthest of them, `c`, is a
/// vertex (of equally far points the lexicographically smallest: an end of their segment);
/// points inside triangle `a b c` are dropped and the rest split between `a -> c` and
/// `c -> b`. "Farther" is [`cross_sign`](crate::geometry::cross_sign) of the edge against
/// the difference of the two points, exact. Runs on an explicit stack: no recursion depth
/// to overflow when h = n.
///
/// Not in the course; the peer crate `geo` uses it for its `ConvexHull`.
///
/// Output convention and degenerate inputs: see the [module docs](super). `keep_collinear`
/// inserts the boundary points afterwards.
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and h the number of hull vertices: time O(nh) worst case, O(n log n)
/// expected on random input (O(n²) on points in convex position with unbalanced splits);
/// auxiliary space O(n).
///
/// # Counts
///
/// Orientation tests: n to split at `a -> b`, then per vertex found one per remaining point
/// of its subproblem for the farthest search (counted as the signed-area test it is) and two
/// per point to split; comparisons: 2(n − 1) for the two ends.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{quickhull_with, HullOptions};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.2)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// assert_eq!(quickhull_with(&set, HullOptions::default(), &mut counts), [0, 1, 2]);
/// assert!(counts.orientation_tests > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn quickhull_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    let points = points.points();
    if points.is_empty() {
        return Vec::new();
    }
    let a = lex_min(points, counter);
    let mut b = a;
    for i in 0..points.len() {
        if counter.cmp_lex(points[i], points[b]) == Ordering::Greater {
            b = i;
        }
    }
    if b == a {
        return finish(points, 0..points.len(), vec![a], options, counter);
    }
    let (pa, pb) = (points[a], points[b]);
    let (mut below, mut above) = (Vec::new(), Vec::new());
    for (i, &p) in points.iter().enumerate() {
        match counter.orient2d(pa, pb, p) {
            Orientation::Clockwise => below.push(i),
            Orientation::CounterClockwise => above.push(i),
            Orientation::Collinear => {}
        }
    }
    let mut hull = Vec::new();
    let mut tasks = vec![
        Task::Side(b, a, above),
        Task::Emit(b),
        Task::Side(a, b, below),
        Task::Emit(a),
    ];
    while let Some(task) = tasks.pop() {
        match task {
            Task::Emit(i) => hull.push(i),
            Task::Side(_, _, set) if set.is_empty() => {}
            Task::Side(a, b, set) => {
                let c = farthest(points, a, b, &set, counter);
                let (pa, pb, pc) = (points[a], points[b], points[c]);
                let (mut first, mut second) = (Vec::new(), Vec::new());
                for i in set {
                    if counter.orient2d(pa, pc, points[i]) == Orientation::Clockwise {
                        first.push(i);
                    } else if counter.orient2d(pc, pb, points[i]) == Orientation::Clockwise {
                        second.push(i);
                    }
                }
                tasks.push(Task::Side(c, b, second));
                tasks.push(Task::Emit(c));
                tasks.push(Task::Side(a, c, first));
            }
        }
    }
    finish(points, 0..points.len(), hull, options, counter)
}

/// Work on the explicit stack: find the vertices right of an edge, or output one.
enum Task {
    Side(usize, usize, Vec<usize>),
    Emit(usize),
}

/// The point of `set` (non-empty, all strictly right of `a -> b`) farthest from the line
/// `a b`; of equally far points the lexicographically smallest, then the smallest index.
fn farthest<C: Counter>(
    points: &[Point2],
    a: usize,
    b: usize,
    set: &[usize],
    counter: &mut C,
) -> usize {
    let (pa, pb) = (points[a], points[b]);
    let mut best = set[0];
    for &q in &set[1..] {
        let better = match counter.cross_sign(pa, pb, points[best], points[q]) {
            Orientation::Clockwise => true,
            Orientation::CounterClockwise => false,
            Orientation::Collinear => {
                counter
                    .cmp_lex(points[q], points[best])
                    .then_with(|| q.cmp(&best))
                    == Ordering::Less
            }
        };
        if better {
            best = q;
        }
    }
    best
}
