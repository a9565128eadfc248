//! [`Demo`]: a [`Session`] (the system as a person drives it) and the renderer behind one
//! handle (spec §5 InventGUI).
//!
//! Every method is one request to the core: the lifecycle requests of spec §1 (per
//! component and for all), `SetPosition`, `Clear`, `SafeMode`, `MapUpdate`, parameters,
//! map and scenario loading, stepping, drawing. What the page reads comes back as JSON
//! (`views`). The page's model of a run — the planning preview, the robot waiting for
//! **Activate**, timed events counted from the start of the drive, share links — is the
//! core's [`Session`]; this layer only converts.

use rtnav::interfaces::{Direction, Pose};
use rtnav::map::GridMap;
use rtnav::render::{Layers, Renderer, caption};
use rtnav::rtc::LifecycleState;
use rtnav::system::{ComponentKind, Input, Scenario, Session, System};
use wasm_bindgen::prelude::*;

use crate::files::Files;
use crate::views::{
    ComponentView, EventView, MapView, PlanView, PoseView, ScenarioView, TelemetryView,
    direction_name,
};
use crate::{Msg, PageError, js, msg, refused};

#[wasm_bindgen]
extern "C" {
    /// The page's wall clock \[ms\]: for the frame budget only (simulated time never reads it).
    #[wasm_bindgen(js_namespace = performance, js_name = now)]
    fn performance_now() -> f64;
}

/// The reason an injected fault gives.
const FAULT_REASON: &str = "requested from the page";

/// The layers the page starts with: everything the renderer draws on the map; the legend,
/// scale bar and caption are the page's own (the renderer has no side panel here).
const PAGE_LAYERS: Layers = Layers {
    scale_bar: false,
    legend: false,
    caption: false,
    ..Layers::ALL
};

/// The page's handle: the session, its renderer and the layers shown.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Demo(pub(crate) Box<Inner>);

/// What the handle holds.
#[derive(Debug)]
pub(crate) struct Inner {
    pub(crate) session: Session,
    pub(crate) renderer: Renderer,
    layers: Layers,
    /// Whether something may have changed since the last frame.
    dirty: bool,
}

impl Inner {
    /// An empty session (no map) and a `width × height` renderer.
    pub(crate) fn new(width: u32, height: u32) -> Msg<Self> {
        let mut renderer = Renderer::new(width, height).map_err(refused)?;
        // The page shows the legend, colour bar, scale and status itself, beside the map.
        renderer.set_side_panel(false);
        Ok(Self {
            session: Session::new().map_err(refused)?,
            renderer,
            layers: PAGE_LAYERS,
            dirty: true,
        })
    }

    pub(crate) fn system(&self) -> &System {
        self.session.system()
    }

    /// A request that may change what is drawn.
    pub(crate) fn changed<T>(&mut self, r: rtnav::Result<T>) -> Msg<T> {
        self.dirty = true;
        r.map_err(refused)
    }

    // ------------------------------------------------------------------ loading

    /// Loads a scenario ([`Session::load_scenario`]). On an error the current one stays.
    pub(crate) fn load_scenario(&mut self, json: &str, files: &Files) -> Msg<()> {
        let scenario = Scenario::from_json(json).map_err(refused)?;
        let name = scenario.name.clone();
        self.session
            .load_scenario(scenario, &files.resolver())
            .map_err(|e| refused(e).about("scenario", &name))?;
        self.replaced();
        Ok(())
    }

    /// Loads the map file(s) the user picked ([`Session::load_map`]). On an error (a bad
    /// file) the current map and system stay.
    pub(crate) fn load_map_files(&mut self, files: &Files, movingai_grid_size: f64) -> Msg<()> {
        let (name, map) = files.load_map(movingai_grid_size)?;
        self.load_map(&name, map)
    }

    fn load_map(&mut self, name: &str, map: GridMap) -> Msg<()> {
        self.session.load_map(name, map).map_err(refused)?;
        self.replaced();
        Ok(())
    }

    pub(crate) fn replaced(&mut self) {
        self.renderer.invalidate();
        if let Some(map) = self.session.system().map() {
            self.renderer.set_camera(map, None);
        }
        self.dirty = true;
    }

