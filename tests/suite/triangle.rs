//! Triangular Bézier patches, checked exactly on the rational back end against independent
//! oracles: the Bernstein basis against the trinomial expansion (it sums to 1); de Casteljau
//! against the Bernstein sum; the exact counts; bad input as named errors.

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::Point;
use compgeo::surface::triangle::{bernstein_basis, multi_indices, storage_index};
use compgeo::surface::{Barycentric, BarycentricVector, Surface, TriangularPatch};
use compgeo::Error;
use proptest::prelude::*;

/// A small rational, also negative and above one.
fn rational() -> impl Strategy<Value = Q> {
    (-12i64..=12, 1i64..=6).prop_map(|(n, d)| q(n, d))
}

/// A point of the plane of the reference triangle (inside or outside it).
fn point() -> impl Strategy<Value = Barycentric<Q>> {
    (rational(), rational()).prop_map(|(u, v)| Barycentric::from_uv(u, v).unwrap())
}

/// A direction of the plane.
fn direction() -> impl Strategy<Value = BarycentricVector<Q>> {
    (rational(), rational()).prop_map(|(du, dv)| BarycentricVector::from_uv(du, dv).unwrap())
}

/// A patch of degree `degrees` with small integer points in R³.
fn patch_of(
    degrees: std::ops::RangeInclusive<usize>,
) -> impl Strategy<Value = TriangularPatch<Q, 3>> {
    degrees
        .prop_flat_map(|n| {
            prop::collection::vec((-9i64..=9, -9i64..=9, -9i64..=9), (n + 1) * (n + 2) / 2)
        })
        .prop_map(|pts| {
            TriangularPatch::new(
                pts.into_iter()
                    .map(|(x, y, z)| Point::new([qi(x), qi(y), qi(z)]))
                    .collect(),
            )
            .unwrap()
        })
}

fn patch() -> impl Strategy<Value = TriangularPatch<Q, 3>> {
    patch_of(0..=6)
}

/// n!/(i! j! k!) as a rational.
fn multinomial(i: usize, j: usize, k: usize) -> Q {
    let fact = |m: usize| (1..=m as i64).fold(qi(1), |f, x| f * qi(x));
    fact(i + j + k) / (fact(i) * fact(j) * fact(k))
}

fn pow(x: &Q, e: usize) -> Q {
    (0..e).fold(qi(1), |p, _| p * x)
}

/// B^n_{ijk}(x) from its definition, an oracle independent of the library's ratios.
fn bernstein(n: usize, [i, j, k]: [usize; 3], x: &Barycentric<Q>) -> Q {
    let [u, v, w] = x.coords();
    debug_assert_eq!(i + j + k, n);
    multinomial(i, j, k) * pow(u, i) * pow(v, j) * pow(w, k)
}

/// Σ b_{ijk} B^n_{ijk}(x) from the definition.
fn bernstein_sum(b: &TriangularPatch<Q, 3>, x: &Barycentric<Q>) -> Point<Q, 3> {
    let n = b.degree();
    multi_indices(n).fold(Point::zero(), |acc, i| {
        acc + b.get(i[0], i[1], i[2]).unwrap().clone() * bernstein(n, i, x)
    })
}

fn c3(n: usize) -> u64 {
    (n * (n + 1) * (n + 2) / 6) as u64
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn the_basis_is_the_trinomial_expansion_and_sums_to_one(n in 0usize..=6, x in point()) {
        let basis = bernstein_basis(n, &x).unwrap();
        prop_assert_eq!(basis.len(), (n + 1) * (n + 2) / 2);
        for (at, i) in multi_indices(n).enumerate() {
            prop_assert_eq!(storage_index(n, i), Some(at));
            prop_assert_eq!(&basis[at], &bernstein(n, i, &x));
        }
        prop_assert_eq!(basis.iter().fold(qi(0), |s, b| s + b), qi(1));
    }

    #[test]
    fn de_casteljau_is_the_bernstein_sum(b in patch(), x in point()) {
        let n = b.degree();
        let want = bernstein_sum(&b, &x);
        let mut c = Counts::default();
        prop_assert_eq!(b.de_casteljau_with(&x, &mut c), want.clone());
        prop_assert_eq!(c.arithmetic_operations, c3(n));
        let mut c = Counts::default();
        prop_assert_eq!(b.bernstein_sum_with(&x, &mut c), want.clone());
        prop_assert_eq!(c.arithmetic_operations, ((n + 1) * (n + 2) / 2) as u64);
        // The surface in (u, v) with w = 1 − u − v.
        let [u, v, _] = x.coords();
        prop_assert_eq!(b.eval(u, v).unwrap(), want);
    }

    #[test]
    fn f64_evaluation_is_close_to_exact(b in patch(), x in point()) {
        let exact = b.de_casteljau(&x).to_f64();
        let [u, v, _] = x.coords().clone().map(|c| compgeo::spline::Scalar::to_f64(&c));
        let xf = Barycentric::from_uv(u, v).unwrap();
        let bf = b.to_f64();
        let scale = 1.0 + exact.coords().iter().fold(0.0f64, |m, c| m.max(c.abs()));
        for got in [bf.de_casteljau(&xf), bf.bernstein_sum(&xf)] {
            for (g, w) in got.coords().iter().zip(exact.coords()) {
                prop_assert!((g - w).abs() <= 1e-9 * scale * 1e4, "{} vs {}", g, w);
            }
        }
    }
}

