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
        // The adversarial magnitudes go through the exact stages often; keep them smaller.
        let n = match kind {
            PointKind::Tiny | PointKind::NearDuplicates => 400,
            _ => 1500,
        };
        let pts = points(kind, n, 7).unwrap();
        checked(&pts, &format!("{kind} n={n}"));
    }
}

#[test]
fn agrees_with_incremental_and_spade_on_general_position_input() {
    for (kind, n) in [
        (PointKind::UniformSquare, 1000),
        (PointKind::UniformDisk, 700),
        (PointKind::Gaussian, 700),
        (PointKind::Clustered, 700),
    ] {
        for seed in 0..2 {
            let pts = points(kind, n, seed).unwrap();
            let what = format!("{kind} n={n} seed={seed}");
            let t = checked_against_incremental(&pts, &what);
            assert!(
                is_unique_delaunay(&pts, &t),
                "{what}: random input is in general position"
            );
            #[cfg(feature = "cli")]
            assert_eq!(
                triangle_set(&t),
                common::spade_triangles(&pts),
                "{what}: spade"
            );
        }
    }
}

#[test]
fn scaled_copies_from_1e_minus_100_to_1e100_are_valid() {
    let base = points(PointKind::UniformDisk, 120, 3).unwrap();
    let grid = points(PointKind::RotatedGrid, 49, 3).unwrap();
    for e in (-100..=100).step_by(20) {
        let s = 10f64.powi(e);
        checked_against_incremental(&scaled(&base, s), &format!("disk scaled by 1e{e}"));
        checked_against_incremental(&scaled(&grid, s), &format!("rotated grid scaled by 1e{e}"));
    }
}

#[test]
fn power_of_two_scaling_keeps_the_triangles() {
    // Scaling by 2^k is exact, so a unique Delaunay triangulation must not change, down to
    // subnormal and up to huge coordinates (below 2^-1000 the points start to lose bits).
    let base = points(PointKind::UniformSquare, 200, 11).unwrap();
    let reference = checked(&base, "base");
    assert!(is_unique_delaunay(&base, &reference));
    let want = triangle_set(&reference);
    for k in [-1060, -1000, -500, -60, 60, 500, 1000, 1020] {
        let pts = scaled(&base, 2f64.powi(k));
        let t = checked(&pts, &format!("2^{k}"));
        if k >= -1000 {
            assert_eq!(triangle_set(&t), want, "scale 2^{k}");
        }
    }
}

#[test]
fn huge_tiny_and_subnormal_magnitudes_in_one_set() {
    let mut pts = points(PointKind::Huge, 20, 1).unwrap();
    pts.extend(points(PointKind::Tiny, 20, 2).unwrap());
    pts.extend(points(PointKind::UniformDisk, 20, 3).unwrap());
    pts.extend([
        Point2::new(5e-324, 0.0),
        Point2::new(0.0, 5e-324),
        Point2::new(-5e-324, -5e-324),
        Point2::new(f64::MAX, f64::MAX),
        Point2::new(-f64::MAX, f64::MAX),
        Point2::new(f64::MAX, -f64::MAX),
        Point2::new(1e300, 1e-300),
        Point2::new(-1e-300, 1e300),
    ]);
    checked_against_incremental(&pts, "huge, tiny and unit points");
    // Tiny points in a fan inside a huge triangle.
    let mut pts = points(PointKind::Tiny, 30, 4).unwrap();
    pts.extend([
        Point2::new(1e300, 0.0),
        Point2::new(0.0, 1e300),
        Point2::new(-1e300, -1e300),
    ]);
    checked_against_incremental(&pts, "tiny points inside a huge triangle");
    // Only subnormals: a 5 x 5 grid of multiples of the smallest one, and a random set.
    let unit = 5e-324;
    let sub: Vec<Point2> = (0..25)
        .map(|i| Point2::new((i % 5) as f64 * unit, (i / 5) as f64 * unit))
        .collect();
    let t = checked_against_incremental(&sub, "subnormal grid");
    assert_eq!(t.triangle_count(), 32);
}

#[test]
fn sites_on_horizontal_rows() {
    // The first row is a run of vertical strips; later rows put several sites on the sweep
    // line at once, some of them exactly above breakpoints.
    for rows in [1, 2, 3, 5] {
        for per_row in [2, 3, 7] {
            let pts: Vec<Point2> = (0..rows * per_row)
                .map(|i| {
                    let (r, c) = (i / per_row, i % per_row);
                    // Odd rows shifted by half a step: their sites are above the midpoints.
                    Point2::new(c as f64 * 2.0 + (r % 2) as f64, r as f64 * 1.5)
                })
                .collect();
            let what = format!("{rows} rows of {per_row}");
            let t = checked_against_incremental(&pts, &what);
            if rows == 1 {
                assert!(t.is_empty(), "{what}");
            }
        }
    }
    // A lowest row of many sites, then one site above all their breakpoints' meeting area.
    let mut pts: Vec<Point2> = (0..9).map(|i| Point2::new(i as f64, 0.0)).collect();
    pts.push(Point2::new(4.0, 1.0));
    pts.push(Point2::new(3.5, 7.0));
    pts.push(Point2::new(-2.0, 0.5));
    checked_against_incremental(&pts, "row with apexes");
}

