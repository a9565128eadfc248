//! The session's read-outs for a user interface (a child of `session.rs`): every view the
//! page and the runner show, built here from the system's parts, so a user interface never
//! reaches past the [`Session`].

use super::Session;
use crate::errors::SessionError;
use crate::map::GridMap;
use crate::rtc::LifecycleState;
use crate::system::runs::scenario::Scenario;
use crate::system::sessions::picked_files::{PickError, PickedFiles};
use crate::system::sessions::refusal::Refusal;
use crate::system::sessions::views::{
    ClockView, ComponentView, DirectionView, EventView, FrameView, MapView, PlanView, PoseView,
    ScenarioView, TelemetryView,
};
use crate::system::simulation::graph::SystemGraph;
use crate::system::simulation::inspect::CellInspection;
use crate::system::simulation::rest::Measured;
use crate::system::simulation::status::SystemState;
use crate::system::vocabulary::input::Input;
use crate::system::vocabulary::kind::ComponentKind;

impl Session {
    /// The map, if one is loaded (what a renderer draws over).
    pub fn map(&self) -> Option<&GridMap> {
        self.state.system.map()
    }

    /// The system's state: `Inactive`, `Active`, `Partial` or `Error`.
    pub fn state(&self) -> SystemState {
        self.state.system.state()
    }

    /// The lifecycle state of `component`.
    pub fn component_state(&self, component: ComponentKind) -> LifecycleState {
        self.state.system.component_state(component)
    }

    /// Whether the robot drives.
    pub fn is_driving(&self) -> bool {
        self.state.system.is_driving()
    }

    /// Simulated time \[s\].
    pub fn time_s(&self) -> f64 {
        self.state.system.time()
    }

    /// One base tick \[s\].
    pub fn tick_s(&self) -> f64 {
        self.state
            .system
            .wiring()
            .execution_context()
            .base_period_ns() as f64
            * 1e-9
    }

    /// The clock.
    pub fn clock(&self) -> ClockView {
        ClockView {
            time_s: self.time_s(),
            behind_s: self.behind_s(),
            paused: self.paused(),
            speed: self.speed(),
            tick_s: self.tick_s(),
        }
    }

    /// One frame's read (see [`FrameView`]): the events in it are those since the last
    /// frame or [`Session::new_events`].
    pub fn frame(&mut self) -> FrameView {
        let events = self.new_events().iter().map(EventView::of).collect();
        FrameView {
            clock: self.clock(),
            telemetry: self.telemetry(),
            components: self.components(),
            events,
            exercise: self.exercise_view(),
        }
    }

    /// The events since the last look, as the log shows them.
    pub fn event_views(&mut self) -> Vec<EventView> {
        self.new_events().iter().map(EventView::of).collect()
    }

    /// Every component, in data-flow order.
    pub fn components(&self) -> Vec<ComponentView> {
        let wiring = self.state.system.wiring();
        let ec = wiring.execution_context();
        ComponentKind::ALL
            .into_iter()
            .map(|kind| {
                let info = self.state.system.component(kind);
                ComponentView {
                    name: kind.name(),
                    colour: info.state.editor_colour(),
                    fault_pending: ec.fault_pending(kind.index()).unwrap_or(false),
                    info,
                }
            })
            .collect()
    }

    /// The telemetry readout and the status.
    pub fn telemetry(&self) -> TelemetryView {
        let s = &self.state.system;
        let pose = s.robot_pose();
        let stats = s.stats();
        let m = s.mission();
        let last = s.record().telemetry().last();
        let pick = |f: fn(&crate::system::simulation::telemetry::TelemetrySample) -> f64| {
            last.map_or(0.0, f)
        };
        // What the robot does now: the physics' measured motion, zero while it does not
        // execute (a frozen robot shows 0 whatever the last sample held).
        let moving = Measured::of(s.wiring());
        let status = self.status();
        // The status as data: `{kind, …fields}` (`Status` is `serde(tag = "kind")`).
        let mut status_fields = match serde_json::to_value(&status) {
            Ok(serde_json::Value::Object(m)) => m,
            _ => serde_json::Map::new(),
        };
        let status_kind = match status_fields.remove("kind") {
            Some(serde_json::Value::String(k)) => k,
            _ => String::new(),
        };
        // The session's clock stands still: a cause of what the robot does (spec §7
        // Decisions 0.3, "motion words"), said with the status (`status.paused`).
        if self.paused() {
            status_fields.insert("paused".to_owned(), serde_json::Value::Bool(true));
        }
        TelemetryView {
            time_s: s.time(),
            state: s.state(),
            driving: s.is_driving(),
            status_kind,
            status_fields,
            arrived: m.is_arrived(),
            halted: m.is_halted(),
            paused: self.paused(),
            speed: self.speed(),
            pose: pose.into(),
            body_radius: s.wiring().motor_geometry().radius_of_body_area,
            start: m.start().map(PoseView::from),
            goal: m.goal().map(PoseView::from),
            direction: m.direction().into(),
            distance_to_goal: m.goal().map(|g| libm::hypot(g.x - pose.x, g.y - pose.y)),
            v: moving.v,
            w: moving.w,
            v_cmd: pick(|t| t.v_cmd),
            w_cmd: pick(|t| t.w_cmd),
            deviation: last.map_or(f64::NAN, |t| t.deviation),
            path_length: stats.path_length,
            global_plans: stats.global_plans,
            local_plans: stats.local_plans,
            planning_failures: stats.planning_failures,
            bumps: stats.bumps,
            min_clearance: stats
                .min_clearance
                .is_finite()
                .then_some(stats.min_clearance),
        }
    }

