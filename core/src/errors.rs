//! The crate's error type: [`Error`] gathers one `thiserror` enum per area, each defined next
//! to the code it describes (`rtc/error.rs`, `map/error.rs`, `global/error.rs`,
//! `local/error.rs`, `motion/error.rs`, `render/error.rs`, `system/error.rs`) and re-exported
//! here.
//!
//! Every variant names the problem with named fields, so a GUI can show it and a test can
//! match it. Library code returns these; it does not panic on bad input.

pub use crate::global::GlobalPlanningError;
pub use crate::local::LocalPathError;
pub use crate::map::MapError;
pub use crate::motion::MotionError;
#[cfg(feature = "render")]
pub use crate::render::RenderError;
pub use crate::rtc::{ConfigError, LifecycleError, TimestampError};
pub use crate::system::{ConfBundleError, ScenarioError, SessionError, SystemError};

/// Any error `rtnav` returns.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An illegal lifecycle request or an execution-context problem (spec §1).
    #[error(transparent)]
    Lifecycle(#[from] LifecycleError),
    /// A configuration parameter or `.conf` file problem (spec §1).
    #[error(transparent)]
    Config(#[from] ConfigError),
    /// A timestamp refused where a sample entered a component (spec §4 Decision 0.2:
    /// `nsec` ≥ 10⁹), by [`Time::checked`](crate::rtc::Time::checked).
    #[error(transparent)]
    Timestamp(#[from] TimestampError),
    /// A map that cannot be built, loaded or updated (spec §2).
    #[error(transparent)]
    Map(#[from] MapError),
    /// A global plan that cannot be made (spec §5 "GlobalPathPlanning").
    #[error(transparent)]
    GlobalPlanning(#[from] GlobalPlanningError),
    /// A LocalPath service call refused, or a local plan that could not be made (spec §3).
    #[error(transparent)]
    LocalPath(#[from] LocalPathError),
    /// Bad input or parameters of the motion components (spec §4, §5).
    #[error(transparent)]
    Motion(#[from] MotionError),
    /// A scene or frame the renderer cannot draw (spec §5 InventGUI).
    #[cfg(feature = "render")]
    #[error(transparent)]
    Render(#[from] RenderError),
    /// A request to the whole system that cannot be carried out (spec §0).
    #[error(transparent)]
    System(#[from] SystemError),
    /// A scenario that cannot be read or used (spec §6).
    #[error(transparent)]
    Scenario(#[from] ScenarioError),
    /// A request of the page's session (clock, share links).
    #[error(transparent)]
    Session(#[from] SessionError),
    /// A configuration bundle that cannot be read or applied (spec §1).
    #[error(transparent)]
    ConfBundle(#[from] ConfBundleError),
}

/// `Result` with this crate's [`Error`].
pub type Result<T, E = Error> = core::result::Result<T, E>;
