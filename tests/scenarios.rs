//! Every scenario of `fixtures/scenarios/` runs to its expected outcome (spec §0, §6), and its
//! trace hash — SHA-256 over every telemetry sample — equals the golden one in
//! `fixtures/golden/traces/`. The same tests run natively and compiled to wasm32 under Node,
//! so the golden hashes prove the two traces bit-identical.
//!
//! `UPDATE_GOLDEN=1 cargo test -p rtnav-tests --test scenarios` rewrites the golden hashes
//! (natively); look at the runs (`rtnav run … --png`) before you commit new ones.
//!
//! Each test also prints the run's real-time factor (simulated time / wall time of the run,
//! without loading the map), measured
//! with the host's clock (`Instant` natively, `Date.now()` in Node); it is reported, never
//! asserted. Build with `--release` for representative figures.
//!
//! `willow_garage` and `arena` drive on real maps of the external data (`$RTNAV_DATA`, else
//! `../shared/data`), read at run time on both targets; without the data they say on one
//! line that they are skipped.

use rtnav::interfaces::Pose;
use rtnav::map::Cell;
use rtnav::motion::angle_diff;
use rtnav::rtc::LifecycleState;
use rtnav::system::setup::{self, BuildOptions, Setup};
use rtnav::system::{
    EventKind, Input, OutcomeKind, Scenario, ScenarioReport, ScenarioRun, SystemEvent,
};
use rtnav_tests::data;
use rtnav_tests::fixtures::files;

macro_rules! scenario {
    ($name:literal) => {
        (
            $name,
            include_str!(concat!("../fixtures/scenarios/", $name, ".json")),
            include_str!(concat!("../fixtures/golden/traces/", $name, ".sha256")),
        )
    };
}

/// Prints a line: to stdout natively, to the console in Node (`--nocapture` shows both).
macro_rules! say {
    ($($t:tt)*) => {{
        #[cfg(not(target_arch = "wasm32"))]
        println!($($t)*);
        #[cfg(target_arch = "wasm32")]
        wasm_bindgen_test::console_log!($($t)*);
    }};
}

/// Wall-clock milliseconds, for the real-time factor only (never asserted).
#[cfg(not(target_arch = "wasm32"))]
fn now_ms() -> f64 {
    use std::sync::OnceLock;
    use std::time::Instant;
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_secs_f64() * 1e3
}

#[cfg(target_arch = "wasm32")]
fn now_ms() -> f64 {
    js_sys::Date::now()
}

/// A finished run: its report, events and telemetry.
struct Run {
    report: ScenarioReport,
    run: ScenarioRun,
}

impl Run {
    fn events(&self) -> Vec<SystemEvent> {
        self.run
            .system()
            .record()
            .events()
            .iter()
            .cloned()
            .collect()
    }
}

/// `report` with every number written exactly, for comparing two runs: `==` on the report
/// says a run that never reached its goal (NaN approach heading) differs from itself.
/// `Debug` writes each `f64` as its shortest round trip, so two numbers print alike
/// exactly when their bits are the same (a NaN as `NaN`, −0 as `-0.0`).
fn exactly(report: &ScenarioReport) -> String {
    format!("{report:?}")
}

/// Why a scenario of the repository always runs.
const IN_REPO: &str = "the scenario's map is in the repository";

/// Runs per scenario: in release builds three, to print the best real-time factor (the
/// first run in Node also pays for V8's tiering up); in debug builds one, to stay fast.
const RUNS: usize = if cfg!(debug_assertions) { 1 } else { 3 };

