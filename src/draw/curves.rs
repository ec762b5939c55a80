//! Pictures of curves: Bézier curves with de Casteljau's scaffolding, B-splines with their
//! knots and de Boor's net, NURBS, cubic Beta-splines, and the rounds of a subdivision
//! scheme.
//!
//! Every picture is generic over the curve's [`Scalar`]: the curve is evaluated with its own
//! arithmetic at exact parameters ([`sample_parameters`]) and only the results are rounded
//! to `f64` and [projected](super::project) for drawing, so exact curves draw as well.

use super::{bounds_of, project, Layer, Picture, Role};
use crate::error::Result;
use crate::geometry::Point2;
use crate::spline::subdivision::Topology;
use crate::spline::{BSpline, BetaSpline, Bezier, Curve, DeBoorLevel, Nurbs, Point, Scalar};
use crate::trace::Frame;

/// How many straight pieces a curve is drawn with per piece of its parameter: per knot
/// interval of a B-spline or NURBS, per segment of a Beta-spline, over [0, 1] for a Bézier
/// curve.
pub const SAMPLES_PER_PIECE: usize = 32;

/// The parameters a curve is drawn at: for each pair of consecutive distinct breakpoints
/// `a < b` of `breaks` (ascending), the [`SAMPLES_PER_PIECE`] parameters
/// `a + (b − a) · i / SAMPLES_PER_PIECE`, `i = 0, …, SAMPLES_PER_PIECE − 1`, then the last
/// breakpoint. Repeated breakpoints (a multiple knot) add nothing; no breakpoints give no
/// parameters.
///
/// # Complexity
/// Θ(m · [`SAMPLES_PER_PIECE`]) time and space for m breakpoints.
///
/// ```
/// use compgeo::draw::{sample_parameters, SAMPLES_PER_PIECE};
///
/// let t = sample_parameters(&[0.0, 1.0, 1.0, 3.0]);
/// assert_eq!(t.len(), 2 * SAMPLES_PER_PIECE + 1);
/// assert_eq!((t[0], t[SAMPLES_PER_PIECE], t[2 * SAMPLES_PER_PIECE]), (0.0, 1.0, 3.0));
/// ```
pub fn sample_parameters<S: Scalar>(breaks: &[S]) -> Vec<S> {
    let n = SAMPLES_PER_PIECE as i64;
    let mut out = Vec::new();
    for pair in breaks.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        if a >= b {
            continue;
        }
        let step = b.clone() - a;
        for i in 0..n {
            out.push(a.clone() + &(step.clone() * &S::from_ratio(i, n)));
        }
    }
    if let Some(last) = breaks.last() {
        out.push(last.clone());
    }
    out
}

/// The Bézier curve over [0, 1] as a polyline (blue), its control polygon (orange, dashed)
/// and control points (numbered from 0 when the picture shows labels), and with `t`
/// de Casteljau's scaffolding at t: the polygon of every level 1, …, n − 1 from
/// [`Bezier::de_casteljau_trace`] (grey), their points, and the point b(t) (vermillion).
///
/// The curve's vertices are its points at [`sample_parameters`]`(&[0, 1])`, computed with
/// [`Curve::eval`] in the curve's own arithmetic. `t` may lie outside [0, 1]; the frame
/// then holds the scaffolding too.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"t"` if `t` is not
/// finite; those of [`project`](super::project) (a dimension other than 2 or 3, or a point
/// beyond the range of `f64`); those of [`Bezier::de_casteljau_trace`].
///
/// # Complexity
/// Θ(n · [`SAMPLES_PER_PIECE`] + n²) evaluations and output for degree n.
///
/// ```
/// use compgeo::draw;
/// use compgeo::spline::{Bezier, Point};
///
/// let b = Bezier::new([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]].map(Point::new).to_vec())?;
/// let picture = draw::bezier(&b, Some(&0.5))?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("curve", 1)) && layers.contains(&("control-polygon", 1)));
/// assert!(layers.contains(&("scaffolding", 2))); // levels 1 and 2 of a cubic
/// assert!(layers.contains(&("point", 1)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bezier<S: Scalar, const D: usize>(curve: &Bezier<S, D>, t: Option<&S>) -> Result<Picture> {
    let samples = curve_points(curve, &[S::zero(), S::one()])?;
    let control = projected(curve.control())?;
    let levels = match t {
        Some(t) => curve
            .de_casteljau_trace(t)?
            .iter()
            .map(|frame| projected(&frame.step.points))
            .collect::<Result<Vec<_>>>()?,
        None => Vec::new(),
    };
    let n = curve.degree();
    let mut title = format!("Bézier curve of degree {n}");
    if let Some(t) = t {
        title.push_str(&format!(", de Casteljau at t = {}", parameter(t)));
    }
    let mut picture = frame_of(
        &title,
        [&samples, &control].into_iter().chain(&levels),
        control.len(),
    );
    control_polygon(&mut picture, &control, false);
    let inner = levels.get(1..n).unwrap_or(&[]);
    net_layers(
        &mut picture,
        ["scaffolding", "scaffolding-points"],
        Role::Triangulation,
        "de Casteljau's levels",
        inner,
    );
    curve_layer(&mut picture, &samples);
    control_points(&mut picture, &control);
    if let Some(point) = levels.last().filter(|_| t.is_some()) {
        picture.points(
            &Layer::new("point", Role::Highlight).legend("b(t)"),
            point.iter().copied(),
        );
    }
    Ok(picture)
}

