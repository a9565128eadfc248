//! The LocalPathPlanning RT-component (seed 000, spec §3): receives the map, start/goal and
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
//! # When a local plan is made (000 §5.2.4, spec §3)
//!
//! A *replan request* flag (000 §5.2.4.5 "局所経路の作成を行うためのフラグ") is raised by:
//! - a new `GlobalPathCourse` (spec §3 Decision 0.2): the potential-field plan is made from
//!   the current pose, so the start and goal posture that `PostureConsiderationLevel` names
//!   are considered in every drive, and its control points replace the global ones (a
//!   headless run and the page do exactly this);
//! - a new `InDeviating` sample above `Deviatinglen` (000 §5.2.4.5);
//! - an accepted `MapUpdate` that changes a cell while the goal is not reached (000
//!   §5.2.4.6; spec §3 Decision: an update that changes no cell requests nothing);
//! - the `TargetArea` rule switching the driving direction (000 §5.2.4.4; **Decision**: the
//!   switch must reach DriveControl, so it replans);
//! - a changed planning parameter (`RouteRemakeDistance`, `dmin`,
//!   `PostureConsiderationLevel`, `NotPostureDistance`: reflected `always`, so the next plan
//!   uses them — and it is made at once);
//! - after a failed plan, every 1 s of simulated time while the goal is held and not reached
//!   (spec §3 Decision 0.2: the robot stands meanwhile, and the first success resumes the
//!   drive);
//! - activation (spec §3 Decision 0.2: the progress flags are reset, so the first tick after
//!   activation plans and sends afresh);
//! - [`LocalPathPlanning::request_replan`] (a GUI button; not in the seed).
//!
//! A request counts only while a plan can be made — map, start/goal and a held path are
//! present, the goal is not reached, SafeMode is off and no new goal waits for its course
//! (spec §3 Decision 0.4: a new goal that the held path does not reach is planned for only
//! once the `GlobalPathCourse` made for it arrives) — and is served once, on the next
//! tick, however many triggers came before it. If a new course arrives while no plan can be
//! made, its control points are made from the path as it is and sent (000 §5.2.4.3). After
//! arrival nothing replans until a new `SetPosition` (or an activation).
//!
//! # Escape from the margin (spec §3 Decision 0.2)
//!
//! If the current cell is within `dmin` of an obstacle without being one (tracking, a
//! `MapUpdate` or rounding put the robot there), the position flag stays on: the local plan
//! starts with the shortest step sequence out of the zone ([`crate::map::escape_route`]) and
//! continues from there ([`LocalPathPlanning::escaped_steps`] says how many steps). `SetPosition`
//! still checks start and goal strictly (000 §5.2.4.2).
//!
//! # Held path
//!
//! The held path is the last `GlobalPathCourse`, replaced by the merged path after every
//! successful local plan (000 §5.2.4.8 "前回までに取得又は作成した経路"). A failed plan
//! keeps it (a later `MapUpdate` may clear the way).

mod params;
mod planning;
pub use params::{LocalPathFlags, LocalPathPlanningParams};
pub use planning::FIELD_CELLS_PER_EXECUTION;

use crate::errors::LocalPathError;
use crate::interfaces::{
    ControlPoints, Direction, GlobalPathCourse, GridPath, PlanningFailure, Pose,
};
use crate::local::{
    EscapeLead, FieldExtent, LocalPlan, LocalPlanner, LocalTarget, PlanParams, PotentialField,
    clear_cell, control_points, course_cells, nearest_path_index,
};
use crate::map::{Cell, GridMap, MapUpdate};
use crate::rtc::{
    Component, Configuration, InPort, OutPort, ReturnCode, Tick, TimedDouble, TimedPosition,
};

/// After a failed plan, how long until the next attempt \[ns\] (spec §3 Decision 0.2).
pub const RETRY_NS: u64 = 1_000_000_000;

/// What was last sent, to send only on change (000 §5.2.4.13).
#[derive(Debug, Clone, PartialEq)]
struct Sent {
    cells: Vec<Cell>,
    points: Vec<(f64, f64)>,
    direction: Direction,
    goal_theta: f64,
}

