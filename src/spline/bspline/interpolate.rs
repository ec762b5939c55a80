//! Collocation interpolation: the B-spline curve of degree d that passes through n points at
//! n given parameters, after a Schoenberg–Whitney check that names the failing index.
//!
//! The problem: control points c₀, …, c_{n−1} with s(τ_k) = Σ_j c_j N_j(τ_k) = p_k for
//! k = 0, …, n − 1, the collocation system N C = P [PPB, §6.7, (2)]. The idea: by the theorem
//! of Schoenberg and Whitney [PPB, §6.7] the collocation matrix at increasing parameters is
//! invertible exactly when its diagonal is non-zero, N_k(τ_k) ≠ 0: for continuous basis
//! functions t_k < τ_k < t_{k+d+1}. That is checked exactly on the knots before anything is
//! solved, and the message names the index, the parameter, the inequality and the knots. The
//! matrix is then banded (row k has its d + 1 non-zero entries N_{μ−d}(τ_k), …, N_μ(τ_k)
//! within d of the diagonal) and totally positive, so the banded solver eliminates without
//! pivoting in O(n d²) ([`BandMatrix`]).
//!
//! The two ends of the rule, with this crate's right-continuous basis and closed last
//! interval (see the [module](super) docs): τ_k = t_k is allowed where t_k = t_{k+d} (the
//! first of d + 1 equal knots, as at a clamped start, where N_k(t_k) = 1), and τ_k = t_n where
//! t_{k+1} = t_{k+d+1} = t_n (the closed end of a clamped vector, N_{n−1}(t_n) = 1).
//!
//! [`BSpline::interpolate`] chooses the parameters (uniform, chord length or centripetal,
//! [`parameterise`]) and the knots by de Boor's averaging ([`KnotVector::averaged`]), which
//! satisfy the condition for distinct parameters; [`BSpline::interpolate_at`] takes both.
//!
//! Follows [PPB, §6.7] (the collocation matrix and the theorem of Schoenberg and Whitney),
//! [PPB, §4.5] (the parameterisations) and de Boor, *A Practical Guide to Splines* (1978),
//! ch. XIII (the banded elimination without pivoting, the averaged knots).
//!
//! # Complexity
//!
//! Θ(n d² + n D d) field operations after O(n log(n − d)) for the spans: Θ(n d²) for the
//! basis rows and the banded solve; Θ(n(d + D)) space.

use super::banded::BandMatrix;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{pow2_scale, validate_points, Point, Scalar};
use crate::spline::{parameterise, Parameterisation};
use crate::{Error, Result};

