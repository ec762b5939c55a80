//! Subdivision on regular nets, exactly in rationals. The tensor Lane–Riesenfeld algorithm
//! against its oracle, the B-spline surface refined by knot insertion (`BSplineSurface::refine`,
//! Boehm's algorithm, a different algorithm on the same surface): k rounds give the control
//! net on the 2^k-refined knots, open (the B-splines meeting the domain) and closed (the
//! periodic surface, through a wrapped net); the biquadratic masks are (9, 3, 3, 1)/16
//! [PPB, §15.2, Obs. 3]; the limit points are the surface's points; the counts as stated;
//! bad input gets named errors.
//!
//! The module also holds the **three-direction box-spline rule** on a periodic triangular
//! grid, B_n = 𝒜₁^{n₁}𝒜₂^{n₂}𝒜₃^{n₃}𝒟 [PPB, §15.7–15.8], written here from the course's
//! operators and nothing else, as the independent oracle of Loop's scheme (whose regular
//! case is the quartic box spline M₂₂₂, B_{112}: the linear refinement 𝓡 = 𝒜₃𝒟, then
//! Boehm's symmetric averaging 𝒜₁𝒜₂𝒜₃). It is checked here against the tensor scheme
//! (n₃ = 0 is tensor Lane–Riesenfeld of bidegree (n₁, n₂) [PPB, §15.8, Obs. 13]), the
//! linear refinement (Obs. 9) and the masks of Loop's regular vertices and edges
//! (5/8 = α(6) and 1/16 around a vertex, 3/8, 3/8, 1/8, 1/8 on an edge [PPB, §16.9, Ex. 3]).

use crate::spline_common::{q, qi, Q};
use compgeo::count::Counts;
use compgeo::spline::subdivision::Topology;
use compgeo::spline::{KnotVector, Point};
use compgeo::surface::{BSplineSurface, ControlNet, Direction, Surface};
use compgeo::Error;
use proptest::prelude::*;

type P3 = Point<Q, 3>;

const OPEN: Topology = Topology::Open;
const CLOSED: Topology = Topology::Closed;

/// A deterministic M × N net of lattice points in R³, irregular enough that no coincidence
/// hides a wrong index.
pub fn lattice_net(m: usize, n: usize, seed: i64) -> ControlNet<Q, 3> {
    let rows = (0..m as i64)
        .map(|i| {
            (0..n as i64)
                .map(|j| {
                    Point::new([
                        qi((i * 7 + j * 3 + seed) % 11 - 5),
                        qi((i * i * 5 + j * 2 + seed) % 13 - 6),
                        qi((i * j * 3 + j * j + 2 * seed) % 9 - 4),
                    ])
                })
                .collect()
        })
        .collect();
    ControlNet::new(rows).unwrap()
}

/// The uniform knots 0, 1, …, count + degree.
fn integer_knots(degree: usize, count: usize) -> KnotVector<Q> {
    KnotVector::new(degree, (0..=(count + degree) as i64).map(qi).collect()).unwrap()
}

/// The uniform B-spline surface Σ c_{i,j} N^p(u − i) N^q(v − j) of a net.
fn uniform_surface(net: &ControlNet<Q, 3>, (p, qd): (usize, usize)) -> BSplineSurface<Q, 3> {
    BSplineSurface::new(
        net.clone(),
        integer_knots(p, net.rows()),
        integer_knots(qd, net.columns()),
    )
    .unwrap()
}

/// The knots j/2^k of (a, b) that are not integers.
fn dyadic_inner(a: usize, b: usize, k: u32) -> Vec<Q> {
    let step = 1i64 << k;
    (a as i64 * step + 1..b as i64 * step)
        .filter(|j| j % step != 0)
        .map(|j| q(j, step))
        .collect()
}

