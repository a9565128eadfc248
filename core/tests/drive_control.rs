//! DriveControl (spec §5) alone, and closed loop with MotorControl, the physics and
//! Localization: DriveControl at 50 Hz, the rest at 1 kHz, in one execution context.

use core::f64::consts::PI;

use rtnav::components::{
    DriveControl, DriveControlParams, DriveStatus, Localization, MotorControl, PhysicsSim,
};
use rtnav::errors::MotionError;
use rtnav::interfaces::{ControlPoints, Direction, Pose};
use rtnav::motion::{DrivePhase, ModelFrame, PhysicsParams, Polyline, angle_diff};
use rtnav::rtc::{
    Component, ComponentId, ConfigAccess, ExecutionContext, InPort, OutPort, ParameterSet, Tick,
    Time, TimedDouble, TimedPosition, TimedVelocity,
};

// ------------------------------------------------------------ the deviation

/// The L of the closed-loop runs: 2 m along +x, then 1.5 m along +y.
const L: [(f64, f64); 3] = [(0.5, 0.5), (2.5, 0.5), (2.5, 2.0)];

#[test]
fn deviation_is_the_point_to_polyline_distance() {
    let line = Polyline::new(&L).unwrap();
    assert_eq!(line.length(), 3.5);
    // (point, distance by hand)
    let cases = [
        ((1.0, 0.8), 0.3),                     // above the first segment
        ((1.0, 0.5), 0.0),                     // on it
        ((3.0, 1.2), 0.5),                     // right of the second
        ((2.4, 0.6), 0.1),                     // inside the corner: 0.1 to both
        ((3.5, 3.0), (1.0f64 + 1.0).sqrt()),   // beyond the goal: to the end point
        ((-0.5, -0.5), (1.0f64 + 1.0).sqrt()), // before the start
        ((2.7, 0.3), (0.08f64).sqrt()),        // outside the corner: to the corner point
    ];
    for (p, want) in cases {
        let got = line.distance_to(p);
        assert!((got - want).abs() < 1e-12, "{p:?}: {got} vs {want}");
    }
    let single = Polyline::new(&[(1.0, 1.0), (1.0, 1.0)]).unwrap();
    assert_eq!(single.points().len(), 1, "repeated points are dropped");
    assert_eq!(single.distance_to((4.0, 5.0)), 5.0);
    assert!(Polyline::new(&[]).is_err());
    assert!(matches!(
        Polyline::new(&[(0.0, 0.0), (f64::NAN, 1.0)]),
        Err(MotionError::NonFinite { .. })
    ));

    // The component sends the same on OutDeviating.
    let mut b = Bench::new();
    b.path(&L, Direction::Forward, 0.0);
    for (k, (p, want)) in cases.into_iter().enumerate() {
        b.pose(k as u64, Pose::new(p.0, p.1, 0.0));
        b.exec(k as u64);
        let d = b.dev.read().unwrap();
        assert!((d.data - want).abs() < 1e-12, "{p:?}: {} vs {want}", d.data);
        assert_eq!(d.tm, Time::from_nanos(k as u64 * 20 * MS));
    }
}

// ------------------------------------------------------------ DriveControl alone

const MS: u64 = 1_000_000;

fn tick(k: u64) -> Tick {
    Tick {
        time_ns: k * 20 * MS,
        period_ns: 20 * MS,
        index: k * 20,
    }
}

struct Bench {
    d: DriveControl,
    cp: OutPort<ControlPoints>,
    pos: OutPort<TimedPosition>,
    vel: InPort<TimedVelocity>,
    dev: InPort<TimedDouble>,
}