#[test]
fn the_vertices_are_the_corner_points() {
    // [PPB, §10.2]: b(p) = b_{n00}, b(q) = b_{0n0}, b(r) = b_{00n}.
    let n = 3;
    let b: TriangularPatch<Q, 3> = TriangularPatch::new(
        multi_indices(n)
            .map(|[i, j, k]| {
                Point::new([
                    qi(i as i64 * 7 - 3),
                    qi(j as i64 * j as i64),
                    qi(k as i64 - 5),
                ])
            })
            .collect(),
    )
    .unwrap();
    for (t, corner) in [[3, 0, 0], [0, 3, 0], [0, 0, 3]].into_iter().enumerate() {
        let x = Barycentric::vertex(t);
        assert_eq!(
            &b.de_casteljau(&x),
            b.get(corner[0], corner[1], corner[2]).unwrap()
        );
        let basis = bernstein_basis(n, &x).unwrap();
        let at = storage_index(n, corner).unwrap();
        for (k, value) in basis.iter().enumerate() {
            assert_eq!(*value, if k == at { qi(1) } else { qi(0) });
        }
    }
}

#[test]
fn bad_input_is_a_named_error() {
    let p = |x: f64| Point::new([x, 0.0, 0.0]);
    assert!(matches!(
        TriangularPatch::<f64, 3>::new(vec![]),
        Err(Error::Empty { .. })
    ));
    for count in [2, 4, 5, 7, 11] {
        assert!(matches!(
            TriangularPatch::new(vec![p(0.0); count]),
            Err(Error::InvalidParameter {
                name: "control points",
                ..
            })
        ));
    }
    assert!(matches!(
        TriangularPatch::with_degree(2, vec![p(0.0); 10]),
        Err(Error::InvalidParameter {
            name: "control points",
            ..
        })
    ));
    assert!(matches!(
        TriangularPatch::new(vec![p(0.0), p(1.0), p(f64::NAN)]),
        Err(Error::NonFinite { index: 2, .. })
    ));
    assert!(matches!(
        TriangularPatch::new(vec![p(f64::INFINITY), p(1.0), p(0.0)]),
        Err(Error::NonFinite { index: 0, .. })
    ));
    for n in [usize::MAX, 1 << 40, (1 << 16) + 1, 20_000] {
        assert!(matches!(
            TriangularPatch::with_degree(n, vec![p(0.0)]),
            Err(Error::LimitExceeded { .. })
        ));
        assert!(matches!(
            bernstein_basis(n, &Barycentric::<f64>::vertex(0)),
            Err(Error::LimitExceeded { .. })
        ));
    }
    // Barycentric coordinates sum to exactly one, directions to exactly zero.
    let name = |e: Error| match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("{other}"),
    };
    assert_eq!(
        name(Barycentric::new(0.5, 0.5, 0.5).unwrap_err()),
        "barycentric"
    );
    assert_eq!(
        name(Barycentric::new(0.7, 0.2, 0.1).unwrap_err()),
        "barycentric"
    ); // rounds to 1 − 2⁻⁵³
    assert_eq!(
        name(Barycentric::new(q(1, 10), q(2, 10), q(6, 10)).unwrap_err()),
        "barycentric"
    );
    assert!(Barycentric::new(q(1, 10), q(2, 10), q(7, 10)).is_ok());
    assert_eq!(
        name(Barycentric::new(f64::NAN, 0.5, 0.5).unwrap_err()),
        "barycentric"
    );
    assert_eq!(
        name(Barycentric::from_uv(f64::INFINITY, 0.0).unwrap_err()),
        "barycentric"
    );
    assert_eq!(
        name(Barycentric::from_uv(-f64::MAX, -f64::MAX).unwrap_err()),
        "barycentric"
    );
    assert_eq!(
        name(BarycentricVector::new(1.0, 1.0, -1.0).unwrap_err()),
        "direction"
    );
    assert_eq!(
        name(BarycentricVector::new(f64::NAN, 1.0, -1.0).unwrap_err()),
        "direction"
    );
    assert_eq!(
        name(BarycentricVector::from_uv(f64::MAX, f64::MAX).unwrap_err()),
        "direction"
    );
    // The surface traits name u and v.
    let b = TriangularPatch::new(vec![p(0.0), p(1.0), p(2.0)]).unwrap();
    assert_eq!(name(b.eval(&f64::NAN, &0.0).unwrap_err()), "u");
    assert_eq!(name(b.eval(&0.0, &f64::INFINITY).unwrap_err()), "v");
}

