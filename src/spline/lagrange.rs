//! Lagrange interpolation: the Lagrange basis, evaluation of the interpolant from it, and
//! Aitken's algorithm (repeated linear interpolation, the interpolation analogue of de
//! Casteljau).
//!
//! Seed 000 §4.2 (the basis `L_i^n(u) = ∏_{j≠i} (u − u_j)/(u_i − u_j)`, its recurrence (1) and
//! Aitken's scheme `p_i^{k+1} = α_{i,n−k} p_i^k + (1 − α_{i,n−k}) p_{n−k}^k` with
//! `α_{ik} = (u − u_k)/(u_i − u_k)`); seed 003 §3.1 ("Lagrange").

use super::interpolate::{check_distinct, check_nodes_and_points, finite};
use super::{validate_parameter, Point, Scalar};
use crate::Result;

/// The values `L_0^n(u), ..., L_n^n(u)` of the Lagrange basis of the distinct nodes
/// `u_0, ..., u_n` at `u`.
///
/// The idea (seed 000 §4.2, recurrence (1)): start from `L_0^0 = 1`; adding node `u_k`
/// multiplies every `L_i^{k−1}` by `α_{ik} = (u − u_k)/(u_i − u_k)` and gives the new basis
/// function `L_k^k = Σ_i L_i^{k−1} (1 − α_{ik})`, so the values sum to one at every stage.
///
/// # Errors
///
/// [`Error::Empty`](crate::Error::Empty) for no nodes; [`Error::InvalidParameter`](crate::Error::InvalidParameter)
/// for a non-finite or repeated node, or a non-finite `u`.
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
        return Err(crate::Error::Empty { what: "nodes" });
    }
    super::interpolate::check_finite_nodes(nodes, "nodes")?;
    check_distinct(nodes)?;
    validate_parameter(u, "u")?;
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
    Ok(basis)
}

/// The value at `u` of the polynomial of degree at most `n` through the points `p_i` at the
/// distinct nodes `u_i`, as `Σ p_i L_i^n(u)` (the Lagrange form).
///
/// Seed 000 §4.2, seed 003 §3.1: the interpolant is the combination of the Lagrange basis with
/// the data as coefficients; the basis comes from [`lagrange_basis`].
///
/// # Errors
///
/// As [`lagrange_basis`], plus [`Error::InvalidParameter`](crate::Error::InvalidParameter)
/// (`"points"`) if the lengths differ and [`Error::NonFinite`](crate::Error::NonFinite) for a
/// bad coordinate.
///
/// # Complexity
///
/// Θ(n² + n·D) time and Θ(n) auxiliary space per evaluation. Nothing is counted.
///
/// ```
/// use compgeo::spline::{lagrange, Point};
///
/// let nodes = [0.0, 1.0, 3.0];
/// let pts = [Point::new([0.0, 1.0]), Point::new([1.0, 2.0]), Point::new([9.0, 4.0])];
/// // The data are (u², u + 1) sampled at the nodes.
/// let p = lagrange(&nodes, &pts, &2.0)?;
/// assert!((p[0] - 4.0).abs() < 1e-12 && (p[1] - 3.0).abs() < 1e-12);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn lagrange<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
    u: &S,
) -> Result<Point<S, D>> {
    check_nodes_and_points(nodes, points)?;
    let basis = lagrange_basis(nodes, u)?;
    let mut acc = Point::zero();
    for (p, l) in points.iter().zip(&basis) {
        acc += &(p.clone() * l);
    }
    Ok(finite(vec![acc])?.swap_remove(0))
}

/// The value at `u` of the interpolating polynomial by Aitken's algorithm: repeated linear
/// interpolation between interpolants of fewer points.
///
/// The idea (seed 000 §4.2, Obs. 4): `p_i^k(u)` interpolates `p_i` and the last `k` points
/// `p_n, ..., p_{n−k+1}`; one step joins `p_i^k` and `p_{n−k}^k`, which share `k − 1` of their
/// points, by the affine combination with the local parameter `α_{i,n−k}`. After `n` steps
/// `p_0^n(u)` is the value of the interpolant. It is the triangular scheme of de Casteljau
/// with nodes instead of the fixed interval [0, 1].
///
/// # Errors
///
/// As [`lagrange`].
///
/// # Complexity
///
/// Θ(n²·D) time and Θ(n·D) auxiliary space per evaluation. Nothing is counted.
///
/// ```
/// use compgeo::spline::{aitken, lagrange, Point};
///
/// let nodes = [0.0, 0.5, 2.0, 3.0];
/// let pts = [Point::new([1.0]), Point::new([2.0]), Point::new([0.0]), Point::new([5.0])];
/// let a = aitken(&nodes, &pts, &1.0)?;
/// let l = lagrange(&nodes, &pts, &1.0)?;
/// assert!((a[0] - l[0]).abs() < 1e-12);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn aitken<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
    u: &S,
) -> Result<Point<S, D>> {
    check_nodes_and_points(nodes, points)?;
    check_distinct(nodes)?;
    validate_parameter(u, "u")?;
    let n = nodes.len() - 1;
    let mut p = points.to_vec();
    for k in 0..n {
        let last = n - k;
        for i in 0..last {
            let alpha = (u.clone() - &nodes[last]) / (nodes[i].clone() - &nodes[last]);
            p[i] = Point::lerp(&p[last], &p[i], &alpha);
        }
    }
    p.truncate(1);
    Ok(finite(p)?.swap_remove(0))
}
