//! The whole system: every component wired as in spec §0, in one execution context at the
//! spec §6 rates, taking [`Input`]s; scenarios, their timeline and the one set-up builder;
//! the page's session.
//!
//! # Parts
//!
//! | part | holds | may not know |
//! | --- | --- | --- |
//! | [`Wiring`] (`wiring.rs`) | the execution context, the components, their connections, the service calls between ticks; each tick returns a [`Report`] of facts | the mission, the record, any user interface |
//! | [`Mission`] (`mission.rs`) | start, goal, direction, route, epochs, halt, and the arrival — decided there alone (`rest.rs`: rest, motion, tolerances) | the record; it never calls a component |
//! | [`Record`] (`record.rs`) | the event log, totals, trail, clearance, telemetry and trace hash — written from the reports | it never changes anything it observes |
//! | [`System`] (`robot.rs`) | the three composed: [`System::apply`] (the one interpreter of [`Input`]), [`System::step`], [`System::run_until`] | clocks, scripts, previews, drawing buffers |
//! | [`SystemGraph`] (`graph.rs`, from `links.rs`) | the system's description: components, ports, connections, last samples and calls | — |
//! | [`Timeline`] (`timeline.rs`) | a scenario's timed events, counted from the drive's start | — |
//! | [`setup::build`] (`setup.rs`) | the one set-up builder (runner, renderer, page, tests) | — |
//! | [`ScenarioRun`] (`runner.rs`) | a headless run to its outcome | — |
//! | [`Comparison`] (`compare.rs`) | one scenario run with two set-ups, side by side | — |
//! | [`Session`] (`session.rs`, `session_replay.rs`) | the user interface's one boundary: clock, set-up record, share links, read-outs, replays and seeking | — |
//! | [`Replay`] (`replay.rs`) | a recorded run as a versioned JSON file: set-up and timed [`Input`]s, exact numbers | — |
//! | `History` (`history.rs`) | a session's recorded inputs, checkpoints and timeline marks | — |
//!
//! # Wiring (spec §0)
//!
//! Data ports, connected with `OutPort::connect`:
//!
//! | from | to |
//! | --- | --- |
//! | PhysicsSim `angle`, `position` | MotorControl `InCurrentWheelAngle`, `InSimulatedPosition` |
//! | MotorControl `Torque` | PhysicsSim `torque` |
//! | MotorControl `OutCurrentWheelAngle`, `OutSimulatedPositionToLocalization` | Localization `InCurrentWheelAngle`, `InSimulatedPosition` |
//! | Localization `OutCurrentPosition` | LocalPathPlanning, DriveControl and GlobalPathPlanning `InCurrentPosition` |
//! | LocalPathPlanning `DriveCons` | DriveControl `InControlPoints` |
//! | DriveControl `TargetVelocity` | MotorControl `TargetVelocity` |
//! | DriveControl `OutDeviating` | LocalPathPlanning `InDeviating` |
//!
//! The seeds' service calls are made by the wiring between ticks. It holds an `InPort` (a
//! *bridge*) on each port that stands for a service call or a notice, reads them after every
//! tick and after every request, and calls the services:
//!
//! | bridge on | service calls / fact |
//! | --- | --- |
//! | MapBuilder `SetMap` | `SetMap` on MapMaintenance, GlobalPathPlanning, LocalPathPlanning, PhysicsSim |
//! | MapMaintenance `MapUpdate` | `MapUpdate` on GlobalPathPlanning, PhysicsSim, LocalPathPlanning |
//! | GlobalPathPlanning `GlobalPathCourse` | `GlobalPathCourse` on LocalPathPlanning |
//! | GlobalPathPlanning `PlanningFailure`, LocalPathPlanning `InventGUIConsFailure` | planning-failed fact |
//! | LocalPathPlanning `InventGUICons` | path-sent fact |
//! | PhysicsSim `bump` | MotorControl `Stop`, bump fact |
//!
//! # Order (data-flow order)
//!
//! Components are attached — and so run within a tick — in the order of
//! [`ComponentKind::ALL`]: MapBuilder, MapMaintenance (the map sources), PhysicsSim,
//! MotorControl, Localization (the 1 kHz loop: the world steps with the torque computed last
//! tick, MotorControl reads the fresh wheel angles and pose and sends the new torque,
//! Localization publishes the fresh pose), GlobalPathPlanning, LocalPathPlanning (10 Hz: they
//! plan from the fresh pose), DriveControl (50 Hz: it follows the newest control points from
//! the fresh pose; its velocity reaches MotorControl on the next tick). A service call made
//! after tick `k` is seen by the component on its next run.
//!
//! # Rates (spec §6)
//!
//! [`Rates`]: physics, MotorControl, Localization 1 kHz; DriveControl 50 Hz; local and
//! global planning 10 Hz; MapBuilder and MapMaintenance 10 Hz; telemetry 50 Hz. The base
//! tick is the highest rate (1 ms by default).
//!
//! A bump fails the physics' `on_execute` with the bump report as the reason: the physics
//! goes to Error (the robot stands still), MotorControl gets `Stop`; `Input::ResetAll`
//! brings every component back to Inactive.

