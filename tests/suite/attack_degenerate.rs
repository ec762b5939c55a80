//! Valid but hostile point sets through every point command of the binary, each answer
//! checked exactly: hulls by the exact hull checkers, triangulations by `check_delaunay`,
//! closest pairs, diameters, nearest points and spanning trees against exact brute force
//! (`cmp_dist`). The sets are the degenerate and extreme cases a hostile user tries: one
//! point, copies of one point, collinear and nearly collinear runs, cocircular points,
//! subnormals, coordinates at ±f64::MAX and magnitudes from 1e-300 to 1e300 mixed.
#![cfg(feature = "cli")]

use compgeo::delaunay::{self, check_delaunay, Triangulation};
use compgeo::geometry::{cmp_dist, cmp_lex, Point2, PointSet};
use compgeo::hull::{self, check_encloses, check_strictly_convex_ccw};
use serde_json::Value;
use std::cmp::Ordering;

use crate::common::run;

const MAX: f64 = f64::MAX;

/// The hostile sets, named for the failure messages.
fn sets() -> Vec<(&'static str, Vec<Point2>)> {
    let p = |v: &[(f64, f64)]| {
        v.iter()
            .map(|&(x, y)| Point2::new(x, y))
            .collect::<Vec<_>>()
    };
    let mut cocircular = Vec::new();
    for (x, y) in [(5.0, 0.0), (4.0, 3.0), (3.0, 4.0), (0.0, 5.0)] {
        for (sx, sy) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
            cocircular.push(Point2::new(sx * x, sy * y));
        }
    }
    cocircular.sort_by(|a, b| cmp_lex(*a, *b));
    cocircular.dedup();
    let grid: Vec<Point2> = (0..16)
        .map(|k| Point2::new(f64::from(k % 4), f64::from(k / 4)))
        .chain([Point2::new(1.0, 1.0)])
        .collect();
    vec![
        ("one point", p(&[(0.0, 0.0)])),
        ("two copies", p(&[(1.0, 1.0), (1.0, 1.0)])),
        ("five copies", vec![Point2::new(-3.5, 2.25); 5]),
        (
            "collinear with copies",
            p(&[
                (0.0, 0.0),
                (1.0, 1.0),
                (2.0, 2.0),
                (1.0, 1.0),
                (3.0, 3.0),
                (-1.0, -1.0),
            ]),
        ),
        (
            "nearly collinear",
            p(&[
                (0.0, 0.0),
                (1.0, 1.0),
                (3.0, 3.0000000000000004),
                (2.0, 2.0000000000000004),
            ]),
        ),
        ("cocircular", cocircular),
        ("grid with a copy", grid),
        (
            "at the range's corners",
            p(&[
                (-MAX, -MAX),
                (MAX, -MAX),
                (MAX, MAX),
                (-MAX, MAX),
                (0.0, 0.0),
                (MAX, 0.0),
            ]),
        ),
        (
            "subnormal",
            p(&[
                (0.0, 0.0),
                (5e-324, 0.0),
                (0.0, 5e-324),
                (1e-320, 1e-320),
                (-5e-324, 1e-321),
            ]),
        ),
        (
            "mixed magnitudes",
            p(&[(0.0, 0.0), (1e-300, 0.0), (0.0, 1e-300), (1e300, 1e300)]),
        ),
        (
            "mixed magnitudes, six",
            p(&[
                (1e300, 1e-300),
                (1e-300, 1e300),
                (0.0, 0.0),
                (1e-300, 1e-300),
                (-1e300, 5e-324),
                (5e-324, -1e300),
            ]),
        ),
        (
            "collinear at 1e300",
            p(&[(1e300, 0.0), (1e300, 1.0), (1e300, 2.0), (1e300, -5.0)]),
        ),
    ]
}

fn json_of(points: &[Point2]) -> String {
    // `{:?}` prints every f64 so that it reads back to the same value.
    let items: Vec<String> = points
        .iter()
        .map(|p| format!("[{:?},{:?}]", p.x, p.y))
        .collect();
    format!("[{}]", items.join(","))
}

