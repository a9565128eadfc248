//! The facts a person reads, decided once in the core (spec §7, Decisions 0.3): the arrival
//! at rest for the current goal, the motion words from the measured motion with the cause
//! from the components' states, positions in metres with the cell, every exercise check
//! decided when a run ends — and a property over random runs.

use proptest::prelude::*;
use rtnav::data::RepoResolver;
use rtnav::interfaces::{Direction, Pose};
use rtnav::present::place;
use rtnav::rtc::LifecycleState;
use rtnav::system::setup::{self, BuildOptions, Setup};
use rtnav::system::{
    CheckState, ComponentKind, DirResolver, DriveInput, EndReason, EventKind, Input, Measured,
    Motion, Offset, OutcomeKind, REST_SPEED, REST_TURN_RATE, Scenario, ScenarioRun, Status, System,
    Tolerances, check_exercise,
};

fn scenario(name: &str) -> Scenario {
    let path = format!("../fixtures/scenarios/{name}.json");
    Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The set-up of `name` (planners Active, the plan made, the robot waiting).
fn set_up(name: &str) -> System {
    let s = scenario(name);
    setup::build(
        &s,
        &DirResolver::new(".."),
        &Setup::of(&s),
        BuildOptions::default(),
    )
    .unwrap()
}

fn apply(s: &mut System, input: Input) {
    s.apply(&input).unwrap_or_else(|e| panic!("{input:?}: {e}"));
}

/// The `Arrived` events after the first `seen`: (time, pose, position error).
fn arrivals_since(s: &System, seen: u64) -> Vec<(u64, Pose, f64)> {
    s.record()
        .events_since(seen)
        .filter_map(|e| match e.kind {
            EventKind::Arrived {
                pose,
                position_error,
                ..
            } => Some((e.time_ns, pose, position_error)),
            _ => None,
        })
        .collect()
}

/// Whether the robot of `s` rests within the tolerances of the goal `s` holds.
fn rests_at_goal(s: &System) -> bool {
    let (Some(goal), Some(tol)) = (s.mission().goal(), Tolerances::of(s.wiring())) else {
        return false;
    };
    Measured::of(s.wiring()).at_rest() && Offset::between(s.robot_pose(), goal).within(tol)
}

#[test]
fn arrival_is_at_rest_and_a_new_goal_gives_no_arrived_until_the_robot_rests_at_it() {
    let mut s = set_up("open_field");
    apply(&mut s, Input::ActivateAll);
    assert!(s.run_until(120.0, |s| s.mission().is_arrived()).unwrap());
    // The tick of the arrival: at rest within the tolerances, the event with that pose.
    assert!(rests_at_goal(&s));
    assert_eq!(s.status(), Status::Arrived);
    let first = arrivals_since(&s, 0);
    assert_eq!(first.len(), 1, "{first:?}");
    assert_eq!(
        first[0].1,
        s.robot_pose(),
        "the Arrived pose is the pose at rest"
    );
    // Standing there a while logs nothing more.
    let seen = s.record().event_count();
    s.run_for(1.0).unwrap();
    assert!(arrivals_since(&s, seen).is_empty());
    assert_eq!(s.status(), Status::Arrived);

    // A new goal from the standing robot ends the arrival at once.
    let back = Pose::new(2.5, 2.5, 0.0);
    let seen = s.record().event_count();
    apply(
        &mut s,
        Input::SetGoal {
            goal: back,
            direction: Direction::Forward,
        },
    );
    assert!(!s.mission().is_arrived());
    assert_ne!(s.status(), Status::Arrived);
    // No `Arrived` until the robot rests at the new goal; then exactly one, there.
    let mut ticks = 0u64;
    while s.mission().goal() == Some(back) && !s.mission().is_arrived() && ticks < 150_000 {
        s.step(1);
        ticks += 1;
        let now = arrivals_since(&s, seen);
        assert!(
            now.is_empty() || rests_at_goal(&s),
            "Arrived at {:?}, {} m from the new goal, moving {:?}",
            now[0].1,
            now[0].2,
            Measured::of(s.wiring())
        );
    }
    assert!(s.mission().is_arrived(), "arrives at the new goal");
    let second = arrivals_since(&s, seen);
    assert_eq!(second.len(), 1);
    assert!(Offset::between(second[0].1, back).distance <= s.map().unwrap().grid_size());
}

#[test]
fn arrival_a_robot_that_overshoots_and_rests_off_the_goal_has_not_arrived() {
    // The wheel loop as ex_pd_gains gives it (D gain 0.3): DriveControl believes it stops at
    // the goal, the robot rolls on past it and comes to rest more than a cell beyond.
    let ex = scenario("ex_pd_gains");
    let mut run = ScenarioRun::new(&ex, &DirResolver::new("..")).unwrap();
    let outcome = run.run_to_end().clone();
    let s = run.system();
    assert_eq!(outcome.kind, OutcomeKind::StoppedOffGoal, "{outcome:?}");
    assert!(arrivals_since(s, 0).is_empty(), "no Arrived");
    assert!(!s.mission().is_arrived());
    let goal = s.mission().goal().unwrap();
    let off = Offset::between(s.robot_pose(), goal);
    assert!(off.distance > s.map().unwrap().grid_size(), "{off:?}");
    match s.status() {
        Status::StoppedOffGoal {
            distance,
            heading_error,
        } => {
            assert_eq!(distance, off.distance);
            assert_eq!(heading_error, off.heading_error);
        }
        other => panic!("the status says {other}"),
    }
    assert!(Measured::of(s.wiring()).at_rest());
    assert!(
        matches!(
            outcome.reason,
            Some(EndReason::Status {
                status: Status::StoppedOffGoal { .. }
            })
        ),
        "{outcome:?}"
    );
}

#[test]
fn motion_after_reset_of_drive_control_in_error_the_status_says_it_coasts() {
    let mut s = set_up("open_field");
    apply(&mut s, Input::ActivateAll);
    s.run_for(8.0).unwrap();
    apply(
        &mut s,
        Input::InjectFault {
            component: ComponentKind::DriveControl,
            reason: "encoder cable pulled".to_owned(),
        },
    );
    assert!(
        s.run_until(1.0, |s| s.component_state(ComponentKind::DriveControl)
            == LifecycleState::Error)
            .unwrap()
    );
    // In Error: the cause, and the robot still moves with nothing driving it.
    match s.status() {
        Status::ComponentError {
            component, motion, ..
        } => {
            assert_eq!(component, "DriveControl0");
            assert_eq!(motion, Motion::Coasts);
        }
        other => panic!("{other}"),
    }
    apply(
        &mut s,
        Input::Reset {
            component: ComponentKind::DriveControl,
        },
    );
    let m = Measured::of(s.wiring());
    assert!(!m.at_rest(), "the robot still moves: {m:?}");
    assert_eq!(
        s.status(),
        Status::Inactive {
            component: "DriveControl0".to_owned(),
            motion: Motion::Coasts,
        }
    );
    assert_eq!(
        s.status().to_string(),
        "DriveControl0 inactive: the robot coasts"
    );
    // Friction brings it to rest: then, and only then, it stands.
    assert!(
        s.run_until(30.0, |s| Measured::of(s.wiring()).at_rest())
            .unwrap()
    );
    assert_eq!(
        s.status(),
        Status::Inactive {
            component: "DriveControl0".to_owned(),
            motion: Motion::Stands,
        }
    );
}

#[test]
fn motion_a_frozen_physics_stands_whatever_speed_it_held() {
    let mut s = set_up("open_field");
    apply(&mut s, Input::ActivateAll);
    s.run_for(6.0).unwrap();
    assert_eq!(s.status().motion(), Some(Motion::Drives), "{}", s.status());
    apply(&mut s, Input::DeactivateAll);
    assert!(Measured::of(s.wiring()).at_rest());
    assert_eq!(s.status(), Status::Ready);
}

#[test]
fn positions_in_words_are_in_metres_with_the_cell() {
    assert_eq!(
        place((1.55, 1.55), (15, 15)),
        "(1.55 m, 1.55 m) (cell 15, 15)"
    );
    // The unreachable scenario's failure says where, in metres first.
    let mut run = ScenarioRun::new(&scenario("unreachable"), &DirResolver::new("..")).unwrap();
    let outcome = run.run_to_end().clone();
    assert_eq!(outcome.kind, OutcomeKind::PlanningFailed);
    let Some(EndReason::Event {
        event: EventKind::PlanningFailed { planner, reason },
    }) = &outcome.reason
    else {
        panic!("{outcome:?}");
    };
    assert_eq!(planner, "GlobalPathPlanning");
    let said = reason.to_string();
    assert!(said.contains(" m, ") && said.contains("(cell "), "{said}");
}

/// The exercises with what the tests give them: the solution, the wrong answer, nothing.
fn exercise_runs() -> Vec<(String, Option<String>, Vec<DriveInput>)> {
    let mut runs = Vec::new();
    for entry in std::fs::read_dir("../fixtures/scenarios").unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        let Some(name) = name.strip_suffix(".json") else {
            continue;
        };
        if scenario(name).exercise.is_none() {
            continue;
        }
        for which in ["solution", "wrong"] {
            let path = format!("../fixtures/exercises/{name}.{which}.conf");
            if let Ok(text) = std::fs::read_to_string(path) {
                runs.push((name.to_owned(), Some(text), Vec::new()));
            }
        }
        runs.push((name.to_owned(), None, Vec::new()));
    }
    // Seed 003's exercise is done with requests: Reset and Activate 10 s into the drive.
    let recover = [
        Input::Reset {
            component: ComponentKind::DriveControl,
        },
        Input::Activate {
            component: ComponentKind::DriveControl,
        },
    ]
    .map(|input| DriveInput { at: 10.0, input });
    runs.push(("ex_fault_recovery".to_owned(), None, recover.to_vec()));
    runs
}

