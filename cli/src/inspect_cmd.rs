//! `rtnav inspect SCENARIO --cell X,Y`: what the map and the potential field say about one
//! cell, as one line of JSON (`rtnav::system::CellInspection`), for the scenario loaded as
//! the browser page loads it ([`Session::load_scenario`]: without its timed events,
//! previewed with the full field).

use std::path::PathBuf;
use std::process::ExitCode;

use clap::Args;
use rtnav::system::Session;
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_load::load;

use crate::options::{RootOption, parse_cell};

/// The options of `rtnav inspect`.
#[derive(Debug, Args)]
pub struct InspectArgs {
    /// The scenario file (JSON).
    scenario: PathBuf,
    /// The cell, X,Y (column, row; 0,0 is the lower-left cell).
    #[arg(long, value_parser = parse_cell, allow_hyphen_values = true)]
    cell: (i64, i64),
    #[command(flatten)]
    root: RootOption,
}

/// `rtnav inspect` (module documentation).
pub fn inspect(args: InspectArgs) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(&args.scenario, args.root.root)?;
    let mut session = Session::new().map_err(CliError::core)?;
    // The set-up's errors name the scenario already.
    session
        .load_scenario(scenario, &resolver)
        .map_err(CliError::core)?;
    let (x, y) = args.cell;
    let cell = session.inspect_cell(x, y).map_err(CliError::core)?;
    println!("{}", serde_json::to_string(&cell)?);
    Ok(ExitCode::SUCCESS)
}
