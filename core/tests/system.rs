//! The whole system's GUI-facing API (SPEC §0, what InventGUI did): bad input is refused
//! with a clear error and changes nothing; a bump puts the system in Error and Reset
//! recovers; goals, SafeMode, Clear, faults, rates, configuration, preview, telemetry.
//! The scenarios themselves run in `tests/scenarios.rs` (native and wasm32).

use rtnav::Error;
use rtnav::errors::{LocalPathError, MapError, SystemError};
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::GridMap;
use rtnav::map::formats::json;
use rtnav::motion::angle_diff;
use rtnav::render::Renderer;
use rtnav::rtc::LifecycleState;
use rtnav::system::{
    ComponentKind, DirResolver, EventKind, MapSource, MemoryResolver, OutcomeKind, Rates, Scenario,
    ScenarioRun, System, SystemState,
};

/// The office floor of `corridor_turn` (22 × 16 m, 0.1 m cells).
fn corridor() -> GridMap {
    json::load(&std::fs::read_to_string("../fixtures/maps/scenarios/corridor_turn.json").unwrap())
        .unwrap()
}

const START: Pose = Pose::new(1.5, 1.3, 0.0);
/// Up the east corridor.
const GOAL: Pose = Pose::new(17.1, 14.5, core::f64::consts::FRAC_PI_2);
/// East end of the south corridor.
const NEAR_GOAL: Pose = Pose::new(12.0, 1.3, 0.0);

/// A system with the corridor map, `dmin` 0.6 m in both planners, start and goal set.
fn system(goal: Pose) -> System {
    let mut s = System::new(Rates::default()).unwrap();
    for kind in [
        ComponentKind::GlobalPathPlanning,
        ComponentKind::LocalPathPlanning,
    ] {
        s.config_mut(kind).unwrap().set("dmin", 0.6).unwrap();
    }
    s.load_map(corridor());
    s.set_position(START, goal, Direction::Forward).unwrap();
    s
}

fn arrived(s: &System) -> bool {
    s.is_arrived()
}

