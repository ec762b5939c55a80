//! Cubic Beta-splines, checked exactly on the rational back end: the seed's printed
//! subdivision matrices (fixture with provenance), the seed's printed C with γ read as 1/δ,
//! β₁ = 1, β₂ = 0 against the uniform cubic B-spline of the B-spline module, the pieces
//! S_L·P and S_R·P against the curve on [0, c] and [c, 1], eq. (7)–(8) against Lemma 1 and
//! against matrices solved here from basis values, the convex-hull predicate against the
//! signs of those independently solved matrices, convergence of recursive subdivision by a
//! stated factor, the β-continuity of consecutive segments (and the curvature vector it
//! implies), and the errors of bad parameters and short polygons.

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::{
    curvature_vector, is_beta_continuous, BSpline, BetaParameters, BetaSpline, Curve, KnotVector,
    Matrix4, Point, Scalar,
};
use compgeo::Error;
use num_traits::Signed;
use proptest::prelude::*;

/// |x|, named apart from the two traits that both offer `abs`.
trait AbsValue {
    fn abs_value(&self) -> Self;
}

impl AbsValue for Q {
    fn abs_value(&self) -> Q {
        Signed::abs(self)
    }
}

// ---------------------------------------------------------------------------------------
// Oracles written here, independent of the library's elimination and matrix code.

/// Solves A·X = B for 4 × 4 rational matrices by Gauss–Jordan elimination (first nonzero
/// pivot); `None` if A is singular.
fn solve(a: &Matrix4<Q>, b: &Matrix4<Q>) -> Option<Matrix4<Q>> {
    let mut a = a.clone();
    let mut b = b.clone();
    for col in 0..4 {
        let p = (col..4).find(|&r| !a[r][col].is_zero())?;
        a.swap(col, p);
        b.swap(col, p);
        let pivot = a[col][col].clone();
        for j in 0..4 {
            a[col][j] = a[col][j].clone() / &pivot;
            b[col][j] = b[col][j].clone() / &pivot;
        }
        for r in 0..4 {
            if r != col && !a[r][col].is_zero() {
                let f = a[r][col].clone();
                for j in 0..4 {
                    let (ac, bc) = (a[col][j].clone(), b[col][j].clone());
                    a[r][j] -= f.clone() * ac;
                    b[r][j] -= f.clone() * bc;
                }
            }
        }
    }
    Some(b)
}

fn product(a: &Matrix4<Q>, b: &Matrix4<Q>) -> Matrix4<Q> {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).map(|k| a[i][k].clone() * &b[k][j]).sum())
    })
}

fn identity() -> Matrix4<Q> {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { qi(1) } else { qi(0) }))
}

/// The basis written out from its definition (Barsky's formulas, before expansion), divided by
/// δ computed here: independent of the library's coefficient table.
fn basis_by_definition(b1: &Q, b2: &Q, t: &Q) -> [Q; 4] {
    let one = qi(1);
    let (t2, t3) = (t.clone() * t, t.clone() * t * t);
    let s = one.clone() - t;
    let delta = qi(2) * b1 * b1 * b1 + qi(4) * b1 * b1 + qi(4) * b1 + b2 + qi(2);
    let b0 = qi(2) * b1 * b1 * b1 * &s * &s * &s;
    let bb1 = qi(2) * b1 * b1 * b1 * t * (t2.clone() - qi(3) * t + qi(3))
        + qi(2) * b1 * b1 * (t3.clone() - qi(3) * &t2 + qi(2))
        + qi(2) * b1 * (t3.clone() - qi(3) * t + qi(2))
        + b2.clone() * (qi(2) * &t3 - qi(3) * &t2 + qi(1));
    let bb2 = qi(2) * b1 * b1 * &t2 * (qi(3) - t)
        + qi(2) * b1 * t * (qi(3) - &t2)
        + b2.clone() * &t2 * (qi(3) - qi(2) * t)
        + qi(2) * (qi(1) - &t3);
    let bb3 = qi(2) * &t3;
    [b0, bb1, bb2, bb3].map(|x| x / &delta)
}

/// Σⱼ wⱼ Pⱼ.
fn combine(w: &[Q; 4], p: &[Point<Q, 2>; 4]) -> Point<Q, 2> {
    let mut out = Point::zero();
    for (wj, pj) in w.iter().zip(p) {
        out += &(pj.clone() * wj);
    }
    out
}

