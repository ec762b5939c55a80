//! The four cubic Beta-spline basis functions, their derivatives, and their coefficients in
//! the monomial and the Bernstein basis.
//!
//! The problem: the values B₀(t), …, B₃(t) of the basis of one segment, and the matrix C
//! with b(t)·C = B(t), b the cubic Bernstein basis [CCKS, §3]. The idea: each Bᵢ is a cubic
//! whose monomial coefficients (after multiplying by δ) are short polynomials in β₁ and β₂:
//!
//! | | 1 | t | t² | t³ |
//! |---|---|---|---|---|
//! | δB₀ | 2β₁³ | −6β₁³ | 6β₁³ | −2β₁³ |
//! | δB₁ | 4β₁² + 4β₁ + β₂ | 6β₁³ − 6β₁ | −(6β₁³ + 6β₁² + 3β₂) | 2β₁³ + 2β₁² + 2β₁ + 2β₂ |
//! | δB₂ | 2 | 6β₁ | 6β₁² + 3β₂ | −(2β₁² + 2β₁ + 2β₂ + 2) |
//! | δB₃ | 0 | 0 | 0 | 2 |
//!
//! (the seed's B₂ drops the t² of its third term: see `docs/design.md`, "Beta-splines"); they
//! are evaluated by Horner's rule. The Bernstein coefficients follow from the monomial ones
//! (the control points of a cubic a + bt + ct² + dt³ are a, a + b/3, a + 2b/3 + c/3,
//! a + b + c + d), and agree with the seed's printed C once its γ is read as 1/δ.
//!
//! Follows [CCKS, §3] (Barsky and Beatty's basis).
//!
//! # Complexity
//!
//! O(1): exactly 16 arithmetic operations for the four values.
//!
//! Invariants the tests check (exactly on rationals): the values sum to one, b(t)·C = B(t) at
//! every sampled t, C·C⁻¹ = I, and β₁ = 1, β₂ = 0 is the uniform cubic B-spline.

use super::{BetaParameters, Matrix4};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::interpolate::linear::solve_dense;
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// The basis, declared.
pub(crate) const BASIS: Declaration = Declaration {
    problem: "beta-spline",
    name: "basis",
    function: "spline::BetaParameters::basis",
    file: "src/spline/beta/basis.rs",
    summary: "the four cubic Beta-spline basis functions at t, by Horner's rule on their monomial coefficients over δ",
    time: "O(1)",
    space: "O(1)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 16 arithmetic operations (12 Horner steps, 4 divisions by δ)",
    source: "[CCKS, §3]",
    claims: &[on("random-parameters", Bound::Linear, Operation::ArithmeticOperations)],
};

impl<S: Scalar> BetaParameters<S> {
    /// The monomial coefficients of δ·Bⱼ: entry `[j][k]` is the coefficient of tᵏ in δBⱼ(t).
    fn scaled_monomial(&self) -> Matrix4<S> {
        let i = |n: i64| S::from_i64(n);
        let b1 = self.beta1().clone();
        let b2 = self.beta2().clone();
        let b1sq = b1.clone() * &b1;
        let b1cu = b1sq.clone() * &b1;
        [
            [
                b1cu.clone() * i(2),
                b1cu.clone() * i(-6),
                b1cu.clone() * i(6),
                b1cu.clone() * i(-2),
            ],
            [
                b1sq.clone() * i(4) + b1.clone() * i(4) + &b2,
                b1cu.clone() * i(6) - b1.clone() * i(6),
                -(b1cu.clone() * i(6) + b1sq.clone() * i(6) + b2.clone() * i(3)),
                b1cu * i(2) + b1sq.clone() * i(2) + b1.clone() * i(2) + b2.clone() * i(2),
            ],
            [
                i(2),
                b1.clone() * i(6),
                b1sq.clone() * i(6) + b2.clone() * i(3),
                -(b1sq * i(2) + b1 * i(2) + b2 * i(2) + i(2)),
            ],
            [i(0), i(0), i(0), i(2)],
        ]
    }