#[test]
fn bad_start_goal_and_map_input_is_refused_and_changes_nothing() {
    let mut s = system(GOAL);
    assert!(s.preview(5.0).unwrap(), "a route and a local plan");
    let goal = s.goal();
    let route = s.global_path().to_vec();
    let held = s.local_path_planning().held_path().to_vec();
    let key = s.map_key();
    let pose = s.robot_pose();
    assert!(!route.is_empty() && !held.is_empty());
    let unchanged = |s: &System| {
        assert_eq!(s.goal(), goal);
        assert_eq!(s.global_path(), &route[..]);
        assert_eq!(s.local_path_planning().held_path(), &held[..]);
        assert_eq!(s.map_key(), key);
        assert_eq!(s.robot_pose(), pose);
    };

    // A NaN pose.
    let e = s
        .set_position(Pose::new(f64::NAN, 1.3, 0.0), GOAL, Direction::Forward)
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::LocalPath(LocalPathError::NotFinite {
                argument: "StartX",
                ..
            })
        ),
        "{e}"
    );
    assert_eq!(e.to_string(), "SetPosition: StartX = NaN is not finite");
    let e = s
        .set_goal(Pose::new(3.0, 1.3, f64::INFINITY), Direction::Forward)
        .unwrap_err();
    assert_eq!(e.to_string(), "SetPosition: GoalAngle = inf is not finite");
    unchanged(&s);

    // A goal inside a desk, and one too close to the corridor wall.
    let e = s
        .set_position(START, Pose::new(1.5, 6.9, 0.0), Direction::Forward)
        .unwrap_err();
    assert!(
        matches!(e, Error::LocalPath(LocalPathError::NotClear { what: "goal", distance, .. }) if distance == 0.0),
        "{e}"
    );
    assert!(e.to_string().contains("too close to an obstacle"), "{e}");
    let e = s
        .set_position(START, Pose::new(6.0, 0.5, 0.0), Direction::Forward)
        .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("goal (6, 0.5) in cell (60, 5) is too close"),
        "{e}"
    );
    // Outside the map.
    let e = s
        .set_position(START, Pose::new(30.0, 1.3, 0.0), Direction::Forward)
        .unwrap_err();
    assert_eq!(e.to_string(), "goal (30, 1.3) is outside the map");
    unchanged(&s);

    // MapUpdate: outside the map, a bad value, mismatched lengths.
    let e = s.set_cells(&[(5, 5, 1), (220, 3, 1)]).unwrap_err();
    assert!(
        matches!(e, Error::Map(MapError::CellOutside { x: 220, .. })),
        "{e}"
    );
    let e = s.set_cells(&[(5, 5, 2)]).unwrap_err();
    assert!(
        matches!(e, Error::Map(MapError::BadCellValue { value: 2, .. })),
        "{e}"
    );
    let mut bad = rtnav::components::MapUpdate::from_cells(&[(5, 5, 1)], Default::default());
    bad.num = 3;
    assert!(s.map_update(bad).is_err());
    unchanged(&s);

    // A bad map file, a missing one: the old map stays.
    let before = s.map().unwrap().clone();
    let files = MemoryResolver::new().with(
        "bad.json",
        &b"{\"width\": 2, \"height\": 1, \"grid_size\": 0.1, \"rows\": [\"#\"]}"[..],
    );
    let e = s
        .load_map_from(
            &MapSource::Json {
                path: "bad.json".into(),
            },
            &files,
        )
        .unwrap_err();
    assert!(e.to_string().starts_with("rtnav JSON map"), "{e}");
    let e = s
        .load_map_from(
            &MapSource::Json {
                path: "missing.json".into(),
            },
            &files,
        )
        .unwrap_err();
    assert!(matches!(e, Error::System(SystemError::File { .. })), "{e}");
    assert_eq!(s.map(), Some(&before));
    unchanged(&s);

    // Names, configuration, numbers.
    assert!(ComponentKind::from_name("Planner").is_err());
    assert_eq!(
        ComponentKind::from_name("DriveControl0").unwrap(),
        ComponentKind::DriveControl
    );
    let e = s.config_mut(ComponentKind::MapBuilder).err().unwrap();
    assert_eq!(
        e.to_string(),
        "component `MapBuilder` has no configuration parameters"
    );
    let cfg = s.config_mut(ComponentKind::LocalPathPlanning).unwrap();
    assert!(cfg.set("PostureConsiderationLevel", 120.0).is_err());
    assert!(cfg.set("NoSuchParameter", 1.0).is_err());
    assert_eq!(cfg.value("PostureConsiderationLevel").unwrap(), 85.0);
    assert!(s.run_for(f64::NAN).is_err());
    assert!(s.set_rate(ComponentKind::DriveControl, 300.0).is_err());
    assert_eq!(s.rates().drive_control, 50.0);
    assert!(s.set_telemetry_rate(0.0).is_err());
    unchanged(&s);
}

#[test]
fn a_bump_stops_the_robot_puts_the_system_in_error_and_reset_recovers() {
    let mut s = system(NEAR_GOAL);
    assert_eq!(s.activate_all(), SystemState::Active);
    s.run_for(4.0).unwrap();
    let p = s.robot_pose();
    assert!(
        p.x > 2.0 && s.physics().physics().body_velocity().0 > 0.3,
        "{p:?}"
    );
    // A crate dropped right in front of the robot, closer than it can brake.
    let front = ((p.x + 0.5) / 0.1) as i64;
    let cells: Vec<_> = (front..front + 3)
        .flat_map(|x| (8..18).map(move |y| (x, y, 1)))
        .collect();
    assert_eq!(s.set_cells(&cells).unwrap(), 30);
    assert!(
        s.run_until(2.0, |s| s.state() == SystemState::Error)
            .unwrap()
    );

    let bump = s
        .events()
        .iter()
        .find_map(|e| match &e.kind {
            EventKind::Bump { report } => Some(report.clone()),
            _ => None,
        })
        .expect("a bump event");
    assert_eq!(bump.who, "rh0");
    assert!(bump.cell.0 >= front && bump.speed > 0.0, "{bump:?}");
    assert_eq!(
        s.component_state(ComponentKind::PhysicsSim),
        LifecycleState::Error
    );
    let reason = s
        .component_info(ComponentKind::PhysicsSim)
        .last_error
        .unwrap();
    assert!(
        reason.starts_with("bump: rh0 bumped into obstacle cell"),
        "{reason}"
    );
    assert!(s.events().iter().any(|e| matches!(
        &e.kind,
        EventKind::ComponentError { component, callback, reason: r }
            if component == "PhysicsSim0" && callback == "on_execute" && *r == reason
    )));
    assert!(s.motor_control().is_stopped(), "bump detection called Stop");
    // The robot stays where it stopped.
    let stopped = s.robot_pose();
    s.run_for(1.0).unwrap();
    assert_eq!(s.robot_pose(), stopped);
    assert!(s.physics().physics().state().in_contact);

    // Reset: every component Inactive, the reason gone.
    assert_eq!(s.reset_all(), SystemState::Inactive);
    for info in s.components() {
        assert_eq!(
            info.state,
            LifecycleState::Inactive,
            "{}",
            info.instance_name
        );
    }
    assert_eq!(s.component_info(ComponentKind::PhysicsSim).last_error, None);

    // Clear the crate, back off, and drive on to the goal.
    let cleared: Vec<_> = cells.iter().map(|&(x, y, _)| (x, y, 0)).collect();
    s.set_cells(&cleared).unwrap();
    s.set_goal(NEAR_GOAL, Direction::Forward).unwrap();
    assert_eq!(s.activate_all(), SystemState::Active);
    assert!(s.run_until(60.0, arrived).unwrap());
    let p = s.robot_pose();
    assert!(
        libm::hypot(p.x - NEAR_GOAL.x, p.y - NEAR_GOAL.y) < 0.1,
        "{p:?}"
    );
    assert_eq!(s.stats().bumps, 1);
}

