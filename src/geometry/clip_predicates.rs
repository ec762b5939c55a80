//! Exact predicates for clipping a Voronoi cell to a box (`delaunay/clip.rs`).
//!
//! A cell and a box are both intersections of half-planes, so the clipper works on *lines*
//! rather than on rounded points: every vertex of the polygon being clipped is the meeting
//! point of two lines, and every decision is the side of a third line on which that meeting
//! point lies. The lines of one cell, in a frame centred on its site `s`, are
//!
//! - the bisector of `s` and a neighbour `t`, kept side `s`: with `u = t − s`,
//!   `−2u · p + |u|² ≥ 0`;
//! - the four sides of the box `[x₀, x₁] × [y₀, y₁]`: `x₁ − x ≥ 0`, `y₁ − y ≥ 0`,
//!   `x − x₀ ≥ 0`, `y − y₀ ≥ 0`;
//! - the line at infinity, `1 ≥ 0` (every point), which closes an unbounded cell.
//!
//! Each line is a triple `(a, b, c)` keeping `a x + b y + c w ≥ 0` in homogeneous coordinates
//! `(x, y, w)`. Two lines `Lᵢ` (arriving) and `Lⱼ` (leaving) of a counter-clockwise convex
//! polygon meet at `Lᵢ × Lⱼ` with `w ≥ 0`: `w > 0` for a finite point, `w = 0` for a point at
//! infinity, the direction in which the polygon runs off along `Lᵢ` (oriented projective
//! geometry). The side of a third line `Lₖ` on which it lies is the sign of the determinant
//! `det(Lᵢ, Lⱼ, Lₖ)`, a polynomial of degree at most 4 in the coordinates (bisectors have
//! degree 1 in `a, b` and 2 in `c`). A half-plane cell also has a vertex at infinity in the
//! direction of its inner normal `(a, b, 0)`, which splits its half-turn at infinity.
//!
//! Stages, as for the other predicates: a filter in midpoint–radius arithmetic ([`Ball`]) on
//! the coordinate differences from the site, scaled by one power of two into `[1, 2)`; when
//! its bound does not decide, or a difference overflows, the determinant is evaluated in
//! the crate's big integers on the exact binary values.

use super::ball::Ball;
use super::bigint::BigInt;
use super::construct::{certified, rational_point};
use super::extended::{exact_integers, exponent};
use super::{ConstructedPoint, Point2};
use std::cell::OnceCell;

/// A vertex of a polygon being clipped, in terms of the lines of its [`CellLines`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Meet {
    /// Where line `0` (arriving) meets line `1` (leaving): their cross product.
    Lines(usize, usize),
    /// The point at infinity in the direction of line `0`'s inner normal.
    Normal(usize),
}

/// The lines of one cell: its bisectors (one per neighbour, in the caller's order), then the
/// box's right, top, left and bottom sides, then the line at infinity.
pub(crate) struct CellLines {
    site: Point2,
    neighbours: Vec<Point2>,
    bounds: [f64; 4],
    /// The lines in the filter's frame: relative to the site, scaled by `2^scale`; `None`
    /// when a difference overflows or all are zero.
    rounded: Option<(Vec<[Ball; 3]>, i32)>,
    /// The lines in big integers (relative to the site, in units of `2^base`), made on the
    /// first decision the filter leaves open.
    exact: OnceCell<ExactLines>,
}

struct ExactLines {
    lines: Vec<[BigInt; 3]>,
    site: [BigInt; 2],
    base: i32,
}

impl CellLines {
    /// The lines of the cell of `site` with the given neighbours (each different from `site`),
    /// clipped to the box `[x₀, x₁] × [y₀, y₁]` given as `[x₀, y₀, x₁, y₁]`.
    pub(crate) fn new(site: Point2, neighbours: Vec<Point2>, bounds: [f64; 4]) -> CellLines {
        let rounded = rounded_lines(site, &neighbours, bounds);
        CellLines {
            site,
            neighbours,
            bounds,
            rounded,
            exact: OnceCell::new(),
        }
    }

    /// The index of the box's side `i` (0 right, 1 top, 2 left, 3 bottom).
    pub(crate) fn side(&self, i: usize) -> usize {
        self.neighbours.len() + i
    }

    /// The index of the line at infinity.
    pub(crate) fn infinity(&self) -> usize {
        self.neighbours.len() + 4
    }

