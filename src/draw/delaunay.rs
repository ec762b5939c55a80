//! Pictures of the Delaunay triangulation (optionally with its circumcircles) and of the
//! Voronoi diagram clipped to a box.

use super::{bounds_of, check_indices, indexed_points, Layer, Picture, Role};
use crate::delaunay::{ClipBox, Triangulation, Voronoi};
use crate::error::{Error, Result};
use crate::geometry::{Point2, PointSet};

/// The triangulation over its points: every triangle as a closed subpath (grey), the hull's
/// boundary as a lightly filled polygon, the points numbered by input index when the picture
/// shows labels, and with `circumcircles` (the dual diagram, whose vertex `k` is the
/// circumcentre of triangle `k`, as [`dual`](crate::delaunay::dual) and
/// [`voronoi`](crate::delaunay::voronoi) build it) each triangle's circumcircle. A
/// circumcircle larger than a hundred pictures (a nearly flat triangle on the hull) is
/// left out, and the legend says how many were.
///
/// A triangulation without triangles (fewer than three distinct points, or all collinear)
/// draws its hull: the points in order along their line.
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"triangulation"`) if a vertex index is out of range
/// or the triangle array is not a whole number of triangles, and (name `"circumcircles"`)
/// if the diagram's vertices are not one per triangle.
///
/// # Complexity
/// O(n + t) time and output size for n points and t triangles.
///
/// ```
/// use compgeo::delaunay::{dual, incremental};
/// use compgeo::draw;
/// use compgeo::geometry::{Point2, PointSet};
///
/// let pts = [(0.0, 0.0), (2.0, 0.0), (1.0, 1.5), (1.0, -1.0)].map(Point2::from);
/// let t = incremental(&pts)?;
/// let set = PointSet::new(&pts)?;
/// let plain = draw::delaunay(&set, &t, None)?;
/// assert!(plain.layers().any(|layer| layer == ("triangles", 2)));
/// let circles = draw::delaunay(&set, &t, Some(&dual(&pts, &t)?))?;
/// assert!(circles.layers().any(|layer| layer == ("circumcircles", 2)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn delaunay(
    points: &PointSet<'_>,
    t: &Triangulation,
    circumcircles: Option<&Voronoi>,
) -> Result<Picture> {
    let n = points.len();
    if t.triangles.len() % 3 != 0 {
        return Err(Error::InvalidParameter {
            name: "triangulation",
            reason: format!(
                "{} triangle vertices are not a whole number of triangles",
                t.triangles.len()
            ),
        });
    }
    check_indices(
        "triangulation",
        t.triangles.iter().chain(&t.hull).copied(),
        n,
    )?;
    if let Some(v) = circumcircles {
        if v.vertices.len() != t.triangle_count() {
            return Err(Error::InvalidParameter {
                name: "circumcircles",
                reason: format!(
                    "the diagram has {} vertices for {} triangles",
                    v.vertices.len(),
                    t.triangle_count()
                ),
            });
        }
    }
    let title = format!(
        "Delaunay triangulation: {} triangles on {} points",
        t.triangle_count(),
        n
    );
    let mut picture = Picture::new(&title, bounds_of(points), n);
    picture.polygons(
        &Layer::new("hull", Role::Result).legend("convex hull"),
        [t.hull.iter().map(|&i| points[i])],
    );
    let triangles = t.triangle_count();
    picture.polygons(
        &Layer::new("triangles", Role::Triangulation).legend(format!("{triangles} triangles")),
        (0..triangles).map(|k| t.triangle(k).map(|i| points[i])),
    );
    if let Some(v) = circumcircles {
        picture.circles(
            &Layer::new("circumcircles", Role::Circle).legend("circumcircles"),
            (0..triangles).map(|k| (v.vertex(k), points[t.triangle(k)[0]])),
        );
    }
    indexed_points(&mut picture, points, "point index");
    Ok(picture)
}

/// The Voronoi diagram's cells clipped to `bounds` ([`Voronoi::clip`]), each a closed
/// subpath (green), over the box's outline (orange, dashed) and the sites, numbered by input
/// index when the picture shows labels. A cell whose clipped polygon is empty (the box
/// misses it) draws nothing. The frame holds the box and the points.
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"voronoi"`) if a cell's site is out of range for
/// `points` (a diagram of other points).
///
/// # Complexity
/// O(n) time and output size for n sites.
///
/// ```
/// use compgeo::delaunay::{voronoi, ClipBox};
/// use compgeo::draw;
/// use compgeo::geometry::{Point2, PointSet};
///
/// let pts = [(0.0, 0.0), (2.0, 0.0), (1.0, 1.5), (1.0, -1.0)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let picture = draw::voronoi(&set, &voronoi(&pts)?, &ClipBox::around(&set)?)?;
/// assert!(picture.layers().any(|layer| layer == ("cells", 4)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn voronoi(points: &PointSet<'_>, v: &Voronoi, bounds: &ClipBox) -> Result<Picture> {
    let n = points.len();
    check_indices("voronoi", v.sites.iter().copied(), n)?;
    let corners = [
        bounds.min,
        Point2::new(bounds.max.x, bounds.min.y),
        bounds.max,
        Point2::new(bounds.min.x, bounds.max.y),
    ];
    let mut frame = bounds_of(points);
    if n == 0 {
        frame.min = bounds.min;
        frame.max = bounds.min;
    }
    frame.extend(bounds.min);
    frame.extend(bounds.max);
    let cells = v.clip(bounds);
    let title = format!("Voronoi diagram: {} cells, clipped", v.cell_count());
    let mut picture = Picture::new(&title, frame, n);
    picture.polygons(
        &Layer::new("clip-box", Role::Construction).legend("clipping box"),
        [corners],
    );
    picture.polygons(
        &Layer::new("cells", Role::Voronoi).legend("Voronoi cells"),
        cells.iter().filter(|c| !c.is_empty()).map(|c| c.iter()),
    );
    indexed_points(&mut picture, points, "site index");
    Ok(picture)
}
