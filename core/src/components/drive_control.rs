//! DriveControl (spec §5): follows LocalPathPlanning's control points and sends MotorControl
//! its `TargetVelocity`; tells LocalPathPlanning how far the robot is from the path
//! (`OutDeviating` → `InDeviating`, 000 §3.1, §5.2.4.5).
//!
//! The control points are a polyline, followed by pure pursuit with a look-ahead, with
//! limits on speed, acceleration and turn rate, turning on the spot when the heading error is
//! large, slowing to a stop at the goal and turning to the goal heading, and driving backward
//! when the planner says so ([`crate::motion::PurePursuit`] has the details). Run it at 50 Hz
//! (spec §6).
//!
//! Without a pose, with a non-finite pose or one whose timestamp has `nsec` ≥ 10⁹ (refused by
//! [`crate::rtc::Time::checked`], spec §4 Decision 0.2), or with no new pose for 0.5 s it
//! sends zero velocity and reports why. Control points with such a timestamp are refused
//! (the held path stays) and reported.
//!
//! **Clearance check (spec §5, Decision)**: the planners keep `dmin` between cell centres,
//! and on a fine map that can leave the body (`radiusOfBodyArea`, told by the system)
//! millimetres from an obstacle's square, less than tracking strays. Like Nav2's collision
//! monitor, DriveControl therefore checks the commanded arc against the map
//! ([`free_travel`]) every tick and limits the speed so the robot can stop `SafetyMargin`
//! short of any contact. Where the arc is blocked it first turns on the spot towards the
//! path; if the way ahead is still blocked it stops, says so
//! ([`DriveStatus::SafetyStop`]), and asks for a new plan on its `SafetyStop` port (the
//! system passes it to LocalPathPlanning, every second while it stands).

use core::fmt;

use crate::define_parameters;
use crate::errors::MotionError;
use crate::interfaces::{ControlPoints, Pose};
use crate::map::{GridMap, MapUpdate};
use crate::motion::{DrivePhase, PurePursuit, PursuitParams, free_travel};
use crate::rtc::{
    Component, Configuration, InPort, OutPort, ReturnCode, Tick, TimedDouble, TimedPosition,
    TimedVelocity,
};

/// How long without a new pose before DriveControl stops: 0.5 s (as MotorControl, spec §4).
pub const POSE_TIMEOUT_NS: u64 = 500_000_000;
/// While a safety stop lasts, how often a new plan is asked for \[ns\].
pub const SAFETY_RETRY_NS: u64 = 1_000_000_000;
/// Free travel below which the way ahead counts as blocked \[m\].
const BLOCKED: f64 = 0.005;

define_parameters! {
    /// DriveControl's configuration parameters (spec §5: "limits on speed, acceleration and
    /// turn rate"); all `always`.
    pub struct DriveControlParams {
        /// Largest speed.
        max_velocity: f64 = ("MaxVelocity", "m/s", 0.5, 0.0, 2.0, Always,
            "largest speed, forward or backward"),
        /// Largest speed change (also the braking rate towards a stop).
        max_acceleration: f64 = ("MaxAcceleration", "m/s^2", 0.5, 0.01, 10.0, Always,
            "largest speed change; braking towards stops uses it too"),
        /// Largest turn rate.
        max_angular_velocity: f64 = ("MaxAngularVelocity", "rad/s", 1.0, 0.01, 6.0, Always,
            "largest turn rate"),
        /// Largest turn-rate change.
        max_angular_acceleration: f64 = ("MaxAngularAcceleration", "rad/s^2", 2.0, 0.01, 50.0,
            Always, "largest turn-rate change"),
        /// Pure-pursuit look-ahead distance.
        look_ahead_distance: f64 = ("LookAheadDistance", "m", 0.3, 0.01, 5.0, Always,
            "pure-pursuit look-ahead along the control-point polyline"),
        /// Heading error above which the robot turns on the spot; control points where the
        /// path turns by more are stops.
        turn_in_place_angle: f64 = ("TurnInPlaceAngle", "rad", core::f64::consts::FRAC_PI_4,
            0.0, core::f64::consts::PI, Always,
            "heading error for turning on the spot; sharper control points are stops"),
        /// Distance at which a stop or the goal is reached.
        goal_tolerance: f64 = ("GoalTolerance", "m", 0.01, 0.001, 1.0, Always,
            "distance at which a stop or the goal counts as reached"),
        /// Heading error at which the goal heading is reached.
        goal_angle_tolerance: f64 = ("GoalAngleTolerance", "rad", 0.01, 0.001, 1.0, Always,
            "heading error at which the goal heading counts as reached"),
        /// Creep speed at which stops are approached.
        min_velocity: f64 = ("MinVelocity", "m/s", 0.03, 0.0, 1.0, Always,
            "creep speed near a stop"),
        /// Turn rate per radian of heading error when turning on the spot.
        heading_gain: f64 = ("HeadingGain", "1/s", 2.0, 0.1, 50.0, Always,
            "turn rate per radian of heading error when turning on the spot"),
        /// Clearance the body keeps from obstacles: the speed is limited so the robot can
        /// stop this far short of any contact.
        safety_margin: f64 = ("SafetyMargin", "m", 0.01, 0.0, 0.5, Always,
            "clearance the body keeps from obstacles (the speed is limited to stop short of it)"),
    }
}

