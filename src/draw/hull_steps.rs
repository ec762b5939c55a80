//! Step pages of the hull algorithms the course traces (Jarvis, Graham, the monotone chain,
//! Quickhull) and of Lawson's flips: one picture per frame of the algorithm's own trace.
//!
//! Every picture of a page shares one frame (the points' bounding box), so stepping through
//! the page moves nothing but what changed. The points are numbered by input index (as the
//! traces name them) up to [`LABEL_LIMIT`](super::LABEL_LIMIT) points. Colours keep their
//! roles: the structure built so far is the result (blue), the point or edge the step is
//! about is highlighted (vermillion), the test in progress is a construction line (orange,
//! dashed).

use super::steps::{StepFrame, StepPage};
use super::svg::{Layer, Picture, Role};
use super::{bounds_of, check_indices, indexed_points, points_legend};
use crate::delaunay::LawsonStep;
use crate::geometry::{BoundingBox, Point2, PointSet};
use crate::hull::{Chain, ChainStep, GrahamStep, JarvisStep, QuickhullStep};
use crate::trace::Frame;
use crate::Result;

/// A picture of `points` with `draw` on top of them: the layers `draw` adds go under the
/// points and their labels.
fn picture_of(points: &[Point2], title: &str, draw: impl FnOnce(&mut Picture)) -> Picture {
    picture_in(bounds_of(points), points, title, draw)
}

/// [`picture_of`] with the world box `bounds` (which holds the points).
pub(super) fn picture_in(
    bounds: BoundingBox,
    points: &[Point2],
    title: &str,
    draw: impl FnOnce(&mut Picture),
) -> Picture {
    let mut picture = Picture::new(title, bounds, points.len());
    draw(&mut picture);
    indexed_points(&mut picture, points, "point index");
    picture
}

/// Draws the points at `indices` as an open chain (the result so far).
fn chain(picture: &mut Picture, points: &[Point2], name: &str, legend: &str, indices: &[usize]) {
    picture.polylines(
        &Layer::new(name, Role::Result).legend(legend),
        [indices.iter().map(|&i| points[i])],
    );
}

/// Draws the closed polygon at `indices` (the finished hull).
fn polygon(picture: &mut Picture, points: &[Point2], indices: &[usize]) {
    picture.polygons(
        &Layer::new("hull", Role::Result).legend("convex hull"),
        [indices.iter().map(|&i| points[i])],
    );
}

/// Rings the points at `indices` (the point a step is about).
pub(super) fn mark(picture: &mut Picture, points: &[Point2], legend: &str, indices: &[usize]) {
    picture.rings(
        &Layer::new("current", Role::Highlight).legend(legend),
        indices.iter().map(|&i| points[i]),
    );
}

/// Draws segments between the points of each index pair, in `role`.
fn segments(
    picture: &mut Picture,
    points: &[Point2],
    name: &str,
    legend: &str,
    role: Role,
    pairs: &[[usize; 2]],
) {
    picture.segments(
        &Layer::new(name, role).legend(legend),
        pairs.iter().map(|&[a, b]| [points[a], points[b]]),
    );
}

/// Every index a step names, to check them against the point set once.
pub(super) fn check<'a>(
    points: &PointSet<'_>,
    indices: impl IntoIterator<Item = &'a usize>,
) -> Result<()> {
    check_indices("trace", indices.into_iter().copied(), points.len())
}

/// `indices` as text, shortened after a dozen.
pub(super) fn list(indices: &[usize]) -> String {
    let shown: Vec<String> = indices.iter().take(12).map(usize::to_string).collect();
    let more = if indices.len() > 12 { ", …" } else { "" };
    format!("[{}{more}]", shown.join(", "))
}