/// Runs a command on the set; `None` if it refused with the contract's exit 2 and one
/// `error:` line (the caller decides whether refusing is right).
fn answer(args: &[&str], points: &[Point2]) -> Option<Value> {
    let (code, out, err) = run(args, Some(&json_of(points)));
    if code == 2 {
        assert!(out.is_empty(), "{args:?}: stdout on failure: {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("error: "), "{args:?}: {err}");
        return None;
    }
    assert_eq!(code, 0, "{args:?}: {err}");
    assert!(!out.contains("-0.0"), "{args:?}: negative zero in {out}");
    Some(serde_json::from_str(&out).unwrap())
}

fn indices(v: &Value) -> Vec<usize> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|i| i.as_u64().unwrap() as usize)
        .collect()
}

fn pairs(v: &Value) -> Vec<[usize; 2]> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|e| {
            let e = indices(e);
            [e[0], e[1]]
        })
        .collect()
}

fn distinct(points: &[Point2]) -> usize {
    let mut sorted = points.to_vec();
    sorted.sort_by(|a, b| cmp_lex(*a, *b));
    sorted.dedup_by(|a, b| cmp_lex(*a, *b) == Ordering::Equal);
    sorted.len()
}

#[test]
fn every_hull_algorithm_answers_hostile_sets_exactly() {
    for (name, points) in sets() {
        for algorithm in hull::Algorithm::ALL {
            let args = ["hull", "-a", algorithm.name(), "-"];
            let v = answer(&args, &points).unwrap_or_else(|| panic!("{name}: {args:?} refused"));
            let h = indices(&v["hull"]);
            check_strictly_convex_ccw(&points, &h)
                .unwrap_or_else(|e| panic!("{name}, {}: {e:?}", algorithm.name()));
            check_encloses(&points, &h)
                .unwrap_or_else(|e| panic!("{name}, {}: {e:?}", algorithm.name()));
            // The documented start: the lexicographically smallest point.
            let first = points
                .iter()
                .copied()
                .min_by(|a, b| cmp_lex(*a, *b))
                .unwrap();
            assert_eq!(cmp_lex(points[h[0]], first), Ordering::Equal, "{name}");
        }
    }
}

#[test]
fn every_delaunay_builder_answers_hostile_sets_exactly() {
    for (name, points) in sets() {
        let set = PointSet::new(&points).unwrap();
        for algorithm in delaunay::Algorithm::ALL {
            let args = ["delaunay", "-a", algorithm.name(), "-"];
            let v = answer(&args, &points).unwrap_or_else(|| panic!("{name}: {args:?} refused"));
            let triangles: Vec<[usize; 3]> = v["triangles"]
                .as_array()
                .unwrap()
                .iter()
                .map(|t| {
                    let t = indices(t);
                    [t[0], t[1], t[2]]
                })
                .collect();
            let t = Triangulation::from_triangles(&set, &triangles, pairs(&v["duplicates"]))
                .unwrap_or_else(|e| panic!("{name}, {}: {e}", algorithm.name()));
            check_delaunay(&points, &t)
                .unwrap_or_else(|e| panic!("{name}, {}: {e:?}", algorithm.name()));
            assert_eq!(
                v["duplicates"].as_array().unwrap().len(),
                points.len() - distinct(&points),
                "{name}"
            );
        }
    }
}

/// Every pair `i < j`, for brute force.
fn all_pairs(n: usize) -> impl Iterator<Item = (usize, usize)> {
    (0..n).flat_map(move |i| (i + 1..n).map(move |j| (i, j)))
}

