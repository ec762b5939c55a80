//! Generators: determinism and the defining property of every kind, checked with the exact
//! predicates, exact integer arithmetic and brute force.

use compgeo::gen::{
    graph, points, sequence, sequence_f64, with_random_weights, GraphKind, PointKind, SequenceKind,
    MAX_COCIRCULAR, MAX_KEYS, MAX_POINTS, RANDOM_KEY_BOUND,
};
use compgeo::geometry::{cmp_dist, incircle, orient2d, InCircle, Orientation, Point2};
use compgeo::graph::{EdgeList, MAX_EDGES, MAX_VERTICES};
use compgeo::Error;
use proptest::prelude::*;
use std::cmp::Ordering;
use std::collections::{BTreeSet, HashSet};

fn bits(pts: &[Point2]) -> Vec<(u64, u64)> {
    pts.iter().map(|p| (p.x.to_bits(), p.y.to_bits())).collect()
}

fn is_integer(v: f64) -> bool {
    v.is_finite() && v.fract() == 0.0
}

fn distinct_count(pts: &[Point2]) -> usize {
    bits(pts).into_iter().collect::<HashSet<_>>().len()
}

// ---------------------------------------------------------------- points

#[test]
fn every_point_kind_is_deterministic_and_seed_sensitive() {
    for kind in PointKind::ALL {
        let a = points(kind, 300, 17).unwrap();
        let b = points(kind, 300, 17).unwrap();
        assert_eq!(bits(&a), bits(&b), "{kind}: same seed, different output");
        let c = points(kind, 300, 18).unwrap();
        if kind == PointKind::Parabola {
            // The parabola is fully determined by n: no randomness to vary.
            assert_eq!(bits(&a), bits(&c));
        } else {
            assert_ne!(bits(&a), bits(&c), "{kind}: seed has no effect");
        }
    }
}

#[test]
fn every_point_kind_gives_n_finite_points_and_empty_for_zero() {
    for kind in PointKind::ALL {
        assert!(points(kind, 0, 1).unwrap().is_empty(), "{kind}");
        for n in [1, 2, 3, 5, 17, 256] {
            let pts = points(kind, n, 5).unwrap();
            assert_eq!(pts.len(), n, "{kind} n = {n}");
            assert!(pts.iter().all(|p| p.is_finite()), "{kind} n = {n}");
        }
    }
}

#[test]
fn too_many_points_is_an_error_naming_the_limit() {
    for kind in PointKind::ALL {
        match points(kind, MAX_POINTS + 1, 0) {
            Err(Error::LimitExceeded {
                limit: "MAX_POINTS",
                max,
                value,
                ..
            }) => assert_eq!((max, value), (MAX_POINTS, MAX_POINTS as u128 + 1)),
            other => panic!("{kind}: expected LimitExceeded, got {other:?}"),
        }
    }
}

#[test]
fn kind_names_round_trip_and_errors_list_them() {
    for kind in PointKind::ALL {
        assert_eq!(kind.name().parse::<PointKind>().unwrap(), kind);
        assert_eq!(kind.to_string(), kind.name());
    }
    let names: HashSet<_> = PointKind::ALL.iter().map(|k| k.name()).collect();
    assert_eq!(names.len(), PointKind::ALL.len());
    let err = "square".parse::<PointKind>().unwrap_err().to_string();
    assert!(err.contains("`square`"), "{err}");
    assert!(
        PointKind::ALL.iter().all(|k| err.contains(k.name())),
        "{err}"
    );

    for kind in GraphKind::ALL {
        assert_eq!(kind.name().parse::<GraphKind>().unwrap(), kind);
    }
    let err = "wheel".parse::<GraphKind>().unwrap_err().to_string();
    assert!(
        GraphKind::ALL.iter().all(|k| err.contains(k.name())),
        "{err}"
    );
    for kind in SequenceKind::ALL {
        assert_eq!(kind.name().parse::<SequenceKind>().unwrap(), kind);
    }
    assert!("Sorted".parse::<SequenceKind>().is_err());
}

