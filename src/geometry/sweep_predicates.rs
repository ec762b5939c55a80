//! Exact predicates of Fortune's sweep: where a new site meets the beach line, and the order
//! of site and circle events.
//!
//! The sweep line `y = L` moves upwards. A site `p` below it has the parabola of the points
//! as far from `p` as from the line; the beach line is their upper envelope. Two questions
//! involve square roots when written with coordinates, and both are reduced here to signs of
//! polynomials in the input coordinates:
//!
//! - **Breakpoints.** With the line through a new site `s`, the beach line above `x = s.x`
//!   is the centre of the smallest circle through an earlier site that touches the line at
//!   `s`; for site `p` its radius is `|s - p|² / (2 (s.y - p.y))`, a quotient without roots.
//!   [`breakpoint_side`] turns "is `s` left of the breakpoint between the arcs of `p` and
//!   `q`?" into a comparison of two such radii (degree 3) and two coordinate comparisons.
//! - **Event order.** A circle event of sites `a, b, c` happens when the line, moving up,
//!   leaves their circumcircle at its top, `y = cy + r`; this is `a.y + (N + √Q) / D` for
//!   polynomials `N` (degree 3), `Q` (degree 6) in the differences `b − a`, `c − a` and the
//!   doubled signed area `D`. Comparing it with a site's `y` or with another event's leads
//!   to `x + √p − √q` with rational `x, p, q`, whose sign follows from a case analysis and
//!   squaring. Ties in `y` are broken by `x` (the centre's), so events are ordered
//!   lexicographically by their point on the sweep line.
//!
//! Stages, as for the other predicates: a filter (plain floating point with an error bound
//! for the breakpoint test, interval arithmetic for circle tops: every operation rounded
//! outwards by an ulp or more; overflow or NaN gives an unbounded interval, which decides
//! nothing), then an exact evaluation in big integers on the
//! doubles' exact binary values brought to a common exponent (see `products.rs`).

use super::bigint::BigInt;
use super::extended::{exact_integers, exponent, odd_parts_and_base, scale_by_pow2};
use super::predicates::pow2;
use super::{cmp_dist, incircle, BoundingBox, InCircle, Point2};
use std::cmp::Ordering;

/// A closed interval `[lo, hi]` of reals holding an exact value; `lo > hi` never happens,
/// and an unusable bound is the whole line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Interval {
    lo: f64,
    hi: f64,
}

/// The filter's view of a circle event: enclosures of the circumcircle's top `cy + r` and of
/// its centre's `x`, computed once when the event is created.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CircleKey {
    top: Interval,
    x: Interval,
}

impl CircleKey {
    /// The enclosures for the circumcircle of `a, b, c` (not collinear).
    pub(crate) fn new(a: Point2, b: Point2, c: Point2) -> CircleKey {
        let (ax, ay) = (Interval::point(a.x), Interval::point(a.y));
        let (bx, by) = (Interval::point(b.x).sub(ax), Interval::point(b.y).sub(ay));
        let (cx, cy) = (Interval::point(c.x).sub(ax), Interval::point(c.y).sub(ay));
        // The offsets from a are homogeneous of degree 1 in the differences: work with the
        // differences near 1 so that no product under- or overflows, and scale back.
        let k = unit_shift(&[bx, by, cx, cy]);
        let [bx, by, cx, cy] = [bx, by, cx, cy].map(|v| v.scaled(k));
        let bb = bx.square().add(by.square());
        let cc = cx.square().add(cy.square());
        let d = bx.mul(cy).sub(by.mul(cx)).twice();
        let ux = cy.mul(bb).sub(by.mul(cc)).div(d);
        let uy = bx.mul(cc).sub(cx.mul(bb)).div(d);
        let r = ux.square().add(uy.square()).sqrt();
        CircleKey {
            top: ay.add(uy.add(r).scaled(-k)),
            x: ax.add(ux.scaled(-k)),
        }
    }
}

impl CircleKey {
    /// The order of the two circles' tops if their enclosures decide it.
    pub(crate) fn cmp_tops(&self, other: &CircleKey) -> Option<Ordering> {
        self.top.cmp(other.top)
    }

    /// Whether the enclosure of the centre's `x` shows that it is not `x`.
    pub(crate) fn centre_x_is_not(&self, x: f64) -> bool {
        self.x.cmp(Interval::point(x)).is_some()
    }
}

/// A circle event's priority in plain floating point: the top of the circumcircle,
/// `y = cy + r`, as a double `top` and a bound `err` with `|exact top − top| <= err`.
///
/// Heap comparisons decide in `f64` when two estimates' intervals `[top − err, top + err]`
/// are disjoint (see [`TopEstimate::cmp`]), and only otherwise load the sites for the exact
/// comparison ([`cmp_circles`], [`cmp_circle_site`]). The bound is derived a priori, once
/// per event, from magnitudes the evaluation computes anyway (see [`TopEstimate::new`]);
/// `err` is an `f32` rounded up (it only needs a few significant bits), so the estimate
/// takes 12 bytes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct TopEstimate {
    /// The top, rounded.
    pub(crate) top: f64,
    /// A bound on the error of `top` (the fields are open so that a caller can store them
    /// beside its own 4-byte index in 16 bytes).
    pub(crate) err: f32,
}

/// The relative margin a stored [`TopEstimate`] bound carries over the derived one.
const ERR_MARGIN: f64 = pow2(-20);

/// `u = 2^-53`, the unit roundoff of `f64` (round to nearest).
const U: f64 = f64::EPSILON / 2.0;

/// Scaled differences of magnitude below this (and not zero) leave the estimate to the
/// exact stages: above it, no product of up to three differences leaves the normal range.
const ESTIMATE_MIN_DIFF: f64 = pow2(-64);

/// The least `|d|` the estimate divides by: the absolute slack of the underflow of a square
/// (below) then stays below `2^-130`, far under the relative error bounds.
const ESTIMATE_MIN_DET: f64 = pow2(-400);

/// Absolute error a possibly underflowing `nx² + ny²` can bring into its square root:
/// each square loses at most `2^-1075`, and `√(s + e) − √s <= √e <= 2^-537` for
/// `e <= 2^-1074`.
const ROOT_UNDERFLOW_SLACK: f64 = pow2(-536);

impl TopEstimate {
    /// The estimate that decides nothing (an infinite bound).
    const UNDECIDED: TopEstimate = TopEstimate {
        top: 0.0,
        err: f32::INFINITY,
    };

