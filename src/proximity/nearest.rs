//! Nearest-neighbour queries: a greedy walk on the Delaunay graph, started from a grid of
//! entry vertices.
//!
//! **Problem.** Given n sites fixed in advance, answer queries "which site is nearest to q?"
//! exactly (distances are compared with the exact [`cmp_dist`](crate::geometry::cmp_dist),
//! never rounded), with ties settled the same way whatever the route: the smallest input
//! index among the nearest sites.
//!
//! **Idea.** [RD, §2.4] (problem 4, "El vecino más cercano") locates the query in the Voronoi
//! diagram; here that is a greedy walk on its dual, the Delaunay graph: from the current site
//! move to the neighbour nearest to the query while that one is strictly nearer. A site that
//! is not a nearest one always has a strictly nearer Delaunay neighbour, so the walk ends at
//! a nearest site from *any* start; the start only decides how long the walk is. The start
//! comes from a uniform grid of about n cells over the sites' bounding box, each cell
//! holding the site nearest to its centre (found by walks at build time, cell after
//! neighbouring cell): the bucketing of Bentley, Weide and Yao (1980) used as a hint, as
//! Mücke, Saias and Zhu's jump-and-walk (1996) uses a random sample. The grid is computed
//! in floating point and may be wrong by a cell or clamp a far query to the border: that
//! costs steps, never exactness. The sites are renumbered along a Hilbert curve so that a
//! walk reads neighbouring memory. A batch ([`NearestSearch::nearest_all`]) sorts its
//! queries along a Hilbert curve and starts each walk at the previous answer or the cell's
//! entry, whichever is nearer to the query.
//!
//! **Complexity.** O(n log n) expected time to build (the triangulation, the curve sort, the
//! O(n) grid walks), O(n) space. A query costs O(d) per step for a vertex of degree d
//! (about six). Every step moves to a site strictly nearer to the query than the entry e,
//! so the steps are at most the sites in the disc about q through e, whose radius is at
//! most |q − c| + |c − e| for the cell's centre c: half a cell diagonal plus the distance
//! from c to its nearest site. For sites uniform in a square (one per cell on average) and
//! queries in their box both are O(1/√n) in expectation, and the disc holds O(1) expected
//! sites: O(1) expected steps. On any input the walk visits no site twice, so O(n) steps
//! in the worst case (a dense cluster inside one cell is crossed step by step; a query
//! far outside the box starts at a border cell).
//!
//! **Invariants tested** (`tests/suite/nearest.rs` and the unit tests below): the answer
//! equals a brute-force scan with exact comparisons and the smallest-index tie rule on
//! random, clustered, collinear, duplicated and lattice sets and at every magnitude from
//! subnormal to `f64::MAX`, for queries far outside; the answer does not depend on the start
//! (grid, hull vertex, any vertex, batch); each cell's entry is a site nearest to the cell's
//! centre; the mean counted distance evaluations per query on 10⁴ uniform sites are small.

use super::{adjacency, at_least, delaunay_edges};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::delaunay::{curve_order, grid_scale, incremental_with, Triangulation};
use crate::error::{Error, Result};
use crate::geometry::{BoundingBox, CountedPredicates, Point2, PointSet};
use std::cmp::Ordering;
use std::collections::HashSet;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "nearest",
    name: "delaunay-walk",
    function: "proximity::NearestSearch::nearest",
    file: "src/proximity/nearest.rs",
    summary: "a greedy walk on the Delaunay graph from a grid cell's entry vertex",
    time: "O(n log n) to build; O(1) expected steps per query on uniform points, O(n) worst",
    space: "O(n)",
    operation: Some(Operation::DistanceEvaluations),
    counts: "one per neighbour looked at during a walk, about six per step",
    source: "[RD, §2.4]",
    claims: &[
        on(
            "uniform-square",
            Bound::Constant,
            Operation::DistanceEvaluations,
        ),
        on(
            "random-queries",
            Bound::Linear,
            Operation::DistanceEvaluations,
        ),
    ],
};

/// Sites per grid cell on average: the grid has about n / `CELL_SITES` cells.
const CELL_SITES: usize = 1;