impl Bench {
    fn new() -> Self {
        let mut d = DriveControl::default();
        let mut cp = OutPort::new("LocalPathPlanning.DriveCons");
        let mut pos = OutPort::new("Localization.OutCurrentPosition");
        cp.connect(&d.in_control_points);
        pos.connect(&d.in_current_position);
        let vel = InPort::new("MotorControl.TargetVelocity");
        let dev = InPort::new("LocalPathPlanning.InDeviating");
        d.target_velocity.connect(&vel);
        d.out_deviating.connect(&dev);
        d.on_activated(&tick(0)).unwrap();
        Self {
            d,
            cp,
            pos,
            vel,
            dev,
        }
    }
    fn path(&mut self, pts: &[(f64, f64)], direction: Direction, goal_theta: f64) {
        self.cp.write(ControlPoints {
            tm: Time::default(),
            points: pts.to_vec(),
            direction,
            goal_theta,
        });
    }
    fn pose(&mut self, k: u64, p: Pose) {
        self.pos.write(TimedPosition {
            tm: Time::from_nanos(k * 20 * MS),
            x: p.x,
            y: p.y,
            theta: p.theta,
            ..TimedPosition::default()
        });
    }
    fn exec(&mut self, k: u64) -> (f64, f64) {
        self.d.on_execute(&tick(k)).unwrap();
        let v = self.vel.read().expect("a velocity every tick");
        assert_eq!(v.tm, Time::from_nanos(k * 20 * MS));
        (v.vx, v.w)
    }
}

#[test]
fn parameters_have_units_ranges_and_always_reflection() {
    let specs = DriveControlParams::SPECS;
    let names: Vec<_> = specs.iter().map(|s| (s.name, s.unit, s.default)).collect();
    assert_eq!(
        names,
        vec![
            ("MaxVelocity", "m/s", 0.5),
            ("MaxAcceleration", "m/s^2", 0.5),
            ("MaxAngularVelocity", "rad/s", 1.0),
            ("MaxAngularAcceleration", "rad/s^2", 2.0),
            ("LookAheadDistance", "m", 0.3),
            ("TurnInPlaceAngle", "rad", PI / 4.0),
            ("GoalTolerance", "m", 0.01),
            ("GoalAngleTolerance", "rad", 0.01),
            ("MinVelocity", "m/s", 0.03),
            ("HeadingGain", "1/s", 2.0),
            ("SafetyMargin", "m", 0.01),
        ]
    );
    assert!(
        specs
            .iter()
            .all(|s| s.reflection == rtnav::rtc::Reflection::Always)
    );
    let mut d = DriveControl::default();
    let cfg = d.configuration().unwrap();
    assert!(cfg.set("MaxVelocity", -0.1).is_err());
    assert!(cfg.set("MaxVelocity", 3.0).is_err());
    assert!(cfg.set("LookAheadDistance", 0.0).is_err());
    assert!(cfg.set("MaxVelocity", 0.8).is_ok());
}

#[test]
fn no_pose_bad_pose_stale_pose_and_empty_points_stop_the_robot() {
    let mut b = Bench::new();
    b.path(&L, Direction::Forward, 0.0);
    assert_eq!(b.exec(0), (0.0, 0.0));
    assert_eq!(b.d.status(), &DriveStatus::WaitingForPose);
    // Drive a little.
    for k in 1..10 {
        b.pose(k, Pose::new(0.5, 0.5, 0.0));
        let (v, _) = b.exec(k);
        assert!(
            v > 0.0 && v <= 0.01 * k as f64 + 1e-12,
            "accelerating within the limit: {v}"
        );
    }
    b.pose(10, Pose::new(0.5, f64::NAN, 0.0));
    assert_eq!(b.exec(10), (0.0, 0.0));
    assert!(matches!(
        b.d.status(),
        DriveStatus::SafeStop(MotionError::NonFinite {
            port: "InCurrentPosition",
            ..
        })
    ));
    b.pose(11, Pose::new(0.5, 0.5, 0.0));
    assert!(b.exec(11).0 > 0.0);
    // 0.5 s (25 ticks) without a new pose.
    for k in 12..36 {
        assert!(b.exec(k).0 > 0.0, "{k}");
    }
    assert_eq!(b.exec(36), (0.0, 0.0));
    assert!(matches!(
        b.d.status(),
        DriveStatus::SafeStop(MotionError::Stale { .. })
    ));
    assert!(
        b.d.status()
            .to_string()
            .starts_with("safe stop, zero velocity")
    );
    // Empty control points: stop (braking within the acceleration limit).
    b.pose(37, Pose::new(0.5, 0.5, 0.0));
    let (v0, _) = b.exec(37);
    assert!(v0 > 0.0);
    b.path(&[], Direction::Forward, 0.0);
    b.pose(38, Pose::new(0.5, 0.5, 0.0));
    let (v1, w1) = b.exec(38);
    assert!((v1 - (v0 - 0.01)).abs() < 1e-12 && w1 == 0.0, "{v0} → {v1}");
    assert_eq!(b.d.status(), &DriveStatus::Driving(DrivePhase::Idle));
    assert!(!b.dev.is_new() || b.dev.read().is_some());
    // Bad control points are refused and the held path stays.
    b.path(&[(0.0, 0.0), (f64::INFINITY, 0.0)], Direction::Forward, 0.0);
    b.exec(39);
    assert!(matches!(
        b.d.last_error(),
        Some(MotionError::NonFinite {
            port: "InControlPoints",
            ..
        })
    ));
}

