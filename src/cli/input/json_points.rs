//! The JSON point reader: a small cursor for the one shape `[[x, y], ...]`, so that every
//! error can name the point and its line and column.

use crate::cli::CliError;
use crate::geometry::Point2;
use crate::util::quote;

/// Parses a JSON point array `[[x, y], ...]`; the command validates the points when it
/// builds its [`PointSet`](crate::geometry::PointSet).
///
/// # Errors
/// [`CliError::Json`] with line and column for malformed JSON or a value that is not a
/// number where a coordinate belongs (naming the point), [`CliError::Arity`] for a point
/// without exactly two coordinates. NaN, infinities and overflowing literals parse (so that
/// validation can name the point) and are rejected by the [`PointSet`](crate::geometry::PointSet).
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
    Ok(points)
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
                    "point {index}: expected a number, found {}",
                    quote(&self.text[start..word_start + word_len])
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
        // The grammar above is a subset of the decimals `parse_f64` rounds correctly (at
        // any length and exponent, which `str::parse` does not).
        let text = &self.text[start..self.pos];
        crate::spline::parse_f64(text).ok_or_else(|| {
            self.error(format!(
                "point {index}: expected a number, found {}",
                quote(text)
            ))
        })
    }

    /// The next token (up to whitespace or a delimiter, else the one character there),
    /// quoted, for error messages.
    fn found(&self) -> String {
        let rest = &self.text[self.pos..];
        let end = rest
            .find(|c: char| c.is_whitespace() || matches!(c, ',' | ']' | '['))
            .unwrap_or(rest.len());
        match rest.chars().next() {
            None => "the end of input".to_string(),
            Some(c) if end == 0 => quote(c.encode_utf8(&mut [0; 4])),
            Some(_) => quote(&rest[..end]),
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
            let pts = json(text).unwrap();
            let err = CliError::from(crate::geometry::PointSet::new(&pts).unwrap_err());
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
            ("{}", 1, 1, "found \"{}\""),
            ("[[1, 2]", 1, 8, "after point 0"),
            ("[[1, 2],\n [3, 4] [5, 6]]", 2, 9, "after point 1"),
            ("[[1, 2]] x", 1, 10, "end of input after"),
            ("[[1, \"2\"]]", 1, 6, "point 0: expected a number"),
            ("[[01, 2]]", 1, 3, "point 0: expected a number"),
            ("[[1., 2]]", 1, 3, "point 0"),
            ("[[+1, 2]]", 1, 3, "point 0"),
            ("[[.5, 2]]", 1, 3, "point 0"),
            ("[[1e, 2]]", 1, 3, "point 0"),
            ("[[true, 2]]", 1, 3, "found \"true\""),
            ("[[\u{7}, 2]]", 1, 3, "found \"\\u{7}\""),
            (
                "[[[[[[[[1]]]]]]]]",
                1,
                3,
                "point 0: expected a number, found \"[\"",
            ),
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
}
