//! What a component is doing or holds, as the RTC panel's status column shows it (RT System
//! Editor's): [`ComponentActivity`], a kind and its fields (`{"kind": "local_planning",
//! "made": 3, "sent": 2, …}`), said in words by a user interface from its catalogue
//! (`rtcstatus.<kind>`); its `Display` is the core's English, for the command line and logs.
//!
//! A component that is not Active never shows an activity: in Error it says so (with its
//! reason), and MotorControl and DriveControl, whose status is what they do, say `inactive`
//! while they are not Active — whatever they did last. The others show what they hold (a
//! map, a route, the plans made), which stays true while they rest.

use core::fmt;

use serde::Serialize;

use super::record::RunStats;
use super::wiring::Wiring;
use crate::components::{DriveStatus, LocalizationMode, MotorStatus};
use crate::motion::DrivePhase;
use crate::present::{fixed, number};
use crate::reason::Reason;
use crate::rtc::LifecycleState;
use crate::system::vocabulary::kind::ComponentKind;

/// What a component is doing or holds (see the module documentation).
#[derive(Debug, Clone, PartialEq, Serialize, strum::EnumDiscriminants)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[strum_discriminants(
    name(ActivityKind),
    vis(pub(crate)),
    derive(strum::VariantNames, strum::IntoStaticStr),
    strum(serialize_all = "snake_case")
)]
#[non_exhaustive]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub enum ComponentActivity {
    /// In Error: it does not execute (spec §1) until a reset.
    InError {
        /// The reason of its last failure, if one is known.
        reason: Option<Reason>,
    },
    /// Not Active: MotorControl and DriveControl do nothing.
    Inactive,
    /// MapBuilder holds a map.
    Map {
        /// Cells in x.
        width: usize,
        /// Cells in y.
        height: usize,
        /// `GridSize` \[m\].
        grid_size: f64,
    },
    /// MapBuilder holds no map.
    NoMap,
    /// MapMaintenance: the map updates it sent.
    UpdatesSent {
        /// How many.
        updates: u64,
    },
    /// PhysicsSim: the bumps so far, and whether the body touches an obstacle now.
    Bumps {
        /// How many.
        bumps: u64,
        /// Whether it touches an obstacle now.
        touching: bool,
    },
    /// MotorControl is Active and waits for these inputs (its ports' names).
    WaitingFor {
        /// The in-ports that have not received a sample yet.
        inputs: Vec<&'static str>,
    },
    /// MotorControl controls the wheels to the target velocity.
    Running,
    /// MotorControl's `Stop` (a bump): braking to zero velocity.
    Stopped,
    /// MotorControl's `Finish`: zero torque.
    Finished,
    /// A controller's safe stop on bad input (spec §4 Decision).
    SafeStop {
        /// What it holds at zero: `torque` (MotorControl) or `velocity` (DriveControl).
        output: ZeroOutput,
        /// Why.
        reason: Reason,
    },
    /// Localization's mode (where the pose it publishes comes from).
    Localizing {
        /// `SimulatedPose` or `Odometry`.
        mode: LocalizationMode,
    },
    /// GlobalPathPlanning's last plan failed.
    RouteFailed {
        /// Why.
        reason: Reason,
    },
    /// GlobalPathPlanning holds a route.
    Route {
        /// Its length \[m\].
        length: f64,
    },
    /// GlobalPathPlanning holds no route.
    NoRoute,
    /// LocalPathPlanning: the flags it holds (000 §5.2.4) and its plans.
    LocalPlanning {
        /// The held flags that are set.
        holds: Vec<Held>,
        /// Local plans made (potential fields computed).
        made: u64,
        /// Local plans sent (the same figure as the telemetry's "local plans sent": the
        /// record's count of them).
        sent: u64,
        /// Whether it waits to try again after a failure (Active only).
        retrying: bool,
    },
    /// DriveControl is Active and no pose has arrived yet.
    WaitingForPose,
    /// DriveControl has no path.
    Idle,
    /// DriveControl turns the robot on the spot towards the path.
    TurningOnTheSpot,
    /// DriveControl follows the path.
    FollowingPath,
    /// DriveControl turns the robot to the goal heading at the goal.
    TurningToGoalHeading,
    /// DriveControl is at the goal with the goal heading.
    Arrived,
    /// DriveControl's clearance check stopped the robot; a new plan was asked for.
    SafetyStop {
        /// Free travel left along the commanded arc \[m\].
        ahead: f64,
    },
    /// A student's script stands in the component's place (spec §8): what it does is the
    /// script's, and its console says it.
    Script {
        /// The script's name (a file name).
        script: String,
        /// Whether it is Active (its actions run every period).
        active: bool,
    },
}

