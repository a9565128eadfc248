//! `rtnav`: the headless runner (spec §0, §6). Runs a scenario to its outcome and prints a
//! summary, writes the final frame as PNG and the telemetry as CSV; or draws the initial
//! plan of a scenario without driving.
//!
//! ```text
//! rtnav run fixtures/scenarios/corridor_turn.json --png turn.png --csv turn.csv
//! rtnav render fixtures/scenarios/willow_garage.json --png willow.png
//! rtnav inspect fixtures/scenarios/open_field.json --cell 30,40
//! rtnav replay run.rtnav.json --png run.png --csv run.csv
//! rtnav compare fixtures/scenarios/parking_wall.json \
//!     --a LocalPathPlanning.PostureConsiderationLevel=0 \
//!     --b LocalPathPlanning.PostureConsiderationLevel=85 --png compare.png
//! rtnav check fixtures/scenarios/ex_door_dmin.json --conf my.conf   # exit 0 pass, 1 fail
//! rtnav check fixtures/scenarios/ex_fault_recovery.json --replay run.rtnav.json
//! rtnav check fixtures/scenarios/ex_door_dmin.json --replay class/ --csv verdicts.csv
//! rtnav scenario check fixtures/scenarios/ex_door_dmin.json   # a new exercise, checked
//! rtnav scenario schema > docs/scenario.schema.json
//! rtnav system fixtures/scenarios/open_field.json --dot | dot -Tsvg > system.svg
//! rtnav system fixtures/scenarios/open_field.json --json --until 5
//! rtnav fuzz --seconds 60                 # every fuzz target, 60 s in all
//! rtnav soak --hours 24 --scenario fixtures/scenarios/willow_garage.json
//! ```
//!
//! `system` prints the system's own description (`rtnav::system::SystemGraph`): the
//! components, their data and service ports with types, and the connections, as Graphviz
//! `dot` or as JSON; with `--until` after running the scenario that long, so the JSON holds
//! each port's newest sample and each service port's last call.
//!
//! `fuzz` and `soak` are the reliability tools (`rtnav_cli::fuzz`,
//! `rtnav_cli::soak`); `cargo xtask fuzz` and `cargo xtask soak` run them in release mode.
//!
//! `inspect` prints what the map and the potential field say about one cell, as one line of
//! JSON (`rtnav::system::CellInspection`), for the scenario loaded as the browser page loads
//! it: without its timed events, previewed with the full field.
//!
//! Scenario files name their maps relative to the project's root; the root is found by
//! walking up from the scenario file to the first folder where the map exists (or given
//! with `--root`). A map of the external data (`../shared/data/…`) is read from
//! `$RTNAV_DATA`, else from `../shared/data` beside the root; without it the runner stops
//! with an error naming the file and `RTNAV_DATA` (`rtnav::data`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use rtnav::components::FIELD_CELLS_PER_EXECUTION;
use rtnav::data::RepoResolver;
use rtnav::render::{Layers, Renderer, caption};
use rtnav::system::{
    BuildOptions, EventKind, FileResolver, OutcomeKind, Scenario, ScenarioRun, Session, Setup,
    System, setup,
};
use rtnav_cli::words::Words;
use rtnav_cli::{alloc, fuzz, soak};

mod check_cmd;
mod replay_cmd;
mod scenario_cmd;

