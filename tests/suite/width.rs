//! Width and minimum-area enclosing rectangle by rotating calipers, against brute-force
//! oracles that score every hull edge with a linear scan and exact comparisons.

use compgeo::calipers::{ConvexPolygon, Rectangle, Width};
use compgeo::count::Counts;
use compgeo::gen::{points, PointKind};
use compgeo::geometry::{
    cmp_line_dist, cmp_rect_area, cmp_rect_perimeter, cross_sign, orient2d, ConstructedPoint,
    Orientation, Point2, PointSet, WideFloat,
};
use compgeo::hull::{monotone_chain, HullOptions};
use compgeo::Error;
use proptest::prelude::*;
use std::cmp::Ordering;

/// The width and the minimum-area rectangle of the hull of `pts`; `None` for no points (the
/// calipers then report [`Error::TooFew`]).
fn calipers(pts: &[Point2]) -> Option<(Width, Rectangle)> {
    let set = PointSet::new(pts).unwrap();
    let hull = ConvexPolygon::hull(&set);
    match (hull.width(), hull.min_area_rectangle()) {
        (Ok(w), Ok(r)) => Some((w, r)),
        (Err(Error::TooFew { .. }), Err(Error::TooFew { .. })) if pts.is_empty() => None,
        other => panic!("{other:?}"),
    }
}

/// The width of the hull of `pts`.
fn width(pts: &[Point2]) -> Option<Width> {
    calipers(pts).map(|c| c.0)
}

/// `p` turned a quarter clockwise: `cross_sign` of turned edges is the sign of a dot product.
fn turned(p: Point2) -> Point2 {
    Point2::new(p.y, -p.x)
}

/// Whether `v` is strictly farther along `b - a` than `w` (`dot(b - a, v - w) > 0`).
fn further_along(a: Point2, b: Point2, w: Point2, v: Point2) -> bool {
    cross_sign(turned(a), turned(b), w, v) == Orientation::CounterClockwise
}

/// Per hull edge, by linear scans: `[a, b, top, left, right]`, the first extreme of each.
fn edge_keys(pts: &[Point2], hull: &[usize]) -> Vec<[usize; 5]> {
    let h = hull.len();
    (0..h)
        .map(|k| {
            let (ia, ib) = (hull[k], hull[(k + 1) % h]);
            let (a, b) = (pts[ia], pts[ib]);
            let pick = |better: &dyn Fn(Point2, Point2) -> bool| {
                hull.iter()
                    .copied()
                    .reduce(|best, v| if better(pts[best], pts[v]) { v } else { best })
                    .unwrap()
            };
            let top = pick(&|best, v| cross_sign(a, b, best, v) == Orientation::CounterClockwise);
            let left = pick(&|best, v| further_along(a, b, v, best));
            let right = pick(&|best, v| further_along(a, b, best, v));
            [ia, ib, top, left, right]
        })
        .collect()
}

/// The first edge whose key is smallest under `cmp`.
fn first_min(
    keys: &[[usize; 5]],
    cmp: impl Fn(&[usize; 5], &[usize; 5]) -> Ordering,
) -> [usize; 5] {
    *keys
        .iter()
        .reduce(|best, k| {
            if cmp(k, best) == Ordering::Less {
                k
            } else {
                best
            }
        })
        .unwrap()
}

