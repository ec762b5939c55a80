//! Nearest-point queries (`NearestSearch`) against a brute-force scan with exact distance
//! comparisons and the documented tie rule (the smallest index among the nearest points):
//! every generator kind, clustered, collinear and duplicated sets, cocircular ties, every
//! magnitude, far queries; the answer does not depend on the start (grid, any vertex, batch);
//! a peer check against kiddo's k-d tree; the counted work per query on uniform points.

use compgeo::count::{Counts, NoCount};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_dist, Point2, PointSet};
use compgeo::proximity::NearestSearch;
use compgeo::Error;
use kiddo::{ImmutableKdTree, SquaredEuclidean};
use proptest::prelude::*;
use std::cmp::Ordering;

/// The smallest index among the points nearest to `q`, by exact comparisons.
fn brute(pts: &[Point2], q: Point2) -> usize {
    let mut best = 0;
    for (i, &p) in pts.iter().enumerate() {
        if cmp_dist(q, p, q, pts[best]) == Ordering::Less {
            best = i;
        }
    }
    best
}

/// Queries near and far from `pts`: the points themselves, mixed coordinates of consecutive
/// points, midpoints (halved first, so nothing overflows), and far-away points.
fn queries_for(pts: &[Point2]) -> Vec<Point2> {
    let mut qs: Vec<Point2> = pts.to_vec();
    qs.extend(pts.windows(2).map(|w| Point2::new(w[0].x, w[1].y)));
    qs.extend(
        pts.windows(2)
            .map(|w| Point2::new(0.5 * w[0].x + 0.5 * w[1].x, 0.5 * w[0].y + 0.5 * w[1].y)),
    );
    qs.extend([
        Point2::new(0.0, 0.0),
        Point2::new(-1e9, 3e9),
        Point2::new(f64::MAX, f64::MAX),
        Point2::new(-f64::MAX, 1.0),
        Point2::new(5e-324, -5e-324),
        Point2::new(1e300, -1e-300),
    ]);
    qs
}

/// Every way of asking gives the brute-force answer: from the grid, counted, from every
/// vertex (for small sets) or a few, and in a batch.
fn check(pts: &[Point2], qs: &[Point2]) {
    let set = PointSet::new(pts).unwrap();
    let search = NearestSearch::new(&set).unwrap();
    let want: Vec<usize> = qs.iter().map(|&q| brute(pts, q)).collect();
    // The vertices: the smallest index of each group of equal points.
    let vertices: Vec<usize> = (0..pts.len())
        .filter(|&i| pts[..i].iter().all(|&p| p != pts[i]))
        .collect();
    let starts: Vec<usize> = if vertices.len() <= 12 {
        vertices.clone()
    } else {
        let step = vertices.len() / 3;
        vertices.iter().copied().step_by(step).collect()
    };
    for (&q, &w) in qs.iter().zip(&want) {
        assert_eq!(search.nearest(q).unwrap(), w, "query {q:?}");
        let mut c = Counts::default();
        assert_eq!(search.nearest_with(q, None, &mut c).unwrap(), w);
        for &s in &starts {
            assert_eq!(
                search.nearest_with(q, Some(s), &mut NoCount).unwrap(),
                w,
                "query {q:?} from {s}"
            );
        }
    }
    assert_eq!(search.nearest_all(qs).unwrap(), want);
    let mut c = Counts::default();
    assert_eq!(search.nearest_all_with(qs, &mut c).unwrap(), want);
}

#[test]
fn every_generator_kind_against_brute_force() {
    for kind in PointKind::ALL {
        // The extreme magnitudes take the exact fallback often, slow in a debug build.
        let extreme = matches!(
            kind,
            PointKind::Huge | PointKind::Tiny | PointKind::Parabola
        );
        let sizes = [(1, 3), (2, 4), (7, 5), (60, 6), (300, 7)];
        for &(n, seed) in &sizes[..if extreme { 4 } else { 5 }] {
            let pts = points(kind, n, seed).unwrap();
            assert_eq!(pts.len(), n, "{kind}");
            let mut qs = queries_for(&pts);
            qs.extend(points(kind, 40, seed ^ 99).unwrap());
            check(&pts, &qs);
        }
    }
}

