//! The session: the system as a person drives it, the user interface's one boundary
//! ([`Session`](session::Session): the clock, the set-up record and share links, the
//! read-outs a user interface shows, replays and seeking, all in `session.rs` and its
//! children `session/`), what it keeps of a run ([`History`](history::History)), the
//! replay file ([`Replay`](replay::Replay)), the plain view types it returns, the files a
//! person picked, and a refused request as a user interface shows it.
//!
//! It may use: every layer below (`super::runs`, `super::simulation`, `super::vocabulary`)
//! and the crate outside `system/`.
//! Used by: nothing of `system/`; the wasm layer binds a `Session`, the renderer's
//! `Screen` pictures one, and the command line and tests use it through the public API.

pub(super) mod history;
pub(super) mod picked_files;
pub(super) mod refusal;
pub(super) mod replay;
pub(super) mod session;
pub(super) mod views;
