//! The geometric fuzz checks: hulls, triangulations and the Voronoi diagram on any `f64`
//! coordinates, checked by the crate's exact checkers, and the predicates against exact
//! rational arithmetic.

use super::{exact, magnitude, nearest, Decoder};
use crate::delaunay::{check_delaunay, dual, find_duplicates, incremental, Triangulation};
use crate::geometry::{
    cmp_dist, cmp_lex, cross_sign, incircle, orient2d, ConstructedPoint, InCircle, Orientation,
    Point2,
};
use crate::hull::{check_encloses, check_strictly_convex_ccw, convex_hull, HullOptions};
use crate::Error;
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use std::cmp::Ordering;

/// At most this many points per input: brute force (Θ(n³)) and Lawson (O(n²)) stay fast.
const MAX_POINTS: usize = 32;

/// The first point with a NaN or infinite coordinate.
fn first_non_finite(pts: &[Point2]) -> Option<usize> {
    pts.iter()
        .position(|p| !(p.x.is_finite() && p.y.is_finite()))
}

/// Asserts that `result` is the error for the first non-finite point.
fn assert_non_finite<T: std::fmt::Debug>(what: &str, result: Result<T, Error>, first: usize) {
    match result {
        Err(Error::NonFinite { index, .. }) if index == first => {}
        other => panic!("{what}: point {first} is not finite, got {other:?}"),
    }
}

/// The indices of the first occurrence of every distinct point.
fn distinct(pts: &[Point2]) -> Vec<usize> {
    let dropped: std::collections::HashSet<usize> =
        find_duplicates(pts).iter().map(|&[d, _]| d).collect();
    (0..pts.len()).filter(|i| !dropped.contains(i)).collect()
}

/// Every hull algorithm, with and without `keep_collinear`.
///
/// NaN and infinities give `Error::NonFinite` naming the first such point. Otherwise,
/// every algorithm returns the same hull; the strict hull passes
/// `check_strictly_convex_ccw` and `check_encloses`, starts at the lexicographically
/// smallest point and names first occurrences only; the keep-collinear hull is the strict
/// hull with exactly the other distinct points on its boundary inserted, in boundary order.
pub fn hull(data: &[u8]) {
    use crate::hull::Algorithm;
    let pts = Decoder::new(data).points(MAX_POINTS);
    let strict = HullOptions::default();
    let keep = HullOptions {
        keep_collinear: true,
    };
    if let Some(first) = first_non_finite(&pts) {
        for a in Algorithm::ALL {
            for o in [strict, keep] {
                assert_non_finite(a.name(), convex_hull(&pts, a, o), first);
            }
        }
        return;
    }
    let run = |o: HullOptions| {
        let hulls: Vec<Vec<usize>> = Algorithm::ALL
            .iter()
            .map(|&a| convex_hull(&pts, a, o).expect("finite points"))
            .collect();
        for (a, h) in Algorithm::ALL.iter().zip(&hulls) {
            assert_eq!(
                h,
                &hulls[0],
                "{} and {} differ",
                a.name(),
                Algorithm::ALL[0].name()
            );
        }
        hulls.into_iter().next().expect("an algorithm")
    };
    let h = run(strict);
    let k = run(keep);
    if let Err(v) = check_strictly_convex_ccw(&pts, &h) {
        panic!("not strictly convex: {v}: {h:?}");
    }
    if let Err(v) = check_encloses(&pts, &h) {
        panic!("does not enclose: {v}: {h:?}");
    }
    let firsts = distinct(&pts);
    assert!(
        h.iter().chain(&k).all(|i| firsts.binary_search(i).is_ok()),
        "a vertex is not a first occurrence"
    );
    if let Some(&lexmin) = firsts.iter().min_by(|&&i, &&j| cmp_lex(pts[i], pts[j])) {
        assert_eq!(
            h[0], lexmin,
            "the hull does not start at the lexicographic minimum"
        );
        assert_eq!(k[0], lexmin, "the keep-collinear hull does not start there");
    } else {
        assert!(h.is_empty() && k.is_empty());
        return;
    }
    check_keep_collinear(&pts, &firsts, &h, &k);
}

