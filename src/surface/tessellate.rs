//! Tessellation: any surface in R³ as a triangle mesh with normals, for viewers and export.
//!
//! The problem: a mesh that a viewer can draw. The idea: evaluate the surface on a grid of
//! parameters (uniform over the domain, or given: a B-spline surface passes its knots so that
//! the mesh follows its pieces), split every grid cell into two triangles along its shorter
//! diagonal in 3D (the better of the two triangulations of a nearly planar quad), and attach
//! to every vertex the unit normal c_u × c_v of the surface there, computed exactly in the
//! surface's scalar before rounding. Where that cross product vanishes (a collapsed edge, a
//! singular parametrisation) the vertex takes the normalised sum of the normals of the grid
//! cells around it (each the cross product of the cell's diagonals, which a cell with one
//! collapsed edge still has), and a vertex none of whose cells has one keeps the zero vector
//! (`TriangleMesh::normals` says so).
//!
//! Vertices are numbered row by row: the vertex of (uᵢ, vⱼ) is i·(number of v samples) + j,
//! and every triangle is counter-clockwise seen from the side c_u × c_v points to.
//!
//! # Complexity
//!
//! Θ(N·E) time for N = (number of u samples)·(number of v samples) vertices and E the cost of
//! one evaluation and two partial derivatives, Θ(N) space for the mesh.

use super::normal::cross;
use super::traits::{SurfaceDerivative, SurfaceDomain};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::{Domain, Point, Scalar};
use crate::{limits, Error, Result};

