//! The execution rates of the system's components (spec §6: "motor and physics 1 kHz, drive
//! control 50 Hz, local planning 10 Hz; rates are configuration").

use serde::{Deserialize, Serialize};

use super::kind::ComponentKind;
use crate::errors::LifecycleError;
use crate::motion::STEP_NS;
use crate::rtc::period_ticks;

fn hz_1000() -> f64 {
    1000.0
}
fn hz_50() -> f64 {
    50.0
}
fn hz_10() -> f64 {
    10.0
}

/// Rates in Hz of every component and of the telemetry sampling. Read from JSON with
/// unknown keys refused; a missing key takes its default (spec §6).
///
/// The execution context's base rate is the highest of them, at most
/// [`MAX_BASE_RATE_HZ`](crate::rtc::MAX_BASE_RATE_HZ); every other rate's period must be a whole number of base ticks,
/// and the physics' period a whole number of its 1 ms steps ([`Rates::check`], when a
/// scenario is read and when the system is built).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[serde(deny_unknown_fields)]
pub struct Rates {
    /// MapBuilder. Default 10 Hz.
    #[serde(default = "hz_10")]
    pub map_builder: f64,
    /// MapMaintenance: how often queued map updates are sent. Default 10 Hz.
    #[serde(default = "hz_10")]
    pub map_maintenance: f64,
    /// The physics (PhysicsSim). Default 1 kHz.
    #[serde(default = "hz_1000")]
    pub physics: f64,
    /// MotorControl. Default 1 kHz.
    #[serde(default = "hz_1000")]
    pub motor_control: f64,
    /// Localization. Default 1 kHz.
    #[serde(default = "hz_1000")]
    pub localization: f64,
    /// GlobalPathPlanning. Default 10 Hz.
    #[serde(default = "hz_10")]
    pub global_path_planning: f64,
    /// LocalPathPlanning. Default 10 Hz.
    #[serde(default = "hz_10")]
    pub local_path_planning: f64,
    /// DriveControl. Default 50 Hz.
    #[serde(default = "hz_50")]
    pub drive_control: f64,
    /// Telemetry sampling (and the trace hash). Default 50 Hz.
    #[serde(default = "hz_50")]
    pub telemetry: f64,
}

impl Default for Rates {
    fn default() -> Self {
        Self {
            map_builder: hz_10(),
            map_maintenance: hz_10(),
            physics: hz_1000(),
            motor_control: hz_1000(),
            localization: hz_1000(),
            global_path_planning: hz_10(),
            local_path_planning: hz_10(),
            drive_control: hz_50(),
            telemetry: hz_50(),
        }
    }
}

impl Rates {
    /// The rate of one component.
    pub fn of(&self, kind: ComponentKind) -> f64 {
        match kind {
            ComponentKind::MapBuilder => self.map_builder,
            ComponentKind::MapMaintenance => self.map_maintenance,
            ComponentKind::PhysicsSim => self.physics,
            ComponentKind::MotorControl => self.motor_control,
            ComponentKind::Localization => self.localization,
            ComponentKind::GlobalPathPlanning => self.global_path_planning,
            ComponentKind::LocalPathPlanning => self.local_path_planning,
            ComponentKind::DriveControl => self.drive_control,
        }
    }

    /// Sets the rate of one component.
    pub fn set(&mut self, kind: ComponentKind, hz: f64) {
        let slot = match kind {
            ComponentKind::MapBuilder => &mut self.map_builder,
            ComponentKind::MapMaintenance => &mut self.map_maintenance,
            ComponentKind::PhysicsSim => &mut self.physics,
            ComponentKind::MotorControl => &mut self.motor_control,
            ComponentKind::Localization => &mut self.localization,
            ComponentKind::GlobalPathPlanning => &mut self.global_path_planning,
            ComponentKind::LocalPathPlanning => &mut self.local_path_planning,
            ComponentKind::DriveControl => &mut self.drive_control,
        };
        *slot = hz;
    }

    /// Checks every rate with [`period_ticks`] against the base tick (the highest rate)
    /// and the physics' period against its 1 ms step; returns the base period \[ns\]. The
    /// error names the first rate refused, whose it is and the limit it breaks.
    pub fn check(&self) -> Result<u64, LifecycleError> {
        let named = ComponentKind::ALL
            .iter()
            .map(|&k| (k.instance_name(), self.of(k)))
            .chain([("telemetry", self.telemetry)]);
        for (who, hz) in named.clone() {
            period_ticks(who, hz, 1)?;
        }
        let base = period_ticks("the base tick", self.base(), 1)?;
        for (who, hz) in named {
            period_ticks(who, hz, base)?;
        }
        let physics = period_ticks(ComponentKind::PhysicsSim.instance_name(), self.physics, 1)?;
        if !physics.is_multiple_of(STEP_NS) {
            return Err(LifecycleError::InvalidRate {
                component: ComponentKind::PhysicsSim.instance_name().to_owned(),
                rate: self.physics,
                reason: format!(
                    "its period of {physics} ns is not a whole number of the physics' \
                     {STEP_NS} ns steps"
                ),
            });
        }
        Ok(base)
    }

    /// The execution context's base rate: the highest rate (NaN rates are ignored here and
    /// refused by [`Rates::check`]).
    pub fn base(&self) -> f64 {
        ComponentKind::ALL
            .iter()
            .map(|&k| self.of(k))
            .chain([self.telemetry])
            .fold(0.0, f64::max)
    }
}
