//! Intersections of two planar Bézier curves by recursive subdivision with bounding-box
//! pruning.
//!
//! The problem: the points where the segments b[0, 1] and c[0, 1] of two planar curves
//! meet. The idea: pieces whose boxes are disjoint cannot meet; otherwise the piece that is
//! not yet flat is halved, and once both are flat their chords stand in for them. The
//! flatness test is the error bound of [PPB, §3.5], `n(n − 1)/8 · max ‖Δ²bᵢ‖∞ ≤ tolerance`,
//! so a chord is within the tolerance of its piece. Whether two chords meet is decided with
//! the exact [`orient2d`]; only the parameters of the crossing are computed in floating point.
//!
//! Follows [PPB, §3.7] (the program INTERSECTAR).
//!
//! # Complexity
//!
//! O(k·d·(m² + n²)) time for k transversal crossings of curves of degrees m and n found at a
//! depth d = O(log(size/tolerance)); O(d(m + n)) auxiliary space.

use super::curve::{bounding_box_of, Bezier};
use super::flatten::flatness_bound;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::geometry::{CountedPredicates, Orientation, Point2};
use crate::spline::curve::Curve;
use crate::spline::scalar::{validate_parameter, Point};
use crate::{Error, Result};

/// The intersection search, declared: its name, bounds, counts, source and claims, in each
/// of its sizes (the degree of one curve; the tolerance ε, as n = 1/ε, which sets the depth
/// d = O(log n)).
pub(crate) const INTERSECTIONS: Declaration = Declaration {
    problem: "bezier",
    name: "intersections",
    function: "spline::intersections",
    file: "src/spline/bezier/intersect.rs",
    summary: "the crossings of two curves by subdivision with box pruning",
    time: "O(k·d·(m² + n²))",
    space: "O(d(m + n))",
    operation: Some(Operation::ArithmeticOperations),
    counts: "n(n + 1)/2 affine combinations per halving of a piece of degree n; four orientation tests per pair of flat pieces whose boxes meet",
    source: "[PPB, §3.7]",
    claims: &[
        on("parabola-degree", Bound::Quadratic, Operation::ArithmeticOperations),
        on("parabola-tolerance", Bound::Log, Operation::ArithmeticOperations),
    ],
};

/// One intersection of two curves: the parameters on each and the point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Intersection {
    /// The parameter on the first curve, in [0, 1].
    pub s: f64,
    /// The parameter on the second curve, in [0, 1].
    pub t: f64,
    /// The point `b(s)` on the first curve (within the tolerance of `c(t)`).
    pub point: Point<f64, 2>,
}

pub use crate::limits::MAX_INTERSECTION_PAIRS;

/// The intersections of the segments b[0, 1] and c[0, 1] of two planar Bézier curves.
///
/// Idea: recursive subdivision as in the course's INTERSECTAR. A pair of pieces with
/// disjoint bounding boxes is dropped; a piece that is not flat within `tolerance` is split
/// at 1/2; two flat pieces are replaced by their chords, which are tested for a crossing
/// with exact orientation tests. Crossings found twice (at a shared end of two pieces) and
/// crossings closer than `tolerance` to one already found are reported once, sorted by `s`.
///
/// Follows [PPB, §3.7] (with the bound of [PPB, §3.5] as the flatness test).
///
/// # Errors
///
/// [`Error::InvalidParameter`] if `tolerance` is not positive and finite, or if more than
/// [`MAX_INTERSECTION_PAIRS`] pairs of pieces would be examined (the curves share a piece,
/// or the tolerance is far below the curves' size).
///
/// # Complexity
///
/// For k transversal intersections and a depth of d = O(log(size/tolerance)) halvings,
/// O(k·d) pairs of pieces, each costing O((m² + n²)) for the split and box of degrees m
/// and n: O(k·d·(m² + n²)) time expected for curves in general position, O(d(m + n))
/// auxiliary space for the recursion. [`intersections_with`] counts the work.
///
/// ```
/// use compgeo::spline::{intersections, Bezier, Point};
///
/// // The parabola y = 2x(1 − x)·2 against the line y = 1/2.
/// let arch = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([0.5, 2.0]), Point::new([1.0, 0.0])])?;
/// let line = Bezier::new(vec![Point::new([0.0, 0.5]), Point::new([1.0, 0.5])])?;
/// let hits = intersections(&arch, &line, 1e-10)?;
/// assert_eq!(hits.len(), 2);
/// let expected = (1.0 - 0.5f64.sqrt()) / 2.0; // 4s(1 − s) = 1/2
/// assert!((hits[0].s - expected).abs() < 1e-6);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn intersections(
    b: &Bezier<f64, 2>,
    c: &Bezier<f64, 2>,
    tolerance: f64,
) -> Result<Vec<Intersection>> {
    intersections_with(b, c, tolerance, &mut NoCount)
}

