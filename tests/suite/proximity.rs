//! The proximity problems against brute force with exact distance comparisons: all nearest
//! neighbours, both closest-pair algorithms, nearest-neighbour queries, the Euclidean MST
//! and the largest empty circle; degenerate suites, bad input and the CLI.

#[cfg(feature = "cli")]
use crate::common::{assert_rejected, run_json};
use compgeo::count::Counts;
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{cmp_dist, orient2d, Orientation, Point2};
use compgeo::hull::{monotone_chain, HullOptions};
use compgeo::proximity::{
    all_nearest_neighbours, all_nearest_neighbours_with, closest_pair_delaunay,
    closest_pair_delaunay_with, closest_pair_divide_and_conquer,
    closest_pair_divide_and_conquer_with, euclidean_mst, largest_empty_circle, nearest,
    NearestSearch,
};
use compgeo::Error;
use proptest::prelude::*;
use std::cmp::Ordering;

/// Every answer of the nearest-neighbour family for one point set, checked by brute force.
fn check_all(pts: &[Point2]) {
    let n = pts.len();
    if n >= 2 {
        let nn = all_nearest_neighbours(pts).unwrap();
        for i in 0..n {
            assert_ne!(nn[i], i);
            for j in (0..n).filter(|&j| j != i) {
                assert_ne!(
                    cmp_dist(pts[i], pts[j], pts[i], pts[nn[i]]),
                    Ordering::Less,
                    "{j} is nearer to {i} than {}",
                    nn[i]
                );
            }
        }
        for pair in [
            closest_pair_delaunay(pts).unwrap().pair,
            closest_pair_divide_and_conquer(pts).unwrap().pair,
        ] {
            let [a, b] = pair;
            assert!(a < b && b < n);
            for i in 0..n {
                for j in i + 1..n {
                    assert_ne!(cmp_dist(pts[i], pts[j], pts[a], pts[b]), Ordering::Less);
                }
            }
        }
    }
    if n >= 1 {
        check_emst(pts);
        let set = crate::common::set(pts);
        let search = NearestSearch::new(&set).unwrap();
        let queries = pts
            .iter()
            .copied()
            .chain(pts.windows(2).map(|w| Point2::new(w[0].x, w[1].y)))
            .chain([Point2::new(0.0, 0.0), Point2::new(-1e9, 3e9)]);
        for q in queries {
            let k = search.nearest(q).unwrap();
            assert!(pts
                .iter()
                .all(|&p| cmp_dist(q, p, q, pts[k]) != Ordering::Less));
        }
    }
}

/// The tree spans every point with n - 1 edges, and its sorted edge lengths equal, exactly,
/// those of a brute-force Prim tree of the complete graph (every minimum spanning tree has
/// the same multiset of lengths).
fn check_emst(pts: &[Point2]) {
    let n = pts.len();
    let t = euclidean_mst(pts).unwrap();
    assert_eq!(t.edges.len(), n - 1);
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], x: usize) -> usize {
        if p[x] == x {
            x
        } else {
            let r = find(p, p[x]);
            p[x] = r;
            r
        }
    }
    for &[u, v] in &t.edges {
        let (a, b) = (find(&mut parent, u), find(&mut parent, v));
        assert_ne!(a, b, "the tree has a cycle");
        parent[a] = b;
    }
    for w in t.edges.windows(2) {
        let ([a, b], [c, d]) = (w[0], w[1]);
        assert_ne!(cmp_dist(pts[a], pts[b], pts[c], pts[d]), Ordering::Greater);
    }
    let mut brute = prim(pts);
    brute.sort_by(|&[a, b], &[c, d]| cmp_dist(pts[a], pts[b], pts[c], pts[d]));
    for (&[a, b], &[c, d]) in t.edges.iter().zip(&brute) {
        assert_eq!(cmp_dist(pts[a], pts[b], pts[c], pts[d]), Ordering::Equal);
    }
}

/// Prim's algorithm on the complete graph, O(n²), with exact comparisons.
fn prim(pts: &[Point2]) -> Vec<[usize; 2]> {
    let n = pts.len();
    let mut in_tree = vec![false; n];
    let mut link = vec![0usize; n];
    in_tree[0] = true;
    let mut edges = Vec::new();
    for _ in 1..n {
        let mut best: Option<usize> = None;
        for v in (0..n).filter(|&v| !in_tree[v]) {
            let nearer =
                |b: usize| cmp_dist(pts[v], pts[link[v]], pts[b], pts[link[b]]) == Ordering::Less;
            if best.is_none_or(nearer) {
                best = Some(v);
            }
        }
        let v = best.unwrap();
        in_tree[v] = true;
        edges.push([link[v], v]);
        for w in (0..n).filter(|&w| !in_tree[w]) {
            if cmp_dist(pts[w], pts[v], pts[w], pts[link[w]]) == Ordering::Less {
                link[w] = v;
            }
        }
    }
    edges
}

