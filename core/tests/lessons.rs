//! Every scenario's lesson (`fixtures/scenarios/*.json`, the page's "Try this"), checked:
//! what the lesson says happens, happens — the system driven as the page drives it (its
//! set-up with the lesson's changes, then Activate all). One test per scenario; the lesson's
//! own words are quoted above each check. The scenarios on external data (willow_garage,
//! arena) are skipped with one line without it.

use rtnav::data::{DataMissing, RepoResolver};
use rtnav::interfaces::{Direction, Pose};
use rtnav::motion::DrivePhase;
use rtnav::system::{
    ComponentKind, EventKind, Input, MapSource, OutcomeKind, Scenario, ScenarioReport, ScenarioRun,
    Setup, System, UnknownSpec, setup,
};

fn scenario(name: &str) -> Scenario {
    let path = format!("../fixtures/scenarios/{name}.json");
    Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn resolver() -> RepoResolver {
    RepoResolver::new("..")
}

/// The external data folder, or why there is none (the test is then skipped with a line).
fn data_or_skip(test: &str) -> Option<()> {
    match resolver().data() {
        Ok(_) => Some(()),
        Err(why) => {
            let why: &DataMissing = why;
            eprintln!("SKIPPED {test}: {why}");
            None
        }
    }
}

fn lesson(name: &str) -> String {
    scenario(name).lesson
}

/// The scenario's set-up with `params` changed (`component`, `name`, value).
fn setup_with(name: &str, params: &[(&str, &str, f64)]) -> Setup {
    let mut setup = Setup::of(&scenario(name));
    for &(component, param, value) in params {
        setup
            .params
            .entry(component.to_owned())
            .or_default()
            .insert(param.to_owned(), value);
    }
    setup
}

/// What a drive did, besides its report (sampled every 20 ms of simulated time).
#[derive(Debug)]
struct Drive {
    report: ScenarioReport,
    /// Largest deviation DriveControl reported \[m\].
    max_deviation: f64,
    /// Simulated time spent turning on the spot \[s\].
    turning_s: f64,
    /// Where the robot was each time it began to turn on the spot.
    turns: Vec<Pose>,
    /// Simulated time LocalPathPlanning drove backward \[s\].
    backward_s: f64,
    /// The global route's length before the drive \[m\].
    route_length: f64,
    /// The global route's smallest obstacle distance before the drive \[m\].
    route_clearance: f64,
    /// The events of the run.
    events: Vec<EventKind>,
    /// The local target's x of each local plan sent after the first `MapUpdate` that changed
    /// a cell \[m\].
    targets_after_update: Vec<f64>,
}

const SAMPLE_TICKS: u64 = 20;

/// Scenario `name` with `params`, driven to its end as the page would after Activate all.
fn drive(name: &str, params: &[(&str, &str, f64)]) -> Drive {
    let sc = scenario(name);
    let mut run = ScenarioRun::with_setup(&sc, &resolver(), &setup_with(name, params)).unwrap();
    let (route_length, route_clearance) = {
        let s = run.system();
        let map = s.map().unwrap();
        let route = s.mission().route();
        assert!(!route.is_empty(), "{name}: a route before the drive");
        (
            s.wiring()
                .global_path_planning()
                .path_length()
                .unwrap_or(f64::NAN),
            route
                .iter()
                .map(|&c| map.obstacle_distance(c))
                .fold(f64::INFINITY, f64::min),
        )
    };
    let dt = SAMPLE_TICKS as f64 * 1e-3;
    let (mut max_deviation, mut turning_s, mut backward_s) = (0.0f64, 0.0, 0.0);
    let mut turns = Vec::new();
    let mut turning = false;
    let mut targets_after_update = Vec::new();
    let mut updated = false;
    let mut seen = run.system().record().event_count();
    while run.advance(SAMPLE_TICKS).is_none() {
        let s = run.system();
        let w = s.wiring();
        let d = w.drive_control().expect("the built-in DriveControl");
        max_deviation = max_deviation.max(d.deviation().unwrap_or(0.0));
        let now = d.pursuit().phase() == DrivePhase::TurnInPlace;
        if now {
            turning_s += dt;
            if !turning {
                turns.push(s.robot_pose());
            }
        }
        turning = now;
        if w.local_path_planning().direction() == Direction::Backward {
            backward_s += dt;
        }
        for e in s.record().events_since(seen) {
            match e.kind {
                EventKind::MapUpdated { changed: 1.., .. } => updated = true,
                EventKind::LocalPlanSent {
                    cells: 1..,
                    replanned: true,
                    ..
                } if updated => {
                    if let (Some(t), Some(map)) = (w.local_path_planning().local_target(), s.map())
                    {
                        targets_after_update.push(map.cell_center(t.cell).0);
                    }
                }
                _ => {}
            }
        }
        seen = s.record().event_count();
    }
    Drive {
        report: run.report(),
        max_deviation,
        turning_s,
        turns,
        backward_s,
        route_length,
        route_clearance,
        events: run
            .system()
            .record()
            .events()
            .iter()
            .map(|e| e.kind.clone())
            .collect(),
        targets_after_update,
    }
}

fn arrived(d: &Drive, what: &str) {
    let r = &d.report;
    assert_eq!(r.outcome.kind, OutcomeKind::Arrived, "{what}: {r}");
    assert_eq!(r.bumps, 0, "{what}: {r}");
    assert!(r.min_clearance >= r.body_radius, "{what}: {r}");
}

/// The set-up of `name` (planners Active, planned, the robot waiting for Activate all).
fn set_up(name: &str) -> System {
    let s = scenario(name);
    setup::build(&s, &resolver(), &Setup::of(&s), Default::default()).unwrap()
}

// ---------------------------------------------------------------------------------------

#[test]
fn open_field() {
    let text = lesson("open_field");
    // "The global route (A*) hugs the dmin boundary around the trees"
    assert!(text.contains("hugs the dmin boundary"), "{text}");
    let plain = drive("open_field", &[]);
    arrived(&plain, "as it is");
    let dmin = 0.6;
    assert!(
        plain.route_clearance > dmin && plain.route_clearance < dmin + 0.1,
        "the route passes within a cell of the dmin boundary: {}",
        plain.route_clearance
    );
    // "Raise dmin to 1 m and watch the route swing wider"
    assert!(text.contains("Raise dmin to 1 m"), "{text}");
    let wide = drive("open_field", &[("LocalPathPlanning", "dmin", 1.0)]);
    arrived(&wide, "dmin 1 m");
    assert!(wide.route_clearance > 1.0 && wide.route_clearance > plain.route_clearance + 0.3);
    assert!(wide.route_length > plain.route_length);
    // "lower MaxVelocity in DriveControl to 0.25 m/s and the drive takes almost twice as
    // long; either way its deviation stays below Deviatinglen (0.1 m), so the first plan is
    // the only one"
    assert!(text.contains("almost twice as long"), "{text}");
    let slow = drive("open_field", &[("DriveControl", "MaxVelocity", 0.25)]);
    arrived(&slow, "MaxVelocity 0.25");
    let ratio = slow.report.sim_time / plain.report.sim_time;
    assert!(ratio > 1.6 && ratio < 2.0, "{ratio}");
    for d in [&plain, &slow] {
        assert!(d.max_deviation < 0.1, "{}", d.max_deviation);
        assert_eq!(d.report.replans, 1);
    }
}

#[test]
fn corridor_turn() {
    let text = lesson("corridor_turn");
    // "Where the path turns off the south corridor toward the east one, the control points
    // make a sharp turn: DriveControl stops there and turns on the spot"
    assert!(text.contains("turns off the south corridor"), "{text}");
    let plain = drive("corridor_turn", &[]);
    arrived(&plain, "as it is");
    assert!(plain.turning_s > 0.5, "{}", plain.turning_s);
    assert!(
        !plain.turns.is_empty() && plain.turns.iter().all(|p| p.x > 9.0 && p.y < 2.3),
        "it turns on the spot in the south corridor, past its middle: {:?}",
        plain.turns
    );
    // "Set TurnInPlaceAngle to 1.8 rad, more than the corner's 90°, and it drives round the
    // corner without stopping"
    assert!(text.contains("TurnInPlaceAngle to 1.8 rad"), "{text}");
    let round = drive(
        "corridor_turn",
        &[("DriveControl", "TurnInPlaceAngle", 1.8)],
    );
    arrived(&round, "TurnInPlaceAngle 1.8");
    assert_eq!(round.turning_s, 0.0);
    assert!(round.report.sim_time < plain.report.sim_time);
    // "set LookAheadDistance to 1 m as well and it cuts the corner: the deviation it
    // reports (InDeviating) passes Deviatinglen and LocalPathPlanning plans again from where
    // the robot is, a few times"
    assert!(text.contains("LookAheadDistance to 1 m as well"), "{text}");
    let cut = drive(
        "corridor_turn",
        &[
            ("DriveControl", "TurnInPlaceAngle", 1.8),
            ("DriveControl", "LookAheadDistance", 1.0),
        ],
    );
    arrived(&cut, "TurnInPlaceAngle 1.8, LookAheadDistance 1");
    assert_eq!(cut.turning_s, 0.0);
    assert!(cut.max_deviation > 0.1, "{}", cut.max_deviation);
    assert!(
        (3..=10).contains(&cut.report.replans),
        "a few replans: {}",
        cut.report.replans
    );
}

#[test]
fn backward_dock() {
    let text = lesson("backward_dock");
    // "Inside TargetArea the direction is chosen by where the goal lies: behind the robot
    // means backward" — the scenario's TargetArea 2 m: straight in, backward.
    let plain = drive("backward_dock", &[]);
    arrived(&plain, "as it is");
    assert!(plain.backward_s > 3.0, "{}", plain.backward_s);
    assert!(plain.report.approach_heading_deg < 5.0);
    assert!(plain.turning_s < 0.5, "{}", plain.turning_s);
    // "Set TargetArea to 0.5 m (the default) and the robot turns around, drives in forward
    // and has to turn around inside the dock"
    assert!(text.contains("Set TargetArea to 0.5 m"), "{text}");
    let forward = drive("backward_dock", &[("LocalPathPlanning", "TargetArea", 0.5)]);
    arrived(&forward, "TargetArea 0.5");
    assert!(forward.turning_s > 3.0, "{}", forward.turning_s);
    assert!(
        forward.report.approach_heading_deg > 120.0,
        "it comes in facing the dock: {}°",
        forward.report.approach_heading_deg
    );
    assert!(forward.report.sim_time > 2.0 * plain.report.sim_time);
}

#[test]
fn appearing_obstacle() {
    let text = lesson("appearing_obstacle");
    let trolley = (12.0, 12.8);
    // "The MapUpdate makes LocalPathPlanning replan … the path bends around the trolley"
    let plain = drive("appearing_obstacle", &[]);
    arrived(&plain, "as it is");
    assert!(plain.report.replans >= 2, "{}", plain.report);
    // "the potential field grows from the local target RouteRemakeDistance ahead": the plan
    // after the MapUpdate has its local target beyond the trolley.
    assert!(
        plain.targets_after_update[0] > trolley.1,
        "{:?}",
        plain.targets_after_update
    );
    // "Lower RouteRemakeDistance to 3 m, below the 7 m to the trolley: the local plan then
    // ends before the trolley, the way around it comes from GlobalPathPlanning's new route
    // (it plans again when a MapUpdate blocks its route), and the robot still gets past"
    assert!(text.contains("RouteRemakeDistance to 3 m"), "{text}");
    let short = drive(
        "appearing_obstacle",
        &[("LocalPathPlanning", "RouteRemakeDistance", 3.0)],
    );
    arrived(&short, "RouteRemakeDistance 3");
    assert!(
        short.targets_after_update[0] < trolley.0,
        "{:?}",
        short.targets_after_update
    );
    let replanned_route = short
        .events
        .iter()
        .any(|e| matches!(e, EventKind::GlobalPlan { reason, .. } if reason == "MapChanged"));
    assert!(replanned_route, "GlobalPathPlanning planned again");
    // "raise dmin to 0.8 m and the gap beside the trolley closes: once it appears, neither
    // planner finds a way, and the robot stops and says why"
    assert!(text.contains("raise dmin to 0.8 m"), "{text}");
    let closed = drive("appearing_obstacle", &[("LocalPathPlanning", "dmin", 0.8)]);
    let r = &closed.report;
    assert_eq!(r.outcome.kind, OutcomeKind::PlanningFailed, "{r}");
    assert!(
        r.path_length > 1.0,
        "it drove until the trolley appeared: {r}"
    );
    let failed: Vec<&str> = closed
        .events
        .iter()
        .filter_map(|e| match e {
            EventKind::PlanningFailed { planner, .. } => Some(planner.as_str()),
            _ => None,
        })
        .collect();
    assert!(failed.contains(&"GlobalPathPlanning") && failed.contains(&"LocalPathPlanning"));
    assert_eq!(r.bumps, 0);
}

#[test]
fn parking_wall() {
    let text = lesson("parking_wall");
    // "Set PostureConsiderationLevel to 0 …: the robot reaches the spot about 90° off it and
    // turns a quarter turn on the spot; at the default 85 it comes in only about 40° off"
    let plain = drive("parking_wall", &[]);
    arrived(&plain, "as it is");
    let none = drive(
        "parking_wall",
        &[("LocalPathPlanning", "PostureConsiderationLevel", 0.0)],
    );
    arrived(&none, "PostureConsiderationLevel 0");
    assert!(
        text.contains("about 90° off") && text.contains("about 40° off"),
        "{text}"
    );
    let (a0, a85) = (
        none.report.approach_heading_deg,
        plain.report.approach_heading_deg,
    );
    assert!((a0 - 90.0).abs() < 15.0, "PCL 0: {a0}°");
    assert!((a85 - 40.0).abs() < 10.0, "PCL 85: {a85}°");
    // "Change the goal heading to 90° and it parks facing the wall instead"
    assert!(text.contains("goal heading to 90°"), "{text}");
    let sc = scenario("parking_wall");
    let mut facing = Setup::of(&sc);
    let g = sc.goal.pose();
    facing.goal = Some([g.x, g.y, core::f64::consts::FRAC_PI_2]);
    let mut run = ScenarioRun::with_setup(&sc, &resolver(), &facing).unwrap();
    run.run_to_end();
    let r = run.report();
    assert_eq!(r.outcome.kind, OutcomeKind::Arrived, "{r}");
    assert!(
        (r.final_pose.theta.to_degrees() - 90.0).abs() < 10.0,
        "it faces the wall (north): {r}"
    );
    // "move the goal closer to the wall than dmin and SetPosition refuses it"
    assert!(text.contains("SetPosition refuses it"), "{text}");
    let mut s = set_up("parking_wall");
    let start = s.mission().start().unwrap();
    let goal = s.mission().goal().unwrap();
    let before = s.mission().clone();
    // The wall is at y = 9.8 m; 9.35 m is 0.5 m from it, closer than dmin 0.6 m.
    let refused = s.apply(&Input::SetPosition {
        start,
        goal: Pose::new(goal.x, 9.35, goal.theta),
        direction: Direction::Forward,
    });
    assert!(refused.is_err(), "{refused:?}");
    assert_eq!(s.mission(), &before, "nothing changed");
}

#[test]
fn unreachable() {
    let text = lesson("unreachable");
    // "A planning failure is a result, not a crash: the components stay Active, the GUI
    // shows the reason"
    let mut s = set_up("unreachable");
    s.apply(&Input::ActivateAll).unwrap();
    s.run_for(3.0).unwrap();
    assert_eq!(s.state().to_string(), "Active");
    let reason = s.record().events().iter().find_map(|e| match &e.kind {
        EventKind::PlanningFailed { planner, reason } if planner == "GlobalPathPlanning" => {
            Some(reason.clone())
        }
        _ => None,
    });
    assert!(reason.is_some_and(|r| r.to_string().contains("no path")));
    assert!(s.stats().path_length < 0.01, "the robot stays where it is");
    // "Open a door: with the Erase tool and a 1 m brush, erase the storeroom's west wall
    // (x ≈ 14 m) from y ≈ 8 m to 10 m — the inspector shows each cell's position in metres —
    // then set the goal again"
    assert!(
        text.contains("west wall (x ≈ 14 m) from y ≈ 8 m to 10 m"),
        "{text}"
    );
    let map = s.map().unwrap();
    let mut door = Vec::new();
    for y in 80..100 {
        for x in 135..145 {
            if map.is_obstacle(x, y) {
                door.push((x, y, 0));
            }
        }
    }
    assert!(!door.is_empty());
    let wall_x: Vec<f64> = door
        .iter()
        .map(|&(x, _, _)| map.cell_center((x as usize, 0)).0)
        .collect();
    assert!(
        wall_x.iter().all(|&x| (13.5..14.5).contains(&x)),
        "{wall_x:?}"
    );
    s.apply(&Input::MapUpdate { cells: door }).unwrap();
    let goal = s.mission().goal().unwrap();
    s.apply(&Input::SetGoal {
        goal,
        direction: Direction::Forward,
    })
    .unwrap();
    let arrived = s.run_until(90.0, |s| s.mission().is_arrived()).unwrap();
    assert!(arrived, "{:?}", s.status());
    assert_eq!(s.stats().bumps, 0);
}

#[test]
fn willow_garage() {
    if data_or_skip("willow_garage lesson").is_none() {
        return;
    }
    let text = lesson("willow_garage");
    // "unknown space counts as obstacle"
    assert!(text.contains("unknown space counts as obstacle"), "{text}");
    let sc = scenario("willow_garage");
    let MapSource::Ros { yaml, unknown } = &sc.map else {
        panic!("a ROS map")
    };
    assert_eq!(*unknown, UnknownSpec::Obstacle);
    let obstacles = |unknown: UnknownSpec| {
        MapSource::Ros {
            yaml: yaml.clone(),
            unknown,
        }
        .load(&resolver())
        .unwrap()
        .cells()
        .iter()
        .filter(|&&c| c == 1)
        .count()
    };
    assert!(obstacles(UnknownSpec::Obstacle) > obstacles(UnknownSpec::Free));
    // "Lower dmin to 0.5 m: the route cuts its corners closer and gets shorter"
    assert!(text.contains("Lower dmin to 0.5 m"), "{text}");
    let plain = drive("willow_garage", &[]);
    arrived(&plain, "as it is");
    let close = drive("willow_garage", &[("LocalPathPlanning", "dmin", 0.5)]);
    arrived(&close, "dmin 0.5");
    assert!(close.route_length < plain.route_length - 0.2);
    assert!(close.route_clearance < plain.route_clearance);
    // "below 0.5 m the page warns that the body can touch obstacles (dmin − half a cell <
    // radiusOfBodyArea 0.45 m)"
    assert!(text.contains("below 0.5 m the page warns"), "{text}");
    let mut s = set_up("willow_garage");
    for (dmin, warned) in [(0.5, false), (0.49, true)] {
        s.apply(&Input::SetParam {
            component: ComponentKind::LocalPathPlanning,
            name: "dmin".to_owned(),
            value: dmin,
        })
        .unwrap();
        assert_eq!(
            s.wiring().clearance_warning().is_some(),
            warned,
            "dmin {dmin}"
        );
    }
}

#[test]
fn arena() {
    if data_or_skip("arena lesson").is_none() {
        return;
    }
    let text = lesson("arena");
    // "MovingAI's .map has no scale: the scenario reads it at 0.5 m per cell (grid_size)"
    assert!(text.contains("0.5 m per cell"), "{text}");
    let s = set_up("arena");
    assert_eq!(s.map().unwrap().grid_size(), 0.5);
    assert!(
        !text.contains("Change it"),
        "the page offers no grid_size: {text}"
    );
    // "Compare with… LocalPathPlanning.dmin 1 m: the ghost keeps further from the pillars,
    // and the table's min clearance grows from 0.71 m to 1.06 m, while the path is no longer
    // (34.1 m both)": what the compare view's table shows.
    assert!(
        text.contains("Compare with… LocalPathPlanning.dmin 1 m"),
        "{text}"
    );
    assert!(text.contains("from 0.71 m to 1.06 m"), "{text}");
    let plain = drive("arena", &[]);
    arrived(&plain, "as it is");
    let wide = drive("arena", &[("LocalPathPlanning", "dmin", 1.0)]);
    arrived(&wide, "dmin 1");
    assert!(wide.route_clearance > plain.route_clearance);
    let (a, b) = (plain.report.min_clearance, wide.report.min_clearance);
    assert!(
        (a - 0.71).abs() < 0.005 && (b - 1.06).abs() < 0.005,
        "{a} → {b}"
    );
    let (a, b) = (plain.report.path_length, wide.report.path_length);
    assert!(
        (a - 34.1).abs() < 0.05 && (b - 34.1).abs() < 0.05,
        "{a} → {b}"
    );
}
