//! Borůvka's algorithm: every tree of the forest adds its lightest outgoing edge, round after
//! round.

use super::{edge_keys, finish, SpanningForest};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::graph::{UnionFind, WeightedGraph};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "mst",
    name: "boruvka",
    function: "graph::boruvka",
    file: "src/graph/mst/boruvka.rs",
    summary: "every tree adds its lightest outgoing edge, round after round",
    time: "O(m log n)",
    space: "O(n + m)",
    operation: Some(Operation::EdgeVisits),
    counts: "at most ⌈log₂ n⌉ rounds over the remaining edges",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::MLogN, Operation::EdgeVisits)],
};

/// Borůvka's algorithm; see [`boruvka_with`].
///
/// # Complexity
/// O(m log n) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{boruvka, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]], &[4.0, 1.0, 2.0, 3.0])?;
/// assert_eq!(boruvka(&g).edges, [1, 2, 3]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn boruvka(g: &WeightedGraph) -> SpanningForest {
    boruvka_with(g, &mut NoCount)
}

/// Borůvka's algorithm, counting its work.
///
/// The idea (not in the course; its greedy scheme, §2.1 "Algoritmo voraz", run for every tree
/// of the forest at once): every tree of the forest picks its lightest outgoing edge at once (ranked by
/// weight, then index, so no cycle can form), all picked edges are added, and the rounds
/// repeat until no tree has an outgoing edge. Each round at least halves the number of
/// trees that still have outgoing edges, so there are at most ⌈log₂ n⌉ rounds; edges inside
/// a tree are dropped from later rounds.
///
/// # Complexity
/// O(m log n) time for n vertices and m edges (O(m) per round); O(n + m) auxiliary space.
///
/// # Counts
/// One `edge_visit` per edge examined in a round and one `comparison` per comparison of an
/// edge against a tree's current lightest: both O(m log n).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{boruvka_with, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [2, 3], [1, 2]], &[1.0, 1.0, 7.0])?;
/// let mut c = Counts::default();
/// assert_eq!(boruvka_with(&g, &mut c).weight, 9.0);
/// // Rounds 1 and 2 see all 3 edges (round 2 drops the 2 now inside trees), round 3 the last.
/// assert_eq!(c.edge_visits, 7);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn boruvka_with<C: Counter>(g: &WeightedGraph, c: &mut C) -> SpanningForest {
    let n = g.vertex_count();
    let keys = edge_keys(g);
    let edges = g.raw_edges();
    let mut live: Vec<u32> = (0..edges.len() as u32)
        .filter(|&e| edges[e as usize][0] != edges[e as usize][1])
        .collect();
    let mut sets = UnionFind::new(n);
    let mut chosen = Vec::with_capacity(n.saturating_sub(1));
    let mut lightest = vec![NO_EDGE; n];
    loop {
        let mut kept = 0;
        for i in 0..live.len() {
            let e = live[i];
            c.edge_visit();
            let [u, v] = edges[e as usize];
            let (ru, rv) = (sets.find(u as usize), sets.find(v as usize));
            if ru == rv {
                continue;
            }
            live[kept] = e;
            kept += 1;
            for r in [ru, rv] {
                let best = lightest[r];
                if best == NO_EDGE || {
                    c.comparison();
                    (keys[e as usize], e) < (keys[best as usize], best)
                } {
                    lightest[r] = e;
                }
            }
        }
        live.truncate(kept);
        let mut added = false;
        for slot in lightest.iter_mut() {
            let e = *slot;
            if e != NO_EDGE {
                *slot = NO_EDGE;
                let [u, v] = edges[e as usize];
                if sets.union(u as usize, v as usize) {
                    chosen.push(e as usize);
                    added = true;
                }
            }
        }
        if !added {
            break;
        }
    }
    let components = sets.set_count();
    finish(g, chosen, components)
}

/// "No edge yet" in Borůvka's per-tree lightest-edge array.
const NO_EDGE: u32 = u32::MAX;