#[test]
fn uniform_square_and_disk_stay_in_their_regions() {
    let square = points(PointKind::UniformSquare, 5000, 1).unwrap();
    assert!(square
        .iter()
        .all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y)));
    let o = Point2::new(0.0, 0.0);
    let e = Point2::new(1.0, 0.0);
    let disk = points(PointKind::UniformDisk, 5000, 1).unwrap();
    assert!(disk.iter().all(|&p| cmp_dist(o, p, o, e) == Ordering::Less));
    // Uniform in the disk: a quarter of the points within radius 1/2 (std. error 0.006).
    let inner = disk
        .iter()
        .filter(|&&p| cmp_dist(o, p, o, Point2::new(0.5, 0.0)) == Ordering::Less)
        .count() as f64
        / 5000.0;
    assert!((inner - 0.25).abs() < 0.03, "{inner}");
}

#[test]
fn gaussian_has_zero_mean_and_unit_sigma() {
    let pts = points(PointKind::Gaussian, 20_000, 3).unwrap();
    let n = pts.len() as f64;
    for coord in [|p: &Point2| p.x, |p: &Point2| p.y] {
        let mean = pts.iter().map(coord).sum::<f64>() / n;
        let var = pts.iter().map(|p| (coord(p) - mean).powi(2)).sum::<f64>() / n;
        // Standard errors: 0.007 for the mean, 0.01 for the variance.
        assert!(mean.abs() < 0.04, "{mean}");
        assert!((var - 1.0).abs() < 0.05, "{var}");
    }
    // About 68% within one sigma per coordinate.
    let within = pts.iter().filter(|p| p.x.abs() < 1.0).count() as f64 / n;
    assert!((within - 0.6827).abs() < 0.02, "{within}");
}

#[test]
fn clustered_points_gather_near_few_centres() {
    let pts = points(PointKind::Clustered, 4096, 8).unwrap();
    // 4096 points use 1 + 12/2 = 7 clusters: a 0.125-cell histogram of [0,1)^2 is mostly
    // empty, unlike a uniform cloud which fills all 64 cells.
    let mut cells = HashSet::new();
    for p in &pts {
        cells.insert(((p.x * 8.0).floor() as i64, (p.y * 8.0).floor() as i64));
    }
    assert!(cells.len() <= 40, "{} cells", cells.len());
    let uniform = points(PointKind::UniformSquare, 4096, 8).unwrap();
    let ucells: HashSet<_> = uniform
        .iter()
        .map(|p| ((p.x * 8.0) as i64, (p.y * 8.0) as i64))
        .collect();
    assert_eq!(ucells.len(), 64);
}

/// Cocircular: distinct integers, same exact x^2 + y^2, and `incircle == On` for every
/// point against a CCW triple of the set.
fn check_cocircular(pts: &[Point2]) {
    assert!(pts.iter().all(|p| is_integer(p.x) && is_integer(p.y)));
    assert!(pts
        .iter()
        .all(|p| p.x.abs() < 2f64.powi(53) && p.y.abs() < 2f64.powi(53)));
    assert_eq!(distinct_count(pts), pts.len());
    let r2 = |p: &Point2| (p.x as i128).pow(2) + (p.y as i128).pow(2);
    assert!(pts.iter().all(|p| r2(p) == r2(&pts[0])));
    if pts.len() >= 3 {
        let (mut a, mut b, c) = (pts[0], pts[1], pts[2]);
        match orient2d(a, b, c) {
            Orientation::CounterClockwise => {}
            Orientation::Clockwise => std::mem::swap(&mut a, &mut b),
            Orientation::Collinear => panic!("three distinct points of a circle are collinear"),
        }
        for &q in pts {
            assert_eq!(incircle(a, b, c, q), InCircle::On, "{q:?}");
        }
    }
}

#[test]
fn cocircular_points_lie_exactly_on_one_circle() {
    for n in [3, 12, 13, 100, 1000, 5000] {
        let pts = points(PointKind::Cocircular, n, n as u64).unwrap();
        assert_eq!(pts.len(), n);
        check_cocircular(&pts);
    }
}

#[test]
fn cocircular_supports_a_hundred_thousand_points() {
    let pts = points(PointKind::Cocircular, 100_000, 1).unwrap();
    assert_eq!(pts.len(), 100_000);
    check_cocircular(&pts);
}

