//! Catalog entries of [`crate::spline::interpolate`]: every interpolation and fitting
//! algorithm, on the arithmetic it counts ([`Operation::ArithmeticOperations`], steps on
//! points and the elimination's entries) or, for building the Lagrange form, on the
//! comparisons of its distinctness check.
//!
//! - `random-nodes`: n nodes equally spaced over [−1, 1] in random order, values uniform in
//!   the unit square. The Vandermonde solves grow as n³ (Gaussian elimination; the confluent
//!   one with n conditions, a value and a slope at each of n/2 nodes), Newton's divided
//!   differences and Aitken's scheme (at a random u) as n², the Lagrange form's check as
//!   n log n (a sort of the nodes: in random order, so the sort has work to do). Equal
//!   spacing keeps the divided differences (about nʲ/j! for the j-th) finite up to n = 512.
//! - `random-points`: n points uniform in the unit square at the knots 0, 1, …, n − 1 (with
//!   random tangents for Hermite's pieces): the Hermite, quadratic and cubic splines are
//!   linear; so is the least-squares fit of n points by a quintic.
//! - `random-degree`: the least-squares fit of 2(n + 1) points by a curve of degree n,
//!   Θ(m·n² + n³) = Θ(n³).
//!
//! [`Operation::ArithmeticOperations`]: crate::count::Operation::ArithmeticOperations

use crate::complexity::{Declaration, Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind, Rng};
use crate::spline::{
    closed_quadratic_spline_with, cubic_spline_with, fit_bezier_with, hermite_with, lagrange_with,
    newton_hermite_with, newton_with, quadratic_spline_with, vandermonde_hermite_with,
    vandermonde_with, EndCondition, FitOptions, HermiteNode, LagrangeForm, Point,
};

/// The degree of the `random-points` fit.
const FIT_DEGREE: usize = 5;

/// Which algorithm a workload runs.
#[derive(Debug, Clone, Copy)]
enum Run {
    Vandermonde,
    VandermondeHermite,
    Lagrange,
    Aitken,
    Newton,
    NewtonHermite,
    Hermite,
    Quadratic,
    ClosedQuadratic,
    Cubic,
    FitPoints,
    FitDegree,
}

/// One interpolation algorithm on its input of size n.
struct Interpolation(Run);

/// The prepared input: nodes (or knots, or fitting parameters), the points, and the tangents
/// or the Lagrange form some runs need.
#[derive(Clone)]
struct Data {
    nodes: Vec<f64>,
    points: Vec<Point<f64, 2>>,
    tangents: Vec<Point<f64, 2>>,
    form: Option<LagrangeForm<f64, 2>>,
    u: f64,
}

/// The interpolation entries.
pub(super) fn entries() -> Vec<Entry> {
    use crate::spline::interpolate::declarations as d;
    let entry = |declaration: &'static Declaration, input: &str, run: Run| {
        let e = Entry::declared(declaration, input, Interpolation(run));
        match run {
            Run::Vandermonde | Run::VandermondeHermite | Run::FitDegree => {
                e.quick(8, 128).full(8, 256)
            }
            Run::Newton | Run::NewtonHermite | Run::Aitken => e.quick(16, 256).full(16, 512),
            _ => e.quick(64, 1 << 12).full(64, 1 << 16),
        }
    };
    vec![
        entry(&d::VANDERMONDE, "random-nodes", Run::Vandermonde),
        entry(
            &d::VANDERMONDE_HERMITE,
            "random-nodes",
            Run::VandermondeHermite,
        ),
        entry(&d::LAGRANGE, "random-nodes", Run::Lagrange),
        entry(&d::AITKEN, "random-nodes", Run::Aitken),
        entry(&d::NEWTON, "random-nodes", Run::Newton),
        entry(&d::NEWTON_HERMITE, "random-nodes", Run::NewtonHermite),
        entry(&d::HERMITE, "random-points", Run::Hermite),
        entry(&d::QUADRATIC, "random-points", Run::Quadratic),
        entry(&d::CLOSED_QUADRATIC, "random-points", Run::ClosedQuadratic),
        entry(&d::CUBIC, "random-points", Run::Cubic),
        entry(&d::LEAST_SQUARES, "random-points", Run::FitPoints),
        entry(&d::LEAST_SQUARES, "random-degree", Run::FitDegree),
    ]
}

