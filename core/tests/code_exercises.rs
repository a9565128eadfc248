//! Exercises with code (spec §8): each has a template the student starts from, a
//! reference solution that passes, and wrong answers that fail for the reason its lesson
//! names (`fixtures/scripts/exercises/NAME.{template,solution,wrong_*}.rhai`).

mod common;

use std::collections::BTreeMap;

use rtnav::system::{Check, CheckState, ExerciseRun, ExerciseStatus, ScriptText, Verdict};

fn check(name: &str, file: Option<&str>) -> ExerciseStatus {
    let (scenario, files) = common::scenario(name);
    let task = scenario.exercise.as_ref().unwrap().script.clone().unwrap();
    let mut scripts = BTreeMap::new();
    if let Some(file) = file {
        let path = format!("fixtures/scripts/exercises/{file}");
        scripts.insert(
            task.component.name().to_owned(),
            ScriptText {
                name: file.to_owned(),
                source: std::fs::read_to_string(common::root().join(path)).unwrap(),
            },
        );
    }
    ExerciseRun::with_scripts(&scenario, &files, &scripts, None, &[])
        .unwrap()
        .run_to_end()
}

fn state(status: &ExerciseStatus, which: fn(&Check) -> bool) -> CheckState {
    status
        .checks
        .iter()
        .find(|c| which(&c.check))
        .map(|c| c.state)
        .unwrap()
}

fn passed(status: &ExerciseStatus) -> bool {
    status.verdict == Verdict::Passed
}

/// Each wrong answer fails the check its lesson names; the template (nothing written
/// yet) fails too; the reference solution and the built-in component pass.
#[test]
fn write_motor_controls_pd_law() {
    let name = "ex_code_pd";
    assert!(passed(&check(name, None)), "the built-in passes");
    assert!(passed(&check(name, Some("ex_code_pd.solution.rhai"))));
    let reach = |c: &Check| matches!(c, Check::ReachSpeed { .. });
    // Positive feedback: the wheels run away and the robot hits the fence at once.
    let sign = check(name, Some("ex_code_pd.wrong_sign.rhai"));
    assert_eq!(state(&sign, reach), CheckState::Failed, "{sign}");
    assert_eq!(
        state(&sign, |c| matches!(c, Check::NoBump)),
        CheckState::Failed
    );
    // P alone: limp, the speed is never reached.
    let limp = check(name, Some("ex_code_pd.wrong_no_d.rhai"));
    assert_eq!(state(&limp, reach), CheckState::Failed, "{limp}");
    assert!(!passed(&check(name, Some("ex_code_pd.template.rhai"))));
}

#[test]
fn write_a_drive_control_that_stops_at_the_goal() {
    let name = "ex_code_drive";
    assert!(passed(&check(name, None)));
    assert!(passed(&check(name, Some("ex_code_drive.solution.rhai"))));
    let arrived = |c: &Check| matches!(c, Check::Arrived { .. });
    let heading = |c: &Check| matches!(c, Check::ArrivalHeading { .. });
    let past = check(name, Some("ex_code_drive.wrong_no_stop.rhai"));
    assert_eq!(state(&past, arrived), CheckState::Failed, "{past}");
    let facing = check(name, Some("ex_code_drive.wrong_no_heading.rhai"));
    assert_eq!(state(&facing, arrived), CheckState::Passed, "{facing}");
    assert_eq!(state(&facing, heading), CheckState::Failed, "{facing}");
    assert!(!passed(&check(name, Some("ex_code_drive.template.rhai"))));
}

#[test]
fn make_a_component_recover() {
    let name = "ex_code_recover";
    assert!(passed(&check(name, None)));
    assert!(passed(&check(name, Some("ex_code_recover.solution.rhai"))));
    let recovered = |c: &Check| matches!(c, Check::Recovered);
    let overshoot = |c: &Check| matches!(c, Check::MaxOvershoot { .. });
    // on_reset fails: Reset leaves MotorControl in Error.
    let stuck = check(name, Some("ex_code_recover.wrong_reset_fails.rhai"));
    assert_eq!(state(&stuck, recovered), CheckState::Failed, "{stuck}");
    // No zero torque on the way to Error: the robot runs on, faster than it may.
    let runs_on = check(name, Some("ex_code_recover.wrong_no_safe_torque.rhai"));
    assert_eq!(state(&runs_on, recovered), CheckState::Passed, "{runs_on}");
    assert_eq!(state(&runs_on, overshoot), CheckState::Failed, "{runs_on}");
    assert!(!passed(&check(name, Some("ex_code_recover.template.rhai"))));
}
