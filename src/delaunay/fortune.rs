//! Fortune's sweep: the Voronoi diagram first, as a sweep line with a beach line of
//! parabolic arcs, and the Delaunay triangulation as its dual (one triangle per Voronoi
//! vertex event).

use super::beach_line::{BeachLine, NIL};
use super::event_queue::{Buckets, Event, EventQueue, Front};
use super::{Triangulation, EMPTY};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::construct::circumcentre;
use crate::geometry::lex_sort::{sorted_items_with, yx_key};
use crate::geometry::sweep_predicates::{
    breakpoint_side, circle_top_floor, cmp_circle_site, cmp_circles, normalize_scale, scaled_box,
    CircleKey, IntegerCircle, TopEstimate,
};
use crate::geometry::{BoxPredicates, ConstructedPoint, Orientation, Point2, PointSet};
use crate::trace::{record, Frame, NoObserver, Observer, TraceSize};
use crate::util::{range_of_most, sorted_sample};
use std::cell::Cell;
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "delaunay",
    name: "fortune",
    function: "delaunay::fortune",
    file: "src/delaunay/fortune.rs",
    summary: "Fortune's sweep with a beach line, the Voronoi diagram first",
    time: "O(n log n) expected",
    space: "O(n)",
    operation: Some(Operation::Comparisons),
    counts: "the sort, the event queue and the breakpoint tests; no in-circle test",
    source: "[RD, §2.4]",
    claims: &[
        on("uniform-square", Bound::NLogN, Operation::Comparisons),
        on("parabola", Bound::NLogN, Operation::Comparisons),
    ],
};

/// A step of Fortune's sweep, as [`fortune_trace`] records it: one per event the sweep
/// processes. Sites are indices into the input (a duplicate goes by the index kept); the
/// state is the one right after the event.
///
/// - `sweep` is the height of the sweep line `y = sweep` (it moves upwards);
/// - `beach` lists the sites of the beach line's arcs from left to right (a site can own
///   several arcs; a site on the sweep line owns a vertical spike);
/// - `triangles` holds the Delaunay triangles found so far, three vertices each,
///   counter-clockwise: those of [`fortune`]'s result, in its order (the k-th circle event
///   found triangle k).
#[derive(Debug, Clone, PartialEq)]
pub enum FortuneStep {
    /// The sweep line reached a site, whose arc entered the beach line (splitting the arc
    /// above it, or beside the others in the lowest row).
    Site {
        /// The site.
        site: usize,
        /// The sweep line's height: the site's `y`.
        sweep: f64,
        /// The beach line after the event.
        beach: Vec<usize>,
        /// The triangles found so far.
        triangles: Vec<usize>,
    },
    /// An arc shrank to a point and left the beach line: the sweep line left the circle
    /// through its site and its two neighbours' at the top, and the circle's centre is a
    /// Voronoi vertex, the dual of a new Delaunay triangle.
    Circle {
        /// The new triangle, counter-clockwise: the sites of the left arc, of the vanished
        /// arc and of the right arc.
        triangle: [usize; 3],
        /// The Voronoi vertex: the triangle's circumcentre, constructed within
        /// [`ConstructedPoint::RELATIVE_ERROR`].
        vertex: ConstructedPoint,
        /// The sweep line's height: the circle's top, rounded down to an `f64` (exactly:
        /// the largest `f64` not above it, so the heights of successive frames never
        /// decrease).
        sweep: f64,
        /// The beach line after the event.
        beach: Vec<usize>,
        /// The triangles found so far, this one last.
        triangles: Vec<usize>,
    },
    /// No event is left: the result of [`fortune`].
    Done {
        /// The triangulation, as [`fortune`] returns it.
        triangulation: Triangulation,
    },
}

impl TraceSize for FortuneStep {
    fn entries(&self) -> usize {
        match self {
            FortuneStep::Site {
                beach, triangles, ..
            } => 1 + beach.len() + triangles.len(),
            FortuneStep::Circle {
                beach, triangles, ..
            } => 4 + beach.len() + triangles.len(),
            FortuneStep::Done { triangulation } => {
                triangulation.triangles.len() + triangulation.hull.len()
            }
        }
    }
}

/// The Delaunay triangulation of `points` by Fortune's sweep. See [`fortune_with`].
///
/// ```
/// use compgeo::delaunay::{check_delaunay, fortune};
/// use compgeo::geometry::Point2;
///
/// let pts = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (1.0, 1.0)].map(Point2::from);
/// let t = fortune(&pts)?;
/// assert_eq!(t.triangle_count(), 4);
/// assert_eq!(t.hull, [0, 1, 2, 3]);
/// assert!(check_delaunay(&pts, &t).is_ok());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn fortune(points: &[Point2]) -> Result<Triangulation> {
    fortune_with(&PointSet::new(points)?, &mut NoCount)
}

