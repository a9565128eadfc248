//! [`Input`]: every request a person (InventGUI, the page, a scenario's timeline) can make of
//! the system, as one value. [`System::apply`](super::System::apply) is the one interpreter;
//! a run is fully described by its set-up and its timed inputs (spec §6).

use serde::{Deserialize, Serialize};

use super::kind::ComponentKind;
use crate::interfaces::{Direction, Pose};

/// One request to the system.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum Input {
    /// `SetPosition` (000 §3.2.2.1 (1)): place the robot at `start` and set the goal; refused
    /// while the robot drives.
    SetPosition {
        /// Where the robot is placed.
        start: Pose,
        /// The goal.
        goal: Pose,
        /// Forward or backward.
        direction: Direction,
    },
    /// A new goal from where the robot is (its estimate while driving).
    SetGoal {
        /// The goal.
        goal: Pose,
        /// Forward or backward.
        direction: Direction,
    },
    /// `MapUpdate` of cells `(x, y, value)`, 0 free / 1 obstacle (spec §2).
    MapUpdate {
        /// The cells.
        cells: Vec<(i64, i64, i16)>,
    },
    /// `Clear` (000 §5.2.4.7).
    Clear,
    /// `SafeMode` (spec §3 Decision).
    SafeMode,
    /// Activate one component.
    Activate {
        /// Which.
        component: ComponentKind,
    },
    /// Deactivate one component.
    Deactivate {
        /// Which.
        component: ComponentKind,
    },
    /// Reset one component in Error.
    Reset {
        /// Which.
        component: ComponentKind,
    },
    /// Activate every Inactive component, in attachment order.
    ActivateAll,
    /// Deactivate every Active component, in reverse order.
    DeactivateAll,
    /// Reset every component in Error and deactivate the Active ones.
    ResetAll,
    /// Make a component's next execution fail.
    InjectFault {
        /// Which.
        component: ComponentKind,
        /// The reason it fails with.
        reason: String,
    },
    /// Write one sample into an input port (rtshell's `rtinject`).
    InjectInput {
        /// Which component.
        component: ComponentKind,
        /// Which port.
        port: String,
        /// The sample's data.
        data: Vec<f64>,
    },
    /// Set one configuration parameter (spec §1; `dmin` is one value, spec §3 Decision 0.2).
    SetParam {
        /// Whose.
        component: ComponentKind,
        /// The seed's name.
        name: String,
        /// The value.
        value: f64,
    },
    /// MotorControl's `SetPDGain(PGainL, PGainR, DGainL, DGainR)` (002 §3.2.2.1 (1)).
    SetPdGain {
        /// `PGainL`.
        p_l: f64,
        /// `PGainR`.
        p_r: f64,
        /// `DGainL`.
        d_l: f64,
        /// `DGainR`.
        d_r: f64,
    },
    /// The whole configuration from one OpenRTM `.conf` bundle (all or nothing).
    LoadConf {
        /// The bundle's text.
        text: String,
    },
    /// A component's execution rate \[Hz\] (spec §6).
    SetRate {
        /// Whose.
        component: ComponentKind,
        /// The rate.
        hz: f64,
    },
    /// Cut a data connection between two components (RT System Editor's "delete
    /// connector"): `DriveControl.TargetVelocity->MotorControl.TargetVelocity`.
    CutConnection {
        /// The connection's id, as the system's description names it.
        connection: String,
    },
    /// Restore a cut data connection.
    RestoreConnection {
        /// The connection's id.
        connection: String,
    },
}

impl Input {
    /// The request in a few words, for the log of a refused one.
    pub fn describe(&self) -> String {
        match self {
            Self::SetPosition { .. } => "SetPosition".to_owned(),
            Self::SetGoal { .. } => "a new goal".to_owned(),
            Self::MapUpdate { cells } => format!("MapUpdate of {} cells", cells.len()),
            Self::Clear => "Clear".to_owned(),
            Self::SafeMode => "SafeMode".to_owned(),
            Self::Activate { component } => format!("activate {component}"),
            Self::Deactivate { component } => format!("deactivate {component}"),
            Self::Reset { component } => format!("reset {component}"),
            Self::ActivateAll => "activate all".to_owned(),
            Self::DeactivateAll => "deactivate all".to_owned(),
            Self::ResetAll => "reset all".to_owned(),
            Self::InjectFault { component, .. } => format!("inject a fault into {component}"),
            Self::InjectInput {
                component, port, ..
            } => format!("inject into {component}.{port}"),
            Self::SetParam {
                component, name, ..
            } => format!("{component}.{name}"),
            Self::SetPdGain { .. } => "SetPDGain".to_owned(),
            Self::LoadConf { .. } => "loading the configuration".to_owned(),
            Self::SetRate { component, .. } => format!("the rate of {component}"),
            Self::CutConnection { connection } => format!("cut {connection}"),
            Self::RestoreConnection { connection } => format!("restore {connection}"),
        }
    }
}
