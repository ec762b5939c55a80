//! The subdivision matrices of a cubic Beta-spline segment, S_L = C⁻¹·S_Lᴮ·C and
//! S_R = C⁻¹·S_Rᴮ·C, for any c in (0, 1); Lemma 1's formula as a cross-check; the
//! convex-hull predicate.
//!
//! The problem: matrices S_L, S_R with B(ct) = B(t)·S_L and B(c + (1 − c)t) = B(t)·S_R, so
//! that the control polygons L = S_L·P and R = S_R·P describe the segment's pieces over
//! [0, c] and [c, 1], each reparametrised to [0, 1] [CCKS, §2, eq. (1)–(3)]. The idea: in the
//! Bernstein basis the matrices are de Casteljau's, S_Lᴮ with rows b⁰(c), b¹(c), b²(c), b³(c)
//! (eq. (5)) and S_Rᴮ with rows b³(c), b²(c) shifted right, … (eq. (6)); a change of basis by
//! the Bernstein coefficient matrix C gives eq. (7) and (8). S_R is computed from eq. (8)
//! always: it is the reversal of S_L (rᵢⱼ = l₃₋ᵢ,₃₋ⱼ, the seed's shortcut) only when β₁ = 1 and
//! c = ½, because reversing the parameter maps a Beta-spline with bias β₁ to one with bias
//! 1/β₁.
//!
//! Lemma 1 gives the same matrices from basis values: S_L = B(T)⁻¹·B(cT) for any four
//! distinct nodes T in [0, 1] ([`BetaParameters::subdivision_matrices_by_interpolation`]).
//! Lemma 4: the subdivided polygon stays in the convex hull of the original one for every
//! control polygon if and only if the matrix has no negative entry (its rows sum to one by
//! Lemma 3) ([`SubdivisionMatrices::keeps_convex_hull`]).
//!
//! Follows [CCKS, §2, Lemmas 1–4, eq. (5)–(8)], after Goldman and DeRose.
//!
//! # Complexity
//!
//! O(1): four 4 × 4 products (256 multiply-adds) and one 4 × 4 inversion.
//!
//! Invariants the tests check (exactly on rationals): the seed's printed matrices, eq. (1) at
//! sampled t, Lemma 1 = eq. (7)/(8), rows summing to one, and that the pieces L and R
//! evaluate to the segment on [0, c] and [c, 1].

use super::basis::{invert, multiply};
use super::{BetaParameters, Matrix4};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{binomial, power, validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// The subdivision matrices, declared.
pub(crate) const MATRICES: Declaration = Declaration {
    problem: "beta-spline",
    name: "subdivision-matrices",
    function: "spline::BetaParameters::subdivision_matrices",
    file: "src/spline/beta/matrices.rs",
    summary: "S_L = C⁻¹ S_Lᴮ C and S_R = C⁻¹ S_Rᴮ C at any c in (0, 1), from de Casteljau's matrices in the Bernstein basis",
    time: "O(1)",
    space: "O(1)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly 256 multiply-adds (four 4 × 4 products), besides one 4 × 4 inversion",
    source: "[CCKS, §2, eq. (7)–(8)]",
    claims: &[on("random-parameters", Bound::Linear, Operation::ArithmeticOperations)],
};

/// The left and right subdivision matrices of a cubic Beta-spline segment at a parameter c:
/// L = S_L·P and R = S_R·P are the control polygons of the pieces over [0, c] and [c, 1]
/// [CCKS, §2].
///
/// ```
/// use compgeo::spline::BetaParameters;
/// use num_rational::BigRational as Q;
///
/// let q = |n: i64, d: i64| Q::new(n.into(), d.into());
/// let m = BetaParameters::new(q(1, 1), q(0, 1))?.subdivision_matrices(&q(1, 2))?;
/// // The cubic B-spline's mask, exactly (in f64 it is right to rounding).
/// assert_eq!(m.left()[1], [q(1, 8), q(3, 4), q(1, 8), q(0, 1)]);
/// assert!(m.keeps_convex_hull());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SubdivisionMatrices<S> {
    left: Matrix4<S>,
    right: Matrix4<S>,
}

