//! The Bézier fuzz check: every operation in `f64` against the same operation in the exact
//! `BigRational` back end, within a rounding bound of the form `c·k·ε·S` where S is the
//! value the operation would have with every term taken in absolute value (the standard
//! bound for sums of products: cancellation is the only way to lose accuracy, and S says
//! how much there is to lose).

use super::{exact, magnitude, Decoder};
use crate::spline::{binomial, Bezier, Curve, Point};
use crate::Error;
use num_rational::BigRational;
use num_traits::Signed;

type Exact = Bezier<BigRational, 2>;

/// The smallest subnormal, the most an operation that underflows rounds away.
const TINY: f64 = 5e-324;

/// A curve of degree 0 to 7 and a parameter from the fuzzer's bytes; every operation
/// checked against the exact back end:
///
/// - `Bezier::new` rejects NaN and infinities with `Error::NonFinite` naming the point;
///   a NaN or infinite parameter is an `Error::InvalidParameter`;
/// - `eval` (Horner with the de Casteljau fallback), `de_casteljau`, `horner` at t;
/// - `split` at t (both pieces' control points);
/// - `elevate` and `elevate_to` up to three degrees more;
/// - `derivative` of every order up to n + 1.
///
/// Each coordinate is within `4(k + 2) ε S + slack` of the exact one, k the number of
/// rounded steps and S the bound sum (the exact value with every term in absolute value;
/// slack covers underflow). A result that overflows (a non-finite value or
/// `Error::Overflow`) is allowed only where S is within a factor of 8(k + 2) of
/// `f64::MAX`, and so is a NaN (infinities that cancel: the stored input
/// `bezier/horner-nan-near-max` is Horner at t = 1 on coordinates near `f64::MAX`).
pub fn bezier(data: &[u8]) {
    let mut d = Decoder::new(data);
    let Some(head) = d.byte() else {
        return;
    };
    let n = usize::from(head % 8);
    let mut control = Vec::with_capacity(n + 1);
    for _ in 0..=n {
        let (Some(x), Some(y)) = (d.coordinate(), d.coordinate()) else {
            return;
        };
        control.push(Point::new([x, y]));
    }
    let t = d.coordinate().unwrap_or(0.5);
    let extra = usize::from(d.byte().unwrap_or(0));
    let curve = Bezier::new(control.clone());
    if let Some(first) = control.iter().position(|p| !p.is_finite()) {
        match curve {
            Err(Error::NonFinite { index, .. }) if index == first => return,
            other => panic!("control point {first} is not finite, got {other:?}"),
        }
    }
    let curve = curve.expect("finite control points");
    let exact_curve = Exact::from_f64(&curve);
    let b: Vec<[BigRational; 2]> = control.iter().map(|p| [exact(p[0]), exact(p[1])]).collect();
    if !t.is_finite() {
        for r in [curve.eval(&t), curve.de_casteljau(&t), curve.horner(&t)] {
            assert!(matches!(r, Err(Error::InvalidParameter { .. })), "{r:?}");
        }
        assert!(matches!(
            curve.split(&t),
            Err(Error::InvalidParameter { .. })
        ));
        return;
    }
    let tq = exact(t);
    let u = BigRational::from_integer(1.into()) - &tq;
    check_evaluations(&curve, &exact_curve, &b, t, &tq, &u);
    check_split(&curve, &exact_curve, &b, t, &tq, &u);
    check_elevation(&curve, &exact_curve, &b, extra % 4);
    for r in 0..=n + 1 {
        check_derivative(&curve, &exact_curve, &b, r);
    }
}

