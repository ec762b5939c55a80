//! Four calipers rotated once around a convex polygon: for each edge, the vertices extreme
//! along its direction, farthest from its line and extreme against its direction. The width
//! and the minimum-area rectangle score the edges they visit.

use super::ConvexPolygon;
use crate::count::Counter;
use crate::geometry::{CountedPredicates, Orientation, Point2};

/// For one hull edge (position `edge`, from `edge` to `edge + 1`), the positions of the
/// vertices on the other sides of its enclosing rectangle; positions count up without
/// wrapping, so take them modulo h.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sides {
    pub(super) edge: usize,
    pub(super) right: usize,
    pub(super) top: usize,
    pub(super) left: usize,
}

/// Rotates four calipers once around `polygon` (at least three vertices) and calls `visit` for every edge with its extreme vertices: the first of
/// equally extreme ones counter-clockwise.
pub(super) fn four_calipers<C: Counter>(
    polygon: &ConvexPolygon<'_>,
    counter: &mut C,
    mut visit: impl FnMut(Sides, &mut C),
) {
    let h = polygon.vertices().len();
    let v = |k: usize| polygon.at(k);
    // The sign of (b - a) · (d - c) is that of (b' - a') x (d - c) for p' = (p.y, -p.x).
    let turned = |p: Point2| Point2::new(p.y, -p.x);
    let (mut right, mut top, mut left) = (1, 1, 1);
    for edge in 0..h {
        let (a, b) = (v(edge), v(edge + 1));
        let (ta, tb) = (turned(a), turned(b));
        right = right.max(edge + 1);
        while counter.cross_sign(ta, tb, v(right), v(right + 1)) == Orientation::CounterClockwise {
            right += 1;
        }
        top = top.max(right);
        while counter.cross_sign(a, b, v(top), v(top + 1)) == Orientation::CounterClockwise {
            top += 1;
        }
        left = left.max(top);
        while counter.cross_sign(ta, tb, v(left), v(left + 1)) == Orientation::Clockwise {
            left += 1;
        }
        visit(
            Sides {
                edge,
                right,
                top,
                left,
            },
            counter,
        );
    }
}
