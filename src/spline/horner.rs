//! Horner-type evaluation of Bézier curves (`000_f3201fe9758fe02a.txt` §2.3, Obs. 4) and
//! what makes it fast on `f64`: the nesting itself (closed forms for degrees 1 to 3, a loop
//! with tabulated binomials above), the control polygon's storage (lines, quadratics and
//! cubics inline, cubics with their binomially scaled points), the bound on |t| under which no
//! step can overflow, and the checked path beyond it (de Casteljau's algorithm when Horner's
//! scheme overflows).
//!
//! The public entry points are on [`Bezier`]: `eval`, `at`, `horner`, `horner_with` (in
//! `bezier.rs`) and `eval_each` (in `bezier_ops.rs`). The `spline` benchmark compares them
//! with a hand-written `f64` cubic and kurbo.

use super::bezier::Bezier;
use super::scalar::{binomial, validate_parameter, Point, Scalar};
use crate::count::{Counter, NoCount};
use crate::Result;

/// A control polygon: lines, quadratics and cubics inline, other degrees on the heap.
///
/// Inline, the points of a borrowed curve are part of the borrowed value, which the compiler
/// knows nothing modifies during the borrow: a loop evaluating the curve loads them once,
/// even though the loop also contains the (rare) out-of-line calls of the checked path. On
/// the heap they would be reloaded at every evaluation. The variant is also the degree
/// dispatch of the closed forms.
#[derive(Clone)]
pub(super) enum Polygon<S, const D: usize> {
    Line([Point<S, D>; 2]),
    Quadratic([Point<S, D>; 3]),
    /// With 3b₁ and 3b₂, the scaled points of Horner's nesting, computed once.
    Cubic([Point<S, D>; 4], [Point<S, D>; 2]),
    /// Degree 0, or degree 4 and more.
    Other(Vec<Point<S, D>>),
}

impl<S: Scalar, const D: usize> Polygon<S, D> {
    /// The polygon of these points (at least one).
    pub(super) fn new(control: Vec<Point<S, D>>) -> Self {
        match <[_; 2]>::try_from(control) {
            Ok(b) => Polygon::Line(b),
            Err(control) => match <[_; 3]>::try_from(control) {
                Ok(b) => Polygon::Quadratic(b),
                Err(control) => match <[_; 4]>::try_from(control) {
                    Ok(b) => {
                        let three = S::from_i64(3);
                        let scaled = [b[1].clone() * &three, b[2].clone() * &three];
                        Polygon::Cubic(b, scaled)
                    }
                    Err(control) => Polygon::Other(control),
                },
            },
        }
    }

    /// The points, by value.
    pub(super) fn into_vec(self) -> Vec<Point<S, D>> {
        match self {
            Polygon::Line(b) => b.into(),
            Polygon::Quadratic(b) => b.into(),
            Polygon::Cubic(b, _) => b.into(),
            Polygon::Other(b) => b,
        }
    }
}

