//! GlobalPathPlanning: the RT-component that plans the whole route on the grid map and sends
//! it to LocalPathPlanning as `GlobalPathCourse` (spec §0, §5 "GlobalPathPlanning";
//! 000 §3.2.2.1 (6) for the data it sends).
//!
//! Services (called between ticks, like the seeds' service ports):
//! - [`set_map`](GlobalPathPlanning::set_map): `SetMap` (spec §2).
//! - [`map_update`](GlobalPathPlanning::map_update): `MapUpdate` (spec §2), atomic.
//! - [`set_position`](GlobalPathPlanning::set_position): start and goal poses; requests a
//!   plan, made at the next `on_execute`.
//!
//! Data port: `InCurrentPosition` (from Localization): where a replan starts.
//!
//! Each tick, a pending request is planned with A* ([`crate::global`]) using the `dmin` in
//! force at that tick. Success writes the route to the OutPort `GlobalPathCourse` and keeps
//! it and its length; failure (start or goal outside the map or blocked, no path, no map)
//! writes a [`PlanningFailure`] to the OutPort `PlanningFailure` and keeps the error. A
//! planning failure is a result, not a component failure: `on_execute` still succeeds.
//!
//! **Replanning (spec §5, Decision 0.2)**: while a goal is held, a new route to it is planned
//! from the current position when
//! - a `MapUpdate` makes a cell of the held route impassable (an obstacle, or within `dmin` of
//!   one), so the path beyond LocalPathPlanning's local target never runs through a new
//!   obstacle;
//! - a `MapUpdate` changes the map after a request failed (the way may be open now);
//! - the effective `dmin` differs from the one the held route (or failure) was planned with
//!   (spec §3 Decision 0.2 "one `dmin`").
//!
//! **Escape from the margin (spec §3 Decision 0.2)**: a start within `dmin` of an obstacle
//! that is not itself an obstacle starts the route with the shortest way out of the zone
//! ([`crate::map::escape_route`]); the goal is still checked strictly.

use crate::errors::GlobalPlanningError;
use crate::global::{AStar, GridPlan, OctileCost};
use crate::interfaces::{GlobalPathCourse, PlanningFailure, Pose};
use crate::map::{Cell, GridMap, MapUpdate, escape_route};
use crate::rtc::{Component, Configuration, InPort, OutPort, ReturnCode, Tick, TimedPosition};

crate::define_parameters! {
    /// GlobalPathPlanning's configuration parameters (spec §5; `dmin` as in 000 §4.2). The
    /// system keeps `dmin` equal to LocalPathPlanning's (spec §3 Decision 0.2 "one `dmin`").
    pub struct GlobalPathPlanningParams {
        /// Closest allowed approach to an obstacle (m): cells whose obstacle distance is
        /// ≤ `dmin` are impassable. `always`: a change replans the held route.
        dmin: f64 = ("dmin", "m", 0.5, 0.0, f64::INFINITY, Always,
            "closest allowed approach to an obstacle (one value with LocalPathPlanning's)"),
    }
}

/// The planner's name in [`PlanningFailure::planner`].
const PLANNER: &str = "GlobalPathPlanning";

/// Why a plan is made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlanReason {
    /// `SetPosition`: a new start and goal.
    Requested,
    /// A `MapUpdate` blocked the held route, or changed the map after a failure.
    MapChanged,
    /// `dmin` changed.
    DminChanged,
}

/// The GlobalPathPlanning RT-component.
#[derive(Debug, Clone)]
pub struct GlobalPathPlanning {
    instance_name: String,
    config: Configuration<GlobalPathPlanningParams>,
    map: Option<GridMap>,
    /// The planner for `map` and the last `dmin` used; dropped when a new map is set, kept
    /// up to date after `MapUpdate`s.
    planner: Option<AStar>,
    /// The goal held (from the last `SetPosition`).
    goal: Option<Pose>,
    /// A plan waits for the next `on_execute`: its start (`None`: the current position).
    request: Option<(Option<Pose>, PlanReason)>,
    /// The newest pose from `InCurrentPosition` (or the last start given).
    current: Option<Pose>,
    /// The `dmin` the held route (or the last failure) was planned with.
    planned_dmin: Option<f64>,
    last_plan: Option<GridPlan>,
    last_reason: Option<PlanReason>,
    last_length: Option<f64>,
    last_error: Option<GlobalPlanningError>,
    escaped: usize,
    /// InPort `InCurrentPosition`: the robot's pose, where a replan starts.
    pub in_current_position: InPort<TimedPosition>,
    /// OutPort `GlobalPathCourse`: the planned grid path, start first.
    pub global_path_course: OutPort<GlobalPathCourse>,
    /// OutPort `PlanningFailure`: why a requested plan could not be made.
    pub planning_failure: OutPort<PlanningFailure>,
}

