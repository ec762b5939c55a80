//! Interpolation and composite curves against exact oracles: the course's worked Hermite example
//! digit for digit, interpolants that reproduce their data and derivatives with rationals,
//! the end conditions of the cubic spline, agreement of the Lagrange, Aitken, Newton and
//! Vandermonde forms, Cʳ joins, C¹ quadratic splines, least-squares fits (exact recovery,
//! orthogonal residuals), and the library's bad-input contract. The Frenet frame is in
//! `tests/frenet.rs`, the `compgeo interpolate` command in `tests/interpolate_cli.rs`.
#![cfg(feature = "exact")]

use crate::spline_common::{p2, pairs, q, qi, Q};
use compgeo::spline::{
    bernstein_all, c1_partition, closed_quadratic_spline, cubic_spline, cubic_spline_tangents,
    estimate_tangents, fit_bezier, hermite, lagrange, lagrange_basis, newton, newton_hermite,
    parameterise, quadratic_spline, vandermonde, vandermonde_hermite, Bezier, CompositeBezier,
    Curve, CurveDerivative, EndCondition, FitOptions, HermiteNode, Parameterisation, Point,
    Polynomial, Scalar,
};
use compgeo::Error;
use proptest::prelude::*;

/// Reads `{ 0, \frac{1}{2}, ... }` into rationals.
fn partition(line: &str) -> Vec<Q> {
    let inner = &line[line.find("\\{").unwrap() + 2..line.find("\\right").unwrap()];
    inner
        .split(", ")
        .map(|s| {
            let s = s.trim();
            if let Some(frac) = s.strip_prefix("\\frac{") {
                let (n, d) = frac.trim_end_matches('}').split_once("}{").unwrap();
                q(n.parse().unwrap(), d.parse().unwrap())
            } else {
                qi(s.parse().unwrap())
            }
        })
        .collect()
}

