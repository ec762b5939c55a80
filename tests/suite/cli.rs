//! The `compgeo` binary against its command-line contract: generated data round-trips
//! exactly through the readers, and every kind of bad input exits with code 2, one
//! `error:` line on stderr and nothing on stdout.
#![cfg(feature = "cli")]

use compgeo::gen::{self, GraphKind, PointKind, SequenceKind};
use compgeo::geometry::Point2;
use serde_json::Value;
use std::collections::HashSet;
use std::path::PathBuf;

use crate::common::{assert_rejected, run, run_json};

/// A file in Cargo's per-test scratch directory.
fn temp_file(name: &str, contents: &str) -> PathBuf {
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-{name}"));
    std::fs::write(&path, contents).unwrap();
    path
}

fn points_of(v: &Value) -> Vec<Point2> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let p = p.as_array().unwrap();
            assert_eq!(p.len(), 2);
            Point2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap())
        })
        .collect()
}

fn bits(pts: &[Point2]) -> Vec<(u64, u64)> {
    pts.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect()
}

/// The stats oracle: distinct points by value (so -0.0 == 0.0) and a min/max fold.
fn expected_stats(pts: &[Point2]) -> (usize, Option<[[f64; 2]; 2]>) {
    let normal = |v: f64| if v == 0.0 { 0u64 } else { v.to_bits() };
    let distinct: HashSet<(u64, u64)> = pts.iter().map(|p| (normal(p.x), normal(p.y))).collect();
    let bbox = (!pts.is_empty()).then(|| {
        let f =
            |g: fn(f64, f64) -> f64, c: fn(&Point2) -> f64| pts.iter().map(c).fold(c(&pts[0]), g);
        [
            [f(f64::min, |p| p.x), f(f64::min, |p| p.y)],
            [f(f64::max, |p| p.x), f(f64::max, |p| p.y)],
        ]
    });
    (distinct.len(), bbox)
}

fn check_stats(stats: &Value, pts: &[Point2]) {
    let (distinct, bbox) = expected_stats(pts);
    assert_eq!(stats["points"].as_u64().unwrap() as usize, pts.len());
    assert_eq!(stats["distinct"].as_u64().unwrap() as usize, distinct);
    match bbox {
        None => assert!(stats["bbox"].is_null()),
        Some(b) => {
            let got: Vec<f64> = stats["bbox"]
                .as_array()
                .unwrap()
                .iter()
                .flat_map(|c| c.as_array().unwrap().iter().map(|v| v.as_f64().unwrap()))
                .collect();
            // Values compare equal (a signed zero may come from either point).
            assert_eq!(got, vec![b[0][0], b[0][1], b[1][0], b[1][1]]);
        }
    }
}

fn to_csv(pts: &[Point2]) -> String {
    let mut s = String::from("x,y\n");
    for p in pts {
        // `{:e}` is Rust's shortest round-trip form in scientific notation.
        s.push_str(&format!("{:e},{:e}\n", p.x, p.y));
    }
    s
}

// ---------------------------------------------------------------- help and version

#[test]
fn help_lists_the_commands_and_version_prints_it() {
    let (code, out, _) = run(&["--help"], None);
    assert_eq!(code, 0);
    assert!(out.contains("gen") && out.contains("stats"), "{out}");
    let (code, out, _) = run(&["gen", "points", "--help"], None);
    assert_eq!(code, 0);
    assert!(
        PointKind::ALL.iter().all(|k| out.contains(k.name())),
        "{out}"
    );
    let (code, out, _) = run(&["gen", "graph", "--help"], None);
    assert_eq!(code, 0);
    assert!(
        GraphKind::ALL.iter().all(|k| out.contains(k.name())),
        "{out}"
    );
    let (code, out, _) = run(&["--version"], None);
    assert_eq!(code, 0);
    assert_eq!(out.trim(), format!("compgeo {}", env!("CARGO_PKG_VERSION")));
}

// ---------------------------------------------------------------- round trips

#[test]
fn generated_points_are_the_library_points_bit_for_bit() {
    for kind in PointKind::ALL {
        let v = run_json(
            &[
                "gen",
                "points",
                "--kind",
                kind.name(),
                "--n",
                "57",
                "--seed",
                "11",
            ],
            None,
        );
        let expected = gen::points(kind, 57, 11).unwrap();
        assert_eq!(bits(&points_of(&v)), bits(&expected), "{kind}");
    }
}

