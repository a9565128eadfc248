//! The whole system: every component wired as in spec §0, in one execution context at the
//! spec §6 rates, taking [`Input`]s; scenarios, their timeline and the one set-up builder;
//! the page's session.
//!
//! # Layers
//!
//! Each file of `system/` lives in the folder of its layer; a layer uses only itself and the
//! layers below it (`core/tests/tidy.rs` checks every import). From the bottom up:
//!
//! | layer | holds | may use | used by |
//! | --- | --- | --- | --- |
//! | `vocabulary/` | [`ComponentKind`], [`Rates`], [`Input`] (every request as one value), [`EventKind`] and [`SystemEvent`] (the facts), the errors, the JSON reader (`json_text.rs`), [`MAX_REPLAY_NS`] (`run_limit.rs`) | — | all above |
//! | `simulation/` | [`Wiring`] (`wiring.rs`: the execution context, the components, the service calls between ticks; each tick returns a [`Report`] of facts; `wiring/connections.rs`: every data connection as made, every service port with its calls, InventGUI's ports, cut and restore), [`Mission`] (start, goal, route, halt, and the arrival, decided there alone; `rest.rs`: rest, motion, tolerances), [`Record`] (log, totals, trail, clearance, telemetry and trace hash — written from the reports), [`System`] (`robot.rs`: the three composed; [`System::apply`], the one interpreter of [`Input`]), and the robot's views: [`Status`], [`ComponentActivity`], [`ParameterWarning`], [`SystemGraph`], [`CellInspection`], the `.conf` bundle | vocabulary | runs, sessions, the renderer |
//! | `runs/` | [`Scenario`] (and its content hash), [`setup::build`] (the one set-up builder), [`Timeline`] (a scenario's timed events from the drive's start), [`ScenarioRun`] (a headless run to its outcome), [`Comparison`] (one scenario, two set-ups), [`Exercise`] with its checks, [`ExerciseWatch`], [`ExerciseRun`] | simulation, vocabulary | sessions |
//! | `sessions/` | [`Session`] (`session.rs` and its children `session/`: the user interface's one boundary — clock, set-up record, share links, read-outs, replays and seeking), `History` (recorded inputs, checkpoints, timeline marks), [`Replay`] (a recorded run as a versioned JSON file), the view types ([`FrameView`], …), [`PickedFiles`], [`Refusal`] | runs, simulation, vocabulary | the wasm layer, the screen |
//!
//! Who may not know what: the wiring knows nothing of the mission, the record or any user
//! interface; the mission never calls a component; the record never changes what it
//! observes; [`System`] holds no clock, script, preview or drawing buffer.
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

mod runs;
mod sessions;
mod simulation;
mod vocabulary;

pub use runs::compare::{ComparePlots, CompareTable, Comparison, RunSummary, compare, setup_with};
pub use runs::exercise::{
    Check, CheckState, CheckStatus, DecidedBy, Exercise, ExerciseStatus, Stuck, Unit, Verdict,
};
pub use runs::exercise_run::{DriveInput, ExerciseRun, check_exercise};
pub use runs::exercise_watch::ExerciseWatch;
pub use runs::runner::{
    EndReason, Outcome, STILL_NS, ScenarioReport, ScenarioRun, judge, run_scenario,
};
#[cfg(not(target_arch = "wasm32"))]
pub use runs::scenario::DirResolver;
pub use runs::scenario::{
    BoxSpec, DirectionSpec, Expectation, FileResolver, MapSource, MemoryResolver, OutcomeKind,
    PoseSpec, Scenario, ScenarioEvent, UnknownSpec,
};
pub use runs::setup::{self, BuildOptions, ScriptText, Setup};
pub use runs::timeline::Timeline;
pub use sessions::history::{MAX_CHECKPOINTS, Mark, MarkKind, TimelineView};
pub use sessions::picked_files::{PickError, PickedFiles};
pub use sessions::refusal::Refusal;
pub use sessions::replay::{Replay, TimedInput};
pub use sessions::session::{
    ComponentParameters, MAX_PLOT_SECONDS, MAX_SPEED, MAX_STEP_MS, MIN_SPEED, ParameterView,
    PlotWindow, ReplayCheck, Session, TOKEN_INFLATE_LIMIT, TUNABLE,
};
pub use sessions::views::{
    ClockView, ComponentView, DirectionView, EventLevel, EventView, ExerciseView, FrameView,
    MapView, PlanView, PoseView, ScenarioView, TelemetryView,
};
pub use simulation::activity::{ComponentActivity, Held, ZeroOutput};
pub use simulation::conf_bundle::CONF_BUNDLE_HEADER;
pub use simulation::graph::{
    ConnectionKind, Endpoint, GraphComponent, GraphConnection, GraphPort, PortKind, SystemGraph,
};
pub use simulation::inspect::{CellInspection, FieldInspection, ParentInspection};
pub use simulation::mission::Mission;
pub use simulation::parameter_warning::ParameterWarning;
pub use simulation::record::{EVENT_CAPACITY, Record, RunStats};
pub use simulation::rest::{
    ARRIVAL_HEADING_DEG, Measured, Motion, Offset, REST_SPEED, REST_TURN_RATE, Tolerances,
};
pub use simulation::robot::System;
pub use simulation::status::{ComponentInfo, Status, SystemState};
pub use simulation::telemetry::{DEFAULT_TELEMETRY_CAPACITY, Telemetry, TelemetrySample};
pub use simulation::wiring::{MotorReadings, Report, Wiring};
pub use vocabulary::error::{ConfBundleError, ScenarioError, SessionError, SystemError};
pub use vocabulary::events::{EventKind, SystemEvent};
pub use vocabulary::input::{Input, InputSummary, RequestSource};
pub use vocabulary::kind::ComponentKind;
pub use vocabulary::rates::Rates;
pub use vocabulary::run_limit::MAX_REPLAY_NS;
