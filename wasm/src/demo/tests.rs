//! The handle's behaviour, natively: what the page relies on, with exact expectations.

use super::*;
use rtnav::interfaces::Direction;

/// The repository's root (the fixtures' paths are relative to it).
fn root() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// A scenario fixture's JSON and the map file it names.
fn scenario(name: &str) -> (String, Files) {
    let json =
        std::fs::read_to_string(root().join(format!("fixtures/scenarios/{name}.json"))).unwrap();
    let s = Scenario::from_json(&json).unwrap();
    let path = match &s.map {
        rtnav::system::MapSource::Json { path } => path.clone(),
        other => panic!("test scenarios use JSON maps, not {other:?}"),
    };
    let mut files = Files::new();
    files.add(&path, std::fs::read(root().join(&path)).unwrap());
    (json, files)
}

fn loaded(name: &str) -> Inner {
    let mut demo = Inner::new(640, 400).unwrap();
    let (json, files) = scenario(name);
    demo.load_scenario(&json, &files).unwrap();
    demo
}

fn states(demo: &Inner) -> Vec<(&'static str, LifecycleState)> {
    demo.components()
        .iter()
        .map(|c| (c.name, c.info.state))
        .collect()
}

fn kinds(events: &[EventView]) -> Vec<&str> {
    events.iter().map(|e| e.kind.as_str()).collect()
}

/// Runs simulated seconds in page-sized steps (16 ms of wall time at the current speed).
fn run(demo: &mut Inner, seconds: f64, stop: impl Fn(&Inner) -> bool) -> bool {
    let frames = (seconds * 1000.0 / (16.0 * demo.session.speed())) as usize;
    for _ in 0..frames {
        demo.step(16.0);
        if stop(demo) {
            return true;
        }
    }
    false
}

#[test]
fn step_turns_wall_time_times_speed_into_whole_ticks() {
    let mut demo = Inner::new(64, 64).unwrap();
    // 16.7 ms → 16 ticks, 0.7 ms kept; 0.4 ms more → 1 tick; clamps and junk count as 0.
    assert_eq!(
        [16.7, 0.4, 0.9, -5.0, f64::NAN, 1000.0].map(|ms| demo.step(ms)),
        [16, 1, 1, 0, 0, 100]
    );
    demo.set_speed(0.25).unwrap();
    assert_eq!([16.0, 16.0].map(|ms| demo.step(ms)), [4, 4]);
    demo.set_speed(16.0).unwrap();
    assert_eq!(demo.step(16.0), 256);
    demo.session.set_paused(true);
    assert_eq!(demo.step(16.0), 0);
    demo.run_ticks(1).unwrap();
    assert_eq!(
        demo.system().time_ns(),
        (16 + 1 + 1 + 100 + 8 + 256 + 1) * 1_000_000
    );
    assert_eq!(
        demo.set_speed(32.0).unwrap_err(),
        "speed 32× is outside 0.25× to 16×"
    );
    assert_eq!(demo.session.speed(), 16.0);
}

#[test]
fn a_scenario_loads_with_its_plan_and_the_robot_waiting() {
    let mut demo = loaded("open_field");
    use LifecycleState::{Active, Inactive};
    assert_eq!(
        states(&demo),
        [
            ("MapBuilder", Active),
            ("MapMaintenance", Active),
            ("PhysicsSim", Inactive),
            ("MotorControl", Inactive),
            ("Localization", Inactive),
            ("GlobalPathPlanning", Active),
            ("LocalPathPlanning", Active),
            ("DriveControl", Inactive),
        ]
    );
    assert_eq!(demo.system().state().to_string(), "Partial");
    let plan = demo.plan();
    assert_eq!(
        plan.goal,
        Some(PoseView {
            x: 23.0,
            y: 15.5,
            theta_deg: 90.0
        })
    );
    assert!(plan.global_path.len() > 20 && !plan.local_path.is_empty());
    assert!(plan.control_points.len() >= 2);
    let events = demo.take_events();
    let k = kinds(&events);
    for expected in ["MapLoaded", "GoalSet", "GlobalPlan", "LocalPlanSent"] {
        assert!(k.contains(&expected), "{expected} missing from {k:?}");
    }
    let scenario = demo.scenario_view().unwrap();
    assert_eq!(scenario.name, "open_field");
    let map = demo.map_view().unwrap();
    assert_eq!(map.name, "fixtures/maps/scenarios/open_field.json");
    // Drawn at once: a frame, then nothing new until something changes.
    assert!(demo.render().unwrap());
    assert!(!demo.render().unwrap());
    demo.step(16.0);
    assert!(demo.render().unwrap());
    assert_eq!(demo.renderer.frame().data().len(), 640 * 400 * 4);
}

