//! `compgeo draw <problem> [--algorithm A] IN --out FILE.svg`: the SVG picture of a
//! geometric result, computed as the problem's own command computes it.
//!
//! Point problems: `hull`, `diameter` (alias `calipers`), `delaunay` (`--circumcircles`),
//! `voronoi` (`--clip`), `closest-pair`, `emst`, `empty-circle`, with the algorithms of the
//! command of the same name, reading the point file `IN`. Curve, surface, mesh and graph
//! problems read what their own command reads: `bezier` (`--control`, `--t` for de
//! Casteljau's scaffolding), `bspline` (`--control`, `--degree`, `--knots`, `--spl`, `--u`
//! for de Boor's net), `nurbs` (and `--weights`), `beta` (`--beta1`, `--beta2`,
//! `--control`), `subdivide` (`--points`, `--scheme`, `--rounds`, ...), `surface` (`--net`
//! and the spline options, `--lines`), `triangle` (`--control`, `--segments`), `mesh` (an OBJ
//! file, `--scheme`, `--rounds`) and `graph` (a JSON graph, `--points` for coordinates,
//! and one of `--colour A`, `--mst A`, `--bfs S`, `--dfs S`); `--exact` computes in exact
//! rationals before the picture rounds to `f64`.
//!
//! The picture goes to `--out` and stdout gets one JSON object:
//! `{"problem": "...", "algorithm": "...", "points": n, "layers": {"hull": 1, ...},
//! "labels": true, "bytes": b, "out": "FILE.svg"}` (`algorithm` only where there is a
//! choice, `points` for the point problems). `--out -` writes the SVG to stdout instead, and
//! nothing else.
//!
//! `--steps` (hull: `jarvis`, `graham`, `monotone-chain`, `quickhull`; delaunay: `lawson`,
//! `fortune`; `bezier --t T`: de Casteljau's scaffolding level by level; `bspline --u U`:
//! de Boor's net level by level; `subdivide` with `--scheme lane-riesenfeld` or `chaikin`:
//! the polygon after each doubling and pass of midpoints; graph: `--bfs S`, `--dfs S`,
//! `--colour course`, `--mst prim`, `--mst kruskal`)
//! writes the run as one self-contained HTML page instead, a picture per frame of the
//! algorithm's own trace ([`crate::draw::StepPage`]), and prints `{"problem", "algorithm",
//! "points", "frames", "bytes", "out"}` (`points`: the control points or polygon vertices
//! of a curve; `vertices` instead of `points` for a graph). `--steps` on a curve without
//! `--t` / `--u`, or on the four-point scheme (which has no trace), is a usage error, as is
//! `--steps` on a graph without one of its traced algorithms.

use super::beta::{beta_of, ControlArgs, ShapeArgs};
use super::bezier::{CurveArgs as BezierArgs, JsonScalar};
use super::bspline::{curve_of, CurveArgs as BsplineArgs};
use super::graph::{non_empty, weighted};
use super::input::{inline_or_stdin, parse_number_arrays, read_text, GraphInput, PointInput};
use super::interpolate::to_points;
use super::mesh::{parse_scheme, scheme_help};
use super::nurbs::{nurbs_of, RationalArgs};
use super::output::{print_json, print_text, write_file};
use super::proximity::parse_numbers;
use super::subdivide::{
    each_round, lane_riesenfeld_degree, polygon_rows, scheme_name, scheme_title, topology,
    SubdivideArgs,
};
use super::surface::{surface_of, NetArgs};
use super::triangle::{patch_of, PatchArgs};
use super::CliError;
use crate::calipers::{diameter, ConvexPolygon, DiameterAlgorithm};
use crate::count::NoCount;
use crate::delaunay::{
    dual, triangulate_with, voronoi_with, Algorithm as DelaunayAlgorithm, ClipBox,
};
use crate::delaunay::{fortune_trace, lawson_trace};
use crate::draw::{self, circle_layout, GraphOverlay, Picture, StepPage};
use crate::geometry::{Point2, PointSet};
use crate::graph::{
    colour_with, search_with, spanning_forest_with, ColouringAlgorithm, Graph, MstAlgorithm,
    SearchAlgorithm,
};
use crate::graph::{
    course_greedy_colouring_trace, kruskal_trace, prim_trace, search_trace, EdgeList,
};
use crate::hull::{convex_hull_with, Algorithm as HullAlgorithm, HullOptions};
use crate::hull::{graham_trace, jarvis_trace, monotone_chain_trace, quickhull_trace};
use crate::mesh::{read_obj, subdivide_with, PolygonMesh, Scheme};
use crate::proximity::{
    closest_pair_with, euclidean_mst_with, largest_empty_circle_with, ClosestPairAlgorithm,
};
use crate::spline::subdivision::lane_riesenfeld_trace;
use crate::spline::{parse_scalar, Bezier};
use clap::{Args, Subcommand};
use serde_json::{json, Map, Value};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Arguments of `compgeo draw`.
#[derive(Debug, Args)]
pub(super) struct DrawArgs {
    #[command(subcommand)]
    problem: Problem,
}

