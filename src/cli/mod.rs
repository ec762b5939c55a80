//! The `compgeo` command line: a thin layer that parses arguments, reads input, calls the
//! library and prints one JSON value on stdout.
//!
//! Exit codes: 0 on success; 2 for bad input, bad arguments, a path that cannot be read or
//! written, or a command group without its subcommand, with exactly one line on stderr
//! starting `error: ` and nothing on stdout; 1 if the result cannot be written to stdout.
//! `--help` and `--version` print to stdout and exit 0.
//!
//! Every command lives in its own file, `src/cli/<command>.rs`, exposing an `Args` struct
//! and a `run` function; adding one means a variant in the private `Command` enum and an arm
//! in `run`. Everything here is private to the crate except [`main`], which the binary calls:
//! the command line is a front end, not a library API.
//! Commands read their input with `input` (points and graphs), print with
//! `output::print_json`, and report problems as `CliError`.
//!
//! Numbers: every `f64` prints in its shortest round-trip form. A length, distance, width,
//! area, radius or total (a [`WideFloat`](crate::geometry::WideFloat)) prints as a JSON number
//! when it fits in `f64` and as a JSON string with its decimal value to 17 significant digits
//! when it exceeds `f64::MAX` (`"distance": "5.0846440246145847e308"`), never as `null`: the
//! rule of "Values beyond f64" in `docs/design.md`.

/// Calls `f::<S, D>(args)` for the scalar (`f64`, or `BigRational` when `exact`) and the
/// dimension `dim` (1 to 4) of the input, the one dispatch every curve command needs; another
/// dimension is a [`CliError::Shape`] naming `what` ("control points have 5 coordinates; 1 to
/// 4 are supported").
macro_rules! by_scalar_and_dimension {
    ($exact:expr, $dim:expr, $what:literal, $f:ident($($arg:expr),* $(,)?)) => {
        match ($exact, $dim) {
            (false, 1) => $f::<f64, 1>($($arg),*),
            (false, 2) => $f::<f64, 2>($($arg),*),
            (false, 3) => $f::<f64, 3>($($arg),*),
            (false, 4) => $f::<f64, 4>($($arg),*),
            (true, 1) => $f::<num_rational::BigRational, 1>($($arg),*),
            (true, 2) => $f::<num_rational::BigRational, 2>($($arg),*),
            (true, 3) => $f::<num_rational::BigRational, 3>($($arg),*),
            (true, 4) => $f::<num_rational::BigRational, 4>($($arg),*),
            (_, d) => Err(CliError::Shape(format!(
                "{} have {d} coordinates; 1 to 4 are supported",
                $what
            ))),
        }
    };
}

mod beta;
mod bezier;
mod bspline;
mod delaunay;
mod diameter;
mod draw;
mod error;
mod gen;
mod graph;
mod hull;
// The fuzz checks (`crate::fuzzing`) call the readers directly.
pub(crate) mod input;
mod interpolate;
mod mesh;
mod nurbs;
mod output;
mod proximity;
mod report;
mod sort;
mod stats;
mod subdivide;
mod surface;
mod triangle;

use error::CliError;

use clap::error::ErrorKind;
use clap::{CommandFactory, Parser, Subcommand};
use std::ffi::OsString;
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
    /// Colour a graph's vertices with a chosen algorithm: greedy orders, DSatur, tabu search
    Colour(graph::ColourArgs),
    /// Minimum spanning tree (forest) of a weighted graph with a chosen algorithm
    Mst(graph::MstArgs),
    /// Convex hull of a point set: vertex indices counter-clockwise from the lexicographically smallest
    Hull(hull::HullArgs),
    /// Diameter of a point set (the farthest pair, by rotating calipers or brute force), its
    /// width and minimum-area and minimum-perimeter rectangles
    Diameter(diameter::DiameterArgs),
    /// Bézier curves: evaluate, split, elevate or differentiate, in f64 or exact rationals
    Bezier(bezier::BezierArgs),
    /// B-spline curves: evaluate (with the de Boor net), insert knots, differentiate, the basis
    Bspline(bspline::BsplineArgs),
    /// NURBS curves: evaluate, insert knots, elevate, rational Bézier pieces
    Nurbs(nurbs::NurbsArgs),
    /// Surfaces (Bézier, B-spline, NURBS): evaluate, differentiate, normals, restrict, elevate,
    /// interpolate, fit, loft, tessellate into OBJ/STL meshes
    Surface(surface::SurfaceArgs),
    /// Uniform subdivision of a polygon: Lane–Riesenfeld of any degree, Chaikin, four-point
    Subdivide(subdivide::SubdivideArgs),
    /// Triangular Bézier patches: evaluate, subdivide (at a point or at the edge midpoints),
    /// elevate, tessellate into OBJ/STL meshes
    Triangle(triangle::TriangleArgs),
    /// Cubic Beta-splines: evaluate, subdivision matrices at any c, recursive subdivision
    Beta(beta::BetaArgs),
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
    /// Polygon meshes from OBJ: k rounds of a subdivision scheme (Catmull–Clark, ...)
    Mesh(mesh::MeshArgs),
    /// Draw a result as an SVG picture: hull, diameter, delaunay, voronoi, closest-pair,
    /// emst, empty-circle; bezier, bspline, nurbs, beta, subdivide; surface, triangle, mesh;
    /// graph
    Draw(draw::DrawArgs),
}

