//! # compgeo
//!
//! Exact computational-geometry and geometric-modelling algorithms that count their
//! operations and measure their own growth against their stated O-bounds.
//!
//! ## Module map
//!
//! | module | what it holds |
//! |---|---|
//! | [`geometry`] | [`Point2`](geometry::Point2), exact predicates, validation |
//! | [`count`] | the [`Counter`](count::Counter) trait, [`Counts`](count::Counts), [`NoCount`](count::NoCount) |
//! | [`error`] | the crate's [`Error`] and [`Result`] |
//! | [`gen`] | seeded workload generators: point sets, graphs, number sequences |
//! | [`complexity`] | stated bounds, the catalog of algorithms, measurement, fits and verdicts |
//! | [`graph`] | CSR graphs, BFS/DFS, greedy colouring, minimum spanning trees |
//! | [`sort`] | the course's sorts, O(n log n) references, radix sort for `f64`, step traces |
//! | [`hull`] | convex hulls: brute force, Jarvis, Graham, monotone chain, Akl–Toussaint, Quickhull; exact checkers |
//! | [`calipers`] | diameter by brute force and by rotating calipers, antipodal pairs |
//! | [`delaunay`] | Delaunay triangulations in half-edge arrays (incremental builder, the seed's divide and conquer, Lawson's flips, Fortune's sweep), exact checker; the Voronoi diagram and the proximity problems on it |
//! | [`spline`] | curves, generic over the scalar (`f64`, exact rationals) and the dimension: the curve traits, [`spline::bezier`] (Bernstein basis, Bézier, reparametrised and composite curves, one algorithm per file), [`spline::interpolate`] (polynomial, Hermite and spline interpolation, least squares), Frenet frames |
//! | `cli` (feature `cli`) | the `compgeo` command line: readers, JSON output, one file per command |
//!
//! ## Algorithms and their bounds
//!
//! n is the input size (for graphs the number of vertices, m the number of edges). Bounds are
//! worst case unless marked otherwise; the counted operation is the one each algorithm's
//! `# Counts` section names.
//!
//! | algorithm | bound |
//! |---|---|
//! | [`geometry::orient2d`], [`geometry::cmp_dist`], [`geometry::cross_sign`] | O(1), exact for every finite input |
//! | [`geometry::incircle`] | O(1), exact for every finite input |
//! | [`sort::bubble_sort`] | Θ(n²) time, exactly n(n−1)/2 comparisons |
//! | [`sort::selection_sort`] | Θ(n²) time, exactly n(n−1)/2 comparisons |
//! | [`sort::insertion_sort`], [`sort::course_insertion_sort`] | O(n²) time, at most n(n−1)/2 comparisons |
//! | [`sort::binary_insertion_sort`], [`sort::course_binary_insertion_sort`] | O(n log n) comparisons, O(n²) time (moves) |
//! | [`sort::merge_sort`] | Θ(n log n) time, at most n⌈log₂ n⌉ comparisons |
//! | [`sort::heap_sort`] | O(n log n) time, at most 2n log₂ n comparisons |
//! | [`sort::quick_sort`] | O(n log n) time (introsort), at most 6n log₂ n + n comparisons |
//! | [`sort::radix_sort_f64`] | Θ(n) time, at most 24n moves and 7.5n key comparisons |
//! | [`graph::bfs`], [`graph::dfs`] | O(n + m) time, exactly 2m edge visits on a connected graph |
//! | [`graph::course_greedy_colouring`] | O(n² + m) time, exactly n(n−1)/2 adjacency tests |
//! | [`graph::greedy_colouring`] (any order) | O(n + m) time |
//! | [`graph::dsatur`] | O((n + m) log n) time |
//! | [`graph::dsatur_tabu`] (DSatur, then a tabu search for fewer colours) | O((n + m) log n) time, at most 20(n + 2m) search steps |
//! | [`graph::prim`] | O(m log n) time (simple graphs), binary heap |
//! | [`graph::kruskal`] | O(m log m) time, union–find |
//! | [`graph::boruvka`] | O(m log n) time, at most ⌈log₂ n⌉ rounds |
//! | [`hull::brute_force_hull`] | Θ(n³) orientation tests |
//! | [`hull::jarvis_march`] | Θ(nh) for h hull vertices: O(n²) on points in convex position |
//! | [`hull::graham_scan`] | O(n log n); at most 2n − 4 orientation tests after sorting |
//! | [`hull::monotone_chain`] | O(n log n) |
//! | [`hull::akl_toussaint`] | O(n log n) worst case, O(n) expected on uniform input |
//! | [`hull::quickhull`] | O(n log n) expected, O(nh) worst case |
//! | [`hull::chan`] | O(n log h), output-sensitive |
//! | [`calipers::antipodal_pairs`] | Θ(n) on a convex polygon of n vertices, at most 3n/2 pairs |
//! | [`calipers::diameter`] | the hull's time plus Θ(h) |
//! | [`calipers::diameter_brute_force`] | Θ(n²) distance evaluations |
//! | [`calipers::width`], [`calipers::min_area_rectangle`] | the hull's time plus Θ(h) |
//! | [`spline::vandermonde`], [`spline::vandermonde_hermite`] | Θ(n³) for n conditions (dense elimination) |
//! | [`spline::lagrange`] (evaluation by the basis, or [`spline::LagrangeForm::aitken`]) | Θ(n²) per evaluation, n nodes |
//! | [`spline::newton`], [`spline::newton_hermite`] | Θ(n²) divided differences, Θ(n) per evaluation |
//! | [`spline::cubic_spline`] (natural, clamped, Bessel, periodic) | Θ(n), exactly 7n + 4 point operations (open ends) |
//! | [`spline::hermite`], [`spline::quadratic_spline`], [`spline::closed_quadratic_spline`] | Θ(n) |
//! | [`spline::fit_bezier`] | Θ(m n² + n³) for m points, degree n |
//! | [`spline::frenet_frame`] | Θ(d³) in R^d |
//! | [`delaunay::incremental`] | O(n log n) expected on every input (BRIO + Hilbert order) |
//! | [`delaunay::divide_and_conquer`] | O(n log n) worst case (Guibas–Stolfi merge) |
//! | [`delaunay::lawson`] | O(n²) worst case: Θ(n²) in-circle tests on a parabola |
//! | [`delaunay::fortune`] | O(n log n) expected (treap beach line, heap of circle events), exact event order |
//! | [`delaunay::check_delaunay`] | O(n log n + t), exact |
//! | [`delaunay::voronoi`] | the triangulation's time, then O(n log n) for the dual (a sort along a curve, then O(n)); clipping O(n) |
//! | [`delaunay::all_nearest_neighbours`] | O(n log n) expected; two distance evaluations per Delaunay edge |
//! | [`delaunay::closest_pair`] | O(n log n) expected; the shortest Delaunay edge |
//! | [`delaunay::closest_pair_divide_and_conquer`] | O(n log n) worst case, exact comparisons |
//! | [`delaunay::NearestSearch`] | O(n log n) to build; a greedy walk per query, O(√n) expected steps on uniform input |
//! | [`delaunay::euclidean_mst`] | O(n log n) expected; Delaunay edges ranked exactly, then Kruskal |
//! | [`delaunay::largest_empty_circle`] | O(n log n) expected on uniform-like input, O(nh) worst case |
//! | [`spline::Bezier::de_casteljau`] (degree n) | Θ(n²): exactly n(n+1)/2 affine combinations per point |
//! | [`spline::Bezier::horner`], [`spline::Curve::eval`] of a Bézier curve | Θ(n): n + 1 point operations per point |
//! | [`spline::Bezier::split`], [`spline::Bezier::blossom`], [`spline::CurveDerivative::derivative_at`] of a Bézier curve | Θ(n²) |
//! | [`spline::Bezier::elevate_to`] (degree n to m) | Θ(mn) |
//! | [`spline::Bezier::flatten`] | Θ(s·n²) for s segments, s = O(√(bound/tolerance)) |
//! | [`spline::intersections`] | O(k·d·(m² + n²)) for k crossings found at depth d |
//!
//! ## A first example
//!
//! Run an algorithm with a counter, and the predicates on inputs where floating point fails:
//!
//! ```
//! use compgeo::count::Counts;
//! use compgeo::geometry::{orient2d, Orientation, Point2};
//! use compgeo::sort::bubble_sort_with;
//!
//! let mut keys = [7, 3, 5, 1];
//! let mut counts = Counts::default();
//! bubble_sort_with(&mut keys, i32::cmp, &mut counts);
//! assert_eq!(keys, [1, 3, 5, 7]);
//! assert_eq!(counts.comparisons, 6); // n(n-1)/2, as the course counts it
//!
//! // (0,0), (1e300, 1e300) and a point one subnormal step right of the diagonal.
//! let (a, b) = (Point2::new(0.0, 0.0), Point2::new(1e300, 1e300));
//! assert_eq!(orient2d(a, b, Point2::new(5e-324, 0.0)), Orientation::Clockwise);
//! ```
//!
//! ## Conventions
//!
//! The plane is oriented with y up: a counter-clockwise turn is positive. Every finite `f64`
//! is valid input; NaN and infinities are rejected with [`Error::NonFinite`]. Sorting is the
//! exception: it orders every `f64`, NaN included, by [`f64::total_cmp`].

pub mod calipers;
pub mod complexity;
pub mod count;
pub mod delaunay;
pub mod error;
pub mod gen;
pub mod geometry;
pub mod graph;
pub mod hull;
pub mod sort;
pub mod spline;

#[cfg(feature = "cli")]
pub mod cli;

pub use error::{Error, Result};
