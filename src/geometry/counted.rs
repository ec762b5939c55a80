//! Counted forms of the predicates: the counter increments at the boundary, so algorithm
//! bodies hold no counting code.

use super::{
    cmp_dist, cmp_lex, cmp_line_dist, cmp_rect_area, cmp_rect_perimeter, cross_sign, incircle,
    orient2d, InCircle, Orientation, Point2,
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
    /// [`orient2d`], counted as one orientation test.
    #[inline]
    fn orient2d(&mut self, a: Point2, b: Point2, c: Point2) -> Orientation {
        self.orientation_test();
        orient2d(a, b, c)
    }

    /// [`incircle`], counted as one in-circle test.
    #[inline]
    fn incircle(&mut self, a: Point2, b: Point2, c: Point2, d: Point2) -> InCircle {
        self.incircle_test();
        incircle(a, b, c, d)
    }

    /// [`cmp_dist`], counted as one distance evaluation.
    #[inline]
    fn cmp_dist(&mut self, a: Point2, b: Point2, c: Point2, d: Point2) -> Ordering {
        self.distance_evaluation();
        cmp_dist(a, b, c, d)
    }

    /// [`cross_sign`], counted as one orientation test (it is a signed-area test of two
    /// edge vectors).
    #[inline]
    fn cross_sign(&mut self, a: Point2, b: Point2, c: Point2, d: Point2) -> Orientation {
        self.orientation_test();
        cross_sign(a, b, c, d)
    }

    /// [`cmp_line_dist`], counted as one distance evaluation.
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
        self.distance_evaluation();
        cmp_line_dist(a, b, p, c, d, q)
    }

    /// [`cmp_rect_area`], counted as one distance evaluation (it compares products of
    /// lengths).
    #[inline]
    fn cmp_rect_area(&mut self, first: [Point2; 5], second: [Point2; 5]) -> Ordering {
        self.distance_evaluation();
        cmp_rect_area(first, second)
    }

    /// [`cmp_rect_perimeter`], counted as one distance evaluation (it compares sums of
    /// lengths).
    #[inline]
    fn cmp_rect_perimeter(&mut self, first: [Point2; 5], second: [Point2; 5]) -> Ordering {
        self.distance_evaluation();
        cmp_rect_perimeter(first, second)
    }

    /// [`cmp_lex`], counted as one comparison.
    #[inline]
    fn cmp_lex(&mut self, a: Point2, b: Point2) -> Ordering {
        self.comparison();
        cmp_lex(a, b)
    }
}

impl<C: Counter + ?Sized> CountedPredicates for C {}
