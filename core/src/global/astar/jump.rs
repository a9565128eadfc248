//! The jump-point search of [`super::AStar::plan`]: the passable cells as bit lines (rows
//! and, transposed, columns), straight runs 64 cells a step, diagonal runs, and A* over the
//! jump points they find (see the parent module's documentation).

use super::{CLOSED, Costs, GENERATION_MASK, Key, MOVE_MASK, PASSABLE, Scratch, Search};
use crate::map::Cell;

/// The passable cells of the padded grid as bits: each row (x fastest) and each column
/// (y fastest) a line of 64-bit words, bit `i % 64` of word `i / 64` for position `i`; the
/// padding and the bits past a line's end are 0 (blocked).
#[derive(Debug, Clone)]
pub(super) struct BitLines {
    row_words: usize,
    column_words: usize,
    rows: Vec<u64>,
    columns: Vec<u64>,
}

impl BitLines {
    pub(super) fn new(width: usize, height: usize) -> Self {
        let (row_words, column_words) = (width.div_ceil(64), height.div_ceil(64));
        Self {
            row_words,
            column_words,
            rows: vec![0; row_words * height],
            columns: vec![0; column_words * width],
        }
    }

    pub(super) fn set(&mut self, x: usize, y: usize, passable: bool) {
        let put = |word: &mut u64, bit: usize| {
            if passable {
                *word |= 1 << bit;
            } else {
                *word &= !(1 << bit);
            }
        };
        put(&mut self.rows[y * self.row_words + x / 64], x % 64);
        put(&mut self.columns[x * self.column_words + y / 64], y % 64);
    }

    fn row(&self, y: usize) -> &[u64] {
        &self.rows[y * self.row_words..(y + 1) * self.row_words]
    }

    fn column(&self, x: usize) -> &[u64] {
        &self.columns[x * self.column_words..(x + 1) * self.column_words]
    }
}

/// Follows a straight line from position `from` (exclusive) in direction `forward` (or
/// backward) along bit line `line`, with the parallel lines `a` and `b` on either side;
/// returns the first position that is blocked (`None`), or else `goal` or has a forced
/// neighbour — a side cell passable where the one behind it is not. 64 positions a step;
/// the lines end in blocked positions, so it ends.
#[inline(always)]
fn run_line(
    line: &[u64],
    a: &[u64],
    b: &[u64],
    from: usize,
    forward: bool,
    goal: usize,
) -> Option<usize> {
    let word = |l: &[u64], i: usize| l.get(i).copied().unwrap_or(0);
    if forward {
        let start = from + 1;
        let mut wi = start / 64;
        let mut mask = u64::MAX << (start % 64);
        loop {
            // Side opens at i: passable at i, blocked at i − 1 (the top bit of the word
            // before carries in at bit 0).
            let opens = |l: &[u64]| {
                let v = word(l, wi);
                let before = (v << 1) | (if wi > 0 { word(l, wi - 1) >> 63 } else { 0 });
                v & !before
            };
            let blocked = !word(line, wi) & mask;
            let mut stop = blocked | ((opens(a) | opens(b)) & mask);
            if goal / 64 == wi && goal >= start {
                stop |= 1 << (goal % 64);
            }
            if stop != 0 {
                let bit = stop.trailing_zeros();
                return (blocked & (1 << bit) == 0).then_some(wi * 64 + bit as usize);
            }
            wi += 1;
            mask = u64::MAX;
        }
    } else {
        let start = from - 1;
        let mut wi = start / 64;
        let mut mask = u64::MAX >> (63 - start % 64);
        loop {
            // Side opens at i: passable at i, blocked at i + 1.
            let opens = |l: &[u64]| {
                let v = word(l, wi);
                let after = (v >> 1) | (word(l, wi + 1) << 63);
                v & !after
            };
            let blocked = !word(line, wi) & mask;
            let mut stop = blocked | ((opens(a) | opens(b)) & mask);
            if goal / 64 == wi && goal <= start {
                stop |= 1 << (goal % 64);
            }
            if stop != 0 {
                let bit = 63 - stop.leading_zeros();
                return (blocked & (1 << bit) == 0).then_some(wi * 64 + bit as usize);
            }
            wi -= 1;
            mask = u64::MAX;
        }
    }
}

