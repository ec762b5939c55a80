//! Newton interpolation: divided differences, also at repeated (confluent) nodes, which turns
//! it into Hermite interpolation, and the [`NewtonForm`] curve they define.
//!
//! The problem: the polynomial through points (and derivatives) at nodes in any order, in a
//! basis that a new node only extends. The idea: in the Newton basis
//! `P_i(u) = (u − u_0)···(u − u_{i−1})` the coefficients are the divided differences
//! `[u_0 ⋯ u_i] q`, computed by a triangular table; at `r + 1` equal nodes the difference is
//! `q⁽ʳ⁾(u)/r!`, the limit of the difference quotient.
//!
//! Follows [PPB, §4.3] (the Newton basis, the recurrence of divided differences, Obs. 5–6),
//! [PPB, §4.4] (Hermite interpolation as the confluent case) and [RD, §3.1] ("Newton": the
//! nodes need not be in increasing order).
//!
//! # Complexity
//!
//! Θ(N²D) time and Θ(ND) space for N conditions in R^D; Θ(ND) per evaluation.

use super::polynomial::{nested_to_bezier, HermiteNode, Polynomial};
use super::validate::{
    check_degree, check_distinct, check_hermite, check_nodes_and_points, finite,
};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::bezier::Reparametrised;
use crate::spline::curve::{check_interval, Curve, CurveDerivative, Domain, Subsegment};
use crate::spline::scalar::{falling_factorial, validate_parameter, Point, Scalar};
use crate::Result;

