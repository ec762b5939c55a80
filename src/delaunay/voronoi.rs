//! The Voronoi diagram as the dual of the Delaunay triangulation (clipping is in `clip.rs`).

use super::hilbert::curve_order;
use super::incremental::{degenerate, incremental_local, LocalTriangulation, NO_TWIN};
use super::triangulation::{next_halfedge as next, prev_halfedge as prev, Triangulation, EMPTY};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::construct::{circumcentre, midpoint, unit_direction};
use crate::geometry::{ConstructedPoint, Point2, PointSet, WideFloat};

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "voronoi",
    name: "delaunay-dual",
    function: "delaunay::voronoi",
    file: "src/delaunay/voronoi.rs",
    summary: "the dual of the incremental Delaunay triangulation, cells in Hilbert order",
    time: "O(n log n) expected",
    space: "O(n)",
    operation: Some(Operation::IncircleTests),
    counts: "those of the triangulation; the dual makes no geometric decision",
    source: "[RD, §2.4]",
    claims: &[on("uniform-square", Bound::NLogN, Operation::IncircleTests)],
};

/// The Voronoi diagram of a point set: one cell per distinct site.
///
/// Cell `k` belongs to site `sites[k]`, an index into the caller's points. [`voronoi`] lists
/// the cells in a spatial order (it is faster to build), [`dual`] in site order. A cell's
/// boundary, counter-clockwise around the site, is stored as
/// [`cell_vertices(k)`](Voronoi::cell_vertices) (indices into `vertices`) and
/// [`cell_rays(k)`](Voronoi::cell_rays); see [`Cell`] for how the two combine.
/// Every input point has a cell: [`cell_of`](Voronoi::cell_of) maps a duplicate to the cell
/// of the point it was merged into.
///
/// `vertices[t]` is the circumcentre of triangle `t` of the triangulation the diagram was
/// built from (for [`voronoi`], its own), so cocircular sites give several equal vertices
/// (one per triangle). Each is within
/// [`ConstructedPoint::RELATIVE_ERROR`] of the exact circumcentre; one whose exact value is
/// beyond the range of `f64` (a nearly flat triangle at a large scale) is clamped to
/// `±f64::MAX` in `vertices`, and [`vertex`](Voronoi::vertex) gives its true value.
///
/// The diagram also keeps each cell's site coordinates and, for each vertex of a cell, the
/// site across the edge leaving it: [`clip_cell`](Voronoi::clip_cell) decides from those
/// lines, exactly, rather than from the rounded vertices.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Voronoi {
    /// The Voronoi vertices: the circumcentre of every Delaunay triangle, in triangle order
    /// (rounded constructions, see [`voronoi`]; a coordinate beyond the range of `f64`
    /// clamped to `±f64::MAX`, see [`Voronoi::vertex`]).
    pub vertices: Vec<Point2>,
    /// The site of each cell.
    pub sites: Vec<usize>,
    /// The vertices beyond the range of `f64`, by increasing index, with their values.
    beyond: Vec<(usize, [WideFloat; 2])>,
    /// `vertex_ids[vertex_start[k]..vertex_start[k + 1]]` are cell k's vertices.
    vertex_start: Vec<usize>,
    vertex_ids: Vec<usize>,
    /// `across[j]`: the site (input index) across the edge that leaves vertex
    /// `vertex_ids[j]` counter-clockwise around its cell, whose bisector that edge lies on.
    across: Vec<u32>,
    /// The coordinates of each cell's site, for clipping from the bisectors.
    site_points: Vec<Point2>,
    ray_start: Vec<usize>,
    rays: Vec<Ray>,
    cell_of: Vec<usize>,
}

