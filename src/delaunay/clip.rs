//! Clipping Voronoi cells to a box.

use super::voronoi::{Ray, Voronoi};
use crate::error::{Error, Result};
use crate::geometry::construct::scale_of;
use crate::geometry::{BoundingBox, Point2, PointSet};

/// An axis-parallel box to clip Voronoi cells to: `min.x < max.x`, `min.y < max.y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClipBox {
    /// The lower-left corner.
    pub min: Point2,
    /// The upper-right corner.
    pub max: Point2,
}

impl ClipBox {
    /// The box `[x0, x1] × [y0, y1]`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"box"`) if a coordinate is not finite or the box is
    /// empty or flat (`x0 >= x1` or `y0 >= y1`).
    ///
    /// ```
    /// use compgeo::delaunay::ClipBox;
    ///
    /// assert!(ClipBox::new(0.0, 0.0, 1.0, 2.0).is_ok());
    /// assert!(ClipBox::new(0.0, 0.0, 0.0, 2.0).is_err());
    /// assert!(ClipBox::new(0.0, f64::NAN, 1.0, 2.0).is_err());
    /// ```
    pub fn new(x0: f64, y0: f64, x1: f64, y1: f64) -> Result<ClipBox> {
        if ![x0, y0, x1, y1].iter().all(|v| v.is_finite()) || x0 >= x1 || y0 >= y1 {
            return Err(Error::InvalidParameter {
                name: "box",
                reason: format!(
                    "[{x0}, {y0}, {x1}, {y1}] is not a box x0 < x1, y0 < y1 of finite numbers"
                ),
            });
        }
        Ok(ClipBox {
            min: Point2::new(x0, y0),
            max: Point2::new(x1, y1),
        })
    }

    /// The default box for `points`: their bounding box grown by a quarter of its larger side
    /// on every side (by a quarter of the largest coordinate, or 1, if the points coincide),
    /// clamped to the finite range.
    ///
    /// # Errors
    /// [`Error::TooFew`] for no points (there is nothing to size the box by).
    ///
    /// ```
    /// use compgeo::delaunay::ClipBox;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let pts = [Point2::new(0.0, 0.0), Point2::new(4.0, 2.0)];
    /// let b = ClipBox::around(&PointSet::new(&pts)?)?;
    /// assert_eq!((b.min, b.max), (Point2::new(-1.0, -1.0), Point2::new(5.0, 3.0)));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn around(points: &PointSet<'_>) -> Result<ClipBox> {
        let Some(BoundingBox { min: lo, max: hi }) = points.bounding_box() else {
            return Err(Error::TooFew {
                what: "point set",
                needed: 1,
                got: 0,
            });
        };
        let side = (hi.x / 4.0 - lo.x / 4.0).max(hi.y / 4.0 - lo.y / 4.0);
        let margin = if side > 0.0 {
            side
        } else {
            let m = lo.x.abs().max(lo.y.abs()) / 4.0;
            if m > 0.0 {
                m
            } else {
                1.0
            }
        };
        let grow = |v: f64, d: f64| (v + d).clamp(-f64::MAX, f64::MAX);
        Ok(ClipBox {
            min: Point2::new(grow(lo.x, -margin), grow(lo.y, -margin)),
            max: Point2::new(grow(hi.x, margin), grow(hi.y, margin)),
        })
    }
}

