//! Least-squares B-spline fitting on given knots, with a rank check before the solve, and
//! the improvement of the parameters by Newton steps.
//!
//! The problem: the control points c₀, …, c_{n−1} of the spline s on a knot vector that
//! minimise Σ_k ‖s(τ_k) − p_k‖² over m ≥ n data points p_k at parameters τ_k. The idea: with
//! the collocation matrix N_{kj} = N_j(τ_k) (m × n) the minimum solves the normal equations
//! NᵀN C = NᵀP [PPB, §4.7, Obs. 11], one system for all coordinates [PPB, §4.6, Obs. 10].
//! NᵀN is banded (N_i and N_j share a parameter only if |i − j| ≤ d) and symmetric; it is
//! positive definite exactly when N has full rank n, so the banded solver eliminates it
//! without pivoting ([`BandMatrix`]).
//!
//! The rank, stated exactly: N has rank n if and only if some n of the parameters,
//! τ_{k₀} < τ_{k₁} < … < τ_{k_{n−1}}, satisfy the Schoenberg–Whitney condition
//! N_i(τ_{k_i}) ≠ 0 for every i (rows of equal parameters are equal, and a square
//! collocation matrix at increasing parameters is invertible exactly under the condition
//! [PPB, §6.7]). The sets {u : N_i(u) ≠ 0} are intervals whose two ends never decrease with i,
//! so the greedy choice (for N₀, N₁, … in turn, the smallest parameter above the last one
//! chosen where the function does not vanish) finds such a subsequence whenever one exists;
//! where it finds none, the error names the basis function that has too little data.
//!
//! Parameter improvement [PPB, §4.8]: the fitted curve is usually nearer to p_k at another
//! parameter than τ_k. Each round moves every τ_k by one Newton step on
//! f(u) = (s(u) − p_k)·s′(u), Δ = −f/f′ with f′ = s′·s′ + (s − p_k)·s″ (the second method of
//! [PPB, §4.8]; where f′ ≤ 0 the tangent projection Δ = −f/(s′·s′), its first method), keeps
//! the new parameter in the domain and accepts it only if the point is no farther from the
//! curve (halving Δ otherwise), and then refits.
//!
//! Follows [PPB, §4.6–4.8] (the residual, the normal equations and the parameter correction)
//! and [PPB, §6.7] (the theorem of Schoenberg and Whitney).
//!
//! # Complexity
//!
//! A fit: Θ(m d² + m d D) field operations to build the normal equations, Θ(n d² + n d D) to
//! solve them, after O(m log(n − d)) for the spans and O(m log m) comparisons for the rank
//! check; Θ(n(d + D) + m) space. A round of parameter improvement adds O(m(d² + dD)) for the
//! Newton steps (each with at most a fixed number of halvings) and a fit.

use super::banded::BandMatrix;
use super::interpolate::check_in_domain;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::curve::{Curve, CurveDerivative};
use crate::spline::scalar::{pow2_scale, validate_points, Point, Scalar};
use crate::{Error, Result};

