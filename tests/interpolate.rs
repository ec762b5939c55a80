//! Interpolation and composite curves against exact oracles: the seed's worked Hermite example
//! digit for digit, interpolants that reproduce their data and derivatives with rationals,
//! the end conditions of the cubic spline, agreement of the Lagrange, Aitken, Newton and
//! Vandermonde forms, C¹ quadratic splines, least-squares fits (exact recovery, orthogonal
//! residuals), Frenet frames against analytic curves, and the bad-input contract (library and
//! `compgeo interpolate`).
#![cfg(feature = "exact")]

use compgeo::spline::{
    aitken, bernstein_all, bezier_frenet, c1_partition, closed_quadratic_spline, cubic_spline,
    cubic_spline_tangents, curvature_vector, estimate_tangents, fit_bezier, frenet_frame, hermite,
    is_g2, is_g2_join, lagrange, lagrange_basis, newton, newton_hermite, parameterise,
    quadratic_spline, vandermonde, vandermonde_hermite, Bezier, CompositeBezier, EndCondition,
    FitOptions, HermiteNode, Parameterisation, Point, Polynomial, Scalar,
};
use compgeo::Error;
use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;

type Q = BigRational;

fn q(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

fn qi(n: i64) -> Q {
    q(n, 1)
}

fn p2(x: Q, y: Q) -> Point<Q, 2> {
    Point::new([x, y])
}

/// Reads "(a, b)" or "[a, b]" pairs of integers out of a line of the seed.
fn pairs(line: &str) -> Vec<Point<Q, 2>> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(start) = rest.find(['(', '[']) {
        let close = if rest.as_bytes()[start] == b'(' {
            ')'
        } else {
            ']'
        };
        let end = start + rest[start..].find(close).unwrap();
        let inner = &rest[start + 1..end];
        let nums: Vec<i64> = inner
            .split(',')
            .map(|s| s.trim().parse().unwrap())
            .collect();
        assert_eq!(nums.len(), 2, "{inner}");
        out.push(p2(qi(nums[0]), qi(nums[1])));
        rest = &rest[end + 1..];
    }
    out
}

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
    let text = include_str!("fixtures/seed003_hermite_example.txt");
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

    let curve = hermite(&points, &tangents, &knots).unwrap();
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
        &points.iter().map(f).collect::<Vec<_>>(),
        &tangents.iter().map(f).collect::<Vec<_>>(),
        &knots.iter().map(Scalar::to_f64).collect::<Vec<_>>(),
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
    // 003 §3.2: Q_2 = λ² (P_n − 2P_{n−1} + P_{n−2}) + 2λ (P_n − P_{n−1}) + P_n.
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
    let dc = c.derivative();
    let knots = vec![qi(-1), q(-1, 4), q(1, 2), qi(2), q(7, 3)];
    let pts: Vec<_> = knots.iter().map(|u| c.eval(u)).collect();
    let end = EndCondition::Clamped {
        start: dc.eval(&knots[0]),
        end: dc.eval(&knots[4]),
    };
    let s = cubic_spline(&knots, &pts, &end).unwrap();
    for k in 0..=8 {
        let u = knots[0].clone() + &(q(k, 8) * &(knots[4].clone() - &knots[0]));
        assert_eq!(s.eval(&u).unwrap(), c.eval(&u));
    }
    // Bessel's tangents are exact for parabolas, so the spline is the parabola.
    let par = Polynomial::new(vec![
        p2(qi(1), qi(0)),
        p2(qi(-3), qi(2)),
        p2(q(1, 2), qi(5)),
    ]);
    let pts: Vec<_> = knots.iter().map(|u| par.eval(u)).collect();
    let s = cubic_spline(&knots, &pts, &EndCondition::Bessel).unwrap();
    let m = cubic_spline_tangents(&knots, &pts, &EndCondition::Bessel).unwrap();
    let dpar = par.derivative();
    assert_eq!(m[0], dpar.eval(&knots[0]));
    assert_eq!(m[4], dpar.eval(&knots[4]));
    assert_eq!(s.eval(&q(1, 7)).unwrap(), par.eval(&q(1, 7)));
}

