//! The LocalPathPlanning RT-component (seed 000, SPEC §3): receives the map, start/goal and
//! the global grid path through its `LocalPath` service, the robot's position and deviation
//! through data ports, and sends the (locally replanned) grid path and its control points
//! to the GUI, DriveControl and bump detection.
//!
//! # Services and ticks
//!
//! As in the original (000 §5.2.6), a service call only validates and stores what it is
//! given and raises flags; the work happens in `on_execute`. Every call returns a `Result`:
//! bad input gets an error naming the problem and changes nothing held.
//!
//! # When a local plan is made (000 §5.2.4, SPEC §3)
//!
//! A *replan request* flag (000 §5.2.4.5 "局所経路の作成を行うためのフラグ") is raised by:
//! - a new `InDeviating` sample above `Deviatinglen` (000 §5.2.4.5);
//! - an accepted `MapUpdate` while the goal is not reached (000 §5.2.4.6);
//! - the `TargetArea` rule switching the driving direction (000 §5.2.4.4; **Decision**: the
//!   switch must reach DriveControl, so it replans);
//! - [`LocalPathPlanning::request_replan`] (a GUI button; not in the seed).
//!
//! A request counts only while a plan can be made — map, start/goal and a held path are
//! present, the goal is not reached and SafeMode is off — and is served once, on the next
//! tick, however many triggers came before it. **Decision**: a new `GlobalPathCourse` does
//! *not* replan: as 000 §5.2.4.3 says, its control points are made from the path as it is and
//! sent (and it drops a pending request, since the path is new). Neither does the first (or
//! any) `InCurrentPosition` by itself. After arrival nothing replans until a new
//! `SetPosition`.
//!
//! # Held path
//!
//! The held path is the last `GlobalPathCourse`, replaced by the merged path after every
//! successful local plan (000 §5.2.4.8 "前回までに取得又は作成した経路"). A failed plan
//! keeps it (a later `MapUpdate` may clear the way).

use serde::{Deserialize, Serialize};

use crate::define_parameters;
use crate::errors::LocalPathError;
use crate::interfaces::{
    ControlPoints, Direction, GlobalPathCourse, GridPath, PlanningFailure, Pose,
};
use crate::local::{
    FieldExtent, LocalPlan, LocalPlanner, LocalTarget, PlanParams, PlanRequest, PotentialField,
    control_points, nearest_path_index,
};
use crate::map::{Cell, GridMap};
use crate::rtc::{
    Component, ConfigAccess, Configuration, InPort, OutPort, ReturnCode, Tick, Time, TimedDouble,
    TimedPosition,
};

define_parameters! {
    /// The configuration parameters of 000 §4.2, all reflected `always` (常時).
    pub struct LocalPathPlanningParams {
        /// `RouteRemakeDistance` \[m\]: path distance from the current position to the local
        /// target (局所経路を生成する際の現在位置から目標位置までの経路上の距離).
        route_remake_distance: f64 = ("RouteRemakeDistance", "m", 10.0, 0.0, f64::INFINITY, Always,
            "path distance from the current position to the local target"),
        /// `Deviatinglen` \[m\]: deviation that triggers a local replan (経路逸脱限界距離).
        deviatinglen: f64 = ("Deviatinglen", "m", 0.1, 0.0, f64::INFINITY, Always,
            "deviation from the path that triggers a local replan"),
        /// `dmin` \[m\]: closest allowed approach to an obstacle (障害物に近づくことができる距離).
        /// The seed's table gives its unit as "-"; it is compared with obstacle distances in
        /// metres, so SPEC §3 gives `m`.
        dmin: f64 = ("dmin", "m", 0.5, 0.0, f64::INFINITY, Always,
            "closest allowed approach to an obstacle"),
        /// `PostureConsiderationLevel` \[%\]: weight of the start/goal posture
        /// (スタート姿勢・ゴール姿勢の考慮レベル).
        posture_consideration_level: f64 = ("PostureConsiderationLevel", "%", 85.0, 0.0, 100.0, Always,
            "weight of the start and goal posture"),
        /// `NotPostureDistance` \[m\]: within this straight distance of the goal, posture is
        /// ignored (姿勢を考慮せずに経路生成を行う目標位置からの距離).
        not_posture_distance: f64 = ("NotPostureDistance", "m", 1.0, 0.0, f64::INFINITY, Always,
            "within this straight distance of the goal the posture is not considered"),
        /// `TargetArea` \[m\]: near the goal, forward/backward is chosen by where the goal lies
        /// (目標位置付近において前進、後進を変更しつつ目標位置に近づく経路生成を行う範囲).
        target_area: f64 = ("TargetArea", "m", 0.5, 0.0, f64::INFINITY, Always,
            "near the goal, forward or backward is chosen by where the goal lies"),
    }
}