/// The Delaunay triangulation of `points` by Fortune's sweep, recording its operations in
/// `counter`.
///
/// Idea: a horizontal line sweeps upwards over the sites. Every point below it that is
/// nearer to some passed site than to the line already has its final nearest site, so the
/// Voronoi diagram below the *beach line* (the upper envelope of the parabolas of points as
/// far from a site as from the line) is final. The beach line is a sequence of parabolic
/// arcs whose breakpoints trace the Voronoi edges. Two events change it: the line reaches a
/// site (the site's arc appears inside the arc below it, splitting it), or an arc shrinks to
/// a point between its neighbours (a *circle event*: the line touches the top of the
/// circle through the three sites, whose centre is a Voronoi vertex). Each circle event is
/// one Delaunay triangle, the dual of that vertex; at a vertex shared by k ≥ 4 cocircular
/// sites, k − 2 events happen at the same point and their triangles tile the sites' polygon.
///
/// Sites are sorted by (y, x); circle events wait in a queue with lazy deletion (an event
/// whose arc has changed neighbours since is skipped when it comes out); the arcs live in a
/// treap threaded by a linked list. A new site's arc is found by a descent that asks, at
/// each arc, whether the site is right of the arc's right breakpoint; first, though, a walk
/// along the list asks the same from a hint (the arc last inserted in the site's bucket of
/// x), and usually arrives in a few steps. The treap is only built (once) if the walks
/// overrun a budget of O(n) steps; until then the line is a bare list. Three consecutive arcs of sites a, b, c
/// get a circle event exactly when a, b, c turn counter-clockwise (their breakpoints
/// converge). The queue parks events far above the sweep line in buckets of equal height,
/// in O(1) each (false alarms among them are dropped when their bucket is reached), and
/// orders only the events near the line exactly: a sorted run (events tied in height, as
/// on integer grids, arrive in order) beside a binary heap.
///
/// Follows [RD, §2.4] "Algoritmos", 2. "Fortune" (the course refers to
/// de Berg et al., *Computational Geometry*, ch. 7), sweeping upwards instead of downwards.
///
/// Exactness. Every decision is exact for every finite input, 1e300 and subnormals in one set
/// included: the convergence test is [`orient2d`](crate::geometry::orient2d); the breakpoint
/// test and the event order, which involve square roots in coordinates, are reduced to signs
/// of polynomials (see `src/geometry/sweep_predicates.rs`) with floating-point filters and
/// exact integer fallbacks. The queue holds each circle event's top as a double with an
/// a-priori error bound, parks it by the bound's lower end, and compares two events exactly
/// only when their bounds overlap;
/// for small-integer sets (integer grids, whose events tie everywhere) those ties are
/// decided in plain floating point when every operation is provably exact. Events are
/// ordered by their point on the sweep line, y then x (a line turned by an infinitesimal
/// angle), and a circle event before a site at the same point, so degenerate input needs no
/// special case beyond two:
/// - the first row of sites (all with the lowest y) has vertical strips as arcs, and each
///   new site of that row is put to the right of the last one;
/// - a site exactly on a breakpoint splits the arc to the left, leaving an arc of zero width
///   whose circle event (through the new site) happens at once, giving the triangle of the
///   site and the two arcs' sites.
///
/// Duplicates are merged (reported in `duplicates`, the smallest index kept) and collinear
/// input gives no triangles (no three sites turn); the hull is then the sorted distinct
/// points.
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or infinite coordinate;
/// [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `points` has more than
/// [`MAX_FORTUNE_POINTS`](crate::limits::MAX_FORTUNE_POINTS) = 2^28 points (arcs and events
/// are indexed with `u32`).
///
/// # Complexity
///
/// With n = `points.len()`: time O(n log n) expected (the sort; at most 2n − 5 circle
/// events and fewer than 6n events queued, each parked in O(1) and ordered in O(log n) at
/// most once; O(n) empty buckets passed; the beach line starts as a bare list and its walks
/// from hints share a budget of O(n) steps; if they overrun it, the treap is built once in
/// O(n), and from then on a site costs a walk of O(1) steps, at most one O(log n) expected
/// descent, and O(log n) expected insertion, the expectation over the treap's priorities, which a fixed seed
/// draws independently of the input); auxiliary space O(n). The exact fallbacks cost more
/// than the filter but are O(1) each for a given input precision.
///
/// # Counts
///
/// Comparisons: the (y, x) sort and duplicate merge, every comparison of two events (the
/// near events' order, and the next site against the first circle event), and every
/// breakpoint test of the beach-line descent; not the queue's bucket arithmetic, which
/// decides no order. Orientation tests: one per triple of arcs checked for a circle
/// event. No in-circle tests: the Delaunay property comes from the sweep itself. Exact
/// fallbacks: every comparison of two events, or of an event and a site, that the
/// floating-point estimates of the events' tops leave open, and every event whose estimate
/// is wider than a bucket of the queue and is estimated again from the exact stage.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::delaunay::fortune_with;
/// use compgeo::geometry::{Point2, PointSet};
///
/// // A 3 x 3 grid: four cocircular sites around each Voronoi vertex.
/// let pts: Vec<Point2> = (0..9).map(|i| Point2::new((i % 3) as f64, (i / 3) as f64)).collect();
/// let set = PointSet::new(&pts)?;
/// let mut counts = Counts::default();
/// let t = fortune_with(&set, &mut counts)?;
/// assert_eq!(t.triangle_count(), 8);
/// assert!(counts.comparisons > 0 && counts.orientation_tests > 0);
/// assert_eq!(counts.incircle_tests, 0);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn fortune_with<C: Counter>(points: &PointSet<'_>, counter: &mut C) -> Result<Triangulation> {
    fortune_observed(points, counter, &mut NoObserver)
}

