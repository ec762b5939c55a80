//! Counted forms of the predicates: the counter increments at the boundary, so algorithm
//! bodies hold no counting code. Each method is the predicate's `_with` form, which also
//! records the calls its floating-point filter could not decide as exact fallbacks.

use super::{
    cmp_dist_with, cmp_lex_with, cmp_line_dist_with, cmp_rect_area_with, cmp_rect_perimeter_with,
    cross_sign_with, incircle_with, orient2d_with, InCircle, Orientation, Point2,
};
use crate::count::Counter;
use std::cmp::Ordering;

/// The predicates of [`crate::geometry`] as methods of any [`Counter`], each recording the
/// operation it performs before answering.
///
/// An algorithm generic over `C: Counter` calls `counter.orient2d(a, b, c)`; with
/// [`NoCount`](crate::count::NoCount) the call compiles to the bare predicate.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{CountedPredicates, Orientation, Point2};
///
/// let mut counts = Counts::default();
/// let (a, b, c) = (Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(0.0, 1.0));
/// assert_eq!(counts.orient2d(a, b, c), Orientation::CounterClockwise);
/// assert_eq!(counts.orientation_tests, 1);
/// ```
pub trait CountedPredicates: Counter {
    /// [`orient2d`](super::orient2d), counted as one orientation test.
    #[inline]
    fn orient2d(&mut self, a: Point2, b: Point2, c: Point2) -> Orientation {
        orient2d_with(a, b, c, self)
    }

    /// [`incircle`](super::incircle), counted as one in-circle test.
    #[inline]
    fn incircle(&mut self, a: Point2, b: Point2, c: Point2, d: Point2) -> InCircle {
        incircle_with(a, b, c, d, self)
    }

    /// [`cmp_dist`](super::cmp_dist), counted as one distance evaluation.
    #[inline]
    fn cmp_dist(&mut self, a: Point2, b: Point2, c: Point2, d: Point2) -> Ordering {
        cmp_dist_with(a, b, c, d, self)
    }

    /// [`cross_sign`](super::cross_sign), counted as one orientation test (it is a signed-area test of two
    /// edge vectors).
    #[inline]
    fn cross_sign(&mut self, a: Point2, b: Point2, c: Point2, d: Point2) -> Orientation {
        cross_sign_with(a, b, c, d, self)
    }

    /// [`cmp_line_dist`](super::cmp_line_dist), counted as one distance evaluation.
    #[inline]
    fn cmp_line_dist(
        &mut self,
        a: Point2,
        b: Point2,
        p: Point2,
        c: Point2,
        d: Point2,
        q: Point2,
    ) -> Ordering {
        cmp_line_dist_with(a, b, p, c, d, q, self)
    }

    /// [`cmp_rect_area`](super::cmp_rect_area), counted as one distance evaluation (it compares products of
    /// lengths).
    #[inline]
    fn cmp_rect_area(&mut self, first: [Point2; 5], second: [Point2; 5]) -> Ordering {
        cmp_rect_area_with(first, second, self)
    }

    /// [`cmp_rect_perimeter`](super::cmp_rect_perimeter), counted as one distance
    /// evaluation (it compares sums of lengths).
    #[inline]
    fn cmp_rect_perimeter(&mut self, first: [Point2; 5], second: [Point2; 5]) -> Ordering {
        cmp_rect_perimeter_with(first, second, self)
    }

    /// [`cmp_lex`](super::cmp_lex), counted as one comparison.
    #[inline]
    fn cmp_lex(&mut self, a: Point2, b: Point2) -> Ordering {
        cmp_lex_with(a, b, self)
    }
}

impl<C: Counter + ?Sized> CountedPredicates for C {}
