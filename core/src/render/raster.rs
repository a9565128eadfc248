//! The static raster layers, drawn pixel by pixel: occupancy, the `dmin` zone and the
//! potential-field heat map (log scale, viridis), resampled from cells to frame pixels.
//!
//! Two per-cell caches feed the raster: [`Base`] (occupancy and `dmin` colours, per map) and
//! [`Heat`] (a log-scale bin per reached cell, per field). Resampling: when a cell is smaller
//! than a pixel, a pixel shows the average colour of the cells whose centres fall in it (so a
//! one-cell wall never vanishes, it turns grey), computed as a separable box sum; when a cell
//! is larger, a pixel shows the cell under its centre, and big cells get faint grid lines.
//! Integer arithmetic and exact float operations only, so the result is the same on every
//! target (spec §6).

use super::colour::Rgba;
use super::scene::{FieldCellState, FieldView, Layers};
use super::style;
use super::view::ViewTransform;
use crate::errors::RenderError;
use crate::map::{CellRect, GridMap, MapStamp};

/// Fills the rectangle `[x0, x1) × [y0, y1)` (clipped) of an RGBA buffer with opaque `c`.
pub(crate) fn fill_rect(data: &mut [u8], width: u32, rect: (u32, u32, u32, u32), c: Rgba) {
    let (x0, y0, x1, y1) = rect;
    let width = width as usize;
    let height = data.len() / 4 / width.max(1);
    let (x0, x1) = (x0 as usize, (x1 as usize).min(width));
    let (y0, y1) = (y0 as usize, (y1 as usize).min(height));
    if x0 >= x1 {
        return;
    }
    let px = [c.r, c.g, c.b, 255];
    for y in y0..y1 {
        let row = &mut data[(y * width + x0) * 4..(y * width + x1) * 4];
        for p in row.chunks_exact_mut(4) {
            p.copy_from_slice(&px);
        }
    }
}

/// The viridis colour map, 256 entries, low potential dark violet, high yellow.
pub(crate) fn viridis() -> [Rgba; 256] {
    let mut lut = [Rgba::rgb(0, 0, 0); 256];
    for (i, c) in lut.iter_mut().enumerate() {
        let v = colorous::VIRIDIS.eval_rational(i, 256);
        *c = Rgba::rgb(v.r, v.g, v.b);
    }
    lut
}

/// Log-scale bins per octave (a factor of 2 in potential): steps of 1.1 %.
const PER_OCTAVE: i64 = 64;
/// The lowest octave binned: potentials below 2⁻⁴⁰ share bin 0.
const LOW_OCTAVE: i64 = -40;
/// Bins in all: 128 octaves, up to 2⁸⁸ (larger potentials share the last bin).
const BINS: usize = 128 * PER_OCTAVE as usize;
/// Mantissa bits that pick the sub-octave bin.
const SUB_BITS: u32 = 12;

/// `floor(64 · log2(1 + m))` for the top 12 mantissa bits `m`, made once with `libm`: a
/// potential's log bin is then bit arithmetic and one table look-up, the same on every target
/// and cheap enough for a million cells per field.
#[derive(Debug, Clone)]
pub(crate) struct LogBins {
    sub: Vec<u8>,
}

impl LogBins {
    pub fn new() -> Self {
        let n = 1usize << SUB_BITS;
        let sub = (0..n)
            .map(|j| {
                let m = (j as f64 + 0.5) / n as f64;
                libm::floor(PER_OCTAVE as f64 * libm::log2(1.0 + m)) as u8
            })
            .collect();
        Self { sub }
    }

    /// The log bin of a finite `x > 0`: `floor(64 · log2 x)` shifted to start at 2⁻⁴⁰,
    /// clamped to the table.
    fn bin(&self, x: f64) -> u16 {
        let bits = x.to_bits();
        let exponent = ((bits >> 52) & 0x7ff) as i64 - 1023;
        let octave = exponent - LOW_OCTAVE;
        if octave < 0 {
            return 0;
        }
        if octave >= (BINS as i64) / PER_OCTAVE {
            return (BINS - 1) as u16;
        }
        let j = ((bits >> (52 - SUB_BITS)) & ((1 << SUB_BITS) - 1)) as usize;
        (octave * PER_OCTAVE + i64::from(self.sub[j])) as u16
    }