/// One cell of a [`Voronoi`] diagram, borrowed from it.
///
/// The boundary, counter-clockwise around `site`, is made of chains. A bounded cell is one
/// closed chain: the polygon `vertices`. An unbounded cell of a triangulated point set has
/// one chain: it arrives from infinity along `rays[0]` (which starts at `vertices[0]` and
/// points away, to infinity), passes through `vertices` and leaves along `rays[1]` (from the
/// last vertex). For collinear sites there are no vertices: each bisector line of the
/// cell's boundary is a chain of two opposite rays from the midpoint of the two sites
/// (`rays[2k]` arriving, `rays[2k + 1]` leaving). A single site's cell is the whole plane:
/// no vertices, no rays, unbounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell<'a> {
    /// The site (an index into the caller's points).
    pub site: usize,
    /// The finite vertices, counter-clockwise, as indices into [`Voronoi::vertices`].
    pub vertices: &'a [usize],
    /// The rays, in pairs (arriving, leaving) per chain of the boundary; empty iff bounded
    /// or the only site.
    pub rays: &'a [Ray],
    /// Whether the cell is a bounded polygon: exactly when the site is not on the convex
    /// hull's boundary (Theorem 2.32), decided from the triangulation's topology.
    pub bounded: bool,
}

/// A half-line of a cell's boundary, on the bisector of two sites.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Ray {
    /// Where it starts: a Voronoi vertex (the cell's first vertex for the arriving ray, its
    /// last for the leaving one; as in [`Voronoi::vertices`], so clamped to `±f64::MAX` where
    /// the vertex is beyond the range of `f64`, see [`Voronoi::vertex`]), or for collinear
    /// sites the midpoint of the two.
    pub origin: Point2,
    /// A unit vector pointing to infinity (rounded), perpendicular to `sites[1] - sites[0]`.
    pub direction: Point2,
    /// The cell's site and the site across the ray.
    pub sites: [usize; 2],
}

impl Voronoi {
    /// The number of cells (distinct sites).
    pub fn cell_count(&self) -> usize {
        self.sites.len()
    }

    /// Cell `k`. Panics if `k >= cell_count()`.
    pub fn cell(&self, k: usize) -> Cell<'_> {
        let rays = self.cell_rays(k);
        Cell {
            site: self.sites[k],
            vertices: self.cell_vertices(k),
            rays,
            bounded: rays.is_empty() && self.sites.len() > 1,
        }
    }

    /// The cells, in the order of [`sites`](Voronoi::sites).
    pub fn cells(&self) -> impl ExactSizeIterator<Item = Cell<'_>> + '_ {
        (0..self.cell_count()).map(|k| self.cell(k))
    }

    /// The finite vertices of cell `k`, counter-clockwise. Panics if `k` is out of range.
    pub fn cell_vertices(&self, k: usize) -> &[usize] {
        &self.vertex_ids[self.vertex_start[k]..self.vertex_start[k + 1]]
    }

    /// The rays of cell `k` (see [`Cell`]). Panics if `k` is out of range.
    pub fn cell_rays(&self, k: usize) -> &[Ray] {
        &self.rays[self.ray_start[k]..self.ray_start[k + 1]]
    }

    /// The cell holding input point `i` (a duplicate shares the cell of the point it was
    /// merged into). Panics if `i` is not an index of the input.
    pub fn cell_of(&self, i: usize) -> usize {
        self.cell_of[i]
    }

    /// Vertex `i`, the circumcentre of triangle `i`, as constructed: within
    /// [`ConstructedPoint::RELATIVE_ERROR`] of the exact circumcentre, and
    /// [`ConstructedPoint::BeyondRange`] exactly when a coordinate's exact value is beyond
    /// the range of `f64` (where [`vertices`](Voronoi::vertices) holds it clamped). Panics if
    /// `i` is out of range.
    ///
    /// # Complexity
    /// O(log b) for b vertices beyond the range (O(1) when there are none).
    pub fn vertex(&self, i: usize) -> ConstructedPoint {
        let p = self.vertices[i];
        if self.beyond.is_empty() {
            return ConstructedPoint::Finite(p);
        }
        match self.beyond.binary_search_by_key(&i, |&(j, _)| j) {
            Ok(k) => ConstructedPoint::BeyondRange(self.beyond[k].1),
            Err(_) => ConstructedPoint::Finite(p),
        }
    }

    /// Whether vertex `i` has a coordinate beyond the range of `f64` (see
    /// [`vertex`](Voronoi::vertex)).
    pub fn is_beyond_range(&self, i: usize) -> bool {
        self.vertex(i).is_beyond_range()
    }

    /// The site of cell `k`'s neighbour across the edge that leaves its `j`-th vertex
    /// counter-clockwise (for the clipper).
    pub(super) fn across(&self, k: usize, j: usize) -> usize {
        self.across[self.vertex_start[k] + j] as usize
    }

    /// The coordinates of the site of cell `k`.
    pub(super) fn site_point(&self, k: usize) -> Point2 {
        self.site_points[k]
    }

    /// The coordinates of input point `i` (a site, or merged into one).
    pub(super) fn point_of(&self, i: usize) -> Point2 {
        self.site_points[self.cell_of[i]]
    }
}