/// `k` is `h` with every other distinct boundary point inserted on its edge, in order.
fn check_keep_collinear(pts: &[Point2], firsts: &[usize], h: &[usize], k: &[usize]) {
    // The edges of the strict hull (for two vertices, the segment there and back).
    let edges: Vec<(usize, usize)> = match h.len() {
        0 | 1 => {
            assert_eq!(k, h, "one distinct point");
            return;
        }
        2 => vec![(h[0], h[1]), (h[1], h[0])],
        n => (0..n).map(|i| (h[i], h[(i + 1) % n])).collect(),
    };
    let on_edge = |p: Point2, (a, b): (usize, usize)| {
        let (a, b) = (pts[a], pts[b]);
        let (to_a, to_b) = (cmp_lex(p, a), cmp_lex(p, b));
        orient2d(a, b, p) == Orientation::Collinear
            && to_a != to_b
            && to_a != Ordering::Equal
            && to_b != Ordering::Equal
    };
    let mut expected = Vec::new();
    for &(a, b) in &edges {
        expected.push(a);
        let mut inner: Vec<usize> = firsts
            .iter()
            .copied()
            .filter(|&i| on_edge(pts[i], (a, b)))
            .collect();
        // Along the edge from a: lexicographic order, reversed if b comes before a.
        inner.sort_by(|&i, &j| cmp_lex(pts[i], pts[j]));
        if cmp_lex(pts[a], pts[b]) == Ordering::Greater {
            inner.reverse();
        }
        expected.extend(inner);
    }
    if h.len() == 2 {
        // A segment is listed once, from lexmin to lexmax.
        expected.truncate(expected.iter().position(|&i| i == h[1]).expect("h[1]") + 1);
    }
    assert_eq!(
        k,
        &expected[..],
        "the keep-collinear hull of the strict hull {h:?}"
    );
}

/// Every Delaunay builder: NaN and infinities give `Error::NonFinite` naming the first
/// such point; otherwise `check_delaunay` accepts the triangulation.
pub fn delaunay(data: &[u8]) {
    use crate::delaunay::{triangulate, Algorithm};
    let pts = Decoder::new(data).points(MAX_POINTS);
    let first = first_non_finite(&pts);
    for a in Algorithm::ALL {
        let t = triangulate(&pts, a);
        match first {
            Some(first) => assert_non_finite(a.name(), t, first),
            None => {
                let t = t.expect("finite points");
                if let Err(v) = check_delaunay(&pts, &t) {
                    panic!("{}: {v}", a.name());
                }
            }
        }
    }
}

/// The Voronoi diagram: NaN and infinities give `Error::NonFinite`. Otherwise, against
/// the exact incremental triangulation `t` (checked by `check_delaunay`):
///
/// - one cell per distinct site, duplicates mapped to the cell of their first occurrence;
///   a cell is bounded exactly when there are several sites and its site is not on the
///   keep-collinear hull (Theorem 2.32);
/// - the cells of `dual``(t)` list the triangles around their site, counter-clockwise and
///   consecutive across a shared edge, every incident triangle once; `voronoi` gives
///   every site the same cell (vertices bit for bit, in the same cyclic order, and rays);
/// - every vertex is within `RELATIVE_ERROR · max(|x|, |y|) + 2^-1075` of the exact
///   circumcentre `(x, y)` of its triangle, as [`ConstructedPoint`] promises, beyond the
///   range of `f64` too: it is `BeyondRange` exactly when a coordinate of the exact centre
///   rounds to ±∞, and `vertices` holds it saturated at `±f64::MAX`;
/// - every ray starts at its cell's first or last vertex (or, for collinear sites, at the
///   midpoint of its two sites, within rounding) and its unit direction is perpendicular to
///   its two sites' difference and points away from the triangles.
pub fn voronoi(data: &[u8]) {
    let pts = Decoder::new(data).points(MAX_POINTS);
    let v = crate::delaunay::voronoi(&pts);
    if let Some(first) = first_non_finite(&pts) {
        return assert_non_finite("voronoi", v, first);
    }
    let v = v.expect("finite points");
    let t = incremental(&pts).expect("finite points");
    if let Err(e) = check_delaunay(&pts, &t) {
        panic!("incremental: {e}");
    }
    let d = dual(&pts, &t).expect("a checked Delaunay triangulation");
    let firsts = distinct(&pts);
    let keep = HullOptions {
        keep_collinear: true,
    };
    let hull = crate::hull::monotone_chain(&pts, keep).expect("finite points");
    for diagram in [&v, &d] {
        assert_eq!(diagram.cell_count(), firsts.len());
        let mut sites = diagram.sites.clone();
        sites.sort_unstable();
        assert_eq!(sites, firsts, "one cell per distinct site");
        for (k, &s) in diagram.sites.iter().enumerate() {
            assert_eq!(diagram.cell_of(s), k);
        }
        for [dropped, kept] in find_duplicates(&pts) {
            assert_eq!(diagram.cell_of(dropped), diagram.cell_of(kept));
        }
        let several = firsts.len() > 1;
        for cell in diagram.cells() {
            let bounded = several && !hull.contains(&cell.site);
            assert_eq!(cell.bounded, bounded, "site {}", cell.site);
            assert_eq!(
                cell.rays.is_empty(),
                bounded || !several,
                "site {}",
                cell.site
            );
        }
    }
    for k in 0..d.cell_count() {
        check_fan(&t, d.cell(k));
    }
    for i in 0..pts.len() {
        let (a, b) = (v.cell(v.cell_of(i)), d.cell(d.cell_of(i)));
        assert_eq!((a.site, a.bounded), (b.site, b.bounded));
        assert_eq!(a.rays, b.rays, "the rays of site {}", a.site);
        let va: Vec<Point2> = a.vertices.iter().map(|&k| v.vertices[k]).collect();
        let mut vb: Vec<Point2> = b.vertices.iter().map(|&k| d.vertices[k]).collect();
        if a.bounded && !va.is_empty() {
            let shift = vb.iter().position(|&p| p == va[0]);
            vb.rotate_left(shift.unwrap_or(0));
        }
        assert_eq!(va, vb, "the vertices of site {}", a.site);
    }
    assert_eq!(d.vertices.len(), t.triangle_count());
    for k in 0..t.triangle_count() {
        let [a, b, c] = t.triangle(k).map(|i| pts[i]);
        check_circumcentre(a, b, c, d.vertex(k), d.vertices[k]);
    }
    for cell in d.cells() {
        for (i, ray) in cell.rays.iter().enumerate() {
            check_ray(&pts, &d, cell, ray, i, t.is_empty());
        }
    }
}

