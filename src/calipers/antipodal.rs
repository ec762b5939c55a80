//! All antipodal pairs of a convex polygon by rotating two calipers: the course's algorithm.

use super::ConvexPolygon;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::geometry::{CountedPredicates, Orientation};
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "antipodal-pairs",
    name: "calipers",
    function: "calipers::ConvexPolygon::antipodal_pairs",
    file: "src/calipers/antipodal.rs",
    summary: "two calipers rotated once around a convex polygon",
    time: "Θ(h)",
    space: "O(h)",
    operation: Some(Operation::OrientationTests),
    counts: "at most h, one exact direction test per step; at most 3h/2 pairs",
    source: "[RD, §2.3]",
    claims: &[on(
        "convex-polygon",
        Bound::Linear,
        Operation::OrientationTests,
    )],
};

impl ConvexPolygon<'_> {
    /// Every antipodal pair of the polygon's vertices; see
    /// [`antipodal_pairs_with`](Self::antipodal_pairs_with).
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(Point2::from);
    /// let polygon = ConvexPolygon::new(&PointSet::new(&square)?, vec![0, 1, 2, 3])?;
    /// assert_eq!(polygon.antipodal_pairs().len(), 6); // 3h/2: two pairs of parallel sides
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn antipodal_pairs(&self) -> Vec<[usize; 2]> {
        self.antipodal_pairs_with(&mut NoCount)
    }

    /// Every antipodal pair of the polygon's vertices (pairs of input indices), by rotating
    /// two calipers, recording the operations in `counter`.
    ///
    /// Idea: start with `p` at the lexicographically smallest vertex and `q` at the largest,
    /// antipodal through vertical supporting lines. Repeatedly record `(p, q)` and rotate the
    /// calipers to the next polygon edge: advance `p` when its edge `p -> SIG(p)` is reached
    /// first, that is when `q -> SIG(q)` turns clockwise of it (the course's
    /// `Δ(p, SIG(p), x) < 0`), `q` when it turns counter-clockwise, and both, recording the
    /// two extra pairs `(p, SIG(q))` and `(SIG(p), q)`, when the edges are parallel. Stop when
    /// `p` reaches the largest vertex and `q` the smallest.
    ///
    /// Follows [RD, §2.3], "Algoritmo de girar calibres" (steps 1–5 and Observaciones 2.23),
    /// with the exact direction test described in the module docs.
    ///
    /// Degenerate polygons: no pair for zero or one vertex, the single pair for two.
    ///
    /// # Complexity
    ///
    /// With h the number of vertices: time Θ(h), auxiliary space O(h) for the output, at
    /// most 3h/2 pairs (h steps, each adding one pair, or three for a pair of parallel
    /// edges).
    ///
    /// # Counts
    ///
    /// Orientation tests: one [`cross_sign`](crate::geometry::cross_sign) per step, at most
    /// h, plus the comparisons that find the two extreme vertices.
    ///
    /// ```
    /// use compgeo::calipers::ConvexPolygon;
    /// use compgeo::count::Counts;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let triangle = [(0.0, 0.0), (2.0, 0.0), (1.0, 3.0)].map(Point2::from);
    /// let polygon = ConvexPolygon::new(&PointSet::new(&triangle)?, vec![0, 1, 2])?;
    /// let mut counts = Counts::default();
    /// assert_eq!(polygon.antipodal_pairs_with(&mut counts), [[0, 1], [0, 2], [1, 2]]);
    /// assert!(counts.orientation_tests <= 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn antipodal_pairs_with<C: Counter>(&self, counter: &mut C) -> Vec<[usize; 2]> {
        let polygon = &self.vertices;
        let n = polygon.len();
        match n {
            0 | 1 => return Vec::new(),
            2 => return vec![[polygon[0], polygon[1]]],
            _ => {}
        }
        let v = |k: usize| self.at(k);
        let (mut lo, mut hi) = (0, 0);
        for k in 1..n {
            if counter.cmp_lex(v(k), v(lo)) == Ordering::Less {
                lo = k;
            }
            if counter.cmp_lex(v(k), v(hi)) == Ordering::Greater {
                hi = k;
            }
        }
        let (mut p, mut q) = (lo, hi);
        let mut pairs = Vec::with_capacity(3 * n / 2 + 1);
        // Each step advances p or q (or both) by one; together they go once around.
        for _ in 0..n {
            if p == hi && q == lo {
                break;
            }
            pairs.push([polygon[p], polygon[q]]);
            let (p_next, q_next) = ((p + 1) % n, (q + 1) % n);
            match counter.cross_sign(v(p), v(p_next), v(q), v(q_next)) {
                // q's edge turns clockwise of p's: p's caliper meets its edge first.
                Orientation::Clockwise => p = p_next,
                Orientation::CounterClockwise => q = q_next,
                Orientation::Collinear => {
                    pairs.push([polygon[p], polygon[q_next]]);
                    pairs.push([polygon[p_next], polygon[q]]);
                    p = p_next;
                    q = q_next;
                }
            }
        }
        pairs
    }
}
