//! The readers' fuzz checks: each reader against an independent oracle where one exists
//! (`serde_json` for valid JSON, `str::parse` for decimals, a line-by-line CSV reading), and
//! a round trip through the text the command line itself would write.

use super::check_message;
use crate::cli::input::{
    parse_csv_points, parse_json_graph, parse_json_points, parse_number_arrays,
};
use crate::geometry::Point2;
use crate::spline::parse_scalar;
use num_bigint::BigInt;
use num_rational::BigRational;

fn bits(pts: &[Point2]) -> Vec<(u64, u64)> {
    pts.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect()
}

fn all_finite(pts: &[Point2]) -> bool {
    pts.iter().all(|p| p.x.is_finite() && p.y.is_finite())
}

/// The JSON point reader (`compgeo hull -` and every point command).
///
/// - Valid JSON of the shape `[[x, y], ...]` (as `serde_json` reads it, correctly rounded)
///   is accepted with the same values, bit for bit.
/// - Anything `serde_json` rejects is rejected, except the non-finite words and overflowing
///   literals the reader accepts on purpose (so that validation can name the point): then a
///   coordinate is non-finite.
/// - Finite points written as the command line writes JSON, and as CSV lines, read back
///   bit for bit.
/// - Errors are one line.
pub fn json_points(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let ours = parse_json_points(text);
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let theirs: Result<Vec<[f64; 2]>, _> = serde_json::from_str(body);
    match (&ours, &theirs) {
        (Ok(p), Ok(q)) => {
            let q: Vec<Point2> = q.iter().map(|&c| Point2::from(c)).collect();
            assert_eq!(bits(p), bits(&q), "serde_json reads other values");
        }
        (Ok(p), Err(e)) => assert!(
            !all_finite(p),
            "accepted finite points that serde_json rejects ({e}): {p:?}"
        ),
        (Err(e), Ok(_)) => panic!("rejected valid JSON: {e}"),
        (Err(e), Err(_)) => check_message("json points", &e.to_string()),
    }
    if let Ok(p) = ours {
        if all_finite(&p) {
            round_trip(&p);
        }
    }
}

/// Finite points through the JSON the command line prints and through CSV lines.
fn round_trip(p: &[Point2]) {
    let pairs: Vec<[f64; 2]> = p.iter().map(|q| [q.x, q.y]).collect();
    let json = serde_json::to_string(&pairs).expect("finite values serialise");
    let back = parse_json_points(&json).expect("the printed JSON reads back");
    assert_eq!(bits(&back), bits(p), "JSON round trip of {json}");
    let csv: String = p.iter().map(|q| format!("{:?},{:?}\n", q.x, q.y)).collect();
    let back = parse_csv_points(&csv).expect("the CSV lines read back");
    assert_eq!(bits(&back), bits(p), "CSV round trip of {csv:?}");
}

/// The CSV point reader.
///
/// Compared with an oracle written independently from the documented syntax (lines by
/// `str::lines`, trimmed, blank ones skipped, an optional first `x,y` header, two fields
/// read by `str::parse::<f64>`): the same points bit for bit, or both an error on the same
/// line. Finite points round-trip as for `json_points`; errors are one line.
pub fn csv_points(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let ours = parse_csv_points(text);
    match (&ours, csv_oracle(text)) {
        (Ok(p), Ok(q)) => assert_eq!(bits(p), bits(&q), "the oracle reads other values"),
        (Ok(p), Err(line)) => panic!("accepted {p:?}; the oracle rejects line {line}"),
        (Err(e), Ok(q)) => panic!("rejected ({e}); the oracle reads {q:?}"),
        (Err(e), Err(line)) => {
            let message = e.to_string();
            check_message("csv points", &message);
            assert!(
                message.starts_with(&format!("invalid CSV at line {line}:")),
                "the oracle rejects line {line}: {message}"
            );
        }
    }
    if let Ok(p) = ours {
        if all_finite(&p) {
            round_trip(&p);
        }
    }
}

