//! Nearest-neighbour queries: a greedy walk on the Delaunay graph towards the query.

use super::{adjacency, at_least, delaunay_edges};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::delaunay::{incremental_with, Triangulation};
use crate::error::{Error, Result};
use crate::geometry::{CountedPredicates, Point2, PointSet};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "nearest",
    name: "delaunay-walk",
    function: "proximity::NearestSearch::nearest",
    file: "src/proximity/nearest.rs",
    summary: "a greedy walk on the Delaunay graph towards the query",
    time: "O(n log n) to build; O(√n) expected steps per query on uniform points",
    space: "O(n)",
    operation: Some(Operation::DistanceEvaluations),
    counts: "one per neighbour looked at during a walk, about six per step",
    source: "[RD, §2.4]",
    claims: &[
        on(
            "uniform-square",
            Bound::Sqrt,
            Operation::DistanceEvaluations,
        ),
        on(
            "random-queries",
            Bound::Linear,
            Operation::DistanceEvaluations,
        ),
    ],
};

/// Nearest-neighbour queries on a fixed point set: a Delaunay triangulation and the
/// adjacency of its vertices, built once.
///
/// ```
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::proximity::NearestSearch;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (0.0, 4.0), (4.0, 4.0), (2.0, 2.0)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let search = NearestSearch::new(&set)?;
/// assert_eq!(search.nearest(Point2::new(3.5, 0.2))?, 1);
/// assert_eq!(search.nearest(Point2::new(2.1, 1.9))?, 4);
/// assert_eq!(search.nearest(Point2::new(-100.0, 50.0))?, 2); // outside the hull
/// assert!(search.nearest(Point2::new(f64::NAN, 0.0)).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct NearestSearch<'a> {
    points: &'a [Point2],
    graph: DelaunayGraph,
}

/// The part of a [`NearestSearch`] that owns its data: the adjacency of the Delaunay graph
/// and the vertex a walk starts from. The catalog keeps one next to its own copy of the
/// points, since a workload's input cannot borrow.
#[derive(Debug, Clone)]
pub(crate) struct DelaunayGraph {
    start: usize,
    offsets: Vec<usize>,
    neighbours: Vec<usize>,
}