/// [`DelaunayGraph::local`] of a point that is no vertex (a merged duplicate).
const NO_VERTEX: u32 = u32::MAX;

/// Words of a star before its neighbours: x, y, and the input index with the degree.
const STAR_HEADER: usize = 3;

/// Nearest-neighbour queries on a fixed point set: its Delaunay graph and a grid of entry
/// vertices, built once.
///
/// A query starts at the entry of its grid cell (about one cell per site, each entered at
/// the site nearest to its centre) and walks the Delaunay graph greedily towards the query
/// ([`nearest_with`](Self::nearest_with)): O(1) expected steps on uniform points, an exact
/// answer on every input, since the walk is correct from any start and the grid is only a
/// hint. Batches of queries go faster through [`nearest_all`](Self::nearest_all).
///
/// ```
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::proximity::NearestSearch;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (0.0, 4.0), (4.0, 4.0), (2.0, 2.0)].map(Point2::from);
/// let set = PointSet::new(&pts)?;
/// let search = NearestSearch::new(&set)?;
/// assert_eq!(search.nearest(Point2::new(3.5, 0.2))?, 1);
/// assert_eq!(search.nearest(Point2::new(2.1, 1.9))?, 4);
/// assert_eq!(search.nearest(Point2::new(-100.0, 50.0))?, 2); // outside the hull
/// assert_eq!(search.nearest(Point2::new(2.0, 0.0))?, 0); // a tie: the smallest index
/// assert!(search.nearest(Point2::new(f64::NAN, 0.0)).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct NearestSearch<'a> {
    points: &'a [Point2],
    graph: DelaunayGraph,
}

/// The part of a [`NearestSearch`] that owns its data: the Delaunay graph of the distinct
/// sites and the grid of entry vertices. The catalog keeps one without the borrowed points.
///
/// A vertex is the position of its *star* in one flat array of 64-bit words: its point (two
/// words, the bits of x and y), its input index and degree (one word, low and high half),
/// then its neighbours' positions, two per word (about 52 bytes a site). The stars follow a
/// Hilbert curve through the sites, so a vertex's neighbours' stars are near it in memory
/// and a walk reads few distinct pages. (Copying the neighbours' points into each star, so
/// that a step reads one run of memory, tripled the size and measured no faster at 10⁶
/// sites.) Positions are 32-bit: a planar graph's stars take at most 6.5n words, so every
/// input the triangulation accepts (2^29 points) fits.
#[derive(Debug, Clone)]
pub(crate) struct DelaunayGraph {
    /// The stars, back to back.
    stars: Vec<u64>,
    /// The vertex (star position) of each input index, [`NO_VERTEX`] for a merged duplicate.
    local: Vec<u32>,
    /// The entry vertex of every cell.
    grid: EntryGrid,
}

/// A `cols` by `rows` grid over the sites' bounding box, in halved coordinates (the width of
/// `[-MAX, MAX]` would overflow), and the vertex nearest to each cell's centre.
#[derive(Debug, Clone)]
struct EntryGrid {
    half_min: Point2,
    half_max: Point2,
    /// Maps `0.5 * (x - min.x)` onto `[0, cols]` (0 for a zero width), likewise for y.
    scale_x: f64,
    scale_y: f64,
    cols: usize,
    rows: usize,
    /// Row by row, the entry vertex of each cell.
    entry: Vec<u32>,
}