/// The documented CSV syntax, read another way; `Err(line)` names the first bad line.
fn csv_oracle(text: &str) -> Result<Vec<Point2>, usize> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut points = Vec::new();
    let mut first = true;
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let was_first = std::mem::replace(&mut first, false);
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if was_first
            && fields.len() == 2
            && fields[0].eq_ignore_ascii_case("x")
            && fields[1].eq_ignore_ascii_case("y")
        {
            continue;
        }
        let [x, y] = fields[..] else {
            return Err(i + 1);
        };
        match (x.parse::<f64>(), y.parse::<f64>()) {
            (Ok(x), Ok(y)) => points.push(Point2::new(x, y)),
            _ => return Err(i + 1),
        }
    }
    Ok(points)
}

/// The JSON graph reader (`compgeo mst`, `bfs`, `colour`, ...).
///
/// An accepted graph has every vertex id below `vertices`, a weight on every edge or on
/// none (and weighted exactly when edge 0 has three entries), finite weights, and reads back
/// equal from the JSON it is written as. Errors are one line.
pub fn graph_json(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let g = match parse_json_graph(text) {
        Ok(g) => g,
        Err(e) => return check_message("graph", &e.to_string()),
    };
    assert!(
        g.edges.iter().flatten().all(|&v| v < g.vertices),
        "a vertex id out of range in {g:?}"
    );
    let edges: Vec<serde_json::Value> = match &g.weights {
        Some(w) => {
            assert_eq!(w.len(), g.edges.len(), "weights on some edges only");
            assert!(w.iter().all(|w| w.is_finite()), "a non-finite weight");
            g.edges
                .iter()
                .zip(w)
                .map(|(&[u, v], &w)| serde_json::json!([u, v, w]))
                .collect()
        }
        None => g
            .edges
            .iter()
            .map(|&[u, v]| serde_json::json!([u, v]))
            .collect(),
    };
    if !g.edges.is_empty() {
        let doc: serde_json::Value =
            serde_json::from_str(text.strip_prefix('\u{feff}').unwrap_or(text))
                .expect("the reader accepted it");
        let first_len = doc["edges"][0].as_array().map(Vec::len);
        assert_eq!(g.weights.is_some(), first_len == Some(3));
    }
    let written = serde_json::json!({"vertices": g.vertices, "edges": edges}).to_string();
    let back = parse_json_graph(&written).expect("the written graph reads back");
    assert_eq!(back, g, "round trip of {written}");
}

/// The exact number-list reader (`--control`, `--points`, `--knots` of the curve commands).
///
/// An accepted list is non-empty and rectangular (an entry may be any text, `""` included:
/// the number parser judges it), and it reads back
/// the same from the list written with every entry as a JSON string. Where `serde_json`
/// reads the text as a list of numbers (or of lists of numbers) the reader accepts it too,
/// with the same shape, each entry's text being that number's literal. Errors are one line.
pub fn number_arrays(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let ours = parse_number_arrays(text);
    let body = text.strip_prefix('\u{feff}').unwrap_or(text);
    let theirs: Option<Vec<Vec<f64>>> = serde_json::from_str::<Vec<Vec<f64>>>(body)
        .ok()
        .or_else(|| {
            serde_json::from_str::<Vec<f64>>(body)
                .ok()
                .map(|v| v.into_iter().map(|x| vec![x]).collect())
        })
        .filter(|v: &Vec<Vec<f64>>| {
            !v.is_empty() && !v[0].is_empty() && v.iter().all(|p| p.len() == v[0].len())
        });
    let points = match ours {
        Ok(points) => points,
        Err(e) => {
            assert!(theirs.is_none(), "rejected valid numbers {theirs:?}: {e}");
            return check_message("number arrays", &e.to_string());
        }
    };
    assert!(!points.is_empty() && !points[0].is_empty());
    let d = points[0].len();
    assert!(points.iter().all(|p| p.len() == d), "ragged: {points:?}");
    if let Some(theirs) = theirs {
        let shape = |v: &[Vec<f64>]| v.iter().map(Vec::len).collect::<Vec<_>>();
        let ours_shape: Vec<usize> = points.iter().map(Vec::len).collect();
        assert_eq!(ours_shape, shape(&theirs));
        for (s, x) in points.iter().flatten().zip(theirs.iter().flatten()) {
            assert_eq!(s.parse::<f64>().ok(), Some(*x), "entry {s:?}");
        }
    }
    let written = format!(
        "[{}]",
        points
            .iter()
            .map(|p| format!(
                "[{}]",
                p.iter()
                    .map(|s| format!("\"{s}\""))
                    .collect::<Vec<_>>()
                    .join(",")
            ))
            .collect::<Vec<_>>()
            .join(",")
    );
    let back = parse_number_arrays(&written).expect("the written list reads back");
    assert_eq!(back, points, "round trip of {written}");
}

