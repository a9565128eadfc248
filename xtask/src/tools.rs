//! Running commands, and installing the tools they need when they are missing.
//!
//! Every `ensure_*` function checks first and installs only what is missing or has the wrong
//! version, so running a command twice does no work the second time. Sources: rustup, crates.io
//! (`cargo install`), Debian (`apt-get`) and npm (from lockfiles); never GitHub.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};

use crate::Result;

/// The oldest Node that `playwright-core` (tests/e2e) supports and that has
/// `process.getBuiltinModule` (the wasm tests read the external data through it).
const MIN_NODE: (u32, u32) = (20, 16);
/// The browser the end-to-end tests drive (Debian's `chromium`).
pub const CHROMIUM: &str = "/usr/bin/chromium";

/// The repository's root (the parent of `xtask/`).
pub fn repo_root() -> PathBuf {
    let xtask = Path::new(env!("CARGO_MANIFEST_DIR"));
    xtask.parent().unwrap_or(xtask).to_path_buf()
}

/// Where `cargo install` puts binaries: `$CARGO_HOME/bin`, by default `~/.cargo/bin`.
fn cargo_bin_dir() -> Option<PathBuf> {
    let home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cargo")))?;
    Some(home.join("bin"))
}

/// `PATH` with cargo's bin directory in front, so tools just installed are found (by us and
/// by `wasm-pack`, which looks for `wasm-bindgen` on `PATH`).
fn search_path() -> std::ffi::OsString {
    let mut dirs: Vec<PathBuf> = cargo_bin_dir().into_iter().collect();
    if let Some(path) = std::env::var_os("PATH") {
        dirs.extend(std::env::split_paths(&path));
    }
    std::env::join_paths(dirs).unwrap_or_default()
}

/// A command run from the repository root with [`search_path`].
pub fn cmd(program: &str) -> Command {
    let mut c = Command::new(program);
    c.current_dir(repo_root()).env("PATH", search_path());
    c
}

/// `cargo`: the one running us (from `$CARGO`) if known.
/// The features every workspace build of the test run uses, so the test stage, the type
/// check's declarations and the browser tests' `rtnav` share one build of the core (features
/// unify per build: a build with other features compiles the core again).
pub const WORKSPACE_FEATURES: [&str; 3] = ["--workspace", "--features", "rtnav/typescript"];

/// The workspace's debug binary `name` as the test stage builds it: `cargo test --no-run`
/// with [`WORKSPACE_FEATURES`], which has nothing to do once `cargo test` ran. The fuzz, soak
/// and browser stages run it, so no stage compiles the workspace a second time: a `cargo run
/// -p rtnav-stress` (the core without `typescript`) or a `cargo build` (no dev-dependencies,
/// so other features for a few shared crates) would, because features unify per build.
pub fn test_build_binary(name: &str) -> Result<PathBuf> {
    run(cargo()
        .args(["test", "--no-run", "-q"])
        .args(WORKSPACE_FEATURES))?;
    let bin = target_dir()
        .join("debug")
        .join(format!("{name}{}", std::env::consts::EXE_SUFFIX));
    if !bin.is_file() {
        return Err(format!("the test build made no binary {}", bin.display()).into());
    }
    Ok(bin)
}

pub fn cargo() -> Command {
    let program = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_owned());
    let mut c = cmd(&program);
    // A CI run builds once from a clean clone: incremental caches would only fill its disk.
    if std::env::var_os("CI").is_some() && std::env::var_os("CARGO_INCREMENTAL").is_none() {
        c.env("CARGO_INCREMENTAL", "0");
    }
    c
}

fn describe(c: &Command) -> String {
    let mut text = c.get_program().to_string_lossy().into_owned();
    for a in c.get_args() {
        text.push(' ');
        text.push_str(&a.to_string_lossy());
    }
    text
}

/// Runs `c`, echoing it first; an error if it cannot start or exits non-zero.
pub fn run(c: &mut Command) -> Result {
    let text = describe(c);
    println!("$ {text}");
    let status = c
        .status()
        .map_err(|e| format!("cannot run `{text}`: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("`{text}` failed ({status})").into())
    }
}

/// The trimmed stdout of `program args` if it runs and succeeds (quietly; for version checks).
fn output_of(program: &str, args: &[&str]) -> Option<String> {
    let out = cmd(program)
        .args(args)
        .stdin(Stdio::null())
        .stderr(Stdio::null())
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_owned())
}