#[test]
fn seed_003_hermite_example_reproduces_the_printed_control_points() {
    let text = include_str!("../fixtures/seed003_hermite_example.txt");
    let line = |prefix: &str| text.lines().find(|l| l.starts_with(prefix)).unwrap();
    let points = pairs(line("$$Q_0"));
    let tangents = pairs(line("$$D_0"));
    let knots = partition(line("$$\\left\\{"));
    assert_eq!((points.len(), tangents.len(), knots.len()), (5, 5, 5));
    let printed: Vec<Vec<Point<Q, 2>>> = text
        .lines()
        .filter(|l| l.starts_with("Tramo"))
        .map(|l| pairs(l.split_once(':').unwrap().1))
        .collect();
    assert_eq!(printed.len(), 4);

    let curve = hermite(&knots, &points, &tangents).unwrap();
    let got: Vec<&[Point<Q, 2>]> = curve.pieces().iter().map(|b| b.control()).collect();
    assert_eq!(got, printed.iter().map(Vec::as_slice).collect::<Vec<_>>());
    // It interpolates the data exactly and is C¹ exactly.
    for i in 0..5 {
        assert_eq!(curve.eval(&knots[i]).unwrap(), points[i]);
        assert_eq!(curve.derivative_at(&knots[i], 1).unwrap(), tangents[i]);
    }
    assert!(curve.is_c(1, &qi(0)));
    assert!(!curve.is_c(2, &qi(0)));

    // The f64 path agrees to rounding.
    let f = |p: &Point<Q, 2>| p.to_f64();
    let curve64 = hermite(
        &knots.iter().map(Scalar::to_f64).collect::<Vec<_>>(),
        &points.iter().map(f).collect::<Vec<_>>(),
        &tangents.iter().map(f).collect::<Vec<_>>(),
    )
    .unwrap();
    for (a, b) in curve64
        .pieces()
        .iter()
        .flat_map(|b| b.control())
        .zip(printed.iter().flatten())
    {
        let b = b.to_f64();
        assert!((a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
    }
}

#[test]
fn seed_003_c1_exercise_gets_its_partition_exactly() {
    let p = |x: i64, y: i64| p2(qi(x), qi(y));
    let pieces = vec![
        vec![p(0, 0), p(-1, 1), p(1, 3)],
        vec![p(1, 3), p(2, 4), p(5, 1)],
        vec![p(5, 1), p(6, 0), p(7, 5)],
    ];
    let u = c1_partition(&pieces, qi(0), qi(1), &qi(0)).unwrap();
    assert_eq!(u, vec![qi(0), qi(1), q(3, 2), q(5, 3)]);
    let curve = CompositeBezier::new(u, pieces.clone()).unwrap();
    assert!(curve.is_c(1, &qi(0)) && curve.is_g1(&qi(0)));
    // A uniform partition keeps G¹ but loses C¹.
    let uniform = CompositeBezier::new(vec![qi(0), qi(1), qi(2), qi(3)], pieces).unwrap();
    assert!(uniform.is_g1(&qi(0)) && !uniform.is_c(1, &qi(0)));
    assert_eq!(uniform.join(1, &qi(0)).unwrap().parametric, Some(0));
}

#[test]
fn cr_builder_matches_the_seeds_q2_formula() {
    // [RD, §3.2]: Q_2 = λ² (P_n − 2P_{n−1} + P_{n−2}) + 2λ (P_n − P_{n−1}) + P_n.
    let p = |x: i64, y: i64| p2(qi(x), qi(y));
    let first = vec![p(0, 0), p(1, 3), p(4, 2), p(5, 5)];
    let mut curve = CompositeBezier::new(vec![qi(0), qi(2)], vec![first.clone()]).unwrap();
    curve.push_cr(2, qi(5), &[p(9, 9)]).unwrap();
    let lambda = q(3, 2);
    let second_diff = first[3].clone() - &(first[2].clone() * qi(2)) + &first[1];
    let q2 = second_diff * &(lambda.clone() * &lambda)
        + &((first[3].clone() - &first[2]) * &(lambda * qi(2)))
        + &first[3];
    assert_eq!(curve.pieces()[1].control()[2], q2);
    assert!(curve.is_c(2, &qi(0)));
    assert_eq!(curve.join(1, &qi(0)).unwrap().parametric, Some(2));
}

#[test]
fn natural_spline_has_zero_second_derivative_at_both_ends() {
    let knots = vec![qi(0), q(1, 3), qi(1), q(5, 2), qi(4)];
    let pts: Vec<_> = [(0, 0), (1, 2), (3, 1), (4, 4), (6, -1)]
        .iter()
        .map(|&(x, y)| p2(qi(x), qi(y)))
        .collect();
    let s = cubic_spline(&knots, &pts, &EndCondition::Natural).unwrap();
    assert_eq!(s.derivative_at(&knots[0], 2).unwrap(), Point::zero());
    assert_eq!(s.derivative_at(&knots[4], 2).unwrap(), Point::zero());
    assert!(s.is_c(2, &qi(0)) && !s.is_c(3, &qi(0)));
}

#[test]
fn periodic_spline_closes_with_c2_continuity() {
    let knots = vec![qi(0), qi(1), q(5, 2), qi(3), qi(5)];
    let pts: Vec<_> = [(0, 0), (2, 1), (1, 3), (-1, 2), (0, 0)]
        .iter()
        .map(|&(x, y)| p2(qi(x), qi(y)))
        .collect();
    let s = cubic_spline(&knots, &pts, &EndCondition::Periodic).unwrap();
    assert!(s.is_c(2, &qi(0)));
    let m = s.pieces().len();
    let start = s.end_derivatives(0, false, 2).unwrap();
    let end = s.end_derivatives(m - 1, true, 2).unwrap();
    assert_eq!(start, end, "value, first and second derivatives close up");
    // Two pieces (the smallest closed spline) also close.
    let two = cubic_spline(
        &[qi(0), qi(1), qi(3)],
        &[p2(qi(0), qi(0)), p2(qi(1), qi(1)), p2(qi(0), qi(0))],
        &EndCondition::Periodic,
    )
    .unwrap();
    assert_eq!(
        two.end_derivatives(0, false, 2).unwrap(),
        two.end_derivatives(1, true, 2).unwrap()
    );
}

#[test]
fn clamped_spline_reproduces_a_cubic_and_bessel_a_parabola() {
    // c(u) = (u³ − 2u, u² + 1): with its own end tangents the clamped spline is c itself.
    let c = Polynomial::new(vec![
        p2(qi(0), qi(1)),
        p2(qi(-2), qi(0)),
        p2(qi(0), qi(1)),
        p2(qi(1), qi(0)),
    ]);
    let dc = c.derivative_curve().unwrap();
    let knots = vec![qi(-1), q(-1, 4), q(1, 2), qi(2), q(7, 3)];
    let pts: Vec<_> = knots.iter().map(|u| c.eval(u).unwrap()).collect();
    let end = EndCondition::Clamped {
        start: dc.eval(&knots[0]).unwrap(),
        end: dc.eval(&knots[4]).unwrap(),
    };
    let s = cubic_spline(&knots, &pts, &end).unwrap();
    for k in 0..=8 {
        let u = knots[0].clone() + &(q(k, 8) * &(knots[4].clone() - &knots[0]));
        assert_eq!(s.eval(&u).unwrap(), c.eval(&u).unwrap());
    }
    // Bessel's tangents are exact for parabolas, so the spline is the parabola.
    let par = Polynomial::new(vec![
        p2(qi(1), qi(0)),
        p2(qi(-3), qi(2)),
        p2(q(1, 2), qi(5)),
    ]);
    let pts: Vec<_> = knots.iter().map(|u| par.eval(u).unwrap()).collect();
    let s = cubic_spline(&knots, &pts, &EndCondition::Bessel).unwrap();
    let m = cubic_spline_tangents(&knots, &pts, &EndCondition::Bessel).unwrap();
    let dpar = par.derivative_curve().unwrap();
    assert_eq!(m[0], dpar.eval(&knots[0]).unwrap());
    assert_eq!(m[4], dpar.eval(&knots[4]).unwrap());
    assert_eq!(s.eval(&q(1, 7)).unwrap(), par.eval(&q(1, 7)).unwrap());
}

#[test]
fn estimated_tangents_are_exact_on_parabolas() {
    let par = Polynomial::new(vec![
        p2(qi(2), qi(-1)),
        p2(qi(1), qi(4)),
        p2(qi(-3), q(2, 3)),
    ]);
    let knots = vec![qi(0), q(1, 5), qi(1), q(3, 2), qi(4)];
    let pts: Vec<_> = knots.iter().map(|u| par.eval(u).unwrap()).collect();
    let d = estimate_tangents(&knots, &pts).unwrap();
    let dpar = par.derivative_curve().unwrap();
    for (u, t) in knots.iter().zip(&d) {
        assert_eq!(*t, dpar.eval(u).unwrap());
    }
}

#[test]
fn chord_and_centripetal_knots_measure_the_chords() {
    let pts = [
        Point::new([0.0, 0.0, 0.0]),
        Point::new([2.0, 3.0, 6.0]),
        Point::new([2.0, 3.0, 6.0 + 16.0]),
    ];
    assert_eq!(
        parameterise(&pts, Parameterisation::ChordLength).unwrap(),
        vec![0.0, 7.0, 23.0]
    );
    let c = parameterise(&pts, Parameterisation::Centripetal).unwrap();
    assert_eq!(c, vec![0.0, 7f64.sqrt(), 7f64.sqrt() + 4.0]);
    let u: Vec<Q> = parameterise(
        &[p2(qi(0), qi(0)), p2(qi(3), qi(4))],
        Parameterisation::ChordLength,
    )
    .unwrap();
    assert_eq!(u, vec![qi(0), qi(5)]);
    let dup = [Point::new([1.0, 1.0]), Point::new([1.0, 1.0])];
    assert!(matches!(
        parameterise(&dup, Parameterisation::ChordLength),
        Err(Error::InvalidParameter { name: "points", .. })
    ));
}

#[test]
fn bad_input_gives_clear_errors() {
    let p = |x: f64| Point::new([x, 0.0]);
    let pts = [p(0.0), p(1.0), p(2.0)];
    // Non-increasing partition.
    let e = cubic_spline(&[0.0, 1.0, 1.0], &pts, &EndCondition::Natural).unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidParameter {
                name: "partition",
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("strictly increasing"), "{e}");
    // NaN coordinate and NaN knot.
    let e = hermite(&[0.0, 1.0], &[p(0.0), p(f64::NAN)], &[p(0.0), p(0.0)]).unwrap_err();
    assert!(matches!(e, Error::NonFinite { index: 1, .. }), "{e}");
    let e = newton(&[0.0, f64::NAN], &[p(0.0), p(1.0)]).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "nodes", .. }),
        "{e}"
    );
    // Mismatched lengths.
    let e = hermite(&[0.0, 1.0, 2.0], &pts, &[p(0.0)]).unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidParameter {
                name: "tangents",
                ..
            }
        ),
        "{e}"
    );
    let e = vandermonde(&[0.0, 1.0], &pts).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "points", .. }),
        "{e}"
    );
    // Repeated nodes without derivative data: singular.
    for e in [
        vandermonde(&[0.0, 1.0, 0.0], &pts).unwrap_err(),
        newton(&[0.0, 1.0, 0.0], &pts).unwrap_err(),
        lagrange(&[0.0, 1.0, 0.0], &pts).unwrap_err(),
        lagrange_basis(&[0.0, 1.0, 0.0], &0.5).unwrap_err(),
    ] {
        assert!(e.to_string().contains("nodes 0 and 2 are equal"), "{e}");
    }
    // A repeated node in Hermite data must carry all its derivatives in one entry.
    let data = [
        HermiteNode {
            u: 0.0,
            values: vec![p(0.0)],
        },
        HermiteNode {
            u: 0.0,
            values: vec![p(1.0)],
        },
    ];
    assert!(newton_hermite(&data).is_err() && vandermonde_hermite(&data).is_err());
    // Too few points.
    let e = cubic_spline(&[0.0, 1.0], &pts[..2], &EndCondition::Bessel).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooFew {
                needed: 3,
                got: 2,
                ..
            }
        ),
        "{e}"
    );
    let e = hermite(&[0.0], &pts[..1], &pts[..1]).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooFew {
                needed: 2,
                got: 1,
                ..
            }
        ),
        "{e}"
    );
    assert!(matches!(
        newton::<f64, 2>(&[], &[]),
        Err(Error::Empty { .. })
    ));
    // Periodic data must close.
    let e = cubic_spline(&[0.0, 1.0, 2.0], &pts, &EndCondition::Periodic).unwrap_err();
    assert!(e.to_string().contains("first and last points"), "{e}");
    // Evaluation outside the partition.
    let s = cubic_spline(&[0.0, 1.0, 2.0], &pts, &EndCondition::Natural).unwrap();
    assert!(matches!(
        s.eval(&2.5),
        Err(Error::InvalidParameter { name: "u", .. })
    ));
    assert!(s.eval(&f64::NAN).is_err());
    // Composite curves: wrong number of pieces, empty polygon, a C^r builder with bad sizes.
    assert!(CompositeBezier::new(vec![0.0, 1.0, 2.0], vec![vec![p(0.0)]]).is_err());
    assert!(CompositeBezier::<f64, 2>::new(vec![0.0, 1.0], vec![vec![]]).is_err());
    let mut c = CompositeBezier::new(vec![0.0, 1.0], vec![pts.to_vec()]).unwrap();
    assert!(c.push_cr(3, 2.0, &[]).is_err());
    assert!(c.push_cr(1, 2.0, &[]).is_err());
    assert!(c.push_cr(1, 0.5, &[p(1.0)]).is_err());
    assert!(c.join(0, &0.0).is_err());
}

