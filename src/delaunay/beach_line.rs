//! The beach line of Fortune's sweep: its arcs from left to right in a treap (a binary
//! search tree kept balanced in expectation by random heap priorities), threaded by a
//! doubly linked list for constant-time neighbours.
//!
//! The tree holds no keys: an arc's place is only defined by its neighbours (the
//! breakpoints move with the sweep), so insertion is "right after this arc" and search is a
//! descent with a caller-supplied monotone test ([`BeachLine::first_arc_where`]).
//!
//! A line made with `keep_tree` false is the list alone: insertion and removal are O(1)
//! and the search is a scan from the left. The sweep finds most arcs by short walks from
//! hints, and then the tree's rotations cost more than they save; it builds the treap
//! ([`BeachLine::build_tree`]) only when the walks overrun their budget.

use crate::gen::Rng;
use crate::geometry::Point2;

/// No arc (a null link).
pub(super) const NIL: u32 = u32::MAX;

/// One arc: the site whose parabola it belongs to, its pending circle event, and links.
#[derive(Debug, Clone, Copy)]
struct Arc {
    /// The site's coordinates, kept beside its index: the descent and the circle checks
    /// read them from the arcs, which stay in cache, instead of from the sites (a miss per
    /// access once the sites outgrow the cache).
    point: Point2,
    site: u32,
    /// The id of the circle event that would remove this arc, or [`NIL`].
    event: u32,
    /// A tag the sweep keeps for the breakpoint on this arc's left (the Voronoi edge it
    /// traces), or [`NIL`].
    edge: u32,
    prio: u32,
    left: u32,
    right: u32,
    parent: u32,
    prev: u32,
    next: u32,
}

/// The arcs in an arena, with a free list for removed slots.
#[derive(Debug)]
pub(super) struct BeachLine {
    arcs: Vec<Arc>,
    free: Vec<u32>,
    root: u32,
    /// The leftmost arc, or [`NIL`].
    first: u32,
    /// Whether the treap is kept (otherwise only the list, and `root` stays [`NIL`]).
    tree: bool,
    rng: Rng,
}

impl BeachLine {
    /// An empty beach line with room for `capacity` arcs, with the treap or (`keep_tree`
    /// false) the list alone.
    pub(super) fn new(capacity: usize, keep_tree: bool) -> BeachLine {
        BeachLine {
            arcs: Vec::with_capacity(capacity),
            free: Vec::new(),
            root: NIL,
            first: NIL,
            tree: keep_tree,
            // Any fixed seed: the priorities only need to be independent of the input.
            rng: Rng::new(0x9E37_79B9_7F4A_7C15),
        }
    }

    /// The site of arc `a`.
    #[inline]
    pub(super) fn site(&self, a: u32) -> u32 {
        self.arcs[a as usize].site
    }

    /// The coordinates of the site of arc `a` (as given to [`insert_after`](Self::insert_after)).
    #[inline]
    pub(super) fn point(&self, a: u32) -> Point2 {
        self.arcs[a as usize].point
    }

    /// The left neighbour of `a`, or [`NIL`].
    #[inline]
    pub(super) fn prev(&self, a: u32) -> u32 {
        self.arcs[a as usize].prev
    }

    /// The right neighbour of `a`, or [`NIL`].
    #[inline]
    pub(super) fn next(&self, a: u32) -> u32 {
        self.arcs[a as usize].next
    }

    /// The pending circle event of `a`, or [`NIL`].
    #[inline]
    pub(super) fn event(&self, a: u32) -> u32 {
        self.arcs[a as usize].event
    }

    /// Sets (or with [`NIL`] clears) the pending circle event of `a`.
    #[inline]
    pub(super) fn set_event(&mut self, a: u32, event: u32) {
        self.arcs[a as usize].event = event;
    }

