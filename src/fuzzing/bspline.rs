//! The B-spline and NURBS fuzz check: a curve of degree 0 to 4 on knots from the fuzzer's
//! bytes (near-duplicates a few ulps apart, subnormal spacing, ±1e300, f64::MAX-sized
//! coordinates all reachable through the [`Decoder`]), every operation in `f64` against the
//! same operation in the exact `BigRational` back end.
//!
//! Each `f64` value must be finite and within `K·(ε·S + TINY·S₁)` of the exact one, where S
//! is the operation with every term taken in absolute value (for the convex operations the
//! largest control coordinate; for the blossoms and elevation the largest coordinate times
//! G, the product of the affine weights' absolute sums; for derivatives the derivative
//! control points built from |cᵢ|), S₁ the same with every coordinate 1 (underflow: an
//! absolute error of a subnormal unit per step, divided by the knot widths as the values
//! are), and K a generous multiple of the steps. An `Error::Overflow` is allowed only where
//! S is within a factor of 8K of `f64::MAX`: the operations that only form convex
//! combinations inside the domain (evaluation, insertion, refinement, splitting, Bézier
//! pieces) may never overflow.

use super::{exact, magnitude, nearest, Decoder};
use crate::spline::{BSpline, KnotVector, Nurbs, Point};
use crate::Error;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

type Q = BigRational;
type Spline = BSpline<f64, 2>;
type Exact = BSpline<Q, 2>;

/// The smallest subnormal, the most an operation that underflows rounds away.
const TINY: f64 = 5e-324;

/// A B-spline (and a NURBS curve on the same knots) from the fuzzer's bytes, every operation
/// checked:
///
/// - `KnotVector::new` rejects NaN/∞ knots, knots out of order, a multiplicity above d + 1 and
///   an empty domain as `InvalidParameter` named "knots"; `BSpline::new` rejects NaN/∞ points
///   with `NonFinite` naming the first;
/// - `de_boor`, `eval_sorted` (bit for bit de Boor's), `derivatives`, `blossom_in_span`,
///   `insert`, `refine`, `oslo`, `split`, `to_bezier`, `elevate`, `integral`, `remove`;
/// - `Nurbs::new` (weights NaN, ∞, zero or negative refused), `de_boor`, `insert`, `elevate`.
///
/// A parameter outside the domain (or NaN/∞) is an `InvalidParameter` for both back ends;
/// where the exact back end refuses an operation (a multiplicity above d, a removal that
/// changes the curve), `f64` refuses it with the same error.
pub fn bspline(data: &[u8]) {
    let mut dec = Decoder::new(data);
    let Some(head) = dec.byte() else {
        return;
    };
    let degree = usize::from(head % 5);
    let n = degree + 1 + usize::from((head / 5) % 4);
    let sort = head < 0xf0;
    let mut knots = Vec::with_capacity(n + degree + 1);
    for _ in 0..n + degree + 1 {
        let Some(x) = dec.coordinate() else {
            return;
        };
        knots.push(x);
    }
    let mut control = Vec::with_capacity(n);
    for _ in 0..n {
        let (Some(x), Some(y)) = (dec.coordinate(), dec.coordinate()) else {
            return;
        };
        control.push(Point::new([x, y]));
    }
    let weights: Vec<f64> = (0..n).map(|_| dec.coordinate().unwrap_or(1.0)).collect();
    let mut params = Vec::new();
    while params.len() < 3 {
        match dec.coordinate() {
            Some(u) => params.push(u),
            None => break,
        }
    }
    let choice = dec.byte().unwrap_or(0);

    if sort {
        knots.sort_by(f64::total_cmp);
    }
    let kv = KnotVector::new(degree, knots.clone());
    let bad_knot = knots.iter().any(|t| !t.is_finite()) || knots.windows(2).any(|w| w[0] > w[1]);
    let kv = match kv {
        Ok(kv) => {
            assert!(!bad_knot, "knots {knots:?} accepted");
            kv
        }
        Err(Error::InvalidParameter { name: "knots", .. }) => {
            if !bad_knot {
                // The other reasons: a multiplicity above d + 1 or an empty domain.
                let too_many = knots.windows(degree + 2).any(|w| w.first() == w.last());
                assert!(
                    too_many || knots[degree] == knots[n],
                    "knots {knots:?} refused"
                );
            }
            return;
        }
        Err(e) => panic!("knots {knots:?}: {e}"),
    };
    let curve = Spline::new(control.clone(), kv);
    if let Some(first) = control.iter().position(|p| !p.is_finite()) {
        match curve {
            Err(Error::NonFinite { index, .. }) if index == first => return,
            other => panic!("control point {first} is not finite, got {other:?}"),
        }
    }
    let s = curve.expect("finite control points on valid knots");
    let q = to_exact(&s);
    let c = Checker::new(&s, &q);

    let (start, end) = (knots[degree], knots[n]);
    let mut at = params.clone();
    at.extend([start, end]);
    for &u in &at {
        c.eval(u);
        c.derivatives(u);
    }
    c.eval_sorted(&at);
    let u = params.first().copied().unwrap_or(start);
    let times = usize::from(choice % 3) + 1;
    c.insert(u, times);
    c.refine(&params);
    c.split(u);
    c.to_bezier();
    c.blossom(usize::from(choice / 3), &at);
    c.elevate(usize::from(choice / 64) % 2 + 1);
    c.integral();
    c.remove(u, times);
    c.nurbs(&control, &weights, &at, u, times);
}

