//! `compgeo subdivide`: k rounds of uniform subdivision of an open or closed polygon, by the
//! Lane–Riesenfeld algorithm of any degree (Chaikin's is degree 2) or the four-point scheme,
//! in `f64` or (with `--exact`) in exact rationals.
//!
//! The polygon is JSON `[[x, y], ...]` in any dimension from 1 to 4, given with `--points`
//! or read from stdin with `--points -`; numbers are read as `bezier` reads them. The output
//! is `{"scheme", "rounds", "closed", "points": [...], "mask": {"start", "coefficients"},
//! "counts"}`, plus `"degree"` and `"limit"` (the limit points of the result's vertices) for
//! the Lane–Riesenfeld schemes and `"tension"` for the four-point scheme. Options that the
//! scheme does not take (`--tension` with Lane–Riesenfeld, `--degree` with the four-point
//! scheme or a degree other than 2 with Chaikin) are errors, not silently ignored.

use super::bezier::{points, scalars, JsonScalar};
use super::input::{inline_or_stdin, parse_number_arrays};
use super::interpolate::to_points;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::spline::subdivision::{
    four_point, four_point_with, lane_riesenfeld, lane_riesenfeld_with, limit_points, Mask,
    Topology,
};
use crate::spline::{parse_scalar, Point};
use clap::{Args, ValueEnum};
use serde_json::{json, Value};

/// Arguments of `compgeo subdivide`.
#[derive(Debug, Args)]
pub(super) struct SubdivideArgs {
    /// The polygon as JSON [[x, y], ...] (dimension 1 to 4), or `-` to read it from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    points: String,
    /// The scheme
    #[arg(long, value_enum)]
    scheme: Scheme,
    /// The degree d of lane-riesenfeld, at least 1 [default: 3]
    #[arg(long)]
    degree: Option<usize>,
    /// How many rounds (each doubles the vertices)
    #[arg(long, default_value_t = 1)]
    pub(super) rounds: usize,
    /// The polygon is closed (its last vertex joined to its first); else it is open
    #[arg(long)]
    closed: bool,
    /// The tension w of four-point, a decimal or a fraction [default: 1/16]
    #[arg(long, value_name = "W", allow_hyphen_values = true)]
    tension: Option<String>,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    pub(super) exact: bool,
}

/// The schemes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Scheme {
    /// Uniform B-spline subdivision of degree d: double, then d passes of midpoints
    LaneRiesenfeld,
    /// Lane–Riesenfeld of degree 2: cut every corner at ¼ and ¾
    Chaikin,
    /// The interpolating four-point scheme with tension w (1/16 reproduces cubics)
    FourPoint,
}

/// Runs `compgeo subdivide`.
pub(super) fn run(args: SubdivideArgs) -> Result<(), CliError> {
    let rows = polygon_rows(&args)?;
    let d = rows[0].len();
    let value = by_scalar_and_dimension!(args.exact, d, "points", run_typed(&args, &rows))?;
    print_json(&value)
}

/// The polygon's rows of number texts, after checking the options.
pub(super) fn polygon_rows(args: &SubdivideArgs) -> Result<Vec<Vec<String>>, CliError> {
    check_options(args)?;
    parse_number_arrays(&inline_or_stdin(&args.points)?)
}

/// Whether the polygon is closed.
pub(super) fn topology(args: &SubdivideArgs) -> Topology {
    if args.closed {
        Topology::Closed
    } else {
        Topology::Open
    }
}

/// The scheme's name, with the degree of Lane–Riesenfeld.
pub(super) fn scheme_title(args: &SubdivideArgs) -> String {
    match args.scheme {
        Scheme::LaneRiesenfeld => format!("Lane–Riesenfeld of degree {}", args.degree.unwrap_or(3)),
        Scheme::Chaikin => "Chaikin".to_string(),
        Scheme::FourPoint => "four-point scheme".to_string(),
    }
}

/// The scheme's name on the command line (`lane-riesenfeld`, `chaikin`, `four-point`).
pub(super) fn scheme_name(args: &SubdivideArgs) -> String {
    args.scheme
        .to_possible_value()
        .map(|v| v.get_name().to_string())
        .unwrap_or_default()
}

