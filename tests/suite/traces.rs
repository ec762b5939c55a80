//! Step traces (`compgeo::trace`): each trace is the algorithm's own run. The last frame is
//! the algorithm's result, the number of frames is the number of steps the algorithm makes
//! (derived here independently, by brute force or from the course's counting arguments),
//! and the counts in the last frame are those of the counted run.

use crate::common::set;
use crate::strategies::{lattice, uniform};
use compgeo::count::Counts;
use compgeo::geometry::{cmp_lex, orient2d, Orientation, Point2};
use compgeo::hull::{
    graham_scan_with, graham_trace, jarvis_march_with, jarvis_trace, monotone_chain_trace,
    monotone_chain_with, quickhull_trace, quickhull_with, Chain, ChainStep, GrahamStep,
    HullOptions, JarvisStep, QuickhullStep,
};
use compgeo::trace::Frame;
use compgeo::Error;
use proptest::prelude::*;

/// Counts never decrease from one frame to the next.
fn counts_grow<S>(frames: &[Frame<S>]) {
    for w in frames.windows(2) {
        for op in compgeo::count::Operation::ALL {
            assert!(w[0].counts.get(op) <= w[1].counts.get(op), "{op:?}");
        }
    }
}

/// The distinct points of `pts`: each one's smallest index.
fn distinct(pts: &[Point2]) -> Vec<usize> {
    (0..pts.len())
        .filter(|&i| (0..i).all(|j| pts[j] != pts[i]))
        .collect()
}

/// The strictly convex hull's vertex set by brute force: a distinct point is a vertex when
/// some line through it has every other distinct point strictly on one side or, for points
/// on the line, behind it; tested as "not in the closed triangle of three others and not
/// strictly between two others on a segment". Returned as a sorted list of indices.
fn brute_vertices(pts: &[Point2]) -> Vec<usize> {
    let d = distinct(pts);
    let inside = |p: usize, a: usize, b: usize, c: usize| {
        let o = [
            orient2d(pts[a], pts[b], pts[p]),
            orient2d(pts[b], pts[c], pts[p]),
            orient2d(pts[c], pts[a], pts[p]),
        ];
        let pos = o.iter().all(|&x| x != Orientation::Clockwise);
        let neg = o.iter().all(|&x| x != Orientation::CounterClockwise);
        pos || neg
    };
    let between = |p: usize, a: usize, b: usize| {
        orient2d(pts[a], pts[b], pts[p]) == Orientation::Collinear
            && cmp_lex(pts[a], pts[p]) != cmp_lex(pts[b], pts[p])
    };
    d.iter()
        .copied()
        .filter(|&p| {
            let others: Vec<usize> = d.iter().copied().filter(|&q| q != p).collect();
            for (x, &a) in others.iter().enumerate() {
                for (y, &b) in others.iter().enumerate().skip(x + 1) {
                    if between(p, a, b) {
                        return false;
                    }
                    for &c in &others[y + 1..] {
                        if orient2d(pts[a], pts[b], pts[c]) != Orientation::Collinear
                            && inside(p, a, b, c)
                        {
                            return false;
                        }
                    }
                }
            }
            true
        })
        .collect()
}

fn options(keep: bool) -> HullOptions {
    HullOptions {
        keep_collinear: keep,
    }
}

/// The multiplicity of `pts[v]` in `pts`.
fn copies(pts: &[Point2], v: usize) -> usize {
    pts.iter().filter(|&&p| p == pts[v]).count()
}

fn check_jarvis(pts: &[Point2], keep: bool) {
    let frames = jarvis_trace(pts, options(keep)).unwrap();
    let mut counts = Counts::default();
    let hull = jarvis_march_with(&set(pts), options(keep), &mut counts);
    let last = frames.last().unwrap();
    assert_eq!(last.step, JarvisStep::Done { hull: hull.clone() });
    assert_eq!(last.counts, counts);
    counts_grow(&frames);
    if pts.is_empty() {
        assert_eq!(frames.len(), 1);
        return;
    }
    // The march wraps from every strict hull vertex once and looks at every point but the
    // copies of the current vertex each time.
    let strict = jarvis_march_with(&set(pts), options(false), &mut Counts::default());
    let mut sorted = strict.clone();
    sorted.sort_unstable();
    assert_eq!(sorted, brute_vertices(pts));
    let looked: usize = strict.iter().map(|&v| pts.len() - copies(pts, v)).sum();
    let candidates: Vec<&Frame<JarvisStep>> = frames
        .iter()
        .filter(|f| matches!(f.step, JarvisStep::Candidate { .. }))
        .collect();
    assert_eq!(candidates.len(), looked);
    let wraps: Vec<usize> = frames
        .iter()
        .filter_map(|f| match &f.step {
            JarvisStep::Wrap { vertex, hull } => {
                assert_eq!(hull.last(), Some(vertex));
                Some(*vertex)
            }
            _ => None,
        })
        .collect();
    assert_eq!(wraps, strict[1..]);
    assert_eq!(frames[0].step, JarvisStep::Start { vertex: strict[0] });
    assert_eq!(frames.len(), 1 + looked + strict.len() - 1 + 1);
    // Each candidate frame after the first of its scan is one orientation test; the best
    // after a scan is the next vertex (or the start, to close the hull).
    let mut prev = frames[0].counts;
    let mut first_of_scan = true;
    for f in &frames[1..frames.len() - 1] {
        match &f.step {
            JarvisStep::Candidate {
                point, best, hull, ..
            } => {
                let tests = f.counts.orientation_tests - prev.orientation_tests;
                assert_eq!(tests, u64::from(!first_of_scan));
                if first_of_scan {
                    assert_eq!(point, best);
                }
                assert!(strict.starts_with(hull));
                first_of_scan = false;
            }
            JarvisStep::Wrap { .. } => first_of_scan = true,
            other => panic!("{other:?}"),
        }
        prev = f.counts;
    }
}

/// The directions from the pivot (the lexicographically smallest point) to the other
/// distinct points, counted by brute force.
fn directions(pts: &[Point2]) -> usize {
    let d = distinct(pts);
    let pivot = *d.iter().min_by(|&&a, &&b| cmp_lex(pts[a], pts[b])).unwrap();
    let others: Vec<usize> = d.into_iter().filter(|&i| i != pivot).collect();
    others
        .iter()
        .enumerate()
        .filter(|&(k, &a)| {
            others[..k]
                .iter()
                .all(|&b| orient2d(pts[pivot], pts[a], pts[b]) != Orientation::Collinear)
        })
        .count()
}