#[test]
fn f64_beyond_the_range_is_infinite_not_a_panic() {
    let p = |x: f64| Point::new([x]);
    let b = TriangularPatch::new(vec![p(f64::MAX), p(-f64::MAX), p(f64::MAX)]).unwrap();
    let x = Barycentric::from_uv(1e10, -1e10).unwrap();
    assert!(!b.de_casteljau(&x).is_finite());
}

/// x + d, a point.
fn shifted(x: &Barycentric<Q>, d: &BarycentricVector<Q>) -> Barycentric<Q> {
    let [u, v, w] = x.coords();
    let [du, dv, dw] = d.coords();
    Barycentric::new(u.clone() + du, v.clone() + dv, w.clone() + dw).unwrap()
}

/// α·x + (1 − α)·y.
fn affine(alpha: &Q, x: &Barycentric<Q>, y: &Barycentric<Q>) -> Barycentric<Q> {
    let c: Vec<Q> = (0..3)
        .map(|t| alpha.clone() * &x.coords()[t] + (qi(1) - alpha) * &y.coords()[t])
        .collect();
    Barycentric::new(c[0].clone(), c[1].clone(), c[2].clone()).unwrap()
}

/// D_{d₁} ⋯ D_{d_r} b(x) term by term: ∂B^n_i/∂u_t = n B^{n−1}_{i−e_t} [PPB, §10.5], so the
/// derivative of the sum is n!/(n − r)! Σ_i b_i Σ_{t₁…t_r} d₁_{t₁} ⋯ d_r_{t_r}
/// B^{n−r}_{i − e_{t₁} − ⋯ − e_{t_r}}.
fn derivative_of_the_sum(
    b: &TriangularPatch<Q, 3>,
    x: &Barycentric<Q>,
    directions: &[BarycentricVector<Q>],
) -> Point<Q, 3> {
    let n = b.degree();
    let r = directions.len();
    if r > n {
        return Point::zero();
    }
    let factor = (0..r).fold(qi(1), |f, s| f * qi((n - s) as i64));
    let mut total = Point::zero();
    for i in multi_indices(n) {
        let mut weight = qi(0);
        for tuple in 0..3usize.pow(r as u32) {
            let mut e = i;
            let mut coefficient = qi(1);
            let mut rest = tuple;
            let mut inside = true;
            for d in directions {
                let t = rest % 3;
                rest /= 3;
                coefficient *= &d.coords()[t];
                if e[t] == 0 {
                    inside = false;
                    break;
                }
                e[t] -= 1;
            }
            if inside {
                weight += coefficient * bernstein(n - r, e, x);
            }
        }
        total = total + b.get(i[0], i[1], i[2]).unwrap().clone() * weight;
    }
    total * factor
}

