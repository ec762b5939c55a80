//! `compgeo bfs`, `compgeo dfs`, `compgeo colour` and `compgeo mst`: the graph module on a
//! JSON graph.
//!
//! Output: `bfs`/`dfs` print `{"order": [...], "parent": [p or null, ...], "components":
//! c, "counts": {...}}` (`components` counts the whole graph's), or with `--trace` the
//! seed's Add / Remove / Q table as text; `colour` prints `{"colours": [...], "count": k,
//! "counts": {...}}`; `mst` prints `{"edges": [[u, v, w], ...], "edge_indices": [...],
//! "weight": w, "components": c, "counts": {...}}`. An empty graph is an error.

use super::input::GraphInput;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::geometry::WideFloat;
use crate::graph::{
    colour_with, components, search_trace, search_with, spanning_forest_with, trace_table,
    ColouringAlgorithm, EdgeList, Graph, MstAlgorithm, SearchAlgorithm, WeightedGraph,
};
use crate::Error;
use clap::Args;
use serde::Serialize;
use std::io::{self, Write};

/// Arguments of `compgeo bfs` and `compgeo dfs`.
#[derive(Debug, Args)]
pub(super) struct SearchArgs {
    /// The start vertex
    #[arg(long, short)]
    start: usize,
    /// Print the course's Add / Remove / Q table instead of JSON (graphs of at most
    /// TRACE_MAX_VERTICES = 1000 vertices)
    #[arg(long)]
    trace: bool,
    #[command(flatten)]
    graph: GraphInput,
}

/// Arguments of `compgeo colour`.
#[derive(Debug, Args)]
pub(super) struct ColourArgs {
    #[arg(long, short, help = ColouringAlgorithm::names(), long_help = ColouringAlgorithm::help())]
    algorithm: ColouringAlgorithm,
    #[command(flatten)]
    graph: GraphInput,
}

/// Arguments of `compgeo mst`.
#[derive(Debug, Args)]
pub(super) struct MstArgs {
    #[arg(long, short, help = MstAlgorithm::names(), long_help = MstAlgorithm::help())]
    algorithm: MstAlgorithm,
    #[command(flatten)]
    graph: GraphInput,
}

#[derive(Debug, Serialize)]
struct SearchOutput {
    order: Vec<usize>,
    parent: Vec<Option<usize>>,
    components: usize,
    counts: Counts,
}

#[derive(Debug, Serialize)]
struct ColourOutput {
    colours: Vec<usize>,
    count: usize,
    counts: Counts,
}

#[derive(Debug, Serialize)]
struct MstOutput {
    edges: Vec<(usize, usize, f64)>,
    edge_indices: Vec<usize>,
    weight: WideFloat,
    components: usize,
    counts: Counts,
}

/// Runs `compgeo bfs` or `compgeo dfs`, as `algorithm` says.
pub(super) fn run_search(args: SearchArgs, algorithm: SearchAlgorithm) -> Result<(), CliError> {
    let g = Graph::from_edge_list(&non_empty(args.graph.read()?)?)?;
    if args.trace {
        let table = trace_table(&search_trace(&g, args.start, algorithm)?, |v| v.to_string());
        let mut out = io::stdout().lock();
        return write!(out, "{table}")
            .and_then(|()| out.flush())
            .map_err(CliError::Output);
    }
    let mut counts = Counts::default();
    let search = search_with(&g, args.start, algorithm, &mut counts)?;
    print_json(&SearchOutput {
        order: search.order,
        parent: search.parent,
        components: components(&g).count,
        counts,
    })
}

/// Runs `compgeo colour`.
pub(super) fn run_colour(args: ColourArgs) -> Result<(), CliError> {
    let g = Graph::from_edge_list(&non_empty(args.graph.read()?)?)?;
    let mut counts = Counts::default();
    let c = colour_with(&g, args.algorithm, &mut counts);
    print_json(&ColourOutput {
        colours: c.colour,
        count: c.count,
        counts,
    })
}

/// Runs `compgeo mst`.
pub(super) fn run_mst(args: MstArgs) -> Result<(), CliError> {
    let g = weighted(&non_empty(args.graph.read()?)?)?;
    let mut counts = Counts::default();
    let f = spanning_forest_with(&g, args.algorithm, &mut counts);
    print_json(&MstOutput {
        edges: f
            .edges
            .iter()
            .map(|&e| {
                let [u, v] = g.endpoints(e);
                (u, v, g.weight(e))
            })
            .collect(),
        edge_indices: f.edges,
        weight: f.weight,
        components: f.components,
        counts,
    })
}

/// The weighted graph of an edge list with a weight on every edge.
pub(super) fn weighted(list: &EdgeList) -> Result<WeightedGraph, CliError> {
    if list.weights.is_none() && !list.edges.is_empty() {
        return Err(CliError::Shape(
            "mst needs a weight on every edge: [[u, v, w], ...]".to_string(),
        ));
    }
    let weights = list.weights.clone().unwrap_or_default();
    Ok(WeightedGraph::from_edges(
        list.vertices,
        &list.edges,
        &weights,
    )?)
}

/// Rejects a graph without vertices.
pub(super) fn non_empty(list: EdgeList) -> Result<EdgeList, CliError> {
    if list.vertices == 0 {
        return Err(Error::Empty { what: "graph" }.into());
    }
    Ok(list)
}