impl DriveControlParams {
    /// As the path follower's parameters.
    pub fn pursuit(&self) -> PursuitParams {
        PursuitParams {
            max_velocity: self.max_velocity,
            max_acceleration: self.max_acceleration,
            max_angular_velocity: self.max_angular_velocity,
            max_angular_acceleration: self.max_angular_acceleration,
            look_ahead_distance: self.look_ahead_distance,
            turn_in_place_angle: self.turn_in_place_angle,
            goal_tolerance: self.goal_tolerance,
            goal_angle_tolerance: self.goal_angle_tolerance,
            min_velocity: self.min_velocity,
            heading_gain: self.heading_gain,
        }
    }
}

/// What DriveControl is doing, for the GUI.
#[derive(Debug, Clone, PartialEq)]
pub enum DriveStatus {
    /// Not activated.
    Inactive,
    /// No pose has arrived yet: zero velocity.
    WaitingForPose,
    /// Driving (or idle, or arrived): the path follower's phase.
    Driving(DrivePhase),
    /// Zero velocity because of this input problem.
    SafeStop(MotionError),
    /// Stopped: the way ahead is blocked within this distance \[m\] of the body's margin
    /// (the clearance check); a new plan has been asked for.
    SafetyStop {
        /// Free travel left along the commanded arc \[m\].
        ahead: f64,
    },
}

impl fmt::Display for DriveStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Inactive => f.write_str("inactive"),
            Self::WaitingForPose => f.write_str("waiting for InCurrentPosition"),
            Self::Driving(DrivePhase::Idle) => f.write_str("idle (no path)"),
            Self::Driving(DrivePhase::TurnInPlace) => f.write_str("turning on the spot"),
            Self::Driving(DrivePhase::Following) => f.write_str("following the path"),
            Self::Driving(DrivePhase::FinalTurn) => f.write_str("turning to the goal heading"),
            Self::Driving(DrivePhase::Arrived) => f.write_str("arrived"),
            Self::SafeStop(e) => write!(f, "safe stop, zero velocity: {e}"),
            Self::SafetyStop { ahead } => {
                write!(
                    f,
                    "safety stop: obstacle {} m ahead, a new plan asked for",
                    crate::present::fixed(*ahead, 2)
                )
            }
        }
    }
}

/// The clearance check's state while the way ahead is blocked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Blocked {
    turned: bool,
    notified_ns: Option<u64>,
}

/// The DriveControl RT-component.
#[derive(Debug, Clone)]
pub struct DriveControl {
    name: String,
    config: Configuration<DriveControlParams>,
    /// `InControlPoints` (in): LocalPathPlanning's control points (empty: stop).
    pub in_control_points: InPort<ControlPoints>,
    /// `InCurrentPosition` (in): the robot pose from Localization.
    pub in_current_position: InPort<TimedPosition>,
    /// `TargetVelocity` (out): (V, ω) for MotorControl.
    pub target_velocity: OutPort<TimedVelocity>,
    /// `OutDeviating` (out): distance from the robot to the polyline \[m\], for
    /// LocalPathPlanning's `InDeviating`.
    pub out_deviating: OutPort<TimedDouble>,
    /// `SafetyStop` (out): the free travel left \[m\] when the clearance check stopped the
    /// robot (the system asks LocalPathPlanning for a new plan).
    pub safety_stop: OutPort<TimedDouble>,
    map: Option<GridMap>,
    body_radius: f64,
    /// The way ahead is blocked: whether the robot has turned towards the path since, and
    /// when the last notice went out \[ns\].
    blocked: Option<Blocked>,
    /// The speed limit of the clearance check this tick \[m/s\], if it limited.
    limited: Option<f64>,
    pursuit: PurePursuit,
    pose: Option<(Pose, u64)>,
    pose_fault: Option<MotionError>,
    status: DriveStatus,
    last_error: Option<MotionError>,
    deviation: Option<f64>,
}

impl Default for DriveControl {
    fn default() -> Self {
        Self::new("DriveControl0")
    }
}

