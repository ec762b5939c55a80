//! Catalog entries of [`crate::graph`]: searches, colourings and spanning trees on random
//! G(n, m) graphs with m = 4n (average degree 8), weights uniform in [0, 1) for the trees.
//!
//! Searches and the linear greedy colourings count edge visits (exactly 2m on a connected
//! graph, n + m in the bound); the seed's colouring counts adjacency tests (exactly
//! n(n − 1)/2); DSatur and Prim count heap comparisons, Kruskal sort comparisons, Borůvka edge
//! visits. DSatur's bound O((n + m) log n) is registered as O(m log n), the same growth at a
//! fixed ratio m/n ≥ 1; DSatur with the tabu search adds its evaluated moves, at most
//! 20(n + 2m), to DSatur's comparisons under the same bound.

use crate::complexity::{Bound, Entry, Workload};
use crate::count::{Counter, Operation};
use crate::error::Result;
use crate::gen::{graph, with_random_weights, GraphKind};
use crate::graph::{
    bfs_with, colour_with, dfs_with, ColouringAlgorithm, Graph, MstAlgorithm, WeightedGraph,
};

/// Edges per vertex of the generated graphs.
const DENSITY: usize = 4;

/// The graph entries.
pub(super) fn entries() -> Vec<Entry> {
    let mut out = vec![
        linear(Entry::new(
            "search/bfs",
            Bound::NPlusM,
            Operation::EdgeVisits,
            Search { depth: false },
        )),
        linear(Entry::new(
            "search/dfs",
            Bound::NPlusM,
            Operation::EdgeVisits,
            Search { depth: true },
        )),
    ];
    for algorithm in ColouringAlgorithm::ALL {
        let id = format!("colour/{}", algorithm.name());
        let workload = Colour { algorithm };
        out.push(match algorithm {
            ColouringAlgorithm::Course => {
                Entry::new(&id, Bound::Quadratic, Operation::AdjacencyTests, workload)
                    .input("gnm-4n")
                    .quick(64, 1 << 12)
                    .full(64, 1 << 14)
            }
            ColouringAlgorithm::Dsatur | ColouringAlgorithm::DsaturTabu => linear(Entry::new(
                &id,
                Bound::MLogN,
                Operation::Comparisons,
                workload,
            )),
            _ => linear(Entry::new(
                &id,
                Bound::NPlusM,
                Operation::EdgeVisits,
                workload,
            )),
        });
    }
    for algorithm in MstAlgorithm::ALL {
        let (bound, operation) = match algorithm {
            MstAlgorithm::Prim => (Bound::MLogN, Operation::Comparisons),
            MstAlgorithm::Kruskal => (Bound::MLogM, Operation::Comparisons),
            MstAlgorithm::Boruvka => (Bound::MLogN, Operation::EdgeVisits),
        };
        let id = format!("mst/{}", algorithm.name());
        out.push(linear(Entry::new(
            &id,
            bound,
            operation,
            Tree { algorithm },
        )));
    }
    out
}

/// Sizes for the near-linear entries: n from 256 (m from 1024) up.
fn linear(e: Entry) -> Entry {
    e.input("gnm-4n").quick(256, 1 << 16).full(256, 1 << 20)
}

/// G(n, 4n), or the complete graph when n is too small for 4n edges.
fn random_graph(n: usize, seed: u64) -> Result<crate::graph::EdgeList> {
    let m = (DENSITY * n).min(n * n.saturating_sub(1) / 2);
    graph(GraphKind::Gnm, n, m, seed)
}

/// BFS or DFS from vertex 0.
struct Search {
    depth: bool,
}

impl Workload for Search {
    type Input = Graph;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Graph> {
        Graph::from_edge_list(&random_graph(n, seed)?)
    }

    fn run<C: Counter>(&self, g: &mut Graph, counter: &mut C) -> Result<usize> {
        let s = if self.depth {
            dfs_with(g, 0, counter)?
        } else {
            bfs_with(g, 0, counter)?
        };
        Ok(s.order.len())
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
    type Output = f64;

    fn prepare(&self, n: usize, seed: u64) -> Result<WeightedGraph> {
        WeightedGraph::from_edge_list(&with_random_weights(random_graph(n, seed)?, seed))
    }

    fn run<C: Counter>(&self, g: &mut WeightedGraph, counter: &mut C) -> Result<f64> {
        Ok(self.algorithm.run_with(g, counter).weight)
    }

    fn edge_count(&self, g: &WeightedGraph) -> Option<usize> {
        Some(g.edge_count())
    }
}