    /// The estimate of the top of the circumcircle of `a, b, c` (counter-clockwise).
    ///
    /// **Evaluation.** With the differences `b − a = (bx, by)`, `c − a = (cx, cy)`
    /// (rounded once, then scaled exactly by `2^k` so that the largest is in `[1, 2)`),
    /// `bb = bx² + by²`, `cc = cx² + cy²`, `d = 2 (bx cy − by cx)`,
    /// `nx = cy bb − by cc`, `ny = bx cc − cx bb`, the centre is `a + (nx, ny) / d` and the
    /// radius `|n| / d`, so `top = a.y + 2^-k (ny + |n|) / d`.
    ///
    /// **Error bound** (`u = 2^-53`; each quantity below is the computed one, the exact one
    /// starred). Round to nearest gives `|fl(z) − z| <= u |fl(z)|` for a normal result, and
    /// additions and subtractions of doubles are exact when the result is subnormal. The
    /// guard (every nonzero scaled difference in `[2^-64, 2)`) keeps every product of up to
    /// three differences normal and every value far below overflow, so the relative model
    /// holds for all of them; to first order:
    ///
    /// 1. a difference: `|X* − X| <= u |X|` (the scaling by `2^k` is exact);
    /// 2. `bb`, `cc` (sums of squares, no cancellation): `<= 4u bb` (two relative errors
    ///    of the difference in its square, the square's rounding, the sum's);
    /// 3. `d = 2 (p1 − p2)`: each product carries `3u` of its own size (two differences and
    ///    its rounding), the subtraction `u |d|`, and the doubling is exact: with
    ///    `Dm = 2 (|bx cy| + |by cx|)`, `|d* − d| <= 3u Dm + u |d| <= 4u Dm`;
    /// 4. `nx`: each term `cy bb` carries `u + 4u + u`, the subtraction `u |nx|`:
    ///    `|nx* − nx| <= 7u Nx` with `Nx = |cy| bb + |by| cc`; likewise `ny` with
    ///    `Ny = |bx| cc + |cx| bb`;
    /// 5. `r = |n|`: the norm is 1-Lipschitz, `| |n*| − |n| | <= |nx* − nx| + |ny* − ny|`,
    ///    and the evaluation of `√(nx² + ny²)` adds `(2u + u)/2 + u = 2.5u r`, plus
    ///    `2^-536` if a square underflows (`ROOT_UNDERFLOW_SLACK`);
    /// 6. `N = ny + r`: the errors of `ny` and `r`, plus `u N`;
    /// 7. `t = N / d`, evaluated as `N` times the rounded `1 / d` (`d` is in
    ///    `[2^-400, 2^6)`, so the reciprocal is normal): with `|d| > E_d`,
    ///    `|N*/d* − N/d| <= E_N / (|d| − E_d) + N E_d / (|d| (|d| − E_d))`, plus `2u t` for
    ///    the reciprocal and the product (and `2^-1074` if the product is subnormal);
    ///    `|d| >= 2^-400` keeps the slack of step 5 below `2^-130` after it;
    /// 8. `s = 2^-k t`: exact, or off by at most `2^-1074` if it lands below the normal
    ///    range;
    /// 9. `top = a.y + s`: plus `u |top|`.
    ///
    /// Every coefficient used below carries one `u` more than this first-order count.
    /// That margin covers the second-order terms (products of two or more relative
    /// errors, each below `2^-50` of the first-order ones) and the rounding of the bound's
    /// own evaluation (fewer than 40 roundings: a relative `40u < 2^-47` of the bound).
    /// Anything outside the guard (tiny or huge differences, a nearly flat triple with
    /// `|d| <= E_d`, a non-finite value) gives an estimate that decides nothing.
    pub(crate) fn new(a: Point2, b: Point2, c: Point2) -> TopEstimate {
        let (bx, by) = (b.x - a.x, b.y - a.y);
        let (cx, cy) = (c.x - a.x, c.y - a.y);
        let m = bx.abs().max(by.abs()).max(cx.abs()).max(cy.abs());
        if !(m > 0.0 && m.is_finite()) {
            return TopEstimate::UNDECIDED;
        }
        let k = -exponent(m);
        if !(-1000..=1000).contains(&k) {
            return TopEstimate::UNDECIDED;
        }
        let (f, inv_f) = (pow2(k), pow2(-k));
        // A nonzero difference that scales below the guard (or underflows to zero) goes to
        // the exact stages; above it the scaled value is normal, so the scaling was exact.
        let tiny = |v: f64| v != 0.0 && (v * f).abs() < ESTIMATE_MIN_DIFF;
        if tiny(bx) || tiny(by) || tiny(cx) || tiny(cy) {
            return TopEstimate::UNDECIDED;
        }
        let (bx, by, cx, cy) = (bx * f, by * f, cx * f, cy * f);
        let bb = bx * bx + by * by;
        let cc = cx * cx + cy * cy;
        let (p1, p2) = (bx * cy, by * cx);
        let d = 2.0 * (p1 - p2);
        let e_d = 5.0 * U * (2.0 * (p1.abs() + p2.abs()));
        let dd = d - e_d;
        if !(dd > 0.0 && d >= ESTIMATE_MIN_DET) {
            return TopEstimate::UNDECIDED;
        }
        // The reciprocals are independent of the square root below, so they are computed
        // beside it instead of as two divisions after it.
        let (inv_d, inv_dd) = (1.0 / d, 1.0 / dd);
        let nx = cy * bb - by * cc;
        let ny = bx * cc - cx * bb;
        let e_nx = 8.0 * U * (cy.abs() * bb + by.abs() * cc);
        let e_ny = 8.0 * U * (bx.abs() * cc + cx.abs() * bb);
        let r = (nx * nx + ny * ny).sqrt();
        let e_r = e_nx + e_ny + 3.5 * U * r + ROOT_UNDERFLOW_SLACK;
        let n = ny + r;
        let e_n = e_ny + e_r + 2.0 * U * n.abs();
        let t = n * inv_d;
        let e_t = (e_n + t.abs() * e_d) * inv_dd + 3.0 * U * t.abs() + TINY;
        // Division by `f` and multiplication by its exact inverse (|k| <= 1000) round the
        // same exact value once: the same result, without a division's latency.
        let s = t * inv_f;
        let top = a.y + s;
        let err = e_t * inv_f + TINY + 2.0 * U * top.abs();
        if !(top.is_finite() && err.is_finite()) {
            return TopEstimate::UNDECIDED;
        }
        TopEstimate {
            top,
            // A relative 2^-20 more, for the rounding of the comparisons (see `cmp`).
            err: round_up_f32(err * (1.0 + ERR_MARGIN)),
        }
    }

    /// The estimate of the top of the circumcircle of `a, b, c` (not collinear) from the
    /// exact stage: within a relative `2^-48` of the exact top (plus `2^-1073`), however
    /// flat or spread the triple. It decides nothing only when that bound leaves the range
    /// of `f32` (a top beyond about `2^176` in magnitude; the sweep scales its sites near 1).
    ///
    /// For the few events whose [`new`](Self::new) estimate is loose (a huge circle through
    /// a far site: its top is a difference of two huge numbers): one exact evaluation, at
    /// about the cost of one exact comparison, instead of an exact comparison with every
    /// event its wide interval overlaps.
    ///
    /// **Evaluation.** In the integers of [`ExactCircle`] the top is `(p + √q) / d`, `d > 0`,
    /// `q > 0`. For `p >= 0` the sum has no cancellation; for `p < 0` it is evaluated as
    /// `(q − p²) / (√q − p)`, the numerator exact and the denominator a sum of two
    /// positives. Each big integer is rounded once to a double mantissa and an integer
    /// exponent (relative error `u`); then at most six operations on positive mantissas
    /// follow (a square root, a sum, two products or quotients, each adding `u`, the root
    /// halving its argument's error), so the result is within `8u` to first order, and
    /// `16u |top|` covers the rest. The final scaling by the exponent is exact unless the
    /// top is subnormal or zero (then `2^-1074` more, or its whole value below `2^-1100`).
    ///
    /// # Complexity
    /// O(1) big-integer products of the coordinates' widths.
    pub(crate) fn exact(a: Point2, b: Point2, c: Point2) -> TopEstimate {
        let (v, base) = exact_integers(&[a.x, a.y, b.x, b.y, c.x, c.y]);
        let circle = ExactCircle::new(&v);
        let q = Scaled::of(&circle.q);
        let root_q = q.sqrt();
        let top = if circle.p.signum() >= 0 {
            root_q
                .add_positive(Scaled::of(&circle.p))
                .div(Scaled::of(&circle.d))
        } else {
            let numerator = circle.q.sub(&circle.p.mul(&circle.p));
            let denominator = root_q.add_positive(Scaled::of(&circle.p.abs()));
            Scaled::of(&numerator).div(denominator.mul(Scaled::of(&circle.d)))
        };
        let top = top.to_f64(base);
        if !top.is_finite() {
            return TopEstimate::UNDECIDED;
        }
        let err = 16.0 * U * top.abs() + 2.0 * TINY;
        TopEstimate {
            top,
            err: round_up_f32(err * (1.0 + ERR_MARGIN)),
        }
    }

    /// The order of the two exact tops if the estimates decide it: their intervals are
    /// disjoint. `None` when they overlap (equal tops always do).
    ///
    /// The test `y.top − x.top > x.err + y.err`, evaluated in doubles, errs by at most a
    /// relative `u` on each side (subtractions of doubles are exact in the subnormal
    /// range). Each stored bound is
    /// the derived one times `1 + 2^-20`, rounded up, and never zero (it holds `2^-1074`
    /// at least, rounded up to an `f32`): if the computed gap exceeds the computed sum,
    /// the exact gap exceeds `(1 − 2u) (1 + 2^-20)` times the derived bounds' sum, which is
    /// more than that sum, so the exact tops are in that order.
    /// (The sweep uses [`is_below`](Self::is_below), the same decision; this form is the
    /// tests' reference.)
    #[cfg(test)]
    pub(crate) fn cmp(&self, other: &TopEstimate) -> Option<Ordering> {
        let gap = other.top - self.top;
        let slack = self.err as f64 + other.err as f64;
        if gap > slack {
            Some(Ordering::Less)
        } else if -gap > slack {
            Some(Ordering::Greater)
        } else {
            None
        }
    }

    /// Whether the exact top is below `other`'s, if the estimates decide it: the answer of
    /// `cmp` (`Some(true)` for `Less`, `Some(false)` for `Greater`; its doc has the proof), written
    /// so that a caller's "which is less" compiles without a data-dependent branch (a
    /// binary heap's child choice): `|gap| > slack` is the condition of `cmp` deciding,
    /// and then the sign of the gap is its order (`slack >= 0`; a NaN gap decides nothing).
    #[inline]
    pub(crate) fn is_below(&self, other: &TopEstimate) -> Option<bool> {
        let gap = other.top - self.top;
        let slack = self.err as f64 + other.err as f64;
        if gap.abs() > slack {
            Some(gap > 0.0)
        } else {
            None
        }
    }

    /// The order of the exact top and the height `y` if the estimate decides it.
    #[inline]
    pub(crate) fn cmp_height(&self, y: f64) -> Option<Ordering> {
        let gap = y - self.top;
        let slack = self.err as f64;
        if gap > slack {
            Some(Ordering::Less)
        } else if -gap > slack {
            Some(Ordering::Greater)
        } else {
            None
        }
    }
}

/// The least `f32` at least `v` (`v >= 0`; infinity above `f32::MAX`).
fn round_up_f32(v: f64) -> f32 {
    let r = v as f32;
    if (r as f64) < v {
        r.next_up()
    } else {
        r
    }
}

