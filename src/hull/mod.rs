//! Convex hulls of finite point sets: the seed's algorithms and the output-sensitive ones.
//!
//! The seed (`003_5b666ee3e15e6353.txt`, §2.2 "Cierre Convexo de una nube de puntos")
//! teaches brute force, Jarvis's march, Graham's scan, its lexicographic variant (Andrew's
//! monotone chain) and the Akl–Toussaint filter; Quickhull is here as the peer crates'
//! default, and Chan's algorithm as the optimal output-sensitive one. The seed assumes no three points collinear; compgeo does not.
//!
//! | algorithm | time | file |
//! |---|---|---|
//! | [`brute_force_hull`] | O(n³) | `brute_force.rs` |
//! | [`jarvis_march`] | O(nh) | `jarvis.rs` |
//! | [`graham_scan`] | O(n log n) | `graham.rs` |
//! | [`monotone_chain`] | O(n log n) | `monotone_chain.rs` |
//! | [`akl_toussaint`] | O(n log n), O(n) expected on uniform input | `akl_toussaint.rs` |
//! | [`quickhull`] | O(n²) worst, O(n log n) expected | `quickhull.rs` |
//! | [`chan`] | O(n log h) | `chan.rs` |
//!
//! n is the number of input points, h the number of hull vertices.
//!
//! # One output for every algorithm
//!
//! Every algorithm returns the same `Vec<usize>` for the same input: indices into the input
//! of the hull's vertices, counter-clockwise, starting at the lexicographically smallest
//! point (smallest x, then smallest y). A point that occurs several times is reported by the
//! index of its first occurrence. By default the hull is strictly convex (a point in the
//! middle of a hull edge is not a vertex); [`HullOptions::keep_collinear`] also lists the
//! points on the boundary, in boundary order. Degenerate input is valid:
//!
//! | input | hull |
//! |---|---|
//! | no points | `[]` |
//! | one point, or all points equal | `[i]` |
//! | all points on one line | the two extreme points `[lexmin, lexmax]` (with `keep_collinear`, every distinct point from lexmin to lexmax) |
//!
//! Every geometric decision is one of the exact predicates of [`crate::geometry`], so the
//! hull is exact for every finite input, including 1e300 and subnormals in one set. NaN and
//! infinities give [`Error::NonFinite`].
//!
//! [`is_strictly_convex_ccw`] and [`encloses`] check a result exactly; tests and debug
//! builds use them.
//!
//! ```
//! use compgeo::geometry::Point2;
//! use compgeo::hull::{convex_hull, Algorithm, HullOptions};
//!
//! let pts: Vec<Point2> = [(0.0, 0.0), (2.0, 0.0), (1.0, 1.0), (2.0, 2.0), (0.0, 2.0), (1.0, 0.0)]
//!     .map(Point2::from)
//!     .to_vec();
//! for algorithm in Algorithm::ALL {
//!     assert_eq!(convex_hull(&pts, algorithm, HullOptions::default())?, [0, 1, 3, 4]);
//! }
//! let keep = HullOptions { keep_collinear: true };
//! assert_eq!(convex_hull(&pts, Algorithm::MonotoneChain, keep)?, [0, 5, 1, 3, 4]);
//! # Ok::<(), compgeo::Error>(())
//! ```

use crate::count::Counter;
use crate::error::{Error, Result};
use crate::geometry::{CountedPredicates, Orientation, Point2};
use std::cmp::Ordering;
use std::fmt;
use std::str::FromStr;

mod akl_toussaint;
mod brute_force;
mod chan;
mod check;
mod collinear;
mod graham;
mod jarvis;
mod monotone_chain;
mod quickhull;

pub use akl_toussaint::{akl_toussaint, akl_toussaint_filter, akl_toussaint_with};
pub use brute_force::{brute_force_hull, brute_force_hull_with};
pub use chan::{chan, chan_with};
pub use check::{encloses, is_strictly_convex_ccw};
pub use graham::{graham_scan, graham_scan_with};
pub use jarvis::{jarvis_march, jarvis_march_with};
pub use monotone_chain::{monotone_chain, monotone_chain_with};
pub use quickhull::{quickhull, quickhull_with};

/// Options shared by every hull algorithm.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct HullOptions {
    /// Also report the input points that lie on the hull's boundary between two vertices,
    /// in boundary order (default `false`: only the strictly convex vertices).
    pub keep_collinear: bool,
}

