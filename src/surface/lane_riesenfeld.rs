//! Subdivision of a regular quadrilateral net: the tensor Lane–Riesenfeld algorithm of
//! bidegree (p, q), and the limit points it converges to.
//!
//! The problem: a net c_{i,j} is the control net of the uniform tensor B-spline surface
//! s(u, v) = Σ c_{i,j} N^p(u − i) N^q(v − j) on the integers; write the same surface on the
//! knots 2^{−k}ℤ in both parameters. The idea [PPB, §15.1]: the tensor-product scheme of two
//! curve schemes A and B is C_k = (Aᵗ)^k C B^k, every column subdivided by A and every row
//! by B. For the Lane–Riesenfeld matrices S_d = D·M^d [PPB, §8.3] one round is the
//! **refinement** 𝒟 (every point quadrupled, every row and column doubled) followed by
//! averaging passes 𝒜 (the centroid of each 2 × 2 block), M_n = 𝒜^n 𝒟 for bidegree (n, n)
//! [PPB, §15.1]; with bidegree (p, q), p passes in u and q in v. Since the row operator B
//! and the column operator A act on different indices they commute, so the k rounds are
//! run as k rounds of the curve algorithm
//! ([`lane_riesenfeld_with`](crate::spline::subdivision::lane_riesenfeld_with)) on every
//! row, then k rounds on every column of the result: the curve code, not a second copy of
//! it. The limit points are likewise the curve limit stencil
//! ([`limit_points_with`](crate::spline::subdivision::limit_points_with)) on the rows, then
//! on the columns: vertex (i, j) tends to s at the centre of its B-spline's support, e.g.
//! the tensor stencil (1, 4, 1)ᵗ(1, 4, 1)/36 for bicubics [PPB, §8.1, §15.1, Obs. 1].
//!
//! Bidegree (2, 2) is the regular case of Doo–Sabin's scheme and (3, 3) the regular case of
//! Catmull–Clark's [PPB, §16.1]; the masks of (2, 2) are (9, 3, 3, 1)/16 [PPB, §15.2, Obs. 3].
//!
//! # Boundaries
//!
//! Each direction is open or closed ([`Topology`]), as for curves: closed is periodic (a
//! cylinder if one direction is closed, a torus if both), and an open direction of m points
//! is the uniform spline on the knots 0, …, m + d with domain [d, m], which keeps after a
//! round the 2m − d control points whose B-splines meet the domain (the surface is
//! unchanged; its boundary rows move inwards). After k rounds an open direction of m points
//! has 2^k(m − d) + d, a closed one 2^k·m.
//!
//! # Complexity
//!
//! For an M × N net giving M′ × N′: Θ(q·M·N′ + p·M′·N′) = Θ((p + q)·M′N′) time and
//! Θ(M′N′·D) space.
//!
//! Invariants the tests check (exactly, on rationals): k rounds give the control net of the
//! same surface on the 2^k-refined knots (the [`BSplineSurface`] refined by knot insertion
//! and restricted to the B-splines meeting the domain, in both topologies), bidegree (2, 2)
//! has the masks (9, 3, 3, 1)/16, the limit points are the surface's points, and the counts
//! below.
//!
//! [`BSplineSurface`]: crate::surface::BSplineSurface

use super::net::ControlNet;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::subdivision::{lane_riesenfeld_with, limit_points_with, Topology};
use crate::spline::Scalar;
use crate::{limits, Error, Result};

