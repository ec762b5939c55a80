//! The blossom (polar form) of a B-spline curve's polynomial pieces, by the extended de Boor
//! algorithm.
//!
//! The problem: on each non-empty span [t_μ, t_{μ+1}) the curve is a polynomial s_μ of degree
//! d, and s_μ has a unique polar form s_μ[u₁, …, u_d]: symmetric, affine in each argument, and
//! equal to s_μ(u) on the diagonal u₁ = … = u_d = u [PPB, §3.1, §5.5]. The idea: de Boor's
//! scheme on c_{μ−d}, …, c_μ with a different argument at each level,
//! c_i^k = ((t_{i+d+1−k} − u_k) c_{i−1}^{k−1} + (u_k − tᵢ) c_i^{k−1})/(t_{i+d+1−k} − tᵢ),
//! computes s_μ[u₁, …, u_d] [PPB, §5.5, Obs. 5], [SPL, §6, eq. (17)]. It is well defined for
//! any real arguments: every denominator is the width of a support that contains the
//! non-empty span, so it is never zero.
//!
//! The fundamental theorem [PPB, §5.5] reads the control points off the polar forms at
//! consecutive knots: c_i = s_μ[t_{i+1}, …, t_{i+d}] for every non-empty span μ = i, …, i + d
//! (PPB's aᵢ are this crate's tᵢ, [module](super)). The polar form belongs to one piece:
//! two pieces have different polar forms (they agree on the knots they share only), so
//! [`BSpline::blossom_in_span`] takes the span, and [`BSpline::blossom`] picks the piece
//! from the arguments (the span of their mean, see there).
//!
//! [PPB, §5.9]'s tetrahedral scheme is the same recursion with some arguments replaced by
//! the direction ε = 1 − 0: its derivative form is [`BSpline::derivatives`].
//!
//! # Complexity
//!
//! Θ(d²D) per value: exactly d(d + 1)/2 affine combinations; O(dD) auxiliary space.
//!
//! Invariants the tests check (exactly on rationals): the blossom is symmetric, affine in
//! each argument, equal to the curve on its diagonal, and gives the control points at
//! consecutive knots for every span of the fundamental theorem.

