//! All derivatives at a parameter by the extended de Boor algorithm: the tetrahedral scheme of
//! [PPB, §5.9].
//!
//! The problem: s(u), s′(u), …, s⁽ᵏ⁾(u) of the piece of the curve at u, at once. The idea: on
//! the span μ of u the piece is a polynomial s_μ of degree d with a polar form, and the points
//! and vectors c_{r,i,k} = s_μ[ε^r, t_{μ−d+i+1}, …, t_{μ+i−r−k}, u^k] (ε the direction 1 − 0,
//! r + k ≤ i ≤ d) fill a tetrahedron whose left edge holds the control points c_{μ−d+i} and
//! whose opposite edge holds the derivatives, s_μ⁽ʳ⁾(u) = d!/(d − r)! · c_{r,d,d−r}
//! [PPB, §5.9]. Two of its faces are enough:
//!
//! - the *back* face (r = 0) is de Boor's scheme at u: level k of the de Boor net is
//!   c_{0,i,k}, i = k, …, d;
//! - the *left* face rule, c_{r+1,i,k} = (c_{r,i,k} − c_{r,i−1,k})/(t_{μ−d+i+d−r−k} − t_{μ−d+i}),
//!   applied r times to level d − r of the net gives c_{r,d,d−r}.
//!
//! Every denominator of both rules is the width of an interval that contains the non-empty
//! span [t_μ, t_{μ+1}], so it is never zero: this is why the derivatives are taken from the
//! back face by differences and not from the bottom face by [PPB, §5.9, eq. (2)], which
//! divides by zero at the knots (its Obs. 9). The factor d!/(d − r)! is folded into the
//! differences, one factor d − r + s at step s, so no factorial is formed.
//!
//! With the derivatives, the Taylor expansion s_μ(u + h) = Σ_r s_μ⁽ʳ⁾(u) hʳ/r! is the
//! monomial form of the piece about u [PPB, §5.9, Obs. 7] ([PPB, §5.12, Ex. 7] asks for it).
//!
//! # Complexity
//!
//! Θ((d² + K³)D) time for the orders 0, …, k, K = min(k, d): d(d + 1)/2 affine combinations
//! for the de Boor net and r(r + 1)/2 differences for order r; O((d + k)D) space.
//!
//! Invariants the tests check (exactly on rationals): the derivatives equal those of the basis
//! ([`KnotVector::basis_derivatives`](super::KnotVector::basis_derivatives)) at every
//! parameter, knots included, and the Taylor expansion at u reproduces the curve on the
//! whole span of u.

use super::basis::quotient;
use super::de_boor::de_boor_level;
use super::BSpline;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::{Error, Result};

