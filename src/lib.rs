//! # compgeo
//!
//! Exact computational-geometry and geometric-modelling algorithms that count their
//! operations and measure their own growth against their stated O-bounds: the report
//! ([`complexity`], `compgeo report`) measures all 167 declared algorithms in 209 catalog
//! entries, one per input distribution and size parameter.
//!
//! ## Module map
//!
//! | module | what it holds | files |
//! |---|---|---|
//! | [`geometry`] | [`Point2`](geometry::Point2), the validated [`PointSet`](geometry::PointSet) and its [`BoundingBox`](geometry::BoundingBox), exact predicates, [`PointPair`](geometry::PointPair), [`WideFloat`](geometry::WideFloat) for lengths beyond `f64` | `src/geometry/` |
//! | [`count`] | the [`Counter`](count::Counter) trait, [`Counts`](count::Counts), [`NoCount`](count::NoCount), [`Silent`](count::Silent) | `src/count.rs` |
//! | [`error`] | the crate's [`Error`] and [`Result`] | `src/error.rs` |
//! | [`limits`] | every size limit (degrees, vertex and edge counts, generated sizes), checked before allocating | `src/limits.rs` |
//! | [`gen`] | seeded workload generators: point sets, graphs, number sequences, polygon meshes | `src/gen/` |
//! | [`complexity`] | every algorithm's [`Declaration`](complexity::Declaration), stated bounds, the catalog, measurement, fits and verdicts | `src/complexity/` |
//! | [`sort`] | the course's sorts, O(n log n) references, radix sort for `f64`, step traces | `src/sort/`, one file per sort |
//! | [`graph`] | CSR graphs and their edge lists (DIMACS `.col` and plain edge lists in and out), BFS/DFS, colourings, minimum spanning trees | `src/graph/`: `colouring/` and `mst/` one file per algorithm |
//! | [`hull`] | convex hulls: brute force, Jarvis, Graham, monotone chain, Akl–Toussaint, Quickhull, Chan; exact checkers | `src/hull/`, one file per algorithm |
//! | [`calipers`] | rotating calipers on a [`ConvexPolygon`](calipers::ConvexPolygon): antipodal pairs, diameter, width, minimum-area rectangle; the diameter by brute force | `src/calipers/`, one file per problem |
//! | [`delaunay`] | Delaunay triangulations in half-edge arrays (incremental builder, the course's divide and conquer, Lawson's flips, Fortune's sweep), the exact checker, the Voronoi diagram and its clipping | `src/delaunay/`, one file per builder |
//! | [`proximity`] | closest pair (on the Delaunay triangulation, by divide and conquer), nearest search, all nearest neighbours, Euclidean MST, largest empty circle | `src/proximity/`, one file per problem |
//! | [`spline`] | curves, generic over the scalar (`f64`, exact rationals) and the dimension: the curve traits, [`spline::bezier`] (Bernstein basis, Bézier, reparametrised and composite curves, one algorithm per file), [`spline::bspline`] (knot vectors, the basis, de Boor, derivatives, blossoms, insertion, refinement, Oslo, removal, elevation, interpolation and fitting), [`spline::rational`] (rational Bézier curves, NURBS, exact conics), [`spline::interpolate`] (polynomial, Hermite and spline interpolation, least squares), [`spline::subdivision`] (Lane–Riesenfeld and Chaikin, the four-point scheme, masks and difference schemes, limit points), [`spline::beta`] (cubic Beta-splines: basis with the corrected normaliser, subdivision matrices at any c, recursive subdivision, β-continuity), Frenet frames | `src/spline/`: `bezier/`, `bspline/`, `rational/`, `interpolate/`, `subdivision/` and `beta/` one algorithm per file |
//! | [`surface`] | tensor-product and triangular surfaces sharing traits ([`Surface`](surface::Surface), [`SurfaceDerivative`](surface::SurfaceDerivative)): the validated [`ControlNet`](surface::ControlNet), [`BezierPatch`](surface::BezierPatch) evaluated in either order or by the tensor de Casteljau algorithm, isoparametric curves, partial derivatives, the blossom, restriction, subdivision, elevation, derivative nets, monomial form, bounding box and Cʳ joins; [`BSplineSurface`](surface::BSplineSurface) and [`NurbsSurface`](surface::NurbsSurface) (insertion, elevation, Bézier patches through the curve code); tensor interpolation, least squares, lofting, bicubic C¹ interpolation; tensor Lane–Riesenfeld subdivision of a regular net; [`normal`](surface::normal) of any surface, [`tessellate`](surface::tessellate) into a [`TriangleMesh`](surface::TriangleMesh) written as OBJ or STL; triangular Bézier patches ([`TriangularPatch`](surface::TriangularPatch), [`surface::triangle`]): the Bernstein basis, de Casteljau, the blossom, directional derivatives, subdivision and the four-way split, degree elevation, Cʳ joins, conversions to and from tensor-product patches, tessellation into the same meshes | `src/surface/`, one algorithm per file; `src/surface/triangle/` |
//! | [`mesh`] | polygon meshes generic over the scalar and the dimension: the validated [`PolygonMesh`](mesh::PolygonMesh) (oriented manifolds with boundary, every violation a named [`MeshError`](mesh::MeshError) with the face), its half-edge [`MeshTopology`](mesh::MeshTopology) (one-rings, valence, boundary loops, Euler characteristic), Wavefront OBJ reading and writing; subdivision surfaces by [`Scheme`](mesh::Scheme): Catmull–Clark on faces of any size with crease rules on the boundary, the midpoint scheme M₃, Loop (Loop's and Warren's weights) and Doo–Sabin; limit positions for Catmull–Clark and Loop | `src/mesh/`, one algorithm per file |
//! | [`trace`] | step traces: the [`Frame`](trace::Frame)s of an algorithm's own run (hulls, Lawson's flips, de Casteljau, Lane–Riesenfeld, the searches, greedy colouring, Prim, Kruskal), with the counts so far | `src/trace.rs`; each `_trace` function beside its algorithm |
//! | [`draw`] | SVG pictures of the geometric results (hull, calipers, Delaunay, Voronoi, closest pair, EMST, largest empty circle): the world → picture [`Frame`](draw::Frame), layers styled by [`Role`](draw::Role), labels and legend; not an algorithm, nothing declared | `src/draw/`, one file per kind of picture |
//! | `cli` (feature `cli`) | the `compgeo` command line: readers, JSON output, one file per command | `src/cli/` |
//!
//! Every algorithm's own file is in the table below.
//!
//! ## Features
//!
//! `cli` (default): the command line and the report. `serde`: `Serialize`/`Deserialize` for
//! result types. `exact`: the arbitrary-precision rational scalar. `parallel` (off by
//! default): the large batch paths use every core through rayon, from 2¹⁶ items up and only
//! when nothing is counted (runs with [`NoCount`](count::NoCount)), with results identical
//! to the sequential ones: the lexicographic point sort (the items distributed by their top
//! digit, then the buckets sorted in parallel), the `f64` radix sort from 2²¹ keys (the keys
//! partitioned in place by their top digit, each thread permuting its own share, then the
//! buckets sorted in parallel), the validation of a
//! [`PointSet`](geometry::PointSet), the Akl–Toussaint filter (and so the hulls that sort
//! through it), the incremental Delaunay builder (its insertion order, and from 2¹⁹ points
//! the two halves it splits the set into, built on two threads and merged), and the cells
//! of the Voronoi diagram (circumcentres and walks).
//!
//! ## Algorithms and their bounds
//!
//! Every algorithm is declared once, in its own file, as a
//! [`Declaration`](complexity::Declaration): its name, the problem it solves, its stated time
//! and space, what it counts, its source and the growth the report measures. This table, the
//! `Algorithm` enums, the command line's `--help` and the report's catalog all read it from
//! there (a test fails when this table differs). n is the input size (for graphs the number
//! of vertices, m the number of edges; h the size of the output, such as the hull's
//! vertices); bounds are worst case unless the row says otherwise. The file is one hop from
//! the algorithm.
//!
//! <!-- algorithms -->
//! | algorithm | time | space | counts | source | file |
//! |---|---|---|---|---|---|
//! | `predicate/orient2d`: [`geometry::orient2d`] | O(1) | O(1) | orientation tests: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/predicates.rs` |
//! | `predicate/incircle`: [`geometry::incircle`] | O(1) | O(1) | incircle tests: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/predicates.rs` |
//! | `predicate/cmp-dist`: [`geometry::cmp_dist`] | O(1) | O(1) | distance evaluations: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/predicates.rs` |
//! | `predicate/cross-sign`: [`geometry::cross_sign`] | O(1) | O(1) | orientation tests: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/predicates.rs` |
//! | `predicate/cmp-lex`: [`geometry::cmp_lex`] | O(1) | O(1) | comparisons: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/predicates.rs` |
//! | `predicate/cmp-line-dist`: [`geometry::cmp_line_dist`] | O(1) | O(1) | distance evaluations: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/products.rs` |
//! | `predicate/cmp-rect-area`: [`geometry::cmp_rect_area`] | O(1) | O(1) | distance evaluations: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/products.rs` |
//! | `predicate/cmp-rect-perimeter`: [`geometry::cmp_rect_perimeter`] | O(1) | O(1) | distance evaluations: one per call; calls the floating-point filter cannot decide also count as exact fallbacks | [Shewchuk, §4] | `src/geometry/products.rs` |
//! | `sort/bubble`: [`sort::bubble_sort`] | Θ(n²) | O(1) | comparisons: exactly n(n − 1)/2 comparisons | [RD, §2.1] | `src/sort/bubble.rs` |
//! | `sort/selection`: [`sort::selection_sort`] | Θ(n²) | O(1) | comparisons: exactly n(n − 1)/2 comparisons | [RD, §2.1] | `src/sort/selection.rs` |
//! | `sort/insertion`: [`sort::insertion_sort`] | Θ(n²) in the worst case and Θ(n) on sorted input | O(1) | comparisons: at most n(n − 1)/2 comparisons, n − 1 on sorted input | [RD, §2.1] | `src/sort/insertion.rs` |
//! | `sort/course-insertion`: [`sort::course_insertion_sort`] | Θ(n²) | O(1) | comparisons: n(n − 1)/2 comparisons on sorted input, as many moves on reversed input | [RD, §2.1] | `src/sort/course_insertion.rs` |
//! | `sort/binary-insertion`: [`sort::binary_insertion_sort`] | O(n²) worst case | O(1) | moves: at most ⌈log₂ k⌉ comparisons per step, one move per inversion | [RD, §2.1] | `src/sort/binary_insertion.rs` |
//! | `sort/course-binary-insertion`: [`sort::course_binary_insertion_sort`] | O(n²) worst case | O(1) | moves: ⌈log₂ k⌉ + 1 comparisons per step, one move per inversion | [RD, §2.1] | `src/sort/course_binary_insertion.rs` |
//! | `sort/merge`: [`sort::merge_sort`] | Θ(n log n) | O(n) | comparisons: at most n⌈log₂ n⌉ comparisons | [RD, §2.1] | `src/sort/merge.rs` |
//! | `sort/heap`: [`sort::heap_sort`] | O(n log n) worst case | O(1) | comparisons: at most 2n log₂ n comparisons | [RD, §2.1] | `src/sort/heap.rs` |
//! | `sort/quick`: [`sort::quick_sort`] | O(n log n) worst case | O(log n) | comparisons: at most 6n log₂ n + n comparisons | [RD, §2.1] | `src/sort/quick.rs` |
//! | `sort/radix-f64`: [`sort::radix_sort_f64`] | O(n) | O(n) | moves: at most 24n moves and 7.5n key comparisons | [RD, §2.1] | `src/sort/radix.rs` |
//! | `search/bfs`: [`graph::bfs`] | O(n + m) | O(n) | edge visits: exactly 2m edge visits on a connected graph | [RD, §2.1] | `src/graph/traverse.rs` |
//! | `search/dfs`: [`graph::dfs`] | O(n + m) | O(n) | edge visits: exactly 2m edge visits on a connected graph | [RD, §2.1] | `src/graph/traverse.rs` |
//! | `colour/course`: [`graph::course_greedy_colouring`] | O(n² + m) | O(n) | adjacency tests: exactly n(n − 1)/2 adjacency tests | [RD, §2.1] | `src/graph/colouring/course.rs` |
//! | `colour/greedy`: [`graph::greedy_colouring`] | O(n + m) | O(n) | edge visits: exactly 2m edge visits | [RD, §2.1] | `src/graph/colouring/greedy.rs` |
//! | `colour/largest-first`: [`graph::largest_first_order`] | O(n + m) | O(n) | edge visits: the greedy colouring's 2m edge visits | [RD, §2.1] | `src/graph/colouring/largest_first.rs` |
//! | `colour/smallest-last`: [`graph::smallest_last_order`] | O(n + m) | O(n) | edge visits: the greedy colouring's 2m edge visits | [RD, §2.1] | `src/graph/colouring/smallest_last.rs` |
//! | `colour/dsatur`: [`graph::dsatur`] | O((n + m) log n) | O(n + m) | comparisons: heap comparisons; exactly 2m edge visits | [RD, §2.1] | `src/graph/colouring/dsatur.rs` |
//! | `colour/dsatur-tabu`: [`graph::dsatur_tabu`] | O((n + m) log n) | O(n + m) | comparisons: DSatur's heap comparisons plus at most 20(n + 2m) search steps | [RD, §2.1] | `src/graph/colouring/tabu.rs` |
//! | `colour/hea`: [`graph::hea`] | O((n + m) log n) | O(n + m) | comparisons: DSatur's heap comparisons plus at most 20(n + 2m) search steps | [GH99, HEA] | `src/graph/colouring/hea.rs` |
//! | `mst/prim`: [`graph::prim`] | O(m log m) | O(n + m) | comparisons: heap comparisons; O(m log n) on simple graphs | [RD, §2.1] | `src/graph/mst/prim.rs` |
//! | `mst/kruskal`: [`graph::kruskal`] | O(m log m) | O(n + m) | comparisons: those of the edge sort, then one edge visit per edge examined | [RD, §2.1] | `src/graph/mst/kruskal.rs` |
//! | `mst/boruvka`: [`graph::boruvka`] | O(m log n) | O(n + m) | edge visits: at most ⌈log₂ n⌉ rounds over the remaining edges | [RD, §2.1] | `src/graph/mst/boruvka.rs` |
//! | `hull/brute-force`: [`hull::brute_force_hull`] | Θ(n³) | O(n) | orientation tests: m − 2 per ordered pair of the m distinct points that is an edge, fewer for the others | [RD, §2.2] | `src/hull/brute_force.rs` |
//! | `hull/jarvis`: [`hull::jarvis_march`] | Θ(nh) | O(h) | orientation tests: at most n − 1 per hull vertex | [RD, §2.2] | `src/hull/jarvis.rs` |
//! | `hull/graham`: [`hull::graham_scan`] | O(n log n) | O(n) | orientation tests: at most 2n − 4 in the scan after the sort | [RD, §2.2] | `src/hull/graham.rs` |
//! | `hull/monotone-chain`: [`hull::monotone_chain`] | O(n log n) | O(n) | comparisons: those of the sort, plus n − 1 to merge duplicates | [RD, §2.2] | `src/hull/monotone_chain.rs` |
//! | `hull/akl-toussaint`: [`hull::akl_toussaint`] | O(n log n) worst case, O(n) expected on uniform input | O(n) | comparisons: four per point for the filter box | [RD, §2.2] | `src/hull/akl_toussaint.rs` |
//! | `hull/quickhull`: [`hull::quickhull`] | O(nh) worst case, O(n log n) expected | O(n) | orientation tests | [RD, §2.2] | `src/hull/quickhull.rs` |
//! | `hull/chan`: [`hull::chan`] | O(n log h) | O(n) | orientation tests | [RD, §2.2] | `src/hull/chan.rs` |
//! | `diameter/calipers`: [`calipers::ConvexPolygon::diameter`] | Θ(h) after the hull | O(n) | distance evaluations: at most 3h/2 after the hull, one per antipodal pair | [RD, §2.3] | `src/calipers/diameter.rs` |
//! | `diameter/brute-force`: [`calipers::diameter_brute_force`] | Θ(n²) | O(1) | distance evaluations: exactly n(n − 1)/2 − 1 for n ≥ 2 | [RD, §2.3] | `src/calipers/diameter.rs` |
//! | `antipodal-pairs/calipers`: [`calipers::ConvexPolygon::antipodal_pairs`] | Θ(h) | O(h) | orientation tests: at most h, one exact direction test per step; at most 3h/2 pairs | [RD, §2.3] | `src/calipers/antipodal.rs` |
//! | `width/calipers`: [`calipers::ConvexPolygon::width`] | Θ(h) after the hull | O(1) | orientation tests: at most 9h for the calipers, and h − 1 exact distance comparisons | [RD, §2.3] | `src/calipers/width.rs` |
//! | `min-area-rectangle/calipers`: [`calipers::ConvexPolygon::min_area_rectangle`] | Θ(h) after the hull | O(1) | orientation tests: at most 9h for the calipers, and h − 1 exact area comparisons | [RD, §2.3] | `src/calipers/rectangle.rs` |
//! | `min-perimeter-rectangle/calipers`: [`calipers::ConvexPolygon::min_perimeter_rectangle`] | Θ(h) after the hull | O(1) | orientation tests: at most 9h for the calipers, and h − 1 exact perimeter comparisons | [RD, §2.3] | `src/calipers/perimeter_rectangle.rs` |
//! | `delaunay/incremental`: [`delaunay::incremental`] | O(n log n) expected on every input | O(n) | incircle tests: about 9 in-circle and 7 orientation tests per point on uniform input | [RD, §2.4] | `src/delaunay/incremental.rs` |
//! | `delaunay/divide-and-conquer`: [`delaunay::divide_and_conquer`] | O(n log n) in the worst case | O(n) | incircle tests: about 29 in-circle tests per point at 10⁵ uniform points | [RD, §2.4] | `src/delaunay/divide_conquer.rs` |
//! | `delaunay/lawson`: [`delaunay::lawson`] | O(n²) in the worst case | O(n) | incircle tests: one per edge check, Θ(n²) on a parabola | [RD, §2.4] | `src/delaunay/lawson.rs` |
//! | `delaunay/fortune`: [`delaunay::fortune`] | O(n log n) expected | O(n) | comparisons: the sort, the event queue and the breakpoint tests; no in-circle test | [RD, §2.4] | `src/delaunay/fortune.rs` |
//! | `voronoi/delaunay-dual`: [`delaunay::voronoi`] | O(n log n) expected | O(n) | incircle tests: those of the triangulation; the dual makes no geometric decision | [RD, §2.4] | `src/delaunay/voronoi.rs` |
//! | `check/delaunay`: [`delaunay::check_delaunay`] | O(n log n + t) | O(n + t) | incircle tests: exactly one per interior edge, 3n − 3 − 2h for n distinct points with h on the hull; one orientation test per triangle, then the hull's | [RD, §2.4] | `src/delaunay/check.rs` |
//! | `closest-pair/delaunay`: [`proximity::closest_pair_delaunay`] | O(n log n) expected | O(n) | incircle tests: those of the triangulation, then one distance evaluation per Delaunay edge | [RD, §2.4] | `src/proximity/closest_pair_delaunay.rs` |
//! | `closest-pair/divide-and-conquer`: [`proximity::closest_pair_divide_and_conquer`] | O(n log n) in the worst case | O(n) | distance evaluations: strip membership, height cut-offs and candidate pairs, all exact | [RD, §2.4] | `src/proximity/closest_pair_divide_and_conquer.rs` |
//! | `all-nearest-neighbours/delaunay`: [`proximity::all_nearest_neighbours`] | O(n log n) expected | O(n) | incircle tests: those of the triangulation, then two distance evaluations per Delaunay edge | [RD, §2.4] | `src/proximity/all_nearest.rs` |
//! | `nearest/delaunay-walk`: [`proximity::NearestSearch::nearest`] | O(n log n) to build; O(1) expected steps per query on uniform points, O(n) worst | O(n) | distance evaluations: one per neighbour looked at during a walk, about six per step | [RD, §2.4] | `src/proximity/nearest.rs` |
//! | `emst/delaunay-kruskal`: [`proximity::euclidean_mst`] | O(n log n) expected | O(n) | distance evaluations: those of the exact length sort, after the triangulation's tests | [RD, §2.4] | `src/proximity/emst.rs` |
//! | `empty-circle/voronoi`: [`proximity::largest_empty_circle`] | O(n log n) expected on uniform-like input, O(nh) worst case | O(n) | orientation tests: the hull tests of the Voronoi vertices, O(log h) each | [RD, §2.4] | `src/proximity/empty_circle.rs` |
//! | `bezier/de-casteljau`: [`spline::Bezier::de_casteljau`] | Θ(n²D) | O(nD) | arithmetic operations: exactly n(n + 1)/2 affine combinations per point | [PPB, §2.3] | `src/spline/bezier/de_casteljau.rs` |
//! | `bezier/horner`: [`spline::Bezier::horner`] | Θ(nD) | O(D) | arithmetic operations: n + 1 point operations per point | [PPB, §2.3] | `src/spline/bezier/horner.rs` |
//! | `bezier/split`: [`spline::Bezier::split`] | Θ(n²D) | O(nD) | arithmetic operations: exactly n(n + 1)/2 affine combinations (one triangle) | [PPB, §3.3] | `src/spline/bezier/de_casteljau.rs` |
//! | `bezier/blossom`: [`spline::Bezier::blossom`] | Θ(n²D) | O(nD) | arithmetic operations: exactly n(n + 1)/2 affine combinations per value | [PPB, §3.2] | `src/spline/bezier/de_casteljau.rs` |
//! | `bezier/elevate-to`: [`spline::Bezier::elevate_to`] | Θ(m·n·D) | Θ(mD) | arithmetic operations: exactly (n + 1)(m − n + 1) terms bᵢ·wᵢ | [PPB, §3.12] | `src/spline/bezier/elevation.rs` |
//! | `bezier/flatten`: [`spline::Bezier::flatten`] | Θ(s·n²D) | O(kn·D) | arithmetic operations: exactly (s − 1)·n(n + 1)/2 affine combinations: one split at ½ per segment but one | [PPB, §3.5] | `src/spline/bezier/flatten.rs` |
//! | `bezier/intersections`: [`spline::intersections`] | O(k·d·(m² + n²)) | O(d(m + n)) | arithmetic operations: n(n + 1)/2 affine combinations per halving of a piece of degree n; four orientation tests per pair of flat pieces whose boxes meet | [PPB, §3.7] | `src/spline/bezier/intersect.rs` |
//! | `interpolate/vandermonde`: [`spline::vandermonde`] | Θ(n³ + n²·D) | Θ(n² + n·D) | arithmetic operations: one per entry changed by elimination and per back-substitution term: exactly (N − 1)N(2N − 1)/6 + N(N − 1) + N(N + 1)/2 for N = n + 1 nodes when no entry vanishes | [RD, §3.1] | `src/spline/interpolate/polynomial.rs` |
//! | `interpolate/vandermonde-hermite`: [`spline::vandermonde_hermite`] | Θ(N³ + N²·D) | Θ(N² + N·D) | arithmetic operations: as the Vandermonde solve's for N conditions, less where an entry below a pivot is zero | [PPB, §4.4] | `src/spline/interpolate/polynomial.rs` |
//! | `interpolate/lagrange`: [`spline::lagrange`] | Θ(n log n + nD) | Θ(nD) | comparisons: the comparisons of the distinctness check: a sort of the nodes, then n | [PPB, §4.2] | `src/spline/interpolate/lagrange.rs` |
//! | `interpolate/aitken`: [`spline::LagrangeForm::aitken`] | Θ(n²D) | Θ(nD) | arithmetic operations: exactly n(n + 1)/2 affine combinations for n + 1 nodes | [PPB, §4.2] | `src/spline/interpolate/lagrange.rs` |
//! | `interpolate/newton`: [`spline::newton`] | Θ(n²·D) | Θ(n·D) | arithmetic operations: exactly n(n + 1)/2 divided differences of points for n + 1 nodes | [PPB, §4.3] | `src/spline/interpolate/newton.rs` |
//! | `interpolate/newton-hermite`: [`spline::newton_hermite`] | Θ(N²·D) | Θ(N·D) | arithmetic operations: exactly N(N − 1)/2 entries of the table for N conditions: differences, or derivatives over factorials | [PPB, §4.4] | `src/spline/interpolate/newton.rs` |
//! | `interpolate/hermite`: [`spline::hermite`] | Θ(m·D) | Θ(m·D) | arithmetic operations: exactly 2m point multiply-adds for m pieces: two inner Bézier points each | [RD, §3.2] | `src/spline/interpolate/hermite.rs` |
//! | `interpolate/quadratic-spline`: [`spline::quadratic_spline`] | Θ(N·D) | Θ(N·D) | arithmetic operations: exactly N point operations for N pieces: one per inner Bézier point | [SPL, §2] | `src/spline/interpolate/quadratic_spline.rs` |
//! | `interpolate/closed-quadratic-spline`: [`spline::closed_quadratic_spline`] | Θ(N·D) | Θ(N·D) | arithmetic operations: exactly 2N point operations for N pieces: N − 1 for the recurrence, one for the closing condition, N for the inner points | [SPL, §2] | `src/spline/interpolate/quadratic_spline.rs` |
//! | `interpolate/cubic-spline`: [`spline::cubic_spline`] | Θ(n·D) | Θ(n·D) | arithmetic operations: the tangents' 7n + 4 point operations (at most 8n periodic), then the Hermite pieces' 2n | [RD, §3.1] | `src/spline/interpolate/cubic_spline.rs` |
//! | `spline/cubic-natural`: [`spline::cubic_spline_tangents`] | Θ(n·D) | Θ(n·D) | arithmetic operations: exactly 7n + 4 point operations | [RD, §3.1] | `src/spline/interpolate/cubic_spline.rs` |
//! | `spline/cubic-periodic`: [`spline::cubic_spline_tangents`] | Θ(n·D) | Θ(n·D) | arithmetic operations: Θ(n) point operations | [RD, §3.1] | `src/spline/interpolate/cubic_spline.rs` |
//! | `fit/least-squares`: [`spline::fit_bezier`] | Θ(m·n² + n³ + m·n·D) | Θ(n² + m·n + n·D) | arithmetic operations: (n + 1)(n + 2) per data point for the normal equations, then the dense solve's count for n + 1 unknowns | [PPB, §4.7] | `src/spline/interpolate/least_squares.rs` |
//! | `bspline/span`: [`spline::KnotVector::span`] | O(log(n − d)) | O(1) | comparisons: at most ⌈log₂(n − d + 1)⌉ + 1 comparisons with knots, plus 2 for the domain | [PPB, §5.4] | `src/spline/bspline/knots.rs` |
//! | `bspline/basis`: [`spline::KnotVector::basis`] | Θ(d²) | O(d) | arithmetic operations: exactly d(d + 1)/2 steps of the triangular scheme | [PPB, §5.3] | `src/spline/bspline/basis.rs` |
//! | `bspline/basis-derivatives`: [`spline::KnotVector::basis_derivatives`] | O(d² + d·K²) | O((k + 1)(d + 1)) | arithmetic operations: exactly d(d + 1)/2 + (d + 1)·K(K + 3)/2 steps, K = min(k, d) | [PPB, §5.7] | `src/spline/bspline/basis.rs` |
//! | `bspline/de-boor`: [`spline::BSpline::de_boor`] | Θ(d²D) | O(dD) | arithmetic operations: exactly d(d + 1)/2 affine combinations per point off the knots, (d − r)(d − r + 1)/2 at a knot of multiplicity r | [PPB, §5.4] | `src/spline/bspline/de_boor.rs` |
//! | `bspline/derivatives`: [`spline::BSpline::derivatives`] | Θ((d² + K³)D), K = min(k, d) | O((d + k)D) | arithmetic operations: exactly d(d + 1)/2 affine combinations and K(K + 1)(K + 2)/6 differences | [PPB, §5.9] | `src/spline/bspline/derivatives.rs` |
//! | `bspline/insert`: [`spline::BSpline::insert`] | Θ((n + d + rd)D) | O((n + d + r)D) | arithmetic operations: exactly r(d − s) − r(r − 1)/2 affine combinations, s the knot's multiplicity before | [PPB, §6.1] | `src/spline/bspline/insert.rs` |
//! | `bspline/to-bezier`: [`spline::BSpline::to_bezier`] | Θ(n + d + p·d·D) plus O(n·d²·D) | Θ(p·d·D) | arithmetic operations: exactly Σ (d − m)(d − m + 1)/2 affine combinations over the distinct knots in the domain, m the multiplicity (at most d) | [PPB, §5.10] | `src/spline/bspline/to_bezier.rs` |
//! | `bspline/from-bezier`: [`spline::BSpline::from_bezier`] | Θ(p·d·D) | Θ(p·d·D) | moves: exactly p·d + 1 control points copied (p for degree 0), and p − 1 comparisons of end points | [PPB, §5.10] | `src/spline/bspline/to_bezier.rs` |
//! | `bspline/elevate`: [`spline::BSpline::elevate`] | Θ((n + p·t)(d + t)²·D) | O((n + p·(d + t))D) | arithmetic operations: the conversion's, (d + 1)(t + 1) Zhou terms per piece and exactly (d + t)(d + t + 1)/2 affine combinations per new control point | [PPB, §6.4] | `src/spline/bspline/elevate.rs` |
//! | `bspline/blossom`: [`spline::BSpline::blossom`] | Θ(d²D) | O(dD) | arithmetic operations: exactly d(d + 1)/2 affine combinations per value | [PPB, §5.5] | `src/spline/bspline/blossom.rs` |
//! | `bspline/greville`: [`spline::KnotVector::greville`] | Θ(nd) | Θ(n) | arithmetic operations: exactly n·d: one per knot in a mean (n for degree 0) | [PPB, §5.8] | `src/spline/bspline/greville.rs` |
//! | `bspline/marsden`: [`spline::KnotVector::marsden`] | Θ(nd) | Θ(n) | arithmetic operations: exactly n·d: one per factor of a product | [PPB, §5.12, Ex. 4] | `src/spline/bspline/greville.rs` |
//! | `bspline/integral`: [`spline::BSpline::integral`] | Θ((n + d)D) | Θ((n + d)D) | arithmetic operations: exactly n running sums; where t₀ < t_d also de Boor's evaluation at t_d and n + 1 shifts | [PPB, §5.6, §5.12 Ex. 2] | `src/spline/bspline/integral.rs` |
//! | `bspline/eval-sorted`: [`spline::BSpline::eval_sorted`] | Θ(m·d²D + n) | O(dD) | arithmetic operations: exactly de Boor's affine combinations at each parameter; at most m + n comparisons for the walk | [PPB, §5.4] | `src/spline/bspline/batch.rs` |
//! | `bspline/refine`: [`spline::BSpline::refine`] | O(m log m + log n + (n + m + md)D) | O((n + m)D) | arithmetic operations: exactly Σ r(d − s) − r(r − 1)/2 affine combinations over the distinct new knots (r new copies, s old ones): md for new simple knots | [PPB, §6.1–6.2] | `src/spline/bspline/refine.rs` |
//! | `bspline/oslo`: [`spline::BSpline::oslo`] | O(m log m + (n + m)D + md(d² + dD + log n)) | O((n + m)D) | arithmetic operations: exactly q(d(d + 1)/2 + d + 1) operations, q ≤ md the new control points that are not copies | [PPB, §6.2] | `src/spline/bspline/oslo.rs` |
//! | `bspline/remove`: [`spline::BSpline::remove`] | O(r²(n + d)D) | O((n + d)D) | arithmetic operations: per removal of a knot of multiplicity s ≤ d: d − s solved points, and d − sᵢ + 1 combinations per re-inserted copy of multiplicity sᵢ | [PPB, §6.1] | `src/spline/bspline/remove.rs` |
//! | `bspline/split`: [`spline::BSpline::split`] | Θ((n + d²)D) | O((n + d²)D) | arithmetic operations: exactly (d − s)(d − s + 1)/2 affine combinations, s ≤ d the multiplicity of u (none at d + 1) | [PPB, §6.1] | `src/spline/bspline/split.rs` |
//! | `bspline/banded-solve`: [`spline::BandMatrix::solve`] | Θ(n·l·(u + D)) | Θ(n(l + u + 1)) | arithmetic operations: exactly Σₖ rₖ(wₖ + 2) + Σₖ (wₖ + 1), rₖ = min(l, n − 1 − k), wₖ = min(u, n − 1 − k) | [PPB, §6.7] | `src/spline/bspline/banded.rs` |
//! | `bspline/interpolate`: [`spline::BSpline::interpolate_at`] | Θ(n d² + n D d) | Θ(n(d + D)) | arithmetic operations: exactly n·d(d + 1)/2 basis steps plus the banded solve's count with l = u = d | [PPB, §6.7] | `src/spline/bspline/interpolate.rs` |
//! | `bspline/fit`: [`spline::BSpline::fit`] | Θ(m d² + m d D + n d² + m log m) | Θ(n(d + D) + m) | arithmetic operations: m·d(d + 1)/2 basis steps, (d + 1)(d + 2) per parameter for the normal equations, then the banded solve's count with l = u = d | [PPB, §4.7] | `src/spline/bspline/fit.rs` |
//! | `bspline/cubic-spline`: [`spline::BSpline::cubic_spline`] | Θ(N·D) | Θ(N·D) | arithmetic operations: exactly 6(N + 1) + 5(N + 2) + 1: the basis values of the N + 1 data rows (6 each) and the tridiagonal solve of the N + 3 rows | [SPL, §3] | `src/spline/bspline/cubic.rs` |
//! | `rational-bezier/de-casteljau`: [`spline::RationalBezier::de_casteljau`] | Θ(n²D) | O(nD) | arithmetic operations: exactly n(n + 1) affine combinations per point: n(n + 1)/2 on the weighted points and as many on the weights | [SPL, §14] | `src/spline/rational/bezier.rs` |
//! | `nurbs/de-boor`: [`spline::Nurbs::de_boor`] | Θ(d²D) | O(dD) | arithmetic operations: exactly d(d + 1) affine combinations per point off the knots, (d − r)(d − r + 1) at a knot of multiplicity r | [SPL, §14] | `src/spline/rational/nurbs.rs` |
//! | `nurbs/insert`: [`spline::Nurbs::insert`] | Θ((n + d + rd)D) | O((n + d + r)D) | arithmetic operations: exactly 2(r(d − s) − r(r − 1)/2) affine combinations, s the knot's multiplicity before | [SPL, §14] | `src/spline/rational/nurbs.rs` |
//! | `nurbs/refine`: [`spline::Nurbs::refine`] | O(m log m + log n + (n + m + md)D) | O((n + m)D) | arithmetic operations: B-spline refinement's count, as two curves | [SPL, §14] | `src/spline/rational/linear.rs` |
//! | `nurbs/elevate`: [`spline::Nurbs::elevate`] | Θ((n + p·t)(d + t)²·D) | O((n + p·(d + t))D) | arithmetic operations: B-spline elevation's count for D + 1 coordinates, as two curves | [SPL, §14] | `src/spline/rational/linear.rs` |
//! | `nurbs/to-bezier`: [`spline::Nurbs::to_bezier`] | Θ(n + d + p·d·D) plus O(n·d²·D) | Θ(p·d·D) | arithmetic operations: B-spline conversion's count, as two curves | [SPL, §14] | `src/spline/rational/linear.rs` |
//! | `subdivision/lane-riesenfeld`: [`spline::subdivision::lane_riesenfeld`] | Θ(d·N), N ≤ n·2^k the output size | Θ(N·D) | arithmetic operations: one per midpoint: 2dm per round on a closed polygon of m vertices, 2dm − d(d + 1)/2 on an open one | [PPB, §8.2–8.4] | `src/spline/subdivision/lane_riesenfeld.rs` |
//! | `subdivision/four-point`: [`spline::subdivision::four_point`] | Θ(N), N ≤ n·2^k the output size | Θ(N·D) | arithmetic operations: one per inserted point and per ghost point: m per round on a closed polygon of m vertices, m + 1 on an open one | [PPB, §8.9, §8.10] | `src/spline/subdivision/four_point.rs` |
//! | `subdivision/mask`: [`spline::subdivision::Mask::refine`] | Θ(L·N) | Θ(N·D) | arithmetic operations: one per non-zero mask coefficient used: (number of non-zero coefficients)·m for a closed polygon of m vertices, per round | [PPB, §8.4, §8.8] | `src/spline/subdivision/mask.rs` |
//! | `subdivision/limit-points`: [`spline::subdivision::limit_points`] | Θ(d² + n·d·D) | Θ(d + n·D) | arithmetic operations: one per stencil term: (2⌊d/2⌋ + 1) per limit point | [PPB, §8.1, §8.3] | `src/spline/subdivision/limit.rs` |
//! | `subdivision/difference`: [`spline::subdivision::Mask::difference`] | Θ(L) | Θ(L) | arithmetic operations: one per coefficient of the quotient and one for the remainder: L | [PPB, §8.8] | `src/spline/subdivision/difference.rs` |
//! | `beta-spline/basis`: [`spline::BetaParameters::basis`] | O(1) | O(1) | arithmetic operations: exactly 16 arithmetic operations (12 Horner steps, 4 divisions by δ) | [CCKS, §3] | `src/spline/beta/basis.rs` |
//! | `beta-spline/eval`: [`spline::BetaSpline::eval`] | O(log m + D) | O(D) | comparisons: ⌊lg m⌋ or ⌈lg m⌉ comparisons to find the segment, then exactly 20 arithmetic operations | [CCKS, §3] | `src/spline/beta/curve.rs` |
//! | `beta-spline/subdivision-matrices`: [`spline::BetaParameters::subdivision_matrices`] | O(1) | O(1) | arithmetic operations: exactly 256 multiply-adds (four 4 × 4 products), besides one 4 × 4 inversion | [CCKS, §2, eq. (7)–(8)] | `src/spline/beta/matrices.rs` |
//! | `beta-spline/subdivide`: [`spline::BetaSpline::subdivide`] | Θ(m·2ᵏ·D) | Θ(m·2ᵏ·D) | arithmetic operations: exactly 32·m·(2ᵏ − 1) point combinations besides the matrices' 256 | [CCKS, §2–3] | `src/spline/beta/subdivide.rs` |
//! | `beta-spline/beta-continuity`: [`spline::is_beta_continuous`] | O(D) | O(D) | arithmetic operations: exactly 3 point operations (β₁Q⁻′ and the two terms of β₁²Q⁻″ + β₂Q⁻′), then at most 3 comparisons of points | [CCKS, §3] | `src/spline/beta/continuity.rs` |
//! | `frenet/frame`: [`spline::frenet_frame`] | Θ(r²·D) | Θ(r·D) | arithmetic operations: one per projection of a residual, 2·Σ i = r(r − 1) for r independent derivatives, and with r = D one per entry changed by the orientation's elimination, (D − 1)D(D + 1)/3 | [PPB, §7.6] | `src/spline/frenet.rs` |
//! | `bezier-patch/rows-first`: [`surface::BezierPatch::rows_first`] | Θ(((m + 1)n² + m²)D) | O((m + n)D) | arithmetic operations: exactly (m + 1)n(n + 1)/2 + m(m + 1)/2 affine combinations | [FJ-surfaces, §2], [PPB, §9.2] | `src/surface/bezier.rs` |
//! | `bezier-patch/columns-first`: [`surface::BezierPatch::columns_first`] | Θ(((n + 1)m² + n²)D) | O((m + n)D) | arithmetic operations: exactly (n + 1)m(m + 1)/2 + n(n + 1)/2 affine combinations | [FJ-surfaces, §2], [PPB, §9.2] | `src/surface/bezier.rs` |
//! | `bezier-patch/de-casteljau`: [`surface::BezierPatch::de_casteljau`] | Θ((mn·min(m, n) + |m − n|²)D) | Θ(mn·D) | arithmetic operations: three affine combinations per bilinear step, Σₖ₌₁ᵏ (m − k + 1)(n − k + 1) steps for k = min(m, n), then the univariate ones | [PPB, §9.5] | `src/surface/bezier.rs` |
//! | `bezier-patch/blossom`: [`surface::BezierPatch::blossom`] | Θ(((m + 1)n² + m²)D) | O((m + n)D) | arithmetic operations: exactly (m + 1)n(n + 1)/2 + m(m + 1)/2 affine combinations | [PPB, §9.3], [FJ-surfaces, §4] | `src/surface/blossom.rs` |
//! | `bezier-patch/restrict`: [`surface::BezierPatch::restrict`] | Θ((m + 1)(n + 1)(m + n)D) | Θ(mnD) | arithmetic operations: exactly (m + 1)n(n + 1) + (n + 1)m(m + 1) affine combinations | [FJ-surfaces, §4], [PPB, §9.3] | `src/surface/subdivide.rs` |
//! | `bezier-patch/split-u`: [`surface::BezierPatch::split_u`] | Θ((n + 1)m²D) | Θ(mnD) | arithmetic operations: exactly (n + 1)m(m + 1)/2 affine combinations | [PPB, §9.5], [PPB, §3.3] | `src/surface/subdivide.rs` |
//! | `bezier-patch/split-v`: [`surface::BezierPatch::split_v`] | Θ((m + 1)n²D) | Θ(mnD) | arithmetic operations: exactly (m + 1)n(n + 1)/2 affine combinations | [PPB, §9.5], [PPB, §3.3] | `src/surface/subdivide.rs` |
//! | `bezier-patch/split`: [`surface::BezierPatch::split`] | Θ(((n + 1)m² + (m + 1)n²)D) | Θ(mnD) | arithmetic operations: exactly (n + 1)m(m + 1)/2 + (m + 1)n(n + 1) affine combinations | [PPB, §9.5], [PPB, §3.3] | `src/surface/subdivide.rs` |
//! | `bezier-patch/elevate-to`: [`surface::BezierPatch::elevate_to`] | Θ(((n + 1)(m + 1)(p − m + 1) + (p + 1)(n + 1)(q − n + 1))D) | Θ(pqD) | arithmetic operations: exactly (n + 1)(m + 1)(p − m + 1) terms if p > m, plus (p + 1)(n + 1)(q − n + 1) if q > n | [FJ-surfaces, §5], [PPB, §3.12] | `src/surface/elevate.rs` |
//! | `bezier-patch/derivative-net`: [`surface::BezierPatch::derivative_net`] | Θ((r·m·n + s·m·n)D) | Θ(mnD) | arithmetic operations: exactly (n + 1)(r(m + 1) − r(r + 1)/2) + (m − r + 1)(s(n + 1) − s(s + 1)/2) differences and (m − r + 1)(n − s + 1) scalings (r ≤ m, s ≤ n) | [FJ-surfaces, §6], [PPB, §9.6] | `src/surface/derivative.rs` |
//! | `bezier-patch/to-monomial`: [`surface::BezierPatch::to_monomial`] | Θ(((n + 1)m² + (m + 1)n²)D) | Θ(mnD) | arithmetic operations: exactly (n + 1)(m + 1)(m + 2)/2 + (m + 1)(n + 1)(n + 2)/2 differences and scalings | [PPB, §9.4], [PPB, §2.9] | `src/surface/monomial.rs` |
//! | `bezier-patch/from-monomial`: [`surface::BezierPatch::from_monomial`] | Θ(((n + 1)m² + (m + 1)n²)D) | Θ(mnD) | arithmetic operations: exactly (n + 1)(m + 1)(m + 4)/2 + (m + 1)(n + 1)(n + 4)/2 scalings and multiply-adds | [PPB, §9.4], [PPB, §2.8] | `src/surface/monomial.rs` |
//! | `bezier-patch/bounding-box`: [`surface::BezierPatch::bounding_box`] | Θ(mnD) | O(D) | comparisons: exactly 2D((m + 1)(n + 1) − 1) comparisons | [PPB, §9.2], [FJ-surfaces, §3] | `src/surface/bounds.rs` |
//! | `bezier-patch/join-u`: [`surface::BezierPatch::join_u`] | Θ((n + 1)(m² + m̃²)D) | O((m + m̃)D) | arithmetic operations: exactly (n + 1)(m(m + 1)/2 + m̃(m̃ + 1)/2 + m + m̃ + 2) differences and scalings | [FJ-surfaces, §6], [PPB, §9.7] | `src/surface/join.rs` |
//! | `bezier-patch/join-v`: [`surface::BezierPatch::join_v`] | Θ((m + 1)(n² + ñ²)D) | Θ(mnD) | arithmetic operations: exactly (m + 1)(n(n + 1)/2 + ñ(ñ + 1)/2 + n + ñ + 2) differences and scalings | [FJ-surfaces, §6], [PPB, §9.7] | `src/surface/join.rs` |
//! | `bezier-patch/extend-cr-u`: [`surface::BezierPatch::extend_cr_u`] | Θ((n + 1)m²D) | Θ(mnD) | arithmetic operations: exactly (n + 1)m(m + 1) affine combinations (two subdivisions per column) | [PPB, §9.7], [PPB, §3.10] | `src/surface/join.rs` |
//! | `bezier-patch/extend-cr-v`: [`surface::BezierPatch::extend_cr_v`] | Θ((m + 1)n²D) | Θ(mnD) | arithmetic operations: exactly (m + 1)n(n + 1) affine combinations (two subdivisions per row) | [PPB, §9.7], [PPB, §3.10] | `src/surface/join.rs` |
//! | `surface/normal`: [`surface::normal`] | Θ(E) for E the cost of one partial derivative | O(1) | arithmetic operations: one per partial derivative taken: exactly 2 at a regular point, 5 at a degenerate one | [FJ-surfaces, §6] | `src/surface/normal.rs` |
//! | `surface/tessellate`: [`surface::tessellate`] | Θ(N·E) for N vertices and E the cost of an evaluation | Θ(N) | arithmetic operations: exactly three surface evaluations per vertex (the point and the two first partials) | [FJ-surfaces, §2] | `src/surface/tessellate.rs` |
//! | `bspline-surface/tensor-de-boor`: [`surface::BSplineSurface::de_boor`] | Θ((p² + p·q²)D) | O((p + q)D) | arithmetic operations: (p + 1)·q(q + 1)/2 affine combinations off the v knots, plus the basis values' p(p + 1) operations | [PPB, §9.1, §5.4], [FJ-surfaces, §2] | `src/surface/bspline.rs` |
//! | `bspline-surface/insert`: [`surface::BSplineSurface::insert`] | Θ(M(N + q + rq)D) in v | Θ(M(N + r)D) | arithmetic operations: M times the curve's r(q − s) − r(r − 1)/2 affine combinations in v (N times, with p, in u) | [PPB, §6.1, §9.1] | `src/surface/bspline_insert.rs` |
//! | `bspline-surface/refine`: [`surface::BSplineSurface::refine`] | O(M(m log m + log N + (N + m + mq)D)) in v | Θ(M(N + m)D) | arithmetic operations: M times the curve refinement's affine combinations in v (N times in u) | [PPB, §6.1–6.2, §9.1] | `src/surface/bspline_insert.rs` |
//! | `bspline-surface/to-bezier`: [`surface::BSplineSurface::to_bezier`] | O((M·N·q² + Q·q·M·p²)D) | Θ(P·Q·(p + 1)(q + 1)D) | arithmetic operations: those of the curve conversion on the M rows, then on the Q(q + 1) columns of the pieces | [PPB, §5.10, §9.2] | `src/surface/bspline_to_bezier.rs` |
//! | `bspline-surface/elevate`: [`surface::BSplineSurface::elevate`] | Θ(M(N + Q·t)(q + t)²·D) in v | Θ(M(N + Q·t)D) | arithmetic operations: M times the curve elevation's in v (N times in u) | [PPB, §6.4–6.5, §9.1] | `src/surface/bspline_elevate.rs` |
//! | `bspline-surface/isoparametric`: [`surface::BSplineSurface::isocurve`] | Θ(M·q²·D) at v₀, Θ(p² + p·N·D) at u₀ | Θ(M·D) or Θ(N·D) | arithmetic operations: those of de Boor's algorithm on each row, or of the basis plus one per point and row | [FJ-surfaces, §2], [PPB, §9.1] | `src/surface/bspline_iso.rs` |
//! | `nurbs-surface/tensor-de-boor`: [`surface::NurbsSurface::de_boor`] | Θ((p² + p·q²)D) | O((p + q)D) | arithmetic operations: those of the B-spline surface evaluation, twice | [SPL, §14], [PPB, §9.1] | `src/surface/nurbs.rs` |
//! | `bspline-surface/grid`: [`surface::BSplineSurface::eval_grid`] | Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²) | Θ(N_u·N_v·D) | arithmetic operations: one multiply-add of points per term: (q + 1) per point and N(p + 1) per u, plus the basis values' p(p + 1)/2 per u and q(q + 1)/2 per v | [FJ-surfaces, §1–2], [PPB, §9.1] | `src/surface/tensor_grid.rs` |
//! | `nurbs-surface/grid`: [`surface::NurbsSurface::eval_grid`] | Θ((N_u·N_v·(q + 1) + N_u·N·(p + 1))D + N_u·p² + N_v·q²) | Θ(N_u·N_v·D) | arithmetic operations: those of the two B-spline grids (the weighted points and the weights) and one per division | [FJ-surfaces, §1–2], [SPL, §14] | `src/surface/tensor_grid.rs` |
//! | `surface-construct/interpolate`: [`surface::BSplineSurface::interpolate_at`] | Θ(M·N·(p² + q² + (p + q)D)) | Θ(MN·D) | arithmetic operations: those of the M curve interpolations in v and the N in u | [FJ-surfaces, §7], [PPB, §6.7, §9.1] | `src/surface/interpolate.rs` |
//! | `surface-construct/least-squares`: [`surface::BSplineSurface::fit`] | Θ(K(p + 1)²(q + 1)² + (MN)³ + (MN)²D) | Θ((MN)² + MN·D) | arithmetic operations: one per entry of the normal equations updated, one per entry changed by elimination and per back-substitution term | [FJ-surfaces, §7, eqs. (28)–(29)] | `src/surface/least_squares.rs` |
//! | `surface-construct/loft`: [`surface::BSplineSurface::loft`] | Θ(N·K(p² + pD)) after making the curves compatible | Θ(K·N·D) | arithmetic operations: those of the curve interpolations in the lofting direction | [RD, §3.3] | `src/surface/loft.rs` |
//! | `surface-construct/bicubic-c1`: [`surface::BezierPatchGrid::bicubic_c1`] | Θ(mn·D) | Θ(mn·D) | arithmetic operations: one per Bézier point the curve scheme produces, (3m + 1)(n + 1) + (3m + 1)(3n + 1) | [PPB, §9.8, §4.5] | `src/surface/bicubic.rs` |
//! | `subdivision-surface/tensor-lane-riesenfeld`: [`surface::ControlNet::lane_riesenfeld`] | Θ((p + q)·M′N′), M′N′ ≤ MN·4^k the output size | Θ(M′N′·D) | arithmetic operations: the curve algorithm's midpoints on the M rows, then on the N′ columns: 2(2^k − 1)(qMN + pMN·2^k) on a torus | [PPB, §15.1, §8.2–8.4] | `src/surface/lane_riesenfeld.rs` |
//! | `subdivision-surface/tensor-limit-points`: [`surface::ControlNet::limit_points`] | Θ(p² + q² + (p + q)·MN·D) | Θ(MN·D) | arithmetic operations: the curve's stencil terms on the rows, then on the columns: (2⌊q/2⌋ + 1)MN + (2⌊p/2⌋ + 1)MN on a torus | [PPB, §8.1, §15.1] | `src/surface/lane_riesenfeld.rs` |
//! | `triangular-patch/de-casteljau`: [`surface::TriangularPatch::de_casteljau`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly n(n + 1)(n + 2)/6 affine combinations of three points | [PPB, §10.4] | `src/surface/triangle/de_casteljau.rs` |
//! | `triangular-patch/bernstein-sum`: [`surface::TriangularPatch::bernstein_sum`] | Θ(n²D) | Θ(n²) | arithmetic operations: exactly (n + 1)(n + 2)/2 multiply-adds of points | [PPB, §10.1–10.2] | `src/surface/triangle/basis.rs` |
//! | `triangular-patch/blossom`: [`surface::TriangularPatch::blossom`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly n(n + 1)(n + 2)/6 affine combinations of three points | [PPB, §11.1–11.2] | `src/surface/triangle/blossom.rs` |
//! | `triangular-patch/derivative`: [`surface::TriangularPatch::directional_derivative`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly n(n + 1)(n + 2)/6 combinations of three points and one scaling for 1 ≤ r ≤ n | [PPB, §10.5], [PPB, §11.6] | `src/surface/triangle/derivative.rs` |
//! | `triangular-patch/subdivide`: [`surface::TriangularPatch::subdivide`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly n(n + 1)(n + 2)/6 affine combinations of three points | [PPB, §11.3] | `src/surface/triangle/subdivide.rs` |
//! | `triangular-patch/split-four`: [`surface::TriangularPatch::split_four`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly n(n + 1)(n + 2) affine combinations of three points (six de Casteljau schemes) | [PPB, §11.3, §11.5] | `src/surface/triangle/split.rs` |
//! | `triangular-patch/elevate-to`: [`surface::TriangularPatch::elevate_to`] | Θ((m³ − n³)D) | Θ(m²D) | arithmetic operations: exactly (m + 1)(m + 2)(m + 3)/6 − (n + 1)(n + 2)(n + 3)/6 affine combinations, one per new point | [PPB, §11.8] | `src/surface/triangle/elevate.rs` |
//! | `triangular-patch/join-order`: [`surface::TriangularPatch::join_order`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly n(n + 1)(n + 2)/6 affine combinations of three points | [PPB, §11.7] | `src/surface/triangle/join.rs` |
//! | `triangular-patch/extend-cr`: [`surface::TriangularPatch::extend_cr`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly n(n + 1)(n + 2)/6 − (n − r)(n − r + 1)(n − r + 2)/6 affine combinations | [PPB, §11.7] | `src/surface/triangle/join.rs` |
//! | `triangular-patch/to-tensor`: [`surface::TriangularPatch::to_tensor`] | Θ(n³D) | Θ(n²D) | arithmetic operations: exactly (n + 1)(n + 2)(n + 3)/6 terms of Zhou's formula | [PPB, §11.10] | `src/surface/triangle/to_tensor.rs` |
//! | `triangular-patch/from-tensor`: [`surface::TriangularPatch::from_tensor`] | Θ(m(m + n)²D) | Θ((m + n)²D) | arithmetic operations: one per scaled control point added, 2(m + 1)(n + 1)(n + 2)/2, and one per point of each elevation by one | [PPB, §11.11] | `src/surface/triangle/from_tensor.rs` |
//! | `triangular-patch/tessellate`: [`surface::TriangularPatch::tessellate`] | Θ(m²·n³D) for m segments per edge | Θ(m²) | arithmetic operations: exactly n(n + 1)(n + 2)/6 + 2 operations per vertex for n ≥ 1, (m + 1)(m + 2)/2 vertices | [PPB, §10.3–10.5] | `src/surface/triangle/tessellate.rs` |
//! | `mesh-subdivision/catmull-clark`: [`mesh::catmull_clark`] | Θ(4ᵏ·H·D) for k rounds on H corners | Θ(4ᵏ·H·D) | arithmetic operations: point additions and scalings: exactly 3H + 3Vᵢ + 4V_b + 4Eᵢ + 2E_b per round (interior and boundary vertices and edges; corners cost nothing) | [PPB, §16.1] | `src/mesh/catmull_clark.rs` |
//! | `mesh-subdivision/midpoint-cubic`: [`mesh::midpoint_cubic`] | Θ(4ᵏ·H·D) for k rounds on H corners | Θ(4ᵏ·H·D) | arithmetic operations: point additions and scalings: exactly 3H + 3Vᵢ + 4V_b + 10Eᵢ + 2E_b per round | [PPB, §16.1] | `src/mesh/midpoint_cubic.rs` |
//! | `mesh-subdivision/doo-sabin`: [`mesh::doo_sabin`] | Θ(4ᵏ·H·D) for k rounds on H corners | Θ(4ᵏ·H·D) | arithmetic operations: one per stencil term: m per face for its centroid and 4 per corner, 5H per round | [PPB, §16.1, §16.4 (b = 2 + 4/m, erratum)] | `src/mesh/doo_sabin.rs` |
//! | `mesh-subdivision/loop`: [`mesh::loop_subdivision`] | Θ(4ᵏ·F·D) for k rounds on F triangles | Θ(4ᵏ·F·D) | arithmetic operations: one per stencil term: n + 1 per inner vertex of valence n, 3 per boundary vertex, 4 per inner edge, 2 per boundary edge; V + 6E per round on a closed mesh | [PPB, §15.7–15.8, §16.8–16.9] | `src/mesh/loop_subdivision.rs` |
//! | `mesh-subdivision/catmull-clark-limit`: [`mesh::catmull_clark_limit`] | Θ(H·D) for H corners | Θ(V·D) | arithmetic operations: point additions and scalings: exactly 2n + 5 for an interior vertex of valence n, 4 for a boundary vertex, none for a corner | [PPB, §16.4] | `src/mesh/catmull_clark_limit.rs` |
//! | `mesh-subdivision/loop-limit`: [`mesh::loop_limit_points`] | Θ((V + F)·D) | Θ(V·D) | arithmetic operations: one per stencil term: n + 1 per inner vertex of valence n, 3 per boundary vertex | [PPB, §16.4–16.6, §16.9] | `src/mesh/loop_subdivision.rs` |
//! | `mesh-subdivision/doo-sabin-limit`: [`mesh::doo_sabin_limit_points`] | Θ(H·D) | Θ(F·D) | arithmetic operations: one per corner: H | [PPB, §16.1, §16.4] | `src/mesh/doo_sabin.rs` |
//! <!-- /algorithms -->
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
//! is valid input. NaN and infinities are rejected with an error that names them: a point
//! coordinate with [`Error::NonFinite`] (when the [`PointSet`](geometry::PointSet) is built),
//! an edge weight with [`Error::NonFiniteWeight`], a curve parameter, knot or control value
//! with [`Error::InvalidParameter`] naming the parameter. Sorting is the exception: it orders
//! every `f64`, NaN included, by [`f64::total_cmp`]. Degenerate input (no points, one point,
//! duplicates, collinear points) has one policy, described in `docs/design.md`: structures
//! exist for every input, answers that need k points are [`Error::TooFew`] below k.
//!
//! Lengths, distances, widths, areas, radii and sums are returned as
//! [`WideFloat`](geometry::WideFloat): within a stated relative error of the exact value
//! even when that exceeds `f64::MAX` (the diameter of `(-f64::MAX, -f64::MAX)` and
//! `(f64::MAX, f64::MAX)` is 2√2 · `f64::MAX`), never an infinity or a NaN; `to_f64()` gives
//! the `f64` when it fits.

pub mod calipers;
pub mod complexity;
pub mod count;
pub mod delaunay;
pub mod draw;
pub mod error;
pub mod gen;
pub mod geometry;
pub mod graph;
pub mod hull;
pub mod limits;
pub mod mesh;
pub mod proximity;
pub mod sort;
pub mod spline;
pub mod surface;
pub mod trace;
mod util;

#[cfg(feature = "parallel")]
mod parallel;

#[cfg(feature = "cli")]
pub mod cli;

/// The fuzz targets' entry points and checks (`fuzz/`, `tests/suite/fuzz_regressions.rs`):
/// not part of the API.
#[cfg(feature = "cli")]
#[doc(hidden)]
pub mod fuzzing;

pub use error::{Error, Result, Violation};
