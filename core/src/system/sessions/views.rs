//! What a user interface reads from a [`Session`](crate::system::Session): plain data, serialized as
//! the page receives it, built by the session's read-outs (`session_view.rs`). With the
//! feature `typescript` each type also derives `ts_rs::TS`, and `core/tests/typescript.rs`
//! writes their TypeScript declarations (`web/types/core.d.ts`) that the page is
//! type-checked against.

use serde::Serialize;

use crate::interfaces::{Direction, Pose};
use crate::rtc::LifecycleState;
use crate::system::runs::exercise::ExerciseStatus;
use crate::system::simulation::status::{ComponentInfo, SystemState};
use crate::system::vocabulary::events::{EventKind, SystemEvent};

/// A pose with its heading in degrees (what a person reads).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct PoseView {
    /// \[m\]
    pub x: f64,
    /// \[m\]
    pub y: f64,
    /// Heading, counter-clockwise from +x \[°\].
    pub theta_deg: f64,
}

impl From<Pose> for PoseView {
    fn from(p: Pose) -> Self {
        Self {
            x: p.x,
            y: p.y,
            theta_deg: p.theta.to_degrees(),
        }
    }
}

impl From<PoseView> for Pose {
    fn from(p: PoseView) -> Self {
        Pose::new(p.x, p.y, p.theta_deg.to_radians())
    }
}

/// `forward` / `backward`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum DirectionView {
    /// Driving forward.
    Forward,
    /// Driving backward.
    Backward,
}

impl From<Direction> for DirectionView {
    fn from(d: Direction) -> Self {
        match d {
            Direction::Forward => Self::Forward,
            Direction::Backward => Self::Backward,
        }
    }
}

impl From<DirectionView> for Direction {
    fn from(d: DirectionView) -> Self {
        match d {
            DirectionView::Forward => Self::Forward,
            DirectionView::Backward => Self::Backward,
        }
    }
}

/// One component as the RTC panel shows it.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ComponentView {
    /// The component's name (`LocalPathPlanning`): what the lifecycle calls take.
    pub name: &'static str,
    /// Its kind, state, rate, last error and status line.
    #[serde(flatten)]
    pub info: ComponentInfo,
    /// The RT System Editor's colour of its state, `#rrggbb`.
    pub colour: &'static str,
    /// Whether an injected fault waits for its next execution.
    pub fault_pending: bool,
}

/// How the event log colours an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
#[serde(rename_all = "snake_case")]
pub enum EventLevel {
    /// A plan, a goal, a map.
    Info,
    /// A lifecycle change.
    State,
    /// An arrival.
    Success,
    /// A refusal, a failed plan, a stop.
    Warn,
    /// A bump, a component in Error.
    Error,
}

impl EventLevel {
    /// The level of an event of `kind`.
    pub fn of(kind: &EventKind) -> Self {
        match kind {
            EventKind::Bump { .. } | EventKind::ComponentError { .. } => Self::Error,
            EventKind::StateChanged { to, .. } if *to == LifecycleState::Error => Self::Error,
            EventKind::StateChanged { .. } => Self::State,
            EventKind::PlanningFailed { .. }
            | EventKind::SafeMode
            | EventKind::Cleared
            | EventKind::ClearanceWarning { .. }
            | EventKind::SafetyStop { .. }
            | EventKind::ConnectionCut { .. }
            | EventKind::RequestRefused { .. } => Self::Warn,
            EventKind::Arrived { .. } => Self::Success,
            _ => Self::Info,
        }
    }
}

/// One entry of the event log.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct EventView {
    /// Simulated time \[s\].
    pub time_s: f64,
    /// The event's kind (`GlobalPlan`, `Bump`, …).
    pub kind: String,
    /// How the log colours it.
    pub level: EventLevel,
    /// The event's fields (`null` for a kind without fields).
    #[cfg_attr(feature = "typescript", ts(type = "Record<string, unknown> | null"))]
    pub data: serde_json::Value,
}

impl EventView {
    /// The view of `e`.
    pub fn of(e: &SystemEvent) -> Self {
        let value = serde_json::to_value(&e.kind).unwrap_or(serde_json::Value::Null);
        let (kind, data) = match value {
            serde_json::Value::String(s) => (s, serde_json::Value::Null),
            serde_json::Value::Object(m) => match m.into_iter().next() {
                Some((k, v)) => (k, v),
                None => (String::new(), serde_json::Value::Null),
            },
            _ => (String::new(), serde_json::Value::Null),
        };
        Self {
            time_s: e.time_ns as f64 * 1e-9,
            kind,
            level: EventLevel::of(&e.kind),
            data,
        }
    }
}

