//! Printing results: one JSON value per command, on one line of stdout.

use super::CliError;
use serde::Serialize;
use serde_json::ser::{CompactFormatter, Formatter};
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

/// Writes `value` as compact JSON followed by a newline to stdout.
///
/// Every `f64` is printed in the shortest form that reads back to the same bits, except
/// that `-0.0` is printed as `0.0`: every command's output goes through here, so none
/// prints a negative zero (an empty sum, a coordinate copied from the input, a product with
/// a zero factor), which readers take for a sign that means something.
///
/// # Errors
/// [`CliError::Output`] if stdout cannot be written (a closed pipe, a full disk).
pub fn print_json<T: Serialize + ?Sized>(value: &T) -> Result<(), CliError> {
    let stdout = io::stdout();
    write_json(&mut io::BufWriter::new(stdout.lock()), value)
}

/// Writes `text` to stdout as it is (an SVG, a step page, DIMACS text) and flushes it.
///
/// # Errors
/// [`CliError::Output`] if stdout cannot be written.
pub fn print_text(text: &str) -> Result<(), CliError> {
    let stdout = io::stdout();
    let mut w = io::BufWriter::new(stdout.lock());
    w.write_all(text.as_bytes())
        .and_then(|()| w.flush())
        .map_err(CliError::Output)
}

/// Writes `value` as compact JSON followed by a newline to `out`, then flushes it; `-0.0` is
/// written as `0.0` (see [`print_json`]).
///
/// # Errors
/// [`CliError::Output`] if writing fails.
pub fn write_json<W: Write, T: Serialize + ?Sized>(out: &mut W, value: &T) -> Result<(), CliError> {
    let mut serializer = serde_json::Serializer::with_formatter(&mut *out, UnsignedZero);
    value
        .serialize(&mut serializer)
        .map_err(|e| CliError::Output(e.into()))?;
    writeln!(out)
        .and_then(|()| out.flush())
        .map_err(CliError::Output)
}

/// Creates the file `path` (a file a command writes: a mesh, a picture) and lets `write`
/// fill it through a buffer.
///
/// # Errors
/// [`CliError::Write`] naming the path if it cannot be created, written or flushed.
pub fn write_file(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> Result<(), CliError> {
    let failed = |source| CliError::Write {
        path: crate::util::quote(&path.display().to_string()),
        source,
    };
    let mut w = BufWriter::new(File::create(path).map_err(failed)?);
    write(&mut w).map_err(failed)?;
    w.flush().map_err(failed)
}

/// serde_json's compact format with `-0.0` written as `0.0`.
struct UnsignedZero;

impl Formatter for UnsignedZero {
    fn write_f64<W: ?Sized + Write>(&mut self, writer: &mut W, value: f64) -> io::Result<()> {
        // `-0.0 == 0.0`, so this maps both zeros to the positive one and nothing else.
        let value = if value == 0.0 { 0.0 } else { value };
        CompactFormatter.write_f64(writer, value)
    }

    fn write_f32<W: ?Sized + Write>(&mut self, writer: &mut W, value: f32) -> io::Result<()> {
        let value = if value == 0.0 { 0.0 } else { value };
        CompactFormatter.write_f32(writer, value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn printed<T: Serialize + ?Sized>(value: &T) -> String {
        let mut buf = Vec::new();
        write_json(&mut buf, value).unwrap();
        String::from_utf8(buf).unwrap()
    }

    #[test]
    fn floats_round_trip_through_the_printed_text() {
        let values = [
            0.1,
            0.0,
            1e300,
            5e-324,
            f64::MAX,
            1.0 / 3.0,
            -2.5e-310,
            -5e-324,
        ];
        let text = printed(&values);
        assert!(text.ends_with('\n') && text.lines().count() == 1);
        let back: Vec<f64> = serde_json::from_str(&text).unwrap();
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back), bits(&values));
    }

    #[test]
    fn negative_zero_is_printed_as_zero_everywhere() {
        // Plain floats, floats inside structures and serde_json values (the curve commands
        // build those), and f32.
        let text = printed(&(
            -0.0f64,
            [[-0.0f64, 1.0]],
            serde_json::json!({"x": -0.0f64, "y": [-0.0f64]}),
            -0.0f32,
        ));
        assert_eq!(text, "[0.0,[[0.0,1.0]],{\"x\":0.0,\"y\":[0.0]},0.0]\n");
        // A string that spells -0.0 is text, not a number, and stays.
        assert_eq!(printed("-0.0"), "\"-0.0\"\n");
    }
}
