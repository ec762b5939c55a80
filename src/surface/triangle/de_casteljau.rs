//! The de Casteljau algorithm on a triangular net, and its one level, the kernel every
//! triangular algorithm runs (evaluation, the blossom, derivatives, subdivision).
//!
//! The problem: the point b(x) = Σ b_{ijk} B^n_{ijk}(u, v, w) of a patch at the point x with
//! barycentric coordinates (u, v, w). The idea: the recurrence of the Bernstein polynomials
//! B^n_i = u B^{n−1}_{i−e₀} + v B^{n−1}_{i−e₁} + w B^{n−1}_{i−e₂} turns the sum of degree n
//! into one of degree n − 1 with the points b_j = u b_{j+e₀} + v b_{j+e₁} + w b_{j+e₂}; n such
//! levels leave one point, b(x) [PPB, §10.4]. The intermediate points form a tetrahedral
//! scheme; for x inside the triangle every step is a convex combination.
//!
//! A level with different weights per level is the blossom [PPB, §11.2, eq. (1)]; with
//! weights summing to zero it takes differences, the directional derivatives of
//! [PPB, §10.5]. The level works in place on the storage order (rows of constant k): the
//! point j of row k of the new net is written where the old net's point j of row k stood,
//! k places earlier, after every old point it still needs was read.
//!
//! # Complexity
//!
//! Θ(n³D) time: n(n + 1)(n + 2)/6 combinations of three points; Θ(n²D) space for a copy of
//! the net.
//!
//! Invariants the tests check (exactly on rationals): equal to the Bernstein sum; the count.

use super::barycentric::Barycentric;
use super::patch::{row_offset, TriangularPatch};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Point, Scalar};