/// The held flags of 000 §5.2.4 ("…を取得したか判断するためのフラグ"), readable for the GUI.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct LocalPathFlags {
    /// A map is held (`SetMap`, 000 §5.2.4.1).
    pub map: bool,
    /// Start and goal are held and passable (`SetPosition`, 000 §5.2.4.2).
    pub position: bool,
    /// A grid path is held (`GlobalPathCourse`, 000 §5.2.4.3).
    pub path: bool,
    /// The current position is in the map and passable (000 §5.2.4.4).
    pub current_position: bool,
    /// The goal is reached: straight distance ≤ `GridSize` (000 §5.2.4.4). Latched until the
    /// next `SetPosition` or `Clear`.
    pub arrived: bool,
    /// A local replan is requested (000 §5.2.4.5, §5.2.4.6).
    pub replan_request: bool,
    /// SafeMode: halted until the next `SetPosition` (SPEC §3 Decision).
    pub safe_mode: bool,
}

/// What was last sent, to send only on change (000 §5.2.4.13).
#[derive(Debug, Clone, PartialEq)]
struct Sent {
    cells: Vec<Cell>,
    points: Vec<(f64, f64)>,
    direction: Direction,
    goal_theta: f64,
}

/// The LocalPathPlanning RT-component (seed 000).
#[derive(Debug)]
pub struct LocalPathPlanning {
    name: String,
    config: Configuration<LocalPathPlanningParams>,
    /// `InCurrentPosition`: the robot's current pose (000 §3.1).
    pub in_current_position: InPort<TimedPosition>,
    /// `InDeviating`: distance of the robot from its target trajectory \[m\] (000 §3.1).
    pub in_deviating: InPort<TimedDouble>,
    /// `InventGUICons`: the grid path for the GUI (000 §3.2.1).
    pub invent_gui_cons: OutPort<GridPath>,
    /// `BumpCons`: the grid path for bump detection (000 §3.2.1).
    pub bump_cons: OutPort<GridPath>,
    /// `DriveCons`: the control points for DriveControl (000 §3.2.1).
    pub drive_cons: OutPort<ControlPoints>,
    /// `InventGUIConsFailure`: the planning-failure notice that `InventGUICons` carries in
    /// the seed ("経路生成エラー通知を送る", 000 §3.2.1, §5.2.4.13).
    pub invent_gui_failure: OutPort<PlanningFailure>,
    map: Option<GridMap>,
    start: Option<Pose>,
    goal: Option<Pose>,
    commanded_direction: Direction,
    direction: Direction,
    current: Option<Pose>,
    deviation: Option<f64>,
    held_path: Vec<Cell>,
    match_index: usize,
    flags: LocalPathFlags,
    send_global: bool,
    send_empty: bool,
    extent: FieldExtent,
    planner: LocalPlanner,
    field_valid: bool,
    plan: Option<LocalPlan>,
    sent: Option<Sent>,
    merged_path: Vec<Cell>,
    control_points: Option<ControlPoints>,
    last_failure: Option<PlanningFailure>,
    plan_count: u64,
}

const PLANNER: &str = "LocalPathPlanning";

impl Default for LocalPathPlanning {
    fn default() -> Self {
        Self::new("LocalPathPlanning0")
    }
}

