//! Blossoms, Greville abscissae, Marsden's identity and batch evaluation of B-spline curves,
//! checked exactly on the rational back end: the blossom of a piece is symmetric, affine in
//! each argument, equal to the curve on its diagonal and gives the control points at
//! consecutive knots for every span of the fundamental theorem [PPB, §5.5]; the splines with
//! the Greville abscissae and Marsden's coefficients as coefficients are u and (y − u)^d at
//! every parameter [PPB, §5.8, §5.12 Ex. 4]; batch evaluation equals de Boor at every
//! parameter. Then `f64` against exact (also bit for bit for the batch, on knots a few ulps
//! apart, near 1e300 and subnormal), bad input as named errors, and [PPB, §5.12, Ex. 7].

use crate::bspline_basis::{knot_vector, parameter};
use crate::spline_common::bspline::{exact, point};
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{BSpline, Curve, KnotVector, Point, Scalar};
use compgeo::Error;
use proptest::prelude::*;

/// An exact curve on a random knot vector of degree 0..=4 (repeated knots included).
fn curve() -> impl Strategy<Value = BSpline<Q, 2>> {
    knot_vector().prop_flat_map(|t| {
        let n = t.control_points();
        (
            Just(t),
            prop::collection::vec((-20i64..=20, -20i64..=20), n),
        )
            .prop_map(|(t, c)| BSpline::new(c.into_iter().map(point).collect(), t).unwrap())
    })
}

/// The non-empty spans d ≤ μ < n of the domain.
fn spans<S: Scalar, const D: usize>(s: &BSpline<S, D>) -> Vec<usize> {
    let t = s.knots().knots();
    (s.degree()..s.control().len())
        .filter(|&m| t[m] < t[m + 1])
        .collect()
}

/// A rational argument anywhere around the knots (also outside the domain and the span).
fn argument(t: &KnotVector<Q>) -> impl Strategy<Value = Q> {
    let k = t.knots();
    let (a, b) = (k[0].clone() - qi(2), k[k.len() - 1].clone() + qi(2));
    prop_oneof![
        1 => prop::sample::select(k.to_vec()),
        3 => (0i64..=90).prop_map(move |j| a.clone() + (b.clone() - &a) * q(j, 90)),
    ]
}

/// A curve, one of its non-empty spans and d arguments.
fn curve_span_arguments() -> impl Strategy<Value = (BSpline<Q, 2>, usize, Vec<Q>)> {
    curve().prop_flat_map(|s| {
        let span = prop::sample::select(spans(&s));
        let args = prop::collection::vec(argument(s.knots()), s.degree());
        (Just(s), span, args)
    })
}

/// Σ aᵢ Nᵢ(u) from the basis (the oracle of every identity here).
fn spline_value(t: &KnotVector<Q>, a: &[Q], u: &Q) -> Q {
    let b = t.basis(u).unwrap();
    let mut sum = Q::zero();
    for (k, n) in b.values().iter().enumerate() {
        sum += a[b.first() + k].clone() * n;
    }
    sum
}

