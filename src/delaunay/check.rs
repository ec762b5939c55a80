//! The exact checker every Delaunay builder's tests run (and users may run on triangulations
//! from elsewhere).

use super::triangulation::{find_duplicates, next_halfedge, prev_halfedge, Triangulation, EMPTY};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Violation;
use crate::geometry::{cmp_lex, CountedPredicates, InCircle, Orientation, Point2, PointSet};
use crate::hull::{monotone_chain_with, HullOptions};
use std::cmp::Ordering;

/// The exact checker's [`Declaration`]: its name, bounds and source.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "check",
    name: "delaunay",
    function: "delaunay::check_delaunay",
    file: "src/delaunay/check.rs",
    summary: "every property of a Delaunay triangulation, checked exactly",
    time: "O(n log n + t)",
    space: "O(n + t)",
    operation: Some(Operation::IncircleTests),
    counts: "exactly one per interior edge, 3n − 3 − 2h for n distinct points with h on the hull; one orientation test per triangle, then the hull's",
    source: "[RD, §2.4]",
    claims: &[on("uniform-disk", Bound::Linear, Operation::IncircleTests)],
};

/// Checks exactly that `t` is a Delaunay triangulation of `points` in compgeo's conventions;
/// the error names the first violation found.
///
/// Checked, with the exact predicates [`orient2d`](crate::geometry::orient2d) and [`incircle`](crate::geometry::incircle) only:
///
/// 1. the arrays fit: three vertices per triangle, one entry of `halfedges` per half-edge,
///    every index in range;
/// 2. `halfedges` is symmetric and pairs each half-edge with its reverse;
/// 3. every triangle is strictly counter-clockwise;
/// 4. every interior edge is locally Delaunay: the vertex across it is not strictly inside
///    the circumcircle;
/// 5. `duplicates` is exactly [`find_duplicates`]`(points)`, and the triangles' vertices are
///    exactly the remaining (distinct) points;
/// 6. the half-edges without an opposite form one cycle, equal to `hull`, and `hull` equals
///    the hull module's keep-collinear hull (a vertex order starting at the
///    lexicographically smallest point);
/// 7. the number of triangles is `2n - 2 - h` for `n` distinct points and `h` hull points,
///    or zero exactly when the distinct points are fewer than three or all collinear.
///
/// Together these say the triangles tile the convex hull: all are positively oriented and
/// glued along their edges, and their boundary winds once around the hull, so every point
/// inside is covered exactly once (the degree of the covering is the boundary's winding
/// number).
///
/// # Errors
/// A [`Violation`] naming the first violated property, with the indices involved.
///
/// # Complexity
/// O(n log n + t) time and O(n + t) auxiliary space for n points and t triangles: one
/// orientation test per triangle and one in-circle test per interior edge, plus the hull
/// and a lexicographic sort.
///
/// ```
/// use compgeo::delaunay::{check_delaunay, Triangulation};
/// use compgeo::geometry::{Point2, PointSet};
///
/// // The square (0,0), (2,0), (2,1), (0,1) is cocircular: both diagonals are Delaunay.
/// let pts = [(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)].map(Point2::from);
/// let t = Triangulation::from_triangles(&PointSet::new(&pts)?, &[[0, 1, 2], [0, 2, 3]], Vec::new())?;
/// assert!(check_delaunay(&pts, &t).is_ok());
///
/// // Moving corner 2 inwards puts it inside the circle through 0, 1, 3: only the
/// // diagonal 0-2 is Delaunay now.
/// let pts = [(0.0, 0.0), (2.0, 0.0), (1.5, 1.0), (0.0, 1.0)].map(Point2::from);
/// let t = Triangulation::from_triangles(&PointSet::new(&pts)?, &[[0, 1, 3], [1, 2, 3]], Vec::new())?;
/// assert!(check_delaunay(&pts, &t).unwrap_err().reason.contains("not locally Delaunay"));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn check_delaunay(points: &[Point2], t: &Triangulation) -> Result<(), Violation> {
    check_delaunay_with(points, t, &mut NoCount)
}