impl<S: Scalar> BetaParameters<S> {
    /// S_L and S_R at `c` by the seed's eq. (7) and (8). See
    /// [`BetaParameters::subdivision_matrices_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"c"` if `c` is NaN, infinite or not strictly between
    /// 0 and 1; as [`BetaParameters::bernstein_matrix_inverse`].
    ///
    /// # Complexity
    ///
    /// O(1) time, O(1) space.
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    ///
    /// let m = BetaParameters::new(2.0, 1.0)?.subdivision_matrices(&0.25)?;
    /// for row in m.left().iter().chain(m.right()) {
    ///     assert!((row.iter().sum::<f64>() - 1.0).abs() < 1e-12); // Lemma 3
    /// }
    /// assert!(BetaParameters::new(1.0, 0.0)?.subdivision_matrices(&1.0).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn subdivision_matrices(&self, c: &S) -> Result<SubdivisionMatrices<S>> {
        self.subdivision_matrices_with(c, &mut NoCount)
    }

    /// S_L = C⁻¹·S_Lᴮ·C and S_R = C⁻¹·S_Rᴮ·C, counting the products' multiply-adds.
    ///
    /// Follows [CCKS, §2, eq. (5)–(8)].
    ///
    /// # Errors
    ///
    /// As [`BetaParameters::subdivision_matrices`].
    ///
    /// # Complexity
    ///
    /// O(1) time, O(1) space.
    ///
    /// # Counts
    ///
    /// Exactly 256 [`arithmetic_operation`](Counter::arithmetic_operation)s (four 4 × 4
    /// products); the inversion of C and the Bernstein values are not counted.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::BetaParameters;
    ///
    /// let mut c = Counts::default();
    /// BetaParameters::new(1.0, 5.0)?.subdivision_matrices_with(&0.5, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 256);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn subdivision_matrices_with<C: Counter>(
        &self,
        c: &S,
        counter: &mut C,
    ) -> Result<SubdivisionMatrices<S>> {
        check_split_parameter(c)?;
        let cm = self.bernstein_matrix();
        let inv = self.bernstein_matrix_inverse()?;
        let (left_b, right_b) = bezier_subdivision(c);
        let left = multiply(&inv, &multiply(&left_b, &cm, counter), counter);
        let right = multiply(&inv, &multiply(&right_b, &cm, counter), counter);
        Ok(SubdivisionMatrices { left, right })
    }

    /// S_L = B(T)⁻¹·B(cT) and S_R = B(T)⁻¹·B(c + (1 − c)T), the seed's Lemma 1, from basis
    /// values at four nodes T: the same matrices as eq. (7)–(8), computed independently of C.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"c"` as in
    /// [`BetaParameters::subdivision_matrices`]; named `"nodes"` if a node is NaN, infinite
    /// or outside [0, 1], or two nodes are equal (then B(T) is singular).
    ///
    /// # Complexity
    ///
    /// O(1).
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    /// use num_rational::BigRational as Q;
    ///
    /// let q = |n: i64, d: i64| Q::new(n.into(), d.into());
    /// let p = BetaParameters::new(q(3, 2), q(1, 1))?;
    /// let nodes = [q(0, 1), q(1, 3), q(2, 3), q(1, 1)];
    /// let by_lemma = p.subdivision_matrices_by_interpolation(&q(2, 5), &nodes)?;
    /// assert_eq!(by_lemma, p.subdivision_matrices(&q(2, 5))?);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn subdivision_matrices_by_interpolation(
        &self,
        c: &S,
        nodes: &[S; 4],
    ) -> Result<SubdivisionMatrices<S>> {
        check_split_parameter(c)?;
        for (k, t) in nodes.iter().enumerate() {
            let inside = t.is_finite() && *t >= S::zero() && *t <= S::one();
            let repeated = nodes[..k].contains(t);
            if !inside || repeated {
                return Err(Error::InvalidParameter {
                    name: "nodes",
                    reason: format!(
                        "Lemma 1 needs four distinct nodes in [0, 1]; node {k} is {}",
                        t.to_f64()
                    ),
                });
            }
        }
        let rows = |ts: [S; 4]| -> Result<Matrix4<S>> {
            let mut m: Matrix4<S> = std::array::from_fn(|_| std::array::from_fn(|_| S::zero()));
            for (row, t) in m.iter_mut().zip(&ts) {
                *row = self.basis(t)?;
            }
            Ok(m)
        };
        let at_nodes = rows(nodes.clone())?;
        let inv = invert(&at_nodes).ok_or_else(|| Error::InvalidParameter {
            name: "nodes",
            reason: "B(T) is singular in this arithmetic".to_string(),
        })?;
        let one_minus_c = S::one() - c;
        let left_nodes = nodes.clone().map(|t| c.clone() * &t);
        let right_nodes = nodes
            .clone()
            .map(|t| c.clone() + &(one_minus_c.clone() * &t));
        Ok(SubdivisionMatrices {
            left: multiply(&inv, &rows(left_nodes)?, &mut NoCount),
            right: multiply(&inv, &rows(right_nodes)?, &mut NoCount),
        })
    }
}

impl<S: Scalar> SubdivisionMatrices<S> {
    /// S_L: row i holds the weights of the left polygon's point Lᵢ.
    pub fn left(&self) -> &Matrix4<S> {
        &self.left
    }

    /// S_R: row i holds the weights of the right polygon's point Rᵢ.
    pub fn right(&self) -> &Matrix4<S> {
        &self.right
    }

