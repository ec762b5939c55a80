//! Fuzz target `bspline`: the checks of [`compgeo::fuzzing::bspline`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::bspline(data));
