//! The divide-and-conquer, Lawson and Fortune builders: the exact checker on every generator
//! kind and on degenerate suites, agreement with the incremental builder and spade where the
//! Delaunay triangulation is unique, counted variants, bad input, and proptests. Tests of what
//! is particular to Fortune's sweep (sites on one horizontal line, many circle events at one
//! point, its counts) are in `tests/fortune.rs`.

use compgeo::count::Counts;
use compgeo::delaunay::{
    check_delaunay, divide_and_conquer, divide_and_conquer_with, find_duplicates, fortune,
    incremental, lawson, lawson_with, Triangulation, EMPTY,
};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::Point2;
use compgeo::{Error, Result};
use proptest::prelude::*;

use crate::common::{is_unique_delaunay, triangle_set};

type Builder = fn(&[Point2]) -> Result<Triangulation>;

/// The builders of this file, by name, and the fast builder they are compared with.
const BUILDERS: [(&str, Builder); 4] = [
    ("divide-and-conquer", divide_and_conquer),
    ("lawson", lawson),
    ("fortune", fortune),
    ("incremental", incremental),
];

/// Runs every builder on `pts` and asserts the exact checker passes; returns the results.
fn build_all_checked(pts: &[Point2], what: &str) -> Vec<Triangulation> {
    BUILDERS
        .iter()
        .map(|(name, build)| {
            let t = build(pts).unwrap_or_else(|e| panic!("{name} on {what}: {e}"));
            if let Err(e) = check_delaunay(pts, &t) {
                panic!("{name} on {what}: {e}");
            }
            t
        })
        .collect()
}

/// Asserts that all builders return the same triangle set when the triangulation is unique;
/// returns whether it was.
fn assert_agree_if_unique(pts: &[Point2], results: &[Triangulation], what: &str) -> bool {
    if !is_unique_delaunay(pts, &results[0]) {
        return false;
    }
    let first = triangle_set(&results[0]);
    for (k, t) in results.iter().enumerate().skip(1) {
        assert_eq!(
            triangle_set(t),
            first,
            "{} and {} differ on {what}",
            BUILDERS[0].0,
            BUILDERS[k].0
        );
    }
    true
}

fn scaled(pts: &[Point2], s: f64) -> Vec<Point2> {
    pts.iter().map(|p| Point2::new(p.x * s, p.y * s)).collect()
}

#[test]
fn every_point_kind_gives_a_valid_triangulation() {
    for kind in PointKind::ALL {
        for n in [0, 1, 2, 3, 4, 5, 6, 7, 9, 16, 50, 200] {
            for seed in 0..2 {
                let pts = points(kind, n, seed).unwrap();
                let what = format!("{kind} n={n} seed={seed}");
                let results = build_all_checked(&pts, &what);
                assert_agree_if_unique(&pts, &results, &what);
            }
        }
    }
}

#[test]
fn divide_and_conquer_on_larger_inputs_of_every_kind() {
    for kind in PointKind::ALL {
        let pts = points(kind, 1000, 7).unwrap();
        let t = divide_and_conquer(&pts).unwrap();
        check_delaunay(&pts, &t).unwrap_or_else(|e| panic!("{kind}: {e}"));
    }
}

