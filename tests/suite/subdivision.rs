//! Uniform subdivision against its oracles, exactly in rationals: k rounds of the
//! Lane–Riesenfeld algorithm are the control polygon of the same uniform B-spline on the
//! 2^k-refined knots and their limit points are that spline's points (both checked with
//! `BSpline` at dyadic parameters); the masks are the scaled binomial coefficients; the
//! four-point scheme interpolates and, for w = 1/16, maps a cubic's integer samples to its
//! half-integer samples; the difference schemes of [PPB, §8.8, §8.10] (with the factor the
//! course loses); bad input gets named errors.
#![cfg(feature = "exact")]

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::subdivision::{
    chaikin, four_point, four_point_with, lane_riesenfeld, lane_riesenfeld_with, limit_points,
    limit_stencil, Mask, Topology,
};
use compgeo::spline::{BSpline, Curve, KnotVector, Point};
use compgeo::Error;
use num_bigint::BigInt;
use proptest::prelude::*;

type P2 = Point<Q, 2>;

fn pt(x: i64, y: i64) -> P2 {
    Point::new([qi(x), qi(y)])
}

/// A deterministic polygon of n lattice points, irregular enough that no coincidence hides a
/// wrong index.
fn polygon(n: usize, seed: i64) -> Vec<P2> {
    (0..n as i64)
        .map(|i| pt((i * 7 + seed * 3) % 11 - 5, (i * i * 5 + seed) % 13 - 6))
        .collect()
}

/// The uniform spline Σ c_j N^d(u − j) on the knots 0, …, n + d (domain [d, n]).
fn open_spline(c: &[P2], d: usize) -> BSpline<Q, 2> {
    let knots = (0..=(c.len() + d) as i64).map(qi).collect();
    BSpline::new(c.to_vec(), KnotVector::new(d, knots).unwrap()).unwrap()
}

/// The periodic spline Σ_{j∈ℤ} c_{j mod n} N^d(scale·u − j) as a B-spline whose domain
/// [d/scale, extra/scale + n/scale·…] covers [d, n + 2d + 2] of the unscaled parameter.
fn periodic_spline(c: &[P2], d: usize, scale: i64) -> BSpline<Q, 2> {
    let n = c.len();
    let wrap = (2 * d + 2) * scale as usize;
    let control: Vec<P2> = (0..n + wrap).map(|i| c[i % n].clone()).collect();
    let knots = (0..=(n + wrap + d) as i64).map(|j| q(j, scale)).collect();
    BSpline::new(control, KnotVector::new(d, knots).unwrap()).unwrap()
}

/// The dyadic parameters a, a + 2^{−e}, …, b.
fn dyadic(a: i64, b: i64, e: u32) -> Vec<Q> {
    let step = 1i64 << e;
    (a * step..=b * step).map(|j| q(j, step)).collect()
}

fn binomial(n: u64, k: u64) -> BigInt {
    (0..k).fold(BigInt::from(1), |acc, i| acc * (n - i) / (i + 1))
}

#[test]
fn lane_riesenfeld_masks_are_scaled_binomials() {
    for d in 1..=12usize {
        let m = Mask::<Q>::lane_riesenfeld(d).unwrap();
        assert_eq!((m.start(), m.end()), (0, d as i64 + 1));
        let scale = BigInt::from(1) << d;
        for i in 0..=d + 1 {
            let expected = Q::new(binomial(d as u64 + 1, i as u64), scale.clone());
            assert_eq!(m.coefficient(i as i64), expected, "d = {d}, i = {i}");
        }
        // The algorithm run on a unit impulse prints its own mask: b_i = α_i.
        let mut impulse = vec![Point::new([qi(0)]); d + 4];
        impulse[0] = Point::new([qi(1)]);
        let b = lane_riesenfeld(&impulse, d, 1, Topology::Closed).unwrap();
        for (i, bi) in b.iter().enumerate() {
            assert_eq!(bi[0], m.coefficient(i as i64), "d = {d}, impulse entry {i}");
        }
    }
    assert_eq!(
        Mask::<Q>::lane_riesenfeld(2).unwrap().coefficients(),
        [q(1, 4), q(3, 4), q(3, 4), q(1, 4)]
    );
}

