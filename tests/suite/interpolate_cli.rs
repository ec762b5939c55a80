//! The `compgeo interpolate` command against the library and the command-line contract: the
//! seed's Hermite solution printed as fractions, splines and polynomial forms equal to the
//! library's in both arithmetics, bad input exiting with code 2 and one `error:` line.
#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run_json};
use crate::spline_common::{p2, pairs, q, qi, Q};
use compgeo::spline::{
    cubic_spline, estimate_tangents, hermite, vandermonde, vandermonde_hermite, Curve,
    EndCondition, HermiteNode, Point,
};
use serde_json::Value;

fn rational(v: &Value) -> Q {
    v.as_str().unwrap().parse().unwrap()
}

fn exact_points(v: &Value) -> Vec<Point<Q, 2>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| p2(rational(&p[0]), rational(&p[1])))
        .collect()
}

#[test]
fn hermite_exact_prints_the_seed_solution_as_fractions() {
    let out = run_json(
        &[
            "interpolate",
            "hermite",
            "--points",
            "[[0,1],[5,2],[10,5],[6,9],[5,4]]",
            "--tangents",
            "[[6,12],[12,-12],[24,48],[-48,0],[48,-72]]",
            "--knots",
            r#"[0,"1/2","3/4","7/8",1]"#,
            "--exact",
        ],
        None,
    );
    let text = include_str!("../fixtures/seed003_hermite_example.txt");
    let printed: Vec<Vec<Point<Q, 2>>> = text
        .lines()
        .filter(|l| l.starts_with("Tramo"))
        .map(|l| pairs(l.split_once(':').unwrap().1))
        .collect();
    let got: Vec<Vec<Point<Q, 2>>> = out["pieces"]
        .as_array()
        .unwrap()
        .iter()
        .map(exact_points)
        .collect();
    assert_eq!(got, printed);
    assert_eq!(out["knots"][1], "1/2");
}

#[test]
fn spline_output_matches_the_library_in_both_arithmetics() {
    let pts = "[[0,0],[1,2],[3,1],[4,4]]";
    let knots = r#"[0,"1/3",1,"5/2"]"#;
    let lib_knots = vec![qi(0), q(1, 3), qi(1), q(5, 2)];
    let lib_pts = vec![
        p2(qi(0), qi(0)),
        p2(qi(1), qi(2)),
        p2(qi(3), qi(1)),
        p2(qi(4), qi(4)),
    ];
    for (end, condition) in [
        ("natural", EndCondition::Natural),
        ("bessel", EndCondition::Bessel),
    ] {
        let out = run_json(
            &[
                "interpolate",
                "spline",
                "--points",
                pts,
                "--knots",
                knots,
                "--end",
                end,
                "--exact",
            ],
            None,
        );
        let want = cubic_spline(&lib_knots, &lib_pts, &condition).unwrap();
        for (piece, b) in out["pieces"].as_array().unwrap().iter().zip(want.pieces()) {
            assert_eq!(exact_points(piece), b.control());
        }
        // f64: the same numbers to rounding.
        let out = run_json(
            &[
                "interpolate",
                "spline",
                "--points",
                pts,
                "--knots",
                knots,
                "--end",
                end,
            ],
            None,
        );
        let flat: Vec<f64> = out["pieces"]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|p| p.as_array().unwrap().iter())
            .flat_map(|c| c.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
            .collect();
        let exact: Vec<f64> = want
            .pieces()
            .iter()
            .flat_map(|b| b.control().iter().flat_map(|p| p.to_f64().0))
            .collect();
        assert_eq!(flat.len(), exact.len());
        for (a, b) in flat.iter().zip(&exact) {
            assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} vs {b}");
        }
    }
    let out = run_json(
        &[
            "interpolate",
            "spline",
            "--points",
            pts,
            "--end",
            "clamped",
            "--start-tangent",
            "[1,0]",
            "--end-tangent",
            r#"["-1/2",3]"#,
            "--exact",
        ],
        None,
    );
    assert_eq!(exact_points(&out["tangents"])[3], p2(q(-1, 2), qi(3)));
}

