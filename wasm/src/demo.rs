//! [`Demo`]: a [`Session`] (the system as a person drives it) and its [`Screen`] behind
//! one handle (spec §5 InventGUI).
//!
//! Every method is one call into the core: the session's requests and read-outs, the
//! screen's drawing and view. A request that may change the picture tells the screen so.
//! What the page reads comes back as JavaScript values of the core's view types
//! (`web/types/core.d.ts`, generated from them).

use rtnav::render::Screen;
use rtnav::system::{DirectionView, Input, PickedFiles, PoseView, Session};
use wasm_bindgen::prelude::*;

use crate::files::Files;
use crate::{Msg, js, refused, value};

#[wasm_bindgen]
extern "C" {
    /// The page's wall clock \[ms\]: for the frame budget only (simulated time never reads it).
    #[wasm_bindgen(js_namespace = performance, js_name = now)]
    fn performance_now() -> f64;
}

/// The reason an injected fault gives.
const FAULT_REASON: &str = "requested from the page";

/// The page's handle: the session and its screen.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Demo {
    pub(crate) session: Session,
    pub(crate) screen: Screen,
}

impl Demo {
    /// A request that may change the picture.
    pub(crate) fn changed<T>(&mut self, r: rtnav::Result<T>) -> Msg<T> {
        self.screen.changed();
        r.map_err(refused)
    }

    /// The session's map was replaced.
    fn replaced(&mut self) {
        self.screen.replaced(&self.session);
    }
}

/// A pose from metres and degrees (what the page's drag gives).
fn pose(x: f64, y: f64, theta_deg: f64) -> PoseView {
    PoseView { x, y, theta_deg }
}

fn direction(backward: bool) -> DirectionView {
    if backward {
        DirectionView::Backward
    } else {
        DirectionView::Forward
    }
}

#[wasm_bindgen]
impl Demo {
    /// A handle with an empty system (no map yet) drawing `width × height` frames.
    #[wasm_bindgen(constructor)]
    pub fn new(width: u32, height: u32) -> Result<Demo, JsValue> {
        Ok(Demo {
            session: Session::new().map_err(|e| js(refused(e)))?,
            screen: Screen::new(width, height).map_err(|e| js(refused(e)))?,
        })
    }

    // ------------------------------------------------------------------ loading

    /// Loads a scenario (its JSON text; `files` holds the map files it names, by the paths
    /// it gives them) and previews its plan. On an error the current scenario stays.
    pub fn load_scenario(&mut self, json: &str, files: &Files) -> Result<(), JsValue> {
        self.session
            .load_scenario_text(json, &files.0)
            .map_err(|e| js((*e).into()))?;
        self.replaced();
        Ok(())
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
        let picked: &PickedFiles = &files.0;
        self.session
            .load_map_files(picked, movingai_grid_size)
            .map_err(|e| js(e.into()))?;
        self.replaced();
        Ok(())
    }

    /// The scenario loaded, or `null` (a map file).
    #[wasm_bindgen(unchecked_return_type = "ScenarioView | null")]
    pub fn scenario(&self) -> Result<JsValue, JsValue> {
        value(&self.session.scenario_view())
    }

    /// The map's geometry, or `null`.
    #[wasm_bindgen(unchecked_return_type = "MapView | null")]
    pub fn map(&self) -> Result<JsValue, JsValue> {
        value(&self.session.map_view())
    }

    /// The map cell `(x, y)`: 1 obstacle, 0 free, −1 outside the map (or no map).
    pub fn cell(&self, x: i32, y: i32) -> i32 {
        self.session
            .cell(i64::from(x), i64::from(y))
            .map_or(-1, i32::from)
    }

    /// The map cell `[x, y]` under the world point `(x, y)` \[m\] (`undefined` outside).
    pub fn world_to_cell(&self, x: f64, y: f64) -> Option<Vec<u32>> {
        let (cx, cy) = self.session.world_to_cell(x, y)?;
        Some(vec![u32::try_from(cx).ok()?, u32::try_from(cy).ok()?])
    }

