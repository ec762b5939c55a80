//! The Euclidean minimum spanning tree: the Delaunay edges ranked exactly, then Kruskal.

use super::{delaunay_edges, Emst};
use crate::count::{Counter, NoCount};
use crate::delaunay::incremental_with;
use crate::error::{Error, Result};
use crate::geometry::construct::distance;
use crate::geometry::{CountedPredicates, Point2};
use crate::graph::{kruskal_with, WeightedGraph};
use std::cmp::Ordering;

/// The Euclidean minimum spanning tree of `points`; see [`euclidean_mst_with`].
///
/// # Errors
/// As [`euclidean_mst_with`].
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
