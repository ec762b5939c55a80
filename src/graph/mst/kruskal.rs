//! Kruskal's algorithm: the edges in order of weight, each added when it joins two trees.

use super::{edge_keys, finish, SpanningForest};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::graph::{UnionFind, WeightedGraph};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "mst",
    name: "kruskal",
    function: "graph::kruskal",
    file: "src/graph/mst/kruskal.rs",
    summary: "the edges by weight, each joining two trees of a union–find",
    time: "O(m log m)",
    space: "O(n + m)",
    operation: Some(Operation::Comparisons),
    counts: "those of the edge sort, then one edge visit per edge examined",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::MLogM, Operation::Comparisons)],
};

/// Kruskal's algorithm; see [`kruskal_with`].
///
/// # Complexity
/// O(m log m) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{kruskal, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]], &[4.0, 1.0, 2.0, 3.0])?;
/// assert_eq!(kruskal(&g).edges, [1, 2, 3]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn kruskal(g: &WeightedGraph) -> SpanningForest {
    kruskal_with(g, &mut NoCount)
}

/// Kruskal's algorithm, counting its work.
///
/// The idea: the greedy scheme of the course (§2.1 "Algoritmo voraz") with the candidates
/// taken in order of weight over the whole graph rather than around one tree: sort the
/// edges by (weight, index), then add each edge whose ends lie in different trees of the
/// forest built so far, tested with union–find (union by rank, path compression). Stops as
/// soon as n − 1 edges are in.
///
/// # Complexity
/// O(m log m) time for m edges (the sort; the union–find work is O(m α(n))), which is
/// O(m log n) when there are no parallel edges; O(n + m) auxiliary space.
///
/// # Counts
/// One `comparison` per comparison of the sort (O(m log m)) and one `edge_visit` per edge
/// examined after it.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{kruskal_with, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 0], [0, 0]], &[3.0, 1.0, 2.0, 0.0])?;
/// let mut c = Counts::default();
/// let t = kruskal_with(&g, &mut c);
/// assert_eq!(t.edges, [1, 2]);
/// assert_eq!(t.weight, 3.0);
/// assert!(c.comparisons > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn kruskal_with<C: Counter>(g: &WeightedGraph, c: &mut C) -> SpanningForest {
    let n = g.vertex_count();
    let keys = edge_keys(g);
    let edges = g.raw_edges();
    let mut order: Vec<(u64, u32)> = (0..edges.len())
        .filter(|&e| edges[e][0] != edges[e][1])
        .map(|e| (keys[e], e as u32))
        .collect();
    order.sort_unstable_by(|a, b| {
        c.comparison();
        a.cmp(b)
    });
    let mut sets = UnionFind::new(n);
    let mut chosen = Vec::with_capacity(n.saturating_sub(1));
    for &(_, e) in &order {
        if chosen.len() + 1 >= n {
            break;
        }
        c.edge_visit();
        let [u, v] = edges[e as usize];
        if sets.union(u as usize, v as usize) {
            chosen.push(e as usize);
        }
    }
    let components = n - chosen.len();
    finish(g, chosen, components)
}
