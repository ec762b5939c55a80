//! Clipping Voronoi cells to a box.

use super::voronoi::Voronoi;
use crate::error::{Error, Result};
use crate::geometry::clip_predicates::{CellLines, Meet};
use crate::geometry::{BoundingBox, ConstructedPoint, Point2, PointSet};

/// An axis-parallel box to clip Voronoi cells to: `min.x < max.x`, `min.y < max.y`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClipBox {
    /// The lower-left corner.
    pub min: Point2,
    /// The upper-right corner.
    pub max: Point2,
}

impl ClipBox {
    /// The box `[x0, x1] × [y0, y1]`.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"box"`) if a coordinate is not finite or the box is
    /// empty or flat (`x0 >= x1` or `y0 >= y1`).
    ///
    /// ```
    /// use compgeo::delaunay::ClipBox;
    ///
    /// assert!(ClipBox::new(0.0, 0.0, 1.0, 2.0).is_ok());
    /// assert!(ClipBox::new(0.0, 0.0, 0.0, 2.0).is_err());
    /// assert!(ClipBox::new(0.0, f64::NAN, 1.0, 2.0).is_err());
    /// ```
    pub fn new(x0: f64, y0: f64, x1: f64, y1: f64) -> Result<ClipBox> {
        if ![x0, y0, x1, y1].iter().all(|v| v.is_finite()) || x0 >= x1 || y0 >= y1 {
            return Err(Error::InvalidParameter {
                name: "box",
                reason: format!(
                    "[{x0}, {y0}, {x1}, {y1}] is not a box x0 < x1, y0 < y1 of finite numbers"
                ),
            });
        }
        Ok(ClipBox {
            min: Point2::new(x0, y0),
            max: Point2::new(x1, y1),
        })
    }

    /// The default box for `points`: their bounding box grown by a quarter of its larger side
    /// on every side (by a quarter of the largest coordinate, or 1, if the points coincide),
    /// clamped to the finite range. It is never flat: a side the margin cannot move (a
    /// margin below the coordinate's precision) moves by one unit in the last place.
    ///
    /// # Errors
    /// [`Error::TooFew`] for no points (there is nothing to size the box by).
    ///
    /// ```
    /// use compgeo::delaunay::ClipBox;
    /// use compgeo::geometry::{Point2, PointSet};
    ///
    /// let pts = [Point2::new(0.0, 0.0), Point2::new(4.0, 2.0)];
    /// let b = ClipBox::around(&PointSet::new(&pts)?)?;
    /// assert_eq!((b.min, b.max), (Point2::new(-1.0, -1.0), Point2::new(5.0, 3.0)));
    ///
    /// // Two sites 1 apart at x = 1e300: the margin 0.25 is below x's precision.
    /// let pts = [Point2::new(1e300, 0.0), Point2::new(1e300, 1.0)];
    /// let b = ClipBox::around(&PointSet::new(&pts)?)?;
    /// assert!(b.min.x < 1e300 && 1e300 < b.max.x);
    /// assert_eq!((b.min.y, b.max.y), (-0.25, 1.25));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn around(points: &PointSet<'_>) -> Result<ClipBox> {
        let Some(BoundingBox { min: lo, max: hi }) = points.bounding_box() else {
            return Err(Error::TooFew {
                what: "point set",
                needed: 1,
                got: 0,
            });
        };
        let side = (hi.x / 4.0 - lo.x / 4.0).max(hi.y / 4.0 - lo.y / 4.0);
        let margin = if side > 0.0 {
            side
        } else {
            let m = lo.x.abs().max(lo.y.abs()) / 4.0;
            if m > 0.0 {
                m
            } else {
                1.0
            }
        };
        // Each side moves out by the margin, or by one unit in the last place where the
        // margin is below the coordinate's precision (points 1e300 apart by 1), so the box
        // is never flat; only at `±f64::MAX` can a side not move, and then the other does.
        let down = |v: f64| {
            let w = (v - margin).max(-f64::MAX);
            if w < v {
                w
            } else {
                v.next_down().max(-f64::MAX)
            }
        };
        let up = |v: f64| {
            let w = (v + margin).min(f64::MAX);
            if w > v {
                w
            } else {
                v.next_up().min(f64::MAX)
            }
        };
        Ok(ClipBox {
            min: Point2::new(down(lo.x), down(lo.y)),
            max: Point2::new(up(hi.x), up(hi.y)),
        })
    }
}

