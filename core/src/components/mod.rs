//! The RT-components, one per file, named as in the seeds (spec §0).

mod drive_control;
mod localization;
mod motor_control;
mod physics_sim;

pub use drive_control::{DriveControl, DriveControlParams, DriveStatus};
pub use localization::{Localization, LocalizationMode, LocalizationParams};
pub use motor_control::{
    GainWarning, INPUT_TIMEOUT_NS, MotorControl, MotorControlParams, MotorGeometry, MotorStatus,
};
pub use physics_sim::{PhysicsSim, PhysicsSimParams};

pub mod local_path_planning;
pub use local_path_planning::{
    FIELD_CELLS_PER_EXECUTION, LocalPathFlags, LocalPathPlanning, LocalPathPlanningParams, RETRY_NS,
};

mod global_path_planning;
pub use global_path_planning::{GlobalPathPlanning, GlobalPathPlanningParams, PlanReason};

mod map_builder;
mod map_maintenance;
mod samples;

pub use map_builder::{MapBuilder, SetMapMessage};
pub use map_maintenance::MapMaintenance;