    // ------------------------------------------------------------------ the view

    /// Zooms by `factor` about the frame pixel `(px, py)` (back to the whole map at 1×).
    pub(crate) fn zoom_at(&mut self, px: f64, py: f64, factor: f64) {
        if let Some(map) = self.session.system().map() {
            self.renderer.zoom_at(map, px, py, factor);
            self.dirty = true;
        }
    }

    /// Drags the picture by `(dx, dy)` frame pixels (while zoomed in).
    pub(crate) fn pan_by(&mut self, dx: f64, dy: f64) {
        if let Some(map) = self.session.system().map() {
            self.renderer.pan_by(map, dx, dy);
            self.dirty = true;
        }
    }

    /// The whole map, fitted.
    pub(crate) fn fit_view(&mut self) {
        if let Some(map) = self.session.system().map() {
            self.renderer.set_camera(map, None);
            self.dirty = true;
        }
    }

    // ------------------------------------------------------------------ time

    /// [`Session::advance`]. Returns the number of ticks run.
    pub(crate) fn step(&mut self, elapsed_ms: f64) -> u32 {
        self.step_while(elapsed_ms, || true)
    }

    /// [`step`](Self::step), asking `more()` before each tick ([`Session::advance_while`]).
    pub(crate) fn step_while(&mut self, elapsed_ms: f64, more: impl FnMut() -> bool) -> u32 {
        let ticks = self.session.advance_while(elapsed_ms, more);
        if ticks > 0 {
            self.dirty = true;
        }
        // At most 100 ms × 16 of 1 ms ticks: fits.
        u32::try_from(ticks).unwrap_or(u32::MAX)
    }

    /// Runs `ticks` base ticks (paused or not).
    pub(crate) fn run_ticks(&mut self, ticks: u64) -> Msg<()> {
        self.session.step_ticks(ticks).map_err(refused)?;
        self.dirty = true;
        Ok(())
    }

    pub(crate) fn set_speed(&mut self, speed: f64) -> Msg<()> {
        self.session.set_speed(speed).map_err(refused)
    }

    // ------------------------------------------------------------------ lifecycle

    fn kind(name: &str) -> Msg<ComponentKind> {
        ComponentKind::from_name(name).map_err(refused)
    }

    /// One request to the session ([`Session::apply`]).
    pub(crate) fn apply(&mut self, input: &Input) -> Msg<()> {
        let r = self.session.apply(input);
        self.changed(r)
    }

    /// A lifecycle request on the component `name`; returns the state it reached.
    fn lifecycle(
        &mut self,
        name: &str,
        request: fn(ComponentKind) -> Input,
    ) -> Msg<LifecycleState> {
        let component = Self::kind(name)?;
        self.apply(&request(component))?;
        Ok(self.system().component_state(component))
    }

    pub(crate) fn activate(&mut self, name: &str) -> Msg<LifecycleState> {
        self.lifecycle(name, |component| Input::Activate { component })
    }

    pub(crate) fn deactivate(&mut self, name: &str) -> Msg<LifecycleState> {
        self.lifecycle(name, |component| Input::Deactivate { component })
    }

    pub(crate) fn reset(&mut self, name: &str) -> Msg<LifecycleState> {
        self.lifecycle(name, |component| Input::Reset { component })
    }

    pub(crate) fn inject_fault(&mut self, name: &str) -> Msg<()> {
        let component = Self::kind(name)?;
        self.apply(&Input::InjectFault {
            component,
            reason: FAULT_REASON.to_owned(),
        })
    }

    pub(crate) fn inject_input(&mut self, name: &str, port: &str, data: Vec<f64>) -> Msg<()> {
        let component = Self::kind(name)?;
        self.apply(&Input::InjectInput {
            component,
            port: port.to_owned(),
            data,
        })
    }

    /// A request on every component; returns the system's state.
    pub(crate) fn all(&mut self, input: &Input) -> String {
        // Requests on all components are never refused.
        let _ = self.apply(input);
        self.system().state().to_string()
    }

    // ------------------------------------------------------------------ inputs