/// Where `s` is relative to the breakpoint between the beach-line arcs of `p` (left) and
/// `q` (right) when the sweep line passes through `s`: `Less` if left of it, `Equal` if on
/// it, `Greater` if right of it.
///
/// Preconditions (Fortune's sweep guarantees them): `p != q`, both at or below `s`
/// (`p.y <= s.y`, `q.y <= s.y`), `s` equal to neither; a site on the sweep line is an earlier
/// site of the same row, so it is left of `s`; if `p.y == q.y` then `p.x < q.x` (two
/// parabolas of equal width cross once, the left site's arc on the left). When both `p` and `q` are on the line (the
/// first row, whose arcs are vertical strips) `s` is right of their breakpoint.
///
/// The higher of two sites has the narrower parabola, and its arc contains the point above
/// it; on the far side of that point the other site's arc comes back, so the breakpoint
/// `p|q` is the intersection on the near side. On the near side, `s` is left of the
/// breakpoint exactly when `p`'s parabola is the higher one above `s`: when the circle
/// through `p` touching the line at `s` is smaller than the one through `q`.
pub(crate) fn breakpoint_side(p: Point2, q: Point2, s: Point2) -> Ordering {
    if p.y < q.y {
        if s.x >= q.x {
            return Ordering::Greater;
        }
    } else if p.y > q.y {
        if s.x <= p.x {
            return Ordering::Less;
        }
    } else if p.y == s.y {
        // Both on the line: the first row, inserted from left to right.
        return Ordering::Greater;
    } else {
        // Equal heights: the breakpoint is on the perpendicular bisector.
        return cmp_dist(s, p, s, q);
    }
    cmp_tangent_radii(p, q, s)
}

/// Compares the event point of the circle of `t` (lexicographically: top `y`, then the
/// centre's `x`) with the site `s`.
pub(crate) fn cmp_circle_site(key: &CircleKey, t: [Point2; 3], s: Point2) -> Ordering {
    let site = CircleKey {
        top: Interval::point(s.y),
        x: Interval::point(s.x),
    };
    if let Some(order) = key.top.cmp(site.top) {
        return order;
    }
    let [a, b, c] = t;
    let coords = [a.x, a.y, b.x, b.y, c.x, c.y, s.x, s.y];
    let v = exact_coords(&coords);
    let circle = ExactCircle::new(&v[..6]);
    let (sx, sy) = (&v[6], &v[7]);
    circle.cmp_top(sy).then_with(|| {
        key.x.cmp(site.x).unwrap_or_else(|| {
            // X / D vs sx.
            ordering(circle.x.sub(&sx.mul(&circle.d)).signum())
        })
    })
}

/// The largest `f64` not above the top of the circumcircle of `t` (not collinear), the
/// height of the sweep line at that circle's event rounded down: rounding down keeps the
/// order of the events, site heights included. `f64::MAX` if the top is beyond it.
///
/// Exact for every finite input: a bisection over the doubles between the filter's
/// enclosure of the top (or the highest of the three sites and `f64::MAX`), each step one
/// exact comparison of the top with a double.
pub(crate) fn circle_top_floor(t: [Point2; 3]) -> f64 {
    let [a, b, c] = t;
    let key = CircleKey::new(a, b, c);
    let not_above_top = |y: f64| cmp_circle_top(&key, t, y) != Ordering::Less;
    // The top is at least as high as every site on the circle.
    let mut lo = a.y.max(b.y).max(c.y);
    if key.top.lo.is_finite() && key.top.lo > lo {
        lo = key.top.lo;
    }
    let hi = if key.top.hi.is_finite() {
        key.top.hi.max(lo)
    } else {
        f64::MAX
    };
    if not_above_top(hi) {
        return hi;
    }
    // The doubles in their order as integers (the map of `f64::total_cmp`, its own
    // inverse); not_above_top(lo) holds and not_above_top(hi) does not.
    let ordered = |v: f64| {
        let b = v.to_bits() as i64;
        i128::from(b ^ ((((b >> 63) as u64) >> 1) as i64))
    };
    let double = |k: i128| {
        let b = k as i64;
        f64::from_bits((b ^ ((((b >> 63) as u64) >> 1) as i64)) as u64)
    };
    let (mut l, mut h) = (ordered(lo), ordered(hi));
    while h - l > 1 {
        let m = l + (h - l) / 2;
        if not_above_top(double(m)) {
            l = m;
        } else {
            h = m;
        }
    }
    double(l)
}

/// Compares the top of the circle of `t` (its filter's `key`) with the height `y`.
fn cmp_circle_top(key: &CircleKey, t: [Point2; 3], y: f64) -> Ordering {
    if let Some(order) = key.top.cmp(Interval::point(y)) {
        return order;
    }
    let [a, b, c] = t;
    let v = exact_coords(&[a.x, a.y, b.x, b.y, c.x, c.y, y]);
    ExactCircle::new(&v[..6]).cmp_top(&v[6])
}

/// Compares the event points of two circles (lexicographically: top `y`, then the
/// centre's `x`).
pub(crate) fn cmp_circles(
    k1: &CircleKey,
    t1: [Point2; 3],
    k2: &CircleKey,
    t2: [Point2; 3],
) -> Ordering {
    if let Some(order) = k1.top.cmp(k2.top) {
        return order;
    }
    // Events at one Voronoi vertex of four or more cocircular sites: one circle, one point.
    let [a, b, c] = t1;
    if t2.iter().all(|&d| incircle(a, b, c, d) == InCircle::On) {
        return Ordering::Equal;
    }
    let coords: Vec<f64> = t1.iter().chain(&t2).flat_map(|p| [p.x, p.y]).collect();
    if let Some(order) = small_ints(&coords).and_then(|v| cmp_small_circles(&v)) {
        return order;
    }
    let v = exact_coords(&coords);
    let c1 = ExactCircle::new(&v[..6]);
    let c2 = ExactCircle::new(&v[6..]);
    // (P1 + √Q1) / D1 vs (P2 + √Q2) / D2 with D1, D2 > 0: the sign of
    // (D2 P1 − D1 P2) + √(D2² Q1) − √(D1² Q2).
    let x = c2.d.mul(&c1.p).sub(&c1.d.mul(&c2.p));
    let p = c2.d.mul(&c2.d).mul(&c1.q);
    let q = c1.d.mul(&c1.d).mul(&c2.q);
    ordering(sign_plus_roots(&x, &p, &q)).then_with(|| {
        k1.x.cmp(k2.x).unwrap_or_else(|| {
            // X1 / D1 vs X2 / D2.
            ordering(c1.x.mul(&c2.d).sub(&c2.x.mul(&c1.d)).signum())
        })
    })
}

/// Scales every point by one power of two so that the largest coordinate magnitude is near
/// 1, if that is exact (no coordinate leaves the normal range); otherwise by the exact
/// power of two nearest to that. Every predicate of this module is invariant under such a
/// scaling, and the filter then works on values far from overflow and underflow.
///
/// Returns the shift `k` (the points were multiplied by `2^k`, exactly; 0 if they were left
/// as they were), so that a caller can scale what it knows of them (a bounding box) alike.
pub(crate) fn normalize_scale(points: &mut [Point2]) -> i32 {
    let exponents = points
        .iter()
        .flat_map(|p| [p.x, p.y])
        .filter(|&v| v != 0.0)
        .map(exponent);
    let (lo, hi) = exponents.fold((i32::MAX, i32::MIN), |(lo, hi), e| (lo.min(e), hi.max(e)));
    if lo > hi {
        return 0; // all zero
    }
    // Every result must stay a normal double: exponents in [-1022, 1022] (one binade of
    // headroom below overflow).
    let (min_shift, max_shift) = (-1022 - lo, 1022 - hi);
    if min_shift > max_shift {
        return 0; // the magnitudes span too much for any one exact shift
    }
    let shift = (-hi).clamp(min_shift, max_shift);
    if shift != 0 {
        for p in points {
            *p = Point2::new(scale_by_pow2(p.x, shift), scale_by_pow2(p.y, shift));
        }
    }
    shift
}

/// `bounds` scaled as [`normalize_scale`] scaled its points (by `2^shift`, the shift it
/// returned): the corners are coordinates of those points, so they scale exactly and the
/// result is the box of the scaled points.
pub(crate) fn scaled_box(bounds: BoundingBox, shift: i32) -> BoundingBox {
    let scale = |p: Point2| Point2::new(scale_by_pow2(p.x, shift), scale_by_pow2(p.y, shift));
    BoundingBox {
        min: scale(bounds.min),
        max: scale(bounds.max),
    }
}

/// The smallest positive subnormal, 2^-1074.
const TINY: f64 = f64::from_bits(1);

impl Interval {
    const ENTIRE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    #[inline]
    fn point(v: f64) -> Interval {
        Interval { lo: v, hi: v }
    }

    /// `[lo, hi]` rounded outwards, or the whole line if a bound is not finite.
    #[inline]
    fn outward(lo: f64, hi: f64) -> Interval {
        // Written so that NaN gives the whole line too.
        if lo.is_finite() && hi.is_finite() {
            // At least one ulp outwards (2^-52 |v| is an ulp or more, 2^-1074 covers
            // subnormals), and rounding to nearest cannot undo a step of a whole ulp.
            Interval {
                lo: lo - (lo.abs() * f64::EPSILON + TINY),
                hi: hi + (hi.abs() * f64::EPSILON + TINY),
            }
        } else {
            Interval::ENTIRE
        }
    }