#[test]
fn activate_all_drives_to_the_goal() {
    let mut demo = loaded("open_field");
    assert_eq!(demo.all(&Input::ActivateAll), "Active");
    demo.set_speed(16.0).unwrap();
    assert!(run(&mut demo, 120.0, |d| d.system().mission().is_arrived()));
    let t = demo.telemetry();
    assert!(t.arrived && t.distance_to_goal.unwrap() <= 0.1, "{t:?}");
    assert_eq!(t.bumps, 0);
    // The preview's plan only: the page asked for no other.
    assert_eq!(t.local_plans, 1);
    let events = demo.take_events();
    assert_eq!(events.iter().filter(|e| e.kind == "Arrived").count(), 1);
    let arrived = events.iter().find(|e| e.kind == "Arrived").unwrap();
    assert_eq!(arrived.level, "success");
    assert!(arrived.text.starts_with("arrived at ("), "{}", arrived.text);
}

#[test]
fn a_goal_inside_an_obstacle_is_refused_and_the_old_plan_stays() {
    let mut demo = loaded("open_field");
    let before = demo.plan();
    demo.take_events();
    // Cell (0, 0) is the fence.
    let map = demo.system().map().unwrap();
    assert!(map.is_obstacle(0, 0));
    let (x, y) = map.cell_center((0, 0));
    let err = demo
        .apply(&Input::SetGoal {
            goal: Pose::new(x, y, 0.0),
            direction: Direction::Forward,
        })
        .unwrap_err();
    assert!(err.contains("goal"), "{err}");
    assert_eq!(demo.plan(), before);
    assert_eq!(kinds(&demo.take_events()), Vec::<&str>::new());
    // Not a number: refused the same way.
    assert!(
        demo.apply(&Input::SetGoal {
            goal: Pose::new(f64::NAN, 1.0, 0.0),
            direction: Direction::Forward
        })
        .is_err()
    );
    assert_eq!(demo.plan(), before);
}

#[test]
fn inject_fault_error_with_reason_reset_and_activate_again() {
    let mut demo = loaded("open_field");
    demo.all(&Input::ActivateAll);
    demo.inject_fault("DriveControl").unwrap();
    assert!(demo.components()[7].fault_pending);
    run(&mut demo, 0.1, |_| false);
    let dc = &demo.components()[7];
    assert_eq!(dc.info.state, LifecycleState::Error);
    assert_eq!(dc.colour, "#ff0000");
    assert_eq!(
        dc.info.last_error,
        Some(rtnav::Reason::InjectedFault(
            "requested from the page".to_owned()
        ))
    );
    assert_eq!(demo.system().state().to_string(), "Error");
    let events = demo.take_events();
    let error = events.iter().find(|e| e.kind == "ComponentError").unwrap();
    assert_eq!(error.level, "error");
    // Activate is refused in Error, with the reason.
    assert_eq!(
        demo.activate("DriveControl").unwrap_err(),
        "component `DriveControl0`: cannot activate while Error"
    );
    assert_eq!(
        demo.reset("DriveControl").unwrap(),
        LifecycleState::Inactive
    );
    assert_eq!(demo.components()[7].info.last_error, None);
    assert_eq!(
        demo.activate("DriveControl").unwrap(),
        LifecycleState::Active
    );
    assert_eq!(demo.system().state().to_string(), "Active");
    assert_eq!(
        demo.activate("Planner").unwrap_err(),
        "no component named `Planner` (expected one of MapBuilder, MapMaintenance, \
         PhysicsSim, MotorControl, Localization, GlobalPathPlanning, LocalPathPlanning, \
         DriveControl)"
    );
}