/// S_L and S_R solved here from basis values at the nodes T = 0, 1/3, 2/3, 1 (Lemma 1 with
/// this file's own elimination).
fn solved_matrices(p: &BetaParameters<Q>, c: &Q) -> (Matrix4<Q>, Matrix4<Q>) {
    let nodes = [qi(0), q(1, 3), q(2, 3), qi(1)];
    let rows = |f: &dyn Fn(&Q) -> Q| -> Matrix4<Q> {
        std::array::from_fn(|i| basis_by_definition(p.beta1(), p.beta2(), &f(&nodes[i])))
    };
    let at = rows(&|t| t.clone());
    let left = rows(&|t| c.clone() * t);
    let right = rows(&|t| c.clone() + (qi(1) - c) * t);
    (solve(&at, &left).unwrap(), solve(&at, &right).unwrap())
}

// ---------------------------------------------------------------------------------------
// The seed's printed matrices.

/// One entry of a printed matrix: `\frac{a}{b}`, `-\frac{a}{b}` or an integer.
fn entry(text: &str) -> Q {
    let t = text.trim();
    let (negative, t) = match t.strip_prefix('-') {
        Some(rest) => (true, rest.trim()),
        None => (false, t),
    };
    let value = match t.strip_prefix("\\frac{") {
        Some(rest) => {
            let (num, rest) = rest.split_once("}{").unwrap();
            let den = rest.strip_suffix('}').unwrap();
            q(num.parse().unwrap(), den.parse().unwrap())
        }
        None => qi(t.parse().unwrap()),
    };
    if negative {
        -value
    } else {
        value
    }
}

/// The matrices of one printed line: each `\begin{pmatrix} … \end{pmatrix}`.
fn matrices(line: &str) -> Vec<Matrix4<Q>> {
    line.split("\\begin{pmatrix}")
        .skip(1)
        .map(|m| {
            let body = m.split("\\end{pmatrix}").next().unwrap();
            let rows: Vec<Vec<Q>> = body
                .split("\\\\")
                .map(|r| r.split('&').map(entry).collect())
                .collect();
            assert_eq!(rows.len(), 4, "{body}");
            std::array::from_fn(|i| {
                assert_eq!(rows[i].len(), 4, "{body}");
                std::array::from_fn(|j| rows[i][j].clone())
            })
        })
        .collect()
}

/// The examples of the fixture: (β₁, β₂, c) from each `Matrices[b1,b2,c]` call and the two
/// printed matrices after it.
pub fn printed_examples() -> Vec<([Q; 3], Matrix4<Q>, Matrix4<Q>)> {
    let text = include_str!("../fixtures/seed004_beta_subdivision_matrices.txt");
    let mut params: Option<[Q; 3]> = None;
    let mut out = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        // The first call is typeset as `\text{Matrices}[1,0,1/2]`.
        let line = line.replace("Matrices}[", "Matrices[");
        let line = line.as_str();
        if let Some(start) = line.find("Matrices[") {
            let inner = &line[start + 9..];
            let inner = &inner[..inner.find(']').unwrap()];
            let v: Vec<Q> = inner
                .split(',')
                .map(|x| x.trim().parse().unwrap())
                .collect();
            params = Some([v[0].clone(), v[1].clone(), v[2].clone()]);
        }
        if line.starts_with("$$\\begin{pmatrix}") {
            let m = matrices(line);
            assert_eq!(m.len(), 2, "{line}");
            out.push((params.take().unwrap(), m[0].clone(), m[1].clone()));
        }
    }
    out
}

