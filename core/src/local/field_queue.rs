//! The potential field's Dijkstra queue: entries keyed by the bit pattern of their
//! non-negative `f64` potential (which orders as the value), taken out in increasing key
//! and, among equal keys, in the order they were put in (spec §3 step 4: "ties by insertion
//! order"). Each entry carries the cell's path length `L`, so a finalized cell is expanded
//! without reading its record back from memory.
//!
//! A bucket queue. The bucket of a key is its top bits (`key >> SHIFT`: sign, exponent and
//! the top [`MANTISSA_BITS`] mantissa bits), so buckets are ordered as their keys and each
//! spans a relative width of 2⁻¹²:
//!
//! - the *current* bucket (the one the last key taken came from) is kept sorted, the next
//!   entry at the end; an entry put into it (rare: an increment below 0.02 % of the
//!   potential) is inserted in place;
//! - the next [`NEAR`] buckets (one octave of potentials) are plain vectors in a ring,
//!   with a bit mask of the non-empty ones; an entry put there is appended, and a bucket is
//!   sorted once, when it becomes current;
//! - entries beyond (a repulsion spike next to the `dmin` zone) wait in a binary heap and
//!   move into the ring once it reaches them.
//!
//! The queue is monotone — every key put in is ≥ the last one taken out (each increment of
//! the field is positive) — which is what lets a bucket be sorted only once. Sorting is by
//! `(key, sequence number)`, the sequence number counting the entries put in: the order is
//! exactly increasing key, then insertion order, whatever the buckets.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// One queued cell: its potential's bits, its path length, its index, and its sequence
/// number (set by the queue).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Entry {
    pub key: u64,
    pub length: f64,
    pub cell: u32,
    seq: u32,
}

impl Entry {
    pub(crate) fn new(key: u64, length: f64, cell: u32) -> Self {
        Self {
            key,
            length,
            cell,
            seq: 0,
        }
    }

    #[inline(always)]
    fn order(&self) -> (u64, u32) {
        (self.key, self.seq)
    }
}

/// Mantissa bits kept in a bucket index: buckets are 2⁻¹² of their potential wide.
const MANTISSA_BITS: u32 = 10;
const SHIFT: u32 = 52 - MANTISSA_BITS;
/// Buckets in the ring after the current one: one octave.
const NEAR: usize = 1 << MANTISSA_BITS;

/// A far entry, ordered by key then sequence number (the heap gives the smallest first).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Far {
    key: u64,
    seq: u32,
    cell: u32,
    length: u64,
}

#[derive(Debug, Clone)]
pub(crate) struct FieldQueue {
    /// The current bucket, sorted by `(key, seq)` descending: the next entry last.
    current: Vec<Entry>,
    /// The current bucket's index; the ring holds buckets `cur + 1 .. cur + NEAR`.
    cur: u64,
    /// Bucket `b` of the ring at `ring[b % NEAR]`.
    ring: Vec<Vec<Entry>>,
    /// Bit `b % NEAR` set when ring bucket `b` is non-empty.
    mask: Vec<u64>,
    far: BinaryHeap<Reverse<Far>>,
    /// The next sequence number.
    seq: u32,
    len: usize,
}

impl Default for FieldQueue {
    fn default() -> Self {
        Self {
            current: Vec::new(),
            cur: 0,
            ring: vec![Vec::new(); NEAR],
            mask: vec![0; NEAR / 64],
            far: BinaryHeap::new(),
            seq: 0,
            len: 0,
        }
    }
}

