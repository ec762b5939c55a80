//! B-spline and NURBS surfaces, checked exactly on the rational back end: evaluation against
//! the double sum of basis products (an oracle from the basis alone) and against the
//! isoparametric curves; knot insertion and refinement in u and v, degree elevation in u and
//! v and the conversion to Bézier patches leave the surface identical; partial derivatives
//! equal the Bézier patches' after conversion (the polynomial pieces) and the isoparametric
//! curves' derivatives; NURBS with all weights 1 is the B-spline surface, and its point is the
//! quotient of the weighted double sums; bad input gives named errors.

use crate::spline_common::{q, qi, Q};
use compgeo::spline::{Curve, CurveDerivative, KnotVector, Point, Scalar};
use compgeo::surface::{
    BSplineSurface, ControlNet, Direction, NurbsSurface, Surface, SurfaceDerivative,
};
use compgeo::Error;
use proptest::prelude::*;

/// A knot vector of degree 1..=3 for `count` control points on [0, 6]: clamped with interior
/// knots from the distinct sorted values `interior` of {1, …, 5}, the first one doubled when
/// `repeat` and the degree allows it; or uniform (unclamped) on [0, count].
fn knots(
    degree: usize,
    count: usize,
    interior: &[i64],
    clamped: bool,
    repeat: bool,
) -> KnotVector<Q> {
    if !clamped {
        return KnotVector::uniform(degree, count, qi(0), qi(count as i64)).unwrap();
    }
    let mut inner: Vec<i64> = interior.to_vec();
    if repeat && degree >= 2 {
        inner.insert(0, inner[0]);
    }
    inner.truncate(count - degree - 1);
    let mut t = vec![qi(0); degree + 1];
    t.extend(inner.into_iter().map(qi));
    t.extend(vec![qi(6); degree + 1]);
    KnotVector::new(degree, t).unwrap()
}

/// A B-spline surface of bidegree (1..=3, 1..=3) with up to three interior knots per
/// direction and integer points in R³.
fn surface() -> impl Strategy<Value = BSplineSurface<Q, 3>> {
    (
        1usize..=3,
        1usize..=3,
        0usize..=3,
        0usize..=3,
        any::<[bool; 4]>(),
    )
        .prop_flat_map(|(p, qd, eu, ev, flags)| {
            let (m, n) = (p + 1 + eu, qd + 1 + ev);
            (
                Just((p, qd, m, n, flags)),
                prop::sample::subsequence(vec![1i64, 2, 3, 4, 5], 3),
                prop::sample::subsequence(vec![1i64, 2, 3, 4, 5], 3),
                prop::collection::vec((-9i64..=9, -9i64..=9, -9i64..=9), m * n),
            )
        })
        .prop_map(|((p, qd, m, n, [cu, cv, ru, rv]), iu, iv, pts)| {
            let points = pts
                .into_iter()
                .map(|(x, y, z)| Point::new([qi(x), qi(y), qi(z)]))
                .collect();
            let net = ControlNet::from_rows(m, n, points).unwrap();
            BSplineSurface::new(net, knots(p, m, &iu, cu, ru), knots(qd, n, &iv, cv, rv)).unwrap()
        })
}

/// Every knot of the domain and a few rationals across it.
fn samples(t: &KnotVector<Q>) -> Vec<Q> {
    let (a, b) = (t.bounds().0.clone(), t.bounds().1.clone());
    let mut out: Vec<Q> = (0..=3)
        .map(|k| a.clone() + (b.clone() - &a) * q(k, 3))
        .collect();
    out.push(a.clone() + (b.clone() - &a) * q(5, 17));
    out.extend(t.knots().iter().filter(|k| **k >= a && **k <= b).cloned());
    out
}

/// Σᵢ Σⱼ c_{i,j}·Nᵢ(u)·Nⱼ(v) from the basis values alone.
fn double_sum(s: &BSplineSurface<Q, 3>, u: &Q, v: &Q) -> Point<Q, 3> {
    let bu = s.u_knots().basis(u).unwrap();
    let bv = s.v_knots().basis(v).unwrap();
    let mut sum = Point::zero();
    for i in 0..s.net().rows() {
        for j in 0..s.net().columns() {
            let w = bu.get(i) * &bv.get(j);
            sum += &(s.net().get(i, j).clone() * &w);
        }
    }
    sum
}