    /// The cells a square brush covers centred at the world point `(x, y)` \[m\], `size`
    /// cells or (`in_metres`) metres across, as `[x0, y0, x1, y1, …]`.
    pub fn brush_cells(&self, x: f64, y: f64, size: f64, in_metres: bool) -> Vec<u32> {
        self.session
            .brush_cells(x, y, size, in_metres)
            .into_iter()
            .flat_map(|(cx, cy)| [cx, cy])
            .map(|c| u32::try_from(c).unwrap_or(u32::MAX))
            .collect()
    }

    // ------------------------------------------------------------------ time

    /// Advances simulated time by `elapsed_ms` of wall time × the speed, in whole ticks;
    /// nothing while paused. Returns the number of ticks run.
    pub fn step(&mut self, elapsed_ms: f64) -> u32 {
        self.step_within(elapsed_ms, f64::INFINITY)
    }

    /// [`step`](Self::step) within `budget_ms` of wall time (`performance.now()`): the ticks
    /// not run stay owed to the next frame ([`Session::advance_while`]); a budget ≤ 0 runs
    /// none. Returns the number of ticks run.
    pub fn step_within(&mut self, elapsed_ms: f64, budget_ms: f64) -> u32 {
        let start = performance_now();
        let ticks = self
            .session
            .advance_while(elapsed_ms, || performance_now() - start < budget_ms);
        if ticks > 0 {
            self.screen.changed();
        }
        // At most 100 ms × 16 of 1 ms ticks: fits.
        u32::try_from(ticks).unwrap_or(u32::MAX)
    }

    /// Simulated time owed to the clock and not yet run \[s\] (behind the chosen speed).
    pub fn behind_s(&self) -> f64 {
        self.session.behind_s()
    }

    /// Runs `ticks` base ticks now, paused or not (the page's single step: one tick).
    pub fn step_ticks(&mut self, ticks: u32) -> Result<(), JsValue> {
        self.session
            .step_ticks(u64::from(ticks))
            .map_err(|e| js(refused(e)))?;
        self.screen.changed();
        Ok(())
    }

    /// Simulated time \[s\].
    pub fn time_s(&self) -> f64 {
        self.session.time_s()
    }

    /// Base ticks in one period of simulated time \[s\] (a step of ±1 tick).
    pub fn tick_s(&self) -> f64 {
        self.session.tick_s()
    }

    /// Pauses or resumes the clock.
    pub fn set_paused(&mut self, paused: bool) {
        self.session.set_paused(paused);
    }

    /// Whether the clock is paused.
    pub fn paused(&self) -> bool {
        self.session.paused()
    }

    /// Sets the speed (simulated seconds per wall second), 0.25 to 16.
    pub fn set_speed(&mut self, speed: f64) -> Result<(), JsValue> {
        self.session.set_speed(speed).map_err(|e| js(refused(e)))
    }

    /// The speed.
    pub fn speed(&self) -> f64 {
        self.session.speed()
    }

    // ------------------------------------------------------------------ lifecycle

    /// Activates one component (`LocalPathPlanning` or `LocalPathPlanning0`). Returns the
    /// state reached; an illegal request is an error and changes nothing.
    pub fn activate(&mut self, name: &str) -> Result<String, JsValue> {
        let r = self
            .session
            .lifecycle(name, |component| Input::Activate { component });
        self.changed(r).map(|s| s.to_string()).map_err(js)
    }

    /// Deactivates one component. Returns the state reached.
    pub fn deactivate(&mut self, name: &str) -> Result<String, JsValue> {
        let r = self
            .session
            .lifecycle(name, |component| Input::Deactivate { component });
        self.changed(r).map(|s| s.to_string()).map_err(js)
    }

    /// Resets one component in Error. Returns the state reached.
    pub fn reset(&mut self, name: &str) -> Result<String, JsValue> {
        let r = self
            .session
            .lifecycle(name, |component| Input::Reset { component });
        self.changed(r).map(|s| s.to_string()).map_err(js)
    }

    /// Makes the component's next execution fail (→ Error with the reason
    /// `injected fault: requested from the page`).
    pub fn inject_fault(&mut self, name: &str) -> Result<(), JsValue> {
        let r = self.session.inject_fault(name, FAULT_REASON);
        self.changed(r).map_err(js)
    }

