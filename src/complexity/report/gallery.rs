//! `gallery.html`: one picture per problem on a small seeded workload, and the step pages of
//! the algorithms the course traces, next to the growth charts.
//!
//! Every picture is the [`draw`](crate::draw) module's, of the library's own result: the
//! point problems on the same points from [`gen::points`] (seed 1, the report's default), so
//! the pictures can be compared; the curves on seeded control polygons (also for the step
//! pages of de Casteljau, de Boor and Lane–Riesenfeld); the surface, the mesh and the graph
//! on fixed or generated inputs. The files go to `DIR/gallery/`; the page links
//! them.

use std::fmt::Write as _;
use std::io;
use std::path::Path;

use crate::calipers::ConvexPolygon;
use crate::delaunay::{fortune_trace, incremental, lawson_trace, voronoi as voronoi_of, ClipBox};
use crate::draw::{self, circle_layout, escape, GraphOverlay};
use crate::gen::with_random_weights;
use crate::gen::{cube, graph as generate_graph, points as generate, GraphKind, PointKind};
use crate::geometry::{Point2, PointSet};
use crate::graph::{colour, ColouringAlgorithm, Graph};
use crate::graph::{
    course_greedy_colouring_trace, kruskal_trace, prim_trace, search_trace, SearchAlgorithm,
    WeightedGraph,
};
use crate::hull::{
    convex_hull, graham_trace, jarvis_trace, monotone_chain_trace, quickhull_trace, Algorithm,
    HullOptions,
};
use crate::mesh::{subdivide, Scheme};
use crate::proximity::{closest_pair, euclidean_mst, largest_empty_circle, ClosestPairAlgorithm};
use crate::spline::beta::{BetaParameters, BetaSpline};
use crate::spline::bspline::{BSpline, KnotVector};
use crate::spline::subdivision::{lane_riesenfeld, lane_riesenfeld_trace, Topology};
use crate::spline::{Bezier, Point};
use crate::surface::{BezierPatch, ControlNet};
use crate::Result;

/// How many points the pictures show: enough to look like the distribution, few enough to
/// number them.
pub(crate) const PICTURE_POINTS: usize = 60;

/// How many points the step pages trace: a run a reader can follow frame by frame.
pub(crate) const STEP_POINTS: usize = 12;

/// One gallery item: a file in `gallery/` and what it shows.
pub(crate) struct Item {
    /// The problem, as the catalog names it.
    pub problem: &'static str,
    /// The file's name in `gallery/`.
    pub file: String,
    /// What the picture shows.
    pub caption: String,
    /// Whether the file is a step page (HTML) rather than a picture (SVG).
    pub steps: bool,
}

/// Writes the pictures and step pages into `dir/gallery/` and `dir/gallery.html`; returns
/// the items written.
pub(crate) fn write_gallery(dir: &Path) -> io::Result<Vec<Item>> {
    let folder = dir.join("gallery");
    std::fs::create_dir_all(&folder)?;
    let mut items = Vec::new();
    for (problem, caption, make) in pictures() {
        let file = format!("{problem}.svg");
        let svg = make().map_err(|e| io::Error::other(format!("gallery {problem}: {e}")))?;
        std::fs::write(folder.join(&file), svg)?;
        items.push(Item {
            problem,
            file,
            caption: caption.to_string(),
            steps: false,
        });
    }
    for (problem, name, make) in step_pages() {
        let file = format!("{problem}-{name}-steps.html");
        let html = make().map_err(|e| io::Error::other(format!("gallery {name}: {e}")))?;
        std::fs::write(folder.join(&file), html)?;
        items.push(Item {
            problem,
            file,
            caption: format!("{name}, step by step"),
            steps: true,
        });
    }
    std::fs::write(dir.join("gallery.html"), gallery_html(&items))?;
    Ok(items)
}

/// A picture of the workload: its SVG text.
type MakePicture = fn() -> Result<String>;

/// The points every picture shows.
fn picture_points() -> Result<Vec<Point2>> {
    generate(PointKind::UniformDisk, PICTURE_POINTS, 1)
}

/// The points every step page traces.
fn step_points() -> Result<Vec<Point2>> {
    generate(PointKind::UniformDisk, STEP_POINTS, 1)
}

