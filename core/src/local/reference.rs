//! The potential field as it was first written (000 §5.2.4.9, spec §3 step 4), kept as the
//! reference the fast [`super::PotentialField`] is checked against (property tests) and
//! measured against (benchmarks). Plain and slow on purpose: one 48-byte record per cell, a
//! pass over every cell's obstacle distance per field, the radix queue of
//! `radix_queue.rs`, `libm::atan2` for both posture angles.
//!
//! Same rules as the fast field: cells finalized in increasing potential, ties in the order
//! they were assigned; a cell gets its potential once, from its first finalized neighbour;
//! `G(c) = G(p) + R(c) + A(c) + P(c)`; diagonal steps never cut the corner of an impassable
//! cell; [`FieldExtent::UntilCurrent`] stops once the current cell is finalized.

use super::potential_field::{CellState, FieldExtent, FieldRequest, TARGET_POTENTIAL};
use super::radix_queue::RadixQueue;
use crate::errors::LocalPathError;
use crate::interfaces::Direction;
use crate::map::{GridMap, NEIGHBOURS};

/// One cell of the reference field; everything 0 / `None` unless reached.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ReferenceCell {
    /// Potential `G`.
    pub potential: f64,
    /// Repulsion `R`.
    pub repulsion: f64,
    /// Attraction `A`.
    pub attraction: f64,
    /// Posture `P`.
    pub posture: f64,
    /// Path length `L` \[m\].
    pub length: f64,
    /// Place in the finalization order, if finalized.
    pub rank: Option<u32>,
    /// Index into [`NEIGHBOURS`] of the move from the parent to this cell.
    pub parent: Option<u8>,
}

/// The reference field of one request.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceField {
    /// Cells in x.
    pub width: usize,
    /// Cells in y.
    pub height: usize,
    /// Per cell, x fastest.
    pub cells: Vec<ReferenceCell>,
    /// Per cell, x fastest.
    pub state: Vec<CellState>,
    /// Cells finalized.
    pub finalized: usize,
    /// Cells reached (finalized and frontier).
    pub reached: usize,
    /// Whether the current cell was finalized.
    pub current_reached: bool,
    /// Whether the queue ran empty.
    pub complete: bool,
}