#[test]
fn grids_and_cocircular_lattice_points() {
    // Grids: four cocircular sites at every Voronoi vertex, two circle events at one point.
    for (w, h) in [(2, 2), (3, 3), (4, 7), (10, 10), (17, 3)] {
        let pts: Vec<Point2> = (0..w * h)
            .map(|i| Point2::new((i % w) as f64, (i / w) as f64))
            .collect();
        let t = checked(&pts, &format!("{w} x {h} grid"));
        assert_eq!(t.triangle_count(), 2 * (w - 1) * (h - 1));
    }
    // The lattice points of the circles x² + y² = 25 and 50 (12 + 12 sites), with and
    // without the centre: up to 12 sites on one empty circle, 10 events at one point.
    let mut circle25 = Vec::new();
    let mut circle50 = Vec::new();
    for x in -7i32..=7 {
        for y in -7i32..=7 {
            let p = Point2::new(x as f64, y as f64);
            match x * x + y * y {
                25 => circle25.push(p),
                50 => circle50.push(p),
                _ => {}
            }
        }
    }
    assert_eq!((circle25.len(), circle50.len()), (12, 12));
    let t = checked(&circle25, "lattice circle r = 5");
    assert_eq!(t.triangle_count(), 10);
    let mut both = circle25.clone();
    both.extend(&circle50);
    checked(&both, "lattice circles r = 5 and r = 5√2");
    both.push(Point2::new(0.0, 0.0));
    checked(&both, "lattice circles and their centre");
    for n in [4, 12, 60, 200] {
        let pts = points(PointKind::Cocircular, n, 5).unwrap();
        let t = checked(&pts, &format!("{n} cocircular"));
        assert_eq!(t.triangle_count(), n - 2);
        assert_eq!(t.hull.len(), n);
    }
}

#[test]
fn duplicates_are_merged_and_reported() {
    let base = points(PointKind::Grid, 25, 0).unwrap();
    let mut pts = Vec::new();
    for round in 0..3 {
        for k in 0..base.len() {
            pts.push(base[(k * 7 + round * 3) % base.len()]);
        }
    }
    pts.push(Point2::new(-0.0, -0.0));
    let t = checked(&pts, "grid three times");
    assert_eq!(t.duplicates, find_duplicates(&pts));
    assert_eq!(t.duplicates.len(), 2 * base.len() + 1);
    assert_eq!(t.triangle_count(), 32);
}

#[test]
fn collinear_input_gives_no_triangles_and_the_line_as_hull() {
    let big = 2f64.powi(900);
    let line: Vec<Point2> = (0..20)
        .map(|i| {
            let k = ((i * 7) % 20) as f64;
            Point2::new(3.0 * k * big, -2.0 * k * big)
        })
        .collect();
    let vertical: Vec<Point2> = (0..9).map(|i| Point2::new(2.5, 9.0 - i as f64)).collect();
    let horizontal: Vec<Point2> = (0..9)
        .map(|i| Point2::new((i * 5 % 9) as f64, -1.0))
        .collect();
    for (pts, what) in [
        (line, "sloped"),
        (vertical, "vertical"),
        (horizontal, "horizontal"),
    ] {
        let t = checked(&pts, what);
        assert!(t.is_empty(), "{what}");
        let mut sorted = t.hull.clone();
        sorted.sort_by(|&a, &b| {
            pts[a]
                .x
                .total_cmp(&pts[b].x)
                .then(pts[a].y.total_cmp(&pts[b].y))
        });
        assert_eq!(t.hull, sorted, "{what}: the hull runs along the line");
    }
}

#[test]
fn fewer_than_three_distinct_points_are_not_an_error() {
    let cases: [&[Point2]; 4] = [
        &[],
        &[Point2::new(1.0, 2.0)],
        &[Point2::new(1.0, 2.0), Point2::new(-1.0, 0.0)],
        &[
            Point2::new(1.0, 2.0),
            Point2::new(1.0, 2.0),
            Point2::new(0.0, 0.0),
        ],
    ];
    for pts in cases {
        let t = checked(pts, &format!("{pts:?}"));
        assert!(t.is_empty());
        assert_eq!(t.hull.len(), pts.len().min(2));
    }
}

#[test]
fn non_finite_input_is_rejected() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let pts = [
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(0.5, bad),
        ];
        match fortune(&pts) {
            Err(Error::NonFinite { index: 2, .. }) => {}
            other => panic!("{bad}: {other:?}"),
        }
        match triangulate(&pts, Algorithm::Fortune) {
            Err(Error::NonFinite { index: 2, .. }) => {}
            other => panic!("{bad}: {other:?}"),
        }
    }
}

