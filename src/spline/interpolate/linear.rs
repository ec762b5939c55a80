//! The linear systems of the interpolation kernels, with points as right-hand sides (one
//! column per coordinate): dense Gaussian elimination (Vandermonde systems, normal equations)
//! and tridiagonal and cyclic tridiagonal elimination (cubic splines).
//!
//! # Complexity
//!
//! Θ(n³ + n²D) for a dense system of n unknowns in R^D, Θ(nD) for a tridiagonal or cyclic
//! one; the matrices are overwritten, the right-hand sides become the solution.

use crate::count::{Counter, NoCount};
use crate::spline::scalar::{Point, Scalar};

/// Solves `A X = B` for a square `A` (rows of scalars) and right-hand sides that are points,
/// by Gaussian elimination; `None` if `A` is singular.
///
/// Exact scalars pivot on the first nonzero entry of the column; rounded ones on the entry of
/// largest magnitude (partial pivoting).
pub(crate) fn solve_dense<S: Scalar, const D: usize>(
    a: Vec<Vec<S>>,
    b: Vec<Point<S, D>>,
) -> Option<Vec<Point<S, D>>> {
    solve_dense_with(a, b, &mut NoCount)
}

/// [`solve_dense`], counting one [`arithmetic_operation`](Counter::arithmetic_operation) per
/// entry a row operation changes (the matrix's and the right-hand side's) and per term of the
/// back substitution.
pub(crate) fn solve_dense_with<S: Scalar, const D: usize, C: Counter>(
    mut a: Vec<Vec<S>>,
    mut b: Vec<Point<S, D>>,
    counter: &mut C,
) -> Option<Vec<Point<S, D>>> {
    let n = a.len();
    for col in 0..n {
        let pivot = pivot(&a, col)?;
        a.swap(col, pivot);
        b.swap(col, pivot);
        eliminate_below(&mut a, col, |row, factor| {
            let delta = b[col].clone() * factor;
            b[row] -= &delta;
            for _ in col..=n {
                counter.arithmetic_operation();
            }
        });
    }
    for col in (0..n).rev() {
        let mut x = b[col].clone();
        for k in col + 1..n {
            let delta = b[k].clone() * &a[col][k];
            x -= &delta;
            counter.arithmetic_operation();
        }
        b[col] = x / &a[col][col];
        counter.arithmetic_operation();
    }
    Some(b)
}

/// The pivot row for column `col` of a square matrix whose columns before `col` are
/// eliminated: for exact scalars the first row from `col` on with a nonzero entry, for rounded
/// ones the row of largest magnitude (partial pivoting); `None` if the column is zero there
/// (the matrix is singular).
pub(crate) fn pivot<S: Scalar>(a: &[Vec<S>], col: usize) -> Option<usize> {
    let rows = col..a.len();
    let best = if S::EXACT {
        rows.into_iter().find(|&r| !a[r][col].is_zero())?
    } else {
        rows.max_by(|&r, &s| {
            a[r][col]
                .abs()
                .partial_cmp(&a[s][col].abs())
                .unwrap_or(std::cmp::Ordering::Equal)
        })?
    };
    (!a[best][col].is_zero()).then_some(best)
}

/// Subtracts multiples of row `col` (whose entry in column `col` is nonzero) from the rows
/// below it so that column `col` is zero there, and calls `each(row, factor)` for every row
/// changed, so that the caller can apply the same step to its right-hand sides.
pub(crate) fn eliminate_below<S: Scalar>(
    a: &mut [Vec<S>],
    col: usize,
    mut each: impl FnMut(usize, &S),
) {
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
        each(col + 1 + offset, &factor);
    }
}

/// Thomas' algorithm for a tridiagonal system with point right-hand sides: row `i` is
/// `sub[i] x_{i−1} + diag[i] x_i + sup[i] x_{i+1} = rhs[i]` (`sub[0]`, `sup[n−1]` unused).
/// The callers' matrices are strictly diagonally dominant, so no pivot is zero.
pub(super) fn solve_tridiagonal<S: Scalar, const D: usize, C: Counter>(
    sub: &[S],
    diag: &[S],
    sup: &[S],
    mut rhs: Vec<Point<S, D>>,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let n = diag.len();
    // One scaling of the first row, a multiply-add and a scaling per later row, one
    // multiply-add per row back.
    count(counter, 3 * n - 1);
    // One division per row: points are scaled by the pivot's reciprocal.
    let mut c = Vec::with_capacity(n);
    let mut inverse = S::one() / &diag[0];
    c.push(sup[0].clone() * &inverse);
    rhs[0] = rhs[0].clone() * &inverse;
    for i in 1..n {
        inverse = S::one() / (diag[i].clone() - &(sub[i].clone() * &c[i - 1]));
        c.push(sup[i].clone() * &inverse);
        let prev = rhs[i - 1].clone() * &sub[i];
        rhs[i] = (rhs[i].clone() - &prev) * &inverse;
    }
    for i in (0..n - 1).rev() {
        let next = rhs[i + 1].clone() * &c[i];
        rhs[i] -= &next;
    }
    rhs
}

