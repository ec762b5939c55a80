//! The largest empty circle [RD, §2.4, problem 5] against an exact brute force in
//! `BigRational`, on small random, degenerate and hostile point sets.
//!
//! The oracle uses neither the library's triangulation nor its hull. f(x), the distance
//! from x to the nearest input point, is maximal over the hull at a Voronoi vertex inside
//! the hull, at a point where a Voronoi edge crosses the hull's boundary, or at a hull
//! vertex. So the maximum of f² is the maximum of f²(X) over the circumcentres X of all
//! non-collinear triples that lie in the closed hull, over all points X of the hull's
//! boundary equidistant from two input points, and 0: every such X is in the hull (so f(X)
//! is at most the maximum), and the true maximiser is among them. The hull is the
//! intersection of the closed half-planes left of every supporting line `i → j` (no point
//! strictly right of it), decided exactly.
//!
//! The algorithm's answer is then rebuilt exactly from its sites (three: their
//! circumcentre; two: the boundary point equidistant from both nearest to the returned
//! centre; one: the point itself) and must be in the hull, empty (no point strictly
//! closer to the centre than its sites), and of squared radius equal to the oracle's
//! maximum; its rounded centre and radius must be close to the exact ones.

use compgeo::gen::{points, PointKind};
use compgeo::geometry::ConstructedPoint;
use compgeo::geometry::Point2;
use compgeo::proximity::{largest_empty_circle, EmptyCircle};
use num_bigint::BigInt as Z;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use proptest::prelude::*;

type Q = BigRational;

fn q(v: f64) -> Q {
    Q::from_float(v).expect("finite")
}

/// A rational point `(x / d, y / d)` with `d > 0` (homogeneous coordinates on the
/// integer grid of the input: exact rational arithmetic without gcds, which on numbers of
/// thousands of bits would make the brute force too slow).
#[derive(Debug, Clone)]
struct H {
    x: Z,
    y: Z,
    d: Z,
}

/// A non-negative rational `num / den`, `den > 0`.
#[derive(Debug, Clone)]
struct Val {
    num: Z,
    den: Z,
}

impl Val {
    fn cmp(&self, o: &Val) -> std::cmp::Ordering {
        (&self.num * &o.den).cmp(&(&o.num * &self.den))
    }

    fn to_q(&self) -> Q {
        Q::new(self.num.clone(), self.den.clone())
    }
}

impl H {
    fn point(x: &Z, y: &Z) -> H {
        H {
            x: x.clone(),
            y: y.clone(),
            d: Z::one(),
        }
    }

    /// `|self − p|²` for a grid point `p`.
    fn dist2(&self, p: &(Z, Z)) -> Val {
        let (dx, dy) = (&self.x - &p.0 * &self.d, &self.y - &p.1 * &self.d);
        Val {
            num: &dx * &dx + &dy * &dy,
            den: &self.d * &self.d,
        }
    }
}

/// The brute force on the distinct input points, all on one integer grid.
struct Oracle {
    pts: Vec<(Z, Z)>,
    /// The grid's spacing: input coordinates are `pts · unit`.
    unit: Q,
    /// Ordered pairs `(i, j)` of distinct points with no point strictly right of `i → j`.
    supports: Vec<(usize, usize)>,
}

fn cross(o: &(Z, Z), a: &(Z, Z), b: &(Z, Z)) -> Z {
    (&a.0 - &o.0) * (&b.1 - &o.1) - (&a.1 - &o.1) * (&b.0 - &o.0)
}

