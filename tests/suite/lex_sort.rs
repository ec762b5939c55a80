//! The lexicographic sorts of the hull and Delaunay code (`src/geometry/lex_sort.rs`): the
//! radix sort that runs with `NoCount` gives the order of the comparison sort that counted
//! runs use, on any finite bit patterns; every algorithm that sorts gives the same result on
//! either path; and the counted path still counts the comparisons of sorting by `cmp_lex`.

use crate::strategies::extreme_coordinate;
use compgeo::count::{Counts, NoCount};
use compgeo::delaunay::{find_duplicates, triangulate_with, Algorithm as Builder};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_lex, comparison_sorted_lex, radix_sorted_lex, Point2};
use compgeo::hull::{convex_hull_with, monotone_chain_with, Algorithm, HullOptions};
use proptest::prelude::*;
use std::collections::HashMap;

/// The oracle: `(point, index)` items sorted by `cmp_lex`, then index, with the comparator
/// calls counted.
fn by_cmp_lex(pts: &[Point2]) -> (Vec<(Point2, usize)>, u64) {
    let mut items: Vec<(Point2, usize)> = pts.iter().copied().zip(0..).collect();
    let mut calls = 0;
    items.sort_unstable_by(|a, b| {
        calls += 1;
        cmp_lex(a.0, b.0).then(a.1.cmp(&b.1))
    });
    (items, calls)
}

/// Bit patterns, so that -0.0 and 0.0 count as different.
fn bits(items: &[(Point2, usize)]) -> Vec<(u64, u64, usize)> {
    items
        .iter()
        .map(|(p, i)| (p.x.to_bits(), p.y.to_bits(), *i))
        .collect()
}

/// Points drawn from a small pool of extreme coordinates (so repeats, equal x with different
/// y, and -0.0 next to 0.0 are common), then a few fresh ones.
fn pooled_points() -> impl Strategy<Value = Vec<Point2>> {
    (
        prop::collection::vec(extreme_coordinate(), 1..12),
        prop::collection::vec(
            (any::<prop::sample::Index>(), any::<prop::sample::Index>()),
            0..700,
        ),
        prop::collection::vec((extreme_coordinate(), extreme_coordinate()), 0..40),
    )
        .prop_map(|(mut pool, picks, fresh)| {
            pool.extend([0.0, -0.0, f64::MAX, -f64::MAX, 5e-324, -5e-324]);
            let mut pts: Vec<Point2> = picks
                .iter()
                .map(|(a, b)| Point2::new(*a.get(&pool), *b.get(&pool)))
                .collect();
            pts.extend(fresh.into_iter().map(Point2::from));
            pts
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn radix_sort_equals_the_comparison_sort_on_any_finite_bit_patterns(pts in pooled_points()) {
        let (expected, _) = by_cmp_lex(&pts);
        prop_assert_eq!(bits(&radix_sorted_lex(&pts)), bits(&expected));
        prop_assert_eq!(bits(&comparison_sorted_lex(&pts)), bits(&expected));
    }

    #[test]
    fn radix_sort_equals_the_comparison_sort_on_arbitrary_finite_doubles(
        v in prop::collection::vec(
            (any::<f64>().prop_filter("finite", |v| v.is_finite()),
             any::<f64>().prop_filter("finite", |v| v.is_finite())),
            0..600,
        )
    ) {
        let pts: Vec<Point2> = v.into_iter().map(Point2::from).collect();
        let (expected, _) = by_cmp_lex(&pts);
        prop_assert_eq!(bits(&radix_sorted_lex(&pts)), bits(&expected));
    }
}

/// Kinds with repeats, ties in x, integer and extreme coordinates, and general position.
const KINDS: [PointKind; 8] = [
    PointKind::UniformSquare,
    PointKind::Gaussian,
    PointKind::Clustered,
    PointKind::Grid,
    PointKind::NearDuplicates,
    PointKind::Collinear,
    PointKind::Cocircular,
    PointKind::Huge,
];

#[test]
fn hulls_are_the_same_on_the_radix_and_the_comparison_path() {
    // From 256 points up NoCount sorts by radix; Counts always compares.
    for kind in KINDS {
        for n in [300, 3000] {
            let pts = points(kind, n, 21).unwrap();
            let set = crate::common::set(&pts);
            for algorithm in [
                Algorithm::MonotoneChain,
                Algorithm::AklToussaint,
                Algorithm::Chan,
            ] {
                for keep_collinear in [false, true] {
                    let options = HullOptions { keep_collinear };
                    let fast = convex_hull_with(&set, algorithm, options, &mut NoCount);
                    let counted =
                        convex_hull_with(&set, algorithm, options, &mut Counts::default());
                    assert_eq!(fast, counted, "{algorithm} on {n} {kind}, {options:?}");
                }
            }
        }
    }
}

#[test]
fn triangulations_are_the_same_on_the_radix_and_the_comparison_path() {
    for kind in KINDS {
        for n in [300, 2000] {
            let pts = points(kind, n, 22).unwrap();
            let set = crate::common::set(&pts);
            for builder in [Builder::DivideAndConquer, Builder::Lawson, Builder::Fortune] {
                let fast = triangulate_with(&set, builder, &mut NoCount).unwrap();
                let counted = triangulate_with(&set, builder, &mut Counts::default()).unwrap();
                assert_eq!(fast, counted, "{builder} on {n} {kind}");
            }
        }
    }
}

#[test]
fn duplicates_found_by_the_radix_path_match_a_hash_map() {
    for kind in [
        PointKind::NearDuplicates,
        PointKind::Grid,
        PointKind::UniformDisk,
    ] {
        let mut pts = points(kind, 3000, 23).unwrap();
        // Copies of earlier points, and the origin with both signs of zero.
        for k in 0..500 {
            pts.push(pts[(k * 7919) % pts.len()]);
        }
        pts.push(Point2::new(-0.0, 0.0));
        pts.push(Point2::new(0.0, -0.0));
        let mut first: HashMap<(u64, u64), usize> = HashMap::new();
        let mut expected = Vec::new();
        for (i, p) in pts.iter().enumerate() {
            let at = (p.x + 0.0, p.y + 0.0);
            match first.get(&(at.0.to_bits(), at.1.to_bits())) {
                Some(&kept) => expected.push([i, kept]),
                None => {
                    first.insert((at.0.to_bits(), at.1.to_bits()), i);
                }
            }
        }
        assert_eq!(find_duplicates(&pts), expected, "{kind}");
    }
}

#[test]
fn counted_sorts_still_count_the_comparisons_of_sorting_by_cmp_lex() {
    // Monotone chain and divide and conquer count one comparison per comparison of the sort
    // plus one per point after the first to merge duplicates; the sort's are those of
    // sorting (point, index) items by cmp_lex and index, as before the radix path existed.
    for kind in [
        PointKind::UniformDisk,
        PointKind::Grid,
        PointKind::NearDuplicates,
    ] {
        for n in [100, 1000, 5000] {
            let pts = points(kind, n, 24).unwrap();
            let (_, calls) = by_cmp_lex(&pts);
            let set = crate::common::set(&pts);
            let mut counts = Counts::default();
            monotone_chain_with(&set, HullOptions::default(), &mut counts);
            assert_eq!(
                counts.comparisons,
                calls + n as u64 - 1,
                "monotone chain, {n} {kind}"
            );
            let mut counts = Counts::default();
            triangulate_with(&set, Builder::DivideAndConquer, &mut counts).unwrap();
            assert_eq!(
                counts.comparisons,
                calls + n as u64 - 1,
                "divide and conquer, {n} {kind}"
            );
        }
    }
}
