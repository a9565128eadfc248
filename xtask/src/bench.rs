//! `cargo xtask bench`: the table — interactive planning on the largest real maps —
//! measured in one run and printed as Markdown (the table of `docs/performance.md`).
//!
//! 1. The criterion benches `interactive` (edit, local plan, full field, route on the
//!    generated 1.7 M-cell warehouse) and `global` (every MovingAI map in the shared data,
//!    against `pathfinding::astar`), each with its baseline in the same run; their medians
//!    are read back from `target/criterion/**/new/estimates.json`.
//! 2. The same operations timed by one harness natively and compiled to wasm32 under Node
//!    (`tests/perf.rs`): the wasm rows, as a ratio to native.
//! 3. The browser: `tests/e2e/large_map.bench.mjs` paints on the warehouse at 16× in
//!    Debian's Chromium (the page as `cargo xtask dist` writes it) and reports the worst frame;
//!    `tests/e2e/load.bench.mjs` loads the page cold at 10 Mbit/s with 40 ms of latency,
//!    compressed and plain, and reports the time to the map drawn.
//!
//! ```text
//! cargo xtask bench [--no-wasm] [--no-browser]
//! ```
//!
//! Nothing is asserted: the machines are shared and noisy. Each row says the goal and
//! whether this run met it. The table is printed and written to
//! `target/bench/performance.md`.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Stdio};

use crate::Result;
use crate::dist;
use crate::serve::Background;
use crate::tools::{self, cargo, cmd, run};

/// Runs everything and prints the table.
pub fn run_all(args: &[String]) -> Result {
    let (mut wasm_rows, mut browser) = (true, true);
    for a in args {
        match a.as_str() {
            "--no-wasm" => wasm_rows = false,
            "--no-browser" => browser = false,
            other => return Err(format!("bench: unexpected argument `{other}`").into()),
        }
    }
    let target = tools::target_dir();
    let criterion_dir = target.join("criterion");
    // Only what this run measures: a result older than this is another run's.
    let started = std::time::SystemTime::now();
    for bench in ["interactive", "global"] {
        run(cargo().args([
            "bench",
            "-p",
            "rtnav",
            "--bench",
            bench,
            "--",
            "--warm-up-time",
            "1",
            "--measurement-time",
            "3",
        ]))?;
    }
    let medians = criterion_medians(&criterion_dir, started);
    let native = harness(false)?;
    let wasm32 = if wasm_rows {
        harness(true)?
    } else {
        Vec::new()
    };
    let frames = if browser {
        browser_frame()?
    } else {
        Frames::default()
    };
    let text = table(&medians, &native, &wasm32, &frames);
    print!("{text}");
    // Recorded beside criterion's own results, for docs/performance.md.
    let record = target.join("bench").join("performance.md");
    std::fs::create_dir_all(record.parent().unwrap_or(&target))?;
    std::fs::write(&record, &text)?;
    println!("\n(table written to {})", record.display());
    Ok(())
}

/// `(group, function)` → median in milliseconds, for every benchmark criterion wrote results
/// of since `since`.
fn criterion_medians(dir: &Path, since: std::time::SystemTime) -> BTreeMap<(String, String), f64> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.file_name().is_some_and(|n| n == "estimates.json")
                && p.parent()
                    .and_then(Path::file_name)
                    .is_some_and(|n| n == "new")
                && std::fs::metadata(&p)
                    .and_then(|m| m.modified())
                    .is_ok_and(|t| t >= since)
            {
                let read = |f: &Path| -> Option<serde_json::Value> {
                    serde_json::from_str(&std::fs::read_to_string(f).ok()?).ok()
                };
                let (Some(est), Some(id)) = (read(&p), read(&p.with_file_name("benchmark.json")))
                else {
                    continue;
                };
                let median = est["median"]["point_estimate"].as_f64();
                let group = id["group_id"].as_str();
                let function = id["function_id"].as_str();
                if let (Some(m), Some(g), Some(f)) = (median, group, function) {
                    out.insert((g.to_owned(), f.to_owned()), m * 1e-6);
                }
            }
        }
    }
    out
}

