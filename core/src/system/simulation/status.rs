//! What the system is doing, from its facts: the whole system's lifecycle state
//! ([`SystemState`]), each component as the RTC panel shows it ([`ComponentInfo`]), and the
//! robot's status ([`Status`]): what it does from the measured motion (`rest.rs`), why from
//! the components' states (spec §7 Decisions 0.3).

use core::fmt;

use serde::Serialize;

use super::activity::ComponentActivity;
use super::mission::Mission;
use super::record::RunStats;
use super::rest::{Measured, Motion};
use super::wiring::Wiring;
use crate::components::{DriveStatus, MotorStatus};
use crate::interfaces::Direction;
use crate::motion::DrivePhase;
use crate::present::fixed;
use crate::reason::Reason;
use crate::rtc::LifecycleState;
use crate::system::vocabulary::kind::ComponentKind;

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

/// What the robot is doing and why, as a kind and its fields (spec §7 Decisions 0.3): what
/// it does — drives, turns, coasts, stands — from the physics' measured motion
/// ([`Motion`]); why, from the components' states and the mission. A kind that names a
/// cause carries the motion as its field `motion`; the kinds without one say the motion
/// themselves (see [`Status::motion`]).
#[derive(Debug, Clone, PartialEq, Serialize, strum::VariantNames)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[strum(serialize_all = "snake_case")]
pub enum Status {
    /// No map is loaded.
    NoMap,
    /// A map, but no goal.
    NoGoal {
        /// What the robot does meanwhile.
        motion: Motion,
    },
    /// A component is in Error (a bump puts the physics there): Reset recovers.
    ComponentError {
        /// The component's instance name.
        component: String,
        /// Its reason, if one is known.
        reason: Option<Reason>,
        /// What the robot does meanwhile.
        motion: Motion,
    },
    /// SafeMode or Clear halted the robot until the next goal.
    Halted {
        /// `SafeMode` or `Clear`.
        by: String,
        /// What the robot does meanwhile.
        motion: Motion,
    },
    /// Arrived: at rest within the arrival tolerances of the goal (spec §7).
    Arrived,
    /// At rest outside the arrival tolerances, DriveControl done with the path: the robot
    /// stopped off the goal (it overshot, or stopped short) and has not arrived.
    StoppedOffGoal {
        /// Distance from the goal \[m\].
        distance: f64,
        /// Heading error \[rad\], absolute.
        heading_error: f64,
    },
    /// GlobalPathPlanning found no route to the goal (it tries again when the map changes).
    NoRoute {
        /// Why.
        reason: Reason,
        /// What the robot does meanwhile.
        motion: Motion,
    },
    /// A goal is held and no plan has reached DriveControl yet; after a failed local plan,
    /// LocalPathPlanning tries again every second (spec §3 Decision 0.2).
    WaitingForPlan {
        /// The failure that is being retried, if any.
        retrying: Option<Reason>,
        /// What the robot does meanwhile.
        motion: Motion,
    },
    /// The plan is ready; the physics is not Active (the robot stands), the robot's
    /// components wait for activation.
    Ready,
    /// A component the drive needs is not Active.
    Inactive {
        /// The component's instance name.
        component: String,
        /// What the robot does meanwhile (it coasts while it still moves).
        motion: Motion,
    },
    /// A data connection between two components is cut.
    ConnectionCut {
        /// The connection's id.
        connection: String,
        /// What the robot does meanwhile.
        motion: Motion,
    },
    /// A controller stopped the robot and says why (MotorControl's or DriveControl's safe
    /// stop, DriveControl's collision check).
    SafeStop {
        /// The component's instance name.
        component: String,
        /// Why.
        reason: Reason,
        /// What the robot does meanwhile.
        motion: Motion,
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
        /// Measured speed \[m/s\].
        v: f64,
        /// Measured turn rate \[rad/s\].
        w: f64,
    },
    /// Everything runs, DriveControl commands nothing, and the robot still moves: it rolls
    /// on (or is braked) to a stop.
    Coasting {
        /// Measured speed \[m/s\].
        v: f64,
        /// Measured turn rate \[rad/s\].
        w: f64,
    },
    /// Everything runs and the robot is at rest.
    Standing,
}

