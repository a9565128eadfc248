//! What a user interface reads from a `Session` and draws on its `Screen`, with exact
//! expectations: the page's handle (`rtnav-wasm`) is one call into each of these.

use std::path::Path;

use rtnav::errors::SystemError;
use rtnav::render::Screen;
use rtnav::rtc::LifecycleState;
use rtnav::system::{
    DirectionView, EventLevel, EventView, Input, MapSource, PickedFiles, PoseView, Scenario,
    Session,
};

/// The repository's root (the fixtures' paths are relative to it).
fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// A scenario fixture's JSON and the map file it names.
fn scenario(name: &str) -> (String, PickedFiles) {
    let json =
        std::fs::read_to_string(root().join(format!("fixtures/scenarios/{name}.json"))).unwrap();
    let s = Scenario::from_json(&json).unwrap();
    let MapSource::Json { path } = &s.map else {
        panic!("test scenarios use JSON maps");
    };
    let mut files = PickedFiles::new();
    files.add(path, std::fs::read(root().join(path)).unwrap());
    (json, files)
}

/// A session with the scenario `name` loaded, and a 640 × 400 screen showing it.
fn loaded(name: &str) -> (Session, Screen) {
    let mut session = Session::new().unwrap();
    let (json, files) = scenario(name);
    session.load_scenario_text(&json, &files).unwrap();
    let mut screen = Screen::new(640, 400).unwrap();
    screen.replaced(&session);
    (session, screen)
}

fn states(session: &Session) -> Vec<(&'static str, LifecycleState)> {
    session
        .components()
        .iter()
        .map(|c| (c.name, c.info.state))
        .collect()
}

fn kinds(events: &[EventView]) -> Vec<&str> {
    events.iter().map(|e| e.kind.as_str()).collect()
}

/// Runs simulated seconds in page-sized steps (16 ms of wall time at the current speed).
fn run(session: &mut Session, seconds: f64, stop: impl Fn(&Session) -> bool) -> bool {
    let frames = (seconds * 1000.0 / (16.0 * session.speed())) as usize;
    for _ in 0..frames {
        session.advance(16.0);
        if stop(session) {
            return true;
        }
    }
    false
}

fn arrived(session: &Session) -> bool {
    session.telemetry().arrived
}

fn pose(x: f64, y: f64, theta_deg: f64) -> PoseView {
    PoseView { x, y, theta_deg }
}

