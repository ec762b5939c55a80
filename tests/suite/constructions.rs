//! Constructed points against exact `BigRational` oracles written from their definitions, on
//! hostile input (magnitudes from subnormal to `f64::MAX` in one set, nearly collinear and
//! nearly coincident points): Voronoi vertices (circumcentres), the corners of the minimum
//! rectangle, and (in `empty_circle.rs`, whose brute force this file's CLI tests reuse) the
//! centres of the largest empty circle. Each must be within
//! `ConstructedPoint::RELATIVE_ERROR · max(|x|, |y|) + 2^-1075` of its exact value `(x, y)`,
//! and beyond the range of `f64` exactly when a coordinate's magnitude is at least
//! `2^1024 − 2^970` (where rounding to nearest overflows). The command line prints such a
//! coordinate as a JSON string holding its decimal value.

use compgeo::calipers::ConvexPolygon;
use compgeo::delaunay::{dual, incremental, voronoi};
use compgeo::geometry::{orient2d, ConstructedPoint, Orientation, Point2, PointSet, WideFloat};
use num_bigint::BigInt as Z;
use num_rational::BigRational as Q;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

fn q(v: f64) -> Q {
    Q::from_float(v).expect("finite")
}

fn pow2(e: i32) -> Q {
    if e >= 0 {
        Q::from_integer(Z::one() << e as usize)
    } else {
        Q::new(Z::one(), Z::one() << (-e) as usize)
    }
}

/// The exact value of a decimal text such as `-4.9999999999999995e899` or `0.25`.
fn decimal(text: &str) -> Q {
    let (mantissa, exponent) = text.split_once(['e', 'E']).unwrap_or((text, "0"));
    let negative = mantissa.starts_with('-');
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let fraction = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i64;
    let e = exponent.parse::<i64>().expect("an exponent") - fraction;
    let ten = num_traits::pow(Q::from_integer(Z::from(10)), e.unsigned_abs() as usize);
    let m = Q::from_integer(digits.parse::<Z>().expect("digits"));
    let v = if e >= 0 { m * ten } else { m / ten };
    if negative {
        -v
    } else {
        v
    }
}

/// A coordinate's value: the double itself, or for one beyond `f64` its decimal text (17
/// digits, so within 2^-53 of the rounded value, which [`check`] allows for).
fn wide_value(w: WideFloat) -> (Q, bool) {
    match w.to_f64() {
        Some(v) => (q(v), false),
        None => (decimal(&w.to_string()), true),
    }
}

/// The IEEE overflow threshold: magnitudes from here on round to infinity.
fn threshold() -> Q {
    pow2(1024) - pow2(970)
}

/// Panics unless the coordinates `got` (each a value and whether it was printed as a
/// decimal string beyond `f64`) are within the stated error of the exact `(x, y)`, and the
/// beyond-range ones are exactly those at least the overflow threshold.
fn check_coordinates(got: [(Q, bool); 2], exact: &(Q, Q), what: &str) {
    let m = exact.0.abs().max(exact.1.abs());
    let relative = q(ConstructedPoint::RELATIVE_ERROR);
    for ((value, beyond), e) in got.iter().zip([&exact.0, &exact.1]) {
        assert_eq!(
            *beyond,
            e.abs() >= threshold(),
            "{what}: beyond range, {value} for {e}"
        );
        let decimal = if *beyond {
            e.abs() * pow2(-53)
        } else {
            Q::zero()
        };
        let bound = &relative * &m + pow2(-1075) + decimal;
        assert!(
            (value - e).abs() <= bound,
            "{what}: {value} for the exact {e}, bound {bound}"
        );
    }
}

