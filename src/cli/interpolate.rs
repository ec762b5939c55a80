//! `compgeo interpolate hermite|spline|lagrange|newton`: interpolation of points given as JSON,
//! in `f64` or (with `--exact`) in exact rationals.
//!
//! Points are `[[x, y], ...]` in any dimension from 1 to 4 (or `[x, ...]` for one coordinate);
//! knots, nodes and parameters are flat lists `[0, "1/2", 1]`. Numbers are JSON numbers or
//! strings such as `"47/18"`. With `--exact` every number is read as the exact rational it
//! writes and printed as a string; without it numbers are `f64` in and out. Composite curves
//! are printed as `{"knots": [...], "tangents": [...], "pieces": [[b_0, b_1, b_2, b_3], ...]}`
//! (the cubic Bézier points of each piece). `newton` prints the nodes of the Newton basis, the
//! divided differences and the power-basis coefficients; with `--derivatives` (first
//! derivatives at the nodes) it is Hermite interpolation, every node counted twice. Numbers
//! are read as `bezier` reads them (bounded exact reading, IEEE rounding for `f64`), and
//! errors name the point and coordinate, the knot, node or parameter, or the entry of the
//! result, that is wrong.

use super::bezier::{point, points, read_number, scalars, JsonScalar};
use super::input::{parse_number_arrays, parse_number_list};
use super::output::print_json;
use super::CliError;
use crate::spline::{
    cubic_spline_tangents, estimate_tangents, hermite, lagrange, newton, newton_hermite,
    parameterise, CompositeBezier, Curve, EndCondition, HermiteNode, Parameterisation, Point,
};
use clap::{Args, Subcommand, ValueEnum};
use serde_json::{json, Value};

/// Arguments of `compgeo interpolate`.
#[derive(Debug, Args)]
pub(super) struct InterpolateArgs {
    #[command(subcommand)]
    method: Method,
}

/// The interpolation methods.
#[derive(Debug, Subcommand)]
enum Method {
    /// Piecewise cubic C¹ Hermite curve through points with given (or estimated) tangents
    Hermite {
        #[command(flatten)]
        data: CurveData,
        /// Tangents at the points, JSON [[x, y], ...] [default: estimated from parabolas
        /// through three consecutive points, [PPB, §4.5]]
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        tangents: Option<String>,
    },
    /// C² cubic spline through the points with an end condition
    Spline {
        #[command(flatten)]
        data: CurveData,
        /// natural, clamped (needs --start-tangent and --end-tangent), bessel or periodic
        /// (first and last points equal)
        #[arg(long, value_enum, default_value = "natural")]
        end: End,
        /// The first derivative at the first knot (clamped), JSON [x, y]
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        start_tangent: Option<String>,
        /// The first derivative at the last knot (clamped), JSON [x, y]
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        end_tangent: Option<String>,
    },
    /// The interpolating polynomial in Lagrange form: its values and basis at parameters
    Lagrange {
        #[command(flatten)]
        data: PolyData,
        /// Evaluate by Aitken's repeated linear interpolation instead of the Lagrange basis
        #[arg(long)]
        aitken: bool,
    },
    /// The interpolating polynomial by divided differences: Newton and power coefficients
    Newton {
        #[command(flatten)]
        data: PolyData,
        /// First derivatives at the nodes, JSON [[x, y], ...]: Hermite interpolation by
        /// divided differences at doubled nodes
        #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
        derivatives: Option<String>,
    },
}

/// Points and knots of a composite interpolant.
#[derive(Debug, Args)]
struct CurveData {
    /// The points, JSON [[x, y], ...] (dimension 1 to 4)
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    points: String,
    /// The knots u_0 < u_1 < ..., JSON [0, "1/2", 1] [default: from --parameterisation]
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    knots: Option<String>,
    /// How to choose the knots when --knots is not given
    #[arg(long, value_enum, default_value = "uniform")]
    parameterisation: Knots,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    exact: bool,
}

/// Points, nodes and evaluation parameters of a polynomial interpolant.
#[derive(Debug, Args)]
struct PolyData {
    /// The points, JSON [[x, y], ...] (dimension 1 to 4)
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    points: String,
    /// The distinct nodes, JSON [0, "1/2", 1] (any order)
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    nodes: String,
    /// Parameters to evaluate the polynomial at, JSON [u, ...] (lagrange also prints the
    /// basis there: at most MAX_BASIS_TABLE = 2^24 values, nodes times parameters)
    #[arg(long, value_name = "JSON", allow_hyphen_values = true)]
    at: Option<String>,
    /// Compute in exact rationals and print every number as a string such as "47/18"
    #[arg(long)]
    exact: bool,
}