/// The hull algorithms, for callers that choose one at run time.
///
/// ```
/// use compgeo::hull::Algorithm;
///
/// let a: Algorithm = "graham".parse()?;
/// assert_eq!(a, Algorithm::Graham);
/// assert_eq!(a.name(), "graham");
/// assert!("gift".parse::<Algorithm>().is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Algorithm {
    /// [`brute_force_hull`]: every pair tested against every point, O(n³).
    BruteForce,
    /// [`jarvis_march`]: gift wrapping, O(nh).
    Jarvis,
    /// [`graham_scan`]: angular sort about the lowest-leftmost point, then the scan.
    Graham,
    /// [`monotone_chain`]: lexicographic sort, lower and upper chains (the seed's variant).
    MonotoneChain,
    /// [`akl_toussaint`]: the eight-extreme-point filter, then the monotone chain.
    AklToussaint,
    /// [`quickhull`]: divide by the farthest point from each edge.
    Quickhull,
    /// [`chan`]: group hulls, then wrapping with tangent searches, O(n log h).
    Chan,
}

/// Runs `algorithm` on `points`: the same as calling its function.
///
/// # Errors
///
/// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate.
///
/// # Complexity
///
/// That of the chosen algorithm (see the [module docs](self)).
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{convex_hull, Algorithm, HullOptions};
///
/// let pts = [Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(f64::NAN, 0.0)];
/// assert!(convex_hull(&pts, Algorithm::Jarvis, HullOptions::default()).is_err());
/// ```
pub fn convex_hull(
    points: &[Point2],
    algorithm: Algorithm,
    options: HullOptions,
) -> Result<Vec<usize>> {
    algorithm.hull_with(points, options, &mut crate::count::NoCount)
}

impl Algorithm {
    /// Every algorithm, brute force first.
    pub const ALL: [Algorithm; 7] = [
        Algorithm::BruteForce,
        Algorithm::Jarvis,
        Algorithm::Graham,
        Algorithm::MonotoneChain,
        Algorithm::AklToussaint,
        Algorithm::Quickhull,
        Algorithm::Chan,
    ];

    /// The kebab-case name used on the command line: `"brute-force"`, `"jarvis"`,
    /// `"graham"`, `"monotone-chain"`, `"akl-toussaint"`, `"quickhull"`, `"chan"`.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::BruteForce => "brute-force",
            Algorithm::Jarvis => "jarvis",
            Algorithm::Graham => "graham",
            Algorithm::MonotoneChain => "monotone-chain",
            Algorithm::AklToussaint => "akl-toussaint",
            Algorithm::Quickhull => "quickhull",
            Algorithm::Chan => "chan",
        }
    }

    /// Runs this algorithm, recording its operations in `counter`.
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] naming the first point with a NaN or infinite coordinate.
    pub fn hull_with<C: Counter>(
        self,
        points: &[Point2],
        options: HullOptions,
        counter: &mut C,
    ) -> Result<Vec<usize>> {
        match self {
            Algorithm::BruteForce => brute_force_hull_with(points, options, counter),
            Algorithm::Jarvis => jarvis_march_with(points, options, counter),
            Algorithm::Graham => graham_scan_with(points, options, counter),
            Algorithm::MonotoneChain => monotone_chain_with(points, options, counter),
            Algorithm::AklToussaint => akl_toussaint_with(points, options, counter),
            Algorithm::Quickhull => quickhull_with(points, options, counter),
            Algorithm::Chan => chan_with(points, options, counter),
        }
    }
}

impl fmt::Display for Algorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Algorithm {
    type Err = Error;

    /// Parses a kebab-case name; an unknown name gives [`Error::InvalidParameter`] listing the
    /// valid ones.
    fn from_str(s: &str) -> Result<Self> {
        crate::error::algorithm_named(s, "hull algorithm", &Algorithm::ALL, Algorithm::name)
    }
}

/// The index of the lexicographically smallest point, the first one among equals.
/// `points` must not be empty.
fn lex_min<C: Counter>(points: &[Point2], counter: &mut C) -> usize {
    let mut best = 0;
    for i in 1..points.len() {
        if counter.cmp_lex(points[i], points[best]) == Ordering::Less {
            best = i;
        }
    }
    best
}

/// The points of `indices` with their indices, sorted lexicographically, each distinct point
/// kept once by its smallest index. The sort compares integer keys that order as
/// [`cmp_lex`](crate::geometry::cmp_lex) does (see [`lex_key`]), twice as fast as comparing
/// the coordinates on circle inputs; one key comparison is counted as one comparison, so
/// the counts are those of sorting by `cmp_lex`. `points` must be finite.
fn lex_sorted_items<C: Counter>(
    points: &[Point2],
    indices: impl Iterator<Item = usize>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    let mut keyed: Vec<(u128, usize)> = indices.map(|i| (lex_key(points[i]), i)).collect();
    keyed.sort_unstable_by(|a, b| {
        counter.comparison();
        a.cmp(b)
    });
    keyed.dedup_by(|b, a| {
        counter.comparison();
        a.0 == b.0
    });
    keyed.into_iter().map(|(_, i)| (points[i], i)).collect()
}

