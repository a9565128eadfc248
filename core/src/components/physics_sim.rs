//! PhysicsSim: the physics as an RT-component, in place of OpenHRP3 and its
//! ControllerBridge (spec §5 "Physics", 002 §5.2.7 `bridge.sh`).
//!
//! Its ports carry the bridge's names and data: in `torque` (`JOINT_TORQUE`, `[left, right]`
//! N·m), out `angle` (`JOINT_VALUE`, `[left, right]` rad) and `position`
//! (`BODY:ABS_TRANSFORM`, `[X, Y, Z, A11..A33]` of the model origin, in the model frame of
//! [`PhysicsParams`]). Connect them to MotorControl's `Torque`, `InCurrentWheelAngle` and
//! `InSimulatedPosition`. A fourth port, `bump`, reports bumps (spec §5: "the robot stops;
//! the GUI shows it").
//!
//! Each tick it applies the newest torque (held between messages, as a simulator does) for
//! `period / 1 ms` fixed steps, then publishes the state stamped with the time reached.
//! Run it at 1 kHz (one step per tick).
//!
//! Its configuration ([`PhysicsSimParams`]) is the model's dynamics — `Mass`, `YawInertia`,
//! `ViscousFriction`, `MaxTorque` — so a lesson can make the robot heavier or its motors
//! weaker while it drives. All are `always`: a changed value is used from the next tick on
//! (the mass matrix and the step matrix are recomputed then; the state carries over).

use crate::define_parameters;
use crate::errors::MotionError;
use crate::interfaces::Pose;
use crate::map::{GridMap, MapUpdate};
use crate::motion::{
    BumpReport, DEFAULT_MASS, DEFAULT_MAX_TORQUE, DEFAULT_VISCOUS_FRICTION, DEFAULT_YAW_INERTIA,
    Physics, PhysicsParams, STEP_NS,
};
use crate::rtc::{
    Component, ComponentError, ConfigAccess, Configuration, InPort, OutPort, ReturnCode, Tick,
    Time, TimedDoubleSeq,
};

define_parameters! {
    /// PhysicsSim's configuration parameters: the dynamics of the robot model of spec §5
    /// "Physics" (`M·ω̇ = τ − b·ω`, torques saturated). All `always`: used from the next tick
    /// on. The defaults are [`PhysicsParams`]' defaults, the model the system is built with.
    pub struct PhysicsSimParams {
        /// Mass `m` \[kg\] (spec §5 "Physics"; [`PhysicsParams::mass`]).
        mass: f64 = ("Mass", "kg", DEFAULT_MASS, 0.1, 1000.0, Always,
            "mass m of the robot (spec §5 Physics): its share of the wheel-space mass matrix"),
        /// Yaw moment of inertia `I` about the axle centre \[kg·m²\] (spec §5 "Physics";
        /// [`PhysicsParams::yaw_inertia`]).
        yaw_inertia: f64 = ("YawInertia", "kg·m²", DEFAULT_YAW_INERTIA, 0.001, 1000.0, Always,
            "yaw moment of inertia I about the axle centre (spec §5 Physics): resists turning"),
        /// Viscous friction `b` at each wheel \[N·m·s/rad\] (spec §5 "Physics";
        /// [`PhysicsParams::viscous_friction`]).
        viscous_friction: f64 = ("ViscousFriction", "N·m·s/rad", DEFAULT_VISCOUS_FRICTION,
            0.0, 10.0, Always,
            "viscous friction b at each wheel (spec §5 Physics): torque b·ω against the wheel's rate"),
        /// Torque saturation of each wheel's motor \[N·m\] (spec §5 "Physics";
        /// [`PhysicsParams::max_torque`]).
        max_torque: f64 = ("MaxTorque", "N·m", DEFAULT_MAX_TORQUE, 0.01, 100.0, Always,
            "largest torque of each wheel's motor (spec §5 Physics): commands above it saturate"),
    }
}

impl PhysicsSimParams {
    /// These values in place of the dynamics of `base` (the rest of the model kept).
    pub fn apply_to(&self, base: &PhysicsParams) -> PhysicsParams {
        PhysicsParams {
            mass: self.mass,
            yaw_inertia: self.yaw_inertia,
            viscous_friction: self.viscous_friction,
            max_torque: self.max_torque,
            ..base.clone()
        }
    }

