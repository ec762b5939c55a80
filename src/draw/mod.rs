//! SVG pictures of the geometric results: a point set with its hull, the calipers' answers,
//! the Delaunay triangulation, the Voronoi diagram, the closest pair, the Euclidean minimum
//! spanning tree and the largest empty circle; of curves (Bézier curves with de Casteljau's
//! scaffolding, B-splines with their knots and de Boor's net, NURBS, Beta-splines, the rounds
//! of a subdivision scheme), of surfaces and meshes as projected wireframes, and of graphs
//! with a colouring, a spanning tree or a search tree.
//!
//! Drawing is not an algorithm of the course: nothing here is declared or measured, and
//! nothing here computes geometry. Every picture takes the results the other modules return
//! (hull indices, a [`Triangulation`](crate::delaunay::Triangulation), a
//! [`Voronoi`](crate::delaunay::Voronoi) diagram and its clipped cells, ...) and only maps and
//! styles them. The module needs no dependency and no feature: the pictures are strings.
//!
//! # The pieces
//!
//! | item | what it is | file |
//! |---|---|---|
//! | [`Frame`] | the world → picture transform: y up, one power-of-two scale for both axes, every finite input drawable | `frame.rs` |
//! | [`Picture`], [`Layer`], [`Role`], [`Style`] | a picture's layers (one SVG group each, the style written once), labels, legend and text | `svg.rs` |
//! | [`hull`], [`calipers`] | a point set with its hull; with antipodal pairs, diameter, width and enclosing rectangles | `hull.rs` |
//! | [`delaunay`], [`voronoi`] | a triangulation (optionally with circumcircles); Voronoi cells clipped to a box | `delaunay.rs` |
//! | [`closest_pair`], [`emst`], [`empty_circle`] | the proximity answers over their point set | `proximity.rs` |
//! | [`bezier`], [`bspline`], [`nurbs`], [`beta`], [`subdivision`] | curves over their control polygons, de Casteljau's scaffolding, de Boor's net, knots, subdivision rounds | `curves.rs` |
//! | [`surface`], [`triangular_patch`], [`mesh`], [`project`] | projected wireframes: isoparametric lines over the control net, a mesh's edges over the coarse mesh | `surfaces.rs` |
//! | [`graph`], [`circle_layout`], [`GraphOverlay`] | a graph at coordinates or on a circle, with a colouring, a spanning or a search tree | `graphs.rs` |
//! | [`StepPage`], [`StepFrame`] | a run as one self-contained HTML page, a picture per step, a slider and keys | `steps.rs` |
//! | [`jarvis_steps`], [`graham_steps`], [`monotone_chain_steps`], [`quickhull_steps`], [`lawson_steps`] | step pages of the traced hulls and of Lawson's flips, from the [`trace`](crate::trace) frames | `hull_steps.rs` |
//! | [`fortune_steps`] | the step page of Fortune's sweep: the sweep line, the beach line's arcs, the triangles and Voronoi vertices so far, each event | `fortune_steps.rs` |
//! | [`de_casteljau_steps`], [`de_boor_steps`], [`lane_riesenfeld_steps`] | step pages of the curve traces: de Casteljau's scaffolding and de Boor's net level by level over the curve, the Lane–Riesenfeld polygon after each doubling and pass over the original | `curve_steps.rs` |
//! | [`search_steps`], [`colouring_steps`], [`prim_steps`], [`kruskal_steps`] | step pages of breadth- and depth-first search (Q, the vertices reached, the tree so far), the course's greedy colouring (the colours so far, the neighbours that ruled colours out) and Prim's and Kruskal's trees (the tree so far, each edge accepted or rejected), drawn by the body of [`graph`] | `graph_steps.rs` |
//!
//! A new kind of picture is a new file that builds a [`Picture`] from its own results,
//! using the same roles.
//!
//! # Conventions
//!
//! - **Frame.** y grows upwards as everywhere in the crate (SVG's own y grows downwards);
//!   one scale for both axes, so circles stay round. The frame is written in the root
//!   element (`data-frame`, see [`Frame`]) so a reader can map the picture back to the
//!   world. Coordinates of any magnitude, `1e300` or subnormal, are normalised through the
//!   bounding box; a single point or a vertical segment gets a frame of its own size.
//! - **Colours by role** ([`Role`]): input points near black, the result blue, a second
//!   result sky blue and dashed, a highlighted pair vermillion, triangulation edges grey,
//!   Voronoi edges green, circles purple, construction lines orange and dashed; white
//!   background, so pictures read in print and on screen.
//! - **Sizes and labels.** Pictures of up to [`LABEL_LIMIT`] points number their points;
//!   larger ones have no labels, thinner strokes and smaller dots. The file grows linearly
//!   with the input: points and edges are subpaths of a few `<path>` elements whose style
//!   is written once per layer, with coordinates rounded to two decimals (one without
//!   labels).
//! - **Legend.** Each layer drawn with a legend text gets an entry below the drawing, after
//!   the title.
//! - **Errors.** A drawing function checks the indices it is given against the point set
//!   ([`Error::InvalidParameter`] names the first bad one).
//!   An empty point set draws an empty picture, as the structures of the other modules
//!   exist for every input.
//!
//! # Complexity
//!
//! Every picture takes O(n + k) time and output size for n points and k drawn items
//! (hull vertices, triangles, cells, edges), plus O(m²) for the m ≤ 4 · [`LABEL_LIMIT`]
//! labels it places; a curve or surface adds its evaluations at the drawn parameters
//! ([`SAMPLES_PER_PIECE`] per piece).
//!
//! # What the tests check
//!
//! `tests/suite/draw.rs` parses every picture with an XML parser and maps it back to the
//! world through the recorded frame, in exact rationals: the drawn hull is the hull in
//! order, the triangles and circumcircles are the triangulation's, the cells are
//! [`Voronoi::clip`](crate::delaunay::Voronoi::clip)'s, the pairs, the width's lines and
//! the rectangles' corners are the calipers'; labels appear up to [`LABEL_LIMIT`] points
//! and not beyond; y grows upwards; extreme and degenerate inputs give finite numbers;
//! files grow linearly. `tests/suite/draw_curves.rs` does the same for curves, surfaces, meshes
//! and graphs against exact oracles: the curve's vertices are the curve's points (de
//! Casteljau's levels from the Bernstein form, a clamped B-spline against its Bézier curve, a
//! uniform Beta-spline against its B-spline, a NURBS arc against the circle), the knots sit on
//! the curve, the wireframes are the projected surface points, the mesh's edges are drawn
//! once each, the colour classes are the colouring's and proper, the tree edges are the
//! tree's. `tests/suite/draw_cli.rs` and `draw_curves_cli.rs` check `compgeo draw` against
//! the other commands. `tests/suite/draw_steps.rs` and `draw_curve_steps.rs` read the step
//! pages: one frame per trace frame with its counts, each frame's state drawn where the
//! trace has it (the curve pages' levels mapped back exactly, the last point the curve's
//! value from the Bernstein form or the B-spline basis, the last polygon the subdivision's
//! result), and every page of the report's gallery parses.
//! `tests/suite/draw_graph_steps.rs` reads the graph step pages back the same way: Q and the
//! tree so far as the trace has them, each colouring frame a prefix of the plain colouring,
//! Kruskal's drawn edges a forest in every frame (an edge rejected exactly when its ends are
//! already joined), and the last frame the plain function's tree or colouring with the
//! counted run's counts.
//!
//! ```
//! use compgeo::delaunay::{dual, incremental};
//! use compgeo::draw::{self, Layer, Role};
//! use compgeo::geometry::{Point2, PointSet};
//!
//! let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (1.0, 1.0), (0.0, 3.0)].map(Point2::from);
//! let t = incremental(&pts)?;
//! let mut picture = draw::delaunay(&PointSet::new(&pts)?, &t, Some(&dual(&pts, &t)?))?;
//! // A picture is open to more layers before it is written.
//! picture.points(&Layer::new("origin", Role::Highlight).legend("origin"), [Point2::new(0.0, 0.0)]);
//! let svg = picture.to_svg();
//! assert!(svg.contains("<g class=\"triangles\"") && svg.contains("<g class=\"origin\""));
//! assert!(svg.contains(">4</text>")); // point 4 is labelled
//!
//! // Any finite coordinates draw.
//! let far = [(0.0, 0.0), (1e300, 0.0), (0.0, 5e-324)].map(Point2::from);
//! let svg = draw::hull(&PointSet::new(&far)?, &[0, 1, 2])?.to_svg();
//! assert!(svg.contains("data-frame=\"0 0 "));
//! assert!(!svg.contains("NaN") && !svg.contains("inf"));
//! # Ok::<(), compgeo::Error>(())
//! ```

