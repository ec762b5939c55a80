//! Greville abscissae and Marsden's identity: the B-spline coefficients of the polynomials
//! u and (y − u)^d, read off the polar forms at consecutive knots.
//!
//! The problem: write a polynomial of degree at most d as a spline Σ aᵢ Nᵢ on a given knot
//! vector. The idea: by the fundamental theorem [PPB, §5.5] the coefficient aᵢ is the polar
//! form of the polynomial at t_{i+1}, …, t_{i+d}. The polar form of u (of degree d) is the
//! mean (u₁ + … + u_d)/d, so u = Σ ξᵢ Nᵢ(u) with the **Greville abscissae**
//! ξᵢ = (t_{i+1} + … + t_{i+d})/d [PPB, §5.8], [SPL, §7, eq. (26)]; the polar form of
//! (y − u)^d is Π_j (y − u_j), so (y − u)^d = Σ ψᵢ(y) Nᵢ(u) with
//! ψᵢ(y) = (y − t_{i+1})⋯(y − t_{i+d}), **Marsden's identity** [PPB, §5.12, Ex. 4] (PPB
//! writes it as (u − a)^d = Σ (t_{i+1} − a)⋯(t_{i+d} − a) Nᵢ(u), the same identity times
//! (−1)^d). Both hold on the whole domain [t_d, t_n], on clamped and unclamped vectors.
//!
//! The consequence for curves, linear precision: the spline with control points ξᵢ is the
//! identity, and the graph (u, s(u)) of a spline function s = Σ cᵢ Nᵢ is the plane B-spline
//! curve with control points (ξᵢ, cᵢ) [PPB, §5.8, Obs. 6] ([`BSpline::graph`]).
//!
//! # Complexity
//!
//! Θ(nd) field operations for the n abscissae or the n coefficients ψᵢ(y), Θ(n) space.
//!
//! Invariants the tests check (exactly on rationals): the spline with coefficients ξᵢ is u
//! and the one with coefficients ψᵢ(y) is (y − u)^d at every parameter, and the graph curve
//! is (u, s(u)).

