//! Lagrange interpolation: the [`LagrangeForm`] curve, evaluated through the Lagrange basis
//! or by Aitken's algorithm (repeated linear interpolation, the interpolation analogue of de
//! Casteljau's).
//!
//! The problem: the polynomial of degree at most n through n + 1 points at distinct nodes,
//! with the data themselves as coefficients. The idea: the Lagrange basis
//! `L_iⁿ(u) = ∏_{j≠i} (u − u_j)/(u_i − u_j)` is 1 at its own node and 0 at the others, so
//! the interpolant is `Σ p_i L_iⁿ(u)`; the basis is built by the recurrence (1) of the course,
//! and Aitken's scheme `p_iᵏ⁺¹ = α_{i,n−k} p_iᵏ + (1 − α_{i,n−k}) p_{n−k}ᵏ` with
//! `α_{ik} = (u − u_k)/(u_i − u_k)` reaches the same value by affine combinations.
//!
//! Follows [PPB, §4.2] (the basis, its recurrence (1), Aitken's scheme of Obs. 4) and
//! [RD, §3.1] ("Lagrange").
//!
//! # Complexity
//!
//! Θ(n log n + nD) to build (the distinctness check), Θ(n² + nD) per evaluation through the
//! basis and Θ(n²D) by Aitken's scheme, for n + 1 nodes in R^D.

use super::newton::{newton_unchecked, NewtonForm};
use super::polynomial::{nested_to_bezier, Polynomial};
use super::validate::{
    check_degree, check_distinct, check_distinct_with, check_finite_nodes, check_nodes_and_points,
};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::Reparametrised;
use crate::spline::curve::{check_interval, Curve, CurveDerivative, Domain, Subsegment};
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// Building the Lagrange form, declared: its name, bounds, counts, source and claims.
pub(crate) const LAGRANGE: Declaration = Declaration {
    problem: "interpolate",
    name: "lagrange",
    function: "spline::lagrange",
    file: "src/spline/interpolate/lagrange.rs",
    summary: "the interpolating polynomial in the Lagrange basis",
    time: "Θ(n log n + nD)",
    space: "Θ(nD)",
    operation: Some(Operation::Comparisons),
    counts: "the comparisons of the distinctness check: a sort of the nodes, then n",
    source: "[PPB, §4.2]",
    claims: &[on("random-nodes", Bound::NLogN, Operation::Comparisons)],
};

