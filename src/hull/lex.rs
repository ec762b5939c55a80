//! The lexicographic order the hull algorithms start from: the smallest point, and the
//! points sorted with their duplicates dropped.

use crate::count::Counter;
use crate::geometry::{CountedPredicates, Point2};
use std::cmp::Ordering;

/// The index of the lexicographically smallest point, the first one among equals.
/// `points` must not be empty.
pub(super) fn lex_min<C: Counter>(points: &[Point2], counter: &mut C) -> usize {
    let mut best = 0;
    for i in 1..points.len() {
        if counter.cmp_lex(points[i], points[best]) == Ordering::Less {
            best = i;
        }
    }
    best
}

/// The points of `indices` with their indices, sorted lexicographically, each distinct point
/// kept once by its smallest index. The sort compares integer keys that order as
/// [`cmp_lex`](crate::geometry::cmp_lex) does (see [`lex_key`]), twice as fast as comparing
/// the coordinates on circle inputs; one key comparison is counted as one comparison, so
/// the counts are those of sorting by `cmp_lex`. `points` must be finite.
pub(super) fn lex_sorted_items<C: Counter>(
    points: &[Point2],
    indices: impl Iterator<Item = usize>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    let mut keyed: Vec<(u128, usize)> = indices.map(|i| (lex_key(points[i]), i)).collect();
    keyed.sort_unstable_by(|a, b| {
        counter.comparison();
        a.cmp(b)
    });
    keyed.dedup_by(|b, a| {
        counter.comparison();
        a.0 == b.0
    });
    keyed.into_iter().map(|(_, i)| (points[i], i)).collect()
}

/// A 128-bit key whose integer order is the lexicographic order of finite points: the
/// order keys of x then y ([`crate::util::order_key`]) after mapping `-0.0` to `0.0`, which
/// `cmp_lex` treats as equal.
#[inline]
fn lex_key(p: Point2) -> u128 {
    let ordered = |v: f64| crate::util::order_key(v + 0.0);
    u128::from(ordered(p.x)) << 64 | u128::from(ordered(p.y))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::cmp_lex;

    /// The key order is `cmp_lex` on signed zeros, subnormals, huge values and neighbours.
    #[test]
    fn lex_key_orders_as_cmp_lex() {
        let values = [
            -f64::MAX,
            -1e300,
            -1.0,
            -f64::MIN_POSITIVE,
            -5e-324,
            -0.0,
            0.0,
            5e-324,
            1e-310,
            f64::MIN_POSITIVE,
            1.0,
            1.0 + f64::EPSILON,
            1e300,
            f64::MAX,
        ];
        for &a in &values {
            for &b in &values {
                for &c in &values {
                    let (p, q) = (Point2::new(a, b), Point2::new(a, c));
                    let (r, s) = (Point2::new(a, b), Point2::new(c, b));
                    assert_eq!(lex_key(p).cmp(&lex_key(q)), cmp_lex(p, q), "{p:?} {q:?}");
                    assert_eq!(lex_key(r).cmp(&lex_key(s)), cmp_lex(r, s), "{r:?} {s:?}");
                }
            }
        }
    }
}