impl<'a> NearestSearch<'a> {
    /// Triangulates `points` (the [`incremental`](crate::delaunay::incremental) builder) and indexes
    /// them for queries.
    ///
    /// # Errors
    /// [`Error::TooFew`] for no points, and the builder's size limit.
    ///
    /// # Complexity
    /// O(n log n) expected time, O(n) space.
    pub fn new(points: &PointSet<'a>) -> Result<NearestSearch<'a>> {
        at_least(1, points.len())?;
        let t = incremental_with(points, &mut NoCount)?;
        Ok(NearestSearch::from_triangulation(points, &t))
    }

    /// Indexes `points` with their Delaunay triangulation `t` (from one of the crate's
    /// builders; with another triangulation the greedy walk can stop at a wrong answer).
    ///
    /// # Complexity
    /// O(n log n + t) time (the Hilbert sort of the sites), O(n + t) space.
    pub fn from_triangulation(points: &PointSet<'a>, t: &Triangulation) -> NearestSearch<'a> {
        NearestSearch {
            points: points.points(),
            graph: DelaunayGraph::new(points.points(), t),
        }
    }

    /// The indexed points.
    ///
    /// ```
    /// use compgeo::geometry::{Point2, PointSet};
    /// use compgeo::proximity::NearestSearch;
    ///
    /// let pts = [Point2::new(1.0, 2.0)];
    /// let set = PointSet::new(&pts)?;
    /// assert_eq!(NearestSearch::new(&set)?.points(), &pts);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn points(&self) -> &'a [Point2] {
        self.points
    }

    /// The index of a point nearest to `query`; see [`nearest_with`](Self::nearest_with).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"query"`) if a coordinate of `query` is NaN or
    /// infinite.
    ///
    /// # Complexity
    /// O(n log n) to build; O(1) expected steps per query on uniform points, O(n) worst;
    /// O(n) space. A step costs O(d) time for a vertex of degree d (about six). No
    /// allocation unless the query is equidistant from several nearest sites.
    pub fn nearest(&self, query: Point2) -> Result<usize> {
        self.nearest_with(query, None, &mut NoCount)
    }

    /// The index of a point nearest to `query`, by a greedy walk on the Delaunay graph from
    /// `start` (or the entry vertex of the query's grid cell), counting its distance
    /// evaluations.
    ///
    /// From the current site the walk moves to its Delaunay neighbour nearest to the query
    /// while that one is strictly nearer ([RD, §2.4], problem 4 "El vecino más cercano":
    /// find the Voronoi region holding the query). A site that is not a nearest one always
    /// has a strictly nearer Delaunay neighbour (the segment from it to the query leaves its
    /// Voronoi cell through an edge shared with a neighbour, which is then nearer), so the
    /// walk ends at a nearest site, inside the hull or not, from any start.
    ///
    /// Ties: the smallest index among the nearest points, whatever the start. Sites at the
    /// same least distance lie on a circle about the query with no site inside, and
    /// consecutive ones around it are joined by Delaunay edges, so a search over the tied
    /// neighbours finds them all. A merged duplicate is never returned (its group's
    /// smallest index is).
    ///
    /// # Errors
    /// As [`nearest`](Self::nearest); also [`Error::InvalidParameter`] (name `"start"`) if
    /// `start` is not the index of a point kept by the triangulation.
    ///
    /// # Complexity
    /// As [`nearest`](Self::nearest) from the grid; from an explicit start, O(k) expected
    /// steps for a start k sites away from the answer on uniform points.
    ///
    /// # Counts
    /// One distance evaluation per neighbour looked at, and one per neighbour of a tied
    /// site when ties are settled.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::gen::{points, PointKind};
    /// use compgeo::geometry::{Point2, PointSet};
    /// use compgeo::proximity::NearestSearch;
    ///
    /// let pts = points(PointKind::UniformSquare, 2000, 7)?;
    /// let set = PointSet::new(&pts)?;
    /// let search = NearestSearch::new(&set)?;
    /// let mut counts = Counts::default();
    /// let q = Point2::new(0.5, 0.5);
    /// let i = search.nearest_with(q, None, &mut counts)?;
    /// assert!(counts.distance_evaluations < 100);
    /// assert!(pts.iter().all(|p| (p.x - q.x).hypot(p.y - q.y) >= (pts[i].x - q.x).hypot(pts[i].y - q.y)));
    /// // The same answer from another start, after a longer walk.
    /// assert_eq!(search.nearest_with(q, Some(0), &mut counts)?, i);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn nearest_with<C: Counter>(
        &self,
        query: Point2,
        start: Option<usize>,
        counter: &mut C,
    ) -> Result<usize> {
        self.graph.walk(query, start, counter)
    }

