//! The system's description ([`SystemGraph`]) is the wiring's: every port it names
//! is a port of that component with that type, every connection it describes carries data
//! in a run, every port of seeds 000 and 002 that rtnav implements is in it, and a cut of
//! `TargetVelocity` is a logged request that makes MotorControl stop safely until restored.

use std::collections::BTreeSet;

use rtnav::components::{INPUT_TIMEOUT_NS, MotorStatus};
use rtnav::errors::SystemError;
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::GridMap;
use rtnav::map::formats::json;
use rtnav::system::{
    ComponentKind, ConnectionKind, EventKind, Input, PortKind, Rates, System, SystemGraph,
};

const TARGET_VELOCITY: &str = "DriveControl.TargetVelocity->MotorControl.TargetVelocity";

/// The office floor of `corridor_turn` (22 × 16 m, 0.1 m cells).
fn corridor() -> GridMap {
    json::load(&std::fs::read_to_string("../fixtures/maps/scenarios/corridor_turn.json").unwrap())
        .unwrap()
}

/// The corridor map, `dmin` 0.6 m, start and goal set along the south corridor.
fn system() -> System {
    let mut s = System::new(Rates::default()).unwrap();
    s.apply(&Input::SetParam {
        component: ComponentKind::LocalPathPlanning,
        name: "dmin".to_owned(),
        value: 0.6,
    })
    .unwrap();
    s.load_map(corridor());
    s.apply(&Input::SetPosition {
        start: Pose::new(1.5, 1.3, 0.0),
        goal: Pose::new(12.0, 1.3, 0.0),
        direction: Direction::Forward,
    })
    .unwrap();
    s
}

fn graph(s: &System) -> SystemGraph {
    s.wiring().graph()
}

/// Runs until the robot is past `x` at cruising speed.
fn under_way(s: &mut System, x: f64) {
    let speed = |s: &System| s.wiring().physics().physics().body_velocity().0;
    assert!(
        s.run_until(6.0, |s| s.robot_pose().x > x && speed(s) > 0.45)
            .unwrap(),
        "the robot drives"
    );
}

/// A wall of obstacle cells across the corridor, `ahead` metres in front of the robot.
fn wall(s: &System, ahead: f64, thickness: i64) -> Input {
    let x0 = ((s.robot_pose().x + ahead) / 0.1) as i64;
    Input::MapUpdate {
        cells: (x0..x0 + thickness)
            .flat_map(|x| (5..22).map(move |y| (x, y, 1)))
            .collect(),
    }
}

/// The ids of the connections that carried something in `g`.
fn carried(g: &SystemGraph) -> BTreeSet<String> {
    g.connections
        .iter()
        .filter(|c| c.carried > 0)
        .map(|c| c.id.clone())
        .collect()
}

