//! The files the fixture scenarios name: the repository's maps compiled in (wasm has no
//! filesystem of its own), the external data's read at run time.

use std::borrow::Cow;

use rtnav::data::{DataMissing, data_relative};
use rtnav::errors::ScenarioError;
use rtnav::system::{FileResolver, MapSource, MemoryResolver, Scenario};

use crate::data::Data;

macro_rules! map {
    ($name:literal) => {
        (
            concat!("fixtures/maps/scenarios/", $name, ".json"),
            &include_bytes!(concat!("../fixtures/maps/scenarios/", $name, ".json"))[..],
        )
    };
}

/// The files a scenario names: the repository's maps compiled in (wasm has no filesystem of
/// its own), the external data's (`../shared/data/…`) read at run time from wherever
/// [`Data`] finds the folder.
#[allow(missing_debug_implementations)]
pub struct Files {
    fixtures: MemoryResolver,
    data: Option<Data>,
}

impl FileResolver for Files {
    fn read(&self, path: &str) -> Result<Cow<'_, [u8]>, ScenarioError> {
        let Some(rel) = data_relative(path) else {
            return self.fixtures.read(path);
        };
        let missing = |reason: String| ScenarioError::File {
            path: path.to_owned(),
            reason,
        };
        let data = self
            .data
            .as_ref()
            .ok_or_else(|| missing("no external data folder".to_owned()))?;
        data.read(rel).map(Cow::Owned).map_err(missing)
    }
}

/// The files for `scenario`, or why it must be skipped: it names external data and there is
/// no data folder.
pub fn files(scenario: &Scenario) -> Result<Files, DataMissing> {
    let mut fixtures = MemoryResolver::new();
    for (path, bytes) in [
        map!("open_field"),
        map!("corridor_turn"),
        map!("parking_wall"),
        map!("appearing_obstacle"),
        map!("backward_dock"),
        map!("unreachable"),
    ] {
        fixtures.insert(path, bytes);
    }
    let external = match &scenario.map {
        MapSource::Json { path } | MapSource::Movingai { path, .. } => path,
        MapSource::Ros { yaml, .. } => yaml,
    };
    let data = match data_relative(external) {
        Some(_) => Some(Data::locate()?),
        None => None,
    };
    Ok(Files { fixtures, data })
}
