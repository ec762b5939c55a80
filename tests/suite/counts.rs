//! Exact operation counts where an algorithm fixes them, each derived in the test from the
//! algorithm's structure (a loop over the levels of a triangle, a sum over the terms of a
//! formula) rather than copied from a run: a count that drifts from its documented value
//! fails here, and so does a counter variant that stops counting.

use crate::spline_common::{q, Q};
use compgeo::count::Counts;
use compgeo::spline::{intersections_with, Bezier, Point};
use proptest::prelude::*;

/// The affine combinations of one de Casteljau triangle of degree n: n at the first level,
/// n − 1 at the second, ..., 1 at the last.
fn triangle(n: usize) -> u64 {
    (1..=n).map(|k| (n + 1 - k) as u64).sum()
}

/// A curve of degree n with small rational control points (the counts do not depend on the
/// scalar, so the exact back end also checks that nothing is counted differently there).
fn rational_curve(n: usize, seed: i64) -> Bezier<Q, 2> {
    Bezier::new(
        (0..=n as i64)
            .map(|i| Point::new([q(i, 1), q((i * 7 + seed) % 11 - 5, 3)]))
            .collect(),
    )
    .unwrap()
}

/// The parabola y = 2t(1 − t), x = t, written with degree n ≥ 2: its flatness bound
/// n(n − 1)/8 · max |Δ²bᵢ| is ½ at every degree and a quarter of it after each halving.
fn parabola(n: usize) -> Bezier<f64, 2> {
    let den = (n * (n - 1)) as f64;
    Bezier::new(
        (0..=n)
            .map(|i| Point::new([i as f64 / n as f64, (2 * i * (n - i)) as f64 / den]))
            .collect(),
    )
    .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn a_split_and_a_blossom_value_cost_one_triangle(n in 0usize..10, seed in 0i64..50, k in 0i64..=8) {
        let b = rational_curve(n, seed);
        let mut c = Counts::default();
        b.split_with(&q(k, 8), &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, triangle(n));
        let mut c = Counts::default();
        let args: Vec<Q> = (0..n as i64).map(|i| q(i + k, 5)).collect();
        b.blossom_with(&args, &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, triangle(n));
    }
}

#[test]
fn elevation_to_m_costs_one_term_per_nonzero_weight() {
    // Zhou's formula: dₖ sums the bᵢ with C(m − n, k − i) ≠ 0, i.e. 0 ≤ k − i ≤ m − n.
    for n in 0..6 {
        let b = rational_curve(n, 3);
        for m in n..n + 9 {
            let terms: u64 = (0..=m)
                .map(|k| (0..=n).filter(|&i| i <= k && k - i <= m - n).count() as u64)
                .sum();
            assert_eq!(
                terms,
                ((n + 1) * (m - n + 1)) as u64,
                "the documented closed form"
            );
            let mut c = Counts::default();
            b.elevate_to_with(m, &mut c).unwrap();
            assert_eq!(c.arithmetic_operations, terms, "n = {n}, m = {m}");
        }
    }
}

#[test]
fn flattening_costs_one_triangle_per_split() {
    // The parabola's pieces after j halvings have the bound ½·4⁻ʲ. With the tolerance 1.5
    // times that bound for j = k, the pieces are flat after exactly k halvings (after k − 1
    // the bound is 8/3 of the tolerance): 2ᵏ pieces, 2ᵏ − 1 splits of n(n + 1)/2 each.
    for n in [2, 3, 5, 8] {
        for k in 0..6u32 {
            let tolerance = 1.5 * 0.5 / 4f64.powi(k as i32);
            let mut c = Counts::default();
            let poly = parabola(n).flatten_with(&tolerance, &mut c).unwrap();
            let segments = 1u64 << k;
            assert_eq!(poly.len() as u64, segments + 1, "n = {n}, k = {k}");
            assert_eq!(c.arithmetic_operations, (segments - 1) * triangle(n));
        }
    }
    // On any curve: one split per segment but the first.
    let wavy = rational_curve(6, 1);
    let mut c = Counts::default();
    let poly = wavy.flatten_with(&q(1, 100), &mut c).unwrap();
    assert!(poly.len() > 2);
    assert_eq!(
        c.arithmetic_operations,
        (poly.len() as u64 - 2) * triangle(6)
    );
}

