//! Step pages of the curve algorithms the course traces: de Casteljau's scaffolding, de
//! Boor's net and the Lane–Riesenfeld rounds, one picture per frame of the algorithm's own
//! trace.
//!
//! Every picture of a page shares one frame (the curve, its control polygon and every point
//! of the trace), so stepping through the page moves nothing but what changed. The layers
//! are those of the curve pictures ([`bezier`](super::bezier), [`bspline`](super::bspline),
//! [`subdivision`](super::subdivision)): the curve blue, the control polygon orange and
//! dashed, the control points numbered. On top of them, the level the frame computed is
//! highlighted (vermillion, layers `level` and `level-points`) over the levels before it
//! (grey); the last frame's single point is the layer `point`. A Lane–Riesenfeld frame draws
//! the polygon after its step (`polygon`, `polygon-points`) over the original polygon
//! (`original`, light).

use super::curves::{
    control_points, control_polygon, curve_layer, curve_points, draw_polygon, net_layers,
    parameter, projected, spline_samples,
};
use super::steps::{StepFrame, StepPage};
use super::svg::{Layer, Picture, Role};
use super::{bounds_of, value};
use crate::geometry::{BoundingBox, Point2, WideFloat};
use crate::spline::subdivision::{LaneRiesenfeldStep, Topology};
use crate::spline::{
    validate_parameter, BSpline, Bezier, CasteljauLevel, DeBoorLevel, Point, Scalar,
};
use crate::trace::Frame;
use crate::{Error, Result};

/// What every frame of a de Casteljau or de Boor page draws: the curve, the control
/// polygon and points, and the levels of the scheme so far.
struct Scheme {
    title: String,
    bounds: BoundingBox,
    samples: Vec<Point2>,
    control: Vec<Point2>,
    levels: Vec<Vec<Point2>>,
}

impl Scheme {
    /// The scheme of `levels` over the curve `samples` and its `control` polygon, in a
    /// frame that holds them all.
    fn new(
        title: String,
        samples: Vec<Point2>,
        control: Vec<Point2>,
        levels: Vec<Vec<Point2>>,
    ) -> Scheme {
        let all: Vec<Point2> = samples
            .iter()
            .chain(&control)
            .chain(levels.iter().flatten())
            .copied()
            .collect();
        Scheme {
            title,
            bounds: bounds_of(&all),
            samples,
            control,
            levels,
        }
    }

    /// The picture of level `k`: the levels before it grey (without level 0, the control
    /// polygon), level k highlighted, or as the point when it is the last one; `draw` adds
    /// its own layers under the control points.
    fn picture(
        &self,
        k: usize,
        names: [&str; 2],
        legends: [&str; 2],
        draw: impl FnOnce(&mut Picture),
    ) -> Picture {
        let mut picture = Picture::new(&self.title, self.bounds, self.control.len());
        control_polygon(&mut picture, &self.control, false);
        net_layers(
            &mut picture,
            names,
            Role::Triangulation,
            legends[0],
            self.levels.get(1..k).unwrap_or(&[]),
        );
        curve_layer(&mut picture, &self.samples);
        draw(&mut picture);
        let level = &self.levels[k];
        if k + 1 < self.levels.len() {
            picture.polylines(
                &Layer::new("level", Role::Highlight).legend(format!("level {k}")),
                [level.iter().copied()],
            );
            picture.points(
                &Layer::new("level-points", Role::Highlight),
                level.iter().copied(),
            );
        }
        control_points(&mut picture, &self.control);
        if k + 1 == self.levels.len() {
            picture.points(
                &Layer::new("point", Role::Highlight).legend(legends[1]),
                level.iter().copied(),
            );
        }
        picture
    }
}

/// A point for a caption: its coordinates to six significant digits.
fn coordinates(p: &Point2) -> String {
    format!(
        "({}, {})",
        value(WideFloat::from(p.x)),
        value(WideFloat::from(p.y))
    )
}