/// The pictures: problem, caption, how to draw it.
fn pictures() -> Vec<(&'static str, &'static str, MakePicture)> {
    vec![
        (
            "hull",
            "the convex hull, its vertices numbered in hull order",
            || {
                let pts = picture_points()?;
                let hull = convex_hull(&pts, Algorithm::AklToussaint, HullOptions::default())?;
                Ok(draw::hull(&PointSet::new(&pts)?, &hull)?.to_svg())
            },
        ),
        (
            "diameter",
            "rotating calipers: antipodal pairs, diameter, width, enclosing rectangles",
            || {
                let pts = picture_points()?;
                let set = PointSet::new(&pts)?;
                let polygon = ConvexPolygon::hull(&set);
                Ok(draw::calipers(&polygon, &polygon.diameter()?)?.to_svg())
            },
        ),
        (
            "delaunay",
            "the Delaunay triangulation with its circumcircles",
            || {
                let pts = picture_points()?;
                let t = incremental(&pts)?;
                let v = crate::delaunay::dual(&pts, &t)?;
                Ok(draw::delaunay(&PointSet::new(&pts)?, &t, Some(&v))?.to_svg())
            },
        ),
        ("voronoi", "the Voronoi cells, clipped to a box", || {
            let pts = picture_points()?;
            let set = PointSet::new(&pts)?;
            Ok(draw::voronoi(&set, &voronoi_of(&pts)?, &ClipBox::around(&set)?)?.to_svg())
        }),
        ("closest-pair", "the closest pair", || {
            let pts = picture_points()?;
            let pair = closest_pair(&pts, ClosestPairAlgorithm::Delaunay)?;
            Ok(draw::closest_pair(&PointSet::new(&pts)?, &pair)?.to_svg())
        }),
        ("emst", "the Euclidean minimum spanning tree", || {
            let pts = picture_points()?;
            Ok(draw::emst(&PointSet::new(&pts)?, &euclidean_mst(&pts)?)?.to_svg())
        }),
        (
            "empty-circle",
            "the largest empty circle centred in the hull",
            || {
                let pts = picture_points()?;
                let hull = convex_hull(&pts, Algorithm::AklToussaint, HullOptions::default())?;
                let circle = largest_empty_circle(&pts)?;
                Ok(draw::empty_circle(&PointSet::new(&pts)?, &hull, &circle)?.to_svg())
            },
        ),
        (
            "bezier",
            "a cubic Bézier curve with de Casteljau's scaffolding at t = 1/3",
            || {
                let curve = Bezier::new(control_polygon(4))?;
                Ok(draw::bezier(&curve, Some(&(1.0 / 3.0)))?.to_svg())
            },
        ),
        (
            "bspline",
            "a cubic B-spline, its knots on the curve and de Boor's net at u = 0.4",
            || {
                let control = control_polygon(7);
                let knots = KnotVector::clamped_uniform(3, control.len(), 0.0, 1.0)?;
                Ok(draw::bspline(&BSpline::new(control, knots)?, Some(&0.4))?.to_svg())
            },
        ),
        (
            "beta",
            "a cubic Beta-spline with β₁ = 2, β₂ = 4 and its control polygon",
            || {
                let curve = BetaSpline::new(BetaParameters::new(2.0, 4.0)?, control_polygon(7))?;
                Ok(draw::beta(&curve)?.to_svg())
            },
        ),
        (
            "subdivision",
            "Chaikin's algorithm: a closed polygon and three rounds",
            || {
                let polygon = control_polygon(6);
                let rounds = (0..=3)
                    .map(|k| lane_riesenfeld(&polygon, 2, k, Topology::Closed))
                    .collect::<Result<Vec<_>>>()?;
                Ok(draw::subdivision("Chaikin", &rounds, Topology::Closed)?.to_svg())
            },
        ),
        (
            "surface",
            "a bicubic Bézier patch: isoparametric lines over its control net",
            || {
                let rows = (0..4)
                    .map(|i| {
                        (0..4)
                            .map(|j| {
                                let (x, y) = (i as f64, j as f64);
                                let bump = if (1..3).contains(&i) && (1..3).contains(&j) {
                                    2.0
                                } else {
                                    0.0
                                };
                                Point::new([x, y, bump + 0.25 * (x - y)])
                            })
                            .collect()
                    })
                    .collect();
                let net = ControlNet::new(rows)?;
                let patch = BezierPatch::new(net.clone())?;
                Ok(draw::surface("bicubic Bézier patch", &patch, &net, 8)?.to_svg())
            },
        ),
        (
            "mesh",
            "Catmull–Clark: a cube and two rounds of subdivision",
            || {
                let coarse = cube();
                let fine = subdivide(&coarse, Scheme::CatmullClark, 2)?;
                Ok(draw::mesh(&coarse, Some(&fine))?.to_svg())
            },
        ),
        (
            "colouring",
            "the 6 × 6 queen graph coloured by DSatur",
            || {
                let g = Graph::from_edge_list(&generate_graph(GraphKind::Queen, 6, 0, 1)?)?;
                let c = colour(&g, ColouringAlgorithm::Dsatur);
                let layout = circle_layout(g.vertex_count());
                Ok(draw::graph(&g, &layout, GraphOverlay::Colouring(&c))?.to_svg())
            },
        ),
    ]
}

