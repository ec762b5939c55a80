//! Graphs: a compact CSR graph type, breadth- and depth-first search, greedy vertex
//! colouring and minimum spanning trees, following [RD, §2.1]
//! ("Algoritmo voraz", "Coloración de vértices", "Árbol Spanning Minimal", "Algoritmos de
//! búsqueda").
//!
//! Build a [`Graph`] (or a [`WeightedGraph`]) once from an edge list, with
//! [`Graph::from_edges`] or from an [`EdgeList`] (what the generators of [`crate::gen`] give); every
//! algorithm is a free function over it, with a `_with` form that takes a
//! [`Counter`](crate::count::Counter).
//!
//! | function | bound (n vertices, m edges) | counted |
//! |---|---|---|
//! | [`bfs`], [`dfs`] (their steps: [`search_trace`]) | O(n + m) | vertex and edge visits |
//! | [`course_greedy_colouring`] (its steps: [`course_greedy_colouring_trace`]) | O(n²), exactly n(n−1)/2 adjacency tests | adjacency tests |
//! | [`greedy_colouring`] (any order, [`largest_first_order`], [`smallest_last_order`]) | O(n + m) | edge visits |
//! | [`dsatur`] | O((n + m) log n) | heap comparisons |
//! | [`dsatur_tabu`] (DSatur, then [`tabu_recolour`] for fewer colours; any [`Budget`]: [`dsatur_tabu_budget`]) | O((n + m) log n) with the default budget, plus the steps of a given one | heap comparisons and moves evaluated |
//! | [`hea`] (DSatur, then the hybrid evolutionary search of Galinier and Hao; any [`Budget`]: [`hea_budget`]) | O((n + m) log n) with the default budget, plus the steps of a given one | heap comparisons and moves evaluated |
//! | [`prim`] (the course's greedy tree; its steps: [`prim_trace`]) | O(m log n) | heap comparisons |
//! | [`kruskal`] (its steps: [`kruskal_trace`]) | O(m log m) | sort comparisons |
//! | [`boruvka`] | O(m log n) | edge visits |

mod colouring;
// `graph/graph.rs` holds the graph types, as the module map of the crate docs says.
#[allow(clippy::module_inception)]
mod graph;
mod mst;
mod text;
mod traverse;
mod union_find;

pub use colouring::{
    check_colouring, colour, colour_budget, colour_budget_with, colour_with,
    course_greedy_colouring, course_greedy_colouring_trace, course_greedy_colouring_with, dsatur,
    dsatur_tabu, dsatur_tabu_budget, dsatur_tabu_budget_with, dsatur_tabu_with, dsatur_with,
    greedy_colouring, greedy_colouring_with, hea, hea_budget, hea_budget_with, hea_with,
    largest_first_order, smallest_last_order, tabu_recolour, tabu_recolour_with, Budget, Colouring,
    ColouringAlgorithm, CourseColouringStep, SearchReport, CLOCK_STRIDE, POPULATION, SEARCH_SEED,
    TABU_EFFORT,
};
pub use graph::{EdgeList, Graph, WeightedGraph, MAX_EDGES, MAX_VERTICES};
pub use mst::{
    boruvka, boruvka_with, check_spanning_forest, kruskal, kruskal_trace, kruskal_with, prim,
    prim_trace, prim_with, spanning_forest, spanning_forest_with, KruskalStep, MstAlgorithm,
    PrimStep, SpanningForest,
};
pub use text::{read_dimacs, read_edge_list, write_dimacs};
pub use traverse::{
    bfs, bfs_with, check_search_tree, components, dfs, dfs_with, is_connected, search,
    search_trace, search_with, trace_table, Components, Search, SearchAlgorithm, SearchStep,
    TRACE_MAX_VERTICES,
};
pub use union_find::UnionFind;