#[test]
fn painting_on_the_robot_is_a_bump_and_reset_keeps_what_is_held() {
    let mut demo = loaded("open_field");
    demo.all(&Input::ActivateAll);
    run(&mut demo, 2.0, |_| false);
    let pose = demo.system().robot_pose();
    let map = demo.system().map().unwrap();
    let (cx, cy) = map.world_to_cell(pose.x, pose.y).unwrap();
    let (xs, ys): (Vec<i32>, Vec<i32>) = (-1..=1)
        .flat_map(|dx| (-1..=1).map(move |dy| (cx as i32 + dx, cy as i32 + dy)))
        .unzip();
    demo.set_cells(&xs, &ys, 1).unwrap();
    run(&mut demo, 0.5, |_| false);
    let physics = &demo.components()[2];
    assert_eq!(physics.info.state, LifecycleState::Error);
    assert!(
        matches!(physics.info.last_error, Some(rtnav::Reason::Bump(_))),
        "{:?}",
        physics.info.last_error
    );
    let events = demo.take_events();
    assert!(kinds(&events).contains(&"Bump"));
    let goal = demo.plan().goal;
    let where_ = demo.system().robot_pose();
    assert_eq!(demo.all(&Input::ResetAll), "Inactive");
    assert_eq!(demo.plan().goal, goal);
    assert_eq!(demo.system().robot_pose(), where_);
    assert_eq!(demo.cell(cx as i32, cy as i32), 1);
    // Erase the obstacle: the robot can drive on.
    demo.set_cells(&xs, &ys, 0).unwrap();
    assert_eq!(demo.all(&Input::ActivateAll), "Active");
    demo.set_speed(16.0).unwrap();
    // DriveControl kept its path and LocalPathPlanning plans afresh on its activation
    // (spec 0.2): the robot drives on with nothing sent again by the page.
    assert!(run(&mut demo, 120.0, |d| d.system().mission().is_arrived()));
    assert_eq!(demo.telemetry().bumps, 1);
}

#[test]
fn an_obstacle_painted_on_the_path_is_driven_around() {
    let mut demo = loaded("open_field");
    demo.all(&Input::ActivateAll);
    demo.set_speed(16.0).unwrap();
    run(&mut demo, 3.0, |_| false);
    demo.take_events();
    // A 5 × 5 block on the global path, a third of the way along.
    let path = demo.plan().global_path;
    let (px, py) = path[path.len() / 3];
    let (xs, ys): (Vec<i32>, Vec<i32>) = (-2..=2)
        .flat_map(|dx| (-2..=2).map(move |dy| (px as i32 + dx, py as i32 + dy)))
        .unzip();
    demo.set_cells(&xs, &ys, 1).unwrap();
    run(&mut demo, 1.0, |_| false);
    let events = demo.take_events();
    let k = kinds(&events);
    // One update; the block is on the route, so GlobalPathPlanning plans again (spec 0.2)
    // and LocalPathPlanning plans around it, for the update and for the new course.
    assert_eq!(k.first(), Some(&"MapUpdated"));
    assert_eq!(k.iter().filter(|&&k| k == "MapUpdated").count(), 1);
    assert!(k.contains(&"GlobalPlan"), "{k:?}");
    let sent = events.iter().rfind(|e| e.kind == "LocalPlanSent").unwrap();
    // A potential-field plan around it (000 §5.2.4.9).
    assert_eq!(sent.data["replanned"], true);
    assert!(sent.text.starts_with("local plan sent: "), "{}", sent.text);
    let block: Vec<(usize, usize)> = xs
        .iter()
        .zip(&ys)
        .map(|(&x, &y)| (x as usize, y as usize))
        .collect();
    let plan = demo.plan();
    assert!(plan.local_path.iter().all(|c| !block.contains(c)));
    assert!(run(&mut demo, 120.0, |d| d.system().mission().is_arrived()));
    assert_eq!(demo.telemetry().bumps, 0);
}

