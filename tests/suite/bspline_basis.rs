//! Knot vectors and the B-spline basis, checked exactly on the rational back end against
//! independent oracles: the partition of unity with `==`; the values against the classical
//! definition as divided differences of the truncated power [PPB, §5.11]; the derivatives
//! against the exact derivative of the polynomial piece interpolated through d + 1 values of
//! the same span; the span search against a linear scan; the convention of [SPL, §12] against
//! this crate's. Then the `f64` path against the exact one on knots a few ulps apart, near
//! 1e300 and subnormal, and bad input, each a named error.

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{KnotVector, Scalar};
use compgeo::Error;
use proptest::prelude::*;

/// A positive rational step with a small denominator.
fn step() -> impl Strategy<Value = Q> {
    (1i64..=6, 1i64..=4).prop_map(|(n, d)| q(n, d))
}

/// A valid exact knot vector of degree 0..=4 with repeated knots: distinct values with
/// multiplicities 1..=d + 1, n = d + 1..=d + 5 control points.
pub(crate) fn knot_vector() -> impl Strategy<Value = KnotVector<Q>> {
    (0usize..=4, 1usize..=5).prop_flat_map(|(d, extra)| {
        let n = d + extra;
        let len = n + d + 1;
        (
            Just(d),
            -3i64..=3,
            prop::collection::vec((step(), 1..=d + 1), len),
        )
            .prop_filter_map("empty domain", move |(d, start, runs)| {
                let mut knots = Vec::with_capacity(len);
                let mut value = qi(start);
                for (s, m) in runs {
                    for _ in 0..m {
                        knots.push(value.clone());
                    }
                    value += s;
                }
                knots.truncate(len);
                KnotVector::new(d, knots).ok()
            })
    })
}

/// A parameter of the domain: an end, a knot of the domain, or a rational in between.
pub(crate) fn parameter(t: &KnotVector<Q>) -> impl Strategy<Value = Q> {
    let (a, b) = (t.bounds().0.clone(), t.bounds().1.clone());
    let inner: Vec<Q> = t
        .knots()
        .iter()
        .filter(|k| **k >= a && **k <= b)
        .cloned()
        .collect();
    prop_oneof![
        1 => Just(a.clone()),
        1 => Just(b.clone()),
        2 => prop::sample::select(inner),
        4 => (0i64..=60).prop_map(move |k| a.clone() + (b.clone() - &a) * q(k, 60)),
    ]
}

fn vector_and_parameter() -> impl Strategy<Value = (KnotVector<Q>, Q)> {
    knot_vector().prop_flat_map(|t| {
        let u = parameter(&t);
        (Just(t), u)
    })
}

/// The falling factorial m (m − 1) ⋯ (m − r + 1).
fn falling(m: usize, r: usize) -> Q {
    (0..r).fold(qi(1), |f, k| f * qi(m as i64 - k as i64))
}

/// The r-th derivative in a of the truncated power F(a) = (a − u)₊^m: zero for a ≤ u
/// (right-continuous in u), or for a < u with `left` (the left limit in u).
fn truncated(a: &Q, u: &Q, m: usize, r: usize, left: bool) -> Q {
    let inside = if left { a >= u } else { a > u };
    if !inside || r > m {
        return qi(0);
    }
    let base = a.clone() - u;
    (0..m - r).fold(falling(m, r), |p, _| p * &base)
}

/// The confluent divided difference [x₀ … x_m] of the function whose r-th derivative at x
/// is `f(x, r)` (x sorted): [x_i … x_j] = f^{(j−i)}(x_i)/(j − i)! when x_i = x_j, else
/// ([x_{i+1} … x_j] − [x_i … x_{j−1}])/(x_j − x_i) [PPB, §4.3–4.4].
fn divided_difference(x: &[Q], f: impl Fn(&Q, usize) -> Q) -> Q {
    let m = x.len();
    // table[i] holds [x_i … x_{i+len−1}] for the current len.
    let mut table: Vec<Q> = x.iter().map(|xi| f(xi, 0)).collect();
    for len in 2..=m {
        let mut next = Vec::with_capacity(m - len + 1);
        for i in 0..=m - len {
            let j = i + len - 1;
            if x[i] == x[j] {
                next.push(f(&x[i], len - 1) / falling(len - 1, len - 1));
            } else {
                next.push((table[i + 1].clone() - &table[i]) / (x[j].clone() - &x[i]));
            }
        }
        table = next;
    }
    table.pop().unwrap()
}

