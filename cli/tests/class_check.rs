//! `rtnav check SCENARIO --replay FOLDER --csv PATH`: a class's hand-ins checked at once.
//!
//! A folder of 32 replays of `ex_speed_limit` is made as students would make them in the
//! page (`Session`: the `.conf` loaded, Activate all, 100 ms frames until the checklist has
//! its verdict, the page's Download replay) — right answers, wrong ones on both sides of the
//! range, a parameter the exercise does not let change, a recording stopped early — and as
//! they should not be: traces edited by hand, another scenario's runs, another behaviour
//! version, another file version, a changed scenario, files that are not replays at all.
//! Every file is one row, sorted by name, with the verdict and the reason the test expects;
//! the CSV says the same. `--conf` takes a folder the same way; one file keeps the checklist;
//! and a sweep of MaxVelocity handed in as a class passes exactly the lesson's range.
//!
//! `RTNAV_CLASS_DIR=PATH` keeps the folders made there (`PATH/replays`, …), to run the release
//! build on them.

use std::path::{Path, PathBuf};
use std::process::Command;

use rtnav::data::RepoResolver;
use rtnav::system::{ComponentKind, Input, Scenario, Session, Verdict};

const SCENARIO: &str = "ex_speed_limit";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn session(name: &str) -> Session {
    let path = root().join(format!("fixtures/scenarios/{name}.json"));
    let scenario = Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut s = Session::new().unwrap();
    s.load_scenario(scenario, &RepoResolver::new(root()))
        .unwrap();
    s
}

fn decided(s: &Session) -> bool {
    matches!(
        s.exercise().map(|e| e.verdict),
        Some(Verdict::Passed | Verdict::Failed)
    )
}

/// A student's run with MaxVelocity `v` as the page records it; `also` changes something
/// more before the drive; `stop_at` ends the recording early \[s of simulated time\].
fn run(v: f64, also: Option<(ComponentKind, &str, &str)>, stop_at: Option<f64>) -> String {
    let mut s = session(SCENARIO);
    let conf = format!("# [DriveControl0]\nconf.default.MaxVelocity: {v}\n");
    s.apply(&Input::LoadConf { text: conf }).unwrap();
    if let Some((component, name, value)) = also {
        s.set_param_text(component, name, value).unwrap();
    }
    s.apply(&Input::ActivateAll).unwrap();
    while !decided(&s) && stop_at.is_none_or(|t| s.system().time() < t) {
        assert!(s.system().time() < 200.0, "no verdict");
        s.advance(100.0);
    }
    s.replay_json().unwrap()
}

/// `json` with `key`'s value replaced by `value` (JSON text).
fn with(json: &str, key: &str, value: &str) -> String {
    let mut v: serde_json::Value = serde_json::from_str(json).unwrap();
    v[key] = serde_json::from_str(value).unwrap();
    v.to_string()
}

