//! `rtnav replay` and `rtnav compare`: a replay recorded by a session reproduces
//! its trace hash from the command line (PNG and CSV written); a tampered hash exits 1, a
//! file of another version exits 2 with the reason, and so does a kept hand-in of a scenario
//! that has changed since (which `rtnav check` refuses, exit 1); PostureConsiderationLevel 0 vs 85 on
//! parking_wall prints different arrival headings.

use std::path::{Path, PathBuf};
use std::process::Command;

use rtnav::system::{ComponentKind, DirResolver, Input, Scenario, Session};

const ROOT: &str = "..";

fn rtnav(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .args(args)
        .output()
        .unwrap()
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtnav-cli-replay-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// A recorded run of open_field: activation, a stroke, a parameter change, 10 s.
fn recorded() -> (String, String) {
    let text = std::fs::read_to_string(Path::new(ROOT).join("fixtures/scenarios/open_field.json"))
        .unwrap();
    let mut s = Session::new().unwrap();
    s.load_scenario(Scenario::from_json(&text).unwrap(), &DirResolver::new(ROOT))
        .unwrap();
    s.apply(&Input::ActivateAll).unwrap();
    s.step_ticks(2_000).unwrap();
    s.apply(&Input::MapUpdate {
        cells: (150..158).map(|x| (x, 101, 1)).collect(),
    })
    .unwrap();
    s.step_ticks(2_000).unwrap();
    s.set_param_text(
        ComponentKind::LocalPathPlanning,
        "PostureConsiderationLevel",
        "85",
    )
    .unwrap();
    s.step_ticks(6_000).unwrap();
    (
        s.replay_json().unwrap(),
        s.system().record().telemetry().trace_hash(),
    )
}

#[test]
fn a_replay_file_reproduces_its_hash_and_a_bad_one_is_refused() {
    let (json, hash) = recorded();
    let file = temp("run.rtnav.json");
    std::fs::write(&file, &json).unwrap();
    let (png, csv) = (temp("run.png"), temp("run.csv"));
    let f = file.to_str().unwrap();
    let out = rtnav(&[
        "replay",
        f,
        "--png",
        png.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
        "--root",
        ROOT,
        "--size",
        "300x200",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains("reproduced      yes") && text.contains(&hash),
        "{text}"
    );
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    let rows = std::fs::read_to_string(&csv).unwrap();
    assert!(rows.lines().count() > 400, "{} rows", rows.lines().count());

    // Another hash recorded: replayed, but not reproduced (exit 1).
    std::fs::write(&file, json.replace(&hash, &"0".repeat(64))).unwrap();
    let out = rtnav(&["replay", f, "--root", ROOT]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains("reproduced      NO"));

    // Another version: refused with the reason (exit 2).
    std::fs::write(&file, json.replace("\"version\":2", "\"version\":3")).unwrap();
    let out = rtnav(&["replay", f, "--root", ROOT]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("version 3") && err.contains("reads version 2"),
        "{err}"
    );
}

/// A copy of the repository's `ex_fault_recovery` scenario and its map under a folder of its
/// own, the scenario's time limit changed: the scenario a kept hand-in names has changed.
fn changed_root() -> PathBuf {
    let root = temp("changed-root");
    let scenarios = root.join("fixtures/scenarios");
    let maps = root.join("fixtures/maps/scenarios");
    std::fs::create_dir_all(&scenarios).unwrap();
    std::fs::create_dir_all(&maps).unwrap();
    let text =
        std::fs::read_to_string(Path::new(ROOT).join("fixtures/scenarios/ex_fault_recovery.json"))
            .unwrap();
    let changed = text.replace("\"time_limit\": 150.0", "\"time_limit\": 151.0");
    assert_ne!(changed, text);
    std::fs::write(scenarios.join("ex_fault_recovery.json"), changed).unwrap();
    std::fs::copy(
        Path::new(ROOT).join("fixtures/maps/scenarios/open_field.json"),
        maps.join("open_field.json"),
    )
    .unwrap();
    root
}

#[test]
fn a_kept_hand_in_of_a_changed_scenario_is_refused_with_that_reason() {
    let hand_in = "../fixtures/replays/ex_fault_recovery.solution.rtnav.json";
    let root = changed_root();
    let root = root.to_str().unwrap();
    let reason = "scenario `ex_fault_recovery` has changed since the replay was recorded";
    let out = rtnav(&["replay", hand_in, "--root", root]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains(reason), "{err}");
    let scenario = format!("{root}/fixtures/scenarios/ex_fault_recovery.json");
    // `rtnav check` judges hand-ins: this one is REFUSED, with the reason (exit 1).
    let out = rtnav(&["check", &scenario, "--replay", hand_in, "--root", root]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(
        text.contains("verdict  REFUSED: ") && text.contains(reason),
        "{text}"
    );
    // The same hand-in on the repository's scenario replays, and passes.
    let out = rtnav(&["replay", hand_in, "--root", ROOT]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("reproduced      yes"));
    let out = rtnav(&[
        "check",
        "../fixtures/scenarios/ex_fault_recovery.json",
        "--replay",
        hand_in,
        "--root",
        ROOT,
    ]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("verdict  PASSED"));
}

#[test]
fn compare_prints_the_table_and_draws_both() {
    let png = temp("compare.png");
    let out = rtnav(&[
        "compare",
        "../fixtures/scenarios/parking_wall.json",
        "--a",
        "LocalPathPlanning.PostureConsiderationLevel=0",
        "--b",
        "LocalPathPlanning.PostureConsiderationLevel=85",
        "--png",
        png.to_str().unwrap(),
        "--size",
        "400x300",
    ]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let row = text
        .lines()
        .find(|l| l.starts_with("arrival heading error"))
        .unwrap();
    let degrees: Vec<f64> = row
        .split_whitespace()
        .filter_map(|w| w.parse().ok())
        .collect();
    assert_eq!(degrees.len(), 2, "{row}");
    assert!(degrees[0] > 70.0 && degrees[1] < 55.0, "{row}");
    for m in [
        "time to goal",
        "path length",
        "min clearance",
        "replans",
        "energy",
    ] {
        assert!(text.contains(m), "{m}: {text}");
    }
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
    let bad = rtnav(&[
        "compare",
        "../fixtures/scenarios/parking_wall.json",
        "--b",
        "Nope.x=1",
    ]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("Nope"));
}