    /// Whether `params` has exactly these dynamics.
    fn matches(&self, params: &PhysicsParams) -> bool {
        self.mass == params.mass
            && self.yaw_inertia == params.yaw_inertia
            && self.viscous_friction == params.viscous_friction
            && self.max_torque == params.max_torque
    }
}

/// The physics RT-component.
#[derive(Debug, Clone)]
pub struct PhysicsSim {
    name: String,
    config: Configuration<PhysicsSimParams>,
    physics: Physics,
    /// `torque` (in): wheel torques `[left, right]` \[N·m\].
    pub torque: InPort<TimedDoubleSeq>,
    /// `angle` (out): wheel angles `[left, right]` \[rad\].
    pub angle: OutPort<TimedDoubleSeq>,
    /// `position` (out): the model's body transform `[X, Y, Z, A11..A33]`.
    pub position: OutPort<TimedDoubleSeq>,
    /// `bump` (out): a report for every new bump.
    pub bump: OutPort<BumpReport>,
    applied: [f64; 2],
    last_error: Option<MotionError>,
    last_bump: Option<BumpReport>,
    fail_on_bump: bool,
}

impl PhysicsSim {
    /// A physics component named `name` with the model `params` (validated). Its
    /// configuration starts at the dynamics of `params`; a value outside the configuration's
    /// range (e.g. a mass above 1000 kg) is refused.
    pub fn new(name: &str, params: PhysicsParams) -> Result<Self, MotionError> {
        let physics = Physics::new(params)?;
        let mut config = Configuration::<PhysicsSimParams>::new();
        let p = physics.params();
        for (key, value) in [
            ("Mass", p.mass),
            ("YawInertia", p.yaw_inertia),
            ("ViscousFriction", p.viscous_friction),
            ("MaxTorque", p.max_torque),
        ] {
            config
                .set(key, value)
                .map_err(|_| MotionError::BadParameter {
                    name: key.to_owned(),
                    value,
                    reason: "is outside PhysicsSim's configuration range",
                })?;
        }
        Ok(Self {
            name: name.to_owned(),
            config,
            physics,
            torque: InPort::new("torque"),
            angle: OutPort::new("angle"),
            position: OutPort::new("position"),
            bump: OutPort::new("bump"),
            applied: [0.0; 2],
            last_error: None,
            last_bump: None,
            fail_on_bump: false,
        })
    }

    /// The physics (state, parameters, map).
    pub fn physics(&self) -> &Physics {
        &self.physics
    }

    /// The configuration (the model's dynamics).
    pub fn config(&self) -> &Configuration<PhysicsSimParams> {
        &self.config
    }

    /// The configuration, to change parameters (used from the next tick on).
    pub fn config_mut(&mut self) -> &mut Configuration<PhysicsSimParams> {
        &mut self.config
    }

    /// Brings the physics' model in line with the configuration (a changed value recomputes
    /// the mass matrix; nothing is done while they agree, so the defaults change no bit).
    fn apply_config(&mut self) -> Result<(), MotionError> {
        let c = *self.config.params();
        if c.matches(self.physics.params()) {
            return Ok(());
        }
        let next = c.apply_to(self.physics.params());
        self.physics.set_params(next)
    }

    /// Places the robot at `pose` (the start pose), at rest.
    pub fn set_pose(&mut self, pose: Pose) -> Result<(), MotionError> {
        self.physics.set_pose(pose)
    }

    /// Sets the map for bump detection (`SetMap`; `None`: open space).
    pub fn set_map(&mut self, map: Option<GridMap>) {
        self.physics.set_map(map);
    }

    /// `MapUpdate` on the held map (atomic; spec §2). A timestamp whose `nsec` is not below
    /// 10⁹ is refused ([`MapUpdate::check`], spec §4 Decision 0.2) and nothing changes.
    pub fn map_update(&mut self, update: &MapUpdate) -> crate::Result<usize> {
        self.physics.map_update(update)
    }

    /// The torque being applied (the newest valid input; zero after a bad one) \[N·m\].
    pub fn applied_torque(&self) -> [f64; 2] {
        self.applied
    }

    /// The most recent bad torque input.
    pub fn last_error(&self) -> Option<&MotionError> {
        self.last_error.as_ref()
    }

