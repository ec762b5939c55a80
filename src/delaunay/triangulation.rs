//! The triangulation every Delaunay builder returns: flat half-edge arrays.

use crate::count::NoCount;
use crate::error::{Error, Result};
use crate::geometry::lex_sort::{lex_key, sorted_items_with};
use crate::geometry::{cmp_lex, Point2, PointSet};
use crate::hull::{monotone_chain_with, HullOptions};
use std::cmp::Ordering;

/// The value of [`Triangulation::halfedges`] for a half-edge on the hull (no opposite).
pub const EMPTY: usize = usize::MAX;

/// A triangulation of a point set in compact half-edge arrays.
///
/// Triangle `t` has the vertices `triangles[3t]`, `triangles[3t + 1]`, `triangles[3t + 2]`
/// (indices into the caller's points) in counter-clockwise order. Half-edge `e` runs from
/// `triangles[e]` to `triangles[next_halfedge(e)]`, with its triangle on its left;
/// `halfedges[e]` is the half-edge running the other way in the neighbouring triangle, or
/// [`EMPTY`] if `e` is on the hull.
///
/// Degenerate input is not an error. Points equal to an earlier one are merged into it and
/// listed in `duplicates`; with fewer than three distinct points, or all of them on one
/// line, there are no triangles and `hull` lists the distinct points from the
/// lexicographically smallest to the largest.
///
/// ```
/// use compgeo::delaunay::{Triangulation, EMPTY};
/// use compgeo::geometry::{Point2, PointSet};
///
/// // A unit square split along the diagonal 0-2.
/// let pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)].map(Point2::from);
/// let t = Triangulation::from_triangles(&PointSet::new(&pts)?, &[[0, 1, 2], [0, 2, 3]], Vec::new())?;
/// assert_eq!(t.triangle_count(), 2);
/// assert_eq!(t.hull, [0, 1, 2, 3]);
/// assert_eq!(t.halfedges[2], 3); // 2 -> 0 in the first triangle, 0 -> 2 in the second
/// assert_eq!(t.halfedges[0], EMPTY);
/// assert_eq!(t.edges().count(), 5);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Triangulation {
    /// Three vertex indices (into the caller's points) per triangle, counter-clockwise.
    pub triangles: Vec<usize>,
    /// `halfedges[e]` is the opposite half-edge of `e`, or [`EMPTY`] on the hull.
    pub halfedges: Vec<usize>,
    /// The hull's boundary counter-clockwise from the lexicographically smallest point,
    /// points in the middle of hull edges included (as the hull module's
    /// [`keep_collinear`](crate::hull::HullOptions::keep_collinear) gives it).
    pub hull: Vec<usize>,
    /// `[dropped, kept]` for every point equal to a point with a smaller index: `kept` is the
    /// smallest index among the equal points. Sorted by `dropped`.
    pub duplicates: Vec<[usize; 2]>,
}

