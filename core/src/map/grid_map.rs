//! `GridMap`: the occupancy grid of `SetMap` (000 §3.2.2.1 (4), §5.2.4.1), its world frame,
//! atomic `MapUpdate` (§3.2.2.1 (5), §5.2.4.6) and obstacle distances (spec §2).

use std::collections::VecDeque;
use std::sync::atomic::{AtomicU64, Ordering};

use super::distance::DistanceField;
use super::{MapError, MapUpdate};
use crate::rtc::Time;

/// The largest map accepted: 16 Mi cells (a 4096 × 4096 map), so a bad header gives a clear
/// error instead of an out-of-memory.
pub const MAX_CELLS: usize = 16 * 1024 * 1024;

/// How far above `dmin` an obstacle distance may be and still count as "within `dmin`":
/// 1 nm. Distances are `g·√k` in floating point, so a cell exactly `dmin` away can come out
/// a few ulps above it (3 × 0.1 = 0.30000000000000004); without this margin such a cell is
/// passable with a repulsion `1/(d − dmin)²` of about 10³².
pub const DMIN_TOLERANCE: f64 = 1e-9;

/// Whether an obstacle distance lies within `dmin` (spec §2, §3 step 4: "cells with obstacle
/// distance ≤ `dmin` are impassable"), with [`DMIN_TOLERANCE`]. Every planner, the renderer's
/// dmin zone and the start/goal checks use this one predicate.
pub fn within_dmin(distance: f64, dmin: f64) -> bool {
    distance <= dmin + DMIN_TOLERANCE
}

/// A cell index `(x, y)`: x is the column (fastest in `MapData`), y the row, (0, 0) the
/// lower-left cell.
pub type Cell = (usize, usize);

/// The cells `[x0, x1) × [y0, y1)` of a map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct CellRect {
    pub x0: usize,
    pub y0: usize,
    pub x1: usize,
    pub y1: usize,
}

/// Which map, and which state of its obstacle distances: what a planner's cache of values
/// derived from the distances (passable cells) was made from. Not part of a map's value
/// (two equal maps have different stamps); it never changes a result, only whether a cache
/// is reused (spec §6).
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) struct MapStamp {
    id: u64,
    revision: u64,
}

impl core::fmt::Debug for MapStamp {
    /// The revision only: ids tell apart map values made in one process, not what a map is
    /// (two equal components print the same).
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("MapStamp")
            .field("revision", &self.revision)
            .finish_non_exhaustive()
    }
}

/// Every `GridMap` value — made, read or cloned — gets its own id, so a cache keyed by a
/// stamp is never applied to another map.
static NEXT_MAP_ID: AtomicU64 = AtomicU64::new(1);

fn fresh_id() -> u64 {
    NEXT_MAP_ID.fetch_add(1, Ordering::Relaxed)
}

/// How many distance changes a map remembers for [`GridMap::distance_changes_since`].
const CHANGES_KEPT: usize = 64;

/// An occupancy grid. A `GridMap` that exists is valid (spec §2 Decision): dimensions ≥ 1,
/// at most [`MAX_CELLS`] cells, a positive finite `GridSize`, a finite origin, and every cell
/// 0 (free) or 1 (obstacle).
pub struct GridMap {
    width: usize,
    height: usize,
    grid_size: f64,
    origin: (f64, f64),
    /// 0 free, 1 obstacle; `x + y * width`.
    cells: Vec<u8>,
    /// Obstacle distances (metres, 0 on obstacle cells), kept current by every change.
    field: DistanceField,
    version: Time,
    /// This value's id (see [`MapStamp`]).
    id: u64,
    /// Counts the `MapUpdate`s that changed a distance.
    revision: u64,
    /// The last [`CHANGES_KEPT`] revisions: where the distances changed.
    changes: VecDeque<(u64, CellRect)>,
}

impl core::fmt::Debug for GridMap {
    /// Every field but the id, as `PartialEq` (the stamp is not part of the value: two
    /// equal maps print the same).
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("GridMap")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("grid_size", &self.grid_size)
            .field("origin", &self.origin)
            .field("cells", &self.cells)
            .field("field", &self.field)
            .field("version", &self.version)
            .field("revision", &self.revision)
            .field("changes", &self.changes)
            .finish_non_exhaustive()
    }
}

impl Clone for GridMap {
    /// A copy with its own id: its distances may change apart from the original's.
    fn clone(&self) -> Self {
        Self {
            width: self.width,
            height: self.height,
            grid_size: self.grid_size,
            origin: self.origin,
            cells: self.cells.clone(),
            field: self.field.clone(),
            version: self.version,
            id: fresh_id(),
            revision: self.revision,
            changes: self.changes.clone(),
        }
    }
}