    #[inline]
    fn is_bounded(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    #[inline]
    fn add(self, o: Interval) -> Interval {
        Interval::outward(self.lo + o.lo, self.hi + o.hi)
    }

    #[inline]
    fn sub(self, o: Interval) -> Interval {
        Interval::outward(self.lo - o.hi, self.hi - o.lo)
    }

    /// Exact: doubling only changes the exponent (overflow is caught later as infinity).
    #[inline]
    fn twice(self) -> Interval {
        Interval {
            lo: 2.0 * self.lo,
            hi: 2.0 * self.hi,
        }
    }

    #[inline]
    fn mul(self, o: Interval) -> Interval {
        if !self.is_bounded() || !o.is_bounded() {
            return Interval::ENTIRE;
        }
        Interval::around_corners([
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ])
    }

    /// The outward-rounded hull of the four corner values of a product or quotient.
    #[inline]
    fn around_corners(p: [f64; 4]) -> Interval {
        Interval::outward(
            p[0].min(p[1]).min(p[2].min(p[3])),
            p[0].max(p[1]).max(p[2].max(p[3])),
        )
    }

    #[inline]
    fn square(self) -> Interval {
        if !self.is_bounded() {
            return Interval::ENTIRE;
        }
        let (a, b) = (self.lo * self.lo, self.hi * self.hi);
        if self.lo >= 0.0 || self.hi <= 0.0 {
            Interval::outward(a.min(b), a.max(b)).non_negative()
        } else {
            Interval::outward(0.0, a.max(b)).non_negative()
        }
    }

    #[inline]
    fn div(self, o: Interval) -> Interval {
        if !self.is_bounded() || !o.is_bounded() || (o.lo <= 0.0 && o.hi >= 0.0) {
            return Interval::ENTIRE;
        }
        Interval::around_corners([
            self.lo / o.lo,
            self.lo / o.hi,
            self.hi / o.lo,
            self.hi / o.hi,
        ])
    }

    /// The square root of the non-negative part (the exact value is a sum of squares).
    #[inline]
    fn sqrt(self) -> Interval {
        if !self.is_bounded() {
            return Interval::ENTIRE;
        }
        Interval::outward(self.lo.max(0.0).sqrt(), self.hi.max(0.0).sqrt()).non_negative()
    }

    /// The interval times `2^k` (rounded outwards where that is inexact: near underflow).
    fn scaled(self, mut k: i32) -> Interval {
        if k == 0 {
            return self;
        }
        if (-1000..=1000).contains(&k) {
            // A product by a power of two is exact unless it overflows or leaves the normal
            // range: then the bounds are kept as they are, with no widening.
            let f = pow2(k);
            let (lo, hi) = (self.lo * f, self.hi * f);
            let exact = |v: f64| v == 0.0 || (v.is_finite() && v.abs() >= f64::MIN_POSITIVE);
            if exact(lo) && exact(hi) {
                return Interval { lo, hi };
            }
        }
        let mut v = self;
        while k != 0 {
            let step = k.clamp(-1000, 1000);
            v = v.mul(Interval::point(pow2(step)));
            k -= step;
        }
        v
    }

    /// Clamps the lower bound at zero, for values known to be non-negative.
    #[inline]
    fn non_negative(self) -> Interval {
        Interval {
            lo: self.lo.max(0.0),
            hi: self.hi,
        }
    }

    /// The order of the exact values if the intervals decide it.
    #[inline]
    fn cmp(self, o: Interval) -> Option<Ordering> {
        if self.hi < o.lo {
            Some(Ordering::Less)
        } else if self.lo > o.hi {
            Some(Ordering::Greater)
        } else if self.lo == self.hi && o.lo == o.hi && self.lo == o.lo && self.is_bounded() {
            // Two exact points.
            Some(Ordering::Equal)
        } else {
            None
        }
    }

    /// The sign of the exact value if the interval decides it.
    #[inline]
    fn sign(self) -> Option<Ordering> {
        self.cmp(Interval::point(0.0))
    }
}

/// The shift `k` that brings the largest magnitude in `values` into `[1, 2)`; 0 if they are
/// all zero or one is unbounded.
fn unit_shift(values: &[Interval]) -> i32 {
    let m = values
        .iter()
        .fold(0.0f64, |m, v| m.max(v.lo.abs()).max(v.hi.abs()));
    if m == 0.0 || !m.is_finite() {
        0
    } else {
        -exponent(m)
    }
}

/// `|s − p|² (s.y − q.y)` vs `|s − q|² (s.y − p.y)`: the radii of the circles through `p`
/// and `q` touching the line `y = s.y` at `s`, denominators cleared (both are `>= 0`).
#[inline]
fn cmp_tangent_radii(p: Point2, q: Point2, s: Point2) -> Ordering {
    // Plain floating point first. With every difference zero or in [2^-300, 2^300] no
    // product under- or overflows, each side carries at most 7 roundings of relative size
    // 2^-53 (the differences counted twice in the squares) and the subtraction one more:
    // 9 · 2^-53 of the sides' sum bounds the error, the bound's own rounding included.
    let (px, py, qx, qy) = (s.x - p.x, s.y - p.y, s.x - q.x, s.y - q.y);
    let safe = |d: f64| d == 0.0 || (FILTER_MIN..=FILTER_MAX).contains(&d.abs());
    if safe(px) && safe(py) && safe(qx) && safe(qy) {
        let lhs = (px * px + py * py) * qy;
        let rhs = (qx * qx + qy * qy) * py;
        let diff = lhs - rhs;
        let bound = 4.5 * f64::EPSILON * (lhs + rhs);
        if diff > bound {
            return Ordering::Greater;
        }
        if -diff > bound {
            return Ordering::Less;
        }
    }
    cmp_tangent_radii_slow(p, q, s)
}

/// Bounds of the differences the plain filter of [`cmp_tangent_radii`] takes.
const FILTER_MIN: f64 = pow2(-300);
const FILTER_MAX: f64 = pow2(300);

/// [`cmp_tangent_radii`] by intervals on rescaled differences, then big integers.
#[cold]
#[inline(never)]
fn cmp_tangent_radii_slow(p: Point2, q: Point2, s: Point2) -> Ordering {
    let (sx, sy) = (Interval::point(s.x), Interval::point(s.y));
    let (px, py) = (sx.sub(Interval::point(p.x)), sy.sub(Interval::point(p.y)));
    let (qx, qy) = (sx.sub(Interval::point(q.x)), sy.sub(Interval::point(q.y)));
    // Homogeneous of degree 3 in the differences: scaling them by 2^k keeps the sign.
    let k = unit_shift(&[px, py, qx, qy]);
    let [px, py, qx, qy] = [px, py, qx, qy].map(|v| v.scaled(k));
    let lhs = px.square().add(py.square()).mul(qy);
    let rhs = qx.square().add(qy.square()).mul(py);
    lhs.sub(rhs).sign().unwrap_or_else(|| {
        let v = exact_coords(&[s.x, s.y, p.x, p.y, q.x, q.y]);
        let sq = |x: &BigInt| x.mul(x);
        let (px, py) = (v[0].sub(&v[2]), v[1].sub(&v[3]));
        let (qx, qy) = (v[0].sub(&v[4]), v[1].sub(&v[5]));
        let lhs = sq(&px).add(&sq(&py)).mul(&qy);
        let rhs = sq(&qx).add(&sq(&qy)).mul(&py);
        ordering(lhs.sub(&rhs).signum())
    })
}

/// A circumcircle in exact integers (coordinates scaled by a common power of two): the top
/// is `(p + √q) / d` (`p = a.y·d + N`) and the centre's `x` is `x / d`, with `d > 0`.
struct ExactCircle {
    d: BigInt,
    p: BigInt,
    q: BigInt,
    x: BigInt,
}

impl ExactCircle {
    /// From `[ax, ay, bx, by, cx, cy]`, not collinear.
    fn new(v: &[BigInt]) -> ExactCircle {
        let (ax, ay) = (&v[0], &v[1]);
        let (bx, by) = (v[2].sub(ax), v[3].sub(ay));
        let (cx, cy) = (v[4].sub(ax), v[5].sub(ay));
        let bb = bx.mul(&bx).add(&by.mul(&by));
        let cc = cx.mul(&cx).add(&cy.mul(&cy));
        let mut d = bx.mul(&cy).sub(&by.mul(&cx));
        d = d.add(&d);
        let mut nx = cy.mul(&bb).sub(&by.mul(&cc));
        let mut ny = bx.mul(&cc).sub(&cx.mul(&bb));
        debug_assert!(d.signum() != 0, "a circle event of collinear sites");
        if d.signum() < 0 {
            // The same circle with the orientation reversed: keep d positive.
            let zero = BigInt::from_parts(false, 0, 0);
            d = zero.sub(&d);
            nx = zero.sub(&nx);
            ny = zero.sub(&ny);
        }
        let q = nx.mul(&nx).add(&ny.mul(&ny));
        ExactCircle {
            p: ay.mul(&d).add(&ny),
            x: ax.mul(&d).add(&nx),
            q,
            d,
        }
    }

    /// Compares the top `(p + √q) / d` with `y` (in the same integer scaling).
    fn cmp_top(&self, y: &BigInt) -> Ordering {
        // (P + √Q) / D vs y  <=>  √Q vs y·D − P.
        let t = y.mul(&self.d).sub(&self.p);
        if t.signum() <= 0 {
            if t.signum() == 0 && self.q.signum() == 0 {
                Ordering::Equal
            } else {
                Ordering::Greater
            }
        } else {
            ordering(self.q.sub(&t.mul(&t)).signum())
        }
    }
}

/// A real `m · 2^e` with a double mantissa and an unbounded exponent: big integers of any
/// width rounded once, for [`TopEstimate::exact`].
#[derive(Debug, Clone, Copy)]
struct Scaled {
    m: f64,
    e: i64,
}

impl Scaled {
    /// `v` rounded to nearest (a relative error of at most `u`).
    fn of(v: &BigInt) -> Scaled {
        let (negative, top, shift) = v.top_bits();
        // The sticky bit of `top_bits` makes this one rounding of the whole integer.
        let m = top as f64;
        Scaled {
            m: if negative { -m } else { m },
            e: i64::from(shift),
        }
    }