/// The `n` control points of the curve pictures: seeded points of the unit square, sorted
/// by x so the polygon runs left to right.
fn control_polygon(n: usize) -> Vec<Point<f64, 2>> {
    let mut pts = generate(PointKind::UniformSquare, n, 1).unwrap_or_default();
    pts.sort_by(|a, b| a.x.total_cmp(&b.x));
    pts.into_iter().map(|p| Point::new([p.x, p.y])).collect()
}

/// The step pages: problem, algorithm, how to write it.
fn step_pages() -> Vec<(&'static str, &'static str, MakePicture)> {
    vec![
        ("hull", "jarvis", || {
            let pts = step_points()?;
            let set = PointSet::new(&pts)?;
            let trace = jarvis_trace(&pts, HullOptions::default())?;
            Ok(draw::jarvis_steps(&set, &trace)?.to_html())
        }),
        ("hull", "graham", || {
            let pts = step_points()?;
            let set = PointSet::new(&pts)?;
            let trace = graham_trace(&pts, HullOptions::default())?;
            Ok(draw::graham_steps(&set, &trace)?.to_html())
        }),
        ("hull", "monotone-chain", || {
            let pts = step_points()?;
            let set = PointSet::new(&pts)?;
            let trace = monotone_chain_trace(&pts, HullOptions::default())?;
            Ok(draw::monotone_chain_steps(&set, &trace)?.to_html())
        }),
        ("hull", "quickhull", || {
            let pts = step_points()?;
            let set = PointSet::new(&pts)?;
            let trace = quickhull_trace(&pts, HullOptions::default())?;
            Ok(draw::quickhull_steps(&set, &trace)?.to_html())
        }),
        ("delaunay", "lawson", || {
            let pts = step_points()?;
            let set = PointSet::new(&pts)?;
            Ok(draw::lawson_steps(&set, &lawson_trace(&pts)?)?.to_html())
        }),
        ("delaunay", "fortune", || {
            let pts = step_points()?;
            let set = PointSet::new(&pts)?;
            Ok(draw::fortune_steps(&set, &fortune_trace(&pts)?)?.to_html())
        }),
        ("bezier", "de-casteljau", || {
            let curve = Bezier::new(control_polygon(5))?;
            let t = 1.0 / 3.0;
            Ok(draw::de_casteljau_steps(&curve, &t, &curve.de_casteljau_trace(&t)?)?.to_html())
        }),
        ("bspline", "de-boor", || {
            let control = control_polygon(7);
            let knots = KnotVector::clamped_uniform(3, control.len(), 0.0, 1.0)?;
            let curve = BSpline::new(control, knots)?;
            Ok(draw::de_boor_steps(&curve, &0.4, &curve.de_boor_trace(&0.4)?)?.to_html())
        }),
        ("subdivision", "lane-riesenfeld", || {
            let polygon = control_polygon(6);
            let trace = lane_riesenfeld_trace(&polygon, 3, 2, Topology::Closed)?;
            Ok(draw::lane_riesenfeld_steps(&polygon, 3, Topology::Closed, &trace)?.to_html())
        }),
        ("search", "bfs", || search_page(SearchAlgorithm::Bfs)),
        ("search", "dfs", || search_page(SearchAlgorithm::Dfs)),
        ("colour", "course", || {
            let g = Graph::from_edge_list(&generate_graph(GraphKind::Queen, 5, 0, 1)?)?;
            let order: Vec<usize> = (0..g.vertex_count()).collect();
            let trace = course_greedy_colouring_trace(&g, &order)?;
            let layout = circle_layout(g.vertex_count());
            Ok(draw::colouring_steps(&g, &layout, &trace)?.to_html())
        }),
        ("mst", "prim", || {
            let g = step_weighted_graph()?;
            let layout = circle_layout(g.vertex_count());
            Ok(draw::prim_steps(&g, &layout, &prim_trace(&g)?)?.to_html())
        }),
        ("mst", "kruskal", || {
            let g = step_weighted_graph()?;
            let layout = circle_layout(g.vertex_count());
            Ok(draw::kruskal_steps(&g, &layout, &kruskal_trace(&g)?)?.to_html())
        }),
    ]
}

