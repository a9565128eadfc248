//! The LocalPathPlanning RT-component (seed 000, spec §3): its services, flags, ports,
//! parameters and the behaviour on every tick, on small hand-made maps with exact
//! expectations. Test names carry the seed section they check.

use core::f64::consts::{FRAC_PI_2, PI};

use rtnav::components::{LocalPathFlags, LocalPathPlanning, LocalPathPlanningParams};
use rtnav::errors::{Error, LocalPathError, MapError};
use rtnav::interfaces::{Direction, GlobalPathCourse, Pose};
use rtnav::local::FieldExtent;
use rtnav::map::{Cell, MapUpdate};
use rtnav::rtc::{
    Component, ConfigAccess, ExecutionContext, ParameterSet, Reflection, Tick, Time, TimedDouble,
    TimedPosition,
};

const G: f64 = 0.25;
const W: usize = 40;
const H: usize = 20;

fn tick(n: u64) -> Tick {
    Tick {
        time_ns: n * 100_000_000,
        period_ns: 100_000_000,
        index: n,
    }
}

fn centre((x, y): Cell) -> (f64, f64) {
    ((x as f64 + 0.5) * G, (y as f64 + 0.5) * G)
}

/// A 10 m × 5 m open map of 0.25 m cells (obstacles at `blocked`).
fn component(blocked: &[Cell]) -> LocalPathPlanning {
    let mut c = LocalPathPlanning::new("LocalPathPlanning0");
    let mut data = vec![0i16; W * H];
    for &(x, y) in blocked {
        data[x + y * W] = 1;
    }
    c.set_map(&data, W as i32, H as i32, G).unwrap();
    c
}

/// Start at cell (4, 10) heading east, goal at cell (35, 10) heading east, forward.
const START: Cell = (4, 10);
const GOAL: Cell = (35, 10);

fn set_position(c: &mut LocalPathPlanning, direction: i16) {
    let (s, g) = (centre(START), centre(GOAL));
    c.set_position(s.0, s.1, 0.0, g.0, g.1, 0.0, direction)
        .unwrap();
}

fn straight_path() -> Vec<Cell> {
    (START.0..=GOAL.0).map(|x| (x, 10)).collect()
}

fn send_path(c: &mut LocalPathPlanning, cells: &[Cell]) {
    c.set_global_path(&GlobalPathCourse::from_cells(cells))
        .unwrap();
}

/// Map, start/goal, the straight global path, and one tick to plan and send it (spec §3
/// Decision 0.2: a new course is planned with the potential field at once, so every test
/// starts with one plan made).
fn ready(blocked: &[Cell]) -> LocalPathPlanning {
    let mut c = component(blocked);
    set_position(&mut c, 1);
    send_path(&mut c, &straight_path());
    c.on_execute(&tick(0)).unwrap();
    assert_eq!(c.plan_count(), 1);
    assert_eq!(c.drive_cons.write_count(), 1);
    c
}

fn position(c: &LocalPathPlanning, x: f64, y: f64, theta: f64) {
    c.in_current_position.put(TimedPosition {
        x,
        y,
        theta,
        ..Default::default()
    });
}

fn deviation(c: &LocalPathPlanning, d: f64) {
    c.in_deviating.put(TimedDouble {
        data: d,
        ..Default::default()
    });
}

fn assert_clear_path(c: &LocalPathPlanning, path: &[Cell]) {
    let map = c.map().unwrap();
    let dmin = c.params().dmin;
    for &p in path {
        assert!(map.obstacle_distance(p) > dmin, "{p:?} within dmin");
    }
    for w in path.windows(2) {
        assert!(w[0].0.abs_diff(w[1].0) <= 1 && w[0].1.abs_diff(w[1].1) <= 1);
    }
}

// ----- 000 §3: ports -----

#[test]
fn s3_ports_have_the_seeds_names() {
    let c = LocalPathPlanning::default();
    assert_eq!(c.instance_name(), "LocalPathPlanning0");
    assert_eq!(c.in_current_position.name(), "InCurrentPosition");
    assert_eq!(c.in_deviating.name(), "InDeviating");
    assert_eq!(c.invent_gui_cons.name(), "InventGUICons");
    assert_eq!(c.bump_cons.name(), "BumpCons");
    assert_eq!(c.drive_cons.name(), "DriveCons");
    assert_eq!(c.invent_gui_failure.name(), "InventGUIConsFailure");
    assert_eq!(c.flags(), LocalPathFlags::default());
}

// ----- 000 §4.2: configuration -----

