//! Constructions: the new points that the Voronoi diagram, the proximity problems and the
//! calipers report (circumcentres, intersections of lines, midpoints), unit directions and
//! distances.
//!
//! These build new points, so they cannot be exact in `f64`; every *decision* stays with the
//! exact predicates. The points whose exact value is a rational function of the input
//! (circumcentres, the corners of a rectangle, where a segment crosses a bisector) are
//! *certified*: a rounded evaluation runs in midpoint–radius arithmetic ([`Ball`]: every
//! operation carries a rigorous bound on its distance to the exact value, underflow and
//! overflow included), on coordinate differences scaled by one power of two; it is accepted
//! when its bound is within half of [`ConstructedPoint::RELATIVE_ERROR`] of the point's size.
//! Otherwise (a nearly flat triangle, a point near the origin built from far-away input,
//! magnitudes that leave the filter's range) the point is formed exactly as `(X / W, Y / W)`
//! in big integers and rounded once per coordinate ([`rational_point`], shared by every
//! construction). So every finite input gets its point within the stated error, and a point
//! whose exact value is beyond the range of `f64` says so
//! ([`ConstructedPoint::BeyondRange`]).

use super::ball::{scaled_differences, Ball};
use super::bigint::BigInt;
use super::circle_predicates::Circumcentre;
use super::extended::exact_coords;
use super::predicates::pow2;
use super::{Point2, WideFloat};

/// A constructed point (a Voronoi vertex, a corner of a rectangle, the centre of an empty
/// circle), rounded from its exact value, a rational function of the input coordinates.
///
/// **Accuracy**, for the exact value `(x, y)` and the returned `(x̃, ỹ)`: both
/// `|x̃ − x|` and `|ỹ − y|` are at most
/// [`RELATIVE_ERROR`](Self::RELATIVE_ERROR)` · max(|x|, |y|) + 2^-1075`. The relative term is
/// a few roundings of a point of that size (16 to 32 units in the last place of the larger
/// coordinate); the absolute one, half the smallest subnormal, matters only for points
/// within the subnormal range.
///
/// **Range**: a coordinate whose exact value rounds to infinity under the IEEE rule
/// (magnitude at least `f64::MAX + ulp(f64::MAX) / 2 = 2^1024 − 2^970`) makes the point
/// [`BeyondRange`](Self::BeyondRange), holding both coordinates as [`WideFloat`] with the
/// same accuracy (and the beyond-range ones at least `2^1024` in magnitude, so their
/// [`WideFloat::to_f64`] is `None`). Every other point is [`Finite`](Self::Finite).
///
/// With the `serde` feature it serialises like [`Point2`], `{"x": .., "y": ..}`, each
/// coordinate beyond the range as its decimal string (the [`WideFloat`] rule).
///
/// ```
/// use compgeo::delaunay::voronoi;
/// use compgeo::geometry::{ConstructedPoint, Point2};
///
/// // A flat triangle 2e300 wide and 1e-300 high: its circumcentre is 1e900 below it.
/// let pts = [(-1e300, 0.0), (1e300, 0.0), (0.0, 1e-300)].map(Point2::from);
/// let v = voronoi(&pts)?;
/// let centre = v.vertex(0);
/// assert!(centre.is_beyond_range());
/// let [x, y] = centre.wide();
/// assert_eq!(x.to_f64(), Some(0.0));
/// assert_eq!(y.to_f64(), None);
/// assert!(y.to_string().ends_with("e899"), "{y}"); // −(1e300)² / (2 · 1e-300), about −5e899
/// assert_eq!(centre.saturating(), Point2::new(0.0, -f64::MAX));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ConstructedPoint {
    /// Both coordinates are within the range of `f64`: the rounded point.
    Finite(Point2),
    /// At least one coordinate is beyond the range of `f64`: both, rounded as
    /// [`WideFloat`]s.
    BeyondRange([WideFloat; 2]),
}

impl ConstructedPoint {
    /// The stated relative error of every constructed point, `2^-48` (about `3.6e-15`).
    ///
    /// Chosen so that the certified `f64` evaluation is accepted for nearly every point of
    /// ordinary input (its bound is a few tens of roundings times the conditioning of the
    /// construction) while staying a real promise: 16 to 32 units in the last place of the
    /// larger exact coordinate (`2^-48 M` for `M` in `[2^e, 2^(e+1))`, whose unit is
    /// `2^(e−52)`). The exact path rounds each coordinate to within 1.5 units of its own.
    pub const RELATIVE_ERROR: f64 = pow2(-48);

