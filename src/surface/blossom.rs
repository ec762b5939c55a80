//! The tensor blossom (polar form) of a Bézier patch.
//!
//! The problem: b[u₁, …, u_m; v₁, …, v_n], the function that is symmetric in the u's and in
//! the v's, affine in each argument, and equal to the patch on its diagonal
//! b[u, …, u; v, …, v] = c(u, v) [PPB, §9.3], [FJ-surfaces, §4, eq. (12)]. The idea: the
//! blossom of a tensor product is the blossom of the curves of the rows at v₁, …, v_n (one de
//! Casteljau scheme with a different parameter per level on each row), then the blossom in u
//! of the m + 1 row values: the curve algorithm, row by row and then once across.
//!
//! Its values at 0s and 1s are the control points, c_{i,j} = b[0^{m−i}, 1^i; 0^{n−j}, 1^j],
//! and at a's and b's, c's and d's the control points of the piece over [a, b] × [c, d]
//! (the fundamental theorem, [PPB, §9.3]).
//!
//! # Complexity
//!
//! Θ(((m + 1)n² + m²)D) time, O((m + n)D) auxiliary space.
//!
//! Invariants the tests check (exactly on rationals): symmetric in each group, affine in each
//! argument, the patch on the diagonal, the control points at 0s and 1s.

use super::bezier::BezierPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::de_casteljau_levels;
use crate::spline::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// The tensor blossom, declared.
pub(crate) const BLOSSOM: Declaration = Declaration {
    problem: "bezier-patch",
    name: "blossom",
    function: "surface::BezierPatch::blossom",
    file: "src/surface/blossom.rs",
    summary: "the polar form: de Casteljau with distinct parameters on every row, then across",
    time: "Θ(((m + 1)n² + m²)D)",
    space: "O((m + n)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (m + 1)n(n + 1)/2 + m(m + 1)/2 affine combinations",
    source: "[PPB, §9.3], [FJ-surfaces, §4]",
    claims: &[on(
        "random-bidegree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The blossom b[u₁, …, u_m; v₁, …, v_n]. See [`BezierPatch::blossom_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"blossom arguments"` unless there are m arguments
    /// in u and n in v, named `"blossom argument"` for a NaN or infinite one.
    ///
    /// # Complexity
    ///
    /// Θ(((m + 1)n² + m²)D) time, O((m + n)D) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// // The bilinear patch of z = uv: its blossom is u₁v₁ (in z).
    /// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    /// let s = BezierPatch::new(ControlNet::new(vec![
    ///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
    ///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
    /// ])?)?;
    /// assert_eq!(s.blossom(&[3.0], &[5.0])?, p(3.0, 5.0, 15.0));
    /// assert!(s.blossom(&[3.0, 1.0], &[5.0]).is_err()); // bidegree (1, 1) takes one and one
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom(&self, us: &[S], vs: &[S]) -> Result<Point<S, D>> {
        self.blossom_with(us, vs, &mut NoCount)
    }

    /// The blossom b[u₁, …, u_m; v₁, …, v_n], counting its affine combinations.
    ///
    /// Idea: b[u₁ … u_m; v₁ … v_n] = b[v₁ … v_n][u₁ … u_m] [FJ-surfaces, §4, eq. (12)]: the
    /// blossom of each row's curve at the v's (de Casteljau's scheme with parameter v_k at
    /// level k, [PPB, §3.1]), then the blossom of the curve of those m + 1 points at the u's
    /// [PPB, §9.3].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::blossom`].
    ///
    /// # Complexity
    ///
    /// Θ(((m + 1)n² + m²)D) time, O((m + n)D) auxiliary space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// exactly (m + 1)n(n + 1)/2 + m(m + 1)/2.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// // Control point (1, 2) is the blossom at (0, 1; 0, 1, 1).
    /// assert_eq!(s.blossom_with(&[0.0, 1.0], &[0.0, 1.0, 1.0], &mut c)?, Point::new([1.0, 2.0]));
    /// assert_eq!(c.arithmetic_operations, 3 * 6 + 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom_with<C: Counter>(
        &self,
        us: &[S],
        vs: &[S],
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        let (m, n) = self.bidegree();
        if us.len() != m || vs.len() != n {
            return Err(Error::InvalidParameter {
                name: "blossom arguments",
                reason: format!(
                    "a patch of bidegree ({m}, {n}) needs {m} arguments in u and {n} in v, got \
                     {} and {}",
                    us.len(),
                    vs.len()
                ),
            });
        }
        for t in us.iter().chain(vs) {
            validate_parameter(t, "blossom argument")?;
        }
        let mut scratch = Vec::with_capacity(n + 1);
        let mut values = Vec::with_capacity(m + 1);
        for i in 0..=m {
            scratch.clear();
            scratch.extend_from_slice(self.net().row(i));
            de_casteljau_levels(&mut scratch, vs, counter);
            values.push(scratch.swap_remove(0));
        }
        de_casteljau_levels(&mut values, us, counter);
        Ok(values.swap_remove(0))
    }
}