/// Least-squares fitting, declared.
pub(crate) const FIT: Declaration = Declaration {
    problem: "bspline",
    name: "fit",
    function: "spline::BSpline::fit",
    file: "src/spline/bspline/fit.rs",
    summary: "the least-squares B-spline on given knots: rank check, banded normal equations",
    time: "Θ(m d² + m d D + n d² + m log m)",
    space: "Θ(n(d + D) + m)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "m·d(d + 1)/2 basis steps, (d + 1)(d + 2) per parameter for the normal equations, then the banded solve's count with l = u = d",
    source: "[PPB, §4.7]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

/// How many times a Newton step that takes a point farther from the curve is halved before
/// the parameter is kept as it was.
const HALVINGS: usize = 8;

/// What [`BSpline::fit_improved`] returns: the last fit, its parameters, and the error of
/// every fit.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ParameterFit<S, const D: usize> {
    /// The least-squares curve at [`params`](ParameterFit::params).
    pub curve: BSpline<S, D>,
    /// The parameters of the last fit, one per point, in the points' order.
    pub params: Vec<S>,
    /// Σ_k ‖s(τ_k) − p_k‖² of each fit, the first for the parameters given: one more entry
    /// than rounds that ran. They never increase (exactly with rationals).
    pub errors: Vec<S>,
}

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The least-squares B-spline on `knots` for `points` at `params`. See
    /// [`BSpline::fit_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::fit_with`].
    ///
    /// # Complexity
    ///
    /// Θ(m d² + m d D + n d² + m log m) time, Θ(n(d + D) + m) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // Points on the line y = 2x + 1 are fitted by the line itself, with noise orthogonal
    /// // to both basis functions (degree 1, no interior knot) or not.
    /// let t = KnotVector::clamped_uniform(1, 2, 0.0, 1.0)?;
    /// let u = [0.0, 0.25, 0.5, 0.75, 1.0];
    /// let p: Vec<_> = u.iter().map(|&x| Point::new([2.0 * x + 1.0])).collect();
    /// let s = BSpline::fit(&p, &u, t)?;
    /// assert!((s.control()[0][0] - 1.0).abs() < 1e-12 && (s.control()[1][0] - 3.0).abs() < 1e-12);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn fit(points: &[Point<S, D>], params: &[S], knots: KnotVector<S>) -> Result<Self> {
        Self::fit_with(points, params, knots, &mut NoCount)
    }

    /// The B-spline on `knots` that minimises Σ_k ‖s(τ_k) − p_k‖², by the banded normal
    /// equations, counting its operations.
    ///
    /// Idea: check the data and the rank ([`KnotVector::check_fit_rank`]) first; then add,
    /// for each parameter, the products N_i(τ_k)N_j(τ_k) of its d + 1 basis values to the
    /// band of NᵀN and N_i(τ_k)p_k to the right-hand side, and solve
    /// ([`BandMatrix::solve_with`]). The parameters may come in any order and repeat (a
    /// repeated parameter weighs its points more; it does not make anything singular unless
    /// the rank check says so). With `f64` the points are scaled by a power of two first, so
    /// coordinates near 1e300 or subnormal keep their precision. With rationals the residual
    /// s(τ_k) − p_k is exactly orthogonal to every basis function, and with m = n (one
    /// parameter per control point) the fit is the interpolant.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] / [`Error::NonFinite`] for no points or a bad coordinate;
    /// [`Error::InvalidParameter`] named `"params"` for another number of parameters than
    /// points, a parameter that is not finite or outside the domain (naming it), or a rank
    /// failure naming the basis function with too little data ([`KnotVector::check_fit_rank`],
    /// also for fewer points than control points); [`Error::InvalidParameter`] named
    /// `"matrix"` if, with `f64`, rounding leaves a zero pivot; [`Error::Overflow`] if, with
    /// `f64`, a control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(m d² + m d D + n d² + m log m) time, Θ(n(d + D) + m) space.
    ///
    /// # Counts
    ///
    /// d(d + 1)/2 [`arithmetic_operation`](Counter::arithmetic_operation)s per parameter for
    /// its basis row and the span search's [`comparison`](Counter::comparison)s,
    /// (d + 1)(d + 2) per parameter for the normal equations ((d + 1)² products and d + 1
    /// scaled points), then the banded solve's count ([`BandMatrix::solve_with`], l = u = d).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?;
    /// let u: Vec<f64> = (0..=8).map(|k| k as f64 / 8.0).collect();
    /// let p: Vec<_> = u.iter().map(|&x| Point::new([x * x])).collect();
    /// let mut c = Counts::default();
    /// let s = BSpline::fit_with(&p, &u, t, &mut c)?;
    /// assert_eq!(s.control().len(), 4);
    /// assert!(c.arithmetic_operations >= 9 * (3 + 12));
    /// // Too little data for N₃: its support [0.5, 1] holds no parameter.
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0)?;
    /// let e = BSpline::fit(&p[..4], &u[..4], t).unwrap_err();
    /// assert!(e.to_string().contains("N_3"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn fit_with<C: Counter>(
        points: &[Point<S, D>],
        params: &[S],
        knots: KnotVector<S>,
        counter: &mut C,
    ) -> Result<Self> {
        validate_points(points, "points")?;
        let m = points.len();
        if params.len() != m {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!("{} parameters for {m} points", params.len()),
            });
        }
        knots.check_fit_rank(params)?;
        let (d, n) = (knots.degree(), knots.control_points());
        let refs: Vec<&Point<S, D>> = points.iter().collect();
        let scale = pow2_scale(&refs);
        let mut band = BandMatrix::zeros(n, d, d)?;
        let mut rhs = vec![Point::<S, D>::zero(); n];
        for (u, p) in params.iter().zip(points) {
            let b = knots.basis_with(u, counter)?;
            let f = b.first();
            let p = p.clone() * &scale;
            for (a, va) in b.values().iter().enumerate() {
                for (c, vc) in b.values().iter().enumerate() {
                    band.add(f + a, f + c, &(va.clone() * vc));
                    counter.arithmetic_operation();
                }
                rhs[f + a] += &(p.clone() * va);
                counter.arithmetic_operation();
            }
        }
        if rhs.iter().any(|p| !p.is_finite()) {
            return Err(Error::Overflow {
                what: "least-squares B-spline fit",
            });
        }
        let mut control = band.solve_with(rhs, counter)?;
        if !S::EXACT {
            let back = S::one() / &scale;
            for c in &mut control {
                *c = c.clone() * &back;
            }
        }
        BSpline::derived(control, knots, "least-squares B-spline fit")
    }

    /// The least-squares fit of [`BSpline::fit`] with its parameters improved `rounds` times
    /// [PPB, §4.8]: each round moves every parameter by a Newton step towards the nearest
    /// point of the current curve, then refits.
    ///
    /// Idea: for each point p_k, one Newton step on f(u) = (s(u) − p_k)·s′(u) from τ_k (the
    /// module docs give the step and its fallback), clamped to the domain; if the new
    /// parameter puts s farther from p_k than τ_k did, the step is halved (at most 8 times)
    /// and otherwise given up. So every point is at most as far from the current curve at its
    /// new parameter as before, and the refit, which minimises over all curves on the knots,
    /// can only do better: the errors Σ_k ‖s(τ_k) − p_k‖² never increase (exactly with
    /// rationals, up to rounding with `f64`).
    ///
    /// Convergence: the errors decrease monotonically and so converge, typically linearly
    /// (each round is one step of an alternating minimisation, not a joint Newton method);
    /// the limit is a local minimum of the orthogonal-distance error, which depends on the
    /// starting parameters, and the steps may stall where the curve has a cusp (s′ = 0). If
    /// the new parameters no longer satisfy the rank condition (they crowded together), the
    /// improvement stops and returns the last fit; `errors.len() − 1` says how many rounds
    /// ran. The method is meant for `f64`; with rationals every round lengthens the numbers
    /// considerably, so keep the rounds few.
    ///
    /// # Errors
    ///
    /// As [`BSpline::fit`] for the first fit; [`Error::Overflow`] if, with `f64`, a
    /// derivative of the curve is beyond the double range.
    ///
    /// # Complexity
    ///
    /// O(r(m d² + m d D + n d² + m log m)) time for r = `rounds`, Θ(n(d + D) + m) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // Points of the unit quarter circle, at parameters a uniform guess gets wrong.
    /// let p: Vec<_> = (0..=12)
    ///     .map(|k| {
    ///         let a = std::f64::consts::FRAC_PI_2 * (k as f64 / 12.0).powi(2);
    ///         Point::new([a.cos(), a.sin()])
    ///     })
    ///     .collect();
    /// let u: Vec<f64> = (0..=12).map(|k| k as f64 / 12.0).collect();
    /// let t = KnotVector::clamped_uniform(3, 5, 0.0, 1.0)?;
    /// let f = BSpline::fit_improved(&p, &u, t, 5)?;
    /// assert!(f.errors.len() >= 2 && f.errors.len() <= 6);
    /// assert!(f.errors.windows(2).all(|w| w[1] <= w[0]));
    /// assert!(f.errors[f.errors.len() - 1] < f.errors[0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn fit_improved(
        points: &[Point<S, D>],
        params: &[S],
        knots: KnotVector<S>,
        rounds: usize,
    ) -> Result<ParameterFit<S, D>> {
        let mut params = params.to_vec();
        let mut curve = Self::fit(points, &params, knots.clone())?;
        let mut errors = vec![squared_error(&curve, points, &params)?];
        for _ in 0..rounds {
            let mut moved = Vec::with_capacity(params.len());
            for (u, p) in params.iter().zip(points) {
                moved.push(newton_step(&curve, u, p)?);
            }
            let next = match Self::fit(points, &moved, knots.clone()) {
                Ok(c) => c,
                Err(Error::InvalidParameter { name: "params", .. }) => break,
                Err(e) => return Err(e),
            };
            let error = squared_error(&next, points, &moved)?;
            // Exactly the error cannot increase; with rounding it may by an ulp, and then the
            // round is not worth keeping.
            if error > errors[errors.len() - 1] {
                break;
            }
            errors.push(error);
            curve = next;
            params = moved;
        }
        Ok(ParameterFit {
            curve,
            params,
            errors,
        })
    }
}