/// Collocation interpolation, declared.
pub(crate) const INTERPOLATE: Declaration = Declaration {
    problem: "bspline",
    name: "interpolate",
    function: "spline::BSpline::interpolate_at",
    file: "src/spline/bspline/interpolate.rs",
    summary: "the B-spline through n points at n parameters: Schoenberg–Whitney check, banded collocation solve",
    time: "Θ(n d² + n D d)",
    space: "Θ(n(d + D))",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n·d(d + 1)/2 basis steps plus the banded solve's count with l = u = d",
    source: "[PPB, §6.7]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The B-spline curve of degree `degree` through `points`, at the parameters of
    /// `parameterisation` ([`parameterise`]: uniform, chord length or centripetal, starting at
    /// 0) on the clamped knots averaged from them ([`KnotVector::averaged`]). See
    /// [`BSpline::interpolate_at`] for the solve.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] / [`Error::NonFinite`] for no points or a bad coordinate;
    /// [`Error::InvalidParameter`] named `"degree"` for degree 0 (averaging needs degree 1 or
    /// more); [`Error::TooFew`] for fewer than d + 1 points; [`Error::InvalidParameter`]
    /// named `"points"` when consecutive points coincide under chord-length or centripetal
    /// parameters, and named `"params"` when two parameters come out equal (naming both
    /// indices: with `f64`, a chord too short to change the running sum); the errors of
    /// [`BSpline::interpolate_at`].
    ///
    /// # Complexity
    ///
    /// Θ(n d² + n D d) time, Θ(n(d + D)) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, Parameterisation, Point};
    ///
    /// let p = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 1.0], [6.0, 0.0]].map(Point::new);
    /// let s = BSpline::interpolate(&p, 3, Parameterisation::Uniform)?;
    /// assert_eq!(s.knots().knots(), [0.0, 0.0, 0.0, 0.0, 2.0, 4.0, 4.0, 4.0, 4.0]);
    /// for (k, pk) in p.iter().enumerate() {
    ///     let q = s.eval(&(k as f64))?;
    ///     assert!((q[0] - pk[0]).abs() < 1e-12 && (q[1] - pk[1]).abs() < 1e-12);
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate(
        points: &[Point<S, D>],
        degree: usize,
        parameterisation: Parameterisation,
    ) -> Result<Self> {
        Self::interpolate_with(points, degree, parameterisation, &mut NoCount)
    }

    /// [`BSpline::interpolate`], counting as [`BSpline::interpolate_at_with`] does.
    ///
    /// # Errors
    ///
    /// As [`BSpline::interpolate`].
    ///
    /// # Complexity
    ///
    /// Θ(n d² + n D d) time, Θ(n(d + D)) space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, Parameterisation, Point};
    ///
    /// let p: Vec<_> = (0..10).map(|i| Point::new([(i * i) as f64])).collect();
    /// let mut c = Counts::default();
    /// BSpline::interpolate_with(&p, 2, Parameterisation::Uniform, &mut c)?;
    /// assert!(c.arithmetic_operations >= 10 * 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate_with<C: Counter>(
        points: &[Point<S, D>],
        degree: usize,
        parameterisation: Parameterisation,
        counter: &mut C,
    ) -> Result<Self> {
        validate_points(points, "points")?;
        let params: Vec<S> = parameterise(points, parameterisation)?;
        check_increasing(&params)?;
        let knots = KnotVector::averaged(degree, &params)?;
        Self::interpolate_at_with(points, &params, knots, counter)
    }

    /// The B-spline curve on `knots` through `points` at the parameters `params`: s(τ_k) = p_k.
    /// See [`BSpline::interpolate_at_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::interpolate_at_with`].
    ///
    /// # Complexity
    ///
    /// Θ(n d² + n D d) time, Θ(n(d + D)) space.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let p = [[0.0], [1.0], [4.0], [2.0]].map(Point::new);
    /// let s = BSpline::interpolate_at(&p, &[0.0, 0.5, 1.5, 2.0], t.clone())?;
    /// assert!((s.eval(&1.5)?[0] - 4.0).abs() < 1e-12);
    /// // N₃ has the support [t₃, t₆] = [1, 2]: it vanishes at τ₃ = 1.
    /// let e = BSpline::interpolate_at(&p, &[0.0, 0.25, 0.5, 1.0], t).unwrap_err();
    /// assert_eq!(
    ///     e.to_string(),
    ///     "invalid params: the Schoenberg–Whitney condition fails at index 3: N_3(τ_3) = 0 \
    ///      for τ_3 = 1; it needs t_3 < τ_3 < t_6 (t_3 = 1, t_6 = 2), but τ_3 = t_3, allowed \
    ///      only where t_3 = t_5 (d + 1 equal knots)"
    /// );
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate_at(
        points: &[Point<S, D>],
        params: &[S],
        knots: KnotVector<S>,
    ) -> Result<Self> {
        Self::interpolate_at_with(points, params, knots, &mut NoCount)
    }

    /// The B-spline curve on `knots` through `points` at `params`, by a banded collocation
    /// solve, counting its operations.
    ///
    /// Idea: check the parameters (finite, strictly increasing, in the domain) and the
    /// Schoenberg–Whitney condition N_k(τ_k) ≠ 0 exactly on the knots
    /// ([`KnotVector::check_schoenberg_whitney`]), then fill row k of the band with the d + 1
    /// basis values at τ_k ([`KnotVector::basis`]) and solve without pivoting
    /// ([`BandMatrix::solve_with`]); the collocation matrix is totally positive and
    /// invertible, so no pivot vanishes [PPB, §6.7]. With rationals the curve passes through
    /// every point exactly.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] / [`Error::NonFinite`] for no points or a bad coordinate;
    /// [`Error::InvalidParameter`] named `"knots"` if the knots serve another number of
    /// control points than there are points; named `"params"` for another number of
    /// parameters, a parameter that is not finite, outside the domain or not above its
    /// predecessor (two equal parameters are named by both indices), or a failure of the
    /// Schoenberg–Whitney condition (index, parameter, inequality and knots named);
    /// [`Error::Overflow`] if, with `f64`, a control point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(n d² + n D d) time after O(n log(n − d)) comparisons for the spans; Θ(n(d + D))
    /// space.
    ///
    /// # Counts
    ///
    /// d(d + 1)/2 [`arithmetic_operation`](Counter::arithmetic_operation)s per parameter for
    /// its basis row ([`KnotVector::basis_with`]) and the span search's
    /// [`comparison`](Counter::comparison)s, then the banded solve's count
    /// ([`BandMatrix::solve_with`] with l = u = d).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // Degree 1 at the knots: the control points are the data, the matrix the identity.
    /// let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0])?;
    /// let p = [[3.0], [5.0], [4.0]].map(Point::new);
    /// let mut c = Counts::default();
    /// let s = BSpline::interpolate_at_with(&p, &[0.0, 1.0, 2.0], t, &mut c)?;
    /// assert_eq!(s.control(), p);
    /// // 3 basis steps, then rows (r, w) = (1, 1), (1, 1), (0, 0): 2·3 + (2 + 2 + 1).
    /// assert_eq!(c.arithmetic_operations, 3 + 6 + 5);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn interpolate_at_with<C: Counter>(
        points: &[Point<S, D>],
        params: &[S],
        knots: KnotVector<S>,
        counter: &mut C,
    ) -> Result<Self> {
        validate_points(points, "points")?;
        let n = points.len();
        knots.check_control_points(n)?;
        if params.len() != n {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!("{} parameters for {n} points", params.len()),
            });
        }
        check_in_domain(params, &knots)?;
        check_increasing(params)?;
        knots.check_schoenberg_whitney(params)?;
        let d = knots.degree();
        let mut band = BandMatrix::zeros(n, d, d)?;
        for (k, u) in params.iter().enumerate() {
            let b = knots.basis_with(u, counter)?;
            for (j, v) in b.values().iter().enumerate() {
                // Schoenberg–Whitney puts k among the row's columns μ − d, …, μ, so every
                // entry is within d of the diagonal.
                band.add(k, b.first() + j, v);
            }
        }
        // A power of two keeps coordinates near 1e300 or subnormal in range and precision
        // (the solution is linear in the data; for rationals the factor is one).
        let refs: Vec<&Point<S, D>> = points.iter().collect();
        let scale = pow2_scale(&refs);
        let rhs = points.iter().map(|p| p.clone() * &scale).collect();
        let mut control = band.solve_with(rhs, counter)?;
        if !S::EXACT {
            let back = S::one() / &scale;
            for c in &mut control {
                *c = c.clone() * &back;
            }
        }
        BSpline::derived(control, knots, "B-spline interpolation")
    }
}