/// The curve with every knot and coordinate exact.
fn to_exact(s: &Spline) -> Exact {
    let knots = s.knots().knots().iter().map(|&t| exact(t)).collect();
    let kv = KnotVector::new(s.degree(), knots).expect("the same knots, exactly");
    let control = s
        .control()
        .iter()
        .map(|p| Point::new([exact(p[0]), exact(p[1])]))
        .collect();
    Exact::new(control, kv).expect("the same points, exactly")
}

fn q_max(a: Q, b: Q) -> Q {
    if a > b {
        a
    } else {
        b
    }
}

fn q_abs_max(values: impl IntoIterator<Item = Q>) -> Q {
    values
        .into_iter()
        .map(|v| v.abs())
        .fold(Q::zero(), |m, v| if v > m { v } else { m })
}

/// A variant tag of an error, to compare the two back ends' refusals.
fn kind(e: &Error) -> String {
    let s = format!("{e:?}");
    s.split([' ', '{', '(']).next().unwrap_or("").to_string()
}

struct Checker<'a> {
    s: &'a Spline,
    q: &'a Exact,
    degree: usize,
    /// max |cᵢ| over every coordinate, exactly.
    m: Q,
}

impl<'a> Checker<'a> {
    fn new(s: &'a Spline, q: &'a Exact) -> Self {
        let m = q_abs_max(
            q.control()
                .iter()
                .flat_map(|p| [p[0].clone(), p[1].clone()]),
        );
        Checker {
            s,
            q,
            degree: s.degree(),
            m,
        }
    }

    /// Checks one coordinate against the exact value: within K(ε·bound + TINY·unit), where
    /// `bound` and `unit` are exact; `None` (an overflow error) only where the bound is near
    /// `f64::MAX`.
    fn value(&self, what: &str, got: Option<f64>, want: &Q, bound: &Q, unit: &Q, k: f64) {
        let b = magnitude(bound);
        let near_overflow = b >= f64::MAX / (8.0 * k);
        match got {
            Some(x) if x.is_finite() => {
                let tol = k * (f64::EPSILON * b + TINY * magnitude(unit));
                if tol.is_finite() {
                    let err = magnitude(&(exact(x) - want));
                    assert!(
                        err <= tol,
                        "{what}: {x:e} is {err:e} from the exact {:e} (tolerance {tol:e}) {:?}",
                        nearest(want),
                        self.s
                    );
                }
            }
            Some(x) => panic!("{what}: {x} in an Ok result (exact {:e})", nearest(want)),
            None => assert!(
                near_overflow,
                "{what}: overflows, though the bound is {b:e} (exact {:e})",
                nearest(want)
            ),
        }
    }

    fn points(
        &self,
        what: &str,
        got: &[Point<f64, 2>],
        want: &[Point<Q, 2>],
        bound: &Q,
        unit: &Q,
        k: f64,
    ) {
        assert_eq!(got.len(), want.len(), "{what}: the number of points");
        for (i, (g, w)) in got.iter().zip(want).enumerate() {
            for j in 0..2 {
                self.value(
                    &format!("{what} point {i}.{j}"),
                    Some(g[j]),
                    &w[j],
                    bound,
                    unit,
                    k,
                );
            }
        }
    }

