//! Readers for the command line's inputs, shared by every command.
//!
//! **Points** come from a path or `-` (stdin), as JSON or CSV:
//!
//! - JSON: an array of two-element arrays, `[[x, y], ...]`. Numbers follow the JSON
//!   grammar and are converted with correct rounding; a literal too large for `f64` (such
//!   as `1e999`) becomes infinite and is then rejected by validation like any other
//!   non-finite coordinate, naming the point. JSON has no NaN or infinity literals, but
//!   other tools write them (`NaN`, `Infinity`, `-Infinity`, in any letter case, or
//!   `inf`): they are recognised so that the error names the point ("point 2 has a
//!   non-finite coordinate (NaN)") instead of a bare syntax error.
//! - CSV: one point per line, `x,y`, with optional spaces around either value. Blank lines
//!   are skipped. The first non-blank line may be the header `x,y` (any letter case); no
//!   other header is recognised, so a typo in the first data line is an error rather than
//!   a silently dropped point. Values use Rust's float syntax (`1e-5`, `.5`, `inf`, `nan`):
//!   `nan` and `inf` parse and are then reported as non-finite coordinates.
//!
//! The format is `--format json|csv` if given, else the file extension (`.json`, `.csv`,
//! any case); stdin defaults to JSON. A leading UTF-8 byte-order mark is ignored.
//!
//! **Graphs** are JSON objects `{"vertices": n, "edges": [[u, v], ...]}`, or with a weight
//! on every edge, `[[u, v, w], ...]`, read into a [`gen::EdgeList`](crate::gen::EdgeList).
//! Vertex ids must be integers in `0..n`; weights are finite numbers.

use super::CliError;
use crate::gen::EdgeList;
use crate::geometry::{validate, Point2};
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

/// A graph argument: the path of a JSON graph, or `-` for stdin.
#[derive(Debug, Clone, clap::Args)]
pub struct GraphInput {
    /// Graph file: JSON {"vertices": n, "edges": [[u, v], ...]} or [[u, v, w], ...]; `-`
    /// reads stdin.
    #[arg(value_name = "G")]
    pub input: PathBuf,
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
    /// Reads and validates the point set.
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
    /// [`parse_json_graph`].
    pub fn read(&self) -> Result<EdgeList, CliError> {
        parse_json_graph(&read_text(&self.input)?)
    }
}

/// Reads all of `path` (or stdin for `-`) as UTF-8 text.
///
/// # Errors
/// [`CliError::Read`] naming the path (or `stdin`) and the I/O error.
pub fn read_text(path: &Path) -> Result<String, CliError> {
    let mut text = String::new();
    let result = if is_stdin(path) {
        std::io::stdin().read_to_string(&mut text).map(|_| ())
    } else {
        std::fs::read_to_string(path).map(|t| text = t)
    };
    result.map_err(|source| CliError::Read {
        path: if is_stdin(path) {
            "stdin".to_string()
        } else {
            format!("'{}'", path.display())
        },
        source,
    })?;
    Ok(text)
}

/// Parses a JSON point array `[[x, y], ...]` and validates the points.
///
/// # Errors
/// [`CliError::Json`] with line and column for malformed JSON or a value that is not a
/// number where a coordinate belongs (naming the point), [`CliError::Arity`] for a point
/// without exactly two coordinates, and [`crate::Error::NonFinite`] (inside
/// [`CliError::Library`]) for the first point with a NaN, infinite or overflowing
/// coordinate.
pub fn parse_json_points(text: &str) -> Result<Vec<Point2>, CliError> {
    let mut p = JsonCursor::new(text);
    p.skip_ws();
    if !p.eat(b'[') {
        return Err(p.error(format!(
            "expected a JSON array of points [[x, y], ...], found {}",
            p.found()
        )));
    }
    let mut points = Vec::new();
    p.skip_ws();
    if !p.eat(b']') {
        loop {
            p.skip_ws();
            points.push(p.point(points.len())?);
            p.skip_ws();
            if p.eat(b',') {
                continue;
            }
            if p.eat(b']') {
                break;
            }
            return Err(p.error(format!(
                "expected ',' or ']' after point {}, found {}",
                points.len() - 1,
                p.found()
            )));
        }
    }
    p.skip_ws();
    if !p.at_end() {
        return Err(p.error(format!(
            "expected the end of input after the point array, found {}",
            p.found()
        )));
    }
    validate(&points)?;
    Ok(points)
}