/// What a safe stop holds at zero.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, strum::VariantNames)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
#[strum(serialize_all = "snake_case")]
pub enum ZeroOutput {
    /// MotorControl: zero torque.
    Torque,
    /// DriveControl: zero velocity.
    Velocity,
}

/// One of LocalPathPlanning's held flags (000 §5.2.4) that the RTC panel lists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, strum::VariantNames)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
#[strum(serialize_all = "snake_case")]
pub enum Held {
    /// A map.
    Map,
    /// Start and goal.
    StartAndGoal,
    /// A grid path.
    Path,
    /// The goal reached (its own flag: within `GridSize`).
    Arrived,
    /// SafeMode.
    SafeMode,
}

impl ComponentActivity {
    /// Every kind an activity serializes with: what a user interface must have words for
    /// (`rtcstatus.<kind>`).
    pub const KINDS: &'static [&'static str] = <ActivityKind as strum::VariantNames>::VARIANTS;

    /// The kind it serializes with.
    pub fn kind(&self) -> &'static str {
        ActivityKind::from(self).into()
    }

    /// What component `kind` of the system whose wiring is `w` and totals `stats` is doing or
    /// holds now ([`System::components`](crate::system::System::components)).
    pub fn of(w: &Wiring, stats: &RunStats, kind: ComponentKind) -> Self {
        let state = w.component_state(kind);
        // A component in Error does not execute (spec §1): what it held last is not what it
        // does.
        if state == LifecycleState::Error {
            let ec = w.execution_context();
            return Self::InError {
                reason: ec.last_error(kind.index()).ok().flatten().cloned(),
            };
        }
        let active = state == LifecycleState::Active;
        if let Some(script) = w.script(kind) {
            return Self::Script {
                script: script.program().name().to_owned(),
                active,
            };
        }
        match kind {
            ComponentKind::MapBuilder => match w.map_builder().map() {
                Some(m) => Self::Map {
                    width: m.width(),
                    height: m.height(),
                    grid_size: m.grid_size(),
                },
                None => Self::NoMap,
            },
            ComponentKind::MapMaintenance => Self::UpdatesSent {
                updates: w.map_maintenance().sent_count(),
            },
            ComponentKind::PhysicsSim => {
                let p = w.physics().physics();
                Self::Bumps {
                    bumps: p.bump_count(),
                    touching: p.state().in_contact,
                }
            }
            ComponentKind::MotorControl if !active => Self::Inactive,
            ComponentKind::MotorControl => match w.motor_control().map(|m| m.status()) {
                None => Self::Inactive,
                Some(status) => match status {
                    MotorStatus::Inactive => Self::Inactive,
                    MotorStatus::WaitingForInput {
                        wheel_angle,
                        target_velocity,
                    } => Self::WaitingFor {
                        inputs: [
                            (!wheel_angle, "InCurrentWheelAngle"),
                            (!target_velocity, "TargetVelocity"),
                        ]
                        .into_iter()
                        .filter_map(|(missing, port)| missing.then_some(port))
                        .collect(),
                    },
                    MotorStatus::Running => Self::Running,
                    MotorStatus::Stopped => Self::Stopped,
                    MotorStatus::Finished => Self::Finished,
                    MotorStatus::SafeStop(e) => Self::SafeStop {
                        output: ZeroOutput::Torque,
                        reason: Reason::Error(e.clone().into()),
                    },
                },
            },
            ComponentKind::Localization => Self::Localizing {
                mode: w.localization().config().params().mode(),
            },
            ComponentKind::GlobalPathPlanning => {
                let g = w.global_path_planning();
                match (g.last_error(), g.path_length()) {
                    (Some(e), _) => Self::RouteFailed {
                        reason: Reason::Error(e.clone().into()),
                    },
                    (None, Some(length)) => Self::Route { length },
                    (None, None) => Self::NoRoute,
                }
            }
            ComponentKind::LocalPathPlanning => {
                let lpp = w.local_path_planning();
                let f = lpp.flags();
                let holds = [
                    (f.map, Held::Map),
                    (f.position, Held::StartAndGoal),
                    (f.path, Held::Path),
                    (f.arrived, Held::Arrived),
                    (f.safe_mode, Held::SafeMode),
                ]
                .into_iter()
                .filter_map(|(on, held)| on.then_some(held))
                .collect();
                Self::LocalPlanning {
                    holds,
                    made: lpp.plan_count(),
                    sent: stats.local_plans,
                    retrying: active && lpp.retry_at_ns().is_some(),
                }
            }
            ComponentKind::DriveControl if !active => Self::Inactive,
            ComponentKind::DriveControl => match w.drive_control().map(|d| d.status()) {
                None => Self::Inactive,
                Some(status) => match status {
                    DriveStatus::Inactive => Self::Inactive,
                    DriveStatus::WaitingForPose => Self::WaitingForPose,
                    DriveStatus::Driving(DrivePhase::Idle) => Self::Idle,
                    DriveStatus::Driving(DrivePhase::TurnInPlace) => Self::TurningOnTheSpot,
                    DriveStatus::Driving(DrivePhase::Following) => Self::FollowingPath,
                    DriveStatus::Driving(DrivePhase::FinalTurn) => Self::TurningToGoalHeading,
                    DriveStatus::Driving(DrivePhase::Arrived) => Self::Arrived,
                    DriveStatus::SafeStop(e) => Self::SafeStop {
                        output: ZeroOutput::Velocity,
                        reason: Reason::Error(e.clone().into()),
                    },
                    DriveStatus::SafetyStop { ahead } => Self::SafetyStop { ahead: *ahead },
                },
            },
        }
    }
}