    fn same_knots(what: &str, got: &KnotVector<f64>, want: &KnotVector<Q>) {
        assert_eq!(got.degree(), want.degree(), "{what}: degree");
        let g: Vec<Q> = got.knots().iter().map(|&t| exact(t)).collect();
        assert_eq!(g, want.knots(), "{what}: knots");
    }

    /// Both back ends refused, with the same kind of error.
    fn same_refusal(what: &str, got: &Error, want: &Error) {
        assert_eq!(
            kind(got),
            kind(want),
            "{what}: f64 says {got}, exact says {want}"
        );
    }

    /// The steps of a convex operation of `levels` de Boor levels.
    fn convex_steps(&self, levels: usize) -> f64 {
        (4 * (levels + 1) * (self.degree + 1) + 4) as f64
    }

    /// A convex curve operation (insert, refine, split): the result's knots exactly, its
    /// points within the convex bound, never an overflow.
    fn curve(
        &self,
        what: &str,
        got: crate::Result<Spline>,
        want: crate::Result<Exact>,
        levels: usize,
    ) {
        match (got, want) {
            (Ok(g), Ok(w)) => {
                Self::same_knots(what, g.knots(), w.knots());
                let k = self.convex_steps(levels);
                self.points(what, g.control(), w.control(), &self.m, &Q::one(), k);
            }
            (Err(g), Err(w)) => Self::same_refusal(what, &g, &w),
            (g, w) => panic!("{what}: f64 gives {g:?}, exact {w:?}"),
        }
    }

    fn eval(&self, u: f64) {
        let got = self.s.de_boor(&u);
        if !u.is_finite() {
            assert!(
                matches!(got, Err(Error::InvalidParameter { .. })),
                "de_boor({u}): {got:?}"
            );
            return;
        }
        let want = self.q.de_boor(&exact(u));
        match (got, want) {
            (Ok(g), Ok(w)) => {
                let k = self.convex_steps(1);
                self.points(
                    &format!("de_boor({u:e})"),
                    &[g],
                    &[w],
                    &self.m,
                    &Q::one(),
                    k,
                );
            }
            (Err(g), Err(w)) => Self::same_refusal("de_boor", &g, &w),
            (g, w) => panic!("de_boor({u:e}): f64 gives {g:?}, exact {w:?}"),
        }
    }

    fn eval_sorted(&self, at: &[f64]) {
        let mut inside: Vec<f64> = at
            .iter()
            .copied()
            .filter(|u| self.s.de_boor(u).is_ok())
            .collect();
        inside.sort_by(f64::total_cmp);
        let got = self
            .s
            .eval_sorted(&inside)
            .expect("sorted parameters in the domain");
        for (u, p) in inside.iter().zip(&got) {
            assert_eq!(
                *p,
                self.s.de_boor(u).unwrap(),
                "eval_sorted({u:e}) is not de_boor's"
            );
        }
    }

    /// Derivative control points with |cᵢ| (or 1) for the coordinates: the bound S_r.
    fn derivative_bounds(&self, ones: bool, orders: usize) -> Vec<Q> {
        let t = self.q.knots().knots();
        let d = self.degree;
        let mut a: Vec<Q> = self
            .q
            .control()
            .iter()
            .map(|p| {
                if ones {
                    Q::one()
                } else {
                    q_abs_max([p[0].clone(), p[1].clone()])
                }
            })
            .collect();
        let mut out = vec![q_abs_max(a.clone())];
        for r in 1..=orders {
            if r > d {
                out.push(Q::zero());
                continue;
            }
            let p = d - r + 1; // the degree of the curve being differentiated
            let next: Vec<Q> = (1..a.len())
                .map(|i| {
                    // Point i of the derivative: p(a_i + a_{i−1})/(t_{i+p} − t_i), offset by r − 1.
                    let (lo, hi) = (&t[i + r - 1], &t[i + r - 1 + p]);
                    if lo == hi {
                        Q::zero()
                    } else {
                        Q::from_integer((p as i64).into()) * (&a[i] + &a[i - 1]) / (hi - lo)
                    }
                })
                .collect();
            a = next;
            out.push(q_abs_max(a.clone()));
        }
        out
    }

