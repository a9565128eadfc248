//! GlobalPathPlanning: the RT-component that plans the whole route on the grid map and sends
//! it to LocalPathPlanning as `GlobalPathCourse` (SPEC §0, §5 "GlobalPathPlanning";
//! 000 §3.2.2.1 (6) for the data it sends).
//!
//! Services (called between ticks, like the seeds' service ports):
//! - [`set_map`](GlobalPathPlanning::set_map) / [`set_map_data`](GlobalPathPlanning::set_map_data):
//!   `SetMap` (SPEC §2); a refused map leaves the held one.
//! - [`map_update`](GlobalPathPlanning::map_update): `MapUpdate` (SPEC §2), atomic.
//! - [`set_position`](GlobalPathPlanning::set_position): start and goal poses; requests a
//!   plan, made at the next `on_execute`.
//!
//! Each tick, a pending request is planned with A* ([`crate::global`]) using the `dmin` in
//! force at that tick. Success writes the path to the OutPort `GlobalPathCourse` and keeps
//! its length ([`GlobalPathPlanning::path_length`]); failure (start or goal outside the map
//! or blocked, no path, no map) writes a [`PlanningFailure`] to the OutPort
//! `PlanningFailure` and keeps the error ([`GlobalPathPlanning::last_error`]). A planning
//! failure is a result, not a component failure: `on_execute` still succeeds.
//!
//! **Decision**: a `MapUpdate` does not replan by itself. The held global path is a route;
//! LocalPathPlanning replans around changes locally (SPEC §3, 000 §5.2.4.6), and a new
//! `set_position` asks for a new route.

use crate::errors::{GlobalPlanningError, MapError};
use crate::global::{AStar, GridPlan};
use crate::interfaces::{GlobalPathCourse, PlanningFailure, Pose};
use crate::map::GridMap;
use crate::rtc::{Component, ConfigAccess, Configuration, OutPort, ReturnCode, Tick, Time};

crate::define_parameters! {
    /// GlobalPathPlanning's configuration parameters (SPEC §5; `dmin` as in 000 §4.2).
    pub struct GlobalPathPlanningParams {
        /// Closest allowed approach to an obstacle (m): cells whose obstacle distance is
        /// ≤ `dmin` are impassable. `always`: the next plan uses the new value.
        dmin: f64 = ("dmin", "m", 0.5, 0.0, f64::INFINITY, Always,
            "closest allowed approach to an obstacle"),
    }
}

/// The planner's name in [`PlanningFailure::planner`].
const PLANNER: &str = "GlobalPathPlanning";

/// The GlobalPathPlanning RT-component.
#[derive(Debug)]
pub struct GlobalPathPlanning {
    instance_name: String,
    config: Configuration<GlobalPathPlanningParams>,
    map: Option<GridMap>,
    /// The planner for `map` and the last `dmin` used; dropped when a new map is set, kept
    /// up to date after `MapUpdate`s.
    planner: Option<AStar>,
    request: Option<(Pose, Pose)>,
    last_plan: Option<GridPlan>,
    last_length: Option<f64>,
    last_error: Option<GlobalPlanningError>,
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
            request: None,
            last_plan: None,
            last_length: None,
            last_error: None,
            global_path_course: OutPort::new("GlobalPathCourse"),
            planning_failure: OutPort::new("PlanningFailure"),
        }
    }

    /// `SetMap` with a map already checked (a `GridMap` is valid by construction).
    pub fn set_map(&mut self, map: GridMap) {
        self.map = Some(map);
        self.planner = None;
    }

    /// `SetMap(MapData, MapLengthX, MapLengthY, GridSize)` (000 §3.2.2.1 (4), SPEC §2): on an
    /// error the held map stays.
    pub fn set_map_data(
        &mut self,
        map_data: &[i16],
        map_length_x: i32,
        map_length_y: i32,
        grid_size: f64,
    ) -> Result<(), MapError> {
        let map = GridMap::from_map_data(map_data, map_length_x, map_length_y, grid_size)?;
        self.set_map(map);
        Ok(())
    }

    /// `MapUpdate(X, Y, value, num, sec, nsec)` (000 §3.2.2.1 (5), SPEC §2): all or nothing.
    /// Returns the number of cells that changed.
    pub fn map_update(
        &mut self,
        x: &[i32],
        y: &[i32],
        value: &[i16],
        num: i32,
        tm: Time,
    ) -> crate::Result<usize> {
        let map = self.map.as_mut().ok_or(GlobalPlanningError::NoMap)?;
        // The planner is brought up to date at the next plan (`AStar::sync`).
        Ok(map.map_update(x, y, value, num, tm)?)
    }

    /// Requests a plan from `start` to `goal` (map frame, metres); it is made at the next
    /// `on_execute`. A non-finite pose is refused at once and nothing changes. A newer
    /// request replaces one not yet planned.
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
        self.request = Some((start, goal));
        Ok(())
    }

    /// Plans from `start` to `goal` now, with the current map and `dmin`, without touching
    /// the ports or the held results (what `on_execute` does for a request).
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
        let mut planner = match self.planner.take() {
            Some(mut p) if p.dmin().to_bits() == dmin.to_bits() => {
                p.sync(map);
                p
            }
            _ => AStar::new(map, dmin)?,
        };
        let result = planner.plan(cells[0], cells[1]);
        self.planner = Some(planner);
        result
    }

    /// Whether a request waits for the next `on_execute`.
    pub fn is_requested(&self) -> bool {
        self.request.is_some()
    }

    /// The held map.
    pub fn map(&self) -> Option<&GridMap> {
        self.map.as_ref()
    }

    /// The last plan made for a request (cleared by a failed one).
    pub fn last_plan(&self) -> Option<&GridPlan> {
        self.last_plan.as_ref()
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

    /// The configuration (to set `dmin`).
    pub fn config_mut(&mut self) -> &mut Configuration<GlobalPathPlanningParams> {
        &mut self.config
    }
}

impl Component for GlobalPathPlanning {
    fn instance_name(&self) -> &str {
        &self.instance_name
    }

    fn configuration(&mut self) -> Option<&mut dyn ConfigAccess> {
        Some(&mut self.config)
    }

    fn configuration_ref(&self) -> Option<&dyn ConfigAccess> {
        Some(&self.config)
    }

    /// Plans a pending request and sends the path or the failure.
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        let Some((start, goal)) = self.request.take() else {
            return Ok(());
        };
        match self.plan(start, goal) {
            Ok(plan) => {
                let grid_size = self.map.as_ref().map_or(0.0, GridMap::grid_size);
                self.last_length = Some(plan.length(grid_size));
                self.global_path_course.write(plan.to_course());
                self.last_plan = Some(plan);
                self.last_error = None;
            }
            Err(e) => {
                self.planning_failure.write(PlanningFailure {
                    tm: tick.tm(),
                    planner: PLANNER.to_owned(),
                    reason: e.to_string(),
                });
                self.last_plan = None;
                self.last_length = None;
                self.last_error = Some(e);
            }
        }
        Ok(())
    }
}
