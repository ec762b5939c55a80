//! Rotating calipers over a convex polygon: the antipodal pairs, the diameter, the width and
//! the minimum-area and minimum-perimeter enclosing rectangles; and the diameter of a point
//! set by brute force.
//!
//! The course ([RD, §2.3], "Cálculo del diámetro de una nube de puntos") proves that the
//! diameter is attained by two hull vertices that are antipodal (they admit parallel
//! supporting lines), and finds all antipodal pairs of a convex polygon with n vertices in
//! O(n) by rotating two calipers ("Algoritmo de girar calibres"). Its angle test builds the
//! point `x = p + SIG(q) − q`, which rounds in floating point; here the same test is
//! [`cross_sign`](crate::geometry::cross_sign) of the two edge directions, exact.
//!
//! The same calipers give the width (the smallest distance between two parallel supporting
//! lines) and the minimum-area and minimum-perimeter enclosing rectangles: all are attained
//! with one side on a hull edge, so four calipers, one per side, rotate once around the hull
//! and each edge is scored with an exact comparison
//! ([`cmp_line_dist`](crate::geometry::cmp_line_dist),
//! [`cmp_rect_area`](crate::geometry::cmp_rect_area),
//! [`cmp_rect_perimeter`](crate::geometry::cmp_rect_perimeter)) instead of a rounded
//! distance, area or perimeter.
//!
//! # One hull, every caliper
//!
//! The calipers run on a [`ConvexPolygon`]: the hull of a point set, computed once
//! ([`ConvexPolygon::hull`]), or a polygon the caller has, checked once
//! ([`ConvexPolygon::new`]). Its methods never compute a hull again:
//!
//! | method | answer | file |
//! |---|---|---|
//! | [`ConvexPolygon::antipodal_pairs`] | every antipodal pair of vertices | `antipodal.rs` |
//! | [`ConvexPolygon::diameter`] | the farthest pair | `diameter.rs` |
//! | [`ConvexPolygon::width`] | the closest pair of parallel supporting lines | `width.rs` |
//! | [`ConvexPolygon::min_area_rectangle`] | the enclosing rectangle of least area | `rectangle.rs` |
//! | [`ConvexPolygon::min_perimeter_rectangle`] | the enclosing rectangle of least perimeter | `perimeter_rectangle.rs` |
//!
//! [`diameter`] chooses between the calipers and brute force ([`DiameterAlgorithm`]) on a
//! point set, as the other algorithm families do.
//!
//! ```
//! use compgeo::calipers::{diameter, ConvexPolygon, DiameterAlgorithm};
//! use compgeo::geometry::{cmp_dist, Point2, PointSet};
//!
//! let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (3.0, 1.0)].map(Point2::from);
//! let hull = ConvexPolygon::hull(&PointSet::new(&pts)?);
//! assert_eq!(hull.vertices(), [0, 1, 2]);
//! let d = hull.diameter()?;
//! assert_eq!(d.pair, [0, 2]);
//! assert_eq!(d.distance, 5.0);
//! assert_eq!(hull.width()?.width, 2.4); // the altitude onto the long side, 12 / 5, rounded once
//! let b = diameter(&pts, DiameterAlgorithm::BruteForce)?;
//! assert_eq!(cmp_dist(pts[0], pts[2], pts[b.pair[0]], pts[b.pair[1]]), std::cmp::Ordering::Equal);
//! # Ok::<(), compgeo::Error>(())
//! ```

mod antipodal;
mod diameter;
mod perimeter_rectangle;
mod rectangle;
mod sides;
mod width;

pub use diameter::{
    diameter, diameter_brute_force, diameter_brute_force_with, diameter_with, DiameterAlgorithm,
};
pub use rectangle::Rectangle;
pub use width::Width;

use crate::complexity::Declaration;
use crate::count::{Counter, NoCount};
use crate::error::{Error, Result};
use crate::geometry::{Point2, PointSet};
use crate::hull::{akl_toussaint_with, check_strictly_convex_ccw, HullOptions};

/// The antipodal pairs' declaration, for the catalog.
pub(crate) const ANTIPODAL_PAIRS: &Declaration = &antipodal::DECLARATION;
/// The width's declaration, for the catalog.
pub(crate) const WIDTH: &Declaration = &width::DECLARATION;
/// The minimum-area rectangle's declaration, for the catalog.
pub(crate) const MIN_AREA_RECTANGLE: &Declaration = &rectangle::DECLARATION;
/// The minimum-perimeter rectangle's declaration, for the catalog.
pub(crate) const MIN_PERIMETER_RECTANGLE: &Declaration = &perimeter_rectangle::DECLARATION;

