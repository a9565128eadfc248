//! `rtnav check SCENARIO --script FOLDER --component MotorControl`: a class's scripts (spec §8)
//! judged at once, into the table `--conf` and `--replay` make.
//!
//! A folder of 36 MotorControl scripts for `ex_pd_gains` is made from the reference script
//! (`fixtures/scripts/motor_control_pd.rhai`) as students would write them: right PD laws
//! with their gains in the script, wrong ones (a D gain of zero or too soft, a P gain that
//! overshoots, a sign error, the scenario's bad gains read as they stand, no torque, the
//! wheels swapped), scripts that fail while they run (an endless loop, an error at the 100th
//! execution, a write of the wrong type, a read of a port that does not exist, a throw, a
//! division by zero, an unknown function, endless recursion, an array grown past its bound),
//! and scripts that do not load (syntax errors, a failing top level, DriveControl's script,
//! a misspelt declaration, bytes that are not text). Every file is one row, sorted by name,
//! with the verdict expected; every reason of a script that failed or was refused names the
//! line and column the test expects. The CSV says the same. Then the sample class in
//! `fixtures/scripts/class/` (docs/cli.md's example), without `--component`: each script in
//! the place it declares, one without a declaration refused; and `rtnav run --script`.
//!
//! `RTNAV_CLASS_DIR=PATH` keeps the folder made there (`PATH/scripts`), to run the release
//! build on it.

use std::path::PathBuf;
use std::process::Command;

const SCENARIO: &str = "ex_pd_gains";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
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

fn reference() -> String {
    std::fs::read_to_string(root().join("fixtures/scripts/motor_control_pd.rhai")).unwrap()
}

/// The reference's lines a student's variant changes.
const P_LINE: &str = r#"let p = [rtc.param("PGainL"), rtc.param("PGainR")];"#;
const D_LINE: &str = r#"let d = [rtc.param("DGainL"), rtc.param("DGainR")];"#;
const LAW: &str =
    "torque[i] = p[i] * (angles[i] - wheels.angle[i]) + d[i] * (rates[i] - wheels.rate[i]);";
const EXECUTE: &str = "fn on_execute(rtc) {\n";
const SEND: &str = "    send_torque(rtc, this.control(rtc, now));\n";

/// `text` with its first `from` replaced by `to` (which must be there).
fn edit(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "the reference script has no `{from}`");
    text.replacen(from, to, 1)
}

/// The reference with its gains written in the script.
fn with_gains(p: f64, d: f64) -> String {
    let text = edit(&reference(), P_LINE, &format!("let p = [{p:.1}, {p:.1}];"));
    edit(&text, D_LINE, &format!("let d = [{d:.1}, {d:.1}];"))
}

/// The reference (gains P 5, D 5) with `lines` put first in `on_execute`.
fn failing_at_execute(lines: &str) -> String {
    edit(&with_gains(5.0, 5.0), EXECUTE, &format!("{EXECUTE}{lines}"))
}

/// The 1-based line of the first line of `text` that contains `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("no `{needle}`"))
        + 1
}

/// One script of the class: its file, bytes, the verdict expected, parts of the reason
/// expected, the line the reason must name (with a column), and whether it must name one.
struct Case {
    name: String,
    bytes: Vec<u8>,
    verdict: &'static str,
    reason: Vec<String>,
    line: Option<usize>,
    placed: bool,
}

fn case(name: &str, text: String, verdict: &'static str, reason: &[&str]) -> Case {
    Case {
        name: name.to_owned(),
        bytes: text.into_bytes(),
        verdict,
        reason: reason.iter().map(|s| (*s).to_owned()).collect(),
        line: None,
        placed: false,
    }
}

/// A script that fails (or is refused) at the first line of it that contains `at`.
fn failing(name: &str, text: String, verdict: &'static str, reason: &[&str], at: &str) -> Case {
    let line = line_of(&text, at);
    Case {
        line: Some(line),
        placed: true,
        ..case(name, text, verdict, reason)
    }
}

