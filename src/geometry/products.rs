//! Exact comparisons of products of degree-2 forms: distances from points to lines, and
//! areas and perimeters of rectangles with a side on a line.
//!
//! Both questions compare quotients such as `cross² / |ab|²`. Clearing the denominators
//! turns each into the sign of `P - Q`, where `P` and `Q` are products of three absolute
//! values of degree-2 forms: cross products `(b - a) x (d - c)` and dot products
//! `(b - a) · (d - c)` of coordinate differences. The stages are those of the other
//! predicates:
//!
//! 1. **Filter.** Each form in floating point with an absolute error bound; if every form is
//!    well clear of zero (relative error at most 1/8) and of overflow and underflow
//!    (magnitude in `[2^-300, 2^300]`), the products carry a relative error bound, and a
//!    difference that clears it has the exact sign.
//! 2. **Exact.** Otherwise every coordinate is written as `m · 2^e` with integer `m`, all
//!    are brought to the smallest exponent, and the forms and products are evaluated in big
//!    integers. Both sides have the same degree, so the common power of two cancels.

use super::bigint::BigInt;
use super::extended::decompose;
use super::predicates::{calls_on, pow2, predicate, UNDERFLOW_SLACK};
use super::{Point2, WideFloat};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use std::cmp::Ordering;

/// The comparisons of products of this file, declared.
pub(super) const DECLARATIONS: [Declaration; 3] = [
    predicate(
        "cmp-line-dist",
        "geometry::cmp_line_dist",
        "src/geometry/products.rs",
        "which of two points is closer to its line",
        Operation::DistanceEvaluations,
        calls_on!(Operation::DistanceEvaluations; "uniform-disk", "grid"),
    ),
    predicate(
        "cmp-rect-area",
        "geometry::cmp_rect_area",
        "src/geometry/products.rs",
        "which of two rectangles on given lines is smaller",
        Operation::DistanceEvaluations,
        calls_on!(Operation::DistanceEvaluations; "uniform-disk", "grid"),
    ),
    predicate(
        "cmp-rect-perimeter",
        "geometry::cmp_rect_perimeter",
        "src/geometry/products.rs",
        "which of two rectangles on given lines has the shorter perimeter",
        Operation::DistanceEvaluations,
        calls_on!(Operation::DistanceEvaluations; "uniform-disk", "grid"),
    ),
];

/// Compares the distance from `p` to the line through `a` and `b` with the distance from
/// `q` to the line through `c` and `d`, exact for every finite input.
///
/// `Ordering::Less` means `p` is strictly closer to its line than `q` to its own. The
/// distances are never computed: the predicate is the sign of
/// `((b - a) x (p - a))² · |d - c|² − ((d - c) x (q - c))² · |b - a|²`, so when a line is
/// degenerate (`a = b` or `c = d`) both terms vanish and the answer is `Ordering::Equal`.
/// Rotating calipers use it to choose the edge that realises a convex polygon's width.
///
/// # Complexity
/// O(1): a floating-point filter; near ties, and operands near overflow or underflow, take
/// an exact big-integer evaluation of the degree-8 polynomial.
///
/// ```
/// use compgeo::geometry::{cmp_line_dist, Point2};
/// use std::cmp::Ordering;
///
/// let p = |x, y| Point2::new(x, y);
/// // (0, 5) is 5 from the x-axis; (4, 0) is 12/5 from the line through (0, 0) and (4, 3).
/// assert_eq!(cmp_line_dist(p(0.0, 0.0), p(1.0, 0.0), p(0.0, 5.0), p(0.0, 0.0), p(4.0, 3.0), p(4.0, 0.0)), Ordering::Greater);
/// // (3, 4) is 4 from the x-axis and (4, 1) is 4 from the y-axis: a tie, detected exactly.
/// assert_eq!(cmp_line_dist(p(0.0, 0.0), p(1.0, 0.0), p(3.0, 4.0), p(0.0, 0.0), p(0.0, 7.0), p(4.0, 1.0)), Ordering::Equal);
/// ```
pub fn cmp_line_dist(a: Point2, b: Point2, p: Point2, c: Point2, d: Point2, q: Point2) -> Ordering {
    cmp_line_dist_with(a, b, p, c, d, q, &mut NoCount)
}