    /// The smallest positive distance between consecutive knots, exactly.
    fn smallest_gap(&self) -> Q {
        let t = self.q.knots().knots();
        t.windows(2)
            .filter(|w| w[0] < w[1])
            .map(|w| &w[1] - &w[0])
            .reduce(|a, b| if b < a { b } else { a })
            .expect("a non-empty domain")
    }

    fn derivatives(&self, u: f64) {
        if !u.is_finite() {
            return;
        }
        let d = self.degree;
        let orders = d + 1;
        let got = self.s.derivatives(&u, orders);
        let want = self.q.derivatives(&exact(u), orders);
        let (g, w) = match (got, want) {
            (Err(g), Err(w)) => return Self::same_refusal("derivatives", &g, &w),
            (Err(Error::Overflow { .. }), Ok(w)) => (None, w),
            (Ok(g), Ok(w)) => (Some(g), w),
            (g, w) => panic!("derivatives({u:e}): f64 gives {g:?}, exact {w:?}"),
        };
        // The extended de Boor scheme divides differences of rounded de Boor points (errors
        // up to ε·M) by knot widths: order r can be off by about ε·M·(2d/gap)^r, gap the
        // smallest distance between distinct knots, beyond the derivative control points'
        // bound S_r (knots 1e-296 apart beside 35 lose every digit of s′ on that span).
        let gap = self.smallest_gap();
        let scale =
            |r: usize| num_traits::pow(Q::from_integer((2 * d.max(1) as i64).into()) / &gap, r);
        let s: Vec<Q> = self
            .derivative_bounds(false, orders)
            .into_iter()
            .enumerate()
            .map(|(r, b)| q_max(b, &self.m * scale(r)))
            .collect();
        let ones: Vec<Q> = self
            .derivative_bounds(true, orders)
            .into_iter()
            .enumerate()
            .map(|(r, b)| q_max(b, scale(r)))
            .collect();
        let steps = |r: usize| (4.0 * (d + 1) as f64).powi(r as i32 + 2);
        let Some(g) = g else {
            // One error for all orders: some order's bound must be near the top of the range.
            assert!(
                (0..=orders).any(|r| magnitude(&s[r]) >= f64::MAX / (8.0 * steps(r))),
                "derivatives({u:e}) overflow, though the bounds are {:?}",
                s.iter().map(magnitude).collect::<Vec<_>>()
            );
            return;
        };
        for r in 0..=orders {
            for j in 0..2 {
                let what = format!("derivative {r} at {u:e}, coordinate {j}");
                self.value(&what, Some(g[r][j]), &w[r][j], &s[r], &ones[r], steps(r));
            }
        }
    }

    fn insert(&self, u: f64, times: usize) {
        if !u.is_finite() {
            assert!(self.s.insert(&u, times).is_err());
            return;
        }
        let got = self.s.insert(&u, times);
        let want = self.q.insert(&exact(u), times);
        self.curve(&format!("insert({u:e}, {times})"), got, want, times);
    }

    fn refine(&self, params: &[f64]) {
        if params.iter().any(|u| !u.is_finite()) {
            assert!(self.s.refine(params).is_err());
            assert!(self.s.oslo(params).is_err());
            return;
        }
        let xs: Vec<Q> = params.iter().map(|&u| exact(u)).collect();
        let want = self.q.refine(&xs);
        let got = self.s.refine(params);
        self.curve(
            &format!("refine({params:?})"),
            got,
            want.clone(),
            params.len(),
        );
        // The Oslo algorithm's blossoms may extrapolate (its combinations need not be convex,
        // see `oslo.rs`): each point within the growth G of its blossom on the worst span.
        let what = format!("oslo({params:?})");
        match (self.s.oslo(params), want) {
            (Ok(g), Ok(w)) => {
                Self::same_knots(&what, g.knots(), w.knots());
                let tau = w.knots().knots();
                let d = self.degree;
                let n = self.s.control().len();
                let t = self.q.knots().knots();
                let k = self.convex_steps(d + 1);
                for (j, (gp, wp)) in g.control().iter().zip(w.control()).enumerate() {
                    let args = &tau[j + 1..=j + d];
                    let growth = (d..n)
                        .filter(|&mu| t[mu] < t[mu + 1])
                        .map(|mu| self.blossom_growth(mu, args))
                        .fold(Q::one(), q_max);
                    let bound = &growth * &self.m;
                    for c in 0..2 {
                        self.value(
                            &format!("{what} point {j}.{c}"),
                            Some(gp[c]),
                            &wp[c],
                            &bound,
                            &growth,
                            k,
                        );
                    }
                }
            }
            (Err(Error::Overflow { .. }), Ok(_)) => {}
            (Err(g), Err(w)) => Self::same_refusal(&what, &g, &w),
            (g, w) => panic!("{what}: f64 gives {g:?}, exact {w:?}"),
        }
    }

