//! The geometric kernel: the point type, the validated point set, exact predicates and
//! ordering helpers.
//!
//! Every geometric decision in compgeo goes through the predicates of this module, and every
//! predicate is exact for every finite `f64` input: the answer is the sign of the exact real
//! expression, never of a rounded one. The plane is oriented with y up, so a counter-clockwise
//! turn is positive.
//!
//! | predicate | question | degree |
//! |---|---|---|
//! | [`orient2d`] | is `c` left of, right of, or on the line `a -> b`? | 2 |
//! | [`incircle`] | is `d` inside, on, or outside the circle through `a, b, c`? | 4 |
//! | [`cmp_dist`] | is `|ab|` shorter than, equal to, or longer than `|cd|`? | 2 |
//! | [`cross_sign`] | does the direction `d - c` turn left or right of `b - a`? | 2 |
//! | [`cmp_line_dist`] | is `p` closer to line `ab` than `q` to line `cd`? | 8 |
//! | [`cmp_rect_area`] | which of two rectangles on given lines is smaller? | 6 |
//! | [`cmp_rect_perimeter`] | which of two rectangles on given lines is shorter around? | 6 |
//! | [`cmp_lex`] | lexicographic (x, then y) order | 1 |
//!
//! Crate-internal modules hold the predicates on constructed points of single algorithms:
//! `sweep_predicates` (Fortune's sweep), `circle_predicates` (the largest empty circle:
//! circumcentres against hull lines, bisector crossings along a hull edge, squared radii) and
//! `clip_predicates` (Voronoi cells clipped to a box: the side of a line on which two others
//! meet). `lex_sort` is the lexicographic sort of points that the hull and Delaunay code
//! share: a radix sort when nobody counts, the counted comparison sort otherwise.
//!
//! Constructed points (Voronoi vertices, rectangle corners, empty-circle centres) are rounded,
//! not exact: each is a [`ConstructedPoint`], within a stated relative error of its exact
//! value and explicit about a value beyond the range of `f64`.
//!
//! How exactness is achieved for inputs of any magnitude is described in `docs/design.md`.
//! [`CountedPredicates`] gives every predicate a counted form for use with a
//! [`Counter`](crate::count::Counter).

mod ball;
mod bigint;
pub(crate) mod circle_predicates;
pub(crate) mod clip_predicates;
pub(crate) mod construct;
mod counted;
pub(crate) mod exact_sum;
mod expansion;
mod extended;
pub(crate) mod lex_sort;
mod point;
mod point_set;
mod predicates;
mod products;
pub(crate) mod sweep_predicates;
mod wide;

pub use construct::ConstructedPoint;
pub use counted::CountedPredicates;
#[cfg(feature = "parallel")]
pub use lex_sort::parallel_sorted_lex;
#[doc(hidden)]
pub use lex_sort::{comparison_sorted_lex, radix_sorted_lex};
pub use point::{Point2, PointPair};
pub use point_set::{BoundingBox, PointSet};
pub use wide::WideFloat;

/// The exact predicates, declared: O(1) each, counted as the operation each one is.
pub(crate) const DECLARATIONS: [&crate::complexity::Declaration; 8] = [
    &predicates::DECLARATIONS[0],
    &predicates::DECLARATIONS[1],
    &predicates::DECLARATIONS[2],
    &predicates::DECLARATIONS[3],
    &predicates::DECLARATIONS[4],
    &products::DECLARATIONS[0],
    &products::DECLARATIONS[1],
    &products::DECLARATIONS[2],
];
pub(crate) use predicates::BoxPredicates;
pub use predicates::{
    cmp_dist, cmp_dist_with, cmp_lex, cmp_lex_with, cross_sign, cross_sign_with, incircle,
    incircle_with, orient2d, orient2d_with, InCircle, Orientation,
};
pub use products::{
    cmp_line_dist, cmp_line_dist_with, cmp_rect_area, cmp_rect_area_with, cmp_rect_perimeter,
    cmp_rect_perimeter_with,
};
pub(crate) use products::{line_distance, rect_area, rect_perimeter};
