//! `rtnav system SCENARIO [--dot | --json] [--until T]`: the system's own description
//! (`rtnav::system::SystemGraph`) — the components, their data and service ports with types,
//! and the connections — as Graphviz `dot` or as JSON; with `--until` after running the
//! scenario that long, so the JSON holds each port's newest sample and each service port's
//! last call.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Args;
use rtnav::system::{BuildOptions, ScenarioRun, Setup, setup};
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_load::load;

use crate::options::RootOption;

/// The options of `rtnav system`.
#[derive(Debug, Args)]
pub struct SystemArgs {
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
    #[command(flatten)]
    root: RootOption,
}

/// `rtnav system` (module documentation).
pub fn describe(args: SystemArgs) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(&args.scenario, args.root.root)?;
    let graph = match args.until {
        Some(t) => {
            let mut run = ScenarioRun::new(&scenario, &resolver).map_err(CliError::core)?;
            run.set_limit(t).map_err(CliError::core)?;
            while run.advance(1000).is_none() {}
            run.system().wiring().graph()
        }
        None => setup::build(
            &scenario,
            &resolver,
            &Setup::of(&scenario),
            BuildOptions::default(),
        )
        .map_err(CliError::core)?
        .wiring()
        .graph(),
    };
    // Graphviz dot unless JSON is asked for (the two exclude each other).
    if args.dot || !args.json {
        print!("{}", graph.to_dot());
    } else {
        println!("{}", serde_json::to_string_pretty(&graph)?);
    }
    Ok(ExitCode::SUCCESS)
}
