//! `rtnav scenario check FILE` and `rtnav scenario schema`: writing a scenario (an exercise)
//! without reading Rust (`docs/authoring.md`).
//!
//! `check` reads the file in two steps and stops at the first that finds something wrong:
//!
//! 1. **The schema** (`rtnav_cli::scenario_file`): every problem with its place — the path
//!    in the file and the line and column — in plain words.
//! 2. **The core**: the file read as the core reads it (numbers finite, event times in order
//!    and within the time limit, known components, the exercise's checks), the map loaded,
//!    the start and the goal on the map and out of the obstacles, the system set up and
//!    planned as the page does, a route found (unless the scenario expects a planning
//!    failure), and each parameter the exercise lets change known to its component.
//!
//! Exit code: 0 when the file is right, 1 when something is wrong, 2 when it cannot be read.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Args, Subcommand};
use rtnav::data::RepoResolver;
use rtnav::scenario_check::{Finding, ScenarioProblem, check_scenario};
use rtnav::system::Scenario;
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_file::{self, SCHEMA_PATH};
use rtnav_cli::scenario_load::find_root;

use crate::options::RootOption;

/// The actions of `rtnav scenario`.
#[derive(Debug, Subcommand)]
pub enum ScenarioAction {
    /// Check a scenario file: against the schema (each problem with its place in the file:
    /// path, line and column), then as the core reads it (the map loads, the start and the
    /// goal are on the map and free, the system sets up and plans, the exercise's
    /// parameters exist). Exits 0 when right, 1 when wrong, 2 when unreadable.
    Check(CheckArgs),
    /// Print the JSON Schema of scenario files (docs/scenario.schema.json).
    Schema,
}

/// The options of `rtnav scenario check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// The scenario file (JSON).
    file: PathBuf,
    #[command(flatten)]
    root: RootOption,
}

/// `rtnav scenario ACTION`.
pub fn scenario(action: ScenarioAction) -> CliResult<ExitCode> {
    match action {
        ScenarioAction::Check(args) => check(&args.file, args.root.root),
        ScenarioAction::Schema => schema(),
    }
}

/// `rtnav scenario schema`: the schema on standard output.
fn schema() -> CliResult<ExitCode> {
    print!("{}", scenario_file::schema_text());
    Ok(ExitCode::SUCCESS)
}

/// `rtnav scenario check FILE` (module documentation).
fn check(path: &Path, root: Option<PathBuf>) -> CliResult<ExitCode> {
    let text = std::fs::read_to_string(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    println!("scenario file {}", path.display());
    let problems = scenario_file::problems(&text);
    if !problems.is_empty() {
        println!(
            "schema        {} problem{} (the schema: {SCHEMA_PATH})",
            problems.len(),
            if problems.len() == 1 { "" } else { "s" }
        );
        for p in &problems {
            println!("  {}: {p}", path.display());
        }
        println!("WRONG: put these right and check again");
        return Ok(ExitCode::from(1));
    }
    println!("schema        ok");
    match core_check(path, &text, root) {
        Ok(lines) => {
            for line in lines {
                println!("{line}");
            }
            println!("OK");
            Ok(ExitCode::SUCCESS)
        }
        Err(reason) => {
            println!("core          {reason}");
            println!("WRONG: put this right and check again");
            Ok(ExitCode::from(1))
        }
    }
}

/// The core's reading (module documentation, step 2; `rtnav::scenario_check`): what it
/// found, one line each, or what is wrong.
fn core_check(path: &Path, text: &str, root: Option<PathBuf>) -> Result<Vec<String>, Wrong> {
    let scenario = Scenario::from_json(text).map_err(|e| Wrong::Read(Box::new(e.into())))?;
    let mut lines = Vec::new();
    let stem = path
        .file_name()
        .and_then(|n| n.to_str())
        .and_then(|n| n.strip_suffix(".json"));
    if stem.is_some_and(|s| s != scenario.name) {
        lines.push(format!(
            "note          the name `{}` is not the file's (`{}`): a replay names its scenario \
             by `name`, and `rtnav replay` looks for fixtures/scenarios/NAME.json",
            scenario.name,
            stem.unwrap_or_default()
        ));
    }
    let root = root.unwrap_or_else(|| find_root(path, &scenario));
    let found = check_scenario(&scenario, &RepoResolver::new(&root))
        .map_err(|problem| Wrong::Core { problem, root })?;
    lines.extend(found.iter().map(|f| format!("{:<14}{f}", label(f))));
    Ok(lines)
}

/// The label of a finding's line.
fn label(finding: &Finding) -> &'static str {
    match finding {
        _ if finding.is_note() => "note",
        Finding::Map { .. } => "map",
        Finding::Route { .. } | Finding::PlanFailsAsExpected { .. } => "plan",
        _ => "exercise",
    }
}

/// What is wrong with a scenario file as the core reads it.
#[derive(Debug, thiserror::Error)]
enum Wrong {
    /// The core does not read it.
    #[error("{0}")]
    Read(Box<rtnav::Error>),
    /// The core reads it and finds it wrong.
    #[error("{}", core_words(problem, root))]
    Core {
        problem: ScenarioProblem,
        /// The folder its paths were read from.
        root: PathBuf,
    },
}

/// A problem the core found; a map that does not load with the folder its path is relative
/// to.
fn core_words(problem: &ScenarioProblem, root: &Path) -> String {
    match problem {
        ScenarioProblem::MapDoesNotLoad(e) => format!(
            "the map does not load (paths are relative to `{}`): {e}",
            root.display()
        ),
        other => other.to_string(),
    }
}