/// The input and the picture's path, shared by every problem.
#[derive(Debug, Args)]
struct Common {
    #[command(flatten)]
    input: PointInput,
    /// Write the SVG to this file (`-` for stdout, instead of the JSON summary)
    #[arg(long, value_name = "FILE.svg")]
    out: PathBuf,
}

/// The picture's path, for the problems that read no point file.
#[derive(Debug, Args)]
struct Out {
    /// Write the SVG to this file (`-` for stdout, instead of the JSON summary)
    #[arg(long, value_name = "FILE.svg")]
    out: PathBuf,
}

/// The problems `compgeo draw` pictures.
#[derive(Debug, Subcommand)]
enum Problem {
    /// The point set and its convex hull, the vertices numbered in hull order
    Hull {
        #[arg(long, short, default_value = "akl-toussaint", help = HullAlgorithm::names(),
            long_help = HullAlgorithm::help())]
        algorithm: HullAlgorithm,
        /// Also take the points in the middle of hull edges as vertices
        #[arg(long)]
        keep_collinear: bool,
        /// Write the run step by step as one HTML page (jarvis, graham, monotone-chain,
        /// quickhull), a picture per step of the algorithm's own trace
        #[arg(long)]
        steps: bool,
        #[command(flatten)]
        common: Common,
    },
    /// The hull with the rotating calipers' antipodal pairs, diameter, width and minimum-area
    /// and minimum-perimeter rectangles
    #[command(visible_alias = "calipers")]
    Diameter {
        #[arg(long, short, default_value = "calipers", help = DiameterAlgorithm::names(),
            long_help = DiameterAlgorithm::help())]
        algorithm: DiameterAlgorithm,
        #[command(flatten)]
        common: Common,
    },
    /// The Delaunay triangulation, optionally with every triangle's circumcircle
    Delaunay {
        #[arg(long, short, default_value = "incremental", help = DelaunayAlgorithm::names(),
            long_help = DelaunayAlgorithm::help())]
        algorithm: DelaunayAlgorithm,
        /// Also draw the circumcircle of every triangle
        #[arg(long)]
        circumcircles: bool,
        /// Write the run step by step as one HTML page (lawson: the sweep, then every flip;
        /// fortune: every site and circle event with the sweep and beach lines)
        #[arg(long)]
        steps: bool,
        #[command(flatten)]
        common: Common,
    },
    /// The Voronoi cells clipped to a box
    Voronoi {
        /// Clip the cells to the box x0,y0,x1,y1 [default: auto, the sites' bounding box
        /// grown by a quarter of its larger side]
        #[arg(long, value_name = "x0,y0,x1,y1", allow_hyphen_values = true)]
        clip: Option<String>,
        #[command(flatten)]
        common: Common,
    },
    /// The closest pair of points
    ClosestPair {
        #[arg(long, short, default_value = "delaunay", help = ClosestPairAlgorithm::names(),
            long_help = ClosestPairAlgorithm::help())]
        algorithm: ClosestPairAlgorithm,
        #[command(flatten)]
        common: Common,
    },
    /// The Euclidean minimum spanning tree
    Emst {
        #[command(flatten)]
        common: Common,
    },
    /// The largest empty circle centred in the convex hull
    EmptyCircle {
        #[command(flatten)]
        common: Common,
    },
    /// A Bézier curve (2 or 3 dimensions) with its control polygon, and with --t de
    /// Casteljau's scaffolding at t
    Bezier {
        #[command(flatten)]
        curve: BezierArgs,
        /// Draw de Casteljau's scaffolding at this parameter: a decimal or a fraction such as
        /// 1/3 (any t, also outside [0, 1])
        #[arg(long = "t", value_name = "T", allow_hyphen_values = true)]
        t: Option<String>,
        /// Write de Casteljau's run at --t step by step as one HTML page: the control
        /// polygon, each level of the scaffolding, the point b(t)
        #[arg(long)]
        steps: bool,
        #[command(flatten)]
        out: Out,
    },
    /// A B-spline curve with its control polygon and its points at the knots, and with --u
    /// de Boor's net at u
    Bspline {
        #[command(flatten)]
        curve: BsplineArgs,
        /// Draw de Boor's net at this parameter of the domain [t_d, t_n]
        #[arg(
            long = "u",
            visible_alias = "t",
            value_name = "U",
            allow_hyphen_values = true
        )]
        u: Option<String>,
        /// Write de Boor's run at --u step by step as one HTML page: the control points that
        /// matter, each level of the net, the point s(u)
        #[arg(long)]
        steps: bool,
        #[command(flatten)]
        out: Out,
    },
    /// A NURBS curve with its control polygon and its points at the knots
    Nurbs {
        #[command(flatten)]
        curve: RationalArgs,
        #[command(flatten)]
        out: Out,
    },
    /// A cubic Beta-spline with its control polygon and its joints
    Beta {
        #[command(flatten)]
        shape: ShapeArgs,
        #[command(flatten)]
        control: ControlArgs,
        #[command(flatten)]
        out: Out,
    },
    /// The polygon after each round of a subdivision scheme, earlier rounds lighter
    Subdivide {
        #[command(flatten)]
        scheme: SubdivideArgs,
        /// Write the run step by step as one HTML page (lane-riesenfeld, chaikin): the
        /// polygon after each doubling and each pass of midpoints
        #[arg(long)]
        steps: bool,
        #[command(flatten)]
        out: Out,
    },
    /// A tensor-product surface (Bézier patch, B-spline or NURBS surface) as a projected
    /// wireframe of isoparametric lines over its dashed control net
    Surface {
        #[command(flatten)]
        net: NetArgs,
        /// Isoparametric lines each way, less one (1 to 1024)
        #[arg(long, default_value_t = 8)]
        lines: usize,
        #[command(flatten)]
        out: Out,
    },
    /// A triangular Bézier patch as a projected wireframe over its dashed control net
    Triangle {
        #[command(flatten)]
        patch: PatchArgs,
        /// Segments along each side (1 to 1024)
        #[arg(long, default_value_t = 8)]
        segments: usize,
        #[command(flatten)]
        out: Out,
    },
    /// A polygon mesh read from OBJ as a projected wireframe, and with --rounds k the mesh
    /// after k rounds of subdivision over it
    Mesh {
        /// The mesh: a Wavefront OBJ file, or - for standard input
        #[arg(value_name = "IN")]
        input: PathBuf,
        /// The subdivision scheme of --rounds
        #[arg(long, default_value = "catmull-clark", value_parser = parse_scheme,
              long_help = scheme_help())]
        scheme: Scheme,
        /// Rounds of subdivision to draw over the mesh
        #[arg(long, default_value_t = 0)]
        rounds: usize,
        /// Read and subdivide in exact rationals
        #[arg(long)]
        exact: bool,
        #[command(flatten)]
        out: Out,
    },
    /// A graph on a circle (or at --points), with its colouring, spanning forest or search
    /// tree on request
    Graph {
        #[command(flatten)]
        graph: GraphInput,
        /// Place vertex i at point i of this point file (JSON or CSV) instead of on a circle
        #[arg(long, value_name = "FILE")]
        points: Option<PathBuf>,
        /// Fill each vertex with its colour by this colouring strategy
        #[arg(long, value_name = "A", group = "overlay", help = ColouringAlgorithm::names(),
            long_help = ColouringAlgorithm::help())]
        colour: Option<ColouringAlgorithm>,
        /// Highlight the minimum spanning forest by this algorithm (weighted edges)
        #[arg(long, value_name = "A", group = "overlay", help = MstAlgorithm::names(),
            long_help = MstAlgorithm::help())]
        mst: Option<MstAlgorithm>,
        /// Highlight the breadth-first search tree from this vertex
        #[arg(long, value_name = "S", group = "overlay")]
        bfs: Option<usize>,
        /// Highlight the depth-first search tree from this vertex
        #[arg(long, value_name = "S", group = "overlay")]
        dfs: Option<usize>,
        /// Write the run step by step as one HTML page (--bfs, --dfs, --colour course, --mst
        /// prim or kruskal), a picture per step of the algorithm's own trace
        #[arg(long)]
        steps: bool,
        #[command(flatten)]
        out: Out,
    },
}