impl Voronoi {
    /// Cell `k` intersected with `bounds`, as a counter-clockwise polygon: empty if they do
    /// not overlap in an area, or if the overlap's points round to fewer than three distinct
    /// ones (a sliver below the precision of `f64`). Panics if `k` is out of range.
    ///
    /// Every decision is exact: the clipper works from the lines that bound the cell (the
    /// bisectors of its site and its Delaunay neighbours) and the box's sides, never from
    /// rounded vertices, and decides on which side of a line two others meet with exact
    /// predicates (Sutherland–Hodgman clipping against the four sides, with the rays of an
    /// unbounded cell closed at infinity). So the polygon has the right shape for nearly
    /// collinear sites, far-away vertices and boxes as large as the range of `f64`.
    ///
    /// The coordinates are rounded constructions: a box corner is exact, a point on a side
    /// has that side's coordinate exactly and the other within
    /// [`ConstructedPoint::RELATIVE_ERROR`](crate::geometry::ConstructedPoint::RELATIVE_ERROR)
    /// of its value, as has a vertex inside the box; every point lies in the box. Consecutive
    /// points that round to the same value are merged.
    ///
    /// # Complexity
    /// O(k) time and space for a cell with k vertices.
    ///
    /// ```
    /// use compgeo::delaunay::{voronoi, ClipBox};
    /// use compgeo::geometry::Point2;
    ///
    /// // Nearly collinear sites: the bisectors cross the box at x + y = 1 and x + y = 4.
    /// let pts = [(0.0, 0.0), (1.0, 1.0), (3.0, 3.0000000000000004)].map(Point2::from);
    /// let v = voronoi(&pts)?;
    /// let bounds = ClipBox::new(-1.0, -1.0, 4.0, 4.0)?;
    /// let first = v.clip_cell(v.cell_of(0), &bounds);
    /// assert!(first.iter().all(|p| p.x + p.y <= 1.0));
    /// assert!(first.contains(&Point2::new(2.0, -1.0)) && first.contains(&Point2::new(-1.0, 2.0)));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn clip_cell(&self, k: usize, bounds: &ClipBox) -> Vec<Point2> {
        let mut out = Vec::new();
        if self.clip_or_keep(k, bounds, &mut out) {
            out.extend(self.cell_vertices(k).iter().map(|&i| self.vertices[i]));
        }
        out
    }

    /// Cell `k` intersected with `bounds`: `true` if that is the cell's own vertex polygon
    /// (every vertex surely inside, no two consecutive ones equal), else `false` with the
    /// polygon appended to `out` (nothing for an empty one).
    fn clip_or_keep(&self, k: usize, bounds: &ClipBox, out: &mut Vec<Point2>) -> bool {
        let cell = self.cell(k);
        let corners = [
            bounds.min,
            Point2::new(bounds.max.x, bounds.min.y),
            bounds.max,
            Point2::new(bounds.min.x, bounds.max.y),
        ];
        if self.cell_count() == 1 {
            out.extend(corners);
            return false;
        }
        if cell.bounded
            && cell
                .vertices
                .iter()
                .all(|&i| surely_inside(self.vertices[i], bounds))
        {
            // The box is convex: a cell whose vertices are all in it is its own clip, with
            // repeated vertices (cocircular sites) merged.
            let at = |j: usize| self.vertices[cell.vertices[j]];
            let m = cell.vertices.len();
            if (0..m).all(|j| at(j) != at((j + 1) % m)) {
                return true;
            }
            merge_into((0..m).map(at), out);
            return false;
        }
        let (lines, mut poly) = self.cell_polygon(k, bounds);
        for side in 0..4 {
            poly = clip_side(&poly, lines.side(side), &lines);
        }
        // An intersection without area lies on one side's line (the cell and the box
        // touch along it): every vertex is then on that line.
        let flat = (0..4).any(|side| poly.iter().all(|v| lines.sign(v.at, lines.side(side)) == 0));
        if !flat {
            merge_into(
                poly.iter().map(|v| match v.at {
                    Meet::Lines(i, j) => lines.point(i, j),
                    Meet::Normal(_) => {
                        unreachable!("the box's sides cut off every point at infinity")
                    }
                }),
                out,
            );
        }
        false
    }

    /// The lines of cell `k` and the polygon of its boundary, counter-clockwise, each vertex
    /// where two of them meet (closed through the line at infinity when unbounded).
    fn cell_polygon(&self, k: usize, bounds: &ClipBox) -> (CellLines, Vec<Vertex>) {
        let cell = self.cell(k);
        let m = cell.vertices.len();
        // Neighbour sites, one per bisector line: an unbounded cell's arriving ray first.
        let mut neighbours: Vec<usize> = Vec::with_capacity(m + 2);
        if m == 0 {
            // Collinear sites: one bisector line per chain.
            neighbours.extend(cell.rays.chunks_exact(2).map(|pair| pair[0].sites[1]));
        } else {
            if !cell.bounded {
                neighbours.push(cell.rays[0].sites[1]);
            }
            neighbours.extend((0..m).map(|j| self.across(k, j)));
        }
        let lines = CellLines::new(
            self.site_point(k),
            neighbours.iter().map(|&i| self.point_of(i)).collect(),
            [bounds.min.x, bounds.min.y, bounds.max.x, bounds.max.y],
        );
        let inf = lines.infinity();
        let n = neighbours.len();
        let vertex = |arrive: usize, leave: usize| Vertex {
            at: Meet::Lines(arrive, leave),
            out: leave,
        };
        let poly = if m == 0 {
            let mut poly = Vec::with_capacity(2 * n + 1);
            for line in 0..n {
                poly.push(vertex(inf, line));
                poly.push(vertex(line, inf));
            }
            if n == 1 {
                // A half-plane: half a turn at infinity, split at its inner normal.
                poly.push(Vertex {
                    at: Meet::Normal(0),
                    out: inf,
                });
            }
            poly
        } else if cell.bounded {
            (0..n).map(|j| vertex((j + n - 1) % n, j)).collect()
        } else {
            let mut poly = Vec::with_capacity(n + 1);
            poly.push(vertex(inf, 0));
            poly.extend((1..n).map(|j| vertex(j - 1, j)));
            poly.push(vertex(n - 1, inf));
            poly
        };
        (lines, poly)
    }
    /// Every cell intersected with `bounds` ([`clip_cell`](Voronoi::clip_cell)), in cell
    /// order.
    ///
    /// A cell that lies inside the box is its own clip: the result refers to its vertices
    /// in the diagram rather than copying them, and stores only the polygons cut at the
    /// box's sides (O(√n) of them for sites spread over the box). So clipping a million
    /// cells allocates a few arrays, not a million polygons or a copy of every vertex.
    ///
    /// # Complexity
    /// O(n) time for n sites (the cells' vertex counts sum to less than 6n); O(n) space,
    /// 4 bytes a cell plus the polygons cut by the box.
    ///
    /// ```
    /// use compgeo::delaunay::{voronoi, ClipBox};
    /// use compgeo::geometry::Point2;
    ///
    /// let pts = [(0.0, 0.0), (2.0, 0.0)].map(Point2::from);
    /// let v = voronoi(&pts)?;
    /// let cells = v.clip(&ClipBox::new(-1.0, -1.0, 3.0, 1.0)?);
    /// assert_eq!(cells.len(), 2);
    /// // The bisector x = 1 splits the box in two.
    /// let left = cells.polygon(v.cell_of(0));
    /// assert_eq!(left.len(), 4);
    /// for corner in [(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)] {
    ///     assert!(left.iter().any(|p| p == Point2::from(corner)));
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn clip(&self, bounds: &ClipBox) -> ClippedCells<'_> {
        let n = self.cell_count();
        let mut polygon = Vec::with_capacity(n);
        let (mut points, mut start) = (Vec::new(), vec![0]);
        for k in 0..n {
            if self.clip_or_keep(k, bounds, &mut points) {
                polygon.push(KEPT);
            } else {
                // Below 2^32 cut polygons: a diagram has fewer than 2^29 cells.
                polygon.push((start.len() - 1) as u32);
                start.push(points.len());
            }
        }
        ClippedCells {
            diagram: self,
            polygon,
            points,
            start,
        }
    }
}

