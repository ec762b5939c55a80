//! Minimum spanning trees (forests): the seed's greedy tree-growing (Prim), Kruskal and
//! Borůvka.
//!
//! A spanning tree of a connected weighted graph joins every vertex with n − 1 of its edges;
//! a minimum one has the least total weight (seed `003_5b666ee3e15e6353.txt`, §2.1 "Árbol
//! Spanning Minimal", Theorem 2.7: the greedy tree is minimal). On a disconnected graph every
//! function here returns a minimum spanning *forest*: a minimum spanning tree of each
//! component, n − c edges for c components.
//!
//! Edges are ranked by weight, ties by edge index. That is a strict total order, so the
//! minimum forest is unique and all three algorithms return the same edges. Self-loops are
//! never used; of parallel edges only the lightest can be.
//!
//! The tests compare the weight with brute force over every spanning forest of small graphs,
//! the three algorithms with each other, and with petgraph on larger graphs.

use super::graph::WeightedGraph;
use super::heap::Heap;
use super::union_find::UnionFind;
use crate::count::{Counter, NoCount};
use crate::error::{Error, Result};
use std::fmt;
use std::str::FromStr;

/// A minimum spanning forest.
#[derive(Debug, Clone, PartialEq)]
pub struct SpanningForest {
    /// The forest's edges as indices into the graph's edge list, ascending.
    pub edges: Vec<usize>,
    /// The total weight, summed in ascending edge index order (so equal edge sets give
    /// bit-identical totals).
    pub weight: f64,
    /// The number of trees, i.e. connected components of the graph (0 for the empty graph).
    pub components: usize,
}

/// The spanning-tree algorithms, by their command-line names.
///
/// ```
/// use compgeo::graph::MstAlgorithm;
///
/// assert_eq!("boruvka".parse::<MstAlgorithm>()?, MstAlgorithm::Boruvka);
/// assert_eq!(MstAlgorithm::Kruskal.name(), "kruskal");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MstAlgorithm {
    /// [`prim`], `prim`.
    Prim,
    /// [`kruskal`], `kruskal`.
    Kruskal,
    /// [`boruvka`], `boruvka`.
    Boruvka,
}

impl MstAlgorithm {
    /// Every algorithm, in the order above.
    pub const ALL: [MstAlgorithm; 3] = [
        MstAlgorithm::Prim,
        MstAlgorithm::Kruskal,
        MstAlgorithm::Boruvka,
    ];

    /// The kebab-case name.
    pub fn name(self) -> &'static str {
        match self {
            MstAlgorithm::Prim => "prim",
            MstAlgorithm::Kruskal => "kruskal",
            MstAlgorithm::Boruvka => "boruvka",
        }
    }

    /// Runs the algorithm, counting its work.
    ///
    /// # Complexity
    /// That of the algorithm: O(m log m) for each (O(m log n) on simple graphs).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::graph::{MstAlgorithm, WeightedGraph};
    ///
    /// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 0]], &[1.0, 2.0, 3.0])?;
    /// for a in MstAlgorithm::ALL {
    ///     assert_eq!(a.run_with(&g, &mut Counts::default()).edges, [0, 1]);
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn run_with<C: Counter>(self, g: &WeightedGraph, c: &mut C) -> SpanningForest {
        match self {
            MstAlgorithm::Prim => prim_with(g, c),
            MstAlgorithm::Kruskal => kruskal_with(g, c),
            MstAlgorithm::Boruvka => boruvka_with(g, c),
        }
    }
}

impl fmt::Display for MstAlgorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for MstAlgorithm {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self> {
        crate::error::algorithm_named(
            s,
            "spanning-tree algorithm",
            &MstAlgorithm::ALL,
            MstAlgorithm::name,
        )
    }
}

/// Prim's algorithm; see [`prim_with`].
///
/// # Complexity
/// O(m log m) time (O(m log n) on simple graphs), O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{prim, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]], &[4.0, 1.0, 2.0, 3.0])?;
/// let t = prim(&g);
/// assert_eq!((t.edges, t.weight), (vec![1, 2, 3], 6.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn prim(g: &WeightedGraph) -> SpanningForest {
    prim_with(g, &mut NoCount)
}

