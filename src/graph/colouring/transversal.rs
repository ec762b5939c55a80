//! An exact search for a colouring with t colours when the vertices split into cliques of
//! t vertices: the colour classes are then independent transversals of those cliques.
//!
//! The problem: the descent of the colouring searches ([`reduce`](super::reduce)) asks for
//! a proper colouring of a core with t colours. Local search finds one or runs out of
//! budget; it can neither prove that none exists nor assemble rigid optima such as the queen
//! graphs', whose optimal classes are disjoint sets of non-attacking queens.
//!
//! The idea (the independent-set formulation of Vasquez, 2004, for the queen graphs, here
//! for any graph): if the core's vertices split into disjoint cliques B₁ … B_r of exactly t
//! vertices each, then every colour of a t-colouring appears exactly once in each Bᵢ, so
//! each colour class is an *independent transversal*: an independent set with one vertex of
//! every Bᵢ. A t-colouring is then the same as t pairwise disjoint independent transversals,
//! an exact cover of the vertices. The search
//!
//! 1. splits the vertices into t-cliques by backtracking (each time the first vertex not yet
//!    covered, with the t-cliques through it in increasing order), and gives up if the split
//!    takes too long: without it the search is not tried;
//! 2. covers the edges by cliques, each edge once, greedily and largest first (every
//!    uncovered edge is grown into a maximal clique of uncovered edges, and the largest
//!    grown cliques are kept first);
//! 3. lists every independent transversal, if there are not too many;
//! 4. looks first for a colouring that an automorphism π of the core maps to itself, for
//!    each of the automorphisms of [`symmetry`](super::symmetry) in turn (largest order
//!    first), with at most half of what is left of its budget each: π permutes the
//!    transversals, and the classes of such a colouring come in whole orbits, so the
//!    search of step 5 runs over the orbits whose members are pairwise disjoint (each
//!    counting as as many classes as it has members) instead of single transversals. A
//!    failure here proves nothing about colourings without that symmetry;
//! 5. chooses the classes one at a time: the uncovered vertex in the fewest remaining
//!    transversals decides the branch, one branch per transversal through it. Two filters
//!    prune (the clique filter of Vasquez): with `left` classes still to choose, a clique
//!    of the cover with more than `left` uncovered vertices cannot be finished, so the node
//!    fails; one with exactly `left` must be hit by every class still to choose, so
//!    transversals missing it are dropped (a union of k classes must hold exactly k of
//!    its uncovered vertices).
//!
//! The branches are tried in a random order or, on every other restart, hitting the cliques
//! with the most uncovered vertices first. The search restarts with node limits that follow
//! the Luby sequence (512, 512, 1024, 512, 512, 1024, 2048, …), so an unlucky early choice
//! costs a bounded number of nodes, and the limits grow without bound. A restart that ends
//! below its limit has searched the whole tree: then no t-colouring exists.
//!
//! Not in the course texts; an exact method beside the heuristic searches (Vasquez, *New
//! results on the Queens_n² graph coloring problem*, Journal of Heuristics 10, 2004: the
//! search over independent sets with the clique filter; Luby, Sinclair and Zuckerman, 1993:
//! the restart sequence).
//!
//! # Complexity
//!
//! With n core vertices, w = ⌈n/64⌉ words per vertex set, T transversals and c cliques in
//! the cover: O(n²w) for the adjacency matrix and the cover's growth per edge, O(w) per
//! node of the split and of the enumeration, and O((T + c)·w) per node of the search
//! (filtering, counting and ordering its transversals). The number of nodes is exponential
//! in the worst case; every step is paid from the [`Meter`], so the search stops when its
//! share of the budget does. Each automorphism of step 4 costs O(T·(r + w)) for its orbits
//! (r vertices per transversal, one hash look-up of w words per image), besides the cost of
//! finding the automorphisms ([`symmetry`](super::symmetry)). Space O(n²/64 + T·w) words; cores of more than
//! [`MAX_VERTICES`] vertices or with more than [`MAX_CANDIDATE_WORDS`] words of
//! transversals are not searched.

use super::budget::Meter;
use super::reduce::Core;
use super::symmetry::automorphisms;
use crate::gen::Rng;
use std::collections::HashMap;

/// What the exact search concluded about a t-colouring of a core.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Outcome {
    /// The core has no split into t-cliques that the search found in time, or is too large
    /// for it: nothing is known.
    NotTried,
    /// The core splits into t-cliques, so it needs at least t colours, but the search
    /// stopped (budget or limits) before it found a t-colouring or proved there is none.
    AtLeast,
    /// A proper t-colouring of the core, colours `0..t` by local vertex id; with the split
    /// into t-cliques it is optimal.
    Found(Vec<u32>),
    /// The core has no proper colouring with t colours.
    Impossible,
}

