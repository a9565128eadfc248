//! The robot's motion: differential-drive kinematics and the physics that replaces OpenHRP3
//! (spec §4, §5).
//!
//! Everything here is pure: explicit inputs, explicit time steps, no clock, `libm` for every
//! transcendental function (spec §6). The RT-components that use it live in
//! `crate::components` (`MotorControl`, `PhysicsSim`, `DriveControl`, `Localization`).
//!
//! Architecture invariant: this module knows nothing of ports, ticks or the lifecycle.

mod error;
pub use error::MotionError;

mod collision;
mod diff_drive;
mod model_frame;
mod odometry;
mod physics;
mod pure_pursuit;

pub use collision::free_travel;
pub use diff_drive::{DiffDrive, angle_diff, arc_step, wrap_angle};
pub use model_frame::{ModelFrame, TRANSFORM_LEN};
pub use odometry::Odometry;
pub use physics::{
    BumpReport, CONTACT_RELEASE, DEFAULT_MASS, DEFAULT_MAX_TORQUE, DEFAULT_VISCOUS_FRICTION,
    DEFAULT_YAW_INERTIA, Physics, PhysicsParams, PhysicsState, STEP_NS, STEP_S,
};
pub use pure_pursuit::{
    DrivePhase, Polyline, Projection, PurePursuit, PursuitCommand, PursuitParams,
};