#[test]
fn gen_then_stats_through_files_and_stdin_in_both_formats() {
    for kind in [
        PointKind::UniformSquare,
        PointKind::NearDuplicates,
        PointKind::Huge,
        PointKind::Tiny,
        PointKind::Cocircular,
        PointKind::Grid,
    ] {
        let (code, json, _) = run(
            &[
                "gen",
                "points",
                "--kind",
                kind.name(),
                "--n",
                "300",
                "--seed",
                "5",
            ],
            None,
        );
        assert_eq!(code, 0);
        let pts = points_of(&serde_json::from_str(&json).unwrap());

        let file = temp_file(&format!("{kind}.json"), &json);
        check_stats(&run_json(&["stats", file.to_str().unwrap()], None), &pts);
        check_stats(&run_json(&["stats", "-"], Some(&json)), &pts);

        let csv = to_csv(&pts);
        let file = temp_file(&format!("{kind}.csv"), &csv);
        check_stats(&run_json(&["stats", file.to_str().unwrap()], None), &pts);
        check_stats(
            &run_json(&["stats", "--format", "csv", "-"], Some(&csv)),
            &pts,
        );
        // An explicit format overrides the extension.
        let odd = temp_file(&format!("{kind}.data"), &csv);
        check_stats(
            &run_json(&["stats", "--format", "csv", odd.to_str().unwrap()], None),
            &pts,
        );
    }
}

#[test]
fn stats_counts_duplicates_and_signed_zeros_once() {
    let text = "[[0, 0], [-0.0, 0], [1, 2], [1, 2], [0, -0.0], [1, 2.0000000000000004]]";
    let v = run_json(&["stats", "-"], Some(text));
    assert_eq!(v["points"], 6);
    assert_eq!(v["distinct"], 3);
    let v = run_json(&["stats", "-"], Some("[]"));
    assert_eq!(
        v,
        serde_json::json!({"points": 0, "distinct": 0, "bbox": null})
    );
    let v = run_json(&["stats", "--format", "csv", "-"], Some("\n\n"));
    assert_eq!(v["points"], 0);
}

#[test]
fn extreme_finite_values_are_accepted_with_exact_stats() {
    let json = "[[1e300, -1e300], [1e-300, 5e-324], [-1e300, 1e300], [5e-324, -5e-324]]";
    let pts = [
        Point2::new(1e300, -1e300),
        Point2::new(1e-300, 5e-324),
        Point2::new(-1e300, 1e300),
        Point2::new(5e-324, -5e-324),
    ];
    let file = temp_file("extremes.json", json);
    let v = run_json(&["stats", file.to_str().unwrap()], None);
    check_stats(&v, &pts);
    assert_eq!(
        v["bbox"],
        serde_json::json!([[-1e300, -1e300], [1e300, 1e300]])
    );
    let csv = "1e300,-1e300\n1e-300, 5e-324\n-1e300,1e300\n5e-324,-5e-324\n";
    let file = temp_file("extremes.csv", csv);
    check_stats(&run_json(&["stats", file.to_str().unwrap()], None), &pts);
    let tiny = run_json(
        &["stats", "-"],
        Some("[[5e-324, 5e-324], [1e-300, 1e-300]]"),
    );
    assert_eq!(tiny["bbox"][0][0].as_f64().unwrap().to_bits(), 1);
}

#[test]
fn generated_graphs_parse_with_the_documented_counts() {
    for (kind, n, m, vertices, edges) in [
        (GraphKind::Gnm, 40, Some(100), 40, 100),
        (GraphKind::Complete, 9, None, 9, 36),
        (GraphKind::Cycle, 7, None, 7, 7),
        (GraphKind::Tree, 25, None, 25, 24),
        (GraphKind::Petersen, 10, None, 10, 15),
        (GraphKind::Mycielski, 4, None, 11, 20),
        (GraphKind::Queen, 4, None, 16, 76),
        (GraphKind::Crown, 5, None, 10, 20),
        (GraphKind::Grid, 9, None, 9, 12),
    ] {
        let n_text = n.to_string();
        let m_text = m.map(|m: usize| m.to_string());
        let mut args = vec!["gen", "graph", "--kind", kind.name(), "--n", &n_text];
        if let Some(m) = &m_text {
            args.extend(["--m", m]);
        }
        let v = run_json(&args, None);
        assert_eq!(v["vertices"], vertices, "{kind}");
        let list = v["edges"].as_array().unwrap();
        assert_eq!(list.len(), edges, "{kind}");
        let library = gen::graph(kind, n, m.unwrap_or(0), 0).unwrap();
        let printed: Vec<[usize; 2]> = list
            .iter()
            .map(|e| {
                let e = e.as_array().unwrap();
                assert_eq!(e.len(), 2);
                [
                    e[0].as_u64().unwrap() as usize,
                    e[1].as_u64().unwrap() as usize,
                ]
            })
            .collect();
        assert_eq!(printed, library.edges, "{kind}");

        args.push("--weighted");
        let v = run_json(&args, None);
        let list = v["edges"].as_array().unwrap();
        assert_eq!(list.len(), edges);
        let weighted = gen::with_random_weights(library, 0);
        for (e, w) in list.iter().zip(weighted.weights.unwrap()) {
            let e = e.as_array().unwrap();
            assert_eq!(e.len(), 3);
            assert_eq!(e[2].as_f64().unwrap().to_bits(), w.to_bits(), "{kind}");
        }
    }
}

