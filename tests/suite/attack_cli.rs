//! The command line attacked as a hostile user would: absurd sizes for every size argument
//! and every size read from an input, command groups without their subcommand, `report
//! --out` on paths it cannot write, unreadable inputs, and a sweep of degenerate valid inputs
//! over every command whose outputs must never contain `-0.0`. Every failure keeps the
//! contract (exit code 2, nothing on stdout, exactly one `error: ` line naming the limit,
//! value or path); every invocation is quick.
#![cfg(feature = "cli")]

use crate::common::{assert_rejected, run, TempDir};
use compgeo::limits;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Size texts no size argument accepts: 2^32 and 2^64 − 1 (beyond every limit), a number
/// beyond u64, a float and a negative number.
const ABSURD: [&str; 5] = [
    "4294967296",
    "18446744073709551615",
    "99999999999999999999999",
    "1e30",
    "-1",
];

/// [`assert_rejected`], and the line names `names` (a limit or the offending value); a hang
/// or an allocation of gigabytes would not finish in seconds.
#[track_caller]
fn assert_names(args: &[&str], stdin: Option<&str>, names: &[&str]) -> String {
    let start = Instant::now();
    let line = assert_rejected(args, stdin);
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "{args:?} took {:?}",
        start.elapsed()
    );
    assert!(
        names.iter().any(|n| line.contains(n)),
        "{args:?}: {line:?} names none of {names:?}"
    );
    line
}

/// What the error of an absurd `value` must name: the limit, or the value itself.
fn named(value: &str, limit: &'static str) -> Vec<String> {
    vec![limit.to_string(), value.to_string()]
}

fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

#[test]
fn absurd_generator_sizes_are_errors_naming_the_limit_or_value() {
    let cases: [(&[&str], &str); 3] = [
        (
            &["gen", "points", "--kind", "uniform-square", "--n"],
            "MAX_POINTS",
        ),
        (&["gen", "sequence", "--kind", "sorted", "--n"], "MAX_KEYS"),
        (&["gen", "graph", "--kind", "tree", "--n"], "MAX_VERTICES"),
    ];
    for (prefix, limit) in cases {
        for value in ABSURD {
            let args = [prefix, &[value]].concat();
            let line = assert_names(&args, None, &strs(&named(value, limit)));
            if value == "4294967296" {
                assert!(line.contains(limit), "{line}");
            }
        }
    }
    // Every graph family, by its vertex or edge count; Petersen names the value it needs.
    for kind in [
        "gnm",
        "grid",
        "complete",
        "cycle",
        "queen",
        "crown",
        "mycielski",
        "petersen",
    ] {
        for value in ABSURD {
            let mut args = vec!["gen", "graph", "--kind", kind, "--n", value];
            if kind == "gnm" {
                args.extend(["--m", "1"]);
            }
            assert_names(&args, None, &["MAX_VERTICES", "MAX_EDGES", value, "10"]);
        }
    }
    // The issue's complete graph: 268 412 865 edges, named with the limit at once.
    let line = assert_names(
        &["gen", "graph", "--kind", "complete", "--n", "23170"],
        None,
        &["MAX_EDGES"],
    );
    assert!(line.contains("268412865"), "{line}");
    for value in ABSURD {
        assert_names(
            &["gen", "graph", "--kind", "gnm", "--n", "10", "--m", value],
            None,
            &[value, "MAX_EDGES"],
        );
    }
    // Seeds are any u64; beyond it, or not an integer, is an error naming the text.
    for value in [
        "18446744073709551616",
        "99999999999999999999999",
        "1e30",
        "-1",
    ] {
        assert_names(
            &[
                "gen", "points", "--kind", "gaussian", "--n", "3", "--seed", value,
            ],
            None,
            &[value],
        );
    }
    // Zero where it is invalid.
    for (kind, says) in [
        ("cycle", "got 0"),
        ("mycielski", "at least 1"),
        ("petersen", "not 0"),
    ] {
        assert_names(&["gen", "graph", "--kind", kind, "--n", "0"], None, &[says]);
    }
    let over = (limits::MAX_COCIRCULAR + 1).to_string();
    assert_names(
        &["gen", "points", "--kind", "cocircular", "--n", &over],
        None,
        &["MAX_COCIRCULAR"],
    );
}