/// Cores with more vertices than this are not searched: the adjacency matrix takes n²/8
/// bytes (2 MiB here).
pub(super) const MAX_VERTICES: usize = 4096;

/// The most words of transversals kept (16 MiB); a core with more is not searched.
pub(super) const MAX_CANDIDATE_WORDS: usize = 1 << 21;

/// The node limit of a restart is this many nodes times the Luby sequence's term.
const RESTART_UNIT: u64 = 512;

/// Looks for a proper colouring of `core` with `core.colours` colours by the exact search
/// of the [module docs](self), paying every step from `meter`.
pub(super) fn colour_by_transversals(core: &Core, meter: &mut Meter, rng: &mut Rng) -> Outcome {
    let (n, t) = (core.len(), core.colours);
    if t < 3 || n == 0 || n % t != 0 || n > MAX_VERTICES || !may_lie_in_a_clique(core, meter) {
        return Outcome::NotTried;
    }
    let words = n.div_ceil(64);
    if !meter.spend((n * words) as u64 + core.edge_ends()) {
        return Outcome::NotTried;
    }
    let adjacency = Sets::adjacency(core, words);
    // The split may cost about one pass over the core: enough for a graph whose cliques it
    // finds at the first try, and little on one where it must give up.
    let split_nodes = ((n as u64 + core.edge_ends()) / words as u64).max(n as u64);
    let Some(blocks) = split_into_cliques(&adjacency, t, split_nodes, meter) else {
        return Outcome::NotTried;
    };
    let Some(cover) = clique_cover(&adjacency, meter) else {
        return Outcome::AtLeast;
    };
    let Some(transversals) = independent_transversals(&adjacency, &blocks, meter) else {
        return Outcome::AtLeast;
    };
    // Colourings that an automorphism maps to themselves first: far fewer candidates. All
    // of it takes at most half of the phase's share, so the plain search keeps the rest.
    let mut symmetric = meter.half();
    if let Some(colour) =
        colour_symmetrically(core, &adjacency, &transversals, &cover, &mut symmetric, rng)
    {
        meter.charge(symmetric.report().steps);
        return Outcome::Found(colour);
    }
    meter.charge(symmetric.report().steps);
    let rows = Rows::plain(&transversals, words);
    match Search::new(&rows, &cover, meter, rng).run(n, t) {
        Ok(Some(colour)) => Outcome::Found(colour),
        Ok(None) => Outcome::Impossible,
        Err(_) => Outcome::AtLeast,
    }
}

/// Step 4 of the [module docs](self): a t-colouring that one of the core's automorphisms
/// maps to itself, trying each automorphism of [`automorphisms`] with at most half of what
/// is left of `meter`; `None` if none turns up.
fn colour_symmetrically(
    core: &Core,
    adjacency: &Sets,
    transversals: &[u64],
    cover: &[Vec<u64>],
    meter: &mut Meter,
    rng: &mut Rng,
) -> Option<Vec<u32>> {
    let (n, t, words) = (core.len(), core.colours, adjacency.words);
    let count = transversals.len() / words;
    if count < t {
        // Not even t transversals: the plain search proves at once that none exists.
        return None;
    }
    let adjacent = |u: usize, v: usize| contains(adjacency.row(u), v);
    let choices = automorphisms(core, &adjacent, meter);
    if choices.is_empty() || !meter.spend(2 * transversals.len() as u64) {
        return None;
    }
    let index: HashMap<&[u64], u32> = transversals
        .chunks_exact(words)
        .enumerate()
        .map(|(i, set)| (set, i as u32))
        .collect();
    for image in choices {
        let rows = orbit_rows(transversals, &index, words, &image, t, meter)?;
        let mut share = meter.half();
        let found = Search::new(&rows, cover, &mut share, rng).run(n, t);
        meter.charge(share.report().steps);
        if let Ok(Some(colour)) = found {
            return Some(colour);
        }
    }
    None
}

/// The candidates of the search: unions of colour classes chosen together, one
/// transversal each or a whole orbit of transversals under an automorphism.
struct Rows<'t> {
    /// Words per vertex set.
    words: usize,
    /// The independent transversals, `words` words each.
    transversals: &'t [u64],
    /// The rows' vertex sets, `words` words each, or `None` when the rows are the
    /// transversals themselves.
    unions: Option<Vec<u64>>,
    /// Per row, the transversals it unites (its classes), as indices into `transversals`.
    parts: Vec<Vec<u32>>,
}

impl<'t> Rows<'t> {
    /// One row per transversal.
    fn plain(transversals: &'t [u64], words: usize) -> Self {
        Rows {
            words,
            transversals,
            unions: None,
            parts: (0..(transversals.len() / words) as u32)
                .map(|i| vec![i])
                .collect(),
        }
    }

    fn len(&self) -> usize {
        self.parts.len()
    }

