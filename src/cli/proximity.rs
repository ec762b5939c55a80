//! `compgeo voronoi`, `closest-pair`, `nearest`, `emst` and `empty-circle`: the proximity
//! problems on the Delaunay triangulation.

use super::input::PointInput;
use super::output::print_json;
use super::CliError;
use crate::count::{Counts, NoCount};
use crate::delaunay::{voronoi_with, Cell, ClipBox, Voronoi};
use crate::geometry::{Point2, PointSet, WideFloat};
use crate::proximity::{
    closest_pair_with, euclidean_mst_with, largest_empty_circle_with, ClosestPairAlgorithm,
    NearestSearch,
};
use crate::spline::parse_f64_or_word;
use crate::util::quote;
use clap::Args;
use serde::Serialize;

/// Arguments of `compgeo voronoi`.
#[derive(Debug, Args)]
pub(super) struct VoronoiArgs {
    /// Clip every cell to the box x0,y0,x1,y1 (or `auto`: the sites' bounding box grown by a
    /// quarter of its larger side) and print the clipped polygons
    #[arg(long, value_name = "x0,y0,x1,y1", allow_hyphen_values = true)]
    clip: Option<String>,
    #[command(flatten)]
    input: PointInput,
}

/// Arguments of `compgeo closest-pair`.
#[derive(Debug, Args)]
pub(super) struct ClosestPairArgs {
    #[arg(long, short, default_value = "delaunay", help = ClosestPairAlgorithm::names(),
        long_help = ClosestPairAlgorithm::help())]
    algorithm: ClosestPairAlgorithm,
    #[command(flatten)]
    input: PointInput,
}

/// Arguments of `compgeo nearest`.
#[derive(Debug, Args)]
pub(super) struct NearestArgs {
    /// The query point x,y
    #[arg(long, value_name = "x,y", allow_hyphen_values = true)]
    query: String,
    #[command(flatten)]
    input: PointInput,
}

/// Arguments of `compgeo emst` and `compgeo empty-circle`.
#[derive(Debug, Args)]
pub(super) struct PointsArgs {
    #[command(flatten)]
    input: PointInput,
}

/// A ray as printed (its origin by the overflow rule, like the vertices).
#[derive(Debug, Serialize)]
struct RayOutput {
    origin: [WideFloat; 2],
    direction: [f64; 2],
    sites: [usize; 2],
}

/// One cell as printed: `rays` only without `--clip`.
#[derive(Debug, Serialize)]
struct CellOutput {
    site: usize,
    vertices: Vec<usize>,
    bounded: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    rays: Option<Vec<RayOutput>>,
}

/// `{"vertices": [[x, y], ...], "cells": [...], "cell_of": [k, ...]}`, plus `"clip"` when
/// clipped. Without `--clip`, a vertex coordinate (or ray origin) whose exact value is beyond
/// the range of `f64` is printed by the overflow rule, as a JSON string holding its decimal
/// value (`"-4.9999999999999995e899"`); every other coordinate is a JSON number.
#[derive(Debug, Serialize)]
struct VoronoiOutput<V> {
    vertices: Vec<V>,
    cells: Vec<CellOutput>,
    cell_of: Vec<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    clip: Option<[f64; 4]>,
}

/// `{"pair": [i, j], "points": [[x, y], [x, y]], "distance": d, "algorithm": "...",
/// "counts": {...}}`.
#[derive(Debug, Serialize)]
struct PairOutput {
    algorithm: &'static str,
    pair: [usize; 2],
    points: [[f64; 2]; 2],
    distance: WideFloat,
    counts: Counts,
}

/// `{"index": i, "point": [x, y], "distance": d, "counts": {...}}`.
#[derive(Debug, Serialize)]
struct NearestOutput {
    index: usize,
    point: [f64; 2],
    distance: WideFloat,
    counts: Counts,
}

/// `{"edges": [[u, v], ...], "length": l, "counts": {...}}`.
#[derive(Debug, Serialize)]
struct EmstOutput {
    edges: Vec<[usize; 2]>,
    length: WideFloat,
    counts: Counts,
}

/// `{"centre": [x, y], "radius": r, "sites": [i, ...], "counts": {...}}`.
#[derive(Debug, Serialize)]
struct CircleOutput {
    centre: [f64; 2],
    radius: WideFloat,
    sites: Vec<usize>,
    counts: Counts,
}

