//! The pictures of `compgeo::draw` read back with an XML parser (roxmltree) and mapped back
//! to the world through the frame the picture records (`data-frame`), in exact rationals:
//! the drawn hull is the hull in order, the triangles are the triangulation's, the cells are
//! the clipped cells, the rectangles' corners and the pairs are the calipers', the labels
//! appear exactly up to `LABEL_LIMIT` points, y grows upwards, extreme inputs give finite
//! numbers, and the files grow linearly.

use crate::strategies::{extreme_points, lattice};
use compgeo::calipers::ConvexPolygon;
use compgeo::delaunay::{dual, incremental, voronoi, ClipBox};
use compgeo::draw::{self, Picture, LABEL_LIMIT};
use compgeo::gen::{points as generate, PointKind};
use compgeo::geometry::{ConstructedPoint, Point2, PointSet};
use compgeo::hull::{convex_hull, Algorithm, HullOptions};
use compgeo::proximity::{closest_pair, euclidean_mst, largest_empty_circle, ClosestPairAlgorithm};
use compgeo::Error;
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};
use proptest::prelude::*;

/// How far a printed coordinate may be from the exact picture coordinate: half a unit of
/// the last printed decimal (one decimal at most), with room for the rounding of the
/// difference to the origin.
const TOLERANCE: f64 = 0.051;

/// One subpath of a `<path>`: its points (a dot `Mx yh0` gives the point twice) and whether
/// it is closed.
#[derive(Debug, Clone, PartialEq)]
pub struct Subpath {
    pub points: Vec<[f64; 2]>,
    pub closed: bool,
}

/// The frame a picture records: `px = left + (x − ox) · 2^−shift`, `py = bottom − (y − oy) ·
/// 2^−shift`.
#[derive(Debug, Clone, Copy)]
pub struct RecordedFrame {
    ox: f64,
    oy: f64,
    shift: i32,
    left: f64,
    bottom: f64,
}

fn rational(v: f64) -> BigRational {
    BigRational::from_float(v).expect("finite")
}

fn pow2(e: i32) -> BigRational {
    let p = BigRational::from_integer(BigInt::from(2).pow(e.unsigned_abs()));
    if e < 0 {
        p.recip()
    } else {
        p
    }
}

impl RecordedFrame {
    /// Whether the picture point `at` maps back to within `TOLERANCE` picture units of the
    /// world point `p`, exactly.
    pub fn maps_back(&self, at: [f64; 2], p: Point2) -> bool {
        let unit = pow2(self.shift);
        let x = rational(self.ox) + (rational(at[0]) - rational(self.left)) * &unit;
        let y = rational(self.oy) + (rational(self.bottom) - rational(at[1])) * &unit;
        let tolerance = rational(TOLERANCE) * &unit;
        (x - rational(p.x)).abs() <= tolerance && (y - rational(p.y)).abs() <= tolerance
    }

    /// Where the world point `p` is drawn, computed exactly and rounded once.
    pub fn picture_of(&self, p: Point2) -> [f64; 2] {
        let unit = pow2(-self.shift);
        let x = rational(self.left) + (rational(p.x) - rational(self.ox)) * &unit;
        let y = rational(self.bottom) - (rational(p.y) - rational(self.oy)) * &unit;
        [x.to_f64().unwrap(), y.to_f64().unwrap()]
    }
}

/// A picture's text, checked to be well-formed XML whose numbers are all finite and bounded.
pub struct Svg {
    pub text: String,
}

