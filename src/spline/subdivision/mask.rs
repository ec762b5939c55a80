//! Subdivision masks: the characteristic polynomial α(z) = Σ_k α_k z^k of a uniform
//! stationary scheme, and k rounds of any such scheme on a polygon.
//!
//! The problem: given the weights α_k, refine a polygon c by b_i = Σ_j c_j α_{i−2j}
//! [PPB, §8.4, §8.6, §8.8]. In matrix form b = cS with S_{j,i} = α_{i−2j}: every column of the
//! subdivision matrix is the mask shifted by two rows, so the mask *is* the matrix. In
//! polynomials b(z) = c(z²)·α(z), which is how [PPB, §8.8] derives the difference schemes
//! (`difference.rs`).
//!
//! Rounds of a closed polygon of n vertices take indices mod n and give b_0, …, b_{2n−1}. On
//! an open polygon a round keeps the b_i that the data determine (every c_j with
//! α_{i−2j} ≠ 0 exists), a contiguous run of 2n + c vertices for a constant c of the mask
//! (−d for Lane–Riesenfeld of degree d, as in `lane_riesenfeld.rs`; −5 for the four-point
//! mask, which loses a vertex and a new point at each end, unlike [`four_point`]'s ghost
//! points).
//!
//! # Complexity
//!
//! Θ(L·N) time for k rounds, N ≤ n·2^k the output size and L the mask's length; Θ(N·D)
//! space.
//!
//! Invariants the tests check: the Lane–Riesenfeld masks are 2^{−d}·C(d + 1, i) (against the
//! binomial coefficients and against the algorithm run on a unit impulse), and k rounds of
//! a mask give the same polygon as [`lane_riesenfeld`] and [`four_point`] (closed).
//!
//! [`four_point`]: super::four_point
//! [`lane_riesenfeld`]: super::lane_riesenfeld

use super::{finite, output_size, validate_polygon, Topology};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::spline::scalar::{validate_parameter, Point, Scalar};
use crate::{Error, Result};

/// Rounds of a scheme given by its mask, declared.
pub(crate) const REFINE: Declaration = Declaration {
    problem: "subdivision",
    name: "mask",
    function: "spline::subdivision::Mask::refine",
    file: "src/spline/subdivision/mask.rs",
    summary: "k rounds of the scheme of any mask α: b_i = Σ_j c_j α_{i−2j}",
    time: "Θ(L·N)",
    space: "Θ(N·D)",
    operation: Some(Operation::ArithmeticOperations),
    counts: "one per non-zero mask coefficient used: (number of non-zero coefficients)·m for a closed polygon of m vertices, per round",
    source: "[PPB, §8.4, §8.8]",
    claims: &[on(
        "random-closed",
        Bound::Linear,
        Operation::ArithmeticOperations,
    )],
};

/// The mask of a uniform subdivision scheme: the coefficients α_k, k = start, …, end, of its
/// characteristic polynomial α(z) = Σ_k α_k z^k, a Laurent polynomial [PPB, §8.8]. One round
/// maps a polygon c to b_i = Σ_j c_j α_{i−2j}.
///
/// A mask is stored trimmed: its first and last coefficients are non-zero, so two masks of
/// the same polynomial are equal (`==`).
///
/// ```
/// use compgeo::spline::subdivision::Mask;
///
/// // Chaikin's algorithm: ¼(1 + z)³ [PPB, §8.4].
/// let m = Mask::<f64>::lane_riesenfeld(2)?;
/// assert_eq!((m.start(), m.coefficients()), (0, &[0.25, 0.75, 0.75, 0.25][..]));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Mask<S> {
    /// The exponent of the first coefficient.
    start: i64,
    /// α_start, …, α_end, the first and last non-zero.
    coefficients: Vec<S>,
}