/// The frames of Fortune's sweep on `points`: the algorithm's own run, event by event.
///
/// The run is [`fortune_with`]'s, told about each event it processes: a
/// [`FortuneStep::Site`] per distinct site, a [`FortuneStep::Circle`] per circle event that
/// fires (one per triangle; the false alarms, events whose arc changed neighbours before
/// their turn, are skipped as the sweep skips them), and last [`FortuneStep::Done`] with the
/// triangulation [`fortune`] returns. Each frame carries the sweep line's height, the beach
/// line and the triangles so far, and the operations counted so far; the last frame's
/// counts are those of [`fortune_with`] with [`Counts`](crate::count::Counts). The frames' own extras (the beach
/// line's list, the Voronoi vertex, the sweep height of a circle event) are built for the
/// trace only and counted nowhere.
///
/// # Errors
///
/// As [`fortune_with`], and [`Error::LimitExceeded`](crate::Error::LimitExceeded) if the
/// frames would hold more than [`TRACE_MAX_ENTRIES`](crate::trace::TRACE_MAX_ENTRIES)
/// entries (about 200 points in general position).
///
/// # Complexity
///
/// That of [`fortune_with`] plus O(n) per frame for its copy of the state: O(n²) time and
/// space for n points (n site events and at most 2n − 5 circle events).
///
/// ```
/// use compgeo::delaunay::{fortune, fortune_trace, FortuneStep};
/// use compgeo::geometry::Point2;
///
/// // Two sites in the lowest row, then one above their breakpoint: three site events and
/// // one circle event.
/// let pts = [(0.0, 0.0), (4.0, 0.0), (2.0, 1.0)].map(Point2::from);
/// let frames = fortune_trace(&pts)?;
/// assert_eq!(frames.len(), 3 + 1 + 1);
/// let FortuneStep::Site { site, beach, .. } = &frames[2].step else { panic!() };
/// // Site 2 lands on the breakpoint of 0 and 1: it splits 0's arc, leaving a sliver.
/// assert_eq!((*site, beach.as_slice()), (2, &[0, 2, 0, 1][..]));
/// let FortuneStep::Circle { triangle, vertex, sweep, beach, .. } = &frames[3].step else {
///     panic!()
/// };
/// assert_eq!((*triangle, beach.as_slice()), ([2, 0, 1], &[0, 2, 1][..]));
/// // The circle through the three sites: centre (2, -1.5), radius 2.5, top at y = 1.
/// assert_eq!(vertex.finite(), Some(Point2::new(2.0, -1.5)));
/// assert_eq!(*sweep, 1.0);
/// assert_eq!(frames[4].step, FortuneStep::Done { triangulation: fortune(&pts)? });
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn fortune_trace(points: &[Point2]) -> Result<Vec<Frame<FortuneStep>>> {
    let points = PointSet::new(points)?;
    record(|counts, recorder| {
        let triangulation = fortune_observed(&points, counts, recorder)?;
        Ok(FortuneStep::Done { triangulation })
    })
}

/// Fortune's sweep, telling `obs` about each event it processes.
fn fortune_observed<C: Counter, O: Observer<FortuneStep, C>>(
    points: &PointSet<'_>,
    counter: &mut C,
    obs: &mut O,
) -> Result<Triangulation> {
    crate::limits::FORTUNE_POINTS.check(points.len() as u128)?;
    let (mut sites, index, duplicates) = sorted_by_y(points, counter);
    // Small-integer sets (integer grids: circle events tie everywhere) have a plain
    // floating-point stage for the ties; their coordinates are kept as they are.
    let mut predicates = BoxPredicates::for_set(points);
    let small_integer = predicates.is_small_integer();
    if !small_integer {
        // An exact power-of-two scaling changes no decision and keeps the filters away
        // from overflow and underflow (1e300 or 1e-300 everywhere); integers below 2^53 in
        // a box 2^12 wide are far from both.
        let shift = normalize_scale(&mut sites);
        // The box's corners are coordinates of sites, scaled alike (exactly): the box of
        // the scaled sites, for the orientation filter's bound.
        if let Some(bounds) = points.bounding_box() {
            predicates = BoxPredicates::over(scaled_box(bounds, shift));
        }
    }
    let ranges = site_ranges(&sites);
    let hint_buckets = hint_buckets(sites.len(), ranges);
    let mut sweep = Sweep {
        sites: &sites,
        input: points,
        index: &index,
        counter,
        obs,
        line: BeachLine::new(2 * sites.len(), false),
        walk_budget: WALK_BUDGET_START,
        queue: if small_integer {
            event_queue(sites.len(), ranges[1]).with_exact_ties()
        } else {
            event_queue(sites.len(), ranges[1])
        },
        hint_buckets,
        hints: vec![[NIL; 2]; hint_buckets.count()],
        events: Vec::new(),
        free_events: Vec::new(),
        exact_comparisons: Cell::new(0),
        predicates,
        small_integer,
        circles: Vec::new(),
        triangles: Vec::with_capacity(2 * sites.len()),
        edges: Vec::with_capacity(3 * sites.len()),
        halfedges: Vec::with_capacity(6 * sites.len()),
    };
    sweep.run();
    let triangles: Vec<usize> = sweep
        .triangles
        .iter()
        .flat_map(|t| t.map(|v| index[v as usize]))
        .collect();
    let halfedges: Vec<usize> = sweep
        .halfedges
        .iter()
        .map(|&h| if h == NIL { EMPTY } else { h as usize })
        .collect();
    Triangulation::from_linked(points, triangles, halfedges, duplicates)
}