/// Newton's divided differences, declared: its name, bounds, counts, source and claims.
pub(crate) const NEWTON: Declaration = Declaration {
    problem: "interpolate",
    name: "newton",
    function: "spline::newton",
    file: "src/spline/interpolate/newton.rs",
    summary: "the interpolating polynomial by divided differences",
    time: "Θ(n²·D)",
    space: "Θ(n·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)/2 divided differences of points for n + 1 nodes",
    source: "[PPB, §4.3]",
    claims: &[on(
        "random-nodes",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

/// Divided differences at confluent nodes, declared: its name, bounds, counts, source and
/// claims.
pub(crate) const NEWTON_HERMITE: Declaration = Declaration {
    problem: "interpolate",
    name: "newton-hermite",
    function: "spline::newton_hermite",
    file: "src/spline/interpolate/newton.rs",
    summary: "divided differences with confluent nodes (derivative data)",
    time: "Θ(N²·D)",
    space: "Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly N(N − 1)/2 entries of the table for N conditions: differences, or derivatives over factorials",
    source: "[PPB, §4.4]",
    claims: &[on(
        "random-nodes",
        Bound::Quadratic,
        Operation::ArithmeticOperations,
    )],
};

/// A polynomial in Newton form: `p(u) = Σ_i c_i (u − z_0)···(u − z_{i−1})`, with the nodes
/// `z_i` (repeated where derivatives were given) and the divided differences
/// `c_i = [z_0 ⋯ z_i] q`.
#[derive(Clone, Debug, PartialEq)]
pub struct NewtonForm<S, const D: usize> {
    nodes: Vec<S>,
    coefficients: Vec<Point<S, D>>,
}

impl<S: Scalar, const D: usize> NewtonForm<S, D> {
    /// The nodes `z_0, ..., z_n` of the Newton basis, each repeated once per condition.
    pub fn nodes(&self) -> &[S] {
        &self.nodes
    }

    /// The divided differences `[z_0 ⋯ z_i] q`, `i = 0..=n`.
    pub fn coefficients(&self) -> &[Point<S, D>] {
        &self.coefficients
    }

    /// The same polynomial in the power basis, by expanding the nested form: Θ(n²·D).
    pub fn to_polynomial(&self) -> Polynomial<S, D> {
        let n = self.coefficients.len();
        // Horner in polynomial arithmetic: acc = acc·(u − z_i) + c_i.
        let mut acc = vec![self.coefficients[n - 1].clone()];
        for i in (0..n - 1).rev() {
            let mut next = vec![Point::zero(); acc.len() + 1];
            for (j, a) in acc.iter().enumerate() {
                next[j + 1] += a;
                let shifted = a.clone() * &self.nodes[i];
                next[j] -= &shifted;
            }
            next[0] += &self.coefficients[i];
            acc = next;
        }
        Polynomial::new(acc)
    }
}

impl<S: Scalar, const D: usize> Curve<S, D> for NewtonForm<S, D> {
    /// [`Domain::Real`].
    fn domain(&self) -> Domain<S> {
        Domain::Real
    }

    /// `p(u)` by nested multiplication (Horner's rule for the Newton basis): `n` steps.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `u` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time, O(D) auxiliary space.
    fn eval(&self, u: &S) -> Result<Point<S, D>> {
        validate_parameter(u, "u")?;
        let n = self.coefficients.len();
        let mut acc = self.coefficients[n - 1].clone();
        for i in (0..n - 1).rev() {
            acc = acc * (u.clone() - &self.nodes[i]) + &self.coefficients[i];
        }
        Ok(acc)
    }
}

/// The derivative of a Newton form is a polynomial in the power basis.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for NewtonForm<S, D> {
    type Derivative = Polynomial<S, D>;

    /// The derivative of [`to_polynomial`](NewtonForm::to_polynomial).
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`](crate::Error::Overflow) as for [`Polynomial`].
    ///
    /// # Complexity
    ///
    /// Θ(n²D).
    fn derivative_curve(&self) -> Result<Polynomial<S, D>> {
        self.to_polynomial().derivative_curve()
    }
}

/// The piece over [a, b] is the Bézier form on [a, b], from the nested form directly.
impl<S: Scalar, const D: usize> Subsegment<S, D> for NewtonForm<S, D> {
    type Segment = Reparametrised<S, D>;

    /// # Complexity
    ///
    /// Θ(n²D) (Horner's rule in the Bernstein basis).
    fn subsegment(&self, a: &S, b: &S) -> Result<Reparametrised<S, D>> {
        check_interval(&self.domain(), a, b)?;
        nested_to_bezier(&self.nodes, &self.coefficients, a, b)
    }
}

/// The Newton form of the polynomial through the points `p_i` at the distinct nodes `u_i`
/// (any order), by the triangular table of divided differences.
///
/// The idea ([PPB, §4.3]): `[u_i] q = p_i` and
/// `[u_i ⋯ u_j] q = ([u_{i+1} ⋯ u_j] q − [u_i ⋯ u_{j−1}] q) / (u_j − u_i)`; the top diagonal
/// of the table gives the coefficients. Adding a node later only adds a term (the basis is
/// permanent), unlike the Lagrange form.
///
/// # Errors
///
/// [`Error::Empty`](crate::Error::Empty) for no nodes;
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) for mismatched lengths, a
/// non-finite or a repeated node (repeated nodes need derivative data: use
/// [`newton_hermite`]); [`Error::NonFinite`](crate::Error::NonFinite) for a bad coordinate;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) for a degree `n` above
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
///
/// # Complexity
///
/// Θ(n²·D) time and Θ(n·D) auxiliary space for `n + 1` nodes in R^D.
///
/// ```
/// use compgeo::spline::{newton, Curve, Point};
///
/// // y = u² at 3, 1, 2 (any order).
/// let p = newton(&[3.0, 1.0, 2.0], &[Point::new([9.0]), Point::new([1.0]), Point::new([4.0])])?;
/// assert_eq!(p.eval(&5.0)?, Point::new([25.0]));
/// assert_eq!(p.coefficients()[2], Point::new([1.0])); // the leading coefficient
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn newton<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<NewtonForm<S, D>> {
    newton_with(nodes, points, &mut NoCount)
}

/// [`newton`], counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// entry of the table of divided differences below its first column (a difference of two
/// points divided by a difference of nodes): column j has n + 1 − j entries, so exactly
/// n(n + 1)/2 for n + 1 nodes.
///
/// # Errors
///
/// As [`newton`].
///
/// # Complexity
///
/// Θ(n²·D) time and Θ(n·D) auxiliary space for `n + 1` nodes in R^D.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{newton_with, Point};
///
/// let mut c = Counts::default();
/// newton_with(&[3.0, 1.0, 2.0, 0.0], &[9.0, 1.0, 4.0, 0.0].map(|y| Point::new([y])), &mut c)?;
/// assert_eq!(c.arithmetic_operations, 3 + 2 + 1);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn newton_with<S: Scalar, const D: usize, C: Counter>(
    nodes: &[S],
    points: &[Point<S, D>],
    counter: &mut C,
) -> Result<NewtonForm<S, D>> {
    check_nodes_and_points(nodes, points)?;
    check_degree(nodes.len())?;
    check_distinct(nodes)?;
    newton_counted(nodes, points, counter)
}

/// The Newton form of the Hermite interpolant: values and derivatives at distinct nodes, by
/// divided differences at repeated nodes.
///
/// The idea ([PPB, §4.3, Obs. 5–6] and [PPB, §4.4]): a node with value and `k` derivatives is
/// repeated `k + 1` times; in the table, a difference over `r + 1` equal nodes is
/// `q⁽ʳ⁾(u)/r!` (the limit of the difference quotient), every other entry follows the usual
/// recurrence. The resulting polynomial of degree `N − 1` (N conditions) matches every given
/// value and derivative.
///
/// # Errors
///
/// [`Error::Empty`](crate::Error::Empty) for no nodes or a node without values;
/// [`Error::NonFinite`](crate::Error::NonFinite) for a bad value (indexed over all values);
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) for a non-finite or repeated
/// node (give all derivatives at a node in one [`HermiteNode`]);
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) for more than
/// [`MAX_DEGREE`](crate::limits::MAX_DEGREE) + 1 conditions.
///
/// # Complexity
///
/// Θ(N²·D) time and Θ(N·D) auxiliary space for `N` conditions.
///
/// ```
/// use compgeo::spline::{newton_hermite, Curve, HermiteNode, Point};
///
/// // u³ from value, slope and second derivative at 0 and its value at 1.
/// let data = [
///     HermiteNode { u: 0.0, values: vec![Point::new([0.0]), Point::new([0.0]), Point::new([0.0])] },
///     HermiteNode { u: 1.0, values: vec![Point::new([1.0])] },
/// ];
/// let p = newton_hermite(&data)?;
/// assert_eq!(p.eval(&2.0)?, Point::new([8.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn newton_hermite<S: Scalar, const D: usize>(
    data: &[HermiteNode<S, D>],
) -> Result<NewtonForm<S, D>> {
    newton_hermite_with(data, &mut NoCount)
}