#[test]
fn the_description_names_real_ports_and_every_seed_port() {
    let s = system();
    let g = graph(&s);
    let names: Vec<_> = g.components.iter().map(|c| c.name).collect();
    let mut expected = vec!["InventGUI"];
    expected.extend(ComponentKind::ALL.map(ComponentKind::name));
    assert_eq!(names, expected);
    for c in &g.components {
        let mut seen = BTreeSet::new();
        for p in &c.ports {
            assert!(seen.insert((p.name, p.kind)), "{}.{} twice", c.name, p.name);
        }
        assert_eq!(c.rtc, c.state.is_some(), "{}", c.name);
    }
    // Every connection joins a port of the right kind and type at each end.
    for e in &g.connections {
        let port = |end: &rtnav::system::Endpoint, kinds: [PortKind; 1]| {
            let c = g.component(end.component).expect("a component");
            c.ports
                .iter()
                .find(|p| p.name == end.port && kinds.contains(&p.kind))
                .unwrap_or_else(|| panic!("{}: no port {}.{}", e.id, end.component, end.port))
                .clone()
        };
        let (from, to) = match e.kind {
            ConnectionKind::Data => (port(&e.from, [PortKind::Out]), port(&e.to, [PortKind::In])),
            ConnectionKind::Service => {
                let to = port(&e.to, [PortKind::Provided]);
                let c = g.component(e.from.component).unwrap();
                let from = c
                    .ports
                    .iter()
                    .find(|p| {
                        p.name == e.from.port
                            && matches!(p.kind, PortKind::Out | PortKind::Required)
                    })
                    .unwrap_or_else(|| panic!("{}: no caller port", e.id))
                    .clone();
                (from, to)
            }
        };
        if e.kind == ConnectionKind::Data {
            assert_eq!(
                (from.interface, to.interface),
                (e.interface, e.interface),
                "{}",
                e.id
            );
        } else {
            assert_eq!(to.interface, e.interface, "{}", e.id);
        }
        assert_eq!(
            e.cuttable,
            e.kind == ConnectionKind::Data && e.to.component != "InventGUI"
        );
    }
    // The ports seeds 000 (LocalPathPlanning) and 002 (MotorControl) name.
    let has = |component: &str, port: &str, kind: PortKind| {
        g.component(component)
            .unwrap()
            .ports
            .iter()
            .any(|p| p.name == port && p.kind == kind)
    };
    for (port, kind) in [
        ("InCurrentPosition", PortKind::In),
        ("InDeviating", PortKind::In),
        ("InventGUIProv", PortKind::Provided),
        ("MapBuilderProv", PortKind::Provided),
        ("MapMaintenanceProv", PortKind::Provided),
        ("GlobalPathProv", PortKind::Provided),
        ("InventGUICons", PortKind::Out),
        ("DriveCons", PortKind::Out),
        ("BumpCons", PortKind::Out),
    ] {
        assert!(
            has("LocalPathPlanning", port, kind),
            "LocalPathPlanning.{port}"
        );
    }
    for (port, kind) in [
        ("TargetVelocity", PortKind::In),
        ("InCurrentWheelAngle", PortKind::In),
        ("InSimulatedPosition", PortKind::In),
        ("Torque", PortKind::Out),
        ("OutCurrentWheelAngle", PortKind::Out),
        ("OutSimulatedPositionToInventGUI", PortKind::Out),
        ("OutSimulatedPositionToLocalization", PortKind::Out),
        ("InventGUIProvPort", PortKind::Provided),
        ("BumpProvPort", PortKind::Provided),
    ] {
        assert!(has("MotorControl", port, kind), "MotorControl.{port}");
    }
    let target = g
        .connection(TARGET_VELOCITY)
        .expect("TargetVelocity's connection");
    assert_eq!(
        (target.interface, target.cuttable, target.cut),
        ("TimedVelocity", true, false)
    );
    // The Graphviz text has every component and connection.
    let dot = g.to_dot();
    assert!(dot.starts_with("digraph rtnav {"));
    assert_eq!(dot.matches(" -> ").count(), g.connections.len());
    for c in &g.components {
        assert!(
            dot.contains(&format!("\"{}\" [label=", c.name)),
            "{}",
            c.name
        );
    }
}

#[test]
fn every_described_connection_carries_data_in_a_run() {
    let mut all = BTreeSet::new();
    let mut seen = BTreeSet::new();

    // A drive with a gain change, map updates behind the robot, a wall across the corridor
    // ahead (a safety stop and failed plans), SafeMode and Clear.
    let mut s = system();
    s.apply(&Input::SetPdGain {
        p_l: 5.0,
        p_r: 5.0,
        d_l: 2.0,
        d_r: 2.0,
    })
    .unwrap();
    s.apply(&Input::ActivateAll).unwrap();
    under_way(&mut s, 2.5);
    s.apply(&Input::MapUpdate {
        cells: vec![(3, 5, 1)],
    })
    .unwrap();
    s.run_for(0.5).unwrap();
    let blocked = wall(&s, 1.6, 2);
    s.apply(&blocked).unwrap();
    s.run_for(3.0).unwrap();
    let g = graph(&s);
    all.extend(g.connections.iter().map(|c| c.id.clone()));
    seen.extend(carried(&g));
    s.apply(&Input::SafeMode).unwrap();
    s.apply(&Input::Clear).unwrap();
    seen.extend(carried(&graph(&s)));

    // A bump: a crate dropped just ahead of the moving robot's body (radius 0.45 m; one on
    // the body is refused, spec §5 Decision 0.4), when its front is 2 mm short of a cell.
    let mut s = system();
    s.apply(&Input::ActivateAll).unwrap();
    under_way(&mut s, 2.0);
    assert!(
        s.run_until(2.0, |s| (s.robot_pose().x + 0.45) / 0.1 % 1.0 > 0.98)
            .unwrap()
    );
    let crate_ = wall(&s, 0.455, 3);
    s.apply(&crate_).unwrap();
    assert!(s.run_until(2.0, |s| s.stats().bumps > 0).unwrap(), "a bump");
    s.run_for(0.1).unwrap();
    seen.extend(carried(&graph(&s)));

    let missing: Vec<_> = all.difference(&seen).collect();
    assert!(
        missing.is_empty(),
        "connections that carried nothing: {missing:#?}"
    );

    // The last samples and calls are shown with their timestamps.
    let g = graph(&s);
    let motor = g.component("MotorControl").unwrap();
    let port = |name: &str| motor.ports.iter().find(|p| p.name == name).unwrap();
    let stop = port("BumpProvPort").last.as_ref().expect("Stop was called");
    assert_eq!(stop.text, "Stop()");
    let velocity = port("TargetVelocity")
        .last
        .as_ref()
        .expect("a velocity arrived");
    assert!(
        velocity.text.starts_with("TimedVelocity {tm: "),
        "{}",
        velocity.text
    );
    assert!(velocity.text.contains(", vx: "), "{}", velocity.text);
}

