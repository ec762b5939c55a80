//! The blossom (polar form) of a triangular patch.
//!
//! The problem: b[x₁, …, x_n], the unique function of n points of the plane that is
//! symmetric, affine in each argument, and equal to the patch on its diagonal,
//! b[x, …, x] = b(x) [PPB, §11.1]. The idea: de Casteljau's scheme with a different point per
//! level, x_l at level l (the recurrence (1) of the fundamental theorem, [PPB, §11.2]). Its
//! values at the vertices are the control points, b[p^i q^j r^k] = b_{ijk}, and at the
//! vertices of another triangle the control points over that triangle [PPB, §11.2–11.3].
//!
//! # Complexity
//!
//! Θ(n³D) time, Θ(n²D) space.
//!
//! Invariants the tests check (exactly on rationals): symmetric, affine in each argument, the
//! patch on the diagonal, the control points at the vertices.

use super::barycentric::Barycentric;
use super::de_casteljau::level;
use super::patch::TriangularPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};
use crate::{Error, Result};

/// The triangular blossom, declared.
pub(crate) const BLOSSOM: Declaration = Declaration {
    problem: "triangular-patch",
    name: "blossom",
    function: "surface::TriangularPatch::blossom",
    file: "src/surface/triangle/blossom.rs",
    summary: "de Casteljau's scheme with the argument x_l at level l",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)(n + 2)/6 affine combinations of three points",
    source: "[PPB, §11.1–11.2]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The blossom b[x₁, …, x_n]. See [`TriangularPatch::blossom_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"blossom arguments"` unless there are n arguments.
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new((0..6).map(|k| Point::new([k as f64])).collect())?; // degree 2
    /// let (p, r) = (Barycentric::vertex(0), Barycentric::vertex(2));
    /// assert_eq!(b.blossom(&[p, r])?, Point::new([3.0])); // b_{101}, index 3
    /// assert!(b.blossom(&[Barycentric::vertex(1)]).is_err()); // degree 2 takes two
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom(&self, args: &[Barycentric<S>]) -> Result<Point<S, D>> {
        self.blossom_with(args, &mut NoCount)
    }

    /// The blossom b[x₁, …, x_n], counting its affine combinations.
    ///
    /// Idea: level l of de Casteljau's scheme at x_l turns the points
    /// b[p^i q^j r^k x₁ ⋯ x_{l−1}] into b[p^i q^j r^k x₁ ⋯ x_l]: each is the combination of
    /// three with the barycentric coordinates of x_l [PPB, §11.2, eq. (1)].
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::blossom`].
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// three points: exactly n(n + 1)(n + 2)/6.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0, 2.0]); 10])?; // degree 3
    /// let x = Barycentric::new(0.5, 0.25, 0.25)?;
    /// let mut c = Counts::default();
    /// assert_eq!(b.blossom_with(&[x.clone(), x.clone(), x], &mut c)?, Point::new([1.0, 2.0]));
    /// assert_eq!(c.arithmetic_operations, 10);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom_with<C: Counter>(
        &self,
        args: &[Barycentric<S>],
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        let n = self.degree();
        if args.len() != n {
            return Err(Error::InvalidParameter {
                name: "blossom arguments",
                reason: format!(
                    "a triangular patch of degree {n} has a blossom of {n} arguments, got {}",
                    args.len()
                ),
            });
        }
        let mut q = self.points().to_vec();
        for (l, x) in args.iter().enumerate() {
            level(&mut q, n - l, x.coords(), counter);
        }
        Ok(q.swap_remove(0))
    }
}