/// The Voronoi diagram of `points`, computed as the dual of their Delaunay triangulation
/// (the crate's [`incremental`](super::incremental) builder).
///
/// The idea ([RD, §2.4] "Diagrama de Voronoi", Observations 2.29 and
/// Theorems 2.30–2.32, Corollary 2.33 and Definition 2.34): the Voronoi vertices are the
/// centres of the empty circles through three sites, i.e. the circumcentres of the Delaunay
/// triangles, and the cell of a site is the polygon of the circumcentres of the triangles
/// around it, in the same rotational order. A site on the hull has an unbounded cell whose
/// two rays lie on the bisectors of its two hull edges, pointing outwards.
///
/// Exact and rounded parts: every decision is topological, taken from the exact
/// triangulation: which cells are bounded (the site is not on the hull), the cyclic order
/// of a cell's vertices (the triangles around the site), which hull edge a ray is
/// perpendicular to. The *coordinates* of the vertices, ray origins and ray directions are
/// constructions, rounded to `f64`: each vertex within
/// [`ConstructedPoint::RELATIVE_ERROR`] of the exact circumcentre for every finite input (a
/// certified floating-point evaluation, or exact big-integer arithmetic when its bound does
/// not certify it), the midpoints of collinear sites within an ulp, the directions within a
/// few. A circumcentre beyond `f64`'s range (a nearly flat triangle at a huge scale) is
/// reported by [`Voronoi::vertex`] and clamped to `±f64::MAX` in [`Voronoi::vertices`].
///
/// The cells come in a spatial order, that of their sites along a Hilbert curve, so the
/// walks around consecutive sites touch nearby memory (cache misses are most of their cost
/// at large n); the dual is built straight from the [`incremental`](super::incremental)
/// builder's own arrays, in its numbering. [`Voronoi::cell_of`] finds a point's cell. (Collinear sites, which have no triangles, come in input order.)
///
/// Degenerate input: cocircular sites give coincident vertices (one per triangle);
/// duplicates share the cell of the point they were merged into; collinear sites (no
/// triangles) give strips and two half-planes bounded by the perpendicular bisectors of
/// consecutive sites, with no vertices; a single site's cell is the whole plane.
///
/// # Errors
/// The errors of [`incremental`](super::incremental)
/// ([`Error::NonFinite`](crate::Error::NonFinite) naming a NaN or infinite coordinate). No
/// points give a diagram without cells.
///
/// # Complexity
/// O(n log n) expected time (the triangulation) and O(n log n) time, O(n) space for the
/// dual (a sort of the sites along the curve, near-linear as they arrive in a few sorted
/// runs; the rest is O(n)), for n points.
///
/// # Counts
/// See [`voronoi_with`]: the triangulation's orientation and in-circle tests.
///
/// ```
/// use compgeo::delaunay::voronoi;
/// use compgeo::geometry::Point2;
///
/// // A square with its centre: the centre's cell is the bounded diamond.
/// let pts = [(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 1.0)].map(Point2::from);
/// let v = voronoi(&pts)?;
/// assert_eq!(v.cell_count(), 5);
/// let centre = v.cell(v.cell_of(4));
/// assert!(centre.bounded);
/// let diamond: Vec<Point2> = centre.vertices.iter().map(|&k| v.vertices[k]).collect();
/// assert_eq!(diamond.len(), 4);
/// assert!(diamond.contains(&Point2::new(1.0, 0.0)) && diamond.contains(&Point2::new(0.0, 1.0)));
/// assert!(v.cells().filter(|c| c.site != 4).all(|c| !c.bounded && c.rays.len() == 2));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn voronoi(points: &[Point2]) -> Result<Voronoi> {
    voronoi_with(&PointSet::new(points)?, &mut NoCount)
}