#[test]
fn cutting_target_velocity_stops_motor_control_safely_until_it_is_restored() {
    let mut s = system();
    s.apply(&Input::ActivateAll).unwrap();
    under_way(&mut s, 2.5);
    let cut = Input::CutConnection {
        connection: TARGET_VELOCITY.to_owned(),
    };
    let restore = Input::RestoreConnection {
        connection: TARGET_VELOCITY.to_owned(),
    };

    // Refused requests change nothing.
    let events = s.record().event_count();
    for (bad, what) in [
        (
            Input::CutConnection {
                connection: "DriveControl.TargetVelocity".to_owned(),
            },
            "unknown",
        ),
        (
            Input::CutConnection {
                connection: "DriveControl.SafetyStop->InventGUI.SafetyStop".to_owned(),
            },
            "kept",
        ),
        (restore.clone(), "already"),
    ] {
        let e = s.apply(&bad).unwrap_err();
        match (what, e) {
            ("unknown", rtnav::Error::System(SystemError::UnknownConnection { known, .. })) => {
                assert!(known.contains(TARGET_VELOCITY), "{known}");
            }
            ("kept", rtnav::Error::System(SystemError::ConnectionKept { .. }))
            | ("already", rtnav::Error::System(SystemError::ConnectionAlready { .. })) => {}
            (what, e) => panic!("{what}: {e:?}"),
        }
    }
    assert_eq!(s.record().event_count(), events);

    let before = graph(&s).connection(TARGET_VELOCITY).unwrap().carried;
    s.apply(&cut).unwrap();
    assert!(graph(&s).connection(TARGET_VELOCITY).unwrap().cut);
    let logged = s.record().events().back().unwrap();
    assert_eq!(
        logged.kind,
        EventKind::ConnectionCut {
            connection: "DriveControl.TargetVelocity → MotorControl.TargetVelocity".to_owned()
        }
    );
    assert!(s.apply(&cut).is_err(), "a second cut is refused");

    // No velocity reaches MotorControl: after INPUT_TIMEOUT_NS it stops, zero torque.
    let stale = |s: &System| {
        matches!(
            s.wiring()
                .motor_control()
                .expect("the built-in MotorControl")
                .status(),
            MotorStatus::SafeStop(_)
        )
    };
    let t0 = s.time_ns();
    assert!(
        s.run_until(1.0, stale).unwrap(),
        "MotorControl stops safely"
    );
    let waited = s.time_ns() - t0;
    assert!(
        (INPUT_TIMEOUT_NS - 20_000_000..=INPUT_TIMEOUT_NS + 2_000_000).contains(&waited),
        "{waited} ns"
    );
    let status = s
        .wiring()
        .motor_control()
        .expect("the built-in MotorControl")
        .status()
        .to_string();
    assert!(status.contains("TargetVelocity"), "{status}");
    assert_eq!(
        graph(&s).connection(TARGET_VELOCITY).unwrap().carried,
        before
    );
    // Zero torque: the robot coasts, slower and slower (spec §4's safe stop).
    let speed = |s: &System| s.wiring().physics().physics().body_velocity().0;
    let mut speeds = vec![speed(&s)];
    for _ in 0..3 {
        s.run_for(1.0).unwrap();
        speeds.push(speed(&s));
    }
    assert!(speeds.windows(2).all(|w| w[1] < w[0]), "{speeds:?}");
    assert!(speeds[3] < 0.6 * speeds[0], "{speeds:?}");
    assert_eq!(
        s.wiring()
            .motor_control()
            .expect("the built-in MotorControl")
            .last_torque(),
        [0.0; 2]
    );

    // Restored: the drive resumes.
    s.apply(&restore).unwrap();
    assert!(matches!(
        &s.record().events().back().unwrap().kind,
        EventKind::ConnectionRestored { .. }
    ));
    let running = |s: &System| {
        matches!(
            s.wiring()
                .motor_control()
                .expect("the built-in MotorControl")
                .status(),
            MotorStatus::Running
        )
    };
    assert!(
        s.run_until(0.1, running).unwrap(),
        "MotorControl runs again"
    );
    let x = s.robot_pose().x;
    s.run_for(1.5).unwrap();
    assert!(s.robot_pose().x > x + 0.3, "the robot drives on");
    assert!(graph(&s).connection(TARGET_VELOCITY).unwrap().carried > before);
}
