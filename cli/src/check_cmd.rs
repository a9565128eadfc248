//! `rtnav check SCENARIO [--conf F… | --replay F… | --script F… [--component NAME]]`: a
//! scenario's exercise judged for one hand-in or for a whole class of them.
//!
//! Each `--conf` / `--replay` / `--script` argument is a file or a folder; a folder stands for
//! its `*.conf` (with `--conf`), `*.json` (with `--replay`) or `*.rhai` (with `--script`)
//! files. A script (spec §8) runs in the place of the component its declaration names, or of
//! the one `--component` names (it wins). The hand-ins are checked in
//! parallel, one per core (`--jobs`), and reported in the order of their paths, sorted, so
//! the table is the same on every machine and at every run.
//!
//! - One hand-in named as a file: the checklist and the verdict, as the page shows them (or
//!   one line of JSON with `--json`).
//! - Otherwise (several, or a folder): one table — file, verdict, each check's measured value
//!   with its unit and whether it passed, when the exercise ended, and the reason of a
//!   verdict other than PASSED — and, with `--csv PATH`, the same rows as CSV.
//!
//! A hand-in that cannot be judged is a row with the reason, never an error of the command:
//! a file that cannot be read or does not parse, a replay of another scenario, of another
//! content of this scenario or of another behaviour version, a replay whose run does not
//! reproduce its recorded trace hash (a file edited by hand), a `.conf` the core refuses, a
//! script that does not load (a syntax error, a failing top level, no declaration, a
//! declaration of another component: the reason names the line and column). A script that
//! fails while it runs (it throws, hits a runtime error, runs past its operations budget)
//! puts its component in Error and the run goes on: its row is judged by the checks like any
//! other, with the script's failure (action, line, column, what went wrong) in the reason.
//! A replay that ends before the exercise ends is UNFINISHED.
//!
//! Exit code: 0 when every hand-in passed, 1 when one failed, was unfinished or was refused,
//! 2 for a usage error (the scenario unreadable or without an exercise, no hand-in found, the
//! CSV not writable).

use std::fmt::Write as _;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use rayon::prelude::*;
use rtnav::data::RepoResolver;
use rtnav::present::number;
use rtnav::system::{
    Check, CheckState, ComponentKind, ExerciseRun, ExerciseStatus, Replay, Scenario, Session, Unit,
    Verdict, check_exercise,
};

use clap::Args;
use rtnav_cli::error::{CliError, CliResult};
use rtnav_cli::scenario_load::load;
use rtnav_cli::script_load::{ScriptHandIn, parse_component, script_failure, script_hand_in};

use crate::options::RootOption;

/// What is handed in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum HandIn {
    /// OpenRTM `.conf` bundles, as the page saves them.
    Conf,
    /// Replays (`*.rtnav.json`), as the page downloads them.
    Replay,
    /// Students' scripts (`*.rhai`, spec §8), each in a component's place.
    Script,
}

impl HandIn {
    /// The file name ending a folder's hand-ins have.
    fn extension(self) -> &'static str {
        match self {
            Self::Conf => "conf",
            Self::Replay => "json",
            Self::Script => "rhai",
        }
    }
}

/// The options of `rtnav check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// The scenario file (JSON) with an exercise.
    scenario: PathBuf,
    /// Configurations handed in, files or folders: OpenRTM `.conf` bundles as the page
    /// saves them (components or parameters left out keep the scenario's values).
    /// Without --conf and --replay: the exercise as the scenario stands.
    #[arg(long, num_args = 1.., value_name = "FILE_OR_DIR")]
    conf: Vec<PathBuf>,
    /// Runs handed in as replays (`*.rtnav.json`, downloaded from the page), files or
    /// folders: each checked as it was recorded, after its run reproduced its recorded
    /// trace.
    #[arg(long, num_args = 1.., value_name = "FILE_OR_DIR", conflicts_with = "conf")]
    replay: Vec<PathBuf>,
    /// Students' scripts (Rhai, spec §8), files or folders: each run in the place of the
    /// component it declares (`const COMPONENT = "MotorControl";`) or that --component
    /// names, the rest of the system as the scenario stands.
    #[arg(
        long,
        num_args = 1..,
        value_name = "FILE_OR_DIR",
        conflicts_with_all = ["conf", "replay"]
    )]
    script: Vec<PathBuf>,
    /// The component every script stands in for (MotorControl or DriveControl); wins over
    /// the scripts' declarations (a script declaring another is refused).
    #[arg(long, value_name = "NAME", requires = "script", value_parser = parse_component)]
    component: Option<ComponentKind>,
    #[command(flatten)]
    root: RootOption,
    /// Print the result of one hand-in as one line of JSON instead.
    #[arg(long)]
    json: bool,
    /// Write the table (one row per hand-in) here as CSV.
    #[arg(long, value_name = "PATH")]
    csv: Option<PathBuf>,
    /// Hand-ins checked at once (default: one per core).
    #[arg(long, value_name = "N")]
    jobs: Option<usize>,
}