#[test]
fn a_large_heading_error_turns_on_the_spot_first() {
    let mut b = Bench::new();
    b.path(&L, Direction::Forward, 0.0);
    b.pose(0, Pose::new(0.5, 0.5, PI / 2.0));
    let (v, w) = b.exec(0);
    assert_eq!(v, 0.0);
    assert!(
        w < 0.0 && (w + 0.04).abs() < 1e-12,
        "turning right within the limit: {w}"
    );
    assert_eq!(b.d.status(), &DriveStatus::Driving(DrivePhase::TurnInPlace));
    // Backward on the same path: the rear must face +x, so turn left.
    let mut b = Bench::new();
    b.path(&L, Direction::Backward, 0.0);
    b.pose(0, Pose::new(0.5, 0.5, PI / 2.0));
    let (v, w) = b.exec(0);
    assert_eq!(v, 0.0);
    assert!(w > 0.0);
    // Already facing backward along the path: drive (backward).
    let mut b = Bench::new();
    b.path(&L, Direction::Backward, 0.0);
    b.pose(0, Pose::new(0.5, 0.5, PI));
    let (v, _) = b.exec(0);
    assert!(v < 0.0 && (v + 0.01).abs() < 1e-12, "{v}");
}

// ------------------------------------------------------------ closed loop

/// PhysicsSim → MotorControl → Localization → DriveControl → MotorControl, wired as spec §0,
/// the physics in RH0's model frame.
struct Rig {
    ec: ExecutionContext,
    physics: ComponentId,
    loc: ComponentId,
    drive: ComponentId,
    cp: OutPort<ControlPoints>,
}

impl Rig {
    fn new(start: Pose, odometry: bool) -> Self {
        let params = PhysicsParams::default().with_model_frame(ModelFrame::RH0);
        let mut physics = PhysicsSim::new("PhysicsSim0", params).unwrap();
        physics.set_pose(start).unwrap();
        let mut motor = MotorControl::default();
        motor
            .config_mut()
            .set("SimulatedOffsetY", ModelFrame::RH0.offset_y)
            .unwrap();
        motor
            .config_mut()
            .set("SimulatedOffsetAngle", ModelFrame::RH0.offset_angle)
            .unwrap();
        let mut loc = Localization::default();
        loc.set_start_pose(start).unwrap();
        loc.config_mut()
            .set("LocalizationMode", if odometry { 1.0 } else { 0.0 })
            .unwrap();
        let mut drive = DriveControl::default();
        physics.angle.connect(&motor.in_current_wheel_angle);
        physics.position.connect(&motor.in_simulated_position);
        motor.torque.connect(&physics.torque);
        motor
            .out_current_wheel_angle
            .connect(&loc.in_current_wheel_angle);
        motor
            .out_simulated_position_to_localization
            .connect(&loc.in_simulated_position);
        loc.out_current_position.connect(&drive.in_current_position);
        drive.target_velocity.connect(&motor.target_velocity);
        let mut cp = OutPort::new("LocalPathPlanning.DriveCons");
        cp.connect(&drive.in_control_points);
        let mut ec = ExecutionContext::new(1000.0).unwrap();
        let physics = ec.attach(Box::new(physics), 1000.0).unwrap();
        let motor = ec.attach(Box::new(motor), 1000.0).unwrap();
        let loc = ec.attach(Box::new(loc), 1000.0).unwrap();
        let drive = ec.attach(Box::new(drive), 50.0).unwrap();
        ec.start().unwrap();
        for id in [physics, motor, loc, drive] {
            ec.activate(id).unwrap();
        }
        Self {
            ec,
            physics,
            loc,
            drive,
            cp,
        }
    }

