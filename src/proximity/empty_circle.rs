//! The largest empty circle centred in the convex hull [RD, §2.4, problem 5]: the
//! candidates are the Voronoi vertices inside the hull, the points where Voronoi edges
//! cross the hull's boundary (found by walking along each hull edge from cell to cell) and
//! the hull vertices; the largest is chosen by exact comparison of squared radii.
//!
//! Every decision is exact: the predicates on the constructed points (circumcentres against
//! hull lines, the order of bisector crossings along a hull edge, squared radii) are in
//! `geometry/circle_predicates/`. Only the returned centre and radius are rounded (the radius
//! once, from its exact square). The tests (`tests/suite/empty_circle.rs`) check the answer
//! against an exact brute force over all triples and all supporting segments: the circle is
//! in the hull, empty, and of the largest squared radius.

use super::{adjacency, delaunay_edges};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::delaunay::{incremental_with, Triangulation};
use crate::error::Result;
use crate::geometry::circle_predicates::{
    cmp_bisector_crossings, dot_sign, Circumcentre, CountedCirclePredicates, SquaredRadius,
};
use crate::geometry::construct::{bisector_crossing, circumcentre, midpoint};
use crate::geometry::sweep_predicates::normalize_scale;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet, WideFloat};
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
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::proximity::largest_empty_circle;
///
/// // The corners of a square at ±f64::MAX: radius √2 · f64::MAX, beyond f64.
/// let m = f64::MAX;
/// let c = largest_empty_circle(&[(-m, -m), (m, -m), (m, m), (-m, m)].map(Point2::from))?;
/// assert_eq!(c.centre, Point2::new(0.0, 0.0));
/// assert_eq!(c.radius.to_f64(), None);
/// assert_eq!(c.radius.to_string(), "2.5423220123072923e308");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct EmptyCircle {
    /// Its centre, rounded: within
    /// [`ConstructedPoint::RELATIVE_ERROR`](crate::geometry::ConstructedPoint::RELATIVE_ERROR)
    /// of the exact one.
    pub centre: Point2,
    /// Its radius: the exact circle's, from its exact squared radius rounded once, with
    /// relative error below 2^-51 for every finite input (a nearly flat triangle's huge
    /// circumradius included, and beyond `f64::MAX` it keeps its value).
    pub radius: WideFloat,
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
/// assert_eq!(c.centre, Point2::new(1.0, 1.0));
/// assert_eq!(c.radius, 2f64.sqrt());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn largest_empty_circle(points: &[Point2]) -> Result<EmptyCircle> {
    largest_empty_circle_with(&PointSet::new(points)?, &mut NoCount)
}

/// The largest circle whose centre lies in the convex hull of `points` and which holds no
/// point strictly inside, counting its predicates.
///
/// The idea ([RD, §2.4], problem 5 "Mayor círculo vacío"): the distance f(x) from x to its
/// nearest point is maximal over the hull at a vertex of the polygons Vor(S) ∩ CH(S): a
/// Voronoi vertex inside the hull, a point where a Voronoi edge crosses the hull's
/// boundary, or a hull vertex (where f = 0). Voronoi vertices are the triangles'
/// circumcentres, tested against the hull. The crossings are found by walking along every
/// hull edge p → q from p's cell: within the cell of site s the walk leaves at the first
/// bisector of s and a Delaunay neighbour it approaches, moves into that neighbour's cell,
/// and records the crossing, until q's cell.
///
/// Every decision is exact for every finite input (`geometry/circle_predicates/`): the
/// triangulation and the hull; whether the exact (rational) circumcentre lies in the
/// closed hull; which neighbour's bisector a walk crosses first, and so which cell it
/// enters; and which candidate has the largest radius, by exact comparison of squared
/// radii across all three kinds. So the circle returned is a true maximum, and it is empty.
/// Among several equally large circles the first found wins: hull vertex `hull[0]` (only
/// if every candidate has radius 0), then the Voronoi vertices in the triangulation's
/// triangle order, then the crossings along the hull edges in hull order.
///
/// The centre is a rounded construction (decisions never depend on it): the circumcentre
/// as in [`voronoi`](fn@crate::delaunay::voronoi) or the crossing point `p + t (q − p)`,
/// within [`ConstructedPoint::RELATIVE_ERROR`](crate::geometry::ConstructedPoint::RELATIVE_ERROR)
/// of its exact value for every finite input (certified floating point, else exact
/// big-integer arithmetic); it lies in the hull, so always within the range of `f64`.
/// The radius is the exact circle's: its exact squared radius (a quotient of big integers)
/// rounded once, then a square root, so its relative error is below 2^-51 at any magnitude
/// and in any configuration (a nearly flat triangle's huge circle included, beyond
/// `f64::MAX` too); for collinear points it is half the widest gap.
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
/// The triangulation's orientation and in-circle tests, one orientation test per step of
/// the hull tests, and the distance evaluations of the collinear case. The walks' and the
/// radius comparisons' predicates are not counted.
pub fn largest_empty_circle_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<EmptyCircle> {
    super::at_least(1, points.len())?;
    let t = incremental_with(points, counter)?;
    if t.is_empty() {
        return Ok(widest_gap(points, &t.hull, counter));
    }
    // Decide on a copy scaled by one exact power of two (when one exists) that puts the
    // largest magnitude near 1: every predicate is invariant under it, and the filters then
    // work far from overflow and underflow. Build the answer from the input itself.
    let mut scaled = points.to_vec();
    normalize_scale(&mut scaled);
    Ok(largest_candidate(&scaled, &t, counter).circle(points))
}

