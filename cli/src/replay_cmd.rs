//! `rtnav replay FILE`: a recorded run (`*.rtnav.json`, downloaded from the page) replayed.
//!
//! A replay names its scenario; the scenario file is `fixtures/scenarios/NAME.json` under
//! `--root`, else under the first folder above the replay file (then above the working
//! folder) that has it. The replay is loaded as the page loads it ([`Session::load_replay`]):
//! the set-up rebuilt, every recorded request at its time, to the recorded end. Exit code: 0
//! if the run reproduces the recorded trace hash, 1 if not.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Args;
use rtnav::system::{Replay, Session};
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_load::load;
use rtnav_cli::words::Words;

use crate::frame::{write_bytes, write_png};
use crate::options::SizeOption;

/// The options of `rtnav replay`.
#[derive(Debug, Args)]
pub struct ReplayArgs {
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
    #[command(flatten)]
    size: SizeOption,
}

/// The scenario file of scenario `name`.
fn scenario_file(name: &str, root: Option<&Path>, near: &Path) -> CliResult<PathBuf> {
    if name.is_empty()
        || !name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
    {
        return Err(CliError::NotAScenarioName(name.to_owned()));
    }
    let rel = PathBuf::from("fixtures/scenarios").join(format!("{name}.json"));
    if let Some(r) = root {
        return Ok(r.join(rel));
    }
    let near = std::fs::canonicalize(near).unwrap_or_else(|_| near.to_path_buf());
    let cwd = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    let found = near
        .ancestors()
        .chain(cwd.ancestors())
        .map(|dir| dir.join(&rel))
        .find(|p| p.exists());
    found.ok_or_else(|| CliError::ScenarioNotFound {
        name: name.to_owned(),
        file: rel,
        near,
    })
}

/// `rtnav replay` (module documentation).
pub fn replay(args: ReplayArgs) -> CliResult<ExitCode> {
    let file = &args.file;
    let text = std::fs::read_to_string(file).map_err(|source| CliError::Read {
        path: file.clone(),
        source,
    })?;
    let replay = Replay::from_json(&text).map_err(CliError::in_file(file))?;
    let path = scenario_file(&replay.setup.scenario, args.root.as_deref(), file)?;
    let (scenario, resolver) = load(&path, args.root)?;
    let mut session = Session::new().map_err(CliError::core)?;
    session
        .load_scenario(scenario, &resolver)
        .map_err(CliError::core)?;
    let check = session
        .load_replay(&replay)
        .map_err(CliError::in_file(file))?;
    println!("replay          {} ({} bytes)", file.display(), text.len());
    println!("scenario        {}", check.scenario);
    println!("requests        {}", check.inputs);
    println!("simulated time  {:.3} s", session.time_s());
    println!(
        "status          {}",
        Words::english().status(&session.status())
    );
    println!(
        "samples         {} (recorded {})",
        check.samples, check.expected_samples
    );
    println!("trace hash      {}", check.hash);
    if check.matches {
        println!("reproduced      yes: the recorded trace hash");
    } else {
        println!("reproduced      NO: recorded {}", check.expected_hash);
    }
    if let Some(p) = &args.csv {
        write_bytes(p, session.telemetry_csv().as_bytes())?;
        println!("telemetry       {}", p.display());
    }
    if let Some(p) = &args.png {
        write_png(session.system(), args.size.size, p)?;
        println!("frame           {}", p.display());
    }
    Ok(if check.matches {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
