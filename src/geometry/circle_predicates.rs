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
//!    exact double ([`GridFactors`]), and two such radii are compared from the factors
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

use super::bigint::BigInt;
use super::expansion::two_diff;
use super::extended::{decompose, exponent, scale_by_pow2};
use super::predicates::{pow2, UNDERFLOW_SLACK};
use super::{cross_sign, Orientation, Point2};
use crate::count::Counter;
use std::cell::OnceCell;
use std::cmp::Ordering;

/// The unit roundoff 2^-53: a rounding to nearest errs by at most `U` times the result.
const U: f64 = f64::EPSILON / 2.0;

/// Absolute slack for roundings that underflow (each errs by at most 2^-1075).
const SLACK: f64 = UNDERFLOW_SLACK;

/// Factor that covers the roundings of an error bound's own evaluation (at most six, each
/// relative `U`, where it is used).
const GROW: f64 = 1.0 + 8.0 * U;

/// Squared lengths and determinants below this (in a frame where the largest difference is
/// in `[1, 2)`) make the squared radius's filter give up: products of three of them stay
/// normal.
const TINY_FACTOR: f64 = pow2(-300);

/// The circumcentre of a triangle as an exact rational point, with a rounded approximation
/// and a bound on its error for the filters.
///
/// Built once per triangle; [`Circumcentre::orient`] then tells on which side of a directed
/// line the exact centre lies, and [`Circumcentre::squared_radius`] gives the circle's
/// squared radius for [`SquaredRadius::cmp`].
#[derive(Debug, Clone)]
pub(crate) struct Circumcentre {
    /// The triangle, for the exact stage.
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
    pub(crate) fn new(a: Point2, b: Point2, c: Point2) -> Circumcentre {
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
        SquaredRadius {
            circle: Circle::Circumcircle(self.tri),
            approx: self.approx_squared_radius(),
            grid: OnceCell::new(),
            exact: OnceCell::new(),
        }
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

/// The squared radius of a candidate circle of the largest empty circle, compared exactly
/// by [`SquaredRadius::cmp`].
///
/// Kept as its defining points (for the exact stages, each computed once on demand) and,
/// when the filter can bound it, an approximation with a relative error bound.
#[derive(Debug, Clone)]
pub(crate) struct SquaredRadius {
    circle: Circle,
    approx: Option<Approx>,
    grid: OnceCell<Option<GridFactors>>,
    exact: OnceCell<Exact>,
}

/// What defines a candidate circle.
#[derive(Debug, Clone, Copy)]
enum Circle {
    /// Radius zero (a circle centred on an input point).
    Point,
    /// The circumcircle of a triangle.
    Circumcircle([Point2; 3]),
    /// `[p, q, s, w]`: centred where the hull edge `p → q` crosses the bisector of `s` and
    /// `w`, through both.
    Crossing([Point2; 4]),
}

/// `r² ∈ [m (1 − rel), m (1 + rel)] · 2^exp` with `m ∈ [1, 2)` and `rel <= 1/4`; `rel`
/// includes the roundings of [`Approx::cmp`].
#[derive(Debug, Clone, Copy)]
struct Approx {
    mantissa: f64,
    exp: i32,
    rel: f64,
}

/// `r² = num / den · 2^(2 base)`, `den > 0`.
#[derive(Debug, Clone)]
struct Exact {
    num: BigInt,
    den: BigInt,
    base: i32,
}

impl SquaredRadius {
    /// Zero: the circle of radius 0 centred on an input point.
    pub(crate) fn zero() -> SquaredRadius {
        SquaredRadius {
            circle: Circle::Point,
            approx: None,
            grid: OnceCell::new(),
            exact: OnceCell::new(),
        }
    }

    /// The squared radius of the circle centred where the hull edge `p → q` crosses the
    /// bisector of `s` and `w`, through `s` and `w`. Precondition: `(q − p) · (w − s) > 0`.
    pub(crate) fn crossing(p: Point2, q: Point2, s: Point2, w: Point2) -> SquaredRadius {
        let leaves = scaled_differences([
            (q.x, p.x),
            (q.y, p.y),
            (w.x, s.x),
            (w.y, s.y),
            (w.x, p.x),
            (w.y, p.y),
            (s.x, p.x),
            (s.y, p.y),
        ]);
        let approx = leaves.and_then(|([gx, gy, ux, uy, dwx, dwy, dsx, dsy], k)| {
            let d = gx.mul(ux).add(gy.mul(uy));
            let n = ux.mul(dwx.add(dsx)).add(uy.mul(dwy.add(dsy)));
            // V = 2 D (p - s) + N g, r^2 = |V|^2 / (4 D^2).
            let two_d = d.twice();
            let vx = n.mul(gx).sub(two_d.mul(dsx));
            let vy = n.mul(gy).sub(two_d.mul(dsy));
            let num = vx.mul(vx).add(vy.mul(vy));
            let r2 = num.div(two_d.mul(two_d))?;
            let rel = r2.rad / r2.mid + 4.0 * U;
            Approx::new(r2.mid, -2 * k, rel)
        });
        SquaredRadius {
            circle: Circle::Crossing([p, q, s, w]),
            approx,
            grid: OnceCell::new(),
            exact: OnceCell::new(),
        }
    }

    /// Compares two squared radii exactly: `Ordering::Greater` if `self` is the larger.
    pub(crate) fn cmp(&self, other: &SquaredRadius) -> Ordering {
        match (self.circle, other.circle) {
            (Circle::Point, Circle::Point) => return Ordering::Equal,
            // Every other candidate has a positive radius: a circumcircle of a proper
            // triangle, or a crossing point, which is equidistant from two distinct sites.
            (Circle::Point, _) => return Ordering::Less,
            (_, Circle::Point) => return Ordering::Greater,
            _ => {}
        }
        if let (Some(a), Some(b)) = (self.approx, other.approx) {
            if let Some(order) = a.cmp(&b) {
                return order;
            }
        }
        // Lattices tie everywhere (every triangle of a grid has the same circumradius):
        // their factors are exact doubles, compared without big integers.
        if let (Some(f1), Some(f2)) = (self.grid(), other.grid()) {
            return f1.cmp(f2);
        }
        self.exact().cmp(other.exact())
    }

    /// The exact factors of a lattice circumcircle, computed once on demand.
    fn grid(&self) -> Option<&GridFactors> {
        self.grid
            .get_or_init(|| match self.circle {
                Circle::Circumcircle(t) => GridFactors::new(t),
                _ => None,
            })
            .as_ref()
    }

    fn exact(&self) -> &Exact {
        self.exact.get_or_init(|| match self.circle {
            Circle::Point => Exact {
                num: BigInt::from_parts(false, 0, 0),
                den: BigInt::from_parts(false, 1, 0),
                base: 0,
            },
            Circle::Circumcircle([a, b, c]) => {
                let ([ax, ay, bx, by, cx, cy], base) = exact_coords([a.x, a.y, b.x, b.y, c.x, c.y]);
                let (ubx, uby) = (bx.sub(&ax), by.sub(&ay));
                let (ucx, ucy) = (cx.sub(&ax), cy.sub(&ay));
                let la = square_sum(&cx.sub(&bx), &cy.sub(&by));
                let half_d = ubx.mul(&ucy).sub(&uby.mul(&ucx));
                Exact {
                    num: la.mul(&square_sum(&ubx, &uby)).mul(&square_sum(&ucx, &ucy)),
                    den: BigInt::from_parts(false, 4, 0).mul(&half_d.mul(&half_d)),
                    base,
                }
            }
            Circle::Crossing([p, q, s, w]) => {
                let ([px, py, qx, qy, sx, sy, wx, wy], base) =
                    exact_coords([p.x, p.y, q.x, q.y, s.x, s.y, w.x, w.y]);
                let (gx, gy) = (qx.sub(&px), qy.sub(&py));
                let (ux, uy) = (wx.sub(&sx), wy.sub(&sy));
                let (dsx, dsy) = (sx.sub(&px), sy.sub(&py));
                let d = dot(&gx, &gy, &ux, &uy);
                let n = dot(&ux, &uy, &wx.sub(&px).add(&dsx), &wy.sub(&py).add(&dsy));
                let two_d = d.add(&d);
                let vx = n.mul(&gx).sub(&two_d.mul(&dsx));
                let vy = n.mul(&gy).sub(&two_d.mul(&dsy));
                Exact {
                    num: square_sum(&vx, &vy),
                    den: two_d.mul(&two_d),
                    base,
                }
            }
        })
    }
}

impl Approx {
    /// `value · 2^exp` with relative error `rel`, if `value` is a positive normal double
    /// and `rel <= 1/4`.
    fn new(value: f64, exp: i32, rel: f64) -> Option<Approx> {
        let usable = (f64::MIN_POSITIVE..f64::INFINITY).contains(&value) && rel <= 0.25;
        usable.then(|| {
            let e = exponent(value);
            Approx {
                mantissa: scale_by_pow2(value, -e),
                exp: exp + e,
                rel,
            }
        })
    }

    /// The order of the exact values if the enclosures decide it.
    fn cmp(&self, other: &Approx) -> Option<Ordering> {
        // Each value is in [3/4, 5/2) · 2^exp: two binades apart decide by exponent.
        let shift = self.exp - other.exp;
        if shift >= 2 {
            return Some(Ordering::Greater);
        }
        if shift <= -2 {
            return Some(Ordering::Less);
        }
        let m = self.mantissa * pow2(shift);
        let (lo, hi) = (m * (1.0 - self.rel), m * (1.0 + self.rel));
        let (other_lo, other_hi) = (
            other.mantissa * (1.0 - other.rel),
            other.mantissa * (1.0 + other.rel),
        );
        if lo > other_hi {
            Some(Ordering::Greater)
        } else if hi < other_lo {
            Some(Ordering::Less)
        } else {
            None
        }
    }
}

impl Exact {
    /// `num₁ den₂ 2^(2 base₁)` against `num₂ den₁ 2^(2 base₂)`.
    fn cmp(&self, other: &Exact) -> Ordering {
        let mut lhs = self.num.mul(&other.den);
        let mut rhs = other.num.mul(&self.den);
        let shift = 2 * (self.base - other.base);
        if shift > 0 {
            lhs = lhs.mul(&BigInt::from_parts(false, 1, shift as u32));
        } else if shift < 0 {
            rhs = rhs.mul(&BigInt::from_parts(false, 1, (-shift) as u32));
        }
        lhs.sub(&rhs).signum().cmp(&0)
    }
}

/// A circumcircle's squared radius `r² = la lb lc / (4 hd²) · 2^(−2k)` from factors that are
/// exact doubles: in the triangle's frame (differences from `a` times `2^k`, the largest in
/// `[1, 2)`, so `|c − b| < 4`) every difference is exact and a multiple of 2^-24, so it has
/// at most 26 significant bits, its squares and products at most 52, and the sums of two
/// of those (multiples of 2^-48 below 2^5) at most 53: nothing rounds. Integer grids and
/// lattices at any scale and position qualify, triangle by triangle.
#[derive(Debug, Clone, Copy)]
struct GridFactors {
    /// `|b − c|², |b − a|², |c − a|²` in increasing order and `|(b − a) × (c − a)|`, in
    /// the frame.
    l: [f64; 3],
    hd: f64,
    k: i32,
}

impl GridFactors {
    fn new([a, b, c]: [Point2; 3]) -> Option<GridFactors> {
        let pairs = [
            (b.x, a.x),
            (b.y, a.y),
            (c.x, a.x),
            (c.y, a.y),
            (c.x, b.x),
            (c.y, b.y),
        ];
        // Every difference exact (a finite difference with no rounding error), folded
        // without branches: this runs on every tie of a lattice.
        let mut exact = true;
        let d = pairs.map(|(x, y)| {
            let (v, err) = two_diff(x, y);
            exact &= (err == 0.0) & v.is_finite();
            v
        });
        let m = d[..4].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if !exact || m == 0.0 {
            return None;
        }
        let k = -exponent(m);
        let mut grid = true;
        let f = d.map(|v| {
            let scaled = times_pow2(v, k);
            // A multiple of 2^-24 (t < 2^26 since |scaled| < 4; adding 2^52 rounds t to an
            // integer), and no nonzero difference lost to underflow.
            let t = scaled.abs() * pow2(24);
            grid &= ((t + pow2(52)) - pow2(52) == t) & ((scaled == 0.0) == (v == 0.0));
            scaled
        });
        let [bx, by, cx, cy, ax, ay] = f;
        let hd = (bx * cy - by * cx).abs();
        if !grid || hd == 0.0 {
            return None;
        }
        let mut l = [ax * ax + ay * ay, bx * bx + by * by, cx * cx + cy * cy];
        // Sorted, so that congruent triangles have equal fields.
        if l[0] > l[1] {
            l.swap(0, 1);
        }
        if l[1] > l[2] {
            l.swap(1, 2);
        }
        if l[0] > l[1] {
            l.swap(0, 1);
        }
        Some(GridFactors { l, hd, k })
    }

    /// `l₁ l₂ l₃ hd'² 2^(−2k)` against `l'₁ l'₂ l'₃ hd² 2^(−2k')`: the squared radii with
    /// the denominators cleared. Congruent triangles in frames of one scale (every triangle
    /// of a grid) have equal fields and need no products.
    fn cmp(&self, o: &GridFactors) -> Ordering {
        if self.l == o.l && self.hd == o.hd && self.k == o.k {
            return Ordering::Equal;
        }
        let [l1, l2, l3] = self.l;
        let [m1, m2, m3] = o.l;
        let lhs = [l1, l2, l3, o.hd, o.hd];
        let rhs = [m1, m2, m3, self.hd, self.hd];
        cmp_products(lhs, -2 * self.k, rhs, -2 * o.k)
    }
}

/// Compares `Π lhs · 2^e₁` with `Π rhs · 2^e₂` for positive finite doubles, exactly: the
/// products of the five odd mantissas in one `u128` when they fit (lattices: small odd
/// parts), else of the five integer mantissas (at most 5 · 53 bits) in 64-bit limbs.
fn cmp_products(lhs: [f64; 5], e1: i32, rhs: [f64; 5], e2: i32) -> Ordering {
    /// The product of the odd parts and its exponent, if its bits (at most the sum of the
    /// factors' lengths) fit.
    fn odd_product(v: [f64; 5], e0: i32) -> Option<(u128, i32)> {
        let (mut p, mut e, mut bits) = (1u128, e0, 0);
        for x in v {
            let (_, m, ex) = decompose(x);
            let zeros = m.trailing_zeros();
            let m = m >> zeros;
            bits += 64 - m.leading_zeros();
            if bits > 127 {
                return None;
            }
            p *= m as u128;
            e += ex + zeros as i32;
        }
        Some((p, e))
    }
    if let (Some((x, ex)), Some((y, ey))) = (odd_product(lhs, e1), odd_product(rhs, e2)) {
        let top = |v: u128, e: i32| 128 - v.leading_zeros() as i32 + e;
        return match top(x, ex).cmp(&top(y, ey)) {
            // Equal tops: the shift is the length difference, so the result fits.
            Ordering::Equal if ex >= ey => (x << (ex - ey)).cmp(&y),
            Ordering::Equal => x.cmp(&(y << (ey - ex))),
            order => order,
        };
    }
    /// Little-endian limbs of the product and its exponent.
    fn product(v: [f64; 5], e0: i32) -> ([u64; 5], i32) {
        let mut limbs = [1u64, 0, 0, 0, 0];
        let mut e = e0;
        for x in v {
            let (_, m, ex) = decompose(x);
            let mut carry = 0u128;
            for limb in limbs.iter_mut() {
                let t = *limb as u128 * m as u128 + carry;
                *limb = t as u64;
                carry = t >> 64;
            }
            e += ex;
        }
        (limbs, e)
    }
    fn bits(l: &[u64; 5]) -> i32 {
        (0..5)
            .rev()
            .find(|&i| l[i] != 0)
            .map_or(0, |i| 64 * i as i32 + 64 - l[i].leading_zeros() as i32)
    }
    /// `l · 2^s`, known to fit.
    fn shifted(l: &[u64; 5], s: i32) -> [u64; 5] {
        let (words, bit) = ((s / 64) as usize, (s % 64) as u32);
        let mut out = [0u64; 5];
        for i in (words..5).rev() {
            let lo = l[i - words] << bit;
            let hi = if bit > 0 && i > words {
                l[i - words - 1] >> (64 - bit)
            } else {
                0
            };
            out[i] = lo | hi;
        }
        out
    }
    let ((x, ex), (y, ey)) = (product(lhs, e1), product(rhs, e2));
    // The leading bits' positions first; equal, the exponents differ by at most the
    // products' length difference, and the shifted one still fits in five limbs.
    match (bits(&x) + ex).cmp(&(bits(&y) + ey)) {
        Ordering::Equal => {}
        order => return order,
    }
    let (x, y) = if ex >= ey {
        (shifted(&x, ex - ey), y)
    } else {
        (x, shifted(&y, ey - ex))
    };
    x.iter().rev().cmp(y.iter().rev())
}

/// A value and a bound on its distance to an exact real (midpoint–radius arithmetic): every
/// operation returns a ball that holds the exact result of the operation on any values in
/// its operands' balls. Non-finite parts (overflow) decide nothing.
#[derive(Debug, Clone, Copy)]
struct Ball {
    mid: f64,
    rad: f64,
}

impl Ball {
    /// `a − b` for doubles: rounding to nearest errs by at most `U` times the result (and
    /// not at all when the result is subnormal).
    #[inline]
    fn diff(a: f64, b: f64) -> Ball {
        let mid = a - b;
        Ball {
            mid,
            rad: U * mid.abs(),
        }
    }

    /// Times `2^k`: exact unless it underflows (an error below 2^-1075, covered by SLACK).
    #[inline]
    fn scaled(self, k: i32) -> Ball {
        Ball {
            mid: times_pow2(self.mid, k),
            rad: times_pow2(self.rad, k) + SLACK,
        }
    }

    #[inline]
    fn add(self, o: Ball) -> Ball {
        let mid = self.mid + o.mid;
        Ball {
            mid,
            rad: (self.rad + o.rad + U * mid.abs()) * GROW + SLACK,
        }
    }

    #[inline]
    fn sub(self, o: Ball) -> Ball {
        self.add(Ball {
            mid: -o.mid,
            rad: o.rad,
        })
    }

    /// `|xy − m₁m₂| <= r₁ |m₂| + |m₁| r₂ + r₁ r₂`, plus the product's rounding.
    #[inline]
    fn mul(self, o: Ball) -> Ball {
        let mid = self.mid * o.mid;
        let rad =
            self.rad * o.mid.abs() + self.mid.abs() * o.rad + self.rad * o.rad + U * mid.abs();
        Ball {
            mid,
            rad: rad * GROW + SLACK,
        }
    }

    /// Exact (doubling changes only the exponent; overflow shows as infinity).
    #[inline]
    fn twice(self) -> Ball {
        Ball {
            mid: 2.0 * self.mid,
            rad: 2.0 * self.rad,
        }
    }

    /// `|x / y − m₁ / m₂| <= (r₁ + |m₁ / m₂| r₂) / (|m₂| − r₂)` when `|m₂| > r₂`; `None`
    /// when the divisor's ball holds zero.
    #[inline]
    fn div(self, o: Ball) -> Option<Ball> {
        let gap = o.mid.abs() - o.rad;
        // False for NaN too.
        let excludes_zero = gap > 0.0;
        if !excludes_zero {
            return None;
        }
        let mid = self.mid / o.mid;
        // |m1 / m2| <= |mid| (1 + U) + 2^-1075: SLACK stands for the underflow part.
        let rad = (self.rad + (mid.abs() + SLACK) * o.rad) / gap + U * mid.abs();
        Some(Ball {
            mid,
            rad: rad * GROW + SLACK,
        })
    }

    /// The sign of every value in the ball, if they share one.
    #[inline]
    fn sign(self) -> Option<Ordering> {
        if self.mid > self.rad {
            Some(Ordering::Greater)
        } else if -self.mid > self.rad {
            Some(Ordering::Less)
        } else {
            None
        }
    }
}

/// The differences `x − y` of the pairs as balls, all times one power of two `2^k` that puts
/// the largest into `[1, 2)`, with `k`; `None` if they are all zero or one overflows.
#[inline]
fn scaled_differences<const N: usize>(pairs: [(f64, f64); N]) -> Option<([Ball; N], i32)> {
    let balls = pairs.map(|(x, y)| Ball::diff(x, y));
    let m = balls.iter().fold(0.0f64, |m, b| m.max(b.mid.abs()));
    // Written so that NaN fails too.
    if !(m > 0.0 && m < f64::INFINITY) {
        return None;
    }
    let k = -exponent(m);
    Some((balls.map(|b| b.scaled(k)), k))
}

/// `v · 2^k`, exact when the result is a normal double; one multiplication in the common
/// case.
#[inline]
fn times_pow2(v: f64, k: i32) -> f64 {
    if (-1022..=1023).contains(&k) {
        v * f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        scale_by_pow2(v, k)
    }
}

/// Every coordinate as an exact big integer, all scaled by `2^-base` for the least exponent
/// `base` of their last nonzero bits (0 if all are zero): integer coordinates stay
/// themselves, so the products stay short.
fn exact_coords<const N: usize>(coords: [f64; N]) -> ([BigInt; N], i32) {
    let parts = coords.map(|v| {
        let (negative, m, e) = decompose(v);
        let zeros = if m == 0 { 0 } else { m.trailing_zeros() };
        (negative, m >> zeros, e + zeros as i32)
    });
    let base = parts
        .iter()
        .filter(|&&(_, m, _)| m != 0)
        .map(|&(_, _, e)| e)
        .min()
        .unwrap_or(0);
    let ints = parts.map(|(negative, m, e)| {
        BigInt::from_parts(negative, m, if m == 0 { 0 } else { (e - base) as u32 })
    });
    (ints, base)
}

fn square_sum(x: &BigInt, y: &BigInt) -> BigInt {
    x.mul(x).add(&y.mul(y))
}

fn dot(ax: &BigInt, ay: &BigInt, bx: &BigInt, by: &BigInt) -> BigInt {
    ax.mul(bx).add(&ay.mul(by))
}

#[cfg(test)]
mod tests {
    //! Against an exact rational oracle written from the definitions: the circumcentre as
    //! the solution of `|X − a|² = |X − b|² = |X − c|²` (Cramer's rule on absolute
    //! coordinates), the crossing parameter as `((m − p) · u) / ((q − p) · u)`, squared
    //! radii as squared distances from the exact centre.
    use super::*;
    use num_rational::BigRational;
    use num_traits::{Signed, Zero};
    use proptest::prelude::*;

    type Q = BigRational;

    fn q(v: f64) -> Q {
        Q::from_float(v).expect("finite")
    }

    fn qp(p: Point2) -> (Q, Q) {
        (q(p.x), q(p.y))
    }

    fn sign(x: &Q) -> Ordering {
        x.cmp(&Q::zero())
    }

    fn cross(o: &(Q, Q), a: &(Q, Q), b: &(Q, Q)) -> Q {
        (&a.0 - &o.0) * (&b.1 - &o.1) - (&a.1 - &o.1) * (&b.0 - &o.0)
    }

    fn dist2(a: &(Q, Q), b: &(Q, Q)) -> Q {
        let (dx, dy) = (&a.0 - &b.0, &a.1 - &b.1);
        &dx * &dx + &dy * &dy
    }

    /// 2 (b − a) · X = |b|² − |a|², 2 (c − a) · X = |c|² − |a|², by Cramer's rule.
    fn circumcentre_q(t: [Point2; 3]) -> (Q, Q) {
        let [a, b, c] = t.map(qp);
        let two = Q::from_integer(2.into());
        let norm = |p: &(Q, Q)| &p.0 * &p.0 + &p.1 * &p.1;
        let (m11, m12) = (&two * (&b.0 - &a.0), &two * (&b.1 - &a.1));
        let (m21, m22) = (&two * (&c.0 - &a.0), &two * (&c.1 - &a.1));
        let (r1, r2) = (norm(&b) - norm(&a), norm(&c) - norm(&a));
        let det = &m11 * &m22 - &m12 * &m21;
        (
            (&r1 * &m22 - &m12 * &r2) / &det,
            (&m11 * &r2 - &r1 * &m21) / &det,
        )
    }

    fn orient_oracle(t: [Point2; 3], p: Point2, r: Point2) -> Orientation {
        let x = circumcentre_q(t);
        Orientation::from_sign(sign(&cross(&qp(p), &qp(r), &x)) as i32)
    }

    /// `(q − p) · (w − s)` and `t = ((m − p) · u) / ((q − p) · u)`.
    fn crossing_q(p: Point2, r: Point2, s: Point2, w: Point2) -> (Q, Q) {
        let [p, r, s, w] = [p, r, s, w].map(qp);
        let two = Q::from_integer(2.into());
        let (ux, uy) = (&w.0 - &s.0, &w.1 - &s.1);
        let (mx, my) = ((&s.0 + &w.0) / &two, (&s.1 + &w.1) / &two);
        let den = (&r.0 - &p.0) * &ux + (&r.1 - &p.1) * &uy;
        let num = (mx - &p.0) * &ux + (my - &p.1) * &uy;
        let t = if den.is_zero() { Q::zero() } else { num / &den };
        (den, t)
    }

    fn crossing_point_q(p: Point2, r: Point2, t: &Q) -> (Q, Q) {
        let (p, r) = (qp(p), qp(r));
        (&p.0 + t * (&r.0 - &p.0), &p.1 + t * (&r.1 - &p.1))
    }

    /// A candidate for the oracle: its exact squared radius.
    fn radius_q(c: &Circle) -> Q {
        match *c {
            Circle::Point => Q::zero(),
            Circle::Circumcircle(t) => dist2(&circumcentre_q(t), &qp(t[0])),
            Circle::Crossing([p, r, s, w]) => {
                let (_, t) = crossing_q(p, r, s, w);
                dist2(&crossing_point_q(p, r, &t), &qp(s))
            }
        }
    }

    fn squared_radius(c: &Circle) -> SquaredRadius {
        match *c {
            Circle::Point => SquaredRadius::zero(),
            Circle::Circumcircle([a, b, c]) => Circumcentre::new(a, b, c).squared_radius(),
            Circle::Crossing([p, r, s, w]) => SquaredRadius::crossing(p, r, s, w),
        }
    }

    // ------------------------------------------------------------ adversarial inputs

    /// Moves `v` by `k` ulps, staying finite.
    fn ulps(v: f64, k: i32) -> f64 {
        let mut v = v;
        for _ in 0..k.unsigned_abs() {
            let next = if k > 0 { v.next_up() } else { v.next_down() };
            if next.is_finite() {
                v = next;
            }
        }
        v
    }

    /// Magnitudes: ordinary, far outside every window, subnormal.
    fn scale() -> impl Strategy<Value = f64> {
        prop::sample::select(vec![
            1.0,
            2f64.powi(-40),
            2f64.powi(60),
            1e200,
            1e300,
            1e-300,
            1e-310,
            5e-324,
        ])
    }

    /// A coordinate near the given magnitude: small integers times it (ties), uniform, or
    /// nudged by ulps.
    fn coordinate(s: f64) -> impl Strategy<Value = f64> {
        prop_oneof![
            (-8i32..=8).prop_map(move |k| k as f64 * s),
            (-1.0f64..1.0).prop_map(move |t| t * s),
            (-1.0f64..1.0, -3i32..4).prop_map(move |(t, k)| ulps(t * s, k)),
        ]
        .prop_map(|v| if v.is_finite() { v } else { 0.0 })
    }

    /// A point whose two coordinates pick their own magnitudes (mixed in one call).
    fn point() -> BoxedStrategy<Point2> {
        (
            scale().prop_flat_map(coordinate),
            scale().prop_flat_map(coordinate),
        )
            .prop_map(|(x, y)| Point2::new(x, y))
            .boxed()
    }

    /// A point with both coordinates near one magnitude.
    fn point_at(s: f64) -> BoxedStrategy<Point2> {
        (coordinate(s), coordinate(s))
            .prop_map(|(x, y)| Point2::new(x, y))
            .boxed()
    }

    fn any_finite() -> impl Strategy<Value = f64> {
        any::<u64>().prop_map(|b| {
            let v = f64::from_bits(b);
            if v.is_finite() {
                v
            } else {
                0.0
            }
        })
    }

    fn bits_point() -> BoxedStrategy<Point2> {
        (any_finite(), any_finite())
            .prop_map(|(x, y)| Point2::new(x, y))
            .boxed()
    }

    /// `N` points: mostly of one magnitude per call (the filters' ground, and near ties for
    /// the exact stage), a quarter with magnitudes mixed point by point or from arbitrary
    /// bit patterns (the exact stage on numbers of thousands of bits, which is slow in a
    /// debug build, hence the weights).
    fn points<const N: usize>() -> BoxedStrategy<[Point2; N]> {
        prop_oneof![
            6 => scale().prop_flat_map(|s| proptest::array::uniform::<_, N>(point_at(s))),
            1 => proptest::array::uniform::<_, N>(point()),
            1 => proptest::array::uniform::<_, N>(bits_point()),
        ]
        .boxed()
    }

    /// Three points, not collinear, as [`points`].
    fn triangle() -> BoxedStrategy<[Point2; 3]> {
        points::<3>()
            .prop_filter("collinear", |[a, b, c]| {
                super::super::orient2d(*a, *b, *c) != Orientation::Collinear
            })
            .boxed()
    }

    /// Integer points on x² + y² = 65²: any three are a triangle with centre 0.
    const LATTICE: [(f64, f64); 12] = [
        (65.0, 0.0),
        (63.0, 16.0),
        (60.0, 25.0),
        (56.0, 33.0),
        (52.0, 39.0),
        (39.0, 52.0),
        (33.0, -56.0),
        (-25.0, 60.0),
        (-16.0, -63.0),
        (0.0, 65.0),
        (-60.0, -25.0),
        (-65.0, 0.0),
    ];

    /// `(x + tx, y + ty) · 2^e`: exact for the lattice's small integers at every `e`.
    fn place(v: (f64, f64), t: (i32, i32), e: i32) -> Point2 {
        let s = |x: f64| scale_by_pow2(x, e);
        Point2::new(s(v.0 + t.0 as f64), s(v.1 + t.1 as f64))
    }

    fn exponent_choice() -> impl Strategy<Value = i32> {
        prop::sample::select(vec![0, -3, 40, -60, 900, -1000, -1066])
    }

    /// Lattice points of the circle of radius 65 about `t · 2^e` (`k` of them, distinct),
    /// the centre's translation and the exponent.
    fn lattice_circle(k: usize) -> impl Strategy<Value = (Vec<Point2>, (i32, i32), i32)> {
        (
            proptest::sample::subsequence(LATTICE.to_vec(), k).prop_shuffle(),
            (-40i32..40, -40i32..40),
            exponent_choice(),
        )
            .prop_map(|(pts, t, e)| (pts.into_iter().map(|v| place(v, t, e)).collect(), t, e))
    }

    fn cases(n: u32) -> ProptestConfig {
        ProptestConfig {
            cases: n,
            ..ProptestConfig::default()
        }
    }

    proptest! {
        #![proptest_config(cases(300))]

        #[test]
        fn circumcentre_side_matches_the_oracle(t in triangle(), [p, r] in points::<2>()) {
            let x = Circumcentre::new(t[0], t[1], t[2]);
            prop_assert_eq!(x.orient(p, r), orient_oracle(t, p, r));
        }

        #[test]
        fn circumcentre_side_on_arbitrary_bit_patterns(
            t in triangle(), p in bits_point(), r in bits_point(),
        ) {
            let x = Circumcentre::new(t[0], t[1], t[2]);
            prop_assert_eq!(x.orient(p, r), orient_oracle(t, p, r));
        }

        #[test]
        fn circumcentre_side_a_few_ulps_from_the_line(
            t in triangle(), [r] in points::<1>(), kx in -3i32..4, ky in -3i32..4,
        ) {
            // The line through the rounded centre (moved by ulps) and another point: the
            // exact centre is within a few rounding errors of it.
            let x = Circumcentre::new(t[0], t[1], t[2]);
            prop_assume!(x.err_x.is_finite());
            let p = Point2::new(ulps(x.x, kx), ulps(x.y, ky));
            prop_assert_eq!(x.orient(p, r), orient_oracle(t, p, r));
            prop_assert_eq!(x.orient(r, p), orient_oracle(t, r, p));
        }

        #[test]
        fn circumcentre_exactly_on_the_line(
            (pts, t, e) in lattice_circle(4), k in -3i32..4, far in 1i32..50, nudge in -2i32..3,
        ) {
            // The centre t · 2^e of a lattice circle, on the line through a lattice point
            // and its reflection through the centre scaled by `far`: collinear exactly,
            // and a nudged endpoint makes a near tie.
            let centre = place((0.0, 0.0), t, e);
            let v = pts[3];
            let (dx, dy) = (v.x - centre.x, v.y - centre.y);
            let r = Point2::new(centre.x - far as f64 * dx, centre.y - far as f64 * dy);
            prop_assume!(r.is_finite());
            let x = Circumcentre::new(pts[0], pts[1], pts[2]);
            prop_assert_eq!(x.orient(v, r), Orientation::Collinear);
            let r = Point2::new(ulps(r.x, k), ulps(r.y, nudge));
            prop_assert_eq!(x.orient(v, r), orient_oracle([pts[0], pts[1], pts[2]], v, r));
        }

        #[test]
        fn dot_sign_matches_the_oracle([a, b, c, d] in points::<4>(), perp in any::<bool>()) {
            // Half of the cases perpendicular exactly: d − c = rot(b − a) when that is exact.
            let d = if perp { Point2::new(c.x - (b.y - a.y), c.y + (b.x - a.x)) } else { d };
            prop_assume!(d.is_finite());
            let [a, b, c, d] = [a, b, c, d].map(qp);
            let exact = (&b.0 - &a.0) * (&d.0 - &c.0) + (&b.1 - &a.1) * (&d.1 - &c.1);
            let [a, b, c, d] = [a, b, c, d].map(|(x, y)| {
                Point2::new(num_traits::ToPrimitive::to_f64(&x).unwrap(), num_traits::ToPrimitive::to_f64(&y).unwrap())
            });
            prop_assert_eq!(dot_sign(a, b, c, d), sign(&exact));
        }

        #[test]
        fn bisector_crossings_match_the_oracle(
            [p, r, s, w, v] in points::<5>(),
        ) {
            let ((dw, tw), (dv, tv)) = (crossing_q(p, r, s, w), crossing_q(p, r, s, v));
            prop_assume!(dw.is_positive() && dv.is_positive());
            prop_assert_eq!(cmp_bisector_crossings(p, r, s, w, v), tw.cmp(&tv));
            prop_assert_eq!(cmp_bisector_crossings(p, r, s, v, w), tv.cmp(&tw));
        }

        #[test]
        fn bisector_crossings_tie_at_a_voronoi_vertex_on_the_edge(
            (pts, t, e) in lattice_circle(3), dir in 0usize..12, len in 1i32..200,
            nudge in -2i32..3,
        ) {
            // s, w, v on a lattice circle whose centre is on the line p → r: both
            // bisectors cross it at the centre; nudging r by ulps breaks the tie.
            let centre = place((0.0, 0.0), t, e);
            let (dx, dy) = (LATTICE[dir].0 * len as f64, LATTICE[dir].1 * len as f64);
            let p = Point2::new(centre.x - scale_by_pow2(dx, e), centre.y - scale_by_pow2(dy, e));
            let r = Point2::new(centre.x + scale_by_pow2(dx, e), centre.y + scale_by_pow2(dy, e));
            let [s, w, v] = [pts[0], pts[1], pts[2]];
            let (p, r) = if crossing_q(p, r, s, w).0.is_positive() { (p, r) } else { (r, p) };
            prop_assume!(crossing_q(p, r, s, v).0.is_positive());
            prop_assert_eq!(cmp_bisector_crossings(p, r, s, w, v), Ordering::Equal);
            let r = Point2::new(ulps(r.x, nudge), r.y);
            let ((dw, tw), (dv, tv)) = (crossing_q(p, r, s, w), crossing_q(p, r, s, v));
            prop_assume!(dw.is_positive() && dv.is_positive());
            prop_assert_eq!(cmp_bisector_crossings(p, r, s, w, v), tw.cmp(&tv));
        }

        #[test]
        fn squared_radii_match_the_oracle(
            t1 in triangle(), t2 in triangle(), [p, r, s, w] in points::<4>(),
            kinds in (0usize..3, 0usize..3),
        ) {
            let crossing = if crossing_q(p, r, s, w).0.is_positive() {
                Circle::Crossing([p, r, s, w])
            } else {
                Circle::Crossing([r, p, s, w])
            };
            prop_assume!(!crossing_q(p, r, s, w).0.is_zero());
            let pick = |k: usize, t: [Point2; 3]| match k {
                0 => Circle::Circumcircle(t),
                1 => crossing,
                _ => Circle::Point,
            };
            let (c1, c2) = (pick(kinds.0, t1), pick(kinds.1, t2));
            let (a, b) = (squared_radius(&c1), squared_radius(&c2));
            let expected = radius_q(&c1).cmp(&radius_q(&c2));
            prop_assert_eq!(a.cmp(&b), expected);
            prop_assert_eq!(b.cmp(&a), expected.reverse());
        }
    }

    proptest! {
        // Each case compares up to 25 pairs of circles.
        #![proptest_config(cases(120))]

        #[test]
        fn squared_radii_tie_exactly(
            (pts, t, e) in lattice_circle(6), shift in (-30i32..30, -30i32..30),
            dir in 0usize..12, len in 1i32..100, nudge in -2i32..3,
        ) {
            // One lattice circle through several triples, a translate (integer offsets:
            // exact) and a crossing at its centre all have radius 65 · 2^e; a nudged
            // vertex breaks the tie by a few ulps.
            let tri = [pts[0], pts[1], pts[2]];
            let other = [pts[3], pts[4], pts[5]];
            let moved = tri.map(|v| Point2::new(
                v.x + scale_by_pow2(shift.0 as f64, e),
                v.y + scale_by_pow2(shift.1 as f64, e),
            ));
            let centre = place((0.0, 0.0), t, e);
            let (dx, dy) = (LATTICE[dir].0 * len as f64, LATTICE[dir].1 * len as f64);
            let p = Point2::new(centre.x - scale_by_pow2(dx, e), centre.y - scale_by_pow2(dy, e));
            let r = Point2::new(centre.x + scale_by_pow2(dx, e), centre.y + scale_by_pow2(dy, e));
            let (p, r) = if crossing_q(p, r, pts[0], pts[1]).0.is_positive() { (p, r) } else { (r, p) };
            let mut circles = vec![Circle::Circumcircle(tri), Circle::Circumcircle(other)];
            if moved.iter().all(|v| v.is_finite()) {
                circles.push(Circle::Circumcircle(moved));
            }
            if !crossing_q(p, r, pts[0], pts[1]).0.is_zero() {
                circles.push(Circle::Crossing([p, r, pts[0], pts[1]]));
            }
            let nudged = [pts[0], pts[1], Point2::new(ulps(pts[2].x, nudge), pts[2].y)];
            if super::super::orient2d(nudged[0], nudged[1], nudged[2]) != Orientation::Collinear {
                circles.push(Circle::Circumcircle(nudged));
            }
            for c1 in &circles {
                for c2 in &circles {
                    let expected = radius_q(c1).cmp(&radius_q(c2));
                    prop_assert_eq!(squared_radius(c1).cmp(&squared_radius(c2)), expected);
                }
            }
            prop_assert_eq!(squared_radius(&circles[0]).cmp(&squared_radius(&circles[1])), Ordering::Equal);
        }
    }

    #[test]
    fn filters_decide_ordinary_input_without_the_exact_stage() {
        // Triangles of ordinary shape at ordinary and extreme magnitudes: the filters'
        // bounds are finite and tight (the centre's up to the absolute slack 2^-1000,
        // which is why the algorithm scales its input to magnitudes near 1 first), so the
        // exact stage is not needed.
        for s in [
            1.0,
            2f64.powi(-400),
            1e300,
            1e-300,
            scale_by_pow2(1.0, -1060),
        ] {
            let p = |x: f64, y: f64| Point2::new(x * s, y * s);
            let x = Circumcentre::new(p(0.1, 0.2), p(3.7, -1.1), p(2.0, 5.5));
            let tight = |err: f64, v: f64| err <= 1e-14 * v.abs() + 2.0 * SLACK;
            assert!(tight(x.err_x, x.x) && tight(x.err_y, x.y), "{x:?}");
            if s == 1.0 {
                let (o, q) = (Point2::new(0.0, 0.0), Point2::new(1.0, 0.0));
                let det = |v: f64| v.abs() > 1e-13;
                assert!(det(x.x) && det(x.y));
                // Decided by the filter: the bound is far below |det|.
                assert_eq!(x.orient(o, q), Orientation::from_sign(x.y.signum() as i32));
            }
            let r2 = x.squared_radius().approx.expect("filtered");
            assert!(r2.rel < 1e-14);
            let c = SquaredRadius::crossing(p(0.0, 0.0), p(4.0, 0.0), p(1.0, 1.0), p(3.0, 2.0));
            assert!(c.approx.expect("filtered").rel < 1e-14);
        }
        // A triangle whose determinant (an ulp's worth, 2^-52 / 3) is below its rounding
        // bound gives up: its bounds are infinite, never wrong, and the exact stage
        // answers. The angle at b is nearly straight, so the centre is far on the other
        // side of a c from b: left of the diagonal, on which b lies.
        let t = [
            (0.0, 0.0),
            (1.0 / 3.0, 1.0 / 3.0),
            (1.0, 1.0 + f64::EPSILON),
        ];
        let [a, b, c] = t.map(Point2::from);
        let flat = Circumcentre::new(a, b, c);
        assert!(flat.err_x.is_infinite() && flat.squared_radius().approx.is_none());
        let (o, diagonal) = (Point2::new(0.0, 0.0), Point2::new(1.0, 1.0));
        assert_eq!(flat.orient(o, diagonal), Orientation::CounterClockwise);
        assert_eq!(
            flat.orient(o, diagonal),
            orient_oracle([a, b, c], o, diagonal)
        );
    }

    proptest! {
        #![proptest_config(cases(300))]

        #[test]
        fn products_of_exact_doubles_compare_exactly(
            // Full 53-bit mantissas (the limbs) or small odd parts (one u128).
            v in proptest::array::uniform10(prop_oneof![1u64..1 << 53, 1u64..40]),
            e in proptest::array::uniform10(-1074i32..971),
            same in any::<bool>(),
        ) {
            // Positive doubles m · 2^e, the right side a permutation of the left (equal
            // products) or arbitrary; the exponents of both sides are offset freely.
            let x = |i: usize| scale_by_pow2(v[i] as f64, e[i].max(-1074 - 52 + 53) - 52);
            let lhs = [x(0), x(1), x(2), x(3), x(4)];
            let rhs = if same { [x(3), x(0), x(4), x(2), x(1)] } else { [x(5), x(6), x(7), x(8), x(9)] };
            prop_assume!(lhs.iter().chain(&rhs).all(|&d| d > 0.0 && d.is_finite()));
            let (e1, e2) = (e[5] % 300, e[6] % 300);
            let exact = |f: [f64; 5], k: i32| {
                f.iter().fold(q(1.0), |acc, &d| acc * q(d)) * q(2.0).pow(k)
            };
            prop_assert_eq!(cmp_products(lhs, e1, rhs, e2), exact(lhs, e1).cmp(&exact(rhs, e2)));
        }

        #[test]
        fn grid_triangles_compare_exactly_without_big_integers(
            t in proptest::array::uniform6(-(1i64 << 24)..(1 << 24)),
            u in proptest::array::uniform6(-(1i64 << 24)..(1 << 24)),
            small in any::<bool>(),
            e in exponent_choice(),
            shift in proptest::array::uniform2(-(1i64 << 30)..(1 << 30)),
        ) {
            // Integer triangles, spread up to 2^25 (the frame's spacing then reaches the
            // 2^-24 limit) or within a few units, scaled by 2^e and translated by a
            // multiple of it (exact).
            let tri = |v: [i64; 6]| {
                let r = |k: i64| if small { k % 7 } else { k };
                let p = |x: i64, y: i64| Point2::new(
                    scale_by_pow2((r(x) + shift[0]) as f64, e),
                    scale_by_pow2((r(y) + shift[1]) as f64, e),
                );
                [p(v[0], v[1]), p(v[2], v[3]), p(v[4], v[5])]
            };
            let (t1, t2) = (tri(t), tri(u));
            for t in [t1, t2] {
                prop_assume!(super::super::orient2d(t[0], t[1], t[2]) != Orientation::Collinear);
            }
            let expected = radius_q(&Circle::Circumcircle(t1)).cmp(&radius_q(&Circle::Circumcircle(t2)));
            if let (Some(f1), Some(f2)) = (GridFactors::new(t1), GridFactors::new(t2)) {
                prop_assert_eq!(f1.cmp(&f2), expected);
            } else {
                // Only spreads beyond the 2^-24 spacing leave the grid path.
                prop_assert!(!small);
            }
            let (a, b) = (squared_radius(&Circle::Circumcircle(t1)), squared_radius(&Circle::Circumcircle(t2)));
            prop_assert_eq!(a.cmp(&b), expected);
        }
    }

    /// Lattice points of x² + y² = R² for R the product of the primes `a² + b²` given by
    /// their Gaussian factors `a + b i`: `Π (a + ε b i)²` for every choice of signs ε.
    fn lattice_circle_of(primes: &[(i64, i64)]) -> (Vec<Point2>, i64) {
        let r = primes.iter().map(|&(a, b)| a * a + b * b).product::<i64>();
        let pts = (0..1u32 << primes.len())
            .map(|signs| {
                let (mut x, mut y) = (1i64, 0i64);
                for (i, &(a, b)) in primes.iter().enumerate() {
                    let b = if signs >> i & 1 == 1 { -b } else { b };
                    // (a + b i)² = (a² − b²) + 2ab i
                    let (u, v) = (a * a - b * b, 2 * a * b);
                    (x, y) = (x * u - y * v, x * v + y * u);
                }
                assert_eq!(
                    x as i128 * x as i128 + y as i128 * y as i128,
                    (r as i128).pow(2)
                );
                (x as f64, y as f64)
            })
            // Every such point has x odd and y even or the other way round, the same for
            // all; their mirror images in y = x have the other parity, so differences
            // between the two kinds are odd: the finest spacing.
            .flat_map(|(x, y)| [Point2::new(x, y), Point2::new(y, x)])
            .collect();
        (pts, r)
    }

    /// Triangles of points of one lattice circle, every one with the circle's radius.
    fn circle_triangles(pts: &[Point2]) -> Vec<[Point2; 3]> {
        let n = pts.len();
        let triangles: Vec<[Point2; 3]> = (0..n / 3)
            .map(|i| [pts[i], pts[i + n / 3 + 1], pts[i + 2 * n / 3]])
            .filter(|t| super::super::orient2d(t[0], t[1], t[2]) != Orientation::Collinear)
            .collect();
        assert!(triangles.len() >= 5);
        triangles
    }

    #[test]
    fn circles_through_lattice_circles_tie() {
        // R = 5 · 13 · 17 · 29 · 37 (about 2^20): differences within the grid path's
        // spacing, which must find every tie by itself.
        let (pts, r) = lattice_circle_of(&[(2, 1), (3, 2), (4, 1), (5, 2), (6, 1)]);
        let triangles = circle_triangles(&pts);
        let f0 = GridFactors::new(triangles[0]).expect("on the grid path");
        for t in &triangles {
            assert_eq!(radius_q(&Circle::Circumcircle(*t)), q((r * r) as f64));
            let f = GridFactors::new(*t).expect("on the grid path");
            assert_eq!(f.cmp(&f0), Ordering::Equal, "{t:?}");
        }
        // R = 5 · 13 · 17 · 29 · 37 · 41 (about 2^25.5): differences up to 2^26.5, beyond
        // the spacing (where squared lengths would round), so the exact stage answers.
        let (pts, r) = lattice_circle_of(&[(2, 1), (3, 2), (4, 1), (5, 2), (6, 1), (5, 4)]);
        let triangles = circle_triangles(&pts);
        let first = squared_radius(&Circle::Circumcircle(triangles[0]));
        for t in &triangles {
            let c = Circle::Circumcircle(*t);
            assert_eq!(radius_q(&c), q(r as f64) * q(r as f64));
            assert_eq!(squared_radius(&c).cmp(&first), Ordering::Equal, "{t:?}");
        }
    }

    proptest! {
        #![proptest_config(cases(1000))]

        #[test]
        fn grid_factors_agree_from_every_vertex(
            a in proptest::array::uniform2(-(1i64 << 30)..(1 << 30)),
            b in proptest::array::uniform2(-(1i64 << 26)..(1 << 26)),
            c in proptest::array::uniform2(-(1i64 << 26)..(1 << 26)),
            flat in any::<bool>(),
        ) {
            // One triangle listed from each vertex: three frames, one radius. Differences
            // up to 2^26 reach beyond the spacing limit; `flat` makes the angle at `a`
            // nearly straight, where |b − c|² is largest in the frame.
            let c = if flat { [-b[0] + c[0] % 64, -b[1] + c[1] % 64] } else { c };
            let p = |d: [i64; 2]| Point2::new((a[0] + d[0]) as f64, (a[1] + d[1]) as f64);
            let t = [p([0, 0]), p(b), p(c)];
            prop_assume!(super::super::orient2d(t[0], t[1], t[2]) != Orientation::Collinear);
            let rotations = [t, [t[1], t[2], t[0]], [t[2], t[0], t[1]], [t[0], t[2], t[1]]];
            let mut found = Vec::new();
            for [a, b, c] in rotations {
                let Some(f) = GridFactors::new([a, b, c]) else { continue };
                // Every factor is the exact value in the frame.
                let frame = q(2.0).pow(2 * f.k);
                let [a, b, c] = [a, b, c].map(qp);
                let mut l = [dist2(&b, &c), dist2(&a, &b), dist2(&a, &c)].map(|v| v * &frame);
                l.sort();
                prop_assert_eq!(f.l.map(q), l);
                prop_assert_eq!(q(f.hd), cross(&a, &b, &c).abs() * &frame);
                found.push(f);
            }
            for f in &found {
                prop_assert_eq!(f.cmp(&found[0]), Ordering::Equal);
            }
        }
    }

    #[test]
    fn products_with_equal_leading_bits_compare_by_their_tails() {
        // a · 2^0 against b · 2^s for small odd a, b (the u128 path) and for mantissas
        // of 53 bits (the limbs): the leading bits often coincide while the exponents
        // differ, so the alignment decides.
        for wide in [false, true] {
            for a in (1u64..64).step_by(2) {
                for b in (1u64..64).step_by(2) {
                    for s in -3i32..=3 {
                        // Three 53-bit factors exceed the u128.
                        let m = |v: u64| if wide { (v << 47) + 1 } else { v } as f64;
                        let lhs = [m(a), m(5), 1.0, m(3), 1.0];
                        let rhs = [m(b), m(3), 1.0, m(5), 1.0];
                        let expected = (q(m(a))).cmp(&(q(m(b)) * q(2.0).pow(s)));
                        assert_eq!(cmp_products(lhs, 0, rhs, s), expected, "{a} {b} {s} {wide}");
                        assert_eq!(cmp_products(rhs, s, lhs, 0), expected.reverse());
                    }
                }
            }
        }
    }

    #[test]
    fn grid_factors_take_lattices_and_refuse_rounded_differences() {
        let p = |x: f64, y: f64| Point2::new(x, y);
        // A unit right triangle far from the origin: r² = 1/2 exactly.
        let t = [p(1e15, 7.0), p(1e15 + 1.0, 7.0), p(1e15, 8.0)];
        let f = GridFactors::new(t).expect("lattice");
        assert_eq!((f.l, f.hd), ([1.0, 1.0, 2.0], 1.0));
        // 1 − 2^-60 is not representable: the difference rounds, so no grid factors.
        assert!(GridFactors::new([p(1.0, 0.0), p(2f64.powi(-60), 0.0), p(0.0, 1.0)]).is_none());
        // A difference below 2^-24 of the largest cannot be a multiple of the spacing.
        assert!(GridFactors::new([p(0.0, 0.0), p(1.0, 0.0), p(0.5, 2f64.powi(-30))]).is_none());
    }

    #[test]
    fn approximations_compare_across_exponents() {
        let a = Approx::new(1.5, 10, 0.2).unwrap();
        let b = Approx::new(1.0, 12, 0.2).unwrap();
        assert_eq!(a.cmp(&b), Some(Ordering::Less));
        assert_eq!(b.cmp(&a), Some(Ordering::Greater));
        // 1.5 · 2^11 = 3 · 2^10 against 1.5 · 2^10 within 20 %: decided.
        let c = Approx::new(3.0, 10, 0.2).unwrap();
        assert_eq!(c.exp, 11);
        assert_eq!(c.cmp(&a), Some(Ordering::Greater));
        // Overlapping enclosures decide nothing, also one binade apart: 2 · 2^10 (stored
        // as 1 · 2^11) against 1.9 · 2^10.
        let d = Approx::new(1.6, 10, 0.2).unwrap();
        assert_eq!(d.cmp(&a), None);
        let (e, f) = (
            Approx::new(2.0, 10, 0.01).unwrap(),
            Approx::new(1.9, 10, 0.1).unwrap(),
        );
        assert_eq!((e.exp, e.cmp(&f), f.cmp(&e)), (11, None, None));
        assert!(Approx::new(0.0, 0, 0.0).is_none() && Approx::new(1.0, 0, 0.3).is_none());
    }
}
