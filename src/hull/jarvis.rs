//! Jarvis's march (gift wrapping): from a hull vertex, the next one is the point every other
//! point lies to the left of.

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
    let points = points.points();
    if points.is_empty() {
        return Vec::new();
    }
    let start = lex_min(points, counter);
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
        }
        match candidate {
            Some(next) if counter.cmp_lex(points[next], points[start]) != Ordering::Equal => {
                hull.push(next);
                current = next;
            }
            _ => break,
        }
    }
    finish(points, 0..points.len(), hull, options, counter)
}