#[test]
fn open_rounds_are_the_control_polygon_on_the_refined_knots() {
    for d in 1..=5usize {
        for n in [d + 1, d + 3, 9] {
            let c = polygon(n, d as i64);
            let s = open_spline(&c, d);
            for k in 0..=3u32 {
                let b = lane_riesenfeld(&c, d, k as usize, Topology::Open).unwrap();
                let scale = 1i64 << k;
                assert_eq!(b.len(), scale as usize * (n - d) + d);
                // b_l is the coefficient of N^d(2^k u − l − d(2^k − 1)).
                let offset = d as i64 * (scale - 1);
                let knots = (0..=(b.len() + d) as i64)
                    .map(|j| q(j + offset, scale))
                    .collect();
                let r = BSpline::new(b.clone(), KnotVector::new(d, knots).unwrap()).unwrap();
                assert_eq!(r.knots().bounds(), s.knots().bounds(), "d = {d}, k = {k}");
                // Eight samples a refined span: two splines of degree ≤ 5 that agree there
                // are equal, so b is the spline's control polygon on the refined knots.
                for u in dyadic(d as i64, n as i64, k + 3) {
                    assert_eq!(
                        r.eval(&u).unwrap(),
                        s.eval(&u).unwrap(),
                        "d={d} k={k} u={u}"
                    );
                }
                // The limit point of vertex l is s at the centre of its B-spline.
                let h = d / 2;
                let limits = limit_points(&b, d, Topology::Open).unwrap();
                assert_eq!(limits.len(), b.len() - 2 * h);
                for (t, lp) in limits.iter().enumerate() {
                    let l = (t + h) as i64;
                    let u = q(2 * (l + offset) + d as i64 + 1, 2 * scale);
                    assert_eq!(*lp, s.eval(&u).unwrap(), "d={d} k={k} vertex {l}");
                }
            }
        }
    }
}

#[test]
fn closed_rounds_are_the_periodic_spline_on_the_refined_knots() {
    for d in 1..=5usize {
        for n in [3, 4, 7] {
            let c = polygon(n, 2 * d as i64 + 1);
            let s = periodic_spline(&c, d, 1);
            for k in 0..=3u32 {
                let b = lane_riesenfeld(&c, d, k as usize, Topology::Closed).unwrap();
                let scale = 1i64 << k;
                assert_eq!(b.len(), n << k);
                let r = periodic_spline(&b, d, scale);
                for u in dyadic(d as i64, (n + d) as i64, k + 3) {
                    assert_eq!(
                        r.eval(&u).unwrap(),
                        s.eval(&u).unwrap(),
                        "d={d} k={k} u={u}"
                    );
                }
                let limits = limit_points(&b, d, Topology::Closed).unwrap();
                assert_eq!(limits.len(), b.len());
                for (l, lp) in limits.iter().enumerate() {
                    let mut u = q(2 * l as i64 + d as i64 + 1, 2 * scale);
                    while u < qi(d as i64) {
                        u += qi(n as i64);
                    }
                    assert_eq!(*lp, s.eval(&u).unwrap(), "d={d} k={k} vertex {l}");
                }
            }
        }
    }
}

#[test]
fn the_closed_forms_of_the_limit_points() {
    assert_eq!(
        limit_stencil::<Q>(3).unwrap().coefficients(),
        [q(1, 6), q(4, 6), q(1, 6)]
    );
    assert_eq!(
        limit_stencil::<Q>(2).unwrap().coefficients(),
        [q(1, 8), q(6, 8), q(1, 8)]
    );
    assert_eq!(limit_stencil::<Q>(1).unwrap().coefficients(), [qi(1)]);
    for d in 1..=10 {
        let m = limit_stencil::<Q>(d).unwrap();
        let h = (d / 2) as i64;
        assert_eq!((m.start(), m.end()), (-h, h));
        let sum: Q = m.coefficients().iter().cloned().sum();
        assert_eq!(sum, qi(1), "degree {d}");
        let c = m.coefficients();
        assert!(c.iter().eq(c.iter().rev()), "degree {d} is symmetric");
    }
    // The cubic limit of a vertex: (p₋₁ + 4p₀ + p₁)/6.
    let p = polygon(5, 4);
    let l = limit_points(&p, 3, Topology::Closed).unwrap();
    for i in 0..5 {
        let expected =
            (p[(i + 4) % 5].clone() + &(p[i].clone() * qi(4)) + &p[(i + 1) % 5]) / q(6, 1);
        assert_eq!(l[i], expected);
    }
}

