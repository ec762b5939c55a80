//! The uniform four-way split of a triangular patch at the midpoints of its edges.
//!
//! The problem: the Bézier nets of the patch over the four triangles into which the
//! midpoints a, b, c of the edges q r, r p, p q cut the reference triangle p q r: the corner
//! triangles p c b, c q a, b a r and the middle one a b c [PPB, §11.5, Fig. 11.6]. Repeated,
//! the split gives nets that converge to the surface [PPB, §11.4–11.5].
//!
//! The idea: repeated bisection [PPB, §11.5, Fig. 11.7], the book's cheap strategy that takes
//! only convex combinations. Subdividing a net at the midpoint of one of its edges is a de
//! Casteljau scheme whose combinations are all convex (weights ½, ½, 0), and one scheme gives
//! both halves [PPB, §11.3]. Five bisections give the three corners: p q r at c into p c r and
//! c q r; p c r at b into p c b (a corner); c q r at a into c q a (a corner) and c a r;
//! p q r at b into b q r; b q r at a into b a r (a corner). The middle triangle is inside no
//! triangle that bisections produce, and reaching it takes the one non-convex step the book
//! warns about for the uniform split [PPB, §11.5, item 3]: c a r subdivided at
//! b = c − a + r (weights 1, −1, 1) gives the net over c a b, reordered as a b c. With `f64`
//! that last scheme may amplify rounding by up to 3 per level, 3ⁿ in all; with rationals
//! every net is exact.
//!
//! Each corner piece keeps its vertex of p q r in its place, and the middle piece has at
//! vertex t the midpoint of the edge opposite vertex t: the point with barycentric
//! coordinates y in corner t is the point (y + e_t)/2 of p q r, and in the middle piece the
//! point (1 − y)/2 (coordinate by coordinate). All four are counter-clockwise when p q r is.
//!
//! # Complexity
//!
//! Θ(n³D) time, Θ(n²D) space.
//!
//! Invariants the tests check (exactly on rationals): every piece at y equals the patch at
//! the mapped point; the pieces are the blossom at the vertices of their triangles; the
//! count.

use super::de_casteljau::sub_nets;
use super::patch::TriangularPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::Scalar;
use crate::Result;

/// The four-way split, declared.
pub(crate) const SPLIT_FOUR: Declaration = Declaration {
    problem: "triangular-patch",
    name: "split-four",
    function: "surface::TriangularPatch::split_four",
    file: "src/surface/triangle/split.rs",
    summary: "five bisections at edge midpoints for the corners, one extrapolation for the middle",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "exactly n(n + 1)(n + 2) affine combinations of three points (six de Casteljau schemes)",
    source: "[PPB, §11.3, §11.5]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The patch over the four triangles of the midpoint split: the corners p c b, c q a,
    /// b a r and the middle a b c, in this order, where a, b, c are the midpoints of q r, r p
    /// and p q. See [`TriangularPatch::split_four_with`].
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
    /// let b = TriangularPatch::new((0..10).map(|k| Point::new([(k * k) as f64])).collect())?;
    /// let [corner_p, _, _, middle] = b.split_four()?;
    /// // The corner p c b at y is the patch at (y + e₀)/2, the middle a b c at (1 − y)/2.
    /// let y = Barycentric::new(0.5, 0.25, 0.25)?;
    /// assert_eq!(corner_p.de_casteljau(&y), b.de_casteljau(&Barycentric::new(0.75, 0.125, 0.125)?));
    /// assert_eq!(middle.de_casteljau(&y), b.de_casteljau(&Barycentric::new(0.25, 0.375, 0.375)?));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_four(&self) -> Result<[Self; 4]> {
        self.split_four_with(&mut NoCount)
    }

    /// The four-way split, counting the affine combinations.
    ///
    /// Idea: bisection at edge midpoints [PPB, §11.5, Fig. 11.7], one de Casteljau scheme per
    /// bisection with both halves read off its faces [PPB, §11.3]: five bisections, all
    /// convex, give the three corners (p q r at c, p c r at b, c q r at a, p q r at b, b q r
    /// at a); the middle lies in no triangle that bisections produce, and one scheme on c a r
    /// at b = c − a + r (weights 1, −1, 1, the one non-convex step) gives it. With `f64`
    /// that scheme may amplify rounding by up to 3 per level.
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::split_four`].
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// three points: six schemes of n(n + 1)(n + 2)/6, exactly n(n + 1)(n + 2).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::TriangularPatch;
    ///
    /// let b = TriangularPatch::new(vec![Point::new([1.0]); 10])?; // degree 3
    /// let mut c = Counts::default();
    /// assert!(b.split_four_with(&mut c)?.iter().all(|piece| piece == &b));
    /// assert_eq!(c.arithmetic_operations, 3 * 4 * 5);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split_four_with<C: Counter>(&self, counter: &mut C) -> Result<[Self; 4]> {
        let n = self.degree();
        let (zero, half, one) = (S::zero(), S::from_ratio(1, 2), S::one());
        // The midpoints of the edges opposite vertex 2 (p q), 1 (p r) and 0 (q r) of whichever
        // triangle is subdivided.
        let mid_pq = [half.clone(), half.clone(), zero.clone()];
        let mid_pr = [half.clone(), zero.clone(), half.clone()];
        let mid_qr = [zero, half.clone(), half];
        let points = self.points();
        // p q r at c: the pieces over c q r and p c r.
        let [cqr, pcr, _] = sub_nets(points, n, &mid_pq, counter);
        // p c r at b (the midpoint of its edge p r): the corner p c b.
        let [_, _, corner_p] = sub_nets(&pcr, n, &mid_pr, counter);
        // c q r at a (the midpoint of its edge q r): the corner c q a, and c a r.
        let [_, car, corner_q] = sub_nets(&cqr, n, &mid_qr, counter);
        // p q r at b, then b q r at a: the corner b a r.
        let [bqr, _, _] = sub_nets(points, n, &mid_pr, counter);
        let [_, corner_r, _] = sub_nets(&bqr, n, &mid_qr, counter);
        // c a r at b = c − a + r: the middle, over c a b.
        let [_, _, cab] = sub_nets(&car, n, &[one.clone(), -one.clone(), one], counter);
        let what = "triangular four-way split";
        Ok([
            Self::derived(n, corner_p, what)?,
            Self::derived(n, corner_q, what)?,
            Self::derived(n, corner_r, what)?,
            // Vertex t of a b c is vertex [1, 2, 0][t] of c a b.
            Self::derived(n, cab, what)?.permuted([1, 2, 0]),
        ])
    }
}
