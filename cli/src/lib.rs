//! The `rtnav` runner's library: the reliability tools behind `rtnav fuzz` and `rtnav soak`,
//! kept apart from the binary so that tests can drive them.
//!
//! - [`alloc`]: a counting allocator (a binary installs it) for allocation bounds and memory;
//! - [`rng`]: the tools' seeded random numbers (the core reads none);
//! - [`fuzz`]: the fuzzer — one target per reader and per kind of hostile call;
//! - [`soak`]: hours of simulated closed loop with random goals and map edits;
//! - [`words`]: the command line's words for the core's facts, from the page's English
//!   catalogue.
//! - [`scenario_file`]: the scenario file's JSON Schema and the check of a file against it.
//!
//! The external data (`../shared/data`, or `$RTNAV_DATA`) is found by `rtnav::data`.

pub mod alloc;
pub mod fuzz;
pub mod rng;
pub mod scenario_file;
pub mod soak;
pub mod words;

use std::path::{Path, PathBuf};

/// The project's root: the first folder, from the working folder up, that holds
/// `fixtures/scenarios`; else the one this crate was built in.
pub fn project_root() -> PathBuf {
    let here = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    here.ancestors()
        .find(|d| d.join("fixtures/scenarios").is_dir())
        .map(Path::to_path_buf)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join(".."))
}
