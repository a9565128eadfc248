//! The build that the page's service worker (`web/sw.js`) keeps for offline use, written into
//! the dist folder's copy of it by `cargo xtask dist`.
//!
//! `web/sw.js` has one line `const BUILD = null;`: as it is (`cargo xtask serve`, `demo`) the
//! worker keeps nothing and serves nothing. In a dist folder that line names every file of the
//! folder (but the worker itself and the precompressed copies) with its SHA-256, and the
//! build's version, a digest of that list:
//!
//! ```text
//! const BUILD = {"version":"3f9c…","files":{"index.html":"a41b…","js/dom.js":"77e0…",…}};
//! ```
//!
//! A build that changes any file has a new version, so a new `sw.js`, which the browser
//! installs beside the old one; the worker fetches the listed files and keeps them only if
//! each has the listed digest (never a mix of two builds), then replaces the old build's cache
//! whole.

use std::path::Path;

use sha2::{Digest, Sha256};

use crate::Result;
use crate::precompress;

/// The worker's file, at the root of the page's folder (its scope is that folder).
pub const FILE: &str = "sw.js";

/// The line of [`FILE`] that names the build (`null` in `web/`).
const BUILD_LINE: &str = "const BUILD = ";

/// What [`seal`] wrote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sealed {
    /// The build's version: the first 16 hex digits of the SHA-256 of its file list.
    pub version: String,
    /// How many files the worker keeps.
    pub files: usize,
    /// Their bytes.
    pub bytes: u64,
}

fn hex(digest: &[u8]) -> String {
    digest.iter().map(|b| format!("{b:02x}")).collect()
}

/// Writes the build of the folder `dir` into its [`FILE`]: every file under `dir` but the
/// worker, hidden files and precompressed copies, with its SHA-256, and the version.
pub fn seal(dir: &Path) -> Result<Sealed> {
    let worker = dir.join(FILE);
    let text = std::fs::read_to_string(&worker)
        .map_err(|e| format!("{}: {e} (the page's service worker)", worker.display()))?;
    let mut files = serde_json::Map::new();
    let mut list = String::new();
    let mut bytes = 0;
    for rel in precompress::files_under(dir)? {
        let path = dir.join(&rel);
        let hidden = rel
            .components()
            .any(|c| c.as_os_str().to_string_lossy().starts_with('.'));
        if rel == Path::new(FILE) || hidden || precompress::is_copy(&path) {
            continue;
        }
        let url = rel
            .components()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .collect::<Vec<_>>()
            .join("/");
        let content = std::fs::read(&path)?;
        bytes += content.len() as u64;
        let digest = hex(&Sha256::digest(&content));
        list.push_str(&format!("{url}\0{digest}\n"));
        files.insert(url, digest.into());
    }
    let version = hex(&Sha256::digest(list.as_bytes()))[..16].to_owned();
    let sealed = Sealed {
        version: version.clone(),
        files: files.len(),
        bytes,
    };
    let build = serde_json::json!({ "version": version, "files": files });
    std::fs::write(&worker, with_build(&text, &build.to_string())?)?;
    Ok(sealed)
}

/// `text` (the worker) with its build line saying `build` (JSON, one line).
fn with_build(text: &str, build: &str) -> Result<String> {
    let mut found = 0;
    let lines: Vec<String> = text
        .lines()
        .map(|line| {
            if line.starts_with(BUILD_LINE) && line.trim_end().ends_with(';') {
                found += 1;
                format!("{BUILD_LINE}{build};")
            } else {
                line.to_owned()
            }
        })
        .collect();
    if found != 1 {
        return Err(format!(
            "{FILE} must have exactly one line `{BUILD_LINE}…;` for the build (found {found})"
        )
        .into());
    }
    Ok(lines.join("\n") + "\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_page_worker_has_one_build_line_and_none_in_web() {
        let text =
            std::fs::read_to_string(crate::tools::repo_root().join("web").join(FILE)).unwrap();
        let lines: Vec<&str> = text.lines().filter(|l| l.starts_with(BUILD_LINE)).collect();
        assert_eq!(lines, ["const BUILD = null;"]);
        let sealed = with_build(&text, r#"{"version":"x","files":{}}"#).unwrap();
        assert!(sealed.contains("\nconst BUILD = {\"version\":\"x\",\"files\":{}};\n"));
        // Sealed again: still one build line, the new one.
        let again = with_build(&sealed, r#"{"version":"y","files":{}}"#).unwrap();
        assert_eq!(again.matches(BUILD_LINE).count(), 1);
        assert!(again.contains(r#"{"version":"y","files":{}};"#));
        assert!(with_build("let a = 1;\n", "{}").is_err());
    }

    #[test]
    fn the_version_follows_the_files() {
        let dir = std::env::temp_dir().join(format!("rtnav-seal-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("js")).unwrap();
        std::fs::write(dir.join(FILE), "// worker\nconst BUILD = null;\n").unwrap();
        std::fs::write(dir.join("index.html"), "<!doctype html>").unwrap();
        std::fs::write(dir.join("js/a.js"), "export const a = 1;\n".repeat(100)).unwrap();
        std::fs::write(dir.join(".hidden"), "no").unwrap();
        precompress::write_beside(&dir).unwrap();
        let first = seal(&dir).unwrap();
        assert_eq!(first.files, 2, "{first:?}");
        assert_eq!(first.version.len(), 16);
        let text = std::fs::read_to_string(dir.join(FILE)).unwrap();
        let line = text.lines().find(|l| l.starts_with(BUILD_LINE)).unwrap();
        let build: serde_json::Value =
            serde_json::from_str(line[BUILD_LINE.len()..].trim_end_matches(';')).unwrap();
        assert_eq!(build["version"], first.version.as_str());
        let keys: Vec<&String> = build["files"].as_object().unwrap().keys().collect();
        assert_eq!(keys, ["index.html", "js/a.js"]);
        assert_eq!(
            build["files"]["index.html"],
            hex(&Sha256::digest(b"<!doctype html>")).as_str()
        );
        // The same files: the same version. One byte changed: another.
        assert_eq!(seal(&dir).unwrap(), first);
        std::fs::write(dir.join("index.html"), "<!doctype html>\n").unwrap();
        assert_ne!(seal(&dir).unwrap().version, first.version);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
