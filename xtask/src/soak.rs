//! `cargo xtask soak [--hours H] [--scenario FILE] [--seed S]`: the closed loop for hours of
//! simulated time (`rtnav-stress soak`, `stress/src/soak.rs`) in release mode. Without `--scenario`, it
//! soaks open_field and then the Willow Garage ROS map from the shared data (skipped, with a
//! line saying so, when the data is absent). Fails on a bump, a panic, a component error, a
//! stuck period or growing memory.
//!
//! `cargo xtask test` runs a one-hour soak of open_field ([`test_stage`]) with the debug
//! runner that `cargo test` has already built (about 30 s; [`test_build_binary`]), rather
//! than building the release runner for it.

use crate::Result;
use crate::tools::{cargo, cmd, run, test_build_binary};

/// The scenarios soaked when none is named.
const DEFAULT_SCENARIOS: [&str; 2] = [
    "fixtures/scenarios/open_field.json",
    "fixtures/scenarios/willow_garage.json",
];

/// Runs the soak with the options in `rest`.
pub fn soak(rest: &[String]) -> Result {
    let mut hours = "24".to_owned();
    let mut seed: Option<String> = None;
    let mut scenarios: Vec<String> = Vec::new();
    let mut it = rest.iter();
    while let Some(a) = it.next() {
        let mut value = || {
            it.next()
                .cloned()
                .ok_or_else(|| format!("soak: {a} needs a value"))
        };
        match a.as_str() {
            "--hours" => hours = value()?,
            "--seed" => seed = Some(value()?),
            "--scenario" => scenarios.push(value()?),
            other => return Err(format!("soak: unexpected argument `{other}`").into()),
        }
    }
    if !hours.parse::<f64>().is_ok_and(|h| h.is_finite() && h > 0.0) {
        return Err(format!("soak: --hours `{hours}` is not a positive number").into());
    }
    if scenarios.is_empty() {
        scenarios = DEFAULT_SCENARIOS.iter().map(|s| (*s).to_owned()).collect();
    }
    let mut failed = Vec::new();
    for scenario in &scenarios {
        let mut c = cargo();
        c.args([
            "run",
            "--release",
            "-q",
            "-p",
            "rtnav-stress",
            "--",
            "soak",
            "--hours",
        ])
        .arg(&hours)
        .args(["--scenario", scenario]);
        if let Some(s) = &seed {
            c.args(["--seed", s]);
        }
        if let Err(e) = run(&mut c) {
            eprintln!("xtask: soak of {scenario} failed: {e}");
            failed.push(scenario.as_str());
        }
    }
    if failed.is_empty() {
        Ok(())
    } else {
        Err(format!("soak failed: {}", failed.join(", ")).into())
    }
}

/// The stage of `cargo xtask test`: one simulated hour of open_field.
pub fn test_stage() -> Result<Option<String>> {
    let stress = test_build_binary("rtnav-stress")?;
    run(cmd(&stress.to_string_lossy()).args([
        "soak",
        "--hours",
        "1",
        "--scenario",
        "fixtures/scenarios/open_field.json",
    ]))?;
    Ok(None)
}
