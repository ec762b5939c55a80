//! Degree elevation of B-spline curves: the same curve as a spline of degree d + t, on the
//! knot vector whose every knot has t more copies.
//!
//! The problem: the control points of s in a higher degree (to join it with curves of higher
//! degree, to give it the degree a surface or a CAD exchange needs, or to bring the polygon
//! closer to the curve [PPB, §6.6]). A piece of degree d is also a piece of degree d + t; at a
//! knot of multiplicity m the curve is C^{d−m}, which in degree d + t needs multiplicity
//! m + t, so each knot gains t copies [PPB, §6.4, Fig. 6.4].
//!
//! The idea: by the fundamental theorem [PPB, §5.5] the new control point d_j is the blossom
//! of degree d + t of any piece of s over the span of its support, at the new knots
//! â_{j+1}, …, â_{j+d+t}. The blossom of degree d + t of a piece is the blossom of its
//! Bézier form elevated to degree d + t, and that is Bézier elevation. So: convert to
//! Bézier pieces (`to_bezier.rs`), elevate each to degree d + t by Zhou's formula
//! [PPB, §3.12], and evaluate each new control point as the blossom of the widest piece
//! under its support, by de Casteljau's scheme with the knots as arguments (in the global
//! parameter: each weight is a ratio of two knot distances). Everything is an affine
//! combination of the old control points with rational weights, so with `BigRational` the
//! result is exact.
//!
//! This is [PPB, §6.4]'s algorithm organised through the Bézier pieces. The seed's formula
//! there has slips in its indices; read correctly it is
//! d_j = s[â_{j+1} … â_{j+n+1}] = 1/(n+1) Σ_{k=1}^{n+1} s[â_{j+1} … (â_{j+k} left out) … â_{j+n+1}]
//! for one elevation of degree n (the omitted argument is â_{j+k}, not â_k; the blossom on
//! the right has n arguments, not r; the points it needs end at â_{j+n+1}, not â_{j+n}).
//! Micchelli's formula of [PPB, §6.5] for the basis is stated with the right factor 1/(n+1),
//! but its printed example for n = 1 is wrong (erratum of SCOPE §9, 000 l.2242): it reads
//! N¹(u|abc) = ½ (N²(u|aabc) + N²(u|abbc) + N²(u|abcc)), every knot doubled in turn (the
//! test suite checks this identity exactly). Repeating one elevation t times is the same as
//! elevating by t at once (the blossom of degree d + t averages over all d-subsets of its
//! arguments); here the t elevations are one Zhou step per piece.
//!
//! The knot vector: every knot (with multiplicity m ≤ d + 1) gets multiplicity m + t. For an
//! unclamped vector that would move the domain, whose ends sit at the (d + t)-th knot from
//! each end, so the knots outside the domain are cut to the d + t nearest it on each side:
//! the domain stays [t_d, t_n], and the copies of the knots at and inside it are exactly
//! m + t. For a clamped vector nothing is cut (the end knots go from d + 1 to d + t + 1).
//!
//! Follows [PPB, §6.4] (the algorithm), [PPB, §6.5] (Micchelli's formula, with the erratum
//! above), [PPB, §3.11–3.12] (Bézier elevation, Zhou's formula) and [PPB, §5.5] (control
//! points as blossom values).
//!
//! # Complexity
//!
//! Θ((n + p·t)(d + t)²·D) time for p non-empty spans: the n + p·t new control points take
//! (d + t)(d + t + 1)/2 affine combinations each (the order (d + t)² per control point of
//! [PPB, §6.4, Obs. 4]; Piegl and Tiller's Algorithm A5.9 does better with knot removal),
//! the conversion and the elevation of the pieces are within that; O((n + p·(d + t))D) space.
//!
//! Invariants the tests check (exactly on rationals): the elevated curve equals the original
//! at every parameter, the knot multiplicities are as stated, elevating a B-spline without
//! interior knots is Bézier elevation, and elevating by t at once equals t elevations by one.

use super::basis::affine;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::Scalar;
use crate::{Error, Result};

