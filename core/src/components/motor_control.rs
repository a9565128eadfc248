//! MotorControl (seed 002, spec §4): wheel PD torque control of a differential-drive robot
//! in the simulator, and the simulated pose for Localization and the GUI.
//!
//! Each tick (002 §5.2.5): read the gains (`always`), the wheel angles (rates from angle
//! differences over the timestamps' difference), the target velocity (→ target wheel rates
//! and angles), compute the PD torques, convert the simulated pose, send everything, keep
//! the current values as the previous ones.
//!
//! **Safe stop** (spec §4 Decision): a non-finite or wrong-length input, a timestamp whose
//! `nsec` is not below 10⁹ (refused by [`Time::checked`], spec §4 Decision 0.2), time going
//! backwards (wheel angles must advance, Δt > 0; a target velocity may repeat its timestamp
//! but not go back), or no new target velocity (or wheel angles) for 0.5 s gives zero torque
//! and a reason ([`MotorControl::status`], [`MotorControl::last_error`]). The component keeps
//! running (it does not go to Error: a component in Error sends nothing, and the simulator
//! would keep applying the last torque); a valid new input on the faulty port resumes control.

use core::fmt;

use crate::define_parameters;
use crate::errors::MotionError;
use crate::interfaces::Pose;
use crate::motion::{DiffDrive, ModelFrame};
use crate::present::number;
use crate::rtc::{
    Component, ComponentError, ConfigAccess, Configuration, InPort, OutPort, ReturnCode, Tick,
    Time, TimedDoubleSeq, TimedVelocity,
};

/// How long without a new target velocity (or new wheel angles) before the safe stop:
/// 0.5 s (spec §4 Decision).
pub const INPUT_TIMEOUT_NS: u64 = 500_000_000;

/// Largest accepted gain: the seed says "0.0以上"; the cap refuses an infinite gain.
const MAX_GAIN: f64 = 1.0e6;

define_parameters! {
    /// MotorControl's configuration parameters (002 §4.2 表4.2-1), in the seed's order.
    /// Gains are `always` (常時); the rest `on_activation` (初期化時): copied in
    /// `on_activated` and locked until the next activation (002 §5.2.3 (2)).
    pub struct MotorControlParams {
        /// `PGainL`: left wheel P gain.
        p_gain_l: f64 = ("PGainL", "-", 5.0, 0.0, MAX_GAIN, Always,
            "left wheel P gain: acts on the wheel-angle error, which is re-anchored every tick, so it works as a rate gain of P·Δt/2 (spec §4 note)",
            seed: "左車輪モータのPゲイン"),
        /// `DGainL`: left wheel D gain.
        d_gain_l: f64 = ("DGainL", "-", 2.0, 0.0, MAX_GAIN, Always,
            "left wheel D gain: acts on the wheel-rate error; it is the gain that holds the wheel at its target rate (spec §4 note)",
            seed: "左車輪モータのDゲイン"),
        /// `PGainR`: right wheel P gain.
        p_gain_r: f64 = ("PGainR", "-", 5.0, 0.0, MAX_GAIN, Always,
            "right wheel P gain: acts on the wheel-angle error, which is re-anchored every tick, so it works as a rate gain of P·Δt/2 (spec §4 note)",
            seed: "右車輪モータのPゲイン"),
        /// `DGainR`: right wheel D gain.
        d_gain_r: f64 = ("DGainR", "-", 2.0, 0.0, MAX_GAIN, Always,
            "right wheel D gain: acts on the wheel-rate error; it is the gain that holds the wheel at its target rate (spec §4 note)",
            seed: "右車輪モータのDゲイン"),
        /// `SimulatedOffsetX`: ΔX = Xp − Xo, model origin → axle centre (002 §4.2 \[*1\]).
        simulated_offset_x: f64 = ("SimulatedOffsetX", "m", 0.0, -100.0, 100.0, OnActivation,
            "offset ΔX from the simulated model's origin to the axle centre (002 §4.2 [*1])",
            seed: "シミュレーション原点位置オフセット（ΔX[m])"),
        /// `SimulatedOffsetY`: ΔY = Yp − Yo (RH0: 0.045795).
        simulated_offset_y: f64 = ("SimulatedOffsetY", "m", 0.0, -100.0, 100.0, OnActivation,
            "offset ΔY from the simulated model's origin to the axle centre (002 §4.2 [*1]; RH0: 0.045795 m)",
            seed: "シミュレーション原点位置オフセット（ΔY[m])"),
        /// `SimulatedOffsetAngle`: Δθ, counter-clockwise from X to the model's 0 rad
        /// (002 §4.2 \[*2\]; RH0: 1.5708).
        simulated_offset_angle: f64 = ("SimulatedOffsetAngle", "rad", 0.0,
            -core::f64::consts::TAU, core::f64::consts::TAU, OnActivation,
            "heading offset Δθ of the simulated model, counter-clockwise from the X axis (002 §4.2 [*2]; RH0: 1.5708 rad)",
            seed: "シミュレーション原点姿勢オフセット（Δθ[rad])"),
        /// `leftWheelID`: index of the left wheel's joint in the angle and torque sequences.
        left_wheel_id: i32 = ("leftWheelID", "-", 0.0, 0.0, 63.0, OnActivation,
            "index of the left wheel's joint in the wheel-angle and torque sequences", seed: "左駆動輪のID番号"),
        /// `rightWheelID`: index of the right wheel's joint.
        right_wheel_id: i32 = ("rightWheelID", "-", 1.0, 0.0, 63.0, OnActivation,
            "index of the right wheel's joint in the wheel-angle and torque sequences", seed: "右駆動輪のID番号"),
        /// `radiusOfLeftWheel` r_L.
        radius_of_left_wheel: f64 = ("radiusOfLeftWheel", "m", 0.1, 0.001, 10.0, OnActivation,
            "left drive wheel radius", seed: "左駆動輪の車輪半径"),
        /// `radiusOfRightWheel` r_R.
        radius_of_right_wheel: f64 = ("radiusOfRightWheel", "m", 0.1, 0.001, 10.0, OnActivation,
            "right drive wheel radius", seed: "右駆動輪の車輪半径"),
        /// `lengthOfAxle` 2R.
        length_of_axle: f64 = ("lengthOfAxle", "m", 0.441, 0.001, 10.0, OnActivation,
            "distance between the two drive wheels", seed: "左右駆動輪間の長さ"),
        /// `radiusOfBodyArea`: the circle around the body (for the safety area).
        radius_of_body_area: f64 = ("radiusOfBodyArea", "m", 0.45, 0.0, 10.0, OnActivation,
            "radius of the circle around the whole body, for the safety area (the physics and DriveControl use it)",
            seed: "ロボット車体全体を円で囲んだ場合の半径。安全を考慮したエリア定義用"),
    }
}