/// Runs `compgeo draw`.
pub(super) fn run(args: DrawArgs) -> Result<(), CliError> {
    if let Problem::Graph {
        graph,
        points,
        colour,
        mst,
        bfs,
        dfs,
        steps: true,
        out,
    } = &args.problem
    {
        let (algorithm, vertices, page) =
            graph_step_page(graph, points.as_deref(), *colour, *mst, *bfs, *dfs)?;
        return write_page(
            "graph",
            Some(algorithm),
            ("vertices", vertices),
            &page,
            &out.out,
        );
    }
    let steps = match &args.problem {
        Problem::Hull {
            algorithm,
            common,
            steps: true,
            ..
        } => Some(("hull", algorithm.name(), common)),
        Problem::Delaunay {
            algorithm,
            common,
            steps: true,
            ..
        } => Some(("delaunay", algorithm.name(), common)),
        _ => None,
    };
    if let Some((name, algorithm, common)) = steps {
        let points = common.input.read()?;
        let set = PointSet::new(&points)?;
        if let Some(page) = step_page(&args.problem, &set)? {
            return write_page(
                name,
                Some(algorithm),
                ("points", points.len()),
                &page,
                &common.out,
            );
        }
    }
    if let Some((name, algorithm, points, page, out)) = curve_step_page(&args.problem)? {
        return write_page(name, Some(&algorithm), ("points", points), &page, out);
    }
    let mut summary = Map::new();
    let mut from_points = |common: &Common| -> Result<Picture, CliError> {
        let points = common.input.read()?;
        let set = PointSet::new(&points)?;
        summary.insert("points".into(), json!(points.len()));
        point_picture(&args.problem, &set, &points)
    };
    let (name, algorithm, out, mut picture) = match &args.problem {
        Problem::Hull {
            algorithm, common, ..
        } => (
            "hull",
            Some(algorithm.name()),
            &common.out,
            from_points(common)?,
        ),
        Problem::Diameter { algorithm, common } => (
            "diameter",
            Some(algorithm.name()),
            &common.out,
            from_points(common)?,
        ),
        Problem::Delaunay {
            algorithm, common, ..
        } => (
            "delaunay",
            Some(algorithm.name()),
            &common.out,
            from_points(common)?,
        ),
        Problem::Voronoi { common, .. } => ("voronoi", None, &common.out, from_points(common)?),
        Problem::ClosestPair { algorithm, common } => (
            "closest-pair",
            Some(algorithm.name()),
            &common.out,
            from_points(common)?,
        ),
        Problem::Emst { common } => ("emst", None, &common.out, from_points(common)?),
        Problem::EmptyCircle { common } => {
            ("empty-circle", None, &common.out, from_points(common)?)
        }
        Problem::Bezier { curve, t, out, .. } => {
            let rows = parse_number_arrays(&inline_or_stdin(&curve.control)?)?;
            let d = rows[0].len();
            let p = by_scalar_and_dimension!(
                curve.exact,
                d,
                "control points",
                bezier_picture(&rows, t.as_deref())
            )?;
            ("bezier", None, &out.out, p)
        }
        Problem::Bspline { curve, u, out, .. } => {
            let rows = parse_number_arrays(&inline_or_stdin(&curve.control)?)?;
            let d = rows[0].len();
            let p = by_scalar_and_dimension!(
                curve.exact,
                d,
                "control points",
                bspline_picture(curve, &rows, u.as_deref())
            )?;
            ("bspline", None, &out.out, p)
        }
        Problem::Nurbs { curve, out } => {
            let rows = parse_number_arrays(&inline_or_stdin(&curve.curve.control)?)?;
            let d = rows[0].len();
            let p = by_scalar_and_dimension!(
                curve.curve.exact,
                d,
                "control points",
                nurbs_picture(curve, &rows)
            )?;
            ("nurbs", None, &out.out, p)
        }
        Problem::Beta {
            shape,
            control,
            out,
        } => {
            let rows = parse_number_arrays(&inline_or_stdin(&control.control)?)?;
            let d = rows[0].len();
            let p = by_scalar_and_dimension!(
                shape.exact,
                d,
                "control points",
                beta_picture(shape, &rows)
            )?;
            ("beta", None, &out.out, p)
        }
        Problem::Subdivide { scheme, out, .. } => {
            let rows = polygon_rows(scheme)?;
            let d = rows[0].len();
            let p = by_scalar_and_dimension!(
                scheme.exact,
                d,
                "points",
                subdivision_picture(scheme, &rows)
            )?;
            ("subdivide", None, &out.out, p)
        }
        Problem::Surface { net, lines, out } => {
            let grid = net.grid()?;
            let d = grid[0][0].len();
            let p = by_scalar_and_dimension!(
                net.exact,
                d,
                "control points",
                surface_picture(net, &grid, *lines)
            )?;
            ("surface", None, &out.out, p)
        }
        Problem::Triangle {
            patch,
            segments,
            out,
        } => {
            let rows = parse_number_arrays(&inline_or_stdin(&patch.control)?)?;
            let d = rows[0].len();
            let p = by_scalar_and_dimension!(
                patch.exact,
                d,
                "control points",
                triangle_picture(patch, &rows, *segments)
            )?;
            ("triangle", None, &out.out, p)
        }
        Problem::Mesh {
            input,
            scheme,
            rounds,
            exact,
            out,
        } => {
            let p = if *exact {
                mesh_picture::<num_rational::BigRational>(input, *scheme, *rounds)?
            } else {
                mesh_picture::<f64>(input, *scheme, *rounds)?
            };
            let algorithm = (*rounds > 0).then(|| scheme.name());
            ("mesh", algorithm, &out.out, p)
        }
        Problem::Graph {
            graph,
            points,
            colour,
            mst,
            bfs,
            dfs,
            out,
            ..
        } => {
            let (p, algorithm) =
                graph_picture(graph, points.as_deref(), *colour, *mst, *bfs, *dfs)?;
            ("graph", algorithm, &out.out, p)
        }
    };
    if let Some(a) = algorithm {
        let title = format!("{} ({a})", picture.title());
        picture.set_title(&title);
    }
    let svg = picture.to_svg();
    if out == Path::new("-") {
        return print_text(&svg);
    }
    write_file(out, |w| w.write_all(svg.as_bytes()))?;
    summary.insert("problem".into(), json!(name));
    if let Some(a) = algorithm {
        summary.insert("algorithm".into(), json!(a));
    }
    let layers: Map<String, Value> = picture
        .layers()
        .map(|(layer, count)| (layer.to_string(), json!(count)))
        .collect();
    summary.insert("layers".into(), Value::Object(layers));
    summary.insert("labels".into(), json!(picture.shows_labels()));
    summary.insert("bytes".into(), json!(svg.len()));
    summary.insert("out".into(), json!(out.display().to_string()));
    print_json(&Value::Object(summary))
}