#[test]
fn the_seeds_printed_matrices_are_reproduced_exactly() {
    let examples = printed_examples();
    let betas: Vec<Q> = examples.iter().map(|e| e.0[1].clone()).collect();
    assert_eq!(betas, [qi(0), qi(5), qi(-10)]);
    for ([b1, b2, c], left, right) in examples {
        assert_eq!((b1.clone(), c.clone()), (qi(1), q(1, 2)));
        let p = BetaParameters::allowing_negative_tension(b1.clone(), b2.clone()).unwrap();
        let m = p.subdivision_matrices(&c).unwrap();
        assert_eq!(m.left(), &left, "S_L, β₂ = {b2}");
        assert_eq!(m.right(), &right, "S_R, β₂ = {b2}");
        // The seed's convex-hull remarks: only β₂ = 0 keeps both polygons in the hull.
        assert_eq!(m.keeps_convex_hull(), b2.is_zero(), "β₂ = {b2}");
        // The f64 path agrees to rounding.
        let m64 = p.to_f64().unwrap().subdivision_matrices(&0.5).unwrap();
        for (a, b) in m64.left().iter().flatten().zip(left.iter().flatten()) {
            assert!((a - b.to_f64()).abs() < 1e-13, "{a} vs {b}");
        }
        // Barsky's range: the default constructor refuses the negative tension.
        assert_eq!(
            BetaParameters::new(b1, b2.clone()).is_ok(),
            !b2.is_negative()
        );
    }
}

#[test]
fn c_is_the_seeds_printed_matrix_with_gamma_read_as_one_over_delta() {
    for (b1, b2) in [
        (qi(1), qi(0)),
        (q(3, 2), q(7, 5)),
        (q(1, 4), qi(9)),
        (qi(3), qi(0)),
    ] {
        let p = BetaParameters::new(b1.clone(), b2.clone()).unwrap();
        let g = qi(1) / p.delta();
        let (b1sq, b1cu) = (b1.clone() * &b1, b1.clone() * &b1 * &b1);
        // The seed's C, line 305 of 004, entry by entry.
        let printed: Matrix4<Q> = [
            [
                qi(2) * &g * &b1cu,
                g.clone() * (b2.clone() + qi(4) * &b1sq + qi(4) * &b1),
                qi(2) * &g,
                qi(0),
            ],
            [
                qi(0),
                g.clone() * (qi(2) * &b1cu + qi(2) * &b1 + &b2 + qi(4) * &b1sq),
                g.clone() * (qi(2) * &b1 + qi(2)),
                qi(0),
            ],
            [
                qi(0),
                g.clone() * (qi(2) * &b1cu + qi(2) * &b1sq),
                g.clone() * (b2.clone() + qi(2) * &b1sq + qi(4) * &b1 + qi(2)),
                qi(0),
            ],
            [
                qi(0),
                qi(2) * &g * &b1cu,
                g.clone() * (b2.clone() + qi(4) * &b1 + qi(4) * &b1sq),
                qi(2) * &g,
            ],
        ];
        assert_eq!(p.bernstein_matrix(), printed);
        assert_eq!(
            product(
                &p.bernstein_matrix(),
                &p.bernstein_matrix_inverse().unwrap()
            ),
            identity()
        );
    }
}

#[test]
fn beta_1_beta_0_is_the_uniform_cubic_b_spline() {
    let pts: Vec<Point<Q, 2>> = [(0, 0), (2, 5), (3, -1), (7, 4), (8, 8), (11, 2), (12, 9)]
        .iter()
        .map(|&(x, y)| Point::new([qi(x), qi(y)]))
        .collect();
    let n = pts.len();
    let m = (n - 3) as i64;
    let beta = BetaSpline::new(BetaParameters::new(qi(1), qi(0)).unwrap(), pts.clone()).unwrap();
    let knots = KnotVector::uniform(3, n, qi(0), qi(m)).unwrap();
    let bspline = BSpline::new(pts, knots).unwrap();
    for k in 0..=8 * m {
        let u = q(k, 8);
        assert_eq!(beta.eval(&u).unwrap(), bspline.eval(&u).unwrap(), "u = {u}");
    }
    // The basis itself: the uniform B-spline's (1 − t)³/6, …, t³/6 at a few t.
    for t in [q(0, 1), q(1, 3), q(5, 7), qi(1)] {
        let s = qi(1) - &t;
        let want = [
            s.clone() * &s * &s / qi(6),
            (qi(3) * &t * &t * &t - qi(6) * &t * &t + qi(4)) / qi(6),
            (qi(-3) * &t * &t * &t + qi(3) * &t * &t + qi(3) * &t + qi(1)) / qi(6),
            t.clone() * &t * &t / qi(6),
        ];
        let p = BetaParameters::new(qi(1), qi(0)).unwrap();
        assert_eq!(p.basis(&t).unwrap(), want);
    }
}

