//! Jarvis's march (gift wrapping): from a hull vertex, the next one is the point every other
//! point lies to the left of.

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
    name: "jarvis",
    function: "hull::jarvis_march",
    file: "src/hull/jarvis.rs",
    summary: "gift wrapping from the lexicographically smallest point",
    time: "Θ(nh)",
    space: "O(h)",
    operation: Some(Operation::OrientationTests),
    counts: "at most n − 1 per hull vertex",
    source: "[RD, §2.2]",
    claims: &[
        on("uniform-disk", Bound::NH, Operation::OrientationTests),
        on("cocircular", Bound::NH, Operation::OrientationTests),
    ],
};

/// A step of Jarvis's march, as [`jarvis_trace`] records it. Indices are into the input.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum JarvisStep {
    /// The march starts at `vertex`, the lexicographically smallest point.
    Start {
        /// The first hull vertex.
        vertex: usize,
    },
    /// From the hull vertex `current`, the march looked at `point` (one step of the scan over
    /// all points); `best` is the candidate for the next vertex after it: `point` itself if
    /// it is the first point looked at or lies right of `current -> best`, or farther in
    /// the same direction.
    Candidate {
        /// The hull vertex the march wraps from.
        current: usize,
        /// The point looked at.
        point: usize,
        /// The best candidate so far, after looking at `point`.
        best: usize,
        /// The hull vertices found so far, `current` last.
        hull: Vec<usize>,
    },
    /// The scan from the last vertex ended at `vertex`, which joins the hull.
    Wrap {
        /// The new hull vertex.
        vertex: usize,
        /// The hull vertices found so far, `vertex` last.
        hull: Vec<usize>,
    },
    /// The march is back at the start: the result of [`jarvis_march`] (with the boundary
    /// points inserted if the options ask for them).
    Done {
        /// The hull, as [`jarvis_march`] returns it.
        hull: Vec<usize>,
    },
}

impl TraceSize for JarvisStep {
    fn entries(&self) -> usize {
        match self {
            JarvisStep::Start { .. } => 1,
            JarvisStep::Candidate { hull, .. } => 3 + hull.len(),
            JarvisStep::Wrap { hull, .. } | JarvisStep::Done { hull } => 1 + hull.len(),
        }
    }
}

/// The convex hull of `points` by Jarvis's march. See [`jarvis_march_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{jarvis_march, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(jarvis_march(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn jarvis_march(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    Ok(jarvis_march_with(
        &PointSet::new(points)?,
        options,
        &mut NoCount,
    ))
}

/// The convex hull of `points` by Jarvis's march, recording its operations in `counter`.
///
/// Idea: start at the lexicographically smallest point v₁ (a hull vertex). From vertex vᵢ,
/// scan all points keeping a candidate; a point right of `vᵢ -> candidate` replaces it
/// (the course's "smallest angle" as a signed-area test), and of points in the candidate's
/// direction the farthest wins, so collinear input yields only the extreme points. Stop when
/// the candidate is v₁ again.
///
/// Follows [RD, §2.2] "Marcha de Jarvis" (steps 0 and i, and the
/// "Observaciones" on signed areas).
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
/// With n = `points.len()` and h the number of hull vertices: time Θ(nh), output-sensitive;
/// O(n²) when every point is a vertex (points on a circle). Auxiliary space O(h).
///
/// # Counts
///
/// Per hull vertex: n comparisons (skipping copies of the current vertex) and at most n − 1
/// orientation tests, plus a distance evaluation per collinear candidate; so about h·n
/// orientation tests in all, plus n − 1 comparisons for the start.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{jarvis_march_with, HullOptions};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.2)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// assert_eq!(jarvis_march_with(&set, HullOptions::default(), &mut counts), [0, 1, 2]);
/// assert_eq!(counts.orientation_tests, 3 * 2); // h = 3 steps, n − 2 tests each
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn jarvis_march_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    jarvis(points.points(), options, counter, &mut NoObserver)
}

