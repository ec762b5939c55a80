//! Clipped Voronoi cells against an exact oracle: the box cut by the bisector of the site and
//! *every* other site (not only its Delaunay neighbours), in rational arithmetic. The
//! clipper must give the same polygon, each point within the construction's error of the
//! oracle's, the points on a box side with that side's coordinate exactly, and nothing where
//! the oracle has no area. Inputs: nearly collinear sites, lattices (cocircular and
//! collinear), mixed magnitudes from 1e-300 to 1e300, boxes from a few ulps wide to the
//! whole range of `f64`.

#[cfg(feature = "cli")]
use crate::common::run_json;
use crate::common::set;
use compgeo::delaunay::{voronoi, ClipBox};
use compgeo::geometry::Point2;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};
use proptest::prelude::*;

type Q = BigRational;

fn q(v: f64) -> Q {
    Q::from_float(v).expect("finite")
}

/// Cell of `pts[s]` in `bounds`, exactly: Sutherland–Hodgman on the box against every
/// bisector, keeping points on a line. Empty when the polygon has no area.
fn oracle_cell(pts: &[Point2], s: usize, bounds: &ClipBox) -> Vec<[Q; 2]> {
    let (x0, y0, x1, y1) = (
        q(bounds.min.x),
        q(bounds.min.y),
        q(bounds.max.x),
        q(bounds.max.y),
    );
    let mut poly = vec![
        [x0.clone(), y0.clone()],
        [x1.clone(), y0],
        [x1, y1.clone()],
        [x0, y1],
    ];
    let site = [q(pts[s].x), q(pts[s].y)];
    for (t, p) in pts.iter().enumerate() {
        let other = [q(p.x), q(p.y)];
        if t == s || other == site {
            continue;
        }
        // Kept: 2 p · (t − s) ≤ |t|² − |s|², as f(p) = |t|² − |s|² − 2 p · (t − s) ≥ 0.
        let d = [&other[0] - &site[0], &other[1] - &site[1]];
        let rhs = &other[0] * &other[0] + &other[1] * &other[1]
            - &site[0] * &site[0]
            - &site[1] * &site[1];
        let f =
            |v: &[Q; 2]| rhs.clone() - (&v[0] * &d[0] + &v[1] * &d[1]) * Q::from_integer(2.into());
        let vals: Vec<Q> = poly.iter().map(f).collect();
        let mut next = Vec::new();
        for i in 0..poly.len() {
            let j = (i + 1) % poly.len();
            let (fu, fv) = (&vals[i], &vals[j]);
            if *fu >= Q::zero() {
                next.push(poly[i].clone());
            }
            if (*fu > Q::zero() && *fv < Q::zero()) || (*fu < Q::zero() && *fv > Q::zero()) {
                let t = fu / (fu - fv);
                next.push([
                    &poly[i][0] + (&poly[j][0] - &poly[i][0]) * &t,
                    &poly[i][1] + (&poly[j][1] - &poly[i][1]) * &t,
                ]);
            }
        }
        poly = next;
    }
    poly.dedup();
    while poly.len() > 1 && poly.first() == poly.last() {
        poly.pop();
    }
    let twice_area = (0..poly.len()).fold(Q::zero(), |a, i| {
        let (p, r) = (&poly[i], &poly[(i + 1) % poly.len()]);
        a + &p[0] * &r[1] - &p[1] * &r[0]
    });
    if twice_area.is_zero() {
        poly.clear();
    }
    poly
}

/// The clipper's cells against the oracle's, cell by cell.
fn check_against_oracle(pts: &[Point2], bounds: &ClipBox) {
    let v = voronoi(pts).unwrap();
    let sides = [bounds.min.x, bounds.min.y, bounds.max.x, bounds.max.y];
    let approx = |poly: &[[Q; 2]]| -> Vec<(f64, f64)> {
        poly.iter()
            .map(|e| (e[0].to_f64().unwrap(), e[1].to_f64().unwrap()))
            .collect()
    };
    for k in 0..v.cell_count() {
        let ours = v.clip_cell(k, bounds);
        let exact = oracle_cell(pts, v.sites[k], bounds);
        if ours.is_empty() && !exact.is_empty() {
            // A sliver whose points round to fewer than three distinct ones is dropped:
            // allowed only when the exact polygon is within a few roundings of a segment.
            let a = approx(&exact);
            assert!(
                thin(&a),
                "cell {k} of {pts:?} in {sides:?}: empty against {a:?}"
            );
            continue;
        }
        assert_eq!(
            ours.is_empty(),
            exact.is_empty(),
            "cell {k} of {pts:?} in {sides:?}: {ours:?} against {:?}",
            approx(&exact)
        );
        let close = |p: Point2, e: &[Q; 2]| {
            let (ex, ey) = (e[0].to_f64().unwrap(), e[1].to_f64().unwrap());
            // Rounded twice at most (the oracle's to_f64 and the construction).
            let tol = 2f64.powi(-46) * ex.abs().max(ey.abs()) + 4.0 * f64::from_bits(1);
            let on_side = [&bounds.min.x, &bounds.max.x, &bounds.min.y, &bounds.max.y]
                .iter()
                .zip([&e[0], &e[0], &e[1], &e[1]])
                .any(|(&&side, v)| *v == q(side));
            let own = |a: f64, b: f64| {
                (a - b).abs() <= 2f64.powi(-46) * b.abs() + 4.0 * f64::from_bits(1)
            };
            if on_side {
                // A point on a side: each coordinate relative to itself (the side's exact).
                own(p.x, ex) && own(p.y, ey)
            } else {
                (p.x - ex).abs() <= tol && (p.y - ey).abs() <= tol
            }
        };
        for p in &ours {
            assert!(
                exact.iter().any(|e| close(*p, e)),
                "cell {k} of {pts:?} in {sides:?}: {p:?} is not a vertex of {:?}",
                approx(&exact)
            );
        }
        for e in &exact {
            assert!(
                ours.iter().any(|p| close(*p, e)),
                "cell {k} of {pts:?} in {sides:?}: misses {:?}, has {ours:?}",
                approx(std::slice::from_ref(e))
            );
        }
    }
}

