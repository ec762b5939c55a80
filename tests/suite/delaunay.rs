//! Delaunay triangulations: every result passes the exact checker; the incremental builder
//! agrees with spade on general-position input; degenerate and bad input.

use compgeo::count::Counts;
use compgeo::delaunay::{
    check_delaunay, find_duplicates, incremental, incremental_with, Triangulation,
};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::Point2;
use compgeo::hull::{monotone_chain, HullOptions};
use compgeo::Error;
use proptest::prelude::*;
use std::collections::BTreeSet;

fn build_and_check(pts: &[Point2]) -> Triangulation {
    let t = incremental(pts).unwrap();
    if let Err(why) = check_delaunay(pts, &t) {
        panic!("{} points: {why}\npoints: {pts:?}", pts.len());
    }
    t
}

/// Triangles as sorted vertex triples, so two triangulations compare as sets.
fn triangle_set(t: &Triangulation) -> BTreeSet<[usize; 3]> {
    (0..t.triangle_count())
        .map(|k| {
            let mut tri = t.triangle(k);
            tri.sort_unstable();
            tri
        })
        .collect()
}

fn spade_triangle_set(pts: &[Point2]) -> BTreeSet<[usize; 3]> {
    crate::common::spade_triangles(pts).into_iter().collect()
}

#[test]
fn every_generator_kind_gives_a_valid_delaunay_triangulation() {
    for kind in PointKind::ALL {
        for n in [0, 1, 2, 3, 4, 5, 7, 10, 31, 100, 400, 2000] {
            for seed in 0..3 {
                let pts = points(kind, n, seed).unwrap();
                let t = build_and_check(&pts);
                if kind == PointKind::Collinear {
                    assert!(t.is_empty(), "collinear input has no triangles");
                }
            }
        }
    }
}

#[test]
fn degenerate_kinds_at_a_larger_size() {
    for kind in [
        PointKind::Grid,
        PointKind::RotatedGrid,
        PointKind::Cocircular,
        PointKind::NearDuplicates,
        PointKind::Parabola,
        PointKind::Clustered,
    ] {
        build_and_check(&points(kind, 20_000, 11).unwrap());
    }
}

#[test]
fn inputs_past_one_widening_slice_are_valid_and_agree_with_spade() {
    // 50 000 points make about 300 000 triangle corners: more than one slice (2^18) of the
    // builder's 32- to 64-bit conversion, so its slice boundaries are crossed.
    let pts = points(PointKind::UniformSquare, 50_000, 3).unwrap();
    let t = build_and_check(&pts);
    assert!(t.triangles.len() > 1 << 18);
    assert_eq!(triangle_set(&t), spade_triangle_set(&pts));
    // A grid (cocircular quadruples everywhere) with copies of some points.
    let mut grid = points(PointKind::Grid, 50_000, 3).unwrap();
    grid.extend_from_within(..1000);
    let t = build_and_check(&grid);
    assert!(t.triangles.len() > 1 << 18);
    assert_eq!(t.duplicates, find_duplicates(&grid));
}

#[test]
fn agrees_with_spade_on_points_in_general_position() {
    for (kind, n) in [
        (PointKind::UniformSquare, 3000),
        (PointKind::UniformDisk, 2000),
        (PointKind::Gaussian, 2000),
        (PointKind::Clustered, 2000),
    ] {
        for seed in 0..3 {
            let pts = points(kind, n, seed).unwrap();
            let t = build_and_check(&pts);
            assert_eq!(
                triangle_set(&t),
                spade_triangle_set(&pts),
                "{kind:?} seed {seed}"
            );
        }
    }
}

#[test]
fn power_of_two_scaled_copies_have_the_same_triangles() {
    // Scaling by 2^k is exact, so the Delaunay triangulation is the same set of triangles.
    let base = points(PointKind::UniformSquare, 1500, 5).unwrap();
    let reference = triangle_set(&build_and_check(&base));
    for k in [-1000, -600, -300, -100, -20, 20, 100, 300, 600, 1000] {
        let s = 2f64.powi(k);
        let scaled: Vec<Point2> = base.iter().map(|p| Point2::new(p.x * s, p.y * s)).collect();
        assert_eq!(triangle_set(&build_and_check(&scaled)), reference, "2^{k}");
    }
}

