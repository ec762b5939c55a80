//! Catalog entries of [`crate::graph`]: searches, colourings and spanning trees on random
//! G(n, m) graphs with m = 4n (average degree 8), weights uniform in [0, 1) for the trees.
//!
//! Searches and the linear greedy colourings count edge visits (exactly 2m on a connected
//! graph, n + m in the bound); the course's colouring counts adjacency tests (exactly
//! n(n − 1)/2); DSatur and Prim count heap comparisons, Kruskal sort comparisons, Borůvka edge
//! visits. DSatur's bound O((n + m) log n) is registered as O(m log n), the same growth at a
//! fixed ratio m/n ≥ 1; DSatur with the tabu search (`dsatur-tabu`) and DSatur with the
//! hybrid evolutionary search (`hea`) add the steps of their default budget, at most
//! 20(n + 2m) (evaluated moves, counted as comparisons, and table updates), to DSatur's
//! comparisons under the same bound.

use crate::complexity::{Bound, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{graph, with_random_weights, GraphKind};
use crate::geometry::WideFloat;
use crate::graph::{
    colour_with, search_with, spanning_forest_with, ColouringAlgorithm, Graph, MstAlgorithm,
    SearchAlgorithm, WeightedGraph,
};

/// Edges per vertex of the generated graphs.
const DENSITY: usize = 4;

/// The graph entries: every claim the searches, colourings and spanning trees declare, all on
/// G(n, 4n) (`gnm-4n`).
pub(super) fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    for algorithm in SearchAlgorithm::ALL {
        out.push(sized(algorithm.declaration(), Search { algorithm }));
    }
    for algorithm in ColouringAlgorithm::ALL {
        out.push(sized(algorithm.declaration(), Colour { algorithm }));
    }
    for algorithm in MstAlgorithm::ALL {
        out.push(sized(algorithm.declaration(), Tree { algorithm }));
    }
    out
}

/// The entry of `declaration`'s claim on `gnm-4n`: n from 256 (m from 1024) up for the
/// near-linear claims, smaller for the quadratic one.
fn sized<W: Workload + 'static>(
    declaration: &'static crate::complexity::Declaration,
    workload: W,
) -> Entry {
    let e = Entry::declared(declaration, "gnm-4n", workload);
    if e.info.bound == Bound::Quadratic {
        e.quick(64, 1 << 12).full(64, 1 << 14)
    } else {
        e.quick(256, 1 << 16).full(256, 1 << 20)
    }
}

/// G(n, 4n), or the complete graph when n is too small for 4n edges.
fn random_graph(n: usize, seed: u64) -> Result<crate::graph::EdgeList> {
    let m = (DENSITY * n).min(n * n.saturating_sub(1) / 2);
    graph(GraphKind::Gnm, n, m, seed)
}

/// BFS or DFS from vertex 0.
struct Search {
    algorithm: SearchAlgorithm,
}

impl Workload for Search {
    type Input = Graph;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Graph> {
        Graph::from_edge_list(&random_graph(n, seed)?)
    }

    fn run<C: Counter>(&self, g: &mut Graph, counter: &mut C) -> Result<usize> {
        Ok(search_with(g, 0, self.algorithm, counter)?.order.len())
    }

    fn edge_count(&self, g: &Graph) -> Option<usize> {
        Some(g.edge_count())
    }
}

/// One colouring algorithm.
struct Colour {
    algorithm: ColouringAlgorithm,
}

impl Workload for Colour {
    type Input = Graph;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Graph> {
        Graph::from_edge_list(&random_graph(n, seed)?)
    }

    fn run<C: Counter>(&self, g: &mut Graph, counter: &mut C) -> Result<usize> {
        Ok(colour_with(g, self.algorithm, counter).count)
    }

    fn edge_count(&self, g: &Graph) -> Option<usize> {
        Some(g.edge_count())
    }
}

/// One spanning-tree algorithm.
struct Tree {
    algorithm: MstAlgorithm,
}

impl Workload for Tree {
    type Input = WeightedGraph;
    type Output = WideFloat;

    fn prepare(&self, n: usize, seed: u64) -> Result<WeightedGraph> {
        WeightedGraph::from_edge_list(&with_random_weights(random_graph(n, seed)?, seed))
    }

    fn run<C: Counter>(&self, g: &mut WeightedGraph, counter: &mut C) -> Result<WideFloat> {
        Ok(spanning_forest_with(g, self.algorithm, counter).weight)
    }

    fn edge_count(&self, g: &WeightedGraph) -> Option<usize> {
        Some(g.edge_count())
    }
}