#[test]
fn absurd_graph_sizes_are_errors_naming_the_limit_or_value() {
    let commands: [&[&str]; 6] = [
        &["bfs", "--start", "0", "-"],
        &["dfs", "--start", "0", "-"],
        &["bfs", "--start", "0", "--trace", "-"],
        &["colour", "--algorithm", "dsatur", "-"],
        &["colour", "--algorithm", "course", "-"],
        &["mst", "--algorithm", "kruskal", "-"],
    ];
    // "vertices" is a number in the input: 20 bytes must not allocate 10^18 entries.
    for command in commands {
        for value in ["4294967296", "18446744073709551615", "1000000000000000000"] {
            let input = format!(r#"{{"vertices": {value}, "edges": []}}"#);
            let line = assert_names(command, Some(&input), &["MAX_VERTICES"]);
            assert!(line.contains(value), "{line}");
        }
        for value in ["99999999999999999999999", "1e30", "-1", "0.5"] {
            let input = format!(r#"{{"vertices": {value}, "edges": []}}"#);
            assert_names(command, Some(&input), &["vertices"]);
        }
        // An edge naming an absurd vertex.
        let input = r#"{"vertices": 3, "edges": [[0, 18446744073709551615, 1.0]]}"#;
        assert_names(command, Some(input), &["18446744073709551615"]);
    }
    let graph = r#"{"vertices": 3, "edges": [[0, 1], [1, 2]]}"#;
    for search in ["bfs", "dfs"] {
        for value in ABSURD {
            assert_names(&[search, "--start", value, "-"], Some(graph), &[value]);
        }
    }
    // A trace is for graphs a reader can follow.
    let big = format!(
        r#"{{"vertices": {}, "edges": []}}"#,
        limits::TRACE_MAX_VERTICES + 1
    );
    assert_names(
        &["dfs", "--start", "0", "--trace", "-"],
        Some(&big),
        &["TRACE_MAX_VERTICES"],
    );
}

#[test]
fn absurd_curve_sizes_are_errors_naming_the_limit_or_value() {
    let cubic = "[[0,0],[1,2],[3,2],[4,0]]";
    for exact in [false, true] {
        let mut prefix = vec!["bezier", "elevate", "--control", cubic];
        if exact {
            prefix.push("--exact");
        }
        for value in ABSURD {
            let args = [&prefix[..], &["--degree", value]].concat();
            let line = assert_names(&args, None, &strs(&named(value, "MAX_DEGREE")));
            if value == "4294967296" {
                assert!(line.contains("MAX_DEGREE = 65536"), "{line}");
            }
        }
        let over = (limits::MAX_DEGREE + 1).to_string();
        assert_names(
            &[&prefix[..], &["--degree", &over]].concat(),
            None,
            &["MAX_DEGREE"],
        );
        // Below the curve's degree is not an elevation.
        assert_names(
            &[&prefix[..], &["--degree", "0"]].concat(),
            None,
            &["degree 0"],
        );
    }
    // Derivative orders: beyond the text of a u64 or negative is an error; any order above
    // the degree is the zero curve, however large.
    for value in ["99999999999999999999999", "1e30", "-1"] {
        assert_names(
            &["bezier", "derivative", "--control", cubic, "--order", value],
            None,
            &[value],
        );
    }
    for value in ["4294967296", "18446744073709551615"] {
        let (code, out, err) = run(
            &[
                "bezier",
                "derivative",
                "--control",
                cubic,
                "--order",
                value,
                "--t",
                "0.5",
            ],
            None,
        );
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["control"], serde_json::json!([[0.0, 0.0]]));
        assert_eq!(v["point"], serde_json::json!([0.0, 0.0]));
        assert_eq!(v["degree"], 0);
    }
    // The Lagrange basis table: 4097 nodes times 4097 parameters is more than 2^24 values.
    let k = 4097;
    let nodes = format!(
        "[{}]",
        (0..k).map(|i| i.to_string()).collect::<Vec<_>>().join(",")
    );
    let points = format!(
        "[{}]",
        (0..k)
            .map(|i| format!("[{i}]"))
            .collect::<Vec<_>>()
            .join(",")
    );
    let line = assert_names(
        &[
            "interpolate",
            "lagrange",
            "--points",
            &points,
            "--nodes",
            &nodes,
            "--at",
            &nodes,
        ],
        None,
        &["MAX_BASIS_TABLE"],
    );
    assert!(line.contains(&(k * k).to_string()), "{line}");
}

#[test]
fn absurd_trace_and_seed_sizes_are_errors() {
    let long: Vec<String> = (0..=limits::TRACE_MAX_LEN).map(|i| i.to_string()).collect();
    let args: Vec<&str> = ["sort", "--algorithm", "bubble", "--trace"]
        .into_iter()
        .chain(long.iter().map(String::as_str))
        .collect();
    assert_names(&args, None, &["TRACE_MAX_LEN"]);
    for value in ["99999999999999999999999", "1e30", "-1"] {
        assert_names(
            &["report", "--seed", value, "--only", "horner"],
            None,
            &[value],
        );
    }
}

#[test]
fn command_groups_without_a_subcommand_name_their_choices() {
    let groups: [(&[&str], &str); 4] = [
        (&[], "`compgeo`; expected one of: gen, stats, report, sort,"),
        (
            &["gen"],
            "`compgeo gen`; expected one of: points, graph, sequence",
        ),
        (
            &["bezier"],
            "`compgeo bezier`; expected one of: eval, split, elevate, derivative",
        ),
        (
            &["interpolate"],
            "`compgeo interpolate`; expected one of: hermite, spline, lagrange, newton",
        ),
    ];
    for (args, expected) in groups {
        let line = assert_rejected(args, None);
        assert!(line.starts_with("error: missing subcommand for "), "{line}");
        assert!(line.contains(expected), "{args:?}: {line}");
        // The help stays on --help: stdout, exit code 0.
        let help = [args, &["--help"]].concat();
        let (code, out, err) = run(&help, None);
        assert_eq!(code, 0, "{help:?}: {err}");
        assert!(out.contains("Usage: compgeo"), "{help:?}: {out}");
        assert!(err.is_empty(), "{help:?}: {err}");
    }
}

fn text(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn report_out_is_checked_before_measuring() {
    let tmp = TempDir::new("report");
    let file = tmp.path("results-file");
    std::fs::write(&file, "not a directory").unwrap();
    let under_file = file.join("report");
    let index_dir = tmp.path("index-is-a-dir");
    std::fs::create_dir_all(index_dir.join("index.html")).unwrap();
    for (out, names) in [
        (file.clone(), file.clone()),
        (under_file.clone(), under_file.clone()),
        (
            PathBuf::from("/dev/null/report"),
            PathBuf::from("/dev/null/report"),
        ),
        (index_dir.clone(), index_dir.join("index.html")),
    ] {
        // Failing before measuring is what makes this quick: the whole catalog would take
        // minutes.
        let line = assert_names(&["report", "--out", text(&out)], None, &[text(&names)]);
        assert!(line.starts_with("error: cannot write"), "{line}");
    }
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "not a directory");
    // An existing directory is written into (the smallest entry: a few sizes of a Horner
    // evaluation).
    let dir = tmp.path("existing");
    std::fs::create_dir_all(&dir).unwrap();
    let (code, out, err) = run(&["report", "--out", text(&dir), "--only", "horner"], None);
    assert_eq!(code, 0, "{err}");
    let written: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(written["algorithms"], 1);
    assert!(dir.join("index.html").is_file() && dir.join("results.json").is_file());
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|name| name.starts_with('.'))
        .collect();
    assert!(
        leftovers.is_empty(),
        "the write probe is removed: {leftovers:?}"
    );
}

