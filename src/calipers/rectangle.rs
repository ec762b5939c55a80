//! The minimum-area rectangle enclosing a convex polygon: one side along an edge, four
//! calipers rotated once around it, the areas compared exactly. The rectangle type and the
//! sweep that scores each edge's rectangle are shared with the minimum-perimeter rectangle
//! (`perimeter_rectangle.rs`).

use super::sides::{four_calipers, Sides};
use super::ConvexPolygon;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::construct::rectangle_corner;
use crate::geometry::{
    rect_area, rect_perimeter, ConstructedPoint, CountedPredicates, Point2, WideFloat,
};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "min-area-rectangle",
    name: "calipers",
    function: "calipers::ConvexPolygon::min_area_rectangle",
    file: "src/calipers/rectangle.rs",
    summary: "four calipers rotated once around the hull, each edge's rectangle scored exactly",
    time: "Θ(h) after the hull",
    space: "O(1)",
    operation: Some(Operation::OrientationTests),
    counts: "at most 9h for the calipers, and h − 1 exact area comparisons",
    source: "[RD, §2.3]",
    claims: &[on(
        "convex-polygon",
        Bound::Linear,
        Operation::OrientationTests,
    )],
};

/// An enclosing rectangle with a side on a polygon edge (the minimum-area or the
/// minimum-perimeter one): the edge, the vertices that touch the other three sides, the
/// corners, the area and the perimeter.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Rectangle {
    /// The hull edge `[i, j]` that one side lies on (counter-clockwise, so the rectangle is
    /// left of `i -> j`).
    pub edge: [usize; 2],
    /// The vertices touching the other sides, counter-clockwise from the edge:
    /// `[right, top, left]` (extreme along the edge's direction, farthest from its line,
    /// extreme against its direction).
    pub support: [usize; 3],
    /// The corners, counter-clockwise, starting on the edge's line below `left`. These are
    /// constructions (intersections of the sides' lines), each within
    /// [`ConstructedPoint::RELATIVE_ERROR`] of its exact value, and
    /// [`ConstructedPoint::BeyondRange`] where that is beyond the range of `f64` (a corner
    /// of a tilted rectangle around points near `±f64::MAX`); the edge and the support
    /// vertices are exact.
    pub corners: [ConstructedPoint; 4],
    /// The area, height times length (`|(j − i) × (top − i)| · |(j − i) · (right − left)| /
    /// |j − i|²`), with relative error below 3 · 2^-52 for every finite input: each factor
    /// is exact, then rounded once. A [`WideFloat`], so an area beyond `f64::MAX` keeps its
    /// value:
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let m = f64::MAX;
    /// let pts = [(-m, -1.0), (m, -1.0), (m, 1.0), (-m, 1.0)].map(Point2::from);
    /// let r = ConvexPolygon::hull(&PointSet::new(&pts)?).min_area_rectangle()?;
    /// assert_eq!(r.area.to_string(), "7.1907725394492628e308"); // 2 · f64::MAX times 2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    ///
    /// 0 for collinear input.
    pub area: WideFloat,
    /// The perimeter, twice height plus length (`2 (|(j − i) × (top − i)| + |(j − i) ·
    /// (right − left)|) / |j − i|`), with relative error below 2^-50 for every finite input:
    /// the sum and the squared length are exact, each rounded once, then a square root and
    /// a division. Twice the segment's length for collinear input, 0 for a single point.
    pub perimeter: WideFloat,
}

/// The five points that fix the rectangle of a caliper position, in the order of
/// [`cmp_rect_area`](crate::geometry::cmp_rect_area): the edge's ends, the top, the left and
/// the right vertex.
pub(super) type RectangleKey = [Point2; 5];

