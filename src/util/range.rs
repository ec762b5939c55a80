//! The range of most of a set of values: what the bucket maps of Fortune's sweep and the
//! Hilbert grid of the insertion order are laid over, so that a few far values (outliers)
//! do not stretch them until all the others share one bucket or one column.

/// The values of at most about `size` of `items`, every `⌈len / size⌉`-th from the first,
/// sorted ascending (in `f64::total_cmp` order); at least one value of a non-empty set.
///
/// O(s log s) time for s = min(size, len), plus the O(s) strided reads.
pub(crate) fn sorted_sample<T>(items: &[T], size: usize, value: impl Fn(&T) -> f64) -> Vec<f64> {
    let stride = items.len().div_ceil(size.max(1)).max(1);
    let mut sample: Vec<f64> = items.iter().step_by(stride).map(value).collect();
    sample.sort_unstable_by(f64::total_cmp);
    sample
}

/// The range of most of `len` ascending values, `value(i)` the `i`-th: from the value
/// `1/cut` of the way up to the one `1/cut` of the way down, when that range is not empty
/// and the `full` range is more than `wider` times as wide; `None` otherwise (and for no
/// values), which tells the caller to keep the full range.
///
/// The widths are compared halved, so a full range wider than the doubles (from below
/// `-f64::MAX / 2` to above `f64::MAX / 2`) counts as wider rather than overflowing.
///
/// O(1) time: two reads of `value`.
pub(crate) fn range_of_most(
    len: usize,
    value: impl Fn(usize) -> f64,
    cut: usize,
    full: (f64, f64),
    wider: f64,
) -> Option<(f64, f64)> {
    if len == 0 {
        return None;
    }
    let trim = len / cut.max(1);
    let (low, high) = (value(trim), value(len - 1 - trim));
    let half_width = |(low, high): (f64, f64)| 0.5 * high - 0.5 * low;
    (low < high && half_width(full) > wider * half_width((low, high))).then_some((low, high))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sample_is_strided_sorted_and_bounded() {
        let items: Vec<f64> = (0..1000).rev().map(f64::from).collect();
        let sample = sorted_sample(&items, 64, |&v| v);
        // Every 16th item from the first: 63 of them, ascending.
        assert_eq!(sample.len(), 63);
        assert!(sample.windows(2).all(|w| w[0] < w[1]));
        assert_eq!((sample[0], sample[62]), (7.0, 999.0));
        // Fewer items than the size: every item; a zero size: one.
        assert_eq!(sorted_sample(&items[..10], 64, |&v| v).len(), 10);
        assert_eq!(sorted_sample(&items[..10], 0, |&v| v), [999.0]);
        assert!(sorted_sample(&[] as &[f64], 64, |&v| v).is_empty());
    }

    #[test]
    fn most_values_leave_out_a_few_far_ones_only() {
        let even: Vec<f64> = (0..1000).map(|i| f64::from(i) / 1000.0).collect();
        let most = |values: &[f64], wider| {
            let full = (values[0], values[values.len() - 1]);
            range_of_most(values.len(), |i| values[i], 64, full, wider)
        };
        // Spread values: no range of most.
        assert_eq!(most(&even, 2.0), None);
        // Two far values at each end: the range cut at 1/64 of the way from each end.
        let mut far = even.clone();
        far[..2].copy_from_slice(&[-1e9, -1e6]);
        far[998..].copy_from_slice(&[1e6, 1e9]);
        assert_eq!(
            most(&far, 2.0),
            Some((far[1000 / 64], far[999 - 1000 / 64]))
        );
        // Only as much wider as asked.
        let mut near = even.clone();
        near[0] = -0.5;
        near[999] = 1.5;
        assert!(most(&near, 2.0).is_some());
        assert_eq!(most(&near, 3.0), None);
        // Most values equal: nothing left after the cut.
        let mut flat = vec![0.5; 1000];
        flat[0] = -1.0;
        flat[999] = 2.0;
        assert_eq!(most(&flat, 2.0), None);
        // A full range wider than the doubles counts as wider; so does an infinite one.
        let mut huge = even.clone();
        huge[0] = -f64::MAX;
        huge[999] = f64::MAX;
        assert_eq!(most(&huge, 2.0), Some((huge[15], huge[984])));
        let full = (f64::NEG_INFINITY, f64::INFINITY);
        assert!(range_of_most(1000, |i| even[i], 64, full, 2.0).is_some());
        // Few values: the cut removes none, and the range of all is not narrower.
        assert_eq!(most(&[0.0, 1.0], 2.0), None);
        assert_eq!(
            range_of_most(0, |_| unreachable!(), 64, (0.0, 1.0), 2.0),
            None
        );
    }
}
