//! The `keep_collinear` option, shared by every algorithm except brute force (which finds the
//! boundary points itself, so that it stays an independent oracle).

use super::{check_strictly_convex_ccw, HullOptions};
use crate::count::Counter;
use crate::geometry::{CountedPredicates, Orientation, Point2};
use crate::util::partition_point;
use std::cmp::Ordering;

/// `strict`, a strictly convex counter-clockwise hull starting at its lexicographically
/// smallest vertex, with the boundary points among `candidates` inserted in boundary order
/// (each distinct point once, by its smallest index).
///
/// The hull splits at its lexicographically largest vertex into a lower chain (increasing)
/// and an upper chain (decreasing); a binary search finds the one edge of each chain whose
/// range holds a point, and one orientation test decides whether the point is on it.
/// O(n log h) comparisons and at most 2n orientation tests, plus sorting the boundary points.
pub(super) fn with_boundary_points<C: Counter>(
    points: &[Point2],
    candidates: impl Iterator<Item = usize>,
    strict: Vec<usize>,
    counter: &mut C,
) -> Vec<usize> {
    let h = strict.len();
    if h <= 1 {
        return strict;
    }
    let v = |k: usize| points[strict[k % h]];
    let mut top = 0;
    for k in 1..h {
        if counter.cmp_lex(v(k), v(top)) == Ordering::Greater {
            top = k;
        }
    }
    // (edge, index): edge k runs from strict[k] to strict[k + 1].
    let mut on_edges: Vec<(usize, usize)> = Vec::new();
    for i in candidates {
        let p = points[i];
        let pos = partition_point(0..top + 1, |k| counter.cmp_lex(v(k), p) == Ordering::Less);
        if pos == 0 || pos > top {
            continue;
        }
        if counter.cmp_lex(v(pos), p) == Ordering::Equal {
            continue;
        }
        if counter.orient2d(v(pos - 1), v(pos), p) == Orientation::Collinear {
            on_edges.push((pos - 1, i));
            continue;
        }
        if h == 2 {
            continue;
        }
        // The upper chain strict[top], ..., strict[h - 1], strict[0], decreasing.
        let pos = partition_point(top..h + 1, |k| {
            counter.cmp_lex(v(k), p) == Ordering::Greater
        });
        if pos == top || pos > h || counter.cmp_lex(v(pos), p) == Ordering::Equal {
            continue;
        }
        if counter.orient2d(v(pos - 1), v(pos), p) == Orientation::Collinear {
            on_edges.push((pos - 1, i));
        }
    }
    on_edges.sort_unstable_by(|&(e, a), &(f, b)| {
        e.cmp(&f).then_with(|| {
            let along = counter.cmp_lex(points[a], points[b]);
            (if e < top { along } else { along.reverse() }).then_with(|| a.cmp(&b))
        })
    });
    on_edges.dedup_by(|b, a| {
        a.0 == b.0 && counter.cmp_lex(points[a.1], points[b.1]) == Ordering::Equal
    });
    let mut out = Vec::with_capacity(h + on_edges.len());
    let mut next = on_edges.iter().peekable();
    for (k, &vertex) in strict.iter().enumerate() {
        out.push(vertex);
        while let Some(&&(_, i)) = next.peek().filter(|(e, _)| *e == k) {
            out.push(i);
            next.next();
        }
    }
    out
}

/// Applies the options to a strictly convex hull computed from `candidates` (a superset of
/// the boundary points).
pub(super) fn finish<C: Counter>(
    points: &[Point2],
    candidates: impl Iterator<Item = usize>,
    strict: Vec<usize>,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    debug_assert!(check_strictly_convex_ccw(points, &strict).is_ok());
    if options.keep_collinear {
        with_boundary_points(points, candidates, strict, counter)
    } else {
        strict
    }
}
