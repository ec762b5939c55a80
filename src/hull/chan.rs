//! Chan's output-sensitive hull: monotone-chain hulls of small groups, then Jarvis's march
//! over the groups with a binary search for each group's tangent.

use super::akl_toussaint::filter;
use super::collinear::finish;
use super::lex::{lex_merged_items, lex_min, lex_sorted_items, lex_sorted_items_by_comparisons};
use super::monotone_chain::chains;
use super::HullOptions;
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::Result;
use crate::geometry::{CountedPredicates, Orientation, Point2, PointSet};
use crate::util::partition_point;
use std::cmp::Ordering;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "hull",
    name: "chan",
    function: "hull::chan",
    file: "src/hull/chan.rs",
    summary: "hulls of groups, then wrapping with tangent searches",
    time: "O(n log h)",
    space: "O(n)",
    operation: Some(Operation::OrientationTests),
    counts: "",
    source: "[RD, §2.2]",
    claims: &[
        on("uniform-disk", Bound::NLogH, Operation::OrientationTests),
        on("cocircular", Bound::NLogH, Operation::OrientationTests),
    ],
};

/// The convex hull of `points` by Chan's algorithm. See [`chan_with`].
///
/// ```
/// use compgeo::geometry::Point2;
/// use compgeo::hull::{chan, HullOptions};
///
/// let pts = [(1.0, 1.0), (0.0, 0.0), (2.0, 0.0), (1.0, 0.5), (1.0, 0.0)].map(Point2::from);
/// assert_eq!(chan(&pts, HullOptions::default())?, [1, 2, 0]);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn chan(points: &[Point2], options: HullOptions) -> Result<Vec<usize>> {
    Ok(chan_with(&PointSet::new(points)?, options, &mut NoCount))
}

