//! Cʳ joins of two Bézier patches across a common boundary: the check and the construction.
//!
//! The problem: two patches over [u₀, u₁] × [v₀, v₁] and [u₁, u₂] × [v₀, v₁] (each net
//! describing its rectangle), meeting along u = u₁; are their derivatives equal there up to
//! order r, and which first rows of the second net make them so? The idea: along the edge
//! every derivative is a curve in v whose control points come from the columns, so the join
//! is Cʳ exactly when, for every column j, the two columns joined are a Cʳ composite curve
//! over [u₀, u₁, u₂]: Δ^{k,0}c_{m−k,j} m!/(m − k)!/(Δu₀)^k =
//! Δ^{k,0}c̃_{0,j} m̃!/(m̃ − k)!/(Δu₁)^k for k = 0, …, r [FJ-surfaces, §6, eq. (23)],
//! [PPB, §9.7]. By Stärk's theorem [PPB, §3.10] the first r + 1 points of each column of
//! the second net are then those of the first column's polynomial over [u₁, u₂]: the curve
//! code restricts every column of the first patch to the local interval [1, λ],
//! λ = (u₂ − u₀)/(u₁ − u₀), and keeps its first r + 1 points. The joins along v are the same
//! on the transposed nets.
//!
//! # Exactness
//!
//! With `BigRational` pass a zero tolerance: the check is exact. With `f64` derivatives are
//! rounded and the check takes a relative tolerance as the curves' joins do: two vectors a, b
//! count as equal when |a − b|² ≤ tol²·max(|a|², |b|²).
//!
//! # Complexity
//!
//! The check Θ((n + 1)(m² + m̃²)D); the construction Θ((n + 1)m²D) (along v, with the roles of
//! m and n exchanged).

use super::bezier::BezierPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::{difference, nearly_equal};
use crate::spline::{falling_factorial, power, validate_parameter, validate_points, Point, Scalar};
use crate::{Error, Result};