    /// Start, goal, paths and control points.
    pub fn plan(&self) -> PlanView {
        let lpp = self.state.system.wiring().local_path_planning();
        let m = self.state.system.mission();
        PlanView {
            start: m.start().map(PoseView::from),
            goal: m.goal().map(PoseView::from),
            direction: m.direction().into(),
            global_path: m.route().to_vec(),
            local_path: lpp.merged_path().to_vec(),
            control_points: lpp
                .control_points()
                .map_or_else(Vec::new, |c| c.points.clone()),
        }
    }

    /// The map's geometry, or `None` without a map.
    pub fn map_view(&self) -> Option<MapView> {
        let m = self.state.system.map()?;
        Some(MapView {
            name: self.map_name.clone(),
            width: m.width(),
            height: m.height(),
            grid_size: m.grid_size(),
            origin: m.origin(),
            obstacles: m.cells().iter().filter(|&&c| c != 0).count(),
            key: self.state.system.wiring().map_key(),
        })
    }

    /// The map cell `(x, y)`: `Some(true)` an obstacle, `Some(false)` free, `None` outside
    /// the map (or no map).
    pub fn cell(&self, x: i64, y: i64) -> Option<bool> {
        let m = self.state.system.map()?;
        let inside = x >= 0 && y >= 0 && (x as u64) < m.width() as u64;
        (inside && (y as u64) < m.height() as u64).then(|| m.is_obstacle(x, y))
    }

    /// The scenario shown, or `None` for a map file.
    pub fn scenario_view(&self) -> Option<ScenarioView> {
        self.scenario().map(|s| ScenarioView {
            name: s.name.clone(),
            description: s.description.clone(),
            lesson: s.lesson.clone(),
        })
    }

    /// The system's description (the System tab, `rtnav system`).
    pub fn graph(&self) -> SystemGraph {
        self.state.system.wiring().graph()
    }

    /// The cell `(x, y)` explained (the inspector). A cell outside the map is an error.
    pub fn inspect_cell(&self, x: i64, y: i64) -> crate::Result<CellInspection> {
        self.state.system.wiring().inspect_cell(x, y)
    }

    /// The whole configuration as one OpenRTM `.conf` text.
    pub fn conf_text(&self) -> String {
        self.state.system.wiring().to_conf()
    }

    /// The telemetry history as CSV (header first).
    pub fn telemetry_csv(&self) -> String {
        self.state.system.record().telemetry().to_csv()
    }

    /// Where the robot has been `[x, y]` \[m\], oldest first.
    pub fn trail(&self) -> &[(f64, f64)] {
        self.state.system.record().trail()
    }

    /// `MapUpdate` of the cells `(xs[i], ys[i])` to `value` (1 obstacle, 0 free): one
    /// request; lists of different lengths are refused.
    pub fn set_cells(&mut self, xs: &[i32], ys: &[i32], value: i16) -> crate::Result<()> {
        if xs.len() != ys.len() {
            return Err(SessionError::CellLists {
                xs: xs.len(),
                ys: ys.len(),
            }
            .into());
        }
        let cells = xs
            .iter()
            .zip(ys)
            .map(|(&x, &y)| (i64::from(x), i64::from(y), value))
            .collect();
        self.apply(&Input::MapUpdate { cells })
    }

    /// The map cell under the world point `(x, y)` \[m\] (`None` outside the map or
    /// without one): the map's own world → cell.
    pub fn world_to_cell(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        self.state.system.map()?.world_to_cell(x, y)
    }

