//! Diameter and antipodal pairs: rotating calipers against the brute-force diameter, exact
//! comparisons of squared distances, the 3n/2 bound, polygons with parallel edges.

use compgeo::calipers::{
    antipodal_pairs, antipodal_pairs_with, diameter, diameter_brute_force, diameter_with,
};
use compgeo::count::Counts;
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_dist, Point2};
use compgeo::hull::{monotone_chain, HullOptions};
use compgeo::Error;
use proptest::prelude::*;
use std::cmp::Ordering;

#[cfg(feature = "cli")]
mod common;

fn small_points() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-6i32..=6, -6i32..=6), 0..30).prop_map(|v| {
        v.into_iter()
            .map(|(x, y)| Point2::new(f64::from(x), f64::from(y)))
            .collect()
    })
}

/// Points and their reflections through the origin: a centrally symmetric hull, whose
/// edges come in parallel pairs.
fn symmetric_points() -> impl Strategy<Value = Vec<Point2>> {
    small_points().prop_map(|v| {
        v.iter()
            .flat_map(|p| [*p, Point2::new(-p.x, -p.y)])
            .collect()
    })
}

/// Calipers and brute force give the same distance, exactly; the calipers' pairs are
/// distinct, at most 3h/2, and include every farthest pair.
fn check(pts: &[Point2]) -> Result<(), TestCaseError> {
    let fast = diameter(pts).unwrap();
    let slow = diameter_brute_force(pts).unwrap();
    match (fast, slow) {
        (None, None) => prop_assert!(pts.is_empty()),
        (Some(f), Some(s)) => {
            prop_assert_eq!(
                cmp_dist(pts[f.a], pts[f.b], pts[s.a], pts[s.b]),
                Ordering::Equal
            );
            // Equal exact distances; the lengths are rounded from different pairs.
            prop_assert!((f.length - s.length).abs() <= 4.0 * f64::EPSILON * f.length);
        }
        other => prop_assert!(false, "{:?}", other),
    }
    let hull = monotone_chain(pts, HullOptions::default()).unwrap();
    let pairs = antipodal_pairs(pts, &hull).unwrap();
    prop_assert!(
        2 * pairs.len() <= 3 * hull.len(),
        "{} pairs for h = {}",
        pairs.len(),
        hull.len()
    );
    let mut sorted: Vec<_> = pairs.iter().map(|&(a, b)| (a.min(b), a.max(b))).collect();
    sorted.sort_unstable();
    sorted.dedup();
    prop_assert_eq!(sorted.len(), pairs.len(), "pairs are distinct");
    if let Some(s) = slow.filter(|_| hull.len() >= 2) {
        for (i, &a) in hull.iter().enumerate() {
            for &b in &hull[i + 1..] {
                if cmp_dist(pts[a], pts[b], pts[s.a], pts[s.b]) == Ordering::Equal {
                    prop_assert!(sorted.contains(&(a.min(b), a.max(b))), "({a}, {b}) missing");
                }
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn calipers_equal_brute_force(pts in small_points()) {
        check(&pts)?;
    }

    #[test]
    fn calipers_equal_brute_force_with_parallel_edges(pts in symmetric_points()) {
        check(&pts)?;
    }

    #[test]
    fn calipers_equal_brute_force_at_any_magnitude(
        pts in small_points(),
        scale in prop::sample::select(vec![5e-324, 1e-200, 1e15, 1e300]),
    ) {
        let pts: Vec<Point2> = pts.iter().map(|p| Point2::new(p.x * scale, p.y * scale)).collect();
        check(&pts)?;
    }
}

#[test]
fn regular_polygons_with_parallel_edges_reach_3n_over_2() {
    // An octagon with integer vertices, symmetric under x <-> y and reflections: four pairs
    // of parallel sides.
    let octagon = [
        (1, -3),
        (3, -1),
        (3, 1),
        (1, 3),
        (-1, 3),
        (-3, 1),
        (-3, -1),
        (-1, -3),
    ]
    .map(|(x, y)| Point2::new(f64::from(x), f64::from(y)));
    let hull = monotone_chain(&octagon, HullOptions::default()).unwrap();
    assert_eq!(hull.len(), 8);
    let pairs = antipodal_pairs(&octagon, &hull).unwrap();
    assert_eq!(pairs.len(), 12);
    let d = diameter(&octagon).unwrap().unwrap();
    let b = diameter_brute_force(&octagon).unwrap().unwrap();
    assert_eq!(
        cmp_dist(octagon[d.a], octagon[d.b], octagon[b.a], octagon[b.b]),
        Ordering::Equal
    );
}

#[test]
fn the_calipers_make_at_most_h_direction_tests() {
    for kind in [
        PointKind::UniformDisk,
        PointKind::Cocircular,
        PointKind::RotatedGrid,
    ] {
        let pts = points(kind, 2000, 4).unwrap();
        let hull = monotone_chain(&pts, HullOptions::default()).unwrap();
        let mut counts = Counts::default();
        let pairs = antipodal_pairs_with(&pts, &hull, &mut counts).unwrap();
        assert!(counts.orientation_tests <= hull.len() as u64, "{kind}");
        assert!(2 * pairs.len() <= 3 * hull.len(), "{kind}");
        let mut all = Counts::default();
        let d = diameter_with(&pts, &mut all).unwrap().unwrap();
        let b = diameter_brute_force(&pts).unwrap().unwrap();
        assert_eq!(
            cmp_dist(pts[d.a], pts[d.b], pts[b.a], pts[b.b]),
            Ordering::Equal,
            "{kind}"
        );
    }
}

#[test]
fn degenerate_and_bad_input() {
    let p = |x: f64, y: f64| Point2::new(x, y);
    assert!(diameter(&[]).unwrap().is_none());
    let line = [p(1.0, 1.0), p(0.0, 0.0), p(3.0, 3.0), p(2.0, 2.0)];
    let d = diameter(&line).unwrap().unwrap();
    assert_eq!((d.a.min(d.b), d.a.max(d.b)), (1, 2));
    let same = [p(2.0, 2.0); 3];
    let d = diameter(&same).unwrap().unwrap();
    assert_eq!(d.length, 0.0);

    let bad = [p(0.0, 0.0), p(f64::NAN, 1.0)];
    assert!(matches!(
        diameter(&bad),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        diameter_brute_force(&bad),
        Err(Error::NonFinite { index: 1, .. })
    ));

    let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
    let clockwise = antipodal_pairs(&square, &[0, 3, 2, 1]).unwrap_err();
    assert!(matches!(
        clockwise,
        Error::InvalidParameter {
            name: "polygon",
            ..
        }
    ));
    let out_of_range = antipodal_pairs(&square, &[0, 1, 7]).unwrap_err();
    assert!(out_of_range.to_string().contains('7'), "{out_of_range}");
}

#[test]
fn the_length_does_not_overflow() {
    let pts = [Point2::new(-1.5e308, 0.0), Point2::new(1.5e308, 0.0)];
    let d = diameter(&pts).unwrap().unwrap();
    assert!(d.length.is_infinite(), "3e308 is beyond f64::MAX");
    let pts = [Point2::new(-8e307, 0.0), Point2::new(8e307, 0.0)];
    assert_eq!(diameter(&pts).unwrap().unwrap().length, 1.6e308);
}

#[cfg(feature = "cli")]
#[test]
fn cli_diameter_by_calipers_and_by_brute_force() {
    use common::run_json;
    let input = "[[1,1],[0,0],[4,0],[4,3],[2,1]]";
    for flag in [None, Some("--brute-force")] {
        let mut args = vec!["diameter", "-"];
        args.extend(flag);
        let v = run_json(&args, Some(input));
        assert_eq!(v["pair"], serde_json::json!([1, 3]), "{flag:?}");
        assert_eq!(v["distance"], serde_json::json!(5.0));
        // The library's antipodal pairs of the hull.
        let pts: Vec<Point2> = [[1.0, 1.0], [0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [2.0, 1.0]]
            .map(Point2::from)
            .to_vec();
        let hull = compgeo::hull::akl_toussaint(&pts, Default::default()).unwrap();
        let expected: Vec<[usize; 2]> = antipodal_pairs(&pts, &hull)
            .unwrap()
            .into_iter()
            .map(|(i, j)| [i, j])
            .collect();
        assert_eq!(v["antipodal_pairs"], serde_json::json!(expected));
        assert_eq!(expected.len(), 4, "the hull 1, 2, 3, 0 is a quadrilateral");
        assert_eq!(v["points"], serde_json::json!([[0.0, 0.0], [4.0, 3.0]]));
    }
    // A 4 x 3 box and an interior point: width 3 on the bottom edge, rectangle the box.
    let v = run_json(&["diameter", "-"], Some("[[0,0],[4,0],[4,3],[0,3],[1,1]]"));
    assert_eq!(v["width"]["edge"], serde_json::json!([0, 1]));
    assert_eq!(v["width"]["width"], serde_json::json!(3.0));
    assert_eq!(v["rectangle"]["edge"], serde_json::json!([0, 1]));
    assert_eq!(v["rectangle"]["area"], serde_json::json!(12.0));
    assert_eq!(
        v["rectangle"]["corners"][2],
        serde_json::json!({"x": 4.0, "y": 3.0})
    );
    let v = run_json(&["diameter", "-"], Some("[]"));
    assert!(v["pair"].is_null() && v["distance"].is_null());
    assert_eq!(v["antipodal_pairs"], serde_json::json!([]));
    assert!(v["width"].is_null() && v["rectangle"].is_null());
}