    fn mul(self, other: Scaled) -> Scaled {
        Scaled {
            m: self.m * other.m,
            e: self.e + other.e,
        }
    }

    fn div(self, other: Scaled) -> Scaled {
        Scaled {
            m: self.m / other.m,
            e: self.e - other.e,
        }
    }

    /// The square root of a non-negative value.
    fn sqrt(self) -> Scaled {
        let (m, e) = if self.e % 2 == 0 {
            (self.m, self.e)
        } else {
            (2.0 * self.m, self.e - 1)
        };
        Scaled {
            m: m.sqrt(),
            e: e / 2,
        }
    }

    /// The sum of two non-negative values: the smaller is aligned to the larger's exponent
    /// (a term more than 2^1100 times smaller is dropped, a relative change far below `u`).
    fn add_positive(self, other: Scaled) -> Scaled {
        let (big, small) = if self.e >= other.e {
            (self, other)
        } else {
            (other, self)
        };
        let gap = (small.e - big.e).max(-1100) as i32;
        Scaled {
            m: big.m + scale_by_pow2(small.m, gap),
            e: big.e,
        }
    }

    /// The value times `2^base` as a double: infinite if it overflows.
    fn to_f64(self, base: i32) -> f64 {
        let e = (self.e + i64::from(base)).clamp(-2000, 2000) as i32;
        scale_by_pow2(self.m, e)
    }
}

/// Bits of the coordinates [`cmp_small_circles`] takes: its largest terms, `D2² Q1`, have
/// degree 10 and stay below 2^(10 B + 19) <= 2^119.
const SMALL_BITS: u32 = 10;

/// The coordinates as integers below `2^SMALL_BITS` in magnitude, all scaled by one power of
/// two, if they are (grids and lattices, whose circles tie exactly and often).
fn small_ints(coords: &[f64]) -> Option<Vec<i128>> {
    let (parts, base) = odd_parts_and_base(coords);
    parts
        .iter()
        .map(|&(negative, m, e)| {
            let shift = (e - base) as u32;
            if m == 0 {
                Some(0)
            } else if shift < SMALL_BITS && m < 1 << (SMALL_BITS - shift) {
                let v = (m << shift) as i128;
                Some(if negative { -v } else { v })
            } else {
                None
            }
        })
        .collect()
}

/// [`cmp_circles`] on small integers when the comparison of the tops needs no squaring:
/// equal centre heights or equal radii (the ties of grids and lattices), or both pointing
/// the same way; `None` otherwise.
fn cmp_small_circles(v: &[i128]) -> Option<Ordering> {
    let circle = |v: &[i128]| {
        let (ax, ay) = (v[0], v[1]);
        let (bx, by, cx, cy) = (v[2] - ax, v[3] - ay, v[4] - ax, v[5] - ay);
        let (bb, cc) = (bx * bx + by * by, cx * cx + cy * cy);
        let d = 2 * (bx * cy - by * cx);
        let (nx, ny) = (cy * bb - by * cc, bx * cc - cx * bb);
        // [d, p, q, x] as in `ExactCircle`, with d > 0.
        let s = d.signum();
        [
            d * s,
            ay * d * s + ny * s,
            nx * nx + ny * ny,
            ax * d * s + nx * s,
        ]
    };
    let ([d1, p1, q1, x1], [d2, p2, q2, x2]) = (circle(&v[..6]), circle(&v[6..]));
    let x = (d2 * p1 - d1 * p2).signum() as i32;
    let roots = (d2 * d2 * q1 - d1 * d1 * q2).signum() as i32;
    let top = sign_without_squaring(x, roots)?;
    Some(ordering(top).then_with(|| ordering((x1 * d2 - x2 * d1).signum() as i32)))
}

/// The sign of `x + √p − √q` from the signs of `x` and `p − q` when they do not disagree
/// (one is zero, or both have the same sign); `None` when only squaring can tell.
fn sign_without_squaring(x: i32, roots: i32) -> Option<i32> {
    if x == 0 {
        Some(roots)
    } else if roots == 0 || x == roots {
        Some(x)
    } else {
        None
    }
}

/// Products below this are exact in `f64` when their factors are integers.
const EXACT_PRODUCT: f64 = pow2(52);

/// [`cmp_circles`] in plain floating point for sites of a small-integer set (every
/// coordinate an integer, the set's box at most 2^12 wide on both axes: see
/// `BoxPredicates::is_small_integer`), when every operation is provably exact; `None`
/// otherwise (the caller then takes [`cmp_circles`]), and also when the tops' order needs
/// squaring (as [`cmp_small_circles`]).
///
/// Why it is exact: see [`IntegerCircle`], with the origin `t1[0]`. (The sweep compares
/// precomputed [`IntegerCircle`]s; this form is the tests'.)
#[cfg(test)]
pub(crate) fn cmp_integer_circles(t1: [Point2; 3], t2: [Point2; 3]) -> Option<Ordering> {
    let o = t1[0];
    IntegerCircle::new(t1, o).cmp(&IntegerCircle::new(t2, o))
}

/// The circumcircle of three sites of a small-integer set (every coordinate an integer,
/// the set's box at most 2^12 wide on both axes: see `BoxPredicates::is_small_integer`), relative to an origin `o` (`[d, p, q, x]` as in `ExactCircle`, with `d > 0`):
/// computed once per circle, so that a caller comparing one circle many times (the sweep's
/// heap on a grid, where events tie everywhere) pays only [`cmp`](Self::cmp).
///
/// Why it is exact: `o` is a site of the same small-integer set (or any point whose
/// differences with its sites are integers of at most `2^12` in magnitude), so relative to
/// `o` every coordinate is an integer of at most `2^12` in magnitude, and so is every
/// difference of two sites. Then `bb, cc <= 2^25`, `|d| <= 2^26`, `|nx|, |ny| <= 2^38`,
/// `|a.y d + ny|, |a.x d + nx| <= 2^39`: integers below `2^53`, so every step is exact.
/// `q = nx² + ny²` is exact when `|nx|, |ny| < 2^26` (each square below `2^52`), which is
/// checked (`small`). The comparisons multiply two such values: each product is checked,
/// on its rounded value, to be below `2^52` (rounding is monotone and `2^52` is a double,
/// so a rounded product below it comes from an exact one below it, which is then exact),
/// and a difference of two is below `2^53`. Two circles are comparable only when taken
/// relative to the same origin.
#[derive(Debug, Clone, Copy)]
pub(crate) struct IntegerCircle {
    d: f64,
    p: f64,
    q: f64,
    x: f64,
    /// Whether `q` is exact.
    small: bool,
}

impl IntegerCircle {
    /// The circle through `t` (counter-clockwise or clockwise, not collinear), relative
    /// to `o`.
    #[inline]
    pub(crate) fn new(t: [Point2; 3], o: Point2) -> IntegerCircle {
        let [a, b, c] = t.map(|p| Point2::new(p.x - o.x, p.y - o.y));
        let (bx, by, cx, cy) = (b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
        let (bb, cc) = (bx * bx + by * by, cx * cx + cy * cy);
        let d = 2.0 * (bx * cy - by * cx);
        let (nx, ny) = (cy * bb - by * cc, bx * cc - cx * bb);
        let s = if d < 0.0 { -1.0 } else { 1.0 };
        let small = nx.abs() < pow2(26) && ny.abs() < pow2(26);
        let q = nx * nx + ny * ny;
        IntegerCircle {
            d: d * s,
            p: (a.y * d + ny) * s,
            q,
            x: (a.x * d + nx) * s,
            small,
        }
    }

    /// The estimate of the circle's top, `o` being the origin the circle was taken
    /// relative to, when `q` is exact (`None` otherwise): the same decisions as
    /// [`TopEstimate::new`] from the integers already computed.
    ///
    /// **Error bound.** `p`, `q`, `d > 0` and `o.y` are exact integers. The square root
    /// `r` errs by at most `u √q`, the sum `s = p + r` adds `u |s|`, the quotient
    /// `t = s / d` adds `u |t|`, and `top = o.y + t` adds `u |top|` (no value is below the
    /// normal range: a nonzero `p + √q` is at least `1 / (|p| + √q) > 2^-41`). So
    /// `|exact top − top| <= u (r' + |s|) / d + u |t| + u |top|` to first order, with
    /// `r' = r (1 + u)` covering `√q`; the stored bound carries the relative margin
    /// `2^-20` and is rounded up, which covers the second-order terms and the bound's
    /// own rounding, as in [`TopEstimate::new`].
    #[inline]
    pub(crate) fn estimate(&self, o: Point2) -> Option<TopEstimate> {
        if !self.small {
            return None;
        }
        let r = self.q.sqrt();
        let s = self.p + r;
        let t = s / self.d;
        let top = o.y + t;
        let err = U * ((r * (1.0 + U) + s.abs()) / self.d + t.abs() + top.abs()) + TINY;
        Some(TopEstimate {
            top,
            err: round_up_f32(err * (1.0 + ERR_MARGIN)),
        })
    }

    /// [`cmp_circles`] for the two circles (relative to the same origin) when every
    /// operation is provably exact, `None` otherwise or when the tops' order needs
    /// squaring (as [`cmp_small_circles`]).
    #[inline]
    pub(crate) fn cmp(&self, other: &IntegerCircle) -> Option<Ordering> {
        let IntegerCircle {
            d: d1,
            p: p1,
            q: q1,
            x: x1,
            small: s1,
        } = *self;
        let IntegerCircle {
            d: d2,
            p: p2,
            q: q2,
            x: x2,
            small: s2,
        } = *other;
        let dm = d1.max(d2);
        let pm = p1.abs().max(p2.abs()).max(x1.abs()).max(x2.abs());
        let exact = s1 && s2 && dm * pm < EXACT_PRODUCT && dm * dm * q1.max(q2) < EXACT_PRODUCT;
        if !exact {
            return None;
        }
        let sign = |v: f64| (v > 0.0) as i32 - (v < 0.0) as i32;
        let x = sign(d2 * p1 - d1 * p2);
        let roots = sign(d2 * d2 * q1 - d1 * d1 * q2);
        let top = sign_without_squaring(x, roots)?;
        Some(ordering(top).then_with(|| ordering(sign(x1 * d2 - x2 * d1))))
    }
}

/// The sign of `x + √p − √q` for `p, q >= 0`.
fn sign_plus_roots(x: &BigInt, p: &BigInt, q: &BigInt) -> i32 {
    let sx = x.signum();
    let sr = p.sub(q).signum();
    if sx == 0 || sr == 0 || sx == sr {
        return if sx == 0 { sr } else { sx };
    }
    let four = BigInt::from_parts(false, 4, 0);
    let xx = x.mul(x);
    if sx > 0 {
        // x + √p > √q  <=>  2x√p > q − p − x² =: m (both sides squared, all non-negative).
        let m = q.sub(p).sub(&xx);
        if m.signum() < 0 {
            return 1;
        }
        four.mul(&xx).mul(p).sub(&m.mul(&m)).signum()
    } else {
        // With y = −x > 0: √p > √q + y  <=>  p − q − y² =: m > 2y√q.
        let m = p.sub(q).sub(&xx);
        if m.signum() < 0 {
            return -1;
        }
        m.mul(&m).sub(&four.mul(&xx).mul(q)).signum()
    }
}

/// Every coordinate as an exact big integer, all scaled by the same power of two (the
/// largest that keeps them integers).
fn exact_coords(coords: &[f64]) -> Vec<BigInt> {
    exact_integers(coords).0
}

fn ordering(sign: i32) -> Ordering {
    sign.cmp(&0)
}

#[cfg(test)]
mod tests {
    //! Against an exact rational oracle written from the definitions: the breakpoint as a
    //! root of the difference of the two parabolas, and circle tops as `cy + r` compared by
    //! squaring.
    use super::*;
    use num_rational::BigRational;
    use num_traits::{Signed, Zero};
    use proptest::prelude::*;