impl<S, const D: usize> Polygon<S, D> {
    /// The points b₀, …, bₙ.
    #[inline]
    pub(super) fn as_slice(&self) -> &[Point<S, D>] {
        match self {
            Polygon::Line(b) => b,
            Polygon::Quadratic(b) => b,
            Polygon::Cubic(b, _) => b,
            Polygon::Other(b) => b,
        }
    }
}

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// `true` if Horner's scheme at `t` provably stays within the `f64` range, which needs t
    /// finite: always for exact scalars, else `|t|` at most the bound of [`horner_limit`].
    #[inline(always)]
    pub(crate) fn horner_is_safe(&self, t: &S) -> bool {
        S::EXACT || t.abs_at_most(self.horner_limit)
    }

    /// Degrees 1 to 3 by the closed forms of Horner's nesting (`None` for other degrees),
    /// for a `t` within the Horner bound.
    #[inline(always)]
    pub(super) fn closed_form(&self, t: &S) -> Option<Point<S, D>> {
        match &self.control {
            Polygon::Line([b0, b1]) => Some(horner_line(b0, b1, t, &(S::one() - t))),
            Polygon::Quadratic([b0, b1, b2]) => {
                Some(horner_quadratic(b0, b1, b2, t, &(S::one() - t)))
            }
            Polygon::Cubic([b0, _, _, b3], [c1, c2]) => {
                Some(horner_cubic(b0, c1, c2, b3, t, &(S::one() - t)))
            }
            Polygon::Other(_) => None,
        }
    }

    /// For a cubic, b₀, 3b₁, 3b₂ and b₃: the points [`horner_cubic`] takes.
    #[inline(always)]
    pub(crate) fn cubic_horner_points(&self) -> Option<[&Point<S, D>; 4]> {
        match &self.control {
            Polygon::Cubic([b0, _, _, b3], [c1, c2]) => Some([b0, c1, c2, b3]),
            _ => None,
        }
    }

    /// [`Bezier::eval`] where [`Bezier::closed_form`] does not apply: validates `t`, then
    /// [`Bezier::eval_general`]. Out of line, so that evaluation loops stay small.
    #[inline(never)]
    pub(super) fn eval_general_checked(&self, t: &S) -> Result<Point<S, D>> {
        validate_parameter(t, "t")?;
        Ok(self.eval_general(t))
    }

    /// The point b(t) for a finite t, any degree: Horner's scheme if its result is finite
    /// (always within the Horner bound), else de Casteljau's algorithm (which only forms
    /// affine combinations). Out of line: the evaluations inline only the closed forms.
    #[inline(never)]
    pub(crate) fn eval_general(&self, t: &S) -> Point<S, D> {
        let p = self.horner_unchecked(t, &mut NoCount);
        if p.is_finite() {
            return p;
        }
        let mut q = self.control().to_vec();
        for k in 1..q.len() {
            for i in 0..q.len() - k {
                q[i] = Point::lerp(&q[i], &q[i + 1], t);
            }
        }
        q.swap_remove(0)
    }

    /// Horner's scheme of Obs. 4 without validation (t finite), counting.
    #[inline(always)]
    pub(crate) fn horner_unchecked<C: Counter>(&self, t: &S, counter: &mut C) -> Point<S, D> {
        let n = self.degree();
        counter.arithmetic_operation();
        if n == 0 {
            return self.control()[0].clone();
        }
        // Lines, quadratics and cubics, the common case, get the same nesting unrolled with
        // their binomials as constants: no loop, no table, no bounds checks.
        if let Some(p) = self.closed_form(t) {
            for _ in 0..n {
                counter.arithmetic_operation();
            }
            return p;
        }
        in_registers(self.horner_loop(t, S::one() - t, counter))
    }

    /// Horner's nesting for degree n ≥ 4 (one counted step is already recorded).
    fn horner_loop<C: Counter>(&self, t: &S, u: S, counter: &mut C) -> Point<S, D> {
        let b = self.control();
        let n = b.len() - 1;
        // acc = Σ_{j<i} C(n, j) tʲ uⁱ⁻ʲ bⱼ after step i; tᵢ = tⁱ.
        let mut ti = S::one();
        let mut acc = b[0].clone() * &u;
        // Past the table, C(n, i) = C(n, i − 1)·(n − i + 1)/i keeps each step O(1).
        let mut c = S::one();
        for (i, bi) in b.iter().enumerate().take(n).skip(1) {
            ti = ti * t;
            let coefficient = if n < BINOMIAL_ROWS {
                binomial_coefficient::<S>(n, i)
            } else {
                c = c * S::from_i64((n - i + 1) as i64) / S::from_i64(i as i64);
                c.clone()
            };
            acc = (acc + &(bi.clone() * (ti.clone() * coefficient))) * &u;
            counter.arithmetic_operation();
        }
        counter.arithmetic_operation();
        acc + &(b[n].clone() * (ti * t))
    }
}

/// `p` itself. For `f64`, taken apart and put together again coordinate by coordinate: where
/// a point returned in memory by an out-of-line call (the checked path, Horner's loop) meets
/// one computed in registers, the compiler then merges the two in registers, instead of
/// storing the register one to memory and loading it back on every evaluation (which
/// measurably slowed down evaluation loops). For exact scalars, a plain move.
#[inline(always)]
pub(crate) fn in_registers<S: Scalar, const D: usize>(p: Point<S, D>) -> Point<S, D> {
    if S::EXACT {
        p
    } else {
        Point(std::array::from_fn(|i| p.0[i].clone()))
    }
}

/// Horner's nesting of degree 1, `b₀u + b₁t` (u = 1 − t).
#[inline(always)]
pub(crate) fn horner_line<S: Scalar, const D: usize>(
    b0: &Point<S, D>,
    b1: &Point<S, D>,
    t: &S,
    u: &S,
) -> Point<S, D> {
    b0.clone() * u + &(b1.clone() * t)
}

