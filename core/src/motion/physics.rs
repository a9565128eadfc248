//! The physics that replaces OpenHRP3 (spec §5 "Physics"): a rigid differential-drive robot
//! without wheel slip, stepped at a fixed 1 ms, with bump detection against the grid map.
//!
//! State: the axle-centre pose, the wheel angles and rates. Input: the wheel torques
//! (saturated at `max_torque`). With mass `m`, yaw inertia `I`, wheel inertia `J`, wheel radius
//! `r`, half axle `R` and viscous friction `b`, the wheel-space dynamics are
//! `M·[ω̇_L, ω̇_R]ᵀ = [τ_L, τ_R]ᵀ − b·[ω_L, ω_R]ᵀ` with `M = [[a, c], [c, a]]`,
//! `a = m r²/4 + I r²/(4R²) + J`, `c = m r²/4 − I r²/(4R²)` (the Lagrangian of the body's
//! translation, its yaw and the wheels' spin).
//!
//! Integration (one step `h` = 1 ms): friction implicitly, torque explicitly,
//! `(M + h·b·I)·ω' = M·ω + h·τ` (a 2×2 solve, unconditionally stable for the passive part);
//! the wheel angles advance by `h·ω'` (semi-implicit Euler); the pose follows the wheel-angle
//! increments as an exact circular arc ([`arc_step`]), so wheel odometry sampled every step
//! reproduces it.

use core::fmt;

use nalgebra::{Matrix2, Vector2};
use serde::{Deserialize, Serialize};

use super::diff_drive::{DiffDrive, arc_step};
use super::model_frame::{ModelFrame, TRANSFORM_LEN};
use crate::errors::MotionError;
use crate::interfaces::Pose;
use crate::map::{GridMap, MapUpdate};
use crate::present::fixed;
use crate::rtc::Time;

/// The fixed physics step: 1 ms (spec §5 "Fixed step 1 ms"), in nanoseconds.
pub const STEP_NS: u64 = 1_000_000;
/// The fixed physics step in seconds.
pub const STEP_S: f64 = 0.001;

/// A contact ends when the body is this far clear of every obstacle \[m\]; until then, touching
/// again is the same bump (no report per millimetre while the motors push against a wall).
pub const CONTACT_RELEASE: f64 = 0.01;

fn default_robot_name() -> String {
    "rh0".to_owned()
}
/// The default mass \[kg\] ([`PhysicsParams::mass`]; PhysicsSim's `Mass`).
pub const DEFAULT_MASS: f64 = 20.0;
/// The default yaw inertia \[kg·m²\] ([`PhysicsParams::yaw_inertia`]; PhysicsSim's
/// `YawInertia`).
pub const DEFAULT_YAW_INERTIA: f64 = 1.0;
/// The default viscous friction \[N·m·s/rad\] ([`PhysicsParams::viscous_friction`];
/// PhysicsSim's `ViscousFriction`).
pub const DEFAULT_VISCOUS_FRICTION: f64 = 0.02;
/// The default torque saturation \[N·m\] ([`PhysicsParams::max_torque`]; PhysicsSim's
/// `MaxTorque`).
pub const DEFAULT_MAX_TORQUE: f64 = 5.0;

fn default_mass() -> f64 {
    DEFAULT_MASS
}
fn default_yaw_inertia() -> f64 {
    DEFAULT_YAW_INERTIA
}
fn default_wheel_inertia() -> f64 {
    0.005
}
fn default_wheel_radius() -> f64 {
    0.1
}
fn default_axle_length() -> f64 {
    0.441
}
fn default_viscous_friction() -> f64 {
    DEFAULT_VISCOUS_FRICTION
}
fn default_max_torque() -> f64 {
    DEFAULT_MAX_TORQUE
}
fn default_body_radius() -> f64 {
    0.45
}