/// The control net, on the knots 2^{−k}ℤ, of the uniform surface of `net` (on the knots
/// 0, …, M + p and 0, …, N + q), by Boehm's insertion ([`BSplineSurface::refine`]): entry
/// (p + l, q + l′) of the result is the coefficient of N^p(2^k u − l) N^q(2^k v − l′) for
/// every such B-spline that meets the domain [p, M] × [q, N].
///
/// Insertion only takes knots inside a spline's domain, so the net is first padded with p
/// rows of zeros on either side (q columns), which moves the domain to [p, M + 2p] in the
/// padded parameter (the knots shift by p): the padded surface is the same on the original
/// domain, and a B-spline coefficient is the blossom of any polynomial piece under the
/// B-spline, so the refined coefficients of every B-spline meeting that domain agree.
fn refined(net: &ControlNet<Q, 3>, (p, qd): (usize, usize), k: u32) -> ControlNet<Q, 3> {
    let (m, n) = (net.rows(), net.columns());
    let zero = Point::new([qi(0), qi(0), qi(0)]);
    let rows = (0..m + 2 * p)
        .map(|i| {
            (0..n + 2 * qd)
                .map(|j| {
                    let inside = (p..p + m).contains(&i) && (qd..qd + n).contains(&j);
                    if inside {
                        net.get(i - p, j - qd).clone()
                    } else {
                        zero.clone()
                    }
                })
                .collect()
        })
        .collect();
    let s = uniform_surface(&ControlNet::new(rows).unwrap(), (p, qd));
    let r = s
        .refine(Direction::U, &dyadic_inner(p, m + 2 * p, k))
        .unwrap();
    r.refine(Direction::V, &dyadic_inner(qd, n + 2 * qd, k))
        .unwrap()
        .net()
        .clone()
}

/// Rows `rows` × columns `columns` of a net (indices taken mod the net's size).
fn block(
    net: &ControlNet<Q, 3>,
    rows: impl Iterator<Item = usize> + Clone,
    columns: impl Iterator<Item = usize> + Clone,
) -> Vec<Vec<P3>> {
    rows.map(|i| {
        columns
            .clone()
            .map(|j| net.get(i % net.rows(), j % net.columns()).clone())
            .collect()
    })
    .collect()
}

/// An open direction of m points and degree d after k rounds: the refined B-splines
/// l = d(2^k − 1), …, m·2^k − 1, those whose support meets the domain [d, m], as rows of
/// [`refined`] (shifted by d).
fn open_range(m: usize, d: usize, k: u32) -> std::ops::Range<usize> {
    d + d * ((1 << k) - 1)..d + (m << k)
}

#[test]
fn open_rounds_are_the_net_on_the_refined_knots() {
    for (p, qd) in [(1, 1), (1, 3), (2, 2), (3, 2), (3, 3), (4, 1)] {
        for (m, n) in [(p + 1, qd + 1), (p + 3, qd + 2)] {
            let net = lattice_net(m, n, (3 * p + qd) as i64);
            for k in 0..=2u32 {
                let r = net
                    .lane_riesenfeld((p, qd), k as usize, (OPEN, OPEN))
                    .unwrap();
                assert_eq!(
                    (r.rows(), r.columns()),
                    (((m - p) << k) + p, ((n - qd) << k) + qd)
                );
                let oracle = block(
                    &refined(&net, (p, qd), k),
                    open_range(m, p, k),
                    open_range(n, qd, k),
                );
                assert_eq!(r.to_rows(), oracle, "({p}, {qd}), {m} × {n}, k = {k}");
            }
        }
    }
}