/// The spline end conditions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum End {
    /// Zero second derivative at both ends
    Natural,
    /// Given first derivatives at both ends
    Clamped,
    /// End tangents of the parabolas through the first and last three points
    Bessel,
    /// Closed curve, C² where it closes
    Periodic,
}

/// The parameterisations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(super) enum Knots {
    /// 0, 1, 2, ...
    Uniform,
    /// Knot gaps equal to the chord lengths
    ChordLength,
    /// Knot gaps equal to the square roots of the chord lengths
    Centripetal,
}

/// Runs `compgeo interpolate`.
pub(super) fn run(args: InterpolateArgs) -> Result<(), CliError> {
    let (points_text, exact) = match &args.method {
        Method::Hermite { data, .. } | Method::Spline { data, .. } => (&data.points, data.exact),
        Method::Lagrange { data, .. } | Method::Newton { data, .. } => (&data.points, data.exact),
    };
    let rows = parse_number_arrays(points_text)?;
    let d = rows[0].len();
    let value = by_scalar_and_dimension!(exact, d, "points", run_typed(&args.method, &rows))?;
    print_json(&value)
}

fn run_typed<S: JsonScalar, const D: usize>(
    method: &Method,
    rows: &[Vec<String>],
) -> Result<Value, CliError> {
    let pts: Vec<Point<S, D>> = to_points(rows, |i| format!("point {i}"))?;
    Ok(match method {
        Method::Hermite { data, tangents } => {
            let knots = knots_of(data, &pts)?;
            let tangents = match tangents {
                Some(text) => read_points::<S, D>(text, "tangent")?,
                None => estimate_tangents(&knots, &pts)?,
            };
            let curve = hermite(&knots, &pts, &tangents)?;
            composite_json(&curve, &tangents)?
        }
        Method::Spline {
            data,
            end,
            start_tangent,
            end_tangent,
        } => {
            let knots = knots_of(data, &pts)?;
            let condition = match (end, start_tangent, end_tangent) {
                (End::Natural, None, None) => EndCondition::Natural,
                (End::Bessel, None, None) => EndCondition::Bessel,
                (End::Periodic, None, None) => EndCondition::Periodic,
                (End::Clamped, Some(a), Some(b)) => EndCondition::Clamped {
                    start: read_one::<S, D>(a, "--start-tangent")?,
                    end: read_one::<S, D>(b, "--end-tangent")?,
                },
                (End::Clamped, _, _) => {
                    return Err(CliError::Usage(
                        "--end clamped needs --start-tangent and --end-tangent".to_string(),
                    ))
                }
                _ => {
                    return Err(CliError::Usage(
                        "--start-tangent and --end-tangent go with --end clamped only".to_string(),
                    ))
                }
            };
            let tangents = cubic_spline_tangents(&knots, &pts, &condition)?;
            let curve = hermite(&knots, &pts, &tangents)?;
            composite_json(&curve, &tangents)?
        }
        Method::Lagrange {
            data,
            aitken: use_aitken,
        } => {
            let nodes = read_scalars::<S>(&data.nodes, "node", "nodes")?;
            let form = lagrange(&nodes, &pts)?;
            let at = match &data.at {
                Some(text) => read_scalars::<S>(text, "parameter", "parameters (--at)")?,
                None => Vec::new(),
            };
            // One basis value per node and parameter: two short lists can ask for a lot.
            crate::limits::BASIS_TABLE.check(nodes.len() as u128 * at.len() as u128)?;
            let mut values = Vec::with_capacity(at.len());
            let mut bases = Vec::with_capacity(at.len());
            for u in &at {
                let p = if *use_aitken {
                    form.aitken(u)?
                } else {
                    form.eval(u)?
                };
                let k = values.len();
                values.push(point(&p, &format!("values[{k}]"))?);
                bases.push(scalars(&form.basis(u)?, &format!("basis[{k}]"))?);
            }
            json!({
                "algorithm": if *use_aitken { "aitken" } else { "lagrange" },
                "nodes": scalars(&nodes, "nodes")?,
                "at": scalars(&at, "at")?,
                "values": values,
                "basis": bases,
            })
        }
        Method::Newton { data, derivatives } => {
            let nodes = read_scalars::<S>(&data.nodes, "node", "nodes")?;
            let form = match derivatives {
                None => newton(&nodes, &pts)?,
                Some(text) => {
                    let slopes = read_points::<S, D>(text, "derivative")?;
                    if slopes.len() != nodes.len() || pts.len() != nodes.len() {
                        return Err(CliError::Usage(format!(
                            "{} nodes, {} points and {} derivatives: give one of each per node",
                            nodes.len(),
                            pts.len(),
                            slopes.len()
                        )));
                    }
                    let data: Vec<HermiteNode<S, D>> = nodes
                        .iter()
                        .zip(&pts)
                        .zip(slopes)
                        .map(|((u, p), d)| HermiteNode {
                            u: u.clone(),
                            values: vec![p.clone(), d],
                        })
                        .collect();
                    newton_hermite(&data)?
                }
            };
            let at = match &data.at {
                Some(text) => read_scalars::<S>(text, "parameter", "parameters (--at)")?,
                None => Vec::new(),
            };
            let values = at
                .iter()
                .enumerate()
                .map(|(k, u)| point(&form.eval(u)?, &format!("values[{k}]")))
                .collect::<Result<Vec<_>, _>>()?;
            json!({
                "nodes": scalars(form.nodes(), "nodes")?,
                "divided_differences": points(form.coefficients(), "divided_differences")?,
                "monomial": points(form.to_polynomial().coefficients(), "monomial")?,
                "at": scalars(&at, "at")?,
                "values": values,
            })
        }
    })
}

