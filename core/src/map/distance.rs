//! Exact Euclidean distance transform in linear time, spec §2 "Obstacle distance".
//!
//! The algorithm is the two-phase one of Meijster, Roerdink & Hesselink ("A general algorithm
//! for computing distance transforms in linear time", 2000), which computes the same lower
//! envelope of parabolas as Felzenszwalb & Huttenlocher ("Distance Transforms of Sampled
//! Functions", 2012), with every squared distance an exact integer:
//!
//! 1. **Column phase**: `g(x, y)` = distance in cells from `(x, y)` to the nearest obstacle in
//!    its own column. Two sweeps (down, then up) done row by row, so the inner loop runs along
//!    memory and vectorises.
//! 2. **Row phase**: for each row, `d²(x, y) = min over x' of (x − x')² + g(x', y)²`. Either
//!    the lower envelope of one parabola per column, found in one pass with a stack (integer
//!    parabolas; the intersection's floor by one exact `f64` division, see [`floor_div`]), or,
//!    for rows whose distances are small, a bounded sideways scan ([`row_scan`]) that is
//!    cheaper there. Both are exact, so the choice only changes the time.
//!
//! Metres are `√d² · GridSize` (`f64::sqrt`, correctly rounded on every target), through a table for small `d²`.
//!
//! Everything outside the map is obstacle (spec §2), so the transform sees a virtual ring of
//! obstacle cells around the map: in the column phase the rows `y = −1` and `y = height`, in
//! the row phase the columns `x = −1` and `x = width`. Distances are therefore always finite
//! and at most half the map's smaller side (plus one).
//!
//! The row phase of a row depends only on that row of `g`, and `g` of a column only on that
//! column's cells. That is what makes the exact *incremental* update after `MapUpdate` simple
//! ([`DistanceField::update_cells`]): recompute `g` for the changed columns, then the row phase
//! for exactly the rows where some `g` changed. `g` is therefore kept with the distances from
//! the map's load on, so the first edit costs what any other does.

use super::grid_map::CellRect;

/// The obstacle distances of a map, and what is needed to keep them current.
///
/// Invariants: `distance` is the full transform of the current cells in metres; `column` is
/// their column phase (`width · height` entries, 4 bytes a cell: made with the distances at
/// the map's load, so that no `MapUpdate` — on a large map, the first stroke of the brush —
/// has to make it).
#[derive(Debug, Clone)]
pub(crate) struct DistanceField {
    /// Phase 1: cells from each cell to the nearest obstacle in its column (virtual rows
    /// `−1` and `height` included), x fastest.
    column: Vec<u32>,
    /// Obstacle distance in metres, x fastest.
    distance: Vec<f64>,
    /// `d²` → metres for this map's grid size (kept: a `MapUpdate` reuses it).
    metres: Metres,
}

/// Equal when the distances are equal: the column phase and the metre table follow from the
/// cells and the grid size.
impl PartialEq for DistanceField {
    fn eq(&self, other: &Self) -> bool {
        self.distance == other.distance
    }
}

/// One parabola of the lower envelope: it is the lowest from position `start` on; its apex
/// is at position `site`, height `g2` (the site column's squared distance).
#[derive(Debug, Clone, Copy, Default)]
struct Segment {
    start: i64,
    site: i64,
    g2: i64,
}

impl Segment {
    /// Squared distance from position `x` through this site.
    #[inline]
    fn at(self, x: i64) -> i64 {
        let d = x - self.site;
        d * d + self.g2
    }
}

/// Scratch space of the row phase: the envelope (one segment per parabola), allocated once
/// per transform, not per row.
struct RowScratch {
    envelope: Vec<Segment>,
}

impl RowScratch {
    fn new(width: usize) -> Self {
        Self {
            envelope: vec![Segment::default(); width + 2],
        }
    }