/// A cyclic tridiagonal system: as [`solve_tridiagonal`] plus the corners
/// `A[0][n−1] = sub[0]` and `A[n−1][0] = sup[n−1]`, by the Sherman–Morrison formula
/// (two tridiagonal solves). Needs `n ≥ 2`; for `n = 2` the corners fold into the
/// off-diagonals.
pub(super) fn solve_cyclic<S: Scalar, const D: usize, C: Counter>(
    sub: &[S],
    diag: &[S],
    sup: &[S],
    rhs: Vec<Point<S, D>>,
    counter: &mut C,
) -> Vec<Point<S, D>> {
    let n = diag.len();
    if n == 2 {
        count(counter, 4);
        let (a, b) = (diag[0].clone(), sup[0].clone() + &sub[0]);
        let (c, d) = (sub[1].clone() + &sup[1], diag[1].clone());
        let det = a.clone() * &d - &(b.clone() * &c);
        let x0 = (rhs[0].clone() * &d - &(rhs[1].clone() * &b)) / &det;
        let x1 = (rhs[1].clone() * &a - &(rhs[0].clone() * &c)) / &det;
        return vec![x0, x1];
    }
    let (beta, alpha) = (sub[0].clone(), sup[n - 1].clone());
    // A = T + w vᵀ with w = (γ, 0, ..., 0, α), v = (1, 0, ..., 0, β/γ).
    let gamma = -diag[0].clone();
    let mut modified = diag.to_vec();
    modified[0] = diag[0].clone() - &gamma;
    modified[n - 1] = diag[n - 1].clone() - &(alpha.clone() * &beta / &gamma);
    let y = solve_tridiagonal(sub, &modified, sup, rhs, counter);
    let mut w = vec![Point::<S, 1>::zero(); n];
    w[0] = Point::new([gamma.clone()]);
    w[n - 1] = Point::new([alpha]);
    // The correction's system has scalar right-hand sides: bookkeeping, not counted.
    let z = solve_tridiagonal(sub, &modified, sup, w, &mut NoCount);
    count(counter, n + 1);
    let ratio = beta / &gamma;
    let vz = z[0][0].clone() + &(z[n - 1][0].clone() * &ratio);
    let vy = y[0].clone() + &(y[n - 1].clone() * &ratio);
    let factor = vy / &(S::one() + &vz);
    y.into_iter()
        .zip(z)
        .map(|(yi, zi)| yi - &(factor.clone() * &zi[0]))
        .collect()
}

/// Records `k` arithmetic operations.
pub(super) fn count<C: Counter>(counter: &mut C, k: usize) {
    for _ in 0..k {
        counter.arithmetic_operation();
    }
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

    /// Multiplies the cyclic matrix by `x` (the oracle for the solver).
    fn cyclic_times(sub: &[f64], diag: &[f64], sup: &[f64], x: &[f64]) -> Vec<f64> {
        let n = x.len();
        (0..n)
            .map(|i| sub[i] * x[(i + n - 1) % n] + diag[i] * x[i] + sup[i] * x[(i + 1) % n])
            .collect()
    }

    #[test]
    fn cyclic_solver_inverts_the_cyclic_matrix() {
        for n in 2..7 {
            let sub: Vec<f64> = (0..n).map(|i| 1.0 + i as f64 * 0.25).collect();
            let sup: Vec<f64> = (0..n).map(|i| 0.5 + i as f64 * 0.125).collect();
            let diag: Vec<f64> = (0..n).map(|i| 2.0 * (sub[i] + sup[i]) + 0.5).collect();
            let x: Vec<f64> = (0..n).map(|i| (i as f64 - 1.5) * 0.75).collect();
            let mut b = cyclic_times(&sub, &diag, &sup, &x);
            if n == 2 {
                // For two unknowns both neighbours are the other one.
                b = vec![
                    (sub[0] + sup[0]) * x[1] + diag[0] * x[0],
                    (sub[1] + sup[1]) * x[0] + diag[1] * x[1],
                ];
            }
            let rhs = b.iter().map(|&v| Point::new([v])).collect();
            let got = solve_cyclic(&sub, &diag, &sup, rhs, &mut NoCount);
            for (g, want) in got.iter().zip(&x) {
                assert!((g[0] - want).abs() < 1e-12, "n = {n}: {g:?} vs {want}");
            }
        }
    }
}