/// The convex hull of `points` by Chan's algorithm, recording its operations in `counter`.
///
/// Idea: first drop the points strictly inside the polygon of the extreme points (the
/// Akl–Toussaint filter over all points, O(n); it stops testing when the first 1024 points
/// nearly all survive, as in convex position). Then guess m = 2^(2^t) for t = 3, 4, 5
/// (256, 65 536, 2^32). Order the survivors by their octant about the centre of their
/// bounding box (a stable pass, so equal points keep their index order; a grouping only,
/// decided in floating point, as any grouping is correct), so that a group lies along one
/// part of the boundary and its hull is small. Split them into groups of m consecutive points
/// and hull each group: the Akl–Toussaint filter inside the
/// group, then the monotone chain on its survivors (O(m log m) per group). Then run Jarvis's
/// march from the lexicographically smallest point, but instead of scanning every point, ask
/// each group for its tangent from the current vertex: the vertex of the group's hull that
/// every point of the group is left of (the farthest of two on one ray), found by binary
/// search in O(log m). The best of the n/m tangents is the next hull vertex (O((n/m) log m)
/// per step). If the march has not closed after m steps, h > m: square m and start again,
/// this time on the group hulls' vertices only (the hull of all points is theirs), which
/// come in sorted runs. The round that succeeds has m < h², and the rounds' costs grow
/// geometrically in log m, so the total is O(n log h).
///
/// Two cuts keep the constant small. A march stops early once its tangent tests would
/// outnumber the vertices the next round sorts, so a failed march never costs more than the
/// next round; and when the next guess would make at most two groups, the candidates are
/// sorted as one group (two groups of at least s/2 cost as much as one) and the monotone
/// chain ends the run. Inputs of at most 256 points are a single group. And the first guess
/// is judged on its first four groups: if their hulls keep more than half of their points,
/// the run starts over with the next guess (Chan's bound holds for any constant first
/// guess, so for either; four groups are all this costs).
///
/// The binary search is exact: seen from the current vertex p (a strict hull vertex, so
/// outside every group's hull or equal to one of its vertices), the group's vertices ordered
/// "more clockwise, then farther" form a cyclic sequence with one minimum and one maximum;
/// every comparison is one [`orient2d`](crate::geometry::orient2d) (and a
/// [`cmp_dist`](crate::geometry::cmp_dist) when two vertices are on one ray from p, as on
/// grids). A group that holds p itself answers with p's successor on its hull.
///
/// Not in the course; T. M. Chan, "Optimal output-sensitive convex hull algorithms in two and
/// three dimensions" (1996). It combines [RD, §2.2] "Marcha de
/// Jarvis" (the wrapping, with the course's signed-area test) and "Scan de Graham - Variante"
/// (the group hulls).
///
/// Output convention and degenerate inputs: see the [module docs](super). `keep_collinear`
/// inserts the boundary points afterwards.
///
/// # Errors
///
/// [`Error::NonFinite`](crate::Error::NonFinite) naming the first point with a NaN or
/// infinite coordinate.
///
/// # Complexity
///
/// With n = `points.len()` and h the number of hull vertices: time O(n log h),
/// output-sensitive (O(n log n) when every point is a vertex, O(n) when h is bounded);
/// auxiliary space O(n) for the group hulls.
///
/// # Counts
///
/// The filter's comparisons and orientation tests (over all points, then in each group of
/// the first round), then per round with group size m: the monotone chain's comparisons (O(n log m), the merge of the runs in later
/// rounds) and orientation tests (at most 3n) on the groups, then per step of the march O(log m)
/// comparisons and at most 2⌈log₂ m⌉ + 3 orientation tests per group, and up to n/m more to
/// pick the best tangent. In all O(n log h) comparisons and orientation tests, plus a
/// distance evaluation for each tie between vertices on one ray, and n − 1 comparisons to
/// find the start.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::gen::{points, PointKind};
/// use compgeo::geometry::PointSet;
/// use compgeo::hull::{chan_with, jarvis_march_with, HullOptions};
///
/// let pts = points(PointKind::UniformDisk, 4096, 7)?;
/// let set = PointSet::new(&pts)?;
/// let (mut fast, mut slow) = (Counts::default(), Counts::default());
/// let hull = chan_with(&set, HullOptions::default(), &mut fast);
/// assert_eq!(hull, jarvis_march_with(&set, HullOptions::default(), &mut slow));
/// assert!(fast.orientation_tests < slow.orientation_tests);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn chan_with<C: Counter>(
    points: &PointSet,
    options: HullOptions,
    counter: &mut C,
) -> Vec<usize> {
    let points = points.points();
    let n = points.len();
    if n == 0 {
        return Vec::new();
    }
    let strict = strict_hull(points, counter);
    finish(points, 0..n, strict, options, counter)
}

/// The strictly convex hull of the finite, non-empty `points` by Chan's rounds (see
/// [`chan_with`]), counter-clockwise from the lexicographically smallest point.
fn strict_hull<C: Counter>(points: &[Point2], counter: &mut C) -> Vec<usize> {
    if points.len() <= 1 << FIRST_EXPONENT {
        return chains(&lex_sorted_items(points, 0..points.len(), counter), counter);
    }
    // The Akl–Toussaint filter over all points first: O(n), and it leaves the rounds only
    // the points outside the polygon of the extreme points. Survivors keep their order, so
    // of equal points the smallest index still comes first.
    let kept = by_octant(points, filter(points, true, counter));
    let survivors: Vec<Point2> = kept.iter().map(|&i| points[i]).collect();
    let hull = rounds(&survivors, counter);
    hull.into_iter().map(|i| kept[i]).collect()
}

