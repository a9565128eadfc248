//! Replays and seeking: a recorded run of open_field with a map stroke and a
//! parameter change is a small file that reproduces the trace hash; a file of another
//! version or a malformed one is refused; seeking back and forth reaches the state a straight
//! run had at that time, trace hash and all.

use std::time::Instant;

use rtnav::system::{
    ComponentKind, Input, MAX_CHECKPOINTS, MapSource, MarkKind, MemoryResolver, Replay, Scenario,
    Session, Verdict, compare, setup_with,
};

mod common;
use common::{loaded, root};

fn hash(s: &Session) -> String {
    s.system().record().telemetry().trace_hash()
}

/// Everything of the state a person can see, bit for bit (pose bits, time, hash, status).
fn fingerprint(s: &Session) -> String {
    let sys = s.system();
    let p = sys.robot_pose();
    format!(
        "{} {} {:x} {:x} {:x} {:?} {:?}",
        sys.time_ns(),
        hash(s),
        p.x.to_bits(),
        p.y.to_bits(),
        p.theta.to_bits(),
        sys.stats(),
        sys.status(),
    )
}

/// A page session's run: activate, drive, a brush stroke across the route, a parameter
/// change, on to `seconds` of simulated time (100 ms frames).
fn student_run(seconds: f64) -> Session {
    let mut s = loaded("open_field");
    s.apply(&Input::ActivateAll).unwrap();
    let frames = |s: &mut Session, n: usize| {
        for _ in 0..n {
            s.advance(100.0);
        }
    };
    frames(&mut s, 30);
    // A stroke of 3 × 8 cells, sent at once when it ends (the page's way).
    let mut cells = Vec::new();
    for x in 150..158 {
        for y in 100..103 {
            cells.push((x, y, 1));
        }
    }
    s.apply(&Input::MapUpdate { cells }).unwrap();
    frames(&mut s, 25);
    s.set_param_text(
        ComponentKind::LocalPathPlanning,
        "PostureConsiderationLevel",
        "85",
    )
    .unwrap();
    let rest = (seconds * 10.0) as usize - 55;
    frames(&mut s, rest);
    s
}

#[test]
fn a_replay_of_open_field_with_a_stroke_and_a_parameter_change_is_small_and_exact() {
    let recorded = student_run(40.0);
    let json = recorded.replay_json().unwrap();
    println!("replay: {} bytes", json.len());
    assert!(json.len() < 20 * 1024, "{} bytes", json.len());
    let replay = Replay::from_json(&json).unwrap();
    assert_eq!(replay.inputs.len(), 3, "{:?}", replay.inputs);
    assert_eq!(replay.trace_hash, hash(&recorded));

    let mut fresh = loaded("open_field");
    let check = fresh.load_replay(&replay).unwrap();
    assert!(check.matches, "{check:?}");
    assert_eq!(fingerprint(&fresh), fingerprint(&recorded));
    // A replay of the replay is the same file.
    assert_eq!(fresh.replay_json().unwrap(), json);
}

#[test]
fn an_injected_nan_is_replayed_bit_for_bit() {
    let mut s = loaded("open_field");
    s.apply(&Input::ActivateAll).unwrap();
    s.advance(100.0);
    let data = vec![f64::from_bits(0x7ff8_0000_dead_beef), 0.0, 0.0, 0.0];
    s.apply(&Input::InjectInput {
        component: ComponentKind::Localization,
        port: "InSimulatedPosition".to_owned(),
        data,
    })
    .unwrap();
    for _ in 0..10 {
        s.advance(100.0);
    }
    let json = s.replay_json().unwrap();
    assert!(json.contains("0x7ff80000deadbeef"), "{json}");
    let mut fresh = loaded("open_field");
    let check = fresh
        .load_replay(&Replay::from_json(&json).unwrap())
        .unwrap();
    assert!(check.matches, "{check:?}");
    assert_eq!(fingerprint(&fresh), fingerprint(&s));
}

#[test]
fn a_replay_of_another_version_scenario_or_shape_is_refused_and_nothing_changes() {
    let json = student_run(6.0).replay_json().unwrap();
    for (bad, why) in [
        (json.replace("\"version\":2", "\"version\":7"), "version 7"),
        (json.replace("\"end_ns\"", "\"end\""), "malformed"),
        (json[..json.len() / 2].to_owned(), "not a JSON object"),
        (
            json.replace("rtnav-replay", "rtnav-share"),
            "not an rtnav replay",
        ),
    ] {
        let e = Replay::from_json(&bad).unwrap_err().to_string();
        assert!(e.starts_with("replay: ") && e.contains(why), "{e}");
    }
    // Another scenario's replay on open_field: refused, the session as it was.
    let mut other = Replay::from_json(&json).unwrap();
    other.setup.scenario = "parking_wall".to_owned();
    let mut s = loaded("open_field");
    s.advance(100.0);
    let before = fingerprint(&s);
    let e = s.load_replay(&other).unwrap_err().to_string();
    assert!(
        e.contains("parking_wall") && e.starts_with("replay: "),
        "{e}"
    );
    assert_eq!(fingerprint(&s), before);
}