#[test]
fn chaikin_is_degree_two_and_cuts_corners_at_a_quarter() {
    let p = polygon(6, 1);
    for topology in [Topology::Open, Topology::Closed] {
        assert_eq!(
            chaikin(&p, 2, topology).unwrap(),
            lane_riesenfeld(&p, 2, 2, topology).unwrap()
        );
    }
    let b = chaikin(&p, 1, Topology::Open).unwrap();
    assert_eq!(b.len(), 2 * 6 - 2);
    for i in 0..5 {
        let quarter = |t: Q| p[i].clone() + &((p[i + 1].clone() - &p[i]) * t);
        assert_eq!(b[2 * i], quarter(q(1, 4)));
        assert_eq!(b[2 * i + 1], quarter(q(3, 4)));
    }
}

/// A cubic of the plane with small integer coefficients, and its value at u.
fn cubic(coefficients: [[i64; 4]; 2], u: &Q) -> P2 {
    let eval = |a: [i64; 4]| a.iter().rev().fold(qi(0), |acc, &x| acc * u + qi(x));
    Point::new([eval(coefficients[0]), eval(coefficients[1])])
}

#[test]
fn the_four_point_scheme_with_one_sixteenth_reproduces_cubics() {
    let w = q(1, 16);
    let coefficients = [[3, -2, 5, -1], [-4, 1, 0, 2]];
    for n in 4..=9usize {
        let samples: Vec<P2> = (0..n as i64).map(|i| cubic(coefficients, &qi(i))).collect();
        for k in 1..=3u32 {
            let b = four_point(&samples, &w, k as usize, Topology::Open).unwrap();
            let expected: Vec<P2> = dyadic(0, n as i64 - 1, k)
                .iter()
                .map(|u| cubic(coefficients, u))
                .collect();
            assert_eq!(b, expected, "n = {n}, k = {k}");
        }
    }
    // Closed: away from the seam, where the stencil does not wrap, the same holds.
    let n = 10;
    let samples: Vec<P2> = (0..n).map(|i| cubic(coefficients, &qi(i))).collect();
    let b = four_point(&samples, &w, 1, Topology::Closed).unwrap();
    for i in 1..=(n - 3) {
        assert_eq!(b[2 * i as usize + 1], cubic(coefficients, &q(2 * i + 1, 2)));
    }
    // Any other tension misses a cubic (but not a line: every tension reproduces lines).
    let b = four_point(&samples, &q(1, 8), 1, Topology::Closed).unwrap();
    assert_ne!(b[5], cubic(coefficients, &q(5, 2)));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn the_four_point_scheme_interpolates_and_is_its_mask(
        coords in prop::collection::vec((-20i64..20, -20i64..20), 4..12),
        w in (-8i64..8, 1i64..32),
        rounds in 1usize..3,
    ) {
        let p: Vec<P2> = coords.iter().map(|&(x, y)| pt(x, y)).collect();
        let w = q(w.0, w.1);
        let mask = Mask::four_point(&w).unwrap();
        for topology in [Topology::Open, Topology::Closed] {
            let b = four_point(&p, &w, rounds, topology).unwrap();
            let step = 1 << rounds;
            let kept: Vec<P2> = b.iter().step_by(step).cloned().collect();
            prop_assert_eq!(&kept, &p);
            let expected = match topology {
                Topology::Open => (p.len() - 1) * step + 1,
                Topology::Closed => p.len() * step,
            };
            prop_assert_eq!(b.len(), expected);
            if topology == Topology::Closed {
                prop_assert_eq!(&b, &mask.refine(&p, topology, rounds).unwrap());
            }
        }
        // Lines are reproduced for every tension, ends included.
        let line: Vec<P2> = (0..p.len() as i64).map(|i| pt(3 * i - 2, 5 - i)).collect();
        let b = four_point(&line, &w, rounds, Topology::Open).unwrap();
        let step = q(1, 1 << rounds);
        for (j, v) in b.iter().enumerate() {
            let u = step.clone() * qi(j as i64);
            prop_assert_eq!(v, &Point::new([qi(3) * &u - qi(2), qi(5) - u]));
        }
    }

    #[test]
    fn lane_riesenfeld_is_its_mask_and_counts_its_midpoints(
        coords in prop::collection::vec((-20i64..20, -20i64..20), 7..14),
        d in 1usize..6,
        rounds in 0usize..3,
    ) {
        let p: Vec<P2> = coords.iter().map(|&(x, y)| pt(x, y)).collect();
        let mask = Mask::lane_riesenfeld(d).unwrap();
        for topology in [Topology::Open, Topology::Closed] {
            let mut counts = Counts::default();
            let b = lane_riesenfeld_with(&p, d, rounds, topology, &mut counts).unwrap();
            prop_assert_eq!(&b, &mask.refine(&p, topology, rounds).unwrap());
            // 2dm per round on a closed polygon of m vertices, 2dm − d(d + 1)/2 on an open one.
            let (mut m, mut expected) = (p.len() as u64, 0u64);
            let d = d as u64;
            for _ in 0..rounds {
                match topology {
                    Topology::Closed => {
                        expected += 2 * d * m;
                        m *= 2;
                    }
                    Topology::Open => {
                        expected += 2 * d * m - d * (d + 1) / 2;
                        m = 2 * m - d;
                    }
                }
            }
            prop_assert_eq!(counts.arithmetic_operations, expected);
            prop_assert_eq!(b.len() as u64, m);
        }
    }

    #[test]
    fn one_plus_z_times_the_difference_scheme_is_the_mask(
        beta in prop::collection::vec((-9i64..10, 1i64..9), 1..10),
        start in -5i64..5,
    ) {
        let beta: Vec<Q> = beta.iter().map(|&(a, b)| q(a, b)).collect();
        prop_assume!(!beta[0].is_zero_value() && !beta[beta.len() - 1].is_zero_value());
        let mut alpha = vec![qi(0); beta.len() + 1];
        for (k, b) in beta.iter().enumerate() {
            alpha[k] += b;
            alpha[k + 1] += b;
        }
        let mask = Mask::new(start, alpha).unwrap();
        let difference = mask.difference().unwrap();
        prop_assert_eq!(difference, Mask::new(start, beta.clone()).unwrap());
        let doubled: Vec<Q> = beta.iter().map(|b| b.clone() * qi(2)).collect();
        prop_assert_eq!(mask.divided_difference().unwrap(), Mask::new(start, doubled).unwrap());
    }
}