fn check(pts: &[Point2]) -> Result<(), TestCaseError> {
    let hull = monotone_chain(pts, HullOptions::default()).unwrap();
    let c = calipers(pts);
    let (w, r) = (c.map(|c| c.0), c.map(|c| c.1));
    if hull.len() <= 2 {
        prop_assert_eq!(w.map(|w| w.width), hull.first().map(|_| WideFloat::ZERO));
        prop_assert_eq!(r.map(|r| r.area), hull.first().map(|_| WideFloat::ZERO));
        if let (Some(w), Some(r)) = (w, r) {
            let ends = [hull[0], hull[hull.len() - 1]];
            prop_assert_eq!(w.edge, ends);
            prop_assert_eq!(r.edge, ends);
            prop_assert_eq!(
                r.corners,
                [pts[ends[0]], pts[ends[1]], pts[ends[1]], pts[ends[0]]]
                    .map(ConstructedPoint::from)
            );
            let twice = WideFloat::distance(pts[ends[0]], pts[ends[1]]).mul(WideFloat::from(2.0));
            prop_assert_eq!(r.perimeter, twice);
            let rp = ConvexPolygon::hull(&PointSet::new(pts).unwrap())
                .min_perimeter_rectangle()
                .unwrap();
            prop_assert_eq!(rp, r);
        }
        return Ok(());
    }
    let (w, r) = (w.unwrap(), r.unwrap());
    let keys = edge_keys(pts, &hull);
    let p = |i: usize| pts[i];

    // Width: the first edge whose farthest vertex is nearest, exactly.
    let oracle = first_min(&keys, |k, b| {
        cmp_line_dist(p(k[0]), p(k[1]), p(k[2]), p(b[0]), p(b[1]), p(b[2]))
    });
    prop_assert_eq!(w.edge, [oracle[0], oracle[1]]);
    let (a, b) = (p(w.edge[0]), p(w.edge[1]));
    prop_assert_eq!(
        cmp_line_dist(a, b, p(w.vertex), a, b, p(oracle[2])),
        Ordering::Equal
    );
    for &q in pts {
        prop_assert!(orient2d(a, b, q) != Orientation::Clockwise);
    }

    // Rectangle: the first edge of smallest area, and support vertices that are extreme.
    let area_key = |k: &[usize; 5]| k.map(p);
    let oracle = first_min(&keys, |k, b| cmp_rect_area(area_key(k), area_key(b)));
    prop_assert_eq!(r.edge, [oracle[0], oracle[1]]);
    let [right, top, left] = r.support;
    let mine = [r.edge[0], r.edge[1], top, left, right];
    prop_assert_eq!(
        cmp_rect_area(area_key(&mine), area_key(&oracle)),
        Ordering::Equal
    );
    let (a, b) = (p(r.edge[0]), p(r.edge[1]));
    for &v in &hull {
        prop_assert!(!further_along(a, b, p(right), p(v)));
        prop_assert!(!further_along(a, b, p(v), p(left)));
        prop_assert!(cross_sign(a, b, p(top), p(v)) != Orientation::CounterClockwise);
    }

    // Perimeter: the first edge of smallest perimeter, on the same calipers.
    let polygon = ConvexPolygon::hull(&PointSet::new(pts).unwrap());
    let rp = polygon.min_perimeter_rectangle().unwrap();
    let oracle = first_min(&keys, |k, b| cmp_rect_perimeter(area_key(k), area_key(b)));
    prop_assert_eq!(rp.edge, [oracle[0], oracle[1]]);
    let [right, top, left] = rp.support;
    let mine = [rp.edge[0], rp.edge[1], top, left, right];
    prop_assert_eq!(
        cmp_rect_perimeter(area_key(&mine), area_key(&oracle)),
        Ordering::Equal
    );
    // Neither criterion beats the other on its own measure (compared exactly: the rounded
    // values of two near-equal rectangles may come out in either order).
    let area_best = [
        r.edge[0],
        r.edge[1],
        r.support[1],
        r.support[2],
        r.support[0],
    ];
    let (mine, area_best) = (area_key(&mine), area_key(&area_best));
    prop_assert!(cmp_rect_perimeter(mine, area_best) != Ordering::Greater);
    prop_assert!(cmp_rect_area(area_best, mine) != Ordering::Greater);
    Ok(())
}

