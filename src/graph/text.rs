//! Graphs as text: the DIMACS `.col` format of the colouring benchmarks, and plain edge lists.
//!
//! **DIMACS** (the format of the Second DIMACS Implementation Challenge's colouring
//! instances, `queen8_8.col`, `DSJC250.5.col`, ...): lines `c ...` are comments, one line
//! `p edge n m` (or `p col n m`) gives the vertex and edge counts, and each of the `m` lines
//! `e u v` an edge between vertices numbered 1 to n. Some published files list an edge twice
//! or in both directions; they are kept as given, and [`Graph`](super::Graph) merges them
//! (reporting how many). Vertices become `0..n` (one less than in the file).
//!
//! **Edge lists**: one edge `u v` (or weighted, `u v w`) per line, vertices numbered from 0,
//! `#` or `%` starting a comment, blank lines ignored; the vertices are 0 to the largest id.
//!
//! Every malformed line is an [`Error::Syntax`] with its 1-based number, and the counts are
//! checked against [`MAX_VERTICES`](crate::limits::MAX_VERTICES) and
//! [`MAX_EDGES`](crate::limits::MAX_EDGES) before anything is allocated for them.
//!
//! ```
//! use compgeo::graph::{read_dimacs, write_dimacs, Graph};
//!
//! let text = "c a triangle and a pendant vertex\np edge 4 4\ne 1 2\ne 2 3\ne 3 1\ne 3 4\n";
//! let edges = read_dimacs(text)?;
//! assert_eq!((edges.vertices, edges.edges.len()), (4, 4));
//! assert_eq!(edges.edges[3], [2, 3]);
//! assert_eq!(read_dimacs(&write_dimacs(&edges))?, edges);
//!
//! let e = read_dimacs("p edge 3 1\ne 1 4\n").unwrap_err();
//! assert_eq!(e.to_string(), "DIMACS line 2: vertex 4 is not in 1..=3");
//! # Ok::<(), compgeo::Error>(())
//! ```

use std::fmt::Write as _;

use super::EdgeList;
use crate::error::{Error, Result};
use crate::limits::{EDGES, VERTICES};
use crate::util::quote;

/// The error for line `line` of a `format` text.
fn syntax(format: &'static str, line: usize, problem: impl Into<String>) -> Error {
    Error::Syntax {
        format,
        line,
        problem: problem.into(),
    }
}

/// Reads a number of kind `what` from `token`, naming the line on failure.
fn number(format: &'static str, line: usize, what: &str, token: Option<&str>) -> Result<usize> {
    let token = token.ok_or_else(|| syntax(format, line, format!("missing {what}")))?;
    token.parse().map_err(|_| {
        syntax(
            format,
            line,
            format!("{what} {} is not a non-negative integer", quote(token)),
        )
    })
}

/// Reads a DIMACS `.col` graph: `c` comment lines, one `p edge n m` (or `p col n m`) line and
/// m lines `e u v` with vertices 1 to n, which become 0 to n − 1. Repeated edges are kept as
/// given; [`Graph`](super::Graph) merges them.
///
/// # Errors
/// [`Error::Syntax`] naming the line: a line that is not a comment, the `p` line or an `e`
/// line; a second `p` line, an `e` line before it, or none at all (the line after the last);
/// a count or vertex that is not a number; a vertex 0 or above n; more or fewer `e` lines
/// than the `p` line says (the `p` line, or the first extra `e` line).
/// [`Error::LimitExceeded`] for counts beyond the graph limits.
///
/// # Complexity
/// O(text length) time; O(n + m) space.
pub fn read_dimacs(text: &str) -> Result<EdgeList> {
    const F: &str = "DIMACS";
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut header: Option<(usize, usize, usize)> = None; // (line, n, m)
    let mut edges: Vec<[usize; 2]> = Vec::new();
    let mut last = 0;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        last = line;
        let mut tokens = raw.split_whitespace();
        match tokens.next() {
            None | Some("c") => continue,
            Some("p") => {
                if let Some((first, _, _)) = header {
                    return Err(syntax(
                        F,
                        line,
                        format!("a second p line (the first is line {first})"),
                    ));
                }
                match tokens.next() {
                    Some("edge" | "col" | "edges") => {}
                    Some(other) => {
                        return Err(syntax(
                            F,
                            line,
                            format!("the p line's format is {}, not edge", quote(other)),
                        ))
                    }
                    None => return Err(syntax(F, line, "the p line has no format (p edge n m)")),
                }
                let n = number(F, line, "vertex count", tokens.next())?;
                let m = number(F, line, "edge count", tokens.next())?;
                if let Some(extra) = tokens.next() {
                    return Err(syntax(
                        F,
                        line,
                        format!("unexpected {} after p edge n m", quote(extra)),
                    ));
                }
                VERTICES.check(n as u128)?;
                EDGES.check(m as u128)?;
                edges.reserve_exact(m);
                header = Some((line, n, m));
            }
            Some("e") => {
                let Some((_, n, m)) = header else {
                    return Err(syntax(F, line, "an e line before the p line"));
                };
                let mut vertex = || -> Result<usize> {
                    let v = number(F, line, "vertex", tokens.next())?;
                    if v == 0 || v > n {
                        return Err(syntax(F, line, format!("vertex {v} is not in 1..={n}")));
                    }
                    Ok(v - 1)
                };
                let (u, v) = (vertex()?, vertex()?);
                if let Some(extra) = tokens.next() {
                    return Err(syntax(
                        F,
                        line,
                        format!("unexpected {} after e u v", quote(extra)),
                    ));
                }
                if edges.len() == m {
                    return Err(syntax(
                        F,
                        line,
                        format!("more e lines than the {m} edges of the p line"),
                    ));
                }
                edges.push([u, v]);
            }
            Some(other) => {
                return Err(syntax(
                    F,
                    line,
                    format!("a line starting with {}: expected c, p or e", quote(other)),
                ))
            }
        }
    }
    let Some((line, n, m)) = header else {
        return Err(syntax(F, last + 1, "no p line (p edge n m)"));
    };
    if edges.len() != m {
        return Err(syntax(
            F,
            line,
            format!("the p line gives {m} edges, the file has {}", edges.len()),
        ));
    }
    Ok(EdgeList {
        vertices: n,
        edges,
        weights: None,
    })
}

