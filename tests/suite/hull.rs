//! Convex hulls: every algorithm against the brute-force oracle on small inputs, all
//! algorithms against each other on larger ones, exact invariants, degenerate and bad input.

use compgeo::count::Counts;
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_lex, orient2d, Orientation, Point2, PointSet};
use compgeo::hull::{
    brute_force_hull, check_encloses, check_strictly_convex_ccw, convex_hull, convex_hull_with,
    Algorithm, HullOptions,
};
use compgeo::Error;
use proptest::prelude::*;
use std::cmp::Ordering;

const STRICT: HullOptions = HullOptions {
    keep_collinear: false,
};
const KEEP: HullOptions = HullOptions {
    keep_collinear: true,
};

/// Checks everything the output convention promises, exactly.
fn check_hull(pts: &[Point2], hull: &[usize], options: HullOptions) {
    if pts.is_empty() {
        assert!(hull.is_empty());
        return;
    }
    let first = (0..pts.len())
        .min_by(|&a, &b| cmp_lex(pts[a], pts[b]).then(a.cmp(&b)))
        .unwrap();
    assert_eq!(
        hull[0], first,
        "starts at the first lexicographically smallest point"
    );
    assert_eq!(
        check_encloses(pts, hull),
        Ok(()),
        "every point on or left of every edge"
    );
    for &i in hull {
        let first_copy = pts
            .iter()
            .position(|&p| cmp_lex(p, pts[i]) == Ordering::Equal)
            .unwrap();
        assert_eq!(
            i, first_copy,
            "duplicates are reported by their first index"
        );
    }
    if !options.keep_collinear {
        assert_eq!(check_strictly_convex_ccw(pts, hull), Ok(()), "{hull:?}");
    } else if hull.len() >= 3 {
        // Boundary order: the points on or left of every edge, turning left or going
        // straight, and the strict vertices among them form a strictly convex polygon.
        let h = hull.len();
        let corners: Vec<usize> = (0..h)
            .filter(|&k| {
                orient2d(
                    pts[hull[(k + h - 1) % h]],
                    pts[hull[k]],
                    pts[hull[(k + 1) % h]],
                ) != Orientation::Collinear
            })
            .map(|k| hull[k])
            .collect();
        assert_eq!(check_strictly_convex_ccw(pts, &corners), Ok(()));
        assert!(
            corners.len() <= 2
                || (0..h).all(|k| orient2d(
                    pts[hull[k]],
                    pts[hull[(k + 1) % h]],
                    pts[hull[(k + 2) % h]]
                ) != Orientation::Clockwise)
        );
    }
}

fn all_algorithms(pts: &[Point2], options: HullOptions) -> Vec<(Algorithm, Vec<usize>)> {
    Algorithm::ALL
        .into_iter()
        .map(|a| (a, convex_hull(pts, a, options).unwrap()))
        .collect()
}

/// A small integer set scaled and shifted, to reach huge, tiny and mixed magnitudes; a shift
/// of 3e16 (where doubles are 4 apart) rounds neighbouring points together or apart.
fn scaled_points() -> impl Strategy<Value = Vec<Point2>> {
    (
        crate::strategies::lattice(-4..=4, 0..24),
        prop::sample::select(vec![1e-300, 1e-160, 5e-324, 1.0, 1e15, 1e200, 1e300]),
        prop::sample::select(vec![0.0, 1.0, 1e15, 3e16, -1e200]),
    )
        .prop_map(|(pts, scale, shift)| {
            pts.into_iter()
                .map(|p| Point2::new(p.x * scale + shift, p.y * scale))
                .collect()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(160))]

    #[test]
    fn every_algorithm_equals_brute_force(pts in crate::strategies::lattice(-4..=4, 0..24)) {
        for options in [STRICT, KEEP] {
            let oracle = brute_force_hull(&pts, options).unwrap();
            check_hull(&pts, &oracle, options);
            for (algorithm, hull) in all_algorithms(&pts, options) {
                prop_assert_eq!(&hull, &oracle, "{} {:?}", algorithm, options);
            }
        }
    }

    #[test]
    fn every_algorithm_equals_brute_force_at_any_magnitude(pts in scaled_points()) {
        for options in [STRICT, KEEP] {
            let oracle = brute_force_hull(&pts, options).unwrap();
            check_hull(&pts, &oracle, options);
            for (algorithm, hull) in all_algorithms(&pts, options) {
                prop_assert_eq!(&hull, &oracle, "{} {:?}", algorithm, options);
            }
        }
    }

    #[test]
    fn one_ulp_perturbations_give_the_exact_hull(pts in crate::strategies::lattice(-4..=4, 0..24), bumps in prop::collection::vec(0u8..4, 24)) {
        let pts: Vec<Point2> = pts.iter().zip(&bumps).map(|(p, &b)| {
            let x = if b & 1 == 1 { p.x.next_up() } else { p.x };
            let y = if b & 2 == 2 { p.y.next_down() } else { p.y };
            Point2::new(x, y)
        }).collect();
        let oracle = brute_force_hull(&pts, STRICT).unwrap();
        check_hull(&pts, &oracle, STRICT);
        for (algorithm, hull) in all_algorithms(&pts, STRICT) {
            prop_assert_eq!(&hull, &oracle, "{}", algorithm);
        }
    }
}

