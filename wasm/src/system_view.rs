//! The System view's requests (issue 19): the system's own description, live, and the cut
//! and restore of a connection — each one call into the core.

use rtnav::system::Input;
use wasm_bindgen::prelude::*;

use crate::demo::{Demo, json};
use crate::js;

#[wasm_bindgen]
impl Demo {
    /// The system's description ([`rtnav::system::SystemGraph`]) as JSON: `{time,
    /// components: [{name, instance_name, rtc, state, rate_hz, ports: [{name, kind,
    /// interface, operations, count, last: {tm, text}}]}], connections: [{id, kind, from,
    /// to, interface, carried, cut, cuttable}]}`.
    pub fn system_json(&self) -> Result<String, JsValue> {
        json(&self.0.system().wiring().graph())
    }

    /// Cuts the data connection `id` (`DriveControl.TargetVelocity->MotorControl.TargetVelocity`):
    /// logged; refused with the reason for an unknown id, a connection to InventGUI or one
    /// already cut.
    pub fn cut_connection(&mut self, id: &str) -> Result<(), JsValue> {
        self.0
            .apply(&Input::CutConnection {
                connection: id.to_owned(),
            })
            .map_err(js)
    }

    /// Restores the cut data connection `id`: logged; refused if it is not cut.
    pub fn restore_connection(&mut self, id: &str) -> Result<(), JsValue> {
        self.0
            .apply(&Input::RestoreConnection {
                connection: id.to_owned(),
            })
            .map_err(js)
    }
}