impl CheckArgs {
    /// What the files handed in are.
    fn kind(&self) -> HandIn {
        if !self.script.is_empty() {
            HandIn::Script
        } else if !self.replay.is_empty() {
            HandIn::Replay
        } else {
            HandIn::Conf
        }
    }

    /// The files and folders handed in.
    fn paths(&self) -> &[PathBuf] {
        match self.kind() {
            HandIn::Conf => &self.conf,
            HandIn::Replay => &self.replay,
            HandIn::Script => &self.script,
        }
    }
}

/// A hand-in's verdict in the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum RowVerdict {
    Passed,
    Failed,
    Unfinished,
    Refused,
}

impl RowVerdict {
    fn word(self) -> &'static str {
        match self {
            Self::Passed => "PASSED",
            Self::Failed => "FAILED",
            Self::Unfinished => "UNFINISHED",
            Self::Refused => "REFUSED",
        }
    }
}

/// One hand-in judged.
#[derive(Debug)]
struct Row {
    file: PathBuf,
    verdict: RowVerdict,
    /// Why, when not PASSED (the failed checks, or why it was not judged).
    reason: String,
    /// The checklist, when the hand-in was judged.
    status: Option<ExerciseStatus>,
    /// How the script handed in failed while it ran, if it did (its action, line, column).
    script_failed: Option<String>,
}

/// The hand-ins `paths` name: files as given, folders' files with `kind`'s ending; sorted by
/// path, each once. An error for a path that does not exist or a folder that cannot be read.
fn hand_ins(paths: &[PathBuf], kind: HandIn) -> CliResult<Vec<PathBuf>> {
    let mut files = Vec::new();
    for path in paths {
        if path.is_dir() {
            let entries = std::fs::read_dir(path).map_err(|source| CliError::ReadFolder {
                path: path.clone(),
                source,
            })?;
            for entry in entries {
                let entry = entry.map_err(|source| CliError::ReadFolder {
                    path: path.clone(),
                    source,
                })?;
                let file = entry.path();
                let wanted = file.is_file()
                    && file
                        .extension()
                        .is_some_and(|x| x.eq_ignore_ascii_case(kind.extension()));
                if wanted {
                    files.push(file);
                }
            }
        } else if path.exists() {
            files.push(path.clone());
        } else {
            return Err(CliError::NoSuchPath { path: path.clone() });
        }
    }
    files.sort();
    files.dedup();
    Ok(files)
}