/// Parses CSV lines `x,y` (see the module docs for the accepted syntax) and validates the
/// points.
///
/// # Errors
/// [`CliError::Csv`] naming the line for a line without exactly two fields or a field that
/// is not a number, and [`crate::Error::NonFinite`] (inside [`CliError::Library`]) for the
/// first point with a NaN or infinite coordinate.
pub fn parse_csv_points(text: &str) -> Result<Vec<Point2>, CliError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut points = Vec::new();
    let mut seen_data_or_header = false;
    for (i, raw) in text.split('\n').enumerate() {
        let line = raw.strip_suffix('\r').unwrap_or(raw).trim();
        if line.is_empty() {
            continue;
        }
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        let first = !seen_data_or_header;
        seen_data_or_header = true;
        if first
            && fields.len() == 2
            && fields[0].eq_ignore_ascii_case("x")
            && fields[1].eq_ignore_ascii_case("y")
        {
            continue;
        }
        let number = i + 1;
        if fields.len() != 2 {
            return Err(CliError::Csv {
                line: number,
                message: format!("expected 2 fields x,y, found {}", fields.len()),
            });
        }
        let parse = |field: &str| {
            field.parse::<f64>().map_err(|_| CliError::Csv {
                line: number,
                message: format!("'{field}' is not a number"),
            })
        };
        points.push(Point2::new(parse(fields[0])?, parse(fields[1])?));
    }
    validate(&points)?;
    Ok(points)
}

/// Parses a JSON graph `{"vertices": n, "edges": [[u, v], ...]}` (or `[[u, v, w], ...]`).
///
/// Either every edge has a weight or none has; an empty edge list is unweighted. Edges are
/// kept in input order, self-loops and parallel edges included (the algorithms decide
/// what they accept).
///
/// # Errors
/// [`CliError::Json`] for malformed JSON (numbers too large for `f64` included),
/// [`CliError::Shape`] for a document that is not such an object (a missing or unknown
/// key, an edge that is not `[u, v]` or `[u, v, w]`, a vertex id that is not a
/// non-negative integer, weights on some edges only), and
/// [`crate::Error::VertexOutOfRange`] (inside [`CliError::Library`]) for an id `>= n`.
pub fn parse_json_graph(text: &str) -> Result<EdgeList, CliError> {
    use serde_json::Value;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let doc: Value = serde_json::from_str(text).map_err(|e| CliError::Json {
        line: e.line(),
        column: e.column(),
        message: strip_position(&e.to_string()),
    })?;
    let Value::Object(map) = doc else {
        return Err(CliError::Shape(
            "expected a graph object {\"vertices\": n, \"edges\": [[u, v], ...]}".to_string(),
        ));
    };
    if let Some(key) = map.keys().find(|k| *k != "vertices" && *k != "edges") {
        return Err(CliError::Shape(format!(
            "unexpected key '{key}' in the graph object; expected \"vertices\" and \"edges\""
        )));
    }
    let vertices = match map.get("vertices") {
        None => {
            return Err(CliError::Shape(
                "the graph object has no \"vertices\" count".to_string(),
            ))
        }
        Some(v) => v
            .as_u64()
            .and_then(|n| usize::try_from(n).ok())
            .ok_or_else(|| {
                CliError::Shape(format!(
                    "\"vertices\" must be a non-negative integer, found {v}"
                ))
            })?,
    };
    let edges = match map.get("edges") {
        None => {
            return Err(CliError::Shape(
                "the graph object has no \"edges\" list".to_string(),
            ))
        }
        Some(Value::Array(edges)) => edges,
        Some(other) => {
            return Err(CliError::Shape(format!(
                "\"edges\" must be an array of [u, v] or [u, v, w], found {other}"
            )))
        }
    };
    let weighted = matches!(edges.first(), Some(Value::Array(e)) if e.len() == 3);
    let mut list = Vec::with_capacity(edges.len());
    let mut weights = Vec::with_capacity(if weighted { edges.len() } else { 0 });
    for (index, edge) in edges.iter().enumerate() {
        let items = match edge {
            Value::Array(items) if items.len() == 2 || items.len() == 3 => items,
            _ => {
                return Err(CliError::Shape(format!(
                    "edge {index} must be [u, v] or [u, v, w], found {edge}"
                )))
            }
        };
        if (items.len() == 3) != weighted {
            return Err(CliError::Shape(format!(
                "edge {index} {} but edge 0 {}; give every edge a weight or none",
                if weighted {
                    "has no weight"
                } else {
                    "has a weight"
                },
                if weighted { "has one" } else { "does not" },
            )));
        }
        let mut ends = [0usize; 2];
        for (end, item) in ends.iter_mut().zip(items) {
            *end = item
                .as_u64()
                .and_then(|v| usize::try_from(v).ok())
                .ok_or_else(|| {
                    CliError::Shape(format!(
                        "edge {index}: vertex ids must be non-negative integers, found {item}"
                    ))
                })?;
            if *end >= vertices {
                return Err(crate::Error::VertexOutOfRange {
                    edge: index,
                    vertex: *end,
                    vertices,
                }
                .into());
            }
        }
        list.push(ends);
        if weighted {
            let w = items[2].as_f64().ok_or_else(|| {
                CliError::Shape(format!(
                    "edge {index}: the weight must be a number, found {}",
                    items[2]
                ))
            })?;
            weights.push(w);
        }
    }
    Ok(EdgeList {
        vertices,
        edges: list,
        weights: weighted.then_some(weights),
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

/// serde_json appends " at line L column C"; we report the position separately.
fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(i) => message[..i].to_string(),
        None => message.to_string(),
    }
}

/// A byte cursor over JSON text, reading the one shape `[[x, y], ...]` with precise errors.
struct JsonCursor<'a> {
    text: &'a str,
    bytes: &'a [u8],
    pos: usize,
}