/// [`voronoi`], recording the triangulation's orientation and in-circle tests in `counter`
/// (the dual itself makes no geometric decision).
///
/// # Errors
/// As [`voronoi`].
///
/// # Complexity
/// As [`voronoi`].
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::delaunay::voronoi_with;
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::PointSet;
///
/// let pts = points(PointKind::UniformSquare, 500, 3)?;
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// let v = voronoi_with(&set, &mut counts)?;
/// assert_eq!(v.cell_count(), 500);
/// assert!(counts.incircle_tests > 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn voronoi_with<C: Counter>(points: &PointSet<'_>, counter: &mut C) -> Result<Voronoi> {
    Ok(match incremental_local(points, counter)? {
        Some(t) => dual_local(&t),
        None => dual_unchecked(points, &degenerate(points)),
    })
}

/// The Voronoi diagram dual to `t`, a Delaunay triangulation of `points` (see [`voronoi`]
/// for what is exact and what is rounded).
///
/// `t` is checked first, exactly, by [`check_delaunay`](super::check_delaunay): a
/// triangulation of other points, or one that is not Delaunay, has no Voronoi diagram as
/// its dual.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) named `"triangulation"`, with
/// the checker's reason, if `t` is not a Delaunay triangulation of `points` in the crate's
/// conventions; the point set's own errors for non-finite points.
///
/// # Complexity
/// O(n log n + t) time and O(n + t) space for n points and t triangles (the check sorts the
/// points; the dual itself is linear).
///
/// ```
/// use compgeo::delaunay::{dual, incremental};
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)].map(Point2::from);
/// let v = dual(&pts, &incremental(&pts)?)?;
/// // Collinear sites: two half-planes and a strip, bounded by the bisectors x = 0.5, 1.5.
/// assert!(v.vertices.is_empty());
/// assert_eq!(v.cell(1).rays.len(), 4);
/// assert_eq!(v.cell(1).rays[0].origin, Point2::new(0.5, 0.0));
/// assert_eq!(v.cell(1).rays[2].origin, Point2::new(1.5, 0.0));
///
/// // A triangulation of other points is refused.
/// let more = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (1.0, 1.0)].map(Point2::from);
/// assert!(dual(&pts, &incremental(&more)?).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dual(points: &[Point2], t: &Triangulation) -> Result<Voronoi> {
    super::check_delaunay(points, t).map_err(|v| crate::Error::InvalidParameter {
        name: "triangulation",
        reason: v.reason,
    })?;
    Ok(dual_unchecked(points, t))
}

/// [`dual`] of a triangulation known to be a Delaunay triangulation of `points` (the
/// builders' own).
pub(crate) fn dual_unchecked(points: &[Point2], t: &Triangulation) -> Voronoi {
    let n = points.len();
    let mut cell_of = vec![usize::MAX; n];
    let mut is_site = vec![true; n];
    for &[dropped, _] in &t.duplicates {
        is_site[dropped] = false;
    }
    let sites: Vec<usize> = (0..n).filter(|&i| is_site[i]).collect();
    for (k, &s) in sites.iter().enumerate() {
        cell_of[s] = k;
    }
    for &[dropped, kept] in &t.duplicates {
        cell_of[dropped] = cell_of[kept];
    }
    let mut v = Voronoi {
        vertices: Vec::new(),
        sites,
        beyond: Vec::new(),
        vertex_start: vec![0],
        vertex_ids: Vec::new(),
        across: Vec::new(),
        site_points: Vec::new(),
        ray_start: vec![0],
        rays: Vec::new(),
        cell_of,
    };
    if t.is_empty() {
        collinear_cells(points, t, &mut v);
    } else {
        // A half-edge leaving each site, in site order.
        let mut starts = vec![EMPTY; v.sites.len()];
        for (e, &a) in t.triangles.iter().enumerate() {
            starts[v.cell_of[a]] = e;
        }
        triangulated_cells(points, &t.triangles, &t.halfedges, &starts, |j| j, &mut v);
    }
    v
}