/// [`cmp_line_dist`], counting one [`distance_evaluation`](Counter::distance_evaluation)
/// and, when the filter cannot decide, one [`exact_fallback`](Counter::exact_fallback).
///
/// # Complexity
/// O(1), as for [`cmp_line_dist`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{cmp_line_dist_with, Point2};
/// use std::cmp::Ordering;
///
/// let p = |x, y| Point2::new(x, y);
/// let mut c = Counts::default();
/// let o = p(0.0, 0.0);
/// let tie = cmp_line_dist_with(o, p(1.0, 0.0), p(3.0, 4.0), o, p(0.0, 7.0), p(4.0, 1.0), &mut c);
/// assert_eq!(tie, Ordering::Equal);
/// assert_eq!((c.distance_evaluations, c.exact_fallbacks), (1, 1));
/// ```
#[allow(clippy::too_many_arguments)]
pub fn cmp_line_dist_with<C: Counter + ?Sized>(
    a: Point2,
    b: Point2,
    p: Point2,
    c: Point2,
    d: Point2,
    q: Point2,
    counter: &mut C,
) -> Ordering {
    counter.distance_evaluation();
    let lhs = [
        Form::cross(a, b, a, p),
        Form::cross(a, b, a, p),
        Form::dot(c, d, c, d),
    ];
    let rhs = [
        Form::cross(c, d, c, q),
        Form::cross(c, d, c, q),
        Form::dot(a, b, a, b),
    ];
    cmp_abs_products(&lhs, &rhs, counter)
}

/// Compares the areas of two rectangles, each given as `[a, b, p, l, r]`: a side on the
/// line through `a` and `b`, the opposite side through `p`, and the two other sides through
/// `l` and `r` perpendicular to the line; exact for every finite input.
///
/// The area is `|(b - a) x (p - a)| · |(b - a) · (r - l)| / |b - a|²` (height times length),
/// and the predicate is the sign of the first area's numerator times the second's
/// denominator minus the other way round, so a degenerate line (`a = b`) gives
/// `Ordering::Equal`. Rotating calipers use it to choose the minimum-area enclosing
/// rectangle without rounding an area.
///
/// # Complexity
/// O(1), as for [`cmp_line_dist`] (a degree-6 polynomial).
///
/// ```
/// use compgeo::geometry::{cmp_rect_area, Point2};
/// use std::cmp::Ordering;
///
/// let p = |x, y| Point2::new(x, y);
/// // A 4 × 2 box on the x-axis against a box on the diagonal y = x: height √2 (through
/// // (0, 2)), length 3√2 (from (0, 0) to (3, 3) along the diagonal), area 6.
/// let flat = [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 2.0), p(0.0, 0.0), p(4.0, 0.0)];
/// let tilted = [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 2.0), p(0.0, 0.0), p(3.0, 3.0)];
/// assert_eq!(cmp_rect_area(flat, tilted), Ordering::Greater);
/// let tilted_8 = [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 2.0), p(0.0, 0.0), p(4.0, 4.0)];
/// assert_eq!(cmp_rect_area(flat, tilted_8), Ordering::Equal);
/// ```
pub fn cmp_rect_area(first: [Point2; 5], second: [Point2; 5]) -> Ordering {
    cmp_rect_area_with(first, second, &mut NoCount)
}