impl Triangulation {
    /// Builds a triangulation from counter-clockwise triangles, rebuilding `halfedges` and
    /// `hull`. Builders produce triangles; this links them.
    ///
    /// With no triangles the result is the degenerate one: `hull` is the hull module's
    /// keep-collinear hull of `points` (the distinct points in order along their line, or
    /// the one distinct point). `duplicates` is stored as given (see
    /// [`find_duplicates`]).
    ///
    /// Nothing geometric is checked here (see [`check_delaunay`](super::check_delaunay)):
    /// only that the triangles fit together as an oriented surface.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"triangles"`) if a vertex index is out of range, a
    /// triangle repeats a vertex, a directed edge occurs twice, or the boundary is not one
    /// cycle.
    ///
    /// # Complexity
    /// O(n + t) time and space for n points and t triangles (O(n log n) without triangles).
    pub fn from_triangles(
        points: &PointSet<'_>,
        triangles: &[[usize; 3]],
        duplicates: Vec<[usize; 2]>,
    ) -> Result<Triangulation> {
        if triangles.is_empty() {
            return Ok(Triangulation::without_triangles(points, duplicates));
        }
        let n = points.len();
        let bad = |reason: String| Error::InvalidParameter {
            name: "triangles",
            reason,
        };
        let flat: Vec<usize> = triangles.iter().flatten().copied().collect();
        for (t, tri) in triangles.iter().enumerate() {
            if let Some(&v) = tri.iter().find(|&&v| v >= n) {
                return Err(bad(format!(
                    "triangle {t} names vertex {v}, but there are only {n} points"
                )));
            }
            if tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] {
                return Err(bad(format!("triangle {t} repeats a vertex: {tri:?}")));
            }
        }
        let halfedges = link_halfedges(n, &flat).map_err(bad)?;
        let hull = boundary_cycle(points, &flat, &halfedges).map_err(bad)?;
        Ok(Triangulation {
            triangles: flat,
            halfedges,
            hull,
            duplicates,
        })
    }

    /// A triangulation from counter-clockwise triangles whose `halfedges` the builder has
    /// already linked (a builder that knows its twins as it creates them skips
    /// [`from_triangles`](Self::from_triangles)' pass over every vertex's edges); only the
    /// hull is derived, as there. In debug builds the links are checked against that pass.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"triangles"`) if the boundary is not one cycle.
    ///
    /// # Complexity
    /// O(n + t) time and space for n points and t triangles (O(n log n) without triangles).
    pub(crate) fn from_linked(
        points: &PointSet<'_>,
        triangles: Vec<usize>,
        halfedges: Vec<usize>,
        duplicates: Vec<[usize; 2]>,
    ) -> Result<Triangulation> {
        if triangles.is_empty() {
            return Ok(Triangulation::without_triangles(points, duplicates));
        }
        debug_assert_eq!(
            Ok(&halfedges),
            link_halfedges(points.len(), &triangles).as_ref(),
            "the builder's half-edge links differ from the rebuilt ones"
        );
        let hull = boundary_cycle(points, &triangles, &halfedges).map_err(|reason| {
            Error::InvalidParameter {
                name: "triangles",
                reason,
            }
        })?;
        Ok(Triangulation {
            triangles,
            halfedges,
            hull,
            duplicates,
        })
    }

    /// The triangulation without triangles of points with no three non-collinear ones (or
    /// fewer than three distinct points): its hull is the keep-collinear hull, the distinct
    /// points along their line.
    ///
    /// # Complexity
    /// O(n log n) time, O(n) space.
    pub(crate) fn without_triangles(
        points: &PointSet<'_>,
        duplicates: Vec<[usize; 2]>,
    ) -> Triangulation {
        let keep = HullOptions {
            keep_collinear: true,
        };
        Triangulation {
            triangles: Vec::new(),
            halfedges: Vec::new(),
            hull: monotone_chain_with(points, keep, &mut NoCount),
            duplicates,
        }
    }

    /// The number of triangles.
    #[inline]
    pub fn triangle_count(&self) -> usize {
        self.triangles.len() / 3
    }

    /// The number of triangles (the same as [`triangle_count`](Self::triangle_count)).
    #[inline]
    pub fn len(&self) -> usize {
        self.triangle_count()
    }

    /// Whether there are no triangles (fewer than three distinct points, or all collinear).
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// The vertices of triangle `t`, counter-clockwise. Panics if `t` is out of range.
    #[inline]
    pub fn triangle(&self, t: usize) -> [usize; 3] {
        [
            self.triangles[3 * t],
            self.triangles[3 * t + 1],
            self.triangles[3 * t + 2],
        ]
    }

    /// The undirected edges, each once as `[from, to]` of one of its half-edges (the one
    /// with the larger index when both exist), hull edges included.
    pub fn edges(&self) -> impl Iterator<Item = [usize; 2]> + '_ {
        (0..self.triangles.len()).filter_map(move |e| {
            let twin = self.halfedges[e];
            (twin == EMPTY || e > twin)
                .then(|| [self.triangles[e], self.triangles[next_halfedge(e)]])
        })
    }
}

