//! Automorphisms of a core, for the exact search of [`transversal`](super::transversal):
//! a colouring whose classes an automorphism permutes is found among far fewer candidates
//! than an arbitrary one.
//!
//! The problem: some graphs whose optimal colourings are rigid and rare, such as the queen
//! graphs, are highly symmetric, and so are many of their optima. Looking for a colouring
//! that an automorphism π maps to itself (π sends every colour class onto a colour class)
//! shrinks the search: the classes come in orbits under π, and choosing one class of an
//! orbit chooses the whole orbit. This is the method of prescribed automorphisms used to
//! construct designs (Kramer and Mesner, *t-designs on hypergraphs*, Discrete Mathematics
//! 15, 1976), here for colourings.
//!
//! This file finds the automorphisms, by individualisation and refinement (the scheme of
//! McKay's nauty, in its plainest form; McKay and Piperno, *Practical graph isomorphism,
//! II*, Journal of Symbolic Computation 60, 2014):
//!
//! 1. **Refinement.** A colouring of the vertices is refined until it is equitable: each
//!    round recolours every vertex by its colour and the multiset of its neighbours'
//!    colours (summed through a fixed hash, so a round costs O(n + m) and a sort), until the
//!    number of cells stops growing. The result depends only on the graph and the colours,
//!    so an automorphism maps every refined cell onto itself.
//! 2. **The base.** From the refined unit colouring, the first vertex of the first cell with
//!    more than one vertex is given a colour of its own and the colouring refined again,
//!    until every cell is a single vertex: the base b₁, b₂, … and its colourings.
//! 3. **Generators.** From the deepest level up, for every other vertex w of the cell that
//!    bᵢ was taken from, not already reached from bᵢ by the generators found so far (they
//!    all fix b₁ … bᵢ₋₁), a backtracking search looks for an automorphism that fixes
//!    b₁ … bᵢ₋₁ and sends bᵢ to w: it individualises bᵢ on one side and w on the other,
//!    refines both, compares the two refinements' traces (every round's cells, their
//!    signatures and sizes), and recurses on the
//!    first non-singleton cell until every cell is a vertex; the bijection is then checked
//!    against every edge. The generators found generate the whole group (the search for
//!    each w is exhaustive, and the orbit test only skips vertices an automorphism already
//!    reaches), unless a limit stops it, in which case they generate a subgroup.
//! 4. **Choices.** The group is closed from its generators up to [`MAX_GROUP`] elements
//!    (a larger group is not listed: its first generators are used as they are),
//!    and one element of each cyclic subgroup is kept, the largest orders first: invariance
//!    under π is invariance under every power of π, so π and its generators of ⟨π⟩ give the
//!    same search, and a larger order gives a smaller one.
//!
//! Not in the course texts.
//!
//! # Complexity
//!
//! A refinement costs O((n + m)·r + n log n·r) for r rounds (r ≤ n); the base takes at most
//! n refinements. The backtracking of step 3 is exponential in the worst case (on regular
//! graphs that refinement cannot split), so the whole search stops after [`NODE_LIMIT`]
//! refinements; each level's orbit test costs O(n + n·g) for g generators, once per level
//! and once per generator found. The closure costs O(|G|·g·n), and the choices O(|G|·n)
//! for the orders plus O(|G|·n) per choice for its powers. Every step is paid from the
//! [`Meter`]. Space: O(L·n) for the colourings of a base of L ≤ n levels, O(|G|·n) for the
//! group, |G| ≤ [`MAX_GROUP`].

use super::budget::Meter;
use super::reduce::Core;
use std::collections::{HashMap, HashSet};

/// The most group elements the closure of step 4 lists.
pub(super) const MAX_GROUP: usize = 512;

/// The most automorphisms handed to the search, one per cyclic subgroup.
pub(super) const MAX_CHOICES: usize = 8;

/// The most refinements the whole search may make: those of the base (steps 1 and 2) and
/// those of the generator search (step 3).
pub(super) const NODE_LIMIT: u64 = 4096;

