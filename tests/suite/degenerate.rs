//! The degenerate-input policy of `docs/design.md`, row by row: what every geometric
//! algorithm returns for no points, one point, two points, copies of one point and collinear
//! points. Structures (hulls, triangulations, Voronoi diagrams, antipodal pairs, spanning
//! trees) exist for every input; answers that need k points (a diameter, a closest pair, a
//! nearest neighbour, an empty circle) are `Error::TooFew` below k.

use compgeo::calipers::{diameter, ConvexPolygon, DiameterAlgorithm};
use compgeo::delaunay::{triangulate, voronoi, Algorithm as Builder};
use compgeo::geometry::{Point2, PointSet, WideFloat};
use compgeo::hull::{convex_hull, Algorithm as Hull, HullOptions};
use compgeo::proximity::{
    all_nearest_neighbours, closest_pair, euclidean_mst, largest_empty_circle, nearest,
    ClosestPairAlgorithm,
};
use compgeo::Error;

const STRICT: HullOptions = HullOptions {
    keep_collinear: false,
};
const KEEP: HullOptions = HullOptions {
    keep_collinear: true,
};

fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
    v.iter().map(|&p| Point2::from(p)).collect()
}

/// Whether `r` is `Error::TooFew` asking for `needed` points.
fn too_few<T: std::fmt::Debug>(r: compgeo::Result<T>, needed: usize) -> bool {
    matches!(r, Err(Error::TooFew { needed: n, .. }) if n == needed)
}

/// Every hull algorithm, strict and keeping collinear points.
fn hulls(p: &[Point2], strict: &[usize], keep: &[usize]) {
    for a in Hull::ALL {
        assert_eq!(convex_hull(p, a, STRICT).unwrap(), strict, "{a}");
        assert_eq!(convex_hull(p, a, KEEP).unwrap(), keep, "{a} keep_collinear");
    }
}

/// Every Delaunay builder: no triangles, `hull`, `duplicates`.
fn no_triangles(p: &[Point2], hull: &[usize], duplicates: &[[usize; 2]]) {
    for b in Builder::ALL {
        let t = triangulate(p, b).unwrap();
        assert_eq!(t.triangle_count(), 0, "{b}");
        assert_eq!(t.hull, hull, "{b}");
        assert_eq!(t.duplicates, duplicates, "{b}");
    }
}

/// Every closest-pair algorithm gives `pair` (any of `ties`) at `distance`.
fn closest(p: &[Point2], ties: &[[usize; 2]], distance: f64) {
    for a in ClosestPairAlgorithm::ALL {
        let c = closest_pair(p, a).unwrap();
        assert!(ties.contains(&c.pair), "{a}: {:?}", c.pair);
        assert_eq!(c.distance, distance, "{a}");
    }
}

/// Every diameter algorithm gives `pair` at `distance`.
fn diameters(p: &[Point2], pair: [usize; 2], distance: f64) {
    for a in DiameterAlgorithm::ALL {
        let d = diameter(p, a).unwrap();
        assert_eq!(
            (d.pair, d.distance),
            (pair, WideFloat::from(distance)),
            "{a}"
        );
    }
}

/// The calipers on the hull: antipodal pairs, and width and area 0 (every degenerate hull).
fn flat_calipers(p: &[Point2], antipodal: &[[usize; 2]]) {
    let set = PointSet::new(p).unwrap();
    let hull = ConvexPolygon::hull(&set);
    assert_eq!(hull.antipodal_pairs(), antipodal);
    assert_eq!(hull.width().unwrap().width, 0.0);
    assert_eq!(hull.min_area_rectangle().unwrap().area, 0.0);
}

#[test]
fn no_points() {
    let p = pts(&[]);
    hulls(&p, &[], &[]);
    no_triangles(&p, &[], &[]);
    assert_eq!(voronoi(&p).unwrap().cell_count(), 0);
    let hull = ConvexPolygon::hull(&PointSet::new(&p).unwrap());
    assert!(hull.antipodal_pairs().is_empty());
    assert!(too_few(hull.width(), 1) && too_few(hull.min_area_rectangle(), 1));
    for a in DiameterAlgorithm::ALL {
        assert!(too_few(diameter(&p, a), 1), "{a}");
    }
    for a in ClosestPairAlgorithm::ALL {
        assert!(too_few(closest_pair(&p, a), 2), "{a}");
    }
    assert!(too_few(all_nearest_neighbours(&p), 2));
    assert!(too_few(nearest(&p, Point2::new(0.0, 0.0)), 1));
    let t = euclidean_mst(&p).unwrap();
    assert_eq!(
        (t.edges.len(), t.weight, t.components),
        (0, WideFloat::ZERO, 0)
    );
    assert_eq!(
        t.weight.to_f64().map(f64::to_bits),
        Some(0),
        "an empty sum is +0.0"
    );
    assert!(too_few(largest_empty_circle(&p), 1));
}

