//! MapBuilder (spec §0, §5 "MapBuilder / MapMaintenance"): holds the loaded map and sends it
//! as `SetMap` to the components that need it.
//!
//! In OpenINVENT the map came from a MapBuilder component through the `SetMap` service of
//! LocalPathPlanning (000 §3.2.2.1 (4)) and the other planners. Here MapBuilder holds the
//! map the GUI (or a scenario) loaded and writes it to its `SetMap` OutPort; the system
//! (`crate::system::System`) reads that port between ticks and makes the `SetMap` service
//! calls on GlobalPathPlanning, LocalPathPlanning, MapMaintenance and the physics.
//!
//! A load is a service call: it is carried out at once, in any lifecycle state (an
//! OpenRTM service port answers whether or not the component is Active). Loading a map
//! cannot fail here: a [`GridMap`] that exists is valid (files are read and checked by
//! `crate::map::formats` before they get here, and a bad file leaves the held map as it is).

use std::rc::Rc;

use crate::map::GridMap;
use crate::rtc::{Component, OutPort, Time};

/// What MapBuilder sends on `SetMap`: the whole map, shared (the consumers copy what they
/// keep).
#[derive(Debug, Clone, PartialEq)]
pub struct SetMapMessage {
    /// When it was sent.
    pub tm: Time,
    /// The map.
    pub map: Rc<GridMap>,
    /// Counts the maps loaded (1 for the first): tells a new load from a resend.
    pub load: u64,
}

/// The MapBuilder RT-component.
#[derive(Debug, Clone)]
pub struct MapBuilder {
    name: String,
    map: Option<Rc<GridMap>>,
    loads: u64,
    /// `SetMap` (out): the held map, sent on every load and resend.
    pub set_map: OutPort<SetMapMessage>,
}

impl Default for MapBuilder {
    fn default() -> Self {
        Self::new("MapBuilder0")
    }
}

impl MapBuilder {
    /// A MapBuilder named `name`, holding no map.
    pub fn new(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            map: None,
            loads: 0,
            set_map: OutPort::new("SetMap"),
        }
    }

    /// Holds `map` (replacing the old one) and sends it on `SetMap` at once.
    pub fn load(&mut self, map: GridMap, tm: Time) {
        self.loads += 1;
        self.map = Some(Rc::new(map));
        self.resend(tm);
    }

    /// Sends the held map again (e.g. after LocalPathPlanning's `Clear` dropped its copy).
    /// Returns whether a map was held.
    pub fn resend(&mut self, tm: Time) -> bool {
        let Some(map) = self.map.clone() else {
            return false;
        };
        self.set_map.write(SetMapMessage {
            tm,
            map,
            load: self.loads,
        });
        true
    }

    /// The held map as loaded (MapUpdates are not applied to it: MapMaintenance holds the
    /// current map).
    pub fn map(&self) -> Option<&GridMap> {
        self.map.as_deref()
    }

    /// How many maps were loaded.
    pub fn load_count(&self) -> u64 {
        self.loads
    }
}

impl Component for MapBuilder {
    component_basics!(name: name);

    component_ports!(in: [], out: [set_map]);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rtc::InPort;

    #[test]
    fn load_and_resend_write_set_map() {
        let mut b = MapBuilder::default();
        let rx = InPort::new("SetMap");
        b.set_map.connect(&rx);
        assert!(!b.resend(Time::default()));
        assert!(!rx.is_new());
        let map = GridMap::from_map_data(&[0, 1, 0, 0], 2, 2, 0.5).unwrap();
        b.load(map.clone(), Time::from_nanos(5));
        let m = rx.read().unwrap();
        assert_eq!((*m.map).clone(), map);
        assert_eq!((m.load, m.tm), (1, Time::from_nanos(5)));
        assert!(b.resend(Time::from_nanos(7)));
        assert_eq!(rx.read().unwrap().load, 1);
        assert_eq!(b.map(), Some(&map));
        assert_eq!(b.load_count(), 1);
    }
}