/// Degree elevation, declared.
pub(crate) const ELEVATE: Declaration = Declaration {
    problem: "bspline",
    name: "elevate",
    function: "spline::BSpline::elevate",
    file: "src/spline/bspline/elevate.rs",
    summary: "the same curve in degree d + t, each knot t more times, by blossoms of the elevated Bézier pieces",
    time: "Θ((n + p·t)(d + t)²·D)",
    space: "O((n + p·(d + t))D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "the conversion's, (d + 1)(t + 1) Zhou terms per piece and exactly (d + t)(d + t + 1)/2 affine combinations per new control point",
    source: "[PPB, §6.4]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The same curve with degree d + `times`. See [`BSpline::elevate_with`].
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if the degree would exceed
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) or the knots
    /// [`MAX_KNOTS`](crate::limits::MAX_KNOTS); [`Error::Overflow`] if, with `f64`, a new
    /// control point rounds beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((n + p·t)(d + t)²·D) time, O((n + p·(d + t))D) space for p non-empty spans and
    /// t = `times`.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// // A clamped quadratic with the simple interior knot 1, raised to a cubic.
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let c = vec![Point::new([0.0]), Point::new([6.0]), Point::new([12.0]), Point::new([6.0])];
    /// let s = BSpline::new(c, t)?;
    /// let e = s.elevate(1)?;
    /// assert_eq!(e.degree(), 3);
    /// assert_eq!(e.knots().knots(), [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0]);
    /// assert_eq!(e.control(), [0.0, 4.0, 7.0, 11.0, 10.0, 6.0].map(|x| Point::new([x])));
    /// assert_eq!(e.eval(&0.5)?, s.eval(&0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate(&self, times: usize) -> Result<Self> {
        self.elevate_with(times, &mut NoCount)
    }

    /// The same curve with degree d + `times`, counting the affine combinations.
    ///
    /// Every knot of multiplicity m gets multiplicity m + t (t = `times`); outside the domain
    /// only the d + t knots nearest it are kept on each side, so the domain stays
    /// [t_d, t_n] (nothing is cut from a clamped vector). The new curve has n + t·(k − 1)
    /// control points, k the number of distinct knots in the domain. `times = 0` returns the
    /// curve unchanged.
    ///
    /// Idea: the Bézier pieces of s ([`BSpline::to_bezier_with`]), each elevated to degree
    /// d + t by Zhou's formula ([`Bezier::elevate_to`](crate::spline::Bezier::elevate_to));
    /// then the new control point d_j is the blossom of degree d + t of a piece under the
    /// support [â_j, â_{j+d+t+1}] of its basis function, at â_{j+1}, …, â_{j+d+t} [PPB, §5.5,
    /// §6.4], by de Casteljau's scheme with the weights (b − x)/(b − a), (x − a)/(b − a) of the
    /// piece's interval [a, b]. The widest piece under the support is used: its weights are
    /// the smallest (at most d + t + 1 in size when the support lies in the domain), so the
    /// rounding with `f64` stays small. A basis function that vanishes on the whole domain
    /// (only at an unclamped end whose knot is repeated) takes the end piece's blossom.
    ///
    /// Follows [PPB, §6.4] and [PPB, §3.12]. The seed's formula in §6.4 has index slips;
    /// read correctly, one elevation of degree n is
    /// d_j = 1/(n+1) Σ_{k=1}^{n+1} s[â_{j+1} … (â_{j+k} left out) … â_{j+n+1}] (the argument
    /// left out is â_{j+k}, not â_k, and the blossom has n arguments). The example of
    /// Micchelli's formula in [PPB, §6.5] is misprinted: it is
    /// N¹(u|abc) = ½ (N²(u|aabc) + N²(u|abbc) + N²(u|abcc)), every knot doubled in turn, with
    /// the factor 1/(n+1) of the formula itself.
    ///
    /// # Errors
    ///
    /// As [`BSpline::elevate`].
    ///
    /// # Complexity
    ///
    /// Θ((n + p·t)(d + t)²·D) time, O((n + p·(d + t))D) space for p non-empty spans and
    /// t = `times`.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination or
    /// weighted term: those of [`BSpline::to_bezier_with`], (d + 1)(t + 1) for Zhou's sums on
    /// each piece, and exactly (d + t)(d + t + 1)/2 for each of the new control points' blossoms.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // A Bézier quadratic (one piece, no conversion) raised by 2 to degree 4: 5 points.
    /// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?;
    /// let s = BSpline::new(vec![Point::new([0.0]), Point::new([4.0]), Point::new([8.0])], t)?;
    /// let mut c = Counts::default();
    /// let e = s.elevate_with(2, &mut c)?;
    /// assert_eq!(e.control().len(), 5);
    /// assert_eq!(c.arithmetic_operations, 3 * 3 + 5 * (4 * 5 / 2));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_with<C: Counter>(&self, times: usize, counter: &mut C) -> Result<Self> {
        if times == 0 {
            return Ok(self.clone());
        }
        let d = self.degree();
        let degree = crate::limits::DEGREE.check(d as u128 + times as u128)?;
        let knots = elevated_knots(self.knots(), times)?;
        let bezier = self.to_bezier_with(counter)?;
        let tau = bezier.partition();
        let p = bezier.pieces().len();
        let mut pieces = Vec::with_capacity(p);
        for piece in bezier.pieces() {
            pieces.push(piece.elevate_to(degree)?);
            // Zhou's sums: every pair of an old point and one of the t + 1 shifts, once.
            for _ in 0..(d + 1) * (times + 1) {
                counter.arithmetic_operation();
            }
        }

        let a = knots.knots();
        let n = knots.control_points();
        let mut control = Vec::with_capacity(n);
        // The pieces under the support [â_j, â_{j+d+t+1}] are lo..hi; both move right with j.
        let (mut lo, mut hi) = (0, 0);
        for j in 0..n {
            while lo < p && tau[lo] < a[j] {
                lo += 1;
            }
            while hi < p && tau[hi + 1] <= a[j + degree + 1] {
                hi += 1;
            }
            let width = |i: usize| tau[i + 1].clone() - &tau[i];
            let i = if lo < hi {
                (lo + 1..hi).fold(lo, |best, i| if width(i) > width(best) { i } else { best })
            } else {
                // The support misses the domain's interior: the end piece it is next to.
                lo.min(p - 1)
            };
            let (start, end) = (&tau[i], &tau[i + 1]);
            let mut q = pieces[i].control().to_vec();
            for (k, x) in a[j + 1..=j + degree].iter().enumerate() {
                for l in 0..degree - k {
                    q[l] = affine(&q[l], start, x, end, &q[l + 1]);
                    counter.arithmetic_operation();
                }
            }
            control.push(q.swap_remove(0));
        }
        BSpline::derived(control, knots, "degree elevation").map_err(|e| match e {
            Error::Overflow { .. } => Error::Overflow {
                what: "B-spline degree elevation",
            },
            e => e,
        })
    }
}

/// The knot vector of degree d + t in which every knot of `knots` has t more copies, cut
/// outside the domain to d + t knots on each side (so the domain is the same).
fn elevated_knots<S: Scalar>(knots: &KnotVector<S>, times: usize) -> Result<KnotVector<S>> {
    let d = knots.degree();
    let t = knots.knots();
    let n = knots.control_points();
    let (start, end) = (&t[d], &t[n]);
    let runs = knots.multiplicities();
    let inside = runs.iter().filter(|(v, _)| v >= start && v <= end).count();
    let len = t.len() as u128 + times as u128 * inside as u128;
    crate::limits::KNOTS.check(len)?;
    let below = runs.iter().filter(|(v, _)| v < start).count() * times;
    let above = runs.iter().filter(|(v, _)| v > end).count() * times;
    let mut raised: Vec<S> = Vec::with_capacity(t.len() + times * runs.len());
    for (v, m) in runs {
        raised.extend(std::iter::repeat_n(v, m + times));
    }
    raised.truncate(raised.len() - above);
    raised.drain(..below);
    debug_assert_eq!(raised.len() as u128, len);
    KnotVector::new(d + times, raised)
}