/// [`newton_hermite`], counting one [`arithmetic_operation`](Counter::arithmetic_operation)
/// per entry of the table below its first column, a divided difference or a derivative over
/// a factorial: exactly N(N − 1)/2 for N conditions.
///
/// # Errors
///
/// As [`newton_hermite`].
///
/// # Complexity
///
/// Θ(N²·D) time and Θ(N·D) auxiliary space for `N` conditions.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::{newton_hermite_with, HermiteNode, Point};
///
/// let data = [
///     HermiteNode { u: 0.0, values: vec![Point::new([0.0]), Point::new([0.0]), Point::new([0.0])] },
///     HermiteNode { u: 1.0, values: vec![Point::new([1.0])] },
/// ];
/// let mut c = Counts::default();
/// newton_hermite_with(&data, &mut c)?;
/// assert_eq!(c.arithmetic_operations, 4 * 3 / 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn newton_hermite_with<S: Scalar, const D: usize, C: Counter>(
    data: &[HermiteNode<S, D>],
    counter: &mut C,
) -> Result<NewtonForm<S, D>> {
    check_hermite(data)?;
    checked(divided_differences(data, counter))
}

/// The Newton form of validated data: distinct finite nodes, as many finite points.
pub(super) fn newton_unchecked<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<NewtonForm<S, D>> {
    newton_counted(nodes, points, &mut NoCount)
}

/// [`newton_unchecked`], counting the table's entries.
fn newton_counted<S: Scalar, const D: usize, C: Counter>(
    nodes: &[S],
    points: &[Point<S, D>],
    counter: &mut C,
) -> Result<NewtonForm<S, D>> {
    let data: Vec<HermiteNode<S, D>> = nodes
        .iter()
        .zip(points)
        .map(|(u, p)| HermiteNode {
            u: u.clone(),
            values: vec![p.clone()],
        })
        .collect();
    checked(divided_differences(&data, counter))
}

/// The form, or an error if an `f64` divided difference overflowed.
fn checked<S: Scalar, const D: usize>(form: NewtonForm<S, D>) -> Result<NewtonForm<S, D>> {
    let coefficients = finite(form.coefficients)?;
    Ok(NewtonForm {
        nodes: form.nodes,
        coefficients,
    })
}

/// The divided-difference table over validated data, kept one column at a time.
fn divided_differences<S: Scalar, const D: usize, C: Counter>(
    data: &[HermiteNode<S, D>],
    counter: &mut C,
) -> NewtonForm<S, D> {
    // z: the nodes repeated per condition; owner[i]: which datum z_i came from.
    let mut z = Vec::new();
    let mut owner = Vec::new();
    for (k, node) in data.iter().enumerate() {
        for _ in &node.values {
            z.push(node.u.clone());
            owner.push(k);
        }
    }
    let n = z.len();
    // column[i] holds [z_i ⋯ z_{i+j}] q for the current order j.
    let mut column: Vec<Point<S, D>> = owner.iter().map(|&k| data[k].values[0].clone()).collect();
    let mut coefficients = Vec::with_capacity(n);
    coefficients.push(column[0].clone());
    for j in 1..n {
        let factorial: S = falling_factorial(j, j);
        for i in 0..n - j {
            column[i] = if owner[i] == owner[i + j] {
                // j + 1 copies of one node: the j-th derivative over j!.
                data[owner[i]].values[j].clone() / &factorial
            } else {
                let diff = column[i + 1].clone() - &column[i];
                diff / (z[i + j].clone() - &z[i])
            };
            counter.arithmetic_operation();
        }
        column.truncate(n - j);
        coefficients.push(column[0].clone());
    }
    NewtonForm {
        nodes: z,
        coefficients,
    }
}