// Counts allocations: the fuzzer's allocation bounds and the soak's memory figures.
#[global_allocator]
static ALLOCATOR: alloc::Counting = alloc::Counting;

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
    /// Run a scenario to its outcome and print a summary.
    Run {
        /// The scenario file (JSON).
        scenario: PathBuf,
        /// Write the final frame here (PNG).
        #[arg(long)]
        png: Option<PathBuf>,
        /// Write the telemetry here (CSV, one row per sample).
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Stop at this simulated time [s] instead of the scenario's time limit.
        #[arg(long)]
        until: Option<f64>,
        /// The folder the scenario's paths are relative to.
        #[arg(long)]
        root: Option<PathBuf>,
        /// Print every event.
        #[arg(long)]
        events: bool,
        /// Frame size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "1200x800", value_parser = parse_size)]
        size: (u32, u32),
    },
    /// Draw the initial plan of a scenario (global route, local plan, potential field)
    /// without driving.
    Render {
        /// The scenario file (JSON).
        scenario: PathBuf,
        /// Write the frame here (PNG).
        #[arg(long)]
        png: PathBuf,
        /// The folder the scenario's paths are relative to.
        #[arg(long)]
        root: Option<PathBuf>,
        /// Frame size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "1200x800", value_parser = parse_size)]
        size: (u32, u32),
    },
    /// Print one map cell's obstacle distance and potential field as JSON, after the
    /// planning preview the browser page makes on loading the scenario.
    Inspect {
        /// The scenario file (JSON).
        scenario: PathBuf,
        /// The cell, X,Y (column, row; 0,0 is the lower-left cell).
        #[arg(long, value_parser = parse_cell, allow_hyphen_values = true)]
        cell: (i64, i64),
        /// The folder the scenario's paths are relative to.
        #[arg(long)]
        root: Option<PathBuf>,
    },
    /// Replay a recorded run (`*.rtnav.json`, downloaded from the page): rebuild its
    /// set-up, apply every request at its time, run to its end. Exits 1 if the trace hash
    /// is not the recorded one.
    Replay {
        /// The replay file.
        file: PathBuf,
        /// Write the final frame here (PNG).
        #[arg(long)]
        png: Option<PathBuf>,
        /// Write the telemetry here (CSV).
        #[arg(long)]
        csv: Option<PathBuf>,
        /// The project's root (its `fixtures/scenarios/NAME.json`).
        #[arg(long)]
        root: Option<PathBuf>,
        /// Frame size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "1200x800", value_parser = parse_size)]
        size: (u32, u32),
    },
    /// Run a scenario with two configurations and print a table side by side (time to
    /// goal, path length, minimum clearance, arrival heading error, replans, energy).
    /// A configuration is `Component.Name=value[,…]` or a file of such lines.
    Compare {
        /// The scenario file (JSON).
        scenario: PathBuf,
        /// Configuration A (drawn solid); empty for the scenario as written.
        #[arg(long, default_value = "")]
        a: String,
        /// Configuration B (drawn as the ghost).
        #[arg(long)]
        b: String,
        /// Draw both runs at their end in one PNG here.
        #[arg(long)]
        png: Option<PathBuf>,
        /// The folder the scenario's paths are relative to.
        #[arg(long)]
        root: Option<PathBuf>,
        /// Frame size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "1200x800", value_parser = parse_size)]
        size: (u32, u32),
    },
    /// Do a scenario's exercise with the hand-ins of one student or of a whole class and
    /// print the verdicts. One hand-in (a file): its checklist and verdict. Several, or a
    /// folder (its *.conf files with --conf, its *.json files with --replay, sorted): one
    /// table, a row per file — verdict, each check's measured value with its unit, and why
    /// when it did not pass. A file that cannot be judged (not a replay of this scenario, of
    /// another version, unreadable, or whose run does not reproduce its recorded trace) is
    /// a REFUSED row with the reason. Exit code: 0 when every hand-in passed; 1 when one
    /// failed, was unfinished or was refused; 2 for a usage error (scenario unreadable or
    /// without an exercise, no hand-in found, CSV not writable).
    Check {
        /// The scenario file (JSON) with an exercise.
        scenario: PathBuf,
        /// Configurations handed in, files or folders: OpenRTM `.conf` bundles as the page
        /// saves them (components or parameters left out keep the scenario's values).
        /// Without --conf and --replay: the exercise as the scenario stands.
        #[arg(long, num_args = 1.., value_name = "FILE_OR_DIR")]
        conf: Vec<PathBuf>,
        /// Runs handed in as replays (`*.rtnav.json`, downloaded from the page), files or
        /// folders: each checked as it was recorded, after its run reproduced its recorded
        /// trace.
        #[arg(long, num_args = 1.., value_name = "FILE_OR_DIR", conflicts_with = "conf")]
        replay: Vec<PathBuf>,
        /// The folder the scenario's paths are relative to.
        #[arg(long)]
        root: Option<PathBuf>,
        /// Print the result of one hand-in as one line of JSON instead.
        #[arg(long)]
        json: bool,
        /// Write the table (one row per hand-in) here as CSV.
        #[arg(long, value_name = "PATH")]
        csv: Option<PathBuf>,
        /// Hand-ins checked at once (default: one per core).
        #[arg(long, value_name = "N")]
        jobs: Option<usize>,
    },
    /// Scenario files: check one, or print their JSON Schema (docs/authoring.md).
    Scenario {
        #[command(subcommand)]
        action: ScenarioAction,
    },
    /// Print the system's description — components, ports, types, connections — as
    /// Graphviz dot (default) or JSON.
    System {
        /// The scenario file (JSON).
        scenario: PathBuf,
        /// Graphviz dot (the default).
        #[arg(long, conflicts_with = "json")]
        dot: bool,
        /// JSON: components, ports with their types and newest samples, connections.
        #[arg(long)]
        json: bool,
        /// Run the scenario this long [s] first (else: as set up, before it drives).
        #[arg(long)]
        until: Option<f64>,
        /// The folder the scenario's paths are relative to.
        #[arg(long)]
        root: Option<PathBuf>,
    },
    /// Fuzz the readers and the hostile calls: mutated fixture inputs and generated ones,
    /// each checked for panics, time (1 s), allocation bounds and refused calls that change
    /// something. Prints, per target, the inputs tried, the failures and the slowest input.
    Fuzz {
        /// Wall time in all, shared evenly by the targets run [s].
        #[arg(long, default_value_t = 60.0)]
        seconds: f64,
        /// Exactly this many inputs per target instead of a time budget.
        #[arg(long)]
        cases: Option<u64>,
        /// The seed (default: from the clock; printed, to replay a run).
        #[arg(long)]
        seed: Option<u64>,
        /// Only the targets whose name contains this (repeatable).
        #[arg(long)]
        target: Vec<String>,
        /// Replay one input (with --seed and --target).
        #[arg(long)]
        case: Option<u64>,
        /// The kept regression cases (`fixtures/fuzz-regressions`): each target's are run
        /// first.
        #[arg(long)]
        corpus: Option<PathBuf>,
        /// Write each failing input under this folder, as a regression case to keep.
        #[arg(long)]
        save: Option<PathBuf>,
        /// The project's root (fixtures).
        #[arg(long)]
        root: Option<PathBuf>,
    },
    /// Drive a scenario for hours of simulated time with random reachable goals and random
    /// map edits; report goals, arrivals, bumps, errors, planning failures, stuck periods and
    /// memory. Exits 1 on a bump, a component error, a stuck period or growing memory.
    Soak {
        /// Simulated hours.
        #[arg(long, default_value_t = 1.0)]
        hours: f64,
        /// The scenario (default: fixtures/scenarios/open_field.json).
        #[arg(long)]
        scenario: Option<PathBuf>,
        /// The seed of the goals and edits.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// The project's root.
        #[arg(long)]
        root: Option<PathBuf>,
    },
}