impl Oracle {
    /// `None` if the distinct points are all collinear (or fewer than three).
    fn new(points: &[Point2]) -> Option<Oracle> {
        // Every double is an integer times a power of two: take the finest.
        let unit = points
            .iter()
            .flat_map(|p| [q(p.x), q(p.y)])
            .map(|v| Q::new(Z::one(), v.denom().clone()))
            .min()
            .expect("points");
        let mut pts: Vec<(Z, Z)> = Vec::new();
        for p in points {
            let g = |v: f64| (q(v) / &unit).to_integer();
            let p = (g(p.x), g(p.y));
            if !pts.contains(&p) {
                pts.push(p);
            }
        }
        let n = pts.len();
        let mut supports = Vec::new();
        let mut flat = true;
        for i in 0..n {
            for j in 0..n {
                if i == j {
                    continue;
                }
                let sides: Vec<Z> = pts.iter().map(|k| cross(&pts[i], &pts[j], k)).collect();
                flat &= sides.iter().all(Zero::is_zero);
                if sides.iter().all(|s| !s.is_negative()) {
                    supports.push((i, j));
                }
            }
        }
        (!flat).then_some(Oracle {
            pts,
            unit,
            supports,
        })
    }

    /// The grid point of an input point.
    fn grid(&self, p: Point2) -> (Z, Z) {
        let g = |v: f64| (q(v) / &self.unit).to_integer();
        (g(p.x), g(p.y))
    }

    fn in_hull(&self, x: &H) -> bool {
        self.supports.iter().all(|&(i, j)| {
            let (a, b) = (&self.pts[i], &self.pts[j]);
            let side = (&b.0 - &a.0) * (&x.y - &a.1 * &x.d) - (&b.1 - &a.1) * (&x.x - &a.0 * &x.d);
            !side.is_negative()
        })
    }

    /// f²(x): the squared distance to the nearest point.
    fn nearest2(&self, x: &H) -> Val {
        self.pts
            .iter()
            .map(|p| x.dist2(p))
            .min_by(Val::cmp)
            .expect("points")
    }

    /// The points of the hull's boundary equidistant from `s` and `w`: on each supporting
    /// segment `p → r`, `t = ((m − p) · u) / ((r − p) · u)` in `[0, 1]` with `u = w − s`
    /// and `m = (s + w) / 2`.
    fn crossings(&self, s: &(Z, Z), w: &(Z, Z)) -> Vec<H> {
        let (ux, uy) = (&w.0 - &s.0, &w.1 - &s.1);
        let mut out = Vec::new();
        for &(i, j) in &self.supports {
            let (p, r) = (&self.pts[i], &self.pts[j]);
            let (gx, gy) = (&r.0 - &p.0, &r.1 - &p.1);
            // t = num / (2 den) with m − p = ((s + w) − 2p) / 2.
            let mut den = &gx * &ux + &gy * &uy;
            let two = Z::from(2);
            let mut num = (&s.0 + &w.0 - &two * &p.0) * &ux + (&s.1 + &w.1 - &two * &p.1) * &uy;
            if den.is_zero() {
                continue;
            }
            if den.is_negative() {
                (den, num) = (-den, -num);
            }
            let d = &two * &den;
            if !num.is_negative() && num <= d {
                out.push(H {
                    x: &d * &p.0 + &num * &gx,
                    y: &d * &p.1 + &num * &gy,
                    d,
                });
            }
        }
        out
    }

    /// The largest f² over all candidates.
    fn max_squared_radius(&self) -> Val {
        let n = self.pts.len();
        let mut best = Val {
            num: Z::zero(),
            den: Z::one(),
        };
        let mut offer = |v: Val| {
            if v.cmp(&best).is_gt() {
                best = v;
            }
        };
        for i in 0..n {
            for j in i + 1..n {
                for k in j + 1..n {
                    if let Some(x) = circumcentre(&self.pts[i], &self.pts[j], &self.pts[k]) {
                        if self.in_hull(&x) {
                            offer(self.nearest2(&x));
                        }
                    }
                }
                for x in self.crossings(&self.pts[i], &self.pts[j]) {
                    offer(self.nearest2(&x));
                }
            }
        }
        best
    }

