//! The step pages of the curve traces (`draw::de_casteljau_steps`, `de_boor_steps`,
//! `lane_riesenfeld_steps`), parsed as XML and mapped back to the world through each
//! picture's recorded frame, in exact rationals: one frame per trace frame, each frame's
//! level (and the levels before it) the trace's points, the control polygon and the curve in
//! every frame, the last frame's point the curve's value computed without the trace (the
//! Bernstein form, the B-spline basis), the last Lane–Riesenfeld polygon the subdivision's
//! result, and the counts of every frame the trace's, the last one the counted run's. Also
//! the command line's `--steps` on the curve problems, its named errors, and every page of
//! the report's gallery as XML.

use crate::bspline_basis::{knot_vector, parameter};
use crate::draw::Svg;
use crate::draw_steps::{frames_of, listed, ShownFrame};
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::draw::{de_boor_steps, de_casteljau_steps, lane_riesenfeld_steps, sample_parameters};
use compgeo::geometry::Point2;
use compgeo::spline::subdivision::{
    lane_riesenfeld, lane_riesenfeld_trace, lane_riesenfeld_with, LaneRiesenfeldStep, Topology,
};
use compgeo::spline::{bernstein, BSpline, Bezier, Curve, KnotVector, Point, Scalar};
use compgeo::trace::Frame;
use compgeo::Error;
use proptest::prelude::*;

type P2 = Point<Q, 2>;

/// A plane point rounded to `f64`.
fn plane<S: Scalar>(p: &Point<S, 2>) -> Point2 {
    Point2::new(p[0].to_f64(), p[1].to_f64())
}

fn planes<S: Scalar>(points: &[Point<S, 2>]) -> Vec<Point2> {
    points.iter().map(plane).collect()
}

/// Asserts that `drawn` (picture points) map back to `expected`, in order.
fn assert_points(svg: &Svg, drawn: &[[f64; 2]], expected: &[Point2], what: &str) {
    assert_eq!(drawn.len(), expected.len(), "{what}");
    let frame = svg.frame();
    for (i, (at, p)) in drawn.iter().zip(expected).enumerate() {
        assert!(frame.maps_back(*at, *p), "{what}[{i}]: {at:?} vs {p:?}");
    }
}

/// The dots of layer `class` (each a subpath `Mx yh0`), in order; none if the picture has
/// no such layer.
fn dots(svg: &Svg, class: &str) -> Vec<[f64; 2]> {
    if !svg.has_layer(class) {
        return Vec::new();
    }
    svg.subpaths(class).iter().map(|s| s.points[0]).collect()
}

/// The vertices of subpath `k` of layer `class`.
fn line(svg: &Svg, class: &str, k: usize) -> Vec<[f64; 2]> {
    svg.subpaths(class)[k].points.clone()
}

/// What every curve page shares: one frame per trace frame, in order, with the trace's
/// kinds and counts, the control polygon and the curve's `samples` drawn in each.
fn check_page<S>(
    html: &str,
    trace: &[Frame<S>],
    kind: impl Fn(usize, &S) -> &'static str,
    control: &[Point2],
    curve: &[Point2],
) -> Vec<ShownFrame> {
    let shown = frames_of(html);
    assert_eq!(shown.len(), trace.len(), "one frame per trace frame");
    for (i, (s, f)) in shown.iter().zip(trace).enumerate() {
        assert_eq!(s.step, i);
        assert_eq!(s.hidden, i > 0);
        assert_eq!(s.kind, kind(i, &f.step), "frame {i}");
        assert_eq!(s.counts, listed(&f.counts), "frame {i}'s counts");
        assert!(s
            .caption
            .contains(&format!("step {} of {}", i + 1, trace.len())));
        if control.len() > 1 {
            assert_points(
                &s.svg,
                &line(&s.svg, "control-polygon", 0),
                control,
                "control polygon",
            );
        }
        assert_points(&s.svg, &dots(&s.svg, "control-points"), control, "control");
        if curve.len() > 1 {
            assert_points(&s.svg, &line(&s.svg, "curve", 0), curve, "curve");
        }
    }
    shown
}