#[derive(Debug, Subcommand)]
enum ScenarioAction {
    /// Check a scenario file: against the schema (each problem with its place in the file:
    /// path, line and column), then as the core reads it (the map loads, the start and the
    /// goal are on the map and free, the system sets up and plans, the exercise's
    /// parameters exist). Exits 0 when right, 1 when wrong, 2 when unreadable.
    Check {
        /// The scenario file (JSON).
        file: PathBuf,
        /// The folder the scenario's paths are relative to.
        #[arg(long)]
        root: Option<PathBuf>,
    },
    /// Print the JSON Schema of scenario files (docs/scenario.schema.json).
    Schema,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once('x')
        .ok_or_else(|| format!("`{s}`: expected WIDTHxHEIGHT, e.g. 1200x800"))?;
    let n = |t: &str| t.trim().parse::<u32>().map_err(|e| format!("`{s}`: {e}"));
    Ok((n(w)?, n(h)?))
}

fn parse_cell(s: &str) -> Result<(i64, i64), String> {
    let (x, y) = s
        .split_once(',')
        .ok_or_else(|| format!("`{s}`: expected X,Y, e.g. 30,40"))?;
    let n = |t: &str| t.trim().parse::<i64>().map_err(|e| format!("`{s}`: {e}"));
    Ok((n(x)?, n(y)?))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Run {
            scenario,
            png,
            csv,
            until,
            root,
            events,
            size,
        } => run(
            &scenario,
            png.as_deref(),
            csv.as_deref(),
            until,
            root,
            events,
            size,
        ),
        Command::Render {
            scenario,
            png,
            root,
            size,
        } => render(&scenario, &png, root, size),
        Command::Inspect {
            scenario,
            cell,
            root,
        } => inspect(&scenario, cell, root),
        Command::Replay {
            file,
            png,
            csv,
            root,
            size,
        } => replay_cmd::replay(&file, png.as_deref(), csv.as_deref(), root, size),
        Command::Compare {
            scenario,
            a,
            b,
            png,
            root,
            size,
        } => replay_cmd::compare_cmd(&scenario, &a, &b, png.as_deref(), root, size),
        Command::Check {
            scenario,
            conf,
            replay,
            root,
            json,
            csv,
            jobs,
        } => {
            let (kind, paths) = if replay.is_empty() {
                (check_cmd::HandIn::Conf, conf)
            } else {
                (check_cmd::HandIn::Replay, replay)
            };
            check_cmd::check(check_cmd::CheckArgs {
                scenario,
                kind,
                paths,
                root,
                json,
                csv,
                jobs,
            })
        }
        Command::Scenario { action } => match action {
            ScenarioAction::Check { file, root } => scenario_cmd::check(&file, root),
            ScenarioAction::Schema => scenario_cmd::schema(),
        },
        Command::System {
            scenario,
            dot: _,
            json,
            until,
            root,
        } => describe(&scenario, json, until, root),
        Command::Fuzz {
            seconds,
            cases,
            seed,
            target,
            case,
            corpus,
            save,
            root,
        } => run_fuzz(seconds, cases, seed, target, case, (corpus, save), root),
        Command::Soak {
            hours,
            scenario,
            seed,
            root,
        } => run_soak(hours, scenario, seed, root),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("rtnav: error: {e}");
            ExitCode::from(2)
        }
    }
}