fn check_graham(pts: &[Point2], keep: bool) {
    let frames = graham_trace(pts, options(keep)).unwrap();
    let mut counts = Counts::default();
    let hull = graham_scan_with(&set(pts), options(keep), &mut counts);
    let last = frames.last().unwrap();
    assert_eq!(last.step, GrahamStep::Done { hull });
    assert_eq!(last.counts, counts);
    counts_grow(&frames);
    if pts.is_empty() {
        assert_eq!(frames.len(), 1);
        return;
    }
    let strict = graham_scan_with(&set(pts), options(false), &mut Counts::default());
    // The course's scan: one push per point of the angular order (the pivot and one point
    // per direction), one pop per point that is not a vertex.
    let pushes = 1 + directions(pts);
    let pops = pushes - strict.len();
    let mut stack: Vec<usize> = Vec::new();
    let (mut seen_pushes, mut seen_pops) = (0, 0);
    for f in &frames[1..frames.len() - 1] {
        match &f.step {
            GrahamStep::Push { point, stack: s } => {
                stack.push(*point);
                assert_eq!(&stack, s);
                seen_pushes += 1;
            }
            GrahamStep::Pop { point, stack: s } => {
                assert_eq!(stack.pop(), Some(*point));
                assert_eq!(&stack, s);
                seen_pops += 1;
            }
            other => panic!("{other:?}"),
        }
    }
    assert_eq!((seen_pushes, seen_pops), (pushes, pops));
    assert_eq!(stack, strict);
    assert_eq!(frames.len(), 1 + pushes + pops + 1);
    // Every orientation test of the scan pops a point or ends a push (the course's 2n − 4
    // argument): the pivot and the first direction are pushed without a test.
    let GrahamStep::Sorted { order } = &frames[0].step else {
        panic!("{:?}", frames[0].step)
    };
    assert_eq!(order.len(), pushes);
    let scan_tests =
        frames[frames.len() - 2].counts.orientation_tests - frames[0].counts.orientation_tests;
    assert_eq!(scan_tests as usize, pops + pushes.saturating_sub(2));
    assert!(scan_tests as usize <= (2 * pts.len()).saturating_sub(4).max(pops));
}

fn check_monotone(pts: &[Point2], keep: bool) {
    let frames = monotone_chain_trace(pts, options(keep)).unwrap();
    let mut counts = Counts::default();
    let hull = monotone_chain_with(&set(pts), options(keep), &mut counts);
    let last = frames.last().unwrap();
    assert_eq!(last.step, ChainStep::Done { hull });
    assert_eq!(last.counts, counts);
    counts_grow(&frames);
    let strict = monotone_chain_with(&set(pts), options(false), &mut Counts::default());
    let mut d = distinct(pts);
    d.sort_by(|&a, &b| cmp_lex(pts[a], pts[b]));
    assert_eq!(frames[0].step, ChainStep::Sorted { order: d.clone() });
    if d.len() <= 2 {
        assert_eq!(frames.len(), 2);
        return;
    }
    let (first, end) = (d[0], d[d.len() - 1]);
    let side = |o: Orientation| -> Vec<usize> {
        d.iter()
            .copied()
            .filter(|&i| orient2d(pts[first], pts[end], pts[i]) == o)
            .collect()
    };
    let below = side(Orientation::Clockwise);
    let mut above = side(Orientation::CounterClockwise);
    above.reverse();
    let lower: Vec<usize> = [first].into_iter().chain(below).chain([end]).collect();
    let upper: Vec<usize> = [end].into_iter().chain(above).chain([first]).collect();
    assert_eq!(
        frames[1].step,
        ChainStep::Split {
            lower: lower.clone(),
            upper: upper.clone()
        }
    );
    let mut stacks = [Vec::new(), Vec::new()];
    let mut moves = [(0, 0), (0, 0)];
    let mut current = Chain::Lower;
    for f in &frames[2..frames.len() - 1] {
        let (chain, point, s, push) = match &f.step {
            ChainStep::Push {
                chain,
                point,
                stack,
            } => (*chain, *point, stack, true),
            ChainStep::Pop {
                chain,
                point,
                stack,
            } => (*chain, *point, stack, false),
            other => panic!("{other:?}"),
        };
        // The lower chain is scanned first, then the upper.
        assert!(chain == current || (current == Chain::Lower && chain == Chain::Upper));
        current = chain;
        let k = usize::from(chain == Chain::Upper);
        if push {
            stacks[k].push(point);
            moves[k].0 += 1;
        } else {
            assert_eq!(stacks[k].pop(), Some(point));
            moves[k].1 += 1;
        }
        assert_eq!(&stacks[k], s);
    }
    // Each chain pushes its points and pops those that are not vertices.
    for (k, chain) in [lower, upper].iter().enumerate() {
        assert_eq!(moves[k].0, chain.len());
        assert_eq!(moves[k].1, chain.len() - stacks[k].len());
    }
    let joined: Vec<usize> = stacks[0][..stacks[0].len() - 1]
        .iter()
        .chain(&stacks[1][..stacks[1].len() - 1])
        .copied()
        .collect();
    assert_eq!(joined, strict);
}

fn check_quickhull(pts: &[Point2], keep: bool) {
    let frames = quickhull_trace(pts, options(keep)).unwrap();
    let mut counts = Counts::default();
    let hull = quickhull_with(&set(pts), options(keep), &mut counts);
    let last = frames.last().unwrap();
    assert_eq!(last.step, QuickhullStep::Done { hull });
    assert_eq!(last.counts, counts);
    counts_grow(&frames);
    let strict = quickhull_with(&set(pts), options(false), &mut Counts::default());
    let d = distinct(pts);
    if d.len() < 2 {
        assert_eq!(frames.len(), 1);
        return;
    }
    // One split per hull vertex other than the two ends.
    assert_eq!(frames.len(), 1 + (strict.len() - 2) + 1);
    let QuickhullStep::Ends { a, b, below, above } = &frames[0].step else {
        panic!("{:?}", frames[0].step)
    };
    let right_of =
        |a: usize, b: usize, i: usize| orient2d(pts[a], pts[b], pts[i]) == Orientation::Clockwise;
    let all: Vec<usize> = (0..pts.len()).collect();
    assert_eq!(
        below,
        &all.iter()
            .copied()
            .filter(|&i| right_of(*a, *b, i))
            .collect::<Vec<_>>()
    );
    assert_eq!(
        above,
        &all.iter()
            .copied()
            .filter(|&i| right_of(*b, *a, i))
            .collect::<Vec<_>>()
    );
    for f in &frames[1..frames.len() - 1] {
        let QuickhullStep::Split {
            edge: [a, b],
            points,
            farthest,
            first,
            second,
        } = &f.step
        else {
            panic!("{:?}", f.step)
        };
        assert!(strict.contains(farthest) && strict.contains(a) && strict.contains(b));
        assert!(points.iter().all(|&i| right_of(*a, *b, i)));
        // No point of the subproblem is farther from the edge's line than the new vertex.
        for &i in points {
            assert_ne!(
                compgeo::geometry::cross_sign(pts[*a], pts[*b], pts[*farthest], pts[i]),
                Orientation::Clockwise
            );
        }
        let expect_first: Vec<usize> = points
            .iter()
            .copied()
            .filter(|&i| right_of(*a, *farthest, i))
            .collect();
        let expect_second: Vec<usize> = points
            .iter()
            .copied()
            .filter(|&i| !right_of(*a, *farthest, i) && right_of(*farthest, *b, i))
            .collect();
        assert_eq!((first, second), (&expect_first, &expect_second));
    }
}

fn check_hulls(pts: &[Point2]) {
    for keep in [false, true] {
        check_jarvis(pts, keep);
        check_graham(pts, keep);
        check_monotone(pts, keep);
        check_quickhull(pts, keep);
    }
}

