//! C² cubic spline interpolation with natural, clamped, Bessel and periodic end conditions,
//! in O(n) by a tridiagonal (or cyclic tridiagonal) solve.
//!
//! Seed 003 §3.1 ("Spline cúbico": a C² function made of cubics with zero second derivative at
//! its ends); seed 001 §3 ("Cúbicas C2 a trozos": the natural condition (10), the clamped
//! tangents (11), Bessel's tangents from the parabola through the first and last three
//! points, and the periodic case of closed curves); seed 000 §4.5 for the Hermite form the
//! result is returned in.
//!
//! The unknowns are the tangents `m_i = s'(u_i)`: with `h_i = u_{i+1} − u_i` and
//! `δ_i = (a_{i+1} − a_i)/h_i`, continuity of the second derivative at an interior knot is
//!
//! `h_i m_{i−1} + 2(h_{i−1} + h_i) m_i + h_{i−1} m_{i+1} = 3(h_i δ_{i−1} + h_{i−1} δ_i)`,
//!
//! a strictly diagonally dominant tridiagonal system, so elimination without pivoting is
//! stable in `f64` and never meets a zero pivot with rationals. The tangents then give the
//! cubic Bézier pieces of [`hermite`](super::hermite()) (the C² spline is the C¹ Hermite
//! interpolant of its own tangents).

use super::interpolate::{check_nodes_and_points, check_partition};
use super::{hermite, CompositeBezier, Point, Scalar};
use crate::count::{Counter, NoCount};
use crate::{Error, Result};
use crate::complexity::{on, Bound, Declaration};
use crate::count::Operation;

/// The C² cubic spline's tangents with natural ends, declared.
pub(crate) const NATURAL: Declaration = Declaration {
    problem: "spline",
    name: "cubic-natural",
    function: "spline::cubic_spline_tangents",
    file: "src/spline/cubic_spline.rs",
    summary: "the tangents of the natural C² cubic spline by a tridiagonal solve",
    time: "Θ(n·D)",
    space: "Θ(n·D)",
    operation: Operation::ArithmeticOperations,
    counts: "exactly 7n + 4 point operations",
    source: "[RD, §3.1]",
    claims: &[on("uniform-square", Bound::Linear, Operation::ArithmeticOperations)],
};

/// The C² cubic spline's tangents with periodic ends, declared.
pub(crate) const PERIODIC: Declaration = Declaration {
    problem: "spline",
    name: "cubic-periodic",
    function: "spline::cubic_spline_tangents",
    file: "src/spline/cubic_spline.rs",
    summary: "the tangents of the periodic C² cubic spline by a cyclic tridiagonal solve",
    time: "Θ(n·D)",
    space: "Θ(n·D)",
    operation: Operation::ArithmeticOperations,
    counts: "Θ(n) point operations",
    source: "[RD, §3.1]",
    claims: &[on("uniform-square", Bound::Linear, Operation::ArithmeticOperations)],
};

/// What the spline does at its two ends (the two conditions a C² cubic spline needs besides
/// its data).
#[derive(Clone, Debug, PartialEq)]
pub enum EndCondition<S, const D: usize> {
    /// Zero second derivative at both ends (seed 003 Def. 3.5; seed 001 (10)).
    Natural,
    /// Prescribed first derivatives at the two ends (seed 001 (11)).
    Clamped {
        /// `s'(u_0)`.
        start: Point<S, D>,
        /// `s'(u_n)`.
        end: Point<S, D>,
    },
    /// The end tangents of the parabolas through the first three and the last three points
    /// (seed 001 §3, Bessel's condition; seed 000 §4.5's end estimate). Needs three points.
    Bessel,
    /// A closed curve: the first and last points must be equal, and the value, first and
    /// second derivatives agree there (the system closes cyclically). Needs three points
    /// (two pieces).
    Periodic,
}