/// The degree of a Lane–Riesenfeld scheme (Chaikin's is 2); `None` for the four-point
/// scheme.
pub(super) fn lane_riesenfeld_degree(args: &SubdivideArgs) -> Option<usize> {
    match args.scheme {
        Scheme::LaneRiesenfeld => Some(args.degree.unwrap_or(3)),
        Scheme::Chaikin => Some(2),
        Scheme::FourPoint => None,
    }
}

/// The polygon after each round 0, 1, …, k (round 0 is the input), one round at a time.
pub(super) fn each_round<S: JsonScalar, const D: usize>(
    args: &SubdivideArgs,
    rows: &[Vec<String>],
) -> Result<Vec<Vec<Point<S, D>>>, CliError> {
    let polygon: Vec<Point<S, D>> = to_points(rows, |i| format!("point {i}"))?;
    let topology = topology(args);
    let w: S = match &args.tension {
        Some(text) => parse_scalar(text, "tension")?,
        None => S::from_ratio(1, 16),
    };
    let mut rounds = vec![polygon];
    for _ in 0..args.rounds {
        let last = rounds.last().expect("the input is round 0");
        let next = match args.scheme {
            Scheme::LaneRiesenfeld => lane_riesenfeld(last, args.degree.unwrap_or(3), 1, topology)?,
            Scheme::Chaikin => lane_riesenfeld(last, 2, 1, topology)?,
            Scheme::FourPoint => four_point(last, &w, 1, topology)?,
        };
        rounds.push(next);
    }
    Ok(rounds)
}

/// Options the chosen scheme does not take are errors.
fn check_options(args: &SubdivideArgs) -> Result<(), CliError> {
    let usage = |m: &str| Err(CliError::Usage(m.to_string()));
    match args.scheme {
        Scheme::FourPoint if args.degree.is_some() => {
            usage("--degree applies to lane-riesenfeld only; four-point has no degree")
        }
        Scheme::Chaikin if args.degree.is_some_and(|d| d != 2) => {
            usage("chaikin is degree 2; use --scheme lane-riesenfeld for another degree")
        }
        Scheme::LaneRiesenfeld | Scheme::Chaikin if args.tension.is_some() => {
            usage("--tension applies to four-point only")
        }
        _ => Ok(()),
    }
}

fn run_typed<S: JsonScalar, const D: usize>(
    args: &SubdivideArgs,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let polygon: Vec<Point<S, D>> = to_points(rows, |i| format!("point {i}"))?;
    let topology = if args.closed {
        Topology::Closed
    } else {
        Topology::Open
    };
    let mut counts = Counts::default();
    let mut out = match args.scheme {
        Scheme::LaneRiesenfeld | Scheme::Chaikin => {
            let degree = match args.scheme {
                Scheme::Chaikin => 2,
                _ => args.degree.unwrap_or(3),
            };
            let refined =
                lane_riesenfeld_with(&polygon, degree, args.rounds, topology, &mut counts)?;
            let limit = limit_points(&refined, degree, topology)?;
            let mask = Mask::<S>::lane_riesenfeld(degree)?;
            json!({
                "degree": degree,
                "points": points(&refined, "points")?,
                "limit": points(&limit, "limit")?,
                "mask": mask_json(&mask)?,
            })
        }
        Scheme::FourPoint => {
            let w: S = match &args.tension {
                Some(text) => parse_scalar(text, "tension")?,
                None => S::from_ratio(1, 16),
            };
            let refined = four_point_with(&polygon, &w, args.rounds, topology, &mut counts)?;
            json!({
                "tension": scalars(std::slice::from_ref(&w), "tension")?[0],
                "points": points(&refined, "points")?,
                "mask": mask_json(&Mask::four_point(&w)?)?,
            })
        }
    };
    out["scheme"] = json!(args
        .scheme
        .to_possible_value()
        .map(|v| v.get_name().to_string()));
    out["rounds"] = json!(args.rounds);
    out["closed"] = json!(args.closed);
    out["counts"] = json!(counts);
    Ok(out)
}

/// A mask as printed: the first exponent and the coefficients.
fn mask_json<S: JsonScalar>(mask: &Mask<S>) -> Result<Value, CliError> {
    Ok(json!({
        "start": mask.start(),
        "coefficients": scalars(mask.coefficients(), "mask.coefficients")?,
    }))
}
