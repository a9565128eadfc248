//! `cargo xtask`: the steps cargo alone cannot do (matklad's cargo-xtask pattern).
//!
//! Nothing to install but cargo and Node: every command installs the tools it needs when they
//! are missing (the wasm target, `wasm-bindgen-cli` at the version pinned in the root
//! `Cargo.toml`, binaryen's `wasm-opt` from npm, Debian's `chromium`, the e2e test's npm
//! packages) and is safe to run again. Nothing is downloaded from GitHub.
//!
//! ```text
//! cargo xtask demo [--port N]     build the wasm and serve web/ (default http://127.0.0.1:8080/)
//! cargo xtask build-wasm [--dev]  build the wasm into web/pkg, stage the fixtures in web/fixtures
//! cargo xtask serve [--port N]    stage the fixtures and serve web/
//! cargo xtask dist [DIR]          the page as a static folder (default dist/)
//! cargo xtask dist --seal DIR     its offline build and precompressed copies, written again
//! cargo xtask dist --no-build DIR the folder from the wasm already built in web/pkg
//! cargo xtask test [--stage WORD]  every check CI runs (or those named), with a summary
//! cargo xtask e2e [FILE...]       the page's build and the browser tests alone
//! cargo xtask types               write web/types from the Rust views, type-check the page
//! cargo xtask bench               the performance table (docs/performance.md)
//! cargo xtask fuzz [--seconds N]  the fuzzer (rtnav-stress) in release mode (default 300 s)
//! cargo xtask soak [--hours H]    hours of simulated closed loop (rtnav-stress; default 24 h)
//! ```

mod bench;
mod dist;
mod fixtures;
mod fuzz;
mod precompress;
mod prefetch;
mod serve;
mod service_worker;
mod soak;
mod test;
mod tools;
mod types;
mod wasm;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Errors are reported to the user as text; nothing here recovers from them.
type Result<T = ()> = std::result::Result<T, Box<dyn std::error::Error>>;

/// The port `demo` and `serve` use unless told otherwise.
const DEFAULT_PORT: u16 = 8080;

const USAGE: &str = "\
usage: cargo xtask <command>

commands:
  demo [--port N]      build the wasm and serve the page (default port 8080)
  build-wasm [--dev]   build rtnav-wasm into web/pkg (release unless --dev) and copy
                       the scenario fixtures and their maps into web/fixtures
  serve [--port N]     copy the fixtures and serve web/ without building
  dist [DIR]           build the wasm and write the page, the wasm and the scenarios
                       as a static folder for any static host (default dist/), with
                       precompressed copies (.br, .gz) and the service worker's build
  dist --seal DIR      write the service worker's build and the precompressed copies of
                       a dist folder again, after its files were changed by hand
  dist --no-build DIR  write the folder from the wasm already in web/pkg (built by
                       `build-wasm`, release or --dev), without building it
  types                write web/types/core.d.ts from the core's view types and
                       type-check the page's JavaScript against it (tsc, strict)
  bench [--no-wasm] [--no-browser]
                       the performance table of docs/performance.md: criterion benches
                       with their baselines, the same operations in wasm32 under Node,
                       and the worst frame painting on a 1.7 M-cell map in Chromium
  test [--stage WORD]...
                       cargo test, clippy (native and wasm32), rustfmt, the fuzz stage
                       (every reader of untrusted input for a time budget, fresh seed),
                       a one-hour soak, the wasm tests under Node, the page's build, its
                       type check and
                       the browser end-to-end tests (against the dist folder, served under
                       a sub-path); --stage runs only the stages whose name has WORD
  e2e [FILE...]        the page's build and the browser end-to-end tests alone (only
                       the named tests/e2e files, e.g. page.test.mjs, if any)
  fuzz [--seconds N] [--cases N] [--seed S] [--target NAME]... [--case I]
                       fuzz the readers and the hostile calls (`rtnav-stress fuzz`, release
                       mode) for N s in all (default 300), or N inputs per target; the
                       kept regression cases first; prints per target the inputs tried, the
                       failures (with the command that replays each) and the slowest input
  soak [--hours H] [--scenario FILE] [--seed S]
                       drive open_field and the Willow Garage ROS map (or FILE) for H
                       simulated hours (default 24) with random goals and map edits
                       (`rtnav-stress soak`, release mode); fails
                       on a bump, an error, a stuck period or growing memory
  help                 this text