    pub(crate) fn set_cells(&mut self, xs: &[i32], ys: &[i32], value: i16) -> Msg<()> {
        if xs.len() != ys.len() {
            return Err(PageError::CellLists {
                xs: xs.len(),
                ys: ys.len(),
            }
            .into());
        }
        let cells: Vec<(i64, i64, i16)> = xs
            .iter()
            .zip(ys)
            .map(|(&x, &y)| (i64::from(x), i64::from(y), value))
            .collect();
        self.apply(&Input::MapUpdate { cells })
    }

    // ------------------------------------------------------------------ drawing

    /// Draws the current state if anything changed since the last frame. Returns whether
    /// it drew (false: the frame is the same, or no map yet).
    pub(crate) fn render(&mut self) -> Msg<bool> {
        if !self.dirty {
            return Ok(false);
        }
        let system = self.session.system();
        if system.map().is_none() {
            return Ok(false);
        }
        self.renderer
            .render_system(system, &caption(system), self.layers)
            .map_err(refused)?;
        self.dirty = false;
        Ok(true)
    }

    /// Whether the next [`render`](Self::render) is cheap: nothing to draw, or only the
    /// moving parts over the layers kept ([`Renderer::draws_from_cache`]).
    pub(crate) fn draws_from_cache(&self) -> bool {
        !self.dirty
            || self
                .renderer
                .draws_from_cache(self.session.system(), self.layers)
    }

    pub(crate) fn resize(&mut self, width: u32, height: u32) -> Msg<()> {
        self.renderer.resize(width, height).map_err(refused)?;
        self.dirty = true;
        Ok(())
    }

    pub(crate) fn set_layer(&mut self, name: &str, on: bool) -> Msg<()> {
        let mut value = serde_json::to_value(self.layers).map_err(msg)?;
        if let Some(map) = value.as_object_mut() {
            if !map.contains_key(name) {
                let known: Vec<&str> = map.keys().map(String::as_str).collect();
                return Err(PageError::UnknownLayer {
                    name: name.to_owned(),
                    known: known.join(", "),
                }
                .into());
            }
            map.insert(name.to_owned(), serde_json::Value::Bool(on));
        }
        self.layers = serde_json::from_value(value).map_err(msg)?;
        self.dirty = true;
        Ok(())
    }

    pub(crate) fn layers(&self) -> Layers {
        self.layers
    }

    pub(crate) fn view(&self) -> Option<rtnav::render::ViewTransform> {
        self.system().map().map(|m| self.renderer.view(m))
    }

    // ------------------------------------------------------------------ reading