const REACH: &str = "failed: reach 0.5 m/s (within 2 %) in 0.3 s";
const OVERSHOOT: &str = "failed: overshoot 0.5 m/s by at most 5 %";
const ARRIVE: &str = "arrive within 80 s";

fn class() -> Vec<Case> {
    let mut out = Vec::new();
    for d in [2.0, 3.0, 5.0, 8.0, 10.0, 20.0] {
        out.push(case(
            &format!("right-d{d:04.1}.rhai"),
            with_gains(5.0, d),
            "passed",
            &[],
        ));
    }
    for p in [0.0, 50.0, 100.0, 200.0] {
        out.push(case(
            &format!("right-p{p:05.1}.rhai"),
            with_gains(p, 5.0),
            "passed",
            &[],
        ));
    }
    out.push(case(
        "wrong-d-zero.rhai",
        with_gains(5.0, 0.0),
        "failed",
        &[REACH, ARRIVE],
    ));
    out.push(case(
        "wrong-d-soft.rhai",
        with_gains(5.0, 1.0),
        "failed",
        &[REACH],
    ));
    out.push(case(
        "wrong-p-high.rhai",
        with_gains(300.0, 5.0),
        "failed",
        &[OVERSHOOT],
    ));
    out.push(case(
        "wrong-p-huge.rhai",
        with_gains(1000.0, 5.0),
        "failed",
        &[OVERSHOOT],
    ));
    out.push(case(
        "wrong-sign-d.rhai",
        edit(
            &with_gains(5.0, 5.0),
            LAW,
            "torque[i] = p[i] * (angles[i] - wheels.angle[i]) + d[i] * (wheels.rate[i] - rates[i]);",
        ),
        "failed",
        &["failed: reach 0.5 m/s"],
    ));
    // The scenario's gains (D 0.3) as they stand: the lesson's point.
    out.push(case(
        "wrong-as-it-stands.rhai",
        reference(),
        "failed",
        &[REACH, ARRIVE],
    ));
    out.push(case(
        "wrong-no-torque.rhai",
        edit(
            &with_gains(5.0, 5.0),
            SEND,
            "    send_torque(rtc, [0.0, 0.0]);\n",
        ),
        "failed",
        &[REACH, ARRIVE],
    ));
    out.push(case(
        "wrong-wheels-swapped.rhai",
        edit(
            &edit(
                &with_gains(5.0, 5.0),
                "data[left] = torque[0];",
                "data[left] = torque[1];",
            ),
            "data[right] = torque[1];",
            "data[right] = torque[0];",
        ),
        "failed",
        &["failed:"],
    ));
    // Scripts that fail while they run: FAILED, with the script's error in the reason.
    let fail = "the script failed: on_execute, line ";
    out.push(failing(
        "run-endless-loop.rhai",
        failing_at_execute("    let turns = 0;\n    while true {\n        turns += 1;\n    }\n"),
        "failed",
        &[REACH, fail, "ran past its budget of 200000 operations"],
        "turns += 1;",
    ));
    out.push(failing(
        "run-error-100th.rhai",
        failing_at_execute(
            "    this.executions = if this.executions == () { 1 } else { this.executions + 1 };\n    \
             if this.executions == 100 {\n        let a = [0.0, 0.0];\n        let b = a[2];\n    }\n",
        ),
        "failed",
        &[fail, "index 2 is outside the array, which has 2 items (at 0.2 s)"],
        "let b = a[2];",
    ));
    out.push(failing(
        "run-wrong-type.rhai",
        failing_at_execute("    rtc.torque.write(#{ tm: rtc.tm, data: \"full power\" });\n"),
        "failed",
        &[
            fail,
            "`write()` on `torque` (TimedDoubleSeq)",
            "not a string",
        ],
        "full power",
    ));
    out.push(failing(
        "run-missing-port.rhai",
        failing_at_execute("    let angles = rtc.in_wheel_angle.read();\n"),
        "failed",
        &[fail, "no port `in_wheel_angle`"],
        "in_wheel_angle",
    ));
    out.push(failing(
        "run-throw.rhai",
        failing_at_execute("    if rtc.time > 2.0 {\n        throw \"tired\";\n    }\n"),
        "failed",
        &[fail, "tired"],
        "throw \"tired\"",
    ));
    out.push(failing(
        "run-divide-by-zero.rhai",
        failing_at_execute("    let zero = 0;\n    let n = 10 / zero;\n"),
        "failed",
        &[fail],
        "10 / zero",
    ));
    out.push(failing(
        "run-unknown-function.rhai",
        failing_at_execute("    let t = torque_for(rtc);\n"),
        "failed",
        &[fail, "torque_for"],
        "torque_for",
    ));
    out.push(failing(
        "run-recursion.rhai",
        edit(
            &failing_at_execute("    deeper(0);\n"),
            "fn on_initialize() {",
            "fn deeper(n) {\n    deeper(n + 1)\n}\n\nfn on_initialize() {",
        ),
        "failed",
        &[fail],
        "deeper(n + 1)",
    ));
    out.push(failing(
        "run-array-grows.rhai",
        failing_at_execute("    let a = [];\n    loop {\n        a.push(1.0);\n    }\n"),
        "failed",
        &[fail],
        "a.push(1.0);",
    ));
    // Scripts that do not load: REFUSED, at the line and column.
    let syntax = "syntax error at line ";
    out.push(failing(
        "load-let-without-name.rhai",
        failing_at_execute("    let = 5;\n"),
        "refused",
        &[syntax],
        "let = 5;",
    ));
    // Where a brace is missing, the parser finds out later: some line and column.
    out.push(Case {
        placed: true,
        ..case(
            "load-missing-brace.rhai",
            edit(
                &with_gains(5.0, 5.0),
                "fn on_deactivated(rtc) {",
                "fn on_deactivated(rtc) {{",
            ),
            "refused",
            &[syntax],
        )
    });
    out.push(failing(
        "load-top-level-fails.rhai",
        edit(
            &with_gains(5.0, 5.0),
            EXECUTE,
            &format!("let wheels = [1, 2];\nlet third = wheels[2];\n\n{EXECUTE}"),
        ),
        "refused",
        &["top level, line ", "index 2 is outside the array"],
        "let third = wheels[2];",
    ));
    let pursuit =
        std::fs::read_to_string(root().join("fixtures/scripts/drive_control_pursuit.rhai"))
            .unwrap();
    out.push(failing(
        "load-drive-control.rhai",
        pursuit,
        "refused",
        &["the script declares `COMPONENT = \"DriveControl\"`, not MotorControl"],
        "const COMPONENT",
    ));
    out.push(failing(
        "load-misspelt-declaration.rhai",
        edit(
            &with_gains(5.0, 5.0),
            "const COMPONENT = \"MotorControl\";",
            "const COMPONENT = \"MotorControll\";",
        ),
        "refused",
        &["MotorControll"],
        "const COMPONENT",
    ));
    out.push(case(
        "load-not-text.rhai",
        String::new(),
        "refused",
        &["not UTF-8 text"],
    ));
    if let Some(last) = out.last_mut() {
        last.bytes = vec![0xff, 0xfe, 0x00, 0x7b];
    }
    out.sort_by(|a, b| a.name.cmp(&b.name));
    out
}

