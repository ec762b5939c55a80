//! The Oslo algorithm: the same curve on a knot vector refined by many knots at once, each new
//! control point computed directly from the old ones.
//!
//! The problem: the control points ĉ₀, …, ĉ_{n+m−1} of s on the refined knots τ (the old knots
//! t with m new ones merged in). The idea: by the fundamental theorem each new control point is
//! a blossom value, ĉ_j = s_μ[τ_{j+1}, …, τ_{j+d}], for the polynomial piece s_μ of any old span
//! [t_μ, t_{μ+1}) that meets the support [τ_j, τ_{j+d+1}] of the new basis function
//! [PPB, §6.2]. The blossom is a combination Σ α_{j,i} cᵢ of the d + 1 control points
//! c_{μ−d}, …, c_μ, and its weights (the discrete B-splines [PPB, §6.1, Obs. 2]) come from the
//! triangle of the Cox–de Boor recursion with the parameter of level k replaced by τ_{j+k}
//! (the generalised de Boor algorithm of [PPB, §5.5, Obs. 5], run on the weights instead of
//! the points). This is the recurrence of Cohen, Lyche and Riesenfeld.
//!
//! A new control point whose d interior knots τ_{j+1}, …, τ_{j+d} are d consecutive old knots
//! t_{i+1}, …, t_{i+d} (no new knot among them) is the old cᵢ, copied, exactly also in `f64`;
//! only the at most md others are computed. The blossom is the same for every span that meets
//! the support; the widest such span is used, which keeps the ratios of knot distances small
//! next to knots a few ulps apart. The affine combinations may be non-convex [PPB, §6.2], so
//! with `f64` the rounding error can exceed that of Boehm's insertions.
//!
//! New knots are placed as [`BSpline::insert`] places them (after the old copies of an equal
//! knot, before the copies of t_n), and control points whose basis function vanishes on the
//! whole domain (possible before t_d or after t_n of an unclamped vector) follow the same
//! rule as the single insertions, so the result equals inserting the knots one by one, exactly
//! on rationals.
//!
//! [PPB, §6.2] itself says that repeated insertion of simple knots is usually the better
//! method: [`BSpline::refine`] does that in one pass and is the faster one (Θ(d) operations
//! per new knot instead of Θ(d²) per new control point, see the `bspline/refine` benches);
//! this file is the course's algorithm, with its discrete B-splines, and an independent
//! oracle for it.
//!
//! Follows [PPB, §6.2] (the Oslo algorithm), [PPB, §5.5] (the fundamental theorem and the
//! generalised de Boor algorithm) and Lyche and Mørken, *Spline Methods* (2008), §4.2 (the
//! discrete B-splines as a product of matrices R₁(τ_{j+1})⋯R_d(τ_{j+d})).
//!
//! # Complexity
//!
//! Θ(m log m) comparisons to sort the new knots, Θ((n + m)D) to merge and copy, and for each
//! of the q ≤ md computed control points (q = n + m for degree 0) a span search,
//! d(d + 1)/2 steps of the weight triangle and d + 1 terms: O(m log m + (n + m)D +
//! md(d² + dD + log n)) time, O((n + m)D) space.
//!
//! Invariants the tests check (exactly on rationals): the result equals the knots inserted one
//! by one with [`BSpline::insert`], and the curve is unchanged at every parameter.

use super::basis::split_value;
use super::refine::checked_new_knots;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::Result;

