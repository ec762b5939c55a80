//! The `compgeo beta` command against the library and the seed: the printed matrices of the
//! three examples with `--exact`, evaluation and subdivision as the library computes them
//! (also from stdin and in `f64`), and bad parameters and polygons exiting with code 2 and one
//! `error:` line naming the parameter.
#![cfg(all(feature = "cli", feature = "exact"))]

use crate::beta::printed_examples;
use crate::common::{assert_rejected, run_json};
use crate::spline_common::{q, qi, Q};
use compgeo::spline::{BetaParameters, BetaSpline, Matrix4, Point};
use serde_json::Value;

fn rational(v: &Value) -> Q {
    v.as_str().unwrap().parse().unwrap()
}

fn matrix(v: &Value) -> Matrix4<Q> {
    std::array::from_fn(|i| std::array::from_fn(|j| rational(&v[i][j])))
}

fn polygon(v: &Value) -> Vec<Point<Q, 2>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| Point::new([rational(&p[0]), rational(&p[1])]))
        .collect()
}

const CONTROL: &str = r#"[[0,0],[1,2],["3/2",3],[4,0],[5,"-1/3"],[6,2]]"#;

fn control() -> Vec<Point<Q, 2>> {
    [
        (qi(0), qi(0)),
        (qi(1), qi(2)),
        (q(3, 2), qi(3)),
        (qi(4), qi(0)),
        (qi(5), q(-1, 3)),
        (qi(6), qi(2)),
    ]
    .into_iter()
    .map(|(x, y)| Point::new([x, y]))
    .collect()
}

#[test]
fn matrices_prints_the_seeds_examples() {
    for ([b1, b2, c], left, right) in printed_examples() {
        let (b1, b2, c) = (b1.to_string(), b2.to_string(), c.to_string());
        let out = run_json(
            &[
                "beta",
                "matrices",
                "--beta1",
                &b1,
                "--beta2",
                &b2,
                "--c",
                &c,
                "--allow-negative-tension",
                "--exact",
            ],
            None,
        );
        assert_eq!(matrix(&out["left"]), left, "β₂ = {b2}");
        assert_eq!(matrix(&out["right"]), right, "β₂ = {b2}");
        assert_eq!(
            rational(&out["delta"]),
            rational(&Value::String(b2.clone())) + qi(12)
        );
        let hull = out["keeps_convex_hull"]["left"].as_bool().unwrap();
        assert_eq!(hull, b2 == "0");
        assert_eq!(out["counts"]["arithmetic_operations"], 256);
    }
    // Without --exact the same matrices, rounded.
    let out = run_json(&["beta", "matrices", "--beta2", "5"], None);
    let x = out["left"][0][0].as_f64().unwrap();
    assert!((x - 79.0 / 153.0).abs() < 1e-15, "{x}");
}

#[test]
fn eval_and_subdivide_are_the_librarys() {
    let p = BetaParameters::new(q(3, 2), q(1, 2)).unwrap();
    let s = BetaSpline::new(p, control()).unwrap();
    for u in ["0", "1/3", "2", "5/2", "3"] {
        let out = run_json(
            &[
                "beta",
                "eval",
                "--control",
                CONTROL,
                "--beta1",
                "3/2",
                "--beta2",
                "1/2",
                "--u",
                u,
                "--exact",
            ],
            None,
        );
        let got = polygon(&Value::Array(vec![out["point"].clone()]));
        assert_eq!(got[0], s.eval(&u.parse().unwrap()).unwrap(), "u = {u}");
        assert_eq!(out["segments"], 3);
    }
    let out = run_json(
        &[
            "beta",
            "subdivide",
            "--control",
            "-",
            "--beta1",
            "3/2",
            "--beta2",
            "1/2",
            "--c",
            "1/3",
            "--rounds",
            "2",
            "--exact",
        ],
        Some(CONTROL),
    );
    let pieces: Vec<Vec<Point<Q, 2>>> = out["pieces"]
        .as_array()
        .unwrap()
        .iter()
        .map(polygon)
        .collect();
    let want: Vec<Vec<Point<Q, 2>>> = s
        .subdivide(&q(1, 3), 2)
        .unwrap()
        .into_iter()
        .map(|p| p.to_vec())
        .collect();
    assert_eq!(pieces, want);
    assert_eq!(pieces.len(), 3 * 4);
    assert_eq!(out["counts"]["arithmetic_operations"], 256 + 32 * 3 * 3);
    // f64 output is numbers.
    let out = run_json(&["beta", "eval", "--control", CONTROL, "--u", "1.5"], None);
    assert!(out["point"][0].is_f64());
}

#[test]
fn bad_parameters_and_polygons_exit_with_code_2() {
    let cases: [(&[&str], &str); 10] = [
        (&["beta", "matrices", "--beta1", "0"], "invalid beta1"),
        (&["beta", "matrices", "--beta1", "-1/2"], "invalid beta1"),
        (&["beta", "matrices", "--beta1", "inf"], "beta1"),
        (&["beta", "matrices", "--beta2", "-10"], "invalid beta2"),
        (
            &[
                "beta",
                "matrices",
                "--beta2",
                "-4",
                "--allow-negative-tension",
                "--exact",
            ],
            "singular",
        ),
        (
            &[
                "beta",
                "matrices",
                "--beta2",
                "-12",
                "--allow-negative-tension",
            ],
            "δ",
        ),
        (&["beta", "matrices", "--c", "1"], "invalid c"),
        (
            &["beta", "subdivide", "--control", "[[0,0],[1,1],[2,0]]"],
            "at least 4",
        ),
        (
            &["beta", "subdivide", "--control", CONTROL, "--rounds", "30"],
            "MAX_SUBDIVIDED_PIECES",
        ),
        (
            &[
                "beta",
                "eval",
                "--control",
                CONTROL,
                "--u",
                "7/2",
                "--exact",
            ],
            "invalid u",
        ),
    ];
    for (args, needle) in cases {
        let line = assert_rejected(args, None);
        assert!(line.contains(needle), "{args:?}: {line}");
    }
    let line = assert_rejected(&["beta", "matrices", "--beta2", "-10"], None);
    assert!(
        line.contains("-10") && line.contains("--allow-negative-tension"),
        "{line}"
    );
}
