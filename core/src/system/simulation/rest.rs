//! Whether the robot moves, as measured, and how close to its goal it must rest to have
//! arrived: the one place the thresholds of rest and the arrival tolerances are (spec §7
//! Decisions 0.3 "arrival" and "motion words").
//!
//! - **At rest**: the physics' measured speed below [`REST_SPEED`] and its turn rate below
//!   [`REST_TURN_RATE`]. A physics that does not execute (Inactive, Error) moves nothing:
//!   its measured motion is zero whatever speed its state held when it stopped.
//! - **Motion words** ([`Motion`]): the robot *stands* at rest; it *drives* or *turns* when
//!   it moves while DriveControl commands motion and MotorControl runs; otherwise it moves
//!   with nothing driving it: it *coasts* (rolls on, or is braked to a stop).
//! - **Arrival tolerances** ([`Tolerances`]): one map cell (`GridSize`, LocalPathPlanning's
//!   own arrival distance, 000 §5.2.4.4) and [`ARRIVAL_HEADING_DEG`].

use serde::Serialize;

use super::wiring::Wiring;
use crate::components::MotorStatus;
use crate::interfaces::Pose;
use crate::motion::angle_diff;
use crate::rtc::LifecycleState;
use crate::system::vocabulary::kind::ComponentKind;

/// Below this measured speed \[m/s\] (and [`REST_TURN_RATE`]) the robot is at rest.
pub const REST_SPEED: f64 = 0.01;
/// Below this measured turn rate \[rad/s\] (and [`REST_SPEED`]) the robot is at rest.
pub const REST_TURN_RATE: f64 = 0.01;
/// Arrival: the heading within this many degrees of the goal's.
pub const ARRIVAL_HEADING_DEG: f64 = 10.0;

/// The robot's measured motion: the physics' body speed and turn rate, zero while the
/// physics does not execute.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Measured {
    /// Speed \[m/s\] (negative backward).
    pub v: f64,
    /// Turn rate \[rad/s\] (counter-clockwise positive).
    pub w: f64,
}

impl Measured {
    /// The motion of the robot of `wiring` now.
    pub fn of(wiring: &Wiring) -> Self {
        if wiring.component_state(ComponentKind::PhysicsSim) != LifecycleState::Active {
            return Self { v: 0.0, w: 0.0 };
        }
        let (v, w) = wiring.physics().physics().body_velocity();
        Self { v, w }
    }

    /// Whether both are below the thresholds of rest.
    pub fn at_rest(&self) -> bool {
        self.v.abs() < REST_SPEED && self.w.abs() < REST_TURN_RATE
    }
}

/// What the robot does, from its measured motion (module documentation).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Motion {
    /// At rest.
    Stands,
    /// Moves along, driven by DriveControl's command.
    Drives,
    /// Turns on the spot (speed below [`REST_SPEED`]), driven by DriveControl's command.
    Turns,
    /// Moves with nothing driving it: no command, or a component of the drive not running.
    Coasts,
}

impl Motion {
    /// The motion of the robot of `wiring` now.
    pub fn of(wiring: &Wiring) -> Self {
        let m = Measured::of(wiring);
        if m.at_rest() {
            Self::Stands
        } else if !driven(wiring) {
            Self::Coasts
        } else if m.v.abs() < REST_SPEED {
            Self::Turns
        } else {
            Self::Drives
        }
    }

    /// Whether the robot moves.
    pub fn moves(self) -> bool {
        self != Self::Stands
    }
}

/// Whether DriveControl commands motion: it is Active and its last command is not zero.
pub fn commanded(wiring: &Wiring) -> bool {
    let (v, w) = wiring.drive_command();
    wiring.component_state(ComponentKind::DriveControl) == LifecycleState::Active
        && (v != 0.0 || w != 0.0)
}

/// Whether the drive pushes the robot: DriveControl commands motion and MotorControl
/// (Active, running) turns that command into torque on an executing physics.
fn driven(wiring: &Wiring) -> bool {
    let active = |k: ComponentKind| wiring.component_state(k) == LifecycleState::Active;
    active(ComponentKind::PhysicsSim)
        && active(ComponentKind::MotorControl)
        // A script in MotorControl's place runs while it is Active.
        && wiring
            .motor_control()
            .is_none_or(|m| *m.status() == MotorStatus::Running)
        && commanded(wiring)
}

/// How close to a goal the robot must rest to have arrived.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tolerances {
    /// Distance from the goal \[m\]: one cell of the map.
    pub position: f64,
    /// Heading error \[rad\]: [`ARRIVAL_HEADING_DEG`].
    pub heading: f64,
}

impl Tolerances {
    /// The tolerances on the map of `wiring` (`None` without a map).
    pub fn of(wiring: &Wiring) -> Option<Self> {
        wiring.map().map(|m| Self {
            position: m.grid_size(),
            heading: ARRIVAL_HEADING_DEG.to_radians(),
        })
    }
}

/// How far a pose is from a goal: distance \[m\] and absolute heading error \[rad\].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Offset {
    /// Straight distance \[m\].
    pub distance: f64,
    /// Absolute heading error \[rad\], in \[0, π\].
    pub heading_error: f64,
}

impl Offset {
    /// From `pose` to `goal`.
    pub fn between(pose: Pose, goal: Pose) -> Self {
        Self {
            distance: libm::hypot(pose.x - goal.x, pose.y - goal.y),
            heading_error: angle_diff(pose.theta, goal.theta).abs(),
        }
    }

    /// Whether it is within `tolerances`.
    pub fn within(&self, tolerances: Tolerances) -> bool {
        self.distance <= tolerances.position && self.heading_error <= tolerances.heading
    }
}