/// `parse_scalar` (the exact decimals and fractions of `--exact`, `--t`, knots and control
/// points) for `BigRational` and `f64`.
///
/// Both scalars accept the same texts, except the plain decimals beyond the exact reader's
/// documented bound (more than `MAX_EXACT_DIGITS` significant digits, or nonzero and below
/// 1e−`MAX_EXACT_EXPONENT` in magnitude, judged here from the text independently), which
/// `f64` rounds and `BigRational` refuses. An accepted decimal's rational is exactly
/// ±digits·10^(exponent − fraction digits), built here from the text independently, and a
/// fraction's is the quotient of its two decimals; the `f64` is the rational correctly
/// rounded, which for a decimal is what `str::parse::<f64>` gives. A decimal that
/// `str::parse` reads as a nonzero finite double is accepted by `f64`. Errors are one line
/// and name the parameter.
pub fn exact_decimal(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let r = parse_scalar::<BigRational>(text, "x");
    let f = parse_scalar::<f64>(text, "x");
    let plain = decimal_oracle(text.trim());
    match (&r, &f) {
        (Ok(r), Ok(f)) => {
            let rounded = super::nearest(r);
            assert!(
                rounded == *f,
                "f64 {f:e} is not the rational rounded, {rounded:e}"
            );
            if let Some(expected) = exact_oracle(text.trim()) {
                assert_eq!(*r, expected, "not the exact value of {text:?}");
            }
            // By value: a rational has no sign of zero, so "-0" is 0 (not -0.0, which the
            // command line never prints anyway).
            if let Some(Ok(x)) = &plain {
                assert!(x == f, "str::parse rounds {text:?} to {x:e}, not {f:e}");
            }
        }
        (Err(a), Err(b)) => {
            for e in [a.to_string(), b.to_string()] {
                check_message("exact decimal", &e);
                assert!(e.starts_with("invalid x: "), "{e}");
            }
            if let Some(Ok(x)) = plain {
                assert!(
                    !(x.is_finite() && x != 0.0),
                    "rejected {text:?}, which str::parse reads as {x:e}: {a}"
                );
            }
        }
        (Err(a), Ok(f)) => {
            let a = a.to_string();
            check_message("exact decimal", &a);
            assert!(a.starts_with("invalid x: "), "{a}");
            assert!(
                breaks_exact_bound(text.trim()),
                "BigRational refuses {text:?}, which is within its bound ({a}); f64 reads {f:e}"
            );
            // Only a plain decimal can break the bound for one scalar alone: both read a
            // fraction's parts exactly.
            match &plain {
                Some(Ok(x)) => assert!(x == f, "str::parse rounds {text:?} to {x:e}, not {f:e}"),
                _ => {
                    panic!("f64 reads {text:?}, not a plain decimal, though BigRational refuses it")
                }
            }
        }
        (Ok(_), Err(b)) => panic!("BigRational reads {text:?}, f64 refuses it: {b}"),
    }
}

/// `str::parse::<f64>` of `text` if it is a plain decimal of the documented grammar
/// (`[+-]digits[.digits][(e|E)[+-]digits]`, a digit somewhere in the mantissa).
fn decimal_oracle(text: &str) -> Option<Result<f64, std::num::ParseFloatError>> {
    split_decimal(text).map(|_| text.parse::<f64>())
}