/// What the queue's comparisons need only when the estimates leave them open: arc `arc`
/// (between the arcs of `sites[0]` and `sites[2]`) vanishes at the top of the circle
/// through `sites`.
#[derive(Debug, Clone)]
struct EventSites {
    sites: [u32; 3],
    arc: u32,
    /// The enclosures of the circle's top and centre ([`CircleKey`]), once a comparison
    /// the plain estimate left open has asked for them.
    key: Cell<Option<CircleKey>>,
    /// The top within a few units of its last place ([`TopEstimate::exact`]), once the
    /// enclosures have left a comparison open too. Nearly cocircular sites (points on a
    /// circle, two nearly parallel lines) give circles whose plain estimates and
    /// enclosures overlap while their tops still differ by far more than this: one big
    /// integer evaluation per event then decides what would otherwise be an exact
    /// comparison, in big integers, every time the event is compared.
    tight: Cell<Option<TopEstimate>>,
}

impl EventSites {
    /// An event of `sites` whose arc `arc` vanishes, nothing evaluated yet.
    fn new(sites: [u32; 3], arc: u32) -> EventSites {
        EventSites {
            sites,
            arc,
            key: Cell::new(None),
            tight: Cell::new(None),
        }
    }

    /// The event's enclosures, evaluated on the first call (`points` are its sites'
    /// coordinates).
    fn key(&self, [a, b, c]: [Point2; 3]) -> CircleKey {
        once(&self.key, || CircleKey::new(a, b, c))
    }

    /// The event's tight estimate, evaluated on the first call.
    fn tight(&self, [a, b, c]: [Point2; 3]) -> TopEstimate {
        once(&self.tight, || TopEstimate::exact(a, b, c))
    }
}

/// The value in `cell`, evaluated by `evaluate` and kept there on the first call.
fn once<T: Copy>(cell: &Cell<Option<T>>, evaluate: impl FnOnce() -> T) -> T {
    cell.get().unwrap_or_else(|| {
        let value = evaluate();
        cell.set(Some(value));
        value
    })
}

/// The sweep's state over the sites (sorted by y, then x, distinct).
struct Sweep<'a, C, O> {
    /// The distinct sites, sorted and scaled (see [`normalize_scale`]).
    sites: &'a [Point2],
    /// The input points, for the observer's frames.
    input: &'a [Point2],
    /// The input index of each site.
    index: &'a [usize],
    counter: &'a mut C,
    obs: &'a mut O,
    line: BeachLine,
    /// Where to start looking for a new site's arc: per bucket of x, the latest arc
    /// inserted there and its site (the arc's slot may have been removed or reused since).
    hints: Vec<[u32; 2]>,
    hint_buckets: Buckets,
    /// Steps the walks may still take before the line gets its treap (see
    /// [`Sweep::arc_above`]).
    walk_budget: usize,
    /// The circle events by event point.
    queue: EventQueue,
    /// The sites and arc of every circle event in the queue, by id, and slots free for
    /// reuse: an event's slot is freed when it leaves the queue, so the array stays as
    /// large as the queue has ever been, not one slot per event ever queued (about 3.5n
    /// for uniform sites, 1.5n of them false alarms).
    events: Vec<EventSites>,
    /// The free slots of `events` (and `circles`).
    free_events: Vec<u32>,
    /// Exact comparisons of two events the queue has made since they were last recorded
    /// as exact fallbacks (before each frame and at the end: the queue's order closures
    /// cannot reach the counter).
    exact_comparisons: Cell<u64>,
    /// The orientation filter's bound for the (scaled) sites' box, or plain floating point
    /// for a small-integer set.
    predicates: BoxPredicates,
    /// Whether the sites are a small-integer set (see [`IntegerCircle`]).
    small_integer: bool,
    /// For a small-integer set, the circle of every event in the queue, by id (the slots
    /// of `events`), relative to the first site; empty otherwise.
    circles: Vec<IntegerCircle>,
    /// Counter-clockwise triangles as site positions.
    triangles: Vec<[u32; 3]>,
    /// Per Voronoi edge (the tag of the breakpoints tracing it, see
    /// [`BeachLine::edge`]): the half-edge of the first triangle found at one of its ends,
    /// or [`NIL`] while there is none.
    edges: Vec<u32>,
    /// The opposite of each half-edge of `triangles` (half-edge `3t + k` runs from vertex
    /// `k` to vertex `k + 1` of triangle `t`), [`NIL`] on the hull.
    halfedges: Vec<u32>,
}