/// A permutation of the core's vertices: `image[v]` is where v goes.
pub(super) type Permutation = Vec<u32>;

/// Up to [`MAX_CHOICES`] automorphisms of `core`, each generating a different cyclic
/// subgroup, those of largest order first; none if the core has no symmetry the search
/// found, or if the meter stops it before it found any. When the group is too large to
/// list ([`MAX_GROUP`]) or the meter stops the closure, the first generators found (at the
/// deepest levels of the base, often involutions moving few vertices) stand in for the
/// choices. `adjacent(u, v)` tells whether u and v are adjacent.
pub(super) fn automorphisms(
    core: &Core,
    adjacent: &dyn Fn(usize, usize) -> bool,
    meter: &mut Meter,
) -> Vec<Permutation> {
    let mut finder = Finder {
        core,
        adjacent,
        meter,
        nodes: 0,
    };
    let generators = finder.generators().unwrap_or_default();
    if generators.is_empty() {
        return Vec::new();
    }
    let Some(group) = closure(&generators, core.len(), finder.meter) else {
        return generators.into_iter().take(MAX_CHOICES).collect();
    };
    cyclic_choices(group, finder.meter)
}

/// One cell of a refinement round: the old colour, the hash of the neighbours' colours, and
/// the number of vertices.
type Signature = (u64, u64, u32);

/// Why a search stopped early.
struct Stop;

/// A colouring of the vertices: `cell[v]` is v's colour.
#[derive(Clone)]
struct Colouring {
    cell: Vec<u32>,
    /// The number of distinct colours.
    cells: usize,
}

/// The search of steps 1–3 in the [module docs](self).
struct Finder<'a> {
    core: &'a Core,
    adjacent: &'a dyn Fn(usize, usize) -> bool,
    meter: &'a mut Meter,
    /// Refinements made so far.
    nodes: u64,
}

