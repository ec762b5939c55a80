//! Fuzz target `csv_points`: the checks of [`compgeo::fuzzing::csv_points`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::csv_points(data));
