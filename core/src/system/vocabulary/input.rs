//! [`Input`]: every request a person (InventGUI, the page, a scenario's timeline) can make of
//! the system, as one value. [`System::apply`](crate::system::System::apply) is the one interpreter;
//! a run is fully described by its set-up and its timed inputs (spec §6).

use core::fmt;

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
    /// Put a student's script in a component's place (spec §8): compiled, then its
    /// `on_initialize` run; refused while the component is Active.
    LoadScript {
        /// Whose place: DriveControl or MotorControl.
        component: ComponentKind,
        /// The script's name (a file name, for people).
        name: String,
        /// The script's text.
        source: String,
    },
    /// Put the built-in component back in its place (spec §8).
    UseBuiltIn {
        /// Whose place.
        component: ComponentKind,
    },
}

impl Input {
    /// What was asked, as data: the request's kind and the fields that say which one, without
    /// its payload ([`InputSummary`]).
    pub fn summary(&self) -> InputSummary {
        match self {
            Self::SetPosition { .. } => InputSummary::SetPosition,
            Self::SetGoal { .. } => InputSummary::SetGoal,
            Self::MapUpdate { cells } => InputSummary::MapUpdate { cells: cells.len() },
            Self::Clear => InputSummary::Clear,
            Self::SafeMode => InputSummary::SafeMode,
            Self::Activate { component } => InputSummary::Activate {
                component: *component,
            },
            Self::Deactivate { component } => InputSummary::Deactivate {
                component: *component,
            },
            Self::Reset { component } => InputSummary::Reset {
                component: *component,
            },
            Self::ActivateAll => InputSummary::ActivateAll,
            Self::DeactivateAll => InputSummary::DeactivateAll,
            Self::ResetAll => InputSummary::ResetAll,
            Self::InjectFault { component, .. } => InputSummary::InjectFault {
                component: *component,
            },
            Self::InjectInput {
                component, port, ..
            } => InputSummary::InjectInput {
                component: *component,
                port: port.clone(),
            },
            Self::SetParam {
                component, name, ..
            } => InputSummary::SetParam {
                component: *component,
                name: name.clone(),
            },
            Self::SetPdGain { .. } => InputSummary::SetPdGain,
            Self::LoadConf { .. } => InputSummary::LoadConf,
            Self::SetRate { component, .. } => InputSummary::SetRate {
                component: *component,
            },
            Self::CutConnection { connection } => InputSummary::CutConnection {
                connection: connection.clone(),
            },
            Self::RestoreConnection { connection } => InputSummary::RestoreConnection {
                connection: connection.clone(),
            },
            Self::LoadScript {
                component, name, ..
            } => InputSummary::LoadScript {
                component: *component,
                name: name.clone(),
            },
            Self::UseBuiltIn { component } => InputSummary::UseBuiltIn {
                component: *component,
            },
        }
    }

    /// The request in a few words, for the log of a refused one (the English of
    /// [`Input::summary`]).
    pub fn describe(&self) -> String {
        self.summary().to_string()
    }
}

/// Which request an [`Input`] is, without its payload: what the log of a refused request
/// names. Serializes as `{"kind": "MapUpdate", "cells": 12}` (the [`Input`]'s `type`, in
/// `UpperCamelCase`), for a user interface to say in its own words (`input.<kind>`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
pub enum InputSummary {
    /// `SetPosition`.
    SetPosition,
    /// A new goal from where the robot is.
    SetGoal,
    /// A `MapUpdate` of this many cells.
    MapUpdate {
        /// Cells listed.
        cells: usize,
    },
    /// `Clear`.
    Clear,
    /// `SafeMode`.
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
    /// Reset one component.
    Reset {
        /// Which.
        component: ComponentKind,
    },
    /// Activate all.
    ActivateAll,
    /// Deactivate all.
    DeactivateAll,
    /// Reset all.
    ResetAll,
    /// A fault injected into a component.
    InjectFault {
        /// Which.
        component: ComponentKind,
    },
    /// A sample written into a component's input port.
    InjectInput {
        /// Which component.
        component: ComponentKind,
        /// Which port.
        port: String,
    },
    /// A configuration parameter set.
    SetParam {
        /// Whose.
        component: ComponentKind,
        /// Which.
        name: String,
    },
    /// MotorControl's `SetPDGain`.
    SetPdGain,
    /// A configuration bundle loaded.
    LoadConf,
    /// A component's rate set.
    SetRate {
        /// Whose.
        component: ComponentKind,
    },
    /// A data connection cut.
    CutConnection {
        /// The connection's id.
        connection: String,
    },
    /// A cut data connection restored.
    RestoreConnection {
        /// The connection's id.
        connection: String,
    },
    /// A student's script loaded into a component's place.
    LoadScript {
        /// Whose place.
        component: ComponentKind,
        /// The script's name.
        name: String,
    },
    /// The built-in component put back.
    UseBuiltIn {
        /// Whose place.
        component: ComponentKind,
    },
}

impl fmt::Display for InputSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::SetPosition => f.write_str("SetPosition"),
            Self::SetGoal => f.write_str("a new goal"),
            Self::MapUpdate { cells } => write!(f, "MapUpdate of {cells} cells"),
            Self::Clear => f.write_str("Clear"),
            Self::SafeMode => f.write_str("SafeMode"),
            Self::Activate { component } => write!(f, "activate {component}"),
            Self::Deactivate { component } => write!(f, "deactivate {component}"),
            Self::Reset { component } => write!(f, "reset {component}"),
            Self::ActivateAll => f.write_str("activate all"),
            Self::DeactivateAll => f.write_str("deactivate all"),
            Self::ResetAll => f.write_str("reset all"),
            Self::InjectFault { component } => write!(f, "inject a fault into {component}"),
            Self::InjectInput { component, port } => write!(f, "inject into {component}.{port}"),
            Self::SetParam { component, name } => write!(f, "{component}.{name}"),
            Self::SetPdGain => f.write_str("SetPDGain"),
            Self::LoadConf => f.write_str("loading the configuration"),
            Self::SetRate { component } => write!(f, "the rate of {component}"),
            Self::CutConnection { connection } => write!(f, "cut {connection}"),
            Self::RestoreConnection { connection } => write!(f, "restore {connection}"),
            Self::LoadScript { component, name } => {
                write!(f, "loading the script {name} into {component}")
            }
            Self::UseBuiltIn { component } => write!(f, "the built-in {component} back"),
        }
    }
}

/// Who made a request on someone's behalf (a refused one is logged naming it).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, strum::VariantNames)]
pub enum RequestSource {
    /// A scenario's timed events.
    Timeline,
    /// A replay played back.
    Replay,
}

impl fmt::Display for RequestSource {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Timeline => "the scenario's timeline",
            Self::Replay => "the replay",
        })
    }
}
