//! The `compgeo bspline` command against the library and the command-line contract: random
//! curves evaluated, refined and differentiated exactly as the library does in both
//! arithmetics, the de Boor net printed level by level, both knot conventions, and bad input
//! exiting with code 2 and one `error:` line that names the index and the value.
#![cfg(all(feature = "cli", feature = "exact"))]

use crate::common::{assert_rejected, run_json};
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{BSpline, Curve, CurveDerivative, KnotVector, Point};
use proptest::prelude::*;
use serde_json::Value;

fn rational(v: &Value) -> Q {
    v.as_str().unwrap().parse().unwrap()
}

fn exact_points(v: &Value) -> Vec<Point<Q, 2>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| Point::new([rational(&p[0]), rational(&p[1])]))
        .collect()
}

fn exact_list(v: &Value) -> Vec<Q> {
    v.as_array().unwrap().iter().map(rational).collect()
}

fn json_list(xs: &[Q]) -> String {
    let items: Vec<String> = xs.iter().map(|x| format!("\"{x}\"")).collect();
    format!("[{}]", items.join(","))
}

fn json_points(ps: &[Point<Q, 2>]) -> String {
    let items: Vec<String> = ps
        .iter()
        .map(|p| format!("[\"{}\",\"{}\"]", p[0], p[1]))
        .collect();
    format!("[{}]", items.join(","))
}

/// A random planar curve of degree 1 to 3 with rational control points and integer knots
/// (multiplicities up to the degree inside), and a rational parameter in its domain.
fn curve_and_parameter() -> impl Strategy<Value = (BSpline<Q, 2>, Q)> {
    (1usize..=3, 0usize..=3)
        .prop_flat_map(|(d, extra)| {
            let n = d + 1 + extra;
            (
                Just(d),
                prop::collection::vec((-20i64..20, -20i64..20, 1i64..4), n),
                prop::collection::vec(0i64..3, n + d + 1),
                0i64..=64,
            )
        })
        .prop_filter_map("multiplicity at most d inside", |(d, c, gaps, at)| {
            let mut t = Vec::with_capacity(gaps.len());
            let mut x = 0;
            for g in gaps {
                x += g;
                t.push(qi(x));
            }
            let knots = KnotVector::new(d, t).ok()?;
            let (lo, hi) = knots.bounds();
            if lo == hi {
                return None;
            }
            let u = lo.clone() + (hi.clone() - lo) * q(at, 64);
            let control = c
                .into_iter()
                .map(|(x, y, den)| Point::new([q(x, den), q(y, den)]))
                .collect();
            Some((BSpline::new(control, knots).ok()?, u))
        })
}

fn curve_args(s: &BSpline<Q, 2>) -> Vec<String> {
    vec![
        "--control".into(),
        json_points(s.control()),
        "--degree".into(),
        s.degree().to_string(),
        "--knots".into(),
        json_list(s.knots().knots()),
    ]
}

fn run_op(op: &str, s: &BSpline<Q, 2>, more: &[&str], exact: bool) -> Value {
    let mut args: Vec<String> = vec!["bspline".into(), op.into()];
    args.extend(curve_args(s));
    args.extend(more.iter().map(|a| a.to_string()));
    if exact {
        args.push("--exact".into());
    }
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    run_json(&refs, None)
}