/// The tangents `s'(u_0), ..., s'(u_n)` of the C² cubic spline through `points` at the knots
/// `partition` with the given end condition.
///
/// The idea: the C² conditions at the interior knots are a tridiagonal system in the tangents
/// (see the module doc); the end condition adds its first and last rows (natural:
/// `2 m_0 + m_1 = 3 δ_0`; clamped and Bessel: `m_0` given), or, for a periodic spline,
/// wraps the system around, which is then solved by the Sherman–Morrison correction of a
/// tridiagonal solve.
///
/// # Errors
///
/// [`Error::TooFew`] for fewer than two points (three for Bessel and periodic);
/// [`Error::InvalidParameter`] (`"partition"`) for a non-finite or non-increasing partition,
/// (`"points"`) for mismatched lengths or a periodic spline whose first and last points differ;
/// [`Error::NonFinite`] for a bad coordinate (also of clamped tangents, reported as indices
/// `n + 1` and `n + 2`); [`Error::InvalidParameter`] (`"points"`) if an `f64` tangent
/// overflows.
///
/// # Complexity
///
/// Θ(n·D) time and Θ(n·D) auxiliary space for `n + 1` points in R^D. Nothing is counted (no
/// geometric decision is made).
///
/// ```
/// use compgeo::spline::{cubic_spline_tangents, EndCondition, Point};
///
/// // A natural spline through collinear, evenly spaced data is the straight line itself.
/// let pts: Vec<_> = (0..5).map(|i| Point::new([2.0 * i as f64])).collect();
/// let m = cubic_spline_tangents(&[0.0, 1.0, 2.0, 3.0, 4.0], &pts, &EndCondition::Natural)?;
/// assert!(m.iter().all(|t| (t[0] - 2.0).abs() < 1e-12)); // exactly 2 with rationals
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn cubic_spline_tangents<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
    end: &EndCondition<S, D>,
) -> Result<Vec<Point<S, D>>> {
    cubic_spline_tangents_with(partition, points, end, &mut NoCount)
}

