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
//! The same calipers give the [`width`] (the smallest distance between two parallel
//! supporting lines) and the [`min_area_rectangle`]: both are attained with one side on a
//! hull edge, so four calipers, one per side, rotate once around the hull and each edge is
//! scored with an exact comparison ([`cmp_line_dist`](crate::geometry::cmp_line_dist),
//! [`cmp_rect_area`](crate::geometry::cmp_rect_area)) instead of a rounded distance or area.
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

/// A width: a hull edge, the hull vertex farthest from its line, and the distance between
/// the two parallel supporting lines through them.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Width {
    /// The hull edge `[i, j]` (indices into the input, counter-clockwise) one supporting line
    /// runs along; `[i, i]` for a one-point set, the two ends for a segment.
    pub edge: [usize; 2],
    /// The vertex on the other supporting line (the edge's start when the width is zero).
    pub vertex: usize,
    /// The distance between the lines, rounded (from the vertex's difference to the edge, so
    /// it keeps its relative accuracy even when tiny; `inf` if it exceeds `f64::MAX`). The
    /// edge and the vertex are exact: chosen by exact comparisons.
    pub width: f64,
}

/// A minimum-area enclosing rectangle: the hull edge one side lies on, the vertices that
/// touch the other three sides, and the corners.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Rectangle {
    /// The hull edge `[i, j]` that one side lies on (counter-clockwise, so the rectangle is
    /// left of `i -> j`).
    pub edge: [usize; 2],
    /// The vertices touching the other sides, counter-clockwise from the edge:
    /// `[right, top, left]` (extreme along the edge's direction, farthest from its line,
    /// extreme against its direction).
    pub support: [usize; 3],
    /// The corners, counter-clockwise, starting on the edge's line below `left`. These are
    /// constructions (projections onto the lines), rounded to within a few ulps of the
    /// hull's largest coordinate; the edge and the support vertices are exact.
    pub corners: [Point2; 4],
    /// The area, rounded: height times length, each from the support vertices' own
    /// differences (`inf` if it exceeds `f64::MAX`; 0 for collinear input).
    pub area: f64,
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

/// The width of `points`. See [`width_with`].
///
/// ```
/// use compgeo::calipers::width;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (2.0, 1.0)].map(Point2::from);
/// let w = width(&pts)?.unwrap();
/// assert_eq!((w.edge, w.vertex, w.width), ([0, 1], 2, 3.0)); // the bottom edge, height 3
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn width(points: &[Point2]) -> Result<Option<Width>> {
    width_with(points, &mut NoCount)
}

/// The width of `points`, the smallest distance between two parallel lines enclosing them,
/// by rotating calipers over the convex hull, recording the operations in `counter`; `None`
/// for an empty set.
///
/// Idea: a pair of parallel supporting lines at minimum distance has one line along a hull
/// edge (rotating a pair that touches only vertices shortens it one way or the other), so
/// the width is the smallest over edges of the distance to the farthest vertex. That vertex
/// moves counter-clockwise as the edge does: one caliper walks around the hull once, moved
/// on by [`cross_sign`](crate::geometry::cross_sign) (does the next vertex lie farther from
/// the edge's line?). Edges are compared by
/// [`cmp_line_dist`](crate::geometry::cmp_line_dist), exact; of equal widths the first edge
/// counter-clockwise from the lexicographically smallest vertex is returned.
///
/// Follows `003_5b666ee3e15e6353.txt`, §2.3 ("Algoritmo de girar calibres": the same
/// calipers, scored per edge instead of per antipodal pair).
///
/// Degenerate input: a single point or collinear points have width 0 (`edge` joins the two
/// extreme points).
///
/// # Errors
///
/// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and h the number of hull vertices: the hull's time (O(n log n)
/// worst case, O(n) expected on uniform input) plus Θ(h); auxiliary space O(n).
///
/// # Counts
///
/// Those of the hull, plus at most 9h orientation tests for the calipers (each of three
/// calipers is tested once per edge to stop it, and advances less than twice around the
/// hull; about 7h on points in convex position) and h − 1 distance evaluations.
///
/// ```
/// use compgeo::calipers::width_with;
/// use compgeo::count::Counts;
/// use compgeo::gen::{points, PointKind};
///
/// let pts = points(PointKind::UniformDisk, 1000, 9)?;
/// let mut counts = Counts::default();
/// let w = width_with(&pts, &mut counts)?.unwrap();
/// assert!(w.width > 1.9 && w.width < 2.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn width_with<C: Counter>(points: &[Point2], counter: &mut C) -> Result<Option<Width>> {
    let hull = akl_toussaint_with(points, HullOptions::default(), counter)?;
    let h = hull.len();
    if h <= 2 {
        return Ok(hull.first().map(|&i| Width {
            edge: [i, hull[h - 1]],
            vertex: i,
            width: 0.0,
        }));
    }
    let v = |k: usize| points[hull[k % h]];
    let mut best: Option<Sides> = None;
    four_calipers(points, &hull, counter, |s, counter| {
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
    let u = direction(v(s.edge), v(s.edge + 1));
    Ok(Some(Width {
        edge: [hull[s.edge % h], hull[(s.edge + 1) % h]],
        vertex: hull[s.top % h],
        width: across(u, v(s.top), v(s.edge)).abs(),
    }))
}

/// The minimum-area rectangle enclosing `points`. See [`min_area_rectangle_with`].
///
/// ```
/// use compgeo::calipers::min_area_rectangle;
/// use compgeo::geometry::Point2;
///
/// // A diamond: the best rectangle is the tilted square on its sides, area 2, not the
/// // axis-parallel box of area 4.
/// let pts = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)].map(Point2::from);
/// let r = min_area_rectangle(&pts)?.unwrap();
/// assert_eq!(r.edge, [3, 0]);
/// assert!((r.area - 2.0).abs() < 1e-12);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn min_area_rectangle(points: &[Point2]) -> Result<Option<Rectangle>> {
    min_area_rectangle_with(points, &mut NoCount)
}

