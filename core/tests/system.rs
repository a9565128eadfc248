//! The whole system's GUI-facing API (spec §0, what InventGUI did), driven with [`Input`]s:
//! bad input is refused with a clear error and changes nothing; a bump puts the system in
//! Error and Reset recovers; goals, SafeMode, Clear, faults, rates, configuration, the set-up,
//! telemetry. The scenarios themselves run in `tests/scenarios.rs` (native and wasm32).

use rtnav::Error;
use rtnav::errors::{LocalPathError, MapError, ScenarioError, SystemError};
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::formats::json;
use rtnav::map::{GridMap, MapUpdate};
use rtnav::motion::angle_diff;
use rtnav::render::{FieldBuffers, Layers, Renderer, scene_of};
use rtnav::rtc::{LifecycleState, Time};
use rtnav::system::setup::{self, BuildOptions, PLAN_SECONDS, Setup};
use rtnav::system::{
    ComponentInfo, ComponentKind, DirResolver, EventKind, Input, MapSource, MemoryResolver,
    OutcomeKind, Rates, STILL_NS, Scenario, ScenarioRun, System, SystemState,
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

/// `SetParam` of `component`'s `name`.
fn param(component: ComponentKind, name: &str, value: f64) -> Input {
    Input::SetParam {
        component,
        name: name.to_owned(),
        value,
    }
}

/// `MapUpdate` of `cells` `(x, y, value)`.
fn cells(cells: &[(i64, i64, i16)]) -> Input {
    Input::MapUpdate {
        cells: cells.to_vec(),
    }
}

/// A system with the corridor map, `dmin` 0.6 m, start and goal set; every component
/// Inactive.
fn system(goal: Pose) -> System {
    let mut s = System::new(Rates::default()).unwrap();
    // One `dmin` (spec §3 Decision 0.2): LocalPathPlanning's sets GlobalPathPlanning's too.
    s.apply(&param(ComponentKind::LocalPathPlanning, "dmin", 0.6))
        .unwrap();
    s.load_map(corridor());
    s.apply(&Input::SetPosition {
        start: START,
        goal,
        direction: Direction::Forward,
    })
    .unwrap();
    s
}

/// Activates the planning components and runs until they have planned, the robot standing.
fn plan(s: &mut System) -> bool {
    for component in ComponentKind::PLANNING {
        s.apply(&Input::Activate { component }).unwrap();
    }
    s.run_until_planned(PLAN_SECONDS).unwrap()
}

fn activate_all(s: &mut System) -> SystemState {
    s.apply(&Input::ActivateAll).unwrap();
    s.state()
}

fn arrived(s: &System) -> bool {
    s.mission().is_arrived()
}

fn info(s: &System, kind: ComponentKind) -> ComponentInfo {
    s.component(kind)
}

/// The newest `MapUpdated` event's `(cells listed, cells changed)`.
fn last_map_update(s: &System) -> (usize, usize) {
    s.record()
        .events()
        .iter()
        .rev()
        .find_map(|e| match e.kind {
            EventKind::MapUpdated { cells, changed } => Some((cells, changed)),
            _ => None,
        })
        .expect("a MapUpdated event")
}

#[test]
fn bad_start_goal_and_map_input_is_refused_and_changes_nothing() {
    let mut s = system(GOAL);
    assert!(plan(&mut s), "the planners settle");
    let goal = s.mission().goal();
    let route = s.mission().route().to_vec();
    let held = s.wiring().local_path_planning().held_path().to_vec();
    let key = s.wiring().map_key();
    let pose = s.robot_pose();
    let events = s.record().event_count();
    assert!(
        !route.is_empty() && !held.is_empty(),
        "a route and a local plan"
    );
    assert!(s.wiring().local_path_planning().local_plan().is_some());
    let unchanged = |s: &System| {
        assert_eq!(s.mission().goal(), goal);
        assert_eq!(s.mission().route(), &route[..]);
        assert_eq!(s.wiring().local_path_planning().held_path(), &held[..]);
        assert_eq!(s.wiring().map_key(), key);
        assert_eq!(s.robot_pose(), pose);
    };

    // A NaN pose.
    let e = s
        .apply(&Input::SetPosition {
            start: Pose::new(f64::NAN, 1.3, 0.0),
            goal: GOAL,
            direction: Direction::Forward,
        })
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
        .apply(&Input::SetGoal {
            goal: Pose::new(3.0, 1.3, f64::INFINITY),
            direction: Direction::Forward,
        })
        .unwrap_err();
    assert_eq!(e.to_string(), "SetGoal: GoalAngle = inf is not finite");
    unchanged(&s);

    // A goal inside a desk, and one too close to the corridor wall.
    let set_goal = |s: &mut System, goal: Pose| {
        s.apply(&Input::SetPosition {
            start: START,
            goal,
            direction: Direction::Forward,
        })
        .unwrap_err()
    };
    let e = set_goal(&mut s, Pose::new(1.5, 6.9, 0.0));
    assert!(
        matches!(e, Error::LocalPath(LocalPathError::NotClear { what: "goal", distance, .. }) if distance == 0.0),
        "{e}"
    );
    assert!(e.to_string().contains("too close to an obstacle"), "{e}");
    let e = set_goal(&mut s, Pose::new(6.0, 0.5, 0.0));
    assert!(
        e.to_string()
            .starts_with("goal (6, 0.5) in cell (60, 5) is too close"),
        "{e}"
    );
    // Outside the map.
    let e = set_goal(&mut s, Pose::new(30.0, 1.3, 0.0));
    assert_eq!(e.to_string(), "goal (30, 1.3) is outside the map");
    unchanged(&s);

    // MapUpdate: outside the map, a bad value.
    let e = s.apply(&cells(&[(5, 5, 1), (220, 3, 1)])).unwrap_err();
    assert!(
        matches!(e, Error::Map(MapError::CellOutside { x: 220, .. })),
        "{e}"
    );
    let e = s.apply(&cells(&[(5, 5, 2)])).unwrap_err();
    assert!(
        matches!(e, Error::Map(MapError::BadCellValue { value: 2, .. })),
        "{e}"
    );
    // Arrays of different lengths cannot be said with `Input::MapUpdate` (one list of
    // cells); the check every receiver of a `MapUpdate` makes refuses them.
    let mut bad = MapUpdate::from_cells(&[(5, 5, 1)], Time::default());
    bad.num = 3;
    assert!(bad.check(s.map().unwrap()).is_err());
    unchanged(&s);

    // A bad map file, a missing one: refused when read, so nothing reaches the system
    // (`System::load_map` takes a `GridMap`, valid by construction).
    let files = MemoryResolver::new().with(
        "bad.json",
        &b"{\"width\": 2, \"height\": 1, \"grid_size\": 0.1, \"rows\": [\"#\"]}"[..],
    );
    let read = |path: &str| {
        MapSource::Json {
            path: path.to_owned(),
        }
        .load(&files)
        .unwrap_err()
    };
    let e = read("bad.json");
    assert!(e.to_string().starts_with("rtnav JSON map"), "{e}");
    let e = read("missing.json");
    assert!(
        matches!(e, Error::Scenario(ScenarioError::File { .. })),
        "{e}"
    );

    // Names, configuration, numbers.
    assert!(ComponentKind::from_name("Planner").is_err());
    assert_eq!(
        ComponentKind::from_name("DriveControl0").unwrap(),
        ComponentKind::DriveControl
    );
    let e = s
        .apply(&param(ComponentKind::MapBuilder, "dmin", 0.5))
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "component `MapBuilder` has no configuration parameters"
    );
    let lpp = ComponentKind::LocalPathPlanning;
    assert!(
        s.apply(&param(lpp, "PostureConsiderationLevel", 120.0))
            .is_err()
    );
    assert!(s.apply(&param(lpp, "NoSuchParameter", 1.0)).is_err());
    let pcl = |s: &System| {
        s.wiring()
            .config(lpp)
            .unwrap()
            .value("PostureConsiderationLevel")
            .unwrap()
    };
    assert_eq!(pcl(&s), 85.0);
    assert!(s.run_for(f64::NAN).is_err());
    assert!(
        s.apply(&Input::SetRate {
            component: ComponentKind::DriveControl,
            hz: 300.0
        })
        .is_err()
    );
    assert_eq!(s.rates().drive_control, 50.0);
    assert!(s.set_telemetry_rate(0.0).is_err());
    unchanged(&s);
    // A refused request leaves no trace in the log either.
    assert_eq!(s.record().event_count(), events);
}

