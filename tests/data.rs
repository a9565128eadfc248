//! The external data (`$RTNAV_DATA`, else `../shared/data` next to the repository; see
//! [`rtnav::data`]) for the whole-system tests, read at run time on both targets: natively
//! from the filesystem, in wasm32 through Node's `fs` (the tests run under Node, which
//! `wasm-bindgen-test-runner` starts with our environment).
//!
//! A test that needs the data and finds none calls [`skip`]: one line on the terminal saying
//! what is skipped and why, written past the test harness's output capture so it shows in a
//! normal run.

use rtnav::data::DataMissing;

/// The repository's root, as this crate was compiled (the tests run where they are built).
pub const REPO_ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/..");

/// The external data folder, found at run time.
#[derive(Debug, Clone)]
pub struct Data {
    dir: String,
}

impl Data {
    /// `$RTNAV_DATA`, else `../shared/data` beside [`REPO_ROOT`]; an error naming where it
    /// looked if that is not a folder.
    pub fn locate() -> Result<Self, DataMissing> {
        #[cfg(not(target_arch = "wasm32"))]
        {
            let dir = rtnav::data::data_dir(std::path::Path::new(REPO_ROOT))?;
            Ok(Self {
                dir: dir.to_string_lossy().into_owned(),
            })
        }
        #[cfg(target_arch = "wasm32")]
        {
            use rtnav::data::{DATA_ENV, DEFAULT_DATA_DIR};
            let default = format!("{REPO_ROOT}/{DEFAULT_DATA_DIR}");
            let looked = match node::env(DATA_ENV) {
                Some(dir) if dir.is_empty() => format!("{DATA_ENV} is set but empty"),
                Some(dir) if node::is_dir(&dir) => return Ok(Self { dir }),
                Some(dir) => format!("{DATA_ENV}={dir} is not a folder"),
                None if node::is_dir(&default) => return Ok(Self { dir: default }),
                None => format!("{DATA_ENV} is unset and {default} is not a folder"),
            };
            Err(DataMissing { looked })
        }
    }

    /// The folder.
    pub fn dir(&self) -> &str {
        &self.dir
    }

    /// The bytes of `rel`, a path inside the folder (e.g. `movingai/dao/arena.map`).
    pub fn read(&self, rel: &str) -> Result<Vec<u8>, String> {
        let path = format!("{}/{rel}", self.dir.trim_end_matches('/'));
        #[cfg(not(target_arch = "wasm32"))]
        {
            std::fs::read(&path).map_err(|e| format!("cannot read {path}: {e}"))
        }
        #[cfg(target_arch = "wasm32")]
        {
            node::read(&path)
        }
    }
}

/// Says, on one line, that `test` is skipped and why. Written straight to the process's
/// standard error (natively past libtest's capture; in Node past the runner's console
/// capture), so a normal test run shows it.
pub fn skip(test: &str, why: &dyn std::fmt::Display) {
    let line = format!("SKIPPED {test}: {why}\n");
    #[cfg(not(target_arch = "wasm32"))]
    {
        use std::io::Write as _;
        let _ = std::io::stderr().lock().write_all(line.as_bytes());
    }
    #[cfg(target_arch = "wasm32")]
    node::stderr(&line);
}

/// The few Node calls the wasm32 tests need, through `globalThis.process` (there in every
/// Node module, CommonJS or ES). `process.getBuiltinModule` needs Node ≥ 20.16.
#[cfg(target_arch = "wasm32")]
mod node {
    use wasm_bindgen::prelude::*;

    #[wasm_bindgen(inline_js = r#"
const fs = () => globalThis.process.getBuiltinModule('node:fs');
export function rtnav_env(name) {
  const v = globalThis.process.env[name];
  return v === undefined ? undefined : String(v);
}
export function rtnav_is_dir(path) {
  try { return fs().statSync(path).isDirectory(); } catch (e) { return false; }
}
export function rtnav_read(path) {
  return new Uint8Array(fs().readFileSync(path));
}
export function rtnav_stderr(text) {
  globalThis.process.stderr.write(text);
}
"#)]
    extern "C" {
        fn rtnav_env(name: &str) -> Option<String>;
        fn rtnav_is_dir(path: &str) -> bool;
        #[wasm_bindgen(catch)]
        fn rtnav_read(path: &str) -> Result<Vec<u8>, JsValue>;
        fn rtnav_stderr(text: &str);
    }

    pub fn env(name: &str) -> Option<String> {
        rtnav_env(name)
    }

    pub fn is_dir(path: &str) -> bool {
        rtnav_is_dir(path)
    }

    pub fn read(path: &str) -> Result<Vec<u8>, String> {
        rtnav_read(path).map_err(|e| {
            let why = js_sys::Reflect::get(&e, &"message".into())
                .ok()
                .and_then(|m| m.as_string())
                .unwrap_or_else(|| format!("{e:?}"));
            format!("cannot read {path}: {why}")
        })
    }

    pub fn stderr(text: &str) {
        rtnav_stderr(text);
    }
}
