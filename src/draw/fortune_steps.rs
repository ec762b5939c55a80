//! The step page of Fortune's sweep: one picture per event of the sweep's own trace
//! ([`fortune_trace`](crate::delaunay::fortune_trace)).
//!
//! Each picture shows the sites, the sweep line (horizontal: the sweep moves upwards), the
//! beach line as parabolic arcs between their breakpoints, the Delaunay triangles and the
//! Voronoi vertices found so far, and the event: the new site ringed, or the empty circle
//! whose top the sweep line has reached, with its centre ringed and its new triangle
//! highlighted.
//!
//! The beach line is drawn, not decided: each arc is the parabola of its site with the sweep
//! line as directrix, sampled between its breakpoints in `f64`, in the picture's own units
//! (coordinates taken relative to the frame's origin and scaled by its power of two, so any
//! finite input draws). Which arcs there are, and in which order, is the trace's: the sweep's
//! exact decisions. A site on the sweep line owns a spike, a vertical segment down to the
//! arcs below it (the whole lowest row, at first).
//!
//! Every picture of the page shares one frame: the sites' bounding box, grown to hold the
//! sweep line's positions and the Voronoi vertices that lie within half the box's larger
//! side of it. A sweep line or a vertex farther away is left out (the caption says where the
//! sweep line is).

use super::hull_steps::{check, mark, picture_in};
use super::steps::{StepFrame, StepPage};
use super::svg::{Layer, Picture, Role};
use super::{bounds_of, points_legend, value, Frame};
use crate::delaunay::FortuneStep;
use crate::geometry::{BoundingBox, ConstructedPoint, Point2, PointSet, WideFloat};
use crate::trace::Frame as TraceFrame;
use crate::Result;

/// Samples of the beach line per picture, shared among the arcs by their drawn width.
const BEACH_SAMPLES: f64 = 240.0;

/// The fewest samples of an arc (its two ends and its middle).
const ARC_SAMPLES: usize = 3;

