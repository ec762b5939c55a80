//! Diameter and antipodal pairs: rotating calipers against the brute-force diameter, exact
//! comparisons of squared distances, the 3n/2 bound, polygons with parallel edges.

use compgeo::calipers::{diameter, diameter_brute_force, ConvexPolygon, DiameterAlgorithm};
use compgeo::count::Counts;
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_dist, Point2, PointPair, PointSet, WideFloat};
use compgeo::hull::{monotone_chain, HullOptions};
use compgeo::Error;
use proptest::prelude::*;
use std::cmp::Ordering;

/// Points and their reflections through the origin: a centrally symmetric hull, whose
/// edges come in parallel pairs.
fn symmetric_points() -> impl Strategy<Value = Vec<Point2>> {
    crate::strategies::lattice(-6..=6, 0..30).prop_map(|v| {
        v.iter()
            .flat_map(|p| [*p, Point2::new(-p.x, -p.y)])
            .collect()
    })
}

/// Whether two pairs of `pts` are exactly as far apart.
fn same_distance(pts: &[Point2], a: PointPair, b: PointPair) -> bool {
    let ([i, j], [k, l]) = (a.pair, b.pair);
    cmp_dist(pts[i], pts[j], pts[k], pts[l]) == Ordering::Equal
}

/// Calipers and brute force give the same distance, exactly; the calipers' pairs are
/// distinct, at most 3h/2, and include every farthest pair.
fn check(pts: &[Point2]) -> Result<(), TestCaseError> {
    let fast = diameter(pts, DiameterAlgorithm::Calipers);
    let slow = diameter_brute_force(pts);
    match (&fast, &slow) {
        (Err(Error::TooFew { .. }), Err(Error::TooFew { .. })) => prop_assert!(pts.is_empty()),
        (Ok(f), Ok(s)) => {
            let (f, s) = (*f, *s);
            prop_assert!(same_distance(pts, f, s));
            // Equal exact distances; the lengths are rounded from different pairs.
            let (fd, sd) = (
                f.distance.to_f64_saturating(),
                s.distance.to_f64_saturating(),
            );
            prop_assert!((fd - sd).abs() <= 4.0 * f64::EPSILON * fd);
        }
        other => prop_assert!(false, "{:?}", other),
    }
    let set = PointSet::new(pts).unwrap();
    let hull = ConvexPolygon::hull(&set);
    prop_assert_eq!(
        hull.vertices(),
        monotone_chain(pts, HullOptions::default()).unwrap()
    );
    let pairs = hull.antipodal_pairs();
    let hull = hull.vertices();
    prop_assert!(
        2 * pairs.len() <= 3 * hull.len(),
        "{} pairs for h = {}",
        pairs.len(),
        hull.len()
    );
    let mut sorted: Vec<_> = pairs.iter().map(|&[a, b]| (a.min(b), a.max(b))).collect();
    sorted.sort_unstable();
    sorted.dedup();
    prop_assert_eq!(sorted.len(), pairs.len(), "pairs are distinct");
    if let Some(s) = slow.ok().filter(|_| hull.len() >= 2) {
        for (i, &a) in hull.iter().enumerate() {
            for &b in &hull[i + 1..] {
                if cmp_dist(pts[a], pts[b], pts[s.pair[0]], pts[s.pair[1]]) == Ordering::Equal {
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
    fn calipers_equal_brute_force(pts in crate::strategies::lattice(-6..=6, 0..30)) {
        check(&pts)?;
    }

    #[test]
    fn calipers_equal_brute_force_with_parallel_edges(pts in symmetric_points()) {
        check(&pts)?;
    }

    #[test]
    fn calipers_equal_brute_force_at_any_magnitude(
        pts in crate::strategies::lattice(-6..=6, 0..30),
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
    let hull = ConvexPolygon::hull(&PointSet::new(&octagon).unwrap());
    assert_eq!(hull.vertices().len(), 8);
    assert_eq!(hull.antipodal_pairs().len(), 12);
    let d = hull.diameter().unwrap();
    let b = diameter_brute_force(&octagon).unwrap();
    assert!(same_distance(&octagon, d, b));
}

#[test]
fn the_calipers_make_at_most_h_direction_tests() {
    for kind in [
        PointKind::UniformDisk,
        PointKind::Cocircular,
        PointKind::RotatedGrid,
    ] {
        let pts = points(kind, 2000, 4).unwrap();
        let set = PointSet::new(&pts).unwrap();
        let hull = ConvexPolygon::hull(&set);
        let h = hull.vertices().len();
        let mut counts = Counts::default();
        let pairs = hull.antipodal_pairs_with(&mut counts);
        assert!(counts.orientation_tests <= h as u64, "{kind}");
        assert!(2 * pairs.len() <= 3 * h, "{kind}");
        let mut counts = Counts::default();
        let d = hull.diameter_with(&mut counts).unwrap();
        assert!(counts.distance_evaluations <= (3 * h / 2) as u64, "{kind}");
        let b = diameter_brute_force(&pts).unwrap();
        assert!(same_distance(&pts, d, b), "{kind}");
    }
}

#[test]
fn degenerate_and_bad_input() {
    let p = |x: f64, y: f64| Point2::new(x, y);
    for algorithm in DiameterAlgorithm::ALL {
        assert!(matches!(
            diameter(&[], algorithm),
            Err(Error::TooFew {
                needed: 1,
                got: 0,
                ..
            })
        ));
        let line = [p(1.0, 1.0), p(0.0, 0.0), p(3.0, 3.0), p(2.0, 2.0)];
        assert_eq!(diameter(&line, algorithm).unwrap().pair, [1, 2]);
        let same = [p(2.0, 2.0); 3];
        let d = diameter(&same, algorithm).unwrap();
        assert_eq!(
            (d.pair, d.distance),
            ([0, 1], WideFloat::ZERO),
            "{algorithm}"
        );
        let one = [p(2.0, 2.0)];
        assert_eq!(
            diameter(&one, algorithm).unwrap().pair,
            [0, 0],
            "{algorithm}"
        );
        let bad = [p(0.0, 0.0), p(f64::NAN, 1.0)];
        assert!(matches!(
            diameter(&bad, algorithm),
            Err(Error::NonFinite { index: 1, .. })
        ));
    }

    let square = [p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
    let set = PointSet::new(&square).unwrap();
    let clockwise = ConvexPolygon::new(&set, vec![0, 3, 2, 1]).unwrap_err();
    assert!(matches!(
        clockwise,
        Error::InvalidParameter {
            name: "polygon",
            ..
        }
    ));
    let out_of_range = ConvexPolygon::new(&set, vec![0, 1, 7]).unwrap_err();
    assert!(out_of_range.to_string().contains('7'), "{out_of_range}");
    let empty = ConvexPolygon::new(&set, Vec::new()).unwrap();
    assert!(empty.antipodal_pairs().is_empty());
    assert!(matches!(empty.diameter(), Err(Error::TooFew { .. })));
    assert!(matches!(empty.width(), Err(Error::TooFew { .. })));
    assert!(matches!(
        empty.min_area_rectangle(),
        Err(Error::TooFew { .. })
    ));
}

#[test]
fn the_length_does_not_overflow() {
    for algorithm in DiameterAlgorithm::ALL {
        let pts = [Point2::new(-1.5e308, 0.0), Point2::new(1.5e308, 0.0)];
        let d = diameter(&pts, algorithm).unwrap();
        assert_eq!(d.distance.to_f64(), None, "3e308 is beyond f64::MAX");
        assert_eq!(d.distance.to_string(), "3.0000000000000000e308");
        let pts = [Point2::new(-8e307, 0.0), Point2::new(8e307, 0.0)];
        assert_eq!(diameter(&pts, algorithm).unwrap().distance, 1.6e308);
    }
}

#[cfg(feature = "cli")]
#[test]
fn cli_diameter_by_calipers_and_by_brute_force() {
    use crate::common::run_json;
    let input = "[[1,1],[0,0],[4,0],[4,3],[2,1]]";
    for algorithm in [None, Some("calipers"), Some("brute-force")] {
        let mut args = vec!["diameter", "-"];
        args.extend(algorithm.map(|a| ["--algorithm", a]).into_iter().flatten());
        let v = run_json(&args, Some(input));
        assert_eq!(v["pair"], serde_json::json!([1, 3]), "{algorithm:?}");
        assert_eq!(v["algorithm"], algorithm.unwrap_or("calipers"));
        assert_eq!(v["distance"], serde_json::json!(5.0));
        // The library's antipodal pairs of the hull.
        let pts: Vec<Point2> = [[1.0, 1.0], [0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [2.0, 1.0]]
            .map(Point2::from)
            .to_vec();
        let expected = ConvexPolygon::hull(&PointSet::new(&pts).unwrap()).antipodal_pairs();
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
    assert_eq!(v["rectangle"]["perimeter"], serde_json::json!(14.0));
    // The two criteria differ on this quadrilateral (see `min_perimeter_rectangle`).
    let v = run_json(&["diameter", "-"], Some("[[-3,0],[-2,-3],[0,0],[1,3]]"));
    assert_eq!(v["perimeter_rectangle"]["edge"], serde_json::json!([3, 0]));
    assert_eq!(
        v["perimeter_rectangle"]["perimeter"],
        serde_json::json!(18.0)
    );
    assert_eq!(v["rectangle"]["edge"], serde_json::json!([1, 2]));
    let v = run_json(&["diameter", "-"], Some("[[0,0],[4,0],[4,3],[0,3],[1,1]]"));
    assert_eq!(
        v["rectangle"]["corners"][2],
        serde_json::json!({"x": 4.0, "y": 3.0})
    );
    let err = crate::common::assert_rejected(&["diameter", "-"], Some("[]"));
    assert!(err.contains("at least 1"), "{err}");
    let v = run_json(&["diameter", "-"], Some("[[2,5]]"));
    assert_eq!(v["pair"], serde_json::json!([0, 0]));
    assert_eq!(v["antipodal_pairs"], serde_json::json!([]));
    assert_eq!(v["width"]["width"], serde_json::json!(0.0));
}
