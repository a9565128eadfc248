//! The simulated pose: OpenHRP3's model frame ↔ the robot's axle-centre pose
//! (002 §4.2 \[*1\] \[*2\], §5.2.5.6, spec §4 "Simulated pose").
//!
//! OpenHRP3 reports the body as `[X, Y, Z, A11, A12, A13, A21, …, A33]`: the model origin and
//! its 3×3 rotation matrix, row-major (`BODY:ABS_TRANSFORM`, 002 §3.1 `InSimulatedPosition`,
//! §5.2.7). The model origin need not be the axle centre, and the model's "0 rad" need not be
//! its X axis: the offsets `SimulatedOffsetX/Y` (`ΔX = Xp − Xo`, `ΔY = Yp − Yo` in the model's
//! axes) and `SimulatedOffsetAngle` (`Δθ`) convert between the two. The RH0 model has
//! `ΔY = 0.045795 m` and `Δθ = 1.5708 rad` (its Y axis is its forward direction).

use nalgebra::{Rotation3, Vector3};

use super::diff_drive::wrap_angle;
use crate::errors::MotionError;
use crate::interfaces::Pose;

/// Number of values in an OpenHRP3 body transform: position (3) and rotation (9).
pub const TRANSFORM_LEN: usize = 12;

/// The offsets between a simulator model's frame and the axle-centre frame (002 §4.2).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ModelFrame {
    /// `SimulatedOffsetX` ΔX \[m\].
    pub offset_x: f64,
    /// `SimulatedOffsetY` ΔY \[m\].
    pub offset_y: f64,
    /// `SimulatedOffsetAngle` Δθ \[rad\].
    pub offset_angle: f64,
}

impl ModelFrame {
    /// A frame; every offset must be finite.
    pub fn new(offset_x: f64, offset_y: f64, offset_angle: f64) -> Result<Self, MotionError> {
        for (name, value) in [
            ("SimulatedOffsetX", offset_x),
            ("SimulatedOffsetY", offset_y),
            ("SimulatedOffsetAngle", offset_angle),
        ] {
            if !value.is_finite() {
                return Err(MotionError::BadParameter {
                    name: name.to_owned(),
                    value,
                    reason: "must be finite",
                });
            }
        }
        Ok(Self {
            offset_x,
            offset_y,
            offset_angle,
        })
    }

    /// The RH0 model of 002 §4.2 \[*1\] \[*2\]: `ΔY = 0.045795 m`, `Δθ = 1.5708 rad`.
    // The seed's value, deliberately not π/2 exactly.
    #[allow(clippy::approx_constant)]
    pub const RH0: Self = Self {
        offset_x: 0.0,
        offset_y: 0.045795,
        offset_angle: 1.5708,
    };

    /// 002 §5.2.5.6: the axle-centre pose `(X, Y, θ)` and the model's `Z` from an OpenHRP3
    /// body transform `data` (exactly [`TRANSFORM_LEN`] finite values; `port` names the
    /// source in errors).
    ///
    /// `θo = atan2(−A12, A11)` (the seed's `−atan(A12/A11)` without its quadrant loss, SPEC
    /// §4), `Len = √(ΔX² + ΔY²)`, `φ = atan2(ΔY, ΔX)`, `X = Xo + Len·cos(θo + φ)`,
    /// `Y = Yo + Len·sin(θo + φ)`, `θ = θo + Δθ` wrapped to (−π, π].
    pub fn axle_pose(&self, data: &[f64], port: &'static str) -> Result<(Pose, f64), MotionError> {
        if data.len() != TRANSFORM_LEN {
            return Err(MotionError::WrongLength {
                port,
                len: data.len(),
                expected: TRANSFORM_LEN.to_string(),
            });
        }
        if let Some((i, &v)) = data.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(MotionError::NonFinite {
                port,
                field: format!("data[{i}]"),
                value: v,
            });
        }
        let (xo, yo, zo) = (data[0], data[1], data[2]);
        let (a11, a12) = (data[3], data[4]);
        let theta_o = libm::atan2(-a12, a11);
        let len = libm::hypot(self.offset_x, self.offset_y);
        let phi = libm::atan2(self.offset_y, self.offset_x);
        let pose = Pose {
            x: xo + len * libm::cos(theta_o + phi),
            y: yo + len * libm::sin(theta_o + phi),
            theta: wrap_angle(theta_o + self.offset_angle),
        };
        Ok((pose, zo))
    }

    /// The inverse of [`ModelFrame::axle_pose`]: the body transform OpenHRP3 would report for
    /// a robot whose axle centre is at `pose`, its model origin at height `z` (used by the
    /// physics, spec §5 "It reports the pose as OpenHRP3 did").
    pub fn model_transform(&self, pose: Pose, z: f64) -> [f64; TRANSFORM_LEN] {
        let theta_o = pose.theta - self.offset_angle;
        let rot = Rotation3::from_axis_angle(&Vector3::z_axis(), theta_o);
        let offset = rot * Vector3::new(self.offset_x, self.offset_y, 0.0);
        let m = rot.matrix();
        [
            pose.x - offset.x,
            pose.y - offset.y,
            z,
            m[(0, 0)],
            m[(0, 1)],
            m[(0, 2)],
            m[(1, 0)],
            m[(1, 1)],
            m[(1, 2)],
            m[(2, 0)],
            m[(2, 1)],
            m[(2, 2)],
        ]
    }
}