    /// The cells a square brush covers with its centre at the world point `(x, y)` \[m\]:
    /// `size` cells across, the `size × size` cells around the cell under it; `size` metres
    /// across (`in_metres`), the cells whose centre lies inside the square (at least the
    /// cell under it). Only cells of the map; none without a map.
    pub fn brush_cells(&self, x: f64, y: f64, size: f64, in_metres: bool) -> Vec<(usize, usize)> {
        let Some(map) = self.state.system.map() else {
            return Vec::new();
        };
        let Some((cx, cy)) = map.world_to_cell_signed(x, y) else {
            return Vec::new();
        };
        let cell = |x: i64, y: i64| map.contains(x, y).then_some((x as usize, y as usize));
        let g = map.grid_size();
        let (ox, oy) = map.origin();
        let mut out = Vec::new();
        if in_metres && size.is_finite() && size > 0.0 {
            let half = size / 2.0;
            // Cell i's centre is at origin + (i + ½) g.
            let first = |w: f64, o: f64| ((w - half - o) / g - 0.5).ceil() as i64;
            let last = |w: f64, o: f64| ((w + half - o) / g - 0.5).floor() as i64;
            let (x0, x1, y0, y1) = (first(x, ox), last(x, ox), first(y, oy), last(y, oy));
            let many = (x1 - x0 + 1).saturating_mul(y1 - y0 + 1);
            if x1 >= x0 && y1 >= y0 && many <= crate::map::MAX_CELLS as i64 {
                out.extend((y0..=y1).flat_map(|y| (x0..=x1).filter_map(move |x| cell(x, y))));
            }
            if out.is_empty() {
                out.extend(cell(cx, cy));
            }
            return out;
        }
        let n = if size.is_finite() {
            size.max(1.0) as i64
        } else {
            1
        };
        let n = n.min(1024);
        let r = (n - 1) / 2;
        out.extend(
            (-r..=n - 1 - r)
                .flat_map(|dy| (-r..=n - 1 - r).filter_map(move |dx| cell(cx + dx, cy + dy))),
        );
        out
    }

    /// A lifecycle request (`Activate`, `Deactivate`, `Reset`) on the component named
    /// `name` (`LocalPathPlanning` or `LocalPathPlanning0`); returns the state it reached.
    /// An unknown name or an illegal request is refused and changes nothing.
    pub fn lifecycle(
        &mut self,
        name: &str,
        request: fn(ComponentKind) -> Input,
    ) -> crate::Result<LifecycleState> {
        let component = ComponentKind::from_name(name)?;
        self.apply(&request(component))?;
        Ok(self.state.system.component_state(component))
    }

    /// A request on every component (`ActivateAll`, `DeactivateAll`, `ResetAll`); returns
    /// the system's state. `ActivateAll` before the robot is placed is refused and changes
    /// nothing (spec §5 "Physics", Decision 0.4: [`SystemError::NotPlaced`]).
    ///
    /// [`SystemError::NotPlaced`]: crate::errors::SystemError::NotPlaced
    pub fn all(&mut self, input: &Input) -> crate::Result<SystemState> {
        self.apply(input)?;
        Ok(self.state.system.state())
    }

    /// Makes the next execution of the component named `name` fail, for `reason`.
    pub fn inject_fault(&mut self, name: &str, reason: &str) -> crate::Result<()> {
        let component = ComponentKind::from_name(name)?;
        self.apply(&Input::InjectFault {
            component,
            reason: reason.to_owned(),
        })
    }

    /// Writes `data` into the input port `port` of the component named `name`.
    pub fn inject_input(&mut self, name: &str, port: &str, data: Vec<f64>) -> crate::Result<()> {
        let component = ComponentKind::from_name(name)?;
        self.apply(&Input::InjectInput {
            component,
            port: port.to_owned(),
            data,
        })
    }

    /// Sets the parameter `name` of the component named `component` from text.
    pub fn set_param_named(
        &mut self,
        component: &str,
        name: &str,
        text: &str,
    ) -> crate::Result<()> {
        let kind = ComponentKind::from_name(component)?;
        self.set_param_text(kind, name, text)
    }

    /// `SetPosition` from metres and degrees: the robot at `start`, the goal at `goal`.
    pub fn set_position_at(
        &mut self,
        start: PoseView,
        goal: PoseView,
        direction: DirectionView,
    ) -> crate::Result<()> {
        self.apply(&Input::SetPosition {
            start: start.into(),
            goal: goal.into(),
            direction: direction.into(),
        })
    }

    /// A new goal from where the robot is, in metres and degrees.
    pub fn set_goal_at(&mut self, goal: PoseView, direction: DirectionView) -> crate::Result<()> {
        self.apply(&Input::SetGoal {
            goal: goal.into(),
            direction: direction.into(),
        })
    }

    /// Loads the scenario `json` (its map files among `files`). On an error the current
    /// scenario stays; the error names the scenario when it was read.
    pub fn load_scenario_text(
        &mut self,
        json: &str,
        files: &PickedFiles,
    ) -> Result<(), Box<Refusal>> {
        let scenario = Scenario::from_json(json)
            .map_err(|e| Box::new(Refusal::from(crate::Error::from(e))))?;
        let name = scenario.name.clone();
        self.load_scenario(scenario, &files.resolver())
            .map_err(|e| Box::new(Refusal::from(e).about_scenario(&name)))
    }

    /// Loads the map picked among `files` ([`PickedFiles::load_map`]) into a fresh system.
    /// On an error the current map stays.
    pub fn load_map_files(
        &mut self,
        files: &PickedFiles,
        movingai_grid_size: f64,
    ) -> Result<(), PickError> {
        let (name, map) = files.load_map(movingai_grid_size)?;
        self.load_map(&name, map).map_err(|error| PickError {
            file: None,
            error: Box::new(error),
        })
    }
}
