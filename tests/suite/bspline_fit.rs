//! B-spline interpolation and fitting, checked exactly on the rational back end against
//! independent oracles: a dense exact elimination (with row exchanges) for the banded solver,
//! for the rank of collocation matrices and so for the theorem of Schoenberg and Whitney
//! [PPB, §6.7] (the knot-based check accepts exactly when the exact basis value N_k(τ_k) is
//! non-zero, and exactly then the dense collocation matrix is invertible); the interpolant
//! through every point with `==`; the least-squares fit with as many parameters as control
//! points against the interpolant, and its residual orthogonal to every basis function
//! [PPB, §4.7]; the rank check against the dense rank; the cubic spline in B-spline form
//! against the tangent-based `cubic_spline` at random rational parameters; the parameter
//! improvement's errors never increasing [PPB, §4.8]; [PPB, §6.9, Ex. 9] (shifted data shift
//! the interpolant). Then f64 against exact on 1e300 and
//! subnormal data, and bad input as named errors.
//!
//! The course's §4.6–4.8 and §5.12 state no worked example of interpolation or fitting with
//! numbers (§4.9 and §5.12 are proofs and drawings); the hand-derived quadratic below stands
//! in for one.

// The dense oracles index rows and columns as the textbook eliminations do.
#![allow(clippy::needless_range_loop)]

use crate::bspline_basis::knot_vector;
use crate::spline_common::bspline::point;
use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{
    cubic_spline, BSpline, BandMatrix, Curve, EndCondition, KnotVector, Parameterisation, Point,
    Scalar,
};
use compgeo::Error;
use proptest::prelude::*;

/// The rank of a rational matrix by exact elimination with row exchanges.
fn dense_rank(mut a: Vec<Vec<Q>>) -> usize {
    let (rows, cols) = (a.len(), a.first().map_or(0, Vec::len));
    let mut rank = 0;
    for c in 0..cols {
        let Some(p) = (rank..rows).find(|&r| a[r][c] != qi(0)) else {
            continue;
        };
        a.swap(rank, p);
        for r in rank + 1..rows {
            let f = a[r][c].clone() / &a[rank][c];
            for k in c..cols {
                let delta = f.clone() * &a[rank][k];
                a[r][k] -= delta;
            }
        }
        rank += 1;
    }
    rank
}

/// The solution of a square invertible rational system (columns of points), by Gauss–Jordan
/// elimination with row exchanges; `None` if singular.
fn dense_solve(mut a: Vec<Vec<Q>>, mut b: Vec<Point<Q, 2>>) -> Option<Vec<Point<Q, 2>>> {
    let n = a.len();
    for c in 0..n {
        let p = (c..n).find(|&r| a[r][c] != qi(0))?;
        a.swap(c, p);
        b.swap(c, p);
        let inv = qi(1) / &a[c][c];
        for k in 0..n {
            a[c][k] = a[c][k].clone() * &inv;
        }
        b[c] = b[c].clone() * &inv;
        for r in 0..n {
            if r != c && a[r][c] != qi(0) {
                let f = a[r][c].clone();
                for k in 0..n {
                    let delta = f.clone() * &a[c][k];
                    a[r][k] -= delta;
                }
                let delta = b[c].clone() * &f;
                b[r] -= &delta;
            }
        }
    }
    Some(b)
}

/// The collocation matrix N_j(τ_k) from the exact basis.
fn collocation(t: &KnotVector<Q>, params: &[Q]) -> Vec<Vec<Q>> {
    let n = t.control_points();
    params
        .iter()
        .map(|u| {
            let b = t.basis(u).unwrap();
            (0..n).map(|j| b.get(j)).collect()
        })
        .collect()
}

/// Strictly increasing parameters of the domain of `t`, `count` of them, from 0..=48 in
/// steps of (b − a)/48 (so knots are hit often).
fn increasing_params(t: &KnotVector<Q>, count: usize) -> impl Strategy<Value = Vec<Q>> {
    let (a, b) = (t.bounds().0.clone(), t.bounds().1.clone());
    prop::sample::subsequence((0..=48i64).collect::<Vec<_>>(), count).prop_map(move |ks| {
        ks.into_iter()
            .map(|k| a.clone() + (b.clone() - &a) * q(k, 48))
            .collect()
    })
}