    fn split(&self, u: f64) {
        if !u.is_finite() {
            assert!(self.s.split(&u).is_err());
            return;
        }
        match (self.s.split(&u), self.q.split(&exact(u))) {
            (Ok((gl, gr)), Ok((wl, wr))) => {
                self.curve("split left", Ok(gl), Ok(wl), self.degree);
                self.curve("split right", Ok(gr), Ok(wr), self.degree);
            }
            (Err(g), Err(w)) => Self::same_refusal("split", &g, &w),
            (g, w) => panic!("split({u:e}): f64 gives {g:?}, exact {w:?}"),
        }
    }

    fn to_bezier(&self) {
        match (self.s.to_bezier(), self.q.to_bezier()) {
            (Ok(g), Ok(w)) => {
                let gp: Vec<Q> = g.partition().iter().map(|&t| exact(t)).collect();
                assert_eq!(gp, w.partition(), "to_bezier: the breakpoints");
                let k = self.convex_steps(self.s.control().len() * self.degree);
                for (i, (a, b)) in g.pieces().iter().zip(w.pieces()).enumerate() {
                    self.points(
                        &format!("to_bezier piece {i}"),
                        a.control(),
                        b.control(),
                        &self.m,
                        &Q::one(),
                        k,
                    );
                }
            }
            (Err(g), Err(w)) => Self::same_refusal("to_bezier", &g, &w),
            (g, w) => panic!("to_bezier: f64 gives {g:?}, exact {w:?}"),
        }
    }

    /// G for blossom arguments `xs` on the span: Π over the levels of the largest
    /// (|u − tᵢ| + |t_j − u|)/(t_j − tᵢ), exactly.
    fn blossom_growth(&self, span: usize, xs: &[Q]) -> Q {
        let t = self.q.knots().knots();
        let d = self.degree;
        let mut g = Q::one();
        for (k, x) in (1..=d).zip(xs) {
            let mut worst = Q::one();
            for jj in k..=d {
                let i = span - d + jj;
                let (lo, hi) = (&t[i], &t[i + d + 1 - k]);
                let f = ((x - lo).abs() + (hi - x).abs()) / (hi - lo);
                if f > worst {
                    worst = f;
                }
            }
            g *= worst;
        }
        g
    }

    fn blossom(&self, pick: usize, at: &[f64]) {
        let (d, n) = (self.degree, self.s.control().len());
        let span = d + pick % (n - d);
        let xs: Vec<f64> = (0..d).map(|i| at[(pick + i) % at.len()]).collect();
        if xs.iter().any(|x| !x.is_finite()) {
            assert!(self.s.blossom_in_span(span, &xs).is_err());
            return;
        }
        let xq: Vec<Q> = xs.iter().map(|&x| exact(x)).collect();
        let got = self.s.blossom_in_span(span, &xs);
        let want = self.q.blossom_in_span(span, &xq);
        let what = format!("blossom_in_span({span}, {xs:?})");
        let w = match (&got, want) {
            (Err(g), Err(w)) => return Self::same_refusal(&what, g, &w),
            (_, Ok(w)) => w,
            (g, Err(w)) => panic!("{what}: f64 gives {g:?}, exact {w:?}"),
        };
        let g = self.blossom_growth(span, &xq);
        let bound = &g * &self.m;
        let k = (4 * d * (d + 1) + 8) as f64;
        for j in 0..2 {
            let x = match &got {
                Ok(p) => Some(p[j]),
                Err(Error::Overflow { .. }) => None,
                Err(e) => panic!("{what}: {e}"),
            };
            self.value(&format!("{what} coordinate {j}"), x, &w[j], &bound, &g, k);
        }
        // The blossom on the diagonal at a parameter of the span is the curve's point there.
        if let Ok(p) = self.s.blossom(&vec![xs.first().copied().unwrap_or(0.0); d]) {
            assert!(p.is_finite(), "blossom: {p:?}");
        }
    }

