//! `compgeo draw <problem> [--algorithm A] IN --out FILE.svg`: the SVG picture of a
//! geometric result, computed as the problem's own command computes it.
//!
//! Problems: `hull`, `diameter` (alias `calipers`), `delaunay` (`--circumcircles`),
//! `voronoi` (`--clip`), `closest-pair`, `emst`, `empty-circle`, with the algorithms of the
//! command of the same name. The picture goes to `--out` and stdout gets one JSON object:
//! `{"problem": "...", "algorithm": "...", "points": n, "layers": {"hull": 1, ...},
//! "labels": true, "bytes": b, "out": "FILE.svg"}` (`algorithm` only where there is a
//! choice). `--out -` writes the SVG to stdout instead, and nothing else.
//!
//! `--steps` (hull: `jarvis`, `graham`, `monotone-chain`, `quickhull`; delaunay: `lawson`,
//! `fortune`)
//! writes the run as one self-contained HTML page instead, a picture per frame of the
//! algorithm's own trace ([`crate::draw::StepPage`]), and prints `{"problem", "algorithm",
//! "points", "frames", "bytes", "out"}`.

use super::input::PointInput;
use super::output::{print_json, write_file};
use super::proximity::parse_numbers;
use super::CliError;
use crate::calipers::{diameter, ConvexPolygon, DiameterAlgorithm};
use crate::count::NoCount;
use crate::delaunay::{
    dual, triangulate_with, voronoi_with, Algorithm as DelaunayAlgorithm, ClipBox,
};
use crate::delaunay::{fortune_trace, lawson_trace};
use crate::draw::{self, Picture, StepPage};
use crate::geometry::{Point2, PointSet};
use crate::hull::{convex_hull_with, Algorithm as HullAlgorithm, HullOptions};
use crate::hull::{graham_trace, jarvis_trace, monotone_chain_trace, quickhull_trace};
use crate::proximity::{
    closest_pair_with, euclidean_mst_with, largest_empty_circle_with, ClosestPairAlgorithm,
};
use clap::{Args, Subcommand};
use serde_json::{json, Map, Value};
use std::io::{BufWriter, Write};
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
}

/// Runs `compgeo draw`.
pub(super) fn run(args: DrawArgs) -> Result<(), CliError> {
    let (name, algorithm, common) = match &args.problem {
        Problem::Hull {
            algorithm, common, ..
        } => ("hull", Some(algorithm.name()), common),
        Problem::Diameter { algorithm, common } => ("diameter", Some(algorithm.name()), common),
        Problem::Delaunay {
            algorithm, common, ..
        } => ("delaunay", Some(algorithm.name()), common),
        Problem::Voronoi { common, .. } => ("voronoi", None, common),
        Problem::ClosestPair { algorithm, common } => {
            ("closest-pair", Some(algorithm.name()), common)
        }
        Problem::Emst { common } => ("emst", None, common),
        Problem::EmptyCircle { common } => ("empty-circle", None, common),
    };
    let points = common.input.read()?;
    let set = PointSet::new(&points)?;
    if let Some(page) = step_page(&args.problem, &set)? {
        return write_page(name, algorithm, points.len(), &page, &common.out);
    }
    let mut picture = picture(&args.problem, &set, &points)?;
    if let Some(a) = algorithm {
        let title = format!("{} ({a})", picture.title());
        picture.set_title(&title);
    }
    let svg = picture.to_svg();
    let out = &common.out;
    if out == Path::new("-") {
        let stdout = std::io::stdout();
        let mut w = BufWriter::new(stdout.lock());
        return w
            .write_all(svg.as_bytes())
            .and_then(|()| w.flush())
            .map_err(CliError::Output);
    }
    write_file(out, |w| w.write_all(svg.as_bytes()))?;
    let mut summary = Map::new();
    summary.insert("problem".into(), json!(name));
    if let Some(a) = algorithm {
        summary.insert("algorithm".into(), json!(a));
    }
    summary.insert("points".into(), json!(points.len()));
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

/// Writes a step page to `out` (`-`: stdout, and nothing else) and prints its summary.
fn write_page(
    name: &str,
    algorithm: Option<&str>,
    points: usize,
    page: &StepPage,
    out: &Path,
) -> Result<(), CliError> {
    let html = page.to_html();
    if out == Path::new("-") {
        let stdout = std::io::stdout();
        let mut w = BufWriter::new(stdout.lock());
        return w
            .write_all(html.as_bytes())
            .and_then(|()| w.flush())
            .map_err(CliError::Output);
    }
    write_file(out, |w| w.write_all(html.as_bytes()))?;
    print_json(&json!({
        "problem": name,
        "algorithm": algorithm,
        "points": points,
        "frames": page.frames().len(),
        "bytes": html.len(),
        "out": out.display().to_string(),
    }))
}

/// The picture of `problem`, each result computed by the library as its own command does.
fn picture(problem: &Problem, set: &PointSet<'_>, points: &[Point2]) -> Result<Picture, CliError> {
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
    })
}
