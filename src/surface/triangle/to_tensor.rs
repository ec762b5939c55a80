//! Conversion of a triangular patch to a tensor-product patch: a triangle as a degenerate
//! square.
//!
//! The problem: a [`BezierPatch`] c(s, t) of bidegree (n, n) that covers the triangle of a
//! patch b of degree n. The bilinear map x(s, t) of [PPB, §11.10] sends the unit square onto
//! the triangle when two corners of the square go to the same vertex: here x(0, t) = r,
//! x(1, 0) = p, x(1, 1) = q, that is (u, v, w) = (s(1 − t), st, 1 − s), and
//! c(s, t) = b(x(s, t)) is a tensor product of bidegree (n, n) [PPB, §11.10]. The edge s = 0
//! collapses to the vertex r, where c_t vanishes.
//!
//! The idea: in these coordinates the Bernstein polynomials factor,
//! B^n_{ijk}(s(1 − t), st, 1 − s) = B^n_{n−k}(s) · B^{n−k}_j(t), so
//! c(s, t) = Σ_a B^n_a(s) Σ_j b_{a−j, j, n−a} B^a_j(t): row a of the tensor net is row
//! k = n − a of the triangular net (a Bézier polygon of degree a) elevated to degree n. This
//! is the book's formula c_{ij} = Σ_k β_{ijk} b[x₀₀^{n+k−i−j} x₀₁^{j−k} x₁₀^{i−k} x₁₁^k] with
//! x₀₀ = x₀₁ = r, x₁₀ = p, x₁₁ = q, whose weights β_{ijk} = C(i, k) C(n − i, j − k)/C(n, j)
//! are those of Zhou's degree elevation [PPB, §3.12].
//!
//! # Complexity
//!
//! Θ(n³D) time, Θ(n²D) space.
//!
//! Invariants the tests check (exactly on rationals): c(s, t) = b(s(1 − t), st, 1 − s) at
//! every (s, t); the count.

use super::patch::{row_offset, TriangularPatch};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Bezier, Scalar};
use crate::surface::BezierPatch;
use crate::{limits, Result};

/// Triangular to tensor-product, declared.
pub(crate) const TO_TENSOR: Declaration = Declaration {
    problem: "triangular-patch",
    name: "to-tensor",
    function: "surface::TriangularPatch::to_tensor",
    file: "src/surface/triangle/to_tensor.rs",
    summary: "the degenerate square (s(1 − t), st, 1 − s): row n − a of the net elevated to degree n is row a",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)(n + 2)(n + 3)/6 terms of Zhou's formula",
    source: "[PPB, §11.10]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The tensor-product patch c(s, t) = b(s(1 − t), st, 1 − s) of bidegree (n, n) over the
    /// unit square, whose edge s = 0 is collapsed to the vertex r. See
    /// [`TriangularPatch::to_tensor_with`].
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if (n + 1)² exceeds
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS); [`Error::Overflow`](crate::Error::Overflow)
    /// if, with `f64`, a point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, Surface, TriangularPatch};
    ///
    /// let b = TriangularPatch::new((0..6).map(|k| Point::new([k as f64, (k * k) as f64])).collect())?;
    /// let c = b.to_tensor()?;
    /// assert_eq!(c.bidegree(), (2, 2));
    /// let (s, t) = (0.5, 0.25);
    /// assert_eq!(c.eval(&s, &t)?, b.de_casteljau(&Barycentric::new(0.375, 0.125, 0.5)?));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_tensor(&self) -> Result<BezierPatch<S, D>> {
        self.to_tensor_with(&mut NoCount)
    }

    /// The tensor-product form, counting the terms of the elevations.
    ///
    /// Idea: with (u, v, w) = (s(1 − t), st, 1 − s) the Bernstein polynomials factor as
    /// B^n_{n−k}(s) B^{n−k}_j(t), so row a of the tensor net is row n − a of the triangular
    /// net elevated from degree a to n by Zhou's formula [PPB, §11.10, §3.12].
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::to_tensor`].
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per term of Zhou's
    /// formula: row a takes (a + 1)(n − a + 1), exactly (n + 1)(n + 2)(n + 3)/6 in all.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::TriangularPatch;
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0]); 6])?; // degree 2
    /// let mut c = Counts::default();
    /// let t = b.to_tensor_with(&mut c)?;
    /// assert!(t.net().points().iter().all(|p| *p == Point::new([1.0])));
    /// assert_eq!(c.arithmetic_operations, 3 * 4 * 5 / 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_tensor_with<C: Counter>(&self, counter: &mut C) -> Result<BezierPatch<S, D>> {
        let n = self.degree();
        limits::POINTS.check((n as u128 + 1) * (n as u128 + 1))?;
        let mut net = Vec::with_capacity((n + 1) * (n + 1));
        for a in 0..=n {
            let start = row_offset(n, n - a);
            let row = Bezier::new(self.points()[start..=start + a].to_vec())
                .expect("a row of a valid net is a valid polygon");
            net.extend(row.elevate_to_counted(n, counter));
        }
        BezierPatch::derived(n + 1, n + 1, net, "triangular to tensor conversion")
    }
}
