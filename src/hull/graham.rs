//! Graham's scan: sort by angle about the lexicographically smallest point, then keep only left
//! turns.

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
    name: "graham",
    function: "hull::graham_scan",
    file: "src/hull/graham.rs",
    summary: "angular sort about the lexicographically smallest point, then the scan",
    time: "O(n log n)",
    space: "O(n)",
    operation: Some(Operation::OrientationTests),
    counts: "at most 2n − 4 in the scan after the sort",
    source: "[RD, §2.2]",
    claims: &[
        on("uniform-disk", Bound::NLogN, Operation::OrientationTests),
        on("cocircular", Bound::NLogN, Operation::OrientationTests),
    ],
};

/// A step of Graham's scan, as [`graham_trace`] records it. Indices are into the input.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum GrahamStep {
    /// The angular sort is done: the pivot (the lexicographically smallest point) followed by
    /// the farthest point of every direction from it, counter-clockwise.
    Sorted {
        /// The pivot, then one point per direction in angular order.
        order: Vec<usize>,
    },
    /// `point` was pushed on the stack.
    Push {
        /// The pushed point.
        point: usize,
        /// The stack after the push, bottom first.
        stack: Vec<usize>,
    },
    /// `point` was popped: it and the top of the stack below it do not turn strictly left
    /// towards the next point of the order.
    Pop {
        /// The popped point.
        point: usize,
        /// The stack after the pop, bottom first.
        stack: Vec<usize>,
    },
    /// The scan is over: the result of [`graham_scan`] (with the boundary points inserted if
    /// the options ask for them).
    Done {
        /// The hull, as [`graham_scan`] returns it.
        hull: Vec<usize>,
    },
}

impl TraceSize for GrahamStep {
    fn entries(&self) -> usize {
        match self {
            GrahamStep::Sorted { order: v } | GrahamStep::Done { hull: v } => v.len(),
            GrahamStep::Push { stack, .. } | GrahamStep::Pop { stack, .. } => 1 + stack.len(),
        }
    }
}

/// The convex hull of `points` by Graham's scan. See [`graham_scan_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{graham_scan, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(graham_scan(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn graham_scan(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    Ok(graham_scan_with(
        &PointSet::new(points)?,
        options,
        &mut NoCount,
    ))
}

/// The convex hull of `points` by Graham's scan, recording its operations in `counter`.
///
/// Idea: the pivot v₁ is the lexicographically smallest point (the course's "abscisa mínima,
/// then ordenada mínima"). Every other point lies in the half-plane right of the vertical
/// through v₁, within an angle below π, so "`a` comes before `b`" is exactly
/// `orient2d(v₁, a, b)` = counter-clockwise: the angular sort needs no angles. Of several
/// points in one direction only the farthest is kept (the course's note for collinear input;
/// [`cmp_dist`](crate::geometry::cmp_dist) decides). The scan then pushes the points in
/// order, first popping every point that does not turn strictly left.
///
/// Follows [RD, §2.2] "Scan de Graham" (steps 1–4 and the "Nota").
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
/// With n = `points.len()`: time O(n log n) (the sort), the scan O(n); auxiliary space O(n).
///
/// # Counts
///
/// Orientation tests: those of the angular sort, O(n log n), the n − 2 that merge equal
/// directions, and at most 2m − 4 ≤ 2n − 4 in the scan (m − 1 directions), the course's bound:
/// every test either pops a point or ends a push. Distance evaluations: one per tie of the
/// sort. Comparisons: 2(n − 1) to find the pivot and drop its duplicates.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{graham_scan_with, HullOptions};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.2)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// assert_eq!(graham_scan_with(&set, HullOptions::default(), &mut counts), [0, 1, 2]);
/// assert!(counts.orientation_tests > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn graham_scan_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    graham(points.points(), options, counter, &mut NoObserver)
}

