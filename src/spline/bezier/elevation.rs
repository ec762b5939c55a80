//! Degree elevation of Bézier curves: by one, and to any degree in one step by Zhou's
//! formula.
//!
//! The problem: the control points of the same curve in a higher degree (to join curves of
//! different degrees, or to bring a polygon closer to its curve). The idea: the blossom of
//! degree n + 1 that averages the degree-n blossom over the argument left out is symmetric,
//! multi-affine and agrees on the diagonal, so its values are the new Bézier points
//! `cᵢ = i/(n+1) bᵢ₋₁ + (1 − i/(n+1)) bᵢ`; repeating it m − n times sums to Zhou's
//! polyhypergeometric weights.
//!
//! Follows [PPB, §3.11] (elevation by one) and [PPB, §3.12] (Zhou's formula).
//!
//! # Complexity
//!
//! Θ(nD) for one degree, Θ(m·n·D) to degree m; Θ(mD) space for the result.
//!
//! Invariants the tests check (exactly on rationals): the elevated curve evaluates to the
//! original, Zhou's formula to degree n + 1 equals elevation by one, to degree n the curve
//! itself.

use super::curve::Bezier;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::{limits, Error, Result};

/// Elevation by Zhou's formula, declared: its name, bounds, counts, source and claims, in
/// each of its sizes (the degree n, elevated to 2n; the target m, from degree 3).
pub(crate) const ELEVATE_TO: Declaration = Declaration {
    problem: "bezier",
    name: "elevate-to",
    function: "spline::Bezier::elevate_to",
    file: "src/spline/bezier/elevation.rs",
    summary: "degree elevation to m in one step (Zhou's formula)",
    time: "Θ(m·n·D)",
    space: "Θ(mD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)(m − n + 1) terms bᵢ·wᵢ",
    source: "[PPB, §3.12]",
    claims: &[
        on(
            "random-degree",
            Bound::Quadratic,
            Operation::ArithmeticOperations,
        ),
        on(
            "random-target",
            Bound::Linear,
            Operation::ArithmeticOperations,
        ),
    ],
};

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The same curve with degree n + 1: `cᵢ = i/(n+1) bᵢ₋₁ + (1 − i/(n+1)) bᵢ`.
    ///
    /// Idea: the blossom of degree n + 1 that averages the degree-n blossom over the argument
    /// left out is symmetric, multi-affine and agrees on the diagonal, so its values give the
    /// new Bézier points.
    ///
    /// Follows [PPB, §3.11].
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space for the result.
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if rounding carries a new point beyond the range of `f64` (only
    /// for coordinates within an ulp of ±`f64::MAX`); [`Error::LimitExceeded`] for a curve
    /// already of degree [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let line = Bezier::new(vec![Point::new([0.0]), Point::new([2.0])])?;
    /// let q = line.elevate()?;
    /// assert_eq!(q.control(), [Point::new([0.0]), Point::new([1.0]), Point::new([2.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate(&self) -> Result<Self> {
        Bezier::derived(elevated_polygon(self.control()), "degree elevation")
    }

    /// The same curve with degree m ≥ n, in one step by Zhou's formula
    /// `dₖ = Σᵢ bᵢ C(n, i) C(m − n, k − i) / C(m, k)`.
    ///
    /// The weights of each `dₖ` are a hypergeometric distribution in i: they sum to one, and
    /// consecutive ones have the ratio `(n − i)(k − i) / ((i + 1)(m − n − k + i + 1))`. So
    /// they are built from that ratio outwards from the largest one (the distribution's
    /// mode) and the sum is divided out: no binomial coefficient is formed, nothing
    /// overflows `f64` however large m is, and with rationals every number stays as small as
    /// the weights themselves.
    ///
    /// Follows [PPB, §3.12] (Zhou's formula, the polyhypergeometric
    /// distribution).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `m < n` (that would be degree reduction, an
    /// approximation); [`Error::LimitExceeded`] if `m` exceeds
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE), before anything is allocated;
    /// [`Error::Overflow`] as for [`Bezier::elevate`].
    ///
    /// # Complexity
    ///
    /// Θ(m·n·D) time (each of the m + 1 points sums at most n + 1 terms), Θ(mD) space for the
    /// result.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([3.0])])?;
    /// let e = b.elevate_to(3)?;
    /// assert_eq!(e.control(), (0..4).map(|i| Point::new([i as f64])).collect::<Vec<_>>());
    /// assert!(b.elevate_to(0).is_err());
    /// assert!(b.elevate_to(1 << 32).is_err()); // beyond MAX_DEGREE
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_to(&self, m: usize) -> Result<Self> {
        self.elevate_to_with(m, &mut NoCount)
    }

    /// [`Bezier::elevate_to`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per term bᵢ·wᵢ of Zhou's sums:
    /// each bᵢ enters the m − n + 1 points dᵢ, …, dᵢ₊ₘ₋ₙ, so exactly (n + 1)(m − n + 1).
    ///
    /// # Errors
    ///
    /// As [`Bezier::elevate_to`].
    ///
    /// # Complexity
    ///
    /// Θ(m·n·D) time, Θ(mD) space for the result.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new((0..4).map(|i| Point::new([i as f64])).collect())?;
    /// let mut c = Counts::default();
    /// b.elevate_to_with(10, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 4 * 8);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_to_with<C: Counter>(&self, m: usize, counter: &mut C) -> Result<Self> {
        let n = self.degree();
        if m < n {
            return Err(Error::InvalidParameter {
                name: "degree",
                reason: format!("cannot elevate a curve of degree {n} to degree {m}"),
            });
        }
        limits::DEGREE.check(m as u128)?;
        Bezier::derived(self.elevate_to_counted(m, counter), "degree elevation")
    }

    /// Zhou's formula without validation (n ≤ m ≤ MAX_DEGREE), counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per term bᵢ·wᵢ: each bᵢ
    /// enters the m − n + 1 points d_i, …, d_{i+m−n}, so exactly (n + 1)(m − n + 1). The
    /// points may be non-finite with `f64` (rounding next to ±`f64::MAX`): the caller checks.
    pub(crate) fn elevate_to_counted<C: Counter>(
        &self,
        m: usize,
        counter: &mut C,
    ) -> Vec<Point<S, D>> {
        let n = self.degree();
        let b = self.control();
        let mut control = Vec::with_capacity(m + 1);
        let mut weight = vec![S::zero(); n + 1];
        // m <= MAX_DEGREE = 2^16, so every product below fits in an i64.
        // The terms run over lo <= i <= hi with lo >= k − (m − n), so m − n + i + 1 − k >= 1.
        let ratio = |i: usize, k: usize| ((n - i) * (k - i), (i + 1) * (m - n + i + 1 - k));
        for k in 0..=m {
            // The terms with C(m − n, k − i) ≠ 0.
            let (lo, hi) = (k.saturating_sub(m - n), k.min(n));
            let mode = ((k + 1) * (n + 1) / (m + 2)).clamp(lo, hi);
            weight[mode] = S::one();
            for i in mode..hi {
                let (num, den) = ratio(i, k);
                weight[i + 1] = weight[i].clone() * S::from_ratio(num as i64, den as i64);
            }
            for i in (lo..mode).rev() {
                let (num, den) = ratio(i, k);
                weight[i] = weight[i + 1].clone() * S::from_ratio(den as i64, num as i64);
            }
            let mut d = Point::zero();
            let mut total = S::zero();
            for (bi, w) in b[lo..=hi].iter().zip(&weight[lo..=hi]) {
                d += &(bi.clone() * w.clone());
                total += w.clone();
                counter.arithmetic_operation();
            }
            control.push(d / &total);
        }
        control
    }
}

/// The control polygon of degree n + 1 of the polygon `b` of degree n (at least one point):
/// `cᵢ = i/(n+1) bᵢ₋₁ + (1 − i/(n+1)) bᵢ` [PPB, §3.11], n + 2 points, each an affine
/// combination of at most two (the ends are copies). Unchecked: with `f64` a point may round
/// to a non-finite value next to ±`f64::MAX`.
pub(crate) fn elevated_polygon<S: Scalar, const D: usize>(b: &[Point<S, D>]) -> Vec<Point<S, D>> {
    let n = b.len() - 1;
    let den = (n + 1) as i64;
    let mut control = Vec::with_capacity(n + 2);
    control.push(b[0].clone());
    for i in 1..=n {
        let w = S::from_ratio(i as i64, den);
        let v = S::one() - &w;
        control.push(Point::combine(&b[i - 1], &w, &b[i], &v));
    }
    control.push(b[n].clone());
    control
}