/// `1 update`, `2 updates`: English's plural of a count.
fn count(n: u64, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

impl fmt::Display for ComponentActivity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InError { reason: None } => f.write_str("in Error, not executing"),
            Self::InError {
                reason: Some(reason),
            } => write!(f, "in Error, not executing: {reason}"),
            Self::Inactive => f.write_str("inactive"),
            Self::Script { script, active } => write!(
                f,
                "runs the student's script `{script}`{}",
                if *active { "" } else { " (inactive)" }
            ),
            Self::Map {
                width,
                height,
                grid_size,
            } => write!(f, "map {width}×{height} at {} m", number(*grid_size)),
            Self::NoMap => f.write_str("no map"),
            Self::UpdatesSent { updates } => {
                write!(f, "{} sent", count(*updates, "update", "updates"))
            }
            Self::Bumps { bumps, touching } => write!(
                f,
                "{}{}",
                count(*bumps, "bump", "bumps"),
                if *touching {
                    ", touching an obstacle"
                } else {
                    ""
                }
            ),
            Self::WaitingFor { inputs } => write!(f, "waiting for {}", inputs.join(" and ")),
            Self::Running => f.write_str("running"),
            Self::Stopped => f.write_str("stopped (Stop): braking to zero velocity"),
            Self::Finished => f.write_str("finished (Finish): zero torque"),
            Self::SafeStop { output, reason } => write!(
                f,
                "safe stop, zero {}: {reason}",
                match output {
                    ZeroOutput::Torque => "torque",
                    ZeroOutput::Velocity => "velocity",
                }
            ),
            Self::Localizing { mode } => write!(f, "{mode:?}"),
            Self::RouteFailed { reason } => write!(f, "failed: {reason}"),
            Self::Route { length } => write!(f, "route of {} m", fixed(*length, 2)),
            Self::NoRoute => f.write_str("no route"),
            Self::LocalPlanning {
                holds,
                made,
                sent,
                retrying,
            } => {
                f.write_str("holds: ")?;
                if holds.is_empty() {
                    f.write_str("nothing")?;
                }
                for (i, held) in holds.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    f.write_str(match held {
                        Held::Map => "map",
                        Held::StartAndGoal => "start and goal",
                        Held::Path => "path",
                        Held::Arrived => "arrived",
                        Held::SafeMode => "SafeMode",
                    })?;
                }
                write!(
                    f,
                    "; {} made, {sent} sent{}",
                    count(*made, "local plan", "local plans"),
                    if *retrying { "; retrying" } else { "" }
                )
            }
            Self::WaitingForPose => f.write_str("waiting for InCurrentPosition"),
            Self::Idle => f.write_str("idle (no path)"),
            Self::TurningOnTheSpot => f.write_str("turning on the spot"),
            Self::FollowingPath => f.write_str("following the path"),
            Self::TurningToGoalHeading => f.write_str("turning to the goal heading"),
            Self::Arrived => f.write_str("arrived"),
            Self::SafetyStop { ahead } => write!(
                f,
                "safety stop: obstacle {} m ahead, a new plan asked for",
                fixed(*ahead, 2)
            ),
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::errors::{GlobalPlanningError, MotionError};

    /// One activity of every kind, with fields that are not defaults.
    pub(crate) fn every_activity() -> Vec<ComponentActivity> {
        use ComponentActivity as A;
        let error = || Reason::Error(GlobalPlanningError::NoMap.into());
        let bad = MotionError::NonFinite {
            port: "TargetVelocity",
            field: "vx".into(),
            value: f64::NAN,
        };
        vec![
            A::InError {
                reason: Some(error()),
            },
            A::Inactive,
            A::Map {
                width: 200,
                height: 100,
                grid_size: 0.05,
            },
            A::NoMap,
            A::UpdatesSent { updates: 1 },
            A::Bumps {
                bumps: 2,
                touching: true,
            },
            A::WaitingFor {
                inputs: vec!["InCurrentWheelAngle", "TargetVelocity"],
            },
            A::Running,
            A::Stopped,
            A::Finished,
            A::SafeStop {
                output: ZeroOutput::Torque,
                reason: Reason::Error(bad.into()),
            },
            A::Localizing {
                mode: LocalizationMode::Odometry,
            },
            A::RouteFailed { reason: error() },
            A::Route { length: 12.5 },
            A::NoRoute,
            A::LocalPlanning {
                holds: vec![Held::Map, Held::StartAndGoal],
                made: 3,
                sent: 2,
                retrying: true,
            },
            A::WaitingForPose,
            A::Idle,
            A::TurningOnTheSpot,
            A::FollowingPath,
            A::TurningToGoalHeading,
            A::Arrived,
            A::SafetyStop { ahead: 0.25 },
            A::Script {
                script: "pd.rhai".into(),
                active: true,
            },
        ]
    }

    /// Every kind is listed, and serializes as its kind with its fields.
    #[test]
    fn every_kind_serializes_with_its_fields() {
        let all = every_activity();
        let kinds: Vec<&str> = all.iter().map(ComponentActivity::kind).collect();
        assert_eq!(kinds, ComponentActivity::KINDS);
        for a in &all {
            let v = serde_json::to_value(a).unwrap();
            assert_eq!(v["kind"], a.kind(), "{v}");
        }
        let v = |i: usize| serde_json::to_value(&all[i]).unwrap();
        assert_eq!(v(0)["reason"]["kind"], "error");
        assert_eq!(v(0)["reason"]["error"]["area"], "GlobalPlanning");
        assert_eq!(
            v(2),
            serde_json::json!({"kind": "map", "width": 200, "height": 100, "grid_size": 0.05})
        );
        assert_eq!(v(5)["touching"], true);
        assert_eq!(
            v(6)["inputs"],
            serde_json::json!(["InCurrentWheelAngle", "TargetVelocity"])
        );
        assert_eq!(v(10)["output"], "torque");
        assert_eq!(v(10)["reason"]["error"]["kind"], "NonFinite");
        assert_eq!(v(11)["mode"], "Odometry");
        assert_eq!(
            v(15),
            serde_json::json!({"kind": "local_planning", "holds": ["map", "start_and_goal"],
                "made": 3, "sent": 2, "retrying": true})
        );
        assert_eq!(v(22)["ahead"], 0.25);
    }

    /// The English says what each counter counts, with English's plural.
    #[test]
    fn counters_say_what_they_count() {
        let all = every_activity();
        assert_eq!(all[4].to_string(), "1 update sent");
        assert_eq!(all[5].to_string(), "2 bumps, touching an obstacle");
        assert_eq!(
            all[15].to_string(),
            "holds: map, start and goal; 3 local plans made, 2 sent; retrying"
        );
        let one = ComponentActivity::LocalPlanning {
            holds: vec![],
            made: 1,
            sent: 1,
            retrying: false,
        };
        assert_eq!(one.to_string(), "holds: nothing; 1 local plan made, 1 sent");
        assert_eq!(all[2].to_string(), "map 200×100 at 0.05 m");
        assert_eq!(all[1].to_string(), "inactive");
    }
}
