//! Tensor-product Bézier patches, checked exactly on the rational back end: the three
//! evaluations (rows first, columns first, the tensor de Casteljau algorithm) and the trait's
//! `eval` against the double sum Σ c_{i,j} Bᵢᵐ(u) Bⱼⁿ(v) of the Bernstein polynomials (an
//! independent oracle), also outside [0, 1]²; the isoparametric curves against the surface;
//! the partial derivatives against the double sum of Bernstein derivatives; the exact counts;
//! the worked example of [FJ-surfaces, §2] (a net of bidegree (2, 3) and its monomial form,
//! from `tests/fixtures/fj_surfaces_bidegree_2_3.txt`) and its graph of f(x, y) = xy; `f64`
//! against exact; bad nets and parameters as named errors.
//!
//! The operations of the patch, exactly: the blossom (symmetric, multi-affine, the patch on
//! its diagonal, the net at 0s and 1s), restriction and subdivision against the patch after
//! the affine change of parameters and against the blossom, elevation, the derivative nets
//! against `partial_at` and against differences of blossoms, the monomial form against its
//! own sum and back, the bounding box around samples, the normal (regular, and at a
//! collapsed edge against the derivative of the normal field by exact interpolation), the Cʳ
//! construction against the Cʳ check and a perturbation; every count; bad input.

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{bernstein, bernstein_derivative, Curve, Point, Scalar};
use compgeo::surface::{
    normal, normal_with, BezierPatch, ControlNet, Normal, Surface, SurfaceDerivative,
};
use compgeo::Error;
use proptest::prelude::*;

/// A patch of bidegree (0..=4, 0..=4) with integer points in R³.
fn patch() -> impl Strategy<Value = BezierPatch<Q, 3>> {
    (1usize..=5, 1usize..=5)
        .prop_flat_map(|(rows, columns)| {
            (
                Just(columns),
                prop::collection::vec((-20i64..=20, -20i64..=20, -20i64..=20), rows * columns),
            )
        })
        .prop_map(|(columns, pts)| {
            let points = pts
                .into_iter()
                .map(|(x, y, z)| Point::new([qi(x), qi(y), qi(z)]))
                .collect::<Vec<_>>();
            let rows = points.len() / columns;
            BezierPatch::new(ControlNet::from_rows(rows, columns, points).unwrap()).unwrap()
        })
}

/// A rational parameter in [−1, 2] (outside the unit interval too).
fn parameter() -> impl Strategy<Value = Q> {
    (-12i64..=24).prop_map(|k| q(k, 12))
}