#[test]
fn a_bump_stops_the_robot_puts_the_system_in_error_and_reset_recovers() {
    let mut s = system(NEAR_GOAL);
    assert_eq!(activate_all(&mut s), SystemState::Active);
    let speed = |s: &System| s.wiring().physics().physics().body_velocity().0;
    // Under way at cruising speed (the local plan stops at sharp control points, so the
    // moment is found, not fixed), the body's front (radius 0.45 m) 2 mm short of a cell.
    let short_of_a_cell = |s: &System| (s.robot_pose().x + 0.45) / 0.1 % 1.0 > 0.98;
    assert!(
        s.run_until(4.0, |s| s.robot_pose().x > 2.0
            && speed(s) > 0.45
            && short_of_a_cell(s))
            .unwrap()
    );
    let p = s.robot_pose();
    // A crate dropped just ahead of the body (one on the body is refused, spec §5 Decision
    // 0.4): no controller can react before the physics' next steps drive the body into it.
    let front = libm::ceil((p.x + 0.45) / 0.1) as i64;
    let crate_cells: Vec<_> = (front..front + 3)
        .flat_map(|x| (8..18).map(move |y| (x, y, 1)))
        .collect();
    s.apply(&cells(&crate_cells)).unwrap();
    assert_eq!(last_map_update(&s), (30, 30));
    assert!(
        s.run_until(2.0, |s| s.state() == SystemState::Error)
            .unwrap()
    );

    let bump = s
        .record()
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
    let reason = info(&s, ComponentKind::PhysicsSim).last_error.unwrap();
    assert!(
        matches!(&reason, rtnav::Reason::Bump(r) if r.who == "rh0"),
        "{reason:?}"
    );
    assert!(
        reason
            .to_string()
            .starts_with("bump: rh0 bumped into obstacle cell"),
        "{reason}"
    );
    assert!(s.record().events().iter().any(|e| matches!(
        &e.kind,
        EventKind::ComponentError { component, callback, reason: r }
            if component == "PhysicsSim0" && callback == "on_execute" && *r == reason
    )));
    assert!(
        s.wiring()
            .motor_control()
            .expect("the built-in MotorControl")
            .is_stopped(),
        "bump detection called Stop"
    );
    // The robot stays where it stopped.
    let stopped = s.robot_pose();
    s.run_for(1.0).unwrap();
    assert_eq!(s.robot_pose(), stopped);
    assert!(s.wiring().physics().physics().state().in_contact);

    // Reset: every component Inactive, the reason gone.
    s.apply(&Input::ResetAll).unwrap();
    assert_eq!(s.state(), SystemState::Inactive);
    for info in s.components() {
        assert_eq!(
            info.state,
            LifecycleState::Inactive,
            "{}",
            info.instance_name
        );
    }
    assert_eq!(info(&s, ComponentKind::PhysicsSim).last_error, None);

    // Clear the crate, back off, and drive on to the goal.
    let cleared: Vec<_> = crate_cells.iter().map(|&(x, y, _)| (x, y, 0)).collect();
    s.apply(&cells(&cleared)).unwrap();
    s.apply(&Input::SetGoal {
        goal: NEAR_GOAL,
        direction: Direction::Forward,
    })
    .unwrap();
    assert_eq!(activate_all(&mut s), SystemState::Active);
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
    activate_all(&mut s);
    s.run_for(5.0).unwrap();
    let e = s
        .apply(&Input::SetPosition {
            start: START,
            goal: GOAL,
            direction: Direction::Forward,
        })
        .unwrap_err();
    assert!(
        matches!(e, Error::System(SystemError::Driving { .. })),
        "{e}"
    );
    let here = s.wiring().localization().current_pose();
    let plans = s.stats().global_plans;
    s.apply(&Input::SetGoal {
        goal: NEAR_GOAL,
        direction: Direction::Forward,
    })
    .unwrap();
    let (start, placed) = s
        .record()
        .events()
        .iter()
        .rev()
        .find_map(|e| match e.kind {
            EventKind::GoalSet { start, placed, .. } => Some((start, placed)),
            _ => None,
        })
        .unwrap();
    assert_eq!(start, here, "planned from the robot's pose");
    assert!(!placed, "the robot is not moved");
    assert!(s.run_until(60.0, arrived).unwrap());
    assert_eq!(s.stats().global_plans, plans + 1);
    let p = s.robot_pose();
    assert!(libm::hypot(p.x - NEAR_GOAL.x, p.y - NEAR_GOAL.y) < 0.1);
    assert!(angle_diff(p.theta, NEAR_GOAL.theta).abs() < 0.1);
}

