//! Polynomial interpolation in the power basis: the [`Polynomial`] curve, and the
//! interpolant through values (and derivatives) at distinct nodes by solving the Vandermonde
//! system.
//!
//! The problem: the polynomial of degree at most n through n + 1 points at distinct nodes,
//! in the basis 1, u, …, uⁿ. The idea: the interpolation conditions are the linear system
//! `B a = y` with `B_ij = u_iʲ`, whose determinant `∏_{i>j} (u_i − u_j)` is nonzero exactly
//! when the nodes are distinct; derivative data add the rows of the differentiated monomials
//! (the confluent system). It is solved by Gaussian elimination, one right-hand side per
//! coordinate.
//!
//! Follows [RD, §3.1] ("Interpolación Polinomial", "Interpolación de Hermite") and
//! [PPB, §4.1] (the interpolation matrix `C X = P`, one column per coordinate). The Lagrange
//! and Aitken forms are in `lagrange.rs`, Newton's divided differences in `newton.rs`; all
//! three give the same polynomial, which the tests check with exact rationals.
//!
//! # Complexity
//!
//! Θ(N³ + N²D) time and Θ(N² + ND) space for N conditions in R^D.

use super::linear::solve_dense_with;
use super::validate::{
    check_degree, check_dense, check_distinct, check_hermite, check_nodes_and_points, finite,
    singular,
};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::Reparametrised;
use crate::spline::curve::{check_interval, Curve, CurveDerivative, Domain, Subsegment};
use crate::spline::scalar::{falling_factorial, validate_parameter, Point, Scalar};
use crate::spline::Bezier;
use crate::{Error, Result};