/// All derivatives at a parameter by the extended de Boor algorithm, declared.
pub(crate) const DERIVATIVES: Declaration = Declaration {
    problem: "bspline",
    name: "derivatives",
    function: "spline::BSpline::derivatives",
    file: "src/spline/bspline/derivatives.rs",
    summary: "s(u), s′(u), …, s⁽ᵏ⁾(u) from the de Boor net by the tetrahedral scheme",
    time: "Θ((d² + K³)D), K = min(k, d)",
    space: "O((d + k)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly d(d + 1)/2 affine combinations and K(K + 1)(K + 2)/6 differences",
    source: "[PPB, §5.9]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The derivatives s(u), s′(u), …, s⁽ᵏ⁾(u) of the piece at `u` (k + 1 points; orders
    /// above d are zero). See [`BSpline::derivatives_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN, infinite or outside the domain
    /// [t_d, t_n]; [`Error::LimitExceeded`] if `k` exceeds
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE); [`Error::Overflow`] if, with `f64`, a
    /// derivative is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((d² + K³)D), K = min(k, d), in time and O((d + k)D) in space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // [PPB, §5.12, Ex. 7]: c = 4, 7, −2, 1 on the knots 0, 1, …, 7, at u = 3.
    /// let t = KnotVector::new(3, (0..=7).map(f64::from).collect())?;
    /// let s = BSpline::new([4.0, 7.0, -2.0, 1.0].map(|c| Point::new([c])).to_vec(), t)?;
    /// let d = s.derivatives(&3.0, 4)?;
    /// // s, s′, s″, s‴ and s⁗ (zero): s(3 + h) = 5 − 3h − 6h² + 4h³ on [3, 4].
    /// for (got, want) in d.iter().zip([5.0, -3.0, -12.0, 24.0, 0.0]) {
    ///     assert!((got[0] - want).abs() < 1e-14, "{got:?} vs {want}");
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn derivatives(&self, u: &S, k: usize) -> Result<Vec<Point<S, D>>> {
        self.derivatives_with(u, k, &mut NoCount)
    }

    /// The derivatives s(u), s′(u), …, s⁽ᵏ⁾(u) of the piece at `u`, counting the operations
    /// of the extended de Boor algorithm.
    ///
    /// Idea: de Boor's scheme at u on the span μ of u (all d levels, also at a knot); after
    /// level d − r, r differences of its r + 1 points, each divided by the width of a
    /// support that contains the span and multiplied by the next factor of d!/(d − r)!, give
    /// s⁽ʳ⁾(u) [PPB, §5.9]. The piece is the one [`KnotVector::span`](super::KnotVector::span)
    /// picks: right derivatives at an interior knot, left ones at the end of the domain (as
    /// [`CurveDerivative::derivative_at`](crate::spline::CurveDerivative::derivative_at)).
    ///
    /// Follows [PPB, §5.9] (the tetrahedral scheme, after Sablonnière).
    ///
    /// # Errors
    ///
    /// As [`BSpline::derivatives`].
    ///
    /// # Complexity
    ///
    /// Θ((d² + K³)D), K = min(k, d), in time and O((d + k)D) in space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// the de Boor net (exactly d(d + 1)/2, none skipped at a knot) and per difference
    /// (r(r + 1)/2 for order r: K(K + 1)(K + 2)/6 in all), plus the span search's
    /// [`comparison`](Counter::comparison)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 6, 0.0, 1.0)?;
    /// let s = BSpline::new((0..6).map(|i| Point::new([i as f64, (i * i) as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let d = s.derivatives_with(&0.25, 3, &mut c)?;
    /// assert_eq!(d.len(), 4);
    /// assert_eq!(c.arithmetic_operations, 6 + 10); // 3·4/2 + 3·4·5/6
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn derivatives_with<C: Counter>(
        &self,
        u: &S,
        k: usize,
        counter: &mut C,
    ) -> Result<Vec<Point<S, D>>> {
        crate::limits::DEGREE.check(k as u128)?;
        let span = self.knots().span_with(u, counter)?;
        let d = self.degree();
        let t = self.knots().knots();
        let orders = k.min(d);
        let mut out = vec![Point::zero(); k + 1];
        let mut q = self.control()[span - d..=span].to_vec();
        let mut differences = Vec::with_capacity(orders + 1);
        for level in 0..=d {
            if level > 0 {
                de_boor_level(t, d, span, level, u, &mut q, counter);
            }
            let r = d - level;
            if r == 0 || r > orders {
                continue;
            }
            // Level d − r holds c_{0,i,d−r}, i = d − r, …, d (window indices).
            differences.clear();
            differences.extend_from_slice(&q[level..]);
            for s in 1..=r {
                let factor = S::from_i64((level + s) as i64); // d − r + s
                for j in (s..=r).rev() {
                    let i = span - d + level + j; // the window index level + j, as a knot index
                    let (lo, hi) = (&t[i], &t[i + r - s + 1]);
                    let diff = differences[j].clone() - &differences[j - 1];
                    differences[j] = Point::new(std::array::from_fn(|c| {
                        quotient(factor.clone() * &diff[c], lo, hi)
                    }));
                    counter.arithmetic_operation();
                }
            }
            out[r] = differences[r].clone();
        }
        out[0] = q[d].clone();
        if out.iter().all(Point::is_finite) {
            Ok(out)
        } else {
            Err(Error::Overflow {
                what: "B-spline derivatives",
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;
    use crate::spline::{CurveDerivative, KnotVector};

    fn line() -> BSpline<f64, 1> {
        // Degree 1 with a jump at 1: 0 → 1 on [0, 1], 5 → 6 on [1, 2].
        let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).unwrap();
        BSpline::new([0.0, 1.0, 5.0, 6.0].map(|x| Point::new([x])).to_vec(), t).unwrap()
    }

    #[test]
    fn a_jump_takes_the_right_piece_and_the_end_the_left_one() {
        let s = line();
        let p = |x: f64| Point::new([x]);
        assert_eq!(s.derivatives(&1.0, 2).unwrap(), [p(5.0), p(1.0), p(0.0)]);
        assert_eq!(s.derivatives(&2.0, 1).unwrap(), [p(6.0), p(1.0)]);
        assert_eq!(s.derivatives(&0.5, 0).unwrap(), [p(0.5)]);
        assert!(matches!(
            s.derivatives(&2.5, 1),
            Err(Error::InvalidParameter { name: "u", .. })
        ));
    }

    #[test]
    fn knots_cost_the_full_scheme_and_agree_with_the_basis() {
        let t = KnotVector::new(
            3,
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0, 3.0],
        )
        .unwrap();
        let c = [0.0, 2.0, -1.0, 4.0, 3.0, 5.0, 1.0].map(|x| Point::new([x, x * x]));
        let s = BSpline::new(c.to_vec(), t).unwrap();
        for u in [0.0, 1.0, 2.0, 2.5, 3.0] {
            let mut counts = Counts::default();
            let d = s.derivatives_with(&u, 5, &mut counts).unwrap();
            assert_eq!(counts.arithmetic_operations, 6 + 10, "{u}");
            for (r, got) in d.iter().enumerate() {
                let want = s.derivative_at(&u, r).unwrap();
                for j in 0..2 {
                    let tol = 1e-12 * want[j].abs().max(1.0);
                    assert!((got[j] - want[j]).abs() <= tol, "u {u}, order {r}");
                }
            }
        }
    }

    #[test]
    fn subnormal_spans_overflow_as_an_error_and_big_orders_are_refused() {
        let tiny = f64::from_bits(1);
        let t = KnotVector::new(1, vec![0.0, 0.0, tiny, 1.0, 1.0]).unwrap();
        let s = BSpline::new([0.0, 1.0, 2.0].map(|x| Point::new([x])).to_vec(), t).unwrap();
        assert!(matches!(
            s.derivatives(&0.0, 1),
            Err(Error::Overflow { .. })
        ));
        assert!(matches!(
            s.derivatives(&0.5, usize::MAX),
            Err(Error::LimitExceeded { .. })
        ));
    }
}
