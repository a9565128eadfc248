//! A scenario file read for the command line's tools, and the folder its paths are
//! relative to.

use std::path::{Path, PathBuf};

use rtnav::data::RepoResolver;
use rtnav::scenario_data::map_file;
use rtnav::system::Scenario;

use crate::error::{CliError, CliResult};

/// The scenario in the file `path`.
pub fn read_scenario(path: &Path) -> CliResult<Scenario> {
    let text = std::fs::read_to_string(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    Scenario::from_json(&text).map_err(CliError::in_file(path))
}

/// The scenario in the file `path` and the resolver of its paths: under `root`, else under
/// [`find_root`].
pub fn load(path: &Path, root: Option<PathBuf>) -> CliResult<(Scenario, RepoResolver)> {
    let scenario = read_scenario(path)?;
    let root = root.unwrap_or_else(|| find_root(path, &scenario));
    Ok((scenario, RepoResolver::new(root)))
}

/// The first ancestor of the scenario file (then the working folder) in which the
/// scenario's map file exists (a map of the external data: where it exists for that root).
pub fn find_root(path: &Path, scenario: &Scenario) -> PathBuf {
    let map = map_file(scenario);
    let start = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    start
        .ancestors()
        .skip(1)
        .find(|dir| {
            RepoResolver::new(*dir)
                .locate(map)
                .is_ok_and(|file| file.exists())
        })
        .map(Path::to_path_buf)
        .unwrap_or_else(|| PathBuf::from("."))
}

/// The project's root: the first folder, from the working folder up, that holds
/// `fixtures/scenarios`; else the one this crate was built in.
pub fn project_root() -> PathBuf {
    let here = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    here.ancestors()
        .find(|d| d.join("fixtures/scenarios").is_dir())
        .map(Path::to_path_buf)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join(".."))
}