/// `kept` in eight stable buckets by the octant about the centre of their bounding box.
fn by_octant(points: &[Point2], kept: Vec<usize>) -> Vec<usize> {
    let half = |i: usize| (0.5 * points[i].x, 0.5 * points[i].y);
    let (mut lo, mut hi) = ((f64::MAX, f64::MAX), (f64::MIN, f64::MIN));
    for &i in &kept {
        let (x, y) = half(i);
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    }
    let (cx, cy) = (0.5 * (lo.0 + hi.0), 0.5 * (lo.1 + hi.1));
    let octant = |i: usize| {
        let (x, y) = half(i);
        let (dx, dy) = (x - cx, y - cy);
        usize::from(dy < 0.0) * 4 + usize::from(dx < 0.0) * 2 + usize::from(dx.abs() < dy.abs())
    };
    let mut start = [0usize; 9];
    for &i in &kept {
        start[octant(i) + 1] += 1;
    }
    for b in 1..9 {
        start[b] += start[b - 1];
    }
    let mut out = vec![0; kept.len()];
    for &i in &kept {
        let b = octant(i);
        out[start[b]] = i;
        start[b] += 1;
    }
    out
}

/// Chan's rounds on the finite, non-empty `points`.
fn rounds<C: Counter>(points: &[Point2], counter: &mut C) -> Vec<usize> {
    let n = points.len();
    let start = lex_min(points, counter);
    let one_group = |counter: &mut C| chains(&lex_sorted_items(points, 0..n, counter), counter);
    let mut exponent = FIRST_EXPONENT;
    let mut m = group_size(exponent, n);
    if m >= n {
        return one_group(counter);
    }
    let mut groups = match Groups::of_input(points, m, Some(PROBED_GROUPS), counter) {
        Some(groups) => groups,
        None => {
            // The first groups are mostly hull vertices: take the next guess from the start.
            exponent *= 2;
            m = group_size(exponent, n);
            if 2 * m >= n {
                return one_group(counter);
            }
            Groups::of_input(points, m, None, counter).expect("no probe, no early return")
        }
    };
    loop {
        let limit = groups.march_limit(m);
        if let Some(hull) = wrap(points, &groups, start, limit, counter) {
            return hull;
        }
        // The hull of all points is the hull of the group hulls' vertices: the next round
        // groups only them, already sorted in runs.
        let candidates = groups.lex_runs();
        exponent = exponent.saturating_mul(2);
        m = group_size(exponent, candidates.len());
        // At most two groups: one costs no more (sorting s candidates in two groups of at
        // least s/2 costs as much as sorting them at once) and needs no march.
        if 2 * m >= candidates.len() {
            return chains(&sorted_candidates(points, candidates, counter), counter);
        }
        groups = Groups::of_runs(points, candidates, m, counter);
    }
}

/// `items`, sorted lexicographically without duplicates: merged from their runs when the
/// counter records (O(s log k) comparisons for k runs), by the radix sort otherwise, which
/// gives the same order faster.
fn sorted_candidates<C: Counter>(
    points: &[Point2],
    items: Vec<(Point2, usize)>,
    counter: &mut C,
) -> Vec<(Point2, usize)> {
    if C::DISCARDS {
        lex_sorted_items(points, items.into_iter().map(|item| item.1), counter)
    } else {
        lex_merged_items(items, counter)
    }
}

/// The first guess of the group size is 2^`FIRST_EXPONENT`; each failed round squares it.
///
/// Chan's analysis allows any constant start. Starting at 256 rather than 4 skips two rounds
/// whose marches cost as much as their groups' hulls and rarely close (uniform points have
/// more than 16 hull vertices from about 100 points on); inputs of up to 256 points are one
/// group, that is the monotone chain.
const FIRST_EXPONENT: u32 = 8;

/// How many groups of the first guess are hulled before the guess is judged: if their hulls
/// keep more than half of their points, the march over groups of 256 could close only after
/// a round of little filtering and many tangents, so the run restarts with the next guess,
/// 65 536, at a cost of at most these four groups. Chan's bound holds for any constant first
/// guess, so it holds for either; the choice only decides the constant.
const PROBED_GROUPS: usize = 4;