/// The B-spline curve over its domain as a polyline (blue), its control polygon (orange,
/// dashed) and control points, the curve's points at its distinct knots in the domain
/// (vermillion), and with `u` de Boor's net at u ([`BSpline::de_boor_trace`]): the polygon
/// of every level from 0 (the d − r + 1 control points that matter) to the last but one
/// (grey), and the point s(u).
///
/// The curve's vertices are its points at [`sample_parameters`] of the distinct knots in
/// the domain [t_d, t_n].
///
/// # Errors
/// Those of [`BSpline::de_boor_trace`] (u outside the domain) and of
/// [`project`](super::project).
///
/// # Complexity
/// Θ(m · [`SAMPLES_PER_PIECE`]) evaluations (each O(d²)) and output for m knot intervals.
///
/// ```
/// use compgeo::draw;
/// use compgeo::spline::{BSpline, KnotVector, Point};
///
/// let knots = KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?; // knots 0, 0, 0, ½, 1, 1, 1
/// let s = BSpline::new([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]].map(Point::new).to_vec(), knots)?;
/// let picture = draw::bspline(&s, Some(&0.25))?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("knots", 3)) && layers.contains(&("de-boor-net", 2)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn bspline<S: Scalar, const D: usize>(curve: &BSpline<S, D>, u: Option<&S>) -> Result<Picture> {
    let net = u.map(|u| curve.de_boor_trace(u)).transpose()?;
    let title = format!(
        "B-spline of degree {} with {} control points",
        curve.degree(),
        curve.control().len()
    );
    let knots = curve.knots().knots();
    spline_picture(&title, curve, curve.control(), knots, net.as_deref(), u)
}

/// The NURBS curve as [`bspline`] draws a B-spline (without a de Boor net): the curve, its
/// control polygon and points, and its points at the distinct knots of the domain.
///
/// # Errors
/// Those of [`project`](super::project).
///
/// # Complexity
/// As [`bspline`].
///
/// ```
/// use compgeo::draw;
/// use compgeo::spline::{KnotVector, Nurbs, Point};
///
/// // A quarter circle.
/// let knots = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
/// let control = [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].map(Point::new).to_vec();
/// let arc = Nurbs::new(control, vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0], knots)?;
/// assert!(draw::nurbs(&arc)?.layers().any(|layer| layer == ("curve", 1)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn nurbs<S: Scalar, const D: usize>(curve: &Nurbs<S, D>) -> Result<Picture> {
    let title = format!(
        "NURBS curve of degree {} with {} control points",
        curve.degree(),
        curve.control().len()
    );
    let knots = curve.knots().knots();
    spline_picture(&title, curve, curve.control(), knots, None, None)
}

/// The cubic Beta-spline over [0, m] (m segments) as a polyline (blue), with its control
/// polygon (orange, dashed) and control points; the curve's points at the integers, where
/// its segments join, are marked (vermillion).
///
/// The curve's vertices are its points at [`sample_parameters`]`(&[0, 1, …, m])`.
///
/// # Errors
/// Those of [`project`](super::project).
///
/// # Complexity
/// Θ(m · [`SAMPLES_PER_PIECE`]) evaluations and output.
///
/// ```
/// use compgeo::draw;
/// use compgeo::spline::{BetaParameters, BetaSpline, Point};
///
/// let control = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0], [5.0, 1.0]].map(Point::new).to_vec();
/// let curve = BetaSpline::new(BetaParameters::new(2.0, 1.0)?, control)?;
/// let picture = draw::beta(&curve)?;
/// assert!(picture.layers().any(|layer| layer == ("joints", 3))); // two segments
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn beta<S: Scalar, const D: usize>(curve: &BetaSpline<S, D>) -> Result<Picture> {
    let m = curve.segments();
    let breaks: Vec<S> = (0..=m as i64).map(S::from_i64).collect();
    let samples = curve_points(curve, &breaks)?;
    let joints = breaks
        .iter()
        .map(|u| project(&curve.eval(u)?))
        .collect::<Result<Vec<_>>>()?;
    let control = projected(curve.control())?;
    let p = curve.parameters();
    let title = format!(
        "cubic Beta-spline, β₁ = {}, β₂ = {}, {m} segments",
        parameter(p.beta1()),
        parameter(p.beta2())
    );
    let mut picture = frame_of(&title, [&samples, &control], control.len());
    control_polygon(&mut picture, &control, false);
    curve_layer(&mut picture, &samples);
    picture.points(
        &Layer::new("joints", Role::Highlight).legend("joints (integer u)"),
        joints,
    );
    control_points(&mut picture, &control);
    Ok(picture)
}

