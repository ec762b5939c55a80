//! The Akl–Toussaint heuristic: discard the points strictly inside the polygon of a few
//! extreme points, then run the monotone chain on the survivors.

use super::collinear::finish;
use super::lex::lex_sorted_items_by_comparisons;
use super::monotone_chain::chains;
use super::HullOptions;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "hull",
    name: "akl-toussaint",
    function: "hull::akl_toussaint",
    file: "src/hull/akl_toussaint.rs",
    summary: "the eight-extreme-point filter, then the monotone chain",
    time: "O(n log n) worst case, O(n) expected on uniform input",
    space: "O(n)",
    operation: Some(Operation::Comparisons),
    counts: "four per point for the filter box",
    source: "[RD, §2.2]",
    claims: &[on("uniform-square", Bound::Linear, Operation::Comparisons)],
};

/// The convex hull of `points` by the Akl–Toussaint filter and the monotone chain. See
/// [`akl_toussaint_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{akl_toussaint, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(akl_toussaint(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn akl_toussaint(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    Ok(akl_toussaint_with(
        &PointSet::new(points)?,
        options,
        &mut NoCount,
    ))
}

/// The convex hull of `points` by the Akl–Toussaint filter followed by the monotone chain,
/// recording its operations in `counter`; the fastest hull of this module on random input.
///
/// Idea: see [`akl_toussaint_filter`]; the survivors, a small fraction on most inputs, are
/// sorted and scanned as in [`monotone_chain`](super::monotone_chain), so only they are
/// sorted.
///
/// Follows [RD, §2.2] "Scan de Graham - Variante de Akl-Toussaint",
/// with the diagonal extremes added to the course's four.
///
/// Output convention and degenerate inputs: see the [module docs](super).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and s the number of survivors: time O(n + s log s), that is
/// O(n log n) worst case, O(n) expected on uniform input (points in convex position all
/// survive; uniform points in a square or disk leave few); auxiliary space O(n), O(s) beyond
/// the output.
///
/// # Counts
///
/// Those of [`akl_toussaint_filter`], plus the monotone chain's on the s survivors.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::PointSet;
/// use compgeo::hull::{akl_toussaint_with, monotone_chain, HullOptions};
///
/// let pts = points(PointKind::UniformSquare, 2000, 1)?;
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// let hull = akl_toussaint_with(&set, HullOptions::default(), &mut counts);
/// assert_eq!(hull, monotone_chain(&pts, HullOptions::default())?);
/// assert!(counts.orientation_tests < 2000); // most points never reach a predicate
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn akl_toussaint_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    let survivors = akl_toussaint_filter(points, counter);
    let points = points.points();
    // The comparison sort even with NoCount: the radix sort, which the monotone chain takes,
    // made this function no faster (median ratios 0.94–1.06 at 10³–10⁶ points on uniform,
    // gaussian and grid input, the survivors being few or, on a disk, a tenth of the points
    // spread over the whole input; see "Lexicographic sorts of points" in docs/design.md).
    #[cfg(feature = "parallel")]
    if C::DISCARDS && survivors.len() >= crate::parallel::THRESHOLD {
        // Many survivors (points near a circle): the parallel radix sort, which gives the
        // same order.
        let sorted = super::lex::lex_sorted_items(points, survivors.into_iter(), counter);
        let strict = chains(&sorted, counter);
        return finish(points, sorted.iter().map(|s| s.1), strict, options, counter);
    }
    let sorted = lex_sorted_items_by_comparisons(points, survivors.into_iter(), counter);
    let strict = chains(&sorted, counter);
    finish(points, sorted.iter().map(|s| s.1), strict, options, counter)
}

