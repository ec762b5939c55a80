//! The bounding box of a Bézier patch's control net, which holds the patch over [0, 1]².
//!
//! The problem: an axis-aligned box around c([0, 1]²). The idea: on [0, 1]² the Bernstein
//! products are non-negative and sum to one, so every point of the patch is a convex
//! combination of the net and lies in its convex hull, and so in the box of the coordinatewise
//! minima and maxima of the net [PPB, §9.2, Obs. 4], [FJ-surfaces, §3]. (Outside [0, 1]² the
//! polynomial leaves the box.)
//!
//! # Complexity
//!
//! Θ(mnD) time, O(D) auxiliary space.

use super::bezier::BezierPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::bounding_box_counted;
use crate::spline::{Point, Scalar};

/// The bounding box, declared.
pub(crate) const BOUNDING_BOX: Declaration = Declaration {
    problem: "bezier-patch",
    name: "bounding-box",
    function: "surface::BezierPatch::bounding_box",
    file: "src/surface/bounds.rs",
    summary: "the coordinatewise minima and maxima of the control net",
    time: "Θ(mnD)",
    space: "O(D)",
    operation: Some(Operation::Comparisons),
    counts: "exactly 2D((m + 1)(n + 1) − 1) comparisons",
    source: "[PPB, §9.2], [FJ-surfaces, §3]",
    claims: &[on(
        "random-bidegree",
        Bound::Quadratic,
        Operation::Comparisons,
    )],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The corners (lo, hi) of the smallest axis-aligned box holding the control net, and so
    /// the patch over [0, 1]². See [`BezierPatch::bounding_box_with`].
    ///
    /// # Complexity
    ///
    /// Θ(mnD) time, O(D) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// let s = BezierPatch::new(ControlNet::new(vec![
    ///     vec![p(0.0, 3.0), p(1.0, -1.0)],
    ///     vec![p(2.0, 0.0), p(-4.0, 1.0)],
    /// ])?)?;
    /// assert_eq!(s.bounding_box(), (p(-4.0, -1.0), p(2.0, 3.0)));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bounding_box(&self) -> (Point<S, D>, Point<S, D>) {
        self.bounding_box_with(&mut NoCount)
    }

    /// The bounding box of the net, counting coordinate comparisons.
    ///
    /// Idea: the patch over [0, 1]² is a convex combination of its control points
    /// [PPB, §9.2, Obs. 4]; the box of the net is the running minimum and maximum of every
    /// coordinate (the curve code's box of a polygon, over all the points).
    ///
    /// # Complexity
    ///
    /// Θ(mnD) time, O(D) auxiliary space.
    ///
    /// # Counts
    ///
    /// Two [`comparison`](Counter::comparison)s per coordinate of every point after the
    /// first: exactly 2D((m + 1)(n + 1) − 1).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let mut c = Counts::default();
    /// let (lo, hi) = BezierPatch::new(ControlNet::new(rows)?)?.bounding_box_with(&mut c);
    /// assert_eq!((lo, hi), (Point::new([0.0, 0.0]), Point::new([2.0, 3.0])));
    /// assert_eq!(c.comparisons, 2 * 2 * 11);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bounding_box_with<C: Counter>(&self, counter: &mut C) -> (Point<S, D>, Point<S, D>) {
        bounding_box_counted(self.net().points(), counter)
    }
}