/// The robot model of the physics (spec §5). Defaults: a ~20 kg robot with the seed's
/// wheels and axle (002 §4.2), tuned so MotorControl's default gains (P 5, D 2) reach a
/// commanded speed within 2 % in well under a second.
///
/// Why these defaults: with MotorControl's PD law the torque is about
/// `D·(ω* − ω) + P·Δt·(ω* + ω)/2`, so in steady state `ω/ω* = (D + PΔt/2)/(D − PΔt/2 + b)`
/// = 0.9926 at `b` = 0.02 (0.74 % short of the command, the same for both wheels, so a
/// commanded turn radius is kept exactly); the time constant of straight driving is
/// `(m r²/2 + J)/(D − PΔt/2 + b)` ≈ 0.052 s, of turning `(I r²/(2R²) + J)/(…)` ≈ 0.054 s.
/// `max_torque` 5 N·m per wheel gives about 5 m/s² of acceleration.
///
/// Read from JSON with unknown keys refused; a missing key takes its default.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhysicsParams {
    /// The robot's name in bump reports ("who"); OpenHRP3's `--robot-name` (002 §5.2.7).
    #[serde(default = "default_robot_name")]
    pub robot_name: String,
    /// Mass `m` \[kg\]; > 0. Default 20.
    #[serde(default = "default_mass")]
    pub mass: f64,
    /// Yaw moment of inertia `I` about the axle centre \[kg·m²\]; > 0. Default 1.0 (about a
    /// 20 kg body of 0.35 m radius).
    #[serde(default = "default_yaw_inertia")]
    pub yaw_inertia: f64,
    /// Spin inertia `J` of each wheel with its motor and gear, at the wheel \[kg·m²\]; ≥ 0.
    /// Default 0.005.
    #[serde(default = "default_wheel_inertia")]
    pub wheel_inertia: f64,
    /// Wheel radius `r` \[m\]; > 0. Default 0.1 (002 §4.2 `radiusOfLeftWheel/Right`).
    #[serde(default = "default_wheel_radius")]
    pub wheel_radius: f64,
    /// Distance between the wheels, `2R` \[m\]; > 0. Default 0.441 (002 §4.2 `lengthOfAxle`).
    #[serde(default = "default_axle_length")]
    pub axle_length: f64,
    /// Viscous friction `b` at each wheel \[N·m·s/rad\]; ≥ 0. Default 0.02 (0.1 N·m per wheel
    /// at 0.5 m/s).
    #[serde(default = "default_viscous_friction")]
    pub viscous_friction: f64,
    /// Torque saturation of each wheel's motor \[N·m\]; ≥ 0. Default 5.
    #[serde(default = "default_max_torque")]
    pub max_torque: f64,
    /// Radius of the circle around the body for bump detection \[m\]; ≥ 0. Default 0.45
    /// (002 §4.2 `radiusOfBodyArea`).
    #[serde(default = "default_body_radius")]
    pub body_radius: f64,
    /// Where the model origin is, seen from the axle centre: MotorControl's
    /// `SimulatedOffsetX` \[m\] for this model (002 §4.2 \[*1\]). Default 0.
    #[serde(default)]
    pub model_offset_x: f64,
    /// `SimulatedOffsetY` for this model \[m\] (RH0: 0.045795). Default 0.
    #[serde(default)]
    pub model_offset_y: f64,
    /// `SimulatedOffsetAngle` for this model \[rad\] (RH0: 1.5708). Default 0.
    #[serde(default)]
    pub model_offset_angle: f64,
    /// Height of the model origin reported as `Z` \[m\]. Default 0.
    #[serde(default)]
    pub model_z: f64,
}

impl Default for PhysicsParams {
    fn default() -> Self {
        Self {
            robot_name: default_robot_name(),
            mass: default_mass(),
            yaw_inertia: default_yaw_inertia(),
            wheel_inertia: default_wheel_inertia(),
            wheel_radius: default_wheel_radius(),
            axle_length: default_axle_length(),
            viscous_friction: default_viscous_friction(),
            max_torque: default_max_torque(),
            body_radius: default_body_radius(),
            model_offset_x: 0.0,
            model_offset_y: 0.0,
            model_offset_angle: 0.0,
            model_z: 0.0,
        }
    }
}

impl PhysicsParams {
    /// These parameters with the model frame of `frame` (e.g. [`ModelFrame::RH0`]).
    pub fn with_model_frame(mut self, frame: ModelFrame) -> Self {
        self.model_offset_x = frame.offset_x;
        self.model_offset_y = frame.offset_y;
        self.model_offset_angle = frame.offset_angle;
        self
    }

    /// The model frame these parameters describe.
    pub fn model_frame(&self) -> ModelFrame {
        ModelFrame {
            offset_x: self.model_offset_x,
            offset_y: self.model_offset_y,
            offset_angle: self.model_offset_angle,
        }
    }