/// The frames of Jarvis's march on `points`: its own run, step by step.
///
/// The run is [`jarvis_march_with`]'s, told about each step: a [`JarvisStep::Start`] at the
/// lexicographically smallest point, then from each hull vertex one
/// [`JarvisStep::Candidate`] per point the scan looks at (every point but the copies of the
/// current vertex) and a [`JarvisStep::Wrap`] when the scan's winner joins the hull, and
/// last a [`JarvisStep::Done`] with the hull [`jarvis_march`] returns. Each frame carries
/// the operations counted so far; the last frame's are those of [`jarvis_march_with`] with
/// [`Counts`](crate::count::Counts).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the frames
/// would hold more than [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES) entries.
///
/// # Complexity
///
/// Θ(nh) time for the march plus the frames: about nh frames of up to h indices, so
/// O(nh²) time and space.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{jarvis_trace, HullOptions, JarvisStep};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.2, 0.2)].map(Point2::from);
/// let frames = jarvis_trace(&pts, HullOptions::default())?;
/// assert_eq!(frames[0].step, JarvisStep::Start { vertex: 0 });
/// // From 0 the scan looks at 1, 2 and 3; 1 stays the best (2 and 3 lie to its left).
/// let from_0: Vec<usize> = frames[1..4]
///     .iter()
///     .map(|f| match f.step { JarvisStep::Candidate { best, .. } => best, _ => panic!() })
///     .collect();
/// assert_eq!(from_0, [1, 1, 1]);
/// assert_eq!(frames[4].step, JarvisStep::Wrap { vertex: 1, hull: vec![0, 1] });
/// assert_eq!(frames.last().unwrap().step, JarvisStep::Done { hull: vec![0, 1, 2] });
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn jarvis_trace(points: &[Point2], options: HullOptions) -> Result<Vec<Frame<JarvisStep>>> {
    let points = PointSet::new(points)?;
    record(|counts, recorder| {
        let hull = jarvis(points.points(), options, counts, recorder);
        Ok(JarvisStep::Done { hull })
    })
}

/// The march, telling `obs` about each step.
fn jarvis<C: Counter, O: Observer<JarvisStep, C>>(
    points: &[Point2],
    options: HullOptions,
    counter: &mut C,
    obs: &mut O,
) -> Vec<usize> {
    if points.is_empty() {
        return Vec::new();
    }
    let start = lex_min(points, counter);
    obs.step(counter, || JarvisStep::Start { vertex: start });
    let mut hull = vec![start];
    let mut current = start;
    while hull.len() <= points.len() {
        let here = points[current];
        let mut candidate: Option<usize> = None;
        for (i, &p) in points.iter().enumerate() {
            if counter.cmp_lex(p, here) == Ordering::Equal {
                continue;
            }
            let Some(c) = candidate else {
                candidate = Some(i);
                obs.step(counter, || JarvisStep::Candidate {
                    current,
                    point: i,
                    best: i,
                    hull: hull.clone(),
                });
                continue;
            };
            let better = match counter.orient2d(here, points[c], p) {
                Orientation::Clockwise => true,
                Orientation::CounterClockwise => false,
                // Strictly farther only: of equal points the first (smallest index) stays.
                Orientation::Collinear => {
                    counter.cmp_dist(here, p, here, points[c]) == Ordering::Greater
                }
            };
            if better {
                candidate = Some(i);
            }
            obs.step(counter, || JarvisStep::Candidate {
                current,
                point: i,
                best: if better { i } else { c },
                hull: hull.clone(),
            });
        }
        match candidate {
            Some(next) if counter.cmp_lex(points[next], points[start]) != Ordering::Equal => {
                hull.push(next);
                current = next;
                obs.step(counter, || JarvisStep::Wrap {
                    vertex: next,
                    hull: hull.clone(),
                });
            }
            _ => break,
        }
    }
    finish(points, 0..points.len(), hull, options, counter)
}
