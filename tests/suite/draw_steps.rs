//! Step pages (`compgeo::draw::StepPage` and the hull and Lawson pages): parsed as XML, one
//! frame per trace frame in order, each frame's picture showing that frame's state and its
//! table the frame's counts, the last frame the algorithm's result; the command line's
//! `--steps`; and in headless Chromium, the keys and the slider move between frames.

use crate::draw::{assert_maps_back, Svg};
use compgeo::count::{Counts, Operation};
use compgeo::delaunay::{fortune, fortune_trace, lawson, lawson_trace, FortuneStep, LawsonStep};
use compgeo::draw::{
    fortune_steps, graham_steps, jarvis_steps, lawson_steps, monotone_chain_steps, quickhull_steps,
    Layer, Picture, Role, StepFrame, StepPage,
};
use compgeo::gen::{points as generate, PointKind};
use compgeo::geometry::{BoundingBox, Point2, PointSet};
use compgeo::hull::{
    convex_hull, graham_trace, jarvis_trace, monotone_chain_trace, quickhull_trace, Algorithm,
    HullOptions,
};
use compgeo::limits::STEP_PAGE_MAX_FRAMES;
use compgeo::trace::Frame;
use compgeo::Error;

/// One frame as the page shows it.
pub struct ShownFrame {
    pub step: usize,
    pub kind: String,
    pub hidden: bool,
    pub caption: String,
    pub svg: Svg,
    pub counts: Vec<(String, u64)>,
}

/// Parses a page as XML and returns its frames, checking the controls on the way.
pub fn frames_of(html: &str) -> Vec<ShownFrame> {
    // `<!DOCTYPE html>` is a DTD to an XML parser.
    let options = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..roxmltree::ParsingOptions::default()
    };
    let doc =
        roxmltree::Document::parse_with_options(html, options).unwrap_or_else(|e| panic!("{e}"));
    let by_id = |id: &str| {
        doc.descendants()
            .find(|n| n.attribute("id") == Some(id))
            .unwrap_or_else(|| panic!("no #{id}"))
    };
    let slider = by_id("slider");
    assert_eq!(slider.attribute("type"), Some("range"));
    assert!(by_id("previous").has_tag_name("button") && by_id("next").has_tag_name("button"));
    // Self-contained: no external script, style or image.
    for n in doc.descendants().filter(|n| n.is_element()) {
        for a in ["src", "href"] {
            assert!(
                n.attribute(a).is_none(),
                "<{}> has {a}",
                n.tag_name().name()
            );
        }
    }
    let sections: Vec<roxmltree::Node> = doc
        .descendants()
        .filter(|n| n.has_tag_name("section") && n.attribute("class") == Some("frame"))
        .collect();
    assert_eq!(
        slider.attribute("max").unwrap().parse::<usize>().unwrap(),
        sections.len().saturating_sub(1)
    );
    sections
        .into_iter()
        .map(|s| {
            let svg_node = s.children().find(|n| n.has_tag_name("svg")).unwrap();
            let svg = Svg::parse(html[svg_node.range()].to_string());
            let caption = s
                .children()
                .find(|n| n.attribute("class") == Some("caption"))
                .unwrap()
                .descendants()
                .filter_map(|n| n.text())
                .collect::<String>();
            let table = s.children().find(|n| n.has_tag_name("table")).unwrap();
            let counts = table
                .descendants()
                .filter(|n| n.has_tag_name("tr") && n.attribute("data-operation").is_some())
                .map(|tr| {
                    let value = tr
                        .children()
                        .filter(|n| n.has_tag_name("td"))
                        .nth(1)
                        .unwrap();
                    (
                        tr.attribute("data-operation").unwrap().to_string(),
                        value.text().unwrap().parse().unwrap(),
                    )
                })
                .collect();
            ShownFrame {
                step: s.attribute("data-step").unwrap().parse().unwrap(),
                kind: s.attribute("data-kind").unwrap().to_string(),
                hidden: s.attribute("hidden").is_some(),
                caption,
                svg,
                counts,
            }
        })
        .collect()
}

/// The non-zero counts, as the page lists them.
pub fn listed(counts: &Counts) -> Vec<(String, u64)> {
    Operation::ALL
        .iter()
        .filter(|&&op| counts.get(op) > 0)
        .map(|&op| (op.name().to_string(), counts.get(op)))
        .collect()
}

