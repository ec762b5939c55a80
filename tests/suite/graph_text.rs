//! Graphs as text: DIMACS `.col` and plain edge lists, read and written by
//! `compgeo::graph::{read_dimacs, write_dimacs, read_edge_list}` and by the command line
//! (`--format`, `.col` files, `gen graph --format dimacs`). Every malformed line is an error
//! naming its number; no text makes a reader panic.

use compgeo::gen::{graph as generate, GraphKind};
use compgeo::graph::{read_dimacs, read_edge_list, write_dimacs, EdgeList, Graph};
use compgeo::Error;
use proptest::prelude::*;

/// The line an error names, asserting it is a syntax error of `format`.
fn line_of(e: Error, format: &str) -> usize {
    match e {
        Error::Syntax {
            format: f, line, ..
        } => {
            assert_eq!(f, format);
            line
        }
        other => panic!("expected a {format} syntax error, got {other:?}"),
    }
}

#[test]
fn every_generated_family_survives_a_dimacs_round_trip() {
    for (kind, n, m) in [
        (GraphKind::Gnm, 40, 120),
        (GraphKind::Grid, 30, 0),
        (GraphKind::Complete, 9, 0),
        (GraphKind::Cycle, 7, 0),
        (GraphKind::Tree, 25, 0),
        (GraphKind::Petersen, 10, 0),
        (GraphKind::Mycielski, 5, 0),
        (GraphKind::Queen, 6, 0),
        (GraphKind::Crown, 5, 0),
    ] {
        let g = generate(kind, n, m, 3).unwrap();
        let text = write_dimacs(&g);
        assert!(text.contains(&format!("p edge {} {}\n", g.vertices, g.edges.len())));
        assert_eq!(
            text.lines().filter(|l| l.starts_with("e ")).count(),
            g.edges.len()
        );
        assert_eq!(read_dimacs(&text).unwrap(), g, "{kind}");
    }
}

#[test]
fn published_conventions_are_read() {
    // Comments anywhere, `p col`, blank lines, CRLF, a byte-order mark, and an edge listed in
    // both directions and once more: the graph merges the copies and says how many.
    let text = "\u{feff}c FILE: tiny.col\r\nc\r\np col 4 5\r\n\r\ne 1 2\r\ne 2 1\r\nc mid\r\n\
                e 2 3\r\ne 3 4\r\ne 1 2\r\n";
    let list = read_dimacs(text).unwrap();
    assert_eq!(list.vertices, 4);
    assert_eq!(list.edges, [[0, 1], [1, 0], [1, 2], [2, 3], [0, 1]]);
    let g = Graph::from_edge_list(&list).unwrap();
    assert_eq!(g.edge_count(), 3);
    assert_eq!(g.parallel_merged(), 2);
    // A graph with isolated vertices keeps them: n comes from the p line.
    let lonely = read_dimacs("p edge 5 1\ne 1 2\n").unwrap();
    assert_eq!(lonely.vertices, 5);
    assert_eq!(read_dimacs("p edge 0 0\n").unwrap().vertices, 0);
}

#[test]
fn every_malformed_dimacs_file_names_its_line() {
    let cases: [(&str, usize, &str); 16] = [
        ("p edge 3 1\ne 1 0\n", 2, "vertex 0 is not in 1..=3"),
        ("p edge 3 1\ne 4 1\n", 2, "vertex 4 is not in 1..=3"),
        ("c no header\ne 1 2\n", 2, "an e line before the p line"),
        ("c only comments\nc\n", 3, "no p line"),
        ("", 1, "no p line"),
        (
            "c\np edge 3 2\ne 1 2\n",
            2,
            "the p line gives 2 edges, the file has 1",
        ),
        (
            "p edge 3 1\ne 1 2\ne 2 3\n",
            3,
            "more e lines than the 1 edges",
        ),
        (
            "p edge three 1\n",
            1,
            "vertex count \"three\" is not a non-negative integer",
        ),
        (
            "p edge 3 -1\n",
            1,
            "edge count \"-1\" is not a non-negative integer",
        ),
        ("p edge 3\n", 1, "missing edge count"),
        ("p edge 3 1 9\n", 1, "unexpected \"9\""),
        ("p graph 3 1\n", 1, "format is \"graph\""),
        (
            "p edge 3 1\ne 1 x\n",
            2,
            "vertex \"x\" is not a non-negative integer",
        ),
        ("p edge 3 1\ne 1\n", 2, "missing vertex"),
        (
            "p edge 3 1\np edge 3 1\n",
            2,
            "a second p line (the first is line 1)",
        ),
        ("p edge 3 1\nv 1 2\n", 2, "a line starting with \"v\""),
    ];
    for (text, line, words) in cases {
        let e = read_dimacs(text).unwrap_err();
        let message = e.to_string();
        assert_eq!(line_of(e, "DIMACS"), line, "{text:?}: {message}");
        assert!(
            message.starts_with(&format!("DIMACS line {line}: ")),
            "{message}"
        );
        assert!(message.contains(words), "{text:?}: {message}");
    }
    // Counts beyond the limits are refused before anything is allocated for them.
    for text in ["p edge 67108865 0\n", "p edge 3 67108865\n"] {
        assert!(
            matches!(read_dimacs(text), Err(Error::LimitExceeded { .. })),
            "{text}"
        );
    }
}