#[test]
fn safe_mode_halts_the_robot_and_clear_drops_the_goal() {
    let mut s = system(GOAL);
    activate_all(&mut s);
    s.run_for(5.0).unwrap();
    s.apply(&Input::SafeMode).unwrap();
    assert!(s.mission().is_halted());
    s.run_for(2.0).unwrap();
    let (v, w) = s.wiring().physics().physics().body_velocity();
    assert!(v.abs() < 1e-3 && w.abs() < 1e-3, "stopped: {v} {w}");
    assert!(s.wiring().local_path_planning().flags().safe_mode);
    let here = s.robot_pose();
    s.run_for(2.0).unwrap();
    assert!(libm::hypot(s.robot_pose().x - here.x, s.robot_pose().y - here.y) < 1e-3);
    // A new goal releases SafeMode.
    let new_goal = Input::SetGoal {
        goal: GOAL,
        direction: Direction::Forward,
    };
    s.apply(&new_goal).unwrap();
    assert!(!s.mission().is_halted());
    s.run_for(3.0).unwrap();
    assert!(
        s.wiring().physics().physics().body_velocity().0 > 0.1,
        "driving again"
    );
    // Clear: no goal, no route; the robot stops; the map stays.
    s.apply(&Input::Clear).unwrap();
    assert_eq!(s.mission().goal(), None);
    assert!(s.mission().route().is_empty());
    s.run_for(2.0).unwrap();
    assert!(s.wiring().physics().physics().body_velocity().0.abs() < 1e-3);
    assert!(
        s.wiring().local_path_planning().flags().map,
        "the map is given back"
    );
    s.apply(&Input::SetGoal {
        goal: NEAR_GOAL,
        direction: Direction::Forward,
    })
    .unwrap();
    assert!(s.run_until(60.0, arrived).unwrap());
}