/// Aitken's scheme, declared: its name, bounds, counts, source and claims.
pub(crate) const AITKEN: Declaration = Declaration {
    problem: "interpolate",
    name: "aitken",
    function: "spline::LagrangeForm::aitken",
    file: "src/spline/interpolate/lagrange.rs",
    summary: "the interpolating polynomial's value by Aitken's scheme",
    time: "Θ(n²D)",
    space: "Θ(nD)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)/2 affine combinations for n + 1 nodes",
    source: "[PPB, §4.2]",
    claims: &[on(
        "random-nodes",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

/// The interpolating polynomial in Lagrange form: distinct nodes `u_0, …, u_n` and the points
/// `p_i` they carry, `p(u) = Σ p_i L_iⁿ(u)`. Built by [`lagrange`]; defined for every real u
/// ([`Domain::Real`]).
///
/// ```
/// use compgeo::spline::{lagrange, Curve, Point};
///
/// let nodes = [0.0, 1.0, 3.0];
/// let pts = [Point::new([0.0, 1.0]), Point::new([1.0, 2.0]), Point::new([9.0, 4.0])];
/// // The data are (u², u + 1) sampled at the nodes.
/// let p = lagrange(&nodes, &pts)?;
/// let v = p.eval(&2.0)?;
/// assert!((v[0] - 4.0).abs() < 1e-12 && (v[1] - 3.0).abs() < 1e-12);
/// let a = p.aitken(&2.0)?;
/// assert!((a[0] - 4.0).abs() < 1e-12 && (a[1] - 3.0).abs() < 1e-12);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct LagrangeForm<S, const D: usize> {
    nodes: Vec<S>,
    points: Vec<Point<S, D>>,
}

impl<S: Scalar, const D: usize> LagrangeForm<S, D> {
    /// The distinct nodes `u_0, …, u_n`, in the caller's order.
    pub fn nodes(&self) -> &[S] {
        &self.nodes
    }

    /// The interpolated points `p_0, …, p_n`.
    pub fn points(&self) -> &[Point<S, D>] {
        &self.points
    }

    /// The values `L_0ⁿ(u), …, L_nⁿ(u)` of the Lagrange basis of the nodes at `u`; see
    /// [`lagrange_basis`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `u` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²) time, Θ(n) space.
    pub fn basis(&self, u: &S) -> Result<Vec<S>> {
        validate_parameter(u, "u")?;
        Ok(basis_unchecked(&self.nodes, u))
    }

    /// The value at `u` by Aitken's algorithm: repeated linear interpolation between
    /// interpolants of fewer points.
    ///
    /// The idea ([PPB, §4.2, Obs. 4]): `p_iᵏ(u)` interpolates `p_i` and the last `k` points
    /// `p_n, ..., p_{n−k+1}`; one step joins `p_iᵏ` and `p_{n−k}ᵏ`, which share `k − 1` of
    /// their points, by the affine combination with the local parameter `α_{i,n−k}`. After
    /// `n` steps `p_0ⁿ(u)` is the value of the interpolant. It is the triangular scheme of de
    /// Casteljau with nodes instead of the fixed interval [0, 1].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `u` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time and Θ(nD) auxiliary space.
    pub fn aitken(&self, u: &S) -> Result<Point<S, D>> {
        self.aitken_with(u, &mut NoCount)
    }

    /// [`LagrangeForm::aitken`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination: step
    /// k makes n − k of them, so exactly n(n + 1)/2 for n + 1 nodes.
    ///
    /// # Errors
    ///
    /// As [`LagrangeForm::aitken`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time and Θ(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{lagrange, Point};
    ///
    /// let p = lagrange(&[0.0, 1.0, 2.0, 4.0], &[0.0, 1.0, 4.0, 16.0].map(|y| Point::new([y])))?;
    /// let mut c = Counts::default();
    /// assert!((p.aitken_with(&3.0, &mut c)?[0] - 9.0).abs() < 1e-12);
    /// assert_eq!(c.arithmetic_operations, 6); // 3 + 2 + 1
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn aitken_with<C: Counter>(&self, u: &S, counter: &mut C) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        let nodes = &self.nodes;
        let n = nodes.len() - 1;
        let mut p = self.points.clone();
        for k in 0..n {
            let last = n - k;
            for i in 0..last {
                let alpha = (u.clone() - &nodes[last]) / (nodes[i].clone() - &nodes[last]);
                p[i] = Point::lerp(&p[last], &p[i], &alpha);
                counter.arithmetic_operation();
            }
        }
        Ok(p.swap_remove(0))
    }

    /// The same polynomial in Newton form (divided differences over the nodes in their
    /// order, [PPB, §4.3]).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] (`"points"`) if, with `f64`, a divided difference
    /// overflows (nearly equal nodes).
    ///
    /// # Complexity
    ///
    /// Θ(n²D).
    pub fn to_newton(&self) -> Result<NewtonForm<S, D>> {
        newton_unchecked(&self.nodes, &self.points)
    }
}

impl<S: Scalar, const D: usize> Curve<S, D> for LagrangeForm<S, D> {
    /// [`Domain::Real`].
    fn domain(&self) -> Domain<S> {
        Domain::Real
    }

    /// `p(u) = Σ p_i L_iⁿ(u)`, with the basis of [`LagrangeForm::basis`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `u` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n² + nD) time and Θ(n) auxiliary space.
    fn eval(&self, u: &S) -> Result<Point<S, D>> {
        let mut acc = Point::zero();
        for (p, l) in self.points.iter().zip(&self.basis(u)?) {
            acc += &(p.clone() * l);
        }
        Ok(acc)
    }
}

/// The derivative of a Lagrange form is a polynomial in the power basis.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for LagrangeForm<S, D> {
    type Derivative = Polynomial<S, D>;

    /// The derivative of the Newton form's power basis expansion.
    ///
    /// # Errors
    ///
    /// As [`LagrangeForm::to_newton`], and [`Error::Overflow`] as for [`Polynomial`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D).
    fn derivative_curve(&self) -> Result<Polynomial<S, D>> {
        self.to_newton()?.derivative_curve()
    }
}

/// The piece over [a, b] is the Bézier form on [a, b], through the Newton form.
impl<S: Scalar, const D: usize> Subsegment<S, D> for LagrangeForm<S, D> {
    type Segment = Reparametrised<S, D>;

    /// # Complexity
    ///
    /// Θ(n²D).
    fn subsegment(&self, a: &S, b: &S) -> Result<Reparametrised<S, D>> {
        check_interval(&self.domain(), a, b)?;
        let newton = self.to_newton()?;
        nested_to_bezier(newton.nodes(), newton.coefficients(), a, b)
    }
}

