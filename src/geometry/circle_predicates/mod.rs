//! Exact predicates of the largest empty circle [RD, §2.4, problem 5]: on which side of a
//! hull line a Voronoi vertex lies, in which order a hull edge crosses bisectors, and which
//! of two candidate circles is larger.
//!
//! The points involved are constructed, but rational in the input coordinates:
//!
//! - the circumcentre of `a, b, c` is `a + (Nx, Ny) / D` with, for `b' = b − a` and
//!   `c' = c − a`, `D = 2 (b' × c')` (twice the doubled signed area),
//!   `Nx = c'y |b'|² − b'y |c'|²` and `Ny = b'x |c'|² − c'x |b'|²`;
//! - on the hull edge `p → q` (`g = q − p`), the point equidistant from sites `s` and `w`
//!   (`u = w − s`, midpoint `m = (s + w) / 2`) is `p + t g` with
//!   `t = ((m − p) · u) / (g · u) = N / (2 D)`, where `N = u · ((w − p) + (s − p))` and
//!   `D = g · u`.
//!
//! Every question is then the sign of a polynomial once the (positive) denominators are
//! cleared:
//!
//! | predicate | polynomial | degree |
//! |---|---|---|
//! | [`Circumcentre::orient`] | `(q − p) × ((a − p) D + N)`, times the sign of `D` | 4 |
//! | [`cmp_bisector_crossings`] | `N_w D_v − N_v D_w` | 4 |
//! | [`dot_sign`] | `(b − a) · (d − c)` | 2 |
//! | [`SquaredRadius::cmp`] | `num₁ den₂ − num₂ den₁` (squared radii `num / den`, each of degree 6 over 4) | 10 |
//!
//! The squared radius of a circumcircle is `|b − c|² |b'|² |c'|² / D²` (`R = abc / 4K`); of a
//! crossing circle, `|V|² / (4 D²)` with `V = 2 D (p − s) + N g` (`V / 2D` is the vector from
//! `s` to the crossing point).
//!
//! Stages, as for the other predicates of the kernel (`docs/design.md`):
//!
//! 1. **Filter.** A rounded evaluation with a proven error bound; if the value clears the
//!    bound its sign is exact. The circumcentre is rounded once per triangle together with a
//!    bound on its error, and each side test against a hull line is then a degree-2
//!    orientation filter widened by that bound, so a point-in-hull search costs about what
//!    `orient2d` on a rounded centre costs. The other filters use midpoint–radius arithmetic
//!    ([`Ball`]: every operation returns a value and a rigorous bound on its distance to the
//!    exact result) on coordinate differences scaled by one power of two into `[1, 2)`, so
//!    neither 1e300 nor 1e-300 defeats them. Squared radii are kept as a mantissa, a
//!    separate exponent and a relative error, and compared without ever forming `r²` in
//!    range-limited floating point.
//! 2. **Lattice ties.** Every triangle of a grid has the same circumradius, so on lattices
//!    nearly every radius comparison is an exact tie. When a triangle's differences, in
//!    its own frame, are exact multiples of 2^-24, every factor of its squared radius is an
//!    exact double (`GridFactors`), and two such radii are compared from the factors
//!    (equal factors, or the products of their mantissas in integers) without big
//!    integers.
//! 3. **Exact stage.** Every double is written `m · 2^e` with integer `m`, all are brought to
//!    the smallest exponent, and the polynomial is evaluated in the crate's big integers
//!    (`bigint.rs`), once per candidate for the squared radii (cached). It is needed only
//!    for near ties, the other exact ties (cocircular lattices of large coordinates,
//!    Voronoi vertices exactly on the hull) and operands whose exponents span too much for
//!    the filter.
//!
//! Overflow in a filter gives `inf` or NaN, which never clears a bound (every test is
//! written `value > bound`), and underflow is covered by an absolute slack (`2^-1000`, a
//! normal double: arithmetic on subnormals is slow) added wherever a rounding can be
//! absolute.
//!
//! Files: this one holds the side test and the order of crossings, `radius.rs` the squared
//! radii (filter, lattice ties, exact stage); the midpoint–radius arithmetic is
//! `geometry/ball.rs`, shared with the certified constructions.