#[test]
fn decimal_scaled_copies_from_1e_minus_100_to_1e100_are_valid() {
    for kind in [
        PointKind::UniformSquare,
        PointKind::Grid,
        PointKind::Cocircular,
    ] {
        let base = points(kind, 600, 2).unwrap();
        for e in (-100..=100).step_by(25) {
            let s = 10f64.powi(e);
            let scaled: Vec<Point2> = base.iter().map(|p| Point2::new(p.x * s, p.y * s)).collect();
            build_and_check(&scaled);
        }
    }
}

#[test]
fn huge_and_tiny_magnitudes_in_one_set() {
    for seed in 0..4 {
        let mut pts = points(PointKind::Huge, 300, seed).unwrap();
        pts.extend(points(PointKind::Tiny, 300, seed + 10).unwrap());
        pts.extend(points(PointKind::UniformSquare, 100, seed).unwrap());
        pts.push(Point2::new(f64::MAX, f64::MAX));
        pts.push(Point2::new(-f64::MAX, f64::MAX));
        pts.push(Point2::new(5e-324, -5e-324));
        pts.push(Point2::new(0.0, 0.0));
        build_and_check(&pts);
    }
    // Points one ulp apart around 1e300 and a subnormal triangle at the origin.
    let big: f64 = 1e300;
    let up = f64::from_bits(big.to_bits() + 1);
    let pts = [
        (big, big),
        (up, big),
        (big, up),
        (up, up),
        (5e-324, 0.0),
        (0.0, 5e-324),
        (-5e-324, -5e-324),
        (-big, 0.0),
    ]
    .map(Point2::from);
    build_and_check(&pts);
}

#[test]
fn duplicates_are_merged_into_the_smallest_index() {
    let base = points(PointKind::UniformSquare, 200, 3).unwrap();
    // Every point three times, the copies scattered; plus -0.0 against 0.0.
    let mut pts = Vec::new();
    for round in 0..3 {
        for k in 0..base.len() {
            pts.push(base[(k * 7 + round * 13) % base.len()]);
        }
    }
    pts.push(Point2::new(0.0, -0.0));
    pts.push(Point2::new(-0.0, 0.0));
    let t = build_and_check(&pts);
    assert_eq!(t.duplicates.len(), 2 * base.len() + 1);
    assert_eq!(t.duplicates, find_duplicates(&pts));
    assert!(t.duplicates.contains(&[pts.len() - 1, pts.len() - 2]));
}

#[test]
fn fewer_than_three_distinct_points_and_collinear_sets_have_no_triangles() {
    let p = |x, y| Point2::new(x, y);
    let empty = incremental(&[]).unwrap();
    assert!(empty.is_empty() && empty.hull.is_empty() && empty.duplicates.is_empty());
    let one = incremental(&[p(1.0, 2.0)]).unwrap();
    assert_eq!(one.hull, [0]);
    let two = incremental(&[p(1.0, 2.0), p(0.0, 0.0)]).unwrap();
    assert_eq!(two.hull, [1, 0]);
    let same = incremental(&[p(1.0, 1.0), p(1.0, 1.0), p(1.0, 1.0)]).unwrap();
    assert_eq!(same.hull, [0]);
    assert_eq!(same.duplicates, [[1, 0], [2, 0]]);
    let line = [
        p(2.0, 2.0),
        p(0.0, 0.0),
        p(1.0, 1.0),
        p(3.0, 3.0),
        p(1.0, 1.0),
    ];
    let t = build_and_check(&line);
    assert!(t.is_empty());
    assert_eq!(t.hull, [1, 2, 0, 3]);
    assert_eq!(t.duplicates, [[4, 2]]);
}

