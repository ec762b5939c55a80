//! Fuzz target `voronoi`: the checks of [`compgeo::fuzzing::voronoi`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::voronoi(data));