impl<C: Counter, O: Observer<FortuneStep, C>> Sweep<'_, C, O> {
    fn run(&mut self) {
        let mut next_site = 0;
        loop {
            let site = self.sites.get(next_site).copied();
            let front = self.settle(site.map_or(f64::INFINITY, |s| s.y));
            // The first circle event if it comes before the next site.
            let circle = match (front, site) {
                (None, None) => break,
                (None, Some(_)) => None,
                (Some(f), None) => Some(f),
                (Some(f), Some(site)) => {
                    self.counter.comparison();
                    // The sites' coordinates only when the estimate leaves it open.
                    let order = f.event.estimate().cmp_height(site.y).unwrap_or_else(|| {
                        self.counter.exact_fallback();
                        self.cmp_event_site(f.event.id, site)
                    });
                    (order != Ordering::Greater).then_some(f)
                }
            };
            match circle {
                Some(f) => {
                    self.take(f);
                    self.circle_event(f.event.id);
                    // No queued event has this id any more, and no arc refers to it: a
                    // valid event's arc is gone, and a false alarm's arc was given another
                    // event or none when it changed neighbours.
                    self.free_events.push(f.event.id);
                }
                None => {
                    self.site_event(next_site as u32);
                    next_site += 1;
                }
            }
        }
        self.record_exact_comparisons();
    }

    fn site_event(&mut self, s: u32) {
        let p = self.sites[s as usize];
        let hint = self.hint_buckets.of(p.x);
        let start = self.hint_near(hint);
        let found = self.arc_above(p, start);
        if found == NIL {
            self.line.insert_after(NIL, s, p);
        } else {
            let (above, above_point) = (self.line.site(found), self.line.point(found));
            self.line.set_event(found, NIL);
            let new = self.line.insert_after(found, s, p);
            // The new breakpoints trace one new Voronoi edge, between `above` and `s`
            // (both of them, in opposite directions, when the arc is split).
            self.hints[hint] = [new, s];
            let edge = self.new_edge(NIL);
            self.line.set_edge(new, edge);
            if above_point.y == p.y {
                // The first row: arcs are vertical strips, and the new one goes to the right.
                debug_assert_eq!(self.line.next(new), NIL, "a first-row arc not at the end");
                self.check_circle(found);
                self.check_circle(new);
            } else {
                let copy = self.line.insert_after(new, above, above_point);
                self.line.set_edge(copy, edge);
                self.check_circle(found);
                self.check_circle(copy);
            }
        }
        self.record_exact_comparisons();
        let (input, index, line, triangles) = (self.input, self.index, &self.line, &self.triangles);
        self.obs.step(self.counter, || {
            let site = index[s as usize];
            FortuneStep::Site {
                site,
                sweep: input[site].y,
                beach: beach_sites(line, index),
                triangles: input_triangles(triangles, index),
            }
        });
    }

    /// A live arc hinted at by hint bucket `b` or the nearest bucket to it with one (the
    /// hint's arc still live and still its site's); [`NIL`] if none is. With the treap the
    /// search reaches [`HINT_REACH`] buckets on either side; before it, it goes as far as it
    /// takes, one step of the walks' budget per pair of buckets (see
    /// [`arc_above`](Self::arc_above)).
    fn hint_near(&mut self, b: usize) -> u32 {
        let (line, hints) = (&self.line, &self.hints);
        let valid = |c: usize| {
            let [arc, site] = hints[c];
            arc != NIL && line.is_live(arc) && line.site(arc) == site
        };
        if valid(b) {
            return hints[b][0];
        }
        let tree = line.has_tree();
        let reach = if tree { HINT_REACH } else { hints.len() };
        for d in 1..=reach {
            if !tree {
                if self.walk_budget == 0 {
                    break;
                }
                self.walk_budget -= 1;
            }
            let (left, right) = (b.checked_sub(d), b + d);
            if left.is_none() && right >= hints.len() {
                break;
            }
            for c in [left, Some(right)].into_iter().flatten() {
                if c < hints.len() && valid(c) {
                    return hints[c][0];
                }
            }
        }
        NIL
    }

    /// The arc above site `p` (`p` is right of the breakpoints left of it and not right of
    /// the one on its right), [`NIL`] on an empty beach line: the arc the treap's descent
    /// finds ([`BeachLine::first_arc_where`]), found first by a walk along the line from
    /// `start` (a live arc, or [`NIL`] for none). The breakpoint tests are monotone along
    /// the line, so the walk ends at the same arc.
    ///
    /// The line starts without its treap: the walks (from the left end when there is no
    /// hint) share a budget of [`WALK_BUDGET_START`] steps plus [`WALK_BUDGET_PER_SITE`] per
    /// site, and when a walk would overrun it the treap is built, in O(arcs), for good.
    /// From then on a walk gives up after [`HINT_STEPS`] steps and leaves the site to the
    /// descent. So the walks cost O(n) steps in all before the treap and O(1) each after
    /// it, and a site costs O(log n) expected whatever the input.
    fn arc_above(&mut self, p: Point2, start: u32) -> u32 {
        if self.line.first() == NIL {
            return NIL;
        }
        if !self.line.has_tree() {
            self.walk_budget = self.walk_budget.saturating_add(WALK_BUDGET_PER_SITE);
        }
        let (line, counter) = (&self.line, &mut *self.counter);
        let side = |a: u32| {
            breakpoint_side(line.point(a), line.point(line.next(a)), p) == Ordering::Greater
        };
        let mut right_of = |a: u32| {
            counter.comparison();
            side(a)
        };
        let walked = if line.has_tree() {
            let mut steps = HINT_STEPS;
            walk_from(line, start, &mut steps, &mut right_of)
        } else {
            // Without the treap, from the left end if there is no hint.
            let start = if start == NIL { line.first() } else { start };
            walk_from(line, start, &mut self.walk_budget, &mut right_of)
        };
        // (Uncounted: debug builds count what release builds count.)
        debug_assert!(
            walked.is_none() || walked == Some(line.first_arc_where(side)),
            "the walk from a hint and the descent disagree"
        );
        if let Some(a) = walked {
            return a;
        }
        // The walks overran their budget (or the hint's short walk did not arrive): the
        // treap's descent, from now on.
        self.line.build_tree();
        let (line, counter) = (&self.line, &mut *self.counter);
        line.first_arc_where(|a| {
            counter.comparison();
            breakpoint_side(line.point(a), line.point(line.next(a)), p) == Ordering::Greater
        })
    }

    fn circle_event(&mut self, id: u32) {
        if !is_pending(&self.line, &self.events, id) {
            return; // a false alarm: the arc changed neighbours or is gone
        }
        let e = &self.events[id as usize];
        let (sites, arc) = (e.sites, e.arc);
        let t = self.triangles.len() as u32;
        self.triangles.push(sites);
        self.halfedges.extend([NIL; 3]);
        let (left, right) = (self.line.prev(arc), self.line.next(arc));
        // The breakpoints on both sides of the vanishing arc end here, at the Voronoi
        // vertex: their edges are the triangle's sides left -> arc (half-edge 3t) and
        // arc -> right (3t + 1). The new breakpoint between left and right starts here,
        // with the side right -> left (3t + 2).
        self.end_edge(self.line.edge(arc), 3 * t);
        self.end_edge(self.line.edge(right), 3 * t + 1);
        let edge = self.new_edge(3 * t + 2);
        self.line.set_edge(right, edge);
        self.line.remove(arc);
        self.line.set_event(left, NIL);
        self.line.set_event(right, NIL);
        self.check_circle(left);
        self.check_circle(right);
        self.record_exact_comparisons();
        let (input, index, line, triangles) = (self.input, self.index, &self.line, &self.triangles);
        self.obs.step(self.counter, || {
            let triangle = sites.map(|v| index[v as usize]);
            let [a, b, c] = triangle.map(|v| input[v]);
            FortuneStep::Circle {
                triangle,
                vertex: circumcentre(a, b, c),
                sweep: circle_top_floor([a, b, c]),
                beach: beach_sites(line, index),
                triangles: input_triangles(triangles, index),
            }
        });
    }

    /// Queues the circle event of arc `m` if its neighbours' breakpoints converge.
    fn check_circle(&mut self, m: u32) {
        let (l, r) = (self.line.prev(m), self.line.next(m));
        if l == NIL || r == NIL {
            return;
        }
        let sites = [self.line.site(l), self.line.site(m), self.line.site(r)];
        if sites[0] == sites[2] {
            return; // both sides of one parabola: the breakpoints diverge
        }
        let [a, b, c] = [l, m, r].map(|x| self.line.point(x));
        if self.predicates.orient2d_with(a, b, c, &mut *self.counter)
            != Orientation::CounterClockwise
        {
            return;
        }
        let event = EventSites::new(sites, m);
        // On a small-integer set the circle's integers give the estimate too.
        let circle = self
            .small_integer
            .then(|| IntegerCircle::new([a, b, c], self.sites[0]));
        let id = match self.free_events.pop() {
            Some(id) => {
                self.events[id as usize] = event;
                if let Some(circle) = circle {
                    self.circles[id as usize] = circle;
                }
                id
            }
            None => {
                self.events.push(event);
                self.circles.extend(circle);
                (self.events.len() - 1) as u32
            }
        };
        self.line.set_event(m, id);
        let mut estimate = circle
            .and_then(|circle| circle.estimate(self.sites[0]))
            .unwrap_or_else(|| TopEstimate::new(a, b, c));
        if self.queue.is_wide(estimate.err) {
            // A loose estimate (a huge circle through a far site) would be compared
            // exactly with every event it overlaps: one exact evaluation instead.
            self.counter.exact_fallback();
            estimate = self.events[id as usize].tight([a, b, c]);
        }
        let TopEstimate { top, err } = estimate;
        self.push(Event { top, err, id });
    }

    /// The exact order of event `id` and `site` (the estimate left it open).
    fn cmp_event_site(&self, id: u32, site: Point2) -> Ordering {
        let event = &self.events[id as usize];
        let t = self.points(event.sites);
        let key = event.key(t);
        // A circle through a point p has its top at p.y or above, at p.y only if p is the
        // top (the centre's x is p.x): a site of the event at the height of `site` either
        // puts the top above it or may tie with it, which no estimate decides.
        let mut may_tie = false;
        for p in t.iter().filter(|p| p.y == site.y) {
            if key.centre_x_is_not(p.x) {
                return Ordering::Greater;
            }
            may_tie = true;
        }
        (!may_tie)
            .then(|| event.tight(t).cmp_height(site.y))
            .flatten()
            .unwrap_or_else(|| cmp_circle_site(&key, t, site))
    }

    /// A new Voronoi edge, with the half-edge found at its start (or [`NIL`]).
    fn new_edge(&mut self, halfedge: u32) -> u32 {
        self.edges.push(halfedge);
        (self.edges.len() - 1) as u32
    }

    /// Voronoi edge `edge` ends in the triangle side `halfedge`: the two are twins if a
    /// triangle was found at its other end.
    fn end_edge(&mut self, edge: u32, halfedge: u32) {
        let other = self.edges[edge as usize];
        if other == NIL {
            self.edges[edge as usize] = halfedge;
        } else {
            self.halfedges[other as usize] = halfedge;
            self.halfedges[halfedge as usize] = other;
        }
    }

    #[inline]
    fn points(&self, t: [u32; 3]) -> [Point2; 3] {
        t.map(|v| self.sites[v as usize])
    }

    #[inline]
    fn push(&mut self, e: Event) {
        let (sites, events, circles, exact) = (
            self.sites,
            &self.events,
            &self.circles,
            &self.exact_comparisons,
        );
        self.queue.push(
            e,
            |x, y| before(sites, events, circles, exact, x, y),
            &mut *self.counter,
        );
    }

    /// The queue's first event, made the first of all or, if not, one after the site at
    /// height `horizon` with every other event after it too (see [`EventQueue::settle`]);
    /// the false alarms met on the way are dropped and their slots freed.
    #[inline]
    fn settle(&mut self, horizon: f64) -> Option<Front> {
        let (sites, events, circles, line, exact) = (
            self.sites,
            &self.events,
            &self.circles,
            &self.line,
            &self.exact_comparisons,
        );
        self.queue.settle(
            horizon,
            |id| is_pending(line, events, id),
            &mut self.free_events,
            |x, y| before(sites, events, circles, exact, x, y),
            &mut *self.counter,
        )
    }

    /// Removes the first event, as [`settle`](Self::settle) returned it.
    #[inline]
    fn take(&mut self, front: Front) {
        let (sites, events, circles, exact) = (
            self.sites,
            &self.events,
            &self.circles,
            &self.exact_comparisons,
        );
        self.queue.take(
            front,
            |x, y| before(sites, events, circles, exact, x, y),
            &mut *self.counter,
        );
    }

    /// Records the exact comparisons of the queue's last call as exact fallbacks.
    #[inline]
    fn record_exact_comparisons(&mut self) {
        if C::DISCARDS {
            return;
        }
        for _ in 0..self.exact_comparisons.take() {
            self.counter.exact_fallback();
        }
    }
}

