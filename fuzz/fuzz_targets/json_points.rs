//! Fuzz target `json_points`: the checks of [`compgeo::fuzzing::json_points`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::json_points(data));