impl GlobalPathPlanning {
    /// A planner named `instance_name` (e.g. `GlobalPathPlanning0`), no map, `dmin` at its
    /// default.
    pub fn new(instance_name: impl Into<String>) -> Self {
        Self {
            instance_name: instance_name.into(),
            config: Configuration::new(),
            map: None,
            planner: None,
            goal: None,
            request: None,
            current: None,
            planned_dmin: None,
            last_plan: None,
            last_reason: None,
            last_length: None,
            last_error: None,
            escaped: 0,
            in_current_position: InPort::new("InCurrentPosition"),
            global_path_course: OutPort::new("GlobalPathCourse"),
            planning_failure: OutPort::new("PlanningFailure"),
        }
    }

    /// `SetMap` with a map already checked (a `GridMap` is valid by construction). The held
    /// goal and route belong to the old map: they are dropped.
    pub fn set_map(&mut self, map: GridMap) {
        self.map = Some(map);
        self.planner = None;
        self.goal = None;
        self.request = None;
        self.last_plan = None;
        self.last_length = None;
        self.last_error = None;
        self.planned_dmin = None;
    }

    /// `MapUpdate` (000 §3.2.2.1 (5), spec §2): all or nothing. Returns the number of cells
    /// that changed. A change that blocks the held route, or any change after a failed
    /// request, requests a new route from the current position (module documentation).
    pub fn map_update(&mut self, update: &MapUpdate) -> crate::Result<usize> {
        let map = self.map.as_mut().ok_or(GlobalPlanningError::NoMap)?;
        let changed = map.map_update(update)?;
        if changed == 0 {
            return Ok(0);
        }
        // The planner is kept: it is brought up to date at the next plan (`AStar::sync`).
        if self.goal.is_some() && self.request.is_none() {
            let dmin = self.planned_dmin.unwrap_or(self.config.params().dmin);
            let blocked = self
                .last_plan
                .as_ref()
                .is_some_and(|p| p.cells.iter().any(|&c| !map.is_clear(c, dmin)));
            if blocked || self.last_error.is_some() {
                self.request = Some((None, PlanReason::MapChanged));
            }
        }
        Ok(changed)
    }

    /// Requests a plan from `start` to `goal` (map frame, metres); it is made at the next
    /// `on_execute`. A non-finite pose is refused at once and nothing changes. A newer
    /// request replaces one not yet planned. The goal is held for later replans.
    pub fn set_position(&mut self, start: Pose, goal: Pose) -> Result<(), GlobalPlanningError> {
        for (which, p) in [("start", start), ("goal", goal)] {
            if !p.is_finite() {
                return Err(GlobalPlanningError::NonFinitePose {
                    which,
                    x: p.x,
                    y: p.y,
                    theta: p.theta,
                });
            }
        }
        self.goal = Some(goal);
        self.current = Some(start);
        self.request = Some((Some(start), PlanReason::Requested));
        Ok(())
    }

    /// `Clear`: the goal and route are dropped; nothing is replanned until the next
    /// `SetPosition`.
    pub fn clear(&mut self) {
        self.goal = None;
        self.request = None;
        self.last_plan = None;
        self.last_length = None;
        self.last_error = None;
    }

    /// Plans from `start` to `goal` now, with the current map and `dmin`, without touching
    /// the ports or the held results (what `on_execute` does for a request). A start within
    /// `dmin` (not an obstacle) escapes first (module documentation).
    pub fn plan(&mut self, start: Pose, goal: Pose) -> Result<GridPlan, GlobalPlanningError> {
        let map = self.map.as_ref().ok_or(GlobalPlanningError::NoMap)?;
        let mut cells = [(0, 0); 2];
        for (slot, (which, p)) in cells.iter_mut().zip([("start", start), ("goal", goal)]) {
            if !p.is_finite() {
                return Err(GlobalPlanningError::NonFinitePose {
                    which,
                    x: p.x,
                    y: p.y,
                    theta: p.theta,
                });
            }
            *slot = map
                .world_to_cell(p.x, p.y)
                .ok_or(GlobalPlanningError::OutsideMap {
                    which,
                    x: p.x,
                    y: p.y,
                })?;
        }
        let dmin = self.config.params().dmin;
        let escape = escape_route(map, cells[0], dmin).unwrap_or_else(|| vec![cells[0]]);
        let from = escape.last().copied().unwrap_or(cells[0]);
        let mut planner = match self.planner.take() {
            Some(mut p) if p.dmin().to_bits() == dmin.to_bits() => {
                p.sync(map);
                p
            }
            _ => AStar::new(map, dmin)?,
        };
        let result = planner.plan(from, cells[1]);
        self.planner = Some(planner);
        let plan = result?;
        Ok(prepend(&escape, plan))
    }

