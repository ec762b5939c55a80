//! Fuzz target `obj`: the checks of [`compgeo::fuzzing::obj`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::obj(data));