    /// Activates every Inactive component. Returns the system's state; before the robot
    /// is placed it is refused (the reason says so) and changes nothing.
    pub fn activate_all(&mut self) -> Result<String, JsValue> {
        let r = self.session.all(&Input::ActivateAll);
        self.changed(r).map(|s| s.to_string()).map_err(js)
    }

    /// Deactivates every Active component. Returns the system's state.
    pub fn deactivate_all(&mut self) -> Result<String, JsValue> {
        let r = self.session.all(&Input::DeactivateAll);
        self.changed(r).map(|s| s.to_string()).map_err(js)
    }

    /// Resets every component in Error and deactivates the Active ones. Returns the
    /// system's state.
    pub fn reset_all(&mut self) -> Result<String, JsValue> {
        let r = self.session.all(&Input::ResetAll);
        self.changed(r).map(|s| s.to_string()).map_err(js)
    }

    /// The system's state: `Inactive`, `Active`, `Partial` or `Error`.
    pub fn system_state(&self) -> String {
        self.session.state().to_string()
    }

    /// Every component, in data-flow order.
    #[wasm_bindgen(unchecked_return_type = "ComponentView[]")]
    pub fn components(&self) -> Result<JsValue, JsValue> {
        value(&self.session.components())
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
        let r = self.session.set_position_at(
            pose(start_x, start_y, start_deg),
            pose(goal_x, goal_y, goal_deg),
            direction(backward),
        );
        self.changed(r).map_err(js)
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
        let r = self
            .session
            .set_goal_at(pose(x, y, theta_deg), direction(backward));
        self.changed(r).map_err(js)
    }

    /// `MapUpdate` of the cells `(xs[i], ys[i])` to `value` (1 obstacle, 0 free): one stroke
    /// is one update. Cells outside the map are an error and nothing changes; an update
    /// that changes no cell requests nothing.
    pub fn set_cells(&mut self, xs: Vec<i32>, ys: Vec<i32>, value: i16) -> Result<(), JsValue> {
        let r = self.session.set_cells(&xs, &ys, value);
        self.changed(r).map_err(js)
    }

    /// `Clear`: the paths and the goal are dropped; the robot stops.
    pub fn clear(&mut self) {
        // Never refused.
        let r = self.session.apply(&Input::Clear);
        let _ = self.changed(r);
    }

    /// `SafeMode`: the robot halts until the next goal.
    pub fn safe_mode(&mut self) {
        // Never refused.
        let r = self.session.apply(&Input::SafeMode);
        let _ = self.changed(r);
    }

    // ------------------------------------------------------------------ drawing

    /// Draws the current state into the frame if anything changed. Returns whether it drew.
    pub fn render(&mut self) -> Result<bool, JsValue> {
        self.screen.draw(&self.session).map_err(|e| js(refused(e)))
    }

    /// Whether the next `render` only draws the moving parts (robot, trail, marks) over the
    /// layers kept from the last frame; `false` when a new plan, a map edit or a new view
    /// makes it redraw the map and the paths.
    pub fn draws_from_cache(&self) -> bool {
        self.screen.draws_from_cache(&self.session)
    }

