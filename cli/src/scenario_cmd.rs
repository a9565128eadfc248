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

use rtnav::system::{
    BuildOptions, ComponentKind, OutcomeKind, ParameterWarning, Scenario, Setup, setup,
};
use rtnav_cli::scenario_file::{self, SCHEMA_PATH};
use rtnav_cli::words::Words;

use super::{CliResult, find_root};

/// `rtnav scenario schema`: the schema on standard output.
pub(super) fn schema() -> CliResult<ExitCode> {
    print!("{}", scenario_file::schema_text());
    Ok(ExitCode::SUCCESS)
}

/// `rtnav scenario check FILE` (module documentation).
pub(super) fn check(path: &Path, root: Option<PathBuf>) -> CliResult<ExitCode> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read `{}`: {e}", path.display()))?;
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

/// The core's reading (module documentation, step 2): what it found, or what is wrong.
fn core_check(path: &Path, text: &str, root: Option<PathBuf>) -> Result<Vec<String>, String> {
    let scenario = Scenario::from_json(text).map_err(|e| e.to_string())?;
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
    let resolver = rtnav::data::RepoResolver::new(&root);
    let map = scenario.load_map(&resolver).map_err(|e| {
        format!(
            "the map does not load (paths are relative to `{}`): {e}",
            root.display()
        )
    })?;
    lines.push(format!(
        "map           {} × {} cells of {} m",
        map.width(),
        map.height(),
        map.grid_size()
    ));
    for (what, pose) in [("start", scenario.start), ("goal", scenario.goal)] {
        let cell = map.world_to_cell(pose.x, pose.y).ok_or_else(|| {
            let (ox, oy) = map.origin();
            format!(
                "the {what} ({}, {}) is off the map, which covers x {ox} to {} and y {oy} to {} m",
                pose.x,
                pose.y,
                ox + map.width() as f64 * map.grid_size(),
                oy + map.height() as f64 * map.grid_size()
            )
        })?;
        let (i, j) = (cell.0 as i64, cell.1 as i64);
        if map.is_obstacle(i, j) {
            return Err(format!(
                "the {what} ({}, {}) is inside an obstacle (cell {i}, {j})",
                pose.x, pose.y
            ));
        }
    }
    let system = setup::build(
        &scenario,
        &resolver,
        &Setup::of(&scenario),
        BuildOptions::default(),
    )
    .map_err(|e| format!("the core cannot set it up: {e}"))?;
    let radius = system
        .wiring()
        .config(ComponentKind::MotorControl)
        .and_then(|c| Ok(c.value("radiusOfBodyArea")?))
        .unwrap_or(0.0);
    for (what, pose) in [("start", scenario.start), ("goal", scenario.goal)] {
        if let Some(cell) = map.world_to_cell(pose.x, pose.y) {
            let d = map.obstacle_distance(cell);
            if d < radius {
                lines.push(format!(
                    "note          the {what} is {d:.2} m from an obstacle, less than the body's \
                     radius ({radius} m, MotorControl.radiusOfBodyArea): the robot touches it there"
                ));
            }
        }
    }
    let route = system.mission().route().len();
    let failure = system
        .mission()
        .failure()
        .map(|f| Words::english().event(f));
    match (failure, scenario.expect.outcome) {
        (Some(why), OutcomeKind::PlanningFailed) => {
            lines.push(format!("plan          fails, as expected: {why}"));
        }
        (Some(why), _) => {
            return Err(format!(
                "no plan from the start to the goal ({why}); the scenario expects `{}`",
                serde_json::to_value(scenario.expect.outcome)
                    .ok()
                    .and_then(|v| v.as_str().map(str::to_owned))
                    .unwrap_or_default()
            ));
        }
        (None, _) => lines.push(format!("plan          a route of {route} cells")),
    }
    if let Some(exercise) = &scenario.exercise {
        for name in &exercise.may_change {
            let Some((component, param)) = name.split_once('.') else {
                continue;
            };
            let kind = ComponentKind::from_name(component).map_err(|e| e.to_string())?;
            let known = system
                .wiring()
                .config(kind)
                .is_ok_and(|c| c.specs().iter().any(|s| s.name == param));
            if !known {
                return Err(format!(
                    "exercise: may_change `{name}`: {component} has no parameter `{param}`"
                ));
            }
        }
        // The rule every exercise holds: a value the Parameters tab warns about never
        // passes. One the scenario sets and the student may not change fails every answer.
        for warned in ParameterWarning::warned(system.wiring()) {
            if !exercise.may_change.contains(&warned) {
                return Err(format!(
                    "exercise: the Parameters tab warns about {warned} as the scenario sets it, \
                     and the exercise does not let it change: no answer can pass"
                ));
            }
            lines.push(format!(
                "note          the Parameters tab warns about {warned} as given: an answer must \
                 change it"
            ));
        }
        lines.push(format!(
            "exercise      {} check{}; may change {}",
            exercise.checks.len(),
            if exercise.checks.len() == 1 { "" } else { "s" },
            if exercise.may_change.is_empty() {
                "nothing".to_owned()
            } else {
                exercise.may_change.join(", ")
            }
        ));
    }
    Ok(lines)
}