/// The indices, increasing, of the points of `points` that are not strictly inside the
/// polygon of its extreme points: a superset of every hull's boundary points, to put in
/// front of any hull algorithm.
///
/// Idea: the points with smallest and largest x, y, x + y and x − y are hull points (or
/// nearly so: the sums are rounded, which only makes the choice less good, never wrong), so
/// their convex hull, an exact polygon of up to eight input points, lies inside the hull, and a
/// point strictly inside it is no hull vertex and on no hull edge. Most points are discarded
/// without a predicate: an axis-parallel box whose corners are verified to be strictly inside
/// the polygon (exactly, with [`orient2d`](crate::geometry::orient2d)) discards the points
/// strictly inside it with four coordinate comparisons.
///
/// Follows [RD, §2.2] "Scan de Graham - Variante de Akl-Toussaint".
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()`: time Θ(n), auxiliary space O(s) for the s survivors.
///
/// # Counts
///
/// Comparisons: four per point for the box, and those of the polygon's construction;
/// orientation tests: per point outside the box, one per polygon edge facing a side of the box
/// it is beyond (at most eight), and at most 160 to verify the box.
///
/// ```
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::PointSet;
/// use compgeo::hull::{akl_toussaint_filter, graham_scan, HullOptions};
///
/// let pts = points(PointKind::UniformDisk, 5000, 3)?;
/// let set = PointSet::new(&pts)?;
/// let kept = akl_toussaint_filter(&set, &mut compgeo::count::NoCount);
/// assert!(kept.len() < 1000);
/// // Any algorithm on the survivors, mapped back, gives the hull of all points.
/// let sub: Vec<_> = kept.iter().map(|&i| pts[i]).collect();
/// let hull: Vec<usize> = graham_scan(&sub, HullOptions::default())?.iter().map(|&k| kept[k]).collect();
/// assert_eq!(hull, graham_scan(&pts, HullOptions::default())?);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn akl_toussaint_filter<C: Counter>(points: &PointSet, counter: &mut C) -> Vec<usize> {
    filter(points.points(), false, counter)
}

/// How many points [`filter`] tests before it may give up.
const FILTER_PROBE: usize = 1024;

/// [`akl_toussaint_filter`] on finite points. With `give_up` (Chan's hull, over all points
/// and then in each of its groups) it stops testing where filtering does not pay: if more
/// than three quarters of the first [`FILTER_PROBE`] points survive, the points in convex
/// position or nearly so, the rest is kept untested (a superset of the boundary points is
/// all Chan needs).
pub(super) fn filter<C: Counter>(points: &[Point2], give_up: bool, counter: &mut C) -> Vec<usize> {
    if points.len() < 4 {
        return (0..points.len()).collect();
    }
    let extremes = extremes(points);
    let corners = lex_sorted_items_by_comparisons(points, extremes.into_iter(), counter);
    let polygon: Vec<Point2> = chains(&corners, counter)
        .into_iter()
        .map(|i| points[i])
        .collect();
    if polygon.len() < 3 {
        return (0..points.len()).collect();
    }
    let facing = facing_sides(&polygon);
    let inner = inner_box(points, &extremes, &polygon, &facing, counter);
    let mut survivors = Vec::new();
    let mut from = 0;
    if give_up && points.len() > FILTER_PROBE {
        keep(
            &points[..FILTER_PROBE],
            0,
            &inner,
            &polygon,
            &facing,
            &mut survivors,
            counter,
        );
        if 4 * survivors.len() > 3 * FILTER_PROBE {
            survivors.extend(FILTER_PROBE..points.len());
            return survivors;
        }
        from = FILTER_PROBE;
    }
    let rest = &points[from..];
    #[cfg(feature = "parallel")]
    if C::DISCARDS && rest.len() >= crate::parallel::THRESHOLD {
        use rayon::prelude::*;
        // Chunks filtered at the same time, their survivors concatenated in order.
        let parts: Vec<Vec<usize>> = rest
            .par_chunks(CHUNK)
            .enumerate()
            .map(|(c, chunk)| {
                let mut kept = Vec::new();
                let (inner, polygon, facing) = (&inner, &polygon, &facing);
                keep(
                    chunk,
                    from + c * CHUNK,
                    inner,
                    polygon,
                    facing,
                    &mut kept,
                    &mut NoCount,
                );
                kept
            })
            .collect();
        survivors.extend(parts.into_iter().flatten());
        return survivors;
    }
    keep(
        rest,
        from,
        &inner,
        &polygon,
        &facing,
        &mut survivors,
        counter,
    );
    survivors
}