/// Σᵢ Σⱼ c_{i,j} Bᵢᵐ⁽ʳ⁾(u) Bⱼⁿ⁽ˢ⁾(v) from the Bernstein polynomials and their derivatives.
fn double_sum(s: &BezierPatch<Q, 3>, u: &Q, v: &Q, r: usize, k: usize) -> Point<Q, 3> {
    let (m, n) = s.bidegree();
    let mut sum = Point::zero();
    for i in 0..=m {
        let bu = if r == 0 {
            bernstein(m, i, u).unwrap()
        } else if r > m {
            qi(0)
        } else {
            bernstein_derivative(m, i, r, u).unwrap()
        };
        for j in 0..=n {
            let bv = if k == 0 {
                bernstein(n, j, v).unwrap()
            } else if k > n {
                qi(0)
            } else {
                bernstein_derivative(n, j, k, v).unwrap()
            };
            sum += &(s.net().get(i, j).clone() * &(bu.clone() * &bv));
        }
    }
    sum
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn every_evaluation_is_the_double_sum(s in patch(), u in parameter(), v in parameter()) {
        let want = double_sum(&s, &u, &v, 0, 0);
        let (m, n) = s.bidegree();
        let (m64, n64) = (m as u64, n as u64);
        let mut c = Counts::default();
        prop_assert_eq!(s.rows_first_with(&u, &v, &mut c).unwrap(), want.clone());
        prop_assert_eq!(c.arithmetic_operations, (m64 + 1) * n64 * (n64 + 1) / 2 + m64 * (m64 + 1) / 2);
        let mut c = Counts::default();
        prop_assert_eq!(s.columns_first_with(&u, &v, &mut c).unwrap(), want.clone());
        prop_assert_eq!(c.arithmetic_operations, (n64 + 1) * m64 * (m64 + 1) / 2 + n64 * (n64 + 1) / 2);
        let mut c = Counts::default();
        prop_assert_eq!(s.de_casteljau_with(&u, &v, &mut c).unwrap(), want.clone());
        let levels = m64.min(n64);
        let steps: u64 = (1..=levels).map(|k| (m64 - k + 1) * (n64 - k + 1)).sum();
        let rest = m64.abs_diff(n64);
        prop_assert_eq!(c.arithmetic_operations, 3 * steps + rest * (rest + 1) / 2);
        prop_assert_eq!(s.eval(&u, &v).unwrap(), want);
    }

    #[test]
    fn isoparametric_curves_lie_on_the_surface(s in patch(), u in parameter(), v in parameter()) {
        let (m, n) = s.bidegree();
        let at_u = s.curve_at_u(&u).unwrap();
        let at_v = s.curve_at_v(&v).unwrap();
        prop_assert_eq!(at_u.degree(), n);
        prop_assert_eq!(at_v.degree(), m);
        let point = s.eval(&u, &v).unwrap();
        prop_assert_eq!(at_u.eval(&v).unwrap(), point.clone());
        prop_assert_eq!(at_v.eval(&u).unwrap(), point);
        // The boundary curves are the net's boundary polygons [FJ-surfaces, §3].
        let (first_row, last_column) = (s.curve_at_u(&qi(0)).unwrap(), s.curve_at_v(&qi(1)).unwrap());
        prop_assert_eq!(first_row.control(), s.net().row(0));
        prop_assert_eq!(last_column.control(), &s.net().column(n)[..]);
    }

    #[test]
    fn partial_derivatives_are_the_double_sum_of_bernstein_derivatives(
        s in patch(),
        u in parameter(),
        v in parameter(),
        r in 0usize..=5,
        k in 0usize..=5,
    ) {
        prop_assert_eq!(s.partial_at(&u, &v, r, k).unwrap(), double_sum(&s, &u, &v, r, k));
    }

    #[test]
    fn transposing_the_net_exchanges_u_and_v(s in patch(), u in parameter(), v in parameter()) {
        let t = BezierPatch::new(s.net().transposed()).unwrap();
        let (m, n) = s.bidegree();
        prop_assert_eq!(t.bidegree(), (n, m));
        prop_assert_eq!(t.eval(&v, &u).unwrap(), s.eval(&u, &v).unwrap());
        prop_assert_eq!(t.partial_at(&v, &u, 0, 1).unwrap(), s.partial_at(&u, &v, 1, 0).unwrap());
    }

    #[test]
    fn f64_agrees_with_exact(s in patch(), u in parameter(), v in parameter()) {
        // Coordinates up to 20 and |u|, |v| ≤ 2: every scheme forms affine combinations with
        // weights up to 3 in magnitude, so the error stays far below 1e-9.
        let sf = BezierPatch::new(s.net().to_f64()).unwrap();
        let want = s.eval(&u, &v).unwrap().to_f64();
        let (uf, vf) = (u.to_f64(), v.to_f64());
        for got in [
            sf.eval(&uf, &vf).unwrap(),
            sf.rows_first(&uf, &vf).unwrap(),
            sf.columns_first(&uf, &vf).unwrap(),
            sf.de_casteljau(&uf, &vf).unwrap(),
        ] {
            for j in 0..3 {
                prop_assert!((got[j] - want[j]).abs() <= 1e-9, "{:?} vs {:?}", got, want);
            }
        }
    }
}

/// The numbers inside "(a, b, c)" groups of a line.
fn triples(line: &str) -> Vec<Point<Q, 3>> {
    line.split('(')
        .skip(1)
        .map(|group| {
            let inner = &group[..group.find(')').unwrap()];
            let xs: Vec<Q> = inner
                .split(',')
                .map(|x| qi(x.trim().parse().unwrap()))
                .collect();
            Point::new([xs[0].clone(), xs[1].clone(), xs[2].clone()])
        })
        .collect()
}

#[test]
fn the_worked_example_of_fj_surfaces_2() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures/fj_surfaces_bidegree_2_3.txt"),
    )
    .unwrap();
    let mut rows = Vec::new();
    let mut terms = Vec::new();
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("net ") {
            rows.push(triples(rest));
        } else if let Some(rest) = line.strip_prefix("term ") {
            let t: Vec<i64> = rest
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            terms.push((t[0] as usize, t[1] as i32, t[2] as i32, qi(t[3])));
        }
    }
    assert_eq!((rows.len(), terms.len()), (3, 15));
    let s = BezierPatch::new(ControlNet::new(rows).unwrap()).unwrap();
    assert_eq!(s.bidegree(), (2, 3));
    // The monomial form printed in the text, at rational parameters in and beyond [0, 1]².
    for (a, b) in [(0, 0), (1, 1), (1, 3), (2, 5), (-3, 7), (9, -4), (6, 6)] {
        let (u, v) = (q(a, 6), q(b, 6));
        let mut want = [qi(0), qi(0), qi(0)];
        for (coordinate, pu, pv, coefficient) in &terms {
            want[*coordinate] += coefficient.clone() * u.pow(*pu) * v.pow(*pv);
        }
        assert_eq!(s.eval(&u, &v).unwrap(), Point::new(want), "({u}, {v})");
    }
    // The graph of f(x, y) = xy: the net (0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1).
    let p = |x: i64, y: i64, z: i64| Point::new([qi(x), qi(y), qi(z)]);
    let graph = BezierPatch::new(
        ControlNet::new(vec![
            vec![p(0, 0, 0), p(0, 1, 0)],
            vec![p(1, 0, 0), p(1, 1, 1)],
        ])
        .unwrap(),
    )
    .unwrap();
    for (x, y) in [(q(1, 3), q(3, 4)), (qi(-2), q(5, 2))] {
        let z = x.clone() * &y;
        assert_eq!(
            graph.eval(&x, &y).unwrap(),
            Point::new([x.clone(), y.clone(), z])
        );
    }
}