/// The rounded values against a plain floating-point evaluation, for small coordinates.
fn check_values(pts: &[Point2], w: Width, r: Rectangle) {
    if r.area == 0.0 {
        return; // collinear input: checked by `check`
    }
    let (a, b, t) = (pts[w.edge[0]], pts[w.edge[1]], pts[w.vertex]);
    let (ux, uy) = (b.x - a.x, b.y - a.y);
    let expected = ((ux * (t.y - a.y) - uy * (t.x - a.x)) / ux.hypot(uy)).abs();
    let width = w.width.to_f64().unwrap();
    assert!(
        (width - expected).abs() <= 1e-12 * expected,
        "{width} vs {expected}"
    );
    // The corners span the rectangle: shoelace area, and every point inside up to rounding.
    let c = r
        .corners
        .map(|c| c.finite().expect("small input, corners in range"));
    let shoelace: f64 = (0..4)
        .map(|k| c[k].x * c[(k + 1) % 4].y - c[(k + 1) % 4].x * c[k].y)
        .sum::<f64>()
        / 2.0;
    let area = r.area.to_f64().unwrap();
    assert!(
        (shoelace - area).abs() <= 1e-9 * area.max(1.0),
        "{shoelace} vs {area}"
    );
    for q in pts {
        for k in 0..4 {
            let (e, f) = (c[k], c[(k + 1) % 4]);
            let side = (f.x - e.x) * (q.y - e.y) - (f.y - e.y) * (q.x - e.x);
            assert!(side >= -1e-9, "{q:?} outside side {k}: {side}");
        }
    }
    // The perimeter is the corners' circumference.
    let around: f64 = (0..4)
        .map(|k| (c[(k + 1) % 4].x - c[k].x).hypot(c[(k + 1) % 4].y - c[k].y))
        .sum();
    let perimeter = r.perimeter.to_f64().unwrap();
    assert!(
        (around - perimeter).abs() <= 1e-9 * perimeter.max(1.0),
        "{around} vs {perimeter}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn width_and_rectangle_equal_brute_force(pts in crate::strategies::lattice(-6..=6, 0..30)) {
        check(&pts)?;
        if let Some((w, r)) = calipers(&pts) {
            check_values(&pts, w, r);
        }
    }

    #[test]
    fn width_and_rectangle_equal_brute_force_at_any_magnitude(
        pts in crate::strategies::lattice(-6..=6, 0..30),
        scale in prop::sample::select(vec![5e-324, 1e-300, 1e-140, 1e15, 1e200, 1e300]),
        shift in prop::sample::select(vec![0.0, 3e16]),
    ) {
        let pts: Vec<Point2> = pts.iter().map(|p| Point2::new(p.x * scale + shift, p.y * scale)).collect();
        check(&pts)?;
    }

    /// Every point picks its own magnitude, from subnormal to near `f64::MAX`: the exact
    /// choices still equal brute force, and no rounded value is NaN.
    #[test]
    fn mixed_magnitudes_in_one_set(
        pts in prop::collection::vec(
            ((-6i32..=6, -6i32..=6), prop::sample::select(vec![5e-324, 1e-300, 1.0, 1e300, 2.5e307])),
            0..20,
        ),
    ) {
        let pts: Vec<Point2> = pts
            .iter()
            .map(|&((x, y), s)| Point2::new(f64::from(x) * s, f64::from(y) * s))
            .collect();
        check(&pts)?;
        if let Some((w, r)) = calipers(&pts) {
            prop_assert!(w.width >= 0.0, "{:?}", w);
            prop_assert!(r.area >= 0.0, "{:?}", r);
            prop_assert!(r.corners.iter().all(|c| c.wide().iter().all(|v| !v.to_f64_saturating().is_nan())), "{:?}", r);
        }
    }

    /// Scaling by a power of two scales the width exactly, in the exact choice and in the
    /// value (rounded once from exact forms), even near the ends of the double range.
    #[test]
    fn the_values_scale(pts in crate::strategies::lattice(-6..=6, 0..30), e in prop::sample::select(vec![-1070, -1000, -500, 500, 1000])) {
        let s = 2f64.powi(e / 2) * 2f64.powi(e - e / 2);
        let scaled: Vec<Point2> = pts.iter().map(|p| Point2::new(p.x * s, p.y * s)).collect();
        if let (Some(w), Some(ws)) = (width(&pts), width(&scaled)) {
            prop_assert_eq!(w.edge, ws.edge);
            prop_assert_eq!(w.vertex, ws.vertex);
            prop_assert_eq!(ws.width, w.width.mul(WideFloat::from(s)));
        }
    }
}

