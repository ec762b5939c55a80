//! The `compgeo` command line: a thin layer that parses arguments, reads input, calls the
//! library and prints one JSON value on stdout.
//!
//! Exit codes: 0 on success; 2 for bad input or bad arguments, with exactly one line on
//! stderr starting `error: ` and nothing on stdout; 1 if the result cannot be written.
//! `--help` and `--version` print to stdout and exit 0.
//!
//! Every command lives in its own file, `src/cli/<command>.rs`, exposing an `Args` struct
//! and a `run` function; adding one means a variant in the private `Command` enum and an arm
//! in `run`. Everything here is private to the crate except [`main`], which the binary calls:
//! the command line is a front end, not a library API.
//! Commands read their input with `input` (points and graphs), print with
//! `output::print_json`, and report problems as `CliError`.

mod bezier;
mod delaunay;
mod diameter;
mod error;
mod gen;
mod graph;
mod hull;
// The fuzz checks (`crate::fuzzing`) call the readers directly.
pub(crate) mod input;
mod interpolate;
mod output;
mod proximity;
mod report;
mod sort;
mod stats;

use error::CliError;

use clap::error::ErrorKind;
use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Exact computational geometry that measures its own complexity.
#[derive(Debug, Parser)]
#[command(name = "compgeo", version, about)]
pub(crate) struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
enum Command {
    /// Generate a seeded workload: points, a graph or a key sequence
    Gen(gen::GenArgs),
    /// Print the size, distinct count and bounding box of a point set
    Stats(stats::StatsArgs),
    /// Measure the catalogued algorithms against their declared bounds and write the HTML/SVG/JSON report
    Report(report::ReportArgs),
    /// Sort numbers with a chosen algorithm and print the operation counts (or --trace)
    Sort(sort::SortArgs),
    /// Breadth-first search from a vertex: visit order and parents (or --trace)
    Bfs(graph::SearchArgs),
    /// Depth-first search from a vertex: visit order and parents (or --trace)
    Dfs(graph::SearchArgs),
    /// Colour a graph's vertices greedily with a chosen algorithm
    Colour(graph::ColourArgs),
    /// Minimum spanning tree (forest) of a weighted graph with a chosen algorithm
    Mst(graph::MstArgs),
    /// Convex hull of a point set: vertex indices counter-clockwise from the lexicographically smallest
    Hull(hull::HullArgs),
    /// Diameter of a point set: the farthest pair, by rotating calipers or brute force
    Diameter(diameter::DiameterArgs),
    /// Bézier curves: evaluate, split, elevate or differentiate, in f64 or exact rationals
    Bezier(bezier::BezierArgs),
    /// Interpolation: cubic Hermite, C² cubic spline, Lagrange or Newton, in f64 or exact
    Interpolate(interpolate::InterpolateArgs),
    /// Delaunay triangulation of a point set: CCW triangles, hull, merged duplicates
    Delaunay(delaunay::DelaunayArgs),
    /// Voronoi diagram: cells per site (vertices, rays), or cells clipped to a box
    Voronoi(proximity::VoronoiArgs),
    /// Closest pair of points, via Delaunay or by divide and conquer
    ClosestPair(proximity::ClosestPairArgs),
    /// Nearest point to a query, by a walk on the Delaunay triangulation
    Nearest(proximity::NearestArgs),
    /// Euclidean minimum spanning tree from the Delaunay edges
    Emst(proximity::PointsArgs),
    /// Largest empty circle centred in the convex hull
    EmptyCircle(proximity::PointsArgs),
}

/// Runs the command line with the process arguments and returns the exit code.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e),
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", one_line(&e.to_string()));
            ExitCode::from(e.exit_code())
        }
    }
}

fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        Command::Gen(args) => gen::run(args),
        Command::Stats(args) => stats::run(args),
        Command::Report(args) => report::run(args),
        Command::Sort(args) => sort::run(args),
        Command::Bfs(args) => graph::run_search(args, crate::graph::SearchAlgorithm::Bfs),
        Command::Dfs(args) => graph::run_search(args, crate::graph::SearchAlgorithm::Dfs),
        Command::Colour(args) => graph::run_colour(args),
        Command::Mst(args) => graph::run_mst(args),
        Command::Hull(args) => hull::run(args),
        Command::Diameter(args) => diameter::run(args),
        Command::Bezier(args) => bezier::run(args),
        Command::Interpolate(args) => interpolate::run(args),
        Command::Delaunay(args) => delaunay::run(args),
        Command::Voronoi(args) => proximity::run_voronoi(args),
        Command::ClosestPair(args) => proximity::run_closest_pair(args),
        Command::Nearest(args) => proximity::run_nearest(args),
        Command::Emst(args) => proximity::run_emst(args),
        Command::EmptyCircle(args) => proximity::run_empty_circle(args),
    }
}

/// Help and version go to stdout as clap prints them; usage errors become one `error:`
/// line on stderr with clap's exit code (2).
fn clap_exit(e: &clap::Error) -> ExitCode {
    let code = u8::try_from(e.exit_code()).unwrap_or(2);
    match e.kind() {
        ErrorKind::DisplayHelp
        | ErrorKind::DisplayVersion
        | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            // Nothing sensible is left to do if the terminal itself cannot be written.
            let _ = e.print();
        }
        _ => {
            let text = e.render().to_string();
            let message = one_line(text.trim_start().trim_start_matches("error:"));
            eprintln!("error: {message}");
        }
    }
    ExitCode::from(code)
}

/// Joins a multi-line message into one line, dropping blank lines and clap's
/// "For more information" hint, and bracketing its usage and tip lines.
fn one_line(text: &str) -> String {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("For more information"))
        .map(|l| {
            if l.starts_with("Usage:") || l.starts_with("tip:") {
                format!("({l})")
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn clap_errors_collapse_to_one_line() {
        let e = Cli::try_parse_from(["compgeo", "gen", "points", "--kind", "hexagon", "--n", "3"])
            .unwrap_err();
        let text = e.render().to_string();
        assert!(text.lines().count() > 1, "clap's own message spans lines");
        let line = one_line(&text);
        assert!(!line.contains('\n'));
        assert!(
            line.contains("hexagon") && line.contains("uniform-square"),
            "{line}"
        );
        assert!(!line.contains("For more information"));
    }
}
