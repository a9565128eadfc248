//! `cargo xtask dist [DIR]`: the page as a static folder (default `dist/`) that works from any
//! static file server, at any path (`https://example.org/rtnav/`): no server of ours.
//!
//! It holds the page (`index.html`, `style.css`, `main.js`, `js/`), the wasm package
//! (`pkg/rtnav_wasm.js`, `pkg/rtnav_wasm_bg.wasm`) and the scenarios with their maps
//! (`fixtures/`, as `crate::fixtures` stages them: the repository's, and the external data's
//! when it is there). Every URL the page uses is relative to the page, so the folder can be
//! served under any sub-path; nothing needs a special header (a server that does not send
//! `application/wasm` for `.wasm` only costs the streaming compile).
//!
//! `index.html` gets a module preload for every module (so they download at once, not one
//! level of imports after another). Two things are written last, from the folder's files: the service worker's build
//! (`sw.js`: every file with its SHA-256 and the build's version, `crate::service_worker`),
//! and the precompressed copies beside the files (`NAME.br`, `NAME.gz`:
//! `crate::precompress`). `cargo xtask dist --seal DIR` writes both again for a folder whose
//! files were changed by hand.

use std::path::{Path, PathBuf};

use crate::Result;
use crate::tools;
use crate::wasm;
use crate::{precompress, service_worker};

/// The folder `cargo xtask dist` writes when not told.
pub fn default_dir() -> PathBuf {
    tools::repo_root().join("dist")
}

/// Builds the wasm (release) and writes the folder.
pub fn build(dir: &Path) -> Result<wasm::Built> {
    let built = wasm::build_pkg(wasm::Profile::Release)?;
    assemble(dir)?;
    Ok(built)
}

/// Writes the folder from `web/` and the wasm package already in `web/pkg` (emptied first).
pub fn assemble(dir: &Path) -> Result {
    let web = tools::repo_root().join("web");
    for file in [wasm::module_path(), wasm::glue_path()] {
        if !file.is_file() {
            return Err(format!(
                "{} is missing: build the wasm first (`cargo xtask build-wasm`)",
                file.display()
            )
            .into());
        }
    }
    if dir.exists() {
        std::fs::remove_dir_all(dir).map_err(|e| format!("cannot empty {}: {e}", dir.display()))?;
    }
    std::fs::create_dir_all(dir)?;
    // The page's own files: everything under web/ but what xtask makes there and what only
    // the type check reads (the declarations, the TypeScript configuration).
    copy_tree(&web, dir, &|rel: &Path| {
        let first = rel.components().next().map(|c| c.as_os_str().to_owned());
        let only_typing = |f: &std::ffi::OsString| f == "types" || f == "tsconfig.json";
        !first.is_some_and(|f| {
            f == "pkg" || f == "fixtures" || f == "node_modules" || only_typing(&f)
        }) && !rel
            .file_name()
            .is_some_and(|n| n.to_string_lossy().starts_with('.'))
    })?;
    let pkg = dir.join("pkg");
    std::fs::create_dir_all(&pkg)?;
    for file in [wasm::module_path(), wasm::glue_path()] {
        let name = file.file_name().ok_or("a file without a name")?;
        std::fs::copy(&file, pkg.join(name))?;
    }
    let n = crate::fixtures::stage_into(&tools::repo_root(), &dir.join("fixtures"))?;
    preload_modules(dir)?;
    check_relative(dir)?;
    seal(dir)?;
    println!(
        "xtask: {} written: the page, the wasm and {n} scenarios (serve it from any static \
         server, under any path)",
        dir.display()
    );
    Ok(())
}

/// The page's entry script in `index.html`; the module preloads go before it.
const ENTRY: &str = r#"<script type="module" src="./main.js"></script>"#;

/// `index.html` of the folder `dir` with a `<link rel="modulepreload">` for every module the
/// page imports (every `.js` under `js/` and `pkg/`) before its entry script: the browser
/// fetches them all at once instead of one level of imports after another (a round trip
/// each on a slow network). `web/index.html` has none, so there is no list to keep.
fn preload_modules(dir: &Path) -> Result {
    let mut modules: Vec<String> = Vec::new();
    for sub in ["js", "pkg"] {
        for rel in precompress::files_under(&dir.join(sub))? {
            if rel.extension().is_some_and(|e| e == "js") {
                let parts: Vec<String> = rel
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy().into_owned())
                    .collect();
                modules.push(format!("./{sub}/{}", parts.join("/")));
            }
        }
    }
    let page = dir.join("index.html");
    let html = std::fs::read_to_string(&page)?;
    std::fs::write(&page, with_preloads(&html, &modules)?)?;
    Ok(())
}