impl PartialEq for GridMap {
    /// Equal cells, geometry, distances and version (the stamp is not part of the value).
    fn eq(&self, other: &Self) -> bool {
        self.width == other.width
            && self.height == other.height
            && self.grid_size == other.grid_size
            && self.origin == other.origin
            && self.version == other.version
            && self.cells == other.cells
            && self.field == other.field
    }
}

impl GridMap {
    /// A map from `cells` (x fastest, 0 free / 1 obstacle), with the lower-left corner of
    /// cell (0, 0) at `origin` (metres).
    pub fn new(
        width: usize,
        height: usize,
        grid_size: f64,
        origin: (f64, f64),
        cells: Vec<u8>,
    ) -> Result<Self, MapError> {
        let side = |n: usize| i64::try_from(n).unwrap_or(i64::MAX);
        Self::check_shape(side(width), side(height))?;
        if !(grid_size.is_finite() && grid_size > 0.0) {
            return Err(MapError::BadGridSize { value: grid_size });
        }
        if !(origin.0.is_finite() && origin.1.is_finite()) {
            return Err(MapError::BadOrigin {
                x: origin.0,
                y: origin.1,
            });
        }
        if cells.len() != width * height {
            return Err(MapError::DataLength {
                len: cells.len(),
                expected: width * height,
            });
        }
        if let Some((index, &v)) = cells.iter().enumerate().find(|(_, v)| **v > 1) {
            return Err(MapError::BadCellValue {
                what: "MapData",
                index,
                value: i64::from(v),
            });
        }
        let field = DistanceField::new(&cells, width, height, grid_size);
        Ok(Self {
            width,
            height,
            grid_size,
            origin,
            cells,
            field,
            version: Time::default(),
            id: fresh_id(),
            revision: 0,
            changes: VecDeque::new(),
        })
    }

    /// `SetMap(MapData, MapLengthX, MapLengthY, GridSize)` (000 §3.2.2.1 (4)): origin (0, 0).
    pub fn from_map_data(
        map_data: &[i16],
        map_length_x: i32,
        map_length_y: i32,
        grid_size: f64,
    ) -> Result<Self, MapError> {
        Self::check_shape(i64::from(map_length_x), i64::from(map_length_y))?;
        let (w, h) = (map_length_x as usize, map_length_y as usize);
        if map_data.len() != w * h {
            return Err(MapError::DataLength {
                len: map_data.len(),
                expected: w * h,
            });
        }
        let mut cells = Vec::with_capacity(map_data.len());
        for (index, &v) in map_data.iter().enumerate() {
            match v {
                0 | 1 => cells.push(v as u8),
                _ => {
                    return Err(MapError::BadCellValue {
                        what: "MapData",
                        index,
                        value: i64::from(v),
                    });
                }
            }
        }
        Self::new(w, h, grid_size, (0.0, 0.0), cells)
    }

    /// The check every map reader makes on the size a file tells it, before it allocates
    /// anything for the cells (spec §2 Decision 0.2): both dimensions at least 1 and
    /// `width × height` at most [`MAX_CELLS`], computed without overflow. Returns the cell
    /// count.
    pub fn check_size(width: u64, height: u64) -> Result<usize, MapError> {
        let signed = |n: u64| i64::try_from(n).unwrap_or(i64::MAX);
        if width < 1 {
            return Err(MapError::BadDimension {
                axis: "MapLengthX",
                value: signed(width),
            });
        }
        if height < 1 {
            return Err(MapError::BadDimension {
                axis: "MapLengthY",
                value: signed(height),
            });
        }
        match width.checked_mul(height) {
            Some(cells) if cells <= MAX_CELLS as u64 => Ok(cells as usize),
            cells => Err(MapError::TooLarge {
                width: usize::try_from(width).unwrap_or(usize::MAX),
                height: usize::try_from(height).unwrap_or(usize::MAX),
                cells: cells.unwrap_or(u64::MAX),
                limit: MAX_CELLS,
            }),
        }
    }

    fn check_shape(width: i64, height: i64) -> Result<(), MapError> {
        if width < 1 {
            return Err(MapError::BadDimension {
                axis: "MapLengthX",
                value: width,
            });
        }
        if height < 1 {
            return Err(MapError::BadDimension {
                axis: "MapLengthY",
                value: height,
            });
        }
        let cells = (width as u64).saturating_mul(height as u64);
        if cells > MAX_CELLS as u64 {
            return Err(MapError::TooLarge {
                width: width as usize,
                height: height as usize,
                cells,
                limit: MAX_CELLS,
            });
        }
        Ok(())
    }

    /// Cells in x (`MapLengthX`).
    pub fn width(&self) -> usize {
        self.width
    }

    /// Cells in y (`MapLengthY`).
    pub fn height(&self) -> usize {
        self.height
    }

