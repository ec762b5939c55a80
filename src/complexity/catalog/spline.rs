//! Catalog entries of [`crate::spline`]: one evaluation of a Bézier curve of degree n by each
//! scheme of [`Evaluation`] (de Casteljau's algorithm, n(n + 1)/2 affine combinations, Θ(n²);
//! the Horner-type scheme of [PPB, §2.3, Obs. 4], n + 1 point operations, Θ(n)); C² cubic
//! spline interpolation of n points (natural and periodic end conditions, Θ(n) by a
//! tridiagonal solve, [SPL, §3]).
//!
//! The Bézier operations besides evaluation, each in its sizes (`random-degree`: n is the
//! degree of a curve with control points uniform in the unit square):
//!
//! - the split at a random c and the blossom at n random arguments: one de Casteljau
//!   triangle, n(n + 1)/2 affine combinations, Θ(n²);
//! - elevation by Zhou's formula, (n + 1)(m − n + 1) terms: from degree n to 2n, Θ(n²)
//!   (`random-degree`), and from degree 3 to n, Θ(n) (`random-target`);
//! - flattening and the intersection search on the parabola y = 2t(1 − t) written with
//!   degree n (its elevated control points), whose flatness bound is ½ at every degree and
//!   exactly a quarter of that after each halving, so the recursion is the same at every n:
//!   four segments (three splits of n(n + 1)/2) at degree n and tolerance 3/64
//!   (`parabola-degree`, Θ(n²)), or n segments of the cubic at tolerance 3/(4n²)
//!   (`parabola-segments`, n − 1 splits, Θ(n));
//!   the crossings with the line y = ¼ at tolerance 10⁻³ and degree n (`parabola-degree`,
//!   Θ(n²)), or at degree 3 and tolerance 1/n, where the search descends
//!   d = log₄(n/2) levels towards each of the two crossings (`parabola-tolerance`, Θ(log n)).
//!
//! The Frenet frame is measured in the dimension D = n of the space with r = D random
//! derivatives (`random-dimension`, n = 2, 4, …, 64): r(r − 1) projections and the
//! orientation's elimination, Θ(n³).
//!
//! The counted operation is the arithmetic step on points
//! ([`Operation::ArithmeticOperations`]). Control points are uniform in the unit square and
//! the parameter is drawn from [0, 1) with the same seed. Degrees stay at most 512: beyond
//! about 1020 the binomial coefficients of Horner's scheme overflow `f64`.

use crate::complexity::{Entry, Workload};
use crate::count::Counter;
use crate::error::Result;
use crate::gen::{points, PointKind};
use crate::spline::bezier::{evaluate_with, Evaluation};
use crate::spline::{
    cubic_spline_tangents_with, frenet_frame_with, intersections_with, Bezier, EndCondition, Point,
};

/// One evaluation of a random curve of degree n at a random parameter.
struct Evaluate(Evaluation);

/// The spline entries: every claim of the Bézier evaluation schemes and the cubic splines.
pub(super) fn entries() -> Vec<Entry> {
    let mut entries: Vec<Entry> = Evaluation::ALL
        .into_iter()
        .map(|scheme| {
            Entry::declared(
                scheme.declaration(),
                PointKind::UniformSquare.name(),
                Evaluate(scheme),
            )
            .quick(8, 256)
            .full(8, 512)
        })
        .collect();
    let cubic = [
        (crate::spline::interpolate::CUBIC_NATURAL, false),
        (crate::spline::interpolate::CUBIC_PERIODIC, true),
    ];
    for (declaration, periodic) in cubic {
        entries.push(
            Entry::declared(
                declaration,
                PointKind::UniformSquare.name(),
                Interpolate { periodic },
            )
            .quick(64, 1 << 12)
            .full(64, 1 << 16),
        );
    }
    use crate::spline::bezier::declarations as b;
    let bezier = |d: &'static crate::complexity::Declaration, input: &str, run: Run| {
        Entry::declared(d, input, Operations(run))
    };
    entries.extend([
        bezier(&b::SPLIT, "random-degree", Run::Split)
            .quick(8, 256)
            .full(8, 1024),
        bezier(&b::BLOSSOM, "random-degree", Run::Blossom)
            .quick(8, 256)
            .full(8, 1024),
        bezier(&b::ELEVATE_TO, "random-degree", Run::ElevateDegree)
            .quick(8, 256)
            .full(8, 2048),
        bezier(&b::ELEVATE_TO, "random-target", Run::ElevateTarget)
            .quick(64, 1 << 12)
            .full(64, 1 << 16),
        bezier(&b::FLATTEN, "parabola-degree", Run::FlattenDegree)
            .quick(8, 256)
            .full(8, 1024),
        bezier(&b::FLATTEN, "parabola-segments", Run::FlattenSegments)
            .quick(16, 1 << 10)
            .full(16, 1 << 14),
        bezier(&b::INTERSECTIONS, "parabola-degree", Run::IntersectDegree)
            .quick(4, 128)
            .full(4, 512),
        bezier(
            &b::INTERSECTIONS,
            "parabola-tolerance",
            Run::IntersectTolerance,
        )
        .quick(16, 1 << 12)
        .full(16, 1 << 20),
    ]);
    entries.push(
        Entry::declared(crate::spline::FRENET, "random-dimension", Frenet)
            .quick(2, 32)
            .full(2, 64),
    );
    entries
}