#[test]
fn the_intersection_search_counts_halvings_and_chord_tests() {
    // Two crossing segments are flat: no halving, one chord test of four orientations.
    let line = |a: [f64; 2], b: [f64; 2]| Bezier::new(vec![Point::new(a), Point::new(b)]).unwrap();
    let mut c = Counts::default();
    let hits = intersections_with(
        &line([0.0, 0.0], [1.0, 1.0]),
        &line([0.0, 1.0], [1.0, 0.0]),
        1e-9,
        &mut c,
    )
    .unwrap();
    assert_eq!(hits.len(), 1);
    assert_eq!((c.arithmetic_operations, c.orientation_tests), (0, 4));
    // The parabola against y = 1/4: only the parabola is ever halved (the line is flat), so
    // the count is a whole number of its triangles, and every chord test is four tests.
    let across = line([-0.25, 0.25], [1.25, 0.25]);
    for n in [2, 3, 6, 10] {
        let mut c = Counts::default();
        let hits = intersections_with(&parabola(n), &across, 1e-4, &mut c).unwrap();
        assert_eq!(hits.len(), 2, "n = {n}");
        let halvings = c.arithmetic_operations / triangle(n);
        assert_eq!(c.arithmetic_operations, halvings * triangle(n), "n = {n}");
        // Each crossing is reached through at least log₄(½ / 10⁻⁴) > 6 halvings.
        assert!(halvings >= 12, "n = {n}: {halvings} halvings");
        assert_eq!(c.orientation_tests % 4, 0);
        assert!(c.orientation_tests >= 8);
    }
}

/// Gaussian elimination on N unknowns with point right-hand sides, when no entry below a
/// pivot is zero: for column c, each of the N − 1 − c rows below changes its N − c entries
/// from column c on and its right-hand side; back substitution takes N − 1 − c terms and one
/// division for unknown c.
fn elimination(unknowns: usize) -> u64 {
    let n = unknowns as u64;
    (0..n)
        .map(|c| (n - 1 - c) * (n - c + 1) + (n - 1 - c) + 1)
        .sum()
}

/// n + 1 distinct rational nodes in a scrambled order, and points with rational coordinates.
fn rational_data(n: usize) -> (Vec<Q>, Vec<Point<Q, 2>>) {
    let nodes = (0..=n as i64)
        .map(|i| q((i * 5) % (n as i64 + 1) - 2, 3))
        .collect();
    let pts = (0..=n as i64)
        .map(|i| Point::new([q(i * i % 7, 2), q(3 - i, 5)]))
        .collect();
    (nodes, pts)
}

#[test]
fn polynomial_interpolation_counts_follow_the_schemes() {
    use compgeo::spline::{
        lagrange, newton_hermite_with, newton_with, vandermonde_with, HermiteNode,
    };
    // n + 1 = 6 coprime with 5, so the scrambled nodes are distinct.
    for n in [1usize, 2, 5, 10] {
        let (nodes, pts) = if n == 5 {
            let nodes: Vec<Q> = (0..=5).map(|i| q(i * i, 4)).collect();
            (nodes, rational_data(5).1)
        } else {
            rational_data(n)
        };
        let levels: u64 = (1..=n).map(|k| (n + 1 - k) as u64).sum();
        let mut c = Counts::default();
        lagrange(&nodes, &pts)
            .unwrap()
            .aitken_with(&q(7, 3), &mut c)
            .unwrap();
        assert_eq!(c.arithmetic_operations, levels, "Aitken, n = {n}");
        let mut c = Counts::default();
        newton_with(&nodes, &pts, &mut c).unwrap();
        assert_eq!(c.arithmetic_operations, levels, "Newton, n = {n}");
        // With exact scalars the pivot is the first nonzero entry and no entry of a
        // Vandermonde matrix with distinct nodes vanishes below it.
        let mut c = Counts::default();
        vandermonde_with(&nodes, &pts, &mut c).unwrap();
        assert_eq!(
            c.arithmetic_operations,
            elimination(n + 1),
            "Vandermonde, n = {n}"
        );
        // Confluent data: a value and a slope at each node, 2(n + 1) conditions.
        let data: Vec<HermiteNode<Q, 2>> = nodes
            .iter()
            .zip(&pts)
            .map(|(u, p)| HermiteNode {
                u: u.clone(),
                values: vec![p.clone(), p.clone()],
            })
            .collect();
        let conditions = 2 * (n + 1);
        let mut c = Counts::default();
        newton_hermite_with(&data, &mut c).unwrap();
        let table: u64 = (1..conditions).map(|j| (conditions - j) as u64).sum();
        assert_eq!(c.arithmetic_operations, table, "Newton–Hermite, n = {n}");
    }
}