fn pow(x: &Q, d: usize) -> Q {
    (0..d).fold(Q::one(), |p, _| p * x)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn the_blossom_of_a_piece_is_symmetric((s, span, args) in curve_span_arguments(), rot in 0usize..5) {
        let b = s.blossom_in_span(span, &args).unwrap();
        let mut perm = args.clone();
        perm.reverse();
        if !perm.is_empty() {
            let r = rot % perm.len();
            perm.rotate_left(r);
        }
        prop_assert_eq!(s.blossom_in_span(span, &perm).unwrap(), b);
        // The rule that picks the piece is symmetric too.
        prop_assert_eq!(s.blossom(&perm).unwrap(), s.blossom(&args).unwrap());
    }

    #[test]
    fn the_blossom_of_a_piece_is_affine_in_each_argument(
        (s, span, args) in curve_span_arguments(),
        k in 0usize..4,
        other in -40i64..=40,
        lambda in -8i64..=16,
    ) {
        prop_assume!(s.degree() > 0);
        let k = k % s.degree();
        let lambda = q(lambda, 8);
        let (a, b) = (args[k].clone(), q(other, 4));
        let mut at_b = args.clone();
        at_b[k] = b.clone();
        let mut mixed = args.clone();
        mixed[k] = (Q::one() - &lambda) * &a + lambda.clone() * &b;
        let want = Point::combine(
            &s.blossom_in_span(span, &args).unwrap(),
            &(Q::one() - &lambda),
            &s.blossom_in_span(span, &at_b).unwrap(),
            &lambda,
        );
        prop_assert_eq!(s.blossom_in_span(span, &mixed).unwrap(), want);
    }

    #[test]
    fn the_diagonal_of_the_blossom_is_the_curve(
        (s, u) in curve().prop_flat_map(|s| { let u = parameter(s.knots()); (Just(s), u) })
    ) {
        let d = s.degree();
        let p = s.de_boor(&u).unwrap();
        if d > 0 {
            // (With no arguments the convenience cannot know the piece: it takes the first.)
            prop_assert_eq!(&s.blossom(&vec![u.clone(); d]).unwrap(), &p);
        }
        let span = s.knots().span(&u).unwrap();
        prop_assert_eq!(&s.blossom_in_span(span, &vec![u.clone(); d]).unwrap(), &p);
        // Every piece whose closed span holds u takes the value there (the curve is
        // continuous at knots of multiplicity at most d).
        let t = s.knots().knots();
        for m in spans(&s) {
            if t[m] <= u && u <= t[m + 1] && s.knots().multiplicity(&u) <= d {
                prop_assert_eq!(&s.blossom_in_span(m, &vec![u.clone(); d]).unwrap(), &p, "span {}", m);
            }
        }
    }

    #[test]
    fn the_blossom_at_consecutive_knots_is_the_control_point(s in curve()) {
        // [PPB, §5.5]: cᵢ = s_μ[t_{i+1}, …, t_{i+d}] for every non-empty span μ = i, …, i + d.
        let (d, t) = (s.degree(), s.knots().knots().to_vec());
        let (start, end) = (s.knots().bounds().0.clone(), s.knots().bounds().1.clone());
        let xi = s.knots().greville();
        for (i, c) in s.control().iter().enumerate() {
            let args = &t[i + 1..=i + d];
            for m in spans(&s).into_iter().filter(|m| (i..=i + d).contains(m)) {
                prop_assert_eq!(&s.blossom_in_span(m, args).unwrap(), c, "c{} in span {}", i, m);
            }
            // The convenience picks the span of the mean ξᵢ (clamped to the domain).
            let at = xi[i].clone().max(start.clone()).min(end.clone());
            let chosen = s.knots().span(&at).unwrap();
            if d > 0 && (i..=i + d).contains(&chosen) {
                prop_assert_eq!(&s.blossom(args).unwrap(), c, "c{}", i);
            }
            // As documented: distinct knots put the mean on a span i + 1, …, i + d − 1.
            if d > 0 && t[i + 1] < t[i + d] && start <= xi[i] && xi[i] <= end {
                prop_assert!((i + 1..i + d).contains(&chosen), "c{} span {}", i, chosen);
            }
        }
    }

    #[test]
    fn marsdens_identity_holds_exactly(
        (t, u) in knot_vector().prop_flat_map(|t| { let u = parameter(&t); (Just(t), u) }),
        y in (-60i64..=60, 1i64..=7).prop_map(|(n, d)| q(n, d)),
    ) {
        let psi = t.marsden(&y).unwrap();
        prop_assert_eq!(psi.len(), t.control_points());
        prop_assert_eq!(spline_value(&t, &psi, &u), pow(&(y.clone() - &u), t.degree()));
        // The definition, factor by factor.
        let k = t.knots();
        for (i, p) in psi.iter().enumerate() {
            let want = (1..=t.degree()).fold(Q::one(), |acc, j| acc * (y.clone() - &k[i + j]));
            prop_assert_eq!(p, &want);
        }
    }

    #[test]
    fn the_greville_abscissae_reproduce_linear_functions(
        (s, u) in curve().prop_flat_map(|s| { let u = parameter(s.knots()); (Just(s), u) }),
        a in -9i64..=9,
        b in -9i64..=9,
    ) {
        let t = s.knots();
        prop_assume!(t.degree() > 0);
        let xi = t.greville();
        prop_assert!(xi.windows(2).all(|w| w[0] <= w[1]));
        for (i, x) in xi.iter().enumerate() {
            let mean = t.knots()[i + 1..=i + t.degree()].iter().fold(Q::zero(), |m, k| m + k)
                / Q::from_i64(t.degree() as i64);
            prop_assert_eq!(x, &mean);
        }
        prop_assert_eq!(spline_value(t, &xi, &u), u.clone());
        let (a, b) = (qi(a), qi(b));
        let line: Vec<Q> = xi.iter().map(|x| a.clone() + b.clone() * x).collect();
        prop_assert_eq!(spline_value(t, &line, &u), a + b * &u);
        // The graph of the first coordinate is (u, s(u)).
        let x = BSpline::new(s.control().iter().map(|p| Point::new([p[0].clone()])).collect(), t.clone()).unwrap();
        let g = x.graph().unwrap();
        prop_assert_eq!(g.eval(&u).unwrap(), Point::new([u.clone(), s.eval(&u).unwrap()[0].clone()]));
    }

    #[test]
    fn batch_evaluation_equals_de_boor(
        (s, mut us) in curve().prop_flat_map(|s| {
            let us = prop::collection::vec(parameter(s.knots()), 0..12);
            (Just(s), us)
        })
    ) {
        us.sort();
        let mut c = Counts::default();
        let got = s.eval_sorted_with(&us, &mut c).unwrap();
        prop_assert_eq!(got.len(), us.len());
        let mut ops = 0;
        for (u, p) in us.iter().zip(&got) {
            let mut k = Counts::default();
            prop_assert_eq!(p, &s.de_boor_with(u, &mut k).unwrap());
            ops += k.arithmetic_operations;
        }
        prop_assert_eq!(c.arithmetic_operations, ops);
        let n = s.control().len() as u64;
        prop_assert!(c.comparisons <= us.len() as u64 + n + 2 * (n + 1).ilog2() as u64 + 2);
        let mut out = vec![Point::zero(); 3];
        s.eval_sorted_into(&us, &mut out).unwrap();
        prop_assert_eq!(out, got);
    }
}

