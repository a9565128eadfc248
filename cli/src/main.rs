//! `rtnav`: the headless runner (spec §0, §6). Runs a scenario to its outcome and prints a
//! summary, writes the final frame as PNG and the telemetry as CSV; or draws the initial
//! plan of a scenario without driving. One module per subcommand (`*_cmd.rs`); the options
//! several share in `options.rs`; what can go wrong in `rtnav_cli::error`.
//!
//! ```text
//! rtnav run fixtures/scenarios/corridor_turn.json --png turn.png --csv turn.csv
//! rtnav run fixtures/scenarios/ex_pd_gains.json --script fixtures/scripts/motor_control_pd.rhai
//! rtnav render fixtures/scenarios/willow_garage.json --png willow.png
//! rtnav inspect fixtures/scenarios/open_field.json --cell 30,40
//! rtnav replay run.rtnav.json --png run.png --csv run.csv
//! rtnav compare fixtures/scenarios/parking_wall.json \
//!     --a LocalPathPlanning.PostureConsiderationLevel=0 \
//!     --b LocalPathPlanning.PostureConsiderationLevel=85 --png compare.png
//! rtnav check fixtures/scenarios/ex_door_dmin.json --conf my.conf   # exit 0 pass, 1 fail
//! rtnav check fixtures/scenarios/ex_fault_recovery.json --replay run.rtnav.json
//! rtnav check fixtures/scenarios/ex_door_dmin.json --replay class/ --csv verdicts.csv
//! rtnav check fixtures/scenarios/ex_pd_gains.json --script fixtures/scripts/class/
//! rtnav scenario check fixtures/scenarios/ex_door_dmin.json   # a new exercise, checked
//! rtnav scenario schema > docs/scenario.schema.json
//! rtnav system fixtures/scenarios/open_field.json --dot | dot -Tsvg > system.svg
//! rtnav system fixtures/scenarios/open_field.json --json --until 5
//! ```
//!
//! The reliability tools (the fuzzer, the soak) are another binary, `rtnav-stress`
//! (`stress/`); `cargo xtask fuzz` and `cargo xtask soak` run them in release mode.
//!
//! Scenario files name their maps relative to the project's root; the root is found by
//! walking up from the scenario file to the first folder where the map exists (or given
//! with `--root`). A map of the external data (`../shared/data/…`) is read from
//! `$RTNAV_DATA`, else from `../shared/data` beside the root; without it the runner stops
//! with an error naming the file and `RTNAV_DATA` (`rtnav::data`).
//!
//! Exit code: a subcommand's own (0, or 1 when what it checks is wrong); 2 with
//! `rtnav: error: …` when it cannot do its work.

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod check_cmd;
mod compare_cmd;
mod frame;
mod inspect_cmd;
mod options;
mod render_cmd;
mod replay_cmd;
mod run_cmd;
mod scenario_cmd;
mod system_cmd;

#[derive(Debug, Parser)]
#[command(
    name = "rtnav",
    version,
    about = "Run and draw rtnav scenarios headlessly"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a scenario to its outcome and print a summary; with --script, a student's
    /// script in a component's place.
    Run(run_cmd::RunArgs),
    /// Draw the initial plan of a scenario (global route, local plan, potential field)
    /// without driving.
    Render(render_cmd::RenderArgs),
    /// Print one map cell's obstacle distance and potential field as JSON, after the
    /// planning preview the browser page makes on loading the scenario.
    Inspect(inspect_cmd::InspectArgs),
    /// Replay a recorded run (`*.rtnav.json`, downloaded from the page): rebuild its
    /// set-up, apply every request at its time, run to its end. Exits 1 if the trace hash
    /// is not the recorded one.
    Replay(replay_cmd::ReplayArgs),
    /// Run a scenario with two configurations and print a table side by side (time to
    /// goal, path length, minimum clearance, arrival heading error, replans, energy).
    /// A configuration is `Component.Name=value[,…]` or a file of such lines.
    Compare(compare_cmd::CompareArgs),
    /// Do a scenario's exercise with the hand-ins of one student or of a whole class and
    /// print the verdicts. One hand-in (a file): its checklist and verdict. Several, or a
    /// folder (its *.conf files with --conf, *.json with --replay, *.rhai with --script,
    /// sorted): one table, a row per file — verdict, each check's measured value with its
    /// unit, and why when it did not pass. A file that cannot be judged (not a replay of
    /// this scenario, of another version, unreadable, or whose run does not reproduce its
    /// recorded trace; a script that does not load, at its line and column) is a REFUSED
    /// row with the reason; a script that fails as it runs is judged, its failure in the
    /// reason. Exit code: 0 when every hand-in passed; 1 when one failed, was unfinished or
    /// was refused; 2 for a usage error (scenario unreadable or without an exercise, no
    /// hand-in found, CSV not writable).
    Check(check_cmd::CheckArgs),
    /// Scenario files: check one, or print their JSON Schema (docs/authoring.md).
    Scenario {
        #[command(subcommand)]
        action: scenario_cmd::ScenarioAction,
    },
    /// Print the system's description — components, ports, types, connections — as
    /// Graphviz dot (default) or JSON.
    System(system_cmd::SystemArgs),
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Run(args) => run_cmd::run(args),
        Command::Render(args) => render_cmd::render(args),
        Command::Inspect(args) => inspect_cmd::inspect(args),
        Command::Replay(args) => replay_cmd::replay(args),
        Command::Compare(args) => compare_cmd::compare_cmd(args),
        Command::Check(args) => check_cmd::check(args),
        Command::Scenario { action } => scenario_cmd::scenario(action),
        Command::System(args) => system_cmd::describe(args),
    };
    result.unwrap_or_else(|e| {
        eprintln!("rtnav: error: {e}");
        ExitCode::from(2)
    })
}