impl Finder<'_> {
    /// The generators of step 3: all that the search found before a limit stopped it
    /// (possibly none), or `Err` if a limit stopped it while it built the base (steps 1
    /// and 2).
    fn generators(&mut self) -> Result<Vec<Permutation>, Stop> {
        let n = self.core.len();
        let mut unit = Colouring {
            cell: vec![0; n],
            cells: usize::from(n > 0),
        };
        let unit_trace = self.refine(&mut unit)?;
        // Step 2: the base, and the chain of its refined colourings with their traces:
        // chain[k + 1] is chain[k] with bases[k] individualised, refined.
        let mut chain: Vec<(Colouring, Vec<Signature>)> = vec![(unit, unit_trace)];
        let mut bases = Vec::new();
        while let Some(cell) = first_open_cell(&chain[chain.len() - 1].0) {
            let current = &chain[chain.len() - 1].0;
            let base = members_of(current, cell)
                .next()
                .expect("an open cell has members");
            let mut next = current.clone();
            individualise(&mut next, base);
            let trace = self.refine(&mut next)?;
            bases.push(base);
            chain.push((next, trace));
        }
        // Step 3, from the deepest level up.
        let mut generators: Vec<Permutation> = Vec::new();
        for (level, &base) in bases.iter().enumerate().rev() {
            let colouring = &chain[level].0;
            let cell = colouring.cell[base];
            // The orbit of the base point under the generators so far, again only when a
            // generator is added.
            let Ok(mut reached) = self.orbit_of(base, &generators) else {
                return Ok(generators);
            };
            for w in members_of(colouring, cell).collect::<Vec<_>>() {
                if reached[w] {
                    continue;
                }
                let mut image = colouring.clone();
                individualise(&mut image, w);
                match self.extend(&chain[level + 1..], image) {
                    Ok(Some(found)) => {
                        generators.push(found);
                        match self.orbit_of(base, &generators) {
                            Ok(orbit) => reached = orbit,
                            Err(Stop) => return Ok(generators),
                        }
                    }
                    Ok(None) => {}
                    Err(Stop) => return Ok(generators),
                }
            }
        }
        Ok(generators)
    }

    /// An automorphism that maps every cell of `left[0]` onto the same cell of `right`
    /// (not yet refined), or `None` if there is none. `left` is the rest of the base's
    /// chain: each colouring with its trace, the next one its successor with the first
    /// vertex of its first open cell individualised, which is the vertex this search
    /// individualises on the left, so the left side is never refined again.
    fn extend(
        &mut self,
        left: &[(Colouring, Vec<Signature>)],
        mut right: Colouring,
    ) -> Result<Option<Permutation>, Stop> {
        let (colouring, trace) = &left[0];
        if self.refine(&mut right)? != *trace {
            return Ok(None);
        }
        let Some(cell) = first_open_cell(colouring) else {
            return Ok(self.bijection(colouring, &right));
        };
        for w in members_of(&right, cell).collect::<Vec<_>>() {
            let mut image = right.clone();
            individualise(&mut image, w);
            if let Some(found) = self.extend(&left[1..], image)? {
                return Ok(Some(found));
            }
        }
        Ok(None)
    }

    /// Which vertices the permutations in `generators` reach from `v`, paying n + g per
    /// vertex reached for g generators.
    fn orbit_of(&mut self, v: usize, generators: &[Permutation]) -> Result<Vec<bool>, Stop> {
        let n = self.core.len();
        let mut reached = vec![false; n];
        reached[v] = true;
        let mut orbit = vec![v];
        let mut next = 0;
        if !self.meter.spend(n as u64) {
            return Err(Stop);
        }
        while next < orbit.len() {
            if !self.meter.spend(generators.len() as u64 + 1) {
                return Err(Stop);
            }
            let u = orbit[next];
            next += 1;
            for g in generators {
                let w = g[u] as usize;
                if !reached[w] {
                    reached[w] = true;
                    orbit.push(w);
                }
            }
        }
        Ok(reached)
    }

    /// The bijection between two discrete colourings (the vertex of each colour on the left
    /// to the vertex of that colour on the right), if it is an automorphism.
    fn bijection(&mut self, left: &Colouring, right: &Colouring) -> Option<Permutation> {
        let n = self.core.len();
        let mut at = vec![0u32; n];
        for (v, &k) in right.cell.iter().enumerate() {
            at[k as usize] = v as u32;
        }
        let image: Permutation = left.cell.iter().map(|&k| at[k as usize]).collect();
        if !self.meter.spend(self.core.edge_ends() + n as u64) {
            return None;
        }
        let preserves_edges = (0..n).all(|v| {
            self.core
                .neighbours(v)
                .iter()
                .all(|&u| (self.adjacent)(image[v] as usize, image[u as usize] as usize))
        });
        preserves_edges.then_some(image)
    }

    /// Refines `colouring` until it is equitable (step 1); the trace is the sorted list of
    /// (signature, count) of every round, equal for two colourings an automorphism maps
    /// onto each other.
    fn refine(&mut self, colouring: &mut Colouring) -> Result<Vec<Signature>, Stop> {
        self.nodes += 1;
        if self.nodes > NODE_LIMIT {
            return Err(Stop);
        }
        let n = self.core.len();
        let mut trace = Vec::new();
        loop {
            let cost = self.core.edge_ends()
                + 2 * n as u64 * (1 + u64::from(usize::BITS - n.leading_zeros()));
            if !self.meter.spend(cost) {
                return Err(Stop);
            }
            let mut signature: Vec<(u64, u64, u32)> = (0..n)
                .map(|v| {
                    let around = self.core.neighbours(v).iter().fold(0u64, |sum, &u| {
                        sum.wrapping_add(mix(colouring.cell[u as usize]))
                    });
                    (u64::from(colouring.cell[v]), around, v as u32)
                })
                .collect();
            signature.sort_unstable();
            let mut cells = 0;
            let mut round = Vec::new();
            for (i, &(old, around, v)) in signature.iter().enumerate() {
                if i == 0 || (old, around) != (signature[i - 1].0, signature[i - 1].1) {
                    cells += 1;
                    round.push((old, around, 0));
                }
                colouring.cell[v as usize] = cells - 1;
                round.last_mut().expect("pushed above").2 += 1;
            }
            trace.extend(round);
            let grew = cells as usize > colouring.cells;
            colouring.cells = cells as usize;
            if !grew {
                return Ok(trace);
            }
        }
    }
}

