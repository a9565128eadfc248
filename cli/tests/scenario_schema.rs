//! The scenario file's JSON Schema (`docs/scenario.schema.json`), made from the core's types
//! (`rtnav_cli::scenario_file`): the committed file is what the types give, every scenario of
//! `fixtures/` is valid by it, and `rtnav scenario check` says where a wrong file is wrong —
//! by the schema, and by the core (a map that does not load, a goal inside an obstacle).
//!
//! `RTNAV_WRITE_SCHEMA=1 cargo test -p rtnav-cli --test scenario_schema` writes the file;
//! without it the test fails when the file is not what the types give.

use std::path::{Path, PathBuf};
use std::process::Command;

use rtnav_cli::scenario_file::{SCHEMA_PATH, problems, schema_text};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

#[test]
fn the_committed_schema_is_what_the_types_give() {
    let path = root().join(SCHEMA_PATH);
    let made = schema_text();
    if std::env::var_os("RTNAV_WRITE_SCHEMA").is_some_and(|v| v == "1") {
        std::fs::write(&path, &made).unwrap();
    }
    let kept = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        kept == made,
        "{SCHEMA_PATH} is not what the scenario's types give (a type changed); write it again \
         with\n    RTNAV_WRITE_SCHEMA=1 cargo test -p rtnav-cli --test scenario_schema"
    );
    // It is a schema a validator accepts, and it describes the exercise's checks.
    let schema: serde_json::Value = serde_json::from_str(&kept).unwrap();
    assert!(jsonschema::validator_for(&schema).is_ok());
    for key in ["max_overshoot", "only_allowed", "map_update", "heading_deg"] {
        assert!(kept.contains(key), "{key}");
    }
}

fn scenario_files(dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_scenario_of_the_fixtures_is_valid_by_the_schema() {
    let files = scenario_files(&root().join("fixtures/scenarios"));
    assert!(files.len() >= 10, "{files:?}");
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let found = problems(&text);
        assert!(
            found.is_empty(),
            "{}:\n{}",
            file.display(),
            found
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        );
    }
    // The fuzzer's kept scenarios that the core reads are valid by the schema too, and
    // those it refuses for a key or a type are not.
    let schema: serde_json::Value = serde_json::from_str(&schema_text()).unwrap();
    let validator = jsonschema::validator_for(&schema).unwrap();
    for file in scenario_files(&root().join("fixtures/fuzz-regressions/scenario"))
        .iter()
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
    {
        let text = std::fs::read_to_string(file).unwrap();
        if rtnav::system::Scenario::from_json(&text).is_ok() {
            let value: serde_json::Value = serde_json::from_str(&text).unwrap();
            assert!(validator.is_valid(&value), "{}", file.display());
        }
    }
}

const OK: &str = r#"{
  "name": "t",
  "description": "",
  "lesson": "",
  "map": { "format": "json", "path": "fixtures/maps/scenarios/speed_hall.json" },
  "start": { "x": 1.5, "y": 2.0 },
  "goal": { "x": 14.5, "y": 2.0, "heading_deg": 0 },
  "events": [ { "at": 3, "type": "map_update", "boxes": [ { "x": [5, 5.5], "y": [3, 3.5] } ] } ],
  "time_limit": 90,
  "expect": { "outcome": "arrived" },
  "exercise": {
    "task": "Cross the hall.",
    "may_change": ["DriveControl.MaxVelocity"],
    "checks": [ { "check": "arrived", "within_s": 45 } ]
  }
}"#;