#[test]
fn hull_traces_on_small_and_degenerate_inputs() {
    let p = |v: &[(f64, f64)]| v.iter().copied().map(Point2::from).collect::<Vec<_>>();
    check_hulls(&[]);
    check_hulls(&p(&[(1.0, 2.0)]));
    check_hulls(&p(&[(1.0, 2.0), (1.0, 2.0)]));
    check_hulls(&p(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (1.0, 1.0)]));
    check_hulls(&p(&[
        (0.0, 0.0),
        (2.0, 0.0),
        (1.0, 1.0),
        (2.0, 2.0),
        (0.0, 2.0),
        (1.0, 0.0),
    ]));
    // A square with its centre and the midpoints of its sides.
    let mut square = Vec::new();
    for x in 0..3 {
        for y in 0..3 {
            square.push(Point2::new(f64::from(x), f64::from(y)));
        }
    }
    check_hulls(&square);
}

#[test]
fn graham_trace_of_a_fan_worked_by_hand() {
    // The pivot (0, 0) and six points on distinct rays from it, alternately near (odd i,
    // (16, 2i)) and far (even i, (32, 4i)). By the course's step 4, worked by hand with the
    // signed areas: 3 is popped when 4 comes; 5 and then 4 (on the segment 2-6) when 6
    // comes.
    let mut pts = vec![Point2::new(0.0, 0.0)];
    for i in 1..=6 {
        let (r, t) = if i % 2 == 0 { (32.0, 4.0) } else { (16.0, 2.0) };
        pts.push(Point2::new(r, t * f64::from(i)));
    }
    let steps: Vec<GrahamStep> = graham_trace(&pts, HullOptions::default())
        .unwrap()
        .into_iter()
        .map(|f| f.step)
        .collect();
    let push = |point: usize, stack: &[usize]| GrahamStep::Push {
        point,
        stack: stack.to_vec(),
    };
    let pop = |point: usize, stack: &[usize]| GrahamStep::Pop {
        point,
        stack: stack.to_vec(),
    };
    assert_eq!(
        steps,
        [
            GrahamStep::Sorted {
                order: (0..7).collect()
            },
            push(0, &[0]),
            push(1, &[0, 1]),
            push(2, &[0, 1, 2]),
            push(3, &[0, 1, 2, 3]),
            pop(3, &[0, 1, 2]),
            push(4, &[0, 1, 2, 4]),
            push(5, &[0, 1, 2, 4, 5]),
            pop(5, &[0, 1, 2, 4]),
            pop(4, &[0, 1, 2]),
            push(6, &[0, 1, 2, 6]),
            GrahamStep::Done {
                hull: vec![0, 1, 2, 6]
            },
        ]
    );
}

#[test]
fn a_trace_beyond_the_limit_is_refused_by_name() {
    // Jarvis on 1100 points in convex position: 1100² candidate frames of growing hulls.
    let pts = compgeo::gen::points(compgeo::gen::PointKind::Cocircular, 1100, 3).unwrap();
    let e = jarvis_trace(&pts, HullOptions::default()).unwrap_err();
    assert!(
        matches!(
            e,
            Error::LimitExceeded {
                limit: "TRACE_MAX_ENTRIES",
                ..
            }
        ),
        "{e}"
    );
    assert!(jarvis_trace(&pts[..30], HullOptions::default()).is_ok());
}

