//! Integration of B-spline curves: the antiderivative as a B-spline of one degree more, and
//! the integral over the domain.
//!
//! The problem: S(u) = ∫_{t_d}^u s for s = Σ cᵢ Nᵢ of degree d on t₀, …, t_{n+d}. The idea:
//! the inverse of the derivative formula [PPB, §5.6, eq. (1)]. On the knots
//! τ = t₀, t₀, t₁, …, t_{n+d}, t_{n+d} (each end knot once more) the spline Σ Cᵢ Nᵢ^{d+1} of
//! degree d + 1 with n + 1 control points has the derivative
//! Σ (d + 1)(Cᵢ − Cᵢ₋₁)/(τ_{i+d+1} − τᵢ) N_{i−1}^d on t₀, …, t_{n+d}, so the sums
//! Cᵢ = Cᵢ₋₁ + c_{i−1}(t_{i+d} − t_{i−1})/(d + 1) give s as its derivative; the constant is
//! chosen so that S(t_d) = 0 (subtracting a constant from every coefficient subtracts it from
//! the spline, by the partition of unity). The new vector repeats an end knot at most d + 2
//! times, which degree d + 1 allows, and has the same domain [t_d, t_n].
//!
//! On a clamped vector this gives [PPB, §5.12, Ex. 2]: ∫ Nᵢ = (t_{i+d+1} − tᵢ)/(d + 1), so
//! ∫_{t_d}^{t_n} s = Σ cᵢ (t_{i+d+1} − tᵢ)/(d + 1) ([`BSpline::definite_integral`]).
//!
//! # Complexity
//!
//! Θ((n + d)D) time and space.
//!
//! Invariants the tests check (exactly on rationals): the antiderivative's derivative is the
//! curve, it is zero at t_d, and its value at t_n is the sum of the integrals of the Bézier
//! pieces (an independent oracle).

use super::basis::product_quotient;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::Result;

