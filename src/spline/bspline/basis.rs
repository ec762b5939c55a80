//! The B-spline basis: the d + 1 basis functions that do not vanish at a parameter, by the
//! recursion of de Boor, Mansfield and Cox, and their derivatives of any order.
//!
//! N_i^0(u) = 1 on [t_i, t_{i+1}) and 0 elsewhere, and
//! N_i^p(u) = (u − t_i)/(t_{i+p} − t_i)·N_i^{p−1}(u) + (t_{i+p+1} − u)/(t_{i+p+1} − t_{i+1})·N_{i+1}^{p−1}(u),
//! where a term whose denominator is zero is zero (0/0 = 0: its basis function has an empty
//! support and vanishes identically) [PPB, §5.3]. On the span t_μ ≤ u < t_{μ+1} only
//! N_{μ−p}^p, …, N_μ^p are non-zero, so the recursion is a triangle of degree rows
//! (the triangular scheme, as for the Bernstein polynomials [PPB, §2.1, Obs. 1]). In it every
//! denominator is the width t_{μ+r+1} − t_{μ+r+1−p} of a support that contains the non-empty
//! span, never zero, so the convention is never even reached; the derivatives, which also
//! use the basis functions of lower degree off the span, apply it with an exact zero test.
//!
//! Derivatives use d/du N_i^p = p/(t_{i+p} − t_i)·N_i^{p−1} − p/(t_{i+p+1} − t_{i+1})·N_{i+1}^{p−1}
//! [PPB, §5.7] k times: N_i^{(k)} = Σ_j a_{k,j} N_{i+j}^{d−k} with
//! a_{k,j} = (d − k + 1)(a_{k−1,j} − a_{k−1,j−1})/(t_{i+j+d−k+1} − t_{i+j}) (0 when the
//! denominator is 0). A spline of degree d has at most d non-zero derivatives; orders above d
//! are zero.
//!
//! Values are right-continuous (at an interior knot, the piece on its right), except at the
//! end t_n of the domain, which belongs to the last non-empty span (the closed last
//! interval), so clamped vectors give N_{n−1}(t_n) = 1 rather than 0.
//!
//! # Complexity
//!
//! Values: Θ(d²) field operations after the O(log(n − d)) span search, O(d) space.
//! Derivatives up to order k: O(d² + d·K²) field operations with K = min(k, d), and
//! O((k + 1)(d + 1)) space for the table.

use super::KnotVector;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{Point, Scalar};
use crate::{limits, Error, Result};

/// The d + 1 basis functions N_{μ−d}, …, N_μ that do not vanish at a parameter u of span μ:
/// what [`KnotVector::basis`] returns.
///
/// ```
/// use compgeo::spline::KnotVector;
///
/// let t = KnotVector::clamped_uniform(2, 4, 0.0, 2.0)?; // 0 0 0 1 2 2 2
/// let b = t.basis(&0.5)?;
/// assert_eq!((b.span(), b.first()), (2, 0));
/// assert_eq!(b.values(), [0.25, 0.625, 0.125]);
/// assert_eq!((b.get(1), b.get(3)), (0.625, 0.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Basis<S> {
    span: usize,
    values: Vec<S>,
}

impl<S: Scalar> Basis<S> {
    /// The span μ of the parameter (t_μ ≤ u < t_{μ+1}, or the last non-empty span at t_n).
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis(&1.0)?.span(), 2);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn span(&self) -> usize {
        self.span
    }

    /// The index μ − d of the first non-zero basis function.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis(&1.5)?.first(), 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn first(&self) -> usize {
        self.span + 1 - self.values.len()
    }

    /// The values N_{μ−d}(u), …, N_μ(u).
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis(&1.5)?.values(), [0.5, 0.5]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn values(&self) -> &[S] {
        &self.values
    }

    /// N_i(u) for any index i (zero outside μ − d, …, μ).
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let b = KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis(&1.5)?;
    /// assert_eq!((b.get(0), b.get(2)), (0.0, 0.5));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn get(&self, i: usize) -> S {
        i.checked_sub(self.first())
            .and_then(|j| self.values.get(j))
            .cloned()
            .unwrap_or_else(S::zero)
    }

    /// The values, by value.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let b = KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis(&2.0)?;
    /// assert_eq!(b.into_values(), [0.0, 1.0]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn into_values(self) -> Vec<S> {
        self.values
    }
}