use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// The Greville abscissae, declared.
pub(crate) const GREVILLE: Declaration = Declaration {
    problem: "bspline",
    name: "greville",
    function: "spline::KnotVector::greville",
    file: "src/spline/bspline/greville.rs",
    summary: "the B-spline coefficients of the identity: means of d consecutive knots",
    time: "Θ(nd)",
    space: "Θ(n)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n·d: one per knot in a mean (n for degree 0)",
    source: "[PPB, §5.8]",
    claims: &[on(
        "random-control",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// Marsden's identity, declared.
pub(crate) const MARSDEN: Declaration = Declaration {
    problem: "bspline",
    name: "marsden",
    function: "spline::KnotVector::marsden",
    file: "src/spline/bspline/greville.rs",
    summary: "the B-spline coefficients of (y − u)^d: products of d knot distances",
    time: "Θ(nd)",
    space: "Θ(n)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n·d: one per factor of a product",
    source: "[PPB, §5.12, Ex. 4]",
    claims: &[on(
        "random-control",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar> KnotVector<S> {
    /// The Greville abscissae ξᵢ = (t_{i+1} + … + t_{i+d})/d, i = 0, …, n − 1: the
    /// coefficients with u = Σ ξᵢ Nᵢ(u) on the domain [PPB, §5.8], [SPL, §7, eq. (26)].
    ///
    /// Exact for rationals. For `f64` each is the sum of the quotients t_j/d (so it cannot
    /// overflow), kept within [t_{i+1}, t_{i+d}] where rounding would leave it; the
    /// abscissae then reproduce u up to rounding. With degree 0 there is no mean of zero
    /// knots and no spline of degree 0 reproduces u; this returns the midpoints
    /// (tᵢ + t_{i+1})/2 of the supports, a convention.
    ///
    /// Exactly they never decrease, and for a clamped vector ξ₀ = t_d and ξ_{n−1} = t_n (the
    /// identity starts and ends at the ends of the domain).
    ///
    /// # Complexity
    ///
    /// Θ(nd) time, Θ(n) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 3.0, 3.0, 3.0])?;
    /// let xi = t.greville();
    /// assert_eq!(xi, [0.0, 0.5, 2.0, 3.0]);
    /// // Linear precision: the spline with these coefficients is the identity.
    /// let s = BSpline::new(xi.into_iter().map(|x| Point::new([x])).collect(), t)?;
    /// assert_eq!(s.eval(&2.5)?, Point::new([2.5]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn greville(&self) -> Vec<S> {
        self.greville_with(&mut NoCount)
    }

    /// The Greville abscissae (see [`KnotVector::greville`]), counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per knot added into a mean:
    /// exactly n·d (n for degree 0, one midpoint each).
    ///
    /// # Complexity
    ///
    /// Θ(nd) time, Θ(n) space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::clamped_uniform(2, 5, 0.0, 3.0)?; // 0 0 0 1 2 3 3 3
    /// let mut c = Counts::default();
    /// assert_eq!(t.greville_with(&mut c), [0.0, 0.5, 1.5, 2.5, 3.0]);
    /// assert_eq!(c.arithmetic_operations, 5 * 2);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn greville_with<C: Counter>(&self, counter: &mut C) -> Vec<S> {
        let (d, n, t) = (self.degree(), self.control_points(), self.knots());
        if d == 0 {
            let half = S::from_ratio(1, 2);
            return (0..n)
                .map(|i| {
                    counter.arithmetic_operation();
                    t[i].clone() * &half + t[i + 1].clone() * &half
                })
                .collect();
        }
        let degree = S::from_i64(d as i64);
        (0..n)
            .map(|i| {
                let mut mean = S::zero();
                for k in &t[i + 1..=i + d] {
                    counter.arithmetic_operation();
                    mean += k.clone() / &degree;
                }
                // Exactly the mean lies in [t_{i+1}, t_{i+d}]; rounding must not leave it.
                if mean < t[i + 1] {
                    t[i + 1].clone()
                } else if mean > t[i + d] {
                    t[i + d].clone()
                } else {
                    mean
                }
            })
            .collect()
    }

    /// Marsden's identity: the coefficients ψᵢ(y) = (y − t_{i+1})⋯(y − t_{i+d}),
    /// i = 0, …, n − 1, with (y − u)^d = Σ ψᵢ(y) Nᵢ(u) for every u in the domain and every y
    /// [PPB, §5.12, Ex. 4], [PPB, §5.8]. With degree 0 every ψᵢ is 1 (the partition of
    /// unity).
    ///
    /// Exact for rationals; for `f64` each product is rounded d times.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"y"` if `y` is NaN or infinite;
    /// [`Error::Overflow`] if, with `f64`, a product is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(nd) time, Θ(n) space.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// // (y − u)² on 0 0 0 1 2 2 2 with y = 3: ψᵢ = (3 − t_{i+1})(3 − t_{i+2}).
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let psi = t.marsden(&3.0)?;
    /// assert_eq!(psi, [9.0, 6.0, 2.0, 1.0]);
    /// // At u = 1 only N₁ and N₂ are non-zero, both 1/2: (3 − 1)² = (6 + 2)/2.
    /// let b = t.basis(&1.0)?;
    /// let sum: f64 = b.values().iter().enumerate().map(|(k, n)| n * psi[b.first() + k]).sum();
    /// assert_eq!(sum, 4.0);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn marsden(&self, y: &S) -> Result<Vec<S>> {
        self.marsden_with(y, &mut NoCount)
    }

    /// Marsden's coefficients ψᵢ(y) (see [`KnotVector::marsden`]), counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per factor multiplied in:
    /// exactly n·d.
    ///
    /// # Errors
    ///
    /// As [`KnotVector::marsden`].
    ///
    /// # Complexity
    ///
    /// Θ(nd) time, Θ(n) space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let mut c = Counts::default();
    /// assert_eq!(t.marsden_with(&3.0, &mut c)?, [9.0, 6.0, 2.0, 1.0]);
    /// assert_eq!(c.arithmetic_operations, 4 * 2);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn marsden_with<C: Counter>(&self, y: &S, counter: &mut C) -> Result<Vec<S>> {
        validate_parameter(y, "y")?;
        let (d, n, t) = (self.degree(), self.control_points(), self.knots());
        let psi: Vec<S> = (0..n)
            .map(|i| {
                let mut product = S::one();
                for k in &t[i + 1..=i + d] {
                    counter.arithmetic_operation();
                    product = product * (y.clone() - k);
                }
                product
            })
            .collect();
        if psi.iter().all(Scalar::is_finite) {
            Ok(psi)
        } else {
            Err(Error::Overflow {
                what: "Marsden coefficient",
            })
        }
    }
}

impl<S: Scalar> BSpline<S, 1> {
    /// The graph u ↦ (u, s(u)) of a spline function s = Σ cᵢ Nᵢ as a plane B-spline curve on
    /// the same knots: its control points are (ξᵢ, cᵢ), ξᵢ the
    /// [Greville abscissae](KnotVector::greville) [PPB, §5.8, Obs. 6], so its first
    /// coordinate is u itself (linear precision).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"degree"` for degree 0 (no spline of degree 0 is
    /// the identity).
    ///
    /// # Complexity
    ///
    /// Θ(nd) time, Θ(n) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?;
    /// let s = BSpline::new([0.0, 2.0, -1.0, 1.0].map(|c| Point::new([c])).to_vec(), t)?;
    /// let g = s.graph()?;
    /// assert_eq!(g.control()[1], Point::new([0.5, 2.0]));
    /// assert_eq!(g.eval(&0.75)?, Point::new([0.75, s.eval(&0.75)?[0]]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn graph(&self) -> Result<BSpline<S, 2>> {
        if self.degree() == 0 {
            return Err(Error::InvalidParameter {
                name: "degree",
                reason: "the graph of a spline of degree 0 is not a B-spline curve of degree 0 \
                         (it would need the identity)"
                    .into(),
            });
        }
        let xi = self.knots().greville();
        let control = xi
            .into_iter()
            .zip(self.control())
            .map(|(x, c)| Point::new([x, c[0].clone()]))
            .collect();
        BSpline::new(control, self.knots().clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounded_means_stay_between_their_knots() {
        // Three equal knots whose thirds round: the mean must still be the knot.
        let x = 0.1 + 0.2;
        let t = KnotVector::new(3, vec![0.0, x, x, x, 1.0, 1.0, 1.0, 1.0]).unwrap();
        let xi = t.greville();
        assert_eq!(xi[0], x);
        assert!(xi.windows(2).all(|w| w[0] <= w[1]), "{xi:?}");
        let t = KnotVector::new(0, vec![0.0, 1.0, 3.0]).unwrap();
        assert_eq!(t.greville(), [0.5, 2.0]);
        let t = KnotVector::new(1, vec![-f64::MAX, -f64::MAX, f64::MAX, f64::MAX]).unwrap();
        assert_eq!(t.greville(), [-f64::MAX, f64::MAX]);
    }

    #[test]
    fn marsden_refuses_nan_and_overflow() {
        let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]).unwrap();
        assert!(matches!(
            t.marsden(&f64::NAN),
            Err(Error::InvalidParameter { name: "y", .. })
        ));
        assert!(matches!(t.marsden(&1e200), Err(Error::Overflow { .. })));
        let t0 = KnotVector::new(0, vec![0.0, 1.0, 3.0]).unwrap();
        assert_eq!(t0.marsden(&7.0).unwrap(), [1.0, 1.0]);
    }
}
