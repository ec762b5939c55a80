//! Diameter of a point set: brute force, and rotating calipers over the convex hull, which
//! also lists every antipodal pair.
//!
//! The seed (`003_5b666ee3e15e6353.txt`, §2.3 "Cálculo del diámetro de una nube de puntos")
//! proves that the diameter is attained by two hull vertices that are antipodal (they admit
//! parallel supporting lines), and finds all antipodal pairs of a convex polygon with n
//! vertices in O(n) by rotating two calipers ("Algoritmo de girar calibres"). Its angle test
//! builds the point `x = p + SIG(q) − q`, which rounds in floating point; here the same test
//! is [`cross_sign`](crate::geometry::cross_sign) of the two edge directions, exact.
//!
//! ```
//! use compgeo::calipers::{diameter, diameter_brute_force};
//! use compgeo::geometry::{cmp_dist, Point2};
//!
//! let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (1.0, 1.0)].map(Point2::from);
//! let d = diameter(&pts)?.unwrap();
//! assert_eq!((d.a, d.b), (0, 2));
//! assert_eq!(d.length, 5.0);
//! let b = diameter_brute_force(&pts)?.unwrap();
//! assert_eq!(cmp_dist(pts[d.a], pts[d.b], pts[b.a], pts[b.b]), std::cmp::Ordering::Equal);
//! # Ok::<(), compgeo::Error>(())
//! ```

use crate::count::{Counter, NoCount};
use crate::error::{Error, Result};
use crate::geometry::{validate, CountedPredicates, Orientation, Point2};
use crate::hull::{akl_toussaint_with, is_strictly_convex_ccw, HullOptions};
use std::cmp::Ordering;

/// A diameter: two input points at the largest distance, and that distance.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Diameter {
    /// Index of one end (the smaller index for a one-point set, where both ends coincide).
    pub a: usize,
    /// Index of the other end.
    pub b: usize,
    /// The Euclidean distance between the two, rounded (within a few ulps). The pair itself
    /// is exact: it is chosen by exact comparisons of squared distances.
    pub length: f64,
}

/// All antipodal pairs of a strictly convex polygon, by rotating calipers. See
/// [`antipodal_pairs_with`].
///
/// ```
/// use compgeo::calipers::antipodal_pairs;
/// use compgeo::geometry::Point2;
///
/// let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(Point2::from);
/// let pairs = antipodal_pairs(&square, &[0, 1, 2, 3])?;
/// assert_eq!(pairs.len(), 6); // 3n/2: two pairs of parallel sides
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn antipodal_pairs(points: &[Point2], polygon: &[usize]) -> Result<Vec<(usize, usize)>> {
    antipodal_pairs_with(points, polygon, &mut NoCount)
}

/// All antipodal pairs of the strictly convex polygon `polygon` (indices into `points`,
/// counter-clockwise, as the [`hull`](crate::hull) functions return it), recording the
/// operations in `counter`.
///
/// Idea: start with `p` at the lexicographically smallest vertex and `q` at the largest,
/// antipodal through vertical supporting lines. Repeatedly record `(p, q)` and rotate the
/// calipers to the next polygon edge: advance `p` when its edge `p -> SIG(p)` is reached
/// first, that is when `q -> SIG(q)` turns clockwise of it (the seed's
/// `Δ(p, SIG(p), x) < 0`), `q` when it turns counter-clockwise, and both, recording the two
/// extra pairs
/// `(p, SIG(q))` and `(SIG(p), q)`, when the edges are parallel. Stop when `p` reaches the
/// largest vertex and `q` the smallest.
///
/// Follows `003_5b666ee3e15e6353.txt`, §2.3 "Algoritmo de girar calibres" (steps 1–5 and
/// Observaciones 2.23), with the exact direction test described in the module docs.
///
/// Degenerate polygons: none for zero or one vertex, the single pair for two.
///
/// # Errors
///
/// [`Error::NonFinite`] if a vertex has a NaN or infinite coordinate;
/// [`Error::InvalidParameter`] (name `"polygon"`) if an index is out of range or the
/// polygon is not strictly convex and counter-clockwise.
///
/// # Complexity
///
/// With n = `polygon.len()`: time Θ(n), auxiliary space O(n) for the output; at most 3n/2
/// pairs (n steps, each adding one pair, or three for a pair of parallel edges).
///
/// # Counts
///
/// Orientation tests: one [`cross_sign`](crate::geometry::cross_sign) per step, at most n,
/// plus the comparisons that find the two extreme vertices.
///
/// ```
/// use compgeo::calipers::antipodal_pairs_with;
/// use compgeo::count::Counts;
/// use compgeo::geometry::Point2;
///
/// let triangle = [(0.0, 0.0), (2.0, 0.0), (1.0, 3.0)].map(Point2::from);
/// let mut counts = Counts::default();
/// let pairs = antipodal_pairs_with(&triangle, &[0, 1, 2], &mut counts)?;
/// assert_eq!(pairs, [(0, 1), (0, 2), (1, 2)]);
/// assert!(counts.orientation_tests <= 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn antipodal_pairs_with<C: Counter>(
    points: &[Point2],
    polygon: &[usize],
    counter: &mut C,
) -> Result<Vec<(usize, usize)>> {
    if let Some(&i) = polygon.iter().find(|&&i| i >= points.len()) {
        return Err(Error::InvalidParameter {
            name: "polygon",
            reason: format!("vertex {i} is out of range for {} points", points.len()),
        });
    }
    let vertices: Vec<Point2> = polygon.iter().map(|&i| points[i]).collect();
    validate(&vertices).map_err(|e| match e {
        Error::NonFinite { index, value } => Error::NonFinite {
            index: polygon[index],
            value,
        },
        other => other,
    })?;
    if !is_strictly_convex_ccw(points, polygon) {
        return Err(Error::InvalidParameter {
            name: "polygon",
            reason: "the polygon is not strictly convex and counter-clockwise".into(),
        });
    }
    Ok(calipers(points, polygon, counter))
}

