//! Scenarios and their runs: a scenario file ([`Scenario`](scenario::Scenario), its content
//! hash), the one set-up builder ([`setup::build`]), its timed events
//! ([`Timeline`](timeline::Timeline)), a headless run to its outcome
//! ([`ScenarioRun`](runner::ScenarioRun)), one scenario with two set-ups
//! ([`Comparison`](compare::Comparison)), and exercises — their checks, the watch that
//! decides them, a hand-in done headlessly.
//!
//! It may use: the simulated robot (`super::simulation`), the vocabulary and the crate
//! outside `system/`. It knows nothing of a session or a user interface.
//! Used by: `sessions`, and through the public API the command line and the tests.

pub(super) mod compare;
pub(super) mod content_hash;
pub(super) mod exercise;
pub(super) mod exercise_run;
pub(super) mod exercise_watch;
pub(super) mod runner;
pub(super) mod scenario;
pub mod setup;
pub(super) mod timeline;