#[test]
fn s4_2_six_parameters_with_defaults_units_and_ranges_all_always() {
    let specs = LocalPathPlanningParams::SPECS;
    let table: Vec<(&str, &str, f64, f64, f64)> = specs
        .iter()
        .map(|s| (s.name, s.unit, s.default, s.min, s.max))
        .collect();
    let inf = f64::INFINITY;
    assert_eq!(
        table,
        vec![
            ("RouteRemakeDistance", "m", 10.0, 0.0, inf),
            ("Deviatinglen", "m", 0.1, 0.0, inf),
            ("dmin", "m", 0.5, 0.0, inf),
            ("PostureConsiderationLevel", "%", 85.0, 0.0, 100.0),
            ("NotPostureDistance", "m", 1.0, 0.0, inf),
            ("TargetArea", "m", 0.5, 0.0, inf),
        ]
    );
    assert!(specs.iter().all(|s| s.reflection == Reflection::Always));
    let mut c = LocalPathPlanning::default();
    let p = *c.params();
    assert_eq!(
        (p.route_remake_distance, p.deviatinglen, p.dmin),
        (10.0, 0.1, 0.5)
    );
    assert_eq!(
        (
            p.posture_consideration_level,
            p.not_posture_distance,
            p.target_area
        ),
        (85.0, 1.0, 0.5)
    );
    let conf = c.configuration().unwrap();
    assert!(conf.set("PostureConsiderationLevel", 100.5).is_err());
    assert!(conf.set("dmin", -0.1).is_err());
    assert!(conf.set("Deviatinglen", f64::NAN).is_err());
    conf.set("dmin", 0.3).unwrap();
    // `always`: in effect at once.
    assert_eq!(c.params().dmin, 0.3);
    assert_eq!(c.params().posture_consideration_level, 85.0);
}

// ----- 000 §3.2.2.1: the LocalPath service -----

#[test]
fn s3_2_2_1_set_position_is_checked_and_a_refusal_keeps_the_old_start() {
    let mut c = LocalPathPlanning::default();
    assert_eq!(
        c.set_position(1.0, 1.0, 0.0, 2.0, 2.0, 0.0, 1),
        Err(Error::LocalPath(LocalPathError::NoMap {
            call: "SetPosition"
        }))
    );
    // An obstacle at (10, 3): cells within dmin = 0.5 m (2 cells) of it are not clear.
    let mut c = component(&[(10, 3)]);
    assert!(matches!(
        c.set_position(1.0, f64::NAN, 0.0, 2.0, 2.0, 0.0, 1),
        Err(Error::LocalPath(LocalPathError::NotFinite {
            call: "SetPosition",
            argument: "StartY",
            value,
        })) if value.is_nan()
    ));
    assert!(matches!(
        c.set_position(1.0, 1.0, 0.0, 2.0, 2.0, f64::INFINITY, 1),
        Err(Error::LocalPath(LocalPathError::NotFinite {
            argument: "GoalAngle",
            ..
        }))
    ));
    assert_eq!(
        c.set_position(1.0, 1.0, 0.0, 2.0, 2.0, 0.0, 3),
        Err(Error::LocalPath(LocalPathError::BadDirection { value: 3 }))
    );
    set_position(&mut c, 2);
    assert_eq!(c.start(), Some(Pose::new(1.125, 2.625, 0.0)));
    assert_eq!(c.current_position(), c.start());
    assert_eq!(c.direction(), Direction::Backward);
    assert!(c.flags().position && c.flags().current_position);
    // Start at cell (11, 4), 0.354 m from the obstacle: refused with the reason.
    let err = c
        .set_position(2.875, 1.125, 0.0, 8.0, 2.0, 0.0, 1)
        .unwrap_err();
    let Error::LocalPath(LocalPathError::NotClear {
        what,
        cell,
        distance,
        dmin,
        ..
    }) = &err
    else {
        panic!("{err:?}");
    };
    assert_eq!((*what, *cell, *dmin), ("start", (11, 4), 0.5));
    assert_eq!(*distance, libm::sqrt(2.0) * G);
    assert_eq!(
        err.to_string(),
        format!(
            "start (2.875, 1.125) in cell (11, 4) is too close to an obstacle: obstacle distance {} m ≤ dmin = 0.5 m",
            rtnav::present::number(libm::sqrt(2.0) * G)
        )
    );
    // Nothing changed.
    assert_eq!(c.start(), Some(Pose::new(1.125, 2.625, 0.0)));
    assert_eq!(c.goal(), Some(Pose::new(8.875, 2.625, 0.0)));
    assert_eq!(c.direction(), Direction::Backward);
    // The goal is checked the same way; outside the map is refused too.
    assert!(matches!(
        c.set_position(1.0, 1.0, 0.0, 2.625, 0.875, 0.0, 1),
        Err(Error::LocalPath(LocalPathError::NotClear {
            what: "goal",
            ..
        }))
    ));
    assert_eq!(
        c.set_position(1.0, 1.0, 0.0, 10.5, 2.0, 0.0, 1),
        Err(Error::LocalPath(LocalPathError::OutsideMap {
            what: "goal",
            x: 10.5,
            y: 2.0
        }))
    );
    assert_eq!(c.start(), Some(Pose::new(1.125, 2.625, 0.0)));
}

