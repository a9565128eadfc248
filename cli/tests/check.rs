//! `rtnav check SCENARIO --conf FILE`: every exercise's reference solution
//! (`fixtures/exercises/NAME.solution.conf`) exits 0, a wrong one (`NAME.wrong.conf`)
//! exits 1 and says FAILED; a scenario without an exercise is an error (exit 2). Seed 003's
//! exercise is done with Reset and Activate, not with a configuration: handed in without
//! them it fails (its solution is checked in `core/tests/exercises.rs`), and handed in as a
//! replay of the run with them (`--replay`) it passes; a replay of another scenario is
//! REFUSED. A class of hand-ins at once: `cli/tests/class_check.rs`.

use std::path::PathBuf;
use std::process::Command;

use rtnav::data::RepoResolver;
use rtnav::rtc::LifecycleState;
use rtnav::system::{ComponentKind, Input, Scenario, Session, Verdict};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn check(scenario: &str, conf: Option<&str>) -> (i32, String) {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_rtnav"));
    cmd.current_dir(root())
        .arg("check")
        .arg(format!("fixtures/scenarios/{scenario}.json"));
    if let Some(c) = conf {
        cmd.arg("--conf").arg(format!("fixtures/exercises/{c}"));
    }
    let out = cmd.output().unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.code().unwrap_or(-1), text)
}

const BY_CONF: [&str; 8] = [
    "ex_parking_posture",
    "ex_route_remake",
    "ex_door_dmin",
    "ex_corner_deviation",
    "ex_backward_dock",
    "ex_pd_gains",
    "ex_model_offset",
    "ex_speed_limit",
];

#[test]
fn reference_solutions_pass_and_wrong_ones_fail() {
    for name in BY_CONF {
        let (code, text) = check(name, Some(&format!("{name}.solution.conf")));
        assert_eq!(code, 0, "{name} solution:\n{text}");
        assert!(text.contains("verdict  PASSED"), "{text}");
        let (code, text) = check(name, Some(&format!("{name}.wrong.conf")));
        assert_eq!(code, 1, "{name} wrong:\n{text}");
        assert!(
            text.contains("verdict  FAILED") && text.contains("[!]"),
            "{text}"
        );
    }
}

#[test]
fn the_fault_exercise_without_its_actions_fails() {
    let (code, text) = check("ex_fault_recovery", None);
    assert_eq!(code, 1, "{text}");
}

#[test]
fn json_output_and_errors() {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_rtnav"));
    let out = cmd
        .current_dir(root())
        .args([
            "check",
            "fixtures/scenarios/ex_door_dmin.json",
            "--conf",
            "fixtures/exercises/ex_door_dmin.solution.conf",
            "--json",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["verdict"], "passed");
    assert_eq!(v["checks"][0]["check"]["check"], "arrived");
    let (code, text) = check("open_field", None);
    assert_eq!(code, 2, "{text}");
    assert!(text.contains("no exercise"), "{text}");
}

/// The student's run of seed 003's exercise in the page, downloaded as a replay: Activate
/// all, the fault at 8 s, then (when `recover`) Reset and Activate on DriveControl.
fn fault_replay(recover: bool) -> PathBuf {
    let json =
        std::fs::read_to_string(root().join("fixtures/scenarios/ex_fault_recovery.json")).unwrap();
    let mut s = Session::new().unwrap();
    s.load_scenario(
        Scenario::from_json(&json).unwrap(),
        &RepoResolver::new(root()),
    )
    .unwrap();
    s.apply(&Input::ActivateAll).unwrap();
    let drive = ComponentKind::DriveControl;
    while s.system().component_state(drive) != LifecycleState::Error {
        s.step_ticks(100).unwrap();
        assert!(s.system().time() < 60.0, "no fault");
    }
    if recover {
        s.apply(&Input::Reset { component: drive }).unwrap();
        s.apply(&Input::Activate { component: drive }).unwrap();
    }
    while matches!(
        s.exercise().unwrap().verdict,
        Verdict::Waiting | Verdict::Running
    ) && s.system().time() < 160.0
    {
        s.step_ticks(1_000).unwrap();
    }
    let path = std::env::temp_dir().join(format!(
        "rtnav-check-{}-{recover}.rtnav.json",
        std::process::id()
    ));
    std::fs::write(&path, s.replay_json().unwrap()).unwrap();
    path
}

fn check_replay(replay: &PathBuf) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .current_dir(root())
        .args([
            "check",
            "fixtures/scenarios/ex_fault_recovery.json",
            "--replay",
        ])
        .arg(replay)
        .output()
        .unwrap();
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    (out.status.code().unwrap_or(-1), text)
}

#[test]
fn the_fault_exercise_handed_in_as_a_replay_is_checked_as_recorded() {
    let done = fault_replay(true);
    let (code, text) = check_replay(&done);
    assert_eq!(code, 0, "recovered:\n{text}");
    assert!(text.contains("verdict  PASSED"), "{text}");
    let not_done = fault_replay(false);
    let (code, text) = check_replay(&not_done);
    assert_eq!(code, 1, "not recovered:\n{text}");
    assert!(text.contains("verdict  FAILED"), "{text}");
    // A replay of another scenario is refused, with the reason (exit 1: not a pass).
    let out = Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .current_dir(root())
        .args(["check", "fixtures/scenarios/ex_pd_gains.json", "--replay"])
        .arg(&done)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stdout).contains(
        "verdict  REFUSED: a replay of scenario `ex_fault_recovery`, not of `ex_pd_gains`"
    ));
    for f in [done, not_done] {
        std::fs::remove_file(f).unwrap();
    }
}
