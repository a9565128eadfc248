//! Replays, the timeline, the restart and the compare view — each one call into the core's
//! [`Session`](rtnav::system::Session) and [`Comparison`].

use rtnav::render::Screen;
use rtnav::system::{Comparison, Replay};
use wasm_bindgen::prelude::*;

use crate::demo::Demo;
use crate::{js, refused, value};

#[wasm_bindgen]
impl Demo {
    /// The run so far as a replay file's JSON text (`*.rtnav.json`): the set-up and every
    /// request up to now. An error for a map loaded from a file.
    pub fn replay_json(&self) -> Result<String, JsValue> {
        self.session.replay_json().map_err(|e| js(refused(e)))
    }

    /// The scenario a replay file was made on (load it first); the file is checked.
    pub fn replay_scenario(text: &str) -> Result<String, JsValue> {
        Replay::scenario_of(text).map_err(|e| js(refused(e)))
    }

    /// Loads a replay file on the scenario loaded and runs it to its end; says whether the
    /// run reproduced the recorded trace. Refused with the reason (another version,
    /// malformed, another scenario).
    #[wasm_bindgen(unchecked_return_type = "ReplayCheck")]
    pub fn load_replay(&mut self, text: &str) -> Result<JsValue, JsValue> {
        let check = self.session.load_replay_text(text);
        value(&self.changed(check).map_err(js)?)
    }

    /// Moves to simulated time `t_s` (back or forth, from the nearest checkpoint).
    pub fn seek(&mut self, t_s: f64) -> Result<(), JsValue> {
        let r = self.session.seek_s(t_s);
        self.changed(r).map_err(js)
    }

    /// Starts the run again: the set-up it started from with the parameters as they are
    /// now, at time 0, the clock running, the exercise's checklist afresh
    /// (`Session::restart`). Refused when no scenario is loaded.
    pub fn restart(&mut self) -> Result<(), JsValue> {
        let r = self.session.restart();
        self.changed(r).map_err(js)
    }

    /// The timeline: the run's span, its requests, checkpoints and marks.
    #[wasm_bindgen(unchecked_return_type = "TimelineView")]
    pub fn timeline(&self) -> Result<JsValue, JsValue> {
        value(&self.session.timeline_view().map_err(|e| js(refused(e)))?)
    }
}

/// The compare view: two runs of the scenario loaded and a screen of its own.
#[wasm_bindgen]
#[derive(Debug)]
pub struct CompareView {
    comparison: Comparison,
    screen: Screen,
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
        let comparison = demo
            .session
            .compare_named(component, name, text)
            .map_err(|e| js(refused(e)))?;
        let screen = Screen::new(width, height).map_err(|e| js(refused(e)))?;
        Ok(CompareView { comparison, screen })
    }

    /// The table: the rows `[measure, A, B]` and both runs' measures.
    #[wasm_bindgen(unchecked_return_type = "CompareTable")]
    pub fn table(&self) -> Result<JsValue, JsValue> {
        value(&self.comparison.table())
    }

    /// Speed and turn rate over time of both runs.
    #[wasm_bindgen(unchecked_return_type = "ComparePlots")]
    pub fn plots(&self) -> Result<JsValue, JsValue> {
        value(&self.comparison.plots())
    }

    /// Draws both runs at their end, B as the ghost; read the frame with `frame_ptr`.
    pub fn render(&mut self) -> Result<(), JsValue> {
        self.screen
            .draw_compare(&self.comparison)
            .map_err(|e| js(refused(e)))
    }

    /// The frame's RGBA bytes' address in the wasm memory.
    pub fn frame_ptr(&self) -> usize {
        self.screen.frame().data().as_ptr() as usize
    }

    /// The frame's byte length.
    pub fn frame_len(&self) -> usize {
        self.screen.frame().data().len()
    }
}