/// [`intersections`], counting one [`arithmetic_operation`](Counter::arithmetic_operation)
/// per affine combination of the halvings (n(n + 1)/2 for a piece of degree n) and the
/// [`orientation_test`](Counter::orientation_test)s of the chord crossings (four per pair of
/// flat pieces whose boxes meet).
///
/// # Errors
///
/// As [`intersections`].
///
/// # Complexity
///
/// O(k·d·(m² + n²)) time expected for curves in general position, O(d(m + n)) auxiliary
/// space, as [`intersections`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{intersections_with, Bezier, Point};
///
/// // Two crossing segments are flat at once: no halving, four orientation tests.
/// let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([1.0, 1.0])])?;
/// let c = Bezier::new(vec![Point::new([0.0, 1.0]), Point::new([1.0, 0.0])])?;
/// let mut counts = Counts::default();
/// assert_eq!(intersections_with(&b, &c, 1e-9, &mut counts)?.len(), 1);
/// assert_eq!((counts.arithmetic_operations, counts.orientation_tests), (0, 4));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn intersections_with<C: Counter>(
    b: &Bezier<f64, 2>,
    c: &Bezier<f64, 2>,
    tolerance: f64,
    counter: &mut C,
) -> Result<Vec<Intersection>> {
    validate_parameter(&tolerance, "tolerance")?;
    if tolerance <= 0.0 {
        return Err(Error::InvalidParameter {
            name: "tolerance",
            reason: format!("must be positive, got {tolerance}"),
        });
    }
    let mut search = Search {
        tolerance,
        pairs: 0,
        hits: Vec::new(),
        counter,
    };
    search.recurse(
        Piece {
            curve: b.clone(),
            lo: 0.0,
            hi: 1.0,
        },
        Piece {
            curve: c.clone(),
            lo: 0.0,
            hi: 1.0,
        },
        0,
    )?;
    let mut hits = search.hits;
    hits.sort_by(|x, y| x.s.total_cmp(&y.s));
    let mut out: Vec<Intersection> = Vec::with_capacity(hits.len());
    for h in hits {
        let point = b.eval(&h.s)?;
        let near = |o: &Intersection| (o.point - point).norm_squared().sqrt() <= tolerance;
        if !out.iter().any(near) {
            out.push(Intersection { point, ..h });
        }
    }
    Ok(out)
}

/// A piece of a curve: its control points over the parameter interval [lo, hi].
struct Piece {
    curve: Bezier<f64, 2>,
    lo: f64,
    hi: f64,
}

struct Search<'c, C> {
    tolerance: f64,
    pairs: usize,
    hits: Vec<Intersection>,
    counter: &'c mut C,
}

/// Halvings beyond which a piece counts as flat whatever its bound says (f64 rounding can
/// keep the bound of a tiny piece above a tolerance near the coordinates' precision).
const MAX_DEPTH: usize = 60;

impl<C: Counter> Search<'_, C> {
    fn recurse(&mut self, b: Piece, c: Piece, depth: usize) -> Result<()> {
        self.pairs += 1;
        if self.pairs > MAX_INTERSECTION_PAIRS {
            return Err(Error::InvalidParameter {
                name: "tolerance",
                reason: format!(
                    "more than MAX_INTERSECTION_PAIRS = {MAX_INTERSECTION_PAIRS} pairs of pieces overlap: the curves share a piece, or the tolerance is too small"
                ),
            });
        }
        if !boxes_overlap(b.curve.control(), c.curve.control()) {
            return Ok(());
        }
        let flat =
            |p: &Piece| depth >= MAX_DEPTH || flatness_bound(p.curve.control()) <= self.tolerance;
        if !flat(&b) {
            let (l, r) = halve(&b, self.counter);
            self.recurse(l, clone_piece(&c), depth + 1)?;
            return self.recurse(r, c, depth + 1);
        }
        if !flat(&c) {
            let (l, r) = halve(&c, self.counter);
            self.recurse(clone_piece(&b), l, depth + 1)?;
            return self.recurse(b, r, depth + 1);
        }
        if let Some((alpha, beta)) = chord_crossing(&b, &c, self.counter) {
            self.hits.push(Intersection {
                s: b.lo + alpha * (b.hi - b.lo),
                t: c.lo + beta * (c.hi - c.lo),
                point: Point::zero(),
            });
        }
        Ok(())
    }
}

