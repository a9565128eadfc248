//! `rtnav run SCENARIO`: the scenario run to its outcome, a summary printed; the final frame
//! as PNG and the telemetry as CSV on request. Exit code: 0 when the scenario's expectation
//! is met (or not checked, with `--until`), 1 when not.
//!
//! With `--script FILE`, a student's script (spec §8) runs in the place of the component its
//! declaration names (`const COMPONENT = "MotorControl";`), or of the one `--component`
//! names (it wins); the summary says so, and how the script failed if it did. A script that
//! does not load stops the command with its error, line and column (exit 2).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use rtnav::system::{
    ComponentKind, FileResolver, OutcomeKind, ScenarioRun, Setup, TelemetrySample,
};
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_load::load;
use rtnav_cli::script_load::{ScriptHandIn, parse_component, script_failure, script_hand_in};
use rtnav_cli::words::Words;

use crate::frame::{write_bytes, write_png};
use crate::options::{RootOption, SizeOption};

/// The options of `rtnav run`.
#[derive(Debug, Args)]
pub struct RunArgs {
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
    #[command(flatten)]
    root: RootOption,
    /// Print every event.
    #[arg(long)]
    events: bool,
    #[command(flatten)]
    size: SizeOption,
    /// A student's script (Rhai, spec §8) run in the place of the component it declares
    /// (`const COMPONENT = "MotorControl";`) or that --component names.
    #[arg(long, value_name = "FILE")]
    script: Option<PathBuf>,
    /// The component the script stands in for (MotorControl or DriveControl); wins over
    /// the script's declaration.
    #[arg(long, value_name = "NAME", requires = "script", value_parser = parse_component)]
    component: Option<ComponentKind>,
}

/// The script `path`, compiled, and where it goes (`component`, else its declaration).
fn read_script(path: &Path, component: Option<ComponentKind>) -> CliResult<ScriptHandIn> {
    let source = std::fs::read_to_string(path).map_err(|source| CliError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path.file_name().map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    script_hand_in(&name, &source, component).map_err(|e| CliError::Script {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })
}

/// `rtnav run` (module documentation).
pub fn run(args: RunArgs) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(&args.scenario, args.root.root)?;
    let resolver: &dyn FileResolver = &resolver;
    let script = match &args.script {
        Some(path) => Some((path, read_script(path, args.component)?)),
        None => None,
    };
    let mut setup = Setup::of(&scenario);
    if let Some((_, s)) = &script {
        setup.scripts = s.scripts();
    }
    let mut run = ScenarioRun::with_setup(&scenario, resolver, &setup).map_err(|e| {
        match &script {
            // Refused for its declaration (another component's script): said at it.
            Some((path, s)) if s.declaration_place().is_some() => CliError::Script {
                path: path.to_path_buf(),
                reason: s.refusal(&e),
            },
            _ => CliError::core(e),
        }
    })?;
    if let Some(t) = args.until {
        run.set_limit(t).map_err(CliError::core)?;
    }
    let limit_ms = (run.limit() * 1000.0) as u64;
    let mut rows = String::new();
    let mut seq = 0u64;
    if args.csv.is_some() {
        rows.push_str(TelemetrySample::CSV_HEADER);
        rows.push('\n');
    }
    let bar = ProgressBar::hidden();
    let started = Instant::now();
    let mut shown = false;
    let mut printed = 0u64;
    loop {
        let done = run.advance(1000).is_some();
        let system = run.system();
        if args.csv.is_some() {
            for s in system.record().telemetry().since(seq) {
                s.write_csv_row(&mut rows);
                rows.push('\n');
            }
            seq = system.record().telemetry().total();
        }
        if args.events {
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
    if let Some((_, s)) = &script {
        let kind = s.component;
        println!(
            "script          {kind} ran the student's script {}",
            s.text.name
        );
        if let Some(failure) = script_failure(run.system(), kind) {
            println!("script failed   {failure}");
        }
    }
    let sim = report.sim_time;
    println!(
        "wall time       {wall:.3} s (real-time factor {:.0}×)",
        if wall > 0.0 {
            sim / wall
        } else {
            f64::INFINITY
        }
    );
    let stopped_early = args.until.is_some() && report.outcome.kind == OutcomeKind::TimeLimit;
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
    if let Some(p) = &args.csv {
        write_bytes(p, rows.as_bytes())?;
        println!("telemetry       {} ({} samples)", p.display(), seq);
    }
    if let Some(p) = &args.png {
        write_png(run.system(), args.size.size, p)?;
        println!("frame           {}", p.display());
    }
    Ok(if expectation.is_ok() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
