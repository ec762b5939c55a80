//! Readers for the command line's inputs, shared by every command.
//!
//! **Points** come from a path or `-` (stdin), as JSON or CSV:
//!
//! - JSON: an array of two-element arrays, `[[x, y], ...]`. Numbers follow the JSON
//!   grammar and are rounded correctly at any length and exponent (`1e-400` is 0); a
//!   literal too large for `f64` (such as `1e999`) becomes infinite and is then rejected by
//!   validation (the command's
//!   [`PointSet`](crate::geometry::PointSet)) like any other non-finite coordinate, naming
//!   the point. JSON has no NaN or infinity literals, but
//!   other tools write them (`NaN`, `Infinity`, `-Infinity`, in any letter case, or
//!   `inf`): they are recognised so that the error names the point ("point 2 has a
//!   non-finite coordinate (NaN)") instead of a bare syntax error.
//! - CSV: one point per line, `x,y`, with optional spaces around either value. Blank lines
//!   are skipped. The first non-blank line may be the header `x,y` (any letter case); no
//!   other header is recognised, so a typo in the first data line is an error rather than
//!   a silently dropped point. Values use Rust's float syntax (`1e-5`, `.5`, `inf`, `nan`),
//!   rounded as the JSON numbers are: `nan` and `inf` parse and are then reported as
//!   non-finite coordinates.
//!
//! The format is `--format json|csv` if given, else the file extension (`.json`, `.csv`,
//! any case); stdin defaults to JSON. A leading UTF-8 byte-order mark is ignored; text that
//! is not UTF-8 is an error giving the byte offset of the first bad byte.
//!
//! **Graphs** are JSON objects `{"vertices": n, "edges": [[u, v], ...]}`, or with a weight
//! on every edge, `[[u, v, w], ...]`, read into a [`graph::EdgeList`](crate::graph::EdgeList).
//! Vertex ids must be integers in `0..n`; weights are finite numbers. The edge list alone,
//! `[[u, v], ...]` or `[[u, v, w], ...]`, is a graph too: its vertices are 0 to the largest
//! id (none for `[]`); a graph with isolated vertices above that needs the object. A key
//! given twice in an object is an error, not a silent overwrite.
//!
//! **Exact number lists** (the curve commands' `--exact`): [`parse_number_arrays`] and
//! [`parse_number_list`] keep the text of every number of `[[x, y, ...], ...]` or
//! `[x, ...]` so it can be read as an exact rational
//! ([`parse_scalar`](crate::spline::parse_scalar), bounded as documented there).
//!
//! **Errors** name the point, line, column or entry; any text of the input they echo is
//! quoted, cut after 40 characters (with its full length) and escaped, so a hostile input
//! still gives one short line. No reader recurses on the input's nesting.

mod csv_points;
mod graph_json;
mod json_points;
mod number_arrays;

pub use csv_points::parse_csv_points;
pub use graph_json::parse_json_graph;
pub use json_points::parse_json_points;
pub use number_arrays::{parse_number_arrays, parse_number_grid, parse_number_list};

use super::CliError;
use crate::geometry::Point2;
use crate::graph::EdgeList;
use std::io::Read;
use std::path::{Path, PathBuf};

/// A point-set argument: the input path and its format. Flatten it into a command's
/// arguments with `#[command(flatten)]`.
#[derive(Debug, Clone, clap::Args)]
pub struct PointInput {
    /// Point file: JSON [[x, y], ...] or CSV lines x,y; `-` reads stdin.
    #[arg(value_name = "IN")]
    pub input: PathBuf,
    /// Input format [default: from the file extension; JSON for stdin].
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<Format>,
}

/// A graph argument: the path of a graph file, or `-` for stdin, and its format.
#[derive(Debug, Clone, clap::Args)]
pub struct GraphInput {
    /// Graph file: JSON {"vertices": n, "edges": [[u, v], ...]} (edges [u, v, w] with
    /// weights) or the edge list alone, [[u, v], ...] or [[u, v, w], ...], on vertices 0 to
    /// the largest id; DIMACS .col (p edge n m, e u v, from 1); or a plain edge list, lines
    /// u v [w] from 0; `-` reads stdin
    #[arg(value_name = "G")]
    pub input: PathBuf,
    /// Graph format [default: dimacs for .col and .dimacs, edges for .edges and .txt, json
    /// otherwise and for stdin]
    #[arg(long = "format", value_enum, value_name = "FORMAT")]
    pub graph_format: Option<GraphFormat>,
}

/// The text formats a graph can be read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GraphFormat {
    /// `{"vertices": n, "edges": [[u, v], ...]}` or `[[u, v], ...]`.
    Json,
    /// DIMACS `.col`: `p edge n m`, `e u v` with vertices from 1, `c` comments.
    Dimacs,
    /// Lines `u v` or `u v w`, vertices from 0, `#` comments.
    Edges,
}

/// The text formats a point set can be read from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// `[[x, y], ...]`.
    Json,
    /// Lines `x,y`.
    Csv,
}

impl PointInput {
    /// Reads the points; the command validates them once, building its
    /// [`PointSet`](crate::geometry::PointSet).
    ///
    /// # Errors
    /// [`CliError::Usage`] if the format cannot be told from the extension,
    /// [`CliError::Read`] if the input cannot be read, and the errors of
    /// [`parse_json_points`] and [`parse_csv_points`].
    pub fn read(&self) -> Result<Vec<Point2>, CliError> {
        let format = match self.format {
            Some(f) => f,
            None => format_of(&self.input)?,
        };
        let text = read_text(&self.input)?;
        match format {
            Format::Json => parse_json_points(&text),
            Format::Csv => parse_csv_points(&text),
        }
    }
}