impl<'a> NearestSearch<'a> {
    /// Triangulates `points` (the [`incremental`](crate::delaunay::incremental) builder) and indexes
    /// them for queries.
    ///
    /// # Errors
    /// [`Error::TooFew`] for no points, and the builder's size limit.
    ///
    /// # Complexity
    /// O(n log n) to build: O(n log n) expected time, O(n) space.
    pub fn new(points: &PointSet<'a>) -> Result<NearestSearch<'a>> {
        at_least(1, points.len())?;
        let t = incremental_with(points, &mut NoCount)?;
        Ok(NearestSearch::from_triangulation(points, &t))
    }

    /// Indexes `points` with their Delaunay triangulation `t` (from one of the crate's
    /// builders; with another triangulation the greedy walk can stop at a wrong answer).
    ///
    /// # Complexity
    /// O(n + t) time and space.
    pub fn from_triangulation(points: &PointSet<'a>, t: &Triangulation) -> NearestSearch<'a> {
        NearestSearch {
            points: points.points(),
            graph: DelaunayGraph::new(points.len(), t),
        }
    }

    /// The index of a point nearest to `query`; see [`nearest_with`](Self::nearest_with).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"query"`) if a coordinate of `query` is NaN or
    /// infinite.
    ///
    /// # Complexity
    /// O(d) time per step of the walk, where d is the degree of the current vertex: O(n log n)
    /// to build; O(√n) expected steps per query on uniform points, O(n) in the worst case.
    pub fn nearest(&self, query: Point2) -> Result<usize> {
        self.nearest_with(query, None, &mut NoCount)
    }

    /// The index of a point nearest to `query`, by a greedy walk on the Delaunay graph from
    /// `start` (or a hull vertex), counting its distance evaluations.
    ///
    /// The idea ([RD, §2.4], problem 4 "El vecino más cercano": find the
    /// Voronoi region holding the query): from the current site move to its Delaunay
    /// neighbour nearest to the query while that one is strictly nearer. A site that is not
    /// a nearest one always has a strictly nearer Delaunay neighbour (the segment from it to
    /// the query leaves its Voronoi cell through an edge shared with a neighbour, which is
    /// then nearer), so the walk ends at a nearest site, inside the hull or not. Ties: any
    /// nearest site may be returned. The answer is never a merged duplicate (it is the
    /// point with the smallest index among equal ones).
    ///
    /// # Errors
    /// As [`nearest`](Self::nearest); also [`Error::InvalidParameter`] (name `"start"`) if
    /// `start` is not the index of a point kept by the triangulation.
    ///
    /// # Complexity
    /// As [`nearest`](Self::nearest). Starting at the previous answer makes a sequence of
    /// nearby queries cheap.
    ///
    /// # Counts
    /// One distance evaluation per neighbour looked at.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::gen::{points, PointKind};
    /// use compgeo::geometry::{Point2, PointSet};
    /// use compgeo::proximity::NearestSearch;
    ///
    /// let pts = points(PointKind::UniformSquare, 2000, 7)?;
    /// let set = PointSet::new(&pts)?;
    /// let search = NearestSearch::new(&set)?;
    /// let mut counts = Counts::default();
    /// let q = Point2::new(0.5, 0.5);
    /// let i = search.nearest_with(q, None, &mut counts)?;
    /// assert!(counts.distance_evaluations < 2000);
    /// assert!(pts.iter().all(|p| (p.x - q.x).hypot(p.y - q.y) >= (pts[i].x - q.x).hypot(pts[i].y - q.y)));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn nearest_with<C: Counter>(
        &self,
        query: Point2,
        start: Option<usize>,
        counter: &mut C,
    ) -> Result<usize> {
        self.graph.walk(self.points, query, start, counter)
    }
}

impl DelaunayGraph {
    /// The adjacency of the Delaunay graph of `n` points triangulated by `t`, and a hull
    /// vertex to start from.
    pub(crate) fn new(n: usize, t: &Triangulation) -> DelaunayGraph {
        let edges = delaunay_edges(t);
        let (offsets, neighbours) = adjacency(n, &edges);
        let start = t.hull.first().copied().unwrap_or(0);
        DelaunayGraph {
            start,
            offsets,
            neighbours,
        }
    }

    /// [`NearestSearch::nearest_with`] on the graph of `p`.
    pub(crate) fn walk<C: Counter>(
        &self,
        p: &[Point2],
        query: Point2,
        start: Option<usize>,
        counter: &mut C,
    ) -> Result<usize> {
        if !query.is_finite() {
            return Err(Error::InvalidParameter {
                name: "query",
                reason: format!("({}, {}) is not a finite point", query.x, query.y),
            });
        }
        let mut v = match start {
            None => self.start,
            Some(s) if s < p.len() && self.is_vertex(s) => s,
            Some(s) => {
                return Err(Error::InvalidParameter {
                    name: "start",
                    reason: format!("{s} is not a vertex of the triangulation"),
                })
            }
        };
        loop {
            let mut best = v;
            for &w in &self.neighbours[self.offsets[v]..self.offsets[v + 1]] {
                if counter.cmp_dist(query, p[w], query, p[best]) == Ordering::Less {
                    best = w;
                }
            }
            if best == v {
                return Ok(v);
            }
            v = best;
        }
    }

    /// Whether `v` is a vertex of the triangulation: it has a neighbour, or it is the only
    /// distinct point.
    fn is_vertex(&self, v: usize) -> bool {
        self.offsets[v] < self.offsets[v + 1] || v == self.start
    }
}

/// The index of a point of `points` nearest to `query`: builds a [`NearestSearch`] and asks
/// it once.
///
/// # Errors
/// [`Error::TooFew`] for no points, [`Error::NonFinite`] for a bad point,
/// [`Error::InvalidParameter`] (name `"query"`) for a NaN or infinite query.
///
/// # Complexity
/// O(n log n) expected time (the triangulation), O(n) space.
///
/// ```
/// use compgeo::proximity::nearest;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (10.0, 0.0), (5.0, 9.0)].map(Point2::from);
/// assert_eq!(nearest(&pts, Point2::new(6.0, 7.0))?, 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn nearest(points: &[Point2], query: Point2) -> Result<usize> {
    NearestSearch::new(&PointSet::new(points)?)?.nearest(query)
}
