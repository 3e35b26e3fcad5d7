//! A counting sort: items put in numbered buckets in one pass each way, each bucket keeping the
//! items' order. The placer's obstacle grid sorts its entries into cells with it, and its
//! whole-drawing search its spots into rings of distance.

/// The `value` of each of `items`, sorted by the item's `bucket` (from 0 to `buckets - 1`),
/// stably, and where each bucket starts among them (one start per bucket, then the end).
pub(crate) fn sorted<T, U: Copy>(
    items: &[T],
    buckets: usize,
    bucket: impl Fn(&T) -> usize,
    value: impl Fn(&T) -> U,
) -> (Vec<U>, Vec<usize>) {
    let mut starts = vec![0_usize; buckets + 1];
    for item in items {
        starts[bucket(item) + 1] += 1;
    }
    for i in 0..buckets {
        starts[i + 1] += starts[i];
    }
    let mut next = starts.clone();
    // Every place is written once below; the values in order only give the vector its length.
    let mut out: Vec<U> = items.iter().map(&value).collect();
    for item in items {
        let at = &mut next[bucket(item)];
        out[*at] = value(item);
        *at += 1;
    }
    (out, starts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_are_sorted_by_bucket_and_keep_their_order_within_one() {
        let items = [(2, 'a'), (0, 'b'), (2, 'c'), (1, 'd'), (0, 'e')];
        let (out, starts) = sorted(&items, 4, |&(b, _)| b, |&item| item);
        assert_eq!(out, [(0, 'b'), (0, 'e'), (1, 'd'), (2, 'a'), (2, 'c')]);
        assert_eq!(starts, [0, 2, 3, 5, 5]);
        let none: &[(usize, char)] = &[];
        assert_eq!(sorted(none, 2, |&(b, _)| b, |&(_, c)| c).1, [0, 0, 0]);
    }
}