/// The Vandermonde solve, declared: its name, bounds, counts, source and claims.
pub(crate) const VANDERMONDE: Declaration = Declaration {
    problem: "interpolate",
    name: "vandermonde",
    function: "spline::vandermonde",
    file: "src/spline/interpolate/polynomial.rs",
    summary: "the power-basis polynomial through distinct nodes, by elimination",
    time: "Θ(n³ + n²·D)",
    space: "Θ(n² + n·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per entry changed by elimination and per back-substitution term: exactly (N − 1)N(2N − 1)/6 + N(N − 1) + N(N + 1)/2 for N = n + 1 nodes when no entry vanishes",
    source: "[RD, §3.1]",
    claims: &[on(
        "random-nodes",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// The confluent Vandermonde solve, declared: its name, bounds, counts, source and claims.
pub(crate) const VANDERMONDE_HERMITE: Declaration = Declaration {
    problem: "interpolate",
    name: "vandermonde-hermite",
    function: "spline::vandermonde_hermite",
    file: "src/spline/interpolate/polynomial.rs",
    summary: "the polynomial with given values and derivatives, by elimination",
    time: "Θ(N³ + N²·D)",
    space: "Θ(N² + N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts:
        "as the Vandermonde solve's for N conditions, less where an entry below a pivot is zero",
    source: "[PPB, §4.4]",
    claims: &[on(
        "random-nodes",
        Bound::Cubic,
        Operation::ArithmeticOperations,
    )],
};

/// A polynomial curve `p(u) = Σ_j a_j u^j` in the power (monomial) basis, with coefficients
/// `a_j ∈ R^D`. It is defined for every real u ([`Domain::Real`]).
///
/// ```
/// use compgeo::spline::{Curve, CurveDerivative, Point, Polynomial};
///
/// // p(u) = (1, 0) + (0, 2)·u + (3, 0)·u²
/// let p = Polynomial::new(vec![Point::new([1.0, 0.0]), Point::new([0.0, 2.0]), Point::new([3.0, 0.0])]);
/// assert_eq!(p.eval(&2.0)?, Point::new([13.0, 4.0]));
/// assert_eq!(p.derivative_curve()?.eval(&2.0)?, Point::new([12.0, 2.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Polynomial<S, const D: usize> {
    coefficients: Vec<Point<S, D>>,
}

/// Interpolation data at one node: the value and the first derivatives there.
///
/// `values[0]` is `p(u)`, `values[r]` is the r-th derivative `p⁽ʳ⁾(u)`. A node with `k + 1`
/// values imposes `k + 1` conditions (the node counts `k + 1` times, [PPB, §4.4]).
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteNode<S, const D: usize> {
    /// The parameter value of the node.
    pub u: S,
    /// The value and derivatives at `u`, lowest order first; at least one.
    pub values: Vec<Point<S, D>>,
}

impl<S: Scalar, const D: usize> Polynomial<S, D> {
    /// The polynomial with coefficients `a_0, a_1, ...` (constant term first). An empty list
    /// is the zero polynomial.
    pub fn new(coefficients: Vec<Point<S, D>>) -> Self {
        Polynomial { coefficients }
    }

    /// The coefficients, constant term first.
    pub fn coefficients(&self) -> &[Point<S, D>] {
        &self.coefficients
    }

    /// The number of coefficients minus one (the degree bound; the leading coefficient may be
    /// zero). The zero polynomial with no coefficients has degree 0.
    pub fn degree(&self) -> usize {
        self.coefficients.len().saturating_sub(1)
    }
}

impl<S: Scalar, const D: usize> Curve<S, D> for Polynomial<S, D> {
    /// [`Domain::Real`].
    fn domain(&self) -> Domain<S> {
        Domain::Real
    }

    /// `p(u)` by Horner's rule: `n` multiplications and additions per coordinate.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `u` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time, O(D) auxiliary space.
    fn eval(&self, u: &S) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        let mut acc = Point::zero();
        for a in self.coefficients.iter().rev() {
            acc = acc * u + a;
        }
        Ok(acc)
    }
}

impl<S: Scalar, const D: usize> CurveDerivative<S, D> for Polynomial<S, D> {
    type Derivative = Polynomial<S, D>;

    /// The derivative `p'(u) = Σ_j j a_j u^{j−1}`.
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if, with `f64`, a coefficient `j a_j` is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(nD).
    fn derivative_curve(&self) -> Result<Self> {
        let coefficients: Vec<Point<S, D>> = self
            .coefficients
            .iter()
            .enumerate()
            .skip(1)
            .map(|(j, a)| a.clone() * S::from_i64(j as i64))
            .collect();
        if coefficients.iter().all(Point::is_finite) {
            Ok(Polynomial { coefficients })
        } else {
            Err(Error::Overflow { what: "derivative" })
        }
    }
}

/// The piece over [a, b] is the Bézier form of the polynomial on [a, b].
impl<S: Scalar, const D: usize> Subsegment<S, D> for Polynomial<S, D> {
    type Segment = Reparametrised<S, D>;

    /// # Complexity
    ///
    /// Θ(n²D) (Horner's rule in the Bernstein basis).
    fn subsegment(&self, a: &S, b: &S) -> Result<Reparametrised<S, D>> {
        check_interval(&self.domain(), a, b)?;
        let zero = Point::zero();
        let coefficients = match self.coefficients.as_slice() {
            [] => std::slice::from_ref(&zero),
            c => c,
        };
        let nodes = vec![S::zero(); coefficients.len() - 1];
        nested_to_bezier(&nodes, coefficients, a, b)
    }
}

/// The polynomial of degree at most `n` through `n + 1` points `p_i` at distinct nodes `u_i`,
/// by solving the Vandermonde system.
///
/// The idea ([RD, §3.1]): in the basis `1, u, ..., u^n` the interpolation conditions are
/// the linear system `B a = y` with `B_ij = u_i^j`; `det B = ∏_{i>j} (u_i − u_j)` is nonzero
/// exactly when the nodes are distinct. The system is solved by Gaussian elimination, one
/// right-hand side per coordinate ([PPB, §4.1]). With `f64` the elimination pivots on the
/// largest entry of each column; the Vandermonde matrix is notoriously ill-conditioned, so for
/// many nodes prefer [`newton`](super::newton()) or the rational back end.
///
/// # Errors
///
/// [`Error::Empty`] for no nodes; [`Error::InvalidParameter`] (`"points"`) if the lengths
/// differ; [`Error::NonFinite`] for a NaN or infinite coordinate; [`Error::InvalidParameter`]
/// (`"nodes"`) for a non-finite node or two equal nodes (the system is singular: a repeated
/// node needs derivative data, see [`vandermonde_hermite`]); [`Error::LimitExceeded`] for
/// more than [`MAX_DENSE_UNKNOWNS`](crate::limits::MAX_DENSE_UNKNOWNS) nodes, before the
/// matrix is allocated.
///
/// # Complexity
///
/// Θ(n³ + n²·D) time and Θ(n² + n·D) auxiliary space for `n + 1` nodes in R^D.
///
/// ```
/// use compgeo::spline::{vandermonde, Curve, Point};
///
/// // The parabola y = u² through (−1, 1), (0, 0), (2, 4).
/// let p = vandermonde(&[-1.0, 0.0, 2.0], &[Point::new([1.0]), Point::new([0.0]), Point::new([4.0])])?;
/// assert_eq!(p.eval(&3.0)?, Point::new([9.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn vandermonde<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<Polynomial<S, D>> {
    vandermonde_with(nodes, points, &mut NoCount)
}