/// A 128-bit key whose integer order is the lexicographic order of finite points: the
/// order keys of x then y ([`crate::util::order_key`]) after mapping `-0.0` to `0.0`, which
/// `cmp_lex` treats as equal.
#[inline]
fn lex_key(p: Point2) -> u128 {
    let ordered = |v: f64| crate::util::order_key(v + 0.0);
    u128::from(ordered(p.x)) << 64 | u128::from(ordered(p.y))
}

/// Andrew's chains over `sorted`, distinct points in lexicographic order: the strictly
/// convex hull, counter-clockwise from `sorted[0]`, as indices into the input.
///
/// The points strictly below the line from the first to the last point go to the lower
/// chain, those strictly above to the upper one, the rest (on the line) to neither: each
/// chain scans only its own points.
fn chains<C: Counter>(sorted: &[(Point2, usize)], counter: &mut C) -> Vec<usize> {
    let m = sorted.len();
    if m <= 2 {
        return sorted.iter().map(|s| s.1).collect();
    }
    let (a, b) = (sorted[0].0, sorted[m - 1].0);
    // Sized up front: growing by pushes reallocates, which dominates on Chan's small groups.
    let mut lower = Vec::with_capacity(m);
    let mut upper = Vec::with_capacity(m);
    lower.push(sorted[0]);
    upper.push(sorted[m - 1]);
    for &item in &sorted[1..m - 1] {
        match counter.orient2d(a, b, item.0) {
            Orientation::Clockwise => lower.push(item),
            Orientation::CounterClockwise => upper.push(item),
            Orientation::Collinear => {}
        }
    }
    lower.push(sorted[m - 1]);
    upper.push(sorted[0]);
    let upper_last = upper.len() - 1;
    upper[1..upper_last].reverse();
    let mut hull = scan_chain(&lower, counter);
    hull.pop();
    let mut top = scan_chain(&upper, counter);
    top.pop();
    hull.extend(top);
    hull
}

/// Graham's scan over one chain whose points are all on one side of its end-to-end line:
/// the chain's strictly convex vertices, both ends included. The stack holds the points
/// themselves, so the scan reads them sequentially.
fn scan_chain<C: Counter>(chain: &[(Point2, usize)], counter: &mut C) -> Vec<usize> {
    let mut stack: Vec<(Point2, usize)> = Vec::with_capacity(chain.len());
    for &item in chain {
        push_left_turn(&mut stack, 2, item, |s| s.0, counter);
    }
    stack.into_iter().map(|s| s.1).collect()
}

/// Pops from `stack` while it holds at least `floor` items and the points (`point`) of its
/// last two do not turn strictly left towards `item`'s, then pushes `item`.
#[inline]
fn push_left_turn<T: Copy, C: Counter>(
    stack: &mut Vec<T>,
    floor: usize,
    item: T,
    point: impl Fn(T) -> Point2,
    counter: &mut C,
) {
    let p = point(item);
    while stack.len() >= floor {
        let (a, b) = (stack[stack.len() - 2], stack[stack.len() - 1]);
        if counter.orient2d(point(a), point(b), p) == Orientation::CounterClockwise {
            break;
        }
        stack.pop();
    }
    stack.push(item);
}

/// Applies the options to a strictly convex hull computed from `candidates` (a superset of
/// the boundary points).
fn finish<C: Counter>(
    points: &[Point2],
    candidates: impl Iterator<Item = usize>,
    strict: Vec<usize>,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    debug_assert!(is_strictly_convex_ccw(points, &strict));
    if options.keep_collinear {
        collinear::with_boundary_points(points, candidates, strict, counter)
    } else {
        strict
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::cmp_lex;

    /// The key order is `cmp_lex` on signed zeros, subnormals, huge values and neighbours.
    #[test]
    fn lex_key_orders_as_cmp_lex() {
        let values = [
            -f64::MAX,
            -1e300,
            -1.0,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            1e-310,
            f64::MIN_POSITIVE,
            1.0,
            1.0 + f64::EPSILON,
            1e300,
            f64::MAX,
        ];
        for &a in &values {
            for &b in &values {
                for &c in &values {
                    let (p, q) = (Point2::new(a, b), Point2::new(a, c));
                    let (r, s) = (Point2::new(a, b), Point2::new(c, b));
                    assert_eq!(lex_key(p).cmp(&lex_key(q)), cmp_lex(p, q), "{p:?} {q:?}");
                    assert_eq!(lex_key(r).cmp(&lex_key(s)), cmp_lex(r, s), "{r:?} {s:?}");
                }
            }
        }
    }
}