/// The values `L_0ⁿ(u), ..., L_nⁿ(u)` of the Lagrange basis of the distinct nodes
/// `u_0, ..., u_n` at `u`.
///
/// The idea ([PPB, §4.2], recurrence (1)): start from `L_0⁰ = 1`; adding node `u_k`
/// multiplies every `L_iᵏ⁻¹` by `α_{ik} = (u − u_k)/(u_i − u_k)` and gives the new basis
/// function `L_kᵏ = Σ_i L_iᵏ⁻¹ (1 − α_{ik})`, so the values sum to one at every stage.
///
/// # Errors
///
/// [`Error::Empty`] for no nodes; [`Error::InvalidParameter`] for a non-finite or repeated
/// node, or a non-finite `u`.
///
/// # Complexity
///
/// Θ(n²) time and Θ(n) auxiliary space for `n + 1` nodes. Nothing is counted.
///
/// ```
/// use compgeo::spline::lagrange_basis;
///
/// let l = lagrange_basis(&[0.0, 1.0, 2.0], &1.0)?;
/// assert_eq!(l, vec![0.0, 1.0, 0.0]); // L_i(u_k) = δ_ik
/// let l = lagrange_basis(&[0.0, 1.0, 2.0], &0.5)?;
/// assert_eq!(l.iter().sum::<f64>(), 1.0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lagrange_basis<S: Scalar>(nodes: &[S], u: &S) -> Result<Vec<S>> {
    if nodes.is_empty() {
        return Err(Error::Empty { what: "nodes" });
    }
    check_finite_nodes(nodes, "nodes")?;
    check_distinct(nodes)?;
    validate_parameter(u, "u")?;
    Ok(basis_unchecked(nodes, u))
}

/// The polynomial of degree at most `n` through the points `p_i` at the distinct nodes
/// `u_i`, in Lagrange form: the data are validated once, and every evaluation of the
/// [`LagrangeForm`] goes through the Lagrange basis (or Aitken's scheme).
///
/// [PPB, §4.2], [RD, §3.1]: the interpolant is the combination of the Lagrange basis with the
/// data as coefficients. It is the polynomial of [`vandermonde`](super::vandermonde()) and
/// [`newton`](super::newton()), exactly with rationals.
///
/// # Errors
///
/// [`Error::Empty`] for no nodes; [`Error::InvalidParameter`] (`"points"`) if the lengths
/// differ, (`"nodes"`) for a non-finite or repeated node; [`Error::NonFinite`] for a bad
/// coordinate; [`Error::LimitExceeded`] for a degree `n` above
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
///
/// # Complexity
///
/// Θ(n log n + nD) time and Θ(nD) space for `n + 1` nodes in R^D.
///
/// ```
/// use compgeo::spline::{lagrange, Curve, Point};
///
/// let nodes = [0.0, 0.5, 2.0, 3.0];
/// let pts = [Point::new([1.0]), Point::new([2.0]), Point::new([0.0]), Point::new([5.0])];
/// let p = lagrange(&nodes, &pts)?;
/// assert!((p.aitken(&1.0)?[0] - p.eval(&1.0)?[0]).abs() < 1e-12);
/// assert_eq!(p.eval(&0.5)?, Point::new([2.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lagrange<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<LagrangeForm<S, D>> {
    lagrange_with(nodes, points, &mut NoCount)
}

/// [`lagrange`], counting the [`comparison`](Counter::comparison)s of its check that the
/// nodes are distinct: those of a sort of the n + 1 nodes (O(n log n)), then one per pair of
/// neighbours in the sorted order, n. Copying the data is not counted.
///
/// # Errors
///
/// As [`lagrange`].
///
/// # Complexity
///
/// Θ(n log n + nD) time and Θ(nD) space for `n + 1` nodes in R^D.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{lagrange_with, Point};
///
/// let mut c = Counts::default();
/// lagrange_with(&[2.0, 0.0, 1.0], &[Point::new([4.0]), Point::new([0.0]), Point::new([1.0])], &mut c)?;
/// assert!(c.comparisons >= 2 + 2 && c.comparisons <= 3 + 2); // the sort, then 2
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lagrange_with<S: Scalar, const D: usize, C: Counter>(
    nodes: &[S],
    points: &[Point<S, D>],
    counter: &mut C,
) -> Result<LagrangeForm<S, D>> {
    check_nodes_and_points(nodes, points)?;
    check_degree(nodes.len())?;
    check_distinct_with(nodes, counter)?;
    Ok(LagrangeForm {
        nodes: nodes.to_vec(),
        points: points.to_vec(),
    })
}

/// The recurrence of [`lagrange_basis`] for validated nodes and a finite `u`.
fn basis_unchecked<S: Scalar>(nodes: &[S], u: &S) -> Vec<S> {
    let mut basis = Vec::with_capacity(nodes.len());
    basis.push(S::one());
    for k in 1..nodes.len() {
        let mut last = S::zero();
        for (i, l) in basis.iter_mut().enumerate() {
            let alpha = (u.clone() - &nodes[k]) / (nodes[i].clone() - &nodes[k]);
            last += l.clone() * (S::one() - &alpha);
            *l = l.clone() * alpha;
        }
        basis.push(last);
    }
    basis
}
