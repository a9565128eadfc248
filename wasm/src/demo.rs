//! [`Demo`]: the whole system and its renderer behind one handle (SPEC §5 InventGUI).
//!
//! Every method is one request to the core: the lifecycle requests of SPEC §1 (per
//! component and for all), `SetPosition`, `Clear`, `SafeMode`, `MapUpdate`, map and scenario
//! loading, stepping, drawing. What the page reads comes back as JSON (`views`).
//!
//! The page's model of a run: after a scenario or a map is loaded, the planning components
//! (MapBuilder, MapMaintenance, GlobalPathPlanning, LocalPathPlanning) are Active and the
//! plan is drawn ([`System::preview`]); the robot's components (PhysicsSim, MotorControl,
//! Localization, DriveControl) wait, Inactive, for **Activate**. The execution context runs
//! all the time (as in OpenRTM: Inactive components simply are not executed), so a goal set
//! while standing is planned at once. A scenario's timed events count from the moment the
//! robot starts (the physics is activated), not from the page load: the obstacle of
//! `appearing_obstacle` appears while the robot drives, however long the page was open.

use rtnav::components::{DriveStatus, MapUpdate};
use rtnav::interfaces::{Direction, Pose};
use rtnav::map::GridMap;
use rtnav::motion::DrivePhase;
use rtnav::render::{Layers, Renderer};
use rtnav::rtc::{LifecycleState, Time};
use rtnav::system::{ComponentKind, MapSource, Rates, Scenario, ScenarioEvent, System};
use wasm_bindgen::prelude::*;

use crate::files::Files;
use crate::views::{
    ComponentView, EventView, MapView, PlanView, PoseView, ScenarioView, TelemetryView,
    direction_name,
};
use crate::{Msg, js, msg};

/// The most wall time one [`Demo::step`] turns into simulated time: a tab that was in the
/// background resumes where it was instead of catching up in one frame.
const MAX_STEP_MS: f64 = 100.0;
/// Speeds the page offers: 0.25× to 16× real time.
const MIN_SPEED: f64 = 0.25;
const MAX_SPEED: f64 = 16.0;
/// How much simulated time the planning preview may take at most \[s\].
const PREVIEW_SECONDS: f64 = 5.0;
/// The reason an injected fault gives.
const FAULT_REASON: &str = "requested from the page";

/// Seconds → nanoseconds as the scenario runner rounds them.
fn secs_to_ns(s: f64) -> u64 {
    libm::round(s * 1e9) as u64
}

/// The page's handle: the system, its renderer and the page's clock settings.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Demo(Box<Inner>);

/// What the handle holds.
#[derive(Debug)]
pub(crate) struct Inner {
    system: System,
    renderer: Renderer,
    layers: Layers,
    speed: f64,
    paused: bool,
    /// Simulated time received but not yet a whole tick \[ns\].
    pending_ns: u64,
    scenario: Option<ScenarioView>,
    map_name: String,
    /// The scenario's timed events, relative to the start of the drive \[ns\], until the
    /// robot starts.
    script: Vec<(u64, ScenarioEvent)>,
    /// Timed events other than map updates (those are queued on MapMaintenance), at
    /// absolute simulated times, once the robot has started.
    due: Vec<(u64, ScenarioEvent)>,
    /// Events of the page's own (a scripted goal that was refused).
    notes: Vec<EventView>,
    /// Whether something changed since the last frame.
    dirty: bool,
    /// Whether the page asked for a plan during DriveControl's current spell without a path.
    resume_asked: bool,
}

impl Inner {
    /// An empty system (no map) and a `width × height` renderer.
    pub(crate) fn new(width: u32, height: u32) -> Msg<Self> {
        let mut system = System::new(Rates::default()).map_err(msg)?;
        system.set_full_field(true);
        Ok(Self {
            system,
            renderer: Renderer::new(width, height).map_err(msg)?,
            layers: Layers::ALL,
            speed: 1.0,
            paused: false,
            pending_ns: 0,
            scenario: None,
            map_name: String::new(),
            script: Vec::new(),
            due: Vec::new(),
            notes: Vec::new(),
            dirty: true,
            resume_asked: false,
        })
    }

    // ------------------------------------------------------------------ loading