impl Svg {
    /// Parses `text`, asserting that it is one `<svg>` element with a `data-frame` and that
    /// every number in its geometry and style attributes is finite and within `±10⁶`.
    pub fn parse(text: String) -> Svg {
        let doc = roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
        let root = doc.root_element();
        assert_eq!(root.tag_name().name(), "svg");
        assert_eq!(
            root.tag_name().namespace(),
            Some("http://www.w3.org/2000/svg")
        );
        for node in doc.descendants().filter(|n| n.is_element()) {
            for a in node.attributes() {
                let numbers: Vec<f64> = match a.name() {
                    "d" => path_numbers(a.value()),
                    "x" | "y" | "cx" | "cy" | "r" | "width" | "height" | "stroke-width"
                    | "font-size" | "fill-opacity" | "stroke-dasharray" | "viewBox" => a
                        .value()
                        .split([' ', ','])
                        .map(|t| {
                            t.parse()
                                .unwrap_or_else(|_| panic!("{}={}", a.name(), a.value()))
                        })
                        .collect(),
                    _ => continue,
                };
                for v in numbers {
                    assert!(
                        v.is_finite() && v.abs() <= 1e6,
                        "{}={}",
                        a.name(),
                        a.value()
                    );
                }
            }
        }
        Svg { text }
    }

    fn doc(&self) -> roxmltree::Document<'_> {
        roxmltree::Document::parse(&self.text).unwrap()
    }

    pub fn frame(&self) -> RecordedFrame {
        let doc = self.doc();
        let f: Vec<&str> = doc
            .root_element()
            .attribute("data-frame")
            .expect("the frame is recorded")
            .split(' ')
            .collect();
        assert_eq!(f.len(), 5);
        RecordedFrame {
            ox: f[0].parse().unwrap(),
            oy: f[1].parse().unwrap(),
            shift: f[2].parse().unwrap(),
            left: f[3].parse().unwrap(),
            bottom: f[4].parse().unwrap(),
        }
    }

    /// Whether the picture has a layer (a group) of this class.
    pub fn has_layer(&self, class: &str) -> bool {
        self.doc()
            .descendants()
            .any(|n| n.has_tag_name("g") && n.attribute("class") == Some(class))
    }

    /// The elements named `tag` in the layer `class`.
    fn elements<T>(&self, class: &str, tag: &str, f: impl Fn(roxmltree::Node) -> T) -> Vec<T> {
        let doc = self.doc();
        let group = doc
            .descendants()
            .find(|n| n.has_tag_name("g") && n.attribute("class") == Some(class))
            .unwrap_or_else(|| panic!("no layer {class}"));
        group
            .children()
            .filter(|n| n.has_tag_name(tag))
            .map(f)
            .collect()
    }

    /// The subpaths of the layer `class`, in order.
    pub fn subpaths(&self, class: &str) -> Vec<Subpath> {
        self.elements(class, "path", |n| parse_path(n.attribute("d").unwrap()))
            .into_iter()
            .flatten()
            .collect()
    }

    /// The circles `[cx, cy, r]` of the layer `class`.
    pub fn circles(&self, class: &str) -> Vec<[f64; 3]> {
        self.elements(class, "circle", |n| {
            ["cx", "cy", "r"].map(|a| n.attribute(a).unwrap().parse().unwrap())
        })
    }

    /// The texts of the layer `class`.
    pub fn texts(&self, class: &str) -> Vec<String> {
        self.elements(class, "text", |n| n.text().unwrap_or("").to_string())
    }

    /// The attribute `name` of the layer `class`'s group.
    pub fn layer_attribute(&self, class: &str, name: &str) -> Option<String> {
        let doc = self.doc();
        let group = doc
            .descendants()
            .find(|n| n.has_tag_name("g") && n.attribute("class") == Some(class))?;
        group.attribute(name).map(str::to_string)
    }

    /// The `<title>`.
    pub fn title(&self) -> String {
        let doc = self.doc();
        let title = doc.descendants().find(|n| n.has_tag_name("title")).unwrap();
        title.text().unwrap_or("").to_string()
    }
}

/// The numbers of path data.
fn path_numbers(d: &str) -> Vec<f64> {
    d.split(|c: char| c.is_ascii_alphabetic() || c == ' ')
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().unwrap_or_else(|_| panic!("{t} in {d}")))
        .collect()
}