#[test]
fn unreadable_inputs_name_their_path() {
    let tmp = TempDir::new("inputs");
    let missing = tmp.path("missing.json");
    let directory = tmp.path("a-directory.json");
    std::fs::create_dir_all(&directory).unwrap();
    let locked = tmp.path("locked.json");
    std::fs::write(&locked, "[[0, 0]]").unwrap();
    let mut paths = vec![missing, directory];
    // Permission bits mean nothing to root, who reads the file anyway.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o000)).unwrap();
        if std::fs::read(&locked).is_err() {
            paths.push(locked.clone());
        }
    }
    let commands: [&[&str]; 13] = [
        &["hull"],
        &["diameter"],
        &["delaunay"],
        &["voronoi"],
        &["closest-pair"],
        &["nearest", "--query", "0,0"],
        &["emst"],
        &["empty-circle"],
        &["stats"],
        &["bfs", "--start", "0"],
        &["dfs", "--start", "0"],
        &["colour", "--algorithm", "greedy"],
        &["mst", "--algorithm", "prim"],
    ];
    for path in &paths {
        for command in commands {
            let args = [command, &[text(path)]].concat();
            let line = assert_names(&args, None, &[text(path)]);
            assert!(line.contains("cannot read"), "{line}");
        }
    }
}

/// Asserts `out` has no number that is a negative zero (`-0.0`, `-0`, `-0e5`, ...), looking
/// at every number token outside JSON strings.
#[track_caller]
fn assert_no_negative_zero(args: &[&str], out: &str) {
    let bytes = out.as_bytes();
    let mut i = 0;
    let mut in_string = false;
    while i < bytes.len() {
        let c = bytes[i];
        if in_string {
            match c {
                b'\\' => i += 1,
                b'"' => in_string = false,
                _ => {}
            }
        } else if c == b'"' {
            in_string = true;
        } else if c == b'-' {
            let end = (i + 1..bytes.len())
                .find(|&j| !matches!(bytes[j], b'0'..=b'9' | b'.' | b'e' | b'E' | b'+' | b'-'))
                .unwrap_or(bytes.len());
            let token = &out[i..end];
            if let Ok(v) = token.parse::<f64>() {
                assert!(v != 0.0, "{args:?} prints {token}: {out}");
            }
            i = end;
            continue;
        }
        i += 1;
    }
}