#[test]
fn cocircular_beyond_its_family_names_the_limit() {
    assert_eq!(
        points(PointKind::Cocircular, MAX_COCIRCULAR, 2)
            .unwrap()
            .len(),
        MAX_COCIRCULAR
    );
    match points(PointKind::Cocircular, MAX_COCIRCULAR + 1, 2) {
        Err(
            e @ Error::LimitExceeded {
                limit: "MAX_COCIRCULAR",
                ..
            },
        ) => assert!(e.to_string().contains(&MAX_COCIRCULAR.to_string()), "{e}"),
        other => panic!("expected LimitExceeded, got {other:?}"),
    }
}

#[test]
fn parabola_is_exact_and_in_increasing_x() {
    for n in [1, 2, 7, 1000] {
        let pts = points(PointKind::Parabola, n, 0).unwrap();
        assert!(pts.iter().all(|p| is_integer(p.x) && p.y == p.x * p.x));
        assert!(pts.windows(2).all(|w| w[1].x == w[0].x + 1.0));
        // Strictly convex: every consecutive triple turns left.
        assert!(pts
            .windows(3)
            .all(|w| orient2d(w[0], w[1], w[2]) == Orientation::CounterClockwise));
    }
}

fn grid_cells(n: usize) -> BTreeSet<(i64, i64)> {
    let cols = (1..).find(|c: &usize| c * c >= n).unwrap().max(1);
    (0..n)
        .map(|k| ((k % cols) as i64, (k / cols) as i64))
        .collect()
}

#[test]
fn grids_are_integer_lattices_of_the_documented_shape() {
    for n in [1, 2, 10, 16, 17, 99, 400] {
        let grid = points(PointKind::Grid, n, 4).unwrap();
        assert!(grid.iter().all(|p| is_integer(p.x) && is_integer(p.y)));
        let cells: BTreeSet<(i64, i64)> = grid.iter().map(|p| (p.x as i64, p.y as i64)).collect();
        assert_eq!(cells.len(), n);
        assert_eq!(cells, grid_cells(n));

        // Rotated grid: (i, j) -> (4i - 3j, 3i + 4j); invert exactly with integers.
        let rotated = points(PointKind::RotatedGrid, n, 4).unwrap();
        let back: BTreeSet<(i64, i64)> = rotated
            .iter()
            .map(|p| {
                assert!(is_integer(p.x) && is_integer(p.y));
                let (x, y) = (p.x as i64, p.y as i64);
                assert_eq!((4 * x + 3 * y) % 25, 0);
                assert_eq!((4 * y - 3 * x) % 25, 0);
                ((4 * x + 3 * y) / 25, (4 * y - 3 * x) / 25)
            })
            .collect();
        assert_eq!(back, grid_cells(n));
    }
    // Not axis-aligned: the grid's first row lies along the direction (4, 3).
    let r = points(PointKind::RotatedGrid, 9, 0).unwrap();
    let row: Vec<Point2> = r
        .iter()
        .copied()
        .filter(|p| (4.0 * p.y - 3.0 * p.x) == 0.0)
        .collect();
    assert_eq!(row.len(), 3);
    assert_eq!(orient2d(row[0], row[1], row[2]), Orientation::Collinear);
    assert!(row.iter().any(|p| p.y != 0.0));
}

fn ulp_distance(a: f64, b: f64) -> u64 {
    // Same sign, non-negative inputs here: the bit patterns are ordered like the values.
    a.to_bits().abs_diff(b.to_bits())
}

#[test]
fn near_duplicates_are_one_ulp_apart() {
    for n in [2, 3, 5, 9, 1000] {
        let pts = points(PointKind::NearDuplicates, n, 6).unwrap();
        assert_eq!(
            distinct_count(&pts),
            n,
            "near-duplicates must not be exact duplicates"
        );
        assert!(pts.iter().all(|p| p.x >= 0.0 && p.y >= 0.0));
        for (i, p) in pts.iter().enumerate() {
            let partner = pts.iter().enumerate().any(|(j, q)| {
                i != j && {
                    let (dx, dy) = (ulp_distance(p.x, q.x), ulp_distance(p.y, q.y));
                    dx <= 1 && dy <= 1 && dx + dy >= 1
                }
            });
            assert!(partner, "n = {n}: point {i} {p:?} has no 1-ulp partner");
        }
    }
}