/// Whether event `id` is still the pending event of its arc (not a false alarm).
#[inline]
fn is_pending(line: &BeachLine, events: &[EventSites], id: u32) -> bool {
    let arc = events[id as usize].arc;
    line.is_live(arc) && line.event(arc) == id
}

/// The walk of [`Sweep::arc_above`]: from arc `a` along the line towards the arc whose
/// breakpoints enclose the site; `None` if `a` is [`NIL`] or the walk would take more than
/// `steps` steps (each step taken is subtracted from `steps`). `right_of(a)`: whether the
/// site is right of the breakpoint between `a` and the arc after it (true for a prefix of
/// the arcs).
fn walk_from(
    line: &BeachLine,
    mut a: u32,
    steps: &mut usize,
    right_of: &mut impl FnMut(u32) -> bool,
) -> Option<u32> {
    if a == NIL {
        return None;
    }
    if line.next(a) != NIL && right_of(a) {
        while *steps > 0 {
            *steps -= 1;
            a = line.next(a);
            if line.next(a) == NIL || !right_of(a) {
                return Some(a);
            }
        }
    } else {
        while *steps > 0 {
            *steps -= 1;
            let left = line.prev(a);
            if left == NIL || right_of(left) {
                return Some(a);
            }
            a = left;
        }
    }
    None
}

