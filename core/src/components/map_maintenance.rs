//! MapMaintenance (SPEC §0, §5 "MapBuilder / MapMaintenance"): obstacles added or removed
//! at run time, sent as `MapUpdate` (000 §3.2.2.1 (5), SPEC §2).
//!
//! It holds the current map (given by `SetMap`, with every update applied), so an update is
//! checked completely when it is asked for: a bad one (array lengths ≠ `num`, a cell outside
//! the map, a value other than 0/1) is refused with an error and nothing changes (SPEC §2
//! Decision "atomic").
//!
//! Two ways in:
//! - [`MapMaintenance::map_update`]: a service call (the GUI's obstacle brush): applied to the
//!   held map and written to the `MapUpdate` OutPort at once, in any lifecycle state.
//! - [`MapMaintenance::schedule`]: a queued update with a due time (a scenario's obstacle
//!   that appears while the robot drives). Each `on_execute` sends every queued update whose
//!   time has come, in time order (equal times in the order they were queued). An update
//!   that has become invalid by then (the map was replaced) is dropped and reported
//!   ([`MapMaintenance::last_error`]); the component does not fail for it.
//!
//! The system (`crate::system::System`) reads `MapUpdate` between ticks and makes the
//! `MapUpdate` service calls on GlobalPathPlanning, LocalPathPlanning and the physics.

use crate::errors::{MapError, SystemError};
use crate::map::GridMap;
use crate::rtc::{Component, OutPort, ReturnCode, Tick, Time};

