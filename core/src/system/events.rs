//! What the GUI is told (InventGUI's log): plans, failures, bumps, arrival, component
//! errors and state changes, map changes — each with its simulated time.

use core::fmt;

use serde::Serialize;

use super::input::{InputSummary, RequestSource};
use crate::interfaces::{Direction, Pose};
use crate::motion::BumpReport;
use crate::present::{fixed, number};
use crate::reason::Reason;
use crate::rtc::LifecycleState;

/// One thing that happened, at simulated time `time_ns`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SystemEvent {
    /// Simulated time \[ns\].
    pub time_ns: u64,
    /// What happened.
    pub kind: EventKind,
}

/// What happened. `EventKind::VARIANTS` (`strum::VariantNames`) lists every kind by the name
/// it serializes with: what a GUI that says events in its own words must have words for.
#[derive(Debug, Clone, PartialEq, Serialize, strum::VariantNames)]
#[non_exhaustive]
pub enum EventKind {
    /// A map was loaded (MapBuilder's `SetMap`).
    MapLoaded {
        /// Cells in x.
        width: usize,
        /// Cells in y.
        height: usize,
        /// `GridSize` \[m\].
        grid_size: f64,
    },
    /// A `MapUpdate` reached the planners and the physics.
    MapUpdated {
        /// Cells listed.
        cells: usize,
        /// Cells whose value changed.
        changed: usize,
    },
    /// Start and goal were accepted (`SetPosition`).
    GoalSet {
        /// The start (the robot's pose for a new goal while driving).
        start: Pose,
        /// The goal.
        goal: Pose,
        /// Forward or backward.
        direction: Direction,
        /// Whether the robot was placed at the start (else: a new goal from where it is).
        placed: bool,
    },
    /// GlobalPathPlanning sent a route (`GlobalPathCourse`).
    GlobalPlan {
        /// Cells on the route.
        cells: usize,
        /// Its length \[m\].
        length: f64,
        /// Why it was planned: `Requested`, `MapChanged` (the route was blocked) or
        /// `DminChanged`.
        reason: String,
        /// Steps at its start that lead out of the `dmin` zone (spec §3 Decision 0.2).
        escaped: usize,
    },
    /// LocalPathPlanning sent a grid path and control points (000 §5.2.4.13).
    LocalPlanSent {
        /// Cells of the merged path (0: the empty path of a failure, Clear or SafeMode).
        cells: usize,
        /// Control points sent.
        control_points: usize,
        /// Whether a potential-field plan made it (else: the global path as received).
        replanned: bool,
        /// Steps at its start that lead out of the `dmin` zone (spec §3 Decision 0.2).
        escaped: usize,
    },
    /// A planner could not make a plan (000 §5.2.4.13's failure notice).
    PlanningFailed {
        /// `GlobalPathPlanning` or `LocalPathPlanning`.
        planner: String,
        /// Why.
        reason: Reason,
    },
    /// The robot touched an obstacle (spec §5): it stops and the physics goes to Error.
    Bump {
        /// The physics' report.
        report: BumpReport,
    },
    /// DriveControl reached the goal with the goal heading.
    Arrived {
        /// The robot's (true) pose.
        pose: Pose,
        /// Distance to the goal \[m\].
        position_error: f64,
        /// Heading error \[rad\].
        heading_error: f64,
        /// Heading error \[rad\] when the robot reached the goal position, before its final
        /// turn: what the posture term of the plan achieved.
        approach_heading_error: f64,
    },
    /// A component's callback failed (spec §1: the reason the GUI shows).
    ComponentError {
        /// The component's instance name.
        component: String,
        /// The callback that failed.
        callback: String,
        /// Its reason.
        reason: Reason,
    },
    /// A component's lifecycle state changed.
    StateChanged {
        /// The component's instance name.
        component: String,
        /// State before.
        from: LifecycleState,
        /// State after.
        to: LifecycleState,
    },
    /// `SafeMode` was called: the robot halts until the next `SetPosition`.
    SafeMode,
    /// `Clear` was called: paths and goal dropped.
    Cleared,
    /// DriveControl's clearance check stopped the robot short of an obstacle (spec §5).
    SafetyStop {
        /// Free travel left along the commanded arc \[m\].
        ahead: f64,
        /// Whether LocalPathPlanning took the request for a new plan.
        replanning: bool,
    },
    /// A component's next execution was made to fail (the page's "Inject fault").
    FaultInjected {
        /// The component's instance name.
        component: String,
        /// The reason it will fail with.
        reason: String,
    },
    /// A configuration parameter was set (spec §1).
    ParameterSet {
        /// The component.
        component: String,
        /// The parameter.
        name: String,
        /// Its new value.
        value: f64,
    },
    /// MotorControl's `SetPDGain` (002 §3.2.2.1 (1)).
    GainsSet {
        /// `PGainL`.
        p_l: f64,
        /// `PGainR`.
        p_r: f64,
        /// `DGainL`.
        d_l: f64,
        /// `DGainR`.
        d_r: f64,
    },
    /// A configuration bundle was loaded (spec §1).
    ConfigurationLoaded {
        /// How many component blocks it had.
        components: usize,
    },
    /// The values let the body touch an obstacle although the planners keep `dmin`
    /// (spec §3 Decision 0.2): `dmin − GridSize/2 < radiusOfBodyArea`.
    ClearanceWarning {
        /// `dmin` \[m\].
        dmin: f64,
        /// The map's `GridSize` \[m\].
        grid_size: f64,
        /// MotorControl's `radiusOfBodyArea` \[m\].
        body_radius: f64,
    },
    /// A request the system made on its own was refused (a scenario's timed goal, a replan
    /// after a parameter change); the previous state stays.
    RequestRefused {
        /// Who asked.
        source: RequestSource,
        /// What was asked.
        request: InputSummary,
        /// Why it was refused.
        reason: Reason,
    },
    /// A sample was written into a component's input port from outside (rtshell's
    /// `rtinject`; the page's "Sensor glitch").
    InputInjected {
        /// The component.
        component: String,
        /// The port.
        port: String,
    },
    /// A data connection was cut: its samples no longer reach the in-port.
    ConnectionCut {
        /// `DriveControl.TargetVelocity → MotorControl.TargetVelocity`.
        connection: String,
    },
    /// A cut data connection was restored.
    ConnectionRestored {
        /// `DriveControl.TargetVelocity → MotorControl.TargetVelocity`.
        connection: String,
    },
}