    fn true_pose(&self) -> Pose {
        self.ec
            .component::<PhysicsSim>(self.physics)
            .unwrap()
            .physics()
            .pose()
    }
    fn drive(&self) -> &DriveControl {
        self.ec.component::<DriveControl>(self.drive).unwrap()
    }
    fn loc(&self) -> &Localization {
        self.ec.component::<Localization>(self.loc).unwrap()
    }
}

/// What a run measured.
#[derive(Debug)]
struct Run {
    seconds: f64,
    final_pose: Pose,
    position_error: f64,
    heading_error_deg: f64,
    max_deviation: f64,
    odometry_error: f64,
    distance: f64,
    max_speed: f64,
    phases: Vec<DrivePhase>,
}

fn run_l(start: Pose, direction: Direction, goal_theta: f64, odometry: bool) -> Run {
    let mut rig = Rig::new(start, odometry);
    let line = Polyline::new(&L).unwrap();
    rig.cp.write(ControlPoints {
        tm: Time::default(),
        points: L.to_vec(),
        direction,
        goal_theta,
    });
    let params = DriveControlParams::default();
    let (mut max_dev, mut max_speed) = (0.0f64, 0.0f64);
    let mut phases = vec![DrivePhase::Idle];
    let mut last_cmd = (0.0, 0.0);
    let mut ms = 0u64;
    while ms < 60_000 && !rig.drive().is_arrived() {
        rig.ec.tick();
        ms += 1;
        let p = rig.true_pose();
        max_dev = max_dev.max(line.distance_to((p.x, p.y)));
        if let DriveStatus::Driving(ph) = *rig.drive().status()
            && phases.last() != Some(&ph)
        {
            phases.push(ph);
        }
        let cmd = rig.drive().pursuit().last_command();
        max_speed = max_speed.max(cmd.0.abs());
        // Limits, every 20 ms command.
        assert!(cmd.0.abs() <= params.max_velocity + 1e-12);
        assert!(cmd.1.abs() <= params.max_angular_velocity + 1e-12);
        assert!((cmd.0 - last_cmd.0).abs() <= params.max_acceleration * 0.02 + 1e-12);
        assert!((cmd.1 - last_cmd.1).abs() <= params.max_angular_acceleration * 0.02 + 1e-12);
        last_cmd = cmd;
    }
    // Let it settle for a second after arrival.
    rig.ec.run_ticks(1000);
    let p = rig.true_pose();
    let goal = L[2];
    let odo = rig.loc().odometry();
    let o = odo.pose();
    Run {
        seconds: ms as f64 * 1e-3,
        final_pose: p,
        position_error: ((p.x - goal.0).powi(2) + (p.y - goal.1).powi(2)).sqrt(),
        heading_error_deg: angle_diff(p.theta, goal_theta).abs() * 180.0 / PI,
        max_deviation: max_dev,
        odometry_error: ((o.x - p.x).powi(2) + (o.y - p.y).powi(2)).sqrt(),
        distance: odo.distance(),
        max_speed,
        phases,
    }
}

fn check(run: &Run, label: &str) {
    eprintln!("{label}: {run:?}");
    assert!(run.final_pose.is_finite());
    assert!(run.seconds < 60.0, "{label}: arrived");
    assert!(
        run.position_error <= 0.05,
        "{label}: position error {}",
        run.position_error
    );
    assert!(
        run.heading_error_deg <= 5.0,
        "{label}: heading error {}°",
        run.heading_error_deg
    );
    assert!(
        run.max_deviation <= 0.2,
        "{label}: deviation {}",
        run.max_deviation
    );
    // The L is 3.5 m; each stop is reached within GoalTolerance (0.01 m).
    assert!(
        run.distance > 3.45,
        "{label}: it drove the L: {} m",
        run.distance
    );
    assert!(
        run.odometry_error <= 0.01 * run.distance,
        "{label}: odometry {} off after {} m",
        run.odometry_error,
        run.distance
    );
}