/// The subpaths of path data made of `M`, `L`, implicit line-tos, `h` and `Z`.
fn parse_path(d: &str) -> Vec<Subpath> {
    let mut out: Vec<Subpath> = Vec::new();
    let mut numbers: Vec<f64> = Vec::new();
    let mut command = ' ';
    let flush = |command: char, numbers: &mut Vec<f64>, out: &mut Vec<Subpath>| {
        match command {
            'M' | 'L' => {
                assert!(numbers.len() % 2 == 0, "{d}");
                for (k, pair) in numbers.chunks(2).enumerate() {
                    if command == 'M' && k == 0 {
                        out.push(Subpath {
                            points: Vec::new(),
                            closed: false,
                        });
                    }
                    out.last_mut().unwrap().points.push([pair[0], pair[1]]);
                }
            }
            'h' => {
                let last = out.last_mut().unwrap();
                let [x, y] = *last.points.last().unwrap();
                for dx in numbers.iter() {
                    last.points.push([x + dx, y]);
                }
            }
            ' ' | 'Z' => assert!(numbers.is_empty(), "{d}"),
            other => panic!("unexpected command {other} in {d}"),
        }
        numbers.clear();
    };
    let mut token = String::new();
    for c in d.chars().chain([' ']) {
        if c.is_ascii_alphabetic() || c == ' ' {
            if !token.is_empty() {
                numbers.push(token.parse().unwrap());
                token.clear();
            }
            if c.is_ascii_alphabetic() {
                flush(command, &mut numbers, &mut out);
                command = c;
                if c == 'Z' {
                    out.last_mut().unwrap().closed = true;
                }
            }
        } else {
            token.push(c);
        }
    }
    flush(command, &mut numbers, &mut out);
    out
}

/// The picture's SVG, parsed and checked.
pub fn svg(picture: &Picture) -> Svg {
    let text = picture.to_svg();
    let mut written = Vec::new();
    picture.write_svg(&mut written).unwrap();
    assert_eq!(written, text.as_bytes(), "to_svg and write_svg agree");
    Svg::parse(text)
}

/// Asserts that the subpath's points map back to `expected`, in order.
pub fn assert_maps_back(frame: &RecordedFrame, drawn: &Subpath, expected: &[Point2]) {
    assert_eq!(
        drawn.points.len(),
        expected.len(),
        "{drawn:?} vs {expected:?}"
    );
    for (at, &p) in drawn.points.iter().zip(expected) {
        assert!(frame.maps_back(*at, p), "{at:?} is not {p:?} ({frame:?})");
    }
}

fn uniform(n: usize, seed: u64) -> Vec<Point2> {
    generate(PointKind::UniformDisk, n, seed).unwrap()
}

/// Every picture the library can make of `pts` (those whose results exist).
fn every_picture(pts: &[Point2]) -> Vec<(&'static str, Picture)> {
    let set = PointSet::new(pts).unwrap();
    let mut out = Vec::new();
    let hull = convex_hull(pts, Algorithm::MonotoneChain, HullOptions::default()).unwrap();
    out.push(("hull", draw::hull(&set, &hull).unwrap()));
    let polygon = ConvexPolygon::hull(&set);
    if let Ok(d) = polygon.diameter() {
        out.push(("calipers", draw::calipers(&polygon, &d).unwrap()));
    }
    let t = incremental(pts).unwrap();
    out.push((
        "delaunay",
        draw::delaunay(&set, &t, Some(&dual(pts, &t).unwrap())).unwrap(),
    ));
    if let Ok(b) = ClipBox::around(&set) {
        let v = voronoi(pts).unwrap();
        out.push(("voronoi", draw::voronoi(&set, &v, &b).unwrap()));
    }
    if let Ok(pair) = closest_pair(pts, ClosestPairAlgorithm::DivideAndConquer) {
        out.push(("closest-pair", draw::closest_pair(&set, &pair).unwrap()));
    }
    out.push((
        "emst",
        draw::emst(&set, &euclidean_mst(pts).unwrap()).unwrap(),
    ));
    if let Ok(c) = largest_empty_circle(pts) {
        out.push(("empty-circle", draw::empty_circle(&set, &hull, &c).unwrap()));
    }
    out
}