#[test]
fn a_scenario_loads_with_its_plan_and_the_robot_waiting() {
    let (mut session, mut screen) = loaded("open_field");
    use LifecycleState::{Active, Inactive};
    assert_eq!(
        states(&session),
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
    assert_eq!(session.state().to_string(), "Partial");
    let plan = session.plan();
    assert_eq!(plan.goal, Some(pose(23.0, 15.5, 90.0)));
    assert!(plan.global_path.len() > 20 && !plan.local_path.is_empty());
    assert!(plan.control_points.len() >= 2);
    let events = session.event_views();
    let k = kinds(&events);
    for expected in ["MapLoaded", "GoalSet", "GlobalPlan", "LocalPlanSent"] {
        assert!(k.contains(&expected), "{expected} missing from {k:?}");
    }
    assert_eq!(session.scenario_view().unwrap().name, "open_field");
    let map = session.map_view().unwrap();
    assert_eq!(map.name, "fixtures/maps/scenarios/open_field.json");
    // Drawn at once: a frame, then nothing new until something changes.
    assert!(screen.draw(&session).unwrap());
    assert!(!screen.draw(&session).unwrap());
    session.advance(16.0);
    screen.changed();
    assert!(screen.draw(&session).unwrap());
    assert_eq!(screen.frame().data().len(), 640 * 400 * 4);
}

#[test]
fn one_frame_read_holds_the_clock_telemetry_components_new_events_and_exercise() {
    let (mut session, _) = loaded("open_field");
    let first = session.frame();
    assert_eq!(first.clock.time_s, session.time_s());
    assert_eq!(first.clock.tick_s, 0.001);
    // (Compared as the page receives them: a deviation without a path is NaN, `null` there.)
    let json = |v: &rtnav::system::TelemetryView| serde_json::to_string(v).unwrap();
    assert_eq!(json(&first.telemetry), json(&session.telemetry()));
    assert_eq!(first.components, session.components());
    assert!(kinds(&first.events).contains(&"GoalSet"));
    assert_eq!(first.exercise, session.exercise_view());
    // The events of a frame are handed out once.
    assert_eq!(session.frame().events, Vec::new());
    session.all(&Input::ActivateAll).unwrap();
    let next = session.frame();
    assert!(
        kinds(&next.events).contains(&"StateChanged"),
        "{:?}",
        kinds(&next.events)
    );
}

#[test]
fn activate_all_drives_to_the_goal() {
    let (mut session, _) = loaded("open_field");
    assert_eq!(
        session.all(&Input::ActivateAll).unwrap().to_string(),
        "Active"
    );
    session.set_speed(16.0).unwrap();
    assert!(run(&mut session, 120.0, arrived));
    let t = session.telemetry();
    assert!(t.arrived && t.distance_to_goal.unwrap() <= 0.1, "{t:?}");
    assert_eq!(t.bumps, 0);
    // The preview's plan only: the page asked for no other.
    assert_eq!(t.local_plans, 1);
    let events = session.event_views();
    assert_eq!(events.iter().filter(|e| e.kind == "Arrived").count(), 1);
    let arrived = events.iter().find(|e| e.kind == "Arrived").unwrap();
    assert_eq!(arrived.level, EventLevel::Success);
    assert!(arrived.data["pose"]["x"].is_number(), "{:?}", arrived.data);
}

#[test]
fn a_goal_inside_an_obstacle_is_refused_and_the_old_plan_stays() {
    let (mut session, _) = loaded("open_field");
    let before = session.plan();
    session.event_views();
    // Cell (0, 0) is the fence.
    assert_eq!(session.cell(0, 0), Some(true));
    let corner = session.map().unwrap().cell_center((0, 0));
    let err = session
        .set_goal_at(pose(corner.0, corner.1, 0.0), DirectionView::Forward)
        .unwrap_err();
    assert!(err.to_string().contains("goal"), "{err}");
    assert_eq!(session.plan(), before);
    assert_eq!(kinds(&session.event_views()), Vec::<&str>::new());
    // Not a number: refused the same way.
    assert!(
        session
            .set_goal_at(pose(f64::NAN, 1.0, 0.0), DirectionView::Forward)
            .is_err()
    );
    assert_eq!(session.plan(), before);
}

#[test]
fn inject_fault_error_with_reason_reset_and_activate_again() {
    let (mut session, _) = loaded("open_field");
    session.all(&Input::ActivateAll).unwrap();
    session
        .inject_fault("DriveControl", "requested from the page")
        .unwrap();
    assert!(session.components()[7].fault_pending);
    run(&mut session, 0.1, |_| false);
    let dc = &session.components()[7];
    assert_eq!(dc.info.state, LifecycleState::Error);
    assert_eq!(dc.colour, "#ff0000");
    assert_eq!(
        dc.info.last_error,
        Some(rtnav::Reason::InjectedFault(
            "requested from the page".to_owned()
        ))
    );
    assert_eq!(session.state().to_string(), "Error");
    let events = session.event_views();
    let error = events.iter().find(|e| e.kind == "ComponentError").unwrap();
    assert_eq!(error.level, EventLevel::Error);
    let activate = |component| Input::Activate { component };
    // Activate is refused in Error, with the reason.
    assert_eq!(
        session
            .lifecycle("DriveControl", activate)
            .unwrap_err()
            .to_string(),
        "component `DriveControl0`: cannot activate while Error"
    );
    assert_eq!(
        session
            .lifecycle("DriveControl", |component| Input::Reset { component })
            .unwrap(),
        LifecycleState::Inactive
    );
    assert_eq!(session.components()[7].info.last_error, None);
    assert_eq!(
        session.lifecycle("DriveControl", activate).unwrap(),
        LifecycleState::Active
    );
    assert_eq!(session.state().to_string(), "Active");
    assert_eq!(
        session
            .lifecycle("Planner", activate)
            .unwrap_err()
            .to_string(),
        "no component named `Planner` (expected one of MapBuilder, MapMaintenance, \
         PhysicsSim, MotorControl, Localization, GlobalPathPlanning, LocalPathPlanning, \
         DriveControl)"
    );
}

#[test]
fn painting_on_the_robot_is_refused_and_reset_keeps_what_is_held() {
    let (mut session, _) = loaded("open_field");
    session.all(&Input::ActivateAll).unwrap();
    run(&mut session, 2.0, |_| false);
    let at = session.telemetry().pose;
    let (cx, cy) = session.world_to_cell(at.x, at.y).unwrap();
    let (xs, ys): (Vec<i32>, Vec<i32>) = (-1..=1)
        .flat_map(|dx| (-1..=1).map(move |dy| (cx as i32 + dx, cy as i32 + dy)))
        .unzip();
    // Spec §5 "Physics", Decision 0.4: an obstacle under the body is refused whole, so it
    // is never a bump at 0 m/s; the robot drives on.
    let e = session.set_cells(&xs, &ys, 1).unwrap_err();
    assert!(
        matches!(e, rtnav::Error::System(SystemError::UnderRobot { .. })),
        "{e}"
    );
    assert_eq!(session.cell(cx as i64, cy as i64), Some(false));
    run(&mut session, 0.5, |_| false);
    let physics = &session.components()[2];
    assert_eq!(physics.info.state, LifecycleState::Active);
    assert!(!kinds(&session.event_views()).contains(&"Bump"));
    // A component in Error, then Reset: what is held stays.
    session.inject_fault("PhysicsSim", "test").unwrap();
    run(&mut session, 0.5, |_| false);
    assert_eq!(session.components()[2].info.state, LifecycleState::Error);
    let goal = session.plan().goal;
    let where_ = session.telemetry().pose;
    assert_eq!(
        session.all(&Input::ResetAll).unwrap().to_string(),
        "Inactive"
    );
    assert_eq!(session.plan().goal, goal);
    assert_eq!(session.telemetry().pose, where_);
    assert_eq!(
        session.all(&Input::ActivateAll).unwrap().to_string(),
        "Active"
    );
    session.set_speed(16.0).unwrap();
    // DriveControl kept its path and LocalPathPlanning plans afresh on its activation
    // (spec 0.2): the robot drives on with nothing sent again by the page.
    assert!(run(&mut session, 120.0, arrived));
    assert_eq!(session.telemetry().bumps, 0);
}

/// Spec §5 "Physics", Decision 0.4: a map loaded from a file has no start, so Activate all
/// is refused with the reason, nothing changes, and no bump is ever reported.
#[test]
fn activate_all_on_a_loaded_map_before_a_start_is_refused_with_the_reason() {
    let mut session = Session::new().unwrap();
    let map = rtnav::map::formats::json::load(
        &std::fs::read_to_string(root().join("fixtures/maps/scenarios/two_rooms.json")).unwrap(),
    )
    .unwrap();
    session.load_map("two_rooms.json", map).unwrap();
    let before = session.state();
    let e = session.all(&Input::ActivateAll).unwrap_err();
    assert!(
        matches!(
            e,
            rtnav::Error::System(SystemError::NotPlaced {
                call: "ActivateAll"
            })
        ),
        "{e}"
    );
    assert_eq!(session.state(), before);
    run(&mut session, 1.0, |_| false);
    assert_eq!(session.telemetry().bumps, 0);
    assert!(!kinds(&session.event_views()).contains(&"Bump"));
}

#[test]
fn an_obstacle_painted_on_the_path_is_driven_around() {
    let (mut session, _) = loaded("open_field");
    session.all(&Input::ActivateAll).unwrap();
    session.set_speed(16.0).unwrap();
    run(&mut session, 3.0, |_| false);
    session.event_views();
    // A 5 × 5 block on the global path, a third of the way along.
    let path = session.plan().global_path;
    let (px, py) = path[path.len() / 3];
    let (xs, ys): (Vec<i32>, Vec<i32>) = (-2..=2)
        .flat_map(|dx| (-2..=2).map(move |dy| (px as i32 + dx, py as i32 + dy)))
        .unzip();
    session.set_cells(&xs, &ys, 1).unwrap();
    run(&mut session, 1.0, |_| false);
    let events = session.event_views();
    let k = kinds(&events);
    // One update; the block is on the route, so GlobalPathPlanning plans again (spec 0.2)
    // and LocalPathPlanning plans around it, for the update and for the new course.
    assert_eq!(k.first(), Some(&"MapUpdated"));
    assert_eq!(k.iter().filter(|&&k| k == "MapUpdated").count(), 1);
    assert!(k.contains(&"GlobalPlan"), "{k:?}");
    let sent = events.iter().rfind(|e| e.kind == "LocalPlanSent").unwrap();
    // A potential-field plan around it (000 §5.2.4.9).
    assert_eq!(sent.data["replanned"], true);
    let block: Vec<(usize, usize)> = xs
        .iter()
        .zip(&ys)
        .map(|(&x, &y)| (x as usize, y as usize))
        .collect();
    assert!(session.plan().local_path.iter().all(|c| !block.contains(c)));
    assert!(run(&mut session, 120.0, arrived));
    assert_eq!(session.telemetry().bumps, 0);
}

#[test]
fn a_bad_map_file_is_refused_and_the_map_stays() {
    let (mut session, _) = loaded("open_field");
    let before = session.map_view();
    let mut bad = PickedFiles::new();
    bad.add("broken.json", b"{\"width\": 3".to_vec());
    let err = session.load_map_files(&bad, 1.0).unwrap_err();
    assert_eq!(err.file.as_deref(), Some("broken.json"));
    assert!(
        err.to_string().starts_with("`broken.json`: rtnav JSON"),
        "{err}"
    );
    assert_eq!(session.map_view(), before);
    assert_eq!(session.scenario_view().unwrap().name, "open_field");
    // A good one replaces the scenario: planners Active, no goal yet.
    let mut good = PickedFiles::new();
    let wall = "#".repeat(20);
    let inside = format!("#{}#", ".".repeat(18));
    let mut rows = vec![wall.clone()];
    rows.extend(std::iter::repeat_n(inside, 8));
    rows.push(wall);
    let room = serde_json::json!({"width": 20, "height": 10, "grid_size": 0.25, "rows": rows});
    good.add("room.json", room.to_string().into_bytes());
    session.load_map_files(&good, 1.0).unwrap();
    let map = session.map_view().unwrap();
    assert_eq!(
        (map.name.as_str(), map.width, map.height),
        ("room.json", 20, 10)
    );
    assert!(session.scenario_view().is_none() && session.plan().goal.is_none());
    assert_eq!(session.state().to_string(), "Partial");
    session
        .set_position_at(
            pose(1.0, 1.2, 0.0),
            pose(4.0, 1.2, 0.0),
            DirectionView::Forward,
        )
        .unwrap();
    assert!(!session.plan().global_path.is_empty());
}

#[test]
fn a_scenarios_timed_obstacle_counts_from_the_start_of_the_drive() {
    let (mut session, _) = loaded("appearing_obstacle");
    let obstacles = session.map_view().unwrap().obstacles;
    // Standing for a minute: nothing appears.
    run(&mut session, 60.0, |_| false);
    assert_eq!(session.map_view().unwrap().obstacles, obstacles);
    session.all(&Input::ActivateAll).unwrap();
    session.set_speed(16.0).unwrap();
    assert!(run(&mut session, 120.0, arrived));
    assert!(session.map_view().unwrap().obstacles > obstacles);
    assert!(session.telemetry().local_plans >= 1);
    assert_eq!(session.telemetry().bumps, 0);
}

#[test]
fn layers_by_name_the_view_and_world_to_cell() {
    let (session, mut screen) = loaded("open_field");
    screen.set_layer("heat_map", false).unwrap();
    assert!(!screen.layers().heat_map && screen.layers().trail);
    assert_eq!(
        screen.set_layer("heatmap", true).unwrap_err().to_string(),
        "no layer named `heatmap` (layers: occupancy, dmin_zone, heat_map, global_path, \
         local_path, control_points, local_target, robot, trail, start_goal, scale_bar, \
         legend, caption)"
    );
    // Every layer the type has can be named (the names are the serialized fields).
    let names = serde_json::to_value(screen.layers()).unwrap();
    for name in names.as_object().unwrap().keys() {
        screen.set_layer(name, true).unwrap();
    }
    let view = screen.view(&session).unwrap();
    let (px, py) = view.world_to_pixel(2.5, 2.5);
    let (x, y) = view.pixel_to_world(px, py);
    assert!((x - 2.5).abs() < 1e-9 && (y - 2.5).abs() < 1e-9);
    let (cx, cy) = view.world_to_pixel(2.55, 2.55);
    assert_eq!(
        screen.pixel_to_cell(&session, cx, cy),
        session.world_to_cell(2.55, 2.55)
    );
    let map = session.map_view().unwrap();
    assert_eq!(session.world_to_cell(-1.0, 0.0), None);
    let g = map.grid_size;
    assert_eq!(session.world_to_cell(2.5 * g, 3.5 * g), Some((2, 3)));
    assert_eq!(session.cell(-1, 0), None);
    let mut session = session;
    assert_eq!(
        session.set_cells(&[1, 2], &[1], 1).unwrap_err().to_string(),
        "MapUpdate: 2 x indices but 1 y indices"
    );
}

#[test]
fn the_status_comes_with_its_fields_for_the_page_to_say() {
    let (mut session, _) = loaded("open_field");
    let t = session.telemetry();
    assert_eq!(t.status_kind, "ready");
    assert!(t.status_fields.is_empty(), "{:?}", t.status_fields);
    session.all(&Input::ActivateAll).unwrap();
    session
        .inject_fault("DriveControl", "requested from the page")
        .unwrap();
    run(&mut session, 0.1, |_| false);
    let t = session.telemetry();
    assert_eq!(t.status_kind, "component_error");
    assert_eq!(
        serde_json::Value::Object(t.status_fields),
        serde_json::json!({
            "component": "DriveControl0",
            "reason": {"kind": "injected_fault", "words": "requested from the page"},
            // The fault came 0.1 s into the drive: the robot had not moved yet.
            "motion": "stands",
        }),
        "{:?}",
        session.status()
    );
}

#[test]
fn the_clock_turns_wall_time_times_speed_into_whole_ticks() {
    let mut session = Session::new().unwrap();
    // 16.7 ms → 16 ticks, 0.7 ms kept; 0.4 ms more → 1 tick; clamps and junk count as 0.
    assert_eq!(
        [16.7, 0.4, 0.9, -5.0, f64::NAN, 1000.0].map(|ms| session.advance(ms)),
        [16, 1, 1, 0, 0, 100]
    );
    session.set_speed(0.25).unwrap();
    assert_eq!([16.0, 16.0].map(|ms| session.advance(ms)), [4, 4]);
    session.set_speed(16.0).unwrap();
    assert_eq!(session.advance(16.0), 256);
    session.set_paused(true);
    assert_eq!(session.advance(16.0), 0);
    session.step_ticks(1).unwrap();
    assert_eq!(
        session.clock().time_s,
        (16 + 1 + 1 + 100 + 8 + 256 + 1) as f64 * 1e-3
    );
    assert_eq!(
        session.set_speed(32.0).unwrap_err().to_string(),
        "speed 32× is outside 0.25× to 16×"
    );
    assert_eq!(session.speed(), 16.0);
}

#[test]
fn the_brush_covers_cells_around_the_cell_under_it_or_a_square_in_metres() {
    let (session, _) = loaded("open_field");
    let map = session.map_view().unwrap();
    let g = map.grid_size;
    let (cx, cy) = (map.origin.0 + 10.5 * g, map.origin.1 + 20.5 * g);
    let square = |x0: usize, x1: usize, y0: usize, y1: usize| -> Vec<(usize, usize)> {
        (y0..=y1)
            .flat_map(|y| (x0..=x1).map(move |x| (x, y)))
            .collect()
    };
    assert_eq!(session.brush_cells(cx, cy, 1.0, false), [(10, 20)]);
    assert_eq!(
        session.brush_cells(cx, cy, 2.0, false),
        square(10, 11, 20, 21)
    );
    assert_eq!(
        session.brush_cells(cx, cy, 3.0, false),
        square(9, 11, 19, 21)
    );
    assert_eq!(
        session.brush_cells(cx, cy, 3.0 * g, true),
        square(9, 11, 19, 21)
    );
    // A square smaller than a cell still paints the cell under it.
    assert_eq!(session.brush_cells(cx, cy, 0.1 * g, true), [(10, 20)]);
    // Only cells of the map.
    let (ox, oy) = map.origin;
    assert_eq!(
        session.brush_cells(ox + 0.5 * g, oy + 0.5 * g, 3.0, false),
        square(0, 1, 0, 1)
    );
    assert_eq!(
        session.brush_cells(ox - 5.0 * g, oy, 3.0, false),
        Vec::new()
    );
    assert_eq!(session.brush_cells(f64::NAN, oy, 3.0, false), Vec::new());
}

#[test]
fn a_frozen_robot_shows_no_speed_after_reset_all_mid_drive() {
    let (mut session, _) = loaded("open_field");
    session.all(&Input::ActivateAll).unwrap();
    assert!(run(&mut session, 8.0, |s| s.telemetry().v > 0.3));
    let driving = session.frame().telemetry;
    assert!(driving.v > 0.3, "driving at {} m/s", driving.v);
    // Reset all mid-drive: every component Inactive, the physics frozen where it stood.
    session.all(&Input::ResetAll).unwrap();
    let pose = session.telemetry().pose;
    run(&mut session, 1.0, |_| false);
    assert_eq!(session.telemetry().pose, pose, "the robot does not move");
    // The read-outs say what the robot does now, not the last sample's speeds.
    for t in [session.telemetry(), session.frame().telemetry] {
        assert_eq!((t.v, t.w), (0.0, 0.0), "a frozen robot shows no speed");
        assert_eq!(t.status_kind, "ready", "{:?}", t.status_fields);
    }
}

#[test]
fn a_paused_clock_is_a_cause_the_status_carries() {
    let (mut session, _) = loaded("open_field");
    session.all(&Input::ActivateAll).unwrap();
    assert!(run(&mut session, 8.0, |s| s.telemetry().v > 0.3));
    session.set_paused(true);
    let t = session.frame().telemetry;
    assert_eq!(
        t.status_kind, "driving",
        "what the robot does stays the kind"
    );
    assert_eq!(
        t.status_fields.get("paused"),
        Some(&serde_json::Value::Bool(true))
    );
    session.set_paused(false);
    assert_eq!(session.telemetry().status_fields.get("paused"), None);
}
