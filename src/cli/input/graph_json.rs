//! The JSON graph reader: `{"vertices": n, "edges": [[u, v], ...]}` or `[[u, v, w], ...]`.

use crate::cli::CliError;
use crate::graph::EdgeList;

/// Parses a JSON graph `{"vertices": n, "edges": [[u, v], ...]}` (or `[[u, v, w], ...]`).
///
/// Either every edge has a weight or none has; an empty edge list is unweighted. Edges are
/// kept in input order, self-loops and parallel edges included (the algorithms decide
/// what they accept).
///
/// # Errors
/// [`CliError::Json`] for malformed JSON (numbers too large for `f64` included),
/// [`CliError::Shape`] for a document that is not such an object (a missing or unknown
/// key, an edge that is not `[u, v]` or `[u, v, w]`, a vertex id that is not a
/// non-negative integer, weights on some edges only), and
/// [`crate::Error::VertexOutOfRange`] (inside [`CliError::Library`]) for an id `>= n`.
pub fn parse_json_graph(text: &str) -> Result<EdgeList, CliError> {
    use serde_json::Value;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let doc: Value = serde_json::from_str(text).map_err(|e| CliError::Json {
        line: e.line(),
        column: e.column(),
        message: strip_position(&e.to_string()),
    })?;
    let Value::Object(map) = doc else {
        return Err(CliError::Shape(
            "expected a graph object {\"vertices\": n, \"edges\": [[u, v], ...]}".to_string(),
        ));
    };
    if let Some(key) = map.keys().find(|k| *k != "vertices" && *k != "edges") {
        return Err(CliError::Shape(format!(
            "unexpected key '{key}' in the graph object; expected \"vertices\" and \"edges\""
        )));
    }
    let vertices = match map.get("vertices") {
        None => {
            return Err(CliError::Shape(
                "the graph object has no \"vertices\" count".to_string(),
            ))
        }
        Some(v) => v
            .as_u64()
            .and_then(|n| usize::try_from(n).ok())
            .ok_or_else(|| {
                CliError::Shape(format!(
                    "\"vertices\" must be a non-negative integer, found {v}"
                ))
            })?,
    };
    let edges = match map.get("edges") {
        None => {
            return Err(CliError::Shape(
                "the graph object has no \"edges\" list".to_string(),
            ))
        }
        Some(Value::Array(edges)) => edges,
        Some(other) => {
            return Err(CliError::Shape(format!(
                "\"edges\" must be an array of [u, v] or [u, v, w], found {other}"
            )))
        }
    };
    let weighted = matches!(edges.first(), Some(Value::Array(e)) if e.len() == 3);
    let mut list = Vec::with_capacity(edges.len());
    let mut weights = Vec::with_capacity(if weighted { edges.len() } else { 0 });
    for (index, edge) in edges.iter().enumerate() {
        let items = match edge {
            Value::Array(items) if items.len() == 2 || items.len() == 3 => items,
            _ => {
                return Err(CliError::Shape(format!(
                    "edge {index} must be [u, v] or [u, v, w], found {edge}"
                )))
            }
        };
        if (items.len() == 3) != weighted {
            return Err(CliError::Shape(format!(
                "edge {index} {} but edge 0 {}; give every edge a weight or none",
                if weighted {
                    "has no weight"
                } else {
                    "has a weight"
                },
                if weighted { "has one" } else { "does not" },
            )));
        }
        let mut ends = [0usize; 2];
        for (end, item) in ends.iter_mut().zip(items) {
            *end = item
                .as_u64()
                .and_then(|v| usize::try_from(v).ok())
                .ok_or_else(|| {
                    CliError::Shape(format!(
                        "edge {index}: vertex ids must be non-negative integers, found {item}"
                    ))
                })?;
            if *end >= vertices {
                return Err(crate::Error::VertexOutOfRange {
                    edge: index,
                    vertex: *end,
                    vertices,
                }
                .into());
            }
        }
        list.push(ends);
        if weighted {
            let w = items[2].as_f64().ok_or_else(|| {
                CliError::Shape(format!(
                    "edge {index}: the weight must be a number, found {}",
                    items[2]
                ))
            })?;
            weights.push(w);
        }
    }
    Ok(EdgeList {
        vertices,
        edges: list,
        weights: weighted.then_some(weights),
    })
}

