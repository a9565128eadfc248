//! A monotone radix priority queue for the potential field's Dijkstra order.
//!
//! Keys are the bit patterns of non-negative `f64` potentials, which order as the values.
//! Keys popped never decrease and every key pushed is ≥ the last popped (each increment of
//! the field is positive), which is what a radix heap needs (Ahuja, Mehlhorn, Orlin, Tarjan,
//! "Faster algorithms for the shortest path problem", 1990). Bucket `b` holds keys whose
//! highest bit differing from the last popped key is bit `b − 1`; bucket 0 holds keys equal
//! to it.
//!
//! **Ties**: entries of equal key come out in push order (spec §3 step 4: "ties by
//! insertion order"). Every bucket stays in push order: a push has the newest sequence
//! number and is appended; a redistribution moves the first non-empty bucket, in order,
//! into the lower buckets, which are all empty at that moment. Bucket 0 is read from the
//! front. (The `radix-heap` crate pops equal keys last-in first-out, hence this module.)

#[derive(Debug, Clone)]
pub(crate) struct RadixQueue {
    buckets: Vec<Vec<(u64, u32)>>,
    /// Read position in bucket 0.
    head: usize,
    last: u64,
    len: usize,
}

impl Default for RadixQueue {
    fn default() -> Self {
        Self {
            buckets: vec![Vec::new(); 65],
            head: 0,
            last: 0,
            len: 0,
        }
    }
}

#[inline]
fn bucket(key: u64, last: u64) -> usize {
    64 - (key ^ last).leading_zeros() as usize
}

impl RadixQueue {
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Pushes `value` with `key`; `key` must be ≥ the last popped key (if it is not, it is
    /// treated as equal to it, so the queue never loses an entry).
    #[inline]
    pub(crate) fn push(&mut self, key: u64, value: u32) {
        let key = key.max(self.last);
        self.buckets[bucket(key, self.last)].push((key, value));
        self.len += 1;
    }

    /// The entry with the smallest key, the earliest pushed among equal keys.
    #[inline]
    pub(crate) fn pop(&mut self) -> Option<(u64, u32)> {
        if self.head == self.buckets[0].len() {
            self.buckets[0].clear();
            self.head = 0;
            let i = (1..self.buckets.len()).find(|&i| !self.buckets[i].is_empty())?;
            let moved = core::mem::take(&mut self.buckets[i]);
            let last = moved.iter().map(|e| e.0).min().unwrap_or(self.last);
            self.last = last;
            for &(k, v) in &moved {
                self.buckets[bucket(k, last)].push((k, v));
            }
            // Give the (emptied) allocation back to bucket i for reuse.
            let mut moved = moved;
            moved.clear();
            self.buckets[i] = moved;
        }
        let e = self.buckets[0][self.head];
        self.head += 1;
        self.len -= 1;
        Some(e)
    }
}

#[cfg(test)]
mod tests {
    use super::RadixQueue;

    #[test]
    fn pops_in_key_then_push_order() {
        let mut q = RadixQueue::default();
        let keys = [5.0f64, 1.0, 3.0, 1.0, 2.0, 3.0];
        for (i, k) in keys.iter().enumerate() {
            q.push(k.to_bits(), i as u32);
        }
        let mut out = Vec::new();
        while let Some((k, v)) = q.pop() {
            out.push((f64::from_bits(k), v));
            if v == 1 {
                // Monotone pushes between pops, equal to and above the last key.
                q.push(1.0f64.to_bits(), 10);
                q.push(2.0f64.to_bits(), 11);
            }
        }
        assert_eq!(
            out,
            vec![
                (1.0, 1),
                (1.0, 3),
                (1.0, 10),
                (2.0, 4),
                (2.0, 11),
                (3.0, 2),
                (3.0, 5),
                (5.0, 0)
            ]
        );
        assert!(q.is_empty());
    }
}