/// The derivatives of orders 0, …, k of the d + 1 basis functions N_{μ−d}, …, N_μ that do not
/// vanish at a parameter of span μ: what [`KnotVector::basis_derivatives`] returns.
///
/// ```
/// use compgeo::spline::KnotVector;
///
/// let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0)?; // the Bernstein basis of degree 2
/// let b = t.basis_derivatives(&0.5, 3)?;
/// assert_eq!(b.order(0), [0.25, 0.5, 0.25]);
/// assert_eq!(b.order(1), [-1.0, 0.0, 1.0]);
/// assert_eq!(b.order(2), [2.0, -4.0, 2.0]);
/// assert_eq!(b.order(3), [0.0, 0.0, 0.0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BasisDerivatives<S> {
    span: usize,
    degree: usize,
    /// Row k holds the k-th derivatives, d + 1 values a row.
    table: Vec<S>,
}

impl<S: Scalar> BasisDerivatives<S> {
    /// The span μ of the parameter.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis_derivatives(&0.5, 1)?.span(), 1);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn span(&self) -> usize {
        self.span
    }

    /// The index μ − d of the first non-zero basis function.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis_derivatives(&0.5, 1)?.first(), 0);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn first(&self) -> usize {
        self.span - self.degree
    }

    /// The highest order k computed.
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// assert_eq!(KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis_derivatives(&0.5, 4)?.orders(), 4);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn orders(&self) -> usize {
        self.table.len() / (self.degree + 1) - 1
    }

    /// The k-th derivatives N_{μ−d}^{(k)}(u), …, N_μ^{(k)}(u) (order 0 is the values).
    ///
    /// # Panics
    ///
    /// If `k` exceeds [`orders`](BasisDerivatives::orders).
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let b = KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis_derivatives(&0.5, 2)?;
    /// assert_eq!((b.order(1), b.order(2)), (&[-1.0, 1.0][..], &[0.0, 0.0][..]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn order(&self, k: usize) -> &[S] {
        let w = self.degree + 1;
        &self.table[k * w..(k + 1) * w]
    }

    /// N_i^{(k)}(u) for any index i and order k ≤ [`orders`](BasisDerivatives::orders) (zero
    /// outside μ − d, …, μ).
    ///
    /// # Panics
    ///
    /// If `k` exceeds [`orders`](BasisDerivatives::orders).
    ///
    /// ```
    /// # use compgeo::spline::KnotVector;
    /// let b = KnotVector::clamped_uniform(1, 3, 0.0, 2.0)?.basis_derivatives(&0.5, 1)?;
    /// assert_eq!((b.get(1, 0), b.get(1, 2)), (-1.0, 0.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn get(&self, k: usize, i: usize) -> S {
        let row = self.order(k);
        i.checked_sub(self.first())
            .and_then(|j| row.get(j))
            .cloned()
            .unwrap_or_else(S::zero)
    }
}