/// [`vandermonde`], counting the elimination's arithmetic: one
/// [`arithmetic_operation`](Counter::arithmetic_operation) per entry a row operation changes
/// (of the matrix and of the right-hand side) and per term of the back substitution,
/// divisions included. For N = n + 1 nodes and no entry below a pivot that vanishes (always
/// so with exact scalars, where the first nonzero entry is the pivot), that is exactly
/// Σₖ₌₀ᴺ⁻¹ k(k + 2) + N(N + 1)/2 = (N − 1)N(2N − 1)/6 + N(N − 1) + N(N + 1)/2. Building the
/// matrix's powers is scalar bookkeeping, not counted.
///
/// # Errors
///
/// As [`vandermonde`].
///
/// # Complexity
///
/// Θ(n³ + n²·D) time and Θ(n² + n·D) auxiliary space for `n + 1` nodes in R^D.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{vandermonde_with, Point};
///
/// let mut c = Counts::default();
/// vandermonde_with(&[-1.0, 0.0, 2.0], &[Point::new([1.0]), Point::new([0.0]), Point::new([4.0])], &mut c)?;
/// // N = 3: 2·4 + 1·3 entries changed by elimination, then 1 + 2 + 3 back-substitution terms.
/// assert_eq!(c.arithmetic_operations, 11 + 6);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn vandermonde_with<S: Scalar, const D: usize, C: Counter>(
    nodes: &[S],
    points: &[Point<S, D>],
    counter: &mut C,
) -> Result<Polynomial<S, D>> {
    check_nodes_and_points(nodes, points)?;
    check_dense(nodes.len())?;
    check_distinct(nodes)?;
    let n = nodes.len();
    let matrix = nodes
        .iter()
        .map(|u| {
            let mut row = Vec::with_capacity(n);
            let mut power = S::one();
            for _ in 0..n {
                row.push(power.clone());
                power = power * u;
            }
            row
        })
        .collect();
    let coefficients = solve_dense_with(matrix, points.to_vec(), counter)
        .ok_or_else(|| singular("nodes", "the Vandermonde matrix is singular"))?;
    Ok(Polynomial::new(finite(coefficients)?))
}

/// The Hermite interpolating polynomial through values and derivatives, by solving the
/// confluent Vandermonde system.
///
/// [RD, §3.1] ("Interpolación de Hermite"): a node with value and `k` derivatives adds the
/// rows `d^r/du^r u^j = j!/(j−r)! u^{j−r}`, `r = 0..=k`; with `N` conditions in all the
/// polynomial has degree `N − 1` and is unique when the nodes are distinct.
///
/// # Errors
///
/// [`Error::Empty`] for no nodes or a node without values; [`Error::NonFinite`] for a
/// non-finite value (the index counts values over all nodes in order);
/// [`Error::InvalidParameter`] (`"nodes"`) for a non-finite or repeated node;
/// [`Error::LimitExceeded`] for more than
/// [`MAX_DENSE_UNKNOWNS`](crate::limits::MAX_DENSE_UNKNOWNS) conditions, before the matrix is
/// allocated.
///
/// # Complexity
///
/// Θ(N³ + N²·D) time and Θ(N² + N·D) auxiliary space for `N` conditions in R^D.
///
/// ```
/// use compgeo::spline::{vandermonde_hermite, Curve, HermiteNode, Point};
///
/// // u³ from its value and slope at 0 and 1: 0, 0 and 1, 3.
/// let data = [
///     HermiteNode { u: 0.0, values: vec![Point::new([0.0]), Point::new([0.0])] },
///     HermiteNode { u: 1.0, values: vec![Point::new([1.0]), Point::new([3.0])] },
/// ];
/// let p = vandermonde_hermite(&data)?;
/// assert_eq!(p.eval(&2.0)?, Point::new([8.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn vandermonde_hermite<S: Scalar, const D: usize>(
    data: &[HermiteNode<S, D>],
) -> Result<Polynomial<S, D>> {
    vandermonde_hermite_with(data, &mut NoCount)
}