impl Status {
    /// Every kind, by the name it serializes with: what a user interface that says the
    /// status in its own words must have words for (`status.<kind>`).
    pub const KINDS: &'static [&'static str] = <Self as strum::VariantNames>::VARIANTS;

    /// The status now of the system whose wiring is `w` and mission `m`
    /// ([`System::status`](crate::system::System::status)).
    pub fn of(w: &Wiring, m: &Mission) -> Self {
        if w.map().is_none() {
            return Self::NoMap;
        }
        let motion = Motion::of(w);
        if let Some(kind) = ComponentKind::ALL
            .into_iter()
            .find(|&k| w.component_state(k) == LifecycleState::Error)
        {
            let id = kind.index();
            let reason = w.execution_context().last_error(id).ok().flatten().cloned();
            return Self::ComponentError {
                component: kind.instance_name().to_owned(),
                reason,
                motion,
            };
        }
        if m.is_halted() {
            let by = if w.local_path_planning().flags().safe_mode {
                "SafeMode"
            } else {
                "Clear"
            };
            return Self::Halted {
                by: by.to_owned(),
                motion,
            };
        }
        if m.goal().is_none() {
            return Self::NoGoal { motion };
        }
        if m.is_arrived() && !motion.moves() {
            return Self::Arrived;
        }
        let lpp = w.local_path_planning();
        if lpp.retry_at_ns().is_some() {
            return Self::WaitingForPlan {
                retrying: lpp.last_failure().map(|f| f.reason.clone()),
                motion,
            };
        }
        if let Some(e) = w.global_path_planning().last_error()
            && !w.global_path_planning().is_requested()
        {
            return Self::NoRoute {
                reason: Reason::Error(e.clone().into()),
                motion,
            };
        }
        if !m.plan_sent() {
            return Self::WaitingForPlan {
                retrying: None,
                motion,
            };
        }
        let active = |k: ComponentKind| w.component_state(k) == LifecycleState::Active;
        if !active(ComponentKind::PhysicsSim) {
            return Self::Ready;
        }
        for k in [
            ComponentKind::MotorControl,
            ComponentKind::Localization,
            ComponentKind::DriveControl,
        ] {
            if !active(k) {
                return Self::Inactive {
                    component: k.instance_name().to_owned(),
                    motion,
                };
            }
        }
        if let Some(link) = w
            .links()
            .all()
            .iter()
            .find(|l| l.cuttable() && l.connector.is_cut())
        {
            return Self::ConnectionCut {
                connection: link.id(),
                motion,
            };
        }
        if let Some(MotorStatus::SafeStop(e)) = w.motor_control().map(|m| m.status()) {
            return Self::SafeStop {
                component: ComponentKind::MotorControl.instance_name().to_owned(),
                reason: Reason::Error(e.clone().into()),
                motion,
            };
        }
        match w.drive_control().map(|d| d.status()) {
            Some(DriveStatus::SafeStop(e)) => {
                return Self::SafeStop {
                    component: ComponentKind::DriveControl.instance_name().to_owned(),
                    reason: Reason::Error(e.clone().into()),
                    motion,
                };
            }
            Some(DriveStatus::SafetyStop { ahead }) => {
                return Self::SafeStop {
                    component: ComponentKind::DriveControl.instance_name().to_owned(),
                    reason: Reason::ObstacleAhead { ahead: *ahead },
                    motion,
                };
            }
            _ => {}
        }
        let (v_cmd, w_cmd) = w.drive_command();
        let Measured { v, w: om } = Measured::of(w);
        if motion.moves() && ((v - v_cmd).abs() > 0.25 || (om - w_cmd).abs() > 1.0) {
            return Self::OffCommand {
                v_cmd,
                w_cmd,
                v,
                w: om,
            };
        }
        match motion {
            Motion::Stands => match m.off_goal() {
                Some(off) => Self::StoppedOffGoal {
                    distance: off.distance,
                    heading_error: off.heading_error,
                },
                None => Self::Standing,
            },
            Motion::Coasts => Self::Coasting { v, w: om },
            Motion::Turns if w.drive_phase() == Some(DrivePhase::FinalTurn) => {
                Self::TurningToGoalHeading
            }
            Motion::Turns => Self::TurningOnTheSpot,
            Motion::Drives => Self::Driving {
                direction: lpp.direction(),
            },
        }
    }

    /// What the status says the robot does (`None`: it says nothing of it).
    pub fn motion(&self) -> Option<Motion> {
        match self {
            Self::NoMap => None,
            Self::NoGoal { motion }
            | Self::ComponentError { motion, .. }
            | Self::Halted { motion, .. }
            | Self::NoRoute { motion, .. }
            | Self::WaitingForPlan { motion, .. }
            | Self::Inactive { motion, .. }
            | Self::ConnectionCut { motion, .. }
            | Self::SafeStop { motion, .. } => Some(*motion),
            Self::Arrived | Self::StoppedOffGoal { .. } | Self::Ready | Self::Standing => {
                Some(Motion::Stands)
            }
            Self::Driving { .. } => Some(Motion::Drives),
            Self::TurningOnTheSpot | Self::TurningToGoalHeading => Some(Motion::Turns),
            Self::Coasting { .. } => Some(Motion::Coasts),
            // Moves, not as commanded: driven, but the words say neither drives nor turns.
            Self::OffCommand { .. } => None,
        }
    }
}