    /// The vertex set of row i.
    fn set(&self, i: usize) -> &[u64] {
        let sets = self.unions.as_deref().unwrap_or(self.transversals);
        &sets[i * self.words..(i + 1) * self.words]
    }

    /// The vertex set of transversal i.
    fn transversal(&self, i: usize) -> &[u64] {
        &self.transversals[i * self.words..(i + 1) * self.words]
    }

    /// The number of colour classes row i holds.
    fn classes(&self, i: usize) -> usize {
        self.parts[i].len()
    }
}

/// The orbits of the transversals (laid end to end, `words` words each) under the
/// automorphism `image`, as rows: the union of each orbit whose members are pairwise
/// disjoint and at most `t`, in the order of their first members. `None` if the meter
/// stops the listing.
///
/// An automorphism maps an independent set of r vertices to another, and with r blocks
/// that is again a transversal, so every image is in the list.
fn orbit_rows<'t>(
    transversals: &'t [u64],
    index: &HashMap<&[u64], u32>,
    words: usize,
    image: &[u32],
    t: usize,
    meter: &mut Meter,
) -> Option<Rows<'t>> {
    let count = transversals.len() / words;
    let set = |i: usize| &transversals[i * words..(i + 1) * words];
    // Every transversal has as many vertices as there are blocks.
    let size = set(0).iter().map(|w| w.count_ones() as u64).sum::<u64>();
    let mut unions = Vec::new();
    let mut parts = Vec::new();
    let mut seen = vec![false; count];
    let mut mapped = vec![0u64; words];
    for first in 0..count {
        if seen[first] {
            continue;
        }
        let mut orbit = vec![first as u32];
        let mut union = set(first).to_vec();
        let mut disjoint = true;
        let mut at = first;
        loop {
            if !meter.spend(3 * words as u64 + size) {
                return None;
            }
            mapped.iter_mut().for_each(|w| *w = 0);
            for v in members(set(at)) {
                insert(&mut mapped, image[v] as usize);
            }
            let Some(&next) = index.get(mapped.as_slice()) else {
                disjoint = false;
                break;
            };
            at = next as usize;
            if at == first {
                break;
            }
            if orbit.len() == t {
                // Longer than the classes there are: the walk stops here and the rest of
                // the orbit is left unmarked (each of its members walks it again, as far).
                disjoint = false;
                break;
            }
            seen[at] = true;
            disjoint &= !intersects(&union, set(at));
            union.iter_mut().zip(set(at)).for_each(|(u, x)| *u |= x);
            orbit.push(at as u32);
        }
        if disjoint {
            unions.extend_from_slice(&union);
            parts.push(orbit);
        }
    }
    Some(Rows {
        words,
        transversals,
        unions: Some(unions),
        parts,
    })
}

/// The i-th term of the Luby sequence (1, 1, 2, 1, 1, 2, 4, 1, …), `i ≥ 1`.
fn luby(mut i: u64) -> u64 {
    loop {
        // The bit length of i: 2^(k − 1) ≤ i ≤ 2^k − 1.
        let k = 64 - i.leading_zeros() as u64;
        if (1u64 << k) - 1 == i {
            return 1 << (k - 1);
        }
        i -= (1 << (k - 1)) - 1;
    }
}

/// Why a restart stopped before it decided.
#[derive(Debug)]
enum Halt {
    /// The restart's node limit: restart with the next limit.
    NodeLimit,
    /// The meter refused a step: the search is over.
    Budget,
}

/// The branch-and-bound over classes of step 5 in the [module docs](self).
struct Search<'a> {
    rows: &'a Rows<'a>,
    /// The cliques of the edge cover, as vertex sets.
    cover: &'a [Vec<u64>],
    meter: &'a mut Meter,
    rng: &'a mut Rng,
    /// Nodes of this restart so far, and its limit.
    nodes: u64,
    limit: u64,
    /// Whether this restart orders the branches by the cliques they hit (else at random).
    weighted: bool,
    /// Scratch: per vertex, the rows through it at the current node.
    counts: Vec<u32>,
    /// The vertices of one class (one transversal): n / t.
    class_size: usize,
}

impl<'a> Search<'a> {
    fn new(
        rows: &'a Rows<'a>,
        cover: &'a [Vec<u64>],
        meter: &'a mut Meter,
        rng: &'a mut Rng,
    ) -> Self {
        Search {
            rows,
            cover,
            meter,
            rng,
            nodes: 0,
            limit: 0,
            weighted: false,
            counts: Vec::new(),
            class_size: 0,
        }
    }

