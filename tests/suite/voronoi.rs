//! The Voronoi diagram: one cell per distinct site, bounded exactly when the site is not on
//! the hull, vertices equidistant from their three sites within a stated tolerance, cells
//! counter-clockwise, clipped cells tiling the box and nearest to their own site; degenerate
//! input, bad input and the CLI.

#[cfg(feature = "cli")]
use crate::common::{assert_rejected, run_json};
use compgeo::delaunay::{
    dual, find_duplicates, incremental, voronoi, ClipBox, Triangulation, Voronoi,
};
use compgeo::gen::{points, PointKind};
use compgeo::geometry::Point2;
use compgeo::hull::{monotone_chain, HullOptions};
use compgeo::Error;
use proptest::prelude::*;
use std::f64::consts::PI;

fn dist(a: Point2, b: Point2) -> f64 {
    (a.x - b.x).hypot(a.y - b.y)
}

/// The structural properties of the diagram of `pts`, all decided independently of it.
fn check_structure(pts: &[Point2], v: &Voronoi) {
    check_structure_of(pts, v, None);
}

/// [`check_structure`]; with the triangulation the diagram is the dual of, also the
/// counter-clockwise order of every cell from the triangles around its site.
fn check_structure_of(pts: &[Point2], v: &Voronoi, t: Option<&Triangulation>) {
    let dups = find_duplicates(pts);
    assert_eq!(v.cell_count(), pts.len() - dups.len());
    for &[dropped, kept] in &dups {
        assert_eq!(v.cell_of(dropped), v.cell_of(kept));
    }
    for k in 0..v.cell_count() {
        assert_eq!(v.cell_of(v.sites[k]), k);
    }
    // Theorem 2.32, against the hull module's exact keep-collinear hull.
    let hull = monotone_chain(
        pts,
        HullOptions {
            keep_collinear: true,
        },
    )
    .unwrap();
    let several = v.cell_count() > 1;
    for cell in v.cells() {
        let on_hull = hull.contains(&cell.site);
        assert_eq!(cell.bounded, several && !on_hull, "site {}", cell.site);
        assert_eq!(cell.rays.is_empty(), cell.bounded || !several);
        if let Some(t) = t {
            check_fan(pts, cell, t);
            // The rounded vertices are in order too where their rounding error is far below
            // the cell's size.
            if cell
                .vertices
                .iter()
                .all(|&k| vertex_tolerance(pts, t, k) < 1e-6 * circumradius(pts, t, k))
            {
                check_ccw(pts[cell.site], cell, v);
            }
        } else {
            check_ccw(pts[cell.site], cell, v);
        }
    }
}

/// The cell's vertices are the triangles around its site in counter-clockwise order: each
/// next triangle is across the edge from the site to the previous one's vertex before the
/// site, and around an inner site the fan closes after exactly one turn (the angles of the
/// input points, each step below a half turn as the triangles are counter-clockwise).
fn check_fan(pts: &[Point2], cell: compgeo::delaunay::Cell<'_>, t: &Triangulation) {
    if cell.vertices.is_empty() {
        return;
    }
    let s = cell.site;
    let around = |k: usize| {
        let tri = t.triangle(k);
        let at = tri
            .iter()
            .position(|&x| x == s)
            .expect("the triangle holds the site");
        (tri[(at + 1) % 3], tri[(at + 2) % 3])
    };
    let ids = cell.vertices;
    let pairs = if cell.bounded {
        ids.len()
    } else {
        ids.len() - 1
    };
    let mut turn = 0.0;
    for i in 0..pairs {
        let (after, before) = around(ids[i]);
        let (next_after, _) = around(ids[(i + 1) % ids.len()]);
        assert_eq!(before, next_after, "cell of {s}: triangles out of order");
        let angle = |w: usize| (pts[w].y - pts[s].y).atan2(pts[w].x - pts[s].x);
        let mut d = angle(before) - angle(after);
        if d < 0.0 {
            d += 2.0 * PI;
        }
        turn += d;
    }
    if cell.bounded {
        assert!(
            (turn - 2.0 * PI).abs() < 1e-6,
            "the fan of {s} turns {turn}"
        );
    }
}

