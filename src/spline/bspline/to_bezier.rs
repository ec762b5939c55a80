//! Conversion between a B-spline curve and its piecewise Bézier form: every polynomial piece
//! of the spline as a Bézier curve over its knot span, and Bézier pieces joined back into a
//! B-spline.
//!
//! The problem: the Bézier points of each piece s|[t_μ, t_{μ+1}] (to hand the curve to code
//! that only knows Bézier curves, to subdivide or intersect it piece by piece). The idea: by
//! the fundamental theorem the Bézier points of the piece on [a, b] are its blossom values
//! s[a^{d−k} b^k], and these are the control points the spline gets when every knot in the
//! domain has multiplicity d [PPB, §5.5, §5.10]. So each knot is inserted up to multiplicity
//! d, and the curve is read off span by span. The insertions are done in one pass from left
//! to right, on a window of d + 1 control points (the idea of Piegl and Tiller's Algorithm
//! A5.6): once the knot a on the left of a span has multiplicity d, the insertion of the knot
//! b on its right only needs a (d copies) and the original knots from b on, so it runs r
//! levels of de Boor's scheme on the window (the same level function as evaluation and
//! insertion); the first points of the levels are the span's Bézier points, the last points
//! the start of the next window.
//!
//! The conversion back is the converse reading: Bézier pieces of one degree d whose end points
//! match are the control points of a B-spline whose interior knots have multiplicity d, the
//! piece boundaries, and whose end knots have multiplicity d + 1. Where the curve is smoother
//! than C⁰, some of those knots could be removed again; knot removal is a separate algorithm,
//! so this gives the multiplicity-d form.
//!
//! Follows [PPB, §5.10] (the conversion between the de Boor and the Bézier representation),
//! [PPB, §5.5] (the fundamental theorem: control points are blossom values at consecutive
//! knots), [PPB, §6.1] (insertion as levels of de Boor's scheme) and Piegl and Tiller,
//! *The NURBS Book* (2nd ed., 1997), Algorithm A5.6.
//!
//! # Complexity
//!
//! To Bézier: Θ((n + d) + p·d·D) time and Θ(p·d·D) space for p non-empty spans, with exactly
//! Σ (d − m)(d − m + 1)/2 affine combinations over the distinct knots in the domain (m the
//! knot's multiplicity, at most d): O(n·d²·D) at worst. Back: Θ(p·d·D).
//!
//! Invariants the tests check (exactly on rationals): each piece equals the spline (by de
//! Boor) at every parameter of its span, the counts above, the pieces' partition is the set
//! of distinct knots in the domain, and converting back gives the same curve.

use super::de_boor::de_boor_level;
use super::{BSpline, KnotVector};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::spline::{Bezier, CompositeBezier};
use crate::{Error, Result};

/// The conversion to piecewise Bézier form, declared.
pub(crate) const TO_BEZIER: Declaration = Declaration {
    problem: "bspline",
    name: "to-bezier",
    function: "spline::BSpline::to_bezier",
    file: "src/spline/bspline/to_bezier.rs",
    summary: "the Bézier pieces of a B-spline curve, every knot in the domain raised to multiplicity d in one pass",
    time: "Θ(n + d + p·d·D) plus O(n·d²·D)",
    space: "Θ(p·d·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly Σ (d − m)(d − m + 1)/2 affine combinations over the distinct knots in the domain, m the multiplicity (at most d)",
    source: "[PPB, §5.10]",
    claims: &[on("random-control", Bound::Linear, Operation::ArithmeticOperations)],
};

/// The conversion from piecewise Bézier form, declared.
pub(crate) const FROM_BEZIER: Declaration = Declaration {
    problem: "bspline",
    name: "from-bezier",
    function: "spline::BSpline::from_bezier",
    file: "src/spline/bspline/to_bezier.rs",
    summary: "Bézier pieces of one degree with matching ends as a B-spline with interior knots of multiplicity d",
    time: "Θ(p·d·D)",
    space: "Θ(p·d·D)",
    operation: Some(Operation::Moves),
    counts: "exactly p·d + 1 control points copied (p for degree 0), and p − 1 comparisons of end points",
    source: "[PPB, §5.10]",
    claims: &[
        on("random-pieces", Bound::Linear, Operation::Moves),
        on("random-degree", Bound::Linear, Operation::Moves),
    ],
};