#[test]
fn generated_sequences_are_the_library_sequences() {
    for kind in SequenceKind::ALL {
        let v = run_json(
            &[
                "gen",
                "sequence",
                "--kind",
                kind.name(),
                "--n",
                "200",
                "--seed",
                "3",
            ],
            None,
        );
        let printed: Vec<i64> = serde_json::from_value(v).unwrap();
        assert_eq!(printed, gen::sequence(kind, 200, 3).unwrap(), "{kind}");
    }
}

// ---------------------------------------------------------------- bad input

#[test]
fn non_finite_csv_values_name_the_point() {
    let csv = "x,y\n0,0\n1,1\n\n2,2\nnan,3\n";
    let file = temp_file("nan.csv", csv);
    let err = assert_rejected(&["stats", file.to_str().unwrap()], None);
    assert_eq!(err, "error: point 3 has a non-finite coordinate (NaN)");
    let err = assert_rejected(&["stats", "--format", "csv", "-"], Some("0,0\n1, inf\n"));
    assert_eq!(err, "error: point 1 has a non-finite coordinate (inf)");
    let err = assert_rejected(&["stats", "--format", "csv", "-"], Some("-infinity,0\n"));
    assert_eq!(err, "error: point 0 has a non-finite coordinate (-inf)");
}

#[test]
fn non_finite_and_overflowing_json_literals_name_the_point() {
    for (json, expected) in [
        (
            "[[0, 0], [NaN, 1]]",
            "error: point 1 has a non-finite coordinate (NaN)",
        ),
        (
            "[[0, 0], [1, 1], [2, Infinity]]",
            "error: point 2 has a non-finite coordinate (inf)",
        ),
        (
            "[[-Infinity, 0]]",
            "error: point 0 has a non-finite coordinate (-inf)",
        ),
        (
            "[[0, 0], [1e999, 0]]",
            "error: point 1 has a non-finite coordinate (inf)",
        ),
        (
            "[[0, 0], [0, -1e400]]",
            "error: point 1 has a non-finite coordinate (-inf)",
        ),
    ] {
        assert_eq!(
            assert_rejected(&["stats", "-"], Some(json)),
            expected,
            "{json}"
        );
    }
}

#[test]
fn malformed_input_is_rejected_with_its_location() {
    for (args, stdin, needle) in [
        (vec!["stats", "-"], "[[1, 2], [3, 4]", "line 1, column 16"),
        (
            vec!["stats", "-"],
            "[[1, 2],\n [3, 4] [5, 6]]",
            "line 2, column 9",
        ),
        (
            vec!["stats", "-"],
            "{\"x\": 1}",
            "expected a JSON array of points",
        ),
        (
            vec!["stats", "-"],
            "[[1, \"2\"]]",
            "point 0: expected a number",
        ),
        (vec!["stats", "-"], "", "found the end of input"),
        (
            vec!["stats", "--format", "csv", "-"],
            "1,2\n3,4,5\n",
            "line 2",
        ),
        (
            vec!["stats", "--format", "csv", "-"],
            "1,2\n\n3;4\n",
            "line 3",
        ),
        (
            vec!["stats", "--format", "csv", "-"],
            "1,2\n3,four\n",
            "\"four\" is not a number",
        ),
        (
            vec!["stats", "--format", "csv", "-"],
            "lon,lat\n1,2\n",
            "line 1",
        ),
    ] {
        let err = assert_rejected(&args, Some(stdin));
        assert!(err.contains(needle), "{stdin:?}: {err}");
    }
}

