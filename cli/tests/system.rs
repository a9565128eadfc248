//! `rtnav system`: the system's description as Graphviz dot and as JSON.

use std::process::Command;

const SCENARIO: &str = "../fixtures/scenarios/open_field.json";

fn rtnav(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn dot_draws_every_component_and_connection() {
    let dot = rtnav(&["system", SCENARIO, "--dot"]);
    assert!(dot.starts_with("digraph rtnav {") && dot.trim_end().ends_with('}'));
    for name in [
        "InventGUI",
        "MapBuilder",
        "MotorControl",
        "LocalPathPlanning",
        "DriveControl",
    ] {
        assert!(dot.contains(&format!("\"{name}\" [label=")), "{name}");
    }
    assert!(dot.contains(
        "\"DriveControl\":\"TargetVelocity\":e -> \"MotorControl\":\"TargetVelocity\":w [label=\"TimedVelocity\"]"
    ));
    // The default is dot.
    assert_eq!(rtnav(&["system", SCENARIO]), dot);
}

#[test]
fn json_after_a_drive_holds_types_samples_and_calls() {
    let text = rtnav(&["system", SCENARIO, "--json", "--until", "3"]);
    let g: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(g["time"].as_f64(), Some(3.0));
    let components = g["components"].as_array().unwrap();
    assert_eq!(components.len(), 9);
    let motor = components
        .iter()
        .find(|c| c["name"] == "MotorControl")
        .unwrap();
    assert_eq!(motor["state"], "Active");
    let port = |name: &str| {
        motor["ports"]
            .as_array()
            .unwrap()
            .iter()
            .find(|p| p["name"] == name)
            .unwrap()
            .clone()
    };
    let velocity = port("TargetVelocity");
    assert_eq!(
        (velocity["kind"].as_str(), velocity["interface"].as_str()),
        (Some("in"), Some("TimedVelocity"))
    );
    let text = velocity["last"]["text"].as_str().unwrap();
    assert!(text.starts_with("TimedVelocity {tm: 2.9"), "{text}");
    assert_eq!(port("BumpProvPort")["kind"], "provided");
    let connections = g["connections"].as_array().unwrap();
    let target = connections
        .iter()
        .find(|c| c["id"] == "DriveControl.TargetVelocity->MotorControl.TargetVelocity")
        .unwrap();
    assert!(target["carried"].as_u64().unwrap() > 100);
    assert_eq!(
        (target["kind"].as_str(), target["cuttable"].as_bool()),
        (Some("data"), Some(true))
    );
}