/// What MotorControl is doing, for the GUI.
#[derive(Debug, Clone, PartialEq)]
pub enum MotorStatus {
    /// Not activated.
    Inactive,
    /// Activated; waits for both inputs (002 §1: control starts once wheel angles and a
    /// target velocity have arrived). Zero torque.
    WaitingForInput {
        /// Whether wheel angles have arrived.
        wheel_angle: bool,
        /// Whether a target velocity has arrived.
        target_velocity: bool,
    },
    /// Controlling the wheels to the target velocity.
    Running,
    /// `Stop` was called (bump): controlling the wheels to zero velocity until `Start`.
    Stopped,
    /// `Finish` was called: zero torque until `Start`.
    Finished,
    /// Zero torque because of this input problem (spec §4 Decision).
    SafeStop(MotionError),
}

impl fmt::Display for MotorStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Inactive => f.write_str("inactive"),
            Self::WaitingForInput {
                wheel_angle,
                target_velocity,
            } => {
                let mut missing = Vec::new();
                if !wheel_angle {
                    missing.push("InCurrentWheelAngle");
                }
                if !target_velocity {
                    missing.push("TargetVelocity");
                }
                write!(f, "waiting for {}", missing.join(" and "))
            }
            Self::Running => f.write_str("running"),
            Self::Stopped => f.write_str("stopped (Stop): braking to zero velocity"),
            Self::Finished => f.write_str("finished (Finish): zero torque"),
            Self::SafeStop(e) => write!(f, "safe stop, zero torque: {e}"),
        }
    }
}

