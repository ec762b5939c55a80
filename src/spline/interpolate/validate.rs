//! The validation every interpolation kernel shares: nodes and points, partitions, Hermite
//! data, and the errors for singular data and for `f64` results out of range. Data is checked
//! once, at the public function; the kernels behind it take it as valid.

use super::polynomial::HermiteNode;
use crate::count::{Counter, NoCount};
use crate::spline::scalar::{validate_points, Point, Scalar};
use crate::{limits, Error, Result};

/// Checks that `nodes` and `points` are non-empty, of equal length and finite.
pub(crate) fn check_nodes_and_points<S: Scalar, const D: usize>(
    nodes: &[S],
    points: &[Point<S, D>],
) -> Result<()> {
    if nodes.is_empty() {
        return Err(Error::Empty { what: "nodes" });
    }
    if nodes.len() != points.len() {
        return Err(Error::InvalidParameter {
            name: "points",
            reason: format!("{} points for {} nodes", points.len(), nodes.len()),
        });
    }
    validate_points(points, "points")?;
    check_finite_nodes(nodes, "nodes")
}

/// Checks that `count` interpolation conditions give a polynomial of degree (`count − 1`)
/// within [`MAX_DEGREE`](crate::limits::MAX_DEGREE).
pub(crate) fn check_degree(count: usize) -> Result<()> {
    limits::DEGREE.check(count.saturating_sub(1) as u128)?;
    Ok(())
}

/// Checks that a dense system of `unknowns` unknowns is within
/// [`MAX_DENSE_UNKNOWNS`](crate::limits::MAX_DENSE_UNKNOWNS), before its matrix is allocated.
pub(crate) fn check_dense(unknowns: usize) -> Result<()> {
    limits::DENSE_UNKNOWNS.check(unknowns as u128)?;
    Ok(())
}

/// Checks every node is finite.
pub(crate) fn check_finite_nodes<S: Scalar>(nodes: &[S], name: &'static str) -> Result<()> {
    match nodes.iter().position(|u| !u.is_finite()) {
        None => Ok(()),
        Some(i) => Err(Error::InvalidParameter {
            name,
            reason: format!("node {i} is not finite ({})", nodes[i].to_f64()),
        }),
    }
}

/// Checks that no two nodes are equal (in any order); O(n log n).
pub(crate) fn check_distinct<S: Scalar>(nodes: &[S]) -> Result<()> {
    check_distinct_with(nodes, &mut NoCount)
}

/// [`check_distinct`], counting one [`comparison`](Counter::comparison) per comparison of two
/// nodes: those of the sort, then one per neighbouring pair.
pub(crate) fn check_distinct_with<S: Scalar, C: Counter>(
    nodes: &[S],
    counter: &mut C,
) -> Result<()> {
    let mut order: Vec<usize> = (0..nodes.len()).collect();
    // The nodes are finite, so `partial_cmp` is total on them.
    order.sort_by(|&a, &b| {
        counter.comparison();
        nodes[a]
            .partial_cmp(&nodes[b])
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    for w in order.windows(2) {
        counter.comparison();
        if nodes[w[0]] == nodes[w[1]] {
            let (i, j) = (w[0].min(w[1]), w[0].max(w[1]));
            return Err(singular(
                "nodes",
                &format!(
                    "nodes {i} and {j} are equal ({}); a repeated node needs derivative data",
                    nodes[i].to_f64()
                ),
            ));
        }
    }
    Ok(())
}

/// Checks that a partition `u_0 < u_1 < ... < u_m` is finite and strictly increasing and has
/// at least `needed` knots.
pub(crate) fn check_partition<S: Scalar>(
    partition: &[S],
    needed: usize,
    name: &'static str,
) -> Result<()> {
    if partition.len() < needed {
        return Err(Error::TooFew {
            what: name,
            needed,
            got: partition.len(),
        });
    }
    check_finite_nodes(partition, name)?;
    match partition.windows(2).position(|w| w[0] >= w[1]) {
        None => Ok(()),
        Some(i) => Err(Error::InvalidParameter {
            name,
            reason: format!(
                "must be strictly increasing, but u_{} = {} is not below u_{} = {}",
                i,
                partition[i].to_f64(),
                i + 1,
                partition[i + 1].to_f64()
            ),
        }),
    }
}

/// Checks the data of a piecewise interpolant: at least `needed` points, one knot per point,
/// all finite, the partition strictly increasing.
pub(crate) fn check_knots_and_points<S: Scalar, const D: usize>(
    partition: &[S],
    points: &[Point<S, D>],
    needed: usize,
) -> Result<()> {
    if points.len() < needed {
        return Err(Error::TooFew {
            what: "points",
            needed,
            got: points.len(),
        });
    }
    check_nodes_and_points(partition, points)?;
    check_partition(partition, needed, "partition")
}

/// Validates Hermite data and returns the number of conditions.
pub(crate) fn check_hermite<S: Scalar, const D: usize>(
    data: &[HermiteNode<S, D>],
) -> Result<usize> {
    if data.is_empty() {
        return Err(Error::Empty { what: "nodes" });
    }
    let mut index = 0;
    for node in data {
        if node.values.is_empty() {
            return Err(Error::Empty {
                what: "values of a Hermite node",
            });
        }
        for v in &node.values {
            if let Some(c) = v.coords().iter().find(|c| !c.is_finite()) {
                return Err(Error::NonFinite {
                    index,
                    value: c.to_f64(),
                });
            }
            index += 1;
        }
    }
    check_degree(index)?;
    let nodes: Vec<S> = data.iter().map(|n| n.u.clone()).collect();
    check_finite_nodes(&nodes, "nodes")?;
    check_distinct(&nodes)?;
    Ok(index)
}

/// The points, or [`overflow`] if an `f64` one is beyond the double range (finite data whose
/// result is out of range: large values, tangents or knot gaps, or nearly equal nodes).
pub(crate) fn finite<S: Scalar, const D: usize>(
    points: Vec<Point<S, D>>,
) -> Result<Vec<Point<S, D>>> {
    if points.iter().all(Point::is_finite) {
        Ok(points)
    } else {
        Err(overflow())
    }
}

/// The error for finite data whose result is beyond the `f64` range.
pub(crate) fn overflow() -> Error {
    Error::InvalidParameter {
        name: "points",
        reason: "the result overflows f64 (large coordinates, tangents or knot gaps, or nearly \
                 equal nodes); use exact rationals"
            .to_string(),
    }
}

/// The error for singular interpolation data.
pub(crate) fn singular(name: &'static str, reason: &str) -> Error {
    Error::InvalidParameter {
        name,
        reason: reason.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn partitions_must_increase_strictly() {
        assert!(check_partition(&[0.0, 0.5, 1.0], 2, "partition").is_ok());
        assert!(check_partition(&[0.0, 0.5, 0.5], 2, "partition").is_err());
        assert!(check_partition(&[0.0, f64::NAN], 2, "partition").is_err());
        assert!(matches!(
            check_partition(&[0.0], 2, "partition"),
            Err(Error::TooFew {
                needed: 2,
                got: 1,
                ..
            })
        ));
    }
}