/// The line and column a reason names after `line `: both must be positive numbers.
fn names_line_and_column(reason: &str, line: usize) -> bool {
    let key = format!("line {line}, column ");
    reason.match_indices(&key).any(|(at, _)| {
        let rest = &reason[at + key.len()..];
        let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
        digits.parse::<usize>().is_ok_and(|c| c > 0)
    })
}

/// Whether a reason names some line and column, both positive.
fn names_a_line_and_column(reason: &str) -> bool {
    reason.match_indices("line ").any(|(at, _)| {
        let rest = &reason[at + "line ".len()..];
        let line: String = rest.chars().take_while(char::is_ascii_digit).collect();
        line.parse::<usize>().is_ok_and(|l| l > 0)
            && names_line_and_column(reason, line.parse().unwrap_or(0))
    })
}

fn folder(name: &str) -> PathBuf {
    match std::env::var_os("RTNAV_CLASS_DIR") {
        Some(dir) => PathBuf::from(dir).join(name),
        None => std::env::temp_dir().join(format!("rtnav-class-{name}-{}", std::process::id())),
    }
}

/// A CSV line's fields (a reason may be quoted).
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
fn a_class_of_scripts_is_one_table_with_a_row_per_script() {
    let dir = folder("scripts");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let class = class();
    assert!(class.len() >= 30, "{} scripts", class.len());
    for c in &class {
        std::fs::write(dir.join(&c.name), &c.bytes).unwrap();
    }
    std::fs::write(dir.join("notes.txt"), "not a script").unwrap();
    let csv = dir.with_extension("csv");
    let (code, table, err) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--script".as_ref(),
        dir.as_os_str(),
        "--component".as_ref(),
        "MotorControl".as_ref(),
        "--csv".as_ref(),
        csv.as_os_str(),
    ]);
    println!("{table}");
    assert_eq!(code, 1, "some failed, so 1:\n{table}{err}");
    assert!(err.is_empty(), "{err}");
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines[0], format!("scenario {SCENARIO}"));
    for column in [
        "file",
        "verdict",
        "reach_speed [m/s]",
        "max_overshoot [percent]",
        "arrived [s]",
        "no_bump",
        "only_allowed",
        "ended",
        "reason",
    ] {
        assert!(lines[1].contains(column), "{column}: {}", lines[1]);
    }
    let rows = &lines[3..3 + class.len()];
    let mut wrong = Vec::new();
    for (c, line) in class.iter().zip(rows) {
        let file = dir.join(&c.name).display().to_string();
        let ok = line.starts_with(&format!("{file} "))
            && line.contains(&format!(" {} ", c.verdict.to_uppercase()))
            && c.reason.iter().all(|r| line.contains(r.as_str()))
            && c.line.is_none_or(|l| names_line_and_column(line, l))
            && (!c.placed || names_a_line_and_column(line));
        if !ok {
            wrong.push(format!(
                "{}: expected {} {:?} at line {:?}:\n  {line}",
                c.name, c.verdict, c.reason, c.line
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    let passed = class.iter().filter(|c| c.verdict == "passed").count();
    assert_eq!(
        lines[3 + class.len()],
        format!("{passed} of {} passed", class.len())
    );
    // The CSV: the same rows and reasons.
    let text = std::fs::read_to_string(&csv).unwrap();
    let csv_lines: Vec<&str> = text.lines().collect();
    assert_eq!(csv_lines.len(), class.len() + 1, "{text}");
    for (c, line) in class.iter().zip(&csv_lines[1..]) {
        let f = fields(line);
        assert_eq!(f[0], dir.join(&c.name).display().to_string());
        assert_eq!(f[1], c.verdict, "{line}");
        let reason = f.last().unwrap();
        assert!(
            c.reason.iter().all(|r| reason.contains(r.as_str())),
            "{line}"
        );
        if c.verdict == "refused" {
            assert!(f[2..f.len() - 1].iter().all(String::is_empty), "{line}");
        }
    }
    if std::env::var_os("RTNAV_CLASS_DIR").is_none() {
        std::fs::remove_dir_all(&dir).unwrap();
        std::fs::remove_file(&csv).unwrap();
    }
}

/// docs/cli.md's example: the sample class, each script in the place it declares.
#[test]
fn the_sample_class_and_one_script_alone() {
    let class = root().join("fixtures/scripts/class");
    let (code, table, err) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--script".as_ref(),
        class.as_os_str(),
    ]);
    println!("{table}");
    assert_eq!(code, 1, "{table}{err}");
    let row = |name: &str| {
        table
            .lines()
            .find(|l| l.starts_with(&class.join(name).display().to_string()))
            .unwrap_or_else(|| panic!("no row {name}:\n{table}"))
            .to_owned()
    };
    for (name, verdict, reason) in [
        ("ada.rhai", "PASSED", ""),
        ("ben.rhai", "FAILED", REACH),
        (
            "chloe.rhai",
            "FAILED",
            "the script failed: on_execute, line 65, column 93: index 2",
        ),
        (
            "dev.rhai",
            "REFUSED",
            "syntax error at line 127, column 93: ",
        ),
        (
            "emil.rhai",
            "FAILED",
            "the script failed: on_execute, line ",
        ),
        ("fay.rhai", "REFUSED", "the script declares no component"),
    ] {
        let line = row(name);
        assert!(
            line.contains(&format!(" {verdict} ")) && line.contains(reason),
            "{name}: expected {verdict} and {reason:?}:\n{line}"
        );
        if name == "emil.rhai" {
            assert!(
                line.contains("ran past its budget") && names_a_line_and_column(&line),
                "{line}"
            );
        }
    }
    assert!(table.contains("1 of 6 passed"), "{table}");
    // One script alone: its checklist, and how the script failed.
    let chloe = class.join("chloe.rhai");
    let (code, text, _) = rtnav(&[
        "check".as_ref(),
        scenario_file().as_os_str(),
        "--script".as_ref(),
        chloe.as_os_str(),
    ]);
    assert_eq!(code, 1, "{text}");
    assert!(
        text.contains("verdict  FAILED") && text.contains("script   FAILED: on_execute, line 65"),
        "{text}"
    );
}

#[test]
fn run_with_a_script_says_so_and_a_script_that_does_not_load_stops_it() {
    let pd = root().join("fixtures/scripts/motor_control_pd.rhai");
    let (code, text, err) = rtnav(&[
        "run".as_ref(),
        scenario_file().as_os_str(),
        "--script".as_ref(),
        pd.as_os_str(),
        "--until".as_ref(),
        "2".as_ref(),
    ]);
    assert_eq!(code, 0, "{text}{err}");
    assert!(
        text.contains(
            "script          MotorControl ran the student's script motor_control_pd.rhai"
        ),
        "{text}"
    );
    let syntax = root().join("fixtures/scripts/class/dev.rhai");
    let (code, text, err) = rtnav(&[
        "run".as_ref(),
        scenario_file().as_os_str(),
        "--script".as_ref(),
        syntax.as_os_str(),
    ]);
    assert_eq!(code, 2, "{text}{err}");
    assert!(
        err.starts_with("rtnav: error: `") && err.contains("syntax error at line 127, column 93"),
        "{err}"
    );
    // --component wins over the declaration; the core refuses a script for another.
    let pursuit = root().join("fixtures/scripts/drive_control_pursuit.rhai");
    let (code, _, err) = rtnav(&[
        "run".as_ref(),
        scenario_file().as_os_str(),
        "--script".as_ref(),
        pursuit.as_os_str(),
        "--component".as_ref(),
        "MotorControl".as_ref(),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("the script declares `COMPONENT = \"DriveControl\"`, not MotorControl")
            && err.contains("(the declaration: line 7, column 1)"),
        "{err}"
    );
    // No declaration and no --component: said, exit 2.
    let fay = root().join("fixtures/scripts/class/fay.rhai");
    let (code, _, err) = rtnav(&[
        "run".as_ref(),
        scenario_file().as_os_str(),
        "--script".as_ref(),
        fay.as_os_str(),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--component names none"), "{err}");
}