type CliResult<T> = Result<T, String>;

/// An error of the core in the catalogue's words (`rtnav_cli::words`).
fn said(e: impl Into<rtnav::Error>) -> String {
    Words::english().error(&e.into())
}

/// An error of the core about the file `path`, in the catalogue's words.
fn said_in_file(path: &Path, e: impl Into<rtnav::Error>) -> String {
    let words = Words::english();
    let file = path.display().to_string();
    words.t(
        "error.in_file",
        &serde_json::json!({ "file": file, "error": words.error(&e.into()) }),
    )
}

fn load(path: &Path, root: Option<PathBuf>) -> CliResult<(Scenario, RepoResolver)> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read `{}`: {e}", path.display()))?;
    let scenario = Scenario::from_json(&text).map_err(|e| said_in_file(path, e))?;
    let root = match root {
        Some(r) => r,
        None => find_root(path, &scenario),
    };
    Ok((scenario, RepoResolver::new(root)))
}

/// The first ancestor of the scenario file (then the working folder) in which the
/// scenario's map file exists (a map of the external data: where it exists for that root).
fn find_root(path: &Path, scenario: &Scenario) -> PathBuf {
    let map = match &scenario.map {
        rtnav::system::MapSource::Json { path }
        | rtnav::system::MapSource::Movingai { path, .. } => path.clone(),
        rtnav::system::MapSource::Ros { yaml, .. } => yaml.clone(),
    };
    let start = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    start
        .ancestors()
        .skip(1)
        .find(|dir| {
            RepoResolver::new(*dir)
                .locate(&map)
                .is_ok_and(|file| file.exists())
        })
        .map(Path::to_path_buf)
        .unwrap_or_else(|| PathBuf::from("."))
}