/// What a wheel's gains do to its rate loop (spec §4, the note for teaching). The target
/// angle is re-anchored at the current angle every tick, so `P·(target angle − angle) =
/// P·(ω* + ω)·Δt/2`: the torque is `(D + P·Δt/2)·ω* − (D − P·Δt/2)·ω`. D holds the wheel at
/// its target rate; P only adds `P·Δt/2` per rad/s, and above `2·D/Δt` it turns the rate
/// feedback positive: the loop is unstable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GainWarning {
    /// `P > 2·D/Δt`: positive rate feedback, the wheel runs away.
    Unstable {
        /// The P gain.
        p: f64,
        /// The D gain.
        d: f64,
        /// The bound `2·D/Δt`.
        bound: f64,
    },
    /// `D = 0`: nothing holds the wheel at its target rate; P alone gives `P·Δt/2` N·m per
    /// rad/s of rate error (on a re-anchored angle), far too little: the wheel is limp.
    Limp {
        /// The P gain.
        p: f64,
        /// The rate gain P alone gives, `P·Δt/2` \[N·m·s/rad\].
        rate_gain: f64,
    },
}

impl GainWarning {
    /// The warning for one wheel's gains `p`, `d` at MotorControl's period `dt` \[s\], if
    /// any (spec §4 note).
    pub fn check(p: f64, d: f64, dt: f64) -> Option<Self> {
        if d == 0.0 {
            return Some(Self::Limp {
                p,
                rate_gain: p * dt / 2.0,
            });
        }
        let bound = 2.0 * d / dt;
        (p > bound).then_some(Self::Unstable { p, d, bound })
    }
}

impl fmt::Display for GainWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Unstable { p, d, bound } => write!(
                f,
                "P {} is above 2·D/Δt = {} (D {}): the rate feedback turns positive and the \
                 wheel runs away",
                number(*p),
                number(*bound),
                number(*d)
            ),
            Self::Limp { rate_gain, .. } => write!(
                f,
                "D is 0: nothing holds the wheel at its target rate (P adds only P·Δt/2 = {} \
                 N·m per rad/s): the wheel is limp",
                number(*rate_gain)
            ),
        }
    }
}

/// The `on_activation` parameters as locked in `on_activated` (002 §5.2.3 (2)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorGeometry {
    /// Wheel radii and axle.
    pub drive: DiffDrive,
    /// Simulated-pose offsets.
    pub frame: ModelFrame,
    /// `leftWheelID`.
    pub left_wheel_id: usize,
    /// `rightWheelID`.
    pub right_wheel_id: usize,
    /// `radiusOfBodyArea` \[m\].
    pub radius_of_body_area: f64,
}

impl MotorGeometry {
    /// The geometry `p`'s `on_activation` parameters give; equal wheel ids are refused.
    pub fn from_params(p: &MotorControlParams) -> Result<Self, MotionError> {
        if p.left_wheel_id == p.right_wheel_id {
            return Err(MotionError::SameWheelId {
                id: p.left_wheel_id,
            });
        }
        Ok(Self {
            drive: DiffDrive::new(
                p.radius_of_left_wheel,
                p.radius_of_right_wheel,
                p.length_of_axle,
            )?,
            frame: ModelFrame::new(
                p.simulated_offset_x,
                p.simulated_offset_y,
                p.simulated_offset_angle,
            )?,
            left_wheel_id: p.left_wheel_id.max(0) as usize,
            right_wheel_id: p.right_wheel_id.max(0) as usize,
            radius_of_body_area: p.radius_of_body_area,
        })
    }

