//! The page's scenario picker reads the scenario fixtures over HTTP: this copies
//! `fixtures/scenarios/*.json` and the map files they name into `web/fixtures/` (git-ignored)
//! and writes `web/fixtures/index.json`:
//!
//! ```json
//! { "default": "open_field",
//!   "scenarios": [ { "name": "open_field", "description": "…", "lesson": "…",
//!                    "url": "fixtures/scenarios/open_field.json",
//!                    "files": { "fixtures/maps/scenarios/open_field.json":
//!                               "fixtures/maps/scenarios/open_field.json" } } ] }
//! ```
//!
//! `files` maps each path as the scenario writes it (relative to the repository root, which
//! the core's `FileResolver` is given) to the URL it is served at. Paths outside the
//! repository (`../shared/data/…`, the real ROS maps) are served under `fixtures/external/`.
//! A scenario whose files are missing (a checkout without `../shared`) is left out, with a
//! note.

use std::path::{Path, PathBuf};

use serde_json::{Value, json};

use crate::Result;
use crate::tools;

/// The scenario the page opens with (first in the picker).
const DEFAULT_SCENARIO: &str = "open_field";

/// Where the page finds the fixtures (git-ignored).
pub fn out_dir() -> PathBuf {
    tools::repo_root().join("web").join("fixtures")
}

/// Copies the scenarios and their maps into `web/fixtures/` and writes its `index.json`.
pub fn stage() -> Result {
    let out = out_dir();
    let n = stage_into(&tools::repo_root(), &out)?;
    println!("xtask: {n} scenarios staged in {}", out.display());
    Ok(())
}

