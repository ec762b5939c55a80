//! Values beyond `f64::MAX`: every length, distance, width, area, radius and sum the library
//! returns is a `WideFloat` within its stated relative error of the exact value, and the
//! command line prints it as a JSON number when it fits in `f64` and as its decimal string
//! when it does not (never `null`, never a wrong finite number).
//!
//! The exact values are computed in `BigRational`: squared lengths, areas and sums exactly,
//! square roots bracketed by integer square roots. A length `d` with relative error `ε` is
//! checked as `(1 − ε)² x ≤ d² ≤ (1 + ε)² x` against its exact square `x`.

use crate::common::wide_q;
use crate::strategies::{extreme_coordinate, extreme_points};
use compgeo::calipers::{diameter, ConvexPolygon, DiameterAlgorithm};
use compgeo::geometry::{BoundingBox, Point2, PointSet};
use compgeo::graph::{spanning_forest, MstAlgorithm, WeightedGraph};
use compgeo::proximity::{closest_pair, euclidean_mst, largest_empty_circle, ClosestPairAlgorithm};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use proptest::prelude::*;

type Q = BigRational;

const M: f64 = f64::MAX;

/// The stated bounds, in units of 2^-52: distances, widths and radii 2 (2^-51), areas 3,
/// the Euclidean tree's total length 2.5, a graph's total weight 0.5 (correctly rounded).
const LENGTH: f64 = 2.0;
const AREA: f64 = 3.0;
const TREE: f64 = 2.5;
const SUM: f64 = 0.5;

fn q(v: f64) -> Q {
    Q::from_float(v).expect("finite")
}

/// `units · 2^-52` as a rational.
fn rel(units: f64) -> Q {
    q(units) / Q::from_integer(BigInt::one() << 52)
}

fn sq(v: &Q) -> Q {
    v * v
}

/// Whether `x` is within relative error `eps` of `exact`.
fn near(x: &Q, exact: &Q, eps: &Q) -> bool {
    (x - exact).abs() <= exact.abs() * eps
}

/// Whether `x ≥ 0` is within relative error `eps` of `√squared`.
fn near_sqrt(x: &Q, squared: &Q, eps: &Q) -> bool {
    let one = Q::one();
    !x.is_negative() && sq(x) <= squared * sq(&(&one + eps)) && sq(x) >= squared * sq(&(&one - eps))
}

/// `[lo, hi]` holding `√x` for `x ≥ 0`, with `hi − lo` below 2^-300 of `√x` (integer square
/// roots of `x` scaled by 4^k).
fn sqrt_bracket(x: &Q) -> (Q, Q) {
    if x.is_zero() {
        return (Q::zero(), Q::zero());
    }
    // √(n / d) = √(n d) / d; scale n d by 4^k so the integer root has 300 bits or more.
    let (n, d) = (x.numer(), x.denom());
    let nd = n * d;
    let k = (600i64 - nd.bits() as i64).max(0) as usize / 2 + 1;
    let root = (&nd << (2 * k)).sqrt();
    let scale = Q::from_integer(d << k);
    (
        Q::from_integer(root.clone()) / &scale,
        Q::from_integer(root + 1) / &scale,
    )
}

/// The exact squared distance `|ab|²`.
fn dist2(a: Point2, b: Point2) -> Q {
    sq(&(q(b.x) - q(a.x))) + sq(&(q(b.y) - q(a.y)))
}

/// `(b − a) × (c − a)` and `(b − a) · (d − c)`, exactly.
fn cross(a: Point2, b: Point2, c: Point2) -> Q {
    (q(b.x) - q(a.x)) * (q(c.y) - q(a.y)) - (q(b.y) - q(a.y)) * (q(c.x) - q(a.x))
}

fn dot(a: Point2, b: Point2, c: Point2, d: Point2) -> Q {
    (q(b.x) - q(a.x)) * (q(d.x) - q(c.x)) + (q(b.y) - q(a.y)) * (q(d.y) - q(c.y))
}

