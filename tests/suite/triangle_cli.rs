//! The `compgeo triangle` command against the library: points, subdivisions, elevations and
//! meshes as the library computes them (exactly with `--exact`), the OBJ file read back by
//! `tobj`, and bad patches and points exiting with code 2 and one `error:` line naming what
//! is wrong.
#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run_json};
use crate::spline_common::{json_list, q, qi, Q};
use compgeo::spline::Point;
use compgeo::surface::{Barycentric, TriangularPatch};
use serde_json::Value;

/// A cubic patch in R³ with fractions, as the command reads it (10 points, rows of constant
/// k first).
const CONTROL: &str = r#"[[0,0,0],[1,0,"1/2"],[2,0,-1],[3,0,0],
                         [0,1,1],[1,1,"2/3"],[2,1,2],
                         [0,2,"-1/4"],[1,2,1],
                         [0,3,"3/5"]]"#;

fn point3(v: &Value) -> Point<Q, 3> {
    let c = json_list(v);
    Point::new([c[0].clone(), c[1].clone(), c[2].clone()])
}

fn points3(v: &Value) -> Vec<Point<Q, 3>> {
    v.as_array().unwrap().iter().map(point3).collect()
}

/// The same patch in the library.
fn patch() -> TriangularPatch<Q, 3> {
    let text: Vec<Vec<Value>> = serde_json::from_str(CONTROL).unwrap();
    let points = text
        .iter()
        .map(|p| {
            let c: Vec<Q> = p
                .iter()
                .map(|x| match x {
                    Value::String(s) => s.parse().unwrap(),
                    other => qi(other.as_i64().unwrap()),
                })
                .collect();
            Point::new([c[0].clone(), c[1].clone(), c[2].clone()])
        })
        .collect();
    TriangularPatch::new(points).unwrap()
}

#[test]
fn eval_matches_the_library_exactly() {
    let b = patch();
    for (u, v) in [(q(1, 3), q(1, 2)), (qi(0), qi(1)), (q(-1, 2), q(7, 5))] {
        let x = Barycentric::from_uv(u.clone(), v.clone()).unwrap();
        let (us, vs) = (u.to_string(), v.to_string());
        for algorithm in ["de-casteljau", "bernstein"] {
            let out = run_json(
                &[
                    "triangle",
                    "eval",
                    "--control",
                    CONTROL,
                    "--u",
                    &us,
                    "--v",
                    &vs,
                    "--algorithm",
                    algorithm,
                    "--exact",
                ],
                None,
            );
            assert_eq!(point3(&out["point"]), b.de_casteljau(&x), "{algorithm}");
            assert_eq!(out["degree"], 3);
            assert_eq!(out["algorithm"], algorithm);
            // Ten of each: C(5, 3) combinations, or (3 + 1)(3 + 2)/2 terms.
            assert_eq!(out["counts"]["arithmetic_operations"], 10);
        }
        // With --w = 1 − u − v, the same point; with --degree 3 too.
        let w = (qi(1) - &u - &v).to_string();
        let out = run_json(
            &[
                "triangle",
                "eval",
                "--control",
                CONTROL,
                "--u",
                &us,
                "--v",
                &vs,
                "--w",
                &w,
                "--degree",
                "3",
                "--exact",
            ],
            None,
        );
        assert_eq!(point3(&out["point"]), b.de_casteljau(&x));
    }
    // Without --exact: numbers in and out, and stdin.
    let out = run_json(
        &[
            "triangle",
            "eval",
            "--control",
            "-",
            "--u",
            "0.25",
            "--v",
            "0.5",
        ],
        Some(CONTROL),
    );
    let x = Barycentric::new(q(1, 4), q(1, 2), q(1, 4)).unwrap();
    let want = b.de_casteljau(&x).to_f64();
    let got: Vec<f64> = out["point"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_f64().unwrap())
        .collect();
    for (g, w) in got.iter().zip(want.coords()) {
        assert!((g - w).abs() <= 1e-12, "{g} vs {w}");
    }
}

