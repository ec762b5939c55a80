//! Rounded constructions of the Voronoi diagram and the proximity problems: circumcentres,
//! midpoints and unit directions (distances are `WideFloat::distance`).
//!
//! These build new points, so they cannot be exact in `f64`; every *decision* stays with
//! the exact predicates. Each construction works on coordinate differences scaled by a
//! power of two (exact), so it neither overflows for coordinates near `f64::MAX` nor loses
//! everything to underflow for subnormal differences: the result carries a few rounding
//! errors relative to the size of the configuration.

use crate::geometry::{cmp_dist, Point2};

/// The circumcentre of the counter-clockwise (strictly) triangle `a, b, c`.
///
/// The formula runs on the two edges at the vertex opposite the longest edge: their cross
/// product, the denominator, then loses at most a few units in the last place relative to
/// its size however short one edge is, so a triangle with two nearly coincident vertices
/// still gets an accurate centre. (Which vertex is a numerical choice, not a geometric
/// decision: it is made on rounded squared lengths; a near tie means either choice is as
/// accurate.) A centre beyond the range of `f64` (a nearly flat triangle at a large scale)
/// is clamped to `±f64::MAX` coordinate by coordinate.
#[inline]
pub(crate) fn circumcentre(a: Point2, b: Point2, c: Point2) -> Point2 {
    let (ab, bc, ca) = (
        (b.x - a.x, b.y - a.y),
        (c.x - b.x, c.y - b.y),
        (a.x - c.x, a.y - c.y),
    );
    let len = |(x, y): (f64, f64)| x * x + y * y;
    let (lab, lbc, lca) = (len(ab), len(bc), len(ca));
    let m = [ab.0, ab.1, bc.0, bc.1, ca.0, ca.1]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    // Cubic terms stay normal and finite for differences in [2^-300, 2^300]; elsewhere
    // (and for NaN from overflowing differences) the scaled path below.
    if (POW2_M300..=POW2_300).contains(&m) {
        // Origin o opposite the longest edge, u and w its two edges, counter-clockwise.
        let neg = |(x, y): (f64, f64)| (-x, -y);
        let (o, u, w, lu, lw) = if lab >= lbc && lab >= lca {
            (c, ca, neg(bc), lca, lbc)
        } else if lca >= lbc {
            (b, bc, neg(ab), lbc, lab)
        } else {
            (a, ab, neg(ca), lab, lca)
        };
        let d = 2.0 * (u.0 * w.1 - u.1 * w.0);
        if d > 0.0 {
            let x = o.x + (w.1 * lu - u.1 * lw) / d;
            let y = o.y + (u.0 * lw - w.0 * lu) / d;
            if x.is_finite() && y.is_finite() {
                return Point2::new(x, y);
            }
        }
    }
    circumcentre_scaled(a, b, c)
}

/// [`circumcentre`] on differences scaled by a power of two, halved first if they
/// overflow: for every finite input.
#[cold]
fn circumcentre_scaled(a: Point2, b: Point2, c: Point2) -> Point2 {
    use std::cmp::Ordering::Greater;
    let (a, b, c) = if cmp_dist(a, b, b, c) == Greater && cmp_dist(a, b, c, a) == Greater {
        (c, a, b)
    } else if cmp_dist(c, a, b, c) == Greater {
        (b, c, a)
    } else {
        (a, b, c)
    };
    let (bx, by, cx, cy, half) = differences(a, b, c);
    // Each edge scaled by its own power of two: in a common scale a short edge next to a
    // long one (1e-300 beside 1e300) would underflow to nothing. The offset is
    // (cy |b|² − by |c|², bx |c|² − cx |b|²) / (2 b × c), and each of its terms is
    // linear in one edge's scale once the determinant's two scales cancel.
    let sb = scale_of(bx.abs().max(by.abs()));
    let sc = scale_of(cx.abs().max(cy.abs()));
    let (bx, by, cx, cy) = (bx / sb, by / sb, cx / sc, cy / sc);
    let b2 = bx * bx + by * by;
    let c2 = cx * cx + cy * cy;
    // The triangle is counter-clockwise, so the exact determinant is positive; a rounded
    // one that is not only means the triangle is very flat and the centre very far.
    let d = (2.0 * (bx * cy - by * cx)).max(f64::MIN_POSITIVE);
    Point2::new(
        clamp(offset(a.x, cy * b2 / d, sb, by * c2 / d, sc, half)),
        clamp(offset(a.y, -(cx * b2 / d), sb, -(bx * c2 / d), sc, half)),
    )
}

/// 2^300 and 2^-300.
const POW2_300: f64 = 2.037035976334486e90;
const POW2_M300: f64 = 4.909093465297727e-91;

/// The midpoint of `a` and `b`.
pub(crate) fn midpoint(a: Point2, b: Point2) -> Point2 {
    let mid = |p: f64, q: f64| {
        let m = (p + q) / 2.0;
        if m.is_finite() {
            m
        } else {
            p / 2.0 + q / 2.0
        }
    };
    Point2::new(mid(a.x, b.x), mid(a.y, b.y))
}

/// The unit vector from `a` towards `b` (`a != b`).
pub(crate) fn unit_direction(a: Point2, b: Point2) -> Point2 {
    let (mut dx, mut dy) = (b.x - a.x, b.y - a.y);
    if !(dx.is_finite() && dy.is_finite()) {
        (dx, dy) = (b.x / 2.0 - a.x / 2.0, b.y / 2.0 - a.y / 2.0);
    }
    let s = scale_of(dx.abs().max(dy.abs()));
    let (dx, dy) = (dx / s, dy / s);
    let len = dx.hypot(dy);
    Point2::new(dx / len, dy / len)
}