/// Whether every point is within a few roundings (relative 2^-44 of the largest
/// coordinate) of the segment between the two farthest apart.
fn thin(points: &[(f64, f64)]) -> bool {
    let m = points
        .iter()
        .fold(0.0f64, |m, &(x, y)| m.max(x.abs()).max(y.abs()));
    if m == 0.0 {
        return true;
    }
    let p: Vec<(f64, f64)> = points.iter().map(|&(x, y)| (x / m, y / m)).collect();
    let far = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).hypot(a.1 - b.1);
    let (mut i, mut j) = (0, 0);
    for a in 0..p.len() {
        for b in 0..p.len() {
            if far(p[a], p[b]) > far(p[i], p[j]) {
                (i, j) = (a, b);
            }
        }
    }
    let (d, len) = ((p[j].0 - p[i].0, p[j].1 - p[i].1), far(p[i], p[j]));
    let tol = 2f64.powi(-44) + 16.0 * f64::from_bits(1) / m;
    p.iter()
        .all(|&r| len <= tol || ((r.0 - p[i].0) * d.1 - (r.1 - p[i].1) * d.0).abs() / len <= tol)
}

#[test]
fn nearly_collinear_sites_split_where_the_bisectors_are() {
    let pts = [(0.0, 0.0), (1.0, 1.0), (3.0, 3.0000000000000004)].map(Point2::from);
    let auto = ClipBox::around(&set(&pts)).unwrap();
    check_against_oracle(&pts, &auto);
    check_against_oracle(&pts, &ClipBox::new(-1e300, -1e300, 1e300, 1e300).unwrap());
    // A box far from every vertex, and one around the middle cell only.
    check_against_oracle(&pts, &ClipBox::new(1.9, 1.9, 2.1, 2.1).unwrap());
    let v = voronoi(&pts).unwrap();
    for p in v.clip_cell(v.cell_of(0), &auto) {
        assert!(p.x + p.y <= 1.0 + 1e-15, "{p:?}");
    }
    for p in v.clip_cell(v.cell_of(2), &auto) {
        assert!(p.x + p.y >= 4.0 - 1e-15, "{p:?}");
    }
}

#[test]
fn boxes_up_to_the_range_of_f64() {
    let pts = [(0.0, 0.0)].map(Point2::from);
    let v = voronoi(&pts).unwrap();
    let b = ClipBox::new(0.0, 0.0, 1.0, 1e308).unwrap();
    let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1e308), (0.0, 1e308)].map(Point2::from);
    assert_eq!(v.clip_cell(0, &b), corners);
    let full = ClipBox::new(-f64::MAX, -f64::MAX, f64::MAX, f64::MAX).unwrap();
    for pts in [
        vec![(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)],
        vec![(-1e308, -1e308), (1e308, 1e308), (1e308, -1e308)],
        vec![(0.0, 0.0), (1e-300, 0.0), (0.0, 1e-300), (1e300, 1e300)],
    ] {
        let pts: Vec<Point2> = pts.into_iter().map(Point2::from).collect();
        check_against_oracle(&pts, &full);
        check_against_oracle(&pts, &ClipBox::around(&set(&pts)).unwrap());
    }
}