#[test]
fn scenario_events_safe_mode_ends_the_run_halted() {
    let json = r#"{
        "name": "halt", "description": "", "lesson": "",
        "map": { "format": "json", "path": "fixtures/maps/scenarios/corridor_turn.json" },
        "start": { "x": 1.5, "y": 1.3 }, "goal": { "x": 17.1, "y": 14.5, "heading_deg": 90 },
        "config": { "LocalPathPlanning": { "dmin": 0.6 } },
        "events": [ { "at": 4.0, "type": "safe_mode" } ],
        "time_limit": 30.0,
        "expect": { "outcome": "halted" }
    }"#;
    let scenario = Scenario::from_json(json).unwrap();
    let mut run = ScenarioRun::new(&scenario, &DirResolver::new("..")).unwrap();
    run.run_to_end();
    let report = run.report();
    assert_eq!(report.outcome.kind, OutcomeKind::Halted);
    report.check(&scenario.expect).unwrap();
    // The run ends once the robot has stood still for STILL_NS after SafeMode (MotorControl
    // brakes it from full speed at MaxTorque in well under two seconds).
    let safe_mode = run
        .system()
        .record()
        .events()
        .iter()
        .find(|e| e.kind == EventKind::SafeMode)
        .expect("the timeline's SafeMode")
        .time_ns;
    let after = report.sim_time - safe_mode as f64 * 1e-9;
    let still = STILL_NS as f64 * 1e-9;
    assert!(after > still && after < still + 2.0, "{after} s");
}

