//! The installs of `cargo xtask test` — Debian's Chromium, the e2e tests' npm packages,
//! binaryen's `wasm-opt`, then `wasm-bindgen-cli` (built from source: minutes of a fresh
//! machine's run) — started in a child process at the beginning of the run, beside the cargo
//! test and clippy stages, so they are done by the time the wasm, page and browser stages need
//! them. The downloads overlap the compiles; the tool's build fills the cores the test stage
//! leaves idle while it links and runs tests.
//!
//! Nothing depends on it for correctness: the stages still call the same `ensure_*` steps,
//! which find the tools there (or install them, if the prefetch failed). The child's output
//! goes to a log that [`Prefetch::finish`] prints, so it does not interleave with cargo's.

use std::fs::File;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};

use crate::Result;
use crate::tools::{self, cmd, run};

/// The hidden subcommand the child runs.
pub const COMMAND: &str = "prefetch";

/// A named install step.
type Step = (&'static str, fn() -> Result);

/// What the child does: each step on its own, so one failure does not stop the others.
pub fn run_steps() -> Result {
    let steps: [Step; 4] = [
        ("Chromium", tools::ensure_chromium),
        ("the e2e tests' npm packages", e2e_packages),
        ("wasm-opt", || tools::ensure_wasm_opt().map(drop)),
        ("wasm-bindgen-cli", tools::ensure_wasm_bindgen_cli),
    ];
    let mut failed = Vec::new();
    for (name, step) in steps {
        if let Err(e) = step() {
            println!("xtask prefetch: {name}: {e}");
            failed.push(name);
        }
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(format!("not fetched: {}", failed.join(", ")).into())
    }
}

/// `npm ci` in `tests/e2e` (the lockfile pins playwright-core; it never downloads a browser),
/// unless its `node_modules` already holds what the lockfile says.
pub fn e2e_packages() -> Result {
    tools::ensure_node()?;
    let dir = crate::test::e2e_dir();
    if tools::npm_installed(&dir) {
        return Ok(());
    }
    run(cmd("npm")
        .args(["ci", "--no-audit", "--no-fund"])
        .current_dir(&dir)
        .env("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1"))
}

/// The child process, while it runs.
#[derive(Debug)]
pub struct Prefetch {
    child: Option<Child>,
    log: PathBuf,
}

impl Prefetch {
    /// Starts `xtask prefetch` in the background (nothing, if it cannot be started: the
    /// stages then install what they need themselves).
    pub fn start() -> Self {
        let log = tools::target_dir().join("xtask-prefetch.log");
        let child = (|| -> Result<Child> {
            std::fs::create_dir_all(tools::target_dir())?;
            let out = File::create(&log)?;
            let err = out.try_clone()?;
            Ok(Command::new(std::env::current_exe()?)
                .arg(COMMAND)
                .current_dir(tools::repo_root())
                .stdin(Stdio::null())
                .stdout(out)
                .stderr(err)
                .spawn()?)
        })();
        match &child {
            Ok(c) => println!(
                "xtask: installing what is missing of Chromium, the npm packages, wasm-opt and \
                 wasm-bindgen-cli in the background (process {}, log {})",
                c.id(),
                log.display()
            ),
            Err(e) => println!("xtask: no background fetch ({e}); the stages install"),
        }
        Self {
            child: child.ok(),
            log,
        }
    }

    /// Waits for the child (once) and prints its log.
    pub fn finish(&mut self) {
        let Some(mut child) = self.child.take() else {
            return;
        };
        let status = match child.wait() {
            Ok(s) if s.success() => "done".to_owned(),
            Ok(s) => format!("failed ({s}); the stages install what is missing"),
            Err(e) => format!("not waited for ({e})"),
        };
        let text = std::fs::read_to_string(&self.log).unwrap_or_default();
        if text.trim().is_empty() {
            println!("xtask: background installs {status}: nothing was missing");
        } else {
            println!("xtask: background installs {status}; their output:");
            for line in text.lines() {
                println!("  | {line}");
            }
        }
    }
}

impl Drop for Prefetch {
    fn drop(&mut self) {
        self.finish();
    }
}
