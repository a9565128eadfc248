//! spec §3 Decision 0.2, "A local plan over executions": a plan whose field needs more than
//! [`FIELD_CELLS_PER_EXECUTION`] cells goes on over the next executions. Made in parts, the
//! field and the plan are those made at once; the component keeps what it sent until the plan
//! is done, sends it from where the robot is then, and begins again when the map changes.

#[path = "../benches/support/warehouse.rs"]
mod warehouse;
#[path = "../benches/support/workloads.rs"]
mod workloads;

use rtnav::components::{FIELD_CELLS_PER_EXECUTION, LocalPathPlanning};
use rtnav::interfaces::{Direction, GlobalPathCourse, Pose};
use rtnav::local::{FieldExtent, LocalPlanner, PlanParams, PlanRequest, Progress};
use rtnav::map::{Cell, GridMap, MapUpdate};
use rtnav::rtc::{Component, Tick, Time, TimedPosition};

use warehouse::centre;
use workloads::{long_route, pose_on};

fn tick(n: u64) -> Tick {
    Tick {
        time_ns: n * 100_000_000,
        period_ns: 100_000_000,
        index: n,
    }
}

/// The generated warehouse (1006 × 1674 cells of 0.03 m, as the benches') and its long route.
fn warehouse() -> (GridMap, Vec<Cell>) {
    let map = warehouse::map();
    let route = long_route(&map);
    (map, route)
}

/// Where on the route the robot stands: in a rack aisle.
const FROM: usize = 450;

fn goal(route: &[Cell]) -> Pose {
    let (x, y) = centre(*route.last().unwrap());
    Pose::new(x, y, 0.0)
}

fn request(route: &[Cell]) -> PlanRequest<'_> {
    PlanRequest {
        held_path: route,
        match_from: 0,
        current: pose_on(route, FROM),
        goal: goal(route),
        direction: Direction::Forward,
        params: PlanParams::default(),
        extent: FieldExtent::UntilCurrent,
    }
}

#[test]
fn a_field_made_in_parts_is_the_field_made_at_once() {
    let (map, path) = warehouse();
    let req = request(&path);
    let mut whole = LocalPlanner::new();
    let at_once = whole.plan(&map, &req).unwrap();
    let cells = whole.field().finalized_count();
    assert!(
        cells > 2 * FIELD_CELLS_PER_EXECUTION,
        "the test's plan must need several executions: {cells} cells"
    );
    for budget in [20_011, FIELD_CELLS_PER_EXECUTION] {
        let mut parts = LocalPlanner::new();
        let mut progress = parts.begin(&map, &req, budget).unwrap();
        let mut calls = 1;
        let plan = loop {
            match progress {
                Progress::Done(plan) => break plan,
                Progress::Continuing => {
                    assert!(parts.is_pending());
                    assert!(parts.field().finalized_count() <= calls * budget);
                    progress = parts.resume(&map, &path, budget).unwrap();
                    calls += 1;
                }
            }
        };
        assert!(!parts.is_pending());
        assert_eq!(calls, cells.div_ceil(budget), "budget {budget}");
        assert_eq!(plan, at_once, "budget {budget}");
        assert_eq!(parts.field().finalized_count(), cells);
        assert!(parts.field().states().eq(whole.field().states()));
        for &cell in &plan.local_path {
            assert_eq!(
                parts.field().info(cell),
                whole.field().info(cell),
                "{cell:?}"
            );
        }
    }
}

#[test]
fn a_cancelled_plan_leaves_nothing_to_resume() {
    let (map, path) = warehouse();
    let mut planner = LocalPlanner::new();
    assert_eq!(
        planner.begin(&map, &request(&path), 100).unwrap(),
        Progress::Continuing
    );
    planner.cancel();
    assert!(!planner.is_pending());
    assert_eq!(
        planner.resume(&map, &path, usize::MAX).unwrap(),
        Progress::Continuing
    );
    // And a plan begun afresh is the plan made at once.
    let at_once = LocalPlanner::new().plan(&map, &request(&path)).unwrap();
    assert_eq!(planner.plan(&map, &request(&path)).unwrap(), at_once);
}

fn component(map: &GridMap, route: &[Cell]) -> LocalPathPlanning {
    let mut c = LocalPathPlanning::new("LocalPathPlanning0");
    c.set_grid_map(map.clone());
    let (s, g) = (pose_on(route, FROM), goal(route));
    c.set_position(s.x, s.y, s.theta, g.x, g.y, g.theta, 1)
        .unwrap();
    c.set_global_path(&GlobalPathCourse::from_cells(route))
        .unwrap();
    c
}

fn position(c: &LocalPathPlanning, p: Pose) {
    c.in_current_position.put(TimedPosition {
        x: p.x,
        y: p.y,
        theta: p.theta,
        ..Default::default()
    });
}