impl<S: Scalar> KnotVector<S> {
    /// Checks that the collocation matrix N_{kj} = N_j(τ_k) at `params` has full rank n (the
    /// number of control points), so that the least-squares fit is unique and its normal
    /// equations are positive definite: exactly when some n parameters
    /// τ_{k₀} < … < τ_{k_{n−1}} satisfy N_i(τ_{k_i}) ≠ 0 for every i (the Schoenberg–Whitney
    /// condition for a subsequence). The sets {u : N_i(u) ≠ 0} are intervals whose ends never
    /// decrease with i, so choosing greedily, for N₀, N₁, … in turn, the smallest parameter
    /// above the last one chosen where the function does not vanish decides it. Decided
    /// exactly on the knots.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"params"` for a parameter that is not finite or
    /// outside the domain (naming it), or naming the first basis function N_i, with its
    /// support, for which no parameter is left above those chosen for N₀, …, N_{i−1}.
    ///
    /// # Complexity
    ///
    /// O(m log m + m log(n − d) + (m + n) d) comparisons, O(m) space.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::clamped_uniform(1, 4, 0.0, 3.0)?; // supports [0,1], [0,2], [1,3], [2,3]
    /// assert!(t.check_fit_rank(&[0.0, 0.5, 1.5, 2.5, 3.0, 3.0]).is_ok());
    /// // Four parameters, but 0.5 twice: N₂ gets 2.5 and N₃ nothing.
    /// let e = t.check_fit_rank(&[0.0, 0.5, 0.5, 2.5]).unwrap_err();
    /// assert!(e.to_string().contains("N_3 (support [t_3, t_5] = [2, 3]) has too little data"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn check_fit_rank(&self, params: &[S]) -> Result<()> {
        check_in_domain(params, self)?;
        let mut sorted: Vec<&S> = params.iter().collect();
        // Finite, so the order is total.
        sorted.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
        let (d, n) = (self.degree(), self.control_points());
        let mut next = 0;
        let mut last: Option<&S> = None;
        for i in 0..n {
            loop {
                let Some(&u) = sorted.get(next) else {
                    return Err(self.rank_error(i, last, params.len()));
                };
                next += 1;
                if last.is_some_and(|l| u <= l) {
                    continue;
                }
                if self.basis_nonzero(i, u) {
                    last = Some(u);
                    break;
                }
                // A parameter past the end of N_i's support: so are all the others.
                if *u >= self.knots()[i + d + 1] {
                    return Err(self.rank_error(i, last, params.len()));
                }
            }
        }
        Ok(())
    }

    /// The error of a basis function N_i with too little data.
    fn rank_error(&self, i: usize, last: Option<&S>, m: usize) -> Error {
        let (d, n, t) = (self.degree(), self.control_points(), self.knots());
        let after = match last {
            None => String::new(),
            Some(u) => format!(" above {}, the one chosen for N_{}", u.to_f64(), i - 1),
        };
        Error::InvalidParameter {
            name: "params",
            reason: format!(
                "the fit is not unique: basis function N_{i} (support [t_{i}, t_{}] = [{}, {}]) \
                 has too little data: the {m} parameters hold no n = {n} increasing ones with \
                 N_j(τ_{{k_j}}) ≠ 0 for every j (the Schoenberg–Whitney condition for a \
                 subsequence), and no parameter is left where N_{i} does not vanish{after}",
                i + d + 1,
                t[i].to_f64(),
                t[i + d + 1].to_f64()
            ),
        }
    }
}

