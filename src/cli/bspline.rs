//! `compgeo bspline eval|insert|derivative|refine|remove|elevate|to-bezier|split|basis`: one
//! operation on a B-spline curve given by its control points, degree and knots, and
//! `compgeo bspline interpolate|fit`: a curve from data points; in `f64` or (with `--exact`)
//! in exact rationals.
//!
//! Control points are JSON `[[x, y], ...]` in any dimension from 1 to 4 (or `[x, ...]` for one
//! coordinate); knots are a flat list `[0, 0, 0, "1/2", 1, 1, 1]`. Numbers are JSON numbers or
//! strings such as `"47/18"`, read as `bezier` reads them (with `--exact`, `0.1` is 1/10 and
//! every number prints as a string). The knots follow the library's convention (n + d + 1 knots
//! for n control points of degree d, the domain [t_d, t_n]; see [`crate::spline::bspline`]), or
//! with `--spl` the lecture notes' (n + d − 1 knots, without the two end knots). Without
//! `--knots` the curve is clamped and uniform on [0, 1]; without `--degree` it is cubic (or of
//! degree n − 1 for fewer than four control points). Curves print as
//! `{"degree": d, "knots": [...], "control": [...]}`. Errors name the control point and
//! coordinate, the knot, or the parameter that is wrong, with its value.

use super::bezier::{point, points, scalars, JsonScalar};
use super::input::{inline_or_stdin, parse_number_arrays, parse_number_list};
use super::interpolate::{read_scalars, to_points, Knots};
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::spline::{parameterise, parse_scalar, BSpline, CurveDerivative, KnotVector, Point};
use clap::{Args, Subcommand};
use num_rational::BigRational;
use serde_json::{json, Value};

/// Arguments of `compgeo bspline`.
#[derive(Debug, Args)]
pub(super) struct BsplineArgs {
    #[command(subcommand)]
    op: Op,
}

