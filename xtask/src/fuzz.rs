//! `cargo xtask fuzz [--seconds N] [--seed S] [--target NAME]…`: the project's fuzzer
//! (`rtnav-stress fuzz`, `stress/src/fuzz/`) in release mode, on stable Rust. `--seconds` is the wall
//! time in all, shared evenly by the targets (default 300); the seed is printed (from the
//! clock unless given), and every failure with the command that replays it. The kept
//! regression cases (`fixtures/fuzz-regressions/`) run first, and a failing input is written
//! to `target/fuzz-failures/TARGET/`, ready to be kept there.
//!
//! `cargo xtask test` has a fuzz stage ([`test_stage`]): the readers of a person's text and
//! files and a student's script, each for [`STAGE_SECONDS_PER_TARGET`] with a fresh seed
//! (printed), after their kept regression cases, with the debug runner `cargo test` has
//! already built ([`test_build_binary`]: nothing is compiled again). The short,
//! fixed-seed run of `stress/tests/fuzz.rs` is part of `cargo test`.

use crate::Result;
use crate::tools::{cargo, cmd, repo_root, run, target_dir, test_build_binary};

/// The targets of the fuzz stage: every reader of untrusted text or files (spec §6,
/// Decision 0.3) — scenario, replay and share-link JSON, `.conf` files and bundles, the map
/// formats and their YAML — and a student's script (spec §8: compiled, loaded and run in
/// MotorControl's or DriveControl's place).
pub const STAGE_TARGETS: &[&str] = &[
    "scenario",
    "replay",
    "share-json",
    "share-token",
    "conf",
    "conf-bundle",
    "json-map",
    "ros-yaml",
    "ros-map",
    "movingai-map",
    "movingai-scen",
    "script",
];

/// The stage's time budget per target \[s\] (12 targets: about 100 s in all, as when it had
/// 11 of 9 s).
pub const STAGE_SECONDS_PER_TARGET: f64 = 8.25;

/// Where a failing input is written.
fn failures_dir() -> std::path::PathBuf {
    target_dir().join("fuzz-failures")
}

/// Runs the fuzzer with the options in `rest` (passed through after checking).
pub fn fuzz(rest: &[String]) -> Result {
    let mut args: Vec<String> = Vec::new();
    let mut seconds = "300".to_owned();
    let mut it = rest.iter();
    while let Some(a) = it.next() {
        let value = |it: &mut std::slice::Iter<'_, String>| {
            it.next()
                .cloned()
                .ok_or_else(|| format!("fuzz: {a} needs a value"))
        };
        match a.as_str() {
            "--seconds" => seconds = value(&mut it)?,
            "--seed" | "--target" | "--case" | "--cases" => {
                args.push(a.clone());
                args.push(value(&mut it)?);
            }
            other => return Err(format!("fuzz: unexpected argument `{other}`").into()),
        }
    }
    if !seconds
        .parse::<f64>()
        .is_ok_and(|s| s.is_finite() && s >= 0.0)
    {
        return Err(format!("fuzz: --seconds `{seconds}` is not a number ≥ 0").into());
    }
    run(cargo()
        .args([
            "run",
            "--release",
            "-q",
            "-p",
            "rtnav-stress",
            "--",
            "fuzz",
            "--seconds",
        ])
        .arg(&seconds)
        .arg("--corpus")
        .arg(repo_root().join("fixtures/fuzz-regressions"))
        .arg("--save")
        .arg(failures_dir())
        .args(&args))
}

/// The fuzz stage of `cargo xtask test` (module documentation). The note is the budget.
pub fn test_stage() -> Result<Option<String>> {
    let seconds = STAGE_SECONDS_PER_TARGET * STAGE_TARGETS.len() as f64;
    let stress = test_build_binary("rtnav-stress")?;
    let mut c = cmd(&stress.to_string_lossy());
    c.args(["fuzz", "--seconds"])
        .arg(seconds.to_string())
        .arg("--corpus")
        .arg(repo_root().join("fixtures/fuzz-regressions"))
        .arg("--save")
        .arg(failures_dir());
    for t in STAGE_TARGETS {
        c.args(["--target", t]);
    }
    run(&mut c)?;
    Ok(Some(format!(
        "{} targets × {STAGE_SECONDS_PER_TARGET} s, fresh seed",
        STAGE_TARGETS.len()
    )))
}