/// The step page of Fortune's sweep from its trace
/// ([`fortune_trace`](crate::delaunay::fortune_trace)): a picture per site event and per
/// circle event, and the triangulation with its Voronoi vertices at the end.
///
/// The layers a test or a reader can look for: `sweep` (the sweep line, when it is in the
/// picture), `beach` (the arcs and spikes), `triangles` (found so far; the result in the
/// last frame), `vertices` (the Voronoi vertices so far within the picture), `current` (the
/// event's site or vertex), `event` (a circle event's triangle) and `circle` (its empty
/// circle).
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if a frame names a point
/// outside `points`, [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
/// [`STEP_PAGE_MAX_FRAMES`](crate::limits::STEP_PAGE_MAX_FRAMES) frames.
///
/// # Complexity
/// O(f·(n + a + t)) time and output for f frames, n points, beach lines of up to a arcs
/// and t triangles: each beach line takes at most 240 + 3a samples.
///
/// ```
/// use compgeo::delaunay::fortune_trace;
/// use compgeo::draw::fortune_steps;
/// use compgeo::geometry::{Point2, PointSet};
///
/// let pts = [(0.0, 0.0), (4.0, 0.5), (1.5, 2.0), (3.0, 3.0)].map(Point2::from);
/// let trace = fortune_trace(&pts)?;
/// let page = fortune_steps(&PointSet::new(&pts)?, &trace)?;
/// assert_eq!(page.frames().len(), trace.len());
/// assert_eq!(page.frames()[0].kind, "site");
/// assert!(page.to_html().contains("<g class=\"beach\""));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn fortune_steps(points: &PointSet<'_>, trace: &[TraceFrame<FortuneStep>]) -> Result<StepPage> {
    let pts: &[Point2] = points;
    for frame in trace {
        match &frame.step {
            FortuneStep::Site {
                site,
                beach,
                triangles,
                ..
            } => check(points, beach.iter().chain(triangles).chain([site]))?,
            FortuneStep::Circle {
                triangle,
                beach,
                triangles,
                ..
            } => check(points, beach.iter().chain(triangles).chain(triangle))?,
            FortuneStep::Done { triangulation } => check(points, &triangulation.triangles)?,
        }
    }
    let title = format!("Fortune's sweep on {}", points_legend(pts.len()));
    let mut page = StepPage::new(&title).about(
        "Fortune's sweep [RD, §2.4]: a horizontal line moves upwards over the sites. Below \
         the beach line (the parabolas of the points as far from a site as from the line) the \
         Voronoi diagram is final. A site event adds the site's arc; a circle event removes an \
         arc squeezed between its neighbours when the line leaves the circle through the \
         three sites: its centre is a Voronoi vertex, and the three sites a Delaunay triangle.",
    );
    let bounds = page_bounds(pts, trace);
    let inside = |p: ConstructedPoint| p.finite().is_some_and(|p| contains(&bounds, p));
    let mut vertices: Vec<ConstructedPoint> = Vec::new();
    for frame in trace {
        let (kind, caption, picture) = match &frame.step {
            FortuneStep::Site {
                site,
                sweep,
                beach,
                triangles,
            } => {
                let picture = picture_in(bounds, pts, &title, |p| {
                    so_far(p, pts, triangles, &vertices, inside);
                    beach_line(p, pts, beach, *sweep);
                    sweep_line(p, &bounds, *sweep);
                    mark(p, pts, "new site", &[*site]);
                });
                let k = beach.iter().position(|s| s == site);
                let split = k.and_then(|k| {
                    (k > 0 && k + 1 < beach.len() && beach[k - 1] == beach[k + 1])
                        .then(|| beach[k - 1])
                });
                let what = match split {
                    Some(a) => format!("its arc splits the arc of site {a}"),
                    None if beach.len() == 1 => "the first arc".to_string(),
                    None => "a spike beside the others in the lowest row".to_string(),
                };
                let caption = format!(
                    "Site event: the sweep line reaches site {site} (y = {}); {what}. The beach \
                     line has {} arcs.{}",
                    value(WideFloat::from(*sweep)),
                    beach.len(),
                    off_picture(&bounds, *sweep)
                );
                ("site", caption, picture)
            }
            FortuneStep::Circle {
                triangle,
                vertex,
                sweep,
                beach,
                triangles,
            } => {
                vertices.push(*vertex);
                let [a, b, c] = *triangle;
                let picture = picture_in(bounds, pts, &title, |p| {
                    so_far(p, pts, triangles, &vertices, inside);
                    p.polygons(
                        &Layer::new("event", Role::Highlight).legend("new triangle"),
                        [triangle.map(|i| pts[i])],
                    );
                    p.circles(
                        &Layer::new("circle", Role::Circle).legend("empty circle"),
                        [(*vertex, pts[a])],
                    );
                    beach_line(p, pts, beach, *sweep);
                    sweep_line(p, &bounds, *sweep);
                    p.rings(
                        &Layer::new("current", Role::Highlight).legend("new Voronoi vertex"),
                        Some(*vertex).filter(|&v| inside(v)),
                    );
                });
                let [x, y] = vertex.wide();
                let caption = format!(
                    "Circle event: the sweep line leaves the circle through sites {a}, {b} and \
                     {c} at its top (y = {}); the arc of site {b} vanishes. Its centre \
                     ({}, {}) is a Voronoi vertex, and triangle {a}, {b}, {c} is Delaunay \
                     ({} so far).{}",
                    value(WideFloat::from(*sweep)),
                    value(x),
                    value(y),
                    triangles.len() / 3,
                    off_picture(&bounds, *sweep)
                );
                ("circle", caption, picture)
            }
            FortuneStep::Done { triangulation } => {
                let picture = picture_in(bounds, pts, &title, |p| {
                    p.polygons(
                        &Layer::new("triangles", Role::Result).legend("Delaunay triangles"),
                        triangles_of(pts, &triangulation.triangles),
                    );
                    vertices_layer(p, &vertices, inside);
                });
                let caption = format!(
                    "No event is left: {} Delaunay triangles, the duals of {} Voronoi vertices.",
                    triangulation.triangles.len() / 3,
                    vertices.len()
                );
                ("done", caption, picture)
            }
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The triangles (flat, three indices each) as point triples.
fn triangles_of(pts: &[Point2], triangles: &[usize]) -> Vec<[Point2; 3]> {
    triangles
        .chunks_exact(3)
        .map(|t| [pts[t[0]], pts[t[1]], pts[t[2]]])
        .collect()
}

/// Draws the triangles and the Voronoi vertices found so far.
fn so_far(
    picture: &mut Picture,
    pts: &[Point2],
    triangles: &[usize],
    vertices: &[ConstructedPoint],
    inside: impl Fn(ConstructedPoint) -> bool,
) {
    picture.polygons(
        &Layer::new("triangles", Role::Triangulation).legend("Delaunay triangles so far"),
        triangles_of(pts, triangles),
    );
    vertices_layer(picture, vertices, inside);
}

/// Draws the Voronoi vertices that lie inside the picture.
fn vertices_layer(
    picture: &mut Picture,
    vertices: &[ConstructedPoint],
    inside: impl Fn(ConstructedPoint) -> bool,
) {
    picture.points(
        &Layer::new("vertices", Role::Voronoi).legend("Voronoi vertices"),
        vertices.iter().copied().filter(|&v| inside(v)),
    );
}

/// Whether `p` lies in the closed box.
fn contains(b: &BoundingBox, p: Point2) -> bool {
    (b.min.x..=b.max.x).contains(&p.x) && (b.min.y..=b.max.y).contains(&p.y)
}

/// Whether the sweep line `y = sweep` crosses the box.
fn crosses(b: &BoundingBox, sweep: f64) -> bool {
    (b.min.y..=b.max.y).contains(&sweep)
}

/// A note for a caption when the sweep line is outside the picture.
fn off_picture(b: &BoundingBox, sweep: f64) -> &'static str {
    if crosses(b, sweep) {
        ""
    } else {
        " (The sweep line is above the picture.)"
    }
}

/// The page's world box: the sites' bounding box, grown to hold every sweep position and
/// Voronoi vertex within half its larger side of it.
fn page_bounds(pts: &[Point2], trace: &[TraceFrame<FortuneStep>]) -> BoundingBox {
    let sites = bounds_of(pts);
    let half = sites.width().max(sites.height()).scale_pow2(-1);
    let grow = |v: f64, sign: f64| {
        WideFloat::from(v)
            .add(half.mul(WideFloat::from(sign)))
            .to_f64_saturating()
    };
    let window = BoundingBox {
        min: Point2::new(grow(sites.min.x, -1.0), grow(sites.min.y, -1.0)),
        max: Point2::new(grow(sites.max.x, 1.0), grow(sites.max.y, 1.0)),
    };
    let mut bounds = sites;
    for frame in trace {
        let (sweep, vertex) = match &frame.step {
            FortuneStep::Site { sweep, .. } => (*sweep, None),
            FortuneStep::Circle { sweep, vertex, .. } => (*sweep, vertex.finite()),
            FortuneStep::Done { .. } => continue,
        };
        if crosses(&window, sweep) {
            bounds.extend(Point2::new(sites.min.x, sweep));
        }
        if let Some(v) = vertex.filter(|&v| contains(&window, v)) {
            bounds.extend(v);
        }
    }
    bounds
}

/// Draws the sweep line `y = sweep` across the picture, if it crosses the page's box.
fn sweep_line(picture: &mut Picture, bounds: &BoundingBox, sweep: f64) {
    if !crosses(bounds, sweep) {
        return;
    }
    let units = Units::of(picture.frame());
    let direction = [units.world(0.0, 0.0), units.world(1.0, 0.0)];
    let at = ConstructedPoint::Finite(Point2::new(bounds.min.x, sweep));
    let legend = format!("sweep line, y = {}", value(WideFloat::from(sweep)));
    picture.parallels(
        &Layer::new("sweep", Role::Construction).legend(legend),
        direction,
        [at],
    );
}

/// World coordinates against picture units: `(x, y)` is `(X, Y)` units right of and above
/// the frame's origin (the picture's y axis turned up).
struct Units {
    frame: Frame,
}

impl Units {
    fn of(frame: &Frame) -> Units {
        Units { frame: *frame }
    }

    /// The units of the world point `p`.
    fn local(&self, p: Point2) -> [f64; 2] {
        let o = self.frame.origin();
        [
            self.frame.length(WideFloat::difference(p.x, o.x)),
            self.frame.length(WideFloat::difference(p.y, o.y)),
        ]
    }

    /// The world point `(x, y)` units from the origin (finite when it fits in `f64`).
    fn world(&self, x: f64, y: f64) -> ConstructedPoint {
        let o = self.frame.origin();
        let shift = self.frame.shift();
        let wx = WideFloat::from(o.x).add(WideFloat::scaled(x, shift));
        let wy = WideFloat::from(o.y).add(WideFloat::scaled(y, shift));
        match (wx.to_f64(), wy.to_f64()) {
            (Some(x), Some(y)) => ConstructedPoint::Finite(Point2::new(x, y)),
            _ => ConstructedPoint::BeyondRange([wx, wy]),
        }
    }

    /// The drawing area's `[left, right, bottom]` in units.
    fn area(&self) -> [f64; 3] {
        let [l, _, r, b] = self.frame.area();
        let [left, bottom] = self.frame.anchor();
        [l - left, r - left, bottom - b]
    }
}

/// The depth below the sweep line, in picture units, under which a site's parabola is
/// drawn as a spike: 600 units below its top it is then under 0.04 units wide.
const SPIKE_DEPTH: f64 = 1e-6;

/// One arc's focus in picture units and its distance below the line (0 for a spike).
#[derive(Clone, Copy)]
struct Focus {
    x: f64,
    y: f64,
    depth: f64,
}

impl Focus {
    /// The parabola's height at `x`: `(line + y) / 2 − (x − fx)² / (2 depth)`.
    fn height(self, line: f64, x: f64) -> f64 {
        let dx = x - self.x;
        (line + self.y) / 2.0 - dx * dx / (2.0 * self.depth)
    }

    /// A site on the sweep line, or so near it that its parabola is narrower than the
    /// drawing's precision (`SPIKE_DEPTH`): a vertical segment.
    fn is_spike(self) -> bool {
        self.depth <= SPIKE_DEPTH
    }
}

/// Where the arc of `p` (left) meets the arc of `q` (right) under the sweep line: the
/// crossing of their parabolas on the side of the lower site's wider parabola that keeps
/// `p` on the left; a spike's own `x`.
fn breakpoint(p: Focus, q: Focus) -> f64 {
    match (p.is_spike(), q.is_spike()) {
        (true, true) => return (p.x + q.x) / 2.0,
        (true, false) => return p.x,
        (false, true) => return q.x,
        (false, false) => {}
    }
    let (dp, dq) = (p.depth, q.depth);
    if dp == dq {
        return (p.x + q.x) / 2.0;
    }
    // dp (x − qx)² − dq (x − px)² + dp dq (py − qy) = 0, as A x² + B x + C = 0, around
    // u = x − px; the wanted root is (−B − √disc) / (2A) whichever sign A has.
    let w = q.x - p.x;
    let a = dp - dq;
    let b = -2.0 * dp * w;
    let c = dp * w * w + dp * dq * (p.y - q.y);
    let root = (b * b - 4.0 * a * c).max(0.0).sqrt();
    let u = if b <= 0.0 {
        2.0 * c / (-b + root)
    } else {
        (-b - root) / (2.0 * a)
    };
    p.x + if u.is_finite() { u } else { w / 2.0 }
}

/// Draws the beach line of the arcs of `beach` (sites, left to right) under the sweep line
/// `y = sweep`: each parabolic arc sampled between its breakpoints and cut to the drawing
/// area, each spike from its site down to the arcs below it.
fn beach_line(picture: &mut Picture, pts: &[Point2], beach: &[usize], sweep: f64) {
    if beach.is_empty() {
        return;
    }
    let units = Units::of(picture.frame());
    let line = units.local(Point2::new(pts[beach[0]].x, sweep))[1];
    let [x_min, x_max, y_min] = units.area();
    let foci: Vec<Focus> = beach
        .iter()
        .map(|&s| {
            let [x, y] = units.local(pts[s]);
            let depth = if pts[s].y < sweep { line - y } else { 0.0 };
            Focus { x, y, depth }
        })
        .collect();
    let breaks: Vec<f64> = foci.windows(2).map(|w| breakpoint(w[0], w[1])).collect();
    let spans: Vec<(f64, f64)> = (0..foci.len())
        .map(|i| {
            let lo = if i == 0 {
                x_min
            } else {
                breaks[i - 1].max(x_min)
            };
            let hi = if i + 1 == foci.len() {
                x_max
            } else {
                breaks[i].min(x_max)
            };
            (lo, hi)
        })
        .collect();
    let total: f64 = foci
        .iter()
        .zip(&spans)
        .filter(|(f, (lo, hi))| !f.is_spike() && hi > lo)
        .map(|(_, (lo, hi))| hi - lo)
        .sum();
    let mut lines: Vec<Vec<ConstructedPoint>> = Vec::new();
    for (focus, &(lo, hi)) in foci.iter().zip(&spans) {
        if focus.is_spike() {
            let below = foci
                .iter()
                .filter(|f| !f.is_spike())
                .map(|f| f.height(line, focus.x))
                .fold(y_min, f64::max);
            lines.push(vec![
                units.world(focus.x, focus.y),
                units.world(focus.x, below.min(focus.y)),
            ]);
            continue;
        }
        if hi <= lo {
            continue;
        }
        let share = (BEACH_SAMPLES * (hi - lo) / total) as usize;
        let samples = share.max(ARC_SAMPLES);
        let mut run: Vec<ConstructedPoint> = Vec::new();
        for k in 0..samples {
            let x = lo + (hi - lo) * k as f64 / (samples - 1) as f64;
            let y = focus.height(line, x);
            if y >= y_min {
                run.push(units.world(x, y));
            } else if !run.is_empty() {
                lines.push(std::mem::take(&mut run));
            }
        }
        if !run.is_empty() {
            lines.push(run);
        }
    }
    picture.polylines(
        &Layer::new("beach", Role::Result).legend("beach line"),
        lines,
    );
}