/// One `RTNAV-BENCH` line of `tests/perf.rs`.
#[derive(Debug, Clone)]
struct Timed {
    op: String,
    median_ms: f64,
}

/// Runs `tests/perf.rs` natively or in wasm32 (release builds) and reads its lines.
fn harness(wasm32: bool) -> Result<Vec<Timed>> {
    let mut c = cargo();
    c.args(["test", "--release", "-p", "rtnav-tests", "--test", "perf"]);
    if wasm32 {
        tools::ensure_wasm_target()?;
        tools::ensure_wasm_bindgen_cli()?;
        c.args(["--target", "wasm32-unknown-unknown"]).env(
            "CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUNNER",
            "wasm-bindgen-test-runner",
        );
    }
    c.args(["--", "--nocapture"]);
    let text = captured(&mut c)?;
    Ok(text
        .lines()
        .filter_map(|l| {
            let json = &l[l.find("RTNAV-BENCH ")? + "RTNAV-BENCH ".len()..];
            let v: serde_json::Value = serde_json::from_str(json.trim()).ok()?;
            Some(Timed {
                op: v["op"].as_str()?.to_owned(),
                median_ms: v["median_ms"].as_f64()?,
            })
        })
        .collect())
}

/// Runs `c`, echoing it and its output; returns the output (stdout and stderr).
fn captured(c: &mut Command) -> Result<String> {
    let mut text = c.get_program().to_string_lossy().into_owned();
    for a in c.get_args() {
        text.push(' ');
        text.push_str(&a.to_string_lossy());
    }
    println!("$ {text}");
    let out = c
        .stdin(Stdio::null())
        .output()
        .map_err(|e| format!("cannot run `{text}`: {e}"))?;
    let all = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    for line in all.lines().filter(|l| l.contains("RTNAV-")) {
        println!("  {line}");
    }
    if out.status.success() {
        Ok(all)
    } else {
        eprintln!("{all}");
        Err(format!("`{text}` failed ({})", out.status).into())
    }
}

/// The browser test's report: `(worst frame, median frame, worst step + render)` ms.
type Frame = (f64, f64, f64);

/// The browser test's two reports: the page as it is, and its steps without the frame budget
/// (the baseline of the same run); and the first loads' (`load.bench.mjs`).
#[derive(Default)]
struct Frames {
    page: Option<Frame>,
    unbudgeted: Option<Frame>,
    loads: Vec<Load>,
}

/// A first load's report: how it was served, and its times [ms] and transfer.
struct Load {
    way: String,
    median_ms: f64,
    fastest_ms: f64,
    slowest_ms: f64,
    requests: u64,
    transferred_kb: u64,
}