/// N_i^{(k)}(u) = (−1)^k (t_{i+d+1} − t_i) [t_i … t_{i+d+1}] ∂_u^k (a − u)₊^d, the classical
/// definition [PPB, §5.11] (the left limit at the domain's end, with `left`).
fn divided_difference_basis(t: &[Q], d: usize, i: usize, u: &Q, k: usize, left: bool) -> Q {
    if k > d {
        return qi(0);
    }
    let x = &t[i..=i + d + 1];
    let c = falling(d, k);
    let dd = divided_difference(x, |a, r| c.clone() * truncated(a, u, d - k, r, left));
    let v = (x[d + 1].clone() - &x[0]) * dd;
    if k % 2 == 1 {
        -v
    } else {
        v
    }
}

/// The k-th derivative at u of the polynomial through (x_s, y_s), by Newton's divided
/// differences and a shift of the Newton form to powers of (x − u).
fn polynomial_derivative(x: &[Q], y: &[Q], u: &Q, k: usize) -> Q {
    let m = x.len();
    let mut c = y.to_vec();
    for len in 1..m {
        for i in (len..m).rev() {
            c[i] = (c[i].clone() - &c[i - 1]) / (x[i].clone() - &x[i - len]);
        }
    }
    // p(y) = Σ c_j Π_{l<j} (y − y_l) with y = x − u, expanded from the inside out.
    let mut poly = vec![c[m - 1].clone()];
    for j in (0..m - 1).rev() {
        let shift = x[j].clone() - u;
        let mut next = vec![qi(0); poly.len() + 1];
        for (e, a) in poly.iter().enumerate() {
            next[e + 1] += a;
            next[e] -= a.clone() * &shift;
        }
        next[0] += &c[j];
        poly = next;
    }
    poly.get(k).cloned().unwrap_or_else(|| qi(0)) * falling(k, k)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_basis_is_exactly_a_partition_of_unity((t, u) in vector_and_parameter()) {
        let b = t.basis(&u).unwrap();
        prop_assert_eq!(b.values().len(), t.degree() + 1);
        let sum = b.values().iter().fold(qi(0), |s, v| s + v);
        prop_assert_eq!(sum, qi(1));
        prop_assert!(b.values().iter().all(|v| *v >= qi(0)));
    }

    #[test]
    fn basis_values_are_divided_differences_of_the_truncated_power(
        (t, u) in vector_and_parameter()
    ) {
        let (d, n) = (t.degree(), t.control_points());
        let b = t.basis(&u).unwrap();
        let left = u == *t.bounds().1;
        for i in 0..n {
            let want = divided_difference_basis(t.knots(), d, i, &u, 0, left);
            prop_assert_eq!(b.get(i), want, "N_{} at {} on {:?}", i, u, t.knots());
        }
    }

    #[test]
    fn derivatives_are_those_of_the_polynomial_piece(
        (t, u) in vector_and_parameter(),
        extra in 0usize..=2,
    ) {
        let d = t.degree();
        let k = d + extra;
        let der = t.basis_derivatives(&u, k).unwrap();
        let b = t.basis(&u).unwrap();
        prop_assert_eq!(der.order(0), b.values());
        prop_assert_eq!(der.span(), b.span());
        // d + 1 parameters of the same span [t_μ, t_{μ+1}) determine its polynomial piece.
        let mu = b.span();
        let (lo, hi) = (t.knots()[mu].clone(), t.knots()[mu + 1].clone());
        let xs: Vec<Q> = (0..=d)
            .map(|s| lo.clone() + (hi.clone() - &lo) * q(s as i64, d as i64 + 1))
            .collect();
        let samples: Vec<_> = xs.iter().map(|x| t.basis(x).unwrap()).collect();
        for s in &samples {
            prop_assert_eq!(s.span(), mu);
        }
        for f in 0..=d {
            let i = mu - d + f;
            let ys: Vec<Q> = samples.iter().map(|s| s.get(i)).collect();
            for order in 0..=k {
                let want = polynomial_derivative(&xs, &ys, &u, order);
                prop_assert_eq!(der.get(order, i), want, "N_{}^({}) at {}", i, order, u);
            }
        }
    }

    #[test]
    fn derivatives_are_divided_differences_too((t, u) in vector_and_parameter()) {
        // The right derivative (left at the domain's end) of the classical definition.
        let (d, n) = (t.degree(), t.control_points());
        let der = t.basis_derivatives(&u, d).unwrap();
        let left = u == *t.bounds().1;
        for k in 0..=d {
            for i in 0..n {
                let want = divided_difference_basis(t.knots(), d, i, &u, k, left);
                prop_assert_eq!(der.get(k, i), want, "N_{}^({}) at {}", i, k, u);
            }
        }
    }

    #[test]
    fn the_span_search_agrees_with_a_linear_scan((t, u) in vector_and_parameter()) {
        let (d, n, k) = (t.degree(), t.control_points(), t.knots());
        let scan = if u == k[n] {
            (d..n).filter(|&i| k[i] < k[n]).max().unwrap()
        } else {
            (d..n).find(|&i| k[i] <= u && u < k[i + 1]).unwrap()
        };
        let mut c = Counts::default();
        prop_assert_eq!(t.span_with(&u, &mut c).unwrap(), scan);
        let bound = 2 + (usize::BITS - (n - d).leading_zeros()) as u64 + 1;
        prop_assert!(c.comparisons <= bound, "{} > {}", c.comparisons, bound);
    }

    #[test]
    fn the_spl_convention_gives_the_same_basis((t, u) in vector_and_parameter()) {
        prop_assume!(t.degree() >= 1);
        let d = t.degree();
        let spl = t.to_spl().to_vec();
        // Through the adapter: the same knots back, hence the same basis.
        let adapted = KnotVector::from_spl(d, &spl);
        if let Ok(adapted) = &adapted {
            prop_assert_eq!(adapted.to_spl(), &spl[..]);
            prop_assert_eq!(adapted.basis(&u).unwrap(), t.basis(&u).unwrap());
        } else {
            // Only an end knot of multiplicity d + 1 in SPL's list is refused.
            let m = t.knots().iter().filter(|k| **k == t.knots()[1]).count();
            let m_end = t.knots().iter().filter(|k| **k == spl[spl.len() - 1]).count();
            prop_assert!(m == d + 1 || m_end == d + 1, "{:?}", adapted);
        }
        // Against SPL's own recursion (28) in its own indices, with end knots of its own.
        let left = u == *t.bounds().1;
        let basis = t.basis(&u).unwrap();
        for i in 0..t.control_points() {
            prop_assert_eq!(basis.get(i), spl_basis(&spl, d, i, &u, left), "N_{}", i);
        }
    }

    #[test]
    fn the_f64_basis_agrees_with_the_exact_one(
        (t, u) in vector_and_parameter()
    ) {
        let knots: Vec<f64> = t.knots().iter().map(Scalar::to_f64).collect();
        let tf = KnotVector::new(t.degree(), knots.clone()).unwrap();
        let uf = u.to_f64();
        let exact_t = KnotVector::new(
            t.degree(),
            knots.iter().map(|k| Q::from_f64(*k).unwrap()).collect(),
        )
        .unwrap();
        let exact = exact_t.basis_derivatives(&Q::from_f64(uf).unwrap(), t.degree()).unwrap();
        let fast = tf.basis_derivatives(&uf, t.degree()).unwrap();
        prop_assert_eq!(fast.span(), exact.span());
        for k in 0..=t.degree() {
            let row: Vec<f64> = exact.order(k).iter().map(Scalar::to_f64).collect();
            let scale = row.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            for (f, e) in fast.order(k).iter().zip(&row) {
                prop_assert!((f - e).abs() <= 1e-12 * scale, "order {}: {} vs {}", k, f, e);
            }
        }
    }
}