/// Runs `args` on `stdin`: a success must print no negative zero, a failure must keep the
/// contract.
fn sweep(args: &[&str], stdin: Option<&str>) -> bool {
    let (code, out, err) = run(args, stdin);
    if code == 0 {
        assert_no_negative_zero(args, &out);
        return true;
    }
    assert_eq!(code, 2, "{args:?}: {err}");
    assert!(out.is_empty(), "{args:?}: stdout must be empty, got {out}");
    assert_eq!(err.lines().count(), 1, "{args:?}: {err:?}");
    assert!(err.starts_with("error: "), "{args:?}: {err}");
    false
}

#[test]
fn the_negative_zero_detector_finds_what_it_must() {
    let found = |s: &str| std::panic::catch_unwind(|| assert_no_negative_zero(&[], s)).is_err();
    for bad in ["[-0.0]", "{\"a\":-0}", "[1,-0e5]", "-0.000", "x -0.0\n"] {
        assert!(found(bad), "{bad}");
    }
    for good in [
        "[0.0]",
        "[-0.5]",
        "[\"-0.0\"]",
        "[-1e-300]",
        "[-10]",
        "Q: 0 -> 1",
    ] {
        assert!(!found(good), "{good}");
    }
}

const DEGENERATE_POINTS: [&str; 10] = [
    "[]",
    "[[0,0]]",
    "[[-0.0,-0.0]]",
    "[[1,1],[1,1]]",
    "[[-0.0,0],[0,-0.0]]",
    "[[0,0],[0,0],[0,0]]",
    "[[0,0],[1,0],[2,0]]",
    "[[-1,0],[-0.0,0],[1,0]]",
    "[[0,-1],[0,-0.0],[0,1]]",
    "[[-1,-1],[1,1],[-1,1],[1,-1],[0,0]]",
];

#[test]
fn point_commands_never_print_negative_zero() {
    let commands: [&[&str]; 21] = [
        &["hull"],
        &["hull", "--keep-collinear"],
        &["hull", "--algorithm", "graham"],
        &["hull", "--algorithm", "jarvis"],
        &["diameter"],
        &["diameter", "--algorithm", "brute-force"],
        &["delaunay"],
        &["delaunay", "--algorithm", "divide-and-conquer"],
        &["delaunay", "--algorithm", "lawson"],
        &["delaunay", "--algorithm", "fortune"],
        &["voronoi"],
        &["voronoi", "--clip", "auto"],
        &["voronoi", "--clip", "-1,-1,1,1"],
        &["closest-pair"],
        &["closest-pair", "--algorithm", "divide-and-conquer"],
        &["nearest", "--query", "0,0"],
        &["nearest", "--query", "-0.0,-0.0"],
        &["emst"],
        &["empty-circle"],
        &["stats"],
        &["stats", "--format", "json"],
    ];
    let mut successes = 0;
    for points in DEGENERATE_POINTS {
        for command in commands {
            let args = [command, &["-"]].concat();
            successes += usize::from(sweep(&args, Some(points)));
        }
    }
    // Most of these are answers (a hull of one point, the EMST of copies), not errors.
    assert!(successes > 150, "{successes}");
    // The issue's examples.
    let out = run(&["emst", "-"], Some("[[0,0]]")).1;
    assert!(out.contains("\"length\":0.0"), "{out}");
    let out = run(&["stats", "-"], Some("[[-0.0,-0.0]]")).1;
    assert!(out.contains("[[0.0,0.0],[0.0,0.0]]"), "{out}");
}