#[test]
fn builders_agree_on_general_position_input() {
    for (kind, n) in [
        (PointKind::UniformSquare, 1000),
        (PointKind::UniformDisk, 700),
        (PointKind::Gaussian, 700),
        (PointKind::Clustered, 700),
    ] {
        for seed in 0..2 {
            let pts = points(kind, n, seed).unwrap();
            let what = format!("{kind} n={n} seed={seed}");
            let results = build_all_checked(&pts, &what);
            assert!(
                assert_agree_if_unique(&pts, &results, &what),
                "{what}: random input is in general position"
            );
            assert_eq!(
                triangle_set(&results[0]),
                crate::common::spade_triangles(&pts),
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
        build_all_checked(&scaled(&base, s), &format!("disk scaled by 1e{e}"));
        build_all_checked(&scaled(&grid, s), &format!("rotated grid scaled by 1e{e}"));
    }
}

#[test]
fn power_of_two_scaling_keeps_the_triangles() {
    // Scaling by 2^k is exact, so the point set is the same up to similarity and a unique
    // Delaunay triangulation must not change, down to subnormal and up to huge coordinates.
    let base = points(PointKind::UniformSquare, 200, 11).unwrap();
    let reference = divide_and_conquer(&base).unwrap();
    assert!(is_unique_delaunay(&base, &reference));
    let want = triangle_set(&reference);
    for k in [-1060, -1000, -500, -60, 60, 500, 1000, 1020] {
        let s = 2f64.powi(k);
        let pts = scaled(&base, s);
        for (name, t) in BUILDERS
            .iter()
            .zip(build_all_checked(&pts, &format!("2^{k}")))
        {
            if k >= -1000 {
                assert_eq!(triangle_set(&t), want, "{} at scale 2^{k}", name.0);
            }
        }
    }
}

#[test]
fn huge_and_tiny_magnitudes_in_one_set() {
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
    let what = "huge, tiny and unit points";
    let results = build_all_checked(&pts, what);
    assert_agree_if_unique(&pts, &results, what);
    // Only points near the origin next to the extreme ones: all of them are squeezed into
    // fans around the origin, where inexact code collapses.
    let mut pts = points(PointKind::Tiny, 30, 4).unwrap();
    pts.extend([
        Point2::new(1e300, 0.0),
        Point2::new(0.0, 1e300),
        Point2::new(-1e300, -1e300),
    ]);
    let what = "tiny points inside a huge triangle";
    let results = build_all_checked(&pts, what);
    assert_agree_if_unique(&pts, &results, what);
}

#[test]
fn near_duplicates_one_ulp_apart() {
    let up = |v: f64| f64::from_bits(v.to_bits() + 1);
    let mut pts = Vec::new();
    for i in 0..6 {
        for j in 0..6 {
            let p = Point2::new(1.0 + i as f64 * 0.25, 3.0 + j as f64 * 0.5);
            pts.push(p);
            pts.push(Point2::new(up(p.x), p.y));
            pts.push(Point2::new(p.x, up(p.y)));
            pts.push(Point2::new(up(p.x), up(p.y)));
        }
    }
    let results = build_all_checked(&pts, "grid with ulp neighbours");
    assert!(results[0].duplicates.is_empty());
    for seed in 0..4 {
        let pts = points(PointKind::NearDuplicates, 400, seed).unwrap();
        build_all_checked(&pts, &format!("near-duplicates seed {seed}"));
    }
}

#[test]
fn duplicates_are_merged_and_reported() {
    let base = points(PointKind::Grid, 25, 0).unwrap();
    // Every point three times, in an interleaved order, plus -0.0 against 0.0.
    let mut pts = Vec::new();
    for round in 0..3 {
        for k in 0..base.len() {
            pts.push(base[(k * 7 + round * 3) % base.len()]);
        }
    }
    pts.push(Point2::new(-0.0, -0.0));
    for t in build_all_checked(&pts, "grid three times") {
        assert_eq!(t.duplicates, find_duplicates(&pts));
        assert_eq!(t.duplicates.len(), 2 * base.len() + 1);
        assert!(t.duplicates.iter().all(|&[d, k]| k < d));
        assert_eq!(t.triangle_count(), 32);
    }
}

#[test]
fn collinear_input_gives_no_triangles_and_the_line_as_hull() {
    let big = 2f64.powi(900);
    let mut line: Vec<Point2> = (0..20)
        .map(|i| {
            let k = ((i * 7) % 20) as f64;
            Point2::new(3.0 * k * big, -2.0 * k * big)
        })
        .collect();
    line.push(line[4]);
    let vertical: Vec<Point2> = (0..9).map(|i| Point2::new(2.5, 9.0 - i as f64)).collect();
    for (pts, what) in [(line, "sloped line"), (vertical, "vertical line")] {
        for t in build_all_checked(&pts, what) {
            assert!(t.is_empty());
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
}

#[test]
fn points_on_one_circle_give_a_fan_of_n_minus_2_triangles() {
    for n in [4, 12, 60, 200] {
        let pts = points(PointKind::Cocircular, n, 5).unwrap();
        for t in build_all_checked(&pts, &format!("{n} cocircular")) {
            assert_eq!(t.triangle_count(), n - 2);
            assert_eq!(t.hull.len(), n);
        }
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
        for t in build_all_checked(pts, &format!("{pts:?}")) {
            assert!(t.is_empty());
            assert_eq!(t.hull.len(), pts.len().min(2));
        }
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
        for (name, build) in BUILDERS {
            match build(&pts) {
                Err(Error::NonFinite { index: 2, .. }) => {}
                other => panic!("{name}: {other:?}"),
            }
        }
    }
}

#[test]
fn counted_variants_return_the_same_triangulation() {
    let pts = points(PointKind::Clustered, 400, 9).unwrap();
    let mut counts = Counts::default();
    let t = divide_and_conquer_with(&crate::common::set(&pts), &mut counts).unwrap();
    assert_eq!(t, divide_and_conquer(&pts).unwrap());
    assert!(counts.comparisons >= pts.len() as u64 - 1);
    assert!(counts.orientation_tests > 0 && counts.incircle_tests > 0);

    let mut counts = Counts::default();
    let t = lawson_with(&crate::common::set(&pts), &mut counts).unwrap();
    assert_eq!(t, lawson(&pts).unwrap());
    // Every interior edge is checked at least once; the sweep pops each point at most once
    // per chain, and each chain's loop ends with one failed test per point.
    let interior = t.halfedges.iter().filter(|&&f| f != EMPTY).count() as u64 / 2;
    assert!(counts.incircle_tests >= interior);
    assert!(counts.orientation_tests <= 4 * pts.len() as u64);
}

#[test]
fn lawson_is_quadratic_on_the_parabola_and_divide_and_conquer_is_not() {
    // Counts, not times: the sweep fans every point from the first one, and Lawson needs a
    // quadratic number of flips to undo that; the merge stays near linear per level.
    let tests = |n: usize| {
        let pts = points(PointKind::Parabola, n, 0).unwrap();
        let (mut lw, mut dc) = (Counts::default(), Counts::default());
        lawson_with(&crate::common::set(&pts), &mut lw).unwrap();
        divide_and_conquer_with(&crate::common::set(&pts), &mut dc).unwrap();
        (lw.incircle_tests as f64, dc.incircle_tests as f64)
    };
    let (lw1, dc1) = tests(200);
    let (lw2, dc2) = tests(400);
    assert!(lw2 / lw1 > 3.5, "Lawson: {lw1} then {lw2}");
    assert!(dc2 / dc1 < 2.5, "divide and conquer: {dc1} then {dc2}");
}

#[cfg(feature = "cli")]
#[test]
fn cli_runs_each_builder_and_rejects_bad_input() {
    use crate::common::{assert_rejected, run_json};
    let mut pts = points(PointKind::UniformDisk, 40, 2).unwrap();
    pts.push(pts[7]);
    let input = serde_json::to_string(&pts.iter().map(|p| [p.x, p.y]).collect::<Vec<_>>()).unwrap();
    for (name, build) in &BUILDERS[..3] {
        let v = run_json(&["delaunay", "--algorithm", name, "-"], Some(&input));
        assert_eq!(v["algorithm"], *name);
        let want = build(&pts).unwrap();
        let tris: Vec<[usize; 3]> = serde_json::from_value(v["triangles"].clone()).unwrap();
        let printed = Triangulation::from_triangles(
            &crate::common::set(&pts),
            &tris,
            want.duplicates.clone(),
        )
        .unwrap();
        assert_eq!(triangle_set(&printed), triangle_set(&want), "{name}");
        assert_eq!(v["hull"], serde_json::json!(want.hull), "{name}");
        assert_eq!(v["duplicates"], serde_json::json!([[40, 7]]), "{name}");
        // Fortune's sweep decides by comparisons of events and breakpoints, not in-circle
        // tests.
        let deciding = if *name == "fortune" {
            "comparisons"
        } else {
            "incircle_tests"
        };
        assert!(v["counts"][deciding].as_u64().unwrap() > 0, "{name}");
        assert!(
            v["counts"]["orientation_tests"].as_u64().unwrap() > 0,
            "{name}"
        );
        let err = assert_rejected(
            &["delaunay", "--algorithm", name, "-"],
            Some("[[0, 0], [1, 1], [2, 0], [1e999, 1]]"),
        );
        assert!(err.contains('3'), "{name}: {err}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn lattice_sets_are_valid(pts in crate::strategies::lattice(-4..=4, 0..40)) {
        build_all_checked(&pts, &format!("{pts:?}"));
    }


    #[test]
    fn builders_agree_on_random_points(
        v in prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 3..60)
    ) {
        let pts: Vec<Point2> = v.into_iter().map(Point2::from).collect();
        let what = format!("{pts:?}");
        let results = build_all_checked(&pts, &what);
        if assert_agree_if_unique(&pts, &results, &what) && results[0].duplicates.is_empty() {
            prop_assert_eq!(triangle_set(&results[0]), crate::common::spade_triangles(&pts));
        }
    }
}

proptest! {
    // The big-integer stage of the predicates is slow in a debug build.
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn mixed_magnitudes_are_valid(pts in crate::strategies::mixed_magnitudes(0..16)) {
        build_all_checked(&pts, &format!("{pts:?}"));
    }
}
