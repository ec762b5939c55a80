//! C² cubic spline interpolation with natural, clamped, Bessel and periodic end conditions,
//! in O(n) by a tridiagonal (or cyclic tridiagonal) solve.
//!
//! Follows [RD, §3.1] ("Spline cúbico": a C² function made of cubics with zero second derivative at
//! its ends), [SPL, §3] ("Cúbicas C2 a trozos": the natural condition (10), the clamped
//! tangents (11), Bessel's tangents from the parabola through the first and last three
//! points, and the periodic case of closed curves) and [PPB, §4.5] for the Hermite form the
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
//!
//! # Complexity
//!
//! Θ(nD) time and space for n + 1 points in R^D: exactly 7n + 4 counted point operations with
//! the open end conditions, at most 8n with the periodic one.

use super::hermite::hermite_with;
use super::linear::{count, solve_cyclic, solve_tridiagonal};
use super::parameterise::parabola_end_tangent;
use super::validate::{check_knots_and_points, finite};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::spline::CompositeBezier;
use crate::{Error, Result};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and claims.
pub(crate) const CUBIC: Declaration = Declaration {
    problem: "interpolate",
    name: "cubic-spline",
    function: "spline::cubic_spline",
    file: "src/spline/interpolate/cubic_spline.rs",
    summary: "the C² cubic spline as composite Bézier curves",
    time: "Θ(n·D)",
    space: "Θ(n·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "the tangents' 7n + 4 point operations (at most 8n periodic), then the Hermite pieces' 2n",
    source: "[RD, §3.1]",
    claims: &[on(
        "random-points",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The C² cubic spline's tangents with natural ends, declared.
pub(crate) const NATURAL: Declaration = Declaration {
    problem: "spline",
    name: "cubic-natural",
    function: "spline::cubic_spline_tangents",
    file: "src/spline/interpolate/cubic_spline.rs",
    summary: "the tangents of the natural C² cubic spline by a tridiagonal solve",
    time: "Θ(n·D)",
    space: "Θ(n·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 7n + 4 point operations",
    source: "[RD, §3.1]",
    claims: &[on(
        "uniform-square",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The C² cubic spline's tangents with periodic ends, declared.
pub(crate) const PERIODIC: Declaration = Declaration {
    problem: "spline",
    name: "cubic-periodic",
    function: "spline::cubic_spline_tangents",
    file: "src/spline/interpolate/cubic_spline.rs",
    summary: "the tangents of the periodic C² cubic spline by a cyclic tridiagonal solve",
    time: "Θ(n·D)",
    space: "Θ(n·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "Θ(n) point operations",
    source: "[RD, §3.1]",
    claims: &[on(
        "uniform-square",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// What the spline does at its two ends (the two conditions a C² cubic spline needs besides
/// its data).
#[derive(Clone, Debug, PartialEq)]
pub enum EndCondition<S, const D: usize> {
    /// Zero second derivative at both ends ([RD, §3.1, Def. 3.5]; [SPL, §3, (10)]).
    Natural,
    /// Prescribed first derivatives at the two ends ([SPL, §3, (11)]).
    Clamped {
        /// `s'(u_0)`.
        start: Point<S, D>,
        /// `s'(u_n)`.
        end: Point<S, D>,
    },
    /// The end tangents of the parabolas through the first three and the last three points
    /// ([SPL, §3], Bessel's condition; the end estimate of [PPB, §4.5]). Needs three points.
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
/// Θ(n·D) time and Θ(n·D) auxiliary space for `n + 1` points in R^D.
/// [`cubic_spline_tangents_with`] counts the arithmetic.
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
    check_knots_and_points(partition, points, needed)?;
    let n = points.len() - 1;
    let h: Vec<S> = partition.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    let delta: Vec<Point<S, D>> = (0..n)
        .map(|i| (points[i + 1].clone() - &points[i]) / &h[i])
        .collect();
    // The differences, then three point operations per right-hand side.
    count(counter, 4 * n);
    let three = S::from_i64(3);
    let two = S::from_i64(2);
    // Row i of the C² equations, i − 1 and i + 1 taken cyclically (row 0 only for a periodic
    // spline): (sub, diag, sup, rhs).
    let interior = |i: usize| {
        let before = (i + n - 1) % n;
        let rhs = (delta[before].clone() * &h[i] + &(delta[i].clone() * &h[before])) * &three;
        (
            h[i].clone(),
            (h[before].clone() + &h[i]) * &two,
            h[before].clone(),
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
        let mut rows = Rows::with_capacity(n);
        for i in 0..n {
            rows.push(interior(i));
        }
        let mut m = solve_cyclic(&rows.sub, &rows.diag, &rows.sup, rows.rhs, counter);
        m.push(m[0].clone());
        return finite(m);
    }
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
    let mut rows = Rows::with_capacity(n + 1);
    // Row 0: m_0 given, or natural 2 m_0 + m_1 = 3 δ_0.
    rows.push(match first {
        Some(t) => (S::zero(), S::one(), S::zero(), t),
        None => (S::zero(), two.clone(), S::one(), delta[0].clone() * &three),
    });
    for i in 1..n {
        rows.push(interior(i));
    }
    // Row n: m_n given, or natural m_{n-1} + 2 m_n = 3 δ_{n-1}.
    rows.push(match last {
        Some(t) => (S::zero(), S::one(), S::zero(), t),
        None => (S::one(), two, S::zero(), delta[n - 1].clone() * &three),
    });
    count(counter, 2);
    finite(solve_tridiagonal(
        &rows.sub, &rows.diag, &rows.sup, rows.rhs, counter,
    ))
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
/// Θ(n·D) time and Θ(n·D) space for `n + 1` points in R^D.
///
/// ```
/// use compgeo::spline::{cubic_spline, Curve, CurveDerivative, EndCondition, Point};
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
    cubic_spline_with(partition, points, end, &mut NoCount)
}

/// [`cubic_spline`], counting the arithmetic on points of both steps: the tangents' (see
/// [`cubic_spline_tangents_with`]: exactly 7n + 4 for the open end conditions) and the
/// Hermite pieces' two inner points each, 2n, so exactly 9n + 4 for `n + 1` points with an
/// open end condition.
///
/// # Errors
///
/// As [`cubic_spline`].
///
/// # Complexity
///
/// Θ(n·D) time and Θ(n·D) space for `n + 1` points in R^D.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{cubic_spline_with, EndCondition, Point};
///
/// let pts = [Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([3.0, 1.0])];
/// let mut c = Counts::default();
/// cubic_spline_with(&[0.0, 1.0, 2.0], &pts, &EndCondition::Natural, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 9 * 2 + 4);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn cubic_spline_with<S: Scalar, const D: usize, C: Counter>(
    partition: &[S],
    points: &[Point<S, D>],
    end: &EndCondition<S, D>,
    counter: &mut C,
) -> Result<CompositeBezier<S, D>> {
    let tangents = cubic_spline_tangents_with(partition, points, end, counter)?;
    hermite_with(partition, points, &tangents, counter)
}

/// The rows of a (cyclic) tridiagonal system, as [`solve_tridiagonal`] and [`solve_cyclic`]
/// take them.
struct Rows<S, const D: usize> {
    sub: Vec<S>,
    diag: Vec<S>,
    sup: Vec<S>,
    rhs: Vec<Point<S, D>>,
}

impl<S: Scalar, const D: usize> Rows<S, D> {
    fn with_capacity(n: usize) -> Self {
        Rows {
            sub: Vec::with_capacity(n),
            diag: Vec::with_capacity(n),
            sup: Vec::with_capacity(n),
            rhs: Vec::with_capacity(n),
        }
    }

    /// Appends the row `(sub, diag, sup, rhs)`.
    fn push(&mut self, (a, b, c, r): (S, S, S, Point<S, D>)) {
        self.sub.push(a);
        self.diag.push(b);
        self.sup.push(c);
        self.rhs.push(r);
    }
}