/// The exact total length of a set of edges, bracketed.
fn total_length(points: &[Point2], edges: &[[usize; 2]]) -> (Q, Q) {
    edges
        .iter()
        .fold((Q::zero(), Q::zero()), |(lo, hi), &[u, v]| {
            let (l, h) = sqrt_bracket(&dist2(points[u], points[v]));
            (lo + l, hi + h)
        })
}

/// Whether `x` is within `eps` of some value in `[lo, hi]`.
fn near_bracket(x: &Q, (lo, hi): &(Q, Q), eps: &Q) -> bool {
    let one = Q::one();
    x >= &(lo * (&one - eps)) && x <= &(hi * (&one + eps))
}

#[test]
fn the_bracket_holds_the_root() {
    for v in [2.0, 1e-300, 5e-324, M, 0.25] {
        let x = q(v);
        let (lo, hi) = sqrt_bracket(&x);
        assert!(sq(&lo) <= x && sq(&hi) >= x && lo < hi, "{v}");
        assert!(
            &hi - &lo < &lo / Q::from_integer(BigInt::one() << 290),
            "{v}"
        );
    }
}

#[test]
fn distances_at_the_corners_of_the_range() {
    let far = [Point2::new(-M, -M), Point2::new(M, M)];
    for a in ClosestPairAlgorithm::ALL {
        let c = closest_pair(&far, a).unwrap();
        assert_eq!(c.distance.to_f64(), None, "{a}");
        assert!(
            near_sqrt(&wide_q(c.distance), &(q(8.0) * sq(&q(M))), &rel(LENGTH)),
            "{a}"
        );
    }
    for a in DiameterAlgorithm::ALL {
        let d = diameter(&far, a).unwrap();
        assert!(
            near_sqrt(&wide_q(d.distance), &(q(8.0) * sq(&q(M))), &rel(LENGTH)),
            "{a}"
        );
    }
    // Half the range: exactly f64::MAX, an f64.
    let half = [Point2::new(-M / 2.0, 0.0), Point2::new(M / 2.0, 0.0)];
    for a in DiameterAlgorithm::ALL {
        assert_eq!(
            diameter(&half, a).unwrap().distance.to_f64(),
            Some(M),
            "{a}"
        );
    }
}