/// Runs the command line with the process arguments and returns the exit code.
pub fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().collect();
    let cli = match Cli::try_parse_from(&args) {
        Ok(cli) => cli,
        Err(e) => return clap_exit(&e, &args),
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
        Command::Bspline(args) => bspline::run(args),
        Command::Nurbs(args) => nurbs::run(args),
        Command::Surface(args) => surface::run(args),
        Command::Subdivide(args) => subdivide::run(args),
        Command::Triangle(args) => triangle::run(args),
        Command::Beta(args) => beta::run(args),
        Command::Interpolate(args) => interpolate::run(args),
        Command::Delaunay(args) => delaunay::run(args),
        Command::Voronoi(args) => proximity::run_voronoi(args),
        Command::ClosestPair(args) => proximity::run_closest_pair(args),
        Command::Nearest(args) => proximity::run_nearest(args),
        Command::Emst(args) => proximity::run_emst(args),
        Command::EmptyCircle(args) => proximity::run_empty_circle(args),
        Command::Mesh(args) => mesh::run(args),
        Command::Draw(args) => draw::run(args),
    }
}

/// Help and version go to stdout as clap prints them; usage errors become one `error:`
/// line on stderr with clap's exit code (2). A command group without its subcommand
/// (`compgeo gen`) is a usage error too, named with the choices, not a page of help on
/// stderr: the help stays on `--help`.
fn clap_exit(e: &clap::Error, args: &[OsString]) -> ExitCode {
    let code = u8::try_from(e.exit_code()).unwrap_or(2);
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            // Nothing sensible is left to do if the terminal itself cannot be written.
            let _ = e.print();
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            eprintln!("error: {}", missing_subcommand(args));
            return ExitCode::from(2);
        }
        _ => {
            let text = e.render().to_string();
            let message = one_line(text.trim_start().trim_start_matches("error:"));
            eprintln!("error: {message}");
        }
    }
    ExitCode::from(code)
}

/// The message for a command group given without its subcommand: "missing subcommand for
/// `compgeo gen`; expected one of: points, graph, sequence". `args` are the process
/// arguments, the program name first; the group is the deepest one they name.
fn missing_subcommand(args: &[OsString]) -> String {
    let mut command = Cli::command();
    let mut path = vec![command.get_name().to_string()];
    for arg in args.iter().skip(1) {
        let Some(sub) = arg.to_str().and_then(|a| command.find_subcommand(a)) else {
            break;
        };
        let sub = sub.clone();
        path.push(sub.get_name().to_string());
        command = sub;
    }
    let path = path.join(" ");
    let choices: Vec<&str> = command
        .get_subcommands()
        .map(clap::Command::get_name)
        .filter(|&name| name != "help")
        .collect();
    if choices.is_empty() {
        format!("missing arguments for `{path}`; see `{path} --help`")
    } else {
        format!(
            "missing subcommand for `{path}`; expected one of: {}",
            choices.join(", ")
        )
    }
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

    #[test]
    fn the_command_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn a_missing_subcommand_names_the_group_and_its_choices() {
        let args = |a: &[&str]| a.iter().map(OsString::from).collect::<Vec<_>>();
        assert_eq!(
            missing_subcommand(&args(&["compgeo", "gen"])),
            "missing subcommand for `compgeo gen`; expected one of: points, graph, sequence"
        );
        let top = missing_subcommand(&args(&["compgeo"]));
        assert!(
            top.starts_with("missing subcommand for `compgeo`; expected one of: gen, stats,"),
            "{top}"
        );
        assert!(!top.contains("help"), "{top}");
        for group in ["bezier", "beta", "bspline", "interpolate", "nurbs"] {
            let text = missing_subcommand(&args(&["compgeo", group]));
            assert!(text.contains(&format!("`compgeo {group}`")), "{text}");
        }
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
