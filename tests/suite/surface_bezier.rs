//! Tensor-product Bézier patches, checked exactly on the rational back end: the three
//! evaluations (rows first, columns first, the tensor de Casteljau algorithm) and the trait's
//! `eval` against the double sum Σ c_{i,j} Bᵢᵐ(u) Bⱼⁿ(v) of the Bernstein polynomials (an
//! independent oracle), also outside [0, 1]²; the isoparametric curves against the surface;
//! the partial derivatives against the double sum of Bernstein derivatives; the exact counts;
//! the worked example of [FJ-surfaces, §2] (a net of bidegree (2, 3) and its monomial form,
//! from `tests/fixtures/fj_surfaces_bidegree_2_3.txt`) and its graph of f(x, y) = xy; `f64`
//! against exact; bad nets and parameters as named errors.

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{bernstein, bernstein_derivative, Curve, Point, Scalar};
use compgeo::surface::{BezierPatch, ControlNet, Surface, SurfaceDerivative};
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
