//! Rounded constructions of caliper results (the rectangle's corners): unit directions, on
//! coordinates scaled by a power of two so that nothing overflows or underflows. The
//! choices are made by exact predicates; these only report them. Widths and areas are
//! evaluated exactly and rounded once (`geometry::line_distance`, `geometry::rect_area`).

use crate::geometry::Point2;

/// Points scaled by a power of two so that the largest coordinate is about 1: rounded
/// constructions on them neither overflow nor lose subnormal precision.
pub(super) struct Frame<const N: usize> {
    pub(super) points: [Point2; N],
    exponent: i32,
}

impl<const N: usize> Frame<N> {
    pub(super) fn new(points: [Point2; N]) -> Frame<N> {
        let largest = points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        // Any nearby power of two will do: the scaling only steers rounding.
        let exponent = if largest == 0.0 {
            0
        } else {
            largest.log2().floor() as i32
        };
        Frame {
            points: points.map(|p| Point2::new(scale(p.x, -exponent), scale(p.y, -exponent))),
            exponent,
        }
    }

    pub(super) fn unscale(&self, v: f64) -> f64 {
        scale(v, self.exponent)
    }
}

/// `v · 2^e` in two steps, so that no factor overflows for |e| up to 2100.
pub(super) fn scale(v: f64, e: i32) -> f64 {
    let half = e / 2;
    v * 2f64.powi(half) * 2f64.powi(e - half)
}

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
