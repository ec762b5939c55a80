//! Subdivision of a triangular patch at a point into three patches.
//!
//! The problem: for a point x of the plane, the Bézier nets of the same polynomial over the
//! three triangles x q r, p x r and p q x into which x cuts the reference triangle p q r.
//! The idea: de Casteljau's scheme at x computes them on the way [PPB, §11.3]: its level-l
//! points are b[p^i q^j r^k x^l], so those with i = 0 are the points b[x^l q^j r^k] of the net
//! over x q r, those with j = 0 the net over p x r, those with k = 0 the net over p q x
//! (the fundamental theorem, [PPB, §11.2]). For x inside the triangle every combination is
//! convex; outside it the three nets fold over one another but still describe the
//! polynomial [PPB, §11.3].
//!
//! Each piece keeps the orientation of p q r: vertex t of piece t is x, the other two are
//! those of p q r, so the point with barycentric coordinates y in piece t is the point of
//! p q r with coordinates y_t·x + Σ_{s ≠ t} y_s·e_s.
//!
//! # Complexity
//!
//! Θ(n³D) time, Θ(n²D) space.
//!
//! Invariants the tests check (exactly on rationals): every piece at y equals the patch at
//! the mapped point; the pieces are the blossom at the vertices of their triangles; the
//! count.

use super::barycentric::Barycentric;
use super::de_casteljau::sub_nets;
use super::patch::TriangularPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::Scalar;
use crate::Result;

/// Subdivision at a point, declared.
pub(crate) const SUBDIVIDE: Declaration = Declaration {
    problem: "triangular-patch",
    name: "subdivide",
    function: "surface::TriangularPatch::subdivide",
    file: "src/surface/triangle/subdivide.rs",
    summary:
        "de Casteljau's scheme at x, its three faces read off as the nets over x q r, p x r, p q x",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)(n + 2)/6 affine combinations of three points",
    source: "[PPB, §11.3]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The patch over x q r, p x r and p q x, in this order: the triangle p q r with vertex
    /// t replaced by x in piece t. See [`TriangularPatch::subdivide_with`].
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`](crate::Error::Overflow) if, with `f64`, a point is beyond the
    /// double range.
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
    /// let x = Barycentric::new(0.5, 0.25, 0.25)?;
    /// let [over_xqr, _, _] = b.subdivide(&x)?;
    /// // The vertex x of the piece x q r is b(x); its point at (1/2, 1/2, 0) is b((x + q)/2).
    /// assert_eq!(over_xqr.get(2, 0, 0), Some(&b.de_casteljau(&x)));
    /// let halfway = Barycentric::new(0.25, 0.625, 0.125)?;
    /// assert_eq!(over_xqr.de_casteljau(&Barycentric::new(0.5, 0.5, 0.0)?), b.de_casteljau(&halfway));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn subdivide(&self, at: &Barycentric<S>) -> Result<[Self; 3]> {
        self.subdivide_with(at, &mut NoCount)
    }

    /// The three pieces of the subdivision at x, counting the affine combinations.
    ///
    /// Idea: the level-l points of de Casteljau's scheme at x are b[p^i q^j r^k x^l]; the
    /// net over a triangle with x for vertex t is the face of the tetrahedral scheme where
    /// the t-th index is 0 [PPB, §11.3, Fig. 11.2].
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::subdivide`].
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// three points: exactly n(n + 1)(n + 2)/6, those of one evaluation.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0]); 15])?; // degree 4
    /// let mut c = Counts::default();
    /// let pieces = b.subdivide_with(&Barycentric::new(0.5, 0.25, 0.25)?, &mut c)?;
    /// assert!(pieces.iter().all(|piece| piece == &b)); // a constant stays constant
    /// assert_eq!(c.arithmetic_operations, 4 * 5 * 6 / 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn subdivide_with<C: Counter>(
        &self,
        at: &Barycentric<S>,
        counter: &mut C,
    ) -> Result<[Self; 3]> {
        let n = self.degree();
        let [a, b, c] = sub_nets(self.points(), n, at.coords(), counter);
        let what = "triangular subdivision";
        Ok([
            Self::derived(n, a, what)?,
            Self::derived(n, b, what)?,
            Self::derived(n, c, what)?,
        ])
    }
}
