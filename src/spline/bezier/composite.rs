//! Composite Bézier curves: Bézier pieces over a partition `u_0 < u_1 < ... < u_m`, their
//! evaluation, derivatives and subsegments in the global parameter. The join checks and the
//! Cʳ builders are in `joins.rs`.
//!
//! The problem: one curve made of several polynomial pieces, each free to move without
//! disturbing the others. The idea: piece `i` (0-based) runs over `[u_i, u_{i+1}]` with local
//! parameter `t = (u − u_i)/(u_{i+1} − u_i)`, so its r-th derivative in `u` is the r-th
//! derivative of the Bézier curve in `t` divided by `(u_{i+1} − u_i)ʳ`; a parameter is located
//! by binary search over the partition, compared exactly.
//!
//! Follows [RD, §3.2] ("Curvas de Bézier compuestas": the global parameter) and
//! [PPB, §3.10].
//!
//! # Complexity
//!
//! O(log m + nD) per point and O(log m + n²D) per derivative for m pieces of degree n in
//! R^D.

use super::curve::Bezier;
use super::derivative::difference;
use crate::spline::curve::{check_interval, Curve, CurveDerivative, Domain, Subsegment};
use crate::spline::interpolate::check_partition;
use crate::spline::scalar::{falling_factorial, power, Point, Scalar};
use crate::{Error, Result};

/// A piecewise Bézier curve over a strictly increasing partition.
///
/// ```
/// use compgeo::spline::{CompositeBezier, Curve, Point};
///
/// let p = |x: f64, y: f64| Point::new([x, y]);
/// // Two quadratic pieces over [0, 1] and [1, 3] meeting at (2, 2).
/// let c = CompositeBezier::new(
///     vec![0.0, 1.0, 3.0],
///     vec![vec![p(0.0, 0.0), p(1.0, 2.0), p(2.0, 2.0)], vec![p(2.0, 2.0), p(4.0, 2.0), p(5.0, 0.0)]],
/// )?;
/// assert_eq!(c.eval(&1.0)?, p(2.0, 2.0));
/// assert!(c.is_c(1, &0.0)); // (2,2)−(1,2) over 1 equals (4,2)−(2,2) over 2
/// assert!(!c.is_c(2, &0.0));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CompositeBezier<S, const D: usize> {
    pub(super) partition: Vec<S>,
    pub(super) pieces: Vec<Bezier<S, D>>,
}

impl<S: Scalar, const D: usize> CompositeBezier<S, D> {
    /// A composite curve from its partition `u_0 < ... < u_m` and its `m` control polygons.
    ///
    /// Pieces may have different degrees and need not meet; the join checks say how they do.
    ///
    /// # Errors
    ///
    /// [`Error::TooFew`] for fewer than two knots; [`Error::InvalidParameter`] (`"partition"`)
    /// for a non-finite or non-increasing partition, (`"pieces"`) if the number of pieces is
    /// not the number of intervals; [`Error::Empty`] / [`Error::NonFinite`] for an empty
    /// control polygon or a bad coordinate.
    pub fn new(partition: Vec<S>, pieces: Vec<Vec<Point<S, D>>>) -> Result<Self> {
        let pieces = pieces
            .into_iter()
            .map(Bezier::new)
            .collect::<Result<Vec<_>>>()?;
        Self::from_pieces(partition, pieces)
    }

    /// A composite curve from its partition and its `m` Bézier pieces.
    ///
    /// # Errors
    ///
    /// As [`new`](Self::new).
    pub fn from_pieces(partition: Vec<S>, pieces: Vec<Bezier<S, D>>) -> Result<Self> {
        check_partition(&partition, 2, "partition")?;
        if pieces.len() + 1 != partition.len() {
            return Err(Error::InvalidParameter {
                name: "pieces",
                reason: format!(
                    "{} pieces for a partition of {} intervals",
                    pieces.len(),
                    partition.len() - 1
                ),
            });
        }
        Ok(CompositeBezier { partition, pieces })
    }

