//! Helpers shared by the B-spline and NURBS tests: small integer points, the exact copy of an
//! `f64` curve, and the rational sample parameters of a domain.

use super::{q, Q};
use compgeo::spline::{BSpline, KnotVector, Point, Scalar};

/// A point of the plane with integer coordinates (any scalar).
pub fn point<S: Scalar>((x, y): (i64, i64)) -> Point<S, 2> {
    Point::new([S::from_i64(x), S::from_i64(y)])
}

/// The exact curve with the same knots and control points as an `f64` one.
pub fn exact(s: &BSpline<f64, 2>) -> BSpline<Q, 2> {
    let knots = s
        .knots()
        .knots()
        .iter()
        .map(|k| <Q as Scalar>::from_f64(*k).unwrap())
        .collect();
    let t = KnotVector::new(s.degree(), knots).unwrap();
    let c = s
        .control()
        .iter()
        .map(|p| Point::from_f64(p).unwrap())
        .collect();
    BSpline::new(c, t).unwrap()
}

/// Every knot of the domain and 25 rationals evenly across it.
pub fn samples(t: &KnotVector<Q>) -> Vec<Q> {
    let (a, b) = (t.bounds().0.clone(), t.bounds().1.clone());
    let mut us: Vec<Q> = (0..=24)
        .map(|k| a.clone() + (b.clone() - &a) * q(k, 24))
        .collect();
    us.extend(t.knots().iter().filter(|k| **k >= a && **k <= b).cloned());
    us
}