    /// Builds the system of a scenario ([`System::from_scenario`]: rates, configuration,
    /// map, start and goal; nothing activated) and previews its plan. The scenario's timed
    /// events wait for the drive to start. On an error the current system stays.
    pub(crate) fn load_scenario(&mut self, json: &str, files: &Files) -> Msg<()> {
        let scenario = Scenario::from_json(json).map_err(msg)?;
        let timeless = Scenario {
            events: Vec::new(),
            ..scenario.clone()
        };
        let mut system = System::from_scenario(&timeless, &files.resolver()).map_err(msg)?;
        system.set_full_field(true);
        system
            .preview(PREVIEW_SECONDS)
            .map_err(|e| format!("scenario `{}`: preview: {e}", scenario.name))?;
        self.map_name = match &scenario.map {
            MapSource::Json { path } | MapSource::Movingai { path, .. } => path.clone(),
            MapSource::Ros { yaml, .. } => yaml.clone(),
        };
        self.script = scenario
            .events
            .iter()
            .map(|e| (secs_to_ns(e.at()), e.clone()))
            .collect();
        self.scenario = Some(ScenarioView {
            name: scenario.name,
            description: scenario.description,
            lesson: scenario.lesson,
        });
        self.replace_system(system);
        Ok(())
    }

    /// Loads a map the user picked into a fresh system with the planning components active
    /// and no start or goal. On an error (a bad file) the current map and system stay.
    pub(crate) fn load_map_files(&mut self, files: &Files, movingai_grid_size: f64) -> Msg<()> {
        let (name, map) = files.load_map(movingai_grid_size)?;
        self.load_map(name, map)
    }

    fn load_map(&mut self, name: String, map: GridMap) -> Msg<()> {
        let mut system = System::new(Rates::default()).map_err(msg)?;
        system.set_full_field(true);
        system.load_map(map);
        for kind in ComponentKind::PLANNING {
            system.activate(kind).map_err(msg)?;
        }
        self.map_name = name;
        self.scenario = None;
        self.script.clear();
        self.replace_system(system);
        Ok(())
    }

    fn replace_system(&mut self, system: System) {
        self.system = system;
        self.due.clear();
        self.notes.clear();
        self.pending_ns = 0;
        self.renderer.invalidate();
        self.dirty = true;
    }

    // ------------------------------------------------------------------ time

    /// Advances simulated time by `elapsed_ms` of wall time × the speed, in whole ticks
    /// (the remainder is kept; nothing while paused; at most 100 ms of wall time per call;
    /// negative or non-finite counts as 0). Returns the number of ticks run.
    pub(crate) fn step(&mut self, elapsed_ms: f64) -> u32 {
        if self.paused {
            return 0;
        }
        let ms = if elapsed_ms.is_finite() {
            elapsed_ms.clamp(0.0, MAX_STEP_MS)
        } else {
            0.0
        };
        self.pending_ns += libm::round(ms * self.speed * 1e6) as u64;
        let base = self.system.execution_context().base_period_ns();
        let ticks = self.pending_ns / base;
        self.pending_ns %= base;
        self.run_ticks(ticks);
        // At most 100 ms × 16 of 1 ms ticks: fits.
        u32::try_from(ticks).unwrap_or(u32::MAX)
    }

    /// Runs `ticks` base ticks (paused or not), applying due scenario events on time.
    pub(crate) fn run_ticks(&mut self, ticks: u64) {
        if ticks == 0 {
            return;
        }
        if self.due.is_empty() {
            self.system.step(ticks);
        } else {
            for _ in 0..ticks {
                self.apply_due();
                self.system.step(1);
            }
            self.apply_due();
        }
        self.resume_if_idle();
        self.dirty = true;
    }