fn close(got: &Value, want: &Point<Q, 2>) {
    for j in 0..2 {
        let (a, b) = (got[j].as_f64().unwrap(), want.to_f64()[j]);
        assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} vs {b}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// eval prints the library's point exactly with --exact and to rounding without it, and
    /// its net is the library's de Boor net level by level.
    #[test]
    fn eval_prints_the_library_point_and_net((s, u) in curve_and_parameter()) {
        let ut = u.to_string();
        let out = run_op("eval", &s, &["--u", &ut, "--trace"], true);
        let want = s.eval(&u).unwrap();
        prop_assert_eq!(&exact_points(&Value::Array(vec![out["point"].clone()]))[0], &want);
        prop_assert_eq!(out["span"].as_u64().unwrap() as usize, s.knots().span(&u).unwrap());
        let net = s.de_boor_trace(&u).unwrap();
        let levels = out["trace"]["levels"].as_array().unwrap();
        prop_assert_eq!(levels.len(), net.len());
        for (got, want) in levels.iter().zip(&net) {
            prop_assert_eq!(&exact_points(got), &want.step.points);
        }
        prop_assert_eq!(out["trace"]["first"].as_u64().unwrap() as usize, net[0].step.first());
        prop_assert_eq!(
            out["trace"]["multiplicity"].as_u64().unwrap() as usize,
            net[0].step.multiplicity
        );
        let f = run_op("eval", &s, &["--u", &ut], false);
        close(&f["point"], &want);
        prop_assert!(f.get("trace").is_none());
    }

    /// insert prints the library's refined curve; derivative the library's derivative curve
    /// and value.
    #[test]
    fn insert_and_derivative_match_the_library((s, u) in curve_and_parameter()) {
        let ut = u.to_string();
        let room = s.degree() - s.knots().multiplicity(&u).min(s.degree());
        if room > 0 {
            let out = run_op("insert", &s, &["--u", &ut, "--times", &room.to_string()], true);
            let want = s.insert(&u, room).unwrap();
            prop_assert_eq!(exact_list(&out["knots"]), want.knots().knots().to_vec());
            prop_assert_eq!(exact_points(&out["control"]), want.control().to_vec());
            prop_assert_eq!(out["degree"].as_u64().unwrap() as usize, s.degree());
        }
        let out = run_op("derivative", &s, &["--u", &ut], true);
        let ds = s.derivative_curve().unwrap();
        prop_assert_eq!(exact_points(&out["control"]), ds.control().to_vec());
        prop_assert_eq!(exact_list(&out["knots"]), ds.knots().knots().to_vec());
        let p = exact_points(&Value::Array(vec![out["point"].clone()]));
        prop_assert_eq!(&p[0], &s.derivative_at(&u, 1).unwrap());
        // Every order up to the requested one, by the extended de Boor algorithm.
        let out = run_op("derivative", &s, &["--u", &ut, "--order", "3"], true);
        prop_assert_eq!(exact_points(&out["derivatives"]), s.derivatives(&u, 3).unwrap());
        let mut counts = Counts::default();
        s.derivatives_with(&u, 3, &mut counts).unwrap();
        prop_assert_eq!(out["counts"]["arithmetic_operations"].as_u64().unwrap(), counts.arithmetic_operations);
    }
}

#[test]
fn defaults_are_a_clamped_uniform_cubic_on_the_unit_interval() {
    let control = "[[0,0],[1,2],[3,2],[4,0],[6,1]]";
    let out = run_json(
        &[
            "bspline",
            "insert",
            "--control",
            control,
            "--u",
            "1/2",
            "--times",
            "0",
            "--exact",
        ],
        None,
    );
    assert_eq!(out["degree"], 3);
    assert_eq!(
        exact_list(&out["knots"]),
        [0, 0, 0, 0, 1, 2, 2, 2, 2].map(|k| q(k, 2)).to_vec()
    );
    // Fewer than four control points: degree n − 1, a Bézier curve.
    let out = run_json(
        &[
            "bspline",
            "eval",
            "--control",
            "[[0,0],[1,2],[2,0]]",
            "--u",
            "1/2",
            "--exact",
        ],
        None,
    );
    assert_eq!(out["degree"], 2);
    assert_eq!(out["point"], serde_json::json!(["1", "1"]));
    assert_eq!(out["counts"]["arithmetic_operations"], 3);
}

#[test]
fn the_lecture_notes_convention_reads_without_the_end_knots() {
    // [SPL, §12]: n + d − 1 knots; the library adds t₀ and t_{n+d}.
    let control = "[[0,0],[1,2],[3,2],[4,0]]";
    let spl = run_json(
        &[
            "bspline",
            "eval",
            "--control",
            control,
            "--degree",
            "2",
            "--knots",
            "[0,1,2,3,4]",
            "--spl",
            "--u",
            "5/2",
            "--exact",
        ],
        None,
    );
    let full = run_json(
        &[
            "bspline",
            "eval",
            "--control",
            control,
            "--degree",
            "2",
            "--knots",
            "[-1,0,1,2,3,4,5]",
            "--u",
            "5/2",
            "--exact",
        ],
        None,
    );
    assert_eq!(spl["point"], full["point"]);
    let basis = run_json(
        &[
            "bspline",
            "basis",
            "--knots",
            "[0,1,2,3,4]",
            "--spl",
            "--degree",
            "2",
            "--u",
            "5/2",
            "--exact",
        ],
        None,
    );
    let t = KnotVector::from_spl(2, &[0, 1, 2, 3, 4].map(qi)).unwrap();
    let want = t.basis(&q(5, 2)).unwrap();
    assert_eq!(exact_list(&basis["values"]), want.values().to_vec());
}

