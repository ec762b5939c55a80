//! Pictures of the proximity answers over their point set: the closest pair, the Euclidean
//! minimum spanning tree and the largest empty circle.

use super::{bounds_of, check_indices, indexed_points, value, Layer, Picture, Role};
use crate::error::Result;
use crate::geometry::{PointPair, PointSet, WideFloat};
use crate::graph::SpanningForest;
use crate::proximity::EmptyCircle;

/// The point set with its closest pair: the segment between the two points and a ring
/// around each (vermillion, so the pair is found at a glance among 10⁵ points), the points
/// numbered by input index when the picture shows labels.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"pair"`) if an index
/// is out of range.
///
/// # Complexity
/// O(n) time and output size.
///
/// ```
/// use compgeo::draw;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::proximity::{closest_pair, ClosestPairAlgorithm};
///
/// let pts = [(0.0, 0.0), (3.0, 4.0), (9.0, 9.0), (3.5, 5.0)].map(Point2::from);
/// let pair = closest_pair(&pts, ClosestPairAlgorithm::Delaunay)?;
/// let svg = draw::closest_pair(&PointSet::new(&pts)?, &pair)?.to_svg();
/// assert!(svg.contains("<g class=\"closest-pair\""));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn closest_pair(points: &PointSet<'_>, pair: &PointPair) -> Result<Picture> {
    let n = points.len();
    check_indices("pair", pair.pair, n)?;
    let title = format!("closest pair of {n} points");
    let mut picture = Picture::new(&title, bounds_of(points), n);
    let ends = pair.pair.map(|i| points[i]);
    picture.segments(
        &Layer::new("closest-pair", Role::Highlight)
            .legend(format!("closest pair, distance {}", value(pair.distance))),
        [ends],
    );
    picture.rings(&Layer::new("closest-pair-rings", Role::Highlight), ends);
    indexed_points(&mut picture, points, "point index");
    Ok(picture)
}

/// The point set with its Euclidean minimum spanning tree (blue edges, as
/// [`euclidean_mst`](crate::proximity::euclidean_mst) returns them), the points numbered by
/// input index when the picture shows labels.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"tree"`) if an edge
/// names a point out of range.
///
/// # Complexity
/// O(n) time and output size.
///
/// ```
/// use compgeo::draw;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::proximity::euclidean_mst;
///
/// let pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (5.0, 1.0)].map(Point2::from);
/// let tree = euclidean_mst(&pts)?;
/// let picture = draw::emst(&PointSet::new(&pts)?, &tree)?;
/// assert!(picture.layers().any(|layer| layer == ("emst", 3)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn emst(points: &PointSet<'_>, tree: &SpanningForest<[usize; 2]>) -> Result<Picture> {
    let n = points.len();
    check_indices("tree", tree.edges.iter().flatten().copied(), n)?;
    let title = format!("Euclidean minimum spanning tree of {n} points");
    let mut picture = Picture::new(&title, bounds_of(points), n);
    picture.segments(
        &Layer::new("emst", Role::Result).legend(format!(
            "{} tree edges, length {}",
            tree.edges.len(),
            value(tree.weight)
        )),
        tree.edges.iter().map(|e| e.map(|i| points[i])),
    );
    indexed_points(&mut picture, points, "point index");
    Ok(picture)
}

/// The point set with its largest empty circle centred in the hull: the hull (`hull`, in
/// boundary order, as the crate's hull functions give it), the circle (purple) through the
/// sites that define it, the radii to those sites (orange, dashed), the centre and rings
/// around the sites (vermillion), the points numbered by input index when the picture shows
/// labels. The frame holds the points and the circle.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"hull"` or
/// `"circle"`) if an index is out of range.
///
/// # Complexity
/// O(n) time and output size.
///
/// ```
/// use compgeo::draw;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{convex_hull, Algorithm, HullOptions};
/// use compgeo::proximity::largest_empty_circle;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0), (1.0, 1.0)].map(Point2::from);
/// let hull = convex_hull(&pts, Algorithm::Graham, HullOptions::default())?;
/// let circle = largest_empty_circle(&pts)?;
/// let picture = draw::empty_circle(&PointSet::new(&pts)?, &hull, &circle)?;
/// assert!(picture.layers().any(|layer| layer == ("empty-circle", 1)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn empty_circle(
    points: &PointSet<'_>,
    hull: &[usize],
    circle: &EmptyCircle,
) -> Result<Picture> {
    let n = points.len();
    check_indices("hull", hull.iter().copied(), n)?;
    check_indices("circle", circle.sites.iter().copied(), n)?;
    let mut bounds = bounds_of(points);
    let c = circle.centre;
    for (dx, dy) in [(-1.0, -1.0), (1.0, 1.0)] {
        let r = circle.radius;
        let x = WideFloat::from(c.x).add(r.mul(WideFloat::from(dx)));
        let y = WideFloat::from(c.y).add(r.mul(WideFloat::from(dy)));
        bounds.extend(crate::geometry::Point2::new(
            x.to_f64_saturating(),
            y.to_f64_saturating(),
        ));
    }
    let title = format!("largest empty circle among {n} points");
    let mut picture = Picture::new(&title, bounds, n);
    let sites: Vec<_> = circle.sites.iter().map(|&i| points[i]).collect();
    picture.polygons(
        &Layer::new("hull", Role::Result).legend("convex hull"),
        [hull.iter().map(|&i| points[i])],
    );
    picture.circles(
        &Layer::new("empty-circle", Role::Circle).legend(format!(
            "largest empty circle, radius {}",
            value(circle.radius)
        )),
        sites.first().map(|&s| (c, s)),
    );
    picture.segments(
        &Layer::new("radii", Role::Construction).legend("radii to its sites"),
        sites.iter().map(|&s| [c, s]),
    );
    picture.rings(&Layer::new("sites", Role::Highlight), sites.iter().copied());
    picture.points(&Layer::new("centre", Role::Highlight).legend("centre"), [c]);
    indexed_points(&mut picture, points, "point index");
    Ok(picture)
}
