//! Fuzz target `number_arrays`: the checks of [`compgeo::fuzzing::number_arrays`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::number_arrays(data));
