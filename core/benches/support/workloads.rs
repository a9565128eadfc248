//! The operations of `docs/performance.md`'s table, shared by the criterion benches
//! (`core/benches/interactive.rs`) and the harness that times them natively and in wasm32
//! (`tests/perf.rs`), so both measure the very same work. Include it next to
//! `warehouse.rs`:
//!
//! ```ignore
//! #[path = ".../core/benches/support/warehouse.rs"]
//! mod warehouse;
//! #[path = ".../core/benches/support/workloads.rs"]
//! mod workloads;
//! ```

#![allow(dead_code)]

use rtnav::global::AStar;
use rtnav::interfaces::{Direction, Pose};
use rtnav::local::{
    FieldExtent, FieldRequest, LocalPlanner, PlanParams, PlanRequest, PotentialField, reference,
};
use rtnav::map::{Cell, GridMap, MapUpdate};
use rtnav::rtc::Time;

use crate::warehouse;

/// `dmin` of the default parameters (000 §4.2), for the global planner too (one `dmin`).
pub const DMIN: f64 = 0.5;

/// The long route on the warehouse, by the planner in use.
pub fn long_route(map: &GridMap) -> Vec<Cell> {
    AStar::new(map, DMIN)
        .expect("a planner")
        .plan(warehouse::LONG_START, warehouse::LONG_GOAL)
        .expect("the long route")
        .cells
}

/// The robot on `route` at index `i`, heading along it.
pub fn pose_on(route: &[Cell], i: usize) -> Pose {
    let (a, b) = (route[i], route[(i + 1).min(route.len() - 1)]);
    let heading = libm::atan2(b.1 as f64 - a.1 as f64, b.0 as f64 - a.0 as f64);
    let (x, y) = warehouse::centre(a);
    Pose::new(x, y, heading)
}

fn goal_pose(route: &[Cell]) -> Pose {
    let (x, y) = warehouse::centre(*route.last().expect("a route"));
    Pose::new(x, y, 0.0)
}

fn plan_request<'a>(route: &'a [Cell], current: Pose, goal: Pose) -> PlanRequest<'a> {
    PlanRequest {
        held_path: route,
        match_from: 0,
        current,
        goal,
        direction: Direction::Forward,
        params: PlanParams::default(),
        extent: FieldExtent::UntilCurrent,
    }
}

/// One edit as the page makes it while the robot drives on the warehouse: a 5 × 5 brush
/// painted (or, every other time, erased) across the held route 6 m ahead of the robot;
/// then the `MapUpdate` with its distance update, the global replan from the robot (the
/// route was blocked) and the local replan on the new route.
pub struct Edit {
    map: GridMap,
    astar: AStar,
    planner: LocalPlanner,
    robot: Pose,
    robot_cell: Cell,
    goal: Pose,
    goal_cell: Cell,
    brush: Cell,
    painted: bool,
    stamp: u32,
}

impl Edit {
    pub fn new() -> Self {
        let map = warehouse::map();
        let route = long_route(&map);
        let at = 330.min(route.len() - 1);
        let robot = pose_on(&route, at);
        let goal = goal_pose(&route);
        let brush = route[(at + 200).min(route.len() - 1)];
        let mut edit = Self {
            astar: AStar::new(&map, DMIN).expect("a planner"),
            planner: LocalPlanner::new(),
            robot_cell: route[at],
            goal_cell: *route.last().expect("a route"),
            map,
            robot,
            goal,
            brush,
            painted: false,
            stamp: 0,
        };
        // Warm: the planners have seen the map once, as they have in a running system.
        edit.step();
        edit.step();
        edit
    }

    fn brush_update(&mut self) {
        self.painted = !self.painted;
        self.stamp += 1;
        let (mut xs, mut ys) = (Vec::new(), Vec::new());
        for dy in -2..=2 {
            for dx in -2..=2 {
                xs.push(self.brush.0 as i32 + dx);
                ys.push(self.brush.1 as i32 + dy);
            }
        }
        let update = MapUpdate {
            value: vec![i16::from(self.painted); xs.len()],
            num: xs.len() as i32,
            x: xs,
            y: ys,
            tm: Time {
                sec: self.stamp,
                nsec: 0,
            },
        };
        self.map.map_update(&update).expect("a valid MapUpdate");
    }