/// The next half-edge in the same triangle: `e - e % 3 + (e + 1) % 3`.
#[inline]
pub fn next_halfedge(e: usize) -> usize {
    if e % 3 == 2 {
        e - 2
    } else {
        e + 1
    }
}

/// The previous half-edge in the same triangle: `e - e % 3 + (e + 2) % 3`.
#[inline]
pub fn prev_halfedge(e: usize) -> usize {
    if e % 3 == 0 {
        e + 2
    } else {
        e - 1
    }
}

/// The duplicate points of `points`: `[dropped, kept]` for every point equal (coordinate by
/// coordinate, `-0.0 == 0.0`) to a point with a smaller index, `kept` the smallest index
/// among the equal points, sorted by `dropped`. Every builder reports duplicates this way.
///
/// # Complexity
/// O(n log n) time (a lexicographic sort: a radix sort from 384 points up, linear on
/// random input), O(n) auxiliary space.
///
/// ```
/// use compgeo::delaunay::find_duplicates;
/// use compgeo::geometry::Point2;
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (1.0, 1.0), (-0.0, 0.0), (1.0, 1.0)].map(Point2::from);
/// assert_eq!(find_duplicates(&pts), [[2, 0], [3, 1], [4, 0]]);
/// ```
pub fn find_duplicates(points: &[Point2]) -> Vec<[usize; 2]> {
    let order = sorted_items_with(points, 0..points.len(), lex_key, &mut NoCount);
    let mut out = Vec::new();
    let mut kept = 0;
    for (k, &(p, i)) in order.iter().enumerate() {
        // Finite coordinates are equal as floats exactly when cmp_lex calls them equal.
        if k > 0 && order[k - 1].0 == p {
            out.push([i, kept]);
        } else {
            kept = i;
        }
    }
    out.sort_unstable();
    out
}