/// The telemetry readout: where the robot is, what it does, the run's counters.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct TelemetryView {
    /// Simulated time \[s\].
    pub time_s: f64,
    /// The system's state.
    pub state: SystemState,
    /// Whether the robot drives (a plan is being followed).
    pub driving: bool,
    /// Which [`Status`](crate::system::Status) it is (`driving`, `arrived`, `no_route`, …): what the
    /// page ties its notices to.
    pub status_kind: String,
    /// Its fields (`component`, `reason`, `by`, `direction`, `retrying`, `v_cmd`, …), so the
    /// page can say the status in its own language with the same details; and `paused:
    /// true` while the session's clock is paused (a cause the status says, `status.paused`).
    #[cfg_attr(feature = "typescript", ts(type = "Record<string, unknown>"))]
    pub status_fields: serde_json::Map<String, serde_json::Value>,
    /// Whether the robot has arrived at the goal.
    pub arrived: bool,
    /// Whether the robot is halted (safe mode, a stop).
    pub halted: bool,
    /// Whether the clock is paused.
    pub paused: bool,
    /// Simulated seconds per wall second.
    pub speed: f64,
    /// The robot's pose.
    pub pose: PoseView,
    /// The body's radius as drawn \[m\] (MotorControl's `radiusOfBodyArea` in use).
    pub body_radius: f64,
    /// The start set, if any.
    pub start: Option<PoseView>,
    /// The goal set, if any.
    pub goal: Option<PoseView>,
    /// The driving direction.
    pub direction: DirectionView,
    /// Distance from the robot to the goal \[m\] (`null` without a goal).
    pub distance_to_goal: Option<f64>,
    /// Measured speed \[m/s\]: the physics' motion now (`Measured`), 0 while it does not
    /// execute.
    pub v: f64,
    /// Measured turn rate \[rad/s\] (as `v`).
    pub w: f64,
    /// Commanded speed \[m/s\].
    pub v_cmd: f64,
    /// Commanded turn rate \[rad/s\].
    pub w_cmd: f64,
    /// Deviation from the path \[m\] (`null` while there is none).
    #[cfg_attr(feature = "typescript", ts(type = "number | null"))]
    pub deviation: f64,
    /// Distance driven \[m\].
    pub path_length: f64,
    /// Global plans made.
    pub global_plans: u64,
    /// Local plans made.
    pub local_plans: u64,
    /// Plans that failed.
    pub planning_failures: u64,
    /// Bumps.
    pub bumps: u64,
    /// Smallest clearance to an obstacle so far \[m\] (`null` before the robot moved).
    pub min_clearance: Option<f64>,
}

/// The plan as data: start, goal, the paths in cells, the control points in metres.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct PlanView {
    /// The start set, if any.
    pub start: Option<PoseView>,
    /// The goal set, if any.
    pub goal: Option<PoseView>,
    /// The driving direction.
    pub direction: DirectionView,
    /// GlobalPathPlanning's route, cells `[x, y]`.
    pub global_path: Vec<(usize, usize)>,
    /// LocalPathPlanning's merged path, cells `[x, y]`.
    pub local_path: Vec<(usize, usize)>,
    /// The control points `[x, y]` \[m\].
    pub control_points: Vec<(f64, f64)>,
}

/// The map's geometry.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct MapView {
    /// The scenario's map file or the file the user loaded.
    pub name: String,
    /// Cells along x.
    pub width: usize,
    /// Cells along y.
    pub height: usize,
    /// Cell size \[m\].
    pub grid_size: f64,
    /// The world point of the map's corner `[x, y]` \[m\].
    pub origin: (f64, f64),
    /// Obstacle cells.
    pub obstacles: usize,
    /// Changes with every load and update.
    pub key: u64,
}

/// The scenario shown (name, description, the lesson's text).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ScenarioView {
    /// The scenario's name.
    pub name: String,
    /// One line about it.
    pub description: String,
    /// The lesson's text.
    pub lesson: String,
}

/// The clock as the system bar shows it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ClockView {
    /// Simulated time \[s\].
    pub time_s: f64,
    /// Simulated time owed to the clock and not yet run \[s\].
    pub behind_s: f64,
    /// Whether the clock is paused.
    pub paused: bool,
    /// Simulated seconds per wall second.
    pub speed: f64,
    /// One base tick \[s\] (a step of ±1 tick).
    pub tick_s: f64,
}

/// The scenario's exercise as the page's panel shows it: what the watch decided, and the
/// session's clock, so the panel never says the drive runs while the clock stands still.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct ExerciseView {
    /// The task, the checks and the verdict (`ExerciseWatch`'s).
    #[serde(flatten)]
    pub status: ExerciseStatus,
    /// Whether the session's clock is paused: an exercise waiting or running goes on only
    /// when it runs.
    pub paused: bool,
}

/// One frame's read of the session: everything the page shows every frame, read once and
/// handed to its panels.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct FrameView {
    /// The clock.
    pub clock: ClockView,
    /// The telemetry and the status.
    pub telemetry: TelemetryView,
    /// Every component, in data-flow order.
    pub components: Vec<ComponentView>,
    /// The events since the last frame, oldest first.
    pub events: Vec<EventView>,
    /// The scenario's exercise as it stands (`null` when it has none).
    pub exercise: Option<ExerciseView>,
}
