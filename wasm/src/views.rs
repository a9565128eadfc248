//! What the page reads, as JSON: plain serde structs built from the system's own values.

use rtnav::interfaces::{Direction, Pose};
use rtnav::rtc::LifecycleState;
use rtnav::system::{ComponentInfo, EventKind, SystemEvent, SystemState};
use serde::Serialize;

/// A pose with its heading in degrees (what a person reads).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub(crate) struct PoseView {
    pub x: f64,
    pub y: f64,
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

/// `forward` / `backward`.
pub(crate) fn direction_name(d: Direction) -> &'static str {
    match d {
        Direction::Forward => "forward",
        Direction::Backward => "backward",
    }
}

/// One component as the RTC panel shows it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub(crate) struct ComponentView {
    /// The component's name (`LocalPathPlanning`): what the lifecycle calls take.
    pub name: &'static str,
    #[serde(flatten)]
    pub info: ComponentInfo,
    /// The RT System Editor's colour of its state, `#rrggbb`.
    pub colour: &'static str,
    /// Whether an injected fault waits for its next execution.
    pub fault_pending: bool,
}

/// One entry of the event log.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub(crate) struct EventView {
    /// Simulated time \[s\].
    pub time_s: f64,
    /// The event's kind (`GlobalPlan`, `Bump`, …).
    pub kind: String,
    /// `info`, `state`, `success`, `warn` or `error`: how the log colours it.
    pub level: &'static str,
    /// The core's words for it.
    pub text: String,
    /// The event's fields.
    pub data: serde_json::Value,
}

impl EventView {
    pub(crate) fn of(e: &SystemEvent) -> Self {
        let level = match &e.kind {
            EventKind::Bump { .. } | EventKind::ComponentError { .. } => "error",
            EventKind::StateChanged { to, .. } if *to == LifecycleState::Error => "error",
            EventKind::StateChanged { .. } => "state",
            EventKind::PlanningFailed { .. }
            | EventKind::SafeMode
            | EventKind::Cleared
            | EventKind::ClearanceWarning { .. }
            | EventKind::SafetyStop { .. }
            | EventKind::ConnectionCut { .. }
            | EventKind::RequestRefused { .. } => "warn",
            EventKind::Arrived { .. } => "success",
            _ => "info",
        };
        let value = serde_json::to_value(&e.kind).unwrap_or(serde_json::Value::Null);
        let (kind, data) = match value {
            serde_json::Value::String(s) => (s, serde_json::Value::Null),
            serde_json::Value::Object(m) => match m.into_iter().next() {
                Some((k, v)) => (k, v),
                None => (String::new(), serde_json::Value::Null),
            },
            _ => (String::new(), serde_json::Value::Null),
        };
        // The core's Display starts with the time in brackets; the log shows it apart.
        let full = e.to_string();
        let text = match full.split_once("] ") {
            Some((_, t)) => t.to_owned(),
            None => full,
        };
        Self {
            time_s: e.time_ns as f64 * 1e-9,
            kind,
            level,
            text,
            data,
        }
    }
}

/// The telemetry readout.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub(crate) struct TelemetryView {
    pub time_s: f64,
    pub state: SystemState,
    pub driving: bool,
    /// What the robot is doing, in words (`rtnav::system::Status`).
    pub status: String,
    /// Which [`Status`](rtnav::system::Status) it is (`driving`, `arrived`, `no_route`, …):
    /// what the page ties its notices to.
    pub status_kind: String,
    /// Its fields (`component`, `reason`, `by`, `direction`, `retrying`, `v_cmd`, …), so the
    /// page can say the status in its own language with the same details.
    pub status_fields: serde_json::Map<String, serde_json::Value>,
    pub arrived: bool,
    pub halted: bool,
    pub paused: bool,
    pub speed: f64,
    pub pose: PoseView,
    /// The body's radius as drawn \[m\] (MotorControl's `radiusOfBodyArea` in use).
    pub body_radius: f64,
    pub start: Option<PoseView>,
    pub goal: Option<PoseView>,
    pub direction: &'static str,
    /// Distance from the robot to the goal \[m\] (`null` without a goal).
    pub distance_to_goal: Option<f64>,
    /// Actual and commanded speed \[m/s\] and turn rate \[rad/s\] (the last sample).
    pub v: f64,
    pub w: f64,
    pub v_cmd: f64,
    pub w_cmd: f64,
    /// Deviation from the path \[m\] (`null` while there is none).
    pub deviation: f64,
    pub path_length: f64,
    pub global_plans: u64,
    pub local_plans: u64,
    pub planning_failures: u64,
    pub bumps: u64,
    /// Smallest clearance to an obstacle so far \[m\] (`null` before the robot moved).
    pub min_clearance: Option<f64>,
}

/// The plan as data (the tests check that a path avoids what was painted).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub(crate) struct PlanView {
    pub start: Option<PoseView>,
    pub goal: Option<PoseView>,
    pub direction: &'static str,
    pub global_path: Vec<(usize, usize)>,
    pub local_path: Vec<(usize, usize)>,
    pub control_points: Vec<(f64, f64)>,
}

/// The map's geometry.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub(crate) struct MapView {
    /// The scenario's map file or the file the user loaded.
    pub name: String,
    pub width: usize,
    pub height: usize,
    pub grid_size: f64,
    pub origin: (f64, f64),
    pub obstacles: usize,
    /// Changes with every load and update.
    pub key: u64,
}

/// The scenario shown (name, description, the lesson's text).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub(crate) struct ScenarioView {
    pub name: String,
    pub description: String,
    pub lesson: String,
}
