//! Composite Bézier curves: Bézier pieces over a partition `u_0 < u_1 < ... < u_m`, with
//! checks and builders for C⁰, G¹, C¹ and Cʳ joins.
//!
//! Seed 003 §3.2 ("Curvas de Bézier compuestas": the global parameter, the C¹ condition
//! `Q_1 − Q_0 = λ (P_n − P_{n−1})` with `λ = (u_2 − u_1)/(u_1 − u_0)`, the C² condition on
//! `Q_2`, the general Cⁿ condition `Δʳ P_{n−r} / (u_1 − u_0)ʳ = Δʳ Q_0 / (u_2 − u_1)ʳ`, and
//! the partition that makes G¹ pieces C¹); seed 000 §3.10 (Stärk's construction: the first
//! `r + 1` points of the next piece are the Bézier points of the previous polynomial over the
//! next interval).
//!
//! Piece `i` (0-based) runs over `[u_i, u_{i+1}]` with local parameter
//! `t = (u − u_i)/(u_{i+1} − u_i)`, so its r-th derivative in `u` is the r-th derivative of the
//! Bézier curve in `t` divided by `(u_{i+1} − u_i)ʳ`.
//!
//! # Exactness of the checks
//!
//! Join checks compare derivatives computed in the scalar field. With `BigRational` they are
//! exact (`tolerance = 0`); with `f64` the derivatives are rounded, so the checks take a
//! relative tolerance: two vectors `a`, `b` count as equal when
//! `|a − b|² ≤ tol² · max(|a|², |b|²)`.

use super::interpolate::check_partition;
use super::{validate_parameter, validate_points, Bezier, Point, Scalar};
use crate::{Error, Result};

/// A piecewise Bézier curve over a strictly increasing partition.
///
/// ```
/// use compgeo::spline::{CompositeBezier, Point};
///
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// // Two quadratic pieces over [0, 1] and [1, 3] meeting at (2, 2).
/// let c = CompositeBezier::new(
///     vec![0.0, 1.0, 3.0],
///     vec![vec![p(0.0, 0.0), p(1.0, 2.0), p(2.0, 2.0)], vec![p(2.0, 2.0), p(4.0, 2.0), p(5.0, 0.0)]],
/// )?;
/// assert_eq!(c.eval(&1.0)?, p(2.0, 2.0));
/// assert!(c.is_c(1, &0.0)); // (2,2)−(1,2) over 1 equals (4,2)−(2,2) over 2
/// assert!(!c.is_c(2, &0.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CompositeBezier<S, const D: usize> {
    partition: Vec<S>,
    pieces: Vec<Bezier<S, D>>,
}

/// How smoothly two consecutive pieces meet, as [`CompositeBezier::join`] reports it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Join {
    /// The largest `r` such that the derivatives of orders `0..=r` agree (parametric
    /// continuity Cʳ), or `None` if the pieces do not even meet (not C⁰). Capped at the
    /// larger degree n of the two pieces: `Some(n)` means they are one polynomial (C^∞).
    pub parametric: Option<usize>,
    /// Whether the join is G¹: C⁰ and nonzero end tangents pointing the same way (seed 003
    /// Def. 3.2).
    pub g1: bool,
}