#[test]
fn problems_are_said_with_their_place_in_plain_words() {
    assert_eq!(problems(OK), Vec::new());
    let one = |text: &str| {
        let found = problems(text);
        assert_eq!(found.len(), 1, "{found:?}");
        found[0].to_string()
    };
    // A misspelt key, at the key.
    assert_eq!(
        one(&OK.replace("\"lesson\"", "\"lessons\"")),
        "line 4, column 14: lessons: unknown key `lessons`: did you mean `lesson`?"
    );
    // A number written as text, in an event's box.
    assert_eq!(
        one(&OK.replace("[5, 5.5]", "[5, \"5.5\"]")),
        "line 8, column 70: events[0].boxes[0].x[1]: \"5.5\" is text, expected a number"
    );
    // A key misspelt inside a check: the check's own form, not "none of the forms".
    assert_eq!(
        one(&OK.replace("\"within_s\": 45", "\"within\": 45")),
        "line 14, column 49: exercise.checks[0].within: unknown key `within`: did you mean \
         `within_s`?"
    );
    // A key left out.
    assert_eq!(
        one(&OK.replace(", \"within_s\": 45", "")),
        "line 14, column 17: exercise.checks[0]: the key \"within_s\" is missing"
    );
    // An unknown check.
    let found = problems(&OK.replace("\"arrived\", \"within_s\"", "\"arive\", \"within_s\""));
    assert!(!found.is_empty());
    assert!(
        found
            .iter()
            .all(|p| p.path.starts_with("exercise.checks[0]")),
        "{found:?}"
    );
    // A missing key, at the object that lacks it.
    assert_eq!(
        one(&OK.replace("\"time_limit\": 90,", "")),
        "line 1, column 1: (the top level): the key \"time_limit\" is missing"
    );
    // Not JSON: where it breaks.
    let broken = problems(&OK.replace("\"lesson\": \"\",", "\"lesson\": \"\""));
    assert_eq!(broken.len(), 1);
    assert_eq!((broken[0].line, broken[0].path.as_str()), (5, "(the file)"));
    assert!(
        broken[0].message.starts_with("not valid JSON: "),
        "{broken:?}"
    );
}

fn scenario_check(file: &Path) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .current_dir(root())
        .args(["scenario", "check"])
        .arg(file)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ),
    )
}

#[test]
fn scenario_check_says_what_the_schema_and_the_core_find() {
    let dir = std::env::temp_dir().join(format!("rtnav-scenario-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // Every scenario of the fixtures is right.
    for file in scenario_files(&root().join("fixtures/scenarios")) {
        if std::fs::read_to_string(&file)
            .unwrap()
            .contains("../shared/data")
            && rtnav::data::data_dir(&root()).is_err()
        {
            continue;
        }
        let (code, text) = scenario_check(&file);
        assert_eq!(code, 0, "{}:\n{text}", file.display());
        assert!(text.ends_with("OK\n"), "{text}");
    }
    let cases = [
        (
            "typo",
            OK.replace("\"within_s\": 45", "\"within_s\": \"45\""),
            "line 14, column 51: exercise.checks[0].within_s: \"45\" is text, expected a number",
        ),
        (
            "no_map",
            OK.replace("speed_hall.json", "speed_hal.json"),
            "the map does not load",
        ),
        (
            "goal_in_pillar",
            OK.replace("\"x\": 14.5, \"y\": 2.0", "\"x\": 8.0, \"y\": 1.75"),
            "the goal (8, 1.75) is inside an obstacle (cell 32, 7)",
        ),
        (
            "goal_off_the_map",
            OK.replace("\"x\": 14.5, \"y\": 2.0", "\"x\": 20.0, \"y\": 2.0"),
            "the goal (20, 2) is off the map",
        ),
        (
            "late_event",
            OK.replace("\"at\": 3", "\"at\": 300"),
            "events[0].at = 300",
        ),
        (
            "unknown_parameter",
            OK.replace("DriveControl.MaxVelocity", "DriveControl.MaxSpeed"),
            "may_change `DriveControl.MaxSpeed`: DriveControl has no parameter `MaxSpeed`",
        ),
    ];
    for (name, text, said) in cases {
        let file = dir.join(format!("{name}.json"));
        std::fs::write(&file, text).unwrap();
        let (code, out) = scenario_check(&file);
        assert_eq!(code, 1, "{name}:\n{out}");
        assert!(out.contains(said), "{name}:\n{out}");
        assert!(out.contains("WRONG"), "{name}:\n{out}");
    }
    let (code, out) = scenario_check(&dir.join("missing.json"));
    assert_eq!(code, 2, "{out}");
    std::fs::remove_dir_all(&dir).unwrap();
    // The schema printed is the committed one.
    let out = Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .args(["scenario", "schema"])
        .output()
        .unwrap();
    assert_eq!(String::from_utf8_lossy(&out.stdout), schema_text());
}