#[test]
fn hull_equals_the_hull_modules_keep_collinear_hull() {
    let keep = HullOptions {
        keep_collinear: true,
    };
    for kind in PointKind::ALL {
        let pts = points(kind, 500, 9).unwrap();
        let t = incremental(&pts).unwrap();
        assert_eq!(t.hull, monotone_chain(&pts, keep).unwrap(), "{kind:?}");
    }
}

#[test]
fn points_on_a_hull_edge_and_on_its_extension() {
    // A square whose sides get extra points, inserted in an order that puts some of them
    // on existing hull edges and some beyond a hull vertex on its line.
    let mut pts = vec![
        Point2::new(0.0, 0.0),
        Point2::new(8.0, 0.0),
        Point2::new(0.0, 8.0),
    ];
    for k in 1..8 {
        pts.push(Point2::new(f64::from(k), 0.0));
        pts.push(Point2::new(0.0, f64::from(k)));
        pts.push(Point2::new(f64::from(8 + k), 0.0));
        pts.push(Point2::new(f64::from(k), f64::from(8 - k)));
    }
    build_and_check(&pts);
}

#[test]
fn non_finite_coordinates_are_errors() {
    let pts = [
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Point2::new(f64::NAN, 1.0),
    ];
    assert!(matches!(
        incremental(&pts),
        Err(Error::NonFinite { index: 2, .. })
    ));
    let pts = [Point2::new(f64::NEG_INFINITY, 0.0)];
    assert!(matches!(
        incremental(&pts),
        Err(Error::NonFinite { index: 0, .. })
    ));
}

#[test]
fn counting_changes_nothing_and_counts_each_kind_of_test() {
    let pts = points(PointKind::UniformSquare, 2000, 4).unwrap();
    let mut counts = Counts::default();
    let counted = incremental_with(&crate::common::set(&pts), &mut counts).unwrap();
    assert_eq!(counted, incremental(&pts).unwrap());
    // Each of the n - 3 insertions tests at least the three edges of its new triangles.
    assert!(counts.incircle_tests >= 3 * (2000 - 3));
    assert!(counts.orientation_tests >= 2000);
    assert_eq!(counts.comparisons + counts.distance_evaluations, 0);
}

#[test]
fn parabola_in_x_order_stays_near_linear_in_flips() {
    // Points on a parabola in x order make naive incremental insertion quadratic; the
    // randomized order keeps the in-circle tests per point bounded by a small constant.
    let per_point = |n: usize| {
        let pts = points(PointKind::Parabola, n, 0).unwrap();
        let mut counts = Counts::default();
        incremental_with(&crate::common::set(&pts), &mut counts).unwrap();
        counts.incircle_tests as f64 / n as f64
    };
    let (small, large) = (per_point(2000), per_point(32_000));
    assert!(
        large < 3.0 * small,
        "{small} -> {large} in-circle tests per point"
    );
}