/// The bound on the rounding error of vertex k: `64 ε (κ R + m)` (see [`check_vertices`]).
fn vertex_tolerance(pts: &[Point2], t: &Triangulation, k: usize) -> f64 {
    let m = t
        .triangle(k)
        .iter()
        .map(|&i| pts[i].x.abs().max(pts[i].y.abs()))
        .fold(0.0, f64::max);
    64.0 * f64::EPSILON * (conditioning(pts, t, k) * circumradius(pts, t, k) + m)
}

/// The circumradius of triangle k, `abc / 4A` (computed on the triangle scaled by a power
/// of two, so that the products neither overflow nor underflow).
fn circumradius(pts: &[Point2], t: &Triangulation, k: usize) -> f64 {
    let ([a, b, c], s) = scaled_triangle(pts, t, k);
    let area = ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).abs() / 2.0;
    dist(a, b) * dist(b, c) * dist(c, a) / (4.0 * area) * s
}

/// Triangle k divided by a power of two `s` near its largest coordinate, and `s`.
fn scaled_triangle(pts: &[Point2], t: &Triangulation, k: usize) -> ([Point2; 3], f64) {
    let tri = t.triangle(k).map(|i| pts[i]);
    let m = tri
        .iter()
        .fold(0.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    let s = 2f64.powi(m.log2().floor().clamp(-1022.0, 1023.0) as i32);
    (tri.map(|p| Point2::new(p.x / s, p.y / s)), s)
}

/// κ = (product of the two shorter edges)/(2·area) = 1/sin θ for the largest angle θ, at
/// least 1: how much rounding the circumcentre amplifies (the construction works at the
/// vertex of that angle; κ is large only for flat triangles, not for two nearly coincident
/// vertices).
fn conditioning(pts: &[Point2], t: &Triangulation, k: usize) -> f64 {
    let ([a, b, c], _) = scaled_triangle(pts, t, k);
    let mut sides = [dist(a, b), dist(b, c), dist(c, a)];
    sides.sort_by(f64::total_cmp);
    let area = ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).abs() / 2.0;
    (sides[0] * sides[1] / (2.0 * area)).max(1.0)
}

/// The boundary winds counter-clockwise around the site, seen from it: the arriving ray's
/// direction, the vertices, the leaving ray's direction; every step turns left (or not at
/// all, for coincident vertices) and the steps, with the gap at infinity back to the
/// arriving ray, add up to one full turn. (Cells without vertices, of collinear sites, are
/// checked by their own test.)
fn check_ccw(site: Point2, cell: compgeo::delaunay::Cell<'_>, v: &Voronoi) {
    if cell.vertices.is_empty() {
        return;
    }
    let angle = |p: Point2| (p.y - site.y).atan2(p.x - site.x);
    let mut angles: Vec<f64> = Vec::new();
    if let Some(r) = cell.rays.first() {
        angles.push(r.direction.y.atan2(r.direction.x));
    }
    angles.extend(cell.vertices.iter().map(|&k| angle(v.vertices[k])));
    if let Some(r) = cell.rays.get(1) {
        angles.push(r.direction.y.atan2(r.direction.x));
    }
    // A step of half a turn (to within the rounding of the angles) is taken as
    // counter-clockwise: near-duplicate sites have cells a few ulps wide whose edges pass
    // through the site at this precision.
    let step = |a: f64, b: f64| {
        let mut d = b - a;
        while d <= -PI + 1e-6 {
            d += 2.0 * PI;
        }
        while d > PI + 1e-6 {
            d -= 2.0 * PI;
        }
        d
    };
    let mut total = 0.0;
    for k in 0..angles.len() {
        let d = step(angles[k], angles[(k + 1) % angles.len()]);
        assert!(d >= -1e-9, "a clockwise step of {d} around {site:?}");
        total += d;
    }
    assert!(
        (total - 2.0 * PI).abs() < 1e-6,
        "the boundary winds {total} around {site:?}"
    );
}

