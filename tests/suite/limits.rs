//! The size limits of `compgeo::limits`: the table in `docs/design.md` says what the code
//! does, and every library entry point that takes a size checks it before allocating, with
//! an error that names the limit.

use compgeo::graph::{search_trace, Graph, SearchAlgorithm, WeightedGraph};
use compgeo::limits::{self, Limit};
use compgeo::spline::{
    fit_bezier, lagrange, newton, newton_hermite, vandermonde, vandermonde_hermite, FitOptions,
    HermiteNode, Point,
};
use compgeo::Error;

/// The rows of the "Size limits" table: (constant, limit column, what column).
fn table() -> Vec<(String, String, String)> {
    let design = include_str!("../../docs/design.md");
    let section = design
        .split("\n## ")
        .find(|s| s.starts_with("Size limits\n"))
        .expect("docs/design.md has a section \"## Size limits\"");
    section
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            let cells: Vec<&str> = l.trim_matches('|').split(" | ").map(str::trim).collect();
            assert_eq!(cells.len(), 4, "{l}");
            (
                cells[0].trim_matches('`').to_string(),
                cells[1].to_string(),
                cells[2].to_string(),
            )
        })
        .collect()
}

#[test]
fn the_design_table_lists_every_limit_with_its_value_and_words() {
    let rows = table();
    let names: Vec<&str> = rows.iter().map(|r| r.0.as_str()).collect();
    let expected: Vec<&str> = limits::ALL.iter().map(|l| l.name).collect();
    assert_eq!(
        names, expected,
        "the table's rows, in the order of limits::ALL"
    );
    for (row, limit) in rows.iter().zip(limits::ALL) {
        // "2^26 = 67108864" or "393660": the decimal value ends the cell.
        let value: usize = row.1.rsplit("= ").next().unwrap().parse().unwrap();
        assert_eq!(value, limit.max, "{}", limit.name);
        if let Some((power, _)) = row.1.split_once(" = ") {
            let exponent: u32 = power.strip_prefix("2^").unwrap().parse().unwrap();
            assert_eq!(1usize << exponent, limit.max, "{}", limit.name);
        }
        assert!(
            row.2.starts_with(&format!("{}: ", limit.what)),
            "{}: the table says {:?}, the error says {:?}",
            limit.name,
            row.2,
            limit.what
        );
    }
}

#[test]
fn the_constants_are_the_ones_the_modules_publish() {
    let by_name = |name: &str| -> Limit { *limits::ALL.iter().find(|l| l.name == name).unwrap() };
    assert_eq!(by_name("MAX_VERTICES").max, compgeo::graph::MAX_VERTICES);
    assert_eq!(by_name("MAX_EDGES").max, compgeo::graph::MAX_EDGES);
    assert_eq!(by_name("MAX_POINTS").max, compgeo::gen::MAX_POINTS);
    assert_eq!(by_name("MAX_COCIRCULAR").max, compgeo::gen::MAX_COCIRCULAR);
    assert_eq!(by_name("MAX_KEYS").max, compgeo::gen::MAX_KEYS);
    assert_eq!(by_name("TRACE_MAX_LEN").max, compgeo::sort::TRACE_MAX_LEN);
    assert_eq!(
        by_name("TRACE_MAX_VERTICES").max,
        compgeo::graph::TRACE_MAX_VERTICES
    );
    assert_eq!(
        by_name("MAX_FLATTEN_SEGMENTS").max,
        compgeo::spline::MAX_FLATTEN_SEGMENTS
    );
    assert_eq!(
        by_name("MAX_INTERSECTION_PAIRS").max,
        compgeo::spline::MAX_INTERSECTION_PAIRS
    );
    // The example sizes are beyond the limits they name, and K_11585 fits.
    const {
        assert!(23170 * 23169 / 2 > limits::MAX_EDGES);
        assert!(11585 * 11584 / 2 <= limits::MAX_EDGES);
        assert!(limits::MAX_DEGREE < 1 << 32);
    }
}

/// Asserts `result` is the limit error of `name` for `value`, and that its message names both.
#[track_caller]
fn assert_limit<T: std::fmt::Debug>(result: compgeo::Result<T>, name: &str, value: u128) {
    match result {
        Err(e @ Error::LimitExceeded { .. }) => {
            let Error::LimitExceeded {
                limit,
                value: v,
                max,
                ..
            } = e.clone()
            else {
                unreachable!()
            };
            assert_eq!((limit, v), (name, value), "{e}");
            let text = e.to_string();
            assert!(
                text.contains(name)
                    && text.contains(&max.to_string())
                    && text.contains(&value.to_string()),
                "{text}"
            );
        }
        other => panic!("expected {name} exceeded by {value}, got {other:?}"),
    }
}

#[test]
fn graphs_check_their_counts_before_allocating() {
    // A few bytes of JSON can say 10^18 vertices; nothing of that size is allocated.
    assert_limit(Graph::from_edges(1 << 60, &[]), "MAX_VERTICES", 1 << 60);
    assert_limit(
        Graph::from_edges(usize::MAX, &[[0, 1]]),
        "MAX_VERTICES",
        usize::MAX as u128,
    );
    assert_limit(
        WeightedGraph::from_edges(limits::MAX_VERTICES + 1, &[], &[]),
        "MAX_VERTICES",
        limits::MAX_VERTICES as u128 + 1,
    );
    let g = Graph::from_edges(limits::TRACE_MAX_VERTICES + 1, &[]).unwrap();
    assert_limit(
        search_trace(&g, 0, SearchAlgorithm::Bfs),
        "TRACE_MAX_VERTICES",
        limits::TRACE_MAX_VERTICES as u128 + 1,
    );
}

