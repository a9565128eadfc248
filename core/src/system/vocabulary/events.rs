//! What the GUI is told (InventGUI's log): plans, failures, bumps, arrival, component
//! errors and state changes, map changes — each with its simulated time. Events are facts
//! as data (a kind and its fields, spec §7): the page and the command line say them from
//! their catalogues (`web/i18n/*.json`; the command line reads the English one), never
//! from words of the core's.

use serde::Serialize;

use super::input::{InputSummary, RequestSource};
use crate::interfaces::{Direction, Pose};
use crate::motion::BumpReport;
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
    /// A student's script was put in a component's place (spec §8); the component is
    /// Inactive, its `on_initialize` run.
    ScriptLoaded {
        /// The component's instance name.
        component: String,
        /// The script's name (a file name).
        script: String,
    },
    /// The built-in component was put back in its place (spec §8).
    BuiltInRestored {
        /// The component's instance name.
        component: String,
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