/// The cell's vertices are the triangles around its site, each next one across the edge
/// from the site to the previous one's vertex before the site; all incident triangles,
/// each once; around an inner site the fan closes.
fn check_fan(t: &Triangulation, cell: crate::delaunay::Cell<'_>) {
    let s = cell.site;
    let around = |k: usize| {
        let tri = t.triangle(k);
        let at = tri
            .iter()
            .position(|&x| x == s)
            .expect("the triangle holds the site");
        (tri[(at + 1) % 3], tri[(at + 2) % 3])
    };
    let ids = cell.vertices;
    let incident = (0..t.triangle_count())
        .filter(|&k| t.triangle(k).contains(&s))
        .count();
    assert_eq!(
        ids.len(),
        incident,
        "cell of {s}: not every triangle around it"
    );
    let mut seen = ids.to_vec();
    seen.sort_unstable();
    seen.dedup();
    assert_eq!(seen.len(), ids.len(), "cell of {s}: a triangle twice");
    let pairs = if cell.bounded {
        ids.len()
    } else {
        ids.len().saturating_sub(1)
    };
    for i in 0..pairs {
        let (_, before) = around(ids[i]);
        let (next_after, _) = around(ids[(i + 1) % ids.len()]);
        assert_eq!(before, next_after, "cell of {s}: triangles out of order");
    }
}

/// The exact circumcentre of the counter-clockwise triangle a, b, c against vertex `centre`
/// of the diagram, as constructed, and `stored`, its entry in `vertices`: what
/// [`ConstructedPoint`] promises. Each coordinate is within
/// `RELATIVE_ERROR · max(|x|, |y|) + 2^-1075` of the exact `(x, y)` (compared in rationals,
/// so that this holds beyond the range of `f64` too); the point is `BeyondRange` exactly
/// when a coordinate rounds to ±∞; `stored` is the point saturated at `±f64::MAX`.
fn check_circumcentre(a: Point2, b: Point2, c: Point2, centre: ConstructedPoint, stored: Point2) {
    let [ax, ay, bx, by, cx, cy] = [a.x, a.y, b.x, b.y, c.x, c.y].map(exact);
    let (bx, by, cx, cy) = (bx - &ax, by - &ay, cx - &ax, cy - &ay);
    let b2 = &bx * &bx + &by * &by;
    let c2 = &cx * &cx + &cy * &cy;
    let det = (&bx * &cy - &by * &cx) * BigRational::from_integer(2.into());
    assert!(
        det.is_positive(),
        "triangle {a:?} {b:?} {c:?} is not counter-clockwise"
    );
    let want = [
        ax + (&cy * &b2 - &by * &c2) / &det,
        ay + (&bx * &c2 - &cx * &b2) / &det,
    ];
    let beyond = want.iter().any(|w| !nearest(w).is_finite());
    assert_eq!(
        centre.is_beyond_range(),
        beyond,
        "circumcentre of {a:?} {b:?} {c:?}: {centre:?}, exact ({:e}, {:e})",
        nearest(&want[0]),
        nearest(&want[1])
    );
    assert_eq!(
        stored,
        centre.saturating(),
        "the stored vertex of {a:?} {b:?} {c:?}"
    );
    let largest = want[0].abs().max(want[1].abs());
    let tol = largest * exact(ConstructedPoint::RELATIVE_ERROR) + exact(5e-324) / two();
    for (got, want) in centre.wide().iter().zip(&want) {
        let (significand, exponent) = got.to_parts();
        let got = exact(significand) * pow2(exponent);
        let err = (got - want).abs();
        assert!(
            err <= tol,
            "circumcentre of {a:?} {b:?} {c:?}: {centre:?} is {:e} from {:e} (tolerance {:e})",
            nearest(&err),
            nearest(want),
            nearest(&tol)
        );
    }
}