/// The frames of Graham's scan on `points`: its own run, step by step.
///
/// The run is [`graham_scan_with`]'s, told about each step: [`GrahamStep::Sorted`] after the
/// angular sort, then one [`GrahamStep::Push`] per point of that order and one
/// [`GrahamStep::Pop`] per point the scan removes, each with the stack after it (the
/// course's step 4), and last [`GrahamStep::Done`] with the hull [`graham_scan`] returns.
/// Each frame carries the operations counted so far; the last frame's are those of
/// [`graham_scan_with`] with [`Counts`](crate::count::Counts).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the frames
/// would hold more than [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES) entries.
///
/// # Complexity
///
/// O(n log n) for the scan plus the frames: at most 2n of up to n indices, O(n²) time and
/// space.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{graham_trace, GrahamStep, HullOptions};
///
/// // 3 lies inside the triangle 0, 1, 2: pushed, then popped when 2 comes.
/// let pts = [(0.0, 0.0), (4.0, 0.0), (0.0, 4.0), (2.0, 1.0)].map(Point2::from);
/// let steps: Vec<GrahamStep> = graham_trace(&pts, HullOptions::default())?
///     .into_iter()
///     .map(|f| f.step)
///     .collect();
/// assert_eq!(steps, [
///     GrahamStep::Sorted { order: vec![0, 1, 3, 2] },
///     GrahamStep::Push { point: 0, stack: vec![0] },
///     GrahamStep::Push { point: 1, stack: vec![0, 1] },
///     GrahamStep::Push { point: 3, stack: vec![0, 1, 3] },
///     GrahamStep::Pop { point: 3, stack: vec![0, 1] },
///     GrahamStep::Push { point: 2, stack: vec![0, 1, 2] },
///     GrahamStep::Done { hull: vec![0, 1, 2] },
/// ]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn graham_trace(points: &[Point2], options: HullOptions) -> Result<Vec<Frame<GrahamStep>>> {
    let points = PointSet::new(points)?;
    record(|counts, recorder| {
        let hull = graham(points.points(), options, counts, recorder);
        Ok(GrahamStep::Done { hull })
    })
}

/// The scan, telling `obs` about each step.
fn graham<C: Counter, O: Observer<GrahamStep, C>>(
    points: &[Point2],
    options: HullOptions,
    counter: &mut C,
    obs: &mut O,
) -> Vec<usize> {
    if points.is_empty() {
        return Vec::new();
    }
    let order = angular_order(points, counter);
    obs.step(counter, || GrahamStep::Sorted {
        order: order.clone(),
    });
    let strict = scan(points, &order, counter, obs);
    finish(points, 0..points.len(), strict, options, counter)
}

/// The pivot followed by the farthest point of every direction from it, in angular order.
fn angular_order<C: Counter>(points: &[Point2], counter: &mut C) -> Vec<usize> {
    let pivot = lex_min(points, counter);
    let o = points[pivot];
    let mut rest: Vec<usize> = (0..points.len())
        .filter(|&i| counter.cmp_lex(points[i], o) != Ordering::Equal)
        .collect();
    rest.sort_unstable_by(|&a, &b| match counter.orient2d(o, points[a], points[b]) {
        Orientation::CounterClockwise => Ordering::Less,
        Orientation::Clockwise => Ordering::Greater,
        // Farthest first, then smallest index: the first of a direction is the one kept.
        Orientation::Collinear => counter
            .cmp_dist(o, points[b], o, points[a])
            .then_with(|| a.cmp(&b)),
    });
    let mut order = Vec::with_capacity(rest.len() + 1);
    order.push(pivot);
    for i in rest {
        let last = order[order.len() - 1];
        if order.len() > 1 && counter.orient2d(o, points[last], points[i]) == Orientation::Collinear
        {
            continue;
        }
        order.push(i);
    }
    order
}