/// The diagram of the builder's own triangulation, sites renamed to input indices.
///
/// The cells come in the order of their sites along a Hilbert curve: a triangle's three
/// corners then belong to cells walked close together, so its half-edges are read from
/// cache after the first. (Measured at 10⁶ points: about 5% faster overall than the cells
/// in insertion order, whose BRIO rounds put the corners of most triangles far apart, and
/// faster still than the memory order of the triangles.) The sort is cheap: the insertion
/// order is already a few runs in curve order, one per round.
fn dual_local(t: &LocalTriangulation) -> Voronoi {
    let (n, tri) = (t.order.len(), &t.triangles);
    // A half-edge leaving each vertex; merged vertices are in no triangle and keep NO_TWIN.
    let mut out = vec![NO_TWIN; n];
    for (e, &a) in tri.iter().enumerate() {
        out[a as usize] = e as u32;
    }
    let starts: Vec<u32> = curve_order(&t.points)
        .into_iter()
        .map(|j| out[j as usize])
        .filter(|&e| e != NO_TWIN)
        .collect();
    drop(out);
    let site = |j: usize| t.order[j] as usize;
    let sites: Vec<usize> = starts
        .iter()
        .map(|&e| site(tri[e as usize] as usize))
        .collect();
    let mut cell_of = vec![0; n];
    for (k, &i) in sites.iter().enumerate() {
        cell_of[i] = k;
    }
    // A merged point shares the cell of its group's smallest index.
    for &[dropped, kept] in &t.duplicates {
        cell_of[dropped] = cell_of[kept];
    }
    let mut v = Voronoi {
        sites,
        cell_of,
        ..Voronoi::default()
    };
    triangulated_cells(&t.points, tri, &t.halfedges, &starts, site, &mut v);
    v
}

/// The cells of a triangulated point set: walk counter-clockwise around every vertex.
///
/// `starts[k]` is a half-edge leaving the vertex of cell k (the caller's choice of cell
/// order); the cells' rows are appended in that order. A walk that meets the hull restarts
/// from the vertex's outgoing hull edge (found by turning clockwise), so an unbounded cell
/// lists its vertices from its clockwise-most triangle. `site(j)` is the input index of
/// vertex `j`, which the rays name.
///
/// With the `parallel` feature and enough triangles, the circumcentres are computed and the
/// cells walked on every thread: the walks in stretches of cells, concatenated in order, so
/// the diagram is the sequential one.
fn triangulated_cells<I: HalfEdgeId>(
    points: &[Point2],
    tri: &[I],
    halfedges: &[I],
    starts: &[I],
    site: impl Fn(usize) -> usize + Sync,
    v: &mut Voronoi,
) {
    (v.vertices, v.beyond) = circumcentres(points, tri);
    #[cfg(feature = "parallel")]
    if crate::parallel::enabled(tri.len() / 3) {
        use rayon::prelude::*;
        let stretch = (starts.len() / (4 * rayon::current_num_threads())).max(1 << 12);
        let vertices = &v.vertices;
        let parts: Vec<CellRows> = starts
            .par_chunks(stretch)
            .map(|starts| walk_cells(points, tri, halfedges, starts, &site, vertices))
            .collect();
        CellRows::concatenate(parts).into_diagram(v);
        return;
    }
    walk_cells(points, tri, halfedges, starts, &site, &v.vertices).into_diagram(v);
}

/// The circumcentre of every triangle of `tri` (as [`ConstructedPoint::saturating`]), and
/// those beyond the range of `f64` with their wide coordinates.
fn circumcentres<I: HalfEdgeId>(
    points: &[Point2],
    tri: &[I],
) -> (Vec<Point2>, Vec<(usize, [WideFloat; 2])>) {
    let centre = |c: &[I]| {
        let [a, b, c] = [c[0], c[1], c[2]].map(|i| points[i.index()]);
        circumcentre(a, b, c)
    };
    #[cfg(feature = "parallel")]
    if crate::parallel::enabled(tri.len() / 3) {
        use rayon::prelude::*;
        let vertices: Vec<Point2> = tri
            .par_chunks_exact(3)
            .map(|c| centre(c).saturating())
            .collect();
        // A vertex beyond the range saturates to ±f64::MAX; the rare finite vertex there
        // is told apart by constructing it again.
        let beyond = vertices
            .par_iter()
            .enumerate()
            .filter(|(_, p)| [p.x, p.y].iter().any(|z| z.abs() == f64::MAX))
            .filter_map(|(t, _)| match centre(&tri[3 * t..3 * t + 3]) {
                ConstructedPoint::Finite(_) => None,
                far => Some((t, far.wide())),
            })
            .collect();
        return (vertices, beyond);
    }
    let mut beyond = Vec::new();
    let vertices = tri
        .chunks_exact(3)
        .enumerate()
        .map(|(t, c)| match centre(c) {
            ConstructedPoint::Finite(p) => p,
            far => {
                beyond.push((t, far.wide()));
                far.saturating()
            }
        })
        .collect();
    (vertices, beyond)
}