impl Knots {
    /// The library's parameterisation.
    pub(super) fn kind(self) -> Parameterisation {
        match self {
            Knots::Uniform => Parameterisation::Uniform,
            Knots::ChordLength => Parameterisation::ChordLength,
            Knots::Centripetal => Parameterisation::Centripetal,
        }
    }
}

/// The knots from `--knots`, or from the parameterisation.
fn knots_of<S: JsonScalar, const D: usize>(
    data: &CurveData,
    pts: &[Point<S, D>],
) -> Result<Vec<S>, CliError> {
    match &data.knots {
        Some(text) => read_scalars(text, "knot", "knots"),
        None => Ok(parameterise(pts, data.parameterisation.kind())?),
    }
}

fn composite_json<S: JsonScalar, const D: usize>(
    curve: &CompositeBezier<S, D>,
    tangents: &[Point<S, D>],
) -> Result<Value, CliError> {
    let pieces = curve
        .pieces()
        .iter()
        .enumerate()
        .map(|(k, b)| points(b.control(), &format!("pieces[{k}]")))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(json!({
        "knots": scalars(curve.partition(), "knots")?,
        "tangents": points(tangents, "tangents")?,
        "pieces": pieces,
    }))
}

/// The points of `rows`, each named in errors as `label(index)` ("point 2", "tangent 0").
pub(super) fn to_points<S: JsonScalar, const D: usize>(
    rows: &[Vec<String>],
    label: impl Fn(usize) -> String,
) -> Result<Vec<Point<S, D>>, CliError> {
    rows.iter()
        .enumerate()
        .map(|(index, row)| {
            if row.len() != D {
                return Err(CliError::Shape(format!(
                    "{} has {} coordinates, expected {D}",
                    label(index),
                    row.len()
                )));
            }
            let mut p = Point::<S, D>::zero();
            for (j, text) in row.iter().enumerate() {
                p[j] = read_number(text, || format!("{}, coordinate {j}", label(index)))?;
            }
            Ok(p)
        })
        .collect()
}

/// A list of points, `what` naming one of them ("tangent").
fn read_points<S: JsonScalar, const D: usize>(
    text: &str,
    what: &str,
) -> Result<Vec<Point<S, D>>, CliError> {
    to_points(&parse_number_arrays(text)?, |i| format!("{what} {i}"))
}

/// One point written as a flat list `[x, y]`, named by its flag.
fn read_one<S: JsonScalar, const D: usize>(
    text: &str,
    flag: &str,
) -> Result<Point<S, D>, CliError> {
    let flat = parse_number_list(text, &format!("coordinates of {flag}"))?;
    to_points(&[flat], |_| flag.to_string()).map(|mut v| v.remove(0))
}

/// A flat list of numbers, `one` naming an entry ("knot") and `all` the list ("knots").
pub(super) fn read_scalars<S: JsonScalar>(
    text: &str,
    one: &str,
    all: &str,
) -> Result<Vec<S>, CliError> {
    parse_number_list(text, all)?
        .iter()
        .enumerate()
        .map(|(i, x)| read_number(x, || format!("{one} {i}")))
        .collect()
}
