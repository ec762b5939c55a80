//! How the pieces of a composite Bézier curve join: C⁰, G¹, C¹ and Cʳ checks, the Cʳ builder
//! (Stärk's construction) and the partition that makes G¹ pieces C¹.
//!
//! The problem: decide, and build, the smoothness of a join. The idea: two pieces meet with
//! Cʳ continuity at `u_i` when their derivatives of orders `0..=r` agree there, and the
//! derivatives at a piece's end are scaled forward differences of its control points:
//! the course's C¹ condition `Q_1 − Q_0 = λ (P_n − P_{n−1})` with `λ = (u_2 − u_1)/(u_1 − u_0)`,
//! the C² condition on `Q_2`, the general `Δʳ P_{n−r} / (u_1 − u_0)ʳ = Δʳ Q_0 / (u_2 − u_1)ʳ`;
//! G¹ asks only for nonzero, positively parallel end tangents. Building a Cʳ join, the first
//! `r + 1` points of the next piece are the Bézier points of the previous polynomial over the
//! next interval (Stärk's construction).
//!
//! Follows [RD, §3.2] ("Curvas de Bézier compuestas", Def. 3.2, and the partition that makes
//! G¹ pieces C¹) and [PPB, §3.10] (Stärk's construction).
//!
//! # Complexity
//!
//! Θ(n²D) per join check, Θ(r·n²D) per built piece, Θ(m·D) for the C¹ partition of m
//! pieces (pieces of degree at most n in R^D).
//!
//! # Exactness of the checks
//!
//! Join checks compare derivatives computed in the scalar field. With `BigRational` they are
//! exact (`tolerance = 0`); with `f64` the derivatives are rounded, so the checks take a
//! relative tolerance: two vectors `a`, `b` count as equal when
//! `|a − b|² ≤ tol² · max(|a|², |b|²)`.

use super::composite::CompositeBezier;
use super::curve::Bezier;
use crate::spline::interpolate::check_partition;
use crate::spline::scalar::{pow2_scale, validate_parameter, validate_points, Point, Scalar};
use crate::{Error, Result};

/// How smoothly two consecutive pieces meet, as [`CompositeBezier::join`] reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Join {
    /// The largest `r` such that the derivatives of orders `0..=r` agree (parametric
    /// continuity Cʳ), or `None` if the pieces do not even meet (not C⁰). Capped at the
    /// larger degree n of the two pieces: `Some(n)` means they are one polynomial (C^∞).
    pub parametric: Option<usize>,
    /// Whether the join is G¹: C⁰ and nonzero end tangents pointing the same way
    /// ([RD, §3.1, Def. 3.2]).
    pub g1: bool,
}

impl<S: Scalar, const D: usize> CompositeBezier<S, D> {
    /// How piece `i − 1` and piece `i` meet at the knot `u_i`, for `i` in `1..m`.
    ///
    /// The Cʳ test is the course's condition `Δᵏ P_{n−k} n!/(n−k)! / h_leftᵏ =
    /// Δᵏ Q_0 n!/(n−k)! / h_rightᵏ` for `k = 0..=r` (derivatives of the two pieces in the
    /// global parameter); the G¹ test asks the end tangents to be nonzero and positively
    /// parallel. `tolerance` is relative (see the module doc); pass zero with exact scalars.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] (`"join"`) if `i` is not an interior knot index.
    ///
    /// # Complexity
    ///
    /// Θ(n²·D) for pieces of degree at most n (forward differences at the two ends).
    ///
    /// ```
    /// use compgeo::spline::{CompositeBezier, Join, Point};
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// // The tangent turns by a factor 3 in length but not in direction: G¹, not C¹.
    /// let c = CompositeBezier::new(
    ///     vec![0.0, 1.0, 2.0],
    ///     vec![vec![p(0.0, 0.0), p(1.0, 1.0)], vec![p(1.0, 1.0), p(4.0, 4.0)]],
    /// )?;
    /// assert_eq!(c.join(1, &0.0)?, Join { parametric: Some(0), g1: true });
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn join(&self, i: usize, tolerance: &S) -> Result<Join> {
        if i == 0 || i >= self.pieces.len() {
            return Err(Error::InvalidParameter {
                name: "join",
                reason: format!(
                    "{i} is not an interior knot index (1..{})",
                    self.pieces.len()
                ),
            });
        }
        // Above the larger degree every derivative of both pieces is zero.
        let max = self.pieces[i - 1].degree().max(self.pieces[i].degree());
        let left = self.end_derivatives_unchecked(i - 1, true, max);
        let right = self.end_derivatives_unchecked(i, false, max);
        let parametric = left
            .iter()
            .zip(&right)
            .take_while(|(a, b)| nearly_equal(a, b, tolerance))
            .count()
            .checked_sub(1);
        let g1 = parametric.is_some() && max >= 1 && same_direction(&left[1], &right[1], tolerance);
        Ok(Join { parametric, g1 })
    }