/// Each Voronoi vertex is equidistant from its triangle's three sites up to
/// `64 ε (κ R + m)` with R the circumradius, κ ≥ 1 the conditioning of the circumcentre
/// ([`conditioning`], large for flat triangles) and m the largest
/// coordinate magnitude of the triangle (the centre is rounded at that scale).
fn check_vertices(pts: &[Point2]) {
    let t = incremental(pts).unwrap();
    let v = dual(pts, &t).unwrap();
    assert_eq!(v.vertices.len(), t.triangle_count());
    for k in 0..t.triangle_count() {
        let [a, b, c] = t.triangle(k).map(|i| pts[i]);
        let x = v.vertices[k];
        let (da, db, dc) = (dist(x, a), dist(x, b), dist(x, c));
        let r = da.max(db).max(dc);
        let kappa = conditioning(pts, &t, k);
        let m = [a, b, c]
            .iter()
            .map(|p| p.x.abs().max(p.y.abs()))
            .fold(0.0, f64::max);
        let tol = 64.0 * f64::EPSILON * (kappa * r + m);
        let spread = da.max(db).max(dc) - da.min(db).min(dc);
        assert!(
            spread <= tol,
            "vertex {k}: distances {da}, {db}, {dc} (tolerance {tol})"
        );
    }
    check_structure_of(pts, &v, Some(&t));
}

/// Clipped cells tile the box (areas add up) and every clipped vertex is nearest to its
/// own site (brute force), up to rounding: relative 1e-9 of the box, plus a few units in
/// the last place of its coordinates' magnitude (the constructions are rounded there, which
/// matters for boxes only a few ulps wide, around near-duplicates).
fn check_clip(pts: &[Point2], bounds: &ClipBox) {
    let v = voronoi(pts).unwrap();
    let cells = v.clip(bounds);
    let size = (bounds.max.x - bounds.min.x).max(bounds.max.y - bounds.min.y);
    let box_area = (bounds.max.x - bounds.min.x) * (bounds.max.y - bounds.min.y);
    let mag = [bounds.min.x, bounds.min.y, bounds.max.x, bounds.max.y]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let slack = 64.0 * f64::EPSILON * mag;
    let mut total = 0.0;
    assert_eq!(cells.len(), v.cell_count());
    for (k, poly) in cells.iter().enumerate() {
        // The view on the diagram and the single cell's clip agree, point by point.
        let poly = poly.to_vec();
        assert_eq!(poly, v.clip_cell(k, bounds), "cell {k}");
        let a = area(&poly);
        assert!(
            a >= -(1e-12 * box_area + slack * size),
            "cell {k} is clockwise"
        );
        total += a;
        let site = pts[v.sites[k]];
        for &q in &poly {
            assert!(q.x >= bounds.min.x && q.x <= bounds.max.x);
            assert!(q.y >= bounds.min.y && q.y <= bounds.max.y);
            let own = dist(q, site);
            let best = pts
                .iter()
                .map(|&p| dist(q, p))
                .fold(f64::INFINITY, f64::min);
            assert!(
                own <= best + 1e-9 * size + slack,
                "{q:?} is nearer to another site than {k}"
            );
        }
    }
    assert!(
        (total - box_area).abs() <= 1e-9 * box_area + slack * size * cells.len() as f64,
        "cells cover {total} of {box_area}"
    );
}

/// The signed area (shoelace formula relative to the first vertex, so coordinates far
/// from the origin do not cancel).
fn area(poly: &[Point2]) -> f64 {
    let Some(&o) = poly.first() else {
        return 0.0;
    };
    (0..poly.len())
        .map(|i| {
            let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
            (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x)
        })
        .sum::<f64>()
        / 2.0
}

#[test]
fn every_generator_kind_gives_a_consistent_diagram() {
    for kind in PointKind::ALL {
        for n in [1, 2, 3, 4, 7, 30, 300] {
            for seed in 0..2 {
                let pts = points(kind, n, seed).unwrap();
                check_vertices(&pts);
                let general = [
                    PointKind::UniformSquare,
                    PointKind::UniformDisk,
                    PointKind::Gaussian,
                    PointKind::Clustered,
                ];
                if general.contains(&kind) {
                    check_relabelling(&pts);
                }
            }
        }
    }
}