    /// The index of a point nearest to each query, as [`nearest`](Self::nearest) answers
    /// it; see [`nearest_all_with`](Self::nearest_all_with).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] (name `"queries"`) naming the first query with a NaN or
    /// infinite coordinate.
    ///
    /// # Complexity
    /// O(m log m) time for m queries (their Hilbert sort) plus the walks, O(m) space.
    pub fn nearest_all(&self, queries: &[Point2]) -> Result<Vec<usize>> {
        self.nearest_all_with(queries, &mut NoCount)
    }

    /// [`nearest`](Self::nearest) for a batch of queries, sorted along a Hilbert curve over
    /// their bounding box so that consecutive walks read the same part of memory: each walk
    /// starts at the previous answer or at the query's cell entry, whichever is nearer to
    /// the query. The answers are those of [`nearest`](Self::nearest), in query order.
    ///
    /// # Errors
    /// As [`nearest_all`](Self::nearest_all).
    ///
    /// # Complexity
    /// As [`nearest_all`](Self::nearest_all).
    ///
    /// # Counts
    /// As [`nearest_with`](Self::nearest_with), plus one distance evaluation per query
    /// after the first to choose its start.
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::gen::{points, PointKind};
    /// use compgeo::geometry::PointSet;
    /// use compgeo::proximity::NearestSearch;
    ///
    /// let pts = points(PointKind::UniformSquare, 1000, 3)?;
    /// let queries = points(PointKind::UniformSquare, 500, 4)?;
    /// let set = PointSet::new(&pts)?;
    /// let search = NearestSearch::new(&set)?;
    /// let mut counts = Counts::default();
    /// let all = search.nearest_all_with(&queries, &mut counts)?;
    /// for (q, &i) in queries.iter().zip(&all) {
    ///     assert_eq!(search.nearest(*q)?, i);
    /// }
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn nearest_all_with<C: Counter>(
        &self,
        queries: &[Point2],
        counter: &mut C,
    ) -> Result<Vec<usize>> {
        self.graph.walk_all(queries, counter)
    }
}

impl DelaunayGraph {
    /// The Delaunay graph of `points` triangulated by `t` (edges naming a point out of range
    /// or a merged duplicate are ignored), its vertices renumbered along a Hilbert curve,
    /// and the grid of entry vertices.
    pub(crate) fn new(points: &[Point2], t: &Triangulation) -> DelaunayGraph {
        let n = points.len();
        // Vertex numbers along the curve, then the stars' positions.
        let mut local = vec![0u32; n];
        for &[dropped, _] in &t.duplicates {
            if let Some(l) = local.get_mut(dropped) {
                *l = NO_VERTEX;
            }
        }
        let input: Vec<u32> = curve_order(points)
            .into_iter()
            .filter(|&i| local[i as usize] != NO_VERTEX)
            .collect();
        for (v, &i) in input.iter().enumerate() {
            local[i as usize] = v as u32;
        }
        let vertex = |i: usize| local.get(i).copied().filter(|&v| v != NO_VERTEX);
        let edges: Vec<[usize; 2]> = delaunay_edges(t)
            .into_iter()
            .filter_map(|[a, b]| Some([vertex(a)? as usize, vertex(b)? as usize]))
            .collect();
        let (offsets, neighbours) = adjacency(input.len(), &edges);
        drop(edges);
        let row = |v: usize| &neighbours[offsets[v]..offsets[v + 1]];
        let mut position = Vec::with_capacity(input.len());
        let mut words = 0usize;
        for v in 0..input.len() {
            position.push(words as u32);
            words += star_words(row(v).len());
        }
        let mut stars = Vec::with_capacity(words);
        for (v, &i) in input.iter().enumerate() {
            let p = points[i as usize];
            let row = row(v);
            stars.extend([
                p.x.to_bits(),
                p.y.to_bits(),
                u64::from(i) | (row.len() as u64) << 32,
            ]);
            stars.extend(row.chunks(2).map(|pair| {
                let high = pair.get(1).map_or(0, |&w| u64::from(position[w]) << 32);
                u64::from(position[pair[0]]) | high
            }));
        }
        for l in local.iter_mut().filter(|l| **l != NO_VERTEX) {
            *l = position[*l as usize];
        }
        let mut graph = DelaunayGraph {
            stars,
            local,
            grid: EntryGrid::empty(),
        };
        graph.grid = EntryGrid::build(&graph, input.len(), BoundingBox::of(points));
        graph
    }