/// [`cmp_rect_area`], counting one [`distance_evaluation`](Counter::distance_evaluation)
/// (it compares products of lengths) and, when the filter cannot decide, one
/// [`exact_fallback`](Counter::exact_fallback).
///
/// # Complexity
/// O(1), as for [`cmp_line_dist`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{cmp_rect_area_with, Point2};
/// use std::cmp::Ordering;
///
/// let p = |x, y| Point2::new(x, y);
/// let mut c = Counts::default();
/// let flat = [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 2.0), p(0.0, 0.0), p(4.0, 0.0)];
/// let tilted = [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 2.0), p(0.0, 0.0), p(4.0, 4.0)];
/// assert_eq!(cmp_rect_area_with(flat, tilted, &mut c), Ordering::Equal);
/// assert_eq!((c.distance_evaluations, c.exact_fallbacks), (1, 1));
/// ```
pub fn cmp_rect_area_with<C: Counter + ?Sized>(
    first: [Point2; 5],
    second: [Point2; 5],
    counter: &mut C,
) -> Ordering {
    counter.distance_evaluation();
    let [a, b, p, l, r] = first;
    let [c, d, q, l2, r2] = second;
    let lhs = [
        Form::cross(a, b, a, p),
        Form::dot(a, b, l, r),
        Form::dot(c, d, c, d),
    ];
    let rhs = [
        Form::cross(c, d, c, q),
        Form::dot(c, d, l2, r2),
        Form::dot(a, b, a, b),
    ];
    cmp_abs_products(&lhs, &rhs, counter)
}

/// Compares the perimeters of two rectangles, each given as `[a, b, p, l, r]` as in
/// [`cmp_rect_area`]: a side on the line through `a` and `b`, the opposite side through `p`,
/// the two other sides through `l` and `r`; exact for every finite input.
///
/// Half the perimeter is `(|(b − a) × (p − a)| + |(b − a) · (r − l)|) / |b − a|` (height
/// plus length). Both halves are non-negative, so the predicate is the sign of the first's
/// squared numerator times the second's squared denominator minus the other way round, a
/// degree-6 polynomial; a degenerate line (`a = b`) gives `Ordering::Equal`. Rotating
/// calipers use it to choose the minimum-perimeter enclosing rectangle without rounding a
/// perimeter.
///
/// # Complexity
/// O(1), as for [`cmp_rect_area`]: a floating-point filter, then exact big integers near ties
/// and near overflow or underflow.
///
/// ```
/// use compgeo::geometry::{cmp_rect_perimeter, Point2};
/// use std::cmp::Ordering;
///
/// let p = |x, y| Point2::new(x, y);
/// // A 4 × 2 box on the x-axis (perimeter 12) against a 3√2 × √2 box on the diagonal
/// // (perimeter 8√2 ≈ 11.3): the same area 6, but the tilted one is shorter around.
/// let flat = [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 2.0), p(0.0, 0.0), p(4.0, 0.0)];
/// let tilted = [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 2.0), p(0.0, 0.0), p(3.0, 3.0)];
/// assert_eq!(cmp_rect_perimeter(flat, tilted), Ordering::Greater);
/// // 3 × 3 on the x-axis against 1 + 5 on the y-axis: both 12, a tie found exactly.
/// let square = [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 3.0), p(0.0, 0.0), p(3.0, 0.0)];
/// let long = [p(0.0, 0.0), p(0.0, 1.0), p(-1.0, 0.0), p(0.0, 0.0), p(0.0, 5.0)];
/// assert_eq!(cmp_rect_perimeter(square, long), Ordering::Equal);
/// ```
pub fn cmp_rect_perimeter(first: [Point2; 5], second: [Point2; 5]) -> Ordering {
    cmp_rect_perimeter_with(first, second, &mut NoCount)
}

