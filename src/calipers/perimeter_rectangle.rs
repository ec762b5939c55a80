//! The minimum-perimeter rectangle enclosing a convex polygon: the same four calipers as the
//! minimum-area rectangle, each edge's rectangle scored by an exact perimeter comparison.

use super::rectangle::Rectangle;
use super::ConvexPolygon;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::CountedPredicates;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "min-perimeter-rectangle",
    name: "calipers",
    function: "calipers::ConvexPolygon::min_perimeter_rectangle",
    file: "src/calipers/perimeter_rectangle.rs",
    summary: "four calipers rotated once around the hull, each edge's rectangle's perimeter compared exactly",
    time: "Θ(h) after the hull",
    space: "O(1)",
    operation: Some(Operation::OrientationTests),
    counts: "at most 9h for the calipers, and h − 1 exact perimeter comparisons",
    source: "[RD, §2.3]",
    claims: &[on(
        "convex-polygon",
        Bound::Linear,
        Operation::OrientationTests,
    )],
};

impl ConvexPolygon<'_> {
    /// The minimum-perimeter rectangle enclosing the polygon; see
    /// [`min_perimeter_rectangle_with`](Self::min_perimeter_rectangle_with).
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`](crate::Error::TooFew) for a polygon without vertices.
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// // The two criteria choose different edges: the smallest area (216/13) lies on
    /// // the side from (-2, -3) to (0, 0), the shortest perimeter on the side from
    /// // (1, 3) to (-3, 0), whose rectangle is 6 × 3 (perimeter 18, area 18).
    /// let pts = [(-3.0, 0.0), (-2.0, -3.0), (0.0, 0.0), (1.0, 3.0)].map(Point2::from);
    /// let hull = ConvexPolygon::hull(&PointSet::new(&pts)?);
    /// let by_perimeter = hull.min_perimeter_rectangle()?;
    /// let by_area = hull.min_area_rectangle()?;
    /// assert_eq!(by_perimeter.edge, [3, 0]);
    /// assert_eq!(by_perimeter.perimeter, 18.0);
    /// assert_eq!(by_perimeter.area, 18.0);
    /// assert_eq!(by_area.edge, [1, 2]);
    /// assert!(by_area.area < by_perimeter.area && by_perimeter.perimeter < by_area.perimeter);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn min_perimeter_rectangle(&self) -> Result<Rectangle> {
        self.min_perimeter_rectangle_with(&mut NoCount)
    }

    /// The minimum-perimeter rectangle enclosing the polygon, by rotating four calipers,
    /// recording the operations in `counter`.
    ///
    /// Idea: a minimum-perimeter enclosing rectangle, like a minimum-area one, has a side
    /// along an edge of the hull (Toussaint, 1983, "Solving geometric problems with the
    /// rotating calipers"), so the calipers of
    /// [`min_area_rectangle_with`](Self::min_area_rectangle_with) visit every candidate and
    /// each is compared with the best so far by
    /// [`cmp_rect_perimeter`](crate::geometry::cmp_rect_perimeter), exact: half the perimeter
    /// is (height + length) / |edge|, and the comparison squares both sides of the
    /// cleared-denominator inequality instead of taking a square root. Of equal perimeters
    /// the first edge counter-clockwise from the first vertex wins.
    ///
    /// Not among the course's algorithms; it extends [RD, §2.3] "Algoritmo de girar
    /// calibres" from two calipers to four, as the minimum-area rectangle does.
    ///
    /// Degenerate polygons: a single vertex gives a rectangle with four equal corners and
    /// perimeter 0; two (collinear points) the segment between them, perimeter twice its
    /// length.
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
    /// At most 9h orientation tests for the calipers and h − 1 distance evaluations
    /// (perimeter comparisons).
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::count::Counts;
    /// use compgeo::gen::{points, PointKind};
    /// use compgeo::geometry::PointSet;
    ///
    /// let pts = points(PointKind::UniformDisk, 1000, 4)?;
    /// let hull = ConvexPolygon::hull(&PointSet::new(&pts)?);
    /// let mut counts = Counts::default();
    /// let r = hull.min_perimeter_rectangle_with(&mut counts)?;
    /// let h = hull.vertices().len() as u64;
    /// assert_eq!(counts.distance_evaluations, h - 1);
    /// assert!(counts.orientation_tests <= 9 * h);
    /// assert!(r.perimeter <= hull.min_area_rectangle()?.perimeter);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn min_perimeter_rectangle_with<C: Counter>(&self, counter: &mut C) -> Result<Rectangle> {
        self.best_rectangle_with(counter, |c, new, best| c.cmp_rect_perimeter(new, best))
    }
}