#[test]
fn hull_traces_reject_non_finite_points() {
    let pts = [Point2::new(0.0, 0.0), Point2::new(f64::NAN, 1.0)];
    for e in [
        jarvis_trace(&pts, HullOptions::default()).map(|_| ()),
        graham_trace(&pts, HullOptions::default()).map(|_| ()),
        monotone_chain_trace(&pts, HullOptions::default()).map(|_| ()),
        quickhull_trace(&pts, HullOptions::default()).map(|_| ()),
    ] {
        assert!(matches!(e, Err(Error::NonFinite { .. })), "{e:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn hull_traces_on_lattices(pts in lattice(-4..=4, 0..14)) {
        check_hulls(&pts);
    }

    #[test]
    fn hull_traces_on_uniform_points(pts in uniform(100.0, 3..16)) {
        check_hulls(&pts);
    }
}

/// The directed edges of flat `triangles` (three per triangle, counter-clockwise), with the
/// opposite vertex of each: edge a -> b of triangle [a, b, c] maps to c.
fn directed_edges(triangles: &[usize]) -> std::collections::HashMap<(usize, usize), usize> {
    let mut out = std::collections::HashMap::new();
    for t in triangles.chunks(3) {
        for k in 0..3 {
            let previous = out.insert((t[k], t[(k + 1) % 3]), t[(k + 2) % 3]);
            assert!(previous.is_none(), "edge twice in one direction");
        }
    }
    out
}

fn check_lawson(pts: &[Point2]) {
    use compgeo::delaunay::{check_delaunay, lawson, lawson_trace, lawson_with, LawsonStep};
    use compgeo::geometry::{incircle, InCircle};
    let frames = lawson_trace(pts).unwrap();
    let mut counts = Counts::default();
    let result = lawson_with(&set(pts), &mut counts).unwrap();
    assert_eq!(result, lawson(pts).unwrap());
    let last = frames.last().unwrap();
    assert_eq!(
        last.step,
        LawsonStep::Done {
            triangulation: result.clone()
        }
    );
    assert_eq!(last.counts, counts);
    assert_eq!(check_delaunay(pts, &result), Ok(()));
    counts_grow(&frames);
    let LawsonStep::Swept { triangles: swept } = &frames[0].step else {
        panic!("{:?}", frames[0].step)
    };
    // Every flip removes an edge whose far vertex is strictly inside the circle through
    // the near triangle, and rewrites exactly its two triangles in place.
    let mut current = swept.clone();
    let undirected = |tris: &[usize]| -> std::collections::HashSet<(usize, usize)> {
        directed_edges(tris)
            .into_keys()
            .map(|(a, b)| (a.min(b), a.max(b)))
            .collect()
    };
    let interior = directed_edges(swept)
        .keys()
        .filter(|&&(a, b)| a < b && directed_edges(swept).contains_key(&(b, a)))
        .count() as u64;
    let mut previous_tests = frames[0].counts.incircle_tests;
    for f in &frames[1..frames.len() - 1] {
        let LawsonStep::Flip {
            removed: [a, b],
            added: [d, c],
            triangles,
        } = &f.step
        else {
            panic!("{:?}", f.step)
        };
        let edges = directed_edges(&current);
        assert_eq!(edges.get(&(*a, *b)), Some(c));
        assert_eq!(edges.get(&(*b, *a)), Some(d));
        assert_eq!(
            incircle(pts[*a], pts[*b], pts[*c], pts[*d]),
            InCircle::Inside
        );
        let changed: Vec<usize> = (0..current.len() / 3)
            .filter(|&k| current[3 * k..3 * k + 3] != triangles[3 * k..3 * k + 3])
            .collect();
        assert_eq!(changed.len(), 2);
        let after = directed_edges(triangles);
        assert!(after.contains_key(&(*d, *c)) && after.contains_key(&(*c, *d)));
        assert!(!after.contains_key(&(*a, *b)) && !after.contains_key(&(*b, *a)));
        // Each flip follows the in-circle test that found its edge.
        assert!(f.counts.incircle_tests > previous_tests);
        previous_tests = f.counts.incircle_tests;
        current = triangles.clone();
    }
    assert_eq!(current, result.triangles);
    // Every edge of the sweep that Delaunay's triangulation lacks was flipped away; the edge
    // checks are the sweep's interior edges plus the four edges around each flip, at most.
    let flips = (frames.len() - 2) as u64;
    let gone = undirected(swept)
        .difference(&undirected(&result.triangles))
        .count() as u64;
    assert!(flips >= gone, "{flips} flips, {gone} edges gone");
    let tests = last.counts.incircle_tests - frames[0].counts.incircle_tests;
    assert!(
        tests >= flips && tests <= interior + 4 * flips,
        "{tests} tests"
    );
}

#[test]
fn lawson_traces_on_a_parabola_and_degenerate_input() {
    // Points on a parabola: the sweep's fans are far from Delaunay.
    let pts = compgeo::gen::points(compgeo::gen::PointKind::Parabola, 24, 0).unwrap();
    check_lawson(&pts);
    assert!(compgeo::delaunay::lawson_trace(&pts).unwrap().len() > 2 + 24);
    check_lawson(&[]);
    check_lawson(&[
        Point2::new(1.0, 1.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 2.0),
    ]);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn lawson_traces_on_lattices(pts in lattice(-5..=5, 0..20)) {
        check_lawson(&pts);
    }

    #[test]
    fn lawson_traces_on_uniform_points(pts in uniform(100.0, 3..30)) {
        check_lawson(&pts);
    }
}

/// A small graph: n vertices and edges [u, v] (loops and parallel edges allowed), with
/// weights from a few integers so that ties are common.
fn arb_weighted() -> impl Strategy<Value = (usize, Vec<[usize; 2]>, Vec<f64>)> {
    (1usize..9).prop_flat_map(|n| {
        prop::collection::vec((0..n, 0..n, 0u8..5), 0..18).prop_map(move |es| {
            let edges = es.iter().map(|&(u, v, _)| [u, v]).collect();
            let weights = es.iter().map(|&(_, _, w)| f64::from(w)).collect();
            (n, edges, weights)
        })
    })
}

/// Component labels by repeated relaxation (no union–find: an independent oracle).
fn labels(n: usize, edges: &[[usize; 2]]) -> Vec<usize> {
    let mut label: Vec<usize> = (0..n).collect();
    loop {
        let mut changed = false;
        for &[u, v] in edges {
            let m = label[u].min(label[v]);
            for x in [u, v] {
                if label[x] != m {
                    label[x] = m;
                    changed = true;
                }
            }
        }
        if !changed {
            return label;
        }
    }
}

fn check_colouring_trace(n: usize, edges: &[[usize; 2]], order: &[usize]) {
    use compgeo::graph::{
        course_greedy_colouring_trace, course_greedy_colouring_with, CourseColouringStep, Graph,
    };
    let g = Graph::from_edges(n, edges).unwrap();
    let frames = course_greedy_colouring_trace(&g, order).unwrap();
    let mut counts = Counts::default();
    let colouring = course_greedy_colouring_with(&g, order, &mut counts).unwrap();
    let last = frames.last().unwrap();
    assert_eq!(last.step, CourseColouringStep::Done { colouring });
    assert_eq!(last.counts, counts);
    assert_eq!(frames.len(), n + 1);
    let adjacent = |u: usize, v: usize| {
        edges
            .iter()
            .any(|&[a, b]| [a, b] == [u, v] || [a, b] == [v, u])
    };
    let mut so_far: Vec<Option<usize>> = vec![None; n];
    for (i, f) in frames[..n].iter().enumerate() {
        let CourseColouringStep::Coloured {
            vertex,
            colour,
            adjacent: found,
            colours,
        } = &f.step
        else {
            panic!("{:?}", f.step)
        };
        // The course: ask about every earlier vertex, then the first colour not in S.
        assert_eq!(*vertex, order[i]);
        assert_eq!(f.counts.adjacency_tests, (i * (i + 1) / 2) as u64);
        let expected: Vec<usize> = order[..i]
            .iter()
            .copied()
            .filter(|&u| u != *vertex && adjacent(u, *vertex))
            .collect();
        assert_eq!(found, &expected);
        let used: Vec<usize> = expected.iter().map(|&u| so_far[u].unwrap()).collect();
        let first_free = (0..).find(|k| !used.contains(k)).unwrap();
        assert_eq!(*colour, first_free);
        so_far[*vertex] = Some(first_free);
        assert_eq!(colours, &so_far);
    }
}

fn check_prim_trace(n: usize, edges: &[[usize; 2]], weights: &[f64]) {
    use compgeo::graph::{prim, prim_trace, prim_with, PrimStep, WeightedGraph};
    let g = WeightedGraph::from_edges(n, edges, weights).unwrap();
    let frames = prim_trace(&g).unwrap();
    let mut counts = Counts::default();
    let forest = prim_with(&g, &mut counts);
    assert_eq!(forest, prim(&g));
    let last = frames.last().unwrap();
    assert_eq!(
        last.step,
        PrimStep::Done {
            forest: forest.clone()
        }
    );
    assert_eq!(last.counts, counts);
    counts_grow(&frames);
    let label = labels(n, edges);
    let components = (0..n).filter(|&v| label[v] == v).count();
    let proper: Vec<usize> = (0..edges.len())
        .filter(|&e| edges[e][0] != edges[e][1])
        .collect();
    let key = |e: usize| (weights[e], e);
    let lighter = |a: usize, b: usize| key(a).0.total_cmp(&key(b).0).then(a.cmp(&b)).is_lt();
    let mut in_tree = vec![false; n];
    let (mut roots, mut edge_frames, mut accepted) = (0, 0, Vec::new());
    for (k, f) in frames[..frames.len() - 1].iter().enumerate() {
        match &f.step {
            PrimStep::Root { vertex } => {
                assert!(!in_tree[*vertex]);
                in_tree[*vertex] = true;
                roots += 1;
            }
            PrimStep::Edge {
                edge,
                to,
                accepted: ok,
                tree,
            } => {
                edge_frames += 1;
                let [u, v] = edges[*edge];
                assert!(*to == u || *to == v);
                assert_eq!(*ok, !in_tree[*to]);
                if *ok {
                    let from = if *to == u { v } else { u };
                    assert!(in_tree[from]);
                    // The course's rule: the lightest edge that adds a new vertex.
                    for &e in &proper {
                        let [a, b] = edges[e];
                        if in_tree[a] != in_tree[b] {
                            assert!(!lighter(e, *edge), "edge {e} is lighter than {edge}");
                        }
                    }
                    // The very first edge is the lightest of the graph.
                    if k == 1 {
                        assert!(proper.iter().all(|&e| !lighter(e, *edge)));
                    }
                    in_tree[*to] = true;
                    accepted.push(*edge);
                }
                assert_eq!(tree, &accepted);
            }
            other => panic!("{other:?}"),
        }
    }
    assert_eq!(roots, components);
    assert_eq!(accepted.len(), n - components);
    // Each edge that is not a loop enters the heap once and comes out once.
    assert_eq!(edge_frames, proper.len());
    accepted.sort_unstable();
    assert_eq!(accepted, forest.edges);
}

fn check_kruskal_trace(n: usize, edges: &[[usize; 2]], weights: &[f64]) {
    use compgeo::graph::{kruskal, kruskal_trace, kruskal_with, KruskalStep, WeightedGraph};
    let g = WeightedGraph::from_edges(n, edges, weights).unwrap();
    let frames = kruskal_trace(&g).unwrap();
    let mut counts = Counts::default();
    let forest = kruskal_with(&g, &mut counts);
    assert_eq!(forest, kruskal(&g));
    let last = frames.last().unwrap();
    assert_eq!(
        last.step,
        KruskalStep::Done {
            forest: forest.clone()
        }
    );
    assert_eq!(last.counts, counts);
    counts_grow(&frames);
    let mut order: Vec<usize> = (0..edges.len())
        .filter(|&e| edges[e][0] != edges[e][1])
        .collect();
    order.sort_by(|&a, &b| weights[a].total_cmp(&weights[b]).then(a.cmp(&b)));
    assert_eq!(
        frames[0].step,
        KruskalStep::Sorted {
            order: order.clone()
        }
    );
    // Every comparison is the sort's; then one edge visit per edge examined.
    assert_eq!(frames[0].counts.comparisons, counts.comparisons);
    let mut chosen: Vec<[usize; 2]> = Vec::new();
    let mut examined = 0;
    for (f, &e) in frames[1..frames.len() - 1].iter().zip(&order) {
        let KruskalStep::Edge {
            edge,
            accepted,
            forest: so_far,
        } = &f.step
        else {
            panic!("{:?}", f.step)
        };
        assert_eq!(*edge, e);
        let label = labels(n, &chosen);
        assert_eq!(*accepted, label[edges[e][0]] != label[edges[e][1]]);
        if *accepted {
            chosen.push(edges[e]);
        }
        assert_eq!(so_far.len(), chosen.len());
        examined += 1;
        assert_eq!(f.counts.edge_visits, examined);
    }
    // It stops as soon as the forest has n − 1 edges, or when the order is exhausted.
    let expected = if chosen.len() + 1 >= n {
        // The examined prefix ends with the acceptance that completed the tree (none
        // needed for a single vertex).
        let mut needed = 0;
        let mut picked: Vec<[usize; 2]> = Vec::new();
        for &e in &order {
            if picked.len() + 1 >= n {
                break;
            }
            needed += 1;
            let label = labels(n, &picked);
            if label[edges[e][0]] != label[edges[e][1]] {
                picked.push(edges[e]);
            }
        }
        needed
    } else {
        order.len()
    };
    assert_eq!(frames.len() - 2, expected);
}

/// The course's search scheme written out here, as an oracle: Q holds the start; look at its
/// first (BFS) or last (DFS) vertex x; append its smallest neighbour not reached yet, else
/// remove x. Returns the rows (added, removed, Q after).
fn course_search(
    n: usize,
    edges: &[[usize; 2]],
    start: usize,
    breadth_first: bool,
) -> Vec<(Option<usize>, Option<usize>, Vec<usize>)> {
    let adjacent = |u: usize, v: usize| {
        u != v
            && edges
                .iter()
                .any(|&[a, b]| [a, b] == [u, v] || [a, b] == [v, u])
    };
    let mut seen = vec![false; n];
    seen[start] = true;
    let mut q = std::collections::VecDeque::from([start]);
    let mut rows = vec![(Some(start), None, vec![start])];
    while let Some(&x) = if breadth_first { q.front() } else { q.back() } {
        match (0..n).find(|&y| !seen[y] && adjacent(x, y)) {
            Some(y) => {
                seen[y] = true;
                q.push_back(y);
                rows.push((Some(y), None, q.iter().copied().collect()));
            }
            None => {
                if breadth_first {
                    q.pop_front();
                } else {
                    q.pop_back();
                }
                rows.push((None, Some(x), q.iter().copied().collect()));
            }
        }
    }
    rows
}

fn check_search_trace(n: usize, edges: &[[usize; 2]], start: usize) {
    use compgeo::graph::{search, search_trace, search_with, Graph, SearchAlgorithm, SearchStep};
    let g = Graph::from_edges(n, edges).unwrap();
    for (kind, breadth_first) in [(SearchAlgorithm::Bfs, true), (SearchAlgorithm::Dfs, false)] {
        let frames = search_trace(&g, start, kind).unwrap();
        let rows = course_search(n, edges, start, breadth_first);
        // A row per vertex of the start's component added and removed, then the result.
        let label = labels(n, edges);
        let component = (0..n).filter(|&v| label[v] == label[start]).count();
        assert_eq!(rows.len(), 2 * component);
        assert_eq!(frames.len(), rows.len() + 1);
        let mut parent_of = vec![None; n];
        for (f, (added, removed, q)) in frames.iter().zip(&rows) {
            match &f.step {
                SearchStep::Add {
                    vertex,
                    parent,
                    list,
                } => {
                    assert_eq!((Some(*vertex), None, list), (*added, *removed, q));
                    // The parent is the vertex Q was looked at for: its first or last
                    // before the step.
                    if let Some(p) = parent {
                        let looked_at = if breadth_first { q[0] } else { q[q.len() - 2] };
                        assert_eq!(*p, looked_at);
                    }
                    parent_of[*vertex] = *parent;
                }
                SearchStep::Remove { vertex, list } => {
                    assert_eq!((None, Some(*vertex), list), (*added, *removed, q));
                }
                SearchStep::Done { .. } => panic!("done before the end"),
            }
        }
        let mut counts = Counts::default();
        let result = search_with(&g, start, kind, &mut counts).unwrap();
        assert_eq!(result, search(&g, start, kind).unwrap());
        assert_eq!(result.parent, parent_of);
        let last = frames.last().unwrap();
        assert_eq!(last.step, SearchStep::Done { search: result });
        assert_eq!(last.counts, counts);
        counts_grow(&frames);
    }
}

#[test]
fn graph_traces_on_small_graphs() {
    // The course's search toy graph shape: a 5-cycle with a chord, in two orders.
    let edges = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 0], [0, 2]];
    check_colouring_trace(5, &edges, &[0, 1, 2, 3, 4]);
    check_colouring_trace(5, &edges, &[4, 2, 0, 3, 1]);
    check_colouring_trace(0, &[], &[]);
    let weights = [4.0, 1.0, 3.0, 1.0, 2.0, 5.0];
    check_prim_trace(5, &edges, &weights);
    check_kruskal_trace(5, &edges, &weights);
    // Two components, a loop and a parallel edge.
    let edges = [[0, 1], [1, 0], [2, 2], [2, 3], [3, 4]];
    let weights = [2.0, 1.0, 0.0, 1.0, 1.0];
    check_prim_trace(6, &edges, &weights);
    check_kruskal_trace(6, &edges, &weights);
    check_prim_trace(0, &[], &[]);
    check_kruskal_trace(0, &[], &[]);
    for start in [0, 2, 5] {
        check_search_trace(6, &edges, start);
    }
}