/// The rounds of a subdivision scheme: `rounds[0]` is the input polygon (orange, dashed,
/// its vertices numbered), `rounds[k]` the polygon after k rounds; every round but the last
/// is drawn light (sky blue) in a layer `round-k`, the last one blue in the layer `result`
/// with its vertices as dots. A closed polygon (`Topology::Closed`) is drawn closed.
///
/// The caller computes the rounds ([`lane_riesenfeld`](crate::spline::subdivision::lane_riesenfeld),
/// [`four_point`](crate::spline::subdivision::four_point), one round at a time); `name` is
/// the scheme's name for the title.
///
/// # Errors
/// [`Error::Empty`](crate::Error::Empty) for no rounds; those of
/// [`project`](super::project).
///
/// # Complexity
/// Θ(N) time and output for N vertices in all the rounds.
///
/// ```
/// use compgeo::draw;
/// use compgeo::spline::subdivision::{lane_riesenfeld, Topology};
/// use compgeo::spline::Point;
///
/// let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]].map(Point::new).to_vec();
/// let rounds = (0..=2)
///     .map(|k| lane_riesenfeld(&square, 2, k, Topology::Closed))
///     .collect::<Result<Vec<_>, _>>()?;
/// let picture = draw::subdivision("Chaikin", &rounds, Topology::Closed)?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("round-1", 1)) && layers.contains(&("result", 1)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn subdivision<S: Scalar, const D: usize>(
    name: &str,
    rounds: &[Vec<Point<S, D>>],
    topology: Topology,
) -> Result<Picture> {
    if rounds.is_empty() {
        return Err(crate::Error::Empty {
            what: "the list of subdivision rounds",
        });
    }
    let polygons = rounds
        .iter()
        .map(|r| projected(r))
        .collect::<Result<Vec<_>>>()?;
    let k = rounds.len() - 1;
    let closed = topology == Topology::Closed;
    let title = format!(
        "{name}: {k} round{} on {} {}",
        if k == 1 { "" } else { "s" },
        if closed { "closed" } else { "open" },
        match rounds[0].len() {
            1 => "point".to_string(),
            n => format!("polygon of {n} vertices"),
        }
    );
    let last = polygons.last().expect("rounds is not empty");
    let mut picture = frame_of(&title, &polygons, last.len());
    control_polygon(&mut picture, &polygons[0], closed);
    for (r, polygon) in polygons.iter().enumerate().take(k).skip(1) {
        let layer = Layer::new(&format!("round-{r}"), Role::Alternative.solid());
        let layer = if r == 1 {
            layer.legend("earlier rounds")
        } else {
            layer
        };
        draw_polygon(&mut picture, &layer, polygon, closed);
    }
    if k > 0 {
        draw_polygon(
            &mut picture,
            &Layer::new("result", Role::Result).legend(format!("after round {k}")),
            last,
            closed,
        );
        picture.points(
            &Layer::new("result-points", Role::Result),
            last.iter().copied(),
        );
    }
    control_points(&mut picture, &polygons[0]);
    Ok(picture)
}

/// The picture of a B-spline or NURBS curve: curve, control polygon, knots, and the net.
fn spline_picture<S: Scalar, const D: usize>(
    title: &str,
    curve: &impl Curve<S, D>,
    control: &[Point<S, D>],
    knots: &[S],
    net: Option<&[Frame<DeBoorLevel<S, D>>]>,
    u: Option<&S>,
) -> Result<Picture> {
    let (samples, knots) = spline_samples(curve, knots)?;
    let control = projected(control)?;
    let levels = match net {
        Some(net) => net
            .iter()
            .map(|frame| projected(&frame.step.points))
            .collect::<Result<Vec<_>>>()?,
        None => Vec::new(),
    };
    let mut title = title.to_string();
    if let Some(u) = u {
        title.push_str(&format!(", de Boor at u = {}", parameter(u)));
    }
    let mut picture = frame_of(
        &title,
        [&samples, &control].into_iter().chain(&levels),
        control.len(),
    );
    control_polygon(&mut picture, &control, false);
    let inner = &levels[..levels.len().saturating_sub(1)];
    net_layers(
        &mut picture,
        ["de-boor-net", "de-boor-points"],
        Role::Triangulation,
        "de Boor's net",
        inner,
    );
    curve_layer(&mut picture, &samples);
    picture.points(
        &Layer::new("knots", Role::Highlight).legend("points at the knots"),
        knots,
    );
    control_points(&mut picture, &control);
    if let Some(point) = levels.last() {
        picture.points(
            &Layer::new("point", Role::Highlight).legend("s(u)"),
            point.iter().copied(),
        );
    }
    Ok(picture)
}