impl LocalPathPlanning {
    /// A component with default parameters and nothing held.
    pub fn new(instance_name: impl Into<String>) -> Self {
        Self {
            name: instance_name.into(),
            config: Configuration::new(),
            in_current_position: InPort::new("InCurrentPosition"),
            in_deviating: InPort::new("InDeviating"),
            invent_gui_cons: OutPort::new("InventGUICons"),
            bump_cons: OutPort::new("BumpCons"),
            drive_cons: OutPort::new("DriveCons"),
            invent_gui_failure: OutPort::new("InventGUIConsFailure"),
            map: None,
            start: None,
            goal: None,
            commanded_direction: Direction::Forward,
            direction: Direction::Forward,
            current: None,
            deviation: None,
            held_path: Vec::new(),
            match_index: 0,
            flags: LocalPathFlags::default(),
            send_global: false,
            send_empty: false,
            extent: FieldExtent::default(),
            planner: LocalPlanner::new(),
            field_valid: false,
            plan: None,
            sent: None,
            merged_path: Vec::new(),
            control_points: None,
            last_failure: None,
            plan_count: 0,
        }
    }

    // ----- LocalPath service (000 §3.2.2.1) -----

    /// `SetPosition` (000 §3.2.2.1 (1), §5.2.4.2): stores start and goal \[m, rad\] and the
    /// direction (1 forward, 2 backward); the start becomes the current position.
    ///
    /// Refused (nothing changes) for a non-finite number, a direction other than 1/2, no map,
    /// or a start/goal outside the map or whose cell or any cell within `dmin` is an
    /// obstacle. Accepting it clears arrival, SafeMode, a pending replan request and the
    /// field and local plan drawn for the old goal; the held path stays (GlobalPathPlanning
    /// sends the new one; until then a replan on the old path fails with
    /// [`LocalPathError::GoalNotOnPath`] unless it passes the new goal).
    #[allow(clippy::too_many_arguments)]
    pub fn set_position(
        &mut self,
        start_x: f64,
        start_y: f64,
        start_angle: f64,
        goal_x: f64,
        goal_y: f64,
        goal_angle: f64,
        direction: i16,
    ) -> crate::Result<()> {
        const CALL: &str = "SetPosition";
        for (argument, value) in [
            ("StartX", start_x),
            ("StartY", start_y),
            ("StartAngle", start_angle),
            ("GoalX", goal_x),
            ("GoalY", goal_y),
            ("GoalAngle", goal_angle),
        ] {
            if !value.is_finite() {
                return Err(LocalPathError::NotFinite {
                    call: CALL,
                    argument,
                    value,
                }
                .into());
            }
        }
        let dir = Direction::from_short(direction)
            .ok_or(LocalPathError::BadDirection { value: direction })?;
        let map = self
            .map
            .as_ref()
            .ok_or(LocalPathError::NoMap { call: CALL })?;
        let dmin = self.config.params().dmin;
        check_clear(map, "start", start_x, start_y, dmin)?;
        check_clear(map, "goal", goal_x, goal_y, dmin)?;
        let start = Pose::new(start_x, start_y, start_angle);
        let goal = Pose::new(goal_x, goal_y, goal_angle);
        self.start = Some(start);
        self.goal = Some(goal);
        self.current = Some(start);
        self.commanded_direction = dir;
        self.direction = dir;
        self.match_index = 0;
        self.flags.position = true;
        self.flags.current_position = true;
        self.flags.arrived = libm::hypot(goal_x - start_x, goal_y - start_y) <= map.grid_size();
        self.flags.replan_request = false;
        self.flags.safe_mode = false;
        // The field and local plan drawn were for the old start/goal.
        self.field_valid = false;
        self.plan = None;
        Ok(())
    }

    /// `Clear` (000 §3.2.2.1 (2), §5.2.4.7): drops everything held — map, start/goal, path,
    /// positions, plans — and turns every flag off. If a non-empty path was sent, the next
    /// tick sends an empty one so the consumers drop theirs. Parameters stay.
    pub fn clear(&mut self) {
        let had_output = self.sent.as_ref().is_some_and(|s| !s.cells.is_empty());
        self.map = None;
        self.start = None;
        self.goal = None;
        self.current = None;
        self.deviation = None;
        self.commanded_direction = Direction::Forward;
        self.direction = Direction::Forward;
        self.held_path.clear();
        self.match_index = 0;
        self.flags = LocalPathFlags::default();
        self.send_global = false;
        self.send_empty = had_output;
        self.field_valid = false;
        self.plan = None;
        self.merged_path.clear();
        self.control_points = None;
        self.last_failure = None;
    }

