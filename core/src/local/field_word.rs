//! The potential field's per-cell word and the repulsion behind it: what the expansion of a
//! neighbour reads in one load (its state, the move it was reached by, its squared obstacle
//! distance), and the repulsion `R = 1 / (d − dmin)²` (000 §5.2.4.9 (1-1)) by that squared
//! distance, from a table.

use std::collections::BTreeMap;

use super::potential_field::CellState;

pub(super) const UNREACHED: u32 = CellState::Unreached as u32;
pub(super) const REACHED: u32 = CellState::Reached as u32;
pub(super) const IMPASSABLE: u32 = CellState::Impassable as u32;
/// A cell's word: its [`CellState`] in bits 0–1, `1 +` the index into [`NEIGHBOURS`](crate::map::NEIGHBOURS) of
/// the move it was reached by in bits 2–5 (0: none), and its squared obstacle distance in
/// cells² from bit 6 on (kept with the impassable marks; 0 on impassable cells): what the
/// expansion of a neighbour reads, in one load.
pub(super) const STATE_MASK: u32 = 0b11;
pub(super) const PARENT_SHIFT: u32 = 2;
pub(super) const PARENT_MASK: u32 = 0b11_1100;
pub(super) const D2_SHIFT: u32 = 6;
/// Squared obstacle distances (cells²) below this have their repulsion in a table.
pub(super) const TABLE_D2: u32 = 1 << 14;
/// In place of a squared distance: the cell's metres are not `map::to_metres` of an
/// integer below 2²⁶ − 1 (never, for a `GridMap` of at most 2²⁴ cells, whose distances are
/// below 2²³ cells²); its repulsion is kept aside.
pub(super) const RAW_D2: u32 = u32::MAX >> D2_SHIFT;

/// The repulsion `R = 1 / (d − dmin)²` by squared obstacle distance, for one grid size
/// and `dmin`; and the impassable marks and squared distances of cells.
#[derive(Debug, Clone, Default)]
pub(super) struct Repulsion {
    grid: f64,
    dmin: f64,
    /// By squared distance below [`TABLE_D2`].
    table: Vec<f64>,
    /// The cells marked [`RAW_D2`] (never, for a `GridMap`'s distances).
    raw: BTreeMap<u32, f64>,
}

impl Repulsion {
    pub(super) fn new(grid: f64, dmin: f64) -> Self {
        Self {
            grid,
            dmin,
            table: (0..TABLE_D2)
                .map(|k2| Self::formula(k2, grid, dmin))
                .collect(),
            raw: BTreeMap::new(),
        }
    }

    /// `R` of a passable cell at `√k2 · g` metres: the metres as the map makes them
    /// (`map::to_metres`), then the seed's formula.
    #[inline(always)]
    fn formula(k2: u32, grid: f64, dmin: f64) -> f64 {
        let clearance = crate::map::to_metres(u64::from(k2), grid) - dmin;
        1.0 / (clearance * clearance)
    }

    /// The repulsion kept aside for cell `i`, marked [`RAW_D2`].
    pub(super) fn raw(&self, i: u32) -> Option<f64> {
        self.raw.get(&i).copied()
    }

    #[inline(always)]
    pub(super) fn of(&self, k2: u32) -> f64 {
        match self.table.get(k2 as usize) {
            Some(&r) => r,
            None => Self::formula(k2, self.grid, self.dmin),
        }
    }

    /// Marks the cells `from..` with obstacle distances `dist`: impassable, or unreached
    /// with their squared distance.
    pub(super) fn mark(&mut self, from: usize, dist: &[f64], words: &mut [u32]) {
        for (i, (&d, word)) in dist.iter().zip(words).enumerate() {
            if crate::map::within_dmin(d, self.dmin) {
                *word = IMPASSABLE;
                continue;
            }
            // Metres are √d² · g (`map::to_metres`); d² comes back exactly from them (the
            // relative error of (d/g)² is below 7·2⁻⁵³, d² < 2⁴⁹), and is used only if it
            // gives the very same metres.
            let q = d / self.grid;
            let r = (q * q).round();
            let k2 = if r < f64::from(RAW_D2) && crate::map::to_metres(r as u64, self.grid) == d {
                r as u32
            } else {
                let clearance = d - self.dmin;
                self.raw
                    .insert((from + i) as u32, 1.0 / (clearance * clearance));
                RAW_D2
            };
            *word = (k2 << D2_SHIFT) | UNREACHED;
        }
    }
}