#[test]
fn s3_2_2_1_global_path_course_is_validated() {
    let mut c = LocalPathPlanning::default();
    assert!(matches!(
        c.global_path_course(&[0], &[0], 1),
        Err(Error::LocalPath(LocalPathError::NoMap { .. }))
    ));
    let mut c = component(&[]);
    send_path(&mut c, &[(1, 1), (2, 2)]);
    let err = |c: &mut LocalPathPlanning, x: &[i32], y: &[i32], n: i32| {
        let e = c.global_path_course(x, y, n).unwrap_err();
        assert_eq!(c.held_path(), &[(1, 1), (2, 2)], "changed by {e}");
        e
    };
    assert_eq!(
        err(&mut c, &[1, 2], &[1], 2),
        Error::LocalPath(LocalPathError::PathLength {
            array: "GridPathY",
            len: 1,
            num: 2
        })
    );
    assert_eq!(
        err(&mut c, &[], &[], 0),
        Error::LocalPath(LocalPathError::EmptyPath)
    );
    assert!(matches!(
        err(&mut c, &[1, 2], &[1, 1], -1),
        Error::LocalPath(LocalPathError::PathLength { num: -1, .. })
    ));
    assert_eq!(
        err(&mut c, &[39, 40], &[1, 1], 2),
        Error::LocalPath(LocalPathError::PathCellOutside {
            index: 1,
            x: 40,
            y: 1,
            width: 40,
            height: 20
        })
    );
    assert_eq!(
        err(&mut c, &[1, 2, 4], &[1, 1, 1], 3),
        Error::LocalPath(LocalPathError::PathNotAdjacent {
            index: 2,
            from: (2, 1),
            to: (4, 1)
        })
    );
    let e = err(&mut c, &[1, 1], &[1, 1], 2);
    assert_eq!(
        e.to_string(),
        "GlobalPathCourse: cells 0 = (1, 1) and 1 = (1, 1) are not 8-neighbours"
    );
    assert!(c.flags().path);
}

#[test]
fn s3_2_2_1_set_map_and_map_update_refuse_bad_input() {
    let mut c = component(&[(3, 3)]);
    assert!(matches!(
        c.set_map(&[0; 5], 2, 2, 1.0),
        Err(Error::Map(MapError::DataLength {
            len: 5,
            expected: 4
        }))
    ));
    assert!(matches!(
        c.set_map(&[0, 0, 2, 0], 2, 2, 1.0),
        Err(Error::Map(MapError::BadCellValue { index: 2, .. }))
    ));
    assert!(matches!(
        c.set_map(&[0; 4], 2, 2, -1.0),
        Err(Error::Map(MapError::BadGridSize { .. }))
    ));
    assert_eq!(c.map().unwrap().width(), W);
    let before = c.map().unwrap().clone();
    assert!(matches!(
        c.map_update(&MapUpdate {
            x: vec![1, 2],
            y: vec![1, 1],
            value: vec![1, 5],
            num: 2,
            tm: Time { sec: 0, nsec: 0 }
        }),
        Err(Error::Map(MapError::BadCellValue { index: 1, .. }))
    ));
    assert!(matches!(
        c.map_update(&MapUpdate {
            x: vec![1, 2],
            y: vec![1],
            value: vec![1, 1],
            num: 2,
            tm: Time { sec: 0, nsec: 0 }
        }),
        Err(Error::Map(MapError::UpdateLength { array: "Y", .. }))
    ));
    assert_eq!(
        c.map_update(&MapUpdate {
            x: vec![1],
            y: vec![1],
            value: vec![1],
            num: 1,
            tm: Time {
                sec: 5,
                nsec: 1_000_000_000
            }
        }),
        Err(Error::Map(MapError::BadTimestamp {
            what: "MapUpdate",
            nsec: 1_000_000_000
        }))
    );
    assert_eq!(c.map(), Some(&before));
    c.map_update(&MapUpdate {
        x: vec![1, 3],
        y: vec![1, 3],
        value: vec![1, 0],
        num: 2,
        tm: Time { sec: 7, nsec: 9 },
    })
    .unwrap();
    let m = c.map().unwrap();
    assert!(m.is_obstacle(1, 1) && !m.is_obstacle(3, 3));
    assert_eq!((m.version().sec, m.version().nsec), (7, 9));
}

// ----- 000 §5.2.4.3: the global path as received -----

