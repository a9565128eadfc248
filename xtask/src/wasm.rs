//! `cargo xtask build-wasm`: `rtnav-wasm` → `web/pkg/` (`rtnav_wasm.js` + `rtnav_wasm_bg.wasm`),
//! then the scenario fixtures → `web/fixtures/` (`crate::fixtures`).
//!
//! Three steps, each a tool we pin:
//!
//! 1. `cargo build -p rtnav-wasm --target wasm32-unknown-unknown --profile web`: the `web`
//!    profile of the root `Cargo.toml` (fat LTO, one codegen unit, no debug info, opt-level 3,
//!    which measured about twice as fast per frame as "s");
//! 2. `wasm-bindgen --target web` (the CLI at the version pinned in `Cargo.toml`), which also
//!    drops the debug sections and the name section;
//! 3. binaryen's `wasm-opt` from npm (`xtask/npm`, pinned, from its lockfile), with the
//!    features rustc's wasm32 output uses. Debian's binaryen 108 cannot be used: even a plain
//!    round trip through it breaks wasm-bindgen 0.2.130's externref table
//!    (`WebAssembly.Table.set(): Argument 1 is invalid for table` at start-up).
//!
//! No `wasm-pack`: it would only run steps 1 and 2 (and download a binaryen from GitHub for
//! step 3), and installing it cost CI several minutes. Each build prints the module's raw and
//! gzipped size.

use std::path::{Path, PathBuf};

use crate::Result;
use crate::tools::{self, cargo, cmd, run};

/// How to build.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Profile {
    /// The `web` profile, then `wasm-opt`: what the demo, `dist` and the e2e tests use.
    Release,
    /// The `dev` profile (debug info kept), no `wasm-opt`: quicker to build.
    Dev,
}

impl Profile {
    /// The cargo profile's name.
    fn cargo_profile(self) -> &'static str {
        match self {
            Profile::Release => "web",
            Profile::Dev => "dev",
        }
    }

    /// The folder of `target/wasm32-unknown-unknown/` the profile builds into.
    fn target_subdir(self) -> &'static str {
        match self {
            Profile::Release => "web",
            Profile::Dev => "debug",
        }
    }
}

/// The features rustc's wasm32-unknown-unknown output uses (its default target features
/// since Rust 1.82, and what wasm-bindgen's externref table needs); binaryen must accept
/// them all, and must not add any a browser of the project's baseline lacks.
const WASM_OPT_FEATURES: &[&str] = &[
    "--enable-bulk-memory",
    "--enable-mutable-globals",
    "--enable-nontrapping-float-to-int",
    "--enable-reference-types",
    "--enable-sign-ext",
    "--enable-multivalue",
];

/// `wasm-opt`'s optimisation level: for speed, as the cargo profile (`-Oz`, `-Os` and `-O2`
/// make the module smaller but compress no better: see docs/history.md).
const WASM_OPT_LEVEL: &str = "-O3";

/// Where the page loads the module from (git-ignored).
pub fn pkg_dir() -> PathBuf {
    tools::repo_root().join("web").join("pkg")
}

/// The module in [`pkg_dir`].
pub fn module_path() -> PathBuf {
    pkg_dir().join("rtnav_wasm_bg.wasm")
}

/// The JavaScript glue in [`pkg_dir`].
pub fn glue_path() -> PathBuf {
    pkg_dir().join("rtnav_wasm.js")
}

/// A module's size: raw and gzipped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Size {
    /// Bytes.
    pub raw: usize,
    /// Bytes after gzip at level 9: the `.gz` copy `cargo xtask dist` writes.
    pub gzip: usize,
}

impl Size {
    /// The size of `bytes`.
    pub fn of(bytes: &[u8]) -> Self {
        Self {
            raw: bytes.len(),
            gzip: crate::precompress::gzip(bytes).len(),
        }
    }
}

/// The most the page's module may weigh gzipped [bytes]: `cargo xtask test` fails past it, so
/// that the wasm grows by a decision (raising this, with the reason in the CHANGELOG), not by
/// accident. It was 766 KB when the budget was set.
pub const GZIP_BUDGET: usize = 850_000;

/// An error if `module` is over [`GZIP_BUDGET`].
pub fn check_budget(module: Size) -> Result {
    if module.gzip > GZIP_BUDGET {
        return Err(format!(
            "the wasm is {:.0} KB gzipped, over its budget of {:.0} KB (xtask/src/wasm.rs \
             GZIP_BUDGET): make it smaller, or raise the budget and say why in CHANGELOG.md",
            module.gzip as f64 / 1000.0,
            GZIP_BUDGET as f64 / 1000.0
        )
        .into());
    }
    Ok(())
}

