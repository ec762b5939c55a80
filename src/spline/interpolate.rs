//! Polynomial interpolation in the power basis: the Vandermonde system, also with derivative
//! (Hermite) data, and the shared pieces of every interpolation kernel (the polynomial type,
//! node validation, the dense linear solver).
//!
//! Seed 003 §3.1 ("Interpolación Polinomial": the system `B a = y` with
//! `det B = ∏_{i>j} (x_i − x_j)`, and "Interpolación de Hermite": the `2n + 2` system with
//! derivative rows); seed 000 §4.1 (the interpolation matrix `C X = P`, one column per
//! coordinate). The Lagrange and Aitken forms are in `lagrange.rs`, Newton's divided
//! differences in `newton.rs`; all three give the same polynomial, which the tests check with
//! exact rationals.

use super::{Point, Scalar};
use crate::{Error, Result};

/// A polynomial curve `p(u) = Σ_j a_j u^j` in the power (monomial) basis, with coefficients
/// `a_j ∈ R^D`.
///
/// ```
/// use compgeo::spline::{Point, Polynomial};
///
/// // p(u) = (1, 0) + (0, 2)·u + (3, 0)·u²
/// let p = Polynomial::new(vec![Point::new([1.0, 0.0]), Point::new([0.0, 2.0]), Point::new([3.0, 0.0])]);
/// assert_eq!(p.eval(&2.0), Point::new([13.0, 4.0]));
/// assert_eq!(p.derivative().eval(&2.0), Point::new([12.0, 2.0]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Polynomial<S, const D: usize> {
    coefficients: Vec<Point<S, D>>,
}

/// Interpolation data at one node: the value and the first derivatives there.
///
/// `values[0]` is `p(u)`, `values[r]` is the r-th derivative `p⁽ʳ⁾(u)`. A node with `k + 1`
/// values imposes `k + 1` conditions (seed 000 §4.4: the node counts `k + 1` times).
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

    /// `p(u)` by Horner's rule: `n` multiplications and additions per coordinate.
    pub fn eval(&self, u: &S) -> Point<S, D> {
        let mut acc = Point::zero();
        for a in self.coefficients.iter().rev() {
            acc = acc * u + a;
        }
        acc
    }

    /// The derivative `p'(u) = Σ_j j a_j u^{j−1}`.
    pub fn derivative(&self) -> Self {
        let coefficients = self
            .coefficients
            .iter()
            .enumerate()
            .skip(1)
            .map(|(j, a)| a.clone() * S::from_i64(j as i64))
            .collect();
        Polynomial { coefficients }
    }
}

/// The polynomial of degree at most `n` through `n + 1` points `p_i` at distinct nodes `u_i`,
/// by solving the Vandermonde system.
///
/// The idea (seed 003 §3.1): in the basis `1, u, ..., u^n` the interpolation conditions are
/// the linear system `B a = y` with `B_ij = u_i^j`; `det B = ∏_{i>j} (u_i − u_j)` is nonzero
/// exactly when the nodes are distinct. The system is solved by Gaussian elimination, one
/// right-hand side per coordinate (seed 000 §4.1). With `f64` the elimination pivots on the
/// largest entry of each column; the Vandermonde matrix is notoriously ill-conditioned, so for
/// many nodes prefer [`newton`](super::newton) or the rational back end.
///
/// # Errors
///
/// [`Error::Empty`] for no nodes; [`Error::InvalidParameter`] (`"points"`) if the lengths
/// differ; [`Error::NonFinite`] for a NaN or infinite coordinate; [`Error::InvalidParameter`]
/// (`"nodes"`) for a non-finite node or two equal nodes (the system is singular: a repeated
/// node needs derivative data, see [`vandermonde_hermite`]).
///
/// # Complexity
///
/// Θ(n³ + n²·D) time and Θ(n² + n·D) auxiliary space for `n + 1` nodes in R^D.
///
/// Nothing is counted: the algorithm makes no geometric decision.
///
/// ```
/// use compgeo::spline::{vandermonde, Point};
///
/// // The parabola y = u² through (−1, 1), (0, 0), (2, 4).
/// let p = vandermonde(&[-1.0, 0.0, 2.0], &[Point::new([1.0]), Point::new([0.0]), Point::new([4.0])])?;
/// assert_eq!(p.eval(&3.0), Point::new([9.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn vandermonde<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<Polynomial<S, D>> {
    check_nodes_and_points(nodes, points)?;
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
    let coefficients = solve_dense(matrix, points.to_vec())
        .ok_or_else(|| singular("nodes", "the Vandermonde matrix is singular"))?;
    Ok(Polynomial::new(finite(coefficients)?))
}

