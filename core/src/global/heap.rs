//! The A* open list: a radix heap (Ahuja, Mehlhorn, Orlin & Tarjan, "Faster algorithms for
//! the shortest path problem", 1990) over exact integer cost keys.
//!
//! A radix heap is a *monotone* priority queue: every key added must be at least the last
//! key taken out. A* with a consistent heuristic and exact costs is exactly that: `f` never
//! decreases along an expansion (`h(p) ≤ step + h(m)`, and the keys of
//! [`OctileCost`](super::OctileCost) keep that order exactly). Bucket `i > 0` holds the
//! keys whose highest bit differing from the last key taken is bit `i − 1`; bucket 0 the
//! keys equal to it. Adding is O(1); taking the minimum empties bucket 0 first, and when it
//! is empty, finds the first non-empty bucket through a bit mask and spreads it over the
//! lower buckets (each entry moves down at most once per bit).
//!
//! Within equal keys the cell added last is taken first (bucket 0 is a stack), so the order
//! depends only on the order of insertion: deterministic (spec §6).

/// An unsigned integer key usable in [`RadixHeap`].
pub(crate) trait RadixKey: Copy + Ord + Default {
    /// Bits in the key.
    const BITS: u32;
    /// The bucket of `self` relative to the last key taken: 0 if equal, else one plus the
    /// index of the highest differing bit.
    fn bucket(self, last: Self) -> usize;
}

impl RadixKey for u64 {
    const BITS: u32 = 64;
    #[inline]
    fn bucket(self, last: Self) -> usize {
        (64 - (self ^ last).leading_zeros()) as usize
    }
}

impl RadixKey for u128 {
    const BITS: u32 = 128;
    #[inline]
    fn bucket(self, last: Self) -> usize {
        (128 - (self ^ last).leading_zeros()) as usize
    }
}

/// A monotone min-priority queue of cells (`u32`) keyed by `K`.
#[derive(Debug, Clone)]
pub(crate) struct RadixHeap<K> {
    /// `K::BITS + 1` buckets of (key, cell).
    buckets: Vec<Vec<(K, u32)>>,
    /// Bit `i − 1` set when bucket `i ≥ 1` is non-empty (buckets 1–64 in word 0, 65–128
    /// in word 1: 64-bit operations on the common `u64` keys).
    nonempty: [u64; 2],
    /// The last key taken out (every key in the heap is ≥ it).
    last: K,
}

impl<K: RadixKey> Default for RadixHeap<K> {
    fn default() -> Self {
        Self {
            buckets: (0..=K::BITS).map(|_| Vec::new()).collect(),
            nonempty: [0; 2],
            last: K::default(),
        }
    }
}

/// A key below the last one taken (the queue would no longer be monotone).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct NotMonotone;

impl<K: RadixKey> RadixHeap<K> {
    /// Empties the queue (keeping its memory); the next keys may start anywhere.
    pub(crate) fn clear(&mut self) {
        for b in &mut self.buckets {
            b.clear();
        }
        self.nonempty = [0; 2];
        self.last = K::default();
    }

    /// Adds `cell` with `key`, which must not be below the last key taken.
    #[inline]
    pub(crate) fn push(&mut self, key: K, cell: u32) -> Result<(), NotMonotone> {
        if key < self.last {
            return Err(NotMonotone);
        }
        let b = key.bucket(self.last);
        self.buckets[b].push((key, cell));
        self.mark(b);
        Ok(())
    }

    /// Takes a cell with the smallest key.
    #[inline]
    pub(crate) fn pop(&mut self) -> Option<(K, u32)> {
        if self.buckets[0].is_empty() {
            let i = if self.nonempty[0] != 0 {
                self.nonempty[0].trailing_zeros() as usize + 1
            } else if self.nonempty[1] != 0 {
                self.nonempty[1].trailing_zeros() as usize + 65
            } else {
                return None;
            };
            self.nonempty[(i - 1) / 64] &= !(1 << ((i - 1) % 64));
            let mut moving = core::mem::take(&mut self.buckets[i]);
            if moving.len() == 1 {
                // A single entry is the minimum: take it without a detour through bucket 0.
                let top = moving.pop();
                if let Some((key, _)) = top {
                    self.last = key;
                }
                self.buckets[i] = moving;
                return top;
            }
            // `moving` is non-empty: its bit was set.
            self.last = moving.iter().map(|e| e.0).min().unwrap_or(self.last);
            for &(key, cell) in &moving {
                let b = key.bucket(self.last);
                self.buckets[b].push((key, cell));
                self.mark(b);
            }
            moving.clear();
            // Keep the emptied allocation for the next time bucket i fills.
            self.buckets[i] = moving;
        }
        self.buckets[0].pop()
    }

    /// Notes that bucket `b` is non-empty.
    #[inline]
    fn mark(&mut self, b: usize) {
        if b > 0 {
            self.nonempty[(b - 1) / 64] |= 1 << ((b - 1) % 64);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pops_in_key_order_last_in_first_out_among_equals() {
        let mut q = RadixHeap::<u64>::default();
        for (k, c) in [(5u64, 1), (3, 2), (5, 3), (900, 4), (3, 5), (7, 6)] {
            q.push(k, c).unwrap();
        }
        let mut out = Vec::new();
        while let Some(e) = q.pop() {
            out.push(e);
            if e.1 == 3 {
                q.push(6, 7).unwrap();
                q.push(5, 8).unwrap();
                assert_eq!(q.push(4, 9), Err(NotMonotone));
            }
        }
        assert_eq!(
            out,
            [
                (3, 5),
                (3, 2),
                (5, 3),
                (5, 8),
                (5, 1),
                (6, 7),
                (7, 6),
                (900, 4)
            ]
        );
        let mut big = RadixHeap::<u128>::default();
        big.push(1 << 100, 1).unwrap();
        big.push(3, 2).unwrap();
        assert_eq!(big.pop(), Some((3, 2)));
        assert_eq!(big.pop(), Some((1 << 100, 1)));
        assert_eq!(big.pop(), None);
        // Monotone: nothing below the last key taken, until cleared.
        assert_eq!(big.push(1, 1), Err(NotMonotone));
        big.clear();
        big.push(1, 1).unwrap();
        big.clear();
        assert_eq!(big.pop(), None);
        big.push(0, 4).unwrap();
        assert_eq!(big.pop(), Some((0, 4)));
    }
}