#[test]
fn bad_nets_and_parameters_are_named_errors() {
    let p = |x: f64| Point::new([x, 0.0]);
    let ragged = ControlNet::new(vec![vec![p(0.0), p(1.0)], vec![p(2.0)]]).unwrap_err();
    assert_eq!(
        ragged.to_string(),
        "invalid net: row 1 has 1 points but row 0 has 2 (a control net is rectangular)"
    );
    assert!(matches!(
        ControlNet::<f64, 2>::new(vec![]),
        Err(Error::Empty { .. })
    ));
    assert!(matches!(
        ControlNet::<f64, 2>::new(vec![vec![]]),
        Err(Error::Empty { .. })
    ));
    let e = ControlNet::new(vec![vec![p(0.0), p(1.0)], vec![p(2.0), p(f64::NAN)]]).unwrap_err();
    assert!(e.to_string().contains("point (1, 1)"), "{e}");
    let e = ControlNet::from_rows(2, 2, vec![p(0.0); 3]).unwrap_err();
    assert!(
        e.to_string().contains("2 × 2 = 4 points expected, got 3"),
        "{e}"
    );
    let e = ControlNet::from_rows(1 << 20, 1 << 20, vec![p(0.0)]).unwrap_err();
    assert!(matches!(e, Error::LimitExceeded { .. }), "{e}");
    let s = BezierPatch::new(
        ControlNet::new(vec![vec![p(0.0), p(1.0)], vec![p(2.0), p(3.0)]]).unwrap(),
    )
    .unwrap();
    for (u, v, name) in [
        (f64::NAN, 0.5, "u"),
        (0.5, f64::INFINITY, "v"),
        (f64::NEG_INFINITY, 0.5, "u"),
    ] {
        for e in [
            s.eval(&u, &v).unwrap_err(),
            s.rows_first(&u, &v).unwrap_err(),
            s.columns_first(&u, &v).unwrap_err(),
            s.de_casteljau(&u, &v).unwrap_err(),
            s.partial_at(&u, &v, 1, 1).unwrap_err(),
        ] {
            assert!(
                matches!(e, Error::InvalidParameter { name: n, .. } if n == name),
                "{e}"
            );
        }
    }
    assert!(s.curve_at_u(&f64::NAN).is_err() && s.curve_at_v(&f64::NAN).is_err());
}

/// A rational in (0, 1).
fn inside() -> impl Strategy<Value = Q> {
    (1i64..=11).prop_map(|k| q(k, 12))
}

/// An interval lo < hi with rational ends in [−1, 2].
fn interval() -> impl Strategy<Value = (Q, Q)> {
    (-6i64..=12, 1i64..=12).prop_map(|(a, w)| (q(a, 6), q(a + w, 6)))
}

/// (1 − t)·lo + t·hi.
fn mix(lo: &Q, hi: &Q, t: &Q) -> Q {
    (qi(1) - t) * lo + t.clone() * hi
}

/// `count` copies of `a` then copies of `b` up to `len`.
fn args(len: usize, count_b: usize, a: &Q, b: &Q) -> Vec<Q> {
    (0..len)
        .map(|k| {
            if k < len - count_b {
                a.clone()
            } else {
                b.clone()
            }
        })
        .collect()
}

/// u(n) as u64.
fn w(n: usize) -> u64 {
    n as u64
}

/// The derivative at 0 of the polynomial f of degree < `nodes` by exact Lagrange
/// interpolation at h = 0, 1, …, nodes − 1 (scaled by `step`).
fn derivative_at_zero(nodes: usize, step: &Q, f: impl Fn(&Q) -> Point<Q, 3>) -> Point<Q, 3> {
    let xs: Vec<Q> = (0..nodes).map(|k| qi(k as i64) * step).collect();
    let mut sum = Point::zero();
    for k in 0..nodes {
        // L_k'(0) = Σ_{l≠k} 1/(x_k − x_l) Π_{i≠k,l} (0 − x_i)/(x_k − x_i).
        let mut weight = qi(0);
        for l in (0..nodes).filter(|&l| l != k) {
            let mut term = qi(1) / (xs[k].clone() - &xs[l]);
            for i in (0..nodes).filter(|&i| i != k && i != l) {
                term = term * (-xs[i].clone()) / (xs[k].clone() - &xs[i]);
            }
            weight += term;
        }
        sum += &(f(&xs[k]) * &weight);
    }
    sum
}

