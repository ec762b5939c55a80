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
//! - **Event order.** A circle event of sites `a, b, c` happens when the line touches their
//!   circumcircle from below, at `y = cy + r`; with `a` as origin this is
//!   `a.y + (P + √Q) / D` for integer polynomials `P` (degree 3), `Q` (degree 6) and the
//!   doubled signed area `D`. Comparing it with a site's `y` or with another event's leads
//!   to `x + √p − √q` with rational `x, p, q`, whose sign follows from a case analysis and
//!   squaring. Ties in `y` are broken by `x` (the centre's), so events are ordered
//!   lexicographically by their point on the sweep line.
//!
//! Stages, as for the other predicates: a filter in interval arithmetic (every operation
//! rounded outwards with `next_down` / `next_up`; overflow or NaN gives an unbounded
//! interval, which decides nothing), then an exact evaluation in big integers on the
//! doubles' exact binary values brought to a common exponent (see `products.rs`).

use super::bigint::BigInt;
use super::extended::decompose;
use super::{cmp_dist, Point2};
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
        let bb = bx.square().add(by.square());
        let cc = cx.square().add(cy.square());
        let d = bx.mul(cy).sub(by.mul(cx)).twice();
        let ux = cy.mul(bb).sub(by.mul(cc)).div(d);
        let uy = bx.mul(cc).sub(cx.mul(bb)).div(d);
        let r = ux.square().add(uy.square()).sqrt();
        CircleKey {
            top: ay.add(uy).add(r),
            x: ax.add(ux),
        }
    }
}

/// Where `s` is relative to the breakpoint between the beach-line arcs of `p` (left) and
/// `q` (right) when the sweep line passes through `s`: `Less` if left of it, `Equal` if on
/// it, `Greater` if right of it.
///
/// Preconditions (Fortune's sweep guarantees them): `p != q`, both at or below `s`
/// (`p.y <= s.y`, `q.y <= s.y`), `s` equal to neither; a site on the sweep line is an earlier
/// site of the same row, so it is left of `s`. When both `p` and `q` are on the line (the
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
    // (P + √Q) / D vs sy  <=>  √Q vs sy·D − P.
    let t = sy.mul(&circle.d).sub(&circle.p);
    let top = if t.signum() <= 0 {
        if t.signum() == 0 && circle.q.signum() == 0 {
            Ordering::Equal
        } else {
            Ordering::Greater
        }
    } else {
        ordering(circle.q.sub(&t.mul(&t)).signum())
    };
    top.then_with(|| {
        key.x.cmp(site.x).unwrap_or_else(|| {
            // X / D vs sx.
            ordering(circle.x.sub(&sx.mul(&circle.d)).signum())
        })
    })
}

/// Compares the event points of two circles (lexicographically: top `y`, then the
/// centre's `x`).
pub(crate) fn cmp_circles(k1: &CircleKey, t1: [Point2; 3], k2: &CircleKey, t2: [Point2; 3]) -> Ordering {
    if let Some(order) = k1.top.cmp(k2.top) {
        return order;
    }
    let coords: Vec<f64> = t1.iter().chain(&t2).flat_map(|p| [p.x, p.y]).collect();
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
            Interval {
                lo: lo.next_down(),
                hi: hi.next_up(),
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
        let p = [self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi];
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
        let p = [self.lo / o.lo, self.lo / o.hi, self.hi / o.lo, self.hi / o.hi];
        Interval::outward(
            p[0].min(p[1]).min(p[2].min(p[3])),
            p[0].max(p[1]).max(p[2].max(p[3])),
        )
    }

    /// The square root of the non-negative part (the exact value is a sum of squares).
    #[inline]
    fn sqrt(self) -> Interval {
        if !self.is_bounded() {
            return Interval::ENTIRE;
        }
        Interval::outward(self.lo.max(0.0).sqrt(), self.hi.max(0.0).sqrt()).non_negative()
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

/// `|s − p|² (s.y − q.y)` vs `|s − q|² (s.y − p.y)`: the radii of the circles through `p`
/// and `q` touching the line `y = s.y` at `s`, denominators cleared (both are `>= 0`).
fn cmp_tangent_radii(p: Point2, q: Point2, s: Point2) -> Ordering {
    let (sx, sy) = (Interval::point(s.x), Interval::point(s.y));
    let (px, py) = (sx.sub(Interval::point(p.x)), sy.sub(Interval::point(p.y)));
    let (qx, qy) = (sx.sub(Interval::point(q.x)), sy.sub(Interval::point(q.y)));
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
/// is `(p + √q) / d` and the centre's `x` is `x / d`, with `d > 0`.
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

/// Every coordinate as an exact big integer, all scaled by the same power of two.
fn exact_coords(coords: &[f64]) -> Vec<BigInt> {
    let parts: Vec<(bool, u64, i32)> = coords.iter().map(|&v| decompose(v)).collect();
    let base = parts
        .iter()
        .filter(|&&(_, m, _)| m != 0)
        .map(|&(_, _, e)| e)
        .min()
        .unwrap_or(0);
    parts
        .iter()
        .map(|&(negative, m, e)| {
            BigInt::from_parts(negative, m, if m == 0 { 0 } else { (e - base) as u32 })
        })
        .collect()
}

fn ordering(sign: i32) -> Ordering {
    sign.cmp(&0)
}