/// The class: (file, its bytes, the verdict expected, a part of the reason expected).
fn class() -> Vec<(String, Vec<u8>, &'static str, &'static str)> {
    let mut out: Vec<(String, Vec<u8>, &'static str, &'static str)> = Vec::new();
    let mut add = |name: String, bytes: Vec<u8>, verdict, reason| {
        out.push((name, bytes, verdict, reason));
    };
    for v in [0.3, 0.33, 0.37, 0.4, 0.44, 0.48, 0.5, 0.53, 0.57, 0.6] {
        add(
            format!("right-{v:.2}.rtnav.json"),
            run(v, None, None).into_bytes(),
            "passed",
            "",
        );
    }
    for v in [0.2, 0.25, 0.29] {
        add(
            format!("slow-{v:.2}.rtnav.json"),
            run(v, None, None).into_bytes(),
            "failed",
            "failed: arrive within 46.5 s",
        );
    }
    for v in [0.61, 0.7, 1.0, 1.5] {
        add(
            format!("fast-{v:.2}.rtnav.json"),
            run(v, None, None).into_bytes(),
            "failed",
            "failed: overshoot 0.6 m/s by at most 0.5 %",
        );
    }
    let posture = (
        ComponentKind::LocalPathPlanning,
        "PostureConsiderationLevel",
        "50",
    );
    add(
        "other-parameter.rtnav.json".to_owned(),
        run(0.5, Some(posture), None).into_bytes(),
        "failed",
        "change only the parameters named (changed: LocalPathPlanning.PostureConsiderationLevel)",
    );
    add(
        "stopped-early.rtnav.json".to_owned(),
        run(0.5, None, Some(10.0)).into_bytes(),
        "unfinished",
        "the recording ends before the exercise ends",
    );
    let right = run(0.5, None, None);
    let tampered = [
        (
            "tampered-hash",
            with(&right, "trace_hash", &format!("\"{}\"", "ab".repeat(32))),
        ),
        ("tampered-samples", {
            let v: serde_json::Value = serde_json::from_str(&right).unwrap();
            let samples = v["samples"].as_u64().unwrap();
            with(&right, "samples", &(samples + 1).to_string())
        }),
        (
            "tampered-value",
            right.replace("MaxVelocity: 0.5\\n", "MaxVelocity: 0.45\\n"),
        ),
        ("tampered-inputs", {
            let mut v: serde_json::Value = serde_json::from_str(&right).unwrap();
            v["inputs"].as_array_mut().unwrap().remove(0);
            v.to_string()
        }),
    ];
    for (name, text) in tampered {
        assert_ne!(text, right, "{name} changed nothing");
        add(
            format!("{name}.rtnav.json"),
            text.into_bytes(),
            "refused",
            "does not reproduce its recorded trace",
        );
    }
    add(
        "another-behaviour.rtnav.json".to_owned(),
        with(
            &right,
            "behaviour",
            &(rtnav::BEHAVIOUR_VERSION + 1).to_string(),
        )
        .into_bytes(),
        "refused",
        "behaviour version",
    );
    add(
        "another-version.rtnav.json".to_owned(),
        with(&right, "version", "1").into_bytes(),
        "refused",
        "format version 1, written by another release of rtnav; this one reads version 2",
    );
    add(
        "changed-scenario.rtnav.json".to_owned(),
        with(&right, "scenario_hash", &format!("\"{}\"", "0".repeat(64))).into_bytes(),
        "refused",
        "has changed since the replay was recorded",
    );
    let door =
        std::fs::read(root().join("fixtures/replays/ex_door_dmin.solution.rtnav.json")).unwrap();
    add(
        "another-exercise.rtnav.json".to_owned(),
        door,
        "refused",
        "a replay of scenario `ex_door_dmin`, not of `ex_speed_limit`",
    );
    let open_field = {
        let mut s = session("open_field");
        s.apply(&Input::ActivateAll).unwrap();
        s.step_ticks(2_000).unwrap();
        s.replay_json().unwrap()
    };
    add(
        "another-scenario.rtnav.json".to_owned(),
        open_field.into_bytes(),
        "refused",
        "a replay of scenario `open_field`",
    );
    add(
        "garbage-text.rtnav.json".to_owned(),
        b"my replay, sorry, the page crashed".to_vec(),
        "refused",
        "not a JSON object",
    );
    add(
        "garbage-empty.rtnav.json".to_owned(),
        Vec::new(),
        "refused",
        "not a JSON object",
    );
    add(
        "garbage-bytes.rtnav.json".to_owned(),
        vec![0xff, 0xfe, 0x00, 0x7b],
        "refused",
        "not UTF-8 text",
    );
    add(
        "garbage-scenario.json".to_owned(),
        std::fs::read(root().join("fixtures/scenarios/ex_speed_limit.json")).unwrap(),
        "refused",
        "not an rtnav replay",
    );
    out.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

fn folder(name: &str) -> PathBuf {
    match std::env::var_os("RTNAV_CLASS_DIR") {
        Some(dir) => PathBuf::from(dir).join(name),
        None => std::env::temp_dir().join(format!("rtnav-class-{name}-{}", std::process::id())),
    }
}

fn rtnav(args: &[&std::ffi::OsStr]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .current_dir(root())
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn scenario_file() -> PathBuf {
    root().join(format!("fixtures/scenarios/{SCENARIO}.json"))
}

/// A CSV line's fields (the test's files have no quotes; a reason may, quoted).
fn fields(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                chars.next();
                out.last_mut().unwrap().push('"');
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            c => out.last_mut().unwrap().push(c),
        }
    }
    out
}