/// The rows of a stretch of cells, as [`walk_cells`] appends them.
#[derive(Default)]
struct CellRows {
    ids: Vec<usize>,
    across: Vec<u32>,
    site_points: Vec<Point2>,
    rays: Vec<Ray>,
    /// Each cell's end in `ids` and in `rays`.
    ends: Vec<usize>,
    ray_ends: Vec<usize>,
}

impl CellRows {
    /// Moves the rows into the diagram's arrays.
    fn into_diagram(self, v: &mut Voronoi) {
        v.vertex_ids = self.ids;
        v.across = self.across;
        v.site_points = self.site_points;
        v.rays = self.rays;
        v.vertex_start = std::iter::once(0).chain(self.ends).collect();
        v.ray_start = std::iter::once(0).chain(self.ray_ends).collect();
    }

    /// The stretches one after another, the ends shifted by what comes before.
    #[cfg(feature = "parallel")]
    fn concatenate(parts: Vec<CellRows>) -> CellRows {
        use crate::parallel::concatenate;
        let (mut id_offset, mut ray_offset) = (0, 0);
        let mut ends = Vec::with_capacity(parts.len());
        let mut ray_ends = Vec::with_capacity(parts.len());
        for part in &parts {
            ends.push(part.ends.iter().map(|e| e + id_offset).collect::<Vec<_>>());
            ray_ends.push(
                part.ray_ends
                    .iter()
                    .map(|e| e + ray_offset)
                    .collect::<Vec<_>>(),
            );
            id_offset += part.ids.len();
            ray_offset += part.rays.len();
        }
        let (mut ids, mut across, mut site_points, mut rays) = (vec![], vec![], vec![], vec![]);
        for part in parts {
            ids.push(part.ids);
            across.push(part.across);
            site_points.push(part.site_points);
            rays.push(part.rays);
        }
        CellRows {
            ids: concatenate(ids),
            across: concatenate(across),
            site_points: concatenate(site_points),
            rays: rays.concat(),
            ends: concatenate(ends),
            ray_ends: concatenate(ray_ends),
        }
    }
}

/// The rows of the cells of `starts` (see [`triangulated_cells`]), with the circumcentres
/// `vertices` for the rays' origins.
fn walk_cells<I: HalfEdgeId>(
    points: &[Point2],
    tri: &[I],
    halfedges: &[I],
    starts: &[I],
    site: &impl Fn(usize) -> usize,
    vertices: &[Point2],
) -> CellRows {
    let at = |e: usize| tri[e].index();
    let mut rows = CellRows {
        ids: Vec::with_capacity(6 * starts.len()),
        across: Vec::with_capacity(6 * starts.len()),
        site_points: Vec::with_capacity(starts.len()),
        rays: Vec::new(),
        ends: Vec::with_capacity(starts.len()),
        ray_ends: Vec::with_capacity(starts.len()),
    };
    for &any in starts {
        let cell_start = rows.ids.len();
        let mut first = any.index();
        rows.site_points.push(points[at(first)]);
        let mut e = first;
        loop {
            rows.ids.push(e / 3);
            // The next triangle counter-clockwise shares the edge to `at(prev(e))`.
            rows.across.push(site(at(prev(e))) as u32);
            // The previous half-edge ends at the vertex; its twin leaves it in the next
            // triangle counter-clockwise.
            let twin = halfedges[prev(e)];
            if twin == I::NONE {
                if halfedges[first] != I::NONE {
                    // A hull vertex reached from the middle of its fan: start again from
                    // its outgoing hull edge, the last one turning clockwise.
                    rows.ids.truncate(cell_start);
                    rows.across.truncate(cell_start);
                    while halfedges[first] != I::NONE {
                        first = next(halfedges[first].index());
                    }
                    e = first;
                    continue;
                }
                // Arrive along the bisector of the outgoing hull edge `s -> q`, leave
                // along that of the incoming one `r -> s`; both point outwards.
                let (s, q, r) = (at(first), at(next(first)), at(prev(e)));
                rows.rays.push(Ray {
                    origin: vertices[first / 3],
                    direction: outward_normal(points[s], points[q]),
                    sites: [site(s), site(q)],
                });
                rows.rays.push(Ray {
                    origin: vertices[e / 3],
                    direction: outward_normal(points[r], points[s]),
                    sites: [site(s), site(r)],
                });
                break;
            }
            e = twin.index();
            if e == first {
                break;
            }
        }
        rows.ends.push(rows.ids.len());
        rows.ray_ends.push(rows.rays.len());
    }
    rows
}

