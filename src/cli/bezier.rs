//! `compgeo bezier eval|split|elevate|derivative`: one operation on a Bézier curve given by
//! its control points, in `f64` or (with `--exact`) in exact rationals.
//!
//! Control points are JSON, `[[x, y], ...]` in any dimension from 1 to 4 (or `[x, ...]` for
//! one coordinate), whose numbers are JSON numbers or strings such as `"47/18"`. With
//! `--exact` every number is read as the exact rational it writes (`0.1` is 1/10) and printed
//! as a string (`"47/18"`, `"-3"`); without it numbers are `f64` in and out.

use super::input::parse_number_arrays;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::spline::bezier::{evaluate_with, Evaluation};
use crate::spline::{parse_scalar, Bezier, CurveDerivative, ParseScalar, Point, Scalar};
use clap::{Args, Subcommand};
use num_rational::BigRational;
use serde_json::{json, Value};
use std::io::Read;

/// Arguments of `compgeo bezier`.
#[derive(Debug, Args)]
pub(super) struct BezierArgs {
    #[command(subcommand)]
    op: Op,
}

/// The operations.
#[derive(Debug, Subcommand)]
enum Op {
    /// The point b(t) (any t, also outside [0, 1]) and the operations it took
    Eval {
        #[command(flatten)]
        curve: CurveArgs,
        /// The parameter: a decimal or a fraction such as 1/3
        #[arg(long = "t", value_name = "T", allow_hyphen_values = true)]
        t: String,
        #[arg(long, default_value = "de-casteljau", help = Evaluation::names(),
            long_help = Evaluation::help())]
        algorithm: Evaluation,
    },
    /// The control points of the two pieces over [0, t] and [t, 1]
    Split {
        #[command(flatten)]
        curve: CurveArgs,
        /// Where to split: a decimal or a fraction such as 1/3
        #[arg(long = "t", value_name = "T", allow_hyphen_values = true)]
        t: String,
    },
    /// The control points of the same curve in a higher degree
    Elevate {
        #[command(flatten)]
        curve: CurveArgs,
        /// The target degree, at most MAX_DEGREE = 65536 [default: the curve's degree plus one]
        #[arg(long)]
        degree: Option<usize>,
    },
    /// The control points of the r-th derivative curve, and its value at t if given
    Derivative {
        #[command(flatten)]
        curve: CurveArgs,
        /// The order r of the derivative (above the curve's degree: the zero curve)
        #[arg(long, default_value_t = 1)]
        order: usize,
        /// Also evaluate the derivative at this parameter
        #[arg(long = "t", value_name = "T", allow_hyphen_values = true)]
        t: Option<String>,
    },
}

/// The curve and the arithmetic, shared by every operation.
#[derive(Debug, Args)]
struct CurveArgs {
    /// Control points as JSON [[x, y], ...] (dimension 1 to 4; numbers or strings such as
    /// "1/3"), or `-` to read them from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    control: String,
    /// Compute in exact rationals and print every coordinate as a string such as "47/18"
    #[arg(long)]
    exact: bool,
}

/// Runs `compgeo bezier`.
pub(super) fn run(args: BezierArgs) -> Result<(), CliError> {
    let curve = match &args.op {
        Op::Eval { curve, .. }
        | Op::Split { curve, .. }
        | Op::Elevate { curve, .. }
        | Op::Derivative { curve, .. } => curve,
    };
    let text = if curve.control == "-" {
        let mut s = String::new();
        std::io::stdin()
            .read_to_string(&mut s)
            .map_err(|source| CliError::Read {
                path: "stdin".to_string(),
                source,
            })?;
        s
    } else {
        curve.control.clone()
    };
    let rows = parse_number_arrays(&text)?;
    let d = rows[0].len();
    let value = match (curve.exact, d) {
        (false, 1) => run_typed::<f64, 1>(&args.op, &rows)?,
        (false, 2) => run_typed::<f64, 2>(&args.op, &rows)?,
        (false, 3) => run_typed::<f64, 3>(&args.op, &rows)?,
        (false, 4) => run_typed::<f64, 4>(&args.op, &rows)?,
        (true, 1) => run_typed::<BigRational, 1>(&args.op, &rows)?,
        (true, 2) => run_typed::<BigRational, 2>(&args.op, &rows)?,
        (true, 3) => run_typed::<BigRational, 3>(&args.op, &rows)?,
        (true, 4) => run_typed::<BigRational, 4>(&args.op, &rows)?,
        _ => {
            return Err(CliError::Shape(format!(
                "control points have {d} coordinates; 1 to 4 are supported"
            )))
        }
    };
    print_json(&value)
}

/// A scalar the command line can print: `f64` as a JSON number, rationals as strings.
pub(super) trait JsonScalar: Scalar + ParseScalar {
    fn to_json(&self) -> Result<Value, CliError>;
}

impl JsonScalar for f64 {
    fn to_json(&self) -> Result<Value, CliError> {
        if self.is_finite() {
            Ok(json!(self))
        } else {
            Err(CliError::Usage(
                "the result is beyond the range of f64; use --exact".to_string(),
            ))
        }
    }
}

impl JsonScalar for BigRational {
    fn to_json(&self) -> Result<Value, CliError> {
        Ok(Value::String(self.to_string()))
    }
}

fn run_typed<S: JsonScalar, const D: usize>(
    op: &Op,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let control = rows
        .iter()
        .map(|row| {
            let mut p = Point::<S, D>::zero();
            for (j, text) in row.iter().enumerate() {
                p[j] = parse_scalar(text, "control point coordinate")?;
            }
            Ok(p)
        })
        .collect::<Result<Vec<_>, crate::Error>>()?;
    let b = Bezier::new(control)?;
    let n = b.degree();
    Ok(match op {
        Op::Eval { t, algorithm, .. } => {
            let t: S = parse_scalar(t, "t")?;
            let mut counts = Counts::default();
            let p = evaluate_with(&b, &t, *algorithm, &mut counts)?;
            json!({"point": point(&p)?, "degree": n, "algorithm": algorithm.name(), "counts": counts})
        }
        Op::Split { t, .. } => {
            let c: S = parse_scalar(t, "t")?;
            let (left, right) = b.split(&c)?;
            json!({"left": points(left.control())?, "right": points(right.control())?})
        }
        Op::Elevate { degree, .. } => {
            let m = degree.unwrap_or(n + 1);
            let e = b.elevate_to(m)?;
            json!({"control": points(e.control())?, "degree": m})
        }
        Op::Derivative { order, t, .. } => {
            let dcurve = b.derivative(*order)?;
            let mut out = json!({
                "control": points(dcurve.control())?,
                "degree": dcurve.degree(),
                "order": order,
            });
            if let Some(t) = t {
                let t: S = parse_scalar(t, "t")?;
                out["point"] = point(&b.derivative_at(&t, *order)?)?;
            }
            out
        }
    })
}

pub(super) fn point<S: JsonScalar, const D: usize>(p: &Point<S, D>) -> Result<Value, CliError> {
    Ok(Value::Array(
        p.coords()
            .iter()
            .map(JsonScalar::to_json)
            .collect::<Result<_, _>>()?,
    ))
}

pub(super) fn points<S: JsonScalar, const D: usize>(ps: &[Point<S, D>]) -> Result<Value, CliError> {
    Ok(Value::Array(
        ps.iter().map(point).collect::<Result<_, _>>()?,
    ))
}
