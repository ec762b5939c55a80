//! The diameter of a point set: the farthest antipodal pair of the hull, or every pair by
//! brute force.

use super::ConvexPolygon;
use crate::complexity::{algorithm_family, on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::{Error, Result};
use crate::geometry::{CountedPredicates, Point2, PointPair, PointSet};
use std::cmp::Ordering;

/// The rotating calipers' [`Declaration`]: its name, bounds, counts, source and claims.
const CALIPERS: Declaration = Declaration {
    problem: "diameter",
    name: "calipers",
    function: "calipers::ConvexPolygon::diameter",
    file: "src/calipers/diameter.rs",
    summary: "the farthest antipodal pair of the convex hull",
    time: "Θ(h) after the hull",
    space: "O(n)",
    operation: Some(Operation::DistanceEvaluations),
    counts: "at most 3h/2 after the hull, one per antipodal pair",
    source: "[RD, §2.3]",
    claims: &[on(
        "convex-polygon",
        Bound::Linear,
        Operation::DistanceEvaluations,
    )],
};

/// Brute force's [`Declaration`]: its name, bounds, counts, source and claims.
const BRUTE_FORCE: Declaration = Declaration {
    problem: "diameter",
    name: "brute-force",
    function: "calipers::diameter_brute_force",
    file: "src/calipers/diameter.rs",
    summary: "every pair compared with the farthest so far",
    time: "Θ(n²)",
    space: "O(1)",
    operation: Some(Operation::DistanceEvaluations),
    counts: "exactly n(n − 1)/2 − 1 for n ≥ 2",
    source: "[RD, §2.3]",
    claims: &[on(
        "uniform-disk",
        Bound::Quadratic,
        Operation::DistanceEvaluations,
    )],
};

algorithm_family! {
    /// The diameter algorithms, for callers that choose one at run time ([`diameter`]).
    ///
    /// ```
    /// use compgeo::calipers::DiameterAlgorithm;
    ///
    /// assert_eq!("calipers".parse::<DiameterAlgorithm>()?, DiameterAlgorithm::Calipers);
    /// assert_eq!(DiameterAlgorithm::BruteForce.declaration().time, "Θ(n²)");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum DiameterAlgorithm ("diameter algorithm") {
        /// The hull, then the farthest of its antipodal pairs ([`ConvexPolygon::diameter`]).
        Calipers = CALIPERS => diameter_calipers_with,
        /// Every pair ([`diameter_brute_force`]).
        BruteForce = BRUTE_FORCE => diameter_brute_force_with,
    }
    fn run_with[C: Counter](points: &PointSet<'_>, counter: &mut C) -> Result<PointPair>;
}

/// The diameter of `points` by `algorithm`: two points at the largest distance.
///
/// Of equally distant pairs the algorithms may return different ones; the distance is the
/// same. A set whose points all coincide has diameter 0: the pair is `[0, 1]` (or `[0, 0]`
/// for a single point).
///
/// # Errors
///
/// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate;
/// [`Error::TooFew`] for an empty set.
///
/// # Complexity
///
/// That of the chosen algorithm ([`DiameterAlgorithm::declaration`]).
///
/// ```
/// use compgeo::calipers::{diameter, DiameterAlgorithm};
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (1.0, 1.0)].map(Point2::from);
/// for algorithm in DiameterAlgorithm::ALL {
///     let d = diameter(&pts, algorithm)?;
///     assert_eq!(d.pair, [0, 1]);
///     assert_eq!(d.distance, 5.0);
/// }
/// assert!(diameter(&[], DiameterAlgorithm::Calipers).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn diameter(points: &[Point2], algorithm: DiameterAlgorithm) -> Result<PointPair> {
    diameter_with(&PointSet::new(points)?, algorithm, &mut NoCount)
}

/// [`diameter`] on a validated point set, recording the operations in `counter`.
///
/// # Errors
///
/// [`Error::TooFew`] for an empty set.
///
/// # Complexity
///
/// That of the chosen algorithm ([`DiameterAlgorithm::declaration`]).
pub fn diameter_with<C: Counter>(
    points: &PointSet<'_>,
    algorithm: DiameterAlgorithm,
    counter: &mut C,
) -> Result<PointPair> {
    algorithm.run_with(points, counter)
}

/// The calipers' diameter from a point set: its hull, then [`ConvexPolygon::diameter_with`].
fn diameter_calipers_with<C: Counter>(points: &PointSet<'_>, counter: &mut C) -> Result<PointPair> {
    ConvexPolygon::hull_with(points, counter).diameter_with(counter)
}