/// Checks what every page shares: one frame per trace frame in order, the first shown,
/// kinds and counts as in the trace, and every input point drawn in every frame.
fn check_page<S>(
    html: &str,
    trace: &[Frame<S>],
    kind: impl Fn(&S) -> &'static str,
    pts: &[Point2],
) -> Vec<ShownFrame> {
    let shown = frames_of(html);
    assert_eq!(shown.len(), trace.len(), "one frame per trace frame");
    for (i, (s, f)) in shown.iter().zip(trace).enumerate() {
        assert_eq!(s.step, i);
        assert_eq!(s.hidden, i > 0, "only the first frame is shown at first");
        assert_eq!(s.kind, kind(&f.step), "frame {i}");
        assert_eq!(s.counts, listed(&f.counts), "frame {i}'s counts");
        assert!(s
            .caption
            .contains(&format!("step {} of {}", i + 1, trace.len())));
        let dots = s.svg.subpaths("points");
        assert_eq!(dots.len(), pts.len());
        for (dot, &p) in dots.iter().zip(pts) {
            assert!(s.svg.frame().maps_back(dot.points[0], p), "frame {i}");
        }
    }
    shown
}

/// The last frame's hull polygon maps back to `hull`.
fn assert_last_is_hull(shown: &[ShownFrame], pts: &[Point2], hull: &[usize]) {
    let last = shown.last().unwrap();
    assert_eq!(last.kind, "done");
    let drawn = last.svg.subpaths("hull");
    assert_eq!(drawn.len(), 1);
    assert!(drawn[0].closed);
    let expected: Vec<Point2> = hull.iter().map(|&i| pts[i]).collect();
    assert_maps_back(&last.svg.frame(), &drawn[0], &expected);
}

fn inputs() -> Vec<Vec<Point2>> {
    vec![
        generate(PointKind::UniformDisk, 15, 1).unwrap(),
        generate(PointKind::Grid, 16, 2).unwrap(),
        generate(PointKind::Clustered, 20, 3).unwrap(),
        generate(PointKind::Huge, 12, 4).unwrap(),
        [(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)]
            .map(Point2::from)
            .to_vec(),
    ]
}

#[test]
fn jarvis_pages_show_every_candidate_against_the_best() {
    use compgeo::hull::JarvisStep::*;
    for pts in inputs() {
        let set = PointSet::new(&pts).unwrap();
        let trace = jarvis_trace(&pts, HullOptions::default()).unwrap();
        let html = jarvis_steps(&set, &trace).unwrap().to_html();
        let kind = |s: &compgeo::hull::JarvisStep| match s {
            Start { .. } => "start",
            Candidate { .. } => "candidate",
            Wrap { .. } => "wrap",
            Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &pts);
        for (s, f) in shown.iter().zip(&trace) {
            if let Candidate {
                current,
                best,
                point,
                hull,
            } = &f.step
            {
                let frame = s.svg.frame();
                assert_maps_back(
                    &frame,
                    &s.svg.subpaths("best")[0],
                    &[pts[*current], pts[*best]],
                );
                assert_maps_back(
                    &frame,
                    &s.svg.subpaths("test")[0],
                    &[pts[*current], pts[*point]],
                );
                let so_far: Vec<Point2> = hull.iter().map(|&i| pts[i]).collect();
                if so_far.len() >= 2 {
                    assert_maps_back(&frame, &s.svg.subpaths("hull-so-far")[0], &so_far);
                }
            }
        }
        let hull = convex_hull(&pts, Algorithm::Jarvis, HullOptions::default()).unwrap();
        assert_last_is_hull(&shown, &pts, &hull);
    }
}

