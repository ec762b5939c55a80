//! Cliques for the colouring searches: a lower bound on the chromatic number, and the
//! cliques of exactly t vertices that the exact search for t colours reasons over.
//!
//! A clique of q vertices needs q colours, so the largest clique found bounds the chromatic
//! number from below: the descent ([`reduce`](super::reduce)) stops as soon as it reaches
//! that many colours, instead of spending the rest of its budget on a target that cannot be
//! met. And when the target t equals the size of a clique, each of the t colours appears
//! exactly once in it: the exact search ([`exact`](super::exact)) uses that to place a colour
//! that has one vertex left in a clique.
//!
//! The cliques are grown greedily from a seed vertex, the usual heuristic: keep the
//! candidates (the vertices adjacent to every member so far) and add one of them until none
//! is left. [`clique_lower_bound`] picks the candidate of highest degree (the first of
//! equals), which costs the candidates plus the picked vertex's neighbours per step; it
//! gives up a seed as soon as its clique and candidates together cannot beat the best clique
//! so far. [`cliques_of_size`] picks the candidate with the most neighbours among the
//! candidates, which finds more of the large cliques at a cost of the candidates' degrees
//! per step, and keeps the distinct cliques of exactly the size asked.
//!
//! The tests check that every clique returned is a clique of the size asked, that the lower
//! bound is at most the chromatic number (brute force on small graphs) and equals the
//! clique number of complete graphs and of some n × n queen graphs (n).

use super::reduce::Adjacency;
use crate::count::Counter;

/// The size of the largest clique found by growing one greedily from every vertex, each
/// step adding the candidate of highest degree, with the steps spent (one per candidate
/// looked at and per neighbour marked).
///
/// # Complexity
/// O(Σ over the seeds of ω·(Δ + 1)) time for cliques of at most ω vertices and maximum
/// degree Δ, O(n) auxiliary space.
pub(super) fn clique_lower_bound<A: Adjacency, C: Counter>(g: &A, c: &mut C) -> (usize, u64) {
    let n = g.vertex_total();
    let mut mark = vec![0u32; n];
    let mut stamp = 0u32;
    let mut candidates: Vec<u32> = Vec::new();
    let (mut best, mut steps) = (usize::from(n > 0), 0u64);
    for v in 0..n {
        if g.neighbours(v).len() < best {
            continue;
        }
        candidates.clear();
        candidates.extend_from_slice(g.neighbours(v));
        steps += candidates.len() as u64;
        let mut size = 1;
        while !candidates.is_empty() && size + candidates.len() > best {
            let mut pick = candidates[0];
            for &x in &candidates[1..] {
                c.comparison();
                if g.neighbours(x as usize).len() > g.neighbours(pick as usize).len() {
                    pick = x;
                }
            }
            size += 1;
            steps += (candidates.len() + g.neighbours(pick as usize).len()) as u64;
            restrict(g, &mut candidates, pick as usize, &mut mark, &mut stamp, c);
        }
        best = best.max(size);
    }
    (best, steps)
}

/// The distinct cliques of exactly `size` vertices found by growing one greedily from every
/// vertex, each step adding the candidate with the most neighbours among the candidates;
/// each sorted, in the order found, with the steps spent (one per candidate looked at and
/// per neighbour of a candidate counted). A seed is given up when its clique and candidates
/// together have fewer than `size` vertices.
///
/// # Complexity
/// O(Σ over the seeds of ω·Σ_{u ∈ N(v)} deg u) time, O(n + the cliques) space.
pub(super) fn cliques_of_size<A: Adjacency, C: Counter>(
    g: &A,
    size: usize,
    c: &mut C,
) -> (Vec<Vec<u32>>, u64) {
    let n = g.vertex_total();
    let mut mark = vec![0u32; n];
    let mut stamp = 0u32;
    let mut found: Vec<Vec<u32>> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    let mut steps = 0u64;
    let mut candidates: Vec<u32> = Vec::new();
    let seeds = (0..n).flat_map(|v| {
        std::iter::once((v, None)).chain(
            g.neighbours(v)
                .iter()
                .filter(move |&&u| u as usize > v)
                .map(move |&u| (v, Some(u))),
        )
    });
    for (v, second) in seeds {
        let mut clique = vec![v as u32];
        candidates.clear();
        candidates.extend_from_slice(g.neighbours(v));
        steps += candidates.len() as u64;
        if let Some(u) = second {
            clique.push(u);
            steps += (candidates.len() + g.neighbours(u as usize).len()) as u64;
            restrict(g, &mut candidates, u as usize, &mut mark, &mut stamp, c);
        }
        while !candidates.is_empty() && clique.len() + candidates.len() >= size {
            fresh(&mut stamp, &mut mark);
            for &x in &candidates {
                mark[x as usize] = stamp;
            }
            let (mut pick, mut most) = (candidates[0], 0);
            for &x in &candidates {
                let within = g
                    .neighbours(x as usize)
                    .iter()
                    .filter(|&&y| mark[y as usize] == stamp)
                    .count();
                steps += g.neighbours(x as usize).len() as u64;
                c.comparison();
                if within > most {
                    (pick, most) = (x, within);
                }
            }
            clique.push(pick);
            steps += (candidates.len() + g.neighbours(pick as usize).len()) as u64;
            restrict(g, &mut candidates, pick as usize, &mut mark, &mut stamp, c);
        }
        if clique.len() == size && candidates.is_empty() {
            clique.sort_unstable();
            if seen.insert(clique.clone()) {
                found.push(clique);
            }
        }
    }
    (found, steps)
}