impl<S: Scalar> KnotVector<S> {
    /// `true` if N_i(u) ≠ 0 for a parameter `u` of the domain, decided exactly on the knots
    /// (no basis value is computed, so nothing can underflow to a false zero).
    ///
    /// With the span μ of u, only N_{μ−d}, …, N_μ can be non-zero. At u = t_μ, a knot with
    /// r copies t_{μ−r+1} = … = t_μ, the functions starting at u vanish there except, when
    /// r = d + 1, the first one (N_{μ−d}(u) = 1). At the closed end u = t_n with s copies
    /// t_{μ+1} = … = t_{μ+s}, mirrored: the functions ending at u vanish there except, when
    /// s = d + 1, the last one.
    pub(super) fn basis_nonzero(&self, i: usize, u: &S) -> bool {
        let (d, n, t) = (self.degree(), self.control_points(), self.knots());
        let mu = self.span_in_domain(u, &mut NoCount);
        if i + d < mu || i > mu {
            return false;
        }
        if *u == t[n] {
            let s = t[mu + 1..].iter().take_while(|k| *k == u).count();
            return if s > d { i == mu } else { i + d >= mu + s };
        }
        if *u == t[mu] {
            let r = t[..=mu].iter().rev().take_while(|k| *k == u).count();
            return if r > d { i + d == mu } else { i + r <= mu };
        }
        true
    }