/// The diameter of `points`: the convex hull ([`akl_toussaint`](crate::hull::akl_toussaint))
/// then the antipodal pair farthest apart. See [`diameter_with`].
///
/// ```
/// use compgeo::calipers::diameter;
/// use compgeo::geometry::Point2;
///
/// assert!(diameter(&[])?.is_none());
/// let d = diameter(&[Point2::new(1.0, 1.0)])?.unwrap();
/// assert_eq!((d.a, d.b, d.length), (0, 0, 0.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn diameter(points: &[Point2]) -> Result<Option<Diameter>> {
    diameter_with(points, &mut NoCount)
}

/// The diameter of `points` by rotating calipers over the convex hull, recording the
/// operations in `counter`; `None` for an empty set.
///
/// Idea: the diameter is attained by an antipodal pair of hull vertices (seed Proposiciones
/// 2.19 and 2.22); compute the hull, list the antipodal pairs with
/// [`antipodal_pairs`] and keep the pair farthest apart by exact
/// [`cmp_dist`](crate::geometry::cmp_dist). Of equally distant pairs the first found is
/// returned, so the pair may differ from [`diameter_brute_force`]'s while the distance is
/// the same.
///
/// Follows `003_5b666ee3e15e6353.txt`, §2.3 ("Diámetro de un polígono convexo", the
/// three-step algorithm).
///
/// # Errors
///
/// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and h the number of hull vertices: the hull's time (O(n log n)
/// worst case, O(n) expected on uniform input) plus Θ(h) for the calipers; auxiliary space
/// O(n).
///
/// # Counts
///
/// Those of the hull, plus at most h orientation tests and 3h/2 distance evaluations.
///
/// ```
/// use compgeo::calipers::diameter_with;
/// use compgeo::count::Counts;
/// use compgeo::gen::{points, PointKind};
///
/// let pts = points(PointKind::UniformDisk, 1000, 9)?;
/// let mut counts = Counts::default();
/// let d = diameter_with(&pts, &mut counts)?.unwrap();
/// assert!(d.length > 1.9 && d.length < 2.0);
/// assert!(counts.distance_evaluations < 1000);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn diameter_with<C: Counter>(points: &[Point2], counter: &mut C) -> Result<Option<Diameter>> {
    let hull = akl_toussaint_with(points, HullOptions::default(), counter)?;
    let pairs = calipers(points, &hull, counter);
    Ok(match hull.len() {
        0 => None,
        1 => Some(make(points, hull[0], hull[0])),
        _ => farthest_pair(points, pairs.into_iter(), counter).map(|(a, b)| make(points, a, b)),
    })
}

