//! What the system is doing, from its facts: the whole system's lifecycle state
//! ([`SystemState`]), each component as the RTC panel shows it ([`ComponentInfo`]), and the
//! robot's status in words ([`Status`]) — "driving" only while DriveControl commands motion
//! and the robot moves, otherwise what is true.

use core::fmt;

use serde::Serialize;

use super::kind::ComponentKind;
use super::mission::Mission;
use super::wiring::Wiring;
use crate::components::{DriveStatus, MotorStatus};
use crate::interfaces::Direction;
use crate::motion::DrivePhase;
use crate::present::fixed;
use crate::rtc::LifecycleState;

/// Below this speed \[m/s\] and turn rate \[rad/s\] the robot stands still.
pub const STILL: f64 = 1e-3;

/// The whole system's state, from its components' states.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub enum SystemState {
    /// Every component Inactive.
    Inactive,
    /// Every component Active.
    Active,
    /// Some Active, some Inactive, none in Error (e.g. only the planners, before the drive).
    Partial,
    /// At least one component in Error (e.g. after a bump): Reset recovers.
    Error,
}

impl SystemState {
    /// The state of the components of `wiring`.
    pub fn of(wiring: &Wiring) -> Self {
        let mut active = 0;
        for kind in ComponentKind::ALL {
            match wiring.component_state(kind) {
                LifecycleState::Active => active += 1,
                LifecycleState::Error => return Self::Error,
                _ => {}
            }
        }
        if active == ComponentKind::ALL.len() {
            Self::Active
        } else if active == 0 {
            Self::Inactive
        } else {
            Self::Partial
        }
    }
}

impl fmt::Display for SystemState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Inactive => "Inactive",
            Self::Active => "Active",
            Self::Partial => "Partial",
            Self::Error => "Error",
        })
    }
}

/// What the robot is doing, in words a person can check against the picture.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Status {
    /// No map is loaded.
    NoMap,
    /// A map, but no goal.
    NoGoal,
    /// A component is in Error (a bump puts the physics there): Reset recovers.
    ComponentError {
        /// The component's instance name.
        component: String,
        /// Its reason.
        reason: String,
    },
    /// SafeMode or Clear halted the robot until the next goal.
    Halted {
        /// `SafeMode` or `Clear`.
        by: String,
    },
    /// At the goal, with the goal heading.
    Arrived,
    /// GlobalPathPlanning found no route to the goal (it tries again when the map changes).
    NoRoute {
        /// Why.
        reason: String,
    },
    /// A goal is held and no plan has reached DriveControl yet; after a failed local plan,
    /// LocalPathPlanning tries again every second (spec §3 Decision 0.2).
    WaitingForPlan {
        /// The failure that is being retried, if any.
        retrying: Option<String>,
    },
    /// The plan is ready; the robot's components wait for activation.
    Ready,
    /// The physics runs but MotorControl does not: no torque, the robot coasts.
    Coasting,
    /// A component the drive needs is not Active (the robot holds still or coasts).
    Inactive {
        /// The component's instance name.
        component: String,
    },
    /// A controller stopped the robot and says why (MotorControl's or DriveControl's safe
    /// stop, DriveControl's collision check).
    SafeStop {
        /// The component's instance name.
        component: String,
        /// Why.
        reason: String,
    },
    /// DriveControl commands motion and the robot moves along the path.
    Driving {
        /// Forward or backward.
        direction: Direction,
    },
    /// Turning on the spot towards the path.
    TurningOnTheSpot,
    /// At the goal, turning to the goal heading.
    TurningToGoalHeading,
    /// The robot moves, but not as commanded (e.g. gains that make the wheel loop unstable).
    OffCommand {
        /// Commanded speed \[m/s\].
        v_cmd: f64,
        /// Commanded turn rate \[rad/s\].
        w_cmd: f64,
        /// Actual speed \[m/s\].
        v: f64,
        /// Actual turn rate \[rad/s\].
        w: f64,
    },
    /// Everything runs, nothing is commanded: the robot stands.
    Standing,
}

