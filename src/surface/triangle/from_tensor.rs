//! Conversion of a tensor-product patch to two triangular patches, one on each side of the
//! diagonal of its square.
//!
//! The problem: a [`BezierPatch`] c(u, v) of bidegree (m, n) has total degree at most
//! l = m + n, so over any triangle it has a triangular Bézier net of degree l [PPB, §11.11].
//! Here the unit square is cut along its diagonal from (1, 0) to (0, 1) into the lower
//! triangle p q r = (1, 0), (0, 1), (0, 0), where the barycentric coordinates of (u, v) are
//! (u, v, 1 − u − v), and the upper triangle q p s = (0, 1), (1, 0), (1, 1): the two patches
//! meet along p q as [`TriangularPatch::join_order`] expects, with s = (1, 1, −1).
//!
//! The idea: the book's formula b_{ijk} = Σ δ^{ijk}_{αβγ} c[p₁^α q₁^β r₁^γ, p₂^{i−α} q₂^{j−β}
//! r₂^{k−γ}] with δ = C(i, α) C(j, β) C(k, γ)/C(l, m) [PPB, §11.11] (the printed factor reads
//! m! n!; the weights sum to one with m! n!/l!) takes Θ(l²m²) terms. Collapsed coordinates
//! regroup it: with v = (1 − u)t the triangular Bernstein polynomials factor as
//! B^l_{ijk} = B^l_i(u) B^{l−i}_j(t), and B^n_b(v) = Σ_e B^n_e(u) B^{n−e}_b(t), so
//!
//! c(u, (1 − u)t) = Σ_i B^l_i(u) Σ_{a+e=i} C(m, a) C(n, e)/C(l, i) · Q_{a,e}(t),
//!
//! where Q_{a,e} is the curve of degree n − e whose control points are c_{a,0}, …, c_{a,n−e}.
//! Row i of the triangular net (the points b_{i,j,l−i−j}) is the bracket elevated to degree
//! l − i; adding the Q_{a,e} in order of increasing a, each one degree higher than the last,
//! between elevations by one, takes Θ(m(m + n)²) operations. The upper triangle is the lower
//! one of the net turned half a turn, c′_{a,b} = c_{m−a,n−b} (the map (u, v) ↦ (1 − u, 1 − v)
//! sends q p s to p q r).
//!
//! # Complexity
//!
//! Θ(m(m + n)²D) time, Θ((m + n)²D) space.
//!
//! Invariants the tests check (exactly on rationals): the lower patch at (u, v, 1 − u − v)
//! and the upper at (α, β, γ) equal c(u, v) and c(β + γ, α + γ) everywhere; the two meet
//! with C^l continuity; the count.

use super::patch::{check_degree, TriangularPatch};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::elevated_polygon;
use crate::spline::{Point, Scalar};
use crate::surface::BezierPatch;
use crate::Result;