#[test]
fn colouring_trace_rejects_a_bad_order() {
    let g = compgeo::graph::Graph::from_edges(3, &[[0, 1]]).unwrap();
    let e = compgeo::graph::course_greedy_colouring_trace(&g, &[0, 0, 1]).unwrap_err();
    assert!(matches!(e, Error::InvalidParameter { .. }), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn graph_traces_on_random_graphs((n, edges, weights) in arb_weighted(), seed in any::<u64>()) {
        // A random order of the vertices.
        let mut order: Vec<usize> = (0..n).collect();
        let mut x = seed | 1;
        for i in (1..n).rev() {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            order.swap(i, (x % (i as u64 + 1)) as usize);
        }
        check_colouring_trace(n, &edges, &order);
        check_search_trace(n, &edges, order.first().copied().unwrap_or(0).min(n - 1));
        check_prim_trace(n, &edges, &weights);
        check_kruskal_trace(n, &edges, &weights);
    }
}

mod curves {
    use super::counts_grow;
    use crate::spline_common::{q, qi, Q};
    use compgeo::count::Counts;
    use compgeo::spline::subdivision::{
        lane_riesenfeld, lane_riesenfeld_trace, lane_riesenfeld_with, LaneRiesenfeldStep, Topology,
    };
    use compgeo::spline::{Bezier, Point};
    use num_bigint::BigInt;
    use proptest::prelude::*;

    type P2 = Point<Q, 2>;

    fn binomial(n: usize, k: usize) -> Q {
        let mut c = BigInt::from(1);
        for j in 0..k {
            c = c * BigInt::from(n - j) / BigInt::from(j + 1);
        }
        Q::from_integer(c)
    }

    /// The point bᵢᵏ(t) = Σⱼ Bⱼᵏ(t) bᵢ₊ⱼ of de Casteljau's triangle, from the Bernstein
    /// polynomials (an independent formula).
    fn triangle_point(b: &[P2], i: usize, k: usize, t: &Q) -> P2 {
        let mut sum = Point::new([qi(0), qi(0)]);
        for j in 0..=k {
            let mut w = binomial(k, j);
            for _ in 0..j {
                w *= t;
            }
            for _ in 0..k - j {
                w *= qi(1) - t;
            }
            sum += &(b[i + j].clone() * &w);
        }
        sum
    }

    fn check_de_casteljau(control: Vec<P2>, t: Q) {
        let curve = Bezier::new(control.clone()).unwrap();
        let n = curve.degree();
        let frames = curve.de_casteljau_trace(&t).unwrap();
        let mut counts = Counts::default();
        let point = curve.de_casteljau_with(&t, &mut counts).unwrap();
        assert_eq!(frames.len(), n + 1);
        let last = frames.last().unwrap();
        assert_eq!(last.step.points, std::slice::from_ref(&point));
        assert_eq!(point, triangle_point(&control, 0, n, &t));
        assert_eq!(last.counts, counts);
        counts_grow(&frames);
        let mut combinations = 0;
        for (k, f) in frames.iter().enumerate() {
            assert_eq!(f.step.level, k);
            assert_eq!(f.step.points.len(), n + 1 - k);
            if k > 0 {
                combinations += n + 1 - k;
            }
            assert_eq!(f.counts.arithmetic_operations, combinations as u64);
            for (i, p) in f.step.points.iter().enumerate() {
                assert_eq!(
                    p,
                    &triangle_point(&control, i, k, &t),
                    "level {k}, point {i}"
                );
            }
        }
        // The borders of the scaffolding are the two halves at t.
        let (left, right) = curve.split(&t).unwrap();
        let first: Vec<P2> = frames.iter().map(|f| f.step.points[0].clone()).collect();
        let mut end: Vec<P2> = frames
            .iter()
            .map(|f| f.step.points[f.step.points.len() - 1].clone())
            .collect();
        end.reverse();
        assert_eq!(left.control(), first);
        assert_eq!(right.control(), end);
    }

    #[test]
    fn de_casteljau_scaffolding_of_the_course_figure() {
        // The course draws the quadratic scaffolding at t = 1/3 ([RD, §3.2]).
        let control = vec![
            Point::new([qi(0), qi(0)]),
            Point::new([qi(3), qi(6)]),
            Point::new([qi(9), qi(0)]),
        ];
        check_de_casteljau(control.clone(), q(1, 3));
        let curve = Bezier::new(control).unwrap();
        let frames = curve.de_casteljau_trace(&q(1, 3)).unwrap();
        // P₀⁽¹⁾ = ⅔P₀ + ⅓P₁, P₁⁽¹⁾ = ⅔P₁ + ⅓P₂, C(⅓) = ⅔P₀⁽¹⁾ + ⅓P₁⁽¹⁾.
        assert_eq!(
            frames[1].step.points,
            [Point::new([qi(1), qi(2)]), Point::new([qi(5), qi(4)])]
        );
        assert_eq!(frames[2].step.points, [Point::new([q(7, 3), q(8, 3)])]);
        assert!(curve.de_casteljau_trace(&Q::from_integer(0.into())).is_ok());
        let bad = Bezier::new(vec![Point::new([0.0]), Point::new([1.0])]).unwrap();
        assert!(bad.de_casteljau_trace(&f64::NAN).is_err());
    }

    fn check_lane_riesenfeld(points: &[P2], degree: usize, rounds: usize, topology: Topology) {
        let frames = lane_riesenfeld_trace(points, degree, rounds, topology).unwrap();
        let mut counts = Counts::default();
        let result = lane_riesenfeld_with(points, degree, rounds, topology, &mut counts).unwrap();
        assert_eq!(frames.len(), 1 + rounds * (degree + 1));
        let polygon = |s: &LaneRiesenfeldStep<Q, 2>| match s {
            LaneRiesenfeldStep::Input { polygon }
            | LaneRiesenfeldStep::Doubled { polygon, .. }
            | LaneRiesenfeldStep::Averaged { polygon, .. } => polygon.clone(),
        };
        let last = frames.last().unwrap();
        assert_eq!(polygon(&last.step), result);
        assert_eq!(last.counts, counts);
        counts_grow(&frames);
        assert_eq!(
            frames[0].step,
            LaneRiesenfeldStep::Input {
                polygon: points.to_vec()
            }
        );
        let mut before = points.to_vec();
        let mut k = 1;
        for round in 1..=rounds {
            let doubled: Vec<P2> = before.iter().flat_map(|p| [p.clone(), p.clone()]).collect();
            assert_eq!(
                frames[k].step,
                LaneRiesenfeldStep::Doubled {
                    round,
                    polygon: doubled
                }
            );
            k += 1;
            for pass in 1..=degree {
                let LaneRiesenfeldStep::Averaged {
                    round: r,
                    pass: p,
                    polygon,
                } = &frames[k].step
                else {
                    panic!("{:?}", frames[k].step)
                };
                assert_eq!((*r, *p), (round, pass));
                // After j passes, the round so far is the round of degree j (the B-spline of
                // degree j is the box convolved j times) when there are enough vertices.
                if topology == Topology::Closed || before.len() > pass {
                    assert_eq!(
                        polygon,
                        &lane_riesenfeld(&before, pass, 1, topology).unwrap(),
                        "round {round} pass {pass}"
                    );
                }
                // One midpoint per vertex, and an open polygon loses one vertex per pass.
                let previous = polygon_len(&frames[k - 1].step);
                let made = frames[k].counts.arithmetic_operations
                    - frames[k - 1].counts.arithmetic_operations;
                match topology {
                    Topology::Closed => assert_eq!(made as usize, previous),
                    Topology::Open => assert_eq!(made as usize, previous - 1),
                }
                k += 1;
            }
            before = polygon(&frames[k - 1].step);
        }
    }

    fn polygon_len(s: &LaneRiesenfeldStep<Q, 2>) -> usize {
        match s {
            LaneRiesenfeldStep::Input { polygon }
            | LaneRiesenfeldStep::Doubled { polygon, .. }
            | LaneRiesenfeldStep::Averaged { polygon, .. } => polygon.len(),
        }
    }

    fn pts(v: &[(i64, i64)]) -> Vec<P2> {
        v.iter().map(|&(x, y)| Point::new([qi(x), qi(y)])).collect()
    }

    #[test]
    fn lane_riesenfeld_traces_on_small_polygons() {
        let square = pts(&[(0, 0), (4, 0), (4, 4), (0, 4)]);
        check_lane_riesenfeld(&square, 2, 2, Topology::Closed);
        check_lane_riesenfeld(&square, 3, 2, Topology::Open);
        check_lane_riesenfeld(&square, 1, 0, Topology::Open);
        assert!(lane_riesenfeld_trace(&square[..2], 2, 1, Topology::Closed).is_err());
        assert!(lane_riesenfeld_trace(&square, 0, 1, Topology::Closed).is_err());
        // A trace beyond the limit is refused by name: 2^18 points after 16 rounds, and
        // every pass's polygon kept (in f64, for speed).
        let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]].map(Point::new);
        let Err(e) = lane_riesenfeld_trace(&square, 3, 16, Topology::Closed) else {
            panic!("a trace of about 2^21 points was accepted")
        };
        assert!(
            matches!(
                e,
                compgeo::Error::LimitExceeded {
                    limit: "TRACE_MAX_ENTRIES",
                    ..
                }
            ),
            "{e}"
        );
    }

    fn point() -> impl Strategy<Value = P2> {
        ((-20i64..20, 1i64..5), (-20i64..20, 1i64..5))
            .prop_map(|((a, b), (c, d))| Point::new([q(a, b), q(c, d)]))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(40))]

        #[test]
        fn de_casteljau_traces_are_the_bernstein_triangle(
            control in prop::collection::vec(point(), 1..7),
            (a, b) in (-6i64..12, 1i64..7),
        ) {
            check_de_casteljau(control, q(a, b));
        }

        #[test]
        fn lane_riesenfeld_traces_are_rounds_of_lower_degree(
            polygon in prop::collection::vec(point(), 5..8),
            degree in 1usize..5,
            rounds in 0usize..3,
            closed in any::<bool>(),
        ) {
            let topology = if closed { Topology::Closed } else { Topology::Open };
            check_lane_riesenfeld(&polygon, degree, rounds, topology);
        }
    }
}

