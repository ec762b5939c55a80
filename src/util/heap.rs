//! A binary min-heap whose comparisons go through the caller's counter, shared by DSatur,
//! Prim and Fortune's sweep (std's `BinaryHeap` cannot report its comparisons).

use crate::count::Counter;

/// A binary min-heap of `T` ordered by a caller-supplied "less than".
#[derive(Debug, Clone)]
pub(crate) struct Heap<T> {
    items: Vec<T>,
}

impl<T: Copy> Heap<T> {
    /// An empty heap with room for `capacity` items.
    pub(crate) fn with_capacity(capacity: usize) -> Self {
        Heap {
            items: Vec::with_capacity(capacity),
        }
    }

    /// The least item, if any, without removing it.
    pub(crate) fn peek(&self) -> Option<&T> {
        self.items.first()
    }

    /// Adds `item`: O(log len) comparisons, each counted.
    pub(crate) fn push<C: Counter>(&mut self, item: T, less: impl Fn(&T, &T) -> bool, c: &mut C) {
        let mut i = self.items.len();
        self.items.push(item);
        while i > 0 {
            let parent = (i - 1) / 2;
            c.comparison();
            if !less(&item, &self.items[parent]) {
                break;
            }
            self.items[i] = self.items[parent];
            i = parent;
        }
        self.items[i] = item;
    }

    /// Removes and returns the least item: O(log len) comparisons, each counted.
    pub(crate) fn pop<C: Counter>(
        &mut self,
        less: impl Fn(&T, &T) -> bool,
        c: &mut C,
    ) -> Option<T> {
        let last = self.items.pop()?;
        if self.items.is_empty() {
            return Some(last);
        }
        let top = self.items[0];
        let n = self.items.len();
        let mut i = 0;
        loop {
            let left = 2 * i + 1;
            if left >= n {
                break;
            }
            let mut child = left;
            if left + 1 < n {
                c.comparison();
                if less(&self.items[left + 1], &self.items[left]) {
                    child = left + 1;
                }
            }
            c.comparison();
            if !less(&self.items[child], &last) {
                break;
            }
            self.items[i] = self.items[child];
            i = child;
        }
        self.items[i] = last;
        Some(top)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::count::Counts;

    #[test]
    fn pops_in_ascending_order_and_counts_logarithmically() {
        let mut h = Heap::with_capacity(0);
        let mut c = Counts::default();
        let keys: Vec<u64> = (0..1000u64).map(|i| (i * 7919) % 1009).collect();
        for &k in &keys {
            h.push(k, |a, b| a < b, &mut c);
        }
        let mut out = Vec::new();
        while let Some(k) = h.pop(|a, b| a < b, &mut c) {
            out.push(k);
        }
        let mut sorted = keys.clone();
        sorted.sort_unstable();
        assert_eq!(out, sorted);
        // At most 3 lg n comparisons per item over a push and a pop.
        assert!(c.comparisons <= 3 * 10 * 1000, "{}", c.comparisons);
    }
}