// ---------------------------------------------------------------------------------------
// Properties over random rational parameters.

fn rational(lo: i64, hi: i64, den: i64) -> impl Strategy<Value = Q> {
    (lo * den..=hi * den).prop_map(move |n| q(n, den))
}

/// β₁ in (0, 4], β₂ in [0, 8], in steps of 1/16 and 1/8.
fn parameters() -> impl Strategy<Value = BetaParameters<Q>> {
    (1i64..=64, 0i64..=64).prop_map(|(a, b)| BetaParameters::new(q(a, 16), q(b, 8)).unwrap())
}

/// c in (0, 1).
fn split_parameter() -> impl Strategy<Value = Q> {
    (1i64..=30).prop_map(|n| q(n, 31))
}

fn point() -> impl Strategy<Value = Point<Q, 2>> {
    (rational(-8, 8, 4), rational(-8, 8, 4)).prop_map(|(x, y)| Point::new([x, y]))
}

fn polygon() -> impl Strategy<Value = [Point<Q, 2>; 4]> {
    [point(), point(), point(), point()]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The basis sums to one and is the definition's; b(t)·C = B(t).
    #[test]
    fn the_basis_is_its_definition_and_c_its_bernstein_form(
        p in parameters(),
        t in rational(-1, 2, 7),
    ) {
        let b = p.basis(&t).unwrap();
        prop_assert_eq!(&b, &basis_by_definition(p.beta1(), p.beta2(), &t));
        prop_assert_eq!(b.iter().cloned().sum::<Q>(), qi(1));
        let s = qi(1) - &t;
        let bern = [
            s.clone() * &s * &s,
            qi(3) * &t * &s * &s,
            qi(3) * &t * &t * &s,
            t.clone() * &t * &t,
        ];
        let c = p.bernstein_matrix();
        let via_c: [Q; 4] =
            std::array::from_fn(|j| (0..4).map(|i| bern[i].clone() * &c[i][j]).sum());
        prop_assert_eq!(via_c, b);
    }

    /// L = S_L·P and R = S_R·P are the curve on [0, c] and [c, 1], reparametrised, exactly;
    /// eq. (7)–(8) equal Lemma 1 (library) and the matrices solved here.
    #[test]
    fn the_pieces_are_the_curve_on_both_sides_of_c(
        p in parameters(),
        c in split_parameter(),
        poly in polygon(),
        s in rational(0, 1, 9),
    ) {
        let m = p.subdivision_matrices(&c).unwrap();
        let (l, r) = m.split(&poly);
        let at = |poly: &[Point<Q, 2>; 4], t: &Q| {
            combine(&basis_by_definition(p.beta1(), p.beta2(), t), poly)
        };
        prop_assert_eq!(at(&l, &s), at(&poly, &(c.clone() * &s)));
        prop_assert_eq!(at(&r, &s), at(&poly, &(c.clone() + (qi(1) - &c) * &s)));
        let (left, right) = solved_matrices(&p, &c);
        prop_assert_eq!(m.left(), &left);
        prop_assert_eq!(m.right(), &right);
        let nodes = [q(1, 5), qi(1), qi(0), q(1, 2)];
        prop_assert_eq!(&p.subdivision_matrices_by_interpolation(&c, &nodes).unwrap(), &m);
        for row in m.left().iter().chain(m.right()) {
            prop_assert_eq!(row.iter().cloned().sum::<Q>(), qi(1)); // Lemma 3
        }
    }

    /// The convex-hull predicate is the sign test of the matrices solved here from basis
    /// samples, and the subdivided points of the simplex are then inside it (barycentric
    /// coordinates non-negative) exactly when the predicate says so.
    #[test]
    fn the_convex_hull_predicate_agrees_with_the_sampled_basis(
        p in parameters(),
        c in split_parameter(),
    ) {
        let m = p.subdivision_matrices(&c).unwrap();
        let (left, right) = solved_matrices(&p, &c);
        let nonnegative = |a: &Matrix4<Q>| a.iter().flatten().all(|x| !x.is_negative());
        prop_assert_eq!(m.left_keeps_convex_hull(), nonnegative(&left));
        prop_assert_eq!(m.right_keeps_convex_hull(), nonnegative(&right));
        prop_assert_eq!(m.keeps_convex_hull(), nonnegative(&left) && nonnegative(&right));
        // Subdivide the standard simplex of R³ (0, e₁, e₂, e₃): point i of L is in it iff
        // its coordinates are ≥ 0 and sum to at most one.
        let simplex = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
            .map(|v| Point::new(v.map(qi)));
        let (l, r) = m.split(&simplex);
        let inside = |pts: &[Point<Q, 3>; 4]| {
            pts.iter().all(|x| {
                x.coords().iter().all(|c| !c.is_negative())
                    && x.coords().iter().cloned().sum::<Q>() <= qi(1)
            })
        };
        prop_assert_eq!(inside(&l), m.left_keeps_convex_hull());
        prop_assert_eq!(inside(&r), m.right_keeps_convex_hull());
    }

    /// The seed: with β₁ = 1 and c = ½, every positive tension puts negative entries in S_L.
    #[test]
    fn positive_tension_loses_the_convex_hull_at_the_midpoint(b2 in 1i64..=400) {
        let p = BetaParameters::new(qi(1), q(b2, 8)).unwrap();
        prop_assert!(!p.subdivision_matrices(&q(1, 2)).unwrap().left_keeps_convex_hull());
    }

    /// S_R is the reversal of S_L for β₁ = 1 and c = ½, and not otherwise in general (the
    /// erratum): with β₁ ≠ 1 they differ.
    #[test]
    fn s_r_is_the_reversal_of_s_l_only_for_unit_bias(p in parameters()) {
        let m = p.subdivision_matrices(&q(1, 2)).unwrap();
        let reversed: Matrix4<Q> =
            std::array::from_fn(|i| std::array::from_fn(|j| m.left()[3 - i][3 - j].clone()));
        prop_assert_eq!(m.right() == &reversed, *p.beta1() == qi(1));
    }

    /// Consecutive segments meet with β-continuity, a moved point breaks it, and a join that
    /// passes has equal curvature vectors from both sides (G²).
    #[test]
    fn consecutive_segments_are_beta_continuous(
        p in parameters(),
        poly in polygon(),
        extra in point(),
        nudge in point(),
    ) {
        let mut pts = poly.to_vec();
        pts.push(extra);
        let s = BetaSpline::new(p.clone(), pts.clone()).unwrap();
        let left = s.segment_derivatives(0, &qi(1)).unwrap();
        let right = s.segment_derivatives(1, &qi(0)).unwrap();
        prop_assert!(is_beta_continuous(&left, &right, &p));
        if !left[1].norm_squared().is_zero() {
            prop_assert_eq!(
                curvature_vector(&left[1], &left[2]).unwrap(),
                curvature_vector(&right[1], &right[2]).unwrap()
            );
        }
        let a = BetaSpline::new(p.clone(), pts[..4].to_vec()).unwrap();
        let b = BetaSpline::new(p.clone(), pts[1..].to_vec()).unwrap();
        prop_assert!(a.joins_beta_continuously(&b).unwrap());
        if !nudge.norm_squared().is_zero() {
            let mut moved = pts[1..].to_vec();
            moved[3] = moved[3].clone() + &nudge;
            let b = BetaSpline::new(p.clone(), moved).unwrap();
            // The last point only enters the second segment's start through B₃(0) = 0 and
            // its derivatives, B₃′(0) = 0 and B₃″(0) = 0: the join is unchanged.
            prop_assert!(a.joins_beta_continuously(&b).unwrap());
            let mut moved = pts[1..].to_vec();
            moved[0] = moved[0].clone() + &nudge;
            let b = BetaSpline::new(p, moved).unwrap();
            prop_assert!(!a.joins_beta_continuously(&b).unwrap());
        }
    }
}