impl ConvexPolygon<'_> {
    /// The diameter of the polygon's point set; see [`diameter_with`](Self::diameter_with).
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`] for a polygon without vertices.
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let one = [Point2::new(1.0, 1.0)];
    /// let d = ConvexPolygon::hull(&PointSet::new(&one)?).diameter()?;
    /// assert_eq!(d.pair, [0, 0]);
    /// assert!(d.distance.is_zero());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn diameter(&self) -> Result<PointPair> {
        self.diameter_with(&mut NoCount)
    }

    /// The diameter of the polygon's point set, the farthest pair of its antipodal vertices,
    /// recording the operations in `counter`.
    ///
    /// Idea: the diameter of a point set is attained by an antipodal pair of hull vertices
    /// (the course's Proposiciones 2.19 and 2.22); list the antipodal pairs with
    /// [`antipodal_pairs`](Self::antipodal_pairs) and keep the pair farthest apart by exact
    /// [`cmp_dist`](crate::geometry::cmp_dist). Of equally distant pairs the first found is
    /// returned, so the pair may differ from [`diameter_brute_force`]'s while the distance is
    /// the same. When the polygon is the hull of one distinct point the pair is that vertex
    /// and the next index of the set (`[0, 1]` for copies of one point, `[0, 0]` for a
    /// single point).
    ///
    /// Follows [RD, §2.3] ("Diámetro de un polígono convexo", the three-step algorithm).
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`] for a polygon without vertices.
    ///
    /// # Complexity
    ///
    /// With h the number of vertices: time Θ(h) after the hull (which costs O(n log n), O(n)
    /// expected on uniform input, when the polygon is a point set's hull); auxiliary space
    /// O(n).
    ///
    /// # Counts
    ///
    /// Those of [`antipodal_pairs_with`](Self::antipodal_pairs_with), plus one distance
    /// evaluation per antipodal pair after the first: at most 3h/2.
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
    /// let d = hull.diameter_with(&mut counts)?;
    /// assert!(d.distance > 1.9 && d.distance < 2.0);
    /// assert!(counts.distance_evaluations <= 3 * hull.vertices().len() as u64 / 2);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn diameter_with<C: Counter>(&self, counter: &mut C) -> Result<PointPair> {
        let points = self.points;
        match *self.vertices() {
            [] => Err(ConvexPolygon::empty()),
            [v] => {
                let other = (0..points.len()).find(|&i| i != v).unwrap_or(v);
                Ok(PointPair::new(points, v, other))
            }
            _ => {
                let pairs = self.antipodal_pairs_with(counter);
                let [a, b] = farthest_pair(points, pairs.into_iter(), counter)
                    .expect("a polygon of two vertices has a pair");
                Ok(PointPair::new(points, a, b))
            }
        }
    }
}

/// The diameter of `points` by comparing every pair; see [`diameter_brute_force_with`].
///
/// # Errors
///
/// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate;
/// [`Error::TooFew`] for an empty set.
///
/// ```
/// use compgeo::calipers::diameter_brute_force;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (1.0, 1.0)].map(Point2::from);
/// let d = diameter_brute_force(&pts)?;
/// assert_eq!(d.pair, [0, 1]);
/// assert_eq!(d.distance, 5.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn diameter_brute_force(points: &[Point2]) -> Result<PointPair> {
    diameter_brute_force_with(&PointSet::new(points)?, &mut NoCount)
}

/// The diameter of `points` by comparing the squared distances of all pairs exactly,
/// recording the operations in `counter`.
///
/// Follows [RD, §2.3], "Algoritmo de fuerza bruta". Of equally distant pairs the first in
/// the order (0, 1), (0, 2), ..., (1, 2), ... is returned; a single point gives `[0, 0]`.
///
/// # Errors
///
/// [`Error::TooFew`] for an empty set.
///
/// # Complexity
///
/// With n = `points.len()`: time Θ(n²), auxiliary space O(1).
///
/// # Counts
///
/// Distance evaluations: exactly n(n − 1)/2 − 1 for n ≥ 2 (each pair against the best so
/// far).
///
/// ```
/// use compgeo::calipers::diameter_brute_force_with;
/// use compgeo::count::Counts;
/// use compgeo::geometry::{Point2, PointSet};
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (1.0, 1.0), (2.0, 0.0)].map(Point2::from);
/// let mut counts = Counts::default();
/// diameter_brute_force_with(&PointSet::new(&pts)?, &mut counts)?;
/// assert_eq!(counts.distance_evaluations, 5);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn diameter_brute_force_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<PointPair> {
    let n = points.len();
    match n {
        0 => Err(Error::TooFew {
            what: "point set",
            needed: 1,
            got: 0,
        }),
        1 => Ok(PointPair::new(points, 0, 0)),
        _ => {
            let pairs = (0..n).flat_map(|a| (a + 1..n).map(move |b| [a, b]));
            let [a, b] = farthest_pair(points, pairs, counter).expect("n ≥ 2 gives a pair");
            Ok(PointPair::new(points, a, b))
        }
    }
}

/// The pair whose points are farthest apart, the first of equals.
fn farthest_pair<C: Counter>(
    points: &[Point2],
    mut pairs: impl Iterator<Item = [usize; 2]>,
    counter: &mut C,
) -> Option<[usize; 2]> {
    let mut best = pairs.next()?;
    for [a, b] in pairs {
        if counter.cmp_dist(points[a], points[b], points[best[0]], points[best[1]])
            == Ordering::Greater
        {
            best = [a, b];
        }
    }
    Some(best)
}
