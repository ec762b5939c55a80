//! [`PolygonMesh`]: vertex positions and validated half-edge connectivity.

use super::topology::MeshTopology;
use crate::spline::{Point, Scalar};
use crate::{Error, Result};

/// A polygon mesh: vertex positions in R^D (any [`Scalar`]) and faces with counter-clockwise
/// corner lists, validated once into half-edge arrays ([`MeshTopology`]).
///
/// A valid mesh is an oriented 2-manifold, possibly with boundary: every face has at least
/// three distinct vertices, every edge has one or two faces and two faces run along it in
/// opposite directions, the faces around every vertex form one fan, and every vertex belongs
/// to a face (isolated vertices are rejected, so every vertex has a one-ring for the
/// subdivision rules). Coordinates are finite. Faces may have any number of corners; they
/// need not be planar or convex (only the connectivity is validated).
///
/// ```
/// use compgeo::mesh::PolygonMesh;
/// use compgeo::spline::Point;
///
/// // A square pyramid without its base: four triangles around the apex 4.
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let positions = vec![
///     p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(1.0, 1.0, 0.0), p(0.0, 1.0, 0.0), p(0.5, 0.5, 1.0),
/// ];
/// let mesh = PolygonMesh::new(positions, &[[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]])?;
/// assert_eq!((mesh.vertex_count(), mesh.edge_count(), mesh.face_count()), (5, 8, 4));
/// assert_eq!(mesh.topology().valence(4), 4);
/// assert!(mesh.topology().is_boundary_vertex(0) && !mesh.topology().is_boundary_vertex(4));
/// assert_eq!(mesh.euler_characteristic(), 1);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonMesh<S, const D: usize> {
    positions: Vec<Point<S, D>>,
    topology: MeshTopology,
}

