//! `compgeo beta eval|matrices|subdivide`: cubic Beta-splines with bias `--beta1` and tension
//! `--beta2`, in `f64` or (with `--exact`) in exact rationals.
//!
//! The parameters are numbers or fractions (`--beta1 3/2`); β₁ must be positive and β₂
//! non-negative unless `--allow-negative-tension` (the seed's third example uses β₂ = −10);
//! values where the construction divides by zero are refused with the parameter's name.
//! Control points are read as `compgeo bezier` reads them (JSON, dimension 1 to 4, at least
//! four points; `-` for stdin). `eval` prints the point at `--u` in [0, m], m the number of
//! segments; `matrices` prints S_L, S_R (rows), the Bernstein matrix C, δ and the
//! convex-hull predicate at `--c`; `subdivide` prints the m·2ᵏ control polygons after
//! `--rounds` rounds at `--c`.

use super::bezier::{point, points, scalars, JsonScalar};
use super::input::{inline_or_stdin, parse_number_arrays};
use super::interpolate::to_points;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::spline::{parse_scalar, BetaParameters, BetaSpline, Matrix4};
use clap::{Args, Subcommand};
use num_rational::BigRational;
use serde_json::{json, Value};

/// Arguments of `compgeo beta`.
#[derive(Debug, Args)]
pub(super) struct BetaArgs {
    #[command(subcommand)]
    op: Op,
}

/// The operations.
#[derive(Debug, Subcommand)]
enum Op {
    /// The point at u in [0, m] (m = control points − 3 segments) and the operations it took
    Eval {
        #[command(flatten)]
        shape: ShapeArgs,
        #[command(flatten)]
        control: ControlArgs,
        /// The parameter, in [0, m]: segment ⌊u⌋ at t = u − ⌊u⌋
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
    },
    /// The subdivision matrices S_L and S_R at c, the Bernstein matrix C and the convex-hull predicate
    Matrices {
        #[command(flatten)]
        shape: ShapeArgs,
        /// Where to split each segment, strictly between 0 and 1
        #[arg(
            long = "c",
            value_name = "C",
            default_value = "1/2",
            allow_hyphen_values = true
        )]
        c: String,
    },
    /// The control polygons after k rounds of subdivision at c: m·2^k polygons of four points
    Subdivide {
        #[command(flatten)]
        shape: ShapeArgs,
        #[command(flatten)]
        control: ControlArgs,
        /// Where to split each polygon, strictly between 0 and 1
        #[arg(
            long = "c",
            value_name = "C",
            default_value = "1/2",
            allow_hyphen_values = true
        )]
        c: String,
        /// How many rounds (the output, m·2^k polygons, is at most MAX_SUBDIVIDED_PIECES = 1048576)
        #[arg(long, default_value_t = 1)]
        rounds: u32,
    },
}

/// The shape parameters and the arithmetic.
#[derive(Debug, Args)]
pub(super) struct ShapeArgs {
    /// The bias β₁ > 0: a number or a fraction such as 3/2
    #[arg(
        long,
        value_name = "B1",
        default_value = "1",
        allow_hyphen_values = true
    )]
    beta1: String,
    /// The tension β₂ ≥ 0: a number or a fraction
    #[arg(
        long,
        value_name = "B2",
        default_value = "0",
        allow_hyphen_values = true
    )]
    beta2: String,
    /// Accept a negative tension (the basis may then be negative); β₂ = −2β₁(β₁ + 1) and
    /// δ = 0 are still refused
    #[arg(long)]
    allow_negative_tension: bool,
    /// Compute in exact rationals and print every number as a string such as "79/153"
    #[arg(long)]
    pub(super) exact: bool,
}

/// The control polygon.
#[derive(Debug, Args)]
pub(super) struct ControlArgs {
    /// Control points as JSON [[x, y], ...] (at least four; dimension 1 to 4; numbers or
    /// strings such as "1/3"), or `-` to read them from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    pub(super) control: String,
}

