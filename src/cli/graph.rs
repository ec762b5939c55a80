//! `compgeo bfs`, `compgeo dfs`, `compgeo colour` and `compgeo mst`: the graph module on a
//! JSON graph.
//!
//! Output: `bfs`/`dfs` print `{"order": [...], "parent": [p or null, ...], "components":
//! c, "counts": {...}}` (`components` counts the whole graph's), or with `--trace` the
//! seed's Add / Remove / Q table as text; `colour` prints `{"colours": [...], "count": k,
//! "counts": {...}}`, and for the search strategies (`dsatur-tabu`, `hea`) also `"steps"`,
//! `"best_step"` and `"timed_out"` (their [`SearchReport`]); `mst` prints `{"edges": [[u, v, w], ...], "edge_indices": [...],
//! "weight": w, "components": c, "counts": {...}}`. An empty graph is an error.

use super::input::GraphInput;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::geometry::WideFloat;
use crate::graph::{
    colour_budget_with, components, search_trace, search_with, spanning_forest_with, trace_table,
    Budget, ColouringAlgorithm, EdgeList, Graph, MstAlgorithm, SearchAlgorithm, SearchReport,
    WeightedGraph, SEARCH_SEED,
};
use crate::Error;
use clap::Args;
use serde::Serialize;
use std::io::{self, Write};
use std::time::Duration;

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
    /// The search's step budget (dsatur-tabu and hea; default 20(n + 2m), or none with
    /// --time alone); the same seed and steps give the same colouring on every machine
    #[arg(long, value_name = "STEPS", allow_negative_numbers = true)]
    effort: Option<u64>,
    /// The search's time limit in seconds (dsatur-tabu and hea); with --effort, whichever
    /// ends first
    #[arg(long, value_name = "SECONDS", allow_negative_numbers = true)]
    time: Option<f64>,
    /// The seed of the search's random choices (dsatur-tabu and hea)
    #[arg(long, value_name = "S", allow_negative_numbers = true)]
    seed: Option<u64>,
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
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    search: Option<SearchReport>,
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
    let search = args.algorithm.is_search();
    if !search && (args.effort.is_some() || args.time.is_some() || args.seed.is_some()) {
        return Err(CliError::Usage(format!(
            "--effort, --time and --seed apply to the search strategies dsatur-tabu and hea, \
             not to {}",
            args.algorithm
        )));
    }
    let time = args.time.map(seconds).transpose()?;
    let g = Graph::from_edge_list(&non_empty(args.graph.read()?)?)?;
    let budget = match (args.effort, time) {
        (None, None) => Budget::default_for(&g),
        (steps, time) => Budget { steps, time },
    };
    let mut counts = Counts::default();
    let seed = args.seed.unwrap_or(SEARCH_SEED);
    let (c, report) = colour_budget_with(&g, args.algorithm, budget, seed, &mut counts)?;
    print_json(&ColourOutput {
        colours: c.colour,
        count: c.count,
        counts,
        search: search.then_some(report),
    })
}

/// The time limit of `--time SECONDS`: a finite, non-negative number of seconds that a
/// [`Duration`] can hold.
fn seconds(value: f64) -> Result<Duration, CliError> {
    Duration::try_from_secs_f64(value).map_err(|_| {
        CliError::Usage(format!(
            "--time must be a finite, non-negative number of seconds below 1.8e19, got {value}"
        ))
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
