//! Seeded graphs: random families and the named graphs the colouring and MST modules are
//! tested and measured on.

use super::points::ceil_sqrt;
use super::rng::Rng;
use crate::error::{Error, Result};
use crate::graph::EdgeList;
use crate::limits;
use crate::util::named_enum;
use std::collections::HashSet;

named_enum! {
    /// The family a graph is drawn from. See [`graph`] for what each kind produces.
    ///
    /// Names are `gnm`, `grid`, `complete`, `cycle`, `tree`, `petersen`, `mycielski`, `queen`,
    /// `crown`.
    ///
    /// ```
    /// use compgeo::gen::GraphKind;
    ///
    /// assert_eq!("crown".parse::<GraphKind>()?, GraphKind::Crown);
    /// assert_eq!(GraphKind::Gnm.name(), "gnm");
    /// assert_eq!(GraphKind::ALL.len(), 9);
    /// # Ok::<(), compgeo::Error>(())
    /// ```
    pub enum GraphKind ("graph kind") {
        /// Uniform random simple graph with `n` vertices and `m` edges, G(n, m).
        Gnm = "gnm",
        /// A near-square grid graph on `n` vertices.
        Grid = "grid",
        /// The complete graph K_n.
        Complete = "complete",
        /// The cycle C_n, `n >= 3`.
        Cycle = "cycle",
        /// A uniform random labelled tree on `n` vertices.
        Tree = "tree",
        /// The Petersen graph (10 vertices, 15 edges, 3-regular).
        Petersen = "petersen",
        /// The Mycielski graph M_n (triangle-free, chromatic number `n`).
        Mycielski = "mycielski",
        /// The queen graph of an `n x n` chessboard.
        Queen = "queen",
        /// The crown graph on `2n` vertices: K_{n,n} minus a perfect matching.
        Crown = "crown",
    }
}

/// A graph of the given kind, the same for the same `seed` on every machine.
///
/// `n` sizes the graph as follows (and `m` is read by `Gnm` only; every other kind
/// ignores it):
///
/// - `Gnm`: `n` vertices and `m` distinct edges, every such graph equally likely (Floyd's
///   sampling of `m` of the `n(n-1)/2` vertex pairs).
/// - `Grid`: `n` vertices laid out row by row in `cols = ceil(sqrt n)` columns (the last
///   row may be partial), vertex `k` at column `k % cols`, row `k / cols`; edges join
///   horizontal and vertical neighbours. The same layout as
///   [`PointKind::Grid`](super::PointKind::Grid) before shuffling.
/// - `Complete`: K_n, `n(n-1)/2` edges.
/// - `Cycle`: C_n, edges `{i, i+1}` and `{0, n-1}`; needs `n >= 3`.
/// - `Tree`: a uniform random labelled tree on `n` vertices (decoded from a random Prüfer
///   sequence), `n - 1` edges.
/// - `Petersen`: the Petersen graph; `n` must be 10. Outer cycle `0..5`, spokes
///   `{i, i+5}`, inner pentagram `{5+i, 5+(i+2) mod 5}`.
/// - `Mycielski`: M_k with `k = n >= 1`: M_1 = K_1, M_2 = K_2, and M_{k+1} is the
///   Mycielskian of M_k (vertices `0..v` of M_k, shadows `v + i` joined to the neighbours
///   of `i`, and a hub `2v` joined to every shadow). M_3 = C_5, M_4 is the Grötzsch graph;
///   for `k >= 2` M_k has `3 * 2^(k-2) - 1` vertices, is triangle-free and has chromatic
///   number `k`.
/// - `Queen`: `n^2` vertices, square `(row r, column c)` is vertex `r n + c`, joined to
///   every square in the same row, column or diagonal: `n(n-1)(5n-1)/3` edges.
/// - `Crown`: vertices `u_0, v_0, u_1, v_1, ...` numbered `u_i = 2i`, `v_i = 2i + 1`,
///   with `u_i v_j` an edge whenever `i != j`: `n(n-1)` edges. Greedy colouring in vertex
///   order uses `n` colours though the graph is bipartite (chromatic number 2 for
///   `n >= 2`).
///
/// The course's facts `chi(K_n) = n`, `chi(C_2p) = 2`, `chi(C_2p+1) = 3`, `chi(T) = 2`
/// ([RD, §2.1] "Coloración de vértices") are checked on these
/// families. Edges come with `u < v`, without duplicates, sorted lexicographically, and
/// unweighted (see [`with_random_weights`]). `n = 0` gives the empty graph for every kind
/// except `Cycle`, `Petersen` and `Mycielski`.
///
/// # Errors
/// [`Error::InvalidParameter`] if `m > n(n-1)/2` for `Gnm` (name `"m"`); if `n < 3` for
/// `Cycle`, `n != 10` for `Petersen`, `n = 0` for `Mycielski` (name `"n"`);
/// [`Error::LimitExceeded`] if the graph would have more than
/// [`MAX_VERTICES`](limits::MAX_VERTICES) vertices or [`MAX_EDGES`](limits::MAX_EDGES) edges
/// (`K_n` has n(n − 1)/2), found before anything is allocated.
///
/// # Complexity
/// O(V + E) time and space for V vertices and E edges, plus O(E log E) for the final sort
/// (and the expected O(m) hash-set work of Floyd's sampling for `Gnm`).
///
/// Counts nothing: generators are workloads, not measured algorithms.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
///
/// let g = graph(GraphKind::Petersen, 10, 0, 1)?;
/// assert_eq!((g.vertices, g.edges.len()), (10, 15));
/// let g = graph(GraphKind::Gnm, 100, 250, 42)?;
/// assert_eq!(g.edges.len(), 250);
/// assert!(g.edges.iter().all(|&[u, v]| u < v && v < 100));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn graph(kind: GraphKind, n: usize, m: usize, seed: u64) -> Result<EdgeList> {
    let mut rng = Rng::new(seed);
    let (vertices, mut edges) = match kind {
        GraphKind::Gnm => (checked_vertices(n as u128)?, gnm(&mut rng, n, m)?),
        GraphKind::Grid => (checked_vertices(n as u128)?, grid(n)?),
        GraphKind::Complete => (checked_vertices(n as u128)?, complete(n)?),
        GraphKind::Cycle => (checked_vertices(n as u128)?, cycle(n)?),
        GraphKind::Tree => (checked_vertices(n as u128)?, tree(&mut rng, n)),
        GraphKind::Petersen => (10, petersen(n)?),
        GraphKind::Mycielski => mycielski(n)?,
        GraphKind::Queen => queen(n)?,
        GraphKind::Crown => crown(n)?,
    };
    edges.sort_unstable();
    Ok(EdgeList {
        vertices,
        edges,
        weights: None,
    })
}