/// The tensor Lane–Riesenfeld algorithm, declared.
pub(crate) const NET_LANE_RIESENFELD: Declaration = Declaration {
    problem: "subdivision-surface",
    name: "tensor-lane-riesenfeld",
    function: "surface::ControlNet::lane_riesenfeld",
    file: "src/surface/lane_riesenfeld.rs",
    summary: "k rounds of uniform B-spline subdivision of bidegree (p, q) on a regular net: the curve Lane–Riesenfeld algorithm on every row, then on every column",
    time: "Θ((p + q)·M′N′), M′N′ ≤ MN·4^k the output size",
    space: "Θ(M′N′·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "the curve algorithm's midpoints on the M rows, then on the N′ columns: 2(2^k − 1)(qMN + pMN·2^k) on a torus",
    source: "[PPB, §15.1, §8.2–8.4]",
    claims: &[on(
        "random-torus",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The limit points of a regular net, declared.
pub(crate) const NET_LIMIT_POINTS: Declaration = Declaration {
    problem: "subdivision-surface",
    name: "tensor-limit-points",
    function: "surface::ControlNet::limit_points",
    file: "src/surface/lane_riesenfeld.rs",
    summary: "where each vertex of a regular net goes under tensor Lane–Riesenfeld subdivision: the curve limit stencil on the rows, then on the columns",
    time: "Θ(p² + q² + (p + q)·MN·D)",
    space: "Θ(MN·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "the curve's stencil terms on the rows, then on the columns: (2⌊q/2⌋ + 1)MN + (2⌊p/2⌋ + 1)MN on a torus",
    source: "[PPB, §8.1, §15.1]",
    claims: &[on(
        "random-torus",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar, const D: usize> ControlNet<S, D> {
    /// `rounds` rounds of the tensor Lane–Riesenfeld algorithm of bidegree (p, q): the
    /// control net of the same uniform B-spline surface on the knots 2^{−k}ℤ in u and v. See
    /// [`ControlNet::lane_riesenfeld_with`].
    ///
    /// `topology` is (u, v): whether the columns (along u, the index i) and the rows (along
    /// v, the index j) are open or closed.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"bidegree"` for a degree 0;
    /// [`Error::TooFew`] for an open direction of at most d points (`"net rows"` for fewer
    /// than p + 1 rows, `"net columns"` for fewer than q + 1 columns) or a closed one of
    /// fewer than 3; [`Error::LimitExceeded`] for a degree past
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE), or an output past
    /// [`MAX_SUBDIVISION_POINTS`](crate::limits::MAX_SUBDIVISION_POINTS) rows or columns or
    /// [`MAX_POINTS`](crate::limits::MAX_POINTS) points, before anything is computed;
    /// [`Error::Overflow`] if, with `f64`, a point overflows.
    ///
    /// # Complexity
    ///
    /// Θ((p + q)·M′N′), M′N′ ≤ MN·4^k the output size; Θ(M′N′·D) space.
    ///
    /// ```
    /// use compgeo::spline::subdivision::Topology;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::ControlNet;
    ///
    /// // Biquadratic on a 3 × 3 open net: one round keeps 2·3 − 2 = 4 rows and columns, and
    /// // the new point (1, 1), nearest c₁₁, is (9c₁₁ + 3c₁₀ + 3c₀₁ + c₀₀)/16.
    /// let net = ControlNet::new((0..3).map(|i| (0..3).map(|j| {
    ///     Point::new([16.0 * i as f64, 16.0 * j as f64, if (i, j) == (1, 1) { 16.0 } else { 0.0 }])
    /// }).collect()).collect())?;
    /// let r = net.lane_riesenfeld((2, 2), 1, (Topology::Open, Topology::Open))?;
    /// assert_eq!((r.rows(), r.columns()), (4, 4));
    /// assert_eq!(r.get(1, 1), &Point::new([12.0, 12.0, 9.0]));
    /// assert_eq!(r.get(0, 0), &Point::new([4.0, 4.0, 1.0])); // (9c₀₀ + 3c₀₁ + 3c₁₀ + c₁₁)/16
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn lane_riesenfeld(
        &self,
        bidegree: (usize, usize),
        rounds: usize,
        topology: (Topology, Topology),
    ) -> Result<Self> {
        self.lane_riesenfeld_with(bidegree, rounds, topology, &mut NoCount)
    }

    /// [`ControlNet::lane_riesenfeld`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per midpoint.
    ///
    /// Idea [PPB, §15.1]: C_k = (Aᵗ)^k C B^k with A and B the curve Lane–Riesenfeld
    /// matrices of degrees p and q; B^k is k rounds of the curve algorithm on every row,
    /// then (Aᵗ)^k k rounds on every column of that.
    ///
    /// # Errors
    ///
    /// As [`ControlNet::lane_riesenfeld`].
    ///
    /// # Complexity
    ///
    /// Θ((p + q)·M′N′), M′N′ ≤ MN·4^k the output size; Θ(M′N′·D) space.
    ///
    /// # Counts
    ///
    /// Those of the curve algorithm: on each of the M rows, then on each of the N′ columns.
    /// On a torus of M × N points that is 2q·N(2^k − 1) per row and 2p·M(2^k − 1) per
    /// column, 2(2^k − 1)(qMN + pMN·2^k) in all.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::subdivision::Topology;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::ControlNet;
    ///
    /// let net = ControlNet::from_rows(4, 5, (0..20).map(|k| Point::new([k as f64, 0.0])).collect())?;
    /// let mut c = Counts::default();
    /// let torus = (Topology::Closed, Topology::Closed);
    /// let r = net.lane_riesenfeld_with((3, 2), 2, torus, &mut c)?;
    /// assert_eq!((r.rows(), r.columns()), (16, 20));
    /// assert_eq!(c.arithmetic_operations, 2 * 3 * (2 * 20 + 3 * 20 * 4));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn lane_riesenfeld_with<C: Counter>(
        &self,
        (p, q): (usize, usize),
        rounds: usize,
        (tu, tv): (Topology, Topology),
        counter: &mut C,
    ) -> Result<Self> {
        let rows = refined_side(self.rows(), p, rounds, tu, "net rows")?;
        let columns = refined_side(self.columns(), q, rounds, tv, "net columns")?;
        limits::POINTS.check(rows as u128 * columns as u128)?;
        // B^k: every row to `columns` points.
        let mut refined_rows = Vec::with_capacity(self.rows() * columns);
        for i in 0..self.rows() {
            refined_rows.extend(lane_riesenfeld_with(self.row(i), q, rounds, tv, counter)?);
        }
        let half = ControlNet::from_rows(self.rows(), columns, refined_rows)?;
        // (Aᵗ)^k: every column of that to `rows` points, kept as the rows of the transpose.
        let mut refined_columns = Vec::with_capacity(rows * columns);
        for j in 0..columns {
            refined_columns.extend(lane_riesenfeld_with(
                &half.column(j),
                p,
                rounds,
                tu,
                counter,
            )?);
        }
        Ok(ControlNet::from_rows(columns, rows, refined_columns)?.transposed())
    }

    /// The limit points of tensor Lane–Riesenfeld subdivision of bidegree (p, q): where each
    /// vertex goes as the rounds continue, the point of the uniform B-spline surface at the
    /// centre of the vertex's B-spline. See [`ControlNet::limit_points_with`].
    ///
    /// A closed direction keeps all its points; an open one of m points keeps the vertices
    /// ⌊d/2⌋, …, m − 1 − ⌊d/2⌋, whose stencils lie inside the net (as
    /// [`limit_points`](crate::spline::subdivision::limit_points) for curves).
    ///
    /// # Errors
    ///
    /// As [`ControlNet::lane_riesenfeld`].
    ///
    /// # Complexity
    ///
    /// Θ(p² + q² + (p + q)·MN·D) time, Θ(MN·D) space.
    ///
    /// ```
    /// use compgeo::spline::subdivision::Topology;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::ControlNet;
    ///
    /// // Bicubic: the stencil (1, 4, 1)ᵗ(1, 4, 1)/36 around each inner vertex; an open 4 × 4
    /// // net keeps the limit points of its 2 × 2 inner vertices.
    /// let net = ControlNet::new((0..4).map(|i| (0..4).map(|j| {
    ///     Point::new([if (i, j) == (1, 1) { 36.0 } else { 0.0 }])
    /// }).collect()).collect())?;
    /// let l = net.limit_points((3, 3), (Topology::Open, Topology::Open))?;
    /// assert_eq!((l.rows(), l.columns()), (2, 2));
    /// assert_eq!((l.get(0, 0), l.get(0, 1), l.get(1, 1)), (&Point::new([16.0]), &Point::new([4.0]), &Point::new([1.0])));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn limit_points(
        &self,
        bidegree: (usize, usize),
        topology: (Topology, Topology),
    ) -> Result<Self> {
        self.limit_points_with(bidegree, topology, &mut NoCount)
    }

    /// [`ControlNet::limit_points`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per stencil term.
    ///
    /// Idea [PPB, §8.1, §15.1]: the limit of a tensor-product scheme is the tensor product of
    /// the curve limits, so the curve stencil runs on every row, then on every column of the
    /// result.
    ///
    /// # Errors
    ///
    /// As [`ControlNet::lane_riesenfeld`].
    ///
    /// # Complexity
    ///
    /// Θ(p² + q² + (p + q)·MN·D) time, Θ(MN·D) space.
    ///
    /// # Counts
    ///
    /// Those of the curve's limit points on each of the M rows, then on each of the N″
    /// columns left: (2⌊q/2⌋ + 1)·M·N + (2⌊p/2⌋ + 1)·M·N on a torus.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::subdivision::Topology;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::ControlNet;
    ///
    /// let net = ControlNet::from_rows(4, 5, (0..20).map(|k| Point::new([k as f64])).collect())?;
    /// let mut c = Counts::default();
    /// net.limit_points_with((3, 2), (Topology::Closed, Topology::Closed), &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 3 * 20 + 3 * 20);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn limit_points_with<C: Counter>(
        &self,
        (p, q): (usize, usize),
        (tu, tv): (Topology, Topology),
        counter: &mut C,
    ) -> Result<Self> {
        refined_side(self.rows(), p, 0, tu, "net rows")?;
        refined_side(self.columns(), q, 0, tv, "net columns")?;
        let kept = |m: usize, d: usize, t: Topology| match t {
            Topology::Closed => m,
            Topology::Open => m - 2 * (d / 2),
        };
        let (rows, columns) = (kept(self.rows(), p, tu), kept(self.columns(), q, tv));
        let mut along_v = Vec::with_capacity(self.rows() * columns);
        for i in 0..self.rows() {
            along_v.extend(limit_points_with(self.row(i), q, tv, counter)?);
        }
        let half = ControlNet::from_rows(self.rows(), columns, along_v)?;
        let mut along_u = Vec::with_capacity(rows * columns);
        for j in 0..columns {
            along_u.extend(limit_points_with(&half.column(j), p, tu, counter)?);
        }
        Ok(ControlNet::from_rows(columns, rows, along_u)?.transposed())
    }
}

/// The number of points of one direction after `rounds` rounds of degree `degree` on `m`
/// points, with the input checked as the curve code checks a polygon (degree at least 1 and
/// at most [`MAX_DEGREE`](crate::limits::MAX_DEGREE), enough points) but with the net's
/// names, and the output against
/// [`MAX_SUBDIVISION_POINTS`](crate::limits::MAX_SUBDIVISION_POINTS).
fn refined_side(
    m: usize,
    degree: usize,
    rounds: usize,
    topology: Topology,
    what: &'static str,
) -> Result<usize> {
    if degree == 0 {
        return Err(Error::InvalidParameter {
            name: "bidegree",
            reason: format!(
                "the degree of the {} must be at least 1 (degree 0 only doubles the points)",
                if what == "net rows" {
                    "columns (u)"
                } else {
                    "rows (v)"
                }
            ),
        });
    }
    limits::DEGREE.check(degree as u128)?;
    let (needed, d) = match topology {
        Topology::Open => (degree + 1, degree as u128),
        Topology::Closed => (3, 0),
    };
    if m < needed {
        return Err(Error::TooFew {
            what,
            needed,
            got: m,
        });
    }
    crate::spline::subdivision::output_size(m, rounds, |x| 2 * x - d)
}
