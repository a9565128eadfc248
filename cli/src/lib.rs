//! The `rtnav` runner's library: what its subcommands share and what tests (and the
//! reliability tools of `rtnav-stress`) use.
//!
//! - [`words`]: the command line's words for the core's facts, from the page's English
//!   catalogue.
//! - [`scenario_file`]: the scenario file's JSON Schema and the check of a file against it.
//! - [`scenario_load`]: a scenario file read, the folder its paths are relative to, the
//!   project's root.
//! - [`script_load`]: a student's script compiled and the component it stands in for
//!   decided (`--script`, `--component`); how it failed in a run.
//! - [`error`]: [`CliError`](error::CliError), what can go wrong for a subcommand.
//!
//! The external data (`../shared/data`, or `$RTNAV_DATA`) is found by `rtnav::data`.

pub mod error;
pub mod scenario_file;
pub mod scenario_load;
pub mod script_load;
pub mod words;

pub use scenario_load::project_root;
