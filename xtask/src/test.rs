//! `cargo xtask test`: every check CI runs (`.ci/run`), one function per stage.
//!
//! Every stage runs even if an earlier one failed (so one run shows every problem); the summary
//! at the end names each stage with its result and time, and the exit code is non-zero if any
//! failed.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use crate::Result;
use crate::prefetch::Prefetch;
use crate::serve::Background;
use crate::tools::{self, cargo, cmd, run};
use crate::{dist, wasm};

/// A named check. It may return a note for the summary (e.g. the wasm's size).
struct Stage {
    name: &'static str,
    run: fn() -> Result<Option<String>>,
    /// Whether it uses what [`Prefetch`] downloads (it waits for it first).
    needs_downloads: bool,
}

const STAGES: &[Stage] = &[
    Stage {
        name: "cargo test --workspace",
        run: cargo_test,
        needs_downloads: false,
    },
    Stage {
        name: "clippy (native, all targets)",
        run: clippy_native,
        needs_downloads: false,
    },
    Stage {
        name: "clippy (wasm32)",
        run: clippy_wasm,
        needs_downloads: false,
    },
    Stage {
        name: "rustfmt --check",
        run: fmt_check,
        needs_downloads: false,
    },
    Stage {
        name: "fuzz (every reader of untrusted input, a time budget each)",
        run: crate::fuzz::test_stage,
        needs_downloads: false,
    },
    Stage {
        name: "soak (1 simulated hour, open_field)",
        run: crate::soak::test_stage,
        needs_downloads: false,
    },
    Stage {
        name: "wasm tests under Node",
        run: wasm_tests,
        needs_downloads: true,
    },
    Stage {
        name: "the page: wasm build, size budget, dist folder",
        run: page,
        needs_downloads: true,
    },
    Stage {
        name: "the page's types (declarations from Rust, tsc strict)",
        run: crate::types::test_stage,
        needs_downloads: true,
    },
    Stage {
        name: "browser end-to-end (dist under /rtnav/)",
        run: e2e,
        needs_downloads: true,
    },
];

/// Runs every stage (or, when `only` names words, the stages whose name contains one of
/// them: `cargo xtask test --stage fuzz`) and prints the summary.
pub fn run_all(only: &[String]) -> ExitCode {
    let started = Instant::now();
    let stages: Vec<&Stage> = STAGES
        .iter()
        .filter(|s| only.is_empty() || only.iter().any(|w| s.name.contains(w.as_str())))
        .collect();
    if stages.is_empty() {
        let names: Vec<&str> = STAGES.iter().map(|s| s.name).collect();
        eprintln!(
            "xtask test: no stage matches {only:?} (stages: {})",
            names.join("; ")
        );
        return ExitCode::FAILURE;
    }
    // The downloads start in the background only when a stage will use them.
    let mut prefetch = stages
        .iter()
        .any(|s| s.needs_downloads)
        .then(Prefetch::start);
    let mut results: Vec<(&str, Duration, Result<Option<String>>)> = Vec::new();
    for (i, stage) in stages.iter().enumerate() {
        if let (true, Some(p)) = (stage.needs_downloads, prefetch.as_mut()) {
            p.finish();
        }
        println!("\n==> [{}/{}] {}", i + 1, stages.len(), stage.name);
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
        if let Ok(Some(note)) = r {
            println!("  {:>16}{note}", "");
        }
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

fn cargo_test() -> Result<Option<String>> {
    // With the view types' declarations: `core/tests/typescript.rs` checks that the committed
    // `web/types/core.d.ts` is what the Rust types give.
    run(cargo().arg("test").args(tools::WORKSPACE_FEATURES))?;
    Ok(None)
}

fn clippy_native() -> Result<Option<String>> {
    run(cargo().args([
        "clippy",
        "--workspace",
        "--all-targets",
        "--",
        "-D",
        "warnings",
    ]))?;
    Ok(None)
}

fn clippy_wasm() -> Result<Option<String>> {
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
    ]))?;
    Ok(None)
}

fn fmt_check() -> Result<Option<String>> {
    run(cargo().args(["fmt", "--all", "--", "--check"]))?;
    Ok(None)
}