/// `Σᵢ C(m, i) |t|ⁱ |1 − t|^(m−i) |bᵢ|` over the points `b` (m + 1 of them), per coordinate.
fn bernstein_bound(b: &[[BigRational; 2]], t: &BigRational, u: &BigRational) -> [f64; 2] {
    let m = b.len() - 1;
    let (t, u) = (t.abs(), u.abs());
    let mut sums = [
        BigRational::from_integer(0.into()),
        BigRational::from_integer(0.into()),
    ];
    for (i, p) in b.iter().enumerate() {
        let w = binomial::<BigRational>(m, i)
            * num_traits::pow(t.clone(), i)
            * num_traits::pow(u.clone(), m - i);
        for (s, c) in sums.iter_mut().zip(p) {
            *s += &w * c.abs();
        }
    }
    sums.map(|s| magnitude(&s))
}

/// Checks one coordinate: `got` (None for an overflow error) against `want`, with bound sum
/// `s` after `steps` rounded steps, amplifying underflow by at most `grow` per step.
fn check_value(what: &str, got: Option<f64>, want: &BigRational, s: f64, steps: usize, grow: f64) {
    let k = (steps + 2) as f64;
    let near_overflow = s >= f64::MAX / (8.0 * k);
    match got {
        Some(x) if x.is_finite() => {
            let tol = 4.0 * k * f64::EPSILON * s + k * TINY * grow.max(1.0).powi(steps as i32);
            if tol.is_finite() {
                let err = magnitude(&(exact(x) - want));
                assert!(
                    err <= tol,
                    "{what}: {x:e} is {err:e} from the exact {:e} (tolerance {tol:e})",
                    super::nearest(want)
                );
            }
        }
        // Infinities that cancel: only where the terms themselves overflow.
        Some(x) if x.is_nan() => assert!(
            near_overflow,
            "{what}: NaN, though the bound sum is only {s:e}"
        ),
        _ => assert!(
            near_overflow,
            "{what}: {got:?} overflows, though the bound sum is {s:e} (exact {:e})",
            super::nearest(want)
        ),
    }
}

fn check_evaluations(
    curve: &Bezier<f64, 2>,
    exact_curve: &Exact,
    b: &[[BigRational; 2]],
    t: f64,
    tq: &BigRational,
    u: &BigRational,
) {
    let n = b.len() - 1;
    let want = exact_curve.eval(tq).expect("exact evaluation");
    let s = bernstein_bound(b, tq, u);
    let grow = 35.0 * t.abs().max((1.0 - t).abs());
    for (name, got) in [
        ("eval", curve.eval(&t)),
        ("de_casteljau", curve.de_casteljau(&t)),
        ("horner", curve.horner(&t)),
    ] {
        let got = got.unwrap_or_else(|e| panic!("{name} at a finite t: {e}"));
        for j in 0..2 {
            let what = format!("{name}({t:e}) coordinate {j} of degree {n}");
            check_value(&what, Some(got[j]), &want[j], s[j], 3 * n + 1, grow);
        }
    }
}

fn check_split(
    curve: &Bezier<f64, 2>,
    exact_curve: &Exact,
    b: &[[BigRational; 2]],
    t: f64,
    tq: &BigRational,
    u: &BigRational,
) {
    let n = b.len() - 1;
    let (left, right) = exact_curve.split(tq).expect("exact split");
    // Left point i is the de Casteljau value of b₀..bᵢ, right point i that of bᵢ..bₙ.
    let bounds: Vec<([f64; 2], [f64; 2])> = (0..=n)
        .map(|i| {
            (
                bernstein_bound(&b[..=i], tq, u),
                bernstein_bound(&b[i..], tq, u),
            )
        })
        .collect();
    let grow = t.abs().max((1.0 - t).abs());
    match curve.split(&t) {
        Ok((l, r)) => {
            for (i, (bl, br)) in bounds.iter().enumerate() {
                for j in 0..2 {
                    let what = format!("split({t:e}) left point {i} coordinate {j}");
                    let (got, want) = (l.control()[i][j], &left.control()[i][j]);
                    check_value(&what, Some(got), want, bl[j], 2 * n, grow);
                    let what = format!("split({t:e}) right point {i} coordinate {j}");
                    let (got, want) = (r.control()[i][j], &right.control()[i][j]);
                    check_value(&what, Some(got), want, br[j], 2 * n, grow);
                }
            }
        }
        Err(Error::Overflow { .. }) => {
            let worst = bounds
                .iter()
                .flat_map(|(l, r)| l.iter().chain(r))
                .fold(0.0f64, |m, &s| m.max(s));
            check_value(
                &format!("split({t:e})"),
                None,
                &left.control()[0][0],
                worst,
                2 * n,
                grow,
            );
        }
        Err(e) => panic!("split at a finite t: {e}"),
    }
}

