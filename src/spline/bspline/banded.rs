//! Banded linear systems: Gaussian elimination without pivoting in O(n·l·u) for a matrix of
//! n unknowns with l diagonals below and u above the main one, with points as right-hand
//! sides (one column per coordinate).
//!
//! The problem: the collocation matrix N_{kj} = N_j(τ_k) of interpolation and the normal
//! matrix NᵀN of a least-squares fit have at most d + 1 non-zero entries a row, all within d
//! of the diagonal [PPB, §6.7]; a dense solve would spend Θ(n³) on zeros. The idea: store the
//! 1 + l + u diagonals only and eliminate without row exchanges, so that no entry is ever
//! created outside the band (the multiplier of row i at step k touches columns k + 1, …,
//! k + u ≤ i + u).
//!
//! Why no pivoting: a collocation matrix of B-splines at increasing parameters is totally
//! positive, and when the Schoenberg–Whitney condition holds it is invertible, so every leading
//! principal minor is positive and Gaussian elimination without pivoting never meets a zero
//! pivot (de Boor, *A Practical Guide to Splines* (1978), ch. XIII; the theorem of
//! Schoenberg and Whitney in [PPB, §6.7]); a symmetric positive definite matrix (the normal
//! equations at full rank [PPB, §4.7]) has positive leading minors too. The solver still
//! checks every pivot and returns an error naming it rather than dividing by zero, so a
//! matrix outside those classes gives an error, not NaN.
//!
//! # Complexity
//!
//! Θ(n·l·(u + D)) field operations for the elimination and Θ(n·u·D) for the back substitution:
//! Θ(n d²) for the collocation matrices of degree d (l = u = d); Θ(n(l + u + 1)) space for the
//! band, overwritten.

use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::{limits, Error, Result};

/// The banded solver, declared.
pub(crate) const BANDED: Declaration = Declaration {
    problem: "bspline",
    name: "banded-solve",
    function: "spline::BandMatrix::solve",
    file: "src/spline/bspline/banded.rs",
    summary: "a banded linear system by Gaussian elimination without pivoting, every pivot checked",
    time: "Θ(n·l·(u + D))",
    space: "Θ(n(l + u + 1))",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly Σₖ rₖ(wₖ + 2) + Σₖ (wₖ + 1), rₖ = min(l, n − 1 − k), wₖ = min(u, n − 1 − k)",
    source: "[PPB, §6.7]",
    claims: &[
        on(
            "random-rows",
            Bound::Linear,
            Operation::ArithmeticOperations,
        ),
        on(
            "random-bandwidth",
            Bound::Quadratic,
            Operation::ArithmeticOperations,
        ),
    ],
};

/// A square n × n matrix with `lower` diagonals below the main one and `upper` above it
/// (entries a_ij with −lower ≤ j − i ≤ upper; all others are zero), stored by its diagonals.
///
/// Build it with [`BandMatrix::zeros`] and [`BandMatrix::set`], solve with
/// [`BandMatrix::solve`].
///
/// ```
/// use compgeo::spline::{BandMatrix, Point};
///
/// // The tridiagonal matrix [2 1 0; 1 2 1; 0 1 2].
/// let mut a = BandMatrix::zeros(3, 1, 1)?;
/// for i in 0..3 {
///     a.set(i, i, 2.0)?;
///     if i > 0 {
///         a.set(i, i - 1, 1.0)?;
///         a.set(i - 1, i, 1.0)?;
///     }
/// }
/// assert_eq!((a.get(0, 2), a.get(1, 0)), (0.0, 1.0));
/// let x = a.solve(vec![Point::new([3.0]), Point::new([4.0]), Point::new([3.0])])?;
/// assert_eq!(x, [Point::new([1.0]), Point::new([1.0]), Point::new([1.0])]);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BandMatrix<S> {
    size: usize,
    lower: usize,
    upper: usize,
    /// Row i holds columns i − lower, …, i + upper, lower + upper + 1 entries a row.
    entries: Vec<S>,
}

