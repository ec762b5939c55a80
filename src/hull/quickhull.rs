//! Quickhull: split by the farthest point from each hull edge, recursively.

use super::collinear::finish;
use super::lex::lex_min;
use super::HullOptions;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};
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

/// A step of Quickhull, as [`quickhull_trace`] records it. Indices are into the input.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum QuickhullStep {
    /// The first split, at the lexicographically smallest point `a` and the largest `b` (two
    /// or more distinct points only).
    Ends {
        /// The lexicographically smallest point.
        a: usize,
        /// The lexicographically largest point.
        b: usize,
        /// The points strictly right of `a -> b`, in input order.
        below: Vec<usize>,
        /// The points strictly left of `a -> b`, in input order.
        above: Vec<usize>,
    },
    /// One split: of `points`, all strictly right of the directed hull edge `edge`,
    /// `farthest` is farthest from its line and becomes a hull vertex; the points inside the
    /// triangle are dropped and the rest go to the two new edges.
    Split {
        /// The edge `[a, b]`, directed with the points on its right.
        edge: [usize; 2],
        /// The points right of the edge.
        points: Vec<usize>,
        /// The farthest of them: a new hull vertex c.
        farthest: usize,
        /// The points strictly right of `a -> c`.
        first: Vec<usize>,
        /// The points strictly right of `c -> b` (and not of `a -> c`).
        second: Vec<usize>,
    },
    /// Every edge is done: the result of [`quickhull`] (with the boundary points inserted if
    /// the options ask for them).
    Done {
        /// The hull, as [`quickhull`] returns it.
        hull: Vec<usize>,
    },
}

impl TraceSize for QuickhullStep {
    fn entries(&self) -> usize {
        match self {
            QuickhullStep::Ends { below, above, .. } => 2 + below.len() + above.len(),
            QuickhullStep::Split {
                points,
                first,
                second,
                ..
            } => 3 + points.len() + first.len() + second.len(),
            QuickhullStep::Done { hull } => hull.len(),
        }
    }
}

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
    quick(points.points(), options, counter, &mut NoObserver)
}

/// The frames of Quickhull on `points`: its own run, step by step.
///
/// The run is [`quickhull_with`]'s, told about each step: [`QuickhullStep::Ends`] with the
/// first split at the extreme points, one [`QuickhullStep::Split`] per edge with points on
/// its right (the segment, the farthest point and the two surviving subsets), in the order
/// the explicit stack takes them (the lower chain first, each edge's first half before its
/// second), and last [`QuickhullStep::Done`] with the hull [`quickhull`] returns. Each frame
/// carries the operations counted so far; the last frame's are those of [`quickhull_with`]
/// with [`Counts`](crate::count::Counts).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the frames
/// would hold more than [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES) entries.
///
/// # Complexity
///
/// That of [`quickhull_with`] plus the frames, which copy each subproblem twice: O(nh) time
/// and space.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{quickhull_trace, HullOptions, QuickhullStep};
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (2.0, 3.0), (2.0, 1.0), (1.0, -1.0)].map(Point2::from);
/// let frames = quickhull_trace(&pts, HullOptions::default())?;
/// let steps: Vec<QuickhullStep> = frames.into_iter().map(|f| f.step).collect();
/// assert_eq!(steps, [
///     QuickhullStep::Ends { a: 0, b: 1, below: vec![4], above: vec![2, 3] },
///     QuickhullStep::Split {
///         edge: [0, 1], points: vec![4], farthest: 4, first: vec![], second: vec![],
///     },
///     QuickhullStep::Split {
///         edge: [1, 0], points: vec![2, 3], farthest: 2, first: vec![], second: vec![],
///     },
///     QuickhullStep::Done { hull: vec![0, 4, 1, 2] },
/// ]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn quickhull_trace(
    points: &[Point2],
    options: HullOptions,
) -> Result<Vec<Frame<QuickhullStep>>> {
    let points = PointSet::new(points)?;
    record(|counts, recorder| {
        let hull = quick(points.points(), options, counts, recorder);
        Ok(QuickhullStep::Done { hull })
    })
}

/// Quickhull, telling `obs` about each split.
fn quick<C: Counter, O: Observer<QuickhullStep, C>>(
    points: &[Point2],
    options: HullOptions,
    counter: &mut C,
    obs: &mut O,
) -> Vec<usize> {
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
    obs.step(counter, || QuickhullStep::Ends {
        a,
        b,
        below: below.clone(),
        above: above.clone(),
    });
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
                for &i in &set {
                    if counter.orient2d(pa, pc, points[i]) == Orientation::Clockwise {
                        first.push(i);
                    } else if counter.orient2d(pc, pb, points[i]) == Orientation::Clockwise {
                        second.push(i);
                    }
                }
                obs.step(counter, || QuickhullStep::Split {
                    edge: [a, b],
                    points: set.clone(),
                    farthest: c,
                    first: first.clone(),
                    second: second.clone(),
                });
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
