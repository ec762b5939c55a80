//! Squared radii of the largest empty circle's candidates, compared exactly: a filter on
//! approximations with relative error bounds, exact ties of lattice circumcircles from
//! exact double factors, and the big-integer evaluation of `num₁ den₂ − num₂ den₁`.

use super::{dot, square_sum};
use crate::geometry::ball::{scaled_differences, times_pow2, U};
use crate::geometry::bigint::BigInt;
use crate::geometry::expansion::two_diff;
use crate::geometry::extended::exact_coords;
use crate::geometry::extended::{decompose, exponent, scale_by_pow2};
use crate::geometry::predicates::pow2;
use crate::geometry::{Point2, WideFloat};
use std::cell::OnceCell;
use std::cmp::Ordering;

/// The squared radius of a candidate circle of the largest empty circle, compared exactly
/// by [`SquaredRadius::cmp`].
///
/// Kept as its defining points (for the exact stages, each computed once on demand) and,
/// when the filter can bound it, an approximation with a relative error bound.
#[derive(Debug, Clone)]
pub(crate) struct SquaredRadius {
    pub(super) circle: Circle,
    pub(super) approx: Option<Approx>,
    grid: OnceCell<Option<GridFactors>>,
    exact: OnceCell<Exact>,
}

/// What defines a candidate circle.
#[derive(Debug, Clone, Copy)]
pub(super) enum Circle {
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
pub(super) struct Approx {
    pub(super) mantissa: f64,
    pub(super) exp: i32,
    pub(super) rel: f64,
}

/// `r² = num / den · 2^(2 base)`, `den > 0`.
#[derive(Debug, Clone)]
struct Exact {
    num: BigInt,
    den: BigInt,
    base: i32,
}

impl SquaredRadius {
    /// The circumcircle of `tri` (not collinear), with its filter's approximation.
    pub(super) fn circumcircle(tri: [Point2; 3], approx: Option<Approx>) -> SquaredRadius {
        SquaredRadius {
            circle: Circle::Circumcircle(tri),
            approx,
            grid: OnceCell::new(),
            exact: OnceCell::new(),
        }
    }

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

    /// The radius `√(num / den) · 2^base` from the exact squared radius, with relative
    /// error below 2^-51 for every finite input: numerator and denominator rounded once
    /// each, then a quotient and a square root (2.5 roundings of 2^-53 in all).
    pub(crate) fn radius(&self) -> WideFloat {
        let e = self.exact();
        let squared = WideFloat::from_big(&e.num)
            .checked_div(WideFloat::from_big(&e.den))
            .expect("the denominator is positive");
        squared
            .sqrt()
            .expect("a squared radius is not negative")
            .scale_pow2(e.base)
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
    pub(super) fn new(value: f64, exp: i32, rel: f64) -> Option<Approx> {
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
    pub(super) fn cmp(&self, other: &Approx) -> Option<Ordering> {
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
pub(super) struct GridFactors {
    /// `|b − c|², |b − a|², |c − a|²` in increasing order and `|(b − a) × (c − a)|`, in
    /// the frame.
    pub(super) l: [f64; 3],
    pub(super) hd: f64,
    pub(super) k: i32,
}

impl GridFactors {
    /// The factors of the circumcircle of `a, b, c`, if they are exact doubles.
    pub(super) fn new([a, b, c]: [Point2; 3]) -> Option<GridFactors> {
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
    pub(super) fn cmp(&self, o: &GridFactors) -> Ordering {
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
pub(super) fn cmp_products(lhs: [f64; 5], e1: i32, rhs: [f64; 5], e2: i32) -> Ordering {
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