fn clone_piece(p: &Piece) -> Piece {
    Piece {
        curve: p.curve.clone(),
        lo: p.lo,
        hi: p.hi,
    }
}

fn halve<C: Counter>(p: &Piece, counter: &mut C) -> (Piece, Piece) {
    let (l, r) = p.curve.split_counted(&0.5, counter);
    let mid = 0.5 * (p.lo + p.hi);
    (
        Piece {
            curve: l,
            lo: p.lo,
            hi: mid,
        },
        Piece {
            curve: r,
            lo: mid,
            hi: p.hi,
        },
    )
}

fn boxes_overlap(b: &[Point<f64, 2>], c: &[Point<f64, 2>]) -> bool {
    let (blo, bhi) = bounding_box_of(b);
    let (clo, chi) = bounding_box_of(c);
    (0..2).all(|j| blo[j] <= chi[j] && clo[j] <= bhi[j])
}

/// Where the chords of two flat pieces meet, as local parameters (α on b's chord, β on
/// c's), if they do. The decision is exact; α and β are rounded.
fn chord_crossing<C: Counter>(b: &Piece, c: &Piece, counter: &mut C) -> Option<(f64, f64)> {
    let end = |p: &Piece, last: bool| -> Point2 {
        let ctrl = p.curve.control();
        (if last { ctrl[ctrl.len() - 1] } else { ctrl[0] }).into()
    };
    let (b0, b1, c0, c1) = (end(b, false), end(b, true), end(c, false), end(c, true));
    let o1 = counter.orient2d(b0, b1, c0);
    let o2 = counter.orient2d(b0, b1, c1);
    let o3 = counter.orient2d(c0, c1, b0);
    let o4 = counter.orient2d(c0, c1, b1);
    let opposite_or_touching = |x: Orientation, y: Orientation| {
        x == Orientation::Collinear || y == Orientation::Collinear || x != y
    };
    if !opposite_or_touching(o1, o2) || !opposite_or_touching(o3, o4) {
        return None;
    }
    let (db, dc, w) = (
        (b1.x - b0.x, b1.y - b0.y),
        (c1.x - c0.x, c1.y - c0.y),
        (c0.x - b0.x, c0.y - b0.y),
    );
    let cross = |u: (f64, f64), v: (f64, f64)| u.0 * v.1 - u.1 * v.0;
    let den = cross(db, dc);
    if [o1, o2, o3, o4]
        .iter()
        .all(|&o| o == Orientation::Collinear)
    {
        return collinear_overlap(b0, b1, c0, c1);
    }
    if den == 0.0 {
        // Touching at an end point while the rounded denominator vanished: use the end.
        return Some(touching_end(o1, o2, o3, o4));
    }
    let alpha = (cross(w, dc) / den).clamp(0.0, 1.0);
    let beta = (cross(w, db) / den).clamp(0.0, 1.0);
    Some((alpha, beta))
}

fn touching_end(o1: Orientation, o2: Orientation, o3: Orientation, o4: Orientation) -> (f64, f64) {
    let col = Orientation::Collinear;
    match (o1 == col, o2 == col, o3 == col, o4 == col) {
        (_, _, true, _) => (0.0, 0.5),
        (_, _, _, true) => (1.0, 0.5),
        (true, _, _, _) => (0.5, 0.0),
        _ => (0.5, 1.0),
    }
}

/// Two chords on one line: the middle of their common part, if they share one.
fn collinear_overlap(b0: Point2, b1: Point2, c0: Point2, c1: Point2) -> Option<(f64, f64)> {
    // Project on the axis along which b's chord is longer (both chords lie on one line).
    let axis = if (b1.x - b0.x).abs() >= (b1.y - b0.y).abs() {
        0
    } else {
        1
    };
    let coord = |p: Point2| if axis == 0 { p.x } else { p.y };
    let (bl, bh) = (coord(b0).min(coord(b1)), coord(b0).max(coord(b1)));
    let (cl, ch) = (coord(c0).min(coord(c1)), coord(c0).max(coord(c1)));
    let (lo, hi) = (bl.max(cl), bh.min(ch));
    if lo > hi {
        return None;
    }
    let mid = 0.5 * (lo + hi);
    let param = |a: f64, z: f64| {
        if z == a {
            0.0
        } else {
            ((mid - a) / (z - a)).clamp(0.0, 1.0)
        }
    };
    Some((param(coord(b0), coord(b1)), param(coord(c0), coord(c1))))
}