#[test]
fn seeking_back_and_forth_reaches_what_a_straight_run_had_then() {
    // The straight run: the student's run stepped to each time, its state noted there.
    let times_ms: [u64; 7] = [2_000, 4_500, 5_800, 9_000, 17_300, 25_000, 33_300];
    let replay_end = student_run(36.0);
    let replay = replay_end.replay().unwrap();
    let mut at = Vec::new();
    for &t in &times_ms {
        let target = t * 1_000_000;
        // Apply the recorded requests the straight way: through a session loading the
        // replay cut at `target` (every request before it, the run to it).
        let mut cut = replay.clone();
        cut.inputs.retain(|i| i.t_ns <= target);
        cut.end_ns = target;
        let mut straight = loaded("open_field");
        straight.load_replay(&cut).unwrap();
        assert_eq!(straight.system().time_ns(), target);
        at.push(fingerprint(&straight));
    }

    let mut s = loaded("open_field");
    assert!(s.load_replay(&replay).unwrap().matches);
    let view = s.timeline_view().unwrap();
    assert!(view.checkpoints >= 10 && view.checkpoints <= MAX_CHECKPOINTS);
    println!("{} marks: {:?}", view.marks.len(), view.marks);
    assert!(view.marks.iter().any(|m| m.kind == MarkKind::Plan));
    // Back, forth, back again, in a jumbled order.
    for &i in &[6usize, 0, 3, 1, 5, 2, 4, 6, 0] {
        let started = Instant::now();
        s.seek(times_ms[i] * 1_000_000).unwrap();
        let ms = started.elapsed().as_secs_f64() * 1e3;
        println!("seek to {:>6} ms: {ms:.1} ms (debug build)", times_ms[i]);
        assert_eq!(fingerprint(&s), at[i], "after a seek to {} ms", times_ms[i]);
    }
    // Stepping one tick on from a seek is the straight run's next tick; the end is reached
    // again with the recorded hash.
    s.seek(replay.end_ns).unwrap();
    assert_eq!(hash(&s), replay.trace_hash);
    // A request made in the past drops the recorded future.
    s.seek(3_000_000_000).unwrap();
    s.apply(&Input::SafeMode).unwrap();
    let view = s.timeline_view().unwrap();
    assert_eq!(view.pending, 0);
    assert!(view.end_ns <= 3_100_000_000, "{view:?}");
}

#[test]
fn posture_consideration_0_and_85_on_parking_wall_arrive_at_different_headings() {
    let json =
        std::fs::read_to_string(root().join("fixtures/scenarios/parking_wall.json")).unwrap();
    let scenario = Scenario::from_json(&json).unwrap();
    let MapSource::Json { path } = &scenario.map else {
        panic!("a JSON map");
    };
    let files = MemoryResolver::new().with(path, std::fs::read(root().join(path)).unwrap());
    let a = setup_with(&scenario, "LocalPathPlanning.PostureConsiderationLevel=0").unwrap();
    let b = setup_with(
        &scenario,
        "LocalPathPlanning.PostureConsiderationLevel = 85 # default",
    )
    .unwrap();
    let c = compare(&scenario, &files, &a, &b).unwrap();
    println!("{c}");
    let (ha, hb) = (
        c.a().arrival_heading_error_deg.unwrap(),
        c.b().arrival_heading_error_deg.unwrap(),
    );
    // The seed's lesson: about 90° off without the posture term, about 40° with it.
    assert!(ha > 70.0 && hb < 55.0, "{ha} vs {hb}");
    for r in [c.a(), c.b()] {
        assert!(
            r.time_to_goal_s
                .is_some_and(|t| t > 0.0 && t < r.sim_time_s)
        );
        assert!(r.path_length_m > 5.0 && r.energy_j > 0.0 && r.min_clearance_m > 0.45);
    }
    let table = c.to_string();
    assert!(table.contains("arrival heading error") && table.contains("energy"));
    let plots = c.plots();
    assert_eq!(plots.t_a.len(), plots.v_a.len());
    assert!(plots.t_b.len() > 100);
    // A bad assignment names itself.
    let e = setup_with(&scenario, "LocalPathPlanning.PostureConsiderationLevel").unwrap_err();
    assert!(
        e.to_string().contains("expected Component.Name=value"),
        "{e}"
    );
}