/// The diameter of `points` by comparing every pair. See [`diameter_brute_force_with`].
///
/// ```
/// use compgeo::calipers::diameter_brute_force;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (1.0, 1.0)].map(Point2::from);
/// let d = diameter_brute_force(&pts)?.unwrap();
/// assert_eq!((d.a, d.b, d.length), (0, 1, 5.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn diameter_brute_force(points: &[Point2]) -> Result<Option<Diameter>> {
    diameter_brute_force_with(points, &mut NoCount)
}

/// The diameter of `points` by comparing the squared distances of all pairs exactly,
/// recording the operations in `counter`; `None` for an empty set.
///
/// Follows `003_5b666ee3e15e6353.txt`, §2.3 "Algoritmo de fuerza bruta". Of equally
/// distant pairs the first in the order (0, 1), (0, 2), ..., (1, 2), ... is returned.
///
/// # Errors
///
/// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()`: time Θ(n²), auxiliary space O(1).
///
/// # Counts
///
/// Distance evaluations: n(n − 1)/2 − 1 for n ≥ 2 (each pair against the best so far).
///
/// ```
/// use compgeo::calipers::diameter_brute_force_with;
/// use compgeo::count::Counts;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (1.0, 1.0), (2.0, 0.0)].map(Point2::from);
/// let mut counts = Counts::default();
/// diameter_brute_force_with(&pts, &mut counts)?;
/// assert_eq!(counts.distance_evaluations, 5);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn diameter_brute_force_with<C: Counter>(
    points: &[Point2],
    counter: &mut C,
) -> Result<Option<Diameter>> {
    validate(points)?;
    let n = points.len();
    Ok(match n {
        0 => None,
        1 => Some(make(points, 0, 0)),
        _ => {
            let pairs = (0..n).flat_map(|a| (a + 1..n).map(move |b| (a, b)));
            farthest_pair(points, pairs, counter).map(|(a, b)| make(points, a, b))
        }
    })
}

/// The seed's loop over a valid strictly convex counter-clockwise polygon.
fn calipers<C: Counter>(
    points: &[Point2],
    polygon: &[usize],
    counter: &mut C,
) -> Vec<(usize, usize)> {
    let n = polygon.len();
    match n {
        0 | 1 => return Vec::new(),
        2 => return vec![(polygon[0], polygon[1])],
        _ => {}
    }
    let v = |k: usize| points[polygon[k % n]];
    let (mut lo, mut hi) = (0, 0);
    for k in 1..n {
        if counter.cmp_lex(v(k), v(lo)) == Ordering::Less {
            lo = k;
        }
        if counter.cmp_lex(v(k), v(hi)) == Ordering::Greater {
            hi = k;
        }
    }
    let (mut p, mut q) = (lo, hi);
    let mut pairs = Vec::with_capacity(3 * n / 2 + 1);
    // Each step advances p or q (or both) by one; together they go once around.
    for _ in 0..n {
        if p == hi && q == lo {
            break;
        }
        pairs.push((polygon[p], polygon[q]));
        let (p_next, q_next) = ((p + 1) % n, (q + 1) % n);
        match counter.cross_sign(v(p), v(p_next), v(q), v(q_next)) {
            // q's edge turns clockwise of p's: p's caliper meets its edge first.
            Orientation::Clockwise => p = p_next,
            Orientation::CounterClockwise => q = q_next,
            Orientation::Collinear => {
                pairs.push((polygon[p], polygon[q_next]));
                pairs.push((polygon[p_next], polygon[q]));
                p = p_next;
                q = q_next;
            }
        }
    }
    pairs
}

/// The pair whose points are farthest apart, the first of equals.
fn farthest_pair<C: Counter>(
    points: &[Point2],
    mut pairs: impl Iterator<Item = (usize, usize)>,
    counter: &mut C,
) -> Option<(usize, usize)> {
    let mut best = pairs.next()?;
    for (a, b) in pairs {
        if counter.cmp_dist(points[a], points[b], points[best.0], points[best.1])
            == Ordering::Greater
        {
            best = (a, b);
        }
    }
    Some(best)
}

/// A [`Diameter`] with its length computed without overflow (halved coordinates).
fn make(points: &[Point2], a: usize, b: usize) -> Diameter {
    let (p, q) = (points[a], points[b]);
    let half = (p.x / 2.0 - q.x / 2.0).hypot(p.y / 2.0 - q.y / 2.0);
    let length = if half < f64::MIN_POSITIVE {
        (p.x - q.x).hypot(p.y - q.y)
    } else {
        2.0 * half
    };
    Diameter { a, b, length }
}
