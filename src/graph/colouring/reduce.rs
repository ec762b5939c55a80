//! What the colouring searches ([`dsatur_tabu_budget`](super::dsatur_tabu_budget) and
//! [`hea_budget`](super::hea_budget)) share: the descent from k to k − 1 colours, the exact
//! 2-colouring, and the reduction to the t-core.
//!
//! The descent starts from a proper colouring with k colours and asks a search for k − 1,
//! then k − 2, …, keeping the last proper colouring found; it stops when a search fails
//! (its budget is spent) or one colour is left. Each target first pays one pass over the
//! graph (n + 2m steps). Two colours are decided exactly, by a breadth-first 2-colouring,
//! instead of searched. For t ≥ 3 colours only the t-core is searched: a vertex with fewer
//! than t neighbours always finds a free colour, so such vertices are set aside one by one
//! (with their edges) and coloured greedily afterwards, in the reverse order. Every vertex
//! of the core has at least t core neighbours, so a table of t entries per core vertex
//! takes at most 2m entries: the searches' tables are O(m) whatever t is.
//!
//! Before a search for t colours, the exact search of [`transversal`](super::transversal)
//! may spend at most half of what is left of the budget (it looks first among the colourings
//! a symmetry of the core preserves, [`symmetry`](super::symmetry)). When the core splits
//! into cliques of t vertices it finds a t-colouring, or proves that none exists, or at
//! least proves that t colours are needed. A t-colouring found after such a proof (by the exact search
//! or by the search after it) is optimal, and so is the last colouring when no t-colouring
//! exists: in those cases the descent stops there.

use super::budget::{pass, Meter};
use super::transversal::{colour_by_transversals, Outcome};
use super::Colouring;
use crate::count::Counter;
use crate::gen::Rng;
use crate::graph::Graph;
use std::collections::VecDeque;

/// The subgraph a search for `colours` colours works on: the `colours`-core of a graph,
/// renumbered `0..len`, and the vertices set aside to reach it.
#[derive(Debug)]
pub(super) struct Core {
    /// The number of colours the core is searched with (its t).
    pub(super) colours: usize,
    /// Local id → vertex of the graph.
    pub(super) vertex: Vec<u32>,
    /// The core's adjacency in local ids: `adjacency[offsets[v]..offsets[v + 1]]`.
    offsets: Vec<usize>,
    adjacency: Vec<u32>,
    /// The vertices set aside, in the order they were: each had fewer than `colours`
    /// neighbours among the core and the vertices set aside after it.
    set_aside: Vec<u32>,
}

impl Core {
    /// The `t`-core of `g` with local ids, in O(n + m) (one `edge_visit` per edge end looked
    /// at while peeling and while copying the core's edges).
    pub(super) fn new<C: Counter>(g: &Graph, t: usize, c: &mut C) -> Self {
        let n = g.vertex_count();
        let mut degree: Vec<usize> = (0..n).map(|v| g.degree(v)).collect();
        let mut in_core = vec![true; n];
        let mut set_aside: Vec<u32> = Vec::new();
        for v in 0..n {
            if degree[v] < t {
                in_core[v] = false;
                set_aside.push(v as u32);
            }
        }
        let mut next = 0;
        while next < set_aside.len() {
            let v = set_aside[next] as usize;
            next += 1;
            for &u in g.adjacent(v) {
                c.edge_visit();
                let u = u as usize;
                degree[u] -= 1;
                if degree[u] + 1 == t && in_core[u] {
                    in_core[u] = false;
                    set_aside.push(u as u32);
                }
            }
        }
        let vertex: Vec<u32> = (0..n as u32).filter(|&v| in_core[v as usize]).collect();
        let mut local = vec![u32::MAX; n];
        for (i, &v) in vertex.iter().enumerate() {
            local[v as usize] = i as u32;
        }
        let mut offsets = Vec::with_capacity(vertex.len() + 1);
        offsets.push(0);
        let mut adjacency = Vec::new();
        for &v in &vertex {
            for &u in g.adjacent(v as usize) {
                c.edge_visit();
                if in_core[u as usize] {
                    adjacency.push(local[u as usize]);
                }
            }
            offsets.push(adjacency.len());
        }
        Core {
            colours: t,
            vertex,
            offsets,
            adjacency,
            set_aside,
        }
    }

    /// The number of core vertices.
    pub(super) fn len(&self) -> usize {
        self.vertex.len()
    }

    /// The core neighbours of local vertex `v`, as local ids.
    pub(super) fn neighbours(&self, v: usize) -> &[u32] {
        &self.adjacency[self.offsets[v]..self.offsets[v + 1]]
    }