/// [`cmp_rect_perimeter`], counting one [`distance_evaluation`](Counter::distance_evaluation)
/// (it compares sums of lengths) and, when the filter cannot decide, one
/// [`exact_fallback`](Counter::exact_fallback).
///
/// # Complexity
/// O(1), as [`cmp_rect_perimeter`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{cmp_rect_perimeter_with, Point2};
/// use std::cmp::Ordering;
///
/// let p = |x, y| Point2::new(x, y);
/// let mut c = Counts::default();
/// // A tie (both half-perimeters are 6) is for the exact stage to confirm.
/// let square = [p(0.0, 0.0), p(1.0, 0.0), p(0.0, 3.0), p(0.0, 0.0), p(3.0, 0.0)];
/// let long = [p(0.0, 0.0), p(0.0, 1.0), p(-1.0, 0.0), p(0.0, 0.0), p(0.0, 5.0)];
/// assert_eq!(cmp_rect_perimeter_with(square, long, &mut c), Ordering::Equal);
/// assert_eq!((c.distance_evaluations, c.exact_fallbacks), (1, 1));
/// ```
pub fn cmp_rect_perimeter_with<C: Counter + ?Sized>(
    first: [Point2; 5],
    second: [Point2; 5],
    counter: &mut C,
) -> Ordering {
    counter.distance_evaluation();
    let [a, b, p, l, r] = first;
    let [c, d, q, l2, r2] = second;
    let lhs = HalfPerimeter {
        height: Form::cross(a, b, a, p),
        length: Form::dot(a, b, l, r),
        squared_side: Form::dot(c, d, c, d),
    };
    let rhs = HalfPerimeter {
        height: Form::cross(c, d, c, q),
        length: Form::dot(c, d, l2, r2),
        squared_side: Form::dot(a, b, a, b),
    };
    lhs.filtered_cmp(&rhs).unwrap_or_else(|| {
        counter.exact_fallback();
        lhs.exact_cmp(&rhs)
    })
}

/// One side of [`cmp_rect_perimeter`]: `(|height| + |length|)² · squared_side`, where
/// `squared_side` is the *other* rectangle's squared side length.
struct HalfPerimeter {
    height: Form,
    length: Form,
    squared_side: Form,
}

impl HalfPerimeter {
    /// The product in floating point with a relative error bound, if every form is usable
    /// by [`Form::approx`].
    #[inline]
    fn approx(&self) -> Option<(f64, f64)> {
        let (h, rh) = self.height.approx()?;
        let (w, rw) = self.length.approx()?;
        let (s, rs) = self.squared_side.approx()?;
        // A sum of two positive values errs relatively by at most the larger relative
        // error, plus its own rounding; the sum is at most 2^301, so the product of three
        // stays a normal double.
        let sum = h + w;
        let r_sum = rh.max(rw) + f64::EPSILON;
        // As in `filtered`: with every relative error at most 1/8, Π(1 + rᵢ) − 1 ≤
        // 1.5 Σ rᵢ, and the two products' roundings fit in 8 eps.
        Some((sum * sum * s, 1.5 * (2.0 * r_sum + rs) + 8.0 * f64::EPSILON))
    }

    #[inline]
    fn filtered_cmp(&self, other: &HalfPerimeter) -> Option<Ordering> {
        let (p, p_rel) = self.approx()?;
        let (q, q_rel) = other.approx()?;
        let diff = p - q;
        let bound = p_rel * p + q_rel * q;
        if diff > bound {
            Some(Ordering::Greater)
        } else if -diff > bound {
            Some(Ordering::Less)
        } else {
            None
        }
    }

    #[cold]
    #[inline(never)]
    fn exact_cmp(&self, other: &HalfPerimeter) -> Ordering {
        let base = least_exponent(
            [self, other]
                .into_iter()
                .flat_map(|s| [s.height, s.length, s.squared_side])
                .flat_map(|f| f.points),
        );
        let product = |s: &HalfPerimeter| {
            let sum = s.height.exact(base).abs().add(&s.length.exact(base).abs());
            sum.mul(&sum).mul(&s.squared_side.exact(base).abs())
        };
        product(self).sub(&product(other)).signum().cmp(&0)
    }
}

/// `(u1 - u0) x (v1 - v0)` or `(u1 - u0) · (v1 - v0)`.
#[derive(Debug, Clone, Copy)]
struct Form {
    dot: bool,
    /// `[u0, u1, v0, v1]`.
    points: [Point2; 4],
}