/// The Oslo refinement, declared.
pub(crate) const OSLO: Declaration = Declaration {
    problem: "bspline",
    name: "oslo",
    function: "spline::BSpline::oslo",
    file: "src/spline/bspline/oslo.rs",
    summary: "the same curve with m knots added at once, each new control point a combination of old ones by the discrete B-splines",
    time: "O(m log m + (n + m)D + md(d² + dD + log n))",
    space: "O((n + m)D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly q(d(d + 1)/2 + d + 1) operations, q ≤ md the new control points that are not copies",
    source: "[PPB, §6.2]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The same curve on the knot vector with all of `new_knots` added, by the Oslo
    /// algorithm: the result of [`BSpline::refine`], computed point by point from the
    /// discrete B-splines. See [`BSpline::oslo_with`].
    ///
    /// # Errors
    ///
    /// As [`BSpline::refine`].
    ///
    /// # Complexity
    ///
    /// O(m log m + (n + m)D + md(d² + dD + log n)) time, O((n + m)D) space for m new knots.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?;
    /// let c = [0.0, 2.0, 2.0, 0.0].map(|x| Point::new([x])).to_vec();
    /// let s = BSpline::new(c, t)?;
    /// assert_eq!(s.oslo(&[1.5, 0.5])?, s.refine(&[0.5, 1.5])?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn oslo(&self, new_knots: &[S]) -> Result<Self> {
        self.oslo_with(new_knots, &mut NoCount)
    }

    /// The same curve on the knot vector with all of `new_knots` added, by the Oslo algorithm,
    /// counting its operations.
    ///
    /// Idea: validate and sort the new knots, merge them into the old ones (τ), and for each
    /// new index j either copy the old cᵢ (when τ_{j+1}, …, τ_{j+d} are the old knots
    /// t_{i+1}, …, t_{i+d}) or take the widest old span μ meeting the support
    /// [τ_j, τ_{j+d+1}], compute the discrete B-splines α_{j,μ−d}, …, α_{j,μ} by the
    /// Cox–de Boor triangle whose level k uses τ_{j+k} in place of the parameter, and set
    /// ĉ_j = Σ α_{j,i} cᵢ [PPB, §6.2]. Knots are compared exactly: a new knot a few ulps from
    /// an old one is a new knot; an equal one raises the multiplicity, up to d. An empty
    /// `new_knots` returns the curve unchanged.
    ///
    /// Follows [PPB, §6.2] and [PPB, §5.5, Obs. 5].
    ///
    /// # Errors
    ///
    /// As [`BSpline::oslo`].
    ///
    /// # Complexity
    ///
    /// As [`BSpline::oslo`].
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per step of the weight
    /// triangle and per term of a combination: exactly q(d(d + 1)/2 + d + 1), where q is the
    /// number of new control points that are not copies (at most md for degree d ≥ 1, all
    /// n + m for degree 0); the [`comparison`](Counter::comparison)s of the span searches.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// let t = KnotVector::clamped_uniform(3, 8, 0.0, 5.0)?;
    /// let s = BSpline::new((0..8).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let r = s.oslo_with(&[0.5], &mut c)?;
    /// // One new knot: d = 3 new control points, each 6 triangle steps and 4 terms.
    /// assert_eq!((c.arithmetic_operations, r.control().len()), (30, 9));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn oslo_with<C: Counter>(&self, new_knots: &[S], counter: &mut C) -> Result<Self> {
        let knots = self.knots();
        let (d, n) = (self.degree(), self.control().len());
        let sorted = checked_new_knots(knots, new_knots, counter)?;
        if sorted.is_empty() {
            return Ok(self.clone());
        }
        let end = knots.bounds().1;

        // The merge: τ, and for each position the old index (None for a new knot). A new
        // knot goes after the old copies of its value, except at t_n, where it goes before
        // them, as Boehm's insertion places it.
        let t = knots.knots();
        let m = sorted.len();
        let mut tau: Vec<S> = Vec::with_capacity(t.len() + m);
        let mut old_index: Vec<Option<usize>> = Vec::with_capacity(t.len() + m);
        let (mut i, mut k) = (0, 0);
        while i < t.len() || k < m {
            let take_old = k == m
                || (i < t.len() && (t[i] < sorted[k] || (t[i] == sorted[k] && sorted[k] < *end)));
            if take_old {
                tau.push(t[i].clone());
                old_index.push(Some(i));
                i += 1;
            } else {
                tau.push(sorted[k].clone());
                old_index.push(None);
                k += 1;
            }
        }
        // new_before[p]: how many new knots lie at positions < p.
        let mut new_before = Vec::with_capacity(tau.len() + 1);
        new_before.push(0usize);
        for o in &old_index {
            new_before.push(new_before[new_before.len() - 1] + usize::from(o.is_none()));
        }

        let old = self.control();
        let mut control = Vec::with_capacity(n + m);
        let mut weights: Vec<S> = Vec::with_capacity(d + 1);
        for j in 0..n + m {
            if d > 0 && new_before[j + d + 1] == new_before[j + 1] {
                // τ_{j+1..=j+d} are old knots, consecutive: the blossom is cᵢ itself.
                let i = old_index[j + 1].expect("an old knot") - 1;
                control.push(old[i].clone());
                continue;
            }
            let mu = widest_span(knots, &tau[j], &tau[j + d + 1], counter);
            discrete_bsplines(t, d, mu, &tau[j + 1..=j + d], &mut weights, counter);
            let window = &old[mu - d..=mu];
            let mut p = Point::zero();
            for (w, c) in weights.iter().zip(window) {
                p += &(c.clone() * w);
                counter.arithmetic_operation();
            }
            if !p.is_finite() {
                // With f64 near f64::MAX: the weights are convex, so the exact coordinate lies
                // between the window's extremes, where it is clamped back to.
                p = clamp_to_window(p, window);
            }
            control.push(p);
        }
        let refined = KnotVector::valid_by_construction(d, tau);
        BSpline::derived(control, refined, "Oslo refinement")
    }
}

