//! Delaunay triangulations: compact half-edge arrays, exact predicates, an exact checker.
//!
//! The seed (`003_5b666ee3e15e6353.txt`, §2.4 "Problemas de proximidad", "Diagrama de
//! Voronoi" and "Triangulación de Delaunay", Definition 2.34 and Theorem 2.35) defines the
//! Delaunay triangulation as the dual of the Voronoi diagram for points in general
//! position: the triangles whose circumcircles hold no other point. compgeo does not assume
//! general position: with four or more cocircular points any triangulation of their
//! polygon is Delaunay, and compgeo returns one of them.
//!
//! # One output for every builder
//!
//! Every builder returns a [`Triangulation`]: counter-clockwise triangles as flat index
//! arrays (`triangles`, `halfedges`, `hull`, as delaunator lays them out) plus the merged
//! `duplicates`. Every geometric decision is one of the exact predicates of
//! [`crate::geometry`] ([`orient2d`](crate::geometry::orient2d) and
//! [`incircle`](crate::geometry::incircle)), so the result is an exact Delaunay
//! triangulation for every finite input, 1e300 and subnormals in one set included.
//!
//! | input | result |
//! |---|---|
//! | NaN or infinite coordinate | [`Error::NonFinite`](crate::Error::NonFinite) |
//! | a point equal to an earlier one | merged, listed as `[dropped, kept]` in `duplicates` |
//! | fewer than 3 distinct points, or all collinear | no triangles; `hull` = the distinct points along their line |
//! | otherwise | `2n - 2 - h` triangles for n distinct points, h of them on the hull boundary |
//!
//! [`check_delaunay`] verifies all of this exactly; the tests run it on every builder.

mod check;
mod closest_pair;
mod construct;
mod empty_circle;
mod hilbert;
mod incremental;
mod proximity;
mod triangulation;
mod voronoi;

pub use check::check_delaunay;
pub use closest_pair::{closest_pair_divide_and_conquer, closest_pair_divide_and_conquer_with};
pub use empty_circle::{largest_empty_circle, largest_empty_circle_with, EmptyCircle};
pub use incremental::{incremental, incremental_with};
pub use proximity::{
    all_nearest_neighbours, all_nearest_neighbours_with, closest_pair, closest_pair_with,
    euclidean_mst, euclidean_mst_with, nearest, ClosestPair, Emst, NearestSearch,
};
pub use triangulation::{find_duplicates, next_halfedge, prev_halfedge, Triangulation, EMPTY};
pub use voronoi::{dual, voronoi, voronoi_with, Cell, ClipBox, Ray, Voronoi};