/// Keeps the candidates adjacent to `x` (one `edge_visit` per neighbour of `x` marked).
fn restrict<A: Adjacency, C: Counter>(
    g: &A,
    candidates: &mut Vec<u32>,
    x: usize,
    mark: &mut [u32],
    stamp: &mut u32,
    c: &mut C,
) {
    fresh(stamp, mark);
    for &y in g.neighbours(x) {
        c.edge_visit();
        mark[y as usize] = *stamp;
    }
    candidates.retain(|&y| mark[y as usize] == *stamp);
}

/// A stamp no entry of `mark` holds yet (clearing the marks when the stamps wrap).
fn fresh(stamp: &mut u32, mark: &mut [u32]) {
    if *stamp == u32::MAX {
        mark.iter_mut().for_each(|m| *m = 0);
        *stamp = 0;
    }
    *stamp += 1;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::gen::{graph, GraphKind};
    use crate::graph::Graph;

    fn generated(kind: GraphKind, n: usize, m: usize, seed: u64) -> Graph {
        Graph::from_edge_list(&graph(kind, n, m, seed).unwrap()).unwrap()
    }

    fn is_clique(g: &Graph, q: &[u32]) -> bool {
        q.iter().enumerate().all(|(i, &u)| {
            q[i + 1..]
                .iter()
                .all(|&v| g.has_edge(u as usize, v as usize))
        })
    }

    /// The clique number by brute force over vertex subsets (small graphs only).
    fn clique_number(g: &Graph) -> usize {
        let n = g.vertex_count();
        (0u32..1 << n)
            .filter(|&set| {
                let q: Vec<u32> = (0..n as u32).filter(|&v| set >> v & 1 == 1).collect();
                is_clique(g, &q)
            })
            .map(|set| set.count_ones() as usize)
            .max()
            .unwrap_or(0)
    }

    #[test]
    fn the_bound_is_a_clique_size_at_most_the_clique_number() {
        for seed in 0..60u64 {
            let n = 1 + seed as usize % 14;
            let m = (n * n.saturating_sub(1) / 2) * (seed as usize % 5) / 4;
            let g = generated(GraphKind::Gnm, n, m, seed);
            let (bound, _) = clique_lower_bound(&g, &mut NoCount);
            let omega = clique_number(&g);
            assert!(
                1 <= bound && bound <= omega,
                "seed {seed}: {bound} vs ω {omega}"
            );
            for size in 1..=omega {
                let (cliques, _) = cliques_of_size(&g, size, &mut NoCount);
                for q in &cliques {
                    assert_eq!(q.len(), size, "seed {seed}");
                    assert!(is_clique(&g, q), "seed {seed}: {q:?}");
                }
            }
        }
        let (empty, _) = clique_lower_bound(&Graph::from_edges(0, &[]).unwrap(), &mut NoCount);
        assert_eq!(empty, 0);
    }

    #[test]
    fn complete_graphs_and_queen_boards_give_their_clique_number() {
        for n in 1..12 {
            let g = generated(GraphKind::Complete, n, 0, 0);
            assert_eq!(clique_lower_bound(&g, &mut NoCount).0, n);
            assert_eq!(cliques_of_size(&g, n, &mut NoCount).0.len(), 1);
        }
        for side in [6, 7, 10, 11, 12, 13] {
            let g = generated(GraphKind::Queen, side, 0, 0);
            assert_eq!(clique_lower_bound(&g, &mut NoCount).0, side, "{side}");
            let (cliques, _) = cliques_of_size(&g, side, &mut NoCount);
            assert!(!cliques.is_empty(), "{side}");
            for q in &cliques {
                assert!(is_clique(&g, q), "{side}");
            }
        }
    }
}