#[test]
fn basis_prints_values_and_derivatives_of_the_library() {
    let t = KnotVector::new(2, [0, 0, 0, 1, 2, 2, 2].map(qi).to_vec()).unwrap();
    let out = run_json(
        &[
            "bspline",
            "basis",
            "--knots",
            "[0,0,0,1,2,2,2]",
            "--degree",
            "2",
            "--u",
            "1/3",
            "--derivatives",
            "2",
            "--exact",
        ],
        None,
    );
    let want = t.basis_derivatives(&q(1, 3), 2).unwrap();
    assert_eq!(out["first"].as_u64().unwrap() as usize, want.first());
    assert_eq!(exact_list(&out["values"]), want.order(0).to_vec());
    let ds = out["derivatives"].as_array().unwrap();
    assert_eq!(ds.len(), 2);
    for (k, row) in ds.iter().enumerate() {
        assert_eq!(exact_list(row), want.order(k + 1).to_vec());
    }
}

#[test]
fn a_huge_derivative_order_is_the_zero_curve_at_once() {
    let out = run_json(
        &[
            "bspline",
            "derivative",
            "--control",
            "[[0],[1],[3],[4]]",
            "--order",
            "100000000000",
        ],
        None,
    );
    assert_eq!(out["degree"], 0);
    assert_eq!(out["control"], serde_json::json!([[0.0]]));
}