/// A random `f64` curve: knots from small steps (some repeated), coordinates in −20..=20.
fn f64_curve() -> impl Strategy<Value = BSpline<f64, 2>> {
    (1usize..=4, 1usize..=6).prop_flat_map(|(d, extra)| {
        let n = d + extra;
        (
            prop::collection::vec((0u8..=3, 1u32..=10), n + d + 1),
            prop::collection::vec((-20i64..=20, -20i64..=20), n),
        )
            .prop_filter_map("invalid knots", move |(steps, c)| {
                let mut x = -1.3f64;
                let knots = steps
                    .iter()
                    .map(|&(zero, s)| {
                        if zero != 0 {
                            x += s as f64 * 0.37;
                        }
                        x
                    })
                    .collect();
                let t = KnotVector::new(d, knots).ok()?;
                BSpline::new(c.into_iter().map(point).collect(), t).ok()
            })
    })
}

/// The largest |coordinate| of the control points (at least the smallest normal).
fn scale(s: &BSpline<f64, 2>) -> f64 {
    s.control()
        .iter()
        .flat_map(|p| p.coords().iter().map(|x| x.abs()))
        .fold(f64::MIN_POSITIVE, f64::max)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn f64_blossoms_greville_and_marsden_agree_with_exact(
        s in f64_curve(),
        picks in prop::collection::vec(0.0f64..=1.0, 4),
        y in -3.0f64..3.0,
    ) {
        let e = exact(&s);
        let (d, t) = (s.degree(), s.knots().knots());
        let (a, b) = (t[0], t[t.len() - 1]);
        // Arguments within the knots: each weight is at most R = (b − a)/(smallest width) in
        // size, so the sum of the terms' sizes is at most (1 + 2R)^d times the control points'.
        let args: Vec<f64> = picks[..d].iter().map(|p| a + (b - a) * p).collect();
        let qargs: Vec<Q> = args.iter().map(|x| Q::from_f64(*x).unwrap()).collect();
        let widths = spans(&s).into_iter().map(|m| t[m + 1] - t[m]).fold(f64::INFINITY, f64::min);
        let growth = (1.0 + 2.0 * (b - a) / widths).powi(d as i32);
        for m in spans(&s) {
            let (p, pq) = (s.blossom_in_span(m, &args).unwrap(), e.blossom_in_span(m, &qargs).unwrap().to_f64());
            for j in 0..2 {
                prop_assert!((p[j] - pq[j]).abs() <= 1e-13 * growth * scale(&s), "{:?} vs {:?}", p, pq);
            }
        }
        let xi = s.knots().greville();
        for (x, xq) in xi.iter().zip(e.knots().greville()) {
            prop_assert!((x - xq.to_f64()).abs() <= 8.0 * f64::EPSILON * a.abs().max(b.abs()));
        }
        let psi = s.knots().marsden(&y).unwrap();
        let psiq = e.knots().marsden(&Q::from_f64(y).unwrap()).unwrap();
        let big = (y.abs() + a.abs().max(b.abs())).powi(d as i32);
        for (p, pq) in psi.iter().zip(&psiq) {
            prop_assert!((p - pq.to_f64()).abs() <= 1e-14 * big, "{} vs {:?}", p, pq);
        }
    }

    #[test]
    fn f64_batch_evaluation_is_de_boor_bit_for_bit(
        s in f64_curve(),
        mut picks in prop::collection::vec(0.0f64..=1.0, 0..40),
        knots_too in any::<bool>(),
    ) {
        let (a, b) = (*s.knots().bounds().0, *s.knots().bounds().1);
        let mut us: Vec<f64> = picks.drain(..).map(|p| (a + (b - a) * p).clamp(a, b)).collect();
        if knots_too {
            us.extend(s.knots().knots().iter().filter(|k| **k >= a && **k <= b));
            us.extend([a, b]);
        }
        us.sort_by(f64::total_cmp);
        let got = s.eval_sorted(&us).unwrap();
        for (u, p) in us.iter().zip(&got) {
            let want = s.de_boor(u).unwrap();
            prop_assert_eq!(p[0].to_bits(), want[0].to_bits(), "u = {}", u);
            prop_assert_eq!(p[1].to_bits(), want[1].to_bits(), "u = {}", u);
        }
    }
}