    /// The tag of the breakpoint on the left of `a` (see [`set_edge`](Self::set_edge)).
    #[inline]
    pub(super) fn edge(&self, a: u32) -> u32 {
        self.arcs[a as usize].edge
    }

    /// Tags the breakpoint on the left of `a` (a new arc's tag is [`NIL`]).
    #[inline]
    pub(super) fn set_edge(&mut self, a: u32, edge: u32) {
        self.arcs[a as usize].edge = edge;
    }

    /// Whether `a` is a live arc (not removed, or removed and reused).
    #[inline]
    pub(super) fn is_live(&self, a: u32) -> bool {
        self.arcs[a as usize].parent != a
    }

    /// The leftmost arc, or [`NIL`] if the line is empty.
    #[inline]
    pub(super) fn first(&self) -> u32 {
        self.first
    }

    /// Whether the treap is kept (see [`new`](Self::new)).
    #[inline]
    pub(super) fn has_tree(&self) -> bool {
        self.tree
    }

    /// The sites of the arcs from left to right (for traces: O(number of arcs)).
    pub(super) fn sites_in_order(&self) -> Vec<u32> {
        let mut sites = Vec::new();
        let mut a = self.first;
        while a != NIL {
            sites.push(self.site(a));
            a = self.next(a);
        }
        sites
    }

    /// The first arc from the left for which `right_of_site` is false, given that it is
    /// true for a prefix of the arcs and false for the rest; the last arc if it is true for
    /// all. `right_of_site(a)` is called only on arcs with a right neighbour. [`NIL`] if
    /// the beach line is empty.
    ///
    /// O(log n) expected with the treap, O(n) without.
    pub(super) fn first_arc_where(&self, mut right_of_site: impl FnMut(u32) -> bool) -> u32 {
        if !self.tree {
            let mut a = self.first;
            while a != NIL && self.arcs[a as usize].next != NIL && right_of_site(a) {
                a = self.arcs[a as usize].next;
            }
            return a;
        }
        let mut node = self.root;
        let mut found = NIL;
        while node != NIL {
            let arc = &self.arcs[node as usize];
            if arc.next == NIL || !right_of_site(node) {
                found = node;
                node = arc.left;
            } else {
                node = arc.right;
            }
        }
        found
    }

    /// Inserts a new arc of `site`, at `point`, right after `after` ([`NIL`]: into the empty
    /// beach line) and returns it.
    pub(super) fn insert_after(&mut self, after: u32, site: u32, point: Point2) -> u32 {
        let prio = if self.tree { self.next_priority() } else { 0 };
        let arc = Arc {
            point,
            site,
            event: NIL,
            edge: NIL,
            prio,
            left: NIL,
            right: NIL,
            parent: NIL,
            prev: after,
            next: NIL,
        };
        let new = match self.free.pop() {
            Some(slot) => {
                self.arcs[slot as usize] = arc;
                slot
            }
            None => {
                self.arcs.push(arc);
                (self.arcs.len() - 1) as u32
            }
        };
        if after == NIL {
            debug_assert_eq!(
                self.first, NIL,
                "insertion at the front of a non-empty line"
            );
            self.first = new;
            if self.tree {
                self.root = new;
            }
            return new;
        }
        let next = self.arcs[after as usize].next;
        self.arcs[new as usize].next = next;
        if next != NIL {
            self.arcs[next as usize].prev = new;
        }
        self.arcs[after as usize].next = new;
        if !self.tree {
            return new;
        }
        // In order, `new` comes right after `after`: as its right child, or as the left
        // child of the leftmost node of its right subtree.
        let right = self.arcs[after as usize].right;
        if right == NIL {
            self.arcs[after as usize].right = new;
            self.arcs[new as usize].parent = after;
        } else {
            let mut leftmost = right;
            while self.arcs[leftmost as usize].left != NIL {
                leftmost = self.arcs[leftmost as usize].left;
            }
            self.arcs[leftmost as usize].left = new;
            self.arcs[new as usize].parent = leftmost;
        }
        while self.arcs[new as usize].parent != NIL
            && self.arcs[self.arcs[new as usize].parent as usize].prio < prio
        {
            self.rotate_up(new);
        }
        new
    }

