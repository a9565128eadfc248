//! Tidy checks of the source itself (matklad's "tidy" tests): the sizes and import structure
//! the architecture promises (`ARCHITECTURE.md`, "Architecture invariants").

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn the_file_that_holds_system_is_short_and_no_source_file_is_over_800_lines() {
    let system = std::fs::read_to_string(src().join("system/simulation/robot.rs")).unwrap();
    assert!(system.contains("pub struct System {"));
    let n = system.lines().count();
    assert!(
        n <= 400,
        "system/simulation/robot.rs: {n} lines (at most 400)"
    );
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let long: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let n = std::fs::read_to_string(f).unwrap().lines().count();
            (n > 800).then(|| format!("{} ({n} lines)", f.display()))
        })
        .collect();
    assert!(long.is_empty(), "over 800 lines: {long:?}");
}

/// The sibling modules a file of `dir` refers to (`super::name`, `use super::{a, b}`).
fn siblings(text: &str, names: &[String]) -> Vec<String> {
    let mut found = Vec::new();
    let code: String = text
        .lines()
        .take_while(|l| !l.starts_with("#[cfg(test)]"))
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n");
    for name in names {
        let direct = format!("super::{name}");
        let grouped = code.match_indices("use super::{").any(|(i, _)| {
            let rest = &code[i + "use super::{".len()..];
            let group = &rest[..rest.find('}').unwrap_or(rest.len())];
            group
                .split(',')
                .any(|item| item.trim().split("::").next() == Some(name.as_str()))
        });
        let plain = code.match_indices(&direct).any(|(i, _)| {
            code[i + direct.len()..]
                .chars()
                .next()
                .is_some_and(|c| c == ':' || c == ';' || c == ',' || c == '}')
        });
        if grouped || plain {
            found.push(name.clone());
        }
    }
    found
}

fn cycles_in(dir: &str) -> Vec<Vec<String>> {
    let dir = src().join(dir);
    let mut names = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        if path.extension().is_some_and(|e| e == "rs") && stem != "mod" {
            names.push(stem);
        }
    }
    names.sort();
    let graph: BTreeMap<String, Vec<String>> = names
        .iter()
        .map(|n| {
            let text = std::fs::read_to_string(dir.join(format!("{n}.rs"))).unwrap();
            let mut deps = siblings(&text, &names);
            deps.retain(|d| d != n);
            (n.clone(), deps)
        })
        .collect();
    // Every cycle found by a depth-first search from each file (reported once per start).
    let mut cycles = Vec::new();
    for start in &names {
        let mut stack = vec![(start.clone(), vec![start.clone()])];
        while let Some((at, path)) = stack.pop() {
            for next in &graph[&at] {
                if next == start {
                    cycles.push(path.clone());
                } else if !path.contains(next) && next > start {
                    let mut p = path.clone();
                    p.push(next.clone());
                    stack.push((next.clone(), p));
                }
            }
        }
    }
    cycles
}

#[test]
fn no_two_files_of_a_layer_of_system_or_of_render_import_each_other_in_a_circle() {
    let layers = SYSTEM_LAYERS.iter().map(|layer| format!("system/{layer}"));
    for dir in layers.chain(["render".to_owned()]) {
        let cycles = cycles_in(&dir);
        assert!(cycles.is_empty(), "{dir}/: import circles {cycles:?}");
    }
}

#[test]
fn errors_rs_keeps_only_the_crate_error_and_the_re_exports() {
    let text = std::fs::read_to_string(src().join("errors.rs")).unwrap();
    let enums = text.matches("pub enum ").count();
    assert_eq!(enums, 1, "errors.rs defines only `Error`");
    assert!(text.contains("pub enum Error {") && text.contains("pub type Result"));
}

/// What the wasm layer may not name: the system's parts behind the session, and the
/// renderer behind the screen (`ARCHITECTURE.md`: the wasm layer binds `Session` and
/// `Screen`, one call each, and holds no logic).
const PAST_THE_BOUNDARY: &[&str] = &[
    ".system()",
    "System",
    "Wiring",
    "Mission",
    "Record",
    "Renderer",
    "ComponentKind",
    "ComponentInfo",
    "GridMap",
    "MapSource",
    "serde_json::json!",
    "serde_json::Value",
    "to_value(",
    "from_value(",
];

