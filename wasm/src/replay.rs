//! Replays, the timeline and the compare view (issue 16) — each one call into the core's
//! [`Session`](rtnav::system::Session) and [`Comparison`].

use rtnav::render::{Layers, Renderer, caption};
use rtnav::system::{Comparison, ComponentKind, Replay};
use wasm_bindgen::prelude::*;

use crate::demo::{Demo, json};
use crate::{js, refused};

#[wasm_bindgen]
impl Demo {
    /// The run so far as a replay file's JSON text (`*.rtnav.json`): the set-up and every
    /// request up to now. An error for a map loaded from a file.
    pub fn replay_json(&self) -> Result<String, JsValue> {
        self.0.session.replay_json().map_err(|e| js(refused(e)))
    }

    /// The scenario a replay file was made on (load it first); the file is checked.
    pub fn replay_scenario(text: &str) -> Result<String, JsValue> {
        Replay::scenario_of(text).map_err(|e| js(refused(e)))
    }

    /// Loads a replay file on the scenario loaded and runs it to its end; JSON
    /// `{scenario, end_ns, inputs, expected_hash, hash, expected_samples, samples,
    /// matches}`. Refused with the reason (another version, malformed, another scenario).
    pub fn load_replay(&mut self, text: &str) -> Result<String, JsValue> {
        let replay = Replay::from_json(text).map_err(|e| js(refused(e)))?;
        let check = self.0.session.load_replay(&replay);
        let check = self.0.changed(check).map_err(js)?;
        json(&check)
    }

    /// Moves to simulated time `t_s` (back or forth, from the nearest checkpoint).
    pub fn seek(&mut self, t_s: f64) -> Result<(), JsValue> {
        let t = if t_s.is_finite() { t_s.max(0.0) } else { 0.0 };
        let r = self.0.session.seek(ns_of(t));
        self.0.changed(r).map_err(js)
    }

    /// The timeline as JSON `{start_ns, now_ns, end_ns, inputs, pending, checkpoints,
    /// checkpoint_ns, marks: [{t_ns, kind, text}]}`.
    pub fn timeline_json(&self) -> Result<String, JsValue> {
        json(&self.0.session.timeline_view().map_err(|e| js(refused(e)))?)
    }

    /// Base ticks in one period of simulated time \[s\] (a step of ±1 tick).
    pub fn tick_s(&self) -> f64 {
        self.0
            .system()
            .wiring()
            .execution_context()
            .base_period_ns() as f64
            * 1e-9
    }
}

/// Seconds → whole nanoseconds.
fn ns_of(t_s: f64) -> u64 {
    (t_s * 1e9).round() as u64
}

/// The compare view: two runs of the scenario loaded and a renderer of its own.
#[wasm_bindgen]
#[derive(Debug)]
pub struct CompareView {
    comparison: Comparison,
    renderer: Renderer,
}

#[wasm_bindgen]
impl CompareView {
    /// Runs the scenario of `demo` with its current set-up (A) and with `component`'s
    /// parameter `name` set to `text` (B), both to their outcome, for `width × height`
    /// frames.
    pub fn run(
        demo: &Demo,
        component: &str,
        name: &str,
        text: &str,
        width: u32,
        height: u32,
    ) -> Result<CompareView, JsValue> {
        let kind = ComponentKind::from_name(component).map_err(|e| js(refused(e)))?;
        let comparison = demo
            .0
            .session
            .compare_with(kind, name, text)
            .map_err(|e| js(refused(e)))?;
        let mut renderer = Renderer::new(width, height).map_err(|e| js(refused(e)))?;
        renderer.set_side_panel(false);
        Ok(CompareView {
            comparison,
            renderer,
        })
    }

    /// The table as JSON `{scenario, rows: [[measure, A, B]], a: {…}, b: {…}}`.
    pub fn table_json(&self) -> Result<String, JsValue> {
        let c = &self.comparison;
        json(&serde_json::json!({
            "scenario": c.scenario(),
            "rows": c.rows(),
            "a": c.a(),
            "b": c.b(),
        }))
    }

    /// Speed and turn rate over time of both runs as JSON `{t_a, v_a, w_a, t_b, v_b, w_b}`.
    pub fn plots_json(&self) -> Result<String, JsValue> {
        json(&self.comparison.plots())
    }

    /// Draws both runs at their end, B as the ghost; read the frame with `frame_ptr`.
    pub fn render(&mut self) -> Result<(), JsValue> {
        let a = self.comparison.system_a();
        let layers = Layers {
            scale_bar: false,
            legend: false,
            caption: false,
            ..Layers::ALL
        };
        self.renderer
            .render_compare(a, self.comparison.system_b(), &caption(a), layers)
            .map(drop)
            .map_err(|e| js(refused(e)))
    }

    /// The frame's RGBA bytes' address in the wasm memory.
    pub fn frame_ptr(&self) -> usize {
        self.renderer.frame().data().as_ptr() as usize
    }

    /// The frame's byte length.
    pub fn frame_len(&self) -> usize {
        self.renderer.frame().data().len()
    }
}