/// The Hermite interpolating polynomial through values and derivatives, by solving the
/// confluent Vandermonde system.
///
/// Seed 003 §3.1 ("Interpolación de Hermite"): a node with value and `k` derivatives adds the
/// rows `d^r/du^r u^j = j!/(j−r)! u^{j−r}`, `r = 0..=k`; with `N` conditions in all the
/// polynomial has degree `N − 1` and is unique when the nodes are distinct.
///
/// # Errors
///
/// [`Error::Empty`] for no nodes or a node without values; [`Error::NonFinite`] for a
/// non-finite value (the index counts values over all nodes in order);
/// [`Error::InvalidParameter`] (`"nodes"`) for a non-finite or repeated node.
///
/// # Complexity
///
/// Θ(N³ + N²·D) time and Θ(N² + N·D) auxiliary space for `N` conditions in R^D.
///
/// Nothing is counted.
///
/// ```
/// use compgeo::spline::{vandermonde_hermite, HermiteNode, Point};
///
/// // u³ from its value and slope at 0 and 1: 0, 0 and 1, 3.
/// let data = [
///     HermiteNode { u: 0.0, values: vec![Point::new([0.0]), Point::new([0.0])] },
///     HermiteNode { u: 1.0, values: vec![Point::new([1.0]), Point::new([3.0])] },
/// ];
/// let p = vandermonde_hermite(&data)?;
/// assert_eq!(p.eval(&2.0), Point::new([8.0]));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn vandermonde_hermite<S: Scalar, const D: usize>(
    data: &[HermiteNode<S, D>],
) -> Result<Polynomial<S, D>> {
    let total = check_hermite(data)?;
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
    let coefficients = solve_dense(matrix, rhs)
        .ok_or_else(|| singular("nodes", "the confluent Vandermonde matrix is singular"))?;
    Ok(Polynomial::new(finite(coefficients)?))
}

/// Checks that `nodes` and `points` are non-empty, of equal length and finite.
pub(crate) fn check_nodes_and_points<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<()> {
    if nodes.is_empty() {
        return Err(Error::Empty { what: "nodes" });
    }
    if nodes.len() != points.len() {
        return Err(Error::InvalidParameter {
            name: "points",
            reason: format!("{} points for {} nodes", points.len(), nodes.len()),
        });
    }
    super::validate_points(points, "points")?;
    check_finite_nodes(nodes, "nodes")
}

/// Checks every node is finite.
pub(crate) fn check_finite_nodes<S: Scalar>(nodes: &[S], name: &'static str) -> Result<()> {
    match nodes.iter().position(|u| !u.is_finite()) {
        None => Ok(()),
        Some(i) => Err(Error::InvalidParameter {
            name,
            reason: format!("node {i} is not finite ({})", nodes[i].to_f64()),
        }),
    }
}