/// Each non-finite coordinate of `p` (a convex combination of `window` that rounded past
/// the double range) replaced by the window's largest coordinate (for +∞) or smallest.
fn clamp_to_window<S: Scalar, const D: usize>(
    p: Point<S, D>,
    window: &[Point<S, D>],
) -> Point<S, D> {
    Point::new(std::array::from_fn(|j| {
        if p[j].is_finite() {
            return p[j].clone();
        }
        let up = p[j] > S::zero();
        let mut best = window[0][j].clone();
        for c in &window[1..] {
            if (up && c[j] > best) || (!up && c[j] < best) {
                best = c[j].clone();
            }
        }
        best
    }))
}

/// The widest non-empty span [t_μ, t_{μ+1}) of the domain that meets [lo, hi), starting from
/// the span of lo (clamped into the domain, so the first or last span serves a basis function
/// that vanishes on the whole domain).
fn widest_span<S: Scalar, C: Counter>(
    knots: &KnotVector<S>,
    lo: &S,
    hi: &S,
    counter: &mut C,
) -> usize {
    let (start, end) = knots.bounds();
    let clamped = if lo < start {
        start
    } else if lo > end {
        end
    } else {
        lo
    };
    let t = knots.knots();
    let n = knots.control_points();
    let mut mu = knots.span_in_domain(clamped, counter);
    let mut width = t[mu + 1].clone() - &t[mu];
    let mut next = mu + 1;
    while next < n && t[next] < *hi {
        if t[next] < t[next + 1] {
            let w = t[next + 1].clone() - &t[next];
            if w > width {
                (mu, width) = (next, w);
            }
        }
        next += 1;
    }
    mu
}

/// The discrete B-splines α_{j,μ−d}, …, α_{j,μ} into `weights`: the Cox–de Boor triangle on
/// the span μ with the parameter of level k replaced by `x[k − 1]` = τ_{j+k}. The
/// denominators t_{μ+r+1} − t_{μ+r+1−k} all contain the non-empty span, so none is zero.
fn discrete_bsplines<S: Scalar, C: Counter>(
    t: &[S],
    d: usize,
    mu: usize,
    x: &[S],
    weights: &mut Vec<S>,
    counter: &mut C,
) {
    weights.clear();
    weights.push(S::one());
    for (level, xk) in x.iter().enumerate() {
        let k = level + 1;
        let mut saved = S::zero();
        for r in 0..k {
            let (lo, hi) = (&t[mu + r + 1 - k], &t[mu + r + 1]);
            let v = std::mem::replace(&mut weights[r], S::zero());
            let (right, left) = split_value(&v, lo, xk, hi);
            weights[r] = saved + right;
            saved = left;
            counter.arithmetic_operation();
        }
        weights.push(saved);
    }
    debug_assert_eq!(weights.len(), d + 1);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::Curve;

    #[test]
    fn the_oslo_algorithm_equals_single_insertions() {
        // The validation of the new knots is shared with `refine` and tested there.
        let t = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
        let c = [0.0, 4.0, 1.0, 3.0].map(|x| Point::new([x])).to_vec();
        let s = BSpline::new(c, t).unwrap();
        // Dyadic knots and points: every operation is exact in f64.
        let r = s.oslo(&[2.5, 2.0, 4.0, 3.0]).unwrap();
        let one = s
            .insert(&2.0, 1)
            .and_then(|s| s.insert(&2.5, 1))
            .and_then(|s| s.insert(&3.0, 1))
            .and_then(|s| s.insert(&4.0, 1))
            .unwrap();
        assert_eq!(r, one);
        for u in [2.0, 2.25, 3.0, 3.75, 4.0] {
            assert_eq!(r.eval(&u).unwrap(), s.eval(&u).unwrap());
        }
        assert!(s.oslo(&[3.0, 3.0]).is_err());
        assert_eq!(s.oslo(&[]).unwrap(), s);
    }
}
