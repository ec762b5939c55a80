//! Minimum spanning trees (forests): the course's greedy tree-growing (Prim), Kruskal and
//! Borůvka.
//!
//! A spanning tree of a connected weighted graph joins every vertex with n − 1 of its edges;
//! a minimum one has the least total weight ([RD, §2.1] "Árbol
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

use crate::complexity::algorithm_family;
use crate::count::{Counter, NoCount};
use crate::error::Violation;
use crate::geometry::exact_sum::ExactSum;
use crate::geometry::WideFloat;
use crate::graph::{UnionFind, WeightedGraph};

mod boruvka;
mod kruskal;
mod prim;

pub use boruvka::{boruvka, boruvka_with};
pub use kruskal::{kruskal, kruskal_trace, kruskal_with, KruskalStep};
pub use prim::{prim, prim_trace, prim_with, PrimStep};

/// A minimum spanning forest: one tree per connected component, and its total weight.
///
/// One shape for every spanning tree of the crate. For a graph ([`prim`], [`kruskal`],
/// [`boruvka`]) an edge is its index into the graph's edge list (`E = usize`); for the
/// Euclidean tree of a point set ([`crate::proximity::euclidean_mst`]) it is the pair of
/// point indices `[u, v]` it joins (`E = [usize; 2]`), and the weight is its length.
///
/// The weight is a [`WideFloat`]: a total beyond `f64::MAX` keeps its value, and with mixed
/// signs nothing cancels away.
///
/// ```
/// use compgeo::graph::{kruskal, WeightedGraph};
///
/// // Summed left to right in f64, 1e308 + 1 − 1e308 would be 0.
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3]], &[1e308, 1.0, -1e308])?;
/// assert_eq!(kruskal(&g).weight, 1.0);
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2]], &[f64::MAX, f64::MAX])?;
/// assert_eq!(kruskal(&g).weight.to_string(), "3.5953862697246314e308");
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SpanningForest<E = usize> {
    /// The forest's edges: for a graph, edge indices, ascending; for a point set, pairs
    /// `[u, v]` with `u < v`, by exactly non-decreasing length.
    pub edges: Vec<E>,
    /// The total weight: for a graph, the exact sum of the edges' weights rounded once
    /// (correctly: relative error at most 2^-53, whatever the signs and the order); for a
    /// point set, the total length, within 2.5 · 2^-52 of the exact one (see
    /// [`euclidean_mst_with`](crate::proximity::euclidean_mst_with)).
    pub weight: WideFloat,
    /// The number of trees, i.e. connected components (0 for no vertices).
    pub components: usize,
}

algorithm_family! {
    /// The spanning-tree algorithms, for callers that choose one at run time
    /// ([`spanning_forest`]).
    ///
    /// ```
    /// use compgeo::graph::MstAlgorithm;
    ///
    /// assert_eq!("boruvka".parse::<MstAlgorithm>()?, MstAlgorithm::Boruvka);
    /// assert_eq!(MstAlgorithm::Kruskal.name(), "kruskal");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum MstAlgorithm ("spanning-tree algorithm") {
        /// [`prim`]: the course's greedy tree.
        Prim = prim::DECLARATION => prim_with,
        /// [`kruskal`]: edges by weight, union–find.
        Kruskal = kruskal::DECLARATION => kruskal_with,
        /// [`boruvka`]: lightest outgoing edges of every tree at once.
        Boruvka = boruvka::DECLARATION => boruvka_with,
    }
    fn run_with[C: Counter](g: &WeightedGraph, c: &mut C) -> SpanningForest;
}

