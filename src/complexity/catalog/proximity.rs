//! Catalog entries of the Voronoi diagram ([`crate::delaunay`]) and the proximity problems
//! ([`crate::proximity`]): all nearest neighbours, the closest pair (via Delaunay and by
//! divide and conquer), the Euclidean minimum spanning tree and the largest empty circle.
//!
//! The algorithms built on the triangulation are measured on its in-circle tests (their
//! dominant cost) or, where their own work is the point, on the operation they add:
//! distance evaluations for the spanning tree's exact length sort, orientation tests for
//! the empty circle's hull tests. The divide and conquer is measured on distance
//! evaluations (strip tests and candidate pairs), on uniform points and on a grid where
//! every distance ties.
//!
//! The exact Delaunay checker is measured on a triangulation built while preparing: one
//! in-circle test per interior edge, Θ(n). Nearest-point queries walk the Delaunay graph
//! (built while preparing, with its grid of entry vertices) greedily from the entry of the
//! query's cell, about six distance evaluations per step, in each of their two sizes: 64
//! queries uniform in the unit square against n uniform sites, where a walk takes O(1)
//! expected steps whatever n (`uniform-square`, O(1)), and n such queries against 1024
//! sites (`random-queries`, Θ(n)).

use std::rc::Rc;

use super::claimed_entries;
use crate::complexity::{Declaration, Entry, Workload};
use crate::count::{Counter, NoCount};
use crate::delaunay::{check_delaunay_with, incremental_with, voronoi_with, Triangulation};
use crate::error::{Error, Result};
use crate::gen::{points, PointKind};
use crate::geometry::{Point2, PointSet};
use crate::proximity::{
    all_nearest_neighbours_with, closest_pair_with, euclidean_mst_with, largest_empty_circle_with,
    ClosestPairAlgorithm, DelaunayGraph,
};

/// The sites of the `random-queries` entry.
const QUERY_SITES: usize = 1024;
/// The queries of the `uniform-square` entry.
const QUERIES: usize = 64;

/// The problems measured here.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Problem {
    Voronoi,
    AllNearest,
    ClosestPair(ClosestPairAlgorithm),
    Emst,
    EmptyCircle,
}

/// One proximity algorithm on one kind of generated point set.
struct Proximity {
    problem: Problem,
    kind: PointKind,
}

/// The proximity entries: every claim of the Voronoi diagram and the proximity problems,
/// each on its input.
pub(super) fn entries() -> Vec<Entry> {
    let mut problems: Vec<(Problem, &'static Declaration)> = vec![
        (Problem::Voronoi, crate::delaunay::VORONOI),
        (Problem::AllNearest, crate::proximity::ALL_NEAREST),
    ];
    for a in ClosestPairAlgorithm::ALL {
        problems.push((Problem::ClosestPair(a), a.declaration()));
    }
    problems.push((Problem::Emst, crate::proximity::EMST));
    problems.push((Problem::EmptyCircle, crate::proximity::EMPTY_CIRCLE));
    let mut out = Vec::new();
    for (problem, declaration) in problems {
        for (_, entry) in claimed_entries(declaration, |kind| Proximity { problem, kind }) {
            out.push(entry.quick(256, 1 << 14).full(256, 1 << 19));
        }
    }
    out.push(
        Entry::declared(crate::delaunay::CHECK, "uniform-disk", Check)
            .quick(256, 1 << 13)
            .full(256, 1 << 19),
    );
    out.push(
        Entry::declared(crate::proximity::NEAREST, "uniform-square", Nearest::Sites)
            .quick(256, 1 << 14)
            .full(256, 1 << 20),
    );
    out.push(
        Entry::declared(
            crate::proximity::NEAREST,
            "random-queries",
            Nearest::Queries,
        )
        .quick(64, 1 << 12)
        .full(64, 1 << 16),
    );
    out
}

/// The exact Delaunay checker on the triangulation of n uniform points in the disk.
struct Check;

impl Workload for Check {
    type Input = (Vec<Point2>, Triangulation);
    type Output = ();

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = points(PointKind::UniformDisk, n, seed)?;
        let t = incremental_with(&PointSet::new(&pts)?, &mut NoCount)?;
        Ok((pts, t))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, counter: &mut C) -> Result<()> {
        let (pts, t) = input;
        check_delaunay_with(pts, t, counter).map_err(|v| Error::InvalidParameter {
            name: "triangulation",
            reason: v.to_string(),
        })
    }
}

/// Nearest-point queries by the greedy walk on the Delaunay graph, in one of their sizes.
#[derive(Debug, Clone, Copy)]
enum Nearest {
    /// [`QUERIES`] queries against n sites.
    Sites,
    /// n queries against [`QUERY_SITES`] sites.
    Queries,
}

impl Workload for Nearest {
    /// The sites' Delaunay graph and the queries; shared, since no run changes them.
    type Input = Rc<(DelaunayGraph, Vec<Point2>)>;
    /// The sum of the answers.
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let (sites, queries) = match self {
            Nearest::Sites => (n, QUERIES),
            Nearest::Queries => (QUERY_SITES, n),
        };
        let pts = points(PointKind::UniformSquare, sites, seed)?;
        let set = PointSet::new(&pts)?;
        let graph = DelaunayGraph::new(&pts, &incremental_with(&set, &mut NoCount)?);
        let queries = points(PointKind::UniformSquare, queries, seed ^ 1)?;
        Ok(Rc::new((graph, queries)))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, counter: &mut C) -> Result<usize> {
        let (graph, queries) = &**input;
        let mut sum = 0;
        for &q in queries {
            sum += graph.walk(q, None, counter)?;
        }
        Ok(sum)
    }
}

impl Workload for Proximity {
    type Input = Vec<Point2>;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Point2>> {
        points(self.kind, n, seed)
    }

    /// Runs the algorithm and returns the size of its answer, so nothing is optimised away.
    fn run<C: Counter>(&self, pts: &mut Vec<Point2>, counter: &mut C) -> Result<usize> {
        let set = PointSet::new(pts)?;
        Ok(match self.problem {
            Problem::Voronoi => voronoi_with(&set, counter)?.cell_count(),
            Problem::AllNearest => all_nearest_neighbours_with(&set, counter)?.len(),
            Problem::ClosestPair(a) => closest_pair_with(&set, a, counter)?.pair[1],
            Problem::Emst => euclidean_mst_with(&set, counter)?.edges.len(),
            Problem::EmptyCircle => largest_empty_circle_with(&set, counter)?.sites.len(),
        })
    }
}
