//! Delaunay triangulations (compact half-edge arrays, exact predicates, an exact checker) and
//! the Voronoi diagram as their dual.
//!
//! The course ([RD, §2.4] "Problemas de proximidad", "Diagrama de
//! Voronoi" and "Triangulación de Delaunay", Definition 2.34 and Theorem 2.35) defines the
//! Delaunay triangulation as the dual of the Voronoi diagram for points in general
//! position: the triangles whose circumcircles hold no other point. compgeo does not assume
//! general position: with four or more cocircular points any triangulation of their
//! polygon is Delaunay, and compgeo returns one of them.
//!
//! # One output for every builder
//!
//! Every builder returns a [`Triangulation`]: counter-clockwise triangles as flat index
//! arrays (`triangles`, `halfedges`, `hull`, as delaunator lays them out) plus the merged
//! `duplicates`. Every geometric decision is one of the exact predicates of
//! [`crate::geometry`] ([`orient2d`](crate::geometry::orient2d) and
//! [`incircle`](crate::geometry::incircle)), so the result is an exact Delaunay
//! triangulation for every finite input, 1e300 and subnormals in one set included.
//!
//! | input | result |
//! |---|---|
//! | NaN or infinite coordinate | [`Error::NonFinite`](crate::Error::NonFinite) (the plain functions; the `_with` ones take a validated [`PointSet`]) |
//! | a point equal to an earlier one | merged, listed as `[dropped, kept]` in `duplicates` |
//! | fewer than 3 distinct points, or all collinear | no triangles; `hull` = the distinct points along their line |
//! | otherwise | `2n - 2 - h` triangles for n distinct points, h of them on the hull boundary |
//!
//! [`check_delaunay`] verifies all of this exactly; the tests run it on every builder.
//!
//! | builder | time | file |
//! |---|---|---|
//! | [`incremental`] | O(n log n) expected on every input | `incremental.rs` (+ `hilbert.rs`, its insertion order) |
//! | [`divide_and_conquer`] | O(n log n) worst case (the course's algorithm) | `divide_conquer.rs` (+ `quad_edge.rs`, its working structure) |
//! | [`lawson`] | O(n²) worst case (flips from a sweep triangulation; for teaching; [`lawson_trace`] records each flip) | `lawson.rs` |
//! | [`fortune`] | O(n log n) expected on every input (Fortune's sweep, the Voronoi diagram first; [`fortune_trace`] records each event) | `fortune.rs` (+ `beach_line.rs`, its treap; `event_queue.rs`, its buckets and heap; exact predicates in `geometry/sweep_predicates.rs`) |
//!
//! # On top of the triangulation
//!
//! | problem | function | file |
//! |---|---|---|
//! | Voronoi diagram: cells with rays, clipping to a box | [`voronoi`], [`dual`], [`ClipBox`], [`ClippedCells`] | `voronoi.rs`, `clip.rs` |
//!
//! The proximity problems built on the triangulation (nearest neighbours, closest pair,
//! Euclidean minimum spanning tree, largest empty circle) are in [`crate::proximity`].
//!
//! ```
//! use compgeo::delaunay::{check_delaunay, triangulate, Algorithm};
//! use compgeo::geometry::Point2;
//!
//! let pts = [(0.0, 0.0), (3.0, 0.0), (0.0, 3.0), (3.0, 3.0), (1.0, 2.0)].map(Point2::from);
//! let t = triangulate(&pts, Algorithm::Incremental)?;
//! assert_eq!(t.triangle_count(), 4);
//! assert_eq!(t.hull, [0, 1, 3, 2]);
//! assert!(check_delaunay(&pts, &t).is_ok());
//! # Ok::<(), compgeo::Error>(())
//! ```

mod beach_line;
mod check;
mod clip;
mod divide_conquer;
mod event_queue;
mod fortune;
mod hilbert;
mod incremental;
mod lawson;
mod partition;
mod quad_edge;
mod triangulation;
mod voronoi;