    /// The potential at the lower edge of bin `b`.
    fn edge(b: usize) -> f64 {
        libm::exp2(b as f64 / PER_OCTAVE as f64 + LOW_OCTAVE as f64)
    }
}

/// The heat map of one field: a log bin per reached cell (or [`NO_HEAT`]) and the colour of
/// every bin.
#[derive(Debug, Clone)]
pub(crate) struct Heat {
    bins: Vec<u16>,
    colours: Vec<u32>,
    /// The potentials at the bottom and top of the colour scale, if any cell is reached.
    pub range: Option<HeatRange>,
}

/// The colour scale of a heat map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct HeatRange {
    /// The smallest reached potential (colour index 0).
    pub lo: f64,
    /// The potential at the top colour; larger ones share it.
    pub hi: f64,
    /// Whether some reached potentials exceed `hi`.
    pub clipped: bool,
}

/// The bin of a cell the heat map does not colour.
const NO_HEAT: u16 = u16::MAX;

/// The share of reached cells below the top of the colour scale: the highest 0.5 % (cells at
/// the edge of the `dmin` zone, where the repulsion `1/(d − dmin)²` explodes) share the top
/// colour, so a few extreme values cannot flatten the rest of the field.
const KEEP: f64 = 0.995;

impl Heat {
    /// The heat map of `field`: log scale from its smallest reached potential up to the
    /// 99.5th percentile. A reached cell whose potential is not finite and > 0 is an error.
    pub fn new(
        field: &FieldView<'_>,
        log: &LogBins,
        viridis: &[Rgba; 256],
    ) -> Result<Self, RenderError> {
        let mut bins = vec![NO_HEAT; field.state.len()];
        let mut histogram = vec![0u32; BINS];
        let (mut lo, mut hi, mut reached) = (f64::INFINITY, 0.0f64, 0u64);
        for (i, ((bin, &p), &s)) in bins
            .iter_mut()
            .zip(field.potential)
            .zip(field.state)
            .enumerate()
        {
            if s != FieldCellState::Reached {
                continue;
            }
            if !(p.is_finite() && p > 0.0) {
                return Err(RenderError::BadNumber {
                    what: "field.potential",
                    index: Some(i),
                    value: p,
                    expected: "finite and > 0 on a reached cell",
                });
            }
            lo = lo.min(p);
            hi = hi.max(p);
            reached += 1;
            *bin = log.bin(p);
            histogram[*bin as usize] += 1;
        }
        let mut colours = vec![0u32; BINS];
        if reached == 0 {
            return Ok(Self {
                bins,
                colours,
                range: None,
            });
        }
        // The top of the scale: the first bin at which KEEP of the cells are counted.
        let wanted = libm::ceil(reached as f64 * KEEP) as u64;
        let (mut count, mut top) = (0u64, BINS - 1);
        for (b, &n) in histogram.iter().enumerate() {
            count += u64::from(n);
            if count >= wanted {
                top = b;
                break;
            }
        }
        let bottom = log.bin(lo) as usize;
        let last = log.bin(hi) as usize;
        let clipped = top < last;
        let shown = (top + 1 - bottom) as u64;
        for (b, c) in colours.iter_mut().enumerate().skip(bottom) {
            let level = ((b - bottom) as u64 * 256 / shown).min(255);
            *c = viridis[level as usize].pack();
        }
        let range = HeatRange {
            lo,
            hi: if clipped { LogBins::edge(top + 1) } else { hi },
            clipped,
        };
        Ok(Self {
            bins,
            colours,
            range: Some(range),
        })
    }
}

/// Per-cell colours of the occupancy and `dmin` layers; an obstacle shown as such carries
/// [`SOLID`] so the heat map does not cover it. They follow a map's `MapUpdate`s where its
/// distances changed ([`Base::follow`]), so an edit does not recolour the whole map.
#[derive(Debug, Clone)]
pub(crate) struct Base {
    colours: Vec<u32>,
    /// The state of the map the colours show.
    stamp: MapStamp,
}

const SOLID: u32 = 1 << 24;

/// Which cells [`Base::follow`] recoloured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Recoloured {
    Nothing,
    Within(CellRect),
    All,
}