/// The minimum spanning forest of `g` by `algorithm`: the same as calling its function.
///
/// Every algorithm returns the same forest: edges are ranked by weight, then index.
///
/// # Complexity
/// That of the chosen algorithm ([`MstAlgorithm::declaration`]).
///
/// ```
/// use compgeo::graph::{spanning_forest, MstAlgorithm, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(3, &[[0, 1], [1, 2], [2, 0]], &[1.0, 2.0, 3.0])?;
/// for a in MstAlgorithm::ALL {
///     assert_eq!(spanning_forest(&g, a).edges, [0, 1]);
/// }
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn spanning_forest(g: &WeightedGraph, algorithm: MstAlgorithm) -> SpanningForest {
    spanning_forest_with(g, algorithm, &mut NoCount)
}

/// [`spanning_forest`], counting the chosen algorithm's work.
///
/// # Complexity
/// That of the chosen algorithm ([`MstAlgorithm::declaration`]).
pub fn spanning_forest_with<C: Counter>(
    g: &WeightedGraph,
    algorithm: MstAlgorithm,
    c: &mut C,
) -> SpanningForest {
    algorithm.run_with(g, c)
}

/// Checks that `edges` (indices into `g`'s edge list) form a spanning forest of `g`: distinct
/// valid indices, no cycle (self-loops included), and one tree per connected component
/// (n − c edges for c components). It does not check minimality; compare weights for that.
///
/// # Errors
/// A [`Violation`] naming an edge index out of range or repeated, the first edge that closes
/// a cycle, or the number of trees when the forest does not span every component.
///
/// # Complexity
/// O(n + m α(n)) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{check_spanning_forest, WeightedGraph};
///
/// let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 0], [3, 3]], &[1.0; 4])?;
/// assert!(check_spanning_forest(&g, &[0, 2]).is_ok());
/// assert!(check_spanning_forest(&g, &[0]).is_err()); // 2 is not reached
/// let cycle = check_spanning_forest(&g, &[0, 1, 2]).unwrap_err();
/// assert_eq!(cycle.to_string(), "edge 2 closes a cycle");
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn check_spanning_forest(g: &WeightedGraph, edges: &[usize]) -> Result<(), Violation> {
    let n = g.vertex_count();
    let mut whole = UnionFind::new(n);
    for &[u, v] in g.raw_edges() {
        whole.union(u as usize, v as usize);
    }
    let mut used = vec![false; g.edge_count()];
    let mut forest = UnionFind::new(n);
    for &e in edges {
        if e >= g.edge_count() {
            return Err(Violation::new(format!(
                "edge {e} is out of range for {} edges",
                g.edge_count()
            )));
        }
        if used[e] {
            return Err(Violation::new(format!("edge {e} is listed twice")));
        }
        used[e] = true;
        let [u, v] = g.endpoints(e);
        if !forest.union(u, v) {
            return Err(Violation::new(format!("edge {e} closes a cycle")));
        }
    }
    if forest.set_count() == whole.set_count() {
        Ok(())
    } else {
        Err(Violation::new(format!(
            "{} trees for {} connected components",
            forest.set_count(),
            whole.set_count()
        )))
    }
}

/// Each weight as a `u64` with the order of `f64::total_cmp`, so edges compare as integers.
pub(super) fn edge_keys(g: &WeightedGraph) -> Vec<u64> {
    g.weights()
        .iter()
        .map(|&w| crate::util::order_key(w))
        .collect()
}

/// Sorts the chosen edges and sums their weights exactly.
pub(super) fn finish(
    g: &WeightedGraph,
    mut chosen: Vec<usize>,
    components: usize,
) -> SpanningForest {
    chosen.sort_unstable();
    debug_assert_eq!(check_spanning_forest(g, &chosen), Ok(()));
    let mut weight = ExactSum::new();
    for &e in &chosen {
        weight.add_f64(g.weight(e));
    }
    SpanningForest {
        edges: chosen,
        weight: weight.value(),
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
                let f = spanning_forest_with(&g, a, &mut NoCount);
                assert_eq!(
                    (f.edges.len(), f.weight, f.components),
                    (0, WideFloat::ZERO, n)
                );
            }
        }
    }
}
