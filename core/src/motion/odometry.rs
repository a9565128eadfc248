//! Wheel odometry: the pose from wheel angles by exact arc integration (spec §5
//! "Localization … or from wheel odometry").

use super::diff_drive::{DiffDrive, arc_step};
use crate::errors::MotionError;
use crate::interfaces::Pose;
use crate::rtc::Time;

/// Dead reckoning from absolute wheel angles `[left, right]`.
///
/// Each new sample's angle increments give a path length and a heading change
/// ([`DiffDrive::body_increment`]), integrated as a circular arc ([`arc_step`]): exact when
/// the wheel rates were constant between samples. The first sample after a reset only sets
/// the reference.
#[derive(Debug, Clone, PartialEq)]
pub struct Odometry {
    drive: DiffDrive,
    pose: Pose,
    last: Option<(Time, [f64; 2])>,
    distance: f64,
}

impl Odometry {
    /// Odometry with this geometry, starting at `pose`.
    pub fn new(drive: DiffDrive, pose: Pose) -> Self {
        Self {
            drive,
            pose,
            last: None,
            distance: 0.0,
        }
    }

    /// The estimated pose.
    pub fn pose(&self) -> Pose {
        self.pose
    }

    /// The geometry in use.
    pub fn drive(&self) -> DiffDrive {
        self.drive
    }

    /// Replaces the geometry (the pose and the reference sample stay).
    pub fn set_drive(&mut self, drive: DiffDrive) {
        self.drive = drive;
    }

    /// Path length driven since the last [`Odometry::reset`] (sum of `|Δs|`) \[m\].
    pub fn distance(&self) -> f64 {
        self.distance
    }

    /// Puts the estimate at `pose` (e.g. the start pose); the next sample continues from the
    /// last reference sample, so no wheel motion is lost.
    pub fn reset(&mut self, pose: Pose) -> Result<(), MotionError> {
        if !pose.is_finite() {
            return Err(MotionError::NonFinite {
                port: "StartPose",
                field: "pose".to_owned(),
                value: [pose.x, pose.y, pose.theta]
                    .into_iter()
                    .find(|v| !v.is_finite())
                    .unwrap_or(f64::NAN),
            });
        }
        self.pose = pose;
        self.distance = 0.0;
        Ok(())
    }

    /// Forgets the reference sample: the next sample only sets it.
    pub fn forget_reference(&mut self) {
        self.last = None;
    }

    /// Integrates a new sample of absolute wheel angles taken at `tm`. A sample with a
    /// non-finite angle or a timestamp not after the previous one is refused and changes
    /// nothing (`port` names the source in errors).
    pub fn update(
        &mut self,
        tm: Time,
        angles: [f64; 2],
        port: &'static str,
    ) -> Result<Pose, MotionError> {
        if let Some((i, &v)) = angles.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(MotionError::NonFinite {
                port,
                field: format!("data[{i}]"),
                value: v,
            });
        }
        if let Some((prev, last)) = self.last {
            if tm <= prev {
                return Err(MotionError::TimeWentBackwards {
                    port,
                    previous_s: prev.as_secs_f64(),
                    now_s: tm.as_secs_f64(),
                });
            }
            let (ds, dtheta) = self
                .drive
                .body_increment([angles[0] - last[0], angles[1] - last[1]]);
            self.pose = arc_step(self.pose, ds, dtheta);
            self.distance += ds.abs();
        }
        self.last = Some((tm, angles));
        Ok(self.pose)
    }
}