    /// Chooses rows covering the `n` vertices with `t` classes in all, under restarts: the
    /// colours by local vertex id, `None` if a restart searched the whole tree without
    /// finding them, or `Err` when the meter stops the search.
    fn run(&mut self, n: usize, t: usize) -> Result<Option<Vec<u32>>, Halt> {
        let all: Vec<u32> = (0..self.rows.len() as u32).collect();
        let mut whole = vec![0u64; self.rows.words];
        (0..n).for_each(|v| insert(&mut whole, v));
        self.counts = vec![0; n];
        self.class_size = n / t;
        for restart in 1u64.. {
            self.nodes = 0;
            self.limit = RESTART_UNIT.saturating_mul(luby(restart));
            self.weighted = restart % 2 == 1;
            let mut chosen = Vec::with_capacity(t);
            match self.node(&all, &whole, t, &mut chosen) {
                Ok(true) => {
                    let mut colour = vec![0u32; n];
                    let classes = chosen
                        .iter()
                        .flat_map(|&row| &self.rows.parts[row as usize]);
                    for (k, &part) in classes.enumerate() {
                        for v in members(self.rows.transversal(part as usize)) {
                            colour[v] = k as u32;
                        }
                    }
                    return Ok(Some(colour));
                }
                Ok(false) => return Ok(None),
                Err(Halt::NodeLimit) => continue,
                Err(Halt::Budget) => return Err(Halt::Budget),
            }
        }
        unreachable!("the restarts end by a result or by the budget")
    }

    fn pay(&mut self, steps: usize) -> Result<(), Halt> {
        if self.meter.spend(steps as u64) {
            Ok(())
        } else {
            Err(Halt::Budget)
        }
    }

    /// Whether `chosen` (pushed in order) can be completed to `left` more classes covering
    /// `uncovered` from the rows `viable` (all disjoint from the chosen ones).
    fn node(
        &mut self,
        viable: &[u32],
        uncovered: &[u64],
        left: usize,
        chosen: &mut Vec<u32>,
    ) -> Result<bool, Halt> {
        self.nodes += 1;
        if self.nodes > self.limit {
            return Err(Halt::NodeLimit);
        }
        if uncovered.iter().all(|&w| w == 0) {
            return Ok(true);
        }
        let words = self.rows.words;
        // The clique filter: a clique with more uncovered vertices than classes left fails
        // the node; one with exactly as many is hit once by every class still to choose,
        // so a row of k classes must hold exactly k of its uncovered vertices.
        self.pay(self.cover.len() * words + self.counts.len())?;
        let mut tight: Vec<Vec<u64>> = Vec::new();
        for q in self.cover {
            let open = count_common(q, uncovered);
            if open > left {
                return Ok(false);
            }
            if open == left {
                tight.push(q.iter().zip(uncovered).map(|(a, b)| a & b).collect());
            }
        }
        self.pay(viable.len() * words * (tight.len() + 1))?;
        let rows = self.rows;
        let viable: Vec<u32> = viable
            .iter()
            .copied()
            .filter(|&i| {
                let (x, k) = (rows.set(i as usize), rows.classes(i as usize));
                k <= left && tight.iter().all(|q| count_common(q, x) == k)
            })
            .collect();
        // The uncovered vertex in the fewest rows decides the branch.
        let visits: usize = viable.iter().map(|&i| rows.classes(i as usize)).sum();
        self.pay(visits * self.class_size)?;
        self.counts.iter_mut().for_each(|c| *c = 0);
        for &i in &viable {
            for v in members(rows.set(i as usize)) {
                self.counts[v] += 1;
            }
        }
        let Some(pivot) = members(uncovered).min_by_key(|&v| (self.counts[v], v)) else {
            return Ok(true);
        };
        if self.counts[pivot] == 0 {
            return Ok(false);
        }
        let mut branch: Vec<u32> = viable
            .iter()
            .copied()
            .filter(|&i| contains(rows.set(i as usize), pivot))
            .collect();
        self.order(&mut branch, uncovered)?;
        for b in branch {
            self.pay(viable.len() * words)?;
            let x = rows.set(b as usize);
            let rest: Vec<u32> = viable
                .iter()
                .copied()
                .filter(|&i| !intersects(rows.set(i as usize), x))
                .collect();
            let still: Vec<u64> = uncovered.iter().zip(x).map(|(u, b)| u & !b).collect();
            chosen.push(b);
            if self.node(&rest, &still, left - rows.classes(b as usize), chosen)? {
                return Ok(true);
            }
            chosen.pop();
        }
        Ok(false)
    }

    /// Orders the branches: at random, or (on weighted restarts) those hitting the cliques
    /// with the most uncovered vertices first, the sum of the squared open sizes of the
    /// cliques hit, ties at random.
    fn order(&mut self, branch: &mut [u32], uncovered: &[u64]) -> Result<(), Halt> {
        self.rng.shuffle(branch);
        if !self.weighted {
            return Ok(());
        }
        self.pay(branch.len() * self.cover.len() * self.rows.words)?;
        let open: Vec<u64> = self
            .cover
            .iter()
            .map(|q| count_common(q, uncovered) as u64)
            .collect();
        let mut keyed: Vec<(u64, u32)> = branch
            .iter()
            .map(|&i| {
                let x = self.rows.set(i as usize);
                let weight = self
                    .cover
                    .iter()
                    .zip(&open)
                    .filter(|(q, _)| intersects(q, x))
                    .map(|(_, &s)| s * s)
                    .sum::<u64>();
                (weight, i)
            })
            .collect();
        // Stable, so equal weights keep the shuffled order.
        keyed.sort_by_key(|&(weight, _)| std::cmp::Reverse(weight));
        for (slot, (_, i)) in branch.iter_mut().zip(keyed) {
            *slot = i;
        }
        Ok(())
    }
}

