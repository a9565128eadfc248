//! The teaching tools' requests (issue 8): parameters, `SetPDGain`, plots, share links and
//! the telemetry CSV — each one call into the core's [`Session`](rtnav::system::Session).

use rtnav::system::{ComponentKind, Input, Session};
use wasm_bindgen::prelude::*;

use crate::demo::{Demo, json};
use crate::{js, refused};

#[wasm_bindgen]
impl Demo {
    /// Every parameter of LocalPathPlanning, MotorControl, DriveControl and PhysicsSim as
    /// JSON `[{component, instance_name, params: [{name, type, unit, default, min, max,
    /// range, reflection, description, value, effective, pending}]}]`.
    pub fn params_json(&self) -> Result<String, JsValue> {
        json(&self.0.session.parameters_view())
    }

    /// Sets a parameter from text: `always` at once, `on_activation` pending until the next
    /// activation; refused (the old value stays) with the reason for an unknown name, a value
    /// that is not a number, or one out of range.
    pub fn set_param(&mut self, component: &str, name: &str, text: &str) -> Result<(), JsValue> {
        let kind = ComponentKind::from_name(component).map_err(|e| js(refused(e)))?;
        let r = self.0.session.set_param_text(kind, name, text);
        self.0.changed(r).map_err(js)
    }

    /// MotorControl's `Motor::SetPDGain(PGainL, PGainR, DGainL, DGainR)`; all four checked
    /// first, nothing changes on an error.
    pub fn set_pd_gain(&mut self, p_l: f64, p_r: f64, d_l: f64, d_r: f64) -> Result<(), JsValue> {
        self.0
            .apply(&Input::SetPdGain { p_l, p_r, d_l, d_r })
            .map_err(js)
    }

    /// The whole configuration (every component that has parameters) as one OpenRTM
    /// `.conf` text: a block per component after its marker line `# [InstanceName]`.
    pub fn conf_export(&self) -> String {
        self.0.system().wiring().to_conf()
    }

    /// Replaces the configuration from a `.conf` text as [`Demo::conf_export`] writes it;
    /// all-or-nothing, refused with the line and the problem.
    pub fn conf_import(&mut self, text: &str) -> Result<(), JsValue> {
        self.0
            .apply(&Input::LoadConf {
                text: text.to_owned(),
            })
            .map_err(js)
    }

    /// The cell `(x, y)` explained as JSON `{x, y, occupancy, obstacle_distance, impassable,
    /// field: null | {potential, repulsion, attraction, posture, state, unreached}}` — the
    /// same numbers `rtnav inspect` prints natively. A cell outside the map is an error.
    pub fn inspect_cell(&self, x: i32, y: i32) -> Result<String, JsValue> {
        let cell = self
            .0
            .system()
            .wiring()
            .inspect_cell(i64::from(x), i64::from(y))
            .map_err(|e| js(refused(e)))?;
        json(&cell)
    }

    /// The last `seconds` (≤ 60) of telemetry as JSON arrays `{t, target_rate_l, …,
    /// deviation, deviatinglen, replans}`.
    pub fn plot_json(&self, seconds: f64) -> Result<String, JsValue> {
        json(&self.0.session.plot(seconds))
    }

    /// The telemetry history as CSV (header first).
    pub fn telemetry_csv(&self) -> String {
        self.0.system().record().telemetry().to_csv()
    }

    /// The set-up (scenario, start and goal, map edits, changed parameters) as a URL-safe
    /// token. While the robot stands, this page restarts its set-up from the token, so it
    /// shows what the link opens with.
    pub fn share_token(&mut self) -> Result<String, JsValue> {
        let r = self.0.session.share_token();
        self.0.changed(r).map_err(js)
    }

    /// The scenario a share token was made for.
    pub fn share_scenario(token: &str) -> Result<String, JsValue> {
        Session::share_scenario(token).map_err(|e| js(refused(e)))
    }

    /// Replays a share token's set-up on the scenario loaded (it must be the token's).
    /// On an error nothing changes.
    pub fn apply_share(&mut self, token: &str) -> Result<(), JsValue> {
        let r = self.0.session.apply_share(token);
        let r = self.0.changed(r);
        if r.is_ok() {
            self.0.replaced();
        }
        r.map_err(js)
    }
}