    /// The partition `u_0 < ... < u_m`.
    pub fn partition(&self) -> &[S] {
        &self.partition
    }

    /// The Bézier pieces, one per interval, each over its local parameter `t ∈ [0, 1]`.
    pub fn pieces(&self) -> &[Bezier<S, D>] {
        &self.pieces
    }

    /// The piece containing `u` and the local parameter there. An interior knot belongs to
    /// the piece on its right; `u_m` to the last piece.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] (`"u"`) if `u` is not finite or outside `[u_0, u_m]`.
    ///
    /// # Complexity
    ///
    /// O(log m) exact comparisons (binary search).
    pub fn locate(&self, u: &S) -> Result<(usize, S)> {
        self.domain().check(u, "u")?;
        let m = self.pieces.len();
        // The last knot <= u among u_0..u_{m-1}.
        let i = self.partition[1..m].partition_point(|k| k <= u);
        Ok((i, self.local(i, u)))
    }

    /// The derivatives of orders `0..=order` at the end of piece `i` (`end = true`, at
    /// `u_{i+1}` from the left) or at its start (at `u_i` from the right), in `u`; those above
    /// the piece's degree are zero.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] (`"piece"`) if `i` is not a piece index;
    /// [`Error::LimitExceeded`] if `order` exceeds [`MAX_DEGREE`](crate::limits::MAX_DEGREE)
    /// (the answer has `order + 1` entries).
    ///
    /// # Complexity
    ///
    /// Θ(order·nD) for a piece of degree n (forward differences at one end).
    pub fn end_derivatives(&self, i: usize, end: bool, order: usize) -> Result<Vec<Point<S, D>>> {
        crate::limits::DEGREE.check(order as u128)?;
        if i >= self.pieces.len() {
            return Err(Error::InvalidParameter {
                name: "piece",
                reason: format!("{i} is not a piece index (0..{})", self.pieces.len()),
            });
        }
        Ok(self.end_derivatives_unchecked(i, end, order))
    }

    /// [`end_derivatives`](Self::end_derivatives) for a valid piece index.
    pub(crate) fn end_derivatives_unchecked(
        &self,
        i: usize,
        end: bool,
        order: usize,
    ) -> Vec<Point<S, D>> {
        let h = self.width(i);
        local_end_derivatives(self.pieces[i].control(), end, order)
            .into_iter()
            .enumerate()
            .map(|(r, d)| d / &power(&h, r))
            .collect()
    }
}

/// A composite curve is defined on its partition.
impl<S: Scalar, const D: usize> Curve<S, D> for CompositeBezier<S, D> {
    /// `[u_0, u_m]`.
    fn domain(&self) -> Domain<S> {
        Domain::Interval {
            start: self.partition[0].clone(),
            end: self.partition[self.pieces.len()].clone(),
        }
    }

    /// The point `C(u)`: the piece containing `u` ([`locate`](CompositeBezier::locate)) at
    /// its local parameter.
    ///
    /// # Errors
    ///
    /// As [`locate`](CompositeBezier::locate).
    ///
    /// # Complexity
    ///
    /// O(log m + nD) for m pieces of degree n (Horner on one piece).
    fn eval(&self, u: &S) -> Result<Point<S, D>> {
        let (i, t) = self.locate(u)?;
        self.pieces[i].eval(&t)
    }
}

/// Derivatives in the global parameter, from the right at an interior knot.
impl<S: Scalar, const D: usize> CurveDerivative<S, D> for CompositeBezier<S, D> {
    type Derivative = CompositeBezier<S, D>;

