//! The JSON graph reader: `{"vertices": n, "edges": [[u, v], ...]}` (or `[[u, v, w], ...]`),
//! or the bare edge list.

use crate::cli::CliError;
use crate::graph::EdgeList;
use crate::util::quote;
use serde::de::{self, Deserialize, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Number, Value};
use std::fmt;

/// Parses a JSON graph: an object `{"vertices": n, "edges": [[u, v], ...]}` (or
/// `[[u, v, w], ...]`), or the bare edge list `[[u, v], ...]` / `[[u, v, w], ...]`, whose
/// vertices are `0..=` the largest id (so `0` for an empty list; give the object to have
/// isolated vertices above the largest id).
///
/// Either every edge has a weight or none has; an empty edge list is unweighted. Edges are
/// kept in input order, self-loops and parallel edges included (the algorithms decide
/// what they accept).
///
/// # Errors
/// [`CliError::Json`] for malformed JSON (numbers too large for `f64` included, nesting
/// deeper than 128 levels, and a key given twice in one object), [`CliError::Shape`] for a
/// document that is not such a graph (a missing or unknown key, an edge that is not
/// `[u, v]` or `[u, v, w]`, a vertex id that is not a non-negative integer, weights on some
/// edges only), and [`crate::Error::VertexOutOfRange`] (inside [`CliError::Library`]) for an
/// id `>= n`. Values echoed in messages are cut and escaped.
pub fn parse_json_graph(text: &str) -> Result<EdgeList, CliError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let doc = serde_json::from_str::<StrictValue>(text)
        .map_err(|e| CliError::Json {
            line: e.line(),
            column: e.column(),
            message: strip_position(&e.to_string()),
        })?
        .0;
    let map = match doc {
        Value::Object(map) => map,
        Value::Array(edges) => {
            let (edges, weights) = parse_edges(&edges, None)?;
            let largest = edges.iter().flatten().max();
            let vertices = match largest {
                None => 0,
                Some(&id) => id.checked_add(1).ok_or_else(|| {
                    CliError::Shape(format!("vertex id {id} is too large for a vertex count"))
                })?,
            };
            return Ok(EdgeList {
                vertices,
                edges,
                weights,
            });
        }
        other => {
            return Err(CliError::Shape(format!(
                "expected a graph object {{\"vertices\": n, \"edges\": [[u, v], ...]}} or an \
                 edge list [[u, v], ...], found {}",
                describe(&other)
            )))
        }
    };
    if let Some(key) = map.keys().find(|k| *k != "vertices" && *k != "edges") {
        return Err(CliError::Shape(format!(
            "unexpected key {} in the graph object; expected \"vertices\" and \"edges\"",
            quote(key)
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
                    "\"vertices\" must be a non-negative integer, found {}",
                    describe(v)
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
                "\"edges\" must be an array of [u, v] or [u, v, w], found {}",
                describe(other)
            )))
        }
    };
    let (edges, weights) = parse_edges(edges, Some(vertices))?;
    Ok(EdgeList {
        vertices,
        edges,
        weights,
    })
}

/// The edges and, if the first edge has one, every edge's weight; ids are checked against
/// `vertices` when the count is given.
#[allow(clippy::type_complexity)]
fn parse_edges(
    edges: &[Value],
    vertices: Option<usize>,
) -> Result<(Vec<[usize; 2]>, Option<Vec<f64>>), CliError> {
    let weighted = matches!(edges.first(), Some(Value::Array(e)) if e.len() == 3);
    let mut list = Vec::with_capacity(edges.len());
    let mut weights = Vec::with_capacity(if weighted { edges.len() } else { 0 });
    for (index, edge) in edges.iter().enumerate() {
        let items = match edge {
            Value::Array(items) if items.len() == 2 || items.len() == 3 => items,
            _ => {
                return Err(CliError::Shape(format!(
                    "edge {index} must be [u, v] or [u, v, w], found {}",
                    describe(edge)
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
                        "edge {index}: vertex ids must be non-negative integers, found {}",
                        describe(item)
                    ))
                })?;
            if let Some(vertices) = vertices.filter(|&n| *end >= n) {
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
                    describe(&items[2])
                ))
            })?;
            weights.push(w);
        }
    }
    Ok((list, weighted.then_some(weights)))
}

/// A JSON value as an error message shows it, short whatever its size: numbers, booleans and
/// null as written, strings quoted (cut and escaped), arrays and objects by their size.
fn describe(v: &Value) -> String {
    match v {
        Value::Null | Value::Bool(_) | Value::Number(_) => v.to_string(),
        Value::String(s) => format!("the string {}", quote(s)),
        Value::Array(a) => format!(
            "an array of {} {}",
            a.len(),
            if a.len() == 1 { "item" } else { "items" }
        ),
        Value::Object(m) => format!(
            "an object with {} {}",
            m.len(),
            if m.len() == 1 { "key" } else { "keys" }
        ),
    }
}

/// serde_json appends " at line L column C"; we report the position separately.
fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(i) => message[..i].to_string(),
        None => message.to_string(),
    }
}

/// A JSON value read like `serde_json::Value`, except that an object giving a key twice is
/// an error (`serde_json::Value` keeps the last silently, so `{"vertices": 3, "vertices":
/// 4}` would mean 4). serde_json's nesting limit (128) still applies, so deep input cannot
/// overflow the stack.
struct StrictValue(Value);

impl<'de> Deserialize<'de> for StrictValue {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(StrictVisitor).map(StrictValue)
    }
}