#[test]
fn closest_pairs_and_diameters_are_the_exact_extremes() {
    for (name, points) in sets() {
        let d = |i: usize, j: usize, k: usize, l: usize| {
            cmp_dist(points[i], points[j], points[k], points[l])
        };
        for algorithm in ["delaunay", "divide-and-conquer"] {
            let args = ["closest-pair", "-a", algorithm, "-"];
            let Some(v) = answer(&args, &points) else {
                assert!(points.len() < 2, "{name}: {args:?} refused");
                continue;
            };
            let [i, j] = pairs(&Value::Array(vec![v["pair"].clone()]))[0];
            assert_ne!(i, j, "{name}");
            for (k, l) in all_pairs(points.len()) {
                assert_ne!(
                    d(i, j, k, l),
                    Ordering::Greater,
                    "{name}, {algorithm}: {k} {l}"
                );
            }
        }
        for algorithm in ["calipers", "brute-force"] {
            let args = ["diameter", "-a", algorithm, "-"];
            let Some(v) = answer(&args, &points) else {
                assert!(points.len() < 2, "{name}: {args:?} refused");
                continue;
            };
            let [i, j] = pairs(&Value::Array(vec![v["pair"].clone()]))[0];
            for (k, l) in all_pairs(points.len()) {
                assert_ne!(
                    d(i, j, k, l),
                    Ordering::Less,
                    "{name}, {algorithm}: {k} {l}"
                );
            }
        }
    }
}

#[test]
fn nearest_points_are_the_exact_nearest() {
    for (name, points) in sets() {
        let mut queries = vec![Point2::new(0.0, 0.0), Point2::new(-MAX, MAX)];
        queries.extend(points.iter().take(3));
        for q in queries {
            let query = format!("{:?},{:?}", q.x, q.y);
            let v = answer(&["nearest", "--query", &query, "-"], &points)
                .unwrap_or_else(|| panic!("{name}: nearest {query} refused"));
            let i = v["index"].as_u64().unwrap() as usize;
            for (k, &p) in points.iter().enumerate() {
                assert_ne!(
                    cmp_dist(q, points[i], q, p),
                    Ordering::Greater,
                    "{name}: query {query}, answer {i}, nearer {k}"
                );
            }
        }
    }
}

/// Kruskal on every pair, ordered exactly: the multiset of exact edge lengths of every
/// minimum spanning tree is the same, so the tree printed must match it edge for edge.
fn brute_force_mst(points: &[Point2]) -> Vec<[usize; 2]> {
    let mut edges: Vec<(usize, usize)> = all_pairs(points.len()).collect();
    edges.sort_by(|&(a, b), &(c, d)| cmp_dist(points[a], points[b], points[c], points[d]));
    let mut root: Vec<usize> = (0..points.len()).collect();
    fn find(root: &mut [usize], mut v: usize) -> usize {
        while root[v] != v {
            root[v] = root[root[v]];
            v = root[v];
        }
        v
    }
    let mut tree = Vec::new();
    for (a, b) in edges {
        let (ra, rb) = (find(&mut root, a), find(&mut root, b));
        if ra != rb {
            root[ra] = rb;
            tree.push([a, b]);
        }
    }
    tree
}

#[test]
fn euclidean_spanning_trees_have_the_exact_minimum_lengths() {
    for (name, points) in sets() {
        let v = answer(&["emst", "-"], &points).unwrap_or_else(|| panic!("{name}: refused"));
        let mut got = pairs(&v["edges"]);
        // Copies join the point they were merged into by zero-length edges, so the tree
        // spans every input index.
        let expected = brute_force_mst(&points);
        assert_eq!(got.len(), expected.len(), "{name}: {got:?}");
        assert_eq!(got.len(), points.len() - 1, "{name}");
        let by_length = |e: &[usize; 2], f: &[usize; 2]| {
            cmp_dist(points[e[0]], points[e[1]], points[f[0]], points[f[1]])
        };
        got.sort_by(by_length);
        for (e, f) in got.iter().zip(&expected) {
            assert_eq!(by_length(e, f), Ordering::Equal, "{name}: {e:?} vs {f:?}");
        }
    }
}