/// The step page of `problem` when `--steps` asks for one, from the algorithm's own trace.
fn step_page(problem: &Problem, set: &PointSet<'_>) -> Result<Option<StepPage>, CliError> {
    let unsupported = |algorithm: &str, traced: &str| {
        CliError::Usage(format!(
            "--steps: no step trace for {algorithm}; the traced algorithms are {traced}"
        ))
    };
    Ok(match problem {
        Problem::Hull {
            algorithm,
            keep_collinear,
            steps: true,
            ..
        } => {
            let options = HullOptions {
                keep_collinear: *keep_collinear,
            };
            Some(match algorithm {
                HullAlgorithm::Jarvis => draw::jarvis_steps(set, &jarvis_trace(set, options)?)?,
                HullAlgorithm::Graham => draw::graham_steps(set, &graham_trace(set, options)?)?,
                HullAlgorithm::MonotoneChain => {
                    draw::monotone_chain_steps(set, &monotone_chain_trace(set, options)?)?
                }
                HullAlgorithm::Quickhull => {
                    draw::quickhull_steps(set, &quickhull_trace(set, options)?)?
                }
                other => {
                    return Err(unsupported(
                        other.name(),
                        "jarvis, graham, monotone-chain and quickhull",
                    ))
                }
            })
        }
        Problem::Delaunay {
            algorithm,
            steps: true,
            ..
        } => match algorithm {
            DelaunayAlgorithm::Lawson => Some(draw::lawson_steps(set, &lawson_trace(set)?)?),
            DelaunayAlgorithm::Fortune => Some(draw::fortune_steps(set, &fortune_trace(set)?)?),
            other => return Err(unsupported(other.name(), "lawson and fortune")),
        },
        _ => None,
    })
}

