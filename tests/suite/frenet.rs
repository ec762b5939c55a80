//! Frenet frames, curvature and torsion against analytic curves and the course texts' formulas, the
//! exact curvature vector and G² checks, and extreme magnitudes (every finite `f64` is valid
//! input: scaling a curve by a power of two scales its curvatures exactly).
#![cfg(feature = "exact")]

use crate::spline_common::{p2, q, qi, Q};
use compgeo::spline::{
    bezier_frenet, cubic_spline, curvature_vector, frenet_frame, is_g2, is_g2_join, newton, Bezier,
    CompositeBezier, Curve, CurveDerivative, EndCondition, Point,
};
use compgeo::Error;
use proptest::prelude::*;

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
fn nearly_dependent_derivatives_still_give_an_orthonormal_frame() {
    // x'' ≈ −2 x' here; one classical Gram–Schmidt pass left the frame 1e-8 off orthogonal.
    let b = Bezier::new(vec![
        Point::new([-1.0, 15.0, 3.0]),
        Point::new([0.0, 0.0, 0.0]),
        Point::new([0.0, 1.0, 0.0]),
        Point::new([-1.0, 0.0, 3.0]),
    ])
    .unwrap();
    let v: Vec<[f64; 3]> = bezier_frenet(&b, &0.0)
        .unwrap()
        .vectors()
        .iter()
        .map(|p| p.0)
        .collect();
    assert_eq!(v.len(), 3);
    for i in 0..3 {
        for j in 0..3 {
            let want = if i == j { 1.0 } else { 0.0 };
            assert!(
                (dot3(v[i], v[j]) - want).abs() < 1e-12,
                "{i} {j}: {}",
                dot3(v[i], v[j])
            );
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
    // On the line the frame is the unit tangent, whichever way the curve runs.
    let back = frenet_frame(&[Point::new([-3.0]), Point::new([5.0])]).unwrap();
    assert_eq!(
        (back.tangent(), back.curvatures()),
        (Point::new([-1.0]), &[][..])
    );
}

#[test]
fn bezier_end_curvature_matches_the_seeds_formula() {
    // [PPB, §4.4, Obs. 8]: κ at b_0 is (n − 1)/n ‖Δb_0 × Δ²b_0‖ / ‖Δb_0‖³.
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

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

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
}