#[test]
fn estimated_tangents_are_exact_on_parabolas() {
    let par = Polynomial::new(vec![
        p2(qi(2), qi(-1)),
        p2(qi(1), qi(4)),
        p2(qi(-3), q(2, 3)),
    ]);
    let knots = vec![qi(0), q(1, 5), qi(1), q(3, 2), qi(4)];
    let pts: Vec<_> = knots.iter().map(|u| par.eval(u)).collect();
    let d = estimate_tangents(&pts, &knots).unwrap();
    let dpar = par.derivative();
    for (u, t) in knots.iter().zip(&d) {
        assert_eq!(*t, dpar.eval(u));
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
    let e = hermite(&[p(0.0), p(f64::NAN)], &[p(0.0), p(0.0)], &[0.0, 1.0]).unwrap_err();
    assert!(matches!(e, Error::NonFinite { index: 1, .. }), "{e}");
    let e = newton(&[0.0, f64::NAN], &[p(0.0), p(1.0)]).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "nodes", .. }),
        "{e}"
    );
    // Mismatched lengths.
    let e = hermite(&pts, &[p(0.0)], &[0.0, 1.0, 2.0]).unwrap_err();
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
        lagrange(&[0.0, 1.0, 0.0], &pts, &0.5).unwrap_err(),
        aitken(&[0.0, 1.0, 0.0], &pts, &0.5).unwrap_err(),
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
    let e = hermite(&pts[..1], &pts[..1], &[0.0]).unwrap_err();
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
        let want = v.eval(&u);
        prop_assert_eq!(&lagrange(&nodes, &pts, &u).unwrap(), &want);
        prop_assert_eq!(&aitken(&nodes, &pts, &u).unwrap(), &want);
        prop_assert_eq!(&nw.eval(&u), &want);
        for (x, p) in nodes.iter().zip(&pts) {
            prop_assert_eq!(&v.eval(x), p);
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
                prop_assert_eq!(&d.eval(&node.u), value);
                d = d.derivative();
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
    fn frenet_frames_of_space_cubics_match_the_cross_product_formulas(
        coords in proptest::collection::vec(-20i32..20, 12),
        k in 0i32..=8,
    ) {
        let ctrl: Vec<Point<f64, 3>> = coords
            .chunks(3)
            .map(|c| Point::new([c[0] as f64, c[1] as f64, c[2] as f64]))
            .collect();
        let b = Bezier::new(ctrl).unwrap();
        let t = k as f64 / 8.0;
        let d: Vec<[f64; 3]> = (1..=3).map(|r| b.derivative_at(&t, r).unwrap().0).collect();
        let x = cross(d[0], d[1]);
        let (speed2, area2) = (dot3(d[0], d[0]), dot3(x, x));
        prop_assume!(speed2 > 1e-6 && area2 > 1e-6 * speed2 * speed2);
        let f = bezier_frenet(&b, &t).unwrap();
        let want_kappa = area2.sqrt() / speed2.powf(1.5);
        let want_tau = dot3(x, d[2]) / area2;
        prop_assert!(close(f.curvature(), want_kappa, 1e-9), "{} vs {want_kappa}", f.curvature());
        prop_assert!(close(f.torsion(), want_tau, 1e-9), "{} vs {want_tau}", f.torsion());
        // Orthonormal, tangent along x', and f_3 = f_1 × f_2 when the frame is full.
        let v: Vec<[f64; 3]> = f.vectors().iter().map(|p| p.0).collect();
        for i in 0..v.len() {
            for j in 0..v.len() {
                let want = if i == j { 1.0 } else { 0.0 };
                prop_assert!((dot3(v[i], v[j]) - want).abs() < 1e-9);
            }
        }
        prop_assert!(dot3(v[0], d[0]) > 0.0 && dot3(v[1], d[1]) > 0.0);
        if v.len() == 3 {
            let c = cross(v[0], v[1]);
            prop_assert!((0..3).all(|i| (c[i] - v[2][i]).abs() < 1e-9));
        }
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
            // C³ between cubics continues the same polynomial.
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
    vandermonde(&ts, &vals).unwrap().eval(u)
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(1.0)
}

#[test]
fn helix_has_the_textbook_curvature_and_torsion() {
    // (a cos t, a sin t, b t): κ = a/(a² + b²), τ = b/(a² + b²).
    for (a, b) in [(1.0, 1.0), (2.0, 0.5), (0.5, -3.0)] {
        for k in 0..8 {
            let t = k as f64 * 0.7;
            let (s, c) = t.sin_cos();
            let d = [
                Point::new([-a * s, a * c, b]),
                Point::new([-a * c, -a * s, 0.0]),
                Point::new([a * s, -a * c, 0.0]),
            ];
            let f = frenet_frame(&d).unwrap();
            let den = a * a + b * b;
            assert!(close(f.curvature(), a / den, 1e-14), "{a} {b} {t}");
            assert!(close(f.torsion(), b / den, 1e-14), "{a} {b} {t}");
            // The principal normal points to the axis.
            let n = f.normal().unwrap();
            assert!(close(n[0], -c, 1e-14) && close(n[1], -s, 1e-14) && n[2].abs() < 1e-14);
        }
    }
}

#[test]
fn plane_curvature_is_signed_by_the_turn() {
    // A circle of radius 3 run counter-clockwise and clockwise.
    let ccw = frenet_frame(&[Point::new([0.0, 3.0]), Point::new([-3.0, 0.0])]).unwrap();
    let cw = frenet_frame(&[Point::new([0.0, -3.0]), Point::new([-3.0, 0.0])]).unwrap();
    assert!(close(ccw.curvature(), 1.0 / 3.0, 1e-15));
    assert!(close(cw.curvature(), -1.0 / 3.0, 1e-15));
    // The frame is positively oriented in both cases: f_2 is f_1 turned by +90°.
    for f in [ccw, cw] {
        let (t, n) = (f.tangent(), f.normal().unwrap());
        assert_eq!((n[0], n[1]), (-t[1], t[0]));
    }
    // A straight line: no normal, zero curvature; a singular point is an error.
    let line = frenet_frame(&[Point::new([1.0, 2.0]), Point::new([2.0, 4.0])]).unwrap();
    assert_eq!((line.normal(), line.curvature()), (None, 0.0));
    let e = frenet_frame(&[Point::new([0.0, 0.0]), Point::new([1.0, 0.0])]).unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidParameter {
            name: "derivatives",
            ..
        }
    ));
    assert!(frenet_frame::<f64, 2>(&[]).is_err());
}