    /// Row phase for one row: `g` is the row of the column phase; `emit(x, d²)` receives the
    /// exact squared distance of every cell `x` of the row, in increasing `x`.
    ///
    /// Positions are `x + 1`: position 0 and `width + 1` are the virtual obstacle columns
    /// (`g = 0`) just outside the map.
    #[inline]
    fn row(&mut self, g: &[u32], mut emit: impl FnMut(usize, u64)) {
        let w = g.len();
        let m = (w + 2) as i64;
        let env = &mut self.envelope[..w + 2];
        env[0] = Segment::default();
        let mut q = 0usize;
        for u in 1..m {
            let g2 = match g.get(u as usize - 1) {
                Some(&gu) => i64::from(gu) * i64::from(gu),
                None => 0,
            };
            let new = Segment {
                start: 0,
                site: u,
                g2,
            };
            // Pop the parabolas that u undercuts at the start of their interval.
            loop {
                let top = env[q];
                if top.at(top.start) <= new.at(top.start) {
                    // u takes over after the intersection: ⌊n / d⌋ + 1 (see below).
                    let n = u * u - top.site * top.site + g2 - top.g2;
                    let start = 1 + floor_div(n, 2 * (u - top.site));
                    if start < m {
                        q += 1;
                        env[q] = Segment { start, ..new };
                    }
                    break;
                }
                if q == 0 {
                    // u is the lowest from position 0 on.
                    env[0] = new;
                    break;
                }
                q -= 1;
            }
        }
        // Read the envelope segment by segment; only the real columns (positions 1..=w)
        // are emitted, as x = position − 1.
        let last = w as i64;
        for k in 0..=q {
            let seg = env[k];
            let from = seg.start.max(1);
            let to = if k < q { env[k + 1].start - 1 } else { last }.min(last);
            for p in from..=to {
                emit(p as usize - 1, seg.at(p) as u64);
            }
        }
    }
}

/// Rows whose column distances average at most this many cells use [`row_scan`]: its work
/// per cell is at most about the cell's distance, a few instructions each, with none of the
/// envelope's hard-to-predict branches; above it the envelope's fixed cost per cell wins.
const SCAN_LIMIT: u64 = 24;

/// Row phase by a bounded scan: from each cell `x`, look at the columns `x ± k` for
/// `k = 1, 2, …` while `k²` is below the best squared distance found (starting from the
/// cell's own column). Exact: a column at `|x − i| ≥ k` adds at least `k²`, so once `k²`
/// reaches the best nothing farther can beat it. Beyond the row's ends the virtual obstacle
/// columns count as `g = 0`.
#[inline]
fn row_scan(g: &[u32], mut emit: impl FnMut(usize, u64)) {
    for x in 0..g.len() {
        emit(x, scan_one(g, x));
    }
}

/// The row phase of one row into metres, by the cheaper of the two exact methods.
#[inline]
fn transform_row(scratch: &mut RowScratch, metres: &Metres, g: &[u32], out: &mut [f64]) {
    let total: u64 = g.iter().map(|&v| u64::from(v)).sum();
    if total <= SCAN_LIMIT * g.len() as u64 {
        row_scan(g, |x, d2| out[x] = metres.get(d2));
    } else {
        scratch.row(g, |x, d2| out[x] = metres.get(d2));
    }
}

/// `⌊n / d⌋` for `d > 0`, via one `f64` division (much faster than a 64-bit integer one) and
/// still exact here: `n` and `d` are integers of magnitude below 2^53 (`n` ≤ (width + 2)² +
/// (height + 1)² < 2^49 for at most 2^24 cells), so a quotient that is not a whole number lies
/// at least `1/d` from one, more than the division's rounding error (`|n/d| · 2^-53 < 1/d`):
/// the rounded quotient has the same floor.
#[inline]
fn floor_div(n: i64, d: i64) -> i64 {
    let q = n as f64 / d as f64;
    let t = q as i64;
    if (t as f64) > q { t - 1 } else { t }
}