impl DriveControl {
    /// A DriveControl named `name`, every parameter at its default.
    pub fn new(name: &str) -> Self {
        Self {
            name: name.to_owned(),
            config: Configuration::new(),
            in_control_points: InPort::new("InControlPoints"),
            in_current_position: InPort::new("InCurrentPosition"),
            target_velocity: OutPort::new("TargetVelocity"),
            out_deviating: OutPort::new("OutDeviating"),
            safety_stop: OutPort::new("SafetyStop"),
            map: None,
            body_radius: 0.0,
            blocked: None,
            limited: None,
            pursuit: PurePursuit::new(),
            pose: None,
            pose_fault: None,
            status: DriveStatus::Inactive,
            last_error: None,
            deviation: None,
        }
    }

    /// The configuration.
    pub fn config(&self) -> &Configuration<DriveControlParams> {
        &self.config
    }

    /// The configuration, to change parameters.
    pub fn config_mut(&mut self) -> &mut Configuration<DriveControlParams> {
        &mut self.config
    }

    /// What the component is doing.
    pub fn status(&self) -> &DriveStatus {
        &self.status
    }

    /// Whether the robot is at the goal with the goal heading.
    pub fn is_arrived(&self) -> bool {
        self.status == DriveStatus::Driving(DrivePhase::Arrived)
    }

    /// The most recent input problem.
    pub fn last_error(&self) -> Option<&MotionError> {
        self.last_error.as_ref()
    }

    /// The last deviation sent \[m\].
    pub fn deviation(&self) -> Option<f64> {
        self.deviation
    }

    /// The path follower (path, phase, last command).
    pub fn pursuit(&self) -> &PurePursuit {
        &self.pursuit
    }

    /// `SetMap`: the map the clearance check uses.
    pub fn set_map(&mut self, map: GridMap) {
        self.map = Some(map);
    }

    /// `MapUpdate` on the held map (spec §2, atomic). Returns the cells changed.
    pub fn map_update(&mut self, update: &MapUpdate) -> crate::Result<usize> {
        let map = self
            .map
            .as_mut()
            .ok_or(MotionError::NoMap { what: "MapUpdate" })?;
        Ok(map.map_update(update)?)
    }

    /// The robot's body radius (MotorControl's `radiusOfBodyArea`, 002 §4.2), which the
    /// clearance check keeps off obstacles. Refused unless finite and ≥ 0.
    pub fn set_body_radius(&mut self, radius: f64) -> Result<(), MotionError> {
        if !(radius.is_finite() && radius >= 0.0) {
            return Err(MotionError::BadParameter {
                name: "radiusOfBodyArea".to_owned(),
                value: radius,
                reason: "must be finite and ≥ 0",
            });
        }
        self.body_radius = radius;
        Ok(())
    }

    /// The speed the clearance check allowed this tick \[m/s\], if it limited the command.
    pub fn speed_limit(&self) -> Option<f64> {
        self.limited
    }

    /// The clearance check (module documentation): limits `(v, ω)` so the robot can stop
    /// short of any contact; turns on the spot or stops where the way is blocked.
    fn check_clearance(&mut self, tick: &Tick, pose: Pose, v: f64, w: f64) -> (f64, f64) {
        self.limited = None;
        let Some(map) = self.map.as_ref() else {
            return (v, w);
        };
        if v == 0.0 {
            return (v, w);
        }
        let params = self.config.params();
        let reach = params.max_velocity * params.max_velocity / params.max_acceleration + 0.05;
        let free = free_travel(
            map,
            pose,
            v.signum(),
            w / v,
            self.body_radius,
            params.safety_margin,
            reach,
        );
        // Braking at half the acceleration limit, as the path follower does towards stops.
        let allowed = f64::sqrt(params.max_acceleration * free);
        if v.abs() <= allowed {
            self.blocked = None;
            return (v, w);
        }
        self.limited = Some(allowed);
        if free > BLOCKED {
            self.blocked = None;
            let k = allowed / v.abs();
            self.pursuit.limit_command(v * k, w * k);
            return (v * k, w * k);
        }
        // Blocked: turn towards the path first; if that does not free the way, stop and ask
        // for a plan (again every second while it lasts).
        let now = tick.time_ns;
        let blocked = self.blocked.get_or_insert(Blocked {
            turned: false,
            notified_ns: None,
        });
        if !blocked.turned {
            blocked.turned = true;
            self.pursuit.turn_in_place();
        } else if blocked
            .notified_ns
            .is_none_or(|at| now.saturating_sub(at) >= SAFETY_RETRY_NS)
        {
            blocked.notified_ns = Some(now);
            self.safety_stop.write(TimedDouble {
                tm: tick.tm(),
                data: free,
            });
        }
        self.status = DriveStatus::SafetyStop { ahead: free };
        self.pursuit.limit_command(0.0, 0.0);
        (0.0, 0.0)
    }

