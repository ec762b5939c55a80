//! Entry points for coverage-guided fuzzing, and the checks they run: not part of the API.
//!
//! Each function takes the fuzzer's raw bytes, runs one reader, builder or predicate family
//! on them and **panics** if a property fails: a panic is how libFuzzer (the `fuzz/` crate,
//! see "Fuzzing" in `docs/design.md`) notices a finding. The same functions replay the
//! stored findings in the regression test `tests/suite/fuzz_regressions.rs`, so a target and
//! its regression test cannot drift apart.
//!
//! | function | runs | checks |
//! |---|---|---|
//! | `json_points` | the JSON point reader | agrees with `serde_json` on valid JSON; finite points survive re-serialising as JSON and CSV |
//! | `csv_points` | the CSV point reader | agrees with a line-by-line oracle, error line included; round trip |
//! | `graph_json` | the graph reader | ids in range, weights on all edges or none; round trip |
//! | `number_arrays` | the exact number-list reader (curve control points, knots) | agrees with `serde_json` on valid JSON numbers; round trip |
//! | `exact_decimal` | `parse_scalar` for `BigRational` and `f64` | the exact value of the decimal or fraction; `f64` correctly rounded, as `str::parse` |
//! | `hull` | every hull algorithm, both options | the exact hull checkers; all algorithms agree |
//! | `delaunay` | every Delaunay builder | [`check_delaunay`](crate::delaunay::check_delaunay) |
//! | `voronoi` | the Voronoi diagram | structure against the exact triangulation; vertices against exact circumcentres |
//! | `predicates` | `orient2d`, `incircle`, `cmp_dist`, `cross_sign` | the sign of the exact rational expression |
//! | `bezier` | Bézier eval, split, elevation, derivatives in `f64` | the `BigRational` back end, within rounding bounds |
//! | `obj` | the Wavefront OBJ reader and the mesh validation, `f64` and exact | accepted meshes keep their invariants, round-trip through `write_obj` and through a Catmull–Clark round; both scalars read the same faces |
//! | `bspline` | every B-spline operation and NURBS eval, insert, elevate in `f64` | the `BigRational` back end, within rounding bounds; overflow only near `f64::MAX` |
//!
//! Every function returns normally on inputs it does not apply to (invalid UTF-8 for a text
//! reader); an error the library returns is checked, not a failure in itself.
//!
//! The checks are strict: none skips the inputs of a known bug. A finding awaiting a fix is
//! stored under `tests/fixtures/fuzz/pending/` (not replayed); should a check have to skip
//! such inputs meanwhile, so that a fuzzing run goes on past them, the skip is a `known_`
//! function naming the stored input, and it goes with the fix.

mod bezier;
mod bspline;
mod geometry;
mod mesh;
mod readers;

pub use bezier::bezier;
pub use bspline::bspline;
pub use geometry::{delaunay, hull, predicates, voronoi};
pub use mesh::obj;
pub use readers::{csv_points, exact_decimal, graph_json, json_points, number_arrays};

use num_rational::BigRational;

/// The fuzzer's bytes as coordinates. Every coordinate starts with a tag byte choosing how
/// it is made, so that short inputs reach the degenerate cases (duplicates, collinear and
/// cocircular points, one-ulp perturbations, mixed magnitudes) that raw bit patterns
/// almost never hit, while raw bit patterns (NaN and infinities included) stay reachable.
pub(crate) struct Decoder<'a> {
    data: &'a [u8],
    pos: usize,
    made: Vec<f64>,
}

impl<'a> Decoder<'a> {
    pub(crate) fn new(data: &'a [u8]) -> Self {
        Decoder {
            data,
            pos: 0,
            made: Vec::new(),
        }
    }

    /// The next byte, if any.
    pub(crate) fn byte(&mut self) -> Option<u8> {
        let b = *self.data.get(self.pos)?;
        self.pos += 1;
        Some(b)
    }

