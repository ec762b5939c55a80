//! The C² cubic interpolating spline in B-spline form: the same curve as
//! [`cubic_spline`](crate::spline::cubic_spline()), as a [`BSpline`] on the clamped knots of
//! its partition.
//!
//! The problem: the C² piecewise cubic through p₀, …, p_N at u₀ < … < u_N with an end
//! condition at each end. The idea: every C² cubic with breakpoints u₁, …, u_{N−1} on
//! [u₀, u_N] is a B-spline on the knots u₀ (four times), u₁, …, u_{N−1}, u_N (four times),
//! with N + 3 control points; the N + 1 interpolation conditions and the two end conditions
//! (a first or second derivative at an end, from [`KnotVector::basis_derivatives`]) are
//! N + 3 linear equations. Ordered as s(u₀), the start condition, s(u₁), …, s(u_{N−1}), the
//! end condition, s(u_N), each involves at most the three unknowns around the diagonal, so
//! the system is tridiagonal and [`BandMatrix`] solves it in Θ(N), exactly with rationals.
//!
//! This is independent of the tangent formulation of `cubic_spline.rs` (which solves for the
//! derivatives at the knots [SPL, §3]); a test checks that both give the same curve exactly.
//!
//! Follows [SPL, §3] (the end conditions: natural (10), clamped (11), Bessel's),
//! [RD, §3.1] (the natural spline) and [PPB, §6.7] (interpolation by B-splines).
//!
//! # Complexity
//!
//! Θ(N D) time and space for N + 1 points in R^D.

use super::banded::BandMatrix;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::interpolate::check_partition;
use crate::spline::scalar::{pow2_scale, validate_points, Point, Scalar};
use crate::spline::EndCondition;
use crate::{Error, Result};