/// The walks' budget before the treap (see [`Sweep::arc_above`]): this many steps to
/// start with...
const WALK_BUDGET_START: usize = 4096;

/// ...and this many more per site.
const WALK_BUDGET_PER_SITE: usize = 16;

/// How many hint buckets on either side [`Sweep::hint_near`] tries when a site's own
/// bucket has no live hint.
const HINT_REACH: usize = 2;

/// The most steps a walk from a hint takes, once the line has its treap, before the
/// descent takes over.
const HINT_STEPS: usize = 8;

/// The ranges of x and y of most sites (see [`bucket_range`]): y from the sorted sites,
/// x from a sample of at most 256 of them (a sort of all the x's would cost a tenth of
/// the sweep at a thousand sites).
fn site_ranges(sites: &[Point2]) -> [(f64, f64); 2] {
    let xs = sorted_sample(sites, 256, |p| p.x);
    [
        bucket_range(xs.len(), |i| xs[i]),
        bucket_range(sites.len(), |i| sites[i].y),
    ]
}

/// The buckets of x for the hints, about one per arc of the beach line: over uniform
/// sites in a box `w` wide and `h` high the line has about `√(n w / h)` arcs, so
/// `2 √(n w / h)` buckets (between 1 and n) over the range `x` of most sites.
fn hint_buckets(n: usize, [x, y]: [(f64, f64); 2]) -> Buckets {
    let aspect = (x.1 - x.0) / (y.1 - y.0);
    let count = 2.0 * (n as f64 * aspect).sqrt();
    // NaN (a single point) or infinite (a single row) aspects: n buckets.
    let count = if count.is_finite() { count as usize } else { n };
    Buckets::new(x.0, x.1, count.clamp(1, n.max(1)))
}

/// An empty event queue for `n` sorted sites whose heights mostly lie in `y`: one bucket
/// per two sites (about 1.75 events each on uniform input, most of them near the sweep
/// line when their bucket is reached).
fn event_queue(n: usize, y: (f64, f64)) -> EventQueue {
    EventQueue::new(y.0, y.1, n / 2)
}

/// The range of equal buckets over `len` ascending values, `value(i)` the `i`-th: all of
/// them, unless the range from the value 1/64 of the way up to the one 1/64 of the way
/// down is less than half as wide ([`range_of_most`]); then that range. A few far values
/// (outliers) would otherwise stretch the buckets until the rest share one; values outside
/// the range map to the first or the last bucket, which keeps the map monotone.
fn bucket_range(len: usize, value: impl Fn(usize) -> f64) -> (f64, f64) {
    if len == 0 {
        return (0.0, 0.0);
    }
    let full = (value(0), value(len - 1));
    range_of_most(len, value, 64, full, 2.0).unwrap_or(full)
}