/// The cells of collinear sites (or of one site): the hull lists them along their line.
fn collinear_cells(points: &[Point2], t: &Triangulation, v: &mut Voronoi) {
    let line = &t.hull;
    let mut rays_of: Vec<Vec<Ray>> = vec![Vec::new(); line.len()];
    for (k, pair) in line.windows(2).enumerate() {
        let (a, b) = (pair[0], pair[1]);
        let m = midpoint(points[a], points[b]);
        let u = unit_direction(points[a], points[b]);
        let n = Point2::new(-u.y, u.x);
        let minus = Point2::new(u.y, -u.x);
        // For `a` the bisector is on its `+u` side, traversed counter-clockwise along `+n`;
        // for `b` on its `-u` side, traversed along `-n`.
        rays_of[k].extend([
            Ray {
                origin: m,
                direction: minus,
                sites: [a, b],
            },
            Ray {
                origin: m,
                direction: n,
                sites: [a, b],
            },
        ]);
        rays_of[k + 1].extend([
            Ray {
                origin: m,
                direction: n,
                sites: [b, a],
            },
            Ray {
                origin: m,
                direction: minus,
                sites: [b, a],
            },
        ]);
    }
    let mut by_site: Vec<(usize, Vec<Ray>)> = line.iter().copied().zip(rays_of).collect();
    by_site.sort_unstable_by_key(|&(s, _)| s);
    for (s, rays) in by_site {
        v.site_points.push(points[s]);
        v.rays.extend(rays);
        v.vertex_start.push(0);
        v.ray_start.push(v.rays.len());
    }
}

/// The index type of a triangulation's arrays: `usize` in a [`Triangulation`], `u32` in the
/// builder's own.
trait HalfEdgeId: Copy + PartialEq + Send + Sync {
    /// The value of a hull half-edge's missing opposite.
    const NONE: Self;
    fn index(self) -> usize;
}

impl HalfEdgeId for usize {
    const NONE: usize = EMPTY;
    #[inline(always)]
    fn index(self) -> usize {
        self
    }
}

impl HalfEdgeId for u32 {
    const NONE: u32 = NO_TWIN;
    #[inline(always)]
    fn index(self) -> usize {
        self as usize
    }
}

/// The unit normal of the hull edge `a -> b` pointing out of the hull (to its right).
fn outward_normal(a: Point2, b: Point2) -> Point2 {
    let d = unit_direction(a, b);
    Point2::new(d.y, -d.x)
}

#[cfg(all(test, feature = "parallel"))]
mod tests {
    use super::*;

    /// The parallel circumcentres keep the vertices beyond the range of `f64` (saturated,
    /// and listed with their wide coordinates) exactly as the sequential ones do.
    #[test]
    fn parallel_circumcentres_list_the_same_vertices_beyond_the_range() {
        let points = [
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 0.0),
            Point2::new(0.0, 1.0),
            // Nearly collinear at the top of the range: the centre is far beyond it.
            Point2::new(-1e308, 0.0),
            Point2::new(1e308, 0.0),
            Point2::new(0.0, 1e-300),
        ];
        let tri: Vec<u32> = (0..70_000u32)
            .flat_map(|t| if t % 3 == 0 { [3, 4, 5] } else { [0, 1, 2] })
            .collect();
        let pool = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a small pool")
        };
        let sequential = pool(1).install(|| circumcentres(&points, &tri));
        assert_eq!(sequential.1.len(), 70_000usize.div_ceil(3));
        assert!(sequential.0[0].y.abs() == f64::MAX);
        for threads in [2, 3] {
            assert_eq!(
                pool(threads).install(|| circumcentres(&points, &tri)),
                sequential
            );
        }
    }
}