fn write_png(system: &System, size: (u32, u32), path: &Path) -> CliResult<()> {
    let mut renderer = Renderer::new(size.0, size.1).map_err(said)?;
    let frame = renderer
        .render_system(system, &caption(system), Layers::ALL)
        .map_err(said)?;
    let bytes = frame.encode_png().map_err(said)?;
    std::fs::write(path, bytes).map_err(|e| format!("cannot write `{}`: {e}", path.display()))
}

fn run(
    path: &Path,
    png: Option<&Path>,
    csv: Option<&Path>,
    until: Option<f64>,
    root: Option<PathBuf>,
    print_events: bool,
    size: (u32, u32),
) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(path, root)?;
    let resolver: &dyn FileResolver = &resolver;
    let mut run = ScenarioRun::new(&scenario, resolver).map_err(said)?;
    if let Some(t) = until {
        run.set_limit(t).map_err(said)?;
    }
    let limit_ms = (run.limit() * 1000.0) as u64;
    let mut rows = String::new();
    let mut seq = 0u64;
    if csv.is_some() {
        rows.push_str(rtnav::system::TelemetrySample::CSV_HEADER);
        rows.push('\n');
    }
    let bar = ProgressBar::hidden();
    let started = Instant::now();
    let mut shown = false;
    let mut printed = 0u64;
    loop {
        let done = run.advance(1000).is_some();
        let system = run.system();
        if csv.is_some() {
            for s in system.record().telemetry().since(seq) {
                s.write_csv_row(&mut rows);
                rows.push('\n');
            }
            seq = system.record().telemetry().total();
        }
        if print_events {
            for e in system.record().events_since(printed) {
                bar.suspend(|| println!("{}", Words::english().logged(e)));
            }
            printed = system.record().event_count();
        }
        if !shown && started.elapsed() > Duration::from_millis(500) {
            // A long run: show progress in simulated seconds.
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            bar.set_length(limit_ms);
            bar.set_style(
                ProgressStyle::with_template(
                    "{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} ms simulated {msg}",
                )
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            shown = true;
        }
        bar.set_position(system.time_ns() / 1_000_000);
        if done {
            break;
        }
    }
    bar.finish_and_clear();
    let wall = started.elapsed().as_secs_f64();
    let report = run.report();
    println!("{report}");
    if let Some(why) = &report.outcome.reason {
        println!("ended           {}", Words::english().end_reason(why));
    }
    println!(
        "status          {}",
        Words::english().status(&run.system().status())
    );
    let sim = report.sim_time;
    println!(
        "wall time       {wall:.3} s (real-time factor {:.0}×)",
        if wall > 0.0 {
            sim / wall
        } else {
            f64::INFINITY
        }
    );
    let stopped_early = until.is_some() && report.outcome.kind == OutcomeKind::TimeLimit;
    let expectation = if stopped_early {
        println!("expectation     not checked: stopped by --until");
        Ok(())
    } else {
        report.check(&scenario.expect)
    };
    match &expectation {
        Ok(()) if stopped_early => {}
        Ok(()) => println!("expectation     met ({:?})", scenario.expect.outcome),
        Err(problems) => println!("expectation     NOT met: {problems}"),
    }
    if let Some(p) = csv {
        std::fs::write(p, &rows).map_err(|e| format!("cannot write `{}`: {e}", p.display()))?;
        println!("telemetry       {} ({} samples)", p.display(), seq);
    }
    if let Some(p) = png {
        write_png(run.system(), size, p)?;
        println!("frame           {}", p.display());
    }
    Ok(if expectation.is_ok() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn render(path: &Path, png: &Path, root: Option<PathBuf>, size: (u32, u32)) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(path, root)?;
    let options = BuildOptions { full_field: true };
    let mut system =
        setup::build(&scenario, &resolver, &Setup::of(&scenario), options).map_err(said)?;
    // The set-up gives the planners PLAN_SECONDS; a large map's plan is spread over more
    // executions of LocalPathPlanning (at most FIELD_CELLS_PER_EXECUTION field cells each):
    // go on as long as the map's size needs, twice over (bounded by the map), then draw.
    if let (false, Some(map)) = (system.wiring().planning_settled(), system.map()) {
        let executions = (map.width() * map.height()).div_ceil(FIELD_CELLS_PER_EXECUTION) + 2;
        let seconds = 2.0 * executions as f64 / system.rates().local_path_planning;
        system.run_until_planned(seconds).map_err(said)?;
    }
    let planned = system.mission().plan_sent();
    for e in system.record().events() {
        if matches!(e.kind, EventKind::PlanningFailed { .. }) {
            println!("{}", Words::english().logged(e));
        }
    }
    write_png(&system, size, png)?;
    println!(
        "{}: {} → {}",
        scenario.name,
        if planned { "planned" } else { "no plan" },
        png.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// The system of a scenario as the browser page loads it ([`Session::load_scenario`]: the
/// set-up built with the full potential field).
fn page_session(path: &Path, root: Option<PathBuf>) -> CliResult<Session> {
    let (scenario, resolver) = load(path, root)?;
    let mut session = Session::new().map_err(said)?;
    // The set-up's errors name the scenario already; a file's name its path.
    session.load_scenario(scenario, &resolver).map_err(said)?;
    Ok(session)
}

fn inspect(path: &Path, (x, y): (i64, i64), root: Option<PathBuf>) -> CliResult<ExitCode> {
    let session = page_session(path, root)?;
    let cell = session.inspect_cell(x, y).map_err(said)?;
    let json = serde_json::to_string(&cell).map_err(|e| e.to_string())?;
    println!("{json}");
    Ok(ExitCode::SUCCESS)
}

fn describe(
    path: &Path,
    json: bool,
    until: Option<f64>,
    root: Option<PathBuf>,
) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(path, root)?;
    let graph = match until {
        Some(t) => {
            let mut run = ScenarioRun::new(&scenario, &resolver).map_err(said)?;
            run.set_limit(t).map_err(said)?;
            while run.advance(1000).is_none() {}
            run.system().wiring().graph()
        }
        None => setup::build(
            &scenario,
            &resolver,
            &Setup::of(&scenario),
            BuildOptions::default(),
        )
        .map_err(said)?
        .wiring()
        .graph(),
    };
    if json {
        let text = serde_json::to_string_pretty(&graph).map_err(|e| e.to_string())?;
        println!("{text}");
    } else {
        print!("{}", graph.to_dot());
    }
    Ok(ExitCode::SUCCESS)
}

fn run_fuzz(
    seconds: f64,
    cases: Option<u64>,
    seed: Option<u64>,
    only: Vec<String>,
    replay: Option<u64>,
    (corpus, save): (Option<PathBuf>, Option<PathBuf>),
    root: Option<PathBuf>,
) -> CliResult<ExitCode> {
    if !(seconds.is_finite() && seconds >= 0.0) {
        return Err(format!("--seconds {seconds}: must be a number ≥ 0"));
    }
    if replay.is_some() && (seed.is_none() || only.is_empty()) {
        return Err("--case replays one input: give --seed and --target too".to_owned());
    }
    let root = root.unwrap_or_else(rtnav_cli::project_root);
    let data_dir = rtnav::data::data_dir(&root).ok();
    let seed = seed.unwrap_or_else(|| {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(18, |d| d.as_secs())
    });
    let targets = fuzz::all_targets(&root, data_dir.as_deref());
    let names: Vec<&str> = targets.iter().map(|t| t.name()).collect();
    let chosen = names
        .iter()
        .filter(|n| fuzz::chosen(n, &only, &names))
        .count()
        .max(1);
    let per_target = Duration::from_secs_f64(seconds / chosen as f64);
    println!(
        "fuzz: seed {seed}, {chosen} targets, {} each (shared data: {})",
        match cases {
            Some(n) => format!("{n} inputs"),
            None => format!("{:.1} s", per_target.as_secs_f64()),
        },
        data_dir
            .as_ref()
            .map_or("absent: its inputs are skipped".to_owned(), |d| d
                .display()
                .to_string())
    );
    let options = fuzz::Options {
        seed,
        per_target,
        cases,
        only,
        replay,
        corpus,
        save,
    };
    let reports = fuzz::run_targets(targets, &options, |r| println!("{}", r.line()));
    let tried: u64 = reports.iter().map(|r| r.tried).sum();
    let failed: u64 = reports.iter().map(|r| r.failed).sum();
    let failures: Vec<(&str, &fuzz::Failure)> = reports
        .iter()
        .flat_map(|r| r.failures.iter().map(move |f| (r.name.as_str(), f)))
        .collect();
    for (target, f) in &failures {
        match &f.regression {
            Some(name) => println!(
                "\nFAILED {target} kept regression case {name} ({}): {}\n  input: {}",
                f.kind, f.message, f.input
            ),
            None => println!(
                "\nFAILED {target} case {} ({}): {}\n  input: {}\n  replay: rtnav fuzz --seed {seed} --target {target} --case {}",
                f.case, f.kind, f.message, f.input, f.case
            ),
        }
        if let Some(path) = &f.saved {
            println!(
                "  written to {}: keep it as a regression case in fixtures/fuzz-regressions/{target}/",
                path.display()
            );
        }
    }
    if !alloc::installed() {
        println!("(allocation bounds not checked: the counting allocator is not installed)");
    }
    println!("fuzz: {tried} inputs, {failed} failures (seed {seed})");
    Ok(if failed == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

fn run_soak(
    hours: f64,
    scenario: Option<PathBuf>,
    seed: u64,
    root: Option<PathBuf>,
) -> CliResult<ExitCode> {
    if !(hours.is_finite() && hours > 0.0) {
        return Err(format!("--hours {hours}: must be a positive number"));
    }
    let root = root.unwrap_or_else(rtnav_cli::project_root);
    let path = scenario.unwrap_or_else(|| root.join("fixtures/scenarios/open_field.json"));
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read `{}`: {e}", path.display()))?;
    let scenario = Scenario::from_json(&text).map_err(|e| said_in_file(&path, e))?;
    let resolver = RepoResolver::new(&root);
    let needs_data = scenario
        .map_files(&resolver)
        .map(|files| {
            files
                .iter()
                .any(|f| rtnav::data::data_relative(f).is_some())
        })
        .unwrap_or_else(|_| format!("{:?}", scenario.map).contains(rtnav::data::DATA_PREFIX));
    if needs_data && let Err(missing) = resolver.data() {
        println!("soak: {} SKIPPED: {missing}", scenario.name);
        return Ok(ExitCode::SUCCESS);
    }
    // The scenario's set-up (its own parameters included), without its timed events: the
    // soak makes its own goals and edits.
    let system = setup::build(
        &scenario,
        &resolver,
        &Setup::of(&scenario),
        BuildOptions::default(),
    )
    .map_err(said)?;
    let mut options = soak::SoakOptions::new(hours, seed);
    if let Some(d) = scenario
        .config
        .get("LocalPathPlanning")
        .and_then(|c| c.get("dmin"))
    {
        options.dmin = *d;
    }
    println!(
        "soak: {}, {hours} simulated hours, seed {seed}, dmin {} m",
        scenario.name, options.dmin
    );
    let soak = soak::Soak::new(system, Some(scenario.goal.pose()), options);
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        soak.run(|h, r| {
            println!(
                "  {h:6.2} h: {} goals, {} arrivals, {} bumps, {} errors, {} stuck, heap {:.1} MiB",
                r.goals,
                r.arrivals,
                r.bumps,
                r.component_errors,
                r.stuck.len(),
                alloc::total_live() as f64 / 1048576.0
            );
        })
    }));
    let report = match outcome {
        Ok(r) => r,
        Err(_) => {
            println!("verdict           FAILED: a panic");
            return Ok(ExitCode::from(1));
        }
    };
    print!("{}", report.text());
    let problems = report.problems();
    if problems.is_empty() {
        println!("verdict           passed");
        Ok(ExitCode::SUCCESS)
    } else {
        println!("verdict           FAILED: {}", problems.join(", "));
        Ok(ExitCode::from(1))
    }
}
