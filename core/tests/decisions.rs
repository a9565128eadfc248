//! Every decision marked 0.2 in the spec (`docs/spec.md`), one test each, named after it,
//! driven through the system as the page and the runner drive it.

use rtnav::Error;
use rtnav::errors::{MapError, SystemError};
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::MapUpdate;
use rtnav::rtc::{LifecycleState, Time};
use rtnav::system::{
    BuildOptions, ComponentKind, DirResolver, EventKind, Input, OutcomeKind, Scenario, ScenarioRun,
    Setup, System, setup,
};

fn scenario(name: &str) -> Scenario {
    let path = format!("../fixtures/scenarios/{name}.json");
    Scenario::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn resolver() -> DirResolver {
    DirResolver::new("..")
}

/// The set-up of `name` (planners Active, the plan made, the robot waiting).
fn set_up(name: &str) -> System {
    let s = scenario(name);
    setup::build(&s, &resolver(), &Setup::of(&s), BuildOptions::default()).unwrap()
}

fn with_params(name: &str, params: &[(&str, &str, f64)]) -> Setup {
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

fn apply(s: &mut System, input: Input) {
    s.apply(&input).unwrap_or_else(|e| panic!("{input:?}: {e}"));
}

fn facts_since(s: &System, seen: u64) -> Vec<EventKind> {
    s.record()
        .events_since(seen)
        .map(|e| e.kind.clone())
        .collect()
}

fn param(s: &System, kind: ComponentKind, name: &str) -> f64 {
    s.wiring().config(kind).unwrap().value(name).unwrap()
}

#[test]
fn decision_a_new_course_raises_the_local_plan_so_the_posture_matters_headless() {
    // Every drive starts with a potential-field plan, not the global path as received.
    let s = set_up("parking_wall");
    let first_sent = s
        .record()
        .events()
        .iter()
        .find_map(|e| match e.kind {
            EventKind::LocalPlanSent { replanned, .. } => Some(replanned),
            _ => None,
        })
        .expect("a path was sent");
    assert!(
        first_sent,
        "the first path sent is a local (potential-field) plan"
    );
    // parking_wall with PostureConsiderationLevel 0 and 85 comes in at different headings.
    let approach = |level: f64| {
        let setup = with_params(
            "parking_wall",
            &[("LocalPathPlanning", "PostureConsiderationLevel", level)],
        );
        let mut run =
            ScenarioRun::with_setup(&scenario("parking_wall"), &resolver(), &setup).unwrap();
        run.run_to_end();
        let report = run.report();
        assert_eq!(report.outcome.kind, OutcomeKind::Arrived, "{report}");
        report.approach_heading_deg
    };
    let (none, default) = (approach(0.0), approach(85.0));
    println!("approach heading error: PCL 0 → {none:.1}°, PCL 85 → {default:.1}°");
    assert!(
        (none - default).abs() > 10.0,
        "PCL 0: {none:.1}°, PCL 85: {default:.1}°"
    );
}

/// Cells of a ring of obstacles around `(cx, cy)` at Chebyshev radius `r`.
fn ring(cx: i64, cy: i64, r: i64, value: i16) -> Vec<(i64, i64, i16)> {
    let mut cells = Vec::new();
    for d in -r..=r {
        cells.extend([
            (cx + d, cy - r, value),
            (cx + d, cy + r, value),
            (cx - r, cy + d, value),
            (cx + r, cy + d, value),
        ]);
    }
    cells
}

#[test]
fn decision_after_a_failure_local_planning_retries_every_second_and_on_every_map_update() {
    let mut s = set_up("open_field");
    apply(&mut s, Input::ActivateAll);
    s.run_for(3.0).unwrap();
    // Walls all around the robot, clear of its body: no way out.
    let map = s.map().unwrap();
    let p = s.robot_pose();
    let (cx, cy) = map.world_to_cell(p.x, p.y).unwrap();
    let cells = ring(cx as i64, cy as i64, 12, 1);
    apply(
        &mut s,
        Input::MapUpdate {
            cells: cells.clone(),
        },
    );
    s.run_for(1.0).unwrap();
    let lpp = s.wiring().local_path_planning();
    assert!(lpp.retry_at_ns().is_some(), "a failure, and a retry due");
    let plans = lpp.plan_count();
    s.run_for(3.0).unwrap();
    let retries = s.wiring().local_path_planning().plan_count() - plans;
    assert_eq!(retries, 3, "one attempt a second");
    let (v, w) = s.wiring().physics().physics().body_velocity();
    assert!(
        v.abs() < 1e-3 && w.abs() < 1e-3,
        "the robot stands meanwhile"
    );
    assert!(
        s.status()
            .to_string()
            .starts_with("waiting for a plan (retrying")
    );
    // Opening the ring is a MapUpdate: planned again at once, and the drive resumes.
    let seen = s.record().event_count();
    let east: Vec<_> = cells
        .iter()
        .filter(|c| c.0 == cx as i64 + 12)
        .map(|&(x, y, _)| (x, y, 0))
        .collect();
    apply(&mut s, Input::MapUpdate { cells: east });
    s.run_for(0.3).unwrap();
    assert!(
        facts_since(&s, seen)
            .iter()
            .any(|f| matches!(f, EventKind::LocalPlanSent { cells: 1.., .. })),
        "{:?}",
        facts_since(&s, seen)
    );
    assert!(s.run_until(120.0, |s| s.mission().is_arrived()).unwrap());
}

#[test]
fn decision_global_planning_replans_when_a_map_update_blocks_its_route() {
    let mut s = set_up("open_field");
    apply(&mut s, Input::ActivateAll);
    s.run_for(2.0).unwrap();
    let route = s.mission().route().to_vec();
    // A wall across the middle of the route, well ahead of the robot.
    let (mx, my) = route[route.len() / 2];
    let wall: Vec<_> = (-6..=6)
        .map(|d| (mx as i64 + d, my as i64 - d, 1))
        .collect();
    let seen = s.record().event_count();
    apply(&mut s, Input::MapUpdate { cells: wall });
    s.run_for(0.5).unwrap();
    let replanned = facts_since(&s, seen)
        .into_iter()
        .any(|f| matches!(f, EventKind::GlobalPlan { reason, .. } if reason == "MapChanged"));
    assert!(replanned, "a new route because the map changed under it");
    let dmin = s.wiring().global_path_planning().params().dmin;
    let map = s.map().unwrap();
    assert!(
        s.mission().route().iter().all(|&c| map.is_clear(c, dmin)),
        "the new route keeps out of the new obstacle's dmin zone"
    );
    assert!(s.run_until(120.0, |s| s.mission().is_arrived()).unwrap());
    assert_eq!(s.stats().bumps, 0);
}

#[test]
fn decision_one_dmin_setting_either_planner_sets_both_and_a_bundle_must_agree() {
    let mut s = set_up("open_field");
    let (lpp, gpp) = (
        ComponentKind::LocalPathPlanning,
        ComponentKind::GlobalPathPlanning,
    );
    for (kind, value) in [(lpp, 0.8), (gpp, 0.7)] {
        apply(
            &mut s,
            Input::SetParam {
                component: kind,
                name: "dmin".into(),
                value,
            },
        );
        assert_eq!(
            (param(&s, lpp, "dmin"), param(&s, gpp, "dmin")),
            (value, value)
        );
    }
    // Out of range on either: refused on both.
    assert!(
        s.apply(&Input::SetParam {
            component: gpp,
            name: "dmin".into(),
            value: -1.0,
        })
        .is_err()
    );
    assert_eq!(param(&s, lpp, "dmin"), 0.7);
    // A bundle giving the two planners different values is refused, naming both.
    let text = s
        .wiring()
        .to_conf()
        .replacen("conf.default.dmin: 0.7", "conf.default.dmin: 0.9", 1);
    let e = s.apply(&Input::LoadConf { text }).unwrap_err();
    assert!(
        matches!(e, Error::System(SystemError::DminMismatch { .. })),
        "{e}"
    );
    assert!(
        e.to_string().contains("GlobalPathPlanning0")
            && e.to_string().contains("LocalPathPlanning0"),
        "{e}"
    );
    assert_eq!(param(&s, gpp, "dmin"), 0.7);
}

#[test]
fn decision_one_dmin_warns_whenever_the_body_can_touch() {
    let mut s = set_up("open_field");
    let warnings = |s: &System| {
        s.record()
            .events()
            .iter()
            .filter(|e| matches!(e.kind, EventKind::ClearanceWarning { .. }))
            .count()
    };
    let grid = s.map().unwrap().grid_size();
    let radius = s.wiring().motor_geometry().radius_of_body_area;
    let dmin = param(&s, ComponentKind::LocalPathPlanning, "dmin");
    assert!(dmin - grid / 2.0 >= radius, "the scenario itself is safe");
    assert_eq!(warnings(&s), 0);
    apply(
        &mut s,
        Input::SetParam {
            component: ComponentKind::LocalPathPlanning,
            name: "dmin".into(),
            value: 0.3,
        },
    );
    assert_eq!(warnings(&s), 1);
    let last = &s.record().events().back().unwrap().kind;
    assert!(
        matches!(last, rtnav::system::EventKind::ClearanceWarning { .. }),
        "{last:?}"
    );
}

#[test]
fn open_field_with_dmin_1_2_set_once_keeps_the_global_route_out_of_the_dmin_zone() {
    let setup = with_params("open_field", &[("LocalPathPlanning", "dmin", 1.2)]);
    let s = setup::build(
        &scenario("open_field"),
        &resolver(),
        &setup,
        BuildOptions::default(),
    )
    .unwrap();
    let map = s.map().unwrap();
    let route = s.mission().route();
    assert!(!route.is_empty());
    assert!(route.iter().all(|&c| map.is_clear(c, 1.2)));
    assert_eq!(
        s.wiring().global_path_planning().params().dmin,
        1.2,
        "GlobalPathPlanning follows"
    );
}

#[test]
fn decision_an_update_that_changes_no_cell_requests_nothing() {
    let mut s = set_up("open_field");
    apply(&mut s, Input::ActivateAll);
    s.run_for(1.0).unwrap();
    let map = s.map().unwrap();
    let free = (0..map.width() as i64)
        .find(|&x| !map.is_obstacle(x, 5))
        .unwrap();
    let plans = (s.stats().local_plans, s.stats().global_plans);
    let planned = s.wiring().local_path_planning().plan_count();
    apply(
        &mut s,
        Input::MapUpdate {
            cells: vec![(free, 5, 0)],
        },
    );
    s.run_for(0.5).unwrap();
    assert_eq!((s.stats().local_plans, s.stats().global_plans), plans);
    assert_eq!(s.wiring().local_path_planning().plan_count(), planned);
    assert_eq!(
        s.wiring().map_maintenance().sent_count(),
        0,
        "nothing was sent"
    );
    assert!(s.record().events().iter().any(|e| matches!(
        e.kind,
        EventKind::MapUpdated {
            cells: 1,
            changed: 0
        }
    )));
}

#[test]
fn decision_reactivation_resets_only_the_progress_flags() {
    let mut s = set_up("open_field");
    apply(&mut s, Input::ActivateAll);
    s.run_for(5.0).unwrap();
    let lpp = ComponentKind::LocalPathPlanning;
    let held = s.wiring().local_path_planning().held_path().to_vec();
    let plans = s.wiring().local_path_planning().plan_count();
    apply(&mut s, Input::Deactivate { component: lpp });
    apply(&mut s, Input::Activate { component: lpp });
    let flags = s.wiring().local_path_planning().flags();
    assert!(
        flags.map && flags.position && flags.path,
        "the service side's data stays"
    );
    assert_eq!(s.wiring().local_path_planning().held_path(), &held[..]);
    let seen = s.record().event_count();
    s.run_for(0.2).unwrap();
    assert!(
        s.wiring().local_path_planning().plan_count() > plans,
        "the first tick after activation plans afresh"
    );
    assert!(
        facts_since(&s, seen)
            .iter()
            .any(|f| matches!(f, EventKind::LocalPlanSent { .. })),
        "and sends afresh"
    );
    assert!(s.run_until(120.0, |s| s.mission().is_arrived()).unwrap());
}

#[test]
fn decision_on_activation_values_apply_only_when_activation_succeeds() {
    let mut s = set_up("open_field");
    let motor = ComponentKind::MotorControl;
    for (name, value) in [
        ("radiusOfBodyArea", 0.3),
        ("leftWheelID", 1.0),
        ("rightWheelID", 1.0),
    ] {
        apply(
            &mut s,
            Input::SetParam {
                component: motor,
                name: name.into(),
                value,
            },
        );
    }
    apply(&mut s, Input::Activate { component: motor });
    assert_eq!(s.component_state(motor), LifecycleState::Error);
    let config = s.wiring().config(motor).unwrap();
    assert_eq!(config.effective_value("radiusOfBodyArea").unwrap(), 0.45);
    assert!(config.is_pending("radiusOfBodyArea").unwrap());
    assert_eq!(s.wiring().motor_geometry().radius_of_body_area, 0.45);
    // Put right, reset and activate: now they apply.
    apply(
        &mut s,
        Input::SetParam {
            component: motor,
            name: "rightWheelID".into(),
            value: 0.0,
        },
    );
    apply(&mut s, Input::Reset { component: motor });
    apply(&mut s, Input::Activate { component: motor });
    assert_eq!(s.component_state(motor), LifecycleState::Active);
    assert_eq!(s.wiring().motor_geometry().radius_of_body_area, 0.3);
}

#[test]
fn decision_a_timestamp_with_nsec_of_a_second_or_more_is_refused_where_it_enters() {
    let bad = Time {
        sec: 0,
        nsec: 1_500_000_000,
    };
    let s = set_up("open_field");
    let update = MapUpdate::from_cells(&[(3, 3, 1)], bad);
    let mut map = s.map().unwrap().clone();
    let e = map.map_update(&update).unwrap_err();
    assert!(
        matches!(
            e,
            MapError::BadTimestamp {
                nsec: 1_500_000_000,
                ..
            }
        ),
        "{e}"
    );
    let mut global = rtnav::components::GlobalPathPlanning::new("g");
    global.set_map(s.map().unwrap().clone());
    let mut local = rtnav::components::LocalPathPlanning::new("l");
    local.set_grid_map(s.map().unwrap().clone());
    for e in [
        global.map_update(&update).unwrap_err(),
        local.map_update(&update).unwrap_err(),
    ] {
        assert!(
            matches!(e, Error::Map(MapError::BadTimestamp { .. })),
            "the same refusal in both planners: {e}"
        );
    }
    assert_eq!(s.map().unwrap().cells(), map.cells(), "nothing changed");
}

#[test]
fn decision_escape_from_the_margin_plans_out_of_the_dmin_zone() {
    // dmin 0.6 m on 0.1 m cells; an obstacle 0.6 m from the robot's cell centre puts it
    // within dmin (≤ dmin), yet 0.5 m from the body's centre to the cell's square: no touch.
    let setup = with_params("open_field", &[("LocalPathPlanning", "dmin", 0.6)]);
    let mut s = setup::build(
        &scenario("open_field"),
        &resolver(),
        &setup,
        BuildOptions::default(),
    )
    .unwrap();
    let map = s.map().unwrap();
    let p = s.robot_pose();
    let (cx, cy) = map.world_to_cell(p.x, p.y).unwrap();
    let (cx, cy) = (cx as i64, cy as i64);
    let post = vec![(cx, cy - 6, 1)];
    let seen = s.record().event_count();
    apply(&mut s, Input::MapUpdate { cells: post });
    s.run_until_planned(5.0).unwrap();
    let map = s.map().unwrap();
    assert!(
        !map.is_clear((cx as usize, cy as usize), 0.6),
        "the robot stands within dmin"
    );
    let escaped = facts_since(&s, seen).into_iter().find_map(|f| match f {
        EventKind::LocalPlanSent { escaped, .. } if escaped > 0 => Some(escaped),
        _ => None,
    });
    assert!(escaped.is_some(), "{:?}", facts_since(&s, seen));
    apply(&mut s, Input::ActivateAll);
    assert!(s.run_until(120.0, |s| s.mission().is_arrived()).unwrap());
    assert_eq!(s.stats().bumps, 0);
    // SetPosition is still strict: the start itself may not be within dmin.
    let here = Pose::new(p.x, p.y, 0.0);
    apply(&mut s, Input::DeactivateAll);
    let e = s
        .apply(&Input::SetPosition {
            start: here,
            goal: s.mission().goal().unwrap(),
            direction: Direction::Forward,
        })
        .unwrap_err();
    assert!(e.to_string().contains("too close to an obstacle"), "{e}");
}