    /// `SafeMode` (000 §3.2.2.1 (3), T.B.D. in the seed). **Decision (SPEC §3)**: halt — the
    /// next tick sends an empty path and empty control points, and nothing is planned or
    /// sent until the next `SetPosition`.
    pub fn safe_mode(&mut self) {
        self.flags.safe_mode = true;
        self.flags.replan_request = false;
        self.send_global = false;
        self.send_empty = true;
    }

    /// `SetMap` (000 §3.2.2.1 (4), §5.2.4.1, SPEC §2): `map_data[x + y · map_length_x]`, 0
    /// free / 1 obstacle. Refused (the old map stays) for a wrong length, a value other than
    /// 0/1, a dimension < 1 or a bad `grid_size`.
    pub fn set_map(
        &mut self,
        map_data: &[i16],
        map_length_x: i32,
        map_length_y: i32,
        grid_size: f64,
    ) -> crate::Result<()> {
        let map = GridMap::from_map_data(map_data, map_length_x, map_length_y, grid_size)?;
        self.set_grid_map(map);
        Ok(())
    }

    /// Holds `map` as `SetMap` does (a convenience for maps loaded elsewhere, e.g. with an
    /// origin). A held path with a cell outside the new map is dropped; the field and plan
    /// drawn for the old map are dropped.
    pub fn set_grid_map(&mut self, map: GridMap) {
        if self
            .held_path
            .iter()
            .any(|&(x, y)| !map.contains(x as i64, y as i64))
        {
            self.held_path.clear();
            self.flags.path = false;
            self.send_global = false;
        }
        self.map = Some(map);
        self.flags.map = true;
        self.field_valid = false;
        self.plan = None;
        self.refresh_current_flag();
    }

    /// `MapUpdate` (000 §3.2.2.1 (5), §5.2.4.6, SPEC §2): sets the listed cells, atomically;
    /// the timestamp becomes the map's version. If the goal is not reached (and a plan is
    /// held), a local replan is requested.
    pub fn map_update(
        &mut self,
        x: &[i32],
        y: &[i32],
        value: &[i16],
        num: i32,
        sec: u32,
        nsec: u32,
    ) -> crate::Result<()> {
        if nsec >= 1_000_000_000 {
            return Err(LocalPathError::BadTimestamp { nsec }.into());
        }
        let map = self
            .map
            .as_mut()
            .ok_or(LocalPathError::NoMap { call: "MapUpdate" })?;
        map.map_update(x, y, value, num, Time { sec, nsec })?;
        self.refresh_current_flag();
        self.raise_replan_request();
        Ok(())
    }

    /// `GlobalPathCourse` (000 §3.2.2.1 (6), §5.2.4.3): holds the grid path (start first);
    /// the next tick makes its control points and sends them (once start/goal are held).
    /// Refused (nothing changes) unless both arrays have `num` entries, `num` ≥ 1, every cell
    /// is in the map and consecutive cells are 8-neighbours (SPEC §3 Decision).
    pub fn global_path_course(
        &mut self,
        grid_path_x: &[i32],
        grid_path_y: &[i32],
        num: i32,
    ) -> crate::Result<()> {
        let map = self.map.as_ref().ok_or(LocalPathError::NoMap {
            call: "GlobalPathCourse",
        })?;
        for (array, len) in [
            ("GridPathX", grid_path_x.len()),
            ("GridPathY", grid_path_y.len()),
        ] {
            if num < 0 || len != num as usize {
                return Err(LocalPathError::PathLength { array, len, num }.into());
            }
        }
        if num == 0 {
            return Err(LocalPathError::EmptyPath.into());
        }
        let mut cells = Vec::with_capacity(grid_path_x.len());
        for (index, (&x, &y)) in grid_path_x.iter().zip(grid_path_y).enumerate() {
            let (x, y) = (i64::from(x), i64::from(y));
            if !map.contains(x, y) {
                return Err(LocalPathError::PathCellOutside {
                    index,
                    x,
                    y,
                    width: map.width(),
                    height: map.height(),
                }
                .into());
            }
            if index > 0 {
                let (px, py) = (
                    i64::from(grid_path_x[index - 1]),
                    i64::from(grid_path_y[index - 1]),
                );
                let (dx, dy) = ((x - px).abs(), (y - py).abs());
                if dx > 1 || dy > 1 || (dx == 0 && dy == 0) {
                    return Err(LocalPathError::PathNotAdjacent {
                        index,
                        from: (px, py),
                        to: (x, y),
                    }
                    .into());
                }
            }
            cells.push((x as usize, y as usize));
        }
        self.held_path = cells;
        self.match_index = 0;
        self.flags.path = true;
        self.flags.replan_request = false;
        self.send_global = true;
        self.field_valid = false;
        self.plan = None;
        Ok(())
    }