/// b[d₁, …, d_r, x, …, x] by inclusion and exclusion over the affine arguments:
/// Σ_{S ⊆ {1..r}} (−1)^{r − |S|} b[y₁, …, y_r, x, …, x], y_s = x + d_s for s ∈ S, else x.
fn blossom_with_directions(
    b: &TriangularPatch<Q, 3>,
    x: &Barycentric<Q>,
    directions: &[BarycentricVector<Q>],
) -> Point<Q, 3> {
    let n = b.degree();
    let r = directions.len();
    let mut total = Point::zero();
    for subset in 0..1usize << r {
        let mut args: Vec<Barycentric<Q>> = directions
            .iter()
            .enumerate()
            .map(|(s, d)| {
                if subset >> s & 1 == 1 {
                    shifted(x, d)
                } else {
                    x.clone()
                }
            })
            .collect();
        args.extend(std::iter::repeat_n(x.clone(), n - r));
        let value = b.blossom(&args).unwrap();
        if (r - subset.count_ones() as usize) % 2 == 0 {
            total = total + value;
        } else {
            total = total - value;
        }
    }
    total
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn the_blossom_is_symmetric_multi_affine_and_the_patch_on_its_diagonal(
        b in patch_of(1..=5),
        xs in prop::collection::vec(point(), 5),
        y in point(),
        alpha in rational(),
        rotate in 0usize..5,
    ) {
        let n = b.degree();
        let args = xs[..n].to_vec();
        let mut c = Counts::default();
        let value = b.blossom_with(&args, &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, c3(n));
        // Symmetric: any rotation and the reversal of the arguments.
        let mut turned = args.clone();
        turned.rotate_left(rotate % n);
        prop_assert_eq!(b.blossom(&turned).unwrap(), value.clone());
        turned.reverse();
        prop_assert_eq!(b.blossom(&turned).unwrap(), value.clone());
        // Affine in the first argument (hence in every one).
        let mut at_y = args.clone();
        at_y[0] = y.clone();
        let mut mixed = args.clone();
        mixed[0] = affine(&alpha, &args[0], &y);
        let want = value.clone() * alpha.clone() + b.blossom(&at_y).unwrap() * (qi(1) - &alpha);
        prop_assert_eq!(b.blossom(&mixed).unwrap(), want);
        // The diagonal.
        let x = &args[0];
        prop_assert_eq!(b.blossom(&vec![x.clone(); n]).unwrap(), b.de_casteljau(x));
    }

    #[test]
    fn the_blossom_at_the_vertices_is_the_net(b in patch_of(0..=5)) {
        let n = b.degree();
        for i in multi_indices(n) {
            let args: Vec<Barycentric<Q>> = (0..3)
                .flat_map(|t| std::iter::repeat_n(Barycentric::vertex(t), i[t]))
                .collect();
            prop_assert_eq!(&b.blossom(&args).unwrap(), b.get(i[0], i[1], i[2]).unwrap());
        }
    }

    #[test]
    fn derivatives_are_the_derivatives_of_the_bernstein_sum(
        b in patch_of(0..=5),
        x in point(),
        directions in prop::collection::vec(direction(), 0..=4),
    ) {
        let n = b.degree();
        let r = directions.len();
        let mut c = Counts::default();
        let got = b.directional_derivative_with(&x, &directions, &mut c);
        prop_assert_eq!(&got, &derivative_of_the_sum(&b, &x, &directions));
        let want_counts = match r {
            0 => c3(n),
            r if r <= n => c3(n) + 1,
            _ => 0,
        };
        prop_assert_eq!(c.arithmetic_operations, want_counts);
        if r <= n {
            // n!/(n − r)! b[d₁ … d_r x … x] [PPB, §11.6], the blossom taken at points only.
            let factor = (0..r).fold(qi(1), |f, s| f * qi((n - s) as i64));
            prop_assert_eq!(&got, &(blossom_with_directions(&b, &x, &directions) * factor));
        }
        // Directions commute.
        let mut reversed = directions.clone();
        reversed.reverse();
        prop_assert_eq!(b.directional_derivative(&x, &reversed), got);
    }

    #[test]
    fn the_partials_in_u_and_v_are_derivatives_along_p_minus_r_and_q_minus_r(
        b in patch_of(0..=5),
        x in point(),
        r in 0usize..=3,
        s in 0usize..=3,
    ) {
        use compgeo::surface::SurfaceDerivative;
        let du = BarycentricVector::new(qi(1), qi(0), qi(-1)).unwrap();
        let dv = BarycentricVector::new(qi(0), qi(1), qi(-1)).unwrap();
        let mut directions = vec![du; r];
        directions.extend(std::iter::repeat_n(dv, s));
        let [u, v, _] = x.coords();
        prop_assert_eq!(
            b.partial_at(u, v, r, s).unwrap(),
            derivative_of_the_sum(&b, &x, &directions)
        );
        if r + s == 0 {
            let grid = b.first_partials_on_grid(std::slice::from_ref(u), std::slice::from_ref(v)).unwrap();
            prop_assert_eq!(&grid[0][0], &b.de_casteljau(&x));
            prop_assert_eq!(&grid[0][1], &b.partial_at(u, v, 1, 0).unwrap());
            prop_assert_eq!(&grid[0][2], &b.partial_at(u, v, 0, 1).unwrap());
        }
    }

    #[test]
    fn the_three_pieces_of_a_subdivision_reproduce_the_patch(
        b in patch(),
        x in point(),
        y in point(),
    ) {
        let n = b.degree();
        let mut c = Counts::default();
        let pieces = b.subdivide_with(&x, &mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, c3(n));
        for (t, piece) in pieces.iter().enumerate() {
            // y in piece t is y_t·x + Σ_{s ≠ t} y_s e_s in p q r.
            let mapped: Vec<Q> = (0..3)
                .map(|s| {
                    let own = if s == t { qi(0) } else { y.coords()[s].clone() };
                    own + y.coords()[t].clone() * &x.coords()[s]
                })
                .collect();
            let mapped = Barycentric::new(mapped[0].clone(), mapped[1].clone(), mapped[2].clone()).unwrap();
            prop_assert_eq!(piece.de_casteljau(&y), b.de_casteljau(&mapped));
            // Its net is the blossom at its vertices [PPB, §11.2].
            let corners: Vec<Barycentric<Q>> = (0..3)
                .map(|s| if s == t { x.clone() } else { Barycentric::vertex(s) })
                .collect();
            for i in multi_indices(n) {
                let args: Vec<Barycentric<Q>> = (0..3)
                    .flat_map(|s| std::iter::repeat_n(corners[s].clone(), i[s]))
                    .collect();
                prop_assert_eq!(&b.blossom(&args).unwrap(), piece.get(i[0], i[1], i[2]).unwrap());
            }
        }
    }

    #[test]
    fn the_four_way_split_reproduces_the_patch(b in patch(), y in point()) {
        let n = b.degree();
        let mut c = Counts::default();
        let pieces = b.split_four_with(&mut c).unwrap();
        prop_assert_eq!(c.arithmetic_operations, 6 * c3(n));
        let half = q(1, 2);
        let at = |coords: Vec<Q>| Barycentric::new(coords[0].clone(), coords[1].clone(), coords[2].clone()).unwrap();
        for (t, corner) in pieces[..3].iter().enumerate() {
            // Corner t at y is the patch at (y + e_t)/2.
            let mapped = at((0..3)
                .map(|s| (y.coords()[s].clone() + if s == t { qi(1) } else { qi(0) }) * &half)
                .collect());
            prop_assert_eq!(corner.de_casteljau(&y), b.de_casteljau(&mapped));
        }
        // The middle at y is the patch at (1 − y)/2.
        let mapped = at((0..3).map(|s| (qi(1) - &y.coords()[s]) * &half).collect());
        prop_assert_eq!(pieces[3].de_casteljau(&y), b.de_casteljau(&mapped));
        // Its vertices are the midpoints of the edges opposite p, q and r.
        let mids = [[0, 1, 1], [1, 0, 1], [1, 1, 0]].map(|m| at(m.iter().map(|&c| q(c, 2)).collect()));
        for i in multi_indices(n) {
            let args: Vec<Barycentric<Q>> = (0..3)
                .flat_map(|s| std::iter::repeat_n(mids[s].clone(), i[s]))
                .collect();
            prop_assert_eq!(&b.blossom(&args).unwrap(), pieces[3].get(i[0], i[1], i[2]).unwrap());
        }
    }
}