    /// The point of vertex `v`.
    #[inline]
    fn point(&self, v: usize) -> Point2 {
        Point2::new(
            f64::from_bits(self.stars[v]),
            f64::from_bits(self.stars[v + 1]),
        )
    }

    /// The input index of vertex `v`.
    #[inline]
    fn input(&self, v: usize) -> usize {
        self.stars[v + 2] as u32 as usize
    }

    /// The star of vertex `v`: its neighbours' positions.
    #[inline]
    fn star(&self, v: usize) -> Star<'_> {
        let degree = (self.stars[v + 2] >> 32) as usize;
        let start = v + STAR_HEADER;
        Star {
            links: &self.stars[start..start + degree.div_ceil(2)],
            degree,
        }
    }

    /// Every vertex, in star order.
    #[cfg(test)]
    fn vertices(&self) -> impl Iterator<Item = usize> + '_ {
        let mut v = 0;
        std::iter::from_fn(move || {
            let here = v;
            (here < self.stars.len()).then(|| {
                v += star_words(self.star(here).degree);
                here
            })
        })
    }

    /// [`NearestSearch::nearest_with`] on this graph.
    pub(crate) fn walk<C: Counter>(
        &self,
        query: Point2,
        start: Option<usize>,
        counter: &mut C,
    ) -> Result<usize> {
        if !query.is_finite() {
            return Err(Error::InvalidParameter {
                name: "query",
                reason: format!("({}, {}) is not a finite point", query.x, query.y),
            });
        }
        let v = match start {
            None => self.grid.entry_of(query),
            Some(s) => match self.local.get(s) {
                Some(&v) if v != NO_VERTEX => v as usize,
                _ => {
                    return Err(Error::InvalidParameter {
                        name: "start",
                        reason: format!("{s} is not a vertex of the triangulation"),
                    })
                }
            },
        };
        Ok(self.answer(query, v, counter))
    }

    /// [`NearestSearch::nearest_all_with`] on this graph.
    pub(crate) fn walk_all<C: Counter>(
        &self,
        queries: &[Point2],
        counter: &mut C,
    ) -> Result<Vec<usize>> {
        if let Some(i) = queries.iter().position(|q| !q.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "queries",
                reason: format!(
                    "query {i} ({}, {}) is not a finite point",
                    queries[i].x, queries[i].y
                ),
            });
        }
        let mut out = vec![0; queries.len()];
        // The curve order numbers queries with 32 bits; a larger batch is answered in order.
        let order: Vec<usize> = if u32::try_from(queries.len()).is_ok() {
            curve_order(queries)
                .into_iter()
                .map(|i| i as usize)
                .collect()
        } else {
            (0..queries.len()).collect()
        };
        let mut previous: Option<usize> = None;
        for i in order {
            let q = queries[i];
            let mut v = self.grid.entry_of(q);
            if let Some(p) = previous {
                if counter.cmp_dist(q, self.point(p), q, self.point(v)) == Ordering::Less {
                    v = p;
                }
            }
            let (nearest, answer) = self.descend_and_settle(q, v, counter);
            previous = Some(nearest);
            out[i] = answer;
        }
        Ok(out)
    }

    /// The input index answering `query` from vertex `v`.
    #[inline]
    fn answer<C: Counter>(&self, query: Point2, v: usize, counter: &mut C) -> usize {
        self.descend_and_settle(query, v, counter).1
    }

    /// The vertex the greedy walk from `v` ends at, and the input index of the answer (the
    /// smallest among the nearest sites).
    #[inline]
    fn descend_and_settle<C: Counter>(
        &self,
        query: Point2,
        v: usize,
        counter: &mut C,
    ) -> (usize, usize) {
        let (v, tied) = self.descend(query, v, counter);
        let answer = if tied {
            self.smallest_tied(query, v, counter)
        } else {
            self.input(v)
        };
        (v, answer)
    }

    /// The greedy walk from `v`: the vertex it ends at (a nearest one) and whether one of
    /// that vertex's neighbours is exactly as near to `query`.
    #[inline]
    fn descend<C: Counter>(&self, query: Point2, mut v: usize, counter: &mut C) -> (usize, bool) {
        loop {
            let star = self.star(v);
            let (mut best, mut best_point, mut tied) = (None, self.point(v), false);
            for k in 0..star.degree {
                let p = self.point(star.vertex(k));
                match counter.cmp_dist(query, p, query, best_point) {
                    Ordering::Less => (best, best_point) = (Some(k), p),
                    // Meaningful only while no neighbour is nearer, which is when it is used.
                    Ordering::Equal => tied = true,
                    Ordering::Greater => {}
                }
            }
            match best {
                None => return (v, tied),
                Some(k) => v = star.vertex(k),
            }
        }
    }

    /// The smallest input index among the vertices as near to `query` as the nearest
    /// vertex `v`: a search over tied neighbours, each vertex looked at once.
    #[cold]
    fn smallest_tied<C: Counter>(&self, query: Point2, v: usize, counter: &mut C) -> usize {
        let at = self.point(v);
        let mut seen = HashSet::from([v]);
        let mut tied = vec![v];
        let mut next = 0;
        while let Some(&u) = tied.get(next) {
            next += 1;
            let star = self.star(u);
            for k in 0..star.degree {
                let w = star.vertex(k);
                if seen.insert(w) && counter.cmp_dist(query, self.point(w), query, at).is_eq() {
                    tied.push(w);
                }
            }
        }
        tied.into_iter()
            .map(|u| self.input(u))
            .min()
            .unwrap_or(self.input(v))
    }
}

