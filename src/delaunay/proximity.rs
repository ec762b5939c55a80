//! The seed's proximity problems solved on the Delaunay triangulation: all nearest
//! neighbours, the closest pair, nearest-neighbour queries and the Euclidean minimum
//! spanning tree.
//!
//! All follow `003_5b666ee3e15e6353.txt`, §2.4 "Solución de los problemas de proximidad":
//! every nearest neighbour of a site is a Delaunay neighbour (Theorem 2.31), so the
//! Delaunay edges (3n − 3 − h of them) hold every answer. Distances are compared with the
//! exact [`cmp_dist`](crate::geometry::cmp_dist) only; the `distance` fields of the
//! results are rounded `f64` values for display.
//!
//! Duplicates are points at distance zero: a duplicate's nearest neighbour is a point equal
//! to it, the closest pair of a set with duplicates is a pair of equal points, and the
//! spanning tree joins equal points by zero-length edges.

use super::construct::distance;
use super::incremental::incremental_with;
use super::triangulation::{Triangulation, EMPTY};
use crate::count::{Counter, NoCount};
use crate::error::{Error, Result};
use crate::geometry::{validate, CountedPredicates, Point2};
use crate::graph::{kruskal_with, WeightedGraph};
use std::cmp::Ordering;

/// Two points of the input at the smallest distance.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ClosestPair {
    /// Their indices, the smaller first.
    pub pair: [usize; 2],
    /// Their distance, rounded.
    pub distance: f64,
}

/// A Euclidean minimum spanning tree.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Emst {
    /// The tree's edges `[u, v]` (`u < v`), by exactly non-decreasing length; n − 1 of them
    /// for n input points.
    pub edges: Vec<[usize; 2]>,
    /// The total length, the sum of the rounded edge lengths in edge order.
    pub length: f64,
}

/// Nearest-neighbour queries on a fixed point set: a Delaunay triangulation and the
/// adjacency of its vertices, built once.
///
/// ```
/// use compgeo::delaunay::NearestSearch;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (0.0, 4.0), (4.0, 4.0), (2.0, 2.0)].map(Point2::from);
/// let search = NearestSearch::new(&pts)?;
/// assert_eq!(search.nearest(Point2::new(3.5, 0.2))?, 1);
/// assert_eq!(search.nearest(Point2::new(2.1, 1.9))?, 4);
/// assert_eq!(search.nearest(Point2::new(-100.0, 50.0))?, 2); // outside the hull
/// assert!(search.nearest(Point2::new(f64::NAN, 0.0)).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct NearestSearch<'a> {
    points: &'a [Point2],
    start: usize,
    offsets: Vec<usize>,
    neighbours: Vec<usize>,
}