    /// A candidate's exact centre as rationals in input units.
    fn to_q(&self, x: &H) -> (Q, Q) {
        let d = Q::from_integer(x.d.clone());
        (
            Q::from_integer(x.x.clone()) / &d * &self.unit,
            Q::from_integer(x.y.clone()) / &d * &self.unit,
        )
    }
}

/// `2 (b − a) · X = |b|² − |a|²`, `2 (c − a) · X = |c|² − |a|²` by Cramer's rule; `None`
/// for collinear points.
fn circumcentre(a: &(Z, Z), b: &(Z, Z), c: &(Z, Z)) -> Option<H> {
    let two = Z::from(2);
    let norm = |p: &(Z, Z)| &p.0 * &p.0 + &p.1 * &p.1;
    let (m11, m12) = (&two * (&b.0 - &a.0), &two * (&b.1 - &a.1));
    let (m21, m22) = (&two * (&c.0 - &a.0), &two * (&c.1 - &a.1));
    let (r1, r2) = (norm(b) - norm(a), norm(c) - norm(a));
    let det = &m11 * &m22 - &m12 * &m21;
    let (x, y) = (&r1 * &m22 - &m12 * &r2, &m11 * &r2 - &r1 * &m21);
    match det.sign() {
        num_bigint::Sign::NoSign => None,
        num_bigint::Sign::Plus => Some(H { x, y, d: det }),
        num_bigint::Sign::Minus => Some(H {
            x: -x,
            y: -y,
            d: -det,
        }),
    }
}

fn dist2_q(a: &(Q, Q), b: &(Q, Q)) -> Q {
    let (dx, dy) = (&a.0 - &b.0, &a.1 - &b.1);
    &dx * &dx + &dy * &dy
}

/// Runs the algorithm and checks its answer against the brute force; returns the exact
/// squared radius it achieved.
fn check(points: &[Point2]) -> Q {
    check_circle(points, &largest_empty_circle(points).expect("valid input"))
}

/// Checks an answer `c` for `points` (from the library or the command line) against the
/// brute force; returns the exact squared radius it achieved.
pub(crate) fn check_circle(points: &[Point2], c: &EmptyCircle) -> Q {
    let Some(oracle) = Oracle::new(points) else {
        // Collinear sets: the widest gap, checked elsewhere (tests/proximity.rs).
        return Q::zero();
    };
    let max = oracle.max_squared_radius();
    let sites: Vec<(Z, Z)> = c.sites.iter().map(|&i| oracle.grid(points[i])).collect();
    let returned = (q(c.centre.x), q(c.centre.y));
    let centre = match sites.len() {
        3 => circumcentre(&sites[0], &sites[1], &sites[2]).expect("a proper triangle"),
        // The bisector of two sites can meet the boundary twice, and the answer does not
        // name the hull edge: take the equidistant boundary point nearest the returned
        // centre among those that are empty with the largest radius (two such points can
        // be closer to each other than the centre's rounding).
        2 => oracle
            .crossings(&sites[0], &sites[1])
            .into_iter()
            .filter(|x| {
                let r2 = x.dist2(&sites[0]);
                r2.cmp(&max).is_eq() && oracle.nearest2(x).cmp(&r2).is_eq()
            })
            .min_by(|a, b| {
                dist2_q(&oracle.to_q(a), &returned).cmp(&dist2_q(&oracle.to_q(b), &returned))
            })
            .unwrap_or_else(|| {
                panic!(
                    "no largest empty circle through sites {:?}: {points:?}",
                    c.sites
                )
            }),
        1 => H::point(&sites[0].0, &sites[0].1),
        k => panic!("{k} sites for {points:?}"),
    };
    let r2 = centre.dist2(&sites[0]);
    for s in &sites {
        assert!(
            centre.dist2(s).cmp(&r2).is_eq(),
            "sites not on one circle: {points:?}"
        );
    }
    assert!(
        oracle.in_hull(&centre),
        "centre outside the hull: {points:?}"
    );
    assert!(
        oracle.nearest2(&centre).cmp(&r2).is_eq(),
        "a point strictly inside: {points:?}"
    );
    assert!(
        r2.cmp(&max).is_eq(),
        "not the largest empty circle: {points:?} gave {c:?}"
    );
    // In input units from here on.
    let r2 = r2.to_q() * &oracle.unit * &oracle.unit;
    let centre = oracle.to_q(&centre);
    // The radius within its stated relative error 2^-51 of the exact one (so its square
    // within (1 ± 2^-51)² of r², bounded by 1 ± 2^-49.9: 1 ± 2^-49 is safe), at every
    // magnitude; the centre within a few rounding errors of the configuration (the
    // tolerance allows for mild conditioning), or of the subnormal spacing 2^-1074 where
    // the values themselves are subnormal.
    let radius = crate::common::wide_q(c.radius);
    let tol = q(2f64.powi(-49));
    let one = Q::one();
    assert!(
        &radius * &radius <= &r2 * (&one + &tol) && &radius * &radius >= &r2 * (&one - &tol),
        "radius {} for exact r² {}: {points:?}",
        c.radius,
        r2.to_f64().unwrap_or(f64::NAN),
    );
    // The centre: within the stated error of the exact one, coordinate by coordinate.
    let m = centre.0.abs().max(centre.1.abs());
    let bound =
        q(ConstructedPoint::RELATIVE_ERROR) * m + q(f64::from_bits(1)) / Q::from_integer(2.into());
    for (got, exact) in [(&returned.0, &centre.0), (&returned.1, &centre.1)] {
        assert!(
            (got - exact).abs() <= bound,
            "centre {:?} off: {points:?}",
            c.centre
        );
    }
    r2
}

fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
    v.iter().map(|&p| Point2::from(p)).collect()
}

// ---------------------------------------------------------------- regressions

#[test]
fn hostile_tiny_triangle_beside_a_point_at_1e300() {
    // Was a circle with input points strictly inside; its centre was also rounded to
    // (0, 1e-300) because the 1e-300 edge underflowed in the circumcentre's scaling.
    let p = pts(&[(0.0, 0.0), (1e-300, 0.0), (0.0, 1e-300), (1e300, 1e300)]);
    let r2 = check(&p);
    assert!(r2 > q(1e299) * q(1e299));
}

#[test]
fn hostile_star_of_1e300_1e_300_and_subnormals() {
    // Was a circle with input points strictly inside.
    let p = pts(&[
        (1e300, 1e-300),
        (1e-300, 1e300),
        (0.0, 0.0),
        (1e-300, 1e-300),
        (-1e300, 5e-324),
        (5e-324, -1e300),
    ]);
    let r2 = check(&p);
    assert!(r2 > q(1e299) * q(1e299));
}

// ---------------------------------------------------------------- hand-picked degeneracies

#[test]
fn voronoi_vertex_exactly_on_a_hull_edge() {
    // A right triangle: its circumcentre is the hypotenuse's midpoint, on the hull, where
    // the walk along the hypotenuse meets three cells at one point.
    assert_eq!(check(&pts(&[(0.0, 0.0), (4.0, 0.0), (0.0, 2.0)])), q(5.0));
    // A rectangle's corners are cocircular: every candidate ties at the centre.
    assert_eq!(
        check(&pts(&[(0.0, 0.0), (6.0, 0.0), (6.0, 2.0), (0.0, 2.0)])),
        q(10.0)
    );
}