#[test]
fn every_generator_agrees_with_brute_force() {
    for kind in PointKind::ALL {
        let pts = points(kind, 300, 11).unwrap();
        check(&pts).unwrap_or_else(|e| panic!("{kind}: {e}"));
    }
}

#[test]
fn the_calipers_make_at_most_9h_orientation_tests() {
    for kind in [
        PointKind::Cocircular,
        PointKind::RotatedGrid,
        PointKind::UniformDisk,
    ] {
        let pts = points(kind, 2000, 3).unwrap();
        let hull = ConvexPolygon::hull(&PointSet::new(&pts).unwrap());
        let h = hull.vertices().len() as u64;
        for which in 0..3 {
            let mut counts = Counts::default();
            match which {
                0 => drop(hull.width_with(&mut counts).unwrap()),
                1 => drop(hull.min_area_rectangle_with(&mut counts).unwrap()),
                _ => drop(hull.min_perimeter_rectangle_with(&mut counts).unwrap()),
            }
            let tests = counts.orientation_tests;
            assert!(tests <= 9 * h, "{kind}: {tests} tests for h = {h}");
            assert!(counts.distance_evaluations < h, "{kind}");
        }
    }
}

#[test]
fn known_shapes() {
    let p = |x: f64, y: f64| Point2::new(x, y);
    // A 4 × 3 box with an interior point: width 3 on the bottom edge [0, 1] (the right edge
    // [1, 2] gives 4); every side gives area 12, the first edge wins.
    let boxed = [
        p(0.0, 0.0),
        p(4.0, 0.0),
        p(4.0, 3.0),
        p(0.0, 3.0),
        p(1.0, 1.0),
    ];
    let (w, r) = calipers(&boxed).unwrap();
    assert_eq!((w.edge, w.width), ([0, 1], WideFloat::from(3.0)));
    assert_eq!((r.edge, r.area), ([0, 1], WideFloat::from(12.0)));
    assert_eq!(
        r.corners,
        [p(0.0, 0.0), p(4.0, 0.0), p(4.0, 3.0), p(0.0, 3.0)].map(ConstructedPoint::from)
    );
    // A right triangle with legs 3, 4: width 12/5 (the altitude on the hypotenuse).
    let tri = [p(0.0, 0.0), p(4.0, 0.0), p(0.0, 3.0)];
    let w = width(&tri).unwrap();
    assert_eq!((w.edge, w.vertex), ([1, 2], 0));
    assert_eq!(w.width, 2.4, "12 / √25, rounded once");
    // A hull edge one subnormal step long next to 1e300: the direction comes from the edge
    // itself, so the rounded values are finite.
    let needle = [p(0.0, 0.0), p(1e300, 0.0), p(1e300, 5e-324)];
    let (w, r) = calipers(&needle).unwrap();
    assert!(r.area > 0.0, "{r:?}");
    assert!(w.width > 0.0);
    // One point, and no point.
    let (_, r) = calipers(&[p(1.0, 2.0)]).unwrap();
    assert_eq!(
        (r.edge, r.area, r.corners),
        (
            [0, 0],
            WideFloat::ZERO,
            [ConstructedPoint::from(p(1.0, 2.0)); 4]
        )
    );
    assert!(calipers(&[]).is_none());
}