/// The hulls of groups of points, stored one after another.
struct Groups {
    /// Every group's strictly convex hull, counter-clockwise from its lexicographically
    /// smallest vertex: the point and its index in the input.
    vertices: Vec<(Point2, usize)>,
    /// Per group: where its hull starts in `vertices`, and its lexicographically largest
    /// vertex (relative to the start).
    spans: Vec<Span>,
}

#[derive(Clone, Copy)]
struct Span {
    start: usize,
    len: usize,
    top: usize,
}

impl Groups {
    /// The hulls of the groups `points[0..m]`, `points[m..2m]`, ...: each group's
    /// Akl–Toussaint survivors (most points of a group are strictly inside the polygon of
    /// its extreme points and are never sorted), sorted, then the monotone chain. The filter
    /// is skipped after a group where it kept more than three quarters of the points, until a
    /// group's hull has at most three quarters of its points.
    ///
    /// With `probe = Some(k)`: `None` as soon as the first k groups (if there are more) have
    /// hulls that keep more than half of their points.
    fn of_input<C: Counter>(
        points: &[Point2],
        m: usize,
        probe: Option<usize>,
        counter: &mut C,
    ) -> Option<Groups> {
        let mut groups = Groups::with_capacity(points.len(), m);
        let mut filtering = true;
        for (k, lo) in (0..points.len()).step_by(m).enumerate() {
            if probe == Some(k) && 2 * groups.vertices.len() > lo {
                return None;
            }
            let hi = (lo + m).min(points.len());
            let sorted = if filtering {
                let kept = filter(&points[lo..hi], true, counter);
                // Points in convex position all survive: stop filtering while the filter
                // keeps more than three quarters of a group.
                filtering = 4 * kept.len() <= 3 * (hi - lo);
                lex_sorted_items_by_comparisons(points, kept.into_iter().map(|i| i + lo), counter)
            } else {
                // Unfiltered groups of the larger guesses are long enough for the radix sort.
                lex_sorted_items(points, lo..hi, counter)
            };
            let before = groups.vertices.len();
            groups.push(points, &sorted, counter);
            // ... and take it up again once a group's hull keeps at most three quarters.
            filtering = filtering || 4 * (groups.vertices.len() - before) <= 3 * (hi - lo);
        }
        Some(groups)
    }

    /// The hulls of the groups `items[0..m]`, `items[m..2m]`, ... of points given in sorted
    /// runs (the last round's hulls, from [`Groups::lex_runs`]): each group is merged, then
    /// the monotone chain.
    fn of_runs<C: Counter>(
        points: &[Point2],
        items: Vec<(Point2, usize)>,
        m: usize,
        counter: &mut C,
    ) -> Groups {
        let mut groups = Groups::with_capacity(items.len(), m);
        for chunk in items.chunks(m) {
            let sorted = sorted_candidates(points, chunk.to_vec(), counter);
            groups.push(points, &sorted, counter);
        }
        groups
    }

    fn with_capacity(n: usize, m: usize) -> Groups {
        Groups {
            vertices: Vec::with_capacity(n),
            spans: Vec::with_capacity(n.div_ceil(m)),
        }
    }

    /// Adds the hull of `sorted` (distinct points in lexicographic order) as a group.
    fn push<C: Counter>(&mut self, points: &[Point2], sorted: &[(Point2, usize)], counter: &mut C) {
        let start = self.vertices.len();
        let hull = chains(sorted, counter);
        self.vertices
            .extend(hull.into_iter().map(|i| (points[i], i)));
        let len = self.vertices.len() - start;
        // Lexicographically increasing up to the top vertex, decreasing after it.
        let v = &self.vertices[start..];
        let top = partition_point(0..len - 1, |k| {
            counter.cmp_lex(v[k].0, v[k + 1].0) == Ordering::Less
        });
        self.spans.push(Span { start, len, top });
    }

