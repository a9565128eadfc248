//! The System view's requests: the system's own description, live, and the cut and
//! restore of a connection — each one call into the core's
//! [`Session`](rtnav::system::Session).

use rtnav::system::Input;
use wasm_bindgen::prelude::*;

use crate::demo::Demo;
use crate::{js, value};

#[wasm_bindgen]
impl Demo {
    /// The system's description ([`rtnav::system::SystemGraph`]): its components with their
    /// ports and newest samples, and the connections.
    #[wasm_bindgen(unchecked_return_type = "SystemGraph")]
    pub fn system_graph(&self) -> Result<JsValue, JsValue> {
        value(&self.session.graph())
    }

    /// Cuts the data connection `id` (`DriveControl.TargetVelocity->MotorControl.TargetVelocity`):
    /// logged; refused with the reason for an unknown id, a connection to InventGUI or one
    /// already cut.
    pub fn cut_connection(&mut self, id: &str) -> Result<(), JsValue> {
        let r = self.session.apply(&Input::CutConnection {
            connection: id.to_owned(),
        });
        self.changed(r).map_err(js)
    }

    /// Restores the cut data connection `id`: logged; refused if it is not cut.
    pub fn restore_connection(&mut self, id: &str) -> Result<(), JsValue> {
        let r = self.session.apply(&Input::RestoreConnection {
            connection: id.to_owned(),
        });
        self.changed(r).map_err(js)
    }
}