/// Fortune's sweep, checked event by event against independent oracles (exact rationals):
/// one site frame per distinct site in (y, x) order, one circle frame per triangle of an
/// independent builder's triangulation (every Delaunay triangulation of a point set has
/// the same number of triangles), each new arc under the highest parabola above its site,
/// each vanished arc between the two sites of its triangle, the sweep height monotone and
/// at each circle's top rounded down, each Voronoi vertex within the stated error of the
/// exact circumcentre, and the last frame the result of the counted run.
mod fortune {
    use super::*;
    use crate::common::wide_q;
    use compgeo::delaunay::{fortune, fortune_trace, fortune_with, incremental, FortuneStep};
    use compgeo::geometry::ConstructedPoint;
    use num_rational::BigRational as Q;
    use num_traits::Signed;

    fn q(v: f64) -> Q {
        Q::from_float(v).unwrap()
    }

    /// Centre and squared radius of the circle through the three points.
    fn circle([a, b, c]: [Point2; 3]) -> (Q, Q, Q) {
        let (ax, ay) = (q(a.x), q(a.y));
        let (bx, by) = (q(b.x) - &ax, q(b.y) - &ay);
        let (cx, cy) = (q(c.x) - &ax, q(c.y) - &ay);
        let d = (&bx * &cy - &by * &cx) * Q::from_integer(2.into());
        let (bb, cc) = (&bx * &bx + &by * &by, &cx * &cx + &cy * &cy);
        let ux = (&cy * &bb - &by * &cc) / &d;
        let uy = (&bx * &cc - &cx * &bb) / &d;
        let r2 = &ux * &ux + &uy * &uy;
        (ax + ux, ay + uy, r2)
    }