/// A fixed 64-bit mixing of a colour (SplitMix64's finaliser), so that sums of neighbour
/// colours tell multisets apart.
fn mix(colour: u32) -> u64 {
    let mut z = u64::from(colour).wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Gives `v` a colour of its own.
fn individualise(colouring: &mut Colouring, v: usize) {
    colouring.cell[v] = colouring.cells as u32;
    colouring.cells += 1;
}

/// The smallest colour with more than one vertex.
fn first_open_cell(colouring: &Colouring) -> Option<u32> {
    let mut size = vec![0u32; colouring.cells];
    for &k in &colouring.cell {
        size[k as usize] += 1;
    }
    size.iter().position(|&s| s > 1).map(|k| k as u32)
}

/// The vertices of colour `cell`, in increasing order.
fn members_of(colouring: &Colouring, cell: u32) -> impl Iterator<Item = usize> + '_ {
    (0..colouring.cell.len()).filter(move |&v| colouring.cell[v] == cell)
}

/// The group the generators generate, identity first, in the order found; `None` if it has
/// more than [`MAX_GROUP`] elements or the meter stops the closure.
fn closure(generators: &[Permutation], n: usize, meter: &mut Meter) -> Option<Vec<Permutation>> {
    let identity: Permutation = (0..n as u32).collect();
    let mut seen: HashSet<Permutation> = HashSet::from([identity.clone()]);
    let mut group = vec![identity];
    let mut next = 0;
    while next < group.len() {
        for g in generators {
            if !meter.spend(2 * n as u64) {
                return None;
            }
            let product: Permutation = group[next].iter().map(|&v| g[v as usize]).collect();
            if seen.insert(product.clone()) {
                if group.len() == MAX_GROUP {
                    return None;
                }
                group.push(product);
            }
        }
        next += 1;
    }
    Some(group)
}

/// One element of each cyclic subgroup of `group` (step 4), largest order first, at most
/// [`MAX_CHOICES`]; the identity is left out. The orders come from the cycle lengths, and
/// only the chosen elements' powers are listed, so the cost is O(|G|·n) steps.
fn cyclic_choices(group: Vec<Permutation>, meter: &mut Meter) -> Vec<Permutation> {
    let n = group.first().map_or(0, Vec::len) as u64;
    if !meter.spend(group.len() as u64 * 2 * n) {
        return Vec::new();
    }
    let index: HashMap<&Permutation, usize> =
        group.iter().enumerate().map(|(i, g)| (g, i)).collect();
    let order: Vec<usize> = group.iter().map(|g| order_of(g)).collect();
    let mut by_order: Vec<usize> = (1..group.len()).collect();
    // Stable: equal orders keep the closure's order.
    by_order.sort_by_key(|&i| std::cmp::Reverse(order[i]));
    let mut covered = vec![false; group.len()];
    let mut choices: Vec<usize> = Vec::new();
    for i in by_order {
        if choices.len() == MAX_CHOICES {
            break;
        }
        if covered[i] {
            continue;
        }
        // gᵏ generates ⟨g⟩ exactly when k is prime to the order: those are covered by g.
        let g = &group[i];
        let mut power = g.clone();
        for k in 1..order[i] {
            if !meter.spend(3 * n) {
                return choices.into_iter().map(|j| group[j].clone()).collect();
            }
            if gcd(k, order[i]) == 1 {
                covered[index[&power]] = true;
            }
            power = power.iter().map(|&v| g[v as usize]).collect();
        }
        choices.push(i);
    }
    choices.into_iter().map(|j| group[j].clone()).collect()
}