#[test]
fn a_class_of_replays_is_one_table_and_one_csv_with_a_row_per_file() {
    let dir = folder("replays");
    std::fs::create_dir_all(&dir).unwrap();
    let class = class();
    assert!(class.len() >= 30, "{} files", class.len());
    for (name, bytes, _, _) in &class {
        std::fs::write(dir.join(name), bytes).unwrap();
    }
    // Not a hand-in: another kind of file in the folder is left out.
    std::fs::write(dir.join("notes.txt"), "marks due Friday").unwrap();
    let csv = dir.with_extension("csv");
    let (code, table, err) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--replay".as_ref(),
        dir.as_os_str(),
        "--csv".as_ref(),
        csv.as_os_str(),
    ]);
    assert_eq!(code, 1, "some failed, so 1:\n{table}{err}");
    assert!(err.is_empty(), "{err}");
    println!("{table}");
    // The table: a header with each check and its unit, a line per file, in order.
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines[0], "scenario ex_speed_limit");
    for column in [
        "file",
        "verdict",
        "arrived [s]",
        "no_bump",
        "max_overshoot [percent]",
        "only_allowed",
        "ended",
        "reason",
    ] {
        assert!(lines[1].contains(column), "{column}: {}", lines[1]);
    }
    let rows = &lines[3..3 + class.len()];
    for ((name, _, verdict, reason), line) in class.iter().zip(rows) {
        let file = dir.join(name);
        assert!(
            line.starts_with(&file.display().to_string()),
            "{name}: {line}"
        );
        assert!(line.contains(&verdict.to_uppercase()), "{name}: {line}");
        assert!(line.contains(reason), "{name}: {line}");
    }
    let passed = class.iter().filter(|c| c.2 == "passed").count();
    assert_eq!(
        lines[3 + class.len()],
        format!("{passed} of {} passed", class.len())
    );
    // A right answer's values, with their units.
    let right = rows[class
        .iter()
        .position(|c| c.0 == "right-0.50.rtnav.json")
        .unwrap()];
    assert!(right.contains(" s ") && right.contains(" %"), "{right}");
    // The CSV: the same rows, a value column per measuring check.
    let text = std::fs::read_to_string(&csv).unwrap();
    let csv_lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        csv_lines[0],
        "file,verdict,arrived,arrived_s,no_bump,max_overshoot,max_overshoot_percent,\
         only_allowed,ended_s,reason"
    );
    assert_eq!(csv_lines.len(), class.len() + 1);
    for ((name, _, verdict, reason), line) in class.iter().zip(&csv_lines[1..]) {
        let f = fields(line);
        assert_eq!(f.len(), 10, "{line}");
        assert_eq!(f[0], dir.join(name).display().to_string());
        assert_eq!(f[1], *verdict, "{name}: {line}");
        assert!(f[9].contains(reason), "{name}: {line}");
        match *verdict {
            "passed" => {
                assert_eq!([&f[2], &f[4], &f[5], &f[7]], ["pass"; 4], "{line}");
                let arrived: f64 = f[3].parse().unwrap();
                assert!(arrived > 0.0 && arrived <= 46.5, "{line}");
                let overshoot: f64 = f[6].parse().unwrap();
                assert!(overshoot <= 0.5, "{line}");
            }
            "refused" => assert!(f[2..9].iter().all(String::is_empty), "{line}"),
            _ => assert!(f[2..8].iter().any(|s| s == "fail" || s == "open"), "{line}"),
        }
    }
    if std::env::var_os("RTNAV_CLASS_DIR").is_none() {
        std::fs::remove_dir_all(&dir).unwrap();
        std::fs::remove_file(&csv).unwrap();
    }
}

