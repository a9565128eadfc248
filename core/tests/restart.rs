//! Restarting a run (`Session::restart`, the exercise panel's Restart): after a run that
//! failed its exercise, a restart with a parameter changed keeps the parameter, clears the
//! checklist, starts again at time 0 with the clock running, and the run passes; the replay
//! made after it reproduces its trace hash and verdict. A restart with nothing to restart is
//! refused by name and changes nothing; and the exercise's read-out says when the clock is
//! paused, so it never says the drive runs while the robot stands paused.

use rtnav::Error;
use rtnav::errors::SessionError;
use rtnav::interfaces::{Direction, Pose};
use rtnav::system::{CheckState, ComponentKind, Input, Session, Verdict};

mod common;
use common::loaded;

fn verdict(s: &Session) -> Verdict {
    s.exercise().unwrap().verdict
}

/// The page's frames (100 ms at 16×) until the exercise ends.
fn to_the_end(s: &mut Session) {
    s.set_speed(16.0).unwrap();
    let mut frames = 0;
    while matches!(verdict(s), Verdict::Waiting | Verdict::Running) {
        s.advance(100.0);
        frames += 1;
        assert!(frames < 2_000, "the exercise never ended");
    }
}

/// LocalPathPlanning's and GlobalPathPlanning's `dmin` as the parameter panel shows it.
fn dmin(s: &Session) -> f64 {
    s.parameters_view()
        .iter()
        .find(|c| c.component == "LocalPathPlanning")
        .and_then(|c| c.params.iter().find(|p| p.name == "dmin"))
        .unwrap()
        .value
}

fn trace_hash(s: &Session) -> String {
    s.system().record().telemetry().trace_hash()
}

#[test]
fn a_restart_after_a_failed_run_keeps_the_parameters_clears_the_checklist_and_passes() {
    let mut s = loaded("ex_door_dmin");
    // Wrong: dmin above half the door, no route through it.
    s.set_param_text(ComponentKind::LocalPathPlanning, "dmin", "0.7")
        .unwrap();
    s.apply(&Input::ActivateAll).unwrap();
    to_the_end(&mut s);
    assert_eq!(verdict(&s), Verdict::Failed);
    assert!(s.system().time_ns() > 0);

    // The right value, entered after the failure; the goal moved too (not kept: the
    // scenario's own goal comes back); the clock paused (it runs after the restart).
    s.set_param_text(ComponentKind::LocalPathPlanning, "dmin", "0.55")
        .unwrap();
    s.apply(&Input::SetGoal {
        goal: Pose::new(3.0, 3.0, 0.0),
        direction: Direction::Forward,
    })
    .unwrap();
    assert_eq!(s.system().mission().goal().unwrap().x, 3.0);
    s.set_paused(true);
    s.restart().unwrap();

    // Time back at the start: where a load's set-up stands once planned (a plan of the
    // route at 10 Hz), before any tick of the drive; the new run's timeline starts there.
    let start_ns = s.system().time_ns();
    assert!(start_ns <= 200_000_000, "{start_ns}");
    assert!(!s.paused(), "the clock runs after a restart");
    assert_eq!(dmin(&s), 0.55, "the student's parameter is kept");
    let goal = s.system().mission().goal().unwrap();
    assert_eq!((goal.x, goal.y), (12.0, 6.0), "the scenario's goal");
    let fresh = s.exercise().unwrap();
    assert_eq!(fresh.verdict, Verdict::Waiting);
    assert_eq!(fresh.started_at, None);
    assert_eq!(fresh.ended_after, None);
    // The checks, then the two rules every exercise holds (only_allowed, no_warning).
    let (checks, rules) = fresh.checks.split_at(fresh.checks.len() - 2);
    assert!(
        checks
            .iter()
            .all(|c| c.state == CheckState::Open && c.measured.is_none()),
        "{checks:?}"
    );
    assert!(
        rules.iter().all(|r| r.state == CheckState::Passed),
        "dmin may be changed, and 0.55 m is not warned about: {rules:?}"
    );
    let timeline = s.timeline_view().unwrap();
    assert_eq!(
        (timeline.start_ns, timeline.end_ns, timeline.inputs),
        (start_ns, start_ns, 0)
    );

    // The run again, now through the door.
    s.apply(&Input::ActivateAll).unwrap();
    to_the_end(&mut s);
    let passed = s.exercise().unwrap();
    assert_eq!(passed.verdict, Verdict::Passed, "{passed}");

    // Its replay: the restarted set-up (dmin 0.55) and the requests since, reproduced in a
    // fresh session with the same verdict.
    let replay = s.replay().unwrap();
    assert_eq!(
        replay.setup.params["LocalPathPlanning"]["dmin"], 0.55,
        "{:?}",
        replay.setup
    );
    let text = s.replay_json().unwrap();
    let mut other = loaded("ex_door_dmin");
    let check = other.load_replay_text(&text).unwrap();
    assert!(check.matches, "{check:?}");
    assert_eq!(trace_hash(&other), trace_hash(&s));
    assert_eq!(other.exercise().unwrap(), passed);
}

