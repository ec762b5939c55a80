//! The command line's error type: library errors plus the ways reading input can fail.

use std::io;

/// Everything that can go wrong in a `compgeo` command.
///
/// Its `Display` is the one-line message printed after `error: `. Every variant except
/// [`CliError::Output`] is a problem with the user's input, arguments or paths and exits
/// with code 2; a failure to write the result to stdout exits with code 1.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CliError {
    /// The library rejected the data (a non-finite coordinate, a vertex out of range, an
    /// invalid parameter, ...).
    #[error(transparent)]
    Library(#[from] crate::Error),
    /// The input could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The path as given, or `stdin`.
        path: String,
        /// The underlying I/O error.
        source: io::Error,
    },
    /// A file or directory the command writes (`report --out`) cannot be written.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The path as given, quoted.
        path: String,
        /// The underlying I/O error.
        source: io::Error,
    },
    /// The input is not well-formed JSON, or not the JSON shape the command expects.
    #[error("invalid JSON at line {line}, column {column}: {message}")]
    Json {
        /// 1-based line of the problem.
        line: usize,
        /// 1-based column (in characters) of the problem.
        column: usize,
        /// What is wrong there.
        message: String,
    },
    /// A CSV line is malformed.
    #[error("invalid CSV at line {line}: {message}")]
    Csv {
        /// 1-based line number.
        line: usize,
        /// What is wrong with the line.
        message: String,
    },
    /// A point does not have exactly two coordinates.
    #[error(
        "point {index} has {got} {}, expected 2 ([x, y])",
        if *.got == 1 { "coordinate" } else { "coordinates" }
    )]
    Arity {
        /// Index of the point in the input.
        index: usize,
        /// How many coordinates it has.
        got: usize,
    },
    /// Well-formed input that does not describe what the command needs (a graph edge that
    /// is not `[u, v]` or `[u, v, w]`, say).
    #[error("{0}")]
    Shape(String),
    /// Arguments that are individually valid but do not fit together.
    #[error("{0}")]
    Usage(String),
    /// The result could not be written to stdout (a closed pipe, a full disk).
    #[error("cannot write output: {0}")]
    Output(io::Error),
}

impl CliError {
    /// The process exit code for this error: 1 for [`CliError::Output`], 2 otherwise.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Output(_) => 1,
            _ => 2,
        }
    }
}
