//! `compgeo sort`: sort numbers with one of the library's algorithms and print the counts, or
//! print the algorithm's step table with `--trace`.

use super::input::read_text;
use super::output::print_json;
use super::CliError;
use crate::count::Counts;
use crate::sort::{sort_with, trace, Algorithm};
use crate::spline::parse_f64_or_word;
use crate::util::quote;
use clap::Args;
use serde::Serialize;
use std::io::{self, Write};
use std::path::Path;

/// Arguments of `compgeo sort`.
#[derive(Debug, Args)]
pub(super) struct SortArgs {
    #[arg(long, short, help = Algorithm::names(), long_help = Algorithm::help())]
    algorithm: Algorithm,
    /// Print the algorithm's step table (as the course prints it) instead of JSON; integers
    /// only, at most TRACE_MAX_LEN = 1000 of them
    #[arg(long)]
    trace: bool,
    /// The numbers to sort; without them, read a JSON array or whitespace/comma-separated
    /// numbers from stdin
    #[arg(allow_negative_numbers = true)]
    numbers: Vec<String>,
}

/// `{"sorted": [...], "counts": {...}}`.
#[derive(Debug, Serialize)]
struct Sorted<T> {
    sorted: Vec<T>,
    counts: Counts,
}

/// The keys: integers when every token is one, otherwise finite floats.
#[derive(Debug, PartialEq)]
enum Keys {
    Integers(Vec<i64>),
    Floats(Vec<f64>),
}

/// Runs `compgeo sort`.
pub(super) fn run(args: SortArgs) -> Result<(), CliError> {
    let tokens = if args.numbers.is_empty() {
        tokens_of(&read_text(Path::new("-"))?)
    } else {
        args.numbers
    };
    let keys = parse_keys(&tokens)?;
    if args.trace {
        let Keys::Integers(values) = keys else {
            return Err(CliError::Usage(
                "--trace prints the course's tables, which sort integers; got a non-integer number"
                    .into(),
            ));
        };
        let table = trace(args.algorithm, &values)?;
        let mut out = io::stdout().lock();
        return writeln!(out, "{}", table.trim_end())
            .and_then(|()| out.flush())
            .map_err(CliError::Output);
    }
    let mut counts = Counts::default();
    match keys {
        Keys::Integers(mut v) => {
            sort_with(&mut v, args.algorithm, i64::cmp, &mut counts);
            print_json(&Sorted { sorted: v, counts })
        }
        Keys::Floats(mut v) => {
            sort_with(&mut v, args.algorithm, f64::total_cmp, &mut counts);
            print_json(&Sorted { sorted: v, counts })
        }
    }
}

/// Splits stdin text into number tokens: a JSON array `[3, 1, 2]` or numbers separated by
/// whitespace and/or commas.
fn tokens_of(text: &str) -> Vec<String> {
    let body = text.trim();
    let body = body
        .strip_prefix('[')
        .and_then(|b| b.strip_suffix(']'))
        .unwrap_or(body);
    body.split(|c: char| c == ',' || c.is_whitespace())
        .filter(|t| !t.is_empty())
        .map(str::to_string)
        .collect()
}

fn parse_keys(tokens: &[String]) -> Result<Keys, CliError> {
    if let Ok(ints) = tokens.iter().map(|t| t.parse::<i64>()).collect() {
        return Ok(Keys::Integers(ints));
    }
    let mut floats = Vec::with_capacity(tokens.len());
    for (index, token) in tokens.iter().enumerate() {
        let value = parse_f64_or_word(token).ok_or_else(|| {
            CliError::Shape(format!("number {index} ({}) is not a number", quote(token)))
        })?;
        if !value.is_finite() {
            return Err(CliError::Shape(format!(
                "number {index} is not finite ({})",
                quote(token)
            )));
        }
        floats.push(value);
    }
    Ok(Keys::Floats(floats))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn strings(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn integers_stay_integers_and_mixed_input_becomes_floats() {
        assert_eq!(
            parse_keys(&strings(&["7", "-3", "5"])).unwrap(),
            Keys::Integers(vec![7, -3, 5])
        );
        assert_eq!(
            parse_keys(&strings(&["7", "2.5", "1e300"])).unwrap(),
            Keys::Floats(vec![7.0, 2.5, 1e300])
        );
    }

    #[test]
    fn bad_numbers_are_named() {
        let e = parse_keys(&strings(&["1", "x"])).unwrap_err();
        assert_eq!(e.to_string(), "number 1 (\"x\") is not a number");
        let e = parse_keys(&strings(&["1", "2.0", "nan"])).unwrap_err();
        assert_eq!(e.to_string(), "number 2 is not finite (\"nan\")");
    }

    #[test]
    fn stdin_accepts_json_arrays_and_separated_lists() {
        assert_eq!(tokens_of("[3, 1,2]\n"), strings(&["3", "1", "2"]));
        assert_eq!(tokens_of("3 1\n2,4"), strings(&["3", "1", "2", "4"]));
        assert!(tokens_of("  \n").is_empty());
    }
}
