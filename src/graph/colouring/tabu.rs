//! Tabu search for a colouring with fewer colours (TabuCol), and DSatur followed by it.
//!
//! The greedy colourings of the course ([RD, §2.1] "Algoritmo voraz
//! aplicado a la coloración") stop at the first proper colouring their order gives. Local
//! search goes on from there: to try k − 1 colours, give the vertices of the last colour the
//! colour their neighbours use least, then move one conflicting vertex at a time to another
//! colour, always the move that leaves the fewest conflicting edges. A move's reverse is
//! forbidden ("tabu") for a while so the search does not cycle, unless it would reach fewer
//! conflicts than ever before. When no edge conflicts, k − 1 colours suffice and the search
//! tries k − 2. This is TabuCol (Hertz and de Werra, 1987) with the tabu tenure of Galinier
//! and Hao (1999): a random 0–9 plus 0.6 times the number of conflicting vertices.
//!
//! Two colours are decided exactly, by a breadth-first 2-colouring, instead of searched. For
//! t ≥ 3 colours only the t-core is searched: a vertex with fewer than t neighbours always
//! finds a free colour, so such vertices are set aside one by one (with their edges) and
//! coloured greedily afterwards, in the reverse order. The core's tables then take O(m) space.
//!
//! The search has a budget of elementary steps (moves evaluated, neighbours updated, and one
//! pass over the graph, n + 2m, to set up each target) and stops when it is spent, keeping
//! the best proper colouring found; it never returns more colours than it was given. Its
//! random choices (where each scan for the best move starts, tenures) come from a fixed
//! seed, so a graph always gets the same colouring.

use super::{check_colouring, dsatur_with, Colouring};
use crate::complexity::{on, Bound, Declaration};
use crate::count::{Counter, NoCount, Operation};
use crate::error::{Error, Result};
use crate::gen::Rng;
use crate::graph::Graph;
use std::collections::VecDeque;

/// This algorithm's [`Declaration`]: its name, bounds, counts, source and measured claims.
pub(super) const DECLARATION: Declaration = Declaration {
    problem: "colour",
    name: "dsatur-tabu",
    function: "graph::dsatur_tabu",
    file: "src/graph/colouring/tabu.rs",
    summary: "DSatur, then a tabu search for fewer colours",
    time: "O((n + m) log n)",
    space: "O(n + m)",
    operation: Some(Operation::Comparisons),
    counts: "DSatur's heap comparisons plus at most 20(n + 2m) search steps",
    source: "[RD, §2.1]",
    claims: &[on("gnm-4n", Bound::MLogN, Operation::Comparisons)],
};

/// The default search budget of [`dsatur_tabu`], in elementary steps per vertex and per
/// edge end: 20·(n + 2m) steps for n vertices and m edges.
///
/// With this budget DSatur and the search together stay faster than petgraph's
/// `dsatur_coloring` at every size `benches/graph.rs` measures (G(n, 10n), n from 2^10 to
/// 2^18, 2 cores): about 0.8 of its time at n = 2^10 and about 0.2 of it from 2^16 on. A
/// larger budget, through [`tabu_recolour`], finds fewer colours on more graphs.
pub const TABU_EFFORT: u64 = 20;

/// The seed of the search's random choices.
const TABU_SEED: u64 = 0x07AB_0C01;

/// DSatur, then [`tabu_recolour`] with a budget of [`TABU_EFFORT`]·(n + 2m) steps; see
/// [`dsatur_tabu_with`].
///
/// # Complexity
/// O((n + m) log n) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::gen::{graph, GraphKind};
/// use compgeo::graph::{dsatur, dsatur_tabu, check_colouring, Graph};
///
/// let g = Graph::from_edge_list(&graph(GraphKind::Gnm, 300, 1500, 7)?)?;
/// let (plain, improved) = (dsatur(&g), dsatur_tabu(&g));
/// assert_eq!(check_colouring(&g, &improved.colour), Ok(()));
/// assert!(improved.count < plain.count);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur_tabu(g: &Graph) -> Colouring {
    dsatur_tabu_with(g, &mut NoCount)
}

