//! The `compgeo nurbs` command against the library: the exact circle's points, insertion,
//! elevation and rational Bézier pieces as the library computes them, and bad weights exiting
//! with code 2 and one `error:` line naming the index and the value.
#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run_json};
use crate::spline_common::{json_list, json_points, q, qi, Q};
use compgeo::spline::{Curve, KnotVector, Nurbs, Point};
use serde_json::Value;

const QUARTER: &str = "[[1,0],[1,1],[0,1]]";
const WEIGHTS: &str = "[1,1,2]";

fn quarter() -> Nurbs<Q, 2> {
    let c = [(1, 0), (1, 1), (0, 1)].map(|(x, y)| Point::new([qi(x), qi(y)]));
    let t = KnotVector::clamped_uniform(2, 3, qi(0), qi(1)).unwrap();
    Nurbs::new(c.to_vec(), vec![qi(1), qi(1), qi(2)], t).unwrap()
}

#[test]
fn the_quarter_circle_is_exact_and_matches_the_library() {
    let s = quarter();
    for k in 0..=8 {
        let u = q(k, 8);
        let out = run_json(
            &[
                "nurbs",
                "eval",
                "--control",
                QUARTER,
                "--weights",
                WEIGHTS,
                "--u",
                &u.to_string(),
                "--exact",
            ],
            None,
        );
        let p = &json_points(&Value::Array(vec![out["point"].clone()]))[0];
        assert_eq!(p, &s.eval(&u).unwrap());
        assert_eq!(p[0].clone() * &p[0] + p[1].clone() * &p[1], qi(1), "at {u}");
    }
}

#[test]
fn insert_elevate_and_pieces_match_the_library() {
    let s = quarter();
    let args = |op: &str, more: &[&str]| {
        let mut a = vec![
            "nurbs",
            op,
            "--control",
            QUARTER,
            "--weights",
            WEIGHTS,
            "--exact",
        ];
        a.extend_from_slice(more);
        run_json(&a, None)
    };
    let out = args("insert", &["--u", "1/3"]);
    let want = s.insert(&q(1, 3), 1).unwrap();
    assert_eq!(json_points(&out["control"]), want.control().to_vec());
    assert_eq!(json_list(&out["weights"]), want.weights().to_vec());
    let out = args("elevate", &[]);
    let want = s.elevate(1).unwrap();
    assert_eq!(json_points(&out["control"]), want.control().to_vec());
    assert_eq!(json_list(&out["weights"]), want.weights().to_vec());
    let out = args("to-bezier", &[]);
    let (breaks, pieces) = s.to_bezier().unwrap();
    assert_eq!(json_list(&out["breakpoints"]), breaks);
    let printed = out["pieces"].as_array().unwrap();
    assert_eq!(printed.len(), pieces.len());
    for (got, b) in printed.iter().zip(&pieces) {
        assert_eq!(json_points(&got["control"]), b.control().to_vec());
        assert_eq!(json_list(&got["weights"]), b.weights().to_vec());
    }
}

#[test]
fn bad_weights_and_unclamped_elevation_are_named_errors() {
    let cases: &[(&[&str], &[&str])] = &[
        (
            &[
                "eval",
                "--control",
                QUARTER,
                "--weights",
                "[1,0,2]",
                "--u",
                "0",
            ],
            &["weight 1 is 0"],
        ),
        (
            &[
                "eval",
                "--control",
                QUARTER,
                "--weights",
                "[1,-1,2]",
                "--u",
                "0",
            ],
            &["weight 1 is -1"],
        ),
        (
            &[
                "eval",
                "--control",
                QUARTER,
                "--weights",
                "[1,2]",
                "--u",
                "0",
            ],
            &["3 weights, got 2"],
        ),
        (
            &[
                "eval",
                "--control",
                QUARTER,
                "--weights",
                "[1,\"x\",2]",
                "--u",
                "0",
            ],
            &["weight 1"],
        ),
        (
            &[
                "elevate",
                "--control",
                "[[0,0],[1,2],[3,2],[4,0]]",
                "--degree",
                "2",
                "--knots",
                "[0,1,2,3,4,5,6]",
            ],
            &["clamped ends"],
        ),
    ];
    for (args, words) in cases {
        let mut all = vec!["nurbs"];
        all.extend_from_slice(args);
        let line = assert_rejected(&all, None);
        for w in *words {
            assert!(line.contains(w), "{all:?}: {line} lacks {w:?}");
        }
    }
}