#[test]
fn graham_pages_show_the_stack_after_every_push_and_pop() {
    use compgeo::hull::GrahamStep::*;
    for pts in inputs() {
        let set = PointSet::new(&pts).unwrap();
        let trace = graham_trace(&pts, HullOptions::default()).unwrap();
        let html = graham_steps(&set, &trace).unwrap().to_html();
        let kind = |s: &compgeo::hull::GrahamStep| match s {
            Sorted { .. } => "sorted",
            Push { .. } => "push",
            Pop { .. } => "pop",
            Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &pts);
        for (s, f) in shown.iter().zip(&trace) {
            if let Push { stack, .. } | Pop { stack, .. } = &f.step {
                let expected: Vec<Point2> = stack.iter().map(|&i| pts[i]).collect();
                let drawn = s.svg.subpaths("stack");
                if expected.len() >= 2 {
                    assert_maps_back(&s.svg.frame(), &drawn[0], &expected);
                } else {
                    assert!(drawn.is_empty());
                }
            }
        }
        let hull = convex_hull(&pts, Algorithm::Graham, HullOptions::default()).unwrap();
        assert_last_is_hull(&shown, &pts, &hull);
    }
}

#[test]
fn monotone_chain_and_quickhull_pages_end_with_their_hulls() {
    use compgeo::hull::{ChainStep, QuickhullStep};
    for pts in inputs() {
        let set = PointSet::new(&pts).unwrap();
        let trace = monotone_chain_trace(&pts, HullOptions::default()).unwrap();
        let html = monotone_chain_steps(&set, &trace).unwrap().to_html();
        let kind = |s: &ChainStep| match s {
            ChainStep::Sorted { .. } => "sorted",
            ChainStep::Split { .. } => "split",
            ChainStep::Push { .. } => "push",
            ChainStep::Pop { .. } => "pop",
            ChainStep::Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &pts);
        let hull = convex_hull(&pts, Algorithm::MonotoneChain, HullOptions::default()).unwrap();
        assert_last_is_hull(&shown, &pts, &hull);

        let trace = quickhull_trace(&pts, HullOptions::default()).unwrap();
        let html = quickhull_steps(&set, &trace).unwrap().to_html();
        let kind = |s: &QuickhullStep| match s {
            QuickhullStep::Ends { .. } => "ends",
            QuickhullStep::Split { .. } => "split",
            QuickhullStep::Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &pts);
        for (s, f) in shown.iter().zip(&trace) {
            if let QuickhullStep::Split { farthest, .. } = &f.step {
                let rings = s.svg.circles("current");
                assert_eq!(rings.len(), 1);
                let at = s.svg.frame().picture_of(pts[*farthest]);
                assert!((rings[0][0] - at[0]).abs() < 0.06 && (rings[0][1] - at[1]).abs() < 0.06);
            }
        }
        let hull = convex_hull(&pts, Algorithm::Quickhull, HullOptions::default()).unwrap();
        assert_last_is_hull(&shown, &pts, &hull);
    }
}

#[test]
fn lawson_pages_draw_each_flip_and_end_with_the_delaunay_triangles() {
    for pts in [
        generate(PointKind::UniformSquare, 25, 5).unwrap(),
        generate(PointKind::Cocircular, 16, 6).unwrap(),
        generate(PointKind::Grid, 25, 7).unwrap(),
    ] {
        let set = PointSet::new(&pts).unwrap();
        let trace = lawson_trace(&pts).unwrap();
        let html = lawson_steps(&set, &trace).unwrap().to_html();
        let kind = |s: &LawsonStep| match s {
            LawsonStep::Swept { .. } => "swept",
            LawsonStep::Flip { .. } => "flip",
            LawsonStep::Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &pts);
        for (s, f) in shown.iter().zip(&trace) {
            let frame = s.svg.frame();
            match &f.step {
                LawsonStep::Swept { triangles } | LawsonStep::Flip { triangles, .. } => {
                    let drawn = s.svg.subpaths("triangles");
                    assert_eq!(drawn.len(), triangles.len() / 3);
                    for (d, t) in drawn.iter().zip(triangles.chunks_exact(3)) {
                        assert_maps_back(&frame, d, &[pts[t[0]], pts[t[1]], pts[t[2]]]);
                    }
                    if let LawsonStep::Flip { removed, added, .. } = &f.step {
                        assert_maps_back(
                            &frame,
                            &s.svg.subpaths("removed")[0],
                            &removed.map(|i| pts[i]),
                        );
                        assert_maps_back(
                            &frame,
                            &s.svg.subpaths("added")[0],
                            &added.map(|i| pts[i]),
                        );
                    }
                }
                LawsonStep::Done { triangulation } => {
                    assert_eq!(triangulation, &lawson(&pts).unwrap());
                    let drawn = s.svg.subpaths("triangles");
                    assert_eq!(drawn.len(), triangulation.triangles.len() / 3);
                }
            }
        }
        let flips = trace
            .iter()
            .filter(|f| matches!(f.step, LawsonStep::Flip { .. }))
            .count();
        assert!(shown
            .last()
            .unwrap()
            .caption
            .contains(&format!("after {flips} flips")));
    }
}

