//! Choosing knots and tangents from the data: the uniform, chord-length and centripetal
//! parameterisations, and tangents estimated from the parabolas through consecutive points.
//!
//! The problem: an interpolant needs knots (and a Hermite interpolant tangents) the data may
//! not give. The idea: make the knot gaps follow the chords (their lengths, or the square
//! roots of their lengths), and take at each point the derivative of the parabola through it
//! and its two neighbours.
//!
//! Follows [PPB, §4.5] (the parameterisations, the tangent estimates and the end conditions
//! `d_0 = 2 Δp_0/Δu_0 − d_1`) and [SPL, §3] (Bessel's end tangents).
//!
//! # Complexity
//!
//! Θ(mD) time and Θ(mD) space for m + 1 points in R^D.

use super::validate::check_knots_and_points;
use crate::spline::scalar::{validate_points, Point, Scalar};
use crate::{Error, Result};

/// How to choose the knots `u_0 < u_1 < ...` of an interpolant from its points
/// ([PPB, §4.5]). Every variant starts at `u_0 = 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Parameterisation {
    /// `Δu_i = 1`: the knots are `0, 1, 2, ...`.
    Uniform,
    /// `Δu_i = ‖Δp_i‖`, the length of the chord.
    ChordLength,
    /// `Δu_i = √‖Δp_i‖` (Lee's centripetal parameterisation).
    Centripetal,
}

/// Tangents for Hermite interpolation estimated from the data ([PPB, §4.5]): at an interior
/// knot the derivative of the parabola through the point and its two neighbours,
/// `d_i = (1 − α_i) Δp_{i−1}/Δu_{i−1} + α_i Δp_i/Δu_i` with `α_i = Δu_{i−1}/(Δu_{i−1} + Δu_i)`;
/// at the ends `d_0 = 2 Δp_0/Δu_0 − d_1` and `d_m = 2 Δp_{m−1}/Δu_{m−1} − d_{m−1}` (the end
/// derivatives of the first and last parabolas). With two points both tangents are the chord
/// slope.
///
/// # Errors
///
/// As [`hermite`](super::hermite()) without the tangents.
///
/// # Complexity
///
/// Θ(m·D) time and space. Nothing is counted.
///
/// ```
/// use compgeo::spline::{estimate_tangents, Point};
///
/// // Samples of the parabola u² get its exact derivative 2u everywhere.
/// let pts = [Point::new([0.0]), Point::new([1.0]), Point::new([9.0]), Point::new([16.0])];
/// let d = estimate_tangents(&[0.0, 1.0, 3.0, 4.0], &pts)?;
/// assert_eq!(d, vec![Point::new([0.0]), Point::new([2.0]), Point::new([6.0]), Point::new([8.0])]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn estimate_tangents<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
) -> Result<Vec<Point<S, D>>> {
    check_knots_and_points(partition, points, 2)?;
    let m = points.len() - 1;
    let h: Vec<S> = partition.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    let delta: Vec<Point<S, D>> = (0..m)
        .map(|i| (points[i + 1].clone() - &points[i]) / &h[i])
        .collect();
    if m == 1 {
        return Ok(vec![delta[0].clone(), delta[0].clone()]);
    }
    let mut d = Vec::with_capacity(m + 1);
    d.push(parabola_end_tangent(&h[0], &h[1], &delta[0], &delta[1]));
    for i in 1..m {
        let sum = h[i - 1].clone() + &h[i];
        d.push((delta[i - 1].clone() * &h[i] + &(delta[i].clone() * &h[i - 1])) / &sum);
    }
    d.push(parabola_end_tangent(
        &h[m - 1],
        &h[m - 2],
        &delta[m - 1],
        &delta[m - 2],
    ));
    Ok(d)
}

/// The knots of `points` under a [`Parameterisation`], starting at 0.
///
/// Uniform knots are exact integers. Chord-length and centripetal knots need square roots:
/// they are computed in `f64` (`‖Δp‖ = √(Σ Δp_k²)` of the coordinates rounded to `f64`), and
/// the rounded sums are converted exactly into `S`, so with rationals the knots are the
/// rationals equal to those doubles.
///
/// # Errors
///
/// [`Error::Empty`] / [`Error::NonFinite`] for no points or a bad coordinate;
/// [`Error::InvalidParameter`] (`"points"`) for chord-length or centripetal knots when two
/// consecutive points coincide (the interval would be empty) or a chord overflows `f64`.
///
/// # Complexity
///
/// Θ(m·D) time and Θ(m) space.
///
/// ```
/// use compgeo::spline::{parameterise, Parameterisation, Point};
///
/// let pts = [Point::new([0.0, 0.0]), Point::new([3.0, 4.0]), Point::new([3.0, 13.0])];
/// assert_eq!(parameterise(&pts, Parameterisation::Uniform)?, vec![0.0, 1.0, 2.0]);
/// assert_eq!(parameterise(&pts, Parameterisation::ChordLength)?, vec![0.0, 5.0, 14.0]);
/// let c = parameterise(&pts, Parameterisation::Centripetal)?;
/// assert_eq!(c[2], 5f64.sqrt() + 3.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn parameterise<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    kind: Parameterisation,
) -> Result<Vec<S>> {
    validate_points(points, "points")?;
    if kind == Parameterisation::Uniform {
        return Ok((0..points.len()).map(|i| S::from_i64(i as i64)).collect());
    }
    let mut knots = Vec::with_capacity(points.len());
    let mut u = 0.0f64;
    knots.push(S::zero());
    for (i, w) in points.windows(2).enumerate() {
        let chord = (w[1].clone() - &w[0]).to_f64();
        // Scale by the largest coordinate so the sum of squares neither overflows nor underflows.
        let scale = chord.coords().iter().fold(0.0f64, |a, c| a.max(c.abs()));
        if scale == 0.0 {
            return Err(Error::InvalidParameter {
                name: "points",
                reason: format!(
                    "points {i} and {} coincide: the knot interval would be empty",
                    i + 1
                ),
            });
        }
        let length = scale
            * chord
                .coords()
                .iter()
                .map(|c| (c / scale) * (c / scale))
                .sum::<f64>()
                .sqrt();
        let step = match kind {
            Parameterisation::ChordLength => length,
            _ => length.sqrt(),
        };
        u += step;
        let knot = S::from_f64(u).ok_or_else(|| Error::InvalidParameter {
            name: "points",
            reason: "the total chord length overflows f64".to_string(),
        })?;
        knots.push(knot);
    }
    Ok(knots)
}

/// The derivative at the first knot of the parabola through three consecutive points, from
/// its two chord slopes: `p'(u_0) = 2 δ_0 − p'(u_1)` with
/// `p'(u_1) = (h_1 δ_0 + h_0 δ_1)/(h_0 + h_1)` ([PPB, §4.5]). With the arguments mirrored
/// (`h_{n−1}, h_{n−2}, δ_{n−1}, δ_{n−2}`) it gives the derivative at the last knot.
pub(super) fn parabola_end_tangent<S: Scalar, const D: usize>(
    h0: &S,
    h1: &S,
    delta0: &Point<S, D>,
    delta1: &Point<S, D>,
) -> Point<S, D> {
    let inner = (delta0.clone() * h1 + &(delta1.clone() * h0)) / (h0.clone() + h1);
    delta0.clone() * S::from_i64(2) - &inner
}