/// [`cubic_spline_tangents`] that counts its arithmetic steps on points (a scaled difference,
/// a multiply-add or a scaling of a point, each one
/// [`arithmetic_operation`](Counter::arithmetic_operation)): exactly `7n + 4` for `n + 1`
/// points with the open end conditions, at most `8n` with the periodic one.
///
/// # Errors
///
/// As [`cubic_spline_tangents`].
///
/// # Complexity
///
/// Θ(n·D) time and Θ(n·D) auxiliary space; Θ(n) counted operations.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{cubic_spline_tangents_with, EndCondition, Point};
///
/// let pts: Vec<_> = (0..100).map(|i| Point::new([(i * i % 7) as f64])).collect();
/// let knots: Vec<f64> = (0..100).map(f64::from).collect();
/// let mut counts = Counts::default();
/// cubic_spline_tangents_with(&knots, &pts, &EndCondition::Natural, &mut counts)?;
/// assert_eq!(counts.arithmetic_operations, 7 * 99 + 4);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn cubic_spline_tangents_with<S: Scalar, const D: usize, C: Counter>(
    partition: &[S],
    points: &[Point<S, D>],
    end: &EndCondition<S, D>,
    counter: &mut C,
) -> Result<Vec<Point<S, D>>> {
    let needed = match end {
        EndCondition::Natural | EndCondition::Clamped { .. } => 2,
        EndCondition::Bessel | EndCondition::Periodic => 3,
    };
    if points.len() < needed {
        return Err(Error::TooFew {
            what: "points",
            needed,
            got: points.len(),
        });
    }
    check_nodes_and_points(partition, points)?;
    check_partition(partition, needed, "partition")?;
    let n = points.len() - 1;
    let h: Vec<S> = partition.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    let delta: Vec<Point<S, D>> = (0..n)
        .map(|i| (points[i + 1].clone() - &points[i]) / &h[i])
        .collect();
    // The differences, then three point operations per right-hand side.
    count(counter, 4 * n);
    let three = S::from_i64(3);
    let two = S::from_i64(2);
    // Row i of the interior equations: (sub, diag, sup, rhs).
    let interior = |i: usize| {
        let rhs = (delta[i - 1].clone() * &h[i] + &(delta[i].clone() * &h[i - 1])) * &three;
        (
            h[i].clone(),
            (h[i - 1].clone() + &h[i]) * &two,
            h[i - 1].clone(),
            rhs,
        )
    };
    if let EndCondition::Periodic = end {
        if points[0] != points[n] {
            return Err(Error::InvalidParameter {
                name: "points",
                reason: "a periodic spline needs its first and last points equal".to_string(),
            });
        }
        // Unknowns m_0..m_{n-1} with m_n = m_0; row 0 wraps to h_{n-1}, δ_{n-1}.
        let mut sub = Vec::with_capacity(n);
        let mut diag = Vec::with_capacity(n);
        let mut sup = Vec::with_capacity(n);
        let mut rhs = Vec::with_capacity(n);
        let rhs0 = (delta[n - 1].clone() * &h[0] + &(delta[0].clone() * &h[n - 1])) * &three;
        sub.push(h[0].clone());
        diag.push((h[n - 1].clone() + &h[0]) * &two);
        sup.push(h[n - 1].clone());
        rhs.push(rhs0);
        for i in 1..n {
            let (a, b, c, r) = interior(i);
            sub.push(a);
            diag.push(b);
            sup.push(c);
            rhs.push(r);
        }
        let mut m = solve_cyclic(&sub, &diag, &sup, rhs, counter);
        m.push(m[0].clone());
        return finite(m);
    }
    let mut sub = Vec::with_capacity(n + 1);
    let mut diag = Vec::with_capacity(n + 1);
    let mut sup = Vec::with_capacity(n + 1);
    let mut rhs = Vec::with_capacity(n + 1);
    let (first, last) = match end {
        EndCondition::Natural => (None, None),
        EndCondition::Clamped { start, end } => {
            for (k, t) in [start, end].into_iter().enumerate() {
                if let Some(c) = t.coords().iter().find(|c| !c.is_finite()) {
                    return Err(Error::NonFinite {
                        index: n + 1 + k,
                        value: c.to_f64(),
                    });
                }
            }
            (Some(start.clone()), Some(end.clone()))
        }
        EndCondition::Bessel => {
            let start = parabola_end_tangent(&h[0], &h[1], &delta[0], &delta[1]);
            let end = parabola_end_tangent(&h[n - 1], &h[n - 2], &delta[n - 1], &delta[n - 2]);
            (Some(start), Some(end))
        }
        EndCondition::Periodic => unreachable!("handled above"),
    };
    // Row 0: m_0 given, or natural 2 m_0 + m_1 = 3 δ_0.
    match first {
        Some(t) => {
            diag.push(S::one());
            sup.push(S::zero());
            rhs.push(t);
        }
        None => {
            diag.push(two.clone());
            sup.push(S::one());
            rhs.push(delta[0].clone() * &three);
        }
    }
    sub.push(S::zero());
    for i in 1..n {
        let (a, b, c, r) = interior(i);
        sub.push(a);
        diag.push(b);
        sup.push(c);
        rhs.push(r);
    }
    // Row n: m_n given, or natural m_{n-1} + 2 m_n = 3 δ_{n-1}.
    match last {
        Some(t) => {
            sub.push(S::zero());
            diag.push(S::one());
            rhs.push(t);
        }
        None => {
            sub.push(S::one());
            diag.push(two);
            rhs.push(delta[n - 1].clone() * &three);
        }
    }
    sup.push(S::zero());
    count(counter, 2);
    finite(solve_tridiagonal(&sub, &diag, &sup, rhs, counter))
}