#[test]
fn wrong_arity_names_the_point() {
    assert_eq!(
        assert_rejected(&["stats", "-"], Some("[[0, 0], [1]]")),
        "error: point 1 has 1 coordinate, expected 2 ([x, y])"
    );
    assert_eq!(
        assert_rejected(&["stats", "-"], Some("[[1, 2, 3]]")),
        "error: point 0 has 3 coordinates, expected 2 ([x, y])"
    );
}

#[test]
fn missing_files_and_unknown_formats_are_rejected() {
    let missing = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli-does-not-exist.json");
    let err = assert_rejected(&["stats", missing.to_str().unwrap()], None);
    assert!(
        err.contains("cannot read") && err.contains("cli-does-not-exist.json"),
        "{err}"
    );

    let txt = temp_file("points.txt", "[[1, 2]]");
    let err = assert_rejected(&["stats", txt.to_str().unwrap()], None);
    assert!(err.contains("--format"), "{err}");

    let err = assert_rejected(&["stats", "--format", "xml", "-"], Some("[]"));
    assert!(
        err.contains("xml") && err.contains("json") && err.contains("csv"),
        "{err}"
    );
}

#[test]
fn unknown_kinds_and_bad_arguments_are_usage_errors() {
    let err = assert_rejected(&["gen", "points", "--kind", "hexagon", "--n", "5"], None);
    assert!(
        err.contains("hexagon") && err.contains("uniform-square"),
        "{err}"
    );
    let err = assert_rejected(&["gen", "graph", "--kind", "wheel", "--n", "5"], None);
    assert!(err.contains("wheel") && err.contains("petersen"), "{err}");
    let err = assert_rejected(&["gen", "sequence", "--kind", "shuffled", "--n", "5"], None);
    assert!(err.contains("few-distinct"), "{err}");
    assert_rejected(&["gen", "points", "--kind", "grid"], None);
    assert_rejected(&["gen", "points", "--kind", "grid", "--n", "-3"], None);
    assert_rejected(&["frobnicate"], None);

    let err = assert_rejected(&["gen", "graph", "--kind", "gnm", "--n", "5"], None);
    assert!(err.contains("--m"), "{err}");
    let err = assert_rejected(
        &["gen", "graph", "--kind", "tree", "--n", "5", "--m", "2"],
        None,
    );
    assert!(err.contains("--m"), "{err}");
    let err = assert_rejected(
        &["gen", "graph", "--kind", "gnm", "--n", "5", "--m", "11"],
        None,
    );
    assert!(err.contains("at most 10"), "{err}");
    let err = assert_rejected(&["gen", "graph", "--kind", "petersen", "--n", "12"], None);
    assert!(err.contains("10"), "{err}");
    let err = assert_rejected(
        &[
            "gen",
            "sequence",
            "--kind",
            "random",
            "--n",
            "10000000000000",
        ],
        None,
    );
    assert!(err.contains(&gen::MAX_KEYS.to_string()), "{err}");
    let err = assert_rejected(
        &["gen", "points", "--kind", "cocircular", "--n", "400000"],
        None,
    );
    assert!(err.contains(&gen::MAX_COCIRCULAR.to_string()), "{err}");
}

#[test]
fn sort_trace_prints_the_seed_bubble_table() {
    let (code, out, err) = run(
        &[
            "sort",
            "--algorithm",
            "bubble",
            "--trace",
            "7",
            "3",
            "5",
            "1",
        ],
        None,
    );
    assert_eq!(code, 0, "{err}");
    // The rows of [RD, §2.1] (bubble sort of {7, 3, 5, 1}): after each comparison the
    // compared pair, after each pass the whole list.
    let seed_rows = [
        "7 3 5 1", "3 7", "5 7", "1 7", "3 5 1 7", "3 5", "1 5", "3 1 5 7", "1 3", "1 3 5 7",
        "1 3 5 7",
    ];
    let rows: Vec<&str> = out.lines().skip(1).take(seed_rows.len()).collect();
    for (row, expected) in rows.iter().zip(seed_rows) {
        assert!(
            row.ends_with(expected),
            "{row:?} should end with {expected:?}"
        );
    }
    assert!(out.contains("Comparisons: 6"), "{out}");
}