/// Computes the reference field. Errors only for a request the fast field refuses too
/// before computing (cells outside the map, bad parameters) and for a blocked target; an
/// unreachable current cell gives a field with `current_reached == false`.
pub fn compute(map: &GridMap, req: &FieldRequest) -> Result<ReferenceField, LocalPathError> {
    for (what, (x, y)) in [("target", req.target), ("current", req.current)] {
        if x >= map.width() || y >= map.height() {
            return Err(LocalPathError::CellOutside {
                what,
                x,
                y,
                width: map.width(),
                height: map.height(),
            });
        }
    }
    let pcl = req.posture_consideration_level;
    if req.dmin.is_nan() || req.dmin < 0.0 || !(0.0..=100.0).contains(&pcl) {
        return Err(LocalPathError::BadParameter {
            name: "dmin / PostureConsiderationLevel",
            value: if req.dmin.is_nan() || req.dmin < 0.0 {
                req.dmin
            } else {
                pcl
            },
            range: "dmin ≥ 0, PCL in [0, 100]",
        });
    }
    let (w, h) = (map.width(), map.height());
    let n = w * h;
    let dist = map.distances();
    let dmin = req.dmin;
    let mut state: Vec<CellState> = dist
        .iter()
        .map(|&d| {
            if crate::map::within_dmin(d, dmin) {
                CellState::Impassable
            } else {
                CellState::Unreached
            }
        })
        .collect();
    let mut cells = vec![ReferenceCell::default(); n];
    let target = map.index(req.target);
    if state[target] == CellState::Impassable {
        return Err(LocalPathError::TargetBlocked { from: req.target });
    }
    let g = map.grid_size();
    let step_straight = g;
    let step_diagonal = f64::sqrt(2.0) * g;
    let attraction_factor = (100.0 - pcl) / 100.0;
    let posture_factor = pcl / 100.0;
    let posture_on = req.posture && posture_factor > 0.0;
    let turn = match req.direction {
        Direction::Forward => 0.0,
        Direction::Backward => core::f64::consts::PI,
    };
    let hs = (
        libm::cos(req.current_heading + turn),
        libm::sin(req.current_heading + turn),
    );
    let ht = (
        libm::cos(req.target_heading + turn),
        libm::sin(req.target_heading + turn),
    );
    let (sx, sy) = (req.current.0 as i64, req.current.1 as i64);
    let (tx, ty) = (req.target.0 as i64, req.target.1 as i64);
    let current = map.index(req.current);
    let (wi, hi) = (w as i64, h as i64);

    let mut queue = RadixQueue::default();
    cells[target].potential = TARGET_POTENTIAL;
    state[target] = CellState::Reached;
    queue.push(TARGET_POTENTIAL.to_bits(), target as u32);
    let (mut finalized, mut reached, mut current_reached) = (0usize, 1usize, false);
    while let Some((_, i)) = queue.pop() {
        let i = i as usize;
        cells[i].rank = Some(finalized as u32);
        finalized += 1;
        if i == current {
            current_reached = true;
            if req.extent == FieldExtent::UntilCurrent {
                break;
            }
        }
        let (px, py) = ((i % w) as i64, (i / w) as i64);
        let gp = cells[i].potential;
        let lp = cells[i].length;
        for (k, &(dx, dy)) in NEIGHBOURS.iter().enumerate() {
            let (nx, ny) = (px + dx, py + dy);
            if nx < 0 || ny < 0 || nx >= wi || ny >= hi {
                continue;
            }
            let ni = (nx + ny * wi) as usize;
            if state[ni] != CellState::Unreached {
                continue;
            }
            let diagonal = dx != 0 && dy != 0;
            if diagonal
                && (state[(px + dx + py * wi) as usize] == CellState::Impassable
                    || state[(px + (py + dy) * wi) as usize] == CellState::Impassable)
            {
                continue;
            }
            let l = lp
                + if diagonal {
                    step_diagonal
                } else {
                    step_straight
                };
            let clearance = dist[ni] - dmin;
            let r = 1.0 / (clearance * clearance);
            let a = l * attraction_factor;
            let p = if posture_on {
                posture_factor * posture_terms(nx - sx, ny - sy, tx - nx, ty - ny, hs, ht, l)
            } else {
                0.0
            };
            let gn = gp + r + a + p;
            cells[ni] = ReferenceCell {
                potential: gn,
                repulsion: r,
                attraction: a,
                posture: p,
                length: l,
                rank: None,
                parent: Some(k as u8),
            };
            state[ni] = CellState::Reached;
            reached += 1;
            queue.push(gn.to_bits(), ni as u32);
        }
    }
    Ok(ReferenceField {
        width: w,
        height: h,
        cells,
        state,
        finalized,
        reached,
        current_reached,
        complete: queue.is_empty(),
    })
}

/// `G_Angle · G_Distance + S_Angle · S_Distance` with `libm::atan2` (spec §3 step 4).
fn posture_terms(
    vx: i64,
    vy: i64,
    wx: i64,
    wy: i64,
    hs: (f64, f64),
    ht: (f64, f64),
    l: f64,
) -> f64 {
    let (vx, vy, wx, wy) = (vx as f64, vy as f64, wx as f64, wy as f64);
    let sl2 = vx * vx + vy * vy;
    let gl2 = wx * wx + wy * wy;
    if sl2 == 0.0 || gl2 == 0.0 {
        return 0.0;
    }
    let sl_over_gl = f64::sqrt(sl2 / gl2);
    let s_angle = libm::atan2((vx * hs.1 - vy * hs.0).abs(), vx * hs.0 + vy * hs.1);
    let g_angle = libm::atan2((wx * ht.1 - wy * ht.0).abs(), wx * ht.0 + wy * ht.1);
    g_angle * sl_over_gl + s_angle * l / sl_over_gl
}
