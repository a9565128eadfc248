//! `rtnav-stress`: the reliability tools (`rtnav_stress::fuzz`, `rtnav_stress::soak`) on the
//! command line, with the counting allocator installed (the fuzzer's allocation bounds, the
//! soak's memory figures). `cargo xtask fuzz` and `cargo xtask soak` run them in release
//! mode, and the fuzz and soak stages of `cargo xtask test` in debug mode.
//!
//! ```text
//! rtnav-stress fuzz --seconds 60                 # every fuzz target, 60 s in all
//! rtnav-stress soak --hours 24 --scenario fixtures/scenarios/willow_garage.json
//! ```
//!
//! Exit code: 0 when nothing was found wrong, 1 when something was, 2 with
//! `rtnav-stress: error: …` when the tool cannot do its work.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use clap::{Args, Parser, Subcommand};
use rtnav::data::RepoResolver;
use rtnav::scenario_data::needs_external_data;
use rtnav::system::{BuildOptions, Setup, setup};
use rtnav_cli::error::CliError;
use rtnav_cli::project_root;
use rtnav_cli::scenario_load::read_scenario;
use rtnav_stress::{alloc, fuzz, soak};

// Counts allocations: the fuzzer's allocation bounds and the soak's memory figures.
#[global_allocator]
static ALLOCATOR: alloc::Counting = alloc::Counting;

#[derive(Debug, Parser)]
#[command(
    name = "rtnav-stress",
    version,
    about = "The reliability tools of rtnav: the fuzzer and the soak"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Fuzz the readers and the hostile calls: mutated fixture inputs and generated ones,
    /// each checked for panics, time (1 s), allocation bounds and refused calls that change
    /// something. Prints, per target, the inputs tried, the failures and the slowest input.
    Fuzz(FuzzArgs),
    /// Drive a scenario for hours of simulated time with random reachable goals and random
    /// map edits; report goals, arrivals, bumps, errors, planning failures, stuck periods and
    /// memory. Exits 1 on a bump, a component error, a stuck period or growing memory.
    Soak(SoakArgs),
}

/// `--root`: where the fixtures are.
#[derive(Debug, Args)]
struct RootOption {
    /// The project's root (default: the first folder up from here with
    /// `fixtures/scenarios`).
    #[arg(long)]
    root: Option<PathBuf>,
}

impl RootOption {
    fn get(self) -> PathBuf {
        self.root.unwrap_or_else(project_root)
    }
}

#[derive(Debug, Args)]
struct FuzzArgs {
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
    #[command(flatten)]
    root: RootOption,
}

#[derive(Debug, Args)]
struct SoakArgs {
    /// Simulated hours.
    #[arg(long, default_value_t = 1.0)]
    hours: f64,
    /// The scenario (default: fixtures/scenarios/open_field.json).
    #[arg(long)]
    scenario: Option<PathBuf>,
    /// The seed of the goals and edits.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    #[command(flatten)]
    root: RootOption,
}

fn main() -> ExitCode {
    let result = match Cli::parse().command {
        Command::Fuzz(args) => run_fuzz(args),
        Command::Soak(args) => run_soak(args),
    };
    result.unwrap_or_else(|e| {
        eprintln!("rtnav-stress: error: {e}");
        ExitCode::from(2)
    })
}

/// `rtnav-stress fuzz` (the command's help; `rtnav_stress::fuzz`).
fn run_fuzz(args: FuzzArgs) -> Result<ExitCode, CliError> {
    let seconds = args.seconds;
    if !(seconds.is_finite() && seconds >= 0.0) {
        return Err(CliError::OutOfRange {
            option: "--seconds",
            value: seconds,
            range: "a number ≥ 0",
        });
    }
    if args.case.is_some() && (args.seed.is_none() || args.target.is_empty()) {
        return Err(CliError::Usage(
            "--case replays one input: give --seed and --target too",
        ));
    }
    let root = args.root.get();
    let data_dir = rtnav::data::data_dir(&root).ok();
    let seed = args.seed.unwrap_or_else(|| {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(18, |d| d.as_secs())
    });
    let only = args.target;
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
        match args.cases {
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
        cases: args.cases,
        only,
        replay: args.case,
        corpus: args.corpus,
        save: args.save,
    };
    let reports = fuzz::run_targets(targets, &options, |r| println!("{}", r.line()));
    let tried: u64 = reports.iter().map(|r| r.tried).sum();
    let failed: u64 = reports.iter().map(|r| r.failed).sum();
    for r in &reports {
        for f in &r.failures {
            let target = r.name.as_str();
            match &f.regression {
                Some(name) => println!(
                    "\nFAILED {target} kept regression case {name} ({}): {}\n  input: {}",
                    f.kind, f.message, f.input
                ),
                None => println!(
                    "\nFAILED {target} case {} ({}): {}\n  input: {}\n  replay: rtnav-stress fuzz --seed {seed} --target {target} --case {}",
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

/// `rtnav-stress soak` (the command's help; `rtnav_stress::soak`).
fn run_soak(args: SoakArgs) -> Result<ExitCode, CliError> {
    let (hours, seed) = (args.hours, args.seed);
    if !(hours.is_finite() && hours > 0.0) {
        return Err(CliError::OutOfRange {
            option: "--hours",
            value: hours,
            range: "a positive number",
        });
    }
    let root = args.root.get();
    let path = args
        .scenario
        .unwrap_or_else(|| root.join("fixtures/scenarios/open_field.json"));
    let scenario = read_scenario(&path)?;
    let resolver = RepoResolver::new(&root);
    if needs_external_data(&scenario, &resolver)
        && let Err(missing) = resolver.data()
    {
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
    .map_err(CliError::core)?;
    let options = soak::SoakOptions::of_scenario(hours, seed, &scenario);
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
    let Ok(report) = outcome else {
        println!("verdict           FAILED: a panic");
        return Ok(ExitCode::from(1));
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