#[test]
fn all_algorithms_agree_on_every_generator() {
    for kind in PointKind::ALL {
        for (n, seed) in [(60, 1), (1500, 2)] {
            let pts = points(kind, n, seed).unwrap();
            for options in [STRICT, KEEP] {
                let fast: Vec<_> = Algorithm::ALL
                    .into_iter()
                    .filter(|&a| a != Algorithm::BruteForce || n <= 60)
                    .map(|a| (a, convex_hull(&pts, a, options).unwrap()))
                    .collect();
                let (_, reference) = &fast[fast.len() - 1];
                check_hull(&pts, reference, options);
                for (algorithm, hull) in &fast {
                    assert_eq!(hull, reference, "{kind} n={n} {algorithm} {options:?}");
                }
            }
        }
    }
}

#[test]
fn degenerate_inputs() {
    let p = |x: f64, y: f64| Point2::new(x, y);
    for algorithm in Algorithm::ALL {
        let run = |pts: &[Point2], o| convex_hull(pts, algorithm, o).unwrap();
        assert_eq!(run(&[], STRICT), Vec::<usize>::new());
        assert_eq!(run(&[p(3.0, 4.0)], STRICT), [0]);
        let same = [p(1.0, 1.0); 5];
        assert_eq!(run(&same, STRICT), [0], "{algorithm}");
        assert_eq!(run(&same, KEEP), [0], "{algorithm}");
        let two = [p(1.0, 1.0), p(0.0, 0.0), p(1.0, 1.0)];
        assert_eq!(run(&two, STRICT), [1, 0], "{algorithm}");
        let line = [
            p(2.0, 2.0),
            p(0.0, 0.0),
            p(3.0, 3.0),
            p(1.0, 1.0),
            p(2.0, 2.0),
        ];
        assert_eq!(run(&line, STRICT), [1, 2], "{algorithm}");
        assert_eq!(run(&line, KEEP), [1, 3, 0, 2], "{algorithm}");
        let vertical = [p(0.0, 5.0), p(0.0, -1.0), p(0.0, 2.0)];
        assert_eq!(run(&vertical, STRICT), [1, 0], "{algorithm}");
        // A square with points on every side, duplicated corners and an interior point.
        let square = [
            p(0.0, 0.0),
            p(2.0, 0.0),
            p(2.0, 2.0),
            p(0.0, 2.0),
            p(1.0, 0.0),
            p(2.0, 1.0),
            p(1.0, 2.0),
            p(0.0, 1.0),
            p(1.0, 1.0),
            p(2.0, 2.0),
            p(1.0, 0.0),
        ];
        assert_eq!(run(&square, STRICT), [0, 1, 2, 3], "{algorithm}");
        assert_eq!(run(&square, KEEP), [0, 4, 1, 5, 2, 6, 3, 7], "{algorithm}");
    }
}

#[test]
fn non_finite_input_is_an_error_naming_the_point() {
    let pts = [
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Point2::new(0.5, f64::INFINITY),
    ];
    for algorithm in Algorithm::ALL {
        match convex_hull(&pts, algorithm, STRICT) {
            Err(Error::NonFinite { index: 2, value }) => assert!(value.is_infinite()),
            other => panic!("{algorithm}: {other:?}"),
        }
    }
}

#[test]
fn huge_and_subnormal_in_one_set() {
    let pts = [
        Point2::new(1e300, 1e300),
        Point2::new(-1e300, 1e300),
        Point2::new(5e-324, -5e-324),
        Point2::new(-5e-324, 5e-324),
        Point2::new(0.0, 0.0),
        Point2::new(1e300, -1e300),
        Point2::new(-1e300, -1e300),
        Point2::new(1e-310, 0.0),
    ];
    let oracle = brute_force_hull(&pts, STRICT).unwrap();
    assert_eq!(oracle, [6, 5, 0, 1]);
    for (algorithm, hull) in all_algorithms(&pts, STRICT) {
        assert_eq!(hull, oracle, "{algorithm}");
    }
}

#[test]
fn jarvis_is_quadratic_on_cocircular_points_and_linear_per_vertex_otherwise() {
    for n in [64, 256] {
        let circle = points(PointKind::Cocircular, n, 5).unwrap();
        let mut counts = Counts::default();
        let set = PointSet::new(&circle).unwrap();
        let hull = convex_hull_with(&set, Algorithm::Jarvis, STRICT, &mut counts);
        assert_eq!(hull.len(), n, "every cocircular point is a vertex");
        assert!(counts.orientation_tests >= (n * (n - 2)) as u64);
        assert!(counts.orientation_tests <= (n * n) as u64);
    }
}