#[test]
fn circumcentre_beyond_a_collinear_last_hull_point() {
    // The hull starts at (-4, 0) and ends at (-4, 1), in the middle of its last edge: the
    // circumcentre (-4, 7) of (0, 4), (-4, 2), (-1, 3) lies on the line of that edge,
    // outside the hull, and must not be taken (found by proptest; the answer is a
    // crossing of radius below 5).
    let p = pts(&[
        (-1.0, 3.0),
        (-4.0, 1.0),
        (-4.0, 2.0),
        (0.0, 4.0),
        (-4.0, 0.0),
    ]);
    assert!(check(&p) < q(25.0));
    // The same with the collinear points on the first edge instead.
    let p = pts(&[
        (0.0, 0.0),
        (0.0, -1.0),
        (0.0, -2.0),
        (4.0, 0.0),
        (2.0, -3.0),
    ]);
    check(&p);
}

#[test]
fn an_obtuse_triangle_and_collinear_hull_points() {
    // The circumcentre is outside; the best centre is on the long edge, which carries
    // collinear hull points.
    check(&pts(&[(0.0, 0.0), (4.0, 0.0), (2.0, 0.5)]));
    check(&pts(&[
        (0.0, 0.0),
        (1.0, 0.0),
        (2.0, 0.0),
        (3.0, 0.0),
        (4.0, 0.0),
        (2.0, 0.5),
    ]));
    // Duplicates change nothing.
    check(&pts(&[
        (0.0, 0.0),
        (4.0, 0.0),
        (2.0, 0.5),
        (4.0, 0.0),
        (0.0, 0.0),
    ]));
}

#[test]
fn near_ties_a_few_ulps_apart() {
    // Two nearly equal circles: a unit square whose corner is moved by one ulp either way;
    // and points one ulp apart.
    let up = 1.0f64.next_up();
    let down = 1.0f64.next_down();
    for v in [up, down] {
        check(&pts(&[
            (0.0, 0.0),
            (1.0, 0.0),
            (v, 1.0),
            (0.0, 1.0),
            (3.0, 0.5),
        ]));
        check(&pts(&[
            (0.0, 0.0),
            (v, 0.0),
            (1.0, 0.0),
            (0.5, 2.0),
            (0.5, -2.0),
        ]));
    }
}

#[test]
fn small_generated_sets_of_every_degenerate_kind() {
    for kind in [
        PointKind::UniformDisk,
        PointKind::Grid,
        PointKind::RotatedGrid,
        PointKind::Cocircular,
        PointKind::Parabola,
        PointKind::Clustered,
    ] {
        for n in [3, 5, 8] {
            for seed in 0..2 {
                check(&points(kind, n, seed).unwrap());
            }
        }
    }
}

#[test]
fn scaling_by_a_power_of_two_changes_nothing() {
    // Every decision is invariant under an exact scaling; so is the tie-breaking order.
    let base = pts(&[
        (0.0, 0.0),
        (5.0, 1.0),
        (7.0, 6.0),
        (2.0, 8.0),
        (-1.0, 4.0),
        (3.0, 3.0),
    ]);
    let sorted = |mut v: Vec<usize>| {
        v.sort_unstable();
        v
    };
    let c = largest_empty_circle(&base).unwrap();
    for e in [-1060, -1000, -300, 300, 1000] {
        let s = |v: f64| v * 2f64.powi(e.max(-1000)) * 2f64.powi(e - e.max(-1000));
        let scaled: Vec<Point2> = base.iter().map(|p| Point2::new(s(p.x), s(p.y))).collect();
        let d = largest_empty_circle(&scaled).unwrap();
        // (The triangulation may list the triangle from another vertex.)
        assert_eq!(sorted(d.sites), sorted(c.sites.clone()), "2^{e}");
        if e > -1000 {
            // The radius is rounded from the exact squared radius: it scales exactly.
            assert_eq!(d.radius, c.radius.mul(s(1.0).into()), "2^{e}");
        }
        check(&scaled);
    }
}

// ---------------------------------------------------------------- properties

/// A magnitude for a whole set, or for one point of a mixed set.
fn magnitude() -> impl Strategy<Value = f64> {
    prop::sample::select(vec![1.0, 1e-300, 1e300, 2f64.powi(-1040), 1e150])
}