/// Executes until the first plan is sent: the executions it took.
fn executions_to_send(c: &mut LocalPathPlanning, route: &[Cell], moving: bool) -> u64 {
    for n in 0..100 {
        if moving && n > 0 {
            // The robot drives on along the held course meanwhile: a cell a tick.
            position(c, pose_on(route, FROM + n as usize));
        }
        c.on_execute(&tick(n)).unwrap();
        if c.drive_cons.write_count() > 0 {
            return n + 1;
        }
        assert!(c.is_planning(), "execution {n}: planning");
        assert!(!c.is_settled());
    }
    panic!("no plan in 100 executions");
}

#[test]
fn the_component_sends_the_plan_when_its_field_is_done_from_where_the_robot_is() {
    let (map, route) = warehouse();
    let mut still = component(&map, &route);
    let n = executions_to_send(&mut still, &route, false);
    assert!(n >= 3, "a large field takes several executions: {n}");
    assert!(!still.is_planning());
    assert_eq!(still.plan_count(), 1);
    // Standing still, the plan sent is the plan made at once.
    let at_once = LocalPlanner::new().plan(&map, &request(&route)).unwrap();
    assert_eq!(still.merged_path(), at_once.merged_path.as_slice());
    assert_eq!(
        still.drive_cons.last().unwrap().points,
        at_once.control_points
    );

    // Moving meanwhile: the path sent begins at the cell nearest the robot now.
    let mut moving = component(&map, &route);
    let m = executions_to_send(&mut moving, &route, true);
    assert_eq!(m, n);
    let robot = route[FROM + m as usize - 1];
    let d2 = |c: Cell| {
        let (dx, dy) = (c.0 as i64 - robot.0 as i64, c.1 as i64 - robot.1 as i64);
        dx * dx + dy * dy
    };
    let first = moving.merged_path()[0];
    let nearest = at_once.merged_path.iter().map(|&c| d2(c)).min().unwrap();
    assert_eq!(
        d2(first),
        nearest,
        "first cell {first:?}, robot at {robot:?}"
    );
    assert!(at_once.merged_path.ends_with(moving.merged_path()));
    assert!(moving.merged_path().len() < at_once.merged_path.len());
    let sent = moving.drive_cons.last().unwrap();
    let p = pose_on(&route, FROM + m as usize - 1);
    assert_eq!(
        sent.points[0],
        (p.x, p.y),
        "the control points begin at the robot"
    );
    assert_eq!(
        moving.merged_path().last(),
        at_once.merged_path.last(),
        "and end at the goal"
    );
}

#[test]
fn a_map_change_while_planning_begins_the_plan_again_on_the_new_map() {
    let (map, route) = warehouse();
    let mut c = component(&map, &route);
    c.on_execute(&tick(0)).unwrap();
    assert!(c.is_planning());
    // An obstacle in a free cell away from the route.
    let (x, y) = route[FROM + 300];
    let cell = (0..200)
        .map(|d| (x as i64, y as i64 + 30 + d))
        .find(|&(x, y)| !map.is_obstacle(x, y))
        .unwrap();
    let update = MapUpdate::from_cells(&[(cell.0, cell.1, 1)], Time { sec: 1, nsec: 0 });
    assert_eq!(c.map_update(&update).unwrap(), 1);
    assert!(!c.is_planning(), "the unfinished plan is dropped");
    let sent_at = executions_to_send(&mut c, &route, false);
    assert_eq!(c.plan_count(), 2, "begun again, once");
    assert!(sent_at >= 3);
    // The same requests give the same executions and plan: a plan over executions is as
    // deterministic as one made at once.
    let mut again = component(&map, &route);
    again.on_execute(&tick(0)).unwrap();
    again.map_update(&update).unwrap();
    assert_eq!(executions_to_send(&mut again, &route, false), sent_at);
    assert_eq!(again.merged_path(), c.merged_path());
}

#[test]
fn clear_safe_mode_and_a_new_goal_drop_an_unfinished_plan() {
    let (map, route) = warehouse();
    type Act = fn(&mut LocalPathPlanning, &[Cell]);
    let acts: [(&str, Act); 3] = [
        ("Clear", |c, _| c.clear()),
        ("SafeMode", |c, _| c.safe_mode()),
        ("SetPosition", |c, route| {
            let (s, g) = (pose_on(route, FROM), pose_on(route, FROM + 40));
            c.set_position(s.x, s.y, s.theta, g.x, g.y, g.theta, 1)
                .unwrap();
        }),
    ];
    for (name, act) in acts {
        let mut c = component(&map, &route);
        c.on_execute(&tick(0)).unwrap();
        assert!(c.is_planning(), "{name}");
        act(&mut c, &route);
        assert!(!c.is_planning(), "{name}");
        c.on_execute(&tick(1)).unwrap();
        assert!(!c.is_planning(), "{name}: nothing begun again");
        assert!(
            c.drive_cons.last().is_none_or(|cp| cp.points.is_empty()),
            "{name}: no plan sent (SafeMode's empty path at most)"
        );
    }
}