    /// Twice the number of core edges.
    pub(super) fn edge_ends(&self) -> u64 {
        self.adjacency.len() as u64
    }

    /// A start for the search from a proper colouring `colour` of the whole graph with
    /// `colours + 1` colours, by local id: the core vertices of the extra colour, in vertex
    /// order, take the colour least used among their core neighbours (the first of equals).
    pub(super) fn start_from<C: Counter>(&self, colour: &[u32], c: &mut C) -> Vec<u32> {
        let t = self.colours;
        let mut own: Vec<u32> = self.vertex.iter().map(|&v| colour[v as usize]).collect();
        let mut used = vec![0u32; t];
        for v in 0..self.len() {
            if (own[v] as usize) < t {
                continue;
            }
            used.iter_mut().for_each(|u| *u = 0);
            for &u in self.neighbours(v) {
                c.edge_visit();
                if let Some(slot) = used.get_mut(own[u as usize] as usize) {
                    *slot += 1;
                }
            }
            let least = (0..t).min_by_key(|&a| used[a]).unwrap_or(0);
            own[v] = least as u32;
        }
        own
    }

    /// The colouring of `g` from a proper colouring of the core with `colours` colours (by
    /// local id): the vertices set aside take, in the reverse order, the first colour none
    /// of their coloured neighbours has.
    fn extend<C: Counter>(&self, g: &Graph, core_colour: &[u32], c: &mut C) -> Vec<u32> {
        const NONE: u32 = u32::MAX;
        let mut colour = vec![NONE; g.vertex_count()];
        for (&v, &k) in self.vertex.iter().zip(core_colour) {
            colour[v as usize] = k;
        }
        // Each vertex set aside had fewer than `colours` neighbours among the core and the
        // vertices set aside after it, which are exactly those coloured before it here.
        let mut seen_at = vec![usize::MAX; self.colours];
        for (i, &v) in self.set_aside.iter().enumerate().rev() {
            let v = v as usize;
            for &u in g.adjacent(v) {
                c.edge_visit();
                let k = colour[u as usize];
                if k != NONE {
                    seen_at[k as usize] = i;
                }
            }
            let free = (0..self.colours).find(|&k| seen_at[k] != i);
            colour[v] = free.expect("fewer neighbours than colours") as u32;
        }
        colour
    }
}

/// Lowers the colour count of the compact proper colouring `start` as far as the budget
/// allows: for each target t it pays a pass over `g`, then asks `solve` for a proper
/// colouring of the t-core with t colours (`None`: the budget ran out first). `solve`
/// receives the core, the best colouring so far (t + 1 colours, of the whole graph), the
/// meter, the random source and the counter.
pub(super) fn descend<C, S>(
    g: &Graph,
    start: Colouring,
    meter: &mut Meter,
    rng: &mut Rng,
    c: &mut C,
    mut solve: S,
) -> Colouring
where
    C: Counter,
    S: FnMut(&Core, &[u32], &mut Meter, &mut Rng, &mut C) -> Option<Vec<u32>>,
{
    let mut best = start;
    // Whether `best` is known to be optimal, so that the descent stops.
    let mut optimal = false;
    while !optimal && best.count > 1 && meter.spend(pass(g)) {
        let target = best.count - 1;
        let found = if g.edge_count() == 0 {
            Some(vec![0; g.vertex_count()])
        } else if target == 1 {
            None
        } else if target == 2 {
            two_colouring(g, c)
        } else {
            let colour: Vec<u32> = best.colour.iter().map(|&k| k as u32).collect();
            let core = Core::new(g, target, c);
            let core_colour = if core.len() == 0 {
                Some(Vec::new())
            } else {
                // The exact search first, with at most half of what is left.
                let mut share = meter.half();
                let outcome = colour_by_transversals(&core, &mut share, rng);
                meter.charge(share.report().steps);
                match outcome {
                    Outcome::Found(colour) => {
                        optimal = true;
                        Some(colour)
                    }
                    Outcome::Impossible => {
                        optimal = true;
                        None
                    }
                    Outcome::AtLeast => {
                        let found = solve(&core, &colour, meter, rng, c);
                        optimal = found.is_some();
                        found
                    }
                    Outcome::NotTried => solve(&core, &colour, meter, rng, c),
                }
            };
            core_colour.map(|k| core.extend(g, &k, c))
        };
        match found {
            // Compact colours, so that the next target drops exactly one class.
            Some(better) => {
                best = renumbered(&better);
                meter.found_best();
            }
            None => break,
        }
    }
    debug_assert_eq!(super::check_colouring(g, &best.colour), Ok(()));
    best
}

