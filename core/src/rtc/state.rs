//! The states and requests of the RT-component lifecycle (spec §1, seed 003
//! "RTCの状態遷移").

use core::fmt;

use serde::{Deserialize, Serialize};

/// A component's lifecycle state (003 "コンポーネント・ライフサイクル").
///
/// `Inactive`, `Active` and `Error` are the three sub-states of `Alive`; the RT System Editor
/// draws them blue, green and red.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub enum LifecycleState {
    /// Created, but `on_initialize` has not succeeded.
    Created,
    /// Alive and inactive: waits to be activated.
    Inactive,
    /// Alive and active: `on_execute` runs every tick of its period.
    Active,
    /// Alive in error: `on_error` runs every tick until a reset succeeds.
    Error,
    /// `on_finalize` has run; nothing more is possible.
    Finalized,
}

impl LifecycleState {
    /// Whether the component is in `Alive` (Inactive, Active or Error).
    pub fn is_alive(self) -> bool {
        matches!(self, Self::Inactive | Self::Active | Self::Error)
    }

    /// The colour OpenRTM's RT System Editor uses for this state, as `#rrggbb`.
    pub fn editor_colour(self) -> &'static str {
        match self {
            Self::Created | Self::Finalized => "#808080",
            Self::Inactive => "#0000ff",
            Self::Active => "#00ff00",
            Self::Error => "#ff0000",
        }
    }
}

impl fmt::Display for LifecycleState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Created => "Created",
            Self::Inactive => "Inactive",
            Self::Active => "Active",
            Self::Error => "Error",
            Self::Finalized => "Finalized",
        })
    }
}

/// The execution context's own state (003 "スレッドの停止状態と実行状態").
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum ContextState {
    /// No callback runs.
    Stopped,
    /// Ticks drive the components.
    Running,
}

impl fmt::Display for ContextState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Stopped => "Stopped",
            Self::Running => "Running",
        })
    }
}

/// A request made of a component from outside (the GUI, the RT System Editor, a test).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum Request {
    /// Run `on_initialize` again after it failed (Created → Inactive).
    Initialize,
    /// Inactive → Active.
    Activate,
    /// Active → Inactive.
    Deactivate,
    /// Error → Inactive.
    Reset,
    /// Any → Finalized.
    Finalize,
    /// Change the component's execution rate.
    ChangeRate,
    /// Make the next `on_execute` fail (a teaching aid).
    InjectFault,
    /// Put another component in its place: a student's script, or the built-in one back
    /// (spec §8).
    Replace,
}

impl fmt::Display for Request {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Initialize => "initialize",
            Self::Activate => "activate",
            Self::Deactivate => "deactivate",
            Self::Reset => "reset",
            Self::Finalize => "finalize",
            Self::ChangeRate => "change the rate",
            Self::InjectFault => "inject a fault",
            Self::Replace => "replace it",
        })
    }
}
