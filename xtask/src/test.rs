//! `cargo xtask test`: every check CI runs (`.ci/run`), one function per stage.
//!
//! Every stage runs even if an earlier one failed (so one run shows every problem); the summary
//! at the end names each stage with its result and time, and the exit code is non-zero if any
//! failed.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use crate::Result;
use crate::serve::Background;
use crate::tools::{self, cargo, cmd, run};
use crate::wasm;

/// A named check.
struct Stage {
    name: &'static str,
    run: fn() -> Result,
}

const STAGES: &[Stage] = &[
    Stage {
        name: "cargo test --workspace",
        run: cargo_test,
    },
    Stage {
        name: "clippy (native, all targets)",
        run: clippy_native,
    },
    Stage {
        name: "clippy (wasm32)",
        run: clippy_wasm,
    },
    Stage {
        name: "rustfmt --check",
        run: fmt_check,
    },
    Stage {
        name: "soak (1 simulated hour, open_field)",
        run: crate::soak::test_stage,
    },
    Stage {
        name: "wasm tests under Node",
        run: wasm_tests,
    },
    Stage {
        name: "browser end-to-end",
        run: e2e,
    },
];

/// Runs every stage and prints the summary.
pub fn run_all() -> ExitCode {
    let started = Instant::now();
    let mut results: Vec<(&str, Duration, Result)> = Vec::new();
    for (i, stage) in STAGES.iter().enumerate() {
        println!("\n==> [{}/{}] {}", i + 1, STAGES.len(), stage.name);
        let t = Instant::now();
        let r = (stage.run)();
        if let Err(e) = &r {
            eprintln!("==> {} FAILED: {e}", stage.name);
        }
        results.push((stage.name, t.elapsed(), r));
    }
    println!("\n==> summary");
    for (name, took, r) in &results {
        let verdict = if r.is_ok() { "ok" } else { "FAILED" };
        println!("  {verdict:<7}{:>7.1} s  {name}", took.as_secs_f64());
    }
    let failed: Vec<&str> = results
        .iter()
        .filter(|(_, _, r)| r.is_err())
        .map(|(n, _, _)| *n)
        .collect();
    println!("  total  {:>7.1} s", started.elapsed().as_secs_f64());
    if failed.is_empty() {
        println!("\nxtask test: all {} stages passed", results.len());
        ExitCode::SUCCESS
    } else {
        eprintln!("\nxtask test: FAILED: {}", failed.join(", "));
        ExitCode::FAILURE
    }
}

fn cargo_test() -> Result {
    run(cargo().args(["test", "--workspace"]))
}

fn clippy_native() -> Result {
    run(cargo().args([
        "clippy",
        "--workspace",
        "--all-targets",
        "--",
        "-D",
        "warnings",
    ]))
}

fn clippy_wasm() -> Result {
    tools::ensure_wasm_target()?;
    run(cargo().args([
        "clippy",
        "-p",
        "rtnav",
        "-p",
        "rtnav-wasm",
        "-p",
        "rtnav-tests",
        "--target",
        "wasm32-unknown-unknown",
        "--",
        "-D",
        "warnings",
    ]))
}

fn fmt_check() -> Result {
    run(cargo().args(["fmt", "--all", "--", "--check"]))
}

/// `rtnav-tests` compiled to wasm32 and run by `wasm-bindgen-test-runner` under Node.
fn wasm_tests() -> Result {
    tools::ensure_wasm_target()?;
    tools::ensure_wasm_bindgen_cli()?;
    run(cargo()
        .args([
            "test",
            "-p",
            "rtnav-tests",
            "--target",
            "wasm32-unknown-unknown",
        ])
        .env(
            "CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER",
            "wasm-bindgen-test-runner",
        ))
}

fn e2e_dir() -> PathBuf {
    tools::repo_root().join("tests").join("e2e")
}

/// Chromium (Debian's, driven by `playwright-core`) against the page served from `web/`.
fn e2e() -> Result {
    tools::ensure_node()?;
    tools::ensure_chromium()?;
    // The lockfile pins playwright-core; it must never download a browser of its own.
    run(cmd("npm")
        .args(["ci", "--no-audit", "--no-fund"])
        .current_dir(e2e_dir())
        .env("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1"))?;
    wasm::build(wasm::Profile::Release)?;
    // The native runner, for tests that compare the page's numbers with the core's.
    run(cargo().args(["build", "-q", "-p", "rtnav-cli"]))?;
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(|| tools::repo_root().join("target"), PathBuf::from);
    let cli = target
        .join("debug")
        .join(format!("rtnav{}", std::env::consts::EXE_SUFFIX));
    let server = Background::start()?;
    println!("xtask: serving web/ at {}", server.url);
    let mut tests: Vec<PathBuf> = std::fs::read_dir(e2e_dir())?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(".test.mjs"))
        .collect();
    tests.sort();
    if tests.is_empty() {
        return Err("no tests/e2e/*.test.mjs files".into());
    }
    let result = run(cmd("node")
        .arg("--test")
        .args(&tests)
        .current_dir(e2e_dir())
        .env("RTNAV_URL", &server.url)
        .env("RTNAV_CLI", &cli)
        .env("RTNAV_CHROMIUM", tools::CHROMIUM)
        .env("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1"));
    drop(server);
    result
}