impl<S: Scalar> KnotVector<S> {
    /// The d + 1 basis functions N_{μ−d}(u), …, N_μ(u) that do not vanish at `u`, by the
    /// triangular scheme of the Cox–de Boor recursion.
    ///
    /// Idea: find the span μ, then raise the degree one row at a time from N_μ^0 = 1: each
    /// value of degree p − 1 splits between its two neighbours of degree p in the ratios
    /// (t_{μ+r+1} − u)/(t_{μ+r+1} − t_{μ+r+1−p}) and (u − t_{μ+r+1−p})/(same), both in
    /// [0, 1] (so nothing overflows, even with subnormal knot distances), over a denominator
    /// that is never zero. Right-continuous, with the closed last interval (see the
    /// [module](super) docs).
    ///
    /// Follows [PPB, §5.3] (the recursion and the 0/0 convention) and [PPB, §5.4] (the span).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` if `u` is NaN, infinite or outside the domain
    /// [t_d, t_n] (the message names the value and the domain).
    ///
    /// # Complexity
    ///
    /// Θ(d²) field operations after the O(log(n − d)) span search; O(d) space for the output
    /// and two scratch rows.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// // A double knot at 1: the quadratic basis is only C⁰ there.
    /// let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0])?;
    /// assert_eq!(t.basis(&1.0)?.values(), [1.0, 0.0, 0.0]); // N₂(1) = 1: the joint
    /// assert_eq!(t.basis(&2.0)?.values(), [0.0, 0.0, 1.0]); // the closed last interval
    /// assert!(t.basis(&f64::NAN).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn basis(&self, u: &S) -> Result<Basis<S>> {
        self.basis_with(u, &mut NoCount)
    }

    /// [`KnotVector::basis`], counting one [`arithmetic_operation`](Counter::arithmetic_operation)
    /// per step of the triangular scheme (two quotients, two products and a sum: one value of
    /// degree p − 1 split between two of degree p), exactly d(d + 1)/2 per call, and the span
    /// search's [`comparison`](Counter::comparison)s ([`KnotVector::span_with`]).
    ///
    /// # Errors
    ///
    /// As [`KnotVector::basis`].
    ///
    /// # Complexity
    ///
    /// Θ(d²) time (exactly d(d + 1)/2 steps) after the O(log(n − d)) span search; O(d) space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::uniform(3, 8, 0.0, 1.0)?;
    /// let mut c = Counts::default();
    /// let b = t.basis_with(&0.3, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6);
    /// assert!((b.values().iter().sum::<f64>() - 1.0).abs() < 1e-15);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn basis_with<C: Counter>(&self, u: &S, counter: &mut C) -> Result<Basis<S>> {
        let span = self.span_with(u, counter)?;
        let mut values = Vec::with_capacity(self.degree() + 1);
        values.push(S::one());
        for p in 1..=self.degree() {
            self.raise(span, u, &mut values, p, counter);
        }
        Ok(Basis { span, values })
    }

    /// The derivatives of orders 0, …, k of the d + 1 basis functions that do not vanish at
    /// `u` (orders above d are zero).
    ///
    /// Idea: the triangular scheme of [`KnotVector::basis`], keeping the rows of degrees
    /// d − K, …, d (K = min(k, d)); then for each function the coefficients a_{k,j} of
    /// N^{(k)} = Σ_j a_{k,j} N_{i+j}^{d−k}, from the derivative formula applied k times with
    /// the factor d − k + 1 folded in at each step (so no d!/(d − k)! overflows) and a zero
    /// where a support has zero width (0/0 = 0, tested exactly). Right derivatives at
    /// interior knots, left derivatives at the end of the domain.
    ///
    /// Follows [PPB, §5.7] (the derivative of a B-spline) and [PPB, §5.6] (smoothness).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u"` as [`KnotVector::basis`];
    /// [`Error::LimitExceeded`] if `k` exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE) or
    /// the table's (k + 1)(d + 1) values exceed
    /// [`MAX_BASIS_TABLE`](crate::limits::MAX_BASIS_TABLE), before anything is allocated;
    /// [`Error::Overflow`] if, with `f64`, a derivative is beyond the double range (knots a
    /// subnormal distance apart have derivatives near 1/2^−1074).
    ///
    /// # Complexity
    ///
    /// O(d² + d·K²) field operations with K = min(k, d); O((k + 1)(d + 1)) space.
    ///
    /// ```
    /// use compgeo::spline::KnotVector;
    ///
    /// // Uniform cubic B-splines at a knot: the values 1/6, 2/3, 1/6, the first derivatives
    /// // −1/2, 0, 1/2 and the second 1, −2, 1 (and N₃, starting there, is flat to order 2).
    /// let t = KnotVector::new(3, vec![-3.0, -2.0, -1.0, 0.0, 1.0, 2.0, 3.0, 4.0])?;
    /// let b = t.basis_derivatives(&0.0, 2)?;
    /// let want = [[1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0, 0.0], [-0.5, 0.0, 0.5, 0.0], [1.0, -2.0, 1.0, 0.0]];
    /// for (k, row) in want.iter().enumerate() {
    ///     for (got, want) in b.order(k).iter().zip(row) {
    ///         assert!((got - want).abs() < 1e-15, "order {k}: {got} vs {want}");
    ///     }
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn basis_derivatives(&self, u: &S, k: usize) -> Result<BasisDerivatives<S>> {
        self.basis_derivatives_with(u, k, &mut NoCount)
    }

    /// [`KnotVector::basis_derivatives`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per step of the triangular
    /// scheme (d(d + 1)/2) and one per derivative coefficient a_{k,j} (k + 1 for each of the
    /// d + 1 functions and each order 1, …, K): exactly d(d + 1)/2 + (d + 1)·K(K + 3)/2, with
    /// K = min(k, d), plus the span search's [`comparison`](Counter::comparison)s.
    ///
    /// # Errors
    ///
    /// As [`KnotVector::basis_derivatives`].
    ///
    /// # Complexity
    ///
    /// O(d² + d·K²) time with K = min(k, d); O((k + 1)(d + 1)) space.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::KnotVector;
    ///
    /// let t = KnotVector::clamped_uniform(3, 6, 0.0, 1.0)?;
    /// let mut c = Counts::default();
    /// t.basis_derivatives_with(&0.4, 5, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 6 + 4 * 3 * 6 / 2);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn basis_derivatives_with<C: Counter>(
        &self,
        u: &S,
        k: usize,
        counter: &mut C,
    ) -> Result<BasisDerivatives<S>> {
        let d = self.degree();
        limits::DEGREE.check(k as u128)?;
        let w = d + 1;
        let size = limits::BASIS_TABLE.check((k as u128 + 1) * w as u128)?;
        let span = self.span_with(u, counter)?;
        let top = k.min(d);
        // rows[q] holds the degree d − top + q basis at u, q = 0..=top (d − top + q + 1 values).
        let mut rows: Vec<Vec<S>> = Vec::with_capacity(top + 1);
        let mut values = Vec::with_capacity(w);
        values.push(S::one());
        for p in 1..=d {
            if p > d - top {
                rows.push(values.clone());
            }
            self.raise(span, u, &mut values, p, counter);
        }
        rows.push(values);
        let t = self.knots();
        let mut table = Vec::with_capacity(size);
        table.extend(rows[top].iter().cloned());
        // coefficients[f][j]: a_{q,j} of function f = 0..=d (index span − d + f).
        let mut coefficients: Vec<Vec<S>> = vec![vec![S::one()]; w];
        for q in 1..=top {
            let p = d - q; // the degree of the functions the q-th derivative combines
            let factor = S::from_i64((p + 1) as i64);
            let lower = &rows[top - q];
            for (f, a) in coefficients.iter_mut().enumerate() {
                let i = span - d + f;
                let mut next = Vec::with_capacity(q + 1);
                for j in 0..=q {
                    counter.arithmetic_operation();
                    let (lo, hi) = (&t[i + j], &t[i + j + p + 1]);
                    if lo == hi {
                        next.push(S::zero());
                        continue;
                    }
                    let mut diff = a.get(j).cloned().unwrap_or_else(S::zero);
                    if j > 0 {
                        diff -= &a[j - 1];
                    }
                    next.push(quotient(factor.clone() * diff, lo, hi));
                }
                *a = next;
            }
            // N^{(q)}_{i} = Σ_j a_{q,j} N^{p}_{i+j}; the degree-p row starts at span − p.
            for (f, a) in coefficients.iter().enumerate() {
                let mut sum = S::zero();
                for (j, c) in a.iter().enumerate() {
                    // Index of N^p_{i+j} in its row: i + j − (span − p) = f + j − q.
                    if let Some(v) = (f + j).checked_sub(q).and_then(|r| lower.get(r)) {
                        sum += c.clone() * v;
                    }
                }
                table.push(sum);
            }
        }
        table.resize(size, S::zero());
        if table.iter().any(|v| !v.is_finite()) {
            return Err(Error::Overflow {
                what: "B-spline basis derivative",
            });
        }
        Ok(BasisDerivatives {
            span,
            degree: d,
            table,
        })
    }

    /// One row of the triangular scheme: `values` holds N_{μ−p+1}^{p−1}, …, N_μ^{p−1} at `u`
    /// and becomes N_{μ−p}^p, …, N_μ^p.
    fn raise<C: Counter>(
        &self,
        span: usize,
        u: &S,
        values: &mut Vec<S>,
        p: usize,
        counter: &mut C,
    ) {
        let t = self.knots();
        let mut saved = S::zero();
        for r in 0..p {
            counter.arithmetic_operation();
            // values[r] = N_{μ−p+1+r}^{p−1}, whose support's degree-p neighbours share
            // [lo, hi] = [t_{μ+r+1−p}, t_{μ+r+1}], which contains the span: lo < hi.
            let (lo, hi) = (&t[span + r + 1 - p], &t[span + r + 1]);
            let (right, left) = ratios(lo, u, hi);
            let v = std::mem::replace(&mut values[r], S::zero());
            values[r] = saved + right * &v;
            saved = left * &v;
        }
        values.push(saved);
    }
}

