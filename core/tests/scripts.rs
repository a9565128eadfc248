//! Components a student writes (spec §8, Decisions 0.4), natively: loading, the lifecycle,
//! every broken reference script's exact error, and the PD script's trace equal to the
//! built-in MotorControl's on every fixture scenario that arrives. (`tests/scripts.rs` of
//! rtnav-tests runs the golden scenarios with the scripts in wasm too.)

mod common;

use std::collections::BTreeMap;

use rtnav::Error;
use rtnav::errors::LifecycleError;
use rtnav::rtc::{LifecycleState, Request};
use rtnav::script::ScriptError;
use rtnav::system::{
    ComponentActivity, ComponentKind, EventKind, Input, OutcomeKind, ScenarioRun, ScriptText,
    Setup, System,
};

fn script(name: &str) -> String {
    std::fs::read_to_string(common::root().join("fixtures/scripts").join(name)).unwrap()
}

fn with_scripts(scenario: &str, scripts: &[(&str, &str)]) -> ScenarioRun {
    let (s, files) = common::scenario(scenario);
    let mut setup = Setup::of(&s);
    for (component, name) in scripts {
        setup.scripts.insert(
            (*component).to_owned(),
            ScriptText {
                name: (*name).to_owned(),
                source: script(name),
            },
        );
    }
    ScenarioRun::with_setup(&s, &files, &setup).unwrap()
}

/// What a refused request must leave as it was.
fn snapshot(system: &System) -> String {
    let w = system.wiring();
    let states: Vec<_> = ComponentKind::ALL
        .iter()
        .map(|&k| (k, w.component_state(k), w.is_scripted(k)))
        .collect();
    format!(
        "{states:?} {} {} {:?}",
        system.record().telemetry().trace_hash(),
        system.record().events().len(),
        w.to_conf()
    )
}

fn load(component: ComponentKind, name: &str) -> Input {
    Input::LoadScript {
        component,
        name: name.to_owned(),
        source: script(name),
    }
}

/// Runs until MotorControl is in Error (at most 30 s) and returns its script's error.
fn error_of(name: &str) -> (ScriptError, u64) {
    let mut run = with_scripts("open_field", &[("MotorControl", name)]);
    for _ in 0..30_000 {
        run.advance(1);
        let w = run.system().wiring();
        if w.component_state(ComponentKind::MotorControl) == LifecycleState::Error {
            let e = w
                .script(ComponentKind::MotorControl)
                .and_then(|s| s.last_error())
                .cloned()
                .expect("the script's error is kept");
            return (e, run.system().time_ns());
        }
    }
    panic!("{name}: MotorControl never went to Error");
}

#[test]
fn a_syntax_error_refuses_the_load_and_nothing_changes() {
    let mut run = with_scripts("open_field", &[]);
    let before = snapshot(run.system());
    let e = run
        .apply(&load(ComponentKind::MotorControl, "broken_syntax.rhai"))
        .unwrap_err();
    let Error::Script(ScriptError::Syntax {
        line,
        column,
        message,
    }) = &e
    else {
        panic!("{e:?}");
    };
    assert_eq!((*line, *column), (7, 9), "{message}");
    assert_eq!(snapshot(run.system()), before);
}

#[test]
fn loading_into_an_active_component_is_refused_and_nothing_changes() {
    let mut run = with_scripts("open_field", &[]);
    run.advance(500);
    let before = snapshot(run.system());
    let e = run
        .apply(&load(ComponentKind::MotorControl, "motor_control_pd.rhai"))
        .unwrap_err();
    assert_eq!(
        e,
        Error::Lifecycle(LifecycleError::InvalidTransition {
            component: "MotorControl0".into(),
            from: LifecycleState::Active,
            request: Request::Replace,
        })
    );
    assert_eq!(snapshot(run.system()), before);
    // Nor into a place no script can take, nor with another component's declaration.
    let e = run
        .apply(&load(
            ComponentKind::LocalPathPlanning,
            "motor_control_pd.rhai",
        ))
        .unwrap_err();
    assert!(
        e.to_string()
            .contains("cannot stand in for LocalPathPlanning"),
        "{e}"
    );
    assert_eq!(snapshot(run.system()), before);
}