/// The antiderivative of a B-spline, declared.
pub(crate) const INTEGRAL: Declaration = Declaration {
    problem: "bspline",
    name: "integral",
    function: "spline::BSpline::integral",
    file: "src/spline/bspline/integral.rs",
    summary: "the antiderivative vanishing at t_d as a B-spline of degree d + 1 on the knots with each end once more",
    time: "Θ((n + d)D)",
    space: "Θ((n + d)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n running sums; where t₀ < t_d also de Boor's evaluation at t_d and n + 1 shifts",
    source: "[PPB, §5.6, §5.12 Ex. 2]",
    claims: &[on(
        "random-control",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The antiderivative S(u) = ∫_{t_d}^u s, a B-spline of degree d + 1 on the same domain.
    /// See [`BSpline::integral_with`].
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`](crate::Error::Overflow) if, with `f64`, a control point of the antiderivative is beyond
    /// the double range; [`Error::LimitExceeded`](crate::Error::LimitExceeded) for a curve already of degree
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
    ///
    /// # Complexity
    ///
    /// Θ((n + d)D) time and space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, CurveDerivative, KnotVector, Point};
    ///
    /// // s(u) = 2u on [0, 2] as a linear spline with a knot at 1.
    /// let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0])?;
    /// let s = BSpline::new([0.0, 2.0, 4.0].map(|c| Point::new([c])).to_vec(), t)?;
    /// let big_s = s.integral()?; // u²
    /// assert_eq!(big_s.degree(), 2);
    /// assert_eq!(big_s.eval(&1.5)?, Point::new([2.25]));
    /// assert_eq!(big_s.derivative_curve()?.eval(&0.5)?, s.eval(&0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn integral(&self) -> Result<Self> {
        self.integral_with(&mut NoCount)
    }

    /// The antiderivative S(u) = ∫_{t_d}^u s, counting its point operations.
    ///
    /// Idea: on the knots t₀, t₀, t₁, …, t_{n+d}, t_{n+d}, the n + 1 running sums
    /// C₀ = 0, Cᵢ = Cᵢ₋₁ + c_{i−1}(t_{i+d} − t_{i−1})/(d + 1), each then less the value of
    /// that spline at t_d (module docs). Where the start is clamped (t₀ = t_d) the value at
    /// t_d is C₀ = 0 and nothing is shifted.
    ///
    /// Follows [PPB, §5.6, eq. (1)] read backwards and [PPB, §5.12, Ex. 2].
    ///
    /// # Errors
    ///
    /// As [`BSpline::integral`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d)D) time and space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per running sum (n), and
    /// where t₀ < t_d the evaluation at t_d (as [`BSpline::de_boor_with`] counts it) and one
    /// per shifted coefficient (n + 1).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 10, 0.0, 1.0)?;
    /// let s = BSpline::new((0..10).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let big_s = s.integral_with(&mut c)?;
    /// assert_eq!((big_s.control().len(), c.arithmetic_operations), (11, 10));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn integral_with<C: Counter>(&self, counter: &mut C) -> Result<Self> {
        let d = self.degree();
        crate::limits::DEGREE.check(d as u128 + 1)?;
        let t = self.knots().knots();
        let n = self.control().len();
        let order = S::from_i64(d as i64 + 1);
        let mut knots = Vec::with_capacity(t.len() + 2);
        knots.push(t[0].clone());
        knots.extend_from_slice(t);
        knots.push(t[t.len() - 1].clone());
        let mut sums = Vec::with_capacity(n + 1);
        sums.push(Point::zero());
        for (i, c) in self.control().iter().enumerate() {
            // ∫ N_i = (t_{i+d+1} − tᵢ)/(d + 1); halves first where the width overflows.
            let (lo, hi) = (&t[i], &t[i + d + 1]);
            // c·width/(d + 1) rounded once: width/(d + 1) alone underflows for subnormal widths.
            let width = hi.clone() - lo;
            let step = if width.is_finite() {
                Point::new(std::array::from_fn(|j| {
                    product_quotient(&c[j], &width, &order)
                }))
            } else {
                let half = S::from_ratio(1, 2);
                let w = hi.clone() * &half - &(lo.clone() * &half);
                Point::new(std::array::from_fn(|j| product_quotient(&c[j], &w, &order)))
                    * S::from_i64(2)
            };
            let next = sums[i].clone() + &step;
            counter.arithmetic_operation();
            sums.push(next);
        }
        let knots = KnotVector::new(d + 1, knots)?;
        let mut big_s = BSpline::derived(sums, knots, "B-spline integral")?;
        if t[0] != t[d] {
            // An unclamped start: S(t_d) = Σ Cᵢ Nᵢ^{d+1}(t_d) need not be C₀.
            let start = big_s.knots().bounds().0.clone();
            let at_start = big_s.de_boor_with(&start, counter)?;
            let shifted: Vec<Point<S, D>> = big_s
                .control()
                .iter()
                .map(|c| {
                    counter.arithmetic_operation();
                    c.clone() - &at_start
                })
                .collect();
            big_s = BSpline::derived(shifted, big_s.knots().clone(), "B-spline integral")?;
        }
        Ok(big_s)
    }

    /// ∫_{t_d}^{t_n} s(u) du, the antiderivative's value at the end of the domain. On a
    /// clamped vector it is Σ cᵢ (t_{i+d+1} − tᵢ)/(d + 1) [PPB, §5.12, Ex. 2].
    ///
    /// # Errors
    ///
    /// As [`BSpline::integral`].
    ///
    /// # Complexity
    ///
    /// Θ((n + d)D) time and space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // s = 6N₂ on the uniform knots 0, 1, …, 6, domain [2, 4]: N₂ has integral 1 over its
    /// // support [2, 5], of which 1/6 + 2/3 lies on the domain.
    /// let t = KnotVector::new(2, (0..=6).map(f64::from).collect())?;
    /// let s = BSpline::new([0.0, 0.0, 6.0, 0.0].map(|c| Point::new([c])).to_vec(), t)?;
    /// assert_eq!(s.definite_integral()?, Point::new([5.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn definite_integral(&self) -> Result<Point<S, D>> {
        let big_s = self.integral()?;
        let end = big_s.knots().bounds().1.clone();
        big_s.de_boor(&end)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    fn constant(value: f64, lo: f64, hi: f64) -> BSpline<f64, 1> {
        let t = KnotVector::new(1, vec![lo, lo, hi, hi]).unwrap();
        BSpline::new(vec![Point::new([value]); 2], t).unwrap()
    }

    #[test]
    fn widths_beyond_the_double_range_are_halved_first() {
        let m = f64::MAX;
        let s = constant(1e-300, -m, m);
        let area = 1e-300 * m * 2.0;
        let got = s.definite_integral().unwrap()[0];
        assert!((got - area).abs() <= 1e-15 * area, "{got} vs {area}");
        assert!(matches!(
            constant(1.0, -m, m).integral(),
            Err(Error::Overflow { .. })
        ));
    }

    #[test]
    fn an_unclamped_start_is_shifted_to_zero() {
        // The uniform linear spline on 0, 1, 2, 3 with c = 1, 1: s = 1 on the domain [1, 2].
        let t = KnotVector::new(1, vec![0.0, 1.0, 2.0, 3.0]).unwrap();
        let s = BSpline::new(vec![Point::new([1.0]); 2], t).unwrap();
        let big_s = s.integral().unwrap();
        assert_eq!(big_s.knots().knots(), [0.0, 0.0, 1.0, 2.0, 3.0, 3.0]);
        assert_eq!(big_s.de_boor(&1.0).unwrap(), Point::new([0.0]));
        assert_eq!(big_s.de_boor(&1.5).unwrap(), Point::new([0.5]));
        assert_eq!(s.definite_integral().unwrap(), Point::new([1.0]));
    }
}
