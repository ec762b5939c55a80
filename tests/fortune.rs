//! Fortune's sweep: the exact checker on every generator kind and on degenerate suites
//! (horizontal rows, grids, cocircular lattice points, duplicates, collinear input, scaled
//! copies, huge and tiny magnitudes, subnormals), the same triangle set as the incremental
//! builder and spade where the Delaunay triangulation is unique, counts, bad input, the CLI.

use compgeo::count::Counts;
use compgeo::delaunay::{
    check_delaunay, find_duplicates, fortune, fortune_with, incremental, prev_halfedge,
    triangulate, Algorithm, Triangulation, EMPTY,
};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{incircle, InCircle, Point2};
use compgeo::Error;
use proptest::prelude::*;

#[cfg(feature = "cli")]
mod common;

/// Runs Fortune's sweep on `pts` and asserts the exact checker passes.
fn checked(pts: &[Point2], what: &str) -> Triangulation {
    let t = fortune(pts).unwrap_or_else(|e| panic!("fortune on {what}: {e}"));
    if let Err(e) = check_delaunay(pts, &t) {
        panic!("fortune on {what}: {e}");
    }
    t
}

/// The triangles as a sorted list of sorted vertex triples.
fn triangle_set(t: &Triangulation) -> Vec<[usize; 3]> {
    let mut out: Vec<[usize; 3]> = (0..t.triangle_count())
        .map(|k| {
            let mut tri = t.triangle(k);
            tri.sort_unstable();
            tri
        })
        .collect();
    out.sort_unstable();
    out
}

/// Whether the Delaunay triangulation is unique: no interior edge of `t` (a valid Delaunay
/// triangulation) has its opposite vertex exactly on the circumcircle.
fn is_unique_delaunay(pts: &[Point2], t: &Triangulation) -> bool {
    (0..t.triangles.len()).all(|e| {
        let f = t.halfedges[e];
        if f == EMPTY {
            return true;
        }
        let [a, b, c] = t.triangle(e / 3);
        let d = t.triangles[prev_halfedge(f)];
        incircle(pts[a], pts[b], pts[c], pts[d]) != InCircle::On
    })
}

/// Checks Fortune's result and, where the triangulation is unique, that it equals the
/// incremental builder's (checked too).
fn checked_against_incremental(pts: &[Point2], what: &str) -> Triangulation {
    let t = checked(pts, what);
    let reference = incremental(pts).unwrap();
    check_delaunay(pts, &reference).unwrap();
    if is_unique_delaunay(pts, &t) {
        assert_eq!(
            triangle_set(&t),
            triangle_set(&reference),
            "fortune and incremental differ on {what}"
        );
    } else {
        assert_eq!(t.triangle_count(), reference.triangle_count(), "{what}");
    }
    t
}

fn scaled(pts: &[Point2], s: f64) -> Vec<Point2> {
    pts.iter().map(|p| Point2::new(p.x * s, p.y * s)).collect()
}

#[test]
fn every_point_kind_gives_a_valid_triangulation() {
    for kind in PointKind::ALL {
        for n in [0, 1, 2, 3, 4, 5, 6, 7, 9, 16, 50, 300] {
            for seed in 0..3 {
                let pts = points(kind, n, seed).unwrap();
                checked_against_incremental(&pts, &format!("{kind} n={n} seed={seed}"));
            }
        }
    }
}

#[test]
fn larger_inputs_of_every_kind() {
    for kind in PointKind::ALL {
        let pts = points(kind, 2000, 7).unwrap();
        checked(&pts, &format!("{kind} n=2000"));
    }
}
