//! Piecewise cubic Hermite interpolation as a composite cubic Bézier curve, with given or
//! estimated tangents, and the parameterisations that choose the knots.
//!
//! Seed 003 §3.2 ("Interpolación cúbica de Hermite": `P_{3i±1} = Q_i ± (Δu/3) D_i` and the
//! worked example through (0,1), (5,2), (10,5), (6,9), (5,4)); seed 000 §4.5 (the Bézier points
//! `b_{3i+1} = p_i + d_i Δu_i/3`, `b_{3i+2} = p_{i+1} − d_{i+1} Δu_i/3`; tangents from the
//! parabola through three consecutive points and the end conditions
//! `d_0 = 2 Δp_0/Δu_0 − d_1`; uniform, chord-length and centripetal parameterisations);
//! seed 001 §4 ("Cúbicas C1 a trozos", equations (12)).

use super::cubic_spline::parabola_end_tangent;
use super::interpolate::{check_nodes_and_points, check_partition};
use super::{CompositeBezier, Point, Scalar};
use crate::{Error, Result};

/// How to choose the knots `u_0 < u_1 < ...` of an interpolant from its points
/// (seed 000 §4.5). Every variant starts at `u_0 = 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Parameterisation {
    /// `Δu_i = 1`: the knots are `0, 1, 2, ...`.
    Uniform,
    /// `Δu_i = ‖Δp_i‖`, the length of the chord.
    ChordLength,
    /// `Δu_i = √‖Δp_i‖` (Lee's centripetal parameterisation).
    Centripetal,
}

/// The piecewise cubic C¹ curve through `points` with the derivatives `tangents` at the knots
/// `partition`, as a composite cubic Bézier curve.
///
/// The idea (seed 003 §3.2, seed 000 §4.5): the cubic over `[u_i, u_{i+1}]` with
/// `h_i = u_{i+1} − u_i` has Bézier points `p_i`, `p_i + h_i d_i / 3`,
/// `p_{i+1} − h_i d_{i+1} / 3`, `p_{i+1}`, since a cubic's end derivatives are
/// `3 (b_1 − b_0)/h` and `3 (b_3 − b_2)/h`. Exact with rationals: the seed's worked example
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
/// Θ(m·D) time and space for `m + 1` points in R^D. Nothing is counted.
///
/// ```
/// use compgeo::spline::{hermite, Point};
///
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// let c = hermite(&[p(0.0, 1.0), p(5.0, 2.0)], &[p(6.0, 12.0), p(12.0, -12.0)], &[0.0, 0.5])?;
/// assert_eq!(c.pieces()[0].control(), [p(0.0, 1.0), p(1.0, 3.0), p(3.0, 4.0), p(5.0, 2.0)]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hermite<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    tangents: &[Point<S, D>],
    partition: &[S],
) -> Result<CompositeBezier<S, D>> {
    check_points_partition(points, partition)?;
    if tangents.len() != points.len() {
        return Err(Error::InvalidParameter {
            name: "tangents",
            reason: format!("{} tangents for {} points", tangents.len(), points.len()),
        });
    }
    super::validate_points(tangents, "tangents")?;
    let three = S::from_i64(3);
    let pieces: Vec<Vec<Point<S, D>>> = (0..points.len() - 1)
        .map(|i| {
            let third = (partition[i + 1].clone() - &partition[i]) / &three;
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

/// Tangents for Hermite interpolation estimated from the data (seed 000 §4.5): at an interior
/// knot the derivative of the parabola through the point and its two neighbours,
/// `d_i = (1 − α_i) Δp_{i−1}/Δu_{i−1} + α_i Δp_i/Δu_i` with `α_i = Δu_{i−1}/(Δu_{i−1} + Δu_i)`;
/// at the ends `d_0 = 2 Δp_0/Δu_0 − d_1` and `d_m = 2 Δp_{m−1}/Δu_{m−1} − d_{m−1}` (the end
/// derivatives of the first and last parabolas). With two points both tangents are the chord
/// slope.
///
/// # Errors
///
/// As [`hermite`] without the tangents.
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
/// let d = estimate_tangents(&pts, &[0.0, 1.0, 3.0, 4.0])?;
/// assert_eq!(d, vec![Point::new([0.0]), Point::new([2.0]), Point::new([6.0]), Point::new([8.0])]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn estimate_tangents<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    partition: &[S],
) -> Result<Vec<Point<S, D>>> {
    check_points_partition(points, partition)?;
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
    super::validate_points(points, "points")?;
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

/// The error for finite data whose Bézier points are beyond the `f64` range.
pub(crate) fn overflow() -> Error {
    Error::InvalidParameter {
        name: "points",
        reason: "the control points overflow f64 (large coordinates, tangents or knot gaps); \
                 use exact rationals"
            .to_string(),
    }
}

/// Points and partition of an interpolant: at least two, equal lengths, finite, increasing.
fn check_points_partition<S: Scalar, const D: usize>(
    points: &[Point<S, D>],
    partition: &[S],
) -> Result<()> {
    if points.len() < 2 {
        return Err(Error::TooFew {
            what: "points",
            needed: 2,
            got: points.len(),
        });
    }
    check_nodes_and_points(partition, points)?;
    check_partition(partition, 2, "partition")
}