/// Each operand of the filter's products stays in `[2^-300, 2^300]`, so a product of three
/// is a normal double and never overflows.
const FORM_MIN: f64 = pow2(-300);
const FORM_MAX: f64 = pow2(300);

/// Absolute error of a form `t1 - t2` with `t = (difference)·(difference)`: each product
/// of rounded differences carries at most about `3 eps` relative error and the subtraction
/// one more `eps` of the sum; `5 eps` leaves room for the rounding of the bound itself.
const FORM_ERRBOUND: f64 = 5.0 * (f64::EPSILON / 2.0);

impl Form {
    fn cross(u0: Point2, u1: Point2, v0: Point2, v1: Point2) -> Form {
        Form {
            dot: false,
            points: [u0, u1, v0, v1],
        }
    }

    fn dot(u0: Point2, u1: Point2, v0: Point2, v1: Point2) -> Form {
        Form {
            dot: true,
            points: [u0, u1, v0, v1],
        }
    }

    /// The rounded absolute value and a bound on its relative error, if the value is well
    /// clear of zero, overflow and underflow.
    #[inline]
    fn approx(&self) -> Option<(f64, f64)> {
        let [u0, u1, v0, v1] = self.points;
        let (ux, uy, vx, vy) = (u1.x - u0.x, u1.y - u0.y, v1.x - v0.x, v1.y - v0.y);
        let (t1, t2) = if self.dot {
            (ux * vx, -(uy * vy))
        } else {
            (ux * vy, uy * vx)
        };
        let value = (t1 - t2).abs();
        let err = FORM_ERRBOUND * (t1.abs() + t2.abs()) + UNDERFLOW_SLACK;
        // Written so that NaN fails every test.
        let usable = value >= 8.0 * err && (FORM_MIN..=FORM_MAX).contains(&value);
        usable.then(|| (value, err / value))
    }

    /// The exact value, its coordinates scaled by `2^-base`.
    fn exact(&self, base: i32) -> BigInt {
        let c: Vec<BigInt> = self
            .points
            .iter()
            .flat_map(|p| [p.x, p.y])
            .map(|v| big(v, base))
            .collect();
        let (ux, uy) = (c[2].sub(&c[0]), c[3].sub(&c[1]));
        let (vx, vy) = (c[6].sub(&c[4]), c[7].sub(&c[5]));
        if self.dot {
            ux.mul(&vx).add(&uy.mul(&vy))
        } else {
            ux.mul(&vy).sub(&uy.mul(&vx))
        }
    }

    /// The value, rounded once: the exact form on the coordinates scaled by `2^-base`
    /// (integers), times `2^(2 base)`.
    fn wide(&self, base: i32) -> WideFloat {
        WideFloat::from_big(&self.exact(base)).scale_pow2(2 * base)
    }
}

/// The sign of `Π |lhs| − Π |rhs|` for two products of the same number of forms, counting
/// an exact fallback when the filter cannot decide.
#[inline]
fn cmp_abs_products<const K: usize, C: Counter + ?Sized>(
    lhs: &[Form; K],
    rhs: &[Form; K],
    counter: &mut C,
) -> Ordering {
    filtered(lhs, rhs).unwrap_or_else(|| {
        counter.exact_fallback();
        exact(lhs, rhs)
    })
}

#[inline]
fn filtered<const K: usize>(lhs: &[Form; K], rhs: &[Form; K]) -> Option<Ordering> {
    let product = |forms: &[Form; K]| -> Option<(f64, f64)> {
        let mut value = 1.0;
        let mut rel = 0.0;
        for f in forms {
            let (v, r) = f.approx()?;
            value *= v;
            rel += r;
        }
        // With every relative error r_i <= 1/8 and K <= 3, Π(1 + r_i) − 1 <= 1.5 Σ r_i; the
        // K − 1 roundings of the product and of the comparison fit in 8 eps.
        Some((value, 1.5 * rel + 8.0 * f64::EPSILON))
    };
    let (p, p_rel) = product(lhs)?;
    let (q, q_rel) = product(rhs)?;
    let diff = p - q;
    let bound = p_rel * p + q_rel * q;
    if diff > bound {
        Some(Ordering::Greater)
    } else if -diff > bound {
        Some(Ordering::Less)
    } else {
        None
    }
}