/// The C² cubic spline through `points` at the knots `partition`, as a composite cubic Bézier
/// curve.
///
/// Computes the tangents with [`cubic_spline_tangents`] and builds the pieces with
/// [`hermite`](super::hermite()): `b_{3i+1} = a_i + h_i m_i / 3`, `b_{3i+2} = a_{i+1} − h_i m_{i+1} / 3`.
///
/// # Errors
///
/// As [`cubic_spline_tangents`].
///
/// # Complexity
///
/// Θ(n·D) time and Θ(n·D) space for `n + 1` points in R^D. Nothing is counted.
///
/// ```
/// use compgeo::spline::{cubic_spline, EndCondition, Point};
///
/// let pts = [Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([3.0, 1.0])];
/// let s = cubic_spline(&[0.0, 1.0, 2.0], &pts, &EndCondition::Natural)?;
/// assert_eq!(s.eval(&1.0)?, pts[1]);
/// // Natural: the second derivative vanishes at both ends (exactly with rationals).
/// let d2 = s.derivative_at(&0.0, 2)?;
/// assert!(d2[0].abs() < 1e-12 && d2[1].abs() < 1e-12);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn cubic_spline<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
    end: &EndCondition<S, D>,
) -> Result<CompositeBezier<S, D>> {
    let tangents = cubic_spline_tangents(partition, points, end)?;
    hermite(points, &tangents, partition)
}

/// The derivative at the first knot of the parabola through three consecutive points, from
/// its two chord slopes: `p'(u_0) = 2 δ_0 − p'(u_1)` with
/// `p'(u_1) = (h_1 δ_0 + h_0 δ_1)/(h_0 + h_1)` (seed 000 §4.5). With the arguments mirrored
/// (`h_{n−1}, h_{n−2}, δ_{n−1}, δ_{n−2}`) it gives the derivative at the last knot.
pub(crate) fn parabola_end_tangent<S: Scalar, const D: usize>(
    h0: &S,
    h1: &S,
    delta0: &Point<S, D>,
    delta1: &Point<S, D>,
) -> Point<S, D> {
    let inner = (delta0.clone() * h1 + &(delta1.clone() * h0)) / (h0.clone() + h1);
    delta0.clone() * S::from_i64(2) - &inner
}

/// Thomas' algorithm for a tridiagonal system with point right-hand sides: row `i` is
/// `sub[i] x_{i−1} + diag[i] x_i + sup[i] x_{i+1} = rhs[i]` (`sub[0]`, `sup[n−1]` unused).
/// The callers' matrices are strictly diagonally dominant, so no pivot is zero.
fn solve_tridiagonal<S: Scalar, const D: usize, C: Counter>(
    sub: &[S],
    diag: &[S],
    sup: &[S],
    mut rhs: Vec<Point<S, D>>,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let n = diag.len();
    // One scaling of the first row, a multiply-add and a scaling per later row, one
    // multiply-add per row back.
    count(counter, 3 * n - 1);
    // One division per row: points are scaled by the pivot's reciprocal.
    let mut c = Vec::with_capacity(n);
    let mut inverse = S::one() / &diag[0];
    c.push(sup[0].clone() * &inverse);
    rhs[0] = rhs[0].clone() * &inverse;
    for i in 1..n {
        inverse = S::one() / (diag[i].clone() - &(sub[i].clone() * &c[i - 1]));
        c.push(sup[i].clone() * &inverse);
        let prev = rhs[i - 1].clone() * &sub[i];
        rhs[i] = (rhs[i].clone() - &prev) * &inverse;
    }
    for i in (0..n - 1).rev() {
        let next = rhs[i + 1].clone() * &c[i];
        rhs[i] -= &next;
    }
    rhs
}