impl fmt::Display for Motion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Stands => "stands",
            Self::Drives => "drives",
            Self::Turns => "turns",
            Self::Coasts => "coasts",
        })
    }
}

impl fmt::Display for Status {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoMap => f.write_str("no map loaded"),
            Self::NoGoal { motion } => {
                write!(f, "no goal: set start and goal; the robot {motion}")
            }
            Self::ComponentError {
                component,
                reason: Some(reason),
                motion,
            } => {
                write!(
                    f,
                    "{component} in Error: {reason} (Reset recovers); the robot {motion}"
                )
            }
            Self::ComponentError {
                component,
                reason: None,
                motion,
            } => {
                write!(
                    f,
                    "{component} in Error (Reset recovers); the robot {motion}"
                )
            }
            Self::Halted { by, motion } => {
                write!(f, "halted by {by} until the next goal; the robot {motion}")
            }
            Self::Arrived => f.write_str("arrived: the robot rests at the goal"),
            Self::StoppedOffGoal {
                distance,
                heading_error,
            } => write!(
                f,
                "stopped off the goal: the robot rests {} m and {}° from it",
                fixed(*distance, 3),
                fixed(heading_error.to_degrees(), 1)
            ),
            Self::NoRoute { reason, motion } => {
                write!(f, "no route ({reason}); the robot {motion}")
            }
            Self::WaitingForPlan {
                retrying: None,
                motion,
            } => write!(f, "waiting for a plan; the robot {motion}"),
            Self::WaitingForPlan {
                retrying: Some(reason),
                motion,
            } => write!(
                f,
                "waiting for a plan (retrying every second: {reason}); the robot {motion}"
            ),
            Self::Ready => f.write_str("plan ready: activate the robot's components"),
            Self::Inactive { component, motion } => {
                write!(f, "{component} inactive: the robot {motion}")
            }
            Self::ConnectionCut { connection, motion } => {
                write!(f, "connection {connection} cut: the robot {motion}")
            }
            Self::SafeStop {
                component,
                reason,
                motion,
            } => {
                write!(f, "safety stop ({component}): {reason}; the robot {motion}")
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
            Self::Coasting { v, w } => write!(
                f,
                "coasting at {} m/s, {} rad/s: no motion commanded",
                fixed(*v, 2),
                fixed(*w, 2)
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
    pub last_error: Option<Reason>,
    /// What it is doing or holds ([`ComponentActivity`]).
    pub status: ComponentActivity,
}

impl ComponentInfo {
    /// Component `kind` of the system whose wiring is `wiring` and totals `stats`, now
    /// ([`System::component`](crate::system::System::component)).
    pub fn of(wiring: &Wiring, stats: &RunStats, kind: ComponentKind) -> Self {
        let id = kind.index();
        let ec = wiring.execution_context();
        Self {
            kind,
            instance_name: kind.instance_name().to_owned(),
            state: wiring.component_state(kind),
            rate: ec.rate(id).unwrap_or(f64::NAN),
            last_error: ec.last_error(id).ok().flatten().cloned(),
            status: ComponentActivity::of(wiring, stats, kind),
        }
    }

    /// Every component, in attachment order.
    pub fn all(wiring: &Wiring, stats: &RunStats) -> Vec<Self> {
        ComponentKind::ALL
            .into_iter()
            .map(|k| Self::of(wiring, stats, k))
            .collect()
    }
}
