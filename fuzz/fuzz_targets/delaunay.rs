//! Fuzz target `delaunay`: the checks of [`compgeo::fuzzing::delaunay`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::delaunay(data));