/// The minimum-area rectangle enclosing `points`, by rotating four calipers over the convex
/// hull, recording the operations in `counter`; `None` for an empty set.
///
/// Idea: a minimum-area enclosing rectangle has a side along a hull edge (Freeman and
/// Shapira, 1975). For each edge, in counter-clockwise order, three more calipers track the
/// vertex extreme along the edge's direction, the one farthest from its line and the one
/// extreme against its direction; each only moves forward, so together they go around the
/// hull a bounded number of times. The extremes along the direction are found with the
/// sign of a dot product, which is [`cross_sign`](crate::geometry::cross_sign) of the edge
/// turned by a right angle (an exact swap and negation of coordinates). Edges are compared
/// by [`cmp_rect_area`](crate::geometry::cmp_rect_area), exact; of equal areas the first
/// edge counter-clockwise from the lexicographically smallest vertex wins.
///
/// Not in the seed's algorithms; it extends `003_5b666ee3e15e6353.txt`, §2.3 "Algoritmo de
/// girar calibres" from two calipers to four.
///
/// Degenerate input: a single point gives a rectangle with four equal corners; collinear
/// points the segment between the extremes (`corners` `[a, b, b, a]`); both have area 0.
///
/// # Errors
///
/// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and h the number of hull vertices: the hull's time plus Θ(h);
/// auxiliary space O(n).
///
/// # Counts
///
/// Those of the hull, plus at most 9h orientation tests for the calipers (as for
/// [`width_with`]) and h − 1 distance evaluations (area comparisons).
///
/// ```
/// use compgeo::calipers::min_area_rectangle_with;
/// use compgeo::count::Counts;
/// use compgeo::gen::{points, PointKind};
///
/// let pts = points(PointKind::UniformSquare, 1000, 4)?;
/// let mut counts = Counts::default();
/// let r = min_area_rectangle_with(&pts, &mut counts)?.unwrap();
/// assert!(r.area > 0.9 && r.area <= 1.0); // nearly the unit square
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn min_area_rectangle_with<C: Counter>(
    points: &[Point2],
    counter: &mut C,
) -> Result<Option<Rectangle>> {
    let hull = akl_toussaint_with(points, HullOptions::default(), counter)?;
    let h = hull.len();
    if h <= 2 {
        return Ok(hull.first().map(|&i| {
            let (a, b) = (points[i], points[hull[h - 1]]);
            Rectangle {
                edge: [i, hull[h - 1]],
                support: [hull[h - 1], i, i],
                corners: [a, b, b, a],
                area: 0.0,
            }
        }));
    }
    let v = |k: usize| points[hull[k % h]];
    let key = |s: Sides| [v(s.edge), v(s.edge + 1), v(s.top), v(s.left), v(s.right)];
    let mut best: Option<Sides> = None;
    four_calipers(points, &hull, counter, |s, counter| {
        if best.is_none_or(|b| counter.cmp_rect_area(key(s), key(b)) == Ordering::Less) {
            best = Some(s);
        }
    });
    let s = best.expect("a polygon has edges");
    let frame = Frame::new([v(s.edge), v(s.edge + 1), v(s.top), v(s.left), v(s.right)]);
    let [a, _, top, left, right] = frame.points;
    let u = direction(v(s.edge), v(s.edge + 1));
    let along = |p: Point2| u.0 * (p.x - a.x) + u.1 * (p.y - a.y);
    let height = u.0 * (top.y - a.y) - u.1 * (top.x - a.x);
    let (lo, hi) = (along(left), along(right));
    let on_line = |t: f64| Point2::new(a.x + t * u.0, a.y + t * u.1);
    let lifted = |p: Point2| Point2::new(p.x - height * u.1, p.y + height * u.0);
    let corners = [
        on_line(lo),
        on_line(hi),
        lifted(on_line(hi)),
        lifted(on_line(lo)),
    ];
    Ok(Some(Rectangle {
        edge: [hull[s.edge % h], hull[(s.edge + 1) % h]],
        support: [s.right, s.top, s.left].map(|k| hull[k % h]),
        corners: corners.map(|c| Point2::new(frame.unscale(c.x), frame.unscale(c.y))),
        area: area(u, [v(s.edge), v(s.top), v(s.left), v(s.right)]),
    }))
}

