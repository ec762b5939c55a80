//! The course's proximity problems: all nearest neighbours, the closest pair (on the Delaunay
//! triangulation and by divide and conquer), nearest-neighbour queries, the Euclidean minimum
//! spanning tree and the largest empty circle.
//!
//! All but the divide and conquer follow [RD, §2.4] "Solución de los
//! problemas de proximidad": every nearest neighbour of a site is a Delaunay neighbour
//! (Theorem 2.31), so the Delaunay edges (3n − 3 − h of them) hold every answer. Distances are
//! compared with the exact [`cmp_dist`](crate::geometry::cmp_dist) only; the distances,
//! lengths and radii of the results are reported as [`WideFloat`](crate::geometry::WideFloat)s,
//! within a stated relative error of the exact values even beyond `f64::MAX`.
//!
//! | problem | function | file |
//! |---|---|---|
//! | all nearest neighbours | [`all_nearest_neighbours`] | `all_nearest.rs` |
//! | closest pair, the shortest Delaunay edge | [`closest_pair`] | `closest_pair_delaunay.rs` |
//! | closest pair by divide and conquer | [`closest_pair_divide_and_conquer`] | `closest_pair_divide_and_conquer.rs` |
//! | nearest site of a query point | [`NearestSearch`], [`nearest`] | `nearest.rs` |
//! | Euclidean minimum spanning tree | [`euclidean_mst`] | `emst.rs` |
//! | largest empty circle centred in the hull | [`largest_empty_circle`] | `empty_circle.rs` |
//!
//! Duplicates are points at distance zero: a duplicate's nearest neighbour is a point equal
//! to it, the closest pair of a set with duplicates is a pair of equal points, and the
//! spanning tree joins equal points by zero-length edges.

mod all_nearest;
mod closest_pair;
mod closest_pair_delaunay;
mod closest_pair_divide_and_conquer;
mod empty_circle;
mod emst;
mod nearest;

pub use all_nearest::{all_nearest_neighbours, all_nearest_neighbours_with};
pub use closest_pair::{closest_pair, closest_pair_with, ClosestPairAlgorithm};
pub use closest_pair_delaunay::{closest_pair_delaunay, closest_pair_delaunay_with};
pub use closest_pair_divide_and_conquer::{
    closest_pair_divide_and_conquer, closest_pair_divide_and_conquer_with,
};
pub use empty_circle::{largest_empty_circle, largest_empty_circle_with, EmptyCircle};
pub use emst::{euclidean_mst, euclidean_mst_with};
pub(crate) use nearest::DelaunayGraph;
pub use nearest::{nearest, NearestSearch};

use crate::complexity::Declaration;
use crate::delaunay::Triangulation;
use crate::error::{Error, Result};
use crate::util::Csr;

/// All nearest neighbours' declaration.
pub(crate) const ALL_NEAREST: &Declaration = &all_nearest::DECLARATION;
/// The nearest-point search's declaration.
pub(crate) const NEAREST: &Declaration = &nearest::DECLARATION;
/// The Euclidean minimum spanning tree's declaration.
pub(crate) const EMST: &Declaration = &emst::DECLARATION;
/// The largest empty circle's declaration.
pub(crate) const EMPTY_CIRCLE: &Declaration = &empty_circle::DECLARATION;

/// The proximity algorithms that are not a choice among alternatives.
pub(crate) const DECLARATIONS: [&Declaration; 4] = [ALL_NEAREST, NEAREST, EMST, EMPTY_CIRCLE];

/// The undirected edges of the Delaunay graph: the triangulation's edges, or for collinear
/// points (no triangles) the segments between consecutive points along their line.
pub(crate) fn delaunay_edges(t: &Triangulation) -> Vec<[usize; 2]> {
    if t.is_empty() {
        t.hull.windows(2).map(|w| [w[0], w[1]]).collect()
    } else {
        t.edges().collect()
    }
}

/// Neighbour lists (compressed rows) of an undirected edge list on `n` vertices: the
/// offsets, and the neighbours of `v` at `offsets[v]..offsets[v + 1]` in ascending order.
pub(crate) fn adjacency(n: usize, edges: &[[usize; 2]]) -> (Vec<usize>, Vec<usize>) {
    let csr = Csr::undirected(n, edges.iter().map(|&e| (e, ())));
    let neighbours = csr.entries.iter().map(|&(w, ())| w as usize).collect();
    (csr.offsets, neighbours)
}

/// The error of a problem that needs at least `needed` points.
pub(crate) fn at_least(needed: usize, got: usize) -> Result<()> {
    if got < needed {
        return Err(Error::TooFew {
            what: "point set",
            needed,
            got,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::geometry::{Point2, PointPair, PointSet, WideFloat};

    fn pts(v: &[(f64, f64)]) -> Vec<Point2> {
        v.iter().map(|&p| Point2::from(p)).collect()
    }

    #[test]
    fn collinear_points_use_the_path_along_their_line() {
        let p = pts(&[(0.0, 0.0), (3.0, 3.0), (1.0, 1.0), (7.0, 7.0)]);
        assert_eq!(all_nearest_neighbours(&p).unwrap(), [2, 2, 0, 1]);
        for algorithm in ClosestPairAlgorithm::ALL {
            assert_eq!(closest_pair(&p, algorithm).unwrap().pair, [0, 2]);
        }
        assert_eq!(nearest(&p, Point2::new(6.0, 1.0)).unwrap(), 1);
        let t = euclidean_mst(&p).unwrap();
        assert_eq!(t.edges, [[0, 2], [1, 2], [1, 3]]);
    }

    #[test]
    fn small_inputs() {
        let one = pts(&[(1.0, 2.0)]);
        for algorithm in ClosestPairAlgorithm::ALL {
            assert!(matches!(
                closest_pair(&one, algorithm),
                Err(Error::TooFew { got: 1, .. })
            ));
        }
        assert_eq!(nearest(&one, Point2::new(-5.0, 0.0)).unwrap(), 0);
        assert_eq!(euclidean_mst(&one).unwrap().edges, Vec::<[usize; 2]>::new());
        assert!(matches!(
            nearest(&[], Point2::new(0.0, 0.0)),
            Err(Error::TooFew {
                needed: 1,
                got: 0,
                ..
            })
        ));
        let same = pts(&[(1.0, 2.0), (1.0, 2.0)]);
        let zero = PointPair {
            pair: [0, 1],
            distance: WideFloat::ZERO,
        };
        for algorithm in ClosestPairAlgorithm::ALL {
            assert_eq!(closest_pair(&same, algorithm).unwrap(), zero);
        }
        assert_eq!(all_nearest_neighbours(&same).unwrap(), [1, 0]);
        assert_eq!(euclidean_mst(&same).unwrap().edges, [[0, 1]]);
    }

    #[test]
    fn a_bad_start_is_an_error() {
        let p = pts(&[(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.0, 0.0)]);
        let set = PointSet::new(&p).unwrap();
        let s = NearestSearch::new(&set).unwrap();
        let q = Point2::new(0.1, 0.1);
        assert!(s.nearest_with(q, Some(3), &mut NoCount).is_err());
        assert!(s.nearest_with(q, Some(9), &mut NoCount).is_err());
        assert_eq!(s.nearest_with(q, Some(2), &mut NoCount).unwrap(), 0);
    }
}