/// Distinct rational nodes: sorted distinct integers scaled by 1/den.
fn nodes_strategy(max: usize) -> impl Strategy<Value = Vec<Q>> {
    (
        proptest::collection::btree_set(-40i64..40, 2..=max),
        1i64..6,
    )
        .prop_map(|(set, den)| set.into_iter().map(|n| q(n, den)).collect())
}

fn points_strategy(n: usize) -> impl Strategy<Value = Vec<Point<Q, 2>>> {
    proptest::collection::vec((-30i64..30, -30i64..30), n)
        .prop_map(|v| v.into_iter().map(|(x, y)| p2(qi(x), qi(y))).collect())
}

fn nodes_and_points(max: usize) -> impl Strategy<Value = (Vec<Q>, Vec<Point<Q, 2>>)> {
    nodes_strategy(max).prop_flat_map(|nodes| {
        let n = nodes.len();
        (Just(nodes), points_strategy(n))
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn lagrange_aitken_newton_and_vandermonde_agree((nodes, pts) in nodes_and_points(7), num in -50i64..50) {
        let u = q(num, 7);
        let v = vandermonde(&nodes, &pts).unwrap();
        // Newton's nodes are order-free: reverse them.
        let rev_nodes: Vec<Q> = nodes.iter().rev().cloned().collect();
        let rev_pts: Vec<_> = pts.iter().rev().cloned().collect();
        let nw = newton(&rev_nodes, &rev_pts).unwrap();
        prop_assert_eq!(&nw.to_polynomial(), &v);
        let want = v.eval(&u).unwrap();
        let lg = lagrange(&nodes, &pts).unwrap();
        prop_assert_eq!(&lg.eval(&u).unwrap(), &want);
        prop_assert_eq!(&lg.aitken(&u).unwrap(), &want);
        prop_assert_eq!(&nw.eval(&u).unwrap(), &want);
        prop_assert_eq!(&lg.to_newton().unwrap().to_polynomial(), &v);
        for (x, p) in nodes.iter().zip(&pts) {
            prop_assert_eq!(&v.eval(x).unwrap(), p);
            prop_assert_eq!(&lg.eval(x).unwrap(), p);
        }
        let basis = lagrange_basis(&nodes, &u).unwrap();
        prop_assert_eq!(basis.into_iter().fold(qi(0), |a, b| a + b), qi(1));
    }

    #[test]
    fn hermite_data_is_reproduced_with_derivatives(
        (nodes, pts) in nodes_and_points(4),
        extra in proptest::collection::vec((-9i64..9, -9i64..9), 12),
        orders in proptest::collection::vec(0usize..3, 4),
    ) {
        let mut it = extra.into_iter();
        let data: Vec<HermiteNode<Q, 2>> = nodes.iter().zip(&pts).zip(&orders).map(|((u, p), &k)| {
            let mut values = vec![p.clone()];
            for _ in 0..k {
                let (x, y) = it.next().unwrap();
                values.push(p2(qi(x), qi(y)));
            }
            HermiteNode { u: u.clone(), values }
        }).collect();
        let nw = newton_hermite(&data).unwrap();
        let poly = nw.to_polynomial();
        prop_assert_eq!(&poly, &vandermonde_hermite(&data).unwrap());
        for node in &data {
            let mut d = poly.clone();
            for value in &node.values {
                prop_assert_eq!(&d.eval(&node.u).unwrap(), value);
                d = d.derivative_curve().unwrap();
            }
        }
    }

    #[test]
    fn splines_interpolate_and_are_c2((nodes, pts) in nodes_and_points(8), kind in 0usize..3) {
        prop_assume!(nodes.len() >= 3);
        let end = match kind {
            0 => EndCondition::Natural,
            1 => EndCondition::Bessel,
            _ => EndCondition::Clamped { start: p2(qi(1), qi(-2)), end: p2(qi(0), qi(3)) },
        };
        let s = cubic_spline(&nodes, &pts, &end).unwrap();
        let tangents = cubic_spline_tangents(&nodes, &pts, &end).unwrap();
        for ((u, p), t) in nodes.iter().zip(&pts).zip(&tangents) {
            prop_assert_eq!(&s.eval(u).unwrap(), p);
            prop_assert_eq!(&s.derivative_at(u, 1).unwrap(), t);
        }
        prop_assert!(s.is_c(2, &qi(0)));
        if let EndCondition::Clamped { start, end } = &end {
            prop_assert_eq!(&tangents[0], start);
            prop_assert_eq!(tangents.last().unwrap(), end);
        }
    }

    #[test]
    fn periodic_splines_close_with_c2((nodes, mut pts) in nodes_and_points(8)) {
        prop_assume!(nodes.len() >= 3);
        let first = pts[0].clone();
        *pts.last_mut().unwrap() = first;
        let s = cubic_spline(&nodes, &pts, &EndCondition::Periodic).unwrap();
        prop_assert!(s.is_c(2, &qi(0)));
        let m = s.pieces().len();
        prop_assert_eq!(s.end_derivatives(0, false, 2).unwrap(), s.end_derivatives(m - 1, true, 2).unwrap());
    }


    #[test]
    fn open_and_closed_quadratic_splines_are_c1((nodes, mut pts) in nodes_and_points(7), v in (-9i64..9, -9i64..9)) {
        let start = p2(qi(v.0), qi(v.1));
        let c = quadratic_spline(&nodes, &pts, &start).unwrap();
        prop_assert!(c.is_c(1, &qi(0)));
        prop_assert_eq!(&c.derivative_at(&nodes[0], 1).unwrap(), &start);
        for (u, p) in nodes.iter().zip(&pts) {
            prop_assert_eq!(&c.eval(u).unwrap(), p);
        }
        prop_assume!(nodes.len() >= 3);
        let first = pts[0].clone();
        *pts.last_mut().unwrap() = first;
        match closed_quadratic_spline(&nodes, &pts) {
            Ok(c) => {
                let m = c.pieces().len();
                prop_assert!(c.is_c(1, &qi(0)));
                prop_assert_eq!(c.end_derivatives(0, false, 1).unwrap(), c.end_derivatives(m - 1, true, 1).unwrap());
            }
            Err(_) => prop_assert!((nodes.len() - 1) % 2 == 0, "an odd number of pieces is regular"),
        }
        if (nodes.len() - 1) % 2 == 0 {
            prop_assert!(closed_quadratic_spline(&nodes, &pts).is_err());
        }
    }

    #[test]
    fn least_squares_recovers_curves_and_leaves_orthogonal_residuals(
        ctrl in points_strategy(4),
        (params, pts) in nodes_and_points(9),
        degree in 1usize..=3,
        clamp in any::<bool>(),
        w in proptest::collection::vec(1i64..4, 9),
    ) {
        // Parameters in [0, 1]: rescale the distinct nodes.
        let lo = params[0].clone();
        let span = params[params.len() - 1].clone() - &lo;
        let u: Vec<Q> = params.iter().map(|x| (x.clone() - &lo) / &span).collect();
        prop_assume!(u.len() > degree);
        let weights: Vec<Q> = w[..u.len()].iter().map(|&x| qi(x)).collect();
        let options = FitOptions { weights: Some(weights.clone()), clamp_ends: clamp };
        // Points on a curve of the fitted degree are recovered exactly.
        let truth = Bezier::new(ctrl[..=degree].to_vec()).unwrap();
        let on: Vec<_> = u.iter().map(|t| truth.eval(t).unwrap()).collect();
        prop_assert_eq!(fit_bezier(&u, &on, degree, &options).unwrap(), truth);
        // Arbitrary points: the weighted residual is orthogonal to every free column.
        let fit = fit_bezier(&u, &pts, degree, &options).unwrap();
        let free = if clamp { 1..degree } else { 0..degree + 1 };
        for j in free {
            let mut acc = Point::<Q, 2>::zero();
            for ((t, p), wi) in u.iter().zip(&pts).zip(&weights) {
                let r = fit.eval(t).unwrap() - p;
                let b = bernstein_all(degree, t).unwrap()[j].clone() * wi * wi;
                acc += &(r * &b);
            }
            prop_assert_eq!(acc, Point::zero());
        }
        if clamp {
            prop_assert_eq!(&fit.control()[0], &pts[0]);
            prop_assert_eq!(&fit.control()[degree], pts.last().unwrap());
        }
    }


    #[test]
    fn f64_splines_agree_with_the_exact_ones((nodes, pts) in nodes_and_points(8), kind in 0usize..2) {
        prop_assume!(nodes.len() >= 3);
        let end_q = if kind == 0 { EndCondition::Natural } else { EndCondition::Bessel };
        let end_f = if kind == 0 { EndCondition::Natural } else { EndCondition::Bessel };
        let exact = cubic_spline(&nodes, &pts, &end_q).unwrap();
        let nodes_f: Vec<f64> = nodes.iter().map(Scalar::to_f64).collect();
        let pts_f: Vec<Point<f64, 2>> = pts.iter().map(Point::to_f64).collect();
        let rounded = cubic_spline(&nodes_f, &pts_f, &end_f).unwrap();
        let scale = exact
            .pieces()
            .iter()
            .flat_map(|b| b.control().iter())
            .fold(1.0f64, |m, p| m.max(p[0].to_f64().abs()).max(p[1].to_f64().abs()));
        for (a, b) in exact.pieces().iter().zip(rounded.pieces()) {
            for (p, q) in a.control().iter().zip(b.control()) {
                let p = p.to_f64();
                prop_assert!((p[0] - q[0]).abs() <= 1e-10 * scale && (p[1] - q[1]).abs() <= 1e-10 * scale);
            }
        }
    }

    #[test]
    fn cr_joins_are_cr_exactly(
        pts in points_strategy(4),
        free in points_strategy(3),
        r in 0usize..=3,
        h in 1i64..9,
    ) {
        let mut c = CompositeBezier::new(vec![qi(0), qi(1)], vec![pts]).unwrap();
        c.push_cr(r, qi(1) + &q(h, 3), &free[..3 - r]).unwrap();
        prop_assert!(c.is_c(r, &qi(0)));
        let join = c.join(1, &qi(0)).unwrap();
        prop_assert!(join.parametric.unwrap() >= r);
        if r == 3 {
            // C³ between cubics continues the same polynomial: C^∞.
            prop_assert_eq!(join.parametric, Some(3));
            prop_assert!(c.is_c(7, &qi(0)));
            let u = qi(1) + &q(h, 6);
            let left = CompositeBezier::from_pieces(vec![qi(0), qi(1)], vec![c.pieces()[0].clone()]).unwrap();
            prop_assert_eq!(c.eval(&u).unwrap(), extrapolate(&left, &u));
        }
    }
}

/// The first piece's polynomial at `u` beyond its interval, by the monomial form of its
/// values at four parameters (a Vandermonde oracle independent of the builder).
fn extrapolate(c: &CompositeBezier<Q, 2>, u: &Q) -> Point<Q, 2> {
    let ts = [qi(0), q(1, 3), q(2, 3), qi(1)];
    let vals: Vec<_> = ts.iter().map(|t| c.eval(t).unwrap()).collect();
    vandermonde(&ts, &vals).unwrap().eval(u).unwrap()
}

#[test]
fn quadratic_splines_follow_seed_001_section_2() {
    // The open spline reproduces a parabola from its start slope.
    let par = Polynomial::new(vec![
        p2(qi(1), qi(2)),
        p2(qi(-1), qi(3)),
        p2(q(3, 2), qi(-1)),
    ]);
    let knots = vec![qi(0), q(1, 2), qi(2), q(9, 4), qi(3)];
    let pts: Vec<_> = knots.iter().map(|u| par.eval(u).unwrap()).collect();
    let start = par.derivative_curve().unwrap().eval(&knots[0]).unwrap();
    let c = quadratic_spline(&knots, &pts, &start).unwrap();
    for k in 0..=12 {
        let u = q(k, 4);
        assert_eq!(c.eval(&u).unwrap(), par.eval(&u).unwrap());
    }
    // Closed: an odd number of pieces is always regular, an even one never (B_i telescopes).
    let square = [(0, 0), (2, 0), (2, 2), (0, 2), (0, 0)].map(|(x, y)| p2(qi(x), qi(y)));
    let uniform = vec![qi(0), qi(1), qi(2), qi(3), qi(4)];
    let uneven = vec![qi(0), qi(1), qi(3), qi(4), qi(7)];
    for knots in [&uniform, &uneven] {
        let e = closed_quadratic_spline(knots, &square).unwrap_err();
        assert!(e.to_string().contains("even number of pieces"), "{e}");
    }
    let triangle = [(0, 0), (2, 0), (2, 2), (0, 0)].map(|(x, y)| p2(qi(x), qi(y)));
    let c = closed_quadratic_spline(&uneven[..4], &triangle).unwrap();
    assert!(c.is_c(1, &qi(0)));
    assert_eq!(
        c.end_derivatives(0, false, 1).unwrap(),
        c.end_derivatives(2, true, 1).unwrap()
    );
    let open = [(0, 0), (2, 0), (2, 2)].map(|(x, y)| p2(qi(x), qi(y)));
    assert!(closed_quadratic_spline(&uniform[..3], &open).is_err());
}

#[test]
fn least_squares_fit_rejects_underdetermined_data() {
    let pts = [Point::new([0.0]), Point::new([1.0]), Point::new([2.0])];
    // Three points at two distinct parameters cannot fix a parabola.
    let e = fit_bezier(&[0.0, 0.5, 0.5], &pts, 2, &FitOptions::default()).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "params", .. }),
        "{e}"
    );
    let bad_weights = FitOptions {
        weights: Some(vec![1.0, f64::NAN, 1.0]),
        clamp_ends: false,
    };
    assert!(fit_bezier(&[0.0, 0.5, 1.0], &pts, 1, &bad_weights).is_err());
    let short = FitOptions {
        weights: Some(vec![1.0]),
        clamp_ends: false,
    };
    assert!(fit_bezier(&[0.0, 0.5, 1.0], &pts, 1, &short).is_err());
    assert!(fit_bezier::<f64, 1>(&[], &[], 1, &FitOptions::default()).is_err());
}