impl<'a> NearestSearch<'a> {
    /// Triangulates `points` (the [`incremental`](super::incremental) builder) and indexes
    /// them for queries.
    ///
    /// # Errors
    /// [`Error::Empty`] for no points, and the builder's errors ([`Error::NonFinite`]).
    ///
    /// # Complexity
    /// O(n log n) expected time, O(n) space.
    pub fn new(points: &'a [Point2]) -> Result<NearestSearch<'a>> {
        if points.is_empty() {
            return Err(Error::Empty { what: "point set" });
        }
        let t = incremental_with(points, &mut NoCount)?;
        Ok(NearestSearch::from_triangulation(points, &t))
    }

    /// Indexes `points` with their Delaunay triangulation `t` (from one of the crate's
    /// builders; with another triangulation the greedy walk can stop at a wrong answer).
    ///
    /// # Complexity
    /// O(n + t) time and space.
    pub fn from_triangulation(points: &'a [Point2], t: &Triangulation) -> NearestSearch<'a> {
        let edges = delaunay_edges(t);
        let (offsets, neighbours) = adjacency(points.len(), &edges);
        let start = t.hull.first().copied().unwrap_or(0);
        NearestSearch {
            points,
            start,
            offsets,
            neighbours,
        }
    }

    /// The index of a point nearest to `query`; see [`nearest_with`](Self::nearest_with).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"query"`) if a coordinate of `query` is NaN or
    /// infinite.
    ///
    /// # Complexity
    /// O(d) time per step of the walk, where d is the degree of the current vertex; O(√n)
    /// steps expected for uniform points, O(n) in the worst case.
    pub fn nearest(&self, query: Point2) -> Result<usize> {
        self.nearest_with(query, None, &mut NoCount)
    }

    /// The index of a point nearest to `query`, by a greedy walk on the Delaunay graph from
    /// `start` (or a hull vertex), counting its distance evaluations.
    ///
    /// The idea (`003_5b666ee3e15e6353.txt`, §2.4, problem 4 "El vecino más cercano": find the
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
    /// use compgeo::delaunay::NearestSearch;
    /// use compgeo::gen::{points, PointKind};
    /// use compgeo::geometry::Point2;
    ///
    /// let pts = points(PointKind::UniformSquare, 2000, 7)?;
    /// let search = NearestSearch::new(&pts)?;
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
        if !query.is_finite() {
            return Err(Error::InvalidParameter {
                name: "query",
                reason: format!("({}, {}) is not a finite point", query.x, query.y),
            });
        }
        let mut v = match start {
            None => self.start,
            Some(s) if s < self.points.len() && self.is_vertex(s) => s,
            Some(s) => {
                return Err(Error::InvalidParameter {
                    name: "start",
                    reason: format!("{s} is not a vertex of the triangulation"),
                })
            }
        };
        let p = self.points;
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
/// [`Error::Empty`] for no points, [`Error::NonFinite`] for a bad point,
/// [`Error::InvalidParameter`] (name `"query"`) for a NaN or infinite query.
///
/// # Complexity
/// O(n log n) expected time (the triangulation), O(n) space.
///
/// ```
/// use compgeo::delaunay::nearest;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (10.0, 0.0), (5.0, 9.0)].map(Point2::from);
/// assert_eq!(nearest(&pts, Point2::new(6.0, 7.0))?, 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn nearest(points: &[Point2], query: Point2) -> Result<usize> {
    NearestSearch::new(points)?.nearest(query)
}

/// For every point, the index of a nearest other point; see
/// [`all_nearest_neighbours_with`].
///
/// # Errors
/// As [`all_nearest_neighbours_with`].
///
/// # Complexity
/// O(n log n) expected time, O(n) space.
///
/// ```
/// use compgeo::delaunay::all_nearest_neighbours;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (5.0, 0.0), (5.0, 2.5), (1.0, 0.0)].map(Point2::from);
/// let nn = all_nearest_neighbours(&pts)?;
/// assert_eq!(nn, [1, 4, 3, 2, 1]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn all_nearest_neighbours(points: &[Point2]) -> Result<Vec<usize>> {
    all_nearest_neighbours_with(points, &mut NoCount)
}

/// For every point, the index of a nearest other point, from the Delaunay edges, counting
/// the triangulation's predicates and the distance evaluations.
///
/// The idea (`003_5b666ee3e15e6353.txt`, §2.4, problem 2 "Todos los vecinos más cercanos"
/// and Theorem 2.31): a nearest neighbour of a site shares an edge of its Voronoi cell, so
/// it is a Delaunay neighbour. One pass over the edges keeps, for each end, the nearer of
/// its current best and the other end (exact [`cmp_dist`](crate::geometry::cmp_dist)).
/// Ties: any nearest point may be returned. A point equal to another has that one as its
/// nearest neighbour (distance zero).
///
/// # Errors
/// [`Error::TooFew`] for fewer than two points; [`Error::NonFinite`] for a NaN or infinite
/// coordinate.
///
/// # Complexity
/// O(n log n) expected time (the triangulation; the pass over the edges is O(n)), O(n)
/// auxiliary space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests, and two distance evaluations per
/// Delaunay edge.
pub fn all_nearest_neighbours_with<C: Counter>(
    points: &[Point2],
    counter: &mut C,
) -> Result<Vec<usize>> {
    at_least_two(points)?;
    let t = incremental_with(points, counter)?;
    let mut best = vec![EMPTY; points.len()];
    let closer = |a: usize, b: usize, best: &mut [usize], c: &mut C| {
        if best[a] == EMPTY
            || c.cmp_dist(points[a], points[b], points[a], points[best[a]]) == Ordering::Less
        {
            best[a] = b;
        }
    };
    for [a, b] in delaunay_edges(&t) {
        closer(a, b, &mut best, counter);
        closer(b, a, &mut best, counter);
    }
    for &[dropped, kept] in &t.duplicates {
        best[dropped] = kept;
    }
    for &[dropped, kept] in t.duplicates.iter().rev() {
        best[kept] = dropped;
    }
    Ok(best)
}

/// The closest pair of `points` via the Delaunay triangulation; see
/// [`closest_pair_with`].
///
/// # Errors
/// As [`closest_pair_with`].
///
/// # Complexity
/// O(n log n) expected time, O(n) space.
///
/// ```
/// use compgeo::delaunay::closest_pair;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (9.0, 9.0), (3.5, 5.0)].map(Point2::from);
/// let c = closest_pair(&pts)?;
/// assert_eq!(c.pair, [1, 3]);
/// assert_eq!(c.distance, 1.25f64.sqrt());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closest_pair(points: &[Point2]) -> Result<ClosestPair> {
    closest_pair_with(points, &mut NoCount)
}