/// [`check_delaunay`], counting its predicates: one
/// [`orientation_test`](Counter::orientation_test) per triangle, one
/// [`incircle_test`](Counter::incircle_test) per interior edge (3n − 3 − 2h of them for n
/// distinct points with h on the hull, when every property holds), and the orientation tests
/// and comparisons of the keep-collinear hull it compares with. The search for duplicates
/// (a lexicographic sort) is not counted.
///
/// # Errors
/// As [`check_delaunay`].
///
/// # Complexity
/// O(n log n + t) time and O(n + t) auxiliary space, as [`check_delaunay`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::delaunay::{check_delaunay_with, Triangulation};
/// use compgeo::geometry::{Point2, PointSet};
///
/// // Four points around a fifth: four triangles, four interior edges, a hull of four.
/// let pts = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 0.9)].map(Point2::from);
/// let fan = [[4, 0, 1], [4, 1, 2], [4, 2, 3], [4, 3, 0]];
/// let t = Triangulation::from_triangles(&PointSet::new(&pts)?, &fan, Vec::new())?;
/// let mut c = Counts::default();
/// assert!(check_delaunay_with(&pts, &t, &mut c).is_ok());
/// assert_eq!(c.incircle_tests, 3 * 5 - 3 - 2 * 4);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn check_delaunay_with<C: Counter>(
    points: &[Point2],
    t: &Triangulation,
    counter: &mut C,
) -> Result<(), Violation> {
    check(points, t, counter).map_err(Violation::new)
}

/// [`check_delaunay`], each property's failure as its message.
fn check<C: Counter>(points: &[Point2], t: &Triangulation, counter: &mut C) -> Result<(), String> {
    let set = PointSet::new(points).map_err(|e| e.to_string())?;
    let n = points.len();
    let len = t.triangles.len();
    if len % 3 != 0 {
        return Err(format!("{len} triangle entries, not a multiple of 3"));
    }
    if t.halfedges.len() != len {
        return Err(format!(
            "{} half-edges for {len} triangle entries",
            t.halfedges.len()
        ));
    }
    if let Some(e) = (0..len).find(|&e| t.triangles[e] >= n) {
        return Err(format!(
            "half-edge {e} starts at vertex {}, but there are {n} points",
            t.triangles[e]
        ));
    }
    let p = |e: usize| points[t.triangles[e]];
    for e in 0..len {
        let f = t.halfedges[e];
        if f == EMPTY {
            continue;
        }
        if f >= len || t.halfedges[f] != e || f == e {
            return Err(format!("half-edge {e} and its opposite {f} are not paired"));
        }
        if t.triangles[f] != t.triangles[next_halfedge(e)]
            || t.triangles[next_halfedge(f)] != t.triangles[e]
        {
            return Err(format!("half-edges {e} and {f} are not reverses"));
        }
    }
    for tri in 0..len / 3 {
        let e = 3 * tri;
        if counter.orient2d(p(e), p(e + 1), p(e + 2)) != Orientation::CounterClockwise {
            return Err(format!(
                "triangle {tri} {:?} is not counter-clockwise",
                t.triangle(tri)
            ));
        }
    }
    for e in 0..len {
        let f = t.halfedges[e];
        if f != EMPTY && e < f {
            let across = p(prev_halfedge(f));
            let (a, b, c) = (p(e), p(next_halfedge(e)), p(prev_halfedge(e)));
            if counter.incircle(a, b, c, across) == InCircle::Inside {
                return Err(format!(
                    "edge {} - {} is not locally Delaunay: vertex {} is inside the circumcircle of triangle {:?}",
                    t.triangles[e],
                    t.triangles[next_halfedge(e)],
                    t.triangles[prev_halfedge(f)],
                    t.triangle(e / 3)
                ));
            }
        }
    }
    check_vertices(points, t)?;
    let expected = monotone_chain_with(
        &set,
        HullOptions {
            keep_collinear: true,
        },
        counter,
    );
    if t.hull != expected {
        return Err(format!(
            "hull {:?} differs from the keep-collinear convex hull {expected:?}",
            t.hull
        ));
    }
    let distinct = n - t.duplicates.len();
    if len == 0 {
        let degenerate =
            distinct < 3 || expected.len() == distinct && all_collinear(points, counter);
        return if degenerate {
            Ok(())
        } else {
            Err(format!(
                "no triangles for {distinct} distinct points that are not collinear"
            ))
        };
    }
    check_boundary(t)?;
    let h = t.hull.len();
    if len / 3 != 2 * distinct - 2 - h {
        return Err(format!(
            "{} triangles, but {distinct} distinct points with {h} on the hull need 2n - 2 - h = {}",
            len / 3,
            2 * distinct - 2 - h
        ));
    }
    Ok(())
}

/// Property 5: duplicates as [`find_duplicates`] reports them, and the vertices are the
/// distinct points (all of them when there are triangles).
fn check_vertices(points: &[Point2], t: &Triangulation) -> Result<(), String> {
    let expected = find_duplicates(points);
    if t.duplicates != expected {
        return Err(format!(
            "duplicates {:?} differ from the expected {expected:?}",
            t.duplicates
        ));
    }
    if t.triangles.is_empty() {
        return Ok(());
    }
    let mut is_vertex = vec![false; points.len()];
    for &v in &t.triangles {
        is_vertex[v] = true;
    }
    for &[dropped, _] in &t.duplicates {
        if is_vertex[dropped] {
            return Err(format!("duplicate point {dropped} is a vertex"));
        }
        is_vertex[dropped] = true;
    }
    match is_vertex.iter().position(|&v| !v) {
        Some(i) => Err(format!("point {i} is neither a vertex nor a duplicate")),
        None => Ok(()),
    }
}

