//! Evaluation of a Bézier curve on a uniform grid by forward differences.
//!
//! The problem: the points b(start + i·step) for many i, cheaply. The idea: on a uniform grid
//! the n-th differences of a degree-n polynomial are constant; evaluate the first n + 1
//! points, build their difference table, then get every further point with n additions of
//! points.
//!
//! Follows [PPB, §3.6] (and its Obs. 6: numerically less stable than subdivision; on `f64`
//! errors grow with the number of steps).
//!
//! # Complexity
//!
//! Θ((n² + count·n)D) time, O(nD) auxiliary space.
//!
//! Invariants the tests check (exactly on rationals): every point equals the evaluation.

use super::curve::Bezier;
use super::derivative::difference;
use crate::spline::curve::Curve;
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::Result;

impl<S: Scalar, const D: usize> Bezier<S, D> {
    /// The points `b(start + i·step)`, i = 0, …, count − 1, by forward differences.
    ///
    /// Idea: on a uniform grid the n-th differences of a degree-n polynomial are constant.
    /// Evaluate the first n + 1 points, build their difference table, then get every further
    /// point with n additions of points.
    ///
    /// Follows [PPB, §3.6] (and its Obs. 6: numerically less stable than
    /// subdivision; on `f64` errors grow with the number of steps).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`](crate::Error::InvalidParameter) if `start` or `step` is NaN
    /// or infinite; [`Error::LimitExceeded`](crate::Error::LimitExceeded) if `count` exceeds
    /// [`MAX_SAMPLES`](crate::limits::MAX_SAMPLES).
    ///
    /// # Complexity
    ///
    /// Θ(n²D) for the start, then Θ(nD) per point: Θ((n² + count·n)D) time, O(nD) auxiliary
    /// space.
    ///
    /// ```
    /// use compgeo::spline::{Bezier, Point};
    ///
    /// let b = Bezier::new(vec![Point::new([0.0]), Point::new([0.0]), Point::new([1.0])])?; // t²
    /// let p = b.forward_differences(&0.0, &0.5, 5)?;
    /// assert_eq!(p, [0.0, 0.25, 1.0, 2.25, 4.0].map(|x| Point::new([x])));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn forward_differences(
        &self,
        start: &S,
        step: &S,
        count: usize,
    ) -> Result<Vec<Point<S, D>>> {
        validate_parameter(start, "start")?;
        validate_parameter(step, "step")?;
        crate::limits::SAMPLES.check(count as u128)?;
        let n = self.degree();
        let mut out = Vec::with_capacity(count);
        let mut t = start.clone();
        for _ in 0..count.min(n + 1) {
            out.push(self.eval(&t)?);
            t += step;
        }
        if count <= n + 1 {
            return Ok(out);
        }
        // e[k] = Δᵏp_{n−k}: the last entry of each column of the difference table.
        let mut q = out.clone();
        let mut e = Vec::with_capacity(n + 1);
        e.push(q[n].clone());
        for k in 1..=n {
            difference(&mut q);
            e.push(q[n - k].clone());
        }
        // Δⁿp is constant; one step down the table is Δᵏp_{j+1−k} = Δᵏp_{j−k} + Δᵏ⁺¹p_{j−k}.
        for _ in n + 1..count {
            for k in (0..n).rev() {
                e[k] = e[k].clone() + &e[k + 1];
            }
            out.push(e[0].clone());
        }
        Ok(out)
    }
}