impl GraphInput {
    /// Reads and validates the graph.
    ///
    /// # Errors
    /// [`CliError::Read`] if the input cannot be read, and the errors of
    /// [`parse_json_graph`], [`read_dimacs`](crate::graph::read_dimacs) and
    /// [`read_edge_list`](crate::graph::read_edge_list) (each malformed line by number).
    pub fn read(&self) -> Result<EdgeList, CliError> {
        let text = read_text(&self.input)?;
        let format = self.graph_format.unwrap_or_else(|| {
            let ext = self
                .input
                .extension()
                .and_then(|e| e.to_str())
                .map(str::to_ascii_lowercase);
            match ext.as_deref() {
                Some("col" | "dimacs") => GraphFormat::Dimacs,
                Some("edges" | "txt") => GraphFormat::Edges,
                _ => GraphFormat::Json,
            }
        });
        match format {
            GraphFormat::Json => parse_json_graph(&text),
            GraphFormat::Dimacs => Ok(crate::graph::read_dimacs(&text)?),
            GraphFormat::Edges => Ok(crate::graph::read_edge_list(&text)?),
        }
    }
}

/// The JSON given inline on the command line, or all of standard input for `-` (the curve
/// and surface commands' `--control`, `--points`, `--net`).
///
/// # Errors
/// As [`read_text`] for `-`.
pub fn inline_or_stdin(text: &str) -> Result<String, CliError> {
    if text == "-" {
        read_text(Path::new("-"))
    } else {
        Ok(text.to_string())
    }
}

/// Reads all of `path` (or stdin for `-`) as UTF-8 text.
///
/// # Errors
/// [`CliError::Read`] naming the path (or `stdin`) and the I/O error; for text that is not
/// UTF-8, the byte offset of the first invalid byte ("invalid UTF-8 at byte 13").
pub fn read_text(path: &Path) -> Result<String, CliError> {
    let mut bytes = Vec::new();
    let result = if is_stdin(path) {
        std::io::stdin().read_to_end(&mut bytes).map(|_| ())
    } else {
        std::fs::read(path).map(|b| bytes = b)
    };
    let error = |source| CliError::Read {
        path: if is_stdin(path) {
            "stdin".to_string()
        } else {
            format!("'{}'", path.display())
        },
        source,
    };
    result.map_err(error)?;
    String::from_utf8(bytes).map_err(|e| {
        error(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("invalid UTF-8 at byte {}", e.utf8_error().valid_up_to()),
        ))
    })
}

/// The format implied by `path`'s extension; stdin is JSON.
fn format_of(path: &Path) -> Result<Format, CliError> {
    if is_stdin(path) {
        return Ok(Format::Json);
    }
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("json") => Ok(Format::Json),
        Some("csv") => Ok(Format::Csv),
        _ => Err(CliError::Usage(format!(
            "cannot tell the format of '{}' from its extension; pass --format json or --format csv",
            path.display()
        ))),
    }
}

fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == "-"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_follow_extensions() {
        assert_eq!(format_of(Path::new("a.json")).unwrap(), Format::Json);
        assert_eq!(format_of(Path::new("dir/a.CSV")).unwrap(), Format::Csv);
        assert_eq!(format_of(Path::new("-")).unwrap(), Format::Json);
        for p in ["a.txt", "noext", "a.json.gz"] {
            assert!(
                matches!(format_of(Path::new(p)), Err(CliError::Usage(_))),
                "{p}"
            );
        }
    }

    #[test]
    fn inputs_read_files_by_extension() {
        let dir = std::env::temp_dir().join(format!("compgeo-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let csv = dir.join("p.csv");
        std::fs::write(&csv, "1,2\n3,4\n").unwrap();
        let input = PointInput {
            input: csv.clone(),
            format: None,
        };
        assert_eq!(
            input.read().unwrap(),
            vec![Point2::new(1.0, 2.0), Point2::new(3.0, 4.0)]
        );
        // Forcing JSON on CSV text fails as JSON would.
        let forced = PointInput {
            input: csv,
            format: Some(Format::Json),
        };
        assert!(matches!(forced.read(), Err(CliError::Json { .. })));
        let g = dir.join("g.json");
        std::fs::write(&g, r#"{"vertices": 2, "edges": [[0, 1]]}"#).unwrap();
        let graph = GraphInput {
            input: g,
            graph_format: None,
        }
        .read()
        .unwrap();
        assert_eq!((graph.vertices, graph.edges), (2, vec![[0, 1]]));
        // Invalid UTF-8: the offset of the first bad byte.
        let bad = dir.join("bad.json");
        std::fs::write(&bad, b"[[1, 2], [3, \xff]]").unwrap();
        let err = PointInput {
            input: bad,
            format: None,
        }
        .read()
        .unwrap_err();
        assert!(
            err.to_string()
                .ends_with("bad.json': invalid UTF-8 at byte 13"),
            "{err}"
        );
        let missing = GraphInput {
            input: dir.join("missing.json"),
            graph_format: None,
        };
        match missing.read() {
            Err(CliError::Read { path, .. }) => assert!(path.contains("missing.json")),
            other => panic!("{other:?}"),
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