    type Q = BigRational;

    fn q(v: f64) -> Q {
        Q::from_float(v).expect("finite")
    }

    fn cmp_q(a: &Q, b: &Q) -> Ordering {
        a.cmp(b)
    }

    /// Where `s` is relative to the breakpoint `p|q` on the line `y = s.y`: the
    /// intersections of the parabolas are the roots of
    /// `phi(x) = dq (x − px)² − dp (x − qx)² − (py − qy) dp dq`; the lower site's arc is
    /// on the outside, so `p|q` is the left root if `p` is lower, the right one if higher.
    fn oracle_side(p: Point2, r: Point2, s: Point2) -> Ordering {
        let (px, py, qx, qy, sx, sy) = (q(p.x), q(p.y), q(r.x), q(r.y), q(s.x), q(s.y));
        let (dp, dq) = (&sy - &py, &sy - &qy);
        if dp.is_zero() {
            return cmp_q(&sx, &px); // p is a vertical spike at px
        }
        if dq.is_zero() {
            return cmp_q(&sx, &qx);
        }
        let two = Q::from_integer(2.into());
        let a = &dq - &dp;
        let b = &two * (&dp * &qx - &dq * &px);
        let c = &dq * &px * &px - &dp * &qx * &qx - (&py - &qy) * &dp * &dq;
        let phi = &a * &sx * &sx + &b * &sx + &c;
        if a.is_zero() {
            let root = -&c / &b;
            return cmp_q(&sx, &root);
        }
        let vertex = -&b / (&two * &a);
        // Positive outside the roots, zero on them, negative between.
        let outside = (&a * &phi).signum();
        let left_of_vertex = sx <= vertex;
        let want_left_root = py < qy;
        // Outside the roots on the root's own side of the vertex means beyond that root.
        let beyond_root = cmp_q(&outside, &Q::zero());
        match (want_left_root, left_of_vertex) {
            (true, true) => beyond_root.reverse(),
            (true, false) => Ordering::Greater,
            (false, true) => Ordering::Less,
            (false, false) => beyond_root,
        }
    }

    /// Centre and squared radius of the circle through `a, b, c`.
    fn circle(t: [Point2; 3]) -> (Q, Q, Q) {
        let [a, b, c] = t.map(|p| (q(p.x), q(p.y)));
        let two = Q::from_integer(2.into());
        let (bx, by) = (&b.0 - &a.0, &b.1 - &a.1);
        let (cx, cy) = (&c.0 - &a.0, &c.1 - &a.1);
        let d = &two * (&bx * &cy - &by * &cx);
        let bb = &bx * &bx + &by * &by;
        let cc = &cx * &cx + &cy * &cy;
        let ux = (&cy * &bb - &by * &cc) / &d;
        let uy = (&bx * &cc - &cx * &bb) / &d;
        let r2 = &ux * &ux + &uy * &uy;
        (&a.0 + ux, &a.1 + uy, r2)
    }

    /// The order of the exact top of the circle of `t` (counter-clockwise) and `v`.
    fn top_vs(t: [Point2; 3]) -> impl Fn(&Q) -> Ordering {
        let (_, cy, r2) = circle(t);
        // cy + r vs v  <=>  (cy − v) + √r2 vs √0.
        move |v: &Q| cmp_root_sum(&(&cy - v), &r2, &Q::zero())
    }

    /// Whether the interval of `e` holds the exact top of the circle of `t`.
    fn holds_top(e: TopEstimate, t: [Point2; 3]) -> bool {
        let top_vs = top_vs(t);
        let (top, err) = (q(e.top), q(e.err as f64));
        top_vs(&(&top - &err)) != Ordering::Less && top_vs(&(&top + &err)) != Ordering::Greater
    }

    /// `x + √b` vs `√d` for `b, d >= 0`.
    fn cmp_root_sum(x: &Q, b: &Q, d: &Q) -> Ordering {
        let m = d - x * x - b; // x² + b + 2x√b vs d  <=>  2x√b vs m
        let four_xxb = Q::from_integer(4.into()) * x * x * b;
        if !x.is_negative() {
            if m.is_negative() {
                Ordering::Greater
            } else {
                four_xxb.cmp(&(&m * &m))
            }
        } else if b < &(x * x) || m.is_positive() {
            // Either x + √b < 0 <= √d, or 2x√b <= 0 < m.
            Ordering::Less
        } else {
            // Both 2x√b and m are <= 0: the smaller magnitude is the larger value.
            (&m * &m).cmp(&four_xxb)
        }
    }

    fn oracle_circle_site(t: [Point2; 3], s: Point2) -> Ordering {
        let (cx, cy, r2) = circle(t);
        // cy + r vs sy  <=>  (cy − sy) + √r2 vs √0.
        cmp_root_sum(&(&cy - q(s.y)), &r2, &Q::zero()).then_with(|| cx.cmp(&q(s.x)))
    }

    fn oracle_circles(t1: [Point2; 3], t2: [Point2; 3]) -> Ordering {
        let (cx1, cy1, r1) = circle(t1);
        let (cx2, cy2, r2) = circle(t2);
        cmp_root_sum(&(cy1 - cy2), &r1, &r2).then_with(|| cx1.cmp(&cx2))
    }

    /// Coordinates that tie often: small integers times one of a few powers of two.
    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![
            (
                -6i32..=6,
                prop::sample::select(vec![-1074, -600, -40, 0, 3, 500, 960])
            )
                .prop_map(|(m, e)| m as f64 * 2f64.powi(e)),
            -1e3f64..1e3,
        ]
    }

    fn point() -> impl Strategy<Value = Point2> {
        (coord(), coord()).prop_map(Point2::from)
    }

    /// Counter-clockwise triples (collinear ones rejected).
    fn ccw_triple() -> impl Strategy<Value = [Point2; 3]> {
        (point(), point(), point()).prop_filter_map("collinear", |(a, b, c)| {
            match super::super::orient2d(a, b, c) {
                super::super::Orientation::CounterClockwise => Some([a, b, c]),
                super::super::Orientation::Clockwise => Some([a, c, b]),
                super::super::Orientation::Collinear => None,
            }
        })
    }