/// Horner's nesting of degree 2, `(b₀u + 2t b₁)u + t² b₂` (u = 1 − t).
#[inline(always)]
pub(crate) fn horner_quadratic<S: Scalar, const D: usize>(
    b0: &Point<S, D>,
    b1: &Point<S, D>,
    b2: &Point<S, D>,
    t: &S,
    u: &S,
) -> Point<S, D> {
    let two_t = S::from_i64(2) * t;
    (b0.clone() * u + &(b1.clone() * two_t)) * u + &(b2.clone() * (t.clone() * t))
}

/// Horner's nesting of degree 3, `((b₀u + c₁t)u + c₂t²)u + b₃t³` (u = 1 − t) with the
/// scaled points c₁ = 3b₁ and c₂ = 3b₂.
#[inline(always)]
pub(crate) fn horner_cubic<S: Scalar, const D: usize>(
    b0: &Point<S, D>,
    c1: &Point<S, D>,
    c2: &Point<S, D>,
    b3: &Point<S, D>,
    t: &S,
    u: &S,
) -> Point<S, D> {
    let t2 = t.clone() * t;
    ((b0.clone() * u + &(c1.clone() * t)) * u + &(c2.clone() * &t2)) * u + &(b3.clone() * (t2 * t))
}

/// The bound on |t| stored in a curve: for |t| at most this value, every intermediate of
/// Horner's scheme ([`Bezier::horner_unchecked`], closed forms and loop) is finite in `f64`.
/// Negative when no parameter is safe; irrelevant (+∞) for exact scalars.
///
/// Why: with M' = max(1, largest |coordinate|) and w = |t| + |1 − t| ≥ 1, the partial sums
/// Σⱼ C(n, j) tʲ (1 − t)ⁱ⁻ʲ bⱼ of the nesting, the scalars C(n, i) tⁱ and the ratio
/// recurrence's C(n, i − 1)(n − i + 1) are all at most (n + 1) 2ⁿ M' wⁿ, so
/// `2ⁿ⁺¹ (n + 1) M' wⁿ ≤ f64::MAX` leaves a factor 2 for rounding. With K = f64::MAX /
/// (2ⁿ⁺¹ (n + 1) M') ≥ 1 and W = 2^⌊⌊log₂ K⌋ / n⌋ (so Wⁿ ≤ K, read off K's exponent: no
/// `powf` on the way, as curves are built by the thousand when flattening or intersecting),
/// it holds for |t| ≤ (W − 1)/2, since w ≤ 2|t| + 1. Degree 0 evaluates to b₀ for any
/// finite t.
pub(super) fn horner_limit<S: Scalar, const D: usize>(control: &[Point<S, D>]) -> f64 {
    let n = control.len() - 1;
    if S::EXACT {
        return f64::INFINITY;
    }
    if n == 0 {
        return f64::MAX;
    }
    let mut m = 1.0f64;
    for p in control {
        for c in p.coords() {
            m = m.max(c.to_f64().abs());
        }
    }
    // 2^(n+1) is +∞ for n ≥ 1023, and then K = 0.
    let k = f64::MAX / (2f64.powi((n + 1).min(2000) as i32) * (n + 1) as f64 * m);
    if k < 1.0 {
        return -1.0;
    }
    // K ≥ 1 is a normal double: its exponent field is ⌊log₂ K⌋ + 1023.
    let log2_k = (k.to_bits() >> 52) as usize - 1023;
    let w = f64::from_bits(((log2_k / n + 1023) as u64) << 52);
    (w - 1.0) / 2.0
}

/// C(n, k) in `S`: from a table of exact integers for n < 64, else by the product formula.
#[inline]
pub(crate) fn binomial_coefficient<S: Scalar>(n: usize, k: usize) -> S {
    if n < BINOMIAL_ROWS && k <= n {
        S::from_i64(BINOMIALS[n * (n + 1) / 2 + k] as i64)
    } else {
        binomial(n, k)
    }
}

/// Rows 0..63 of Pascal's triangle (all fit in an i64), row n starting at n(n + 1)/2.
const BINOMIAL_ROWS: usize = 64;

static BINOMIALS: [u64; BINOMIAL_ROWS * (BINOMIAL_ROWS + 1) / 2] = pascal();

