//! Batch evaluation at sorted parameters: de Boor's algorithm at many parameters, with the
//! span found by walking forward instead of a binary search per point.
//!
//! The problem: the points s(u₀), …, s(u_{m−1}) for u₀ ≤ … ≤ u_{m−1}, as for drawing or
//! sampling a curve. The idea: the span of u_{j+1} is at or after the span of u_j, so one
//! binary search for u₀ and then a forward walk over the knots find all the spans in
//! O(m + n) comparisons; each point is then de Boor's scheme on its d + 1 control points
//! [PPB, §5.4], in one scratch buffer reused for every point (no allocation per point).
//!
//! Each point is computed by exactly the same operations as [`BSpline::de_boor`] (the same
//! span, the same levels skipped at a knot, the same weights), so the results are equal to
//! it, bit for bit with `f64`.
//!
//! # Complexity
//!
//! Θ(m·d²D + n) time for m parameters: exactly the affine combinations of de Boor at each
//! point, and at most m + n comparisons for the walk after one O(log(n − d)) search; O(dD)
//! auxiliary space besides the output.
//!
//! Invariants the tests check (exactly on rationals, and bit for bit with `f64`): the batch
//! equals de Boor at every parameter, and a decreasing, NaN or outside parameter is an error
//! naming its index.

use super::de_boor::de_boor_level;
use super::BSpline;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::{Error, Result};

/// Batch evaluation at sorted parameters, declared.
pub(crate) const EVAL_SORTED: Declaration = Declaration {
    problem: "bspline",
    name: "eval-sorted",
    function: "spline::BSpline::eval_sorted",
    file: "src/spline/bspline/batch.rs",
    summary: "de Boor at m sorted parameters, the spans found by one forward walk over the knots",
    time: "Θ(m·d²D + n)",
    space: "O(dD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly de Boor's affine combinations at each parameter; at most m + n comparisons for the walk",
    source: "[PPB, §5.4]",
    claims: &[on("random-parameters", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The points s(u₀), …, s(u_{m−1}) at non-decreasing parameters. See
    /// [`BSpline::eval_sorted_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"params"`, naming the index and the value, for the
    /// first parameter that is NaN or infinite or below its predecessor, or outside the
    /// domain [t_d, t_n] (only the first and the last can be, once the order is checked).
    ///
    /// # Complexity
    ///
    /// Θ(m·d²D + n) time for m parameters, O(dD) auxiliary space besides the output.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?;
    /// let s = BSpline::new([0.0, 2.0, -1.0, 1.0].map(|c| Point::new([c])).to_vec(), t)?;
    /// let us = [0.0, 0.25, 1.0, 1.0, 2.0];
    /// let points = s.eval_sorted(&us)?;
    /// for (u, p) in us.iter().zip(&points) {
    ///     assert_eq!(*p, s.de_boor(u)?);
    /// }
    /// let e = s.eval_sorted(&[0.5, 0.25]).unwrap_err();
    /// assert_eq!(e.to_string(), "invalid params: parameter 1 (0.25) is below parameter 0 (0.5)");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_sorted(&self, params: &[S]) -> Result<Vec<Point<S, D>>> {
        self.eval_sorted_with(params, &mut NoCount)
    }

    /// The points at non-decreasing parameters, counting the affine combinations and the
    /// comparisons of the span walk.
    ///
    /// Idea: check the parameters once (each finite and not below its predecessor, the first
    /// and the last in the domain), find the span of the first by binary search and, for
    /// each next parameter u, step the span forward while t_{μ+1} ≤ u (at u = t_n, the last
    /// non-empty span, as [`KnotVector::span`](super::KnotVector::span) does). Then de Boor's
    /// scheme on c_{μ−d}, …, c_{μ−r} (r the multiplicity of u as the knot t_μ) in one scratch
    /// buffer of d + 1 points reused for every parameter.
    ///
    /// Follows [PPB, §5.4].
    ///
    /// # Errors
    ///
    /// As [`BSpline::eval_sorted`].
    ///
    /// # Complexity
    ///
    /// Θ(m·d²D + n) time for m parameters: the affine combinations of
    /// [`BSpline::de_boor_with`] at each parameter, d(d + 1)/2 off the knots, and at most
    /// m + n comparisons for the walk after one O(log(n − d)) search; O(dD) auxiliary space
    /// besides the output.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination;
    /// one [`comparison`](Counter::comparison) per step of the walk and per parameter where
    /// it stops, and those of the binary searches for the first parameter and for t_n. The
    /// checks of the input are not counted.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::uniform(3, 8, 0.0, 1.0)?;
    /// let s = BSpline::new((0..8).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let us: Vec<f64> = (0..100).map(|k| (k as f64 + 0.5) / 100.0).collect();
    /// s.eval_sorted_with(&us, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 100 * 6); // no parameter is a knot
    /// assert!(c.comparisons <= 100 + 8 + 2 * 4);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_sorted_with<C: Counter>(
        &self,
        params: &[S],
        counter: &mut C,
    ) -> Result<Vec<Point<S, D>>> {
        let mut out = Vec::new();
        self.eval_sorted_core(params, &mut out, counter)?;
        Ok(out)
    }

    /// The points at non-decreasing parameters into `out`, which is cleared first (so its
    /// allocation is reused across calls); on an error it is left empty.
    ///
    /// # Errors
    ///
    /// As [`BSpline::eval_sorted`].
    ///
    /// # Complexity
    ///
    /// Θ(m·d²D + n) time for m parameters, O(dD) auxiliary space besides `out`.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?;
    /// let s = BSpline::new([0.0, 4.0, 0.0].map(|c| Point::new([c])).to_vec(), t)?;
    /// let mut out = Vec::new();
    /// s.eval_sorted_into(&[0.5, 1.5], &mut out)?;
    /// assert_eq!(out, [Point::new([2.0]), Point::new([2.0])]);
    /// assert!(s.eval_sorted_into(&[1.0, f64::NAN], &mut out).is_err());
    /// assert!(out.is_empty());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn eval_sorted_into(&self, params: &[S], out: &mut Vec<Point<S, D>>) -> Result<()> {
        self.eval_sorted_core(params, out, &mut NoCount)
    }

    /// Checks the parameters, then evaluates them into `out` (cleared).
    fn eval_sorted_core<C: Counter>(
        &self,
        params: &[S],
        out: &mut Vec<Point<S, D>>,
        counter: &mut C,
    ) -> Result<()> {
        out.clear();
        let Some(first) = params.first() else {
            return Ok(());
        };
        check_sorted(params)?;
        let knots = self.knots();
        let (start, end) = knots.bounds();
        let last = &params[params.len() - 1];
        for (i, u) in [(0, first), (params.len() - 1, last)] {
            if u < start || u > end {
                return Err(Error::InvalidParameter {
                    name: "params",
                    reason: format!(
                        "parameter {i} ({}) is outside the domain [{}, {}]",
                        u.to_f64(),
                        start.to_f64(),
                        end.to_f64()
                    ),
                });
            }
        }
        out.reserve(params.len());

        let d = self.degree();
        let t = knots.knots();
        let control = self.control();
        let last_span = knots.span_in_domain(end, counter);
        let mut span = knots.span_in_domain(first, counter);
        let mut q: Vec<Point<S, D>> = Vec::with_capacity(d + 1);
        for u in params {
            if u == end {
                span = last_span;
            } else {
                // t_μ ≤ u holds from the previous parameter; t_n > u stops the walk before n.
                counter.comparison();
                while t[span + 1] <= *u {
                    span += 1;
                    counter.comparison();
                }
            }
            let r = (0..d).take_while(|&j| t[span - j] == *u).count();
            let m = d - r;
            q.clear();
            q.extend_from_slice(&control[span - d..=span - r]);
            for k in 1..=m {
                de_boor_level(t, d, span, k, u, &mut q, counter);
            }
            out.push(q[m].clone());
        }
        Ok(())
    }
}