    fn send(&mut self, tick: &Tick, v: f64, w: f64) {
        self.target_velocity.write(TimedVelocity {
            tm: tick.tm(),
            id: Vec::new(),
            vx: v,
            vy: 0.0,
            w,
            error: Vec::new(),
        });
    }

    fn stop_with(&mut self, tick: &Tick, status: DriveStatus) {
        self.pursuit.reset_command();
        self.status = status;
        self.send(tick, 0.0, 0.0);
    }
}

/// An `InCurrentPosition` sample checked: a valid timestamp ([`crate::rtc::Time::checked`],
/// spec §4 Decision 0.2) and finite numbers.
fn check_position(msg: &TimedPosition) -> Result<Pose, MotionError> {
    const PORT: &str = "InCurrentPosition";
    msg.tm.checked(PORT)?;
    match [("x", msg.x), ("y", msg.y), ("theta", msg.theta)]
        .into_iter()
        .find(|(_, v)| !v.is_finite())
    {
        Some((field, value)) => Err(MotionError::NonFinite {
            port: PORT,
            field: field.to_owned(),
            value,
        }),
        None => Ok(Pose::new(msg.x, msg.y, msg.theta)),
    }
}

impl Component for DriveControl {
    component_basics!(name: name, config: config);

    component_ports!(in: [in_control_points, in_current_position], out: [target_velocity, out_deviating, safety_stop]);

    /// Starts from standstill with the path it holds (a path that came on `InControlPoints`
    /// is the component's data: a Reset and an Activate resume it; a newer one waiting on the
    /// port replaces it at the first tick).
    fn on_activated(&mut self, _tick: &Tick) -> ReturnCode {
        self.pursuit.reset_command();
        self.blocked = None;
        self.limited = None;
        self.pose = None;
        self.pose_fault = None;
        self.last_error = None;
        self.deviation = None;
        self.status = DriveStatus::WaitingForPose;
        Ok(())
    }

    /// Sends zero velocity on the way out.
    fn on_deactivated(&mut self, tick: &Tick) -> ReturnCode {
        self.stop_with(tick, DriveStatus::Inactive);
        Ok(())
    }

    fn on_execute(&mut self, tick: &Tick) -> ReturnCode {
        let now = tick.time_ns;
        if self.in_control_points.is_new()
            && let Some(cp) = self.in_control_points.read()
        {
            // A sample with a bad timestamp is refused whole (the held path stays).
            let accepted = cp
                .tm
                .checked("InControlPoints")
                .map_err(MotionError::from)
                .and_then(|_| self.pursuit.set_path(&cp));
            match accepted {
                // A new path: the clearance check starts afresh.
                Ok(()) => self.blocked = None,
                Err(e) => self.last_error = Some(e),
            }
        }
        if self.in_current_position.is_new()
            && let Some(msg) = self.in_current_position.read()
        {
            match check_position(&msg) {
                Err(e) => {
                    self.last_error = Some(e.clone());
                    self.pose_fault = Some(e);
                }
                Ok(pose) => {
                    self.pose = Some((pose, now));
                    self.pose_fault = None;
                }
            }
        }
        if let Some(e) = self.pose_fault.clone() {
            self.stop_with(tick, DriveStatus::SafeStop(e));
            return Ok(());
        }
        let Some((pose, arrived)) = self.pose else {
            self.stop_with(tick, DriveStatus::WaitingForPose);
            return Ok(());
        };
        let age = now.saturating_sub(arrived);
        if age >= POSE_TIMEOUT_NS {
            let e = MotionError::Stale {
                port: "InCurrentPosition",
                age_s: age as f64 * 1e-9,
                limit_s: POSE_TIMEOUT_NS as f64 * 1e-9,
            };
            if !matches!(
                self.status,
                DriveStatus::SafeStop(MotionError::Stale { .. })
            ) {
                self.last_error = Some(e.clone());
            }
            self.stop_with(tick, DriveStatus::SafeStop(e));
            return Ok(());
        }
        let params = self.config.params().pursuit();
        match self.pursuit.update(pose, tick.period(), &params) {
            Ok(cmd) => {
                self.status = DriveStatus::Driving(cmd.phase);
                self.deviation = cmd.deviation;
                if let Some(d) = cmd.deviation {
                    self.out_deviating.write(TimedDouble {
                        tm: tick.tm(),
                        data: d,
                    });
                }
                let (v, w) = self.check_clearance(tick, pose, cmd.v, cmd.w);
                self.send(tick, v, w);
            }
            Err(e) => {
                self.last_error = Some(e.clone());
                self.stop_with(tick, DriveStatus::SafeStop(e));
            }
        }
        Ok(())
    }
}
