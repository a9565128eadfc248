//! Every exercise (`fixtures/scenarios/ex_*.json`) done headlessly as `rtnav check` does it
//! ([`check_exercise`]): its reference solution (`fixtures/exercises/NAME.solution.conf`, or
//! timed requests for seed 003's) passes every check, and a wrong one
//! (`NAME.wrong.conf`, or nothing done) fails — with the check that should fail named.

use rtnav::data::RepoResolver;
use rtnav::system::{
    Check, CheckState, ComponentKind, DriveInput, ExerciseStatus, Input, Scenario, Verdict,
    check_exercise,
};

const EXERCISES: [&str; 9] = [
    "ex_parking_posture",
    "ex_route_remake",
    "ex_door_dmin",
    "ex_corner_deviation",
    "ex_backward_dock",
    "ex_pd_gains",
    "ex_model_offset",
    "ex_fault_recovery",
    "ex_speed_limit",
];

fn scenario(name: &str) -> Scenario {
    let path = format!("../fixtures/scenarios/{name}.json");
    Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn conf(file: &str) -> String {
    std::fs::read_to_string(format!("../fixtures/exercises/{file}")).unwrap()
}

fn check(name: &str, conf: Option<&str>, inputs: &[DriveInput]) -> ExerciseStatus {
    check_exercise(&scenario(name), &RepoResolver::new(".."), conf, inputs).unwrap()
}

fn passed(name: &str, status: &ExerciseStatus) {
    assert_eq!(status.verdict, Verdict::Passed, "{name}:\n{status}");
    assert!(
        status.checks.iter().all(|c| c.state == CheckState::Passed),
        "{name}:\n{status}"
    );
}

/// Failed, and `which` among the failed checks.
fn failed(name: &str, status: &ExerciseStatus, which: fn(&Check) -> bool) {
    assert_eq!(status.verdict, Verdict::Failed, "{name}:\n{status}");
    assert!(
        status
            .checks
            .iter()
            .any(|c| c.state == CheckState::Failed && which(&c.check)),
        "{name}: the expected check did not fail:\n{status}"
    );
}

#[test]
fn every_exercise_names_its_seed_and_is_listed() {
    for name in EXERCISES {
        let s = scenario(name);
        let e = s.exercise.as_ref().unwrap();
        assert!(!e.task.is_empty() && !e.checks.is_empty(), "{name}");
        assert!(s.description.contains("(seed 00"), "{name}: names its seed");
    }
    // Every exercise fixture is listed here.
    let mut on_disk: Vec<String> = std::fs::read_dir("../fixtures/scenarios")
        .unwrap()
        .filter_map(|e| {
            let n = e.unwrap().file_name().into_string().unwrap();
            n.strip_prefix("ex_")
                .map(|r| format!("ex_{}", r.trim_end_matches(".json")))
        })
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = EXERCISES.iter().map(|s| s.to_string()).collect();
    listed.sort();
    assert_eq!(on_disk, listed);
}

macro_rules! conf_exercise {
    ($test:ident, $name:literal, $which:pat) => {
        #[test]
        fn $test() {
            let ok = check($name, Some(&conf(concat!($name, ".solution.conf"))), &[]);
            passed($name, &ok);
            let wrong = check($name, Some(&conf(concat!($name, ".wrong.conf"))), &[]);
            failed($name, &wrong, |c| matches!(c, $which));
            // As the scenario stands, nothing changed: not done yet.
            let untouched = check($name, None, &[]);
            assert_eq!(
                untouched.verdict,
                Verdict::Failed,
                "{}:\n{untouched}",
                $name
            );
        }
    };
}

conf_exercise!(
    parking_posture,
    "ex_parking_posture",
    Check::ApproachHeading { .. }
);
conf_exercise!(route_remake, "ex_route_remake", Check::Arrived { .. });
conf_exercise!(door_dmin, "ex_door_dmin", Check::Arrived { .. });
conf_exercise!(
    corner_deviation,
    "ex_corner_deviation",
    Check::MaxReplans { .. }
);
conf_exercise!(
    backward_dock,
    "ex_backward_dock",
    Check::BackwardDistance { .. }
);
conf_exercise!(pd_gains, "ex_pd_gains", Check::MaxOvershoot { .. });
conf_exercise!(speed_limit, "ex_speed_limit", Check::MaxOvershoot { .. });
conf_exercise!(model_offset, "ex_model_offset", Check::Arrived { .. });

#[test]
fn fault_recovery_with_reset_and_activate() {
    let name = "ex_fault_recovery";
    let reset_activate = |at: f64| {
        vec![
            DriveInput {
                at,
                input: Input::Reset {
                    component: ComponentKind::DriveControl,
                },
            },
            DriveInput {
                at,
                input: Input::Activate {
                    component: ComponentKind::DriveControl,
                },
            },
        ]
    };
    passed(name, &check(name, None, &reset_activate(10.0)));
    // At a student's pace: Reset 12 s after the fault, Activate a second later. The robot
    // coasted meanwhile (zero torque), so it arrives later than after a prompt recovery,
    // but within the time the task gives.
    let at_a_students_pace = |reset: f64| {
        let mut inputs = reset_activate(reset);
        inputs[1].at += 1.0;
        inputs
    };
    passed(name, &check(name, None, &at_a_students_pace(20.0)));
    // Waiting 40 s is too late: the robot arrives, but not within the task's time.
    failed(name, &check(name, None, &at_a_students_pace(48.0)), |c| {
        matches!(c, Check::Arrived { .. })
    });
    // Reset alone leaves DriveControl Inactive: the robot never moves again.
    let reset_only = &reset_activate(10.0)[..1];
    failed(name, &check(name, None, reset_only), |c| {
        matches!(c, Check::Arrived { .. })
    });
    // Nothing done: it stays in Error.
    failed(name, &check(name, None, &[]), |c| {
        matches!(c, Check::Arrived { .. })
    });
}

#[test]
fn a_parameter_the_exercise_does_not_name_fails_it() {
    let name = "ex_backward_dock";
    let text = format!(
        "{}\n{}",
        conf("ex_backward_dock.solution.conf"),
        conf("ex_rule_breaker.wrong.conf")
    );
    let status = check(name, Some(&text), &[]);
    failed(name, &status, |c| matches!(c, Check::OnlyAllowed));
    let rule = status.checks.last().unwrap();
    assert_eq!(rule.changed, vec!["DriveControl.MaxVelocity".to_owned()]);
    // Everything else passed: only the rule failed.
    let others = &status.checks[..status.checks.len() - 1];
    assert!(
        others.iter().all(|c| c.state == CheckState::Passed),
        "{status}"
    );
}

#[test]
fn a_scenario_without_an_exercise_and_a_bad_conf_are_errors() {
    let err = check_exercise(&scenario("open_field"), &RepoResolver::new(".."), None, &[])
        .unwrap_err()
        .to_string();
    assert!(err.contains("no exercise"), "{err}");
    let bad = "# [LocalPathPlanning0]\nconf.default.Deviatinglen: -1\n";
    let err = check_exercise(
        &scenario("ex_corner_deviation"),
        &RepoResolver::new(".."),
        Some(bad),
        &[],
    )
    .unwrap_err()
    .to_string();
    assert!(err.contains("Deviatinglen"), "{err}");
}

#[test]
fn bad_exercises_are_refused_with_the_reason() {
    let text = std::fs::read_to_string("../fixtures/scenarios/ex_door_dmin.json").unwrap();
    for (from, to, says) in [
        ("\"within_s\": 60", "\"within_s\": -1", "within_s = -1"),
        ("\"LocalPathPlanning.dmin\"", "\"Planner.dmin\"", "Planner"),
        (
            "\"LocalPathPlanning.dmin\"",
            "\"dmin\"",
            "Component.Parameter",
        ),
        (
            "{\n        \"check\": \"no_bump\"\n      }",
            "{\"check\": \"only_allowed\"}",
            "always checked",
        ),
    ] {
        assert!(text.contains(from), "{from}");
        let err = Scenario::from_json(&text.replace(from, to))
            .unwrap_err()
            .to_string();
        assert!(err.contains(says), "{to}: {err}");
    }
}
