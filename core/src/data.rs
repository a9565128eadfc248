//! External data: real maps nobody on the project wrote (the MovingAI grid benchmark, ROS
//! map_server maps), read in place at run time and never copied into the repository.
//!
//! The folder is `$RTNAV_DATA` if that variable is set, else `../shared/data` next to the
//! repository's root. Scenario files name a file of it as `../shared/data/<file>` (relative to
//! the repository's root, as every scenario path is); [`RepoResolver`] reads such a path from
//! wherever the folder really is. A clone without the folder still builds and passes its
//! tests: whatever needs the data says on one line that it is skipped and why
//! ([`DataMissing`]'s message).
//!
//! Nothing here runs in wasm32 but [`data_relative`]: the page and the wasm tests are handed
//! the bytes by JavaScript.

/// The environment variable that names the data folder.
pub const DATA_ENV: &str = "RTNAV_DATA";

/// Where the data folder is when [`DATA_ENV`] is not set, relative to the repository's root.
pub const DEFAULT_DATA_DIR: &str = "../shared/data";

/// How a scenario names a file of the data folder: this prefix, then the file's path inside
/// the folder (e.g. `../shared/data/movingai/dao/arena.map`).
pub const DATA_PREFIX: &str = "../shared/data/";

/// The path inside the data folder of a scenario path that names external data
/// (`../shared/data/movingai/dao/arena.map` → `movingai/dao/arena.map`), `None` for a path
/// in the repository.
pub fn data_relative(path: &str) -> Option<&str> {
    let mut p = path;
    while let Some(rest) = p.strip_prefix("./") {
        p = rest;
    }
    p.strip_prefix(DATA_PREFIX).filter(|rest| !rest.is_empty())
}

/// Why the external data cannot be used: the message names the folder looked for and how to
/// point at another one.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "external data not found: {looked} (set {DATA_ENV} to the folder that holds `movingai/` and `rosmaps/`)"
)]
pub struct DataMissing {
    /// What was looked for, e.g. `RTNAV_DATA=/x is not a folder`.
    pub looked: String,
}

#[cfg(not(target_arch = "wasm32"))]
pub use native::{RepoResolver, data_dir, data_dir_with};

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use std::borrow::Cow;
    use std::path::{Path, PathBuf};

    use super::*;
    use crate::errors::ScenarioError;
    use crate::system::FileResolver;

    /// The data folder for the repository at `repo_root`: `$RTNAV_DATA` if set, else
    /// `repo_root/../shared/data`; an error if that is not a folder.
    pub fn data_dir(repo_root: &Path) -> Result<PathBuf, DataMissing> {
        data_dir_with(repo_root, std::env::var_os(DATA_ENV).map(PathBuf::from))
    }

    /// [`data_dir`] with the variable's value given (`None`: unset).
    pub fn data_dir_with(repo_root: &Path, var: Option<PathBuf>) -> Result<PathBuf, DataMissing> {
        match var {
            Some(dir) if dir.as_os_str().is_empty() => Err(DataMissing {
                looked: format!("{DATA_ENV} is set but empty"),
            }),
            Some(dir) if dir.is_dir() => Ok(dir),
            Some(dir) => Err(DataMissing {
                looked: format!("{DATA_ENV}={} is not a folder", dir.display()),
            }),
            None => {
                let dir = repo_root.join(DEFAULT_DATA_DIR);
                if dir.is_dir() {
                    Ok(dir)
                } else {
                    Err(DataMissing {
                        looked: format!(
                            "{DATA_ENV} is unset and {} is not a folder",
                            dir.display()
                        ),
                    })
                }
            }
        }
    }

    /// Files of the repository (paths relative to its root) and of the external data folder
    /// (paths that start with [`DATA_PREFIX`]), from the filesystem.
    #[derive(Debug, Clone)]
    pub struct RepoResolver {
        root: PathBuf,
        data: Result<PathBuf, DataMissing>,
    }

    impl RepoResolver {
        /// The repository at `root`, the data folder found by [`data_dir`].
        pub fn new(root: impl Into<PathBuf>) -> Self {
            let root = root.into();
            let data = data_dir(&root);
            Self { root, data }
        }

        /// The repository at `root` and the data folder `data` (or why there is none).
        pub fn with_data(root: impl Into<PathBuf>, data: Result<PathBuf, DataMissing>) -> Self {
            Self {
                root: root.into(),
                data,
            }
        }

        /// The repository's root.
        pub fn root(&self) -> &Path {
            &self.root
        }

        /// The data folder, or why there is none.
        pub fn data(&self) -> Result<&Path, &DataMissing> {
            self.data.as_deref()
        }

        /// Where `path` (as a scenario writes it) is on disk.
        pub fn locate(&self, path: &str) -> Result<PathBuf, DataMissing> {
            match data_relative(path) {
                Some(rest) => self
                    .data
                    .as_ref()
                    .map(|d| d.join(rest))
                    .map_err(Clone::clone),
                None => Ok(self.root.join(path)),
            }
        }
    }

    impl FileResolver for RepoResolver {
        fn read(&self, path: &str) -> Result<Cow<'_, [u8]>, ScenarioError> {
            let full = self.locate(path).map_err(|e| ScenarioError::File {
                path: path.to_owned(),
                reason: e.to_string(),
            })?;
            std::fs::read(&full)
                .map(Cow::Owned)
                .map_err(|e| ScenarioError::File {
                    path: path.to_owned(),
                    reason: match data_relative(path) {
                        Some(_) => format!(
                            "{} in the external data folder: {e} (the folder is ${DATA_ENV}, \
                             else {DEFAULT_DATA_DIR} next to the repository)",
                            full.display()
                        ),
                        None => format!("{}: {e}", full.display()),
                    },
                })
        }
    }
}

