//! Operations that change a Bézier curve's representation or sample it: batch evaluation,
//! degree elevation
//! (by one and, by Zhou's formula, to any degree), monomial ↔ Bézier conversion, integration,
//! flattening by recursive subdivision and evaluation on a uniform grid by forward
//! differences.
//!
//! Follows `000_f3201fe9758fe02a.txt` §2.7 (integration), §2.8–2.9 (conversions), §3.5
//! (flattening and its error bound), §3.6 (forward differences), §3.11–3.12 (degree
//! elevation, Zhou's formula).

use super::bezier::Bezier;
use super::horner::{
    binomial_coefficient, horner_cubic, horner_line, horner_quadratic, in_registers,
};
use super::scalar::{validate_parameter, validate_points, Point, Scalar};
use crate::{Error, Result};

/// The largest number of segments [`Bezier::flatten`] produces before it reports that the
/// tolerance is too small for the curve.
pub const MAX_FLATTEN_SEGMENTS: usize = 1 << 20;

/// The deepest recursion of [`Bezier::flatten`].
const MAX_FLATTEN_DEPTH: usize = 40;

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// Calls `f(b(tᵢ))` for every parameter tᵢ in order: [`Bezier::eval`] over a batch, for
    /// sampling a curve densely (plotting, tables).
    ///
    /// Idea: the degree is looked at once, so lines, quadratics and cubics run their closed
    /// form of the Horner nesting in a loop of their own, with the control points held in
    /// local variables (registers, for `f64`). Per parameter, one comparison with the curve's
    /// Horner bound (see [`Bezier::eval`]) rules out NaN, ±∞ and any overflow; parameters
    /// that fail it take [`Bezier::eval`]'s checked path, out of line.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming the index of the first NaN or infinite parameter. As
    /// with [`Iterator::try_for_each`], `f` has then been called for every parameter before
    /// that one, in order, and for none after it.
    ///
    /// # Complexity
    ///
    /// Θ(m·nD) time for m parameters, O(D) auxiliary space (as [`Bezier::eval`] per
    /// parameter, overflow case included).
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// let mut ys = Vec::new();
    /// b.eval_each(&[0.0, 0.5, 2.0], |p| ys.push(p[0]))?;
    /// assert_eq!(ys, [0.0, 0.25, 4.0]);
    ///
    /// ys.clear();
    /// assert!(b.eval_each(&[0.5, f64::NAN, 1.0], |p| ys.push(p[0])).is_err());
    /// assert_eq!(ys, [0.25]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    #[inline]
    pub fn eval_each<F: FnMut(Point<S, D>)>(&self, ts: &[S], mut f: F) -> Result<()> {
        if let Some([b0, c1, c2, b3]) = self.cubic_horner_points() {
            let (b0, c1, c2, b3) = (b0.clone(), c1.clone(), c2.clone(), b3.clone());
            return self.each_with(ts, &mut f, |t| {
                horner_cubic(&b0, &c1, &c2, &b3, t, &(S::one() - t))
            });
        }
        match self.control() {
            [b0, b1] => {
                let (b0, b1) = (b0.clone(), b1.clone());
                self.each_with(ts, &mut f, |t| horner_line(&b0, &b1, t, &(S::one() - t)))
            }
            [b0, b1, b2] => {
                let (b0, b1, b2) = (b0.clone(), b1.clone(), b2.clone());
                self.each_with(ts, &mut f, |t| {
                    horner_quadratic(&b0, &b1, &b2, t, &(S::one() - t))
                })
            }
            _ => self.each_with(ts, &mut f, |t| in_registers(self.eval_general(t))),
        }
    }

    /// The same curve with degree n + 1: `cᵢ = i/(n+1) bᵢ₋₁ + (1 − i/(n+1)) bᵢ`.
    ///
    /// Idea: the blossom of degree n + 1 that averages the degree-n blossom over the argument
    /// left out is symmetric, multi-affine and agrees on the diagonal, so its values give the
    /// new Bézier points.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §3.11.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space for the result.
    ///
    /// # Errors
    ///
    /// [`Error::Overflow`] if rounding carries a new point beyond the range of `f64` (only
    /// for coordinates within an ulp of ±`f64::MAX`).
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let line = Bezier::new(vec![Point::new([0.0]), Point::new([2.0])])?;
    /// let q = line.elevate()?;
    /// assert_eq!(q.control(), [Point::new([0.0]), Point::new([1.0]), Point::new([2.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate(&self) -> Result<Self> {
        let b = self.control();
        let n = self.degree();
        let den = (n + 1) as i64;
        let mut control = Vec::with_capacity(n + 2);
        control.push(b[0].clone());
        for i in 1..=n {
            let w = S::from_ratio(i as i64, den);
            let v = S::one() - &w;
            control.push(Point::combine(&b[i - 1], &w, &b[i], &v));
        }
        control.push(b[n].clone());
        Bezier::derived(control, "degree elevation")
    }

    /// The same curve with degree m ≥ n, in one step by Zhou's formula
    /// `dₖ = Σᵢ bᵢ C(n, i) C(m − n, k − i) / C(m, k)`.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §3.12 (Zhou's formula, the polyhypergeometric
    /// distribution).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `m < n` (that would be degree reduction, an
    /// approximation); [`Error::Overflow`] as for [`Bezier::elevate`].
    ///
    /// # Complexity
    ///
    /// Θ(m·n·D) time (each of the m + 1 points sums at most n + 1 terms), Θ(mD) space for the
    /// result.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([3.0])])?;
    /// let e = b.elevate_to(3)?;
    /// assert_eq!(e.control(), (0..4).map(|i| Point::new([i as f64])).collect::<Vec<_>>());
    /// assert!(b.elevate_to(0).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn elevate_to(&self, m: usize) -> Result<Self> {
        let n = self.degree();
        if m < n {
            return Err(Error::InvalidParameter {
                name: "degree",
                reason: format!("cannot elevate a curve of degree {n} to degree {m}"),
            });
        }
        let b = self.control();
        let mut control = Vec::with_capacity(m + 1);
        for k in 0..=m {
            let mut d = Point::zero();
            let den: S = binomial_coefficient(m, k);
            for (i, bi) in b.iter().enumerate().take(k.min(n) + 1) {
                if k - i > m - n {
                    continue;
                }
                let w = binomial_coefficient::<S>(n, i) * binomial_coefficient::<S>(m - n, k - i)
                    / &den;
                d += &(bi.clone() * w);
            }
            control.push(d);
        }
        Bezier::derived(control, "degree elevation")
    }

    /// The coefficients a₀, …, aₙ of the power form `b(t) = Σᵢ aᵢ tⁱ`:
    /// `aᵢ = C(n, i) Δⁱb₀`.
    ///
    /// Idea: the Taylor expansion at t = 0, whose derivatives are differences of the control
    /// points (the seed writes the power basis scaled by C(n, i); here the plain monomials tⁱ).
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.9.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time (the difference table), O(nD) auxiliary space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// // Bézier points 0, 0, 1 are t².
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?;
    /// assert_eq!(b.to_monomial(), [Point::new([0.0]), Point::new([0.0]), Point::new([1.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn to_monomial(&self) -> Vec<Point<S, D>> {
        let n = self.degree();
        let mut q = self.control().to_vec();
        let mut out = Vec::with_capacity(n + 1);
        for i in 0..=n {
            out.push(q[0].clone() * binomial_coefficient::<S>(n, i));
            for j in 0..q.len() - 1 {
                q[j] = q[j + 1].clone() - &q[j];
            }
            q.pop();
        }
        out
    }

    /// The Bézier curve of the power form `Σᵢ aᵢ tⁱ` (degree n = `coefficients.len() − 1`):
    /// `bⱼ = Σ_{i ≤ j} C(j, i)/C(n, i) · aᵢ`.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.8 (with aᵢ there being aᵢ/C(n, i) here).
    ///
    /// # Errors
    ///
    /// [`Error::Empty`] for no coefficients; [`Error::NonFinite`] naming the first
    /// coefficient with a NaN or infinite coordinate; [`Error::Overflow`] if a control point
    /// is beyond the range of `f64`.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) time, Θ(nD) space for the result.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::from_monomial(&[Point::new([1.0]), Point::new([2.0])])?; // 1 + 2t
    /// assert_eq!(b.control(), [Point::new([1.0]), Point::new([3.0])]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_monomial(coefficients: &[Point<S, D>]) -> Result<Self> {
        validate_points(coefficients, "monomial coefficients")?;
        let n = coefficients.len() - 1;
        let scaled: Vec<Point<S, D>> = coefficients
            .iter()
            .enumerate()
            .map(|(i, a)| a.clone() / binomial_coefficient::<S>(n, i))
            .collect();
        let control = (0..=n)
            .map(|j| {
                let mut b = Point::zero();
                for (i, a) in scaled.iter().enumerate().take(j + 1) {
                    b += &(a.clone() * binomial_coefficient::<S>(j, i));
                }
                b
            })
            .collect();
        Bezier::derived(control, "conversion from the monomial form")
    }

    /// The antiderivative with value `start` at t = 0, a curve of degree n + 1:
    /// `c₀ = start`, `cᵢ = cᵢ₋₁ + bᵢ₋₁/(n + 1)`.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.7 (with the interval [0, 1]).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] if `start` has a NaN or infinite coordinate; [`Error::Overflow`]
    /// if a control point is beyond the range of `f64`.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time and space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([2.0])])?; // 2t
    /// let c = b.integral(Point::new([0.0]))?; // t²
    /// assert_eq!(c.control(), [Point::new([0.0]), Point::new([0.0]), Point::new([1.0])]);
    /// assert_eq!(b.definite_integral(), Point::new([1.0]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn integral(&self, start: Point<S, D>) -> Result<Self> {
        validate_points(std::slice::from_ref(&start), "integration constant")?;
        let den = S::from_i64(self.control().len() as i64);
        let mut control = Vec::with_capacity(self.control().len() + 1);
        let mut c = start;
        control.push(c.clone());
        for b in self.control() {
            c += &(b.clone() / &den);
            control.push(c.clone());
        }
        Bezier::derived(control, "integration")
    }

    /// `∫₀¹ b(t) dt = (b₀ + ⋯ + bₙ)/(n + 1)`.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §2.7.
    ///
    /// # Complexity
    ///
    /// Θ(nD) time, O(D) auxiliary space.
    pub fn definite_integral(&self) -> Point<S, D> {
        let mut sum = Point::zero();
        for b in self.control() {
            sum += b;
        }
        sum / S::from_i64(self.control().len() as i64)
    }

    /// A polyline within `tolerance` of the curve segment b[0, 1], by recursive subdivision.
    ///
    /// Idea: the chord b₀bₙ is within `n(n − 1)/8 · max ‖Δ²bᵢ‖∞` of the curve; while that
    /// bound exceeds the tolerance, split at 1/2 and recurse on both halves, else emit the
    /// chord. Each halving divides the second differences by four, so a uniform depth of
    /// ⌈log₄(bound/tolerance)⌉ always suffices; the recursion never goes deeper (on `f64`,
    /// rounding may keep the bound just above a tolerance near the coordinates' precision).
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §3.5 (the program PLOT BÉZIER, its flatness test and
    /// the error bound of the linear interpolant).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `tolerance` is not a positive finite number, or if the
    /// polyline would need more than [`MAX_FLATTEN_SEGMENTS`] segments.
    ///
    /// # Complexity
    ///
    /// Θ(s·n²D) time for s output segments (each subdivision is a de Casteljau triangle);
    /// s ≤ 2ᵏ with k = ⌈log₄(n(n − 1) max ‖Δ²bᵢ‖ / (8·tolerance))⌉, i.e. s = O(√(bound /
    /// tolerance)); O(kn·D) auxiliary space for the recursion.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0, 0.0]), Point::new([1.0, 2.0]), Point::new([2.0, 0.0])])?;
    /// let poly = b.flatten(&0.01)?;
    /// assert_eq!(poly.first(), Some(&Point::new([0.0, 0.0])));
    /// assert_eq!(poly.last(), Some(&Point::new([2.0, 0.0])));
    /// assert!(poly.len() > 4);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn flatten(&self, tolerance: &S) -> Result<Vec<Point<S, D>>> {
        validate_parameter(tolerance, "tolerance")?;
        if *tolerance <= S::zero() {
            return Err(Error::InvalidParameter {
                name: "tolerance",
                reason: format!("must be positive, got {}", tolerance.to_f64()),
            });
        }
        let bound = flatness_bound(self.control());
        let depth = if bound <= *tolerance {
            0
        } else {
            // A cap on the recursion, not a geometric decision: f64 is fine here.
            let ratio = bound.to_f64() / tolerance.to_f64();
            if !ratio.is_finite() {
                return Err(too_many_segments());
            }
            ((ratio.log2() / 2.0).ceil() as usize + 1).min(MAX_FLATTEN_DEPTH)
        };
        let mut out = vec![self.control()[0].clone()];
        flatten_into(self, tolerance, depth, &mut out)?;
        Ok(out)
    }

    /// The points `b(start + i·step)`, i = 0, …, count − 1, by forward differences.
    ///
    /// Idea: on a uniform grid the n-th differences of a degree-n polynomial are constant.
    /// Evaluate the first n + 1 points, build their difference table, then get every further
    /// point with n additions of points.
    ///
    /// Follows `000_f3201fe9758fe02a.txt` §3.6 (and its Obs. 6: numerically less stable than
    /// subdivision; on `f64` errors grow with the number of steps).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] if `start` or `step` is NaN or infinite.
    ///
    /// # Complexity
    ///
    /// Θ(n²D) for the start, then Θ(nD) per point: Θ((n² + count·n)D) time, O(nD) auxiliary
    /// space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?; // t²
    /// let p = b.forward_differences(&0.0, &0.5, 5)?;
    /// assert_eq!(p, [0.0, 0.25, 1.0, 2.25, 4.0].map(|x| Point::new([x])));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn forward_differences(
        &self,
        start: &S,
        step: &S,
        count: usize,
    ) -> Result<Vec<Point<S, D>>> {
        validate_parameter(start, "start")?;
        validate_parameter(step, "step")?;
        let n = self.degree();
        let mut out = Vec::with_capacity(count);
        let mut t = start.clone();
        for _ in 0..count.min(n + 1) {
            out.push(self.eval(&t)?);
            t += step;
        }
        if count <= n + 1 {
            return Ok(out);
        }
        // e[k] = Δᵏp_{n−k}: the last entry of each column of the difference table.
        let mut q = out.clone();
        let mut e = Vec::with_capacity(n + 1);
        e.push(q[n].clone());
        for k in 1..=n {
            for i in 0..=n - k {
                q[i] = q[i + 1].clone() - &q[i];
            }
            e.push(q[n - k].clone());
        }
        // Δⁿp is constant; one step down the table is Δᵏp_{j+1−k} = Δᵏp_{j−k} + Δᵏ⁺¹p_{j−k}.
        for _ in n + 1..count {
            for k in (0..n).rev() {
                e[k] = e[k].clone() + &e[k + 1];
            }
            out.push(e[0].clone());
        }
        Ok(out)
    }
}

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// [`Bezier::eval_each`]'s loop for one evaluation `g` (a closed form, or Horner's
    /// scheme): `g` where the Horner bound allows it, the checked path elsewhere.
    #[inline(always)]
    fn each_with<F, G>(&self, ts: &[S], f: &mut F, g: G) -> Result<()>
    where
        F: FnMut(Point<S, D>),
        G: Fn(&S) -> Point<S, D>,
    {
        for (i, t) in ts.iter().enumerate() {
            let p = if self.horner_is_safe(t) {
                g(t)
            } else {
                in_registers(self.eval_each_slow(i, t)?)
            };
            f(p);
        }
        Ok(())
    }

    /// The checked evaluation of parameter number `index`, out of line (it never sees `f`, so
    /// the caller's closure state can stay in registers).
    #[cold]
    #[inline(never)]
    fn eval_each_slow(&self, index: usize, t: &S) -> Result<Point<S, D>> {
        if !t.is_finite() {
            return Err(Error::InvalidParameter {
                name: "t",
                reason: format!("parameter {index} must be finite, got {}", t.to_f64()),
            });
        }
        Ok(self.eval_general(t))
    }
}