impl FieldQueue {
    /// Empties the queue, keeping its memory; the next key may be anything.
    pub(crate) fn clear(&mut self) {
        self.current.clear();
        for (word, m) in self.mask.iter_mut().enumerate() {
            let mut bits = *m;
            while bits != 0 {
                let b = bits.trailing_zeros() as usize;
                bits &= bits - 1;
                self.ring[word * 64 + b].clear();
            }
            *m = 0;
        }
        self.far.clear();
        self.cur = 0;
        self.seq = 0;
        self.len = 0;
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Puts `e` in. Its key must be ≥ the last key taken out (if it is not, it is queued
    /// in the current bucket all the same, so nothing is ever lost).
    #[inline(always)]
    pub(crate) fn push(&mut self, mut e: Entry) {
        // Potentials are ≥ 0: the sign bit is clear (cleared anyway).
        e.key &= u64::MAX >> 1;
        e.seq = self.seq;
        self.seq = self.seq.wrapping_add(1);
        self.len += 1;
        let b = e.key >> SHIFT;
        if b <= self.cur {
            // After every entry of a smaller key or an equal key (those are older).
            let at = self.current.partition_point(|x| x.key > e.key);
            self.current.insert(at, e);
        } else if b - self.cur < NEAR as u64 {
            let slot = (b as usize) % NEAR;
            self.ring[slot].push(e);
            self.mask[slot / 64] |= 1 << (slot % 64);
        } else {
            self.far.push(Reverse(Far {
                key: e.key,
                seq: e.seq,
                cell: e.cell,
                length: e.length.to_bits(),
            }));
        }
    }

    /// The entry with the smallest key, the earliest put in among equal keys.
    #[inline(always)]
    pub(crate) fn pop(&mut self) -> Option<Entry> {
        if self.current.is_empty() {
            self.advance()?;
        }
        self.len -= 1;
        self.current.pop()
    }

    /// The current bucket is used up: makes the next non-empty bucket current. `None` when
    /// the queue is empty.
    #[inline(never)]
    fn advance(&mut self) -> Option<()> {
        if self.len == 0 {
            return None;
        }
        let next = match self.next_in_ring() {
            Some(b) => b,
            None => {
                // The ring is empty: jump to the first far bucket and bring in what is
                // now near.
                let Reverse(first) = *self.far.peek()?;
                let b = first.key >> SHIFT;
                self.cur = b - 1;
                b
            }
        };
        // Far entries the ring now reaches (bucket < next + NEAR) move in; bucket `next`
        // is taken directly below, so those of it go to the ring's slot too.
        self.cur = next;
        while let Some(&Reverse(f)) = self.far.peek() {
            let b = f.key >> SHIFT;
            if b >= next + NEAR as u64 {
                break;
            }
            self.far.pop();
            let slot = (b as usize) % NEAR;
            self.ring[slot].push(Entry {
                key: f.key,
                length: f64::from_bits(f.length),
                cell: f.cell,
                seq: f.seq,
            });
            self.mask[slot / 64] |= 1 << (slot % 64);
        }
        let slot = (next as usize) % NEAR;
        self.mask[slot / 64] &= !(1 << (slot % 64));
        core::mem::swap(&mut self.current, &mut self.ring[slot]);
        self.current
            .sort_unstable_by_key(|e| core::cmp::Reverse(e.order()));
        Some(())
    }

    /// The first non-empty ring bucket after the current one.
    fn next_in_ring(&self) -> Option<u64> {
        let start = (self.cur as usize + 1) % NEAR;
        let words = NEAR / 64;
        // The first word from `start`'s bit on, then whole words, wrapping round, then
        // the first word's bits below `start`.
        let (w0, b0) = (start / 64, start % 64);
        let first = self.mask[w0] & (u64::MAX << b0);
        let found = if first != 0 {
            Some(w0 * 64 + first.trailing_zeros() as usize)
        } else {
            (1..=words).find_map(|k| {
                let w = (w0 + k) % words;
                let m = if k == words {
                    self.mask[w] & !(u64::MAX << b0)
                } else {
                    self.mask[w]
                };
                (m != 0).then(|| w * 64 + m.trailing_zeros() as usize)
            })
        }?;
        let distance = (found + NEAR - start) % NEAR;
        Some(self.cur + 1 + distance as u64)
    }
}

#[cfg(test)]
mod tests {
    use super::{Entry, FieldQueue};

    fn drain(q: &mut FieldQueue) -> Vec<(f64, u32)> {
        let mut out = Vec::new();
        while let Some(x) = q.pop() {
            out.push((f64::from_bits(x.key), x.cell));
        }
        out
    }

    #[test]
    fn pops_in_key_then_push_order() {
        let mut q = FieldQueue::default();
        let e = |k: f64, v: u32| Entry::new(k.to_bits(), f64::from(v), v);
        for (i, k) in [5.0f64, 1.0, 3.0, 1.0, 2.0, 3.0].iter().enumerate() {
            q.push(e(*k, i as u32));
        }
        let mut out = Vec::new();
        while let Some(x) = q.pop() {
            out.push((f64::from_bits(x.key), x.cell));
            assert_eq!(x.length, f64::from(x.cell));
            if x.cell == 1 {
                q.push(e(1.0, 10));
                q.push(e(2.0, 11));
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

    /// Against a sort by (key, insertion order), with keys near and far, equal keys and
    /// pushes between pops, over many octaves; reused after `clear`.
    #[test]
    fn equals_a_stable_sort() {
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = |m: u64| {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 33) % m
        };
        let mut q = FieldQueue::default();
        for round in 0..30 {
            q.clear();
            let mut pending: Vec<(f64, u32)> = Vec::new();
            let mut out = Vec::new();
            let mut expected = Vec::new();
            let mut last = 0.1f64;
            let mut id = 0u32;
            for _ in 0..2000 {
                for _ in 0..next(4) {
                    let inc = match next(5) {
                        0 => 0.0,
                        1 => 1e-9 * next(10) as f64,
                        2 => next(100) as f64 * 0.01,
                        3 => next(1000) as f64,
                        _ => 2f64.powi(next(40) as i32),
                    };
                    let k = last + inc * (1 + round % 3) as f64;
                    q.push(Entry::new(k.to_bits(), 0.0, id));
                    pending.push((k, id));
                    id += 1;
                }
                if let Some(x) = q.pop() {
                    // The expected next: smallest key, earliest id.
                    let (pos, _) = pending
                        .iter()
                        .enumerate()
                        .min_by(|a, b| a.1.0.total_cmp(&b.1.0).then(a.1.1.cmp(&b.1.1)))
                        .unwrap();
                    let want = pending.remove(pos);
                    expected.push(want);
                    last = f64::from_bits(x.key);
                    out.push((last, x.cell));
                }
            }
            pending.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            expected.extend(pending);
            out.extend(drain(&mut q));
            assert_eq!(out, expected, "round {round}");
        }
    }
}