/// A spline curve's points at [`sample_parameters`] of the distinct knots of its domain
/// [t_d, t_n], and its points at those knots, projected.
pub(super) fn spline_samples<S: Scalar, const D: usize>(
    curve: &impl Curve<S, D>,
    knots: &[S],
) -> Result<(Vec<Point2>, Vec<Point2>)> {
    // The distinct knots of the domain, ascending (the knot vector is sorted).
    let mut breaks: Vec<S> = match curve.domain().bounds() {
        Some((start, end)) => knots
            .iter()
            .filter(|&k| start <= k && k <= end)
            .cloned()
            .collect(),
        None => Vec::new(),
    };
    breaks.dedup();
    let samples = curve_points(curve, &breaks)?;
    let at_knots = breaks
        .iter()
        .map(|u| project(&curve.eval(u)?))
        .collect::<Result<Vec<_>>>()?;
    Ok((samples, at_knots))
}

/// The levels of a de Casteljau or de Boor scheme: each level's polyline in the layer
/// `names[0]` (with the legend entry) and all their points as dots in `names[1]`.
pub(super) fn net_layers(
    picture: &mut Picture,
    names: [&str; 2],
    role: Role,
    legend: &str,
    levels: &[Vec<Point2>],
) {
    picture.polylines(
        &Layer::new(names[0], role).legend(legend),
        levels.iter().map(|level| level.iter().copied()),
    );
    picture.points(
        &Layer::new(names[1], role),
        levels.iter().flatten().copied(),
    );
}

/// A parameter for a title, to six significant digits.
pub(super) fn parameter<S: Scalar>(t: &S) -> String {
    super::value(crate::geometry::WideFloat::from(t.to_f64()))
}

/// The curve's points at [`sample_parameters`] of `breaks`, projected.
pub(super) fn curve_points<S: Scalar, const D: usize>(
    curve: &impl Curve<S, D>,
    breaks: &[S],
) -> Result<Vec<Point2>> {
    sample_parameters(breaks)
        .iter()
        .map(|t| project(&curve.eval(t)?))
        .collect()
}

/// The points, projected.
pub(super) fn projected<S: Scalar, const D: usize>(points: &[Point<S, D>]) -> Result<Vec<Point2>> {
    points.iter().map(project).collect()
}

/// A picture whose frame holds every point of `sets`, sized for `count` points.
pub(super) fn frame_of<'a>(
    title: &str,
    sets: impl IntoIterator<Item = &'a Vec<Point2>>,
    count: usize,
) -> Picture {
    let all: Vec<Point2> = sets.into_iter().flatten().copied().collect();
    Picture::new(title, bounds_of(&all), count)
}

/// The control polygon layer (open or closed).
pub(super) fn control_polygon(picture: &mut Picture, control: &[Point2], closed: bool) {
    let layer = Layer::new("control-polygon", Role::Construction).legend("control polygon");
    draw_polygon(picture, &layer, control, closed);
}

/// A polygon, open or closed, as one subpath.
pub(super) fn draw_polygon(picture: &mut Picture, layer: &Layer, polygon: &[Point2], closed: bool) {
    if closed {
        picture.polygons(layer, [polygon.iter().copied()]);
    } else {
        picture.polylines(layer, [polygon.iter().copied()]);
    }
}

/// The curve's polyline.
pub(super) fn curve_layer(picture: &mut Picture, samples: &[Point2]) {
    picture.polylines(
        &Layer::new("curve", Role::Result).legend("curve"),
        [samples.iter().copied()],
    );
}

/// The control points as dots, numbered from 0 when the picture shows labels.
pub(super) fn control_points(picture: &mut Picture, control: &[Point2]) {
    picture.points(
        &Layer::new("control-points", Role::Input),
        control.iter().copied(),
    );
    picture.labels(
        &Layer::new("labels", Role::Label).legend("control point index"),
        control.iter().enumerate().map(|(i, &p)| (p, i.to_string())),
    );
}