    /// The composite curve of the hodographs, piece `i` divided by `u_{i+1} − u_i`, over the
    /// same partition.
    ///
    /// # Complexity
    ///
    /// Θ(m·nD).
    fn derivative_curve(&self) -> Result<Self> {
        let pieces = self
            .pieces
            .iter()
            .enumerate()
            .map(|(i, piece)| {
                let h = self.width(i);
                let scaled = piece
                    .hodograph()?
                    .into_control()
                    .into_iter()
                    .map(|p| p / &h)
                    .collect();
                Bezier::derived(scaled, "derivative")
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(CompositeBezier {
            partition: self.partition.clone(),
            pieces,
        })
    }

    /// The r-th derivative `C⁽ʳ⁾(u)` (from the right at an interior knot, from the left at
    /// `u_m`). Order 0 is the point itself.
    ///
    /// # Errors
    ///
    /// As [`locate`](CompositeBezier::locate).
    ///
    /// # Complexity
    ///
    /// O(log m + n²D) (the tetrahedral algorithm on one piece).
    fn derivative_at(&self, u: &S, order: usize) -> Result<Point<S, D>> {
        let (i, t) = self.locate(u)?;
        Ok(self.pieces[i].derivative_at(&t, order)? / &power(&self.width(i), order))
    }
}

/// The piece over [a, b] is the composite curve over `a, u_{i+1}, …, u_j, b` (the knots
/// strictly between a and b): the pieces strictly inside are kept, the first and the last are
/// restricted by blossoming. A knot b belongs to the piece on its left here (the curve's
/// value at b is the right piece's, which differs where the pieces do not meet).
impl<S: Scalar, const D: usize> Subsegment<S, D> for CompositeBezier<S, D> {
    type Segment = CompositeBezier<S, D>;

    /// # Complexity
    ///
    /// O(log m + k·n·D + n³D) for k pieces in [a, b].
    fn subsegment(&self, a: &S, b: &S) -> Result<Self> {
        check_interval(&self.domain(), a, b)?;
        let m = self.pieces.len();
        let first = self.partition[1..m].partition_point(|k| k <= a);
        // The piece that ends at b or contains it: b belongs to the piece on its left.
        let last = self.partition[1..m].partition_point(|k| k < b);
        let mut partition = Vec::with_capacity(last - first + 2);
        let mut pieces = Vec::with_capacity(last - first + 1);
        partition.push(a.clone());
        for i in first..=last {
            let start = if i == first {
                self.local(i, a)
            } else {
                S::zero()
            };
            let end = if i == last {
                self.local(i, b)
            } else {
                S::one()
            };
            let piece = &self.pieces[i];
            pieces.push(if start.is_zero() && end == S::one() {
                piece.clone()
            } else {
                piece.restrict(&start, &end)?
            });
            partition.push(if i == last {
                b.clone()
            } else {
                self.partition[i + 1].clone()
            });
        }
        Ok(CompositeBezier { partition, pieces })
    }
}

impl<S: Scalar, const D: usize> CompositeBezier<S, D> {
    /// The local parameter of `u` on piece `i`.
    fn local(&self, i: usize, u: &S) -> S {
        (u.clone() - &self.partition[i]) / self.width(i)
    }

    /// The length `u_{i+1} − u_i` of interval `i`.
    fn width(&self, i: usize) -> S {
        self.partition[i + 1].clone() - &self.partition[i]
    }
}

/// The derivatives of orders `0..=order` of a Bézier curve at `t = 1` (`end`) or `t = 0`:
/// `n!/(n−k)! Δᵏ b_{n−k}` or `n!/(n−k)! Δᵏ b_0`, and zero above the degree n.
fn local_end_derivatives<S: Scalar, const D: usize>(
    control: &[Point<S, D>],
    end: bool,
    order: usize,
) -> Vec<Point<S, D>> {
    let n = control.len() - 1;
    let top = order.min(n);
    // The top + 1 points nearest the end, as Δᵗᵒᵖ needs them.
    let mut diffs: Vec<Point<S, D>> = if end {
        control[n - top..].to_vec()
    } else {
        control[..=top].to_vec()
    };
    let mut out = Vec::with_capacity(order + 1);
    for k in 0..=top {
        let d = if end {
            &diffs[diffs.len() - 1]
        } else {
            &diffs[0]
        };
        out.push(d.clone() * falling_factorial::<S>(n, k));
        difference(&mut diffs);
    }
    // Derivatives above the degree are zero.
    out.resize(order + 1, Point::zero());
    out
}