impl Base {
    pub fn new(map: &GridMap, dmin: f64, layers: &Layers) -> Self {
        let colour = Self::colouring(dmin, layers);
        let colours = map
            .cells()
            .iter()
            .zip(map.distances())
            .map(|(&c, &d)| colour(c, d))
            .collect();
        Self {
            colours,
            stamp: map.stamp(),
        }
    }

    /// Brings the colours up to `map`'s state, given that they were made for this map value
    /// (same size) with the same `dmin` and layers: recoloured where the distances changed
    /// since — a changed cell changes its own distance, so that covers every cell whose
    /// colour can differ — or everywhere when the map cannot tell where.
    pub fn follow(&mut self, map: &GridMap, dmin: f64, layers: &Layers) -> Recoloured {
        let stamp = map.stamp();
        if stamp == self.stamp {
            return Recoloured::Nothing;
        }
        let Some(changes) = map.distance_changes_since(self.stamp) else {
            *self = Self::new(map, dmin, layers);
            return Recoloured::All;
        };
        let colour = Self::colouring(dmin, layers);
        let (w, cells, distances) = (map.width(), map.cells(), map.distances());
        let mut within: Option<CellRect> = None;
        for r in changes {
            for y in r.y0..r.y1 {
                let row = y * w;
                for i in row + r.x0..row + r.x1 {
                    self.colours[i] = colour(cells[i], distances[i]);
                }
            }
            within = Some(within.map_or(r, |u| u.union(&r)));
        }
        self.stamp = stamp;
        within.map_or(Recoloured::Nothing, Recoloured::Within)
    }

    /// A cell's colour from its value and obstacle distance.
    fn colouring(dmin: f64, layers: &Layers) -> impl Fn(u8, f64) -> u32 {
        let free = style::FREE.pack();
        let zone = style::FREE.mix(style::DMIN, style::DMIN_ALPHA).pack();
        let obstacle = style::OBSTACLE.pack() | SOLID;
        let (occupancy, dmin_zone) = (layers.occupancy, layers.dmin_zone);
        move |c, d| {
            if c == 1 && occupancy {
                obstacle
            } else if dmin_zone && crate::map::within_dmin(d, dmin) {
                zone
            } else {
                free
            }
        }
    }
}

/// Pixel bounds `(x0, y0, x1, y1)`: columns `[x0, x1)`, rows `[y0, y1)`.
pub(crate) type Bounds = (u32, u32, u32, u32);

/// Which part of the map raster to draw: the pixels that show a cell of `cells` (the others
/// would come out the same if their cells did not change), and only if `fits` accepts their
/// bounds.
pub(crate) struct Region<'a> {
    pub cells: CellRect,
    pub fits: &'a dyn Fn(Bounds) -> bool,
}