mod curve_steps;
mod curves;
mod delaunay;
mod fortune_steps;
mod frame;
mod graph_steps;
mod graphs;
mod hull;
mod hull_steps;
mod labels;
mod proximity;
mod steps;
mod surfaces;
mod svg;

pub use curve_steps::{de_boor_steps, de_casteljau_steps, lane_riesenfeld_steps};
pub use curves::{beta, bezier, bspline, nurbs, sample_parameters, subdivision, SAMPLES_PER_PIECE};
pub use delaunay::{delaunay, voronoi};
pub use fortune_steps::fortune_steps;
pub use frame::Frame;
pub use graph_steps::{colouring_steps, kruskal_steps, prim_steps, search_steps};
pub use graphs::{circle_layout, graph, GraphOverlay};
pub use hull::{calipers, hull};
pub use hull_steps::{
    graham_steps, jarvis_steps, lawson_steps, monotone_chain_steps, quickhull_steps,
};
pub use proximity::{closest_pair, empty_circle, emst};
pub use steps::{StepFrame, StepPage};
pub use surfaces::{mesh, surface, triangular_patch};
pub use svg::{escape, Dash, Layer, Picture, Role, Style, CLASS_COLOURS, LABEL_LIMIT};

use crate::error::{Error, Result};
use crate::geometry::{BoundingBox, Point2, WideFloat};
use crate::spline::{Point, Scalar};