#[test]
fn ulp_close_huge_and_subnormal_knots_batch_as_de_boor() {
    let one = 1.0f64;
    let up = |k: u64| f64::from_bits(one.to_bits() + k);
    let tiny = f64::from_bits(1);
    let vectors = [
        vec![
            0.0,
            0.0,
            0.0,
            0.0,
            0.5,
            one,
            one,
            one,
            up(1),
            up(2),
            2.0,
            2.0,
            2.0,
            2.0,
        ],
        vec![
            -1e308, -1e308, -1e308, -1e308, 0.0, 1e308, 1e308, 1e308, 1e308,
        ],
        vec![
            0.0,
            0.0,
            0.0,
            0.0,
            tiny,
            2.0 * tiny,
            2.0 * tiny,
            2.0 * tiny,
            2.0 * tiny,
        ],
    ];
    for knots in vectors {
        let t = KnotVector::new(3, knots).unwrap();
        let n = t.control_points();
        let (a, b) = (*t.bounds().0, *t.bounds().1);
        let c = (0..n)
            .map(|i| Point::new([(i as f64 - 2.0) * 1e300, (i * i) as f64 * tiny]))
            .collect();
        let s = BSpline::new(c, t.clone()).unwrap();
        let mut us: Vec<f64> = t.knots().to_vec();
        us.extend((0..=16).map(|k| a + (b / 16.0 - a / 16.0) * k as f64));
        us.retain(|u| *u >= a && *u <= b);
        us.sort_by(f64::total_cmp);
        let got = s.eval_sorted(&us).unwrap();
        let e = exact(&s);
        for (u, p) in us.iter().zip(&got) {
            let want = s.de_boor(u).unwrap();
            assert_eq!(
                p.coords().map(f64::to_bits),
                want.coords().map(f64::to_bits)
            );
            assert!(p.is_finite(), "{u}: {p:?}");
            let pq = e.de_boor(&Q::from_f64(*u).unwrap()).unwrap().to_f64();
            assert!(
                (p[0] - pq[0]).abs() <= 1e-13 * 1e300 * n as f64,
                "{u}: {p:?} vs {pq:?}"
            );
        }
        // The blossom's diagonal on the huge and subnormal vectors: finite, the curve.
        for u in us.iter().step_by(3) {
            let p = s.blossom(&[*u; 3]).unwrap();
            let pq = e
                .blossom(&vec![Q::from_f64(*u).unwrap(); 3])
                .unwrap()
                .to_f64();
            assert!(p.is_finite());
            assert!(
                (p[0] - pq[0]).abs() <= 1e-13 * 1e300 * n as f64,
                "{u}: {p:?} vs {pq:?}"
            );
        }
        assert!(t
            .greville()
            .iter()
            .all(|x| x.is_finite() && *x >= t.knots()[0]));
    }
}