/// The triangular de Casteljau algorithm, declared.
pub(crate) const DE_CASTELJAU: Declaration = Declaration {
    problem: "triangular-patch",
    name: "de-casteljau",
    function: "surface::TriangularPatch::de_casteljau",
    file: "src/surface/triangle/de_casteljau.rs",
    summary: "n levels of three-point affine combinations on the triangular net",
    time: "Θ(n³D)",
    space: "Θ(n²D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)(n + 2)/6 affine combinations of three points",
    source: "[PPB, §10.4]",
    claims: &[on(
        "random-degree",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> TriangularPatch<S, D> {
    /// The point b(x) by the de Casteljau algorithm. See [`TriangularPatch::de_casteljau_with`].
    ///
    /// With `f64` a point beyond the double range comes out with infinite coordinates (exact
    /// scalars never overflow).
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    ///
    /// // Degree 1: the affine map u·b100 + v·b010 + w·b001.
    /// let b = TriangularPatch::new(vec![Point::new([3.0]), Point::new([5.0]), Point::new([7.0])])?;
    /// assert_eq!(b.de_casteljau(&Barycentric::new(0.5, 0.25, 0.25)?), Point::new([4.5]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_casteljau(&self, at: &Barycentric<S>) -> Point<S, D> {
        self.de_casteljau_with(at, &mut NoCount)
    }

    /// The point b(x) by the de Casteljau algorithm, counting its affine combinations.
    ///
    /// Idea: level m replaces the net of degree m by the net of degree m − 1 whose point j is
    /// u b_{j+e₀} + v b_{j+e₁} + w b_{j+e₂}; after n levels one point is left, b(x)
    /// [PPB, §10.4].
    ///
    /// # Complexity
    ///
    /// Θ(n³D) time, Θ(n²D) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination of
    /// three points: level m makes m(m + 1)/2 of them, exactly n(n + 1)(n + 2)/6 in all.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{Barycentric, TriangularPatch};
    /// use compgeo::surface::triangle::multi_indices;
    ///
    /// let n = 4;
    /// let points = multi_indices(n).map(|[i, j, _]| Point::new([i as f64, j as f64])).collect();
    /// let b = TriangularPatch::new(points)?; // the linear map (u, v, w) ↦ n·(u, v)
    /// let mut c = Counts::default();
    /// let x = b.de_casteljau_with(&Barycentric::new(0.25, 0.5, 0.25)?, &mut c);
    /// assert_eq!(x, Point::new([1.0, 2.0]));
    /// assert_eq!(c.arithmetic_operations, 4 * 5 * 6 / 6);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn de_casteljau_with<C: Counter>(
        &self,
        at: &Barycentric<S>,
        counter: &mut C,
    ) -> Point<S, D> {
        let mut q = self.points().to_vec();
        for m in (1..=self.degree()).rev() {
            level(&mut q, m, at.coords(), counter);
        }
        q.swap_remove(0)
    }
}

/// `a·x + b·y + c·z` for the weights [a, b, c].
#[inline]
pub(super) fn combine3<S: Scalar, const D: usize>(
    x: &Point<S, D>,
    y: &Point<S, D>,
    z: &Point<S, D>,
    [a, b, c]: &[S; 3],
) -> Point<S, D> {
    Point::new(std::array::from_fn(|t| {
        a.clone() * &x[t] + b.clone() * &y[t] + c.clone() * &z[t]
    }))
}

/// One level of the scheme: the net of degree m in `q[..(m + 1)(m + 2)/2]` (storage order)
/// becomes the net of degree m − 1 in `q[..m(m + 1)/2]`, point j of row k being
/// a·b_{i+1,j,k} + b·b_{i,j+1,k} + c·b_{i,j,k+1} for the weights [a, b, c]. One counted
/// operation per new point, m(m + 1)/2.
pub(super) fn level<S: Scalar, const D: usize, C: Counter>(
    q: &mut [Point<S, D>],
    m: usize,
    weights: &[S; 3],
    counter: &mut C,
) {
    let mut out = 0;
    for k in 0..m {
        let (row, next) = (row_offset(m, k), row_offset(m, k + 1));
        for j in 0..m - k {
            // Old row k holds b_{i+1,j,k} at j and b_{i,j+1,k} at j + 1, old row k + 1 holds
            // b_{i,j,k+1} at j; `out` is at most `row + j`, read just now, and every later read
            // is beyond it.
            let p = combine3(&q[row + j], &q[row + j + 1], &q[next + j], weights);
            q[out] = p;
            out += 1;
            counter.arithmetic_operation();
        }
    }
}

/// The three sub-nets of the de Casteljau scheme at `weights` [PPB, §11.3]: for the point x
/// with those barycentric coordinates, the nets over (x, q, r), (p, x, r) and (p, q, x), the
/// triangle p q r with vertex t replaced by x. The level-l point with i = 0 is b[x^l q^j r^k]
/// (net 0), with j = 0 is b[p^i x^l r^k] (net 1), with k = 0 is b[p^i q^j x^l] (net 2).
/// Counts exactly n(n + 1)(n + 2)/6 combinations.
pub(super) fn sub_nets<S: Scalar, const D: usize, C: Counter>(
    points: &[Point<S, D>],
    n: usize,
    weights: &[S; 3],
    counter: &mut C,
) -> [Vec<Point<S, D>>; 3] {
    let size = points.len();
    let mut nets: [Vec<Point<S, D>>; 3] = std::array::from_fn(|_| vec![Point::zero(); size]);
    // Every point of every sub-net is written once, at its level.
    let mut q = points.to_vec();
    for l in 0..=n {
        let m = n - l;
        for k in 0..=m {
            let row = row_offset(m, k);
            // Net 0: (l, j, k) with j = m − k, the last point of the row.
            nets[0][row_offset(n, k) + (m - k)] = q[row + m - k].clone();
            // Net 1: (i, l, k) with i = m − k, the first point of the row.
            nets[1][row_offset(n, k) + l] = q[row].clone();
        }
        // Net 2: (i, j, l), the whole first row, j = 0, …, m.
        let start = row_offset(n, l);
        nets[2][start..=start + m].clone_from_slice(&q[..=m]);
        if m > 0 {
            level(&mut q, m, weights, counter);
        }
    }
    nets
}