/// The largest distance to the nearest point over candidate centres in the hull, by brute
/// force: circumcentres of all triples inside the hull, points of the hull's edges
/// equidistant from two points, and the midpoints of collinear gaps.
fn brute_empty_radius(pts: &[Point2]) -> f64 {
    let hull = monotone_chain(pts, HullOptions::default()).unwrap();
    let f = |x: Point2| {
        pts.iter()
            .map(|p| (p.x - x.x).hypot(p.y - x.y))
            .fold(f64::INFINITY, f64::min)
    };
    let mut best = 0.0f64;
    let n = pts.len();
    let inside = |x: Point2| {
        (0..hull.len()).all(|k| {
            orient2d(pts[hull[k]], pts[hull[(k + 1) % hull.len()]], x) != Orientation::Clockwise
        })
    };
    if hull.len() >= 3 {
        for i in 0..n {
            for j in i + 1..n {
                for k in j + 1..n {
                    let (a, b, c) = (pts[i], pts[j], pts[k]);
                    let d = 2.0 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
                    if d == 0.0 {
                        continue;
                    }
                    let (b2, c2) = (
                        (b.x - a.x).powi(2) + (b.y - a.y).powi(2),
                        (c.x - a.x).powi(2) + (c.y - a.y).powi(2),
                    );
                    let x = Point2::new(
                        a.x + ((c.y - a.y) * b2 - (b.y - a.y) * c2) / d,
                        a.y + ((b.x - a.x) * c2 - (c.x - a.x) * b2) / d,
                    );
                    if inside(x) {
                        best = best.max(f(x));
                    }
                }
            }
        }
    }
    let edges: Vec<[Point2; 2]> = if hull.len() >= 2 {
        (0..hull.len())
            .map(|k| [pts[hull[k]], pts[hull[(k + 1) % hull.len()]]])
            .collect()
    } else {
        Vec::new()
    };
    for [p, q] in edges {
        for i in 0..n {
            for j in i + 1..n {
                let (s, w) = (pts[i], pts[j]);
                let (ux, uy) = (w.x - s.x, w.y - s.y);
                let towards = (q.x - p.x) * ux + (q.y - p.y) * uy;
                if towards == 0.0 {
                    continue;
                }
                let t = (ux * ((w.x + s.x) / 2.0 - p.x) + uy * ((w.y + s.y) / 2.0 - p.y)) / towards;
                if (0.0..=1.0).contains(&t) {
                    best = best.max(f(Point2::new(p.x + t * (q.x - p.x), p.y + t * (q.y - p.y))));
                }
            }
        }
    }
    best
}

fn check_empty_circle(pts: &[Point2]) {
    let c = largest_empty_circle(pts).unwrap();
    let radius = c.radius.to_f64().expect("generated points are moderate");
    let brute = brute_empty_radius(pts);
    let scale = pts
        .iter()
        .map(|p| p.x.abs().max(p.y.abs()))
        .fold(0.0, f64::max);
    let tol = 1e-9 * scale.max(f64::MIN_POSITIVE);
    assert!(
        (radius - brute).abs() <= tol,
        "radius {radius} but brute force {brute} for {pts:?}"
    );
    // The circle is empty (up to rounding) and each defining site is on it.
    for p in pts {
        assert!((p.x - c.centre.x).hypot(p.y - c.centre.y) >= radius - tol);
    }
    for &s in &c.sites {
        let d = (pts[s].x - c.centre.x).hypot(pts[s].y - c.centre.y);
        assert!((d - radius).abs() <= tol);
    }
}

#[test]
fn every_generator_kind_agrees_with_brute_force() {
    for kind in PointKind::ALL {
        for n in [1, 2, 3, 5, 8, 30, 120] {
            for seed in 0..2 {
                let pts = points(kind, n, seed).unwrap();
                check_all(&pts);
            }
        }
    }
}