/// Squared distances below this many cells² are turned into metres through a table built
/// once per transform (`√d² · GridSize` by the same formula), instead of one `sqrt` per cell;
/// the values are identical, it only saves time.
const METRE_TABLE_LEN: usize = 4096;

/// `√d² · grid_size`: the one formula for metres (spec §6: `sqrt` through `libm`).
pub(crate) fn to_metres(d2: u64, grid_size: f64) -> f64 {
    f64::sqrt(d2 as f64) * grid_size
}

/// `√d² · grid_size`, with a lookup table for the small `d²` a map can have.
#[derive(Debug, Clone, PartialEq)]
struct Metres {
    table: Vec<f64>,
    grid_size: f64,
}

impl Metres {
    /// The table for a `width × height` map: no distance exceeds half its smaller side plus
    /// one (the virtual ring), so small maps get small tables.
    fn new(width: usize, height: usize, grid_size: f64) -> Self {
        let r = (width.min(height) as u64 + 2) / 2;
        let len = (r * r * 2 + 1).min(METRE_TABLE_LEN as u64);
        Self {
            table: (0..len).map(|d2| to_metres(d2, grid_size)).collect(),
            grid_size,
        }
    }

    #[inline]
    fn get(&self, d2: u64) -> f64 {
        match self.table.get(d2 as usize) {
            Some(&v) => v,
            None => to_metres(d2, self.grid_size),
        }
    }
}

/// Phase 1 for the whole map, row by row (`cells`: x fastest, 1 = obstacle).
fn column_phase(cells: &[u8], width: usize, height: usize, column: &mut [u32]) {
    // Down sweep: distance to the nearest obstacle at or above (virtual row −1 is obstacle).
    for (g, &c) in column[..width].iter_mut().zip(&cells[..width]) {
        *g = u32::from(c == 0);
    }
    for y in 1..height {
        let (done, rest) = column.split_at_mut(y * width);
        let prev = &done[(y - 1) * width..];
        let row = &mut rest[..width];
        let crow = &cells[y * width..(y + 1) * width];
        for ((g, &p), &c) in row.iter_mut().zip(prev).zip(crow) {
            // Branch-free so the loop vectorises (c is 0 or 1).
            *g = (p + 1) * u32::from(c == 0);
        }
    }
    // Up sweep: virtual row `height` is obstacle, so the last row is at most 1.
    for g in &mut column[(height - 1) * width..height * width] {
        *g = (*g).min(1);
    }
    for y in (0..height - 1).rev() {
        let (head, tail) = column.split_at_mut((y + 1) * width);
        let row = &mut head[y * width..];
        let below = &tail[..width];
        for (g, &b) in row.iter_mut().zip(below) {
            *g = (*g).min(b + 1);
        }
    }
}

/// Phase 1 for the single column `x` into `out` (length `height`).
fn column_phase_one(cells: &[u8], width: usize, x: usize, out: &mut [u32]) {
    let mut run = 0u32;
    for (y, g) in out.iter_mut().enumerate() {
        run = if cells[x + y * width] == 1 {
            0
        } else {
            run + 1
        };
        *g = run;
    }
    run = 0;
    for g in out.iter_mut().rev() {
        run = (run + 1).min(*g);
        *g = run;
    }
}

impl DistanceField {
    /// The transform of `cells` (x fastest, 1 = obstacle; `width, height ≥ 1`), in metres
    /// with `grid_size`, and its column phase.
    pub(crate) fn new(cells: &[u8], width: usize, height: usize, grid_size: f64) -> Self {
        debug_assert_eq!(cells.len(), width * height);
        let metres = Metres::new(width, height, grid_size);
        let mut column = vec![0u32; cells.len()];
        column_phase(cells, width, height, &mut column);
        let mut distance = vec![0.0; cells.len()];
        let mut scratch = RowScratch::new(width);
        for (g, out) in column
            .chunks_exact(width)
            .zip(distance.chunks_exact_mut(width))
        {
            transform_row(&mut scratch, &metres, g, out);
        }
        Self {
            column,
            distance,
            metres,
        }
    }