/// Runs `compgeo beta`.
pub(super) fn run(args: BetaArgs) -> Result<(), CliError> {
    let value = match &args.op {
        Op::Matrices { shape, c } => {
            if shape.exact {
                matrices::<BigRational>(shape, c)?
            } else {
                matrices::<f64>(shape, c)?
            }
        }
        Op::Eval { shape, control, .. } | Op::Subdivide { shape, control, .. } => {
            let text = inline_or_stdin(&control.control)?;
            let rows = parse_number_arrays(&text)?;
            let d = rows[0].len();
            by_scalar_and_dimension!(
                shape.exact,
                d,
                "control points",
                run_curve(&args.op, shape, &rows)
            )?
        }
    };
    print_json(&value)
}

/// The validated parameters.
fn parameters<S: JsonScalar>(shape: &ShapeArgs) -> Result<BetaParameters<S>, CliError> {
    let b1: S = parse_scalar(&shape.beta1, "beta1")?;
    let b2: S = parse_scalar(&shape.beta2, "beta2")?;
    Ok(if shape.allow_negative_tension {
        BetaParameters::allowing_negative_tension(b1, b2)?
    } else {
        BetaParameters::new(b1, b2)?
    })
}

/// The Beta-spline the arguments describe.
pub(super) fn beta_of<S: JsonScalar, const D: usize>(
    shape: &ShapeArgs,
    rows: &[Vec<String>],
) -> Result<BetaSpline<S, D>, CliError> {
    let p = parameters::<S>(shape)?;
    let control = to_points::<S, D>(rows, |i| format!("control point {i}"))?;
    Ok(BetaSpline::new(p, control)?)
}

/// A 4 × 4 matrix printed as its rows.
fn matrix<S: JsonScalar>(m: &Matrix4<S>, name: &str) -> Result<Value, CliError> {
    m.iter()
        .enumerate()
        .map(|(i, row)| scalars(row, &format!("{name}[{i}]")))
        .collect::<Result<_, _>>()
        .map(Value::Array)
}

fn matrices<S: JsonScalar>(shape: &ShapeArgs, c: &str) -> Result<Value, CliError> {
    let p = parameters::<S>(shape)?;
    let c: S = parse_scalar(c, "c")?;
    let mut counts = Counts::default();
    let m = p.subdivision_matrices_with(&c, &mut counts)?;
    Ok(json!({
        "beta1": scalars(std::slice::from_ref(p.beta1()), "beta1")?[0],
        "beta2": scalars(std::slice::from_ref(p.beta2()), "beta2")?[0],
        "delta": scalars(std::slice::from_ref(p.delta()), "delta")?[0],
        "c": scalars(std::slice::from_ref(&c), "c")?[0],
        "left": matrix(m.left(), "left")?,
        "right": matrix(m.right(), "right")?,
        "bernstein": matrix(&p.bernstein_matrix(), "bernstein")?,
        "keeps_convex_hull": {
            "left": m.left_keeps_convex_hull(),
            "right": m.right_keeps_convex_hull(),
        },
        "counts": counts,
    }))
}

fn run_curve<S: JsonScalar, const D: usize>(
    op: &Op,
    shape: &ShapeArgs,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let s = beta_of::<S, D>(shape, rows)?;
    let mut counts = Counts::default();
    Ok(match op {
        Op::Eval { u, .. } => {
            let u: S = parse_scalar(u, "u")?;
            let q = s.eval_with(&u, &mut counts)?;
            json!({"point": point(&q, "point")?, "segments": s.segments(), "counts": counts})
        }
        Op::Subdivide { c, rounds, .. } => {
            let c: S = parse_scalar(c, "c")?;
            let pieces = s.subdivide_with(&c, *rounds, &mut counts)?;
            let printed = pieces
                .iter()
                .enumerate()
                .map(|(k, poly)| points(poly, &format!("pieces[{k}]")))
                .collect::<Result<Vec<_>, CliError>>()?;
            json!({"pieces": printed, "rounds": rounds, "segments": s.segments(), "counts": counts})
        }
        Op::Matrices { .. } => unreachable!("`matrices` takes no control points"),
    })
}