    /// The most recent bump.
    pub fn last_bump(&self) -> Option<&BumpReport> {
        self.last_bump.as_ref()
    }

    /// Whether a bump also fails `on_execute` with the bump report as the reason, so the
    /// component goes to Error (the whole system's "a bump stops the robot and puts the
    /// system in Error", spec §5 Physics; used by `system::System`). Off by default: the
    /// report is then only written to `bump`.
    pub fn set_fail_on_bump(&mut self, fail: bool) {
        self.fail_on_bump = fail;
    }

    /// Whether a bump fails `on_execute` ([`PhysicsSim::set_fail_on_bump`]).
    pub fn fails_on_bump(&self) -> bool {
        self.fail_on_bump
    }

    fn steps(tick: &Tick) -> Result<u64, MotionError> {
        if tick.period_ns == 0 || !tick.period_ns.is_multiple_of(STEP_NS) {
            return Err(MotionError::BadPeriod {
                period_ns: tick.period_ns,
                step_ns: STEP_NS,
            });
        }
        Ok(tick.period_ns / STEP_NS)
    }

    fn read_torque(&mut self) {
        if !self.torque.is_new() {
            return;
        }
        let Some(msg) = self.torque.read() else {
            return;
        };
        let checked = if let Err(e) = msg.tm.checked("torque") {
            Err(MotionError::from(e))
        } else if msg.data.len() != 2 {
            Err(MotionError::WrongLength {
                port: "torque",
                len: msg.data.len(),
                expected: "2".to_owned(),
            })
        } else if let Some((i, &v)) = msg.data.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            Err(MotionError::NonFinite {
                port: "torque",
                field: format!("data[{i}]"),
                value: v,
            })
        } else {
            Ok([msg.data[0], msg.data[1]])
        };
        match checked {
            Ok(t) => self.applied = t,
            Err(e) => {
                self.applied = [0.0; 2];
                self.last_error = Some(e);
            }
        }
    }

    fn publish(&mut self) {
        let tm = Time::from_nanos(self.physics.state().time_ns);
        self.angle.write(TimedDoubleSeq {
            tm,
            data: self.physics.state().wheel_angle.to_vec(),
        });
        self.position.write(TimedDoubleSeq {
            tm,
            data: self.physics.model_transform().to_vec(),
        });
    }
}

impl Component for PhysicsSim {
    component_basics!(name: name, config: config);

    component_ports!(in: [torque], out: [angle, position, bump]);

    /// Checks the period and starts the simulated clock at the activation time.
    fn on_activated(&mut self, tick: &Tick) -> ReturnCode {
        Self::steps(tick).map_err(|e| ComponentError::from(crate::Error::from(e)))?;
        self.physics.set_time_ns(tick.time_ns);
        self.applied = [0.0; 2];
        self.torque.clear();
        Ok(())
    }

    /// Refuses a rate whose period is not a whole number of 1 ms steps (reported; the
    /// next tick fails if it is kept).
    fn on_rate_changed(&mut self, tick: &Tick) -> ReturnCode {
        Self::steps(tick).map_err(|e| ComponentError::from(crate::Error::from(e)))?;
        Ok(())
    }

    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        let n = Self::steps(tick).map_err(|e| ComponentError::from(crate::Error::from(e)))?;
        self.apply_config()
            .map_err(|e| ComponentError::from(crate::Error::from(e)))?;
        if self.physics.state().time_ns != tick.time_ns {
            // Inactive for a while, or ticks skipped: the world waited.
            self.physics.set_time_ns(tick.time_ns);
        }
        self.read_torque();
        for _ in 0..n {
            match self.physics.step(self.applied) {
                Ok(Some(report)) => {
                    self.bump.write(report.clone());
                    self.last_bump = Some(report.clone());
                    if self.fail_on_bump {
                        self.applied = [0.0; 2];
                        self.publish();
                        return Err(ComponentError::new(crate::Reason::Bump(report)));
                    }
                }
                Ok(None) => {}
                Err(e) => {
                    // Unreachable with the checks above; keep the time running all the same.
                    self.applied = [0.0; 2];
                    self.last_error = Some(e);
                }
            }
        }
        self.publish();
        Ok(())
    }
}
