//! The width of a convex polygon: the closest pair of parallel supporting lines, one along an
//! edge, found by rotating calipers and compared exactly.

use super::sides::{four_calipers, Sides};
use super::ConvexPolygon;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{line_distance, CountedPredicates, WideFloat};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "width",
    name: "calipers",
    function: "calipers::ConvexPolygon::width",
    file: "src/calipers/width.rs",
    summary: "three calipers rotated once around the hull, each edge scored exactly",
    time: "Θ(h) after the hull",
    space: "O(1)",
    operation: Some(Operation::OrientationTests),
    counts: "at most 9h for the calipers, and h − 1 exact distance comparisons",
    source: "[RD, §2.3]",
    claims: &[on(
        "convex-polygon",
        Bound::Linear,
        Operation::OrientationTests,
    )],
};

/// A width: an edge of the polygon, the vertex farthest from its line, and the distance
/// between the two parallel supporting lines through them.
///
/// ```
/// use compgeo::calipers::ConvexPolygon;
/// use compgeo::geometry::{Point2, PointSet};
///
/// // A square with corners at ±f64::MAX: its width, 2 · f64::MAX, is beyond f64.
/// let m = f64::MAX;
/// let pts = [(-m, -m), (m, -m), (m, m), (-m, m)].map(Point2::from);
/// let w = ConvexPolygon::hull(&PointSet::new(&pts)?).width()?;
/// assert_eq!(w.width.to_f64(), None);
/// assert_eq!(w.width.to_string(), "3.5953862697246314e308");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Width {
    /// The hull edge `[i, j]` (indices into the input, counter-clockwise) one supporting line
    /// runs along; `[i, i]` for a one-point set, the two ends for a segment.
    pub edge: [usize; 2],
    /// The vertex on the other supporting line (the edge's start when the width is zero).
    pub vertex: usize,
    /// The distance between the lines, `|(j − i) × (vertex − i)| / |j − i|`, with relative
    /// error below 2^-51 for every finite input (the cross product and the squared length
    /// are exact, then rounded once each), tiny or beyond `f64::MAX` alike. The edge and the
    /// vertex are exact: chosen by exact comparisons.
    pub width: WideFloat,
}

impl ConvexPolygon<'_> {
    /// The width of the polygon; see [`width_with`](Self::width_with).
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`](crate::Error::TooFew) for a polygon without vertices.
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (2.0, 1.0)].map(Point2::from);
    /// let w = ConvexPolygon::hull(&PointSet::new(&pts)?).width()?;
    /// assert_eq!((w.edge, w.vertex), ([0, 1], 2));
    /// assert_eq!(w.width, 3.0); // the bottom edge, height 3
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn width(&self) -> Result<Width> {
        self.width_with(&mut NoCount)
    }

    /// The width of the polygon, the smallest distance between two parallel lines enclosing
    /// it, by rotating calipers, recording the operations in `counter`.
    ///
    /// Idea: a pair of parallel supporting lines at minimum distance has one line along an
    /// edge (rotating a pair that touches only vertices shortens it one way or the other), so
    /// the width is the smallest over edges of the distance to the farthest vertex. That
    /// vertex moves counter-clockwise as the edge does: one caliper walks around the polygon
    /// once, moved on by [`cross_sign`](crate::geometry::cross_sign) (does the next vertex
    /// lie farther from the edge's line?). Edges are compared by
    /// [`cmp_line_dist`](crate::geometry::cmp_line_dist), exact; of equal widths the first
    /// edge counter-clockwise from the first vertex is returned.
    ///
    /// Follows [RD, §2.3] ("Algoritmo de girar calibres": the same calipers, scored per edge
    /// instead of per antipodal pair).
    ///
    /// Degenerate polygons: one vertex or two (a point, collinear points) have width 0, with
    /// `edge` joining the two ends.
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
    /// At most 9h orientation tests for the calipers (each of three calipers is tested once
    /// per edge to stop it, and advances less than twice around the polygon; about 7h on
    /// points in convex position) and h − 1 distance evaluations.
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::count::Counts;
    /// use compgeo::gen::{points, PointKind};
    /// use compgeo::geometry::PointSet;
    ///
    /// let pts = points(PointKind::UniformDisk, 1000, 9)?;
    /// let hull = ConvexPolygon::hull(&PointSet::new(&pts)?);
    /// let mut counts = Counts::default();
    /// let w = hull.width_with(&mut counts)?;
    /// assert!(w.width > 1.9 && w.width < 2.0);
    /// assert!(counts.orientation_tests <= 9 * hull.vertices().len() as u64);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn width_with<C: Counter>(&self, counter: &mut C) -> Result<Width> {
        let hull = self.vertices();
        let h = hull.len();
        match h {
            0 => return Err(ConvexPolygon::empty()),
            1 | 2 => {
                return Ok(Width {
                    edge: [hull[0], hull[h - 1]],
                    vertex: hull[0],
                    width: WideFloat::ZERO,
                })
            }
            _ => {}
        }
        let v = |k: usize| self.at(k);
        let mut best: Option<Sides> = None;
        four_calipers(self, counter, |s, counter| {
            let better = best.is_none_or(|b| {
                counter.cmp_line_dist(
                    v(s.edge),
                    v(s.edge + 1),
                    v(s.top),
                    v(b.edge),
                    v(b.edge + 1),
                    v(b.top),
                ) == Ordering::Less
            });
            if better {
                best = Some(s);
            }
        });
        let s = best.expect("a polygon has edges");
        Ok(Width {
            edge: [hull[s.edge % h], hull[(s.edge + 1) % h]],
            vertex: hull[s.top % h],
            width: line_distance(v(s.edge), v(s.edge + 1), v(s.top)),
        })
    }
}