#[test]
fn s5_2_4_3_a_course_before_set_position_is_sent_as_received_once_without_a_field() {
    let mut c = component(&[]);
    // East from (4, 4) to (20, 4), then north to (20, 12): an L.
    let mut path: Vec<Cell> = (4..=20).map(|x| (x, 4)).collect();
    path.extend((5..=12).map(|y| (20, y)));
    send_path(&mut c, &path);
    // No start/goal yet: nothing to send.
    c.on_execute(&tick(0)).unwrap();
    assert_eq!(c.drive_cons.write_count(), 0);
    let (s, g) = (centre((4, 4)), centre((20, 12)));
    c.set_position(s.0 + 0.05, s.1, 0.3, g.0, g.1 - 0.1, FRAC_PI_2, 1)
        .unwrap();
    c.on_execute(&tick(1)).unwrap();
    let cp = c.drive_cons.last().unwrap();
    assert_eq!(
        cp.points,
        vec![(s.0 + 0.05, s.1), centre((20, 4)), (g.0, g.1 - 0.1)]
    );
    assert_eq!(cp.direction, Direction::Forward);
    assert_eq!(cp.goal_theta, FRAC_PI_2);
    assert_eq!(cp.tm.nsec, 100_000_000);
    assert_eq!(c.invent_gui_cons.last().unwrap().cells, path);
    assert_eq!(c.bump_cons.last().unwrap().cells, path);
    assert_eq!(c.merged_path(), &path[..]);
    assert_eq!(c.plan_count(), 0);
    assert!(c.potential_field().is_none());
    // Sent once: the next ticks send nothing.
    c.on_execute(&tick(2)).unwrap();
    c.on_execute(&tick(3)).unwrap();
    assert_eq!(c.drive_cons.write_count(), 1);
    assert_eq!(c.invent_gui_cons.write_count(), 1);
    assert_eq!(c.bump_cons.write_count(), 1);
    // Spec §3 Decision 0.2: a course that comes while start and goal are held is planned
    // with the potential field at once.
    send_path(&mut c, &path);
    c.on_execute(&tick(4)).unwrap();
    assert_eq!(c.plan_count(), 1);
    assert!(c.potential_field().is_some());
    assert_eq!(c.merged_path().last(), Some(&(20, 12)));
    // Direction 2 drives backward.
    c.set_position(s.0, s.1, PI, g.0, g.1, FRAC_PI_2, 2)
        .unwrap();
    send_path(&mut c, &path);
    c.on_execute(&tick(5)).unwrap();
    assert_eq!(c.drive_cons.last().unwrap().direction, Direction::Backward);
}

#[test]
fn s5_2_4_3_a_global_path_that_misses_the_goal_cell_is_a_failure() {
    let mut c = component(&[]);
    set_position(&mut c, 1);
    let short: Vec<Cell> = (START.0..=20).map(|x| (x, 10)).collect();
    send_path(&mut c, &short);
    c.on_execute(&tick(0)).unwrap();
    assert!(c.drive_cons.last().unwrap().points.is_empty());
    assert_eq!(
        c.last_failure().unwrap().reason.to_string(),
        "the held path does not reach the goal cell (35, 10)"
    );
    // Spec §3 Decision 0.2: the course was planned at once, and failed.
    assert_eq!(c.plan_count(), 1);
    // A deviation replans on the held path: the same failure, no route to a target.
    deviation(&c, 0.5);
    c.on_execute(&tick(1)).unwrap();
    assert_eq!(c.plan_count(), 2);
    assert_eq!(c.invent_gui_failure.write_count(), 2);
    // Spec §3 Decision 0.2: while the goal is held, it tries again every second.
    assert_eq!(c.retry_at_ns(), Some(tick(11).time_ns));
    for n in 2..=10 {
        c.on_execute(&tick(n)).unwrap();
    }
    assert_eq!(c.plan_count(), 2);
    c.on_execute(&tick(11)).unwrap();
    assert_eq!(c.plan_count(), 3);
    assert_eq!(c.invent_gui_failure.write_count(), 3);
}

// ----- 000 §5.2.4.4: the current position -----