#[test]
fn collinear_points_are_exactly_collinear_and_distinct() {
    for seed in 0..5 {
        let pts = points(PointKind::Collinear, 500, seed).unwrap();
        assert_eq!(distinct_count(&pts), 500);
        assert!(pts.iter().all(|p| is_integer(p.x) && is_integer(p.y)));
        let (a, b) = (pts[0], pts[1]);
        assert!(pts
            .iter()
            .all(|&q| orient2d(a, b, q) == Orientation::Collinear));
        // And a point off the line is seen as such: the line is not degenerate.
        let off = Point2::new(a.x, a.y + 1.0);
        assert_ne!(orient2d(a, b, off), Orientation::Collinear);
    }
}

#[test]
fn huge_and_tiny_magnitudes_are_in_range() {
    let huge = points(PointKind::Huge, 2000, 9).unwrap();
    let coords: Vec<f64> = huge.iter().flat_map(|p| [p.x, p.y]).collect();
    assert!(coords
        .iter()
        .all(|c| c.is_finite() && (1e200..=1e300).contains(&c.abs())));
    assert!(coords.iter().any(|&c| c < 0.0) && coords.iter().any(|&c| c > 0.0));
    assert!(coords.iter().any(|c| c.abs() < 1e210) && coords.iter().any(|c| c.abs() > 1e290));

    let tiny = points(PointKind::Tiny, 2000, 9).unwrap();
    let coords: Vec<f64> = tiny.iter().flat_map(|p| [p.x, p.y]).collect();
    let subnormal = |c: f64| c != 0.0 && c.abs() < f64::MIN_POSITIVE;
    assert!(coords
        .iter()
        .all(|&c| subnormal(c) || (1e-300..=1e-140).contains(&c.abs())));
    let subnormals = coords.iter().filter(|&&c| subnormal(c)).count();
    // One in eight coordinates is subnormal (expected 500 of 4000).
    assert!((350..650).contains(&subnormals), "{subnormals}");
    assert!(coords.iter().any(|&c| c < 0.0) && coords.iter().any(|&c| c > 0.0));
    assert!(coords.iter().all(|&c| c != 0.0));
}

// ---------------------------------------------------------------- graphs

/// Simple, in range, `u < v`, sorted.
fn check_simple(g: &EdgeList) {
    assert!(
        g.edges.iter().all(|&[u, v]| u < v && v < g.vertices),
        "{g:?}"
    );
    assert!(
        g.edges.windows(2).all(|w| w[0] < w[1]),
        "not sorted or has parallels"
    );
}

fn degrees(g: &EdgeList) -> Vec<usize> {
    let mut d = vec![0; g.vertices];
    for &[u, v] in &g.edges {
        d[u] += 1;
        d[v] += 1;
    }
    d
}

fn adjacency(g: &EdgeList) -> Vec<Vec<bool>> {
    let mut a = vec![vec![false; g.vertices]; g.vertices];
    for &[u, v] in &g.edges {
        a[u][v] = true;
        a[v][u] = true;
    }
    a
}

fn components(g: &EdgeList) -> usize {
    fn find(p: &mut [usize], x: usize) -> usize {
        let mut r = x;
        while p[r] != r {
            r = p[r];
        }
        p[x] = r;
        r
    }
    let mut parent: Vec<usize> = (0..g.vertices).collect();
    let mut count = g.vertices;
    for &[u, v] in &g.edges {
        let (a, b) = (find(&mut parent, u), find(&mut parent, v));
        if a != b {
            parent[a] = b;
            count -= 1;
        }
    }
    count
}

/// Colour count of greedy colouring in vertex order (first colour unused by neighbours).
fn greedy_colours(g: &EdgeList) -> usize {
    let adj = adjacency(g);
    let mut colour = vec![usize::MAX; g.vertices];
    for v in 0..g.vertices {
        let used: HashSet<usize> = (0..v).filter(|&u| adj[v][u]).map(|u| colour[u]).collect();
        colour[v] = (0..).find(|c| !used.contains(c)).unwrap();
    }
    colour.iter().map(|c| c + 1).max().unwrap_or(0)
}