/// `g` with one random weight per edge, replacing any weights it had.
///
/// Weights are independent and uniform in `[0, 1)`, multiples of 2^-53 (53 random bits
/// each), so they are exact, non-negative, and distinct with overwhelming probability (a
/// minimum spanning tree is then unique). The same `seed` gives the same weights on every
/// machine. The weights come from a different ChaCha8 stream than [`graph`] uses, so
/// passing the graph's own seed gives weights independent of its structure.
///
/// # Complexity
/// O(E) time and space for E edges.
///
/// ```
/// use compgeo::gen::{graph, with_random_weights, GraphKind};
///
/// let g = with_random_weights(graph(GraphKind::Complete, 5, 0, 0)?, 9);
/// let w = g.weights.as_ref().unwrap();
/// assert_eq!(w.len(), 10);
/// assert!(w.iter().all(|&x| (0.0..1.0).contains(&x)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn with_random_weights(g: EdgeList, seed: u64) -> EdgeList {
    let mut rng = Rng::with_stream(seed, WEIGHT_STREAM);
    let weights = g.edges.iter().map(|_| rng.unit()).collect();
    EdgeList {
        weights: Some(weights),
        ..g
    }
}

/// The ChaCha8 stream the weights are drawn from (the structure uses stream 0).
const WEIGHT_STREAM: u64 = 1;

fn invalid(name: &'static str, reason: String) -> Error {
    Error::InvalidParameter { name, reason }
}

/// Rejects a graph with more than `MAX_VERTICES` vertices before allocating it.
fn checked_vertices(v: u128) -> Result<usize> {
    limits::VERTICES.check(v)
}

/// Rejects a graph with more than `MAX_EDGES` edges before allocating it.
fn checked_edges(e: u128) -> Result<usize> {
    limits::EDGES.check(e)
}

/// `n(n-1)/2` without overflow.
fn pairs(n: usize) -> u128 {
    let n = n as u128;
    n * n.saturating_sub(1) / 2
}