#[test]
fn newton_and_lagrange_agree_exactly() {
    let pts = r#"[[1,0],[2,"1/2"],[0,3],[5,1]]"#;
    let nodes = r#"[0,"1/2",2,3]"#;
    let at = r#"["1/3",4,-1]"#;
    let n = run_json(
        &[
            "interpolate",
            "newton",
            "--points",
            pts,
            "--nodes",
            nodes,
            "--at",
            at,
            "--exact",
        ],
        None,
    );
    let l = run_json(
        &[
            "interpolate",
            "lagrange",
            "--points",
            pts,
            "--nodes",
            nodes,
            "--at",
            at,
            "--exact",
        ],
        None,
    );
    let a = run_json(
        &[
            "interpolate",
            "lagrange",
            "--aitken",
            "--points",
            pts,
            "--nodes",
            nodes,
            "--at",
            at,
            "--exact",
        ],
        None,
    );
    assert_eq!(n["values"], l["values"]);
    assert_eq!(n["values"], a["values"]);
    assert_eq!(n["monomial"].as_array().unwrap().len(), 4);
    // The value at 1/3 from the library's Vandermonde solution.
    let v = vandermonde(
        &[qi(0), q(1, 2), qi(2), qi(3)],
        &[
            p2(qi(1), qi(0)),
            p2(qi(2), q(1, 2)),
            p2(qi(0), qi(3)),
            p2(qi(5), qi(1)),
        ],
    )
    .unwrap();
    assert_eq!(exact_points(&n["values"])[0], v.eval(&q(1, 3)).unwrap());
}

#[test]
fn hermite_without_tangents_uses_the_parabola_estimates() {
    let out = run_json(
        &[
            "interpolate",
            "hermite",
            "--points",
            "[[0,0],[1,2],[3,3],[4,0]]",
            "--parameterisation",
            "uniform",
            "--exact",
        ],
        None,
    );
    let pts = [(0, 0), (1, 2), (3, 3), (4, 0)].map(|(x, y)| p2(qi(x), qi(y)));
    let knots = [qi(0), qi(1), qi(2), qi(3)];
    let want = estimate_tangents(&knots, &pts).unwrap();
    assert_eq!(exact_points(&out["tangents"]), want);
    let curve = hermite(&knots, &pts, &want).unwrap();
    for (piece, b) in out["pieces"].as_array().unwrap().iter().zip(curve.pieces()) {
        assert_eq!(exact_points(piece), b.control());
    }
}

#[test]
fn newton_with_derivatives_is_the_hermite_interpolant() {
    let out = run_json(
        &[
            "interpolate",
            "newton",
            "--points",
            "[[0,1],[2,0],[1,1]]",
            "--nodes",
            r#"[0,"1/2",2]"#,
            "--derivatives",
            r#"[[1,0],[0,"-3/2"],[2,2]]"#,
            "--at",
            r#"["1/3"]"#,
            "--exact",
        ],
        None,
    );
    let nodes = [qi(0), q(1, 2), qi(2)];
    let pts = [p2(qi(0), qi(1)), p2(qi(2), qi(0)), p2(qi(1), qi(1))];
    let slopes = [p2(qi(1), qi(0)), p2(qi(0), q(-3, 2)), p2(qi(2), qi(2))];
    let data: Vec<HermiteNode<Q, 2>> = (0..3)
        .map(|i| HermiteNode {
            u: nodes[i].clone(),
            values: vec![pts[i].clone(), slopes[i].clone()],
        })
        .collect();
    let want = vandermonde_hermite(&data).unwrap();
    assert_eq!(exact_points(&out["monomial"]), want.coefficients());
    assert_eq!(
        exact_points(&out["values"])[0],
        want.eval(&q(1, 3)).unwrap()
    );
    assert_eq!(out["nodes"].as_array().unwrap().len(), 6, "each node twice");
}

#[test]
fn bad_input_exits_2_with_one_error_line() {
    let cases: [(&[&str], &str); 8] = [
        (
            &[
                "interpolate",
                "spline",
                "--points",
                "[[0,0],[1,2],[3,1]]",
                "--knots",
                "[0,1,1]",
            ],
            "strictly increasing",
        ),
        (
            &[
                "interpolate",
                "hermite",
                "--points",
                "[[0,0],[1,2]]",
                "--tangents",
                "[[1,1]]",
            ],
            "tangents",
        ),
        (
            &[
                "interpolate",
                "newton",
                "--points",
                "[1,2,3]",
                "--nodes",
                "[0,1,0]",
            ],
            "nodes 0 and 2 are equal",
        ),
        (
            &[
                "interpolate",
                "lagrange",
                "--points",
                "[1,2]",
                "--nodes",
                "[0,1,2]",
            ],
            "points",
        ),
        (
            &["interpolate", "spline", "--points", "[[0,0],[1,NaN]]"],
            "NaN",
        ),
        (
            &[
                "interpolate",
                "spline",
                "--points",
                "[[0,0],[1,2]]",
                "--end",
                "bessel",
            ],
            "at least 3",
        ),
        (
            &[
                "interpolate",
                "spline",
                "--points",
                "[[0,0],[1,2],[3,1]]",
                "--end",
                "periodic",
            ],
            "first and last",
        ),
        (
            &[
                "interpolate",
                "spline",
                "--points",
                "[[0,0],[1,2]]",
                "--end",
                "clamped",
            ],
            "--start-tangent",
        ),
    ];
    for (args, needle) in cases {
        let line = assert_rejected(args, None);
        assert!(line.contains(needle), "{args:?}: {line}");
    }
}
