//! The point type every geometric algorithm takes.

use super::WideFloat;

/// A point (or vector) in the plane with `f64` coordinates.
///
/// The plane is oriented with y up, so counter-clockwise turns are positive. Any finite
/// coordinates are valid, however large or small; NaN and infinities are rejected by
/// [`PointSet::new`](crate::geometry::PointSet::new) before an algorithm sees them.
///
/// ```
/// use compgeo::geometry::Point2;
///
/// let p = Point2::new(1.0, 2.0);
/// assert_eq!(p, Point2::from([1.0, 2.0]));
/// assert_eq!(p, Point2::from((1.0, 2.0)));
/// assert_eq!(<[f64; 2]>::from(p), [1.0, 2.0]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Point2 {
    /// The x coordinate.
    pub x: f64,
    /// The y coordinate.
    pub y: f64,
}

impl Point2 {
    /// The point `(x, y)`.
    #[inline]
    pub const fn new(x: f64, y: f64) -> Self {
        Point2 { x, y }
    }

    /// Whether both coordinates are finite (neither NaN nor infinite).
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite()
    }
}

impl From<[f64; 2]> for Point2 {
    #[inline]
    fn from([x, y]: [f64; 2]) -> Self {
        Point2 { x, y }
    }
}

impl From<(f64, f64)> for Point2 {
    #[inline]
    fn from((x, y): (f64, f64)) -> Self {
        Point2 { x, y }
    }
}

impl From<Point2> for [f64; 2] {
    #[inline]
    fn from(p: Point2) -> Self {
        [p.x, p.y]
    }
}

impl From<Point2> for (f64, f64) {
    #[inline]
    fn from(p: Point2) -> Self {
        (p.x, p.y)
    }
}

/// Two points of a set, by their indices, and their distance: the answer of the diameter and
/// of the closest pair.
///
/// The pair is exact (chosen by exact comparisons); the distance is rounded, within 2^-51
/// relative of the true value for every finite pair, and a [`WideFloat`] so that a distance
/// beyond `f64::MAX` keeps its value (see [`WideFloat::distance`]).
///
/// ```
/// use compgeo::calipers::{diameter, DiameterAlgorithm};
/// use compgeo::geometry::Point2;
///
/// let pts = [Point2::new(-f64::MAX, -f64::MAX), Point2::new(f64::MAX, f64::MAX)];
/// let d = diameter(&pts, DiameterAlgorithm::Calipers)?;
/// assert_eq!(d.pair, [0, 1]);
/// assert_eq!(d.distance.to_f64(), None); // 2√2 · f64::MAX
/// assert_eq!(d.distance.to_string(), "5.0846440246145847e308");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PointPair {
    /// The two indices into the input, the smaller first; equal only for a set of one point.
    pub pair: [usize; 2],
    /// Their Euclidean distance, rounded (relative error below 2^-51).
    pub distance: WideFloat,
}

impl PointPair {
    /// The pair `a`, `b` of `points` (in either order) with its rounded distance.
    pub(crate) fn new(points: &[Point2], a: usize, b: usize) -> PointPair {
        PointPair {
            pair: [a.min(b), a.max(b)],
            distance: WideFloat::distance(points[a], points[b]),
        }
    }
}