    /// `true` if every join is Cʳ (derivatives of orders `0..=r` agree) within `tolerance`.
    /// A single piece is C^∞, and so is a join where the derivatives agree up to the larger
    /// degree of its pieces (they are one polynomial).
    pub fn is_c(&self, r: usize, tolerance: &S) -> bool {
        (1..self.pieces.len()).all(|i| {
            let max = self.pieces[i - 1].degree().max(self.pieces[i].degree());
            let left = self.end_derivatives_unchecked(i - 1, true, r.min(max));
            let right = self.end_derivatives_unchecked(i, false, r.min(max));
            left.iter()
                .zip(&right)
                .all(|(a, b)| nearly_equal(a, b, tolerance))
        })
    }

    /// `true` if every join is G¹ within `tolerance` (see [`join`](Self::join)).
    pub fn is_g1(&self, tolerance: &S) -> bool {
        (1..self.pieces.len()).all(|i| self.join(i, tolerance).is_ok_and(|j| j.g1))
    }

    /// Appends a piece of the same degree `n` as the last one over `[u_m, next_knot]`, joined
    /// with Cʳ continuity: its first `r + 1` control points are the Bézier points of the last
    /// piece's polynomial over the new interval (Stärk's construction, [PPB, §3.10]), the
    /// other `n − r` are `free`.
    ///
    /// For `r = 1` this is the course's `Q_1 = Q_0 + λ (P_n − P_{n−1})`, for `r = 2` its formula
    /// for `Q_2` ([RD, §3.2]); `r = n` continues the same polynomial (C^n means C^∞).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] (`"r"`) if `r` exceeds the degree, (`"free"`) if
    /// `free.len() != n − r`, (`"next_knot"`) if it is not finite and above `u_m`;
    /// [`Error::NonFinite`] for a bad free point.
    ///
    /// # Complexity
    ///
    /// Θ(r·n²·D) for degree n (a blossom, that is a de Casteljau scheme, per determined point).
    ///
    /// ```
    /// use compgeo::spline::{CompositeBezier, Point};
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// let mut c = CompositeBezier::new(vec![0.0, 1.0], vec![vec![p(0.0, 0.0), p(1.0, 2.0), p(3.0, 2.0), p(4.0, 0.0)]])?;
    /// c.push_cr(2, 2.0, &[p(6.0, 1.0)])?; // C² over [1, 2], one free point
    /// assert!(c.is_c(2, &1e-12) && !c.is_c(3, &1e-12));
    /// // Its second point continues the first piece's last leg: Q₁ = Q₀ + λ (P₃ − P₂), λ = 1.
    /// assert_eq!(c.pieces()[1].control()[1], p(5.0, -2.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn push_cr(&mut self, r: usize, next_knot: S, free: &[Point<S, D>]) -> Result<()> {
        let last = self.pieces.last().expect("a composite curve has a piece");
        let n = last.degree();
        if r > n {
            return Err(Error::InvalidParameter {
                name: "r",
                reason: format!("C^{r} needs a degree of at least {r}, the last piece has {n}"),
            });
        }
        if free.len() != n - r {
            return Err(Error::InvalidParameter {
                name: "free",
                reason: format!(
                    "a C^{r} piece of degree {n} has {} free points, got {}",
                    n - r,
                    free.len()
                ),
            });
        }
        if !free.is_empty() {
            validate_points(free, "free points")?;
        }
        let m = self.pieces.len();
        validate_parameter(&next_knot, "next_knot")?;
        if next_knot <= self.partition[m] {
            return Err(Error::InvalidParameter {
                name: "next_knot",
                reason: format!(
                    "{} is not above the last knot {}",
                    next_knot.to_f64(),
                    self.partition[m].to_f64()
                ),
            });
        }
        // The new interval in the last piece's local parameter is [1, lambda].
        let h = self.partition[m].clone() - &self.partition[m - 1];
        let lambda = (next_knot.clone() - &self.partition[m - 1]) / &h;
        let mut piece = Vec::with_capacity(n + 1);
        for i in 0..=r {
            let mut args = vec![S::one(); n - i];
            args.resize(n, lambda.clone());
            piece.push(last.blossom(&args)?);
        }
        piece.extend_from_slice(free);
        self.partition.push(next_knot);
        self.pieces.push(Bezier::new(piece)?);
        Ok(())
    }
}

