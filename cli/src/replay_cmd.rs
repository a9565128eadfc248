//! `rtnav replay FILE` and `rtnav compare SCENARIO --a CONF --b CONF`.
//!
//! A replay names its scenario; the scenario file is `fixtures/scenarios/NAME.json` under
//! `--root`, else under the first folder above the replay file (then above the working
//! folder) that has it. The replay is loaded as the page loads it ([`Session::load_replay`]):
//! the set-up rebuilt, every recorded request at its time, to the recorded end.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use rtnav::render::{Layers, Renderer, caption};
use rtnav::system::{Replay, Session, compare, setup_with};

use rtnav_cli::words::Words;

use super::{CliResult, load, said, said_in_file, write_png};

/// The scenario file of scenario `name`.
fn scenario_file(name: &str, root: Option<&Path>, near: &Path) -> CliResult<PathBuf> {
    if name.is_empty()
        || !name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
    {
        return Err(format!(
            "the replay names scenario `{name}`, not a scenario name"
        ));
    }
    let rel = PathBuf::from("fixtures/scenarios").join(format!("{name}.json"));
    if let Some(r) = root {
        return Ok(r.join(rel));
    }
    let near = std::fs::canonicalize(near).unwrap_or_else(|_| near.to_path_buf());
    let cwd = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    near.ancestors()
        .chain(cwd.ancestors())
        .map(|dir| dir.join(&rel))
        .find(|p| p.exists())
        .ok_or_else(|| {
            format!(
                "scenario `{name}`: no {} above `{}` or the working folder (give --root)",
                rel.display(),
                near.display()
            )
        })
}

/// `rtnav replay FILE [--png P] [--csv C] [--root R]`: exit 0 if the run reproduces the
/// recorded trace hash, 1 if not.
pub(super) fn replay(
    file: &Path,
    png: Option<&Path>,
    csv: Option<&Path>,
    root: Option<PathBuf>,
    size: (u32, u32),
) -> CliResult<ExitCode> {
    let text = std::fs::read_to_string(file)
        .map_err(|e| format!("cannot read `{}`: {e}", file.display()))?;
    let replay = Replay::from_json(&text).map_err(|e| said_in_file(file, e))?;
    let path = scenario_file(&replay.setup.scenario, root.as_deref(), file)?;
    let (scenario, resolver) = load(&path, root)?;
    let mut session = Session::new().map_err(said)?;
    session.load_scenario(scenario, &resolver).map_err(said)?;
    let check = session
        .load_replay(&replay)
        .map_err(|e| said_in_file(file, e))?;
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
    if let Some(p) = csv {
        let rows = session.telemetry_csv();
        std::fs::write(p, rows).map_err(|e| format!("cannot write `{}`: {e}", p.display()))?;
        println!("telemetry       {}", p.display());
    }
    if let Some(p) = png {
        write_png(session.system(), size, p)?;
        println!("frame           {}", p.display());
    }
    Ok(if check.matches {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// A configuration argument: a file of `Component.Name=value` lines, or the assignments
/// themselves.
fn conf_text(conf: &str) -> CliResult<String> {
    let path = Path::new(conf);
    if !conf.contains('=') && path.exists() {
        std::fs::read_to_string(path).map_err(|e| format!("cannot read `{conf}`: {e}"))
    } else {
        Ok(conf.to_owned())
    }
}

/// `rtnav compare SCENARIO --a CONF --b CONF [--png P]`.
pub(super) fn compare_cmd(
    path: &Path,
    a: &str,
    b: &str,
    png: Option<&Path>,
    root: Option<PathBuf>,
    size: (u32, u32),
) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(path, root)?;
    let setup_a = setup_with(&scenario, &conf_text(a)?).map_err(|e| format!("--a: {}", said(e)))?;
    let setup_b = setup_with(&scenario, &conf_text(b)?).map_err(|e| format!("--b: {}", said(e)))?;
    let comparison = compare(&scenario, &resolver, &setup_a, &setup_b).map_err(said)?;
    print!("{comparison}");
    if let Some(p) = png {
        let mut renderer = Renderer::new(size.0, size.1).map_err(said)?;
        let a = comparison.system_a();
        let text = format!("A (solid) vs B (ghost)  {}", caption(a));
        let frame = renderer
            .render_compare(a, comparison.system_b(), &text, Layers::ALL)
            .map_err(said)?;
        let bytes = frame.encode_png().map_err(said)?;
        std::fs::write(p, bytes).map_err(|e| format!("cannot write `{}`: {e}", p.display()))?;
        println!("frame  {}", p.display());
    }
    Ok(ExitCode::SUCCESS)
}
