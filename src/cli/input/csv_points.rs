//! The CSV point reader: lines `x,y`, blank lines skipped, an optional `x,y` header.

use crate::cli::CliError;
use crate::geometry::Point2;
use crate::spline::parse_f64_or_word;
use crate::util::quote;

/// Parses CSV lines `x,y` (syntax in [`crate::cli::input`]); the command validates the points
/// when it builds its [`PointSet`](crate::geometry::PointSet).
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
            parse_f64_or_word(field).ok_or_else(|| CliError::Csv {
                line: number,
                message: format!("{} is not a number", quote(field)),
            })
        };
        points.push(Point2::new(parse(fields[0])?, parse(fields[1])?));
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::PointSet;

    /// What a command does with the points it reads: build the validated set.
    fn validated(pts: Result<Vec<Point2>, CliError>) -> Result<Vec<Point2>, CliError> {
        let pts = pts?;
        PointSet::new(&pts)?;
        Ok(pts)
    }

    fn bits(pts: &[Point2]) -> Vec<(u64, u64)> {
        pts.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect()
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
        let err = validated(parse_csv_points("0,0\n1,1\n2,2\nnan,3\n")).unwrap_err();
        assert_eq!(err.to_string(), "point 3 has a non-finite coordinate (NaN)");
        let err = validated(parse_csv_points("0,0\n\n-inf,1\n")).unwrap_err();
        assert_eq!(
            err.to_string(),
            "point 1 has a non-finite coordinate (-inf)"
        );
        for (text, line, needle) in [
            ("1,2\n3\n", 2, "expected 2 fields x,y, found 1"),
            ("1,2\n\n3,4,5\n", 3, "found 3"),
            ("1,2\n3,abc\n", 2, "\"abc\" is not a number"),
            ("1,2\nx,y\n", 2, "\"x\" is not a number"),
            ("lon,lat\n1,2\n", 1, "\"lon\" is not a number"),
            ("1,\u{1b}[31m\n", 1, "\"\\u{1b}[31m\" is not a number"),
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
}