/// Runs the scenario, checks its expectation (and the rules every run keeps) and its golden
/// trace hash, prints the summary and the real-time factor. `None` (after one line saying
/// so) if the scenario needs the external data and there is none.
fn check((name, json, golden): (&str, &str, &str)) -> Option<Run> {
    let scenario = Scenario::from_json(json).unwrap();
    assert_eq!(
        scenario.name, name,
        "the file's name and the scenario's agree"
    );
    let files = match files(&scenario) {
        Ok(files) => files,
        Err(why) => {
            data::skip(&format!("scenario {name}"), &why);
            return None;
        }
    };
    let mut best = f64::INFINITY;
    let mut runs = Vec::new();
    for _ in 0..RUNS {
        let mut run = ScenarioRun::new(&scenario, &files).unwrap();
        let t0 = now_ms();
        run.run_to_end();
        best = best.min((now_ms() - t0) * 1e-3);
        runs.push(run);
    }
    let Some(run) = runs.pop() else {
        unreachable!("RUNS ≥ 1")
    };
    let report = run.report();
    for other in &runs {
        assert_eq!(
            exactly(&other.report()),
            exactly(&report),
            "{name}: every run the same"
        );
    }
    say!(
        "{name}: {:?} after {:.3} s simulated, {:.3} m, {} local plans, clearance {:.4} m; \
         wall {:.4} s, real-time factor {:.0}× (best of {RUNS})",
        report.outcome.kind,
        report.sim_time,
        report.path_length,
        report.replans,
        report.min_clearance,
        best,
        report.sim_time / best
    );
    if let Err(problems) = report.check(&scenario.expect) {
        panic!("{name}: {problems}\n{report}");
    }
    check_golden(name, golden, &report.trace_hash);
    Some(Run { report, run })
}

#[cfg(not(target_arch = "wasm32"))]
fn check_golden(name: &str, golden: &str, hash: &str) {
    if std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1") {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../fixtures/golden/traces")
            .join(format!("{name}.sha256"));
        std::fs::write(&path, format!("{hash}\n")).unwrap();
        println!("{name}: golden trace hash written to {}", path.display());
        return;
    }
    assert_eq!(
        hash,
        golden.trim(),
        "{name}: the trace differs from the golden one (UPDATE_GOLDEN=1 to refresh it)"
    );
}