    /// Checks the Schoenberg–Whitney condition for interpolation at `params` (one parameter
    /// per control point, in the domain and increasing): N_k(τ_k) ≠ 0 for every k, that is
    /// t_k < τ_k < t_{k+d+1}, or τ_k = t_k where t_k = t_{k+d} (d + 1 equal knots, as at a
    /// clamped start), or τ_k = t_n where t_{k+1} = t_{k+d+1} (the closed end of a clamped
    /// vector). By the theorem of Schoenberg and Whitney [PPB, §6.7] the collocation matrix
    /// N_j(τ_k) is then invertible, and otherwise singular.
    ///
    /// Every comparison is exact, on the knots: the decision is the same for `f64` and for
    /// rationals.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"params"` for another number of parameters than
    /// control points, a parameter outside the domain or not above its predecessor (naming
    /// it; two equal parameters by both indices), or for the first index
    /// k where the condition fails, naming k, τ_k, the violated inequality and the knots
    /// t_k and t_{k+d+1}.
    ///
    /// # Complexity
    ///
    /// O(n log(n − d) + n d) comparisons, O(1) space.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0])?;
    /// assert!(t.check_schoenberg_whitney(&[0.0, 1.0, 2.0]).is_ok());
    /// let e = t.check_schoenberg_whitney(&[0.0, 0.5, 1.0]).unwrap_err();
    /// assert!(e.to_string().contains("index 2: N_2(τ_2) = 0 for τ_2 = 1"), "{e}");
    /// assert!(e.to_string().contains("(t_2 = 1, t_4 = 2), but τ_2 = t_2"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn check_schoenberg_whitney(&self, params: &[S]) -> Result<()> {
        let n = self.control_points();
        if params.len() != n {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!("{} parameters for {n} control points", params.len()),
            });
        }
        check_in_domain(params, self)?;
        check_increasing(params)?;
        match (0..n).find(|&k| !self.basis_nonzero(k, &params[k])) {
            None => Ok(()),
            Some(k) => Err(self.schoenberg_whitney_error(k, &params[k], "")),
        }
    }

    /// The error of N_k(u) = 0 where the condition needs it non-zero; `context` is appended.
    pub(super) fn schoenberg_whitney_error(&self, k: usize, u: &S, context: &str) -> Error {
        let d = self.degree();
        let t = self.knots();
        let e = k + d + 1;
        let (lo, hi) = (&t[k], &t[e]);
        let violated = if u < lo {
            format!("τ_{k} < t_{k}")
        } else if u == lo {
            format!(
                "τ_{k} = t_{k}, allowed only where t_{k} = t_{} (d + 1 equal knots)",
                k + d
            )
        } else if u > hi {
            format!("τ_{k} > t_{e}")
        } else if u == hi {
            format!(
                "τ_{k} = t_{e}, allowed only at the end t_n where t_{} = t_{e}",
                k + 1
            )
        } else {
            format!("N_{k} vanishes at τ_{k}")
        };
        Error::InvalidParameter {
            name: "params",
            reason: format!(
                "the Schoenberg–Whitney condition fails at index {k}: N_{k}(τ_{k}) = 0 for \
                 τ_{k} = {}; it needs t_{k} < τ_{k} < t_{e} (t_{k} = {}, t_{e} = {}), but \
                 {violated}{context}",
                u.to_f64(),
                lo.to_f64(),
                hi.to_f64()
            ),
        }
    }
}