/// The order of a permutation: the least common multiple of its cycle lengths.
fn order_of(image: &[u32]) -> usize {
    let mut seen = vec![false; image.len()];
    let mut order = 1;
    for start in 0..image.len() {
        let mut length = 0;
        let mut v = start;
        while !seen[v] {
            seen[v] = true;
            v = image[v] as usize;
            length += 1;
        }
        if length > 0 {
            order = order / gcd(order, length) * length;
        }
    }
    order
}

fn gcd(a: usize, b: usize) -> usize {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::NoCount;
    use crate::gen::{graph, GraphKind, Rng};
    use crate::graph::colouring::budget::Budget;
    use crate::graph::Graph;

    fn generated(kind: GraphKind, n: usize) -> Graph {
        Graph::from_edge_list(&graph(kind, n, 0, 0).unwrap()).unwrap()
    }

    /// The whole graph as a core (no vertex has fewer than 0 neighbours).
    fn core_of(g: &Graph) -> Core {
        Core::new(g, 0, &mut NoCount)
    }

    fn adjacency(core: &Core) -> impl Fn(usize, usize) -> bool + '_ {
        |u, v| core.neighbours(u).contains(&(v as u32))
    }

    fn is_automorphism(core: &Core, image: &[u32]) -> bool {
        let mut sorted = image.to_vec();
        sorted.sort_unstable();
        let bijective = sorted.iter().enumerate().all(|(i, &v)| i as u32 == v);
        let adjacent = adjacency(core);
        bijective
            && (0..core.len()).all(|v| {
                (0..core.len())
                    .all(|u| adjacent(u, v) == adjacent(image[u] as usize, image[v] as usize))
            })
    }

    fn generators_of(core: &Core) -> Vec<Permutation> {
        let mut meter = Meter::new(&Budget::steps(u64::MAX));
        let adjacent = adjacency(core);
        let mut finder = Finder {
            core,
            adjacent: &adjacent,
            meter: &mut meter,
            nodes: 0,
        };
        finder
            .generators()
            .unwrap_or_else(|_| panic!("no limit hit"))
    }

    fn group_order(core: &Core) -> Option<usize> {
        let mut meter = Meter::new(&Budget::steps(u64::MAX));
        closure(&generators_of(core), core.len(), &mut meter).map(|group| group.len())
    }

    /// The number of automorphisms of `core`, by trying every permutation.
    fn brute_force_order(core: &Core) -> usize {
        fn extend(core: &Core, image: &mut Vec<u32>, used: &mut [bool]) -> usize {
            let v = image.len();
            if v == core.len() {
                return 1;
            }
            let mut count = 0;
            for w in 0..core.len() {
                // Edges to the vertices already mapped must map to edges, non-edges to
                // non-edges.
                let consistent = (0..v).all(|u| {
                    core.neighbours(u).contains(&(v as u32))
                        == core.neighbours(image[u] as usize).contains(&(w as u32))
                });
                if !used[w] && consistent {
                    used[w] = true;
                    image.push(w as u32);
                    count += extend(core, image, used);
                    image.pop();
                    used[w] = false;
                }
            }
            count
        }
        extend(core, &mut Vec::new(), &mut vec![false; core.len()])
    }

    #[test]
    fn the_generators_generate_the_whole_group_of_small_graphs() {
        let mut rng = Rng::new(0xA07);
        let mut nontrivial = 0;
        for case in 0..400 {
            let n = 1 + rng.index(7);
            let density = rng.index(11);
            let mut edges = Vec::new();
            for u in 0..n {
                for v in u + 1..n {
                    if rng.index(10) < density {
                        edges.push([u, v]);
                    }
                }
            }
            let g = Graph::from_edges(n, &edges).unwrap();
            let core = core_of(&g);
            let generators = generators_of(&core);
            assert!(
                generators.iter().all(|p| is_automorphism(&core, p)),
                "case {case}"
            );
            let expected = brute_force_order(&core);
            // Groups larger than the closure lists are not listed.
            let listed = (expected <= MAX_GROUP).then_some(expected);
            assert_eq!(group_order(&core), listed, "case {case}: {edges:?}");
            nontrivial += usize::from(expected > 1);
        }
        assert!(nontrivial > 100, "{nontrivial}");
    }

    #[test]
    fn the_groups_of_named_graphs() {
        let petersen = generated(GraphKind::Petersen, 10);
        assert_eq!(group_order(&core_of(&petersen)), Some(120));
        for n in [5, 9, 16] {
            // The dihedral group of the n-gon.
            let cycle = generated(GraphKind::Cycle, n);
            assert_eq!(group_order(&core_of(&cycle)), Some(2 * n), "C{n}");
        }
        for side in [5, 6, 7, 8, 13] {
            // The board's rotations and reflections.
            let queen = generated(GraphKind::Queen, side);
            assert_eq!(group_order(&core_of(&queen)), Some(8), "queen{side}");
        }
        // K₆ has 720 automorphisms, more than the closure lists.
        let complete = generated(GraphKind::Complete, 6);
        assert_eq!(group_order(&core_of(&complete)), None);
    }

    #[test]
    fn the_choices_generate_distinct_cyclic_subgroups_largest_first() {
        for (g, first_order, choices) in [
            // D₅: the rotations, and five reflections.
            (generated(GraphKind::Cycle, 5), 5, 6),
            // D₄: the quarter turn, the half turn, and four reflections.
            (generated(GraphKind::Queen, 7), 4, 6),
            // S₅ has elements of order 6 and more cyclic subgroups than are kept.
            (generated(GraphKind::Petersen, 10), 6, MAX_CHOICES),
        ] {
            let core = core_of(&g);
            let mut meter = Meter::new(&Budget::steps(u64::MAX));
            let chosen = automorphisms(&core, &adjacency(&core), &mut meter);
            assert_eq!(chosen.len(), choices);
            let mut subgroups: Vec<Vec<Permutation>> = Vec::new();
            for image in &chosen {
                assert!(is_automorphism(&core, image));
                let mut powers = vec![image.clone()];
                while powers
                    .last()
                    .unwrap()
                    .iter()
                    .enumerate()
                    .any(|(i, &v)| i as u32 != v)
                {
                    let next = powers
                        .last()
                        .unwrap()
                        .iter()
                        .map(|&v| image[v as usize])
                        .collect();
                    powers.push(next);
                }
                powers.sort();
                assert!(!subgroups.contains(&powers), "a subgroup chosen twice");
                subgroups.push(powers);
            }
            let orders: Vec<usize> = subgroups.iter().map(Vec::len).collect();
            assert_eq!(orders[0], first_order, "{orders:?}");
            assert!(orders.windows(2).all(|w| w[0] >= w[1]), "{orders:?}");
        }
    }

    #[test]
    fn graphs_without_symmetry_and_an_empty_budget_give_no_choices() {
        // A triangle 0–1–4 with the path 1–2–3 hanging off vertex 1: swapping 0 and 4 is the
        // only symmetry.
        let g = Graph::from_edges(5, &[[0, 1], [1, 2], [2, 3], [1, 4], [4, 0]]).unwrap();
        let core = core_of(&g);
        let mut meter = Meter::new(&Budget::steps(u64::MAX));
        assert_eq!(brute_force_order(&core), 2);
        assert_eq!(automorphisms(&core, &adjacency(&core), &mut meter).len(), 1);
        let asymmetric = Graph::from_edges(6, &[[0, 1], [1, 2], [2, 3], [3, 4], [2, 5], [5, 1]]);
        let core = core_of(&asymmetric.unwrap());
        assert_eq!(brute_force_order(&core), 1);
        assert!(automorphisms(&core, &adjacency(&core), &mut meter).is_empty());
        let queen = core_of(&generated(GraphKind::Queen, 7));
        let mut broke = Meter::new(&Budget::steps(0));
        assert!(automorphisms(&queen, &adjacency(&queen), &mut broke).is_empty());
    }
}