/// Parameters of the domain of `t` in any order, repeats allowed.
fn any_params(t: &KnotVector<Q>, count: usize) -> impl Strategy<Value = Vec<Q>> {
    let (a, b) = (t.bounds().0.clone(), t.bounds().1.clone());
    prop::collection::vec(0..=24i64, count).prop_map(move |ks| {
        ks.into_iter()
            .map(|k| a.clone() + (b.clone() - &a) * q(k, 24))
            .collect()
    })
}

/// A knot vector, n increasing parameters (n = control points) and n points.
fn collocation_case() -> impl Strategy<Value = (KnotVector<Q>, Vec<Q>, Vec<Point<Q, 2>>)> {
    knot_vector().prop_flat_map(|t| {
        let n = t.control_points();
        (
            increasing_params(&t, n),
            prop::collection::vec((-20i64..=20, -20i64..=20), n),
            Just(t),
        )
            .prop_map(|(u, p, t)| (t, u, p.into_iter().map(point).collect()))
    })
}

/// Strictly increasing rational parameters and integer points for averaged interpolation.
fn averaged_case() -> impl Strategy<Value = (usize, Vec<Q>, Vec<Point<Q, 2>>)> {
    (1usize..=4, 0usize..=6).prop_flat_map(|(d, extra)| {
        let n = d + 1 + extra;
        (
            Just(d),
            prop::collection::vec((1i64..=5, 1i64..=3), n - 1),
            prop::collection::vec((-20i64..=20, -20i64..=20), n),
        )
            .prop_map(|(d, steps, p)| {
                let mut u = vec![qi(0)];
                for (a, b) in steps {
                    let next = u[u.len() - 1].clone() + q(a, b);
                    u.push(next);
                }
                (d, u, p.into_iter().map(point).collect())
            })
    })
}