#[test]
fn clustered_collinear_and_duplicated_sets() {
    let clustered = points(PointKind::Clustered, 2000, 11).unwrap();
    let qs = points(PointKind::UniformSquare, 300, 12).unwrap();
    check(&clustered, &qs);
    // Collinear: a path along a line, horizontal and diagonal, with duplicates.
    let line: Vec<Point2> = (0..50)
        .map(|i| Point2::new(f64::from(i * 7 % 50), 2.0))
        .collect();
    check(&line, &queries_for(&line));
    let mut diagonal: Vec<Point2> = (0..40)
        .map(|i| Point2::new(f64::from(i), f64::from(i)))
        .collect();
    diagonal.extend_from_within(5..15);
    check(&diagonal, &queries_for(&diagonal));
    // Every point duplicated, the copies first: the answer is the smallest index.
    let base = points(PointKind::UniformDisk, 100, 13).unwrap();
    let mut doubled = base.clone();
    doubled.extend_from_slice(&base);
    doubled.rotate_left(37);
    check(&doubled, &queries_for(&doubled));
    // One distinct point, many times.
    let same = vec![Point2::new(-3.0, 4.5); 9];
    check(&same, &queries_for(&same));
}

#[test]
fn cocircular_ties_answer_the_smallest_index_from_any_start() {
    // The twelve lattice points at distance 5 from the origin, shuffled among farther ones.
    let ring = [
        (5, 0),
        (4, 3),
        (3, 4),
        (0, 5),
        (-3, 4),
        (-4, 3),
        (-5, 0),
        (-4, -3),
        (-3, -4),
        (0, -5),
        (3, -4),
        (4, -3),
    ];
    let mut pts: Vec<Point2> = (-9..=9)
        .flat_map(|x| (-9..=9).map(move |y| (x, y)))
        .filter(|&(x, y)| x * x + y * y > 25)
        .map(|(x, y)| Point2::new(f64::from(x), f64::from(y)))
        .collect();
    for (k, &(x, y)) in ring.iter().enumerate() {
        pts.insert(k * 20 + 30, Point2::new(f64::from(x), f64::from(y)));
    }
    let set = PointSet::new(&pts).unwrap();
    let search = NearestSearch::new(&set).unwrap();
    let first = pts
        .iter()
        .position(|p| p.x * p.x + p.y * p.y == 25.0)
        .unwrap();
    let origin = Point2::new(0.0, 0.0);
    assert_eq!(brute(&pts, origin), first);
    for s in 0..pts.len() {
        assert_eq!(
            search.nearest_with(origin, Some(s), &mut NoCount).unwrap(),
            first
        );
    }
    // Half-integer queries on the lattice tie four ways.
    let qs: Vec<Point2> = (-10..10)
        .flat_map(|x| (-10..10).map(move |y| Point2::new(f64::from(x) + 0.5, f64::from(y) + 0.5)))
        .collect();
    check(&pts, &qs);
}

#[test]
fn every_magnitude_from_subnormal_to_max() {
    let base = points(PointKind::UniformSquare, 200, 21).unwrap();
    let lattice: Vec<Point2> = (0..150)
        .map(|i| Point2::new(f64::from(i % 13) - 6.0, f64::from(i % 11) - 5.0))
        .collect();
    for scale in [5e-324, 1e-300, 1e-150, 1.0, 1e150, 1e300, f64::MAX / 16.0] {
        for set in [&base, &lattice] {
            let pts: Vec<Point2> = set
                .iter()
                .map(|p| Point2::new(p.x * scale, p.y * scale))
                .collect();
            check(&pts, &queries_for(&pts));
        }
    }
    // Mixed magnitudes in one set: the grid's cells are hints only.
    let mixed: Vec<Point2> = [
        (f64::MAX, -f64::MAX),
        (-f64::MAX, f64::MAX),
        (0.0, 0.0),
        (5e-324, 5e-324),
        (1e-300, 0.0),
        (1.0, 1.0),
        (-1e300, -1e300),
        (2.0, -3.0),
    ]
    .into_iter()
    .map(Point2::from)
    .collect();
    check(&mixed, &queries_for(&mixed));
}