impl<S: Scalar, const D: usize> BSpline<S, D> {
    /// The curve as Bézier pieces, one per non-empty knot span of the domain. See
    /// [`BSpline::to_bezier_with`].
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`] if the pieces would have more than
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS) control points in all; [`Error::Overflow`]
    /// if, with `f64`, a Bézier point rounds beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(n + d + p·d·D) plus O(n·d²·D) time, Θ(p·d·D) space for p non-empty spans.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, Curve, KnotVector, Point};
    ///
    /// // A clamped quadratic with the interior knot 1: two parabolas meeting at c₁c₂'s midpoint.
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0])?;
    /// let c = vec![Point::new([0.0]), Point::new([2.0]), Point::new([4.0]), Point::new([8.0])];
    /// let s = BSpline::new(c, t)?;
    /// let b = s.to_bezier()?;
    /// assert_eq!(b.partition(), [0.0, 1.0, 2.0]);
    /// assert_eq!(b.pieces()[0].control(), [Point::new([0.0]), Point::new([2.0]), Point::new([3.0])]);
    /// assert_eq!(b.pieces()[1].control(), [Point::new([3.0]), Point::new([4.0]), Point::new([8.0])]);
    /// assert_eq!(b.eval(&0.5)?, s.eval(&0.5)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_bezier(&self) -> Result<CompositeBezier<S, D>> {
        self.to_bezier_with(&mut NoCount)
    }

    /// The curve as Bézier pieces, counting the affine combinations.
    ///
    /// Piece i is the Bézier curve, in its local parameter, of the spline on the i-th
    /// non-empty span [t_μ, t_{μ+1}] of the domain [t_d, t_n]; the partition of the result is
    /// the distinct knots in the domain, so [`CompositeBezier::eval`](crate::spline::Curve::eval)
    /// in the global parameter is the spline (right-continuous at a knot, as the spline).
    /// Clamped and unclamped vectors alike: the ends of the domain are raised to multiplicity
    /// d as the interior knots, so the knots outside the domain never matter. Where an
    /// interior knot has multiplicity d + 1 the curve may jump, and the two pieces there
    /// do not meet.
    ///
    /// Idea: for the first span, insert its left end up to multiplicity d into the d + 1
    /// control points it depends on; then for each span with left end a (now of multiplicity
    /// d) and right end b of multiplicity m < d, run r = d − m levels of de Boor's scheme at
    /// b on the last r + 1 window points, with the knots a (r + 1 copies), b (m copies) and
    /// the original knots after b. The span's Bézier points s[a^{d−k} b^k] are the first m window points and the
    /// first point of each level; the next window is the last point of each level, from the
    /// last level back, and the original control points after the window [PPB, §5.10, §6.1].
    ///
    /// Follows [PPB, §5.10] and Piegl and Tiller's Algorithm A5.6.
    ///
    /// # Errors
    ///
    /// As [`BSpline::to_bezier`].
    ///
    /// # Complexity
    ///
    /// Θ(n + d + p·d·D) plus O(n·d²·D) time, Θ(p·d·D) space for p non-empty spans.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination:
    /// exactly Σ (d − m)(d − m + 1)/2 over the distinct knots t_d ≤ v ≤ t_n, with m the
    /// multiplicity of v capped at d (what inserting each v up to multiplicity d costs by
    /// [`BSpline::insert_with`]); none for a clamped curve whose interior knots have
    /// multiplicity at least d.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, KnotVector, Point};
    ///
    /// // A uniform cubic with 3 spans on [0, 9]: the simple knots 0, 3, 6, 9 of its domain
    /// // each need 2 more copies, 2 + 1 affine combinations (d = 3, m = 1: 2·3/2).
    /// let t = KnotVector::uniform(3, 6, 0.0, 9.0)?;
    /// let s = BSpline::new((0..6).map(|i| Point::new([i as f64])).collect(), t)?;
    /// let mut c = Counts::default();
    /// let b = s.to_bezier_with(&mut c)?;
    /// assert_eq!((b.pieces().len(), c.arithmetic_operations), (3, 4 * 3));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_bezier_with<C: Counter>(&self, counter: &mut C) -> Result<CompositeBezier<S, D>> {
        let d = self.degree();
        let t = self.knots().knots();
        let c = self.control();
        let n = c.len();
        // The non-empty spans of the domain: d ≤ μ < n with t_μ < t_{μ+1}.
        let spans: Vec<usize> = (d..n).filter(|&mu| t[mu] < t[mu + 1]).collect();
        crate::limits::POINTS.check(spans.len() as u128 * (d as u128 + 1))?;
        let mut partition = Vec::with_capacity(spans.len() + 1);
        let mut pieces = Vec::with_capacity(spans.len());

        // The first window: c_{μ−d}, …, c_μ with the left end a = t_μ raised to multiplicity
        // d. Its copies at or below μ (all of them, as t_μ < t_{μ+1}) are s, at most d.
        let first = spans[0];
        let a = &t[first];
        let s = (0..d).take_while(|&j| t[first - j] == *a).count();
        let mut window: Vec<Point<S, D>> = if s == d {
            c[first - d..=first].to_vec()
        } else {
            let mut q = c[first - d..=first - s].to_vec();
            let (_, lasts) = levels(t, d, first, a, &mut q, d - s, counter);
            let mut w: Vec<Point<S, D>> = lasts.into_iter().rev().collect();
            w.extend_from_slice(&c[first - s + 1..=first]);
            w
        };
        partition.push(a.clone());

        for &mu in &spans {
            let (a, b) = (&t[mu], &t[mu + 1]);
            // The multiplicity m of b: its copies start at μ + 1.
            let m = t[mu + 1..].iter().take_while(|&v| v == b).count();
            let s = m.min(d);
            let r = d - s;
            let mut bezier = Vec::with_capacity(d + 1);
            bezier.extend_from_slice(&window[..s]);
            let mut next: Vec<Point<S, D>> = if r == 0 {
                bezier.push(window[d].clone());
                vec![window[d].clone()]
            } else {
                // Knots a (r + 1 copies: the first is never read), b (s copies), then the
                // original ones after b, enough for r levels on r + 1 points.
                let mut local: Vec<S> = Vec::with_capacity(2 * d - s + 1);
                local.extend(std::iter::repeat_n(a.clone(), r + 1));
                local.extend(std::iter::repeat_n(b.clone(), s));
                local.extend_from_slice(&t[mu + s + 1..=mu + d]);
                let mut q = window[s..].to_vec();
                let (firsts, lasts) = levels(&local, d, d, b, &mut q, r, counter);
                bezier.extend(firsts);
                lasts.into_iter().rev().collect()
            };
            pieces.push(Bezier::derived(bezier, "B-spline to Bézier conversion")?);
            partition.push(b.clone());
            // The next window (unused after the last span): the tail, then the original
            // control points up to the next span μ + m; with m = d + 1 only the latter.
            let end = (mu + m).min(n - 1);
            next.extend_from_slice(&c[mu + 1..=end]);
            let keep = next.len().saturating_sub(d + 1);
            next.drain(..keep);
            window = next;
        }
        CompositeBezier::from_pieces(partition, pieces)
    }

    /// The B-spline of Bézier pieces of one degree d whose consecutive end points are equal:
    /// on the partition u₀ < … < u_p of `curve`, the knots u₀ and u_p with multiplicity
    /// d + 1 and every interior u_i with multiplicity d, and as control points the pieces'
    /// Bézier points, each shared end point once [PPB, §5.10].
    ///
    /// This is the multiplicity-d form, the inverse of [`BSpline::to_bezier`] for a clamped
    /// curve: the knots are all kept even where the joins are smoother than C⁰ (knot removal,
    /// a separate algorithm, can lower them). Pieces of degree 0 (a step function) have no
    /// end points to match and are joined by simple knots.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"pieces"` if a piece's degree differs from the
    /// first one's, or a piece does not start exactly where the one before ends (naming the
    /// piece and both points); [`Error::LimitExceeded`] beyond
    /// [`MAX_KNOTS`](crate::limits::MAX_KNOTS).
    ///
    /// # Complexity
    ///
    /// Θ(p·d·D) time and Θ(p·d·D) space for p pieces of degree d.
    ///
    /// ```
    /// use compgeo::spline::{BSpline, CompositeBezier, Curve, Point};
    ///
    /// let p = |x: f64| Point::new([x]);
    /// let b = CompositeBezier::new(
    ///     vec![0.0, 1.0, 2.0],
    ///     vec![vec![p(0.0), p(2.0), p(3.0)], vec![p(3.0), p(4.0), p(8.0)]],
    /// )?;
    /// let s = BSpline::from_bezier(&b)?;
    /// assert_eq!(s.knots().knots(), [0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]);
    /// assert_eq!(s.control(), [p(0.0), p(2.0), p(3.0), p(4.0), p(8.0)]);
    /// assert_eq!(s.eval(&1.5)?, b.eval(&1.5)?);
    /// let gap = CompositeBezier::new(vec![0.0, 1.0, 2.0], vec![vec![p(0.0), p(1.0)], vec![p(2.0), p(3.0)]])?;
    /// let e = BSpline::from_bezier(&gap).unwrap_err();
    /// assert!(e.to_string().contains("piece 1 starts at (2) but piece 0 ends at (1)"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_bezier(curve: &CompositeBezier<S, D>) -> Result<Self> {
        Self::from_bezier_with(curve, &mut NoCount)
    }

    /// [`BSpline::from_bezier`], counting one [`element_move`](Counter::element_move) per
    /// control point copied (exactly p·d + 1 for p pieces of degree d ≥ 1, p for degree 0)
    /// and one [`comparison`](Counter::comparison) per pair of end points checked (p − 1 for
    /// d ≥ 1).
    ///
    /// # Errors
    ///
    /// As [`BSpline::from_bezier`].
    ///
    /// # Complexity
    ///
    /// Θ(p·d·D) time and Θ(p·d·D) space for p pieces of degree d.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BSpline, CompositeBezier, Point};
    ///
    /// let p = |x: f64| Point::new([x]);
    /// let b = CompositeBezier::new(
    ///     vec![0.0, 1.0, 2.0],
    ///     vec![vec![p(0.0), p(2.0), p(3.0)], vec![p(3.0), p(4.0), p(8.0)]],
    /// )?;
    /// let mut c = Counts::default();
    /// BSpline::from_bezier_with(&b, &mut c)?;
    /// assert_eq!((c.moves, c.comparisons), (2 * 2 + 1, 1));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_bezier_with<C: Counter>(
        curve: &CompositeBezier<S, D>,
        counter: &mut C,
    ) -> Result<Self> {
        let pieces = curve.pieces();
        let u = curve.partition();
        let d = pieces[0].degree();
        for (i, piece) in pieces.iter().enumerate().skip(1) {
            if piece.degree() != d {
                return Err(Error::InvalidParameter {
                    name: "pieces",
                    reason: format!(
                        "piece {i} has degree {}, piece 0 has degree {d} (elevate the lower \
                         ones first)",
                        piece.degree()
                    ),
                });
            }
            let (start, end) = (&piece.control()[0], &pieces[i - 1].control()[d]);
            if d > 0 {
                counter.comparison();
            }
            if d > 0 && start != end {
                return Err(Error::InvalidParameter {
                    name: "pieces",
                    reason: format!(
                        "piece {i} starts at {} but piece {} ends at {} (the pieces must meet \
                         exactly)",
                        show(start),
                        i - 1,
                        show(end)
                    ),
                });
            }
        }
        let p = pieces.len();
        let inner = d.max(1);
        let count = 2 * (d as u128 + 1) + (p as u128 - 1) * inner as u128;
        crate::limits::KNOTS.check(count)?;
        let mut knots = Vec::with_capacity(count as usize);
        knots.extend(std::iter::repeat_n(u[0].clone(), d + 1));
        for ui in &u[1..p] {
            knots.extend(std::iter::repeat_n(ui.clone(), inner));
        }
        knots.extend(std::iter::repeat_n(u[p].clone(), d + 1));
        let mut control = Vec::with_capacity(p * inner + 1);
        control.extend_from_slice(pieces[0].control());
        for piece in &pieces[1..] {
            // The shared end point once (a degree-0 piece is its own point).
            control.extend_from_slice(&piece.control()[1.min(d)..]);
        }
        for _ in &control {
            counter.element_move();
        }
        BSpline::new(control, KnotVector::new(d, knots)?)
    }
}