/// The multinomial n!/(i! j! k!) of a multi-index.
fn multinomial_of(i: [usize; 3]) -> Q {
    multinomial(i[0], i[1], i[2])
}

/// Zhou's formula [PPB, §11.9]: d_k = Σ_i b_i C(n; i) C(m − n; k − i)/C(m; k).
fn zhou(b: &TriangularPatch<Q, 3>, m: usize) -> Vec<Point<Q, 3>> {
    let n = b.degree();
    multi_indices(m)
        .map(|k| {
            multi_indices(n)
                .filter(|i| (0..3).all(|t| i[t] <= k[t]))
                .fold(Point::zero(), |acc, i| {
                    let rest = [k[0] - i[0], k[1] - i[1], k[2] - i[2]];
                    let beta = multinomial_of(i) * multinomial_of(rest) / multinomial_of(k);
                    acc + b.get(i[0], i[1], i[2]).unwrap().clone() * beta
                })
        })
        .collect()
}

/// A far vertex s across p q: any point whose w-coordinate is negative.
fn far_vertex() -> impl Strategy<Value = Barycentric<Q>> {
    (rational(), rational(), 1i64..=6, 1i64..=4).prop_map(|(u, v, a, d)| {
        let w = q(-a, d);
        let rest = qi(1) - &w - &u;
        let _ = v;
        Barycentric::new(u, rest, w).unwrap()
    })
}