// ---------------------------------------------------------------------------------------
// Convergence of recursive subdivision.

/// Max-norm of a point.
fn norm(p: &Point<Q, 2>) -> Q {
    p.coords().iter().map(|c| c.abs_value()).max().unwrap()
}

/// The basis's coefficients ξ, ζ, η of s, s², s³ (Σⱼ Bⱼ(s)·ξⱼ = s, …), solved here from
/// basis values at four nodes.
fn dual_coefficients(p: &BetaParameters<Q>) -> [[Q; 4]; 3] {
    let nodes = [qi(0), q(1, 3), q(2, 3), qi(1)];
    let a: Matrix4<Q> =
        std::array::from_fn(|i| basis_by_definition(p.beta1(), p.beta2(), &nodes[i]));
    // Right-hand sides: column k holds the nodes to the power k + 1 (last column unused).
    let b: Matrix4<Q> = std::array::from_fn(|i| {
        let t = &nodes[i];
        [t.clone(), t.clone() * t, t.clone() * t * t, qi(0)]
    });
    let x = solve(&a, &b).unwrap();
    std::array::from_fn(|k| std::array::from_fn(|j| x[j][k].clone()))
}

/// The distance of a piece's polygon to its curve: maxⱼ |Lⱼ − q(ξⱼ)|∞, q the piece's curve.
fn distance(p: &BetaParameters<Q>, xi: &[Q; 4], poly: &[Point<Q, 2>; 4]) -> Q {
    poly.iter()
        .zip(xi)
        .map(|(l, x)| {
            norm(&(l.clone() - &combine(&basis_by_definition(p.beta1(), p.beta2(), x), poly)))
        })
        .max()
        .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// A quadratic curve (control points from three random Bézier-form coefficients): the
    /// distance falls by exactly c² on left pieces and (1 − c)² on right ones, so by
    /// exactly 4 per round at c = ½.
    #[test]
    fn subdivision_of_a_quadratic_converges_by_exactly_four_per_round(
        p in parameters(),
        a in point(), b in point(), cq in point(),
    ) {
        // The curve a + b s + c s²: its control points are a + b ξⱼ + c ζⱼ.
        let [xi, zeta, _] = dual_coefficients(&p);
        let poly: [Point<Q, 2>; 4] = std::array::from_fn(|j| {
            a.clone() + &(b.clone() * &xi[j]) + &(cq.clone() * &zeta[j])
        });
        let s = BetaSpline::new(p.clone(), poly.to_vec()).unwrap();
        let d0 = distance(&p, &xi, &poly);
        let mut previous = d0.clone();
        for k in 1..=3u32 {
            let pieces = s.subdivide(&q(1, 2), k).unwrap();
            prop_assert_eq!(pieces.len(), 1 << k);
            let dk = pieces.iter().map(|pc| distance(&p, &xi, pc)).max().unwrap();
            prop_assert_eq!(dk.clone() * qi(4), previous);
            previous = dk;
        }
    }

    /// A cubic: after k rounds at c = ½, every piece's distance is at most
    /// 4⁻ᵏ·(K₂/2)·Z + 8⁻ᵏ·(K₃/6)·H, where K₂ bounds |Q″| on [0, 1] (it is linear: its
    /// larger end), K₃ = |Q‴|, Z = maxⱼ|ζⱼ − ξⱼ²| and H = maxⱼ|ηⱼ − ξⱼ³|; the bound falls by at
    /// least 4 per round.
    #[test]
    fn subdivision_of_a_cubic_converges_by_a_factor_four_per_round(
        p in parameters(),
        poly in polygon(),
    ) {
        let [xi, zeta, eta] = dual_coefficients(&p);
        let z = (0..4).map(|j| (zeta[j].clone() - xi[j].clone() * &xi[j]).abs_value()).max().unwrap();
        let h = (0..4)
            .map(|j| (eta[j].clone() - xi[j].clone() * &xi[j] * &xi[j]).abs_value())
            .max()
            .unwrap();
        let s = BetaSpline::new(p.clone(), poly.to_vec()).unwrap();
        let d0 = s.segment_derivatives(0, &qi(0)).unwrap();
        let d1 = s.segment_derivatives(0, &qi(1)).unwrap();
        let k2 = norm(&d0[2]).max(norm(&d1[2]));
        let k3 = norm(&(d1[2].clone() - &d0[2])); // Q‴ is constant: Q″(1) − Q″(0)
        for k in 0..=4u32 {
            let pieces = s.subdivide(&q(1, 2), k).unwrap();
            let worst = pieces.iter().map(|pc| distance(&p, &xi, pc)).max().unwrap();
            let h2 = q(1, 1 << (2 * k));
            let h3 = q(1, 1 << (3 * k));
            let bound = h2 * &k2 / qi(2) * &z + h3 * &k3 / qi(6) * &h;
            prop_assert!(worst <= bound, "round {}: {} > {}", k, worst, bound);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Counts, limits and errors.

#[test]
fn evaluation_and_subdivision_count_as_documented() {
    let p = BetaParameters::new(2.0, 1.0).unwrap();
    let s = BetaSpline::new(p, (0..35).map(|i| Point::new([i as f64, 1.0])).collect()).unwrap();
    // m = 32 segments: bisection takes exactly lg 32 = 5 comparisons.
    let mut c = Counts::default();
    s.eval_with(&17.25, &mut c).unwrap();
    assert_eq!((c.comparisons, c.arithmetic_operations), (5, 20));
    let mut c = Counts::default();
    let pieces = s.subdivide_with(&0.25, 3, &mut c).unwrap();
    assert_eq!(pieces.len(), 32 * 8);
    assert_eq!(c.arithmetic_operations, 256 + 32 * 32 * 7);
    // The domain end is the last segment at t = 1.
    assert_eq!(s.eval(&32.0).unwrap(), s.eval_segment(31, &1.0).unwrap());
}

#[test]
fn bad_parameters_and_short_polygons_are_named_errors() {
    let name = |e: Error| match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(name(BetaParameters::new(0.0, 1.0).unwrap_err()), "beta1");
    assert_eq!(name(BetaParameters::new(-2.0, 1.0).unwrap_err()), "beta1");
    assert_eq!(
        name(BetaParameters::new(f64::NAN, 1.0).unwrap_err()),
        "beta1"
    );
    assert_eq!(
        name(BetaParameters::new(1.0, f64::NEG_INFINITY).unwrap_err()),
        "beta2"
    );
    assert_eq!(name(BetaParameters::new(1.0, -1.0).unwrap_err()), "beta2");
    // The degenerate values of the extended range, exactly: δ = 0 and det C = 0.
    for b1 in [q(1, 2), qi(1), qi(3)] {
        let delta_zero = -(qi(2) * &b1 * &b1 * &b1 + qi(4) * &b1 * &b1 + qi(4) * &b1 + qi(2));
        let singular = -(qi(2) * &b1 * (b1.clone() + qi(1)));
        for b2 in [delta_zero, singular] {
            let e = BetaParameters::allowing_negative_tension(b1.clone(), b2).unwrap_err();
            assert_eq!(name(e), "beta2");
        }
    }
    let p = BetaParameters::new(1.0, 0.0).unwrap();
    for c in [0.0, 1.0, -0.5, f64::NAN] {
        assert_eq!(name(p.subdivision_matrices(&c).unwrap_err()), "c");
    }
    let nodes = [0.0, 0.5, 0.5, 1.0];
    assert_eq!(
        name(
            p.subdivision_matrices_by_interpolation(&0.5, &nodes)
                .unwrap_err()
        ),
        "nodes"
    );
    let pt = |x: f64| Point::new([x, 0.0]);
    let e = BetaSpline::new(p.clone(), vec![pt(0.0), pt(1.0), pt(2.0)]).unwrap_err();
    assert_eq!(
        e,
        Error::TooFew {
            what: "Beta-spline control polygon",
            needed: 4,
            got: 3
        }
    );
    assert!(matches!(
        BetaSpline::<f64, 2>::new(p.clone(), vec![]),
        Err(Error::Empty { .. })
    ));
    let e = BetaSpline::new(p.clone(), vec![pt(0.0), pt(1.0), pt(f64::NAN), pt(3.0)]);
    assert!(matches!(e, Err(Error::NonFinite { index: 2, .. })));
    let s = BetaSpline::new(p, (0..5).map(|i| pt(i as f64)).collect()).unwrap();
    assert_eq!(name(s.eval(&2.5).unwrap_err()), "u");
    assert_eq!(name(s.eval(&-0.25).unwrap_err()), "u");
    assert_eq!(name(s.segment(2).unwrap_err()), "segment");
    for rounds in [20, 64, 200, u32::MAX] {
        assert!(matches!(
            s.subdivide(&0.5, rounds),
            Err(Error::LimitExceeded {
                limit: "MAX_SUBDIVIDED_PIECES",
                ..
            })
        ));
    }
    assert_eq!(s.subdivide(&0.5, 19).map(|v| v.len()), Ok(1 << 20));
}