#[test]
fn spline_interpolation_counts_one_operation_per_point_computed() {
    use compgeo::spline::{
        closed_quadratic_spline_with, cubic_spline_tangents_with, cubic_spline_with, hermite_with,
        quadratic_spline_with, EndCondition,
    };
    for pieces in [1usize, 2, 3, 7, 20] {
        let knots: Vec<Q> = (0..=pieces as i64).map(|i| q(i * i + i, 2)).collect();
        let pts: Vec<Point<Q, 2>> = (0..=pieces as i64)
            .map(|i| Point::new([q(i, 1), q((i * 3) % 5, 1)]))
            .collect();
        // Hermite: two inner Bézier points per piece.
        let mut c = Counts::default();
        hermite_with(&knots, &pts, &pts, &mut c).unwrap();
        assert_eq!(c.arithmetic_operations, 2 * pieces as u64);
        // Quadratic: one inner point per piece.
        let mut c = Counts::default();
        quadratic_spline_with(&knots, &pts, &pts[0], &mut c).unwrap();
        assert_eq!(c.arithmetic_operations, pieces as u64);
        // Cubic with open ends, n = pieces: per interval a difference quotient and the three
        // operations of its right-hand side (4n), the two end rows' right-hand sides (2), and
        // Thomas' algorithm on the n + 1 rows (3(n + 1) − 1): 7n + 4. Then Hermite's 2n.
        let n = pieces as u64;
        let thomas = 3 * (n + 1) - 1;
        for end in [
            EndCondition::Natural,
            EndCondition::Clamped {
                start: pts[0].clone(),
                end: pts[1].clone(),
            },
        ] {
            let mut c = Counts::default();
            cubic_spline_tangents_with(&knots, &pts, &end, &mut c).unwrap();
            assert_eq!(c.arithmetic_operations, 4 * n + 2 + thomas, "{end:?}");
            assert_eq!(c.arithmetic_operations, 7 * n + 4);
            let mut c = Counts::default();
            cubic_spline_with(&knots, &pts, &end, &mut c).unwrap();
            assert_eq!(c.arithmetic_operations, 7 * n + 4 + 2 * n);
        }
    }
    // Closed quadratic (an odd number N of pieces): the N − 1 points of the recurrence, the
    // closing equation's right-hand side, and the N inner points.
    for pieces in [3usize, 5, 9] {
        let knots: Vec<Q> = (0..=pieces as i64).map(|i| q(i, 1)).collect();
        let mut pts: Vec<Point<Q, 2>> = (0..=pieces as i64)
            .map(|i| Point::new([q(i % 4, 1), q(i * i % 5, 1)]))
            .collect();
        pts[pieces] = pts[0].clone();
        let mut c = Counts::default();
        closed_quadratic_spline_with(&knots, &pts, &mut c).unwrap();
        assert_eq!(c.arithmetic_operations, (pieces - 1 + 1 + pieces) as u64);
    }
}

#[test]
fn least_squares_counts_the_normal_equations_and_their_solve() {
    use compgeo::spline::{fit_bezier_with, FitOptions};
    for degree in [0usize, 1, 3, 6] {
        let m = 3 * (degree + 1);
        let params: Vec<Q> = (0..m as i64).map(|i| q(i, m as i64 - 1)).collect();
        let pts: Vec<Point<Q, 2>> = (0..m as i64)
            .map(|i| Point::new([q(i, 1), q(i * i % 7, 1)]))
            .collect();
        let mut c = Counts::default();
        fit_bezier_with(&params, &pts, degree, &FitOptions::default(), &mut c).unwrap();
        // Each point adds its Bernstein row's outer product (n + 1)² and n + 1 right-hand
        // sides; the Gram matrix of the Bernstein basis at distinct parameters has no zero
        // entry, so none is skipped by the elimination.
        let per_point = ((degree + 1) * (degree + 1) + degree + 1) as u64;
        assert_eq!(
            c.arithmetic_operations,
            m as u64 * per_point + elimination(degree + 1),
            "degree {degree}"
        );
    }
}

