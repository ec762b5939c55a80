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
    ///
    /// Bottom-up (Floyd's, Wegener's "bottom-up heapsort" trick): the hole left at the root
    /// goes down the path of smaller children to a leaf, one comparison per level (of the
    /// two children), and the last item then climbs from there while its parent is not
    /// less than it. The last item is usually among the largest, so it climbs little: about
    /// lg n + O(1) comparisons instead of the 2 lg n of the top-down sift, which compares
    /// the item with the smaller child at every level as well.
    ///
    /// The layout is the top-down sift's: along the path the items are sorted, and the
    /// item stops above every path item it is not less than, exactly where "go down while
    /// the smaller child is less than it" stops. So pops come out in the same order, ties
    /// included.
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
                // Without a branch on the answer when `less` has none (the choice between
                // two children is a coin toss for the branch predictor).
                child += usize::from(less(&self.items[left + 1], &self.items[left]));
            }
            self.items[i] = self.items[child];
            i = child;
        }
        while i > 0 {
            let parent = (i - 1) / 2;
            c.comparison();
            if less(&self.items[parent], &last) {
                break;
            }
            self.items[i] = self.items[parent];
            i = parent;
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

    /// The top-down sift of the earlier `pop`, as the reference for the layout.
    fn pop_top_down(
        items: &mut Vec<(u32, u32)>,
        less: impl Fn(&(u32, u32), &(u32, u32)) -> bool,
    ) -> Option<(u32, u32)> {
        let last = items.pop()?;
        if items.is_empty() {
            return Some(last);
        }
        let top = items[0];
        let n = items.len();
        let mut i = 0;
        loop {
            let left = 2 * i + 1;
            if left >= n {
                break;
            }
            let mut child = left;
            if left + 1 < n && less(&items[left + 1], &items[left]) {
                child = left + 1;
            }
            if !less(&items[child], &last) {
                break;
            }
            items[i] = items[child];
            i = child;
        }
        items[i] = last;
        Some(top)
    }

    #[test]
    fn bottom_up_pop_keeps_the_top_down_layout_with_ties() {
        // Keys with many ties, told apart by a payload the order ignores: the heap must
        // end in the same layout, so equal keys come out in the same order.
        let less = |a: &(u32, u32), b: &(u32, u32)| a.0 < b.0;
        let mut h = Heap::with_capacity(0);
        let mut reference = Vec::new();
        let mut c = Counts::default();
        let mut x = 12345u32;
        for round in 0..3000u32 {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            if x % 3 == 0 && !h.items.is_empty() {
                let got = h.pop(less, &mut c);
                assert_eq!(got, pop_top_down(&mut reference, less));
            } else {
                let item = (x % 7, round);
                h.push(item, less, &mut c);
                // The push is shared: mirror it on the reference.
                let mut r = Heap {
                    items: std::mem::take(&mut reference),
                };
                r.push(item, less, &mut Counts::default());
                reference = r.items;
            }
            assert_eq!(h.items, reference);
        }
    }

    #[test]
    fn bottom_up_pop_saves_comparisons() {
        // Heapsort of a permutation: pops take about lg n comparisons each, not 2 lg n.
        let n = 1 << 12;
        let mut h = Heap::with_capacity(n);
        let mut none = Counts::default();
        for i in 0..n as u64 {
            h.push((i * 2654435761) % n as u64, |a, b| a < b, &mut none);
        }
        let mut c = Counts::default();
        let mut out = Vec::new();
        while let Some(k) = h.pop(|a, b| a < b, &mut c) {
            out.push(k);
        }
        assert!(out.windows(2).all(|w| w[0] < w[1]));
        // 12 levels: the top-down sift takes close to 2 * 12 per pop.
        assert!(c.comparisons <= 15 * n as u64, "{}", c.comparisons);
    }
}