fn gnm(rng: &mut Rng, n: usize, m: usize) -> Result<Vec<[usize; 2]>> {
    let total = pairs(n);
    if m as u128 > total {
        return Err(invalid(
            "m",
            format!("{m} edges do not fit in a simple graph on {n} vertices (at most {total})"),
        ));
    }
    checked_edges(m as u128)?;
    // n <= MAX_VERTICES = 2^26 keeps the number of pairs below 2^51, well inside u64.
    let total = total as u64;
    // Floyd's algorithm: a uniform m-subset of 0..total in m draws. The set is only
    // queried, never iterated, so its hashing order cannot leak into the output.
    let mut chosen: HashSet<u64> = HashSet::with_capacity(m);
    for j in total - m as u64..total {
        let t = rng.below(j + 1);
        if !chosen.insert(t) {
            chosen.insert(j);
        }
    }
    let mut indices: Vec<u64> = chosen.into_iter().collect();
    indices.sort_unstable();
    Ok(indices.into_iter().map(pair_of_index).collect())
}

/// The pair `[u, v]`, `u < v`, with colexicographic index `k = v(v-1)/2 + u`.
fn pair_of_index(k: u64) -> [usize; 2] {
    // Start from the rounded closed form and correct it with exact integer checks.
    let mut v = ((1.0 + (8.0 * k as f64 + 1.0).sqrt()) / 2.0) as u64;
    while v * (v.saturating_sub(1)) / 2 > k {
        v -= 1;
    }
    while (v + 1) * v / 2 <= k {
        v += 1;
    }
    let u = k - v * (v - 1) / 2;
    [u as usize, v as usize]
}

fn grid(n: usize) -> Result<Vec<[usize; 2]>> {
    let cols = ceil_sqrt(n).max(1);
    let rows = n.div_ceil(cols);
    checked_edges((n - rows.min(n) + n.saturating_sub(cols)) as u128)?;
    let mut edges = Vec::new();
    for k in 0..n {
        if (k + 1) % cols != 0 && k + 1 < n {
            edges.push([k, k + 1]);
        }
        if k + cols < n {
            edges.push([k, k + cols]);
        }
    }
    Ok(edges)
}

fn complete(n: usize) -> Result<Vec<[usize; 2]>> {
    let mut edges = Vec::with_capacity(checked_edges(pairs(n))?);
    for u in 0..n {
        edges.extend((u + 1..n).map(|v| [u, v]));
    }
    Ok(edges)
}

fn cycle(n: usize) -> Result<Vec<[usize; 2]>> {
    if n < 3 {
        return Err(invalid(
            "n",
            format!("a cycle needs at least 3 vertices, got {n}"),
        ));
    }
    let mut edges: Vec<[usize; 2]> = (0..n - 1).map(|i| [i, i + 1]).collect();
    edges.push([0, n - 1]);
    Ok(edges)
}

fn tree(rng: &mut Rng, n: usize) -> Vec<[usize; 2]> {
    if n < 2 {
        return Vec::new();
    }
    let code: Vec<usize> = (0..n - 2).map(|_| rng.index(n)).collect();
    // Linear-time Prüfer decoding: the smallest current leaf is joined to each code entry.
    let mut degree = vec![1usize; n];
    for &x in &code {
        degree[x] += 1;
    }
    let mut ptr = degree.iter().position(|&d| d == 1).unwrap_or(0);
    let mut leaf = ptr;
    let mut edges = Vec::with_capacity(n - 1);
    for &x in &code {
        edges.push(ordered(leaf, x));
        degree[x] -= 1;
        if degree[x] == 1 && x < ptr {
            leaf = x;
        } else {
            ptr += 1;
            while degree[ptr] != 1 {
                ptr += 1;
            }
            leaf = ptr;
        }
    }
    edges.push(ordered(leaf, n - 1));
    edges
}

fn ordered(a: usize, b: usize) -> [usize; 2] {
    [a.min(b), a.max(b)]
}

fn petersen(n: usize) -> Result<Vec<[usize; 2]>> {
    if n != 10 {
        return Err(invalid(
            "n",
            format!("the Petersen graph has exactly 10 vertices; pass n = 10, not {n}"),
        ));
    }
    let mut edges = Vec::with_capacity(15);
    for i in 0..5 {
        edges.push(ordered(i, (i + 1) % 5));
        edges.push([i, i + 5]);
        edges.push(ordered(5 + i, 5 + (i + 2) % 5));
    }
    Ok(edges)
}

