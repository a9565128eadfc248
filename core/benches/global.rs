//! GlobalPathPlanning's planner (spec §5) on every MovingAI benchmark map in the shared data
//! (`RTNAV_DATA`, else `../shared/data`; skipped with one line when it is not there), side by
//! side with the `pathfinding` crate's `astar` on the same grid and rules (8 moves, octile
//! costs, no corner cutting; `support/baseline.rs`).
//!
//! Criterion mode (default): for each map, one iteration solves a *stratified slice* of its
//! scenarios — every `N`-th problem, starting one further on each iteration, so every bucket
//! is represented and successive iterations walk through all of them (`N` grows with the
//! map's size and problem count). The ratio of the two lines is the speed-up.
//!
//! ```text
//! cargo bench -p rtnav --bench global -- --warm-up-time 1 --measurement-time 3
//! ```
//!
//! Full mode (`RTNAV_BENCH_FULL=1`): one pass over *every* scenario of every map with each
//! planner, checking that both find paths of the same length, and a table of total times.
//!
//! The benchmark is external data (`movingai/` of `$RTNAV_DATA`, else `../shared/data`):
//! without it this says on one line that it is skipped.

#[path = "support/baseline.rs"]
mod baseline;

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use criterion::Criterion;
use rtnav::global::AStar;
use rtnav::map::formats::movingai::{self, ScenProblem};

struct Case {
    name: String,
    slice: usize,
    astar: AStar,
    problems: Vec<ScenProblem>,
}

/// Every `.scen` of the MovingAI data with its map, sorted by name.
fn scen_files(data: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let Ok(sets) = std::fs::read_dir(data.join("movingai")) else {
        return out;
    };
    for set in sets.flatten() {
        for f in std::fs::read_dir(set.path())
            .into_iter()
            .flatten()
            .flatten()
        {
            let p = f.path();
            if p.extension().is_some_and(|e| e == "scen") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

fn load(data: &Path) -> Vec<Case> {
    scen_files(data)
        .iter()
        .map(|scen| {
            let map = movingai::load_map_file(scen.with_extension("")).expect("map");
            let problems = movingai::load_scen_file(scen).expect("scen");
            // About 2·10⁷ cell-problems per iteration: every problem of a small map, a slice
            // of a large one.
            let work = problems.len() as f64 * (map.width() * map.height()) as f64;
            let slice = (work / 2e7).ceil().max(1.0) as usize;
            let name = scen
                .file_name()
                .and_then(|n| n.to_str())
                .map_or_else(String::new, |n| n.trim_end_matches(".map.scen").to_owned());
            Case {
                name,
                slice,
                astar: AStar::new(&map, 0.0).expect("planner"),
                problems,
            }
        })
        .collect()
}

/// Our planner: the path length in cells.
fn ours(astar: &mut AStar, p: &ScenProblem) -> f64 {
    astar
        .plan(
            p.start_cell().expect("checked on reading"),
            p.goal_cell().expect("checked on reading"),
        )
        .expect("solvable")
        .length_cells()
}

/// `pathfinding::astar` with the same rules; the path length in cells.
fn theirs(grid: &AStar, p: &ScenProblem) -> f64 {
    baseline::pathfinding_astar(
        grid,
        p.start_cell().expect("checked on reading"),
        p.goal_cell().expect("checked on reading"),
    )
}

fn criterion_mode(cases: &mut [Case]) {
    let mut c = Criterion::default().configure_from_args();
    for case in cases.iter_mut() {
        let mut g = c.benchmark_group(format!("movingai/{}", case.name));
        g.sample_size(10);
        let n = case.slice;
        let mut offset = 0;
        let problems = &case.problems;
        let astar = &mut case.astar;
        g.bench_function("rtnav", |b| {
            b.iter(|| {
                offset = (offset + 1) % n;
                problems
                    .iter()
                    .skip(offset)
                    .step_by(n)
                    .map(|p| ours(astar, p))
                    .sum::<f64>()
            })
        });
        let mut offset = 0;
        let grid = &*astar;
        g.bench_function("pathfinding", |b| {
            b.iter(|| {
                offset = (offset + 1) % n;
                problems
                    .iter()
                    .skip(offset)
                    .step_by(n)
                    .map(|p| theirs(grid, p))
                    .sum::<f64>()
            })
        });
        g.finish();
    }
    c.final_summary();
}

fn full_mode(cases: &mut [Case]) {
    println!("| map | problems | rtnav | pathfinding::astar | ratio |");
    println!("| --- | --- | --- | --- | --- |");
    for case in cases.iter_mut() {
        let t = Instant::now();
        let a: Vec<f64> = case
            .problems
            .iter()
            .map(|p| ours(&mut case.astar, p))
            .collect();
        let ours_time = t.elapsed();
        let t = Instant::now();
        let b: Vec<f64> = case
            .problems
            .iter()
            .map(|p| theirs(&case.astar, p))
            .collect();
        let theirs_time = t.elapsed();
        for (i, (x, y)) in a.iter().zip(&b).enumerate() {
            assert!(
                (x - y).abs() <= 1e-6 * x.max(1.0),
                "{} #{i}: {x} vs {y}",
                case.name
            );
        }
        let secs = |d: Duration| format!("{:.1} ms", d.as_secs_f64() * 1e3);
        println!(
            "| {} | {} | {} | {} | {:.2} |",
            case.name,
            case.problems.len(),
            secs(ours_time),
            secs(theirs_time),
            theirs_time.as_secs_f64() / ours_time.as_secs_f64()
        );
    }
}

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let data = match rtnav::data::data_dir(&root) {
        Ok(dir) => dir,
        Err(why) => {
            let _ = writeln!(
                std::io::stderr(),
                "SKIPPED the global benchmark (movingai/*): {why}"
            );
            return;
        }
    };
    let mut cases = load(&data);
    if std::env::var_os("RTNAV_BENCH_FULL").is_some() {
        full_mode(&mut cases);
    } else {
        criterion_mode(&mut cases);
    }
}