/// A curve's step page when `--steps` asks for one: the problem's name, the algorithm, the
/// number of control points, the page and where it goes.
type CurvePage<'a> = (&'static str, String, usize, StepPage, &'a Path);

/// The step page of a curve problem when `--steps` asks for one, from the algorithm's own
/// trace; `--steps` without the parameter the trace needs, or on a scheme with no trace, is
/// a usage error.
fn curve_step_page(problem: &Problem) -> Result<Option<CurvePage<'_>>, CliError> {
    let needs = |option: &str, algorithm: &str| {
        CliError::Usage(format!(
            "--steps: {algorithm}'s steps are at one parameter; give it with {option}"
        ))
    };
    Ok(match problem {
        Problem::Bezier {
            curve,
            t,
            out,
            steps: true,
        } => {
            let t = t.as_deref().ok_or_else(|| needs("--t", "de Casteljau"))?;
            let rows = parse_number_arrays(&inline_or_stdin(&curve.control)?)?;
            let d = rows[0].len();
            let page = by_scalar_and_dimension!(
                curve.exact,
                d,
                "control points",
                de_casteljau_page(&rows, t)
            )?;
            let name = "de-casteljau".to_string();
            Some(("bezier", name, rows.len(), page, &out.out))
        }
        Problem::Bspline {
            curve,
            u,
            out,
            steps: true,
        } => {
            let u = u.as_deref().ok_or_else(|| needs("--u", "de Boor"))?;
            let rows = parse_number_arrays(&inline_or_stdin(&curve.control)?)?;
            let d = rows[0].len();
            let page = by_scalar_and_dimension!(
                curve.exact,
                d,
                "control points",
                de_boor_page(curve, &rows, u)
            )?;
            Some(("bspline", "de-boor".to_string(), rows.len(), page, &out.out))
        }
        Problem::Subdivide {
            scheme,
            out,
            steps: true,
        } => {
            let rows = polygon_rows(scheme)?;
            let d = rows[0].len();
            let page = by_scalar_and_dimension!(
                scheme.exact,
                d,
                "points",
                lane_riesenfeld_page(scheme, &rows)
            )?;
            Some(("subdivide", scheme_name(scheme), rows.len(), page, &out.out))
        }
        _ => None,
    })
}

