//! The validated point set every geometric algorithm takes, and its bounding box.
//!
//! User data is checked once, at the boundary: [`PointSet::new`] rejects NaN and infinities
//! (naming the first bad point) and records the bounding box in the same pass. Every
//! geometric `_with` function takes a `&PointSet`, so it neither checks the coordinates again
//! nor fails on them; the plain functions take `&[Point2]` for convenience and build the set
//! themselves.

use super::{Point2, WideFloat};
use crate::error::{Error, Result};
use std::ops::Deref;

/// A point set whose coordinates are all finite, checked once when it is built.
///
/// It borrows the caller's points (no copy), so results that carry indices refer to the
/// caller's own slice. It dereferences to `[Point2]`: index it, iterate it, take its
/// length as a slice. Every finite `f64` is valid, however large or small.
///
/// ```
/// use compgeo::geometry::{BoundingBox, Point2, PointSet};
/// use compgeo::Error;
///
/// let pts = [Point2::new(1e300, -2.0), Point2::new(-0.5, 5e-324)];
/// let set = PointSet::new(&pts)?;
/// assert_eq!(set.len(), 2);
/// assert_eq!(set[0], pts[0]);
/// let BoundingBox { min, max } = set.bounding_box().unwrap();
/// assert_eq!((min, max), (Point2::new(-0.5, -2.0), Point2::new(1e300, 5e-324)));
///
/// let bad = [Point2::new(0.0, 0.0), Point2::new(1.0, f64::NAN)];
/// let err = PointSet::new(&bad).unwrap_err();
/// assert!(matches!(err, Error::NonFinite { index: 1, .. }));
/// assert_eq!(err.to_string(), "point 1 has a non-finite coordinate (NaN)");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointSet<'a> {
    points: &'a [Point2],
    bounds: Option<BoundingBox>,
}

/// The smallest axis-parallel box holding a non-empty point set: the least and the largest x
/// and y.
///
/// Of equal extremes the first in input order is kept, so `-0.0` and `0.0` stay as the input
/// has them.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BoundingBox {
    /// The corner with the least x and the least y.
    pub min: Point2,
    /// The corner with the largest x and the largest y.
    pub max: Point2,
}

impl<'a> PointSet<'a> {
    /// Checks that every coordinate is finite and records the bounding box.
    ///
    /// # Errors
    /// [`Error::NonFinite`] naming the first point (in input order) with a NaN or infinite
    /// coordinate, and that coordinate.
    ///
    /// # Complexity
    /// O(n) time, O(1) auxiliary space.
    pub fn new(points: &'a [Point2]) -> Result<PointSet<'a>> {
        #[cfg(feature = "parallel")]
        if points.len() >= crate::parallel::THRESHOLD {
            use rayon::prelude::*;
            // Chunks checked at the same time, then combined in input order: the first
            // error is the first chunk's, and extending by a chunk's corners with strict
            // comparisons keeps the first of equal extremes, as the sequential pass does.
            const CHUNK: usize = 1 << 15;
            let parts: Vec<Result<Option<BoundingBox>>> = points
                .par_chunks(CHUNK)
                .enumerate()
                .map(|(c, chunk)| bounds_of(chunk, c * CHUNK))
                .collect();
            let mut bounds: Option<BoundingBox> = None;
            for part in parts {
                match (&mut bounds, part?) {
                    (_, None) => {}
                    (None, b) => bounds = b,
                    (Some(b), Some(c)) => {
                        b.extend(c.min);
                        b.extend(c.max);
                    }
                }
            }
            return Ok(PointSet { points, bounds });
        }
        let bounds = bounds_of(points, 0)?;
        Ok(PointSet { points, bounds })
    }

    /// The points, as the caller passed them.
    #[inline]
    pub fn points(&self) -> &'a [Point2] {
        self.points
    }

    /// The bounding box; `None` for an empty set.
    #[inline]
    pub fn bounding_box(&self) -> Option<BoundingBox> {
        self.bounds
    }
}

/// The bounding box of `points` (`None` if empty), or [`Error::NonFinite`] naming the first
/// point with a NaN or infinite coordinate; `points[k]` has index `offset + k`.
fn bounds_of(points: &[Point2], offset: usize) -> Result<Option<BoundingBox>> {
    let mut bounds: Option<BoundingBox> = None;
    for (k, &p) in points.iter().enumerate() {
        for value in [p.x, p.y] {
            if !value.is_finite() {
                return Err(Error::NonFinite {
                    index: offset + k,
                    value,
                });
            }
        }
        match &mut bounds {
            None => bounds = Some(BoundingBox { min: p, max: p }),
            Some(b) => b.extend(p),
        }
    }
    Ok(bounds)
}

impl Deref for PointSet<'_> {
    type Target = [Point2];

    #[inline]
    fn deref(&self) -> &[Point2] {
        self.points
    }
}