/// ((hi − u)/(hi − lo), (u − lo)/(hi − lo)) for lo ≤ u ≤ hi and lo < hi: both in [0, 1].
///
/// With `f64`, when a difference overflows (knots farther apart than the double range) every
/// term is halved first, which is exact for the normal numbers such knots are and leaves the
/// ratios unchanged.
pub(super) fn ratios<S: Scalar>(lo: &S, u: &S, hi: &S) -> (S, S) {
    let width = hi.clone() - lo;
    if width.is_finite() {
        let right = hi.clone() - u;
        let left = u.clone() - lo;
        return (right / &width, left / &width);
    }
    let half = S::from_ratio(1, 2);
    let (lo, u, hi) = (lo.clone() * &half, u.clone() * &half, hi.clone() * &half);
    let width = hi.clone() - &lo;
    let right = hi - &u;
    let left = u - &lo;
    (right / &width, left / &width)
}

/// x/(hi − lo) for lo < hi; with `f64`, when the width overflows, (x/2)/(hi/2 − lo/2).
pub(super) fn quotient<S: Scalar>(x: S, lo: &S, hi: &S) -> S {
    let width = hi.clone() - lo;
    if width.is_finite() {
        return x / width;
    }
    let half = S::from_ratio(1, 2);
    let width = hi.clone() * &half - lo.clone() * &half;
    x * &half / width
}

