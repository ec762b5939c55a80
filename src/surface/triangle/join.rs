//! Cʳ joins of two triangular patches along a common edge: the check and the continuation.
//!
//! The problem: a patch b over the triangle p q r and a patch c over the triangle q p s on
//! the other side of the edge p q (the same edge traversed the other way, so that both
//! triangles are counter-clockwise when s is across p q from r); do their derivatives of
//! orders 0 to r agree along p q, and which points of c make them agree? The point s is
//! given in barycentric coordinates with respect to p q r; its w-coordinate is nonzero
//! (negative when the triangles do not overlap).
//!
//! The idea: Farin's version of Stärk's theorem [PPB, §11.7]: the derivatives agree up to
//! order r on the edge exactly when the first r + 1 rows parallel to it of c's net are those
//! of b's polynomial over q p s, b[q^i p^j s^k] = c_{ijk} for k ≤ r. Those are points of the
//! subdivision of b at s [PPB, §11.3]: level k of de Casteljau's scheme at s holds
//! b[p^i q^j s^k] in its first row. The rows of constant k come first in the storage order,
//! so the rows that Cʳ fixes are the first points of c's net.
//!
//! # Exactness
//!
//! With `BigRational` pass a zero tolerance: the check is exact. With `f64` the points are
//! rounded, and the check takes a relative tolerance as the tensor patches' joins do: two
//! points a, b count as equal when |a − b|² ≤ tol²·max(|a|², |b|²).
//!
//! # Complexity
//!
//! Θ(n³D) time, Θ(n²D) space, for both.
//!
//! Invariants the tests check (exactly on rationals): the continuation passes the check at
//! its order and a perturbation of its row r fails it; the derivatives of both patches
//! across the edge agree up to order r; the counts.

use super::barycentric::Barycentric;
use super::de_casteljau::level;
use super::patch::TriangularPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::nearly_equal;
use crate::spline::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// The Cʳ check, declared.
pub(crate) const JOIN_ORDER: Declaration = Declaration {
    problem: "triangular-patch",
    name: "join-order",
    function: "surface::TriangularPatch::join_order",
    file: "src/surface/triangle/join.rs",
    summary: "the neighbour's rows parallel to the edge against the subdivision of the patch at its far vertex",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)(n + 2)/6 affine combinations of three points",
    source: "[PPB, §11.7]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// The Cʳ continuation, declared.