/// [`ClippedCells::polygon`] of a cell that is its own clip.
const KEPT: u32 = u32::MAX;

/// The cells of a [`Voronoi`] diagram clipped to a [`ClipBox`] ([`Voronoi::clip`]): one
/// counter-clockwise [`ClippedPolygon`] per cell, in cell order, empty for a cell outside
/// the box. It borrows the diagram, whose vertices form the polygons of the cells inside
/// the box.
///
/// ```
/// use compgeo::delaunay::{voronoi, ClipBox};
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (0.0, 4.0), (9.0, 9.0)].map(Point2::from);
/// let v = voronoi(&pts)?;
/// let cells = v.clip(&ClipBox::new(-1.0, -1.0, 1.0, 1.0)?);
/// // Only the first site's cell reaches the small box about it.
/// assert_eq!(cells.polygon(v.cell_of(0)).len(), 4);
/// assert_eq!(cells.iter().filter(|c| c.is_empty()).count(), 3);
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct ClippedCells<'a> {
    diagram: &'a Voronoi,
    /// Per cell: [`KEPT`] for a cell inside the box, else its polygon's number in `start`.
    polygon: Vec<u32>,
    /// The cut polygons' points, back to back: number j is `points[start[j]..start[j + 1]]`.
    points: Vec<Point2>,
    start: Vec<usize>,
}