    /// Checks every value (positive / non-negative and finite, as documented per field), in
    /// this order; the first that breaks its bound is the error.
    pub fn validate(&self) -> Result<(), MotionError> {
        use Bound::{Finite, NonNegative, Positive};
        let checks = [
            ("mass", self.mass, Positive),
            ("yaw_inertia", self.yaw_inertia, Positive),
            ("wheel_radius", self.wheel_radius, Positive),
            ("axle_length", self.axle_length, Positive),
            ("wheel_inertia", self.wheel_inertia, NonNegative),
            ("viscous_friction", self.viscous_friction, NonNegative),
            ("max_torque", self.max_torque, NonNegative),
            ("body_radius", self.body_radius, NonNegative),
            ("model_offset_x", self.model_offset_x, Finite),
            ("model_offset_y", self.model_offset_y, Finite),
            ("model_offset_angle", self.model_offset_angle, Finite),
            ("model_z", self.model_z, Finite),
        ];
        match checks
            .into_iter()
            .find(|&(_, value, bound)| !bound.holds(value))
        {
            Some((name, value, bound)) => Err(MotionError::BadParameter {
                name: name.to_owned(),
                value,
                reason: bound.reason(),
            }),
            None => Ok(()),
        }
    }

    /// The wheel-space mass matrix `M = [[a, c], [c, a]]` (spec §5).
    pub fn mass_matrix(&self) -> Matrix2<f64> {
        let r2 = self.wheel_radius * self.wheel_radius;
        let half = self.axle_length / 2.0;
        let trans = self.mass * r2 / 4.0;
        let yaw = self.yaw_inertia * r2 / (4.0 * half * half);
        let a = trans + yaw + self.wheel_inertia;
        let c = trans - yaw;
        Matrix2::new(a, c, c, a)
    }
}

/// What a parameter of [`PhysicsParams::validate`] must be.
#[derive(Debug, Clone, Copy)]
enum Bound {
    Positive,
    NonNegative,
    Finite,
}

impl Bound {
    fn holds(self, value: f64) -> bool {
        value.is_finite()
            && match self {
                Self::Positive => value > 0.0,
                Self::NonNegative => value >= 0.0,
                Self::Finite => true,
            }
    }

    /// The words of [`MotionError::BadParameter`]'s `reason`.
    fn reason(self) -> &'static str {
        match self {
            Self::Positive => "must be positive and finite",
            Self::NonNegative => "must be non-negative and finite",
            Self::Finite => "must be finite",
        }
    }
}

/// The physics' state (spec §5 "state pose, wheel angles and rates").
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PhysicsState {
    /// Simulated time \[ns\].
    pub time_ns: u64,
    /// The axle-centre pose in the map frame.
    pub pose: Pose,
    /// Wheel angles `[left, right]` \[rad\], absolute since the start.
    pub wheel_angle: [f64; 2],
    /// Wheel rates `[left, right]` \[rad/s\].
    pub wheel_rate: [f64; 2],
    /// The torques applied in the last step, after saturation \[N·m\].
    pub torque: [f64; 2],
    /// Whether the body touches an obstacle: from a bump until it is [`CONTACT_RELEASE`]
    /// clear of every obstacle again.
    pub in_contact: bool,
}

/// A bump (spec §5 "touching an obstacle cell is a bump"): who hit what, where, when.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub struct BumpReport {
    /// Simulated time of the bump.
    pub tm: Time,
    /// The robot ([`PhysicsParams::robot_name`]).
    pub who: String,
    /// Where the robot stopped (axle-centre pose).
    pub pose: Pose,
    /// The obstacle cell touched (may lie outside the map, which counts as obstacle).
    pub cell: (i64, i64),
    /// The point of the cell nearest the body's centre \[m\].
    pub contact: (f64, f64),
    /// Body speed when it hit \[m/s\].
    pub speed: f64,
}

impl fmt::Display for BumpReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} bumped into obstacle cell ({}, {}) at ({}, {}) m, t = {} s, \
             speed {} m/s; stopped at ({}, {}, {} rad)",
            self.who,
            self.cell.0,
            self.cell.1,
            fixed(self.contact.0, 3),
            fixed(self.contact.1, 3),
            fixed(self.tm.as_secs_f64(), 3),
            fixed(self.speed, 3),
            fixed(self.pose.x, 3),
            fixed(self.pose.y, 3),
            fixed(self.pose.theta, 3)
        )
    }
}

/// The nearest obstacle cell touching a body circle.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Touch {
    distance: f64,
    cell: (i64, i64),
    contact: (f64, f64),
}