External data (the real maps of some tests and scenarios) is read from $RTNAV_DATA, else
../shared/data beside the repository; without it they are skipped with a line.";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match dispatch(&args) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("xtask: error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn dispatch(args: &[String]) -> Result<ExitCode> {
    let (command, rest) = match args.split_first() {
        Some((c, rest)) => (c.as_str(), rest),
        None => ("help", &[][..]),
    };
    match command {
        "demo" => {
            let port = port_option(rest)?;
            wasm::build(wasm::Profile::Release)?;
            serve::serve_forever(serve::web_root(), port)?;
        }
        "build-wasm" => {
            let profile = match rest {
                [] => wasm::Profile::Release,
                [flag] if flag == "--dev" => wasm::Profile::Dev,
                _ => return Err(format!("build-wasm: unexpected arguments {rest:?}").into()),
            };
            wasm::build(profile)?;
        }
        "serve" => {
            // `--dir DIR` (after the port option) serves another folder as it is: the e2e
            // stage's server of the dist folder.
            let (rest, dir) = match rest {
                [head @ .., flag, dir] if flag == "--dir" => (head, Some(PathBuf::from(dir))),
                _ => (rest, None),
            };
            let port = port_option(rest)?;
            let root = match dir {
                Some(dir) => dir,
                None => {
                    fixtures::stage()?;
                    serve::web_root()
                }
            };
            serve::serve_forever(root, port)?;
        }
        // `cargo xtask test`'s background downloads (not for people: see `prefetch.rs`).
        prefetch::COMMAND => {
            prefetch::run_steps()?;
        }
        "dist" => match rest {
            [] => {
                dist::build(&dist::default_dir())?;
            }
            [dir] if !dir.starts_with('-') => {
                dist::build(Path::new(dir))?;
            }
            [flag, dir] if flag == "--seal" => dist::seal(Path::new(dir))?,
            [flag, dir] if flag == "--no-build" => dist::assemble(Path::new(dir))?,
            _ => return Err(format!("dist: unexpected arguments {rest:?}").into()),
        },
        "test" => {
            let mut only = Vec::new();
            let mut it = rest.iter();
            while let Some(a) = it.next() {
                match (a.as_str(), it.next()) {
                    ("--stage", Some(word)) => only.push(word.clone()),
                    _ => return Err(format!("test: unexpected arguments {rest:?}").into()),
                }
            }
            return Ok(test::run_all(&only));
        }
        "types" => types::types()?,
        "e2e" => return Ok(test::run_e2e(rest)),
        "bench" => bench::run_all(rest)?,
        "fuzz" => fuzz::fuzz(rest)?,
        "soak" => soak::soak(rest)?,
        "help" | "--help" | "-h" => println!("{USAGE}"),
        other => return Err(format!("unknown command `{other}`\n\n{USAGE}").into()),
    }
    Ok(ExitCode::SUCCESS)
}

/// `[]` or `["--port", N]` (also `--port=N`).
fn port_option(rest: &[String]) -> Result<u16> {
    let text = match rest {
        [] => return Ok(DEFAULT_PORT),
        [flag, value] if flag == "--port" => value.as_str(),
        [flag] if flag.starts_with("--port=") => &flag["--port=".len()..],
        _ => return Err(format!("unexpected arguments {rest:?} (expected --port N)").into()),
    };
    text.parse()
        .map_err(|_| format!("--port: `{text}` is not a port number").into())
}