/// The cubic spline in B-spline form, declared.
pub(crate) const CUBIC_SPLINE: Declaration = Declaration {
    problem: "bspline",
    name: "cubic-spline",
    function: "spline::BSpline::cubic_spline",
    file: "src/spline/bspline/cubic.rs",
    summary: "the C² cubic interpolating spline as a B-spline, by a tridiagonal solve",
    time: "Θ(N·D)",
    space: "Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 6(N + 1) + 5(N + 2) + 1: the basis values of the N + 1 data rows (6 each) and the tridiagonal solve of the N + 3 rows",
    source: "[SPL, §3]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The C² cubic spline through `points` at the increasing `partition` with the end
    /// condition `end`, as a cubic B-spline on the clamped knots u₀, u₀, u₀, u₀, u₁, …,
    /// u_{N−1}, u_N, u_N, u_N, u_N (N + 3 control points; a Bézier curve for two points).
    ///
    /// It is the curve [`cubic_spline`](crate::spline::cubic_spline()) returns as composite
    /// Bézier pieces, for the end conditions [`EndCondition::Natural`],
    /// [`EndCondition::Clamped`] and [`EndCondition::Bessel`] (the tangents of the parabolas
    /// through the first and last three points); exactly equal with rationals. The periodic
    /// spline needs a periodic knot vector, which this form does not use: it is refused.
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`] for fewer than two points (three for Bessel);
    /// [`Error::InvalidParameter`] named `"partition"` for a non-finite or non-increasing
    /// partition, `"points"` for another number of points than knots, `"end"` for
    /// [`EndCondition::Periodic`]; [`Error::NonFinite`] for a bad coordinate (also of the
    /// clamped tangents, as indices N + 1 and N + 2); [`Error::Overflow`] if, with `f64`, a
    /// control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(N·D) time and Θ(N·D) space for N + 1 points in R^D.
    ///
    /// ```
    /// use compgeo::spline::{cubic_spline, BSpline, Curve, EndCondition, Point};
    ///
    /// let u = [0.0, 1.0, 3.0, 4.0];
    /// let p = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 3.0]].map(Point::new);
    /// let s = BSpline::cubic_spline(&p, &u, &EndCondition::Natural)?;
    /// assert_eq!(s.knots().knots(), [0.0, 0.0, 0.0, 0.0, 1.0, 3.0, 4.0, 4.0, 4.0, 4.0]);
    /// let c = cubic_spline(&u, &p, &EndCondition::Natural)?;
    /// for x in [0.5, 2.0, 3.5] {
    ///     let (a, b) = (s.eval(&x)?, c.eval(&x)?);
    ///     assert!((a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn cubic_spline(
        points: &[Point<S, D>],
        partition: &[S],
        end: &EndCondition<S, D>,
    ) -> Result<Self> {
        Self::cubic_spline_with(points, partition, end, &mut NoCount)
    }

    /// The C² cubic spline in B-spline form (see [`BSpline::cubic_spline`]), counting its
    /// arithmetic.
    ///
    /// # Errors
    ///
    /// As [`BSpline::cubic_spline`].
    ///
    /// # Complexity
    ///
    /// Θ(N·D) time and Θ(N·D) space for N + 1 points in R^D.
    ///
    /// # Counts
    ///
    /// The [`arithmetic_operation`](Counter::arithmetic_operation)s of the basis values of
    /// the N + 1 data rows ([`KnotVector::basis_with`]: 6 each)
    /// and of the tridiagonal solve ([`BandMatrix::solve_with`]: 5(N + 2) + 1 for its
    /// N + 3 rows): exactly 6(N + 1) + 5(N + 2) + 1. The two derivative rows are not counted.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, EndCondition, Point};
    ///
    /// let u: Vec<f64> = (0..=10).map(f64::from).collect();
    /// let p: Vec<Point<f64, 1>> = u.iter().map(|&x| Point::new([x * x])).collect();
    /// let mut c = Counts::default();
    /// BSpline::cubic_spline_with(&p, &u, &EndCondition::Natural, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6 * 11 + 5 * 12 + 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn cubic_spline_with<C: Counter>(
        points: &[Point<S, D>],
        partition: &[S],
        end: &EndCondition<S, D>,
        counter: &mut C,
    ) -> Result<Self> {
        let needed = match end {
            EndCondition::Natural | EndCondition::Clamped { .. } => 2,
            EndCondition::Bessel => 3,
            EndCondition::Periodic => {
                return Err(Error::InvalidParameter {
                    name: "end",
                    reason: "the periodic cubic spline needs a periodic knot vector; use \
                             cubic_spline for its composite Bézier form"
                        .into(),
                })
            }
        };
        if points.len() < needed {
            return Err(Error::TooFew {
                what: "points",
                needed,
                got: points.len(),
            });
        }
        validate_points(points, "points")?;
        check_partition(partition, needed, "partition")?;
        if partition.len() != points.len() {
            return Err(Error::InvalidParameter {
                name: "points",
                reason: format!("{} points for {} knots", points.len(), partition.len()),
            });
        }
        let big_n = points.len() - 1;
        let (u0, un) = (&partition[0], &partition[big_n]);
        let mut knots = Vec::with_capacity(big_n + 7);
        knots.extend(std::iter::repeat_n(u0.clone(), 4));
        knots.extend_from_slice(&partition[1..big_n]);
        knots.extend(std::iter::repeat_n(un.clone(), 4));
        let knots = KnotVector::new(3, knots)?;
        let size = big_n + 3;

        // The end rows: (order of the derivative, its value) at u₀ and at u_N.
        let (start, finish) = match end {
            EndCondition::Natural => ((2, Point::zero()), (2, Point::zero())),
            EndCondition::Clamped { start, end } => {
                for (k, t) in [start, end].into_iter().enumerate() {
                    if let Some(c) = t.coords().iter().find(|c| !c.is_finite()) {
                        return Err(Error::NonFinite {
                            index: big_n + 1 + k,
                            value: c.to_f64(),
                        });
                    }
                }
                ((1, start.clone()), (1, end.clone()))
            }
            EndCondition::Bessel => {
                let h = |i: usize| partition[i + 1].clone() - &partition[i];
                let delta = |i: usize| (points[i + 1].clone() - &points[i]) / &h(i);
                let a = parabola_tangent(&h(0), &h(1), &delta(0), &delta(1));
                let b = parabola_tangent(
                    &h(big_n - 1),
                    &h(big_n - 2),
                    &delta(big_n - 1),
                    &delta(big_n - 2),
                );
                ((1, a), (1, b))
            }
            EndCondition::Periodic => unreachable!("refused above"),
        };

        // The data rows and the derivative rows share one scale (the system is linear).
        let mut refs: Vec<&Point<S, D>> = points.iter().collect();
        refs.push(&start.1);
        refs.push(&finish.1);
        let scale = pow2_scale(&refs);

        let mut band = BandMatrix::zeros(size, 1, 1)?;
        let mut rhs = Vec::with_capacity(size);
        let data_row =
            |band: &mut BandMatrix<S>, rhs: &mut Vec<Point<S, D>>, k: usize, counter: &mut C| {
                let b = knots.basis_with(&partition[k], counter)?;
                for (j, v) in b.values().iter().enumerate() {
                    // The zeros (N_{k+3}(u_k)) may lie outside the band.
                    if !v.is_zero() {
                        band.set(k + 1, b.first() + j, v.clone())?;
                    }
                }
                rhs.push(points[k].clone() * &scale);
                Ok::<(), Error>(())
            };
        // Row 0 is s(u₀) = p₀; data row k ≥ 1 goes to row k + 1, after the start condition.
        let b = knots.basis_with(u0, counter)?;
        band.set(0, 0, b.get(0))?;
        rhs.push(points[0].clone() * &scale);
        derivative_row(&knots, &mut band, 1, u0, start.0)?;
        rhs.push(start.1.clone() * &scale);
        for k in 1..big_n {
            data_row(&mut band, &mut rhs, k, counter)?;
        }
        derivative_row(&knots, &mut band, big_n + 1, un, finish.0)?;
        rhs.push(finish.1.clone() * &scale);
        let b = knots.basis_with(un, counter)?;
        band.set(big_n + 2, big_n + 2, b.get(big_n + 2))?;
        rhs.push(points[big_n].clone() * &scale);

        let mut control = band.solve_with(rhs, counter)?;
        if !S::EXACT {
            let back = S::one() / &scale;
            for c in &mut control {
                *c = c.clone() * &back;
            }
        }
        BSpline::derived(control, knots, "cubic spline in B-spline form")
    }
}