#[test]
fn empty_circle_on_small_generated_sets() {
    for kind in [
        PointKind::UniformSquare,
        PointKind::Gaussian,
        PointKind::Grid,
        PointKind::Cocircular,
        PointKind::Collinear,
        PointKind::Parabola,
    ] {
        for n in [1, 2, 3, 4, 6, 9, 14] {
            for seed in 0..3 {
                check_empty_circle(&points(kind, n, seed).unwrap());
            }
        }
    }
}

#[test]
fn grids_tie_everywhere_and_any_optimal_answer_is_accepted() {
    let pts: Vec<Point2> = (0..12)
        .flat_map(|i| (0..12).map(move |j| Point2::new(i as f64, j as f64)))
        .collect();
    check_all(&pts);
    let c = closest_pair_delaunay(&pts).unwrap();
    assert_eq!(c.distance, 1.0);
    assert_eq!(euclidean_mst(&pts).unwrap().weight, 143.0);
    let e = largest_empty_circle(&pts).unwrap();
    assert_eq!(
        e.radius,
        0.5f64.sqrt(),
        "the exact radius √(1/2), rounded once"
    );
}

#[test]
fn near_duplicates_one_ulp_apart_and_exact_duplicates() {
    let x = 1.0f64;
    let up = f64::from_bits(x.to_bits() + 1);
    let pts = vec![
        Point2::new(x, x),
        Point2::new(up, x),
        Point2::new(x, up),
        Point2::new(3.0, 1.0),
        Point2::new(x, x),
        Point2::new(2.0, 5.0),
    ];
    check_all(&pts);
    // The duplicate pair is the unique closest pair (distance zero).
    assert_eq!(closest_pair_delaunay(&pts).unwrap().pair, [0, 4]);
    assert_eq!(closest_pair_divide_and_conquer(&pts).unwrap().pair, [0, 4]);
    let nn = all_nearest_neighbours(&pts).unwrap();
    assert_eq!((nn[0], nn[4]), (4, 0));
    // A query at the duplicated point answers the smallest index of the pair.
    assert_eq!(nearest(&pts, Point2::new(x, x)).unwrap(), 0);
    // Without the duplicate, the 1-ulp pairs tie exactly: both are accepted by check_all.
    let distinct = &pts[..4];
    check_all(distinct);
    let c = closest_pair_divide_and_conquer(distinct).unwrap();
    assert!(c.pair == [0, 1] || c.pair == [0, 2]);
}

#[test]
fn huge_tiny_and_subnormal_magnitudes() {
    let sub = 5e-324;
    let sets = [
        vec![
            (1e300, 1e300),
            (-1e300, 2e300),
            (3e300, -1e300),
            (1e300, 1.0000000000000002e300),
        ],
        vec![
            (0.0, 0.0),
            (3.0 * sub, 0.0),
            (0.0, 4.0 * sub),
            (7.0 * sub, 9.0 * sub),
        ],
        vec![
            (1e300, 0.0),
            (0.0, 1e300),
            (0.0, 0.0),
            (sub, sub),
            (2.0 * sub, 0.0),
            (-1e300, -1e300),
        ],
        vec![
            (f64::MAX, f64::MAX),
            (-f64::MAX, f64::MAX),
            (0.0, -f64::MAX),
            (1.0, 1.0),
        ],
    ];
    for set in sets {
        let pts: Vec<Point2> = set.into_iter().map(Point2::from).collect();
        check_all(&pts);
    }
}

#[test]
fn counted_runs_give_the_same_answers_and_count_their_work() {
    let pts = points(PointKind::UniformDisk, 500, 9).unwrap();
    let mut c = Counts::default();
    assert_eq!(
        closest_pair_delaunay_with(&crate::common::set(&pts), &mut c).unwrap(),
        closest_pair_delaunay(&pts).unwrap()
    );
    assert!(c.incircle_tests > 0 && c.distance_evaluations > 0);
    let mut c = Counts::default();
    assert_eq!(
        closest_pair_divide_and_conquer_with(&crate::common::set(&pts), &mut c).unwrap(),
        closest_pair_divide_and_conquer(&pts).unwrap()
    );
    assert!(c.comparisons > 0 && c.distance_evaluations > 0);
    let mut c = Counts::default();
    assert_eq!(
        all_nearest_neighbours_with(&crate::common::set(&pts), &mut c).unwrap(),
        all_nearest_neighbours(&pts).unwrap()
    );
    // Two distance evaluations per Delaunay edge, fewer than 3n edges.
    assert!(c.distance_evaluations < 6 * 500);
}