/// `is_zero` for the proptest filter without importing the trait's name twice.
trait IsZeroValue {
    fn is_zero_value(&self) -> bool;
}

impl IsZeroValue for Q {
    fn is_zero_value(&self) -> bool {
        *self == qi(0)
    }
}

#[test]
fn lane_riesenfeld_differences_are_half_the_lower_degree() {
    // [PPB, §8.8, Obs. 5]: the difference scheme of S_d is ½ S_{d−1}.
    for d in 2..=10 {
        let beta = Mask::<Q>::lane_riesenfeld(d).unwrap().difference().unwrap();
        let lower = Mask::<Q>::lane_riesenfeld(d - 1).unwrap();
        let half: Vec<Q> = lower
            .coefficients()
            .iter()
            .map(|a| a.clone() * q(1, 2))
            .collect();
        assert_eq!(beta, Mask::new(0, half).unwrap(), "degree {d}");
        assert_eq!(beta.norm(), lower.norm() * q(1, 2));
    }
}

#[test]
fn the_four_point_analysis_of_the_course_with_its_erratum() {
    for (a, b) in [(1, 16), (1, 8), (-1, 10), (3, 20), (1, 5)] {
        let w = q(a, b);
        let alpha = Mask::four_point(&w).unwrap();
        // [PPB, §8.10]'s α(z) = −w + (½ + w)z² + z³ + (½ + w)z⁴ − wz⁶ is z³ times ours.
        let half_w = q(1, 2) + &w;
        let course = Mask::new(
            0,
            vec![
                -w.clone(),
                qi(0),
                half_w.clone(),
                qi(1),
                half_w,
                qi(0),
                -w.clone(),
            ],
        )
        .unwrap();
        assert_eq!(course.coefficients(), alpha.coefficients());
        assert_eq!(course.start(), alpha.start() + 3);
        // β(z) = −w + wz + ½z² + ½z³ + wz⁴ − wz⁵, as printed.
        let beta = alpha.difference().unwrap();
        let printed_beta = [
            -w.clone(),
            w.clone(),
            q(1, 2),
            q(1, 2),
            w.clone(),
            -w.clone(),
        ];
        assert_eq!(beta.coefficients(), printed_beta);
        // ‖β‖ = ½ + 2|w|: below 1, so the polygons converge, exactly when |w| < ¼.
        let abs_w = if w < qi(0) { -w.clone() } else { w.clone() };
        assert_eq!(beta.norm(), q(1, 2) + abs_w * qi(2));
        // The course prints γ = 2β/(1 + z) as −w + 2wz + (½ − 2w)z² + 2wz³ − wz⁴: those are
        // the coefficients of β/(1 + z); 2β/(1 + z) is twice them.
        let printed_gamma = [
            -w.clone(),
            w.clone() * qi(2),
            q(1, 2) - w.clone() * qi(2),
            w.clone() * qi(2),
            -w.clone(),
        ];
        assert_eq!(beta.difference().unwrap().coefficients(), printed_gamma);
        let gamma = alpha.divided_difference().unwrap().difference().unwrap();
        let doubled: Vec<Q> = printed_gamma.iter().map(|g| g.clone() * qi(2)).collect();
        assert_eq!(gamma.coefficients(), doubled);
    }
}