/// `n(n − 1)/8 · max ‖Δ²bᵢ‖∞`, the seed's bound on the distance from the curve to its chord.
pub(crate) fn flatness_bound<S: Scalar, const D: usize>(b: &[Point<S, D>]) -> S {
    let n = b.len() - 1;
    let mut max = S::zero();
    for w in b.windows(3) {
        let second = w[2].clone() - &w[1] - &w[1] + &w[0];
        for c in second.coords() {
            let a = c.abs();
            if a > max {
                max = a;
            }
        }
    }
    max * S::from_ratio((n * n.saturating_sub(1)) as i64, 8)
}

fn flatten_into<S: Scalar, const D: usize>(
    curve: &Bezier<S, D>,
    tolerance: &S,
    depth: usize,
    out: &mut Vec<Point<S, D>>,
) -> Result<()> {
    if depth == 0 || flatness_bound(curve.control()) <= *tolerance {
        if out.len() > MAX_FLATTEN_SEGMENTS {
            return Err(too_many_segments());
        }
        out.push(curve.control()[curve.degree()].clone());
        return Ok(());
    }
    let (left, right) = curve.split_unchecked(&S::from_ratio(1, 2));
    flatten_into(&left, tolerance, depth - 1, out)?;
    flatten_into(&right, tolerance, depth - 1, out)
}

fn too_many_segments() -> Error {
    Error::InvalidParameter {
        name: "tolerance",
        reason: format!(
            "too small for this curve: the polyline would need more than {MAX_FLATTEN_SEGMENTS} segments"
        ),
    }
}
