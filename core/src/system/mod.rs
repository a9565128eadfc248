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

mod clearance;
mod events;
mod kind;
mod rates;
mod runner;
mod runtime;
mod scenario;
#[cfg(feature = "render")]
mod scene;
mod telemetry;

pub use clearance::{ClearanceTracker, clearance, clearance_lower_bound, could_be_below};
pub use events::{EventKind, SystemEvent};
pub use kind::ComponentKind;
pub use rates::Rates;
pub use runner::{
    ARRIVAL_HEADING_DEG, Outcome, STILL_NS, ScenarioReport, ScenarioRun, run_scenario,
};
pub use runtime::{ComponentInfo, EVENT_CAPACITY, RunStats, System, SystemState, TRAIL_CAPACITY};
#[cfg(not(target_arch = "wasm32"))]
pub use scenario::DirResolver;
pub use scenario::{
    BoxSpec, DirectionSpec, Expectation, FileResolver, MapSource, MemoryResolver, OutcomeKind,
    PoseSpec, Scenario, ScenarioEvent, UnknownSpec,
};
pub use telemetry::{DEFAULT_TELEMETRY_CAPACITY, Telemetry, TelemetrySample};