/// The neighbours of one vertex, as [`DelaunayGraph::star`] reads them.
struct Star<'a> {
    /// The neighbours' positions, two per word.
    links: &'a [u64],
    degree: usize,
}

impl Star<'_> {
    /// The `k`-th neighbour.
    #[inline]
    fn vertex(&self, k: usize) -> usize {
        (self.links[k >> 1] >> ((k & 1) * 32)) as u32 as usize
    }
}

/// The words of a star with `degree` neighbours, before padding.
fn star_words(degree: usize) -> usize {
    STAR_HEADER + degree.div_ceil(2)
}

impl EntryGrid {
    /// A placeholder: one cell entered at vertex 0.
    fn empty() -> EntryGrid {
        EntryGrid {
            half_min: Point2::new(0.0, 0.0),
            half_max: Point2::new(0.0, 0.0),
            scale_x: 0.0,
            scale_y: 0.0,
            cols: 1,
            rows: 1,
            entry: vec![0],
        }
    }

    /// The grid of `graph`'s sites (`vertices` of them in the box `bounds`): about
    /// n / [`CELL_SITES`] cells shaped like the bounding box, each entered at the vertex nearest to its centre, found by a walk from the
    /// previous cell's entry (the rows are visited in alternating directions, so consecutive
    /// cells are neighbours).
    fn build(graph: &DelaunayGraph, vertices: usize, bounds: Option<BoundingBox>) -> EntryGrid {
        let Some(bounds) = bounds else {
            return EntryGrid::empty();
        };
        let (min, max) = (bounds.min, bounds.max);
        let half_min = Point2::new(0.5 * min.x, 0.5 * min.y);
        let half_max = Point2::new(0.5 * max.x, 0.5 * max.y);
        let cells = (vertices / CELL_SITES).max(1);
        let (cols, rows) = grid_shape(cells, half_max.x - half_min.x, half_max.y - half_min.y);
        let mut grid = EntryGrid {
            half_min,
            half_max,
            scale_x: grid_scale(min.x, max.x, cols as f64),
            scale_y: grid_scale(min.y, max.y, rows as f64),
            cols,
            rows,
            entry: Vec::with_capacity(cols * rows),
        };
        let mut entry = vec![0u32; cols * rows];
        let mut v = 0;
        for row in 0..rows {
            for k in 0..cols {
                let col = if row % 2 == 0 { k } else { cols - 1 - k };
                v = graph.descend(grid.centre(col, row), v, &mut NoCount).0;
                entry[row * cols + col] = v as u32;
            }
        }
        grid.entry = entry;
        grid
    }