#[cfg(test)]
#[cfg(not(target_arch = "wasm32"))]
mod tests {
    use std::path::{Path, PathBuf};

    use super::*;
    use crate::system::FileResolver;

    #[test]
    fn scenario_paths_under_the_prefix_name_data_files() {
        let cases = [
            (
                "../shared/data/movingai/dao/arena.map",
                Some("movingai/dao/arena.map"),
            ),
            ("./../shared/data/rosmaps/w.yaml", Some("rosmaps/w.yaml")),
            ("../shared/data/", None),
            ("fixtures/maps/tiny.yaml", None),
            ("../shared/SPEC.md", None),
        ];
        for (path, expect) in cases {
            assert_eq!(data_relative(path), expect, "{path}");
        }
    }

    fn here() -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
    }

    #[test]
    fn the_variable_wins_and_a_missing_folder_says_where_it_looked() {
        let root = here();
        assert_eq!(
            data_dir_with(&root, Some(root.join("src"))),
            Ok(root.join("src"))
        );
        let e = data_dir_with(&root, Some(PathBuf::from("/nonexistent/rtnav-data"))).unwrap_err();
        assert_eq!(
            e.to_string(),
            "external data not found: RTNAV_DATA=/nonexistent/rtnav-data is not a folder \
             (set RTNAV_DATA to the folder that holds `movingai/` and `rosmaps/`)"
        );
        let e = data_dir_with(&root, Some(PathBuf::new())).unwrap_err();
        assert_eq!(e.looked, "RTNAV_DATA is set but empty");
        // Unset: `../shared/data` beside the root (`core/` here, so `shared/data` holds it
        // only if someone made one; either way the answer names that folder).
        match data_dir_with(&root, None) {
            Ok(dir) => assert_eq!(dir, root.join("../shared/data")),
            Err(e) => assert_eq!(
                e.looked,
                format!(
                    "RTNAV_DATA is unset and {} is not a folder",
                    root.join("../shared/data").display()
                )
            ),
        }
    }

    #[test]
    fn the_resolver_reads_repository_files_and_maps_data_paths() {
        let root = here().join("..");
        let r = RepoResolver::with_data(&root, Ok(root.join("fixtures")));
        // In the repository.
        let bytes = r.read("fixtures/maps/tiny.yaml").unwrap();
        assert_eq!(
            bytes.as_ref(),
            std::fs::read(root.join("fixtures/maps/tiny.yaml")).unwrap()
        );
        // In the "data" folder (here the fixtures folder stands in for it).
        let bytes = r.read("../shared/data/maps/tiny.yaml").unwrap();
        assert_eq!(
            bytes.as_ref(),
            std::fs::read(root.join("fixtures/maps/tiny.yaml")).unwrap()
        );
        assert_eq!(
            r.locate("../shared/data/maps/x").unwrap(),
            root.join("fixtures/maps/x")
        );
        // A missing file of the data folder names the folder and the variable.
        let e = r.read("../shared/data/none.map").unwrap_err().to_string();
        assert!(
            e.starts_with("cannot read `../shared/data/none.map`: "),
            "{e}"
        );
        assert!(
            e.contains("in the external data folder") && e.contains("$RTNAV_DATA"),
            "{e}"
        );
        // No data folder at all: the reason is the DataMissing message.
        let missing = DataMissing {
            looked: "RTNAV_DATA=/nonexistent is not a folder".to_owned(),
        };
        let r = RepoResolver::with_data(&root, Err(missing.clone()));
        assert_eq!(r.data(), Err(&missing));
        let e = r
            .read("../shared/data/movingai/dao/arena.map")
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            format!("cannot read `../shared/data/movingai/dao/arena.map`: {missing}")
        );
        assert!(r.read("fixtures/maps/tiny.yaml").is_ok());
        assert_eq!(r.root(), Path::new(&root));
    }
}
