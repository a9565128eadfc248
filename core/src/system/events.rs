//! What the GUI is told (InventGUI's log): plans, failures, bumps, arrival, component
//! errors and state changes, map changes — each with its simulated time.

use core::fmt;

use serde::Serialize;

use crate::interfaces::{Direction, Pose};
use crate::motion::BumpReport;
use crate::rtc::LifecycleState;

/// One thing that happened, at simulated time `time_ns`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SystemEvent {
    /// Simulated time \[ns\].
    pub time_ns: u64,
    /// What happened.
    pub kind: EventKind,
}

/// What happened.
#[derive(Debug, Clone, PartialEq, Serialize)]
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
    },
    /// GlobalPathPlanning sent a route (`GlobalPathCourse`).
    GlobalPlan {
        /// Cells on the route.
        cells: usize,
        /// Its length \[m\].
        length: f64,
    },
    /// LocalPathPlanning sent a grid path and control points (000 §5.2.4.13).
    LocalPlanSent {
        /// Cells of the merged path (0: the empty path of a failure, Clear or SafeMode).
        cells: usize,
        /// Control points sent.
        control_points: usize,
        /// Whether a potential-field plan made it (else: the global path as received).
        replanned: bool,
    },
    /// A planner could not make a plan (000 §5.2.4.13's failure notice).
    PlanningFailed {
        /// `GlobalPathPlanning` or `LocalPathPlanning`.
        planner: String,
        /// Why.
        reason: String,
    },
    /// The robot touched an obstacle (SPEC §5): it stops and the physics goes to Error.
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
    },
    /// A component's callback failed (SPEC §1: the reason the GUI shows).
    ComponentError {
        /// The component's instance name.
        component: String,
        /// The callback that failed.
        callback: String,
        /// Its reason.
        reason: String,
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
    /// DriveControl was activated with no path while a goal was held: the goal was sent
    /// again from where the robot stands (see `System::activate`).
    GoalResent {
        /// Why sending it again was refused, if it was.
        refused: Option<String>,
    },
    /// A request the system made on its own was refused (a scenario's timed goal, a replan
    /// after a parameter change); the previous state stays.
    RequestRefused {
        /// What was asked.
        request: String,
        /// Why it was refused.
        reason: String,
    },
    /// A sample was written into a component's input port from outside (rtshell's
    /// `rtinject`; the page's "Sensor glitch").
    InputInjected {
        /// The component.
        component: String,
        /// The port.
        port: String,
    },
}

impl fmt::Display for SystemEvent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[{:9.3} s] ", self.time_ns as f64 * 1e-9)?;
        match &self.kind {
            EventKind::MapLoaded {
                width,
                height,
                grid_size,
            } => write!(f, "map loaded: {width}×{height} cells of {grid_size} m"),
            EventKind::MapUpdated { cells, changed } => {
                write!(f, "map updated: {cells} cells listed, {changed} changed")
            }
            EventKind::GoalSet {
                start,
                goal,
                direction,
            } => write!(
                f,
                "goal set: ({:.2}, {:.2}, {:.1}°) → ({:.2}, {:.2}, {:.1}°), {direction:?}",
                start.x,
                start.y,
                start.theta.to_degrees(),
                goal.x,
                goal.y,
                goal.theta.to_degrees()
            ),
            EventKind::GlobalPlan { cells, length } => {
                write!(f, "global plan: {cells} cells, {length:.2} m")
            }
            EventKind::LocalPlanSent {
                cells,
                control_points,
                replanned,
            } => write!(
                f,
                "local plan sent: {cells} cells, {control_points} control points{}",
                if *replanned { " (replanned)" } else { "" }
            ),
            EventKind::PlanningFailed { planner, reason } => {
                write!(f, "planning failed ({planner}): {reason}")
            }
            EventKind::Bump { report } => write!(f, "BUMP: {report}"),
            EventKind::Arrived {
                pose,
                position_error,
                heading_error,
            } => write!(
                f,
                "arrived at ({:.3}, {:.3}, {:.1}°): {:.3} m and {:.2}° from the goal",
                pose.x,
                pose.y,
                pose.theta.to_degrees(),
                position_error,
                heading_error.to_degrees()
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
            EventKind::GoalResent { refused: None } => f.write_str(
                "DriveControl had no path after its activation: the goal was sent again",
            ),
            EventKind::GoalResent { refused: Some(r) } => {
                write!(
                    f,
                    "DriveControl has no path; sending the goal again was refused: {r}"
                )
            }
            EventKind::RequestRefused { request, reason } => {
                write!(f, "{request} was refused: {reason}")
            }
            EventKind::InputInjected { component, port } => {
                write!(f, "a sample was injected into {component}.{port}")
            }
        }
    }
}