    /// Fortune's preconditions for `breakpoint_side(p, r, s)`: distinct sites, both at or
    /// below s, a site on the line left of s, not both on the line; at equal heights (one
    /// intersection) the arc of the smaller x on the left.
    fn meets_sweep_preconditions(p: Point2, r: Point2, s: Point2) -> bool {
        p != r
            && p != s
            && r != s
            && p.y <= s.y
            && r.y <= s.y
            && (p.y < s.y || p.x < s.x)
            && (r.y < s.y || r.x < s.x)
            && (p.y < s.y || r.y < s.y)
            && (p.y != r.y || p.x < r.x)
    }

    fn unit_coord() -> impl Strategy<Value = f64> {
        (-8i32..=8).prop_map(|m| m as f64)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        #[test]
        fn breakpoint_side_matches_the_roots(p in point(), r in point(), s in point()) {
            prop_assume!(meets_sweep_preconditions(p, r, s));
            prop_assert_eq!(breakpoint_side(p, r, s), oracle_side(p, r, s));
        }

        #[test]
        fn breakpoint_side_on_a_small_lattice(
            v in prop::collection::vec((-4i32..=4, -4i32..=0), 3),
            scale in prop::sample::select(vec![1.0, 2f64.powi(-1070), 2f64.powi(1000)]),
        ) {
            // Sites at or below the line y = 0 through s: many ties on the bisectors.
            let [p, r, s] = [0, 1, 2].map(|k| Point2::new(v[k].0 as f64 * scale, v[k].1 as f64 * scale));
            let s = Point2::new(s.x, 0.0);
            prop_assume!(meets_sweep_preconditions(p, r, s));
            prop_assert_eq!(breakpoint_side(p, r, s), oracle_side(p, r, s));
        }

        #[test]
        fn circle_against_site_matches_the_oracle(t in ccw_triple(), s in point(), pick in 0usize..4) {
            // Sometimes the site is exactly at a triple's vertex height or on the circle.
            let s = if pick < 3 { Point2::new(s.x, t[pick].y) } else { s };
            let key = CircleKey::new(t[0], t[1], t[2]);
            prop_assert_eq!(cmp_circle_site(&key, t, s), oracle_circle_site(t, s));
        }

        #[test]
        fn circle_top_floor_is_the_largest_double_not_above_the_top(t in ccw_triple()) {
            let y = circle_top_floor(t);
            let exact_vs = top_vs(t);
            let top_vs = |v: f64| exact_vs(&q(v));
            prop_assert_ne!(top_vs(y), Ordering::Less, "{} is above the top", y);
            if y < f64::MAX {
                let next = f64::from_bits(if y >= 0.0 { y.to_bits() + 1 } else { y.to_bits() - 1 });
                let next = if y == 0.0 { f64::from_bits(1) } else { next };
                prop_assert_eq!(top_vs(next), Ordering::Less, "{} is not the largest", y);
            }
        }

        #[test]
        fn top_estimate_holds_the_exact_top(t in ccw_triple()) {
            let e = TopEstimate::new(t[0], t[1], t[2]);
            if e.err.is_finite() {
                prop_assert!(holds_top(e, t), "{:?}", e);
            }
        }

        #[test]
        fn integer_circle_estimate_holds_cancelling_tops(
            h in 2i32..=256,
            w in 1i32..=16,
            skew in 1i32..=16,
            shift in -4096i32..=4096,
            origin in 0usize..3,
        ) {
            // A large circle through two close sites near its top: the top is a small
            // difference of two large terms (p + √q with p near −√q, √q irrational).
            let y = shift as f64;
            let t = [
                Point2::new(-w as f64, y),
                Point2::new(0.0, y - h as f64),
                Point2::new((w + skew) as f64, y + 1.0),
            ];
            prop_assert_eq!(
                super::super::orient2d(t[0], t[1], t[2]),
                super::super::Orientation::CounterClockwise
            );
            let o = t[origin];
            let e = IntegerCircle::new(t, o).estimate(o).expect("q is exact here");
            prop_assert!(holds_top(e, t), "{:?}", e);
        }

        #[test]
        fn integer_circle_estimate_holds_the_exact_top(
            coords in proptest::array::uniform6(-4096i32..=4096),
            origin in 0usize..3,
        ) {
            let pts: Vec<Point2> =
                coords.chunks(2).map(|c| Point2::new(c[0] as f64, c[1] as f64)).collect();
            let t = match super::super::orient2d(pts[0], pts[1], pts[2]) {
                super::super::Orientation::CounterClockwise => [pts[0], pts[1], pts[2]],
                super::super::Orientation::Clockwise => [pts[0], pts[2], pts[1]],
                super::super::Orientation::Collinear => return Ok(()),
            };
            let o = t[origin];
            let Some(e) = IntegerCircle::new(t, o).estimate(o) else {
                // Only circles whose q could be inexact are left out.
                return Ok(());
            };
            prop_assert!(holds_top(e, t), "{:?}", e);
            prop_assert!((e.err as f64) <= 2f64.powi(-48) * (e.top.abs() + 1.0) * 64.0, "{:?}", e);
        }

        #[test]
        fn exact_top_estimate_is_tight_and_holds_the_exact_top(t in ccw_triple()) {
            let e = TopEstimate::exact(t[0], t[1], t[2]);
            let top_vs = top_vs(t);
            if e.err.is_finite() {
                prop_assert!(holds_top(e, t), "{:?}", e);
                // Tight: a few ulps of the top, or the least f32 for the tiniest tops.
                let least = f32::from_bits(1) as f64;
                prop_assert!((e.err as f64) <= (2f64.powi(-47) * e.top.abs()).max(least), "{:?}", e);
            } else {
                // Only a top whose bound leaves the f32 range decides nothing.
                let huge = q(2f64.powi(176));
                prop_assert!(
                    top_vs(&huge) == Ordering::Greater || top_vs(&-huge) == Ordering::Less
                );
            }
        }

        #[test]
        fn top_estimates_decide_as_the_exact_comparison(
            t1 in ccw_triple(),
            t2 in ccw_triple(),
            shift in unit_coord(),
            ulps in -3i64..=3,
            same in 0usize..4,
            y in coord(),
        ) {
            // Near-ties: the same circle's top a few ulps up or down (every point moved),
            // a horizontal translate (an exact tie), or unrelated circles.
            let nudge = |v: f64| if v == 0.0 { v } else { f64::from_bits((v.to_bits() as i64 + ulps) as u64) };
            let t2 = match same {
                0 => t1.map(|p| Point2::new(p.x, nudge(p.y))),
                1 => t1.map(|p| Point2::new(p.x + shift, p.y)),
                2 => [t1[1], t1[2], t1[0]],
                _ => t2,
            };
            prop_assume!(
                super::super::orient2d(t2[0], t2[1], t2[2])
                    == super::super::Orientation::CounterClockwise
            );
            let (e1, e2) = (TopEstimate::new(t1[0], t1[1], t1[2]), TopEstimate::new(t2[0], t2[1], t2[2]));
            let (k1, k2) = (CircleKey::new(t1[0], t1[1], t1[2]), CircleKey::new(t2[0], t2[1], t2[2]));
            if let Some(order) = e1.cmp(&e2) {
                prop_assert_eq!(order, cmp_circles(&k1, t1, &k2, t2));
                prop_assert_eq!(order.reverse(), e2.cmp(&e1).unwrap());
            }
            // The heap's form decides exactly when `cmp` does, the same way.
            prop_assert_eq!(e1.is_below(&e2), e1.cmp(&e2).map(|o| o == Ordering::Less));
            prop_assert_eq!(e2.is_below(&e1), e2.cmp(&e1).map(|o| o == Ordering::Less));
            // Against a height: the top itself rounded, a site's height, any height.
            for h in [e1.top, nudge(e1.top), t1[0].y, y] {
                if let Some(order) = e1.cmp_height(h) {
                    let site = Point2::new(t1[0].x, h);
                    prop_assert_eq!(order, cmp_circle_site(&k1, t1, site));
                }
            }
        }

        #[test]
        fn circles_match_the_oracle(t1 in ccw_triple(), t2 in ccw_triple(), shift in unit_coord(), same in 0usize..3) {
            // Half of the cases share the top exactly: a horizontal translate, or the same
            // circle through other points of it.
            let t2 = match same {
                0 => t1.map(|p| Point2::new(p.x + shift, p.y)),
                1 => [t1[1], t1[2], t1[0]],
                _ => t2,
            };
            // Rounding in the translate can flatten a triple of large coordinates.
            prop_assume!(
                super::super::orient2d(t2[0], t2[1], t2[2])
                    == super::super::Orientation::CounterClockwise
            );
            let (k1, k2) = (CircleKey::new(t1[0], t1[1], t1[2]), CircleKey::new(t2[0], t2[1], t2[2]));
            prop_assert_eq!(cmp_circles(&k1, t1, &k2, t2), oracle_circles(t1, t2));
            prop_assert_eq!(cmp_circles(&k2, t2, &k1, t1), oracle_circles(t2, t1));
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]

        #[test]
        fn integer_circles_match_the_exact_comparison(
            v in prop::collection::vec((0i32..=4096, 0i32..=4096), 6),
            near in prop::collection::vec((-3i32..=3, -3i32..=3), 6),
            local in 0usize..3,
            base in prop::sample::select(vec![0.0, -2048.0, 1e9]),
        ) {
            // Anywhere in a box of width 2^12, or two small clusters (the grid's ties),
            // possibly far from the origin.
            let p = |k: usize| {
                let (x, y) = if local > 0 { (near[k].0 + 2000 * (k as i32 / 3), near[k].1) } else { v[k] };
                Point2::new(base + x as f64, base + y as f64)
            };
            let ccw = |t: [Point2; 3]| match super::super::orient2d(t[0], t[1], t[2]) {
                super::super::Orientation::CounterClockwise => Some(t),
                super::super::Orientation::Clockwise => Some([t[0], t[2], t[1]]),
                super::super::Orientation::Collinear => None,
            };
            let t1 = ccw([p(0), p(1), p(2)]);
            let t2 = if local == 2 { t1.map(|t| t.map(|q| Point2::new(q.x + 1.0, q.y))) } else { ccw([p(3), p(4), p(5)]) };
            if let (Some(t1), Some(t2)) = (t1, t2) {
                let (k1, k2) = (CircleKey::new(t1[0], t1[1], t1[2]), CircleKey::new(t2[0], t2[1], t2[2]));
                let want = cmp_circles(&k1, t1, &k2, t2);
                if let Some(order) = cmp_integer_circles(t1, t2) {
                    prop_assert_eq!(order, want);
                }
                // Precomputed relative to another site of the set (the sweep's first site).
                for o in [t2[1], t1[2]] {
                    let (c1, c2) = (IntegerCircle::new(t1, o), IntegerCircle::new(t2, o));
                    if let Some(order) = c1.cmp(&c2) {
                        prop_assert_eq!(order, want);
                    }
                }
            }
        }
    }