#[test]
fn clipped_cells_tile_the_box() {
    for kind in [
        PointKind::UniformSquare,
        PointKind::Clustered,
        PointKind::Grid,
        PointKind::Cocircular,
        PointKind::Collinear,
        PointKind::NearDuplicates,
    ] {
        for n in [1, 2, 3, 10, 100] {
            let pts = points(kind, n, 4).unwrap();
            check_clip(&pts, &ClipBox::around(&crate::common::set(&pts)).unwrap());
        }
    }
    // A box far smaller than the diagram, and one far larger.
    let pts = points(PointKind::UniformSquare, 50, 8).unwrap();
    check_clip(&pts, &ClipBox::new(0.4, 0.4, 0.41, 0.42).unwrap());
    check_clip(&pts, &ClipBox::new(-1e6, -1e6, 1e6, 1e6).unwrap());
}

#[test]
fn collinear_sites_give_strips_and_two_half_planes() {
    let pts: Vec<Point2> = [(4.0, 4.0), (0.0, 0.0), (1.0, 1.0), (3.0, 3.0)]
        .map(Point2::from)
        .to_vec();
    let v = voronoi(&pts).unwrap();
    assert!(v.vertices.is_empty());
    for cell in v.cells() {
        let end = cell.site == 0 || cell.site == 1;
        assert_eq!(cell.rays.len(), if end { 2 } else { 4 });
        for r in cell.rays {
            // Each ray is perpendicular to the line and starts at a midpoint.
            assert_eq!(r.direction.x, -r.direction.y);
            assert_eq!(r.origin.x, r.origin.y);
        }
    }
    check_structure(&pts, &v);
    check_clip(&pts, &ClipBox::new(-1.0, -2.0, 5.0, 6.0).unwrap());
    // The strip of (1, 1) lies between the bisectors x + y = 1 and x + y = 4.
    let b = ClipBox::new(-1.0, -1.0, 5.0, 5.0).unwrap();
    let strip = v.clip_cell(v.cell_of(2), &b);
    assert!((area(&strip) - 13.5).abs() < 1e-12);
}

#[test]
fn one_and_two_sites() {
    let one = [Point2::new(3.0, -1.0), Point2::new(3.0, -1.0)];
    let v = voronoi(&one).unwrap();
    assert_eq!(v.cell_count(), 1);
    let c = v.cell(0);
    assert!(!c.bounded && c.rays.is_empty() && c.vertices.is_empty());
    let b = ClipBox::new(0.0, 0.0, 1.0, 1.0).unwrap();
    assert_eq!(area(&v.clip_cell(0, &b)), 1.0);
    let two = [Point2::new(0.0, 0.0), Point2::new(0.0, 2.0)];
    let v = voronoi(&two).unwrap();
    check_structure(&two, &v);
    let b = ClipBox::new(-1.0, -1.0, 1.0, 3.0).unwrap();
    assert_eq!(area(&v.clip_cell(0, &b)), 4.0);
    assert_eq!(area(&v.clip_cell(1, &b)), 4.0);
}

#[test]
fn cocircular_sites_share_their_vertex() {
    // Eight lattice points on the circle x² + y² = 25 and its centre.
    let mut pts: Vec<Point2> = [
        (5, 0),
        (3, 4),
        (0, 5),
        (-4, 3),
        (-5, 0),
        (-3, -4),
        (0, -5),
        (4, -3),
    ]
    .map(|(x, y)| Point2::new(x as f64, y as f64))
    .to_vec();
    check_vertices(&pts);
    let v = voronoi(&pts).unwrap();
    assert!(v.vertices.iter().all(|&c| c == Point2::new(0.0, 0.0)));
    pts.push(Point2::new(0.0, 0.0));
    check_vertices(&pts);
    check_clip(&pts, &ClipBox::new(-6.0, -6.0, 6.0, 6.0).unwrap());
}