impl<'a> JsonCursor<'a> {
    fn new(text: &'a str) -> Self {
        let pos = if text.starts_with('\u{feff}') { 3 } else { 0 };
        JsonCursor {
            text,
            bytes: text.as_bytes(),
            pos,
        }
    }

    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.pos).copied()
    }

    fn at_end(&self) -> bool {
        self.pos >= self.bytes.len()
    }

    fn eat(&mut self, b: u8) -> bool {
        if self.peek() == Some(b) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn skip_ws(&mut self) {
        while matches!(self.peek(), Some(b' ' | b'\t' | b'\n' | b'\r')) {
            self.pos += 1;
        }
    }

    /// One point `[x, y]`; any number of coordinates is parsed so the arity error can say
    /// how many there were.
    fn point(&mut self, index: usize) -> Result<Point2, CliError> {
        if !self.eat(b'[') {
            return Err(self.error(format!(
                "point {index} must be an array [x, y], found {}",
                self.found()
            )));
        }
        let mut coords = [0.0; 2];
        let mut count = 0;
        self.skip_ws();
        if !self.eat(b']') {
            loop {
                self.skip_ws();
                let value = self.number(index)?;
                if count < 2 {
                    coords[count] = value;
                }
                count += 1;
                self.skip_ws();
                if self.eat(b',') {
                    continue;
                }
                if self.eat(b']') {
                    break;
                }
                return Err(self.error(format!(
                    "expected ',' or ']' in point {index}, found {}",
                    self.found()
                )));
            }
        }
        if count != 2 {
            return Err(CliError::Arity { index, got: count });
        }
        Ok(Point2::new(coords[0], coords[1]))
    }

    /// A JSON number, or a non-finite word (so validation can name the point).
    fn number(&mut self, index: usize) -> Result<f64, CliError> {
        let start = self.pos;
        let sign = matches!(self.peek(), Some(b'-' | b'+'));
        let word_start = start + usize::from(sign);
        let word_len = self.bytes[word_start..]
            .iter()
            .take_while(|b| b.is_ascii_alphabetic())
            .count();
        if word_len > 0 {
            let word = &self.text[word_start..word_start + word_len];
            let value = match word.to_ascii_lowercase().as_str() {
                "nan" => Some(f64::NAN),
                "inf" | "infinity" if self.bytes[start] == b'-' => Some(f64::NEG_INFINITY),
                "inf" | "infinity" => Some(f64::INFINITY),
                _ => None,
            };
            return match value {
                Some(v) => {
                    self.pos = word_start + word_len;
                    Ok(v)
                }
                None => Err(self.error(format!(
                    "point {index}: expected a number, found '{}'",
                    &self.text[start..word_start + word_len]
                ))),
            };
        }
        self.eat(b'-');
        let digits = |c: &mut Self| {
            let from = c.pos;
            while matches!(c.peek(), Some(b'0'..=b'9')) {
                c.pos += 1;
            }
            c.pos - from
        };
        let int_start = self.pos;
        let int_digits = digits(self);
        let leading_zero = int_digits > 1 && self.bytes[int_start] == b'0';
        let mut valid = int_digits > 0 && !leading_zero;
        if valid && self.eat(b'.') {
            valid = digits(self) > 0;
        }
        if valid && matches!(self.peek(), Some(b'e' | b'E')) {
            self.pos += 1;
            if !self.eat(b'+') {
                self.eat(b'-');
            }
            valid = digits(self) > 0;
        }
        if !valid {
            self.pos = start;
            return Err(self.error(format!(
                "point {index}: expected a number, found {}",
                self.found()
            )));
        }
        // The grammar above is a subset of what Rust's correctly rounded parser accepts.
        self.text[start..self.pos]
            .parse::<f64>()
            .map_err(|e| self.error(format!("point {index}: {e}")))
    }

    /// The next token, quoted, for error messages.
    fn found(&self) -> String {
        let rest = &self.text[self.pos..];
        let token: String = rest
            .chars()
            .take_while(|c| !c.is_whitespace() && !matches!(c, ',' | ']' | '['))
            .take(24)
            .collect();
        match rest.chars().next() {
            None => "the end of input".to_string(),
            Some(c) if token.is_empty() => format!("'{c}'"),
            Some(_) => format!("'{token}'"),
        }
    }

    fn error(&self, message: String) -> CliError {
        let before = &self.text[..self.pos.min(self.text.len())];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before[line_start..].chars().count() + 1;
        CliError::Json {
            line,
            column,
            message,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    fn json(text: &str) -> Result<Vec<Point2>, CliError> {
        parse_json_points(text)
    }

    fn bits(pts: &[Point2]) -> Vec<(u64, u64)> {
        pts.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect()
    }

    #[test]
    fn json_points_parse_exactly() {
        let pts = json(" \n[[1, 2],[-0.0,1e300] ,\n [5e-324, -2.5E-3], [0.1,1E+2]]\n").unwrap();
        let expected = [
            Point2::new(1.0, 2.0),
            Point2::new(-0.0, 1e300),
            Point2::new(5e-324, -2.5e-3),
            Point2::new(0.1, 100.0),
        ];
        assert_eq!(bits(&pts), bits(&expected));
        assert!(json("[]").unwrap().is_empty());
        assert!(json("\u{feff}[ ]").unwrap().is_empty());
    }

    #[test]
    fn json_agrees_with_serde_json_on_valid_numbers() {
        // serde_json is the oracle for the grammar and the rounding of valid JSON.
        let text = "[[0, -0], [123456789012345678901234567890, 1.7976931348623157e308], \
                    [2.2250738585072011e-308, 0.30000000000000004], [1e-400, -12.5e-1]]";
        let ours = json(text).unwrap();
        let theirs: Vec<[f64; 2]> = serde_json::from_str(text).unwrap();
        let theirs: Vec<Point2> = theirs.into_iter().map(Point2::from).collect();
        assert_eq!(bits(&ours), bits(&theirs));
    }

    #[test]
    fn json_non_finite_values_name_the_point() {
        for (text, index, shown) in [
            ("[[0, 0], [NaN, 1]]", 1, "NaN"),
            ("[[0, 0], [1, 2], [3, Infinity]]", 2, "inf"),
            ("[[-Infinity, 0]]", 0, "-inf"),
            ("[[0, 0], [1e999, 0]]", 1, "inf"),
            ("[[0, 0], [0, -1e400]]", 1, "-inf"),
            ("[[nan, 1]]", 0, "NaN"),
        ] {
            let err = json(text).unwrap_err();
            assert!(
                matches!(err, CliError::Library(Error::NonFinite { index: i, .. }) if i == index),
                "{text}: {err:?}"
            );
            assert_eq!(
                err.to_string(),
                format!("point {index} has a non-finite coordinate ({shown})")
            );
        }
    }

    #[test]
    fn json_arity_errors_name_the_point() {
        for (text, index, got) in [
            ("[[1]]", 0, 1),
            ("[[0, 0], [1, 2, 3]]", 1, 3),
            ("[[0, 0], []]", 1, 0),
        ] {
            match json(text) {
                Err(CliError::Arity { index: i, got: g }) => assert_eq!((i, g), (index, got)),
                other => panic!("{text}: {other:?}"),
            }
        }
        assert_eq!(
            json("[[1,2,3]]").unwrap_err().to_string(),
            "point 0 has 3 coordinates, expected 2 ([x, y])"
        );
    }

    #[test]
    fn malformed_json_reports_line_and_column() {
        for (text, line, column, needle) in [
            ("", 1, 1, "the end of input"),
            ("{}", 1, 1, "found '{}'"),
            ("[[1, 2]", 1, 8, "after point 0"),
            ("[[1, 2],\n [3, 4] [5, 6]]", 2, 9, "after point 1"),
            ("[[1, 2]] x", 1, 10, "end of input after"),
            ("[[1, \"2\"]]", 1, 6, "point 0: expected a number"),
            ("[[01, 2]]", 1, 3, "point 0: expected a number"),
            ("[[1., 2]]", 1, 3, "point 0"),
            ("[[+1, 2]]", 1, 3, "point 0"),
            ("[[.5, 2]]", 1, 3, "point 0"),
            ("[[1e, 2]]", 1, 3, "point 0"),
            ("[[true, 2]]", 1, 3, "found 'true'"),
            ("[[1, 2], 3]", 1, 10, "point 1 must be an array"),
            ("[[1 2]]", 1, 5, "in point 0"),
            ("[[1, 2],]", 1, 9, "point 1 must be an array"),
        ] {
            match json(text) {
                Err(CliError::Json {
                    line: l,
                    column: c,
                    message,
                }) => {
                    assert_eq!((l, c), (line, column), "{text:?}: {message}");
                    assert!(message.contains(needle), "{text:?}: {message}");
                }
                other => panic!("{text:?}: {other:?}"),
            }
        }
    }

    #[test]
    fn csv_points_with_header_blanks_and_spaces() {
        let text = "x, Y\r\n\n 1.5 , -2\n\n3,4e-320\r\n  \n-0,1e300\n";
        let pts = parse_csv_points(text).unwrap();
        let expected = [
            Point2::new(1.5, -2.0),
            Point2::new(3.0, 4e-320),
            Point2::new(-0.0, 1e300),
        ];
        assert_eq!(bits(&pts), bits(&expected));
        assert!(parse_csv_points("").unwrap().is_empty());
        assert!(parse_csv_points("x,y\n").unwrap().is_empty());
    }

    #[test]
    fn csv_errors_name_the_line_or_point() {
        let err = parse_csv_points("0,0\n1,1\n2,2\nnan,3\n").unwrap_err();
        assert_eq!(err.to_string(), "point 3 has a non-finite coordinate (NaN)");
        let err = parse_csv_points("0,0\n\n-inf,1\n").unwrap_err();
        assert_eq!(
            err.to_string(),
            "point 1 has a non-finite coordinate (-inf)"
        );
        for (text, line, needle) in [
            ("1,2\n3\n", 2, "expected 2 fields x,y, found 1"),
            ("1,2\n\n3,4,5\n", 3, "found 3"),
            ("1,2\n3,abc\n", 2, "'abc' is not a number"),
            ("1,2\nx,y\n", 2, "'x' is not a number"),
            ("lon,lat\n1,2\n", 1, "'lon' is not a number"),
            ("1;2\n", 1, "found 1"),
        ] {
            match parse_csv_points(text) {
                Err(CliError::Csv { line: l, message }) => {
                    assert_eq!(l, line, "{text:?}");
                    assert!(message.contains(needle), "{text:?}: {message}");
                }
                other => panic!("{text:?}: {other:?}"),
            }
        }
    }

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
    fn graphs_parse_with_and_without_weights() {
        let g = parse_json_graph(r#"{"vertices": 4, "edges": [[0, 1], [3, 2], [1, 1]]}"#).unwrap();
        assert_eq!(g.vertices, 4);
        assert_eq!(g.edges, vec![[0, 1], [3, 2], [1, 1]]);
        assert_eq!(g.weights, None);
        let g = parse_json_graph(r#"{"edges": [[0, 1, 0.5], [1, 2, -3]], "vertices": 3}"#).unwrap();
        assert_eq!(g.weights, Some(vec![0.5, -3.0]));
        let g = parse_json_graph(r#"{"vertices": 0, "edges": []}"#).unwrap();
        assert_eq!((g.vertices, g.edges.len(), g.weights), (0, 0, None));
    }

    #[test]
    fn generated_graphs_round_trip_through_the_reader() {
        use crate::gen::{graph, with_random_weights, GraphKind};
        let g = with_random_weights(graph(GraphKind::Gnm, 30, 80, 2).unwrap(), 2);
        let weights = g.weights.clone().unwrap();
        let edges: Vec<(usize, usize, f64)> = g
            .edges
            .iter()
            .zip(&weights)
            .map(|(&[u, v], &w)| (u, v, w))
            .collect();
        let text = serde_json::json!({"vertices": g.vertices, "edges": edges}).to_string();
        assert_eq!(parse_json_graph(&text).unwrap(), g);
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
        let graph = GraphInput { input: g }.read().unwrap();
        assert_eq!((graph.vertices, graph.edges), (2, vec![[0, 1]]));
        let missing = GraphInput {
            input: dir.join("missing.json"),
        };
        match missing.read() {
            Err(CliError::Read { path, .. }) => assert!(path.contains("missing.json")),
            other => panic!("{other:?}"),
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn bad_graphs_are_named() {
        let vertex = parse_json_graph(r#"{"vertices": 3, "edges": [[0, 1], [1, 3]]}"#);
        assert!(matches!(
            vertex,
            Err(CliError::Library(Error::VertexOutOfRange {
                edge: 1,
                vertex: 3,
                vertices: 3
            }))
        ));
        for (text, needle) in [
            ("[]", "expected a graph object"),
            (r#"{"edges": []}"#, "no \"vertices\""),
            (r#"{"vertices": 2}"#, "no \"edges\""),
            (r#"{"vertices": -1, "edges": []}"#, "non-negative integer"),
            (r#"{"vertices": 2.5, "edges": []}"#, "non-negative integer"),
            (r#"{"vertices": 2, "edges": {}}"#, "must be an array"),
            (r#"{"vertices": 2, "edges": [[0]]}"#, "edge 0 must be"),
            (
                r#"{"vertices": 2, "edges": [[0, 1], [0, 1, 2, 3]]}"#,
                "edge 1 must be",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 1], [0, 1, 2]]}"#,
                "edge 1 has a weight",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 1, 1], [0, 1]]}"#,
                "edge 1 has no weight",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, -1]]}"#,
                "edge 0: vertex ids",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 0.5]]}"#,
                "edge 0: vertex ids",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 1, "w"]]}"#,
                "edge 0: the weight",
            ),
            (
                r#"{"vertices": 2, "edges": [], "colour": 1}"#,
                "unexpected key 'colour'",
            ),
        ] {
            match parse_json_graph(text) {
                Err(CliError::Shape(m)) => assert!(m.contains(needle), "{text}: {m}"),
                other => panic!("{text}: {other:?}"),
            }
        }
        match parse_json_graph("{\"vertices\": 2,\n \"edges\": [[0, 1, 1e999]]}") {
            Err(CliError::Json {
                line: 2, message, ..
            }) => {
                assert!(message.contains("out of range"), "{message}")
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            parse_json_graph(r#"{"vertices": 2, "edges": [[0, 1, NaN]]}"#),
            Err(CliError::Json { .. })
        ));
    }
}