impl<S: Scalar> BandMatrix<S> {
    /// The zero matrix of `size` unknowns with `lower` and `upper` off-diagonals.
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for size 0; [`Error::LimitExceeded`] if `size` exceeds
    /// [`MAX_KNOTS`](crate::limits::MAX_KNOTS) or the n(l + u + 1) stored entries exceed
    /// [`MAX_BASIS_TABLE`](crate::limits::MAX_BASIS_TABLE), before anything is allocated.
    ///
    /// # Complexity
    ///
    /// Θ(n(l + u + 1)) time and space.
    ///
    /// ```
    /// use compgeo::spline::BandMatrix;
    ///
    /// let a = BandMatrix::<f64>::zeros(4, 2, 1)?;
    /// assert_eq!((a.size(), a.lower(), a.upper()), (4, 2, 1));
    /// assert!(BandMatrix::<f64>::zeros(0, 1, 1).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn zeros(size: usize, lower: usize, upper: usize) -> Result<Self> {
        if size == 0 {
            return Err(Error::Empty {
                what: "band matrix",
            });
        }
        limits::KNOTS.check(size as u128)?;
        let width = lower as u128 + upper as u128 + 1;
        let len = limits::BASIS_TABLE.check(size as u128 * width)?;
        Ok(BandMatrix {
            size,
            lower,
            upper,
            entries: vec![S::zero(); len],
        })
    }

    /// The number n of unknowns (rows and columns).
    ///
    /// ```
    /// # use compgeo::spline::BandMatrix;
    /// assert_eq!(BandMatrix::<f64>::zeros(5, 1, 1)?.size(), 5);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn size(&self) -> usize {
        self.size
    }

    /// The number of diagonals below the main one.
    ///
    /// ```
    /// # use compgeo::spline::BandMatrix;
    /// assert_eq!(BandMatrix::<f64>::zeros(5, 2, 1)?.lower(), 2);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn lower(&self) -> usize {
        self.lower
    }

    /// The number of diagonals above the main one.
    ///
    /// ```
    /// # use compgeo::spline::BandMatrix;
    /// assert_eq!(BandMatrix::<f64>::zeros(5, 2, 1)?.upper(), 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn upper(&self) -> usize {
        self.upper
    }

    /// `true` if (i, j) lies in the matrix and in its band.
    fn in_band(&self, i: usize, j: usize) -> bool {
        i < self.size && j < self.size && j + self.lower >= i && j <= i + self.upper
    }

    /// The position of a_ij (in the band) in `entries`.
    fn at(&self, i: usize, j: usize) -> usize {
        i * (self.lower + self.upper + 1) + j + self.lower - i
    }

    /// The entry a_ij (zero outside the band).
    ///
    /// # Panics
    ///
    /// If `i` or `j` is not below [`size`](BandMatrix::size).
    ///
    /// ```
    /// # use compgeo::spline::BandMatrix;
    /// let mut a = BandMatrix::zeros(3, 0, 1)?;
    /// a.set(0, 1, 5.0)?;
    /// assert_eq!((a.get(0, 1), a.get(1, 0), a.get(0, 2)), (5.0, 0.0, 0.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn get(&self, i: usize, j: usize) -> S {
        assert!(
            i < self.size && j < self.size,
            "({i}, {j}) outside the matrix"
        );
        if self.in_band(i, j) {
            self.entries[self.at(i, j)].clone()
        } else {
            S::zero()
        }
    }

    /// Sets the entry a_ij.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"matrix"` if (i, j) is outside the matrix or its
    /// band, or the value is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// O(1).
    ///
    /// ```
    /// # use compgeo::spline::BandMatrix;
    /// let mut a = BandMatrix::zeros(3, 1, 0)?;
    /// a.set(1, 0, 2.0)?;
    /// let e = a.set(0, 1, 2.0).unwrap_err();
    /// assert!(e.to_string().contains("outside the band"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn set(&mut self, i: usize, j: usize, value: S) -> Result<()> {
        if !self.in_band(i, j) {
            return Err(Error::InvalidParameter {
                name: "matrix",
                reason: format!(
                    "entry ({i}, {j}) is outside the band (−{} ≤ j − i ≤ {}) of the {n} × {n} \
                     matrix",
                    self.lower,
                    self.upper,
                    n = self.size
                ),
            });
        }
        if !value.is_finite() {
            return Err(Error::InvalidParameter {
                name: "matrix",
                reason: format!("entry ({i}, {j}) is not finite ({})", value.to_f64()),
            });
        }
        let k = self.at(i, j);
        self.entries[k] = value;
        Ok(())
    }

    /// Adds `value` to the entry a_ij, which must lie in the band.
    pub(super) fn add(&mut self, i: usize, j: usize, value: &S) {
        debug_assert!(self.in_band(i, j));
        let k = self.at(i, j);
        self.entries[k] += value;
    }

    /// The solution X of A X = B for right-hand sides that are points. See
    /// [`BandMatrix::solve_with`].
    ///
    /// # Errors
    ///
    /// As [`BandMatrix::solve_with`].
    ///
    /// # Complexity
    ///
    /// Θ(n·l·(u + D)) time; Θ(n(l + u + 1)) space, the band it takes (nothing beyond it and
    /// the right-hand sides).
    ///
    /// ```
    /// use compgeo::spline::{BandMatrix, Point};
    ///
    /// // A zero pivot is an error, not a division by zero: [0 1; 1 0] needs a row exchange.
    /// let mut a = BandMatrix::zeros(2, 1, 1)?;
    /// a.set(0, 1, 1.0)?;
    /// a.set(1, 0, 1.0)?;
    /// let e = a.solve(vec![Point::new([1.0]), Point::new([2.0])]).unwrap_err();
    /// assert!(e.to_string().contains("pivot 0 is zero"), "{e}");
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn solve<const D: usize>(self, rhs: Vec<Point<S, D>>) -> Result<Vec<Point<S, D>>> {
        self.solve_with(rhs, &mut NoCount)
    }

    /// The solution X of A X = B by Gaussian elimination without pivoting, counting its
    /// operations.
    ///
    /// Idea: for k = 0, …, n − 1 subtract multiples of row k from the at most l rows below
    /// it that have an entry in column k (no entry outside the band is created), then solve
    /// the upper triangular band from the bottom. No rows are exchanged: the module docs say
    /// for which matrices that is safe; every pivot is checked (exactly: with `f64` only an
    /// exact zero is refused), so for other matrices the result is an error or the solution.
    ///
    /// Follows the elimination of [PPB, §6.7]'s collocation systems as de Boor, *A Practical
    /// Guide to Splines* (1978), ch. XIII, describes it.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"rhs"` if there are not n right-hand sides or one
    /// has a non-finite coordinate; [`Error::InvalidParameter`] named `"matrix"` naming the
    /// first pivot that is zero (the leading principal minor of that order vanishes);
    /// [`Error::Overflow`] if, with `f64`, the solution is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(n·l·(u + D)) time; Θ(n(l + u + 1)) space, the band it takes (nothing beyond it and
    /// the right-hand sides).
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per multiplier, per update
    /// of an entry of the band and per update of a right-hand side (a point), none skipped
    /// for zero entries: exactly Σₖ rₖ(wₖ + 2) for the elimination and Σₖ (wₖ + 1) for the
    /// back substitution, with rₖ = min(l, n − 1 − k) and wₖ = min(u, n − 1 − k).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::{BandMatrix, Point};
    ///
    /// let n = 100;
    /// let mut a = BandMatrix::zeros(n, 1, 1)?;
    /// for i in 0..n {
    ///     a.set(i, i, 4.0)?;
    ///     if i > 0 {
    ///         a.set(i, i - 1, 1.0)?;
    ///         a.set(i - 1, i, 1.0)?;
    ///     }
    /// }
    /// let mut c = Counts::default();
    /// a.solve_with(vec![Point::new([1.0]); n], &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 3 * 99 + (2 * 99 + 1));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn solve_with<const D: usize, C: Counter>(
        mut self,
        mut rhs: Vec<Point<S, D>>,
        counter: &mut C,
    ) -> Result<Vec<Point<S, D>>> {
        let n = self.size;
        if rhs.len() != n {
            return Err(Error::InvalidParameter {
                name: "rhs",
                reason: format!("{} right-hand sides for {n} unknowns", rhs.len()),
            });
        }
        if let Some(i) = rhs.iter().position(|p| !p.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "rhs",
                reason: format!("right-hand side {i} has a non-finite coordinate"),
            });
        }
        let (l, u) = (self.lower, self.upper);
        for k in 0..n {
            let pivot = self.entries[self.at(k, k)].clone();
            if pivot.is_zero() {
                return Err(zero_pivot(k));
            }
            let last_col = (k + u).min(n - 1);
            for i in k + 1..=(k + l).min(n - 1) {
                let factor = self.entries[self.at(i, k)].clone() / &pivot;
                counter.arithmetic_operation();
                for j in k + 1..=last_col {
                    let delta = factor.clone() * &self.entries[self.at(k, j)];
                    let at = self.at(i, j);
                    self.entries[at] -= &delta;
                    counter.arithmetic_operation();
                }
                let at = self.at(i, k);
                self.entries[at] = S::zero();
                let delta = rhs[k].clone() * &factor;
                rhs[i] -= &delta;
                counter.arithmetic_operation();
            }
        }
        for k in (0..n).rev() {
            let mut x = rhs[k].clone();
            let last = (k + u).min(n - 1);
            for (j, xj) in rhs.iter().enumerate().take(last + 1).skip(k + 1) {
                let delta = xj.clone() * &self.entries[self.at(k, j)];
                x -= &delta;
                counter.arithmetic_operation();
            }
            rhs[k] = x / &self.entries[self.at(k, k)];
            counter.arithmetic_operation();
        }
        if rhs.iter().all(Point::is_finite) {
            Ok(rhs)
        } else {
            Err(Error::Overflow {
                what: "banded linear solve",
            })
        }
    }
}