#[test]
fn a_class_of_confs_and_one_file_alone() {
    let dir = folder("confs");
    std::fs::create_dir_all(&dir).unwrap();
    let exercises = root().join("fixtures/exercises");
    for which in ["solution", "wrong"] {
        std::fs::copy(
            exercises.join(format!("{SCENARIO}.{which}.conf")),
            dir.join(format!("{which}.conf")),
        )
        .unwrap();
    }
    std::fs::write(
        dir.join("typo.conf"),
        "# [DriveControl0]\nconf.default.MaxVelocty: 0.5\n",
    )
    .unwrap();
    let (code, table, err) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--conf".as_ref(),
        dir.as_os_str(),
    ]);
    assert_eq!(code, 1, "{table}{err}");
    let row = |name: &str| {
        table
            .lines()
            .find(|l| l.starts_with(&dir.join(name).display().to_string()))
            .unwrap_or_else(|| panic!("no row {name}:\n{table}"))
            .to_owned()
    };
    assert!(row("solution.conf").contains("PASSED"), "{table}");
    assert!(row("wrong.conf").contains("FAILED"), "{table}");
    let typo = row("typo.conf");
    assert!(
        typo.contains("REFUSED") && typo.contains("MaxVelocty"),
        "{table}"
    );
    assert!(table.contains("1 of 3 passed"), "{table}");
    // Only passes: exit 0. One file: the checklist, as the page shows it.
    let solution = dir.join("solution.conf");
    let (code, text, _) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--conf".as_ref(),
        solution.as_os_str(),
    ]);
    assert_eq!(code, 0, "{text}");
    assert!(
        text.contains("verdict  PASSED") && text.contains("[x] arrive within 46.5 s"),
        "{text}"
    );
    // A usage error: exit 2.
    let (code, _, err) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--conf".as_ref(),
        Path::new("no/such/folder").as_os_str(),
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("no such file or folder"), "{err}");
    if std::env::var_os("RTNAV_CLASS_DIR").is_none() {
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// The exercise discriminates: MaxVelocity swept from 0.2 to 0.8 m/s in steps of 0.01,
/// handed in as a class of `.conf`s, passes for exactly the range its lesson states (0.3 to
/// 0.6 m/s) — slower arrives late, faster breaks the hall's speed limit.
#[test]
fn a_sweep_handed_in_as_a_class_passes_exactly_the_range_the_lesson_states() {
    let dir = folder("sweep");
    std::fs::create_dir_all(&dir).unwrap();
    let lesson = std::fs::read_to_string(scenario_file()).unwrap();
    assert!(
        lesson.contains("Any MaxVelocity from 0.3 to 0.6 m/s is right"),
        "the lesson states the range"
    );
    for cents in 20..=80 {
        std::fs::write(
            dir.join(format!("v{cents:03}.conf")),
            format!("# [DriveControl0]\nconf.default.MaxVelocity: 0.{cents:02}\n"),
        )
        .unwrap();
    }
    let csv = dir.with_extension("csv");
    let (code, table, err) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--conf".as_ref(),
        dir.as_os_str(),
        "--csv".as_ref(),
        csv.as_os_str(),
    ]);
    assert_eq!(code, 1, "{table}{err}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let passing: Vec<u32> = text
        .lines()
        .skip(1)
        .map(fields)
        .filter(|f| f[1] == "passed")
        .map(|f| {
            let name = Path::new(&f[0]).file_stem().unwrap().to_str().unwrap();
            name.trim_start_matches('v').parse().unwrap()
        })
        .collect();
    assert_eq!(passing, (30..=60).collect::<Vec<u32>>(), "{table}");
    if std::env::var_os("RTNAV_CLASS_DIR").is_none() {
        std::fs::remove_dir_all(&dir).unwrap();
        std::fs::remove_file(&csv).unwrap();
    }
}