/// The words of `PAST_THE_BOUNDARY` that `text` names outside comments and tests (a word
/// counts only whole: `SystemGraph` is not `System`).
fn past_the_boundary(text: &str) -> Vec<&'static str> {
    let code: String = text
        .lines()
        .take_while(|l| !l.starts_with("#[cfg(test)]"))
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n");
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    PAST_THE_BOUNDARY
        .iter()
        .copied()
        .filter(|word| {
            code.match_indices(word).any(|(i, _)| {
                let before = code[..i].chars().next_back();
                let after = code[i + word.len()..].chars().next();
                let whole =
                    |c: Option<char>, edge: char| !edge.is_alphanumeric() || !c.is_some_and(ident);
                whole(before, word.chars().next().unwrap_or(' '))
                    && whole(after, word.chars().next_back().unwrap_or(' '))
            })
        })
        .collect()
}

#[test]
fn the_wasm_layer_reaches_nothing_past_the_session_and_the_screen() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../wasm/src");
    let mut files = Vec::new();
    rust_files(&dir, &mut files);
    assert!(files.len() >= 5, "{files:?}");
    let found: Vec<String> = files
        .iter()
        .filter_map(|f| {
            let words = past_the_boundary(&std::fs::read_to_string(f).unwrap());
            (!words.is_empty()).then(|| format!("{}: {words:?}", f.display()))
        })
        .collect();
    assert!(
        found.is_empty(),
        "the wasm layer reaches past Session: {found:?}"
    );
    // The check can fail: each kind of reach is found.
    let reach = "fn f(d: &Demo) { d.session.system().wiring(); }\n\
                 fn g(m: &Mission) {}\nfn h() { let v = serde_json::json!({}); }";
    assert_eq!(
        past_the_boundary(reach),
        [".system()", "Mission", "serde_json::json!"]
    );
    assert_eq!(
        past_the_boundary("fn f() -> SystemGraph {}\n// System"),
        Vec::<&str>::new()
    );
}

/// The layers of `system/`, bottom first: a module may use its own layer and the layers
/// before it, never one after it (`system/mod.rs`, "Layers").
const SYSTEM_LAYERS: [&str; 4] = ["vocabulary", "simulation", "runs", "sessions"];

#[test]
fn system_holds_only_mod_rs_at_its_top_and_a_folder_for_each_layer() {
    let mut files = Vec::new();
    let mut folders = Vec::new();
    for entry in std::fs::read_dir(src().join("system")).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            folders.push(name);
        } else {
            files.push(name);
        }
    }
    folders.sort();
    assert_eq!(
        files,
        ["mod.rs"],
        "system/ holds only mod.rs; the rest in its layers"
    );
    let mut layers = SYSTEM_LAYERS.to_vec();
    layers.sort();
    assert_eq!(
        folders, layers,
        "every folder of system/ is a layer of SYSTEM_LAYERS"
    );
    for layer in SYSTEM_LAYERS {
        let mod_rs = src().join("system").join(layer).join("mod.rs");
        let text = std::fs::read_to_string(&mod_rs).unwrap();
        assert!(
            text.starts_with("//!"),
            "{layer}/mod.rs opens with what the layer is"
        );
    }
}

/// What `code` names by the paths that can reach another layer, each with its path's
/// start: `crate::system::NAME` (a group `crate::system::{a::X, b}` names each item's first
/// part) and `super::NAME`, however many `super::` before it. Comments are left out; tests
/// are not.
fn system_paths(code: &str) -> Vec<(&'static str, String)> {
    let code: String = code
        .lines()
        .map(|l| l.find("//").map_or(l, |i| &l[..i]))
        .collect::<Vec<_>>()
        .join("\n");
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect()
    };
    let mut names = Vec::new();
    for (i, _) in code.match_indices("crate::system::") {
        let rest = code[i + "crate::system::".len()..].trim_start();
        if let Some(group) = rest.strip_prefix('{') {
            // The group's items at its own depth, each item's first part.
            let (mut depth, mut start) = (0, 0);
            for (j, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        names.push(("crate::system", ident(group[start..j].trim_start())));
                        break;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        names.push(("crate::system", ident(group[start..j].trim_start())));
                        start = j + 1;
                    }
                    _ => {}
                }
            }
        } else {
            names.push(("crate::system", ident(rest)));
        }
    }
    for (i, _) in code.match_indices("super::") {
        let before = code[..i].chars().next_back();
        if before.is_some_and(|c| c == ':' || c.is_alphanumeric() || c == '_') {
            continue; // the second `super` of `super::super::`: counted from the first
        }
        let mut rest = &code[i..];
        while let Some(r) = rest.strip_prefix("super::") {
            rest = r;
        }
        names.push(("super", ident(rest)));
    }
    names.retain(|(_, n)| !n.is_empty());
    names
}

