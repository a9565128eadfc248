//! `cargo xtask build-wasm`: `rtnav-wasm` → `web/pkg/` (`rtnav_wasm.js` + `rtnav_wasm_bg.wasm`),
//! then the scenario fixtures → `web/fixtures/` (`crate::fixtures`).
//!
//! `wasm-pack` runs with `--mode no-install`, so it uses the `wasm-bindgen` we installed and
//! never downloads one. Its `wasm-opt` step is off (`wasm/Cargo.toml`): it would download
//! binaryen from GitHub, and Debian's binaryen (108, bookworm) is too old for wasm-bindgen
//! 0.2.130's output — even a plain `wasm-opt in.wasm -o out.wasm` round trip breaks the
//! externref table (`WebAssembly.Table.set(): Argument 1 is invalid for table` at start-up).
//! The module is used as rustc and wasm-bindgen leave it (release: ~170 KB; `wasm-opt -Oz`
//! would save ~20%).

use std::path::PathBuf;

use crate::Result;
use crate::tools::{self, cmd, run};

/// How to build.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Profile {
    /// Optimised: what the demo and the e2e tests use.
    Release,
    /// Unoptimised, with debug info; quicker to build.
    Dev,
}

/// Where the page loads the module from (git-ignored).
pub fn pkg_dir() -> PathBuf {
    tools::repo_root().join("web").join("pkg")
}

/// Installs what is missing, then builds the wasm package into `web/pkg`.
pub fn build(profile: Profile) -> Result {
    tools::ensure_wasm_target()?;
    tools::ensure_wasm_bindgen_cli()?;
    tools::ensure_wasm_pack()?;
    let out = pkg_dir();
    let mut c = cmd("wasm-pack");
    c.args([
        "build",
        "wasm",
        "--mode",
        "no-install",
        "--target",
        "web",
        "--no-pack",
    ])
    .arg("--out-dir")
    .arg(&out)
    .arg(match profile {
        Profile::Release => "--release",
        Profile::Dev => "--dev",
    });
    run(&mut c)?;
    println!("xtask: built {}", out.display());
    crate::fixtures::stage()
}