/// Serves the page as `cargo xtask dist` writes it and runs `tests/e2e/large_map.bench.mjs`
/// (Chromium), which paints on the generated warehouse at 16× (with and without the frame
/// budget); its `RTNAV-FRAME` lines.
fn browser_frame() -> Result<Frames> {
    tools::ensure_node()?;
    tools::ensure_chromium()?;
    let e2e = tools::repo_root().join("tests").join("e2e");
    run(cmd("npm")
        .args(["ci", "--no-audit", "--no-fund"])
        .current_dir(&e2e)
        .env("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1"))?;
    let site = tools::target_dir().join("bench-site");
    dist::build(&site)?;
    let server = Background::start(&site)?;
    let text = captured(
        cmd("node")
            .args(["--test", "large_map.bench.mjs"])
            .current_dir(&e2e)
            .env("RTNAV_URL", &server.url)
            .env("RTNAV_CHROMIUM", tools::CHROMIUM)
            .env("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1"),
    );
    let loads = captured(
        cmd("node")
            .args(["--test", "load.bench.mjs"])
            .current_dir(&e2e)
            .env("RTNAV_URL", &server.url)
            .env("RTNAV_CHROMIUM", tools::CHROMIUM)
            .env("PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD", "1"),
    );
    drop(server);
    let mut frames = Frames::default();
    for line in loads?.lines() {
        let Some(at) = line.find("RTNAV-LOAD ") else {
            continue;
        };
        let Ok(v) = serde_json::from_str::<serde_json::Value>(line[at + 11..].trim()) else {
            continue;
        };
        let load = (|| {
            Some(Load {
                way: v["way"].as_str()?.to_owned(),
                median_ms: v["median_ms"].as_f64()?,
                fastest_ms: v["fastest_ms"].as_f64()?,
                slowest_ms: v["slowest_ms"].as_f64()?,
                requests: v["requests"].as_u64()?,
                transferred_kb: v["transferred_kb"].as_u64()?,
            })
        })();
        frames.loads.extend(load);
    }
    for line in text?.lines() {
        let Some(at) = line.find("RTNAV-FRAME ") else {
            continue;
        };
        let Ok(v) = serde_json::from_str::<serde_json::Value>(line[at + 12..].trim()) else {
            continue;
        };
        let frame = (|| {
            Some((
                v["worst_frame_ms"].as_f64()?,
                v["median_frame_ms"].as_f64()?,
                v["worst_step_render_ms"].as_f64()?,
            ))
        })();
        if v["budget"].as_bool() == Some(false) {
            frames.unbudgeted = frame;
        } else {
            frames.page = frame;
        }
    }
    Ok(frames)
}

fn ms(v: Option<f64>) -> String {
    v.map_or_else(
        || "—".to_owned(),
        |v| {
            if v >= 100.0 {
                format!("{v:.0} ms")
            } else if v >= 10.0 {
                format!("{v:.1} ms")
            } else {
                format!("{v:.2} ms")
            }
        },
    )
}

/// Whether this run met a row's goal (`None`: it was not measured).
fn verdict(met: Option<bool>) -> &'static str {
    match met {
        Some(true) => "met",
        Some(false) => "**not met**",
        None => "not measured",
    }
}