/// Vertex sets of a core as rows of bits: `bits[v * words..(v + 1) * words]` is row v.
struct Sets {
    words: usize,
    bits: Vec<u64>,
}

impl Sets {
    /// The core's adjacency matrix.
    fn adjacency(core: &Core, words: usize) -> Self {
        let mut bits = vec![0u64; core.len() * words];
        for v in 0..core.len() {
            for &u in core.neighbours(v) {
                insert(&mut bits[v * words..(v + 1) * words], u as usize);
            }
        }
        Sets { words, bits }
    }

    fn len(&self) -> usize {
        self.bits.len() / self.words
    }

    fn row(&self, v: usize) -> &[u64] {
        &self.bits[v * self.words..(v + 1) * self.words]
    }
}

fn contains(set: &[u64], v: usize) -> bool {
    set[v / 64] >> (v % 64) & 1 == 1
}

fn insert(set: &mut [u64], v: usize) {
    set[v / 64] |= 1 << (v % 64);
}

fn remove(set: &mut [u64], v: usize) {
    set[v / 64] &= !(1 << (v % 64));
}

fn intersects(a: &[u64], b: &[u64]) -> bool {
    a.iter().zip(b).any(|(x, y)| x & y != 0)
}

fn count_common(a: &[u64], b: &[u64]) -> usize {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x & y).count_ones() as usize)
        .sum()
}

/// The members of a vertex set, in increasing order.
fn members(set: &[u64]) -> impl Iterator<Item = usize> + '_ {
    set.iter().enumerate().flat_map(|(k, &word)| {
        let mut rest = word;
        std::iter::from_fn(move || {
            (rest != 0).then(|| {
                let bit = rest.trailing_zeros() as usize;
                rest &= rest - 1;
                k * 64 + bit
            })
        })
    })
}

/// A necessary condition, in O(d²) steps for the first vertex's degree d, for the first
/// vertex of `core` to lie in a clique of `core.colours` vertices: it has `t − 1` neighbours
/// with `t − 2` common neighbours each. It keeps the search from building the adjacency
/// matrix of a sparse graph that has no such split.
fn may_lie_in_a_clique(core: &Core, meter: &mut Meter) -> bool {
    let t = core.colours;
    let first = core.neighbours(0);
    let cost: u64 = first
        .iter()
        .map(|&u| core.neighbours(u as usize).len() as u64)
        .sum();
    if !meter.spend(cost + first.len() as u64) {
        return false;
    }
    let mut near = vec![false; core.len()];
    for &u in first {
        near[u as usize] = true;
    }
    let candidates = first
        .iter()
        .filter(|&&u| {
            let common = core.neighbours(u as usize);
            common.iter().filter(|&&w| near[w as usize]).count() + 2 >= t
        })
        .count();
    candidates + 1 >= t
}

/// Splits the vertices into cliques of exactly `t` vertices (step 1), or `None` if the
/// backtracking finds no split within `limit` nodes or the meter stops it.
fn split_into_cliques(
    adjacency: &Sets,
    t: usize,
    limit: u64,
    meter: &mut Meter,
) -> Option<Vec<Vec<u32>>> {
    let n = adjacency.len();
    let mut split = Split {
        adjacency,
        t,
        meter,
        nodes: 0,
        limit,
        blocks: Vec::new(),
    };
    let mut uncovered = vec![0u64; adjacency.words];
    for v in 0..n {
        insert(&mut uncovered, v);
    }
    match split.cover_from(&mut uncovered) {
        Some(true) => Some(split.blocks),
        _ => None,
    }
}

/// The backtracking of [`split_into_cliques`].
struct Split<'a> {
    adjacency: &'a Sets,
    t: usize,
    meter: &'a mut Meter,
    nodes: u64,
    limit: u64,
    blocks: Vec<Vec<u32>>,
}