/// Whether the graph has a proper colouring with `k` colours (backtracking).
fn colourable(g: &EdgeList, k: usize) -> bool {
    fn go(adj: &[Vec<bool>], colour: &mut Vec<usize>, k: usize) -> bool {
        let v = colour.len();
        if v == adj.len() {
            return true;
        }
        for c in 0..k {
            if (0..v).all(|u| !adj[v][u] || colour[u] != c) {
                colour.push(c);
                if go(adj, colour, k) {
                    return true;
                }
                colour.pop();
            }
            // Symmetry: the first vertex may as well take colour 0.
            if v == 0 {
                break;
            }
        }
        false
    }
    go(&adjacency(g), &mut Vec::new(), k)
}

fn has_triangle(g: &EdgeList) -> bool {
    let adj = adjacency(g);
    g.edges
        .iter()
        .any(|&[u, v]| (0..g.vertices).any(|w| adj[u][w] && adj[v][w]))
}

#[test]
fn every_graph_kind_is_deterministic_simple_and_sorted() {
    for kind in GraphKind::ALL {
        let n = match kind {
            GraphKind::Petersen => 10,
            GraphKind::Mycielski => 5,
            GraphKind::Queen => 6,
            _ => 30,
        };
        let a = graph(kind, n, 100, 21).unwrap();
        assert_eq!(a, graph(kind, n, 100, 21).unwrap(), "{kind}");
        assert_eq!(a.weights, None);
        check_simple(&a);
        let b = graph(kind, n, 100, 22).unwrap();
        if matches!(kind, GraphKind::Gnm | GraphKind::Tree) {
            assert_ne!(a, b, "{kind}: seed has no effect");
        } else {
            assert_eq!(a, b, "{kind}: a fixed graph must not depend on the course");
        }
    }
}

#[test]
fn gnm_has_m_distinct_edges_and_rejects_too_many() {
    for (n, m) in [
        (0, 0),
        (1, 0),
        (2, 1),
        (10, 0),
        (10, 20),
        (10, 45),
        (300, 5000),
    ] {
        let g = graph(GraphKind::Gnm, n, m, 3).unwrap();
        assert_eq!((g.vertices, g.edges.len()), (n, m));
        check_simple(&g);
    }
    assert_eq!(
        graph(GraphKind::Gnm, 10, 45, 3).unwrap().edges,
        graph(GraphKind::Complete, 10, 0, 0).unwrap().edges
    );
    match graph(GraphKind::Gnm, 10, 46, 3) {
        Err(Error::InvalidParameter { name: "m", reason }) => assert!(reason.contains("45")),
        other => panic!("expected InvalidParameter, got {other:?}"),
    }
    // Every pair turns up over many seeds: the sampler reaches the whole pair space.
    let mut seen = HashSet::new();
    for seed in 0..200 {
        seen.extend(graph(GraphKind::Gnm, 8, 3, seed).unwrap().edges);
    }
    assert_eq!(seen.len(), 28);
    // A huge vertex count with few edges is fine (no O(n) work).
    let g = graph(GraphKind::Gnm, MAX_VERTICES, 10, 1).unwrap();
    assert_eq!(g.edges.len(), 10);
    check_simple(&g);
}

#[test]
fn grid_graph_joins_exactly_the_lattice_neighbours() {
    for n in [0, 1, 2, 5, 12, 16, 30] {
        let g = graph(GraphKind::Grid, n, 0, 0).unwrap();
        assert_eq!(g.vertices, n);
        let cols = (1..).find(|c: &usize| c * c >= n).unwrap().max(1);
        let cell = |k: usize| ((k % cols) as i64, (k / cols) as i64);
        let mut expected = Vec::new();
        for u in 0..n {
            for v in u + 1..n {
                let (a, b) = (cell(u), cell(v));
                if (a.0 - b.0).abs() + (a.1 - b.1).abs() == 1 {
                    expected.push([u, v]);
                }
            }
        }
        assert_eq!(g.edges, expected, "n = {n}");
    }
}