/// The affine combination ((hi − x)·a + (x − lo)·b)/(hi − lo) of two points, for lo < hi and
/// any finite x (outside [lo, hi] it extrapolates: the blossoms and degree elevation).
///
/// The weights are [`ratios`], as everywhere in this module, and where that gives finite
/// coordinates (always with rationals) it is the result. With `f64` a coordinate can come
/// out infinite or NaN although its exact value is in range: inside [lo, hi] a convex
/// combination of two coordinates near `f64::MAX` can round past it, and outside, a weight
/// overflows where the width hi − lo is subnormal (∞·0 = NaN for a zero coordinate). Such a
/// coordinate is recomputed: inside, clamped between the two coordinates (where the exact
/// value lies); outside, as a + (x − lo)(b − a)/(hi − lo) with the product and quotient
/// taken on mantissas and exponents ([`mul_div`]), so that only a value truly beyond the
/// range comes out infinite (and a constant stays exactly constant).
pub(super) fn affine<S: Scalar, const D: usize>(
    a: &Point<S, D>,
    lo: &S,
    x: &S,
    hi: &S,
    b: &Point<S, D>,
) -> Point<S, D> {
    let (right, left) = ratios(lo, x, hi);
    let p = Point::combine(a, &right, b, &left);
    if p.is_finite() {
        return p;
    }
    let inside = lo <= x && x <= hi;
    let (lo, x, hi) = (lo.to_f64(), x.to_f64(), hi.to_f64());
    Point::new(std::array::from_fn(|j| {
        if p[j].is_finite() {
            return p[j].clone();
        }
        let (aj, bj) = (a[j].to_f64(), b[j].to_f64());
        let v = if aj == bj {
            aj
        } else if inside {
            if p[j] > S::zero() {
                aj.max(bj)
            } else {
                aj.min(bj)
            }
        } else {
            // Beyond both points: a difference out of range puts the value out of range too.
            let (_, from_lo, width) = distances(lo, x, hi);
            let diff = bj - aj;
            if diff.is_finite() {
                aj + mul_div(from_lo, diff, width)
            } else {
                diff
            }
        };
        S::from_f64(v).unwrap_or_else(|| p[j].clone())
    }))
}

/// ((hi − x)·v/(hi − lo), (x − lo)·v/(hi − lo)): the value v split by the [`ratios`], for
/// lo < hi and any finite x (the discrete B-splines of the Oslo algorithm). Where a product
/// is not finite (a ratio overflows for x far outside a subnormal width), both are taken by
/// [`mul_div`], so that a zero v splits into zeros rather than ∞·0 = NaN and only a value
/// truly beyond the range is infinite.
pub(super) fn split_value<S: Scalar>(v: &S, lo: &S, x: &S, hi: &S) -> (S, S) {
    let (right, left) = ratios(lo, x, hi);
    let (r, l) = (right * v, left * v);
    if r.is_finite() && l.is_finite() {
        return (r, l);
    }
    let (to_hi, from_lo, width) = distances(lo.to_f64(), x.to_f64(), hi.to_f64());
    let v = v.to_f64();
    let back = |y: f64, fallback: S| S::from_f64(y).unwrap_or(fallback);
    (
        back(mul_div(to_hi, v, width), r),
        back(mul_div(from_lo, v, width), l),
    )
}