    /// The whole transform again, in place. Returns the rectangle of the cells whose
    /// distance changed, if any did.
    fn recompute(&mut self, cells: &[u8], width: usize, height: usize) -> Option<CellRect> {
        let column = &mut self.column;
        column_phase(cells, width, height, column);
        let mut scratch = RowScratch::new(width);
        let mut row = vec![0.0; width];
        let mut changed = Changed::default();
        for (y, (g, out)) in column
            .chunks_exact(width)
            .zip(self.distance.chunks_exact_mut(width))
            .enumerate()
        {
            transform_row(&mut scratch, &self.metres, g, &mut row);
            for (x, (o, &n)) in out.iter_mut().zip(&row).enumerate() {
                if o.to_bits() != n.to_bits() {
                    *o = n;
                    changed.add(x, y);
                }
            }
        }
        changed.rect()
    }

    /// Obstacle distances in metres, x fastest.
    pub(crate) fn distances(&self) -> &[f64] {
        &self.distance
    }

    /// Brings the field up to date after the cells at flat indices `changed` (any order,
    /// duplicates allowed) changed in `cells`. Exact: the result equals
    /// [`DistanceField::new`] on the new cells. Returns the rectangle of the cells whose
    /// distance changed (`None`: none did).
    ///
    /// Bounded to what can change: `g` is recomputed for the changed columns only, and in a
    /// row where `g` changed, only the cells that the change can reach are recomputed (by
    /// the exact bounded scan of [`row_scan`], from the row's `g`). A cell `x` can change
    /// only if some changed column `c` has `(x − c)² + min(g_old(c), g_new(c))² ≤ D_old(x)`
    /// (`D` the squared distance in cells): a new nearer obstacle must beat the old
    /// distance, and a lost one must have been the nearest. With `dx` the distance from `x`
    /// to the span of changed columns and `m` the smallest such `min(g_old, g_new)²` of the
    /// row, `dx² + m ≤ D_old(x)` is therefore necessary. The scan outward from the span stops
    /// at the first `x` with `dx² > D_old(x)`: `√D_old` grows by at most 1 per cell (a
    /// distance is 1-Lipschitz) while `dx` grows by exactly 1, so no cell farther out can
    /// pass either. `D_old(x)` is read back from the metres exactly (`(d/g)²` rounds to the
    /// integer: its relative error is below 7·2⁻⁵³ and `D < 2⁴⁹`), plus one for margin.
    pub(crate) fn update_cells(
        &mut self,
        cells: &[u8],
        width: usize,
        height: usize,
        changed: &[usize],
    ) -> Option<CellRect> {
        let mut columns: Vec<usize> = changed.iter().map(|&i| i % width).collect();
        columns.sort_unstable();
        columns.dedup();
        if columns.len() * 8 > width {
            // Many columns: the row-major full recompute is cheaper than strided columns.
            return self.recompute(cells, width, height);
        }
        let column = &mut self.column;
        // Per row: the span of changed columns and the smallest min(g_old, g_new)².
        let mut rows: Vec<(u32, u32, u64)> = vec![(u32::MAX, 0, u64::MAX); height];
        let mut dirty: Vec<usize> = Vec::new();
        let mut col = vec![0u32; height];
        for &x in &columns {
            column_phase_one(cells, width, x, &mut col);
            for (y, &g) in col.iter().enumerate() {
                let old = &mut column[x + y * width];
                if *old != g {
                    let low = u64::from((*old).min(g));
                    *old = g;
                    let r = &mut rows[y];
                    if r.0 == u32::MAX {
                        dirty.push(y);
                    }
                    r.0 = r.0.min(x as u32);
                    r.1 = r.1.max(x as u32);
                    r.2 = r.2.min(low * low);
                }
            }
        }
        let grid = self.metres.grid_size;
        let mut changed_rect = Changed::default();
        let mut scratch: Option<RowScratch> = None;
        let mut fresh = Vec::new();
        for &y in &dirty {
            let (x0, x1, m) = rows[y];
            let (x0, x1) = (x0 as usize, x1 as usize);
            let g = &column[y * width..(y + 1) * width];
            let out = &mut self.distance[y * width..(y + 1) * width];
            let old_d2 = |d: f64| -> u64 {
                let q = d / grid;
                (q * q).round() as u64 + 1
            };
            // The cells to recompute, found by the outward scans.
            fresh.clear();
            for (x, &d) in out.iter().enumerate().take(x1 + 1).skip(x0) {
                if m <= old_d2(d) {
                    fresh.push(x);
                }
            }
            for x in (0..x0).rev() {
                let dx = (x0 - x) as u64;
                let d2 = old_d2(out[x]);
                if dx * dx > d2 {
                    break;
                }
                if dx * dx + m <= d2 {
                    fresh.push(x);
                }
            }
            for (x, &d) in out.iter().enumerate().skip(x1 + 1) {
                let dx = (x - x1) as u64;
                let d2 = old_d2(d);
                if dx * dx > d2 {
                    break;
                }
                if dx * dx + m <= d2 {
                    fresh.push(x);
                }
            }
            if fresh.len() * 8 > width {
                // Most of the row: the whole row by the cheaper exact method.
                let scratch = scratch.get_or_insert_with(|| RowScratch::new(width));
                let mut row = vec![0.0; width];
                transform_row(scratch, &self.metres, g, &mut row);
                for (x, (o, &n)) in out.iter_mut().zip(&row).enumerate() {
                    if o.to_bits() != n.to_bits() {
                        *o = n;
                        changed_rect.add(x, y);
                    }
                }
                continue;
            }
            for &x in &fresh {
                let n = self.metres.get(scan_one(g, x));
                if out[x].to_bits() != n.to_bits() {
                    out[x] = n;
                    changed_rect.add(x, y);
                }
            }
        }
        changed_rect.rect()
    }
}

