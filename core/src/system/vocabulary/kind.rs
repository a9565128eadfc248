//! Which component: the system's eight RT-components, in attachment (data-flow) order.

use core::fmt;

use serde::{Deserialize, Serialize};

use crate::errors::SystemError;

/// One of the system's components (spec §0). The order of [`ComponentKind::ALL`] is the
/// attachment order, which is the order they run in a tick (see `crate::system`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub enum ComponentKind {
    /// Holds the loaded map; sends `SetMap`.
    MapBuilder,
    /// Run-time map changes; sends `MapUpdate`.
    MapMaintenance,
    /// The physics in place of OpenHRP3.
    PhysicsSim,
    /// Wheel PD torque control (seed 002).
    MotorControl,
    /// The robot pose (simulated pose or odometry).
    Localization,
    /// A* on the grid; sends `GlobalPathCourse`.
    GlobalPathPlanning,
    /// The potential-field local planner (seed 000).
    LocalPathPlanning,
    /// Pure pursuit along the control points; sends `TargetVelocity`.
    DriveControl,
}

impl ComponentKind {
    /// Every component, in attachment order.
    pub const ALL: [Self; 8] = [
        Self::MapBuilder,
        Self::MapMaintenance,
        Self::PhysicsSim,
        Self::MotorControl,
        Self::Localization,
        Self::GlobalPathPlanning,
        Self::LocalPathPlanning,
        Self::DriveControl,
    ];

    /// The components a plan needs, without the robot moving (the preview): map, planners.
    pub const PLANNING: [Self; 4] = [
        Self::MapBuilder,
        Self::MapMaintenance,
        Self::GlobalPathPlanning,
        Self::LocalPathPlanning,
    ];

    /// The components that hold `dmin`: one value for the system (spec §3 Decision 0.2).
    pub const DMIN_HOLDERS: [Self; 2] = [Self::LocalPathPlanning, Self::GlobalPathPlanning];

    /// Whether the component holds `dmin` ([`ComponentKind::DMIN_HOLDERS`]).
    pub fn holds_dmin(self) -> bool {
        Self::DMIN_HOLDERS.contains(&self)
    }

    /// The component's name as in the seeds and spec §0 (e.g. `LocalPathPlanning`).
    pub fn name(self) -> &'static str {
        match self {
            Self::MapBuilder => "MapBuilder",
            Self::MapMaintenance => "MapMaintenance",
            Self::PhysicsSim => "PhysicsSim",
            Self::MotorControl => "MotorControl",
            Self::Localization => "Localization",
            Self::GlobalPathPlanning => "GlobalPathPlanning",
            Self::LocalPathPlanning => "LocalPathPlanning",
            Self::DriveControl => "DriveControl",
        }
    }

    /// The instance name in the execution context (OpenRTM style: `LocalPathPlanning0`).
    pub fn instance_name(self) -> &'static str {
        match self {
            Self::MapBuilder => "MapBuilder0",
            Self::MapMaintenance => "MapMaintenance0",
            Self::PhysicsSim => "PhysicsSim0",
            Self::MotorControl => "MotorControl0",
            Self::Localization => "Localization0",
            Self::GlobalPathPlanning => "GlobalPathPlanning0",
            Self::LocalPathPlanning => "LocalPathPlanning0",
            Self::DriveControl => "DriveControl0",
        }
    }

    /// The component's index in [`ComponentKind::ALL`] (also its execution-context id).
    pub fn index(self) -> usize {
        self as usize
    }

    /// The component named `name` (its name or its instance name).
    pub fn from_name(name: &str) -> Result<Self, SystemError> {
        Self::ALL
            .into_iter()
            .find(|k| k.name() == name || k.instance_name() == name)
            .ok_or_else(|| SystemError::UnknownComponent {
                name: crate::present::excerpt(name),
                expected: Self::ALL.map(Self::name).join(", "),
            })
    }
}

impl fmt::Display for ComponentKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
