//! `rtnav inspect`: one cell of a scenario as the page sees it after loading, as JSON.

use std::process::Command;

use rtnav::system::{BuildOptions, DirResolver, Scenario, Setup, setup};

const SCENARIO: &str = "../fixtures/scenarios/open_field.json";

fn rtnav(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn inspect_prints_the_cell_as_one_line_of_json() {
    let out = rtnav(&["inspect", SCENARIO, "--cell", "40,30"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 1, "{text}");
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(
        (json["x"].as_i64(), json["y"].as_i64()),
        (Some(40), Some(30))
    );
    assert_eq!(json["occupancy"], 0);
    assert!(json["obstacle_distance"].as_f64().unwrap() > 0.6);
    assert_eq!(json["impassable"], false);
    let field = &json["field"];
    assert_eq!(field["state"], "Reached");
    assert_eq!(field["unreached"], false);
    for key in ["potential", "repulsion", "attraction", "posture"] {
        assert!(field[key].as_f64().is_some(), "{key}: {field}");
    }

    // The same as the library gives for the scenario loaded as the page loads it.
    let scenario = Scenario::from_json(&std::fs::read_to_string(SCENARIO).unwrap()).unwrap();
    let options = BuildOptions { full_field: true };
    let system = setup::build(
        &scenario,
        &DirResolver::new(".."),
        &Setup::of(&scenario),
        options,
    )
    .unwrap();
    let cell = system.wiring().inspect_cell(40, 30).unwrap();
    let expected = serde_json::to_string(&cell).unwrap();
    assert_eq!(text.trim_end(), expected);
}

#[test]
fn a_scenario_that_cannot_be_set_up_is_named_once() {
    // The start lies outside the map: the set-up refuses it, and says which scenario once.
    let dir = std::env::temp_dir().join(format!("rtnav-inspect-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut value: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(SCENARIO).unwrap()).unwrap();
    value["start"] = serde_json::json!({"x": -50.0, "y": -50.0});
    let file = dir.join("outside.json");
    std::fs::write(&file, value.to_string()).unwrap();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = rtnav(&[
        "inspect",
        file.to_str().unwrap(),
        "--cell",
        "1,1",
        "--root",
        root.to_str().unwrap(),
    ]);
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.starts_with("rtnav: error: scenario `open_field`: "),
        "{err}"
    );
    assert_eq!(err.matches("scenario `open_field`").count(), 1, "{err}");
}

#[test]
fn inspect_refuses_a_cell_outside_the_map_and_a_missing_scenario() {
    let out = rtnav(&["inspect", SCENARIO, "--cell", "260,0"]);
    assert!(!out.status.success());
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("cell (260, 0) is outside the map (260 × 180 cells)"),
        "{err}"
    );

    let out = rtnav(&["inspect", SCENARIO, "--cell", "-3,5"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("cell (-3, 5) is outside the map"), "{err}");

    let out = rtnav(&["inspect", SCENARIO, "--cell", "4"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("expected X,Y"));

    let out = rtnav(&["inspect", "no_such_scenario.json", "--cell", "1,1"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read `no_such_scenario.json`"));
}