#[test]
fn an_injected_fault_puts_one_component_in_error_with_its_reason() {
    let mut s = system(GOAL);
    activate_all(&mut s);
    s.apply(&Input::InjectFault {
        component: ComponentKind::DriveControl,
        reason: "test".to_owned(),
    })
    .unwrap();
    s.step(25);
    assert_eq!(s.state(), SystemState::Error);
    let drive = info(&s, ComponentKind::DriveControl);
    assert_eq!(drive.state, LifecycleState::Error);
    let fault = rtnav::Reason::InjectedFault("test".to_owned());
    assert_eq!(drive.last_error.as_ref(), Some(&fault));
    // Its status says so: it does not drive while it is in Error.
    assert_eq!(
        drive.status,
        rtnav::system::ComponentActivity::InError {
            reason: Some(fault)
        }
    );
    assert_eq!(
        drive.status.to_string(),
        "in Error, not executing: injected fault: test"
    );
    assert!(s.record().events().iter().any(|e| matches!(
        &e.kind,
        EventKind::FaultInjected { component, reason } if component == "DriveControl0" && reason == "test"
    )));
    assert!(s.record().events().iter().any(|e| matches!(
        &e.kind,
        EventKind::StateChanged { component, to: LifecycleState::Error, .. } if component == "DriveControl0"
    )));
    let component = ComponentKind::DriveControl;
    assert!(
        s.apply(&Input::Activate { component }).is_err(),
        "Error → Active is illegal"
    );
    s.apply(&Input::Reset { component }).unwrap();
    assert_eq!(s.component_state(component), LifecycleState::Inactive);
    s.apply(&Input::Activate { component }).unwrap();
    assert_eq!(s.component_state(component), LifecycleState::Active);
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
    s.apply(&param(
        ComponentKind::LocalPathPlanning,
        "RouteRemakeDistance",
        4.0,
    ))
    .unwrap();
    assert_eq!(
        s.wiring()
            .local_path_planning()
            .params()
            .route_remake_distance,
        4.0
    );
    s.apply(&Input::SetRate {
        component: ComponentKind::DriveControl,
        hz: 25.0,
    })
    .unwrap();
    assert_eq!(info(&s, ComponentKind::DriveControl).rate, 25.0);
    assert_eq!(s.rates().drive_control, 25.0);
    activate_all(&mut s);
    assert!(s.run_until(90.0, arrived).unwrap(), "arrives at 25 Hz too");
    s.apply(&Input::DeactivateAll).unwrap();
    assert_eq!(s.state(), SystemState::Inactive);
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
fn rates_beyond_a_kilohertz_or_off_the_base_tick_are_refused_where_they_enter() {
    // Built: a 1 GHz physics would make the base tick 1 ns and the set-up's 5 s of planning
    // five billion ticks.
    let fast = Rates {
        physics: 1e9,
        ..Rates::default()
    };
    let e = System::new(fast).unwrap_err().to_string();
    assert_eq!(
        e,
        "PhysicsSim0: rate 1000000000 Hz is not usable: it is above the highest rate, 1000 Hz \
         (the physics' 1 ms step)"
    );
    // Read: a scenario's rates are checked with the scenario, naming the component.
    let scenario = |rates: &str| {
        format!(
            r#"{{"name": "r", "description": "", "lesson": "",
                "map": {{"format": "json", "path": "m.json"}},
                "start": {{"x": 1, "y": 1}}, "goal": {{"x": 2, "y": 1}},
                "rates": {rates}, "time_limit": 10, "expect": {{"outcome": "arrived"}}}}"#
        )
    };
    let refused = |rates: &str| {
        Scenario::from_json(&scenario(rates))
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        refused(r#"{"motor_control": 1e9}"#),
        "scenario `r`: rates: MotorControl0: rate 1000000000 Hz is not usable: it is above the \
         highest rate, 1000 Hz (the physics' 1 ms step)"
    );
    assert_eq!(
        refused(r#"{"drive_control": 3}"#),
        "scenario `r`: rates: DriveControl0: rate 3 Hz is not usable: its period is not a whole \
         number of nanoseconds"
    );
    assert_eq!(
        refused(r#"{"drive_control": 400}"#),
        "scenario `r`: rates: DriveControl0: rate 400 Hz is not usable: its period of 2500000 ns \
         is not a whole number of base ticks (1000000 ns)"
    );
    let slow = r#"{"physics": 400, "motor_control": 400, "localization": 400,
                   "drive_control": 50, "telemetry": 50}"#;
    assert_eq!(
        refused(slow),
        "scenario `r`: rates: PhysicsSim0: rate 400 Hz is not usable: its period of 2500000 ns \
         is not a whole number of the physics' 1000000 ns steps"
    );
    assert!(Scenario::from_json(&scenario(r#"{"drive_control": 25}"#)).is_ok());
    // SetRate: the same check, and nothing changes.
    let mut s = System::new(Rates::default()).unwrap();
    let e = s
        .apply(&Input::SetRate {
            component: ComponentKind::DriveControl,
            hz: 2000.0,
        })
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "DriveControl0: rate 2000 Hz is not usable: it is above the highest rate, 1000 Hz (the \
         physics' 1 ms step)"
    );
    assert_eq!(s.rates(), Rates::default());
    assert!(
        s.set_telemetry_rate(1e12)
            .unwrap_err()
            .to_string()
            .starts_with("telemetry: ")
    );
}

#[test]
fn a_map_of_tiny_cells_loads_at_once() {
    // 40 × 40 cells of 0.1 mm under a body of radius 0.45 m: loading it checks the body
    // against the map (and a ring of outside cells), not against 8·10⁷ cells of its box.
    let mut s = System::new(Rates::default()).unwrap();
    s.load_map(GridMap::new(40, 40, 1e-4, (0.0, 0.0), vec![0; 1600]).unwrap());
    let e = s
        .apply(&Input::SetPosition {
            start: Pose::new(0.0002, 0.0002, 0.0),
            goal: Pose::new(0.0003, 0.0002, 0.0),
            direction: Direction::Forward,
        })
        .unwrap_err();
    assert!(e.to_string().contains("too close to an obstacle"), "{e}");
}

#[test]
fn refusals_say_the_request_and_the_numbers_as_sent() {
    let mut s = system(GOAL);
    let e = s
        .apply(&Input::SetGoal {
            goal: Pose::new(f64::NAN, 1.0, 0.0),
            direction: Direction::Forward,
        })
        .unwrap_err()
        .to_string();
    assert_eq!(e, "SetGoal: GoalX = NaN is not finite");
    let e = s
        .apply(&Input::MapUpdate {
            cells: vec![(1, 1, 1), (5_000_000_000, -7, 1)],
        })
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "cell (5000000000, -7) is outside the map (220 × 160 cells)"
    );
    assert_eq!(
        s.map().unwrap().is_obstacle(1, 1),
        corridor().is_obstacle(1, 1)
    );
}

#[test]
fn words_for_people_never_say_minus_zero() {
    // (The events' words come from the catalogues: `cli/tests/words.rs` checks them.)

    // Two timestamps a microsecond apart are told apart.
    let e = rtnav::errors::MotionError::TimeWentBackwards {
        port: "TargetVelocity",
        previous_s: 1.000001,
        now_s: 1.0000001,
    };
    assert_eq!(
        e.to_string(),
        "TargetVelocity: time went backwards (or stood still): 1.0000001 s after 1.000001 s"
    );
}

#[test]
fn a_run_longer_than_a_day_is_refused() {
    let json = |limit: &str| {
        format!(
            r#"{{"name": "long", "description": "", "lesson": "",
                "map": {{"format": "json", "path": "fixtures/maps/scenarios/corridor_turn.json"}},
                "start": {{"x": 1.5, "y": 1.3}}, "goal": {{"x": 12.0, "y": 1.3}},
                "time_limit": {limit}, "expect": {{"outcome": "arrived"}}}}"#
        )
    };
    let e = Scenario::from_json(&json("1e18")).unwrap_err().to_string();
    assert_eq!(
        e,
        "scenario `long`: time_limit 1000000000000000000 s is later than 86400 s (24 h of \
         simulated time), the longest a run or a replay goes"
    );
    let scenario = Scenario::from_json(&json("86400")).unwrap();
    let mut run = ScenarioRun::new(&scenario, &DirResolver::new("..")).unwrap();
    let limit = run.limit();
    let e = run.set_limit(1e18).unwrap_err().to_string();
    assert_eq!(
        e,
        "scenario `long`: until 1000000000000000000 s is later than 86400 s (24 h of simulated \
         time), the longest a run or a replay goes"
    );
    assert_eq!(run.limit(), limit, "the limit stays");
    run.set_limit(86_400.0).unwrap();
}

