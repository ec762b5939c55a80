//! Fuzz target `exact_decimal`: the checks of [`compgeo::fuzzing::exact_decimal`].
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| compgeo::fuzzing::exact_decimal(data));