#[test]
fn generators_check_their_sizes_before_allocating() {
    use compgeo::gen::{graph, points, sequence, GraphKind, PointKind, SequenceKind};
    assert_limit(
        points(PointKind::Gaussian, usize::MAX, 0),
        "MAX_POINTS",
        usize::MAX as u128,
    );
    assert_limit(
        sequence(SequenceKind::Sorted, limits::MAX_KEYS + 1, 0),
        "MAX_KEYS",
        limits::MAX_KEYS as u128 + 1,
    );
    // Sizes derived from n are computed exactly, past u64: the queen graph on n² squares.
    assert_limit(
        graph(GraphKind::Queen, 1 << 40, 0, 0),
        "MAX_VERTICES",
        1u128 << 80,
    );
    assert_limit(
        graph(GraphKind::Complete, 23170, 0, 0),
        "MAX_EDGES",
        268_412_865,
    );
    assert_limit(
        graph(GraphKind::Crown, 1 << 20, 0, 0),
        "MAX_EDGES",
        (1u128 << 20) * ((1 << 20) - 1),
    );
    assert_eq!(
        graph(GraphKind::Complete, 300, 0, 0).unwrap().edges.len(),
        300 * 299 / 2
    );
}

#[test]
fn interpolation_checks_degrees_and_dense_systems() {
    let n = limits::MAX_DEGREE + 2;
    let nodes: Vec<f64> = (0..n).map(|i| i as f64).collect();
    let pts: Vec<Point<f64, 1>> = nodes.iter().map(|&u| Point::new([u])).collect();
    assert_limit(lagrange(&nodes, &pts), "MAX_DEGREE", n as u128 - 1);
    assert_limit(newton(&nodes, &pts), "MAX_DEGREE", n as u128 - 1);
    let data: Vec<HermiteNode<f64, 1>> = (0..n / 2 + 1)
        .map(|i| HermiteNode {
            u: i as f64,
            values: vec![Point::new([0.0]), Point::new([1.0])],
        })
        .collect();
    assert_limit(
        newton_hermite(&data),
        "MAX_DEGREE",
        2 * (n as u128 / 2 + 1) - 1,
    );
    // The dense systems: one node more than the limit, checked before the n² matrix.
    let m = limits::MAX_DENSE_UNKNOWNS + 1;
    assert_limit(
        vandermonde(&nodes[..m], &pts[..m]),
        "MAX_DENSE_UNKNOWNS",
        m as u128,
    );
    assert_limit(
        vandermonde_hermite(&data[..m / 2 + 1]),
        "MAX_DENSE_UNKNOWNS",
        m as u128 + 1,
    );
    let options = FitOptions::default();
    assert_limit(
        fit_bezier(&nodes[..10], &pts[..10], usize::MAX, &options),
        "MAX_DENSE_UNKNOWNS",
        usize::MAX as u128,
    );
    let clamped = FitOptions {
        clamp_ends: true,
        ..FitOptions::default()
    };
    assert_limit(
        fit_bezier(
            &nodes[..10],
            &pts[..10],
            limits::MAX_DENSE_UNKNOWNS - 2,
            &clamped,
        ),
        "MAX_DENSE_UNKNOWNS",
        m as u128,
    );
    // Power-form coefficients can be any number; their Θ(n²) conversions to the Bézier
    // form check the degree first.
    use compgeo::spline::{Bezier, Polynomial, Subsegment};
    let coefficients = vec![Point::new([1.0]); n];
    assert_limit(
        Bezier::from_monomial(&coefficients),
        "MAX_DEGREE",
        n as u128 - 1,
    );
    assert_limit(
        Polynomial::new(coefficients).subsegment(&0.0, &1.0),
        "MAX_DEGREE",
        n as u128 - 1,
    );
    // At the limits the work is done.
    assert_eq!(lagrange(&nodes[..5], &pts[..5]).unwrap().nodes().len(), 5);
    assert!(vandermonde(&nodes[..8], &pts[..8]).is_ok());
}

#[test]
fn knot_vectors_check_degrees_counts_and_tables_before_allocating() {
    use compgeo::spline::KnotVector;
    let big = limits::MAX_DEGREE as u128 + 1;
    assert_limit(
        KnotVector::<f64>::clamped_uniform(limits::MAX_DEGREE + 1, 2, 0.0, 1.0),
        "MAX_DEGREE",
        big,
    );
    assert_limit(
        KnotVector::<f64>::averaged(limits::MAX_DEGREE + 1, &[0.0, 1.0]),
        "MAX_DEGREE",
        big,
    );
    assert_limit(
        KnotVector::<f64>::uniform(3, limits::MAX_KNOTS - 3, 0.0, 1.0),
        "MAX_KNOTS",
        limits::MAX_KNOTS as u128 + 1,
    );
    // An order and a degree within MAX_DEGREE whose table is not.
    let t = KnotVector::clamped_uniform(300, 301, 0.0, 1.0).unwrap();
    let k = limits::MAX_DEGREE;
    assert_limit(
        t.basis_derivatives(&0.5, k),
        "MAX_BASIS_TABLE",
        (k as u128 + 1) * 301,
    );
}