#[test]
fn bad_input_names_the_index_and_the_value() {
    let c = "[[0,0],[1,2],[3,3]]";
    let cases: &[(&[&str], &[&str])] = &[
        (
            &[
                "eval",
                "--control",
                c,
                "--degree",
                "2",
                "--knots",
                "[0,0,1,0.5,1,1]",
                "--u",
                "0.5",
            ],
            &["knot 3", "0.5", "knot 2"],
        ),
        (
            &[
                "eval",
                "--control",
                c,
                "--degree",
                "2",
                "--knots",
                "[0,0,0,1,1]",
                "--u",
                "0.5",
            ],
            &["at least 6", "got 5"],
        ),
        (
            &[
                "eval",
                "--control",
                c,
                "--degree",
                "1",
                "--knots",
                "[0,1,1,1,2]",
                "--u",
                "0.5",
            ],
            &["knots 1..=3", "multiplicity 3"],
        ),
        (
            &[
                "eval",
                "--control",
                c,
                "--degree",
                "1",
                "--knots",
                "[0,0,1,2,3,3]",
                "--u",
                "1",
            ],
            &["3 control points of degree 1 need 5 knots, got 6"],
        ),
        (&["eval", "--control", c, "--u", "2"], &["u", "2", "[0, 1]"]),
        (&["eval", "--control", c, "--u", "NaN"], &["u", "NaN"]),
        (
            &["eval", "--control", "[[0,0],[1,\"x\"],[3,3]]", "--u", "0"],
            &["control point 1, coordinate 1"],
        ),
        (
            &[
                "eval",
                "--control",
                c,
                "--degree",
                "2",
                "--knots",
                "[0,0,0,\"1/0\",1,1]",
                "--u",
                "0",
            ],
            &["knot 3"],
        ),
        (
            &["insert", "--control", c, "--u", "1/2", "--times", "3"],
            &["times", "multiplicity 3", "degree 2"],
        ),
        (
            &["eval", "--control", c, "--degree", "3", "--u", "0"],
            &["degree"],
        ),
        (
            &["basis", "--knots", "[]", "--degree", "1", "--u", "0"],
            &["knots", "empty"],
        ),
    ];
    for (args, words) in cases {
        let mut all = vec!["bspline"];
        all.extend_from_slice(args);
        let line = assert_rejected(&all, None);
        for w in *words {
            assert!(line.contains(w), "{all:?}: {line} lacks {w:?}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// refine, elevate, to-bezier and split print the library's curves exactly.
    #[test]
    fn refine_elevate_convert_and_split_match_the_library((s, u) in curve_and_parameter()) {
        let ut = u.to_string();
        if s.knots().multiplicity(&u) < s.degree() {
            let new = json_list(std::slice::from_ref(&u));
            let out = run_op("refine", &s, &["--new", &new], true);
            let want = s.refine(std::slice::from_ref(&u)).unwrap();
            prop_assert_eq!(exact_points(&out["control"]), want.control().to_vec());
            prop_assert_eq!(exact_list(&out["knots"]), want.knots().knots().to_vec());
            // --oslo: the same curve, the Oslo algorithm's counts.
            let oslo = run_op("refine", &s, &["--new", &new, "--oslo"], true);
            prop_assert_eq!(exact_points(&oslo["control"]), want.control().to_vec());
            let mut counts = Counts::default();
            s.oslo_with(std::slice::from_ref(&u), &mut counts).unwrap();
            let printed = oslo["counts"]["arithmetic_operations"].as_u64().unwrap();
            prop_assert_eq!(printed, counts.arithmetic_operations);
        }
        let out = run_op("elevate", &s, &[], true);
        let want = s.elevate(1).unwrap();
        prop_assert_eq!(exact_points(&out["control"]), want.control().to_vec());
        prop_assert_eq!(out["degree"].as_u64().unwrap() as usize, s.degree() + 1);
        let out = run_op("to-bezier", &s, &[], true);
        let want = s.to_bezier().unwrap();
        prop_assert_eq!(exact_list(&out["breakpoints"]), want.partition().to_vec());
        for (got, b) in out["pieces"].as_array().unwrap().iter().zip(want.pieces()) {
            prop_assert_eq!(exact_points(got), b.control().to_vec());
        }
        let (lo, hi) = s.knots().bounds();
        if &u > lo && &u < hi {
            let out = run_op("split", &s, &["--u", &ut], true);
            let (left, right) = s.split(&u).unwrap();
            prop_assert_eq!(exact_points(&out["left"]["control"]), left.control().to_vec());
            prop_assert_eq!(exact_list(&out["right"]["knots"]), right.knots().knots().to_vec());
        }
    }
}

#[test]
fn remove_interpolate_and_fit_match_the_library() {
    // Insert-then-remove on the command line gives the parabola back.
    let out = run_json(
        &[
            "bspline",
            "remove",
            "--control",
            r#"[[0,0],["1/2",1],[1,1],["3/2",1],[2,0]]"#,
            "--degree",
            "2",
            "--knots",
            r#"[0,0,0,"1/2","1/2",1,1,1]"#,
            "--u",
            "1/2",
            "--times",
            "2",
            "--exact",
        ],
        None,
    );
    assert_eq!(
        exact_points(&out["control"]),
        [(0, 0), (1, 2), (2, 0)]
            .map(|(x, y)| Point::new([qi(x), qi(y)]))
            .to_vec()
    );
    let line = assert_rejected(
        &[
            "bspline",
            "remove",
            "--control",
            "[[0,0],[1,2],[3,2],[4,0],[6,1]]",
            "--u",
            "1/2",
        ],
        None,
    );
    assert!(line.contains("0 of 1 removals succeeded"), "{line}");
    // Interpolation passes through the points; the fit equals the library's.
    let data = "[[0,0],[1,2],[3,1],[4,4],[5,0],[6,1],[7,3]]";
    let out = run_json(
        &[
            "bspline",
            "interpolate",
            "--points",
            data,
            "--parameterisation",
            "uniform",
            "--exact",
        ],
        None,
    );
    let s = BSpline::new(
        exact_points(&out["control"]),
        KnotVector::new(3, exact_list(&out["knots"])).unwrap(),
    )
    .unwrap();
    let pts = [(0, 0), (1, 2), (3, 1), (4, 4), (5, 0), (6, 1), (7, 3)]
        .map(|(x, y)| Point::new([qi(x), qi(y)]));
    for (i, p) in pts.iter().enumerate() {
        assert_eq!(&s.eval(&qi(i64::try_from(i).unwrap())).unwrap(), p);
    }
    let out = run_json(
        &[
            "bspline",
            "fit",
            "--points",
            data,
            "--control-points",
            "4",
            "--parameterisation",
            "uniform",
            "--exact",
        ],
        None,
    );
    let params: Vec<Q> = (0..7).map(qi).collect();
    let knots = KnotVector::clamped_uniform(3, 4, qi(0), qi(6)).unwrap();
    let want = BSpline::fit(&pts, &params, knots).unwrap();
    assert_eq!(exact_points(&out["control"]), want.control().to_vec());
    let line = assert_rejected(
        &[
            "bspline",
            "interpolate",
            "--points",
            "[[0,0],[0,0],[1,1],[2,2],[3,3]]",
        ],
        None,
    );
    assert!(line.contains("points 0 and 1"), "{line}");
}
