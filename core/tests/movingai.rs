//! spec §5 "GlobalPathPlanning": A* is optimal on the MovingAI grid benchmark
//! (`movingai/` of the external data folder — `$RTNAV_DATA`, else `../shared/data`; skipped
//! with a line when absent — Sturtevant 2012, ODC-BY): for every problem of every `.scen`
//! file, the path length equals the published optimal length (relative 1e-4) and the path is
//! valid (start and goal right, 8-adjacent steps, no blocked cell, no corner cut).
//! (The readers' edge cases are in `map_formats.rs`.)

use std::io::Write as _;
use std::path::{Path, PathBuf};

use rtnav::global::AStar;
use rtnav::map::formats::movingai::{self, ScenProblem};

/// The benchmark's folder, or `None` after one line saying `test` is skipped.
fn benchmark(test: &str) -> Option<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    match rtnav::data::data_dir(&root) {
        Ok(dir) => Some(dir.join("movingai")),
        Err(why) => {
            let _ = writeln!(std::io::stderr(), "SKIPPED {test}: {why}");
            None
        }
    }
}

fn scen_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for set in std::fs::read_dir(dir).unwrap() {
        for f in std::fs::read_dir(set.unwrap().path()).unwrap() {
            let p = f.unwrap().path();
            if p.extension().is_some_and(|e| e == "scen") {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The `.map` beside a `.scen` (`x.map.scen` → `x.map`).
fn map_of(scen: &Path) -> PathBuf {
    scen.with_extension("")
}

fn check_problem(astar: &mut AStar, p: &ScenProblem, what: &str) {
    let (s, g) = (p.start_cell().unwrap(), p.goal_cell().unwrap());
    let plan = astar.plan(s, g).unwrap_or_else(|e| panic!("{what}: {e}"));
    let len = plan.length_cells();
    let tol = 1e-4 * p.optimal_length.max(1.0);
    assert!(
        (len - p.optimal_length).abs() <= tol,
        "{what}: length {len}, optimal {}",
        p.optimal_length
    );
    assert_eq!(plan.cells.first(), Some(&s), "{what}: start");
    assert_eq!(plan.cells.last(), Some(&g), "{what}: goal");
    let (mut straight, mut diagonal) = (0u32, 0u32);
    for w in plan.cells.windows(2) {
        assert!(
            astar.step_allowed(w[0], w[1]),
            "{what}: illegal step {:?} → {:?}",
            w[0],
            w[1]
        );
        if w[0].0 != w[1].0 && w[0].1 != w[1].1 {
            diagonal += 1;
        } else {
            straight += 1;
        }
    }
    assert_eq!(
        (straight, diagonal),
        (plan.cost.straight, plan.cost.diagonal),
        "{what}"
    );
}

#[test]
fn every_scenario_is_solved_optimally_with_a_valid_path() {
    let Some(dir) = benchmark("A* on the MovingAI benchmark") else {
        return;
    };
    let files = scen_files(&dir);
    assert_eq!(files.len(), 5, "{files:?}");
    // The problems of a map are independent: split them over the available cores (each
    // thread with its own planner), so this test takes its share of a small machine only.
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get().min(4));
    let mut total = 0;
    for scen in &files {
        let map = movingai::load_map_file(map_of(scen)).unwrap();
        let problems = movingai::load_scen_file(scen).unwrap();
        let astar = AStar::new(&map, 0.0).unwrap();
        let chunk = problems.len().div_ceil(threads);
        std::thread::scope(|s| {
            for (c, part) in problems.chunks(chunk).enumerate() {
                let mut astar = astar.clone();
                let name = scen.display().to_string();
                s.spawn(move || {
                    for (i, p) in part.iter().enumerate() {
                        assert_eq!((p.map_width, p.map_height), (astar.width(), astar.height()));
                        check_problem(&mut astar, p, &format!("{name} #{}", c * chunk + i));
                    }
                });
            }
        });
        total += problems.len();
    }
    // The data README's table: 160 + 320 + 11960 + 1670 + 930 problems.
    assert_eq!(total, 15040);
}