/// Writes `graph` as DIMACS text: a comment, `p edge n m` and one `e u v` line per edge,
/// vertices numbered from 1. Weights are not part of the format and are left out.
///
/// # Complexity
/// O(n + m).
pub fn write_dimacs(graph: &EdgeList) -> String {
    let mut out = String::with_capacity(16 * graph.edges.len() + 64);
    let _ = writeln!(out, "c written by compgeo {}", env!("CARGO_PKG_VERSION"));
    let _ = writeln!(out, "p edge {} {}", graph.vertices, graph.edges.len());
    for [u, v] in &graph.edges {
        let _ = writeln!(out, "e {} {}", u + 1, v + 1);
    }
    out
}

/// Reads a plain edge list: lines `u v` or `u v w` with vertices from 0, `#` or `%` starting a
/// comment, blank lines ignored; the vertices are 0 to the largest id.
///
/// # Errors
/// [`Error::Syntax`] naming the line: a vertex that is not a non-negative integer, a weight
/// that is not a finite number, a line with fewer than two or more than three fields, or
/// weights on some lines only. [`Error::LimitExceeded`] for a vertex id or edge count
/// beyond the graph limits.
///
/// # Complexity
/// O(text length) time; O(m) space.
pub fn read_edge_list(text: &str) -> Result<EdgeList> {
    const F: &str = "edge list";
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut edges: Vec<[usize; 2]> = Vec::new();
    let mut weights: Vec<f64> = Vec::new();
    let mut weighted: Option<(bool, usize)> = None; // (weighted, first edge's line)
    let mut largest: Option<usize> = None;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let content = raw.split(['#', '%']).next().unwrap_or("");
        let tokens: Vec<&str> = content.split_whitespace().collect();
        if tokens.is_empty() {
            continue;
        }
        if !(2..=3).contains(&tokens.len()) {
            return Err(syntax(
                F,
                line,
                format!("{} fields: expected u v or u v w", tokens.len()),
            ));
        }
        let has_weight = tokens.len() == 3;
        match weighted {
            None => weighted = Some((has_weight, line)),
            Some((w, first)) if w != has_weight => {
                return Err(syntax(
                    F,
                    line,
                    format!(
                        "{} but line {first} {}: either every edge has a weight or none has",
                        if has_weight { "a weight" } else { "no weight" },
                        if w { "has one" } else { "has none" }
                    ),
                ))
            }
            Some(_) => {}
        }
        let u = number(F, line, "vertex", Some(tokens[0]))?;
        let v = number(F, line, "vertex", Some(tokens[1]))?;
        VERTICES.check(u.max(v) as u128 + 1)?;
        EDGES.check(edges.len() as u128 + 1)?;
        if has_weight {
            let w: f64 = tokens[2].parse().map_err(|_| {
                syntax(
                    F,
                    line,
                    format!("weight {} is not a number", quote(tokens[2])),
                )
            })?;
            if !w.is_finite() {
                return Err(syntax(F, line, format!("weight {w} is not finite")));
            }
            weights.push(w);
        }
        largest = Some(largest.map_or(u.max(v), |l| l.max(u).max(v)));
        edges.push([u, v]);
    }
    Ok(EdgeList {
        vertices: largest.map_or(0, |l| l + 1),
        edges,
        weights: matches!(weighted, Some((true, _))).then_some(weights),
    })
}