impl Split<'_> {
    /// Whether the vertices of `uncovered` split into t-cliques (pushed on `blocks`);
    /// `None` when the node limit or the meter stops the search.
    fn cover_from(&mut self, uncovered: &mut [u64]) -> Option<bool> {
        let Some(first) = members(uncovered).next() else {
            return Some(true);
        };
        let candidates: Vec<u64> = self
            .adjacency
            .row(first)
            .iter()
            .zip(uncovered.iter())
            .map(|(a, u)| a & u)
            .collect();
        let mut clique = vec![first as u32];
        self.grow(&mut clique, &candidates, uncovered)
    }

    /// Extends `clique` by members of `candidates` (all adjacent to every member, all
    /// after its last member) to t vertices in every way, and each complete clique by a
    /// split of the rest.
    fn grow(
        &mut self,
        clique: &mut Vec<u32>,
        candidates: &[u64],
        uncovered: &mut [u64],
    ) -> Option<bool> {
        self.nodes += 1;
        if self.nodes > self.limit || !self.meter.spend(self.adjacency.words as u64) {
            return None;
        }
        if clique.len() == self.t {
            for &v in clique.iter() {
                remove(uncovered, v as usize);
            }
            self.blocks.push(clique.clone());
            let done = self.cover_from(uncovered);
            if done != Some(true) {
                self.blocks.pop();
                for &v in clique.iter() {
                    insert(uncovered, v as usize);
                }
            }
            return done;
        }
        if members(candidates).count() < self.t - clique.len() {
            return Some(false);
        }
        let last = *clique
            .last()
            .expect("a clique starts with its first vertex") as usize;
        for w in members(candidates)
            .filter(|&w| w > last)
            .collect::<Vec<_>>()
        {
            let next: Vec<u64> = candidates
                .iter()
                .zip(self.adjacency.row(w))
                .map(|(c, a)| c & a)
                .collect();
            clique.push(w as u32);
            let done = self.grow(clique, &next, uncovered);
            clique.pop();
            if done != Some(false) {
                return done;
            }
        }
        Some(false)
    }
}

/// A family of cliques that covers every edge once (step 2), or `None` if the meter stops
/// it. Each round grows every uncovered edge into a maximal clique of uncovered edges (by
/// the candidate with the most uncovered edges to the other candidates, the first of
/// equals), then keeps the grown cliques from the largest down, each if none of its edges
/// was covered by one kept before it; the next round starts from the edges left.
fn clique_cover(adjacency: &Sets, meter: &mut Meter) -> Option<Vec<Vec<u64>>> {
    let (n, words) = (adjacency.len(), adjacency.words);
    let mut open = Sets {
        words,
        bits: adjacency.bits.clone(),
    };
    let mut cover = Vec::new();
    loop {
        let mut grown: Vec<Vec<usize>> = Vec::new();
        for u in 0..n {
            for v in members(open.row(u)).filter(|&v| v > u).collect::<Vec<_>>() {
                let mut clique = vec![u, v];
                let mut candidates: Vec<u64> = open
                    .row(u)
                    .iter()
                    .zip(open.row(v))
                    .map(|(a, b)| a & b)
                    .collect();
                loop {
                    let inside: Vec<usize> = members(&candidates).collect();
                    if !meter.spend((inside.len() * words) as u64 + 1) {
                        return None;
                    }
                    let Some(w) = inside
                        .iter()
                        .copied()
                        .max_by_key(|&w| (count_common(open.row(w), &candidates), n - w))
                    else {
                        break;
                    };
                    clique.push(w);
                    for (c, a) in candidates.iter_mut().zip(open.row(w)) {
                        *c &= a;
                    }
                }
                grown.push(clique);
            }
        }
        if grown.is_empty() {
            return Some(cover);
        }
        // Stable: equal sizes keep the order of their first edges.
        grown.sort_by_key(|clique| std::cmp::Reverse(clique.len()));
        for clique in grown {
            let all_open = clique
                .iter()
                .enumerate()
                .all(|(i, &a)| clique[i + 1..].iter().all(|&b| contains(open.row(a), b)));
            if !all_open {
                continue;
            }
            let mut set = vec![0u64; words];
            for &a in &clique {
                insert(&mut set, a);
                for &b in &clique {
                    remove(&mut open.bits[a * words..(a + 1) * words], b);
                }
            }
            cover.push(set);
        }
    }
}

/// Every independent set with one vertex of each block (step 3), as vertex sets laid end
/// to end, or `None` if there are more than [`MAX_CANDIDATE_WORDS`] words of them or the
/// meter stops the listing.
fn independent_transversals(
    adjacency: &Sets,
    blocks: &[Vec<u32>],
    meter: &mut Meter,
) -> Option<Vec<u64>> {
    let words = adjacency.words;
    let mut out = Vec::new();
    let mut allowed = vec![u64::MAX; words];
    let mut picked = vec![0u64; words];
    list_transversals(
        adjacency,
        blocks,
        &mut allowed,
        &mut picked,
        meter,
        &mut out,
    )?;
    Some(out)
}

