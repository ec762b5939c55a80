//! `compgeo draw` for curves, surfaces, meshes and graphs against the commands that compute
//! the same things: the marked points are what `bezier eval`, `bspline eval`, `beta eval`,
//! `surface eval` and `triangle eval` print, the subdivision rounds are what `subdivide
//! --rounds r` prints, the mesh is what `mesh subdivide` prints, the colour classes, trees and
//! search trees are what `colour`, `mst`, `bfs` and `dfs` print; bad input exits with code 2
//! and one `error:` line naming the problem.
#![cfg(feature = "cli")]

use crate::common::{assert_rejected, run_json};
use crate::draw::Svg;
use compgeo::geometry::Point2;
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::PathBuf;

/// A scratch directory of this test process.
fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("compgeo-draw-curves-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes `text` to a scratch file and returns its path.
fn file(name: &str, text: &str) -> String {
    let path = scratch().join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// Runs `compgeo draw ARGS... --out OUT` and returns the summary and the parsed picture.
fn draw(args: &[&str], out: &str) -> (Value, Svg) {
    let out = scratch().join(out).display().to_string();
    let mut all = vec!["draw"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["--out", &out]);
    let summary = run_json(&all, None);
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(summary["bytes"], text.len());
    (summary, Svg::parse(text))
}

/// A JSON number, or a string such as "34/27", as `f64`.
fn number(v: &Value) -> f64 {
    match v {
        Value::String(s) => match s.split_once('/') {
            Some((n, d)) => n.parse::<f64>().unwrap() / d.parse::<f64>().unwrap(),
            None => s.parse().unwrap(),
        },
        other => other.as_f64().unwrap(),
    }
}

/// The plane point of a printed point of two or three coordinates, by the documented
/// projection (x, y, z) ↦ (x + k·y, z + k·y), k = √2/4.
fn plane(v: &Value) -> Point2 {
    let c: Vec<f64> = v.as_array().unwrap().iter().map(number).collect();
    match c.len() {
        2 => Point2::new(c[0], c[1]),
        3 => {
            let k = 2f64.sqrt() / 4.0;
            Point2::new(c[0] + k * c[1], c[2] + k * c[1])
        }
        n => panic!("{n} coordinates"),
    }
}

/// The first point of each subpath of a layer (dots are one-point subpaths).
fn firsts(svg: &Svg, class: &str) -> Vec<[f64; 2]> {
    svg.subpaths(class).iter().map(|s| s.points[0]).collect()
}

const CONTROL: &str = "[[0, 0], [1, 2], [3, 2], [4, 0], [5, 1]]";

#[test]
fn curve_pictures_mark_what_the_curve_commands_compute() {
    let cubic = "[[0, 0], [1, 2], [3, 2], [4, 0]]";
    let (summary, svg) = draw(
        &["bezier", "--control", cubic, "--t", "1/3", "--exact"],
        "bezier.svg",
    );
    assert_eq!(summary["problem"], "bezier");
    assert_eq!(summary["layers"]["scaffolding"], 2);
    assert_eq!(summary["layers"]["curve"], 1);
    let eval = run_json(
        &[
            "bezier",
            "eval",
            "--control",
            cubic,
            "--t",
            "1/3",
            "--exact",
        ],
        None,
    );
    assert!(svg
        .frame()
        .maps_back(firsts(&svg, "point")[0], plane(&eval["point"])));

    let (summary, svg) = draw(
        &["bspline", "--control", CONTROL, "--u", "0.3"],
        "bspline.svg",
    );
    assert_eq!(summary["layers"]["knots"], 3); // clamped cubic on five points: 0, ½, 1
    assert_eq!(summary["layers"]["de-boor-net"], 3);
    let eval = run_json(
        &["bspline", "eval", "--control", CONTROL, "--u", "0.3"],
        None,
    );
    assert!(svg
        .frame()
        .maps_back(firsts(&svg, "point")[0], plane(&eval["point"])));
    let knots = firsts(&svg, "knots");
    for (at, u) in knots.iter().zip(["0", "1/2", "1"]) {
        let eval = run_json(&["bspline", "eval", "--control", CONTROL, "--u", u], None);
        assert!(svg.frame().maps_back(*at, plane(&eval["point"])), "u = {u}");
    }

    let weights = "[1, 2, 1, 3, 1]";
    let (summary, svg) = draw(
        &[
            "nurbs",
            "--control",
            CONTROL,
            "--weights",
            weights,
            "--degree",
            "2",
        ],
        "nurbs.svg",
    );
    assert_eq!(summary["layers"]["knots"], 4);
    for (at, u) in firsts(&svg, "knots").iter().zip(["0", "1/3", "2/3", "1"]) {
        let eval = run_json(
            &[
                "nurbs",
                "eval",
                "--control",
                CONTROL,
                "--weights",
                weights,
                "--degree",
                "2",
                "--u",
                u,
            ],
            None,
        );
        assert!(svg.frame().maps_back(*at, plane(&eval["point"])), "u = {u}");
    }

    let shape = ["--beta1", "2", "--beta2", "1", "--control", CONTROL];
    let mut args = vec!["beta"];
    args.extend_from_slice(&shape);
    let (summary, svg) = draw(&args, "beta.svg");
    assert_eq!(summary["layers"]["joints"], 3);
    for (k, at) in firsts(&svg, "joints").iter().enumerate() {
        let mut eval = vec!["beta", "eval"];
        eval.extend_from_slice(&shape);
        let u = k.to_string();
        eval.extend_from_slice(&["--u", &u]);
        let eval = run_json(&eval, None);
        assert!(svg.frame().maps_back(*at, plane(&eval["point"])), "u = {u}");
    }
}

#[test]
fn subdivision_pictures_draw_each_round_the_command_computes() {
    let polygon = "[[0, 0], [8, 0], [8, 8], [0, 8], [-4, 4]]";
    for scheme in [
        &["--scheme", "chaikin"][..],
        &["--scheme", "lane-riesenfeld", "--degree", "3"],
        &["--scheme", "four-point"],
    ] {
        for closed in [false, true] {
            let mut args = vec!["subdivide", "--points", polygon, "--rounds", "3"];
            args.extend_from_slice(scheme);
            if closed {
                args.push("--closed");
            }
            let (summary, svg) = draw(&args, "subdivide.svg");
            assert_eq!(summary["layers"]["result"], 1);
            for r in 1..=3 {
                let rounds = r.to_string();
                let mut cmd = vec!["subdivide", "--points", polygon, "--rounds", &rounds];
                cmd.extend_from_slice(scheme);
                if closed {
                    cmd.push("--closed");
                }
                let printed = run_json(&cmd, None);
                let class = if r == 3 {
                    "result".to_string()
                } else {
                    format!("round-{r}")
                };
                let drawn = &svg.subpaths(&class)[0];
                assert_eq!(drawn.closed, closed);
                let points = printed["points"].as_array().unwrap();
                assert_eq!(drawn.points.len(), points.len(), "{args:?} round {r}");
                for (at, p) in drawn.points.iter().zip(points) {
                    assert!(svg.frame().maps_back(*at, plane(p)), "{args:?} round {r}");
                }
            }
        }
    }
}

#[test]
fn surface_triangle_and_mesh_pictures_agree_with_their_commands() {
    let net = "[[[0,0,0],[1,0,1],[2,0,0]],[[0,1,1],[1,1,2],[2,1,1]],[[0,2,0],[1,2,1],[2,2,0]]]";
    for spline in [&[][..], &["--degree-u", "2", "--degree-v", "1"]] {
        let mut args = vec!["surface", "--net", net, "--lines", "4"];
        args.extend_from_slice(spline);
        let (summary, svg) = draw(&args, "surface.svg");
        assert_eq!(summary["layers"]["iso-u"], 5);
        assert_eq!(summary["layers"]["control-net"], 6);
        let iso_u = svg.subpaths("iso-u");
        for (i, u) in ["0", "1/4", "1/2", "3/4", "1"].iter().enumerate() {
            for (at, v) in [
                (iso_u[i].points[0], "0"),
                (*iso_u[i].points.last().unwrap(), "1"),
            ] {
                let mut cmd = vec!["surface", "eval", "--net", net, "--u", u, "--v", v];
                cmd.extend_from_slice(spline);
                let eval = run_json(&cmd, None);
                assert!(svg.frame().maps_back(at, plane(&eval["point"])), "{u} {v}");
            }
        }
    }

    let control = "[[1,0,0],[0.5,0.5,0.5],[0,1,0],[0.5,0,0],[0,0.5,0],[0,0,0]]";
    let (summary, svg) = draw(
        &[
            "triangle",
            "--control",
            control,
            "--segments",
            "4",
            "--exact",
        ],
        "triangle.svg",
    );
    assert_eq!(summary["layers"]["iso-u"], 4);
    let iso_u = svg.subpaths("iso-u");
    for (i, u) in ["0", "1/4", "1/2", "3/4"].iter().enumerate() {
        for (j, at) in iso_u[i].points.iter().enumerate() {
            let v = format!("{j}/4");
            let eval = run_json(
                &[
                    "triangle",
                    "eval",
                    "--control",
                    control,
                    "--u",
                    u,
                    "--v",
                    &v,
                ],
                None,
            );
            assert!(svg.frame().maps_back(*at, plane(&eval["point"])), "{u} {v}");
        }
    }

    let obj = file(
        "pyramid.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n\
         f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 1 4 3 2\n",
    );
    let (summary, _) = draw(&["mesh", &obj], "mesh.svg");
    assert_eq!(summary["layers"]["edges"], 8);
    assert!(summary.get("algorithm").is_none());
    let (summary, svg) = draw(
        &["mesh", &obj, "--scheme", "catmull-clark", "--rounds", "2"],
        "mesh-fine.svg",
    );
    let fine = run_json(
        &[
            "mesh",
            "subdivide",
            "--scheme",
            "catmull-clark",
            "--rounds",
            "2",
            &obj,
        ],
        None,
    );
    assert_eq!(summary["algorithm"], "catmull-clark");
    assert_eq!(summary["layers"]["coarse"], 8);
    assert_eq!(summary["layers"]["edges"], fine["output"]["edges"]);
    let positions: Vec<Point2> = fine["positions"]
        .as_array()
        .unwrap()
        .iter()
        .map(plane)
        .collect();
    for s in svg.subpaths("edges") {
        for at in s.points {
            assert!(positions.iter().any(|&p| svg.frame().maps_back(at, p)));
        }
    }
}

/// The vertex each drawn point of `positions` maps back to.
fn vertex(svg: &Svg, at: [f64; 2], positions: &[Point2]) -> usize {
    (0..positions.len())
        .find(|&v| svg.frame().maps_back(at, positions[v]))
        .unwrap_or_else(|| panic!("{at:?} is no vertex"))
}

#[test]
fn graph_pictures_show_what_colour_mst_bfs_and_dfs_print() {
    let g = file(
        "g.json",
        r#"{"vertices": 6, "edges": [[0,1,4],[1,2,1],[2,3,3],[3,4,2],[4,5,5],[5,0,1],[0,3,2],[1,4,6]]}"#,
    );
    let positions = compgeo::draw::circle_layout(6);
    let printed = run_json(&["colour", "--algorithm", "dsatur", &g], None);
    let (summary, svg) = draw(&["graph", &g, "--colour", "dsatur"], "colour.svg");
    assert_eq!(summary["algorithm"], "dsatur");
    let colours: Vec<usize> = serde_json::from_value(printed["colours"].clone()).unwrap();
    let count = printed["count"].as_u64().unwrap() as usize;
    for k in 0..count {
        let drawn: BTreeSet<usize> = svg
            .circles(&format!("colour-{k}"))
            .iter()
            .map(|&[x, y, _]| vertex(&svg, [x, y], &positions))
            .collect();
        let expected: BTreeSet<usize> = (0..6).filter(|&v| colours[v] == k).collect();
        assert_eq!(drawn, expected);
    }

    let printed = run_json(&["mst", "--algorithm", "prim", &g], None);
    let (_, svg) = draw(&["graph", &g, "--mst", "prim"], "mst.svg");
    let tree: BTreeSet<[usize; 2]> = printed["edges"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            let (u, v) = (
                e[0].as_u64().unwrap() as usize,
                e[1].as_u64().unwrap() as usize,
            );
            [u.min(v), u.max(v)]
        })
        .collect();
    let drawn: BTreeSet<[usize; 2]> = svg
        .subpaths("tree")
        .iter()
        .map(|s| {
            let [u, v] = [s.points[0], s.points[1]].map(|at| vertex(&svg, at, &positions));
            [u.min(v), u.max(v)]
        })
        .collect();
    assert_eq!(drawn, tree);

    // Coordinates from a point file, a search tree from vertex 2.
    let points = file(
        "g-points.json",
        "[[0, 0], [4, 0], [6, 3], [4, 6], [0, 6], [-2, 3]]",
    );
    let at: Vec<Point2> = [(0, 0), (4, 0), (6, 3), (4, 6), (0, 6), (-2, 3)]
        .iter()
        .map(|&(x, y)| Point2::new(x as f64, y as f64))
        .collect();
    for kind in ["bfs", "dfs"] {
        let printed = run_json(&[kind, "--start", "2", &g], None);
        let (summary, svg) = draw(
            &["graph", &g, "--points", &points, &format!("--{kind}"), "2"],
            "search.svg",
        );
        assert_eq!(summary["algorithm"], kind);
        let parent: Vec<Option<usize>> = serde_json::from_value(printed["parent"].clone()).unwrap();
        let expected: BTreeSet<[usize; 2]> = (0..6)
            .filter_map(|v| parent[v].map(|p| [p.min(v), p.max(v)]))
            .collect();
        let drawn: BTreeSet<[usize; 2]> = svg
            .subpaths("tree")
            .iter()
            .map(|s| {
                let [u, v] = [s.points[0], s.points[1]].map(|p| vertex(&svg, p, &at));
                [u.min(v), u.max(v)]
            })
            .collect();
        assert_eq!(drawn, expected);
    }
}

#[test]
fn bad_curve_surface_mesh_and_graph_input_exits_2_with_a_named_error() {
    let out = scratch().join("bad.svg").display().to_string();
    let reject = |args: &[&str]| {
        let mut all = vec!["draw"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--out", &out]);
        assert_rejected(&all, None)
    };
    let e = reject(&["bezier", "--control", "[[0], [1]]"]);
    assert!(e.contains("dimension") && e.contains("2 or 3"), "{e}");
    let e = reject(&["bezier", "--control", "[[0, 0], [1, 1]]", "--t", "x"]);
    assert!(e.contains("t"), "{e}");
    let e = reject(&["bspline", "--control", CONTROL, "--u", "2"]);
    assert!(e.contains("u") && e.contains("outside"), "{e}");
    let e = reject(&["bspline", "--control", "[[0, 0], [1, NaN]]"]);
    assert!(e.contains("control point 1"), "{e}");
    let e = reject(&[
        "nurbs",
        "--control",
        CONTROL,
        "--weights",
        "[1, 1, -1, 1, 1]",
    ]);
    assert!(e.contains("weight"), "{e}");
    let e = reject(&["beta", "--beta1", "0", "--control", CONTROL]);
    assert!(e.contains("beta1") || e.contains("β₁"), "{e}");
    let e = reject(&[
        "subdivide",
        "--points",
        CONTROL,
        "--scheme",
        "four-point",
        "--degree",
        "3",
    ]);
    assert!(e.contains("--degree"), "{e}");
    let e = reject(&[
        "surface",
        "--net",
        "[[[0,0,0],[1,0,0]],[[0,1,0],[1,1,0]]]",
        "--lines",
        "0",
    ]);
    assert!(e.contains("lines"), "{e}");
    let e = reject(&["triangle", "--control", "[[0,0,0],[1,0,0]]"]);
    assert!(e.contains("control points"), "{e}");
    let bad = file("bad.obj", "v 0 0 0\nv 1 0\nf 1 2 3\n");
    let e = reject(&["mesh", &bad]);
    assert!(e.contains("line 2"), "{e}");
    let g = file(
        "bad-g.json",
        r#"{"vertices": 3, "edges": [[0, 1], [1, 2]]}"#,
    );
    let e = reject(&["graph", &g, "--bfs", "7"]);
    assert!(e.contains("vertex 7"), "{e}");
    let e = reject(&["graph", &g, "--mst", "kruskal"]);
    assert!(e.contains("weight"), "{e}");
    let e = reject(&["graph", &g, "--bfs", "0", "--dfs", "0"]);
    assert!(e.contains("--dfs") || e.contains("--bfs"), "{e}");
    let two = file("two.json", "[[0, 0], [1, 1]]");
    let e = reject(&["graph", &g, "--points", &two]);
    assert!(e.contains("2 points for 3 vertices"), "{e}");
    let empty = file("empty-g.json", r#"{"vertices": 0, "edges": []}"#);
    let e = reject(&["graph", &empty]);
    assert!(e.contains("empty"), "{e}");
}
