//! The largest empty circle centred in the convex hull.

use super::{adjacency, delaunay_edges};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::delaunay::{incremental_with, Triangulation};
use crate::error::Result;
use crate::geometry::construct::{circumcentre, distance, midpoint, scale_of};
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "empty-circle",
    name: "voronoi",
    function: "proximity::largest_empty_circle",
    file: "src/proximity/empty_circle.rs",
    summary: "the best Voronoi vertex inside the hull or crossing of a Voronoi edge with it",
    time: "O(n log n) expected on uniform-like input, O(nh) worst case",
    space: "O(n)",
    operation: Some(Operation::OrientationTests),
    counts: "the hull tests of the Voronoi vertices, O(log h) each",
    source: "[RD, §2.4]",
    claims: &[on(
        "uniform-disk",
        Bound::NLogN,
        Operation::OrientationTests,
    )],
};

/// A circle with no input point strictly inside.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct EmptyCircle {
    /// Its centre (rounded).
    pub centre: Point2,
    /// Its radius (rounded).
    pub radius: f64,
    /// The input points on it that define it: three for a Voronoi vertex, two for a point
    /// where a Voronoi edge crosses the hull's boundary, one for a lone point.
    pub sites: Vec<usize>,
}

/// The largest empty circle centred in the convex hull; see
/// [`largest_empty_circle_with`].
///
/// # Errors
/// As [`largest_empty_circle_with`].
///
/// # Complexity
/// As [`largest_empty_circle_with`].
///
/// ```
/// use compgeo::proximity::largest_empty_circle;
/// use compgeo::geometry::Point2;
///
/// // The corners of a square: the centre is the square's, the radius half the diagonal.
/// let pts = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)].map(Point2::from);
/// let c = largest_empty_circle(&pts)?;
/// assert_eq!((c.centre, c.radius), (Point2::new(1.0, 1.0), 2f64.sqrt()));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn largest_empty_circle(points: &[Point2]) -> Result<EmptyCircle> {
    largest_empty_circle_with(&PointSet::new(points)?, &mut NoCount)
}

/// The largest circle whose centre lies in the convex hull of `points` and which holds no
/// point strictly inside, counting its predicates.
///
/// The idea ([RD, §2.4], problem 5 "Mayor círculo vacío"): the
/// distance f(x) from x to its nearest point is maximal over the hull at a vertex of the
/// polygons Vor(S) ∩ CH(S): a Voronoi vertex inside the hull, a point where a Voronoi edge
/// crosses the hull's boundary, or a hull vertex (where f = 0). Voronoi vertices are the
/// triangles' circumcentres, tested against the hull. The crossings are found by walking
/// along every hull edge p → q from p's cell: within the cell of site s the walk leaves at
/// the first bisector of s and a Delaunay neighbour it reaches, moves into that
/// neighbour's cell, and records the crossing, until q's cell.
///
/// Exact and rounded parts: the triangulation and the hull are exact; the circumcentres
/// and crossing points are rounded constructions (on coordinates scaled by a power of two,
/// so nothing overflows); whether a rounded circumcentre lies in the hull is decided
/// exactly (orientation tests against the hull), which cell a walk enters next and which
/// candidate has the largest radius are decided on rounded values. The radius is
/// therefore within a few rounding errors (relative to the configuration's size) of the
/// true maximum, and ties between equal circles go to any of them.
///
/// Degenerate input: for collinear points the hull is a segment and the answer is the
/// midpoint of the widest gap between consecutive points (exact comparison of gaps); a
/// single distinct point gives radius 0 centred on it; duplicates change nothing.
///
/// # Errors
/// [`Error::TooFew`](crate::Error::TooFew) for no points; the triangulation's size limit.
///
/// # Complexity
/// O(n log n) expected on uniform-like input, O(nh) worst case, for n points: the
/// triangulation, and an O(log h) hull test per triangle for h hull points, then walks along
/// the hull that cost the degrees of the cells they cross, O(n) for uniform-like input and
/// O(nh) in the worst case. O(n) space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests, the orientation tests of the hull
/// tests and the distance evaluations of the collinear case.
pub fn largest_empty_circle_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<EmptyCircle> {
    super::at_least(1, points.len())?;
    let t = incremental_with(points, counter)?;
    if t.is_empty() {
        return Ok(widest_gap(points, &t.hull, counter));
    }
    // A hull vertex (f = 0) is the fallback candidate.
    let mut best = EmptyCircle {
        centre: points[t.hull[0]],
        radius: 0.0,
        sites: vec![t.hull[0]],
    };
    let mut offer = |c: EmptyCircle| {
        if c.radius > best.radius {
            best = c;
        }
    };
    for tri in t.triangles.chunks_exact(3) {
        let (a, b, c) = (points[tri[0]], points[tri[1]], points[tri[2]]);
        let centre = circumcentre(a, b, c);
        if in_hull(points, &t.hull, centre, counter) {
            offer(EmptyCircle {
                centre,
                radius: distance(centre, a),
                sites: tri.to_vec(),
            });
        }
    }
    for c in boundary_crossings(points, &t) {
        offer(c);
    }
    Ok(best)
}