#[test]
fn bad_parameters_and_short_polygons_are_named_errors() {
    let p = polygon(6, 0);
    let invalid = |e: Error, name: &str| match e {
        Error::InvalidParameter { name: got, .. } => assert_eq!(got, name),
        other => panic!("expected invalid {name}, got {other:?}"),
    };
    invalid(
        lane_riesenfeld(&p, 0, 1, Topology::Open).unwrap_err(),
        "degree",
    );
    invalid(limit_points(&p, 0, Topology::Open).unwrap_err(), "degree");
    invalid(Mask::<Q>::lane_riesenfeld(0).unwrap_err(), "degree");
    let pf: Vec<Point<f64, 2>> = (0..6).map(|i| Point::new([i as f64, 0.0])).collect();
    for w in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        invalid(
            four_point(&pf, &w, 1, Topology::Open).unwrap_err(),
            "tension",
        );
        invalid(Mask::four_point(&w).unwrap_err(), "tension");
    }
    invalid(Mask::new(0, vec![1.0, f64::NAN]).unwrap_err(), "mask");
    invalid(Mask::<Q>::new(0, vec![qi(0), qi(0)]).unwrap_err(), "mask");
    let e = Mask::new(0, vec![qi(1), qi(1), qi(1)])
        .unwrap()
        .difference()
        .unwrap_err();
    assert!(e.to_string().contains("α(−1) ≠ 0"), "{e}");

    let too_few = |e: Error, needed: usize, got: usize| {
        assert!(
            matches!(e, Error::TooFew { needed: n, got: g, .. } if n == needed && g == got),
            "expected too few ({needed}, {got}), got {e:?}"
        );
    };
    too_few(
        lane_riesenfeld(&p[..3], 3, 1, Topology::Open).unwrap_err(),
        4,
        3,
    );
    too_few(
        lane_riesenfeld(&p[..2], 1, 1, Topology::Closed).unwrap_err(),
        3,
        2,
    );
    too_few(
        four_point(&p[..3], &q(1, 16), 1, Topology::Open).unwrap_err(),
        4,
        3,
    );
    too_few(
        four_point(&p[..2], &q(1, 16), 1, Topology::Closed).unwrap_err(),
        3,
        2,
    );
    too_few(limit_points(&p[..4], 4, Topology::Open).unwrap_err(), 5, 4);
    let four = Mask::four_point(&q(1, 16)).unwrap();
    too_few(four.refine(&p[..5], Topology::Open, 1).unwrap_err(), 6, 5);
    assert!(matches!(
        lane_riesenfeld::<Q, 2>(&[], 2, 1, Topology::Closed),
        Err(Error::Empty { .. })
    ));
    let mut bad = pf.clone();
    bad[4][1] = f64::NAN;
    assert!(matches!(
        chaikin(&bad, 1, Topology::Open),
        Err(Error::NonFinite { index: 4, .. })
    ));
    // An absurd number of rounds is refused before anything is allocated, and at once.
    for rounds in [30, 1000, usize::MAX] {
        for e in [
            lane_riesenfeld(&pf, 3, rounds, Topology::Open).unwrap_err(),
            four_point(&pf, &0.0625, rounds, Topology::Closed).unwrap_err(),
            Mask::lane_riesenfeld(2)
                .unwrap()
                .refine(&pf, Topology::Open, rounds)
                .unwrap_err(),
        ] {
            assert!(
                matches!(
                    e,
                    Error::LimitExceeded {
                        limit: "MAX_SUBDIVISION_POINTS",
                        ..
                    }
                ),
                "{e:?}"
            );
        }
    }
    // The largest round that fits is allowed: 6·2^21 < 2^24 < 6·2^22.
    let mut counts = Counts::default();
    let line: Vec<Point<f64, 1>> = (0..6).map(|i| Point::new([i as f64])).collect();
    let big = four_point_with(&line, &0.0, 21, Topology::Closed, &mut counts).unwrap();
    assert_eq!(big.len(), 6 << 21);
    assert!(four_point(&line, &0.0, 22, Topology::Closed).is_err());
}

