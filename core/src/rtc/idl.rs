//! The data types of the seeds' IDL (`IIS.idl`, OpenRTM `BasicDataType.idl`), as serde types.

use serde::{Deserialize, Serialize};

const NANOS_PER_SEC: u64 = 1_000_000_000;

/// `RTC::Time`: seconds and nanoseconds.
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize,
)]
pub struct Time {
    /// Whole seconds.
    pub sec: u32,
    /// Nanoseconds, `0..1_000_000_000`.
    pub nsec: u32,
}

impl Time {
    /// The time `ns` nanoseconds after zero (saturating at `u32::MAX` seconds).
    pub fn from_nanos(ns: u64) -> Self {
        let sec = (ns / NANOS_PER_SEC).min(u64::from(u32::MAX));
        Self {
            sec: sec as u32,
            nsec: (ns % NANOS_PER_SEC) as u32,
        }
    }

    /// Total nanoseconds.
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
