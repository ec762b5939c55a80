//! Exact invariant checkers for hull outputs: tests and debug builds call them, and so may
//! users who compute hulls elsewhere.

use crate::geometry::{cmp_lex, orient2d, Orientation, Point2};
use std::cmp::Ordering;

/// Whether `hull` (indices into `points`) is a strictly convex polygon in counter-clockwise
/// order: consecutive vertices turn strictly left and the boundary winds around once.
///
/// The empty polygon and a single vertex are strictly convex; two vertices are when they
/// are distinct points (a degenerate hull of collinear input). Out-of-range indices give
/// `false`. The start vertex is not checked.
///
/// Uses [`orient2d`] and [`cmp_lex`] only, so the answer is exact.
///
/// # Complexity
///
/// O(h) time, O(1) auxiliary space, for h = `hull.len()`.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::is_strictly_convex_ccw;
///
/// let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.5, 0.0)].map(Point2::from);
/// assert!(is_strictly_convex_ccw(&square, &[0, 1, 2, 3]));
/// assert!(!is_strictly_convex_ccw(&square, &[0, 3, 2, 1])); // clockwise
/// assert!(!is_strictly_convex_ccw(&square, &[0, 4, 1, 2, 3])); // 4 is not a corner
/// ```
pub fn is_strictly_convex_ccw(points: &[Point2], hull: &[usize]) -> bool {
    if hull.iter().any(|&i| i >= points.len()) {
        return false;
    }
    let h = hull.len();
    let at = |k: usize| points[hull[k % h]];
    match h {
        0 | 1 => true,
        2 => cmp_lex(at(0), at(1)) != Ordering::Equal,
        _ => {
            let left_turns = (0..h)
                .all(|k| orient2d(at(k), at(k + 1), at(k + 2)) == Orientation::CounterClockwise);
            // Left turns everywhere still allow a star that winds twice; a simple convex
            // polygon switches between lexicographically increasing and decreasing edges
            // exactly twice.
            let switches = (0..h)
                .filter(|&k| cmp_lex(at(k), at(k + 1)) != cmp_lex(at(k + 1), at(k + 2)))
                .count();
            left_turns && switches == 2
        }
    }
}

/// Whether every point of `points` lies in the closed polygon `hull`: on or left of every
/// directed edge for three or more vertices, on the segment for two, equal to the vertex for
/// one; only an empty set is enclosed by an empty hull. Out-of-range indices give `false`.
///
/// Together with [`is_strictly_convex_ccw`] and "every vertex is an input point" this says
/// `hull` is the convex hull of `points`.
///
/// # Complexity
///
/// O(nh) time, O(1) auxiliary space, for n = `points.len()` and h = `hull.len()`.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::encloses;
///
/// let pts = [(0.0, 0.0), (2.0, 0.0), (0.0, 2.0), (0.5, 0.5)].map(Point2::from);
/// assert!(encloses(&pts, &[0, 1, 2]));
/// assert!(!encloses(&pts, &[0, 1, 3])); // misses point 2
/// ```
pub fn encloses(points: &[Point2], hull: &[usize]) -> bool {
    if hull.iter().any(|&i| i >= points.len()) {
        return false;
    }
    let h = hull.len();
    match h {
        0 => points.is_empty(),
        1 => points
            .iter()
            .all(|&p| cmp_lex(p, points[hull[0]]) == Ordering::Equal),
        2 => {
            let (a, b) = (points[hull[0]], points[hull[1]]);
            points
                .iter()
                .all(|&p| orient2d(a, b, p) == Orientation::Collinear && between(a, p, b))
        }
        _ => points.iter().all(|&p| {
            (0..h).all(|k| {
                orient2d(points[hull[k]], points[hull[(k + 1) % h]], p) != Orientation::Clockwise
            })
        }),
    }
}

/// Whether `p` lies between `a` and `b` in lexicographic order, ends included.
fn between(a: Point2, p: Point2, b: Point2) -> bool {
    let (lo, hi) = if cmp_lex(a, b) == Ordering::Greater {
        (b, a)
    } else {
        (a, b)
    };
    cmp_lex(lo, p) != Ordering::Greater && cmp_lex(p, hi) != Ordering::Greater
}
