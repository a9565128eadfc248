//! Errors of the component model: lifecycle requests and the execution context (spec §1,
//! seed 003), configuration parameters and `.conf` files.

use super::{ContextState, LifecycleState, Request};

/// Errors of the RT-component lifecycle and execution context (spec §1, seed 003).
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum LifecycleError {
    /// The request is not a legal transition from the component's current state.
    #[error("component `{component}`: cannot {request} while {from}")]
    InvalidTransition {
        /// The component's instance name.
        component: String,
        /// Its state when the request arrived (unchanged).
        from: LifecycleState,
        /// What was asked.
        request: Request,
    },
    /// Activate / deactivate / reset need a running execution context (no callback runs while
    /// it is Stopped, 003 "スレッドの停止状態と実行状態").
    #[error("component `{component}`: cannot {request} while the execution context is {context}")]
    ContextNotRunning {
        /// The component's instance name.
        component: String,
        /// What was asked.
        request: Request,
        /// The context's state.
        context: ContextState,
    },
    /// Start while Running or stop while Stopped.
    #[error("execution context is already {state}")]
    ContextAlready {
        /// The state it is already in.
        state: ContextState,
    },
    /// No component with that id is attached.
    #[error("no component with id {id}")]
    UnknownComponent {
        /// The id asked for.
        id: usize,
    },
    /// A rate that is not positive and finite, above the highest rate
    /// ([`MAX_BASE_RATE_HZ`](super::MAX_BASE_RATE_HZ)), or whose period is not a whole
    /// number of the context's base ticks ([`period_ticks`](super::period_ticks)).
    #[error("{component}: rate {rate} Hz is not usable: {reason}")]
    InvalidRate {
        /// Whose rate: a component's instance name, `telemetry`, `the base tick`.
        component: String,
        /// The rate asked for, in Hz.
        rate: f64,
        /// Why it was refused.
        reason: String,
    },
    /// A callback returned an error; the state change it caused is described by `outcome`.
    #[error("component `{component}`: {callback} failed: {reason}")]
    CallbackFailed {
        /// The component's instance name.
        component: String,
        /// The callback that failed, e.g. `on_activated`.
        callback: &'static str,
        /// The reason the callback gave.
        reason: String,
    },
}

/// Errors of configuration parameters and `.conf` files (spec §1).
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum ConfigError {
    /// No parameter of that name.
    #[error("unknown configuration parameter `{name}`{}", at_line(*line))]
    UnknownParameter {
        /// The key as written.
        name: String,
        /// 1-based line in the `.conf` file, if it came from one.
        line: Option<usize>,
    },
    /// A value outside the parameter's range (or NaN).
    #[error("configuration parameter `{name}`{}: {value} is out of range {range}", at_line(*line))]
    OutOfRange {
        /// The parameter.
        name: String,
        /// The value refused.
        value: String,
        /// The allowed range, e.g. `[0, 100]`.
        range: String,
        /// 1-based line in the `.conf` file, if it came from one.
        line: Option<usize>,
    },
    /// A value that does not parse as the parameter's type.
    #[error("configuration parameter `{name}`{}: `{value}` is not a valid {kind}", at_line(*line))]
    BadValue {
        /// The parameter.
        name: String,
        /// The text refused.
        value: String,
        /// The expected type, e.g. `double` (serialized as `type`: `kind` names the variant).
        #[serde(rename = "type")]
        kind: &'static str,
        /// 1-based line in the `.conf` file, if it came from one.
        line: Option<usize>,
    },
    /// A `.conf` line that is not `key: value`, a comment or blank.
    #[error("line {line}: cannot read `{text}`: {reason}")]
    Syntax {
        /// 1-based line number.
        line: usize,
        /// The line as written.
        text: String,
        /// What is wrong with it.
        reason: String,
    },
    /// No configuration set of that name.
    #[error("unknown configuration set `{name}`")]
    UnknownSet {
        /// The set asked for.
        name: String,
    },
}

fn at_line(line: Option<usize>) -> String {
    line.map(|l| format!(" (line {l})")).unwrap_or_default()
}

/// A timestamp whose `nsec` is not below 10⁹ (spec §4 Decision 0.2): refused where the
/// sample enters, by [`Time::checked`](super::Time::checked).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error, serde::Serialize)]
#[error(
    "{what}: timestamp {{sec: {sec}, nsec: {nsec}}} is not valid: nsec must be below 1000000000"
)]
pub struct TimestampError {
    /// Where the sample entered: the port or service (seed names, e.g. `TargetVelocity`,
    /// `MapUpdate`).
    pub what: &'static str,
    /// The seconds given.
    pub sec: u32,
    /// The nanoseconds given (≥ 10⁹).
    pub nsec: u32,
}