/// The `wasm-bindgen` version pinned (`= x.y.z`) in the root `Cargo.toml`. The CLI must have
/// exactly this version: it and the library agree on a private ABI.
pub fn pinned_wasm_bindgen() -> Result<String> {
    let manifest = std::fs::read_to_string(repo_root().join("Cargo.toml"))?;
    manifest
        .lines()
        .filter_map(|l| l.trim().strip_prefix("wasm-bindgen"))
        .filter_map(|l| l.trim_start().strip_prefix('='))
        .filter_map(|l| l.trim().strip_prefix("\"="))
        .find_map(|l| l.split('"').next().map(str::to_owned))
        .ok_or_else(|| "no `wasm-bindgen = \"=x.y.z\"` pin in the root Cargo.toml".into())
}

/// `rustup target add wasm32-unknown-unknown` unless it is installed.
pub fn ensure_wasm_target() -> Result {
    let installed = output_of("rustup", &["target", "list", "--installed"]).unwrap_or_default();
    if installed
        .lines()
        .any(|t| t.trim() == "wasm32-unknown-unknown")
    {
        return Ok(());
    }
    run(cmd("rustup").args(["target", "add", "wasm32-unknown-unknown"]))
}

/// `cargo install` of `krate` at exactly `version`, with `options`, unless `binary --version`
/// already says `version`. `--locked` first; if the registry lacks a version the published
/// lockfile names (a mirror can), once more without it: the crate's own version stays exact
/// either way.
fn ensure_cargo_tool(binary: &str, krate: &str, version: &str, options: &[&str]) -> Result {
    let have = output_of(binary, &["--version"]);
    if have
        .as_deref()
        .and_then(|v| v.split_whitespace().nth(1))
        .is_some_and(|v| v == version)
    {
        return Ok(());
    }
    match &have {
        Some(v) => println!("xtask: found `{v}`, need {krate} {version}: installing"),
        None => println!("xtask: `{binary}` not found: installing {krate} {version}"),
    }
    let install = |locked: bool| {
        let mut c = cargo();
        c.args([
            "install",
            krate,
            "--version",
            &format!("={version}"),
            "--force",
        ]);
        c.args(options);
        // Its own temporary build folder (cargo's default for `install`), not the project's:
        // `cargo xtask test` installs while the test stage builds there.
        c.env_remove("CARGO_TARGET_DIR");
        if locked {
            c.arg("--locked");
        }
        run(&mut c)
    };
    install(true).or_else(|e| {
        println!(
            "xtask: `cargo install --locked` failed ({e}); retrying without --locked \
             (dependencies resolved from the registry, {krate} itself still ={version})"
        );
        install(false)
    })
}

/// `wasm-bindgen`, `wasm-bindgen-test-runner` etc. at the version pinned in `Cargo.toml`.
///
/// Only the two programs xtask runs, and without the crate's default `rustls-tls` feature:
/// the test runner talks to Node and to local web drivers over plain HTTP, and leaving out
/// rustls and `ring` (C and assembly) spares a fresh machine a good part of the install.
pub fn ensure_wasm_bindgen_cli() -> Result {
    ensure_cargo_tool(
        "wasm-bindgen",
        "wasm-bindgen-cli",
        &pinned_wasm_bindgen()?,
        &[
            "--no-default-features",
            "--bin",
            "wasm-bindgen",
            "--bin",
            "wasm-bindgen-test-runner",
        ],
    )
}

/// Where cargo builds: `$CARGO_TARGET_DIR`, else `target/` in the repository.
pub fn target_dir() -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| repo_root().join("target"), PathBuf::from)
}

/// The folder of the npm tools `cargo xtask` runs (`package.json` and its lockfile).
fn npm_tools_dir() -> PathBuf {
    repo_root().join("xtask").join("npm")
}

/// The version of `package` pinned in `xtask/npm/package.json`'s devDependencies.
fn npm_pinned(package: &str) -> Result<String> {
    let path = npm_tools_dir().join("package.json");
    let manifest: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&path)?)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    manifest["devDependencies"][package]
        .as_str()
        .map(str::to_owned)
        .ok_or_else(|| format!("{}: no devDependency `{package}`", path.display()).into())
}

/// binaryen's `wasm-opt` from npm (the `binaryen` package at the version pinned in
/// `xtask/npm/package.json`, installed from its lockfile with `npm ci` unless
/// `wasm-opt --version` already says that version). Debian's binaryen 108 cannot be used: it
/// breaks wasm-bindgen 0.2.130's externref table. Returns the program's path.
pub fn ensure_wasm_opt() -> Result<PathBuf> {
    let dir = npm_tools_dir();
    let program = dir.join("node_modules").join(".bin").join("wasm-opt");
    let major = npm_pinned("binaryen")?
        .split('.')
        .next()
        .unwrap_or_default()
        .to_owned();
    let wanted = format!("wasm-opt version {major} ");
    let have = output_of(&program.to_string_lossy(), &["--version"]);
    if have.as_deref().is_some_and(|v| v.starts_with(&wanted)) {
        return Ok(program);
    }
    ensure_node()?;
    println!(
        "xtask: installing binaryen {major} (wasm-opt) from npm into {}",
        dir.display()
    );
    run(cmd("npm")
        .args(["ci", "--no-audit", "--no-fund"])
        .current_dir(&dir))?;
    match output_of(&program.to_string_lossy(), &["--version"]) {
        Some(v) if v.starts_with(&wanted) => Ok(program),
        other => Err(format!(
            "{} says {other:?} after `npm ci`, expected binaryen {major}",
            program.display()
        )
        .into()),
    }
}