/// The step page of Jarvis's march from its trace ([`jarvis_trace`](crate::hull::jarvis_trace)).
///
/// # Errors
/// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if a frame names a point
/// outside `points`, [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
/// [`STEP_PAGE_MAX_FRAMES`](crate::limits::STEP_PAGE_MAX_FRAMES) frames.
///
/// # Complexity
/// O(f·(n + h)) time and output for f frames, n points and hulls of up to h vertices.
///
/// ```
/// use compgeo::draw::jarvis_steps;
/// use compgeo::geometry::{Point2, PointSet};
/// use compgeo::hull::{jarvis_trace, HullOptions};
///
/// let pts = [(0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 2.0)].map(Point2::from);
/// let trace = jarvis_trace(&pts, HullOptions::default())?;
/// let page = jarvis_steps(&PointSet::new(&pts)?, &trace)?;
/// assert_eq!(page.frames().len(), trace.len());
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn jarvis_steps(points: &PointSet<'_>, trace: &[Frame<JarvisStep>]) -> Result<StepPage> {
    let pts: &[Point2] = points;
    let title = format!("Jarvis's march on {}", points_legend(pts.len()));
    let mut page = StepPage::new(&title).about(
        "Gift wrapping [RD, §2.2]: from the lexicographically smallest point, each step tests \
         one point against the best candidate so far; the candidate that leaves every point on \
         its left becomes the next hull vertex.",
    );
    for frame in trace {
        let (kind, caption, picture) = match &frame.step {
            JarvisStep::Start { vertex } => {
                check(points, [vertex])?;
                let picture = picture_of(pts, &title, |p| {
                    mark(p, pts, "first hull vertex", &[*vertex]);
                });
                (
                    "start",
                    format!("Start at point {vertex}, the lexicographically smallest."),
                    picture,
                )
            }
            JarvisStep::Candidate {
                current,
                point,
                best,
                hull,
            } => {
                check(points, hull.iter().chain([current, point, best]))?;
                let picture = picture_of(pts, &title, |p| {
                    chain(p, pts, "hull-so-far", "hull so far", hull);
                    segments(
                        p,
                        pts,
                        "test",
                        "tested",
                        Role::Construction,
                        &[[*current, *point]],
                    );
                    segments(
                        p,
                        pts,
                        "best",
                        "best so far",
                        Role::Highlight,
                        &[[*current, *best]],
                    );
                });
                (
                    "candidate",
                    format!(
                        "From {current}: test point {point}; the best candidate is now {best}."
                    ),
                    picture,
                )
            }
            JarvisStep::Wrap { vertex, hull } => {
                check(points, hull.iter().chain([vertex]))?;
                let picture = picture_of(pts, &title, |p| {
                    chain(p, pts, "hull-so-far", "hull so far", hull);
                    mark(p, pts, "new hull vertex", &[*vertex]);
                });
                (
                    "wrap",
                    format!("Point {vertex} is the next hull vertex."),
                    picture,
                )
            }
            JarvisStep::Done { hull } => done(points, &title, hull)?,
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The last frame of every hull page: the hull as a polygon.
fn done(
    points: &PointSet<'_>,
    title: &str,
    hull: &[usize],
) -> Result<(&'static str, String, Picture)> {
    check(points, hull)?;
    let pts: &[Point2] = points;
    let picture = picture_of(pts, title, |p| polygon(p, pts, hull));
    Ok((
        "done",
        format!("The hull: {} vertices {}.", hull.len(), list(hull)),
        picture,
    ))
}

/// The step page of Graham's scan from its trace ([`graham_trace`](crate::hull::graham_trace)).
///
/// # Errors
/// As [`jarvis_steps`].
///
/// # Complexity
/// O(f·(n + h)) time and output for f frames, n points and stacks of up to h points.
pub fn graham_steps(points: &PointSet<'_>, trace: &[Frame<GrahamStep>]) -> Result<StepPage> {
    let pts: &[Point2] = points;
    let title = format!("Graham's scan on {}", points_legend(pts.len()));
    let mut page = StepPage::new(&title).about(
        "Graham's scan [RD, §2.2]: the points sorted by angle around the lexicographically smallest point, then a \
         stack that keeps only left turns; a point that makes a right turn pops the top.",
    );
    for frame in trace {
        let (kind, caption, picture) = match &frame.step {
            GrahamStep::Sorted { order } => {
                check(points, order)?;
                let picture = picture_of(pts, &title, |p| {
                    if let Some((&pivot, rest)) = order.split_first() {
                        let rays: Vec<[usize; 2]> = rest.iter().map(|&i| [pivot, i]).collect();
                        segments(p, pts, "order", "angular order", Role::Construction, &rays);
                        mark(p, pts, "pivot", &[pivot]);
                    }
                });
                (
                    "sorted",
                    format!("Sorted by angle around the pivot: {}.", list(order)),
                    picture,
                )
            }
            GrahamStep::Push { point, stack } => {
                check(points, stack.iter().chain([point]))?;
                let picture = picture_of(pts, &title, |p| {
                    chain(p, pts, "stack", "stack", stack);
                    mark(p, pts, "pushed", &[*point]);
                });
                (
                    "push",
                    format!("Push {point}: the stack is {}.", list(stack)),
                    picture,
                )
            }
            GrahamStep::Pop { point, stack } => {
                check(points, stack.iter().chain([point]))?;
                let picture = picture_of(pts, &title, |p| {
                    chain(p, pts, "stack", "stack", stack);
                    if let Some(&top) = stack.last() {
                        segments(
                            p,
                            pts,
                            "popped-edge",
                            "popped: no left turn",
                            Role::Construction,
                            &[[top, *point]],
                        );
                    }
                    mark(p, pts, "popped", &[*point]);
                });
                (
                    "pop",
                    format!("Pop {point}: it does not make a left turn."),
                    picture,
                )
            }
            GrahamStep::Done { hull } => done(points, &title, hull)?,
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The step page of the monotone chain from its trace
/// ([`monotone_chain_trace`](crate::hull::monotone_chain_trace)). Each picture shows both
/// chains as far as the trace has built them.
///
/// # Errors
/// As [`jarvis_steps`].
///
/// # Complexity
/// O(f·(n + h)) time and output for f frames, n points and chains of up to h points.
pub fn monotone_chain_steps(points: &PointSet<'_>, trace: &[Frame<ChainStep>]) -> Result<StepPage> {
    let pts: &[Point2] = points;
    let title = format!("The monotone chain on {}", points_legend(pts.len()));
    let mut page = StepPage::new(&title).about(
        "Andrew's monotone chain [RD, §2.2]: the points sorted lexicographically, the lower \
         chain from left to right and the upper chain back, each a stack of left turns.",
    );
    let (mut lower, mut upper): (Vec<usize>, Vec<usize>) = (Vec::new(), Vec::new());
    for frame in trace {
        let (kind, caption, picture) = match &frame.step {
            ChainStep::Sorted { order } => {
                check(points, order)?;
                let picture = picture_of(pts, &title, |p| {
                    p.polylines(
                        &Layer::new("order", Role::Construction).legend("lexicographic order"),
                        [order.iter().map(|&i| pts[i])],
                    );
                });
                (
                    "sorted",
                    format!("Sorted lexicographically: {}.", list(order)),
                    picture,
                )
            }
            ChainStep::Split { lower: l, upper: u } => {
                check(points, l.iter().chain(u))?;
                let picture = picture_of(pts, &title, |p| {
                    p.rings(
                        &Layer::new("lower-candidates", Role::Result).legend("below the line"),
                        l.iter().map(|&i| pts[i]),
                    );
                    p.rings(
                        &Layer::new("upper-candidates", Role::Alternative).legend("above the line"),
                        u.iter().map(|&i| pts[i]),
                    );
                });
                (
                    "split",
                    format!(
                        "{} points for the lower chain, {} for the upper.",
                        l.len(),
                        u.len()
                    ),
                    picture,
                )
            }
            ChainStep::Push {
                chain: which,
                point,
                stack,
            }
            | ChainStep::Pop {
                chain: which,
                point,
                stack,
            } => {
                check(points, stack.iter().chain([point]))?;
                match which {
                    Chain::Lower => lower.clone_from(stack),
                    Chain::Upper => upper.clone_from(stack),
                }
                let pushed = matches!(frame.step, ChainStep::Push { .. });
                let name = match which {
                    Chain::Lower => "lower",
                    Chain::Upper => "upper",
                };
                let picture = picture_of(pts, &title, |p| {
                    chain(p, pts, "lower", "lower chain", &lower);
                    p.polylines(
                        &Layer::new("upper", Role::Alternative).legend("upper chain"),
                        [upper.iter().map(|&i| pts[i])],
                    );
                    mark(p, pts, if pushed { "pushed" } else { "popped" }, &[*point]);
                });
                let caption = if pushed {
                    format!("Push {point} on the {name} chain.")
                } else {
                    format!("Pop {point} from the {name} chain: no left turn.")
                };
                (if pushed { "push" } else { "pop" }, caption, picture)
            }
            ChainStep::Done { hull } => done(points, &title, hull)?,
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The step page of Quickhull from its trace
/// ([`quickhull_trace`](crate::hull::quickhull_trace)). The hull edges found so far stay
/// drawn: each split replaces its edge by two.
///
/// # Errors
/// As [`jarvis_steps`].
///
/// # Complexity
/// O(f·(n + h)) time and output for f frames, n points and h hull vertices.
pub fn quickhull_steps(points: &PointSet<'_>, trace: &[Frame<QuickhullStep>]) -> Result<StepPage> {
    let pts: &[Point2] = points;
    let title = format!("Quickhull on {}", points_legend(pts.len()));
    let mut page = StepPage::new(&title).about(
        "Quickhull [RD, §2.2]: split by the line through the extreme points, then, on each \
         side, take the point farthest from the edge, drop the points inside the triangle and \
         recurse on the two new edges.",
    );
    // The edges of the current polygon: a split replaces its edge by two.
    let mut edges: Vec<[usize; 2]> = Vec::new();
    for frame in trace {
        let (kind, caption, picture) = match &frame.step {
            QuickhullStep::Ends { a, b, below, above } => {
                check(points, below.iter().chain(above).chain([a, b]))?;
                edges = vec![[*a, *b], [*b, *a]];
                let picture = picture_of(pts, &title, |p| {
                    segments(p, pts, "edges", "edges so far", Role::Result, &[[*a, *b]]);
                    p.rings(
                        &Layer::new("below", Role::Construction).legend("below the line"),
                        below.iter().map(|&i| pts[i]),
                    );
                    mark(p, pts, "extreme points", &[*a, *b]);
                });
                (
                    "ends",
                    format!(
                        "Split at {a} and {b}: {} points below the line, {} above.",
                        below.len(),
                        above.len()
                    ),
                    picture,
                )
            }
            QuickhullStep::Split {
                edge,
                points: considered,
                farthest,
                first,
                second,
            } => {
                check(
                    points,
                    considered
                        .iter()
                        .chain(first)
                        .chain(second)
                        .chain(edge)
                        .chain([farthest]),
                )?;
                if let Some(k) = edges.iter().position(|e| e == edge) {
                    edges.splice(k..=k, [[edge[0], *farthest], [*farthest, edge[1]]]);
                }
                let picture = picture_of(pts, &title, |p| {
                    segments(p, pts, "edges", "edges so far", Role::Result, &edges);
                    p.rings(
                        &Layer::new("considered", Role::Construction).legend("points of the edge"),
                        considered.iter().map(|&i| pts[i]),
                    );
                    mark(p, pts, "farthest point", &[*farthest]);
                });
                (
                    "split",
                    format!(
                        "Edge {}–{}: the farthest of its {} points is {farthest}; {} and {} \
                         points go on.",
                        edge[0],
                        edge[1],
                        considered.len(),
                        first.len(),
                        second.len()
                    ),
                    picture,
                )
            }
            QuickhullStep::Done { hull } => done(points, &title, hull)?,
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}

/// The step page of Lawson's flips from their trace
/// ([`lawson_trace`](crate::delaunay::lawson_trace)): the sweep's triangulation, then one
/// picture per flip with the removed edge dashed and the added one highlighted.
///
/// # Errors
/// As [`jarvis_steps`].
///
/// # Complexity
/// O(f·(n + t)) time and output for f frames, n points and t triangles.
pub fn lawson_steps(points: &PointSet<'_>, trace: &[Frame<LawsonStep>]) -> Result<StepPage> {
    let pts: &[Point2] = points;
    let title = format!("Lawson's flips on {}", points_legend(pts.len()));
    let mut page = StepPage::new(&title).about(
        "Lawson's algorithm [RD, §2.4]: any triangulation (here a sweep's), then flip every \
         edge whose opposite vertex lies inside the circumcircle of its triangle until none \
         does; the result is the Delaunay triangulation.",
    );
    let triangles_of = |triangles: &[usize]| -> Vec<[Point2; 3]> {
        triangles
            .chunks_exact(3)
            .map(|t| [pts[t[0]], pts[t[1]], pts[t[2]]])
            .collect()
    };
    let mut flips = 0;
    for frame in trace {
        let (kind, caption, picture) = match &frame.step {
            LawsonStep::Swept { triangles } => {
                check(points, triangles)?;
                let picture = picture_of(pts, &title, |p| {
                    p.polygons(
                        &Layer::new("triangles", Role::Triangulation).legend("triangles"),
                        triangles_of(triangles),
                    );
                });
                (
                    "swept",
                    format!(
                        "A sweep triangulates the points: {} triangles.",
                        triangles.len() / 3
                    ),
                    picture,
                )
            }
            LawsonStep::Flip {
                removed,
                added,
                triangles,
            } => {
                check(points, triangles.iter().chain(removed).chain(added))?;
                flips += 1;
                let picture = picture_of(pts, &title, |p| {
                    p.polygons(
                        &Layer::new("triangles", Role::Triangulation).legend("triangles"),
                        triangles_of(triangles),
                    );
                    segments(
                        p,
                        pts,
                        "removed",
                        "flipped away",
                        Role::Construction,
                        &[*removed],
                    );
                    segments(p, pts, "added", "new edge", Role::Highlight, &[*added]);
                });
                (
                    "flip",
                    format!(
                        "Flip {flips}: edge {}–{} is not locally Delaunay; it becomes {}–{}.",
                        removed[0], removed[1], added[0], added[1]
                    ),
                    picture,
                )
            }
            LawsonStep::Done { triangulation } => {
                check(points, &triangulation.triangles)?;
                let picture = picture_of(pts, &title, |p| {
                    p.polygons(
                        &Layer::new("triangles", Role::Result).legend("Delaunay triangles"),
                        triangles_of(&triangulation.triangles),
                    );
                });
                (
                    "done",
                    format!(
                        "Delaunay after {flips} flips: {} triangles.",
                        triangulation.triangles.len() / 3
                    ),
                    picture,
                )
            }
        };
        page.push(StepFrame::new(kind, caption, picture, frame.counts))?;
    }
    Ok(page)
}