#[test]
fn complete_and_cycle_have_their_counts_and_chromatic_numbers() {
    for n in [0, 1, 2, 5, 9] {
        let k = graph(GraphKind::Complete, n, 0, 0).unwrap();
        assert_eq!(k.edges.len(), n * n.saturating_sub(1) / 2);
        if n > 0 {
            assert!(colourable(&k, n) && !colourable(&k, n - 1));
        }
    }
    for n in [3, 4, 5, 8, 11] {
        let c = graph(GraphKind::Cycle, n, 0, 0).unwrap();
        assert_eq!((c.vertices, c.edges.len()), (n, n));
        assert!(degrees(&c).iter().all(|&d| d == 2));
        assert_eq!(components(&c), 1);
        let chi = if n % 2 == 0 { 2 } else { 3 };
        assert!(colourable(&c, chi) && !colourable(&c, chi - 1), "C_{n}");
    }
    for n in [0, 1, 2] {
        assert!(matches!(
            graph(GraphKind::Cycle, n, 0, 0),
            Err(Error::InvalidParameter { name: "n", .. })
        ));
    }
}

#[test]
fn trees_are_connected_with_n_minus_one_edges() {
    for seed in 0..20 {
        for n in [0, 1, 2, 3, 10, 57] {
            let t = graph(GraphKind::Tree, n, 0, seed).unwrap();
            check_simple(&t);
            assert_eq!(t.vertices, n);
            assert_eq!(t.edges.len(), n.saturating_sub(1));
            if n > 0 {
                assert_eq!(components(&t), 1, "n = {n} seed = {seed}");
            }
            if n >= 2 {
                assert!(colourable(&t, 2));
            }
        }
    }
    // Cayley: 4^(4-2) = 16 labelled trees on 4 vertices; a uniform sampler finds them all.
    let shapes: HashSet<_> = (0..300)
        .map(|s| graph(GraphKind::Tree, 4, 0, s).unwrap().edges)
        .collect();
    assert_eq!(shapes.len(), 16);
}

#[test]
fn petersen_is_the_petersen_graph() {
    let g = graph(GraphKind::Petersen, 10, 0, 0).unwrap();
    assert_eq!((g.vertices, g.edges.len()), (10, 15));
    assert!(degrees(&g).iter().all(|&d| d == 3));
    assert!(!has_triangle(&g));
    let adj = adjacency(&g);
    for u in 0..10 {
        for v in u + 1..10 {
            let common = (0..10).filter(|&w| adj[u][w] && adj[v][w]).count();
            // Strongly regular (10, 3, 0, 1): adjacent vertices share no neighbour,
            // non-adjacent ones exactly one.
            assert_eq!(common, usize::from(!adj[u][v]), "{u} {v}");
        }
    }
    assert!(colourable(&g, 3) && !colourable(&g, 2));
    for n in [0, 9, 11] {
        assert!(matches!(
            graph(GraphKind::Petersen, n, 0, 0),
            Err(Error::InvalidParameter { name: "n", .. })
        ));
    }
}

#[test]
fn mycielski_graphs_have_the_right_size_and_chromatic_number() {
    let (mut v, mut e) = (2usize, 1usize);
    for k in 2..=8 {
        let g = graph(GraphKind::Mycielski, k, 0, 0).unwrap();
        check_simple(&g);
        assert_eq!(g.vertices, 3 * (1 << (k - 2)) - 1, "k = {k}");
        assert_eq!((g.vertices, g.edges.len()), (v, e), "k = {k}");
        assert!(!has_triangle(&g) && components(&g) == 1);
        if k <= 4 {
            assert!(colourable(&g, k) && !colourable(&g, k - 1), "k = {k}");
        }
        (v, e) = (2 * v + 1, 3 * e + v);
    }
    let m3 = graph(GraphKind::Mycielski, 3, 0, 0).unwrap();
    assert!(degrees(&m3).iter().all(|&d| d == 2)); // C_5
    let m1 = graph(GraphKind::Mycielski, 1, 0, 0).unwrap();
    assert_eq!((m1.vertices, m1.edges.len()), (1, 0));
    assert!(graph(GraphKind::Mycielski, 0, 0, 0).is_err());
    assert!(graph(GraphKind::Mycielski, 40, 0, 0).is_err());
}

