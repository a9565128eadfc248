//! Errors of the motion components (spec §4, §5).

/// Errors of the motion components: MotorControl (spec §4), the physics, DriveControl and
/// Localization (spec §5). A component that meets one of these on a data port does not fail:
/// it goes to its safe state (zero torque, zero velocity, the held pose) and reports it.
#[derive(Debug, Clone, PartialEq, thiserror::Error, serde::Serialize, strum::VariantNames)]
#[serde(tag = "kind")]
#[non_exhaustive]
pub enum MotionError {
    /// A NaN or infinite number where a finite one is needed.
    #[error("{port}: {field} = {value} is not finite")]
    NonFinite {
        /// The port, service or parameter that carried it (seed name).
        port: &'static str,
        /// Which value, e.g. `vx`, `data[1]`.
        field: String,
        /// The value.
        value: f64,
    },
    /// A sequence of the wrong length.
    #[error("{port}: {len} values, expected {expected}")]
    WrongLength {
        /// The port (seed name).
        port: &'static str,
        /// Values received.
        len: usize,
        /// What is needed, e.g. `2`, `at least 2`, `12`.
        expected: String,
    },
    /// A timestamp with `nsec` ≥ 10⁹ on a port or service (spec §4 Decision 0.2), refused
    /// by [`Time::checked`](crate::rtc::Time::checked).
    #[error(transparent)]
    BadTimestamp(#[from] crate::rtc::TimestampError),
    /// A timestamp not later than the previous one on the same port. Both are written
    /// exactly: two stamps a microsecond apart would read alike at three decimals.
    #[error("{port}: time went backwards (or stood still): {now_s} s after {previous_s} s")]
    TimeWentBackwards {
        /// The port (seed name).
        port: &'static str,
        /// The previous timestamp \[s\].
        previous_s: f64,
        /// The refused timestamp \[s\].
        now_s: f64,
    },
    /// No new data on a port for too long.
    #[error("{port}: no new data for {age_s:.3} s (limit {limit_s:.3} s)")]
    Stale {
        /// The port (seed name).
        port: &'static str,
        /// Time since the last valid data \[s\].
        age_s: f64,
        /// The limit \[s\].
        limit_s: f64,
    },
    /// A model or controller parameter that cannot be used.
    #[error("parameter `{name}` = {value}: {reason}")]
    BadParameter {
        /// The parameter's name.
        name: String,
        /// The value given.
        value: f64,
        /// Why it is refused.
        reason: &'static str,
    },
    /// `leftWheelID` and `rightWheelID` name the same joint (002 §4.2).
    #[error("leftWheelID and rightWheelID are both {id}: the wheels need two joints")]
    SameWheelId {
        /// The shared id.
        id: i32,
    },
    /// A map operation on a physics that has no map yet.
    #[error("{what}: no map has been set")]
    NoMap {
        /// The operation, e.g. `MapUpdate`.
        what: &'static str,
    },
    /// A component's period that is not a whole number of physics steps.
    #[error(
        "period of {period_ns} ns is not a whole, positive number of {step_ns} ns physics steps"
    )]
    BadPeriod {
        /// The component's period.
        period_ns: u64,
        /// The physics step.
        step_ns: u64,
    },
}