#[test]
fn two_restarts_run_the_same_run() {
    let mut s = loaded("ex_door_dmin");
    s.set_param_text(ComponentKind::LocalPathPlanning, "dmin", "0.55")
        .unwrap();
    let mut runs = Vec::new();
    for _ in 0..2 {
        s.restart().unwrap();
        s.apply(&Input::ActivateAll).unwrap();
        to_the_end(&mut s);
        runs.push((trace_hash(&s), s.exercise().unwrap()));
    }
    assert_eq!(runs[0], runs[1]);
    assert_eq!(runs[0].1.verdict, Verdict::Passed);
}

#[test]
fn a_restart_with_no_scenario_is_refused_by_name_and_changes_nothing() {
    let mut empty = Session::new().unwrap();
    let refused = empty.restart().unwrap_err();
    assert!(
        matches!(refused, Error::Session(SessionError::NothingToRestart)),
        "{refused:?}"
    );

    // A map picked from a file has no set-up to start again from.
    let s = loaded("open_field");
    let map = s.map().unwrap().clone();
    let mut picked = Session::new().unwrap();
    picked.load_map("picked.json", map).unwrap();
    // No start yet (spec §5 Decision 0.4): the robot is not activated, nothing changes.
    assert!(matches!(
        picked.apply(&Input::ActivateAll).unwrap_err(),
        Error::System(rtnav::errors::SystemError::NotPlaced { .. })
    ));
    picked.set_paused(true);
    picked.step_ticks(500).unwrap();
    let before = (picked.system().time_ns(), trace_hash(&picked));
    let refused = picked.restart().unwrap_err();
    assert!(
        matches!(refused, Error::Session(SessionError::NothingToRestart)),
        "{refused:?}"
    );
    assert_eq!((picked.system().time_ns(), trace_hash(&picked)), before);
    assert!(picked.paused(), "the clock as it was");
}

#[test]
fn the_exercise_read_out_says_when_the_clock_stands_still() {
    // The run back at 0 on the timeline (which pauses the clock), then Activate all: the
    // drive has started, and the read-out says the clock is paused, as the status does.
    let mut s = loaded("ex_door_dmin");
    s.advance(100.0);
    s.apply(&Input::ActivateAll).unwrap();
    to_the_end(&mut s);
    s.set_paused(true);
    s.seek(0).unwrap();
    assert_eq!(verdict(&s), Verdict::Waiting);
    s.apply(&Input::ActivateAll).unwrap();
    let view = s.exercise_view().unwrap();
    // As given, the door has no route, but nothing is decided at the drive's very start
    // (spec §7 Decision 0.4): the clock is paused.
    assert_eq!(view.status.verdict, Verdict::Running);
    assert!(view.status.ended_after.is_none());
    assert!(view.paused);
    assert!(s.telemetry().paused);
    let t = s.system().time_ns();
    s.advance(100.0);
    assert_eq!(s.system().time_ns(), t, "nothing runs while paused");
    // Run: the read-out and the clock agree again, and with no route the run is decided.
    s.set_paused(false);
    assert!(!s.exercise_view().unwrap().paused);
    s.advance(1000.0);
    assert!(s.system().time_ns() > t);
    assert_eq!(verdict(&s), Verdict::Failed);
}
