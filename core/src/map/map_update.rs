//! [`MapUpdate`]: the seeds' `MapUpdate(X[], Y[], value[], num, sec, nsec)` (000 §3.2.2.1 (5),
//! spec §2) as one value. Every component that takes a map update takes this type, and
//! [`GridMap::map_update`] applies it.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::{GridMap, MapError};
use crate::rtc::Time;

/// Cells to set, 0 free / 1 obstacle, with the timestamp that becomes the map's version.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct MapUpdate {
    /// `X`: cell x indices.
    pub x: Vec<i32>,
    /// `Y`: cell y indices.
    pub y: Vec<i32>,
    /// `value`: 0 free, 1 obstacle.
    pub value: Vec<i16>,
    /// `num`: the number of cells (must equal each array's length).
    pub num: i32,
    /// `sec`, `nsec`: the timestamp, kept as the map's version.
    pub tm: Time,
}

impl MapUpdate {
    /// An update of `cells` (`(x, y, value)`) stamped `tm`. Cells beyond `i32` (which no map
    /// has) are clamped to `i32::MAX` and refused when the update is checked.
    pub fn from_cells(cells: &[(i64, i64, i16)], tm: Time) -> Self {
        let narrow = |v: i64| i32::try_from(v).unwrap_or(if v < 0 { i32::MIN } else { i32::MAX });
        Self {
            x: cells.iter().map(|c| narrow(c.0)).collect(),
            y: cells.iter().map(|c| narrow(c.1)).collect(),
            value: cells.iter().map(|c| c.2).collect(),
            num: i32::try_from(cells.len()).unwrap_or(i32::MAX),
            tm,
        }
    }

    /// What the edits `cells` (`(x, y, value)`, in the order made; a cell listed again takes
    /// its last value) amount to on `map`: each cell once, in the order first listed, and only
    /// if its value would change — one paint stroke as one update. Cells outside the map and
    /// values other than 0 and 1 are kept, so that the update is still refused (spec §2
    /// Decision "atomic"). Empty when nothing would change.
    pub fn net_changes(cells: &[(i64, i64, i16)], map: &GridMap) -> Vec<(i64, i64, i16)> {
        let mut last: BTreeMap<(i64, i64), (usize, i16)> = BTreeMap::new();
        for (order, &(x, y, v)) in cells.iter().enumerate() {
            let entry = last.entry((x, y)).or_insert((order, v));
            entry.1 = v;
        }
        let mut net: Vec<(usize, (i64, i64, i16))> = last
            .into_iter()
            .filter(|&((x, y), (_, v))| {
                !map.contains(x, y) || !(v == 0 || v == 1) || i16::from(map.is_obstacle(x, y)) != v
            })
            .map(|((x, y), (order, v))| (order, (x, y, v)))
            .collect();
        net.sort_unstable_by_key(|e| e.0);
        net.into_iter().map(|e| e.1).collect()
    }

    /// The same update stamped `tm`.
    pub fn at(mut self, tm: Time) -> Self {
        self.tm = tm;
        self
    }

    /// The cells listed, as `(x, y, value)`.
    pub fn cells(&self) -> impl Iterator<Item = (i32, i32, i16)> + '_ {
        self.x
            .iter()
            .zip(&self.y)
            .zip(&self.value)
            .map(|((&x, &y), &v)| (x, y, v))
    }

    /// Checks the update against `map` (spec §2 Decision "atomic"): each array has `num`
    /// entries, every cell is inside the map, every value is 0 or 1, and the timestamp's
    /// `nsec` is below 10⁹ (spec §4 Decision 0.2). Nothing is changed.
    pub fn check(&self, map: &GridMap) -> Result<(), MapError> {
        // The one timestamp check (spec §4 Decision 0.2), as every component makes it.
        self.tm
            .checked("MapUpdate")
            .map_err(|e| MapError::BadTimestamp {
                what: e.what,
                nsec: e.nsec,
            })?;
        for (array, len) in [
            ("X", self.x.len()),
            ("Y", self.y.len()),
            ("value", self.value.len()),
        ] {
            if self.num < 0 || len != self.num as usize {
                return Err(MapError::UpdateLength {
                    array,
                    len,
                    num: i64::from(self.num),
                });
            }
        }
        for (i, (x, y, v)) in self.cells().enumerate() {
            let (cx, cy) = (i64::from(x), i64::from(y));
            if !map.contains(cx, cy) {
                return Err(MapError::CellOutside {
                    what: "MapUpdate",
                    x: cx,
                    y: cy,
                    width: map.width(),
                    height: map.height(),
                });
            }
            if !(0..=1).contains(&v) {
                return Err(MapError::BadCellValue {
                    what: "value",
                    index: i,
                    value: i64::from(v),
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stroke_nets_to_the_cells_it_changes_each_once_in_order() {
        // 4 × 3 cells, (1, 1) an obstacle.
        let mut data = [0i16; 12];
        data[1 + 4] = 1;
        let map = GridMap::from_map_data(&data, 4, 3, 0.5).unwrap();
        // (2, 0) twice, (1, 1) already an obstacle, (0, 0) painted then erased.
        let stroke = [
            (2, 0, 1),
            (1, 1, 1),
            (0, 0, 1),
            (2, 0, 1),
            (3, 2, 1),
            (0, 0, 0),
        ];
        assert_eq!(
            MapUpdate::net_changes(&stroke, &map),
            [(2, 0, 1), (3, 2, 1)]
        );
        // Nothing changes: nothing to send.
        assert!(MapUpdate::net_changes(&[(1, 1, 1), (0, 0, 0)], &map).is_empty());
        // Bad cells stay, so the update is refused as a whole.
        let bad = MapUpdate::net_changes(&[(0, 0, 1), (9, 9, 1), (1, 0, 7)], &map);
        assert_eq!(bad, [(0, 0, 1), (9, 9, 1), (1, 0, 7)]);
        assert!(
            MapUpdate::from_cells(&bad, Time::default())
                .check(&map)
                .is_err()
        );
    }
}
