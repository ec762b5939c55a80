//! `compgeo gen`: print a seeded workload (points, graph or key sequence) as JSON.

use super::output::{print_json, print_text};
use super::CliError;
use crate::gen::{self, GraphKind, PointKind, SequenceKind};
use clap::builder::PossibleValue;
use clap::{Args, Subcommand, ValueEnum};
use serde::Serialize;

/// Arguments of `compgeo gen`.
#[derive(Debug, Args)]
pub(super) struct GenArgs {
    #[command(subcommand)]
    what: What,
}

#[derive(Debug, Subcommand)]
enum What {
    /// Print a point set as JSON [[x, y], ...]
    Points(PointsArgs),
    /// Print a graph as JSON {"vertices": n, "edges": [[u, v], ...]} ([[u, v, w], ...] with --weighted)
    Graph(GraphArgs),
    /// Print integer keys as a JSON array
    Sequence(SequenceArgs),
}

#[derive(Debug, Args)]
struct PointsArgs {
    /// Distribution or degenerate configuration
    #[arg(long)]
    kind: PointKind,
    /// Number of points (at most MAX_POINTS = 2^26; cocircular at most MAX_COCIRCULAR =
    /// 393660)
    #[arg(long)]
    n: usize,
    /// Seed: the same seed gives the same points on every machine
    #[arg(long, default_value_t = 0)]
    seed: u64,
}

#[derive(Debug, Args)]
struct GraphArgs {
    /// Graph family
    #[arg(long)]
    kind: GraphKind,
    /// Size: vertices (gnm, grid, complete, cycle, tree), 10 (petersen), order k
    /// (mycielski), board side (queen), vertices per side (crown); the graph may have at
    /// most MAX_VERTICES = 2^26 vertices and MAX_EDGES = 2^26 edges
    #[arg(long)]
    n: usize,
    /// Number of edges (gnm only, where it is required)
    #[arg(long)]
    m: Option<usize>,
    /// Seed: the same seed gives the same graph on every machine
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Add a weight uniform in [0, 1) to every edge (drawn independently of the structure)
    #[arg(long)]
    weighted: bool,
    /// Output format: the JSON graph, or DIMACS .col text (vertices from 1, no weights)
    #[arg(long, value_enum, default_value = "json")]
    format: GraphOutput,
}

/// How `gen graph` writes the graph.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum GraphOutput {
    /// `{"vertices": n, "edges": [[u, v], ...]}`.
    Json,
    /// DIMACS `.col` text, as the colouring benchmarks are published.
    Dimacs,
}

#[derive(Debug, Args)]
struct SequenceArgs {
    /// Order of the keys
    #[arg(long)]
    kind: SequenceKind,
    /// Number of keys (at most MAX_KEYS = 2^26)
    #[arg(long)]
    n: usize,
    /// Seed: the same seed gives the same keys on every machine
    #[arg(long, default_value_t = 0)]
    seed: u64,
}

/// Runs `compgeo gen`.
pub(super) fn run(args: GenArgs) -> Result<(), CliError> {
    match args.what {
        What::Points(a) => {
            let pts = gen::points(a.kind, a.n, a.seed)?;
            let pairs: Vec<[f64; 2]> = pts.into_iter().map(<[f64; 2]>::from).collect();
            print_json(&pairs)
        }
        What::Graph(a) => {
            let m = match (a.kind, a.m) {
                (GraphKind::Gnm, Some(m)) => m,
                (GraphKind::Gnm, None) => {
                    return Err(CliError::Usage(
                        "--kind gnm needs --m (the edge count)".into(),
                    ))
                }
                (_, None) => 0,
                (kind, Some(_)) => {
                    return Err(CliError::Usage(format!(
                        "--m applies only to --kind gnm, not --kind {kind}"
                    )))
                }
            };
            let mut g = gen::graph(a.kind, a.n, m, a.seed)?;
            if a.format == GraphOutput::Dimacs {
                if a.weighted {
                    return Err(CliError::Usage(
                        "--weighted: DIMACS .col has no weights; use --format json".into(),
                    ));
                }
                return print_text(&crate::graph::write_dimacs(&g));
            }
            if a.weighted {
                g = gen::with_random_weights(g, a.seed);
            }
            print_json(&graph_json(g))
        }
        What::Sequence(a) => print_json(&gen::sequence(a.kind, a.n, a.seed)?),
    }
}

/// The contract's graph JSON: `{"vertices": n, "edges": [[u, v], ...]}` or, weighted,
/// `[[u, v, w], ...]`, keys in that order.
#[derive(Serialize)]
struct GraphJson {
    vertices: usize,
    edges: EdgesJson,
}

#[derive(Serialize)]
#[serde(untagged)]
enum EdgesJson {
    Plain(Vec<[usize; 2]>),
    Weighted(Vec<(usize, usize, f64)>),
}

fn graph_json(g: crate::graph::EdgeList) -> GraphJson {
    let edges = match g.weights {
        None => EdgesJson::Plain(g.edges),
        Some(w) => EdgesJson::Weighted(
            g.edges
                .iter()
                .zip(w)
                .map(|(&[u, v], w)| (u, v, w))
                .collect(),
        ),
    };
    GraphJson {
        vertices: g.vertices,
        edges,
    }
}

impl ValueEnum for PointKind {
    fn value_variants<'a>() -> &'a [Self] {
        &PointKind::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.name()))
    }
}

impl ValueEnum for GraphKind {
    fn value_variants<'a>() -> &'a [Self] {
        &GraphKind::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.name()))
    }
}

impl ValueEnum for SequenceKind {
    fn value_variants<'a>() -> &'a [Self] {
        &SequenceKind::ALL
    }

    fn to_possible_value(&self) -> Option<PossibleValue> {
        Some(PossibleValue::new(self.name()))
    }
}
