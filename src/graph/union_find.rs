//! Disjoint sets with union by rank and path compression, for Kruskal and Borůvka.

/// A partition of `0..n` into disjoint sets (union–find).
///
/// Union by rank keeps every tree O(log n) deep; path compression flattens the paths
/// `find` walks. Together a sequence of m operations costs O(m α(n)), α the inverse
/// Ackermann function (below 5 for any n that fits in memory).
///
/// ```
/// use compgeo::graph::UnionFind;
///
/// let mut sets = UnionFind::new(4);
/// assert!(sets.union(0, 1));
/// assert!(sets.union(2, 1));
/// assert!(!sets.union(0, 2)); // already together
/// assert_eq!(sets.set_count(), 2);
/// assert_eq!(sets.find(2), sets.find(0));
/// assert_ne!(sets.find(3), sets.find(0));
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnionFind {
    parent: Vec<u32>,
    rank: Vec<u8>,
    sets: usize,
}

impl UnionFind {
    /// `n` singleton sets `{0}, ..., {n-1}`.
    ///
    /// # Panics
    /// If `n` exceeds `u32::MAX` (the graph types' limit is far below).
    ///
    /// # Complexity
    /// O(n) time and space.
    pub fn new(n: usize) -> Self {
        assert!(u32::try_from(n).is_ok(), "union-find of {n} elements");
        UnionFind {
            parent: (0..n as u32).collect(),
            rank: vec![0; n],
            sets: n,
        }
    }

    /// The number of elements n.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Whether there are no elements.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }

    /// The number of disjoint sets.
    pub fn set_count(&self) -> usize {
        self.sets
    }

    /// The representative of `x`'s set, compressing the path to it.
    ///
    /// # Panics
    /// If `x >= n`.
    ///
    /// # Complexity
    /// O(log n) worst case, O(α(n)) amortised.
    pub fn find(&mut self, x: usize) -> usize {
        let mut root = x;
        while self.parent[root] as usize != root {
            root = self.parent[root] as usize;
        }
        let mut y = x;
        while self.parent[y] as usize != root {
            let next = self.parent[y] as usize;
            self.parent[y] = root as u32;
            y = next;
        }
        root
    }

    /// Merges the sets of `a` and `b`; `false` if they were already one set.
    ///
    /// # Panics
    /// If `a >= n` or `b >= n`.
    ///
    /// # Complexity
    /// O(log n) worst case, O(α(n)) amortised.
    pub fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        let (low, high) = if self.rank[ra] < self.rank[rb] {
            (ra, rb)
        } else {
            (rb, ra)
        };
        self.parent[low] = high as u32;
        if self.rank[low] == self.rank[high] {
            self.rank[high] += 1;
        }
        self.sets -= 1;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::Rng;

    #[test]
    fn matches_a_naive_labelling() {
        let n = 50;
        let mut sets = UnionFind::new(n);
        let mut label: Vec<usize> = (0..n).collect();
        let mut rng = Rng::new(12345);
        for _ in 0..200 {
            let (a, b) = (rng.index(n), rng.index(n));
            let merged = label[a] != label[b];
            assert_eq!(sets.union(a, b), merged);
            if merged {
                let (from, to) = (label[b], label[a]);
                label
                    .iter_mut()
                    .filter(|l| **l == from)
                    .for_each(|l| *l = to);
            }
            for u in 0..n {
                assert_eq!(sets.find(u) == sets.find(a), label[u] == label[a]);
            }
        }
        let mut distinct = label.clone();
        distinct.sort_unstable();
        distinct.dedup();
        assert_eq!(sets.set_count(), distinct.len());
        // Union by rank keeps ranks logarithmic.
        assert!(sets.rank.iter().all(|&r| (1usize << r) <= n));
    }
}