/// [`vandermonde_hermite`], counting the elimination's arithmetic as
/// [`vandermonde_with`] does: at most (N − 1)N(2N − 1)/6 + N(N − 1) + N(N + 1)/2 for N
/// conditions (fewer where a derivative row's zeros below a pivot are skipped).
///
/// # Errors
///
/// As [`vandermonde_hermite`].
///
/// # Complexity
///
/// Θ(N³ + N²·D) time and Θ(N² + N·D) auxiliary space for `N` conditions in R^D.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{vandermonde_hermite_with, HermiteNode, Point};
///
/// let data = [
///     HermiteNode { u: 0.0, values: vec![Point::new([0.0]), Point::new([0.0])] },
///     HermiteNode { u: 1.0, values: vec![Point::new([1.0]), Point::new([3.0])] },
/// ];
/// let mut c = Counts::default();
/// vandermonde_hermite_with(&data, &mut c)?;
/// assert!(c.arithmetic_operations > 0 && c.arithmetic_operations <= 14 + 12 + 10);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn vandermonde_hermite_with<S: Scalar, const D: usize, C: Counter>(
    data: &[HermiteNode<S, D>],
    counter: &mut C,
) -> Result<Polynomial<S, D>> {
    let total = check_hermite(data)?;
    check_dense(total)?;
    let mut matrix = Vec::with_capacity(total);
    let mut rhs = Vec::with_capacity(total);
    for node in data {
        for (r, value) in node.values.iter().enumerate() {
            // Row r: the r-th derivative of u^j is j!/(j-r)! u^(j-r).
            let mut row = vec![S::zero(); total];
            let mut power = S::one();
            for (j, entry) in row.iter_mut().enumerate().skip(r) {
                *entry = falling_factorial::<S>(j, r) * &power;
                power = power * &node.u;
            }
            matrix.push(row);
            rhs.push(value.clone());
        }
    }
    let coefficients = solve_dense_with(matrix, rhs, counter)
        .ok_or_else(|| singular("nodes", "the confluent Vandermonde matrix is singular"))?;
    Ok(Polynomial::new(finite(coefficients)?))
}

/// The Bézier form over [a, b] of the nested polynomial
/// `c₀ + (u − z₀)(c₁ + (u − z₁)(⋯ (c_{n−1} + (u − z_{n−1}) cₙ)))` (Newton's form; the power
/// form with every z = 0), for a < b finite: Horner's rule in the Bernstein basis.
///
/// Idea: the affine factor is `u − z = (a − z)(1 − t) + (b − z) t` in the local parameter t,
/// and the product of an affine `α(1 − t) + βt` with `Σ pⱼ Bⱼᵏ` has the coefficients
/// `(j/(k+1)) β pⱼ₋₁ + (1 − j/(k+1)) α pⱼ` of degree k + 1 (degree elevation, [PPB, §3.11],
/// is the case α = β = 1); a constant adds to every coefficient (the partition of unity,
/// [PPB, §2.1]). Only affine combinations and scalings: stable on `f64`, exact on rationals.
///
/// # Errors
///
/// [`Error::Overflow`] if, with `f64`, a control point is beyond the double range;
/// [`Error::LimitExceeded`] for a degree above [`MAX_DEGREE`](crate::limits::MAX_DEGREE)
/// (a [`Polynomial`] may have any number of coefficients), before the Θ(n²) work.
///
/// # Complexity
///
/// Θ(n²D) time and O(nD) space for degree n.
pub(super) fn nested_to_bezier<S: Scalar, const D: usize>(
    nodes: &[S],
    coefficients: &[Point<S, D>],
    a: &S,
    b: &S,
) -> Result<Reparametrised<S, D>> {
    check_degree(coefficients.len())?;
    let n = coefficients.len() - 1;
    let mut p = vec![coefficients[n].clone()];
    for i in (0..n).rev() {
        let alpha = a.clone() - &nodes[i];
        let beta = b.clone() - &nodes[i];
        let k = p.len() - 1;
        let mut next = Vec::with_capacity(k + 2);
        for j in 0..=k + 1 {
            let w = S::from_ratio(j as i64, (k + 1) as i64);
            let mut v = coefficients[i].clone();
            if j > 0 {
                v += &(p[j - 1].clone() * (w.clone() * &beta));
            }
            if j <= k {
                v += &(p[j].clone() * ((S::one() - &w) * &alpha));
            }
            next.push(v);
        }
        p = next;
    }
    let curve = Bezier::derived(p, "conversion to the Bézier form")?;
    Ok(Reparametrised::new_unchecked(curve, a.clone(), b.clone()))
}