/// The step page of de Casteljau's algorithm at `t` from its trace
/// ([`Bezier::de_casteljau_trace`]): the control polygon (level 0), then each level of the
/// scaffolding as it is computed over the levels before it, and the point b(t) last.
///
/// The layers a test or a reader can look for: `curve`, `control-polygon`,
/// `control-points`, `scaffolding` and `scaffolding-points` (the levels 1, …, k − 1 before
/// frame k), `level` and `level-points` (frame k's level, but the last), `point` (the last
/// frame's point b(t)).
///
/// # Errors
/// [`Error::InvalidParameter`] named `"t"` if `t` is not finite, or named `"trace"` for a
/// frame without points; those of [`project`](super::project) (a dimension other than 2 or
/// 3, a point beyond the range of `f64`);
/// [`Error::LimitExceeded`] beyond [`STEP_PAGE_MAX_FRAMES`](crate::limits::STEP_PAGE_MAX_FRAMES)
/// frames.
///
/// # Complexity
/// O(f·(n + [`SAMPLES_PER_PIECE`](super::SAMPLES_PER_PIECE)) + n²) time and output for f
/// frames and degree n.
///
/// ```
/// use compgeo::draw::de_casteljau_steps;
/// use compgeo::spline::{Bezier, Point};
///
/// let b = Bezier::new([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]].map(Point::new).to_vec())?;
/// let trace = b.de_casteljau_trace(&0.25)?;
/// let page = de_casteljau_steps(&b, &0.25, &trace)?;
/// assert_eq!(page.frames().len(), 4); // the control polygon, levels 1 and 2, the point
/// assert_eq!(page.frames()[3].kind, "point");
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn de_casteljau_steps<S: Scalar, const D: usize>(
    curve: &Bezier<S, D>,
    t: &S,
    trace: &[Frame<CasteljauLevel<S, D>>],
) -> Result<StepPage> {
    validate_parameter(t, "t")?;
    let levels = levels_of(trace.iter().map(|f| &f.step.points))?;
    let n = curve.degree();
    let at = parameter(t);
    let scheme = Scheme::new(
        format!("de Casteljau's algorithm at t = {at}, degree {n}"),
        curve_points(curve, &[S::zero(), S::one()])?,
        projected(curve.control())?,
        levels,
    );
    let mut page = StepPage::new(&scheme.title).about(
        "De Casteljau's algorithm [PPB, §2.3]: replace the control polygon by the points \
         (1 − t)·bᵢ + t·bᵢ₊₁ on its edges, one level at a time, until one point is left: the \
         point b(t) of the curve. The first points of the levels are the control points of \
         the curve over [0, t], the last ones those over [t, 1].",
    );
    for (k, frame) in trace.iter().enumerate() {
        let picture = scheme.picture(
            k,
            ["scaffolding", "scaffolding-points"],
            ["levels so far", "b(t)"],
            |_| {},
        );
        let level = &scheme.levels[k];
        let last = k + 1 == trace.len();
        let (kind, caption) = if last {
            (
                "point",
                format!(
                    "Level {}: the point b({at}) = {} of the curve.",
                    frame.step.level,
                    coordinates(&level[0])
                ),
            )
        } else if k == 0 {
            (
                "control",
                format!(
                    "Level 0: the {} control points b₀, …, b{}.",
                    level.len(),
                    subscript(level.len() - 1)
                ),
            )
        } else {
            (
                "level",
                format!(
                    "Level {}: {} points, each (1 − t) times a point of level {} plus t times \
                     its successor, t = {at}.",
                    frame.step.level,
                    level.len(),
                    frame.step.level.saturating_sub(1)
                ),
            )
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The step page of de Boor's algorithm at `u` from its trace
/// ([`BSpline::de_boor_trace`]): the control points the point depends on (level 0, ringed
/// in every frame), then each level of the net as it is computed over the levels before it,
/// and the point s(u) last. The curve's points at its distinct knots are marked.
///
/// The layers a test or a reader can look for: those of [`de_casteljau_steps`] with the
/// earlier levels in `de-boor-net` and `de-boor-points`, `knots` (the curve at its knots)
/// and `affected` (the rings around level 0's control points).
///
/// # Errors
/// [`Error::InvalidParameter`] named `"u"` if `u` is not finite, or named `"trace"` for a
/// frame without points or whose span is not a knot interval of `curve`; those of
/// [`project`](super::project); [`Error::LimitExceeded`] beyond
/// [`STEP_PAGE_MAX_FRAMES`](crate::limits::STEP_PAGE_MAX_FRAMES) frames.
///
/// # Complexity
/// O(f·(m·[`SAMPLES_PER_PIECE`](super::SAMPLES_PER_PIECE) + n) + d²) time and output for f
/// frames, m knot intervals, n control points and degree d.
///
/// ```
/// use compgeo::draw::de_boor_steps;
/// use compgeo::spline::{BSpline, KnotVector, Point};
///
/// let knots = KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?; // knots 0, 0, 0, ½, 1, 1, 1
/// let control = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]].map(Point::new).to_vec();
/// let s = BSpline::new(control, knots)?;
/// let trace = s.de_boor_trace(&0.25)?;
/// let page = de_boor_steps(&s, &0.25, &trace)?;
/// assert_eq!(page.frames().len(), 3); // c₀, c₁, c₂; level 1; the point
/// assert!(page.to_html().contains("<g class=\"affected\""));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn de_boor_steps<S: Scalar, const D: usize>(
    curve: &BSpline<S, D>,
    u: &S,
    trace: &[Frame<DeBoorLevel<S, D>>],
) -> Result<StepPage> {
    validate_parameter(u, "u")?;
    let levels = levels_of(trace.iter().map(|f| &f.step.points))?;
    let knots = curve.knots().knots();
    let span = match trace.first() {
        Some(frame) if frame.step.span + 1 < knots.len() => frame.step.span,
        Some(frame) => {
            return Err(Error::InvalidParameter {
                name: "trace",
                reason: format!(
                    "span {} is not a knot interval of a curve with {} knots",
                    frame.step.span,
                    knots.len()
                ),
            })
        }
        None => 0,
    };
    let d = curve.degree();
    let at = parameter(u);
    let (samples, at_knots) = spline_samples(curve, knots)?;
    let scheme = Scheme::new(
        format!(
            "de Boor's algorithm at u = {at}, degree {d}, {} control points",
            curve.control().len()
        ),
        samples,
        projected(curve.control())?,
        levels,
    );
    let mut page = StepPage::new(&scheme.title).about(
        "De Boor's algorithm [PPB, §5.4]: on the knot interval t_μ ≤ u < t_{μ+1} only the \
         d + 1 control points c_{μ−d}, …, c_μ matter (fewer when u is a knot). Each level \
         replaces them by the points (1 − α)·c_{i−1} + α·c_i with α = (u − t_i)/(t_{i+d+1−k} \
         − t_i), one point fewer each time, until one point is left: s(u). The first and the \
         last points of the levels are the control points after inserting u as a knot \
         [PPB, §6.1].",
    );
    let affected = scheme.levels.first().cloned().unwrap_or_default();
    for (k, frame) in trace.iter().enumerate() {
        let picture = scheme.picture(
            k,
            ["de-boor-net", "de-boor-points"],
            ["levels so far", "s(u)"],
            |p| {
                p.points(
                    &Layer::new("knots", Role::Alternative.solid()).legend("points at the knots"),
                    at_knots.iter().copied(),
                );
                p.rings(
                    &Layer::new("affected", Role::Highlight).legend("control points used"),
                    affected.iter().copied(),
                );
            },
        );
        let step = &frame.step;
        let level = &scheme.levels[k];
        let first = step.first();
        let last = k + 1 == trace.len();
        let (kind, caption) = if k == 0 {
            let knot = if step.multiplicity > 0 {
                format!(", a knot of multiplicity {}", step.multiplicity)
            } else {
                String::new()
            };
            let point = if last {
                format!(
                    "; no level to compute: s({at}) = {} is the control point c{}",
                    coordinates(&level[0]),
                    subscript(first)
                )
            } else {
                String::new()
            };
            (
                if last { "point" } else { "control" },
                format!(
                    "u = {at} lies in the knot interval [t{}, t{}] = [{}, {}]{knot}: s(u) \
                     depends on {}{point}.",
                    subscript(span),
                    subscript(span + 1),
                    parameter(&knots[span]),
                    parameter(&knots[span + 1]),
                    named(
                        first,
                        level.len(),
                        "the control point",
                        "the control points"
                    )
                ),
            )
        } else if last {
            (
                "point",
                format!(
                    "Level {}: the point s({at}) = {} of the curve.",
                    step.level,
                    coordinates(&level[0])
                ),
            )
        } else {
            (
                "level",
                format!(
                    "Level {}: {}, each an affine combination of two neighbours of \
                     level {}.",
                    step.level,
                    named(first, level.len(), "the point", "the points"),
                    step.level - 1
                ),
            )
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The step page of the Lane–Riesenfeld algorithm of degree `degree` on `polygon` from its
/// trace ([`lane_riesenfeld_trace`](crate::spline::subdivision::lane_riesenfeld_trace)):
/// the polygon after each doubling and after each pass of midpoints, over the original
/// polygon drawn light.
///
/// The layers a test or a reader can look for: `original` (the given polygon, light) with
/// `control-points` (its numbered vertices), `polygon` and `polygon-points` (the polygon
/// after the frame's step).
///
/// # Errors
/// Those of [`project`](super::project); [`Error::LimitExceeded`] beyond
/// [`STEP_PAGE_MAX_FRAMES`](crate::limits::STEP_PAGE_MAX_FRAMES) frames.
///
/// # Complexity
/// O(f·(n + N)) time and output for f frames, n vertices in the original polygon and N in
/// the largest one.
///
/// ```
/// use compgeo::draw::lane_riesenfeld_steps;
/// use compgeo::spline::subdivision::{lane_riesenfeld_trace, Topology};
/// use compgeo::spline::Point;
///
/// // Chaikin (degree 2) on a closed square: the square, then double, average, average.
/// let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]].map(Point::new);
/// let trace = lane_riesenfeld_trace(&square, 2, 1, Topology::Closed)?;
/// let page = lane_riesenfeld_steps(&square, 2, Topology::Closed, &trace)?;
/// let kinds: Vec<&str> = page.frames().iter().map(|f| f.kind).collect();
/// assert_eq!(kinds, ["input", "double", "average", "average"]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lane_riesenfeld_steps<S: Scalar, const D: usize>(
    polygon: &[Point<S, D>],
    degree: usize,
    topology: Topology,
    trace: &[Frame<LaneRiesenfeldStep<S, D>>],
) -> Result<StepPage> {
    let original = projected(polygon)?;
    let polygons = trace
        .iter()
        .map(|f| match &f.step {
            LaneRiesenfeldStep::Input { polygon }
            | LaneRiesenfeldStep::Doubled { polygon, .. }
            | LaneRiesenfeldStep::Averaged { polygon, .. } => projected(polygon),
        })
        .collect::<Result<Vec<_>>>()?;
    let all: Vec<Point2> = original
        .iter()
        .chain(polygons.iter().flatten())
        .copied()
        .collect();
    let bounds = bounds_of(&all);
    let count = polygons
        .iter()
        .map(Vec::len)
        .chain([original.len()])
        .max()
        .unwrap_or(0);
    let closed = topology == Topology::Closed;
    let name = match degree {
        2 => "Chaikin's algorithm (Lane–Riesenfeld of degree 2)".to_string(),
        d => format!("Lane–Riesenfeld of degree {d}"),
    };
    let title = format!(
        "{name} on {} polygon of {} vertices",
        if closed { "a closed" } else { "an open" },
        original.len()
    );
    let mut page = StepPage::new(&title).about(
        "The Lane–Riesenfeld algorithm [PPB, §8.2–8.4]: each round doubles every vertex, then \
         replaces every vertex by the midpoint of it and its predecessor, d times (an open \
         polygon loses its first vertex at each pass). The result is the control polygon of \
         the same uniform B-spline of degree d on knots twice as dense; the rounds converge \
         to the curve.",
    );
    for (frame, drawn) in trace.iter().zip(&polygons) {
        let mut picture = Picture::new(&title, bounds, count);
        draw_polygon(
            &mut picture,
            &Layer::new("original", Role::Alternative).legend("original polygon"),
            &original,
            closed,
        );
        draw_polygon(
            &mut picture,
            &Layer::new("polygon", Role::Result).legend("polygon after the step"),
            drawn,
            closed,
        );
        picture.points(
            &Layer::new("polygon-points", Role::Result),
            drawn.iter().copied(),
        );
        control_points(&mut picture, &original);
        let m = drawn.len();
        let (kind, caption) = match &frame.step {
            LaneRiesenfeldStep::Input { .. } => (
                "input",
                format!("The polygon the rounds start from: {m} vertices."),
            ),
            LaneRiesenfeldStep::Doubled { round, .. } => (
                "double",
                format!("Round {round}: every vertex doubled, {m} vertices."),
            ),
            LaneRiesenfeldStep::Averaged { round, pass, .. } => (
                "average",
                format!(
                    "Round {round}, pass {pass} of {degree}: every vertex replaced by the \
                     midpoint of it and its predecessor; {m} vertices."
                ),
            ),
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The levels of a trace, projected; a level without points is an error.
fn levels_of<'a, S: Scalar + 'a, const D: usize>(
    levels: impl Iterator<Item = &'a Vec<Point<S, D>>>,
) -> Result<Vec<Vec<Point2>>> {
    levels
        .enumerate()
        .map(|(k, points)| {
            if points.is_empty() {
                Err(Error::InvalidParameter {
                    name: "trace",
                    reason: format!("frame {k} has no points"),
                })
            } else {
                projected(points)
            }
        })
        .collect()
}

/// The `count` points c_first, … by name: "the point c₂", "the points c₂ and c₃", "the
/// points c₂, …, c₅".
fn named(first: usize, count: usize, one: &str, many: &str) -> String {
    let c = |i: usize| format!("c{}", subscript(i));
    match count {
        1 => format!("{one} {}", c(first)),
        2 => format!("{many} {} and {}", c(first), c(first + 1)),
        _ => format!("{many} {}, …, {}", c(first), c(first + count - 1)),
    }
}

/// `n` in subscript digits.
fn subscript(n: usize) -> String {
    n.to_string()
        .chars()
        .map(|c| char::from_u32(0x2080 + c.to_digit(10).unwrap_or(0)).unwrap_or(c))
        .collect()
}