/// `b - a` and `c - a`, halved (and `true`) if a full difference overflows.
fn differences(a: Point2, b: Point2, c: Point2) -> (f64, f64, f64, f64, bool) {
    let d = (b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
    if d.0.is_finite() && d.1.is_finite() && d.2.is_finite() && d.3.is_finite() {
        (d.0, d.1, d.2, d.3, false)
    } else {
        (
            b.x / 2.0 - a.x / 2.0,
            b.y / 2.0 - a.y / 2.0,
            c.x / 2.0 - a.x / 2.0,
            c.y / 2.0 - a.y / 2.0,
            true,
        )
    }
}

/// A power of two within a factor 2 of `m` (1 for zero), so dividing by it is exact
/// unless the quotient underflows.
pub(crate) fn scale_of(m: f64) -> f64 {
    if m == 0.0 || !m.is_finite() {
        return 1.0;
    }
    let e = (m.to_bits() >> 52) as i32 - 1023;
    // Subnormals have the biased exponent 0; 2^-1022 is close enough as their scale.
    f64::from_bits(((e.clamp(-1022, 1023) + 1023) as u64) << 52)
}

/// `base + (p sp − q sq)` (times 2 if `half`: then the differences were halved) without
/// an intermediate overflow where the result is representable.
fn offset(base: f64, p: f64, sp: f64, q: f64, sq: f64, half: bool) -> f64 {
    let u = p * sp - q * sq;
    if half {
        return 2.0 * (base / 2.0 + u);
    }
    let r = base + u;
    if r.is_finite() {
        return r;
    }
    // The offset or the sum overflowed, but the result may not: add the halves.
    2.0 * (base / 2.0 + (p * (sp / 2.0) - q * (sq / 2.0)))
}

fn clamp(v: f64) -> f64 {
    if v.is_nan() {
        0.0
    } else {
        v.clamp(-f64::MAX, f64::MAX)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new(x, y)
    }

    #[test]
    fn circumcentre_of_a_right_triangle_is_the_hypotenuse_midpoint() {
        assert_eq!(
            circumcentre(p(0.0, 0.0), p(4.0, 0.0), p(0.0, 2.0)),
            p(2.0, 1.0)
        );
        // The same triangle at 1e300 and at 1e-300: scaling by powers of two is exact.
        let s = 2f64.powi(996);
        assert_eq!(
            circumcentre(p(0.0, 0.0), p(4.0 * s, 0.0), p(0.0, 2.0 * s)),
            p(2.0 * s, s)
        );
        let s = 2f64.powi(-1060);
        assert_eq!(
            circumcentre(p(0.0, 0.0), p(4.0 * s, 0.0), p(0.0, 2.0 * s)),
            p(2.0 * s, s)
        );
    }

    #[test]
    fn overflowing_differences_are_halved() {
        let m = f64::MAX;
        let c = circumcentre(p(-m, -m), p(m, -m), p(-m, m));
        assert_eq!(c, p(0.0, 0.0));
        assert_eq!(midpoint(p(m, m), p(m, -m)), p(m, 0.0));
        assert_eq!(unit_direction(p(-m, 0.0), p(m, 0.0)), p(1.0, 0.0));
    }

    #[test]
    fn a_short_edge_beside_a_long_one_keeps_its_centre() {
        // Isosceles about y = x with apex (1e300, 1e300): the centre is near
        // (5e299, 5e299), found from the vertex where the 1e-300 edge meets a long one.
        let c = circumcentre(p(1e-300, 0.0), p(1e300, 1e300), p(0.0, 1e-300));
        assert!((c.x / 5e299 - 1.0).abs() < 1e-15, "{c:?}");
        assert!((c.y / 5e299 - 1.0).abs() < 1e-15, "{c:?}");
    }

    #[test]
    fn a_flat_triangle_has_a_far_but_finite_centre() {
        let c = circumcentre(p(0.0, 0.0), p(2.0, 0.0), p(1.0, 1e-300));
        assert!(c.is_finite());
        assert!(c.y < -1e290);
        assert_eq!(c.x, 1.0);
    }

    #[test]
    fn the_fast_path_and_the_scaled_path_agree() {
        let tri = [p(0.1, 0.2), p(3.7, -1.1), p(2.0, 5.5)];
        let fast = circumcentre(tri[0], tri[1], tri[2]);
        let scaled = circumcentre_scaled(tri[0], tri[1], tri[2]);
        assert!((fast.x - scaled.x).abs() < 1e-14 && (fast.y - scaled.y).abs() < 1e-14);
        assert_eq!(POW2_300, 2f64.powi(300));
        assert_eq!(POW2_M300, 2f64.powi(-300));
    }

    #[test]
    fn scale_is_a_power_of_two_near_the_value() {
        for m in [1.0, 3.0, 1e300, 1e-300, 5e-324, f64::MAX] {
            let s = scale_of(m);
            assert_eq!(s.to_bits() & ((1u64 << 52) - 1), 0);
            assert!(m / s < 2.0 && (m / s >= 1.0 || m < f64::MIN_POSITIVE));
        }
    }
}