/// De Casteljau's step page at `t`.
fn de_casteljau_page<S: JsonScalar, const D: usize>(
    rows: &[Vec<String>],
    t: &str,
) -> Result<StepPage, CliError> {
    let b = Bezier::new(to_points::<S, D>(rows, |i| format!("control point {i}"))?)?;
    let t: S = parse_scalar(t, "t")?;
    Ok(draw::de_casteljau_steps(
        &b,
        &t,
        &b.de_casteljau_trace(&t)?,
    )?)
}

/// De Boor's step page at `u`.
fn de_boor_page<S: JsonScalar, const D: usize>(
    args: &BsplineArgs,
    rows: &[Vec<String>],
    u: &str,
) -> Result<StepPage, CliError> {
    let s = curve_of::<S, D>(args, rows)?;
    let u: S = parse_scalar(u, "u")?;
    Ok(draw::de_boor_steps(&s, &u, &s.de_boor_trace(&u)?)?)
}

/// The Lane–Riesenfeld step page of the subdivision's polygon and rounds.
fn lane_riesenfeld_page<S: JsonScalar, const D: usize>(
    args: &SubdivideArgs,
    rows: &[Vec<String>],
) -> Result<StepPage, CliError> {
    let degree = lane_riesenfeld_degree(args).ok_or_else(|| {
        CliError::Usage(format!(
            "--steps: no step trace for {}; the traced schemes are lane-riesenfeld and chaikin",
            scheme_name(args)
        ))
    })?;
    let polygon = to_points::<S, D>(rows, |i| format!("point {i}"))?;
    let topology = topology(args);
    let trace = lane_riesenfeld_trace(&polygon, degree, args.rounds, topology)?;
    Ok(draw::lane_riesenfeld_steps(
        &polygon, degree, topology, &trace,
    )?)
}

/// Writes a step page to `out` (`-`: stdout, and nothing else) and prints its summary, with
/// the input's `size` (`("points", n)`, `("vertices", n)`).
fn write_page(
    name: &str,
    algorithm: Option<&str>,
    size: (&str, usize),
    page: &StepPage,
    out: &Path,
) -> Result<(), CliError> {
    let html = page.to_html();
    if out == Path::new("-") {
        return print_text(&html);
    }
    write_file(out, |w| w.write_all(html.as_bytes()))?;
    let mut summary = json!({
        "problem": name,
        "algorithm": algorithm,
        "frames": page.frames().len(),
        "bytes": html.len(),
        "out": out.display().to_string(),
    });
    summary[size.0] = json!(size.1);
    print_json(&summary)
}

/// A Bézier curve, with de Casteljau's scaffolding at `t`.
fn bezier_picture<S: JsonScalar, const D: usize>(
    rows: &[Vec<String>],
    t: Option<&str>,
) -> Result<Picture, CliError> {
    let b = Bezier::new(to_points::<S, D>(rows, |i| format!("control point {i}"))?)?;
    let t: Option<S> = t.map(|t| parse_scalar(t, "t")).transpose()?;
    Ok(draw::bezier(&b, t.as_ref())?)
}

/// A B-spline curve, with de Boor's net at `u`.
fn bspline_picture<S: JsonScalar, const D: usize>(
    args: &BsplineArgs,
    rows: &[Vec<String>],
    u: Option<&str>,
) -> Result<Picture, CliError> {
    let s = curve_of::<S, D>(args, rows)?;
    let u: Option<S> = u.map(|u| parse_scalar(u, "u")).transpose()?;
    Ok(draw::bspline(&s, u.as_ref())?)
}