#[test]
fn drives_an_l_forward_to_its_goal_and_heading() {
    // Start facing +y (90° off the first segment), end facing −x (90° off the last).
    let run = run_l(Pose::new(0.5, 0.5, PI / 2.0), Direction::Forward, PI, false);
    check(&run, "forward L (simulated pose)");
    use DrivePhase::*;
    assert_eq!(
        run.phases,
        vec![
            Idle,
            TurnInPlace,
            Following,
            TurnInPlace,
            Following,
            FinalTurn,
            Arrived
        ]
    );
    assert!((run.max_speed - 0.5).abs() < 1e-12, "reaches MaxVelocity");
}

#[test]
fn drives_the_same_l_backward_on_odometry() {
    // Rear first: start facing +y, so the rear must turn to face +x; the last segment runs
    // +y rear first (heading −π/2); end facing +x.
    let run = run_l(
        Pose::new(0.5, 0.5, PI / 2.0),
        Direction::Backward,
        0.0,
        true,
    );
    check(&run, "backward L (odometry)");
    use DrivePhase::*;
    assert_eq!(
        run.phases,
        vec![
            Idle,
            TurnInPlace,
            Following,
            TurnInPlace,
            Following,
            FinalTurn,
            Arrived
        ]
    );
}

// ------------------------------------------------------------ the clearance check

#[test]
fn the_clearance_check_stops_the_body_short_of_an_obstacle_on_the_path_and_says_so() {
    use rtnav::map::GridMap;
    // 60 × 20 cells of 0.1 m; a wall at x = 3.0 .. 3.1 m across the corridor.
    let mut data = vec![0i16; 60 * 20];
    for y in 0..20 {
        data[30 + y * 60] = 1;
    }
    let map = GridMap::from_map_data(&data, 60, 20, 0.1).unwrap();
    let mut b = Bench::new();
    b.d.set_map(map);
    b.d.set_body_radius(0.45).unwrap();
    assert!(b.d.set_body_radius(f64::NAN).is_err());
    let notices = InPort::new("SafetyStop");
    b.d.safety_stop.connect(&notices);
    // A path straight through the wall (as a stale plan would be).
    b.path(&[(0.5, 1.0), (5.5, 1.0)], Direction::Forward, 0.0);
    let mut p = Pose::new(0.5, 1.0, 0.0);
    let mut slowest_near = f64::INFINITY;
    for k in 0..500 {
        b.pose(k, p);
        let (v, w) = b.exec(k);
        // A kinematic robot following the command exactly.
        p = rtnav::motion::arc_step(p, v * 0.02, w * 0.02);
        if p.x > 2.4 {
            slowest_near = slowest_near.min(v.abs());
        }
    }
    let face = 3.0 - 0.45;
    assert!(
        p.x <= face - 0.01 + 1e-9,
        "the body stops short: x = {}",
        p.x
    );
    assert!(p.x > face - 0.05, "but not far short: x = {}", p.x);
    assert!(slowest_near < 0.01);
    assert!(
        matches!(b.d.status(), DriveStatus::SafetyStop { ahead } if *ahead < 0.01),
        "{}",
        b.d.status()
    );
    assert!(
        b.d.status()
            .to_string()
            .starts_with("safety stop: obstacle")
    );
    assert!(notices.read().is_some(), "a new plan was asked for");
    // Without a map, nothing is checked: the command is the path follower's.
    let mut free = Bench::new();
    free.path(&[(0.5, 1.0), (5.5, 1.0)], Direction::Forward, 0.0);
    free.pose(0, Pose::new(2.5, 1.0, 0.0));
    assert!(free.exec(0).0 > 0.0);
}
