//! The simulated robot: the eight components wired in one execution context
//! ([`Wiring`](wiring::Wiring), with the record of its connections in
//! `wiring/connections.rs`), what it is told to do and has done
//! ([`Mission`](mission::Mission), [`Record`](record::Record), telemetry), the three
//! composed ([`System`](robot::System), one interpreter of requests), and the robot's
//! own views of itself: its status, the components' activities, the parameters' warnings,
//! its description ([`SystemGraph`](graph::SystemGraph)), the cell inspector, the whole
//! configuration as one `.conf`.
//!
//! It may use: the vocabulary (`super::vocabulary`) and the crate outside `system/`. It
//! knows nothing of scenarios, runs, sessions or user interfaces.
//! Used by: `runs` and `sessions`; the renderer (`render::of_system`) draws a `System`.

pub(super) mod activity;
pub(super) mod conf_bundle;
pub(super) mod graph;
pub(super) mod inspect;
pub(super) mod mission;
pub(super) mod parameter_warning;
mod placement;
pub(super) mod record;
pub(super) mod rest;
pub(super) mod robot;
pub(super) mod status;
pub(super) mod telemetry;
pub(super) mod wiring;