#[test]
fn the_set_up_plans_without_moving_and_draws_the_field() {
    let json = r#"{
        "name": "corridor", "description": "", "lesson": "",
        "map": { "format": "json", "path": "fixtures/maps/scenarios/corridor_turn.json" },
        "start": { "x": 1.5, "y": 1.3 }, "goal": { "x": 17.1, "y": 14.5, "heading_deg": 90 },
        "config": { "LocalPathPlanning": { "dmin": 0.6 } },
        "time_limit": 60.0,
        "expect": { "outcome": "arrived" }
    }"#;
    let scenario = Scenario::from_json(json).unwrap();
    let s = setup::build(
        &scenario,
        &DirResolver::new(".."),
        &Setup::of(&scenario),
        BuildOptions { full_field: true },
    )
    .unwrap();
    // The planners are Active and settled; the robot's own components wait for activation.
    assert_eq!(s.state(), SystemState::Partial);
    assert!(s.wiring().planning_settled());
    for kind in ComponentKind::ALL {
        let want = if ComponentKind::PLANNING.contains(&kind) {
            LifecycleState::Active
        } else {
            LifecycleState::Inactive
        };
        assert_eq!(s.component_state(kind), want, "{kind}");
    }
    assert_eq!(s.robot_pose(), START);
    assert_eq!(s.mission().goal(), Some(GOAL));
    assert!(!s.mission().route().is_empty());
    let lpp = s.wiring().local_path_planning();
    assert!(lpp.potential_field().is_some());
    assert!(lpp.local_plan().is_some());
    // Spec §3 Decision 0.2: the new course is planned with the potential field at once.
    assert!(
        s.record()
            .events()
            .iter()
            .any(|e| matches!(e.kind, EventKind::GlobalPlan { cells, .. } if cells > 0))
    );
    assert!(s.record().events().iter().any(|e| matches!(
        e.kind,
        EventKind::LocalPlanSent { replanned: true, cells, .. } if cells > 0
    )));
    assert!(s.stats().local_plans >= 1);

    let mut buffers = FieldBuffers::default();
    let scene = scene_of(&s, &mut buffers, "set up", Layers::ALL).unwrap();
    assert!(scene.field.is_some() && !scene.global_path.is_empty());
    assert_eq!(scene.start, Some(START));
    let mut r = Renderer::new(600, 400).unwrap();
    let frame = r.render(&scene).unwrap();
    assert_eq!((frame.width(), frame.height()), (600, 400));
    assert!(frame.data().chunks_exact(4).all(|p| p[3] == 255), "opaque");
    let pixels = frame.data().to_vec();
    let direct = Renderer::new(600, 400)
        .unwrap()
        .render_system(&s, "set up", Layers::ALL)
        .unwrap()
        .data()
        .to_vec();
    assert!(direct == pixels, "render_system draws the same scene");
}

