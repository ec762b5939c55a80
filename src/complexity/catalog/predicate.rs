//! Catalog entries of the exact predicates of [`crate::geometry`]: O(1) per call, so each
//! entry makes n calls (Θ(n) in the predicate's own operation, exactly n) on the n
//! consecutive windows of generated points: call i reads points i, i + 1, ....
//!
//! What differs between the inputs is how often the floating-point filter cannot decide and
//! an exact stage runs, counted as [`exact_fallbacks`](crate::count::Counts::exact_fallbacks)
//! besides the calls. At 16384 calls (seed 1): none on uniform points in the disk; a few in a
//! thousand on an integer grid (the windows that happen to be collinear, cocircular or of
//! equal length); every call on points exactly on one line, where each answer is a tie; and
//! every call with magnitudes near the ends of the double range (`huge`, `tiny`), where the
//! filter's products overflow or underflow. The ratio of fallbacks to calls is in every
//! sample's counts in the report. (Cocircular points would tie every `incircle` call too, but
//! the generator's radius grows with n, so the exact stage changes regime from integers to
//! expansions between sizes and the time per call jumps: collinear points keep one regime.)

use super::claimed_entries;
use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::geometry::{
    cmp_dist_with, cmp_lex_with, cmp_line_dist_with, cmp_rect_area_with, cmp_rect_perimeter_with,
    cross_sign_with, incircle_with, orient2d_with, Point2,
};

/// The predicate a workload calls.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Predicate {
    Orient2d,
    Incircle,
    CmpDist,
    CrossSign,
    CmpLex,
    CmpLineDist,
    CmpRectArea,
    CmpRectPerimeter,
}

/// The points one call may read, from point i on: `cmp_rect_area` and `cmp_rect_perimeter`
/// read two rectangles of
/// five points each, the others fewer.
const WINDOW: usize = 10;

/// n calls of one predicate on one kind of generated points.
struct Calls {
    predicate: Predicate,
    kind: PointKind,
}

/// The predicate entries: every claim of the seven predicates.
pub(super) fn entries() -> Vec<Entry> {
    let mut out = Vec::new();
    for declaration in crate::geometry::DECLARATIONS {
        let predicate = which(declaration);
        for (_, entry) in claimed_entries(declaration, |kind| Calls { predicate, kind }) {
            // Up to 2¹⁶ calls: on `tiny` input every call takes the big-integer path (about
            // 10 µs), so one run of 2²⁰ calls would take seconds.
            out.push(entry.quick(256, 1 << 12).full(256, 1 << 16));
        }
    }
    out
}

/// The predicate `declaration` declares.
///
/// # Panics
///
/// For a declaration of another predicate: a programming error the catalog's tests catch.
fn which(declaration: &Declaration) -> Predicate {
    match declaration.name {
        "orient2d" => Predicate::Orient2d,
        "incircle" => Predicate::Incircle,
        "cmp-dist" => Predicate::CmpDist,
        "cross-sign" => Predicate::CrossSign,
        "cmp-lex" => Predicate::CmpLex,
        "cmp-line-dist" => Predicate::CmpLineDist,
        "cmp-rect-area" => Predicate::CmpRectArea,
        "cmp-rect-perimeter" => Predicate::CmpRectPerimeter,
        other => panic!("no workload for the predicate {other}"),
    }
}

impl Workload for Calls {
    type Input = Vec<Point2>;
    /// How many calls gave each of the three answers, so no call is optimised away.
    type Output = [usize; 3];

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n + WINDOW - 1, seed)
    }

    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, c: &mut C) -> Result<[usize; 3]> {
        let mut tally = [0; 3];
        for w in pts.windows(WINDOW) {
            let answer = match self.predicate {
                Predicate::Orient2d => orient2d_with(w[0], w[1], w[2], c) as i64,
                Predicate::Incircle => incircle_with(w[0], w[1], w[2], w[3], c) as i64,
                Predicate::CmpDist => cmp_dist_with(w[0], w[1], w[2], w[3], c) as i64,
                Predicate::CrossSign => cross_sign_with(w[0], w[1], w[2], w[3], c) as i64,
                Predicate::CmpLex => cmp_lex_with(w[0], w[1], c) as i64,
                Predicate::CmpLineDist => {
                    cmp_line_dist_with(w[0], w[1], w[2], w[3], w[4], w[5], c) as i64
                }
                Predicate::CmpRectArea => {
                    let first = [w[0], w[1], w[2], w[3], w[4]];
                    let second = [w[5], w[6], w[7], w[8], w[9]];
                    cmp_rect_area_with(first, second, c) as i64
                }
                Predicate::CmpRectPerimeter => {
                    let first = [w[0], w[1], w[2], w[3], w[4]];
                    let second = [w[5], w[6], w[7], w[8], w[9]];
                    cmp_rect_perimeter_with(first, second, c) as i64
                }
            };
            tally[answer.rem_euclid(3) as usize] += 1;
        }
        Ok(tally)
    }
}
