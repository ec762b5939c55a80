//! Pictures of a point set with its convex hull, and with the answers of the rotating
//! calipers (antipodal pairs, diameter, width, minimum-area and minimum-perimeter
//! rectangles).

use super::{bounds_of, check_indices, index_labels, points_legend, value, Layer, Picture, Role};
use crate::calipers::ConvexPolygon;
use crate::error::Result;
use crate::geometry::{PointPair, PointSet};

/// The point set with its convex hull: the hull as a lightly filled polygon, its vertices
/// numbered in hull order (`k` next to `hull[k]`) when the picture shows labels.
///
/// `hull` is any hull the crate computes (indices into `points`, in boundary order); an
/// empty point set gives an empty picture.
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"hull"`) if an index
/// is out of range.
///
/// # Complexity
/// O(n + h) time and output size for n points and h hull vertices (labels add O(h²) for at
/// most [`LABEL_LIMIT`](super::LABEL_LIMIT) points).
///
/// ```
/// use compgeo::draw;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{convex_hull, Algorithm, HullOptions};
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (1.0, 1.0), (4.0, 3.0), (0.0, 3.0)].map(Point2::from);
/// let hull = convex_hull(&pts, Algorithm::Graham, HullOptions::default())?;
/// let svg = draw::hull(&PointSet::new(&pts)?, &hull)?.to_svg();
/// assert!(svg.contains("<g class=\"hull\""));
/// for k in 0..4 {
///     assert!(svg.contains(&format!(">{k}</text>")));
/// }
/// assert!(draw::hull(&PointSet::new(&pts)?, &[0, 9]).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn hull(points: &PointSet<'_>, hull: &[usize]) -> Result<Picture> {
    check_indices("hull", hull.iter().copied(), points.len())?;
    let title = format!(
        "convex hull: {} vertices of {} points",
        hull.len(),
        points.len()
    );
    let mut picture = Picture::new(&title, bounds_of(points), points.len());
    picture.polygons(
        &Layer::new("hull", Role::Result).legend("convex hull"),
        [hull.iter().map(|&i| points[i])],
    );
    picture.points(
        &Layer::new("points", Role::Input).legend(points_legend(points.len())),
        points.iter().copied(),
    );
    picture.labels(
        &Layer::new("labels", Role::Label).legend("position in hull order"),
        hull.iter()
            .enumerate()
            .map(|(k, &i)| (points[i], k.to_string())),
    );
    Ok(picture)
}

/// The point set with its hull and everything the rotating calipers find on it: the
/// antipodal pairs (orange, dashed), the diameter `diameter` (vermillion: the pair from
/// [`ConvexPolygon::diameter`] or from [`diameter`](crate::calipers::diameter) by brute
/// force), the width's two supporting lines (vermillion, dashed), and the minimum-area
/// (dashed) and minimum-perimeter (dotted) enclosing rectangles (sky blue). The hull's
/// vertices are labelled with their input indices, as the pairs name them.
///
/// The pairs, the width and the rectangles are the polygon's own
/// ([`ConvexPolygon::antipodal_pairs`], [`ConvexPolygon::width`],
/// [`ConvexPolygon::min_area_rectangle`], [`ConvexPolygon::min_perimeter_rectangle`]). The
/// frame holds the points and the rectangles' corners.
///
/// # Errors
/// [`Error::TooFew`](crate::Error::TooFew) for a polygon without vertices, and
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) (name `"diameter"`) if the
/// pair is out of range for the polygon's points.
///
/// # Complexity
/// O(n + h) time and output size for n points and h hull vertices, after the calipers'
/// Θ(h).
///
/// ```
/// use compgeo::calipers::ConvexPolygon;
/// use compgeo::draw;
/// use compgeo::geometry::{Point2, PointSet};
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (2.0, 1.0)].map(Point2::from);
/// let polygon = ConvexPolygon::hull(&PointSet::new(&pts)?);
/// let picture = draw::calipers(&polygon, &polygon.diameter()?)?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("diameter", 1)) && layers.contains(&("width", 2)));
/// assert!(layers.contains(&("antipodal-pairs", polygon.antipodal_pairs().len())));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn calipers(polygon: &ConvexPolygon<'_>, diameter: &PointPair) -> Result<Picture> {
    let points = polygon.points();
    check_indices("diameter", diameter.pair, points.len())?;
    let width = polygon.width()?;
    let area = polygon.min_area_rectangle()?;
    let perimeter = polygon.min_perimeter_rectangle()?;
    let pairs = polygon.antipodal_pairs();
    let hull = polygon.vertices();
    let mut bounds = bounds_of(points);
    for corner in area.corners.iter().chain(&perimeter.corners) {
        bounds.extend(corner.saturating());
    }
    let title = format!(
        "rotating calipers: {} hull vertices of {} points",
        hull.len(),
        points.len()
    );
    let mut picture = Picture::new(&title, bounds, points.len());
    picture.polygons(
        &Layer::new("min-perimeter-rectangle", Role::Alternative.dotted()).legend(format!(
            "min-perimeter rectangle ({})",
            value(perimeter.perimeter)
        )),
        [perimeter.corners],
    );
    picture.polygons(
        &Layer::new("min-area-rectangle", Role::Alternative.dashed())
            .legend(format!("min-area rectangle ({})", value(area.area))),
        [area.corners],
    );
    picture.polygons(
        &Layer::new("hull", Role::Result).legend("convex hull"),
        [hull.iter().map(|&i| points[i])],
    );
    picture.segments(
        &Layer::new("antipodal-pairs", Role::Construction)
            .legend(format!("{} antipodal pairs", pairs.len())),
        pairs.iter().map(|&[i, j]| [points[i], points[j]]),
    );
    let [i, j] = width.edge;
    picture.parallels(
        &Layer::new("width", Role::Highlight.dashed())
            .legend(format!("width {}", value(width.width))),
        [points[i], points[j]],
        [points[i], points[width.vertex]],
    );
    picture.segments(
        &Layer::new("diameter", Role::Highlight)
            .legend(format!("diameter {}", value(diameter.distance))),
        [diameter.pair.map(|k| points[k])],
    );
    picture.points(
        &Layer::new("points", Role::Input).legend(points_legend(points.len())),
        points.iter().copied(),
    );
    picture.labels(
        &Layer::new("labels", Role::Label).legend("point index"),
        index_labels(points, hull.iter().copied()),
    );
    Ok(picture)
}
