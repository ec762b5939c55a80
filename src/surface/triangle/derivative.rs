//! Directional derivatives of a triangular patch, of any order, through its blossom.
//!
//! The problem: D_{d₁} ⋯ D_{d_r} b(x), the r-th derivative of the patch at the point x along
//! the directions d₁, …, d_r (barycentric differences, their coordinates summing to 0),
//! with d₁ = ⋯ = d_r = d the r-th derivative along the line x + t·d. The idea: the blossom
//! is affine in each argument, so it extends linearly to directions, and
//! D_{d₁} ⋯ D_{d_r} b(x) = n!/(n − r)! · b[d₁, …, d_r, x, …, x] [PPB, §11.6]: r levels of
//! the de Casteljau scheme with the directions as weights (differences Δ_d, [PPB, §10.5]),
//! then n − r levels at x, in either order since the levels commute. Zero for r > n.
//!
//! # Complexity
//!
//! Θ(n³D) time, Θ(n²D) space.
//!
//! Invariants the tests check (exactly on rationals): the term-by-term derivative of the
//! Bernstein sum, ∂B^n_i/∂u_t = n B^{n−1}_{i−e_t} [PPB, §10.5]; the blossom at points by
//! finite differences of its affine arguments; the partial derivatives of the surface in
//! (u, v); the counts.

use super::barycentric::{Barycentric, BarycentricVector};
use super::patch::TriangularPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};

/// The directional derivatives, declared.
pub(crate) const DIRECTIONAL_DERIVATIVE: Declaration = Declaration {
    problem: "triangular-patch",
    name: "derivative",
    function: "surface::TriangularPatch::directional_derivative",
    file: "src/surface/triangle/derivative.rs",
    summary: "the blossom with r directions among its arguments, times n!/(n − r)!",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)(n + 2)/6 combinations of three points and one scaling for 1 ≤ r ≤ n",
    source: "[PPB, §10.5], [PPB, §11.6]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The derivative D_{d₁} ⋯ D_{d_r} b(x) along the directions `directions` (r of them;
    /// none: the point b(x)). See [`TriangularPatch::directional_derivative_with`].
    ///
    /// With the reference triangle p q r of the plane, D_d is the derivative along the
    /// vector du·p + dv·q + dw·r. With `f64` a result beyond the double range comes out with
    /// infinite coordinates.
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, BarycentricVector, TriangularPatch};
    ///
    /// // z = u·v = B_{110}/2 in the (u, v) plane of the triangle (1, 0), (0, 1), (0, 0).
    /// let z = |c: f64| Point::new([c]);
    /// let b = TriangularPatch::new(vec![z(0.0), z(0.5), z(0.0), z(0.0), z(0.0), z(0.0)])?;
    /// let x = Barycentric::new(0.5, 0.25, 0.25)?;
    /// let along_u = BarycentricVector::new(1.0, 0.0, -1.0)?; // p − r, the u axis
    /// let along_v = BarycentricVector::new(0.0, 1.0, -1.0)?;
    /// assert_eq!(b.directional_derivative(&x, &[along_u.clone()]), z(0.25)); // ∂(uv)/∂u = v
    /// assert_eq!(b.directional_derivative(&x, &[along_u.clone(), along_v]), z(1.0));
    /// assert_eq!(b.directional_derivative(&x, &[along_u.clone(), along_u]), z(0.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn directional_derivative(
        &self,
        at: &Barycentric<S>,
        directions: &[BarycentricVector<S>],
    ) -> Point<S, D> {
        self.directional_derivative_with(at, directions, &mut NoCount)
    }

    /// The directional derivative D_{d₁} ⋯ D_{d_r} b(x), counting its operations.
    ///
    /// Idea: n!/(n − r)! · b[d₁, …, d_r, x, …, x] [PPB, §11.6]: the first r levels of de
    /// Casteljau's scheme take the weights of the directions (the differences
    /// c_j = Δ_d b_j = du b_{j+e₀} + dv b_{j+e₁} + dw b_{j+e₂} of [PPB, §10.5]), the last
    /// n − r the coordinates of x.
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per combination of three
    /// points, exactly n(n + 1)(n + 2)/6, and one for the scaling by n!/(n − r)! when
    /// 1 ≤ r ≤ n; nothing for r > n (the zero vector).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, BarycentricVector, TriangularPatch};
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0]); 10])?; // degree 3, constant
    /// let x = Barycentric::new(0.5, 0.25, 0.25)?;
    /// let d = BarycentricVector::from_uv(1.0, 2.0)?;
    /// let mut c = Counts::default();
    /// assert_eq!(b.directional_derivative_with(&x, &[d], &mut c), Point::new([0.0]));
    /// assert_eq!(c.arithmetic_operations, 10 + 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn directional_derivative_with<C: Counter>(
        &self,
        at: &Barycentric<S>,
        directions: &[BarycentricVector<S>],
        counter: &mut C,
    ) -> Point<S, D> {
        self.derivative_counted(at, directions, counter)
    }
}