    /// Which box side line `line` is, if it is one.
    pub(crate) fn as_side(&self, line: usize) -> Option<usize> {
        line.checked_sub(self.neighbours.len()).filter(|&i| i < 4)
    }

    /// The sign of line `line` at the vertex `at`: 1 strictly inside its half-plane, 0 on the
    /// line, −1 outside. Exact.
    pub(crate) fn sign(&self, at: Meet, line: usize) -> i32 {
        if let Some((lines, _)) = &self.rounded {
            let value = match at {
                Meet::Lines(i, j) => det(&lines[i], &lines[j], &lines[line]),
                Meet::Normal(i) => {
                    let (n, l) = (&lines[i], &lines[line]);
                    n[0].mul(l[0]).add(n[1].mul(l[1]))
                }
            };
            if let Some(order) = value.sign() {
                return order as i32;
            }
        }
        self.sign_exact(at, line)
    }

    #[cold]
    #[inline(never)]
    fn sign_exact(&self, at: Meet, line: usize) -> i32 {
        let lines = &self.exact().lines;
        let l = &lines[line];
        match at {
            Meet::Lines(i, j) => {
                let [x, y, w] = cross(&lines[i], &lines[j]);
                l[0].mul(&x).add(&l[1].mul(&y)).add(&l[2].mul(&w)).signum()
            }
            Meet::Normal(i) => {
                let n = &lines[i];
                n[0].mul(&l[0]).add(&n[1].mul(&l[1])).signum()
            }
        }
    }

    /// The finite point where lines `i` and `j` meet (`i × j` must have `w > 0`), within
    /// [`ConstructedPoint::RELATIVE_ERROR`](super::ConstructedPoint::RELATIVE_ERROR) of its
    /// exact value and then clamped into the box; a coordinate fixed by a box side is that
    /// side's exact value.
    pub(crate) fn point(&self, i: usize, j: usize) -> Point2 {
        let [x0, y0, x1, y1] = self.bounds;
        let fixed = |line: usize| self.as_side(line);
        let (mut fx, mut fy) = (None, None);
        for side in [fixed(i), fixed(j)].into_iter().flatten() {
            match side {
                0 => fx = Some(x1),
                1 => fy = Some(y1),
                2 => fx = Some(x0),
                _ => fy = Some(y0),
            }
        }
        if let (Some(x), Some(y)) = (fx, fy) {
            return Point2::new(x, y);
        }
        let p = self
            .point_rounded(i, j, fx.is_some(), fy.is_some())
            .unwrap_or_else(|| self.point_exact(i, j));
        Point2::new(
            fx.unwrap_or(p.x.clamp(x0, x1)),
            fy.unwrap_or(p.y.clamp(y0, y1)),
        )
    }

    /// The filter's point, if its bound certifies it: relative to the larger coordinate, or,
    /// when the caller replaces x (`x_fixed`) or y (`y_fixed`) by a side's, relative to the
    /// other coordinate alone.
    fn point_rounded(&self, i: usize, j: usize, x_fixed: bool, y_fixed: bool) -> Option<Point2> {
        let (lines, scale) = self.rounded.as_ref()?;
        let [x, y, w] = cross_balls(&lines[i], &lines[j]);
        let back = |v: Ball, s: f64| Some(v.div(w)?.scaled(-scale).add(Ball { mid: s, rad: 0.0 }));
        let (x, y) = (back(x, self.site.x)?, back(y, self.site.y)?);
        // Every comparison is false for NaN.
        let own = |v: Ball| {
            v.mid.abs() < f64::MAX && v.rad <= ConstructedPoint::RELATIVE_ERROR / 2.0 * v.mid.abs()
        };
        match (x_fixed, y_fixed) {
            (true, _) => own(y).then_some(Point2::new(x.mid, y.mid)),
            (_, true) => own(x).then_some(Point2::new(x.mid, y.mid)),
            _ => certified(x, y),
        }
    }

    #[cold]
    #[inline(never)]
    fn point_exact(&self, i: usize, j: usize) -> Point2 {
        let e = self.exact();
        let [x, y, w] = cross(&e.lines[i], &e.lines[j]);
        rational_point(
            &x.add(&e.site[0].mul(&w)),
            &y.add(&e.site[1].mul(&w)),
            &w,
            e.base,
            "two lines that meet",
        )
        .saturating()
    }