    /// Cell edge length in metres (`GridSize`).
    pub fn grid_size(&self) -> f64 {
        self.grid_size
    }

    /// World position of the lower-left corner of cell (0, 0), metres.
    pub fn origin(&self) -> (f64, f64) {
        self.origin
    }

    /// The timestamp of the last `MapUpdate` (zero for a new map): the map's version.
    pub fn version(&self) -> Time {
        self.version
    }

    /// The cells, x fastest, 0 free / 1 obstacle.
    pub fn cells(&self) -> &[u8] {
        &self.cells
    }

    /// Obstacle distances in metres, x fastest (spec §2): from each cell's centre to the
    /// nearest obstacle cell's centre, cells outside the map counting as obstacles; 0 on an
    /// obstacle cell.
    pub fn distances(&self) -> &[f64] {
        self.field.distances()
    }

    /// The current [`MapStamp`].
    pub(crate) fn stamp(&self) -> MapStamp {
        MapStamp {
            id: self.id,
            revision: self.revision,
        }
    }

    /// Where the obstacle distances changed since `since` (a stamp of this map): one
    /// rectangle per change, oldest first. `None` when that cannot be told — another map's
    /// stamp, or changes too old to be remembered — and everything must be taken as changed.
    pub(crate) fn distance_changes_since(
        &self,
        since: MapStamp,
    ) -> Option<impl Iterator<Item = CellRect> + '_> {
        if since.id != self.id || since.revision > self.revision {
            return None;
        }
        let missing = self.revision - since.revision;
        if missing as usize > self.changes.len() {
            return None;
        }
        Some(
            self.changes
                .iter()
                .filter(move |(r, _)| *r > since.revision)
                .map(|&(_, rect)| rect),
        )
    }

    /// Flat index of an in-map cell, `x + y · width` (meaningless, but no panic, for a cell
    /// outside the map).
    pub fn index(&self, (x, y): Cell) -> usize {
        x.wrapping_add(y.wrapping_mul(self.width))
    }

    /// Whether `(x, y)` (possibly negative) lies inside the map.
    pub fn contains(&self, x: i64, y: i64) -> bool {
        x >= 0 && y >= 0 && (x as u64) < self.width as u64 && (y as u64) < self.height as u64
    }

    /// Whether `(x, y)` is an obstacle; outside the map counts as obstacle (spec §2).
    pub fn is_obstacle(&self, x: i64, y: i64) -> bool {
        !self.contains(x, y) || self.cells[x as usize + y as usize * self.width] == 1
    }

    /// Obstacle distance of a cell, metres (spec §2): 0 on an obstacle cell, and 0 for a
    /// cell outside the map, which counts as obstacle.
    pub fn obstacle_distance(&self, (x, y): Cell) -> f64 {
        if x < self.width && y < self.height {
            self.field.distances()[x + y * self.width]
        } else {
            0.0
        }
    }

    /// The cell containing world point `(wx, wy)` as signed indices (may be outside the map;
    /// `None` only for non-finite input).
    pub fn world_to_cell_signed(&self, wx: f64, wy: f64) -> Option<(i64, i64)> {
        if !(wx.is_finite() && wy.is_finite()) {
            return None;
        }
        let fx = libm::floor((wx - self.origin.0) / self.grid_size);
        let fy = libm::floor((wy - self.origin.1) / self.grid_size);
        if fx.abs() > 1e15 || fy.abs() > 1e15 {
            return None;
        }
        Some((fx as i64, fy as i64))
    }

    /// The in-map cell containing world point `(wx, wy)`, if any (spec §2 "World ↔ grid").
    pub fn world_to_cell(&self, wx: f64, wy: f64) -> Option<Cell> {
        let (x, y) = self.world_to_cell_signed(wx, wy)?;
        self.contains(x, y).then_some((x as usize, y as usize))
    }

    /// World position of the centre of cell `(x, y)`: `ox + (x + ½)·g`.
    pub fn cell_center(&self, (x, y): Cell) -> (f64, f64) {
        (
            self.origin.0 + (x as f64 + 0.5) * self.grid_size,
            self.origin.1 + (y as f64 + 0.5) * self.grid_size,
        )
    }

    /// Whether a cell and every cell whose centre lies within `dmin` of it are passable
    /// (000 §5.2.4.2, §5.2.4.4): equivalently its obstacle distance exceeds `dmin`. False
    /// for a cell outside the map.
    pub fn is_clear(&self, cell: Cell, dmin: f64) -> bool {
        !within_dmin(self.obstacle_distance(cell), dmin)
    }

    /// `MapUpdate` (000 §3.2.2.1 (5), spec §2 Decision): checked completely first
    /// ([`MapUpdate::check`]), then applied — all or nothing. Returns the number of cells whose
    /// value changed; the timestamp becomes the map's version.
    pub fn map_update(&mut self, update: &MapUpdate) -> Result<usize, MapError> {
        update.check(self)?;
        let (x, y, value, tm) = (&update.x, &update.y, &update.value, update.tm);
        // Validated: apply. A cell listed twice takes its last value, as if the entries were
        // applied one after the other; only cells whose value differs afterwards count.
        let mut listed: Vec<(usize, u8)> = x
            .iter()
            .zip(y)
            .map(|(&cx, &cy)| {
                let idx = cx as usize + cy as usize * self.width;
                (idx, self.cells[idx])
            })
            .collect();
        listed.sort_unstable();
        listed.dedup_by_key(|e| e.0);
        for i in 0..x.len() {
            self.cells[x[i] as usize + y[i] as usize * self.width] = value[i] as u8;
        }
        let changed: Vec<usize> = listed
            .iter()
            .filter(|&&(idx, before)| self.cells[idx] != before)
            .map(|&(idx, _)| idx)
            .collect();
        self.version = tm;
        if !changed.is_empty()
            && let Some(rect) =
                self.field
                    .update_cells(&self.cells, self.width, self.height, &changed)
        {
            self.revision += 1;
            if self.changes.len() == CHANGES_KEPT {
                self.changes.pop_front();
            }
            self.changes.push_back((self.revision, rect));
        }
        Ok(changed.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_map_is_x_fastest_as_the_3x3_example() {
        // 000 §3.2.2.1 (4): MapData[1] is X[1]Y[0], MapData[3] is X[0]Y[1].
        let m = GridMap::from_map_data(&[0, 1, 0, 1, 0, 0, 0, 0, 0], 3, 3, 0.5).unwrap();
        assert!(m.is_obstacle(1, 0));
        assert!(m.is_obstacle(0, 1));
        assert!(!m.is_obstacle(1, 1));
        assert!(m.is_obstacle(-1, 1) && m.is_obstacle(3, 0));
        assert_eq!(m.world_to_cell(0.75, 0.25), Some((1, 0)));
        assert_eq!(m.cell_center((1, 0)), (0.75, 0.25));
        assert_eq!(m.obstacle_distance((1, 1)), 0.5);
        assert_eq!(m.obstacle_distance((2, 2)), 0.5);
    }

    #[test]
    fn bad_input_is_refused_and_the_map_unchanged() {
        assert!(matches!(
            GridMap::from_map_data(&[0; 8], 3, 3, 1.0),
            Err(MapError::DataLength {
                len: 8,
                expected: 9
            })
        ));
        assert!(matches!(
            GridMap::from_map_data(&[0, 2, 0, 0], 2, 2, 1.0),
            Err(MapError::BadCellValue {
                index: 1,
                value: 2,
                ..
            })
        ));
        assert!(matches!(
            GridMap::from_map_data(&[0; 4], 2, 2, 0.0),
            Err(MapError::BadGridSize { .. })
        ));
        assert!(matches!(
            GridMap::from_map_data(&[0; 4], 2, 2, f64::NAN),
            Err(MapError::BadGridSize { .. })
        ));
        assert!(matches!(
            GridMap::from_map_data(&[], 0, 2, 1.0),
            Err(MapError::BadDimension {
                axis: "MapLengthX",
                ..
            })
        ));
        assert!(matches!(
            GridMap::new(5000, 5000, 1.0, (0.0, 0.0), vec![]),
            Err(MapError::TooLarge { .. })
        ));
        let mut m = GridMap::from_map_data(&[0; 4], 2, 2, 1.0).unwrap();
        let before = m.clone();
        let tm = Time { sec: 3, nsec: 4 };
        assert!(matches!(
            m.map_update(&MapUpdate {
                x: vec![0, 1],
                y: vec![0],
                value: vec![1, 1],
                num: 2,
                tm,
            }),
            Err(MapError::UpdateLength { array: "Y", .. })
        ));
        assert!(matches!(
            m.map_update(&MapUpdate {
                x: vec![0, 2],
                y: vec![0, 0],
                value: vec![1, 1],
                num: 2,
                tm,
            }),
            Err(MapError::CellOutside { x: 2, .. })
        ));
        assert!(matches!(
            m.map_update(&MapUpdate {
                x: vec![0, 1],
                y: vec![0, 0],
                value: vec![1, 2],
                num: 2,
                tm,
            }),
            Err(MapError::BadCellValue { what: "value", .. })
        ));
        assert_eq!(m, before);
        assert_eq!(
            m.map_update(&MapUpdate {
                x: vec![0, 1],
                y: vec![0, 0],
                value: vec![1, 1],
                num: 2,
                tm,
            }),
            Ok(2)
        );
        assert_eq!(m.version(), tm);
        assert!(m.is_obstacle(1, 0));
        assert_eq!(m.obstacle_distance((0, 1)), 1.0);
    }
}