#[test]
fn queen_graph_matches_the_attack_rule() {
    for n in 0..=7usize {
        let g = graph(GraphKind::Queen, n, 0, 0).unwrap();
        assert_eq!(g.vertices, n * n);
        let square = |k: usize| ((k / n) as i64, (k % n) as i64);
        let mut expected = Vec::new();
        for a in 0..n * n {
            for b in a + 1..n * n {
                let ((ra, ca), (rb, cb)) = (square(a), square(b));
                if ra == rb || ca == cb || (ra - rb).abs() == (ca - cb).abs() {
                    expected.push([a, b]);
                }
            }
        }
        assert_eq!(g.edges, expected, "n = {n}");
        if n >= 1 {
            assert_eq!(g.edges.len(), n * (n - 1) * (5 * n - 1) / 3);
        }
    }
}

#[test]
fn crown_defeats_greedy_colouring() {
    for n in [1, 2, 3, 6, 10] {
        let g = graph(GraphKind::Crown, n, 0, 0).unwrap();
        assert_eq!((g.vertices, g.edges.len()), (2 * n, n * (n - 1)));
        let adj = adjacency(&g);
        for i in 0..n {
            for j in 0..n {
                assert_eq!(adj[2 * i][2 * j + 1], i != j);
                assert!(!adj[2 * i][2 * j] && !adj[2 * i + 1][2 * j + 1]);
            }
        }
        assert_eq!(greedy_colours(&g), n);
        if n >= 2 {
            assert!(colourable(&g, 2));
        }
    }
}

#[test]
fn oversized_graphs_are_errors_not_allocations() {
    for (kind, n) in [
        (GraphKind::Complete, 1 << 20),
        (GraphKind::Queen, 1000),
        (GraphKind::Crown, 1 << 20),
        (GraphKind::Tree, MAX_VERTICES + 1),
        (GraphKind::Grid, usize::MAX),
        (GraphKind::Mycielski, 1 << 40),
    ] {
        match graph(kind, n, 0, 0) {
            Err(e @ Error::LimitExceeded { limit, max, .. }) => {
                assert!(
                    ["MAX_VERTICES", "MAX_EDGES"].contains(&limit),
                    "{kind}: {e}"
                );
                assert!(e.to_string().contains(&max.to_string()), "{kind}: {e}");
            }
            other => panic!("{kind}: expected LimitExceeded, got {other:?}"),
        }
    }
    // The K_23170 has 268 412 865 edges; the largest complete graph is K_11585.
    assert!(matches!(
        graph(GraphKind::Complete, 23170, 0, 0),
        Err(Error::LimitExceeded {
            limit: "MAX_EDGES",
            value: 268_412_865,
            ..
        })
    ));
    assert!(matches!(
        graph(GraphKind::Gnm, 100_000, MAX_EDGES + 1, 0),
        Err(Error::LimitExceeded {
            limit: "MAX_EDGES",
            ..
        })
    ));
    assert!(matches!(
        sequence(SequenceKind::Random, MAX_KEYS + 1, 0),
        Err(Error::LimitExceeded {
            limit: "MAX_KEYS",
            ..
        })
    ));
    assert!(matches!(
        sequence_f64(usize::MAX, 0),
        Err(Error::LimitExceeded {
            limit: "MAX_KEYS",
            ..
        })
    ));
}

#[test]
fn random_weights_are_seeded_and_in_the_unit_interval() {
    let g = graph(GraphKind::Gnm, 50, 300, 1).unwrap();
    let a = with_random_weights(g.clone(), 5);
    assert_eq!(a.edges, g.edges);
    let w = a.weights.clone().unwrap();
    assert_eq!(w.len(), 300);
    assert!(w.iter().all(|&x| (0.0..1.0).contains(&x)));
    let distinct: HashSet<u64> = w.iter().map(|x| x.to_bits()).collect();
    assert_eq!(distinct.len(), 300);
    assert_eq!(a, with_random_weights(g.clone(), 5));
    let b = with_random_weights(a.clone(), 6);
    assert_ne!(
        b.weights, a.weights,
        "weights are replaced by the new seed's"
    );
    // Weights use their own stream: they are not the first unit draws of the course's main
    // stream, which is exactly what `uniform-square` coordinates are.
    let square: Vec<f64> = points(PointKind::UniformSquare, 150, 5)
        .unwrap()
        .iter()
        .flat_map(|p| [p.x, p.y])
        .collect();
    assert!(w.iter().zip(&square).all(|(a, b)| a != b));
}