    /// Every group's vertices in two lexicographically increasing runs (the lower chain,
    /// then the upper chain reversed), one group after another.
    fn lex_runs(&self) -> Vec<(Point2, usize)> {
        let mut runs = Vec::with_capacity(self.vertices.len());
        for &Span { start, len, top } in &self.spans {
            let v = &self.vertices[start..start + len];
            runs.extend_from_slice(&v[..=top]);
            runs.extend(v[top + 1..].iter().rev());
        }
        runs
    }

    /// The most vertices the march over these groups may find before the round gives up:
    /// `m`, or fewer when that many steps would cost more tangent tests than there are
    /// vertices in all the groups (about 4 log₂ a + 3 per group and step for groups of a
    /// vertices: two binary searches for the current vertex, one for the tangent). A march cut short costs no more than the next round's sorting of those
    /// vertices, so the rounds' total stays O(n log h); without the cut, uniform points
    /// (h ≈ 3.4 n^(1/3) in a disk) pay a march of 256 steps over n/256 groups, several
    /// times the cost of the whole hull, before the round with m = 65 536 closes.
    fn march_limit(&self, m: usize) -> usize {
        let (s, g) = (self.vertices.len(), self.spans.len());
        let log = (usize::BITS - (s / g).leading_zeros()) as usize;
        (s / (g * (4 * log + 3))).clamp(1, m)
    }

    /// The tangent of group `g` from `p`: the vertex of its hull that no vertex is right of
    /// (seen from `p`), the farthest of two on one ray; `None` if the group is only `p`.
    /// `p` must be outside the group's hull or one of its vertices.
    fn tangent<C: Counter>(&self, g: usize, p: Point2, counter: &mut C) -> Option<(Point2, usize)> {
        let Span { start, len, top } = self.spans[g];
        let v = &self.vertices[start..start + len];
        if let Some(j) = vertex_at(v, top, p, counter) {
            return (len > 1).then(|| v[(j + 1) % len]);
        }
        if len <= 2 {
            return v.iter().copied().reduce(|best, c| {
                if better(p, c.0, best.0, counter) {
                    c
                } else {
                    best
                }
            });
        }
        // key(i) < key(j) when v[i] is more clockwise from p than v[j] (or on one ray and
        // farther). Around the polygon the keys rise from their minimum to their maximum
        // and fall back: find the minimum by binary search over 1..len, anchored at v[0].
        let k = len;
        let mut below = |i: usize, j: usize| better(p, v[i].0, v[j].0, counter);
        let falls_at_0 = below(1, 0);
        let min = partition_point(1..k, |i| {
            let falls = below((i + 1) % k, i);
            let under_0 = below(i, 0);
            if falls_at_0 {
                // 0 is on the falling arc: before the minimum the keys fall below key(0).
                falls && under_0
            } else {
                // 0 is on the rising arc: after the minimum they rise below key(0).
                falls || !under_0
            }
        });
        Some(v[min % k])
    }
}

/// Chan's group size for the guess `exponent` (2^exponent), capped at `n`.
fn group_size(exponent: u32, n: usize) -> usize {
    if exponent >= usize::BITS {
        n
    } else {
        (1usize << exponent).min(n)
    }
}

/// Jarvis's march from `start` over the group hulls; `None` if it has not closed after
/// `limit` vertices.
fn wrap<C: Counter>(
    points: &[Point2],
    groups: &Groups,
    start: usize,
    limit: usize,
    counter: &mut C,
) -> Option<Vec<usize>> {
    let first = points[start];
    let mut hull = vec![start];
    let mut p = first;
    loop {
        let mut next: Option<(Point2, usize)> = None;
        // Groups in input order and strict improvement only: of equal points the one with
        // the smallest index wins.
        for g in 0..groups.spans.len() {
            if let Some(c) = groups.tangent(g, p, counter) {
                next = match next {
                    Some(best) if !better(p, c.0, best.0, counter) => Some(best),
                    _ => Some(c),
                };
            }
        }
        match next {
            Some((q, i)) if counter.cmp_lex(q, first) != Ordering::Equal => {
                if hull.len() == limit {
                    return None;
                }
                hull.push(i);
                p = q;
            }
            _ => return Some(hull),
        }
    }
}