/// `n` points uniform in the unit square.
fn uniform(n: usize, seed: u64) -> Result<Vec<Point<f64, 2>>> {
    Ok(points(PointKind::UniformSquare, n, seed)?
        .into_iter()
        .map(Point::from)
        .collect())
}

impl Workload for Interpolation {
    type Input = Data;
    /// The size of the result, so nothing is optimised away.
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Data> {
        let mut rng = Rng::new(seed ^ 0x5eed);
        let (nodes, count) = match self.0 {
            Run::Vandermonde
            | Run::VandermondeHermite
            | Run::Lagrange
            | Run::Aitken
            | Run::Newton
            | Run::NewtonHermite => {
                // n/2 nodes with a value and a slope each for the confluent runs.
                let k = match self.0 {
                    Run::VandermondeHermite | Run::NewtonHermite => n / 2,
                    _ => n,
                };
                let mut nodes: Vec<f64> = (0..k)
                    .map(|i| -1.0 + 2.0 * i as f64 / (k - 1) as f64)
                    .collect();
                rng.shuffle(&mut nodes);
                (nodes, k)
            }
            Run::ClosedQuadratic => {
                // An odd number of pieces, n + 1, and the first point repeated at the end.
                ((0..n + 2).map(|i| i as f64).collect(), n + 2)
            }
            Run::FitPoints | Run::FitDegree => {
                let m = match self.0 {
                    Run::FitDegree => 2 * (n + 1),
                    _ => n,
                };
                ((0..m).map(|i| i as f64 / (m - 1) as f64).collect(), m)
            }
            _ => ((0..n).map(|i| i as f64).collect(), n),
        };
        let mut pts = uniform(count, seed)?;
        if let Run::ClosedQuadratic = self.0 {
            pts[count - 1] = pts[0];
        }
        let tangents = uniform(count, seed ^ 1)?;
        let form = match self.0 {
            Run::Aitken => Some(crate::spline::lagrange(&nodes, &pts)?),
            _ => None,
        };
        let u = 2.0 * rng.unit() - 1.0;
        Ok(Data {
            nodes,
            points: pts,
            tangents,
            form,
            u,
        })
    }

    fn run<C: Counter>(&self, data: &mut Data, c: &mut C) -> Result<usize> {
        let Data {
            nodes,
            points,
            tangents,
            form,
            u,
        } = data;
        let confluent = || -> Vec<HermiteNode<f64, 2>> {
            nodes
                .iter()
                .zip(points.iter().zip(tangents.iter()))
                .map(|(&u, (&p, &t))| HermiteNode {
                    u,
                    values: vec![p, t],
                })
                .collect()
        };
        Ok(match self.0 {
            Run::Vandermonde => vandermonde_with(nodes, points, c)?.coefficients().len(),
            Run::VandermondeHermite => vandermonde_hermite_with(&confluent(), c)?
                .coefficients()
                .len(),
            Run::Lagrange => lagrange_with(nodes, points, c)?.nodes().len(),
            Run::Aitken => match form {
                Some(f) => f.aitken_with(u, c)?.coords()[0].to_bits() as usize,
                None => 0,
            },
            Run::Newton => newton_with(nodes, points, c)?.coefficients().len(),
            Run::NewtonHermite => newton_hermite_with(&confluent(), c)?.coefficients().len(),
            Run::Hermite => hermite_with(nodes, points, tangents, c)?.pieces().len(),
            Run::Quadratic => quadratic_spline_with(nodes, points, &tangents[0], c)?
                .pieces()
                .len(),
            Run::ClosedQuadratic => closed_quadratic_spline_with(nodes, points, c)?
                .pieces()
                .len(),
            Run::Cubic => cubic_spline_with(nodes, points, &EndCondition::Natural, c)?
                .pieces()
                .len(),
            Run::FitPoints => {
                fit_bezier_with(nodes, points, FIT_DEGREE, &FitOptions::default(), c)?
                    .control()
                    .len()
            }
            Run::FitDegree => {
                let degree = points.len() / 2 - 1;
                fit_bezier_with(nodes, points, degree, &FitOptions::default(), c)?
                    .control()
                    .len()
            }
        })
    }
}
