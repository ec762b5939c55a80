//! Tessellation of a triangular patch in R³ into a [`TriangleMesh`] with normals, for viewers
//! and for the OBJ and STL writers of the surface module.
//!
//! The problem: a mesh that follows the patch over its reference triangle. The idea: the
//! uniform refinement of the triangle into m² triangles [PPB, §10.3, Fig. 10.4]: its
//! vertices are the points with barycentric coordinates (i, j, k)/m, i + j + k = m, numbered
//! as control points are (rows of constant k, j increasing: vertex (i, j, k) has index
//! k(2m + 3 − k)/2 + j); each is evaluated with its two first partials by one de Casteljau
//! scheme (n − 1 levels, then the point and two differences, [PPB, §10.5]), and takes the unit
//! normal b_u × b_v computed in the patch's scalar (u along p − r, v along q − r, as the
//! [`Surface`](crate::surface::Surface) parameters). Where that cross product vanishes (a
//! collapsed edge, a singular corner) the vertex takes the normalised sum of the normals of
//! its triangles, and keeps the zero vector if none has one.
//!
//! Each small triangle is counter-clockwise seen from the side b_u × b_v points to: row k
//! holds the m − k triangles (i, j, k), (i − 1, j + 1, k), (i − 1, j, k + 1) pointing towards
//! r, and the m − k − 1 triangles between them.
//!
//! # Complexity
//!
//! Θ(m²·n³D) time for m segments per edge and degree n, Θ(m²) space for the mesh.

use super::barycentric::Barycentric;
use super::patch::{point_count, row_offset, TriangularPatch};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::Scalar;
use crate::surface::normal::cross;
use crate::surface::tessellate::{normalise, triangle_normal, unit};
use crate::surface::TriangleMesh;
use crate::{limits, Error, Result};

