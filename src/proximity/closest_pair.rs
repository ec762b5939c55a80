//! The closest pair, chosen among its algorithms like every other algorithm family.

use super::{closest_pair_delaunay, closest_pair_divide_and_conquer};
use crate::complexity::algorithm_family;
use crate::count::{Counter, NoCount};
use crate::error::Result;
use crate::geometry::{Point2, PointPair, PointSet};

algorithm_family! {
    /// The closest-pair algorithms, for callers that choose one at run time
    /// ([`closest_pair`]).
    ///
    /// ```
    /// use compgeo::proximity::ClosestPairAlgorithm;
    ///
    /// let a: ClosestPairAlgorithm = "divide-and-conquer".parse()?;
    /// assert_eq!(a, ClosestPairAlgorithm::DivideAndConquer);
    /// assert_eq!(ClosestPairAlgorithm::Delaunay.name(), "delaunay");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum ClosestPairAlgorithm ("closest-pair algorithm") {
        /// The shortest Delaunay edge ([`closest_pair_delaunay`]).
        Delaunay = closest_pair_delaunay::DECLARATION => closest_pair_delaunay::closest_pair_delaunay_with,
        /// Shamos's divide and conquer ([`closest_pair_divide_and_conquer`]).
        DivideAndConquer = closest_pair_divide_and_conquer::DECLARATION
            => closest_pair_divide_and_conquer::closest_pair_divide_and_conquer_with,
    }
    fn run_with[C: Counter](points: &PointSet<'_>, counter: &mut C) -> Result<PointPair>;
}

/// The closest pair of `points` by `algorithm`: two points at the smallest distance.
///
/// With duplicates the answer is a pair of equal points (distance zero). Of equally close
/// pairs the algorithms may return different ones; the distance is the same.
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::TooFew`](crate::Error::TooFew) for fewer than two points.
///
/// # Complexity
/// That of the chosen algorithm ([`ClosestPairAlgorithm::declaration`]).
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::proximity::{closest_pair, ClosestPairAlgorithm};
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (9.0, 9.0), (3.5, 5.0)].map(Point2::from);
/// for algorithm in ClosestPairAlgorithm::ALL {
///     let c = closest_pair(&pts, algorithm)?;
///     assert_eq!(c.pair, [1, 3]);
///     assert_eq!(c.distance, 1.25f64.sqrt());
/// }
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closest_pair(points: &[Point2], algorithm: ClosestPairAlgorithm) -> Result<PointPair> {
    closest_pair_with(&PointSet::new(points)?, algorithm, &mut NoCount)
}

/// [`closest_pair`] on a validated point set, recording the operations in `counter`.
///
/// # Errors
/// [`Error::TooFew`](crate::Error::TooFew) for fewer than two points, and the errors of
/// the triangulation for [`ClosestPairAlgorithm::Delaunay`] (a point set beyond its size
/// limit).
///
/// # Complexity
/// That of the chosen algorithm ([`ClosestPairAlgorithm::declaration`]).
pub fn closest_pair_with<C: Counter>(
    points: &PointSet<'_>,
    algorithm: ClosestPairAlgorithm,
    counter: &mut C,
) -> Result<PointPair> {
    algorithm.run_with(points, counter)
}