fn check_elevation(
    curve: &Bezier<f64, 2>,
    exact_curve: &Exact,
    b: &[[BigRational; 2]],
    more: usize,
) {
    let n = b.len() - 1;
    let results = [
        ("elevate", curve.elevate(), exact_curve.elevate(), n + 1),
        (
            "elevate_to",
            curve.elevate_to(n + more),
            exact_curve.elevate_to(n + more),
            n + more,
        ),
    ];
    for (name, got, want, m) in results {
        let want = want.expect("exact elevation");
        // dₖ = Σᵢ wₖᵢ bᵢ with the weights C(n, i) C(m − n, k − i) / C(m, k).
        let bound = |k: usize, j: usize| -> f64 {
            let mut s = BigRational::from_integer(0.into());
            for (i, p) in b.iter().enumerate() {
                if i <= k && k - i <= m - n {
                    let w = binomial::<BigRational>(n, i) * binomial::<BigRational>(m - n, k - i)
                        / binomial::<BigRational>(m, k);
                    s += w * p[j].abs();
                }
            }
            magnitude(&s)
        };
        match got {
            Ok(got) => {
                assert_eq!(got.degree(), m, "{name}");
                for k in 0..=m {
                    for j in 0..2 {
                        let what = format!("{name} to {m} point {k} coordinate {j}");
                        check_value(
                            &what,
                            Some(got.control()[k][j]),
                            &want.control()[k][j],
                            bound(k, j),
                            n + 3,
                            1.0,
                        );
                    }
                }
            }
            Err(Error::Overflow { .. }) => {
                let worst = (0..=m)
                    .flat_map(|k| [bound(k, 0), bound(k, 1)])
                    .fold(0.0f64, f64::max);
                check_value(name, None, &want.control()[0][0], worst, n + 3, 1.0);
            }
            Err(e) => panic!("{name}: {e}"),
        }
    }
}

fn check_derivative(curve: &Bezier<f64, 2>, exact_curve: &Exact, b: &[[BigRational; 2]], r: usize) {
    let n = b.len() - 1;
    let want = exact_curve.derivative(r).expect("exact derivative");
    // Point i is n⋯(n − r + 1) Σⱼ (−1)^(r−j) C(r, j) b_{i+j}.
    let factor: BigRational = (0..r.min(n))
        .map(|k| BigRational::from_integer(((n - k) as i64).into()))
        .product();
    let bound = |i: usize, c: usize| -> f64 {
        if r > n {
            return 0.0;
        }
        let s: BigRational = (0..=r)
            .map(|j| binomial::<BigRational>(r, j) * b[i + j][c].abs())
            .sum();
        magnitude(&(s * &factor))
    };
    match curve.derivative(r) {
        Ok(got) => {
            assert_eq!(got.control().len(), want.control().len(), "derivative {r}");
            for i in 0..want.control().len() {
                for j in 0..2 {
                    let what = format!("derivative {r} point {i} coordinate {j}");
                    check_value(
                        &what,
                        Some(got.control()[i][j]),
                        &want.control()[i][j],
                        bound(i, j),
                        r + 1,
                        1.0,
                    );
                }
            }
        }
        Err(Error::Overflow { .. }) => {
            let worst = (0..want.control().len())
                .flat_map(|i| [bound(i, 0), bound(i, 1)])
                .fold(0.0f64, f64::max);
            check_value(
                &format!("derivative {r}"),
                None,
                &want.control()[0][0],
                worst,
                r + 1,
                1.0,
            );
        }
        Err(e) => panic!("derivative {r}: {e}"),
    }
}