impl Status {
    /// The status now of the system whose wiring is `w` and mission `m`
    /// ([`System::status`](super::System::status)).
    pub fn of(w: &Wiring, m: &Mission) -> Self {
        if w.map().is_none() {
            return Self::NoMap;
        }
        if let Some(kind) = ComponentKind::ALL
            .into_iter()
            .find(|&k| w.component_state(k) == LifecycleState::Error)
        {
            let id = kind.index();
            let reason = w
                .execution_context()
                .last_error(id)
                .ok()
                .flatten()
                .unwrap_or("")
                .to_owned();
            return Self::ComponentError {
                component: kind.instance_name().to_owned(),
                reason,
            };
        }
        if m.is_halted() {
            let by = if w.local_path_planning().flags().safe_mode {
                "SafeMode"
            } else {
                "Clear"
            };
            return Self::Halted { by: by.to_owned() };
        }
        if m.goal().is_none() {
            return Self::NoGoal;
        }
        if m.is_arrived() {
            return Self::Arrived;
        }
        let lpp = w.local_path_planning();
        if lpp.retry_at_ns().is_some() {
            return Self::WaitingForPlan {
                retrying: lpp.last_failure().map(|f| f.reason.clone()),
            };
        }
        if let Some(e) = w.global_path_planning().last_error()
            && !w.global_path_planning().is_requested()
        {
            return Self::NoRoute {
                reason: e.to_string(),
            };
        }
        if !m.plan_sent() {
            return Self::WaitingForPlan { retrying: None };
        }
        let active = |k: ComponentKind| w.component_state(k) == LifecycleState::Active;
        if !active(ComponentKind::PhysicsSim) {
            return Self::Ready;
        }
        if !active(ComponentKind::MotorControl) {
            return Self::Coasting;
        }
        for k in [ComponentKind::Localization, ComponentKind::DriveControl] {
            if !active(k) {
                return Self::Inactive {
                    component: k.instance_name().to_owned(),
                };
            }
        }
        if let MotorStatus::SafeStop(e) = w.motor_control().status() {
            return Self::SafeStop {
                component: ComponentKind::MotorControl.instance_name().to_owned(),
                reason: e.to_string(),
            };
        }
        let drive = w.drive_control();
        match drive.status() {
            DriveStatus::SafeStop(e) => {
                return Self::SafeStop {
                    component: ComponentKind::DriveControl.instance_name().to_owned(),
                    reason: e.to_string(),
                };
            }
            DriveStatus::SafetyStop { ahead } => {
                return Self::SafeStop {
                    component: ComponentKind::DriveControl.instance_name().to_owned(),
                    reason: format!("obstacle {} m ahead", fixed(*ahead, 2)),
                };
            }
            _ => {}
        }
        let (v_cmd, w_cmd) = drive.pursuit().last_command();
        let (v, om) = w.physics().physics().body_velocity();
        let moving = v.abs() >= STILL || om.abs() >= STILL;
        let commanded = v_cmd != 0.0 || w_cmd != 0.0;
        if moving && ((v - v_cmd).abs() > 0.25 || (om - w_cmd).abs() > 1.0) {
            return Self::OffCommand {
                v_cmd,
                w_cmd,
                v,
                w: om,
            };
        }
        if !(moving && commanded) {
            return Self::Standing;
        }
        match drive.pursuit().phase() {
            DrivePhase::TurnInPlace => Self::TurningOnTheSpot,
            DrivePhase::FinalTurn => Self::TurningToGoalHeading,
            _ => Self::Driving {
                direction: lpp.direction(),
            },
        }
    }
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoMap => f.write_str("no map loaded"),
            Self::NoGoal => f.write_str("no goal: set start and goal"),
            Self::ComponentError { component, reason } => {
                write!(f, "{component} in Error: {reason} (Reset recovers)")
            }
            Self::Halted { by } => write!(f, "halted by {by} until the next goal"),
            Self::Arrived => f.write_str("arrived"),
            Self::NoRoute { reason } => write!(f, "stopped: no route ({reason})"),
            Self::WaitingForPlan { retrying: None } => f.write_str("waiting for a plan"),
            Self::WaitingForPlan {
                retrying: Some(reason),
            } => write!(f, "waiting for a plan (retrying every second: {reason})"),
            Self::Ready => f.write_str("plan ready: activate the robot's components"),
            Self::Coasting => f.write_str("MotorControl inactive: coasting"),
            Self::Inactive { component } => write!(f, "{component} inactive: the robot stands"),
            Self::SafeStop { component, reason } => {
                write!(f, "safety stop ({component}): {reason}")
            }
            Self::Driving {
                direction: Direction::Forward,
            } => f.write_str("driving forward"),
            Self::Driving {
                direction: Direction::Backward,
            } => f.write_str("driving backward"),
            Self::TurningOnTheSpot => f.write_str("turning on the spot"),
            Self::TurningToGoalHeading => f.write_str("turning to the goal heading"),
            Self::OffCommand { v_cmd, w_cmd, v, w } => write!(
                f,
                "not following the command: v {} m/s, ω {} rad/s (commanded {} m/s, {} rad/s)",
                fixed(*v, 2),
                fixed(*w, 2),
                fixed(*v_cmd, 2),
                fixed(*w_cmd, 2)
            ),
            Self::Standing => f.write_str("standing"),
        }
    }
}