    /// Whether `y` is at most the top `cy + r` of a circle, exactly.
    fn below_top(y: f64, cy: &Q, r2: &Q) -> bool {
        let up = q(y) - cy; // y <= cy + r  <=>  y − cy <= r
        !up.is_positive() || &up * &up <= *r2
    }

    /// The next double above `y` (finite, below `f64::MAX`).
    fn next_up(y: f64) -> f64 {
        if y == 0.0 {
            f64::from_bits(1)
        } else if y > 0.0 {
            f64::from_bits(y.to_bits() + 1)
        } else {
            f64::from_bits(y.to_bits() - 1)
        }
    }

    /// The height at `x` of the parabola of site `p` under the sweep line `y = line`
    /// (`p.y < line`): `(line + p.y) / 2 − (x − p.x)² / (2 (line − p.y))`.
    fn parabola(p: Point2, line: f64, x: f64) -> Q {
        let two = Q::from_integer(2.into());
        let dx = q(x) - q(p.x);
        (q(line) + q(p.y)) / &two - &dx * &dx / (two * (q(line) - q(p.y)))
    }

    /// `beach` is `before` with `[site, before[k]]` inserted after some arc `k`, whose site
    /// is returned; or with `site` appended (the lowest row, or the first site).
    fn split_arc(before: &[usize], beach: &[usize], site: usize) -> Option<usize> {
        if beach.len() == before.len() + 1 && beach[..before.len()] == *before {
            assert_eq!(beach.last(), Some(&site));
            return None;
        }
        assert_eq!(beach.len(), before.len() + 2, "{before:?} -> {beach:?}");
        let k = (0..before.len())
            .find(|&k| {
                let mut want = before[..=k].to_vec();
                want.extend([site, before[k]]);
                want.extend(&before[k + 1..]);
                want == beach
            })
            .unwrap_or_else(|| panic!("site {site}: {before:?} -> {beach:?}"));
        Some(before[k])
    }