/// Checks a beach line as drawn, in picture units: every drawn point `p` lies as far from
/// the sweep line as from its nearest site among the beach's (up to the rounding of the
/// drawing), and no site passed by the sweep line is nearer to it than the line (the beach
/// line is the envelope of the parabolas, so its arcs end at the right breakpoints).
fn assert_beach_drawn(
    s: &ShownFrame,
    pts: &[Point2],
    beach: &[usize],
    passed: &[usize],
    sweep: f64,
) {
    let frame = s.svg.frame();
    let drawn = s.svg.subpaths("beach");
    assert!(!drawn.is_empty(), "frame {}: no beach line", s.step);
    let line = frame.picture_of(Point2::new(pts[beach[0]].x, sweep))[1];
    let drawn_sites: Vec<[f64; 2]> = pts.iter().map(|&p| frame.picture_of(p)).collect();
    let at = |i: usize| drawn_sites[i];
    let dist = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).hypot(p[1] - q[1]);
    let tolerance = 0.2;
    for p in drawn.iter().flat_map(|d| &d.points) {
        let to_line = p[1] - line; // y grows downwards in the picture
        assert!(
            to_line >= -tolerance,
            "frame {}: {p:?} above the sweep line",
            s.step
        );
        let nearest = beach
            .iter()
            .map(|&i| dist(*p, at(i)))
            .fold(f64::INFINITY, f64::min);
        assert!(
            (nearest - to_line).abs() <= tolerance,
            "frame {}: {p:?} is {nearest} from the beach's sites, {to_line} from the line",
            s.step
        );
        for &i in passed {
            assert!(
                dist(*p, at(i)) >= to_line - tolerance,
                "frame {}: site {i}",
                s.step
            );
        }
    }
}

#[test]
fn fortune_pages_draw_the_sweep_line_the_beach_line_and_each_event() {
    for pts in [
        generate(PointKind::UniformDisk, 15, 11).unwrap(),
        generate(PointKind::Grid, 16, 12).unwrap(),
        generate(PointKind::Cocircular, 10, 13).unwrap(),
        generate(PointKind::Huge, 12, 14).unwrap(),
        [(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)]
            .map(Point2::from)
            .to_vec(),
    ] {
        let set = PointSet::new(&pts).unwrap();
        let trace = fortune_trace(&pts).unwrap();
        let html = fortune_steps(&set, &trace).unwrap().to_html();
        let kind = |s: &FortuneStep| match s {
            FortuneStep::Site { .. } => "site",
            FortuneStep::Circle { .. } => "circle",
            FortuneStep::Done { .. } => "done",
        };
        let shown = check_page(&html, &trace, kind, &pts);
        let mut passed: Vec<usize> = Vec::new();
        for (s, f) in shown.iter().zip(&trace) {
            let frame = s.svg.frame();
            let (sweep, beach, triangles) = match &f.step {
                FortuneStep::Site {
                    site,
                    sweep,
                    beach,
                    triangles,
                } => {
                    passed.push(*site);
                    let ring = s.svg.subpaths("current");
                    let rings = s.svg.circles("current");
                    assert!(ring.is_empty() && rings.len() == 1, "frame {}", s.step);
                    let want = frame.picture_of(pts[*site]);
                    assert!((rings[0][0] - want[0]).abs() < 0.051);
                    assert!((rings[0][1] - want[1]).abs() < 0.051);
                    (*sweep, beach, triangles)
                }
                FortuneStep::Circle {
                    triangle,
                    sweep,
                    beach,
                    triangles,
                    ..
                } => {
                    let event = s.svg.subpaths("event");
                    assert_eq!(event.len(), 1);
                    assert_maps_back(&frame, &event[0], &triangle.map(|i| pts[i]));
                    (*sweep, beach, triangles)
                }
                FortuneStep::Done { triangulation } => {
                    assert_eq!(triangulation, &fortune(&pts).unwrap());
                    let drawn = s.svg.subpaths("triangles");
                    assert_eq!(drawn.len(), triangulation.triangle_count());
                    let circles = triangulation.triangle_count();
                    assert!(s.caption.contains(&format!("{circles} Voronoi vertices")));
                    continue;
                }
            };
            let drawn = s.svg.subpaths("triangles");
            assert_eq!(drawn.len(), triangles.len() / 3);
            for (d, t) in drawn.iter().zip(triangles.chunks_exact(3)) {
                assert_maps_back(&frame, d, &[pts[t[0]], pts[t[1]], pts[t[2]]]);
            }
            // The sweep line: one horizontal line at the frame's height, or a caption
            // saying it is above the picture.
            let lines = s.svg.subpaths("sweep");
            if s.caption.contains("above the picture") {
                assert!(lines.is_empty());
            } else {
                assert_eq!(lines.len(), 1, "frame {}", s.step);
                let y = frame.picture_of(Point2::new(pts[0].x, sweep))[1];
                for p in &lines[0].points {
                    assert!((p[1] - y).abs() < 0.051, "frame {}: {p:?} vs {y}", s.step);
                }
            }
            assert_beach_drawn(s, &pts, beach, &passed, sweep);
        }
    }
}