/// DSatur followed by a tabu search for fewer colours, counting the work of both.
///
/// [`dsatur_with`] gives a proper colouring with k colours; [`tabu_recolour_with`] then looks
/// for one with k − 1, k − 2, … colours until its budget of [`TABU_EFFORT`]·(n + 2m) steps
/// is spent. The result never has more colours than DSatur's. On random G(n, m) graphs of up
/// to a thousand vertices it had fewer on more than half of those tried; on graphs of 10⁵
/// vertices and more the budget seldom suffices to remove a colour.
///
/// # Complexity
/// O((n + m) log n) time: DSatur's, plus at most 20·(n + 2m) search steps. Auxiliary space
/// O(n + m): DSatur's, and a count and a tabu mark per colour for each vertex of the core.
///
/// # Counts
/// DSatur's counts, plus one `comparison` per move the search evaluates and one `edge_visit`
/// per neighbour it updates.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{dsatur_tabu_with, Graph};
///
/// // The 5-cycle needs 3 colours; DSatur finds them and the search cannot do better.
/// let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 0]])?;
/// let mut c = Counts::default();
/// assert_eq!(dsatur_tabu_with(&g, &mut c).count, 3);
/// assert!(c.edge_visits >= 10);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn dsatur_tabu_with<C: Counter>(g: &Graph, c: &mut C) -> Colouring {
    let start = dsatur_with(g, c);
    let budget = TABU_EFFORT.saturating_mul(steps(g));
    search(g, start, budget, c)
}

/// A colouring of `g` with as few colours as a tabu search finds within `budget` steps,
/// starting from the proper colouring `start`; see [`tabu_recolour_with`].
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"colouring"`) if `start` is not a proper colouring of
/// `g` with colours `0..start.count`, or has more colours than `g` has vertices.
///
/// # Complexity
/// O(n + m + budget) time, O(n + m) auxiliary space.
///
/// ```
/// use compgeo::graph::{greedy_colouring, tabu_recolour, Graph};
///
/// // The 6-cycle in the order 0, 3, 1, 4, 2, 5: greedy needs 3 colours, 2 suffice.
/// let g = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0]])?;
/// let greedy = greedy_colouring(&g, &[0, 3, 1, 4, 2, 5])?;
/// assert_eq!(greedy.count, 3);
/// assert_eq!(tabu_recolour(&g, &greedy, 1000)?.count, 2);
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn tabu_recolour(g: &Graph, start: &Colouring, budget: u64) -> Result<Colouring> {
    tabu_recolour_with(g, start, budget, &mut NoCount)
}

