//! The `compgeo subdivide` command against the library: the printed polygons, limit points
//! and masks are the library's, exactly; bad parameters exit with code 2 and one `error:`
//! line that names them.
#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run_json};
use crate::spline_common::{json_list, json_points, q, qi, Q};
use compgeo::spline::subdivision::{four_point, lane_riesenfeld, limit_points, Mask, Topology};
use compgeo::spline::Point;

const POLYGON: &str = r#"[[0, 0], [4, 1], ["7/2", 5], [-1, 3], [0, "1/3"]]"#;

fn polygon() -> Vec<Point<Q, 2>> {
    [
        (qi(0), qi(0)),
        (qi(4), qi(1)),
        (q(7, 2), qi(5)),
        (qi(-1), qi(3)),
        (qi(0), q(1, 3)),
    ]
    .map(|(x, y)| Point::new([x, y]))
    .to_vec()
}

#[test]
fn lane_riesenfeld_and_chaikin_print_the_library_results() {
    for (scheme, degree, closed, rounds) in [
        ("lane-riesenfeld", 3, false, 2),
        ("lane-riesenfeld", 4, true, 3),
        ("lane-riesenfeld", 1, true, 1),
        ("chaikin", 2, false, 3),
        ("chaikin", 2, true, 0),
    ] {
        let rounds_text = rounds.to_string();
        let degree_text = degree.to_string();
        let mut args = vec![
            "subdivide",
            "--scheme",
            scheme,
            "--points",
            POLYGON,
            "--rounds",
            &rounds_text,
            "--exact",
        ];
        if scheme == "lane-riesenfeld" {
            args.extend(["--degree", &degree_text]);
        }
        if closed {
            args.push("--closed");
        }
        let out = run_json(&args, None);
        let topology = if closed {
            Topology::Closed
        } else {
            Topology::Open
        };
        let b = lane_riesenfeld(&polygon(), degree, rounds, topology).unwrap();
        assert_eq!(json_points(&out["points"]), b, "{args:?}");
        assert_eq!(
            json_points(&out["limit"]),
            limit_points(&b, degree, topology).unwrap()
        );
        let mask = Mask::<Q>::lane_riesenfeld(degree).unwrap();
        assert_eq!(json_list(&out["mask"]["coefficients"]), mask.coefficients());
        assert_eq!(out["mask"]["start"], 0);
        assert_eq!(out["degree"], degree);
        assert_eq!(out["closed"], closed);
        assert_eq!(out["scheme"], scheme);
        assert!(out["counts"]["arithmetic_operations"].as_u64().unwrap() > 0 || rounds == 0);
    }
}

#[test]
fn four_point_prints_the_library_result_from_stdin_too() {
    for (tension, closed) in [(None, false), (Some("1/8"), true), (Some("-0.05"), false)] {
        let mut args = vec![
            "subdivide",
            "--scheme",
            "four-point",
            "--points",
            "-",
            "--rounds",
            "2",
            "--exact",
        ];
        if let Some(t) = tension {
            args.extend(["--tension", t]);
        }
        if closed {
            args.push("--closed");
        }
        let out = run_json(&args, Some(POLYGON));
        let w: Q = tension.map_or(q(1, 16), |t| match t {
            "1/8" => q(1, 8),
            _ => q(-1, 20),
        });
        let topology = if closed {
            Topology::Closed
        } else {
            Topology::Open
        };
        assert_eq!(
            json_points(&out["points"]),
            four_point(&polygon(), &w, 2, topology).unwrap()
        );
        assert_eq!(out["tension"].as_str().unwrap().parse::<Q>().unwrap(), w);
        assert_eq!(out["mask"]["start"], -3);
    }
    // In f64 the numbers print as numbers: samples of u³ map to samples at half-integers.
    let out = run_json(
        &[
            "subdivide",
            "--scheme",
            "four-point",
            "--points",
            "[0, 1, 8, 27]",
        ],
        None,
    );
    let got: Vec<f64> = out["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p[0].as_f64().unwrap())
        .collect();
    assert_eq!(got, [0.0, 0.125, 1.0, 3.375, 8.0, 15.625, 27.0]);
}

#[test]
fn bad_parameters_exit_with_code_two_and_a_named_error() {
    let cases: [(&[&str], &str); 10] = [
        (
            &["--scheme", "lane-riesenfeld", "--degree", "0"],
            "invalid degree",
        ),
        (
            &["--scheme", "four-point", "--tension", "nan"],
            "invalid tension",
        ),
        (&["--scheme", "four-point", "--tension", "1/0"], "tension"),
        (
            &["--scheme", "lane-riesenfeld", "--tension", "1/16"],
            "--tension",
        ),
        (&["--scheme", "four-point", "--degree", "3"], "--degree"),
        (
            &["--scheme", "chaikin", "--degree", "3"],
            "chaikin is degree 2",
        ),
        (
            &["--scheme", "four-point", "--rounds", "40"],
            "MAX_SUBDIVISION_POINTS",
        ),
        (
            &["--scheme", "lane-riesenfeld", "--degree", "9"],
            "at least 10",
        ),
        (&["--scheme", "bezier"], "bezier"),
        (
            &[
                "--scheme",
                "four-point",
                "--closed",
                "--points",
                "[[0, 0], [1, 1]]",
            ],
            "at least 3",
        ),
    ];
    for (extra, needle) in cases {
        let mut args = vec!["subdivide"];
        args.extend_from_slice(extra);
        if !extra.contains(&"--points") {
            args.extend(["--points", POLYGON]);
        }
        let line = assert_rejected(&args, None);
        assert!(line.contains(needle), "{args:?}: {line}");
    }
    let line = assert_rejected(
        &[
            "subdivide",
            "--scheme",
            "chaikin",
            "--points",
            "[[0, 0], [1, NaN], [2, 0]]",
        ],
        None,
    );
    assert!(line.contains("point 1"), "{line}");
}
