//! `cargo xtask types`: the page's type check. The core's view types write their TypeScript
//! declarations (`web/types/core.d.ts`, by `core/tests/typescript.rs` with the feature
//! `typescript`), wasm-bindgen writes the handle's (`web/pkg/rtnav_wasm.d.ts`, whose reads
//! return those types), and TypeScript checks the page's JavaScript against both
//! (`web/tsconfig.json`: `strict`, `noEmit`). A field renamed in Rust fails here wherever the
//! page reads it.
//!
//! Every module of the page is checked: each starts with `// @ts-check` (the check fails and
//! names the modules that do not), and none opts out (`@ts-nocheck`, `@ts-ignore`).

use std::path::{Path, PathBuf};

use crate::Result;
use crate::tools::{self, cargo, cmd, run};
use crate::wasm;

/// Modules of the page (relative to `web/`) not type-checked yet: named on every run, not a
/// failure. Every module is checked today; a module added here is a decision to write down.
const NOT_YET_CHECKED: &[&str] = &[];

/// The line each module starts with: it says so to a reader, and it keeps an editor checking
/// the module even where it opens it outside `web/tsconfig.json` (which sets `checkJs`).
const CHECK_LINE: &str = "// @ts-check";

/// What no module of the page may say: a way around the check.
const OPT_OUTS: &[&str] = &["@ts-nocheck", "@ts-ignore", "@ts-expect-error"];

/// The page's modules, as `web/tsconfig.json` includes them (`main.js`, `js/**/*.js`):
/// paths relative to `web`, with `/`, sorted.
fn page_modules(web: &Path) -> Result<Vec<String>> {
    fn walk(dir: &Path, rel: &str, out: &mut Vec<String>) -> Result {
        for entry in std::fs::read_dir(dir)? {
            let path = entry?.path();
            let name = path
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let rel = format!("{rel}/{name}");
            if path.is_dir() {
                walk(&path, &rel, out)?;
            } else if name.ends_with(".js") {
                out.push(rel);
            }
        }
        Ok(())
    }
    let mut out = vec!["main.js".to_owned()];
    walk(&web.join("js"), "js", &mut out)?;
    out.sort();
    Ok(out)
}

/// What the modules under `web` break of the rule: those without `// @ts-check` (as their
/// first line) that are not in `not_yet`, and every opt-out. Also returns the modules of
/// `not_yet` still unchecked.
fn unchecked(web: &Path, not_yet: &[&str]) -> Result<(Vec<String>, Vec<String>)> {
    let mut problems = Vec::new();
    let mut waiting = Vec::new();
    for module in page_modules(web)? {
        let text = std::fs::read_to_string(web.join(&module))?;
        if text.lines().next().map(str::trim_end) != Some(CHECK_LINE) {
            if not_yet.contains(&module.as_str()) {
                waiting.push(module.clone());
            } else {
                problems.push(format!(
                    "web/{module}: not type-checked (its first line is not `{CHECK_LINE}`)"
                ));
            }
        }
        for (i, line) in text.lines().enumerate() {
            for opt_out in OPT_OUTS {
                if line.contains(opt_out) {
                    problems.push(format!(
                        "web/{module}:{}: `{opt_out}` goes around the type check",
                        i + 1
                    ));
                }
            }
        }
    }
    Ok((problems, waiting))
}

/// Fails, naming them, when a module of the page is not type-checked or opts out; names the
/// modules still waiting to be annotated.
pub fn check_every_module_is_checked() -> Result {
    let web = tools::repo_root().join("web");
    let (problems, waiting) = unchecked(&web, NOT_YET_CHECKED)?;
    if !waiting.is_empty() {
        println!(
            "xtask: not type-checked yet (xtask/src/types.rs NOT_YET_CHECKED): web/{}",
            waiting.join(", web/")
        );
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "every module of the page is type-checked:\n  {}",
            problems.join("\n  ")
        )
        .into())
    }
}

/// The declarations wasm-bindgen writes beside the glue.
fn bindings() -> PathBuf {
    wasm::pkg_dir().join("rtnav_wasm.d.ts")
}

/// Writes `web/types/core.d.ts` from the Rust types.
pub fn write_declarations() -> Result {
    // The workspace's build of the core (the test stage's), so that after it this only runs.
    run(cargo()
        .args(["test", "-q", "--test", "typescript"])
        .args(tools::WORKSPACE_FEATURES)
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
    type_check()?;
    check_every_module_is_checked()
}

/// The test stage: the declarations written again from the Rust types, then the check of
/// the page against them and the page stage's wasm declarations.
pub fn test_stage() -> Result<Option<String>> {
    write_declarations()?;
    type_check()?;
    check_every_module_is_checked()?;
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A folder laid out as `web/` with the modules `files` (path, text).
    fn web_with(name: &str, files: &[(&str, &str)]) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rtnav-types-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        for (path, text) in files {
            let file = dir.join(path);
            std::fs::create_dir_all(file.parent().unwrap()).unwrap();
            std::fs::write(file, text).unwrap();
        }
        dir
    }

    #[test]
    fn a_module_without_the_check_line_is_named() {
        let web = web_with(
            "unchecked",
            &[
                ("main.js", "// @ts-check\nimport './js/a.js';\n"),
                ("js/a.js", "// @ts-check\nexport const a = 1;\n"),
                ("js/panels/b.js", "// The panel B.\nexport const b = 2;\n"),
                ("js/later.js", "export const c = 3;\n"),
                ("pkg/glue.js", "export const d = 4;\n"),
            ],
        );
        let (problems, waiting) = unchecked(&web, &["js/later.js"]).unwrap();
        assert_eq!(
            problems,
            ["web/js/panels/b.js: not type-checked (its first line is not `// @ts-check`)"]
        );
        assert_eq!(waiting, ["js/later.js"]);
        let (problems, waiting) = unchecked(&web, &[]).unwrap();
        assert_eq!(problems.len(), 2, "{problems:?}");
        assert!(waiting.is_empty());
        std::fs::remove_dir_all(web).unwrap();
    }

    #[test]
    fn an_opt_out_is_named_with_its_line() {
        let web = web_with(
            "opt-out",
            &[
                ("main.js", "// @ts-check\n// @ts-ignore\nx.y = 1;\n"),
                ("js/a.js", "// @ts-nocheck\nexport const a = 1;\n"),
            ],
        );
        let (problems, _) = unchecked(&web, &[]).unwrap();
        assert_eq!(
            problems,
            [
                "web/js/a.js: not type-checked (its first line is not `// @ts-check`)",
                "web/js/a.js:1: `@ts-nocheck` goes around the type check",
                "web/main.js:2: `@ts-ignore` goes around the type check",
            ]
        );
        std::fs::remove_dir_all(web).unwrap();
    }

    #[test]
    fn the_page_s_modules_are_all_checked_but_those_named() {
        let web = tools::repo_root().join("web");
        let (problems, _) = unchecked(&web, NOT_YET_CHECKED).unwrap();
        assert!(problems.is_empty(), "{problems:#?}");
    }
}