#[test]
fn a_graph_total_is_exact_whatever_the_order_and_the_signs() {
    // Summed left to right in f64: 1e308 + 1 = 1e308, then − 1e308 = 0.
    let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3]], &[1e308, 1.0, -1e308]).unwrap();
    for a in MstAlgorithm::ALL {
        assert_eq!(spanning_forest(&g, a).weight, 1.0, "{a}");
    }
    // f64::MAX three times: 3 f64::MAX needs 54 significant bits, so it is rounded once,
    // within half a unit.
    let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3]], &[M, M, M]).unwrap();
    for a in MstAlgorithm::ALL {
        let w = spanning_forest(&g, a).weight;
        assert_eq!(w.to_f64(), None);
        assert!(near(&wide_q(w), &(q(3.0) * q(M)), &rel(SUM)), "{a}: {w}");
    }
    // The subnormal survives the cancellation of the giants around it.
    let g = WeightedGraph::from_edges(4, &[[0, 1], [1, 2], [2, 3]], &[M, 5e-324, -M]).unwrap();
    assert_eq!(spanning_forest(&g, MstAlgorithm::Kruskal).weight, 5e-324);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Closest pairs and diameters: the distance of the returned pair within 2^-51.
    #[test]
    fn pair_distances_are_within_their_bound(pts in extreme_points(2..10)) {
        let eps = rel(LENGTH);
        for a in ClosestPairAlgorithm::ALL {
            let c = closest_pair(&pts, a).unwrap();
            let [i, j] = c.pair;
            prop_assert!(near_sqrt(&wide_q(c.distance), &dist2(pts[i], pts[j]), &eps), "{a}: {c:?}");
        }
        for a in DiameterAlgorithm::ALL {
            let d = diameter(&pts, a).unwrap();
            let [i, j] = d.pair;
            prop_assert!(near_sqrt(&wide_q(d.distance), &dist2(pts[i], pts[j]), &eps), "{a}: {d:?}");
        }
    }

    /// The width (distance from the vertex to the edge's line) within 2^-51 and the
    /// rectangle's area within 3 · 2^-52, for the edge and vertices the calipers chose.
    #[test]
    fn widths_and_areas_are_within_their_bounds(pts in extreme_points(1..10)) {
        let set = PointSet::new(&pts).unwrap();
        let hull = ConvexPolygon::hull(&set);
        let (w, r) = (hull.width().unwrap(), hull.min_area_rectangle().unwrap());
        if hull.vertices().len() < 3 {
            prop_assert!(w.width.is_zero() && r.area.is_zero());
            return Ok(());
        }
        let (a, b) = (pts[w.edge[0]], pts[w.edge[1]]);
        let width2 = sq(&cross(a, b, pts[w.vertex])) / dist2(a, b);
        prop_assert!(near_sqrt(&wide_q(w.width), &width2, &rel(LENGTH)), "{w:?}");
        let (a, b) = (pts[r.edge[0]], pts[r.edge[1]]);
        let [right, top, left] = r.support.map(|i| pts[i]);
        let area = cross(a, b, top).abs() * dot(a, b, left, right).abs() / dist2(a, b);
        prop_assert!(near(&wide_q(r.area), &area, &rel(AREA)), "{r:?}");
    }

    /// The Euclidean tree's total length within 2.5 · 2^-52 of the sum of its exact lengths.
    #[test]
    fn tree_lengths_are_within_their_bound(pts in extreme_points(1..10)) {
        let t = euclidean_mst(&pts).unwrap();
        let exact = total_length(&pts, &t.edges);
        prop_assert!(near_bracket(&wide_q(t.weight), &exact, &rel(TREE)), "{:?}", t);
    }

    /// The largest empty circle's radius within 2^-51 of the exact one of its defining
    /// sites (three: the circumcircle; one: zero; two: checked against its own sites in
    /// `empty_circle.rs`, which rebuilds the crossing point exactly).
    #[test]
    fn circumradii_are_within_their_bound(pts in extreme_points(3..8)) {
        let c = largest_empty_circle(&pts).unwrap();
        match c.sites[..] {
            [i] => prop_assert!(c.radius.is_zero(), "{i}: {c:?}"),
            [i, j, k] => {
                let (a, b, d) = (pts[i], pts[j], pts[k]);
                // r² = |ab|² |bd|² |da|² / (2 (b − a) × (d − a))².
                let r2 = dist2(a, b) * dist2(b, d) * dist2(d, a) / sq(&(q(2.0) * cross(a, b, d)));
                prop_assert!(near_sqrt(&wide_q(c.radius), &r2, &rel(LENGTH)), "{c:?}");
            }
            _ => {}
        }
    }

    /// A graph's total weight: the exact sum of the chosen weights, correctly rounded,
    /// whatever their magnitudes and signs.
    #[test]
    fn graph_totals_are_correctly_rounded(
        weights in prop::collection::vec(extreme_coordinate(), 1..12),
        extra in prop::collection::vec((0usize..12, 0usize..12), 0..6),
    ) {
        let n = weights.len() + 1;
        // A path (so the graph is connected) and some chords with the same weights again.
        let mut edges: Vec<[usize; 2]> = (0..weights.len()).map(|i| [i, i + 1]).collect();
        let mut w = weights.clone();
        for (k, &(u, v)) in extra.iter().enumerate() {
            edges.push([u % n, v % n]);
            w.push(weights[k % weights.len()]);
        }
        let g = WeightedGraph::from_edges(n, &edges, &w).unwrap();
        for a in MstAlgorithm::ALL {
            let f = spanning_forest(&g, a);
            let exact = f.edges.iter().fold(Q::zero(), |s, &e| s + q(g.weight(e)));
            prop_assert!(near(&wide_q(f.weight), &exact, &rel(SUM)), "{a}: {} vs exact", f.weight);
        }
    }

    /// A bounding box's width and height: the exact differences, correctly rounded.
    #[test]
    fn box_extents_are_correctly_rounded(pts in extreme_points(1..6)) {
        let b = BoundingBox::of(&pts).unwrap();
        let exact_w = q(b.max.x) - q(b.min.x);
        let exact_h = q(b.max.y) - q(b.min.y);
        prop_assert!(near(&wide_q(b.width()), &exact_w, &rel(SUM)));
        prop_assert!(near(&wide_q(b.height()), &exact_h, &rel(SUM)));
    }
}