    pub(crate) fn components(&self) -> Vec<ComponentView> {
        let wiring = self.system().wiring();
        let ec = wiring.execution_context();
        ComponentKind::ALL
            .into_iter()
            .map(|kind| {
                let info = self.system().component(kind);
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
        self.session
            .new_events()
            .iter()
            .map(EventView::of)
            .collect()
    }

    pub(crate) fn telemetry(&self) -> TelemetryView {
        let s = self.system();
        let pose = s.robot_pose();
        let stats = s.stats();
        let m = s.mission();
        let last = s.record().telemetry().last();
        let pick = |f: fn(&rtnav::system::TelemetrySample) -> f64| last.map_or(0.0, f);
        let status = self.session.status();
        // The status as data: `{kind, …fields}` (`Status` is `serde(tag = "kind")`).
        let mut status_fields = match serde_json::to_value(&status) {
            Ok(serde_json::Value::Object(m)) => m,
            _ => serde_json::Map::new(),
        };
        let status_kind = match status_fields.remove("kind") {
            Some(serde_json::Value::String(k)) => k,
            _ => String::new(),
        };
        TelemetryView {
            time_s: s.time(),
            state: s.state(),
            driving: s.is_driving(),
            status: status.to_string(),
            status_kind,
            status_fields,
            arrived: m.is_arrived(),
            halted: m.is_halted(),
            paused: self.session.paused(),
            speed: self.session.speed(),
            pose: pose.into(),
            body_radius: s.wiring().motor_control().geometry().radius_of_body_area,
            start: m.start().map(PoseView::from),
            goal: m.goal().map(PoseView::from),
            direction: direction_name(m.direction()),
            distance_to_goal: m.goal().map(|g| libm::hypot(g.x - pose.x, g.y - pose.y)),
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
        let s = self.system();
        let lpp = s.wiring().local_path_planning();
        let m = s.mission();
        PlanView {
            start: m.start().map(PoseView::from),
            goal: m.goal().map(PoseView::from),
            direction: direction_name(m.direction()),
            global_path: m.route().to_vec(),
            local_path: lpp.merged_path().to_vec(),
            control_points: lpp
                .control_points()
                .map_or_else(Vec::new, |c| c.points.clone()),
        }
    }

    pub(crate) fn cell(&self, x: i32, y: i32) -> i32 {
        match self.system().map() {
            Some(m)
                if x >= 0 && y >= 0 && (x as usize) < m.width() && (y as usize) < m.height() =>
            {
                i32::from(m.is_obstacle(i64::from(x), i64::from(y)))
            }
            _ => -1,
        }
    }

    pub(crate) fn scenario_view(&self) -> Option<ScenarioView> {
        self.session.scenario().map(|s| ScenarioView {
            name: s.name.clone(),
            description: s.description.clone(),
            lesson: s.lesson.clone(),
        })
    }

    pub(crate) fn map_view(&self) -> Option<MapView> {
        let s = self.system();
        let m = s.map()?;
        Some(MapView {
            name: self.session.map_name().to_owned(),
            width: m.width(),
            height: m.height(),
            grid_size: m.grid_size(),
            origin: m.origin(),
            obstacles: m.cells().iter().filter(|&&c| c != 0).count(),
            key: s.wiring().map_key(),
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

pub(crate) fn json<T: serde::Serialize>(value: &T) -> Result<String, JsValue> {
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
    pub fn new(width: u32, height: u32) -> Result<Demo, JsValue> {
        Ok(Demo(Box::new(Inner::new(width, height).map_err(js)?)))
    }

    // ------------------------------------------------------------------ loading

    /// Loads a scenario (its JSON text; `files` holds the map files it names, by the paths
    /// it gives them) and previews its plan. On an error the current scenario stays.
    pub fn load_scenario(&mut self, json: &str, files: &Files) -> Result<(), JsValue> {
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
    ) -> Result<(), JsValue> {
        self.0.load_map_files(files, movingai_grid_size).map_err(js)
    }

    /// The scenario loaded, as JSON `{name, description, lesson}`, or `null` (a map file).
    pub fn scenario_json(&self) -> Result<String, JsValue> {
        json(&self.0.scenario_view())
    }

    /// The map as JSON `{name, width, height, grid_size, origin, obstacles, key}`, or `null`.
    pub fn map_json(&self) -> Result<String, JsValue> {
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

    /// [`step`](Self::step) within `budget_ms` of wall time (`performance.now()`): the ticks
    /// not run stay owed to the next frame, so an expensive tick (a plan on a large map) does
    /// not freeze the page for the rest of the frame's simulated time
    /// ([`Session::advance_while`]); a budget ≤ 0 runs none. Returns the number of ticks run.
    pub fn step_within(&mut self, elapsed_ms: f64, budget_ms: f64) -> u32 {
        let start = performance_now();
        self.0
            .step_while(elapsed_ms, || performance_now() - start < budget_ms)
    }

    /// Simulated time owed to the clock and not yet run \[s\] (behind the chosen speed).
    pub fn behind_s(&self) -> f64 {
        self.0.session.behind_s()
    }

    /// Runs `ticks` base ticks now, paused or not (the page's single step: one tick).
    pub fn step_ticks(&mut self, ticks: u32) -> Result<(), JsValue> {
        self.0.run_ticks(u64::from(ticks)).map_err(js)
    }

    /// Simulated time \[s\].
    pub fn time_s(&self) -> f64 {
        self.0.system().time()
    }

    /// Pauses or resumes the clock.
    pub fn set_paused(&mut self, paused: bool) {
        self.0.session.set_paused(paused);
    }

    /// Whether the clock is paused.
    pub fn paused(&self) -> bool {
        self.0.session.paused()
    }

    /// Sets the speed (simulated seconds per wall second), 0.25 to 16.
    pub fn set_speed(&mut self, speed: f64) -> Result<(), JsValue> {
        self.0.set_speed(speed).map_err(js)
    }

    /// The speed.
    pub fn speed(&self) -> f64 {
        self.0.session.speed()
    }

    // ------------------------------------------------------------------ lifecycle

    /// Activates one component (`LocalPathPlanning` or `LocalPathPlanning0`). Returns the
    /// state reached; an illegal request is an error and changes nothing.
    pub fn activate(&mut self, name: &str) -> Result<String, JsValue> {
        self.0.activate(name).map(|s| s.to_string()).map_err(js)
    }

    /// Deactivates one component. Returns the state reached.
    pub fn deactivate(&mut self, name: &str) -> Result<String, JsValue> {
        self.0.deactivate(name).map(|s| s.to_string()).map_err(js)
    }

    /// Resets one component in Error. Returns the state reached.
    pub fn reset(&mut self, name: &str) -> Result<String, JsValue> {
        self.0.reset(name).map(|s| s.to_string()).map_err(js)
    }

    /// Makes the component's next execution fail (→ Error with the reason
    /// `injected fault: requested from the page`).
    pub fn inject_fault(&mut self, name: &str) -> Result<(), JsValue> {
        self.0.inject_fault(name).map_err(js)
    }

    /// Activates every Inactive component. Returns the system's state.
    pub fn activate_all(&mut self) -> String {
        self.0.all(&Input::ActivateAll)
    }

    /// Deactivates every Active component. Returns the system's state.
    pub fn deactivate_all(&mut self) -> String {
        self.0.all(&Input::DeactivateAll)
    }

    /// Resets every component in Error and deactivates the Active ones. Returns the
    /// system's state.
    pub fn reset_all(&mut self) -> String {
        self.0.all(&Input::ResetAll)
    }

    /// The system's state: `Inactive`, `Active`, `Partial` or `Error`.
    pub fn system_state(&self) -> String {
        self.0.system().state().to_string()
    }

    /// Every component as JSON: `[{name, kind, instance_name, state, colour, rate,
    /// last_error, status, fault_pending}]`, in data-flow order.
    pub fn components_json(&self) -> Result<String, JsValue> {
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
    ) -> Result<(), JsValue> {
        self.0
            .apply(&Input::SetPosition {
                start: pose(start_x, start_y, start_deg),
                goal: pose(goal_x, goal_y, goal_deg),
                direction: direction(backward),
            })
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
    ) -> Result<(), JsValue> {
        self.0
            .apply(&Input::SetGoal {
                goal: pose(x, y, theta_deg),
                direction: direction(backward),
            })
            .map_err(js)
    }

    /// `MapUpdate` of the cells `(xs[i], ys[i])` to `value` (1 obstacle, 0 free): one stroke
    /// (or one frame of it) is one update. Cells outside the map are an error and nothing
    /// changes; an update that changes no cell requests nothing.
    pub fn set_cells(&mut self, xs: Vec<i32>, ys: Vec<i32>, value: i16) -> Result<(), JsValue> {
        self.0.set_cells(&xs, &ys, value).map_err(js)
    }

    /// `Clear`: the paths and the goal are dropped; the robot stops.
    pub fn clear(&mut self) {
        // Never refused.
        let _ = self.0.apply(&Input::Clear);
    }

    /// `SafeMode`: the robot halts until the next goal.
    pub fn safe_mode(&mut self) {
        // Never refused.
        let _ = self.0.apply(&Input::SafeMode);
    }

    // ------------------------------------------------------------------ drawing

    /// Draws the current state into the frame if anything changed. Returns whether it drew.
    pub fn render(&mut self) -> Result<bool, JsValue> {
        self.0.render().map_err(js)
    }

    /// Whether the next `render` only draws the moving parts (robot, trail, marks) over the
    /// layers kept from the last frame; `false` when a new plan, a map edit or a new view
    /// makes it redraw the map and the paths (the page leaves that to the next frame after
    /// an expensive step).
    pub fn draws_from_cache(&self) -> bool {
        self.0.draws_from_cache()
    }

    /// Changes the frame size (pixels).
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), JsValue> {
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
    pub fn layers_json(&self) -> Result<String, JsValue> {
        json(&self.0.layers())
    }

    /// Shows or hides a layer (`heat_map`, `trail`, …).
    pub fn set_layer(&mut self, name: &str, on: bool) -> Result<(), JsValue> {
        self.0.set_layer(name, on).map_err(js)
    }

    /// Frame pixel → world point `[x, y]` in metres (`undefined` without a map).
    pub fn pixel_to_world(&self, px: f64, py: f64) -> Option<Vec<f64>> {
        let (x, y) = self.0.view()?.pixel_to_world(px, py);
        Some(vec![x, y])
    }

    /// Frame pixel → map cell `[x, y]` (`undefined` outside the map).
    pub fn pixel_to_cell(&self, px: f64, py: f64) -> Option<Vec<u32>> {
        let map = self.0.system().map()?;
        let (x, y) = self.0.renderer.view(map).pixel_to_cell(map, px, py)?;
        Some(vec![u32::try_from(x).ok()?, u32::try_from(y).ok()?])
    }

    /// World point → frame pixel `[px, py]` (`undefined` without a map).
    pub fn world_to_pixel(&self, x: f64, y: f64) -> Option<Vec<f64>> {
        let (px, py) = self.0.view()?.world_to_pixel(x, y);
        Some(vec![px, py])
    }

    /// Zooms the picture by `factor` about the frame pixel `(px, py)`, which keeps showing
    /// the same world point (wheel, pinch, the zoom buttons); 1× to 64×, and back to the
    /// whole map at 1×.
    pub fn zoom_at(&mut self, px: f64, py: f64, factor: f64) {
        self.0.zoom_at(px, py, factor);
    }

    /// Drags the picture by `(dx, dy)` frame pixels, while zoomed in (pan).
    pub fn pan_by(&mut self, dx: f64, dy: f64) {
        self.0.pan_by(dx, dy);
    }

    /// Shows the whole map again (fit).
    pub fn fit_view(&mut self) {
        self.0.fit_view();
    }

    /// The magnification of the whole-map view (1 when it is fitted).
    pub fn zoom(&self) -> f64 {
        self.0.renderer.camera().map_or(1.0, |c| c.zoom)
    }

    /// The heat map's colour scale `[lo, hi, clipped]` (potentials, log scale; `clipped` 1
    /// when the top half percent is above `hi`), or `undefined` when none is drawn.
    pub fn heat_range(&self) -> Option<Vec<f64>> {
        let (lo, hi, clipped) = self.0.renderer.heat_range()?;
        Some(vec![lo, hi, f64::from(u8::from(clipped))])
    }

    /// Where the robot has been, as JSON `[[x, y], …]` in metres (points at least 2 cm
    /// apart, oldest first).
    pub fn trail_json(&self) -> Result<String, JsValue> {
        json(&self.0.system().record().trail())
    }

    /// Frame pixels per metre (`0` without a map).
    pub fn pixels_per_metre(&self) -> f64 {
        self.0.view().map_or(0.0, |v| v.pixels_per_metre())
    }

    // ------------------------------------------------------------------ reading

    /// The events since the last call, oldest first, as JSON `[{time_s, kind, level, text,
    /// data}]`.
    pub fn take_events(&mut self) -> Result<String, JsValue> {
        json(&self.0.take_events())
    }

    /// The telemetry readout as JSON.
    pub fn telemetry_json(&self) -> Result<String, JsValue> {
        json(&self.0.telemetry())
    }

    /// Start, goal, paths and control points as JSON.
    pub fn plan_json(&self) -> Result<String, JsValue> {
        json(&self.0.plan())
    }

    // ------------------------------------------------------------------ faults

    /// Writes one sample into a component's input port, as a connected output port would
    /// (rtshell's `rtinject`): `Localization` `InSimulatedPosition` (`[x, y, z, θ]`) or
    /// `InCurrentWheelAngle` (`[left, right]`). A NaN pose puts Localization in Error.
    pub fn inject_input(
        &mut self,
        component: &str,
        port: &str,
        values: Vec<f64>,
    ) -> Result<(), JsValue> {
        self.0.inject_input(component, port, values).map_err(js)
    }

    /// Panics on purpose, so the end-to-end test can prove the page shows a crash.
    pub fn debug_panic(&mut self) {
        panic!("debug_panic: deliberate panic requested by the page");
    }
}

#[cfg(test)]
mod tests;