    /// Length of the joint sequences: both wheel ids must index into it.
    fn joints(&self) -> usize {
        self.left_wheel_id.max(self.right_wheel_id) + 1
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Wheels {
    tm: Time,
    angle: [f64; 2],
    rate: [f64; 2],
    /// TimeStep: the timestamps' difference \[s\] (0 for the first sample).
    dt: f64,
    arrived_ns: u64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct Target {
    tm: Time,
    v: f64,
    w: f64,
    arrived_ns: u64,
}

/// The MotorControl RT-component (002).
#[derive(Debug, Clone)]
pub struct MotorControl {
    name: String,
    config: Configuration<MotorControlParams>,
    /// `TargetVelocity` (in): target (V, ω) at the robot centre from DriveControl (002 §3.1).
    pub target_velocity: InPort<TimedVelocity>,
    /// `InCurrentWheelAngle` (in): absolute wheel angles from the simulator, indexed by
    /// `leftWheelID` / `rightWheelID` \[rad\].
    pub in_current_wheel_angle: InPort<TimedDoubleSeq>,
    /// `InSimulatedPosition` (in): the simulator's body transform `[X, Y, Z, A11..A33]`.
    pub in_simulated_position: InPort<TimedDoubleSeq>,
    /// `Torque` (out): wheel torques at the wheel ids (`[left, right]` by default) \[N·m\].
    pub torque: OutPort<TimedDoubleSeq>,
    /// `OutCurrentWheelAngle` (out): the valid wheel-angle input, passed through.
    pub out_current_wheel_angle: OutPort<TimedDoubleSeq>,
    /// `OutSimulatedPositionToInventGUI` (out): the axle-centre pose `[X, Y, Z, θ]`.
    pub out_simulated_position_to_invent_gui: OutPort<TimedDoubleSeq>,
    /// `OutSimulatedPositionToLocalization` (out): the same pose, for Localization.
    pub out_simulated_position_to_localization: OutPort<TimedDoubleSeq>,
    geometry: MotorGeometry,
    wheels: Option<Wheels>,
    target: Option<Target>,
    wheel_fault: Option<MotionError>,
    velocity_fault: Option<MotionError>,
    enabled: bool,
    stopped: bool,
    status: MotorStatus,
    last_error: Option<MotionError>,
    target_rates: [f64; 2],
    target_angles: [f64; 2],
    last_torque: [f64; 2],
    simulated_pose: Option<(Pose, f64)>,
}

impl Default for MotorControl {
    fn default() -> Self {
        Self::new("MotorControl0")
    }
}

impl MotorControl {
    /// A MotorControl named `name`, every parameter at its default.
    pub fn new(name: &str) -> Self {
        let config = Configuration::<MotorControlParams>::new();
        let geometry = default_geometry();
        Self {
            name: name.to_owned(),
            config,
            target_velocity: InPort::new("TargetVelocity"),
            in_current_wheel_angle: InPort::new("InCurrentWheelAngle"),
            in_simulated_position: InPort::new("InSimulatedPosition"),
            torque: OutPort::new("Torque"),
            out_current_wheel_angle: OutPort::new("OutCurrentWheelAngle"),
            out_simulated_position_to_invent_gui: OutPort::new("OutSimulatedPositionToInventGUI"),
            out_simulated_position_to_localization: OutPort::new(
                "OutSimulatedPositionToLocalization",
            ),
            geometry,
            wheels: None,
            target: None,
            wheel_fault: None,
            velocity_fault: None,
            enabled: true,
            stopped: false,
            status: MotorStatus::Inactive,
            last_error: None,
            target_rates: [0.0; 2],
            target_angles: [0.0; 2],
            last_torque: [0.0; 2],
            simulated_pose: None,
        }
    }

    /// The configuration (requested and effective values).
    pub fn config(&self) -> &Configuration<MotorControlParams> {
        &self.config
    }

    /// The configuration, to change parameters (as RtSystemEditor's ConfigurationView).
    pub fn config_mut(&mut self) -> &mut Configuration<MotorControlParams> {
        &mut self.config
    }

    /// The `on_activation` parameters locked at the last activation.
    pub fn geometry(&self) -> &MotorGeometry {
        &self.geometry
    }

    /// What the component is doing, with the reason of a safe stop.
    pub fn status(&self) -> &MotorStatus {
        &self.status
    }

    /// The most recent input problem (kept until `Clear` or the next activation).
    pub fn last_error(&self) -> Option<&MotionError> {
        self.last_error.as_ref()
    }

    /// Current wheel rates `[left, right]` \[rad/s\] from the angle differences (002 §5.2.5.3).
    pub fn wheel_rates(&self) -> [f64; 2] {
        self.wheels.map_or([0.0; 2], |w| w.rate)
    }

    /// Target wheel rates `[ω_L*, ω_R*]` of the last control step (002 §5.2.5.4).
    pub fn target_wheel_rates(&self) -> [f64; 2] {
        self.target_rates
    }

    /// Target wheel angles of the last control step (002 §5.2.5.4).
    pub fn target_wheel_angles(&self) -> [f64; 2] {
        self.target_angles
    }

    /// The torques `[left, right]` sent last \[N·m\].
    pub fn last_torque(&self) -> [f64; 2] {
        self.last_torque
    }

    /// The last simulated pose converted (002 §5.2.5.6) and the model's Z.
    pub fn simulated_pose(&self) -> Option<(Pose, f64)> {
        self.simulated_pose
    }

    /// Whether torque output is enabled (`Start` / `Finish`).
    pub fn is_enabled(&self) -> bool {
        self.enabled
    }

    /// Whether `Stop` holds the target velocity at zero.
    pub fn is_stopped(&self) -> bool {
        self.stopped
    }

    // --- Service `Motor` (002 §3.2.2.1) ---

    /// `SetPDGain(PGainL, PGainR, DGainL, DGainR)` (002 §3.2.2.1 (1), §5.2.5.1): sets the
    /// four gains (as the `always` parameters), effective at the next tick. All four are
    /// checked first (each in `[0, 10⁶]`); on any error nothing changes.
    pub fn set_pd_gain(
        &mut self,
        p_gain_l: f64,
        p_gain_r: f64,
        d_gain_l: f64,
        d_gain_r: f64,
    ) -> crate::Result<()> {
        let mut next = self.config.clone();
        next.set("PGainL", p_gain_l)?;
        next.set("PGainR", p_gain_r)?;
        next.set("DGainL", d_gain_l)?;
        next.set("DGainR", d_gain_r)?;
        self.config = next;
        Ok(())
    }

    /// `Start` (T.B.D. in the seed; spec §4 Decision): enables torque output and releases
    /// `Stop`.
    pub fn start(&mut self) {
        self.enabled = true;
        self.stopped = false;
    }

    /// `Finish` (spec §4 Decision): disables torque output (zero torque) until `Start`.
    pub fn finish(&mut self) {
        self.enabled = false;
    }

    /// `Clear` (spec §4 Decision): drops the controller's held state — wheel angles and
    /// rates, target velocity, input faults and the last error — as after activation.
    /// `Start`/`Finish`/`Stop` states stay.
    pub fn clear(&mut self) {
        self.wheels = None;
        self.target = None;
        self.wheel_fault = None;
        self.velocity_fault = None;
        self.last_error = None;
        self.target_rates = [0.0; 2];
        self.target_angles = [0.0; 2];
    }

    /// `Stop` (from bump detection; spec §4 Decision): the target velocity is zero until the
    /// next `Start` (the wheels are braked by the PD law).
    pub fn stop(&mut self) {
        self.stopped = true;
    }

    // --- onExecute parts (002 §5.2.5) ---

    fn fail(&mut self, e: MotionError) -> MotionError {
        self.last_error = Some(e.clone());
        e
    }

    /// 002 §5.2.5.3: checks and keeps a wheel-angle sample; the rate is the angle difference
    /// over the timestamps' difference (0 for the first sample). The sequence must hold both
    /// wheel ids (shorter is the wrong length); longer is accepted, because OpenHRP3's
    /// `JOINT_VALUE` carries every joint of the model and the ids pick the wheels.
    fn accept_wheel_angles(&mut self, msg: &TimedDoubleSeq, now: u64) -> Result<(), MotionError> {
        const PORT: &str = "InCurrentWheelAngle";
        let tm = msg.tm.checked(PORT)?;
        let g = self.geometry;
        if msg.data.len() < g.joints() {
            return Err(MotionError::WrongLength {
                port: PORT,
                len: msg.data.len(),
                expected: format!(
                    "at least {} (leftWheelID {}, rightWheelID {})",
                    g.joints(),
                    g.left_wheel_id,
                    g.right_wheel_id
                ),
            });
        }
        let angle = [msg.data[g.left_wheel_id], msg.data[g.right_wheel_id]];
        for (id, v) in [(g.left_wheel_id, angle[0]), (g.right_wheel_id, angle[1])] {
            if !v.is_finite() {
                return Err(MotionError::NonFinite {
                    port: PORT,
                    field: format!("data[{id}]"),
                    value: v,
                });
            }
        }
        let (rate, dt) = match self.wheels {
            None => ([0.0; 2], 0.0),
            Some(prev) => {
                if tm <= prev.tm {
                    return Err(MotionError::TimeWentBackwards {
                        port: PORT,
                        previous_s: prev.tm.as_secs_f64(),
                        now_s: tm.as_secs_f64(),
                    });
                }
                // Both timestamps are valid and ordered, so this is positive; the
                // difference saturates all the same (spec §4 Decision 0.2).
                let dt = tm.nanos_since(prev.tm) as f64 * 1e-9;
                (
                    [
                        (angle[0] - prev.angle[0]) / dt,
                        (angle[1] - prev.angle[1]) / dt,
                    ],
                    dt,
                )
            }
        };
        self.wheels = Some(Wheels {
            tm,
            angle,
            rate,
            dt,
            arrived_ns: now,
        });
        Ok(())
    }

    /// 002 §5.2.5.4: checks and keeps a target velocity (`vy` is ignored: a differential
    /// drive cannot move sideways, spec §4).
    fn accept_target_velocity(&mut self, msg: &TimedVelocity, now: u64) -> Result<(), MotionError> {
        const PORT: &str = "TargetVelocity";
        let tm = msg.tm.checked(PORT)?;
        for (field, v) in [("vx", msg.vx), ("w", msg.w)] {
            if !v.is_finite() {
                return Err(MotionError::NonFinite {
                    port: PORT,
                    field: field.to_owned(),
                    value: v,
                });
            }
        }
        if let Some(prev) = self.target
            && tm < prev.tm
        {
            return Err(MotionError::TimeWentBackwards {
                port: PORT,
                previous_s: prev.tm.as_secs_f64(),
                now_s: tm.as_secs_f64(),
            });
        }
        self.target = Some(Target {
            tm,
            v: msg.vx,
            w: msg.w,
            arrived_ns: now,
        });
        Ok(())
    }

    /// 002 §5.2.5.6: the simulated pose, converted to the axle centre.
    fn convert_simulated_position(&mut self, msg: &TimedDoubleSeq) -> Result<(), MotionError> {
        let tm = msg.tm.checked("InSimulatedPosition")?;
        let (pose, z) = self
            .geometry
            .frame
            .axle_pose(&msg.data, "InSimulatedPosition")?;
        self.simulated_pose = Some((pose, z));
        let out = TimedDoubleSeq {
            tm,
            data: vec![pose.x, pose.y, z, pose.theta],
        };
        self.out_simulated_position_to_invent_gui.write(out.clone());
        self.out_simulated_position_to_localization.write(out);
        Ok(())
    }

    fn safe_stop(&mut self, e: MotionError) -> [f64; 2] {
        let already = matches!(&self.status, MotorStatus::SafeStop(old) if *old == e);
        if !already {
            self.last_error = Some(e.clone());
        }
        self.status = MotorStatus::SafeStop(e);
        [0.0; 2]
    }

    /// 002 §5.2.5.4–5: target rates and angles, and the PD torque
    /// `P·(target angle − angle) + D·(target rate − rate)` (restoring sign, spec §4 Decision).
    fn control(&mut self, now: u64) -> [f64; 2] {
        if !self.enabled {
            self.status = MotorStatus::Finished;
            return [0.0; 2];
        }
        if let Some(e) = self
            .wheel_fault
            .clone()
            .or_else(|| self.velocity_fault.clone())
        {
            return self.safe_stop(e);
        }
        let (Some(wheels), Some(target)) = (self.wheels, self.target) else {
            self.status = MotorStatus::WaitingForInput {
                wheel_angle: self.wheels.is_some(),
                target_velocity: self.target.is_some(),
            };
            return [0.0; 2];
        };
        for (port, arrived) in [
            ("InCurrentWheelAngle", wheels.arrived_ns),
            ("TargetVelocity", target.arrived_ns),
        ] {
            let age = now.saturating_sub(arrived);
            if age >= INPUT_TIMEOUT_NS {
                let age_s = age as f64 * 1e-9;
                let limit_s = INPUT_TIMEOUT_NS as f64 * 1e-9;
                // Report once per stale episode (the age grows every tick).
                if !matches!(&self.status, MotorStatus::SafeStop(MotionError::Stale { port: p, .. }) if *p == port)
                {
                    self.last_error = Some(MotionError::Stale {
                        port,
                        age_s,
                        limit_s,
                    });
                }
                self.status = MotorStatus::SafeStop(MotionError::Stale {
                    port,
                    age_s,
                    limit_s,
                });
                return [0.0; 2];
            }
        }
        let (v, w) = if self.stopped {
            (0.0, 0.0)
        } else {
            (target.v, target.w)
        };
        let gains = *self.config.params();
        let p = [gains.p_gain_l, gains.p_gain_r];
        let d = [gains.d_gain_l, gains.d_gain_r];
        let target_rates = self.geometry.drive.wheel_rates(v, w);
        let mut torque = [0.0; 2];
        let mut target_angles = [0.0; 2];
        for i in 0..2 {
            target_angles[i] =
                wheels.angle[i] + (target_rates[i] + wheels.rate[i]) * wheels.dt / 2.0;
            torque[i] = p[i] * (target_angles[i] - wheels.angle[i])
                + d[i] * (target_rates[i] - wheels.rate[i]);
        }
        self.target_rates = target_rates;
        self.target_angles = target_angles;
        if let Some((i, &t)) = torque.iter().enumerate().find(|(_, t)| !t.is_finite()) {
            return self.safe_stop(MotionError::NonFinite {
                port: "Torque",
                field: format!(
                    "[{i}] (from TargetVelocity vx = {}, w = {})",
                    target.v, target.w
                ),
                value: t,
            });
        }
        self.status = if self.stopped {
            MotorStatus::Stopped
        } else {
            MotorStatus::Running
        };
        torque
    }

    fn send_torque(&mut self, tm: Time, torque: [f64; 2]) {
        let g = self.geometry;
        let mut data = vec![0.0; g.joints()];
        data[g.left_wheel_id] = torque[0];
        data[g.right_wheel_id] = torque[1];
        self.last_torque = torque;
        self.torque.write(TimedDoubleSeq { tm, data });
    }
}

/// The geometry of the default parameters.
pub fn default_geometry() -> MotorGeometry {
    let p = MotorControlParams::default();
    MotorGeometry {
        drive: DiffDrive::default(),
        frame: ModelFrame::default(),
        left_wheel_id: 0,
        right_wheel_id: 1,
        radius_of_body_area: p.radius_of_body_area,
    }
}

impl Component for MotorControl {
    component_basics!(name: name, config: config);

    component_ports!(in: [target_velocity, in_current_wheel_angle, in_simulated_position], out: [torque, out_current_wheel_angle, out_simulated_position_to_invent_gui, out_simulated_position_to_localization]);

    /// 002 §5.2.3: (1) every held value and flag off; (2) the `on_activation` parameters
    /// copied and locked; (3) stale data dropped from the in-ports. Equal wheel ids fail the
    /// activation (→ Error, with the reason).
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        let geometry = MotorGeometry::from_params(self.config.params())
            .map_err(|e| ComponentError::from(crate::Error::from(e)))?;
        self.geometry = geometry;
        self.wheels = None;
        self.target = None;
        self.wheel_fault = None;
        self.velocity_fault = None;
        self.enabled = true;
        self.stopped = false;
        self.last_error = None;
        self.target_rates = [0.0; 2];
        self.target_angles = [0.0; 2];
        self.simulated_pose = None;
        self.status = MotorStatus::WaitingForInput {
            wheel_angle: false,
            target_velocity: false,
        };
        self.target_velocity.clear();
        self.in_current_wheel_angle.clear();
        self.in_simulated_position.clear();
        Ok(())
    }

    /// 002 §5.2.4; also sends zero torque, so the simulator does not keep the last one.
    fn on_deactivated(&mut self, tick: &Tick) -> ReturnCode {
        self.send_torque(tick.tm(), [0.0; 2]);
        self.status = MotorStatus::Inactive;
        Ok(())
    }

    /// Sends zero torque before the component enters Error.
    fn on_aborting(&mut self, tick: &Tick) -> ReturnCode {
        self.send_torque(tick.tm(), [0.0; 2]);
        Ok(())
    }

    /// 002 §5.2.5 (the gains are read inside the control step, §5.2.5.1; services act
    /// directly on the held flags, §5.2.5.2, §5.2.6).
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        let now = tick.time_ns;
        if self.in_current_wheel_angle.is_new()
            && let Some(msg) = self.in_current_wheel_angle.read()
        {
            match self.accept_wheel_angles(&msg, now) {
                Ok(()) => {
                    self.wheel_fault = None;
                    self.out_current_wheel_angle.write(msg);
                }
                Err(e) => self.wheel_fault = Some(self.fail(e)),
            }
        }
        if self.target_velocity.is_new()
            && let Some(msg) = self.target_velocity.read()
        {
            match self.accept_target_velocity(&msg, now) {
                Ok(()) => self.velocity_fault = None,
                Err(e) => self.velocity_fault = Some(self.fail(e)),
            }
        }
        if self.in_simulated_position.is_new()
            && let Some(msg) = self.in_simulated_position.read()
            && let Err(e) = self.convert_simulated_position(&msg)
        {
            self.fail(e);
        }
        let torque = self.control(now);
        self.send_torque(tick.tm(), torque);
        Ok(())
    }
}