/// SPL's basis function N_i^p (support [u_{i−1}, u_{i+p}]) by its recursion (28), in SPL's
/// indices, with the end knots u_{−1} = u₀ − 1 and u_{last+1} = u_last + 1 (any values do
/// on the domain); terms with a zero denominator are zero. `left` takes the degree-0
/// functions left-continuous (u ∈ (u_{i−1}, u_i]), for the end of the domain.
fn spl_basis(spl: &[Q], p: usize, i: usize, u: &Q, left: bool) -> Q {
    let knot = |j: isize| -> Q {
        if j < 0 {
            spl[0].clone() - qi(1)
        } else if j as usize >= spl.len() {
            spl[spl.len() - 1].clone() + qi(1)
        } else {
            spl[j as usize].clone()
        }
    };
    let i = i as isize;
    if p == 0 {
        let (a, b) = (knot(i - 1), knot(i));
        let inside = if left {
            a < *u && *u <= b
        } else {
            a <= *u && *u < b
        };
        return if inside { qi(1) } else { qi(0) };
    }
    let p_i = p as isize;
    let mut v = qi(0);
    let den = knot(i + p_i - 1) - knot(i - 1);
    if den != qi(0) {
        v += (u.clone() - knot(i - 1)) / den * spl_basis(spl, p - 1, i as usize, u, left);
    }
    let den = knot(i + p_i) - knot(i);
    if den != qi(0) {
        v += (knot(i + p_i) - u) / den * spl_basis(spl, p - 1, i as usize + 1, u, left);
    }
    v
}

