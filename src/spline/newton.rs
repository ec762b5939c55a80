//! Newton interpolation: divided differences, also at repeated (confluent) nodes, which turns
//! it into Hermite interpolation.
//!
//! Seed 000 §4.3 (the Newton basis `P_i(u) = (u − u_0)···(u − u_{i−1})`, the recurrence of
//! divided differences, Obs. 5–6: `[u_i ⋯ u_i] q = q⁽ⁿ⁾(u_i)/n!` at `n + 1` equal nodes) and
//! §4.4 (Hermite interpolation as the confluent case); seed 003 §3.1 ("Newton": the nodes need
//! not be in increasing order).

use super::interpolate::{
    check_distinct, check_hermite, check_nodes_and_points, finite, HermiteNode,
};
use super::{Point, Polynomial, Scalar};
use crate::Result;

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

    /// `p(u)` by nested multiplication (Horner's rule for the Newton basis): `n` steps.
    pub fn eval(&self, u: &S) -> Point<S, D> {
        let n = self.coefficients.len();
        let mut acc = self.coefficients[n - 1].clone();
        for i in (0..n - 1).rev() {
            acc = acc * (u.clone() - &self.nodes[i]) + &self.coefficients[i];
        }
        acc
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

/// The Newton form of the polynomial through the points `p_i` at the distinct nodes `u_i`
/// (any order), by the triangular table of divided differences.
///
/// The idea (seed 000 §4.3): `[u_i] q = p_i` and
/// `[u_i ⋯ u_j] q = ([u_{i+1} ⋯ u_j] q − [u_i ⋯ u_{j−1}] q) / (u_j − u_i)`; the top diagonal
/// of the table gives the coefficients. Adding a node later only adds a term (the basis is
/// permanent), unlike the Lagrange form.
///
/// # Errors
///
/// [`Error::Empty`](crate::Error::Empty) for no nodes;
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) for mismatched lengths, a
/// non-finite or a repeated node (repeated nodes need derivative data: use
/// [`newton_hermite`]); [`Error::NonFinite`](crate::Error::NonFinite) for a bad coordinate.
///
/// # Complexity
///
/// Θ(n²·D) time and Θ(n·D) auxiliary space for `n + 1` nodes in R^D. Nothing is counted.
///
/// ```
/// use compgeo::spline::{newton, Point};
///
/// // y = u² at 3, 1, 2 (any order).
/// let p = newton(&[3.0, 1.0, 2.0], &[Point::new([9.0]), Point::new([1.0]), Point::new([4.0])])?;
/// assert_eq!(p.eval(&5.0), Point::new([25.0]));
/// assert_eq!(p.coefficients()[2], Point::new([1.0])); // the leading coefficient
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn newton<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<NewtonForm<S, D>> {
    check_nodes_and_points(nodes, points)?;
    check_distinct(nodes)?;
    let data: Vec<HermiteNode<S, D>> = nodes
        .iter()
        .zip(points)
        .map(|(u, p)| HermiteNode {
            u: u.clone(),
            values: vec![p.clone()],
        })
        .collect();
    checked(divided_differences(&data))
}

/// The Newton form of the Hermite interpolant: values and derivatives at distinct nodes, by
/// divided differences at repeated nodes.
///
/// The idea (seed 000 §4.3 Obs. 5–6 and §4.4): a node with value and `k` derivatives is
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
/// node (give all derivatives at a node in one [`HermiteNode`]).
///
/// # Complexity
///
/// Θ(N²·D) time and Θ(N·D) auxiliary space for `N` conditions. Nothing is counted.
///
/// ```
/// use compgeo::spline::{newton_hermite, HermiteNode, Point};
///
/// // u³ from value, slope and second derivative at 0 and its value at 1.
/// let data = [
///     HermiteNode { u: 0.0, values: vec![Point::new([0.0]), Point::new([0.0]), Point::new([0.0])] },
///     HermiteNode { u: 1.0, values: vec![Point::new([1.0])] },
/// ];
/// let p = newton_hermite(&data)?;
/// assert_eq!(p.eval(&2.0), Point::new([8.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn newton_hermite<S: Scalar, const D: usize>(
    data: &[HermiteNode<S, D>],
) -> Result<NewtonForm<S, D>> {
    check_hermite(data)?;
    checked(divided_differences(data))
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
fn divided_differences<S: Scalar, const D: usize>(data: &[HermiteNode<S, D>]) -> NewtonForm<S, D> {
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
    let mut factorial = S::one();
    for j in 1..n {
        factorial = factorial * S::from_i64(j as i64);
        for i in 0..n - j {
            column[i] = if owner[i] == owner[i + j] {
                // j + 1 copies of one node: the j-th derivative over j!.
                data[owner[i]].values[j].clone() / &factorial
            } else {
                let diff = column[i + 1].clone() - &column[i];
                diff / (z[i + j].clone() - &z[i])
            };
        }
        column.truncate(n - j);
        coefficients.push(column[0].clone());
    }
    NewtonForm {
        nodes: z,
        coefficients,
    }
}