impl<S: Scalar, const D: usize> CompositeBezier<S, D> {
    /// A composite curve from its partition `u_0 < ... < u_m` and its `m` control polygons.
    ///
    /// Pieces may have different degrees and need not meet; the join checks say how they do.
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`] for fewer than two knots; [`Error::InvalidParameter`] (`"partition"`)
    /// for a non-finite or non-increasing partition, (`"pieces"`) if the number of pieces is
    /// not the number of intervals; [`Error::Empty`] / [`Error::NonFinite`] for an empty
    /// control polygon or a bad coordinate.
    pub fn new(partition: Vec<S>, pieces: Vec<Vec<Point<S, D>>>) -> Result<Self> {
        let pieces = pieces
            .into_iter()
            .map(Bezier::new)
            .collect::<Result<Vec<_>>>()?;
        Self::from_pieces(partition, pieces)
    }

    /// A composite curve from its partition and its `m` Bézier pieces.
    ///
    /// # Errors
    ///
    /// As [`new`](Self::new).
    pub fn from_pieces(partition: Vec<S>, pieces: Vec<Bezier<S, D>>) -> Result<Self> {
        check_partition(&partition, 2, "partition")?;
        if pieces.len() + 1 != partition.len() {
            return Err(Error::InvalidParameter {
                name: "pieces",
                reason: format!(
                    "{} pieces for a partition of {} intervals",
                    pieces.len(),
                    partition.len() - 1
                ),
            });
        }
        Ok(CompositeBezier { partition, pieces })
    }

    /// The partition `u_0 < ... < u_m`.
    pub fn partition(&self) -> &[S] {
        &self.partition
    }

    /// The Bézier pieces, one per interval, each over its local parameter `t ∈ [0, 1]`.
    pub fn pieces(&self) -> &[Bezier<S, D>] {
        &self.pieces
    }

    /// The piece containing `u` and the local parameter there. An interior knot belongs to
    /// the piece on its right; `u_m` to the last piece.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] (`"u"`) if `u` is not finite or outside `[u_0, u_m]`.
    pub fn locate(&self, u: &S) -> Result<(usize, S)> {
        validate_parameter(u, "u")?;
        let m = self.pieces.len();
        if *u < self.partition[0] || *u > self.partition[m] {
            return Err(Error::InvalidParameter {
                name: "u",
                reason: format!(
                    "{} is outside [{}, {}]",
                    u.to_f64(),
                    self.partition[0].to_f64(),
                    self.partition[m].to_f64()
                ),
            });
        }
        // The last knot <= u among u_0..u_{m-1}.
        let i = self.partition[1..m].partition_point(|k| k <= u);
        let t =
            (u.clone() - &self.partition[i]) / (self.partition[i + 1].clone() - &self.partition[i]);
        Ok((i, t))
    }

    /// The point `C(u)`.
    ///
    /// # Errors
    ///
    /// As [`locate`](Self::locate).
    ///
    /// # Complexity
    ///
    /// O(log m + n²·D) for m pieces of degree n (de Casteljau on one piece).
    pub fn eval(&self, u: &S) -> Result<Point<S, D>> {
        let (i, t) = self.locate(u)?;
        self.pieces[i].eval(&t)
    }

    /// The r-th derivative `C⁽ʳ⁾(u)` (from the right at an interior knot, from the left at
    /// `u_m`). Order 0 is the point itself.
    ///
    /// # Errors
    ///
    /// As [`locate`](Self::locate).
    pub fn derivative_at(&self, u: &S, order: usize) -> Result<Point<S, D>> {
        let (i, t) = self.locate(u)?;
        let h = self.partition[i + 1].clone() - &self.partition[i];
        Ok(self.pieces[i].derivative_at(&t, order)? / &power(&h, order))
    }

    /// The derivatives of orders `0..=order` at the end of piece `i` (`end = true`, at
    /// `u_{i+1}` from the left) or at its start (at `u_i` from the right), in `u`; those above
    /// the piece's degree are zero.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] (`"piece"`) if `i` is not a piece index.
    pub fn end_derivatives(&self, i: usize, end: bool, order: usize) -> Result<Vec<Point<S, D>>> {
        if i >= self.pieces.len() {
            return Err(Error::InvalidParameter {
                name: "piece",
                reason: format!("{i} is not a piece index (0..{})", self.pieces.len()),
            });
        }
        Ok(self.end_derivatives_unchecked(i, end, order))
    }

    /// How piece `i − 1` and piece `i` meet at the knot `u_i`, for `i` in `1..m`.
    ///
    /// The Cʳ test is the seed's condition `Δᵏ P_{n−k} n!/(n−k)! / h_leftᵏ =
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
    /// piece's polynomial over the new interval (Stärk's construction, seed 000 §3.10), the
    /// other `n − r` are `free`.
    ///
    /// For `r = 1` this is the seed's `Q_1 = Q_0 + λ (P_n − P_{n−1})`, for `r = 2` its formula
    /// for `Q_2` (003 §3.2); `r = n` continues the same polynomial (C^n means C^∞).
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

/// The partition that makes G¹ pieces C¹ (seed 003 §3.2):
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
/// // Seed 003 §3.2's exercise: three parabolic pieces that are G¹.
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

impl<S: Scalar, const D: usize> CompositeBezier<S, D> {
    /// [`end_derivatives`](Self::end_derivatives) for a valid piece index.
    pub(crate) fn end_derivatives_unchecked(
        &self,
        i: usize,
        end: bool,
        order: usize,
    ) -> Vec<Point<S, D>> {
        let h = self.partition[i + 1].clone() - &self.partition[i];
        local_end_derivatives(self.pieces[i].control(), end, order)
            .into_iter()
            .enumerate()
            .map(|(r, d)| d / &power(&h, r))
            .collect()
    }
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

/// For rounded scalars, the power of two `2^−e` that brings the largest coordinate of
/// `vectors` into `[1, 2)` (e clamped to ±1020 so the factor is a normal double); one for
/// exact scalars and for all-zero input. Multiplying by it is exact unless a coordinate
/// underflows, which only happens to coordinates below 2^−1074 relative to the largest.
pub(crate) fn pow2_scale<S: Scalar, const D: usize>(vectors: &[&Point<S, D>]) -> S {
    if S::EXACT {
        return S::one();
    }
    let max = vectors
        .iter()
        .flat_map(|v| v.coords().iter())
        .fold(0.0f64, |m, c| m.max(c.to_f64().abs()));
    if max == 0.0 || !max.is_finite() {
        return S::one();
    }
    let e = (max.log2().floor() as i32).clamp(-1020, 1020);
    S::from_f64(2f64.powi(-e)).unwrap_or_else(S::one)
}

/// `x^k`.
pub(crate) fn power<S: Scalar>(x: &S, k: usize) -> S {
    let mut p = S::one();
    for _ in 0..k {
        p = p * x;
    }
    p
}

/// The derivatives of orders `0..=order` of a Bézier curve at `t = 1` (`end`) or `t = 0`:
/// `n!/(n−k)! Δᵏ b_{n−k}` or `n!/(n−k)! Δᵏ b_0`, and zero above the degree n.
fn local_end_derivatives<S: Scalar, const D: usize>(
    control: &[Point<S, D>],
    end: bool,
    order: usize,
) -> Vec<Point<S, D>> {
    let n = control.len() - 1;
    let wanted = order;
    let order = order.min(n);
    // The k+1 points nearest the end, as Δᵏ needs them.
    let mut diffs: Vec<Point<S, D>> = if end {
        control[n - order..].to_vec()
    } else {
        control[..=order].to_vec()
    };
    let mut out = Vec::with_capacity(order + 1);
    let mut factor = S::one();
    for k in 0..=order {
        let d = if end {
            diffs[diffs.len() - 1].clone()
        } else {
            diffs[0].clone()
        };
        out.push(d * &factor);
        factor = factor * S::from_i64((n - k) as i64);
        for j in 0..diffs.len() - 1 {
            diffs[j] = diffs[j + 1].clone() - &diffs[j];
        }
        diffs.pop();
    }
    // Derivatives above the degree are zero.
    out.resize(wanted + 1, Point::zero());
    out
}