/// Checks the levels a de Casteljau or de Boor frame draws: frame k's level highlighted
/// (`level`, `level-points`), the levels 1, …, k − 1 before it in `net` (polylines) and
/// `net-points` (dots), and the last frame's single point in `point`, equal to `value`.
fn check_levels(shown: &[ShownFrame], levels: &[Vec<Point2>], net: [&str; 2], value: Point2) {
    let last = levels.len() - 1;
    for (k, s) in shown.iter().enumerate() {
        let svg = &s.svg;
        let before = &levels[1.min(k)..k];
        let lines: Vec<&Vec<Point2>> = before.iter().filter(|l| l.len() > 1).collect();
        assert_eq!(svg.subpaths(net[0]).len(), lines.len(), "frame {k}");
        for (j, level) in lines.iter().enumerate() {
            assert_points(svg, &line(svg, net[0], j), level, "earlier level");
        }
        let flat: Vec<Point2> = before.iter().flatten().copied().collect();
        assert_points(svg, &dots(svg, net[1]), &flat, "earlier levels' points");
        if k < last {
            assert_points(svg, &dots(svg, "level-points"), &levels[k], "level");
            assert_points(svg, &line(svg, "level", 0), &levels[k], "level line");
            assert!(dots(svg, "point").is_empty());
        } else {
            assert!(dots(svg, "level-points").is_empty());
            assert_eq!(levels[k].len(), 1);
            // The point is the trace's last level and the curve's value.
            assert_points(svg, &dots(svg, "point"), &levels[k], "the trace's point");
            assert_points(svg, &dots(svg, "point"), &[value], "the curve's point");
        }
    }
}

/// b(t) = Σ Bᵢⁿ(t) bᵢ from the Bernstein polynomials.
fn bernstein_sum(control: &[P2], t: &Q) -> P2 {
    let n = control.len() - 1;
    let mut sum = Point::zero();
    for (i, b) in control.iter().enumerate() {
        sum += &(b.clone() * &bernstein(n, i, t).unwrap());
    }
    sum
}

/// s(u) = Σ cᵢ Nᵢ(u) from the basis.
fn basis_sum(s: &BSpline<Q, 2>, u: &Q) -> P2 {
    let b = s.knots().basis(u).unwrap();
    let mut sum = Point::zero();
    for (k, n) in b.values().iter().enumerate() {
        sum += &(s.control()[b.first() + k].clone() * n);
    }
    sum
}

fn check_de_casteljau(control: Vec<P2>, t: Q) {
    let curve = Bezier::new(control.clone()).unwrap();
    let trace = curve.de_casteljau_trace(&t).unwrap();
    let html = de_casteljau_steps(&curve, &t, &trace).unwrap().to_html();
    let n = curve.degree();
    let kind = |k: usize, _: &_| match k {
        k if k == n => "point",
        0 => "control",
        _ => "level",
    };
    let samples: Vec<Point2> = sample_parameters(&[qi(0), qi(1)])
        .iter()
        .map(|u| plane(&bernstein_sum(&control, u)))
        .collect();
    let shown = check_page(&html, &trace, kind, &planes(&control), &samples);
    let levels: Vec<Vec<Point2>> = trace.iter().map(|f| planes(&f.step.points)).collect();
    check_levels(
        &shown,
        &levels,
        ["scaffolding", "scaffolding-points"],
        plane(&bernstein_sum(&control, &t)),
    );
    let mut counts = Counts::default();
    curve.de_casteljau_with(&t, &mut counts).unwrap();
    assert_eq!(shown.last().unwrap().counts, listed(&counts));
}