impl fmt::Display for SystemEvent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{:9.3} s] {}", self.time_ns as f64 * 1e-9, self.kind)
    }
}

impl fmt::Display for EventKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            EventKind::MapLoaded {
                width,
                height,
                grid_size,
            } => write!(
                f,
                "map loaded: {width}×{height} cells of {} m",
                number(*grid_size)
            ),
            EventKind::MapUpdated { cells, changed } => {
                write!(f, "map updated: {cells} cells listed, {changed} changed")
            }
            EventKind::GoalSet {
                start,
                goal,
                direction,
                placed,
            } => write!(
                f,
                "{}: ({}, {}, {}°) → ({}, {}, {}°), {direction:?}",
                if *placed {
                    "start and goal set"
                } else {
                    "new goal"
                },
                fixed(start.x, 2),
                fixed(start.y, 2),
                fixed(start.theta.to_degrees(), 1),
                fixed(goal.x, 2),
                fixed(goal.y, 2),
                fixed(goal.theta.to_degrees(), 1)
            ),
            EventKind::GlobalPlan {
                cells,
                length,
                reason,
                escaped,
            } => {
                write!(f, "global plan: {cells} cells, {} m", fixed(*length, 2))?;
                match reason.as_str() {
                    "MapChanged" => f.write_str(" (the map changed under the route)")?,
                    "DminChanged" => f.write_str(" (dmin changed)")?,
                    _ => {}
                }
                escape(f, *escaped)
            }
            EventKind::LocalPlanSent { cells: 0, .. } => {
                f.write_str("empty path sent: the robot stops")
            }
            EventKind::LocalPlanSent {
                cells,
                control_points,
                replanned,
                escaped,
            } => {
                write!(
                    f,
                    "{} sent: {cells} cells, {control_points} control points",
                    if *replanned {
                        "local plan"
                    } else {
                        "global path"
                    }
                )?;
                escape(f, *escaped)
            }
            EventKind::PlanningFailed { planner, reason } => {
                write!(f, "planning failed ({planner}): {reason}")
            }
            EventKind::Bump { report } => write!(f, "BUMP: {report}"),
            EventKind::Arrived {
                pose,
                position_error,
                heading_error,
                approach_heading_error,
            } => write!(
                f,
                "arrived at ({}, {}, {}°): {} m and {}° from the goal \
                 (it came in {}° off the goal heading)",
                fixed(pose.x, 3),
                fixed(pose.y, 3),
                fixed(pose.theta.to_degrees(), 1),
                fixed(*position_error, 3),
                fixed(heading_error.to_degrees(), 2),
                fixed(approach_heading_error.to_degrees(), 1)
            ),
            EventKind::ComponentError {
                component,
                callback,
                reason,
            } => write!(f, "{component}: {callback} failed: {reason}"),
            EventKind::StateChanged {
                component,
                from,
                to,
            } => write!(f, "{component}: {from} → {to}"),
            EventKind::SafeMode => f.write_str("SafeMode: halt"),
            EventKind::Cleared => f.write_str("Clear: paths and goal dropped"),
            EventKind::SafetyStop { ahead, replanning } => write!(
                f,
                "safety stop: obstacle {} m ahead{}",
                fixed(*ahead, 2),
                if *replanning {
                    ", planning again from here"
                } else {
                    ""
                }
            ),
            EventKind::FaultInjected { component, reason } => {
                write!(f, "{component}: its next execution will fail ({reason})")
            }
            EventKind::ParameterSet {
                component,
                name,
                value,
            } => write!(f, "{component}.{name} = {}", number(*value)),
            EventKind::GainsSet { p_l, p_r, d_l, d_r } => {
                write!(
                    f,
                    "MotorControl SetPDGain({}, {}, {}, {})",
                    number(*p_l),
                    number(*p_r),
                    number(*d_l),
                    number(*d_r)
                )
            }
            EventKind::ConfigurationLoaded { components } => {
                write!(f, "configuration loaded: {components} component blocks")
            }
            EventKind::ClearanceWarning {
                dmin,
                grid_size,
                body_radius,
            } => write!(
                f,
                "warning: the body can touch obstacles: dmin {} m − half a cell ({} m) is \
                 less than radiusOfBodyArea {} m",
                number(*dmin),
                number(grid_size / 2.0),
                number(*body_radius)
            ),
            EventKind::RequestRefused {
                source,
                request,
                reason,
            } => {
                write!(f, "{source}: {request} was refused: {reason}")
            }
            EventKind::InputInjected { component, port } => {
                write!(f, "a sample was injected into {component}.{port}")
            }
            EventKind::ConnectionCut { connection } => {
                write!(f, "connection {connection} cut: no sample passes")
            }
            EventKind::ConnectionRestored { connection } => {
                write!(f, "connection {connection} restored")
            }
        }
    }
}

/// ", escaping the dmin zone in N steps" when a plan starts inside it.
fn escape(f: &mut fmt::Formatter<'_>, steps: usize) -> fmt::Result {
    if steps > 0 {
        write!(f, ", escaping the dmin zone in {steps} steps")?;
    }
    Ok(())
}