/// A 5-minute run of open_field back and forth between two corners (a new goal at each
/// arrival), then seeks to times spread over it: each restores a checkpoint and re-simulates
/// at most the checkpoints' spacing. The page's bound is 100 ms (a release build); a debug
/// build is allowed ten times that.
#[test]
fn any_seek_on_a_five_minute_run_is_fast() {
    use rtnav::interfaces::{Direction, Pose};
    let mut s = loaded("open_field");
    s.apply(&Input::ActivateAll).unwrap();
    let corners = [
        Pose::new(2.5, 2.5, 0.0),
        Pose::new(23.0, 15.5, core::f64::consts::FRAC_PI_2),
    ];
    let mut next = 0;
    while s.system().time() < 300.0 {
        s.step_ticks(500).unwrap();
        if s.system().mission().is_arrived() {
            s.apply(&Input::SetGoal {
                goal: corners[next],
                direction: Direction::Forward,
            })
            .unwrap();
            next = 1 - next;
        }
    }
    let end = s.system().time_ns();
    let hash_end = hash(&s);
    let view = s.timeline_view().unwrap();
    println!(
        "5-minute run: {} requests, {} checkpoints {} s apart, replay {} bytes",
        view.inputs,
        view.checkpoints,
        view.checkpoint_ns as f64 * 1e-9,
        s.replay_json().unwrap().len()
    );
    assert!(view.inputs >= 4, "it drove back and forth: {view:?}");
    assert!(view.checkpoints <= MAX_CHECKPOINTS);
    let mut worst: f64 = 0.0;
    for k in 0..20u64 {
        // 20 times spread over the run, back and forth (a stride coprime with 20).
        let t = (k * 7 % 20) * (end / 20) + 12_345_000;
        let started = Instant::now();
        s.seek(t).unwrap();
        worst = worst.max(started.elapsed().as_secs_f64() * 1e3);
    }
    let limit = if cfg!(debug_assertions) {
        1000.0
    } else {
        100.0
    };
    println!("slowest of 20 seeks: {worst:.1} ms (limit {limit} ms)");
    assert!(worst < limit, "{worst} ms");
    s.seek(end).unwrap();
    assert_eq!(hash(&s), hash_end);
}

#[test]
fn a_seek_back_takes_the_exercise_back_too() {
    let mut s = loaded("ex_backward_dock");
    s.apply(&Input::ActivateAll).unwrap();
    s.set_speed(16.0).unwrap();
    let mut frames = 0;
    while s.exercise().unwrap().verdict == Verdict::Running
        || s.exercise().unwrap().verdict == Verdict::Waiting
    {
        s.advance(100.0);
        frames += 1;
        assert!(frames < 2_000, "the exercise never ended");
    }
    let ended = s.exercise().unwrap();
    let end_ns = s.system().time_ns();
    // Back to two seconds into the drive: nothing decided after then is kept ...
    s.seek(2_000_000_000).unwrap();
    assert_eq!(s.exercise().unwrap().verdict, Verdict::Running);
    // ... and forward again, the same verdict as the straight run.
    s.seek(end_ns).unwrap();
    assert_eq!(s.exercise().unwrap(), ended);
}

#[test]
fn a_cut_connection_is_recorded_and_seeking_keeps_when_it_was_cut() {
    const TARGET_VELOCITY: &str = "DriveControl.TargetVelocity->MotorControl.TargetVelocity";
    let cut_at = |s: &Session| {
        let graph = s.system().wiring().graph();
        let c = graph.connections.iter().find(|c| c.id == TARGET_VELOCITY);
        c.map(|c| (c.cut, c.carried)).unwrap()
    };
    let mut s = loaded("open_field");
    s.apply(&Input::ActivateAll).unwrap();
    s.step_ticks(3_000).unwrap();
    s.apply(&Input::CutConnection {
        connection: TARGET_VELOCITY.to_owned(),
    })
    .unwrap();
    s.step_ticks(3_000).unwrap();
    let (cut, carried) = cut_at(&s);
    assert!(cut);
    let replay = s.replay().unwrap();
    assert!(
        replay
            .inputs
            .iter()
            .any(|t| matches!(&t.input, Input::CutConnection { .. })),
        "the cut is in the replay"
    );
    s.seek(2_000_000_000).unwrap();
    assert!(!cut_at(&s).0, "before the cut");
    s.seek(5_000_000_000).unwrap();
    assert!(cut_at(&s).0, "after the cut");
    s.seek(6_000_000_000).unwrap();
    assert_eq!(cut_at(&s), (cut, carried));
}

#[test]
fn a_time_past_a_day_is_refused_instead_of_run_to() {
    let mut s = loaded("open_field");
    let day = rtnav::system::MAX_REPLAY_NS;
    let before = fingerprint(&s);
    let e = s.seek(1_000_000_000_000_000_000).unwrap_err().to_string();
    assert_eq!(
        e,
        "replay: seeking to 1000000000000000000 ns is later than 86400000000000 ns (24 h of \
         simulated time), the longest a run or a replay goes"
    );
    // A replay made in code (not read from a file) is checked when it is loaded.
    let mut replay = s.replay().unwrap();
    replay.end_ns = day + 1;
    let e = s.load_replay(&replay).unwrap_err().to_string();
    assert!(
        e.starts_with("replay: end_ns 86400000000001 is later than"),
        "{e}"
    );
    assert_eq!(fingerprint(&s), before, "nothing changed");
}