/// serde_json appends " at line L column C"; we report the position separately.
fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(i) => message[..i].to_string(),
        None => message.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Error;

    #[test]
    fn graphs_parse_with_and_without_weights() {
        let g = parse_json_graph(r#"{"vertices": 4, "edges": [[0, 1], [3, 2], [1, 1]]}"#).unwrap();
        assert_eq!(g.vertices, 4);
        assert_eq!(g.edges, vec![[0, 1], [3, 2], [1, 1]]);
        assert_eq!(g.weights, None);
        let g = parse_json_graph(r#"{"edges": [[0, 1, 0.5], [1, 2, -3]], "vertices": 3}"#).unwrap();
        assert_eq!(g.weights, Some(vec![0.5, -3.0]));
        let g = parse_json_graph(r#"{"vertices": 0, "edges": []}"#).unwrap();
        assert_eq!((g.vertices, g.edges.len(), g.weights), (0, 0, None));
    }

    #[test]
    fn generated_graphs_round_trip_through_the_reader() {
        use crate::gen::{graph, with_random_weights, GraphKind};
        let g = with_random_weights(graph(GraphKind::Gnm, 30, 80, 2).unwrap(), 2);
        let weights = g.weights.clone().unwrap();
        let edges: Vec<(usize, usize, f64)> = g
            .edges
            .iter()
            .zip(&weights)
            .map(|(&[u, v], &w)| (u, v, w))
            .collect();
        let text = serde_json::json!({"vertices": g.vertices, "edges": edges}).to_string();
        assert_eq!(parse_json_graph(&text).unwrap(), g);
    }

    #[test]
    fn bad_graphs_are_named() {
        let vertex = parse_json_graph(r#"{"vertices": 3, "edges": [[0, 1], [1, 3]]}"#);
        assert!(matches!(
            vertex,
            Err(CliError::Library(Error::VertexOutOfRange {
                edge: 1,
                vertex: 3,
                vertices: 3
            }))
        ));
        for (text, needle) in [
            ("[]", "expected a graph object"),
            (r#"{"edges": []}"#, "no \"vertices\""),
            (r#"{"vertices": 2}"#, "no \"edges\""),
            (r#"{"vertices": -1, "edges": []}"#, "non-negative integer"),
            (r#"{"vertices": 2.5, "edges": []}"#, "non-negative integer"),
            (r#"{"vertices": 2, "edges": {}}"#, "must be an array"),
            (r#"{"vertices": 2, "edges": [[0]]}"#, "edge 0 must be"),
            (
                r#"{"vertices": 2, "edges": [[0, 1], [0, 1, 2, 3]]}"#,
                "edge 1 must be",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 1], [0, 1, 2]]}"#,
                "edge 1 has a weight",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 1, 1], [0, 1]]}"#,
                "edge 1 has no weight",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, -1]]}"#,
                "edge 0: vertex ids",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 0.5]]}"#,
                "edge 0: vertex ids",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 1, "w"]]}"#,
                "edge 0: the weight",
            ),
            (
                r#"{"vertices": 2, "edges": [], "colour": 1}"#,
                "unexpected key 'colour'",
            ),
        ] {
            match parse_json_graph(text) {
                Err(CliError::Shape(m)) => assert!(m.contains(needle), "{text}: {m}"),
                other => panic!("{text}: {other:?}"),
            }
        }
        match parse_json_graph("{\"vertices\": 2,\n \"edges\": [[0, 1, 1e999]]}") {
            Err(CliError::Json {
                line: 2, message, ..
            }) => {
                assert!(message.contains("out of range"), "{message}")
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(
            parse_json_graph(r#"{"vertices": 2, "edges": [[0, 1, NaN]]}"#),
            Err(CliError::Json { .. })
        ));
    }
}
