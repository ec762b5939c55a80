//! Convex hulls of finite point sets: the course's algorithms and the output-sensitive ones.
//!
//! The course ([RD, §2.2], "Cierre Convexo de una nube de puntos") teaches brute force,
//! Jarvis's march, Graham's scan, its lexicographic variant (Andrew's monotone chain) and the
//! Akl–Toussaint filter; Quickhull is here as the peer crates' default, and Chan's algorithm as
//! the optimal output-sensitive one. The course assumes no three points collinear; compgeo
//! does not.
//!
//! | algorithm | file |
//! |---|---|
//! | [`brute_force_hull`] | `brute_force.rs` |
//! | [`jarvis_march`] (its steps: [`jarvis_trace`]) | `jarvis.rs` |
//! | [`graham_scan`] (its steps: [`graham_trace`]) | `graham.rs` |
//! | [`monotone_chain`] (its steps: [`monotone_chain_trace`]) | `monotone_chain.rs` |
//! | [`akl_toussaint`] (and its filter [`akl_toussaint_filter`]) | `akl_toussaint.rs` |
//! | [`quickhull`] (its steps: [`quickhull_trace`]) | `quickhull.rs` |
//! | [`chan`] | `chan.rs` |
//!
//! Their bounds are in the crate's [algorithm table](crate#algorithms-and-their-bounds), from
//! each algorithm's [`Declaration`](crate::complexity::Declaration); every function's docs
//! state them under `# Complexity`.
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
//! hull is exact for every finite input, including 1e300 and subnormals in one set. The
//! `_with` functions take a validated [`PointSet`]; the plain ones take a slice and reject
//! NaN and infinities with [`Error::NonFinite`](crate::Error::NonFinite).
//!
//! [`check_strictly_convex_ccw`] and [`check_encloses`] check a result exactly; tests and debug
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

use crate::complexity::algorithm_family;
use crate::count::{Counter, NoCount};
use crate::error::Result;
use crate::geometry::{Point2, PointSet};

mod akl_toussaint;
mod brute_force;
mod chan;
mod check;
mod collinear;
mod graham;
mod jarvis;
mod lex;
mod monotone_chain;
mod quickhull;

pub use akl_toussaint::{akl_toussaint, akl_toussaint_filter, akl_toussaint_with};
pub use brute_force::{brute_force_hull, brute_force_hull_with};
pub use chan::{chan, chan_with};
pub use check::{check_encloses, check_strictly_convex_ccw};
pub use graham::{graham_scan, graham_scan_with, graham_trace, GrahamStep};
pub use jarvis::{jarvis_march, jarvis_march_with, jarvis_trace, JarvisStep};
pub use monotone_chain::{
    monotone_chain, monotone_chain_trace, monotone_chain_with, Chain, ChainStep,
};
pub use quickhull::{quickhull, quickhull_trace, quickhull_with, QuickhullStep};

/// Options shared by every hull algorithm.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct HullOptions {
    /// Also report the input points that lie on the hull's boundary between two vertices,
    /// in boundary order (default `false`: only the strictly convex vertices).
    pub keep_collinear: bool,
}

algorithm_family! {
    /// The hull algorithms, for callers that choose one at run time ([`convex_hull`]).
    ///
    /// ```
    /// use compgeo::hull::Algorithm;
    ///
    /// let a: Algorithm = "graham".parse()?;
    /// assert_eq!(a, Algorithm::Graham);
    /// assert_eq!(a.name(), "graham");
    /// assert_eq!(a.declaration().time, "O(n log n)");
    /// assert!("gift".parse::<Algorithm>().is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum Algorithm ("hull algorithm") {
        /// [`brute_force_hull`]: every pair tested against every point.
        BruteForce = brute_force::DECLARATION => brute_force_hull_with,
        /// [`jarvis_march`]: gift wrapping.
        Jarvis = jarvis::DECLARATION => jarvis_march_with,
        /// [`graham_scan`]: angular sort about the lexicographically smallest point, then the
        /// scan.
        Graham = graham::DECLARATION => graham_scan_with,
        /// [`monotone_chain`]: lexicographic sort, lower and upper chains (the course's
        /// variant of Graham's scan).
        MonotoneChain = monotone_chain::DECLARATION => monotone_chain_with,
        /// [`akl_toussaint`]: the eight-extreme-point filter, then the monotone chain.
        AklToussaint = akl_toussaint::DECLARATION => akl_toussaint_with,
        /// [`quickhull`]: divide by the farthest point from each edge.
        Quickhull = quickhull::DECLARATION => quickhull_with,
        /// [`chan`]: group hulls, then wrapping with tangent searches.
        Chan = chan::DECLARATION => chan_with,
    }
    fn run_with[C: Counter](points: &PointSet<'_>, options: HullOptions, counter: &mut C)
        -> Vec<usize>;
}

/// The convex hull of `points` by `algorithm`: the same as calling its function.
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// That of the chosen algorithm ([`Algorithm::declaration`]).
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
    Ok(convex_hull_with(
        &PointSet::new(points)?,
        algorithm,
        options,
        &mut NoCount,
    ))
}

/// The convex hull of the validated `points` by `algorithm`, recording its operations in
/// `counter`.
///
/// # Complexity
///
/// That of the chosen algorithm ([`Algorithm::declaration`]).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{convex_hull_with, Algorithm, HullOptions};
///
/// let pts = [(0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (0.0, 2.0)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// let hull = convex_hull_with(&set, Algorithm::Graham, HullOptions::default(), &mut counts);
/// assert_eq!(hull, [0, 1, 3]);
/// assert!(counts.orientation_tests > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn convex_hull_with<C: Counter>(
    points: &PointSet<'_>,
    algorithm: Algorithm,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    algorithm.run_with(points, options, counter)
}
