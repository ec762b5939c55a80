//! Validation of user point sets: the boundary where NaN and infinities are turned away.

use super::Point2;
use crate::error::{Error, Result};

/// Checks that every coordinate of every point is finite.
///
/// Every finite `f64` is valid, including subnormals and values near `f64::MAX`: the
/// predicates of this module are exact for all of them.
///
/// # Errors
/// [`Error::NonFinite`] naming the first point (in input order) with a NaN or infinite
/// coordinate, and that coordinate.
///
/// # Complexity
/// O(n) time, O(1) auxiliary space.
///
/// ```
/// use compgeo::geometry::{validate, Point2};
/// use compgeo::Error;
///
/// let ok = [Point2::new(1e300, 5e-324), Point2::new(0.0, -0.0)];
/// assert!(validate(&ok).is_ok());
///
/// let bad = [Point2::new(0.0, 0.0), Point2::new(1.0, f64::NAN)];
/// let err = validate(&bad).unwrap_err();
/// assert!(matches!(err, Error::NonFinite { index: 1, .. }));
/// assert_eq!(err.to_string(), "point 1 has a non-finite coordinate (NaN)");
/// ```
pub fn validate(points: &[Point2]) -> Result<()> {
    for (index, p) in points.iter().enumerate() {
        for value in [p.x, p.y] {
            if !value.is_finite() {
                return Err(Error::NonFinite { index, value });
            }
        }
    }
    Ok(())
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
        match validate(&pts) {
            Err(Error::NonFinite { index, value }) => {
                assert_eq!(index, 1);
                assert_eq!(value, f64::INFINITY);
            }
            other => panic!("expected NonFinite, got {other:?}"),
        }
    }

    #[test]
    fn accepts_extremes_and_empty() {
        assert!(validate(&[]).is_ok());
        let pts = [
            Point2::new(f64::MAX, -f64::MAX),
            Point2::new(f64::MIN_POSITIVE, 5e-324),
            Point2::new(-0.0, 1e-310),
        ];
        assert!(validate(&pts).is_ok());
    }
}