pub(crate) const EXTEND_CR: Declaration = Declaration {
    problem: "triangular-patch",
    name: "extend-cr",
    function: "surface::TriangularPatch::extend_cr",
    file: "src/surface/triangle/join.rs",
    summary: "Stärk's construction: r levels of de Casteljau at the far vertex give the fixed rows",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)(n + 2)/6 − (n − r)(n − r + 1)(n − r + 2)/6 affine combinations",
    source: "[PPB, §11.7]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// How this patch, over p q r, meets `other`, over q p s, along the edge p q: the largest
    /// r such that their derivatives of orders 0..=r agree along the edge (the join is Cʳ),
    /// or `None` if the edges differ (not even C⁰). `Some(n)` means one polynomial. See
    /// [`TriangularPatch::join_order_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"other"` if the degrees differ, `"s"` if s lies on
    /// the line p q (its w-coordinate is zero: no triangle), `"tolerance"` for a negative,
    /// NaN or infinite tolerance.
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// // The plane map (u, v, w) ↦ (u, v) over p q r = (1, 0), (0, 1), (0, 0) and its
    /// // continuation over q p s with s = (1, 1) = p + q − r.
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// let b = TriangularPatch::new(vec![p(1.0, 0.0), p(0.0, 1.0), p(0.0, 0.0)])?;
    /// let s = Barycentric::new(1.0, 1.0, -1.0)?;
    /// let c = TriangularPatch::new(vec![p(0.0, 1.0), p(1.0, 0.0), p(1.0, 1.0)])?;
    /// assert_eq!(b.join_order(&c, &s, &0.0)?, Some(1)); // one polynomial
    /// let kinked = TriangularPatch::new(vec![p(0.0, 1.0), p(1.0, 0.0), p(2.0, 2.0)])?;
    /// assert_eq!(b.join_order(&kinked, &s, &0.0)?, Some(0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn join_order(
        &self,
        other: &Self,
        s: &Barycentric<S>,
        tolerance: &S,
    ) -> Result<Option<usize>> {
        self.join_order_with(other, s, tolerance, &mut NoCount)
    }

    /// The Cʳ check along p q, counting the affine combinations.
    ///
    /// Idea: by Stärk's theorem [PPB, §11.7] the join is Cʳ exactly when the rows k ≤ r of
    /// `other` are b[q^i p^j s^k], the first rows of the levels of de Casteljau's scheme at s
    /// (read backwards: the scheme lists them from p to q); the rows are compared in order
    /// until one differs.
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::join_order`].
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// the scheme, every level computed before comparing: exactly n(n + 1)(n + 2)/6.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0]); 10])?; // degree 3, constant
    /// let mut c = Counts::default();
    /// let s = Barycentric::new(1.0, 1.0, -1.0)?;
    /// assert_eq!(b.join_order_with(&b, &s, &0.0, &mut c)?, Some(3));
    /// assert_eq!(c.arithmetic_operations, 10);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn join_order_with<C: Counter>(
        &self,
        other: &Self,
        s: &Barycentric<S>,
        tolerance: &S,
        counter: &mut C,
    ) -> Result<Option<usize>> {
        let n = self.degree();
        if other.degree() != n {
            return Err(Error::InvalidParameter {
                name: "other",
                reason: format!(
                    "a join compares nets of one degree; the patches have degrees {n} and {}",
                    other.degree()
                ),
            });
        }
        check_far_vertex(s)?;
        validate_parameter(tolerance, "tolerance")?;
        if *tolerance < S::zero() {
            return Err(Error::InvalidParameter {
                name: "tolerance",
                reason: format!("a tolerance is not negative, got {}", tolerance.to_f64()),
            });
        }
        let rows = across_rows(self.points(), n, n, s, counter);
        let mut start = 0;
        let mut agree: usize = 0;
        for row in &rows {
            let theirs = &other.points()[start..start + row.len()];
            if !row
                .iter()
                .zip(theirs)
                .all(|(a, b)| nearly_equal(a, b, tolerance))
            {
                break;
            }
            start += row.len();
            agree += 1;
        }
        Ok(agree.checked_sub(1))
    }

    /// The patch over q p s that continues this one across the edge p q with Cʳ
    /// continuity: its rows k ≤ r (the first (r + 1)(2n − r + 2)/2 points of its net) are
    /// determined, the other (n − r)(n − r + 1)/2 points are `free`, in the storage order.
    /// `r = n` continues the same polynomial. See [`TriangularPatch::extend_cr_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"r"` if r > n, `"s"` if s lies on the line p q,
    /// `"free"` unless there are (n − r)(n − r + 1)/2 free points; [`Error::NonFinite`] with
    /// the index of a NaN or infinite free point; [`Error::Overflow`] if, with `f64`, a
    /// point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new((0..6).map(|k| Point::new([(k * k) as f64])).collect())?;
    /// let s = Barycentric::new(1.0, 1.0, -1.0)?;
    /// let c = b.extend_cr(&s, 1, &[Point::new([7.0])])?; // one free point, b'_{002}
    /// assert_eq!(c.get(0, 0, 2), Some(&Point::new([7.0])));
    /// assert_eq!(b.join_order(&c, &s, &0.0)?, Some(1));
    /// assert!(b.extend_cr(&s, 3, &[]).is_err()); // r > n
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn extend_cr(&self, s: &Barycentric<S>, r: usize, free: &[Point<S, D>]) -> Result<Self> {
        self.extend_cr_with(s, r, free, &mut NoCount)
    }

    /// The Cʳ continuation across p q, counting its affine combinations.
    ///
    /// Idea: Stärk's construction [PPB, §11.7]: the first r levels of de Casteljau's scheme
    /// at s give b[p^i q^j s^k], k ≤ r, the rows that a Cʳ neighbour over q p s shares with b
    /// (its point c_{ijk} is b[q^i p^j s^k]); the rest of the net is free.
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::extend_cr`].
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// levels 1 to r: exactly n(n + 1)(n + 2)/6 − (n − r)(n − r + 1)(n − r + 2)/6.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0]); 10])?; // degree 3
    /// let s = Barycentric::new(1.0, 1.0, -1.0)?;
    /// let mut c = Counts::default();
    /// b.extend_cr_with(&s, 1, &[Point::new([1.0]); 3], &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6); // the level of degree 3 only
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn extend_cr_with<C: Counter>(
        &self,
        s: &Barycentric<S>,
        r: usize,
        free: &[Point<S, D>],
        counter: &mut C,
    ) -> Result<Self> {
        let n = self.degree();
        if r > n {
            return Err(Error::InvalidParameter {
                name: "r",
                reason: format!("C^{r} needs a degree of at least {r}, the patch has {n}"),
            });
        }
        check_far_vertex(s)?;
        let wanted = (n - r) * (n - r + 1) / 2;
        if free.len() != wanted {
            return Err(Error::InvalidParameter {
                name: "free",
                reason: format!(
                    "a C^{r} continuation of degree {n} has {wanted} free points, got {}",
                    free.len()
                ),
            });
        }
        for (index, p) in free.iter().enumerate() {
            if let Some(c) = p.coords().iter().find(|c| !c.is_finite()) {
                return Err(Error::NonFinite {
                    index,
                    value: c.to_f64(),
                });
            }
        }
        let mut points: Vec<Point<S, D>> = across_rows(self.points(), n, r, s, counter)
            .into_iter()
            .flatten()
            .collect();
        points.extend_from_slice(free);
        Self::derived(n, points, "triangular C^r continuation")
    }
}

/// The rows k = 0, …, r of the net over q p s of the polynomial of `points` (degree n):
/// row k is b[q^i p^j s^k], j = 0, …, n − k, the first row of level k of de Casteljau's scheme
/// at s (which runs from p to q) reversed. Counts the combinations of levels 1 to r.
fn across_rows<S: Scalar, const D: usize, C: Counter>(
    points: &[Point<S, D>],
    n: usize,
    r: usize,
    s: &Barycentric<S>,
    counter: &mut C,
) -> Vec<Vec<Point<S, D>>> {
    let mut q = points.to_vec();
    let mut rows = Vec::with_capacity(r + 1);
    for k in 0..=r {
        let m = n - k;
        if k > 0 {
            level(&mut q, m + 1, s.coords(), counter);
        }
        rows.push(q[..=m].iter().rev().cloned().collect());
    }
    rows
}

/// s makes a triangle with p and q: its w-coordinate is nonzero.
fn check_far_vertex<S: Scalar>(s: &Barycentric<S>) -> Result<()> {
    if s.coords()[2].is_zero() {
        Err(Error::InvalidParameter {
            name: "s",
            reason: "the vertex across the edge p q lies on the line p q (its w-coordinate is \
                     zero), so q p s is no triangle"
                .to_string(),
        })
    } else {
        Ok(())
    }
}