/// Closed in u (periodic with M rows), open or closed in v: the periodic surface equals on
/// [p, M + p + 2] the open one of the net wrapped by p + 2 rows (and likewise in v if
/// closed), so the refined coefficients l = (p + 1)(2^k − 1), … (M·2^k of them, each of
/// whose B-splines meets that domain) are the periodic net's, rotated so that the periodic
/// net's row l mod M·2^k comes first.
#[test]
fn closed_rounds_are_the_periodic_net_on_the_refined_knots() {
    for (p, qd) in [(1, 2), (2, 2), (3, 3), (2, 1)] {
        for (m, n) in [(3, 4), (5, 3)] {
            for tv in [OPEN, CLOSED] {
                if tv == OPEN && n < qd + 1 {
                    continue;
                }
                let net = lattice_net(m, n, (p + 2 * qd) as i64);
                let (wm, wn) = (m + p + 2, if tv == CLOSED { n + qd + 2 } else { n });
                let wrapped = ControlNet::new(block(&net, 0..wm, 0..wn)).unwrap();
                for k in 0..=2u32 {
                    let r = net
                        .lane_riesenfeld((p, qd), k as usize, (CLOSED, tv))
                        .unwrap();
                    let fine = refined(&wrapped, (p, qd), k);
                    // Shifted by d, as the rows of `refined`.
                    let start = |d: usize| d + (d + 1) * ((1 << k) - 1);
                    let (rows, columns) = (
                        m << k,
                        if tv == CLOSED {
                            n << k
                        } else {
                            ((n - qd) << k) + qd
                        },
                    );
                    assert_eq!((r.rows(), r.columns()), (rows, columns));
                    let u = start(p)..start(p) + rows;
                    let v = match tv {
                        CLOSED => start(qd)..start(qd) + columns,
                        OPEN => open_range(n, qd, k),
                    };
                    let (su, sv) = (u.start - p, v.start - qd);
                    let oracle = block(&fine, u, v);
                    for (a, row) in oracle.iter().enumerate() {
                        for (b, point) in row.iter().enumerate() {
                            let i = (a + su) % rows;
                            let j = if tv == CLOSED { (b + sv) % columns } else { b };
                            assert_eq!(r.get(i, j), point, "({p}, {qd}) {m}×{n} k={k} ({i}, {j})");
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn biquadratic_masks_are_nine_three_three_one_sixteenths() {
    // A unit impulse at (2, 3) of a 6 × 6 torus: new point (2i + a, 2j + b) gets the weight
    // of c₂₃ in the mask of its parity (a, b).
    let rows: Vec<Vec<Point<Q, 1>>> = (0..6)
        .map(|i| {
            (0..6)
                .map(|j| Point::new([qi(i64::from((i, j) == (2, 3)))]))
                .collect()
        })
        .collect();
    let r = ControlNet::new(rows)
        .unwrap()
        .lane_riesenfeld((2, 2), 1, (CLOSED, CLOSED))
        .unwrap();
    // b_{2i} = (3c_{i−1} + c_i)/4 and b_{2i+1} = (c_{i−1} + 3c_i)/4 in each direction
    // ([PPB, §8.4]'s indexing): the new points of the face with corners (1..2, 2..3).
    let weight = |i: usize, j: usize| r.get(i, j)[0].clone() * qi(16);
    assert_eq!(
        [weight(5, 7), weight(5, 6), weight(4, 7), weight(4, 6)],
        [qi(9), qi(3), qi(3), qi(1)]
    );
    // Every new point lies in one face: the weights of c₂₃ over the 16 points around it.
    let total: Q = (4..8)
        .flat_map(|i| (6..10).map(move |j| (i, j)))
        .map(|(i, j)| r.get(i % 12, j % 12)[0].clone())
        .fold(qi(0), |a, b| a + b);
    assert_eq!(total, qi(4), "each of the four faces at c₂₃ sums 16/16");
}

#[test]
fn limit_points_are_the_surface_at_the_centres() {
    for (p, qd) in [(1, 2), (2, 2), (3, 3), (2, 3), (4, 1)] {
        let (m, n) = (p + 3, qd + 2);
        let net = lattice_net(m, n, (p * qd) as i64);
        let s = uniform_surface(&net, (p, qd));
        for k in 0..=1u32 {
            let r = net
                .lane_riesenfeld((p, qd), k as usize, (OPEN, OPEN))
                .unwrap();
            let l = r.limit_points((p, qd), (OPEN, OPEN)).unwrap();
            let (hp, hq) = (p / 2, qd / 2);
            assert_eq!(
                (l.rows(), l.columns()),
                (r.rows() - 2 * hp, r.columns() - 2 * hq)
            );
            // Vertex (a, b) of r is the refined B-spline (a + p(2^k − 1), …), centred at
            // (a + p(2^k − 1) + (p + 1)/2)/2^k.
            let centre =
                |a: usize, d: usize| q(2 * (a + d * ((1 << k) - 1)) as i64 + d as i64 + 1, 2 << k);
            for a in 0..l.rows() {
                for b in 0..l.columns() {
                    let (u, v) = (centre(a + hp, p), centre(b + hq, qd));
                    assert_eq!(
                        l.get(a, b),
                        &s.eval(&u, &v).unwrap(),
                        "({p}, {qd}) k={k} vertex ({a}, {b})"
                    );
                }
            }
        }
    }
    // Closed: the limit of the wrapped net's vertex (i, j) is the periodic surface there.
    let net = lattice_net(4, 5, 1);
    let wrapped = ControlNet::new(block(&net, 0..4 + 5, 0..5 + 5)).unwrap();
    let s = uniform_surface(&wrapped, (3, 2));
    let l = net.limit_points((3, 2), (CLOSED, CLOSED)).unwrap();
    for i in 0..4 {
        for j in 0..5 {
            // Vertex i is centred at i + (p + 1)/2, shifted by periods into the domain
            // [p, M + 5] of the wrapped net, where it is the periodic surface.
            let centre = |i: usize, d: usize, period: i64| {
                let mut t = q(2 * i as i64 + d as i64 + 1, 2);
                while t < qi(d as i64) {
                    t += qi(period);
                }
                t
            };
            let (u, v) = (centre(i, 3, 4), centre(j, 2, 5));
            assert_eq!(l.get(i, j), &s.eval(&u, &v).unwrap(), "({i}, {j})");
        }
    }
}

/// The counts the curve algorithm states, summed over the rows and then the columns: per
/// round on m points 2dm (closed) or 2dm − d(d + 1)/2 (open).
fn expected_counts(
    (m, n): (usize, usize),
    (p, qd): (usize, usize),
    k: usize,
    (tu, tv): (Topology, Topology),
) -> u64 {
    let curve = |mut len: usize, d: usize, t: Topology| {
        let mut ops = 0;
        for _ in 0..k {
            let (round, next) = match t {
                CLOSED => (2 * d * len, 2 * len),
                OPEN => (2 * d * len - d * (d + 1) / 2, 2 * len - d),
            };
            ops += round;
            len = next;
        }
        (ops as u64, len)
    };
    let (row_ops, columns) = curve(n, qd, tv);
    let (column_ops, _) = curve(m, p, tu);
    m as u64 * row_ops + columns as u64 * column_ops
}

#[test]
fn counts_are_the_curve_algorithms_on_rows_then_columns() {
    for (tu, tv) in [
        (OPEN, OPEN),
        (OPEN, CLOSED),
        (CLOSED, OPEN),
        (CLOSED, CLOSED),
    ] {
        for (p, qd) in [(1, 3), (3, 2), (2, 2)] {
            let net = lattice_net(5, 6, 0).to_f64();
            for k in 0..=3 {
                let mut c = Counts::default();
                net.lane_riesenfeld_with((p, qd), k, (tu, tv), &mut c)
                    .unwrap();
                assert_eq!(
                    c.arithmetic_operations,
                    expected_counts((5, 6), (p, qd), k, (tu, tv)),
                    "({p}, {qd}), k = {k}, {tu:?} × {tv:?}"
                );
            }
        }
    }
    // The closed form on a torus.
    let (m, n, p, qd, k) = (5u64, 6u64, 3u64, 2u64, 3u32);
    let mut c = Counts::default();
    lattice_net(5, 6, 0)
        .to_f64()
        .lane_riesenfeld_with((3, 2), 3, (CLOSED, CLOSED), &mut c)
        .unwrap();
    let f = (1u64 << k) - 1;
    assert_eq!(
        c.arithmetic_operations,
        2 * f * (qd * m * n + p * m * n * (1 << k))
    );
}

#[test]
fn bad_nets_and_parameters_are_named_errors() {
    let net = lattice_net(3, 4, 0);
    let both = (OPEN, OPEN);
    assert!(matches!(
        net.lane_riesenfeld((0, 2), 1, both),
        Err(Error::InvalidParameter {
            name: "bidegree",
            ..
        })
    ));
    assert!(matches!(
        net.limit_points((2, 0), both),
        Err(Error::InvalidParameter {
            name: "bidegree",
            ..
        })
    ));
    assert!(matches!(
        net.lane_riesenfeld((3, 2), 1, both),
        Err(Error::TooFew {
            what: "net rows",
            needed: 4,
            got: 3
        })
    ));
    assert!(matches!(
        net.lane_riesenfeld((1, 4), 1, both),
        Err(Error::TooFew {
            what: "net columns",
            needed: 5,
            got: 4
        })
    ));
    let thin = lattice_net(2, 4, 0);
    assert!(matches!(
        thin.lane_riesenfeld((1, 1), 1, (CLOSED, OPEN)),
        Err(Error::TooFew {
            what: "net rows",
            needed: 3,
            got: 2
        })
    ));
    // Absurd sizes are refused before any work.
    for rounds in [13, 40, usize::MAX] {
        assert!(matches!(
            net.to_f64().lane_riesenfeld((1, 1), rounds, both),
            Err(Error::LimitExceeded { .. })
        ));
    }
    assert!(matches!(
        net.lane_riesenfeld((1 << 20, 1), 1, (CLOSED, CLOSED)),
        Err(Error::LimitExceeded { .. })
    ));
    // Overflow in f64 is reported, not returned as infinities.
    let huge = ControlNet::from_rows(3, 3, vec![Point::new([f64::MAX]); 9]).unwrap();
    assert!(matches!(
        huge.lane_riesenfeld((1, 1), 1, (CLOSED, CLOSED)),
        Err(Error::Overflow { .. })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Random nets, bidegrees, topologies and rounds: the result is the refined surface's net.
    #[test]
    fn random_open_nets_refine_to_the_same_surface(
        p in 1usize..=3,
        qd in 1usize..=3,
        extra in (0usize..=2, 0usize..=2),
        k in 0u32..=2,
        coords in prop::collection::vec(-20i64..=20, 3 * 36),
    ) {
        let (m, n) = (p + 1 + extra.0, qd + 1 + extra.1);
        let points = (0..m * n)
            .map(|t| Point::new([qi(coords[3 * t]), qi(coords[3 * t + 1]), qi(coords[3 * t + 2])]))
            .collect();
        let net = ControlNet::from_rows(m, n, points).unwrap();
        let r = net.lane_riesenfeld((p, qd), k as usize, (OPEN, OPEN)).unwrap();
        let oracle = block(
            &refined(&net, (p, qd), k),
            open_range(m, p, k),
            open_range(n, qd, k),
        );
        prop_assert_eq!(r.to_rows(), oracle);
        // f64 on small integers: every midpoint is a dyadic rational, exact in f64.
        let f = net.to_f64().lane_riesenfeld((p, qd), k as usize, (OPEN, OPEN)).unwrap();
        prop_assert_eq!(f, r.to_f64());
    }
}

// ---------------------------------------------------------------------------------------
// The three-direction box-spline rule on a periodic triangular grid [PPB, §15.7–15.8].

/// A periodic regular triangular grid: c[i][j], indices mod the sizes, with the three
/// directions e₁ = (1, 0), e₂ = (0, 1), e₃ = (−1, −1) [PPB, §15.7]; its triangles are
/// (i, j), (i + 1, j), (i + 1, j + 1) and (i, j), (i + 1, j + 1), (i, j + 1).
pub type Grid<T> = Vec<Vec<T>>;

/// The doubling operator 𝒟: d_{i} = c_{⌊i/2⌋} [PPB, §15.7].
fn double<T: Clone>(c: &Grid<T>) -> Grid<T> {
    let (m, n) = (c.len(), c[0].len());
    (0..2 * m)
        .map(|i| (0..2 * n).map(|j| c[i / 2][j / 2].clone()).collect())
        .collect()
}

/// The averaging operator 𝒜_k: a_i = ½(c_i + c_{i − e_k}), indices mod the grid
/// [PPB, §15.7].
fn average<const D: usize>(c: &Grid<Point<Q, D>>, k: usize) -> Grid<Point<Q, D>> {
    let (m, n) = (c.len() as i64, c[0].len() as i64);
    let e: (i64, i64) = [(1, 0), (0, 1), (-1, -1)][k];
    let half = q(1, 2);
    (0..m)
        .map(|i| {
            (0..n)
                .map(|j| {
                    let (a, b) = ((i - e.0).rem_euclid(m), (j - e.1).rem_euclid(n));
                    (c[i as usize][j as usize].clone() + &c[a as usize][b as usize]) * &half
                })
                .collect()
        })
        .collect()
}

/// One round of the three-direction box-spline rule B_n = 𝒜₁^{n₁}𝒜₂^{n₂}𝒜₃^{n₃}𝒟
/// [PPB, §15.7]: new point 2i sits on old vertex i, new point 2i + e on the midpoint of the
/// old edge from i to i + e for e = (1, 0), (0, 1), (1, 1).
pub fn box_spline_round<const D: usize>(c: &Grid<Point<Q, D>>, n: [usize; 3]) -> Grid<Point<Q, D>> {
    let mut g = double(c);
    // The operators commute; 𝒜₃ first, as 𝓡 = 𝒜₃𝒟.
    for (k, times) in [(2, n[2]), (1, n[1]), (0, n[0])] {
        for _ in 0..times {
            g = average(&g, k);
        }
    }
    g
}

/// Loop's regular rule: the quartic box spline M₂₂₂, B_{112} = (𝒜₁𝒜₂𝒜₃)(𝒜₃𝒟).
pub fn quartic_box_spline_round<const D: usize>(c: &Grid<Point<Q, D>>) -> Grid<Point<Q, D>> {
    box_spline_round(c, [1, 1, 2])
}

fn grid_of_net<const D: usize>(net: &ControlNet<Q, D>) -> Grid<Point<Q, D>> {
    net.to_rows()
}

#[test]
fn box_splines_without_the_third_direction_are_tensor_lane_riesenfeld() {
    let net = lattice_net(4, 5, 2);
    for (n1, n2) in [(1, 1), (2, 1), (2, 2), (3, 3)] {
        let r = net.lane_riesenfeld((n1, n2), 1, (CLOSED, CLOSED)).unwrap();
        assert_eq!(
            box_spline_round(&grid_of_net(&net), [n1, n2, 0]),
            r.to_rows(),
            "B_({n1}, {n2}, 0)"
        );
    }
}

#[test]
fn the_refinement_operator_is_linear_subdivision() {
    let c = grid_of_net(&lattice_net(3, 4, 5));
    let r = box_spline_round(&c, [0, 0, 1]);
    let half = q(1, 2);
    for i in 0..3 {
        for j in 0..4 {
            let (i1, j1) = ((i + 1) % 3, (j + 1) % 4);
            assert_eq!(r[2 * i][2 * j], c[i][j]);
            assert_eq!(r[2 * i + 1][2 * j], (c[i][j].clone() + &c[i1][j]) * &half);
            assert_eq!(r[2 * i][2 * j + 1], (c[i][j].clone() + &c[i][j1]) * &half);
            assert_eq!(
                r[2 * i + 1][2 * j + 1],
                (c[i][j].clone() + &c[i1][j1]) * &half
            );
        }
    }
}

#[test]
fn the_quartic_box_spline_has_loops_regular_masks() {
    // A unit impulse at (3, 3) of an 8 × 8 periodic grid: the weight of c₃₃ in each new
    // point is the mask entry of c₃₃ for that point.
    let c: Grid<Point<Q, 1>> = (0..8)
        .map(|i| {
            (0..8)
                .map(|j| Point::new([qi(i64::from((i, j) == (3, 3)))]))
                .collect()
        })
        .collect();
    let r = quartic_box_spline_round(&c);
    let w = |i: i64, j: i64| r[i.rem_euclid(16) as usize][j.rem_euclid(16) as usize][0].clone();
    // The vertex point: α(6) = 5/8 on the vertex itself, 1/16 = (1 − α)/6 on each of its
    // six neighbours, which see c₃₃ from the directions ±e₁, ±e₂, ±(e₁ + e₂).
    assert_eq!(w(6, 6), q(5, 8));
    for (di, dj) in [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1)] {
        assert_eq!(
            w(6 + 2 * di, 6 + 2 * dj),
            q(1, 16),
            "neighbour ({di}, {dj})"
        );
    }
    for (di, dj) in [(1, -1), (-1, 1), (2, 0), (1, 2)] {
        assert_eq!(
            w(6 + 2 * di, 6 + 2 * dj),
            qi(0),
            "not a neighbour ({di}, {dj})"
        );
    }
    // The edge points: 3/8 at each end of the edge, 1/8 at the two opposite vertices.
    for (di, dj) in [(1, 0), (0, 1), (1, 1), (-1, 0), (0, -1), (-1, -1)] {
        assert_eq!(w(6 + di, 6 + dj), q(3, 8), "edge ({di}, {dj}) at its end");
    }
    // c₃₃ is the vertex opposite the outer edge of each of its six triangles.
    for (a, b) in [
        ((4, 3), (4, 4)),
        ((3, 4), (4, 4)),
        ((2, 2), (2, 3)),
        ((2, 2), (3, 2)),
        ((4, 3), (3, 2)),
        ((3, 4), (2, 3)),
    ] {
        let (i, j) = (a.0 + b.0, a.1 + b.1);
        assert_eq!(w(i, j), q(1, 8), "edge {a:?}–{b:?} opposite c₃₃");
    }
    // Every mask sums to 1: the weights of c₃₃ over the four parities sum to 4.
    let total = (0..16)
        .flat_map(|i| (0..16).map(move |j| (i, j)))
        .fold(qi(0), |a, (i, j)| a + w(i, j));
    assert_eq!(total, qi(4));
}