mod radius;

use super::ball::{scaled_differences, times_pow2, Ball, GROW, SLACK, U};
use super::bigint::BigInt;
use super::extended::{exact_coords, exponent};
use super::predicates::pow2;
use super::{cross_sign, Orientation, Point2};
use crate::count::Counter;
use radius::Approx;
pub(crate) use radius::SquaredRadius;
use std::cmp::Ordering;

/// Squared lengths and determinants below this (in a frame where the largest difference is
/// in `[1, 2)`) make the squared radius's filter give up: products of three of them stay
/// normal.
const TINY_FACTOR: f64 = pow2(-300);

/// The circumcentre of a triangle as an exact rational point, with a rounded approximation
/// and a bound on its error for the filters.
///
/// Built once per triangle; [`Circumcentre::orient`] then tells on which side of a directed
/// line the exact centre lies, [`Circumcentre::squared_radius`] gives the circle's squared
/// radius for [`SquaredRadius::cmp`], and [`Circumcentre::rounded`] the rounded centre and
/// its error bounds (which the certified constructions of `construct.rs` accept or not).
#[derive(Debug, Clone)]
pub(crate) struct Circumcentre {
    /// The triangle, for the exact stage, from the vertex opposite its longest edge.
    tri: [Point2; 3],
    /// The rounded centre and bounds on the errors of its coordinates; the bounds are
    /// infinite when the filter cannot say anything (a nearly flat triangle, overflow).
    x: f64,
    y: f64,
    err_x: f64,
    err_y: f64,
    /// In the triangle's frame (differences from `a` times `2^k`): `|b'|²`, `|c'|²`,
    /// `b' × c'` and the bound on the relative error of the latter (at most 1/8 when the
    /// bounds above are finite).
    lb: f64,
    lc: f64,
    half_d: f64,
    rel_d: f64,
    k: i32,
}