fn cross(a: &Point<Q, 3>, b: &Point<Q, 3>) -> Point<Q, 3> {
    let c = |i: usize, j: usize| a[i].clone() * &b[j] - a[j].clone() * &b[i];
    Point::new([c(1, 2), c(2, 0), c(0, 1)])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn the_blossom_is_symmetric_multi_affine_and_the_patch_on_its_diagonal(
        s in patch(),
        us in prop::collection::vec(parameter(), 4),
        vs in prop::collection::vec(parameter(), 4),
        x in parameter(),
        lambda in parameter(),
    ) {
        let (m, n) = s.bidegree();
        let (us, vs) = (&us[..m], &vs[..n]);
        let mut c = Counts::default();
        let value = s.blossom_with(us, vs, &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, (w(m) + 1) * w(n) * (w(n) + 1) / 2 + w(m) * (w(m) + 1) / 2);
        let reversed = |xs: &[Q]| xs.iter().rev().cloned().collect::<Vec<_>>();
        prop_assert_eq!(s.blossom(&reversed(us), &reversed(vs)).unwrap(), value.clone());
        // Affine in the first u argument and in the last v argument.
        if m > 0 {
            let at = |t: &Q| { let mut a = us.to_vec(); a[0] = t.clone(); s.blossom(&a, vs).unwrap() };
            let (p0, p1) = (at(&x), at(&(x.clone() + qi(1))));
            let mid = at(&(x.clone() + &lambda));
            prop_assert_eq!(mid, p0.clone() * &(qi(1) - &lambda) + &(p1 * &lambda));
        }
        if n > 0 {
            let at = |t: &Q| { let mut a = vs.to_vec(); a[n - 1] = t.clone(); s.blossom(us, &a).unwrap() };
            let (p0, p1) = (at(&x), at(&(x.clone() + qi(2))));
            let mid = at(&(x.clone() + qi(2) * &lambda));
            prop_assert_eq!(mid, p0.clone() * &(qi(1) - &lambda) + &(p1 * &lambda));
        }
        // The diagonal, and the control points at 0s and 1s.
        prop_assert_eq!(s.blossom(&vec![x.clone(); m], &vec![lambda.clone(); n]).unwrap(), s.eval(&x, &lambda).unwrap());
        let (zero, one) = (qi(0), qi(1));
        for i in 0..=m {
            for j in 0..=n {
                prop_assert_eq!(&s.blossom(&args(m, i, &zero, &one), &args(n, j, &zero, &one)).unwrap(), s.net().get(i, j));
            }
        }
    }

    #[test]
    fn restriction_reproduces_the_patch_and_is_the_blossom(
        s in patch(),
        (a, b) in interval(),
        (c, d) in interval(),
        x in parameter(),
        y in parameter(),
    ) {
        let (m, n) = s.bidegree();
        let mut counts = Counts::default();
        let r = s.restrict_with(&a, &b, &c, &d, &mut counts).unwrap();
        prop_assert_eq!(counts.arithmetic_operations, (w(m) + 1) * w(n) * (w(n) + 1) + (w(n) + 1) * w(m) * (w(m) + 1));
        prop_assert_eq!(r.bidegree(), (m, n));
        prop_assert_eq!(r.eval(&x, &y).unwrap(), s.eval(&mix(&a, &b, &x), &mix(&c, &d, &y)).unwrap());
        for i in 0..=m {
            for j in 0..=n {
                prop_assert_eq!(&s.blossom(&args(m, i, &a, &b), &args(n, j, &c, &d)).unwrap(), r.net().get(i, j));
            }
        }
    }

    #[test]
    fn subdivision_reproduces_the_patch(
        s in patch(),
        t in inside(),
        t2 in inside(),
        x in parameter(),
        y in parameter(),
    ) {
        let (m, n) = s.bidegree();
        let (zero, one) = (qi(0), qi(1));
        let mut c = Counts::default();
        let (low, high) = s.split_u_with(&t, &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, (w(n) + 1) * w(m) * (w(m) + 1) / 2);
        prop_assert_eq!(low.eval(&x, &y).unwrap(), s.eval(&mix(&zero, &t, &x), &y).unwrap());
        prop_assert_eq!(high.eval(&x, &y).unwrap(), s.eval(&mix(&t, &one, &x), &y).unwrap());
        prop_assert_eq!(&low, &s.restrict(&zero, &t, &zero, &one).unwrap());
        let mut c = Counts::default();
        let (low, high) = s.split_v_with(&t, &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, (w(m) + 1) * w(n) * (w(n) + 1) / 2);
        prop_assert_eq!(low.eval(&x, &y).unwrap(), s.eval(&x, &mix(&zero, &t, &y)).unwrap());
        prop_assert_eq!(high.eval(&x, &y).unwrap(), s.eval(&x, &mix(&t, &one, &y)).unwrap());
        let mut c = Counts::default();
        let pieces = s.split_with(&t, &t2, &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, (w(n) + 1) * w(m) * (w(m) + 1) / 2 + (w(m) + 1) * w(n) * (w(n) + 1));
        let ranges = [(&zero, &t, &zero, &t2), (&zero, &t, &t2, &one), (&t, &one, &zero, &t2), (&t, &one, &t2, &one)];
        for (piece, (a, b, c, d)) in pieces.iter().zip(ranges) {
            prop_assert_eq!(piece.eval(&x, &y).unwrap(), s.eval(&mix(a, b, &x), &mix(c, d, &y)).unwrap());
        }
    }

    #[test]
    fn elevation_preserves_the_patch(
        s in patch(),
        du in 0usize..=3,
        dv in 0usize..=3,
        x in parameter(),
        y in parameter(),
    ) {
        let (m, n) = s.bidegree();
        let mut c = Counts::default();
        let e = s.elevate_to_with(m + du, n + dv, &mut c).unwrap();
        let (p, qq) = (w(m + du), w(n + dv));
        let want = if du > 0 { (w(n) + 1) * (w(m) + 1) * (p - w(m) + 1) } else { 0 }
            + if dv > 0 { (p + 1) * (w(n) + 1) * (qq - w(n) + 1) } else { 0 };
        prop_assert_eq!(c.arithmetic_operations, want);
        prop_assert_eq!(e.bidegree(), (m + du, n + dv));
        prop_assert_eq!(e.eval(&x, &y).unwrap(), s.eval(&x, &y).unwrap());
        prop_assert_eq!(s.elevate_u().unwrap().eval(&x, &y).unwrap(), s.eval(&x, &y).unwrap());
        prop_assert_eq!(s.elevate_v().unwrap().eval(&x, &y).unwrap(), s.eval(&x, &y).unwrap());
    }

    #[test]
    fn derivative_nets_are_partials_and_differences_of_blossoms(
        s in patch(),
        r in 0usize..=5,
        k in 0usize..=5,
        x in parameter(),
        y in parameter(),
    ) {
        let (m, n) = s.bidegree();
        let mut c = Counts::default();
        let net = s.derivative_net_with(r, k, &mut c).unwrap();
        prop_assert_eq!(net.eval(&x, &y).unwrap(), s.partial_at(&x, &y, r, k).unwrap());
        if r <= m && k <= n {
            prop_assert_eq!(net.bidegree(), (m - r, n - k));
            let (rr, kk) = (w(r), w(k));
            let want = (w(n) + 1) * (rr * (w(m) + 1) - rr * (rr + 1) / 2)
                + (w(m) - rr + 1) * (kk * (w(n) + 1) - kk * (kk + 1) / 2)
                + (w(m) - rr + 1) * (w(n) - kk + 1);
            prop_assert_eq!(c.arithmetic_operations, want);
        } else {
            prop_assert_eq!(net.bidegree(), (0, 0));
            prop_assert_eq!(net.net().get(0, 0), &Point::zero());
        }
        // First derivatives and the twist as differences of blossoms [PPB, §9.6].
        let (zero, one) = (qi(0), qi(1));
        let b = |iu: Option<&Q>, iv: Option<&Q>| {
            let mut us = vec![x.clone(); m];
            let mut vs = vec![y.clone(); n];
            if let Some(t) = iu { us[m - 1] = t.clone(); }
            if let Some(t) = iv { vs[n - 1] = t.clone(); }
            s.blossom(&us, &vs).unwrap()
        };
        if m > 0 {
            let du = (b(Some(&one), None) - &b(Some(&zero), None)) * qi(m as i64);
            prop_assert_eq!(s.derivative_net(1, 0).unwrap().eval(&x, &y).unwrap(), du);
        }
        if m > 0 && n > 0 {
            let twist = (b(Some(&one), Some(&one)) - &b(Some(&one), Some(&zero))
                - &b(Some(&zero), Some(&one)) + &b(Some(&zero), Some(&zero))) * qi((m * n) as i64);
            prop_assert_eq!(s.twist_net().unwrap().eval(&x, &y).unwrap(), twist);
        }
    }

    #[test]
    fn the_monomial_form_is_the_patch_and_converts_back(s in patch(), x in parameter(), y in parameter()) {
        let (m, n) = s.bidegree();
        let mut c = Counts::default();
        let a = s.to_monomial_with(&mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, (w(n) + 1) * (w(m) + 1) * (w(m) + 2) / 2 + (w(m) + 1) * (w(n) + 1) * (w(n) + 2) / 2);
        let mut sum = Point::zero();
        for k in 0..=m {
            for l in 0..=n {
                sum += &(a.get(k, l).clone() * &(x.pow(k as i32) * y.pow(l as i32)));
            }
        }
        prop_assert_eq!(sum, s.eval(&x, &y).unwrap());
        let mut c = Counts::default();
        prop_assert_eq!(BezierPatch::from_monomial_with(&a, &mut c).unwrap(), s);
        prop_assert_eq!(c.arithmetic_operations, (w(n) + 1) * (w(m) + 1) * (w(m) + 4) / 2 + (w(m) + 1) * (w(n) + 1) * (w(n) + 4) / 2);
    }

    #[test]
    fn the_bounding_box_holds_the_patch_over_the_unit_square(s in patch(), x in inside(), y in inside()) {
        let (m, n) = s.bidegree();
        let mut c = Counts::default();
        let (lo, hi) = s.bounding_box_with(&mut c);
        prop_assert_eq!(c.comparisons, 2 * 3 * ((w(m) + 1) * (w(n) + 1) - 1));
        for (u, v) in [(x.clone(), y.clone()), (qi(0), y.clone()), (x.clone(), qi(1))] {
            let p = s.eval(&u, &v).unwrap();
            for k in 0..3 {
                prop_assert!(lo[k] <= p[k] && p[k] <= hi[k]);
            }
        }
        // Tight: every bound is a coordinate of the net.
        for k in 0..3 {
            prop_assert!(s.net().points().iter().any(|p| p[k] == lo[k]));
            prop_assert!(s.net().points().iter().any(|p| p[k] == hi[k]));
        }
    }

    #[test]
    fn the_normal_is_c_u_cross_c_v_and_its_first_order_terms_at_a_collapsed_edge(
        s in patch(),
        x in parameter(),
        y in parameter(),
    ) {
        let (m, n) = s.bidegree();
        let cu = s.derivative_net(1, 0).unwrap().eval(&x, &y).unwrap();
        let cv = s.derivative_net(0, 1).unwrap().eval(&x, &y).unwrap();
        let product = cross(&cu, &cv);
        let mut c = Counts::default();
        let got = normal_with(&s, &x, &y, &mut c).unwrap();
        if product.coords().iter().all(Scalar::is_zero) {
            prop_assert!(!got.is_regular());
            prop_assert_eq!(c.arithmetic_operations, 5);
        } else {
            prop_assert_eq!(got, Normal::Regular(product));
            prop_assert_eq!(c.arithmetic_operations, 2);
        }
        // Collapse the first row to one point (a pole at u = 0): c_v vanishes along u = 0.
        if m >= 1 && n >= 1 {
            let mut rows = s.net().to_rows();
            let pole = rows[0][0].clone();
            rows[0] = vec![pole; n + 1];
            let cone = BezierPatch::new(ControlNet::new(rows).unwrap()).unwrap();
            let field = |u: &Q, v: &Q| cross(&cone.partial_at(u, v, 1, 0).unwrap(), &cone.partial_at(u, v, 0, 1).unwrap());
            let got = normal(&cone, &qi(0), &y).unwrap();
            // The normal field has degree ≤ 2m − 1 in u and ≤ 2n − 1 in v.
            let along_u = derivative_at_zero(2 * m, &q(1, 3), |h| field(h, &y));
            let along_v = derivative_at_zero(2 * n, &q(1, 3), |h| field(&qi(0), &(y.clone() + h)));
            prop_assert_eq!(along_v.clone(), Point::zero());
            prop_assert_eq!(got.clone(), Normal::Degenerate { along_u: along_u.clone(), along_v });
            prop_assert_eq!(got.towards(&qi(1), &qi(0)), (!along_u.coords().iter().all(Scalar::is_zero)).then_some(along_u));
        }
    }

    #[test]
    fn the_cr_construction_passes_the_cr_check_and_a_perturbation_fails_it(
        s in patch(),
        r in 0usize..=4,
        (u0, u1) in interval(),
        width in 1i64..=12,
        other in patch(),
    ) {
        let (m, n) = s.bidegree();
        let knots = [u0, u1.clone(), u1 + q(width, 6)];
        let zero = qi(0);
        // Along u: free rows from the other random patch, cut or padded to shape.
        let point = |i: usize, j: usize| other.net().get(i % other.net().rows(), j % other.net().columns()).clone();
        if r > m {
            let refused = matches!(s.extend_cr_u(r, &knots, &[]), Err(Error::InvalidParameter { name: "r", .. }));
            prop_assert!(refused);
        } else {
            let free: Vec<Vec<Point<Q, 3>>> = (r + 1..=m).map(|i| (0..=n).map(|j| point(i, j)).collect()).collect();
            let mut c = Counts::default();
            let next = s.extend_cr_u_with(r, &knots, &free, &mut c).unwrap();
            prop_assert_eq!(c.arithmetic_operations, (w(n) + 1) * w(m) * (w(m) + 1));
            let mut c = Counts::default();
            let join = s.join_u_with(&next, &knots, &zero, &mut c).unwrap();
            prop_assert_eq!(c.arithmetic_operations, (w(n) + 1) * (w(m) * (w(m) + 1) + 2 * w(m) + 2));
            prop_assert!(join >= Some(r), "{:?} < C^{}", join, r);
            // Moving one point of row r breaks exactly the order r.
            let mut rows = next.net().to_rows();
            rows[r][0] = rows[r][0].clone() + &Point::new([qi(1), qi(0), qi(0)]);
            let moved = BezierPatch::new(ControlNet::new(rows).unwrap()).unwrap();
            prop_assert_eq!(s.join_u(&moved, &knots, &zero).unwrap(), r.checked_sub(1));
            // The columns joined are C^r composite curves: the derivatives in u agree on the
            // whole edge, at any v.
            for k in 0..=r {
                let left = s.partial_at(&qi(1), &q(1, 3), k, 0).unwrap() * &(qi(1) / (knots[1].clone() - &knots[0]).pow(k as i32));
                let right = next.partial_at(&qi(0), &q(1, 3), k, 0).unwrap() * &(qi(1) / (knots[2].clone() - &knots[1]).pow(k as i32));
                prop_assert_eq!(left, right);
            }
        }
        // Along v, the same on columns.
        if r <= n {
            let free: Vec<Vec<Point<Q, 3>>> = (r + 1..=n).map(|j| (0..=m).map(|i| point(i, j)).collect()).collect();
            let next = s.extend_cr_v(r, &knots, &free).unwrap();
            prop_assert!(s.join_v(&next, &knots, &zero).unwrap() >= Some(r));
            let mut rows = next.net().to_rows();
            rows[0][r] = rows[0][r].clone() + &Point::new([qi(0), qi(1), qi(0)]);
            let moved = BezierPatch::new(ControlNet::new(rows).unwrap()).unwrap();
            prop_assert_eq!(s.join_v(&moved, &knots, &zero).unwrap(), r.checked_sub(1));
        }
    }
}