impl<'a> ClippedCells<'a> {
    /// The number of cells (as [`Voronoi::cell_count`]), empty polygons included.
    pub fn len(&self) -> usize {
        self.polygon.len()
    }

    /// Whether there are no cells (never, for a diagram of at least one site).
    pub fn is_empty(&self) -> bool {
        self.polygon.is_empty()
    }

    /// Cell `k`'s polygon. Panics if `k` is out of range (see [`get`](Self::get)).
    pub fn polygon(&self, k: usize) -> ClippedPolygon<'_> {
        match self.polygon[k] {
            KEPT => ClippedPolygon::Kept {
                ids: self.diagram.cell_vertices(k),
                vertices: &self.diagram.vertices,
            },
            j => {
                let j = j as usize;
                ClippedPolygon::Cut(&self.points[self.start[j]..self.start[j + 1]])
            }
        }
    }

    /// Cell `k`'s polygon, `None` if `k` is out of range.
    pub fn get(&self, k: usize) -> Option<ClippedPolygon<'_>> {
        (k < self.len()).then(|| self.polygon(k))
    }

    /// The polygons in cell order.
    pub fn iter(
        &self,
    ) -> impl ExactSizeIterator<Item = ClippedPolygon<'_>> + DoubleEndedIterator + '_ {
        (0..self.len()).map(|k| self.polygon(k))
    }

    /// The polygons as vectors of points, in cell order.
    pub fn to_vecs(&self) -> Vec<Vec<Point2>> {
        self.iter().map(|p| p.to_vec()).collect()
    }
}

/// One polygon of [`ClippedCells`], counter-clockwise: a view of a cell's vertices when
/// the cell is inside the box, or of the points of its cut polygon.
#[derive(Debug, Clone, Copy)]
pub enum ClippedPolygon<'a> {
    /// A cell inside the box: its vertices, as indices into the diagram's vertices.
    Kept {
        /// The cell's vertex indices ([`Cell::vertices`](super::Cell::vertices)).
        ids: &'a [usize],
        /// The diagram's vertices ([`Voronoi::vertices`]).
        vertices: &'a [Point2],
    },
    /// A cell cut by the box (or outside it: then empty): its points.
    Cut(&'a [Point2]),
}

