//! Fuzz target `hull`: the checks of [`compgeo::fuzzing::hull`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::hull(data));