/// Fills `row` with the derivatives of order `order` of the basis functions at `u` (an end
/// of the domain: right derivatives at the start, left at the end), the non-zero ones only.
fn derivative_row<S: Scalar>(
    knots: &KnotVector<S>,
    band: &mut BandMatrix<S>,
    row: usize,
    u: &S,
    order: usize,
) -> Result<()> {
    let b = knots.basis_derivatives(u, order)?;
    for (j, v) in b.order(order).iter().enumerate() {
        if !v.is_zero() {
            band.set(row, b.first() + j, v.clone())?;
        }
    }
    Ok(())
}

/// The derivative at the first knot of the parabola through three consecutive points, from
/// the gaps h₀, h₁ and the chord slopes δ₀, δ₁: 2δ₀ − (h₁δ₀ + h₀δ₁)/(h₀ + h₁) (Bessel's end
/// tangent [SPL, §3]; mirrored arguments give the last knot's).
fn parabola_tangent<S: Scalar, const D: usize>(
    h0: &S,
    h1: &S,
    delta0: &Point<S, D>,
    delta1: &Point<S, D>,
) -> Point<S, D> {
    let inner = (delta0.clone() * h1 + &(delta1.clone() * h0)) / (h0.clone() + h1);
    delta0.clone() * S::from_i64(2) - &inner
}
