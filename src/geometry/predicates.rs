//! Exact geometric predicates (fast path; the exact slow path for extreme magnitudes follows).

use super::Point2;
use std::cmp::Ordering;

/// Where a point lies relative to a directed line, or the turn of a point triple.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// A left turn: positive signed area.
    CounterClockwise,
    /// A right turn: negative signed area.
    Clockwise,
    /// Zero signed area.
    Collinear,
}

/// Where a point lies relative to a circle.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InCircle {
    /// Strictly inside.
    Inside,
    /// Exactly on the circle.
    On,
    /// Strictly outside.
    Outside,
}

fn orientation_of(det: f64) -> Orientation {
    if det > 0.0 {
        Orientation::CounterClockwise
    } else if det < 0.0 {
        Orientation::Clockwise
    } else {
        Orientation::Collinear
    }
}

fn coord(p: Point2) -> robust::Coord<f64> {
    robust::Coord { x: p.x, y: p.y }
}

/// Orientation of the triple `(a, b, c)`.
pub fn orient2d(a: Point2, b: Point2, c: Point2) -> Orientation {
    orientation_of(robust::orient2d(coord(a), coord(b), coord(c)))
}

/// Position of `d` relative to the circle through the counter-clockwise triangle `a, b, c`.
pub fn incircle(a: Point2, b: Point2, c: Point2, d: Point2) -> InCircle {
    let det = robust::incircle(coord(a), coord(b), coord(c), coord(d));
    if det > 0.0 {
        InCircle::Inside
    } else if det < 0.0 {
        InCircle::Outside
    } else {
        InCircle::On
    }
}

/// Compares `|ab|^2` with `|cd|^2`.
pub fn cmp_dist(a: Point2, b: Point2, c: Point2, d: Point2) -> Ordering {
    let ab = (b.x - a.x).powi(2) + (b.y - a.y).powi(2);
    let cd = (d.x - c.x).powi(2) + (d.y - c.y).powi(2);
    ab.total_cmp(&cd)
}

/// Sign of the cross product `(b - a) x (d - c)`.
pub fn cross_sign(a: Point2, b: Point2, c: Point2, d: Point2) -> Orientation {
    orientation_of((b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x))
}

/// Lexicographic order: by x, then by y.
pub fn cmp_lex(a: Point2, b: Point2) -> Ordering {
    cmp_f64(a.x, b.x).then_with(|| cmp_f64(a.y, b.y))
}

fn cmp_f64(a: f64, b: f64) -> Ordering {
    if a < b {
        Ordering::Less
    } else if a > b {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}
