//! Fuzz target `bezier`: the checks of [`compgeo::fuzzing::bezier`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::bezier(data));