#[test]
fn edge_lists_read_vertices_from_zero_with_optional_weights() {
    let list = read_edge_list("# a path\n0 1\n1 2 % trailing comment\n\n2 5\n").unwrap();
    assert_eq!(list.vertices, 6);
    assert_eq!(list.edges, [[0, 1], [1, 2], [2, 5]]);
    assert_eq!(list.weights, None);
    let weighted = read_edge_list("0 1 0.5\n1 2 -2e3\n").unwrap();
    assert_eq!(weighted.weights, Some(vec![0.5, -2000.0]));
    assert_eq!(
        read_edge_list("").unwrap(),
        EdgeList {
            vertices: 0,
            edges: vec![],
            weights: None
        }
    );
    let cases: [(&str, usize, &str); 6] = [
        ("0 1\n1\n", 2, "1 fields"),
        ("0 1 2 3\n", 1, "4 fields"),
        (
            "0 1\n1 2 0.5\n",
            2,
            "either every edge has a weight or none has",
        ),
        ("0 -1\n", 1, "vertex \"-1\""),
        ("0 1 heavy\n", 1, "weight \"heavy\" is not a number"),
        ("0 1 NaN\n", 1, "is not finite"),
    ];
    for (text, line, words) in cases {
        let e = read_edge_list(text).unwrap_err();
        let message = e.to_string();
        assert_eq!(line_of(e, "edge list"), line, "{text:?}: {message}");
        assert!(message.contains(words), "{text:?}: {message}");
    }
    assert!(matches!(
        read_edge_list("0 67108864\n"),
        Err(Error::LimitExceeded { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_graphs_round_trip(n in 1usize..60, density in 0.0f64..1.0, seed in any::<u64>()) {
        let m = ((n * (n - 1) / 2) as f64 * density) as usize;
        let g = generate(GraphKind::Gnm, n, m, seed).unwrap();
        prop_assert_eq!(read_dimacs(&write_dimacs(&g)).unwrap(), g);
    }

    #[test]
    fn no_text_makes_a_reader_panic(text in "(p|e|c| |edge|col|[0-9]{1,3}|-|x|\n){0,40}") {
        for result in [read_dimacs(&text), read_edge_list(&text)] {
            if let Err(e) = result {
                prop_assert!(matches!(e, Error::Syntax { .. } | Error::LimitExceeded { .. }), "{e:?}");
            }
        }
    }

    #[test]
    fn arbitrary_bytes_are_read_or_refused(bytes in proptest::collection::vec(any::<u8>(), 0..200)) {
        let text = String::from_utf8_lossy(&bytes);
        let _ = read_dimacs(&text);
        let _ = read_edge_list(&text);
    }
}

#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use crate::common::{run, TempDir};
    use serde_json::Value;

    #[test]
    fn the_command_line_reads_dimacs_files_and_gen_writes_them() {
        let dir = TempDir::new("dimacs");
        let col = dir.path("queen6_6.col");
        let (code, text, err) = run(
            &[
                "gen", "graph", "--kind", "queen", "--n", "6", "--format", "dimacs",
            ],
            None,
        );
        assert_eq!(code, 0, "{err}");
        assert_eq!(
            read_dimacs(&text).unwrap(),
            generate(GraphKind::Queen, 6, 0, 0).unwrap()
        );
        std::fs::write(&col, &text).unwrap();
        // The same colouring from the .col file, from stdin with --format, and from JSON.
        let json = dir.path("queen6_6.json");
        let (_, json_text, _) = run(&["gen", "graph", "--kind", "queen", "--n", "6"], None);
        std::fs::write(&json, json_text).unwrap();
        let colour = |args: &[&str], stdin: Option<&str>| -> Value {
            let (code, out, err) = run(args, stdin);
            assert_eq!(code, 0, "{args:?}: {err}");
            serde_json::from_str(out.trim()).unwrap()
        };
        let from_col = colour(
            &["colour", "--algorithm", "dsatur", col.to_str().unwrap()],
            None,
        );
        let from_stdin = colour(
            &["colour", "--algorithm", "dsatur", "--format", "dimacs", "-"],
            Some(&text),
        );
        let from_json = colour(
            &["colour", "--algorithm", "dsatur", json.to_str().unwrap()],
            None,
        );
        assert_eq!(from_col["colours"], from_json["colours"]);
        assert_eq!(from_stdin["colours"], from_json["colours"]);
        // Edge lists by extension.
        let edges = dir.path("path.edges");
        std::fs::write(&edges, "0 1\n1 2\n").unwrap();
        let path = colour(
            &["colour", "--algorithm", "greedy", edges.to_str().unwrap()],
            None,
        );
        assert_eq!(path["count"], 2);
        // Weights cannot be written as DIMACS.
        let (code, _, err) = run(
            &[
                "gen",
                "graph",
                "--kind",
                "cycle",
                "--n",
                "5",
                "--weighted",
                "--format",
                "dimacs",
            ],
            None,
        );
        assert_eq!(code, 2);
        assert!(err.contains("DIMACS .col has no weights"), "{err}");
    }

    #[test]
    fn malformed_dimacs_files_exit_2_with_the_line_number() {
        let dir = TempDir::new("dimacs-bad");
        for (text, line) in [
            ("c x\np edge a 3\n", 2),
            ("p edge 3 1\ne 0 1\n", 2),
            ("p edge 3 1\ne 1 9\n", 2),
            ("e 1 2\n", 1),
            ("c\nc\n", 3),
            ("p edge 3 2\ne 1 2\n", 1),
            ("p edge 3 1\ne 1 2 3\n", 2),
        ] {
            let col = dir.path("bad.col");
            std::fs::write(&col, text).unwrap();
            let (code, out, err) = run(
                &["colour", "--algorithm", "dsatur", col.to_str().unwrap()],
                None,
            );
            assert_eq!(code, 2, "{text:?}");
            assert!(out.is_empty());
            assert!(
                err.starts_with(&format!("error: DIMACS line {line}: ")),
                "{text:?}: {err}"
            );
            assert_eq!(err.lines().count(), 1, "{err}");
        }
    }
}