#[test]
fn exercise_checks_every_check_is_decided_when_the_run_ends() {
    let runs = exercise_runs();
    assert!(runs.len() >= 16, "{} runs", runs.len());
    for (name, conf, inputs) in runs {
        let status = check_exercise(
            &scenario(&name),
            &RepoResolver::new(".."),
            conf.as_deref(),
            &inputs,
        )
        .unwrap();
        let what = format!(
            "{name} ({}):\n{status}",
            conf.as_deref()
                .map_or("as given", |c| { c.lines().next().unwrap_or("") })
        );
        assert!(status.ended_after.is_some(), "{what}");
        for c in &status.checks {
            assert_ne!(c.state, CheckState::Open, "undecided: {what}");
            assert_eq!(c.unit, c.check.unit(), "{what}");
            if c.measured.is_some() {
                assert!(c.unit.is_some(), "a value without a unit: {what}");
            }
        }
    }
}

/// The motion a status claims agrees with the measured motion.
fn status_agrees(s: &System) -> Result<(), TestCaseError> {
    let status = s.status();
    let m = Measured::of(s.wiring());
    match status.motion() {
        Some(Motion::Stands) => prop_assert!(
            m.v.abs() < REST_SPEED && m.w.abs() < REST_TURN_RATE,
            "`{}` while moving {:?}",
            status,
            m
        ),
        Some(Motion::Drives | Motion::Turns) => prop_assert!(
            m.v.abs() >= REST_SPEED || m.w.abs() >= REST_TURN_RATE,
            "`{}` while at rest {:?}",
            status,
            m
        ),
        _ => {}
    }
    Ok(())
}