mod activity;
mod compare;
mod conf_bundle;
mod content_hash;
mod error;
mod events;
mod exercise;
mod exercise_run;
mod exercise_watch;
mod graph;
mod history;
mod input;
mod inspect;
mod json_text;
mod kind;
mod links;
mod mission;
mod parameter_warning;
mod picked_files;
mod rates;
mod record;
mod refusal;
mod replay;
mod rest;
mod robot;
mod run_limit;
mod runner;
mod scenario;
mod session;
pub mod setup;
mod status;
mod telemetry;
mod timeline;
mod views;
mod wiring;

pub use activity::{ComponentActivity, Held, ZeroOutput};
pub use compare::{ComparePlots, CompareTable, Comparison, RunSummary, compare, setup_with};
pub use conf_bundle::CONF_BUNDLE_HEADER;
pub use error::{ConfBundleError, MAP_FILES_EXPECTED, ScenarioError, SessionError, SystemError};
pub use events::{EventKind, SystemEvent};
pub use exercise::{
    Check, CheckState, CheckStatus, Exercise, ExerciseStatus, ParameterValues, Unit, Verdict,
    parameter_values,
};
pub use exercise_run::{DriveInput, ExerciseRun, check_exercise};
pub use exercise_watch::ExerciseWatch;
pub use graph::{
    ConnectionKind, Endpoint, GraphComponent, GraphConnection, GraphPort, PortKind, SystemGraph,
};
pub use history::{
    CHECKPOINT_CELLS, CHECKPOINT_NS, CHECKPOINT_SAMPLES, MAX_CHECKPOINTS, Mark, MarkKind,
    TimelineView,
};
pub use input::{Input, InputSummary, RequestSource};
pub use inspect::{CellInspection, FieldInspection, ParentInspection};
pub use kind::ComponentKind;
pub use links::Peer;
pub use mission::Mission;
pub use parameter_warning::ParameterWarning;
pub use picked_files::{PickError, PickedFiles};
pub use rates::Rates;
pub use record::{EVENT_CAPACITY, PLAN_TIMES_CAPACITY, Record, RunStats, TRAIL_CAPACITY};
pub use refusal::Refusal;
pub use replay::{MAX_REPLAY_BYTES, REPLAY_FORMAT, REPLAY_VERSION, Replay, TimedInput};
pub use rest::{
    ARRIVAL_HEADING_DEG, Measured, Motion, Offset, REST_SPEED, REST_TURN_RATE, Tolerances,
};
pub use robot::System;
pub use run_limit::MAX_REPLAY_NS;
pub use runner::{EndReason, Outcome, STILL_NS, ScenarioReport, ScenarioRun, judge, run_scenario};
#[cfg(not(target_arch = "wasm32"))]
pub use scenario::DirResolver;
pub use scenario::{
    BoxSpec, DirectionSpec, Expectation, FileResolver, MapSource, MemoryResolver, OutcomeKind,
    PoseSpec, Scenario, ScenarioEvent, UnknownSpec,
};
pub use session::{
    ComponentParameters, MAX_PLOT_SECONDS, MAX_SPEED, MAX_STEP_MS, MIN_SPEED, ParameterView,
    PlotWindow, ReplayCheck, Session, TOKEN_INFLATE_LIMIT, TUNABLE,
};
pub use setup::{BuildOptions, PLAN_SECONDS, Setup};
pub use status::{ComponentInfo, Status, SystemState};
pub use telemetry::{DEFAULT_TELEMETRY_CAPACITY, Telemetry, TelemetrySample};
pub use timeline::Timeline;
pub use views::{
    ClockView, ComponentView, DirectionView, EventLevel, EventView, ExerciseView, FrameView,
    MapView, PlanView, PoseView, ScenarioView, TelemetryView,
};
pub use wiring::{Report, Wiring};