#[test]
fn s5_2_4_4_current_position_flag_and_arrival() {
    let mut c = ready(&[(20, 15)]);
    assert!(c.flags().current_position);
    // Within dmin of the obstacle at (20, 15): spec §3 Decision 0.2, the flag stays on (a
    // plan escapes the zone first).
    position(&c, 5.125, 3.625, 0.0); // cell (20, 14)
    c.on_execute(&tick(1)).unwrap();
    assert!(c.flags().current_position);
    assert_eq!(c.current_position(), Some(Pose::new(5.125, 3.625, 0.0)));
    // On the obstacle itself: off.
    position(&c, 5.125, 3.875, 0.0); // cell (20, 15)
    c.on_execute(&tick(2)).unwrap();
    assert!(!c.flags().current_position);
    // Outside the map: off; NaN: off and ignored.
    position(&c, -1.0, 1.0, 0.0);
    c.on_execute(&tick(3)).unwrap();
    assert!(!c.flags().current_position);
    position(&c, 3.0, 2.6, 0.0);
    c.on_execute(&tick(4)).unwrap();
    assert!(c.flags().current_position);
    position(&c, f64::NAN, 2.6, 0.0);
    c.on_execute(&tick(5)).unwrap();
    assert!(!c.flags().current_position);
    assert_eq!(c.current_position(), Some(Pose::new(3.0, 2.6, 0.0)));
    // Arrived when the straight distance to the goal is ≤ GridSize (0.25 m).
    let g = centre(GOAL);
    position(&c, g.0 - 0.26, g.1, 0.0);
    c.on_execute(&tick(6)).unwrap();
    assert!(!c.flags().arrived);
    position(&c, g.0 - 0.15, g.1 + 0.15, 0.0);
    c.on_execute(&tick(7)).unwrap();
    assert!(c.flags().arrived);
    // Latched until the next SetPosition.
    position(&c, 3.0, 2.6, 0.0);
    c.on_execute(&tick(8)).unwrap();
    assert!(c.flags().arrived);
    set_position(&mut c, 1);
    assert!(!c.flags().arrived);
}

#[test]
fn s5_2_4_4_target_area_switches_to_backward_and_turns_the_headings() {
    let mut c = ready(&[]);
    let g = centre(GOAL);
    // 0.4 m before the goal (inside TargetArea 0.5 m), facing away from it: backward.
    position(&c, g.0 - 0.4, g.1, PI);
    c.on_execute(&tick(1)).unwrap();
    assert_eq!(c.direction(), Direction::Backward);
    assert_eq!(c.commanded_direction(), Direction::Forward);
    assert_eq!(c.plan_count(), 2, "the switch replans");
    let cp = c.drive_cons.last().unwrap();
    assert_eq!(cp.direction, Direction::Backward);
    assert_eq!(cp.points.first(), Some(&(g.0 - 0.4, g.1)));
    assert_eq!(cp.points.last(), Some(&g));
    let plan = c.local_plan().unwrap();
    assert_eq!(plan.direction, Direction::Backward);
    let req = c.potential_field().unwrap().request().unwrap();
    assert_eq!(req.direction, Direction::Backward);
    assert_eq!(req.current_heading, PI);
    // Exactly 90° away still counts as within ±90°: forward again.
    position(&c, g.0 - 0.4, g.1, FRAC_PI_2);
    c.on_execute(&tick(2)).unwrap();
    assert_eq!(c.direction(), Direction::Forward);
    assert_eq!(c.plan_count(), 3);
    assert_eq!(c.drive_cons.last().unwrap().direction, Direction::Forward);
    // Facing the goal: forward, no change, no replan.
    position(&c, g.0 - 0.4, g.1, 0.2);
    c.on_execute(&tick(3)).unwrap();
    assert_eq!(c.plan_count(), 3);
    // Outside TargetArea the commanded direction holds whatever the heading.
    position(&c, g.0 - 2.0, g.1, PI);
    c.on_execute(&tick(4)).unwrap();
    assert_eq!(c.direction(), Direction::Forward);
    assert_eq!(c.plan_count(), 3);
}

// ----- 000 §5.2.4.5: deviation -----

#[test]
fn s5_2_4_5_deviation_above_deviatinglen_replans_exactly_once() {
    let mut c = ready(&[]);
    assert!(!c.flags().replan_request);
    // Not above 0.1 m: nothing (beyond the course's plan, spec §3 Decision 0.2).
    deviation(&c, 0.1);
    c.on_execute(&tick(1)).unwrap();
    assert_eq!(c.plan_count(), 1);
    assert_eq!(c.deviation(), Some(0.1));
    // Above: one replan, on this tick.
    deviation(&c, 0.15);
    c.on_execute(&tick(2)).unwrap();
    assert_eq!(c.plan_count(), 2);
    assert!(!c.flags().replan_request);
    assert!(c.potential_field().is_some());
    // No new sample: no more replans.
    c.on_execute(&tick(3)).unwrap();
    c.on_execute(&tick(4)).unwrap();
    assert_eq!(c.plan_count(), 2);
    // Several triggers before a tick: still one replan.
    deviation(&c, 0.3);
    c.request_replan();
    c.map_update(&MapUpdate {
        x: vec![0],
        y: vec![0],
        value: vec![1],
        num: 1,
        tm: Time { sec: 1, nsec: 0 },
    })
    .unwrap();
    assert!(c.flags().replan_request);
    c.on_execute(&tick(5)).unwrap();
    assert_eq!(c.plan_count(), 3);
    // The plan starts at the current position and ends at the goal.
    let plan = c.local_plan().unwrap();
    assert_eq!(plan.local_path.first(), Some(&START));
    assert_eq!(plan.merged_path.last(), Some(&GOAL));
    assert_eq!(c.held_path(), &plan.merged_path[..]);
}