#[test]
fn while_driving_set_position_is_refused_and_a_new_goal_plans_from_the_pose() {
    let mut s = system(GOAL);
    s.activate_all();
    s.run_for(5.0).unwrap();
    let e = s.set_position(START, GOAL, Direction::Forward).unwrap_err();
    assert!(
        matches!(e, Error::System(SystemError::Driving { .. })),
        "{e}"
    );
    let here = s.localization().current_pose();
    let plans = s.stats().global_plans;
    s.set_goal(NEAR_GOAL, Direction::Forward).unwrap();
    let set = s
        .events()
        .iter()
        .rev()
        .find_map(|e| match e.kind {
            EventKind::GoalSet { start, .. } => Some(start),
            _ => None,
        })
        .unwrap();
    assert_eq!(set, here, "planned from the robot's pose");
    assert!(s.run_until(60.0, arrived).unwrap());
    assert_eq!(s.stats().global_plans, plans + 1);
    let p = s.robot_pose();
    assert!(libm::hypot(p.x - NEAR_GOAL.x, p.y - NEAR_GOAL.y) < 0.1);
    assert!(angle_diff(p.theta, NEAR_GOAL.theta).abs() < 0.1);
}

#[test]
fn safe_mode_halts_the_robot_and_clear_drops_the_goal() {
    let mut s = system(GOAL);
    s.activate_all();
    s.run_for(5.0).unwrap();
    s.safe_mode();
    assert!(s.is_halted());
    s.run_for(2.0).unwrap();
    let (v, w) = s.physics().physics().body_velocity();
    assert!(v.abs() < 1e-3 && w.abs() < 1e-3, "stopped: {v} {w}");
    assert!(s.local_path_planning().flags().safe_mode);
    let here = s.robot_pose();
    s.run_for(2.0).unwrap();
    assert!(libm::hypot(s.robot_pose().x - here.x, s.robot_pose().y - here.y) < 1e-3);
    // A new goal releases SafeMode.
    s.set_goal(GOAL, Direction::Forward).unwrap();
    assert!(!s.is_halted());
    s.run_for(3.0).unwrap();
    assert!(
        s.physics().physics().body_velocity().0 > 0.1,
        "driving again"
    );
    // Clear: no goal, no path; the robot stops; the map stays.
    s.clear();
    assert_eq!(s.goal(), None);
    assert!(s.global_path().is_empty());
    s.run_for(2.0).unwrap();
    assert!(s.physics().physics().body_velocity().0.abs() < 1e-3);
    assert!(s.local_path_planning().flags().map, "the map is given back");
    s.set_goal(NEAR_GOAL, Direction::Forward).unwrap();
    assert!(s.run_until(60.0, arrived).unwrap());
}