#[test]
fn the_counter_counts_exactly_the_triangular_steps() {
    for d in 0..=6usize {
        let t = KnotVector::clamped_uniform(d, d + 4, 0.0, 1.0).unwrap();
        let mut c = Counts::default();
        t.basis_with(&0.37, &mut c).unwrap();
        assert_eq!(
            c.arithmetic_operations,
            (d * (d + 1) / 2) as u64,
            "degree {d}"
        );
        for k in 0..=d + 2 {
            let mut c = Counts::default();
            t.basis_derivatives_with(&0.37, k, &mut c).unwrap();
            let kk = k.min(d);
            let want = d * (d + 1) / 2 + (d + 1) * kk * (kk + 3) / 2;
            assert_eq!(
                c.arithmetic_operations, want as u64,
                "degree {d}, order {k}"
            );
        }
    }
}

#[test]
fn knots_a_few_ulps_apart_are_distinct_and_exact() {
    let one = 1.0f64;
    let up = |x: f64, k: u64| f64::from_bits(x.to_bits() + k);
    let knots = vec![0.0, 0.0, 0.0, one, up(one, 1), up(one, 3), 2.0, 2.0, 2.0];
    let t = KnotVector::new(2, knots.clone()).unwrap();
    assert_eq!(
        t.multiplicities(),
        [
            (0.0, 3),
            (one, 1),
            (up(one, 1), 1),
            (up(one, 3), 1),
            (2.0, 3)
        ]
    );
    let exact =
        KnotVector::new(2, knots.iter().map(|k| Q::from_f64(*k).unwrap()).collect()).unwrap();
    for u in [
        0.5,
        one,
        up(one, 1),
        up(one, 2),
        up(one, 3),
        up(one, 4),
        f64::from_bits(one.to_bits() - 1),
        2.0,
    ] {
        let (f, e) = (
            t.basis(&u).unwrap(),
            exact.basis(&Q::from_f64(u).unwrap()).unwrap(),
        );
        assert_eq!(f.span(), e.span(), "u = {u:e}");
        for (a, b) in f.values().iter().zip(e.values()) {
            assert!((a - b.to_f64()).abs() <= 1e-14, "u = {u:e}: {a} vs {b}");
        }
        // Derivatives of order 1 are of size 1/ulp; relative agreement.
        let (fd, ed) = (
            t.basis_derivatives(&u, 2).unwrap(),
            exact
                .basis_derivatives(&Q::from_f64(u).unwrap(), 2)
                .unwrap(),
        );
        for k in 1..=2 {
            let row: Vec<f64> = ed.order(k).iter().map(Scalar::to_f64).collect();
            let scale = row.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (a, b) in fd.order(k).iter().zip(&row) {
                assert!(
                    (a - b).abs() <= 1e-10 * scale,
                    "u = {u:e}, order {k}: {a} vs {b}"
                );
            }
        }
    }
}