#[test]
fn s5_2_4_5_the_first_current_position_does_not_replan_and_a_new_course_plans_once() {
    let mut c = ready(&[]);
    position(&c, 1.2, 2.6, 0.1);
    c.on_execute(&tick(1)).unwrap();
    assert_eq!(c.plan_count(), 1);
    // Spec §3 Decision 0.2: a new course is planned with the potential field at once; a
    // request pending before it is served by the same plan.
    assert!(c.request_replan());
    let mut path = straight_path();
    path[3].1 = 11;
    send_path(&mut c, &path);
    assert!(c.flags().replan_request);
    assert_eq!(c.held_path(), &path[..]);
    c.on_execute(&tick(2)).unwrap();
    assert_eq!(c.plan_count(), 2);
    let plan = c.local_plan().unwrap();
    assert_eq!(c.invent_gui_cons.last().unwrap().cells, plan.merged_path);
    c.on_execute(&tick(3)).unwrap();
    assert_eq!(c.plan_count(), 2);
}

// ----- 000 §5.2.4.6: map updates -----

#[test]
fn s5_2_4_6_a_map_update_that_blocks_the_path_replans_around_it() {
    let mut c = ready(&[]);
    // A 2 × 3 block on the straight path, half way.
    let (xs, ys): (Vec<i32>, Vec<i32>) = [(19, 9), (20, 9), (19, 10), (20, 10), (19, 11), (20, 11)]
        .iter()
        .copied()
        .unzip();
    c.map_update(&MapUpdate {
        x: xs.to_vec(),
        y: ys.to_vec(),
        value: vec![1; 6],
        num: 6,
        tm: Time { sec: 12, nsec: 0 },
    })
    .unwrap();
    assert!(c.flags().replan_request);
    c.on_execute(&tick(1)).unwrap();
    assert_eq!(c.plan_count(), 2);
    let sent = c.invent_gui_cons.last().unwrap().cells.clone();
    assert_eq!(sent.first(), Some(&START));
    assert_eq!(sent.last(), Some(&GOAL));
    assert_clear_path(&c, &sent);
    assert!(!sent.iter().any(|p| p.1 == 10 && (17..=22).contains(&p.0)));
    assert_eq!(c.drive_cons.write_count(), 2);
    let cp = c.drive_cons.last().unwrap();
    assert_eq!(cp.points.first(), Some(&centre(START)));
    assert_eq!(cp.points.last(), Some(&centre(GOAL)));
    assert!(
        cp.points.len() >= 3,
        "the detour has corners: {:?}",
        cp.points
    );
    // What the GUI draws.
    let t = c.local_target().unwrap();
    assert_eq!((t.cell, t.is_goal, t.heading), (GOAL, true, 0.0));
    assert_eq!(c.local_path(), &sent[..]);
    assert_eq!(c.merged_path(), &sent[..]);
    assert!(c.potential_field().unwrap().current_reached());
    assert_eq!(c.field_extent(), FieldExtent::UntilCurrent);
}

#[test]
fn s5_2_4_6_after_arrival_a_map_update_replans_nothing() {
    let mut c = ready(&[]);
    let g = centre(GOAL);
    position(&c, g.0 - 0.1, g.1, 0.0);
    c.on_execute(&tick(1)).unwrap();
    assert!(c.flags().arrived);
    c.map_update(&MapUpdate {
        x: vec![20],
        y: vec![10],
        value: vec![1],
        num: 1,
        tm: Time { sec: 3, nsec: 0 },
    })
    .unwrap();
    assert!(!c.flags().replan_request);
    deviation(&c, 1.0);
    assert!(!c.request_replan());
    c.on_execute(&tick(2)).unwrap();
    assert_eq!(c.plan_count(), 1, "only the course's plan");
    assert_eq!(c.drive_cons.write_count(), 1);
}

// ----- 000 §5.2.4.7: Clear -----