/// Opposite half-edges of `triangles` (flat, three per triangle): buckets the half-edges
/// by their start vertex, then looks for each half-edge's reverse in its end's bucket.
fn link_halfedges(n: usize, triangles: &[usize]) -> std::result::Result<Vec<usize>, String> {
    let mut start = vec![0usize; n + 1];
    for &v in triangles {
        start[v + 1] += 1;
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut by_start = vec![0usize; triangles.len()];
    for (e, &v) in triangles.iter().enumerate() {
        by_start[fill[v]] = e;
        fill[v] += 1;
    }
    let mut halfedges = vec![EMPTY; triangles.len()];
    for e in 0..triangles.len() {
        let (a, b) = (triangles[e], triangles[next_halfedge(e)]);
        let mut found = EMPTY;
        for &f in &by_start[start[b]..start[b + 1]] {
            if triangles[next_halfedge(f)] == a {
                if found != EMPTY {
                    return Err(format!("the edge {b} -> {a} occurs twice"));
                }
                found = f;
            }
        }
        halfedges[e] = found;
    }
    Ok(halfedges)
}

/// The boundary half-edges' vertices as one counter-clockwise cycle from the
/// lexicographically smallest boundary vertex.
fn boundary_cycle(
    points: &[Point2],
    triangles: &[usize],
    halfedges: &[usize],
) -> std::result::Result<Vec<usize>, String> {
    let mut out_edge = vec![EMPTY; points.len()];
    let mut boundary = 0;
    for e in 0..triangles.len() {
        if halfedges[e] == EMPTY {
            let v = triangles[e];
            if out_edge[v] != EMPTY {
                return Err(format!("the boundary passes through vertex {v} twice"));
            }
            out_edge[v] = e;
            boundary += 1;
        }
    }
    let Some(first) = (0..triangles.len()).find(|&e| halfedges[e] == EMPTY) else {
        return Err("there is no boundary: the triangles close up".to_string());
    };
    let mut hull = Vec::with_capacity(boundary);
    let mut e = first;
    loop {
        hull.push(triangles[e]);
        let v = triangles[next_halfedge(e)];
        e = out_edge[v];
        if e == EMPTY {
            return Err(format!("the boundary stops at vertex {v}"));
        }
        if e == first {
            break;
        }
        if hull.len() > boundary {
            return Err("the boundary is not a simple cycle".to_string());
        }
    }
    if hull.len() != boundary {
        return Err(format!(
            "the boundary is {} cycles, not one",
            if hull.len() < boundary {
                "several"
            } else {
                "no"
            }
        ));
    }
    rotate_to_lex_min(points, &mut hull);
    Ok(hull)
}

/// Rotates a cycle of vertex indices to start at its lexicographically smallest point.
pub(crate) fn rotate_to_lex_min(points: &[Point2], cycle: &mut [usize]) {
    let mut best = 0;
    for k in 1..cycle.len() {
        if cmp_lex(points[cycle[k]], points[cycle[best]]) == Ordering::Less {
            best = k;
        }
    }
    cycle.rotate_left(best);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
        v.iter().map(|&p| Point2::from(p)).collect()
    }

    #[test]
    fn links_a_fan_and_finds_its_boundary() {
        // A square with a centre point: four triangles around vertex 4.
        let p = pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 1.0)]);
        let tris = [[4, 0, 1], [4, 1, 2], [4, 2, 3], [4, 3, 0]];
        let t =
            Triangulation::from_triangles(&PointSet::new(&p).unwrap(), &tris, Vec::new()).unwrap();
        assert_eq!(t.hull, [0, 1, 2, 3]);
        for e in 0..12 {
            let f = t.halfedges[e];
            if f != EMPTY {
                assert_eq!(t.halfedges[f], e);
                assert_eq!(t.triangles[f], t.triangles[next_halfedge(e)]);
            }
        }
        assert_eq!(t.halfedges.iter().filter(|&&f| f == EMPTY).count(), 4);
        assert_eq!(t.edges().count(), 8);
    }

    #[test]
    fn rejects_inconsistent_triangles() {
        let p = pts(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]);
        assert!(Triangulation::from_triangles(
            &PointSet::new(&p).unwrap(),
            &[[0, 1, 7]],
            Vec::new()
        )
        .is_err());
        assert!(Triangulation::from_triangles(
            &PointSet::new(&p).unwrap(),
            &[[0, 1, 1]],
            Vec::new()
        )
        .is_err());
        // The same triangle twice: every directed edge occurs twice.
        assert!(Triangulation::from_triangles(
            &PointSet::new(&p).unwrap(),
            &[[0, 1, 2], [0, 1, 2]],
            Vec::new()
        )
        .is_err());
        // Two triangles touching at one vertex: the boundary visits it twice.
        let p = pts(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)]);
        assert!(Triangulation::from_triangles(
            &PointSet::new(&p).unwrap(),
            &[[0, 1, 2], [0, 3, 4]],
            Vec::new()
        )
        .is_err());
    }

    #[test]
    fn degenerate_input_gives_the_collinear_hull() {
        let p = pts(&[(2.0, 2.0), (0.0, 0.0), (1.0, 1.0), (0.0, 0.0)]);
        let t =
            Triangulation::from_triangles(&PointSet::new(&p).unwrap(), &[], find_duplicates(&p))
                .unwrap();
        assert!(t.is_empty());
        assert_eq!(t.hull, [1, 2, 0]);
        assert_eq!(t.duplicates, [[3, 1]]);
    }

    #[test]
    fn next_and_prev_stay_in_the_triangle() {
        for e in 0..9 {
            assert_eq!(next_halfedge(e) / 3, e / 3);
            assert_eq!(prev_halfedge(next_halfedge(e)), e);
            assert_eq!(next_halfedge(next_halfedge(next_halfedge(e))), e);
        }
    }
}