impl<'a> ClippedPolygon<'a> {
    /// The number of points.
    pub fn len(&self) -> usize {
        match self {
            ClippedPolygon::Kept { ids, .. } => ids.len(),
            ClippedPolygon::Cut(points) => points.len(),
        }
    }

    /// Whether the polygon is empty (the cell misses the box, or meets it without area).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The `j`-th point, `None` if `j` is out of range.
    pub fn get(&self, j: usize) -> Option<Point2> {
        match *self {
            ClippedPolygon::Kept { ids, vertices } => ids.get(j).map(|&i| vertices[i]),
            ClippedPolygon::Cut(points) => points.get(j).copied(),
        }
    }

    /// The points, counter-clockwise.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = Point2> + DoubleEndedIterator + 'a {
        let polygon = *self;
        (0..self.len()).map(move |j| match polygon {
            ClippedPolygon::Kept { ids, vertices } => vertices[ids[j]],
            ClippedPolygon::Cut(points) => points[j],
        })
    }

    /// The points, counter-clockwise, in a vector.
    pub fn to_vec(&self) -> Vec<Point2> {
        self.iter().collect()
    }
}

/// A vertex of a polygon being clipped: where it is, and the line its leaving edge lies on.
#[derive(Debug, Clone, Copy)]
struct Vertex {
    at: Meet,
    out: usize,
}

/// Sutherland–Hodgman against the half-plane of line `side`, with exact signs. A vertex on
/// the line is kept and no crossing is made there, so every point appears once.
fn clip_side(poly: &[Vertex], side: usize, lines: &CellLines) -> Vec<Vertex> {
    let signs: Vec<i32> = poly.iter().map(|v| lines.sign(v.at, side)).collect();
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (i, &u) in poly.iter().enumerate() {
        let next = (i + 1) % poly.len();
        let (su, sv) = (signs[i], signs[next]);
        if su >= 0 {
            // Leaving the half-plane at `u` itself: the boundary follows the side from here.
            let out_line = if su == 0 && sv < 0 { side } else { u.out };
            out.push(Vertex {
                at: u.at,
                out: out_line,
            });
        }
        if su > 0 && sv < 0 {
            out.push(Vertex {
                at: Meet::Lines(u.out, side),
                out: side,
            });
        } else if su < 0 && sv > 0 {
            out.push(Vertex {
                at: Meet::Lines(side, u.out),
                out: u.out,
            });
        }
    }
    out
}

/// Whether the exact value of a constructed vertex `p` (within
/// [`ConstructedPoint::RELATIVE_ERROR`] of it) is surely in the box: every rounded gap to
/// a side exceeds twice the error bound. A vertex clamped to `±f64::MAX` never is.
fn surely_inside(p: Point2, b: &ClipBox) -> bool {
    let err = ConstructedPoint::RELATIVE_ERROR * p.x.abs().max(p.y.abs()) + f64::MIN_POSITIVE;
    let clear = |gap: f64| gap > 2.0 * err;
    p.x.abs() < f64::MAX
        && p.y.abs() < f64::MAX
        && clear(p.x - b.min.x)
        && clear(b.max.x - p.x)
        && clear(p.y - b.min.y)
        && clear(b.max.y - p.y)
}