#[test]
fn a_page_refuses_frames_beyond_its_limit_and_escapes_its_text() {
    let pts = [Point2::new(0.0, 0.0)];
    let bounds = BoundingBox::of(&pts).unwrap();
    let mut page = StepPage::new("a <page> & \"quotes\"").about("x < y");
    let frame = || {
        let mut picture = Picture::new("p", bounds, 1);
        picture.points(&Layer::new("points", Role::Input), pts);
        StepFrame {
            kind: "add",
            caption: "a < b & c".to_string(),
            picture,
            counts: Counts::default(),
        }
    };
    for _ in 0..STEP_PAGE_MAX_FRAMES {
        page.push(frame()).unwrap();
    }
    assert!(matches!(
        page.push(frame()),
        Err(Error::LimitExceeded {
            limit: "STEP_PAGE_MAX_FRAMES",
            ..
        })
    ));
    let html = page.to_html();
    let shown = frames_of(&html);
    assert_eq!(shown.len(), STEP_PAGE_MAX_FRAMES);
    assert!(shown[0].caption.contains("a < b & c"));
    assert!(shown[0].counts.is_empty(), "nothing counted yet");
    assert!(html.contains("<title>a &lt;page&gt; &amp; &quot;quotes&quot;</title>"));
    // An empty page is still a page.
    assert!(frames_of(&StepPage::new("empty").to_html()).is_empty());
}