#[test]
fn the_drawn_hull_is_the_hull_in_order_with_its_positions_as_labels() {
    for (kind, n) in [
        (PointKind::UniformDisk, 40),
        (PointKind::Cocircular, 60),
        (PointKind::Grid, 49),
        (PointKind::Huge, 30),
        (PointKind::Tiny, 30),
    ] {
        let pts = generate(kind, n, 7).unwrap();
        for algorithm in [Algorithm::Graham, Algorithm::Jarvis, Algorithm::Quickhull] {
            let hull = convex_hull(&pts, algorithm, HullOptions::default()).unwrap();
            let s = svg(&draw::hull(&PointSet::new(&pts).unwrap(), &hull).unwrap());
            let drawn = s.subpaths("hull");
            assert_eq!(drawn.len(), 1);
            assert!(drawn[0].closed);
            let expected: Vec<Point2> = hull.iter().map(|&i| pts[i]).collect();
            assert_maps_back(&s.frame(), &drawn[0], &expected);
            let labels: Vec<String> = (0..hull.len()).map(|k| k.to_string()).collect();
            assert_eq!(s.texts("labels"), labels, "{kind:?}");
            // Every input point is a dot.
            let dots = s.subpaths("points");
            assert_eq!(dots.len(), pts.len());
            for (dot, &p) in dots.iter().zip(&pts) {
                assert!(s.frame().maps_back(dot.points[0], p));
            }
        }
    }
}

#[test]
fn the_triangles_are_the_triangulation_s_and_the_circumcircles_pass_through_them() {
    for (kind, n) in [
        (PointKind::UniformSquare, 60),
        (PointKind::Cocircular, 40),
        (PointKind::Grid, 36),
    ] {
        let pts = generate(kind, n, 3).unwrap();
        let set = PointSet::new(&pts).unwrap();
        let t = incremental(&pts).unwrap();
        let s = svg(&draw::delaunay(&set, &t, Some(&dual(&pts, &t).unwrap())).unwrap());
        let frame = s.frame();
        let drawn = s.subpaths("triangles");
        assert_eq!(drawn.len(), t.triangle_count(), "{kind:?}");
        for (k, triangle) in drawn.iter().enumerate() {
            assert!(triangle.closed);
            let expected = t.triangle(k).map(|i| pts[i]);
            assert_maps_back(&frame, triangle, &expected);
        }
        let hull: Vec<Point2> = t.hull.iter().map(|&i| pts[i]).collect();
        assert_maps_back(&frame, &s.subpaths("hull")[0], &hull);
        // Each drawn circle passes through its triangle's three vertices, wherever they
        // are drawn (an independent check of centre and radius); circles too large to draw
        // are counted in the legend.
        let circles = s.circles("circumcircles");
        let mut k = 0;
        for triangle in 0..t.triangle_count() {
            let corners = t.triangle(triangle).map(|i| frame.picture_of(pts[i]));
            let Some(&[cx, cy, r]) = circles.get(k) else {
                break;
            };
            let fits = corners
                .iter()
                .all(|c| ((c[0] - cx).hypot(c[1] - cy) - r).abs() < 4.0 * TOLERANCE);
            if fits {
                k += 1;
            }
        }
        assert_eq!(
            k,
            circles.len(),
            "{kind:?}: every circle belongs to its triangle"
        );
        if circles.len() < t.triangle_count() {
            assert!(s.text.contains("too large to draw"));
        }
    }
}

#[test]
fn the_voronoi_cells_are_the_clipped_cells() {
    let pts = uniform(50, 11);
    let set = PointSet::new(&pts).unwrap();
    let v = voronoi(&pts).unwrap();
    for bounds in [
        ClipBox::around(&set).unwrap(),
        ClipBox::new(-0.5, -0.5, 0.25, 0.5).unwrap(),
    ] {
        let s = svg(&draw::voronoi(&set, &v, &bounds).unwrap());
        let cells = v.clip(&bounds);
        let expected: Vec<Vec<Point2>> = cells
            .iter()
            .filter(|c| !c.is_empty())
            .map(|c| c.to_vec())
            .collect();
        let drawn = s.subpaths("cells");
        assert_eq!(drawn.len(), expected.len());
        for (cell, polygon) in drawn.iter().zip(&expected) {
            assert!(cell.closed);
            assert_maps_back(&s.frame(), cell, polygon);
        }
        let corners = [
            bounds.min,
            Point2::new(bounds.max.x, bounds.min.y),
            bounds.max,
            Point2::new(bounds.min.x, bounds.max.y),
        ];
        assert_maps_back(&s.frame(), &s.subpaths("clip-box")[0], &corners);
    }
}