/// Σ_k N_i(τ_k)(s(τ_k) − p_k) for every i.
fn residual_products(s: &BSpline<Q, 2>, params: &[Q], points: &[Point<Q, 2>]) -> Vec<Point<Q, 2>> {
    let t = s.knots();
    let mut out = vec![Point::zero(); t.control_points()];
    for (u, p) in params.iter().zip(points) {
        let r = s.eval(u).unwrap() - p;
        let b = t.basis(u).unwrap();
        for (j, out) in out.iter_mut().enumerate() {
            *out += &(r.clone() * &b.get(j));
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_banded_solver_is_the_dense_solve(
        n in 1usize..=7,
        lower in 0usize..=3,
        upper in 0usize..=3,
        entries in prop::collection::vec(-6i64..=6, 49),
        x in prop::collection::vec((-9i64..=9, -9i64..=9), 7),
    ) {
        let mut a = BandMatrix::<Q>::zeros(n, lower, upper).unwrap();
        let mut dense = vec![vec![qi(0); n]; n];
        for i in 0..n {
            for j in 0..n {
                if j + lower >= i && j <= i + upper {
                    let v = qi(entries[i * 7 + j]);
                    a.set(i, j, v.clone()).unwrap();
                    dense[i][j] = v;
                }
            }
        }
        let x: Vec<Point<Q, 2>> = x[..n].iter().copied().map(point).collect();
        let b: Vec<Point<Q, 2>> = (0..n)
            .map(|i| {
                let mut s = Point::zero();
                for j in 0..n {
                    s += &(x[j].clone() * &dense[i][j]);
                }
                s
            })
            .collect();
        let mut c = Counts::default();
        match a.solve_with(b.clone(), &mut c) {
            Ok(got) => {
                prop_assert_eq!(&Some(got.clone()), &dense_solve(dense.clone(), b));
                prop_assert_eq!(got, x);
                let want: u64 = (0..n)
                    .map(|k| {
                        let (r, w) = (lower.min(n - 1 - k), upper.min(n - 1 - k));
                        (r * (w + 2) + w + 1) as u64
                    })
                    .sum();
                prop_assert_eq!(c.arithmetic_operations, want);
            }
            Err(e) => {
                // A zero pivot k: the leading principal minor of order k + 1 is singular.
                let msg = e.to_string();
                let k: usize = msg
                    .split("pivot ")
                    .nth(1)
                    .and_then(|s| s.split(' ').next())
                    .and_then(|s| s.parse().ok())
                    .unwrap_or_else(|| panic!("{msg}"));
                let minor: Vec<Vec<Q>> = dense[..=k].iter().map(|r| r[..=k].to_vec()).collect();
                prop_assert!(dense_rank(minor) <= k, "{}", msg);
            }
        }
    }

    #[test]
    fn schoenberg_whitney_is_the_exact_basis_and_the_invertibility((t, u, p) in collocation_case()) {
        let nonzero = (0..u.len()).all(|k| t.basis(&u[k]).unwrap().get(k) != qi(0));
        let n = u.len();
        let invertible = dense_rank(collocation(&t, &u)) == n;
        // The theorem of Schoenberg and Whitney, on the exact basis.
        prop_assert_eq!(nonzero, invertible);
        let checked = t.check_schoenberg_whitney(&u);
        prop_assert_eq!(checked.is_ok(), nonzero, "{:?}", checked);
        match BSpline::interpolate_at(&p, &u, t.clone()) {
            Ok(s) => {
                prop_assert!(nonzero);
                for (uk, pk) in u.iter().zip(&p) {
                    prop_assert_eq!(&s.eval(uk).unwrap(), pk);
                }
            }
            Err(e) => {
                prop_assert!(!nonzero);
                let k = (0..n).find(|&k| t.basis(&u[k]).unwrap().get(k) == qi(0)).unwrap();
                let msg = e.to_string();
                let index = format!("fails at index {k}: N_{k}(τ_{k}) = 0");
                prop_assert!(msg.contains(&index), "{}", msg);
            }
        }
    }

    #[test]
    fn interpolating_shifted_points_shifts_the_interpolant(
        (d, u, p) in averaged_case(),
        (hx, hy) in (-9i64..=9, -9i64..=9),
    ) {
        // [PPB, §6.9, Ex. 9]: the rows of the collocation matrix sum to one (the parameters
        // lie in the domain), so the spline through pᵢ + h is s + h: every control point
        // moves by h, exactly.
        let t = KnotVector::averaged(d, &u).unwrap();
        let h: Point<Q, 2> = point((hx, hy));
        let shifted: Vec<Point<Q, 2>> = p.iter().map(|pk| pk.clone() + &h).collect();
        let s = BSpline::interpolate_at(&p, &u, t.clone()).unwrap();
        let sh = BSpline::interpolate_at(&shifted, &u, t).unwrap();
        for (a, b) in s.control().iter().zip(sh.control()) {
            prop_assert_eq!(a.clone() + &h, b.clone());
        }
    }

    #[test]
    fn the_averaged_interpolant_passes_through_every_point((d, u, p) in averaged_case()) {
        let t = KnotVector::averaged(d, &u).unwrap();
        let mut c = Counts::default();
        let s = BSpline::interpolate_at_with(&p, &u, t, &mut c).unwrap();
        for (uk, pk) in u.iter().zip(&p) {
            prop_assert_eq!(&s.eval(uk).unwrap(), pk);
        }
        let n = u.len();
        let solve: u64 = (0..n)
            .map(|k| {
                let w = d.min(n - 1 - k);
                (w * (w + 2) + w + 1) as u64
            })
            .sum();
        prop_assert_eq!(c.arithmetic_operations, (n * d * (d + 1) / 2) as u64 + solve);
        // Uniform parameters give the same as explicit ones 0, 1, …, n − 1.
        let uniform = BSpline::interpolate(&p, d, Parameterisation::Uniform).unwrap();
        let ints: Vec<Q> = (0..n as i64).map(qi).collect();
        for (k, pk) in p.iter().enumerate() {
            prop_assert_eq!(&uniform.eval(&ints[k]).unwrap(), pk);
        }
    }

    #[test]
    fn least_squares_with_one_parameter_per_control_point_is_interpolation(
        (t, u, p) in collocation_case()
    ) {
        if let Ok(s) = BSpline::interpolate_at(&p, &u, t.clone()) {
            let f = BSpline::fit(&p, &u, t).unwrap();
            prop_assert_eq!(f, s);
        }
    }

    #[test]
    fn the_rank_check_is_the_rank_and_the_residual_is_orthogonal(
        (t, u, p) in knot_vector().prop_flat_map(|t| {
            let n = t.control_points();
            (n..=n + 6).prop_flat_map(move |m| {
                (
                    Just(t.clone()),
                    any_params(&t, m),
                    prop::collection::vec((-20i64..=20, -20i64..=20), m),
                )
            })
        })
    ) {
        let p: Vec<Point<Q, 2>> = p.into_iter().map(point).collect();
        let n = t.control_points();
        let full = dense_rank(collocation(&t, &u)) == n;
        let checked = t.check_fit_rank(&u);
        prop_assert_eq!(checked.is_ok(), full, "{:?}", checked);
        match BSpline::fit(&p, &u, t) {
            Ok(s) => {
                prop_assert!(full);
                for r in residual_products(&s, &u, &p) {
                    prop_assert_eq!(r, Point::zero());
                }
            }
            Err(e) => {
                prop_assert!(!full);
                prop_assert!(e.to_string().contains("has too little data"), "{}", e);
            }
        }
    }

    #[test]
    fn the_b_spline_cubic_is_the_cubic_spline(
        steps in prop::collection::vec((1i64..=5, 1i64..=3), 1..=6),
        p in prop::collection::vec((-20i64..=20, -20i64..=20), 7),
        tangents in ((-9i64..=9, -9i64..=9), (-9i64..=9, -9i64..=9)),
        kind in 0usize..3,
        samples in prop::collection::vec(0i64..=97, 8),
    ) {
        let mut u = vec![qi(0)];
        for (a, b) in steps {
            let next = u[u.len() - 1].clone() + q(a, b);
            u.push(next);
        }
        let p: Vec<Point<Q, 2>> = p[..u.len()].iter().copied().map(point).collect();
        let end = match kind {
            0 => EndCondition::Natural,
            1 => EndCondition::Clamped { start: point(tangents.0), end: point(tangents.1) },
            _ => EndCondition::Bessel,
        };
        if kind == 2 && u.len() < 3 {
            let few = matches!(
                BSpline::cubic_spline(&p, &u, &end),
                Err(Error::TooFew { needed: 3, .. })
            );
            prop_assert!(few);
            return Ok(());
        }
        let s = BSpline::cubic_spline(&p, &u, &end).unwrap();
        let c = cubic_spline(&u, &p, &end).unwrap();
        let last = u[u.len() - 1].clone();
        let mut at: Vec<Q> = samples.iter().map(|k| last.clone() * q(*k, 97)).collect();
        at.extend(u.iter().cloned());
        for x in &at {
            prop_assert_eq!(s.eval(x).unwrap(), c.eval(x).unwrap(), "at {}", x);
        }
    }
}

#[test]
fn parameter_improvement_never_increases_the_error_exactly() {
    // Points of the parabola y = x² at parameters x² (a poor guess), fitted by a quadratic
    // with one interior knot; one exact round.
    let xs = [0, 1, 2, 3, 4, 5, 6].map(|k| q(k, 6));
    let p: Vec<Point<Q, 2>> = xs
        .iter()
        .map(|x| Point::new([x.clone(), x.clone() * x]))
        .collect();
    let u: Vec<Q> = xs.iter().map(|x| x.clone() * x).collect();
    let t = KnotVector::new(2, [0, 0, 0, 1, 2, 2, 2].map(|k| q(k, 2)).to_vec()).unwrap();
    let f = BSpline::fit_improved(&p, &u, t, 1).unwrap();
    assert_eq!(f.errors.len(), 2);
    assert!(f.errors[1] < f.errors[0], "{:?}", f.errors);
    // The errors are those of the curve at the parameters returned.
    let mut e = qi(0);
    for (uk, pk) in f.params.iter().zip(&p) {
        e += (f.curve.eval(uk).unwrap() - pk).norm_squared();
    }
    assert_eq!(e, f.errors[1]);
}

#[test]
fn parameter_improvement_in_f64_decreases_and_stays_in_the_domain() {
    let p: Vec<Point<f64, 2>> = (0..=20)
        .map(|k| {
            let a = std::f64::consts::PI * (k as f64 / 20.0).powi(2);
            Point::new([a.cos(), a.sin()])
        })
        .collect();
    let u: Vec<f64> = (0..=20).map(|k| k as f64 / 20.0).collect();
    let t = KnotVector::clamped_uniform(3, 6, 0.0, 1.0).unwrap();
    let f = BSpline::fit_improved(&p, &u, t, 10).unwrap();
    assert!(f.errors.windows(2).all(|w| w[1] <= w[0]), "{:?}", f.errors);
    assert!(
        f.errors[f.errors.len() - 1] < 0.5 * f.errors[0],
        "{:?}",
        f.errors
    );
    assert!(f.params.iter().all(|u| (0.0..=1.0).contains(u)));
}

/// A worked example derived by hand: the quadratic Bézier interpolant at 0, 1/2, 1 has
/// c₁ = 2 p(1/2) − (p₀ + p₂)/2, since N₁(1/2) = 1/2 and N₀(1/2) = N₂(1/2) = 1/4.
#[test]
fn the_quadratic_through_three_points_by_hand() {
    let p = [(0, 0), (2, 3), (4, 1)].map(point::<Q>);
    let t = KnotVector::clamped_uniform(2, 3, qi(0), qi(1)).unwrap();
    let s = BSpline::interpolate_at(&p, &[qi(0), q(1, 2), qi(1)], t).unwrap();
    let c1 = p[1].clone() * qi(2) - &((p[0].clone() + &p[2]) / qi(2));
    assert_eq!(s.control(), [p[0].clone(), c1, p[2].clone()]);
    assert_eq!(s.control()[1], Point::new([qi(2), q(11, 2)]));
}

#[test]
fn huge_and_subnormal_data_give_the_exact_result_closely() {
    let tiny = f64::from_bits(1);
    for scale in [1e300, 1.0, 1e-310, tiny * 64.0] {
        let raw = [
            (0.0, 1.0),
            (2.0, 3.0),
            (3.0, -1.0),
            (5.0, 2.0),
            (6.0, 0.0),
            (8.0, 1.0),
        ];
        let p: Vec<Point<f64, 2>> = raw
            .iter()
            .map(|&(x, y)| Point::new([x * scale, y * scale]))
            .collect();
        let pq: Vec<Point<Q, 2>> = p.iter().map(|x| Point::from_f64(x).unwrap()).collect();
        let u: Vec<f64> = (0..6).map(|k| k as f64).collect();
        let uq: Vec<Q> = u.iter().map(|x| Q::from_f64(*x).unwrap()).collect();
        let t = KnotVector::averaged(3, &u).unwrap();
        let tq = KnotVector::averaged(3, &uq).unwrap();
        let s = BSpline::interpolate_at(&p, &u, t.clone()).unwrap();
        let sq = BSpline::interpolate_at(&pq, &uq, tq.clone()).unwrap();
        let fitted = BSpline::fit(&p, &u, t).unwrap();
        let big = p
            .iter()
            .flat_map(|x| x.coords().iter().map(|c| c.abs()))
            .fold(0.0, f64::max);
        // Subnormal data keep only their few significant bits.
        let rel = if scale < 1e-300 { 1e-1 } else { 1e-13 };
        for (a, b) in [(&s, &sq), (&fitted, &sq)] {
            for (x, y) in a.control().iter().zip(b.control()) {
                for k in 0..2 {
                    let want = y[k].to_f64();
                    assert!(x[k].is_finite(), "{scale}: {x:?}");
                    assert!(
                        (x[k] - want).abs() <= rel * big,
                        "{scale}: {} vs {want}",
                        x[k]
                    );
                }
            }
        }
        for (uk, pk) in u.iter().zip(&p) {
            let got = s.eval(uk).unwrap();
            for k in 0..2 {
                assert!(
                    (got[k] - pk[k]).abs() <= rel * big,
                    "{scale}: {got:?} vs {pk:?}"
                );
            }
        }
    }
    // Near the top of the range a control point of the interpolant is beyond it: an error.
    let p = [(0.0, 0.0), (f64::MAX, 0.0), (0.0, 0.0)].map(|(x, y)| Point::new([x, y]));
    let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0).unwrap();
    let e = BSpline::interpolate_at(&p, &[0.0, 0.5, 1.0], t).unwrap_err();
    assert!(matches!(e, Error::Overflow { .. }), "{e}");
}

#[test]
fn schoenberg_whitney_failures_name_the_index_the_inequality_and_the_knots() {
    let t = KnotVector::new(2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]).unwrap();
    let p = [[0.0], [1.0], [2.0], [3.0], [4.0]].map(Point::new);
    // τ₁ = 2.5 is past N₁'s support [t₁, t₄] = [0, 2].
    let e = BSpline::interpolate_at(&p, &[0.0, 2.5, 2.75, 2.9, 3.0], t.clone()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid params: the Schoenberg–Whitney condition fails at index 1: N_1(τ_1) = 0 for \
         τ_1 = 2.5; it needs t_1 < τ_1 < t_4 (t_1 = 0, t_4 = 2), but τ_1 > t_4"
    );
    // τ₃ = 1 = t₃, a simple knot: N₃ starts there and vanishes.
    let e = BSpline::interpolate_at(&p, &[0.0, 0.25, 0.5, 1.0, 3.0], t.clone()).unwrap_err();
    assert!(
        e.to_string().contains("index 3: N_3(τ_3) = 0 for τ_3 = 1"),
        "{e}"
    );
    assert!(
        e.to_string()
            .contains("but τ_3 = t_3, allowed only where t_3 = t_5"),
        "{e}"
    );
    // The clamped ends are allowed: τ₀ = t₀ and τ₄ = t₅.
    assert!(t
        .check_schoenberg_whitney(&[0.0, 0.5, 1.5, 2.5, 3.0])
        .is_ok());
    // At an unclamped end the last function does not end: N₂ on 0, 1, …, 5 (domain [2, 3],
    // support [2, 5]) is non-zero at t₃ = 3, N₀ (support [0, 3]) vanishes there.
    let u = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0]).unwrap();
    assert!(u.check_schoenberg_whitney(&[2.0, 2.5, 3.0]).is_ok());
    // On 0, 1, …, 6 (domain [2, 4]) N₀ (support [0, 3]) vanishes at 3.
    let u = KnotVector::new(2, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
    let e = u
        .check_schoenberg_whitney(&[3.0, 3.25, 3.5, 4.0])
        .unwrap_err();
    assert!(
        e.to_string().contains("index 0: N_0(τ_0) = 0 for τ_0 = 3"),
        "{e}"
    );
    assert!(
        e.to_string()
            .contains("but τ_0 = t_3, allowed only at the end"),
        "{e}"
    );
}