/// The Frenet frame from n random derivatives in R^n, for n a power of two up to 64 (the
/// dimension is a type parameter: each size is its own instance).
struct Frenet;

impl Workload for Frenet {
    /// The derivatives, as rows of n coordinates.
    type Input = Vec<Vec<f64>>;
    /// The first curvature's bits.
    type Output = u64;

    fn prepare(&self, n: usize, seed: u64) -> Result<Vec<Vec<f64>>> {
        let coords: Vec<f64> = points(PointKind::UniformSquare, n * n / 2 + 1, seed)?
            .into_iter()
            .flat_map(|p| [p.x - 0.5, p.y - 0.5])
            .collect();
        Ok(coords.chunks(n).take(n).map(<[f64]>::to_vec).collect())
    }

    fn run<C: Counter>(&self, rows: &mut Vec<Vec<f64>>, c: &mut C) -> Result<u64> {
        fn frame<const D: usize, C: Counter>(rows: &[Vec<f64>], c: &mut C) -> Result<u64> {
            let derivatives: Vec<Point<f64, D>> = rows
                .iter()
                .map(|r| Point::new(std::array::from_fn(|i| r[i])))
                .collect();
            Ok(frenet_frame_with(&derivatives, c)?.curvature().to_bits())
        }
        match rows.len() {
            2 => frame::<2, C>(rows, c),
            4 => frame::<4, C>(rows, c),
            8 => frame::<8, C>(rows, c),
            16 => frame::<16, C>(rows, c),
            32 => frame::<32, C>(rows, c),
            64 => frame::<64, C>(rows, c),
            n => Err(crate::Error::InvalidParameter {
                name: "dimension",
                reason: format!("the Frenet workload has no instance for dimension {n}"),
            }),
        }
    }
}

/// The Bézier operations measured besides evaluation (see the module docs for the sizes).
#[derive(Debug, Clone, Copy)]
enum Run {
    Split,
    Blossom,
    ElevateDegree,
    ElevateTarget,
    FlattenDegree,
    FlattenSegments,
    IntersectDegree,
    IntersectTolerance,
}

/// One Bézier operation on its input of size n.
struct Operations(Run);

/// The parabola y = 2t(1 − t), x = t, as a curve of degree `n ≥ 2`: its elevated control
/// points `(i/n, 2i(n − i)/(n(n − 1)))`.
fn parabola(n: usize) -> Result<Bezier<f64, 2>> {
    let den = (n * (n - 1)) as f64;
    Bezier::new(
        (0..=n)
            .map(|i| Point::new([i as f64 / n as f64, (2 * i * (n - i)) as f64 / den]))
            .collect(),
    )
}

/// The prepared input: a curve, the parameters a run needs (a split point, the blossom's
/// arguments, a tolerance) and a second curve or a target degree.
#[derive(Clone)]
struct Curves {
    curve: Bezier<f64, 2>,
    params: Vec<f64>,
    other: Option<Bezier<f64, 2>>,
    target: usize,
}