    /// Changes the frame size (pixels).
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), JsValue> {
        self.screen
            .resize(width, height)
            .map_err(|e| js(refused(e)))
    }

    /// Where the frame's pixels start in wasm memory (RGBA, opaque, rows top to bottom).
    pub fn frame_ptr(&self) -> usize {
        self.screen.frame().data().as_ptr() as usize
    }

    /// The frame's length in bytes (`4 · width · height`).
    pub fn frame_len(&self) -> usize {
        self.screen.frame().data().len()
    }

    /// The frame's width in pixels.
    pub fn frame_width(&self) -> u32 {
        self.screen.width()
    }

    /// The frame's height in pixels.
    pub fn frame_height(&self) -> u32 {
        self.screen.height()
    }

    /// The layers shown.
    #[wasm_bindgen(unchecked_return_type = "Layers")]
    pub fn layers(&self) -> Result<JsValue, JsValue> {
        value(&self.screen.layers())
    }

    /// Shows or hides a layer (`heat_map`, `trail`, …).
    pub fn set_layer(&mut self, name: &str, on: bool) -> Result<(), JsValue> {
        self.screen.set_layer(name, on).map_err(|e| js(refused(e)))
    }

    /// Frame pixel → world point `[x, y]` in metres (`undefined` without a map).
    pub fn pixel_to_world(&self, px: f64, py: f64) -> Option<Vec<f64>> {
        let (x, y) = self.screen.view(&self.session)?.pixel_to_world(px, py);
        Some(vec![x, y])
    }

    /// Frame pixel → map cell `[x, y]` (`undefined` outside the map).
    pub fn pixel_to_cell(&self, px: f64, py: f64) -> Option<Vec<u32>> {
        let (x, y) = self.screen.pixel_to_cell(&self.session, px, py)?;
        Some(vec![u32::try_from(x).ok()?, u32::try_from(y).ok()?])
    }

    /// World point → frame pixel `[px, py]` (`undefined` without a map).
    pub fn world_to_pixel(&self, x: f64, y: f64) -> Option<Vec<f64>> {
        let (px, py) = self.screen.view(&self.session)?.world_to_pixel(x, y);
        Some(vec![px, py])
    }

    /// Zooms the picture by `factor` about the frame pixel `(px, py)`, which keeps showing
    /// the same world point (wheel, pinch, the zoom buttons); 1× to 64×, and back to the
    /// whole map at 1×.
    pub fn zoom_at(&mut self, px: f64, py: f64, factor: f64) {
        self.screen.zoom_at(&self.session, px, py, factor);
    }

    /// Drags the picture by `(dx, dy)` frame pixels, while zoomed in (pan).
    pub fn pan_by(&mut self, dx: f64, dy: f64) {
        self.screen.pan_by(&self.session, dx, dy);
    }

    /// Shows the whole map again (fit).
    pub fn fit_view(&mut self) {
        self.screen.fit(&self.session);
    }

    /// The magnification of the whole-map view (1 when it is fitted).
    pub fn zoom(&self) -> f64 {
        self.screen.zoom()
    }

    /// The heat map's colour scale `[lo, hi, clipped]` (potentials, log scale; `clipped` 1
    /// when the top half percent is above `hi`), or `undefined` when none is drawn.
    pub fn heat_range(&self) -> Option<Vec<f64>> {
        let (lo, hi, clipped) = self.screen.heat_range()?;
        Some(vec![lo, hi, f64::from(u8::from(clipped))])
    }

    /// Frame pixels per metre (`0` without a map).
    pub fn pixels_per_metre(&self) -> f64 {
        self.screen
            .view(&self.session)
            .map_or(0.0, |v| v.pixels_per_metre())
    }

    /// Where the robot has been, `[[x, y], …]` in metres (points at least 2 cm apart,
    /// oldest first).
    #[wasm_bindgen(unchecked_return_type = "Array<[number, number]>")]
    pub fn trail(&self) -> Result<JsValue, JsValue> {
        value(&self.session.trail())
    }

    // ------------------------------------------------------------------ reading

    /// One frame's read: the clock, the telemetry and status, the components, the events
    /// since the last frame, the exercise.
    #[wasm_bindgen(unchecked_return_type = "FrameView")]
    pub fn frame(&mut self) -> Result<JsValue, JsValue> {
        value(&self.session.frame())
    }

    /// The events since the last look, oldest first.
    #[wasm_bindgen(unchecked_return_type = "EventView[]")]
    pub fn take_events(&mut self) -> Result<JsValue, JsValue> {
        value(&self.session.event_views())
    }

    /// The telemetry readout and the status.
    #[wasm_bindgen(unchecked_return_type = "TelemetryView")]
    pub fn telemetry(&self) -> Result<JsValue, JsValue> {
        value(&self.session.telemetry())
    }

    /// Start, goal, paths and control points.
    #[wasm_bindgen(unchecked_return_type = "PlanView")]
    pub fn plan(&self) -> Result<JsValue, JsValue> {
        value(&self.session.plan())
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
        let r = self.session.inject_input(component, port, values);
        self.changed(r).map_err(js)
    }

    /// Panics on purpose, so the end-to-end test can prove the page shows a crash.
    pub fn debug_panic(&mut self) {
        panic!("debug_panic: deliberate panic requested by the page");
    }
}