/// The coordinates over q p s of the point or vector with coordinates `x` over p q r.
fn across(x: &[Q; 3], s: &Barycentric<Q>) -> [Q; 3] {
    let [s0, s1, s2] = s.coords();
    let gamma = x[2].clone() / s2;
    [
        x[1].clone() - gamma.clone() * s1,
        x[0].clone() - gamma.clone() * s0,
        gamma,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn elevation_keeps_the_polynomial_and_is_zhous_formula(
        b in patch_of(0..=5),
        by in 0usize..=3,
        x in point(),
    ) {
        let n = b.degree();
        let m = n + by;
        let mut c = Counts::default();
        let e = b.elevate_to_with(m, &mut c).unwrap();
        prop_assert_eq!(e.degree(), m);
        prop_assert_eq!(c.arithmetic_operations, c3(m + 1) - c3(n + 1));
        prop_assert_eq!(e.de_casteljau(&x), b.de_casteljau(&x));
        let want = zhou(&b, m);
        prop_assert_eq!(e.points(), want.as_slice());
        if by == 1 {
            prop_assert_eq!(b.elevate().unwrap(), e);
        }
    }

    #[test]
    fn a_continuation_joins_with_its_order_and_a_perturbed_one_does_not(
        b in patch_of(1..=5),
        s in far_vertex(),
        r in 0usize..=5,
        free_seed in prop::collection::vec(-9i64..=9, 21),
        t in rational(),
        d in direction(),
    ) {
        let n = b.degree();
        let r = r.min(n);
        let count = (n - r) * (n - r + 1) / 2;
        let free: Vec<Point<Q, 3>> = free_seed[..count]
            .iter()
            .map(|&z| Point::new([qi(z), qi(z * z), qi(1 - z)]))
            .collect();
        let mut counts = Counts::default();
        let c = b.extend_cr_with(&s, r, &free, &mut counts).unwrap();
        prop_assert_eq!(counts.arithmetic_operations, c3(n) - c3(n - r));
        let mut counts = Counts::default();
        let order = b.join_order_with(&c, &s, &qi(0), &mut counts).unwrap();
        prop_assert_eq!(counts.arithmetic_operations, c3(n));
        prop_assert!(order.is_some_and(|o| o >= r), "{:?} < {}", order, r);
        // The derivatives across the edge agree up to order r: at y = (t, 1 − t, 0) on p q,
        // D_d^k b(y) = D_{d'}^k c(y') with y', d' the same point and vector over q p s.
        let y = Barycentric::new(t.clone(), qi(1) - &t, qi(0)).unwrap();
        let y_c = across(y.coords(), &s);
        let y_c = Barycentric::new(y_c[0].clone(), y_c[1].clone(), y_c[2].clone()).unwrap();
        let d_c = across(d.coords(), &s);
        let d_c = BarycentricVector::new(d_c[0].clone(), d_c[1].clone(), d_c[2].clone()).unwrap();
        for k in 0..=r {
            prop_assert_eq!(
                b.directional_derivative(&y, &vec![d.clone(); k]),
                c.directional_derivative(&y_c, &vec![d_c.clone(); k])
            );
        }
        // A point of row r moved: the join is C^{r−1} and no better.
        let mut moved = c.points().to_vec();
        let row_r = (r + 1) * (2 * n + 2 - r) / 2 - 1; // the last point of row r
        moved[row_r][0] += qi(1);
        let moved = TriangularPatch::new(moved).unwrap();
        prop_assert_eq!(b.join_order(&moved, &s, &qi(0)).unwrap(), r.checked_sub(1));
        // C^n is the same polynomial: c at z over q p s is b at the point z names.
        let whole = b.extend_cr(&s, n, &[]).unwrap();
        prop_assert_eq!(b.join_order(&whole, &s, &qi(0)).unwrap(), Some(n));
        let z = Barycentric::new(q(1, 3), q(1, 2), q(1, 6)).unwrap();
        let [a0, a1, a2] = z.coords();
        let mapped: Vec<Q> = (0..3)
            .map(|t| {
                let own = match t { 0 => a1.clone(), 1 => a0.clone(), _ => qi(0) };
                own + a2.clone() * &s.coords()[t]
            })
            .collect();
        let mapped = Barycentric::new(mapped[0].clone(), mapped[1].clone(), mapped[2].clone()).unwrap();
        prop_assert_eq!(whole.de_casteljau(&z), b.de_casteljau(&mapped));
    }

    #[test]
    fn the_tensor_form_is_the_patch_on_the_degenerate_square(
        b in patch(),
        s in rational(),
        t in rational(),
    ) {
        let n = b.degree();
        let mut c = Counts::default();
        let tensor = b.to_tensor_with(&mut c).unwrap();
        prop_assert_eq!(tensor.bidegree(), (n, n));
        prop_assert_eq!(c.arithmetic_operations, ((n + 1) * (n + 2) * (n + 3) / 6) as u64);
        let x = Barycentric::new(s.clone() * (qi(1) - &t), s.clone() * &t, qi(1) - &s).unwrap();
        prop_assert_eq!(tensor.eval(&s, &t).unwrap(), b.de_casteljau(&x));
    }

    #[test]
    fn the_two_triangular_halves_are_the_tensor_patch(
        (m, n, pts) in (0usize..=4, 0usize..=4).prop_flat_map(|(m, n)| {
            (Just(m), Just(n), prop::collection::vec((-9i64..=9, -9i64..=9, -9i64..=9), (m + 1) * (n + 1)))
        }),
        u in rational(),
        v in rational(),
    ) {
        use compgeo::surface::{BezierPatch, ControlNet};
        let net: Vec<Point<Q, 3>> = pts.iter().map(|&(x, y, z)| Point::new([qi(x), qi(y), qi(z)])).collect();
        let tensor = BezierPatch::new(ControlNet::from_rows(m + 1, n + 1, net).unwrap()).unwrap();
        let mut c = Counts::default();
        let [lower, upper] = TriangularPatch::from_tensor_with(&tensor, &mut c).unwrap();
        let l = m + n;
        prop_assert_eq!(lower.degree(), l);
        // The stated count: per half, (m + 1)(n + 1)(n + 2)/2 terms and d + 2 per elevation
        // of row i from degree d = l − i − (m − a₀), …, l − i − 1, a₀ = max(0, i − n).
        let elevations: usize = (0..=l)
            .map(|i| {
                let a0 = i.saturating_sub(n);
                (l - i - (m - a0)..l - i).map(|d| d + 2).sum::<usize>()
            })
            .sum();
        let per_half = (m + 1) * (n + 1) * (n + 2) / 2 + elevations;
        prop_assert_eq!(c.arithmetic_operations, 2 * per_half as u64);
        // The lower half at (u, v, 1 − u − v) and the upper half at (α, β, γ) are the tensor
        // patch at (u, v) and (β + γ, α + γ).
        prop_assert_eq!(lower.eval(&u, &v).unwrap(), tensor.eval(&u, &v).unwrap());
        let y = Barycentric::from_uv(u.clone(), v.clone()).unwrap();
        let [a, b, g] = y.coords();
        prop_assert_eq!(
            upper.de_casteljau(&y),
            tensor.eval(&(b.clone() + g), &(a.clone() + g)).unwrap()
        );
        // They meet along the diagonal as one polynomial.
        let s = Barycentric::new(qi(1), qi(1), qi(-1)).unwrap();
        prop_assert_eq!(lower.join_order(&upper, &s, &qi(0)).unwrap(), Some(l));
        // The book's formula [PPB, §11.11] with δ = C(i, α) C(j, β) C(k, γ)/C(l, m) over the
        // lower triangle p q r = (1, 0), (0, 1), (0, 0): the x arguments 1^α 0^{β+γ}, the y
        // arguments 0^{i−α} 1^{j−β} 0^{k−γ}, so the tensor blossom is c_{α, j−β}.
        let choose = |a: usize, b: usize| multinomial(b, a - b, 0);
        for [i, j, k] in multi_indices(l) {
            let mut want = Point::zero();
            for alpha in 0..=i.min(m) {
                for beta in 0..=j.min(m - alpha) {
                    let gamma = m - alpha - beta;
                    if gamma > k || j - beta > n {
                        continue;
                    }
                    let delta = choose(i, alpha) * choose(j, beta) * choose(k, gamma) / choose(l, m);
                    want = want + tensor.net().get(alpha, j - beta).clone() * delta;
                }
            }
            prop_assert_eq!(lower.get(i, j, k).unwrap(), &want);
        }
    }
}

#[test]
fn bad_operations_are_named_errors() {
    let p = |x: f64| Point::new([x]);
    let b = TriangularPatch::new((0..6).map(|k| p(k as f64)).collect()).unwrap();
    let name = |e: Error| match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("{other}"),
    };
    assert_eq!(
        name(b.blossom(&[Barycentric::vertex(0)]).unwrap_err()),
        "blossom arguments"
    );
    assert_eq!(name(b.elevate_to(1).unwrap_err()), "degree");
    assert!(matches!(
        b.elevate_to(1 << 17),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        b.elevate_to(12_000),
        Err(Error::LimitExceeded { .. })
    )); // MAX_POINTS
    let s = Barycentric::new(1.0, 1.0, -1.0).unwrap();
    let on_pq = Barycentric::new(2.0, -1.0, 0.0).unwrap();
    let line = TriangularPatch::new(vec![p(0.0), p(1.0), p(2.0)]).unwrap();
    assert_eq!(name(b.join_order(&line, &s, &0.0).unwrap_err()), "other");
    assert_eq!(name(b.join_order(&b, &on_pq, &0.0).unwrap_err()), "s");
    assert_eq!(name(b.join_order(&b, &s, &-1.0).unwrap_err()), "tolerance");
    assert_eq!(
        name(b.join_order(&b, &s, &f64::NAN).unwrap_err()),
        "tolerance"
    );
    assert_eq!(name(b.extend_cr(&s, 3, &[]).unwrap_err()), "r");
    assert_eq!(name(b.extend_cr(&on_pq, 1, &[p(0.0)]).unwrap_err()), "s");
    assert_eq!(name(b.extend_cr(&s, 1, &[]).unwrap_err()), "free");
    assert!(matches!(
        b.extend_cr(&s, 0, &[p(0.0), p(f64::NAN), p(1.0)]),
        Err(Error::NonFinite { index: 1, .. })
    ));
    // With f64 the check takes a relative tolerance.
    let moved =
        TriangularPatch::new((0..6).map(|k| p(k as f64 * (1.0 + 1e-12))).collect()).unwrap();
    let c = b.extend_cr(&s, 2, &[]).unwrap();
    let c_moved = moved.extend_cr(&s, 2, &[]).unwrap();
    assert_eq!(b.join_order(&c_moved, &s, &1e-9).unwrap(), Some(2));
    assert_eq!(b.join_order(&c, &s, &0.0).unwrap(), Some(2));
    // Results beyond f64 are errors, not infinite points.
    let huge = TriangularPatch::new(vec![p(f64::MAX), p(-f64::MAX), p(f64::MAX)]).unwrap();
    let far = Barycentric::from_uv(1e10, -1e10).unwrap();
    assert!(matches!(huge.subdivide(&far), Err(Error::Overflow { .. })));
}