/// The colouring with the colours of `colour` renumbered to `0..count` in order of first use.
pub(super) fn renumbered(colour: &[u32]) -> Colouring {
    let mut new_name: Vec<usize> = Vec::new();
    let mut count = 0;
    let colour = colour
        .iter()
        .map(|&k| {
            let k = k as usize;
            if new_name.len() <= k {
                new_name.resize(k + 1, usize::MAX);
            }
            if new_name[k] == usize::MAX {
                new_name[k] = count;
                count += 1;
            }
            new_name[k]
        })
        .collect();
    Colouring { colour, count }
}

/// A proper 2-colouring of `g` by breadth-first search, or `None` if `g` has an odd cycle.
fn two_colouring<C: Counter>(g: &Graph, c: &mut C) -> Option<Vec<u32>> {
    const UNSEEN: u32 = u32::MAX;
    let mut side = vec![UNSEEN; g.vertex_count()];
    let mut queue = VecDeque::new();
    for root in 0..g.vertex_count() {
        if side[root] != UNSEEN {
            continue;
        }
        side[root] = 0;
        queue.push_back(root);
        while let Some(v) = queue.pop_front() {
            for &u in g.adjacent(v) {
                c.edge_visit();
                let u = u as usize;
                if side[u] == UNSEEN {
                    side[u] = 1 - side[v];
                    queue.push_back(u);
                } else if side[u] == side[v] {
                    return None;
                }
            }
        }
    }
    Some(side)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::graph::check_colouring;

    #[test]
    fn renumbering_follows_first_use() {
        let c = renumbered(&[4, 1, 4, 0, 1]);
        assert_eq!(c.colour, vec![0, 1, 0, 2, 1]);
        assert_eq!(c.count, 3);
    }

    #[test]
    fn two_colouring_finds_bipartite_sides_and_rejects_odd_cycles() {
        let even = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3], [3, 0]]).unwrap();
        let sides = two_colouring(&even, &mut NoCount).unwrap();
        let sides: Vec<usize> = sides.into_iter().map(|s| s as usize).collect();
        assert_eq!(check_colouring(&even, &sides), Ok(()));
        let odd = Graph::from_edges(3, &[[0, 1], [1, 2], [2, 0]]).unwrap();
        assert!(two_colouring(&odd, &mut NoCount).is_none());
    }

    #[test]
    fn the_core_keeps_the_vertices_of_degree_at_least_t() {
        // A triangle with a path hanging off it and a pendant vertex on the path.
        let g = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 0], [2, 3], [3, 4], [3, 5]]).unwrap();
        let core = Core::new(&g, 2, &mut NoCount);
        assert_eq!(core.vertex, vec![0, 1, 2]);
        assert_eq!(core.edge_ends(), 6);
        for v in 0..core.len() {
            assert_eq!(core.neighbours(v).len(), 2);
        }
        for (i, &v) in core.set_aside.iter().enumerate() {
            // Fewer than t neighbours among the core and the vertices set aside later.
            let later = g
                .neighbours(v as usize)
                .filter(|&u| {
                    core.vertex.contains(&(u as u32))
                        || core.set_aside[i + 1..].contains(&(u as u32))
                })
                .count();
            assert!(later < 2, "vertex {v}");
        }
        assert_eq!(Core::new(&g, 3, &mut NoCount).len(), 0);
        // Colouring the core's triangle with 3 colours extends to the whole graph.
        let core = Core::new(&g, 3, &mut NoCount);
        assert_eq!(core.set_aside.len(), 6);
        let core = Core::new(&g, 2, &mut NoCount);
        let two = core.extend(&g, &[0, 1, 0], &mut NoCount);
        assert_eq!(&two[..3], &[0, 1, 0]);
        let three = Core {
            colours: 3,
            ..Core::new(&g, 2, &mut NoCount)
        };
        let full: Vec<usize> = three
            .extend(&g, &[0, 1, 2], &mut NoCount)
            .into_iter()
            .map(|k| k as usize)
            .collect();
        assert_eq!(check_colouring(&g, &full), Ok(()));
    }

    #[test]
    fn the_start_reassigns_the_extra_colour_to_the_least_used() {
        // The path 0-1-2-3 coloured 0, 1, 2, 0 squeezed into 2 colours: vertex 2 sees colours
        // 1 and 0 once each and takes the first, 0.
        let g = Graph::from_edges(4, &[[0, 1], [1, 2], [2, 3]]).unwrap();
        let core = Core {
            colours: 2,
            ..Core::new(&g, 0, &mut NoCount)
        };
        assert_eq!(
            core.start_from(&[0, 1, 2, 0], &mut NoCount),
            vec![0, 1, 0, 0]
        );
    }
}
