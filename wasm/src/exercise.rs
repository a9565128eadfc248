//! The exercise checklist (issue 17): one call into the core's
//! [`Session::exercise`](rtnav::system::Session::exercise).

use wasm_bindgen::prelude::*;

use crate::demo::{Demo, json};

#[wasm_bindgen]
impl Demo {
    /// The scenario's exercise as it stands, as JSON `{task, may_change, actions, checks:
    /// [{check: {check, …numbers}, state, measured, changed?}], verdict, started_at,
    /// ended_after}`, or `null` when the scenario has none.
    pub fn exercise_json(&self) -> Result<String, JsValue> {
        json(&self.0.session.exercise())
    }
}
