//! The cell inspector (the teaching page's hover panel and `rtnav inspect`): what the map and
//! LocalPathPlanning's potential field say about one cell (spec §2 obstacle distance, spec §3
//! step 4 / 000 §5.2.4.9 potential `G = G(parent) + R + A + P`).

use serde::Serialize;

use crate::errors::SystemError;
use crate::local::CellState;
use crate::map;

use super::wiring::Wiring;

/// Everything about one map cell, as the inspector shows it (JSON: `{x, y, occupancy,
/// obstacle_distance, impassable, field}`).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct CellInspection {
    /// Column.
    pub x: i64,
    /// Row.
    pub y: i64,
    /// The cell's centre in the map's world frame \[m\] (spec §2: `origin + (i + ½)·g`).
    pub centre: [f64; 2],
    /// The map's value: 0 free, 1 obstacle (spec §2).
    pub occupancy: u8,
    /// Metres from the cell's centre to the nearest obstacle cell's centre (spec §2; 0 on an
    /// obstacle cell).
    pub obstacle_distance: f64,
    /// Whether the cell is within LocalPathPlanning's effective `dmin` of an obstacle
    /// ([`map::within_dmin`], spec §3 step 4: impassable).
    pub impassable: bool,
    /// The potential field's view of the cell; `None` while LocalPathPlanning has no field
    /// for this map.
    pub field: Option<FieldInspection>,
}

/// One cell of LocalPathPlanning's potential field (000 §5.2.4.9). The numbers are defined
/// on reached cells only (`None` elsewhere): `potential` is `G`, and for every reached cell
/// but the local target `G = G(parent) + repulsion + attraction + posture`; the target has
/// `G` = 0.1 and parts 0.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct FieldInspection {
    /// Potential `G`.
    pub potential: Option<f64>,
    /// Repulsion `R = 1 / (d − dmin)²`.
    pub repulsion: Option<f64>,
    /// Attraction `A = L · (100 − PCL) / 100`.
    pub attraction: Option<f64>,
    /// Posture `P`.
    pub posture: Option<f64>,
    /// The neighbour the cell got its potential from (000 §5.2.4.9: the first finalized
    /// 8-neighbour, the one with the lowest potential), with that potential `G(parent)`, so
    /// that `G = G(parent) + R + A + P`; `None` for the local target and cells not reached.
    pub parent: Option<ParentInspection>,
    /// Path length `L` from the local target along the parents \[m\].
    pub length: Option<f64>,
    /// The field's cell state: `Reached`, `Unreached` or `Impassable`
    /// ([`CellState`]'s names).
    pub state: String,
    /// Whether the cell is passable but was not reached (not connected to the local target,
    /// or beyond where the field stopped).
    pub unreached: bool,
}

/// The parent of a reached cell in the potential field.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ParentInspection {
    /// Column.
    pub x: i64,
    /// Row.
    pub y: i64,
    /// Its potential `G(parent)`.
    pub potential: f64,
}

fn state_name(s: CellState) -> &'static str {
    match s {
        CellState::Reached => "Reached",
        CellState::Unreached => "Unreached",
        CellState::Impassable => "Impassable",
    }
}

impl Wiring {
    /// What the current map and LocalPathPlanning's latest potential field say about cell
    /// `(x, y)`. Errors: no map loaded, or a cell outside the map (named).
    pub fn inspect_cell(&self, x: i64, y: i64) -> crate::Result<CellInspection> {
        let map = self.map().ok_or(SystemError::NoMap {
            call: "inspect_cell",
        })?;
        if !map.contains(x, y) {
            return Err(SystemError::CellOutsideMap {
                x,
                y,
                width: map.width(),
                height: map.height(),
            }
            .into());
        }
        let cell = (x as usize, y as usize);
        let lpp = self.local_path_planning();
        let distance = map.obstacle_distance(cell);
        let field = lpp
            .potential_field()
            .filter(|f| f.width() == map.width() && f.height() == map.height())
            .and_then(|f| Some((f, f.info(cell)?)))
            .map(|(f, info)| {
                let reached = info.state == CellState::Reached;
                let defined = |v: f64| reached.then_some(v);
                let parent = info
                    .parent
                    .filter(|_| reached)
                    .map(|(px, py)| ParentInspection {
                        x: px as i64,
                        y: py as i64,
                        potential: f.potential((px, py)),
                    });
                FieldInspection {
                    potential: defined(info.potential),
                    repulsion: defined(info.repulsion),
                    attraction: defined(info.attraction),
                    posture: defined(info.posture),
                    parent,
                    length: defined(info.length),
                    state: state_name(info.state).to_owned(),
                    unreached: info.state == CellState::Unreached,
                }
            });
        let (cx, cy) = map.cell_center(cell);
        Ok(CellInspection {
            x,
            y,
            centre: [cx, cy],
            occupancy: map.cells()[map.index(cell)],
            obstacle_distance: distance,
            impassable: map::within_dmin(distance, lpp.params().dmin),
            field,
        })
    }
}
