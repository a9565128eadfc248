//! `cargo xtask types`: the page's type check. The core's view types write their TypeScript
//! declarations (`web/types/core.d.ts`, by `core/tests/typescript.rs` with the feature
//! `typescript`), wasm-bindgen writes the handle's (`web/pkg/rtnav_wasm.d.ts`, whose reads
//! return those types), and TypeScript checks the page's JavaScript against both
//! (`web/tsconfig.json`: `checkJs`, `strict`, `noEmit`). A field renamed in Rust fails here
//! wherever the page reads it.

use std::path::PathBuf;

use crate::Result;
use crate::tools::{self, cargo, cmd, run};
use crate::wasm;

/// The declarations wasm-bindgen writes beside the glue.
fn bindings() -> PathBuf {
    wasm::pkg_dir().join("rtnav_wasm.d.ts")
}

/// Writes `web/types/core.d.ts` from the Rust types.
pub fn write_declarations() -> Result {
    run(cargo()
        .args([
            "test",
            "-q",
            "-p",
            "rtnav",
            "--features",
            "typescript",
            "--test",
            "typescript",
        ])
        .env("RTNAV_WRITE_TYPES", "1"))
}

/// `tsc --noEmit` over the page (`web/tsconfig.json`).
pub fn type_check() -> Result {
    let tsc = tools::ensure_tsc()?;
    if !bindings().is_file() {
        return Err(format!(
            "{} missing: build the wasm first (`cargo xtask build-wasm`)",
            bindings().display()
        )
        .into());
    }
    let config = tools::repo_root().join("web").join("tsconfig.json");
    run(cmd(&tsc.to_string_lossy())
        .arg("-p")
        .arg(&config)
        .arg("--pretty")
        .arg("false"))
}

/// The command: the declarations written, the wasm built if its declarations are missing
/// (dev profile), the check.
pub fn types() -> Result {
    write_declarations()?;
    if !bindings().is_file() {
        wasm::build_pkg(wasm::Profile::Dev)?;
    }
    type_check()
}

/// The test stage: the declarations written again from the Rust types, then the check of
/// the page against them and the page stage's wasm declarations.
pub fn test_stage() -> Result<Option<String>> {
    write_declarations()?;
    type_check()?;
    Ok(None)
}