fn mycielski(k: usize) -> Result<(usize, Vec<[usize; 2]>)> {
    if k == 0 {
        return Err(invalid(
            "n",
            "the Mycielski order k = n must be at least 1".to_string(),
        ));
    }
    if k == 1 {
        return Ok((1, Vec::new()));
    }
    // Size check first: v' = 2v + 1, e' = 3e + v; both limits are passed long before
    // u128 could overflow.
    let (mut v, mut e) = (2u128, 1u128);
    for _ in 2..k {
        (v, e) = (2 * v + 1, 3 * e + v);
        checked_vertices(v)?;
        checked_edges(e)?;
    }
    let mut vertices = 2;
    let mut edges = vec![[0, 1]];
    for _ in 2..k {
        let hub = 2 * vertices;
        let mut next = Vec::with_capacity(3 * edges.len() + vertices);
        for &[a, b] in &edges {
            next.extend([[a, b], [a, vertices + b], [b, vertices + a]]);
        }
        next.extend((0..vertices).map(|i| [vertices + i, hub]));
        vertices = hub + 1;
        edges = next;
    }
    Ok((vertices, edges))
}

fn queen(n: usize) -> Result<(usize, Vec<[usize; 2]>)> {
    let nn = n as u128;
    let squares = checked_vertices(nn * nn)?;
    checked_edges(nn * nn.saturating_sub(1) * (5 * nn).saturating_sub(1) / 3)?;
    let mut edges = Vec::new();
    // Each attacking pair once: rays to the right, down, down-right and down-left.
    for r in 0..n {
        for c in 0..n {
            let id = r * n + c;
            edges.extend((c + 1..n).map(|c2| [id, r * n + c2]));
            for step in 1..n - r {
                let r2 = r + step;
                edges.push([id, r2 * n + c]);
                if c + step < n {
                    edges.push([id, r2 * n + c + step]);
                }
                if step <= c {
                    edges.push([id, r2 * n + c - step]);
                }
            }
        }
    }
    Ok((squares, edges))
}

fn crown(n: usize) -> Result<(usize, Vec<[usize; 2]>)> {
    let vertices = checked_vertices(2 * n as u128)?;
    let mut edges = Vec::with_capacity(checked_edges(2 * pairs(n))?);
    for i in 0..n {
        for j in (0..n).filter(|&j| j != i) {
            edges.push(ordered(2 * i, 2 * j + 1));
        }
    }
    Ok((vertices, edges))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pair_index_round_trips() {
        let mut k = 0;
        for v in 1..200usize {
            for u in 0..v {
                assert_eq!(pair_of_index(k), [u, v]);
                k += 1;
            }
        }
        // Near the largest index the generator can ask for.
        let n = limits::MAX_VERTICES as u64;
        let last = n * (n - 1) / 2 - 1;
        assert_eq!(pair_of_index(last), [(n - 2) as usize, (n - 1) as usize]);
    }

    #[test]
    fn prufer_oracle_decodes_a_known_code() {
        // Code [3, 3, 3] on 5 vertices: leaves 0, 1, 2 hang from 3, and 3-4 closes it.
        let mut edges = tree_from_code(5, &[3, 3, 3]);
        edges.sort_unstable();
        assert_eq!(edges, vec![[0, 3], [1, 3], [2, 3], [3, 4]]);
    }

    /// Prüfer decoding straight from the definition (repeatedly join the smallest leaf to
    /// the next code entry and remove it), in O(n^2): the oracle for the linear decoder.
    fn tree_from_code(n: usize, code: &[usize]) -> Vec<[usize; 2]> {
        let mut degree = vec![1usize; n];
        for &x in code {
            degree[x] += 1;
        }
        let mut edges = Vec::new();
        for &x in code {
            let leaf = (0..n).find(|&i| degree[i] == 1).unwrap();
            edges.push(ordered(leaf, x));
            degree[leaf] = 0;
            degree[x] -= 1;
        }
        let rest: Vec<usize> = (0..n).filter(|&i| degree[i] == 1).collect();
        edges.push(ordered(rest[0], rest[1]));
        edges
    }

    #[test]
    fn linear_prufer_decoding_matches_the_definition() {
        for seed in 0..50 {
            let n = 2 + seed as usize % 30;
            // Reproduce the code the generator draws, then decode it both ways.
            let mut rng = Rng::new(seed);
            let code: Vec<usize> = (0..n - 2).map(|_| rng.index(n)).collect();
            let mut expected = tree_from_code(n, &code);
            expected.sort_unstable();
            let mut got = tree(&mut Rng::new(seed), n);
            got.sort_unstable();
            assert_eq!(got, expected, "n = {n}, code = {code:?}");
        }
    }
}
