//! Seeded workload generators: point sets, graphs, number sequences and polygon meshes.
//!
//! Every generator is deterministic: the same arguments and seed give bit-identical output
//! on every machine. Randomness comes from ChaCha8 (`rand_chacha`, seeded with
//! `seed_from_u64`), turned into integers by exact rejection sampling and into `f64` by
//! exact scaling of random bits; coordinates are then computed with correctly rounded IEEE
//! operations (`+ - * / sqrt`) and bit manipulation only. Platform `ln`, `sin`, `cos` and
//! `exp` are never used, since libm implementations may differ in the last ulp; gaussian
//! samples use a logarithm assembled from `+ - * /`.
//!
//! The generators lean toward the inputs that break geometry code: cocircular lattice
//! points, points one ulp apart, exactly collinear sets, integer grids and magnitudes near
//! the ends of the `f64` range, next to the usual uniform and gaussian clouds.
//!
//! | function | produces |
//! |---|---|
//! | [`points`] | `Vec<Point2>` of a [`PointKind`] |
//! | [`graph`], [`with_random_weights`] | an [`EdgeList`](crate::graph::EdgeList) of a [`GraphKind`] |
//! | [`sequence`], [`sequence_f64`] | `i64` keys of a [`SequenceKind`], `f64` keys |
//! | [`mesh`] (and [`quad_grid`], [`triangle_grid`], [`cube`], [`quad_torus`], [`triangle_torus`], [`irregular_torus`], [`irregular_disk`]) | a [`PolygonMesh`](crate::mesh::PolygonMesh) of a [`MeshKind`] |
//!
//! ```
//! use compgeo::gen::{points, PointKind};
//!
//! let a = points(PointKind::Gaussian, 1000, 42)?;
//! let b = points(PointKind::Gaussian, 1000, 42)?;
//! assert_eq!(a, b);
//! assert_ne!(a, points(PointKind::Gaussian, 1000, 43)?);
//! # Ok::<(), compgeo::Error>(())
//! ```

mod cocircular;
mod gaussian;
mod graphs;
mod meshes;
mod points;
mod rng;
mod sequences;

pub use graphs::{graph, with_random_weights, GraphKind};
pub use meshes::{
    cube, irregular_disk, irregular_torus, mesh, quad_grid, quad_torus, triangle_grid,
    triangle_torus, MeshKind,
};
pub use points::{points, PointKind, MAX_COCIRCULAR};
pub use sequences::{sequence, sequence_f64, SequenceKind, RANDOM_KEY_BOUND};

pub(crate) use rng::Rng;

pub use crate::limits::{MAX_KEYS, MAX_POINTS};