/// [`stage`] from the repository at `root` into `out` (emptied first). Returns how many
/// scenarios were staged.
pub fn stage_into(root: &Path, out: &Path) -> Result<usize> {
    if out.exists() {
        std::fs::remove_dir_all(out)?;
    }
    std::fs::create_dir_all(out)?;
    let dir = root.join("fixtures").join("scenarios");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map_err(|e| format!("cannot list {}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    let mut scenarios = Vec::new();
    for path in paths {
        let text = std::fs::read_to_string(&path)?;
        let scenario: Value =
            serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
        let field = |k: &str| scenario[k].as_str().unwrap_or_default().to_owned();
        let name = field("name");
        let files = match map_files(root, &scenario["map"]) {
            Ok(files) => files,
            Err(e) => {
                println!("xtask: scenario `{name}` left out of the page: {e}");
                continue;
            }
        };
        let mut served = serde_json::Map::new();
        for file in files {
            let url = url_for(&file);
            copy(&root.join(&file), &out.parent().unwrap_or(out).join(&url))?;
            served.insert(file, Value::String(url));
        }
        let rel = path.strip_prefix(root).unwrap_or(&path);
        let url = url_for(&rel.to_string_lossy().replace('\\', "/"));
        copy(&path, &out.parent().unwrap_or(out).join(&url))?;
        scenarios.push(json!({
            "name": name,
            "description": field("description"),
            "lesson": field("lesson"),
            "url": url,
            "files": served,
        }));
    }
    // The default first, the rest in file order.
    scenarios.sort_by_key(|s| s["name"] != DEFAULT_SCENARIO);
    let index = json!({ "default": DEFAULT_SCENARIO, "scenarios": scenarios });
    std::fs::write(
        out.join("index.json"),
        serde_json::to_string_pretty(&index)?,
    )?;
    Ok(scenarios.len())
}

/// The files a scenario's `map` needs, as the scenario writes their paths; an error if one
/// is missing.
fn map_files(root: &Path, map: &Value) -> Result<Vec<String>> {
    let s = |k: &str| map[k].as_str().map(str::to_owned);
    let files = match map["format"].as_str() {
        Some("json" | "movingai") => vec![s("path").ok_or("map without a path")?],
        Some("ros") => {
            let yaml = s("yaml").ok_or("ROS map without a yaml")?;
            let text = std::fs::read_to_string(root.join(&yaml))
                .map_err(|e| format!("cannot read `{yaml}`: {e}"))?;
            let image = yaml_image(&text).ok_or_else(|| format!("`{yaml}` names no image"))?;
            let image = sibling(&yaml, &image);
            vec![yaml, image]
        }
        other => return Err(format!("unknown map format {other:?}").into()),
    };
    for f in &files {
        if !root.join(f).is_file() {
            return Err(format!("`{f}` is missing").into());
        }
    }
    Ok(files)
}

/// The value of a map_server YAML's `image:` line.
fn yaml_image(text: &str) -> Option<String> {
    text.lines().find_map(|l| {
        let v = l.trim().strip_prefix("image:")?.trim();
        Some(v.trim_matches(|c| c == '"' || c == '\'').to_owned())
    })
}

/// `image` relative to the folder of `yaml` (as the core's resolver reads it), normalized.
fn sibling(yaml: &str, image: &str) -> String {
    let joined = match yaml.rfind('/') {
        Some(i) if !image.starts_with('/') => format!("{}/{image}", &yaml[..i]),
        _ => image.to_owned(),
    };
    let mut parts: Vec<&str> = Vec::new();
    for p in joined.split('/') {
        match p {
            "" | "." => {}
            ".." if parts.last().is_some_and(|l| *l != "..") => {
                parts.pop();
            }
            _ => parts.push(p),
        }
    }
    parts.join("/")
}

/// The URL (relative to `web/`) a repository-relative path is served at.
fn url_for(path: &str) -> String {
    let mut rest = path;
    let mut outside = false;
    while let Some(r) = rest.strip_prefix("../") {
        rest = r;
        outside = true;
    }
    let rest = rest.trim_start_matches("./");
    if outside {
        format!("fixtures/external/{rest}")
    } else if rest.starts_with("fixtures/") {
        rest.to_owned()
    } else {
        format!("fixtures/repo/{rest}")
    }
}

fn copy(from: &Path, to: &Path) -> Result {
    if let Some(dir) = to.parent() {
        std::fs::create_dir_all(dir)?;
    }
    std::fs::copy(from, to).map_err(|e| format!("cannot copy {}: {e}", from.display()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn urls_stay_under_fixtures() {
        let cases = [
            ("fixtures/maps/a.json", "fixtures/maps/a.json"),
            (
                "../shared/data/rosmaps/w/w.yaml",
                "fixtures/external/shared/data/rosmaps/w/w.yaml",
            ),
            ("maps/x.map", "fixtures/repo/maps/x.map"),
        ];
        for (path, url) in cases {
            assert_eq!(url_for(path), url, "{path}");
        }
    }

    #[test]
    fn ros_images_are_found_beside_their_yaml() {
        let yaml = "image: 'w.pgm'\nresolution: 0.1\n";
        assert_eq!(yaml_image(yaml).as_deref(), Some("w.pgm"));
        assert_eq!(sibling("../d/m.yaml", "m.pgm"), "../d/m.pgm");
        assert_eq!(sibling("a/b/m.yaml", "./../m.pgm"), "a/m.pgm");
    }

    #[test]
    fn every_scenario_fixture_is_staged_default_first() {
        let out = std::env::temp_dir().join(format!("rtnav-xtask-fixtures-{}", std::process::id()));
        let root = tools::repo_root();
        let n = stage_into(&root, &out.join("fixtures")).unwrap();
        let index: Value = serde_json::from_str(
            &std::fs::read_to_string(out.join("fixtures/index.json")).unwrap(),
        )
        .unwrap();
        let scenarios = index["scenarios"].as_array().unwrap();
        assert_eq!(scenarios.len(), n);
        assert_eq!(scenarios[0]["name"], DEFAULT_SCENARIO);
        for s in scenarios {
            assert!(out.join(s["url"].as_str().unwrap()).is_file(), "{s}");
            for url in s["files"].as_object().unwrap().values() {
                assert!(out.join(url.as_str().unwrap()).is_file(), "{url}");
            }
        }
        std::fs::remove_dir_all(&out).unwrap();
    }
}