    /// Whether a request waits for the next `on_execute`.
    pub fn is_requested(&self) -> bool {
        self.request.is_some()
    }

    /// The held map.
    pub fn map(&self) -> Option<&GridMap> {
        self.map.as_ref()
    }

    /// The goal held.
    pub fn goal(&self) -> Option<Pose> {
        self.goal
    }

    /// The route held: the last plan made for a request (cleared by a failed one).
    pub fn last_plan(&self) -> Option<&GridPlan> {
        self.last_plan.as_ref()
    }

    /// Why the last plan (or failure) was made.
    pub fn last_reason(&self) -> Option<PlanReason> {
        self.last_reason
    }

    /// How many steps of the last route escape the `dmin` zone (0: the start was clear).
    pub fn escaped_steps(&self) -> usize {
        self.escaped
    }

    /// Length in metres of the last plan made for a request.
    pub fn path_length(&self) -> Option<f64> {
        self.last_length
    }

    /// Why the last request failed (cleared by a successful one).
    pub fn last_error(&self) -> Option<&GlobalPlanningError> {
        self.last_error.as_ref()
    }

    /// The parameter values in use.
    pub fn params(&self) -> &GlobalPathPlanningParams {
        self.config.params()
    }

    /// The configuration, to read (requested and effective values, sets).
    pub fn config(&self) -> &Configuration<GlobalPathPlanningParams> {
        &self.config
    }

    /// The configuration (the system sets `dmin` together with LocalPathPlanning's).
    pub fn config_mut(&mut self) -> &mut Configuration<GlobalPathPlanningParams> {
        &mut self.config
    }
}

/// `escape` (from the start to its exit, both included) followed by `plan` (from the exit).
fn prepend(escape: &[Cell], plan: GridPlan) -> GridPlan {
    if escape.len() <= 1 {
        return plan;
    }
    let mut cost = OctileCost::ZERO;
    for w in escape.windows(2) {
        cost = cost + OctileCost::between(w[0], w[1]);
    }
    let mut cells = escape[..escape.len() - 1].to_vec();
    cells.extend_from_slice(&plan.cells);
    GridPlan {
        cells,
        cost: cost + plan.cost,
        expanded: plan.expanded,
    }
}

impl Component for GlobalPathPlanning {
    component_basics!(name: instance_name, config: config);

    component_ports!(in: [in_current_position], out: [global_path_course, planning_failure]);

    /// Reads the current position, replans when `dmin` changed, plans a pending request and
    /// sends the route or the failure.
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        if self.in_current_position.is_new()
            && let Some(p) = self.in_current_position.read()
        {
            let pose = Pose::new(p.x, p.y, p.theta);
            // A sample whose timestamp is not valid is ignored like a pose that is not
            // finite (spec §4 Decision 0.2, the one check `Time::checked`).
            if pose.is_finite() && p.tm.checked("InCurrentPosition").is_ok() {
                self.current = Some(pose);
            }
        }
        let dmin = self.config.params().dmin;
        if self.request.is_none()
            && self.goal.is_some()
            && self
                .planned_dmin
                .is_some_and(|d| d.to_bits() != dmin.to_bits())
        {
            self.request = Some((None, PlanReason::DminChanged));
        }
        let Some((start, reason)) = self.request.take() else {
            return Ok(());
        };
        let (Some(start), Some(goal)) = (start.or(self.current), self.goal) else {
            return Ok(());
        };
        self.planned_dmin = Some(dmin);
        self.last_reason = Some(reason);
        match self.plan(start, goal) {
            Ok(plan) => {
                let grid_size = self.map.as_ref().map_or(0.0, GridMap::grid_size);
                self.escaped = self.map.as_ref().map_or(0, |m| {
                    plan.cells
                        .iter()
                        .take_while(|&&c| !m.is_clear(c, dmin))
                        .count()
                });
                self.last_length = Some(plan.length(grid_size));
                self.global_path_course.write(plan.to_course());
                self.last_plan = Some(plan);
                self.last_error = None;
            }
            Err(e) => {
                self.planning_failure.write(PlanningFailure {
                    tm: tick.tm(),
                    planner: PLANNER.to_owned(),
                    reason: crate::Reason::Error(e.clone().into()),
                });
                self.last_plan = None;
                self.last_length = None;
                self.escaped = 0;
                self.last_error = Some(e);
            }
        }
        Ok(())
    }
}