/// A cyclic tridiagonal system: as [`solve_tridiagonal`] plus the corners
/// `A[0][n−1] = sub[0]` and `A[n−1][0] = sup[n−1]`, by the Sherman–Morrison formula
/// (two tridiagonal solves). Needs `n ≥ 2`; for `n = 2` the corners fold into the
/// off-diagonals.
fn solve_cyclic<S: Scalar, const D: usize, C: Counter>(
    sub: &[S],
    diag: &[S],
    sup: &[S],
    rhs: Vec<Point<S, D>>,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let n = diag.len();
    if n == 2 {
        count(counter, 4);
        let (a, b) = (diag[0].clone(), sup[0].clone() + &sub[0]);
        let (c, d) = (sub[1].clone() + &sup[1], diag[1].clone());
        let det = a.clone() * &d - &(b.clone() * &c);
        let x0 = (rhs[0].clone() * &d - &(rhs[1].clone() * &b)) / &det;
        let x1 = (rhs[1].clone() * &a - &(rhs[0].clone() * &c)) / &det;
        return vec![x0, x1];
    }
    let (beta, alpha) = (sub[0].clone(), sup[n - 1].clone());
    // A = T + w vᵀ with w = (γ, 0, ..., 0, α), v = (1, 0, ..., 0, β/γ).
    let gamma = -diag[0].clone();
    let mut modified = diag.to_vec();
    modified[0] = diag[0].clone() - &gamma;
    modified[n - 1] = diag[n - 1].clone() - &(alpha.clone() * &beta / &gamma);
    let y = solve_tridiagonal(sub, &modified, sup, rhs, counter);
    let mut w = vec![Point::<S, 1>::zero(); n];
    w[0] = Point::new([gamma.clone()]);
    w[n - 1] = Point::new([alpha]);
    // The correction's system has scalar right-hand sides: bookkeeping, not counted.
    let z = solve_tridiagonal(sub, &modified, sup, w, &mut NoCount);
    count(counter, n + 1);
    let ratio = beta / &gamma;
    let vz = z[0][0].clone() + &(z[n - 1][0].clone() * &ratio);
    let vy = y[0].clone() + &(y[n - 1].clone() * &ratio);
    let factor = vy / &(S::one() + &vz);
    y.into_iter()
        .zip(z)
        .map(|(yi, zi)| yi - &(factor.clone() * &zi[0]))
        .collect()
}

/// The tangents, or an error if an `f64` one overflowed.
fn finite<S: Scalar, const D: usize>(tangents: Vec<Point<S, D>>) -> Result<Vec<Point<S, D>>> {
    if tangents.iter().all(Point::is_finite) {
        Ok(tangents)
    } else {
        Err(super::hermite::overflow())
    }
}

/// Records `k` arithmetic operations.
fn count<C: Counter>(counter: &mut C, k: usize) {
    for _ in 0..k {
        counter.arithmetic_operation();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Multiplies the cyclic matrix by `x` (the oracle for the solver).
    fn cyclic_times(sub: &[f64], diag: &[f64], sup: &[f64], x: &[f64]) -> Vec<f64> {
        let n = x.len();
        (0..n)
            .map(|i| sub[i] * x[(i + n - 1) % n] + diag[i] * x[i] + sup[i] * x[(i + 1) % n])
            .collect()
    }

    #[test]
    fn cyclic_solver_inverts_the_cyclic_matrix() {
        for n in 2..7 {
            let sub: Vec<f64> = (0..n).map(|i| 1.0 + i as f64 * 0.25).collect();
            let sup: Vec<f64> = (0..n).map(|i| 0.5 + i as f64 * 0.125).collect();
            let diag: Vec<f64> = (0..n).map(|i| 2.0 * (sub[i] + sup[i]) + 0.5).collect();
            let x: Vec<f64> = (0..n).map(|i| (i as f64 - 1.5) * 0.75).collect();
            let mut b = cyclic_times(&sub, &diag, &sup, &x);
            if n == 2 {
                // For two unknowns both neighbours are the other one.
                b = vec![
                    (sub[0] + sup[0]) * x[1] + diag[0] * x[0],
                    (sub[1] + sup[1]) * x[0] + diag[1] * x[1],
                ];
            }
            let rhs = b.iter().map(|&v| Point::new([v])).collect();
            let got = solve_cyclic(&sub, &diag, &sup, rhs, &mut NoCount);
            for (g, want) in got.iter().zip(&x) {
                assert!((g[0] - want).abs() < 1e-12, "n = {n}: {g:?} vs {want}");
            }
        }
    }
}