    fn elevate(&self, times: usize) {
        let got = self.s.elevate(times);
        let want = self.q.elevate(times);
        let what = format!("elevate({times})");
        let w = match (&got, want) {
            (Err(g), Err(w)) => return Self::same_refusal(&what, g, &w),
            (_, Ok(w)) => w,
            (g, Err(w)) => panic!("{what}: f64 gives {g:?}, exact {w:?}"),
        };
        // G: every blossom's arguments are knots of the new vector, its piece one of the
        // domain's; the factor (|x − s| + |e − x|)/(e − s) is largest at the extreme knots.
        let a = w.knots().knots();
        let breaks: Vec<Q> = w
            .knots()
            .multiplicities()
            .into_iter()
            .map(|(v, _)| v)
            .collect();
        let (lo, hi) = self.q.knots().bounds();
        let inside: Vec<&Q> = breaks.iter().filter(|v| *v >= lo && *v <= hi).collect();
        let mut g = Q::one();
        for p in inside.windows(2) {
            let (s, e) = (p[0], p[1]);
            for x in [&a[0], &a[a.len() - 1]] {
                let f = ((x - s).abs() + (e - x).abs()) / (e - s);
                let f = num_traits::pow(f, w.degree());
                if f > g {
                    g = f;
                }
            }
        }
        let bound = &g * &self.m;
        let deg = w.degree();
        let k = (4 * (deg + 1) * (deg + 1) * (self.s.control().len() + 2)) as f64;
        match got {
            Ok(e) => {
                Self::same_knots(&what, e.knots(), w.knots());
                self.points(&what, e.control(), w.control(), &bound, &g, k);
            }
            Err(Error::Overflow { .. }) => {
                self.value(&what, None, &w.control()[0][0], &bound, &g, k);
            }
            Err(e) => panic!("{what}: {e}"),
        }
    }

    fn integral(&self) {
        let got = self.s.integral();
        let want = self.q.integral();
        let w = match (&got, want) {
            (Err(g), Err(w)) => return Self::same_refusal("integral", g, &w),
            (_, Ok(w)) => w,
            (g, Err(w)) => panic!("integral: f64 gives {g:?}, exact {w:?}"),
        };
        // Each point is a running sum of cᵢ(t_{i+d+1} − tᵢ)/(d + 1), shifted on an unclamped
        // start by the value there: bounded by the sum of all terms in absolute value (twice).
        let t = self.q.knots().knots();
        let d = self.degree;
        let mut total = Q::zero();
        let mut widths = Q::zero();
        for (i, p) in self.q.control().iter().enumerate() {
            let width = (&t[i + d + 1] - &t[i]) / Q::from_integer(((d + 1) as i64).into());
            total += q_abs_max([p[0].clone(), p[1].clone()]) * &width;
            widths += width;
        }
        let two = Q::from_integer(2.into());
        let bound = total * &two;
        let unit = widths * two + Q::one();
        let k = (8 * (self.s.control().len() + d + 4)) as f64;
        match got {
            Ok(g) => {
                Self::same_knots("integral", g.knots(), w.knots());
                self.points("integral", g.control(), w.control(), &bound, &unit, k);
            }
            Err(Error::Overflow { .. }) => {
                self.value("integral", None, &w.control()[0][0], &bound, &unit, k);
            }
            Err(e) => panic!("integral: {e}"),
        }
    }

    fn remove(&self, u: f64, times: usize) {
        // Removing what was inserted: exact gives the curve back; f64 gives it back within
        // rounding or refuses (the re-insertion check is exact).
        if let Ok(r) = self.s.insert(&u, times) {
            match r.remove(&u, times) {
                Ok(b) => {
                    Self::same_knots("insert then remove", b.knots(), self.q.knots());
                    assert!(b.control().iter().all(Point::is_finite));
                }
                Err(Error::InvalidParameter { .. }) => {}
                Err(e) => panic!("insert({u:e}, {times}) then remove: {e}"),
            }
        }
        // Removing an existing knot: refused or accepted as the exact back end decides, but
        // f64 may refuse for rounding.
        let t = self.s.knots().knots();
        let v = t[(self.degree + times) % t.len()];
        match (self.s.remove(&v, 1), self.q.remove(&exact(v), 1)) {
            (Ok(g), Ok(w)) => {
                Self::same_knots("remove", g.knots(), w.knots());
                assert!(g.control().iter().all(Point::is_finite));
            }
            (Ok(g), Err(w)) => panic!("remove({v:e}): f64 gives {g:?}, exact {w}"),
            (Err(Error::InvalidParameter { .. }), _) => {}
            (Err(e), _) => panic!("remove({v:e}): {e}"),
        }
    }