    pub(super) fn check_fortune(pts: &[Point2]) {
        let frames = fortune_trace(pts).unwrap();
        let mut counts = Counts::default();
        let result = fortune_with(&set(pts), &mut counts).unwrap();
        assert_eq!(result, fortune(pts).unwrap());
        let last = frames.last().unwrap();
        assert_eq!(
            last.step,
            FortuneStep::Done {
                triangulation: result.clone()
            }
        );
        assert_eq!(last.counts, counts);
        counts_grow(&frames);
        // The events: the distinct sites in (y, x) order, and a circle per triangle.
        let mut sites = distinct(pts);
        sites.sort_by(|&i, &j| {
            let (a, b) = (pts[i], pts[j]);
            a.y.total_cmp(&b.y).then(a.x.total_cmp(&b.x))
        });
        let triangles = incremental(pts).unwrap().triangle_count();
        assert_eq!(frames.len(), sites.len() + triangles + 1);
        let lowest = sites.first().map(|&i| pts[i].y);
        let (mut beach, mut found): (Vec<usize>, Vec<usize>) = (Vec::new(), Vec::new());
        let mut height = f64::NEG_INFINITY;
        let mut next_site = sites.iter();
        for f in &frames[..frames.len() - 1] {
            match &f.step {
                FortuneStep::Site {
                    site,
                    sweep,
                    beach: after,
                    triangles,
                } => {
                    assert_eq!(Some(site), next_site.next());
                    assert_eq!(*sweep, pts[*site].y);
                    assert_eq!(triangles, &found);
                    let above = split_arc(&beach, after, *site);
                    match above {
                        None => assert!(beach.is_empty() || Some(*sweep) == lowest),
                        Some(a) => {
                            // The split arc is the highest parabola above the site.
                            let s = pts[*site];
                            let top = parabola(pts[a], *sweep, s.x);
                            for &other in beach.iter().filter(|&&o| pts[o].y < *sweep) {
                                assert!(parabola(pts[other], *sweep, s.x) <= top, "{other}");
                            }
                        }
                    }
                    beach.clone_from(after);
                    height = height.max(*sweep);
                    assert_eq!(height, *sweep, "the sweep moves up");
                }
                FortuneStep::Circle {
                    triangle,
                    vertex,
                    sweep,
                    beach: after,
                    triangles,
                } => {
                    let [a, b, c] = triangle.map(|i| pts[i]);
                    assert_eq!(orient2d(a, b, c), Orientation::CounterClockwise);
                    // The middle arc vanished from between its two neighbours.
                    let k = (1..beach.len().saturating_sub(1))
                        .find(|&k| {
                            beach[k - 1..=k + 1] == *triangle && {
                                let mut want = beach.clone();
                                want.remove(k);
                                want == *after
                            }
                        })
                        .unwrap_or_else(|| panic!("{triangle:?}: {beach:?} -> {after:?}"));
                    assert!(k > 0);
                    found.extend(triangle);
                    assert_eq!(triangles, &found);
                    let (cx, cy, r2) = circle([a, b, c]);
                    // The sweep height: the largest double not above the circle's top.
                    assert!(below_top(*sweep, &cy, &r2));
                    assert!(*sweep == f64::MAX || !below_top(next_up(*sweep), &cy, &r2));
                    assert!(*sweep >= height, "the sweep moves up");
                    height = *sweep;
                    // The Voronoi vertex within the stated error of the circumcentre.
                    let [x, y] = vertex.wide().map(wide_q);
                    let tol = cx.abs().max(cy.abs()) * q(ConstructedPoint::RELATIVE_ERROR)
                        + q(f64::from_bits(1)) / Q::from_integer(2.into());
                    assert!(
                        (x - &cx).abs() <= tol && (y - &cy).abs() <= tol,
                        "{vertex:?}"
                    );
                    beach.clone_from(after);
                }
                FortuneStep::Done { .. } => panic!("Done before the end"),
            }
            assert!(beach.iter().all(|&s| pts[s].y <= height));
        }
        assert_eq!(found, result.triangles);
        assert!(next_site.next().is_none());
        // After the last event the beach line holds the sites of the unbounded Voronoi cells
        // (the hull's) clockwise, from the cell below everything: the lowest site's, on both
        // ends, or with a lowest row from its leftmost to its rightmost site. The cells of the
        // row's inner sites are strips open downwards only, which the beach line never meets.
        if triangles > 0 {
            let min_y = sites
                .iter()
                .map(|&i| pts[i].y)
                .fold(f64::INFINITY, f64::min);
            let row: Vec<usize> = sites
                .iter()
                .copied()
                .filter(|&i| pts[i].y == min_y)
                .collect();
            let (first, last) = (row[0], row[row.len() - 1]);
            assert_eq!(
                (beach[0], beach[beach.len() - 1]),
                (first, last),
                "{beach:?}"
            );
            let core = if row.len() == 1 {
                &beach[..beach.len() - 1]
            } else {
                &beach[..]
            };
            let inner = if row.len() > 2 {
                &row[1..row.len() - 1]
            } else {
                &[][..]
            };
            let mut clockwise: Vec<usize> = result.hull.iter().rev().copied().collect();
            clockwise.retain(|i| !inner.contains(i));
            let start = clockwise.iter().position(|&i| i == first).unwrap();
            clockwise.rotate_left(start);
            assert_eq!(core, clockwise, "beach {beach:?}, hull {:?}", result.hull);
        }
    }
}

#[test]
fn fortune_traces_on_small_and_degenerate_inputs() {
    use compgeo::gen::{points, PointKind};
    fortune::check_fortune(&[]);
    fortune::check_fortune(&[Point2::new(1.0, 2.0)]);
    // Duplicates, a collinear row, the lowest row then sites on its breakpoints.
    fortune::check_fortune(&[
        Point2::new(1.0, 1.0),
        Point2::new(1.0, 1.0),
        Point2::new(2.0, 2.0),
        Point2::new(3.0, 3.0),
    ]);
    fortune::check_fortune(&[(0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (2.0, 5.0)].map(Point2::from));
    for (kind, n) in [
        (PointKind::Grid, 25),
        (PointKind::Cocircular, 12),
        (PointKind::Parabola, 20),
        (PointKind::UniformDisk, 40),
        (PointKind::Huge, 15),
    ] {
        fortune::check_fortune(&points(kind, n, 7).unwrap());
    }
}

#[test]
fn fortune_trace_beyond_the_limit_is_refused_by_name() {
    use compgeo::delaunay::fortune_trace;
    let pts = compgeo::gen::points(compgeo::gen::PointKind::UniformSquare, 600, 1).unwrap();
    let e = fortune_trace(&pts).unwrap_err();
    assert!(
        matches!(
            e,
            Error::LimitExceeded {
                limit: "TRACE_MAX_ENTRIES",
                ..
            }
        ),
        "{e}"
    );
    assert!(fortune_trace(&pts[..60]).is_ok());
    let bad = [Point2::new(0.0, 0.0), Point2::new(1.0, f64::INFINITY)];
    assert!(matches!(fortune_trace(&bad), Err(Error::NonFinite { .. })));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn fortune_traces_on_lattices(pts in lattice(-4..=4, 0..18)) {
        fortune::check_fortune(&pts);
    }

    #[test]
    fn fortune_traces_on_uniform_points(pts in uniform(100.0, 3..25)) {
        fortune::check_fortune(&pts);
    }
}
