//! A piecewise surface made of Bézier patches over the cells of a rectangular grid: the
//! Bézier form of a B-spline surface (`bspline_to_bezier.rs`) and of the piecewise bicubic
//! interpolant (`bicubic.rs`).
//!
//! Patch (a, b) describes the surface over [u_a, u_{a+1}] × [v_b, v_{b+1}] in the local
//! parameters s = (u − u_a)/(u_{a+1} − u_a) and t = (v − v_b)/(v_{b+1} − v_b) in [0, 1], as
//! a [`CompositeBezier`](crate::spline::CompositeBezier) curve's pieces do in one parameter
//! [PPB, §9.2]; by the chain rule a derivative of orders (r, s) is the patch's divided by
//! Δu_a^r·Δv_b^s.
//!
//! # Complexity
//!
//! Locating a parameter pair takes O(log P + log Q) exact comparisons for P × Q cells, then
//! the patch's own evaluation.

use super::bezier::BezierPatch;
use super::traits::{Surface, SurfaceDerivative, SurfaceDomain};
use crate::spline::interpolate::check_partition;
use crate::spline::{Domain, Point, Scalar};
use crate::{Error, Result};

/// Bézier patches over the cells of the grid u₀ < … < u_P by v₀ < … < v_Q.
///
/// ```
/// use compgeo::spline::Point;
/// use compgeo::surface::{BezierPatch, BezierPatchGrid, ControlNet, Surface};
///
/// // One bilinear patch of z = uv over [0, 2] × [0, 1].
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let patch = BezierPatch::new(ControlNet::new(vec![
///     vec![p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
///     vec![p(2.0, 0.0, 0.0), p(2.0, 1.0, 2.0)],
/// ])?)?;
/// let g = BezierPatchGrid::new(vec![0.0, 2.0], vec![0.0, 1.0], vec![vec![patch]])?;
/// assert_eq!(g.eval(&1.0, &0.5)?, p(1.0, 0.5, 0.5));
/// assert!(g.eval(&3.0, &0.5).is_err());
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct BezierPatchGrid<S, const D: usize> {
    u_partition: Vec<S>,
    v_partition: Vec<S>,
    /// Row a holds the patches over [u_a, u_{a+1}], by increasing v.
    patches: Vec<Vec<BezierPatch<S, D>>>,
}

impl<S: Scalar, const D: usize> BezierPatchGrid<S, D> {
    /// The grid of `patches[a][b]` over [u_a, u_{a+1}] × [v_b, v_{b+1}].
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] named `"u partition"` or `"v partition"` for fewer than
    /// two values, a non-finite value or one not above its predecessor;
    /// [`Error::InvalidParameter`] named `"patches"` if there are not P rows of Q patches.
    ///
    /// # Complexity
    ///
    /// Θ(P + Q) time beyond the moves.
    pub fn new(
        u_partition: Vec<S>,
        v_partition: Vec<S>,
        patches: Vec<Vec<BezierPatch<S, D>>>,
    ) -> Result<Self> {
        check_partition(&u_partition, 2, "u partition")?;
        check_partition(&v_partition, 2, "v partition")?;
        let (p, q) = (u_partition.len() - 1, v_partition.len() - 1);
        if patches.len() != p || patches.iter().any(|row| row.len() != q) {
            return Err(Error::InvalidParameter {
                name: "patches",
                reason: format!("a grid of {p} × {q} cells needs {p} rows of {q} patches"),
            });
        }
        Ok(BezierPatchGrid {
            u_partition,
            v_partition,
            patches,
        })
    }

    /// u₀ < … < u_P.
    pub fn u_partition(&self) -> &[S] {
        &self.u_partition
    }

    /// v₀ < … < v_Q.
    pub fn v_partition(&self) -> &[S] {
        &self.v_partition
    }

    /// The patches, row a over [u_a, u_{a+1}].
    pub fn patches(&self) -> &[Vec<BezierPatch<S, D>>] {
        &self.patches
    }

    /// The patch over [u_a, u_{a+1}] × [v_b, v_{b+1}].
    ///
    /// # Panics
    ///
    /// If a ≥ P or b ≥ Q.
    pub fn patch(&self, a: usize, b: usize) -> &BezierPatch<S, D> {
        &self.patches[a][b]
    }

    /// The cell of (u, v) (the last cell's closed ends included) and the local parameters.
    fn locate(&self, u: &S, v: &S) -> Result<(usize, usize, S, S)> {
        self.domain().check(u, v)?;
        let (a, s) = local(&self.u_partition, u);
        let (b, t) = local(&self.v_partition, v);
        Ok((a, b, s, t))
    }
}

/// The interval index of `x` in a partition (right-continuous, the last one closed) and the
/// local parameter there.
fn local<S: Scalar>(partition: &[S], x: &S) -> (usize, S) {
    let cells = partition.len() - 1;
    let i = partition[1..cells].partition_point(|k| k <= x);
    let h = partition[i + 1].clone() - &partition[i];
    (i, (x.clone() - &partition[i]) / &h)
}

/// Defined on [u₀, u_P] × [v₀, v_Q].
impl<S: Scalar, const D: usize> Surface<S, D> for BezierPatchGrid<S, D> {
    fn domain(&self) -> SurfaceDomain<S> {
        let interval = |p: &[S]| Domain::Interval {
            start: p[0].clone(),
            end: p[p.len() - 1].clone(),
        };
        SurfaceDomain {
            u: interval(&self.u_partition),
            v: interval(&self.v_partition),
        }
    }

    fn eval(&self, u: &S, v: &S) -> Result<Point<S, D>> {
        let (a, b, s, t) = self.locate(u, v)?;
        self.patches[a][b].eval(&s, &t)
    }
}

/// The patch's derivative in the local parameters over Δu^r·Δv^s (the chain rule); from the
/// right at an inner grid line, from the left at the far ends.
impl<S: Scalar, const D: usize> SurfaceDerivative<S, D> for BezierPatchGrid<S, D> {
    fn partial_at(&self, u: &S, v: &S, r: usize, s: usize) -> Result<Point<S, D>> {
        let (a, b, x, y) = self.locate(u, v)?;
        let mut d = self.patches[a][b].partial_at(&x, &y, r, s)?;
        let hu = self.u_partition[a + 1].clone() - &self.u_partition[a];
        let hv = self.v_partition[b + 1].clone() - &self.v_partition[b];
        for _ in 0..r {
            d = d / &hu;
        }
        for _ in 0..s {
            d = d / &hv;
        }
        if d.is_finite() {
            Ok(d)
        } else {
            Err(Error::Overflow {
                what: "Bézier patch grid derivative",
            })
        }
    }
}