impl ConvexPolygon<'_> {
    /// The enclosing rectangle with a side on an edge that `better` prefers: rotates four
    /// calipers once and keeps the first edge counter-clockwise whose rectangle no later one
    /// beats (`better(new, best) == Less` replaces the best).
    pub(super) fn best_rectangle_with<C: Counter>(
        &self,
        counter: &mut C,
        better: impl Fn(&mut C, RectangleKey, RectangleKey) -> Ordering,
    ) -> Result<Rectangle> {
        let hull = self.vertices();
        let h = hull.len();
        match h {
            0 => return Err(ConvexPolygon::empty()),
            1 | 2 => {
                let (i, j) = (hull[0], hull[h - 1]);
                let (a, b) = (self.points[i], self.points[j]);
                return Ok(Rectangle {
                    edge: [i, j],
                    support: [j, i, i],
                    corners: [a, b, b, a].map(ConstructedPoint::from),
                    area: WideFloat::ZERO,
                    perimeter: WideFloat::distance(a, b).scale_pow2(1),
                });
            }
            _ => {}
        }
        let v = |k: usize| self.at(k);
        let key = |s: Sides| [v(s.edge), v(s.edge + 1), v(s.top), v(s.left), v(s.right)];
        let mut best: Option<Sides> = None;
        four_calipers(self, counter, |s, counter| {
            if best.is_none_or(|b| better(counter, key(s), key(b)) == Ordering::Less) {
                best = Some(s);
            }
        });
        let s = best.expect("a polygon has edges");
        let (a, b) = (v(s.edge), v(s.edge + 1));
        let (top, left, right) = (v(s.top), v(s.left), v(s.right));
        // The sides' lines: the edge's, the parallel through `top`, the perpendiculars
        // through `left` and `right`.
        let corners = [(left, a), (right, a), (right, top), (left, top)]
            .map(|(p, q)| rectangle_corner(a, b, p, q));
        Ok(Rectangle {
            edge: [hull[s.edge % h], hull[(s.edge + 1) % h]],
            support: [s.right, s.top, s.left].map(|k| hull[k % h]),
            corners,
            area: rect_area(key(s)),
            perimeter: rect_perimeter(key(s)),
        })
    }
}

impl ConvexPolygon<'_> {
    /// The minimum-area rectangle enclosing the polygon; see
    /// [`min_area_rectangle_with`](Self::min_area_rectangle_with).
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`](crate::Error::TooFew) for a polygon without vertices.
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// // A diamond: the best rectangle is the tilted square on its sides, area 2, not the
    /// // axis-parallel box of area 4.
    /// let pts = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)].map(Point2::from);
    /// let r = ConvexPolygon::hull(&PointSet::new(&pts)?).min_area_rectangle()?;
    /// assert_eq!(r.edge, [3, 0]);
    /// assert_eq!(r.area, 2.0);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn min_area_rectangle(&self) -> Result<Rectangle> {
        self.min_area_rectangle_with(&mut NoCount)
    }

    /// The minimum-area rectangle enclosing the polygon, by rotating four calipers,
    /// recording the operations in `counter`.
    ///
    /// Idea: a minimum-area enclosing rectangle has a side along an edge of the hull
    /// (Freeman and Shapira, 1975). For each edge, in counter-clockwise order, three more
    /// calipers track the vertex extreme along the edge's direction, the one farthest from
    /// its line and the one extreme against its direction; each only moves forward, so
    /// together they go around the polygon a bounded number of times. The extremes along the
    /// direction are found with the sign of a dot product, which is
    /// [`cross_sign`](crate::geometry::cross_sign) of the edge turned by a right angle (an
    /// exact swap and negation of coordinates). Edges are compared by
    /// [`cmp_rect_area`](crate::geometry::cmp_rect_area), exact; of equal areas the first
    /// edge counter-clockwise from the first vertex wins.
    ///
    /// Not among the course's algorithms; it extends [RD, §2.3] "Algoritmo de girar
    /// calibres" from two calipers to four.
    ///
    /// Degenerate polygons: a single vertex gives a rectangle with four equal corners; two
    /// (collinear points) the segment between them (`corners` `[a, b, b, a]`); both have
    /// area 0.
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`](crate::Error::TooFew) for a polygon without vertices.
    ///
    /// # Complexity
    ///
    /// With h the number of vertices: time Θ(h) after the hull, auxiliary space O(1).
    ///
    /// # Counts
    ///
    /// At most 9h orientation tests for the calipers (as for
    /// [`width_with`](Self::width_with)) and h − 1 distance evaluations (area comparisons).
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::count::Counts;
    /// use compgeo::gen::{points, PointKind};
    /// use compgeo::geometry::PointSet;
    ///
    /// let pts = points(PointKind::UniformSquare, 1000, 4)?;
    /// let mut counts = Counts::default();
    /// let r = ConvexPolygon::hull(&PointSet::new(&pts)?).min_area_rectangle_with(&mut counts)?;
    /// assert!(r.area > 0.9 && r.area <= 1.0); // nearly the unit square
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn min_area_rectangle_with<C: Counter>(&self, counter: &mut C) -> Result<Rectangle> {
        self.best_rectangle_with(counter, |c, new, best| c.cmp_rect_area(new, best))
    }
}
