//! Recursive subdivision of a cubic Beta-spline's control polygon: k rounds of S_L and S_R.
//!
//! The problem: control polygons of ever shorter pieces of the curve, which converge to it
//! [CCKS, §2–3]. The idea: every segment's four control points are one polygon; a round
//! replaces each polygon P by the two polygons S_L·P and S_R·P of its pieces over [0, c] and
//! [c, 1] (see [`SubdivisionMatrices`](super::SubdivisionMatrices)); the matrices are
//! computed once. After k rounds the m segments are m·2ᵏ polygons of four points, in the
//! order of the curve.
//!
//! Pieces of neighbouring segments are kept apart: the refined curve is a Beta-spline whose
//! new joints (inside the old segments) are C² while the old ones keep β₁, β₂, so the
//! pieces do not share control points as the uniform B-spline's do.
//!
//! Convergence: a piece of parameter length h whose curve is q(s) = a + bs + cs² + ds³ has
//! control points Lⱼ = a + bξⱼ + cζⱼ + dηⱼ, where ξ, ζ, η are the basis's coefficients of
//! s, s², s³ (fixed numbers); so |Lⱼ − q(ξⱼ)| ≤ |c|·|ζⱼ − ξⱼ²| + |d|·|ηⱼ − ξⱼ³|, and c, d
//! shrink as h² and h³. With c = ½ a round halves h: the distance of the polygons to the
//! curve falls by a factor of 4 per round (exactly 4 for a quadratic curve; for a cubic the
//! bound falls by at least 4 — the tests check both).
//!
//! Follows [CCKS, §2–3] (the seed's figures: three and five rounds at c = ½).
//!
//! # Complexity
//!
//! Θ(m·2ᵏ·D) time and space: linear in the output, m·2ᵏ polygons (one round is linear in
//! the polygon); the count is checked against [`MAX_SUBDIVIDED_PIECES`] first.
//!
//! [`MAX_SUBDIVIDED_PIECES`]: crate::limits::MAX_SUBDIVIDED_PIECES

use super::BetaSpline;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::limits::SUBDIVIDED_PIECES;
use crate::spline::scalar::{Point, Scalar};
use crate::Result;

/// Recursive subdivision, declared.
pub(crate) const SUBDIVIDE: Declaration = Declaration {
    problem: "beta-spline",
    name: "subdivide",
    function: "spline::BetaSpline::subdivide",
    file: "src/spline/beta/subdivide.rs",
    summary: "k rounds of S_L and S_R on every segment's polygon: m·2ᵏ polygons of four points",
    time: "Θ(m·2ᵏ·D)",
    space: "Θ(m·2ᵏ·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 32·m·(2ᵏ − 1) point combinations besides the matrices' 256",
    source: "[CCKS, §2–3]",
    claims: &[on(
        "random-control",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BetaSpline<S, D> {
    /// The control polygons after `rounds` rounds of subdivision at `c`. See
    /// [`BetaSpline::subdivide_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"c"` unless
    /// 0 < c < 1; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if m·2ᵏ exceeds
    /// [`MAX_SUBDIVIDED_PIECES`](crate::limits::MAX_SUBDIVIDED_PIECES).
    ///
    /// # Complexity
    ///
    /// Θ(m·2ᵏ·D) time, Θ(m·2ᵏ·D) space.
    ///
    /// ```
    /// use compgeo::spline::{BetaParameters, BetaSpline, Point};
    ///
    /// let p = BetaParameters::new(1.0, 5.0)?;
    /// let c = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)];
    /// let s = BetaSpline::new(p, c.map(|(x, y)| Point::new([x, y])).to_vec())?;
    /// let pieces = s.subdivide(&0.5, 3)?;
    /// assert_eq!(pieces.len(), 8); // one segment, 2³ pieces, as in the seed's Figure 2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn subdivide(&self, c: &S, rounds: u32) -> Result<Vec<[Point<S, D>; 4]>> {
        self.subdivide_with(c, rounds, &mut NoCount)
    }

    /// The control polygons after `rounds` rounds at `c`, counting the arithmetic.
    ///
    /// Idea: compute S_L and S_R once; start from the m segment polygons; each round maps
    /// every polygon P to S_L·P, S_R·P in place of it [CCKS, §2, eq. (3)].
    ///
    /// Follows [CCKS, §2–3].
    ///
    /// # Errors
    ///
    /// As [`BetaSpline::subdivide`].
    ///
    /// # Complexity
    ///
    /// Θ(m·2ᵏ·D) time, Θ(m·2ᵏ·D) space.
    ///
    /// # Counts
    ///
    /// Exactly 256 + 32·m·(2ᵏ − 1) [`arithmetic_operation`](Counter::arithmetic_operation)s:
    /// the matrices' four products, then 32 point combinations per polygon split (m·(2ᵏ − 1)
    /// splits in all).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BetaParameters, BetaSpline, Point};
    ///
    /// let p = BetaParameters::new(1.0, 0.0)?;
    /// let s = BetaSpline::new(p, (0..7).map(|i| Point::new([i as f64])).collect())?;
    /// let mut c = Counts::default();
    /// let pieces = s.subdivide_with(&0.5, 2, &mut c)?;
    /// assert_eq!(pieces.len(), 4 * 4);
    /// assert_eq!(c.arithmetic_operations, 256 + 32 * 4 * 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn subdivide_with<C: Counter>(
        &self,
        c: &S,
        rounds: u32,
        counter: &mut C,
    ) -> Result<Vec<[Point<S, D>; 4]>> {
        let m = self.segments();
        let pieces = (m as u128)
            .checked_shl(rounds)
            .filter(|p| p >> rounds == m as u128);
        SUBDIVIDED_PIECES.check(pieces.unwrap_or(u128::MAX))?;
        let matrices = self.parameters().subdivision_matrices_with(c, counter)?;
        let mut polygons: Vec<[Point<S, D>; 4]> =
            (0..m).map(|i| self.segment(i)).collect::<Result<_>>()?;
        for _ in 0..rounds {
            let mut next = Vec::with_capacity(polygons.len() * 2);
            for p in &polygons {
                let (l, r) = matrices.split_with(p, counter);
                next.push(l);
                next.push(r);
            }
            polygons = next;
        }
        Ok(polygons)
    }
}
