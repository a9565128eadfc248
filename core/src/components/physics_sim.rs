//! PhysicsSim: the physics as an RT-component, in place of OpenHRP3 and its
//! ControllerBridge (SPEC §5 "Physics", 002 §5.2.7 `bridge.sh`).
//!
//! Its ports carry the bridge's names and data: in `torque` (`JOINT_TORQUE`, `[left, right]`
//! N·m), out `angle` (`JOINT_VALUE`, `[left, right]` rad) and `position`
//! (`BODY:ABS_TRANSFORM`, `[X, Y, Z, A11..A33]` of the model origin, in the model frame of
//! [`PhysicsParams`]). Connect them to MotorControl's `Torque`, `InCurrentWheelAngle` and
//! `InSimulatedPosition`. A fourth port, `bump`, reports bumps (SPEC §5: "the robot stops;
//! the GUI shows it").
//!
//! Each tick it applies the newest torque (held between messages, as a simulator does) for
//! `period / 1 ms` fixed steps, then publishes the state stamped with the time reached.
//! Run it at 1 kHz (one step per tick).

use crate::errors::MotionError;
use crate::interfaces::Pose;
use crate::map::GridMap;
use crate::motion::{BumpReport, Physics, PhysicsParams, STEP_NS};
use crate::rtc::{
    Component, ComponentError, InPort, OutPort, ReturnCode, Tick, Time, TimedDoubleSeq,
};

/// The physics RT-component.
#[derive(Debug)]
pub struct PhysicsSim {
    name: String,
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
    /// A physics component named `name` with the model `params` (validated).
    pub fn new(name: &str, params: PhysicsParams) -> Result<Self, MotionError> {
        Ok(Self {
            name: name.to_owned(),
            physics: Physics::new(params)?,
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

    /// Places the robot at `pose` (the start pose), at rest.
    pub fn set_pose(&mut self, pose: Pose) -> Result<(), MotionError> {
        self.physics.set_pose(pose)
    }

    /// Sets the map for bump detection (`SetMap`; `None`: open space).
    pub fn set_map(&mut self, map: Option<GridMap>) {
        self.physics.set_map(map);
    }

    /// `MapUpdate` on the held map (atomic; SPEC §2).
    pub fn map_update(
        &mut self,
        x: &[i32],
        y: &[i32],
        value: &[i16],
        num: i32,
        tm: Time,
    ) -> crate::Result<usize> {
        self.physics.map_update(x, y, value, num, tm)
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
    /// system in Error", SPEC §5 Physics; used by `system::System`). Off by default: the
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
        let checked = if msg.data.len() != 2 {
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
    fn instance_name(&self) -> &str {
        &self.name
    }

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
                        return Err(ComponentError::new(format!("bump: {report}")));
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