#[test]
fn bad_input_is_a_named_error() {
    let t = KnotVector::clamped_uniform(3, 6, 0.0, 3.0).unwrap();
    let s = BSpline::new((0..6).map(|i| Point::new([i as f64])).collect(), t).unwrap();
    for args in [&[][..], &[1.0, 2.0], &[1.0, 2.0, 3.0, 4.0]] {
        let e = s.blossom(args).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidParameter {
                    name: "blossom arguments",
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("needs 3 arguments"), "{e}");
        assert!(s.blossom_in_span(3, args).is_err());
    }
    for bad in [f64::NAN, f64::INFINITY] {
        let e = s.blossom(&[0.0, bad, 1.0]).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidParameter {
                    name: "blossom argument",
                    ..
                }
            ),
            "{e}"
        );
    }
    let e = s.blossom_in_span(6, &[0.0, 1.0, 2.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid span: the spans of the domain are 3..6 (degree 3, 6 control points), got 6"
    );
    let e = s.eval_sorted(&[0.0, 1.0, 0.5, 2.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid params: parameter 2 (0.5) is below parameter 1 (1)"
    );
    let e = s.eval_sorted(&[0.0, f64::NAN]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid params: parameter 1 is not finite (NaN)"
    );
    let e = s.eval_sorted(&[f64::NEG_INFINITY, 0.0]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid params: parameter 0 is not finite (-inf)"
    );
    let e = s.eval_sorted(&[0.0, 3.0, 3.5]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid params: parameter 2 (3.5) is outside the domain [0, 3]"
    );
    let e = s.knots().marsden(&f64::NAN).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "y", .. }),
        "{e}"
    );
    let t0 = KnotVector::new(0, vec![0.0, 1.0, 2.0]).unwrap();
    let s0 = BSpline::new(vec![Point::new([1.0]), Point::new([2.0])], t0).unwrap();
    assert!(matches!(
        s0.graph(),
        Err(Error::InvalidParameter { name: "degree", .. })
    ));
}

#[test]
fn the_blossom_in_the_exercise_of_ppb_5_12_7() {
    // [PPB, §5.12, Ex. 7]: s = Σ cᵢ Nᵢ³ on the knots 0, 1, …, 7 with c₀, …, c₃ = 4, 7, −2, 1
    // (given in the text), on its only span [3, 4]. The text states no answers to its
    // questions; the Taylor coefficients at 3 (s, s′, s″, s‴ = 5, −3, −12, 24) and the
    // Bézier points 5, 4, 1, 0 over [3, 4] were computed by hand (see
    // tests/suite/bspline_curve.rs, the same exercise). So s(3 + h) = 5 − 3h − 6h² + 4h³, whose
    // polar form in hᵢ = uᵢ − 3 is 5 − (h₁ + h₂ + h₃) − 2(h₁h₂ + h₁h₃ + h₂h₃) + 4h₁h₂h₃.
    let t = KnotVector::new(3, (0..=7).map(qi).collect()).unwrap();
    let s: BSpline<Q, 1> =
        BSpline::new([4, 7, -2, 1].map(|c| Point::new([qi(c)])).to_vec(), t).unwrap();
    // The control points are the blossom at consecutive knots (the fundamental theorem).
    for (i, c) in [4, 7, -2, 1].into_iter().enumerate() {
        let args: Vec<Q> = (1..=3).map(|j| qi((i + j) as i64)).collect();
        assert_eq!(s.blossom(&args).unwrap(), Point::new([qi(c)]), "c{i}");
        assert_eq!(s.blossom_in_span(3, &args).unwrap(), Point::new([qi(c)]));
    }
    // The Bézier points over [3, 4] are s[3, 3, 3], s[3, 3, 4], s[3, 4, 4], s[4, 4, 4].
    for (k, b) in [5, 4, 1, 0].into_iter().enumerate() {
        let args: Vec<Q> = (0..3).map(|j| qi(if j < 3 - k { 3 } else { 4 })).collect();
        assert_eq!(s.blossom(&args).unwrap(), Point::new([qi(b)]), "b{k}");
    }
    // The polar form of the monomial form at rational arguments, also outside [3, 4].
    let polar = |h: [Q; 3]| {
        let e1 = h[0].clone() + &h[1] + &h[2];
        let e2 = h[0].clone() * &h[1] + h[0].clone() * &h[2] + h[1].clone() * &h[2];
        let e3 = h[0].clone() * &h[1] * &h[2];
        qi(5) - e1 - qi(2) * e2 + qi(4) * e3
    };
    for (a, b, c) in [
        (0, 0, 0),
        (1, 5, 9),
        (-7, 3, 22),
        (40, -13, 6),
        (11, 11, -30),
    ] {
        let args = [q(a, 5) + qi(3), q(b, 7) + qi(3), q(c, 3) + qi(3)];
        let h = args.clone().map(|x| x - qi(3));
        assert_eq!(
            s.blossom(&args).unwrap(),
            Point::new([polar(h)]),
            "{a} {b} {c}"
        );
    }
    // The Greville abscissae of the uniform knots are the middles of the supports.
    assert_eq!(s.knots().greville(), [2, 3, 4, 5].map(qi));
}