/// 2 as a rational.
fn two() -> BigRational {
    BigRational::from_integer(2.into())
}

/// 2^e, exactly.
fn pow2(e: i32) -> BigRational {
    let p = num_traits::pow(two(), e.unsigned_abs() as usize);
    if e >= 0 {
        p
    } else {
        p.recip()
    }
}

/// √r for r ≥ 0, rounded, without overflow or underflow on the way (+∞ if beyond range).
fn sqrt(r: &BigRational) -> f64 {
    if r.is_zero() {
        return 0.0;
    }
    let bits = r.numer().bits() as i64 - r.denom().bits() as i64;
    let half = bits.div_euclid(2);
    let two = BigRational::from_integer(2.into());
    let power = num_traits::pow(two, (2 * half).unsigned_abs() as usize);
    let scaled = if half >= 0 { r / power } else { r * power };
    let root = nearest(&scaled).sqrt();
    // 2^half in at most two normal steps (|half| ≤ about 2200 for the inputs here).
    let mut x = root;
    let mut e = half;
    while e != 0 {
        let step = e.clamp(-1000, 1000);
        x *= f64::from_bits(((step + 1023) as u64) << 52);
        e -= step;
    }
    x
}

/// Ray `index` of cell `cell`: its origin and its direction.
fn check_ray(
    pts: &[Point2],
    v: &crate::delaunay::Voronoi,
    cell: crate::delaunay::Cell<'_>,
    ray: &crate::delaunay::Ray,
    index: usize,
    collinear: bool,
) {
    let [s, q] = ray.sites;
    assert_eq!(s, cell.site, "a ray of cell {} names site {s}", cell.site);
    assert_ne!(pts[s], pts[q], "a ray between equal sites");
    let (p, q) = (pts[s], pts[q]);
    if collinear {
        // The midpoint, rounded once (halved first where the sum overflows).
        for (got, a, b) in [(ray.origin.x, p.x, q.x), (ray.origin.y, p.y, q.y)] {
            let want = (exact(a) + exact(b)) / BigRational::from_integer(2.into());
            let err = magnitude(&(exact(got) - &want));
            let tol = f64::EPSILON * magnitude(&want) + 5e-324;
            assert!(
                err <= tol,
                "the midpoint of {p:?} {q:?}: {got:e}, off by {err:e}"
            );
        }
    } else {
        // The arriving ray starts at the first vertex, the leaving one at the last.
        let end = if index == 0 {
            cell.vertices.first()
        } else {
            cell.vertices.last()
        };
        assert_eq!(
            Some(ray.origin),
            end.map(|&k| v.vertices[k]),
            "ray {index} of cell {s} does not start at its end vertex"
        );
        assert!(index < 2, "cell {s} has more than two rays");
    }
    // Unit length and perpendicular to q - p, to rounding: compare with the exact
    // difference scaled to unit size (a power of two, so exact).
    let dx = exact(q.x) - exact(p.x);
    let dy = exact(q.y) - exact(p.y);
    let (u, w) = (exact(ray.direction.x), exact(ray.direction.y));
    let len = sqrt(&(&dx * &dx + &dy * &dy));
    let dot = magnitude(&(&u * &dx + &w * &dy));
    assert!(
        dot <= 8.0 * f64::EPSILON * len,
        "ray {ray:?} is not perpendicular to its sites (dot {dot:e}, length {len:e})"
    );
    let norm = nearest(&(&u * &u + &w * &w));
    assert!(
        (norm - 1.0).abs() <= 8.0 * f64::EPSILON,
        "ray {ray:?} is not a unit vector"
    );
    if !collinear {
        // The arriving ray lies on the bisector of the hull edge s -> q, the leaving one on
        // that of r -> s (q and r the ray's other site): the triangles are on the edge's
        // left, so the ray points to its right.
        let cross = &dx * &w - &dy * &u;
        let outwards = if index == 0 {
            cross.is_negative()
        } else {
            cross.is_positive()
        };
        assert!(outwards, "ray {index} {ray:?} points inwards");
    }
}