/// TypeScript's `tsc` from npm (the `typescript` package at the version pinned in
/// `xtask/npm/package.json`, installed from its lockfile with `npm ci` unless
/// `tsc --version` already says that version). Returns the program's path.
pub fn ensure_tsc() -> Result<PathBuf> {
    let dir = npm_tools_dir();
    let program = dir.join("node_modules").join(".bin").join("tsc");
    let wanted = format!("Version {}", npm_pinned("typescript")?);
    let have = output_of(&program.to_string_lossy(), &["--version"]);
    if have.as_deref().is_some_and(|v| v.trim() == wanted) {
        return Ok(program);
    }
    ensure_node()?;
    println!(
        "xtask: installing TypeScript ({wanted}) from npm into {}",
        dir.display()
    );
    run(cmd("npm")
        .args(["ci", "--no-audit", "--no-fund"])
        .current_dir(&dir))?;
    match output_of(&program.to_string_lossy(), &["--version"]) {
        Some(v) if v.trim() == wanted => Ok(program),
        other => Err(format!(
            "{} says {other:?} after `npm ci`, expected {wanted}",
            program.display()
        )
        .into()),
    }
}

static APT_UPDATED: AtomicBool = AtomicBool::new(false);

/// `apt-get`, through `sudo` unless we are root, waiting for another apt to finish.
fn apt_get(args: &[&str]) -> Result {
    let root = output_of("id", &["-u"]).as_deref() == Some("0");
    let mut c = if root { cmd("apt-get") } else { cmd("sudo") };
    if !root {
        c.arg("apt-get");
    }
    c.env("DEBIAN_FRONTEND", "noninteractive")
        .args(["-o", "DPkg::Lock::Timeout=600"])
        .args(args);
    run(&mut c)
}

/// Installs Debian `packages` unless `file` exists (`apt-get update` once per run first).
pub fn ensure_apt(file: &str, packages: &[&str]) -> Result {
    if Path::new(file).exists() {
        return Ok(());
    }
    println!("xtask: {file} not found: installing {}", packages.join(" "));
    if !APT_UPDATED.swap(true, Ordering::SeqCst) {
        apt_get(&["update"])?;
    }
    let mut args = vec!["install", "-y", "--no-install-recommends"];
    args.extend_from_slice(packages);
    apt_get(&args)?;
    if Path::new(file).exists() {
        Ok(())
    } else {
        Err(format!(
            "{file} still missing after installing {}",
            packages.join(" ")
        )
        .into())
    }
}

/// Debian's `chromium` and a font for the page's text.
pub fn ensure_chromium() -> Result {
    ensure_apt(CHROMIUM, &["chromium", "fonts-liberation"])
}

/// Whether `dir/node_modules` holds exactly the packages of `dir/package-lock.json`: npm's
/// own record of what it installed (`node_modules/.package-lock.json`) lists the same
/// packages, at the same versions and integrity, as the lockfile.
pub fn npm_installed(dir: &Path) -> bool {
    let packages = |path: PathBuf| -> Option<serde_json::Map<String, serde_json::Value>> {
        let text = std::fs::read_to_string(path).ok()?;
        let mut value: serde_json::Value = serde_json::from_str(&text).ok()?;
        let mut packages = value.get_mut("packages")?.as_object_mut()?.clone();
        packages.remove(""); // the project itself, in the lockfile only
        Some(packages)
    };
    let wanted = packages(dir.join("package-lock.json"));
    let installed = packages(dir.join("node_modules").join(".package-lock.json"));
    wanted.is_some() && wanted == installed
}

/// Checks that `node` and `npm` are there and Node is new enough.
pub fn ensure_node() -> Result {
    let version = output_of("node", &["--version"]).ok_or("`node` not found: install Node.js")?;
    let mut parts = version
        .trim_start_matches('v')
        .split('.')
        .map(|m| m.parse::<u32>().ok());
    let (Some(Some(major)), Some(Some(minor))) = (parts.next(), parts.next()) else {
        return Err(format!("cannot read Node's version `{version}`").into());
    };
    if (major, minor) < MIN_NODE {
        let (a, b) = MIN_NODE;
        return Err(format!("Node {version} is too old: need {a}.{b} or newer").into());
    }
    output_of("npm", &["--version"]).ok_or("`npm` not found: install npm")?;
    Ok(())
}