    /// Builds the treap over the list (a line made without it; a no-op otherwise): random
    /// priorities in list order, and the Cartesian tree of the sequence with a stack, in
    /// O(number of arcs). The line keeps the treap from then on.
    pub(super) fn build_tree(&mut self) {
        if self.tree {
            return;
        }
        self.tree = true;
        let mut stack: Vec<u32> = Vec::new();
        let mut a = self.first;
        while a != NIL {
            let prio = self.next_priority();
            let node = &mut self.arcs[a as usize];
            (node.prio, node.left, node.right, node.parent) = (prio, NIL, NIL, NIL);
            // The arcs popped have lower priorities: they become `a`'s left subtree.
            let mut last = NIL;
            while let Some(&top) = stack.last() {
                if self.arcs[top as usize].prio >= prio {
                    break;
                }
                last = stack.pop().expect("the stack has a top");
            }
            if last != NIL {
                self.arcs[a as usize].left = last;
                self.arcs[last as usize].parent = a;
            }
            if let Some(&top) = stack.last() {
                self.arcs[top as usize].right = a;
                self.arcs[a as usize].parent = top;
            }
            stack.push(a);
            a = self.arcs[a as usize].next;
        }
        self.root = stack.first().copied().unwrap_or(NIL);
    }

    /// Removes arc `a`; its slot may be reused by a later insertion.
    pub(super) fn remove(&mut self, a: u32) {
        if self.tree {
            self.remove_from_tree(a);
        }
        let Arc { prev, next, .. } = self.arcs[a as usize];
        if prev != NIL {
            self.arcs[prev as usize].next = next;
        }
        if next != NIL {
            self.arcs[next as usize].prev = prev;
        }
        if self.first == a {
            self.first = next;
        }
        // A removed arc is its own parent: `is_live` tells it from a live one.
        let dead = &mut self.arcs[a as usize];
        dead.parent = a;
        dead.event = NIL;
        self.free.push(a);
    }

    /// Unlinks `a` from the treap.
    fn remove_from_tree(&mut self, a: u32) {
        // Rotate `a` down to a leaf, always lifting the child of higher priority.
        loop {
            let Arc { left, right, .. } = self.arcs[a as usize];
            let child = match (left, right) {
                (NIL, NIL) => break,
                (c, NIL) | (NIL, c) => c,
                (l, r) => {
                    if self.arcs[l as usize].prio > self.arcs[r as usize].prio {
                        l
                    } else {
                        r
                    }
                }
            };
            self.rotate_up(child);
        }
        let parent = self.arcs[a as usize].parent;
        if parent == NIL {
            self.root = NIL;
        } else if self.arcs[parent as usize].left == a {
            self.arcs[parent as usize].left = NIL;
        } else {
            self.arcs[parent as usize].right = NIL;
        }
    }

    /// Rotates `x` above its parent, keeping the in-order sequence.
    fn rotate_up(&mut self, x: u32) {
        let p = self.arcs[x as usize].parent;
        let g = self.arcs[p as usize].parent;
        if self.arcs[p as usize].left == x {
            let moved = self.arcs[x as usize].right;
            self.arcs[p as usize].left = moved;
            if moved != NIL {
                self.arcs[moved as usize].parent = p;
            }
            self.arcs[x as usize].right = p;
        } else {
            let moved = self.arcs[x as usize].left;
            self.arcs[p as usize].right = moved;
            if moved != NIL {
                self.arcs[moved as usize].parent = p;
            }
            self.arcs[x as usize].left = p;
        }
        self.arcs[p as usize].parent = x;
        self.arcs[x as usize].parent = g;
        if g == NIL {
            self.root = x;
        } else if self.arcs[g as usize].left == p {
            self.arcs[g as usize].left = x;
        } else {
            self.arcs[g as usize].right = x;
        }
    }

