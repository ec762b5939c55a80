//! The integration tests, one binary: each module tests one part of the crate against its
//! oracles (brute force, exact rationals, a second algorithm, a peer crate), its degenerate
//! and bad inputs, and its command line.
//!
//! One binary instead of one per file: the peer crates (spade, delaunator, geo, petgraph,
//! kurbo, ...) are linked once. Run one part with `cargo test --test suite hull::`.

mod common;
mod spline_common;
mod strategies;

mod attack_cli;
mod attack_degenerate;
mod attack_readers;
mod beta;
mod beta_cli;
mod bezier;
mod bezier_eval;
mod browser;
mod bspline_basis;
mod bspline_blossom;
mod bspline_cli;
mod bspline_convert;
mod bspline_curve;
mod bspline_fit;
mod bspline_hostile;
mod bspline_knot_ops;
mod calipers;
mod catmull_clark;
mod cli;
mod colouring_search;
mod complexity;
mod constructions;
mod counts;
mod degenerate;
mod delaunay;
mod delaunay_builders;
mod draw;
mod draw_cli;
mod draw_curve_steps;
mod draw_curves;
mod draw_curves_cli;
mod draw_graph_steps;
mod draw_steps;
mod empty_circle;
mod fortune;
mod frenet;
mod fuzz_regressions;
mod gen;
mod graph;
mod graph_text;
mod hull;
mod interpolate;
mod interpolate_cli;
mod lex_sort;
mod limits;
mod mesh;
mod mesh_cli;
mod mesh_cli_schemes;
mod mesh_doo_sabin;
mod mesh_loop;
mod nearest;
mod nurbs;
mod nurbs_cli;
mod overflow;
#[cfg(feature = "parallel")]
mod parallel;
mod predicates;
mod proximity;
mod registry;
mod sort;
mod subdivision;
mod subdivision_cli;
mod surface_bezier;
mod surface_bezier_examples;
mod surface_bspline;
mod surface_cli;
mod surface_construct;
mod surface_mesh;
mod surface_subdivision;
mod traces;
mod triangle;
mod triangle_cli;
mod voronoi;
mod voronoi_clip;
mod width;