#[test]
fn the_closest_pair_and_the_tree_are_drawn_between_their_points() {
    let pts = uniform(80, 5);
    let set = PointSet::new(&pts).unwrap();
    let pair = closest_pair(&pts, ClosestPairAlgorithm::Delaunay).unwrap();
    let s = svg(&draw::closest_pair(&set, &pair).unwrap());
    assert_maps_back(
        &s.frame(),
        &s.subpaths("closest-pair")[0],
        &pair.pair.map(|i| pts[i]),
    );
    assert_eq!(s.circles("closest-pair-rings").len(), 2);

    let tree = euclidean_mst(&pts).unwrap();
    let s = svg(&draw::emst(&set, &tree).unwrap());
    let drawn = s.subpaths("emst");
    assert_eq!(drawn.len(), pts.len() - 1);
    for (edge, &[u, v]) in drawn.iter().zip(&tree.edges) {
        assert_maps_back(&s.frame(), edge, &[pts[u], pts[v]]);
    }
}

#[test]
fn the_empty_circle_is_drawn_through_its_sites() {
    let pts = uniform(60, 9);
    let set = PointSet::new(&pts).unwrap();
    let hull = convex_hull(&pts, Algorithm::Graham, HullOptions::default()).unwrap();
    let c = largest_empty_circle(&pts).unwrap();
    let s = svg(&draw::empty_circle(&set, &hull, &c).unwrap());
    let frame = s.frame();
    let [[cx, cy, r]] = s.circles("empty-circle")[..] else {
        panic!("one circle");
    };
    assert!(frame.maps_back([cx, cy], c.centre));
    for &i in &c.sites {
        let p = frame.picture_of(pts[i]);
        assert!(((p[0] - cx).hypot(p[1] - cy) - r).abs() < 4.0 * TOLERANCE);
    }
    // No input point is drawn inside the circle.
    for &p in &pts {
        let q = frame.picture_of(p);
        assert!((q[0] - cx).hypot(q[1] - cy) > r - 4.0 * TOLERANCE);
    }
    assert_eq!(s.subpaths("radii").len(), c.sites.len());
}

#[test]
fn the_calipers_picture_draws_the_calipers_answers() {
    for seed in 0..4 {
        let pts = uniform(40, seed);
        let set = PointSet::new(&pts).unwrap();
        let polygon = ConvexPolygon::hull(&set);
        let d = polygon.diameter().unwrap();
        let s = svg(&draw::calipers(&polygon, &d).unwrap());
        let frame = s.frame();
        assert_maps_back(&frame, &s.subpaths("diameter")[0], &d.pair.map(|i| pts[i]));
        let pairs = polygon.antipodal_pairs();
        let drawn = s.subpaths("antipodal-pairs");
        assert_eq!(drawn.len(), pairs.len());
        for (segment, &[i, j]) in drawn.iter().zip(&pairs) {
            assert_maps_back(&frame, segment, &[pts[i], pts[j]]);
        }
        for (layer, r) in [
            ("min-area-rectangle", polygon.min_area_rectangle().unwrap()),
            (
                "min-perimeter-rectangle",
                polygon.min_perimeter_rectangle().unwrap(),
            ),
        ] {
            let corners = r.corners.map(|c| c.finite().unwrap());
            assert_maps_back(&frame, &s.subpaths(layer)[0], &corners);
        }
        // The width: two lines parallel to its edge, through the edge and its vertex.
        let w = polygon.width().unwrap();
        let [a, b] = w.edge.map(|i| frame.picture_of(pts[i]));
        let dir = [b[0] - a[0], b[1] - a[1]];
        let len = dir[0].hypot(dir[1]);
        let lines = s.subpaths("width");
        assert_eq!(lines.len(), 2);
        for (line, through) in lines.iter().zip([a, frame.picture_of(pts[w.vertex])]) {
            let [p, q] = [line.points[0], line.points[1]];
            let cross = |u: [f64; 2], v: [f64; 2]| u[0] * v[1] - u[1] * v[0];
            let along = [q[0] - p[0], q[1] - p[1]];
            assert!(cross(along, dir).abs() / (len * along[0].hypot(along[1])) < 1e-3);
            let off = [through[0] - p[0], through[1] - p[1]];
            assert!(cross(along, off).abs() / along[0].hypot(along[1]) < 4.0 * TOLERANCE);
        }
    }
}

