//! Hostile input to every reader of the command line (points as JSON and CSV, graphs, number
//! lists for `sort`, control points, knots, nodes and parameters of the curve commands): huge
//! exponents of both signs, tokens of a million characters, control characters, invalid UTF-8,
//! duplicate keys, nesting 10⁵ deep and numbers of a million digits. Each must give exit code 2,
//! nothing on stdout and one short `error:` line naming the problem, in well under a second —
//! or, where IEEE rounding makes the input valid (`1e-400` is 0), the right answer.
//!
//! The time bound (5 s for a debug binary) only catches hangs; it is no performance claim.
#![cfg(feature = "cli")]

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A generous bound that only a hang or a quadratic parse of a megabyte would exceed.
const HANG: Duration = Duration::from_secs(5);

/// The longest error line we accept: the message plus one quoted token of 40 characters.
const SHORT: usize = 300;

/// Runs the binary with raw bytes on stdin; returns (exit code, stdout, stderr) after checking
/// that it finished within [`HANG`].
fn run_bytes(args: &[&str], stdin: &[u8]) -> (i32, String, String) {
    let start = Instant::now();
    let mut child = Command::new(env!("CARGO_BIN_EXE_compgeo"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut pipe = child.stdin.take().unwrap();
    let input = stdin.to_vec();
    // A command may stop reading at its first error; a broken pipe is no failure here.
    let writer = std::thread::spawn(move || {
        let _ = pipe.write_all(&input);
    });
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    let elapsed = start.elapsed();
    assert!(elapsed < HANG, "{args:?} took {elapsed:?}");
    (
        out.status.code().expect("exited, not killed by a signal"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).expect("the error line is UTF-8"),
    )
}

/// Asserts the bad-input contract and that the line names the problem (contains every one of
/// `needles`), is short and holds no control character; returns the line.
fn rejected(args: &[&str], stdin: &[u8], needles: &[&str]) -> String {
    let (code, out, err) = run_bytes(args, stdin);
    assert_eq!(code, 2, "{args:?}: {}", &err[..err.len().min(500)]);
    assert!(
        out.is_empty(),
        "{args:?}: stdout {}",
        &out[..out.len().min(500)]
    );
    assert_eq!(
        err.lines().count(),
        1,
        "{args:?}: {}",
        &err[..err.len().min(500)]
    );
    let line = err.strip_suffix('\n').unwrap_or(&err);
    assert!(line.starts_with("error: "), "{args:?}: {line}");
    assert!(line.chars().count() < SHORT, "{args:?}: {line}");
    assert!(!line.chars().any(char::is_control), "{args:?}: {line:?}");
    for needle in needles {
        assert!(line.contains(needle), "{args:?}: {line} lacks {needle:?}");
    }
    line.to_string()
}

/// Asserts success with one JSON line; returns it.
fn accepted(args: &[&str], stdin: &[u8]) -> Value {
    let (code, out, err) = run_bytes(args, stdin);
    assert_eq!(code, 0, "{args:?}: {err}");
    assert!(err.is_empty(), "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

const STATS: &[&str] = &["stats", "-"];
const STATS_CSV: &[&str] = &["stats", "--format", "csv", "-"];
const MST: &[&str] = &["mst", "--algorithm", "kruskal", "-"];
const SORT: &[&str] = &["sort", "--algorithm", "insertion"];
const POINTS4: &str = "[[0,0],[1,2],[3,1],[4,4]]";

fn bezier(exact: bool, control: &str, t: &str) -> Vec<String> {
    let mut args: Vec<String> = ["bezier", "eval", "--control", control, "--t", t]
        .map(String::from)
        .to_vec();
    if exact {
        args.push("--exact".into());
    }
    args
}

fn spline(exact: bool, points: &str, knots: &str) -> Vec<String> {
    let mut args: Vec<String> = [
        "interpolate",
        "spline",
        "--points",
        points,
        "--knots",
        knots,
    ]
    .map(String::from)
    .to_vec();
    if exact {
        args.push("--exact".into());
    }
    args
}

fn strs(v: &[String]) -> Vec<&str> {
    v.iter().map(String::as_str).collect()
}

/// The smallest x of a `stats` bounding box.
fn min_x(stats: &Value) -> f64 {
    stats["bbox"][0][0].as_f64().unwrap()
}

// ------------------------------------------------------------------- huge exponents

#[test]
fn huge_exponents_in_points_round_as_ieee() {
    // Negative: 0, the valid answer. Positive: infinity, which validation names.
    let s = accepted(
        STATS,
        b"[[1e-9223372036854775808, 5], [1, -1e-99999999999999999999]]",
    );
    assert_eq!((s["points"].as_u64(), min_x(&s)), (Some(2), 0.0));
    let s = accepted(STATS, b"[[1e-400, 1], [2, 3]]");
    assert_eq!(min_x(&s), 0.0);
    rejected(
        STATS,
        b"[[0, 0], [1e9223372036854775808, 0]]",
        &["point 1 has a non-finite coordinate (inf)"],
    );
    rejected(
        STATS_CSV,
        b"0,0\n\n-1e99999999999999999999,1\n",
        &["point 1 has a non-finite coordinate (-inf)"],
    );
    let s = accepted(STATS_CSV, b"3e-9223372036854775808,1\n");
    assert_eq!(min_x(&s), 0.0);
}

#[test]
fn huge_exponents_in_control_points_and_parameters() {
    // The hang of issue 22, without --exact: the coordinate rounds to 0.
    let v = accepted(
        &strs(&bezier(false, "[[1e-9223372036854775808,1]]", "0.5")),
        b"",
    );
    assert_eq!(v["point"], serde_json::json!([0.0, 1.0]));
    // With --exact it is beyond the bound, and the error says where and which bound.
    rejected(
        &strs(&bezier(true, "[[1e-9223372036854775808,1]]", "0.5")),
        b"",
        &[
            "invalid control point 0, coordinate 0",
            "below 1e-400",
            "1e-9223372036854775808",
        ],
    );
    for exact in [false, true] {
        rejected(
            &strs(&bezier(
                exact,
                "[[0,0],[2,\"1e9223372036854775808\"]]",
                "0.5",
            )),
            b"",
            &[
                "invalid control point 1, coordinate 1",
                "outside the range of f64",
            ],
        );
        rejected(
            &strs(&bezier(exact, "[[0,0],[1,1]]", "7e99999999999999999999999")),
            b"",
            &["invalid t", "outside the range of f64"],
        );
    }
    let v = accepted(&strs(&bezier(false, "[[0,0],[2,2]]", "1e-9999999")), b"");
    assert_eq!(v["point"], serde_json::json!([0.0, 0.0]));
    rejected(
        &strs(&bezier(true, "[[0,0],[2,2]]", "-1e-9999999")),
        b"",
        &["invalid t", "below 1e-400"],
    );
}

#[test]
fn huge_exponents_in_knots_nodes_and_parameters() {
    // The second hang of issue 22: without --exact the knot is 0, so the knots decrease.
    let knots = r#"[0,1,2,"3e-9223372036854775808"]"#;
    rejected(
        &strs(&spline(false, POINTS4, knots)),
        b"",
        &["strictly increasing"],
    );
    rejected(
        &strs(&spline(true, POINTS4, knots)),
        b"",
        &["invalid knot 3", "below 1e-400"],
    );
    for exact in [false, true] {
        rejected(
            &strs(&spline(exact, POINTS4, "[0,1,2,3e9223372036854775808]")),
            b"",
            &["invalid knot 3", "outside the range of f64"],
        );
    }
    let lagrange = |exact: bool, at: &str| {
        let mut a = vec![
            "interpolate",
            "lagrange",
            "--points",
            "[1,2,3]",
            "--nodes",
            "[0,1,2]",
            "--at",
        ];
        a.push(if exact { "--exact" } else { "--aitken" });
        a.insert(7, at);
        a.iter().map(|s| s.to_string()).collect::<Vec<_>>()
    };
    rejected(
        &strs(&lagrange(true, "[0, \"1e-99999999999999999999\"]")),
        b"",
        &["invalid parameter 1", "below 1e-400"],
    );
    let v = accepted(
        &strs(&lagrange(false, "[\"1e-99999999999999999999\"]")),
        b"",
    );
    assert_eq!(v["values"], serde_json::json!([[1.0]]));
}

#[test]
fn huge_exponents_in_sorted_numbers_and_queries() {
    let v = accepted(
        &[SORT, &["--", "2", "1e-9223372036854775808", "-1"]].concat(),
        b"",
    );
    assert_eq!(v["sorted"], serde_json::json!([-1.0, 0.0, 2.0]));
    rejected(
        &[SORT, &["1", "1e9223372036854775808"]].concat(),
        b"",
        &["number 1 is not finite", "1e9223372036854775808"],
    );
    rejected(
        &["nearest", "--query", "1e9223372036854775808,0", "-"],
        b"[[0, 0]]",
        &["query"],
    );
}

// ------------------------------------------------------------------- long tokens

#[test]
fn million_character_tokens_give_short_errors() {
    let a = "a".repeat(1_000_000);
    rejected(
        STATS_CSV,
        format!("1,2\n3,{a}\n").as_bytes(),
        &["line 2", "is not a number", "(1000000 characters)"],
    );
    rejected(
        STATS,
        format!("[[1, 2], [{a}, 3]]").as_bytes(),
        &["point 1: expected a number", "(1000000 characters)"],
    );
    rejected(
        STATS,
        format!("[[\"{a}\", 3]]").as_bytes(),
        &["point 0: expected a number", "(1000002 characters)"],
    );
    rejected(
        &["bezier", "eval", "--control", "-", "--t", "0"],
        format!("[[0, 0], [1, \"{a}\"]]").as_bytes(),
        &[
            "invalid control point 1, coordinate 1",
            "(1000000 characters)",
        ],
    );
    rejected(
        MST,
        format!("{{\"vertices\": 1, \"edges\": [], \"{a}\": 0}}").as_bytes(),
        &["unexpected key", "(1000000 characters)"],
    );
    rejected(
        MST,
        format!("[[0, 1, \"{a}\"]]").as_bytes(),
        &[
            "edge 0: the weight must be a number",
            "(1000000 characters)",
        ],
    );
    rejected(
        SORT,
        format!("3 {a} 1").as_bytes(),
        &["number 1", "is not a number", "(1000000 characters)"],
    );
    // An argument is at most 128 KiB on Linux: a tenth of the size there.
    let knots = format!("[0,1,2,\"{}\"]", "y".repeat(100_000));
    rejected(
        &strs(&spline(false, POINTS4, &knots)),
        b"",
        &["invalid knot 3", "(100000 characters)"],
    );
}

// ------------------------------------------------------------------- control characters

#[test]
fn control_characters_are_escaped_in_errors() {
    rejected(
        STATS_CSV,
        b"1,2\n3,\x1b[31mred\n",
        &["line 2", "\"\\u{1b}[31mred\" is not a number"],
    );
    rejected(STATS, b"[[1, \x07]]", &["point 0", "\"\\u{7}\""]);
    rejected(
        STATS,
        "[[1, 2], [\u{202e}3, 4]]".as_bytes(),
        &["point 1", "\\u{202e}"],
    );
    rejected(
        MST,
        b"{\"vertices\": 1, \"edges\": [], \"\\u001b]0;pwned\\u0007\": 0}",
        &["unexpected key \"\\u{1b}]0;pwned\\u{7}\""],
    );
    rejected(
        &["bezier", "eval", "--control", "-", "--t", "0"],
        b"[[0, \"1\x00\"]]",
        &["invalid control point 0, coordinate 1", "\"1\\0\""],
    );
    rejected(
        &strs(&spline(true, POINTS4, "[0,1,\"\u{1b}[2J\",3]")),
        b"",
        &["invalid knot 2", "\"\\u{1b}[2J\""],
    );
    rejected(SORT, b"1 \x1b[2J", &["number 1", "\\u{1b}"]);
}

// ------------------------------------------------------------------- invalid UTF-8

#[test]
fn invalid_utf8_reports_the_byte_offset() {
    rejected(
        STATS,
        b"[[1, 2], [3, \xff]]",
        &["cannot read stdin: invalid UTF-8 at byte 13"],
    );
    rejected(
        STATS_CSV,
        b"1,2\n\xc3\x28,1\n",
        &["invalid UTF-8 at byte 4"],
    );
    let graph = br#"{"vertices": 2, "edges": [[0, 1, 1]]}"#;
    let offset = format!("invalid UTF-8 at byte {}", graph.len());
    rejected(MST, &[&graph[..], b"\xfe"].concat(), &[&offset]);
    rejected(
        &["bezier", "eval", "--control", "-", "--t", "0"],
        b"[[0, 1], [\xed\xa0\x80, 2]]",
        &["invalid UTF-8 at byte 10"],
    );
    rejected(SORT, b"1 2 \xc0\xaf", &["invalid UTF-8 at byte 4"]);
}

// ------------------------------------------------------------------- duplicate keys

#[test]
fn duplicate_keys_are_rejected() {
    rejected(
        MST,
        br#"{"vertices": 3, "vertices": 4, "edges": []}"#,
        &["line 1, column 26", "duplicate key \"vertices\""],
    );
    rejected(
        &["colour", "--algorithm", "dsatur", "-"],
        br#"{"edges": [], "vertices": 2, "edges": [[0, 1]]}"#,
        &["duplicate key \"edges\""],
    );
    // The same key, escaped differently.
    rejected(
        &["bfs", "--start", "0", "-"],
        br#"{"vertices": 2, "vertic\u0065s": 2, "edges": []}"#,
        &["duplicate key \"vertices\""],
    );
}

#[test]
fn a_bare_weighted_edge_list_is_a_graph() {
    // As the help text offers: the vertices are 0 to the largest id.
    let v = accepted(MST, b"[[0, 1, 2.5], [1, 2, 1], [0, 2, 3], [3, 4, 0.5]]");
    assert_eq!(v["weight"], 4.0);
    assert_eq!(v["components"], 2);
    let one = accepted(MST, b"[[0, 1, 1]]");
    assert_eq!(one["edges"], serde_json::json!([[0, 1, 1.0]]));
    let (_, out, _) = run_bytes(&["mst", "--help"], b"");
    assert!(out.contains("[[u, v, w], ...]"), "{out}");
    rejected(MST, b"[[0, 1, 1], [1, 2]]", &["edge 1 has no weight"]);
}

// ------------------------------------------------------------------- deep nesting

#[test]
fn nesting_a_hundred_thousand_deep_does_not_overflow_the_stack() {
    let deep = |n: usize| format!("{}{}", "[".repeat(n), "]".repeat(n));
    let d = deep(100_000);
    rejected(
        STATS,
        d.as_bytes(),
        &["line 1, column 3", "point 0: expected a number"],
    );
    rejected(STATS_CSV, d.as_bytes(), &["line 1", "expected 2 fields"]);
    rejected(MST, d.as_bytes(), &["recursion limit exceeded"]);
    rejected(
        &["bezier", "eval", "--control", "-", "--t", "0"],
        d.as_bytes(),
        &["column 3", "expected a number, a string or a point"],
    );
    rejected(SORT, d.as_bytes(), &["number 0", "is not a number"]);
    // Within the 128 KiB an argument may have.
    rejected(
        &strs(&spline(false, POINTS4, &deep(60_000))),
        b"",
        &["column 3", "expected a number, a string or a point"],
    );
}

// ------------------------------------------------------------------- a million digits

#[test]
fn million_digit_numbers_round_or_are_refused_at_once() {
    let ones = "1".repeat(1_000_000);
    rejected(
        STATS,
        format!("[[0, 0], [{ones}, 0]]").as_bytes(),
        &["point 1 has a non-finite coordinate (inf)"],
    );
    rejected(
        STATS_CSV,
        format!("{ones},0\n").as_bytes(),
        &["point 0 has a non-finite coordinate (inf)"],
    );
    // A million zeros and an exponent of seven digits that cancel: exactly 1, which
    // `str::parse` gets wrong (0 and infinity).
    let one = format!("0.{}1e1000001", "0".repeat(1_000_000));
    let s = accepted(STATS, format!("[[{one}, 2]]").as_bytes());
    assert_eq!(min_x(&s), 1.0);
    let one = format!("1{}e-1000000", "0".repeat(1_000_000));
    let s = accepted(STATS_CSV, format!("{one},2\n").as_bytes());
    assert_eq!(min_x(&s), 1.0);
    let v = accepted(
        &["bezier", "eval", "--control", "-", "--t", "0", "--exact"],
        format!("[[\"{one}\", 2]]").as_bytes(),
    );
    assert_eq!(v["point"], serde_json::json!(["1", "2"]));
    // Exactly, a million significant digits break the bound; as f64 they round.
    let digits = format!("0.{}", "3".repeat(1_000_000));
    rejected(
        &["bezier", "eval", "--control", "-", "--t", "0", "--exact"],
        format!("[[0, \"{digits}\"]]").as_bytes(),
        &[
            "invalid control point 0, coordinate 1",
            "at most 1000 significant digits; this one has 1000000",
        ],
    );
    let v = accepted(
        &["bezier", "eval", "--control", "-", "--t", "0"],
        format!("[[0, {digits}]]").as_bytes(),
    );
    assert_eq!(v["point"], serde_json::json!([0.0, 1.0 / 3.0]));
    rejected(
        &["bezier", "eval", "--control", "-", "--t", "0"],
        format!("[[{ones}, 0]]").as_bytes(),
        &[
            "invalid control point 0, coordinate 0",
            "outside the range of f64",
        ],
    );
    rejected(
        MST,
        format!("[[0, 1, {ones}]]").as_bytes(),
        &["number out of range"],
    );
    rejected(SORT, ones.as_bytes(), &["number 0 is not finite"]);
}

// ------------------------------------------------------------------- fuzz findings

/// The readers' findings of the fuzzing (`tests/fixtures/fuzz/<reader>/`), each by the command
/// of its report: a byte-order mark before a syntax error panicked (exit 101); a CSV field and
/// a graph key were echoed with raw `\r` and `\r\n`; a decimal with 2001 zeros and `e-2001`
/// (the value 1) and `1e-2001` were refused as outside the range of f64.
#[test]
fn the_readers_fuzz_findings_stay_fixed() {
    rejected(
        &strs(&bezier(false, "\u{feff} z", "0.5")),
        b"",
        &["invalid JSON at line 1, column 2: expected '['"],
    );
    rejected(
        STATS_CSV,
        b"1,-\r0",
        &["line 1", "\"-\\r0\" is not a number"],
    );
    rejected(
        MST,
        br#"{"vertices": 1, "edges": [], "a\r\nb": 0}"#,
        &["unexpected key \"a\\r\\nb\""],
    );
    let one = format!("[[\"1{}e-2001\", 2]]", "0".repeat(2001));
    let v = accepted(&strs(&bezier(false, &one, "0.5")), b"");
    assert_eq!(v["point"], serde_json::json!([1.0, 2.0]));
    let v = accepted(&strs(&bezier(true, &one, "0.5")), b"");
    assert_eq!(v["point"], serde_json::json!(["1", "2"]));
    // Tiny: 0 as IEEE rounds it in f64; refused by the named bound with --exact.
    let tiny = "[[\"1e-2001\", 2]]";
    let v = accepted(&strs(&bezier(false, tiny, "0.5")), b"");
    assert_eq!(v["point"], serde_json::json!([0.0, 2.0]));
    rejected(
        &strs(&bezier(true, tiny, "0.5")),
        b"",
        &["control point 0, coordinate 0", "below 1e-400"],
    );
}
