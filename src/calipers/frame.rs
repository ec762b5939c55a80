//! Rounded reporting of caliper results: unit directions, distances across a line and areas,
//! from differences halved where they would overflow. The choices are made by exact
//! predicates; these only report them. (The rectangle's corners are certified constructions,
//! `geometry::construct::rectangle_corner`.)

use crate::geometry::Point2;

/// `p - a`, rounded, as a vector and a factor (1, or 2 when the difference overflows and its
/// half is returned).
pub(super) fn difference(p: Point2, a: Point2) -> ((f64, f64), f64) {
    let (x, y) = (p.x - a.x, p.y - a.y);
    if x.is_finite() && y.is_finite() {
        ((x, y), 1.0)
    } else {
        ((p.x / 2.0 - a.x / 2.0, p.y / 2.0 - a.y / 2.0), 2.0)
    }
}

/// The signed distance of `p` from the line through `a` along the unit vector `u`, rounded
/// (computed from the difference itself, so it keeps its relative accuracy when tiny).
pub(super) fn across(u: (f64, f64), p: Point2, a: Point2) -> f64 {
    let ((x, y), k) = difference(p, a);
    (u.0 * y - u.1 * x) * k
}

/// The area of the rectangle with a side on the line through `a` along `u`, the opposite side
/// through `top`, and the others through `left` and `right`, rounded: height times length,
/// each from its own differences.
pub(super) fn area(u: (f64, f64), [a, top, left, right]: [Point2; 4]) -> f64 {
    let height = across(u, top, a).abs();
    let ((x, y), k) = difference(right, left);
    let length = ((u.0 * x + u.1 * y) * k).abs();
    if height == 0.0 || length == 0.0 {
        0.0
    } else {
        height * length
    }
}

/// The unit vector from `a` towards `b` (distinct points), rounded. Taken from the points
/// themselves, not from a common frame: the edge may be tiny next to the frame's largest
/// coordinate (a difference of distinct doubles is never zero), and halves avoid overflow.
pub(super) fn direction(a: Point2, b: Point2) -> (f64, f64) {
    let ((x, y), _) = difference(b, a);
    let largest = x.abs().max(y.abs());
    let (x, y) = (x / largest, y / largest);
    let length = x.hypot(y);
    (x / length, y / length)
}