#[test]
fn a_script_of_another_component_is_refused() {
    let mut run = with_scripts("open_field", &[]);
    run.apply(&Input::DeactivateAll).unwrap();
    let before = snapshot(run.system());
    let e = run
        .apply(&load(ComponentKind::DriveControl, "motor_control_pd.rhai"))
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "the script declares `COMPONENT = \"MotorControl\"`, not DriveControl"
    );
    assert_eq!(snapshot(run.system()), before);
}

#[test]
fn each_broken_script_fails_with_its_exact_error() {
    let cases: [(&str, ScriptError); 4] = [
        (
            "broken_runtime_error.rhai",
            ScriptError::Runtime {
                action: "on_execute".into(),
                line: 13,
                column: 37,
                message: "index 2 is outside the array, which has 2 items".into(),
            },
        ),
        (
            "broken_endless_loop.rhai",
            ScriptError::Bound {
                action: "on_execute".into(),
                line: 8,
                column: 15,
                message: "ran past its budget of 200000 operations — an endless loop? Every \
                          action must end within its budget"
                    .into(),
            },
        ),
        (
            "broken_wrong_type.rhai",
            ScriptError::Runtime {
                action: "on_execute".into(),
                line: 6,
                column: 16,
                message: "`write()` on `torque` (TimedDoubleSeq): the field `data` must be an \
                          array of numbers, not a string"
                    .into(),
            },
        ),
        (
            "broken_missing_port.rhai",
            ScriptError::Runtime {
                action: "on_execute".into(),
                line: 6,
                column: 11,
                message: "the component has no port `in_wheel_angle` (its in-ports: \
                          target_velocity, in_current_wheel_angle, in_simulated_position; its \
                          out-ports: torque, out_current_wheel_angle, \
                          out_simulated_position_to_invent_gui, \
                          out_simulated_position_to_localization; and rtc.time, rtc.period, \
                          rtc.tm, rtc.index, rtc.param(\"name\"))"
                    .into(),
            },
        ),
    ];
    for (name, expected) in cases {
        let (e, _) = error_of(name);
        assert_eq!(e, expected, "{name}: {e}");
    }
    // The runtime error comes at the 100th execution: MotorControl runs every tick from the
    // drive's start.
    let (_, at) = error_of("broken_runtime_error.rhai");
    let run = with_scripts("open_field", &[]);
    assert_eq!(at - run.system().time_ns(), 100 * 1_000_000);
}

#[test]
fn the_card_and_the_graph_say_a_script_runs_and_the_built_in_comes_back() {
    let mut run = with_scripts("open_field", &[("MotorControl", "motor_control_pd.rhai")]);
    run.advance(100);
    let system = run.system();
    let card = ComponentActivity::of(
        system.wiring(),
        &system.record().stats(),
        ComponentKind::MotorControl,
    );
    assert_eq!(
        card,
        ComponentActivity::Script {
            script: "motor_control_pd.rhai".into(),
            active: true
        }
    );
    let graph = system.wiring().graph();
    let motor = graph
        .components
        .iter()
        .find(|c| c.name == "MotorControl")
        .unwrap();
    assert_eq!(motor.script.as_deref(), Some("motor_control_pd.rhai"));
    assert!(system.record().events().iter().any(|e| matches!(
        &e.kind,
        EventKind::ScriptLoaded { component, script } if component == "MotorControl0" && script == "motor_control_pd.rhai"
    )));
    // One request puts the built-in back, once the component is not Active.
    run.apply(&Input::Deactivate {
        component: ComponentKind::MotorControl,
    })
    .unwrap();
    run.apply(&Input::UseBuiltIn {
        component: ComponentKind::MotorControl,
    })
    .unwrap();
    assert!(run.system().wiring().motor_control().is_some());
    run.apply(&Input::Activate {
        component: ComponentKind::MotorControl,
    })
    .unwrap();
    let report = {
        run.run_to_end();
        run.report()
    };
    assert_eq!(report.outcome.kind, OutcomeKind::Arrived, "{report}");
}