#[test]
fn labels_number_the_points_up_to_the_limit_and_not_beyond() {
    for n in [LABEL_LIMIT, LABEL_LIMIT + 1] {
        let pts = uniform(n, 1);
        let set = PointSet::new(&pts).unwrap();
        let picture = draw::delaunay(&set, &incremental(&pts).unwrap(), None).unwrap();
        let s = svg(&picture);
        let texts = s.texts("labels");
        if n <= LABEL_LIMIT {
            assert!(picture.shows_labels());
            let expected: Vec<String> = (0..n).map(|i| i.to_string()).collect();
            assert_eq!(texts, expected);
        } else {
            assert!(!picture.shows_labels());
            assert!(texts.is_empty());
        }
    }
}

#[test]
fn labels_of_a_spread_out_set_do_not_overlap() {
    // A 12 × 12 grid: room for every label next to its point.
    let pts: Vec<Point2> = (0..144)
        .map(|k| Point2::new(f64::from(k % 12), f64::from(k / 12)))
        .collect();
    let set = PointSet::new(&pts).unwrap();
    let s = svg(&draw::emst(&set, &euclidean_mst(&pts).unwrap()).unwrap());
    let doc = roxmltree::Document::parse(&s.text).unwrap();
    let group = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("labels"))
        .unwrap();
    let font: f64 = group.attribute("font-size").unwrap().parse().unwrap();
    let boxes: Vec<[f64; 4]> = group
        .children()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| {
            let x: f64 = n.attribute("x").unwrap().parse().unwrap();
            let y: f64 = n.attribute("y").unwrap().parse().unwrap();
            let w = 0.6 * font * n.text().unwrap().len() as f64;
            let left = match n.attribute("text-anchor") {
                Some("end") => x - w,
                Some("middle") => x - w / 2.0,
                _ => x,
            };
            [left, y - 0.8 * font, left + w, y + 0.2 * font]
        })
        .collect();
    assert_eq!(boxes.len(), 144);
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[..i] {
            let overlap = a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
            assert!(!overlap, "{a:?} and {b:?}");
        }
    }
}

#[test]
fn y_grows_upwards() {
    let pts = [(0.0, 0.0), (0.0, 1.0), (1.0, -1.0)].map(Point2::from);
    let s = svg(&draw::hull(&PointSet::new(&pts).unwrap(), &[2, 1, 0]).unwrap());
    let dots = s.subpaths("points");
    let y: Vec<f64> = dots.iter().map(|d| d.points[0][1]).collect();
    assert!(y[1] < y[0] && y[0] < y[2], "{y:?}");
    let x: Vec<f64> = dots.iter().map(|d| d.points[0][0]).collect();
    assert!(x[0] == x[1] && x[1] < x[2], "{x:?}");
}

