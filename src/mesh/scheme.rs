//! [`Scheme`]: the subdivision schemes on polygon meshes, for callers that choose one at run
//! time (the command line's `mesh subdivide --scheme`), and [`subdivide`].

use super::catmull_clark::{self, catmull_clark_with};
use super::doo_sabin::{self, doo_sabin_with};
use super::loop_subdivision::{self, loop_subdivision_with};
use super::midpoint_cubic::{self, midpoint_cubic_with};
use super::polygon_mesh::PolygonMesh;
use crate::complexity::algorithm_family;
use crate::count::{Counter, NoCount};
use crate::spline::Scalar;
use crate::Result;

algorithm_family! {
    /// The subdivision schemes of polygon meshes; each runs k rounds of `(mesh, rounds)`.
    ///
    /// ```
    /// use compgeo::mesh::Scheme;
    ///
    /// let s: Scheme = "catmull-clark".parse()?;
    /// assert_eq!(s, Scheme::CatmullClark);
    /// assert_eq!(Scheme::MidpointCubic.name(), "midpoint-cubic");
    /// assert!("butterfly".parse::<Scheme>().is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum Scheme ("subdivision scheme") {
        /// [`catmull_clark_with`](super::catmull_clark_with): Catmull–Clark, faces of any
        /// size, crease rules on the boundary.
        CatmullClark = catmull_clark::CATMULL_CLARK => catmull_clark_with,
        /// [`midpoint_cubic_with`](super::midpoint_cubic_with): the midpoint scheme
        /// M₃ = A²R of [PPB, §16.1].
        MidpointCubic = midpoint_cubic::MIDPOINT_CUBIC => midpoint_cubic_with,
        /// [`doo_sabin_with`](super::doo_sabin_with): Doo–Sabin, the midpoint scheme
        /// M₂ = AR of [PPB, §16.1], faces of any size.
        DooSabin = doo_sabin::DOO_SABIN => doo_sabin_with,
        /// [`loop_subdivision_with`](super::loop_subdivision_with): Loop's scheme with
        /// Loop's weights, triangle meshes only.
        Loop = loop_subdivision::LOOP => loop_subdivision_with,
    }
    fn run_with[S: Scalar, const D: usize, C: Counter](
        mesh: &PolygonMesh<S, D>,
        rounds: usize,
        counter: &mut C,
    ) -> Result<PolygonMesh<S, D>>;
}

/// `rounds` rounds of `scheme` on `mesh`: the same as calling the scheme's function.
///
/// # Errors
///
/// Those of the scheme (a result beyond
/// [`MAX_MESH_CORNERS`](crate::limits::MAX_MESH_CORNERS) corners; a scheme may require
/// particular faces).
///
/// # Complexity
///
/// That of the scheme: Θ(4ᵏ·H·D) time and space for k rounds on H corners for the schemes
/// that split every face into four.
///
/// ```
/// use compgeo::gen::cube;
/// use compgeo::mesh::{catmull_clark, subdivide, Scheme};
///
/// let mesh = cube();
/// assert_eq!(subdivide(&mesh, Scheme::CatmullClark, 2)?, catmull_clark(&mesh, 2)?);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn subdivide<S: Scalar, const D: usize>(
    mesh: &PolygonMesh<S, D>,
    scheme: Scheme,
    rounds: usize,
) -> Result<PolygonMesh<S, D>> {
    scheme.run_with(mesh, rounds, &mut NoCount)
}

/// [`subdivide`] with a counter: the operations the scheme's `_with` function counts.
///
/// # Errors
///
/// As [`subdivide`].
///
/// # Complexity
///
/// As [`subdivide`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::cube;
/// use compgeo::mesh::{subdivide_with, Scheme};
///
/// let mut counts = Counts::default();
/// subdivide_with(&cube(), Scheme::CatmullClark, 1, &mut counts)?;
/// assert!(counts.arithmetic_operations > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn subdivide_with<S: Scalar, const D: usize, C: Counter>(
    mesh: &PolygonMesh<S, D>,
    scheme: Scheme,
    rounds: usize,
    counter: &mut C,
) -> Result<PolygonMesh<S, D>> {
    scheme.run_with(mesh, rounds, counter)
}