/// The bounding rectangle of the cells whose distance changed.
#[derive(Debug, Default)]
struct Changed(Option<CellRect>);

impl Changed {
    #[inline]
    fn add(&mut self, x: usize, y: usize) {
        match &mut self.0 {
            None => {
                self.0 = Some(CellRect {
                    x0: x,
                    y0: y,
                    x1: x + 1,
                    y1: y + 1,
                })
            }
            Some(r) => {
                r.x0 = r.x0.min(x);
                r.y0 = r.y0.min(y);
                r.x1 = r.x1.max(x + 1);
                r.y1 = r.y1.max(y + 1);
            }
        }
    }

    fn rect(self) -> Option<CellRect> {
        self.0
    }
}

/// The squared distance of cell `x` of a row from its column phase `g`, by [`row_scan`]'s
/// bounded scan.
#[inline]
fn scan_one(g: &[u32], x: usize) -> u64 {
    let mut best = u64::from(g[x]) * u64::from(g[x]);
    let mut k = 1usize;
    while ((k * k) as u64) < best {
        let left = if k <= x { u64::from(g[x - k]) } else { 0 };
        let right = g.get(x + k).map_or(0, |&v| u64::from(v));
        let side = left.min(right);
        best = best.min((k * k) as u64 + side * side);
        k += 1;
    }
    best
}