impl Voronoi {
    /// Cell `k` intersected with `bounds`, as a counter-clockwise polygon (empty if they do
    /// not overlap in an area). Panics if `k` is out of range.
    ///
    /// The cell's rays are cut at points far enough that the cut cannot reach the box, and
    /// the polygon is clipped to the box's four sides (Sutherland–Hodgman); the crossing
    /// points lie exactly on the box's sides. Coordinates are rounded constructions. The
    /// computation runs in a frame scaled by a power of two to the box's magnitude; Voronoi
    /// vertices more than 2^600 times the box's largest coordinate away are pulled in to
    /// that distance, which only matters for cells whose shape inside the box is then
    /// below the precision of `f64` anyway.
    ///
    /// # Complexity
    /// O(k) time and space for a cell with k vertices.
    pub fn clip_cell(&self, k: usize, bounds: &ClipBox) -> Vec<Point2> {
        let s = scale_of(
            bounds
                .min
                .x
                .abs()
                .max(bounds.min.y.abs())
                .max(bounds.max.x.abs())
                .max(bounds.max.y.abs()),
        ) * 2.0;
        let scaled = |p: Point2| {
            let c = |v: f64| (v / s).clamp(-FAR, FAR);
            Point2::new(c(p.x), c(p.y))
        };
        let cell = self.cell(k);
        let inside = |p: Point2| {
            p.x >= bounds.min.x && p.x <= bounds.max.x && p.y >= bounds.min.y && p.y <= bounds.max.y
        };
        if cell.bounded && cell.vertices.iter().all(|&i| inside(self.vertices[i])) {
            // The box is convex: a cell whose vertices are all in it is its own clip.
            let mut out: Vec<Point2> = Vec::with_capacity(cell.vertices.len());
            for &i in cell.vertices {
                let q = self.vertices[i];
                if out.last() != Some(&q) {
                    out.push(q);
                }
            }
            while out.len() > 1 && out.first() == out.last() {
                out.pop();
            }
            if out.len() < 3 {
                out.clear();
            }
            return out;
        }
        let mut poly: Vec<Point2> = cell
            .vertices
            .iter()
            .map(|&v| scaled(self.vertices[v]))
            .collect();
        if !cell.bounded {
            poly = unbounded_polygon(&poly, cell.rays, scaled);
        }
        let lo = Point2::new(bounds.min.x / s, bounds.min.y / s);
        let hi = Point2::new(bounds.max.x / s, bounds.max.y / s);
        for side in [
            Side::Right(hi.x),
            Side::Top(hi.y),
            Side::Left(lo.x),
            Side::Bottom(lo.y),
        ] {
            poly = clip_side(&poly, side);
        }
        let mut out: Vec<Point2> = Vec::with_capacity(poly.len());
        for p in poly {
            let q = Point2::new(
                (p.x * s).clamp(bounds.min.x, bounds.max.x),
                (p.y * s).clamp(bounds.min.y, bounds.max.y),
            );
            if out.last() != Some(&q) {
                out.push(q);
            }
        }
        while out.len() > 1 && out.first() == out.last() {
            out.pop();
        }
        if out.len() < 3 {
            out.clear();
        }
        out
    }

    /// Every cell intersected with `bounds` ([`clip_cell`](Voronoi::clip_cell)), in cell
    /// order.
    ///
    /// # Complexity
    /// O(n) time and space for n sites (the cells' vertex counts sum to less than 6n).
    ///
    /// ```
    /// use compgeo::delaunay::{voronoi, ClipBox};
    /// use compgeo::geometry::Point2;
    ///
    /// let pts = [(0.0, 0.0), (2.0, 0.0)].map(Point2::from);
    /// let v = voronoi(&pts)?;
    /// let cells = v.clip(&ClipBox::new(-1.0, -1.0, 3.0, 1.0)?);
    /// // The bisector x = 1 splits the box in two.
    /// let left = &cells[v.cell_of(0)];
    /// assert_eq!(left.len(), 4);
    /// for corner in [(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)] {
    ///     assert!(left.contains(&Point2::from(corner)));
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn clip(&self, bounds: &ClipBox) -> Vec<Vec<Point2>> {
        (0..self.cell_count())
            .map(|k| self.clip_cell(k, bounds))
            .collect()
    }
}

/// `FAR` bounds scaled coordinates, keeping every product in the clipper finite.
const FAR: f64 = 4.149515568880993e180; // 2^600

/// The polygon of an unbounded cell (scaled coordinates) with its rays cut far away: past
/// every chain's leaving ray comes the next chain's arriving ray, and far points at most a
/// quarter turn apart close the gap, so the closing edges stay out of the box.
fn unbounded_polygon(
    vertices: &[Point2],
    rays: &[Ray],
    scaled: impl Fn(Point2) -> Point2,
) -> Vec<Point2> {
    if rays.is_empty() {
        // The whole plane: a square around the box.
        return [(-4.0, -4.0), (4.0, -4.0), (4.0, 4.0), (-4.0, 4.0)]
            .map(Point2::from)
            .to_vec();
    }
    let origins: Vec<Point2> = rays.iter().map(|r| scaled(r.origin)).collect();
    // The box lies within radius sqrt(2) < 2 of the origin in the scaled frame; every
    // polygon point before the far ones within `m` (1-norm).
    let m = vertices
        .iter()
        .chain(&origins)
        .map(|p| p.x.abs() + p.y.abs())
        .fold(0.0, f64::max);
    let reach = 4.0 * (m + 2.0);
    let far = |o: Point2, d: Point2| Point2::new(o.x + reach * d.x, o.y + reach * d.y);
    let mut poly = Vec::with_capacity(vertices.len() + 3 * rays.len());
    let chains = rays.len() / 2;
    for c in 0..chains {
        let (arrive, leave) = (&rays[2 * c], &rays[2 * c + 1]);
        poly.push(far(origins[2 * c], arrive.direction));
        if chains == 1 {
            poly.extend_from_slice(vertices);
        }
        let out = far(origins[2 * c + 1], leave.direction);
        poly.push(out);
        let next = &rays[(2 * c + 2) % rays.len()];
        let (d0, d1) = (leave.direction, next.direction);
        let cross = d0.x * d1.y - d0.y * d1.x;
        let dot = d0.x * d1.x + d0.y * d1.y;
        if dot < 0.0 {
            // More than a quarter turn (at most a half turn, the cell being convex) to the
            // next ray: add the far point halfway round, counter-clockwise from `d0`.
            let mid = if cross > 0.0 {
                let (x, y) = (d0.x + d1.x, d0.y + d1.y);
                let len = x.hypot(y);
                Point2::new(x / len, y / len)
            } else {
                Point2::new(-d0.y, d0.x)
            };
            poly.push(far(origins[2 * c + 1], mid));
        }
    }
    poly
}