/// Draws the map raster into the RGBA buffer `data` of a frame `width` pixels wide: all of
/// it, or `only` a region. Returns the bounds drawn; `None` if nothing was.
pub(crate) fn draw_map(
    data: &mut [u8],
    width: u32,
    view: &ViewTransform,
    map: &GridMap,
    base: &Base,
    heat: Option<&Heat>,
    only: Option<Region<'_>>,
) -> Option<Bounds> {
    let w = map.width();
    let colour = |i: usize| -> u32 {
        let b = base.colours[i];
        match heat {
            Some(h) if b & SOLID == 0 && h.bins[i] != NO_HEAT => h.colours[h.bins[i] as usize],
            _ => b,
        }
    };
    let cs = view.pixels_per_metre() * map.grid_size();
    let (left, top, right, bottom) = view.map_rect();
    let height = (data.len() / 4) as u32 / width.max(1);
    let mut cols = pixel_cells(left, right, cs, w, width, |i| i - left);
    let mut rows = pixel_cells(top, bottom, cs, map.height(), height, |j| {
        bottom - (j + 1.0)
    });
    // The first pixel column and row: no grid line on the map's own edge.
    let (col0, row0) = (cols.first().map(|c| c.0), rows.first().map(|r| r.0));
    if let Some(Region { cells: r, .. }) = only {
        // Pixels show contiguous, ordered cell ranges: the ones meeting the rectangle are
        // one run of columns and one of rows. Their first and last keep their own edge flag.
        cols.retain(|&(_, c0, c1, _)| c0 < r.x1 && r.x0 < c1);
        rows.retain(|&(_, r0, r1, _)| r0 < r.y1 && r.y0 < r1);
    }
    let grid = cs >= 8.0;
    // Rounded division by n as a fixed-point multiply by ⌈2³²/n⌉ (exact for these sums).
    let most = |v: &[(u32, usize, usize, bool)]| v.iter().map(|c| c.2 - c.1).max().unwrap_or(1);
    let inverse: Vec<u64> = (0..=(most(&cols) * most(&rows)) as u64)
        .map(|n| (1u64 << 32).div_ceil(n.max(1)))
        .collect();
    // Per cell column, the sums of the colour channels over the pixel row's cell rows.
    let mut acc = vec![[0u32; 3]; w];
    let (c_first, c_last) = match (cols.first(), cols.last()) {
        (Some(a), Some(b)) => (a.1, b.2),
        _ => return None,
    };
    let drawn = match (rows.first(), rows.last()) {
        (Some(a), Some(b)) => (cols[0].0, a.0, cols[cols.len() - 1].0 + 1, b.0 + 1),
        _ => return None,
    };
    if only.is_some_and(|o| !(o.fits)(drawn)) {
        return None;
    }
    for &(j, r0, r1, row_edge) in &rows {
        for a in &mut acc[c_first..c_last] {
            *a = [0; 3];
        }
        for r in r0..r1 {
            let row = r * w;
            for (c, a) in acc.iter_mut().enumerate().take(c_last).skip(c_first) {
                let v = colour(row + c);
                a[0] += v & 0xff;
                a[1] += (v >> 8) & 0xff;
                a[2] += (v >> 16) & 0xff;
            }
        }
        let line = (j * width) as usize * 4;
        let nr = (r1 - r0) as u32;
        for &(i, c0, c1, col_edge) in &cols {
            let n = nr * (c1 - c0) as u32;
            let mut c = if n == 1 {
                let a = acc[c0];
                Rgba::rgb(a[0] as u8, a[1] as u8, a[2] as u8)
            } else {
                let mut sum = [0u32; 3];
                for a in &acc[c0..c1] {
                    sum[0] += a[0];
                    sum[1] += a[1];
                    sum[2] += a[2];
                }
                let inv = inverse[n as usize];
                let avg = |s: u32| ((u64::from(s + n / 2) * inv) >> 32).min(255) as u8;
                Rgba::rgb(avg(sum[0]), avg(sum[1]), avg(sum[2]))
            };
            if grid && ((row_edge && Some(j) != row0) || (col_edge && Some(i) != col0)) {
                c = c.shade(style::GRID_SHADE);
            }
            let k = line + i as usize * 4;
            data[k..k + 4].copy_from_slice(&[c.r, c.g, c.b, 255]);
        }
    }
    Some(drawn)
}