#[test]
fn telemetry_is_bounded_and_the_same_run_gives_the_same_trace() {
    let run = |capacity: usize| {
        let mut s = system(NEAR_GOAL);
        s.set_telemetry_capacity(capacity).unwrap();
        activate_all(&mut s);
        assert!(s.run_until(60.0, arrived).unwrap());
        s
    };
    let a = run(100);
    let b = run(1 << 16);
    let (ta, tb) = (a.record().telemetry(), b.record().telemetry());
    assert_eq!(ta.trace_hash(), tb.trace_hash());
    assert_eq!(ta.total(), tb.total());
    assert_eq!(ta.samples().len(), 100);
    assert_eq!(tb.samples().len() as u64, tb.total());
    assert_eq!(ta.last(), tb.last());
    // 50 Hz: one sample every 20 ms, from t = 0.
    let t: Vec<u64> = tb.samples().iter().take(3).map(|s| s.time_ns).collect();
    assert_eq!(t, [0, 20_000_000, 40_000_000]);
    let csv = tb.to_csv();
    assert_eq!(csv.lines().count() as u64, 1 + tb.total());
    assert_eq!(a.record().events(), b.record().events());
    assert!(
        a.record().events().iter().any(|e| matches!(
            e.kind,
            EventKind::Arrived { pose, .. } if (11.99..12.0).contains(&pose.x)
        )),
        "{:?}",
        a.record().events()
    );
}

#[test]
fn scenario_events_a_new_goal_while_driving_is_reached() {
    let json = r#"{
        "name": "retarget", "description": "", "lesson": "",
        "map": { "format": "json", "path": "fixtures/maps/scenarios/corridor_turn.json" },
        "start": { "x": 1.5, "y": 1.3 }, "goal": { "x": 17.1, "y": 14.5, "heading_deg": 90 },
        "config": { "LocalPathPlanning": { "dmin": 0.6 } },
        "events": [ { "at": 2.0, "type": "goal", "goal": { "x": 12.0, "y": 1.3, "heading_deg": 180 } } ],
        "time_limit": 60.0,
        "expect": { "outcome": "arrived" }
    }"#;
    // The new goal comes at 2 s, while the robot cruises down the straight corridor: the
    // drive's first local plan (spec §3 Decision 0.2) has a one-cell jog at x ≈ 3.15 m
    // sharper than TurnInPlaceAngle, where it brakes from 3 s and turns on the spot at 5 s.
    let scenario = Scenario::from_json(json).unwrap();
    let mut run = ScenarioRun::new(&scenario, &DirResolver::new("..")).unwrap();
    run.run_to_end();
    let report = run.report();
    report.check(&scenario.expect).unwrap();
    assert_eq!(
        report.goal,
        Some(Pose::new(12.0, 1.3, core::f64::consts::PI))
    );
    assert_eq!(report.global_plans, 2);
    let record = run.system().record();
    // The timeline counts from the start of the drive, which comes after the set-up.
    let retarget = record
        .events()
        .iter()
        .find(|e| matches!(e.kind, EventKind::GoalSet { placed: false, .. }))
        .expect("the timeline's new goal")
        .time_ns;
    // It did not stop to take the new goal: no sample below 0.1 m/s in the second after it.
    let slow = record
        .telemetry()
        .samples()
        .iter()
        .filter(|s| (retarget..retarget + 1_000_000_000).contains(&s.time_ns))
        .any(|s| s.v < 0.1);
    assert!(!slow, "kept driving through the new goal");
}