#[test]
fn error_and_reset_take_the_lifecycle_path_with_the_scripts_actions() {
    let source = r#"
        const COMPONENT = "MotorControl";
        fn on_initialize() { this.errors = 0; this.resets = 0; }
        fn on_error(rtc) { this.errors += 1; }
        fn on_reset(rtc) { this.resets += 1; print(`reset after ${this.errors} periods in Error`); }
        fn on_execute(rtc) { if rtc.time > 1.0 && this.resets == 0 { throw "stuck wheel"; } }
    "#;
    let mut run = with_scripts("open_field", &[]);
    run.apply(&Input::DeactivateAll).unwrap();
    run.apply(&Input::LoadScript {
        component: ComponentKind::MotorControl,
        name: "recover.rhai".into(),
        source: source.into(),
    })
    .unwrap();
    run.apply(&Input::ActivateAll).unwrap();
    run.advance(2_000);
    let w = run.system().wiring();
    assert_eq!(
        w.component_state(ComponentKind::MotorControl),
        LifecycleState::Error
    );
    let e = w
        .script(ComponentKind::MotorControl)
        .unwrap()
        .last_error()
        .unwrap();
    assert_eq!(e.message(), "the script threw stuck wheel");
    assert_eq!(e.position(), Some((6, 70)), "at `throw`");
    run.apply(&Input::Reset {
        component: ComponentKind::MotorControl,
    })
    .unwrap();
    let w = run.system().wiring();
    assert_eq!(
        w.component_state(ComponentKind::MotorControl),
        LifecycleState::Inactive
    );
    let script = w.script(ComponentKind::MotorControl).unwrap();
    let printed: Vec<_> = script.console().lines().map(|l| l.text.clone()).collect();
    assert!(
        printed
            .iter()
            .any(|l| l.starts_with("reset after ") && l.ends_with(" periods in Error")),
        "{printed:?}"
    );
}

/// Every fixture scenario whose run with the built-in MotorControl arrives gives the same
/// trace with MotorControl's PD law as a script, bit for bit.
#[test]
fn the_pd_script_gives_the_built_in_trace_on_every_fixture_scenario_that_arrives() {
    let mut compared = BTreeMap::new();
    let mut expected = Vec::new();
    let dir = common::root().join("fixtures/scenarios");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            name.strip_suffix(".json").map(str::to_owned)
        })
        .collect();
    names.sort();
    for name in names {
        let json = std::fs::read_to_string(dir.join(format!("{name}.json"))).unwrap();
        if !json.contains("fixtures/maps/") {
            // willow_garage and arena (the external data): rtnav-tests' `scripts` test.
            continue;
        }
        if rtnav::system::Scenario::from_json(&json)
            .unwrap()
            .expect
            .outcome
            == OutcomeKind::Arrived
        {
            expected.push(name.clone());
        }
        let mut built_in = with_scripts(&name, &[]);
        built_in.run_to_end();
        let built_in = built_in.report();
        if built_in.outcome.kind != OutcomeKind::Arrived {
            continue;
        }
        let mut scripted = with_scripts(&name, &[("MotorControl", "motor_control_pd.rhai")]);
        scripted.run_to_end();
        let scripted = scripted.report();
        assert_eq!(scripted.trace_hash, built_in.trace_hash, "{name}");
        compared.insert(name, built_in.trace_hash);
    }
    // Every one in the repository that is to arrive did (willow_garage and arena: in
    // rtnav-tests).
    assert_eq!(compared.keys().cloned().collect::<Vec<_>>(), expected);
}
