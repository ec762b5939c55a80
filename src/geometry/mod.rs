//! The geometric kernel: the point type, exact predicates, validation and ordering helpers.
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
//! | [`cmp_lex`] | lexicographic (x, then y) order | 1 |
//!
//! Crate-internal modules hold the predicates on constructed points of single algorithms:
//! `sweep_predicates` (Fortune's sweep) and `circle_predicates` (the largest empty circle:
//! circumcentres against hull lines, bisector crossings along a hull edge, squared radii).
//!
//! How exactness is achieved for inputs of any magnitude is described in `docs/design.md`.
//! [`CountedPredicates`] gives every predicate a counted form for use with a
//! [`Counter`](crate::count::Counter).

mod bigint;
pub(crate) mod circle_predicates;
mod counted;
mod expansion;
mod extended;
mod point;
mod predicates;
mod products;
pub(crate) mod sweep_predicates;
mod validate;

pub use counted::CountedPredicates;
pub use point::Point2;
pub use predicates::{cmp_dist, cmp_lex, cross_sign, incircle, orient2d, InCircle, Orientation};
pub use products::{cmp_line_dist, cmp_rect_area};
pub use validate::validate;
