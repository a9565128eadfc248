//! A build without the feature `script` (the page's first download keeps the engine out):
//! no component a student writes can exist. [`ScriptComponent`] has no value here — the
//! [`Program`] it would run cannot be made ([`Program::compile`] refuses, saying why) — so
//! every path of the system that reads one is never taken.

use super::{MotorControlParams, ScriptPlace};
use crate::rtc::{Component, ConfigAccess, Tick};
use crate::script::{Console, Program, ScriptError};

/// The script component, absent from this build (module documentation).
#[derive(Debug, Clone)]
pub enum ScriptComponent {}

impl ScriptComponent {
    /// As the build with scripts has it; `program` cannot exist here.
    pub fn new(
        _place: ScriptPlace,
        _name: &str,
        program: Program,
        _from: Option<&dyn ConfigAccess>,
        _now: Tick,
    ) -> Self {
        match program {}
    }
    /// The place it stands in.
    pub fn place(&self) -> ScriptPlace {
        match *self {}
    }
    /// MotorControl's parameters in effect.
    pub fn motor_params(&self) -> Option<&MotorControlParams> {
        match *self {}
    }
    /// The script.
    pub fn program(&self) -> &Program {
        match *self {}
    }
    /// A pair its state keeps.
    pub fn state_pair(&self, _key: &str) -> Option<[f64; 2]> {
        match *self {}
    }
    /// The console.
    pub fn console(&self) -> &Console {
        match *self {}
    }
    /// The last failure of an action.
    pub fn last_error(&self) -> Option<&ScriptError> {
        match *self {}
    }
    /// The last `TargetVelocity` written.
    pub fn last_command(&self) -> Option<(f64, f64)> {
        match *self {}
    }
    /// Since when it has commanded nothing.
    pub fn standing_since(&self) -> Option<u64> {
        match *self {}
    }
    /// The last `OutDeviating` written.
    pub fn last_deviation(&self) -> Option<f64> {
        match *self {}
    }
    /// The end of the newest control points.
    pub fn path_end(&self) -> Option<(f64, f64)> {
        match *self {}
    }
    /// The last `Torque` written, at the wheel ids.
    pub fn last_torque(&self, _left: usize, _right: usize) -> Option<[f64; 2]> {
        match *self {}
    }
}

impl Component for ScriptComponent {
    fn instance_name(&self) -> &str {
        match *self {}
    }
}