fn check(got: ConstructedPoint, exact: &(Q, Q), what: &str) {
    let [x, y] = got.wide();
    let beyond = exact.0.abs() >= threshold() || exact.1.abs() >= threshold();
    assert_eq!(got.is_beyond_range(), beyond, "{what}: {got:?}");
    check_coordinates([wide_value(x), wide_value(y)], exact, what);
    // The clamped point agrees with the wide one wherever that is in range.
    let clamped = got.saturating();
    for (c, w) in [(clamped.x, x), (clamped.y, y)] {
        assert_eq!(c, w.to_f64_saturating(), "{what}");
    }
}

fn circumcentre_q([a, b, c]: [Point2; 3]) -> (Q, Q) {
    let (ax, ay) = (q(a.x), q(a.y));
    let (bx, by) = (q(b.x) - &ax, q(b.y) - &ay);
    let (cx, cy) = (q(c.x) - &ax, q(c.y) - &ay);
    let lb = &bx * &bx + &by * &by;
    let lc = &cx * &cx + &cy * &cy;
    let d = (&bx * &cy - &by * &cx) * Q::from_integer(Z::from(2));
    (
        ax + (&cy * &lb - &by * &lc) / &d,
        ay + (&bx * &lc - &cx * &lb) / &d,
    )
}

/// Where the perpendicular to `a → b` through `p` meets the parallel through `r`.
fn corner_q(a: Point2, b: Point2, p: Point2, r: Point2) -> (Q, Q) {
    let (ax, ay) = (q(a.x), q(a.y));
    let (gx, gy) = (q(b.x) - &ax, q(b.y) - &ay);
    let along = (q(p.x) - &ax) * &gx + (q(p.y) - &ay) * &gy;
    let across = &gx * (q(r.y) - &ay) - &gy * (q(r.x) - &ax);
    let n = &gx * &gx + &gy * &gy;
    (
        ax + (&along * &gx - &across * &gy) / &n,
        ay + (&along * &gy + &across * &gx) / &n,
    )
}

/// A hostile coordinate: magnitudes from subnormal to `f64::MAX`, random mantissas.
fn coordinate() -> impl Strategy<Value = f64> {
    let exponents = vec![
        -1074, -1060, -1022, -1000, -600, -300, -52, 0, 52, 300, 600, 1000, 1020, 1023,
    ];
    prop_oneof![
        (
            any::<bool>(),
            1u64..(1 << 53),
            prop::sample::select(exponents)
        )
            .prop_map(|(negative, m, e)| {
                // m · 2^(e − 52) in two steps, so neither factor overflows nor underflows.
                let v = m as f64 * 2f64.powi((e - 52) / 2) * 2f64.powi((e - 52) - (e - 52) / 2);
                let v = if v.is_finite() { v } else { f64::MAX };
                if negative {
                    -v
                } else {
                    v
                }
            }),
        -4.0..4.0f64,
        prop::sample::select(vec![
            0.0,
            5e-324,
            -5e-324,
            f64::MAX,
            -f64::MAX,
            1e300,
            1e-300
        ]),
        any::<f64>().prop_filter("finite", |v| v.is_finite()),
    ]
}

fn point() -> impl Strategy<Value = Point2> {
    (coordinate(), coordinate()).prop_map(|(x, y)| Point2::new(x, y))
}

/// `v` moved by `k` units in the last place (staying finite).
fn nudge(v: f64, k: i32) -> f64 {
    let mut v = v;
    for _ in 0..k.unsigned_abs() {
        v = if k > 0 { v.next_up() } else { v.next_down() };
    }
    v.clamp(-f64::MAX, f64::MAX)
}