/// Spec §3 Decision 0.4 "a new goal waits for its course": a new goal off the held route,
/// then a map edit soon after, at several delays within and beyond the global planner's
/// period. Before the course made for the new goal arrives no local plan is made on the old
/// route, so no planning failure is reported in the 300 ms after the goal, and a plan for
/// the new goal is sent within them.
#[test]
fn a_new_goal_then_a_map_edit_soon_after_reports_no_planning_failure() {
    // Back where it started, behind the robot: not on the held path ahead of it.
    let aside = Pose::new(START.x, START.y, core::f64::consts::PI);
    let mut driving = system(GOAL);
    activate_all(&mut driving);
    // Off the 10 Hz planners' ticks, so that the delays fall on both sides of one.
    driving.run_for(5.037).unwrap();
    assert!(driving.is_driving());
    for delay_ms in [0, 1, 5, 20, 50, 62, 63, 64, 80, 99, 150, 250] {
        let mut s = driving.try_clone().unwrap();
        let goal_ns = s.time_ns();
        s.apply(&Input::SetGoal {
            goal: aside,
            direction: Direction::Forward,
        })
        .unwrap();
        s.run_for(delay_ms as f64 * 1e-3).unwrap();
        // A cell of the west room, far from both routes: it changes, so it asks for a plan.
        s.apply(&cells(&[(20, 50, 1)])).unwrap();
        assert_eq!(last_map_update(&s), (1, 1));
        s.run_for(0.3 - delay_ms as f64 * 1e-3).unwrap();
        let window = goal_ns..goal_ns + 300_000_000;
        let failures: Vec<_> = s
            .record()
            .events()
            .iter()
            .filter(|e| window.contains(&e.time_ns))
            .filter(|e| matches!(e.kind, EventKind::PlanningFailed { .. }))
            .map(|e| (e.time_ns - goal_ns, e.kind.clone()))
            .collect();
        assert!(
            failures.is_empty(),
            "edit {delay_ms} ms after the goal: {failures:?}"
        );
        assert!(
            s.mission().plan_sent(),
            "edit {delay_ms} ms after the goal: a plan for the new goal was sent"
        );
    }
}

/// Spec §5 "Physics", Decision 0.4: the robot has no pose until a start is placed — Activate
/// and Activate all are refused, naming why, and change nothing — and an obstacle painted
/// onto the placed robot's body is refused as a whole, naming the cell, so no bump at 0 m/s
/// is ever reported.
#[test]
fn no_pose_before_a_start_and_no_obstacle_under_the_body() {
    let mut s = System::new(Rates::default()).unwrap();
    s.load_map(corridor());
    for component in ComponentKind::PLANNING {
        s.apply(&Input::Activate { component }).unwrap();
    }
    let before = s.state();
    for (input, call) in [
        (Input::ActivateAll, "ActivateAll"),
        (
            Input::Activate {
                component: ComponentKind::PhysicsSim,
            },
            "Activate",
        ),
    ] {
        let e = s.apply(&input).unwrap_err();
        assert_eq!(e, Error::System(SystemError::NotPlaced { call }), "{e}");
        assert!(e.to_string().contains("place a start first"), "{e}");
        assert_eq!(s.state(), before, "nothing changed");
    }
    // Before a start, a cell at (0, 0) is a cell like any other.
    s.apply(&cells(&[(5, 5, 1)])).unwrap();
    s.run_for(1.0).unwrap();
    assert_eq!(s.stats().bumps, 0);
    assert_eq!(
        s.component_state(ComponentKind::PhysicsSim),
        LifecycleState::Inactive
    );

    // Placed: the edit under the body is refused whole, one beside it is carried out.
    s.apply(&Input::SetPosition {
        start: START,
        goal: NEAR_GOAL,
        direction: Direction::Forward,
    })
    .unwrap();
    let (x, y) = ((START.x / 0.1) as i64, (START.y / 0.1) as i64);
    let beside = (x + 6, y, 1);
    let e = s.apply(&cells(&[beside, (x, y, 1)])).unwrap_err();
    assert_eq!(e, Error::System(SystemError::UnderRobot { x, y }), "{e}");
    let map = s.map().unwrap();
    assert!(!map.is_obstacle(x, y) && !map.is_obstacle(beside.0, beside.1));
    // The body's rim: a cell whose square is 0.45 m away is not under it; one nearer is.
    let rim = libm::ceil((START.x + 0.45) / 0.1) as i64;
    assert!(s.apply(&cells(&[(rim - 1, y, 1)])).is_err());
    s.apply(&cells(&[(rim, y, 1)])).unwrap();
    assert_eq!(activate_all(&mut s), SystemState::Active);
    s.run_for(0.5).unwrap();
    assert_eq!(s.stats().bumps, 0, "no bump at 0 m/s");
}