#[test]
fn s5_2_4_7_clear_drops_everything() {
    let mut c = ready(&[]);
    deviation(&c, 0.5);
    c.on_execute(&tick(1)).unwrap();
    assert!(c.local_plan().is_some());
    c.clear();
    assert_eq!(c.flags(), LocalPathFlags::default());
    assert!(c.map().is_none() && c.start().is_none() && c.goal().is_none());
    assert!(c.current_position().is_none() && c.deviation().is_none());
    assert!(c.held_path().is_empty() && c.merged_path().is_empty());
    assert!(c.potential_field().is_none() && c.local_plan().is_none());
    assert!(c.local_target().is_none() && c.local_path().is_empty());
    assert!(c.control_points().is_none());
    // The consumers are told once: an empty path, no failure notice.
    let writes = c.drive_cons.write_count();
    c.on_execute(&tick(2)).unwrap();
    c.on_execute(&tick(3)).unwrap();
    assert_eq!(c.drive_cons.write_count(), writes + 1);
    assert!(c.drive_cons.last().unwrap().points.is_empty());
    assert!(c.invent_gui_cons.last().unwrap().cells.is_empty());
    assert_eq!(c.invent_gui_failure.write_count(), 0);
    // Triggers do nothing now; SetPosition needs a new map.
    deviation(&c, 0.5);
    c.on_execute(&tick(4)).unwrap();
    assert_eq!(c.plan_count(), 2, "the course's plan and the deviation's");
    assert!(matches!(
        c.set_position(1.0, 1.0, 0.0, 2.0, 2.0, 0.0, 1),
        Err(Error::LocalPath(LocalPathError::NoMap { .. }))
    ));
}

// ----- SafeMode (spec §3 Decision) -----

#[test]
fn s3_2_2_1_safe_mode_halts_until_the_next_set_position() {
    let mut c = ready(&[]);
    c.safe_mode();
    assert!(c.flags().safe_mode);
    c.on_execute(&tick(1)).unwrap();
    assert_eq!(c.drive_cons.write_count(), 2);
    assert!(c.drive_cons.last().unwrap().points.is_empty());
    assert!(c.bump_cons.last().unwrap().cells.is_empty());
    // No replan, no global path sent.
    deviation(&c, 1.0);
    assert!(!c.request_replan());
    send_path(&mut c, &straight_path());
    c.on_execute(&tick(2)).unwrap();
    assert_eq!(c.plan_count(), 1, "only the course's plan before SafeMode");
    assert_eq!(c.drive_cons.write_count(), 2);
    // SetPosition ends it; the course is planned when it comes again (spec §3 Decision 0.2).
    set_position(&mut c, 1);
    assert!(!c.flags().safe_mode);
    send_path(&mut c, &straight_path());
    c.on_execute(&tick(3)).unwrap();
    assert_eq!(c.plan_count(), 2);
    assert_eq!(c.drive_cons.write_count(), 3);
    assert_eq!(c.drive_cons.last().unwrap().points.len(), 2);
}

// ----- 000 §5.2.4.13: sending -----

#[test]
fn s5_2_4_13_an_unchanged_plan_is_not_sent_twice() {
    let mut c = ready(&[]);
    c.config_mut()
        .set("PostureConsiderationLevel", 60.0)
        .unwrap();
    position(&c, 1.125, 2.625, 0.5);
    deviation(&c, 0.2);
    c.on_execute(&tick(1)).unwrap();
    assert_eq!((c.plan_count(), c.drive_cons.write_count()), (2, 2));
    let first = c.drive_cons.last().unwrap().clone();
    // The same situation again: the same plan, not sent again.
    deviation(&c, 0.2);
    c.on_execute(&tick(2)).unwrap();
    assert_eq!(c.plan_count(), 3);
    assert_eq!(c.drive_cons.write_count(), 2);
    assert_eq!(c.invent_gui_cons.write_count(), 2);
    assert_eq!(c.control_points().unwrap().points, first.points);
    // A changed heading changes the plan: sent.
    position(&c, 1.125, 2.625, -0.8);
    deviation(&c, 0.2);
    c.on_execute(&tick(3)).unwrap();
    assert_eq!(c.plan_count(), 4);
    assert_eq!(c.drive_cons.write_count(), 3);
}

