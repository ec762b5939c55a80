//! Replays every stored fuzz input under `tests/fixtures/fuzz/<target>/` through the same
//! check the fuzz target runs (`compgeo::fuzzing::<target>`): the crashes and wrong answers
//! the fuzzers found, minimised, and a few interesting inputs per target. Inputs under
//! `tests/fixtures/fuzz/pending/` are open findings awaiting a fix (none at present); they
//! are not replayed (see "Fuzzing" in `docs/design.md`).
#![cfg(feature = "cli")]

use std::path::{Path, PathBuf};

/// A fuzz target's check: panics when a property fails.
type Check = fn(&[u8]);

/// The fuzz targets and their checks.
const TARGETS: [(&str, Check); 12] = [
    ("json_points", compgeo::fuzzing::json_points),
    ("csv_points", compgeo::fuzzing::csv_points),
    ("graph_json", compgeo::fuzzing::graph_json),
    ("number_arrays", compgeo::fuzzing::number_arrays),
    ("exact_decimal", compgeo::fuzzing::exact_decimal),
    ("hull", compgeo::fuzzing::hull),
    ("delaunay", compgeo::fuzzing::delaunay),
    ("voronoi", compgeo::fuzzing::voronoi),
    ("predicates", compgeo::fuzzing::predicates),
    ("bezier", compgeo::fuzzing::bezier),
    ("bspline", compgeo::fuzzing::bspline),
    ("obj", compgeo::fuzzing::obj),
];

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/fuzz")
}

fn inputs(target: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(fixtures().join(target))
        .unwrap_or_else(|e| panic!("tests/fixtures/fuzz/{target}: {e}"))
        .map(|entry| entry.unwrap().path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    files
}

#[test]
fn every_stored_input_passes_its_targets_check() {
    for (target, check) in TARGETS {
        let files = inputs(target);
        assert!(!files.is_empty(), "no stored inputs for {target}");
        for file in files {
            let data = std::fs::read(&file).unwrap();
            let outcome = std::panic::catch_unwind(|| check(&data));
            assert!(
                outcome.is_ok(),
                "{target}: {} fails its check",
                file.display()
            );
        }
    }
}

#[test]
fn every_fixture_directory_is_a_target_or_pending() {
    for entry in std::fs::read_dir(fixtures()).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        assert!(
            name == "pending" || TARGETS.iter().any(|(t, _)| *t == name),
            "tests/fixtures/fuzz/{name} is not a fuzz target: its inputs would not be replayed"
        );
    }
}