/// Σ_k ‖s(τ_k) − p_k‖².
fn squared_error<S: Scalar, const D: usize>(
    curve: &BSpline<S, D>,
    points: &[Point<S, D>],
    params: &[S],
) -> Result<S> {
    let mut sum = S::zero();
    for (u, p) in params.iter().zip(points) {
        sum += &(curve.eval(u)? - p).norm_squared();
    }
    Ok(sum)
}

/// One safeguarded Newton step on (s(u) − p)·s′(u) = 0 from `u` (see the module docs).
fn newton_step<S: Scalar, const D: usize>(
    curve: &BSpline<S, D>,
    u: &S,
    p: &Point<S, D>,
) -> Result<S> {
    let r = curve.eval(u)? - p;
    let d1 = curve.derivative_at(u, 1)?;
    let d2 = curve.derivative_at(u, 2)?;
    let f = r.dot(&d1);
    let speed = d1.norm_squared();
    let slope = speed.clone() + &r.dot(&d2);
    let zero = S::zero();
    let mut delta = if slope > zero {
        -(f / &slope)
    } else if speed > zero {
        -(f / &speed)
    } else {
        return Ok(u.clone());
    };
    if !delta.is_finite() || delta.is_zero() {
        return Ok(u.clone());
    }
    let before = r.norm_squared();
    let (start, end) = curve.knots().bounds();
    let half = S::from_ratio(1, 2);
    for _ in 0..=HALVINGS {
        let mut v = u.clone() + &delta;
        if v < *start {
            v = start.clone();
        } else if v > *end {
            v = end.clone();
        }
        if (curve.eval(&v)? - p).norm_squared() <= before {
            return Ok(v);
        }
        delta = delta * &half;
    }
    Ok(u.clone())
}