/// A patch of degree 1..=4 over the unit triangle of the xy plane with z perturbed by at most
/// 1/8: its partials never vanish, and coarse triangles face the way its normals do.
fn nearly_flat() -> impl Strategy<Value = TriangularPatch<Q, 3>> {
    (1usize..=4)
        .prop_flat_map(|n| {
            (
                Just(n),
                prop::collection::vec(-8i64..=8, (n + 1) * (n + 2) / 2),
            )
        })
        .prop_map(|(n, zs)| {
            let points = multi_indices(n)
                .zip(zs)
                .map(|([i, j, _], z)| {
                    Point::new([q(i as i64, n as i64), q(j as i64, n as i64), q(z, 64)])
                })
                .collect();
            TriangularPatch::new(points).unwrap()
        })
}

fn cross_f64(a: &Point<f64, 3>, b: &Point<f64, 3>) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn the_mesh_samples_the_patch_exactly(b in nearly_flat(), m in 1usize..=6) {
        use compgeo::surface::SurfaceDerivative;
        let n = b.degree();
        let mut c = Counts::default();
        let mesh = b.tessellate_with(m, &mut c).unwrap();
        let vertices = (m + 1) * (m + 2) / 2;
        prop_assert_eq!(mesh.positions.len(), vertices);
        prop_assert_eq!(mesh.triangles.len(), m * m);
        prop_assert_eq!(c.arithmetic_operations, (vertices as u64) * (c3(n) + 2));
        for (k, [i, j, kk]) in multi_indices(m).enumerate() {
            let x = Barycentric::new(q(i as i64, m as i64), q(j as i64, m as i64), q(kk as i64, m as i64)).unwrap();
            // The vertex is the exact point, rounded once.
            prop_assert_eq!(mesh.positions[k], *b.de_casteljau(&x).to_f64().coords());
            let [u, v, _] = x.coords();
            let normal = cross_f64(
                &b.partial_at(u, v, 1, 0).unwrap().to_f64(),
                &b.partial_at(u, v, 0, 1).unwrap().to_f64(),
            );
            let length = normal.iter().map(|c| c * c).sum::<f64>().sqrt();
            for (got, want) in mesh.normals[k].iter().zip(normal) {
                prop_assert!((got - want / length).abs() < 1e-12);
            }
        }
        // Every triangle is counter-clockwise seen from its corners' normals; every vertex
        // is used.
        let mut used = vec![false; vertices];
        for t in &mesh.triangles {
            let [a, bb, cc] = t.map(|k| mesh.positions[k]);
            let e1 = Point::new([bb[0] - a[0], bb[1] - a[1], bb[2] - a[2]]);
            let e2 = Point::new([cc[0] - a[0], cc[1] - a[1], cc[2] - a[2]]);
            let face = cross_f64(&e1, &e2);
            for &k in t {
                let n = mesh.normals[k];
                prop_assert!(face[0] * n[0] + face[1] * n[1] + face[2] * n[2] > 0.0);
                used[k] = true;
            }
        }
        prop_assert!(used.into_iter().all(|u| u));
    }

    #[test]
    fn the_obj_file_reads_back_the_same_mesh(b in nearly_flat(), m in 1usize..=5) {
        let mesh = b.to_f64().tessellate(m).unwrap();
        let (positions, triangles) = crate::surface_mesh::read_obj(&mesh);
        prop_assert_eq!(positions.len(), mesh.positions.len());
        prop_assert_eq!(triangles.len(), mesh.triangles.len());
        for (got, want) in triangles.iter().zip(&mesh.triangles) {
            for (g, w) in got.iter().zip(want) {
                prop_assert_eq!(positions[*g], mesh.positions[*w]);
            }
        }
    }
}