/// Tessellation, declared.
pub(crate) const TESSELLATE: Declaration = Declaration {
    problem: "surface",
    name: "tessellate",
    function: "surface::tessellate",
    file: "src/surface/tessellate.rs",
    summary: "a grid of samples as a triangle mesh with the surface's unit normals",
    time: "Θ(N·E) for N vertices and E the cost of an evaluation",
    space: "Θ(N)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly three surface evaluations per vertex (the point and the two first partials)",
    source: "[FJ-surfaces, §2]",
    claims: &[on(
        "random-samples",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// A triangle mesh in `f64`: vertex positions, one normal per vertex, and triangles as
/// triples of vertex indices, counter-clockwise seen from the normals' side.
#[derive(Clone, Debug, PartialEq)]
pub struct TriangleMesh {
    /// The vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// One unit normal per vertex, or the zero vector where neither the surface nor any
    /// grid cell around the vertex has a normal (every adjacent cell degenerate).
    pub normals: Vec<[f64; 3]>,
    /// The triangles, as indices into `positions`.
    pub triangles: Vec<[usize; 3]>,
}

/// The mesh of `surface` on a uniform grid of `u_segments` × `v_segments` cells over its
/// domain (over [0, 1]² in a parameter whose domain is the whole line, as for a Bézier
/// patch, whose net describes that square). See [`tessellate_at_with`].
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"segments"` if either count is zero;
/// [`Error::LimitExceeded`] beyond [`MAX_SAMPLES`](crate::limits::MAX_SAMPLES) vertices;
/// otherwise as [`tessellate_at_with`].
///
/// # Complexity
///
/// Θ(N·E) for N vertices and E the cost of an evaluation in time, Θ(N) in space; here
/// N = (`u_segments` + 1)(`v_segments` + 1).
///
/// ```
/// use compgeo::spline::Point;
/// use compgeo::surface::{tessellate, BezierPatch, ControlNet};
///
/// // The bilinear patch of z = xy over the unit square.
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let net = ControlNet::new(vec![
///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
///     vec![p(1.0, 0.0, 0.0), p(1.0, 1.0, 1.0)],
/// ])?;
/// let mesh = tessellate(&BezierPatch::new(net)?, 4, 2)?;
/// assert_eq!((mesh.positions.len(), mesh.triangles.len()), (5 * 3, 4 * 2 * 2));
/// assert_eq!(mesh.positions[5 * 3 - 1], [1.0, 1.0, 1.0]);
/// assert_eq!(mesh.normals[0], [0.0, 0.0, 1.0]); // c_u × c_v at (0, 0)
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn tessellate<S: Scalar, F: SurfaceDerivative<S, 3>>(
    surface: &F,
    u_segments: usize,
    v_segments: usize,
) -> Result<TriangleMesh> {
    if u_segments == 0 || v_segments == 0 {
        return Err(Error::InvalidParameter {
            name: "segments",
            reason: format!(
                "a grid needs at least one cell each way, got {u_segments} × {v_segments}"
            ),
        });
    }
    let vertices = (u_segments as u128 + 1) * (v_segments as u128 + 1);
    limits::SAMPLES.check(vertices)?;
    let SurfaceDomain { u, v } = surface.domain();
    let us = uniform(&u, u_segments);
    let vs = uniform(&v, v_segments);
    tessellate_at_with(surface, &us, &vs, &mut NoCount)
}

/// The mesh of `surface` at the grid of parameters `us` × `vs`, counting one
/// [`arithmetic_operation`](Counter::arithmetic_operation) per evaluation of a point or a
/// first partial derivative (three per vertex).
///
/// Idea: the vertex of (uᵢ, vⱼ) is c(uᵢ, vⱼ) and its normal the unit vector of
/// c_u × c_v there, computed in `S` and then rounded (so a normal that vanishes exactly is
/// known to vanish); each grid cell becomes two counter-clockwise triangles split along its
/// shorter diagonal; a vertex without a surface normal takes the normalised sum of its
/// cells' normals (the cross products of their diagonals).
///
/// # Errors
///
/// [`Error::InvalidParameter`] named `"samples"` if `us` or `vs` has fewer than two values
/// or is not strictly increasing; [`Error::LimitExceeded`] beyond
/// [`MAX_SAMPLES`](crate::limits::MAX_SAMPLES) vertices; the surface's own errors (a
/// parameter outside its domain); [`Error::Overflow`] if, with `f64`, a position is beyond
/// the double range.
///
/// # Complexity
///
/// Θ(N·E) for N vertices and E the cost of an evaluation in time, and Θ(N) in space.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::spline::Point;
/// use compgeo::surface::{tessellate_at_with, BezierPatch, ControlNet};
///
/// let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
/// let net = ControlNet::new(vec![vec![p(0.0, 0.0), p(0.0, 1.0)], vec![p(1.0, 0.0), p(1.0, 1.0)]])?;
/// let mut c = Counts::default();
/// let mesh = tessellate_at_with(&BezierPatch::new(net)?, &[0.0, 0.5, 1.0], &[0.0, 1.0], &mut c)?;
/// assert_eq!((mesh.triangles.len(), c.arithmetic_operations), (4, 3 * 6));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn tessellate_at_with<S: Scalar, F: SurfaceDerivative<S, 3>, C: Counter>(
    surface: &F,
    us: &[S],
    vs: &[S],
    counter: &mut C,
) -> Result<TriangleMesh> {
    check_samples(us, "u")?;
    check_samples(vs, "v")?;
    limits::SAMPLES.check(us.len() as u128 * vs.len() as u128)?;
    let (nu, nv) = (us.len(), vs.len());
    let mut positions = Vec::with_capacity(nu * nv);
    let mut normals = Vec::with_capacity(nu * nv);
    // The surface's own grid of points and partials: spline surfaces compute each
    // parameter's basis once for the whole grid.
    for [p, du, dv] in surface.first_partials_on_grid(us, vs)? {
        let p = p.to_f64();
        if !p.is_finite() {
            return Err(Error::Overflow {
                what: "tessellation vertex",
            });
        }
        counter.arithmetic_operation();
        counter.arithmetic_operation();
        counter.arithmetic_operation();
        positions.push(*p.coords());
        normals.push(unit(&cross(&du, &dv)));
    }
    let index = |i: usize, j: usize| i * nv + j;
    let mut triangles = Vec::with_capacity(2 * (nu - 1) * (nv - 1));
    for i in 0..nu - 1 {
        for j in 0..nv - 1 {
            let (a, b, c, d) = (
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            );
            // Counter-clockwise seen from c_u × c_v: u runs along a→b, v along a→d.
            if distance2(&positions[a], &positions[c]) <= distance2(&positions[b], &positions[d]) {
                triangles.push([a, b, c]);
                triangles.push([a, c, d]);
            } else {
                triangles.push([a, b, d]);
                triangles.push([b, c, d]);
            }
        }
    }
    fill_missing_normals(&positions, nu, nv, &mut normals);
    Ok(TriangleMesh {
        positions,
        normals,
        triangles,
    })
}

/// `segments` + 1 equally spaced parameters over the domain ([0, 1] for the whole line).
fn uniform<S: Scalar>(domain: &Domain<S>, segments: usize) -> Vec<S> {
    let (start, end) = match domain.bounds() {
        Some((a, b)) => (a.clone(), b.clone()),
        None => (S::zero(), S::one()),
    };
    let width = end.clone() - &start;
    (0..=segments)
        .map(|k| {
            if k == segments {
                end.clone()
            } else {
                start.clone() + width.clone() * S::from_ratio(k as i64, segments as i64)
            }
        })
        .collect()
}

/// At least two finite, strictly increasing samples.
fn check_samples<S: Scalar>(samples: &[S], which: &str) -> Result<()> {
    if samples.len() < 2 {
        return Err(Error::InvalidParameter {
            name: "samples",
            reason: format!(
                "a grid needs at least two {which} samples, got {}",
                samples.len()
            ),
        });
    }
    for (k, pair) in samples.windows(2).enumerate() {
        if !(pair[0].is_finite() && pair[1].is_finite()) || pair[0] >= pair[1] {
            return Err(Error::InvalidParameter {
                name: "samples",
                reason: format!(
                    "the {which} samples must be finite and strictly increasing: sample {} is \
                     {} and sample {} is {}",
                    k,
                    pair[0].to_f64(),
                    k + 1,
                    pair[1].to_f64()
                ),
            });
        }
    }
    Ok(())
}

/// The unit vector of `n` in `f64`, or zero when `n` is exactly zero. The vector is scaled by
/// a power of two before its length is taken, so neither huge nor tiny components overflow.
pub(super) fn unit<S: Scalar>(n: &Point<S, 3>) -> [f64; 3] {
    if n.coords().iter().all(Scalar::is_zero) {
        return [0.0; 3];
    }
    normalise(*n.to_f64().coords())
}

/// `v / |v|`, or zero for a zero (or non-finite) vector.
pub(super) fn normalise(v: [f64; 3]) -> [f64; 3] {
    let largest = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if largest == 0.0 || !largest.is_finite() {
        return [0.0; 3];
    }
    // The power of two nearest the largest component, so the squares stay in range.
    let scale = 2f64.powi(-(largest.log2().round() as i32));
    let w = v.map(|x| x * scale);
    let length = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
    w.map(|x| x / length)
}

/// The unit normal of the triangle a, b, c (counter-clockwise), zero if it has no area.
pub(super) fn triangle_normal(a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> [f64; 3] {
    let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    normalise(cross_f64(&e1, &e2))
}

fn cross_f64(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn distance2(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|k| (a[k] - b[k]) * (a[k] - b[k])).sum()
}

/// Gives every vertex whose normal is zero the normalised sum of the normals of the grid
/// cells around it, each the unit cross product of the cell's diagonals (c − a) × (d − b):
/// a cell with one collapsed edge (two equal corners) still has one, where a triangle with
/// that edge has none.
fn fill_missing_normals(positions: &[[f64; 3]], nu: usize, nv: usize, normals: &mut [[f64; 3]]) {
    let index = |i: usize, j: usize| i * nv + j;
    for i in 0..nu {
        for j in 0..nv {
            let k = index(i, j);
            if normals[k] != [0.0; 3] {
                continue;
            }
            let mut sum = [0.0f64; 3];
            for ci in i.saturating_sub(1)..(i + 1).min(nu - 1) {
                for cj in j.saturating_sub(1)..(j + 1).min(nv - 1) {
                    let [a, b, c, d] = [
                        index(ci, cj),
                        index(ci + 1, cj),
                        index(ci + 1, cj + 1),
                        index(ci, cj + 1),
                    ]
                    .map(|k| positions[k]);
                    let first = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
                    let second = [d[0] - b[0], d[1] - b[1], d[2] - b[2]];
                    let cell = normalise(cross_f64(&first, &second));
                    for (s, n) in sum.iter_mut().zip(cell) {
                        *s += n;
                    }
                }
            }
            normals[k] = normalise(sum);
        }
    }
}
