//! Exact invariant checkers for hull outputs: tests and debug builds call them, and so may
//! users who compute hulls elsewhere. Each returns the first broken property as a
//! [`Violation`].

use crate::error::Violation;
use crate::geometry::{cmp_lex, orient2d, Orientation, Point2};
use std::cmp::Ordering;

/// Checks that `hull` (indices into `points`) is a strictly convex polygon in
/// counter-clockwise order: consecutive vertices turn strictly left and the boundary winds
/// around once.
///
/// The empty polygon and a single vertex are strictly convex; two vertices are when they
/// are distinct points (a degenerate hull of collinear input). The start vertex is not
/// checked.
///
/// Uses [`orient2d`] and [`cmp_lex`] only, so the answer is exact.
///
/// # Errors
///
/// A [`Violation`] naming an out-of-range vertex, two equal vertices of a two-vertex hull,
/// the first vertex where the boundary does not turn strictly left, or a boundary that winds
/// around more than once.
///
/// # Complexity
///
/// O(h) time, O(1) auxiliary space, for h = `hull.len()`.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::check_strictly_convex_ccw;
///
/// let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.5, 0.0)].map(Point2::from);
/// assert!(check_strictly_convex_ccw(&square, &[0, 1, 2, 3]).is_ok());
/// let clockwise = check_strictly_convex_ccw(&square, &[0, 3, 2, 1]).unwrap_err();
/// assert!(clockwise.to_string().contains("does not turn left"), "{clockwise}");
/// assert!(check_strictly_convex_ccw(&square, &[0, 4, 1, 2, 3]).is_err()); // 4 is not a corner
/// ```
pub fn check_strictly_convex_ccw(points: &[Point2], hull: &[usize]) -> Result<(), Violation> {
    in_range(points, hull)?;
    let h = hull.len();
    let at = |k: usize| points[hull[k % h]];
    match h {
        0 | 1 => Ok(()),
        2 if cmp_lex(at(0), at(1)) == Ordering::Equal => Err(Violation::new(format!(
            "the two vertices {} and {} are the same point",
            hull[0], hull[1]
        ))),
        2 => Ok(()),
        _ => {
            if let Some(k) = (0..h)
                .find(|&k| orient2d(at(k), at(k + 1), at(k + 2)) != Orientation::CounterClockwise)
            {
                return Err(Violation::new(format!(
                    "the boundary does not turn left at vertex {} (position {})",
                    hull[(k + 1) % h],
                    (k + 1) % h
                )));
            }
            // Left turns everywhere still allow a star that winds twice; a simple convex
            // polygon switches between lexicographically increasing and decreasing edges
            // exactly twice.
            let switches = (0..h)
                .filter(|&k| cmp_lex(at(k), at(k + 1)) != cmp_lex(at(k + 1), at(k + 2)))
                .count();
            if switches == 2 {
                Ok(())
            } else {
                Err(Violation::new(format!(
                    "the boundary winds around {} times",
                    switches / 2
                )))
            }
        }
    }
}

/// Checks that every point of `points` lies in the closed polygon `hull`: on or left of every
/// directed edge for three or more vertices, on the segment for two, equal to the vertex for
/// one; only an empty set is enclosed by an empty hull.
///
/// Together with [`check_strictly_convex_ccw`] and "every vertex is an input point" this says
/// `hull` is the convex hull of `points`.
///
/// # Errors
///
/// A [`Violation`] naming an out-of-range vertex or the first point outside, and the edge it
/// is outside of.
///
/// # Complexity
///
/// O(nh) time, O(1) auxiliary space, for n = `points.len()` and h = `hull.len()`.
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::check_encloses;
///
/// let pts = [(0.0, 0.0), (2.0, 0.0), (0.0, 2.0), (0.5, 0.5)].map(Point2::from);
/// assert!(check_encloses(&pts, &[0, 1, 2]).is_ok());
/// let missed = check_encloses(&pts, &[0, 1, 3]).unwrap_err();
/// assert!(missed.to_string().starts_with("point 2"), "{missed}");
/// ```
pub fn check_encloses(points: &[Point2], hull: &[usize]) -> Result<(), Violation> {
    in_range(points, hull)?;
    let h = hull.len();
    let outside =
        |i: usize, what: String| Err(Violation::new(format!("point {i} is outside {what}")));
    for (i, &p) in points.iter().enumerate() {
        match h {
            0 => return outside(i, "the empty hull".to_string()),
            1 if cmp_lex(p, points[hull[0]]) != Ordering::Equal => {
                return outside(i, format!("the one-vertex hull [{}]", hull[0]))
            }
            1 => {}
            2 => {
                let (a, b) = (points[hull[0]], points[hull[1]]);
                if orient2d(a, b, p) != Orientation::Collinear || !between(a, p, b) {
                    return outside(i, format!("the segment {:?}", [hull[0], hull[1]]));
                }
            }
            _ => {
                if let Some(k) = (0..h).find(|&k| {
                    orient2d(points[hull[k]], points[hull[(k + 1) % h]], p)
                        == Orientation::Clockwise
                }) {
                    return outside(i, format!("the edge {:?}", [hull[k], hull[(k + 1) % h]]));
                }
            }
        }
    }
    Ok(())
}

/// Every vertex index is a point of `points`.
fn in_range(points: &[Point2], hull: &[usize]) -> Result<(), Violation> {
    match hull.iter().position(|&i| i >= points.len()) {
        Some(k) => Err(Violation::new(format!(
            "vertex {} (position {k}) is out of range for {} points",
            hull[k],
            points.len()
        ))),
        None => Ok(()),
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