/// What the physics derives from its parameters (checked).
struct Model {
    drive: DiffDrive,
    frame: ModelFrame,
    mass: Matrix2<f64>,
    step_matrix: Matrix2<f64>,
}

impl Model {
    fn of(params: &PhysicsParams) -> Result<Self, MotionError> {
        params.validate()?;
        let drive = DiffDrive::new(params.wheel_radius, params.wheel_radius, params.axle_length)?;
        let frame = ModelFrame::new(
            params.model_offset_x,
            params.model_offset_y,
            params.model_offset_angle,
        )?;
        let mass = params.mass_matrix();
        let lhs = mass + Matrix2::identity() * (STEP_S * params.viscous_friction);
        let step_matrix = lhs.try_inverse().ok_or(MotionError::BadParameter {
            name: "mass_matrix".to_owned(),
            value: lhs.determinant(),
            reason: "is singular",
        })?;
        Ok(Self {
            drive,
            frame,
            mass,
            step_matrix,
        })
    }
}

/// The distance from `(x, y)` to the square of cell `(i, j)` of `map` (0 inside it) \[m\].
fn square_distance(map: &GridMap, i: i64, j: i64, x: f64, y: f64) -> f64 {
    let g = map.grid_size();
    let (ox, oy) = map.origin();
    let (lx, ly) = (ox + i as f64 * g, oy + j as f64 * g);
    libm::hypot(x - x.clamp(lx, lx + g), y - y.clamp(ly, ly + g))
}

/// The physics of spec §5: [`Physics::step`] advances it by exactly 1 ms.
#[derive(Debug, Clone, PartialEq)]
pub struct Physics {
    params: PhysicsParams,
    drive: DiffDrive,
    frame: ModelFrame,
    mass: Matrix2<f64>,
    /// `(M + h·b·I)⁻¹`.
    step_matrix: Matrix2<f64>,
    state: PhysicsState,
    map: Option<GridMap>,
    /// The nearest obstacle touching the body at the current pose.
    touch: Option<Touch>,
    /// A bump found outside a step (a map update onto the body), reported by the next step.
    pending_bump: bool,
    bumps: u64,
}