#[test]
fn graph_and_sort_commands_never_print_negative_zero() {
    let graphs = [
        r#"{"vertices": 1, "edges": []}"#,
        r#"{"vertices": 3, "edges": []}"#,
        r#"{"vertices": 2, "edges": [[0, 1, -0.0]]}"#,
        r#"{"vertices": 2, "edges": [[0, 0, -0.0], [0, 1, 0]]}"#,
        r#"{"vertices": 3, "edges": [[0, 1, -0.0], [1, 2, -0.0], [0, 2, -0.0]]}"#,
        r#"{"vertices": 2, "edges": [[0, 1]]}"#,
    ];
    let commands: [&[&str]; 10] = [
        &["bfs", "--start", "0"],
        &["dfs", "--start", "0"],
        &["bfs", "--start", "0", "--trace"],
        &["colour", "--algorithm", "course"],
        &["colour", "--algorithm", "dsatur"],
        &["colour", "--algorithm", "dsatur-tabu"],
        &["colour", "--algorithm", "smallest-last"],
        &["mst", "--algorithm", "prim"],
        &["mst", "--algorithm", "kruskal"],
        &["mst", "--algorithm", "boruvka"],
    ];
    for graph in graphs {
        for command in commands {
            sweep(&[command, &["-"]].concat(), Some(graph));
        }
    }
    let out = run(&["mst", "--algorithm", "kruskal", "-"], Some(graphs[1])).1;
    assert!(out.contains("\"weight\":0.0"), "{out}");
    for keys in ["-0.0", "0 -0.0 -0", "[-0.0, 0.0, -1e-300]", "-0"] {
        for algorithm in ["bubble", "merge", "quick"] {
            assert!(sweep(&["sort", "--algorithm", algorithm], Some(keys)));
        }
    }
}

#[test]
fn curve_commands_never_print_negative_zero() {
    let controls = [
        "[[0,0]]",
        "[[-0.0,-0.0]]",
        "[[0,0],[0,0]]",
        "[[1,-0.0],[1,-0.0]]",
        "[[-0.0]]",
    ];
    let ops: [&[&str]; 9] = [
        &["eval", "--t", "0"],
        &["eval", "--t", "-0.0"],
        &["eval", "--t", "0.5", "--algorithm", "horner"],
        &["split", "--t", "0.5"],
        &["split", "--t", "0"],
        &["elevate"],
        &["elevate", "--degree", "5"],
        &["derivative"],
        &["derivative", "--order", "3", "--t", "0.5"],
    ];
    for control in controls {
        for op in ops {
            for exact in [false, true] {
                let mut args = vec!["bezier", op[0], "--control", control];
                args.extend(&op[1..]);
                if exact {
                    args.push("--exact");
                }
                sweep(&args, None);
            }
        }
    }
    let flat = [
        "[[0,0],[0,0]]",
        "[[0,0],[0,0],[0,0]]",
        "[[-0.0,0],[0,-0.0],[-0.0,-0.0]]",
    ];
    for points in flat {
        for exact in [false, true] {
            let mut runs: Vec<Vec<&str>> = vec![
                vec!["interpolate", "hermite", "--points", points],
                vec!["interpolate", "spline", "--points", points],
                vec![
                    "interpolate",
                    "spline",
                    "--points",
                    points,
                    "--end",
                    "bessel",
                ],
                vec![
                    "interpolate",
                    "spline",
                    "--points",
                    points,
                    "--end",
                    "periodic",
                ],
                vec![
                    "interpolate",
                    "hermite",
                    "--points",
                    points,
                    "--parameterisation",
                    "chord-length",
                ],
            ];
            let nodes = if points.matches('[').count() == 3 {
                "[0,1]"
            } else {
                "[0,1,2]"
            };
            runs.push(vec![
                "interpolate",
                "lagrange",
                "--points",
                points,
                "--nodes",
                nodes,
                "--at",
                "[0,-0.0,0.5]",
            ]);
            runs.push(vec![
                "interpolate",
                "newton",
                "--points",
                points,
                "--nodes",
                nodes,
                "--at",
                "[-0.0]",
            ]);
            runs.push(vec![
                "interpolate",
                "newton",
                "--points",
                points,
                "--nodes",
                nodes,
                "--derivatives",
                points,
            ]);
            for mut args in runs {
                if exact {
                    args.push("--exact");
                }
                sweep(&args, None);
            }
        }
    }
}