/// The curve traits' properties (`spline_common::curve_properties`) on every interpolation
/// result: the three polynomial forms, the Hermite curve and the cubic and quadratic splines.
mod traits {
    use crate::spline_common::curve_properties::{
        curve_property_tests, eighths, point, points, Family,
    };
    use compgeo::spline::{
        closed_quadratic_spline, cubic_spline, hermite, lagrange, newton, quadratic_spline,
        vandermonde, CompositeBezier, EndCondition, LagrangeForm, NewtonForm, Polynomial, Scalar,
    };
    use proptest::prelude::*;

    type Pairs = Vec<(i64, i64)>;

    /// 2 to `max` distinct nodes in [−1, 2] (eighths), in a random order, and a point per node.
    fn nodes_and_points(max: usize) -> impl Strategy<Value = (Vec<i64>, Pairs)> {
        prop::collection::btree_set(-8i64..=16, 2..=max).prop_flat_map(|set| {
            let nodes: Vec<i64> = set.into_iter().collect();
            let n = nodes.len();
            (
                Just(nodes).prop_shuffle(),
                prop::collection::vec((-80i64..=80, -80i64..=80), n),
            )
        })
    }

    /// An increasing partition of `pieces` intervals (knots in eighths) starting in [−1, 0],
    /// with a point per knot.
    fn knots_and_points(
        pieces: std::ops::RangeInclusive<usize>,
    ) -> impl Strategy<Value = (Vec<i64>, Pairs)> {
        (-8i64..=0, prop::collection::vec(1i64..=12, pieces)).prop_flat_map(|(start, gaps)| {
            let mut knots = vec![start];
            for g in &gaps {
                knots.push(knots.last().unwrap() + g);
            }
            let n = knots.len();
            (
                Just(knots),
                prop::collection::vec((-80i64..=80, -80i64..=80), n),
            )
        })
    }