#[test]
fn degenerate_and_extreme_inputs_draw_valid_svg() {
    let m = f64::MAX;
    let cases: Vec<Vec<Point2>> = vec![
        vec![Point2::new(3.0, 4.0)],
        vec![Point2::new(1e300, -1e300)],
        (0..5)
            .map(|k| Point2::new(f64::from(k), 2.0 * f64::from(k)))
            .collect(),
        (0..5).map(|k| Point2::new(7.0, f64::from(k))).collect(),
        [(-m, -m), (m, -m), (m, m), (-m, m), (0.0, 0.0)]
            .map(Point2::from)
            .to_vec(),
        [
            (5e-324, 0.0),
            (1e-323, 5e-324),
            (0.0, 1.5e-323),
            (2e-323, 2e-323),
        ]
        .map(Point2::from)
        .to_vec(),
        [(1e300, 5e-324), (-1e300, 0.0), (0.0, 1e300), (3.0, -2.0)]
            .map(Point2::from)
            .to_vec(),
        [(1e300, 1.0), (1e300, 2.0), (1.0000000000000002e300, 1.0)]
            .map(Point2::from)
            .to_vec(),
        [(0.0, 0.0), (0.0, 0.0), (1.0, 1.0)]
            .map(Point2::from)
            .to_vec(),
    ];
    for pts in &cases {
        for (name, picture) in every_picture(pts) {
            let s = svg(&picture);
            if name == "hull" {
                let hull =
                    convex_hull(pts, Algorithm::MonotoneChain, HullOptions::default()).unwrap();
                let expected: Vec<Point2> = hull.iter().map(|&i| pts[i]).collect();
                match s.subpaths("hull").first() {
                    Some(drawn) => assert_maps_back(&s.frame(), drawn, &expected),
                    None => assert!(expected.len() < 2),
                }
                for (dot, &p) in s.subpaths("points").iter().zip(pts) {
                    assert!(s.frame().maps_back(dot.points[0], p), "{p:?} in {pts:?}");
                }
            }
        }
    }
}

#[test]
fn an_empty_point_set_draws_an_empty_picture() {
    let set = PointSet::new(&[]).unwrap();
    let s = svg(&draw::hull(&set, &[]).unwrap());
    assert!(s.subpaths("points").is_empty() && s.subpaths("hull").is_empty());
}

#[test]
fn files_grow_linearly_with_the_input() {
    type Draws = dyn Fn(&[Point2]) -> Picture;
    let size = |n: usize, f: &Draws| f(&uniform(n, 2)).to_svg().len();
    let pictures: [(&str, &Draws); 4] = [
        ("hull", &|p| {
            let h = convex_hull(p, Algorithm::Graham, HullOptions::default()).unwrap();
            draw::hull(&PointSet::new(p).unwrap(), &h).unwrap()
        }),
        ("delaunay", &|p| {
            draw::delaunay(&PointSet::new(p).unwrap(), &incremental(p).unwrap(), None).unwrap()
        }),
        ("voronoi", &|p| {
            let set = PointSet::new(p).unwrap();
            let b = ClipBox::around(&set).unwrap();
            draw::voronoi(&set, &voronoi(p).unwrap(), &b).unwrap()
        }),
        ("emst", &|p| {
            draw::emst(&PointSet::new(p).unwrap(), &euclidean_mst(p).unwrap()).unwrap()
        }),
    ];
    for (name, f) in pictures {
        let (small, large) = (size(1000, f), size(10_000, f));
        let ratio = large as f64 / small as f64;
        assert!(
            (8.0..=12.0).contains(&ratio),
            "{name}: {small} → {large} bytes"
        );
        // And a few dozen bytes per point, not hundreds.
        assert!(large < 120 * 10_000, "{name}: {large} bytes");
    }
}

