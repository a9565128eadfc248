//! Localization (spec §5): the robot pose as `TimedPosition`, from the simulated pose or from
//! wheel odometry, selectable so that odometry drift can be taught.
//!
//! Inputs are MotorControl's outputs: `InSimulatedPosition` ← `OutSimulatedPositionToLocalization`
//! (`[X, Y, Z, θ]`, 002 §3.1) and `InCurrentWheelAngle` ← `OutCurrentWheelAngle` (absolute
//! wheel angles). Both estimates are kept all the time; `LocalizationMode` chooses which one
//! is published on `OutCurrentPosition` (→ LocalPathPlanning's and DriveControl's
//! `InCurrentPosition`). Odometry starts at the start pose ([`Localization::set_start_pose`])
//! and integrates exact arcs ([`crate::motion::Odometry`]) with its own wheel geometry
//! (which may differ from the simulated robot's: drift).
//!
//! **Decision (faults)**: a non-finite number on either input is a fault — the pose
//! can no longer be trusted, and publishing it would send NaN on to the planners and
//! DriveControl — so `on_execute` fails with the port and field named, and the component goes
//! to Error (spec §1); the held pose stays and Reset recovers. A wrong length, a timestamp
//! whose `nsec` is not below 10⁹ ([`crate::rtc::Time::checked`], spec §4 Decision 0.2) or
//! time not advancing is ignored and reported ([`Localization::last_error`]); the held pose stays.

use crate::define_parameters;
use crate::errors::MotionError;
use crate::interfaces::Pose;
use crate::motion::{DiffDrive, Odometry, wrap_angle};
use crate::rtc::{
    Component, ComponentError, Configuration, InPort, OutPort, ReturnCode, Tick, TimedDoubleSeq,
    TimedPosition,
};

/// Where the published pose comes from (`LocalizationMode`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[cfg_attr(feature = "typescript", derive(ts_rs::TS))]
pub enum LocalizationMode {
    /// 0: the simulated pose (ground truth).
    #[default]
    SimulatedPose,
    /// 1: wheel odometry.
    Odometry,
}

define_parameters! {
    /// Localization's configuration parameters.
    pub struct LocalizationParams {
        /// `LocalizationMode`: 0 simulated pose, 1 wheel odometry (`always`).
        localization_mode: i32 = ("LocalizationMode", "-", 0.0, 0.0, 1.0, Always,
            "0: simulated pose, 1: wheel odometry"),
        /// `leftWheelID`: index of the left wheel in `InCurrentWheelAngle`.
        left_wheel_id: i32 = ("leftWheelID", "-", 0.0, 0.0, 63.0, OnActivation,
            "index of the left wheel angle"),
        /// `rightWheelID`: index of the right wheel.
        right_wheel_id: i32 = ("rightWheelID", "-", 1.0, 0.0, 63.0, OnActivation,
            "index of the right wheel angle"),
        /// Odometry's left wheel radius.
        radius_of_left_wheel: f64 = ("radiusOfLeftWheel", "m", 0.1, 0.001, 10.0, OnActivation,
            "left wheel radius used by odometry"),
        /// Odometry's right wheel radius.
        radius_of_right_wheel: f64 = ("radiusOfRightWheel", "m", 0.1, 0.001, 10.0, OnActivation,
            "right wheel radius used by odometry"),
        /// Odometry's axle length.
        length_of_axle: f64 = ("lengthOfAxle", "m", 0.441, 0.001, 10.0, OnActivation,
            "axle length used by odometry"),
    }
}

impl LocalizationParams {
    /// The selected mode.
    pub fn mode(&self) -> LocalizationMode {
        if self.localization_mode == 1 {
            LocalizationMode::Odometry
        } else {
            LocalizationMode::SimulatedPose
        }
    }
}

/// The Localization RT-component.
#[derive(Debug, Clone)]
pub struct Localization {
    name: String,
    config: Configuration<LocalizationParams>,
    /// `InSimulatedPosition` (in): `[X, Y, Z, θ]` from MotorControl.
    pub in_simulated_position: InPort<TimedDoubleSeq>,
    /// `InCurrentWheelAngle` (in): absolute wheel angles from MotorControl.
    pub in_current_wheel_angle: InPort<TimedDoubleSeq>,
    /// `OutCurrentPosition` (out): the robot pose.
    pub out_current_position: OutPort<TimedPosition>,
    start: Pose,
    simulated: Option<Pose>,
    odometry: Odometry,
    wheel_ids: (usize, usize),
    last_error: Option<MotionError>,
}

impl Default for Localization {
    fn default() -> Self {
        Self::new("Localization0")
    }
}