    /// DriveControl starts without a path when it is activated (after a Reset, or a
    /// Deactivate), and LocalPathPlanning sends a path only when it changes: the robot would
    /// stand still before a goal it still holds. As InventGUI's operator would, the page
    /// then sends the held goal again (`SetPosition` from where the robot is) — once per
    /// such spell, only while the robot drives, with a goal held, not reached, not halted.
    fn resume_if_idle(&mut self) {
        let idle = matches!(
            self.system.drive_control().status(),
            DriveStatus::Driving(DrivePhase::Idle)
        );
        if !idle {
            self.resume_asked = false;
            return;
        }
        let s = &self.system;
        let Some(goal) = s.goal() else {
            return;
        };
        if self.resume_asked
            || !s.is_driving()
            || s.is_arrived()
            || s.is_halted()
            || s.component_state(ComponentKind::LocalPathPlanning) != LifecycleState::Active
        {
            return;
        }
        self.resume_asked = true;
        let direction = s.direction();
        let text = match self.system.set_goal(goal, direction) {
            Ok(()) => {
                "DriveControl had no path after its activation: the goal was sent again".to_owned()
            }
            Err(e) => format!("DriveControl has no path; sending the goal again was refused: {e}"),
        };
        self.notes.push(EventView {
            time_s: self.system.time(),
            kind: "GoalResent".to_owned(),
            level: "info",
            text,
            data: serde_json::Value::Null,
        });
    }

    fn apply_due(&mut self) {
        let now = self.system.time_ns();
        while let Some((at, _)) = self.due.first()
            && *at <= now
        {
            let (_, event) = self.due.remove(0);
            match event {
                ScenarioEvent::Goal {
                    goal, direction, ..
                } => {
                    if let Err(e) = self.system.set_goal(goal.pose(), direction.direction()) {
                        self.notes.push(EventView {
                            time_s: now as f64 * 1e-9,
                            kind: "ScenarioGoalRefused".to_owned(),
                            level: "warn",
                            text: format!("the scenario's next goal was refused: {e}"),
                            data: serde_json::Value::Null,
                        });
                    }
                }
                ScenarioEvent::SafeMode { .. } => self.system.safe_mode(),
                ScenarioEvent::Clear { .. } => self.system.clear(),
                _ => {}
            }
        }
    }

    /// Once the robot drives, the scenario's timed events are queued from now: map updates
    /// on MapMaintenance (which sends them on time), the rest for [`Inner::run_ticks`].
    fn start_script(&mut self) {
        if self.script.is_empty() || !self.system.is_driving() {
            return;
        }
        let now = self.system.time_ns();
        for (at, event) in std::mem::take(&mut self.script) {
            match &event {
                ScenarioEvent::MapUpdate {
                    boxes,
                    cells,
                    value,
                    ..
                } => {
                    let Some(map) = self.system.map() else {
                        continue;
                    };
                    let update = Scenario::map_update(map, boxes, cells, *value);
                    // Checked when the scenario was written for this map; a refusal is
                    // the core's event.
                    let _ = self.system.schedule_map_update(now + at, update);
                }
                _ => self.due.push((now + at, event)),
            }
        }
    }

    pub(crate) fn set_speed(&mut self, speed: f64) -> Msg<()> {
        if !(MIN_SPEED..=MAX_SPEED).contains(&speed) {
            return Err(format!(
                "speed {speed}× is outside {MIN_SPEED}× to {MAX_SPEED}×"
            ));
        }
        self.speed = speed;
        Ok(())
    }

    // ------------------------------------------------------------------ lifecycle

    fn kind(name: &str) -> Msg<ComponentKind> {
        ComponentKind::from_name(name).map_err(msg)
    }

    fn changed<T>(&mut self, r: rtnav::Result<T>) -> Msg<T> {
        self.dirty = true;
        self.start_script();
        r.map_err(msg)
    }

    pub(crate) fn activate(&mut self, name: &str) -> Msg<LifecycleState> {
        let r = self.system.activate(Self::kind(name)?);
        self.changed(r)
    }

    pub(crate) fn deactivate(&mut self, name: &str) -> Msg<LifecycleState> {
        let r = self.system.deactivate(Self::kind(name)?);
        self.changed(r)
    }

    pub(crate) fn reset(&mut self, name: &str) -> Msg<LifecycleState> {
        let r = self.system.reset(Self::kind(name)?);
        self.changed(r)
    }

    pub(crate) fn inject_fault(&mut self, name: &str) -> Msg<()> {
        let r = self.system.inject_fault(Self::kind(name)?, FAULT_REASON);
        self.changed(r)
    }

    pub(crate) fn activate_all(&mut self) -> String {
        let s = self.system.activate_all();
        self.dirty = true;
        self.start_script();
        s.to_string()
    }

    pub(crate) fn deactivate_all(&mut self) -> String {
        self.dirty = true;
        self.system.deactivate_all().to_string()
    }