/// Tensor-product to triangular, declared.
pub(crate) const FROM_TENSOR: Declaration = Declaration {
    problem: "triangular-patch",
    name: "from-tensor",
    function: "surface::TriangularPatch::from_tensor",
    file: "src/surface/triangle/from_tensor.rs",
    summary: "collapsed coordinates: each row of the net a sum of the tensor rows' initial pieces, elevated in turn",
    time: "Θ(m(m + n)²D)",
    space: "Θ((m + n)²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per scaled control point added, 2(m + 1)(n + 1)(n + 2)/2, and one per point of each elevation by one",
    source: "[PPB, §11.11]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The two triangular patches of degree l = m + n of a tensor-product patch of bidegree
    /// (m, n): over (1, 0), (0, 1), (0, 0) (the lower half of the unit square, barycentric
    /// coordinates (u, v, 1 − u − v)) and over (0, 1), (1, 0), (1, 1) (the upper half). See
    /// [`TriangularPatch::from_tensor_with`].
    ///
    /// # Errors
    ///
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if (l + 1)(l + 2)/2 exceeds
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS); [`Error::Overflow`](crate::Error::Overflow)
    /// if, with `f64`, a point is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(m(m + n)²D) time, Θ((m + n)²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, BezierPatch, ControlNet, Surface, TriangularPatch};
    ///
    /// // The bilinear patch of z = uv.
    /// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    /// let c = BezierPatch::new(ControlNet::new(vec![
    ///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
    ///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
    /// ])?)?;
    /// let [lower, upper] = TriangularPatch::from_tensor(&c)?;
    /// assert_eq!(lower.degree(), 2);
    /// assert_eq!(lower.eval(&0.25, &0.5)?, c.eval(&0.25, &0.5)?);
    /// // (α, β, γ) on the upper half is (u, v) = (β + γ, α + γ).
    /// let y = Barycentric::new(0.5, 0.25, 0.25)?;
    /// assert_eq!(upper.de_casteljau(&y), c.eval(&0.5, &0.75)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_tensor(patch: &BezierPatch<S, D>) -> Result<[Self; 2]> {
        Self::from_tensor_with(patch, &mut NoCount)
    }

    /// The two triangular halves of a tensor-product patch, counting point operations.
    ///
    /// Idea: the formula of [PPB, §11.11] regrouped by collapsed coordinates: with
    /// v = (1 − u)t, B^{m+n}_{ijk} = B^{m+n}_i(u) B^{m+n−i}_j(t) and
    /// B^n_b(v) = Σ_e B^n_e(u) B^{n−e}_b(t), so row i of the net over the lower half is
    /// Σ_{a+e=i} C(m, a) C(n, e)/C(l, i) · Q_{a,e} elevated to degree l − i, where Q_{a,e} is
    /// the polygon c_{a,0}, …, c_{a,n−e}; the terms are added by increasing a, one elevation by
    /// one between each. The upper half is the lower half of the net turned half a turn.
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::from_tensor`].
    ///
    /// # Complexity
    ///
    /// Θ(m(m + n)²D) time, Θ((m + n)²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per scaled control point
    /// added, (m + 1)(n + 1)(n + 2)/2 per half, and one per point of each elevation by one
    /// (d + 2 from degree d): per half, Σ_i Σ_d (d + 2) over i = 0, …, l and
    /// d = l − i − (m − a₀), …, l − i − 1, a₀ = max(0, i − n).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, TriangularPatch};
    ///
    /// // Bidegree (1, 1): per half 2·2·3/2 = 6 terms, and elevations of 3 points (row i = 0,
    /// // from degree 1) and 2 (row i = 1, from degree 0).
    /// let c = BezierPatch::new(ControlNet::new(vec![vec![Point::new([1.0]); 2]; 2])?)?;
    /// let mut counts = Counts::default();
    /// let [lower, upper] = TriangularPatch::from_tensor_with(&c, &mut counts)?;
    /// assert!(lower.points().iter().chain(upper.points()).all(|p| *p == Point::new([1.0])));
    /// assert_eq!(counts.arithmetic_operations, 2 * (6 + 3 + 2));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_tensor_with<C: Counter>(
        patch: &BezierPatch<S, D>,
        counter: &mut C,
    ) -> Result<[Self; 2]> {
        let (m, n) = patch.bidegree();
        let l = m + n;
        check_degree(l)?;
        let net = patch.net().points();
        let turned: Vec<Point<S, D>> = net.iter().rev().cloned().collect();
        let what = "tensor to triangular conversion";
        Ok([
            Self::derived(l, lower_half(net, m, n, counter), what)?,
            Self::derived(l, lower_half(&turned, m, n, counter), what)?,
        ])
    }
}

/// The net of degree l = m + n over (1, 0), (0, 1), (0, 0) of the tensor patch whose net
/// (row after row, (m + 1) × (n + 1)) is `net`, in the triangular storage order.
fn lower_half<S: Scalar, const D: usize, C: Counter>(
    net: &[Point<S, D>],
    m: usize,
    n: usize,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let l = m + n;
    let row = |a: usize| &net[a * (n + 1)..(a + 1) * (n + 1)];
    // Row i of the triangular net, as rows of constant i: b_{i,j,l−i−j}, j = 0, …, l − i.
    let by_i: Vec<Vec<Point<S, D>>> = (0..=l)
        .map(|i| {
            let first = i.saturating_sub(n);
            let last = i.min(m);
            let weights = row_weights(m, n, i, first, last);
            let mut sum: Vec<Point<S, D>> = Vec::new();
            for (a, weight) in (first..=last).zip(&weights) {
                let e = i - a;
                if !sum.is_empty() {
                    sum = elevate_counted(&sum, counter);
                }
                let piece = &row(a)[..=n - e];
                if sum.is_empty() {
                    sum = vec![Point::zero(); piece.len()];
                }
                for (s, c) in sum.iter_mut().zip(piece) {
                    *s += &(c.clone() * weight);
                    counter.arithmetic_operation();
                }
            }
            for _ in last..m {
                sum = elevate_counted(&sum, counter);
            }
            sum
        })
        .collect();
    // The storage order has rows of constant k = l − i − j: b_{i,j,k} is entry j of row i.
    let mut out = Vec::with_capacity((l + 1) * (l + 2) / 2);
    for k in 0..=l {
        for j in 0..=l - k {
            out.push(by_i[l - k - j][j].clone());
        }
    }
    out
}

/// The weights C(m, a) C(n, i − a)/C(l, i) for a = first, …, last (a hypergeometric
/// distribution in a, summing to one): built from their ratios outwards from the largest
/// one and divided by their sum, as Zhou's formula is for curves, so that no binomial
/// coefficient is formed and none overflows `f64` however large the degrees.
fn row_weights<S: Scalar>(m: usize, n: usize, i: usize, first: usize, last: usize) -> Vec<S> {
    // w(a + 1)/w(a) = (m − a)(i − a) / ((a + 1)(n − i + a + 1)); degrees are at most
    // MAX_DEGREE = 2^16, so the products fit in an i64.
    let ratio = |a: usize| ((m - a) * (i - a), (a + 1) * (n + a + 1 - i));
    let mode = ((i + 1) * (m + 1) / (m + n + 2)).clamp(first, last);
    let mut w = vec![S::zero(); last - first + 1];
    w[mode - first] = S::one();
    for a in mode..last {
        let (num, den) = ratio(a);
        w[a + 1 - first] = w[a - first].clone() * S::from_ratio(num as i64, den as i64);
    }
    for a in (first..mode).rev() {
        let (num, den) = ratio(a);
        w[a - first] = w[a + 1 - first].clone() * S::from_ratio(den as i64, num as i64);
    }
    let total = w.iter().fold(S::zero(), |t, x| t + x);
    w.into_iter().map(|x| x / &total).collect()
}

/// The polygon elevated by one degree, one counted operation per new point.
fn elevate_counted<S: Scalar, const D: usize, C: Counter>(
    b: &[Point<S, D>],
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let out = elevated_polygon(b);
    for _ in 0..out.len() {
        counter.arithmetic_operation();
    }
    out
}