fn check_de_boor(s: BSpline<Q, 2>, u: Q) {
    let trace = s.de_boor_trace(&u).unwrap();
    let html = de_boor_steps(&s, &u, &trace).unwrap().to_html();
    let last = trace.len() - 1;
    let kind = |k: usize, _: &_| match k {
        k if k == last => "point",
        0 => "control",
        _ => "level",
    };
    let (a, b) = s.knots().bounds();
    let mut breaks: Vec<Q> = s
        .knots()
        .knots()
        .iter()
        .filter(|k| *k >= a && *k <= b)
        .cloned()
        .collect();
    breaks.dedup();
    let samples: Vec<Point2> = sample_parameters(&breaks)
        .iter()
        .map(|v| plane(&basis_sum(&s, v)))
        .collect();
    let shown = check_page(&html, &trace, kind, &planes(s.control()), &samples);
    let levels: Vec<Vec<Point2>> = trace.iter().map(|f| planes(&f.step.points)).collect();
    check_levels(
        &shown,
        &levels,
        ["de-boor-net", "de-boor-points"],
        plane(&basis_sum(&s, &u)),
    );
    // Level 0 is the control points c_{μ−d}, …, c_{μ−r}, ringed in every frame; the knots
    // of the domain are on the curve.
    let first = trace[0].step.first();
    let used = planes(&s.control()[first..first + trace[0].step.points.len()]);
    let at_knots: Vec<Point2> = breaks.iter().map(|v| plane(&basis_sum(&s, v))).collect();
    for f in &shown {
        let rings: Vec<[f64; 2]> = f
            .svg
            .circles("affected")
            .iter()
            .map(|c| [c[0], c[1]])
            .collect();
        assert_points(&f.svg, &rings, &used, "affected control points");
        assert_points(&f.svg, &dots(&f.svg, "knots"), &at_knots, "knots");
    }
    let mut counts = Counts::default();
    s.de_boor_with(&u, &mut counts).unwrap();
    assert_eq!(shown.last().unwrap().counts, listed(&counts));
}

fn polygon_of(step: &LaneRiesenfeldStep<Q, 2>) -> &[P2] {
    match step {
        LaneRiesenfeldStep::Input { polygon }
        | LaneRiesenfeldStep::Doubled { polygon, .. }
        | LaneRiesenfeldStep::Averaged { polygon, .. } => polygon,
    }
}

fn check_lane_riesenfeld(polygon: &[P2], degree: usize, rounds: usize, topology: Topology) {
    let trace = lane_riesenfeld_trace(polygon, degree, rounds, topology).unwrap();
    let html = lane_riesenfeld_steps(polygon, degree, topology, &trace)
        .unwrap()
        .to_html();
    let kind = |_: usize, s: &LaneRiesenfeldStep<Q, 2>| match s {
        LaneRiesenfeldStep::Input { .. } => "input",
        LaneRiesenfeldStep::Doubled { .. } => "double",
        LaneRiesenfeldStep::Averaged { .. } => "average",
    };
    let shown = frames_of(&html);
    assert_eq!(shown.len(), trace.len());
    assert_eq!(shown.len(), 1 + rounds * (degree + 1));
    let closed = topology == Topology::Closed;
    let original = planes(polygon);
    for (i, (s, f)) in shown.iter().zip(&trace).enumerate() {
        let svg = &s.svg;
        assert_eq!(s.kind, kind(i, &f.step));
        assert_eq!(s.counts, listed(&f.counts), "frame {i}'s counts");
        let drawn = svg.subpaths("original");
        assert_eq!(drawn[0].closed, closed);
        assert_points(svg, &drawn[0].points, &original, "original");
        assert_points(svg, &dots(svg, "control-points"), &original, "vertices");
        let expected = planes(polygon_of(&f.step));
        let drawn = svg.subpaths("polygon");
        assert_eq!(drawn.len(), 1);
        assert_eq!(drawn[0].closed, closed);
        assert_points(svg, &drawn[0].points, &expected, "polygon");
        assert_points(svg, &dots(svg, "polygon-points"), &expected, "its vertices");
    }
    // The last frame's polygon is the subdivision's result, and its counts the counted run's.
    let mut counts = Counts::default();
    let result = lane_riesenfeld_with(polygon, degree, rounds, topology, &mut counts).unwrap();
    assert_eq!(
        result,
        lane_riesenfeld(polygon, degree, rounds, topology).unwrap()
    );
    let last = shown.last().unwrap();
    assert_points(
        &last.svg,
        &last.svg.subpaths("polygon")[0].points,
        &planes(&result),
        "result",
    );
    assert_eq!(last.counts, listed(&counts));
}

