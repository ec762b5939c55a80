//! Fuzz target `predicates`: the checks of [`compgeo::fuzzing::predicates`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::predicates(data));