/// x·y/z for z ≠ 0: exact with rationals; with `f64` rounded once at the end ([`mul_div`]),
/// so that neither y/z nor x·y underflows or overflows on the way (the integral's
/// c·(t_{i+d+1} − tᵢ)/(d + 1) with a subnormal width beside a coordinate near 1e308).
pub(super) fn product_quotient<S: Scalar>(x: &S, y: &S, z: &S) -> S {
    let naive = || x.clone() * y / z;
    if S::EXACT {
        return naive();
    }
    let (x, y, z) = (x.to_f64(), y.to_f64(), z.to_f64());
    let v = if y.is_finite() && x.is_finite() {
        mul_div(x, y, z)
    } else {
        f64::NAN
    };
    S::from_f64(v).unwrap_or_else(naive)
}

/// (hi − x, x − lo, hi − lo), all three halved first if one of them overflows (the ratios
/// stay the same; halving is exact for the normal numbers such distances come from).
fn distances(lo: f64, x: f64, hi: f64) -> (f64, f64, f64) {
    let d = (hi - x, x - lo, hi - lo);
    if d.0.is_finite() && d.1.is_finite() && d.2.is_finite() {
        return d;
    }
    (hi / 2.0 - x / 2.0, x / 2.0 - lo / 2.0, hi / 2.0 - lo / 2.0)
}

/// p·q/w for finite p, q and a finite non-zero w, rounded once at the end (and twice on the
/// mantissas): no intermediate overflows or underflows, so the result is infinite only
/// when the value is beyond the double range.
fn mul_div(p: f64, q: f64, w: f64) -> f64 {
    if p == 0.0 || q == 0.0 {
        return 0.0;
    }
    let ((mp, ep), (mq, eq), (mw, ew)) = (frexp(p), frexp(q), frexp(w));
    ldexp(mp * mq / mw, ep + eq - ew)
}

/// (m, e) with x = m·2^e and 1/2 ≤ |m| < 1, for a finite non-zero x (subnormals included).
fn frexp(x: f64) -> (f64, i32) {
    let (x, shift) = if x.abs() < f64::MIN_POSITIVE {
        (x * ldexp(1.0, 64), -64)
    } else {
        (x, 0)
    };
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i32 - 1022;
    let m = f64::from_bits((bits & !(0x7ff << 52)) | (1022 << 52));
    (m, e + shift)
}

/// m·2^e by steps of normal powers of two, in one direction (so a result in the normal
/// range is exact, and one below it rounds at most twice).
fn ldexp(mut m: f64, mut e: i32) -> f64 {
    let power = |e: i32| f64::from_bits(((e + 1023) as u64) << 52);
    while e > 1000 {
        m *= power(1000);
        e -= 1000;
    }
    while e < -1000 {
        m *= power(-1000);
        e += 1000;
    }
    m * power(e)
}

/// The basis, declared.
pub(crate) const BASIS: Declaration = Declaration {
    problem: "bspline",
    name: "basis",
    function: "spline::KnotVector::basis",
    file: "src/spline/bspline/basis.rs",
    summary: "the d + 1 non-zero B-splines at a parameter by the Cox–de Boor triangle",
    time: "Θ(d²)",
    space: "O(d)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly d(d + 1)/2 steps of the triangular scheme",
    source: "[PPB, §5.3]",
    claims: &[
        on(
            "random-degree",
            Bound::Quadratic,
            Operation::ArithmeticOperations,
        ),
        on(
            "random-control",
            Bound::Constant,
            Operation::ArithmeticOperations,
        ),
    ],
};