/// The input index of the site of every arc of `line`, from left to right.
fn beach_sites(line: &BeachLine, index: &[usize]) -> Vec<usize> {
    line.sites_in_order()
        .into_iter()
        .map(|v| index[v as usize])
        .collect()
}

/// The triangles as input indices, flat.
fn input_triangles(triangles: &[[u32; 3]], index: &[usize]) -> Vec<usize> {
    triangles
        .iter()
        .flat_map(|t| t.map(|v| index[v as usize]))
        .collect()
}

/// Whether event `x` comes strictly before event `y` (their circles' tops on the sweep
/// line); `circles` as `Sweep::circles` (empty unless the sites are a small-integer set).
#[inline]
fn before(
    sites: &[Point2],
    events: &[EventSites],
    circles: &[IntegerCircle],
    exact: &Cell<u64>,
    x: &Event,
    y: &Event,
) -> bool {
    // The sites' coordinates only when the estimates leave it open.
    match x.estimate().is_below(&y.estimate()) {
        Some(below) => below,
        None => {
            exact.set(exact.get() + 1);
            before_exact(sites, events, circles, x, y)
        }
    }
}

/// [`before`] when the estimates overlap: the exact comparison of the event points, in
/// plain floating point first for small-integer sites (their circles precomputed).
#[cold]
#[inline(never)]
fn before_exact(
    sites: &[Point2],
    events: &[EventSites],
    circles: &[IntegerCircle],
    x: &Event,
    y: &Event,
) -> bool {
    if !circles.is_empty() {
        if let Some(order) = circles[x.id as usize].cmp(&circles[y.id as usize]) {
            return order == Ordering::Less;
        }
    }
    let points = |e: &Event| events[e.id as usize].sites.map(|v| sites[v as usize]);
    let (t1, t2) = (points(x), points(y));
    let (e1, e2) = (&events[x.id as usize], &events[y.id as usize]);
    // The enclosures (no big integers), then the tight estimates, then the big integers;
    // each event evaluates each stage once.
    let (k1, k2) = (e1.key(t1), e2.key(t2));
    if k1.cmp_tops(&k2).is_none() {
        if let Some(below) = e1.tight(t1).is_below(&e2.tight(t2)) {
            return below;
        }
    }
    cmp_circles(&k1, t1, &k2, t2) == Ordering::Less
}

/// The points sorted by (y, x) without repeats, the input index of each (the smallest among
/// equal points), and the duplicates as `[dropped, kept]` sorted by `dropped`.
fn sorted_by_y<C: Counter>(
    points: &[Point2],
    counter: &mut C,
) -> (Vec<Point2>, Vec<usize>, Vec<[usize; 2]>) {
    // One comparison per comparison of two (key, index) pairs; a radix sort with NoCount
    // (see crate::geometry::lex_sort).
    let order = sorted_items_with(points, 0..points.len(), yx_key, counter);
    let mut sites: Vec<Point2> = Vec::with_capacity(order.len());
    let mut index = Vec::with_capacity(order.len());
    let mut duplicates = Vec::new();
    for (p, i) in order {
        if let Some(&last) = sites.last() {
            counter.comparison();
            // Finite coordinates: equal as floats exactly when equal in the (y, x) order.
            if last == p {
                duplicates.push([i, *index.last().expect("index follows sites")]);
                continue;
            }
        }
        sites.push(p);
        index.push(i);
    }
    duplicates.sort_unstable();
    (sites, index, duplicates)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bucket_range_leaves_out_a_few_far_values_only() {
        let even: Vec<f64> = (0..1000).map(|i| i as f64 / 1000.0).collect();
        // Spread values: the whole range.
        assert_eq!(bucket_range(even.len(), |i| even[i]), (0.0, 0.999));
        // Two far values at each end: the range of the rest, cut at 1/64 of the way.
        let mut far = even.clone();
        far[..2].copy_from_slice(&[-1e9, -1e6]);
        far[998..].copy_from_slice(&[1e6, 1e9]);
        let (low, high) = bucket_range(far.len(), |i| far[i]);
        assert_eq!((low, high), (far[1000 / 64], far[999 - 1000 / 64]));
        assert!(0.0 < low && high < 1.0);
        // Values spread to less than twice the width of most: still the whole range.
        let mut spread = even.clone();
        spread[0] = -0.5;
        spread[999] = 1.4;
        assert_eq!(bucket_range(spread.len(), |i| spread[i]), (-0.5, 1.4));
        assert_eq!(bucket_range(0, |_| unreachable!()), (0.0, 0.0));
    }

    #[test]
    fn hint_buckets_follow_the_box_shape() {
        let n = 10_000;
        let square = hint_buckets(n, [(0.0, 1.0), (0.0, 1.0)]);
        assert_eq!(square.count(), 200);
        // A box 1000 times higher than wide: √1000 times fewer buckets.
        let tall = hint_buckets(n, [(0.0, 1e-3), (0.0, 1.0)]);
        assert_eq!(tall.count(), 6);
        // One row: every site is an arc; one column or one site: one bucket.
        assert_eq!(hint_buckets(n, [(0.0, 1.0), (0.0, 0.0)]).count(), n);
        assert_eq!(hint_buckets(n, [(0.0, 0.0), (0.0, 1.0)]).count(), 1);
        assert_eq!(hint_buckets(1, [(0.0, 0.0), (0.0, 0.0)]).count(), 1);
        assert_eq!(hint_buckets(0, [(0.0, 0.0), (0.0, 0.0)]).count(), 1);
    }
}
