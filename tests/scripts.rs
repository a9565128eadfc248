//! Components a student writes (spec §8), natively and compiled to wasm32 under Node: the
//! reference scripts of `fixtures/scripts/`.
//!
//! - MotorControl's PD law as a script gives **the golden trace** — the built-in
//!   MotorControl's, bit for bit — on every fixture scenario that arrives: the script sees the
//!   real ports, ticks and reflection timing, and its math is the core's (`libm`). On both
//!   targets, so the two traces are the same too.
//! - A DriveControl written as a script arrives in open_field, corridor_turn and
//!   parking_wall.

use rtnav::system::{OutcomeKind, Scenario, ScenarioRun, ScriptText, Setup};
use rtnav_tests::data;
use rtnav_tests::fixtures::files;

const PD: &str = include_str!("../fixtures/scripts/motor_control_pd.rhai");
const DRIVE: &str = include_str!("../fixtures/scripts/drive_control_pursuit.rhai");

macro_rules! scenario {
    ($name:literal) => {
        (
            include_str!(concat!("../fixtures/scenarios/", $name, ".json")),
            include_str!(concat!("../fixtures/golden/traces/", $name, ".sha256")),
        )
    };
}

/// Runs `json`'s scenario with `script` in `component`'s place; `None` (after one line
/// saying so) without the external data it needs.
fn run(json: &str, component: &str, name: &str, script: &str) -> Option<ScenarioRun> {
    let scenario = Scenario::from_json(json).unwrap();
    let files = match files(&scenario) {
        Ok(f) => f,
        Err(why) => {
            data::skip(&format!("scenario {} with a script", scenario.name), &why);
            return None;
        }
    };
    let mut setup = Setup::of(&scenario);
    setup.scripts.insert(
        component.to_owned(),
        ScriptText {
            name: name.to_owned(),
            source: script.to_owned(),
        },
    );
    let mut run = ScenarioRun::with_setup(&scenario, &files, &setup).unwrap();
    run.run_to_end();
    Some(run)
}

fn pd_gives_the_golden_trace((json, golden): (&str, &str)) {
    let Some(run) = run(json, "MotorControl", "motor_control_pd.rhai", PD) else {
        return;
    };
    let report = run.report();
    assert_eq!(report.outcome.kind, OutcomeKind::Arrived, "{report}");
    assert_eq!(
        report.trace_hash,
        golden.trim(),
        "{}: the PD script's trace differs from the built-in MotorControl's",
        run.scenario().name
    );
}

macro_rules! pd_test {
    ($($test:ident: $name:literal),* $(,)?) => {$(
        #[cfg_attr(not(target_arch = "wasm32"), test)]
        #[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
        fn $test() {
            pd_gives_the_golden_trace(scenario!($name));
        }
    )*};
}

pd_test!(
    pd_script_open_field: "open_field",
    pd_script_corridor_turn: "corridor_turn",
    pd_script_parking_wall: "parking_wall",
    pd_script_appearing_obstacle: "appearing_obstacle",
    pd_script_backward_dock: "backward_dock",
    pd_script_willow_garage: "willow_garage",
    pd_script_arena: "arena",
);

fn drive_script_arrives(json: &str) {
    let Some(run) = run(json, "DriveControl", "drive_control_pursuit.rhai", DRIVE) else {
        return;
    };
    let report = run.report();
    assert_eq!(report.outcome.kind, OutcomeKind::Arrived, "{report}");
    assert!(report.bumps == 0, "{report}");
}

macro_rules! drive_test {
    ($($test:ident: $name:literal),* $(,)?) => {$(
        #[cfg_attr(not(target_arch = "wasm32"), test)]
        #[cfg_attr(target_arch = "wasm32", wasm_bindgen_test::wasm_bindgen_test)]
        fn $test() {
            drive_script_arrives(scenario!($name).0);
        }
    )*};
}

drive_test!(
    drive_script_open_field: "open_field",
    drive_script_corridor_turn: "corridor_turn",
    drive_script_parking_wall: "parking_wall",
);
