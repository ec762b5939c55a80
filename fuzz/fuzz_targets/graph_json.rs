//! Fuzz target `graph_json`: the checks of [`compgeo::fuzzing::graph_json`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::graph_json(data));