/// The closest pair of `points`: the shortest Delaunay edge, counting the triangulation's
/// predicates and the distance evaluations.
///
/// The idea (`003_5b666ee3e15e6353.txt`, §2.4, problem 3 "El par más cercano": linear time
/// once the nearest neighbours are known): the closest pair are each other's nearest
/// neighbours, so their segment is a Delaunay edge; the shortest edge is found with the
/// exact [`cmp_dist`](crate::geometry::cmp_dist). With duplicates the answer is the first
/// duplicate pair (distance zero). Ties: any closest pair may be returned. The classic
/// divide and conquer is [`closest_pair_divide_and_conquer`](super::closest_pair_divide_and_conquer).
///
/// # Errors
/// [`Error::TooFew`] for fewer than two points; [`Error::NonFinite`] for a NaN or infinite
/// coordinate.
///
/// # Complexity
/// O(n log n) expected time (the triangulation; the scan is O(n)), O(n) space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests and one distance evaluation per
/// Delaunay edge.
pub fn closest_pair_with<C: Counter>(points: &[Point2], counter: &mut C) -> Result<ClosestPair> {
    at_least_two(points)?;
    let t = incremental_with(points, counter)?;
    if let Some(&[dropped, kept]) = t.duplicates.first() {
        return Ok(pair_of(points, kept, dropped));
    }
    let mut edges = delaunay_edges(&t).into_iter();
    let first = edges.next().expect("two distinct points have an edge");
    let best = edges.fold(first, |[a, b], [c, d]| {
        if counter.cmp_dist(points[c], points[d], points[a], points[b]) == Ordering::Less {
            [c, d]
        } else {
            [a, b]
        }
    });
    Ok(pair_of(points, best[0], best[1]))
}

/// The Euclidean minimum spanning tree of `points`; see [`euclidean_mst_with`].
///
/// # Errors
/// As [`euclidean_mst_with`].
///
/// # Complexity
/// O(n log n) expected time, O(n) space.
///
/// ```
/// use compgeo::delaunay::euclidean_mst;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (10.0, 0.0), (1.0, 0.0), (10.0, 2.0)].map(Point2::from);
/// let t = euclidean_mst(&pts)?;
/// assert_eq!(t.edges, [[0, 2], [1, 3], [1, 2]]);
/// assert_eq!(t.length, 12.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn euclidean_mst(points: &[Point2]) -> Result<Emst> {
    euclidean_mst_with(points, &mut NoCount)
}

/// The Euclidean minimum spanning tree of `points` from the Delaunay edges and Kruskal's
/// algorithm, counting the triangulation's predicates, the distance evaluations of the
/// length sort and Kruskal's work.
///
/// The idea (`003_5b666ee3e15e6353.txt`, §2.4, problem 7 "Árbol spanning mínimo"): the
/// minimum spanning tree of the complete graph uses Delaunay edges only (an edge of it is
/// the shortest link between two parts, so no point lies in the circle with that edge as
/// diameter, which makes it a Delaunay edge). The edges are sorted by the exact
/// [`cmp_dist`](crate::geometry::cmp_dist), numbered by rank (equal lengths, exactly,
/// share a rank) and handed to the graph module's [`kruskal`](crate::graph::kruskal) with
/// the ranks as weights: small integers, exact in `f64`, so no rounded length ever decides
/// anything and squared lengths never overflow. Kruskal breaks ties of equal rank by edge
/// index; every tie-break gives a minimum tree. Duplicates join the point they were merged
/// into by zero-length edges, so the tree spans every input index.
///
/// # Errors
/// [`Error::Empty`] for no points; [`Error::NonFinite`] for a NaN or infinite coordinate.
///
/// # Complexity
/// O(n log n) expected time (the triangulation and the sort of its O(n) edges), O(n) space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests, the distance evaluations of the
/// sort, and Kruskal's comparisons and edge visits.
pub fn euclidean_mst_with<C: Counter>(points: &[Point2], counter: &mut C) -> Result<Emst> {
    if points.is_empty() {
        return Err(Error::Empty { what: "point set" });
    }
    let t = incremental_with(points, counter)?;
    let mut edges = delaunay_edges(&t);
    edges.sort_unstable_by(|&[a, b], &[c, d]| {
        counter.cmp_dist(points[a], points[b], points[c], points[d])
    });
    let mut ranks = Vec::with_capacity(edges.len() + t.duplicates.len());
    let mut rank = 0u64;
    for k in 0..edges.len() {
        if k > 0 {
            let ([a, b], [c, d]) = (edges[k - 1], edges[k]);
            if counter.cmp_dist(points[a], points[b], points[c], points[d]) != Ordering::Equal {
                rank += 1;
            }
        }
        // Rank 0 is the duplicates' zero length.
        ranks.push((rank + 1) as f64);
    }
    for &[dropped, kept] in &t.duplicates {
        edges.push([kept, dropped]);
        ranks.push(0.0);
    }
    let g = WeightedGraph::from_edges(points.len(), &edges, &ranks)?;
    let forest = kruskal_with(&g, counter);
    // Kruskal returns edge indices ascending; order them by exact length (rank, then index).
    let mut order = forest.edges;
    order.sort_by(|&e, &f| ranks[e].total_cmp(&ranks[f]).then(e.cmp(&f)));
    let tree: Vec<[usize; 2]> = order
        .iter()
        .map(|&e| {
            let [u, v] = edges[e];
            [u.min(v), u.max(v)]
        })
        .collect();
    let length = tree
        .iter()
        .map(|&[u, v]| distance(points[u], points[v]))
        .sum();
    Ok(Emst {
        edges: tree,
        length,
    })
}