/// Appends the points to `out` with consecutive equal ones merged (first and last too);
/// appends nothing if fewer than three remain.
fn merge_into(points: impl Iterator<Item = Point2>, out: &mut Vec<Point2>) {
    let from = out.len();
    for q in points {
        if out.len() == from || out.last() != Some(&q) {
            out.push(q);
        }
    }
    while out.len() > from + 1 && out[from] == out[out.len() - 1] {
        out.pop();
    }
    if out.len() < from + 3 {
        out.truncate(from);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::voronoi;

    fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
        v.iter().map(|&p| Point2::from(p)).collect()
    }

    fn area(poly: &[Point2]) -> f64 {
        (0..poly.len())
            .map(|i| {
                let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
                p.x * q.y - p.y * q.x
            })
            .sum::<f64>()
            / 2.0
    }

    #[test]
    fn one_site_owns_the_whole_box() {
        let p = pts(&[(5.0, 5.0), (5.0, 5.0)]);
        let v = voronoi(&p).unwrap();
        assert_eq!(v.cell_count(), 1);
        assert_eq!(v.cell_of(1), 0);
        assert!(!v.cell(0).bounded);
        let b = ClipBox::new(0.0, 0.0, 2.0, 3.0).unwrap();
        assert_eq!(area(&v.clip_cell(0, &b)), 6.0);
    }

    #[test]
    fn collinear_sites_split_the_box_into_strips() {
        let p = pts(&[(2.0, 0.0), (0.0, 0.0), (6.0, 0.0)]);
        let v = voronoi(&p).unwrap();
        let b = ClipBox::new(-1.0, -1.0, 7.0, 1.0).unwrap();
        let cells = v.clip(&b);
        // Bisectors at x = 1 and x = 4.
        assert_eq!(area(&cells.polygon(v.cell_of(1)).to_vec()), 4.0);
        assert_eq!(area(&cells.polygon(v.cell_of(0)).to_vec()), 6.0);
        assert_eq!(area(&cells.polygon(v.cell_of(2)).to_vec()), 6.0);
    }

    #[test]
    fn an_inside_cell_is_kept_unless_its_vertices_repeat() {
        // A 4 by 4 lattice: every square's two triangles share their circumcentre, so an
        // inner cell lists each corner of its square twice.
        let lattice: Vec<(f64, f64)> = (0..16).map(|i| ((i % 4) as f64, (i / 4) as f64)).collect();
        let v = voronoi(&pts(&lattice)).unwrap();
        let b = ClipBox::new(-1.0, -1.0, 4.0, 4.0).unwrap();
        let cells = v.clip(&b);
        let inner = v.cell_of(5); // the site (1, 1)
        assert!(v.cell(inner).vertices.len() > 4);
        let square = cells.polygon(inner);
        assert!(matches!(square, ClippedPolygon::Cut(_)));
        assert_eq!(square.to_vec(), v.clip_cell(inner, &b));
        assert_eq!(square.len(), 4);
        assert_eq!(area(&square.to_vec()), 1.0);
        // Moved off the lattice, the sites are in general position: the inner cells are
        // their own clips, read from the diagram.
        let moved: Vec<(f64, f64)> = lattice
            .iter()
            .enumerate()
            .map(|(i, &(x, y))| (x + 0.01 * (i % 3) as f64, y + 0.013 * (i % 5) as f64))
            .collect();
        let v = voronoi(&pts(&moved)).unwrap();
        let cells = v.clip(&b);
        let kept = cells
            .iter()
            .filter(|c| matches!(c, ClippedPolygon::Kept { .. }));
        assert_eq!(kept.count(), 4);
        for (k, polygon) in cells.iter().enumerate().rev() {
            assert_eq!(polygon.to_vec(), v.clip_cell(k, &b));
            assert_eq!(polygon.get(polygon.len()), None);
        }
        assert!(cells.get(cells.len()).is_none());
    }

    #[test]
    fn a_box_away_from_a_cell_clips_it_to_nothing() {
        let p = pts(&[
            (0.0, 0.0),
            (10.0, 0.0),
            (0.0, 10.0),
            (10.0, 10.0),
            (5.0, 5.0),
        ]);
        let v = voronoi(&p).unwrap();
        let b = ClipBox::new(8.0, 8.0, 9.0, 9.0).unwrap();
        let cells = v.clip(&b);
        assert_eq!(area(&cells.polygon(v.cell_of(3)).to_vec()), 1.0);
        assert!(cells.polygon(v.cell_of(0)).is_empty() && cells.polygon(v.cell_of(4)).is_empty());
    }
}
