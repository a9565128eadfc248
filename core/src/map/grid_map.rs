//! `GridMap`: the occupancy grid of `SetMap` (000 §3.2.2.1 (4), §5.2.4.1), its world frame,
//! atomic `MapUpdate` (§3.2.2.1 (5), §5.2.4.6) and obstacle distances (spec §2).

use std::collections::VecDeque;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, PoisonError, Weak};

use super::distance::DistanceField;
use super::{MapError, MapUpdate};
use crate::rtc::Time;

/// The largest map accepted: 16 Mi cells (a 4096 × 4096 map), so a bad header gives a clear
/// error instead of an out-of-memory.
pub const MAX_CELLS: usize = 16 * 1024 * 1024;

/// The smallest `GridSize` accepted: 0.1 mm (spec §2 Decision "geometry").
pub const MIN_GRID_SIZE: f64 = 1e-4;

/// The largest `GridSize` accepted: 1 km (spec §2 Decision "geometry").
pub const MAX_GRID_SIZE: f64 = 1e3;

/// How far from 0 a map's origin and far corner may lie on either axis: 10⁹ m (spec §2
/// Decision "geometry"), so that world coordinates, distances and their squares stay far
/// from overflow.
pub const MAX_COORDINATE: f64 = 1e9;

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

impl CellRect {
    /// The smallest rectangle holding both.
    pub(crate) fn union(&self, other: &Self) -> Self {
        Self {
            x0: self.x0.min(other.x0),
            y0: self.y0.min(other.y0),
            x1: self.x1.max(other.x1),
            y1: self.y1.max(other.y1),
        }
    }
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
/// at most [`MAX_CELLS`] cells, the geometry [`GridMap::check_geometry`] accepts (`GridSize`
/// within [`MIN_GRID_SIZE`] ..= [`MAX_GRID_SIZE`], origin and far corner within
/// ±[`MAX_COORDINATE`]), and every cell 0 (free) or 1 (obstacle).
///
/// **Copies share** (spec §5: every component keeps its own map, so one `MapUpdate` reaches
/// five copies): the cells and distances are held behind an [`Arc`] and copied only when a
/// copy changes, and a `MapUpdate` applied to shared cells leaves its result with them, so
/// the next copy that gets the same update takes that result instead of computing the
/// distances again. Each copy still changes only when it is told to; the result is the same
/// value either way.
pub struct GridMap {
    width: usize,
    height: usize,
    grid_size: f64,
    origin: (f64, f64),
    content: Arc<Content>,
    version: Time,
    /// This value's id (see [`MapStamp`]).
    id: u64,
}

/// What a `MapUpdate` changes: the cells, their distances and the change log.
#[derive(Debug)]
struct Content {
    /// 0 free, 1 obstacle; `x + y * width`.
    cells: Vec<u8>,
    /// Obstacle distances (metres, 0 on obstacle cells), kept current by every change.
    field: DistanceField,
    /// Counts the `MapUpdate`s that changed a distance.
    revision: u64,
    /// The last [`CHANGES_KEPT`] revisions: where the distances changed.
    changes: VecDeque<(u64, CellRect)>,
    /// The content a `MapUpdate` made from this one (its cells and values, the number of
    /// cells it changed, the result), for the other copies that get the same update; held
    /// weakly, so a copy left behind (a snapshot) does not keep later maps alive.
    next: Mutex<Option<Successor>>,
}

#[derive(Debug)]
struct Successor {
    x: Vec<i32>,
    y: Vec<i32>,
    value: Vec<i16>,
    changed: usize,
    content: Weak<Content>,
}

impl Content {
    /// The result a `MapUpdate` left here (one thread at a time; a panic while it was held
    /// left it whole: it is only ever replaced).
    fn successor(&self) -> std::sync::MutexGuard<'_, Option<Successor>> {
        self.next.lock().unwrap_or_else(PoisonError::into_inner)
    }

    fn new(cells: Vec<u8>, field: DistanceField) -> Self {
        Self {
            cells,
            field,
            revision: 0,
            changes: VecDeque::new(),
            next: Mutex::new(None),
        }
    }
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
            .field("cells", &self.content.cells)
            .field("field", &self.content.field)
            .field("version", &self.version)
            .field("revision", &self.content.revision)
            .field("changes", &self.content.changes)
            .finish_non_exhaustive()
    }
}