impl Localization {
    /// A Localization named `name`, start pose at the origin.
    pub fn new(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            config: Configuration::new(),
            in_simulated_position: InPort::new("InSimulatedPosition"),
            in_current_wheel_angle: InPort::new("InCurrentWheelAngle"),
            out_current_position: OutPort::new("OutCurrentPosition"),
            start: Pose::default(),
            simulated: None,
            odometry: Odometry::new(DiffDrive::default(), Pose::default()),
            wheel_ids: (0, 1),
            last_error: None,
        }
    }

    /// The configuration.
    pub fn config(&self) -> &Configuration<LocalizationParams> {
        &self.config
    }

    /// The configuration, to change parameters (e.g. `LocalizationMode`).
    pub fn config_mut(&mut self) -> &mut Configuration<LocalizationParams> {
        &mut self.config
    }

    /// Sets the start pose: odometry restarts there (its distance from zero), and it is the
    /// published pose until a simulated pose arrives. A non-finite pose is refused.
    pub fn set_start_pose(&mut self, pose: Pose) -> Result<(), MotionError> {
        self.odometry.reset(pose)?;
        self.start = Pose {
            theta: wrap_angle(pose.theta),
            ..pose
        };
        Ok(())
    }

    /// The start pose.
    pub fn start_pose(&self) -> Pose {
        self.start
    }

    /// The last simulated pose received.
    pub fn simulated_pose(&self) -> Option<Pose> {
        self.simulated
    }

    /// The odometry estimate.
    pub fn odometry(&self) -> &Odometry {
        &self.odometry
    }

    /// The pose published: from the selected source.
    pub fn current_pose(&self) -> Pose {
        match self.config.params().mode() {
            LocalizationMode::SimulatedPose => self.simulated.unwrap_or(self.start),
            LocalizationMode::Odometry => self.odometry.pose(),
        }
    }

    /// The most recent bad input.
    pub fn last_error(&self) -> Option<&MotionError> {
        self.last_error.as_ref()
    }

    fn read_simulated(&mut self, msg: &TimedDoubleSeq) -> Result<(), MotionError> {
        const PORT: &str = "InSimulatedPosition";
        msg.tm.checked(PORT)?;
        if msg.data.len() != 4 {
            return Err(MotionError::WrongLength {
                port: PORT,
                len: msg.data.len(),
                expected: "4 ([X, Y, Z, θ])".to_owned(),
            });
        }
        if let Some((i, &v)) = msg.data.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(MotionError::NonFinite {
                port: PORT,
                field: format!("data[{i}]"),
                value: v,
            });
        }
        self.simulated = Some(Pose::new(msg.data[0], msg.data[1], wrap_angle(msg.data[3])));
        Ok(())
    }

    /// Records a bad input; a non-finite one is returned as the component's failure.
    fn fail_if_fault(&mut self, e: MotionError) -> Result<(), ComponentError> {
        let fault = matches!(e, MotionError::NonFinite { .. });
        self.last_error = Some(e.clone());
        if fault {
            return Err(ComponentError::from(crate::Error::from(e)));
        }
        Ok(())
    }

    fn read_wheels(&mut self, msg: &TimedDoubleSeq) -> Result<(), MotionError> {
        const PORT: &str = "InCurrentWheelAngle";
        let tm = msg.tm.checked(PORT)?;
        let (l, r) = self.wheel_ids;
        let need = l.max(r) + 1;
        if msg.data.len() < need {
            return Err(MotionError::WrongLength {
                port: PORT,
                len: msg.data.len(),
                expected: format!("at least {need}"),
            });
        }
        self.odometry
            .update(tm, [msg.data[l], msg.data[r]], PORT)
            .map(|_| ())
    }
}

impl Component for Localization {
    component_basics!(name: name, config: config);

    component_ports!(in: [in_simulated_position, in_current_wheel_angle], out: [out_current_position]);

    /// Locks the odometry geometry and restarts odometry at the start pose.
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        let p = *self.config.params();
        let fail = |e: MotionError| ComponentError::from(crate::Error::from(e));
        if p.left_wheel_id == p.right_wheel_id {
            return Err(fail(MotionError::SameWheelId {
                id: p.left_wheel_id,
            }));
        }
        let drive = DiffDrive::new(
            p.radius_of_left_wheel,
            p.radius_of_right_wheel,
            p.length_of_axle,
        )
        .map_err(fail)?;
        self.wheel_ids = (
            p.left_wheel_id.max(0) as usize,
            p.right_wheel_id.max(0) as usize,
        );
        self.odometry = Odometry::new(drive, self.start);
        self.simulated = None;
        self.last_error = None;
        Ok(())
    }

    /// Reads both inputs and publishes the selected pose. A non-finite input fails (→ Error,
    /// nothing published); other bad input is ignored and reported.
    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        if self.in_simulated_position.is_new()
            && let Some(msg) = self.in_simulated_position.read()
            && let Err(e) = self.read_simulated(&msg)
        {
            self.fail_if_fault(e)?;
        }
        if self.in_current_wheel_angle.is_new()
            && let Some(msg) = self.in_current_wheel_angle.read()
            && let Err(e) = self.read_wheels(&msg)
        {
            self.fail_if_fault(e)?;
        }
        let pose = self.current_pose();
        self.out_current_position.write(TimedPosition {
            tm: tick.tm(),
            id: Vec::new(),
            x: pose.x,
            y: pose.y,
            theta: pose.theta,
            error: Vec::new(),
        });
        Ok(())
    }
}