    pub(crate) fn reset_all(&mut self) -> String {
        self.dirty = true;
        self.system.reset_all().to_string()
    }

    // ------------------------------------------------------------------ inputs

    /// After a new start or goal while the robot stands, with the planners running: plan
    /// now, so the new path and its potential field are drawn at once.
    fn after_goal(&mut self) -> Msg<()> {
        self.dirty = true;
        let planners_active = ComponentKind::PLANNING
            .iter()
            .all(|&k| self.system.component_state(k) == LifecycleState::Active);
        if !self.system.is_driving() && planners_active {
            self.system.preview(PREVIEW_SECONDS).map_err(msg)?;
        }
        Ok(())
    }

    pub(crate) fn set_position(&mut self, start: Pose, goal: Pose, backward: bool) -> Msg<()> {
        self.system
            .set_position(start, goal, direction(backward))
            .map_err(msg)?;
        self.after_goal()
    }

    pub(crate) fn set_goal(&mut self, goal: Pose, backward: bool) -> Msg<()> {
        self.system
            .set_goal(goal, direction(backward))
            .map_err(msg)?;
        self.after_goal()
    }

    pub(crate) fn set_cells(&mut self, xs: &[i32], ys: &[i32], value: i16) -> Msg<usize> {
        if xs.len() != ys.len() {
            return Err(format!(
                "MapUpdate: {} x indices but {} y indices",
                xs.len(),
                ys.len()
            ));
        }
        let cells: Vec<(i64, i64, i16)> = xs
            .iter()
            .zip(ys)
            .map(|(&x, &y)| (i64::from(x), i64::from(y), value))
            .collect();
        let update = MapUpdate::from_cells(&cells, Time::default());
        let r = self.system.map_update(update);
        self.changed(r)
    }

    pub(crate) fn clear(&mut self) {
        self.system.clear();
        self.dirty = true;
    }

    pub(crate) fn safe_mode(&mut self) {
        self.system.safe_mode();
        self.dirty = true;
    }

    // ------------------------------------------------------------------ drawing

    /// Draws the current state if anything changed since the last frame. Returns whether
    /// it drew (false: the frame is the same, or no map yet).
    pub(crate) fn render(&mut self) -> Msg<bool> {
        if !self.dirty {
            return Ok(false);
        }
        let Inner {
            system,
            renderer,
            layers,
            ..
        } = self;
        let Some(mut scene) = system.scene() else {
            return Ok(false);
        };
        scene.layers = *layers;
        renderer.render(&scene).map_err(msg)?;
        self.dirty = false;
        Ok(true)
    }

    pub(crate) fn resize(&mut self, width: u32, height: u32) -> Msg<()> {
        self.renderer.resize(width, height).map_err(msg)?;
        self.dirty = true;
        Ok(())
    }

    pub(crate) fn set_layer(&mut self, name: &str, on: bool) -> Msg<()> {
        let mut value = serde_json::to_value(self.layers).map_err(msg)?;
        if let Some(map) = value.as_object_mut() {
            if !map.contains_key(name) {
                let known: Vec<&str> = map.keys().map(String::as_str).collect();
                return Err(format!(
                    "no layer named `{name}` (layers: {})",
                    known.join(", ")
                ));
            }
            map.insert(name.to_owned(), serde_json::Value::Bool(on));
        }
        self.layers = serde_json::from_value(value).map_err(msg)?;
        self.dirty = true;
        Ok(())
    }

    fn view(&self) -> Option<rtnav::render::ViewTransform> {
        self.system.map().map(|m| self.renderer.view(m))
    }

    // ------------------------------------------------------------------ reading

    pub(crate) fn components(&self) -> Vec<ComponentView> {
        let ec = self.system.execution_context();
        ComponentKind::ALL
            .into_iter()
            .map(|kind| {
                let info = self.system.component_info(kind);
                ComponentView {
                    name: kind.name(),
                    colour: info.state.editor_colour(),
                    fault_pending: ec.fault_pending(kind.index()).unwrap_or(false),
                    info,
                }
            })
            .collect()
    }

    pub(crate) fn take_events(&mut self) -> Vec<EventView> {
        let mut out: Vec<EventView> = self
            .system
            .drain_events()
            .iter()
            .map(EventView::of)
            .collect();
        if !self.notes.is_empty() {
            out.append(&mut self.notes);
            out.sort_by(|a, b| a.time_s.total_cmp(&b.time_s));
        }
        out
    }