#[test]
fn scenario_events_safe_mode_ends_the_run_halted() {
    let json = r#"{
        "name": "halt", "description": "", "lesson": "",
        "map": { "format": "json", "path": "fixtures/maps/scenarios/corridor_turn.json" },
        "start": { "x": 1.5, "y": 1.3 }, "goal": { "x": 17.1, "y": 14.5, "heading_deg": 90 },
        "config": { "GlobalPathPlanning": { "dmin": 0.6 }, "LocalPathPlanning": { "dmin": 0.6 } },
        "events": [ { "at": 4.0, "type": "safe_mode" } ],
        "time_limit": 30.0,
        "expect": { "outcome": "halted" }
    }"#;
    let scenario = Scenario::from_json(json).unwrap();
    let mut run = ScenarioRun::new(&scenario, &DirResolver::new("..")).unwrap();
    run.run_to_end().unwrap();
    let report = run.report();
    assert_eq!(report.outcome.kind, OutcomeKind::Halted);
    report.check(&scenario.expect).unwrap();
    assert!(
        report.sim_time > 5.0 && report.sim_time < 8.0,
        "{}",
        report.sim_time
    );
}

#[test]
fn an_injected_fault_puts_one_component_in_error_with_its_reason() {
    let mut s = system(GOAL);
    s.activate_all();
    s.inject_fault(ComponentKind::DriveControl, "test").unwrap();
    s.step(25);
    assert_eq!(s.state(), SystemState::Error);
    let info = s.component_info(ComponentKind::DriveControl);
    assert_eq!(info.state, LifecycleState::Error);
    assert_eq!(info.last_error.as_deref(), Some("injected fault: test"));
    assert!(s.events().iter().any(|e| matches!(
        &e.kind,
        EventKind::StateChanged { component, to: LifecycleState::Error, .. } if component == "DriveControl0"
    )));
    assert!(
        s.activate(ComponentKind::DriveControl).is_err(),
        "Error → Active is illegal"
    );
    assert_eq!(
        s.reset(ComponentKind::DriveControl).unwrap(),
        LifecycleState::Inactive
    );
    assert_eq!(
        s.activate(ComponentKind::DriveControl).unwrap(),
        LifecycleState::Active
    );
    assert_eq!(s.state(), SystemState::Active);
    assert!(s.run_until(90.0, arrived).unwrap());
}