    /// [`LocalPathPlanning::global_path_course`] from the shared message type.
    pub fn set_global_path(&mut self, course: &GlobalPathCourse) -> crate::Result<()> {
        self.global_path_course(&course.grid_path_x, &course.grid_path_y, course.num)
    }

    /// Requests a local replan on the next tick, as a deviation would (a GUI button; not in
    /// the seed). Returns whether the request counts (see the module documentation).
    pub fn request_replan(&mut self) -> bool {
        self.raise_replan_request()
    }

    /// How much of the potential field to compute (default: until the current cell; the
    /// GUI may ask for the full field). The path is the same either way.
    pub fn set_field_extent(&mut self, extent: FieldExtent) {
        self.extent = extent;
    }

    // ----- what the GUI reads -----

    /// The held flags (000 §5.2.4).
    pub fn flags(&self) -> LocalPathFlags {
        self.flags
    }

    /// The parameters in effect.
    pub fn params(&self) -> &LocalPathPlanningParams {
        self.config.params()
    }

    /// The configuration (to set parameters: `config_mut().set("dmin", 0.3)`).
    pub fn config(&self) -> &Configuration<LocalPathPlanningParams> {
        &self.config
    }

    /// The configuration, mutably.
    pub fn config_mut(&mut self) -> &mut Configuration<LocalPathPlanningParams> {
        &mut self.config
    }

    /// The held map.
    pub fn map(&self) -> Option<&GridMap> {
        self.map.as_ref()
    }

    /// The start of `SetPosition`.
    pub fn start(&self) -> Option<Pose> {
        self.start
    }

    /// The goal of `SetPosition`.
    pub fn goal(&self) -> Option<Pose> {
        self.goal
    }

    /// The current position (the start until the first `InCurrentPosition`).
    pub fn current_position(&self) -> Option<Pose> {
        self.current
    }

    /// The last deviation read from `InDeviating` \[m\].
    pub fn deviation(&self) -> Option<f64> {
        self.deviation
    }

    /// The driving direction in effect (the `TargetArea` rule may have switched it).
    pub fn direction(&self) -> Direction {
        self.direction
    }

    /// The direction given by `SetPosition`.
    pub fn commanded_direction(&self) -> Direction {
        self.commanded_direction
    }

    /// The held path.
    pub fn held_path(&self) -> &[Cell] {
        &self.held_path
    }

    /// How much of the field is computed.
    pub fn field_extent(&self) -> FieldExtent {
        self.extent
    }

    /// The potential field of the latest local plan (also of a failed one), until the path
    /// or map is replaced.
    pub fn potential_field(&self) -> Option<&PotentialField> {
        self.field_valid.then(|| self.planner.field())
    }

    /// The latest successful local plan, until the path or map is replaced.
    pub fn local_plan(&self) -> Option<&LocalPlan> {
        self.plan.as_ref()
    }

    /// The latest local target (cell and heading).
    pub fn local_target(&self) -> Option<&LocalTarget> {
        self.plan.as_ref().map(|p| &p.target)
    }

    /// The latest local path (current cell … target).
    pub fn local_path(&self) -> &[Cell] {
        self.plan.as_ref().map_or(&[], |p| &p.local_path)
    }

    /// The grid path last made for the consumers (merged path, or the global path as
    /// received); empty after a failure.
    pub fn merged_path(&self) -> &[Cell] {
        &self.merged_path
    }

