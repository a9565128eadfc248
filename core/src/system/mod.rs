//! The whole system: every component wired as in SPEC §0, in one execution context at the
//! SPEC §6 rates; the GUI-facing API; scenarios; telemetry and the trace hash.
//!
//! # Wiring (SPEC §0)
//!
//! Data ports, connected with `OutPort::connect`:
//!
//! | from | to |
//! | --- | --- |
//! | PhysicsSim `angle`, `position` | MotorControl `InCurrentWheelAngle`, `InSimulatedPosition` |
//! | MotorControl `Torque` | PhysicsSim `torque` |
//! | MotorControl `OutCurrentWheelAngle`, `OutSimulatedPositionToLocalization` | Localization `InCurrentWheelAngle`, `InSimulatedPosition` |
//! | Localization `OutCurrentPosition` | LocalPathPlanning and DriveControl `InCurrentPosition` |
//! | LocalPathPlanning `DriveCons` | DriveControl `InControlPoints` |
//! | DriveControl `TargetVelocity` | MotorControl `TargetVelocity` |
//! | DriveControl `OutDeviating` | LocalPathPlanning `InDeviating` |
//!
//! The seeds' service calls are made by the system between ticks. It holds an `InPort`
//! (a *bridge*) on each port that stands for a service call or a GUI notice, reads them after
//! every tick and after every GUI request, and calls the services:
//!
//! | bridge on | service calls / event |
//! | --- | --- |
//! | MapBuilder `SetMap` | `SetMap` on MapMaintenance, GlobalPathPlanning, LocalPathPlanning, PhysicsSim |
//! | MapMaintenance `MapUpdate` | `MapUpdate` on GlobalPathPlanning, PhysicsSim, LocalPathPlanning |
//! | GlobalPathPlanning `GlobalPathCourse` | `GlobalPathCourse` on LocalPathPlanning |
//! | GlobalPathPlanning `PlanningFailure`, LocalPathPlanning `InventGUIConsFailure` | planning-failed event |
//! | LocalPathPlanning `InventGUICons` | local-plan-sent event |
//! | PhysicsSim `bump` | MotorControl `Stop`, bump event |
//!
//! # Order (data-flow order)
//!
//! Components are attached — and so run within a tick — in the order of
//! [`ComponentKind::ALL`]: MapBuilder, MapMaintenance (the map sources), PhysicsSim,
//! MotorControl, Localization (the 1 kHz loop: the world steps with the torque computed last
//! tick, MotorControl reads the fresh wheel angles and pose and sends the new torque,
//! Localization publishes the fresh pose), GlobalPathPlanning, LocalPathPlanning (10 Hz: they
//! plan from the fresh pose), DriveControl (50 Hz: it follows the newest control points from
//! the fresh pose; its velocity reaches MotorControl on the next tick). A service call made by
//! the system after tick `k` is seen by the component on its next run.
//!
//! # Rates (SPEC §6)
//!
//! [`Rates`]: physics, MotorControl, Localization 1 kHz; DriveControl 50 Hz; local and
//! global planning 10 Hz; MapBuilder and MapMaintenance 10 Hz; telemetry 50 Hz. The base
//! tick is the highest rate (1 ms by default).
//!
//! # The GUI-facing API (what InventGUI did)
//!
//! - Map: [`System::load_map`], [`System::load_map_from`] (a file through a
//!   [`FileResolver`]; a bad file leaves the old map), [`System::map_update`] /
//!   [`System::set_cells`] (checked completely, atomic), [`System::schedule_map_update`].
//! - Goals: [`System::set_position`] (`SetPosition`: places the robot at the start in the
//!   physics and Localization; refused while driving), [`System::set_goal`] (a new goal from
//!   where the robot is, also while driving), [`System::clear`], [`System::safe_mode`].
//!   Bad input (NaN, outside the map, within `dmin` of an obstacle) is refused with
//!   LocalPathPlanning's error and changes nothing.
//! - Lifecycle: activate / deactivate / reset of all components ([`System::activate_all`],
//!   [`System::deactivate_all`], [`System::reset_all`]) or one ([`System::activate`], …),
//!   [`System::inject_fault`], [`System::set_rate`]; [`System::state`] and
//!   [`System::component_info`] (state, last error, rate, status); each component's
//!   parameters as `&mut dyn ConfigAccess` ([`System::config_mut`]).
//! - Teaching tools: [`System::config`] (read-only twin of `config_mut`), the whole
//!   configuration as one OpenRTM `.conf` text ([`System::to_conf`], [`System::load_conf`],
//!   all-or-nothing), [`System::inspect_cell`] (map and potential field at one cell).
//! - Running: [`System::step`] (base ticks), [`System::run_for`], [`System::run_until`];
//!   [`System::preview`] plans without driving (the page's first frame, `rtnav render`).
//! - Output: [`System::events`] ([`SystemEvent`], stamped with the simulated time of the tick
//!   that caused them), [`System::telemetry`] ([`TelemetrySample`] at the telemetry rate, a
//!   bounded history, and the SHA-256 trace hash over every sample), [`System::stats`]
//!   (path length, exact minimum clearance, plans, bumps), `System::scene` (feature
//!   `render`: the renderer's `Scene` of the current state).
//!
//! A bump fails the physics' `on_execute` with the bump report as the reason: the physics
//! goes to Error (the robot stands still), MotorControl gets `Stop`, the system's state is
//! Error; [`System::reset_all`] brings every component back to Inactive.
//!
//! # Scenarios
//!
//! [`Scenario`] files (`fixtures/scenarios/*.json`) give the map, start and goal,
//! configuration, rates, timed events and the expected outcome; [`ScenarioRun`] /
//! [`run_scenario`] drive the system to the outcome and report ([`ScenarioReport`]).

mod clearance;
mod events;
mod kind;
// --- teaching tools (branch `teachcore`): the configuration bundle, the cell inspector ---
mod conf_bundle;
mod inspect;
pub use conf_bundle::CONF_BUNDLE_HEADER;
pub use inspect::{CellInspection, FieldInspection};

mod rates;
mod runner;
mod runtime;
mod scenario;
#[cfg(feature = "render")]
mod scene;
mod script;
mod session;
mod telemetry;

pub use clearance::{ClearanceTracker, clearance, clearance_lower_bound, could_be_below};
pub use events::{EventKind, SystemEvent};
pub use kind::ComponentKind;
pub use rates::Rates;
pub use runner::{
    ARRIVAL_HEADING_DEG, Outcome, STILL_NS, ScenarioReport, ScenarioRun, run_scenario,
};
pub use runtime::{
    ComponentInfo, EVENT_CAPACITY, PLAN_TIMES_CAPACITY, RunStats, System, SystemState,
    TRAIL_CAPACITY,
};
#[cfg(not(target_arch = "wasm32"))]
pub use scenario::DirResolver;
pub use scenario::{
    BoxSpec, DirectionSpec, Expectation, FileResolver, MapSource, MemoryResolver, OutcomeKind,
    PoseSpec, Scenario, ScenarioEvent, UnknownSpec,
};
pub use session::{
    ComponentParameters, MAX_PLOT_SECONDS, MAX_SPEED, MAX_STEP_MS, MIN_SPEED, PREVIEW_SECONDS,
    ParameterView, PlotWindow, Session, Setup, TUNABLE,
};
pub use telemetry::{DEFAULT_TELEMETRY_CAPACITY, Telemetry, TelemetrySample};
