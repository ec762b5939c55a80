//! Exact-rational helpers shared by the spline tests: short constructors, a reader for the
//! integer pairs printed in the seeds, and the properties every curve type must have
//! (`curve_properties`).

pub mod bspline;
pub mod curve_properties;

use compgeo::spline::Point;
use num_bigint::BigInt;
use num_rational::BigRational;

/// The exact scalar of the spline tests.
pub type Q = BigRational;

/// The rational n/d.
pub fn q(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

/// The integer n as a rational.
pub fn qi(n: i64) -> Q {
    q(n, 1)
}

/// The exact numbers of a JSON list the command line printed with `--exact` (strings such
/// as "47/18").
#[cfg(feature = "cli")]
pub fn json_list(v: &serde_json::Value) -> Vec<Q> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_str().unwrap().parse().unwrap())
        .collect()
}

/// The exact plane points of a JSON list of pairs printed with `--exact`.
#[cfg(feature = "cli")]
pub fn json_points(v: &serde_json::Value) -> Vec<Point<Q, 2>> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let c = json_list(p);
            Point::new([c[0].clone(), c[1].clone()])
        })
        .collect()
}

/// A point of the plane with rational coordinates.
pub fn p2(x: Q, y: Q) -> Point<Q, 2> {
    Point::new([x, y])
}
/// Reads "(a, b)" or "[a, b]" pairs of integers out of a line of the course.
pub fn pairs(line: &str) -> Vec<Point<Q, 2>> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(start) = rest.find(['(', '[']) {
        let close = if rest.as_bytes()[start] == b'(' {
            ')'
        } else {
            ']'
        };
        let end = start + rest[start..].find(close).unwrap();
        let inner = &rest[start + 1..end];
        let nums: Vec<i64> = inner
            .split(',')
            .map(|s| s.trim().parse().unwrap())
            .collect();
        assert_eq!(nums.len(), 2, "{inner}");
        out.push(p2(qi(nums[0]), qi(nums[1])));
        rest = &rest[end + 1..];
    }
    out
}