    /// The centre of cell `(col, row)`, kept inside the bounding box (a hint only: any
    /// finite point would do).
    fn centre(&self, col: usize, row: usize) -> Point2 {
        let along = |half_min: f64, half_max: f64, scale: f64, k: usize| {
            let offset = if scale > 0.0 {
                (k as f64 + 0.5) / scale
            } else {
                0.0
            };
            2.0 * (half_min + offset).min(half_max)
        };
        Point2::new(
            along(self.half_min.x, self.half_max.x, self.scale_x, col),
            along(self.half_min.y, self.half_max.y, self.scale_y, row),
        )
    }

    /// The cell holding `q` (clamped to the grid: a query outside the box gets the nearest
    /// border cell).
    #[inline]
    fn cell_of(&self, q: Point2) -> usize {
        // Finite halved differences times finite scales: no NaN, and `as` saturates a
        // negative or infinite product to 0 or `usize::MAX`.
        let x = ((0.5 * q.x - self.half_min.x) * self.scale_x) as usize;
        let y = ((0.5 * q.y - self.half_min.y) * self.scale_y) as usize;
        y.min(self.rows - 1) * self.cols + x.min(self.cols - 1)
    }

    /// The entry vertex of `q`'s cell.
    #[inline]
    fn entry_of(&self, q: Point2) -> usize {
        self.entry[self.cell_of(q)] as usize
    }
}

/// Columns and rows of a grid of about `cells` cells over a box of half widths `wx` and `wy`
/// (finite, not negative): square cells where the aspect ratio allows, one row or column
/// for a flat box.
fn grid_shape(cells: usize, wx: f64, wy: f64) -> (usize, usize) {
    match (wx > 0.0, wy > 0.0) {
        (false, false) => (1, 1),
        (true, false) => (cells, 1),
        (false, true) => (1, cells),
        (true, true) => {
            let c = cells as f64;
            // Both positive and finite: the ratio is not NaN (it may overflow or vanish).
            let aspect = (wx / wy).clamp(1.0 / c, c);
            let cols = ((c * aspect).sqrt().round() as usize).clamp(1, cells);
            (cols, (cells / cols).max(1))
        }
    }
}