    #[test]
    fn integer_circles_decide_the_grid_ties() {
        let p = |x: f64, y: f64| Point2::new(x, y);
        // Two unit squares side by side: translated circles, equal tops, x decides.
        let t1 = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0)];
        let t2 = t1.map(|v| p(v.x + 1.0, v.y));
        assert_eq!(cmp_integer_circles(t1, t2), Some(Ordering::Less));
        assert_eq!(cmp_integer_circles(t2, t1), Some(Ordering::Greater));
        // The same circle through another triple of the square: one event point.
        let t3 = [p(0.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
        assert_eq!(cmp_integer_circles(t1, t3), Some(Ordering::Equal));
        // Too large for the plain path: left to the exact stages.
        let big = [p(0.0, 0.0), p(4096.0, 1.0), p(1.0, 4096.0)];
        assert_eq!(cmp_integer_circles(big, t1), None);
        // Precomputed relative to a fixed site, as the sweep does: the same answers.
        let c = |t: [Point2; 3]| IntegerCircle::new(t, p(3.0, 2.0));
        assert_eq!(c(t1).cmp(&c(t2)), Some(Ordering::Less));
        assert_eq!(c(t2).cmp(&c(t1)), Some(Ordering::Greater));
        assert_eq!(c(t1).cmp(&c(t3)), Some(Ordering::Equal));
        assert_eq!(c(big).cmp(&c(t1)), None);
    }

    #[test]
    fn lattice_circles_with_equal_tops() {
        // Centre (0, 0), radius 5 through (3, 4), (-4, 3), (5, 0): top at (0, 5). Centre
        // (0, 1), radius 4: top (0, 5) too, a different circle; the site (0, 5) is on both.
        let p = |x: f64, y: f64| Point2::new(x, y);
        let t1 = [p(5.0, 0.0), p(3.0, 4.0), p(-4.0, 3.0)];
        let t2 = [p(4.0, 1.0), p(0.0, 5.0), p(-4.0, 1.0)];
        let (k1, k2) = (
            CircleKey::new(t1[0], t1[1], t1[2]),
            CircleKey::new(t2[0], t2[1], t2[2]),
        );
        assert_eq!(cmp_circles(&k1, t1, &k2, t2), Ordering::Equal);
        assert_eq!(cmp_circle_site(&k1, t1, p(0.0, 5.0)), Ordering::Equal);
        assert_eq!(cmp_circle_site(&k1, t1, p(1.0, 5.0)), Ordering::Less);
        assert_eq!(cmp_circle_site(&k1, t1, p(-1.0, 5.0)), Ordering::Greater);
        let t3 = t1.map(|v| p(v.x, v.y + 2f64.powi(-40)));
        let k3 = CircleKey::new(t3[0], t3[1], t3[2]);
        assert_eq!(cmp_circles(&k1, t1, &k3, t3), Ordering::Less);
    }

    #[test]
    fn top_estimates_decide_ordinary_triples_and_leave_ties_open() {
        let p = |x: f64, y: f64| Point2::new(x, y);
        // Unit-sized triples: the estimate is within a few ulps and decides.
        let t1 = [p(0.1, 0.2), p(0.7, 0.25), p(0.4, 0.9)];
        let t2 = t1.map(|v| p(v.x, v.y + 1e-9));
        let (e1, e2) = (
            TopEstimate::new(t1[0], t1[1], t1[2]),
            TopEstimate::new(t2[0], t2[1], t2[2]),
        );
        assert!((e1.err as f64) < 1e-14, "{e1:?}");
        assert_eq!(e1.cmp(&e2), Some(Ordering::Less));
        assert_eq!(e2.cmp(&e1), Some(Ordering::Greater));
        // An exact tie (a horizontal translate) is never decided in floating point.
        let t3 = t1.map(|v| p(v.x + 0.25, v.y));
        let e3 = TopEstimate::new(t3[0], t3[1], t3[2]);
        assert_eq!(e1.cmp(&e3), None);
        assert_eq!(e1.cmp_height(e1.top), None);
        // Differences too far apart in magnitude (below 2^-64 of the largest) or a flat
        // triple: no decision at all.
        let flat = TopEstimate::new(p(0.0, 0.0), p(1.0, 1e-30), p(2.0, 0.0));
        assert!(flat.err.is_infinite());
        let spread = TopEstimate::new(p(0.0, 0.0), p(1.0, 0.0), p(0.5, 1e-25));
        assert!(spread.err.is_infinite());
    }

    #[test]
    fn exact_top_estimate_is_tight_where_the_plain_one_is_loose() {
        let p = |x: f64, y: f64| Point2::new(x, y);
        // A far site and two near ones on a row above it: the centre is about 10^12 below,
        // so the top is a difference of two numbers near 10^12 and the plain estimate
        // loses 12 digits.
        let t = [p(-1e6, 0.5), p(3e-4, 0.9), p(7e-4, 0.9)];
        let loose = TopEstimate::new(t[0], t[1], t[2]);
        let tight = TopEstimate::exact(t[0], t[1], t[2]);
        assert!(loose.err as f64 > 1e-6, "{loose:?}");
        assert!((tight.err as f64) < 1e-14 * tight.top.abs(), "{tight:?}");
        // Both hold the exact top, which the bisection pins to one double.
        let holds = |e: TopEstimate, t: [Point2; 3]| {
            let floor = circle_top_floor(t);
            assert!(
                e.cmp_height(floor) != Some(Ordering::Less),
                "{e:?} vs {floor}"
            );
            assert!(
                e.cmp_height(floor.next_up()) != Some(Ordering::Greater),
                "{e:?}"
            );
            floor
        };
        holds(loose, t);
        let floor = holds(tight, t);
        // Decided against tops a few ulps away, where the plain one decides nothing.
        let above = TopEstimate {
            top: floor + 64.0 * (floor.next_up() - floor),
            err: 0.0,
        };
        assert_eq!(tight.is_below(&above), Some(true));
        assert_eq!(loose.is_below(&above), None);
        // A top past the doubles decides nothing; a subnormal one is still held (its
        // bound is the least f32, far above its size: the sweep scales its sites near 1).
        let beyond = [p(0.0, 0.0), p(f64::MAX, 1.0), p(-f64::MAX, 1.0)];
        assert!(TopEstimate::exact(beyond[0], beyond[1], beyond[2])
            .err
            .is_infinite());
        let tiny = [p(-2e-323, -4e-323), p(2e-323, -4e-323), p(0.0, -1e-323)];
        let e = TopEstimate::exact(tiny[0], tiny[1], tiny[2]);
        assert!(e.err.is_finite(), "{e:?}");
        holds(e, tiny);
    }

    #[test]
    fn scaling_keeps_magnitudes_normal_and_exact() {
        let mut pts = vec![Point2::new(1e300, -3e299), Point2::new(0.0, 2e250)];
        let before = pts.clone();
        let k = normalize_scale(&mut pts);
        assert!(pts.iter().all(|p| p.x.abs() < 2.0 && p.y.abs() < 2.0));
        let ratio = before[0].x / pts[0].x;
        assert_eq!(ratio.log2().fract(), 0.0);
        assert_eq!(ratio, 2f64.powi(-k));
        for (a, b) in before.iter().zip(&pts) {
            assert_eq!(a.x / ratio, b.x);
            assert_eq!(a.y / ratio, b.y);
        }
        // Subnormals next to 1e300: no exact common shift exists, nothing changes.
        let mut wide = vec![Point2::new(5e-324, 1e300)];
        assert_eq!(normalize_scale(&mut wide), 0);
        assert_eq!(wide, [Point2::new(5e-324, 1e300)]);
        // Subnormals alone are scaled up exactly, the largest magnitude into [1, 2).
        let mut tiny = vec![Point2::new(5e-324, -1.5e-323)];
        assert_eq!(normalize_scale(&mut tiny), 1073);
        assert_eq!(tiny, [Point2::new(0.5, -1.5)]);
    }
}