/// The course's step 4 over `order` (pivot first, then one point per direction in angular
/// order): the strictly convex hull.
fn scan<C: Counter, O: Observer<GrahamStep, C>>(
    points: &[Point2],
    order: &[usize],
    counter: &mut C,
    obs: &mut O,
) -> Vec<usize> {
    let mut stack: Vec<usize> = Vec::with_capacity(order.len());
    for &i in order.iter().take(2) {
        stack.push(i);
        obs.step(counter, || GrahamStep::Push {
            point: i,
            stack: stack.clone(),
        });
    }
    for &i in order.iter().skip(2) {
        push_left_turn(
            &mut stack,
            2,
            i,
            |k| points[k],
            counter,
            |moved, stack, counter| {
                obs.step(counter, || match moved {
                    Move::Push(point) => GrahamStep::Push {
                        point,
                        stack: stack.to_vec(),
                    },
                    Move::Pop(point) => GrahamStep::Pop {
                        point,
                        stack: stack.to_vec(),
                    },
                })
            },
        );
    }
    stack
}

/// What [`push_left_turn`] did to its stack.
pub(super) enum Move<T> {
    /// Pushed this item.
    Push(T),
    /// Popped this item.
    Pop(T),
}

/// Pops from `stack` while it holds at least `floor` items and the points (`point`) of its
/// last two do not turn strictly left towards `item`'s, then pushes `item`; `watch` sees
/// each pop and the push with the stack after it (a trace's observer, or nothing).
#[inline]
pub(super) fn push_left_turn<T: Copy, C: Counter>(
    stack: &mut Vec<T>,
    floor: usize,
    item: T,
    point: impl Fn(T) -> Point2,
    counter: &mut C,
    mut watch: impl FnMut(Move<T>, &[T], &C),
) {
    let p = point(item);
    while stack.len() >= floor {
        let (a, b) = (stack[stack.len() - 2], stack[stack.len() - 1]);
        if counter.orient2d(point(a), point(b), p) == Orientation::CounterClockwise {
            break;
        }
        stack.pop();
        watch(Move::Pop(b), stack, counter);
    }
    stack.push(item);
    watch(Move::Push(item), stack, counter);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;
    use crate::gen::{points as generate, PointKind};

    /// The course's bound: the scan after sorting makes at most 2n − 4 orientation tests.
    #[test]
    fn the_scan_makes_at_most_2n_minus_4_orientation_tests() {
        for kind in PointKind::ALL {
            for (n, seed) in [(3, 1), (10, 2), (100, 3), (1000, 4)] {
                let pts = generate(kind, n, seed).unwrap();
                let order = angular_order(&pts, &mut NoCount);
                let mut counts = Counts::default();
                let hull = scan(&pts, &order, &mut counts, &mut NoObserver);
                assert!(
                    counts.orientation_tests <= (2 * n).saturating_sub(4) as u64,
                    "{kind} n={n}: {} tests",
                    counts.orientation_tests
                );
                assert!(super::super::check_strictly_convex_ccw(&pts, &hull).is_ok());
            }
        }
    }

    /// Points in convex position in angular order are all kept: every test ends a push, so
    /// the scan makes exactly n − 2 tests, and a zig-zag that pops often stays within 2n − 4.
    #[test]
    fn the_bound_is_tight_in_shape() {
        let convex: Vec<Point2> = (0..20)
            .map(|i| Point2::new(f64::from(i), f64::from(i * i)))
            .collect();
        let order = angular_order(&convex, &mut NoCount);
        let mut counts = Counts::default();
        assert_eq!(
            scan(&convex, &order, &mut counts, &mut NoObserver).len(),
            20
        );
        assert_eq!(counts.orientation_tests, 18);

        // Alternating near/far points on a fan: every second point is popped.
        let fan: Vec<Point2> = (0..40)
            .map(|i| {
                let r = if i % 2 == 0 { 4.0 } else { 1.0 };
                let t = f64::from(i) / 40.0;
                Point2::new(r * (1.0 + t), r * t)
            })
            .chain([Point2::new(0.0, 0.0)])
            .collect();
        let order = angular_order(&fan, &mut NoCount);
        let mut counts = Counts::default();
        let hull = scan(&fan, &order, &mut counts, &mut NoObserver);
        assert!(counts.orientation_tests <= 2 * 41 - 4);
        assert!(counts.orientation_tests > 41, "pops happened");
        assert!(super::super::check_strictly_convex_ccw(&fan, &hull).is_ok());
    }
}
