//! What can go wrong for the command line's tools, as one error type: `rtnav` prints it as
//! `rtnav: error: …` and exits 2.

use std::path::PathBuf;

use crate::words::Words;

/// An error of a subcommand (its usage, its files, or the core refusing what it was given).
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// A file could not be read.
    #[error("cannot read `{}`: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A folder's files could not be listed.
    #[error("cannot read folder `{}`: {source}", path.display())]
    ReadFolder {
        /// The folder.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A file could not be written.
    #[error("cannot write `{}`: {source}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A path named on the command line does not exist.
    #[error("`{}`: no such file or folder", path.display())]
    NoSuchPath {
        /// The path.
        path: PathBuf,
    },
    /// The core refused something; said in the catalogue's words ([`Words::error`]).
    #[error("{}", Words::english().error(.0))]
    Core(Box<rtnav::Error>),
    /// The core refused the content of a file; said in the catalogue's words, with the file.
    #[error("{}", in_file(path, error))]
    InFile {
        /// The file.
        path: PathBuf,
        /// What the core found wrong in it.
        error: Box<rtnav::Error>,
    },
    /// An option's value that the core refused (`--a`, `--b`).
    #[error("{option}: {}", Words::english().error(error))]
    Option {
        /// The option, e.g. `--a`.
        option: &'static str,
        /// What the core found wrong.
        error: Box<rtnav::Error>,
    },
    /// A student's script that is not loaded (`--script`): it does not compile, names no
    /// component, or the core refuses it in the component's place; the reason names the
    /// line and column where it has them.
    #[error("`{}`: {reason}", path.display())]
    Script {
        /// The script file.
        path: PathBuf,
        /// Why, with the line and column.
        reason: String,
    },
    /// Options that do not go together, or a value out of its range.
    #[error("{0}")]
    Usage(&'static str),
    /// A number option out of its range.
    #[error("{option} {value}: must be {range}")]
    OutOfRange {
        /// The option, e.g. `--hours`.
        option: &'static str,
        /// The value given.
        value: f64,
        /// What it must be, e.g. `a positive number`.
        range: &'static str,
    },
    /// A replay names something that is not a scenario's name.
    #[error("the replay names scenario `{0}`, not a scenario name")]
    NotAScenarioName(String),
    /// The scenario file of a replay's scenario is nowhere to be found.
    #[error(
        "scenario `{name}`: no {} above `{}` or the working folder (give --root)",
        file.display(),
        near.display()
    )]
    ScenarioNotFound {
        /// The scenario's name.
        name: String,
        /// The file looked for, relative to a root.
        file: PathBuf,
        /// Where the search started.
        near: PathBuf,
    },
    /// `rtnav check` on a scenario without an exercise.
    #[error("scenario `{0}` has no exercise")]
    NoExercise(String),
    /// `rtnav check` found no hand-in where it was told to look.
    #[error("no hand-ins: no *.{extension} file in {places}")]
    NoHandIns {
        /// The file name ending looked for.
        extension: &'static str,
        /// The paths given, quoted.
        places: String,
    },
    /// The pool of threads `rtnav check` judges a class with.
    #[error(transparent)]
    Threads(#[from] rayon::ThreadPoolBuildError),
    /// A value that could not be written as JSON.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
}

impl CliError {
    /// An error of the core (any area's error).
    pub fn core(e: impl Into<rtnav::Error>) -> Self {
        Self::Core(Box::new(e.into()))
    }

    /// An error of the core about the content of `path`.
    pub fn in_file<E: Into<rtnav::Error>>(path: impl Into<PathBuf>) -> impl FnOnce(E) -> Self {
        let path = path.into();
        move |error| Self::InFile {
            path,
            error: Box::new(error.into()),
        }
    }
}

/// A subcommand's result.
pub type CliResult<T> = Result<T, CliError>;

/// An error of the core about the file `path`, in the catalogue's words.
fn in_file(path: &std::path::Path, e: &rtnav::Error) -> String {
    let words = Words::english();
    let file = path.display().to_string();
    words.t(
        "error.in_file",
        &serde_json::json!({ "file": file, "error": words.error(e) }),
    )
}