impl<S: Scalar> Mask<S> {
    /// The mask α_k = `coefficients[k − start]`, trimmed of zero coefficients at both ends.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming `"mask"` if a coefficient is NaN or infinite (with
    /// its index), if every coefficient is zero (or there are none), or if the last exponent
    /// is beyond `i64`.
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// let m = Mask::new(-2, vec![0.0, 0.5, 1.0, 0.5, 0.0])?;
    /// assert_eq!((m.start(), m.end()), (-1, 1));
    /// assert!(Mask::new(0, vec![0.0; 3]).is_err());
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn new(start: i64, coefficients: Vec<S>) -> Result<Self> {
        if let Some(i) = coefficients.iter().position(|c| !c.is_finite()) {
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: format!(
                    "coefficient {i} must be finite, got {}",
                    coefficients[i].to_f64()
                ),
            });
        }
        let Some(first) = coefficients.iter().position(|c| !c.is_zero()) else {
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: "has no non-zero coefficient".to_string(),
            });
        };
        let last = coefficients
            .iter()
            .rposition(|c| !c.is_zero())
            .unwrap_or(first);
        let new_start = start as i128 + first as i128;
        let end = start as i128 + last as i128;
        if i64::try_from(end).is_err() || i64::try_from(new_start).is_err() {
            return Err(Error::InvalidParameter {
                name: "mask",
                reason: format!("its last exponent {end} is beyond i64"),
            });
        }
        let mut coefficients = coefficients;
        coefficients.truncate(last + 1);
        coefficients.drain(..first);
        Ok(Mask {
            start: new_start as i64,
            coefficients,
        })
    }

    /// The mask of the Lane–Riesenfeld algorithm of degree d, 2^{−d}(1 + z)^{d+1}:
    /// α_i = 2^{−d}·C(d + 1, i), i = 0, …, d + 1 [PPB, §8.4, §8.8 Obs. 5]. Degree 1 is the
    /// midpoint rule ½(1, 2, 1), degree 2 Chaikin's ¼(1, 3, 3, 1), degree 3 the cubic
    /// B-spline's ⅛(1, 4, 6, 4, 1).
    ///
    /// Computed as the algorithm computes it, doubling (1 + z) then d times multiplying by
    /// (1 + z)/2, so every coefficient lies in [0, 1] and none overflows in `f64`.
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] for degree 0; [`Error::LimitExceeded`] beyond
    /// [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
    ///
    /// # Complexity
    ///
    /// Θ(d²) time, Θ(d) space.
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// let m = Mask::<f64>::lane_riesenfeld(3)?;
    /// assert_eq!(m.coefficients(), [1.0, 4.0, 6.0, 4.0, 1.0].map(|a| a / 8.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn lane_riesenfeld(degree: usize) -> Result<Self> {
        check_degree(degree)?;
        let half = S::from_ratio(1, 2);
        let mut a = vec![S::one(), S::one()];
        for _ in 0..degree {
            // Multiply by (1 + z)/2, from the top so each old value is read before it changes.
            a.push(S::zero());
            for k in (1..a.len()).rev() {
                a[k] = (a[k].clone() + &a[k - 1]) * &half;
            }
            a[0] = a[0].clone() * &half;
        }
        Mask::new(0, a)
    }

    /// The mask of the four-point scheme with tension w [PPB, §8.9, §8.10], centred:
    /// α_{±3} = −w, α_{±1} = ½ + w, α_0 = 1, so b_{2i} = c_i and
    /// b_{2i+1} = −w c_{i−1} + (½ + w)(c_i + c_{i+1}) − w c_{i+2}. (The course's α(z) is z³
    /// times this one.) For w = 0 it is the midpoint rule ½(1, 2, 1).
    ///
    /// # Errors
    ///
    /// [`Error::InvalidParameter`] naming `"tension"` if w is NaN or infinite.
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// let m = Mask::four_point(&(1.0 / 16.0))?;
    /// assert_eq!(m.start(), -3);
    /// assert_eq!(m.coefficients(), [-1.0, 0.0, 9.0, 16.0, 9.0, 0.0, -1.0].map(|a| a / 16.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn four_point(tension: &S) -> Result<Self> {
        validate_parameter(tension, "tension")?;
        let w = tension.clone();
        let inner = S::from_ratio(1, 2) + &w;
        Mask::new(
            -3,
            vec![
                -w.clone(),
                S::zero(),
                inner.clone(),
                S::one(),
                inner,
                S::zero(),
                -w,
            ],
        )
    }

    /// The exponent of the first (non-zero) coefficient.
    pub fn start(&self) -> i64 {
        self.start
    }

    /// The exponent of the last (non-zero) coefficient.
    pub fn end(&self) -> i64 {
        self.start + self.coefficients.len() as i64 - 1
    }

    /// The coefficients α_start, …, α_end.
    pub fn coefficients(&self) -> &[S] {
        &self.coefficients
    }

    /// The coefficient α_k (zero outside start..=end).
    ///
    /// ```
    /// use compgeo::spline::subdivision::Mask;
    ///
    /// let m = Mask::<f64>::lane_riesenfeld(1)?;
    /// assert_eq!((m.coefficient(1), m.coefficient(7)), (1.0, 0.0));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn coefficient(&self, k: i64) -> S {
        let i = k as i128 - self.start as i128;
        usize::try_from(i)
            .ok()
            .and_then(|i| self.coefficients.get(i))
            .cloned()
            .unwrap_or_else(S::zero)
    }

    /// `rounds` rounds of the scheme on a polygon: b_i = Σ_j c_j α_{i−2j}, closed (indices
    /// mod n, 2n vertices a round) or open (the run of b_i that the data determine; module
    /// docs). See [`Mask::refine_with`].
    ///
    /// # Errors
    ///
    /// [`Error::Empty`], [`Error::NonFinite`] for a bad vertex; [`Error::TooFew`] for a closed
    /// polygon of fewer than 3 vertices or an open one too short for a round to grow it;
    /// [`Error::LimitExceeded`] if the output would pass
    /// [`MAX_SUBDIVISION_POINTS`](crate::limits::MAX_SUBDIVISION_POINTS);
    /// [`Error::Overflow`] if, with `f64`, a vertex overflows.
    ///
    /// # Complexity
    ///
    /// Θ(L·N) time, N the output size, L the mask's length; Θ(N·D) space.
    ///
    /// ```
    /// use compgeo::spline::subdivision::{Mask, Topology};
    /// use compgeo::spline::Point;
    ///
    /// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].map(Point::new);
    /// let b = Mask::lane_riesenfeld(1)?.refine(&square, Topology::Closed, 1)?;
    /// // The midpoint rule ½(1, 2, 1): b_{2j} the midpoint of c_{j−1}c_j, b_{2j+1} = c_j.
    /// assert_eq!(b[2], Point::new([0.5, 0.0]));
    /// assert_eq!(b[3], Point::new([1.0, 0.0]));
    /// assert_eq!(b[0], Point::new([0.0, 0.5]));
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn refine<const D: usize>(
        &self,
        points: &[Point<S, D>],
        topology: Topology,
        rounds: usize,
    ) -> Result<Vec<Point<S, D>>> {
        self.refine_with(points, topology, rounds, &mut NoCount)
    }

    /// [`Mask::refine`], counting one
    /// [`arithmetic_operation`](Counter::arithmetic_operation) per non-zero coefficient used
    /// (a point scaled and added).
    ///
    /// Follows [PPB, §8.4] (the refinement equations) and [PPB, §8.8].
    ///
    /// # Errors
    ///
    /// As [`Mask::refine`].
    ///
    /// # Complexity
    ///
    /// Θ(L·N) time, N the output size, L the mask's length; Θ(N·D) space.
    ///
    /// # Counts
    ///
    /// On a closed polygon of m vertices, a round takes exactly z·m operations, z the number
    /// of non-zero coefficients (each one is used by m of the 2m new vertices).
    ///
    /// ```
    /// use compgeo::count::Counts;
    /// use compgeo::spline::subdivision::{Mask, Topology};
    /// use compgeo::spline::Point;
    ///
    /// let p: Vec<Point<f64, 1>> = (0..10).map(|i| Point::new([i as f64])).collect();
    /// let mut c = Counts::default();
    /// Mask::lane_riesenfeld(3)?.refine_with(&p, Topology::Closed, 2, &mut c)?;
    /// assert_eq!(c.arithmetic_operations, 5 * 10 + 5 * 20);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub fn refine_with<const D: usize, C: Counter>(
        &self,
        points: &[Point<S, D>],
        topology: Topology,
        rounds: usize,
        counter: &mut C,
    ) -> Result<Vec<Point<S, D>>> {
        validate_polygon(points, topology, 1, "polygon")?;
        let n = points.len();
        match topology {
            Topology::Closed => {
                output_size(n, rounds, |m| 2 * m)?;
            }
            Topology::Open => {
                // m → 2m + c; a round must grow the polygon, so m ≥ 1 − c.
                let c = self.open_growth();
                let needed = usize::try_from(1 - c).unwrap_or(usize::MAX).max(1);
                if n < needed {
                    return Err(Error::TooFew {
                        what: "open polygon for this mask",
                        needed,
                        got: n,
                    });
                }
                output_size(n, rounds, |m| (2 * m as i128 + c) as u128)?;
            }
        }
        let mut current = points.to_vec();
        for _ in 0..rounds {
            current = self.round(&current, topology, counter);
        }
        finite(current, "mask subdivision")
    }

    /// c in "an open round maps m vertices to 2m + c": the determined run is [lo, hi] with
    /// hi − lo + 1 = 2m + c for every m large enough.
    fn open_growth(&self) -> i128 {
        // Take m = the mask's length + 2, large enough for the run not to be empty.
        let m = self.coefficients.len() as i128 + 2;
        let (lo, hi) = self.open_run(m);
        hi - lo + 1 - 2 * m
    }

    /// The first and last index i whose b_i an open polygon of m vertices determines.
    fn open_run(&self, m: i128) -> (i128, i128) {
        // For each parity p, with K_p its exponents of non-zero coefficients: b_i (i ≡ p)
        // needs c_{(i−k)/2} for every k in K_p, so i ∈ [max K_p, min K_p + 2m − 2].
        let mut first = [i128::MIN, i128::MIN];
        let mut last = [i128::MAX, i128::MAX];
        let mut seen = [false, false];
        for (i, a) in self.coefficients.iter().enumerate() {
            if a.is_zero() {
                continue;
            }
            let k = self.start as i128 + i as i128;
            let p = k.rem_euclid(2) as usize;
            if !seen[p] {
                seen[p] = true;
                first[p] = k;
                last[p] = k + 2 * m - 2;
            } else {
                first[p] = first[p].max(k);
                last[p] = last[p].min(k + 2 * m - 2);
            }
        }
        let determined = |i: i128| {
            let p = i.rem_euclid(2) as usize;
            !seen[p] || (first[p] <= i && i <= last[p])
        };
        // A parity without coefficients puts no bound: start from the other's.
        let mut lo = if seen[0] && seen[1] {
            first[0].max(first[1])
        } else {
            first[0].max(first[1]).max(0)
        };
        if determined(lo - 1) {
            lo -= 1;
        }
        let mut hi = if seen[0] && seen[1] {
            last[0].min(last[1])
        } else {
            last[0].min(last[1]).min(lo + 2 * m - 1)
        };
        if determined(hi + 1) {
            hi += 1;
        }
        (lo, hi)
    }

    /// One round on a polygon the caller validated.
    fn round<const D: usize, C: Counter>(
        &self,
        c: &[Point<S, D>],
        topology: Topology,
        counter: &mut C,
    ) -> Vec<Point<S, D>> {
        let m = c.len() as i128;
        let (lo, hi) = match topology {
            Topology::Closed => (0, 2 * m - 1),
            Topology::Open => self.open_run(m),
        };
        (lo..=hi)
            .map(|i| {
                let mut b = Point::zero();
                for (t, a) in self.coefficients.iter().enumerate() {
                    let k = self.start as i128 + t as i128;
                    if a.is_zero() || (i - k).rem_euclid(2) != 0 {
                        continue;
                    }
                    let j = ((i - k) / 2).rem_euclid(m) as usize;
                    counter.arithmetic_operation();
                    b += &(c[j].clone() * a);
                }
                b
            })
            .collect()
    }
}

/// Degree 0 (the doubling alone, a discontinuous limit) is refused, and a degree is a number.
pub(super) fn check_degree(degree: usize) -> Result<()> {
    if degree == 0 {
        return Err(Error::InvalidParameter {
            name: "degree",
            reason: "must be at least 1 (degree 0 only doubles the vertices)".to_string(),
        });
    }
    crate::limits::DEGREE.check(degree as u128)?;
    Ok(())
}