#[cfg(feature = "cli")]
#[test]
fn cli_prints_the_triangulation_and_rejects_bad_input() {
    use crate::common::{assert_rejected, run_json};
    use compgeo::delaunay::Algorithm;
    let pts = points(PointKind::Grid, 30, 3).unwrap();
    let mut with_copy = pts.clone();
    with_copy.push(pts[4]);
    let input =
        serde_json::to_string(&with_copy.iter().map(|p| [p.x, p.y]).collect::<Vec<_>>()).unwrap();
    for algorithm in Algorithm::ALL {
        let v = run_json(
            &["delaunay", "--algorithm", algorithm.name(), "-"],
            Some(&input),
        );
        let tris: Vec<[usize; 3]> = serde_json::from_value(v["triangles"].clone()).unwrap();
        let hull: Vec<usize> = serde_json::from_value(v["hull"].clone()).unwrap();
        let duplicates: Vec<[usize; 2]> = serde_json::from_value(v["duplicates"].clone()).unwrap();
        // The printed triangles, relinked, pass the exact checker on the printed input.
        let t = Triangulation::from_triangles(&crate::common::set(&with_copy), &tris, duplicates)
            .unwrap();
        assert_eq!(t.hull, hull);
        assert_eq!(check_delaunay(&with_copy, &t), Ok(()));
        assert_eq!(t.duplicates, [[30, 4]]);
        // Fortune's sweep decides by breakpoint and event comparisons, not in-circle tests.
        let counted = if algorithm == Algorithm::Fortune {
            "comparisons"
        } else {
            "incircle_tests"
        };
        assert!(
            v["counts"][counted].as_u64().unwrap() > 0,
            "{algorithm}: {counted}"
        );
    }
    // Collinear input: no triangles, the hull along the line.
    let v = run_json(&["delaunay", "-"], Some("[[2, 2], [0, 0], [1, 1]]"));
    assert_eq!(v["triangles"], serde_json::json!([]));
    assert_eq!(v["hull"], serde_json::json!([1, 2, 0]));
    let err = assert_rejected(&["delaunay", "--algorithm", "sweep", "-"], Some(&input));
    assert!(err.contains("incremental"), "{err}");
    let err = assert_rejected(&["delaunay", "-"], Some("[[0, 0], [1, 1], [1e999, 1]]"));
    assert!(err.contains("2"), "{err}");
    assert_rejected(&["delaunay", "-"], Some("[[0, 0], [1, "));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn integer_grids_with_many_cocircular_quadruples(pts in crate::strategies::lattice(-6..=6, 0..60)) {
        let t = incremental(&pts).unwrap();
        prop_assert_eq!(check_delaunay(&pts, &t), Ok(()));
    }

    #[test]
    fn random_points_and_their_copies(pts in crate::strategies::uniform(1e3, 0..80), copies in 0usize..4) {
        let mut all = pts.clone();
        for c in 0..copies {
            all.extend(pts.iter().step_by(c + 1).copied());
        }
        let t = incremental(&all).unwrap();
        prop_assert_eq!(check_delaunay(&all, &t), Ok(()));
    }

    #[test]
    fn random_points_agree_with_spade(pts in prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 3..80)) {
        let pts: Vec<Point2> = pts.into_iter().map(Point2::from).collect();
        let t = incremental(&pts).unwrap();
        prop_assert_eq!(check_delaunay(&pts, &t), Ok(()));
        // Random doubles are in general position with overwhelming probability; skip the
        // rare draw with duplicates.
        if t.duplicates.is_empty() {
            prop_assert_eq!(triangle_set(&t), spade_triangle_set(&pts));
        }
    }
}

#[test]
fn far_points_do_not_lengthen_the_walks() {
    // The insertion order follows a Hilbert curve over the box of most points: a far point
    // stretching the bounding box used to put every other point in one cell of the curve's
    // grid, so each walk crossed O(√n) triangles (150 orientation tests per point at
    // 20000 points, against 7 now). The walks are counted in orientation tests.
    let n = 20_000;
    let mut s = 0x9E37_79B9_7F4A_7C15u64;
    let mut r = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let cluster: Vec<Point2> = std::iter::once(Point2::new(1e8, 1e8))
        .chain((0..n).map(|_| Point2::new(r() * 1e-6, r() * 1e-6)))
        .collect();
    let mut far: Vec<Point2> = vec![
        Point2::new(0.0, 1e9),
        Point2::new(0.0, -1e9),
        Point2::new(1e9, 0.0),
    ];
    far.extend((0..n).map(|_| Point2::new(r(), r())));
    let tall: Vec<Point2> = (0..n).map(|_| Point2::new(r() * 1e-3, r())).collect();
    for (what, pts) in [("cluster", cluster), ("far", far), ("tall band", tall)] {
        let t = build_and_check(&pts);
        let mut c = Counts::default();
        let counted = incremental_with(&crate::common::set(&pts), &mut c).unwrap();
        assert_eq!(counted, t, "{what}");
        assert!(
            c.orientation_tests < 15 * pts.len() as u64,
            "{what}: {} orientation tests",
            c.orientation_tests
        );
    }
}
