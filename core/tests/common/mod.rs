//! What the whole-system tests share: the repository's root and its fixture scenarios, loaded
//! as the page loads them (the scenario and its JSON map through a `MemoryResolver`).
// Each test crate uses what it needs of this module.
#![allow(dead_code)]

use std::path::Path;

use rtnav::system::{MapSource, MemoryResolver, Scenario, Session};

/// The repository's root.
pub fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// `fixtures/scenarios/NAME.json` and its map, as files in memory.
pub fn scenario(name: &str) -> (Scenario, MemoryResolver) {
    let json =
        std::fs::read_to_string(root().join(format!("fixtures/scenarios/{name}.json"))).unwrap();
    let s = Scenario::from_json(&json).unwrap();
    let MapSource::Json { path } = &s.map else {
        panic!("test scenarios use JSON maps");
    };
    let files = MemoryResolver::new().with(path, std::fs::read(root().join(path)).unwrap());
    (s, files)
}

/// A session with the fixture scenario `name` loaded.
pub fn loaded(name: &str) -> Session {
    let (s, files) = scenario(name);
    let mut session = Session::new().unwrap();
    session.load_scenario(s, &files).unwrap();
    session
}
