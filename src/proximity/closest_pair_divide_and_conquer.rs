//! The closest pair by the classic divide and conquer (Shamos), with exact comparisons only.

use super::at_least;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Point2, PointPair, PointSet};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "closest-pair",
    name: "divide-and-conquer",
    function: "proximity::closest_pair_divide_and_conquer",
    file: "src/proximity/closest_pair_divide_and_conquer.rs",
    summary: "split at the median x, solve both halves, check the strip (Shamos)",
    time: "O(n log n) in the worst case",
    space: "O(n)",
    operation: Some(Operation::DistanceEvaluations),
    counts: "strip membership, height cut-offs and candidate pairs, all exact",
    source: "[RD, §2.4]",
    claims: &[
        on(
            "uniform-square",
            Bound::NLogN,
            Operation::DistanceEvaluations,
        ),
        on("grid", Bound::NLogN, Operation::DistanceEvaluations),
    ],
};

/// The closest pair of `points` by divide and conquer; see
/// [`closest_pair_divide_and_conquer_with`].
///
/// # Errors
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate; [`Error::TooFew`](crate::Error::TooFew) for fewer than two points.
///
/// # Complexity
/// O(n log n) time, O(n) auxiliary space.
///
/// ```
/// use compgeo::proximity::closest_pair_divide_and_conquer;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (9.0, 9.0), (3.5, 5.0)].map(Point2::from);
/// assert_eq!(closest_pair_divide_and_conquer(&pts)?.pair, [1, 3]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closest_pair_divide_and_conquer(points: &[Point2]) -> Result<PointPair> {
    closest_pair_divide_and_conquer_with(&PointSet::new(points)?, &mut NoCount)
}

/// The closest pair of `points` by the classic O(n log n) divide and conquer, counting its
/// comparisons and distance evaluations.
///
/// The idea (the course's divide-and-conquer scheme, [RD, §2.4] "Algoritmos", applied to
/// problem 3 "El par más cercano"; Shamos and Hoey): sort by x;
/// split at the median x; solve both halves; the best pair across the split line has both
/// points in the strip of half-width δ (the better half's distance) around it. Sorted by y
/// (each call returns its points merged by y, so there is no re-sorting), each strip point
/// needs comparing only with the following ones less than δ higher, at most seven.
///
/// Every decision is exact: "is this point's distance to the split line below δ" and "is
/// the height difference below δ" are [`cmp_dist`](crate::geometry::cmp_dist) against the
/// current pair, with the point `(x_split, y)` or `(x, y')` built from input coordinates
/// (nothing is rounded), and candidate pairs are compared with `cmp_dist` too. Ties: any
/// closest pair may be returned; duplicates are pairs at distance zero.
///
/// # Errors
/// [`Error::TooFew`](crate::Error::TooFew) for fewer than two points.
///
/// # Complexity
/// O(n log n) in the worst case for n points (the sort, then O(n) per level of the
/// recursion), O(n) auxiliary space.
///
/// # Counts
/// One comparison per comparison of the x sort and the y merges, one distance evaluation
/// per `cmp_dist` (strip membership, height cut-off, candidate pairs): O(n log n) each.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::PointSet;
/// use compgeo::proximity::closest_pair_divide_and_conquer_with;
///
/// let pts = points(PointKind::UniformSquare, 1024, 5)?;
/// let mut counts = Counts::default();
/// let best = closest_pair_divide_and_conquer_with(&PointSet::new(&pts)?, &mut counts)?;
/// assert_ne!(best.pair[0], best.pair[1]);
/// assert!(counts.distance_evaluations < 20 * 1024 * 10);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closest_pair_divide_and_conquer_with<C: Counter>(
    points: &PointSet<'_>,
    counter: &mut C,
) -> Result<PointPair> {
    at_least(2, points.len())?;
    let points = points.points();
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_unstable_by(|&a, &b| counter.cmp_lex(points[a], points[b]));
    let mut scratch = vec![0usize; points.len()];
    let mut strip = Vec::with_capacity(points.len());
    let [a, b] = solve(points, &mut order, &mut scratch, &mut strip, counter);
    Ok(PointPair::new(points, a, b))
}

