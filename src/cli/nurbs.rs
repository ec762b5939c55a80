//! `compgeo nurbs eval|insert|elevate|to-bezier`: one operation on a NURBS curve given by its
//! control points, weights, degree and knots, in `f64` or (with `--exact`) in exact rationals.
//!
//! The curve is read as `compgeo bspline` reads it (control points, `--degree`, `--knots` in
//! either convention, clamped uniform on [0, 1] by default), plus `--weights`, a flat list of
//! positive numbers, one per control point. Curves print as
//! `{"degree", "knots", "control", "weights"}`; `to-bezier` prints the breakpoints and each
//! rational Bézier piece's control points and weights. Errors name the index and the value.

use super::bezier::{point, points, scalars, JsonScalar};
use super::bspline::{curve_of, CurveArgs};
use super::input::{inline_or_stdin, parse_number_arrays};
use super::interpolate::read_scalars;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::spline::{parse_scalar, Nurbs};
use clap::{Args, Subcommand};
use serde_json::{json, Value};

/// Arguments of `compgeo nurbs`.
#[derive(Debug, Args)]
pub(super) struct NurbsArgs {
    #[command(subcommand)]
    op: Op,
}

/// The operations.
#[derive(Debug, Subcommand)]
enum Op {
    /// The point s(u) (de Boor on the homogeneous form) and the operations it took
    Eval {
        #[command(flatten)]
        curve: RationalArgs,
        /// The parameter, in the domain [t_d, t_n]
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
    },
    /// The same curve with the knot u inserted r times
    Insert {
        #[command(flatten)]
        curve: RationalArgs,
        /// The knot to insert, in the domain
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// How many times (the multiplicity may reach the degree)
        #[arg(long, default_value_t = 1)]
        times: usize,
    },
    /// The same curve in a degree t higher (clamped ends only)
    Elevate {
        #[command(flatten)]
        curve: RationalArgs,
        /// How many degrees to raise
        #[arg(long, default_value_t = 1)]
        times: usize,
    },
    /// The rational Bézier pieces, one per non-empty knot interval of the domain
    ToBezier {
        #[command(flatten)]
        curve: RationalArgs,
    },
}

/// A B-spline curve and its weights.
#[derive(Debug, Args)]
pub(super) struct RationalArgs {
    #[command(flatten)]
    pub(super) curve: CurveArgs,
    /// The weights, JSON [1, "1/2", ...]: one per control point, finite and positive
    /// [default: all 1]
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    weights: Option<String>,
}

/// Runs `compgeo nurbs`.
pub(super) fn run(args: NurbsArgs) -> Result<(), CliError> {
    let rational = match &args.op {
        Op::Eval { curve, .. }
        | Op::Insert { curve, .. }
        | Op::Elevate { curve, .. }
        | Op::ToBezier { curve } => curve,
    };
    let text = inline_or_stdin(&rational.curve.control)?;
    let rows = parse_number_arrays(&text)?;
    let d = rows[0].len();
    let value = by_scalar_and_dimension!(
        rational.curve.exact,
        d,
        "control points",
        run_typed(&args.op, rational, &rows)
    )?;
    print_json(&value)
}

/// A NURBS curve as printed.
fn nurbs_json<S: JsonScalar, const D: usize>(s: &Nurbs<S, D>) -> Result<Value, CliError> {
    Ok(json!({
        "degree": s.degree(),
        "knots": scalars(s.knots().knots(), "knots")?,
        "control": points(s.control(), "control")?,
        "weights": scalars(s.weights(), "weights")?,
    }))
}

/// The curve the arguments describe.
pub(super) fn nurbs_of<S: JsonScalar, const D: usize>(
    args: &RationalArgs,
    rows: &[Vec<String>],
) -> Result<Nurbs<S, D>, CliError> {
    let b = curve_of::<S, D>(&args.curve, rows)?;
    let weights = match &args.weights {
        Some(text) => read_scalars::<S>(text, "weight", "weights")?,
        None => vec![S::one(); b.control().len()],
    };
    let (control, knots) = b.into_parts();
    Ok(Nurbs::new(control, weights, knots)?)
}

fn run_typed<S: JsonScalar, const D: usize>(
    op: &Op,
    args: &RationalArgs,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let s = nurbs_of::<S, D>(args, rows)?;
    Ok(match op {
        Op::Eval { u, .. } => {
            let u: S = parse_scalar(u, "u")?;
            let mut counts = Counts::default();
            let p = s.de_boor_with(&u, &mut counts)?;
            json!({"point": point(&p, "point")?, "degree": s.degree(), "counts": counts})
        }
        Op::Insert { u, times, .. } => {
            let u: S = parse_scalar(u, "u")?;
            nurbs_json(&s.insert(&u, *times)?)?
        }
        Op::Elevate { times, .. } => nurbs_json(&s.elevate(*times)?)?,
        Op::ToBezier { .. } => {
            let (breaks, pieces) = s.to_bezier()?;
            let printed = pieces
                .iter()
                .enumerate()
                .map(|(k, b)| {
                    Ok(json!({
                        "control": points(b.control(), &format!("pieces[{k}].control"))?,
                        "weights": scalars(b.weights(), &format!("pieces[{k}].weights"))?,
                    }))
                })
                .collect::<Result<Vec<_>, CliError>>()?;
            json!({
                "degree": s.degree(),
                "breakpoints": scalars(&breaks, "breakpoints")?,
                "pieces": printed,
            })
        }
    })
}