impl Clone for GridMap {
    /// A copy with its own id: its distances may change apart from the original's. The
    /// cells and distances are shared until one of the two changes.
    fn clone(&self) -> Self {
        Self {
            width: self.width,
            height: self.height,
            grid_size: self.grid_size,
            origin: self.origin,
            content: Arc::clone(&self.content),
            version: self.version,
            id: fresh_id(),
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
            && (Arc::ptr_eq(&self.content, &other.content)
                || (self.content.cells == other.content.cells
                    && self.content.field == other.content.field))
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
        let count = Self::check_size(width as u64, height as u64)?;
        Self::check_geometry(width, height, grid_size, origin)?;
        if cells.len() != count {
            return Err(MapError::DataLength {
                len: cells.len(),
                expected: count,
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
            content: Arc::new(Content::new(cells, field)),
            version: Time::default(),
            id: fresh_id(),
        })
    }

    /// `SetMap(MapData, MapLengthX, MapLengthY, GridSize)` (000 §3.2.2.1 (4)): origin (0, 0).
    pub fn from_map_data(
        map_data: &[i16],
        map_length_x: i32,
        map_length_y: i32,
        grid_size: f64,
    ) -> Result<Self, MapError> {
        let side = |axis, n: i32| {
            u64::try_from(n).map_err(|_| MapError::BadDimension {
                axis,
                value: i64::from(n),
            })
        };
        let (w, h) = (
            side("MapLengthX", map_length_x)?,
            side("MapLengthY", map_length_y)?,
        );
        let count = Self::check_size(w, h)?;
        if map_data.len() != count {
            return Err(MapError::DataLength {
                len: map_data.len(),
                expected: count,
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
        Self::new(w as usize, h as usize, grid_size, (0.0, 0.0), cells)
    }

    /// The check every map reader makes on the size a file tells it, before it allocates
    /// anything for the cells (spec §2 Decision 0.2): both dimensions at least 1 and
    /// `width × height` at most [`MAX_CELLS`], computed without overflow. Returns the cell
    /// count.
    pub fn check_size(width: u64, height: u64) -> Result<usize, MapError> {
        for (axis, n) in [("MapLengthX", width), ("MapLengthY", height)] {
            if n < 1 {
                return Err(MapError::BadDimension { axis, value: 0 });
            }
        }
        // Exact in 128 bits, so the error says the true product.
        let cells = u128::from(width) * u128::from(height);
        if cells > MAX_CELLS as u128 {
            return Err(MapError::TooLarge {
                width,
                height,
                cells: cells.to_string(),
                limit: MAX_CELLS,
            });
        }
        Ok(cells as usize)
    }

    /// The check every way of making a map makes on its geometry (spec §2 Decision
    /// "geometry"): `grid_size` within [`MIN_GRID_SIZE`] ..= [`MAX_GRID_SIZE`] metres, and
    /// the origin and the far corner (`origin + (width, height) · grid_size`) finite and
    /// within ±[`MAX_COORDINATE`] metres on both axes. A reader that does not know the size
    /// yet checks a 1 × 1 map; the full check follows when the map is made.
    pub fn check_geometry(
        width: usize,
        height: usize,
        grid_size: f64,
        origin: (f64, f64),
    ) -> Result<(), MapError> {
        if !(MIN_GRID_SIZE..=MAX_GRID_SIZE).contains(&grid_size) {
            return Err(MapError::BadGridSize {
                value: grid_size,
                min: MIN_GRID_SIZE,
                max: MAX_GRID_SIZE,
            });
        }
        let far = (
            origin.0 + width as f64 * grid_size,
            origin.1 + height as f64 * grid_size,
        );
        let within = |v: f64| v.abs() <= MAX_COORDINATE;
        if ![origin.0, origin.1, far.0, far.1].into_iter().all(within) {
            return Err(MapError::BadOrigin {
                x: origin.0,
                y: origin.1,
                far_x: far.0,
                far_y: far.1,
                limit: MAX_COORDINATE,
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
        &self.content.cells
    }

    /// Obstacle distances in metres, x fastest (spec §2): from each cell's centre to the
    /// nearest obstacle cell's centre, cells outside the map counting as obstacles; 0 on an
    /// obstacle cell.
    pub fn distances(&self) -> &[f64] {
        self.content.field.distances()
    }

    /// The current [`MapStamp`].
    pub(crate) fn stamp(&self) -> MapStamp {
        MapStamp {
            id: self.id,
            revision: self.content.revision,
        }
    }

    /// Where the obstacle distances changed since `since` (a stamp of this map): one
    /// rectangle per change, oldest first. `None` when that cannot be told — another map's
    /// stamp, or changes too old to be remembered — and everything must be taken as changed.
    pub(crate) fn distance_changes_since(
        &self,
        since: MapStamp,
    ) -> Option<impl Iterator<Item = CellRect> + '_> {
        let content = &*self.content;
        if since.id != self.id || since.revision > content.revision {
            return None;
        }
        let missing = content.revision - since.revision;
        if missing as usize > content.changes.len() {
            return None;
        }
        Some(
            content
                .changes
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
        !self.contains(x, y) || self.content.cells[x as usize + y as usize * self.width] == 1
    }

    /// Obstacle distance of a cell, metres (spec §2): 0 on an obstacle cell, and 0 for a
    /// cell outside the map, which counts as obstacle.
    pub fn obstacle_distance(&self, (x, y): Cell) -> f64 {
        if x < self.width && y < self.height {
            self.content.field.distances()[x + y * self.width]
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
        self.version = update.tm;
        let same = |n: &Successor| n.x == update.x && n.y == update.y && n.value == update.value;
        // Another copy got this update on these cells before: its result.
        let taken = self
            .content
            .successor()
            .as_ref()
            .filter(|n| same(n))
            .and_then(|n| Some((n.content.upgrade()?, n.changed)));
        if let Some((content, changed)) = taken {
            self.content = content;
            return Ok(changed);
        }
        // Nobody else holds these cells: change them in place (a result left for copies
        // that are gone is dropped).
        if let Some(content) = Arc::get_mut(&mut self.content) {
            *content
                .next
                .get_mut()
                .unwrap_or_else(PoisonError::into_inner) = None;
            return Ok(content.apply(update, self.width, self.height));
        }
        // Shared: a changed copy, left with the shared cells for the other copies.
        let mut content = Content {
            cells: self.content.cells.clone(),
            field: self.content.field.clone(),
            revision: self.content.revision,
            changes: self.content.changes.clone(),
            next: Mutex::new(None),
        };
        let changed = content.apply(update, self.width, self.height);
        let content = Arc::new(content);
        *self.content.successor() = Some(Successor {
            x: update.x.clone(),
            y: update.y.clone(),
            value: update.value.clone(),
            changed,
            content: Arc::downgrade(&content),
        });
        self.content = content;
        Ok(changed)
    }
}

impl Content {
    /// Applies a checked `update` to these cells of a `width × height` map: the number of
    /// cells whose value changed.
    fn apply(&mut self, update: &MapUpdate, width: usize, height: usize) -> usize {
        let (x, y, value) = (&update.x, &update.y, &update.value);
        // A cell listed twice takes its last value, as if the entries were applied one
        // after the other; only cells whose value differs afterwards count.
        let mut listed: Vec<(usize, u8)> = x
            .iter()
            .zip(y)
            .map(|(&cx, &cy)| {
                let idx = cx as usize + cy as usize * width;
                (idx, self.cells[idx])
            })
            .collect();
        listed.sort_unstable();
        listed.dedup_by_key(|e| e.0);
        for i in 0..x.len() {
            self.cells[x[i] as usize + y[i] as usize * width] = value[i] as u8;
        }
        let changed: Vec<usize> = listed
            .iter()
            .filter(|&&(idx, before)| self.cells[idx] != before)
            .map(|&(idx, _)| idx)
            .collect();
        if !changed.is_empty()
            && let Some(rect) = self
                .field
                .update_cells(&self.cells, width, height, &changed)
        {
            self.revision += 1;
            if self.changes.len() == CHANGES_KEPT {
                self.changes.pop_front();
            }
            self.changes.push_back((self.revision, rect));
        }
        changed.len()
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

    /// The size error says the true product `width × height` and the sizes as given: not a
    /// saturated or wrapped count, not a width clamped to `i64::MAX` or to a 32-bit `usize`
    /// (the browser's).
    #[test]
    fn too_large_says_width_times_height() {
        let too_large = |e: MapError| match e {
            MapError::TooLarge {
                width,
                height,
                cells,
                ..
            } => (width, height, cells.parse::<u128>().unwrap()),
            other => panic!("{other:?}"),
        };
        // 2⁶⁴ − 1 by 2 needs 65 bits.
        let e = GridMap::check_size(u64::MAX, 2).unwrap_err();
        assert_eq!(
            e.to_string(),
            "map of 18446744073709551615×2 = 36893488147419103230 cells exceeds the limit of \
             16777216 cells"
        );
        assert_eq!(
            crate::Error::from(e).detail().fields["cells"],
            "36893488147419103230"
        );
        assert_eq!(
            too_large(GridMap::check_size(u64::MAX, u64::MAX).unwrap_err()),
            (
                u64::MAX,
                u64::MAX,
                u128::from(u64::MAX) * u128::from(u64::MAX)
            )
        );
        // Wider than 32 bits: the width as given, on every target.
        assert_eq!(
            too_large(GridMap::check_size(1 << 40, 3).unwrap_err()),
            (1 << 40, 3, 3 << 40)
        );
        // The constructors: the width given, not clamped.
        let widest = usize::MAX as u64;
        assert_eq!(
            too_large(GridMap::new(usize::MAX, 2, 1.0, (0.0, 0.0), vec![]).unwrap_err()),
            (widest, 2, u128::from(widest) * 2)
        );
        assert_eq!(
            too_large(GridMap::new(usize::MAX, usize::MAX, 1.0, (0.0, 0.0), vec![]).unwrap_err()),
            (widest, widest, u128::from(widest) * u128::from(widest))
        );
        assert_eq!(
            too_large(GridMap::from_map_data(&[], i32::MAX, 3, 1.0).unwrap_err()),
            (i32::MAX as u64, 3, 3 * i32::MAX as u128)
        );
        assert_eq!(
            GridMap::from_map_data(&[], 2, -3, 1.0),
            Err(MapError::BadDimension {
                axis: "MapLengthY",
                value: -3
            })
        );
    }

    /// Copies share their cells; the same update on each copy is computed once and gives
    /// each the same map as on its own; another update, or one on a lone map, changes only
    /// that map.
    #[test]
    fn copies_share_cells_and_one_update_is_computed_once() {
        let mut cells = vec![0u8; 40 * 30];
        cells[5 + 7 * 40] = 1;
        let original = GridMap::new(40, 30, 0.1, (0.0, 0.0), cells).unwrap();
        let mut copies: Vec<GridMap> = (0..4).map(|_| original.clone()).collect();
        assert!(
            copies
                .iter()
                .all(|c| Arc::ptr_eq(&c.content, &original.content))
        );
        let brush = MapUpdate::from_cells(
            &[(20, 15, 1), (21, 15, 1), (21, 16, 1), (5, 7, 0)],
            Time::from_nanos(7),
        );
        let mut alone = original.clone();
        alone.content = Arc::new(Content {
            cells: original.content.cells.clone(),
            field: original.content.field.clone(),
            revision: 0,
            changes: VecDeque::new(),
            next: Mutex::new(None),
        });
        let stamp = alone.stamp();
        assert_eq!(alone.map_update(&brush), Ok(4));
        for c in &mut copies {
            assert_eq!(c.map_update(&brush), Ok(4));
            assert_eq!(*c, alone);
            assert_eq!(c.content.revision, 1);
        }
        assert!(
            copies
                .iter()
                .all(|c| Arc::ptr_eq(&c.content, &copies[0].content))
        );
        // The original was not told: unchanged.
        assert!(!original.is_obstacle(20, 15) && original.is_obstacle(5, 7));
        assert_eq!(
            alone.distance_changes_since(stamp).map(Iterator::count),
            Some(1)
        );
        // Another update on one copy parts it from the others.
        let other = MapUpdate::from_cells(&[(30, 3, 1)], Time::from_nanos(8));
        assert_eq!(copies[1].map_update(&other), Ok(1));
        assert!(copies[1].is_obstacle(30, 3) && !copies[0].is_obstacle(30, 3));
        assert!(!Arc::ptr_eq(&copies[0].content, &copies[1].content));
        // The same update again changes nothing, shared or not.
        assert_eq!(copies[0].map_update(&brush), Ok(0));
        assert_eq!(copies[0], copies[2].clone());
        // A copy left behind (the original) keeps nothing that came after it alive.
        let second = MapUpdate::from_cells(&[(2, 2, 1)], Time::from_nanos(9));
        for c in &mut copies {
            assert_eq!(c.map_update(&second), Ok(1));
        }
        assert!(
            original
                .content
                .successor()
                .as_ref()
                .is_some_and(|n| n.content.upgrade().is_none())
        );
    }
}