/// Runs `r` levels of de Boor's scheme at `u` on the window `q` (the points c_{μ−d+j} of the
/// span `span` of the knots `t`, j = 0, …, r) and returns the first and the last point of
/// each level 0, …, r: after an r-fold insertion of u the first ones are the points on the
/// left of u, the last ones those on its right [PPB, §6.1].
fn levels<S: Scalar, const D: usize, C: Counter>(
    t: &[S],
    d: usize,
    span: usize,
    u: &S,
    q: &mut [Point<S, D>],
    r: usize,
    counter: &mut C,
) -> (Vec<Point<S, D>>, Vec<Point<S, D>>) {
    debug_assert_eq!(q.len(), r + 1);
    let mut firsts = Vec::with_capacity(r + 1);
    let mut lasts = Vec::with_capacity(r + 1);
    firsts.push(q[0].clone());
    lasts.push(q[r].clone());
    for k in 1..=r {
        de_boor_level(t, d, span, k, u, q, counter);
        firsts.push(q[k].clone());
        lasts.push(q[r].clone());
    }
    (firsts, lasts)
}

/// A point as the error messages print it: `(x, y, …)` in `f64`.
fn show<S: Scalar, const D: usize>(p: &Point<S, D>) -> String {
    let coords: Vec<String> = p.coords().iter().map(|x| x.to_f64().to_string()).collect();
    format!("({})", coords.join(", "))
}