/// For one hull edge (position `edge`, from `edge` to `edge + 1`), the positions of the
/// vertices on the other sides of its enclosing rectangle; positions count up without
/// wrapping, so take them modulo h.
#[derive(Debug, Clone, Copy)]
struct Sides {
    edge: usize,
    right: usize,
    top: usize,
    left: usize,
}

/// Rotates four calipers once around the strictly convex counter-clockwise `hull` (at least
/// three vertices) and calls `visit` for every edge with its extreme vertices: the first of
/// equally extreme ones counter-clockwise.
fn four_calipers<C: Counter>(
    points: &[Point2],
    hull: &[usize],
    counter: &mut C,
    mut visit: impl FnMut(Sides, &mut C),
) {
    let h = hull.len();
    let v = |k: usize| points[hull[k % h]];
    // The sign of (b - a) · (d - c) is that of (b' - a') x (d - c) for p' = (p.y, -p.x).
    let turned = |p: Point2| Point2::new(p.y, -p.x);
    let (mut right, mut top, mut left) = (1, 1, 1);
    for edge in 0..h {
        let (a, b) = (v(edge), v(edge + 1));
        let (ta, tb) = (turned(a), turned(b));
        right = right.max(edge + 1);
        while counter.cross_sign(ta, tb, v(right), v(right + 1)) == Orientation::CounterClockwise {
            right += 1;
        }
        top = top.max(right);
        while counter.cross_sign(a, b, v(top), v(top + 1)) == Orientation::CounterClockwise {
            top += 1;
        }
        left = left.max(top);
        while counter.cross_sign(ta, tb, v(left), v(left + 1)) == Orientation::Clockwise {
            left += 1;
        }
        visit(
            Sides {
                edge,
                right,
                top,
                left,
            },
            counter,
        );
    }
}

/// Points scaled by a power of two so that the largest coordinate is about 1: rounded
/// constructions on them neither overflow nor lose subnormal precision.
struct Frame<const N: usize> {
    points: [Point2; N],
    exponent: i32,
}

impl<const N: usize> Frame<N> {
    fn new(points: [Point2; N]) -> Frame<N> {
        let largest = points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
        // Any nearby power of two will do: the scaling only steers rounding.
        let exponent = if largest == 0.0 {
            0
        } else {
            largest.log2().floor() as i32
        };
        Frame {
            points: points.map(|p| Point2::new(scale(p.x, -exponent), scale(p.y, -exponent))),
            exponent,
        }
    }

    fn unscale(&self, v: f64) -> f64 {
        scale(v, self.exponent)
    }
}

/// `v · 2^e` in two steps, so that no factor overflows for |e| up to 2100.
fn scale(v: f64, e: i32) -> f64 {
    let half = e / 2;
    v * 2f64.powi(half) * 2f64.powi(e - half)
}

/// `p - a`, rounded, as a vector and a factor (1, or 2 when the difference overflows and its
/// half is returned).
fn difference(p: Point2, a: Point2) -> ((f64, f64), f64) {
    let (x, y) = (p.x - a.x, p.y - a.y);
    if x.is_finite() && y.is_finite() {
        ((x, y), 1.0)
    } else {
        ((p.x / 2.0 - a.x / 2.0, p.y / 2.0 - a.y / 2.0), 2.0)
    }
}

/// The signed distance of `p` from the line through `a` along the unit vector `u`, rounded
/// (computed from the difference itself, so it keeps its relative accuracy when tiny).
fn across(u: (f64, f64), p: Point2, a: Point2) -> f64 {
    let ((x, y), k) = difference(p, a);
    (u.0 * y - u.1 * x) * k
}

/// The area of the rectangle with a side on the line through `a` along `u`, the opposite side
/// through `top`, and the others through `left` and `right`, rounded: height times length,
/// each from its own differences.
fn area(u: (f64, f64), [a, top, left, right]: [Point2; 4]) -> f64 {
    let height = across(u, top, a).abs();
    let ((x, y), k) = difference(right, left);
    let length = ((u.0 * x + u.1 * y) * k).abs();
    if height == 0.0 || length == 0.0 {
        0.0
    } else {
        height * length
    }
}

/// The unit vector from `a` towards `b` (distinct points), rounded. Taken from the points
/// themselves, not from a common frame: the edge may be tiny next to the frame's largest
/// coordinate (a difference of distinct doubles is never zero), and halves avoid overflow.
fn direction(a: Point2, b: Point2) -> (f64, f64) {
    let ((x, y), _) = difference(b, a);
    let largest = x.abs().max(y.abs());
    let (x, y) = (x / largest, y / largest);
    let length = x.hypot(y);
    (x / length, y / length)
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