/// The factor of the cabinet projection, √2 / 4: the y axis recedes at 45° with half its
/// length (see [`project`]).
pub const CABINET: f64 = std::f64::consts::SQRT_2 / 4.0;

/// The picture-plane point of a curve's or surface's point, rounded to `f64`: in two
/// dimensions the point itself; in three the fixed cabinet projection
///
/// ```text
/// (x, y, z) ↦ (x + k·y, z + k·y),   k = √2 / 4 (CABINET)
/// ```
///
/// which keeps x to the right and z up, and draws the y axis receding at 45° up and to the
/// right at half its length, so that a height field z = f(x, y) reads as a relief seen from
/// the front and slightly above. Lengths and angles in planes y = const are kept.
///
/// # Errors
/// [`Error::InvalidParameter`] named `"dimension"` for points in a dimension other than 2
/// or 3; [`Error::Overflow`] if the point or its projection is beyond the range of `f64`.
///
/// # Complexity
/// O(D) time.
///
/// ```
/// use compgeo::draw::{project, CABINET};
/// use compgeo::geometry::Point2;
/// use compgeo::spline::Point;
///
/// assert_eq!(project(&Point::new([1.0, 2.0]))?, Point2::new(1.0, 2.0));
/// assert_eq!(project(&Point::new([1.0, 0.0, 3.0]))?, Point2::new(1.0, 3.0));
/// assert_eq!(project(&Point::new([0.0, 4.0, 0.0]))?, Point2::new(4.0 * CABINET, 4.0 * CABINET));
/// assert!(project(&Point::new([1.0])).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn project<S: Scalar, const D: usize>(p: &Point<S, D>) -> Result<Point2> {
    let c = p.to_f64();
    let c = c.coords();
    let (x, y) = match D {
        2 => (c[0], c[1]),
        3 => (c[0] + CABINET * c[1], c[2] + CABINET * c[1]),
        _ => {
            return Err(Error::InvalidParameter {
                name: "dimension",
                reason: format!("pictures are of points in 2 or 3 dimensions, got {D}"),
            })
        }
    };
    if x.is_finite() && y.is_finite() {
        Ok(Point2::new(x, y))
    } else {
        Err(Error::Overflow {
            what: "the projection for drawing",
        })
    }
}

/// The bounding box of `points`, or the unit box at the origin for no points (an empty
/// picture still has a frame).
fn bounds_of(points: &[Point2]) -> BoundingBox {
    BoundingBox::of(points).unwrap_or(BoundingBox {
        min: Point2::new(0.0, 0.0),
        max: Point2::new(1.0, 1.0),
    })
}

/// Checks that every index is below `n`.
///
/// # Errors
/// [`Error::InvalidParameter`] named `name`, giving the first index out of range.
fn check_indices(
    name: &'static str,
    indices: impl IntoIterator<Item = usize>,
    n: usize,
) -> Result<()> {
    match indices.into_iter().find(|&i| i >= n) {
        None => Ok(()),
        Some(i) => Err(Error::InvalidParameter {
            name,
            reason: format!("index {i} is out of range for {n} points"),
        }),
    }
}

/// Each point of `indices` labelled with its index.
fn index_labels<'a>(
    points: &'a [Point2],
    indices: impl IntoIterator<Item = usize> + 'a,
) -> impl Iterator<Item = (Point2, String)> + 'a {
    indices.into_iter().map(|i| (points[i], i.to_string()))
}

/// Draws `points` as the input layer (dots) and numbers each by its index, `what` saying in
/// the legend what the numbers are: the top layers of most pictures.
fn indexed_points(picture: &mut Picture, points: &[Point2], what: &str) {
    picture.points(
        &Layer::new("points", Role::Input).legend(points_legend(points.len())),
        points.iter().copied(),
    );
    picture.labels(
        &Layer::new("labels", Role::Label).legend(what),
        index_labels(points, 0..points.len()),
    );
}

/// The legend text of the input points.
fn points_legend(n: usize) -> String {
    match n {
        1 => "1 point".to_string(),
        n => format!("{n} points"),
    }
}

/// A length, area or distance for a legend: six significant digits when it fits in `f64`,
/// the decimal value otherwise.
fn value(w: WideFloat) -> String {
    match w.to_f64() {
        Some(v) if v != 0.0 => {
            let rounded: f64 = format!("{v:.5e}").parse().unwrap_or(v);
            if (1e-4..1e7).contains(&rounded.abs()) {
                rounded.to_string()
            } else {
                format!("{rounded:e}")
            }
        }
        Some(_) => "0".to_string(),
        None => {
            // `d.ddd…e±N` beyond f64: the significand to six digits.
            let text = w.to_string();
            match text.split_once('e') {
                Some((significand, exponent)) => {
                    let rounded: f64 = format!("{:.5e}", significand.parse::<f64>().unwrap_or(0.0))
                        .parse()
                        .unwrap_or(0.0);
                    format!("{rounded}e{exponent}")
                }
                None => text,
            }
        }
    }
}