#[test]
fn repeated_parameters_are_named_by_both_indices_never_nan() {
    let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0).unwrap();
    let p = [[0.0], [1.0], [2.0], [3.0]].map(Point::new);
    let e = BSpline::interpolate_at(&p, &[0.0, 0.5, 0.5, 1.0], t.clone()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "invalid params: parameters 1 and 2 are equal (0.5): two rows of the collocation \
         matrix would be equal"
    );
    // A chord too short to move the running sum of chord lengths in f64: equal parameters.
    let p = [(0.0, 0.0), (1e17, 0.0), (1e17, 4.0), (2e17, 4.0)].map(|(x, y)| Point::new([x, y]));
    let e = BSpline::interpolate(&p, 2, Parameterisation::ChordLength).unwrap_err();
    assert!(
        e.to_string().contains("parameters 1 and 2 are equal"),
        "{e}"
    );
    // Consecutive equal points under chord length: named by parameterise.
    let p = [(0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (2.0, 0.0)].map(|(x, y)| Point::new([x, y]));
    let e = BSpline::interpolate(&p, 2, Parameterisation::ChordLength).unwrap_err();
    assert!(e.to_string().contains("points 1 and 2 coincide"), "{e}");
    // Least squares takes repeated parameters: they weigh their points more, no NaN.
    let u = [0.0, 0.0, 0.25, 0.5, 0.5, 0.75, 1.0, 1.0];
    let v: Vec<Point<f64, 1>> = u.iter().map(|&x| Point::new([3.0 * x * x - x])).collect();
    let s = BSpline::fit(&v, &u, t).unwrap();
    assert!(s.control().iter().all(|c| c[0].is_finite()));
    // A quadratic is in the space: recovered.
    for (x, want) in u.iter().zip(&v) {
        assert!((s.eval(x).unwrap()[0] - want[0]).abs() < 1e-12);
    }
}