/// `rtnav-tests` compiled to wasm32 and run by `wasm-bindgen-test-runner` under Node (which
/// gets our environment: `RTNAV_DATA` reaches the tests that read the external data).
fn wasm_tests() -> Result<Option<String>> {
    tools::ensure_wasm_target()?;
    tools::ensure_wasm_bindgen_cli()?;
    tools::ensure_node()?;
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
        ))?;
    Ok(None)
}

/// Where the e2e stage's static site is: the dist folder at `rtnav/` inside it, so the page
/// is served under a sub-path.
fn e2e_site() -> PathBuf {
    tools::target_dir().join("e2e-site")
}

/// The sub-path the e2e tests open the page at.
const E2E_SUB_PATH: &str = "rtnav";

/// The page's wasm (release: the `web` profile and wasm-opt), and the dist folder made from
/// it, which the e2e stage serves. The note is the module's size; the stage fails (after
/// writing the folder, so the browser tests still run) if the module is over its gzipped
/// budget (`wasm::GZIP_BUDGET`).
fn page() -> Result<Option<String>> {
    let built = wasm::build_pkg(wasm::Profile::Release)?;
    dist::assemble(&e2e_site().join(E2E_SUB_PATH))?;
    wasm::check_budget(built.module)?;
    Ok(Some(format!(
        "{built}; budget {:.0} KB gzipped",
        wasm::GZIP_BUDGET as f64 / 1000.0
    )))
}

pub(crate) fn e2e_dir() -> PathBuf {
    tools::repo_root().join("tests").join("e2e")
}

/// Chromium (Debian's, driven by `playwright-core`) against the dist folder of the page stage,
/// served by a plain static server under `/rtnav/`; the native runner built by the test
/// stage answers the tests that compare the page with the core. The tests of a new build
/// (`offline.test.mjs`) copy the folder (`RTNAV_SITE`) and serve and seal the copy with this
/// program (`RTNAV_XTASK`).
fn e2e() -> Result<Option<String>> {
    e2e_files(&[])
}

/// `cargo xtask e2e [FILE...]`: the page stage, then the browser stage alone (only the named
/// `tests/e2e` files, if any), with the time each took.
pub fn run_e2e(files: &[String]) -> ExitCode {
    let started = Instant::now();
    let mut prefetch = Prefetch::start();
    prefetch.finish();
    let result = page().and_then(|_| {
        println!("==> page built in {:.1} s", started.elapsed().as_secs_f64());
        let t = Instant::now();
        let r = e2e_files(files);
        println!("==> browser tests took {:.1} s", t.elapsed().as_secs_f64());
        r
    });
    match result {
        Ok(_) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask e2e: FAILED: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The browser stage over `only` (file names in `tests/e2e`), or every `*.test.mjs` there.
fn e2e_files(only: &[String]) -> Result<Option<String>> {
    tools::ensure_node()?;
    tools::ensure_chromium()?;
    // The lockfile pins playwright-core; it must never download a browser of its own.
    crate::prefetch::e2e_packages()?;
    let site = e2e_site();
    if !site.join(E2E_SUB_PATH).join("index.html").is_file() {
        return Err("no dist folder to test: the page stage did not make one".into());
    }
    // Built every time (a no-op when it is current): a binary left from an older build would
    // judge the page's run by older rules. The test stage's build, not one of its own.
    let cli = tools::test_build_binary("rtnav")?;
    let server = Background::start(&site)?;
    let url = format!("{}{E2E_SUB_PATH}/", server.url);
    println!(
        "xtask: serving {} at {url}",
        site.join(E2E_SUB_PATH).display()
    );
    let mut tests: Vec<PathBuf> = std::fs::read_dir(e2e_dir())?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(".test.mjs"))
        .filter(|p| {
            only.is_empty()
                || p.file_name()
                    .is_some_and(|n| only.iter().any(|o| n.to_string_lossy() == o.as_str()))
        })
        .collect();
    tests.sort();
    if tests.is_empty() {
        return Err(format!("no tests/e2e/*.test.mjs files (asked for {only:?})").into());
    }
    let result = run(cmd("node")
        .arg("--test")
        .args(&tests)
        .current_dir(e2e_dir())
        .env("RTNAV_URL", &url)
        .env("RTNAV_CLI", &cli)
        .env("RTNAV_SITE", site.join(E2E_SUB_PATH))
        .env("RTNAV_XTASK", std::env::current_exe()?)
        .env("RTNAV_CHROMIUM", tools::CHROMIUM)
        .env("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1"));
    drop(server);
    result.map(|()| None)
}