#[test]
fn a_collapsed_corner_takes_the_normals_of_its_triangles() {
    // Degree 2 with b101 = b011 = b002: both partials vanish at r.
    let p = |x: i64, y: i64| Point::new([q(x, 2), q(y, 2), qi(0)]);
    let b: TriangularPatch<Q, 3> =
        TriangularPatch::new(vec![p(2, 0), p(1, 1), p(0, 2), p(0, 0), p(0, 0), p(0, 0)]).unwrap();
    let r = Barycentric::vertex(2);
    let du = BarycentricVector::new(qi(1), qi(0), qi(-1)).unwrap();
    assert_eq!(b.directional_derivative(&r, &[du]), Point::zero());
    let mesh = b.tessellate(4).unwrap();
    for normal in &mesh.normals {
        assert_eq!(*normal, [0.0, 0.0, 1.0]);
    }
}

#[test]
fn bad_tessellations_are_named_errors() {
    let p = |x: f64| Point::new([x, 0.0, 0.0]);
    let b = TriangularPatch::new(vec![p(0.0), p(1.0), p(2.0)]).unwrap();
    assert!(matches!(
        b.tessellate(0),
        Err(Error::InvalidParameter {
            name: "segments",
            ..
        })
    ));
    assert!(matches!(
        b.tessellate(1 << 14),
        Err(Error::LimitExceeded { .. })
    ));
    assert!(matches!(
        b.tessellate(usize::MAX),
        Err(Error::LimitExceeded { .. })
    ));
    let huge = TriangularPatch::new(vec![p(f64::MAX), p(-f64::MAX), p(f64::MAX)]).unwrap();
    assert!(huge.tessellate(2).is_ok()); // inside the triangle every point is in range
}

#[test]
fn f64_tessellation_whose_rounded_ratios_do_not_sum_to_one() {
    // 20/22 + 1/22 + 1/22 rounds to 1 − 2⁻⁵³ in f64: the vertices take w = 1 − u − v.
    let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
    let b = TriangularPatch::new(vec![p(1.0, 0.0), p(0.0, 1.0), p(0.0, 0.0)]).unwrap();
    for m in [22, 49, 100] {
        let mesh = b.tessellate(m).unwrap();
        assert_eq!(mesh.triangles.len(), m * m);
        assert!(mesh.normals.iter().all(|n| *n == [0.0, 0.0, 1.0]));
    }
}