    fn knots<S: Scalar>(k: &[i64]) -> Vec<S> {
        k.iter().copied().map(eighths).collect()
    }

    /// A polynomial interpolant built from distinct nodes and points by `$build`.
    macro_rules! polynomial_family {
        ($family:ident, $curve:ident, $build:ident) => {
            struct $family;

            impl Family for $family {
                type Data = (Vec<i64>, Pairs);
                type Curve<S: Scalar> = $curve<S, 2>;
                const TOLERANCE: f64 = 1e-9;
                fn data() -> BoxedStrategy<Self::Data> {
                    nodes_and_points(6).boxed()
                }
                fn build<S: Scalar>((nodes, pts): &Self::Data) -> $curve<S, 2> {
                    $build(&knots(nodes), &points(pts)).unwrap()
                }
            }
        };
    }

    polynomial_family!(Power, Polynomial, vandermonde);
    polynomial_family!(Newton, NewtonForm, newton);
    polynomial_family!(Lagrange, LagrangeForm, lagrange);

    struct Hermite;

    impl Family for Hermite {
        /// Knots, points and tangents.
        type Data = (Vec<i64>, Pairs, Pairs);
        type Curve<S: Scalar> = CompositeBezier<S, 2>;
        const TOLERANCE: f64 = 1e-12;
        fn data() -> BoxedStrategy<Self::Data> {
            knots_and_points(1..=4)
                .prop_flat_map(|(k, p)| {
                    let n = k.len();
                    (
                        Just(k),
                        Just(p),
                        prop::collection::vec((-80i64..=80, -80i64..=80), n),
                    )
                })
                .boxed()
        }
        fn build<S: Scalar>((k, p, d): &Self::Data) -> CompositeBezier<S, 2> {
            hermite(&knots(k), &points(p), &points(d)).unwrap()
        }
    }