/// The first parameter that is not finite or is below its predecessor, as an error.
fn check_sorted<S: Scalar>(params: &[S]) -> Result<()> {
    let mut previous: Option<&S> = None;
    for (i, u) in params.iter().enumerate() {
        if !u.is_finite() {
            return Err(Error::InvalidParameter {
                name: "params",
                reason: format!("parameter {i} is not finite ({})", u.to_f64()),
            });
        }
        if let Some(p) = previous {
            if u < p {
                return Err(Error::InvalidParameter {
                    name: "params",
                    reason: format!(
                        "parameter {i} ({}) is below parameter {} ({})",
                        u.to_f64(),
                        i - 1,
                        p.to_f64()
                    ),
                });
            }
        }
        previous = Some(u);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;
    use crate::spline::KnotVector;

    #[test]
    fn repeated_knots_and_the_end_take_de_boors_spans() {
        // Multiplicities 1, 2, 3 and d + 1 = 4 (a jump at 3), and the closed end at 4.
        let t = KnotVector::new(
            3,
            vec![
                0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 3.0, 3.0, 3.0, 3.0, 4.0, 4.0, 4.0, 4.0,
            ],
        )
        .unwrap();
        let s = BSpline::new((0..11).map(|i| Point::new([(i * i) as f64])).collect(), t).unwrap();
        let us = [
            0.0, 0.0, 0.5, 1.0, 1.0, 1.5, 2.0, 2.5, 3.0, 3.0, 3.5, 4.0, 4.0,
        ];
        let mut c = Counts::default();
        let got = s.eval_sorted_with(&us, &mut c).unwrap();
        let mut want_ops = 0;
        for (u, p) in us.iter().zip(&got) {
            let mut k = Counts::default();
            assert_eq!(*p, s.de_boor_with(u, &mut k).unwrap(), "u = {u}");
            want_ops += k.arithmetic_operations;
        }
        assert_eq!(c.arithmetic_operations, want_ops);
        assert!(c.comparisons <= us.len() as u64 + 11 + 2 * 4, "{c:?}");
        assert!(s.eval_sorted(&[]).unwrap().is_empty());
    }

    #[test]
    fn errors_name_the_index() {
        let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0).unwrap();
        let s = BSpline::new(vec![Point::new([0.0]); 4], t).unwrap();
        let msg = |us: &[f64]| s.eval_sorted(us).unwrap_err().to_string();
        assert_eq!(
            msg(&[0.0, f64::NAN, 1.0]),
            "invalid params: parameter 1 is not finite (NaN)"
        );
        assert_eq!(
            msg(&[-0.5, 0.0]),
            "invalid params: parameter 0 (-0.5) is outside the domain [0, 1]"
        );
        assert_eq!(
            msg(&[0.0, 0.5, 1.5]),
            "invalid params: parameter 2 (1.5) is outside the domain [0, 1]"
        );
        assert_eq!(
            msg(&[0.0, 0.5, 0.5, 0.25]),
            "invalid params: parameter 3 (0.25) is below parameter 2 (0.5)"
        );
    }
}
