//! Catalog entries of [`crate::spline::subdivision`]: k = 3 rounds of the Lane–Riesenfeld
//! algorithm of degree 3, of the four-point scheme (w = 1/16) and of the cubic B-spline's
//! mask on a closed polygon of n random vertices (`random-closed`), and the cubic limit
//! points of such a polygon. A round is linear in the polygon and k rounds give n·2^k
//! vertices, so for a fixed k every count is linear in n: 2·3·n·(2^3 − 1) midpoints,
//! n·(2^3 − 1) inserted points, 5·n·(2^3 − 1) mask terms, 3n stencil terms.
//!
//! `random-mask`: the difference scheme of a mask of n + 1 coefficients, (1 + z) times n
//! random integers (integers, so that α(−1) = 0 holds exactly in `f64`); n + 1 operations.

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::subdivision::{
    four_point_with, lane_riesenfeld_with, limit_points_with, Mask, Topology,
};
use crate::spline::Point;

/// The rounds every polygon entry runs.
const ROUNDS: usize = 3;

/// The degree of the Lane–Riesenfeld entries.
const DEGREE: usize = 3;

/// Which algorithm runs on the random closed polygon.
#[derive(Clone, Copy, Debug)]
enum Scheme {
    LaneRiesenfeld,
    FourPoint,
    Mask,
    Limit,
}

/// One algorithm on a random closed polygon of n vertices.
struct Subdivide(Scheme);

/// The difference scheme of a random mask.
struct Difference;

/// The subdivision entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::spline::subdivision::declarations as s;
    let entry = |declaration: &'static Declaration, scheme: Scheme| {
        Entry::declared(declaration, "random-closed", Subdivide(scheme))
            .quick(64, 1 << 12)
            .full(64, 1 << 16)
    };
    vec![
        entry(&s::LANE_RIESENFELD, Scheme::LaneRiesenfeld),
        entry(&s::FOUR_POINT, Scheme::FourPoint),
        entry(&s::REFINE, Scheme::Mask),
        entry(&s::LIMIT_POINTS, Scheme::Limit),
        Entry::declared(&s::DIFFERENCE, "random-mask", Difference)
            .quick(256, 1 << 14)
            .full(256, 1 << 18),
    ]
}

impl Workload for Subdivide {
    type Input = (Vec<Point<f64, 2>>, Mask<f64>);
    type Output = Vec<Point<f64, 2>>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let polygon = points(PointKind::UniformSquare, n, seed)?
            .into_iter()
            .map(Point::from)
            .collect();
        Ok((polygon, Mask::lane_riesenfeld(DEGREE)?))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (polygon, mask) = input;
        let closed = Topology::Closed;
        match self.0 {
            Scheme::LaneRiesenfeld => lane_riesenfeld_with(polygon, DEGREE, ROUNDS, closed, c),
            Scheme::FourPoint => four_point_with(polygon, &0.0625, ROUNDS, closed, c),
            Scheme::Mask => mask.refine_with(polygon, closed, ROUNDS, c),
            Scheme::Limit => limit_points_with(polygon, DEGREE, closed, c),
        }
    }
}

impl Workload for Difference {
    type Input = Mask<f64>;
    type Output = Mask<f64>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        // β: n integers in [0, 1024); α = (1 + z)β, exact in f64.
        let beta: Vec<f64> = points(PointKind::UniformSquare, n, seed)?
            .iter()
            .map(|p| (p.x * 1024.0).floor() + 1.0)
            .collect();
        let mut alpha = vec![0.0; n + 1];
        for (k, b) in beta.iter().enumerate() {
            alpha[k] += b;
            alpha[k + 1] += b;
        }
        Mask::new(0, alpha)
    }

    fn run<C: Counter>(&self, mask: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        mask.difference_with(c)
    }
}