    /// The monomial coefficients of the basis: entry `[j][k]` is the coefficient of tᵏ in
    /// Bⱼ(t) [CCKS, §3], with the normaliser δ (not the seed's 1/(β₂ + 12)).
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    ///
    /// // β₁ = 1, β₂ = 0: B₃(t) = t³/6, the uniform cubic B-spline.
    /// let m = BetaParameters::new(1.0, 0.0)?.monomial_matrix();
    /// assert_eq!(m[3], [0.0, 0.0, 0.0, 2.0 / 12.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn monomial_matrix(&self) -> Matrix4<S> {
        self.scaled_monomial()
            .map(|row| row.map(|x| x / self.delta()))
    }

    /// B₀(t), …, B₃(t). See [`BetaParameters::basis_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"t"` if `t` is NaN
    /// or infinite. Any finite t is evaluated (outside [0, 1] the polynomials' extension).
    ///
    /// # Complexity
    ///
    /// O(1) time, O(1) space.
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    ///
    /// let b = BetaParameters::new(2.0, 3.0)?.basis(&0.5)?;
    /// assert!((b.iter().sum::<f64>() - 1.0).abs() < 1e-15);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn basis(&self, t: &S) -> Result<[S; 4]> {
        self.basis_with(t, &mut NoCount)
    }

    /// B₀(t), …, B₃(t), counting the arithmetic: each δBⱼ by Horner's rule on its monomial
    /// coefficients (three multiply-add steps), then one division by δ.
    ///
    /// Follows [CCKS, §3].
    ///
    /// # Errors
    ///
    /// As [`BetaParameters::basis`].
    ///
    /// # Complexity
    ///
    /// O(1) time, O(1) space.
    ///
    /// # Counts
    ///
    /// Exactly 16 [`arithmetic_operation`](Counter::arithmetic_operation)s.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::BetaParameters;
    ///
    /// let mut c = Counts::default();
    /// let b = BetaParameters::new(1.0, 0.0)?.basis_with(&0.0, &mut c)?;
    /// assert_eq!(b, [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0]);
    /// assert_eq!(c.arithmetic_operations, 16);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn basis_with<C: Counter>(&self, t: &S, counter: &mut C) -> Result<[S; 4]> {
        validate_parameter(t, "t")?;
        let m = self.scaled_monomial();
        Ok(m.map(|row| {
            let mut v = row[3].clone();
            for k in (0..3).rev() {
                counter.arithmetic_operation();
                v = v * t + &row[k];
            }
            counter.arithmetic_operation();
            v / self.delta()
        }))
    }

    /// The values and the first and second derivatives of the basis at t: entry `[r][j]` is
    /// Bⱼ⁽ʳ⁾(t), r = 0, 1, 2.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"t"` if `t` is NaN
    /// or infinite.
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    ///
    /// let d = BetaParameters::new(1.0, 0.0)?.basis_derivatives(&1.0)?;
    /// assert_eq!(d[1], [0.0, -0.5, 0.0, 0.5]); // the B-spline's derivative at a knot
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn basis_derivatives(&self, t: &S) -> Result<[[S; 4]; 3]> {
        validate_parameter(t, "t")?;
        let m = self.monomial_matrix();
        let i = |n: i64| S::from_i64(n);
        let value = |c: &[S; 4]| ((c[3].clone() * t + &c[2]) * t + &c[1]) * t + &c[0];
        let first = |c: &[S; 4]| (c[3].clone() * i(3) * t + &(c[2].clone() * i(2))) * t + &c[1];
        let second = |c: &[S; 4]| c[3].clone() * i(6) * t + &(c[2].clone() * i(2));
        Ok([
            m.clone().map(|c| value(&c)),
            m.clone().map(|c| first(&c)),
            m.map(|c| second(&c)),
        ])
    }

    /// The Bernstein coefficient matrix C of the seed's eq. (7): b(t)·C = B(t), so column j
    /// holds the cubic Bézier control values of Bⱼ, and a segment with control points
    /// P₀, …, P₃ is the Bézier curve with control points C·P [CCKS, §2–3].
    ///
    /// # Complexity
    ///
    /// O(1).
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    ///
    /// // β₁ = 1, β₂ = 0: the B-spline-to-Bézier matrix, rows 1/6 (1 4 1 0), (0 4 2 0), ...
    /// let c = BetaParameters::new(1.0, 0.0)?.bernstein_matrix();
    /// assert_eq!(c[1], [0.0, 4.0 / 6.0, 2.0 / 6.0, 0.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bernstein_matrix(&self) -> Matrix4<S> {
        let m = self.monomial_matrix();
        let third = S::from_ratio(1, 3);
        let mut c: Matrix4<S> = std::array::from_fn(|_| std::array::from_fn(|_| S::zero()));
        for (j, [a, b, cc, d]) in m.iter().enumerate() {
            let b3 = b.clone() * &third;
            let c3 = cc.clone() * &third;
            c[0][j] = a.clone();
            c[1][j] = a.clone() + &b3;
            c[2][j] = a.clone() + &(b3.clone() * S::from_i64(2)) + &c3;
            c[3][j] = a.clone() + b + cc + d;
        }
        c
    }

    /// C⁻¹, by Gaussian elimination (exact with rationals).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"beta2"` if, in
    /// `f64`, rounding makes C singular (β₂ within rounding of −2β₁(β₁ + 1)); never for
    /// rationals, where the validated parameters make det C ≠ 0.
    ///
    /// # Complexity
    ///
    /// O(1).
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    ///
    /// let p = BetaParameters::new(1.0, 0.0)?;
    /// // The first row of C⁻¹ for the uniform B-spline: (6 −7 2 0) (from Bézier to B-spline).
    /// let inv = p.bernstein_matrix_inverse()?;
    /// assert!((inv[0][0] - 6.0).abs() < 1e-12 && (inv[0][1] + 7.0).abs() < 1e-12);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn bernstein_matrix_inverse(&self) -> Result<Matrix4<S>> {
        invert(&self.bernstein_matrix()).ok_or_else(|| Error::InvalidParameter {
            name: "beta2",
            reason: format!(
                "β₂ = {} is so close to −2β₁(β₁ + 1) that C is singular in this arithmetic",
                self.beta2().to_f64()
            ),
        })
    }
}

/// The inverse of a 4 × 4 matrix by Gaussian elimination (the rows of the identity as the
/// right-hand sides); `None` if it is singular.
pub(crate) fn invert<S: Scalar>(a: &Matrix4<S>) -> Option<Matrix4<S>> {
    let rows = a.iter().map(|r| r.to_vec()).collect();
    let identity = (0..4)
        .map(|i| {
            Point::new(std::array::from_fn(|j| {
                if i == j {
                    S::one()
                } else {
                    S::zero()
                }
            }))
        })
        .collect();
    let x = solve_dense(rows, identity)?;
    let mut out: Matrix4<S> = std::array::from_fn(|_| std::array::from_fn(|_| S::zero()));
    for (row, p) in out.iter_mut().zip(x) {
        *row = p.0;
    }
    Some(out)
}

/// The product of two 4 × 4 matrices, counting one arithmetic operation per multiply-add.
pub(crate) fn multiply<S: Scalar, C: Counter>(
    a: &Matrix4<S>,
    b: &Matrix4<S>,
    counter: &mut C,
) -> Matrix4<S> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let mut s = S::zero();
            for k in 0..4 {
                counter.arithmetic_operation();
                s += a[i][k].clone() * &b[k][j];
            }
            s
        })
    })
}
