//! `compgeo bezier eval|split|elevate|derivative`: one operation on a Bézier curve given by
//! its control points, in `f64` or (with `--exact`) in exact rationals.
//!
//! Control points are JSON, `[[x, y], ...]` in any dimension from 1 to 4 (or `[x, ...]` for
//! one coordinate), whose numbers are JSON numbers or strings such as `"47/18"`. With
//! `--exact` every number is read as the exact rational it writes (`0.1` is 1/10) and printed
//! as a string (`"47/18"`, `"-3"`); without it numbers are `f64` in and out. Reading is
//! bounded as [`parse_scalar`] documents (exact decimals of at most 1000 significant digits
//! and magnitude at least 1e-400; `f64` rounds any decimal as IEEE 754 does, so `1e-400`
//! is 0 without `--exact` and an error with it). Errors name the control point and
//! coordinate, or the entry of the result, that is wrong.

use super::input::{inline_or_stdin, parse_number_arrays};
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::spline::bezier::{evaluate_with, Evaluation};
use crate::spline::{
    parse_scalar, read_scalar, Bezier, Curve, CurveDerivative, ParseScalar, Point, Scalar,
};
use clap::{Args, Subcommand};
use num_rational::BigRational;
use serde_json::{json, Value};

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
pub(super) struct CurveArgs {
    /// Control points as JSON [[x, y], ...] (dimension 1 to 4; numbers or strings such as
    /// "1/3"), or `-` to read them from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    pub(super) control: String,
    /// Compute in exact rationals and print every coordinate as a string such as "47/18"
    #[arg(long)]
    pub(super) exact: bool,
}

/// Runs `compgeo bezier`.
pub(super) fn run(args: BezierArgs) -> Result<(), CliError> {
    let curve = match &args.op {
        Op::Eval { curve, .. }
        | Op::Split { curve, .. }
        | Op::Elevate { curve, .. }
        | Op::Derivative { curve, .. } => curve,
    };
    let text = inline_or_stdin(&curve.control)?;
    let rows = parse_number_arrays(&text)?;
    let d = rows[0].len();
    let value =
        by_scalar_and_dimension!(curve.exact, d, "control points", run_typed(&args.op, &rows))?;
    print_json(&value)
}

/// A scalar the command line can print: `f64` as a JSON number, rationals as strings.
pub(super) trait JsonScalar: Scalar + ParseScalar {
    /// The JSON value; `None` for an `f64` beyond its range (infinite or NaN).
    fn to_json(&self) -> Option<Value>;
}

impl JsonScalar for f64 {
    fn to_json(&self) -> Option<Value> {
        self.is_finite().then(|| json!(self))
    }
}

impl JsonScalar for BigRational {
    fn to_json(&self) -> Option<Value> {
        Some(Value::String(self.to_string()))
    }
}

/// Reads one input number, naming it by `what` ("control point 2, coordinate 1") if it is
/// not one: "invalid control point 2, coordinate 1: the number is outside the range of f64
/// (got "1e400")".
pub(super) fn read_number<S: JsonScalar>(
    text: &str,
    what: impl FnOnce() -> String,
) -> Result<S, CliError> {
    read_scalar(text).map_err(|reason| CliError::Shape(format!("invalid {}: {reason}", what())))
}

/// The numbers `xs` as a JSON array; an `f64` beyond its range is an error naming its place
/// in the output, `at(i)` for entry `i` ("pieces[1][2][0]").
fn numbers<S: JsonScalar>(xs: &[S], at: impl Fn(usize) -> String) -> Result<Value, CliError> {
    xs.iter()
        .enumerate()
        .map(|(i, x)| {
            x.to_json().ok_or_else(|| {
                CliError::Usage(format!(
                    "the result is beyond the range of f64 at {}; use --exact",
                    at(i)
                ))
            })
        })
        .collect::<Result<_, _>>()
        .map(Value::Array)
}

/// A list of numbers printed as the output field `name`.
pub(super) fn scalars<S: JsonScalar>(xs: &[S], name: &str) -> Result<Value, CliError> {
    numbers(xs, |i| format!("{name}[{i}]"))
}

/// A point printed as the output field `name`.
pub(super) fn point<S: JsonScalar, const D: usize>(
    p: &Point<S, D>,
    name: &str,
) -> Result<Value, CliError> {
    scalars(p.coords(), name)
}

/// A list of points printed as the output field `name`.
pub(super) fn points<S: JsonScalar, const D: usize>(
    ps: &[Point<S, D>],
    name: &str,
) -> Result<Value, CliError> {
    ps.iter()
        .enumerate()
        .map(|(i, p)| numbers(p.coords(), |j| format!("{name}[{i}][{j}]")))
        .collect::<Result<_, _>>()
        .map(Value::Array)
}

/// Why the `f64` point b(t) is not finite: `beyond` (the range error) if the exact value of
/// b(t) is beyond the range of `f64` too, else an error saying that the evaluation overflowed
/// on the way (both schemes can, far outside [0, 1], where large terms cancel: de Casteljau's
/// affine combinations and Horner's partial sums alike).
fn not_finite<S: JsonScalar, const D: usize>(
    b: &Bezier<S, D>,
    t: &S,
    beyond: CliError,
) -> CliError {
    let (Ok(rounded), Some(t)) = (b.to_f64(), <BigRational as Scalar>::from_f64(t.to_f64())) else {
        return beyond;
    };
    match Bezier::<BigRational, D>::from_f64(&rounded).eval(&t) {
        Ok(q) if q.coords().iter().all(|c| Scalar::to_f64(c).is_finite()) => CliError::Usage(
            "the point is within the range of f64, but its evaluation in f64 overflows at this t; use --exact"
                .to_string(),
        ),
        _ => beyond,
    }
}

fn run_typed<S: JsonScalar, const D: usize>(
    op: &Op,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let control = rows
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut p = Point::<S, D>::zero();
            for (j, text) in row.iter().enumerate() {
                p[j] = read_number(text, || format!("control point {i}, coordinate {j}"))?;
            }
            Ok(p)
        })
        .collect::<Result<Vec<_>, CliError>>()?;
    let b = Bezier::new(control)?;
    let n = b.degree();
    Ok(match op {
        Op::Eval { t, algorithm, .. } => {
            let t: S = parse_scalar(t, "t")?;
            let mut counts = Counts::default();
            let p = evaluate_with(&b, &t, *algorithm, &mut counts)?;
            let printed = point(&p, "point").map_err(|e| not_finite(&b, &t, e))?;
            json!({"point": printed, "degree": n, "algorithm": algorithm.name(), "counts": counts})
        }
        Op::Split { t, .. } => {
            let c: S = parse_scalar(t, "t")?;
            let (left, right) = b.split(&c)?;
            json!({"left": points(left.control(), "left")?, "right": points(right.control(), "right")?})
        }
        Op::Elevate { degree, .. } => {
            let m = degree.unwrap_or(n + 1);
            let e = b.elevate_to(m)?;
            json!({"control": points(e.control(), "control")?, "degree": m})
        }
        Op::Derivative { order, t, .. } => {
            let dcurve = b.derivative(*order)?;
            let mut out = json!({
                "control": points(dcurve.control(), "control")?,
                "degree": dcurve.degree(),
                "order": order,
            });
            if let Some(t) = t {
                let t: S = parse_scalar(t, "t")?;
                out["point"] = point(&b.derivative_at(&t, *order)?, "point")?;
            }
            out
        }
    })
}
