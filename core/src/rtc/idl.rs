//! The data types of the seeds' IDL (`IIS.idl`, OpenRTM `BasicDataType.idl`), as serde types.

use serde::{Deserialize, Serialize};

use super::TimestampError;

const NANOS_PER_SEC: u64 = 1_000_000_000;

/// `RTC::Time`: seconds and nanoseconds.
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize,
)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct Time {
    /// Whole seconds.
    pub sec: u32,
    /// Nanoseconds, `0..1_000_000_000`.
    pub nsec: u32,
}

impl Time {
    /// The one check of a timestamp where a sample enters a component (a data port, a
    /// service call; spec §4 Decision 0.2): `nsec` must be below 10⁹. Returns the time
    /// unchanged, or an error naming `what` (the port or service) and the value. Every
    /// component uses this, so all refuse the same timestamps the same way.
    pub fn checked(self, what: &'static str) -> Result<Self, TimestampError> {
        if self.is_valid() {
            Ok(self)
        } else {
            Err(TimestampError {
                what,
                sec: self.sec,
                nsec: self.nsec,
            })
        }
    }

    /// Whether `nsec` is below 10⁹ (see [`Time::checked`]).
    pub fn is_valid(self) -> bool {
        u64::from(self.nsec) < NANOS_PER_SEC
    }

    /// Nanoseconds from `earlier` to `self`, 0 if `earlier` is not before `self`: a time
    /// difference that never underflows (spec §4 Decision 0.2). Exact for any two times,
    /// valid or not ([`Time::as_nanos`] cannot overflow a `u64`).
    pub fn nanos_since(self, earlier: Self) -> u64 {
        self.as_nanos().saturating_sub(earlier.as_nanos())
    }

    /// The time `ns` nanoseconds after zero (saturating at `u32::MAX` seconds).
    pub fn from_nanos(ns: u64) -> Self {
        let sec = (ns / NANOS_PER_SEC).min(u64::from(u32::MAX));
        Self {
            sec: sec as u32,
            nsec: (ns % NANOS_PER_SEC) as u32,
        }
    }

    /// Total nanoseconds (exact: at most `u32::MAX · 10⁹ + u32::MAX` < 2⁶⁴, even for an
    /// invalid `nsec`).
    pub fn as_nanos(self) -> u64 {
        u64::from(self.sec) * NANOS_PER_SEC + u64::from(self.nsec)
    }

    /// Seconds as `f64` (correctly rounded from the exact nanosecond count below 2⁵³ ns).
    pub fn as_secs_f64(self) -> f64 {
        self.as_nanos() as f64 / 1e9
    }
}

/// `IIS::TimedPosition` (000 §3.1): a pose in the map frame.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct TimedPosition {
    /// Timestamp.
    pub tm: Time,
    /// ID array (unused in the seeds).
    pub id: Vec<i32>,
    /// X position (m).
    pub x: f64,
    /// Y position (m).
    pub y: f64,
    /// Heading (rad), counter-clockwise from the X axis.
    pub theta: f64,
    /// Error-code array (unused in the seeds).
    pub error: Vec<f64>,
}

/// `IIS::TimedVelocity` (002 §3.1): a velocity command at the robot centre.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct TimedVelocity {
    /// Timestamp.
    pub tm: Time,
    /// ID array (unused in the seeds).
    pub id: Vec<i32>,
    /// Forward speed (m/s).
    pub vx: f64,
    /// Sideways speed (m/s) (ignored by a differential drive).
    pub vy: f64,
    /// Turn rate (rad/s).
    pub w: f64,
    /// Error-code array (unused in the seeds).
    pub error: Vec<f64>,
}

/// `RTC::TimedDouble`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct TimedDouble {
    /// Timestamp.
    pub tm: Time,
    /// The value.
    pub data: f64,
}

/// `RTC::TimedDoubleSeq`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct TimedDoubleSeq {
    /// Timestamp.
    pub tm: Time,
    /// The values.
    pub data: Vec<f64>,
}