/// Whether `c` beats `best` as the next vertex after `p`: `c` is right of `p -> best`, or
/// on the ray from `p` through `best` and strictly farther.
#[inline]
fn better<C: Counter>(p: Point2, c: Point2, best: Point2, counter: &mut C) -> bool {
    match counter.orient2d(p, best, c) {
        Orientation::Clockwise => true,
        Orientation::CounterClockwise => false,
        Orientation::Collinear => counter.cmp_dist(p, c, p, best) == Ordering::Greater,
    }
}

/// The position of `p` among the vertices `v` of a strictly convex hull (counter-clockwise
/// from its lexicographically smallest vertex, `top` its largest), if it is one: a binary
/// search on the increasing lower chain, then on the decreasing upper chain.
fn vertex_at<C: Counter>(
    v: &[(Point2, usize)],
    top: usize,
    p: Point2,
    counter: &mut C,
) -> Option<usize> {
    let k = partition_point(0..top + 1, |i| counter.cmp_lex(v[i].0, p) == Ordering::Less);
    if k <= top && counter.cmp_lex(v[k].0, p) == Ordering::Equal {
        return Some(k);
    }
    let k = partition_point(top + 1..v.len(), |i| {
        counter.cmp_lex(v[i].0, p) == Ordering::Greater
    });
    (k < v.len() && counter.cmp_lex(v[k].0, p) == Ordering::Equal).then_some(k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hull::brute_force_hull;

    /// The tangent search against a linear scan, from every point outside a polygon with
    /// collinear neighbours (a grid) and from each of its vertices.
    #[test]
    fn tangents_match_a_linear_scan() {
        let mut pts = Vec::new();
        for x in -3..=3 {
            for y in -3..=3 {
                pts.push(Point2::new(f64::from(x), f64::from(y)));
            }
        }
        let polygon: Vec<Point2> = [
            (0.0, -2.0),
            (2.0, -1.0),
            (2.0, 1.0),
            (0.0, 2.0),
            (-1.0, 0.0),
        ]
        .map(Point2::from)
        .to_vec();
        let groups = Groups::of_input(&polygon, polygon.len(), None, &mut NoCount).unwrap();
        let hull: Vec<Point2> = groups.vertices.iter().map(|v| v.0).collect();
        let outside = |q: Point2| {
            (0..hull.len()).any(|k| {
                crate::geometry::orient2d(hull[k], hull[(k + 1) % hull.len()], q)
                    == Orientation::Clockwise
            })
        };
        for &p in pts.iter().filter(|&&q| outside(q) || hull.contains(&q)) {
            let got = groups.tangent(0, p, &mut NoCount).unwrap().0;
            let expected = hull
                .iter()
                .copied()
                .filter(|&q| q != p)
                .reduce(|best, c| {
                    if better(p, c, best, &mut NoCount) {
                        c
                    } else {
                        best
                    }
                })
                .unwrap();
            assert_eq!(got, expected, "from {p:?}");
        }
    }

    /// 300 points in convex position: the march over two groups of at most 256 stops
    /// early, the next guess (65 536) holds every candidate, and the last round is one group.
    #[test]
    fn restarts_with_squared_group_size() {
        let pts: Vec<Point2> = (0..300)
            .map(|i| Point2::new(f64::from(i), f64::from(i * i)))
            .collect();
        assert_eq!([8, 16, 32].map(|e| group_size(e, 300)), [256, 300, 300]);
        assert_eq!(group_size(64, 300), 300);
        let groups = Groups::of_input(&pts, 256, None, &mut NoCount).unwrap();
        assert_eq!(groups.spans.len(), 2);
        assert_eq!(groups.vertices.len(), 300, "every point is a group vertex");
        let limit = groups.march_limit(256);
        assert!((1..=256).contains(&limit));
        assert!(wrap(&pts, &groups, 0, limit, &mut NoCount).is_none());
        let oracle = brute_force_hull(&pts, HullOptions::default()).unwrap();
        assert_eq!(oracle.len(), 300);
        assert_eq!(chan(&pts, HullOptions::default()).unwrap(), oracle);
        // With a limit of h the march closes: the first 16 points have 16 vertices.
        let groups = Groups::of_input(&pts[..16], 4, None, &mut NoCount).unwrap();
        let small = wrap(&pts[..16], &groups, 0, 16, &mut NoCount).unwrap();
        assert_eq!(
            small,
            brute_force_hull(&pts[..16], HullOptions::default()).unwrap()
        );
    }

    /// The probe: groups in convex position send the run to the next guess, groups of
    /// uniform points in a disk do not; either way the hull is the brute force's, also when
    /// only the probed groups are in convex position and the rest is inside them (the
    /// monotone chain as the oracle: the brute force is cubic).
    #[test]
    fn convex_first_groups_restart_with_the_next_guess() {
        let parabola: Vec<Point2> = (0..1100)
            .map(|i| Point2::new(f64::from(i), f64::from(i) * f64::from(i)))
            .collect();
        assert!(Groups::of_input(&parabola, 256, Some(PROBED_GROUPS), &mut NoCount).is_none());
        let disk = crate::gen::points(crate::gen::PointKind::UniformDisk, 3000, 5).unwrap();
        assert!(Groups::of_input(&disk, 256, Some(PROBED_GROUPS), &mut NoCount).is_some());
        // A parabola's first 1024 points, then points of a disk well inside it.
        let mut mixed = parabola[..1024].to_vec();
        mixed.extend(
            disk.iter()
                .map(|p| Point2::new(500.0 + 100.0 * p.x, 400_000.0 + 100.0 * p.y)),
        );
        for pts in [&parabola, &mixed] {
            let oracle = crate::hull::monotone_chain(pts, HullOptions::default()).unwrap();
            assert_eq!(chan(pts, HullOptions::default()).unwrap(), oracle);
            let mut counts = crate::count::Counts::default();
            let set = PointSet::new(pts).unwrap();
            assert_eq!(chan_with(&set, HullOptions::default(), &mut counts), oracle);
        }
    }

    /// The next round's groups, built from the last round's vertices in runs, are the hulls
    /// that grouping the input afresh would give (points in a disk, several group sizes).
    #[test]
    fn regrouped_runs_give_the_hulls_of_the_merged_groups() {
        let pts = crate::gen::points(crate::gen::PointKind::UniformDisk, 3000, 11).unwrap();
        for (m, m2) in [(4, 16), (16, 256), (256, 65536)] {
            let groups = Groups::of_input(&pts, m, None, &mut NoCount).unwrap();
            let runs = groups.lex_runs();
            assert_eq!(runs.len(), groups.vertices.len());
            // Runs rise; a fall starts a new run, at most two per group.
            let falls = runs
                .windows(2)
                .filter(|w| crate::geometry::cmp_lex(w[0].0, w[1].0) != Ordering::Less)
                .count();
            assert!(falls < 2 * groups.spans.len(), "m = {m}");
            let regrouped = Groups::of_runs(&pts, runs.clone(), m2, &mut NoCount);
            for (k, chunk) in runs.chunks(m2).enumerate() {
                let sub: Vec<Point2> = chunk.iter().map(|c| c.0).collect();
                let expected: Vec<usize> = brute_force_hull(&sub, HullOptions::default())
                    .unwrap()
                    .into_iter()
                    .map(|i| chunk[i].1)
                    .collect();
                let Span { start, len, .. } = regrouped.spans[k];
                let got: Vec<usize> = regrouped.vertices[start..start + len]
                    .iter()
                    .map(|v| v.1)
                    .collect();
                assert_eq!(got, expected, "m = {m}, group {k}");
            }
        }
    }
}