/// `html` with a module preload for each of `modules` before [`ENTRY`].
fn with_preloads(html: &str, modules: &[String]) -> Result<String> {
    let at = html
        .find(ENTRY)
        .ok_or_else(|| format!("index.html has no `{ENTRY}` to preload the modules for"))?;
    let indent = html[..at]
        .rsplit('\n')
        .next()
        .filter(|s| s.trim().is_empty())
        .unwrap_or("");
    let links: String = modules
        .iter()
        .map(|m| format!(r#"<link rel="modulepreload" href="{m}">"#) + "\n" + indent)
        .collect();
    Ok(format!("{}{links}{}", &html[..at], &html[at..]))
}

/// Writes the service worker's build and the precompressed copies of the folder `dir` (last:
/// they are made from its files as they are).
pub fn seal(dir: &Path) -> Result {
    let sealed = service_worker::seal(dir)?;
    println!(
        "xtask: offline build {}: {} files, {:.0} KB, kept by the service worker",
        sealed.version,
        sealed.files,
        sealed.bytes as f64 / 1000.0
    );
    let written = precompress::write_beside(dir)?;
    println!("xtask: precompressed copies (.br, .gz) of {written}");
    Ok(())
}

/// Copies the files of `from` whose path (relative to `from`) `keep` accepts into `to`.
fn copy_tree(from: &Path, to: &Path, keep: &dyn Fn(&Path) -> bool) -> Result {
    let mut stack = vec![PathBuf::new()];
    while let Some(rel) = stack.pop() {
        let mut entries: Vec<_> = std::fs::read_dir(from.join(&rel))?
            .filter_map(|e| e.ok())
            .collect();
        entries.sort_by_key(|e| e.file_name());
        for e in entries {
            let rel = rel.join(e.file_name());
            if !keep(&rel) {
                continue;
            }
            if e.file_type()?.is_dir() {
                std::fs::create_dir_all(to.join(&rel))?;
                stack.push(rel);
            } else {
                std::fs::copy(e.path(), to.join(&rel))?;
            }
        }
    }
    Ok(())
}

/// Every URL in the folder's HTML and JavaScript that the page loads is relative: no
/// `src="/…"`, `href="/…"`, `from '/…'`, `import('/…')` or `fetch('/…')`. (A root-relative
/// URL would break the page under a sub-path.)
fn check_relative(dir: &Path) -> Result {
    let mut problems = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d)? {
            let path = e?.path();
            if path.is_dir() {
                if !path.ends_with("fixtures") {
                    stack.push(path);
                }
                continue;
            }
            let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
            if !matches!(ext, "html" | "js" | "mjs" | "css") {
                continue;
            }
            let text = std::fs::read_to_string(&path)?;
            for (n, line) in text.lines().enumerate() {
                if let Some(bad) = root_relative(line) {
                    problems.push(format!("{}:{}: {bad}", path.display(), n + 1));
                }
            }
        }
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(format!(
            "root-relative URLs would break the page under a sub-path:\n  {}",
            problems.join("\n  ")
        )
        .into())
    }
}

/// The first root-relative URL a line loads, if any.
fn root_relative(line: &str) -> Option<&str> {
    const OPENERS: [&str; 10] = [
        "src=\"/",
        "href=\"/",
        "src='/",
        "href='/",
        "from '/",
        "from \"/",
        "import('/",
        "import(\"/",
        "fetch('/",
        "fetch(\"/",
    ];
    OPENERS.iter().find_map(|o| {
        let i = line.find(o)?;
        // `//example.org` (protocol-relative) is not ours either.
        Some(&line[i..line.len().min(i + o.len() + 30)])
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn root_relative_urls_are_found() {
        assert_eq!(root_relative("import init from './pkg/x.js';"), None);
        assert_eq!(root_relative(r#"<link href="style.css">"#), None);
        assert_eq!(
            root_relative(r#"<script src="/main.js">"#),
            Some(r#"src="/main.js">"#)
        );
        assert!(root_relative("await fetch('/fixtures/index.json')").is_some());
        assert!(root_relative("import { x } from '/js/dom.js';").is_some());
    }

    #[test]
    fn every_module_is_preloaded_before_the_entry() {
        let html = std::fs::read_to_string(tools::repo_root().join("web/index.html")).unwrap();
        let modules = ["./js/a.js".to_owned(), "./pkg/b.js".to_owned()];
        let out = with_preloads(&html, &modules).unwrap();
        let a = out
            .find(r#"<link rel="modulepreload" href="./js/a.js">"#)
            .unwrap();
        let b = out
            .find(r#"<link rel="modulepreload" href="./pkg/b.js">"#)
            .unwrap();
        let entry = out.find(ENTRY).unwrap();
        assert!(a < b && b < entry, "{out}");
        assert!(with_preloads("<html></html>", &modules).is_err());
    }

    #[test]
    fn the_page_loads_nothing_from_the_server_root() {
        let web = tools::repo_root().join("web");
        let mut files = vec![
            web.join("index.html"),
            web.join("main.js"),
            web.join("style.css"),
        ];
        for e in std::fs::read_dir(web.join("js")).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                files.extend(std::fs::read_dir(p).unwrap().map(|e| e.unwrap().path()));
            } else {
                files.push(p);
            }
        }
        assert!(files.len() > 10, "{files:?}");
        for f in files {
            let text = std::fs::read_to_string(&f).unwrap();
            for (n, line) in text.lines().enumerate() {
                assert_eq!(root_relative(line), None, "{}:{}", f.display(), n + 1);
            }
        }
    }
}