const fn pascal() -> [u64; BINOMIAL_ROWS * (BINOMIAL_ROWS + 1) / 2] {
    let mut table = [0u64; BINOMIAL_ROWS * (BINOMIAL_ROWS + 1) / 2];
    let mut n = 0;
    while n < BINOMIAL_ROWS {
        let row = n * (n + 1) / 2;
        table[row] = 1;
        table[row + n] = 1;
        let mut k = 1;
        while k < n {
            let prev = (n - 1) * n / 2;
            table[row + k] = table[prev + k - 1] + table[prev + k];
            k += 1;
        }
        n += 1;
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomial_table_matches_product_formula() {
        for n in 0..BINOMIAL_ROWS {
            for k in 0..=n {
                let product: f64 = binomial(n, k);
                let table: f64 = binomial_coefficient(n, k);
                // Both are the same integer rounded to f64 once at most.
                assert!((product - table).abs() <= product * 1e-15, "C({n},{k})");
            }
        }
        assert_eq!(BINOMIALS[63 * 64 / 2 + 31], 916_312_070_471_295_267);
    }

    /// Deterministic coordinates of magnitude up to `m`, both signs, some zero.
    fn polygon(n: usize, m: f64, seed: u64) -> Vec<Point<f64, 2>> {
        let mut s = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            let r = (s >> 11) as f64 / (1u64 << 53) as f64;
            if s % 7 == 0 {
                0.0
            } else {
                (2.0 * r - 1.0) * m
            }
        };
        (0..=n).map(|_| Point::new([next(), next()])).collect()
    }

    #[test]
    fn no_horner_step_overflows_within_the_bound() {
        let magnitudes = [0.0, 1e-300, 1.0, 1e10, 1e100, 1e250, 1e300, 1e306, f64::MAX];
        let degrees = (1..=12).chain([20, 40, 63, 64, 65, 100, 300, 1000, 1030]);
        let mut fast = 0;
        for n in degrees {
            for (k, &m) in magnitudes.iter().enumerate() {
                let b = Bezier::new(polygon(n, m, (n * 31 + k) as u64)).unwrap();
                let limit = b.horner_limit;
                if limit < 0.0 {
                    continue;
                }
                fast += 1;
                for t in [
                    limit,
                    -limit,
                    limit * 0.999,
                    -limit * 0.5,
                    0.0,
                    0.5,
                    1.0,
                    -1.0,
                ] {
                    if t.abs() > limit {
                        continue;
                    }
                    assert!(b.horner_is_safe(&t), "n = {n}, M = {m}, t = {t}");
                    let p = b.horner_unchecked(&t, &mut NoCount);
                    assert!(p.is_finite(), "n = {n}, M = {m}, t = {t}: {p:?}");
                }
                // Just past the bound the fast path is not taken.
                let beyond = limit * 1.01 + 1e-300;
                assert!(!b.horner_is_safe(&beyond) && !b.horner_is_safe(&-beyond));
            }
        }
        assert!(
            fast > 100,
            "the bound should admit most of these curves, got {fast}"
        );
        assert!(!Bezier::new(polygon(3, 1.0, 1))
            .unwrap()
            .horner_is_safe(&f64::NAN));
        assert!(!Bezier::new(polygon(0, 1.0, 1))
            .unwrap()
            .horner_is_safe(&f64::INFINITY));
    }

    #[test]
    fn the_bound_admits_every_usual_parameter() {
        // A cubic in the unit square: everything up to |t| ≈ 1e100 is on the fast path.
        assert!(Bezier::new(polygon(3, 1.0, 5)).unwrap().horner_limit > 1e100);
        // Degree 63 (the last tabulated row) in a box of size 1e6 still covers [−100, 100].
        assert!(Bezier::new(polygon(63, 1e6, 5)).unwrap().horner_limit > 100.0);
        // Coordinates near the top of the range: only the checked path.
        assert!(Bezier::new(polygon(3, 1e307, 5)).unwrap().horner_limit < 0.0);
        // Exact scalars never overflow; a constant curve ignores t.
        assert_eq!(horner_limit::<f64, 1>(&[Point::new([f64::MAX])]), f64::MAX);
    }

    #[test]
    fn polygons_keep_their_points_and_cubics_their_scaled_points() {
        for n in 0..8 {
            let pts = polygon(n, 10.0, n as u64);
            let b = Bezier::new(pts.clone()).unwrap();
            assert_eq!(b.control(), &pts[..]);
            assert_eq!(b.clone().into_control(), pts);
            assert_eq!(format!("{b:?}"), format!("Bezier {{ control: {pts:?} }}"));
            let inline = !matches!(b.control, Polygon::Other(_));
            assert_eq!(inline, (1..=3).contains(&n), "n = {n}");
            if let Some([b0, c1, c2, b3]) = b.cubic_horner_points() {
                assert_eq!(
                    [*b0, *c1, *c2, *b3],
                    [pts[0], pts[1] * 3.0, pts[2] * 3.0, pts[3]]
                );
            }
        }
    }
}