#[test]
fn subdivide_and_elevate_match_the_library_exactly() {
    let b = patch();
    let out = run_json(
        &[
            "triangle",
            "subdivide",
            "--control",
            CONTROL,
            "--u",
            "1/2",
            "--v",
            "1/3",
            "--exact",
        ],
        None,
    );
    let x = Barycentric::new(q(1, 2), q(1, 3), q(1, 6)).unwrap();
    let pieces = b.subdivide(&x).unwrap();
    let printed = out["patches"].as_array().unwrap();
    assert_eq!(printed.len(), 3);
    for (p, piece) in printed.iter().zip(&pieces) {
        assert_eq!(p["degree"], 3);
        assert_eq!(points3(&p["control"]), piece.points());
    }
    assert_eq!(out["counts"]["arithmetic_operations"], 10);

    let out = run_json(
        &[
            "triangle",
            "subdivide",
            "--control",
            CONTROL,
            "--midpoints",
            "--exact",
        ],
        None,
    );
    let pieces = b.split_four().unwrap();
    let printed = out["patches"].as_array().unwrap();
    assert_eq!(printed.len(), 4);
    for (p, piece) in printed.iter().zip(&pieces) {
        assert_eq!(points3(&p["control"]), piece.points());
    }
    assert_eq!(out["counts"]["arithmetic_operations"], 60);

    for (args, m) in [(vec!["--to", "5"], 5), (vec!["--by", "2"], 5), (vec![], 4)] {
        let mut all = vec!["triangle", "elevate", "--control", CONTROL, "--exact"];
        all.extend(args);
        let out = run_json(&all, None);
        assert_eq!(out["degree"], m);
        assert_eq!(points3(&out["control"]), b.elevate_to(m).unwrap().points());
    }
}

#[test]
fn tessellate_writes_the_library_mesh() {
    let b = patch();
    let mesh = b.tessellate(3).unwrap();
    let out = run_json(
        &[
            "triangle",
            "tessellate",
            "--control",
            CONTROL,
            "--segments",
            "3",
            "--exact",
        ],
        None,
    );
    assert_eq!(out["vertices"], 10);
    assert_eq!(out["triangles"], 9);
    let positions: Vec<[f64; 3]> = serde_json::from_value(out["positions"].clone()).unwrap();
    assert_eq!(positions, mesh.positions);
    let dir = std::env::temp_dir().join(format!("compgeo-triangle-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("patch.obj");
    let out = run_json(
        &[
            "triangle",
            "tessellate",
            "--control",
            CONTROL,
            "--segments",
            "3",
            "--exact",
            "--obj",
            obj.to_str().unwrap(),
        ],
        None,
    );
    assert_eq!(out["obj"], obj.to_str().unwrap());
    let (models, _) = tobj::load_obj(
        &obj,
        &tobj::LoadOptions {
            single_index: true,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(models[0].mesh.indices.len(), 3 * 9);
    assert_eq!(models[0].mesh.positions.len(), 3 * 10);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_exits_2_with_a_named_error() {
    let cases: [(&[&str], &str); 10] = [
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0],[1],[2],[3]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "control points",
        ),
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0],[1],[2]]",
                "--degree",
                "2",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "control points",
        ),
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0],[1],[2]]",
                "--degree",
                "99999999",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "MAX_DEGREE",
        ),
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0],[\"nan\"],[2]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "control point 1",
        ),
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0],[1e400],[2]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "control point 1",
        ),
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0],[1],[2]]",
                "--u",
                "1/2",
                "--v",
                "1/2",
                "--w",
                "1/2",
                "--exact",
            ],
            "barycentric",
        ),
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0],[1],[2]]",
                "--u",
                "nan",
                "--v",
                "0",
            ],
            "u",
        ),
        (
            &[
                "triangle",
                "elevate",
                "--control",
                "[[0],[1],[2]]",
                "--to",
                "1000000",
            ],
            "MAX_DEGREE",
        ),
        (
            &["triangle", "tessellate", "--control", "[[0,0],[1,0],[2,0]]"],
            "three dimensions",
        ),
        (
            &[
                "triangle",
                "eval",
                "--control",
                "[[0,0,0,0,0],[1,0,0,0,0],[2,0,0,0,0]]",
                "--u",
                "0",
                "--v",
                "0",
            ],
            "5 coordinates",
        ),
    ];
    for (args, needle) in cases {
        let line = assert_rejected(args, None);
        assert!(line.contains(needle), "{args:?}: {line}");
    }
    // A missing point, and an evaluation beyond f64.
    let line = assert_rejected(
        &["triangle", "subdivide", "--control", "[[0],[1],[2]]"],
        None,
    );
    assert!(line.contains("--u"), "{line}");
    let line = assert_rejected(
        &[
            "triangle",
            "eval",
            "--control",
            "[[1e308],[-1e308],[1e308]]",
            "--u",
            "1e10",
            "--v",
            "-1e10",
        ],
        None,
    );
    assert!(line.contains("--exact"), "{line}");
}

#[test]
fn the_group_alone_names_its_subcommands() {
    let line = assert_rejected(&["triangle"], None);
    assert!(
        line.contains("`compgeo triangle`")
            && line.contains("eval, subdivide, elevate, tessellate"),
        "{line}"
    );
}