/// The coordinates as integers with one common power-of-two scale: every finite `f64` is
/// an integer times 2^-1074, so multiplying all by one power of two is exact, and the signs
/// of the predicates' polynomials (homogeneous) do not change. Integers instead of rationals
/// keep the exact oracle fast (no gcd per operation).
fn common_integers(xs: &[f64]) -> Vec<BigInt> {
    let parts: Vec<(BigInt, u64)> = xs
        .iter()
        .map(|&x| {
            let r = exact(x);
            // The denominator of a finite double is a power of two.
            let shift = r.denom().bits() - 1;
            (r.numer().clone(), shift)
        })
        .collect();
    let top = parts.iter().map(|&(_, s)| s).max().unwrap_or(0);
    parts.into_iter().map(|(n, s)| n << (top - s)).collect()
}

/// [`orient2d`], `incircle`, `cmp_dist` and `cross_sign` on four decoded points
/// against the sign of the exact expression they stand for, evaluated on big integers.
pub fn predicates(data: &[u8]) {
    let pts = Decoder::new(data).points(4);
    let [a, b, c, d] = pts[..] else {
        return;
    };
    if first_non_finite(&pts).is_some() {
        return;
    }
    let v = common_integers(&[a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y]);
    let [ax, ay, bx, by, cx, cy, dx, dy] = [0, 1, 2, 3, 4, 5, 6, 7].map(|i| &v[i]);
    let cross = |ux: &BigInt, uy: &BigInt, vx: &BigInt, vy: &BigInt| ux * vy - uy * vx;
    let orientation = |r: BigInt| match r.sign() {
        Sign::Plus => Orientation::CounterClockwise,
        Sign::Minus => Orientation::Clockwise,
        Sign::NoSign => Orientation::Collinear,
    };
    let order = |r: BigInt| match r.sign() {
        Sign::Plus => Ordering::Greater,
        Sign::Minus => Ordering::Less,
        Sign::NoSign => Ordering::Equal,
    };
    let o = cross(&(bx - ax), &(by - ay), &(cx - ax), &(cy - ay));
    assert_eq!(orient2d(a, b, c), orientation(o), "orient2d{:?}", (a, b, c));
    let turn = cross(&(bx - ax), &(by - ay), &(dx - cx), &(dy - cy));
    assert_eq!(
        cross_sign(a, b, c, d),
        orientation(turn),
        "cross_sign{:?}",
        (a, b, c, d)
    );
    let d2 = |px: &BigInt, py: &BigInt, qx: &BigInt, qy: &BigInt| {
        (qx - px) * (qx - px) + (qy - py) * (qy - py)
    };
    let dist = d2(ax, ay, bx, by) - d2(cx, cy, dx, dy);
    assert_eq!(
        cmp_dist(a, b, c, d),
        order(dist),
        "cmp_dist{:?}",
        (a, b, c, d)
    );
    // The lifted determinant, relative to d: positive when d is inside the circle of the
    // counter-clockwise a, b, c.
    let lift = |x: &BigInt, y: &BigInt| {
        let (x, y) = (x - dx, y - dy);
        let l = &x * &x + &y * &y;
        (x, y, l)
    };
    let (px, py, pl) = lift(ax, ay);
    let (qx, qy, ql) = lift(bx, by);
    let (rx, ry, rl) = lift(cx, cy);
    let det = pl * cross(&qx, &qy, &rx, &ry)
        + ql * cross(&rx, &ry, &px, &py)
        + rl * cross(&px, &py, &qx, &qy);
    let expected = match det.sign() {
        Sign::Plus => InCircle::Inside,
        Sign::Minus => InCircle::Outside,
        Sign::NoSign => InCircle::On,
    };
    assert_eq!(incircle(a, b, c, d), expected, "incircle{:?}", (a, b, c, d));
}