impl<S: Scalar, const D: usize> PolygonMesh<S, D> {
    /// The mesh of `positions` and `faces`, each face a list of vertex indices
    /// (counter-clockwise seen from the side the surface faces).
    ///
    /// # Errors
    ///
    /// [`Error::NonFinite`] naming the first vertex with a NaN or infinite coordinate;
    /// [`Error::Empty`] without faces; [`Error::LimitExceeded`] beyond
    /// [`MAX_MESH_VERTICES`](crate::limits::MAX_MESH_VERTICES) vertices or
    /// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners in all; otherwise the
    /// first violation as an [`Error::Mesh`] naming the face (or vertex): a face with fewer
    /// than three corners, a vertex out of range or repeated in a face (faces in order), an
    /// edge with a third face or two faces along it in the same direction (half-edges in
    /// order), an isolated or non-manifold vertex (vertices in order).
    ///
    /// # Complexity
    ///
    /// O(V + H log d) time for V vertices, H corners in all and d the most corners at one
    /// vertex; O(V + H) space.
    ///
    /// ```
    /// use compgeo::mesh::{MeshError, PolygonMesh};
    /// use compgeo::spline::Point;
    /// use compgeo::Error;
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y, 0.0]);
    /// let e = PolygonMesh::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)], &[[0, 1, 3]]);
    /// assert_eq!(
    ///     e.unwrap_err(),
    ///     Error::Mesh(MeshError::VertexOutOfRange { face: 0, vertex: 3, vertices: 3 })
    /// );
    /// ```
    pub fn new<F: AsRef<[usize]>>(positions: Vec<Point<S, D>>, faces: &[F]) -> Result<Self> {
        let mut offsets = Vec::with_capacity(faces.len() + 1);
        offsets.push(0);
        let mut corners = Vec::new();
        for face in faces {
            corners.extend_from_slice(face.as_ref());
            crate::limits::MESH_CORNERS.check(corners.len() as u128)?;
            offsets.push(corners.len());
        }
        Self::from_offsets(positions, &offsets, &corners)
    }

    /// The mesh of `positions` and faces given flat: face `f` is
    /// `corners[offsets[f]..offsets[f + 1]]`. See [`new`](Self::new).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"face offsets"` unless `offsets` starts at 0, does
    /// not decrease and ends at `corners.len()`; otherwise as [`new`](Self::new).
    ///
    /// # Complexity
    ///
    /// As [`new`](Self::new).
    ///
    /// ```
    /// use compgeo::mesh::PolygonMesh;
    /// use compgeo::spline::Point;
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// let square = vec![p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)];
    /// let mesh = PolygonMesh::from_offsets(square, &[0, 4], &[0, 1, 2, 3])?;
    /// assert_eq!(mesh.face_vertices(0), [0, 1, 2, 3]);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn from_offsets(
        positions: Vec<Point<S, D>>,
        offsets: &[usize],
        corners: &[usize],
    ) -> Result<Self> {
        if offsets.first() != Some(&0)
            || offsets.last() != Some(&corners.len())
            || offsets.windows(2).any(|w| w[0] > w[1])
        {
            return Err(Error::InvalidParameter {
                name: "face offsets",
                reason: format!(
                    "must start at 0, not decrease and end at the corner count {}",
                    corners.len()
                ),
            });
        }
        check_finite(&positions)?;
        let topology = MeshTopology::from_faces(positions.len(), offsets, corners)?;
        Ok(PolygonMesh {
            positions,
            topology,
        })
    }

    /// A mesh from positions and connectivity a scheme built (no validation; debug builds
    /// check the sizes agree).
    pub(crate) fn from_parts_unchecked(
        positions: Vec<Point<S, D>>,
        topology: MeshTopology,
    ) -> Self {
        debug_assert_eq!(positions.len(), topology.vertex_count());
        PolygonMesh {
            positions,
            topology,
        }
    }

    /// The vertex positions.
    #[inline]
    pub fn positions(&self) -> &[Point<S, D>] {
        &self.positions
    }

    /// The position of vertex `v`.
    #[inline]
    pub fn position(&self, v: usize) -> &Point<S, D> {
        &self.positions[v]
    }

    /// The connectivity: faces, half-edges, edges, one-rings, boundary loops.
    #[inline]
    pub fn topology(&self) -> &MeshTopology {
        &self.topology
    }

    /// The number of vertices V.
    #[inline]
    pub fn vertex_count(&self) -> usize {
        self.topology.vertex_count()
    }

    /// The number of faces F.
    #[inline]
    pub fn face_count(&self) -> usize {
        self.topology.face_count()
    }

    /// The number of edges E.
    #[inline]
    pub fn edge_count(&self) -> usize {
        self.topology.edge_count()
    }

    /// The vertices of face `f`, counter-clockwise.
    #[inline]
    pub fn face_vertices(&self, f: usize) -> &[u32] {
        self.topology.face_vertices(f)
    }

    /// The Euler characteristic V − E + F.
    #[inline]
    pub fn euler_characteristic(&self) -> i64 {
        self.topology.euler_characteristic()
    }

    /// The positions and the connectivity, taken apart.
    pub fn into_parts(self) -> (Vec<Point<S, D>>, MeshTopology) {
        (self.positions, self.topology)
    }

    /// The same connectivity with other positions (one per vertex, finite), in any scalar
    /// and dimension: a converted copy, a projection, a deformation.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"positions"` if the count differs from the
    /// vertex count; [`Error::NonFinite`] naming the first vertex with a non-finite
    /// coordinate.
    ///
    /// # Complexity
    ///
    /// O(V + H) time (the connectivity is cloned), O(V + H) space.
    ///
    /// ```
    /// use compgeo::mesh::PolygonMesh;
    /// use compgeo::spline::Point;
    /// use num_rational::BigRational;
    ///
    /// let p = |x: f64, y: f64| Point::new([x, y]);
    /// let mesh = PolygonMesh::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, 0.1)], &[[0, 1, 2]])?;
    /// let exact: Vec<Point<BigRational, 2>> =
    ///     mesh.positions().iter().map(|q| Point::from_f64(q).unwrap()).collect();
    /// let exact = mesh.with_positions(exact)?;
    /// assert_eq!(exact.topology(), mesh.topology());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn with_positions<T: Scalar, const E: usize>(
        &self,
        positions: Vec<Point<T, E>>,
    ) -> Result<PolygonMesh<T, E>> {
        if positions.len() != self.vertex_count() {
            return Err(Error::InvalidParameter {
                name: "positions",
                reason: format!(
                    "expected one per vertex ({}), got {}",
                    self.vertex_count(),
                    positions.len()
                ),
            });
        }
        check_finite(&positions)?;
        Ok(PolygonMesh {
            positions,
            topology: self.topology.clone(),
        })
    }
}

/// [`Error::NonFinite`] for the first vertex with a NaN or infinite coordinate.
fn check_finite<S: Scalar, const D: usize>(positions: &[Point<S, D>]) -> Result<()> {
    for (index, p) in positions.iter().enumerate() {
        if let Some(c) = p.0.iter().find(|c| !c.is_finite()) {
            return Err(Error::NonFinite {
                index,
                value: c.to_f64(),
            });
        }
    }
    Ok(())
}