impl std::fmt::Display for Size {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let kb = |b: usize| b as f64 / 1000.0;
        write!(
            f,
            "{:.0} KB ({:.0} KB gzipped)",
            kb(self.raw),
            kb(self.gzip)
        )
    }
}

/// What a build made.
#[derive(Debug, Clone, Copy)]
pub struct Built {
    /// `rtnav_wasm_bg.wasm`.
    pub module: Size,
    /// `rtnav_wasm.js`.
    pub glue: Size,
}

impl std::fmt::Display for Built {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "wasm {}, JS glue {}", self.module, self.glue)
    }
}

/// Installs what is missing, builds the wasm package into `web/pkg` and stages the fixtures.
pub fn build(profile: Profile) -> Result<Built> {
    let built = build_pkg(profile)?;
    crate::fixtures::stage()?;
    Ok(built)
}

/// The package alone: `web/pkg`, with its sizes printed.
pub fn build_pkg(profile: Profile) -> Result<Built> {
    tools::ensure_wasm_target()?;
    tools::ensure_wasm_bindgen_cli()?;
    let wasm_opt = match profile {
        Profile::Release => Some(tools::ensure_wasm_opt()?),
        Profile::Dev => None,
    };
    run(cargo().args([
        "build",
        "-p",
        "rtnav-wasm",
        "--lib",
        "--target",
        "wasm32-unknown-unknown",
        "--profile",
        profile.cargo_profile(),
    ]))?;
    let input = tools::target_dir()
        .join("wasm32-unknown-unknown")
        .join(profile.target_subdir())
        .join("rtnav_wasm.wasm");
    let out = pkg_dir();
    if out.exists() {
        std::fs::remove_dir_all(&out)?;
    }
    let mut bindgen = cmd("wasm-bindgen");
    bindgen.args(["--target", "web", "--out-dir"]).arg(&out);
    if profile == Profile::Release {
        bindgen.args(["--remove-name-section", "--remove-producers-section"]);
    } else {
        bindgen.arg("--keep-debug");
    }
    run(bindgen.arg(&input))?;
    let module = module_path();
    if let Some(wasm_opt) = wasm_opt {
        optimise(&wasm_opt, &module)?;
    }
    let built = Built {
        module: Size::of(&std::fs::read(&module)?),
        glue: Size::of(&std::fs::read(glue_path())?),
    };
    println!(
        "xtask: built {} ({} profile): {built}",
        out.display(),
        profile.cargo_profile()
    );
    Ok(built)
}

/// `wasm-opt` in place, with [`WASM_OPT_FEATURES`] and nothing but them.
fn optimise(wasm_opt: &Path, module: &Path) -> Result {
    let before = Size::of(&std::fs::read(module)?);
    let tmp = module.with_extension("opt.wasm");
    run(cmd(&wasm_opt.to_string_lossy())
        .arg(WASM_OPT_LEVEL)
        .arg("--mvp-features")
        .args(WASM_OPT_FEATURES)
        .args(["--strip-debug", "--strip-producers"])
        .arg(module)
        .arg("-o")
        .arg(&tmp))?;
    std::fs::rename(&tmp, module)?;
    println!(
        "xtask: wasm-opt {WASM_OPT_LEVEL}: {before} → {}",
        Size::of(&std::fs::read(module)?)
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_budget_refuses_a_module_past_it() {
        let at = |gzip| Size { raw: 0, gzip };
        assert!(check_budget(at(GZIP_BUDGET)).is_ok());
        let e = check_budget(at(GZIP_BUDGET + 1)).unwrap_err().to_string();
        assert!(e.contains("over its budget of 850 KB"), "{e}");
    }

    #[test]
    fn gzip_size_is_the_deflate_stream_and_its_framing() {
        let zeros = vec![0u8; 100_000];
        let s = Size::of(&zeros);
        assert_eq!(s.raw, 100_000);
        assert!(s.gzip > 18 && s.gzip < 1000, "{s:?}");
        assert_eq!(
            Size {
                raw: 2_750_000,
                gzip: 949_000
            }
            .to_string(),
            "2750 KB (949 KB gzipped)"
        );
    }
}