/// Points per task of the parallel filter and extremes (feature `parallel`).
#[cfg(feature = "parallel")]
const CHUNK: usize = 1 << 15;

/// Pushes onto `survivors` the indices (`points[k]` has index `offset + k`) of the points not
/// strictly inside `polygon`, those strictly inside the `inner` box discarded first.
fn keep<C: Counter>(
    points: &[Point2],
    offset: usize,
    inner: &Option<Box>,
    polygon: &[Point2],
    facing: &[u8],
    survivors: &mut Vec<usize>,
    counter: &mut C,
) {
    for (k, &p) in points.iter().enumerate() {
        let sides = match inner {
            Some(b) => match sides_outside(p, b, counter) {
                0 => continue,
                sides => sides,
            },
            None => ALL_SIDES,
        };
        if !strictly_inside(polygon, facing, sides, p, counter) {
            survivors.push(offset + k);
        }
    }
}

/// Bits of [`sides_outside`] and [`facing_sides`]: west, east, south, north.
const WEST: u8 = 1;
const EAST: u8 = 2;
const SOUTH: u8 = 4;
const NORTH: u8 = 8;
const ALL_SIDES: u8 = WEST | EAST | SOUTH | NORTH;

/// Per edge of the counter-clockwise `polygon` (from vertex k to k + 1), the sides its
/// outward normal `(Δy, −Δx)` points to, decided exactly by comparing coordinates: west when
/// the edge goes down, east when it goes up, south when it goes right, north when it goes
/// left.
fn facing_sides(polygon: &[Point2]) -> Vec<u8> {
    let h = polygon.len();
    (0..h)
        .map(|k| {
            let (a, c) = (polygon[k], polygon[(k + 1) % h]);
            let mut sides = 0;
            if c.y < a.y {
                sides |= WEST;
            }
            if c.y > a.y {
                sides |= EAST;
            }
            if c.x > a.x {
                sides |= SOUTH;
            }
            if c.x < a.x {
                sides |= NORTH;
            }
            sides
        })
        .collect()
}

/// The sides of the box `b` that `p` is on or beyond (0 when strictly inside): four
/// comparisons.
#[inline]
fn sides_outside<C: Counter>(p: Point2, b: &Box, counter: &mut C) -> u8 {
    for _ in 0..4 {
        counter.comparison();
    }
    (u8::from(p.x <= b[0]) * WEST)
        | (u8::from(p.x >= b[1]) * EAST)
        | (u8::from(p.y <= b[2]) * SOUTH)
        | (u8::from(p.y >= b[3]) * NORTH)
}

/// An axis-parallel box `[x_lo, x_hi, y_lo, y_hi]`.
type Box = [f64; 4];

/// The indices of the points with smallest and largest x, y, x + y and x − y (the first of
/// equals; sums that overflow compare as infinities, which only makes the choice less good).
fn extremes(points: &[Point2]) -> [usize; 8] {
    #[cfg(feature = "parallel")]
    if points.len() >= crate::parallel::THRESHOLD {
        use rayon::prelude::*;
        // Per chunk at the same time, then combined in input order with the same strict
        // comparisons, so the first of equals is still chosen.
        let parts: Vec<Extremes> = points
            .par_chunks(CHUNK)
            .enumerate()
            .map(|(c, chunk)| chunk_extremes(chunk, c * CHUNK))
            .collect();
        let mut all = parts[0];
        for part in &parts[1..] {
            all.absorb(part);
        }
        return all.indices();
    }
    chunk_extremes(points, 0).indices()
}

/// The smallest and largest keys x, y, x + y, x − y of some points and the indices where
/// they were first met.
#[derive(Clone, Copy)]
struct Extremes {
    lo: [f64; 4],
    hi: [f64; 4],
    lo_at: [usize; 4],
    hi_at: [usize; 4],
}