    /// The next coordinate, if the bytes last; any f64, NaN and infinities included.
    pub(crate) fn coordinate(&mut self) -> Option<f64> {
        let tag = self.byte()?;
        let earlier = |d: &mut Self| -> Option<f64> {
            let k = d.byte()? as usize;
            Some(if d.made.is_empty() {
                0.0
            } else {
                d.made[k % d.made.len()]
            })
        };
        let x = match tag % 8 {
            // A small integer: grids are full of collinear and cocircular points.
            0..=2 => f64::from(self.byte()? as i8),
            // A small integer times a power of two in [2^-1100, 2^1100): mixed magnitudes,
            // subnormals, 0 and (rarely) overflow to infinity.
            3 => {
                let m = f64::from(self.byte()? as i8);
                let e = i32::from(i16::from_le_bytes([self.byte()?, self.byte()?]) % 1100);
                scale(m, e)
            }
            // Any bit pattern.
            4 => {
                let mut b = [0u8; 8];
                for v in &mut b {
                    *v = self.byte()?;
                }
                f64::from_bits(u64::from_le_bytes(b))
            }
            // An earlier coordinate again: duplicates and axis-parallel lines.
            5 => earlier(self)?,
            // An earlier coordinate moved by one ulp: near-degenerate configurations.
            6 => {
                let v = earlier(self)?;
                if tag & 8 == 0 {
                    v.next_up()
                } else {
                    v.next_down()
                }
            }
            // The negation of an earlier one: symmetric configurations.
            _ => -earlier(self)?,
        };
        self.made.push(x);
        Some(x)
    }

    /// Up to `max` points, two coordinates each, until the bytes run out.
    pub(crate) fn points(&mut self, max: usize) -> Vec<crate::geometry::Point2> {
        let mut pts = Vec::new();
        while pts.len() < max {
            let (Some(x), Some(y)) = (self.coordinate(), self.coordinate()) else {
                break;
            };
            pts.push(crate::geometry::Point2::new(x, y));
        }
        pts
    }
}

/// `m · 2^e`, exact unless it underflows or overflows (then as IEEE rounds).
fn scale(m: f64, e: i32) -> f64 {
    // Three steps keep every factor a normal power of two.
    let step = |x: f64, e: i32| x * f64::from_bits(((e + 1023) as u64) << 52);
    let e1 = e.clamp(-1000, 1000);
    let e2 = (e - e1).clamp(-1000, 1000);
    step(step(m, e1), e2)
}

/// The exact value of a finite `f64`.
pub(crate) fn exact(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

/// The nearest `f64` to `r` (±∞ beyond the range).
pub(crate) fn nearest(r: &BigRational) -> f64 {
    crate::spline::Scalar::to_f64(r)
}

/// `|r|` as an `f64` rounded to nearest, +∞ if beyond the range.
pub(crate) fn magnitude(r: &BigRational) -> f64 {
    nearest(r).abs()
}

/// A message for the `error:` line: not empty, one line with no control character at all
/// (readers quote what they echo with control characters escaped) and short (an echoed
/// token is cut after 40 characters of its escaped form, `src/util/quote.rs`).
pub(crate) fn check_message(what: &str, message: &str) {
    assert!(!message.is_empty(), "{what}: an empty error message");
    assert!(
        !message.chars().any(char::is_control),
        "{what}: a control character in the error message {message:?}"
    );
    assert!(
        message.chars().count() <= MAX_MESSAGE,
        "{what}: an error message of {} characters: {message:?}",
        message.chars().count()
    );
}

/// The longest error message [`check_message`] accepts: far more than a few cut tokens and
/// the words around them, far less than the fuzzers' inputs (up to 1024 bytes) echoed whole.
const MAX_MESSAGE: usize = 640;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_decoder_makes_every_kind_of_coordinate() {
        // Tag 0: small integer; 3: scaled; 4: raw bits; 5: repeat; 6: next ulp; 7: negation.
        let mut bytes = vec![0, 0xfd, 3, 5, 0x0a, 0x00];
        bytes.push(4);
        bytes.extend(f64::NAN.to_bits().to_le_bytes());
        bytes.extend([5, 0, 6, 1, 7, 1]);
        let mut d = Decoder::new(&bytes);
        let got: Vec<f64> = std::iter::from_fn(|| d.coordinate()).collect();
        assert_eq!(got.len(), 6);
        assert_eq!(got[0], -3.0);
        assert_eq!(got[1], 5.0 * 2f64.powi(10));
        assert!(got[2].is_nan());
        assert_eq!(got[3], -3.0);
        assert_eq!(got[4], 5120f64.next_up());
        assert_eq!(got[5], -5120.0);
        assert_eq!(scale(1.0, -1074), 5e-324);
        assert_eq!(scale(1.0, 1024), f64::INFINITY);
    }

    #[test]
    fn an_escaped_short_message_passes_the_check() {
        check_message("csv", "invalid CSV at line 1: \"-\\r0\" is not a number");
    }

    #[test]
    #[should_panic(expected = "a control character")]
    fn a_raw_line_break_fails_the_message_check() {
        check_message("graph", "unexpected key 'a\r\nb' in the graph object");
    }

    #[test]
    #[should_panic(expected = "an error message of 2008 characters")]
    fn a_token_echoed_whole_fails_the_message_check() {
        check_message("decimal", &"0".repeat(2008));
    }
}
