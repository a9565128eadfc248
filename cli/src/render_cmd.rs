//! `rtnav render SCENARIO --png FILE`: the initial plan of a scenario drawn without driving
//! (global route, local plan, potential field), however many executions of the planners the
//! map's size needs for it (`rtnav::plan_preview`).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Args;
use rtnav::plan_preview::finish_plan;
use rtnav::system::{BuildOptions, EventKind, Setup, setup};
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_load::load;
use rtnav_cli::words::Words;

use crate::frame::write_png;
use crate::options::{RootOption, SizeOption};

/// The options of `rtnav render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// The scenario file (JSON).
    scenario: PathBuf,
    /// Write the frame here (PNG).
    #[arg(long)]
    png: PathBuf,
    #[command(flatten)]
    root: RootOption,
    #[command(flatten)]
    size: SizeOption,
}

/// `rtnav render` (module documentation).
pub fn render(args: RenderArgs) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(&args.scenario, args.root.root)?;
    let options = BuildOptions { full_field: true };
    let mut system = setup::build(&scenario, &resolver, &Setup::of(&scenario), options)
        .map_err(CliError::core)?;
    let planned = finish_plan(&mut system).map_err(CliError::core)?;
    for e in system.record().events() {
        if matches!(e.kind, EventKind::PlanningFailed { .. }) {
            println!("{}", Words::english().logged(e));
        }
    }
    write_png(&system, args.size.size, &args.png)?;
    println!(
        "{}: {} → {}",
        scenario.name,
        if planned { "planned" } else { "no plan" },
        args.png.display()
    );
    Ok(ExitCode::SUCCESS)
}