fn point() -> impl Strategy<Value = P2> {
    ((-40i64..40, 1i64..5), (-40i64..40, 1i64..5))
        .prop_map(|((a, b), (c, d))| Point::new([q(a, b), q(c, d)]))
}

#[test]
fn de_casteljau_page_of_the_course_figure() {
    // The course's quadratic at t = 1/3 [RD, §3.2]: level 1 is (1, 2), (5, 4), the point
    // (7/3, 8/3).
    let control = [(0, 0), (3, 6), (9, 0)].map(|(x, y)| Point::new([qi(x), qi(y)]));
    check_de_casteljau(control.to_vec(), q(1, 3));
    let curve = Bezier::new(control.to_vec()).unwrap();
    let t = q(1, 3);
    let page = de_casteljau_steps(&curve, &t, &curve.de_casteljau_trace(&t).unwrap()).unwrap();
    let shown = frames_of(&page.to_html());
    assert_points(
        &shown[1].svg,
        &dots(&shown[1].svg, "level-points"),
        &[Point2::new(1.0, 2.0), Point2::new(5.0, 4.0)],
        "level 1",
    );
    assert!(
        shown[2].caption.contains("b(0.333333)"),
        "{}",
        shown[2].caption
    );
}

#[test]
fn curve_pages_in_three_dimensions_and_of_single_points() {
    // A space curve draws through the cabinet projection: its last point is the projected
    // curve point.
    let control: Vec<Point<f64, 3>> = [[0.0, 0.0, 0.0], [1.0, 4.0, 2.0], [3.0, -1.0, 5.0]]
        .map(Point::new)
        .to_vec();
    let curve = Bezier::new(control).unwrap();
    let trace = curve.de_casteljau_trace(&0.75).unwrap();
    let shown = frames_of(&de_casteljau_steps(&curve, &0.75, &trace).unwrap().to_html());
    let last = shown.last().unwrap();
    let want = compgeo::draw::project(&curve.eval(&0.75).unwrap()).unwrap();
    assert_points(&last.svg, &dots(&last.svg, "point"), &[want], "b(t)");
    // Degree 0: one frame, the control point is the point.
    let single = Bezier::new(vec![Point::new([2.0, 3.0])]).unwrap();
    let trace = single.de_casteljau_trace(&0.5).unwrap();
    let shown = frames_of(&de_casteljau_steps(&single, &0.5, &trace).unwrap().to_html());
    assert_eq!((shown.len(), shown[0].kind.as_str()), (1, "point"));
    // A knot of multiplicity d: de Boor's scheme has nothing to compute.
    let knots = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]).unwrap();
    let control = (0..5)
        .map(|i| Point::new([i as f64, (i * i) as f64]))
        .collect();
    let s = BSpline::new(control, knots).unwrap();
    let trace = s.de_boor_trace(&1.0).unwrap();
    assert_eq!(trace.len(), 1);
    let shown = frames_of(&de_boor_steps(&s, &1.0, &trace).unwrap().to_html());
    assert_eq!(shown[0].kind, "point");
    assert!(
        shown[0].caption.contains("no level to compute"),
        "{}",
        shown[0].caption
    );
}