impl<'a> TryFrom<&'a [Point2]> for PointSet<'a> {
    type Error = Error;

    /// [`PointSet::new`].
    fn try_from(points: &'a [Point2]) -> Result<PointSet<'a>> {
        PointSet::new(points)
    }
}

impl BoundingBox {
    /// The bounding box of `points` (finite coordinates); `None` for no points.
    ///
    /// # Complexity
    /// O(n) time.
    ///
    /// ```
    /// use compgeo::geometry::{BoundingBox, Point2};
    ///
    /// let b = BoundingBox::of(&[Point2::new(3.0, -1.0), Point2::new(0.0, 2.0)]).unwrap();
    /// assert_eq!((b.min, b.max), (Point2::new(0.0, -1.0), Point2::new(3.0, 2.0)));
    /// assert_eq!(b.width(), 3.0);
    /// assert!(BoundingBox::of(&[]).is_none());
    /// ```
    pub fn of(points: &[Point2]) -> Option<BoundingBox> {
        let (&first, rest) = points.split_first()?;
        let mut b = BoundingBox {
            min: first,
            max: first,
        };
        for &p in rest {
            b.extend(p);
        }
        Some(b)
    }

    /// The box's extent along x, `max.x - min.x`, correctly rounded; a [`WideFloat`], so
    /// an extent beyond `f64::MAX` keeps its value.
    ///
    /// ```
    /// use compgeo::geometry::{BoundingBox, Point2};
    ///
    /// let b = BoundingBox::of(&[Point2::new(-f64::MAX, 0.0), Point2::new(f64::MAX, 1.0)]).unwrap();
    /// assert_eq!(b.width().to_f64(), None);
    /// assert_eq!(b.width().to_string(), "3.5953862697246314e308"); // 2 · f64::MAX
    /// assert_eq!(b.height(), 1.0);
    /// ```
    pub fn width(&self) -> WideFloat {
        WideFloat::difference(self.max.x, self.min.x)
    }

    /// The box's extent along y, `max.y - min.y`, correctly rounded, as
    /// [`width`](Self::width).
    pub fn height(&self) -> WideFloat {
        WideFloat::difference(self.max.y, self.min.y)
    }

    /// Grows the box to hold `p` (a finite point); equal extremes keep the earlier value.
    #[inline]
    pub(crate) fn extend(&mut self, p: Point2) {
        if p.x < self.min.x {
            self.min.x = p.x;
        }
        if p.y < self.min.y {
            self.min.y = p.y;
        }
        if p.x > self.max.x {
            self.max.x = p.x;
        }
        if p.y > self.max.y {
            self.max.y = p.y;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_first_bad_point_and_its_value() {
        let pts = [
            Point2::new(0.0, 0.0),
            Point2::new(f64::INFINITY, 0.0),
            Point2::new(f64::NAN, 0.0),
        ];
        match PointSet::new(&pts) {
            Err(Error::NonFinite { index, value }) => {
                assert_eq!(index, 1);
                assert_eq!(value, f64::INFINITY);
            }
            other => panic!("expected NonFinite, got {other:?}"),
        }
        let pts = [Point2::new(1.0, 1.0), Point2::new(2.0, f64::NEG_INFINITY)];
        assert!(matches!(
            PointSet::new(&pts),
            Err(Error::NonFinite { index: 1, .. })
        ));
    }

    #[test]
    fn accepts_extremes_and_empty() {
        let empty = PointSet::new(&[]).unwrap();
        assert!(empty.is_empty() && empty.bounding_box().is_none());
        let pts = [
            Point2::new(f64::MAX, -f64::MAX),
            Point2::new(f64::MIN_POSITIVE, 5e-324),
            Point2::new(-0.0, 1e-310),
        ];
        let set = PointSet::new(&pts).unwrap();
        let b = set.bounding_box().unwrap();
        assert_eq!(b.min, Point2::new(-0.0, -f64::MAX));
        assert_eq!(b.max, Point2::new(f64::MAX, 1e-310));
        assert_eq!((b.width(), b.height()), (f64::MAX.into(), f64::MAX.into()));
        let far = BoundingBox::of(&[Point2::new(0.0, -f64::MAX), Point2::new(0.0, f64::MAX)]);
        let two_max = WideFloat::from(f64::MAX).mul(WideFloat::from(2.0));
        assert_eq!(far.unwrap().height(), two_max);
    }

    #[test]
    fn equal_extremes_keep_the_first() {
        let pts = [Point2::new(0.0, -0.0), Point2::new(-0.0, 0.0)];
        let b = BoundingBox::of(&pts).unwrap();
        assert!(b.min.x.is_sign_positive() && b.min.y.is_sign_negative());
        assert!(b.max.x.is_sign_positive() && b.max.y.is_sign_negative());
        let set = PointSet::new(&pts).unwrap();
        assert_eq!(set.bounding_box(), Some(b));
    }
}