/// The failed checks, in words.
fn failures(status: &ExerciseStatus) -> String {
    status
        .checks
        .iter()
        .filter(|c| c.state == CheckState::Failed)
        .map(|c| {
            let mut s = c.check.to_string();
            if !c.changed.is_empty() {
                let _ = write!(s, " (changed: {})", c.changed.join(", "));
            }
            s
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// A judged hand-in's row; `script_failed`: how its script failed while it ran.
fn judged(file: &Path, status: ExerciseStatus, script_failed: Option<String>) -> Row {
    let (verdict, mut reason) = match status.verdict {
        Verdict::Passed => (RowVerdict::Passed, String::new()),
        Verdict::Failed => (RowVerdict::Failed, format!("failed: {}", failures(&status))),
        Verdict::Waiting => (
            RowVerdict::Unfinished,
            "the drive never started (Activate all)".to_owned(),
        ),
        Verdict::Running => (
            RowVerdict::Unfinished,
            "the recording ends before the exercise ends".to_owned(),
        ),
    };
    if let Some(failure) = &script_failed {
        if !reason.is_empty() {
            reason.push_str("; ");
        }
        let _ = write!(reason, "the script failed: {failure}");
    }
    Row {
        file: file.to_path_buf(),
        verdict,
        reason,
        status: Some(status),
        script_failed,
    }
}

fn refused(file: &Path, reason: impl Into<String>) -> Row {
    Row {
        file: file.to_path_buf(),
        verdict: RowVerdict::Refused,
        reason: reason.into(),
        status: None,
        script_failed: None,
    }
}

/// Judges one replay: loaded on the scenario as the page loads it, to its recorded end;
/// refused unless its run reproduces the recorded trace.
fn judge_replay(
    file: &Path,
    text: &str,
    scenario: &Scenario,
    resolver: &RepoResolver,
) -> CliResult<Row> {
    let run = match Replay::from_json(text) {
        Ok(run) => run,
        Err(e) => return Ok(refused(file, e.to_string())),
    };
    if run.setup.scenario != scenario.name {
        return Ok(refused(
            file,
            format!(
                "a replay of scenario `{}`, not of `{}`",
                rtnav::present::excerpt(&run.setup.scenario),
                scenario.name
            ),
        ));
    }
    let mut session = Session::new().map_err(CliError::core)?;
    session
        .load_scenario(scenario.clone(), resolver)
        .map_err(CliError::core)?;
    let check = match session.load_replay(&run) {
        Ok(check) => check,
        Err(e) => return Ok(refused(file, e.to_string())),
    };
    if !check.matches {
        return Ok(refused(
            file,
            format!(
                "does not reproduce its recorded trace (trace hash {}…, recorded {}…; {} samples, \
                 recorded {}): the file was changed after it was recorded",
                &check.hash[..12],
                check
                    .expected_hash
                    .get(..12)
                    .unwrap_or(&check.expected_hash),
                check.samples,
                check.expected_samples
            ),
        ));
    }
    let status = session
        .exercise()
        .ok_or_else(|| CliError::NoExercise(scenario.name.clone()))?;
    Ok(judged(file, status, None))
}

/// Judges the exercise done with a `.conf` or a script handed in (the rest of the set-up as
/// the scenario stands): refused when the core refuses either.
fn judge_exercise(
    file: &Path,
    scenario: &Scenario,
    resolver: &RepoResolver,
    conf: Option<&str>,
    script: Option<&ScriptHandIn>,
) -> Row {
    let scripts = script.map(ScriptHandIn::scripts).unwrap_or_default();
    let mut run = match ExerciseRun::with_scripts(scenario, resolver, &scripts, conf, &[]) {
        Ok(run) => run,
        Err(e) => {
            return refused(
                file,
                script.map_or_else(|| e.to_string(), |s| s.refusal(&e)),
            );
        }
    };
    let status = run.run_to_end();
    let failed = script.and_then(|s| script_failure(run.system(), s.component));
    judged(file, status, failed)
}

/// Judges one script: compiled and placed (`component`, else its declaration), then the
/// exercise done with it; refused when it does not load.
fn judge_script(
    file: &Path,
    text: &str,
    scenario: &Scenario,
    resolver: &RepoResolver,
    component: Option<ComponentKind>,
) -> Row {
    let name = file.file_name().map_or_else(
        || file.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    match script_hand_in(&name, text, component) {
        Ok(script) => judge_exercise(file, scenario, resolver, None, Some(&script)),
        Err(e) => refused(file, e.to_string()),
    }
}

/// Judges one hand-in. `Err` only for what is not the hand-in's fault (the scenario).
fn judge(
    file: &Path,
    kind: HandIn,
    component: Option<ComponentKind>,
    scenario: &Scenario,
    resolver: &RepoResolver,
) -> CliResult<Row> {
    let bytes = match std::fs::read(file) {
        Ok(b) => b,
        Err(e) => return Ok(refused(file, format!("cannot read: {e}"))),
    };
    let Ok(text) = String::from_utf8(bytes) else {
        return Ok(refused(file, "not UTF-8 text"));
    };
    match kind {
        HandIn::Replay => judge_replay(file, &text, scenario, resolver),
        HandIn::Conf => Ok(judge_exercise(file, scenario, resolver, Some(&text), None)),
        HandIn::Script => Ok(judge_script(file, &text, scenario, resolver, component)),
    }
}

/// [`judge`], with a panic (a defect of the core) reported as the row's reason.
fn judge_guarded(
    file: &Path,
    kind: HandIn,
    component: Option<ComponentKind>,
    scenario: &Scenario,
    resolver: &RepoResolver,
) -> CliResult<Row> {
    catch_unwind(AssertUnwindSafe(|| {
        judge(file, kind, component, scenario, resolver)
    }))
    .unwrap_or_else(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Ok(refused(
            file,
            format!("rtnav failed on this file (a defect, please report it): {what}"),
        ))
    })
}

/// Every hand-in `args` names, judged in parallel, in path order; and whether they are a
/// class (several, or a folder) rather than one file.
fn judge_all(
    args: &CheckArgs,
    scenario: &Scenario,
    resolver: &RepoResolver,
) -> CliResult<(Vec<Row>, bool)> {
    let files = hand_ins(args.paths(), args.kind())?;
    if files.is_empty() {
        return Err(CliError::NoHandIns {
            extension: args.kind().extension(),
            places: args
                .paths()
                .iter()
                .map(|p| format!("`{}`", p.display()))
                .collect::<Vec<_>>()
                .join(", "),
        });
    }
    let class = files.len() > 1 || args.paths().iter().any(|p| p.is_dir());
    if class && args.json {
        return Err(CliError::Usage(
            "--json prints one hand-in; for a class use the table or --csv",
        ));
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.jobs.unwrap_or(0))
        .build()?;
    let rows = pool.install(|| {
        files
            .par_iter()
            .map(|f| judge_guarded(f, args.kind(), args.component, scenario, resolver))
            .collect::<Result<Vec<_>, _>>()
    })?;
    Ok((rows, class))
}

/// `rtnav check` (module documentation).
pub fn check(args: CheckArgs) -> CliResult<ExitCode> {
    let (scenario, resolver) = load(&args.scenario, args.root.root.clone())?;
    let exercise = scenario
        .exercise
        .clone()
        .ok_or_else(|| CliError::NoExercise(scenario.name.clone()))?;
    let (rows, class) = if args.paths().is_empty() {
        // No hand-in: the exercise as the scenario stands (nothing changed).
        let status = check_exercise(&scenario, &resolver, None, &[]).map_err(CliError::core)?;
        (
            vec![judged(
                Path::new("(the scenario as it stands)"),
                status,
                None,
            )],
            false,
        )
    } else {
        judge_all(&args, &scenario, &resolver)?
    };
    let columns = columns(&exercise.checks);
    if let Some(csv) = &args.csv {
        std::fs::write(csv, csv_text(&columns, &rows)).map_err(|source| CliError::Write {
            path: csv.clone(),
            source,
        })?;
    }
    if !class {
        let Some(row) = rows.into_iter().next() else {
            return Err(CliError::NoHandIns {
                extension: args.kind().extension(),
                places: String::new(),
            });
        };
        return one(&args, &scenario, row);
    }
    println!("scenario {}", scenario.name);
    print!("{}", table(&columns, &rows));
    let passed = rows
        .iter()
        .filter(|r| r.verdict == RowVerdict::Passed)
        .count();
    println!("{passed} of {} passed", rows.len());
    Ok(exit(rows.iter().all(|r| r.verdict == RowVerdict::Passed)))
}

fn exit(all_passed: bool) -> ExitCode {
    if all_passed {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// One hand-in: the checklist (or why it was refused).
fn one(args: &CheckArgs, scenario: &Scenario, row: Row) -> CliResult<ExitCode> {
    let passed = row.verdict == RowVerdict::Passed;
    match (&row.status, args.json) {
        (Some(status), true) => {
            let mut value = serde_json::to_value(status)?;
            if let (Some(failure), Some(fields)) = (&row.script_failed, value.as_object_mut()) {
                fields.insert("script_failed".to_owned(), failure.clone().into());
            }
            println!("{value}");
        }
        (None, true) => println!(
            "{}",
            serde_json::json!({
                "file": row.file.display().to_string(),
                "verdict": "refused",
                "reason": row.reason,
            })
        ),
        (Some(status), false) => {
            println!("scenario {}", scenario.name);
            println!("{status}");
            if row.verdict == RowVerdict::Unfinished {
                println!("         ({})", row.reason);
            }
            if let Some(failure) = &row.script_failed {
                println!("script   FAILED: {failure}");
            }
        }
        (None, false) => {
            println!("scenario {}", scenario.name);
            println!("file     {}", row.file.display());
            println!("verdict  REFUSED: {}", row.reason);
        }
    }
    Ok(exit(passed))
}

/// A check's column: its name (the file's `check` key, numbered when it repeats) and unit.
struct Column {
    name: String,
    unit: Option<Unit>,
}

impl Column {
    /// The unit's short name (`s`, `deg`, `m`, `plans`, `percent`: as the core writes it in
    /// JSON).
    fn unit_name(&self) -> Option<String> {
        let value = serde_json::to_value(self.unit?).ok()?;
        value.as_str().map(str::to_owned)
    }
}

fn columns(checks: &[Check]) -> Vec<Column> {
    let mut out: Vec<Column> = Vec::new();
    let all = checks.iter().cloned().chain([Check::OnlyAllowed]);
    for check in all {
        let key = serde_json::to_value(&check)
            .ok()
            .and_then(|v| v.get("check")?.as_str().map(str::to_owned))
            .unwrap_or_else(|| "check".to_owned());
        let seen = out
            .iter()
            .filter(|c| c.name == key || c.name.starts_with(&format!("{key}#")))
            .count();
        let name = if seen == 0 {
            key
        } else {
            format!("{key}#{}", seen + 1)
        };
        out.push(Column {
            name,
            unit: check.unit(),
        });
    }
    out
}

fn state_word(state: CheckState) -> &'static str {
    match state {
        CheckState::Open => "open",
        CheckState::Passed => "pass",
        CheckState::Failed => "FAIL",
    }
}

/// A cell of the table: `pass 12.4 s`, `FAIL 0.41 m`, `pass` (nothing measured).
fn cell(row: &Row, i: usize, column: &Column) -> String {
    let Some(c) = row.status.as_ref().and_then(|s| s.checks.get(i)) else {
        return "-".to_owned();
    };
    let mut s = state_word(c.state).to_owned();
    if let Some(m) = c.measured {
        let _ = write!(s, " {}", number(round3(m)));
        if let Some(u) = column.unit {
            let _ = write!(s, "{u}");
        }
    }
    s
}

fn round3(v: f64) -> f64 {
    libm::round(v * 1000.0) / 1000.0
}

fn ended(row: &Row) -> String {
    row.status
        .as_ref()
        .and_then(|s| s.ended_after)
        .map_or_else(|| "-".to_owned(), |t| format!("{} s", number(round3(t))))
}

/// The table: a header, a rule, one line per row; then what each column checks.
fn table(columns: &[Column], rows: &[Row]) -> String {
    let mut header = vec!["file".to_owned(), "verdict".to_owned()];
    header.extend(columns.iter().map(|c| match c.unit_name() {
        Some(u) => format!("{} [{u}]", c.name),
        None => c.name.clone(),
    }));
    header.push("ended".to_owned());
    header.push("reason".to_owned());
    let lines: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let mut line = vec![r.file.display().to_string(), r.verdict.word().to_owned()];
            line.extend(columns.iter().enumerate().map(|(i, c)| cell(r, i, c)));
            line.push(ended(r));
            line.push(r.reason.clone());
            line
        })
        .collect();
    let widths: Vec<usize> = (0..header.len())
        .map(|i| {
            lines
                .iter()
                .map(|l| l[i].chars().count())
                .chain([header[i].chars().count()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    let mut put = |cells: &[String]| {
        let last = cells.len() - 1;
        let text: Vec<String> = cells
            .iter()
            .enumerate()
            .map(|(i, c)| {
                if i == last {
                    c.clone()
                } else {
                    let pad = widths[i].saturating_sub(c.chars().count());
                    format!("{c}{}", " ".repeat(pad))
                }
            })
            .collect();
        let _ = writeln!(out, "{}", text.join("  ").trim_end());
    };
    put(&header);
    let rule: Vec<String> = widths.iter().map(|w| "-".repeat((*w).max(1))).collect();
    put(&rule);
    for line in &lines {
        put(line);
    }
    out
}

/// A CSV field, quoted when it must be (RFC 4180).
fn field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// The rows as CSV: `file,verdict`, per check its state (`pass`, `fail`, empty when not
/// judged) and, for a check that measures, its value in the unit its header names; when the
/// exercise ended \[s\]; the reason.
fn csv_text(columns: &[Column], rows: &[Row]) -> String {
    let mut header = vec!["file".to_owned(), "verdict".to_owned()];
    for c in columns {
        header.push(c.name.clone());
        if let Some(u) = c.unit_name() {
            header.push(format!("{}_{u}", c.name));
        }
    }
    header.push("ended_s".to_owned());
    header.push("reason".to_owned());
    let mut out = header
        .iter()
        .map(|h| field(h))
        .collect::<Vec<_>>()
        .join(",");
    out.push('\n');
    for r in rows {
        let mut line = vec![
            r.file.display().to_string(),
            r.verdict.word().to_lowercase(),
        ];
        for (i, c) in columns.iter().enumerate() {
            let check = r.status.as_ref().and_then(|s| s.checks.get(i));
            line.push(check.map_or_else(String::new, |k| state_word(k.state).to_lowercase()));
            if c.unit.is_some() {
                line.push(
                    check
                        .and_then(|k| k.measured)
                        .map_or_else(String::new, number),
                );
            }
        }
        line.push(
            r.status
                .as_ref()
                .and_then(|s| s.ended_after)
                .map_or_else(String::new, number),
        );
        line.push(r.reason.clone());
        out.push_str(&line.iter().map(|f| field(f)).collect::<Vec<_>>().join(","));
        out.push('\n');
    }
    out
}