/// Squared distance, in cells², from every cell's centre to the nearest obstacle cell's
/// centre, counting the ring of cells just outside the map as obstacles (spec §2). `obstacle`
/// is x fastest, `width × height`; an empty vector if the length does not match or a side is
/// 0. The metre values a [`super::GridMap`] holds are `√d² · GridSize` of these.
pub fn euclidean_distance_squared(obstacle: &[bool], width: usize, height: usize) -> Vec<f64> {
    if width == 0 || height == 0 || obstacle.len() != width * height {
        return Vec::new();
    }
    let cells: Vec<u8> = obstacle.iter().map(|&o| u8::from(o)).collect();
    let mut column = vec![0; cells.len()];
    column_phase(&cells, width, height, &mut column);
    let mut out = vec![0.0; cells.len()];
    let mut scratch = RowScratch::new(width);
    for (g, o) in column.chunks_exact(width).zip(out.chunks_exact_mut(width)) {
        scratch.row(g, |x, d2| o[x] = d2 as f64);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(obstacle: &[bool], w: usize, h: usize) -> Vec<f64> {
        let mut out = vec![f64::INFINITY; w * h];
        for y in 0..h as i64 {
            for x in 0..w as i64 {
                let mut best = f64::INFINITY;
                for oy in -1..=h as i64 {
                    for ox in -1..=w as i64 {
                        let outside = ox < 0 || oy < 0 || ox >= w as i64 || oy >= h as i64;
                        if outside || obstacle[(ox + oy * w as i64) as usize] {
                            let d = ((x - ox).pow(2) + (y - oy).pow(2)) as f64;
                            best = best.min(d);
                        }
                    }
                }
                out[(x + y * w as i64) as usize] = best;
            }
        }
        out
    }

    /// Both row methods equal the row formula on random rows, short and long distances.
    #[test]
    fn envelope_and_scan_agree_with_the_formula() {
        let mut seed = 777u64;
        let mut next = |n: u64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) % n
        };
        let mut scratch = RowScratch::new(300);
        for _ in 0..400 {
            let w = 1 + next(300) as usize;
            let top = [1, 3, 30, 400][next(4) as usize];
            let g: Vec<u32> = (0..w).map(|_| next(top + 1) as u32).collect();
            let formula: Vec<u64> = (0..w as i64)
                .map(|x| {
                    // Sites: the columns, and the virtual obstacles at −1 and w.
                    let mut best = ((x + 1) * (x + 1)).min((w as i64 - x).pow(2)) as u64;
                    for (i, &gi) in g.iter().enumerate() {
                        let d = (x - i as i64).unsigned_abs();
                        best = best.min(d * d + u64::from(gi) * u64::from(gi));
                    }
                    best
                })
                .collect();
            let mut envelope = vec![0; w];
            scratch.row(&g, |x, d2| envelope[x] = d2);
            let mut scan = vec![0; w];
            row_scan(&g, |x, d2| scan[x] = d2);
            assert_eq!(envelope, formula, "{g:?}");
            assert_eq!(scan, formula, "{g:?}");
        }
    }

    #[test]
    fn matches_brute_force_on_small_maps() {
        let mut seed = 12345u64;
        for (w, h) in [
            (1, 1),
            (3, 1),
            (1, 4),
            (7, 5),
            (13, 9),
            (20, 20),
            (70, 3),
            (5, 90),
        ] {
            for density in [0u64, 5, 30, 90] {
                let obstacle: Vec<bool> = (0..w * h)
                    .map(|_| {
                        seed = seed
                            .wrapping_mul(6364136223846793005)
                            .wrapping_add(1442695040888963407);
                        (seed >> 33) % 100 < density
                    })
                    .collect();
                let expected = brute(&obstacle, w, h);
                assert_eq!(
                    euclidean_distance_squared(&obstacle, w, h),
                    expected,
                    "{w}x{h} density {density}"
                );
                let cells: Vec<u8> = obstacle.iter().map(|&o| u8::from(o)).collect();
                let field = DistanceField::new(&cells, w, h, 0.25);
                let metres: Vec<f64> = expected
                    .iter()
                    .map(|&d2| to_metres(d2 as u64, 0.25))
                    .collect();
                assert_eq!(field.distances(), &metres[..]);
            }
        }
    }
}