    /// The control points last made for DriveControl.
    pub fn control_points(&self) -> Option<&ControlPoints> {
        self.control_points.as_ref()
    }

    /// The last planning-failure notice.
    pub fn last_failure(&self) -> Option<&PlanningFailure> {
        self.last_failure.as_ref()
    }

    /// How many local plans (potential fields) were attempted.
    pub fn plan_count(&self) -> u64 {
        self.plan_count
    }

    // ----- internals -----

    fn can_replan(&self) -> bool {
        let f = &self.flags;
        f.map && f.position && f.path && !f.arrived && !f.safe_mode
    }

    fn raise_replan_request(&mut self) -> bool {
        let ok = self.can_replan();
        if ok {
            self.flags.replan_request = true;
        }
        ok
    }

    fn refresh_current_flag(&mut self) {
        let dmin = self.config.params().dmin;
        self.flags.current_position = match (&self.map, self.current) {
            (Some(map), Some(p)) => map
                .world_to_cell(p.x, p.y)
                .is_some_and(|c| map.is_clear(c, dmin)),
            _ => false,
        };
    }

    /// SPEC §3 step 1 (000 §5.2.4.4).
    fn update_current(&mut self, p: &TimedPosition, params: &LocalPathPlanningParams) {
        let pose = Pose::new(p.x, p.y, p.theta);
        if !pose.is_finite() {
            self.flags.current_position = false;
            return;
        }
        self.current = Some(pose);
        self.refresh_current_flag();
        let (Some(goal), Some(map)) = (self.goal, self.map.as_ref()) else {
            return;
        };
        let (dx, dy) = (goal.x - pose.x, goal.y - pose.y);
        let dist = libm::hypot(dx, dy);
        if dist <= map.grid_size() {
            self.flags.arrived = true;
        }
        let direction = if dist <= params.target_area && dist > 0.0 {
            // Forward if the goal lies within ±90° of the current heading.
            if dx * libm::cos(pose.theta) + dy * libm::sin(pose.theta) >= 0.0 {
                Direction::Forward
            } else {
                Direction::Backward
            }
        } else if dist > params.target_area {
            self.commanded_direction
        } else {
            self.direction
        };
        if direction != self.direction {
            self.direction = direction;
            self.raise_replan_request();
        }
    }

    /// 000 §5.2.4.3: control points of the held path as received, sent.
    fn send_held_path(&mut self, tick: &Tick) {
        let (Some(map), Some(goal), Some(cur)) = (self.map.as_ref(), self.goal, self.current)
        else {
            return;
        };
        let Some(goal_cell) = map.world_to_cell(goal.x, goal.y) else {
            return;
        };
        let Some(m) = nearest_path_index(map, &self.held_path, 0, (cur.x, cur.y)) else {
            return;
        };
        let Some(k) = self.held_path[m..].iter().position(|&c| c == goal_cell) else {
            self.fail(tick, LocalPathError::GoalNotOnPath { goal: goal_cell });
            return;
        };
        let cells = self.held_path[m..=m + k].to_vec();
        let points = control_points(map, &cells, (cur.x, cur.y), (goal.x, goal.y));
        self.match_index = m;
        self.send(tick, cells, points);
    }

    /// SPEC §3 steps 3–8.
    fn replan(&mut self, tick: &Tick, params: &LocalPathPlanningParams) {
        let (Some(map), Some(goal), Some(current)) = (self.map.as_ref(), self.goal, self.current)
        else {
            return;
        };
        let request = PlanRequest {
            held_path: &self.held_path,
            match_from: self.match_index,
            current,
            goal,
            direction: self.direction,
            params: PlanParams {
                route_remake_distance: params.route_remake_distance,
                dmin: params.dmin,
                posture_consideration_level: params.posture_consideration_level,
                not_posture_distance: params.not_posture_distance,
            },
            extent: self.extent,
        };
        self.plan_count += 1;
        let result = self.planner.plan(map, &request);
        self.field_valid = self.planner.field_is_fresh();
        match result {
            Ok(plan) => {
                self.held_path = plan.merged_path.clone();
                self.match_index = 0;
                self.send(tick, plan.merged_path.clone(), plan.control_points.clone());
                self.plan = Some(plan);
            }
            Err(e) => {
                self.plan = None;
                self.fail(tick, e);
            }
        }
    }