/// The recursion of [`independent_transversals`]: extends `picked` (one vertex of each
/// block before `blocks`) by a vertex of `allowed` in each block of `blocks`.
fn list_transversals(
    adjacency: &Sets,
    blocks: &[Vec<u32>],
    allowed: &mut [u64],
    picked: &mut [u64],
    meter: &mut Meter,
    out: &mut Vec<u64>,
) -> Option<()> {
    let Some((block, rest)) = blocks.split_first() else {
        if out.len() + picked.len() > MAX_CANDIDATE_WORDS {
            return None;
        }
        out.extend_from_slice(picked);
        return Some(());
    };
    for &v in block {
        let v = v as usize;
        if !contains(allowed, v) {
            continue;
        }
        if !meter.spend(adjacency.words as u64) {
            return None;
        }
        let mut narrower: Vec<u64> = allowed
            .iter()
            .zip(adjacency.row(v))
            .map(|(a, b)| a & !b)
            .collect();
        insert(picked, v);
        list_transversals(adjacency, rest, &mut narrower, picked, meter, out)?;
        remove(picked, v);
    }
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::gen::{graph, GraphKind};
    use crate::graph::colouring::budget::Budget;
    use crate::graph::colouring::check_colouring;
    use crate::graph::Graph;

    fn queen(side: usize) -> Graph {
        Graph::from_edge_list(&graph(GraphKind::Queen, side, 0, 0).unwrap()).unwrap()
    }

    fn exact(g: &Graph, t: usize, steps: u64, seed: u64) -> Outcome {
        let core = Core::new(g, t, &mut NoCount);
        let mut meter = Meter::new(&Budget::steps(steps));
        colour_by_transversals(&core, &mut meter, &mut Rng::new(seed))
    }

    /// Whether `g` has a proper colouring with `k` colours, by brute force.
    fn colourable(g: &Graph, k: usize) -> bool {
        fn extend(g: &Graph, colour: &mut Vec<usize>, k: usize) -> bool {
            let v = colour.len();
            if v == g.vertex_count() {
                return true;
            }
            let used = colour.iter().copied().max().map_or(0, |m| m + 1);
            for a in 0..k.min(used + 1) {
                if g.adjacent(v)
                    .iter()
                    .all(|&u| (u as usize) >= v || colour[u as usize] != a)
                {
                    colour.push(a);
                    if extend(g, colour, k) {
                        return true;
                    }
                    colour.pop();
                }
            }
            false
        }
        extend(g, &mut Vec::new(), k)
    }

    fn assert_proper(g: &Graph, t: usize, colour: &[u32]) {
        let colour: Vec<usize> = colour.iter().map(|&k| k as usize).collect();
        assert!(colour.iter().all(|&k| k < t));
        assert_eq!(check_colouring(g, &colour), Ok(()));
    }

    #[test]
    fn the_luby_sequence() {
        let terms: Vec<u64> = (1..=15).map(luby).collect();
        assert_eq!(terms, [1, 1, 2, 1, 1, 2, 4, 1, 1, 2, 1, 1, 2, 4, 8]);
    }

    #[test]
    fn queen_graphs_are_decided_at_their_side() {
        // χ(queen n×n) = n for n = 5, 7, 11 and n + 1 for n = 6, 8, 9, 10.
        for side in [5, 6, 7, 8, 9, 10, 11] {
            let g = queen(side);
            match exact(&g, side, u64::MAX, 7) {
                Outcome::Found(colour) => {
                    assert!([5, 7, 11].contains(&side), "queen{side}: found");
                    assert_proper(&g, side, &colour);
                }
                Outcome::Impossible => assert!(![5, 7, 11].contains(&side), "queen{side}"),
                other => panic!("queen{side}: {other:?}"),
            }
        }
    }

    #[test]
    fn queen12_12_and_queen13_13_are_coloured_with_their_side() {
        // χ = n for both; queen13_13 is found among the colourings the quarter turn of the
        // board maps to themselves.
        for side in [12, 13] {
            let g = queen(side);
            match exact(&g, side, u64::MAX, 5) {
                Outcome::Found(colour) => assert_proper(&g, side, &colour),
                other => panic!("queen{side}: {other:?}"),
            }
        }
    }

    /// Every row of `orbit_rows` is an orbit of transversals under the automorphism: each
    /// part maps onto the next, and the parts are disjoint and make up the row.
    #[test]
    fn orbit_rows_are_disjoint_orbits() {
        for side in [5, 7] {
            let g = queen(side);
            let core = Core::new(&g, side, &mut NoCount);
            let n = core.len();
            let words = n.div_ceil(64);
            let adjacency = Sets::adjacency(&core, words);
            let mut meter = Meter::new(&Budget::steps(u64::MAX));
            let blocks = split_into_cliques(&adjacency, side, u64::MAX, &mut meter).unwrap();
            let transversals = independent_transversals(&adjacency, &blocks, &mut meter).unwrap();
            let adjacent = |u: usize, v: usize| contains(adjacency.row(u), v);
            let choices = automorphisms(&core, &adjacent, &mut meter);
            assert_eq!(choices.len(), 6, "queen{side}: the board's symmetries");
            let index: HashMap<&[u64], u32> = transversals
                .chunks_exact(words)
                .enumerate()
                .map(|(i, set)| (set, i as u32))
                .collect();
            let mut sizes = Vec::new();
            for image in &choices {
                let rows = orbit_rows(&transversals, &index, words, image, side, &mut meter);
                let rows = rows.unwrap();
                for i in 0..rows.len() {
                    let parts = &rows.parts[i];
                    let mut union = vec![0u64; words];
                    for (k, &part) in parts.iter().enumerate() {
                        let x = rows.transversal(part as usize);
                        assert!(!intersects(&union, x), "queen{side}: parts overlap");
                        union.iter_mut().zip(x).for_each(|(u, b)| *u |= b);
                        let next = rows.transversal(parts[(k + 1) % parts.len()] as usize);
                        let mut mapped = vec![0u64; words];
                        members(x).for_each(|v| insert(&mut mapped, image[v] as usize));
                        assert_eq!(mapped, next, "queen{side}: not an orbit");
                    }
                    assert_eq!(union, rows.set(i));
                    sizes.push(parts.len());
                }
            }
            // Rows of one and of several classes both occur.
            assert!(
                sizes.contains(&1) && sizes.iter().any(|&k| k > 1),
                "{sizes:?}"
            );
        }
    }

    #[test]
    fn graphs_without_a_split_are_not_tried() {
        // Four vertices in a path: no split into two triangles, and t below 3.
        let path = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 3], [3, 4], [4, 5]]).unwrap();
        assert_eq!(exact(&path, 3, u64::MAX, 1), Outcome::NotTried);
        // 25 vertices of queen5_5 do not split into cliques of 4.
        assert_eq!(exact(&queen(5), 4, u64::MAX, 1), Outcome::NotTried);
        // No budget: nothing is tried.
        assert_eq!(exact(&queen(5), 5, 0, 1), Outcome::NotTried);
    }

    #[test]
    fn a_small_budget_stops_the_search_after_the_split() {
        // queen11_11 splits into its rows at once; a few thousand steps do not finish it.
        let outcome = exact(&queen(11), 11, 20_000, 1);
        assert_eq!(outcome, Outcome::AtLeast);
    }

    #[test]
    fn the_same_seed_gives_the_same_colouring() {
        let g = queen(11);
        assert_eq!(exact(&g, 11, u64::MAX, 3), exact(&g, 11, u64::MAX, 3));
    }

    /// Random graphs built on r disjoint t-cliques, with random edges between them: the
    /// search's verdict agrees with brute force, and its colourings are proper.
    #[test]
    fn planted_splits_against_brute_force() {
        let mut rng = Rng::new(0x5EED);
        let mut decided = [0usize; 2];
        for case in 0..300 {
            let t = 3 + rng.index(2);
            let r = 2 + rng.index(if t == 3 { 3 } else { 2 });
            let n = r * t;
            // Shuffle the vertex ids so the blocks are not consecutive.
            let mut id: Vec<usize> = (0..n).collect();
            rng.shuffle(&mut id);
            let mut edges = Vec::new();
            for b in 0..r {
                for i in 0..t {
                    for j in i + 1..t {
                        edges.push([id[b * t + i], id[b * t + j]]);
                    }
                }
            }
            let density = 1 + rng.index(6);
            for u in 0..n {
                for v in u + 1..n {
                    if u / t != v / t && rng.index(10) < density {
                        edges.push([id[u], id[v]]);
                    }
                }
            }
            let g = Graph::from_edges(n, &edges).unwrap();
            let core = Core::new(&g, t, &mut NoCount);
            // The search colours the t-core; brute force colours the same subgraph.
            let core_edges: Vec<[usize; 2]> = (0..core.len())
                .flat_map(|v| core.neighbours(v).iter().map(move |&u| [v, u as usize]))
                .filter(|&[v, u]| v < u)
                .collect();
            let h = Graph::from_edges(core.len(), &core_edges).unwrap();
            let mut meter = Meter::new(&Budget::steps(u64::MAX));
            let outcome = colour_by_transversals(&core, &mut meter, &mut rng);
            let expected = colourable(&h, t);
            match outcome {
                Outcome::Found(colour) => {
                    assert!(
                        expected,
                        "case {case}: found a colouring brute force denies"
                    );
                    assert_proper(&h, t, &colour);
                    decided[0] += 1;
                }
                Outcome::Impossible => {
                    assert!(!expected, "case {case}: brute force colours it with {t}");
                    decided[1] += 1;
                }
                Outcome::NotTried | Outcome::AtLeast => {}
            }
        }
        // Both verdicts occur, so the test exercises both.
        assert!(decided[0] > 20 && decided[1] > 20, "{decided:?}");
    }
}