/// A candidate centre: where f is locally maximal over the hull.
#[derive(Debug, Clone, Copy)]
enum Candidate {
    /// A hull vertex (radius 0).
    HullVertex(usize),
    /// The circumcentre of a triangle (counter-clockwise vertex indices).
    VoronoiVertex([usize; 3]),
    /// Where the hull edge `edge[0] → edge[1]` crosses the bisector of `sites[0]` (the
    /// cell the walk leaves) and `sites[1]` (the cell it enters).
    Crossing { edge: [usize; 2], sites: [usize; 2] },
}

/// The candidate with the largest exact squared radius (the first of equal ones).
fn largest_candidate<C: Counter>(p: &[Point2], t: &Triangulation, counter: &mut C) -> Candidate {
    let mut best = (Candidate::HullVertex(t.hull[0]), SquaredRadius::zero());
    let corners = corners(p, &t.hull, counter);
    let mut offer = |candidate: Candidate, r2: SquaredRadius| {
        if r2.cmp(&best.1) == Ordering::Greater {
            best = (candidate, r2);
        }
    };
    for tri in t.triangles.chunks_exact(3) {
        let x = Circumcentre::new(p[tri[0]], p[tri[1]], p[tri[2]]);
        if in_hull(p, &corners, &x, counter) {
            offer(
                Candidate::VoronoiVertex([tri[0], tri[1], tri[2]]),
                x.squared_radius(),
            );
        }
    }
    for (edge, sites) in boundary_crossings(p, t) {
        let r2 = SquaredRadius::crossing(p[edge[0]], p[edge[1]], p[sites[0]], p[sites[1]]);
        offer(Candidate::Crossing { edge, sites }, r2);
    }
    best.0
}

impl Candidate {
    /// The candidate's circle on the input points: rounded centre and radius.
    fn circle(self, points: &[Point2]) -> EmptyCircle {
        match self {
            Candidate::HullVertex(i) => EmptyCircle {
                centre: points[i],
                radius: WideFloat::ZERO,
                sites: vec![i],
            },
            // Both centres are in the hull, within the range of f64: `saturating` never
            // clamps them.
            Candidate::VoronoiVertex(tri) => {
                let [a, b, c] = tri.map(|i| points[i]);
                EmptyCircle {
                    centre: circumcentre(a, b, c).saturating(),
                    radius: Circumcentre::new(a, b, c).squared_radius().radius(),
                    sites: tri.to_vec(),
                }
            }
            Candidate::Crossing { edge, sites } => {
                let [p, q] = edge.map(|i| points[i]);
                let [s, w] = sites.map(|i| points[i]);
                EmptyCircle {
                    centre: bisector_crossing(p, q, s, w).saturating(),
                    radius: SquaredRadius::crossing(p, q, s, w).radius(),
                    sites: vec![sites[0].min(sites[1]), sites[0].max(sites[1])],
                }
            }
        }
    }
}