#[test]
fn a_bad_map_file_is_refused_and_the_map_stays() {
    let mut demo = loaded("open_field");
    let before = demo.map_view();
    let mut bad = Files::new();
    bad.add("broken.json", b"{\"width\": 3".to_vec());
    let err = demo.load_map_files(&bad, 1.0).unwrap_err();
    assert!(err.starts_with("`broken.json`: rtnav JSON"), "{err}");
    assert_eq!(demo.map_view(), before);
    assert_eq!(demo.scenario_view().unwrap().name, "open_field");
    // A good one replaces the scenario: planners Active, no goal yet.
    let mut good = Files::new();
    let wall = "#".repeat(20);
    let inside = format!("#{}#", ".".repeat(18));
    let mut rows = vec![wall.clone()];
    rows.extend(std::iter::repeat_n(inside, 8));
    rows.push(wall);
    let room = serde_json::json!({"width": 20, "height": 10, "grid_size": 0.25, "rows": rows});
    good.add("room.json", room.to_string().into_bytes());
    demo.load_map_files(&good, 1.0).unwrap();
    let map = demo.map_view().unwrap();
    assert_eq!(
        (map.name.as_str(), map.width, map.height),
        ("room.json", 20, 10)
    );
    assert!(demo.scenario_view().is_none() && demo.plan().goal.is_none());
    assert_eq!(demo.system().state().to_string(), "Partial");
    demo.apply(&Input::SetPosition {
        start: Pose::new(1.0, 1.2, 0.0),
        goal: Pose::new(4.0, 1.2, 0.0),
        direction: Direction::Forward,
    })
    .unwrap();
    assert!(!demo.plan().global_path.is_empty());
}

#[test]
fn a_scenarios_timed_obstacle_counts_from_the_start_of_the_drive() {
    let mut demo = loaded("appearing_obstacle");
    let obstacles = demo.map_view().unwrap().obstacles;
    // Standing for a minute: nothing appears.
    run(&mut demo, 60.0, |_| false);
    assert_eq!(demo.map_view().unwrap().obstacles, obstacles);
    demo.all(&Input::ActivateAll);
    demo.set_speed(16.0).unwrap();
    assert!(run(&mut demo, 120.0, |d| d.system().mission().is_arrived()));
    assert!(demo.map_view().unwrap().obstacles > obstacles);
    assert!(demo.telemetry().local_plans >= 1);
    assert_eq!(demo.telemetry().bumps, 0);
}

#[test]
fn layers_by_name_and_the_view() {
    let mut demo = loaded("open_field");
    demo.set_layer("heat_map", false).unwrap();
    assert!(!demo.layers.heat_map && demo.layers.trail);
    assert!(
        demo.set_layer("heatmap", true)
            .unwrap_err()
            .starts_with("no layer named `heatmap` (layers: caption, control_points, dmin_zone,")
    );
    let view = demo.view().unwrap();
    let (px, py) = view.world_to_pixel(2.5, 2.5);
    let (x, y) = view.pixel_to_world(px, py);
    assert!((x - 2.5).abs() < 1e-9 && (y - 2.5).abs() < 1e-9);
    assert_eq!(
        demo.set_cells(&[1, 2], &[1], 1).unwrap_err(),
        "MapUpdate: 2 x indices but 1 y indices"
    );
}

#[test]
fn the_status_comes_with_its_fields_for_the_page_to_say() {
    let mut demo = loaded("open_field");
    let t = demo.telemetry();
    assert_eq!(t.status_kind, "ready");
    assert!(t.status_fields.is_empty(), "{:?}", t.status_fields);
    demo.all(&Input::ActivateAll);
    demo.inject_fault("DriveControl").unwrap();
    run(&mut demo, 0.1, |_| false);
    let t = demo.telemetry();
    assert_eq!(t.status_kind, "component_error");
    assert_eq!(
        serde_json::Value::Object(t.status_fields),
        serde_json::json!({
            "component": "DriveControl0",
            "reason": {"kind": "injected_fault", "words": FAULT_REASON},
            // The fault came 0.1 s into the drive: the robot had not moved yet.
            "motion": "stands",
        }),
        "{}",
        t.status
    );
}
