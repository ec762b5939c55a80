//! The course's brute-force hull: a pair of points is a hull edge when no point lies to its
//! right. The oracle every other algorithm is tested against.

use super::lex::lex_sorted_items;
use super::HullOptions;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "hull",
    name: "brute-force",
    function: "hull::brute_force_hull",
    file: "src/hull/brute_force.rs",
    summary: "every pair of points tested against all the others",
    time: "Θ(n³)",
    space: "O(n)",
    operation: Some(Operation::OrientationTests),
    counts: "m − 2 per ordered pair of the m distinct points that is an edge, fewer for the others",
    source: "[RD, §2.2]",
    claims: &[on(
        "uniform-square",
        Bound::Cubic,
        Operation::OrientationTests,
    )],
};

/// The convex hull of `points` by brute force. See [`brute_force_hull_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{brute_force_hull, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(brute_force_hull(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn brute_force_hull(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    Ok(brute_force_hull_with(
        &PointSet::new(points)?,
        options,
        &mut NoCount,
    ))
}

/// The convex hull of `points` by brute force, recording its operations in `counter`.
///
/// Idea (seed step 1): for every ordered pair `(a, b)` of distinct points, `a -> b` is a
/// counter-clockwise hull edge when every other point is strictly left of it or on the
/// segment between them; because input may be collinear (the course assumes it is not), a
/// point on the line beyond `a` or `b` disqualifies the pair. Step 2 links the edges into a
/// cycle from the lexicographically smallest point. With `keep_collinear` the points found
/// on each edge's segment are inserted in order along it.
///
/// Follows [RD, §2.2] "Algoritmo de fuerza bruta".
///
/// Output convention and degenerate inputs: see the [module docs](super).
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and m ≤ n the number of distinct points: time Θ(n³) in the worst
/// case, Θ(m³) orientation tests plus an O(n log n) sort; auxiliary space O(n).
///
/// # Counts
///
/// Orientation tests: (m − 2) for each of the m(m − 1) ordered pairs that is an edge, fewer
/// for the others (a pair is rejected at its first point on the wrong side); comparisons:
/// those of the lexicographic sort that merges duplicates plus the betweenness checks.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{brute_force_hull_with, HullOptions};
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// assert_eq!(brute_force_hull_with(&set, HullOptions::default(), &mut counts), [0, 1, 2]);
/// assert_eq!(counts.orientation_tests, 6); // 6 ordered pairs, one other point each
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn brute_force_hull_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    let points = points.points();
    let unique: Vec<usize> = lex_sorted_items(points, 0..points.len(), counter)
        .into_iter()
        .map(|s| s.1)
        .collect();
    let m = unique.len();
    if m <= 2 {
        return unique;
    }
    let p = |k: usize| points[unique[k]];
    // For each position in `unique`: the edge leaving it and the points inside that edge.
    let mut next: Vec<Option<(usize, Vec<usize>)>> = vec![None; m];
    for (a, slot) in next.iter_mut().enumerate() {
        for b in 0..m {
            if a == b {
                continue;
            }
            let mut inside = Vec::new();
            let is_edge = (0..m).filter(|&c| c != a && c != b).all(|c| {
                match counter.orient2d(p(a), p(b), p(c)) {
                    Orientation::CounterClockwise => true,
                    Orientation::Clockwise => false,
                    Orientation::Collinear => {
                        let between = counter.cmp_lex(p(a), p(c)) == counter.cmp_lex(p(c), p(b));
                        if between {
                            inside.push(c);
                        }
                        between
                    }
                }
            });
            if is_edge {
                // `unique` is in lexicographic order, so positions order the points along
                // the edge.
                if b < a {
                    inside.reverse();
                }
                *slot = Some((b, inside));
            }
        }
    }
    let mut cycle = vec![0];
    let mut at = 0;
    while let Some((b, _)) = &next[at] {
        if *b == 0 || cycle.len() > m {
            break;
        }
        cycle.push(*b);
        at = *b;
    }
    let h = cycle.len();
    let mut hull = Vec::new();
    for (k, &a) in cycle.iter().enumerate() {
        hull.push(unique[a]);
        // A two-vertex hull (collinear input) lists its inner points once, on the way out.
        if options.keep_collinear && (h > 2 || k == 0) {
            if let Some((_, inside)) = &next[a] {
                hull.extend(inside.iter().map(|&c| unique[c]));
            }
        }
    }
    hull
}