/// Runs `compgeo voronoi`.
pub(super) fn run_voronoi(args: VoronoiArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let set = PointSet::new(&points)?;
    let bounds = match args.clip.as_deref() {
        None => None,
        Some("auto") => Some(ClipBox::around(&set)?),
        Some(text) => {
            let [x0, y0, x1, y1] = parse_numbers::<4>("--clip", text)?;
            Some(ClipBox::new(x0, y0, x1, y1)?)
        }
    };
    let v = voronoi_with(&set, &mut NoCount)?;
    let cell_of = (0..points.len()).map(|i| v.cell_of(i)).collect();
    // The two shapes differ in their vertices: constructed points by the overflow rule, or
    // the clipped polygons' corners.
    match bounds {
        None => print_json(&VoronoiOutput {
            vertices: (0..v.vertices.len()).map(|i| v.vertex(i).wide()).collect(),
            cells: v
                .cells()
                .map(|c| CellOutput {
                    site: c.site,
                    vertices: c.vertices.to_vec(),
                    bounded: c.bounded,
                    rays: Some(ray_outputs(&v, c)),
                })
                .collect(),
            cell_of,
            clip: None,
        }),
        Some(b) => {
            let mut vertices = Vec::new();
            let mut cells = Vec::with_capacity(v.cell_count());
            for (k, cell) in v.cells().enumerate() {
                let polygon = v.clip_cell(k, &b);
                let first = vertices.len();
                vertices.extend(polygon.iter().map(|&p| <[f64; 2]>::from(p)));
                cells.push(CellOutput {
                    site: cell.site,
                    vertices: (first..vertices.len()).collect(),
                    bounded: cell.bounded,
                    rays: None,
                });
            }
            print_json(&VoronoiOutput {
                vertices,
                cells,
                cell_of,
                clip: Some([b.min.x, b.min.y, b.max.x, b.max.y]),
            })
        }
    }
}

/// Runs `compgeo closest-pair`.
pub(super) fn run_closest_pair(args: ClosestPairArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let mut counts = Counts::default();
    let best = closest_pair_with(&PointSet::new(&points)?, args.algorithm, &mut counts)?;
    print_json(&PairOutput {
        algorithm: args.algorithm.name(),
        pair: best.pair,
        points: best.pair.map(|i| points[i].into()),
        distance: best.distance,
        counts,
    })
}

/// Runs `compgeo nearest`.
pub(super) fn run_nearest(args: NearestArgs) -> Result<(), CliError> {
    let [x, y] = parse_numbers::<2>("--query", &args.query)?;
    let points = args.input.read()?;
    let query = Point2::new(x, y);
    let set = PointSet::new(&points)?;
    let search = NearestSearch::new(&set)?;
    let mut counts = Counts::default();
    let index = search.nearest_with(query, None, &mut counts)?;
    let p = points[index];
    print_json(&NearestOutput {
        index,
        point: p.into(),
        distance: WideFloat::distance(p, query),
        counts,
    })
}

/// Runs `compgeo emst`.
pub(super) fn run_emst(args: PointsArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let mut counts = Counts::default();
    let tree = euclidean_mst_with(&PointSet::new(&points)?, &mut counts)?;
    print_json(&EmstOutput {
        edges: tree.edges,
        length: tree.weight,
        counts,
    })
}

/// Runs `compgeo empty-circle`.
pub(super) fn run_empty_circle(args: PointsArgs) -> Result<(), CliError> {
    let points = args.input.read()?;
    let mut counts = Counts::default();
    let c = largest_empty_circle_with(&PointSet::new(&points)?, &mut counts)?;
    print_json(&CircleOutput {
        centre: c.centre.into(),
        radius: c.radius,
        sites: c.sites,
        counts,
    })
}

/// The rays of a cell as printed. A ray of a triangulated point set starts at a Voronoi
/// vertex, the cell's first for the arriving ray and its last for the leaving one (see
/// `Cell`), whose unclamped value is printed; collinear sites' rays start at midpoints.
fn ray_outputs(v: &Voronoi, cell: Cell<'_>) -> Vec<RayOutput> {
    let ends = [cell.vertices.first(), cell.vertices.last()];
    cell.rays
        .iter()
        .enumerate()
        .map(|(k, r)| RayOutput {
            origin: match ends[k % 2] {
                Some(&i) if cell.rays.len() == 2 => v.vertex(i).wide(),
                _ => [r.origin.x, r.origin.y].map(WideFloat::from),
            },
            direction: r.direction.into(),
            sites: r.sites,
        })
        .collect()
}

/// `N` comma-separated numbers; NaN and infinities parse here and are rejected by the
/// library with a message naming the parameter.
pub(super) fn parse_numbers<const N: usize>(flag: &str, text: &str) -> Result<[f64; N], CliError> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let bad = || {
        CliError::Usage(format!(
            "{flag} expects {N} comma-separated numbers, got {}",
            quote(text)
        ))
    };
    if parts.len() != N {
        return Err(bad());
    }
    let mut out = [0.0; N];
    for (slot, part) in out.iter_mut().zip(parts) {
        *slot = parse_f64_or_word(part).ok_or_else(bad)?;
    }
    Ok(out)
}