/// The Cʳ check along u, declared.
pub(crate) const JOIN_U: Declaration = Declaration {
    problem: "bezier-patch",
    name: "join-u",
    function: "surface::BezierPatch::join_u",
    file: "src/surface/join.rs",
    summary:
        "the transversal derivatives of every column at the common edge, compared order by order",
    time: "Θ((n + 1)(m² + m̃²)D)",
    space: "O((m + m̃)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)(m(m + 1)/2 + m̃(m̃ + 1)/2 + m + m̃ + 2) differences and scalings",
    source: "[FJ-surfaces, §6], [PPB, §9.7]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// The Cʳ check along v, declared.
pub(crate) const JOIN_V: Declaration = Declaration {
    problem: "bezier-patch",
    name: "join-v",
    function: "surface::BezierPatch::join_v",
    file: "src/surface/join.rs",
    summary: "the check along u on the transposed nets",
    time: "Θ((m + 1)(n² + ñ²)D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (m + 1)(n(n + 1)/2 + ñ(ñ + 1)/2 + n + ñ + 2) differences and scalings",
    source: "[FJ-surfaces, §6], [PPB, §9.7]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// The Cʳ construction along u, declared.
pub(crate) const EXTEND_CR_U: Declaration = Declaration {
    problem: "bezier-patch",
    name: "extend-cr-u",
    function: "surface::BezierPatch::extend_cr_u",
    file: "src/surface/join.rs",
    summary: "Stärk's construction on every column: its polynomial restricted to the next interval",
    time: "Θ((n + 1)m²D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)m(m + 1) affine combinations (two subdivisions per column)",
    source: "[PPB, §9.7], [PPB, §3.10]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// The Cʳ construction along v, declared.
pub(crate) const EXTEND_CR_V: Declaration = Declaration {
    problem: "bezier-patch",
    name: "extend-cr-v",
    function: "surface::BezierPatch::extend_cr_v",
    file: "src/surface/join.rs",
    summary: "Stärk's construction on every row of the net",
    time: "Θ((m + 1)n²D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (m + 1)n(n + 1) affine combinations (two subdivisions per row)",
    source: "[PPB, §9.7], [PPB, §3.10]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// How this patch, over [u₀, u₁] in u, meets `next`, over [u₁, u₂], along u = u₁: the
    /// largest r such that the partial derivatives ∂^k/∂u^k of orders 0..=r agree along the
    /// edge (the join is Cʳ), or `None` if the edges differ (not even C⁰). Capped at the
    /// larger u degree: `Some(max(m, m̃))` means one polynomial (C^∞). `knots` is
    /// [u₀, u₁, u₂]; both patches describe [v₀, v₁] in v. See [`BezierPatch::join_u_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"knots"` unless u₀ < u₁ < u₂, all finite; named
    /// `"tolerance"` for a negative, NaN or infinite tolerance; named `"next"` if the
    /// patches' v degrees differ (the edges cannot be compared point by point).
    ///
    /// # Complexity
    ///
    /// Θ((n + 1)(m² + m̃²)D) time, O((m + m̃)D) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// // Two bilinear pieces of the plane map (u, v) ↦ (u, v) over [0, 1] and [1, 3].
    /// let a = BezierPatch::new(ControlNet::new(vec![vec![p(0.0, 0.0), p(0.0, 1.0)], vec![p(1.0, 0.0), p(1.0, 1.0)]])?)?;
    /// let b = BezierPatch::new(ControlNet::new(vec![vec![p(1.0, 0.0), p(1.0, 1.0)], vec![p(3.0, 0.0), p(3.0, 1.0)]])?)?;
    /// assert_eq!(a.join_u(&b, &[0.0, 1.0, 3.0], &0.0)?, Some(1)); // one polynomial
    /// assert_eq!(a.join_u(&b, &[0.0, 1.0, 2.0], &0.0)?, Some(0)); // the speeds differ
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn join_u(&self, next: &Self, knots: &[S; 3], tolerance: &S) -> Result<Option<usize>> {
        self.join_u_with(next, knots, tolerance, &mut NoCount)
    }

    /// The Cʳ check along u = u₁, counting point operations.
    ///
    /// Idea: the k-th derivative in u along the edge is the curve in v whose control points
    /// are m!/(m − k)! Δ^k c_{m−k,j}/(Δu₀)^k on this side and m̃!/(m̃ − k)! Δ^k
    /// c̃_{0,j}/(Δu₁)^k on the other [FJ-surfaces, §6, eqs. (19)–(20), (23)]; two curves of
    /// the same degree are equal exactly when their control points are, so the orders are
    /// compared point by point.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::join_u`].
    ///
    /// # Complexity
    ///
    /// Θ((n + 1)(m² + m̃²)D) time, O((m + m̃)D) auxiliary space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per difference or scaling
    /// of a point, every order computed before comparing: exactly
    /// (n + 1)(m(m + 1)/2 + m̃(m̃ + 1)/2 + m + m̃ + 2).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..2).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 1)
    /// let mut c = Counts::default();
    /// assert_eq!(s.join_u_with(&s, &[0.0, 1.0, 2.0], &0.0, &mut c)?, None); // edges x = 2, x = 0
    /// assert_eq!(c.arithmetic_operations, 2 * (3 + 3 + 2 + 2 + 2));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn join_u_with<C: Counter>(
        &self,
        next: &Self,
        knots: &[S; 3],
        tolerance: &S,
        counter: &mut C,
    ) -> Result<Option<usize>> {
        let (h0, h1) = check_knots(knots)?;
        validate_parameter(tolerance, "tolerance")?;
        if *tolerance < S::zero() {
            return Err(Error::InvalidParameter {
                name: "tolerance",
                reason: format!("a tolerance is not negative, got {}", tolerance.to_f64()),
            });
        }
        let ((m, n), (m2, n2)) = (self.bidegree(), next.bidegree());
        if n != n2 {
            return Err(Error::InvalidParameter {
                name: "next",
                reason: format!(
                    "the common edge has degree {n} in v on one patch and {n2} on the other"
                ),
            });
        }
        let top = m.max(m2);
        // agree[k]: the k-th derivatives are equal along the whole edge.
        let mut agree = vec![true; top + 1];
        for j in 0..=n {
            let left = end_derivatives(self.net().column(j), true, &h0, counter);
            let right = end_derivatives(next.net().column(j), false, &h1, counter);
            let zero = Point::zero();
            for (k, ok) in agree.iter_mut().enumerate() {
                let a = left.get(k).unwrap_or(&zero);
                let b = right.get(k).unwrap_or(&zero);
                *ok = *ok && nearly_equal(a, b, tolerance);
            }
        }
        Ok(agree.iter().take_while(|ok| **ok).count().checked_sub(1))
    }

    /// How this patch, over [v₀, v₁] in v, meets `next`, over [v₁, v₂], along v = v₁: as
    /// [`BezierPatch::join_u`] with u and v exchanged (`knots` is [v₀, v₁, v₂]). See
    /// [`BezierPatch::join_v_with`].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::join_u`], with `"next"` for different u degrees.
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)(n² + ñ²)D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let p = |x: f64| Point::new([x]);
    /// let a = BezierPatch::new(ControlNet::new(vec![vec![p(0.0), p(1.0)]])?)?;
    /// let b = BezierPatch::new(ControlNet::new(vec![vec![p(1.0), p(2.0)]])?)?;
    /// assert_eq!(a.join_v(&b, &[0.0, 1.0, 2.0], &0.0)?, Some(1));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn join_v(&self, next: &Self, knots: &[S; 3], tolerance: &S) -> Result<Option<usize>> {
        self.join_v_with(next, knots, tolerance, &mut NoCount)
    }

    /// The Cʳ check along v = v₁, counting: [`BezierPatch::join_u_with`] on the transposed
    /// nets.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::join_v`].
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)(n² + ñ²)D) time, Θ(mnD) space (the transposed nets).
    ///
    /// # Counts
    ///
    /// Exactly (m + 1)(n(n + 1)/2 + ñ(ñ + 1)/2 + n + ñ + 2)
    /// [`arithmetic_operation`](Counter::arithmetic_operation)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let p = |x: f64| Point::new([x]);
    /// let a = BezierPatch::new(ControlNet::new(vec![vec![p(0.0), p(1.0)]])?)?;
    /// let mut c = Counts::default();
    /// assert_eq!(a.join_v_with(&a, &[0.0, 1.0, 2.0], &0.0, &mut c)?, None);
    /// assert_eq!(c.arithmetic_operations, 1 + 1 + 1 + 1 + 2);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn join_v_with<C: Counter>(
        &self,
        next: &Self,
        knots: &[S; 3],
        tolerance: &S,
        counter: &mut C,
    ) -> Result<Option<usize>> {
        self.transposed()?
            .join_u_with(&next.transposed()?, knots, tolerance, counter)
    }

    /// The patch over [u₁, u₂] that continues this one (over [u₀, u₁]) with Cʳ continuity
    /// along u = u₁, of the same bidegree (m, n): its first r + 1 rows are determined, the
    /// other m − r are `free` (each of n + 1 points). `r = m` continues the same polynomial.
    /// See [`BezierPatch::extend_cr_u_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"r"` if r > m (Cʳ asks for degree at least r),
    /// `"knots"` unless u₀ < u₁ < u₂ (finite), `"free"` unless there are m − r free rows of
    /// n + 1 points, `"free rows"` for a NaN or infinite free point; [`Error::Overflow`] if,
    /// with `f64`, a point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((n + 1)m²D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..2).map(|j| Point::new([(i * i) as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 1)
    /// let knots = [0.0, 1.0, 2.0];
    /// let free = vec![vec![Point::new([9.0, 0.0]), Point::new([9.0, 1.0])]];
    /// let next = s.extend_cr_u(1, &knots, &free)?;
    /// assert_eq!(next.net().get(1, 0), &Point::new([7.0, 0.0])); // 4 + (4 − 1)
    /// assert_eq!(s.join_u(&next, &knots, &0.0)?, Some(1));
    /// assert!(s.extend_cr_u(3, &knots, &[]).is_err()); // r > m
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn extend_cr_u(&self, r: usize, knots: &[S; 3], free: &[Vec<Point<S, D>>]) -> Result<Self> {
        self.extend_cr_u_with(r, knots, free, &mut NoCount)
    }

    /// The Cʳ continuation along u, counting its affine combinations.
    ///
    /// Idea: Stärk's theorem [PPB, §3.10] column by column [PPB, §9.7]: the first r + 1 Bézier
    /// points over [u₁, u₂] of the polynomial of column j are those of a Cʳ continuation; in
    /// the local parameter of this patch [u₁, u₂] is [1, λ], λ = (u₂ − u₀)/(u₁ − u₀), and the
    /// curve code restricts the column to it by two subdivisions.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::extend_cr_u`].
    ///
    /// # Complexity
    ///
    /// Θ((n + 1)m²D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// two de Casteljau triangles per column, exactly (n + 1)m(m + 1).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// let next = s.extend_cr_u_with(2, &[0.0, 1.0, 2.0], &[], &mut c)?;
    /// assert_eq!(next.net().get(2, 0), &Point::new([4.0, 0.0])); // x = 2u continued
    /// assert_eq!(c.arithmetic_operations, 4 * 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn extend_cr_u_with<C: Counter>(
        &self,
        r: usize,
        knots: &[S; 3],
        free: &[Vec<Point<S, D>>],
        counter: &mut C,
    ) -> Result<Self> {
        let (m, n) = self.bidegree();
        if r > m {
            return Err(Error::InvalidParameter {
                name: "r",
                reason: format!("C^{r} needs a degree of at least {r} in u, the patch has {m}"),
            });
        }
        let (h0, h1) = check_knots(knots)?;
        if free.len() != m - r || free.iter().any(|row| row.len() != n + 1) {
            return Err(Error::InvalidParameter {
                name: "free",
                reason: format!(
                    "a C^{r} continuation of bidegree ({m}, {n}) has {} free rows of {} points",
                    m - r,
                    n + 1
                ),
            });
        }
        for row in free {
            validate_points(row, "free rows")?;
        }
        let lambda = (h0.clone() + &h1) / &h0;
        let one = S::one();
        let columns: Vec<Vec<Point<S, D>>> = self
            .column_curves()
            .iter()
            .map(|column| {
                column
                    .restrict_by_splits(&one, &lambda, counter)
                    .into_control()
            })
            .collect();
        let mut points = Vec::with_capacity((m + 1) * (n + 1));
        for i in 0..=r {
            points.extend(columns.iter().map(|column| column[i].clone()));
        }
        for row in free {
            points.extend(row.iter().cloned());
        }
        BezierPatch::derived(m + 1, n + 1, points, "C^r continuation")
    }

    /// The patch over [v₁, v₂] that continues this one (over [v₀, v₁]) with Cʳ continuity
    /// along v = v₁: [`BezierPatch::extend_cr_u`] with u and v exchanged. Its first r + 1
    /// columns are determined; `free` holds the other n − r columns, each of m + 1 points
    /// (c̃_{0,j}, …, c̃_{m,j}). See [`BezierPatch::extend_cr_v_with`].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::extend_cr_u`], with n for m.
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)n²D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let s = BezierPatch::new(ControlNet::new(vec![vec![Point::new([0.0]), Point::new([1.0])]])?)?;
    /// let next = s.extend_cr_v(0, &[0.0, 1.0, 2.0], &[vec![Point::new([5.0])]])?;
    /// assert_eq!(next.net().row(0), [Point::new([1.0]), Point::new([5.0])]);
    /// assert_eq!(s.join_v(&next, &[0.0, 1.0, 2.0], &0.0)?, Some(0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn extend_cr_v(&self, r: usize, knots: &[S; 3], free: &[Vec<Point<S, D>>]) -> Result<Self> {
        self.extend_cr_v_with(r, knots, free, &mut NoCount)
    }

    /// The Cʳ continuation along v, counting: [`BezierPatch::extend_cr_u_with`] on the
    /// transposed net, transposed back.
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::extend_cr_v`].
    ///
    /// # Complexity
    ///
    /// Θ((m + 1)n²D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// Exactly (m + 1)n(n + 1) [`arithmetic_operation`](Counter::arithmetic_operation)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// s.extend_cr_v_with(3, &[0.0, 1.0, 2.0], &[], &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 3 * 12);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn extend_cr_v_with<C: Counter>(
        &self,
        r: usize,
        knots: &[S; 3],
        free: &[Vec<Point<S, D>>],
        counter: &mut C,
    ) -> Result<Self> {
        self.transposed()?
            .extend_cr_u_with(r, knots, free, counter)?
            .transposed()
    }

    /// The patch with u and v exchanged.
    fn transposed(&self) -> Result<Self> {
        BezierPatch::new(self.net().transposed())
    }
}

/// u₀ < u₁ < u₂, all finite: the widths (Δu₀, Δu₁).
fn check_knots<S: Scalar>(knots: &[S; 3]) -> Result<(S, S)> {
    for t in knots {
        validate_parameter(t, "knots")?;
    }
    if knots[0] < knots[1] && knots[1] < knots[2] {
        Ok((knots[1].clone() - &knots[0], knots[2].clone() - &knots[1]))
    } else {
        Err(Error::InvalidParameter {
            name: "knots",
            reason: format!(
                "u0 < u1 < u2 is required, got {}, {}, {}",
                knots[0].to_f64(),
                knots[1].to_f64(),
                knots[2].to_f64()
            ),
        })
    }
}

/// The derivatives of orders 0..=d of the curve with control points `column` (degree d) over
/// an interval of width `h`, at its end (`at_end`) or at its start: d!/(d − k)! Δ^k b/h^k with
/// Δ^k b_{d−k} or Δ^k b_0. One counted operation per difference and per scaling.
fn end_derivatives<S: Scalar, const D: usize, C: Counter>(
    mut column: Vec<Point<S, D>>,
    at_end: bool,
    h: &S,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let d = column.len() - 1;
    let mut out = Vec::with_capacity(d + 1);
    for k in 0..=d {
        let end = if at_end {
            column[column.len() - 1].clone()
        } else {
            column[0].clone()
        };
        counter.arithmetic_operation();
        out.push(end * (falling_factorial::<S>(d, k) / power(h, k)));
        if k < d {
            for _ in 1..column.len() {
                counter.arithmetic_operation();
            }
            difference(&mut column);
        }
    }
    out
}
