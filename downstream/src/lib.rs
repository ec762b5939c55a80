//! A dependent crate of `compgeo`, kept in the repository to time the public API from outside.
//!
//! Benchmarks inside a crate can be flattered by what the crate's own build settles (its
//! features, its profile, code it inlines into itself), and a loop over a slice of parameters
//! lets the compiler interleave many evaluations. A user's crate does neither: it depends on
//! `compgeo` without default features, builds with the default release profile, and calls
//! `eval` once per point it needs. This crate does the same. Its bench `per_call` times one
//! call at a time, each parameter and each result passed through `black_box`, against kurbo's
//! `CubicBez::eval` on the same curve and parameters.
//!
//! Run it from the repository root with `cargo bench -p compgeo-downstream`.
//!
//! # Example
//!
//! ```
//! use compgeo::spline::Curve;
//!
//! let (curve, ts) = compgeo_downstream::cubic_and_parameters(8, 1);
//! assert_eq!(ts.len(), 8);
//! let p = curve.eval(&ts[0]).unwrap();
//! assert!(p.0[0].is_finite() && p.0[1].is_finite());
//! ```

use compgeo::gen::{points, PointKind};
use compgeo::spline::{Bezier, Point};

/// A seeded cubic Bézier curve in the unit square and `count` seeded parameters in [0, 1),
/// the inputs every variant of the bench shares.
///
/// # Panics
///
/// Never for counts the generator accepts (it refuses absurd sizes, which the bench never
/// asks for).
pub fn cubic_and_parameters(count: usize, seed: u64) -> (Bezier<f64, 2>, Vec<f64>) {
    let control = points(PointKind::UniformSquare, 4, seed).expect("four points");
    let curve = Bezier::new(control.iter().map(|q| Point::new([q.x, q.y])).collect())
        .expect("finite control points");
    let ts = points(PointKind::UniformSquare, count, seed + 1)
        .expect("parameters")
        .into_iter()
        .map(|q| q.x)
        .collect();
    (curve, ts)
}

/// The control points of `curve` as arrays, for building the same curve in another crate.
pub fn control_points(curve: &Bezier<f64, 2>) -> Vec<[f64; 2]> {
    curve.control().iter().map(|p| p.0).collect()
}