/// Collinear points (or one): the midpoint of the widest gap along the line.
fn widest_gap<C: Counter>(points: &[Point2], line: &[usize], c: &mut C) -> EmptyCircle {
    if line.len() == 1 {
        return EmptyCircle {
            centre: points[line[0]],
            radius: WideFloat::ZERO,
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
    EmptyCircle {
        centre: midpoint(points[a], points[b]),
        // Half the gap: exact halving of the rounded length.
        radius: WideFloat::distance(points[a], points[b]).scale_pow2(-1),
        sites: vec![a, b],
    }
}

/// The strict corners of the triangulation's `hull` (counter-clockwise, points in the
/// middle of edges included, not all collinear): the points where the boundary turns, in
/// the same order, from the same first point (the lexicographically smallest is always a
/// corner). One counted orientation test per hull point.
///
/// The fan search of [`in_hull`] needs them: from a fan edge along a boundary segment
/// (such as `hull[0] → hull[last]` when `hull[last]` lies in the middle of the last edge)
/// the wedge is degenerate, and a point beyond the hull on that line would pass.
fn corners<C: Counter>(p: &[Point2], hull: &[usize], c: &mut C) -> Vec<usize> {
    let h = hull.len();
    (0..h)
        .filter(|&k| {
            let (prev, next) = (hull[(k + h - 1) % h], hull[(k + 1) % h]);
            c.orient2d(p[prev], p[hull[k]], p[next]) != Orientation::Collinear
        })
        .map(|k| hull[k])
        .collect()
}

/// Whether the exact circumcentre `x` is in the closed convex polygon `hull`
/// (counter-clockwise strict corners, at least three): a binary search in the fan from
/// `hull[0]`, one counted orientation test per step.
fn in_hull<C: Counter>(p: &[Point2], hull: &[usize], x: &Circumcentre, c: &mut C) -> bool {
    let h0 = p[hull[0]];
    let last = hull.len() - 1;
    if c.orient_circumcentre(h0, p[hull[1]], x) == Orientation::Clockwise
        || c.orient_circumcentre(h0, p[hull[last]], x) == Orientation::CounterClockwise
    {
        return false;
    }
    // Invariant: x is not right of h0 -> hull[lo]; it is right of h0 -> hull[hi], or hi
    // is the last vertex.
    let (mut lo, mut hi) = (1, last);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if c.orient_circumcentre(h0, p[hull[mid]], x) == Orientation::Clockwise {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    c.orient_circumcentre(p[hull[lo]], p[hull[hi]], x) != Orientation::Clockwise
}

/// The points where the hull's boundary crosses Voronoi edges, in hull order, each as the
/// hull edge and the two sites (the cell left, the cell entered).
///
/// On hull edge p → q the walk is in the cell of site s at a point x(t) = p + t (q − p)
/// of that cell (first s = p, t = 0). Moving on, it stays in the cell until it reaches
/// the bisector of s and a Delaunay neighbour w it approaches ((q − p) · (w − s) > 0),
/// at the least such parameter, decided exactly; that point is in w's cell too, so the
/// walk records it and continues in w's cell. Each step increases (q − p) · s strictly,
/// so the walk ends, and only in q's cell: q itself is in no other cell. At a Voronoi
/// vertex on the edge several bisectors cross at one parameter; the walk then passes the
/// cells around that vertex one by one, each step a crossing of radius equal to the
/// vertex's.
fn boundary_crossings(points: &[Point2], t: &Triangulation) -> Vec<([usize; 2], [usize; 2])> {
    let (offsets, neighbours) = adjacency(points.len(), &delaunay_edges(t));
    let mut out = Vec::new();
    let h = t.hull.len();
    for k in 0..h {
        let (pi, qi) = (t.hull[k], t.hull[(k + 1) % h]);
        let (p, q) = (points[pi], points[qi]);
        let mut site = pi;
        while site != qi {
            let s = points[site];
            let mut next: Option<usize> = None;
            for &w in &neighbours[offsets[site]..offsets[site + 1]] {
                let wp = points[w];
                if dot_sign(p, q, s, wp) == Ordering::Greater
                    && next.is_none_or(|v| {
                        cmp_bisector_crossings(p, q, s, wp, points[v]) == Ordering::Less
                    })
                {
                    next = Some(w);
                }
            }
            let w = next.expect("a cell other than q's is left before q");
            out.push(([pi, qi], [site, w]));
            site = w;
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
            (Point2::new(3.5, 0.0), WideFloat::from(1.5), vec![3, 1])
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
        // Equidistant from (0, 0) and (2, 0.5) on the x-axis: x² = (x − 2)² + 1/4 at
        // x = 17/16 (or 4 − 17/16 by symmetry), so the exact radius 17/16 comes out exactly.
        assert_eq!(c.radius, 1.0625);
        assert!([1.0625, 4.0 - 1.0625].contains(&c.centre.x), "{c:?}");
    }
}