/// The basis derivatives, declared.
pub(crate) const BASIS_DERIVATIVES: Declaration = Declaration {
    problem: "bspline",
    name: "basis-derivatives",
    function: "spline::KnotVector::basis_derivatives",
    file: "src/spline/bspline/basis.rs",
    summary: "derivatives of orders 0 to k of the non-zero B-splines at a parameter",
    time: "O(d² + d·K²)",
    space: "O((k + 1)(d + 1))",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly d(d + 1)/2 + (d + 1)·K(K + 3)/2 steps, K = min(k, d)",
    source: "[PPB, §5.7]",
    claims: &[
        on(
            "random-degree",
            Bound::Quadratic,
            Operation::ArithmeticOperations,
        ),
        on(
            "all-derivatives",
            Bound::Cubic,
            Operation::ArithmeticOperations,
        ),
        on(
            "random-control",
            Bound::Constant,
            Operation::ArithmeticOperations,
        ),
    ],
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::bernstein_all;

    #[test]
    fn clamped_without_interior_knots_is_the_bernstein_basis() {
        // [PPB, §5.3, Obs. 1]: N_i^d = B_i^d on [0, 1].
        for d in 0..=7 {
            let t = KnotVector::clamped_uniform(d, d + 1, 0.0, 1.0).unwrap();
            for k in 0..=16 {
                let u = k as f64 / 16.0;
                let b = t.basis(&u).unwrap();
                let want: Vec<f64> = bernstein_all(d, &u).unwrap();
                for (x, y) in b.values().iter().zip(&want) {
                    assert!((x - y).abs() < 1e-15, "d = {d}, u = {u}: {x} vs {y}");
                }
            }
        }
    }

    #[test]
    fn a_knot_of_multiplicity_d_plus_one_splits_the_basis() {
        // A discontinuity at 1: the values jump, the derivatives skip the empty supports.
        let t = KnotVector::new(1, vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]).unwrap();
        assert_eq!(t.basis(&1.0).unwrap().values(), [1.0, 0.0]);
        assert_eq!(t.basis(&1.0).unwrap().first(), 2);
        let left = t.basis(&0.75).unwrap();
        assert_eq!((left.first(), left.values()), (0, &[0.25, 0.75][..]));
        let der = t.basis_derivatives(&1.0, 3).unwrap();
        assert_eq!(der.order(1), [-1.0, 1.0]);
        assert_eq!(
            (der.order(2), der.order(3)),
            (&[0.0, 0.0][..], &[0.0, 0.0][..])
        );
    }

    #[test]
    fn mul_div_rounds_once_where_the_steps_would_underflow_or_overflow() {
        use num_rational::BigRational;
        let cases = [
            (-9.9911551518932e307, 5e-324, 4.0),
            (1e-200, 1e-200, 5e-324),
            (1e300, 1e300, 1e300),
            (3.0, 7e-310, 1e-320),
        ];
        for (p, q, w) in cases {
            let exact = BigRational::from_float(p).unwrap() * BigRational::from_float(q).unwrap()
                / BigRational::from_float(w).unwrap();
            let got = BigRational::from_float(mul_div(p, q, w)).unwrap();
            let err = (got - &exact).abs();
            let want = exact.to_f64();
            assert!(
                err <= BigRational::from_float(4.0 * f64::EPSILON * want.abs()).unwrap(),
                "{p}·{q}/{w}"
            );
        }
        assert_eq!(mul_div(0.0, 1e308, 5e-324), 0.0);
        assert_eq!(mul_div(1e308, 1e308, 1.0), f64::INFINITY);
    }

    #[test]
    fn affine_keeps_a_constant_beyond_a_subnormal_width() {
        let a = Point::new([3.0, 0.0]);
        // The weights (1e-323 − 0.5)/5e-324 and (0.5 − 5e-324)/5e-324 overflow.
        assert_eq!(affine(&a, &5e-324, &0.5, &1e-323, &a), a);
        let b = Point::new([3.0, 5e-324]);
        let p = affine(&a, &5e-324, &1e-323f64.next_up(), &1e-323, &b);
        assert_eq!(p, Point::new([3.0, 1e-323]));
        let m = Point::new([f64::MAX, -f64::MAX]);
        for k in 1..10 {
            let x = f64::from(k) / 10.0;
            assert!(affine(&m, &0.0, &x, &1.0, &m).is_finite(), "{x}");
        }
        let (r, l) = split_value(&0.0, &5e-324, &0.5, &1e-323);
        assert_eq!((r, l), (0.0, 0.0));
    }

    #[test]
    fn ratios_survive_widths_beyond_the_double_range() {
        let m = f64::MAX;
        let (right, left) = ratios(&-m, &0.0, &m);
        assert_eq!((right, left), (0.5, 0.5));
        assert_eq!(quotient(1.0, &-m, &m), 0.5 / m);
    }
}