#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use crate::browser::Browser;
    use crate::common::{run, TempDir};
    use serde_json::Value;

    fn points_file(dir: &TempDir, pts: &[Point2]) -> String {
        let path = dir.path("points.json");
        let text: Vec<String> = pts
            .iter()
            .map(|p| format!("[{:?},{:?}]", p.x, p.y))
            .collect();
        std::fs::write(&path, format!("[{}]", text.join(","))).unwrap();
        path.to_str().unwrap().to_string()
    }

    #[test]
    fn draw_steps_writes_one_frame_per_trace_frame() {
        let dir = TempDir::new("draw-steps");
        let pts = generate(PointKind::UniformDisk, 14, 9).unwrap();
        let input = points_file(&dir, &pts);
        let cases: [(&str, &str, usize); 6] = [
            (
                "hull",
                "jarvis",
                jarvis_trace(&pts, HullOptions::default()).unwrap().len(),
            ),
            (
                "hull",
                "graham",
                graham_trace(&pts, HullOptions::default()).unwrap().len(),
            ),
            (
                "hull",
                "monotone-chain",
                monotone_chain_trace(&pts, HullOptions::default())
                    .unwrap()
                    .len(),
            ),
            (
                "hull",
                "quickhull",
                quickhull_trace(&pts, HullOptions::default()).unwrap().len(),
            ),
            ("delaunay", "lawson", lawson_trace(&pts).unwrap().len()),
            ("delaunay", "fortune", fortune_trace(&pts).unwrap().len()),
        ];
        for (problem, algorithm, frames) in cases {
            let out = dir.path(&format!("{algorithm}.html"));
            let out = out.to_str().unwrap();
            let (code, stdout, err) = run(
                &[
                    "draw",
                    problem,
                    "--algorithm",
                    algorithm,
                    "--steps",
                    &input,
                    "--out",
                    out,
                ],
                None,
            );
            assert_eq!(code, 0, "{err}");
            let summary: Value = serde_json::from_str(stdout.trim()).unwrap();
            assert_eq!(summary["frames"], frames);
            assert_eq!(summary["algorithm"], algorithm);
            let html = std::fs::read_to_string(out).unwrap();
            assert_eq!(summary["bytes"], html.len());
            assert_eq!(frames_of(&html).len(), frames);
        }
        // To stdout: the page alone.
        let (code, stdout, _) = run(
            &[
                "draw", "hull", "-a", "graham", "--steps", &input, "--out", "-",
            ],
            None,
        );
        assert_eq!(code, 0);
        assert_eq!(
            frames_of(&stdout).len(),
            graham_trace(&pts, HullOptions::default()).unwrap().len()
        );
        // Untraced algorithms and bad input are named errors.
        for args in [
            vec![
                "draw", "hull", "-a", "chan", "--steps", &input, "--out", "x.html",
            ],
            vec![
                "draw",
                "delaunay",
                "-a",
                "incremental",
                "--steps",
                &input,
                "--out",
                "x.html",
            ],
        ] {
            let (code, _, err) = run(&args, None);
            assert_eq!(code, 2, "{args:?}");
            assert!(
                err.starts_with("error: --steps: no step trace for"),
                "{err}"
            );
        }
        let (code, _, err) = run(
            &[
                "draw", "hull", "-a", "jarvis", "--steps", "-", "--out", "x.html",
            ],
            Some("[[0, 0], [1, NaN]]"),
        );
        assert_eq!(code, 2);
        assert!(err.starts_with("error:"), "{err}");
    }

    #[test]
    fn a_step_page_renders_and_its_keys_and_slider_change_frames() {
        let Some(mut browser) = Browser::start() else {
            return;
        };
        let dir = TempDir::new("browser-steps");
        let pts = generate(PointKind::UniformDisk, 10, 3).unwrap();
        let input = points_file(&dir, &pts);
        let page = dir.path("graham.html");
        let (code, _, err) = run(
            &[
                "draw",
                "hull",
                "-a",
                "graham",
                "--steps",
                &input,
                "--out",
                page.to_str().unwrap(),
            ],
            None,
        );
        assert_eq!(code, 0, "{err}");
        let frames = graham_trace(&pts, HullOptions::default()).unwrap().len();
        browser.open(&page);
        assert!(browser.errors().is_empty(), "{:?}", browser.errors());
        let visible = "Array.from(document.querySelectorAll('section.frame')).filter(s => \
                       getComputedStyle(s).display !== 'none').map(s => Number(s.dataset.step))";
        let position = "document.getElementById('position').textContent";
        assert_eq!(browser.eval(visible), serde_json::json!([0]));
        browser.press("ArrowRight", 39);
        browser.press("ArrowRight", 39);
        assert_eq!(browser.eval(visible), serde_json::json!([2]));
        assert_eq!(browser.eval(position), format!("3 / {frames}"));
        browser.press("ArrowLeft", 37);
        assert_eq!(browser.eval(visible), serde_json::json!([1]));
        browser.press("End", 35);
        assert_eq!(browser.eval(visible), serde_json::json!([frames - 1]));
        browser.press("ArrowRight", 39);
        assert_eq!(
            browser.eval(visible),
            serde_json::json!([frames - 1]),
            "stays at the end"
        );
        browser.press("Home", 36);
        assert_eq!(browser.eval(visible), serde_json::json!([0]));
        // The slider, moved as a user drags it, shows its frame.
        browser.eval(
            "(() => { const s = document.getElementById('slider'); s.value = '4'; \
                      s.dispatchEvent(new Event('input')); return 0; })()",
        );
        assert_eq!(browser.eval(visible), serde_json::json!([4]));
        assert_eq!(browser.eval("document.body.dataset.current"), "4");
        // The frame shown has its picture laid out with a size.
        let width =
            browser.eval("document.querySelector('#frame-4 svg').getBoundingClientRect().width");
        assert!(width.as_f64().unwrap() > 100.0, "{width}");
        assert!(browser.errors().is_empty(), "{:?}", browser.errors());
    }
}
