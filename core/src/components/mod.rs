//! The RT-components, one per file, named as in the seeds (SPEC §0).

// --- motion: MotorControl (002), the physics, DriveControl, Localization (SPEC §4, §5) ---
mod drive_control;
mod localization;
mod motor_control;
mod physics_sim;

pub use drive_control::{DriveControl, DriveControlParams, DriveStatus};
pub use localization::{Localization, LocalizationMode, LocalizationParams};
pub use motor_control::{
    INPUT_TIMEOUT_NS, MotorControl, MotorControlParams, MotorGeometry, MotorStatus,
};
pub use physics_sim::{PhysicsSim, PhysicsSimParams};

// --- LocalPathPlanning (branch `local`) ---
pub mod local_path_planning;
pub use local_path_planning::{LocalPathFlags, LocalPathPlanning, LocalPathPlanningParams};

// Demo component for the browser page until the robot system exists (tooling issue).
pub mod heartbeat;
pub use heartbeat::{Heartbeat, HeartbeatParams};

// --- maps: GlobalPathPlanning ---
mod global_path_planning;
pub use global_path_planning::{GlobalPathPlanning, GlobalPathPlanningParams};

// --- system: MapBuilder / MapMaintenance (SPEC §5) ---
mod map_builder;
mod map_maintenance;

pub use map_builder::{MapBuilder, SetMapMessage};
pub use map_maintenance::{MapMaintenance, MapUpdate};
