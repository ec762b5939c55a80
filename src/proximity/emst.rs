//! The Euclidean minimum spanning tree: the Delaunay edges ranked exactly, then Kruskal.

use super::delaunay_edges;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::delaunay::incremental_with;
use crate::error::Result;
use crate::geometry::exact_sum::ExactSum;
use crate::geometry::{CountedPredicates, Point2, PointSet, WideFloat};
use crate::graph::{kruskal_with, SpanningForest, WeightedGraph};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "emst",
    name: "delaunay-kruskal",
    function: "proximity::euclidean_mst",
    file: "src/proximity/emst.rs",
    summary: "the Delaunay edges ranked by exact length, then Kruskal",
    time: "O(n log n) expected",
    space: "O(n)",
    operation: Some(Operation::DistanceEvaluations),
    counts: "those of the exact length sort, after the triangulation's tests",
    source: "[RD, §2.4]",
    claims: &[on(
        "uniform-square",
        Bound::NLogN,
        Operation::DistanceEvaluations,
    )],
};

/// The Euclidean minimum spanning tree of `points`; see [`euclidean_mst_with`].
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
/// O(n log n) expected time, O(n) space.
///
/// ```
/// use compgeo::proximity::euclidean_mst;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (10.0, 0.0), (1.0, 0.0), (10.0, 2.0)].map(Point2::from);
/// let t = euclidean_mst(&pts)?;
/// assert_eq!(t.edges, [[0, 2], [1, 3], [1, 2]]);
/// assert_eq!((t.weight.to_f64(), t.components), (Some(12.0), 1));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn euclidean_mst(points: &[Point2]) -> Result<SpanningForest<[usize; 2]>> {
    euclidean_mst_with(&PointSet::new(points)?, &mut NoCount)
}

/// The Euclidean minimum spanning tree of `points` from the Delaunay edges and Kruskal's
/// algorithm, counting the triangulation's predicates, the distance evaluations of the
/// length sort and Kruskal's work.
///
/// The idea ([RD, §2.4], problem 7 "Árbol spanning mínimo"): the
/// minimum spanning tree of the complete graph uses Delaunay edges only (an edge of it is
/// the shortest link between two parts, so no point lies in the circle with that edge as
/// diameter, which makes it a Delaunay edge). The edges are sorted by the exact
/// [`cmp_dist`](crate::geometry::cmp_dist), numbered by rank (equal lengths, exactly,
/// share a rank) and handed to the graph module's [`kruskal`](crate::graph::kruskal) with
/// the ranks as weights: small integers, exact in `f64`, so no rounded length ever decides
/// anything and squared lengths never overflow. Kruskal breaks ties of equal rank by edge
/// index; every tie-break gives a minimum tree. Duplicates join the point they were merged
/// into by zero-length edges, so the tree spans every input index: one component, or none
/// for no points.
///
/// The weight is the tree's total length: each edge's [`WideFloat::distance`] (relative
/// error below 2^-51), summed exactly and rounded once, so it is within 2.5 · 2^-52 of the
/// true total however many edges there are, and beyond `f64::MAX` it keeps its value:
///
/// ```
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::proximity::euclidean_mst_with;
///
/// let m = f64::MAX;
/// let pts = [(-m, 0.0), (0.0, 0.0), (m, 0.0)].map(Point2::from);
/// let t = euclidean_mst_with(&PointSet::new(&pts)?, &mut compgeo::count::NoCount)?;
/// assert_eq!(t.weight.to_string(), "3.5953862697246314e308"); // 2 · f64::MAX
/// # Ok::<(), compgeo::Error>(())
/// ```
///
/// # Errors
/// The triangulation's size limit.
///
/// # Complexity
/// O(n log n) expected time (the triangulation and the sort of its O(n) edges), O(n) space.
///
/// # Counts
/// The triangulation's orientation and in-circle tests, the distance evaluations of the
/// sort, and Kruskal's comparisons and edge visits.
pub fn euclidean_mst_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<SpanningForest<[usize; 2]>> {
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
    let mut weight = ExactSum::new();
    for &[u, v] in &tree {
        weight.add(WideFloat::distance(points[u], points[v]));
    }
    Ok(SpanningForest {
        edges: tree,
        weight: weight.value(),
        components: usize::from(!points.is_empty()),
    })
}