/// Chan's count: per round with group size m, at most 3n tests for the group hulls and
/// m (n/m + 1)(2 log₂ m + 4) for the march; log₂ m doubles from round to round and the last
/// round has m < h², so the sum is below 8 n lg h plus lower-order terms. The test allows
/// 16 n lg h + 16 n.
#[test]
fn chan_makes_o_n_log_h_orientation_tests() {
    for kind in [
        PointKind::UniformSquare,
        PointKind::UniformDisk,
        PointKind::Cocircular,
        PointKind::Grid,
        PointKind::Collinear,
    ] {
        for n in [1000, 8000] {
            let pts = points(kind, n, 3).unwrap();
            let mut counts = Counts::default();
            let set = PointSet::new(&pts).unwrap();
            let hull = convex_hull_with(&set, Algorithm::Chan, STRICT, &mut counts);
            let lg_h = (hull.len().max(2) as f64).log2();
            let bound = 16.0 * n as f64 * lg_h + 16.0 * n as f64;
            assert!(
                (counts.orientation_tests as f64) <= bound,
                "{kind} n={n} h={}: {} tests",
                hull.len(),
                counts.orientation_tests
            );
        }
    }
}

/// Chan's later rounds: 140 000 points on a circle keep every point in the first round's
/// group hulls, so the second round regroups them into three groups of at most 65 536 (the
/// merged runs when counting, the radix sort when not); a circle inside a far triangle closes
/// in the first round's march. Both equal the monotone chain, counted or not.
#[test]
fn chan_rounds_give_the_monotone_chain_hull() {
    let circle = points(PointKind::Cocircular, 140_000, 5).unwrap();
    let mut framed = points(PointKind::Cocircular, 20_000, 6).unwrap();
    let r = framed
        .iter()
        .map(|p| p.x.abs().max(p.y.abs()))
        .fold(0.0, f64::max);
    framed.extend([(-8.0 * r, -8.0 * r), (8.0 * r, -8.0 * r), (0.0, 8.0 * r)].map(Point2::from));
    for pts in [&circle, &framed] {
        let set = PointSet::new(pts).unwrap();
        let reference = convex_hull(pts, Algorithm::MonotoneChain, STRICT).unwrap();
        let mut counts = Counts::default();
        assert_eq!(
            convex_hull_with(&set, Algorithm::Chan, STRICT, &mut counts),
            reference
        );
        assert_eq!(
            convex_hull(pts, Algorithm::Chan, STRICT).unwrap(),
            reference
        );
    }
    // The triangle's march closes after three vertices, long before the rounds end.
    let set = PointSet::new(&framed).unwrap();
    let mut counts = Counts::default();
    let hull = convex_hull_with(&set, Algorithm::Chan, STRICT, &mut counts);
    assert_eq!(hull.len(), 3);
    let mut chain = Counts::default();
    convex_hull_with(&set, Algorithm::MonotoneChain, STRICT, &mut chain);
    assert!(
        counts.comparisons < chain.comparisons,
        "{counts:?} vs {chain:?}"
    );
}

#[test]
fn algorithm_names_round_trip() {
    for a in Algorithm::ALL {
        assert_eq!(a.name().parse::<Algorithm>().unwrap(), a);
        assert_eq!(a.to_string(), a.name());
    }
    let err = "gift".parse::<Algorithm>().unwrap_err().to_string();
    assert!(err.contains("gift") && err.contains("quickhull"), "{err}");
}

#[cfg(feature = "cli")]
#[test]
fn cli_hull_prints_the_hull_of_every_algorithm_and_rejects_bad_input() {
    use crate::common::{assert_rejected, run_json};
    let input = "[[0,0],[2,0],[1,1],[2,2],[0,2],[1,0],[0,0]]";
    for algorithm in Algorithm::ALL {
        for (flag, expected) in [
            (None, vec![0, 1, 3, 4]),
            (Some("--keep-collinear"), vec![0, 5, 1, 3, 4]),
        ] {
            let mut args = vec!["hull", "--algorithm", algorithm.name(), "-"];
            args.extend(flag);
            let v = run_json(&args, Some(input));
            let hull: Vec<usize> = serde_json::from_value(v["hull"].clone()).unwrap();
            assert_eq!(hull, expected, "{algorithm} {flag:?}");
            assert_eq!(
                v["vertices"][1],
                serde_json::json!([if flag.is_some() { 1.0 } else { 2.0 }, 0.0])
            );
            assert!(v["counts"]["orientation_tests"].as_u64().unwrap() > 0);
        }
    }
    let err = assert_rejected(&["hull", "--algorithm", "gift", "-"], Some(input));
    assert!(err.contains("quickhull"), "{err}");
    assert_rejected(&["hull", "-"], Some("[[0, 0], [1e999, 1]]"));
}