/// The partition that makes G¹ pieces C¹ ([RD, §3.2]):
/// `u_{i+1} = u_i + (u_i − u_{i−1}) λ_i` with `λ_i = ‖Q_1 − Q_0‖ / ‖P_n − P_{n−1}‖` at join i.
///
/// Because the two end tangents are parallel at a G¹ join, `λ_i = (R·L)/(L·L)` with
/// `L = P_n − P_{n−1}`, `R = Q_1 − Q_0`: a rational function of the control points, exact with
/// rationals (no square root).
///
/// # Errors
///
/// [`Error::TooFew`] for no pieces; [`Error::Empty`] / [`Error::NonFinite`] for a bad polygon;
/// [`Error::InvalidParameter`] (`"pieces"`) if a piece has degree 0 or a join is not G¹
/// within `tolerance`, (`"partition"`) unless `u0 < u1`.
///
/// # Complexity
///
/// Θ(m·D) for m pieces.
///
/// ```
/// use compgeo::spline::{c1_partition, CompositeBezier, Point};
///
/// // The exercise of [RD, §3.2]: three parabolic pieces that are G¹.
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// let pieces = vec![
///     vec![p(0.0, 0.0), p(-1.0, 1.0), p(1.0, 3.0)],
///     vec![p(1.0, 3.0), p(2.0, 4.0), p(5.0, 1.0)],
///     vec![p(5.0, 1.0), p(6.0, 0.0), p(7.0, 5.0)],
/// ];
/// let u = c1_partition(&pieces, 0.0, 1.0, &0.0)?;
/// assert_eq!(u[..3], [0.0, 1.0, 1.5]);
/// assert!(CompositeBezier::new(u, pieces)?.is_c(1, &1e-12));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn c1_partition<S: Scalar, const D: usize>(
    pieces: &[Vec<Point<S, D>>],
    u0: S,
    u1: S,
    tolerance: &S,
) -> Result<Vec<S>> {
    if pieces.is_empty() {
        return Err(Error::TooFew {
            what: "pieces",
            needed: 1,
            got: 0,
        });
    }
    for piece in pieces {
        validate_points(piece, "control polygon")?;
        if piece.len() < 2 {
            return Err(Error::InvalidParameter {
                name: "pieces",
                reason: "every piece needs degree at least 1".to_string(),
            });
        }
    }
    check_partition(&[u0.clone(), u1.clone()], 2, "partition")?;
    let mut u = vec![u0, u1];
    for i in 1..pieces.len() {
        let prev = &pieces[i - 1];
        let n = prev.len() - 1;
        let left = prev[n].clone() - &prev[n - 1];
        let right = pieces[i][1].clone() - &pieces[i][0];
        if !nearly_equal(&prev[n], &pieces[i][0], tolerance)
            || !same_direction(&left, &right, tolerance)
        {
            return Err(Error::InvalidParameter {
                name: "pieces",
                reason: format!("the join of pieces {} and {i} is not G1", i - 1),
            });
        }
        let lambda = right.dot(&left) / left.norm_squared();
        let next = u[i].clone() + &((u[i].clone() - &u[i - 1]) * lambda);
        u.push(next);
    }
    Ok(u)
}

/// `|a − b|² ≤ tol² · max(|a|², |b|²)`; with `tol = 0` exact equality. Rounded scalars are
/// first scaled by a common power of two so that the squares cannot overflow.
pub(crate) fn nearly_equal<S: Scalar, const D: usize>(
    a: &Point<S, D>,
    b: &Point<S, D>,
    tol: &S,
) -> bool {
    if tol.is_zero() {
        return a == b;
    }
    let s = pow2_scale(&[a, b]);
    let (a, b) = (a.clone() * &s, b.clone() * &s);
    let diff = (a.clone() - &b).norm_squared();
    let (na, nb) = (a.norm_squared(), b.norm_squared());
    let scale = if na > nb { na } else { nb };
    diff <= tol.clone() * tol * &scale
}

/// Nonzero vectors pointing the same way: `a·b > 0` and
/// `|a|²|b|² − (a·b)² ≤ tol² |a|²|b|²` (the squared sine of their angle is at most `tol²`).
/// Rounded scalars scale each vector by a power of two first (the test is invariant under
/// positive scaling), so that the degree-4 terms cannot overflow.
pub(crate) fn same_direction<S: Scalar, const D: usize>(
    a: &Point<S, D>,
    b: &Point<S, D>,
    tol: &S,
) -> bool {
    let a = a.clone() * pow2_scale(&[a]);
    let b = b.clone() * pow2_scale(&[b]);
    let dot = a.dot(&b);
    if dot <= S::zero() {
        return false;
    }
    let norms = a.norm_squared() * b.norm_squared();
    norms.clone() - &(dot.clone() * &dot) <= tol.clone() * tol * &norms
}