/// `f64` against the exact basis on the same knots: values within a few ulps, derivatives
/// relative to the largest of their order.
fn agrees_with_exact(degree: usize, knots: &[f64], us: &[f64], derivatives: bool) {
    let t = KnotVector::new(degree, knots.to_vec()).unwrap();
    let exact = KnotVector::new(
        degree,
        knots.iter().map(|k| Q::from_f64(*k).unwrap()).collect(),
    )
    .unwrap();
    for &u in us {
        let uq = Q::from_f64(u).unwrap();
        let (f, e) = (t.basis(&u).unwrap(), exact.basis(&uq).unwrap());
        assert_eq!(f.span(), e.span(), "u = {u:e}");
        for (a, b) in f.values().iter().zip(e.values()) {
            assert!(
                a.is_finite() && (a - b.to_f64()).abs() <= 1e-14,
                "u = {u:e}: {a} vs {b}"
            );
        }
        if derivatives {
            let (fd, ed) = (
                t.basis_derivatives(&u, degree).unwrap(),
                exact.basis_derivatives(&uq, degree).unwrap(),
            );
            for k in 1..=degree {
                let row: Vec<f64> = ed.order(k).iter().map(Scalar::to_f64).collect();
                let scale = row.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                for (a, b) in fd.order(k).iter().zip(&row) {
                    assert!(
                        (a - b).abs() <= 1e-12 * scale + 1e-320,
                        "u = {u:e}, order {k}: {a:e} vs {b:e}"
                    );
                }
            }
        }
    }
}

#[test]
fn huge_knots_give_the_exact_basis() {
    let knots = [0.0, 0.0, 0.0, 1e300, 2.5e300, 3e300, 3e300, 3e300];
    agrees_with_exact(2, &knots, &[0.0, 7e299, 1e300, 2.9e300, 3e300], true);
    // Knots farther apart than the double range: their differences overflow, the basis not.
    let m = f64::MAX;
    let knots = [-m, -m, -m, -0.5 * m, 0.25 * m, m, m, m];
    agrees_with_exact(2, &knots, &[-m, -1e308, 0.0, 1e300, 0.3 * m, m], true);
}

#[test]
fn subnormal_knots_give_the_exact_basis() {
    let s = f64::from_bits(1); // 2^-1074
    let knots = [0.0, 0.0, s, 3.0 * s, 4.0 * s, 4.0 * s];
    agrees_with_exact(1, &knots, &[0.0, s, 2.0 * s, 3.0 * s, 4.0 * s], false);
    // The derivatives are near 2^1074, beyond the double range: a named error, not inf.
    let t = KnotVector::new(1, knots.to_vec()).unwrap();
    assert_eq!(
        t.basis_derivatives(&s, 1),
        Err(Error::Overflow {
            what: "B-spline basis derivative"
        })
    );
    // Knots 2^-1000 apart have derivatives near 2^1000: finite, and right.
    let h = 2f64.powi(-1000);
    let knots = [0.0, 0.0, h, 3.0 * h, 3.0 * h];
    agrees_with_exact(1, &knots, &[0.0, 0.3 * h, h, 1.5 * h, 3.0 * h], true);
}