    struct Cubic;

    impl Family for Cubic {
        /// The end condition (natural, clamped, Bessel, periodic), knots and points.
        type Data = (usize, Vec<i64>, Pairs);
        type Curve<S: Scalar> = CompositeBezier<S, 2>;
        const TOLERANCE: f64 = 1e-11;
        fn data() -> BoxedStrategy<Self::Data> {
            (0usize..4, knots_and_points(2..=5))
                .prop_map(|(kind, (k, mut p))| {
                    if kind == 3 {
                        let first = p[0];
                        *p.last_mut().unwrap() = first;
                    }
                    (kind, k, p)
                })
                .boxed()
        }
        fn build<S: Scalar>((kind, k, p): &Self::Data) -> CompositeBezier<S, 2> {
            let end = match kind {
                0 => EndCondition::Natural,
                1 => EndCondition::Clamped {
                    start: point((8, -16)),
                    end: point((0, 24)),
                },
                2 => EndCondition::Bessel,
                _ => EndCondition::Periodic,
            };
            cubic_spline(&knots(k), &points(p), &end).unwrap()
        }
    }

    struct Quadratic;

    impl Family for Quadratic {
        /// Closed or open (with a start tangent), knots and points.
        type Data = (bool, (i64, i64), Vec<i64>, Pairs);
        type Curve<S: Scalar> = CompositeBezier<S, 2>;
        const TOLERANCE: f64 = 1e-10;
        fn data() -> BoxedStrategy<Self::Data> {
            let tangent = (-40i64..=40, -40i64..=40);
            let open = (tangent, knots_and_points(1..=4)).prop_map(|(v, (k, p))| (false, v, k, p));
            // A closed spline needs an odd number of pieces (an even one is singular).
            let closed = prop_oneof![knots_and_points(3..=3), knots_and_points(5..=5)].prop_map(
                |(k, mut p)| {
                    let first = p[0];
                    *p.last_mut().unwrap() = first;
                    (true, (0, 0), k, p)
                },
            );
            prop_oneof![open, closed].boxed()
        }
        fn build<S: Scalar>((closed, v, k, p): &Self::Data) -> CompositeBezier<S, 2> {
            if *closed {
                closed_quadratic_spline(&knots(k), &points(p)).unwrap()
            } else {
                quadratic_spline(&knots(k), &points(p), &point(*v)).unwrap()
            }
        }
    }

    curve_property_tests! {
        power_forms_have_the_curve_properties: Power, 32;
        newton_forms_have_the_curve_properties: Newton, 32;
        lagrange_forms_have_the_curve_properties: Lagrange, 32;
        hermite_curves_have_the_curve_properties: Hermite, 32;
        cubic_splines_have_the_curve_properties: Cubic, 48;
        quadratic_splines_have_the_curve_properties: Quadratic, 32;
    }
}