use super::BSpline;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bspline::basis::affine;
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// The blossom by the extended de Boor algorithm, declared.
pub(crate) const BLOSSOM: Declaration = Declaration {
    problem: "bspline",
    name: "blossom",
    function: "spline::BSpline::blossom",
    file: "src/spline/bspline/blossom.rs",
    summary: "the polar form of a polynomial piece by de Boor's scheme with one argument per level",
    time: "Θ(d²D)",
    space: "O(dD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly d(d + 1)/2 affine combinations per value",
    source: "[PPB, §5.5]",
    claims: &[on(
        "random-degree",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The blossom s_μ[u₁, …, u_d] of the piece the arguments lie on. See
    /// [`BSpline::blossom_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"blossom arguments"` if there are not exactly d
    /// arguments, named `"blossom argument"` if one is NaN or infinite;
    /// [`Error::Overflow`] if, with `f64`, the value (arguments far outside the knots
    /// extrapolate) is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time after the O(log(n − d)) span search, O(dD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// // s(u) = u² on [0, 2] as a clamped quadratic with a knot at 1: its blossom is u₁u₂.
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let c = [0.0, 0.0, 2.0, 4.0].map(|x| Point::new([x])).to_vec();
    /// let s = BSpline::new(c, t)?;
    /// assert_eq!(s.blossom(&[0.5, 1.5])?, Point::new([0.75]));
    /// assert_eq!(s.blossom(&[1.0, 2.0])?, s.control()[2]); // c₂ = s[t₃, t₄]
    /// assert_eq!(s.blossom(&[1.5, 1.5])?, s.eval(&1.5)?);
    /// assert!(s.blossom(&[1.0]).is_err()); // degree 2 takes two arguments
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom(&self, args: &[S]) -> Result<Point<S, D>> {
        self.blossom_with(args, &mut NoCount)
    }

    /// The blossom s_μ[u₁, …, u_d] of the piece the arguments lie on, counting its affine
    /// combinations.
    ///
    /// The piece: the span μ of the arguments' mean (u₁ + … + u_d)/d, clamped to the domain
    /// [t_d, t_n] (so arguments before the domain use the first piece, after it the last),
    /// with the conventions of [`KnotVector::span`](super::KnotVector::span): right-continuous
    /// at an interior knot, the last non-empty span at t_n. The mean is symmetric in the
    /// arguments (for `f64` it is summed in sorted order, so a permutation of the arguments
    /// picks the same piece), on the diagonal it is u itself (so s[u, …, u] = s(u) on the
    /// domain), and for the knots t_{i+1}, …, t_{i+d} it is the Greville abscissa ξᵢ, which
    /// lies on one of the spans i, …, i + d whose polar forms all give cᵢ (when the knots are
    /// not all equal it lies strictly before t_{i+d}, in a span i + 1, …, i + d − 1; when they
    /// are, it is the knot, on the span i + d unless the knot has multiplicity d + 1, a jump,
    /// where cᵢ is the left piece's end point and the right piece is taken). The mean is
    /// only a rule for picking the piece: the blossom is affine in each argument only while
    /// the piece stays the same; for one fixed piece use [`BSpline::blossom_in_span_with`].
    /// With degree 0 there are no arguments and the first non-empty span is taken.
    ///
    /// Then the extended de Boor algorithm on c_{μ−d}, …, c_μ, argument u_k at level k
    /// ([`BSpline::blossom_in_span_with`]).
    ///
    /// Follows [PPB, §5.5] (the fundamental theorem and Obs. 5) and [SPL, §6–7].
    ///
    /// # Errors
    ///
    /// As [`BSpline::blossom`].
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time after the O(log(n − d)) span search: exactly d(d + 1)/2 affine
    /// combinations; O(dD) auxiliary space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination and
    /// the span search's [`comparison`](Counter::comparison)s; the mean is not counted.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::uniform(3, 7, 0.0, 1.0)?;
    /// let s = BSpline::new((0..7).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// s.blossom_with(&[0.1, 0.4, 2.0], &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6); // 3·4/2
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom_with<C: Counter>(&self, args: &[S], counter: &mut C) -> Result<Point<S, D>> {
        self.check_arguments(args)?;
        let d = self.degree();
        let knots = self.knots();
        let (start, end) = knots.bounds();
        let span = if d == 0 {
            knots.span_in_domain(start, counter)
        } else {
            let mut sorted: Vec<&S> = args.iter().collect();
            sorted.sort_by(|a, b| a.partial_cmp(b).expect("finite arguments"));
            // Σ uᵢ/d: it cannot overflow with f64, and exactly it is the mean.
            let degree = S::from_i64(d as i64);
            let mut mean = S::zero();
            for u in sorted {
                mean += u.clone() / &degree;
            }
            let at = if mean < *start {
                start
            } else if mean > *end {
                end
            } else {
                &mean
            };
            counter.comparison();
            counter.comparison();
            knots.span_in_domain(at, counter)
        };
        self.blossom_unchecked(span, args, counter)
    }

    /// The blossom s_μ[u₁, …, u_d] of the polynomial piece on the span μ = `span`
    /// (t_μ < t_{μ+1}, d ≤ μ < n). See [`BSpline::blossom_in_span_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"span"` if `span` is not a non-empty span of the
    /// domain; otherwise as [`BSpline::blossom`].
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time, O(dD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // The uniform quadratic on 0, 1, …, 6 with c = 0, 1, 0, 1: the fundamental theorem
    /// // gives c₁ = s₂[t₂, t₃] = s₃[t₂, t₃], from the two pieces that depend on it.
    /// let t = KnotVector::new(2, (0..=6).map(f64::from).collect())?;
    /// let s = BSpline::new([0.0, 1.0, 0.0, 1.0].map(|x| Point::new([x])).to_vec(), t)?;
    /// assert_eq!(s.blossom_in_span(2, &[2.0, 3.0])?, Point::new([1.0]));
    /// assert_eq!(s.blossom_in_span(3, &[2.0, 3.0])?, Point::new([1.0]));
    /// // Elsewhere the two pieces' polar forms differ.
    /// assert_ne!(s.blossom_in_span(2, &[0.0, 0.0])?, s.blossom_in_span(3, &[0.0, 0.0])?);
    /// assert!(s.blossom_in_span(4, &[2.0, 3.0]).is_err()); // spans 2 and 3 only
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom_in_span(&self, span: usize, args: &[S]) -> Result<Point<S, D>> {
        self.blossom_in_span_with(span, args, &mut NoCount)
    }

    /// The blossom s_μ[u₁, …, u_d] of the piece on the span μ = `span`, counting its affine
    /// combinations.
    ///
    /// Idea: copy c_{μ−d}, …, c_μ and run the d levels of de Boor's scheme with the argument
    /// u_k at level k: c_i^k = (1 − α) c_{i−1}^{k−1} + α c_i^{k−1},
    /// α = (u_k − tᵢ)/(t_{i+d+1−k} − tᵢ), i = μ − d + k, …, μ [SPL, §6, eq. (17)]; the
    /// weights are ratios of knot distances as in [`BSpline::de_boor_with`], but outside
    /// [0, 1] when an argument is outside the support (the polar form extends the piece to
    /// all real arguments). The arguments need not be sorted, nor lie in the span or the
    /// domain. With `f64`, a weight that overflows (an argument far beyond a support of
    /// subnormal width) is not multiplied: that coordinate is recomputed as
    /// a + (u − tᵢ)(b − a)/(t_j − tᵢ) on mantissas and exponents, so a zero stays zero
    /// instead of ∞·0 = NaN, and only a value truly beyond the range is an overflow. Unlike evaluation, no level is skipped when an argument is a knot, so the
    /// count is always d(d + 1)/2.
    ///
    /// Follows [PPB, §5.5, Obs. 5] and [SPL, §6–7].
    ///
    /// # Errors
    ///
    /// As [`BSpline::blossom_in_span`].
    ///
    /// # Complexity
    ///
    /// Θ(d²D) time: exactly d(d + 1)/2 affine combinations; O(dD) auxiliary space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?; // a Bézier parabola
    /// let c = vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])];
    /// let s = BSpline::new(c, t)?;
    /// let mut k = Counts::default();
    /// // The Bézier points are blossom values at 0s and 1s.
    /// assert_eq!(s.blossom_in_span_with(2, &[0.0, 1.0], &mut k)?, Point::new([1.0, 2.0]));
    /// assert_eq!(k.arithmetic_operations, 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn blossom_in_span_with<C: Counter>(
        &self,
        span: usize,
        args: &[S],
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        let (d, n) = (self.degree(), self.control().len());
        let t = self.knots().knots();
        if span < d || span >= n || t[span] == t[span + 1] {
            return Err(Error::InvalidParameter {
                name: "span",
                reason: if span < d || span >= n {
                    format!("the spans of the domain are {d}..{n} (degree {d}, {n} control points), got {span}")
                } else {
                    format!(
                        "span {span} is empty (t_{span} = t_{} = {})",
                        span + 1,
                        t[span].to_f64()
                    )
                },
            });
        }
        self.check_arguments(args)?;
        self.blossom_unchecked(span, args, counter)
    }

    /// Checks that there are d arguments, all finite.
    fn check_arguments(&self, args: &[S]) -> Result<()> {
        let d = self.degree();
        if args.len() != d {
            return Err(Error::InvalidParameter {
                name: "blossom arguments",
                reason: format!(
                    "a curve of degree {d} needs {d} arguments, got {}",
                    args.len()
                ),
            });
        }
        for u in args {
            validate_parameter(u, "blossom argument")?;
        }
        Ok(())
    }

    /// The extended de Boor scheme on a valid non-empty span with d finite arguments.
    fn blossom_unchecked<C: Counter>(
        &self,
        span: usize,
        args: &[S],
        counter: &mut C,
    ) -> Result<Point<S, D>> {
        let d = self.degree();
        let t = self.knots().knots();
        let mut q = self.control()[span - d..=span].to_vec();
        for (k, u) in (1..=d).zip(args) {
            // Going down, each combination reads level k − 1 (as de_boor_level does).
            for j in (k..=d).rev() {
                let i = span - d + j;
                q[j] = affine(&q[j - 1], &t[i], u, &t[i + d + 1 - k], &q[j]);
                counter.arithmetic_operation();
            }
        }
        let p = q.pop().expect("d + 1 points");
        if p.is_finite() {
            Ok(p)
        } else {
            Err(Error::Overflow {
                what: "B-spline blossom",
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::KnotVector;

    #[test]
    fn degree_zero_has_the_empty_blossom() {
        let t = KnotVector::new(0, vec![0.0, 1.0, 2.0]).unwrap();
        let s = BSpline::new(vec![Point::new([3.0]), Point::new([4.0])], t).unwrap();
        assert_eq!(s.blossom(&[]).unwrap(), Point::new([3.0]));
        assert_eq!(s.blossom_in_span(1, &[]).unwrap(), Point::new([4.0]));
    }

    #[test]
    fn empty_and_outside_spans_are_refused() {
        let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).unwrap();
        let s = BSpline::new([0.0, 1.0, 5.0, 6.0].map(|x| Point::new([x])).to_vec(), t).unwrap();
        for span in [0, 2, 4, 9] {
            let e = s.blossom_in_span(span, &[0.5]).unwrap_err();
            assert!(
                matches!(e, Error::InvalidParameter { name: "span", .. }),
                "{e}"
            );
        }
        assert_eq!(s.blossom_in_span(1, &[1.0]).unwrap(), Point::new([1.0]));
        assert_eq!(s.blossom_in_span(3, &[1.0]).unwrap(), Point::new([5.0]));
        // The jump at 1 (multiplicity d + 1): the mean picks the right piece.
        assert_eq!(s.blossom(&[1.0]).unwrap(), Point::new([5.0]));
    }

    #[test]
    fn far_arguments_overflow_as_an_error() {
        let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1e-300, 1.0, 1.0, 1.0]).unwrap();
        let c = [0.0, 1e300, -1e300, 0.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        let e = s.blossom_in_span(2, &[1e300, 1e300]).unwrap_err();
        assert!(matches!(e, Error::Overflow { .. }), "{e}");
    }
}