/// `MapUpdate(X[], Y[], value[], num, sec, nsec)` (000 §3.2.2.1 (5)): cells to set, 0 free /
/// 1 obstacle.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
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

    /// The same update stamped `tm`.
    pub fn at(mut self, tm: Time) -> Self {
        self.tm = tm;
        self
    }

    /// Checks the update against `map` as `GridMap::map_update` does, without changing it.
    pub fn check(&self, map: &GridMap) -> Result<(), MapError> {
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
        for (i, ((&x, &y), &v)) in self.x.iter().zip(&self.y).zip(&self.value).enumerate() {
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

/// A queued update and its due time.
#[derive(Debug, Clone, PartialEq)]
struct Scheduled {
    due_ns: u64,
    update: MapUpdate,
}

/// The MapMaintenance RT-component.
#[derive(Debug)]
pub struct MapMaintenance {
    name: String,
    map: Option<GridMap>,
    queue: Vec<Scheduled>,
    last_error: Option<String>,
    sent: u64,
    /// `MapUpdate` (out): every accepted update, in the order applied.
    pub map_update_out: OutPort<MapUpdate>,
}

impl Default for MapMaintenance {
    fn default() -> Self {
        Self::new("MapMaintenance0")
    }
}

impl MapMaintenance {
    /// A MapMaintenance named `name`, holding no map.
    pub fn new(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            map: None,
            queue: Vec::new(),
            last_error: None,
            sent: 0,
            map_update_out: OutPort::new("MapUpdate"),
        }
    }

    /// `SetMap`: holds `map` as the current map. Queued updates stay queued (they are
    /// checked against the new map when due).
    pub fn set_map(&mut self, map: GridMap) {
        self.map = Some(map);
    }

    /// The current map: the last `SetMap` with every update since applied.
    pub fn map(&self) -> Option<&GridMap> {
        self.map.as_ref()
    }

    /// `MapUpdate` now: applied to the held map and sent. Returns the number of cells that
    /// changed. Refused (nothing changes, nothing is sent) without a map or for a bad update.
    pub fn map_update(&mut self, update: MapUpdate) -> crate::Result<usize> {
        let map = self
            .map
            .as_mut()
            .ok_or(SystemError::NoMap { call: "MapUpdate" })?;
        let changed = map.map_update(&update.x, &update.y, &update.value, update.num, update.tm)?;
        self.map_update_out.write(update);
        self.sent += 1;
        Ok(changed)
    }

    /// Queues `update` to be applied and sent by the first `on_execute` at or after
    /// `due_ns` (simulated time). It is checked against the held map now; a bad one is
    /// refused and nothing is queued.
    pub fn schedule(&mut self, due_ns: u64, update: MapUpdate) -> crate::Result<()> {
        let map = self.map.as_ref().ok_or(SystemError::NoMap {
            call: "MapUpdate (scheduled)",
        })?;
        update.check(map)?;
        let at = self.queue.partition_point(|s| s.due_ns <= due_ns);
        self.queue.insert(at, Scheduled { due_ns, update });
        Ok(())
    }

    /// Number of queued updates.
    pub fn pending(&self) -> usize {
        self.queue.len()
    }

    /// Due time of the next queued update \[ns\].
    pub fn next_due_ns(&self) -> Option<u64> {
        self.queue.first().map(|s| s.due_ns)
    }

    /// Drops every queued update.
    pub fn clear_queue(&mut self) {
        self.queue.clear();
    }

    /// Why the last queued update was dropped.
    pub fn last_error(&self) -> Option<&str> {
        self.last_error.as_deref()
    }

    /// Updates sent so far.
    pub fn sent_count(&self) -> u64 {
        self.sent
    }
}

impl Component for MapMaintenance {
    fn instance_name(&self) -> &str {
        &self.name
    }

    /// Sends every queued update that is due, in one `MapUpdate` stamped with this tick's
    /// time (an InPort keeps only the newest value, so one message per tick loses nothing;
    /// a cell listed twice takes its last value, as if applied one after the other).
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        let due = self.queue.partition_point(|s| s.due_ns <= tick.time_ns);
        if due == 0 {
            return Ok(());
        }
        let Some(map) = self.map.as_mut() else {
            self.last_error = Some("queued MapUpdate dropped: no map".to_owned());
            self.queue.drain(..due);
            return Ok(());
        };
        let mut combined = MapUpdate {
            tm: tick.tm(),
            ..MapUpdate::default()
        };
        for s in self.queue.drain(..due) {
            let u = s.update;
            match map.map_update(&u.x, &u.y, &u.value, u.num, tick.tm()) {
                Ok(_) => {
                    combined.x.extend(&u.x);
                    combined.y.extend(&u.y);
                    combined.value.extend(&u.value);
                }
                Err(e) => {
                    self.last_error = Some(format!(
                        "queued MapUpdate due at {} s dropped: {e}",
                        s.due_ns as f64 * 1e-9
                    ));
                }
            }
        }
        if !combined.x.is_empty() {
            combined.num = i32::try_from(combined.x.len()).unwrap_or(i32::MAX);
            self.map_update_out.write(combined);
            self.sent += 1;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rtc::InPort;

    fn map() -> GridMap {
        GridMap::from_map_data(&[0; 12], 4, 3, 0.5).unwrap()
    }

    #[test]
    fn updates_are_checked_applied_and_sent_in_time_order() {
        let mut m = MapMaintenance::default();
        let rx = InPort::new("MapUpdate");
        m.map_update_out.connect(&rx);
        let one = MapUpdate::from_cells(&[(1, 1, 1)], Time::default());
        assert!(m.map_update(one.clone()).is_err(), "no map yet");
        m.set_map(map());
        assert!(
            m.map_update(MapUpdate::from_cells(&[(4, 0, 1)], Time::default()))
                .is_err()
        );
        assert!(
            m.map_update(MapUpdate::from_cells(&[(0, 0, 2)], Time::default()))
                .is_err()
        );
        let mut bad = one.clone();
        bad.num = 2;
        assert!(m.schedule(0, bad).is_err());
        assert!(!rx.is_new());
        assert_eq!(m.map_update(one).unwrap(), 1);
        assert!(m.map().unwrap().is_obstacle(1, 1));
        assert_eq!(rx.read().unwrap().x, vec![1]);

        let tick = |ms: u64| Tick {
            time_ns: ms * 1_000_000,
            period_ns: 100_000_000,
            index: ms,
        };
        m.schedule(
            300_000_000,
            MapUpdate::from_cells(&[(2, 2, 1)], Time::default()),
        )
        .unwrap();
        m.schedule(
            200_000_000,
            MapUpdate::from_cells(&[(3, 2, 1)], Time::default()),
        )
        .unwrap();
        m.schedule(
            200_000_000,
            MapUpdate::from_cells(&[(3, 1, 1)], Time::default()),
        )
        .unwrap();
        assert_eq!((m.pending(), m.next_due_ns()), (3, Some(200_000_000)));
        m.on_execute(&tick(100)).unwrap();
        assert!(!rx.is_new());
        m.on_execute(&tick(200)).unwrap();
        // Both due updates in one message, in queue order.
        let last = rx.read().unwrap();
        assert_eq!(
            (last.x.clone(), last.y.clone(), last.num),
            (vec![3, 3], vec![2, 1], 2)
        );
        assert_eq!(last.tm, Time::from_nanos(200_000_000));
        assert!(m.map().unwrap().is_obstacle(3, 2) && m.map().unwrap().is_obstacle(3, 1));
        assert_eq!(m.pending(), 1);
        // The map is replaced by a smaller one: the queued update no longer fits.
        m.set_map(GridMap::from_map_data(&[0; 4], 2, 2, 0.5).unwrap());
        m.on_execute(&tick(300)).unwrap();
        assert_eq!(m.pending(), 0);
        assert!(m.last_error().unwrap().contains("outside"));
        assert_eq!(m.sent_count(), 2);
    }
}
