//! A* on the MovingAI benchmark maps (spec §5 "GlobalPathPlanning"), side by side with the
//! `pathfinding` crate's `astar` on the same grid and rules (8 moves, octile costs, no corner
//! cutting; its costs are integers, straight 2^32 and diagonal round(√2 · 2^32)).
//!
//! Criterion mode (default): for each map, one iteration solves a *stratified slice* of its
//! scenarios — every `N`-th problem, starting one further on each iteration, so every bucket
//! is represented and successive iterations walk through all of them. The time of a whole
//! map is `N ×` the reported time; the ratio of the two lines is the speed-up.
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

use std::hint::black_box;
use std::io::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

use criterion::Criterion;
use rtnav::global::AStar;
use rtnav::map::formats::movingai::{self, ScenProblem};

/// (map, slice: every N-th problem per criterion iteration).
const MAPS: [(&str, usize); 5] = [
    ("dao/arena", 1),
    ("dao/den312d", 1),
    ("mazes/maze512-1-0", 120),
    ("random/random512-10-0", 16),
    ("street/Berlin_0_256", 8),
];

const STRAIGHT: u64 = 1 << 32;
/// round(√2 · 2^32).
const DIAGONAL: u64 = 6_074_001_000;
const MOVES: [(i32, i32); 8] = [
    (1, 0),
    (0, 1),
    (-1, 0),
    (0, -1),
    (1, 1),
    (-1, 1),
    (-1, -1),
    (1, -1),
];

struct Case {
    name: String,
    slice: usize,
    astar: AStar,
    problems: Vec<ScenProblem>,
}

fn load(data: &Path) -> Vec<Case> {
    MAPS.iter()
        .map(|&(name, slice)| {
            let map = movingai::load_map_file(data.join(format!("{name}.map"))).expect("map");
            let problems =
                movingai::load_scen_file(data.join(format!("{name}.map.scen"))).expect("scen");
            Case {
                name: name.rsplit('/').next().unwrap_or(name).to_owned(),
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
        .plan(p.start_cell(), p.goal_cell())
        .expect("solvable")
        .length_cells()
}

/// `pathfinding::astar` with the same rules; the path length in cells.
fn theirs(grid: &AStar, p: &ScenProblem) -> f64 {
    let (s, t) = (p.start_cell(), p.goal_cell());
    let goal = (t.0 as i32, t.1 as i32);
    let free = |x: i32, y: i32| grid.is_passable(i64::from(x), i64::from(y));
    let (path, cost) = pathfinding::prelude::astar(
        &(s.0 as i32, s.1 as i32),
        |&(x, y)| {
            MOVES.iter().filter_map(move |&(dx, dy)| {
                let ok = free(x + dx, y + dy)
                    && (dx == 0 || dy == 0 || (free(x + dx, y) && free(x, y + dy)));
                ok.then(|| {
                    let c = if dx != 0 && dy != 0 {
                        DIAGONAL
                    } else {
                        STRAIGHT
                    };
                    ((x + dx, y + dy), c)
                })
            })
        },
        |&(x, y)| {
            let (dx, dy) = (x.abs_diff(goal.0), y.abs_diff(goal.1));
            u64::from(dx.abs_diff(dy)) * STRAIGHT + u64::from(dx.min(dy)) * DIAGONAL
        },
        |&c| c == goal,
    )
    .expect("solvable");
    black_box(path);
    cost as f64 / STRAIGHT as f64
}

fn criterion_mode(cases: &mut [Case]) {
    let mut c = Criterion::default().configure_from_args();
    for case in cases.iter_mut() {
        let mut g = c.benchmark_group(format!("astar/{} (1 in {})", case.name, case.slice));
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
        Ok(dir) => dir.join("movingai"),
        Err(why) => {
            let _ = writeln!(
                std::io::stderr(),
                "SKIPPED the global benchmark (astar/*): {why}"
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