    /// `true` if S_L has no negative entry: by the seed's Lemma 4, the left polygon then
    /// lies in the convex hull of every control polygon it is computed from, and only then.
    ///
    /// # Complexity
    ///
    /// O(1): 16 comparisons.
    pub fn left_keeps_convex_hull(&self) -> bool {
        is_nonnegative(&self.left)
    }

    /// `true` if S_R has no negative entry (Lemma 4 for the right polygon).
    ///
    /// # Complexity
    ///
    /// O(1): 16 comparisons.
    pub fn right_keeps_convex_hull(&self) -> bool {
        is_nonnegative(&self.right)
    }

    /// The convex-hull predicate of [CCKS, §2, Lemma 4]: `true` if neither matrix has a
    /// negative entry, so that both subdivided polygons lie in the convex hull of the
    /// original one whatever its points.
    ///
    /// # Complexity
    ///
    /// O(1): at most 32 comparisons.
    ///
    /// ```
    /// use compgeo::spline::BetaParameters;
    ///
    /// // The seed's second example: with tension β₂ = 5 the first and last rows of S_L have
    /// // negative entries.
    /// let m = BetaParameters::new(1.0, 5.0)?.subdivision_matrices(&0.5)?;
    /// assert!(!m.keeps_convex_hull());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn keeps_convex_hull(&self) -> bool {
        self.left_keeps_convex_hull() && self.right_keeps_convex_hull()
    }

    /// The two polygons L = S_L·P and R = S_R·P of one segment. See
    /// [`SubdivisionMatrices::split_with`].
    ///
    /// # Complexity
    ///
    /// O(D) time and space.
    ///
    /// ```
    /// use compgeo::spline::{BetaParameters, Point};
    /// use num_rational::BigRational as Q;
    ///
    /// let q = |n: i64| Q::from_integer(n.into());
    /// let m = BetaParameters::new(q(1), q(0))?.subdivision_matrices(&(q(1) / q(2)))?;
    /// let p = [0, 8, 16, 24].map(|x| Point::new([q(x)]));
    /// let (l, r) = m.split(&p);
    /// assert_eq!(l, [4, 8, 12, 16].map(|x| Point::new([q(x)])));
    /// assert_eq!(r, [8, 12, 16, 20].map(|x| Point::new([q(x)])));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn split<const D: usize>(
        &self,
        polygon: &[Point<S, D>; 4],
    ) -> ([Point<S, D>; 4], [Point<S, D>; 4]) {
        self.split_with(polygon, &mut NoCount)
    }

    /// L = S_L·P and R = S_R·P, counting one arithmetic operation per point scaled and
    /// added.
    ///
    /// Follows [CCKS, §2, eq. (3)].
    ///
    /// # Complexity
    ///
    /// O(D) time and space.
    ///
    /// # Counts
    ///
    /// Exactly 32 [`arithmetic_operation`](Counter::arithmetic_operation)s (16 per polygon).
    pub fn split_with<const D: usize, C: Counter>(
        &self,
        polygon: &[Point<S, D>; 4],
        counter: &mut C,
    ) -> ([Point<S, D>; 4], [Point<S, D>; 4]) {
        let apply = |m: &Matrix4<S>, counter: &mut C| {
            m.clone().map(|row| {
                let mut p = Point::zero();
                for (w, q) in row.iter().zip(polygon) {
                    counter.arithmetic_operation();
                    p += &(q.clone() * w);
                }
                p
            })
        };
        (apply(&self.left, counter), apply(&self.right, counter))
    }
}

/// `true` if no entry of `m` is negative.
fn is_nonnegative<S: Scalar>(m: &Matrix4<S>) -> bool {
    m.iter().flatten().all(|x| *x >= S::zero())
}

/// Rejects a split parameter that is not strictly between 0 and 1.
fn check_split_parameter<S: Scalar>(c: &S) -> Result<()> {
    validate_parameter(c, "c")?;
    if *c <= S::zero() || *c >= S::one() {
        return Err(Error::InvalidParameter {
            name: "c",
            reason: format!(
                "the subdivision parameter must be strictly between 0 and 1, got {}",
                c.to_f64()
            ),
        });
    }
    Ok(())
}

/// De Casteljau's subdivision matrices of a cubic Bézier curve at c, eq. (5) and (6):
/// S_Lᴮ[i][j] = bⱼⁱ(c) (j ≤ i) and S_Rᴮ[i][j] = b_{j−i}^{3−i}(c) (j ≥ i).
fn bezier_subdivision<S: Scalar>(c: &S) -> (Matrix4<S>, Matrix4<S>) {
    let one_minus_c = S::one() - c;
    let bern = |i: usize, n: usize| -> S {
        binomial::<S>(n, i) * power(c, i) * &power(&one_minus_c, n - i)
    };
    let left = std::array::from_fn(|i| {
        std::array::from_fn(|j| if j <= i { bern(j, i) } else { S::zero() })
    });
    let right = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if j >= i {
                bern(j - i, 3 - i)
            } else {
                S::zero()
            }
        })
    });
    (left, right)
}