/// The command line: strings beyond `f64`, numbers below, each within its bound.
#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use crate::common::run_json;
    use compgeo::geometry::WideFloat;
    use serde_json::Value;

    /// `[[x, y], ...]` with every double in its shortest round-trip text.
    fn points_json(pts: &[(f64, f64)]) -> String {
        let items: Vec<String> = pts.iter().map(|(x, y)| format!("[{x:?},{y:?}]")).collect();
        format!("[{}]", items.join(","))
    }

    /// The exact value of a decimal `d.ddd…e±n` (the string form of a value beyond `f64`).
    fn decimal_q(s: &str) -> Q {
        let (mantissa, exponent) = s.split_once('e').expect("an exponent");
        let (negative, mantissa) = match mantissa.strip_prefix('-') {
            Some(m) => (true, m),
            None => (false, mantissa),
        };
        let (int, frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let digits: BigInt = format!("{int}{frac}").parse().expect("digits");
        let e: i64 = exponent.parse::<i64>().expect("an integer exponent") - frac.len() as i64;
        let ten = Q::from_integer(BigInt::from(10));
        let p = num_traits::pow(ten, e.unsigned_abs() as usize);
        let v = Q::from_integer(digits);
        let v = if e >= 0 { v * p } else { v / p };
        if negative {
            -v
        } else {
            v
        }
    }

    /// A printed value: a string must be a value beyond `f64` (and is one exactly when
    /// `beyond`), a number one within it.
    fn printed(v: &Value, beyond: bool) -> Q {
        match v {
            Value::String(s) => {
                assert!(beyond, "{s} printed as a string but fits in f64");
                let x = decimal_q(s);
                assert!(x.abs() > q(M), "{s} is not beyond f64::MAX");
                x
            }
            Value::Number(n) => {
                assert!(!beyond, "{n} printed as a number but is beyond f64");
                q(n.as_f64().unwrap())
            }
            other => panic!("a length printed as {other}"),
        }
    }

    /// The bound of a printed value: the library's, plus the last rounding (to `f64`, or to
    /// 17 decimal digits, at most 5 · 10^-17 relative; 2^-53 covers both).
    fn printed_rel(units: f64) -> Q {
        rel(units + 0.5)
    }

    fn no_nulls(v: &Value) {
        match v {
            Value::Null => panic!("a null in the output"),
            Value::Array(a) => a.iter().for_each(no_nulls),
            Value::Object(o) => o.values().for_each(no_nulls),
            _ => {}
        }
    }

    fn run(args: &[&str], input: &str) -> Value {
        let v = run_json(args, Some(input));
        no_nulls(&v);
        v
    }

    #[test]
    fn the_reported_closest_pair_is_a_decimal_string() {
        // The issue's reproduction: once a wrong finite value, then null.
        let far = points_json(&[(-M, -M), (M, M)]);
        let v = run(&["closest-pair", "-"], &far);
        assert_eq!(v["distance"], "5.0846440246145847e308");
        let three = points_json(&[(-M, -M), (M, M), (M, -M)]);
        for a in ClosestPairAlgorithm::ALL {
            let v = run(&["closest-pair", "-a", a.name(), "-"], &three);
            let d = printed(&v["distance"], true);
            assert!(
                near_sqrt(&d, &(q(4.0) * sq(&q(M))), &printed_rel(LENGTH)),
                "{a}: {v}"
            );
            // Just below: exactly f64::MAX, and 0.6 √2 f64::MAX.
            let v = run(
                &["closest-pair", "-a", a.name(), "-"],
                &points_json(&[(-M / 2.0, 0.0), (M / 2.0, 0.0)]),
            );
            assert_eq!(v["distance"], M, "{a}");
            let v = run(
                &["closest-pair", "-a", a.name(), "-"],
                &points_json(&[(0.0, 0.0), (0.6 * M, 0.6 * M)]),
            );
            let d = printed(&v["distance"], false);
            assert!(
                near_sqrt(&d, &(q(2.0) * sq(&q(0.6 * M))), &printed_rel(LENGTH)),
                "{a}: {v}"
            );
        }
    }

    #[test]
    fn diameter_width_and_area_beyond_f64() {
        let square = points_json(&[(-M, -M), (M, -M), (M, M), (-M, M), (0.0, 0.0)]);
        let diamond = points_json(&[(-M, 0.0), (0.0, -M), (M, 0.0), (0.0, M)]);
        let m2 = sq(&q(M));
        for a in DiameterAlgorithm::ALL {
            let v = run(&["diameter", "-a", a.name(), "-"], &square);
            let eps = printed_rel(LENGTH);
            assert!(
                near_sqrt(&printed(&v["distance"], true), &(q(8.0) * &m2), &eps),
                "{v}"
            );
            assert!(
                near(&printed(&v["width"]["width"], true), &(q(2.0) * q(M)), &eps),
                "{v}"
            );
            let area = printed(&v["rectangle"]["area"], true);
            assert!(near(&area, &(q(4.0) * &m2), &printed_rel(AREA)), "{v}");

            // Tilted: diameter 2 f64::MAX, width √2 f64::MAX, area 2 f64::MAX².
            let v = run(&["diameter", "-a", a.name(), "-"], &diamond);
            assert!(
                near(&printed(&v["distance"], true), &(q(2.0) * q(M)), &eps),
                "{v}"
            );
            assert!(
                near_sqrt(&printed(&v["width"]["width"], true), &(q(2.0) * &m2), &eps),
                "{v}"
            );
            let area = printed(&v["rectangle"]["area"], true);
            assert!(near(&area, &(q(2.0) * &m2), &printed_rel(AREA)), "{v}");

            // Just below: f64::MAX long and 1 high, so the area is f64::MAX too.
            let flat = points_json(&[
                (-M / 2.0, 0.0),
                (M / 2.0, 0.0),
                (M / 2.0, 1.0),
                (-M / 2.0, 1.0),
            ]);
            let v = run(&["diameter", "-a", a.name(), "-"], &flat);
            assert_eq!(v["distance"], M, "{v}"); // √(f64::MAX² + 1), rounded
            assert_eq!(v["width"]["width"], 1.0, "{v}");
            assert_eq!(v["rectangle"]["area"], M, "{v}");
        }
    }

    #[test]
    fn tree_lengths_beyond_f64() {
        // Three sides of the square: 6 f64::MAX.
        let square = points_json(&[(-M, -M), (M, -M), (M, M), (-M, M)]);
        let v = run(&["emst", "-"], &square);
        assert!(
            near(
                &printed(&v["length"], true),
                &(q(6.0) * q(M)),
                &printed_rel(TREE)
            ),
            "{v}"
        );
        // Two halves of the diagonal, 2 √2 f64::MAX, and an edge one ulp of f64::MAX long.
        let pts = [(-M, -M), (0.0, 0.0), (M, M), (M, M - 2f64.powi(971))];
        let v = run(&["emst", "-"], &points_json(&pts));
        let p: Vec<Point2> = pts.iter().map(|&p| Point2::from(p)).collect();
        let edges: Vec<[usize; 2]> = serde_json::from_value(v["edges"].clone()).unwrap();
        let exact = total_length(&p, &edges);
        assert!(
            near_bracket(&printed(&v["length"], true), &exact, &printed_rel(TREE)),
            "{v}"
        );
        // Just below: f64::MAX exactly.
        let half = points_json(&[(-M / 2.0, 0.0), (0.0, 0.0), (M / 2.0, 0.0)]);
        assert_eq!(run(&["emst", "-"], &half)["length"], M);
    }

    #[test]
    fn nearest_distances_beyond_f64() {
        let one = points_json(&[(-M, -M)]);
        let v = run(&["nearest", "--query", &format!("{M:?},{M:?}"), "-"], &one);
        let d = printed(&v["distance"], true);
        assert!(
            near_sqrt(&d, &(q(8.0) * sq(&q(M))), &printed_rel(LENGTH)),
            "{v}"
        );
        let origin = points_json(&[(0.0, 0.0)]);
        let v = run(&["nearest", "--query", &format!("{M:?},0"), "-"], &origin);
        assert_eq!(v["distance"], M);
        let v = run(
            &[
                "nearest",
                "--query",
                &format!("{:?},{:?}", M / 2.0, M / 2.0),
                "-",
            ],
            &origin,
        );
        let d = printed(&v["distance"], false);
        assert!(
            near_sqrt(&d, &(q(2.0) * sq(&q(M / 2.0))), &printed_rel(LENGTH)),
            "{v}"
        );
    }

    #[test]
    fn mst_totals_beyond_f64_and_through_cancellation() {
        let graph = |w: &[f64]| {
            let edges: Vec<String> = w
                .iter()
                .enumerate()
                .map(|(i, w)| format!("[{i},{},{w:?}]", i + 1))
                .collect();
            format!(
                r#"{{"vertices": {}, "edges": [{}]}}"#,
                w.len() + 1,
                edges.join(",")
            )
        };
        for a in MstAlgorithm::ALL {
            let args = ["mst", "-a", a.name(), "-"];
            let v = run(&args, &graph(&[M, M, M]));
            assert!(
                near(
                    &printed(&v["weight"], true),
                    &(q(3.0) * q(M)),
                    &printed_rel(SUM)
                ),
                "{v}"
            );
            // 3 · f64::MAX rounded to 53 bits, then to 17 digits (the exact value's digits
            // are 5.3930794045869471).
            assert_eq!(v["weight"], "5.3930794045869469e308");
            let v = run(&args, &graph(&[1e308, 1.0, -1e308]));
            assert_eq!(v["weight"], 1.0, "{a}: exact, where f64 would give 0");
            let v = run(&args, &graph(&[M / 2.0, M / 2.0]));
            assert_eq!(v["weight"], M, "{a}");
            let v = run(&args, &graph(&[M, M, -M, 5e-324]));
            assert_eq!(v["weight"], M, "{a}: f64::MAX + 2^-1074, rounded once");
        }
    }

    #[test]
    fn empty_circle_radii_beyond_f64() {
        let square = points_json(&[(-M, -M), (M, -M), (M, M), (-M, M)]);
        let v = run(&["empty-circle", "-"], &square);
        let r = printed(&v["radius"], true);
        assert!(
            near_sqrt(&r, &(q(2.0) * sq(&q(M))), &printed_rel(LENGTH)),
            "{v}"
        );
        let half = points_json(&[
            (-M / 2.0, -M / 2.0),
            (M / 2.0, -M / 2.0),
            (M / 2.0, M / 2.0),
            (-M / 2.0, M / 2.0),
        ]);
        let v = run(&["empty-circle", "-"], &half);
        let r = printed(&v["radius"], false);
        assert!(
            near_sqrt(&r, &(q(2.0) * sq(&q(M / 2.0))), &printed_rel(LENGTH)),
            "{v}"
        );
    }

    #[test]
    fn the_decimal_reader_reads_the_printed_form() {
        assert_eq!(decimal_q("1.5e2"), q(150.0));
        assert_eq!(decimal_q("-2.5e-1"), q(-0.25));
        let s = WideFloat::from(M).mul(WideFloat::from(2.0)).to_string();
        let x = decimal_q(&s);
        assert!(near(
            &x,
            &(q(2.0) * q(M)),
            &Q::new(BigInt::from(1), BigInt::from(10).pow(16))
        ));
    }
}