pub use check::{check_delaunay, check_delaunay_with};
pub use clip::{ClipBox, ClippedCells, ClippedPolygon};
pub use divide_conquer::{divide_and_conquer, divide_and_conquer_with};
pub use fortune::{fortune, fortune_trace, fortune_with, FortuneStep};
pub(crate) use hilbert::{curve_order, grid_scale};
pub use incremental::{incremental, incremental_with};
pub use lawson::{lawson, lawson_trace, lawson_with, LawsonStep};
pub use triangulation::{find_duplicates, next_halfedge, prev_halfedge, Triangulation, EMPTY};
pub use voronoi::{dual, voronoi, voronoi_with, Cell, Ray, Voronoi};

use crate::complexity::{algorithm_family, Declaration};
use crate::count::{Counter, NoCount};
use crate::error::Result;
use crate::geometry::{Point2, PointSet};

/// The algorithms on a triangulation that are not a choice among builders: the Voronoi
/// diagram as the dual, and the exact checker.
pub(crate) const DECLARATIONS: [&Declaration; 2] = [VORONOI, CHECK];

/// The exact checker's declaration.
pub(crate) const CHECK: &Declaration = &check::DECLARATION;

/// The Voronoi diagram's declaration.
pub(crate) const VORONOI: &Declaration = &voronoi::DECLARATION;

algorithm_family! {
    /// The Delaunay builders, for callers that choose one at run time ([`triangulate`]).
    ///
    /// ```
    /// use compgeo::delaunay::Algorithm;
    ///
    /// let a: Algorithm = "incremental".parse()?;
    /// assert_eq!(a, Algorithm::Incremental);
    /// assert_eq!(a.name(), "incremental");
    /// assert!("sweep".parse::<Algorithm>().is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum Algorithm ("Delaunay algorithm") {
        /// [`incremental`]: BRIO + Hilbert order, walking location, Lawson flips.
        Incremental = incremental::DECLARATION => incremental_with,
        /// [`divide_and_conquer`]: the course's divide and conquer with Guibas and Stolfi's
        /// merge.
        DivideAndConquer = divide_conquer::DECLARATION => divide_and_conquer_with,
        /// [`lawson`]: a sweep triangulation, then Lawson's flips (O(n²), for teaching).
        Lawson = lawson::DECLARATION => lawson_with,
        /// [`fortune`]: Fortune's sweep with a beach line, the Voronoi diagram first.
        Fortune = fortune::DECLARATION => fortune_with,
    }
    fn run_with[C: Counter](points: &PointSet<'_>, counter: &mut C) -> Result<Triangulation>;
}

/// The Delaunay triangulation of `points` by `algorithm`: the same as calling its function.
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate (and the builder's own errors, see its docs).
///
/// # Complexity
/// That of the chosen builder ([`Algorithm::declaration`]).
///
/// ```
/// use compgeo::delaunay::{triangulate, Algorithm};
/// use compgeo::geometry::Point2;
///
/// let pts = [Point2::new(0.0, 0.0), Point2::new(1.0, 1.0), Point2::new(f64::NAN, 0.0)];
/// assert!(triangulate(&pts, Algorithm::Incremental).is_err());
/// ```
pub fn triangulate(points: &[Point2], algorithm: Algorithm) -> Result<Triangulation> {
    triangulate_with(&PointSet::new(points)?, algorithm, &mut NoCount)
}

/// [`triangulate`] on a validated point set, recording the builder's orientation and
/// in-circle tests (and comparisons) in `counter`.
///
/// # Errors
/// The builder's own errors (a point set beyond its size limit).
///
/// # Complexity
/// That of the chosen builder ([`Algorithm::declaration`]).
pub fn triangulate_with<C: Counter>(
    points: &PointSet<'_>,
    algorithm: Algorithm,
    counter: &mut C,
) -> Result<Triangulation> {
    algorithm.run_with(points, counter)
}