/// The error of a zero pivot at step `k`.
fn zero_pivot(k: usize) -> Error {
    Error::InvalidParameter {
        name: "matrix",
        reason: format!(
            "pivot {k} is zero after eliminating columns 0..{k}: the leading principal minor \
             of order {} vanishes, and elimination without row exchanges cannot go on",
            k + 1
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_outside_the_band_are_zero_and_refused() {
        let mut a = BandMatrix::zeros(4, 1, 2).unwrap();
        a.set(2, 1, 3.0).unwrap();
        a.set(1, 3, 4.0).unwrap();
        assert_eq!((a.get(2, 1), a.get(1, 3), a.get(3, 1)), (3.0, 4.0, 0.0));
        assert!(a.set(3, 1, 1.0).is_err());
        assert!(a.set(0, 3, 1.0).is_err());
        assert!(a.set(4, 4, 1.0).is_err());
        assert!(a.set(0, 0, f64::NAN).is_err());
        assert!(matches!(
            BandMatrix::<f64>::zeros(1 << 25, 4, 4),
            Err(Error::LimitExceeded { .. })
        ));
    }

    #[test]
    fn a_wide_band_solves_a_full_system() {
        // [[4, 1, 2], [1, 5, 1], [2, 1, 6]] x = A·(1, −2, 3).
        let a = [[4.0, 1.0, 2.0], [1.0, 5.0, 1.0], [2.0, 1.0, 6.0]];
        let x = [1.0, -2.0, 3.0];
        let mut m = BandMatrix::zeros(3, 2, 2).unwrap();
        let mut rhs = Vec::new();
        for (i, row) in a.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                m.set(i, j, *v).unwrap();
            }
            rhs.push(Point::new([row
                .iter()
                .zip(x)
                .map(|(v, xj)| v * xj)
                .sum::<f64>()]));
        }
        let got = m.solve(rhs).unwrap();
        for (g, w) in got.iter().zip(x) {
            assert!((g[0] - w).abs() < 1e-14, "{g:?} vs {w}");
        }
    }
}