/// The index of a point of `points` nearest to `query`: builds a [`NearestSearch`] and asks
/// it once.
///
/// # Errors
/// [`Error::TooFew`] for no points, [`Error::NonFinite`] for a bad point,
/// [`Error::InvalidParameter`] (name `"query"`) for a NaN or infinite query.
///
/// # Complexity
/// O(n log n) expected time (the triangulation), O(n) space.
///
/// ```
/// use compgeo::proximity::nearest;
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (10.0, 0.0), (5.0, 9.0)].map(Point2::from);
/// assert_eq!(nearest(&pts, Point2::new(6.0, 7.0))?, 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn nearest(points: &[Point2], query: Point2) -> Result<usize> {
    NearestSearch::new(&PointSet::new(points)?)?.nearest(query)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::{points, PointKind};
    use crate::geometry::cmp_dist;

    fn search_graph(pts: &[Point2]) -> DelaunayGraph {
        let set = PointSet::new(pts).unwrap();
        DelaunayGraph::new(pts, &incremental_with(&set, &mut NoCount).unwrap())
    }

    #[test]
    fn every_cell_entry_is_nearest_to_its_centre() {
        for kind in [
            PointKind::UniformSquare,
            PointKind::Clustered,
            PointKind::Grid,
        ] {
            let pts = points(kind, 300, 5).unwrap();
            let g = search_graph(&pts);
            let grid = &g.grid;
            assert_eq!(grid.entry.len(), grid.cols * grid.rows);
            assert!(grid.entry.len() <= pts.len() / CELL_SITES);
            for row in 0..grid.rows {
                for col in 0..grid.cols {
                    let c = grid.centre(col, row);
                    assert_eq!(grid.cell_of(c), row * grid.cols + col, "{kind} {col} {row}");
                    let e = g.point(grid.entry[row * grid.cols + col] as usize);
                    assert!(pts.iter().all(|&p| cmp_dist(c, p, c, e) != Ordering::Less));
                }
            }
        }
    }

    #[test]
    fn cells_clamp_far_queries_and_extreme_boxes() {
        let sub = 5e-324;
        let sets: [&[(f64, f64)]; 5] = [
            &[
                (-f64::MAX, -f64::MAX),
                (f64::MAX, f64::MAX),
                (0.0, 0.0),
                (1.0, -1.0),
            ],
            &[
                (0.0, 0.0),
                (sub, 0.0),
                (0.0, sub),
                (sub, sub),
                (2.0 * sub, sub),
            ],
            &[(0.0, 0.0), (1e300, 0.0), (2e300, 0.0), (-1e300, 0.0)],
            &[(0.0, 0.0), (sub, 1e300), (0.0, -1e300), (sub, 5.0)],
            &[(3.0, 3.0), (3.0, 3.0), (3.0, 3.0)],
        ];
        let far = [
            Point2::new(f64::MAX, -f64::MAX),
            Point2::new(-f64::MAX, 0.0),
            Point2::new(0.0, 0.0),
            Point2::new(sub, -sub),
            Point2::new(1e-300, 1e300),
        ];
        for set in sets {
            let pts: Vec<Point2> = set.iter().map(|&p| Point2::from(p)).collect();
            let g = search_graph(&pts);
            let grid = &g.grid;
            assert!(grid.cols >= 1 && grid.rows >= 1);
            assert!(grid.scale_x.is_finite() && grid.scale_y.is_finite());
            for row in 0..grid.rows {
                for col in 0..grid.cols {
                    assert!(grid.centre(col, row).is_finite());
                }
            }
            for &q in &far {
                assert!(grid.cell_of(q) < grid.entry.len());
                let k = g.walk(q, None, &mut NoCount).unwrap();
                assert!(pts
                    .iter()
                    .all(|&p| cmp_dist(q, p, q, pts[k]) != Ordering::Less));
            }
        }
    }

    #[test]
    fn grid_shapes_follow_the_box() {
        assert_eq!(grid_shape(100, 1.0, 1.0), (10, 10));
        assert_eq!(grid_shape(100, 4.0, 1.0), (20, 5));
        assert_eq!(grid_shape(100, 1.0, 0.0), (100, 1));
        assert_eq!(grid_shape(100, 0.0, 1.0), (1, 100));
        assert_eq!(grid_shape(100, 0.0, 0.0), (1, 1));
        assert_eq!(grid_shape(100, f64::MAX, 5e-324), (100, 1));
        assert_eq!(grid_shape(100, 5e-324, f64::MAX), (1, 100));
        assert_eq!(grid_shape(1, 3.0, 1.0), (1, 1));
    }

    #[test]
    fn sites_follow_the_curve_and_map_back() {
        let mut pts = points(PointKind::UniformDisk, 200, 1).unwrap();
        pts.extend_from_within(..20);
        let g = search_graph(&pts);
        let vertices: Vec<usize> = g.vertices().collect();
        assert_eq!(vertices.len(), 200);
        for &v in &vertices {
            let i = g.input(v);
            assert_eq!(g.local[i] as usize, v);
            assert_eq!(g.point(v), pts[i]);
            // Neighbours are vertices, and the graph is undirected.
            let star = g.star(v);
            assert!(star.degree >= 2);
            for k in 0..star.degree {
                let w = star.vertex(k);
                assert!(vertices.binary_search(&w).is_ok());
                let back = g.star(w);
                assert!((0..back.degree).any(|j| back.vertex(j) == v));
            }
        }
        assert!(g.local[200..].iter().all(|&v| v == NO_VERTEX));
        // The stars follow the curve: the first 200 input ids in curve order.
        let order: Vec<usize> = curve_order(&pts[..200])
            .into_iter()
            .map(|i| i as usize)
            .collect();
        assert_eq!(
            vertices.iter().map(|&v| g.input(v)).collect::<Vec<_>>(),
            order
        );
    }
}