/// Property 6, first half: the half-edges without an opposite form exactly the cycle `hull`.
fn check_boundary(t: &Triangulation) -> Result<(), String> {
    let boundary: Vec<usize> = (0..t.triangles.len())
        .filter(|&e| t.halfedges[e] == EMPTY)
        .collect();
    let h = t.hull.len();
    if boundary.len() != h {
        return Err(format!(
            "{} boundary half-edges, but the hull has {h} points",
            boundary.len()
        ));
    }
    let mut position = vec![EMPTY; t.triangles.iter().max().map_or(0, |&m| m + 1)];
    for (k, &v) in t.hull.iter().enumerate() {
        if v >= position.len() || position[v] != EMPTY {
            return Err(format!("hull point {v} is not a single vertex"));
        }
        position[v] = k;
    }
    for e in boundary {
        let (a, b) = (t.triangles[e], t.triangles[next_halfedge(e)]);
        if position[a] == EMPTY || position[b] != (position[a] + 1) % h {
            return Err(format!(
                "boundary half-edge {a} -> {b} is not an edge of the hull cycle"
            ));
        }
    }
    Ok(())
}

fn all_collinear<C: Counter>(points: &[Point2], counter: &mut C) -> bool {
    let Some(&a) = points.first() else {
        return true;
    };
    let Some(&b) = points.iter().find(|&&q| cmp_lex(q, a) != Ordering::Equal) else {
        return true;
    };
    points
        .iter()
        .all(|&q| counter.orient2d(a, b, q) == Orientation::Collinear)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
        v.iter().map(|&p| Point2::from(p)).collect()
    }

    #[test]
    fn accepts_a_valid_fan_and_rejects_broken_copies() {
        let p = pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 1.0)]);
        let tris = [[4, 0, 1], [4, 1, 2], [4, 2, 3], [4, 3, 0]];
        let t =
            Triangulation::from_triangles(&PointSet::new(&p).unwrap(), &tris, Vec::new()).unwrap();
        assert_eq!(check_delaunay(&p, &t), Ok(()));

        let mut cw = t.clone();
        cw.triangles.swap(1, 2);
        assert!(check_delaunay(&p, &cw).is_err());

        let mut unlinked = t.clone();
        let f = unlinked.halfedges[0];
        assert_ne!(f, EMPTY);
        unlinked.halfedges[0] = EMPTY;
        unlinked.halfedges[f] = EMPTY;
        assert!(check_delaunay(&p, &unlinked)
            .unwrap_err()
            .reason
            .contains("boundary"));

        let mut wrong_hull = t.clone();
        wrong_hull.hull.rotate_left(1);
        assert!(check_delaunay(&p, &wrong_hull).is_err());

        // Dropping the centre's fan leaves point 4 unused.
        let square = Triangulation::from_triangles(
            &PointSet::new(&p).unwrap(),
            &[[0, 1, 2], [0, 2, 3]],
            Vec::new(),
        );
        assert!(check_delaunay(&p, &square.unwrap())
            .unwrap_err()
            .reason
            .contains("neither a vertex"));
    }

    #[test]
    fn a_double_cover_fails_the_euler_count_or_the_boundary() {
        // Two overlapping fans of the same square about different centres.
        let p = pts(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0), (1.0, 1.0)]);
        let tris = [
            [0, 1, 2],
            [0, 2, 3],
            [4, 0, 1],
            [4, 1, 2],
            [4, 2, 3],
            [4, 3, 0],
        ];
        assert!(
            Triangulation::from_triangles(&PointSet::new(&p).unwrap(), &tris, Vec::new()).is_err()
        );
    }

    #[test]
    fn degenerate_sets_need_no_triangles_but_others_do() {
        let line = pts(&[(0.0, 0.0), (1.0, 1.0), (3.0, 3.0), (1.0, 1.0)]);
        let t = Triangulation::from_triangles(
            &PointSet::new(&line).unwrap(),
            &[],
            find_duplicates(&line),
        )
        .unwrap();
        assert_eq!(check_delaunay(&line, &t), Ok(()));
        let tri = pts(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]);
        let t =
            Triangulation::from_triangles(&PointSet::new(&tri).unwrap(), &[], Vec::new()).unwrap();
        assert!(check_delaunay(&tri, &t).is_err());
        let mut wrong =
            Triangulation::from_triangles(&PointSet::new(&line).unwrap(), &[], Vec::new()).unwrap();
        wrong.duplicates = vec![[3, 0]];
        assert!(check_delaunay(&line, &wrong).is_err());
    }
}