    fn exact(&self) -> &ExactLines {
        self.exact.get_or_init(|| {
            let mut coords = vec![self.site.x, self.site.y];
            coords.extend(self.neighbours.iter().flat_map(|t| [t.x, t.y]));
            coords.extend(self.bounds);
            let (ints, base) = exact_integers(&coords);
            let (sx, sy) = (&ints[0], &ints[1]);
            let zero = || BigInt::from_parts(false, 0, 0);
            let one = |negative| BigInt::from_parts(negative, 1, 0);
            let m = self.neighbours.len();
            let mut lines = Vec::with_capacity(m + 5);
            for k in 0..m {
                let ux = ints[2 + 2 * k].sub(sx);
                let uy = ints[3 + 2 * k].sub(sy);
                let c = ux.mul(&ux).add(&uy.mul(&uy));
                let minus_twice = |v: &BigInt| zero().sub(&v.add(v));
                lines.push([minus_twice(&ux), minus_twice(&uy), c]);
            }
            let b = &ints[2 + 2 * m..];
            lines.push([one(true), zero(), b[2].sub(sx)]);
            lines.push([zero(), one(true), b[3].sub(sy)]);
            lines.push([one(false), zero(), sx.sub(&b[0])]);
            lines.push([zero(), one(false), sy.sub(&b[1])]);
            lines.push([zero(), zero(), one(false)]);
            ExactLines {
                lines,
                site: [sx.clone(), sy.clone()],
                base,
            }
        })
    }
}

/// The filter's lines: differences from the site as balls, scaled by one power of two.
fn rounded_lines(
    site: Point2,
    neighbours: &[Point2],
    [x0, y0, x1, y1]: [f64; 4],
) -> Option<(Vec<[Ball; 3]>, i32)> {
    let mut diffs: Vec<Ball> = neighbours
        .iter()
        .flat_map(|t| [Ball::diff(t.x, site.x), Ball::diff(t.y, site.y)])
        .collect();
    diffs.extend([
        Ball::diff(x1, site.x),
        Ball::diff(y1, site.y),
        Ball::diff(site.x, x0),
        Ball::diff(site.y, y0),
    ]);
    let m = diffs.iter().fold(0.0f64, |m, b| m.max(b.mid.abs()));
    // Written so that NaN fails too.
    if !(m > 0.0 && m < f64::INFINITY) {
        return None;
    }
    let scale = -exponent(m);
    let d: Vec<Ball> = diffs.iter().map(|b| b.scaled(scale)).collect();
    let exact = |v: f64| Ball { mid: v, rad: 0.0 };
    let neg = |b: Ball| Ball {
        mid: -b.mid,
        rad: b.rad,
    };
    let n = neighbours.len();
    let mut lines = Vec::with_capacity(n + 5);
    for k in 0..n {
        let (ux, uy) = (d[2 * k], d[2 * k + 1]);
        lines.push([neg(ux.twice()), neg(uy.twice()), ux.mul(ux).add(uy.mul(uy))]);
    }
    let b = &d[2 * n..];
    lines.push([exact(-1.0), exact(0.0), b[0]]);
    lines.push([exact(0.0), exact(-1.0), b[1]]);
    lines.push([exact(1.0), exact(0.0), b[2]]);
    lines.push([exact(0.0), exact(1.0), b[3]]);
    lines.push([exact(0.0), exact(0.0), exact(1.0)]);
    Some((lines, scale))
}

/// `det(p, q, r)`, expanded along `r`: `r · (p × q)`.
fn det(p: &[Ball; 3], q: &[Ball; 3], r: &[Ball; 3]) -> Ball {
    let [x, y, w] = cross_balls(p, q);
    r[0].mul(x).add(r[1].mul(y)).add(r[2].mul(w))
}

fn cross_balls(p: &[Ball; 3], q: &[Ball; 3]) -> [Ball; 3] {
    [
        p[1].mul(q[2]).sub(p[2].mul(q[1])),
        p[2].mul(q[0]).sub(p[0].mul(q[2])),
        p[0].mul(q[1]).sub(p[1].mul(q[0])),
    ]
}

fn cross(p: &[BigInt; 3], q: &[BigInt; 3]) -> [BigInt; 3] {
    [
        p[1].mul(&q[2]).sub(&p[2].mul(&q[1])),
        p[2].mul(&q[0]).sub(&p[0].mul(&q[2])),
        p[0].mul(&q[1]).sub(&p[1].mul(&q[0])),
    ]
}