/// Whether `text` is a plain decimal beyond the bound of exact reading (`parse_scalar`,
/// "Bounded parsing"): nonzero with more than `MAX_EXACT_DIGITS` significant digits, or
/// with a magnitude below 1e−`MAX_EXACT_EXPONENT`.
fn breaks_exact_bound(text: &str) -> bool {
    let Some(((_, int, frac), exponent)) = split_decimal(text) else {
        return false;
    };
    let all = format!("{int}{frac}");
    let Some(first) = all.bytes().position(|b| b != b'0') else {
        return false;
    };
    let last = all
        .bytes()
        .rposition(|b| b != b'0')
        .expect("a nonzero digit");
    let significant = last - first + 1;
    // Saturating: an exponent of hundreds of digits is far past every bound either way.
    let (sign, e) = match exponent.strip_prefix('-') {
        Some(rest) => (-1, rest),
        None => (1, exponent.strip_prefix('+').unwrap_or(exponent)),
    };
    let e = e.bytes().fold(0i128, |acc, b| {
        acc.saturating_mul(10).saturating_add(i128::from(b - b'0'))
    });
    // 10^(magnitude − 1) ≤ |value| < 10^magnitude.
    let magnitude = (all.len() - first) as i128 - frac.len() as i128 + sign * e;
    significant > crate::spline::MAX_EXACT_DIGITS
        || magnitude <= -i128::from(crate::spline::MAX_EXACT_EXPONENT)
}

/// Sign, integer digits, fraction digits and exponent digits of a plain decimal, or `None`.
fn split_decimal(text: &str) -> Option<((bool, &str, &str), &str)> {
    let digits = |d: &str| d.bytes().all(|b| b.is_ascii_digit());
    let (negative, s) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text.strip_prefix('+').unwrap_or(text)),
    };
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], &s[i + 1..]),
        None => (s, "0"),
    };
    let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let e = exponent.strip_prefix(['+', '-']).unwrap_or(exponent);
    (int.len() + frac.len() > 0 && digits(int) && digits(frac) && !e.is_empty() && digits(e))
        .then_some(((negative, int, frac), exponent))
}

/// The exact value of a plain decimal or a fraction of two, built from the text.
fn exact_oracle(text: &str) -> Option<BigRational> {
    if let Some((p, q)) = text.split_once('/') {
        if q.contains('/') {
            return None;
        }
        let q = exact_oracle(q.trim())?;
        return (q != BigRational::from_integer(0.into()))
            .then(|| exact_oracle(p.trim()).map(|p| p / q))
            .flatten();
    }
    let ((negative, int, frac), exponent) = split_decimal(text)?;
    let mantissa: BigInt = format!("0{int}{frac}").parse().ok()?;
    // Zero whatever the exponent (which may be too long for the power below).
    if mantissa == BigInt::from(0) {
        return Some(BigRational::from_integer(mantissa));
    }
    let shift = exponent.parse::<i64>().ok()? - frac.len() as i64;
    let power = BigRational::from_integer(BigInt::from(10).pow(shift.unsigned_abs() as u32));
    let value = BigRational::from_integer(mantissa);
    let value = if shift >= 0 {
        value * power
    } else {
        value / power
    };
    Some(if negative { -value } else { value })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_exact_bound_is_judged_from_the_text() {
        let long_one = format!("1{}e-2001", "0".repeat(2001));
        let many_digits = format!("0.{}", "7".repeat(1001));
        let enough_digits = format!("0.{}", "7".repeat(1000));
        for (text, broken) in [
            ("1e-400", false),
            ("1e-401", true),
            ("0.001e-398", true),
            ("100e-402", false),
            ("0e-99999999999999999999", false),
            ("-1e-2001", true),
            (&long_one, false),
            (&many_digits, true),
            (&enough_digits, false),
            ("1/2", false),
        ] {
            assert_eq!(breaks_exact_bound(text), broken, "{text}");
        }
    }

    #[test]
    fn a_tiny_decimal_is_zero_in_f64_and_refused_exactly() {
        exact_decimal(b"1e-2001");
        exact_decimal(b"1e-401");
        exact_decimal(b"0e-9999999999");
    }
}