/// The search step pages: the Petersen graph on a circle, from vertex 0.
fn search_page(algorithm: SearchAlgorithm) -> Result<String> {
    let g = Graph::from_edge_list(&generate_graph(GraphKind::Petersen, 10, 0, 1)?)?;
    let trace = search_trace(&g, 0, algorithm)?;
    let layout = circle_layout(g.vertex_count());
    Ok(draw::search_steps(&g, &layout, algorithm, &trace)?.to_html())
}

/// The graph the spanning-tree step pages trace: 9 vertices and 16 seeded edges, with
/// weights 1 to 9 (seeded) so the labels stay short.
fn step_weighted_graph() -> Result<WeightedGraph> {
    let list = with_random_weights(generate_graph(GraphKind::Gnm, 9, 16, 1)?, 1);
    let weights: Vec<f64> = list
        .weights
        .iter()
        .flatten()
        .map(|w| (1.0 + 9.0 * w).floor().min(9.0))
        .collect();
    WeightedGraph::from_edges(list.vertices, &list.edges, &weights)
}

/// The gallery page.
fn gallery_html(items: &[Item]) -> String {
    let mut h = String::new();
    let _ = write!(
        h,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>compgeo gallery</title>\n<style>\
         body{{font-family:sans-serif;max-width:1700px;margin:1em auto;padding:0 1em;color:#222}}\
         figure{{display:inline-block;vertical-align:top;margin:.5em;max-width:420px}}\
         img{{max-width:100%;border:1px solid #ddd}}</style>\n</head>\n<body>\n\
         <h1>compgeo gallery</h1>\n<p>Each picture is the library's own result, drawn by \
         <code>compgeo draw</code>: the point problems on the same {PICTURE_POINTS} points of the \
         uniform-disk distribution (seed 1), the curves on seeded control polygons, the surface, \
         the mesh and the graph on fixed inputs. Each step page is the run of an algorithm on \
         {STEP_POINTS} such points (the curve algorithms on seeded control polygons, the graph          algorithms on small fixed graphs), a picture per frame of its trace (<code>compgeo draw          --steps</code>; ← and → step through it). <a href=\"index.html\">Back to the          report</a>.</p>\n<h2>Pictures</h2>\n"
    );
    for item in items.iter().filter(|i| !i.steps) {
        let _ = writeln!(
            h,
            "<figure><a href=\"gallery/{file}\"><img src=\"gallery/{file}\" alt=\"{caption}\"></a>\
             <figcaption><strong>{problem}</strong>: {caption}</figcaption></figure>",
            file = escape(&item.file),
            caption = escape(&item.caption),
            problem = escape(item.problem),
        );
    }
    h.push_str("<h2>Step pages</h2>\n<ul>\n");
    for item in items.iter().filter(|i| i.steps) {
        let _ = writeln!(
            h,
            "<li><a href=\"gallery/{}\">{}: {}</a></li>",
            escape(&item.file),
            escape(item.problem),
            escape(&item.caption)
        );
    }
    h.push_str("</ul>\n</body>\n</html>\n");
    h
}