#[test]
fn no_module_of_system_imports_a_layer_above_its_own() {
    let mut problems = Vec::new();
    for (rank, layer) in SYSTEM_LAYERS.iter().enumerate() {
        let mut files = Vec::new();
        rust_files(&src().join("system").join(layer), &mut files);
        for file in files {
            let code = std::fs::read_to_string(&file).unwrap();
            let name = file.strip_prefix(src()).unwrap().display().to_string();
            for (start, used) in system_paths(&code) {
                match SYSTEM_LAYERS.iter().position(|l| *l == used) {
                    Some(above) if above > rank => {
                        problems.push(format!("{name} ({layer}) uses {start}::{used}"));
                    }
                    // A public re-export (`crate::system::Session`) would hide the layer.
                    None if start == "crate::system" => {
                        problems.push(format!("{name} names {start}::{used}, not by its layer"));
                    }
                    _ => {}
                }
            }
        }
    }
    assert!(
        problems.is_empty(),
        "imports against the layers: {problems:#?}"
    );
    // The check can fail: each way of naming another layer is found.
    let reach = "use crate::system::sessions::session::Session;\n\
                 use crate::system::{runs::setup, vocabulary::kind::ComponentKind};\n\
                 fn f() -> super::super::simulation::robot::System {}\n\
                 // crate::system::commented\n\
                 use super::wiring::Wiring;";
    let named: Vec<String> = system_paths(reach)
        .into_iter()
        .map(|(start, name)| format!("{start}::{name}"))
        .collect();
    assert_eq!(
        named,
        [
            "crate::system::sessions",
            "crate::system::runs",
            "crate::system::vocabulary",
            "super::simulation",
            "super::wiring"
        ]
    );
}

/// The dependencies only the fuzzer needs (`stress/`): its PNG maps and share tokens.
const FUZZER_ONLY: [&str; 4] = ["png", "image", "base64", "miniz_oxide"];

/// The names of the dependencies a `Cargo.toml` lists (every `*dependencies` table).
fn dependency_names(manifest: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut in_deps = false;
    for line in manifest.lines().map(str::trim) {
        if line.starts_with('[') {
            in_deps = line.trim_matches(['[', ']']).ends_with("dependencies");
        } else if in_deps && !line.starts_with('#') {
            let key = line.split(['=', '.']).next().unwrap_or("").trim();
            if !key.is_empty() {
                names.push(key.trim_matches('"').to_owned());
            }
        }
    }
    names
}

#[test]
fn the_runner_has_no_counting_allocator_and_no_dependency_only_the_fuzzer_needs() {
    let cli = Path::new(env!("CARGO_MANIFEST_DIR")).join("../cli");
    let mut files = Vec::new();
    rust_files(&cli.join("src"), &mut files);
    assert!(files.len() >= 5, "{files:?}");
    let allocating: Vec<String> = files
        .iter()
        .filter(|f| {
            std::fs::read_to_string(f)
                .unwrap()
                .contains("global_allocator")
        })
        .map(|f| f.display().to_string())
        .collect();
    assert!(
        allocating.is_empty(),
        "rtnav-cli installs an allocator (the counting one is rtnav-stress's): {allocating:?}"
    );
    let names = dependency_names(&std::fs::read_to_string(cli.join("Cargo.toml")).unwrap());
    assert!(names.iter().any(|n| n == "rtnav"), "{names:?}");
    let fuzzer_only: Vec<&String> = names
        .iter()
        .filter(|n| FUZZER_ONLY.contains(&n.as_str()))
        .collect();
    assert!(
        fuzzer_only.is_empty(),
        "rtnav-cli depends on what only the fuzzer needs: {fuzzer_only:?}"
    );
    // The check can fail: each form of a dependency is read.
    let manifest = "[package]\nname = \"x\"\n[dependencies]\npng.workspace = true\n\
                    # image = \"1\"\nbase64 = \"0.23\"\n[dev-dependencies]\n\
                    miniz_oxide = { workspace = true }\n[lints]\nworkspace = true\n";
    assert_eq!(dependency_names(manifest), ["png", "base64", "miniz_oxide"]);
}