#[cold]
#[inline(never)]
fn exact<const K: usize>(lhs: &[Form; K], rhs: &[Form; K]) -> Ordering {
    let base = least_exponent(lhs.iter().chain(rhs).flat_map(|f| f.points));
    let product = |forms: &[Form; K]| {
        forms
            .iter()
            .map(|f| f.exact(base).abs())
            .reduce(|acc, v| acc.mul(&v))
            .expect("at least one form")
    };
    product(lhs).sub(&product(rhs)).signum().cmp(&0)
}

/// The distance from `p` to the line through `a` and `b` (`a != b`),
/// `|(b − a) × (p − a)| / |b − a|`, with relative error below 2^-51 for every finite input:
/// the cross product and the squared length are exact big integers, each rounded once,
/// then a square root and a division (3.5 roundings of 2^-53 in all).
pub(crate) fn line_distance(a: Point2, b: Point2, p: Point2) -> WideFloat {
    let base = least_exponent([a, b, p].into_iter());
    let cross = Form::cross(a, b, a, p).wide(base).abs();
    let length = Form::dot(a, b, a, b)
        .wide(base)
        .sqrt()
        .expect("a squared length is not negative");
    cross.checked_div(length).expect("the line's points differ")
}

/// The area `|(b − a) × (p − a)| · |(b − a) · (r − l)| / |b − a|²` of the rectangle of
/// [`cmp_rect_area`] (`a != b`), with relative error below 3 · 2^-52 for every finite
/// input: three exact forms, each rounded once, then a product and a quotient.
pub(crate) fn rect_area([a, b, p, l, r]: [Point2; 5]) -> WideFloat {
    let base = least_exponent([a, b, p, l, r].into_iter());
    let height = Form::cross(a, b, a, p).wide(base).abs();
    let length = Form::dot(a, b, l, r).wide(base).abs();
    let squared = Form::dot(a, b, a, b).wide(base);
    height
        .mul(length)
        .checked_div(squared)
        .expect("the line's points differ")
}

/// The perimeter `2 (|(b − a) × (p − a)| + |(b − a) · (r − l)|) / |b − a|` of the rectangle
/// of [`cmp_rect_perimeter`] (`a != b`), with relative error below 2^-50 for every finite
/// input: the sum of the two exact forms and the squared length are exact big integers,
/// each rounded once, then a square root and a division.
pub(crate) fn rect_perimeter([a, b, p, l, r]: [Point2; 5]) -> WideFloat {
    let base = least_exponent([a, b, p, l, r].into_iter());
    let half_numerator = Form::cross(a, b, a, p)
        .exact(base)
        .abs()
        .add(&Form::dot(a, b, l, r).exact(base).abs());
    let numerator = WideFloat::from_big(&half_numerator).scale_pow2(2 * base + 1);
    let length = Form::dot(a, b, a, b)
        .wide(base)
        .sqrt()
        .expect("a squared length is not negative");
    numerator
        .checked_div(length)
        .expect("the line's points differ")
}

/// The least exponent of the last nonzero bits of the points' coordinates (0 if all are
/// zero): scaled by its inverse, every coordinate is an integer.
fn least_exponent(points: impl Iterator<Item = Point2>) -> i32 {
    points
        .flat_map(|p| [p.x, p.y])
        .map(decompose)
        .filter(|&(_, m, _)| m != 0)
        .map(|(_, _, e)| e)
        .min()
        .unwrap_or(0)
}

/// `v · 2^-base` as a big integer (`base` at most the exponent of `v`'s last bit).
fn big(v: f64, base: i32) -> BigInt {
    let (negative, mantissa, e) = decompose(v);
    let shift = if mantissa == 0 { 0 } else { (e - base) as u32 };
    BigInt::from_parts(negative, mantissa, shift)
}