// ---------------------------------------------------------------- sequences

#[test]
fn sequences_are_deterministic_and_have_their_shapes() {
    for kind in SequenceKind::ALL {
        assert!(sequence(kind, 0, 1).unwrap().is_empty());
        let a = sequence(kind, 1000, 1).unwrap();
        assert_eq!(a.len(), 1000);
        assert_eq!(a, sequence(kind, 1000, 1).unwrap());
        assert_ne!(a, sequence(kind, 1000, 2).unwrap(), "{kind}");
    }
    let random = sequence(SequenceKind::Random, 1000, 4).unwrap();
    assert!(random.iter().all(|k| k.abs() <= RANDOM_KEY_BOUND));
    assert!(random.iter().any(|&k| k < -(1 << 50)) && random.iter().any(|&k| k > 1 << 50));

    let sorted = sequence(SequenceKind::Sorted, 1000, 4).unwrap();
    assert!(sorted.windows(2).all(|w| w[0] < w[1]));
    assert!(sorted.iter().all(|k| k.abs() <= RANDOM_KEY_BOUND));
    let reversed = sequence(SequenceKind::Reversed, 1000, 4).unwrap();
    assert!(reversed.windows(2).all(|w| w[0] > w[1]));
    assert_eq!(reversed.iter().rev().copied().collect::<Vec<_>>(), sorted);

    let few = sequence(SequenceKind::FewDistinct, 1000, 4).unwrap();
    let values: HashSet<i64> = few.iter().copied().collect();
    assert_eq!(values.len(), 8);
    assert!(values.iter().all(|k| k.abs() <= RANDOM_KEY_BOUND));
    let small: HashSet<i64> = sequence(SequenceKind::FewDistinct, 5, 4)
        .unwrap()
        .into_iter()
        .collect();
    assert!(
        small.is_subset(&values),
        "the value set depends on the seed only"
    );
}

#[test]
fn float_keys_mix_signs_and_magnitudes() {
    let keys = sequence_f64(5000, 12).unwrap();
    let bits_of = |v: &[f64]| v.iter().map(|k| k.to_bits()).collect::<Vec<_>>();
    assert_eq!(bits_of(&keys), bits_of(&sequence_f64(5000, 12).unwrap()));
    assert_ne!(bits_of(&keys), bits_of(&sequence_f64(5000, 13).unwrap()));
    assert!(keys
        .iter()
        .all(|k| k.is_normal() && (2f64.powi(-64)..2f64.powi(64)).contains(&k.abs())));
    assert!(keys.iter().any(|&k| k < 0.0) && keys.iter().any(|&k| k > 0.0));
    assert!(keys.iter().any(|k| k.abs() < 1e-15) && keys.iter().any(|k| k.abs() > 1e15));
}

// ---------------------------------------------------------------- properties

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn cocircular_holds_for_any_seed_and_size(n in 0usize..400, seed in any::<u64>()) {
        let pts = points(PointKind::Cocircular, n, seed).unwrap();
        prop_assert_eq!(pts.len(), n);
        check_cocircular(&pts);
    }

    #[test]
    fn collinear_holds_for_any_seed(n in 3usize..300, seed in any::<u64>()) {
        let pts = points(PointKind::Collinear, n, seed).unwrap();
        prop_assert!(pts.iter().all(|&q| orient2d(pts[0], pts[1], q) == Orientation::Collinear));
    }

    #[test]
    fn random_graphs_are_simple_for_any_seed(n in 2usize..60, frac in 0.0f64..=1.0, seed in any::<u64>()) {
        let m = ((n * (n - 1) / 2) as f64 * frac) as usize;
        let g = graph(GraphKind::Gnm, n, m, seed).unwrap();
        prop_assert_eq!(g.edges.len(), m);
        check_simple(&g);
        let t = graph(GraphKind::Tree, n, 0, seed).unwrap();
        prop_assert_eq!(t.edges.len(), n - 1);
        prop_assert_eq!(components(&t), 1);
    }
}