/// The caliper algorithms that are not a choice among alternatives: the antipodal pairs, the
/// width and the minimum-area and minimum-perimeter rectangles.
pub(crate) const DECLARATIONS: [&Declaration; 4] = [
    ANTIPODAL_PAIRS,
    WIDTH,
    MIN_AREA_RECTANGLE,
    MIN_PERIMETER_RECTANGLE,
];

/// A strictly convex polygon: the vertices, counter-clockwise, as indices into a validated
/// point set. The input every caliper runs on.
///
/// Built once, either as the hull of a point set ([`ConvexPolygon::hull`]: the strictly
/// convex hull, counter-clockwise from the lexicographically smallest point, as
/// [`crate::hull`] computes it) or from vertices the caller has ([`ConvexPolygon::new`],
/// which checks them). A polygon of zero, one or two vertices is valid (the hull of an empty
/// set, of one distinct point, of collinear points).
#[derive(Debug, Clone, PartialEq)]
pub struct ConvexPolygon<'a> {
    points: &'a [Point2],
    vertices: Vec<usize>,
}

impl<'a> ConvexPolygon<'a> {
    /// The convex hull of `points` (by [`akl_toussaint`](crate::hull::akl_toussaint)), as a
    /// polygon for the calipers.
    ///
    /// # Complexity
    /// That of the hull: O(n log n) worst case, O(n) expected on uniform input; O(n) space.
    pub fn hull(points: &PointSet<'a>) -> ConvexPolygon<'a> {
        ConvexPolygon::hull_with(points, &mut NoCount)
    }

    /// [`ConvexPolygon::hull`], recording the hull's operations in `counter`.
    ///
    /// # Complexity
    /// As [`ConvexPolygon::hull`].
    pub fn hull_with<C: Counter>(points: &PointSet<'a>, counter: &mut C) -> ConvexPolygon<'a> {
        ConvexPolygon {
            points: points.points(),
            vertices: akl_toussaint_with(points, HullOptions::default(), counter),
        }
    }

    /// The polygon with the given vertices (indices into `points`, counter-clockwise, each
    /// turn strictly left, starting anywhere), checked.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"polygon"`) if a vertex index is out of range, or
    /// the vertices are not a strictly convex counter-clockwise polygon (checked exactly).
    ///
    /// # Complexity
    /// O(h) time for h vertices.
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(Point2::from);
    /// let set = PointSet::new(&square)?;
    /// assert!(ConvexPolygon::new(&set, vec![0, 1, 2, 3]).is_ok());
    /// assert!(ConvexPolygon::new(&set, vec![0, 3, 2, 1]).is_err()); // clockwise
    /// assert!(ConvexPolygon::new(&set, vec![0, 1, 9]).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn new(points: &PointSet<'a>, vertices: Vec<usize>) -> Result<ConvexPolygon<'a>> {
        if let Some(&i) = vertices.iter().find(|&&i| i >= points.len()) {
            return Err(Error::InvalidParameter {
                name: "polygon",
                reason: format!("vertex {i} is out of range for {} points", points.len()),
            });
        }
        if let Err(v) = check_strictly_convex_ccw(points, &vertices) {
            return Err(Error::InvalidParameter {
                name: "polygon",
                reason: format!("not strictly convex and counter-clockwise: {v}"),
            });
        }
        Ok(ConvexPolygon {
            points: points.points(),
            vertices,
        })
    }

    /// The vertices, counter-clockwise, as indices into [`points`](Self::points).
    pub fn vertices(&self) -> &[usize] {
        &self.vertices
    }

    /// The point set the vertices index.
    pub fn points(&self) -> &'a [Point2] {
        self.points
    }

    /// The vertex at position `k` of the polygon, counted cyclically.
    #[inline]
    fn at(&self, k: usize) -> Point2 {
        self.points[self.vertices[k % self.vertices.len()]]
    }

    /// The error of a caliper that needs a vertex.
    fn empty() -> Error {
        Error::TooFew {
            what: "convex polygon",
            needed: 1,
            got: 0,
        }
    }
}