    fn nurbs(&self, control: &[Point<f64, 2>], weights: &[f64], at: &[f64], u: f64, times: usize) {
        let got = Nurbs::new(control.to_vec(), weights.to_vec(), self.s.knots().clone());
        if let Some(i) = weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
            assert!(
                matches!(
                    got,
                    Err(Error::InvalidParameter {
                        name: "weights",
                        ..
                    })
                ),
                "weight {i} is {}, got {got:?}",
                weights[i]
            );
            return;
        }
        let wq: Vec<Q> = weights.iter().map(|&w| exact(w)).collect();
        let wmax = q_abs_max(wq.clone());
        let wmin = wq
            .iter()
            .cloned()
            .fold(wmax.clone(), |m, w| if w < m { w } else { m });
        let ratio = &wmax / &wmin;
        let cq = self.q.control().to_vec();
        let want = Nurbs::new(cq, wq, self.q.knots().clone()).expect("exact NURBS");
        let bound = &self.m * &ratio;
        let k = self.convex_steps(2) * 2.0;
        let g = match got {
            Ok(g) => g,
            Err(Error::Overflow { .. }) => {
                // Only where the weights' ratio is beyond the range (the smallest underflows
                // once the largest is scaled into [1, 2)) or a weighted point is.
                let big = &self.m * &ratio;
                assert!(
                    magnitude(&ratio) >= f64::MAX / 4.0 || magnitude(&big) >= f64::MAX / 4.0,
                    "Nurbs::new overflows at {:e}, weights {weights:?}",
                    magnitude(&big)
                );
                return;
            }
            Err(e) => panic!("Nurbs::new: {e}"),
        };
        for &x in at {
            if !x.is_finite() {
                assert!(g.de_boor(&x).is_err());
                continue;
            }
            match (g.de_boor(&x), want.de_boor(&exact(x))) {
                (Ok(p), Ok(w)) => self.points(
                    &format!("NURBS de_boor({x:e})"),
                    &[p],
                    &[w],
                    &bound,
                    &ratio,
                    k,
                ),
                (Err(a), Err(b)) => Self::same_refusal("NURBS de_boor", &a, &b),
                (a, b) => panic!("NURBS de_boor({x:e}): f64 gives {a:?}, exact {b:?}"),
            }
        }
        if u.is_finite() {
            match (g.insert(&u, times), want.insert(&exact(u), times)) {
                (Ok(a), Ok(b)) => {
                    Self::same_knots("NURBS insert", a.knots(), b.knots());
                    let k = self.convex_steps(times) * 2.0;
                    self.points("NURBS insert", a.control(), b.control(), &bound, &ratio, k);
                    for (i, (x, y)) in a.weights().iter().zip(b.weights()).enumerate() {
                        self.value(
                            &format!("NURBS insert weight {i}"),
                            Some(*x),
                            y,
                            &wmax,
                            &Q::one(),
                            k,
                        );
                    }
                }
                (Err(a), Err(b)) => Self::same_refusal("NURBS insert", &a, &b),
                (a, b) => panic!("NURBS insert({u:e}): f64 gives {a:?}, exact {b:?}"),
            }
        }
        match (g.elevate(1), want.elevate(1)) {
            (Ok(a), Ok(b)) => {
                Self::same_knots("NURBS elevate", a.knots(), b.knots());
                assert!(
                    a.control().iter().all(Point::is_finite),
                    "NURBS elevate: {a:?}"
                );
                assert!(
                    a.weights().iter().all(|w| w.is_finite() && *w > 0.0),
                    "NURBS elevate: {a:?}"
                );
            }
            (Err(a), Err(b)) => Self::same_refusal("NURBS elevate", &a, &b),
            (Err(Error::Overflow { .. }), Ok(_)) => {}
            (a, b) => panic!("NURBS elevate: f64 gives {a:?}, exact {b:?}"),
        }
    }
}