#[test]
fn b_spline_counts_follow_their_schemes() {
    use compgeo::spline::{BSpline, BandMatrix, CompositeBezier, KnotVector};
    // The basis and its derivatives: the triangular scheme's d(d + 1)/2 steps, then for
    // each order j = 1, …, K = min(k, d) the j + 1 coefficients of each of the d + 1
    // functions.
    for d in 0..7usize {
        let t = KnotVector::clamped_uniform(d, d + 4, q(0, 1), q(1, 1)).unwrap();
        for k in 0..9usize {
            let mut c = Counts::default();
            t.basis_derivatives_with(&q(2, 7), k, &mut c).unwrap();
            let orders: u64 = (1..=k.min(d)).map(|j| ((d + 1) * (j + 1)) as u64).sum();
            assert_eq!(
                c.arithmetic_operations,
                triangle(d) + orders,
                "d = {d}, k = {k}"
            );
        }
    }
    // The banded solver: below pivot k, each of the r rows with an entry in column k takes a
    // multiplier, w band entries and a right-hand side; back substitution w terms and a
    // division per row.
    for (size, lower, upper) in [(1usize, 0usize, 0usize), (5, 1, 1), (9, 2, 3), (12, 4, 1)] {
        let mut a = BandMatrix::zeros(size, lower, upper).unwrap();
        for i in 0..size {
            for j in i.saturating_sub(lower)..(i + upper + 1).min(size) {
                let v = if i == j {
                    q(20, 1)
                } else {
                    q((i + 2 * j) as i64 % 5 + 1, 3)
                };
                a.set(i, j, v).unwrap();
            }
        }
        let rhs: Vec<Point<Q, 2>> = (0..size as i64)
            .map(|i| Point::new([q(i, 1), q(1, 1)]))
            .collect();
        let mut c = Counts::default();
        a.solve_with(rhs, &mut c).unwrap();
        let want: u64 = (0..size)
            .map(|k| {
                let (r, w) = (lower.min(size - 1 - k), upper.min(size - 1 - k));
                (r * (w + 2) + w + 1) as u64
            })
            .sum();
        assert_eq!(
            c.arithmetic_operations, want,
            "{size} × {size}, l = {lower}, u = {upper}"
        );
    }
    // From p Bézier pieces of degree d ≥ 1: the first piece's d + 1 points, then d new ones
    // per piece; one check of the shared end per join.
    for (pieces, d) in [(1usize, 1usize), (3, 2), (5, 4)] {
        let points: Vec<Point<Q, 2>> = (0..=(pieces * d) as i64)
            .map(|i| Point::new([q(i, 1), q(i * i % 3, 1)]))
            .collect();
        let control = (0..pieces)
            .map(|i| points[d * i..=d * (i + 1)].to_vec())
            .collect();
        let partition = (0..=pieces as i64).map(|i| q(i, 1)).collect();
        let b = CompositeBezier::new(partition, control).unwrap();
        let mut c = Counts::default();
        let s = BSpline::from_bezier_with(&b, &mut c).unwrap();
        assert_eq!(c.moves, (d + 1 + (pieces - 1) * d) as u64);
        assert_eq!(c.moves, s.control().len() as u64);
        assert_eq!(c.comparisons, pieces as u64 - 1);
    }
}

#[test]
fn rational_counts_are_those_of_both_homogeneous_halves() {
    use compgeo::spline::{KnotVector, Nurbs, RationalBezier};
    for n in 1..7usize {
        let control: Vec<Point<Q, 2>> = (0..=n as i64)
            .map(|i| Point::new([q(i, 1), q(i % 2, 1)]))
            .collect();
        let weights: Vec<Q> = (0..=n as i64).map(|i| q(i % 3 + 1, 2)).collect();
        let r = RationalBezier::new(control.clone(), weights.clone()).unwrap();
        let mut c = Counts::default();
        r.de_casteljau_with(&q(1, 3), &mut c).unwrap();
        assert_eq!(c.arithmetic_operations, 2 * triangle(n), "n = {n}");
        // A knot inserted once inside a span of a clamped NURBS curve of degree d = n: d
        // combinations of points and d of weights (r = 1, s = 0: r(d − s) − r(r − 1)/2 = d).
        let knots = KnotVector::clamped_uniform(n, n + 1, q(0, 1), q(1, 1)).unwrap();
        let s = Nurbs::new(control, weights, knots).unwrap();
        let mut c = Counts::default();
        s.insert_with(&q(1, 3), 1, &mut c).unwrap();
        assert_eq!(c.arithmetic_operations, 2 * n as u64, "d = {n}");
    }
}

