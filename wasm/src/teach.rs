//! The teaching tools' requests: parameters, `SetPDGain`, plots, the inspector, the
//! exercise, share links and the exports — each one call into the core's
//! [`Session`](rtnav::system::Session).

use rtnav::system::{Input, Session};
use wasm_bindgen::prelude::*;

use crate::demo::Demo;
use crate::{js, refused, value};

#[wasm_bindgen]
impl Demo {
    /// Every parameter of LocalPathPlanning, MotorControl, DriveControl and PhysicsSim.
    #[wasm_bindgen(unchecked_return_type = "ComponentParameters[]")]
    pub fn params(&self) -> Result<JsValue, JsValue> {
        value(&self.session.parameters_view())
    }

    /// Sets a parameter from text: `always` at once, `on_activation` pending until the next
    /// activation; refused (the old value stays) with the reason for an unknown name, a value
    /// that is not a number, or one out of range.
    pub fn set_param(&mut self, component: &str, name: &str, text: &str) -> Result<(), JsValue> {
        let r = self.session.set_param_named(component, name, text);
        self.changed(r).map_err(js)
    }

    /// MotorControl's `Motor::SetPDGain(PGainL, PGainR, DGainL, DGainR)`; all four checked
    /// first, nothing changes on an error.
    pub fn set_pd_gain(&mut self, p_l: f64, p_r: f64, d_l: f64, d_r: f64) -> Result<(), JsValue> {
        let r = self.session.apply(&Input::SetPdGain { p_l, p_r, d_l, d_r });
        self.changed(r).map_err(js)
    }

    /// The whole configuration (every component that has parameters) as one OpenRTM
    /// `.conf` text: a block per component after its marker line `# [InstanceName]`.
    pub fn conf_export(&self) -> String {
        self.session.conf_text()
    }

    /// Replaces the configuration from a `.conf` text as [`Demo::conf_export`] writes it;
    /// all-or-nothing, refused with the line and the problem.
    pub fn conf_import(&mut self, text: &str) -> Result<(), JsValue> {
        let r = self.session.apply(&Input::LoadConf {
            text: text.to_owned(),
        });
        self.changed(r).map_err(js)
    }

    /// The cell `(x, y)` explained — the same numbers `rtnav inspect` prints natively. A
    /// cell outside the map is an error.
    #[wasm_bindgen(unchecked_return_type = "CellInspection")]
    pub fn inspect(&self, x: i32, y: i32) -> Result<JsValue, JsValue> {
        let cell = self
            .session
            .inspect_cell(i64::from(x), i64::from(y))
            .map_err(|e| js(refused(e)))?;
        value(&cell)
    }

    /// The last `seconds` (≤ 60) of telemetry, one array per series.
    #[wasm_bindgen(unchecked_return_type = "PlotWindow")]
    pub fn plot(&self, seconds: f64) -> Result<JsValue, JsValue> {
        value(&self.session.plot(seconds))
    }

    /// The scenario's exercise as it stands, with the clock's pause, or `null` when the
    /// scenario has none.
    #[wasm_bindgen(unchecked_return_type = "ExerciseView | null")]
    pub fn exercise(&self) -> Result<JsValue, JsValue> {
        value(&self.session.exercise_view())
    }

    /// The telemetry history as CSV (header first).
    pub fn telemetry_csv(&self) -> String {
        self.session.telemetry_csv()
    }

    /// The set-up (scenario, start and goal, map edits, changed parameters) as a URL-safe
    /// token. While the robot stands, this page restarts its set-up from the token, so it
    /// shows what the link opens with.
    pub fn share_token(&mut self) -> Result<String, JsValue> {
        let r = self.session.share_token();
        self.changed(r).map_err(js)
    }

    /// The scenario a share token was made for.
    pub fn share_scenario(token: &str) -> Result<String, JsValue> {
        Session::share_scenario(token).map_err(|e| js(refused(e)))
    }

    /// Replays a share token's set-up on the scenario loaded (it must be the token's).
    /// On an error nothing changes.
    pub fn apply_share(&mut self, token: &str) -> Result<(), JsValue> {
        self.session
            .apply_share(token)
            .map_err(|e| js(refused(e)))?;
        self.screen.replaced(&self.session);
        Ok(())
    }
}