/// Tabu search (TabuCol) for a proper colouring of `g` with fewer colours than `start`,
/// counting its work.
///
/// The colours of `start` are first renumbered to `0..count` in order of first use, dropping
/// unused ones. From k colours the search tries k − 1 on the (k − 1)-core (see the module
/// notes): the vertices of the last colour take the colour least used among their
/// neighbours, and then, while some edge joins two vertices of one colour, the search makes
/// the best move of a conflicting vertex to another colour that is not tabu (among equal
/// moves, the first found by a scan of the conflicting vertices that starts at a random one:
/// cheaper than drawing among all ties). After moving v away from colour a, putting v back
/// into a stays tabu for a random 0–9 plus ⌊0.6·(conflicting vertices)⌋ iterations, unless
/// that would give fewer conflicts than ever before. Two colours are tried exactly, with a
/// breadth-first 2-colouring. Setting up a target costs n + 2m steps of the budget. The
/// search stops when a target cannot be set up or fails within the budget, and returns the
/// best proper colouring it reached.
///
/// # Errors
/// [`Error::InvalidParameter`] (name `"colouring"`) if `start` is not a proper colouring of
/// `g` with colours `0..start.count`, or has more colours than `g` has vertices.
///
/// # Complexity
/// O(n + m + budget) time, O(n + m) auxiliary space: each target spends n + 2m steps of the
/// budget on its set-up, and each iteration the moves it evaluates and the neighbours it
/// updates. The tables have one entry per colour for each vertex of the core, whose
/// vertices all have at least that many neighbours.
///
/// # Counts
/// One `comparison` per move evaluated, one `edge_visit` per neighbour updated or looked at.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::graph::{colour, tabu_recolour_with, ColouringAlgorithm, Graph};
///
/// let g = Graph::from_edges(4, &[[0, 1], [2, 3]])?;
/// let natural = colour(&g, ColouringAlgorithm::Greedy);
/// let mut c = Counts::default();
/// let better = tabu_recolour_with(&g, &natural, 100, &mut c)?;
/// assert_eq!((natural.count, better.count), (2, 2));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn tabu_recolour_with<C: Counter>(
    g: &Graph,
    start: &Colouring,
    budget: u64,
    c: &mut C,
) -> Result<Colouring> {
    let n = g.vertex_count();
    let largest = start.colour.iter().max().copied();
    if start.count > n || largest.map_or(0, |k| k.saturating_add(1)) != start.count {
        return Err(Error::InvalidParameter {
            name: "colouring",
            reason: format!(
                "{} colours for a graph of {n} vertices, the largest colour being {}; \
                 expected colours 0..count with count at most the number of vertices",
                start.count,
                largest.map_or("none".to_string(), |k| k.to_string()),
            ),
        });
    }
    if check_colouring(g, &start.colour).is_err() {
        return Err(Error::InvalidParameter {
            name: "colouring",
            reason: format!(
                "not a proper colouring of the graph: {} colours for {n} vertices, or an edge \
                 whose ends share a colour",
                start.colour.len()
            ),
        });
    }
    let compact: Vec<u32> = start.colour.iter().map(|&k| k as u32).collect();
    Ok(search(g, renumbered(&compact), budget, c))
}

/// The number of elementary steps one pass over `g` takes: n + 2m.
fn steps(g: &Graph) -> u64 {
    (g.vertex_count() as u64).saturating_add(2 * g.edge_count() as u64)
}

/// Lowers the colour count of the compact proper colouring `best` as far as `budget` allows.
fn search<C: Counter>(g: &Graph, mut best: Colouring, budget: u64, c: &mut C) -> Colouring {
    let mut left = budget;
    let mut rng = Rng::new(TABU_SEED);
    while best.count > 1 && left >= steps(g) {
        left -= steps(g);
        let target = best.count - 1;
        let found = if g.edge_count() == 0 {
            Some(vec![0; g.vertex_count()])
        } else if target == 1 {
            None
        } else if target == 2 {
            two_colouring(g, c)
        } else {
            let colour: Vec<u32> = best.colour.iter().map(|&k| k as u32).collect();
            recolour_with_core(g, colour, target, &mut left, &mut rng, c)
        };
        match found {
            // Compact colours, so that the next target drops exactly one class.
            Some(better) => best = renumbered(&better),
            None => break,
        }
    }
    debug_assert_eq!(check_colouring(g, &best.colour), Ok(()));
    best
}