/// Tessellation of a triangular patch, declared.
pub(crate) const TESSELLATE: Declaration = Declaration {
    problem: "triangular-patch",
    name: "tessellate",
    function: "surface::TriangularPatch::tessellate",
    file: "src/surface/triangle/tessellate.rs",
    summary: "the uniform refinement of the triangle, each vertex with its point and partials from one de Casteljau scheme",
    time: "Θ(m²·n³D) for m segments per edge",
    space: "Θ(m²)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "exactly n(n + 1)(n + 2)/6 + 2 operations per vertex for n ≥ 1, (m + 1)(m + 2)/2 vertices",
    source: "[PPB, §10.3–10.5]",
    claims: &[on(
        "random-samples",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

impl<S: Scalar> TriangularPatch<S, 3> {
    /// The mesh of the patch over its reference triangle, `segments` = m segments per edge:
    /// (m + 1)(m + 2)/2 vertices, m² triangles. See [`TriangularPatch::tessellate_with`].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"segments"` if m is zero;
    /// [`Error::LimitExceeded`] beyond [`MAX_SAMPLES`](crate::limits::MAX_SAMPLES) vertices;
    /// [`Error::Overflow`] if, with `f64`, a vertex is beyond the double range.
    ///
    /// # Complexity
    ///
    /// Θ(m²·n³D) for m segments per edge in time, Θ(m²) in space.
    ///
    /// ```
    /// use compgeo::spline::Point;
    /// use compgeo::surface::TriangularPatch;
    ///
    /// // The flat triangle (1, 0, 0), (0, 1, 0), (0, 0, 0): every normal is +z.
    /// let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
    /// let b = TriangularPatch::new(vec![p(1.0, 0.0), p(0.0, 1.0), p(0.0, 0.0)])?;
    /// let mesh = b.tessellate(4)?;
    /// assert_eq!((mesh.positions.len(), mesh.triangles.len()), (15, 16));
    /// assert_eq!(mesh.positions[1], [0.75, 0.25, 0.0]); // (i, j, k) = (3, 1, 0)
    /// assert!(mesh.normals.iter().all(|n| *n == [0.0, 0.0, 1.0]));
    /// let mut obj = Vec::new();
    /// mesh.write_obj(&mut obj).unwrap();
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn tessellate(&self, segments: usize) -> Result<TriangleMesh> {
        self.tessellate_with(segments, &mut NoCount)
    }

    /// The mesh of the patch, counting the operations of its evaluations.
    ///
    /// Idea: the uniform refinement of the triangle [PPB, §10.3]; at each vertex n − 1 levels
    /// of de Casteljau's scheme leave b_{100}, b_{010}, b_{001}, whose combination is the
    /// point and whose differences n(b_{100} − b_{001}), n(b_{010} − b_{001}) are the partials
    /// b_u, b_v [PPB, §10.5]; the normal is the unit b_u × b_v, or the triangles' where that
    /// vanishes.
    ///
    /// # Errors
    ///
    /// As [`TriangularPatch::tessellate`].
    ///
    /// # Complexity
    ///
    /// Θ(m²·n³D) for m segments per edge in time, Θ(m²) in space.
    ///
    /// # Counts
    ///
    /// One [`arithmetic_operation`](Counter::arithmetic_operation) per affine combination
    /// and per difference: exactly n(n + 1)(n + 2)/6 + 2 per vertex for n ≥ 1 (none for
    /// n = 0), (m + 1)(m + 2)/2 vertices.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::Point;
    /// use compgeo::surface::TriangularPatch;
    ///
    /// let b = TriangularPatch::new((0..10).map(|k| Point::new([k as f64, (k * k) as f64, 1.0])).collect())?;
    /// let mut c = Counts::default();
    /// let mesh = b.tessellate_with(3, &mut c)?;
    /// assert_eq!(mesh.triangles.len(), 9);
    /// assert_eq!(c.arithmetic_operations, 10 * (10 + 2)); // 10 vertices, degree 3
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn tessellate_with<C: Counter>(
        &self,
        segments: usize,
        counter: &mut C,
    ) -> Result<TriangleMesh> {
        let m = segments;
        if m == 0 {
            return Err(Error::InvalidParameter {
                name: "segments",
                reason: "a tessellation needs at least one segment per edge, got 0".to_string(),
            });
        }
        limits::SAMPLES.check((m as u128 + 1).saturating_mul(m as u128 + 2) / 2)?;
        let mut positions = Vec::with_capacity(point_count(m));
        let mut normals = Vec::with_capacity(point_count(m));
        // m ≤ MAX_SAMPLES, so the ratios fit in an i64.
        let ratio = |c: usize| S::from_ratio(c as i64, m as i64);
        for k in 0..=m {
            for j in 0..=m - k {
                // w = 1 − u − v: with f64 the three rounded ratios need not sum to 1.
                let at = Barycentric::from_uv(ratio(m - k - j), ratio(j))
                    .expect("coordinates in [0, 1] are finite");
                let [point, du, dv] = self.point_and_partials(&at, counter);
                let point = point.to_f64();
                if !point.is_finite() {
                    return Err(Error::Overflow {
                        what: "tessellation vertex",
                    });
                }
                positions.push(*point.coords());
                normals.push(unit(&cross(&du, &dv)));
            }
        }
        let index = |j: usize, k: usize| row_offset(m, k) + j;
        let mut triangles = Vec::with_capacity(m * m);
        for k in 0..m {
            for j in 0..m - k {
                triangles.push([index(j, k), index(j + 1, k), index(j, k + 1)]);
                if j + 1 < m - k {
                    triangles.push([index(j + 1, k), index(j + 1, k + 1), index(j, k + 1)]);
                }
            }
        }
        fill_missing_normals(&positions, &triangles, &mut normals);
        Ok(TriangleMesh {
            positions,
            normals,
            triangles,
        })
    }
}

/// Gives every vertex whose normal is zero the normalised sum of the unit normals of its
/// triangles (zero for a degenerate triangle), or leaves it zero if they sum to zero.
fn fill_missing_normals(
    positions: &[[f64; 3]],
    triangles: &[[usize; 3]],
    normals: &mut [[f64; 3]],
) {
    let missing: Vec<bool> = normals.iter().map(|n| *n == [0.0; 3]).collect();
    if !missing.contains(&true) {
        return;
    }
    let mut sums = vec![[0.0f64; 3]; positions.len()];
    for t in triangles {
        if !t.iter().any(|&k| missing[k]) {
            continue;
        }
        let [a, b, c] = t.map(|k| positions[k]);
        let n = triangle_normal(&a, &b, &c);
        for &k in t {
            for (s, x) in sums[k].iter_mut().zip(n) {
                *s += x;
            }
        }
    }
    for (k, normal) in normals.iter_mut().enumerate() {
        if missing[k] {
            *normal = normalise(sums[k]);
        }
    }
}