/// Collinear points (or one): the midpoint of the widest gap along the line.
fn widest_gap<C: Counter>(points: &[Point2], line: &[usize], c: &mut C) -> EmptyCircle {
    if line.len() == 1 {
        return EmptyCircle {
            centre: points[line[0]],
            radius: 0.0,
            sites: line.to_vec(),
        };
    }
    let mut best = [line[0], line[1]];
    for w in line.windows(2).skip(1) {
        let [a, b] = best;
        if c.cmp_dist(points[w[0]], points[w[1]], points[a], points[b]) == Ordering::Greater {
            best = [w[0], w[1]];
        }
    }
    let [a, b] = best;
    let centre = midpoint(points[a], points[b]);
    EmptyCircle {
        centre,
        radius: distance(centre, points[a]).max(distance(centre, points[b])),
        sites: vec![a, b],
    }
}

/// Whether `x` is in the closed convex polygon `hull` (counter-clockwise, at least three
/// points, not all collinear): a binary search in the fan from `hull[0]`.
fn in_hull<C: Counter>(p: &[Point2], hull: &[usize], x: Point2, c: &mut C) -> bool {
    let h0 = p[hull[0]];
    let last = hull.len() - 1;
    if c.orient2d(h0, p[hull[1]], x) == Orientation::Clockwise
        || c.orient2d(h0, p[hull[last]], x) == Orientation::CounterClockwise
    {
        return false;
    }
    // Invariant: x is not right of h0 -> hull[lo]; it is right of h0 -> hull[hi], or hi
    // is the last vertex.
    let (mut lo, mut hi) = (1, last);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if c.orient2d(h0, p[hull[mid]], x) == Orientation::Clockwise {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    c.orient2d(p[hull[lo]], p[hull[hi]], x) != Orientation::Clockwise
}

/// The points where the hull's boundary crosses Voronoi edges, with their circles.
fn boundary_crossings(points: &[Point2], t: &Triangulation) -> Vec<EmptyCircle> {
    let (offsets, neighbours) = adjacency(points.len(), &delaunay_edges(t));
    // Work in coordinates scaled to at most 1 by a power of two: squares stay finite.
    let s = scale_of(
        t.hull
            .iter()
            .map(|&i| points[i].x.abs().max(points[i].y.abs()))
            .fold(0.0, f64::max),
    ) * 2.0;
    let sc = |i: usize| Point2::new(points[i].x / s, points[i].y / s);
    let mut out = Vec::new();
    let h = t.hull.len();
    for k in 0..h {
        let (pi, qi) = (t.hull[k], t.hull[(k + 1) % h]);
        let (p, q) = (sc(pi), sc(qi));
        let (dx, dy) = (q.x - p.x, q.y - p.y);
        let mut site = pi;
        let mut at = 0.0f64;
        // Each step moves to a cell further along the edge; the bound stops a walk that
        // rounding would otherwise keep at one parameter.
        for _ in 0..points.len() {
            let sp = sc(site);
            let mut next: Option<(f64, usize)> = None;
            for &w in &neighbours[offsets[site]..offsets[site + 1]] {
                let wp = sc(w);
                let (ux, uy) = (wp.x - sp.x, wp.y - sp.y);
                let towards = dx * ux + dy * uy;
                if towards <= 0.0 {
                    continue;
                }
                let (mx, my) = ((wp.x + sp.x) / 2.0 - p.x, (wp.y + sp.y) / 2.0 - p.y);
                let cross_at = (ux * mx + uy * my) / towards;
                if cross_at >= at && next.is_none_or(|(best, _)| cross_at < best) {
                    next = Some((cross_at, w));
                }
            }
            let Some((cross_at, w)) = next.filter(|&(c, _)| c < 1.0) else {
                break;
            };
            let x = Point2::new(p.x + cross_at * dx, p.y + cross_at * dy);
            let centre = Point2::new(x.x * s, x.y * s);
            out.push(EmptyCircle {
                centre,
                radius: distance(centre, points[site]),
                sites: vec![site.min(w), site.max(w)],
            });
            site = w;
            at = cross_at;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn collinear_points_give_the_widest_gap() {
        let pts = [(0.0, 0.0), (5.0, 0.0), (1.0, 0.0), (2.0, 0.0)].map(Point2::from);
        let c = largest_empty_circle(&pts).unwrap();
        assert_eq!(
            (c.centre, c.radius, c.sites),
            (Point2::new(3.5, 0.0), 1.5, vec![3, 1])
        );
        let c = largest_empty_circle(&[Point2::new(1.0, 1.0)]).unwrap();
        assert_eq!(c.radius, 0.0);
        assert!(largest_empty_circle(&[]).is_err());
    }

    #[test]
    fn an_obtuse_triangle_uses_a_boundary_crossing() {
        // The circumcentre (2, -3.5) is outside; the best centre is on the long edge.
        let pts = [(0.0, 0.0), (4.0, 0.0), (2.0, 0.5)].map(Point2::from);
        let c = largest_empty_circle(&pts).unwrap();
        assert_eq!(c.centre.y, 0.0);
        assert!(c.centre.x > 0.0 && c.centre.x < 4.0);
        assert!((c.radius - distance(c.centre, pts[0])).abs() < 1e-12);
        assert!((c.radius - distance(c.centre, pts[2])).abs() < 1e-12);
    }
}
