//! MapMaintenance (spec §0, §5 "MapBuilder / MapMaintenance"): obstacles added or removed at
//! run time, sent as `MapUpdate` (000 §3.2.2.1 (5), spec §2).
//!
//! It holds the current map (given by `SetMap`, with every update applied), so an update is
//! checked completely when it is asked for: a bad one (array lengths ≠ `num`, a cell outside
//! the map, a value other than 0/1, a bad timestamp) is refused with an error and nothing
//! changes (spec §2 Decision "atomic"). An accepted update that changes at least one cell is
//! written to the `MapUpdate` OutPort at once, in any lifecycle state; one that changes
//! nothing is not sent (spec §3 Decision: it requests nothing). Timed updates (a scenario's
//! obstacle that appears while the robot drives) are the timeline's: it makes this same call
//! at their time.
//!
//! The system reads `MapUpdate` between ticks and makes the `MapUpdate` service calls on
//! GlobalPathPlanning, LocalPathPlanning, DriveControl and the physics.

use crate::errors::SystemError;
use crate::map::{GridMap, MapUpdate};
use crate::rtc::{Component, OutPort};

/// The MapMaintenance RT-component.
#[derive(Debug, Clone)]
pub struct MapMaintenance {
    name: String,
    map: Option<GridMap>,
    sent: u64,
    /// `MapUpdate` (out): every accepted update that changed the map, in the order applied.
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
            sent: 0,
            map_update_out: OutPort::new("MapUpdate"),
        }
    }

    /// `SetMap`: holds `map` as the current map.
    pub fn set_map(&mut self, map: GridMap) {
        self.map = Some(map);
    }

    /// The current map: the last `SetMap` with every update since applied.
    pub fn map(&self) -> Option<&GridMap> {
        self.map.as_ref()
    }

    /// `MapUpdate` now: checked, applied to the held map and, if a cell changed, sent.
    /// Returns the number of cells that changed. Refused (nothing changes, nothing is sent)
    /// without a map or for a bad update.
    pub fn map_update(&mut self, update: MapUpdate) -> crate::Result<usize> {
        let map = self
            .map
            .as_mut()
            .ok_or(SystemError::NoMap { call: "MapUpdate" })?;
        let changed = map.map_update(&update)?;
        if changed > 0 {
            self.map_update_out.write(update);
            self.sent += 1;
        }
        Ok(changed)
    }

    /// Updates sent so far.
    pub fn sent_count(&self) -> u64 {
        self.sent
    }
}

impl Component for MapMaintenance {
    component_basics!(name: name);

    component_ports!(in: [], out: [map_update_out]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rtc::{InPort, Time};

    fn map() -> GridMap {
        GridMap::from_map_data(&[0; 12], 4, 3, 0.5).unwrap()
    }

    #[test]
    fn updates_are_checked_applied_and_sent_only_when_they_change_a_cell() {
        let mut m = MapMaintenance::default();
        let rx = InPort::new("MapUpdate");
        m.map_update_out.connect(&rx);
        let one = MapUpdate::from_cells(&[(1, 1, 1)], Time::default());
        assert!(m.map_update(one.clone()).is_err(), "no map yet");
        m.set_map(map());
        for bad in [
            MapUpdate::from_cells(&[(4, 0, 1)], Time::default()),
            MapUpdate::from_cells(&[(0, 0, 2)], Time::default()),
            MapUpdate::from_cells(
                &[(0, 0, 1)],
                Time {
                    sec: 0,
                    nsec: 1_500_000_000,
                },
            ),
        ] {
            assert!(m.map_update(bad).is_err());
        }
        assert!(!rx.is_new());
        assert_eq!(m.map_update(one.clone()).unwrap(), 1);
        assert!(m.map().unwrap().is_obstacle(1, 1));
        assert_eq!(rx.read().unwrap().x, vec![1]);
        // The same cell again changes nothing and is not sent.
        assert_eq!(m.map_update(one).unwrap(), 0);
        assert!(!rx.is_new());
        assert_eq!(m.sent_count(), 1);
    }
}