#[test]
fn f64_overflow_is_reported() {
    let m = f64::MAX;
    let p: Vec<Point<f64, 1>> = [m, -m, m, -m, m].map(|x| Point::new([x])).to_vec();
    assert!(matches!(
        four_point(&p, &0.0625, 1, Topology::Closed),
        Err(Error::Overflow { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn random_open_polygons_refine_to_the_same_spline(
        coords in prop::collection::vec((-30i64..30, -30i64..30), 6..10),
        d in 1usize..5,
        rounds in 1u32..3,
    ) {
        let c: Vec<P2> = coords.iter().map(|&(x, y)| pt(x, y)).collect();
        let s = open_spline(&c, d);
        let b = lane_riesenfeld(&c, d, rounds as usize, Topology::Open).unwrap();
        let scale = 1i64 << rounds;
        let offset = d as i64 * (scale - 1);
        let knots = (0..=(b.len() + d) as i64).map(|j| q(j + offset, scale)).collect();
        let r = BSpline::new(b, KnotVector::new(d, knots).unwrap()).unwrap();
        for u in dyadic(d as i64, c.len() as i64, rounds + 3) {
            prop_assert_eq!(r.eval(&u).unwrap(), s.eval(&u).unwrap());
        }
    }

    #[test]
    fn f64_agrees_with_exact_where_every_step_is_exact(
        coords in prop::collection::vec((-1000i64..1000, -1000i64..1000), 5..12),
        d in 1usize..5,
        rounds in 0usize..4,
        closed in any::<bool>(),
    ) {
        // Small integers halved a few times stay exact in f64, so both back ends must agree.
        let topology = if closed { Topology::Closed } else { Topology::Open };
        let exact: Vec<P2> = coords.iter().map(|&(x, y)| pt(x, y)).collect();
        let float: Vec<Point<f64, 2>> =
            coords.iter().map(|&(x, y)| Point::new([x as f64, y as f64])).collect();
        let to_q = |v: Vec<Point<f64, 2>>| -> Vec<P2> {
            v.iter().map(|p| Point::from_f64(p).unwrap()).collect()
        };
        prop_assert_eq!(
            to_q(lane_riesenfeld(&float, d, rounds, topology).unwrap()),
            lane_riesenfeld(&exact, d, rounds, topology).unwrap()
        );
        prop_assert_eq!(
            to_q(four_point(&float, &0.0625, rounds, topology).unwrap()),
            four_point(&exact, &q(1, 16), rounds, topology).unwrap()
        );
        prop_assert_eq!(
            to_q(limit_points(&float, 2, topology).unwrap()),
            limit_points(&exact, 2, topology).unwrap()
        );
    }
}