/// Small integers times an exact power of two: grids, collinear runs, cocircular
/// quadruples and duplicates, at any magnitude.
fn integer_set() -> impl Strategy<Value = Vec<Point2>> {
    (
        prop::collection::vec((-6i32..=6, -6i32..=6), 3..9),
        prop::sample::select(vec![0, -1070, -900, 900, 960]),
    )
        .prop_map(|(v, e)| {
            let s = |k: i32| k as f64 * 2f64.powi(e.max(-1000)) * 2f64.powi(e - e.max(-1000));
            v.into_iter()
                .map(|(x, y)| Point2::new(s(x), s(y)))
                .collect()
        })
}

/// Uniform floats of one magnitude.
fn float_set() -> impl Strategy<Value = Vec<Point2>> {
    (
        prop::collection::vec((-1.0f64..1.0, -1.0f64..1.0), 3..9),
        magnitude(),
    )
        .prop_map(|(v, s)| {
            v.into_iter()
                .map(|(x, y)| Point2::new(x * s, y * s))
                .collect()
        })
}

/// Each point at its own magnitude: 1e300 next to 1e-300 and subnormals.
fn mixed_set() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((-4i32..=4, -4i32..=4, magnitude(), magnitude()), 3..7).prop_map(|v| {
        v.into_iter()
            .map(|(x, y, sx, sy)| Point2::new(x as f64 * sx, y as f64 * sy))
            .collect()
    })
}

/// Lattice points of the circle x² + y² = 25 and its centre, some nudged by ulps: exact and
/// near ties between circumcircles and crossings.
fn cocircular_set() -> impl Strategy<Value = Vec<Point2>> {
    const CIRCLE: [(f64, f64); 12] = [
        (5.0, 0.0),
        (4.0, 3.0),
        (3.0, 4.0),
        (0.0, 5.0),
        (-3.0, 4.0),
        (-4.0, 3.0),
        (-5.0, 0.0),
        (-4.0, -3.0),
        (-3.0, -4.0),
        (0.0, -5.0),
        (3.0, -4.0),
        (4.0, -3.0),
    ];
    (
        proptest::sample::subsequence(CIRCLE.to_vec(), 3..8),
        prop::collection::vec(-1i32..=1, 8),
        any::<bool>(),
    )
        .prop_map(|(v, nudges, centre)| {
            let mut out: Vec<Point2> = v
                .into_iter()
                .zip(nudges)
                .map(|((x, y), k)| {
                    let x = match k {
                        1 => f64::next_up(x),
                        -1 => f64::next_down(x),
                        _ => x,
                    };
                    Point2::new(x, y)
                })
                .collect();
            if centre {
                out.push(Point2::new(0.0, 0.0));
            }
            out
        })
}

/// Any finite bit patterns.
fn bits_set() -> impl Strategy<Value = Vec<Point2>> {
    prop::collection::vec((any::<u64>(), any::<u64>()), 3..6).prop_map(|v| {
        let f = |b: u64| {
            let x = f64::from_bits(b);
            if x.is_finite() {
                x
            } else {
                0.0
            }
        };
        v.into_iter()
            .map(|(x, y)| Point2::new(f(x), f(y)))
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn integer_sets_match_the_brute_force(p in integer_set()) {
        check(&p);
    }

    #[test]
    fn float_sets_match_the_brute_force(p in float_set()) {
        check(&p);
    }

    #[test]
    fn cocircular_sets_match_the_brute_force(p in cocircular_set()) {
        check(&p);
    }
}

proptest! {
    // Rationals of thousands of bits: fewer cases.
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn mixed_magnitudes_match_the_brute_force(p in mixed_set()) {
        check(&p);
    }

    #[test]
    fn arbitrary_bit_patterns_match_the_brute_force(p in bits_set()) {
        check(&p);
    }
}