#[test]
fn bad_input_to_the_operations_is_a_named_error() {
    let p = |x: f64, y: f64| Point::new([x, y]);
    let s = BezierPatch::new(
        ControlNet::new(vec![
            vec![p(0.0, 0.0), p(0.0, 1.0), p(0.0, 2.0)],
            vec![p(1.0, 0.0), p(1.0, 1.0), p(1.0, 2.0)],
        ])
        .unwrap(),
    )
    .unwrap(); // bidegree (1, 2)
    let named =
        |e: Error, name: &str| matches!(e, Error::InvalidParameter { name: n, .. } if n == name);
    // The blossom: argument counts and values.
    assert!(named(
        s.blossom(&[0.5, 0.5], &[0.5, 0.5]).unwrap_err(),
        "blossom arguments"
    ));
    assert!(named(
        s.blossom(&[0.5], &[0.5]).unwrap_err(),
        "blossom arguments"
    ));
    assert!(named(
        s.blossom(&[f64::NAN], &[0.5, 0.5]).unwrap_err(),
        "blossom argument"
    ));
    // Restriction: NaN, infinite, empty or reversed intervals.
    assert!(named(
        s.restrict(&f64::NAN, &1.0, &0.0, &1.0).unwrap_err(),
        "a"
    ));
    assert!(named(
        s.restrict(&0.0, &f64::INFINITY, &0.0, &1.0).unwrap_err(),
        "b"
    ));
    assert!(named(
        s.restrict(&0.0, &1.0, &0.0, &f64::NAN).unwrap_err(),
        "d"
    ));
    assert!(named(
        s.restrict(&1.0, &0.5, &0.0, &1.0).unwrap_err(),
        "u interval"
    ));
    assert!(named(
        s.restrict(&0.0, &1.0, &0.5, &0.5).unwrap_err(),
        "v interval"
    ));
    let e = s.restrict(&1.0, &0.5, &0.0, &1.0).unwrap_err().to_string();
    assert!(e.contains("a < b"), "{e}");
    // Subdivision: strictly inside (0, 1).
    for t in [0.0, 1.0, -0.5, 1.5, f64::NAN, f64::INFINITY] {
        assert!(named(s.split_u(&t).unwrap_err(), "u"));
        assert!(named(s.split_v(&t).unwrap_err(), "v"));
        assert!(named(s.split(&0.5, &t).unwrap_err(), "v"));
    }
    // Elevation: no reduction, no absurd degrees.
    assert!(named(s.elevate_to(0, 2).unwrap_err(), "degree"));
    assert!(named(s.elevate_to(1, 1).unwrap_err(), "degree"));
    assert!(matches!(
        s.elevate_to(1 << 40, 2),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        s.elevate_to(1 << 14, 1 << 14),
        Err(Error::LimitExceeded { .. })
    ));
    // Joins: knots, tolerance, r beyond the degree, free rows of the wrong shape.
    let knots = [0.0, 1.0, 2.0];
    assert!(named(
        s.join_u(&s, &[0.0, 1.0, 1.0], &0.0).unwrap_err(),
        "knots"
    ));
    assert!(named(
        s.join_u(&s, &[0.0, f64::NAN, 2.0], &0.0).unwrap_err(),
        "knots"
    ));
    assert!(named(s.join_u(&s, &knots, &-1.0).unwrap_err(), "tolerance"));
    assert!(named(
        s.join_u(&s, &knots, &f64::NAN).unwrap_err(),
        "tolerance"
    ));
    let t = BezierPatch::new(s.net().transposed()).unwrap(); // bidegree (2, 1)
    assert!(named(s.join_u(&t, &knots, &0.0).unwrap_err(), "next"));
    assert!(named(s.join_v(&t, &knots, &0.0).unwrap_err(), "next"));
    assert!(named(s.extend_cr_u(2, &knots, &[]).unwrap_err(), "r"));
    assert!(named(s.extend_cr_v(3, &knots, &[]).unwrap_err(), "r"));
    assert!(named(
        s.extend_cr_u(0, &[1.0, 0.0, 2.0], &[vec![p(0.0, 0.0); 3]])
            .unwrap_err(),
        "knots"
    ));
    assert!(named(s.extend_cr_u(0, &knots, &[]).unwrap_err(), "free"));
    assert!(named(
        s.extend_cr_u(0, &knots, &[vec![p(0.0, 0.0); 2]])
            .unwrap_err(),
        "free"
    ));
    assert!(s
        .extend_cr_u(0, &knots, &[vec![p(0.0, f64::NAN); 3]])
        .is_err());
    // Normals: the parameters of the surface.
    let p3 = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
    let s3 = BezierPatch::new(
        ControlNet::new(vec![
            vec![p3(0.0, 0.0, 0.0), p3(0.0, 1.0, 0.0)],
            vec![p3(1.0, 0.0, 0.0), p3(1.0, 1.0, 1.0)],
        ])
        .unwrap(),
    )
    .unwrap();
    assert!(named(normal(&s3, &f64::NAN, &0.5).unwrap_err(), "u"));
    assert!(named(normal(&s3, &0.5, &f64::INFINITY).unwrap_err(), "v"));
    // With f64, a restriction far outside the unit square overflows into a named error.
    let big = BezierPatch::new(
        ControlNet::new(vec![
            vec![p(0.0, 0.0), p(1e300, 0.0)],
            vec![p(0.0, 1e300), p(1e300, 1e300)],
        ])
        .unwrap(),
    )
    .unwrap();
    assert!(matches!(
        big.restrict(&0.0, &1e300, &0.0, &1.0),
        Err(Error::Overflow { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn f64_operations_agree_with_exact_and_the_rounded_join_check_takes_a_tolerance(
        s in patch(),
        (a, b) in interval(),
        r in 0usize..=4,
    ) {
        let (m, n) = s.bidegree();
        let sf = BezierPatch::new(s.net().to_f64()).unwrap();
        let (af, bf) = (a.to_f64(), b.to_f64());
        // Coordinates up to 20 and intervals within [−1, 2]: errors far below 1e-9.
        let close = |x: &BezierPatch<f64, 3>, y: &BezierPatch<Q, 3>| {
            x.net().points().iter().zip(y.net().points()).all(|(p, q)| {
                let q = q.to_f64();
                (0..3).all(|k| (p[k] - q[k]).abs() <= 1e-9 * (1.0 + q[k].abs()))
            })
        };
        prop_assert!(close(&sf.restrict(&af, &bf, &af, &bf).unwrap(), &s.restrict(&a, &b, &a, &b).unwrap()));
        prop_assert!(close(&sf.elevate_to(m + 2, n + 1).unwrap(), &s.elevate_to(m + 2, n + 1).unwrap()));
        prop_assert!(close(&sf.twist_net().unwrap(), &s.twist_net().unwrap()));
        if r <= m {
            let knots = [0.0, 1.0, 2.5];
            let free = sf.net().to_rows()[r + 1..].to_vec();
            let next = sf.extend_cr_u(r, &knots, &free).unwrap();
            prop_assert!(sf.join_u(&next, &knots, &1e-9).unwrap() >= Some(r));
        }
    }
}