/// One side of the box, as the half-plane that is kept.
#[derive(Debug, Clone, Copy)]
enum Side {
    Right(f64),
    Top(f64),
    Left(f64),
    Bottom(f64),
}

impl Side {
    fn inside(self, p: Point2) -> bool {
        match self {
            Side::Right(x) => p.x <= x,
            Side::Top(y) => p.y <= y,
            Side::Left(x) => p.x >= x,
            Side::Bottom(y) => p.y >= y,
        }
    }

    /// Where the segment `p q` (one end inside, one outside) crosses the side's line.
    fn crossing(self, p: Point2, q: Point2) -> Point2 {
        let along = |c: f64, p0: f64, q0: f64, p1: f64, q1: f64| {
            let t = (c - p0) / (q0 - p0);
            let v = p1 + t * (q1 - p1);
            v.clamp(p1.min(q1), p1.max(q1))
        };
        match self {
            Side::Right(x) | Side::Left(x) => Point2::new(x, along(x, p.x, q.x, p.y, q.y)),
            Side::Top(y) | Side::Bottom(y) => Point2::new(along(y, p.y, q.y, p.x, q.x), y),
        }
    }
}

/// Sutherland–Hodgman against one side.
fn clip_side(poly: &[Point2], side: Side) -> Vec<Point2> {
    let mut out = Vec::with_capacity(poly.len() + 2);
    for (i, &q) in poly.iter().enumerate() {
        let p = poly[(i + poly.len() - 1) % poly.len()];
        match (side.inside(p), side.inside(q)) {
            (true, true) => out.push(q),
            (true, false) => out.push(side.crossing(p, q)),
            (false, true) => {
                out.push(side.crossing(q, p));
                out.push(q);
            }
            (false, false) => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::voronoi;

    fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
        v.iter().map(|&p| Point2::from(p)).collect()
    }

    fn area(poly: &[Point2]) -> f64 {
        (0..poly.len())
            .map(|i| {
                let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
                p.x * q.y - p.y * q.x
            })
            .sum::<f64>()
            / 2.0
    }

    #[test]
    fn one_site_owns_the_whole_box() {
        let p = pts(&[(5.0, 5.0), (5.0, 5.0)]);
        let v = voronoi(&p).unwrap();
        assert_eq!(v.cell_count(), 1);
        assert_eq!(v.cell_of(1), 0);
        assert!(!v.cell(0).bounded);
        let b = ClipBox::new(0.0, 0.0, 2.0, 3.0).unwrap();
        assert_eq!(area(&v.clip_cell(0, &b)), 6.0);
    }

    #[test]
    fn collinear_sites_split_the_box_into_strips() {
        let p = pts(&[(2.0, 0.0), (0.0, 0.0), (6.0, 0.0)]);
        let v = voronoi(&p).unwrap();
        let b = ClipBox::new(-1.0, -1.0, 7.0, 1.0).unwrap();
        let cells = v.clip(&b);
        // Bisectors at x = 1 and x = 4.
        assert_eq!(area(&cells[v.cell_of(1)]), 4.0);
        assert_eq!(area(&cells[v.cell_of(0)]), 6.0);
        assert_eq!(area(&cells[v.cell_of(2)]), 6.0);
    }

    #[test]
    fn a_box_away_from_a_cell_clips_it_to_nothing() {
        let p = pts(&[
            (0.0, 0.0),
            (10.0, 0.0),
            (0.0, 10.0),
            (10.0, 10.0),
            (5.0, 5.0),
        ]);
        let v = voronoi(&p).unwrap();
        let b = ClipBox::new(8.0, 8.0, 9.0, 9.0).unwrap();
        let cells = v.clip(&b);
        assert_eq!(area(&cells[v.cell_of(3)]), 1.0);
        assert!(cells[v.cell_of(0)].is_empty() && cells[v.cell_of(4)].is_empty());
    }
}