    /// 000 §5.2.4.13: empty path and control points (if that is a change) and the notice.
    fn fail(&mut self, tick: &Tick, error: LocalPathError) {
        self.send(tick, Vec::new(), Vec::new());
        let notice = PlanningFailure {
            tm: tick.tm(),
            planner: PLANNER.to_owned(),
            reason: error.to_string(),
        };
        self.invent_gui_failure.write(notice.clone());
        self.last_failure = Some(notice);
    }

    /// 000 §5.2.4.13: sends grid path and control points if they differ from the last sent.
    fn send(&mut self, tick: &Tick, cells: Vec<Cell>, points: Vec<(f64, f64)>) {
        let goal_theta = self.goal.map_or(0.0, |g| g.theta);
        let sent = if points.is_empty() && cells.is_empty() {
            Sent {
                cells: Vec::new(),
                points: Vec::new(),
                direction: Direction::Forward,
                goal_theta: 0.0,
            }
        } else {
            Sent {
                cells: cells.clone(),
                points: points.clone(),
                direction: self.direction,
                goal_theta,
            }
        };
        let cp = ControlPoints {
            tm: tick.tm(),
            points,
            direction: self.direction,
            goal_theta,
        };
        if self.sent.as_ref() != Some(&sent) {
            let path = GridPath {
                tm: tick.tm(),
                cells: cells.clone(),
            };
            self.invent_gui_cons.write(path.clone());
            self.bump_cons.write(path);
            self.drive_cons.write(cp.clone());
            self.sent = Some(sent);
        }
        self.merged_path = cells;
        self.control_points = Some(cp);
    }
}

fn check_clear(
    map: &GridMap,
    what: &'static str,
    x: f64,
    y: f64,
    dmin: f64,
) -> Result<(), LocalPathError> {
    let cell = map
        .world_to_cell(x, y)
        .ok_or(LocalPathError::OutsideMap { what, x, y })?;
    if !map.is_clear(cell, dmin) {
        return Err(LocalPathError::NotClear {
            what,
            x,
            y,
            cell,
            distance: map.obstacle_distance(cell),
            dmin,
        });
    }
    Ok(())
}

impl Component for LocalPathPlanning {
    fn instance_name(&self) -> &str {
        &self.name
    }

    fn configuration(&mut self) -> Option<&mut dyn ConfigAccess> {
        Some(&mut self.config)
    }

    fn configuration_ref(&self) -> Option<&dyn ConfigAccess> {
        Some(&self.config)
    }

    /// 000 §5.2.3: initialisation. Stale port data is dropped and a pending replan request
    /// cleared. **Decision**: what the services delivered (map, start/goal, path) is kept,
    /// since in rtnav they may be called before activation.
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        self.in_current_position.clear();
        self.in_deviating.clear();
        self.flags.replan_request = false;
        Ok(())
    }

    /// 000 §5.2.4, SPEC §3 "Behaviour on every tick".
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        let params = *self.config.params();
        if self.send_empty {
            // Clear / SafeMode: the consumers drop what they hold.
            self.send_empty = false;
            self.sent = None;
            self.send(tick, Vec::new(), Vec::new());
        }
        // Step 1: current position (000 §5.2.4.4).
        if self.in_current_position.is_new()
            && let Some(p) = self.in_current_position.read()
        {
            self.update_current(&p, &params);
        }
        // Step 2: deviation (000 §5.2.4.5).
        if self.in_deviating.is_new()
            && let Some(d) = self.in_deviating.read()
            && d.data.is_finite()
        {
            self.deviation = Some(d.data);
            if d.data > params.deviatinglen {
                self.raise_replan_request();
            }
        }
        // Steps 3–8: a local plan, if requested (000 §5.2.4.8–13); else the new global
        // path as it is (000 §5.2.4.3).
        let replan = self.flags.replan_request && self.can_replan();
        self.flags.replan_request = false;
        if replan {
            self.send_global = false;
            self.replan(tick, &params);
        } else if self.send_global && self.flags.position && !self.flags.safe_mode {
            self.send_global = false;
            self.send_held_path(tick);
        }
        Ok(())
    }
}