struct StrictVisitor;

impl<'de> Visitor<'de> for StrictVisitor {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_bool<E>(self, b: bool) -> Result<Value, E> {
        Ok(Value::Bool(b))
    }

    fn visit_i64<E>(self, n: i64) -> Result<Value, E> {
        Ok(Value::Number(n.into()))
    }

    fn visit_u64<E>(self, n: u64) -> Result<Value, E> {
        Ok(Value::Number(n.into()))
    }

    fn visit_f64<E: de::Error>(self, x: f64) -> Result<Value, E> {
        // serde_json reports non-finite numbers itself; this is for other formats.
        Number::from_f64(x)
            .map(Value::Number)
            .ok_or_else(|| E::custom("a number is not finite"))
    }

    fn visit_str<E>(self, s: &str) -> Result<Value, E> {
        Ok(Value::String(s.to_string()))
    }

    fn visit_string<E>(self, s: String) -> Result<Value, E> {
        Ok(Value::String(s))
    }

    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut items = Vec::new();
        while let Some(StrictValue(item)) = seq.next_element()? {
            items.push(item);
        }
        Ok(Value::Array(items))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut access: A) -> Result<Value, A::Error> {
        let mut map = Map::new();
        while let Some(key) = access.next_key::<String>()? {
            if map.contains_key(&key) {
                return Err(de::Error::custom(format!(
                    "duplicate key {} in an object",
                    quote(&key)
                )));
            }
            let StrictValue(value) = access.next_value()?;
            map.insert(key, value);
        }
        Ok(Value::Object(map))
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
            ("3", "expected a graph object"),
            ("\"g\"", "found the string \"g\""),
            (
                r#"{"vertices": 2, "edges": [[0, 1, "w"], [1, 0, 2]]}"#,
                "found the string \"w\"",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, [1]]]}"#,
                "found an array of 1 item",
            ),
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
                "unexpected key \"colour\"",
            ),
            (
                "{\"vertices\": 2, \"edges\": [], \"\\u001b[2J\": 1}",
                "unexpected key \"\\u{1b}[2J\"",
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

    #[test]
    fn a_key_given_twice_is_an_error_where_it_is_given() {
        for (text, key) in [
            (r#"{"vertices": 3, "vertices": 4, "edges": []}"#, "vertices"),
            (
                r#"{"edges": [], "vertices": 2, "edges": [[0, 1]]}"#,
                "edges",
            ),
            (
                r#"{"vertices": 2, "edges": [[0, 1, {"a": 1, "a": 2}]]}"#,
                "a",
            ),
        ] {
            // The position is the closing quote of the second occurrence.
            let column = text.rfind(&format!("\"{key}\"")).unwrap() + key.len() + 2;
            match parse_json_graph(text) {
                Err(CliError::Json {
                    line: 1,
                    column: c,
                    message,
                }) => {
                    assert_eq!(message, format!("duplicate key \"{key}\" in an object"));
                    assert_eq!(c, column, "{text}");
                }
                other => panic!("{text}: {other:?}"),
            }
        }
        // Distinct keys that differ only after unescaping are the same key.
        assert!(matches!(
            parse_json_graph(r#"{"vertices": 1, "vert\u0069ces": 2, "edges": []}"#),
            Err(CliError::Json { .. })
        ));
    }

    #[test]
    fn bare_edge_lists_count_vertices_up_to_the_largest_id() {
        let g = parse_json_graph("[[0, 1, 2.5], [3, 1, -1]]").unwrap();
        assert_eq!(g.vertices, 4);
        assert_eq!(g.edges, vec![[0, 1], [3, 1]]);
        assert_eq!(g.weights, Some(vec![2.5, -1.0]));
        let g = parse_json_graph(" [[2, 2]] ").unwrap();
        assert_eq!((g.vertices, g.edges, g.weights), (3, vec![[2, 2]], None));
        let g = parse_json_graph("[]").unwrap();
        assert_eq!((g.vertices, g.edges.len()), (0, 0));
        // The same checks as inside the object.
        for (text, needle) in [
            ("[[0, 1], [0, 1, 2]]", "edge 1 has a weight"),
            ("[[0, -1]]", "edge 0: vertex ids"),
            ("[[0]]", "edge 0 must be"),
            ("[[0, 18446744073709551615]]", "too large"),
        ] {
            match parse_json_graph(text) {
                Err(CliError::Shape(m)) => assert!(m.contains(needle), "{text}: {m}"),
                other => panic!("{text}: {other:?}"),
            }
        }
    }

    #[test]
    fn hostile_documents_give_short_errors() {
        let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
        match parse_json_graph(&deep) {
            Err(CliError::Json { message, .. }) => {
                assert!(message.contains("recursion"), "{message}")
            }
            other => panic!("{other:?}"),
        }
        let long_key = format!(
            r#"{{"vertices": 1, "edges": [], "{}": 0}}"#,
            "k".repeat(1_000_000)
        );
        let m = parse_json_graph(&long_key).unwrap_err().to_string();
        assert!(m.len() < 200 && m.contains("(1000000 characters)"), "{m}");
        let long_edge = format!("[[0, 1, 2, {}]]", "3, ".repeat(100_000) + "3");
        let m = parse_json_graph(&long_edge).unwrap_err().to_string();
        assert_eq!(
            m,
            "edge 0 must be [u, v] or [u, v, w], found an array of 100004 items"
        );
    }
}