    pub(crate) fn telemetry(&self) -> TelemetryView {
        let s = &self.system;
        let pose = s.robot_pose();
        let stats = s.stats();
        let last = s.telemetry().last();
        let pick = |f: fn(&rtnav::system::TelemetrySample) -> f64| last.map_or(0.0, f);
        TelemetryView {
            time_s: s.time(),
            state: s.state(),
            driving: s.is_driving(),
            arrived: s.is_arrived(),
            halted: s.is_halted(),
            paused: self.paused,
            speed: self.speed,
            pose: pose.into(),
            start: s.start().map(PoseView::from),
            goal: s.goal().map(PoseView::from),
            direction: direction_name(s.direction()),
            distance_to_goal: s.goal().map(|g| libm::hypot(g.x - pose.x, g.y - pose.y)),
            v: pick(|t| t.v),
            w: pick(|t| t.w),
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

    pub(crate) fn plan(&self) -> PlanView {
        let s = &self.system;
        let lpp = s.local_path_planning();
        PlanView {
            start: s.start().map(PoseView::from),
            goal: s.goal().map(PoseView::from),
            direction: direction_name(s.direction()),
            global_path: s.global_path().to_vec(),
            local_path: lpp.merged_path().to_vec(),
            control_points: lpp
                .control_points()
                .map_or_else(Vec::new, |c| c.points.clone()),
        }
    }

    pub(crate) fn cell(&self, x: i32, y: i32) -> i32 {
        match self.system.map() {
            Some(m)
                if x >= 0 && y >= 0 && (x as usize) < m.width() && (y as usize) < m.height() =>
            {
                i32::from(m.is_obstacle(i64::from(x), i64::from(y)))
            }
            _ => -1,
        }
    }

    pub(crate) fn map_view(&self) -> Option<MapView> {
        let m = self.system.map()?;
        Some(MapView {
            name: self.map_name.clone(),
            width: m.width(),
            height: m.height(),
            grid_size: m.grid_size(),
            origin: m.origin(),
            obstacles: m.cells().iter().filter(|&&c| c != 0).count(),
            key: self.system.map_key(),
        })
    }
}

fn direction(backward: bool) -> Direction {
    if backward {
        Direction::Backward
    } else {
        Direction::Forward
    }
}

fn json<T: serde::Serialize>(value: &T) -> Result<String, JsError> {
    serde_json::to_string(value).map_err(|e| js(msg(e)))
}

/// A pose from metres and degrees (what the page's drag gives).
fn pose(x: f64, y: f64, theta_deg: f64) -> Pose {
    Pose::new(x, y, theta_deg.to_radians())
}

#[wasm_bindgen]
impl Demo {
    /// A handle with an empty system (no map yet) drawing `width × height` frames.
    #[wasm_bindgen(constructor)]
    pub fn new(width: u32, height: u32) -> Result<Demo, JsError> {
        Ok(Demo(Box::new(Inner::new(width, height).map_err(js)?)))
    }

    // ------------------------------------------------------------------ loading

    /// Loads a scenario (its JSON text; `files` holds the map files it names, by the paths
    /// it gives them) and previews its plan. On an error the current scenario stays.
    pub fn load_scenario(&mut self, json: &str, files: &Files) -> Result<(), JsError> {
        self.0.load_scenario(json, files).map_err(js)
    }

    /// Loads the map file(s) the user picked — one rtnav JSON, one MovingAI `.map` (scaled
    /// to `movingai_grid_size` metres per cell) or a ROS YAML with its image — into a fresh
    /// system with no start or goal. On an error (a bad file, named in the message) the
    /// current map stays.
    pub fn load_map_files(
        &mut self,
        files: &Files,
        movingai_grid_size: f64,
    ) -> Result<(), JsError> {
        self.0.load_map_files(files, movingai_grid_size).map_err(js)
    }

    /// The scenario loaded, as JSON `{name, description, lesson}`, or `null` (a map file).
    pub fn scenario_json(&self) -> Result<String, JsError> {
        json(&self.0.scenario)
    }

    /// The map as JSON `{name, width, height, grid_size, origin, obstacles, key}`, or `null`.
    pub fn map_json(&self) -> Result<String, JsError> {
        json(&self.0.map_view())
    }

    /// The map cell `(x, y)`: 1 obstacle, 0 free, −1 outside the map (or no map).
    pub fn cell(&self, x: i32, y: i32) -> i32 {
        self.0.cell(x, y)
    }

    // ------------------------------------------------------------------ time

    /// Advances simulated time by `elapsed_ms` of wall time × the speed, in whole ticks;
    /// nothing while paused. Returns the number of ticks run.
    pub fn step(&mut self, elapsed_ms: f64) -> u32 {
        self.0.step(elapsed_ms)
    }

    /// Runs `ticks` base ticks now, paused or not (the page's single step: one tick).
    pub fn step_ticks(&mut self, ticks: u32) {
        self.0.run_ticks(u64::from(ticks));
    }

    /// Simulated time \[s\].
    pub fn time_s(&self) -> f64 {
        self.0.system.time()
    }

    /// Pauses or resumes the clock.
    pub fn set_paused(&mut self, paused: bool) {
        self.0.paused = paused;
    }

    /// Whether the clock is paused.
    pub fn paused(&self) -> bool {
        self.0.paused
    }

    /// Sets the speed (simulated seconds per wall second), 0.25 to 16.
    pub fn set_speed(&mut self, speed: f64) -> Result<(), JsError> {
        self.0.set_speed(speed).map_err(js)
    }

    /// The speed.
    pub fn speed(&self) -> f64 {
        self.0.speed
    }

    // ------------------------------------------------------------------ lifecycle

    /// Activates one component (`LocalPathPlanning` or `LocalPathPlanning0`). Returns the
    /// state reached; an illegal request is an error and changes nothing.
    pub fn activate(&mut self, name: &str) -> Result<String, JsError> {
        self.0.activate(name).map(|s| s.to_string()).map_err(js)
    }

    /// Deactivates one component. Returns the state reached.
    pub fn deactivate(&mut self, name: &str) -> Result<String, JsError> {
        self.0.deactivate(name).map(|s| s.to_string()).map_err(js)
    }

    /// Resets one component in Error. Returns the state reached.
    pub fn reset(&mut self, name: &str) -> Result<String, JsError> {
        self.0.reset(name).map(|s| s.to_string()).map_err(js)
    }

    /// Makes the component's next execution fail (→ Error with the reason
    /// `injected fault: requested from the page`).
    pub fn inject_fault(&mut self, name: &str) -> Result<(), JsError> {
        self.0.inject_fault(name).map_err(js)
    }

    /// Activates every Inactive component. Returns the system's state.
    pub fn activate_all(&mut self) -> String {
        self.0.activate_all()
    }

    /// Deactivates every Active component. Returns the system's state.
    pub fn deactivate_all(&mut self) -> String {
        self.0.deactivate_all()
    }

    /// Resets every component in Error and deactivates the Active ones. Returns the
    /// system's state.
    pub fn reset_all(&mut self) -> String {
        self.0.reset_all()
    }

    /// The system's state: `Inactive`, `Active`, `Partial` or `Error`.
    pub fn system_state(&self) -> String {
        self.0.system.state().to_string()
    }

    /// Every component as JSON: `[{name, kind, instance_name, state, colour, rate,
    /// last_error, status, fault_pending}]`, in data-flow order.
    pub fn components_json(&self) -> Result<String, JsError> {
        json(&self.0.components())
    }

    // ------------------------------------------------------------------ inputs

    /// `SetPosition`: places the robot at the start and sets the goal (metres, degrees
    /// counter-clockwise from +x). Only while the robot is not driving. A refused request
    /// (e.g. a goal inside an obstacle) is an error and changes nothing.
    #[allow(clippy::too_many_arguments)]
    pub fn set_position(
        &mut self,
        start_x: f64,
        start_y: f64,
        start_deg: f64,
        goal_x: f64,
        goal_y: f64,
        goal_deg: f64,
        backward: bool,
    ) -> Result<(), JsError> {
        self.0
            .set_position(
                pose(start_x, start_y, start_deg),
                pose(goal_x, goal_y, goal_deg),
                backward,
            )
            .map_err(js)
    }

    /// A new goal from where the robot is. A refused goal is an error; the previous goal
    /// and its path stay.
    pub fn set_goal(
        &mut self,
        x: f64,
        y: f64,
        theta_deg: f64,
        backward: bool,
    ) -> Result<(), JsError> {
        self.0.set_goal(pose(x, y, theta_deg), backward).map_err(js)
    }

    /// `MapUpdate` of the cells `(xs[i], ys[i])` to `value` (1 obstacle, 0 free). Returns
    /// how many changed; cells outside the map are an error and nothing changes.
    pub fn set_cells(&mut self, xs: Vec<i32>, ys: Vec<i32>, value: i16) -> Result<usize, JsError> {
        self.0.set_cells(&xs, &ys, value).map_err(js)
    }

    /// `Clear`: the paths and the goal are dropped; the robot stops.
    pub fn clear(&mut self) {
        self.0.clear();
    }

    /// `SafeMode`: the robot halts until the next goal.
    pub fn safe_mode(&mut self) {
        self.0.safe_mode();
    }

    // ------------------------------------------------------------------ drawing

    /// Draws the current state into the frame if anything changed. Returns whether it drew.
    pub fn render(&mut self) -> Result<bool, JsError> {
        self.0.render().map_err(js)
    }

    /// Changes the frame size (pixels).
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), JsError> {
        self.0.resize(width, height).map_err(js)
    }

    /// Where the frame's pixels start in wasm memory (RGBA, opaque, rows top to bottom).
    pub fn frame_ptr(&self) -> usize {
        self.0.renderer.frame().data().as_ptr() as usize
    }

    /// The frame's length in bytes (`4 · width · height`).
    pub fn frame_len(&self) -> usize {
        self.0.renderer.frame().data().len()
    }

    /// The frame's width in pixels.
    pub fn frame_width(&self) -> u32 {
        self.0.renderer.width()
    }

    /// The frame's height in pixels.
    pub fn frame_height(&self) -> u32 {
        self.0.renderer.height()
    }

    /// The layers as JSON `{occupancy: true, …}`.
    pub fn layers_json(&self) -> Result<String, JsError> {
        json(&self.0.layers)
    }

    /// Shows or hides a layer (`heat_map`, `trail`, …).
    pub fn set_layer(&mut self, name: &str, on: bool) -> Result<(), JsError> {
        self.0.set_layer(name, on).map_err(js)
    }

    /// Frame pixel → world point `[x, y]` in metres (`undefined` without a map).
    pub fn pixel_to_world(&self, px: f64, py: f64) -> Option<Vec<f64>> {
        let (x, y) = self.0.view()?.pixel_to_world(px, py);
        Some(vec![x, y])
    }

    /// Frame pixel → map cell `[x, y]` (`undefined` outside the map).
    pub fn pixel_to_cell(&self, px: f64, py: f64) -> Option<Vec<u32>> {
        let map = self.0.system.map()?;
        let (x, y) = self.0.renderer.view(map).pixel_to_cell(map, px, py)?;
        Some(vec![u32::try_from(x).ok()?, u32::try_from(y).ok()?])
    }

    /// World point → frame pixel `[px, py]` (`undefined` without a map).
    pub fn world_to_pixel(&self, x: f64, y: f64) -> Option<Vec<f64>> {
        let (px, py) = self.0.view()?.world_to_pixel(x, y);
        Some(vec![px, py])
    }

    /// Frame pixels per metre (`0` without a map).
    pub fn pixels_per_metre(&self) -> f64 {
        self.0.view().map_or(0.0, |v| v.pixels_per_metre())
    }

    // ------------------------------------------------------------------ reading

    /// The events since the last call, oldest first, as JSON `[{time_s, kind, level, text,
    /// data}]`.
    pub fn take_events(&mut self) -> Result<String, JsError> {
        json(&self.0.take_events())
    }

    /// The telemetry readout as JSON.
    pub fn telemetry_json(&self) -> Result<String, JsError> {
        json(&self.0.telemetry())
    }

    /// Start, goal, paths and control points as JSON.
    pub fn plan_json(&self) -> Result<String, JsError> {
        json(&self.0.plan())
    }

    /// Panics on purpose, so the end-to-end test can prove the page shows a crash.
    pub fn debug_panic(&mut self) {
        panic!("debug_panic: deliberate panic requested by the page");
    }
}

#[cfg(test)]
mod tests;