#[test]
fn registered_as_an_algorithm() {
    let a: Algorithm = "fortune".parse().unwrap();
    assert_eq!(a, Algorithm::Fortune);
    assert_eq!(a.name(), "fortune");
    assert!(Algorithm::ALL.contains(&Algorithm::Fortune));
    let pts = points(PointKind::Gaussian, 300, 4).unwrap();
    let mut counts = Counts::default();
    let t = Algorithm::Fortune
        .triangulate_with(&pts, &mut counts)
        .unwrap();
    assert_eq!(t, fortune(&pts).unwrap());
    assert!(counts.comparisons > 0);
}

#[test]
fn counts_grow_as_n_log_n_on_the_parabola_and_uniform_input() {
    // Counts, not times: per point, the comparisons (sort, heap and beach-line descent) grow
    // like log n, far from the doubling a quadratic method shows; no in-circle tests.
    for kind in [PointKind::Parabola, PointKind::UniformSquare] {
        let per_point = |n: usize| {
            let pts = points(kind, n, 0).unwrap();
            let mut c = Counts::default();
            let t = fortune_with(&pts, &mut c).unwrap();
            assert_eq!(t, fortune(&pts).unwrap());
            assert_eq!(c.incircle_tests, 0);
            // At least one convergence check per circle event (= triangle).
            assert!(c.orientation_tests >= t.triangle_count() as u64);
            // At most two per site event and two per circle event.
            assert!(c.orientation_tests <= 2 * (n + t.triangle_count()) as u64);
            c.comparisons as f64 / n as f64
        };
        let (small, large) = (per_point(500), per_point(4000));
        let ratio = large / small;
        // log2(4000) / log2(500) = 1.33; a linear factor would give 8.
        assert!(
            ratio > 1.0 && ratio < 1.8,
            "{kind}: {small} then {large} per point"
        );
    }
}

#[cfg(feature = "cli")]
#[test]
fn cli_runs_fortune_and_rejects_bad_input() {
    use common::{assert_rejected, run_json};
    let mut pts = points(PointKind::UniformDisk, 40, 2).unwrap();
    pts.push(pts[7]);
    let input = serde_json::to_string(&pts.iter().map(|p| [p.x, p.y]).collect::<Vec<_>>()).unwrap();
    let v = run_json(&["delaunay", "--algorithm", "fortune", "-"], Some(&input));
    assert_eq!(v["algorithm"], "fortune");
    let want = fortune(&pts).unwrap();
    let tris: Vec<[usize; 3]> = serde_json::from_value(v["triangles"].clone()).unwrap();
    let printed = Triangulation::from_triangles(&pts, &tris, want.duplicates.clone()).unwrap();
    assert_eq!(triangle_set(&printed), triangle_set(&want));
    check_delaunay(&pts, &printed).unwrap();
    assert_eq!(v["hull"], serde_json::json!(want.hull));
    assert_eq!(v["duplicates"], serde_json::json!([[40, 7]]));
    assert!(v["counts"]["comparisons"].as_u64().unwrap() > 0);
    assert!(v["counts"]["orientation_tests"].as_u64().unwrap() > 0);
    let err = assert_rejected(
        &["delaunay", "--algorithm", "fortune", "-"],
        Some("[[0, 0], [1, 1], [2, 0], [1e999, 1]]"),
    );
    assert!(err.contains('3'), "{err}");
}

/// Small integer coordinates: many duplicates, collinear triples, cocircular quadruples,
/// sites on one horizontal line and sites exactly above breakpoints.
fn lattice_points() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-4i32..=4, -4i32..=4), 0..40).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Point2::new(x as f64, y as f64))
            .collect()
    })
}

/// Points whose coordinates mix magnitudes from subnormal to huge.
fn mixed_magnitude_points() -> impl Strategy<Value = Vec<Point2>> {
    let coord = (
        -1i32..=1,
        1u32..4,
        prop::sample::select(vec![-1074, -600, -3, 0, 5, 300, 1000]),
    )
        .prop_map(|(sign, m, e)| sign as f64 * m as f64 * 2f64.powi(e));
    prop::collection::vec((coord.clone(), coord), 0..16)
        .prop_map(|v| v.into_iter().map(Point2::from).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn lattice_sets_are_valid(pts in lattice_points()) {
        checked_against_incremental(&pts, &format!("{pts:?}"));
    }

    #[test]
    fn same_triangles_as_incremental_on_random_points(
        v in prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 3..60)
    ) {
        let pts: Vec<Point2> = v.into_iter().map(Point2::from).collect();
        let t = checked_against_incremental(&pts, &format!("{pts:?}"));
        // Random doubles are in general position: the triangulation is unique.
        prop_assert!(is_unique_delaunay(&pts, &t));
    }
}

proptest! {
    // The big-integer stages are slow in a debug build.
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn mixed_magnitudes_are_valid(pts in mixed_magnitude_points()) {
        checked_against_incremental(&pts, &format!("{pts:?}"));
    }
}