#[test]
fn s5_2_4_13_a_walled_off_goal_gives_an_empty_path_and_a_notice() {
    let mut c = ready(&[]);
    // A ring of obstacles 3 cells around the goal (the goal itself stays clear).
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for x in GOAL.0 - 3..=GOAL.0 + 3 {
        for y in GOAL.1 - 3..=GOAL.1 + 3 {
            if x.abs_diff(GOAL.0) == 3 || y.abs_diff(GOAL.1) == 3 {
                xs.push(x as i32);
                ys.push(y as i32);
            }
        }
    }
    let n = xs.len();
    c.map_update(&MapUpdate {
        x: xs.to_vec(),
        y: ys.to_vec(),
        value: vec![1; n].to_vec(),
        num: n as i32,
        tm: Time { sec: 20, nsec: 0 },
    })
    .unwrap();
    c.on_execute(&tick(1)).unwrap();
    assert_eq!(c.plan_count(), 2);
    assert!(c.drive_cons.last().unwrap().points.is_empty());
    assert!(c.invent_gui_cons.last().unwrap().cells.is_empty());
    assert!(c.bump_cons.last().unwrap().cells.is_empty());
    assert_eq!(c.invent_gui_failure.write_count(), 1);
    let notice = c.invent_gui_failure.last().unwrap();
    assert_eq!(notice.planner, "LocalPathPlanning");
    assert_eq!(
        notice.reason.to_string(),
        "no route: the potential field from the local target (35, 10) does not reach the current cell (4, 10)"
    );
    assert_eq!(notice.tm.nsec, 100_000_000);
    assert_eq!(c.last_failure(), Some(notice));
    assert!(c.merged_path().is_empty() && c.local_plan().is_none());
    // The field that failed stays for display; the held path stays for a later update.
    assert!(!c.potential_field().unwrap().current_reached());
    assert_eq!(c.held_path(), &straight_path()[..]);
    // A second failure: a new notice, but the empty path is not sent again.
    deviation(&c, 0.5);
    c.on_execute(&tick(2)).unwrap();
    assert_eq!(c.invent_gui_failure.write_count(), 2);
    assert_eq!(c.drive_cons.write_count(), 2);
    // Opening 5 cells of the ring (a 1-cell corridor with dmin = 2 cells) lets the next
    // replan through.
    let x = GOAL.0 as i32 - 3;
    c.map_update(&MapUpdate {
        x: vec![x; 5],
        y: vec![8, 9, 10, 11, 12],
        value: vec![0; 5],
        num: 5,
        tm: Time { sec: 21, nsec: 0 },
    })
    .unwrap();
    c.on_execute(&tick(3)).unwrap();
    assert_eq!(c.drive_cons.write_count(), 3);
    assert_eq!(c.invent_gui_cons.last().unwrap().cells.last(), Some(&GOAL));
}

#[test]
fn s5_2_4_13_a_current_position_within_dmin_escapes_the_zone_and_one_on_an_obstacle_fails() {
    let mut c = ready(&[(10, 12)]);
    // Spec §3 Decision 0.2 "escape from the margin": next to the obstacle the position flag
    // stays on, and the plan first steps out of the dmin zone.
    position(&c, 2.625, 2.875, 0.0); // cell (10, 11), next to the obstacle
    deviation(&c, 0.5);
    c.on_execute(&tick(1)).unwrap();
    assert!(c.flags().current_position);
    assert_eq!(c.plan_count(), 2);
    let escaped = c.escaped_steps();
    assert!(escaped > 0);
    let path = c.invent_gui_cons.last().unwrap().cells.clone();
    assert_eq!(path.first(), Some(&(10, 11)));
    assert_eq!(path.last(), Some(&GOAL));
    assert_clear_path(&c, &path[escaped..]);
    // On the obstacle cell itself: no plan, and the reason.
    position(&c, 2.625, 3.125, 0.0); // cell (10, 12)
    deviation(&c, 0.5);
    c.on_execute(&tick(2)).unwrap();
    assert!(!c.flags().current_position);
    assert_eq!(c.plan_count(), 3);
    assert!(c.drive_cons.last().unwrap().points.is_empty());
    let reason = c.last_failure().unwrap().reason.to_string();
    assert!(
        reason.starts_with("current position (2.625, 3.125) in cell (10, 12)"),
        "{reason}"
    );
}

// ----- in an execution context (spec §1) -----

#[test]
fn s5_2_4_runs_in_an_execution_context() {
    let mut ec = ExecutionContext::new(10.0).unwrap();
    let id = ec.attach(Box::new(component(&[])), 10.0).unwrap();
    ec.start().unwrap();
    {
        let c = ec.component_mut::<LocalPathPlanning>(id).unwrap();
        set_position(c, 1);
        send_path(c, &straight_path());
    }
    ec.activate(id).unwrap();
    ec.run_ticks(2);
    let c = ec.component_mut::<LocalPathPlanning>(id).unwrap();
    assert_eq!(c.drive_cons.write_count(), 1);
    c.set_field_extent(FieldExtent::Full);
    deviation(c, 0.2);
    ec.run_ticks(1);
    let c = ec.component::<LocalPathPlanning>(id).unwrap();
    // The activation's plan (spec §3 Decision 0.2) and the deviation's.
    assert_eq!(c.plan_count(), 2);
    let f = c.potential_field().unwrap();
    assert!(f.is_complete());
    assert_eq!((f.width(), f.height()), (W, H));
    assert!(ec.last_error(id).unwrap().is_none());
}
