//! A reader for lists of points whose numbers must keep their exact text: JSON arrays
//! `[[x, y, ...], ...]` (or `[x, ...]` for points of one coordinate) whose entries are JSON
//! numbers or strings holding a number (`"47/18"`, `"0.1"`).
//!
//! `serde_json` turns every number into an `f64` on reading, so `0.1` would already be
//! rounded; the exact (`--exact`) commands need the digits as written. Converting the text
//! is the caller's job ([`crate::spline::parse_scalar`]).

use crate::cli::CliError;
use crate::util::quote;

/// The entries of a JSON list of points, as the text of each number.
///
/// `[[0, 1], ["1/3", 2.5]]` gives `[["0", "1"], ["1/3", "2.5"]]`; a flat list `[1, "2/3"]`
/// gives one-coordinate points `[["1"], ["2/3"]]`.
///
/// # Errors
///
/// [`CliError::Json`] with the line and column of a syntax error; [`CliError::Shape`] if
/// the list is empty, mixes numbers and arrays, or its points differ in length.
pub fn parse_number_arrays(text: &str) -> Result<Vec<Vec<String>>, CliError> {
    let items = parse_items(text, 1)?;
    let points: Vec<Vec<String>> = if items.iter().all(|i| matches!(i, Item::Number(_))) {
        items
            .into_iter()
            .map(|i| match i {
                Item::Number(s) => vec![s],
                Item::List(_) => unreachable!("checked above"),
            })
            .collect()
    } else {
        items
            .into_iter()
            .enumerate()
            .map(|(index, i)| match i {
                Item::List(v) => Ok(Item::numbers(v)),
                Item::Number(_) => Err(CliError::Shape(format!(
                    "point {index} is a number, but other points are lists"
                ))),
            })
            .collect::<Result<_, _>>()?
    };
    if points.is_empty() {
        return Err(CliError::Shape("the list of points is empty".to_string()));
    }
    let d = points[0].len();
    if d == 0 {
        return Err(CliError::Shape("point 0 has no coordinates".to_string()));
    }
    if let Some((index, p)) = points.iter().enumerate().find(|(_, p)| p.len() != d) {
        return Err(CliError::Shape(format!(
            "point {index} has {} coordinates, but point 0 has {d}",
            p.len()
        )));
    }
    Ok(points)
}

/// The entries of a flat JSON list of numbers `[0, "1/2", 1]`, as the text of each number;
/// `what` names the list in errors ("knots").
///
/// # Errors
///
/// [`CliError::Json`] with the line and column of a syntax error; [`CliError::Shape`] if
/// the list is empty or an entry is a list, naming the entry.
pub fn parse_number_list(text: &str, what: &str) -> Result<Vec<String>, CliError> {
    let items = parse_items(text, 1)?;
    if items.is_empty() {
        return Err(CliError::Shape(format!("the list of {what} is empty")));
    }
    items
        .into_iter()
        .enumerate()
        .map(|(index, i)| match i {
            Item::Number(s) => Ok(s),
            Item::List(v) => Err(CliError::Shape(format!(
                "expected a flat list of numbers for the {what}; entry {index} is a list of {} {}",
                v.len(),
                if v.len() == 1 { "number" } else { "numbers" }
            ))),
        })
        .collect()
}

/// The entries of a JSON grid of points `[[[x, y, z], ...], ...]` (a control net: a list of
/// rows, each a list of points), as the text of each number.
///
/// # Errors
///
/// [`CliError::Json`] with the line and column of a syntax error; [`CliError::Shape`] if
/// the grid or a row is empty, an entry has the wrong nesting, the rows differ in length or
/// the points in their number of coordinates, naming the row and column.
pub fn parse_number_grid(text: &str) -> Result<Vec<Vec<Vec<String>>>, CliError> {
    let rows = parse_items(text, 2)?;
    if rows.is_empty() {
        return Err(CliError::Shape(
            "the grid of points has no rows".to_string(),
        ));
    }
    let mut grid = Vec::with_capacity(rows.len());
    for (i, row) in rows.into_iter().enumerate() {
        let Item::List(row) = row else {
            return Err(CliError::Shape(format!(
                "row {i} is a number; a grid is a list of rows of points"
            )));
        };
        let mut points = Vec::with_capacity(row.len());
        for (j, p) in row.into_iter().enumerate() {
            match p {
                Item::List(p) => points.push(Item::numbers(p)),
                Item::Number(_) => {
                    return Err(CliError::Shape(format!(
                        "point ({i}, {j}) is a number; a grid's points are lists of coordinates"
                    )))
                }
            }
        }
        grid.push(points);
    }
    let columns = grid[0].len();
    let dimension = grid[0].first().map_or(0, Vec::len);
    for (i, row) in grid.iter().enumerate() {
        if row.is_empty() {
            return Err(CliError::Shape(format!("row {i} of the grid is empty")));
        }
        if row.len() != columns {
            return Err(CliError::Shape(format!(
                "row {i} has {} points, but row 0 has {columns}",
                row.len()
            )));
        }
        if let Some((j, p)) = row.iter().enumerate().find(|(_, p)| p.len() != dimension) {
            return Err(CliError::Shape(format!(
                "point ({i}, {j}) has {} coordinates, but point (0, 0) has {dimension}",
                p.len()
            )));
        }
    }
    if dimension == 0 {
        return Err(CliError::Shape(
            "point (0, 0) has no coordinates".to_string(),
        ));
    }
    Ok(grid)
}