#[test]
fn bad_indices_and_mismatched_results_are_named_errors() {
    let pts = uniform(10, 0);
    let set = PointSet::new(&pts).unwrap();
    let invalid = |e: Error, name: &str| {
        assert!(
            matches!(e, Error::InvalidParameter { name: n, .. } if n == name),
            "{e}"
        );
    };
    invalid(draw::hull(&set, &[0, 10]).unwrap_err(), "hull");
    let mut t = incremental(&pts).unwrap();
    let more = uniform(12, 1);
    let other = dual(&more, &incremental(&more).unwrap()).unwrap();
    invalid(
        draw::delaunay(&set, &t, Some(&other)).unwrap_err(),
        "circumcircles",
    );
    t.triangles.push(0);
    invalid(draw::delaunay(&set, &t, None).unwrap_err(), "triangulation");
    t.triangles.extend([1, 99]);
    invalid(draw::delaunay(&set, &t, None).unwrap_err(), "triangulation");
    let big = uniform(20, 3);
    let v = voronoi(&big).unwrap();
    invalid(
        draw::voronoi(&set, &v, &ClipBox::around(&set).unwrap()).unwrap_err(),
        "voronoi",
    );
    let mut pair = closest_pair(&pts, ClosestPairAlgorithm::Delaunay).unwrap();
    pair.pair[1] = 10;
    invalid(draw::closest_pair(&set, &pair).unwrap_err(), "pair");
    let polygon = ConvexPolygon::hull(&set);
    invalid(draw::calipers(&polygon, &pair).unwrap_err(), "diameter");
    let mut tree = euclidean_mst(&pts).unwrap();
    tree.edges[0][0] = 11;
    invalid(draw::emst(&set, &tree).unwrap_err(), "tree");
    let mut c = largest_empty_circle(&pts).unwrap();
    let hull = convex_hull(&pts, Algorithm::Graham, HullOptions::default()).unwrap();
    invalid(draw::empty_circle(&set, &[0, 42], &c).unwrap_err(), "hull");
    c.sites.push(10);
    invalid(draw::empty_circle(&set, &hull, &c).unwrap_err(), "circle");
    let empty = PointSet::new(&[]).unwrap();
    assert!(matches!(
        draw::calipers(&ConvexPolygon::hull(&empty), &pair),
        Err(Error::InvalidParameter { .. } | Error::TooFew { .. })
    ));
}

#[test]
fn titles_and_legends_are_escaped() {
    let pts = uniform(5, 0);
    let set = PointSet::new(&pts).unwrap();
    let mut picture = draw::hull(&set, &[0]).unwrap();
    let title = "<a & \"b\" 'c'>\u{1}\u{1b}";
    picture.set_title(title);
    let s = svg(&picture);
    assert_eq!(s.title(), "<a & \"b\" 'c'>\u{fffd}\u{fffd}");
}

#[test]
fn a_beyond_range_constructed_point_is_drawn_finite() {
    // A nearly flat triangle's circumcentre is beyond f64: its circle is left out, and the
    // picture stays finite.
    let pts = [(-1e300, 0.0), (1e300, 0.0), (0.0, 1e-300)].map(Point2::from);
    let t = incremental(&pts).unwrap();
    let v = dual(&pts, &t).unwrap();
    assert!(matches!(v.vertex(0), ConstructedPoint::BeyondRange(_)));
    let s = svg(&draw::delaunay(&PointSet::new(&pts).unwrap(), &t, Some(&v)).unwrap());
    assert!(s.circles("circumcircles").is_empty());
    assert!(s.text.contains("1 too large to draw"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn every_finite_input_draws_finite_svg(pts in extreme_points(1..10)) {
        for (name, picture) in every_picture(&pts) {
            let s = svg(&picture);
            prop_assert!(s.has_layer("points"), "{}", name);
            for (dot, &p) in s.subpaths("points").iter().zip(&pts) {
                prop_assert!(s.frame().maps_back(dot.points[0], p), "{} {:?}", name, p);
            }
        }
    }

    #[test]
    fn hulls_and_triangulations_of_lattices_map_back(pts in lattice(-6..=6, 1..40)) {
        let set = PointSet::new(&pts).unwrap();
        let hull = convex_hull(&pts, Algorithm::Chan, HullOptions::default()).unwrap();
        let s = svg(&draw::hull(&set, &hull).unwrap());
        if hull.len() >= 2 {
            let expected: Vec<Point2> = hull.iter().map(|&i| pts[i]).collect();
            assert_maps_back(&s.frame(), &s.subpaths("hull")[0], &expected);
        }
        let t = incremental(&pts).unwrap();
        let s = svg(&draw::delaunay(&set, &t, None).unwrap());
        prop_assert_eq!(s.subpaths("triangles").len(), t.triangle_count());
    }
}