#[test]
fn huge_tiny_and_mixed_magnitudes() {
    let sub = 5e-324;
    let sets: [Vec<(f64, f64)>; 3] = [
        vec![(1e300, 1e300), (-1e300, 2e300), (3e300, -1e300), (0.0, 0.0)],
        vec![
            (0.0, 0.0),
            (3.0 * sub, 0.0),
            (0.0, 4.0 * sub),
            (7.0 * sub, 9.0 * sub),
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
        let v = voronoi(&pts).unwrap();
        check_structure(&pts, &v);
        assert!(v.vertices.iter().all(|p| p.is_finite()));
    }
    // Subnormal sites: the vertices are exact here (power-of-two scaling).
    let pts: Vec<Point2> = [(0.0, 0.0), (4.0 * sub, 0.0), (0.0, 2.0 * sub)]
        .map(Point2::from)
        .to_vec();
    assert_eq!(
        voronoi(&pts).unwrap().vertices,
        [Point2::new(2.0 * sub, sub)]
    );
}

#[test]
fn bad_input_is_an_error() {
    assert_eq!(voronoi(&[]).unwrap().cell_count(), 0);
    let nan = [Point2::new(0.0, 0.0), Point2::new(1.0, f64::NAN)];
    assert!(matches!(
        voronoi(&nan),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(ClipBox::new(1.0, 0.0, 0.0, 1.0).is_err());
    assert!(ClipBox::new(0.0, 0.0, f64::INFINITY, 1.0).is_err());
    assert!(matches!(
        ClipBox::around(&crate::common::set(&[])),
        Err(Error::TooFew { .. })
    ));
}

#[cfg(feature = "cli")]
#[test]
fn cli_prints_cells_and_clipped_cells() {
    let input = "[[0,0],[2,0],[2,2],[0,2],[1,1],[1,1]]";
    let v = run_json(&["voronoi", "-"], Some(input));
    let cells = v["cells"].as_array().unwrap();
    assert_eq!(cells.len(), 5);
    let cell_of = |i: usize| v["cell_of"][i].as_u64().unwrap() as usize;
    assert_eq!(cell_of(5), cell_of(4));
    let centre = &cells[cell_of(4)];
    assert_eq!(centre["site"], 4);
    assert_eq!(centre["bounded"], true);
    assert_eq!(centre["vertices"].as_array().unwrap().len(), 4);
    assert_eq!(cells[cell_of(0)]["rays"].as_array().unwrap().len(), 2);

    let v = run_json(&["voronoi", "--clip", "0,0,2,2", "-"], Some(input));
    let vertices = v["vertices"].as_array().unwrap();
    let poly = |site: usize| -> Vec<Point2> {
        let k = v["cell_of"][site].as_u64().unwrap() as usize;
        v["cells"][k]["vertices"]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| {
                let p = &vertices[i.as_u64().unwrap() as usize];
                Point2::new(p[0].as_f64().unwrap(), p[1].as_f64().unwrap())
            })
            .collect()
    };
    assert_eq!(area(&poly(4)), 2.0);
    assert_eq!(area(&poly(0)), 0.5);
    // Negative coordinates are values, not flags.
    let v = run_json(&["voronoi", "--clip", "-1,-1,3,3", "-"], Some(input));
    assert_eq!(v["clip"], serde_json::json!([-1.0, -1.0, 3.0, 3.0]));
    let v = run_json(&["voronoi", "--clip", "auto", "-"], Some(input));
    assert_eq!(v["clip"], serde_json::json!([-0.5, -0.5, 2.5, 2.5]));

    assert_rejected(&["voronoi", "--clip", "0,0,0,2", "-"], Some(input));
    assert_rejected(&["voronoi", "--clip", "0,0,2", "-"], Some(input));
    let err = assert_rejected(&["voronoi", "-"], Some("[[0,0],[1,NaN]]"));
    assert!(err.contains("point 1"), "{err}");
    // No sites, no cells; clipping needs a site to size the box by.
    let v = run_json(&["voronoi", "-"], Some("[]"));
    assert_eq!(v["cells"], serde_json::json!([]));
    assert!(
        assert_rejected(&["voronoi", "--clip", "auto", "-"], Some("[]")).contains("at least 1")
    );
}

/// `voronoi` (built from the incremental builder's own numbering, in insertion order) and
/// the dual of the triangulation in input numbering give every site the same cell: the same vertices in
/// the same cyclic order, bit for bit, and the same rays.
fn check_relabelling(pts: &[Point2]) {
    let a = voronoi(pts).unwrap();
    let b = dual(pts, &incremental(pts).unwrap()).unwrap();
    assert_eq!(a.cell_count(), b.cell_count());
    for i in 0..pts.len() {
        let (ca, cb) = (a.cell(a.cell_of(i)), b.cell(b.cell_of(i)));
        assert_eq!(ca.site, cb.site);
        assert_eq!(ca.bounded, cb.bounded);
        assert_eq!(ca.rays, cb.rays);
        let va: Vec<Point2> = ca.vertices.iter().map(|&k| a.vertices[k]).collect();
        let mut vb: Vec<Point2> = cb.vertices.iter().map(|&k| b.vertices[k]).collect();
        if !ca.bounded || va.is_empty() {
            assert_eq!(va, vb);
        } else {
            let shift = vb.iter().position(|&p| p == va[0]).expect("same vertices");
            vb.rotate_left(shift);
            assert_eq!(va, vb);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn integer_points_with_cocircular_quadruples(
        pts in prop::collection::vec((-8i32..8, -8i32..8), 1..50)
    ) {
        let pts: Vec<Point2> = pts.into_iter().map(|(x, y)| Point2::new(x as f64, y as f64)).collect();
        check_vertices(&pts);
        // Duplicates and cocircular sites: `voronoi` (built from the builder's own
        // numbering) against the dual of the input-numbered triangulation.
        check_structure(&pts, &voronoi(&pts).unwrap());
        check_relabelling(&pts);
        check_clip(&pts, &ClipBox::new(-10.0, -10.0, 10.0, 10.0).unwrap());
    }

    #[test]
    fn random_points(pts in prop::collection::vec((-1e3f64..1e3, -1e3f64..1e3), 1..60)) {
        let pts: Vec<Point2> = pts.into_iter().map(Point2::from).collect();
        check_vertices(&pts);
        check_relabelling(&pts);
        check_clip(&pts, &ClipBox::around(&crate::common::set(&pts)).unwrap());
    }
}

#[test]
fn dual_refuses_a_triangulation_that_is_not_one_of_its_points() {
    use compgeo::delaunay::{check_delaunay, lawson, Triangulation};
    use compgeo::geometry::PointSet;
    let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (1.0, 1.0)].map(Point2::from);
    let more = [
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 3.0),
        (0.0, 3.0),
        (1.0, 1.0),
        (3.0, 2.0),
        (2.0, 2.5),
    ]
    .map(Point2::from);
    let fewer = &pts[..4];
    let good = incremental(&pts).unwrap();
    assert!(dual(&pts, &good).is_ok());
    // Another builder's triangulation of the same points: the same vertices, in its order.
    let sorted = |v: compgeo::delaunay::Voronoi| {
        let mut xs: Vec<(f64, f64)> = v.vertices.iter().map(|p| (p.x, p.y)).collect();
        xs.sort_by(|a, b| a.partial_cmp(b).unwrap());
        xs
    };
    assert_eq!(
        sorted(dual(&pts, &lawson(&pts).unwrap()).unwrap()),
        sorted(dual(&pts, &good).unwrap())
    );
    // More points (indices out of range), fewer points, a broken array, a reversed hull, a
    // triangulation that is not Delaunay: each a named error, never a panic.
    let mut broken = good.clone();
    broken.halfedges.pop();
    let mut wrong_hull = incremental(fewer).unwrap();
    wrong_hull.hull.reverse();
    let kite = [(0.0, 0.0), (2.0, 0.0), (1.5, 1.0), (0.0, 1.0)].map(Point2::from);
    let not_delaunay = Triangulation::from_triangles(
        &PointSet::new(&kite).unwrap(),
        &[[0, 1, 3], [1, 2, 3]],
        Vec::new(),
    )
    .unwrap();
    let cases: [(&[Point2], Triangulation); 5] = [
        (&pts, incremental(&more).unwrap()),
        (&pts, incremental(fewer).unwrap()),
        (&pts, broken),
        (fewer, wrong_hull),
        (&kite, not_delaunay),
    ];
    for (against, t) in &cases {
        let err = dual(against, t).unwrap_err();
        assert!(check_delaunay(against, t).is_err());
        match err {
            compgeo::Error::InvalidParameter { name, reason } => {
                assert_eq!(name, "triangulation");
                assert!(!reason.is_empty());
            }
            other => panic!("{other:?}"),
        }
    }
}
