//! The places of the system a student's script can take (spec §8, Decision 0.4 "what can be
//! replaced").

/// The places of the system a script can take (spec §8, Decision 0.4 "what can be
/// replaced").
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub enum ScriptPlace {
    /// DriveControl: control points and the current position in, `TargetVelocity` out.
    DriveControl,
    /// MotorControl: the target velocity and the wheel angles in, `Torque` out (seed 002's
    /// PD law).
    MotorControl,
}

impl ScriptPlace {
    /// Every place.
    pub const ALL: [Self; 2] = [Self::DriveControl, Self::MotorControl];

    /// The component's name (`MotorControl`), as a script declares it.
    pub fn name(self) -> &'static str {
        match self {
            Self::DriveControl => "DriveControl",
            Self::MotorControl => "MotorControl",
        }
    }

    /// The place a script's declaration names.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|p| p.name() == name)
    }
}