impl Extremes {
    /// Takes the keys of `other`, points met later, where they are strictly more extreme.
    #[cfg(feature = "parallel")]
    fn absorb(&mut self, other: &Extremes) {
        for d in 0..4 {
            if other.lo[d] < self.lo[d] {
                self.lo[d] = other.lo[d];
                self.lo_at[d] = other.lo_at[d];
            }
            if other.hi[d] > self.hi[d] {
                self.hi[d] = other.hi[d];
                self.hi_at[d] = other.hi_at[d];
            }
        }
    }

    fn indices(&self) -> [usize; 8] {
        let (lo, hi) = (self.lo_at, self.hi_at);
        [lo[0], lo[1], lo[2], lo[3], hi[0], hi[1], hi[2], hi[3]]
    }
}

/// The [`Extremes`] of the non-empty `points`, the first having index `offset`.
fn chunk_extremes(points: &[Point2], offset: usize) -> Extremes {
    let key = |p: Point2| [p.x, p.y, p.x + p.y, p.x - p.y];
    let first = key(points[0]);
    let mut e = Extremes {
        lo: first,
        hi: first,
        lo_at: [offset; 4],
        hi_at: [offset; 4],
    };
    for (k, &p) in points.iter().enumerate() {
        for (d, value) in key(p).into_iter().enumerate() {
            if value < e.lo[d] {
                e.lo[d] = value;
                e.lo_at[d] = offset + k;
            }
            if value > e.hi[d] {
                e.hi[d] = value;
                e.hi_at[d] = offset + k;
            }
        }
    }
    e
}

/// The largest box spanned by the diagonal extremes, if its corners are strictly inside
/// `polygon` (checked exactly).
fn inner_box<C: Counter>(
    points: &[Point2],
    extremes: &[usize; 8],
    polygon: &[Point2],
    facing: &[u8],
    counter: &mut C,
) -> Option<Box> {
    // extremes: min x+y (south-west), min x−y (north-west), max x+y (north-east),
    // max x−y (south-east).
    let [sw, nw, ne, se] = [2, 3, 6, 7].map(|k| points[extremes[k]]);
    let widest = [
        sw.x.max(nw.x),
        ne.x.min(se.x),
        sw.y.max(se.y),
        nw.y.min(ne.y),
    ];
    let (w, h) = (widest[1] - widest[0], widest[3] - widest[2]);
    if !(w > 0.0 && h > 0.0 && w.is_finite() && h.is_finite()) {
        return None;
    }
    // The widest box may poke out of the polygon by a hair; shrink it until it does not.
    [0.0, 1.0 / 256.0, 1.0 / 32.0, 1.0 / 8.0, 1.0 / 4.0]
        .into_iter()
        .map(|t| {
            [
                widest[0] + t * w,
                widest[1] - t * w,
                widest[2] + t * h,
                widest[3] - t * h,
            ]
        })
        .find(|b| {
            b[0] < b[1]
                && b[2] < b[3]
                && [(b[0], b[2]), (b[1], b[2]), (b[1], b[3]), (b[0], b[3])]
                    .into_iter()
                    .all(|c| strictly_inside(polygon, facing, ALL_SIDES, c.into(), counter))
        })
}

/// Whether `p` is strictly left of every edge of the counter-clockwise convex `polygon`,
/// testing only the edges that face one of `sides` (`facing` from [`facing_sides`]).
///
/// A point on or beyond the west side of a box strictly inside the polygon, and not beyond
/// the other sides, is the point q on that side moved west: moving west cannot take it out
/// through an edge whose outward normal has no westward part, so only the west-facing edges
/// can have it outside; likewise for the other sides and their unions. With every side this
/// tests every edge.
#[inline]
fn strictly_inside<C: Counter>(
    polygon: &[Point2],
    facing: &[u8],
    sides: u8,
    p: Point2,
    counter: &mut C,
) -> bool {
    let h = polygon.len();
    (0..h).all(|k| {
        facing[k] & sides == 0
            || counter.orient2d(polygon[k], polygon[(k + 1) % h], p)
                == Orientation::CounterClockwise
    })
}