#[test]
fn kiddo_finds_no_nearer_point() {
    let pts = points(PointKind::UniformSquare, 5000, 31).unwrap();
    let qs = points(PointKind::UniformSquare, 2000, 32).unwrap();
    let set = PointSet::new(&pts).unwrap();
    let search = NearestSearch::new(&set).unwrap();
    let coords: Vec<[f64; 2]> = pts.iter().map(|p| [p.x, p.y]).collect();
    let tree: ImmutableKdTree<f64, 2> = ImmutableKdTree::new_from_slice(&coords);
    for &q in &qs {
        let ours = search.nearest(q).unwrap();
        let theirs = tree.nearest_one::<SquaredEuclidean>(&[q.x, q.y]).item as usize;
        assert_ne!(
            cmp_dist(q, pts[theirs], q, pts[ours]),
            Ordering::Less,
            "kiddo's {theirs} is nearer to {q:?} than {ours}"
        );
    }
}

#[test]
fn a_query_costs_a_few_distance_evaluations_on_uniform_points() {
    let pts = points(PointKind::UniformSquare, 10_000, 41).unwrap();
    let qs = points(PointKind::UniformSquare, 2000, 42).unwrap();
    let set = PointSet::new(&pts).unwrap();
    let search = NearestSearch::new(&set).unwrap();
    let mut grid = Counts::default();
    for &q in &qs {
        search.nearest_with(q, None, &mut grid).unwrap();
    }
    let mean = grid.distance_evaluations as f64 / qs.len() as f64;
    // About six per vertex looked at, and one or two vertices per query.
    assert!(mean < 50.0, "{mean} distance evaluations per query");
    // From a fixed vertex a walk crosses the set: Θ(√n) steps, far more evaluations.
    let mut fixed = Counts::default();
    for &q in &qs {
        search.nearest_with(q, Some(0), &mut fixed).unwrap();
    }
    assert!(fixed.distance_evaluations > 5 * grid.distance_evaluations);
    let mut batch = Counts::default();
    search.nearest_all_with(&qs, &mut batch).unwrap();
    assert!((batch.distance_evaluations as f64 / qs.len() as f64) < 50.0);
}

#[test]
fn bad_queries_and_starts_are_errors() {
    let pts = vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 0.0),
        Point2::new(0.0, 0.0),
    ];
    let set = PointSet::new(&pts).unwrap();
    let search = NearestSearch::new(&set).unwrap();
    for q in [
        Point2::new(f64::NAN, 0.0),
        Point2::new(0.0, f64::NEG_INFINITY),
    ] {
        assert!(matches!(
            search.nearest(q),
            Err(Error::InvalidParameter { name: "query", .. })
        ));
    }
    let qs = [Point2::new(0.5, 0.5), Point2::new(f64::INFINITY, 0.0)];
    match search.nearest_all(&qs) {
        Err(Error::InvalidParameter {
            name: "queries",
            reason,
        }) => {
            assert!(reason.contains("query 1"), "{reason}")
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(search.nearest_all(&[]).unwrap(), Vec::<usize>::new());
    let q = Point2::new(0.1, 0.0);
    for bad in [2, 3, usize::MAX] {
        assert!(matches!(
            search.nearest_with(q, Some(bad), &mut NoCount),
            Err(Error::InvalidParameter { name: "start", .. })
        ));
    }
    assert_eq!(search.nearest_with(q, Some(1), &mut NoCount).unwrap(), 0);
    assert!(matches!(
        NearestSearch::new(&PointSet::new(&[]).unwrap()),
        Err(Error::TooFew { .. })
    ));
}

fn scaled_lattice() -> impl Strategy<Value = (Vec<Point2>, Vec<Point2>)> {
    let scale = prop::sample::select(vec![1.0, 1e300, 1e-300, 5e-324, 0.1]);
    (
        prop::collection::vec((-20i32..20, -20i32..20), 1..60),
        prop::collection::vec((-45i32..45, -45i32..45), 1..30),
        scale,
    )
        .prop_map(|(p, q, s)| {
            let at = |(x, y): (i32, i32)| Point2::new(f64::from(x) * s, f64::from(y) * s);
            // Queries on the half-lattice: ties between two and four points are common.
            let half =
                |(x, y): (i32, i32)| Point2::new(f64::from(x) * 0.5 * s, f64::from(y) * 0.5 * s);
            (
                p.into_iter().map(at).collect(),
                q.into_iter().map(half).collect(),
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn lattices_with_ties_at_every_scale((pts, qs) in scaled_lattice()) {
        check(&pts, &qs);
    }

    #[test]
    fn random_floats(
        pts in crate::strategies::uniform(1e3, 1..200),
        qs in crate::strategies::uniform(2e3, 1..40),
    ) {
        check(&pts, &qs);
    }
}