#[test]
fn sort_prints_the_sorted_keys_and_counts() {
    let keys = gen::sequence(SequenceKind::Random, 40, 5).unwrap();
    let args: Vec<String> = keys.iter().map(i64::to_string).collect();
    for algorithm in [
        "bubble",
        "selection",
        "insertion",
        "course-insertion",
        "binary-insertion",
        "course-binary-insertion",
        "merge",
        "heap",
        "quick",
    ] {
        let mut cmd = vec!["sort", "--algorithm", algorithm];
        cmd.extend(args.iter().map(String::as_str));
        let v = run_json(&cmd, None);
        let sorted: Vec<i64> = serde_json::from_value(v["sorted"].clone()).unwrap();
        let mut expected = keys.clone();
        expected.sort();
        assert_eq!(sorted, expected, "{algorithm}");
        let comparisons = v["counts"]["comparisons"].as_u64().unwrap();
        if matches!(algorithm, "bubble" | "selection") {
            assert_eq!(comparisons, 40 * 39 / 2, "{algorithm}");
        } else {
            assert!(
                comparisons > 0 && comparisons <= 40 * 39 / 2,
                "{algorithm}: {comparisons}"
            );
        }
    }
    // Floats from stdin, as a JSON array, including extremes.
    let v = run_json(
        &["sort", "-a", "merge"],
        Some("[1e300, -5e-324, 0.5, -1e-300]"),
    );
    let sorted: Vec<f64> = serde_json::from_value(v["sorted"].clone()).unwrap();
    assert_eq!(sorted, [-1e-300, -5e-324, 0.5, 1e300]);
}

#[test]
fn sort_rejects_bad_numbers_and_names_them() {
    let err = assert_rejected(&["sort", "-a", "quick", "3", "oops", "1"], None);
    assert!(err.contains("number 1") && err.contains("oops"), "{err}");
    let err = assert_rejected(&["sort", "-a", "quick"], Some("1 2 inf"));
    assert!(
        err.contains("number 2") && err.contains("not finite"),
        "{err}"
    );
    let err = assert_rejected(&["sort", "-a", "bubble", "--trace", "1.5", "2"], None);
    assert!(err.contains("--trace"), "{err}");
    let err = assert_rejected(&["sort", "-a", "shell", "1"], None);
    assert!(
        err.contains("shell") && err.contains("binary-insertion"),
        "{err}"
    );
}

/// The README's tour of the command line, run line by line as a newcomer would (in a scratch
/// directory, files written by `>` kept for the next lines): every command exits with 0 and,
/// but for the step tables and the help, prints one line of JSON. The report line is left
/// out here (a debug build takes minutes over the sorts); `complexity.rs` runs the report.
#[test]
fn the_readme_tour_runs() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let tour = readme
        .split("```sh\n")
        .nth(2)
        .and_then(|block| block.split("```").next())
        .expect("the README has the tour block");
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("readme-tour");
    std::fs::create_dir_all(&dir).unwrap();
    let mut ran = 0;
    for line in tour.lines() {
        let command = line.split(" #").next().unwrap().trim();
        let command = command
            .strip_prefix("cargo run --release -- ")
            .unwrap_or_else(|| panic!("a tour line runs the binary: {line}"));
        if command.starts_with("report") {
            continue;
        }
        let (command, target) = match command.split_once(" > ") {
            Some((c, file)) => (c, Some(file.trim())),
            None => (command, None),
        };
        // Words, with '...' quoting as the shell reads it.
        let mut words = Vec::new();
        let mut rest = command;
        while let Some(start) = rest.find(|c: char| !c.is_whitespace()) {
            rest = &rest[start..];
            let (word, tail) = match rest.strip_prefix('\'') {
                Some(quoted) => quoted.split_once('\'').unwrap(),
                None => rest.split_once(' ').unwrap_or((rest, "")),
            };
            words.push(word.to_string());
            rest = tail;
        }
        let out = assert_cmd::cargo::cargo_bin_cmd!("compgeo")
            .args(&words)
            .current_dir(&dir)
            .output()
            .unwrap();
        let stdout = String::from_utf8(out.stdout).unwrap();
        assert!(
            out.status.success(),
            "{line}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        if let Some(file) = target {
            std::fs::write(dir.join(file), &stdout).unwrap();
        }
        let dimacs = words
            .windows(2)
            .any(|w| w[0] == "--format" && w[1] == "dimacs")
            && words[0] == "gen";
        if dimacs {
            compgeo::graph::read_dimacs(&stdout).unwrap_or_else(|e| panic!("{line}: {e}"));
        } else if !words.iter().any(|w| w == "--trace" || w == "--help") {
            assert_eq!(stdout.lines().count(), 1, "{line}: one line of JSON");
            serde_json::from_str::<Value>(&stdout).unwrap_or_else(|e| panic!("{line}: {e}"));
        }
        ran += 1;
    }
    assert!(ran >= 15, "{ran} tour lines ran");
}
