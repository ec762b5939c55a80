//! `compgeo draw` against the library and the other commands: the picture file parses, its
//! layers agree with what `compgeo hull`, `delaunay`, ... print for the same input, the JSON
//! summary describes the file, `--out -` writes the SVG alone, and bad input exits with code
//! 2 and one `error:` line naming the problem.
#![cfg(feature = "cli")]

use crate::common::{assert_rejected, run, run_json};
use crate::draw::Svg;
use compgeo::geometry::Point2;
use serde_json::Value;
use std::path::PathBuf;

/// A scratch directory of this test process.
fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("compgeo-draw-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes `n` points of a seeded disk to a JSON file and returns its path and the points.
fn input(name: &str, n: usize) -> (String, Vec<Point2>) {
    let pts = compgeo::gen::points(compgeo::gen::PointKind::UniformDisk, n, 4).unwrap();
    let json: Vec<[f64; 2]> = pts.iter().map(|p| [p.x, p.y]).collect();
    let path = scratch().join(name);
    std::fs::write(&path, serde_json::to_string(&json).unwrap()).unwrap();
    (path.display().to_string(), pts)
}

/// Runs `compgeo draw ARGS... IN --out OUT` and returns the summary and the parsed picture.
fn draw(args: &[&str], input: &str, out: &str) -> (Value, Svg) {
    let out = scratch().join(out).display().to_string();
    let mut all = vec!["draw"];
    all.extend_from_slice(args);
    all.extend_from_slice(&[input, "--out", &out]);
    let summary = run_json(&all, None);
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(summary["out"], out.as_str());
    assert_eq!(summary["bytes"], text.len());
    (summary, Svg::parse(text))
}

#[test]
fn every_problem_draws_what_its_own_command_prints() {
    let (path, pts) = input("every.json", 40);
    let hull = run_json(&["hull", "--algorithm", "graham", &path], None);
    let (summary, svg) = draw(&["hull", "--algorithm", "graham"], &path, "hull.svg");
    assert_eq!(summary["problem"], "hull");
    assert_eq!(summary["algorithm"], "graham");
    assert_eq!(summary["points"], 40);
    assert_eq!(summary["labels"], true);
    let indices: Vec<usize> = serde_json::from_value(hull["hull"].clone()).unwrap();
    let drawn = &svg.subpaths("hull")[0];
    assert_eq!(drawn.points.len(), indices.len());
    for (at, &i) in drawn.points.iter().zip(&indices) {
        assert!(svg.frame().maps_back(*at, pts[i]));
    }
    assert!(svg.title().contains("(graham)"));

    let delaunay = run_json(&["delaunay", "--algorithm", "lawson", &path], None);
    let (summary, svg) = draw(
        &["delaunay", "--algorithm", "lawson", "--circumcircles"],
        &path,
        "delaunay.svg",
    );
    let triangles: Vec<[usize; 3]> = serde_json::from_value(delaunay["triangles"].clone()).unwrap();
    assert_eq!(summary["layers"]["triangles"], triangles.len());
    let drawn = svg.subpaths("triangles");
    for (triangle, abc) in drawn.iter().zip(&triangles) {
        for (at, &i) in triangle.points.iter().zip(abc) {
            assert!(svg.frame().maps_back(*at, pts[i]));
        }
    }
    assert!(summary["layers"]["circumcircles"].as_u64().unwrap() > 0);

    let diameter = run_json(&["diameter", &path], None);
    for name in ["diameter", "calipers"] {
        let (summary, svg) = draw(&[name], &path, "diameter.svg");
        assert_eq!(summary["problem"], "diameter");
        let pair: [usize; 2] = serde_json::from_value(diameter["pair"].clone()).unwrap();
        let drawn = &svg.subpaths("diameter")[0];
        assert!(svg.frame().maps_back(drawn.points[0], pts[pair[0]]));
        assert!(svg.frame().maps_back(drawn.points[1], pts[pair[1]]));
        let pairs = diameter["antipodal_pairs"].as_array().unwrap().len();
        assert_eq!(summary["layers"]["antipodal-pairs"], pairs);
    }

    let closest = run_json(
        &["closest-pair", "--algorithm", "divide-and-conquer", &path],
        None,
    );
    let (_, svg) = draw(
        &["closest-pair", "--algorithm", "divide-and-conquer"],
        &path,
        "closest.svg",
    );
    let pair: [usize; 2] = serde_json::from_value(closest["pair"].clone()).unwrap();
    let drawn = &svg.subpaths("closest-pair")[0];
    assert!(svg.frame().maps_back(drawn.points[0], pts[pair[0]]));
    assert!(svg.frame().maps_back(drawn.points[1], pts[pair[1]]));

    let emst = run_json(&["emst", &path], None);
    let (summary, _) = draw(&["emst"], &path, "emst.svg");
    assert_eq!(
        summary["layers"]["emst"],
        emst["edges"].as_array().unwrap().len()
    );
    assert!(summary.get("algorithm").is_none());

    let voronoi = run_json(&["voronoi", "--clip", "-0.5,-0.5,0.5,0.5", &path], None);
    let (summary, _) = draw(
        &["voronoi", "--clip", "-0.5,-0.5,0.5,0.5"],
        &path,
        "voronoi.svg",
    );
    let nonempty = voronoi["cells"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| !c["vertices"].as_array().unwrap().is_empty())
        .count();
    assert_eq!(summary["layers"]["cells"], nonempty);
    let (summary, _) = draw(&["voronoi"], &path, "voronoi-auto.svg");
    assert_eq!(summary["layers"]["cells"], 40);

    let circle = run_json(&["empty-circle", &path], None);
    let (_, svg) = draw(&["empty-circle"], &path, "circle.svg");
    let [[cx, cy, _]] = svg.circles("empty-circle")[..] else {
        panic!("one circle");
    };
    let centre: [f64; 2] = serde_json::from_value(circle["centre"].clone()).unwrap();
    assert!(svg
        .frame()
        .maps_back([cx, cy], Point2::new(centre[0], centre[1])));
}

#[test]
fn stdin_csv_and_out_dash_work() {
    let text = "x,y\n0,0\n1,0\n0,1\n1,1\n0.5,0.25\n";
    let (code, out, err) = run(
        &["draw", "hull", "--format", "csv", "-", "--out", "-"],
        Some(text),
    );
    assert_eq!(code, 0, "{err}");
    assert!(err.is_empty());
    let svg = Svg::parse(out);
    assert_eq!(svg.subpaths("hull")[0].points.len(), 4);
}

#[test]
fn large_inputs_have_no_labels() {
    let (path, _) = input("large.json", 400);
    let (summary, svg) = draw(&["delaunay"], &path, "large.svg");
    assert_eq!(summary["labels"], false);
    assert_eq!(summary["layers"]["labels"], 0);
    assert!(svg.texts("labels").is_empty());
}

#[test]
fn bad_input_exits_2_with_a_named_error() {
    let out = scratch().join("bad.svg").display().to_string();
    let nan = "[[0, 0], [1, NaN], [2, 2]]";
    let e = assert_rejected(&["draw", "hull", "-", "--out", &out], Some(nan));
    assert!(e.contains("point 1") && e.contains("NaN"), "{e}");
    let e = assert_rejected(
        &["draw", "delaunay", "-", "--out", &out],
        Some("[[0, 0], [1"),
    );
    assert!(e.contains("invalid JSON"), "{e}");
    let e = assert_rejected(
        &["draw", "closest-pair", "-", "--out", &out],
        Some("[[0, 0]]"),
    );
    assert!(e.contains("at least 2"), "{e}");
    let e = assert_rejected(
        &["draw", "emst", "--algorithm", "prim", "-", "--out", &out],
        Some("[[0, 0]]"),
    );
    assert!(e.contains("--algorithm"), "{e}");
    let e = assert_rejected(
        &["draw", "voronoi", "--clip", "1,1,0,0", "-", "--out", &out],
        Some("[[0, 0], [1, 1]]"),
    );
    assert!(e.contains("box"), "{e}");
    let e = assert_rejected(
        &["draw", "hull", "--algorithm", "gift", "-", "--out", &out],
        Some("[[0, 0]]"),
    );
    assert!(e.contains("gift"), "{e}");
    let missing = scratch()
        .join("no-such-dir")
        .join("x.svg")
        .display()
        .to_string();
    let e = assert_rejected(&["draw", "hull", "-", "--out", &missing], Some("[[0, 0]]"));
    assert!(e.contains("cannot write"), "{e}");
    let e = assert_rejected(&["draw", "hull", "-"], Some("[[0, 0]]"));
    assert!(e.contains("--out"), "{e}");
    let e = assert_rejected(&["draw"], None);
    assert!(e.contains("missing subcommand for `compgeo draw`"), "{e}");
}