/// The surfaces agree at every sample pair of the first one's domain.
fn same_surface<A: Surface<Q, 3>, B: Surface<Q, 3>>(
    a: &A,
    b: &B,
    us: &[Q],
    vs: &[Q],
) -> Result<(), TestCaseError> {
    for u in us {
        for v in vs {
            prop_assert_eq!(
                a.eval(u, v).unwrap(),
                b.eval(u, v).unwrap(),
                "at ({}, {})",
                u,
                v
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn eval_is_the_double_sum_and_the_isoparametric_curves(s in surface()) {
        for u in samples(s.u_knots()) {
            let across = s.isocurve(Direction::U, &u).unwrap();
            for v in samples(s.v_knots()) {
                let want = double_sum(&s, &u, &v);
                prop_assert_eq!(s.eval(&u, &v).unwrap(), want.clone());
                prop_assert_eq!(across.eval(&v).unwrap(), want.clone());
                prop_assert_eq!(s.isocurve(Direction::V, &v).unwrap().eval(&u).unwrap(), want);
            }
        }
    }

    #[test]
    fn insertion_and_refinement_keep_the_surface(s in surface(), a in 0i64..=12, b in 0i64..=12, r in 1usize..=2) {
        let (us, vs) = (samples(s.u_knots()), samples(s.v_knots()));
        let within = |t: &KnotVector<Q>, k: i64| {
            let (lo, hi) = t.bounds();
            lo.clone() + (hi.clone() - lo) * q(k, 12)
        };
        let tu = within(s.u_knots(), a);
        let tv = within(s.v_knots(), b);
        let (p, qd) = s.bidegree();
        if s.u_knots().multiplicity(&tu) + r <= p {
            let i = s.insert(Direction::U, &tu, r).unwrap();
            prop_assert_eq!(i.net().rows(), s.net().rows() + r);
            prop_assert_eq!(i.u_knots().multiplicity(&tu), s.u_knots().multiplicity(&tu) + r);
            same_surface(&s, &i, &us, &vs)?;
        }
        if s.v_knots().multiplicity(&tv) + r <= qd {
            let i = s.insert(Direction::V, &tv, r).unwrap();
            prop_assert_eq!(i.net().columns(), s.net().columns() + r);
            same_surface(&s, &i, &us, &vs)?;
        }
        let new: Vec<Q> = [1, 5, 7].iter().map(|k| within(s.v_knots(), *k)).collect();
        let refined = s.refine(Direction::V, &new).unwrap();
        prop_assert_eq!(refined.net().columns(), s.net().columns() + 3);
        same_surface(&s, &refined, &us, &vs)?;
        let mid = within(s.u_knots(), 6);
        if s.u_knots().multiplicity(&mid) + 2 <= p {
            let refined = s.refine(Direction::U, &[mid.clone(), mid]).unwrap();
            prop_assert_eq!(refined.net().rows(), s.net().rows() + 2);
            same_surface(&s, &refined, &us, &vs)?;
        }
    }

    #[test]
    fn bezier_conversion_reproduces_the_surface_and_its_derivatives(s in surface()) {
        let g = s.to_bezier().unwrap();
        let (p, qd) = s.bidegree();
        prop_assert!(g.patches().iter().flatten().all(|b| b.bidegree() == (p, qd)));
        let (us, vs) = (samples(s.u_knots()), samples(s.v_knots()));
        same_surface(&s, &g, &us, &vs)?;
        for u in &us {
            for v in &vs {
                for (r, k) in [(1, 0), (0, 1), (1, 1), (2, 1), (0, 3), (4, 0)] {
                    prop_assert_eq!(
                        s.partial_at(u, v, r, k).unwrap(),
                        g.partial_at(u, v, r, k).unwrap(),
                        "∂({}, {}) at ({}, {})", r, k, u, v
                    );
                }
                // The isoparametric curves' derivatives are the pure partials.
                prop_assert_eq!(
                    s.partial_at(u, v, 1, 0).unwrap(),
                    s.isocurve(Direction::V, v).unwrap().derivative_at(u, 1).unwrap()
                );
                prop_assert_eq!(
                    s.partial_at(u, v, 0, 2).unwrap(),
                    s.isocurve(Direction::U, u).unwrap().derivative_at(v, 2).unwrap()
                );
            }
        }
    }

    #[test]
    fn elevation_keeps_the_surface(s in surface(), t in 1usize..=2) {
        let (us, vs) = (samples(s.u_knots()), samples(s.v_knots()));
        let (p, qd) = s.bidegree();
        let eu = s.elevate(Direction::U, t).unwrap();
        prop_assert_eq!(eu.bidegree(), (p + t, qd));
        same_surface(&s, &eu, &us, &vs)?;
        let ev = s.elevate(Direction::V, t).unwrap();
        prop_assert_eq!(ev.bidegree(), (p, qd + t));
        same_surface(&s, &ev, &us, &vs)?;
    }

    #[test]
    fn nurbs_with_unit_weights_is_the_bspline_surface(s in surface()) {
        let count = s.net().points().len();
        let n = NurbsSurface::new(s.net().clone(), vec![qi(1); count], s.u_knots().clone(), s.v_knots().clone()).unwrap();
        for u in samples(s.u_knots()) {
            for v in samples(s.v_knots()) {
                prop_assert_eq!(n.eval(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
                for (r, k) in [(1, 0), (0, 1), (1, 1), (2, 2)] {
                    prop_assert_eq!(n.partial_at(&u, &v, r, k).unwrap(), s.partial_at(&u, &v, r, k).unwrap());
                }
            }
        }
    }

    #[test]
    fn grid_evaluation_is_the_double_sum_and_eval_at_every_pair(s in surface(), ws in prop::collection::vec(1i64..=6, 49)) {
        // The parameters out of order and repeated: the grid does not care.
        let mut us = samples(s.u_knots());
        us.reverse();
        let vs = samples(s.v_knots());
        let grid = s.eval_grid(&us, &vs).unwrap();
        prop_assert_eq!(grid.len(), us.len() * vs.len());
        let count = s.net().points().len();
        let weights: Vec<Q> = ws[..count].iter().map(|w| q(*w, 3)).collect();
        let n = NurbsSurface::new(s.net().clone(), weights, s.u_knots().clone(), s.v_knots().clone()).unwrap();
        let rational = n.eval_grid(&us, &vs).unwrap();
        for (i, u) in us.iter().enumerate() {
            for (j, v) in vs.iter().enumerate() {
                prop_assert_eq!(&grid[i * vs.len() + j], &double_sum(&s, u, v));
                prop_assert_eq!(&rational[i * vs.len() + j], &n.eval(u, v).unwrap());
            }
        }
        // The points and first partials on the grid (what tessellation uses) are eval's and
        // partial_at's, for both surfaces.
        let partials = s.first_partials_on_grid(&us, &vs).unwrap();
        let rational_partials = n.first_partials_on_grid(&us, &vs).unwrap();
        for (i, u) in us.iter().enumerate() {
            for (j, v) in vs.iter().enumerate() {
                let k = i * vs.len() + j;
                prop_assert_eq!(&partials[k][0], &s.eval(u, v).unwrap());
                prop_assert_eq!(&partials[k][1], &s.partial_at(u, v, 1, 0).unwrap());
                prop_assert_eq!(&partials[k][2], &s.partial_at(u, v, 0, 1).unwrap());
                prop_assert_eq!(&rational_partials[k][0], &n.eval(u, v).unwrap());
                prop_assert_eq!(&rational_partials[k][1], &n.partial_at(u, v, 1, 0).unwrap());
                prop_assert_eq!(&rational_partials[k][2], &n.partial_at(u, v, 0, 1).unwrap());
            }
        }
        let outside = s.v_knots().bounds().1.clone() + qi(1);
        prop_assert!(s.eval_grid(&us, std::slice::from_ref(&outside)).is_err());
        prop_assert!(n.first_partials_on_grid(&us, &[outside]).is_err());
    }

    #[test]
    fn nurbs_is_the_homogeneous_projection(s in surface(), ws in prop::collection::vec(1i64..=6, 49), t in 1usize..=1) {
        let count = s.net().points().len();
        let weights: Vec<Q> = ws[..count].iter().map(|w| q(*w, 2)).collect();
        let n = NurbsSurface::new(s.net().clone(), weights.clone(), s.u_knots().clone(), s.v_knots().clone()).unwrap();
        let columns = s.net().columns();
        let (us, vs) = (samples(s.u_knots()), samples(s.v_knots()));
        let inserted = n.insert(Direction::V, &(s.v_knots().bounds().0.clone() + q(1, 3)), 1);
        let elevated = n.elevate(Direction::U, t).unwrap();
        for u in &us {
            let iso_u = n.isocurve(Direction::U, u).unwrap();
            for v in &vs {
                let bu = s.u_knots().basis(u).unwrap();
                let bv = s.v_knots().basis(v).unwrap();
                let (mut a, mut w) = (Point::<Q, 3>::zero(), qi(0));
                for (k, c) in s.net().points().iter().enumerate() {
                    let b = bu.get(k / columns) * &bv.get(k % columns) * &weights[k];
                    a += &(c.clone() * &b);
                    w += &b;
                }
                let want = a / &w;
                prop_assert_eq!(n.eval(u, v).unwrap(), want.clone());
                prop_assert_eq!(iso_u.eval(v).unwrap(), want.clone());
                prop_assert_eq!(elevated.eval(u, v).unwrap(), want.clone());
                if let Ok(i) = &inserted {
                    prop_assert_eq!(i.eval(u, v).unwrap(), want.clone());
                }
                // Pure partials against the NURBS curves' quotient rule.
                let iso_v = n.isocurve(Direction::V, v).unwrap();
                prop_assert_eq!(n.partial_at(u, v, 1, 0).unwrap(), iso_v.derivative_at(u, 1).unwrap());
                prop_assert_eq!(n.partial_at(u, v, 2, 0).unwrap(), iso_v.derivative_at(u, 2).unwrap());
                prop_assert_eq!(n.partial_at(u, v, 0, 1).unwrap(), iso_u.derivative_at(v, 1).unwrap());
            }
        }
    }
}

/// The twist of a NURBS surface against the product rule of its homogeneous form: from
/// a = w·s, a_uv = w_uv·s + w_u·s_v + w_v·s_u + w·s_uv (the quotient rule run backwards).
#[test]
fn nurbs_twist_satisfies_the_product_rule() {
    let p = |x: i64, y: i64, z: i64| Point::new([qi(x), qi(y), qi(z)]);
    let net = ControlNet::new(vec![
        vec![p(0, 0, 1), p(0, 1, 2), p(0, 2, 0)],
        vec![p(1, 0, 3), p(1, 1, -1), p(1, 2, 2)],
        vec![p(2, 0, 0), p(2, 1, 4), p(2, 2, 1)],
    ])
    .unwrap();
    let weights = [1, 2, 1, 3, 1, 2, 1, 1, 4].map(qi).to_vec();
    let t = KnotVector::clamped_uniform(2, 3, qi(0), qi(1)).unwrap();
    let s = NurbsSurface::new(net, weights, t.clone(), t).unwrap();
    let (a, w) = s.homogeneous();
    for (u, v) in [(q(1, 3), q(1, 2)), (q(0, 1), q(1, 1)), (q(3, 4), q(1, 5))] {
        let d = |r, k| s.partial_at(&u, &v, r, k).unwrap();
        let wd = |r, k| w.partial_at(&u, &v, r, k).unwrap()[0].clone();
        let lhs = a.partial_at(&u, &v, 1, 1).unwrap();
        let rhs = d(0, 0) * &wd(1, 1)
            + &(d(0, 1) * &wd(1, 0))
            + &(d(1, 0) * &wd(0, 1))
            + &(d(1, 1) * &wd(0, 0));
        assert_eq!(lhs, rhs, "at ({u}, {v})");
    }
}

#[test]
fn f64_surface_is_near_the_exact_one() {
    let net = ControlNet::new(
        (0..4)
            .map(|i| {
                (0..3)
                    .map(|j| Point::new([i as f64, j as f64, ((i * 7 + j * 3) % 5) as f64]))
                    .collect()
            })
            .collect(),
    )
    .unwrap();
    let tu = KnotVector::new(2, vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0]).unwrap();
    let tv = KnotVector::clamped_uniform(2, 3, 0.0, 1.0).unwrap();
    let s = BSplineSurface::new(net, tu, tv).unwrap();
    let exact = {
        let conv = |t: &KnotVector<f64>| {
            KnotVector::new(
                t.degree(),
                t.knots()
                    .iter()
                    .map(|k| <Q as Scalar>::from_f64(*k).unwrap())
                    .collect(),
            )
            .unwrap()
        };
        let pts = s
            .net()
            .points()
            .iter()
            .map(|p| Point::from_f64(p).unwrap())
            .collect();
        BSplineSurface::new(
            ControlNet::from_rows(4, 3, pts).unwrap(),
            conv(s.u_knots()),
            conv(s.v_knots()),
        )
        .unwrap()
    };
    for k in 0..=10 {
        let (u, v) = (k as f64 / 10.0, (10 - k) as f64 / 10.0);
        let got = s.eval(&u, &v).unwrap();
        let want = exact
            .eval(
                &<Q as Scalar>::from_f64(u).unwrap(),
                &<Q as Scalar>::from_f64(v).unwrap(),
            )
            .unwrap()
            .to_f64();
        for c in 0..3 {
            assert!((got[c] - want[c]).abs() < 1e-12, "{got:?} vs {want:?}");
        }
    }
    assert_eq!(exact.to_f64().unwrap(), s);
}

fn invalid_name(e: Error) -> &'static str {
    match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("not an invalid parameter: {other:?}"),
    }
}

#[test]
fn bad_input_gives_named_errors() {
    let p = |x: f64, y: f64| Point::new([x, y]);
    // Ragged nets.
    assert!(matches!(
        ControlNet::new(vec![vec![p(0.0, 0.0), p(1.0, 0.0)], vec![p(0.0, 1.0)]]),
        Err(Error::InvalidParameter { name: "net", .. })
    ));
    let net = ControlNet::new(vec![
        vec![p(0.0, 0.0), p(0.0, 1.0)],
        vec![p(1.0, 0.0), p(1.0, 1.0)],
    ])
    .unwrap();
    let t1 = KnotVector::clamped_uniform(1, 2, 0.0, 1.0).unwrap();
    let t3 = KnotVector::clamped_uniform(1, 3, 0.0, 1.0).unwrap();
    // Knot counts that do not match the net.
    assert_eq!(
        invalid_name(BSplineSurface::new(net.clone(), t3.clone(), t1.clone()).unwrap_err()),
        "u knots"
    );
    assert_eq!(
        invalid_name(BSplineSurface::new(net.clone(), t1.clone(), t3.clone()).unwrap_err()),
        "v knots"
    );
    let s = BSplineSurface::new(net.clone(), t1.clone(), t1.clone()).unwrap();
    // Parameters outside the domain, NaN, infinite.
    assert_eq!(invalid_name(s.eval(&1.5, &0.5).unwrap_err()), "u");
    assert_eq!(invalid_name(s.eval(&0.5, &-0.1).unwrap_err()), "v");
    assert_eq!(invalid_name(s.eval(&f64::NAN, &0.5).unwrap_err()), "u");
    assert_eq!(
        invalid_name(s.partial_at(&0.5, &f64::INFINITY, 1, 0).unwrap_err()),
        "v"
    );
    assert_eq!(
        invalid_name(s.isocurve(Direction::U, &2.0).unwrap_err()),
        "u"
    );
    assert_eq!(
        invalid_name(s.insert(Direction::V, &f64::NAN, 1).unwrap_err()),
        "v"
    );
    assert_eq!(
        invalid_name(s.insert(Direction::U, &0.5, 5).unwrap_err()),
        "u"
    );
    // Weights: zero, negative, NaN, infinite, too few.
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        let e = NurbsSurface::new(
            net.clone(),
            vec![1.0, bad, 1.0, 1.0],
            t1.clone(),
            t1.clone(),
        )
        .unwrap_err();
        assert_eq!(invalid_name(e), "weights");
    }
    let e = NurbsSurface::new(net.clone(), vec![1.0; 3], t1.clone(), t1.clone()).unwrap_err();
    assert_eq!(invalid_name(e), "weights");
    let e = NurbsSurface::new(net, vec![1.0; 4], t3, t1).unwrap_err();
    assert_eq!(invalid_name(e), "u knots");
}