/// For each frame pixel column (or row) whose centre lies in `[lo, hi)`: the pixel index, the
/// cell range `[c0, c1)` it shows (cells whose centres fall in it, else the cell under its
/// centre) and whether it starts a new cell. `edge(i)` is the pixel's lower edge measured
/// from the map's cell-0 side, in pixels.
fn pixel_cells(
    lo: f64,
    hi: f64,
    cs: f64,
    cells: usize,
    frame: u32,
    edge: impl Fn(f64) -> f64,
) -> Vec<(u32, usize, usize, bool)> {
    // The smallest i with i + ½ ≥ lo.
    let first = libm::ceil(lo - 0.5).max(0.0) as u32;
    let n = cells as f64;
    let clamp = |v: f64| v.clamp(0.0, n) as usize;
    let mut out = Vec::new();
    let mut previous = usize::MAX;
    let mut i = first;
    while i < frame && f64::from(i) + 0.5 < hi {
        let e = edge(f64::from(i));
        let mut c0 = clamp(libm::ceil(e / cs - 0.5));
        let mut c1 = clamp(libm::ceil((e + 1.0) / cs - 0.5));
        if c0 >= c1 {
            c0 = clamp(libm::floor((e + 0.5) / cs)).min(cells - 1);
            c1 = c0 + 1;
        }
        out.push((i, c0, c1, c0 != previous));
        previous = c0;
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_bins_are_floor_of_64_log2_within_one_bin() {
        let log = LogBins::new();
        let exact = |x: f64| (libm::floor(64.0 * libm::log2(x)) as i64 - 64 * LOW_OCTAVE) as u16;
        // Powers of two start their bins exactly.
        for e in -40..88 {
            let x = libm::exp2(f64::from(e));
            assert_eq!(log.bin(x), exact(x), "2^{e}");
        }
        let mut x = 1.3e-9;
        while x < 1e25 {
            let (b, e) = (log.bin(x), exact(x));
            assert!(b.abs_diff(e) <= 1, "{x}: {b} vs {e}");
            x *= 1.0137;
        }
        // Outside the table: clamped.
        assert_eq!(log.bin(1e-300), 0);
        assert_eq!(log.bin(1e300), (BINS - 1) as u16);
        assert_eq!(log.bin(f64::MIN_POSITIVE / 4.0), 0);
    }

    #[test]
    fn heat_levels_span_the_colour_map_and_clip_the_top_half_percent() {
        let log = LogBins::new();
        let lut = viridis();
        // 1000 reached cells from 0.1 to 100 (log-uniform), 4 extreme ones, 2 not reached.
        let mut potential: Vec<f64> = (0..1000)
            .map(|i| 0.1 * libm::pow(1000.0, f64::from(i) / 999.0))
            .collect();
        potential.extend([1e30; 4]);
        potential.extend([0.0, f64::NAN]);
        let mut state = vec![FieldCellState::Reached; 1004];
        state.extend([FieldCellState::Impassable, FieldCellState::Unreached]);
        let field = FieldView {
            potential: &potential,
            state: &state,
            key: 0,
        };
        let heat = Heat::new(&field, &log, &lut).unwrap();
        let range = heat.range.unwrap();
        assert_eq!(range.lo, 0.1);
        assert!(range.clipped);
        assert!(range.hi > 99.0 && range.hi < 102.0, "{}", range.hi);
        let colour = |i: usize| heat.colours[heat.bins[i] as usize];
        assert_eq!(colour(0), lut[0].pack());
        assert_eq!(colour(999), lut[255].pack());
        assert_eq!(colour(1003), lut[255].pack());
        assert_eq!(colour(500), lut[128].pack());
        assert_eq!(heat.bins[1004..], [NO_HEAT, NO_HEAT]);
        // A reached cell without a positive potential is refused.
        let mut state = state.clone();
        state[1004] = FieldCellState::Reached;
        let field = FieldView {
            potential: &potential,
            state: &state,
            key: 0,
        };
        assert!(matches!(
            Heat::new(&field, &log, &lut),
            Err(RenderError::BadNumber {
                index: Some(1004),
                ..
            })
        ));
    }

    #[test]
    fn pixels_partition_small_cells_and_sample_big_ones() {
        // 10 cells of 0.7 px from x = 3.2: every cell in exactly one pixel, in order.
        let cols = pixel_cells(3.2, 10.2, 0.7, 10, 100, |i| i - 3.2);
        let mut next = 0;
        for &(_, c0, c1, _) in &cols {
            assert_eq!(c0, next);
            assert!(c1 > c0);
            next = c1;
        }
        assert_eq!(next, 10);
        assert_eq!(cols.first().unwrap().0, 3);
        assert_eq!(cols.last().unwrap().0, 9);
        // 3 cells of 4 px from x = 2: the cell under each pixel centre; new-cell flags.
        let cols = pixel_cells(2.0, 14.0, 4.0, 3, 100, |i| i - 2.0);
        let cells: Vec<usize> = cols.iter().map(|c| c.1).collect();
        assert_eq!(cells, [0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2]);
        assert!(cols.iter().all(|c| c.2 == c.1 + 1));
        let edges: Vec<bool> = cols.iter().map(|c| c.3).collect();
        assert_eq!(edges.iter().filter(|&&e| e).count(), 3);
        // Clipped to the frame.
        assert_eq!(pixel_cells(2.0, 14.0, 4.0, 3, 5, |i| i - 2.0).len(), 3);
    }
}
