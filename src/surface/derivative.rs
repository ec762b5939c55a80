//! The nets of the partial derivatives of a Bézier patch (its hodographs), the twist among
//! them.
//!
//! The problem: ∂^{r+s}c/∂u^r∂v^s as a patch of bidegree (m − r, n − s). The idea: the basis
//! is a product, so the derivative in u acts on the columns and the one in v on the rows,
//! each as for curves: the net is m!/(m − r)! · n!/(n − s)! · Δ^{r,s}c_{i,j}, with the mixed
//! differences Δ^{r,s} = Δ^{1,0}Δ^{r−1,s} = Δ^{0,1}Δ^{r,s−1} [FJ-surfaces, §6, eq. (18)],
//! [PPB, §9.6]. For r = s = 1 it is the twist, mn Δ^{1,1}c_{i,j} [FJ-surfaces, §6, eq. (24)].
//! Past the degree (r > m or s > n) the derivative is the zero patch of bidegree (0, 0).
//!
//! # Complexity
//!
//! Θ((r·m·n + s·m·n)D) time, Θ(mnD) space.
//!
//! Invariants the tests check (exactly on rationals): the net evaluates to
//! [`SurfaceDerivative::partial_at`](super::SurfaceDerivative::partial_at), and to the
//! differences of blossoms m(b[u…u, 1; v…v] − b[u…u, 0; v…v]) and the like.

use super::bezier::BezierPatch;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::difference;
use crate::spline::{falling_factorial, Point, Scalar};
use crate::Result;

/// The derivative nets, declared.
pub(crate) const DERIVATIVE_NET: Declaration = Declaration {
    problem: "bezier-patch",
    name: "derivative-net",
    function: "surface::BezierPatch::derivative_net",
    file: "src/surface/derivative.rs",
    summary: "r differences down every column, s along every row, then one scaling per point",
    time: "Θ((r·m·n + s·m·n)D)",
    space: "Θ(mnD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly (n + 1)(r(m + 1) − r(r + 1)/2) + (m − r + 1)(s(n + 1) − s(s + 1)/2) differences and (m − r + 1)(n − s + 1) scalings (r ≤ m, s ≤ n)",
    source: "[FJ-surfaces, §6], [PPB, §9.6]",
    claims: &[on(
        "random-bidegree",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> BezierPatch<S, D> {
    /// The net of ∂^{r+s}c/∂u^r∂v^s, a patch of bidegree (m − r, n − s) (the zero patch of
    /// bidegree (0, 0) if r > m or s > n). See [`BezierPatch::derivative_net_with`].
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`](crate::Error::Overflow) if, with `f64`, a point of the derivative
    /// is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ((r·m·n + s·m·n)D) time, Θ(mnD) space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet, SurfaceDerivative};
    ///
    /// // z = uv: c_u = (1, 0, v), the twist is (0, 0, 1).
    /// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    /// let s = BezierPatch::new(ControlNet::new(vec![
    ///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
    ///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
    /// ])?)?;
    /// let cu = s.derivative_net(1, 0)?;
    /// assert_eq!(cu.net().row(0), [p(1.0, 0.0, 0.0), p(1.0, 0.0, 1.0)]);
    /// assert_eq!(s.twist_net()?.net().get(0, 0), &p(0.0, 0.0, 1.0));
    /// assert_eq!(s.twist_net()?.net().get(0, 0), &s.partial_at(&0.3, &0.6, 1, 1)?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn derivative_net(&self, r: usize, s: usize) -> Result<Self> {
        self.derivative_net_with(r, s, &mut NoCount)
    }

    /// The twist net, ∂²c/∂u∂v: mn Δ^{1,1}c_{i,j} [FJ-surfaces, §6, eq. (24)]. See
    /// [`BezierPatch::derivative_net_with`].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::derivative_net`].
    ///
    /// # Complexity
    ///
    /// Θ(mnD) time and space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..3).map(|j| Point::new([(i * j) as f64])).collect()).collect();
    /// let t = BezierPatch::new(ControlNet::new(rows)?)?.twist_net()?;
    /// assert_eq!(t.net().get(1, 1), &Point::new([4.0])); // 2·2·(4 − 2 − 2 + 1)
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn twist_net(&self) -> Result<Self> {
        self.derivative_net(1, 1)
    }

    /// The net of ∂^{r+s}c/∂u^r∂v^s, counting point operations.
    ///
    /// Idea: the r-th derivative of every column's curve is m(m − 1)⋯(m − r + 1) times its
    /// r-th forward differences, and likewise along the rows; differences in the two indices
    /// commute, so take r down the columns, then s along the rows of what is left, and scale
    /// once [FJ-surfaces, §6, eq. (18)], [PPB, §9.6].
    ///
    /// # Errors
    ///
    /// As [`BezierPatch::derivative_net`].
    ///
    /// # Complexity
    ///
    /// Θ((r·m·n + s·m·n)D) time, Θ(mnD) space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per difference or scaling
    /// of a point: for r ≤ m and s ≤ n exactly (n + 1)(r(m + 1) − r(r + 1)/2) +
    /// (m − r + 1)(s(n + 1) − s(s + 1)/2) + (m − r + 1)(n − s + 1); none past the degree.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::{BezierPatch, ControlNet};
    ///
    /// let rows = (0..3).map(|i| (0..4).map(|j| Point::new([i as f64, j as f64])).collect()).collect();
    /// let s = BezierPatch::new(ControlNet::new(rows)?)?; // bidegree (2, 3)
    /// let mut c = Counts::default();
    /// let twist = s.derivative_net_with(1, 1, &mut c)?;
    /// assert_eq!(twist.bidegree(), (1, 2));
    /// assert_eq!(c.arithmetic_operations, 4 * 2 + 2 * 3 + 2 * 3);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn derivative_net_with<C: Counter>(
        &self,
        r: usize,
        s: usize,
        counter: &mut C,
    ) -> Result<Self> {
        let (m, n) = self.bidegree();
        if r > m || s > n {
            return BezierPatch::derived(1, 1, vec![Point::zero()], "derivative net");
        }
        // Columns: r rounds of differences on each.
        let mut columns: Vec<Vec<Point<S, D>>> = (0..=n).map(|j| self.net().column(j)).collect();
        for column in &mut columns {
            for _ in 0..r {
                counted_difference(column, counter);
            }
        }
        let factor = falling_factorial::<S>(m, r) * falling_factorial::<S>(n, s);
        let mut points = Vec::with_capacity((m - r + 1) * (n - s + 1));
        for i in 0..=m - r {
            let mut row: Vec<Point<S, D>> = columns.iter().map(|c| c[i].clone()).collect();
            for _ in 0..s {
                counted_difference(&mut row, counter);
            }
            points.extend(row.into_iter().map(|p| {
                counter.arithmetic_operation();
                p * &factor
            }));
        }
        BezierPatch::derived(m - r + 1, n - s + 1, points, "derivative net")
    }
}

/// One round of forward differences, one counted operation per difference.
fn counted_difference<S: Scalar, const D: usize, C: Counter>(
    q: &mut Vec<Point<S, D>>,
    counter: &mut C,
) {
    for _ in 1..q.len() {
        counter.arithmetic_operation();
    }
    difference(q);
}