/// The LocalPathPlanning RT-component (seed 000).
#[derive(Debug, Clone)]
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
    /// After a failure: when the next attempt is made \[ns\].
    retry_at_ns: Option<u64>,
    /// The planning parameters of the last plan (a change replans).
    planned_with: Option<PlanParams>,
    /// Steps of the last plan that lead out of the `dmin` zone.
    escaped: usize,
    /// A plan begun and not finished (its field grows over executions in the planner): the
    /// way out of the `dmin` zone to put before it.
    unfinished: Option<EscapeLead>,
    /// A new goal that the held path does not reach: no local plan until the
    /// `GlobalPathCourse` made for it arrives (spec §3 Decision 0.4).
    awaiting_course: bool,
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
            retry_at_ns: None,
            planned_with: None,
            escaped: 0,
            unfinished: None,
            awaiting_course: false,
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
    /// sends the new one). Spec §3 Decision 0.4: if the held path, from the cell nearest the
    /// start on, does not reach the new goal's cell, no local plan is made until the next
    /// `GlobalPathCourse` ([`LocalPathPlanning::awaits_course`]); one that does is planned on.
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
        clear_cell(map, "start", start_x, start_y, dmin)?;
        clear_cell(map, "goal", goal_x, goal_y, dmin)?;
        let start = Pose::new(start_x, start_y, start_angle);
        let goal = Pose::new(goal_x, goal_y, goal_angle);
        self.awaiting_course = !self.held_path_reaches(map, (start_x, start_y), (goal_x, goal_y));
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
        self.retry_at_ns = None;
        self.drop_unfinished();
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
        self.retry_at_ns = None;
        self.planned_with = None;
        self.awaiting_course = false;
        self.drop_unfinished();
    }

    /// `SafeMode` (000 §3.2.2.1 (3), T.B.D. in the seed). **Decision (spec §3)**: halt — the
    /// next tick sends an empty path and empty control points, and nothing is planned or
    /// sent until the next `SetPosition`.
    pub fn safe_mode(&mut self) {
        self.flags.safe_mode = true;
        self.flags.replan_request = false;
        self.send_global = false;
        self.send_empty = true;
        self.retry_at_ns = None;
        self.drop_unfinished();
    }

    /// `SetMap` (000 §3.2.2.1 (4), §5.2.4.1, spec §2): `map_data[x + y · map_length_x]`, 0
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
        // A plan begun on the old map is made again on this one (if one can be).
        if self.unfinished.is_some() {
            self.drop_unfinished();
            self.raise_replan_request();
        }
    }

    /// `MapUpdate` (000 §3.2.2.1 (5), §5.2.4.6, spec §2): sets the listed cells, atomically;
    /// the timestamp becomes the map's version. Returns the number of cells that changed. If
    /// a cell changed and the goal is not reached (and a plan is held), a local replan is
    /// requested; an update that changes nothing requests nothing (spec §3 Decision).
    pub fn map_update(&mut self, update: &MapUpdate) -> crate::Result<usize> {
        let map = self
            .map
            .as_mut()
            .ok_or(LocalPathError::NoMap { call: "MapUpdate" })?;
        let changed = map.map_update(update)?;
        if changed > 0 {
            // A plan begun on the map before is made again on this one.
            self.drop_unfinished();
            self.refresh_current_flag();
            self.raise_replan_request();
        }
        Ok(changed)
    }

    /// `GlobalPathCourse` (000 §3.2.2.1 (6), §5.2.4.3): holds the grid path (start first);
    /// the next tick makes its control points and sends them (once start/goal are held).
    /// Refused (nothing changes) unless both arrays have `num` entries, `num` ≥ 1, every cell
    /// is in the map and consecutive cells are 8-neighbours (spec §3 Decision).
    pub fn global_path_course(
        &mut self,
        grid_path_x: &[i32],
        grid_path_y: &[i32],
        num: i32,
    ) -> crate::Result<()> {
        let map = self.map.as_ref().ok_or(LocalPathError::NoMap {
            call: "GlobalPathCourse",
        })?;
        let cells = course_cells(map, grid_path_x, grid_path_y, num)?;
        self.held_path = cells;
        self.awaiting_course = false;
        self.match_index = 0;
        self.flags.path = true;
        self.drop_unfinished();
        self.field_valid = false;
        self.plan = None;
        // Spec §3 Decision 0.2: the next tick makes the potential-field plan from the current
        // pose; if none can be made, the course is sent as it is (000 §5.2.4.3).
        self.flags.replan_request = false;
        self.send_global = !self.raise_replan_request();
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

    /// How many steps of the last local plan lead out of the `dmin` zone (0: the robot stood
    /// clear; spec §3 Decision 0.2 "escape from the margin").
    pub fn escaped_steps(&self) -> usize {
        self.escaped
    }

    /// After a failed plan: the simulated time \[ns\] of the next attempt (spec §3
    /// Decision 0.2); `None` when no retry is due.
    pub fn retry_at_ns(&self) -> Option<u64> {
        self.retry_at_ns
    }

    /// Whether nothing waits to be planned or sent: no replan request, no course to send,
    /// no parameter change to plan with.
    pub fn is_settled(&self) -> bool {
        let params_changed = self.can_replan()
            && self
                .planned_with
                .is_some_and(|p| p != plan_params(self.config.params()));
        let waiting = (self.flags.replan_request && self.can_replan())
            || self.unfinished.is_some()
            || self.send_global
            || self.send_empty
            || params_changed;
        !waiting
    }

    /// Whether a new goal waits for the `GlobalPathCourse` made for it: the held path does
    /// not reach it, so no local plan is made on it meanwhile (spec §3 Decision 0.4).
    pub fn awaits_course(&self) -> bool {
        self.awaiting_course
    }

    /// Whether a plan is being made over executions (spec §3 Decision 0.2): its field is
    /// unfinished, and what was last sent stays until it is done.
    pub fn is_planning(&self) -> bool {
        self.unfinished.is_some()
    }

    // ----- internals -----

    /// Drops a plan begun and not finished (a new goal, map or path, Clear, SafeMode).
    fn drop_unfinished(&mut self) {
        self.unfinished = None;
        self.planner.cancel();
    }

    fn can_replan(&self) -> bool {
        let f = &self.flags;
        f.map && f.position && f.path && !f.arrived && !f.safe_mode && !self.awaiting_course
    }

    fn raise_replan_request(&mut self) -> bool {
        let ok = self.can_replan();
        if ok {
            self.flags.replan_request = true;
        }
        ok
    }

    /// The position flag (000 §5.2.4.4): the current cell is in the map and not an obstacle.
    /// A cell within `dmin` keeps it on (spec §3 Decision 0.2: the plan escapes first).
    fn refresh_current_flag(&mut self) {
        self.flags.current_position = match (&self.map, self.current) {
            (Some(map), Some(p)) => map
                .world_to_cell(p.x, p.y)
                .is_some_and(|(x, y)| !map.is_obstacle(x as i64, y as i64)),
            _ => false,
        };
    }

    /// spec §3 step 1 (000 §5.2.4.4).
    fn update_current(&mut self, p: &TimedPosition, params: &LocalPathPlanningParams) {
        let pose = Pose::new(p.x, p.y, p.theta);
        // A pose that is not finite, or whose timestamp is not valid (spec §4 Decision 0.2,
        // the one check `Time::checked`), cannot be trusted: no current position.
        if !pose.is_finite() || p.tm.checked("InCurrentPosition").is_err() {
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

    /// 000 §5.2.4.13: empty path and control points (if that is a change) and the notice.
    fn fail(&mut self, tick: &Tick, error: LocalPathError) {
        self.send(tick, Vec::new(), Vec::new());
        let notice = PlanningFailure {
            tm: tick.tm(),
            planner: PLANNER.to_owned(),
            reason: crate::Reason::Error(error.into()),
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

/// The planning parameters of `params` (the ones a plan depends on).
fn plan_params(params: &LocalPathPlanningParams) -> PlanParams {
    PlanParams {
        route_remake_distance: params.route_remake_distance,
        dmin: params.dmin,
        posture_consideration_level: params.posture_consideration_level,
        not_posture_distance: params.not_posture_distance,
    }
}

impl Component for LocalPathPlanning {
    component_basics!(name: name, config: config);

    component_ports!(in: [in_current_position, in_deviating], out: [invent_gui_cons, bump_cons, drive_cons, invent_gui_failure]);

    /// 000 §5.2.3: initialisation. Stale port data is dropped. Spec §3 Decision 0.2: what
    /// the services delivered (map, start/goal, held path) is kept — it is the service
    /// side's, and may come before activation — and the component's own progress flags are
    /// reset (arrived, what was last sent, a pending retry), with a replan requested, so the
    /// first tick after activation plans and sends afresh.
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        self.drop_unfinished();
        self.in_current_position.clear();
        self.in_deviating.clear();
        self.sent = None;
        self.retry_at_ns = None;
        if let (Some(map), Some(goal), Some(cur)) = (self.map.as_ref(), self.goal, self.current) {
            self.flags.arrived = libm::hypot(goal.x - cur.x, goal.y - cur.y) <= map.grid_size();
        }
        self.flags.replan_request = false;
        if !self.raise_replan_request() && self.flags.path && self.flags.position {
            self.send_global = true;
        }
        Ok(())
    }

    /// 000 §5.2.4, spec §3 "Behaviour on every tick".
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
            && d.tm.checked("InDeviating").is_ok()
        {
            self.deviation = Some(d.data);
            if d.data > params.deviatinglen {
                self.raise_replan_request();
            }
        }
        // A retry after a failure (spec §3 Decision 0.2), a changed planning parameter.
        if self.retry_at_ns.is_some_and(|at| tick.time_ns >= at) {
            self.retry_at_ns = None;
            self.raise_replan_request();
        }
        if self.planned_with.is_some_and(|p| p != plan_params(&params)) {
            self.raise_replan_request();
        }
        // Spec §3 Decision 0.2: a plan over executions goes on (a request made meanwhile is
        // served after it), unless it can no longer be made or its parameters changed.
        if self.unfinished.is_some() {
            if self.can_replan() && self.planned_with == Some(plan_params(&params)) {
                self.go_on(tick);
                return Ok(());
            }
            self.drop_unfinished();
        }
        // Steps 3–8: a local plan, if requested (000 §5.2.4.8–13); else the new global
        // path as it is (000 §5.2.4.3).
        let replan = self.flags.replan_request && self.can_replan();
        self.flags.replan_request = false;
        if replan {
            self.send_global = false;
            self.replan(tick, &params);
        } else if self.send_global
            && self.flags.position
            && !self.flags.safe_mode
            && !self.awaiting_course
        {
            self.send_global = false;
            self.send_held_path(tick);
        }
        Ok(())
    }
}