/// Checks that no two nodes are equal (in any order); O(n log n).
pub(crate) fn check_distinct<S: Scalar>(nodes: &[S]) -> Result<()> {
    let mut order: Vec<usize> = (0..nodes.len()).collect();
    // The nodes are finite, so `partial_cmp` is total on them.
    order.sort_by(|&a, &b| {
        nodes[a]
            .partial_cmp(&nodes[b])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    for w in order.windows(2) {
        if nodes[w[0]] == nodes[w[1]] {
            let (i, j) = (w[0].min(w[1]), w[0].max(w[1]));
            return Err(singular(
                "nodes",
                &format!(
                    "nodes {i} and {j} are equal ({}); a repeated node needs derivative data",
                    nodes[i].to_f64()
                ),
            ));
        }
    }
    Ok(())
}

/// Checks that a partition `u_0 < u_1 < ... < u_m` is finite and strictly increasing and has
/// at least `needed` knots.
pub(crate) fn check_partition<S: Scalar>(
    partition: &[S],
    needed: usize,
    name: &'static str,
) -> Result<()> {
    if partition.len() < needed {
        return Err(Error::TooFew {
            what: name,
            needed,
            got: partition.len(),
        });
    }
    check_finite_nodes(partition, name)?;
    match partition.windows(2).position(|w| w[0] >= w[1]) {
        None => Ok(()),
        Some(i) => Err(Error::InvalidParameter {
            name,
            reason: format!(
                "must be strictly increasing, but u_{} = {} is not below u_{} = {}",
                i,
                partition[i].to_f64(),
                i + 1,
                partition[i + 1].to_f64()
            ),
        }),
    }
}

/// Validates Hermite data and returns the number of conditions.
pub(crate) fn check_hermite<S: Scalar, const D: usize>(
    data: &[HermiteNode<S, D>],
) -> Result<usize> {
    if data.is_empty() {
        return Err(Error::Empty { what: "nodes" });
    }
    let mut index = 0;
    for node in data {
        if node.values.is_empty() {
            return Err(Error::Empty {
                what: "values of a Hermite node",
            });
        }
        for v in &node.values {
            if let Some(c) = v.coords().iter().find(|c| !c.is_finite()) {
                return Err(Error::NonFinite {
                    index,
                    value: c.to_f64(),
                });
            }
            index += 1;
        }
    }
    let nodes: Vec<S> = data.iter().map(|n| n.u.clone()).collect();
    check_finite_nodes(&nodes, "nodes")?;
    check_distinct(&nodes)?;
    Ok(index)
}

/// The points, or an error if an `f64` one overflowed (finite data, result out of range).
pub(crate) fn finite<S: Scalar, const D: usize>(
    points: Vec<Point<S, D>>,
) -> Result<Vec<Point<S, D>>> {
    if points.iter().all(Point::is_finite) {
        Ok(points)
    } else {
        Err(Error::InvalidParameter {
            name: "points",
            reason: "the result overflows f64 (large values or nearly equal nodes); use exact \
                     rationals"
                .to_string(),
        })
    }
}

/// The error for singular interpolation data.
pub(crate) fn singular(name: &'static str, reason: &str) -> Error {
    Error::InvalidParameter {
        name,
        reason: reason.to_string(),
    }
}

/// `j (j−1) ... (j−r+1)`, the factor of the r-th derivative of `u^j`.
pub(crate) fn falling_factorial<S: Scalar>(j: usize, r: usize) -> S {
    let mut f = S::one();
    for k in 0..r {
        f = f * S::from_i64((j - k) as i64);
    }
    f
}

/// Solves `A X = B` for a square `A` (rows of scalars) and right-hand sides that are points,
/// by Gaussian elimination; `None` if `A` is singular.
///
/// Exact scalars pivot on the first nonzero entry of the column; rounded ones on the entry of
/// largest magnitude (partial pivoting).
pub(crate) fn solve_dense<S: Scalar, const D: usize>(
    mut a: Vec<Vec<S>>,
    mut b: Vec<Point<S, D>>,
) -> Option<Vec<Point<S, D>>> {
    let n = a.len();
    for col in 0..n {
        let pivot = if S::EXACT {
            (col..n).find(|&r| !a[r][col].is_zero())?
        } else {
            let best = (col..n).max_by(|&r, &s| {
                a[r][col]
                    .abs()
                    .partial_cmp(&a[s][col].abs())
                    .unwrap_or(std::cmp::Ordering::Equal)
            })?;
            if a[best][col].is_zero() {
                return None;
            }
            best
        };
        a.swap(col, pivot);
        b.swap(col, pivot);
        let (top, rest) = a.split_at_mut(col + 1);
        let pivot_row = &top[col];
        for (offset, row) in rest.iter_mut().enumerate() {
            if row[col].is_zero() {
                continue;
            }
            let factor = row[col].clone() / &pivot_row[col];
            for (x, p) in row[col..].iter_mut().zip(&pivot_row[col..]) {
                *x -= factor.clone() * p;
            }
            let delta = b[col].clone() * &factor;
            b[col + 1 + offset] -= &delta;
        }
    }
    for col in (0..n).rev() {
        let mut x = b[col].clone();
        for k in col + 1..n {
            let delta = b[k].clone() * &a[col][k];
            x -= &delta;
        }
        b[col] = x / &a[col][col];
    }
    Some(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dense_solver_solves_a_system_that_needs_a_row_swap() {
        // [[0, 1], [2, 3]] x = [1, 8]  ->  x = [2.5, 1]
        let a = vec![vec![0.0, 1.0], vec![2.0, 3.0]];
        let b = vec![Point::new([1.0]), Point::new([8.0])];
        let x = solve_dense(a, b).unwrap();
        assert_eq!(x, vec![Point::new([2.5]), Point::new([1.0])]);
        let singular = vec![vec![1.0, 2.0], vec![2.0, 4.0]];
        assert!(solve_dense(singular, vec![Point::new([1.0]), Point::new([2.0])]).is_none());
    }

    #[test]
    fn partitions_must_increase_strictly() {
        assert!(check_partition(&[0.0, 0.5, 1.0], 2, "partition").is_ok());
        assert!(check_partition(&[0.0, 0.5, 0.5], 2, "partition").is_err());
        assert!(check_partition(&[0.0, f64::NAN], 2, "partition").is_err());
        assert!(matches!(
            check_partition(&[0.0], 2, "partition"),
            Err(Error::TooFew {
                needed: 2,
                got: 1,
                ..
            })
        ));
    }
}
