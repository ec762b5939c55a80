//! Piecewise cubic Hermite interpolation as a composite cubic Bézier curve.
//!
//! The problem: a C¹ curve through points at given knots with given derivatives there
//! (tangents estimated from the data are in `parameterise.rs`). The idea: the cubic over
//! `[u_i, u_{i+1}]` with `h_i = u_{i+1} − u_i` has the Bézier points `p_i`,
//! `p_i + h_i d_i / 3`, `p_{i+1} − h_i d_{i+1} / 3`, `p_{i+1}`, since a cubic's end
//! derivatives are `3 (b_1 − b_0)/h` and `3 (b_3 − b_2)/h`.
//!
//! Follows [RD, §3.2] ("Interpolación cúbica de Hermite": `P_{3i±1} = Q_i ± (Δu/3) D_i` and
//! the worked example through (0,1), (5,2), (10,5), (6,9), (5,4)), [PPB, §4.5] (the Bézier
//! points `b_{3i+1} = p_i + d_i Δu_i/3`, `b_{3i+2} = p_{i+1} − d_{i+1} Δu_i/3`) and
//! [SPL, §4] ("Cúbicas C1 a trozos", equations (12)).
//!
//! # Complexity
//!
//! Θ(mD) time and space for m + 1 points in R^D.

use super::validate::{check_knots_and_points, overflow};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{validate_points, Point, Scalar};
use crate::spline::CompositeBezier;
use crate::{Error, Result};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and claims.
pub(crate) const HERMITE: Declaration = Declaration {
    problem: "interpolate",
    name: "hermite",
    function: "spline::hermite",
    file: "src/spline/interpolate/hermite.rs",
    summary: "piecewise cubic Hermite interpolation as composite Bézier curves",
    time: "Θ(m·D)",
    space: "Θ(m·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 2m point multiply-adds for m pieces: two inner Bézier points each",
    source: "[RD, §3.2]",
    claims: &[on(
        "random-points",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The piecewise cubic C¹ curve through `points` at the knots `partition` with the
/// derivatives `tangents` there, as a composite cubic Bézier curve.
///
/// The idea ([RD, §3.2], [PPB, §4.5]): the cubic over `[u_i, u_{i+1}]` with
/// `h_i = u_{i+1} − u_i` has Bézier points `p_i`, `p_i + h_i d_i / 3`,
/// `p_{i+1} − h_i d_{i+1} / 3`, `p_{i+1}`, since a cubic's end derivatives are
/// `3 (b_1 − b_0)/h` and `3 (b_3 − b_2)/h`. Exact with rationals: the course's worked example
/// comes out digit for digit.
///
/// # Errors
///
/// [`Error::TooFew`] for fewer than two points; [`Error::InvalidParameter`] for mismatched
/// lengths (`"points"`, `"tangents"`) or a non-finite, non-increasing partition
/// (`"partition"`), and (`"points"`) when an `f64` control point overflows;
/// [`Error::NonFinite`] for a bad coordinate.
///
/// # Complexity
///
/// Θ(m·D) time and space for `m + 1` points in R^D.
///
/// ```
/// use compgeo::spline::{hermite, Point};
///
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// let c = hermite(&[0.0, 0.5], &[p(0.0, 1.0), p(5.0, 2.0)], &[p(6.0, 12.0), p(12.0, -12.0)])?;
/// assert_eq!(c.pieces()[0].control(), [p(0.0, 1.0), p(1.0, 3.0), p(3.0, 4.0), p(5.0, 2.0)]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hermite<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
    tangents: &[Point<S, D>],
) -> Result<CompositeBezier<S, D>> {
    hermite_with(partition, points, tangents, &mut NoCount)
}

/// [`hermite`], counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// inner Bézier point (a point plus or minus a scaled tangent): exactly 2m for m pieces.
///
/// # Errors
///
/// As [`hermite`].
///
/// # Complexity
///
/// Θ(m·D) time and space for `m + 1` points in R^D.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{hermite_with, Point};
///
/// let p = |x: f64| Point::new([x]);
/// let mut c = Counts::default();
/// hermite_with(&[0.0, 1.0, 3.0, 4.0], &[p(0.0), p(1.0), p(0.0), p(2.0)], &[p(1.0); 4], &mut c)?;
/// assert_eq!(c.arithmetic_operations, 2 * 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hermite_with<S: Scalar, const D: usize, C: Counter>(
    partition: &[S],
    points: &[Point<S, D>],
    tangents: &[Point<S, D>],
    counter: &mut C,
) -> Result<CompositeBezier<S, D>> {
    check_knots_and_points(partition, points, 2)?;
    if tangents.len() != points.len() {
        return Err(Error::InvalidParameter {
            name: "tangents",
            reason: format!("{} tangents for {} points", tangents.len(), points.len()),
        });
    }
    validate_points(tangents, "tangents")?;
    let three = S::from_i64(3);
    let pieces: Vec<Vec<Point<S, D>>> = (0..points.len() - 1)
        .map(|i| {
            let third = (partition[i + 1].clone() - &partition[i]) / &three;
            counter.arithmetic_operation();
            counter.arithmetic_operation();
            vec![
                points[i].clone(),
                points[i].clone() + &(tangents[i].clone() * &third),
                points[i + 1].clone() - &(tangents[i + 1].clone() * &third),
                points[i + 1].clone(),
            ]
        })
        .collect();
    if pieces.iter().flatten().any(|p| !p.is_finite()) {
        return Err(overflow());
    }
    CompositeBezier::new(partition.to_vec(), pieces)
}