impl Circumcentre {
    /// The circumcentre of `a, b, c`, which must not be collinear (either orientation).
    #[inline]
    pub(crate) fn new(a: Point2, b: Point2, c: Point2) -> Circumcentre {
        // The frame's origin is the vertex opposite the longest edge (the largest angle):
        // then `b' × c'` loses at most a few roundings relative to its size however short
        // one edge is, so a triangle with two nearly coincident vertices keeps the filter.
        // (A numerical choice on rounded squared lengths, not a geometric decision: a near
        // tie means either is as accurate. The rotation keeps the orientation.)
        let len2 = |p: Point2, q: Point2| (q.x - p.x).powi(2) + (q.y - p.y).powi(2);
        let (ab, bc, ca) = (len2(a, b), len2(b, c), len2(c, a));
        let (a, b, c) = if ab >= bc && ab >= ca {
            (c, a, b)
        } else if bc >= ca {
            (a, b, c)
        } else {
            (b, c, a)
        };
        let unusable = Circumcentre {
            tri: [a, b, c],
            x: 0.0,
            y: 0.0,
            err_x: f64::INFINITY,
            err_y: f64::INFINITY,
            lb: 0.0,
            lc: 0.0,
            half_d: 0.0,
            rel_d: f64::INFINITY,
            k: 0,
        };
        let (bx, by, cx, cy) = (b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
        let m = bx.abs().max(by.abs()).max(cx.abs()).max(cy.abs());
        // Written so that NaN (from an overflowing difference) fails too.
        if !(m > 0.0 && m < f64::INFINITY) {
            return unusable;
        }
        // The frame: differences times 2^k, the largest in [1, 2). Each scaled difference
        // carries the relative error U of its subtraction, and an absolute error below
        // 2^-1075 if the scaling underflows.
        let k = -exponent(m);
        let [bx, by, cx, cy] = [bx, by, cx, cy].map(|v| times_pow2(v, k));
        let lb = bx * bx + by * by;
        let lc = cx * cx + cy * cy;
        let (t1, t2) = (bx * cy, by * cx);
        let half_d = t1 - t2;
        // Each term of b' × c' passes through four roundings (two differences, the
        // product, the subtraction); of N, through seven (a difference twice in a square,
        // the square, the sum, the product, the subtraction, and the other difference).
        // With every scaled difference below 2, the absolute errors of underflowed
        // operations, however amplified, stay below 2^-1060: SLACK covers them.
        let err_d = 5.0 * U * (t1.abs() + t2.abs()) + SLACK;
        let nx = cy * lb - by * lc;
        let ny = bx * lc - cx * lb;
        let err_nx = 8.0 * U * (cy.abs() * lb + by.abs() * lc) + SLACK;
        let err_ny = 8.0 * U * (bx.abs() * lc + cx.abs() * lb) + SLACK;
        // False for NaN too.
        let conditioned = half_d.abs() > 8.0 * err_d;
        if !conditioned {
            return unusable;
        }
        let rel_d = err_d / half_d.abs();
        let d = 2.0 * half_d;
        let (ox, oy) = (nx / d, ny / d);
        // With |D - D~| <= r |D~| (r <= 1/8) and |N - N~| <= e:
        // |N / D - N~ / D~| <= (|N~ / D~| r + e / |D~|) / (1 - r), and the division adds
        // U |o| (8/7 and the roundings of this bound fit in 1.25).
        let err_ox = 1.25 * (ox.abs() * (rel_d + U) + err_nx / d.abs()) + SLACK;
        let err_oy = 1.25 * (oy.abs() * (rel_d + U) + err_ny / d.abs()) + SLACK;
        // Back to the input's frame (exact unless it over- or underflows; an underflow
        // errs by at most 2^-1075, covered by the final SLACK), then the addition to `a`.
        let [ox, oy, err_ox, err_oy] = [ox, oy, err_ox, err_oy].map(|v| times_pow2(v, -k));
        let (x, y) = (a.x + ox, a.y + oy);
        let err_x = (err_ox + U * x.abs()) * GROW + SLACK;
        let err_y = (err_oy + U * y.abs()) * GROW + SLACK;
        if !(x.is_finite() && y.is_finite() && err_x.is_finite() && err_y.is_finite()) {
            return unusable;
        }
        Circumcentre {
            tri: [a, b, c],
            x,
            y,
            err_x,
            err_y,
            lb,
            lc,
            half_d,
            rel_d,
            k,
        }
    }

    /// The rounded centre and bounds on the errors of its coordinates (infinite when the
    /// filter could not bound them).
    #[inline]
    pub(crate) fn rounded(&self) -> (Point2, f64, f64) {
        (Point2::new(self.x, self.y), self.err_x, self.err_y)
    }

    /// On which side of the directed line `p → q` the exact circumcentre lies: the sign of
    /// `(q − p) × (X − p)`, as [`orient2d`](super::orient2d)`(p, q, X)` would give for the
    /// exact centre `X`. [`Orientation::CounterClockwise`] means left of the line,
    /// [`Orientation::Collinear`] on it (or `p = q`).
    #[inline]
    pub(crate) fn orient(&self, p: Point2, q: Point2) -> Orientation {
        // orient2d's filter on the rounded centre (Shewchuk's bound (3 + 16 U) U, here
        // 4 U to leave room for the rounding of the sum below), widened by what the
        // centre's error can change: |gx| err_y + |gy| err_x for the exact g = q - p
        // (|g| <= |g~| (1 + U); 1 + 16 U covers that and the bound's roundings).
        let (gx, gy) = (q.x - p.x, q.y - p.y);
        let (dx, dy) = (self.x - p.x, self.y - p.y);
        let (t1, t2) = (gx * dy, gy * dx);
        let det = t1 - t2;
        let bound = 4.0 * U * (t1.abs() + t2.abs())
            + (gx.abs() * self.err_y + gy.abs() * self.err_x) * (1.0 + 16.0 * U)
            + SLACK;
        if det > bound {
            Orientation::CounterClockwise
        } else if -det > bound {
            Orientation::Clockwise
        } else {
            self.orient_exact(p, q)
        }
    }

    #[cold]
    #[inline(never)]
    fn orient_exact(&self, p: Point2, q: Point2) -> Orientation {
        let [a, b, c] = self.tri;
        let ([ax, ay, bx, by, cx, cy, px, py, qx, qy], _) =
            exact_coords([a.x, a.y, b.x, b.y, c.x, c.y, p.x, p.y, q.x, q.y]);
        let (ubx, uby) = (bx.sub(&ax), by.sub(&ay));
        let (ucx, ucy) = (cx.sub(&ax), cy.sub(&ay));
        let lb = square_sum(&ubx, &uby);
        let lc = square_sum(&ucx, &ucy);
        let half_d = ubx.mul(&ucy).sub(&uby.mul(&ucx));
        let d = half_d.add(&half_d);
        let nx = ucy.mul(&lb).sub(&uby.mul(&lc));
        let ny = ubx.mul(&lc).sub(&ucx.mul(&lb));
        // (q - p) x ((a - p) D + N), and X - p = ((a - p) D + N) / D.
        let vx = ax.sub(&px).mul(&d).add(&nx);
        let vy = ay.sub(&py).mul(&d).add(&ny);
        let det = qx.sub(&px).mul(&vy).sub(&qy.sub(&py).mul(&vx));
        Orientation::from_sign(det.signum() * half_d.signum())
    }

    /// The squared radius of the circumcircle.
    pub(crate) fn squared_radius(&self) -> SquaredRadius {
        SquaredRadius::circumcircle(self.tri, self.approx_squared_radius())
    }

    /// `r² = |b − c|² |b'|² |c'|² / (4 (b' × c')²)` in the triangle's frame. Each squared
    /// length has relative error at most 4 U (no cancellation: the leaf's rounding twice,
    /// the square, the sum), the determinant at most `rel_d <= 1/8`, so `r²` is within
    /// `3 rel_d + 24 U` (four more roundings; `(1 − 1/8)^-2 − 1 < 2.62 / 8`); 4 U more pay
    /// for the comparison's own roundings.
    fn approx_squared_radius(&self) -> Option<Approx> {
        if self.rel_d > 0.125 {
            return None;
        }
        let [_, b, c] = self.tri;
        let (ax, ay) = (times_pow2(c.x - b.x, self.k), times_pow2(c.y - b.y, self.k));
        let la = ax * ax + ay * ay;
        let factors = [la, self.lb, self.lc, self.half_d.abs()];
        if !factors
            .iter()
            .all(|f| (TINY_FACTOR..f64::INFINITY).contains(f))
        {
            return None;
        }
        let v = la * self.lb * self.lc / (4.0 * self.half_d * self.half_d);
        Approx::new(v, -2 * self.k, 3.0 * self.rel_d + 28.0 * U)
    }
}

/// [`Circumcentre::orient`] counted as one orientation test, for algorithms generic over a
/// [`Counter`].
pub(crate) trait CountedCirclePredicates: Counter {
    /// [`Circumcentre::orient`] of `x` against the line `p → q`, counted as one
    /// orientation test.
    #[inline]
    fn orient_circumcentre(&mut self, p: Point2, q: Point2, x: &Circumcentre) -> Orientation {
        self.orientation_test();
        x.orient(p, q)
    }
}

impl<C: Counter + ?Sized> CountedCirclePredicates for C {}

/// The sign of the dot product `(b − a) · (d − c)`, exact for every finite input:
/// `Ordering::Greater` when the directions of `b − a` and `d − c` make an acute angle,
/// `Equal` when they are perpendicular (or one is zero).
///
/// It is [`cross_sign`] of the first edge turned by a quarter: with `rot(x, y) = (−y, x)`
/// (exact), `rot(b − a) × (d − c) = −(b − a) · (d − c)`.
#[inline]
pub(crate) fn dot_sign(a: Point2, b: Point2, c: Point2, d: Point2) -> Ordering {
    let rot = |p: Point2| Point2::new(-p.y, p.x);
    match cross_sign(rot(a), rot(b), c, d) {
        Orientation::Clockwise => Ordering::Greater,
        Orientation::CounterClockwise => Ordering::Less,
        Orientation::Collinear => Ordering::Equal,
    }
}

/// Compares where the hull edge `p → q` (its line) crosses the bisector of `s` and `w` with
/// where it crosses the bisector of `s` and `v`: `Ordering::Less` if the first crossing
/// comes first along `p → q` (`t_w < t_v`), `Equal` if they are the same point.
///
/// Precondition: moving from `p` towards `q` approaches both `w` and `v`:
/// `(q − p) · (w − s) > 0` and `(q − p) · (v − s) > 0` ([`dot_sign`]), so both parameters
/// `t = N / (2 D)` have positive denominators and the predicate is the sign of
/// `N_w D_v − N_v D_w`.
pub(crate) fn cmp_bisector_crossings(
    p: Point2,
    q: Point2,
    s: Point2,
    w: Point2,
    v: Point2,
) -> Ordering {
    let leaves = scaled_differences([
        (q.x, p.x),
        (q.y, p.y),
        (w.x, s.x),
        (w.y, s.y),
        (v.x, s.x),
        (v.y, s.y),
        (w.x, p.x),
        (w.y, p.y),
        (v.x, p.x),
        (v.y, p.y),
        (s.x, p.x),
        (s.y, p.y),
    ]);
    // Homogeneous of degree 4 in the differences: the common scale does not change the
    // sign.
    if let Some(([gx, gy, uwx, uwy, uvx, uvy, dwx, dwy, dvx, dvy, dsx, dsy], _)) = leaves {
        let dot = |ax: Ball, ay: Ball, bx: Ball, by: Ball| ax.mul(bx).add(ay.mul(by));
        let nw = dot(uwx, uwy, dwx.add(dsx), dwy.add(dsy));
        let nv = dot(uvx, uvy, dvx.add(dsx), dvy.add(dsy));
        let den_w = dot(gx, gy, uwx, uwy);
        let den_v = dot(gx, gy, uvx, uvy);
        if let Some(order) = nw.mul(den_v).sub(nv.mul(den_w)).sign() {
            return order;
        }
    }
    cmp_bisector_crossings_exact(p, q, s, w, v)
}

#[cold]
#[inline(never)]
fn cmp_bisector_crossings_exact(p: Point2, q: Point2, s: Point2, w: Point2, v: Point2) -> Ordering {
    let ([px, py, qx, qy, sx, sy, wx, wy, vx, vy], _) =
        exact_coords([p.x, p.y, q.x, q.y, s.x, s.y, w.x, w.y, v.x, v.y]);
    let (gx, gy) = (qx.sub(&px), qy.sub(&py));
    let (dsx, dsy) = (sx.sub(&px), sy.sub(&py));
    let form = |x: &BigInt, y: &BigInt| {
        let (ux, uy) = (x.sub(&sx), y.sub(&sy));
        let n = dot(&ux, &uy, &x.sub(&px).add(&dsx), &y.sub(&py).add(&dsy));
        (n, dot(&gx, &gy, &ux, &uy))
    };
    let (nw, den_w) = form(&wx, &wy);
    let (nv, den_v) = form(&vx, &vy);
    nw.mul(&den_v).sub(&nv.mul(&den_w)).signum().cmp(&0)
}

fn square_sum(x: &BigInt, y: &BigInt) -> BigInt {
    x.mul(x).add(&y.mul(y))
}

fn dot(ax: &BigInt, ay: &BigInt, bx: &BigInt, by: &BigInt) -> BigInt {
    ax.mul(bx).add(&ay.mul(by))
}

#[cfg(test)]
mod tests;
