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
//! the core's `FileResolver` is given) to the URL it is served at. Files of the external data
//! (`../shared/data/…`: read from `$RTNAV_DATA`, else `../shared/data` beside the repository,
//! as `rtnav::data` does) are served under `fixtures/data/`. A scenario whose files are
//! missing (a clone without the data) is left out, with a line saying which and why.

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

/// The environment variable naming the external data folder (as `rtnav::data::DATA_ENV`).
pub const DATA_ENV: &str = "RTNAV_DATA";
/// How scenarios name the external data folder (as `rtnav::data::DATA_PREFIX`); it is also
/// where the folder is, relative to the repository, when [`DATA_ENV`] is not set.
const DATA_PREFIX: &str = "../shared/data/";

/// The external data folder: `$RTNAV_DATA`, else `../shared/data` beside the repository at
/// `root`; an error saying where it looked if that is not a folder.
pub fn data_dir(root: &Path) -> std::result::Result<PathBuf, String> {
    match std::env::var_os(DATA_ENV).map(PathBuf::from) {
        Some(dir) if dir.as_os_str().is_empty() => Err(format!("{DATA_ENV} is set but empty")),
        Some(dir) if dir.is_dir() => Ok(dir),
        Some(dir) => Err(format!("{DATA_ENV}={} is not a folder", dir.display())),
        None => {
            let dir = root.join(DATA_PREFIX.trim_end_matches('/'));
            if dir.is_dir() {
                Ok(dir)
            } else {
                Err(format!(
                    "{DATA_ENV} is unset and {} is not a folder",
                    dir.display()
                ))
            }
        }
    }
}

/// A path inside the external data folder, for a scenario path that names one.
fn data_relative(path: &str) -> Option<&str> {
    path.trim_start_matches("./")
        .strip_prefix(DATA_PREFIX)
        .filter(|rest| !rest.is_empty())
}

/// The repository's files and the external data's, as a scenario names them.
struct Sources<'a> {
    root: &'a Path,
    data: std::result::Result<PathBuf, String>,
}

impl Sources<'_> {
    /// Where `path` (as the scenario writes it) is on disk.
    fn locate(&self, path: &str) -> Result<PathBuf> {
        match data_relative(path) {
            None => Ok(self.root.join(path)),
            Some(rest) => match &self.data {
                Ok(dir) => Ok(dir.join(rest)),
                Err(why) => Err(format!("`{path}` is external data: {why}").into()),
            },
        }
    }
}

/// Copies the scenarios and their maps into `web/fixtures/` and writes its `index.json`.
pub fn stage() -> Result {
    let out = out_dir();
    let n = stage_into(&tools::repo_root(), &out)?;
    println!("xtask: {n} scenarios staged in {}", out.display());
    Ok(())
}

/// [`stage`] from the repository at `root` into `out` (emptied first), the files at the URLs
/// of the index relative to `out`'s parent (the page's folder). Returns how many scenarios
/// were staged.
pub fn stage_into(root: &Path, out: &Path) -> Result<usize> {
    let sources = Sources {
        root,
        data: data_dir(root),
    };
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
        let files = match map_files(&sources, &scenario["map"]) {
            Ok(files) => files,
            Err(e) => {
                println!("xtask: scenario `{name}` left out of the page: {e}");
                continue;
            }
        };
        let mut served = serde_json::Map::new();
        for file in files {
            let url = url_for(&file);
            copy(
                &sources.locate(&file)?,
                &out.parent().unwrap_or(out).join(&url),
            )?;
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
fn map_files(sources: &Sources<'_>, map: &Value) -> Result<Vec<String>> {
    let s = |k: &str| map[k].as_str().map(str::to_owned);
    let files = match map["format"].as_str() {
        Some("json" | "movingai") => vec![s("path").ok_or("map without a path")?],
        Some("ros") => {
            let yaml = s("yaml").ok_or("ROS map without a yaml")?;
            let text = std::fs::read_to_string(sources.locate(&yaml)?)
                .map_err(|e| format!("cannot read `{yaml}`: {e}"))?;
            let image = yaml_image(&text).ok_or_else(|| format!("`{yaml}` names no image"))?;
            let image = sibling(&yaml, &image);
            vec![yaml, image]
        }
        other => return Err(format!("unknown map format {other:?}").into()),
    };
    for f in &files {
        let file = sources.locate(f)?;
        if !file.is_file() {
            return Err(format!("`{f}` is missing ({} is not a file)", file.display()).into());
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
    if let Some(rest) = data_relative(path) {
        return format!("fixtures/data/{rest}");
    }
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
                "fixtures/data/rosmaps/w/w.yaml",
            ),
            ("../elsewhere/m.map", "fixtures/external/elsewhere/m.map"),
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
        // Every fixture is there, but those on external data when there is none.
        let mut expected = Vec::new();
        for e in std::fs::read_dir(root.join("fixtures/scenarios")).unwrap() {
            let text = std::fs::read_to_string(e.unwrap().path()).unwrap();
            let s: Value = serde_json::from_str(&text).unwrap();
            let map = &s["map"];
            let file = map["path"].as_str().or(map["yaml"].as_str()).unwrap();
            if data_relative(file).is_none() || data_dir(&root).is_ok() {
                expected.push(s["name"].as_str().unwrap().to_owned());
            }
        }
        let mut staged: Vec<String> = scenarios
            .iter()
            .map(|s| s["name"].as_str().unwrap().to_owned())
            .collect();
        expected.sort();
        staged.sort();
        assert_eq!(staged, expected);
        for s in scenarios {
            assert!(out.join(s["url"].as_str().unwrap()).is_file(), "{s}");
            for url in s["files"].as_object().unwrap().values() {
                assert!(out.join(url.as_str().unwrap()).is_file(), "{url}");
            }
        }
        std::fs::remove_dir_all(&out).unwrap();
    }
}