#[test]
fn one_point() {
    let p = pts(&[(2.0, 3.0)]);
    hulls(&p, &[0], &[0]);
    no_triangles(&p, &[0], &[]);
    let v = voronoi(&p).unwrap();
    assert_eq!(v.cell_count(), 1);
    let cell = v.cell(0);
    assert!(!cell.bounded && cell.vertices.is_empty() && cell.rays.is_empty());
    flat_calipers(&p, &[]);
    diameters(&p, [0, 0], 0.0);
    for a in ClosestPairAlgorithm::ALL {
        assert!(too_few(closest_pair(&p, a), 2), "{a}");
    }
    assert!(too_few(all_nearest_neighbours(&p), 2));
    assert_eq!(nearest(&p, Point2::new(-9.0, 1e9)).unwrap(), 0);
    let t = euclidean_mst(&p).unwrap();
    assert_eq!(
        (t.edges.len(), t.weight, t.components),
        (0, WideFloat::ZERO, 1)
    );
    let c = largest_empty_circle(&p).unwrap();
    assert_eq!(
        (c.centre, c.radius, c.sites),
        (p[0], WideFloat::ZERO, vec![0])
    );
}

#[test]
fn two_points() {
    let p = pts(&[(2.0, 3.0), (5.0, -1.0)]);
    hulls(&p, &[0, 1], &[0, 1]);
    no_triangles(&p, &[0, 1], &[]);
    let v = voronoi(&p).unwrap();
    assert_eq!(v.cell_count(), 2);
    assert!(v.vertices.is_empty() && v.cells().all(|c| !c.bounded && c.rays.len() == 2));
    flat_calipers(&p, &[[0, 1]]);
    diameters(&p, [0, 1], 5.0);
    closest(&p, &[[0, 1]], 5.0);
    assert_eq!(all_nearest_neighbours(&p).unwrap(), [1, 0]);
    assert_eq!(nearest(&p, Point2::new(5.0, 0.0)).unwrap(), 1);
    let t = euclidean_mst(&p).unwrap();
    assert_eq!(
        (t.edges, t.weight, t.components),
        (vec![[0, 1]], 5.0.into(), 1)
    );
    let c = largest_empty_circle(&p).unwrap();
    assert_eq!((c.centre, c.radius), (Point2::new(3.5, 1.0), 2.5.into()));
}

#[test]
fn copies_of_one_point() {
    let p = pts(&[(1.0, 1.0), (1.0, 1.0), (1.0, 1.0)]);
    hulls(&p, &[0], &[0]);
    no_triangles(&p, &[0], &[[1, 0], [2, 0]]);
    let v = voronoi(&p).unwrap();
    assert_eq!(v.cell_count(), 1);
    assert_eq!((0..3).map(|i| v.cell_of(i)).collect::<Vec<_>>(), [0, 0, 0]);
    flat_calipers(&p, &[]);
    diameters(&p, [0, 1], 0.0);
    closest(&p, &[[0, 1]], 0.0);
    assert_eq!(all_nearest_neighbours(&p).unwrap(), [1, 0, 0]);
    assert_eq!(nearest(&p, Point2::new(7.0, 7.0)).unwrap(), 0);
    let t = euclidean_mst(&p).unwrap();
    assert_eq!(
        (t.edges, t.weight, t.components),
        (vec![[0, 1], [0, 2]], WideFloat::ZERO, 1)
    );
    let c = largest_empty_circle(&p).unwrap();
    assert_eq!((c.centre, c.radius), (p[0], WideFloat::ZERO));
}

#[test]
fn collinear_points() {
    // On the line y = x, out of order: lexicographically 0, 2, 1, 3.
    let p = pts(&[(0.0, 0.0), (2.0, 2.0), (1.0, 1.0), (3.0, 3.0)]);
    hulls(&p, &[0, 3], &[0, 2, 1, 3]);
    no_triangles(&p, &[0, 2, 1, 3], &[]);
    let v = voronoi(&p).unwrap();
    assert_eq!(v.cell_count(), 4);
    assert!(v.vertices.is_empty() && v.cells().all(|c| !c.bounded));
    flat_calipers(&p, &[[0, 3]]);
    diameters(&p, [0, 3], 18f64.sqrt());
    let gap = 2f64.sqrt();
    closest(&p, &[[0, 2], [1, 2], [1, 3]], gap);
    let nn = all_nearest_neighbours(&p).unwrap();
    assert_eq!((nn[0], nn[3]), (2, 1));
    assert!(nn[1] == 2 || nn[1] == 3);
    assert!(nn[2] == 0 || nn[2] == 1);
    assert_eq!(nearest(&p, Point2::new(2.9, 3.5)).unwrap(), 3);
    let t = euclidean_mst(&p).unwrap();
    assert_eq!(t.edges.len(), 3);
    assert!((t.weight.to_f64().unwrap() - 3.0 * gap).abs() < 1e-15);
    let c = largest_empty_circle(&p).unwrap();
    assert_eq!(c.sites, [0, 2], "the first of the widest gaps");
    assert_eq!(
        (c.centre, c.radius),
        (Point2::new(0.5, 0.5), (gap / 2.0).into())
    );
}