/// Checks that every parameter is finite and in the domain of `knots`, naming the first that
/// is not.
pub(super) fn check_in_domain<S: Scalar>(params: &[S], knots: &KnotVector<S>) -> Result<()> {
    let (start, end) = knots.bounds();
    for (k, u) in params.iter().enumerate() {
        if !u.is_finite() {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!("parameter {k} is not finite ({})", u.to_f64()),
            });
        }
        if u < start || u > end {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!(
                    "parameter {k} ({}) is outside the domain [{}, {}]",
                    u.to_f64(),
                    start.to_f64(),
                    end.to_f64()
                ),
            });
        }
    }
    Ok(())
}

/// Checks that the parameters are finite and strictly increasing; two equal ones are named
/// by both indices (they would make two rows of the collocation matrix equal).
pub(super) fn check_increasing<S: Scalar>(params: &[S]) -> Result<()> {
    if let Some(k) = params.iter().position(|u| !u.is_finite()) {
        return Err(Error::InvalidParameter {
            name: "params",
            reason: format!("parameter {k} is not finite ({})", params[k].to_f64()),
        });
    }
    for k in 1..params.len() {
        let (a, b) = (&params[k - 1], &params[k]);
        if a == b {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!(
                    "parameters {} and {k} are equal ({}): two rows of the collocation \
                     matrix would be equal",
                    k - 1,
                    b.to_f64()
                ),
            });
        }
        if b < a {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!(
                    "parameter {k} ({}) is below parameter {} ({}): interpolation needs \
                     increasing parameters",
                    b.to_f64(),
                    k - 1,
                    a.to_f64()
                ),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clamped_ends_are_allowed_and_nothing_else_on_the_support_ends() {
        let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]).unwrap();
        assert!(t.basis_nonzero(0, &0.0));
        assert!(!t.basis_nonzero(1, &0.0));
        assert!(t.basis_nonzero(3, &2.0));
        assert!(!t.basis_nonzero(2, &2.0));
        assert!(!t.basis_nonzero(3, &1.0)); // N₃ starts at the simple knot 1
        assert!(t.basis_nonzero(2, &1.0));
        // An unclamped end: N₂ on 0..5 ends at t₅ = 3 = t_n... its left limit there is 0.
        let u = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0]).unwrap();
        assert!(!u.basis_nonzero(0, &3.0) && u.basis_nonzero(1, &3.0) && u.basis_nonzero(2, &3.0));
        assert!(u.basis_nonzero(0, &2.0) && u.basis_nonzero(1, &2.0) && !u.basis_nonzero(2, &2.0));
    }

    #[test]
    fn repeated_and_decreasing_parameters_are_named() {
        let e = check_increasing(&[0.0, 0.5, 0.5, 1.0]).unwrap_err();
        assert!(
            e.to_string().contains("parameters 1 and 2 are equal (0.5)"),
            "{e}"
        );
        let e = check_increasing(&[0.0, 0.5, 0.25]).unwrap_err();
        assert!(
            e.to_string()
                .contains("parameter 2 (0.25) is below parameter 1"),
            "{e}"
        );
        let e = check_increasing(&[0.0, f64::NAN]).unwrap_err();
        assert!(
            e.to_string().contains("parameter 1 is not finite (NaN)"),
            "{e}"
        );
    }
}