impl Workload for Operations {
    type Input = Curves;
    type Output = usize;

    fn prepare(&self, n: usize, seed: u64) -> Result<Curves> {
        let random = |degree: usize| -> Result<(Bezier<f64, 2>, Vec<f64>)> {
            let pts = points(PointKind::UniformSquare, degree + 1, seed)?;
            let params = pts.iter().take(degree).map(|p| p.x).collect();
            Ok((
                Bezier::new(pts.into_iter().map(Point::from).collect())?,
                params,
            ))
        };
        let line = Bezier::new(vec![Point::new([-0.25, 0.25]), Point::new([1.25, 0.25])])?;
        let (curve, params, other, target) = match self.0 {
            Run::Split | Run::Blossom => {
                let (curve, params) = random(n)?;
                (curve, params, None, 0)
            }
            Run::ElevateDegree => (random(n)?.0, Vec::new(), None, 2 * n),
            Run::ElevateTarget => (random(3)?.0, Vec::new(), None, n),
            // The flatness bound after k halvings is ½·4⁻ᵏ: a tolerance 1.5 times that bound
            // for k = 2 (or k = lg n) stops the recursion at exactly that depth.
            Run::FlattenDegree => (parabola(n)?, vec![0.75 / 16.0], None, 0),
            Run::FlattenSegments => (parabola(3)?, vec![0.75 / (n * n) as f64], None, 0),
            Run::IntersectDegree => (parabola(n)?, vec![1e-3], Some(line), 0),
            Run::IntersectTolerance => (parabola(3)?, vec![1.0 / n as f64], Some(line), 0),
        };
        Ok(Curves {
            curve,
            params,
            other,
            target,
        })
    }

    fn run<C: Counter>(&self, input: &mut Curves, c: &mut C) -> Result<usize> {
        let Curves {
            curve,
            params,
            other,
            target,
        } = input;
        // A small summary of each result keeps the optimiser from dropping the work.
        Ok(match self.0 {
            Run::Split => curve.split_with(&params[0], c)?.1.control().len(),
            Run::Blossom => curve.blossom_with(params, c)?.coords()[0].to_bits() as usize,
            Run::ElevateDegree | Run::ElevateTarget => {
                curve.elevate_to_with(*target, c)?.control().len()
            }
            Run::FlattenDegree | Run::FlattenSegments => curve.flatten_with(&params[0], c)?.len(),
            Run::IntersectDegree | Run::IntersectTolerance => match other {
                Some(line) => intersections_with(curve, line, params[0], c)?.len(),
                None => 0,
            },
        })
    }
}

/// The tangents of the C² cubic spline through n random points at the knots 0, 1, ..., n − 1
/// (a periodic spline repeats the first point at the end).
struct Interpolate {
    periodic: bool,
}

impl Workload for Interpolate {
    type Input = (Vec<f64>, Vec<Point<f64, 2>>);
    type Output = Vec<Point<f64, 2>>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let mut pts: Vec<Point<f64, 2>> = points(PointKind::UniformSquare, n, seed)?
            .into_iter()
            .map(Point::from)
            .collect();
        if self.periodic {
            if let Some(&first) = pts.first() {
                pts.push(first);
            }
        }
        let knots = (0..pts.len()).map(|i| i as f64).collect();
        Ok((knots, pts))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (knots, pts) = input;
        let end = if self.periodic {
            EndCondition::Periodic
        } else {
            EndCondition::Natural
        };
        cubic_spline_tangents_with(knots, pts, &end, c)
    }
}

impl Workload for Evaluate {
    type Input = (Bezier<f64, 2>, f64);
    type Output = Point<f64, 2>;

    fn prepare(&self, n: usize, seed: u64) -> Result<Self::Input> {
        let pts = points(PointKind::UniformSquare, n + 1, seed)?;
        // The first generated coordinate is uniform in [0, 1): a parameter inside the segment.
        let t = pts[0].x;
        let curve = Bezier::new(pts.into_iter().map(Point::from).collect())?;
        Ok((curve, t))
    }

    fn run<C: Counter>(&self, input: &mut Self::Input, c: &mut C) -> Result<Self::Output> {
        let (curve, t) = input;
        evaluate_with(curve, t, self.0, c)
    }
}