impl Physics {
    /// A robot at rest at the origin, heading 0, with no map.
    pub fn new(params: PhysicsParams) -> Result<Self, MotionError> {
        let Model {
            drive,
            frame,
            mass,
            step_matrix,
        } = Model::of(&params)?;
        Ok(Self {
            params,
            drive,
            frame,
            mass,
            step_matrix,
            state: PhysicsState {
                time_ns: 0,
                pose: Pose::default(),
                wheel_angle: [0.0; 2],
                wheel_rate: [0.0; 2],
                torque: [0.0; 2],
                in_contact: false,
            },
            map: None,
            touch: None,
            pending_bump: false,
            bumps: 0,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &PhysicsParams {
        &self.params
    }

    /// Replaces the parameters (PhysicsSim's configuration, spec §5 "Physics"): checked as
    /// [`Physics::new`] checks them, then everything that depends on them is recomputed —
    /// the mass matrix `M`, `(M + h·b·I)⁻¹`, the wheel geometry, the model frame and the
    /// body's contact. The state (pose, wheel angles and rates, time) is kept, so the next
    /// step continues from it with the new model. A bad value is refused and nothing changes.
    pub fn set_params(&mut self, params: PhysicsParams) -> Result<(), MotionError> {
        let Model {
            drive,
            frame,
            mass,
            step_matrix,
        } = Model::of(&params)?;
        self.params = params;
        self.drive = drive;
        self.frame = frame;
        self.mass = mass;
        self.step_matrix = step_matrix;
        // The body radius may have changed: an obstacle now under the body is a bump.
        self.refresh_touch();
        Ok(())
    }

    /// The state.
    pub fn state(&self) -> &PhysicsState {
        &self.state
    }

    /// The axle-centre pose.
    pub fn pose(&self) -> Pose {
        self.state.pose
    }

    /// The wheel-space mass matrix `M`.
    pub fn mass_matrix(&self) -> Matrix2<f64> {
        self.mass
    }

    /// The wheel geometry.
    pub fn drive(&self) -> DiffDrive {
        self.drive
    }

    /// Body velocity `(v, ω)` from the wheel rates: `v = r(ω_R + ω_L)/2`,
    /// `ω = r(ω_R − ω_L)/(2R)`.
    pub fn body_velocity(&self) -> (f64, f64) {
        self.drive.body_velocity(self.state.wheel_rate)
    }

    /// Number of bumps so far.
    pub fn bump_count(&self) -> u64 {
        self.bumps
    }

    /// Sets the simulated time (the physics component keeps it in step with its context).
    pub fn set_time_ns(&mut self, time_ns: u64) {
        self.state.time_ns = time_ns;
    }

    /// Puts the robot at `pose`, at rest (wheel angles kept: they are absolute encoders).
    /// A non-finite pose is refused.
    pub fn set_pose(&mut self, pose: Pose) -> Result<(), MotionError> {
        if let Some(v) = [pose.x, pose.y, pose.theta]
            .into_iter()
            .find(|v| !v.is_finite())
        {
            return Err(MotionError::NonFinite {
                port: "set_pose",
                field: "pose".to_owned(),
                value: v,
            });
        }
        self.state.pose = Pose {
            theta: super::diff_drive::wrap_angle(pose.theta),
            ..pose
        };
        self.state.wheel_rate = [0.0; 2];
        self.state.in_contact = false;
        self.refresh_touch();
        Ok(())
    }

    /// The map used for bump detection (spec §5), `None` for open space.
    pub fn map(&self) -> Option<&GridMap> {
        self.map.as_ref()
    }

    /// Sets (or removes) the map. A map whose obstacles touch the body now gives a bump at
    /// the next step.
    pub fn set_map(&mut self, map: Option<GridMap>) {
        self.map = map;
        self.refresh_touch();
    }

    /// `MapUpdate` on the held map (spec §2, atomic). An obstacle that appears on the body
    /// gives a bump at the next step.
    pub fn map_update(&mut self, update: &MapUpdate) -> crate::Result<usize> {
        let map = self
            .map
            .as_mut()
            .ok_or(MotionError::NoMap { what: "MapUpdate" })?;
        let changed = map.map_update(update)?;
        self.refresh_touch();
        Ok(changed)
    }

    fn refresh_touch(&mut self) {
        self.touch = self.touching(self.state.pose.x, self.state.pose.y);
        if self.touch.is_some() && !self.state.in_contact {
            self.pending_bump = true;
        }
    }

    /// Whether an obstacle in cell `(i, j)` of the held map would touch the body where it
    /// stands now (the test of [`Physics::step`]: the cell's square closer than
    /// `body_radius` to the axle centre, or containing it). `false` without a map.
    pub fn body_covers(&self, i: i64, j: i64) -> bool {
        let Some(map) = self.map.as_ref() else {
            return false;
        };
        let (x, y) = (self.state.pose.x, self.state.pose.y);
        let d = square_distance(map, i, j, x, y);
        d < self.params.body_radius || d == 0.0
    }

    /// The body transform OpenHRP3 would report: `[X, Y, Z, A11..A33]` of the model origin
    /// (spec §5 "It reports the pose as OpenHRP3 did").
    pub fn model_transform(&self) -> [f64; TRANSFORM_LEN] {
        self.frame
            .model_transform(self.state.pose, self.params.model_z)
    }

    /// The nearest obstacle cell that a body circle centred at `(x, y)` touches, if any.
    fn touching(&self, x: f64, y: f64) -> Option<Touch> {
        self.within(x, y, self.params.body_radius)
    }

    /// The nearest obstacle cell closer than `r` to `(x, y)` (or containing it), if any.
    fn within(&self, x: f64, y: f64, r: f64) -> Option<Touch> {
        let map = self.map.as_ref()?;
        let g = map.grid_size();
        // Quick reject with the exact distance transform: the centre lies within g·√2/2 of
        // its cell's centre, an obstacle square within g·√2/2 of its own centre.
        if let Some(c) = map.world_to_cell(x, y)
            && map.obstacle_distance(c) - g * core::f64::consts::SQRT_2 >= r
        {
            return None;
        }
        // The cells the body's bounding box covers, clipped so that the work is bounded by
        // the map, not by the radius in cells (a body of millions of tiny cells): for a
        // centre in the map, the map and one ring of cells around it — outside cells are
        // obstacles, and the ring's cell towards any cell beyond it is strictly nearer; for
        // a centre outside the map, the 3 × 3 cells around its own cell, which is an
        // obstacle at distance 0, as is every cell that touches the centre.
        let (cx, cy) = map.world_to_cell_signed(x, y)?;
        let (w, h) = (map.width() as i64, map.height() as i64);
        let ((lx0, ly0), (lx1, ly1)) = if map.contains(cx, cy) {
            ((-1, -1), (w, h))
        } else {
            ((cx - 1, cy - 1), (cx + 1, cy + 1))
        };
        let (ox, oy) = map.origin();
        let clip = |v: f64, o: f64, lo: i64, hi: i64| {
            libm::floor((v - o) / g).clamp(lo as f64, hi as f64) as i64
        };
        let (x0, x1) = (clip(x - r, ox, lx0, lx1), clip(x + r, ox, lx0, lx1));
        let (y0, y1) = (clip(y - r, oy, ly0, ly1), clip(y + r, oy, ly0, ly1));
        let mut best: Option<Touch> = None;
        for j in y0..=y1 {
            for i in x0..=x1 {
                if !map.is_obstacle(i, j) {
                    continue;
                }
                let (lx, ly) = (ox + i as f64 * g, oy + j as f64 * g);
                let cx = x.clamp(lx, lx + g);
                let cy = y.clamp(ly, ly + g);
                let d = square_distance(map, i, j, x, y);
                let touches = d < r || d == 0.0;
                if touches && best.is_none_or(|b| d < b.distance) {
                    best = Some(Touch {
                        distance: d,
                        cell: (i, j),
                        contact: (cx, cy),
                    });
                }
            }
        }
        best
    }

    fn report(&self, touch: Touch, speed: f64) -> BumpReport {
        BumpReport {
            tm: Time::from_nanos(self.state.time_ns),
            who: self.params.robot_name.clone(),
            pose: self.state.pose,
            cell: touch.cell,
            contact: touch.contact,
            speed,
        }
    }

    /// Advances by one 1 ms step with wheel torques `[left, right]` \[N·m\] (saturated at
    /// `max_torque`). Returns a bump report when the body newly touches an obstacle: the
    /// move that would touch it (or go deeper) is refused and the wheels stop. A non-finite
    /// torque is refused and changes nothing.
    pub fn step(&mut self, torque: [f64; 2]) -> Result<Option<BumpReport>, MotionError> {
        if let Some((i, &v)) = torque.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(MotionError::NonFinite {
                port: "torque",
                field: format!("data[{i}]"),
                value: v,
            });
        }
        let max = self.params.max_torque;
        let tau = Vector2::new(torque[0].clamp(-max, max), torque[1].clamp(-max, max));
        let rate = Vector2::new(self.state.wheel_rate[0], self.state.wheel_rate[1]);
        let next_rate = self.step_matrix * (self.mass * rate + tau * STEP_S);
        let dphi = [next_rate.x * STEP_S, next_rate.y * STEP_S];
        let (ds, dtheta) = self.drive.body_increment(dphi);
        let next_pose = arc_step(self.state.pose, ds, dtheta);
        self.state.time_ns += STEP_NS;
        self.state.torque = [tau.x, tau.y];

        let next_touch = self.touching(next_pose.x, next_pose.y);
        let blocked = match (next_touch, self.touch) {
            (None, _) => false,
            (Some(_), None) => true,
            (Some(n), Some(o)) => n.distance < o.distance,
        };
        if blocked {
            let speed = self.drive.body_velocity([next_rate.x, next_rate.y]).0;
            self.state.wheel_rate = [0.0; 2];
            let newly = !self.state.in_contact;
            self.state.in_contact = true;
            self.pending_bump = false;
            if newly {
                self.bumps += 1;
                let touch = next_touch.unwrap_or(Touch {
                    distance: 0.0,
                    cell: (0, 0),
                    contact: (next_pose.x, next_pose.y),
                });
                return Ok(Some(self.report(touch, speed)));
            }
            return Ok(None);
        }
        self.state.pose = next_pose;
        self.state.wheel_angle[0] += dphi[0];
        self.state.wheel_angle[1] += dphi[1];
        self.state.wheel_rate = [next_rate.x, next_rate.y];
        self.touch = next_touch;
        match next_touch {
            None => {
                let r = self.params.body_radius + CONTACT_RELEASE;
                if self.state.in_contact && self.within(next_pose.x, next_pose.y, r).is_none() {
                    self.state.in_contact = false;
                }
                self.pending_bump = false;
                Ok(None)
            }
            Some(t) if self.pending_bump => {
                // An obstacle appeared on the body (map update or placement): stop and report.
                self.pending_bump = false;
                self.state.in_contact = true;
                self.state.wheel_rate = [0.0; 2];
                self.bumps += 1;
                Ok(Some(self.report(t, 0.0)))
            }
            Some(_) => Ok(None),
        }
    }
}