#[test]
fn bad_input_is_an_error() {
    let nan = vec![Point2::new(0.0, 0.0), Point2::new(f64::NAN, 1.0)];
    assert!(matches!(
        closest_pair_delaunay(&nan),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        closest_pair_divide_and_conquer(&nan),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(euclidean_mst(&nan), Err(Error::NonFinite { .. })));
    assert!(matches!(
        largest_empty_circle(&nan),
        Err(Error::NonFinite { .. })
    ));
    assert!(matches!(
        all_nearest_neighbours(&[]),
        Err(Error::TooFew { .. })
    ));
    assert_eq!(euclidean_mst(&[]).unwrap().edges, Vec::<[usize; 2]>::new());
    let pts = vec![Point2::new(0.0, 0.0), Point2::new(1.0, 1.0)];
    for q in [Point2::new(f64::NAN, 0.0), Point2::new(0.0, f64::INFINITY)] {
        assert!(matches!(
            nearest(&pts, q),
            Err(Error::InvalidParameter { name: "query", .. })
        ));
    }
}

#[cfg(feature = "cli")]
#[test]
fn cli_proximity_commands() {
    let input = "[[0,0],[4,0],[4,4],[0,4],[1,1],[1,1]]";
    let v = run_json(&["closest-pair", "-"], Some(input));
    assert_eq!(v["pair"], serde_json::json!([4, 5]));
    assert_eq!(v["distance"], 0.0);
    let v = run_json(
        &["closest-pair", "-a", "divide-and-conquer", "-"],
        Some(input),
    );
    assert_eq!(v["pair"], serde_json::json!([4, 5]));
    let v = run_json(&["nearest", "--query", "3.5,-1", "-"], Some(input));
    assert_eq!(v["index"], 1);
    let v = run_json(&["emst", "-"], Some(input));
    assert_eq!(v["edges"].as_array().unwrap().len(), 5);
    let v = run_json(&["empty-circle", "-"], Some("[[0,0],[2,0],[2,2],[0,2]]"));
    assert_eq!(v["centre"], serde_json::json!([1.0, 1.0]));
    assert_eq!(v["radius"], 2f64.sqrt());

    let err = assert_rejected(&["nearest", "--query", "nan,0", "-"], Some(input));
    assert!(err.contains("query"), "{err}");
    assert_rejected(&["nearest", "--query", "1", "-"], Some(input));
    let err = assert_rejected(&["closest-pair", "-"], Some("[[0,0],[NaN,1]]"));
    assert!(err.contains("point 1"), "{err}");
    assert_rejected(&["closest-pair", "-"], Some("[[0,0]]"));
    // The tree of no points is empty; the problems about an answer point need points.
    let v = run_json(&["emst", "-"], Some("[]"));
    assert_eq!(
        (v["edges"].clone(), v["length"].clone()),
        (serde_json::json!([]), serde_json::json!(0.0))
    );
    assert!(assert_rejected(&["empty-circle", "-"], Some("[]")).contains("at least 1"));
    assert!(
        assert_rejected(&["nearest", "--query", "0,0", "-"], Some("[]")).contains("at least 1")
    );
    assert_rejected(&["empty-circle", "-"], Some("[[0,0],[1]]"));
}

fn scaled_coords() -> impl Strategy<Value = Vec<Point2>> {
    let scale = prop::sample::select(vec![1.0, 1e300, 1e-300, 5e-324, 0.1]);
    (
        prop::collection::vec((-1000i32..1000, -1000i32..1000), 2..40),
        scale,
    )
        .prop_map(|(v, s)| {
            v.into_iter()
                .map(|(x, y)| Point2::new(x as f64 * s, y as f64 * s))
                .collect()
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn integer_points_with_ties_and_duplicates(pts in crate::strategies::lattice(-6..=5, 1..40)) {
        check_all(&pts);
    }

    #[test]
    fn scaled_points_down_to_subnormals(pts in scaled_coords()) {
        check_all(&pts);
    }

    #[test]
    fn random_floats(pts in prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 1..60)) {
        let pts: Vec<Point2> = pts.into_iter().map(Point2::from).collect();
        check_all(&pts);
    }

    #[test]
    fn empty_circle_matches_brute_force(pts in prop::collection::vec((-50i32..50, -50i32..50), 1..10)) {
        let pts: Vec<Point2> = pts.into_iter().map(|(x, y)| Point2::new(x as f64, y as f64)).collect();
        check_empty_circle(&pts);
    }
}