#[test]
fn components_have_their_rates_states_and_live_configuration() {
    let mut s = system(GOAL);
    let rates: Vec<_> = s
        .components()
        .iter()
        .map(|c| (c.instance_name.clone(), c.rate))
        .collect();
    assert_eq!(
        rates,
        [
            ("MapBuilder0", 10.0),
            ("MapMaintenance0", 10.0),
            ("PhysicsSim0", 1000.0),
            ("MotorControl0", 1000.0),
            ("Localization0", 1000.0),
            ("GlobalPathPlanning0", 10.0),
            ("LocalPathPlanning0", 10.0),
            ("DriveControl0", 50.0),
        ]
        .map(|(n, r)| (n.to_owned(), r))
    );
    assert_eq!(s.state(), SystemState::Inactive);
    s.config_mut(ComponentKind::LocalPathPlanning)
        .unwrap()
        .set("RouteRemakeDistance", 4.0)
        .unwrap();
    assert_eq!(s.local_path_planning().params().route_remake_distance, 4.0);
    s.set_rate(ComponentKind::DriveControl, 25.0).unwrap();
    assert_eq!(s.component_info(ComponentKind::DriveControl).rate, 25.0);
    s.activate_all();
    assert!(s.run_until(90.0, arrived).unwrap(), "arrives at 25 Hz too");
    assert_eq!(s.deactivate_all(), SystemState::Inactive);
    // Rates come from JSON too; unknown keys are refused.
    let r: Rates = serde_json::from_str(r#"{"drive_control": 25}"#).unwrap();
    assert_eq!((r.drive_control, r.physics), (25.0, 1000.0));
    assert!(serde_json::from_str::<Rates>(r#"{"drive": 25}"#).is_err());
    let bad = Rates {
        telemetry: 3.0,
        ..Rates::default()
    };
    assert!(
        System::new(bad).is_err(),
        "a telemetry period that is not whole ticks"
    );
}

#[test]
fn the_preview_plans_without_moving_and_draws_the_field() {
    let mut s = system(GOAL);
    s.set_full_field(true);
    assert!(s.preview(5.0).unwrap());
    assert_eq!(s.state(), SystemState::Partial);
    assert_eq!(
        s.component_state(ComponentKind::PhysicsSim),
        LifecycleState::Inactive
    );
    assert_eq!(s.robot_pose(), START);
    assert!(s.local_path_planning().potential_field().is_some());
    assert!(s.local_path_planning().local_plan().is_some());
    let kinds: Vec<_> = s
        .events()
        .iter()
        .map(|e| std::mem::discriminant(&e.kind))
        .collect();
    for want in [
        EventKind::GlobalPlan {
            cells: 0,
            length: 0.0,
        },
        EventKind::LocalPlanSent {
            cells: 0,
            control_points: 0,
            replanned: false,
        },
    ] {
        assert!(kinds.contains(&std::mem::discriminant(&want)));
    }
    let mut r = Renderer::new(600, 400).unwrap();
    let scene = s.scene().unwrap();
    assert!(scene.field.is_some() && !scene.global_path.is_empty());
    assert_eq!(scene.start, Some(START));
    let frame = r.render(&scene).unwrap();
    assert_eq!((frame.width(), frame.height()), (600, 400));
    assert!(frame.data().chunks_exact(4).all(|p| p[3] == 255), "opaque");
}

#[test]
fn telemetry_is_bounded_and_the_same_run_gives_the_same_trace() {
    let run = |capacity: usize| {
        let mut s = system(NEAR_GOAL);
        s.telemetry_mut().set_capacity(capacity).unwrap();
        s.activate_all();
        assert!(s.run_until(60.0, arrived).unwrap());
        s
    };
    let a = run(100);
    let b = run(1 << 16);
    assert_eq!(a.telemetry().trace_hash(), b.telemetry().trace_hash());
    assert_eq!(a.telemetry().total(), b.telemetry().total());
    assert_eq!(a.telemetry().samples().len(), 100);
    assert_eq!(b.telemetry().samples().len() as u64, b.telemetry().total());
    assert_eq!(a.telemetry().last(), b.telemetry().last());
    // 50 Hz: one sample every 20 ms, from t = 0.
    let t: Vec<u64> = b
        .telemetry()
        .samples()
        .iter()
        .take(3)
        .map(|s| s.time_ns)
        .collect();
    assert_eq!(t, [0, 20_000_000, 40_000_000]);
    let csv = b.telemetry().to_csv();
    assert_eq!(csv.lines().count() as u64, 1 + b.telemetry().total());
    let events = |s: &System| s.events().iter().map(|e| e.to_string()).collect::<Vec<_>>();
    assert_eq!(events(&a), events(&b));
    assert!(
        events(&a).iter().any(|e| e.contains("arrived at (11.99")),
        "{:?}",
        events(&a)
    );
}

#[test]
fn scenario_events_a_new_goal_while_driving_is_reached() {
    let json = r#"{
        "name": "retarget", "description": "", "lesson": "",
        "map": { "format": "json", "path": "fixtures/maps/scenarios/corridor_turn.json" },
        "start": { "x": 1.5, "y": 1.3 }, "goal": { "x": 17.1, "y": 14.5, "heading_deg": 90 },
        "config": { "GlobalPathPlanning": { "dmin": 0.6 }, "LocalPathPlanning": { "dmin": 0.6 } },
        "events": [ { "at": 5.0, "type": "goal", "goal": { "x": 12.0, "y": 1.3, "heading_deg": 180 } } ],
        "time_limit": 60.0,
        "expect": { "outcome": "arrived" }
    }"#;
    let scenario = Scenario::from_json(json).unwrap();
    let mut run = ScenarioRun::new(&scenario, &DirResolver::new("..")).unwrap();
    run.run_to_end().unwrap();
    let report = run.report();
    report.check(&scenario.expect).unwrap();
    assert_eq!(
        report.goal,
        Some(Pose::new(12.0, 1.3, core::f64::consts::PI))
    );
    assert_eq!(report.global_plans, 2);
    // It did not stop to take the new goal: no sample below 0.1 m/s between 5 and 6 s.
    let slow = run
        .system()
        .telemetry()
        .samples()
        .iter()
        .filter(|s| (5_000_000_000..6_000_000_000).contains(&s.time_ns))
        .any(|s| s.v < 0.1);
    assert!(!slow, "kept driving through the new goal");
}