#[test]
fn bad_input_is_a_named_error() {
    let t = KnotVector::clamped_uniform(2, 4, 0.0, 1.0).unwrap();
    let p = [[0.0], [1.0], [2.0], [3.0]].map(Point::new);
    let nan = [[0.0], [f64::NAN], [2.0], [3.0]].map(Point::new);
    assert!(matches!(
        BSpline::interpolate_at(&nan, &[0.0, 0.25, 0.5, 1.0], t.clone()),
        Err(Error::NonFinite { index: 1, .. })
    ));
    assert!(matches!(
        BSpline::fit(&nan, &[0.0, 0.25, 0.5, 1.0], t.clone()),
        Err(Error::NonFinite { index: 1, .. })
    ));
    let e = BSpline::interpolate_at(&p, &[0.0, f64::NAN, 0.5, 1.0], t.clone()).unwrap_err();
    assert!(
        e.to_string().contains("parameter 1 is not finite (NaN)"),
        "{e}"
    );
    let e = BSpline::fit(&p, &[0.0, 0.25, 0.5, 1.5], t.clone()).unwrap_err();
    assert!(
        e.to_string()
            .contains("parameter 3 (1.5) is outside the domain [0, 1]"),
        "{e}"
    );
    let e = BSpline::interpolate_at(&p, &[0.0, 0.5, 0.25, 1.0], t.clone()).unwrap_err();
    assert!(
        e.to_string()
            .contains("parameter 2 (0.25) is below parameter 1"),
        "{e}"
    );
    let e = BSpline::interpolate_at(&p[..3], &[0.0, 0.5, 1.0], t.clone()).unwrap_err();
    assert!(
        matches!(e, Error::InvalidParameter { name: "knots", .. }),
        "{e}"
    );
    let e = BSpline::interpolate_at(&p, &[0.0, 0.5, 1.0], t.clone()).unwrap_err();
    assert!(e.to_string().contains("3 parameters for 4 points"), "{e}");
    // Too few points: for the degree, and for the control points of a fit.
    assert!(matches!(
        BSpline::interpolate(&p[..2], 2, Parameterisation::Uniform),
        Err(Error::TooFew {
            needed: 3,
            got: 2,
            ..
        })
    ));
    let e = BSpline::fit(&p[..3], &[0.0, 0.5, 1.0], t.clone()).unwrap_err();
    // N₀ ← 0, N₁ ← 0.5, and 1 is the closed end, where only N₃ is non-zero.
    assert!(
        e.to_string()
            .contains("N_2 (support [t_2, t_5] = [0, 1]) has too little data"),
        "{e}"
    );
    let empty: [Point<f64, 1>; 0] = [];
    assert!(matches!(
        BSpline::fit(&empty, &[], t),
        Err(Error::Empty { .. })
    ));
    assert!(matches!(
        BSpline::cubic_spline(&p, &[0.0, 1.0, 2.0, 3.0], &EndCondition::Periodic),
        Err(Error::InvalidParameter { name: "end", .. })
    ));
    assert!(matches!(
        BSpline::cubic_spline(&p, &[0.0, 1.0, 1.0, 3.0], &EndCondition::Natural),
        Err(Error::InvalidParameter {
            name: "partition",
            ..
        })
    ));
}