/// The closest pair of `idx` (sorted by x on entry, by y on return).
fn solve<C: Counter>(
    p: &[Point2],
    idx: &mut [usize],
    scratch: &mut [usize],
    strip: &mut Vec<usize>,
    c: &mut C,
) -> [usize; 2] {
    let n = idx.len();
    if n <= 3 {
        let mut best = [idx[0], idx[1]];
        for i in 0..n {
            for j in i + 1..n {
                if (i, j) != (0, 1) && closer(p, [idx[i], idx[j]], best, c) {
                    best = [idx[i], idx[j]];
                }
            }
        }
        idx.sort_unstable_by(|&a, &b| by_y(p, a, b, c));
        return best;
    }
    let mid = n / 2;
    let split = p[idx[mid]].x;
    let (left, right) = idx.split_at_mut(mid);
    let l = solve(p, left, scratch, strip, c);
    let r = solve(p, right, scratch, strip, c);
    let mut best = if closer(p, r, l, c) { r } else { l };
    merge_by_y(p, idx, mid, &mut scratch[..n], c);
    let [a, b] = best;
    strip.clear();
    strip.extend(
        idx.iter().copied().filter(|&i| {
            c.cmp_dist(p[i], Point2::new(split, p[i].y), p[a], p[b]) == Ordering::Less
        }),
    );
    for s in 0..strip.len() {
        let u = p[strip[s]];
        for &w in &strip[s + 1..] {
            let [a, b] = best;
            if c.cmp_dist(u, Point2::new(u.x, p[w].y), p[a], p[b]) != Ordering::Less {
                break;
            }
            if closer(p, [strip[s], w], best, c) {
                best = [strip[s], w];
            }
        }
    }
    best
}

/// Whether the pair `x` is strictly closer than the pair `y`.
fn closer<C: Counter>(p: &[Point2], x: [usize; 2], y: [usize; 2], c: &mut C) -> bool {
    c.cmp_dist(p[x[0]], p[x[1]], p[y[0]], p[y[1]]) == Ordering::Less
}

/// Order by y, then x (a total order on distinct points; equal points in any order).
fn by_y<C: Counter>(p: &[Point2], a: usize, b: usize, c: &mut C) -> Ordering {
    c.comparison();
    let (u, v) = (p[a], p[b]);
    u.y.partial_cmp(&v.y)
        .unwrap_or(Ordering::Equal)
        .then(u.x.partial_cmp(&v.x).unwrap_or(Ordering::Equal))
}

/// Merges the y-sorted halves `idx[..mid]` and `idx[mid..]` through `scratch`.
fn merge_by_y<C: Counter>(
    p: &[Point2],
    idx: &mut [usize],
    mid: usize,
    scratch: &mut [usize],
    c: &mut C,
) {
    let (mut i, mut j) = (0, mid);
    for slot in scratch.iter_mut() {
        let take_left = j == idx.len() || (i < mid && by_y(p, idx[i], idx[j], c).is_le());
        if take_left {
            *slot = idx[i];
            i += 1;
        } else {
            *slot = idx[j];
            j += 1;
        }
    }
    idx.copy_from_slice(scratch);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_best_pair_may_straddle_the_split() {
        // Halves {0, 1, 2, 3} and {4, 5, 6, 7} by x; the pair 3-4 crosses x = 10.
        let pts: Vec<Point2> = [
            (0.0, 0.0),
            (0.0, 5.0),
            (3.0, 0.0),
            (9.9, 2.0),
            (10.0, 2.05),
            (20.0, 0.0),
            (20.0, 5.0),
            (15.0, 0.0),
        ]
        .map(Point2::from)
        .to_vec();
        assert_eq!(closest_pair_divide_and_conquer(&pts).unwrap().pair, [3, 4]);
    }
}