/// The colouring with the colours of `colour` renumbered to `0..count` in order of first use.
fn renumbered(colour: &[u32]) -> Colouring {
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

/// A proper colouring of `g` with `target` colours, from the proper `colour` with
/// `target + 1`: the tabu search colours the `target`-core, then the vertices set aside take
/// free colours in the reverse order. `None` if the budget runs out first.
fn recolour_with_core<C: Counter>(
    g: &Graph,
    mut colour: Vec<u32>,
    target: usize,
    left: &mut u64,
    rng: &mut Rng,
    c: &mut C,
) -> Option<Vec<u32>> {
    let set_aside = peel_below(g, target, c);
    let core: Vec<u32> = (0..g.vertex_count() as u32)
        .filter(|&v| set_aside.position[v as usize] == NOT_SET_ASIDE)
        .collect();
    if !core.is_empty() {
        let state = TabuCol::new(g, &colour, &core, target, c);
        for (&v, &k) in core.iter().zip(&state.run(g, left, rng, c)?) {
            colour[v as usize] = k;
        }
    }
    // Each vertex set aside had fewer than `target` neighbours among the core and the
    // vertices set aside after it, which are exactly those coloured before it here.
    let mut seen_at = vec![usize::MAX; target];
    let mut coloured = vec![false; g.vertex_count()];
    for &v in &core {
        coloured[v as usize] = true;
    }
    for (i, &v) in set_aside.order.iter().enumerate().rev() {
        let v = v as usize;
        for &u in g.adjacent(v) {
            c.edge_visit();
            if coloured[u as usize] {
                seen_at[colour[u as usize] as usize] = i;
            }
        }
        let free = (0..target).find(|&k| seen_at[k] != i);
        colour[v] = free.expect("fewer neighbours than colours") as u32;
        coloured[v] = true;
    }
    Some(colour)
}

/// The vertices outside the `t`-core of a graph, in the order they were set aside.
struct SetAside {
    /// The vertices, each with fewer than `t` neighbours among the vertices not yet set
    /// aside when it was.
    order: Vec<u32>,
    /// Each vertex's position in `order`, or `NOT_SET_ASIDE` for the core.
    position: Vec<u32>,
}

/// The position of a core vertex in [`SetAside::position`].
const NOT_SET_ASIDE: u32 = u32::MAX;

/// Sets aside, one by one, vertices with fewer than `t` neighbours left, in O(n + m).
fn peel_below<C: Counter>(g: &Graph, t: usize, c: &mut C) -> SetAside {
    let n = g.vertex_count();
    let mut degree: Vec<usize> = (0..n).map(|v| g.degree(v)).collect();
    let mut position = vec![NOT_SET_ASIDE; n];
    let mut order: Vec<u32> = Vec::new();
    for v in 0..n {
        if degree[v] < t {
            position[v] = order.len() as u32;
            order.push(v as u32);
        }
    }
    let mut next = 0;
    while next < order.len() {
        let v = order[next] as usize;
        next += 1;
        for &u in g.adjacent(v) {
            c.edge_visit();
            let u = u as usize;
            degree[u] -= 1;
            if degree[u] + 1 == t && position[u] == NOT_SET_ASIDE {
                position[u] = order.len() as u32;
                order.push(u as u32);
            }
        }
    }
    SetAside { order, position }
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

/// The state of one search for a colouring with `k` colours.
struct TabuCol {
    k: usize,
    /// The core's vertices: local id → vertex of the graph.
    vertex: Vec<u32>,
    /// Vertex of the graph → local id, or `NOT_IN_CORE`.
    local: Vec<u32>,
    /// The colour of each core vertex (by local id), in `0..k`.
    colour: Vec<u32>,
    /// `neighbours_in[v * k + a]`: how many core neighbours of v have colour a.
    neighbours_in: Vec<u32>,
    /// `tabu_until[v * k + a]`: the first iteration at which v may move back into a.
    tabu_until: Vec<u32>,
    /// The local ids of the vertices with a neighbour of their own colour, in any order.
    conflicting: Vec<u32>,
    /// The position of each local id in `conflicting`, or `NOT_CONFLICTING`.
    position: Vec<u32>,
    /// The number of core edges whose ends share a colour.
    conflicts: u64,
}

/// The position of a vertex that is not in the conflicting list.
const NOT_CONFLICTING: u32 = u32::MAX;

/// The local id of a vertex outside the core.
const NOT_IN_CORE: u32 = u32::MAX;

impl TabuCol {
    /// The start for `k` colours on the subgraph induced by `core`, from a proper colouring
    /// `colour` of the graph with `k + 1`: the core vertices of colour `k`, in vertex order,
    /// take the colour least used among their core neighbours.
    fn new<C: Counter>(g: &Graph, colour: &[u32], core: &[u32], k: usize, c: &mut C) -> Self {
        let mut local = vec![NOT_IN_CORE; g.vertex_count()];
        for (i, &v) in core.iter().enumerate() {
            local[v as usize] = i as u32;
        }
        let size = core.len();
        let mut own: Vec<u32> = core.iter().map(|&v| colour[v as usize]).collect();
        let mut neighbours_in = vec![0u32; size * k];
        let count_in = |v: u32, a: usize, c: &mut C, table: &mut [u32]| {
            for &u in g.adjacent(v as usize) {
                c.edge_visit();
                let u = local[u as usize];
                if u != NOT_IN_CORE {
                    table[u as usize * k + a] += 1;
                }
            }
        };
        for (&v, &a) in core.iter().zip(&own) {
            if (a as usize) < k {
                count_in(v, a as usize, c, &mut neighbours_in);
            }
        }
        for i in 0..size {
            if own[i] as usize >= k {
                let row = &neighbours_in[i * k..(i + 1) * k];
                let a = (0..k).min_by_key(|&a| row[a]).unwrap_or(0);
                own[i] = a as u32;
                count_in(core[i], a, c, &mut neighbours_in);
            }
        }
        let mut state = TabuCol {
            k,
            vertex: core.to_vec(),
            local,
            colour: own,
            neighbours_in,
            tabu_until: vec![0; size * k],
            conflicting: Vec::new(),
            position: vec![NOT_CONFLICTING; size],
            conflicts: 0,
        };
        for v in 0..size {
            let own = state.own_count(v);
            state.conflicts += u64::from(own);
            state.update_membership(v);
        }
        state.conflicts /= 2;
        state
    }

    /// How many neighbours of `v` share its colour.
    fn own_count(&self, v: usize) -> u32 {
        self.neighbours_in[v * self.k + self.colour[v] as usize]
    }

    /// Puts `v` in the conflicting list or takes it out, as its colour now requires.
    fn update_membership(&mut self, v: usize) {
        let conflicting = self.own_count(v) > 0;
        let listed = self.position[v] != NOT_CONFLICTING;
        if conflicting && !listed {
            self.position[v] = self.conflicting.len() as u32;
            self.conflicting.push(v as u32);
        } else if !conflicting && listed {
            let at = self.position[v] as usize;
            let last = *self.conflicting.last().expect("v is listed") as usize;
            self.conflicting.swap_remove(at);
            self.position[last] = at as u32;
            self.position[v] = NOT_CONFLICTING;
        }
    }

    /// The best move of a conflicting vertex v to another colour a that is not tabu at
    /// `iteration` or changes the conflict count by less than `aspire_below`: (v, a, change).
    /// Of equal moves, the first found scanning the conflicting vertices from a random one.
    fn best_move(
        &self,
        iteration: u32,
        aspire_below: i64,
        rng: &mut Rng,
    ) -> Option<(usize, usize, i64)> {
        let k = self.k;
        let mut best = None;
        let mut best_change = i64::MAX;
        let len = self.conflicting.len();
        let shift = rng.index(len);
        let (tail, head) = self.conflicting.split_at(shift);
        for &v in head.iter().chain(tail) {
            let v = v as usize;
            let here = self.colour[v] as usize;
            let row = &self.neighbours_in[v * k..(v + 1) * k];
            let tabu = &self.tabu_until[v * k..(v + 1) * k];
            let stay = i64::from(row[here]);
            for (a, (&count, &until)) in row.iter().zip(tabu).enumerate() {
                let change = i64::from(count) - stay;
                if change >= best_change
                    || a == here
                    || (until > iteration && change >= aspire_below)
                {
                    continue;
                }
                best_change = change;
                best = Some((v, a, change));
            }
        }
        best
    }

    /// Searches until no edge conflicts (the core's colours, by local id) or the budget runs
    /// out (`None`).
    fn run<C: Counter>(
        mut self,
        g: &Graph,
        left: &mut u64,
        rng: &mut Rng,
        c: &mut C,
    ) -> Option<Vec<u32>> {
        let k = self.k;
        let mut fewest = self.conflicts;
        let mut iteration: u32 = 0;
        while self.conflicts > 0 {
            let evaluations = (self.conflicting.len() * (k - 1)) as u64;
            if *left < evaluations || iteration == u32::MAX - 1 {
                *left = 0;
                return None;
            }
            *left -= evaluations;
            iteration += 1;
            for _ in 0..evaluations {
                c.comparison();
            }
            let aspire_below = fewest as i64 - self.conflicts as i64;
            let best = self.best_move(iteration, aspire_below, rng);
            let Some((v, a, change)) = best else { continue };
            let from = self.colour[v] as usize;
            let tenure = rng.below(10) as u32 + (self.conflicting.len() * 3 / 5) as u32;
            self.tabu_until[v * k + from] = iteration.saturating_add(tenure).saturating_add(1);
            self.colour[v] = a as u32;
            self.conflicts = (self.conflicts as i64 + change) as u64;
            fewest = fewest.min(self.conflicts);
            let neighbours = g.adjacent(self.vertex[v] as usize);
            *left = left.saturating_sub(neighbours.len() as u64);
            for &u in neighbours {
                c.edge_visit();
                let u = self.local[u as usize];
                if u == NOT_IN_CORE {
                    continue;
                }
                let u = u as usize;
                self.neighbours_in[u * k + from] -= 1;
                self.neighbours_in[u * k + a] += 1;
                self.update_membership(u);
            }
            self.update_membership(v);
        }
        Some(self.colour)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn the_start_state_counts_conflicts_of_the_reassigned_class() {
        // A triangle coloured 0, 1, 2 squeezed into 2 colours: exactly one conflicting edge.
        let g = Graph::from_edges(3, &[[0, 1], [1, 2], [2, 0]]).unwrap();
        let state = TabuCol::new(&g, &[0, 1, 2], &[0, 1, 2], 2, &mut NoCount);
        assert_eq!(state.conflicts, 1);
        assert_eq!(state.conflicting.len(), 2);
    }

    #[test]
    fn peeling_leaves_a_core_of_degree_at_least_t() {
        // A triangle with a path hanging off it and a pendant vertex on the path.
        let g = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 0], [2, 3], [3, 4], [3, 5]]).unwrap();
        let aside = peel_below(&g, 2, &mut NoCount);
        let core: Vec<usize> = (0..6)
            .filter(|&v| aside.position[v] == NOT_SET_ASIDE)
            .collect();
        assert_eq!(core, vec![0, 1, 2]);
        for (i, &v) in aside.order.iter().enumerate() {
            assert_eq!(aside.position[v as usize] as usize, i);
            // Fewer than t neighbours among the core and the vertices set aside later.
            let later = g
                .neighbours(v as usize)
                .filter(|&u| aside.position[u] == NOT_SET_ASIDE || aside.position[u] as usize > i)
                .count();
            assert!(later < 2, "vertex {v}");
        }
        assert_eq!(peel_below(&g, 3, &mut NoCount).order.len(), 6);
    }

    #[test]
    fn the_budget_pays_for_each_target() {
        let g = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0]]).unwrap();
        let three = Colouring {
            colour: vec![0, 1, 0, 1, 0, 2],
            count: 3,
        };
        // Two colours are decided by breadth-first search, once its pass is paid for.
        assert_eq!(tabu_recolour(&g, &three, 0).unwrap(), three);
        assert_eq!(tabu_recolour(&g, &three, steps(&g)).unwrap().count, 2);
        // The triangular prism (3-regular, so its own 3-core) needs 3 colours, but the fourth
        // colour's vertex sees each of the other three once, so removing it needs moves.
        let g = Graph::from_edges(
            6,
            &[
                [0, 1],
                [1, 2],
                [2, 0],
                [3, 4],
                [4, 5],
                [5, 3],
                [0, 3],
                [1, 4],
                [2, 5],
            ],
        )
        .unwrap();
        let four = Colouring {
            colour: vec![0, 1, 2, 3, 2, 1],
            count: 4,
        };
        assert_eq!(check_colouring(&g, &four.colour), Ok(()));
        assert_eq!(tabu_recolour(&g, &four, 0).unwrap(), four);
        assert_eq!(tabu_recolour(&g, &four, steps(&g)).unwrap(), four);
        assert_eq!(tabu_recolour(&g, &four, 10_000).unwrap().count, 3);
    }
}