#[test]
fn the_auto_box_is_never_flat() {
    for pts in [
        vec![(1e300, 0.0), (1e300, 1.0)],
        vec![(0.0, 1e300), (1.0, 1e300)],
        vec![(f64::MAX, f64::MAX), (f64::MAX, f64::MAX)],
        vec![(-f64::MAX, 5.0), (-f64::MAX, 6.0)],
        vec![(5e-324, 0.0)],
    ] {
        let pts: Vec<Point2> = pts.into_iter().map(Point2::from).collect();
        let b = ClipBox::around(&set(&pts)).unwrap();
        assert!(b.min.x < b.max.x && b.min.y < b.max.y, "{pts:?}: {b:?}");
        check_against_oracle(&pts, &b);
    }
    // Split at the bisector y = 0.5, each cell keeping its half.
    let pts = [(1e300, 0.0), (1e300, 1.0)].map(Point2::from);
    let b = ClipBox::around(&set(&pts)).unwrap();
    let v = voronoi(&pts).unwrap();
    let low = v.clip_cell(v.cell_of(0), &b);
    assert_eq!(low.len(), 4);
    assert!(low.iter().all(|p| p.y <= 0.5) && low.iter().any(|p| p.y == 0.5));
}

#[test]
fn lattices_with_cocircular_and_collinear_sites() {
    let grid: Vec<Point2> = (0..4)
        .flat_map(|i| (0..4).map(move |j| Point2::new(i as f64, j as f64)))
        .collect();
    for b in [
        ClipBox::around(&set(&grid)).unwrap(),
        // Sides on bisectors, corners on vertices: cells that touch the box along a side.
        ClipBox::new(0.5, 0.5, 2.5, 2.5).unwrap(),
        ClipBox::new(1.5, -1.0, 3.5, 1.5).unwrap(),
        ClipBox::new(-10.0, 0.5, 10.0, 0.75).unwrap(),
    ] {
        check_against_oracle(&grid, &b);
    }
    let line: Vec<Point2> = (0..5)
        .map(|i| Point2::new(i as f64, 2.0 * i as f64))
        .collect();
    check_against_oracle(&line, &ClipBox::around(&set(&line)).unwrap());
    check_against_oracle(&line, &ClipBox::new(0.0, 0.0, 1.0, 1.0).unwrap());
}

#[cfg(feature = "cli")]
#[test]
fn the_issue_commands_give_the_exact_splits() {
    let v = run_json(
        &["voronoi", "--clip", "auto", "-"],
        Some("[[0,0],[1,1],[3,3.0000000000000004]]"),
    );
    let cells = v["cells"].as_array().unwrap();
    let vertices = v["vertices"].as_array().unwrap();
    let sums = |cell: usize| -> Vec<f64> {
        cells[cell]["vertices"]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| {
                let p = &vertices[i.as_u64().unwrap() as usize];
                p[0].as_f64().unwrap() + p[1].as_f64().unwrap()
            })
            .collect()
    };
    // The bisector x + y = 1 (the box's corners are not dyadic, so its ends are rounded).
    assert!(sums(0).iter().all(|&s| s <= 1.0 + 1e-15));
    assert!(
        sums(0)
            .iter()
            .filter(|&&s| (s - 1.0).abs() <= 1e-15)
            .count()
            == 2
    );
    assert!(sums(2).iter().all(|&s| s >= 4.0 - 1e-15));
    let v = run_json(&["voronoi", "--clip", "0,0,1,1e308", "-"], Some("[[0,0]]"));
    assert_eq!(
        v["vertices"],
        serde_json::json!([[0.0, 0.0], [1.0, 0.0], [1.0, 1e308], [0.0, 1e308]])
    );
    let v = run_json(
        &["voronoi", "--clip", "auto", "-"],
        Some("[[1e300,0],[1e300,1]]"),
    );
    let clip: Vec<f64> = v["clip"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_f64().unwrap())
        .collect();
    assert!(clip[0] < clip[2] && clip[1] < clip[3], "{clip:?}");
    assert_eq!(v["cells"][0]["vertices"].as_array().unwrap().len(), 4);
    assert!(v["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .any(|p| p[1].as_f64() == Some(0.5)));
}

fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-8i32..8).prop_map(f64::from),
        (-8i32..8).prop_map(|v| f64::from(v) * 1e-300),
        (-8i32..8).prop_map(|v| f64::from(v) * 1e300),
        (-8i32..8).prop_map(|v| 1.0 + f64::from(v) * f64::EPSILON),
        any::<f64>().prop_filter("finite", |v| v.is_finite()),
    ]
}

fn a_box() -> impl Strategy<Value = Option<[f64; 4]>> {
    prop_oneof![
        Just(None),
        Just(Some([-f64::MAX, -f64::MAX, f64::MAX, f64::MAX])),
        (coordinate(), coordinate(), coordinate(), coordinate()).prop_map(|(a, b, c, d)| Some([
            a.min(c),
            b.min(d),
            a.max(c),
            b.max(d)
        ])),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn clipped_cells_match_the_exact_oracle(
        raw in prop::collection::vec((coordinate(), coordinate()), 1..9),
        bounds in a_box(),
    ) {
        let pts: Vec<Point2> = raw.into_iter().map(Point2::from).collect();
        let b = match bounds {
            None => ClipBox::around(&set(&pts)).unwrap(),
            Some([x0, y0, x1, y1]) => match ClipBox::new(x0, y0, x1, y1) {
                Ok(b) => b,
                Err(_) => return Ok(()),
            },
        };
        check_against_oracle(&pts, &b);
    }
}
