//! Where the files are: the project's root (fixtures, scenarios) and the shared data
//! (`RTNAV_DATA`, else `../shared/data` beside the project's root), read in place.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use rtnav::system::{DirResolver, FileResolver};

/// The project's root: the first folder, from the working folder up, that holds
/// `fixtures/scenarios`; else the one this crate was built in.
pub fn project_root() -> PathBuf {
    let here = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    here.ancestors()
        .find(|d| d.join("fixtures/scenarios").is_dir())
        .map(Path::to_path_buf)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join(".."))
}

/// The shared data folder: `RTNAV_DATA` if set, else `ROOT/../shared/data`; `None` if it
/// does not exist.
pub fn data_dir(root: &Path) -> Option<PathBuf> {
    let dir = match std::env::var_os("RTNAV_DATA") {
        Some(d) => PathBuf::from(d),
        None => root.join("../shared/data"),
    };
    dir.is_dir().then_some(dir)
}

/// The prefix scenarios use for the shared data.
const SHARED: &str = "../shared/data/";

/// Files relative to the project's root, with `../shared/data/…` read from [`data_dir`].
#[derive(Debug, Clone)]
pub struct DataResolver {
    root: DirResolver,
    data: Option<DirResolver>,
}

impl DataResolver {
    /// For the project at `root`.
    pub fn new(root: &Path) -> Self {
        Self {
            root: DirResolver::new(root),
            data: data_dir(root).map(DirResolver::new),
        }
    }

    /// Whether the shared data is there.
    pub fn has_data(&self) -> bool {
        self.data.is_some()
    }
}

impl FileResolver for DataResolver {
    fn read(&self, path: &str) -> Result<Cow<'_, [u8]>, rtnav::errors::SystemError> {
        match (path.strip_prefix(SHARED), &self.data) {
            (Some(rest), Some(data)) => data.read(rest),
            _ => self.root.read(path),
        }
    }
}