/// A NURBS curve.
fn nurbs_picture<S: JsonScalar, const D: usize>(
    args: &RationalArgs,
    rows: &[Vec<String>],
) -> Result<Picture, CliError> {
    Ok(draw::nurbs(&nurbs_of::<S, D>(args, rows)?)?)
}

/// A Beta-spline.
fn beta_picture<S: JsonScalar, const D: usize>(
    shape: &ShapeArgs,
    rows: &[Vec<String>],
) -> Result<Picture, CliError> {
    Ok(draw::beta(&beta_of::<S, D>(shape, rows)?)?)
}

/// The rounds of a subdivision scheme.
fn subdivision_picture<S: JsonScalar, const D: usize>(
    args: &SubdivideArgs,
    rows: &[Vec<String>],
) -> Result<Picture, CliError> {
    let rounds = each_round::<S, D>(args, rows)?;
    Ok(draw::subdivision(
        &scheme_title(args),
        &rounds,
        topology(args),
    )?)
}

/// A tensor-product surface.
fn surface_picture<S: JsonScalar, const D: usize>(
    args: &NetArgs,
    grid: &[Vec<Vec<String>>],
    lines: usize,
) -> Result<Picture, CliError> {
    let s = surface_of::<S, D>(args, grid)?;
    Ok(draw::surface(s.kind(), &s, s.net(), lines)?)
}

/// A triangular patch.
fn triangle_picture<S: JsonScalar, const D: usize>(
    args: &PatchArgs,
    rows: &[Vec<String>],
    segments: usize,
) -> Result<Picture, CliError> {
    Ok(draw::triangular_patch(
        &patch_of::<S, D>(args, rows)?,
        segments,
    )?)
}

/// A mesh read from OBJ, with `rounds` rounds of `scheme` over it.
fn mesh_picture<S: JsonScalar>(
    input: &Path,
    scheme: Scheme,
    rounds: usize,
) -> Result<Picture, CliError> {
    let text = read_text(input)?;
    let mesh: PolygonMesh<S, 3> = read_obj(text.as_bytes())?;
    let fine = if rounds > 0 {
        Some(subdivide_with(&mesh, scheme, rounds, &mut NoCount)?)
    } else {
        None
    };
    Ok(draw::mesh(&mesh, fine.as_ref())?)
}

/// The graph of `input`, as an edge list and a graph, and its vertices' positions: the
/// points of the file `points`, or the circle.
fn graph_input(
    input: &GraphInput,
    points: Option<&Path>,
) -> Result<(EdgeList, Graph, Vec<Point2>), CliError> {
    let list = non_empty(input.read()?)?;
    let g = Graph::from_edge_list(&list)?;
    let n = g.vertex_count();
    let positions = match points {
        Some(path) => {
            let pts = PointInput {
                input: path.to_path_buf(),
                format: None,
            }
            .read()?;
            PointSet::new(&pts)?;
            if pts.len() != n {
                return Err(CliError::Shape(format!(
                    "--points gives {} points for {n} vertices",
                    pts.len()
                )));
            }
            pts
        }
        None => circle_layout(n),
    };
    Ok((list, g, positions))
}

/// The step page of the graph algorithm `--steps` asks for, its name and the vertex count.
fn graph_step_page(
    input: &GraphInput,
    points: Option<&Path>,
    colour: Option<ColouringAlgorithm>,
    mst: Option<MstAlgorithm>,
    bfs: Option<usize>,
    dfs: Option<usize>,
) -> Result<(&'static str, usize, StepPage), CliError> {
    const TRACED: &str = "--bfs S, --dfs S, --colour course, --mst prim and --mst kruskal";
    let unsupported = |algorithm: &str| {
        CliError::Usage(format!(
            "--steps: no step trace for {algorithm}; the traced algorithms are {TRACED}"
        ))
    };
    let read = || graph_input(input, points);
    Ok(match (colour, mst, bfs, dfs) {
        (Some(a @ ColouringAlgorithm::Course), ..) => {
            let (_, g, positions) = read()?;
            let order: Vec<usize> = (0..g.vertex_count()).collect();
            let trace = course_greedy_colouring_trace(&g, &order)?;
            let page = draw::colouring_steps(&g, &positions, &trace)?;
            (a.name(), g.vertex_count(), page)
        }
        (Some(other), ..) => return Err(unsupported(other.name())),
        (_, Some(a @ (MstAlgorithm::Prim | MstAlgorithm::Kruskal)), ..) => {
            let (list, g, positions) = read()?;
            let w = weighted(&list)?;
            let page = if a == MstAlgorithm::Prim {
                draw::prim_steps(&w, &positions, &prim_trace(&w)?)?
            } else {
                draw::kruskal_steps(&w, &positions, &kruskal_trace(&w)?)?
            };
            (a.name(), g.vertex_count(), page)
        }
        (_, Some(other), ..) => return Err(unsupported(other.name())),
        (_, _, Some(start), _) | (_, _, None, Some(start)) => {
            let kind = if bfs.is_some() {
                SearchAlgorithm::Bfs
            } else {
                SearchAlgorithm::Dfs
            };
            let (_, g, positions) = read()?;
            let trace = search_trace(&g, start, kind)?;
            let page = draw::search_steps(&g, &positions, kind, &trace)?;
            (kind.name(), g.vertex_count(), page)
        }
        (None, None, None, None) => {
            return Err(CliError::Usage(format!(
                "--steps on a graph needs an algorithm: one of {TRACED}"
            )))
        }
    })
}

