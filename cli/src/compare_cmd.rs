//! `rtnav compare SCENARIO --a CONF --b CONF [--png P]`: one scenario run with two
//! configurations (`rtnav::system::compare`), the table side by side; both runs drawn at
//! their end in one frame on request (A solid, B as the ghost).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Args;
use rtnav::render::{Layers, Renderer, caption};
use rtnav::system::{compare, setup_with};
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_load::load;

use crate::frame::write_bytes;
use crate::options::{RootOption, SizeOption};

/// The options of `rtnav compare`.
#[derive(Debug, Args)]
pub struct CompareArgs {
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
    #[command(flatten)]
    root: RootOption,
    #[command(flatten)]
    size: SizeOption,
}

/// A configuration argument: a file of `Component.Name=value` lines, or the assignments
/// themselves.
fn conf_text(conf: &str) -> CliResult<String> {
    let path = Path::new(conf);
    if !conf.contains('=') && path.exists() {
        std::fs::read_to_string(path).map_err(|source| CliError::Read {
            path: path.to_path_buf(),
            source,
        })
    } else {
        Ok(conf.to_owned())
    }
}

/// `rtnav compare` (module documentation).
pub fn compare_cmd(args: CompareArgs) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(&args.scenario, args.root.root)?;
    let option = |option: &'static str| {
        move |error: rtnav::Error| CliError::Option {
            option,
            error: Box::new(error),
        }
    };
    let setup_a = setup_with(&scenario, &conf_text(&args.a)?).map_err(option("--a"))?;
    let setup_b = setup_with(&scenario, &conf_text(&args.b)?).map_err(option("--b"))?;
    let comparison = compare(&scenario, &resolver, &setup_a, &setup_b).map_err(CliError::core)?;
    print!("{comparison}");
    if let Some(p) = &args.png {
        let (w, h) = args.size.size;
        let mut renderer = Renderer::new(w, h).map_err(CliError::core)?;
        let a = comparison.system_a();
        let text = format!("A (solid) vs B (ghost)  {}", caption(a));
        let frame = renderer
            .render_compare(a, comparison.system_b(), &text, Layers::ALL)
            .map_err(CliError::core)?;
        write_bytes(p, &frame.encode_png().map_err(CliError::core)?)?;
        println!("frame  {}", p.display());
    }
    Ok(ExitCode::SUCCESS)
}