/// The items of the outer list, the whole text read, with lists nested at most `max_depth`
/// levels inside it.
fn parse_items(text: &str, max_depth: usize) -> Result<Vec<Item>, CliError> {
    // Offsets index the text after the byte-order mark, which the errors' positions count.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut p = Parser {
        chars: text.char_indices().collect(),
        pos: 0,
        text,
        max_depth,
    };
    let items = p.array(0)?;
    p.skip_ws();
    if p.pos < p.chars.len() {
        return Err(p.error("trailing characters after the list"));
    }
    Ok(items)
}

enum Item {
    Number(String),
    List(Vec<Item>),
}

impl Item {
    /// The numbers of a list whose entries are numbers (the parser's depth guarantees it).
    fn numbers(items: Vec<Item>) -> Vec<String> {
        items
            .into_iter()
            .filter_map(|i| match i {
                Item::Number(s) => Some(s),
                Item::List(_) => None,
            })
            .collect()
    }
}

struct Parser<'a> {
    chars: Vec<(usize, char)>,
    pos: usize,
    text: &'a str,
    max_depth: usize,
}

impl Parser<'_> {
    /// An array at nesting `depth` (0: the outer list); arrays nest at most `max_depth`
    /// levels below it (1 for a list of points, 2 for a grid of them), so the recursion is
    /// bounded whatever the text.
    fn array(&mut self, depth: usize) -> Result<Vec<Item>, CliError> {
        self.skip_ws();
        self.expect('[')?;
        let mut items = Vec::new();
        self.skip_ws();
        if self.peek() == Some(']') {
            self.pos += 1;
            return Ok(items);
        }
        loop {
            self.skip_ws();
            let item = match self.peek() {
                Some('[') if depth < self.max_depth => Item::List(self.array(depth + 1)?),
                Some('"') => Item::Number(self.string()?),
                Some(c) if c == '-' || c == '+' || c == '.' || c.is_ascii_alphanumeric() => {
                    Item::Number(self.bare_number())
                }
                other => {
                    let found = match other {
                        Some(c) => quote(c.encode_utf8(&mut [0; 4])),
                        None => "the end of input".to_string(),
                    };
                    return Err(self.error(&format!(
                        "expected a number, a string or a point, found {found}"
                    )));
                }
            };
            items.push(item);
            self.skip_ws();
            match self.peek() {
                Some(',') => self.pos += 1,
                Some(']') => {
                    self.pos += 1;
                    return Ok(items);
                }
                _ => return Err(self.error("expected ',' or ']'")),
            }
        }
    }

    /// A run of number-like characters; the number parser says whether it is valid
    /// (words such as `NaN` get a message naming them there).
    fn bare_number(&mut self) -> String {
        let start = self.pos;
        while let Some(c) = self.peek() {
            if c.is_ascii_alphanumeric() || matches!(c, '-' | '+' | '.' | '/') {
                self.pos += 1;
            } else {
                break;
            }
        }
        self.chars[start..self.pos]
            .iter()
            .map(|&(_, c)| c)
            .collect()
    }

    fn string(&mut self) -> Result<String, CliError> {
        self.expect('"')?;
        let start = self.pos;
        while let Some(c) = self.peek() {
            match c {
                '"' => {
                    let s = self.chars[start..self.pos]
                        .iter()
                        .map(|&(_, c)| c)
                        .collect();
                    self.pos += 1;
                    return Ok(s);
                }
                '\\' => return Err(self.error("escapes are not allowed in a number string")),
                _ => self.pos += 1,
            }
        }
        Err(self.error("unterminated string"))
    }

    fn expect(&mut self, c: char) -> Result<(), CliError> {
        if self.peek() == Some(c) {
            self.pos += 1;
            Ok(())
        } else {
            Err(self.error(&format!("expected '{c}'")))
        }
    }

    fn peek(&self) -> Option<char> {
        self.chars.get(self.pos).map(|&(_, c)| c)
    }

    fn skip_ws(&mut self) {
        while matches!(self.peek(), Some(' ' | '\t' | '\n' | '\r')) {
            self.pos += 1;
        }
    }

    fn error(&self, message: &str) -> CliError {
        let byte = self
            .chars
            .get(self.pos)
            .map_or(self.text.len(), |&(b, _)| b);
        let before = &self.text[..byte.min(self.text.len())];
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        CliError::Json {
            line,
            column,
            message: message.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_the_text_of_every_number() {
        let p = parse_number_arrays(r#" [[0, 1.50], ["1/3", -2e-3]] "#).unwrap();
        assert_eq!(p, [["0", "1.50"], ["1/3", "-2e-3"]]);
        let flat = parse_number_arrays(r#"[1, "2/3"]"#).unwrap();
        assert_eq!(flat, [["1"], ["2/3"]]);
    }

    #[test]
    fn reports_shape_and_syntax_problems() {
        assert!(matches!(
            parse_number_arrays("[[1, 2], [3]]"),
            Err(CliError::Shape(_))
        ));
        assert!(matches!(parse_number_arrays("[]"), Err(CliError::Shape(_))));
        assert!(matches!(
            parse_number_arrays("[[1], 2]"),
            Err(CliError::Shape(_))
        ));
        match parse_number_arrays("[[1, 2],\n [3 4]]") {
            Err(CliError::Json {
                line: 2, column, ..
            }) => assert_eq!(column, 5),
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            parse_number_arrays("[[1, 2]] x"),
            Err(CliError::Json { .. })
        ));
        assert!(matches!(
            parse_number_arrays("[[[1]]]"),
            Err(CliError::Json { .. })
        ));
        // Deep nesting is refused at the third level, without recursion.
        let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
        match parse_number_arrays(&deep) {
            Err(CliError::Json {
                line: 1,
                column: 3,
                message,
            }) => assert_eq!(
                message,
                "expected a number, a string or a point, found \"[\""
            ),
            other => panic!("{other:?}"),
        }
        // Positions count from after a byte-order mark.
        match parse_number_arrays("\u{feff}[[1, 2],\n [3 4]]") {
            Err(CliError::Json {
                line: 2, column, ..
            }) => assert_eq!(column, 5),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn grids_keep_their_text_and_name_the_bad_row_or_point() {
        let g = parse_number_grid(r#"[[[0, 1], ["1/3", 2]], [[4, 5], [6, "-7e-1"]]]"#).unwrap();
        assert_eq!(
            g,
            [[["0", "1"], ["1/3", "2"]], [["4", "5"], ["6", "-7e-1"]]]
        );
        for (text, message) in [
            ("[]", "the grid of points has no rows"),
            (
                "[[[1]], 2]",
                "row 1 is a number; a grid is a list of rows of points",
            ),
            (
                "[[[1], 2]]",
                "point (0, 1) is a number; a grid's points are lists of coordinates",
            ),
            ("[[[1], [2]], [[3]]]", "row 1 has 1 points, but row 0 has 2"),
            (
                "[[[1], [2, 3]]]",
                "point (0, 1) has 2 coordinates, but point (0, 0) has 1",
            ),
            ("[[[1]], []]", "row 1 of the grid is empty"),
            ("[[[]]]", "point (0, 0) has no coordinates"),
        ] {
            match parse_number_grid(text) {
                Err(CliError::Shape(m)) => assert_eq!(m, message, "{text}"),
                other => panic!("{text}: {other:?}"),
            }
        }
        // A fourth level is a syntax error, as a third is for a list of points.
        assert!(matches!(
            parse_number_grid("[[[[1]]]]"),
            Err(CliError::Json { .. })
        ));
    }

    #[test]
    fn flat_lists_name_the_entry_that_is_not_a_number() {
        assert_eq!(
            parse_number_list(r#"[0, "1/2", 1e-3]"#, "knots").unwrap(),
            ["0", "1/2", "1e-3"]
        );
        for (text, message) in [
            (
                "[0, [1], 2]",
                "expected a flat list of numbers for the knots; entry 1 is a list of 1 number",
            ),
            (
                "[[0, 1], [2, 3]]",
                "expected a flat list of numbers for the knots; entry 0 is a list of 2 numbers",
            ),
            ("[]", "the list of knots is empty"),
        ] {
            match parse_number_list(text, "knots") {
                Err(CliError::Shape(m)) => assert_eq!(m, message, "{text}"),
                other => panic!("{text}: {other:?}"),
            }
        }
    }
}