/// The seed's greedy spanning tree (Prim's algorithm), counting its work.
///
/// The idea (`003_5b666ee3e15e6353.txt`, §2.1 "Árbol Spanning Minimal", "Algoritmo voraz
/// aplicado a un Árbol Spanning Minimal"): take the lightest edge; then repeatedly add the
/// lightest edge that brings a new vertex into the tree, until no edge does. The tree grows
/// from an endpoint of the lightest edge (whose lightest edge is that one, so the first step
/// is the seed's). A binary heap holds the edges leaving the tree, keyed by (weight, edge
/// index); edges whose far end joined the tree meanwhile are skipped when popped. When the
/// heap runs dry with vertices left, a new tree starts at the smallest vertex not yet
/// reached, which makes a minimum spanning forest.
///
/// # Complexity
/// O(m log m) time for n vertices and m edges, which is O(m log n) when there are no
/// parallel edges (m < n²); O(n + m) auxiliary space for the heap.
///
/// # Counts
/// One `comparison` per comparison of heap entries (the dominant work, at most
/// 2·m·⌈log₂(2m)⌉ + m) and one `edge_visit` per incidence looked at (exactly 2m minus the
/// self-loops' share).
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{prim_with, WeightedGraph};
///
/// // Two components: a triangle and a single edge.
/// let g = WeightedGraph::from_edges(5, &[[0, 1], [1, 2], [0, 2], [3, 4]], &[1.0, 1.0, 5.0, 2.0])?;
/// let mut c = Counts::default();
/// let f = prim_with(&g, &mut c);
/// assert_eq!((f.edges, f.weight, f.components), (vec![0, 1, 3], 4.0, 2));
/// assert_eq!(c.edge_visits, 8);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn prim_with<C: Counter>(g: &WeightedGraph, c: &mut C) -> SpanningForest {
    let n = g.vertex_count();
    let keys = edge_keys(g);
    let mut in_tree = vec![false; n];
    let mut chosen = Vec::with_capacity(n.saturating_sub(1));
    let mut heap: Heap<(u64, u32, u32)> = Heap::with_capacity(0);
    let first = (0..g.edge_count())
        .filter(|&e| g.endpoints(e)[0] != g.endpoints(e)[1])
        .min_by_key(|&e| (keys[e], e))
        .map_or(0, |e| g.endpoints(e)[0]);
    let mut components = 0;
    let starts = std::iter::once(first).chain(0..n);
    for root in starts {
        if root >= n || in_tree[root] {
            continue;
        }
        components += 1;
        grow(g, &keys, root, &mut in_tree, &mut heap, c);
        while let Some((_, e, t)) = heap.pop(lighter, c) {
            if !in_tree[t as usize] {
                chosen.push(e as usize);
                grow(g, &keys, t as usize, &mut in_tree, &mut heap, c);
            }
        }
    }
    finish(g, chosen, components)
}

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
/// The idea: the greedy scheme of the seed (§2.1 "Algoritmo voraz") with the candidates
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
/// assert_eq!((t.edges, t.weight), (vec![1, 2], 3.0));
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
/// The idea (not in the seed; its greedy scheme, §2.1 "Algoritmo voraz", run for every tree
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

/// Whether `edges` (indices into `g`'s edge list) form a spanning forest of `g`: distinct
/// valid indices, no cycle (self-loops included), and one tree per connected component
/// (n − c edges for c components). It does not check minimality; compare weights for that.
///
/// # Complexity
/// O(n + m α(n)) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{is_spanning_forest, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 0], [3, 3]], &[1.0; 4])?;
/// assert!(is_spanning_forest(&g, &[0, 2]));
/// assert!(!is_spanning_forest(&g, &[0])); // 2 is not reached
/// assert!(!is_spanning_forest(&g, &[0, 1, 2])); // a cycle
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn is_spanning_forest(g: &WeightedGraph, edges: &[usize]) -> bool {
    let n = g.vertex_count();
    let mut whole = UnionFind::new(n);
    for &[u, v] in g.raw_edges() {
        whole.union(u as usize, v as usize);
    }
    let mut used = vec![false; g.edge_count()];
    let mut forest = UnionFind::new(n);
    for &e in edges {
        if e >= g.edge_count() || used[e] {
            return false;
        }
        used[e] = true;
        let [u, v] = g.endpoints(e);
        if !forest.union(u, v) {
            return false;
        }
    }
    forest.set_count() == whole.set_count()
}

/// Prim's step: `v` joins the tree and its edges to vertices outside go on the heap.
fn grow<C: Counter>(
    g: &WeightedGraph,
    keys: &[u64],
    v: usize,
    in_tree: &mut [bool],
    heap: &mut Heap<(u64, u32, u32)>,
    c: &mut C,
) {
    in_tree[v] = true;
    for &(t, e) in g.incidences_of(v) {
        c.edge_visit();
        if !in_tree[t as usize] {
            heap.push((keys[e as usize], e, t), lighter, c);
        }
    }
}

/// Prim's heap order: by weight key, then edge index.
fn lighter(a: &(u64, u32, u32), b: &(u64, u32, u32)) -> bool {
    (a.0, a.1) < (b.0, b.1)
}

/// "No edge yet" in Borůvka's per-tree lightest-edge array.
const NO_EDGE: u32 = u32::MAX;

/// Each weight mapped to a `u64` with the same order as `f64::total_cmp`, so edges compare
/// as integers (a monotone bijection on the bit patterns, not arithmetic on the values).
fn edge_keys(g: &WeightedGraph) -> Vec<u64> {
    g.weights()
        .iter()
        .map(|w| {
            let bits = w.to_bits();
            if bits >> 63 == 1 {
                !bits
            } else {
                bits | (1 << 63)
            }
        })
        .collect()
}

/// Sorts the chosen edges and sums their weights in index order.
fn finish(g: &WeightedGraph, mut chosen: Vec<usize>, components: usize) -> SpanningForest {
    chosen.sort_unstable();
    debug_assert!(is_spanning_forest(g, &chosen));
    let weight = chosen.iter().map(|&e| g.weight(e)).sum();
    SpanningForest {
        edges: chosen,
        weight,
        components,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_order_like_total_cmp() {
        let w = [
            -3.5,
            -0.0,
            0.0,
            1e-300,
            2.0,
            -1e300,
            7.25,
            f64::MIN_POSITIVE,
        ];
        let g = WeightedGraph::from_edges(2, &vec![[0, 1]; w.len()], &w).unwrap();
        let keys = edge_keys(&g);
        for i in 0..w.len() {
            for j in 0..w.len() {
                assert_eq!(
                    keys[i].cmp(&keys[j]),
                    w[i].total_cmp(&w[j]),
                    "{} {}",
                    w[i],
                    w[j]
                );
            }
        }
    }

    #[test]
    fn empty_and_edgeless_graphs_give_empty_forests() {
        for n in [0, 1, 4] {
            let g = WeightedGraph::from_edges(n, &[], &[]).unwrap();
            for a in MstAlgorithm::ALL {
                let f = a.run_with(&g, &mut NoCount);
                assert_eq!((f.edges.len(), f.weight, f.components), (0, 0.0, n));
            }
        }
    }
}