#[cfg(target_arch = "wasm32")]
fn check_golden(name: &str, golden: &str, hash: &str) {
    assert_eq!(
        hash,
        golden.trim(),
        "{name}: the wasm32 trace differs from the golden (native) one"
    );
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn open_field_arrives() {
    check(scenario!("open_field")).expect(IN_REPO);
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn corridor_turn_arrives() {
    let r = check(scenario!("corridor_turn")).expect(IN_REPO);
    // It went round the corner: up the east corridor after the south one.
    assert!(r.report.path_length > 25.0, "{}", r.report.path_length);
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn parking_wall_arrives_parallel_to_the_wall() {
    let r = check(scenario!("parking_wall")).expect(IN_REPO);
    // Posture: parallel to the wall (heading 0), within a few degrees.
    assert!(
        r.report.heading_error_deg < 2.0,
        "{}",
        r.report.heading_error_deg
    );
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn appearing_obstacle_is_avoided_after_a_replan() {
    let r = check(scenario!("appearing_obstacle")).expect(IN_REPO);
    let events = r.events();
    let system = r.run.system();
    // The timeline counts from the start of the drive: the physics' activation.
    let drive = events
        .iter()
        .find(|e| {
            matches!(&e.kind, EventKind::StateChanged { component, to: LifecycleState::Active, .. }
                if component == "PhysicsSim0")
        })
        .expect("the drive starts")
        .time_ns;
    let update = events
        .iter()
        .find(|e| matches!(e.kind, EventKind::MapUpdated { changed, .. } if changed > 0))
        .expect("the trolley appears");
    assert_eq!(
        update.time_ns - drive,
        6_000_000_000,
        "at the scenario's time"
    );
    assert!(
        events.iter().any(|e| e.time_ns > update.time_ns
            && matches!(e.kind, EventKind::LocalPlanSent { replanned: true, cells, .. } if cells > 0)),
        "a local plan around the trolley is sent after it appears"
    );
    // The route planned before the trolley appeared ran through it: avoiding it needed a
    // replan.
    let scenario = r.run.scenario();
    let Input::MapUpdate { cells: trolley } = scenario.events[0].to_input(system.map()) else {
        panic!("the scenario's event is the trolley's MapUpdate");
    };
    let crosses = |route: &[Cell]| {
        route.iter().any(|c| {
            trolley
                .iter()
                .any(|t| (t.0, t.1) == (c.0 as i64, c.1 as i64))
        })
    };
    let set_up = setup::build(
        scenario,
        &files(scenario).expect(IN_REPO),
        &Setup::of(scenario),
        BuildOptions::default(),
    )
    .unwrap();
    assert!(
        crosses(set_up.mission().route()),
        "the first global route crosses the trolley's cells"
    );
    // Spec §5 Decision 0.2: GlobalPathPlanning plans again when an update blocks its route,
    // so the route held beyond the local target no longer runs through the trolley.
    assert!(events.iter().any(|e| e.time_ns >= update.time_ns
        && matches!(&e.kind, EventKind::GlobalPlan { reason, .. } if reason == "MapChanged")));
    assert!(!crosses(system.mission().route()));
    // The robot passed it on the north side, its body clear of the trolley (y ≤ 4.3 m).
    let beside: Vec<_> = system
        .record()
        .trail()
        .iter()
        .filter(|p| (12.0..=12.8).contains(&p.0))
        .collect();
    assert!(!beside.is_empty());
    for p in beside {
        assert!(
            p.1 - r.report.body_radius > 4.3,
            "beside the trolley at {p:?}"
        );
    }
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn backward_dock_reverses_in_without_turning() {
    let r = check(scenario!("backward_dock")).expect(IN_REPO);
    let samples = r.run.system().record().telemetry().samples();
    assert_eq!(samples.len() as u64, r.report.samples, "every sample kept");
    assert!(
        samples.iter().all(|s| s.v_cmd <= 0.0),
        "never commanded forward"
    );
    assert!(samples.iter().any(|s| s.v_cmd < -0.1), "reversed");
    let facing_out = core::f64::consts::PI;
    let worst = samples
        .iter()
        .map(|s| angle_diff(s.pose.theta, facing_out).abs().to_degrees())
        .fold(0.0, f64::max);
    assert!(worst < 10.0, "it never turned around: {worst}°");
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn unreachable_goal_fails_to_plan_and_the_robot_stands_still() {
    let r = check(scenario!("unreachable")).expect(IN_REPO);
    let failures: Vec<_> = r
        .events()
        .into_iter()
        .filter_map(|e| match e.kind {
            EventKind::PlanningFailed { planner, reason } => Some((planner, reason)),
            _ => None,
        })
        .collect();
    assert_eq!(failures.len(), 1, "{failures:?}");
    assert_eq!(failures[0].0, "GlobalPathPlanning");
    assert!(
        failures[0].1.to_string().starts_with("no path"),
        "{}",
        failures[0].1
    );
    assert_eq!(r.report.path_length, 0.0);
    let start = Pose::new(1.5, 1.5, 0.0);
    assert_eq!(r.report.final_pose, start, "the robot did not move at all");
    let samples = r.run.system().record().telemetry().samples();
    assert!(
        samples
            .iter()
            .all(|s| s.v == 0.0 && s.w == 0.0 && s.torque == [0.0; 2])
    );
    assert_eq!(r.report.outcome.kind, OutcomeKind::PlanningFailed);
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn willow_garage_drives_through_the_building() {
    let Some(r) = check(scenario!("willow_garage")) else {
        return;
    };
    assert!(r.report.path_length > 35.0, "{}", r.report.path_length);
}

#[cfg_attr(not(target_arch = "wasm32"), test)]
#[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
fn arena_from_movingai_arrives() {
    let Some(r) = check(scenario!("arena")) else {
        return;
    };
    let map = r.run.system().map().unwrap();
    assert_eq!((map.width(), map.height(), map.grid_size()), (49, 49, 0.5));
}