/// A graph with the overlay asked for, and the algorithm that computed it.
fn graph_picture(
    input: &GraphInput,
    points: Option<&Path>,
    colour: Option<ColouringAlgorithm>,
    mst: Option<MstAlgorithm>,
    bfs: Option<usize>,
    dfs: Option<usize>,
) -> Result<(Picture, Option<&'static str>), CliError> {
    let (list, g, positions) = graph_input(input, points)?;
    Ok(if let Some(a) = colour {
        let c = colour_with(&g, a, &mut NoCount);
        (
            draw::graph(&g, &positions, GraphOverlay::Colouring(&c))?,
            Some(a.name()),
        )
    } else if let Some(a) = mst {
        let w = weighted(&list)?;
        let forest = spanning_forest_with(&w, a, &mut NoCount);
        let edges: Vec<[usize; 2]> = forest.edges.iter().map(|&e| w.endpoints(e)).collect();
        (
            draw::graph(&g, &positions, GraphOverlay::Tree(&edges))?,
            Some(a.name()),
        )
    } else if let Some((start, kind)) = bfs
        .map(|s| (s, SearchAlgorithm::Bfs))
        .or(dfs.map(|s| (s, SearchAlgorithm::Dfs)))
    {
        let search = search_with(&g, start, kind, &mut NoCount)?;
        (
            draw::graph(
                &g,
                &positions,
                GraphOverlay::Search {
                    search: &search,
                    start,
                },
            )?,
            Some(kind.name()),
        )
    } else {
        (draw::graph(&g, &positions, GraphOverlay::Plain)?, None)
    })
}

/// The picture of a point problem, each result computed by the library as its own command
/// does.
fn point_picture(
    problem: &Problem,
    set: &PointSet<'_>,
    points: &[Point2],
) -> Result<Picture, CliError> {
    Ok(match problem {
        Problem::Hull {
            algorithm,
            keep_collinear,
            ..
        } => {
            let options = HullOptions {
                keep_collinear: *keep_collinear,
            };
            draw::hull(
                set,
                &convex_hull_with(set, *algorithm, options, &mut NoCount),
            )?
        }
        Problem::Diameter { algorithm, .. } => {
            let polygon = ConvexPolygon::hull(set);
            let pair = match algorithm {
                DiameterAlgorithm::Calipers => polygon.diameter()?,
                other => diameter(points, *other)?,
            };
            draw::calipers(&polygon, &pair)?
        }
        Problem::Delaunay {
            algorithm,
            circumcircles,
            ..
        } => {
            let t = triangulate_with(set, *algorithm, &mut NoCount)?;
            let circles = circumcircles.then(|| dual(points, &t)).transpose()?;
            draw::delaunay(set, &t, circles.as_ref())?
        }
        Problem::Voronoi { clip, .. } => {
            let bounds = match clip.as_deref() {
                None | Some("auto") => ClipBox::around(set)?,
                Some(text) => {
                    let [x0, y0, x1, y1] = parse_numbers::<4>("--clip", text)?;
                    ClipBox::new(x0, y0, x1, y1)?
                }
            };
            draw::voronoi(set, &voronoi_with(set, &mut NoCount)?, &bounds)?
        }
        Problem::ClosestPair { algorithm, .. } => {
            draw::closest_pair(set, &closest_pair_with(set, *algorithm, &mut NoCount)?)?
        }
        Problem::Emst { .. } => draw::emst(set, &euclidean_mst_with(set, &mut NoCount)?)?,
        Problem::EmptyCircle { .. } => {
            let hull = convex_hull_with(
                set,
                HullAlgorithm::AklToussaint,
                HullOptions::default(),
                &mut NoCount,
            );
            draw::empty_circle(set, &hull, &largest_empty_circle_with(set, &mut NoCount)?)?
        }
        _ => unreachable!("only the point problems read a point file"),
    })
}
