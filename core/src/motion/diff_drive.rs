//! Differential-drive kinematics (002 §5.2.5.4, spec §4, §5) and exact arc integration.

use core::f64::consts::PI;

use crate::errors::MotionError;
use crate::interfaces::Pose;

/// The geometry of a differential-drive robot: two wheel radii and the axle length
/// (002 §4.2 `radiusOfLeftWheel`, `radiusOfRightWheel`, `lengthOfAxle`).
///
/// A `DiffDrive` that exists has positive, finite radii and axle length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiffDrive {
    radius_left: f64,
    radius_right: f64,
    axle_length: f64,
}

impl Default for DiffDrive {
    /// The seed's defaults (002 §4.2): wheel radii 0.1 m, axle 0.441 m.
    fn default() -> Self {
        Self {
            radius_left: 0.1,
            radius_right: 0.1,
            axle_length: 0.441,
        }
    }
}

impl DiffDrive {
    /// A geometry; every length must be positive and finite.
    pub fn new(radius_left: f64, radius_right: f64, axle_length: f64) -> Result<Self, MotionError> {
        for (name, value) in [
            ("radiusOfLeftWheel", radius_left),
            ("radiusOfRightWheel", radius_right),
            ("lengthOfAxle", axle_length),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(MotionError::BadParameter {
                    name: name.to_owned(),
                    value,
                    reason: "must be positive and finite",
                });
            }
        }
        Ok(Self {
            radius_left,
            radius_right,
            axle_length,
        })
    }

    /// Left wheel radius `r_L` \[m\].
    pub fn radius_left(&self) -> f64 {
        self.radius_left
    }

    /// Right wheel radius `r_R` \[m\].
    pub fn radius_right(&self) -> f64 {
        self.radius_right
    }

    /// Axle length \[m\].
    pub fn axle_length(&self) -> f64 {
        self.axle_length
    }

    /// Half the axle length, the seed's turning radius `R` \[m\] (002 §5.2.5.4).
    pub fn half_axle(&self) -> f64 {
        self.axle_length / 2.0
    }

    /// Target wheel rates `[ω_L*, ω_R*]` \[rad/s\] for a body velocity `(V, ω)`.
    ///
    /// 002 §5.2.5.4 writes `(ρ ∓ R)·ω / r` with `ρ = V/ω`; spec §4 Decision: computed as
    /// `(V ∓ R·ω)/r`, the same value, defined also for ω = 0.
    pub fn wheel_rates(&self, v: f64, w: f64) -> [f64; 2] {
        let r = self.half_axle();
        [
            (v - r * w) / self.radius_left,
            (v + r * w) / self.radius_right,
        ]
    }

    /// Body velocity `(V, ω)` for wheel rates `[ω_L, ω_R]` (the inverse of
    /// [`DiffDrive::wheel_rates`]): `V = (r_R ω_R + r_L ω_L)/2`, `ω = (r_R ω_R − r_L ω_L)/(2R)`.
    pub fn body_velocity(&self, rates: [f64; 2]) -> (f64, f64) {
        self.body_increment(rates)
    }

    /// Path length and heading change `(Δs, Δθ)` for wheel-angle increments `[Δφ_L, Δφ_R]`
    /// (no slip).
    pub fn body_increment(&self, dphi: [f64; 2]) -> (f64, f64) {
        let left = self.radius_left * dphi[0];
        let right = self.radius_right * dphi[1];
        ((right + left) / 2.0, (right - left) / self.axle_length)
    }
}

/// `sin(x)/x`, exact to rounding also near 0.
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-4 {
        // Taylor: 1 − x²/6 + x⁴/120; the next term is below 1e-20 here.
        let x2 = x * x;
        1.0 - x2 / 6.0 + x2 * x2 / 120.0
    } else {
        libm::sin(x) / x
    }
}

/// Moves `pose` along a circular arc of length `ds` that turns the heading by `dtheta`
/// (exact for constant curvature; a straight line when `dtheta` = 0). spec §5 "exact arc
/// integration": the chord has length `ds·sinc(Δθ/2)` and direction `θ + Δθ/2`.
/// The heading is wrapped to (−π, π].
pub fn arc_step(pose: Pose, ds: f64, dtheta: f64) -> Pose {
    let half = dtheta / 2.0;
    let chord = ds * sinc(half);
    let dir = pose.theta + half;
    Pose {
        x: pose.x + chord * libm::cos(dir),
        y: pose.y + chord * libm::sin(dir),
        theta: wrap_angle(pose.theta + dtheta),
    }
}

/// `a` wrapped to (−π, π] (spec §4: "θ … wrapped to (−π, π]").
pub fn wrap_angle(a: f64) -> f64 {
    if !a.is_finite() {
        return a;
    }
    if a > -PI && a <= PI {
        return a;
    }
    let two_pi = 2.0 * PI;
    let w = a - two_pi * libm::ceil((a - PI) / two_pi);
    // Rounding can land exactly on −π; that is π in (−π, π].
    if w <= -PI { w + two_pi } else { w }
}

/// The signed smallest rotation from `from` to `to`, in (−π, π].
pub fn angle_diff(to: f64, from: f64) -> f64 {
    wrap_angle(to - from)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_angle_is_half_open() {
        assert_eq!(wrap_angle(PI), PI);
        assert_eq!(wrap_angle(-PI), PI);
        assert_eq!(wrap_angle(3.0 * PI), PI);
        assert_eq!(wrap_angle(0.5), 0.5);
        assert!((wrap_angle(-3.0 * PI / 2.0) - PI / 2.0).abs() < 1e-15);
        assert!((wrap_angle(7.0) - (7.0 - 2.0 * PI)).abs() < 1e-15);
    }

    #[test]
    fn arc_step_is_exact_on_a_quarter_circle() {
        // Radius 1, a quarter turn: from (0,0) heading 0 to (1,1) heading π/2.
        let p = arc_step(Pose::new(0.0, 0.0, 0.0), PI / 2.0, PI / 2.0);
        assert!((p.x - 1.0).abs() < 1e-15 && (p.y - 1.0).abs() < 1e-15);
        assert_eq!(p.theta, PI / 2.0);
        let s = arc_step(Pose::new(1.0, 2.0, PI / 2.0), 0.5, 0.0);
        assert!((s.x - 1.0).abs() < 1e-15 && s.y == 2.5);
    }
}
