//! Printing results: one JSON value per command, on one line of stdout.

use super::CliError;
use serde::Serialize;
use std::io::{self, Write};

/// Writes `value` as compact JSON followed by a newline to stdout.
///
/// Every `f64` is printed in the shortest form that reads back to the same bits, so
/// coordinates round-trip exactly through the point reader.
///
/// # Errors
/// [`CliError::Output`] if stdout cannot be written (a closed pipe, a full disk).
pub fn print_json<T: Serialize + ?Sized>(value: &T) -> Result<(), CliError> {
    let stdout = io::stdout();
    write_json(&mut io::BufWriter::new(stdout.lock()), value)
}

/// Writes `value` as compact JSON followed by a newline to `out`, then flushes it.
///
/// # Errors
/// [`CliError::Output`] if writing fails.
pub fn write_json<W: Write, T: Serialize + ?Sized>(out: &mut W, value: &T) -> Result<(), CliError> {
    serde_json::to_writer(&mut *out, value).map_err(|e| CliError::Output(e.into()))?;
    writeln!(out)
        .and_then(|()| out.flush())
        .map_err(CliError::Output)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_round_trip_through_the_printed_text() {
        let values = [0.1, -0.0, 1e300, 5e-324, f64::MAX, 1.0 / 3.0, -2.5e-310];
        let mut buf = Vec::new();
        write_json(&mut buf, &values).unwrap();
        let text = String::from_utf8(buf).unwrap();
        assert!(text.ends_with('\n') && text.lines().count() == 1);
        let back: Vec<f64> = serde_json::from_str(&text).unwrap();
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back), bits(&values));
    }
}