    /// One edit with today's planners; returns the lengths of the new route and local path.
    pub fn step(&mut self) -> (usize, usize) {
        self.brush_update();
        self.astar.sync(&self.map);
        let route = self
            .astar
            .plan(self.robot_cell, self.goal_cell)
            .expect("a route around the brush")
            .cells;
        let plan = self
            .planner
            .plan(&self.map, &plan_request(&route, self.robot, self.goal))
            .expect("a local plan");
        (route.len(), plan.local_path.len())
    }

    /// The same edit with the planners as they were: a cell-by-cell A* made afresh after
    /// the `MapUpdate` (as GlobalPathPlanning did), and the reference field (its pass over
    /// the whole map and its records included).
    pub fn step_reference(&mut self) -> (usize, usize) {
        self.brush_update();
        let mut astar = AStar::new(&self.map, DMIN).expect("a planner");
        let route = astar
            .plan_cellwise(self.robot_cell, self.goal_cell)
            .expect("a route around the brush")
            .cells;
        let request = field_request_for(&self.map, &route, self.robot, self.goal);
        let field = reference::compute(&self.map, &request).expect("a field");
        (route.len(), field.finalized)
    }
}

impl Default for Edit {
    fn default() -> Self {
        Self::new()
    }
}

/// The field request a default local plan makes (the local target found the same way),
/// for the reference field.
fn field_request_for(map: &GridMap, route: &[Cell], robot: Pose, goal: Pose) -> FieldRequest {
    let mut planner = LocalPlanner::new();
    planner
        .plan(map, &plan_request(route, robot, goal))
        .expect("a local plan");
    *planner.field().request().expect("a field was made")
}

/// Default local plans (RouteRemakeDistance 10 m, 000 §4.2) at robot positions every
/// 4.5 m along the long route, heading along it, one position per step, round and round.
pub struct LocalPlans {
    map: GridMap,
    route: Vec<Cell>,
    positions: Vec<usize>,
    planner: LocalPlanner,
    next: usize,
    requests: Vec<FieldRequest>,
}

impl LocalPlans {
    pub fn new() -> Self {
        let map = warehouse::map();
        let route = long_route(&map);
        let positions: Vec<usize> = (0..route.len() - 1).step_by(150).collect();
        let goal = goal_pose(&route);
        let requests = positions
            .iter()
            .map(|&i| field_request_for(&map, &route, pose_on(&route, i), goal))
            .collect();
        Self {
            map,
            route,
            positions,
            planner: LocalPlanner::new(),
            next: 0,
            requests,
        }
    }

    /// How many positions there are.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// The next plan; returns the number of finalized cells.
    pub fn step(&mut self) -> usize {
        let i = self.positions[self.next];
        self.next = (self.next + 1) % self.positions.len();
        let goal = goal_pose(&self.route);
        let request = plan_request(&self.route, pose_on(&self.route, i), goal);
        self.planner
            .plan(&self.map, &request)
            .expect("a local plan");
        self.planner.field().finalized_count()
    }

    /// The reference field for the next position; returns the number of finalized cells.
    pub fn step_reference(&mut self) -> usize {
        let request = self.requests[self.next];
        self.next = (self.next + 1) % self.positions.len();
        reference::compute(&self.map, &request)
            .expect("a field")
            .finalized
    }
}

impl Default for LocalPlans {
    fn default() -> Self {
        Self::new()
    }
}

/// The 1000 × 1000 open map of 0.05 m cells, and a full-field request across it (target
/// 40 m ahead of the robot, default `dmin` and posture level).
pub fn open_field() -> (GridMap, FieldRequest) {
    let map = GridMap::new(1000, 1000, 0.05, (0.0, 0.0), vec![0; 1_000_000]).expect("a map");
    let request = FieldRequest {
        target: (900, 500),
        current: (100, 500),
        current_heading: 0.3,
        target_heading: 0.0,
        direction: Direction::Forward,
        dmin: DMIN,
        posture_consideration_level: PlanParams::default().posture_consideration_level,
        posture: true,
        extent: FieldExtent::Full,
    };
    (map, request)
}

/// The full field of [`open_field`] on reused buffers; returns the cells finalized.
pub fn full_field(field: &mut PotentialField, map: &GridMap, request: &FieldRequest) -> usize {
    field.compute(map, request).expect("a field");
    field.finalized_count()
}