    /// A pseudo-random priority.
    fn next_priority(&mut self) -> u32 {
        (self.rng.next_u64() >> 32) as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sites from the leftmost arc along the list, checked against an in-order walk
    /// of the tree, with every parent link and heap priority checked on the way.
    fn sequence(line: &BeachLine) -> Vec<u32> {
        fn walk(line: &BeachLine, node: u32, parent: u32, out: &mut Vec<u32>) {
            if node == NIL {
                return;
            }
            let arc = line.arcs[node as usize];
            assert_eq!(arc.parent, parent);
            if parent != NIL {
                assert!(line.arcs[parent as usize].prio >= arc.prio);
            }
            walk(line, arc.left, node, out);
            out.push(node);
            walk(line, arc.right, node, out);
        }
        let mut listed = Vec::new();
        let mut a = line.first;
        if a != NIL {
            assert_eq!(line.prev(a), NIL);
        }
        while a != NIL {
            listed.push(a);
            a = line.next(a);
        }
        if line.has_tree() {
            let mut in_order = Vec::new();
            walk(line, line.root, NIL, &mut in_order);
            assert_eq!(in_order, listed);
        } else {
            assert_eq!(line.root, NIL);
        }
        let sites: Vec<u32> = listed.iter().map(|&a| line.site(a)).collect();
        assert_eq!(line.sites_in_order(), sites);
        sites
    }

    #[test]
    fn insertions_and_removals_match_a_vec() {
        for keep_tree in [true, false] {
            mirror_on_a_vec(keep_tree);
        }
    }

    /// A deterministic mix of operations, mirrored on a plain Vec of (arc, site).
    fn mirror_on_a_vec(keep_tree: bool) {
        let mut line = BeachLine::new(0, keep_tree);
        let mut model: Vec<(u32, u32)> = Vec::new();
        let mut rng = Rng::new(12345);
        let mut rand = |m: usize| rng.index(m);
        for step in 0..3000u32 {
            if model.is_empty() || rand(3) > 0 {
                let (at, after) = if model.is_empty() {
                    (0, NIL)
                } else {
                    let k = rand(model.len());
                    (k + 1, model[k].0)
                };
                let at_step = Point2::new(step as f64, 0.5);
                let a = line.insert_after(after, step, at_step);
                assert!(line.is_live(a));
                assert_eq!(line.point(a), at_step);
                model.insert(at, (a, step));
            } else {
                let k = rand(model.len());
                let (a, _) = model.remove(k);
                line.remove(a);
                assert!(!line.is_live(a));
            }
            if step == 1500 {
                line.build_tree();
                assert!(line.has_tree());
            }
            if step % 97 == 0 {
                let want: Vec<u32> = model.iter().map(|&(_, s)| s).collect();
                assert_eq!(sequence(&line), want);
            }
        }
        let want: Vec<u32> = model.iter().map(|&(_, s)| s).collect();
        assert_eq!(sequence(&line), want);
    }

    #[test]
    fn search_finds_the_first_arc_failing_a_monotone_test() {
        for keep_tree in [true, false] {
            search_in(keep_tree);
        }
    }

    fn search_in(keep_tree: bool) {
        let mut line = BeachLine::new(0, keep_tree);
        let mut last = NIL;
        let mut arcs = Vec::new();
        for site in 0..200 {
            last = line.insert_after(last, site, Point2::new(0.0, site as f64));
            arcs.push(last);
        }
        for threshold in 0..205 {
            let found = line.first_arc_where(|a| line.site(a) < threshold);
            let want = arcs[threshold.min(199) as usize];
            assert_eq!(found, want, "threshold {threshold}");
        }
        assert_eq!(BeachLine::new(0, keep_tree).first_arc_where(|_| true), NIL);
    }
}