/// Hostile triangles: independent points; nearly collinear (the third a few ulps off a
/// point of the line through the first two); nearly coincident (two a few ulps apart).
fn triangle() -> impl Strategy<Value = [Point2; 3]> {
    prop_oneof![
        [point(), point(), point()],
        (point(), point(), 0.0..1.0f64, -3i32..=3, -3i32..=3).prop_map(|(a, b, t, i, j)| {
            let on = Point2::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
            let on = if on.is_finite() {
                on
            } else {
                Point2::new(a.x / 2.0 + b.x / 2.0, a.y / 2.0 + b.y / 2.0)
            };
            [a, b, Point2::new(nudge(on.x, i), nudge(on.y, j))]
        }),
        (point(), point(), -4i32..=4, -4i32..=4).prop_map(|(a, c, i, j)| [
            a,
            Point2::new(nudge(a.x, i), nudge(a.y, j)),
            c
        ]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The one vertex of three sites' diagram is their circumcentre, within the stated error
    /// and beyond the range exactly when it is.
    #[test]
    fn voronoi_vertices_of_hostile_triangles(t in triangle()) {
        prop_assume!(orient2d(t[0], t[1], t[2]) != Orientation::Collinear);
        let v = voronoi(&t).unwrap();
        prop_assert_eq!(v.vertices.len(), 1);
        check(v.vertex(0), &circumcentre_q(t), "circumcentre");
        prop_assert_eq!(v.is_beyond_range(0), v.vertex(0).is_beyond_range());
        prop_assert_eq!(v.vertices[0], v.vertex(0).saturating());
    }

    /// Every vertex of a larger hostile set, against its own triangle.
    #[test]
    fn voronoi_vertices_of_mixed_magnitudes(pts in crate::strategies::mixed_magnitudes(3..12)) {
        let t = incremental(&pts).unwrap();
        let v = dual(&pts, &t).unwrap();
        for k in 0..t.triangle_count() {
            check(v.vertex(k), &circumcentre_q(t.triangle(k).map(|i| pts[i])), "vertex");
        }
    }

    /// The rectangle's corners: the intersections of its sides' lines, from the edge and
    /// the support vertices it reports (which the calipers' own tests check exactly).
    #[test]
    fn rectangle_corners_of_hostile_hulls(pts in prop::collection::vec(point(), 3..8)) {
        let r = ConvexPolygon::hull(&PointSet::new(&pts).unwrap()).min_area_rectangle().unwrap();
        let [i, j] = r.edge;
        if i == j {
            return Ok(()); // one distinct point: the corners are that point
        }
        let (a, b) = (pts[i], pts[j]);
        let [right, top, left] = r.support.map(|k| pts[k]);
        let expected = [(left, a), (right, a), (right, top), (left, top)];
        for (k, (p, s)) in expected.into_iter().enumerate() {
            check(r.corners[k], &corner_q(a, b, p, s), "corner");
        }
    }
}

#[test]
fn a_flat_triangle_at_a_large_scale_has_its_centre_beyond_the_range() {
    let t = [(-1e300, 0.0), (1e300, 0.0), (0.0, 1e-300)].map(Point2::from);
    let v = voronoi(&t).unwrap();
    assert!(v.is_beyond_range(0));
    assert_eq!(v.vertices[0], Point2::new(0.0, -f64::MAX));
    check(v.vertex(0), &circumcentre_q(t), "flat");
    // In range: a centre about −1e300 / 2e-7 = −5e306 away.
    let t = [(-1e150, 0.0), (1e150, 0.0), (0.0, 1e-7)].map(Point2::from);
    let v = voronoi(&t).unwrap();
    assert!(!v.is_beyond_range(0));
    check(v.vertex(0), &circumcentre_q(t), "in range");
}

/// The Voronoi findings of the fuzzing (`tests/fixtures/fuzz/voronoi/`), each one triangle:
/// a centre beyond the range that came out as 2^1023, one that came out as the wrong finite
/// 9.98e291, a nearly flat triangle whose centre (−1.75e35, 45) was clamped to −f64::MAX,
/// and a centre 2.9e-5 from the origin beside an edge of 4.6e-308 that was off by a
/// relative 2e-8. Each is within the stated error now, beyond the range exactly when its
/// exact centre is.
#[test]
fn the_voronoi_fuzz_findings_are_within_the_stated_error() {
    let cases: [([(f64, f64); 3], bool); 4] = [
        ([(-1.0, 2.122060549e-314), (0.0, 0.0), (1.0, 0.0)], true),
        ([(5e-324, -1.0), (0.0, -0.0), (0.0, -5e-324)], true),
        (
            [
                (-3.9999999999999987, 86.0),
                (-3.9999999999999996, 4.000000000000001),
                (-3.999999999999999, 45.0),
            ],
            false,
        ),
        (
            [
                (-2.9087066650390625e-5, -2.9087066650390625e-5),
                (4.569793315955872e-308, 0.0),
                (0.0, 0.0),
            ],
            false,
        ),
    ];
    for (t, beyond) in cases {
        let t = t.map(Point2::from);
        let v = voronoi(&t).unwrap();
        assert_eq!(v.vertices.len(), 1, "{t:?}");
        assert_eq!(v.is_beyond_range(0), beyond, "{t:?}");
        check(v.vertex(0), &circumcentre_q(t), "fuzz finding");
    }
}

#[test]
fn a_tilted_rectangle_around_the_largest_doubles_has_corners_beyond_the_range() {
    // The square [−M, M]² with its corner (M, −M) cut off: the best rectangle lies along
    // the diagonal, area 3 M² < 4 M², and sticks out of the square at its corners
    // (−M/4, −7M/4) and (7M/4, M/4).
    let m = f64::MAX;
    let pts = [(-m, -m), (m, m), (m, -m / 2.0), (m / 2.0, -m)].map(Point2::from);
    let r = ConvexPolygon::hull(&PointSet::new(&pts).unwrap())
        .min_area_rectangle()
        .unwrap();
    let beyond = r.corners.iter().filter(|c| c.is_beyond_range()).count();
    assert_eq!(beyond, 2, "{r:?}");
    let (a, b) = (pts[r.edge[0]], pts[r.edge[1]]);
    let [right, top, left] = r.support.map(|k| pts[k]);
    for (k, (p, s)) in [(left, a), (right, a), (right, top), (left, top)]
        .into_iter()
        .enumerate()
    {
        check(r.corners[k], &corner_q(a, b, p, s), "corner");
    }
}

#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use crate::common::run_json;
    use serde_json::Value;

    /// A printed coordinate: a JSON number, or a decimal string for one beyond `f64`.
    fn coordinate(v: &Value) -> (Q, bool) {
        match v {
            Value::Number(n) => (q(n.as_f64().expect("a double")), false),
            Value::String(s) => {
                let value = decimal(s);
                assert!(
                    value.abs() > q(f64::MAX),
                    "{s} printed as a string but in range"
                );
                (value, true)
            }
            other => panic!("a coordinate printed as {other}"),
        }
    }

    fn point_of(v: &Value) -> [(Q, bool); 2] {
        [coordinate(&v[0]), coordinate(&v[1])]
    }

    /// Every printed vertex is within the stated error of the exact circumcentre of its
    /// sites (the three cells that list it), and every ray from it starts at its value.
    fn check_voronoi(input: &str) -> Value {
        let pts: Vec<Point2> = serde_json::from_str::<Vec<(f64, f64)>>(input)
            .unwrap()
            .into_iter()
            .map(Point2::from)
            .collect();
        let out = run_json(&["voronoi", "-"], Some(input));
        let vertices = out["vertices"].as_array().unwrap();
        let cells = out["cells"].as_array().unwrap();
        for (k, vertex) in vertices.iter().enumerate() {
            let sites: Vec<usize> = cells
                .iter()
                .filter(|c| c["vertices"].as_array().unwrap().contains(&Value::from(k)))
                .map(|c| c["site"].as_u64().unwrap() as usize)
                .collect();
            assert_eq!(sites.len(), 3, "vertex {k}: {out}");
            let exact = circumcentre_q([sites[0], sites[1], sites[2]].map(|i| pts[i]));
            check_coordinates(point_of(vertex), &exact, &format!("vertex {k}"));
        }
        for c in cells {
            let ids = c["vertices"].as_array().unwrap();
            if ids.is_empty() {
                continue; // collinear sites: rays from midpoints
            }
            for (ray, end) in c["rays"].as_array().unwrap().iter().zip([0, ids.len() - 1]) {
                let k = ids[end].as_u64().unwrap() as usize;
                assert_eq!(ray["origin"], vertices[k], "{out}");
            }
        }
        out
    }

    #[test]
    fn voronoi_of_mixed_magnitudes_from_the_issue() {
        // Was a vertex closer to another site than to its own three.
        check_voronoi("[[0.0,0.0],[1e-300,0.0],[0.0,1e-300],[1e300,1e300]]");
        check_voronoi(
            "[[1e300,1e-300],[1e-300,1e300],[0,0],[1e-300,1e-300],[-1e300,5e-324],[5e-324,-1e300]]",
        );
    }

    #[test]
    fn voronoi_prints_a_vertex_beyond_the_range_as_a_decimal_string() {
        let out = check_voronoi("[[-1e300,0],[1e300,0],[0,1e-300]]");
        assert_eq!(out["vertices"][0][0], serde_json::json!(0.0));
        let y = out["vertices"][0][1].as_str().expect("a string beyond f64");
        assert!(
            y.starts_with("-5.0000000000000") && y.ends_with("e899"),
            "{y}"
        );
    }

    #[test]
    fn empty_circle_from_the_issue_checked_by_the_exact_brute_force() {
        for input in [
            "[[0.0,0.0],[1e-300,0.0],[0.0,1e-300],[1e300,1e300]]",
            "[[1e300,1e-300],[1e-300,1e300],[0,0],[1e-300,1e-300],[-1e300,5e-324],[5e-324,-1e300]]",
        ] {
            let pts: Vec<Point2> = serde_json::from_str::<Vec<(f64, f64)>>(input)
                .unwrap()
                .into_iter()
                .map(Point2::from)
                .collect();
            let out = run_json(&["empty-circle", "-"], Some(input));
            // The printed centre is in range (it is in the hull): two numbers.
            let centre = Point2::new(
                out["centre"][0].as_f64().unwrap(),
                out["centre"][1].as_f64().unwrap(),
            );
            let circle = compgeo::proximity::EmptyCircle {
                centre,
                radius: out["radius"].as_f64().unwrap().into(),
                sites: out["sites"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|s| s.as_u64().unwrap() as usize)
                    .collect(),
            };
            // Sites on one circle, no point strictly inside, centre in the hull, the largest
            // such circle, all in exact rationals; the printed centre within the stated
            // error of the exact one.
            crate::empty_circle::check_circle(&pts, &circle);
        }
    }

    #[test]
    fn diameter_prints_rectangle_corners_beyond_the_range_as_decimal_strings() {
        let m = f64::MAX;
        let pts = [(-m, -m), (m, m), (m, -m / 2.0), (m / 2.0, -m)];
        let input = serde_json::to_string(&pts).unwrap();
        let out = run_json(&["diameter", "-"], Some(&input));
        let r = &out["rectangle"];
        let p = |k: &Value| Point2::from(pts[k.as_u64().unwrap() as usize]);
        let (a, b) = (p(&r["edge"][0]), p(&r["edge"][1]));
        let [right, top, left] = [0, 1, 2].map(|k| p(&r["support"][k]));
        let mut strings = 0;
        for (k, (s, t)) in [(left, a), (right, a), (right, top), (left, top)]
            .into_iter()
            .enumerate()
        {
            let c = &r["corners"][k];
            let got = [coordinate(&c["x"]), coordinate(&c["y"])];
            strings += got.iter().filter(|g| g.1).count();
            check_coordinates(got, &corner_q(a, b, s, t), &format!("corner {k}"));
        }
        assert_eq!(strings, 2, "{out}");
    }
}