/// The Markdown table.
fn table(
    medians: &BTreeMap<(String, String), f64>,
    native: &[Timed],
    wasm32: &[Timed],
    frames: &Frames,
) -> String {
    let get = |g: &str, f: &str| medians.get(&(g.to_owned(), f.to_owned())).copied();
    let timed = |rows: &[Timed], op: &str| rows.iter().find(|t| t.op == op).map(|t| t.median_ms);
    let ratio = |a: Option<f64>, b: Option<f64>| a.zip(b).map(|(a, b)| a / b);
    let mut s = String::new();
    s += "\n| operation | before (same run) | rtnav | speed-up | goal | |\n";
    s += "| --- | --- | --- | --- | --- | --- |\n";
    let mut row =
        |name: &str, before: Option<f64>, now: Option<f64>, goal: &str, met: Option<bool>| {
            s += &format!(
                "| {name} | {} | {} | {} | {goal} | {} |\n",
                ms(before),
                ms(now),
                ratio(before, now).map_or_else(|| "—".to_owned(), |r| format!("{r:.1}×")),
                if goal == "—" { "" } else { verdict(met) },
            );
        };
    let edit = get("edit", "rtnav");
    row(
        "edit on 1.7 M cells: 5×5 brush + distances + global + local replan",
        get("edit", "before"),
        edit,
        "≤ 10 ms",
        edit.map(|v| v <= 10.0),
    );
    let local = get("local_plan", "rtnav");
    row(
        "one default local plan, 1.7 M cells (positions every 4.5 m along the route)",
        get("local_plan", "reference"),
        local,
        "≤ 8 ms",
        local.map(|v| v <= 8.0),
    );
    let full = get("full_field", "rtnav");
    row(
        "full potential field, 1000×1000 open map",
        get("full_field", "reference"),
        full,
        "≤ 20 ms",
        full.map(|v| v <= 20.0),
    );
    let route = get("route", "rtnav");
    row(
        "route on 1.7 M cells (62 m), vs plain A*",
        get("route", "cellwise"),
        route,
        "≤ 5 ms",
        route.map(|v| v <= 5.0),
    );
    row(
        "route on 1.7 M cells (62 m), vs `pathfinding::astar`",
        get("route", "pathfinding"),
        route,
        "—",
        None,
    );
    let maps: Vec<String> = medians
        .keys()
        .filter_map(|(g, _)| g.strip_prefix("movingai/").map(str::to_owned))
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    for m in &maps {
        let group = format!("movingai/{m}");
        let (ours, theirs) = (get(&group, "rtnav"), get(&group, "pathfinding"));
        let r = ratio(theirs, ours);
        row(
            &format!("MovingAI {m} (a slice of its problems), vs `pathfinding::astar`"),
            theirs,
            ours,
            "≥ 4×",
            r.map(|r| r >= 4.0),
        );
    }
    s += "\n| wasm32 under Node (same harness) | native | wasm32 | wasm / native | goal | |\n";
    s += "| --- | --- | --- | --- | --- | --- |\n";
    for (op, name, goal) in [
        ("edit", "edit on 1.7 M cells", Some(2.0)),
        ("local_plan", "default local plan, 1.7 M cells", None),
        ("full_field", "full field, 1000×1000", None),
        ("route", "route on 1.7 M cells", None),
    ] {
        let (n, w) = (timed(native, op), timed(wasm32, op));
        let r = ratio(w, n);
        s += &format!(
            "| {name} | {} | {} | {} | {} | {} |\n",
            ms(n),
            ms(w),
            r.map_or_else(|| "—".to_owned(), |r| format!("{r:.2}")),
            goal.map_or_else(|| "—".to_owned(), |g| format!("≤ {g}×")),
            if goal.is_some() {
                verdict(r.zip(goal).map(|(r, g)| r <= g))
            } else {
                ""
            },
        );
    }
    s += "\n| page (Chromium, 1280×800) | worst frame | median frame | worst step + render | goal | |\n";
    s += "| --- | --- | --- | --- | --- | --- |\n";
    let rows = [
        (
            "painting on the 1.7 M-cell warehouse at 16×",
            frames.page,
            true,
        ),
        (
            "the same, steps without the frame budget (before, same run)",
            frames.unbudgeted,
            false,
        ),
    ];
    for (what, frame, goal) in rows {
        s += &format!(
            "| {what} | {} | {} | {} | {} | {} |\n",
            ms(frame.map(|f| f.0)),
            ms(frame.map(|f| f.1)),
            ms(frame.map(|f| f.2)),
            if goal { "worst ≤ 50 ms" } else { "—" },
            if goal {
                verdict(frame.map(|f| f.0 <= 50.0))
            } else {
                ""
            },
        );
    }
    s += "\n| first load (Chromium, cold cache, 10 Mbit/s, 40 ms) | map drawn (median) | fastest – slowest | requests | transferred | goal | |\n";
    s += "| --- | --- | --- | --- | --- | --- | --- |\n";
    for way in ["compressed", "plain"] {
        let load = frames.loads.iter().find(|l| l.way == way);
        let goal = way == "compressed";
        s += &format!(
            "| served {way} | {} | {} | {} | {} | {} | {} |\n",
            ms(load.map(|l| l.median_ms)),
            load.map_or_else(
                || "—".to_owned(),
                |l| format!("{:.0}–{:.0} ms", l.fastest_ms, l.slowest_ms)
            ),
            load.map_or_else(|| "—".to_owned(), |l| l.requests.to_string()),
            load.map_or_else(|| "—".to_owned(), |l| format!("{} KB", l.transferred_kb)),
            if goal { "≤ 1.5 s" } else { "—" },
            if goal {
                verdict(load.map(|l| l.median_ms <= 1500.0))
            } else {
                ""
            },
        );
    }
    s
}