/// One component as the GUI's RTC panel shows it.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ComponentInfo {
    /// Which component.
    pub kind: ComponentKind,
    /// Its instance name.
    pub instance_name: String,
    /// Its lifecycle state.
    pub state: LifecycleState,
    /// Its rate \[Hz\].
    pub rate: f64,
    /// The reason of its last callback failure (kept until a reset succeeds).
    pub last_error: Option<String>,
    /// What it is doing, in a few words.
    pub status: String,
}

impl ComponentInfo {
    /// Component `kind` of `wiring` now.
    pub fn of(wiring: &Wiring, kind: ComponentKind) -> Self {
        let id = kind.index();
        let ec = wiring.execution_context();
        Self {
            kind,
            instance_name: kind.instance_name().to_owned(),
            state: wiring.component_state(kind),
            rate: ec.rate(id).unwrap_or(f64::NAN),
            last_error: ec.last_error(id).ok().flatten().map(str::to_owned),
            status: component_status(wiring, kind),
        }
    }

    /// Every component of `wiring`, in attachment order.
    pub fn all(wiring: &Wiring) -> Vec<Self> {
        ComponentKind::ALL
            .into_iter()
            .map(|k| Self::of(wiring, k))
            .collect()
    }
}

fn plural(n: u64, one: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {one}s")
    }
}

fn component_status(w: &Wiring, kind: ComponentKind) -> String {
    // A component in Error does not execute (spec §1): what it held last is not what it does.
    if w.component_state(kind) == LifecycleState::Error {
        let ec = w.execution_context();
        return match ec.last_error(kind.index()).ok().flatten() {
            Some(reason) => format!("in Error, not executing: {reason}"),
            None => "in Error, not executing".to_owned(),
        };
    }
    match kind {
        ComponentKind::MapBuilder => match w.map_builder().map() {
            Some(m) => format!("map {}×{} at {} m", m.width(), m.height(), m.grid_size()),
            None => "no map".to_owned(),
        },
        ComponentKind::MapMaintenance => {
            format!(
                "{} sent",
                plural(w.map_maintenance().sent_count(), "update")
            )
        }
        ComponentKind::PhysicsSim => {
            let p = w.physics().physics();
            format!(
                "{}{}",
                plural(p.bump_count(), "bump"),
                if p.state().in_contact {
                    ", touching an obstacle"
                } else {
                    ""
                }
            )
        }
        ComponentKind::MotorControl => w.motor_control().status().to_string(),
        ComponentKind::Localization => {
            format!("{:?}", w.localization().config().params().mode())
        }
        ComponentKind::GlobalPathPlanning => {
            let g = w.global_path_planning();
            match (g.last_error(), g.path_length()) {
                (Some(e), _) => format!("failed: {e}"),
                (None, Some(l)) => format!("route of {} m", fixed(l, 2)),
                (None, None) => "no route".to_owned(),
            }
        }
        ComponentKind::LocalPathPlanning => {
            // The held flags of 000 §5.2.4, the ones that are set, and the plans made.
            let lpp = w.local_path_planning();
            let f = lpp.flags();
            let held: Vec<&str> = [
                (f.map, "map"),
                (f.position, "start and goal"),
                (f.path, "path"),
                (f.arrived, "arrived"),
                (f.safe_mode, "SafeMode"),
            ]
            .into_iter()
            .filter_map(|(on, name)| on.then_some(name))
            .collect();
            format!(
                "holds: {}; {} made{}",
                if held.is_empty() {
                    "nothing".to_owned()
                } else {
                    held.join(", ")
                },
                plural(lpp.plan_count(), "plan"),
                if lpp.retry_at_ns().is_some() {
                    "; retrying"
                } else {
                    ""
                }
            )
        }
        ComponentKind::DriveControl => w.drive_control().status().to_string(),
    }
}
