//! `cargo xtask fuzz [--seconds N] [--seed S] [--target NAME]…`: the project's fuzzer
//! (`rtnav fuzz`, `cli/src/fuzz/`) in release mode, on stable Rust. `--seconds` is the wall
//! time in all, shared evenly by the targets (default 300); the seed is printed (from the
//! clock unless given), and every failure with the command that replays it. The short,
//! fixed-seed run of CI is `cli/tests/fuzz.rs`, part of `cargo test`.

use crate::Result;
use crate::tools::{cargo, run};

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
            "rtnav-cli",
            "--",
            "fuzz",
            "--seconds",
        ])
        .arg(&seconds)
        .args(&args))
}
