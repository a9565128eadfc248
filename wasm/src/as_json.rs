//! The read-outs the browser tests compare with what the page shows, as JSON text (the
//! tests and the console read them; the page reads the same views as values).

use wasm_bindgen::prelude::*;

use crate::demo::Demo;
use crate::{js, msg, refused};

fn text<T: serde::Serialize>(v: &T) -> Result<String, JsValue> {
    serde_json::to_string(v).map_err(|e| js(msg(e)))
}

#[wasm_bindgen]
impl Demo {
    /// [`Demo::telemetry`] as JSON text.
    pub fn telemetry_json(&self) -> Result<String, JsValue> {
        text(&self.session.telemetry())
    }

    /// [`Demo::plan`] as JSON text.
    pub fn plan_json(&self) -> Result<String, JsValue> {
        text(&self.session.plan())
    }

    /// [`Demo::map`] as JSON text.
    pub fn map_json(&self) -> Result<String, JsValue> {
        text(&self.session.map_view())
    }

    /// [`Demo::params`] as JSON text.
    pub fn params_json(&self) -> Result<String, JsValue> {
        text(&self.session.parameters_view())
    }

    /// [`Demo::plot`] as JSON text.
    pub fn plot_json(&self, seconds: f64) -> Result<String, JsValue> {
        text(&self.session.plot(seconds))
    }

    /// [`Demo::system_graph`] as JSON text.
    pub fn system_json(&self) -> Result<String, JsValue> {
        text(&self.session.graph())
    }

    /// [`Demo::trail`] as JSON text.
    pub fn trail_json(&self) -> Result<String, JsValue> {
        text(&self.session.trail())
    }

    /// [`Demo::inspect`] as JSON text.
    pub fn inspect_cell(&self, x: i32, y: i32) -> Result<String, JsValue> {
        let cell = self
            .session
            .inspect_cell(i64::from(x), i64::from(y))
            .map_err(|e| js(refused(e)))?;
        text(&cell)
    }
}