    /// The point, if it is within the range of `f64`.
    pub fn finite(self) -> Option<Point2> {
        match self {
            ConstructedPoint::Finite(p) => Some(p),
            ConstructedPoint::BeyondRange(_) => None,
        }
    }

    /// Whether a coordinate is beyond the range of `f64`.
    pub fn is_beyond_range(self) -> bool {
        matches!(self, ConstructedPoint::BeyondRange(_))
    }

    /// The coordinates as [`WideFloat`]s (exactly the rounded doubles of a finite point).
    pub fn wide(self) -> [WideFloat; 2] {
        match self {
            ConstructedPoint::Finite(p) => [WideFloat::from(p.x), WideFloat::from(p.y)],
            ConstructedPoint::BeyondRange(w) => w,
        }
    }

    /// The point with every coordinate beyond the range of `f64` clamped to `±f64::MAX`
    /// (for drawing, or for code that only needs a direction from far away).
    pub fn saturating(self) -> Point2 {
        match self {
            ConstructedPoint::Finite(p) => p,
            ConstructedPoint::BeyondRange([x, y]) => {
                Point2::new(x.to_f64_saturating(), y.to_f64_saturating())
            }
        }
    }
}

impl From<Point2> for ConstructedPoint {
    /// An input point, which is its own exact value.
    fn from(p: Point2) -> ConstructedPoint {
        ConstructedPoint::Finite(p)
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for ConstructedPoint {
    /// `{"x": .., "y": ..}` like [`Point2`]; a coordinate beyond `f64` as a decimal string.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut s = serializer.serialize_struct("ConstructedPoint", 2)?;
        match self {
            ConstructedPoint::Finite(p) => {
                s.serialize_field("x", &p.x)?;
                s.serialize_field("y", &p.y)?;
            }
            ConstructedPoint::BeyondRange([x, y]) => {
                s.serialize_field("x", x)?;
                s.serialize_field("y", y)?;
            }
        }
        s.end()
    }
}

/// The circumcentre of the triangle `a, b, c` (not collinear; either orientation), within
/// [`ConstructedPoint::RELATIVE_ERROR`].
///
/// The certified evaluation works at the vertex opposite the longest edge (the largest
/// angle): the determinant of its two edges then loses at most a few roundings relative to
/// its size however short one edge is, so a triangle with two nearly coincident vertices
/// keeps the fast path.
///
/// Panics if the points are collinear (a broken invariant of the caller: every Delaunay
/// triangle is proper).
#[inline]
pub(crate) fn circumcentre(a: Point2, b: Point2, c: Point2) -> ConstructedPoint {
    match circumcentre_rounded(a, b, c) {
        Some(p) => ConstructedPoint::Finite(p),
        None => circumcentre_exact(a, b, c),
    }
}

/// The certified `f64` circumcentre, or `None` when its bound does not certify it: the
/// rounded centre and error bounds of the empty circle's predicates
/// ([`Circumcentre`], `circle_predicates/mod.rs`, which derives them), accepted or not.
#[inline]
pub(crate) fn circumcentre_rounded(a: Point2, b: Point2, c: Point2) -> Option<Point2> {
    let (centre, err_x, err_y) = Circumcentre::new(a, b, c).rounded();
    certified(
        Ball {
            mid: centre.x,
            rad: err_x,
        },
        Ball {
            mid: centre.y,
            rad: err_y,
        },
    )
}

/// The circumcentre in big integers: with `b' = b − a`, `c' = c − a`,
/// `a + (c'y |b'|² − b'y |c'|², b'x |c'|² − c'x |b'|²) / (2 b' × c')`.
#[cold]
#[inline(never)]
fn circumcentre_exact(a: Point2, b: Point2, c: Point2) -> ConstructedPoint {
    let ([ax, ay, bx, by, cx, cy], base) = exact_coords([a.x, a.y, b.x, b.y, c.x, c.y]);
    let (ubx, uby) = (bx.sub(&ax), by.sub(&ay));
    let (ucx, ucy) = (cx.sub(&ax), cy.sub(&ay));
    let lb = ubx.mul(&ubx).add(&uby.mul(&uby));
    let lc = ucx.mul(&ucx).add(&ucy.mul(&ucy));
    let half_d = ubx.mul(&ucy).sub(&uby.mul(&ucx));
    let d = half_d.add(&half_d);
    let nx = ucy.mul(&lb).sub(&uby.mul(&lc));
    let ny = ubx.mul(&lc).sub(&ucx.mul(&lb));
    rational_point(
        &ax.mul(&d).add(&nx),
        &ay.mul(&d).add(&ny),
        &d,
        base,
        "a triangle that is not flat",
    )
}

/// Where the line through `p` perpendicular to the line `a → b` meets the line through `q`
/// parallel to it (`a ≠ b`): a corner of a rectangle with a side on `a → b`, within
/// [`ConstructedPoint::RELATIVE_ERROR`].
///
/// With `g = b − a`, the point is `a + (((p − a) · g) g + (g × (q − a)) g⊥) / |g|²` for
/// `g⊥ = (−g_y, g_x)`; `q = a` gives the foot of the perpendicular from `p`.
pub(crate) fn rectangle_corner(a: Point2, b: Point2, p: Point2, q: Point2) -> ConstructedPoint {
    let rounded = || {
        let ([gx, gy, px, py, qx, qy], k) = scaled_differences([
            (b.x, a.x),
            (b.y, a.y),
            (p.x, a.x),
            (p.y, a.y),
            (q.x, a.x),
            (q.y, a.y),
        ])?;
        let along = px.mul(gx).add(py.mul(gy));
        let across = gx.mul(qy).sub(gy.mul(qx));
        let n = gx.mul(gx).add(gy.mul(gy));
        let ox = along.mul(gx).sub(across.mul(gy)).div(n)?.scaled(-k);
        let oy = along.mul(gy).add(across.mul(gx)).div(n)?.scaled(-k);
        certified(exact(a.x).add(ox), exact(a.y).add(oy))
    };
    match rounded() {
        Some(c) => ConstructedPoint::Finite(c),
        None => rectangle_corner_exact(a, b, p, q),
    }
}

#[cold]
#[inline(never)]
fn rectangle_corner_exact(a: Point2, b: Point2, p: Point2, q: Point2) -> ConstructedPoint {
    let ([ax, ay, bx, by, px, py, qx, qy], base) =
        exact_coords([a.x, a.y, b.x, b.y, p.x, p.y, q.x, q.y]);
    let (gx, gy) = (bx.sub(&ax), by.sub(&ay));
    let along = px.sub(&ax).mul(&gx).add(&py.sub(&ay).mul(&gy));
    let across = gx.mul(&qy.sub(&ay)).sub(&gy.mul(&qx.sub(&ax)));
    let n = gx.mul(&gx).add(&gy.mul(&gy));
    let x = ax.mul(&n).add(&along.mul(&gx)).sub(&across.mul(&gy));
    let y = ay.mul(&n).add(&along.mul(&gy)).add(&across.mul(&gx));
    rational_point(&x, &y, &n, base, "an edge of two distinct points")
}

/// Where the line `p → q` crosses the bisector of `s` and `w`, within
/// [`ConstructedPoint::RELATIVE_ERROR`]: `p + t (q − p)` with `t = N / (2 D)`,
/// `N = (w − s) · ((w − p) + (s − p))` and `D = (q − p) · (w − s)`, which must not be zero
/// (the line is not parallel to the bisector).
pub(crate) fn bisector_crossing(p: Point2, q: Point2, s: Point2, w: Point2) -> ConstructedPoint {
    let rounded = || {
        let ([gx, gy, ux, uy, dwx, dwy, dsx, dsy], k) = scaled_differences([
            (q.x, p.x),
            (q.y, p.y),
            (w.x, s.x),
            (w.y, s.y),
            (w.x, p.x),
            (w.y, p.y),
            (s.x, p.x),
            (s.y, p.y),
        ])?;
        let n = ux.mul(dwx.add(dsx)).add(uy.mul(dwy.add(dsy)));
        let t = n.div(gx.mul(ux).add(gy.mul(uy)).twice())?;
        certified(
            exact(p.x).add(t.mul(gx).scaled(-k)),
            exact(p.y).add(t.mul(gy).scaled(-k)),
        )
    };
    match rounded() {
        Some(c) => ConstructedPoint::Finite(c),
        None => bisector_crossing_exact(p, q, s, w),
    }
}

#[cold]
#[inline(never)]
fn bisector_crossing_exact(p: Point2, q: Point2, s: Point2, w: Point2) -> ConstructedPoint {
    let ([px, py, qx, qy, sx, sy, wx, wy], base) =
        exact_coords([p.x, p.y, q.x, q.y, s.x, s.y, w.x, w.y]);
    let (gx, gy) = (qx.sub(&px), qy.sub(&py));
    let (ux, uy) = (wx.sub(&sx), wy.sub(&sy));
    let n = ux
        .mul(&wx.sub(&px).add(&sx.sub(&px)))
        .add(&uy.mul(&wy.sub(&py).add(&sy.sub(&py))));
    let half = gx.mul(&ux).add(&gy.mul(&uy));
    let d = half.add(&half);
    let x = px.mul(&d).add(&n.mul(&gx));
    let y = py.mul(&d).add(&n.mul(&gy));
    rational_point(&x, &y, &d, base, "a line not parallel to the bisector")
}

/// The rounded point of a certified evaluation, if its bounds certify
/// [`ConstructedPoint::RELATIVE_ERROR`] and the range: each bound at most half the stated
/// error times the larger rounded coordinate (so at most the stated error times the exact
/// one's: `e ≤ (τ/2) (M + e)` gives `e ≤ τ M`), and both coordinates below `2^1023` (so the
/// exact ones are far below the overflow threshold).
#[inline]
pub(crate) fn certified(x: Ball, y: Ball) -> Option<Point2> {
    let limit = ACCEPT * x.mid.abs().max(y.mid.abs());
    // Every comparison is false for NaN.
    let accepted = x.mid.abs() < RANGE && y.mid.abs() < RANGE && x.rad <= limit && y.rad <= limit;
    accepted.then(|| Point2::new(x.mid, y.mid))
}

/// The acceptance threshold of [`certified`]: half the stated error.
const ACCEPT: f64 = ConstructedPoint::RELATIVE_ERROR / 2.0;

/// 2^1023: certified coordinates stay below it.
const RANGE: f64 = pow2(1023);

/// A double as an exact ball.
#[inline]
fn exact(v: f64) -> Ball {
    Ball { mid: v, rad: 0.0 }
}

/// The point `(x / w, y / w) · 2^base` of big integers (`w ≠ 0`, else a panic naming the
/// caller's `invariant`), each coordinate rounded to within 1.5 units in its last place
/// (the numerator and the denominator rounded correctly, then their quotient) and, in the
/// subnormal range, once more to the nearest double (2^-1075 at most). Whether a coordinate
/// is beyond the range of `f64` is decided exactly.
///
/// The one rounding of exact rational points, shared by every construction.
pub(crate) fn rational_point(
    x: &BigInt,
    y: &BigInt,
    w: &BigInt,
    base: i32,
    invariant: &str,
) -> ConstructedPoint {
    let den = WideFloat::from_big(w);
    let unit = WideFloat::scaled(1.0, base);
    let coordinate = |n: &BigInt| {
        let v = WideFloat::from_big(n)
            .checked_div(den)
            .unwrap_or_else(|| panic!("a zero denominator: expected {invariant}"))
            .mul(unit);
        // Below 2^1023 the rounded value is at most 1.5 ulps from the exact one, so the
        // exact one is far below the overflow threshold; above, decide exactly.
        if v.abs() < WideFloat::scaled(1.0, 1023) || !overflows(n, w, base) {
            let f =
                v.to_f64()
                    .unwrap_or(f64::MAX.copysign(if v.is_negative() { -1.0 } else { 1.0 }));
            return Ok(f);
        }
        // Beyond: at least 2^1024, so it never prints as a finite double (the exact value
        // is at least 2^1024 − 2^970, within 2^-54 relative of that).
        let least = WideFloat::scaled(if v.is_negative() { -1.0 } else { 1.0 }, 1024);
        Err(if v.abs() < least.abs() { least } else { v })
    };
    match (coordinate(x), coordinate(y)) {
        (Ok(x), Ok(y)) => ConstructedPoint::Finite(Point2::new(x, y)),
        (x, y) => {
            let wide = |c: Result<f64, WideFloat>| c.map_or_else(|w| w, WideFloat::from);
            ConstructedPoint::BeyondRange([wide(x), wide(y)])
        }
    }
}

/// Whether `|n / w| · 2^base` rounds to infinity: at least `2^1024 − 2^970`, the midpoint
/// between `f64::MAX` and `2^1024` (a tie rounds to the even `2^1024`).
fn overflows(n: &BigInt, w: &BigInt, base: i32) -> bool {
    let threshold = BigInt::from_parts(false, (1 << 54) - 1, 970);
    let shift = BigInt::from_parts(false, 1, base.unsigned_abs());
    let (lhs, rhs) = if base >= 0 {
        (n.abs().mul(&shift), w.abs().mul(&threshold))
    } else {
        (n.abs(), w.abs().mul(&threshold).mul(&shift))
    };
    lhs.sub(&rhs).signum() >= 0
}

/// The midpoint of `a` and `b`: each coordinate within one unit in the last place (the
/// rounded sum halved, or the sum of the halves when the sum overflows), plus 2^-1075 in
/// the subnormal range. It is always within the range of `f64`.
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

/// The unit vector from `a` towards `b` (`a != b`), within a few units in the last place.
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

#[cfg(test)]
mod tests;