/// The operations.
#[derive(Debug, Subcommand)]
enum Op {
    /// The point s(u) by de Boor's algorithm, its span and counts (or --trace for the net)
    Eval {
        #[command(flatten)]
        curve: CurveArgs,
        /// The parameter, in the domain [t_d, t_n]: a decimal or a fraction such as 1/3
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// Also print the de Boor net: every level of the scheme
        #[arg(long)]
        trace: bool,
    },
    /// The same curve with the knot u inserted r times (Boehm's algorithm)
    Insert {
        #[command(flatten)]
        curve: CurveArgs,
        /// The knot to insert, in the domain
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// How many times (the knot's multiplicity may reach the degree)
        #[arg(long, default_value_t = 1)]
        times: usize,
    },
    /// The r-th derivative curve, and its value at u if given
    Derivative {
        #[command(flatten)]
        curve: CurveArgs,
        /// The order r of the derivative
        #[arg(long, default_value_t = 1)]
        order: usize,
        /// Also evaluate the derivative at this parameter, and every order up to it (the
        /// extended de Boor algorithm)
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: Option<String>,
    },
    /// The same curve with all the given knots inserted at once (one backward pass of
    /// Boehm's insertions, or the Oslo algorithm)
    Refine {
        #[command(flatten)]
        curve: CurveArgs,
        /// The knots to insert, JSON ["1/4", 0.5, ...], in the domain (any order)
        #[arg(long = "new", value_name = "JSON", allow_hyphen_values = true)]
        new: String,
        /// Compute the new control points by the Oslo algorithm (the same curve; its own
        /// counts) instead of one backward pass of Boehm's insertions
        #[arg(long)]
        oslo: bool,
    },
    /// The same curve with the knot u removed r times, if the curve allows it
    Remove {
        #[command(flatten)]
        curve: CurveArgs,
        /// The knot to remove, strictly inside the domain
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// How many times
        #[arg(long, default_value_t = 1)]
        times: usize,
        /// Accept a removal that moves every control point by at most this distance
        /// [default: exact removal only]
        #[arg(long, value_name = "DISTANCE", allow_hyphen_values = true)]
        tolerance: Option<String>,
    },
    /// The same curve in a degree t higher (every knot t more times)
    Elevate {
        #[command(flatten)]
        curve: CurveArgs,
        /// How many degrees to raise
        #[arg(long, default_value_t = 1)]
        times: usize,
    },
    /// The Bézier pieces of the curve, one per non-empty knot interval of the domain
    ToBezier {
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// The two curves on [t_d, u] and [u, t_n]
    Split {
        #[command(flatten)]
        curve: CurveArgs,
        /// Where to split, strictly inside the domain
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
    },
    /// The B-spline of a degree through the points (collocation, averaged knots)
    Interpolate {
        #[command(flatten)]
        data: DataArgs,
    },
    /// The least-squares B-spline with the given number of control points (clamped uniform knots)
    Fit {
        #[command(flatten)]
        data: DataArgs,
        /// The number of control points, at least degree + 1
        #[arg(long)]
        control_points: usize,
    },
    /// The non-zero basis functions N_{μ−d}, …, N_μ at u (and their derivatives)
    Basis {
        /// The knots, JSON [0, 0, "1/2", 1, 1]
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        knots: String,
        /// The degree d
        #[arg(long)]
        degree: usize,
        /// Read --knots in the lecture notes' convention, without the two end knots
        #[arg(long)]
        spl: bool,
        /// The parameter, in the domain [t_d, t_n]
        #[arg(long = "u", value_name = "U", allow_hyphen_values = true)]
        u: String,
        /// Also print the derivatives of orders 1 to K
        #[arg(long, value_name = "K")]
        derivatives: Option<usize>,
        /// Compute in exact rationals and print every number as a string such as "47/18"
        #[arg(long)]
        exact: bool,
    },
}

/// The curve and the arithmetic, shared by the curve operations.
#[derive(Debug, Args)]
pub(super) struct CurveArgs {
    /// Control points as JSON [[x, y], ...] (dimension 1 to 4), or `-` to read them from stdin
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    pub(super) control: String,
    /// The degree d [default: 3, or n − 1 for n < 4 control points]
    #[arg(long)]
    degree: Option<usize>,
    /// The knots, JSON [0, 0, 0, 0, "1/2", 1, 1, 1, 1]: n + d + 1 of them [default: clamped
    /// and uniform on [0, 1]]
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    knots: Option<String>,
    /// Read --knots in the lecture notes' convention: n + d − 1 knots, without the end ones
    #[arg(long)]
    spl: bool,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    pub(super) exact: bool,
}

/// The data of `interpolate` and `fit`.
#[derive(Debug, Args)]
struct DataArgs {
    /// The points, JSON [[x, y], ...] (dimension 1 to 4)
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    points: String,
    /// The degree d
    #[arg(long, default_value_t = 3)]
    degree: usize,
    /// How to choose the parameters of the points
    #[arg(long, value_enum, default_value = "chord-length")]
    parameterisation: Knots,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    exact: bool,
}

/// Runs `compgeo bspline`.
pub(super) fn run(args: BsplineArgs) -> Result<(), CliError> {
    let curve = match &args.op {
        Op::Eval { curve, .. }
        | Op::Insert { curve, .. }
        | Op::Derivative { curve, .. }
        | Op::Refine { curve, .. }
        | Op::Remove { curve, .. }
        | Op::Elevate { curve, .. }
        | Op::ToBezier { curve, .. }
        | Op::Split { curve, .. } => curve,
        Op::Interpolate { data } | Op::Fit { data, .. } => {
            let rows = parse_number_arrays(&data.points)?;
            let d = rows[0].len();
            let value =
                by_scalar_and_dimension!(data.exact, d, "points", run_data(&args.op, data, &rows))?;
            return print_json(&value);
        }
        Op::Basis {
            knots,
            degree,
            spl,
            u,
            derivatives,
            exact,
        } => {
            let value = if *exact {
                basis::<BigRational>(knots, *degree, *spl, u, *derivatives)?
            } else {
                basis::<f64>(knots, *degree, *spl, u, *derivatives)?
            };
            return print_json(&value);
        }
    };
    let text = inline_or_stdin(&curve.control)?;
    let rows = parse_number_arrays(&text)?;
    let d = rows[0].len();
    let value = by_scalar_and_dimension!(
        curve.exact,
        d,
        "control points",
        run_typed(&args.op, curve, &rows)
    )?;
    print_json(&value)
}

/// The knot vector from `--knots` (in either convention), named in errors by index.
fn knot_vector<S: JsonScalar>(
    text: &str,
    degree: usize,
    spl: bool,
) -> Result<KnotVector<S>, CliError> {
    let knots = read_scalars::<S>(text, "knot", "knots")?;
    Ok(if spl {
        KnotVector::from_spl(degree, &knots)?
    } else {
        KnotVector::new(degree, knots)?
    })
}

/// The curve the arguments describe.
pub(super) fn curve_of<S: JsonScalar, const D: usize>(
    args: &CurveArgs,
    rows: &[Vec<String>],
) -> Result<BSpline<S, D>, CliError> {
    let control: Vec<Point<S, D>> = to_points(rows, |i| format!("control point {i}"))?;
    let n = control.len();
    let degree = args.degree.unwrap_or(3.min(n - 1));
    let knots = match &args.knots {
        Some(text) => knot_vector(text, degree, args.spl)?,
        None => KnotVector::clamped_uniform(degree, n, S::zero(), S::one())?,
    };
    Ok(BSpline::new(control, knots)?)
}

/// A curve as printed: degree, knots and control points.
fn curve_json<S: JsonScalar, const D: usize>(s: &BSpline<S, D>) -> Result<Value, CliError> {
    Ok(json!({
        "degree": s.degree(),
        "knots": scalars(s.knots().knots(), "knots")?,
        "control": points(s.control(), "control")?,
    }))
}

fn run_typed<S: JsonScalar, const D: usize>(
    op: &Op,
    args: &CurveArgs,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let s = curve_of::<S, D>(args, rows)?;
    Ok(match op {
        Op::Eval { u, trace, .. } => {
            let u: S = parse_scalar(u, "u")?;
            let mut counts = Counts::default();
            let p = s.de_boor_with(&u, &mut counts)?;
            let mut out = json!({
                "point": point(&p, "point")?,
                "degree": s.degree(),
                "span": s.knots().span(&u)?,
                "counts": counts,
            });
            if *trace {
                let net = s.de_boor_trace(&u)?;
                let levels = net
                    .iter()
                    .enumerate()
                    .map(|(k, f)| points(&f.step.points, &format!("trace.levels[{k}]")))
                    .collect::<Result<Vec<_>, _>>()?;
                out["trace"] = json!({
                    "first": net[0].step.first(),
                    "multiplicity": net[0].step.multiplicity,
                    "levels": levels,
                });
            }
            out
        }
        Op::Insert { u, times, .. } => {
            let u: S = parse_scalar(u, "u")?;
            let mut counts = Counts::default();
            let r = s.insert_with(&u, *times, &mut counts)?;
            let mut out = curve_json(&r)?;
            out["counts"] = json!(counts);
            out
        }
        Op::Derivative { order, u, .. } => {
            // Past the degree every derivative is the zero curve of degree 0: d + 1 steps at
            // most, however large the order.
            let mut curve = s.clone();
            for _ in 0..(*order).min(s.degree() + 1) {
                curve = curve.derivative_curve()?;
            }
            let mut out = curve_json(&curve)?;
            out["order"] = json!(order);
            if let Some(u) = u {
                let u: S = parse_scalar(u, "u")?;
                out["point"] = point(&s.derivative_at(&u, *order)?, "point")?;
                // Every order up to this one at u, by the extended de Boor algorithm.
                let mut counts = Counts::default();
                let all = s.derivatives_with(&u, *order, &mut counts)?;
                out["derivatives"] = points(&all, "derivatives")?;
                out["counts"] = json!(counts);
            }
            out
        }
        Op::Refine { new, oslo, .. } => {
            let knots = read_scalars::<S>(new, "new knot", "new knots")?;
            let mut counts = Counts::default();
            let r = if *oslo {
                s.oslo_with(&knots, &mut counts)?
            } else {
                s.refine_with(&knots, &mut counts)?
            };
            let mut out = curve_json(&r)?;
            out["counts"] = json!(counts);
            out
        }
        Op::Remove {
            u,
            times,
            tolerance,
            ..
        } => {
            let u: S = parse_scalar(u, "u")?;
            let r = match tolerance {
                None => s.remove(&u, *times)?,
                Some(text) => s.remove_within(&u, *times, &parse_scalar(text, "tolerance")?)?,
            };
            curve_json(&r)?
        }
        Op::Elevate { times, .. } => {
            let mut counts = Counts::default();
            let r = s.elevate_with(*times, &mut counts)?;
            let mut out = curve_json(&r)?;
            out["counts"] = json!(counts);
            out
        }
        Op::ToBezier { .. } => {
            let pieces = s.to_bezier()?;
            let printed = pieces
                .pieces()
                .iter()
                .enumerate()
                .map(|(k, b)| points(b.control(), &format!("pieces[{k}]")))
                .collect::<Result<Vec<_>, _>>()?;
            json!({
                "degree": s.degree(),
                "breakpoints": scalars(pieces.partition(), "breakpoints")?,
                "pieces": printed,
            })
        }
        Op::Split { u, .. } => {
            let u: S = parse_scalar(u, "u")?;
            let (left, right) = s.split(&u)?;
            json!({"left": curve_json(&left)?, "right": curve_json(&right)?})
        }
        Op::Interpolate { .. } | Op::Fit { .. } | Op::Basis { .. } => {
            unreachable!("interpolate, fit and basis read no control points and run before")
        }
    })
}

/// `interpolate` and `fit`: a curve from data points.
fn run_data<S: JsonScalar, const D: usize>(
    op: &Op,
    data: &DataArgs,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let pts: Vec<Point<S, D>> = to_points(rows, |i| format!("point {i}"))?;
    let kind = data.parameterisation.kind();
    let mut counts = Counts::default();
    let s = match op {
        Op::Fit { control_points, .. } => {
            let params = parameterise(&pts, kind)?;
            let (first, last) = (params[0].clone(), params[params.len() - 1].clone());
            let knots = KnotVector::clamped_uniform(data.degree, *control_points, first, last)?;
            BSpline::fit_with(&pts, &params, knots, &mut counts)?
        }
        _ => BSpline::interpolate_with(&pts, data.degree, kind, &mut counts)?,
    };
    let mut out = curve_json(&s)?;
    out["counts"] = json!(counts);
    Ok(out)
}

/// `compgeo bspline basis`: the non-zero basis functions at u, and their derivatives.
fn basis<S: JsonScalar>(
    knots: &str,
    degree: usize,
    spl: bool,
    u: &str,
    derivatives: Option<usize>,
) -> Result<Value, CliError> {
    // Fail on an empty or malformed list before the degree is checked against it.
    parse_number_list(knots, "knots")?;
    let t = knot_vector::<S>(knots, degree, spl)?;
    let u: S = parse_scalar(u, "u")?;
    let b = t.basis(&u)?;
    let mut out = json!({
        "span": b.span(),
        "first": b.first(),
        "values": scalars(b.values(), "values")?,
    });
    if let Some(k) = derivatives {
        let ds = t.basis_derivatives(&u, k)?;
        let orders = (1..=ds.orders())
            .map(|r| scalars(ds.order(r), &format!("derivatives[{}]", r - 1)))
            .collect::<Result<Vec<_>, _>>()?;
        out["derivatives"] = Value::Array(orders);
    }
    Ok(out)
}