impl Search<'_> {
    #[inline(always)]
    fn passable(&self, p: usize) -> bool {
        self.cells[p] & PASSABLE != 0
    }

    /// The jump point reached from padded index `p` by straight move `k` (0 E, 1 N, 2 W,
    /// 3 S), and the number of steps.
    #[inline(always)]
    fn jump_straight(&self, p: usize, k: usize, t: usize) -> Option<(usize, u32)> {
        let s = self.stride;
        let (px, py) = (p % s, p / s);
        let b = self.bits;
        if k == 0 || k == 2 {
            let goal = if t / s == py { t % s } else { usize::MAX };
            let x = run_line(b.row(py), b.row(py + 1), b.row(py - 1), px, k == 0, goal)?;
            Some((py * s + x, x.abs_diff(px) as u32))
        } else {
            let goal = if t % s == px { t / s } else { usize::MAX };
            let y = run_line(
                b.column(px),
                b.column(px + 1),
                b.column(px - 1),
                py,
                k == 1,
                goal,
            )?;
            Some((y * s + px, y.abs_diff(py) as u32))
        }
    }

    /// The jump point reached from `p` by diagonal move `k` (4 NE, 5 NW, 6 SW, 7 SE): each
    /// diagonal step needs both cells beside it passable; it stops at the goal or where a
    /// straight run along either of its components finds a jump point.
    #[inline(always)]
    fn jump_diagonal(
        &self,
        p: usize,
        k: usize,
        t: usize,
        offsets: &[isize; 8],
    ) -> Option<(usize, u32)> {
        // The straight components of diagonal 4 + j: j and (j + 1) % 4.
        let (a, b) = (k - 4, (k - 3) % 4);
        let (oa, ob) = (offsets[a], offsets[b]);
        let mut i = p;
        let mut n = 0u32;
        loop {
            if !(self.passable(i.wrapping_add_signed(oa))
                && self.passable(i.wrapping_add_signed(ob)))
            {
                return None;
            }
            i = i.wrapping_add_signed(offsets[k]);
            n += 1;
            if !self.passable(i) {
                return None;
            }
            if i == t
                || self.jump_straight(i, a, t).is_some()
                || self.jump_straight(i, b, t).is_some()
            {
                return Some((i, n));
            }
        }
    }

    /// A* over jump points from padded index `s` to `t`; returns the number of expanded
    /// jump points if the goal was reached (its arrival moves are then in the cell bytes,
    /// its parents in `scratch.parent`).
    pub(super) fn jump<K: Key>(
        &mut self,
        s: usize,
        t: usize,
        start: Cell,
        scratch: &mut Scratch<K>,
    ) -> Option<usize> {
        let n = self.cells.len();
        if scratch.parent.len() < n {
            scratch.parent.resize(n, 0);
        }
        let Costs {
            tag,
            offsets,
            straight,
            diagonal,
            heuristic,
        } = self.begin(s, start, scratch)?;
        let stride = self.stride;
        let Scratch { g, parent, open } = scratch;
        parent[s] = s as u32;
        let mut expanded = 0usize;
        while let Some((f, node)) = open.pop() {
            let p = node as usize;
            if self.cells[p] & CLOSED != 0 {
                continue;
            }
            self.cells[p] |= CLOSED;
            expanded += 1;
            if p == t {
                return Some(expanded);
            }
            let (px, py) = (p as u32 % stride as u32, p as u32 / stride as u32);
            let gp = f - heuristic.at(px - 1, py - 1);
            let pass = |o: isize| self.cells[p.wrapping_add_signed(o)] >> 7;
            // Bit k: orthogonal move k leads to a passable cell.
            let orth = pass(offsets[0])
                | pass(offsets[1]) << 1
                | pass(offsets[2]) << 2
                | pass(offsets[3]) << 3;
            // Diagonal 4 + j needs orthogonals j and (j + 1) % 4 (no corner cutting).
            let diagonals = orth & ((orth >> 1) | ((orth & 1) << 3));
            let all = orth | (diagonals << 4);
            // The directions kept, by the move that reached p.
            let mut moves = if p == s {
                all
            } else {
                let k = usize::from(self.cells[p] & MOVE_MASK);
                if k >= 4 {
                    // Diagonal 4 + j: its two components and itself.
                    let (a, b) = (k - 4, (k - 3) % 4);
                    all & ((1 << a) | (1 << b) | (1 << k))
                } else {
                    // Straight k: ahead, and each side that is forced — the cell behind it
                    // (beside the cell p was entered from) blocked — with the diagonal
                    // between ahead and that side (the diagonal between orthogonals j and
                    // j + 1 is 4 + j). Where the cell behind a side is passable, the side
                    // and the diagonal ahead of it are reached as cheaply without p.
                    let (left, right) = ((k + 1) % 4, (k + 3) % 4);
                    let behind = p.wrapping_add_signed(-offsets[k]);
                    let forced = |side: usize| {
                        self.cells[behind.wrapping_add_signed(offsets[side])] & PASSABLE == 0
                    };
                    let mut keep = 1 << k;
                    if forced(left) {
                        keep |= (1 << left) | (1 << (4 + k));
                    }
                    if forced(right) {
                        keep |= (1 << right) | (1 << (4 + right));
                    }
                    all & keep
                }
            };
            while moves != 0 {
                let k = moves.trailing_zeros() as usize;
                moves &= moves - 1;
                let found = if k < 4 {
                    self.jump_straight(p, k, t)
                } else {
                    self.jump_diagonal(p, k, t, &offsets)
                };
                let Some((m, steps)) = found else { continue };
                let step = if k < 4 { straight } else { diagonal };
                let ng = gp + K::times(step, steps);
                let c = self.cells[m];
                let reached = c & GENERATION_MASK == tag & GENERATION_MASK;
                if reached && (c & CLOSED != 0 || ng >= g[m]) {
                    continue;
                }
                self.cells[m] = tag | k as u8;
                g[m] = ng;
                parent[m] = p as u32;
                let (mx, my) = (m as u32 % stride as u32 - 1, m as u32 / stride as u32 - 1);
                // Never fails: f never decreases (consistent heuristic, exact keys).
                open.push(ng + heuristic.at(mx, my), m as u32).ok()?;
            }
        }
        None
    }
}