#[derive(Debug, Clone)]
enum Step {
    Run(u64),
    Goal(f64, f64, f64),
    Edit(i64, i64, i16),
    Lifecycle(u8, usize),
}

fn step() -> impl Strategy<Value = Step> {
    prop_oneof![
        3 => (200u64..4_000).prop_map(Step::Run),
        1 => (1.0..24.0f64, 1.0..17.0f64, -3.1..3.1f64).prop_map(|(x, y, t)| Step::Goal(x, y, t)),
        1 => (0i64..250, 0i64..180, 0i16..2).prop_map(|(x, y, v)| Step::Edit(x, y, v)),
        1 => (0u8..6, 0usize..ComponentKind::ALL.len()).prop_map(|(r, k)| Step::Lifecycle(r, k)),
    ]
}

fn input_of(step: &Step) -> Option<Input> {
    Some(match *step {
        Step::Run(_) => return None,
        Step::Goal(x, y, theta) => Input::SetGoal {
            goal: Pose::new(x, y, theta),
            direction: Direction::Forward,
        },
        Step::Edit(x, y, v) => Input::MapUpdate {
            cells: (0..4)
                .flat_map(|d| [(x + d, y, v), (x, y + d, v)])
                .collect(),
        },
        Step::Lifecycle(r, k) => {
            let component = ComponentKind::ALL[k];
            match r {
                0 => Input::Activate { component },
                1 => Input::Deactivate { component },
                2 => Input::Reset { component },
                3 => Input::ActivateAll,
                4 => Input::ResetAll,
                _ => Input::InjectFault {
                    component,
                    reason: "random fault".to_owned(),
                },
            }
        }
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 10, ..ProptestConfig::default() })]

    /// Over random runs (goals, map edits, lifecycle requests): the status's motion words
    /// agree with the physics' measured motion after every tick, and `Arrived` is only
    /// logged at rest within the tolerances of the goal held then.
    #[test]
    fn the_status_and_the_arrival_agree_with_the_measured_motion(
        steps in proptest::collection::vec(step(), 1..8)
    ) {
        let mut s = set_up("open_field");
        s.apply(&Input::ActivateAll).unwrap();
        let mut seen = s.record().event_count();
        for step in steps.iter().chain([&Step::Run(6_000)]) {
            if let Some(input) = input_of(step) {
                // Refusals change nothing; the property holds either way.
                let _ = s.apply(&input);
                status_agrees(&s)?;
            }
            let Step::Run(ticks) = *step else { continue };
            for _ in 0..ticks {
                s.step(1);
                status_agrees(&s)?;
                for (_, pose, _) in arrivals_since(&s, seen) {
                    prop_assert_eq!(pose, s.robot_pose());
                    prop_assert!(rests_at_goal(&s), "Arrived at {:?} not at rest at the goal", pose);
                }
                seen = s.record().event_count();
            }
        }
    }
}