#[test]
fn bad_step_page_input_is_a_named_error() {
    let curve = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([1.0, 1.0])]).unwrap();
    let trace = curve.de_casteljau_trace(&0.5).unwrap();
    for t in [f64::NAN, f64::INFINITY] {
        assert!(matches!(
            de_casteljau_steps(&curve, &t, &trace),
            Err(Error::InvalidParameter { name: "t", .. })
        ));
    }
    let mut empty = trace.clone();
    empty[1].step.points.clear();
    assert!(matches!(
        de_casteljau_steps(&curve, &0.5, &empty),
        Err(Error::InvalidParameter { name: "trace", .. })
    ));
    // A trace of another curve whose span is not a knot interval of this one.
    let long = BSpline::new(
        (0..8).map(|i| Point::new([i as f64, 0.0])).collect(),
        KnotVector::clamped_uniform(2, 8, 0.0, 1.0).unwrap(),
    )
    .unwrap();
    let short = BSpline::new(
        (0..3).map(|i| Point::new([i as f64, 1.0])).collect(),
        KnotVector::clamped_uniform(2, 3, 0.0, 1.0).unwrap(),
    )
    .unwrap();
    let trace = long.de_boor_trace(&0.9).unwrap();
    assert!(matches!(
        de_boor_steps(&short, &0.9, &trace),
        Err(Error::InvalidParameter { name: "trace", .. })
    ));
    assert!(matches!(
        de_boor_steps(&long, &f64::NAN, &trace),
        Err(Error::InvalidParameter { name: "u", .. })
    ));
    // Pictures are of 2 or 3 dimensions.
    let line = Bezier::new(vec![Point::new([0.0]), Point::new([1.0])]).unwrap();
    let trace = line.de_casteljau_trace(&0.5).unwrap();
    assert!(matches!(
        de_casteljau_steps(&line, &0.5, &trace),
        Err(Error::InvalidParameter {
            name: "dimension",
            ..
        })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn de_casteljau_pages_draw_each_level_and_end_at_the_curve_point(
        control in prop::collection::vec(point(), 1..7),
        (a, b) in (-6i64..12, 1i64..7),
    ) {
        check_de_casteljau(control, q(a, b));
    }

    #[test]
    fn de_boor_pages_draw_each_level_and_end_at_the_curve_point(
        (s, u) in knot_vector().prop_flat_map(|t| {
            let n = t.control_points();
            (
                Just(t.clone()),
                prop::collection::vec(point(), n),
                parameter(&t),
            )
        }).prop_map(|(t, c, u)| (BSpline::new(c, t).unwrap(), u))
    ) {
        check_de_boor(s, u);
    }

    #[test]
    fn lane_riesenfeld_pages_draw_each_step_and_end_at_the_result(
        polygon in prop::collection::vec(point(), 5..8),
        degree in 1usize..5,
        rounds in 0usize..3,
        closed in any::<bool>(),
    ) {
        let topology = if closed { Topology::Closed } else { Topology::Open };
        check_lane_riesenfeld(&polygon, degree, rounds, topology);
    }
}

#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use crate::common::{assert_rejected, run_json, TempDir};

    #[test]
    fn draw_steps_on_the_curve_problems_writes_one_frame_per_trace_frame() {
        let dir = TempDir::new("draw-curve-steps");
        let control = "[[0, 0], [1, 3], [3, 3], [4, 0], [6, 2]]";
        let c: Vec<Point<f64, 2>> = [[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0], [6.0, 2.0]]
            .map(Point::new)
            .to_vec();
        let bezier = Bezier::new(c.clone()).unwrap();
        let spline = BSpline::new(
            c.clone(),
            KnotVector::clamped_uniform(3, 5, 0.0, 1.0).unwrap(),
        )
        .unwrap();
        let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]].map(Point::new);
        let cases: [(Vec<&str>, &str, &str, usize); 4] = [
            (
                vec!["bezier", "--control", control, "--t", "1/3"],
                "bezier",
                "de-casteljau",
                bezier.de_casteljau_trace(&(1.0 / 3.0)).unwrap().len(),
            ),
            (
                vec![
                    "bspline",
                    "--control",
                    control,
                    "--degree",
                    "3",
                    "--u",
                    "0.4",
                    "--exact",
                ],
                "bspline",
                "de-boor",
                spline.de_boor_trace(&0.4).unwrap().len(),
            ),
            (
                vec![
                    "subdivide",
                    "--points",
                    "[[0,0],[4,0],[4,4],[0,4]]",
                    "--scheme",
                    "lane-riesenfeld",
                    "--degree",
                    "3",
                    "--rounds",
                    "2",
                    "--closed",
                ],
                "subdivide",
                "lane-riesenfeld",
                lane_riesenfeld_trace(&square, 3, 2, Topology::Closed)
                    .unwrap()
                    .len(),
            ),
            (
                vec![
                    "subdivide",
                    "--points",
                    "[[0,0],[4,0],[4,4],[0,4]]",
                    "--scheme",
                    "chaikin",
                    "--rounds",
                    "1",
                ],
                "subdivide",
                "chaikin",
                lane_riesenfeld_trace(&square, 2, 1, Topology::Open)
                    .unwrap()
                    .len(),
            ),
        ];
        for (args, problem, algorithm, frames) in cases {
            let out = dir.path(&format!("{algorithm}.html"));
            let out = out.to_str().unwrap();
            let mut all = vec!["draw"];
            all.extend(&args);
            all.extend(["--steps", "--out", out]);
            let summary = run_json(&all, None);
            assert_eq!(summary["problem"], problem);
            assert_eq!(summary["algorithm"], algorithm);
            assert_eq!(summary["frames"], frames, "{args:?}");
            let html = std::fs::read_to_string(out).unwrap();
            assert_eq!(summary["bytes"], html.len());
            assert_eq!(summary["out"], out);
            assert_eq!(frames_of(&html).len(), frames);
        }
        // The command's page is the library's.
        let page = de_casteljau_steps(
            &bezier,
            &(1.0 / 3.0),
            &bezier.de_casteljau_trace(&(1.0 / 3.0)).unwrap(),
        )
        .unwrap();
        let written = std::fs::read_to_string(dir.path("de-casteljau.html")).unwrap();
        assert_eq!(written, page.to_html());
    }

    #[test]
    fn draw_steps_on_a_curve_without_its_parameter_or_trace_is_a_named_error() {
        let control = "[[0, 0], [1, 3], [3, 3], [4, 0]]";
        let err = assert_rejected(
            &[
                "draw",
                "bezier",
                "--control",
                control,
                "--steps",
                "--out",
                "x.html",
            ],
            None,
        );
        assert!(err.contains("--steps") && err.contains("--t"), "{err}");
        let err = assert_rejected(
            &[
                "draw",
                "bspline",
                "--control",
                control,
                "--degree",
                "2",
                "--steps",
                "--out",
                "x.html",
            ],
            None,
        );
        assert!(err.contains("--steps") && err.contains("--u"), "{err}");
        let err = assert_rejected(
            &[
                "draw",
                "subdivide",
                "--points",
                control,
                "--scheme",
                "four-point",
                "--steps",
                "--out",
                "x.html",
            ],
            None,
        );
        assert!(
            err.starts_with("error: --steps: no step trace for four-point"),
            "{err}"
        );
        // Bad parameters are named as the pictures name them.
        let err = assert_rejected(
            &[
                "draw",
                "bspline",
                "--control",
                control,
                "--degree",
                "2",
                "--u",
                "7",
                "--steps",
                "--out",
                "x.html",
            ],
            None,
        );
        assert!(err.starts_with("error: invalid u"), "{err}");
        let err = assert_rejected(
            &[
                "draw",
                "bezier",
                "--control",
                control,
                "--t",
                "NaN",
                "--steps",
                "--out",
                "x.html",
            ],
            None,
        );
        assert!(err.starts_with("error: invalid t"), "{err}");
    }

    /// Every file of the report's gallery parses: the pictures as SVG, the step pages as
    /// XHTML with a frame per step, the curve pages among them.
    #[test]
    fn every_gallery_page_is_well_formed() {
        let dir = TempDir::new("gallery-xml");
        let out = dir.0.to_str().unwrap();
        let (code, _, err) = crate::common::run(
            &["report", "--quick", "--only", "hull/graham/", "--out", out],
            None,
        );
        assert_eq!(code, 0, "{err}");
        let mut pages = Vec::new();
        for entry in std::fs::read_dir(dir.path("gallery")).unwrap() {
            let path = entry.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap();
            let name = path.file_name().unwrap().to_str().unwrap().to_string();
            if name.ends_with("-steps.html") {
                assert!(!frames_of(&text).is_empty(), "{name}");
                pages.push(name);
            } else {
                assert!(name.ends_with(".svg"), "{name}");
                Svg::parse(text);
            }
        }
        for page in [
            "bezier-de-casteljau-steps.html",
            "bspline-de-boor-steps.html",
            "subdivision-lane-riesenfeld-steps.html",
        ] {
            assert!(pages.iter().any(|p| p == page), "{page}: {pages:?}");
        }
    }
}