/// The undirected edges of the Delaunay graph: the triangulation's edges, or for collinear
/// points (no triangles) the segments between consecutive points along their line.
pub(crate) fn delaunay_edges(t: &Triangulation) -> Vec<[usize; 2]> {
    if t.is_empty() {
        t.hull.windows(2).map(|w| [w[0], w[1]]).collect()
    } else {
        t.edges().collect()
    }
}

/// Neighbour lists (compressed rows) of an undirected edge list on `n` vertices.
pub(crate) fn adjacency(n: usize, edges: &[[usize; 2]]) -> (Vec<usize>, Vec<usize>) {
    let mut offsets = vec![0usize; n + 1];
    for &[a, b] in edges {
        offsets[a + 1] += 1;
        offsets[b + 1] += 1;
    }
    for v in 0..n {
        offsets[v + 1] += offsets[v];
    }
    let mut fill = offsets.clone();
    let mut neighbours = vec![0usize; offsets[n]];
    for &[a, b] in edges {
        neighbours[fill[a]] = b;
        fill[a] += 1;
        neighbours[fill[b]] = a;
        fill[b] += 1;
    }
    (offsets, neighbours)
}

/// The pair `[a, b]` ordered, with its rounded distance.
pub(crate) fn pair_of(points: &[Point2], a: usize, b: usize) -> ClosestPair {
    ClosestPair {
        pair: [a.min(b), a.max(b)],
        distance: distance(points[a], points[b]),
    }
}

/// Validation for the problems about pairs.
pub(crate) fn at_least_two(points: &[Point2]) -> Result<()> {
    validate(points)?;
    if points.len() < 2 {
        return Err(Error::TooFew {
            what: "point set",
            needed: 2,
            got: points.len(),
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
        v.iter().map(|&p| Point2::from(p)).collect()
    }

    #[test]
    fn collinear_points_use_the_path_along_their_line() {
        let p = pts(&[(0.0, 0.0), (3.0, 3.0), (1.0, 1.0), (7.0, 7.0)]);
        assert_eq!(all_nearest_neighbours(&p).unwrap(), [2, 2, 0, 1]);
        assert_eq!(closest_pair(&p).unwrap().pair, [0, 2]);
        assert_eq!(nearest(&p, Point2::new(6.0, 1.0)).unwrap(), 1);
        let t = euclidean_mst(&p).unwrap();
        assert_eq!(t.edges, [[0, 2], [1, 2], [1, 3]]);
    }

    #[test]
    fn small_inputs() {
        let one = pts(&[(1.0, 2.0)]);
        assert!(matches!(
            closest_pair(&one),
            Err(Error::TooFew { got: 1, .. })
        ));
        assert_eq!(nearest(&one, Point2::new(-5.0, 0.0)).unwrap(), 0);
        assert_eq!(euclidean_mst(&one).unwrap().edges, Vec::<[usize; 2]>::new());
        assert!(matches!(
            nearest(&[], Point2::new(0.0, 0.0)),
            Err(Error::Empty { .. })
        ));
        let same = pts(&[(1.0, 2.0), (1.0, 2.0)]);
        assert_eq!(closest_pair(&same).unwrap(), pair_of(&same, 0, 1));
        assert_eq!(all_nearest_neighbours(&same).unwrap(), [1, 0]);
        assert_eq!(euclidean_mst(&same).unwrap().edges, [[0, 1]]);
    }

    #[test]
    fn a_bad_start_is_an_error() {
        let p = pts(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.0, 0.0)]);
        let s = NearestSearch::new(&p).unwrap();
        let q = Point2::new(0.1, 0.1);
        assert!(s.nearest_with(q, Some(3), &mut NoCount).is_err());
        assert!(s.nearest_with(q, Some(9), &mut NoCount).is_err());
        assert_eq!(s.nearest_with(q, Some(2), &mut NoCount).unwrap(), 0);
    }
}