#[test]
fn beta_spline_joints_and_frenet_frames_count_their_steps() {
    use compgeo::spline::{frenet_frame_with, is_beta_continuous_with, BetaParameters, BetaSpline};
    // Every joint of a Beta-spline: β₁Q⁻′ and the two terms of β₁²Q⁻″ + β₂Q⁻′, then the three
    // comparisons of a joint that holds (exactly, with rationals).
    let p = BetaParameters::new(q(3, 2), q(1, 2)).unwrap();
    let control: Vec<Point<Q, 2>> = (0..9i64)
        .map(|i| Point::new([q(i, 1), q(i * i % 5, 2)]))
        .collect();
    let s = BetaSpline::new(p.clone(), control).unwrap();
    for i in 1..s.segments() {
        let left = s.segment_derivatives(i - 1, &q(1, 1)).unwrap();
        let right = s.segment_derivatives(i, &q(0, 1)).unwrap();
        let mut c = Counts::default();
        assert!(is_beta_continuous_with(&left, &right, &p, &mut c));
        assert_eq!((c.arithmetic_operations, c.comparisons), (3, 3));
    }
    // The Frenet frame in R³ from three independent derivatives: each is projected twice on
    // every residual before it (0 + 2 + 4), then the orientation's elimination of the 3 × 3
    // matrix of derivatives changes 2·3 + 1·2 entries (none vanishes below a pivot here).
    let d = [
        Point::new([q(1, 1), q(2, 1), q(3, 1)]),
        Point::new([q(2, 1), q(-1, 1), q(5, 1)]),
        Point::new([q(4, 1), q(3, 1), q(-2, 1)]),
    ];
    let projections: u64 = (0..3).map(|i| 2 * i).sum();
    let elimination: u64 = (0..3).map(|c| (2 - c) * (3 - c)).sum();
    let mut c = Counts::default();
    frenet_frame_with(&d, &mut c).unwrap();
    assert_eq!(c.arithmetic_operations, projections + elimination);
    // With two derivatives in R³ the frame is not full: projections only.
    let mut c = Counts::default();
    frenet_frame_with(&d[..2], &mut c).unwrap();
    assert_eq!(c.arithmetic_operations, 2);
}

#[test]
fn surface_isocurves_and_refinement_count_the_curves_they_run_on() {
    use compgeo::spline::KnotVector;
    use compgeo::surface::{BSplineSurface, ControlNet, Direction};
    // M = 6 rows and N = 7 columns, bidegree (p, q) = (2, 3), clamped uniform knots.
    let (rows, columns, p, qd) = (6usize, 7usize, 2usize, 3usize);
    let net = ControlNet::new(
        (0..rows as i64)
            .map(|i| {
                (0..columns as i64)
                    .map(|j| Point::new([q(i, 1), q(j, 1), q((i * j) % 5, 1)]))
                    .collect()
            })
            .collect(),
    )
    .unwrap();
    let s = BSplineSurface::new(
        net,
        KnotVector::clamped_uniform(p, rows, q(0, 1), q(1, 1)).unwrap(),
        KnotVector::clamped_uniform(qd, columns, q(0, 1), q(1, 1)).unwrap(),
    )
    .unwrap();
    // v fixed off the knots: de Boor on each of the M rows, q(q + 1)/2 combinations each.
    let mut c = Counts::default();
    s.isocurve_with(Direction::V, &q(1, 7), &mut c).unwrap();
    assert_eq!(c.arithmetic_operations, rows as u64 * triangle(qd));
    // u fixed off the knots: the basis in u (p(p + 1)/2 steps), then one multiply-add per
    // point of each of the p + 1 rows that matter.
    let mut c = Counts::default();
    s.isocurve_with(Direction::U, &q(1, 7), &mut c).unwrap();
    assert_eq!(
        c.arithmetic_operations,
        triangle(p) + ((p + 1) * columns) as u64
    );
    // Refinement in v by m new simple knots inside spans: q combinations per knot and row.
    let new = [q(1, 9), q(4, 9), q(8, 9)];
    let mut c = Counts::default();
    s.refine_with(Direction::V, &new, &mut c).unwrap();
    assert_eq!(c.arithmetic_operations, (rows * new.len() * qd) as u64);
}