#[test]
fn bezier_end_curvature_matches_the_seeds_formula() {
    // 000 §4.4 Obs. 8: κ at b_0 is (n − 1)/n ‖Δb_0 × Δ²b_0‖ / ‖Δb_0‖³.
    let b = Bezier::new(vec![
        Point::new([0.0, 0.0, 0.0]),
        Point::new([1.0, 2.0, 0.5]),
        Point::new([3.0, 1.0, 2.0]),
        Point::new([4.0, 4.0, -1.0]),
        Point::new([2.0, 5.0, 0.0]),
    ])
    .unwrap();
    let c = b.control();
    let sub = |p: &Point<f64, 3>, q: &Point<f64, 3>| [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    let d1 = sub(&c[1], &c[0]);
    let d1b = sub(&c[2], &c[1]);
    let d2 = [d1b[0] - d1[0], d1b[1] - d1[1], d1b[2] - d1[2]];
    let x = cross(d1, d2);
    let want = 3.0 / 4.0 * dot3(x, x).sqrt() / dot3(d1, d1).powf(1.5);
    let f = bezier_frenet(&b, &0.0).unwrap();
    assert!(
        close(f.curvature(), want, 1e-14),
        "{} vs {want}",
        f.curvature()
    );
}

#[test]
fn seed_003_g1_curve_is_neither_c1_nor_g2_and_splines_are_g2() {
    let p = |x: Q, y: Q| Point::new([x, y, qi(0)]);
    let c = CompositeBezier::new(
        vec![qi(-1), qi(0), q(1, 2)],
        vec![
            vec![p(qi(-1), qi(0)), p(q(-1, 2), qi(0)), p(qi(0), qi(0))],
            vec![p(qi(0), qi(0)), p(q(1, 2), qi(0)), p(qi(1), qi(1))],
        ],
    )
    .unwrap();
    let join = c.join(1, &qi(0)).unwrap();
    assert!(join.g1 && join.parametric == Some(0));
    assert!(!is_g2_join(&c, 1, &qi(0)).unwrap());
    // Right of the join α'' = (0, 8, 0), α' = (2, 0, 0): κ n = (0, 2, 0).
    let right = c.end_derivatives(1, false, 2).unwrap();
    assert_eq!(
        curvature_vector(&right[1], &right[2]).unwrap(),
        p(qi(0), qi(2))
    );
    // A C² spline is G² exactly.
    let knots = vec![qi(0), qi(1), q(5, 2), qi(4)];
    let pts: Vec<_> = [(0, 0), (1, 3), (4, 2), (5, 5)]
        .iter()
        .map(|&(x, y)| p2(qi(x), qi(y)))
        .collect();
    let s = cubic_spline(&knots, &pts, &EndCondition::Natural).unwrap();
    assert!(is_g2(&s, &qi(0)));
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
    let pts: Vec<_> = knots.iter().map(|u| par.eval(u)).collect();
    let c = quadratic_spline(&knots, &pts, &par.derivative().eval(&knots[0])).unwrap();
    for k in 0..=12 {
        let u = q(k, 4);
        assert_eq!(c.eval(&u).unwrap(), par.eval(&u));
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

#[test]
fn extreme_magnitudes_are_computed_or_rejected_cleanly() {
    // Scaling a curve by 2^k scales its curvature, torsion and curvature vector by 2^−k.
    let d = [
        Point::new([0.0, 2.0, 1.0]),
        Point::new([-2.0, 0.0, 0.0]),
        Point::new([0.0, -2.0, 0.0]),
    ];
    let f = frenet_frame(&d).unwrap();
    let kn = curvature_vector(&d[0], &d[1]).unwrap();
    for k in [-1000, -600, 600, 1000] {
        let s = 2f64.powi(k);
        let scaled: Vec<_> = d.iter().map(|p| *p * s).collect();
        let g = frenet_frame(&scaled).unwrap();
        assert_eq!(g.curvature(), f.curvature() / s, "2^{k}");
        assert_eq!(g.torsion(), f.torsion() / s, "2^{k}");
        assert_eq!(g.vectors(), f.vectors());
        assert_eq!(curvature_vector(&scaled[0], &scaled[1]).unwrap(), kn / s);
    }
    // Joins of huge and of tiny pieces are still recognised as G¹ and C¹ within a tolerance.
    for scale in [1e300, 1e-300] {
        let p = |x: f64, y: f64| Point::new([x * scale, y * scale]);
        let c = CompositeBezier::new(
            vec![0.0, 1.0, 3.0],
            vec![
                vec![p(0.0, 0.0), p(1.0, 1.0), p(2.0, 1.0)],
                vec![p(2.0, 1.0), p(4.0, 1.0), p(5.0, 3.0)],
            ],
        )
        .unwrap();
        let join = c.join(1, &1e-12).unwrap();
        assert!(join.g1 && join.parametric == Some(1), "{scale}: {join:?}");
    }
    // A spline through points near 1e300 interpolates them; one whose tangents overflow is an
    // error, not a panic or an infinite curve.
    let big: Vec<_> = [1.0, -1.5, 2.0, 0.5]
        .iter()
        .map(|&y| Point::new([y * 1e300]))
        .collect();
    let knots = [0.0, 1.0, 2.0, 3.0];
    let s = cubic_spline(&knots, &big, &EndCondition::Natural).unwrap();
    for (u, p) in knots.iter().zip(&big) {
        assert_eq!(s.eval(u).unwrap(), *p);
    }
    let tight = [0.0, 1e-300, 2e-300, 3e-300];
    let e = cubic_spline(&tight, &big, &EndCondition::Natural).unwrap_err();
    assert!(e.to_string().contains("overflow"), "{e}");
    let e = newton(&tight, &big).unwrap_err();
    assert!(e.to_string().contains("overflow"), "{e}");
}

#[cfg(feature = "cli")]
mod common;

/// The `compgeo interpolate` command against the library and the bad-input contract.
#[cfg(feature = "cli")]
mod cli {
    use super::*;
    use serde_json::Value;

    use crate::common::{assert_rejected, run_json};

    fn rational(v: &Value) -> Q {
        v.as_str().unwrap().parse().unwrap()
    }

    fn exact_points(v: &Value) -> Vec<Point<Q, 2>> {
        v.as_array()
            .unwrap()
            .iter()
            .map(|p| p2(rational(&p[0]), rational(&p[1])))
            .collect()
    }

    #[test]
    fn hermite_exact_prints_the_seed_solution_as_fractions() {
        let out = run_json(
            &[
                "interpolate",
                "hermite",
                "--points",
                "[[0,1],[5,2],[10,5],[6,9],[5,4]]",
                "--tangents",
                "[[6,12],[12,-12],[24,48],[-48,0],[48,-72]]",
                "--knots",
                r#"[0,"1/2","3/4","7/8",1]"#,
                "--exact",
            ],
            None,
        );
        let text = include_str!("fixtures/seed003_hermite_example.txt");
        let printed: Vec<Vec<Point<Q, 2>>> = text
            .lines()
            .filter(|l| l.starts_with("Tramo"))
            .map(|l| pairs(l.split_once(':').unwrap().1))
            .collect();
        let got: Vec<Vec<Point<Q, 2>>> = out["pieces"]
            .as_array()
            .unwrap()
            .iter()
            .map(exact_points)
            .collect();
        assert_eq!(got, printed);
        assert_eq!(out["knots"][1], "1/2");
    }

    #[test]
    fn spline_output_matches_the_library_in_both_arithmetics() {
        let pts = "[[0,0],[1,2],[3,1],[4,4]]";
        let knots = r#"[0,"1/3",1,"5/2"]"#;
        let lib_knots = vec![qi(0), q(1, 3), qi(1), q(5, 2)];
        let lib_pts = vec![
            p2(qi(0), qi(0)),
            p2(qi(1), qi(2)),
            p2(qi(3), qi(1)),
            p2(qi(4), qi(4)),
        ];
        for (end, condition) in [
            ("natural", EndCondition::Natural),
            ("bessel", EndCondition::Bessel),
        ] {
            let out = run_json(
                &[
                    "interpolate",
                    "spline",
                    "--points",
                    pts,
                    "--knots",
                    knots,
                    "--end",
                    end,
                    "--exact",
                ],
                None,
            );
            let want = cubic_spline(&lib_knots, &lib_pts, &condition).unwrap();
            for (piece, b) in out["pieces"].as_array().unwrap().iter().zip(want.pieces()) {
                assert_eq!(exact_points(piece), b.control());
            }
            // f64: the same numbers to rounding.
            let out = run_json(
                &[
                    "interpolate",
                    "spline",
                    "--points",
                    pts,
                    "--knots",
                    knots,
                    "--end",
                    end,
                ],
                None,
            );
            let flat: Vec<f64> = out["pieces"]
                .as_array()
                .unwrap()
                .iter()
                .flat_map(|p| p.as_array().unwrap().iter())
                .flat_map(|c| c.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
                .collect();
            let exact: Vec<f64> = want
                .pieces()
                .iter()
                .flat_map(|b| b.control().iter().flat_map(|p| p.to_f64().0))
                .collect();
            assert_eq!(flat.len(), exact.len());
            for (a, b) in flat.iter().zip(&exact) {
                assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} vs {b}");
            }
        }
        let out = run_json(
            &[
                "interpolate",
                "spline",
                "--points",
                pts,
                "--end",
                "clamped",
                "--start-tangent",
                "[1,0]",
                "--end-tangent",
                r#"["-1/2",3]"#,
                "--exact",
            ],
            None,
        );
        assert_eq!(exact_points(&out["tangents"])[3], p2(q(-1, 2), qi(3)));
    }

    #[test]
    fn newton_and_lagrange_agree_exactly() {
        let pts = r#"[[1,0],[2,"1/2"],[0,3],[5,1]]"#;
        let nodes = r#"[0,"1/2",2,3]"#;
        let at = r#"["1/3",4,-1]"#;
        let n = run_json(
            &[
                "interpolate",
                "newton",
                "--points",
                pts,
                "--nodes",
                nodes,
                "--at",
                at,
                "--exact",
            ],
            None,
        );
        let l = run_json(
            &[
                "interpolate",
                "lagrange",
                "--points",
                pts,
                "--nodes",
                nodes,
                "--at",
                at,
                "--exact",
            ],
            None,
        );
        let a = run_json(
            &[
                "interpolate",
                "lagrange",
                "--aitken",
                "--points",
                pts,
                "--nodes",
                nodes,
                "--at",
                at,
                "--exact",
            ],
            None,
        );
        assert_eq!(n["values"], l["values"]);
        assert_eq!(n["values"], a["values"]);
        assert_eq!(n["monomial"].as_array().unwrap().len(), 4);
        // The value at 1/3 from the library's Vandermonde solution.
        let v = vandermonde(
            &[qi(0), q(1, 2), qi(2), qi(3)],
            &[
                p2(qi(1), qi(0)),
                p2(qi(2), q(1, 2)),
                p2(qi(0), qi(3)),
                p2(qi(5), qi(1)),
            ],
        )
        .unwrap();
        assert_eq!(exact_points(&n["values"])[0], v.eval(&q(1, 3)));
    }

    #[test]
    fn hermite_without_tangents_uses_the_parabola_estimates() {
        let out = run_json(
            &[
                "interpolate",
                "hermite",
                "--points",
                "[[0,0],[1,2],[3,3],[4,0]]",
                "--parameterisation",
                "uniform",
                "--exact",
            ],
            None,
        );
        let pts = [(0, 0), (1, 2), (3, 3), (4, 0)].map(|(x, y)| p2(qi(x), qi(y)));
        let knots = [qi(0), qi(1), qi(2), qi(3)];
        let want = estimate_tangents(&pts, &knots).unwrap();
        assert_eq!(exact_points(&out["tangents"]), want);
        let curve = hermite(&pts, &want, &knots).unwrap();
        for (piece, b) in out["pieces"].as_array().unwrap().iter().zip(curve.pieces()) {
            assert_eq!(exact_points(piece), b.control());
        }
    }

    #[test]
    fn bad_input_exits_2_with_one_error_line() {
        let cases: [(&[&str], &str); 8] = [
            (
                &[
                    "interpolate",
                    "spline",
                    "--points",
                    "[[0,0],[1,2],[3,1]]",
                    "--knots",
                    "[0,1,1]",
                ],
                "strictly increasing",
            ),
            (
                &[
                    "interpolate",
                    "hermite",
                    "--points",
                    "[[0,0],[1,2]]",
                    "--tangents",
                    "[[1,1]]",
                ],
                "tangents",
            ),
            (
                &[
                    "interpolate",
                    "newton",
                    "--points",
                    "[1,2,3]",
                    "--nodes",
                    "[0,1,0]",
                ],
                "nodes 0 and 2 are equal",
            ),
            (
                &[
                    "interpolate",
                    "lagrange",
                    "--points",
                    "[1,2]",
                    "--nodes",
                    "[0,1,2]",
                ],
                "points",
            ),
            (
                &["interpolate", "spline", "--points", "[[0,0],[1,NaN]]"],
                "NaN",
            ),
            (
                &[
                    "interpolate",
                    "spline",
                    "--points",
                    "[[0,0],[1,2]]",
                    "--end",
                    "bessel",
                ],
                "at least 3",
            ),
            (
                &[
                    "interpolate",
                    "spline",
                    "--points",
                    "[[0,0],[1,2],[3,1]]",
                    "--end",
                    "periodic",
                ],
                "first and last",
            ),
            (
                &[
                    "interpolate",
                    "spline",
                    "--points",
                    "[[0,0],[1,2]]",
                    "--end",
                    "clamped",
                ],
                "--start-tangent",
            ),
        ];
        for (args, needle) in cases {
            let line = assert_rejected(args, None);
            assert!(line.contains(needle), "{args:?}: {line}");
        }
    }
}