#[test]
fn generators_never_print_negative_zero() {
    let kinds = [
        "uniform-square",
        "uniform-disk",
        "gaussian",
        "clustered",
        "cocircular",
        "parabola",
        "grid",
        "rotated-grid",
        "near-duplicates",
        "collinear",
        "huge",
        "tiny",
    ];
    for kind in kinds {
        for n in ["0", "1", "2", "5"] {
            assert!(sweep(
                &["gen", "points", "--kind", kind, "--n", n, "--seed", "3"],
                None
            ));
        }
    }
    let graphs: [&[&str]; 9] = [
        &["--kind", "gnm", "--n", "4", "--m", "3"],
        &["--kind", "grid", "--n", "4"],
        &["--kind", "complete", "--n", "3"],
        &["--kind", "cycle", "--n", "3"],
        &["--kind", "tree", "--n", "1"],
        &["--kind", "petersen", "--n", "10"],
        &["--kind", "mycielski", "--n", "1"],
        &["--kind", "queen", "--n", "0"],
        &["--kind", "crown", "--n", "1"],
    ];
    for graph in graphs {
        assert!(sweep(
            &[&["gen", "graph", "--weighted"], graph].concat(),
            None
        ));
    }
    for kind in ["random", "sorted", "reversed", "few-distinct"] {
        assert!(sweep(
            &["gen", "sequence", "--kind", kind, "--n", "3"],
            None
        ));
    }
}

/// `bezier eval` at parameters far outside [0, 1]: the zero quadratic at t = 1.55e231 (a
/// fuzz finding: t² overflows) is 0 by either scheme; a constant curve at 1e300, whose
/// value 1e300 both schemes lose to an overflow of terms that cancel, is named as such
/// (the evaluation overflows, use --exact) and `--exact` gives it; a point that really is
/// beyond f64 keeps the range error.
#[test]
fn bezier_eval_far_outside_the_unit_interval_answers_or_names_the_overflow() {
    let eval = |control: &str, t: &str, algorithm: &str| {
        [
            "bezier",
            "eval",
            "--control",
            control,
            "--t",
            t,
            "--algorithm",
            algorithm,
        ]
        .map(str::to_string)
    };
    let zero = "[[0,0],[0,0],[0,0]]";
    for algorithm in ["horner", "de-casteljau"] {
        let args = eval(zero, "1.55e231", algorithm);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let v = crate::common::run_json(&args, None);
        assert_eq!(v["point"], serde_json::json!([0.0, 0.0]), "{algorithm}");
    }
    let constant = "[[1e300,1],[1e300,1],[1e300,1]]";
    for algorithm in ["horner", "de-casteljau"] {
        let args = eval(constant, "1e10", algorithm);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let err = assert_rejected(&args, None);
        assert!(
            err.contains("within the range of f64")
                && err.contains("overflows")
                && err.contains("--exact"),
            "{algorithm}: {err}"
        );
        let mut exact = args.clone();
        exact.push("--exact");
        let v = crate::common::run_json(&exact, None);
        let one_e300 = format!("1{}", "0".repeat(300));
        assert_eq!(
            v["point"],
            serde_json::json!([one_e300, "1"]),
            "{algorithm}"
        );
    }
    let huge = "[[0,0],[1e300,0],[0,0]]";
    let args = eval(huge, "1e10", "horner");
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let err = assert_rejected(&args, None);
    assert!(err.contains("beyond the range of f64"), "{err}");
}