#[test]
fn bad_input_is_a_named_error() {
    let msg = |r: compgeo::Result<KnotVector<f64>>| r.unwrap_err().to_string();
    assert_eq!(
        msg(KnotVector::new(1, vec![0.0, 1.0, f64::NAN, 2.0])),
        "invalid knots: knot 2 is not finite (NaN)"
    );
    assert_eq!(
        msg(KnotVector::new(1, vec![f64::NEG_INFINITY, 0.0, 1.0, 2.0])),
        "invalid knots: knot 0 is not finite (-inf)"
    );
    assert_eq!(
        msg(KnotVector::new(
            2,
            vec![0.0, 0.0, 0.0, 2.0, 1.0, 3.0, 3.0, 3.0]
        )),
        "invalid knots: knot 4 (1) is below knot 3 (2)"
    );
    assert_eq!(
        msg(KnotVector::new(
            2,
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0]
        )),
        "invalid knots: knots 3..=6 (1) have multiplicity 4, more than degree + 1 = 3"
    );
    assert_eq!(
        msg(KnotVector::new(3, vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0])),
        "knots (degree d needs 2d + 2) needs at least 8 elements, got 7"
    );
    assert!(matches!(
        KnotVector::new(usize::MAX, vec![0.0, 1.0]),
        Err(Error::LimitExceeded {
            limit: "MAX_DEGREE",
            ..
        })
    ));
    assert!(matches!(
        KnotVector::<f64>::clamped_uniform(usize::MAX, 3, 0.0, 1.0),
        Err(Error::LimitExceeded {
            limit: "MAX_DEGREE",
            ..
        })
    ));
    assert!(matches!(
        KnotVector::<f64>::uniform(3, usize::MAX - 1, 0.0, 1.0),
        Err(Error::LimitExceeded {
            limit: "MAX_KNOTS",
            ..
        })
    ));
    assert!(KnotVector::<f64>::averaged(2, &[0.0, f64::NAN, 1.0]).is_err());

    let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0).unwrap();
    for u in [-0.5, 1.0 + f64::EPSILON, f64::NAN, f64::INFINITY] {
        let e = t.basis(&u).unwrap_err();
        assert!(
            matches!(&e, Error::InvalidParameter { name: "u", .. }),
            "{u}: {e}"
        );
    }
    assert_eq!(
        t.basis(&-0.5).unwrap_err().to_string(),
        "invalid u: -0.5 is outside [0, 1]"
    );
    assert!(matches!(
        t.basis_derivatives(&0.5, usize::MAX),
        Err(Error::LimitExceeded {
            limit: "MAX_DEGREE",
            ..
        })
    ));
    let wide = KnotVector::clamped_uniform(60_000, 60_001, 0.0, 1.0).unwrap();
    assert!(matches!(
        wide.basis_derivatives(&0.5, 60_000),
        Err(Error::LimitExceeded {
            limit: "MAX_BASIS_TABLE",
            ..
        })
    ));
}

#[test]
fn exact_rational_knots_a_hair_apart_keep_their_multiplicities() {
    // 1 and 1 + 10^-30 are distinct knots: no tolerance merges them into a triple knot.
    let tiny = q(1, 1_000_000_000_000_000) * q(1, 1_000_000_000_000_000);
    let knots = vec![
        qi(0),
        qi(0),
        qi(0),
        qi(1),
        qi(1),
        qi(1) + tiny.clone(),
        qi(2),
        qi(2),
        qi(2),
    ];
    let t = KnotVector::new(2, knots).unwrap();
    assert_eq!(t.multiplicity(&qi(1)), 2);
    let u = qi(1) + tiny / qi(2);
    let b = t.basis(&u).unwrap();
    assert_eq!(b.span(), 4);
    assert_eq!(b.values().iter().fold(qi(0), |s, v| s + v), qi(1));
}
