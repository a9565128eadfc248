//! The physics (spec §5) alone and in closed loop with MotorControl (spec §4) at 1 kHz with
//! the seed's default gains (P 5, D 2).

use rtnav::components::{MotorControl, MotorStatus, PhysicsSim};
use rtnav::errors::MotionError;
use rtnav::interfaces::Pose;
use rtnav::map::{GridMap, MapUpdate};
use rtnav::motion::{BumpReport, DiffDrive, ModelFrame, Physics, PhysicsParams, STEP_NS, arc_step};
use rtnav::rtc::{
    ComponentId, ConfigAccess, ExecutionContext, InPort, LifecycleState, OutPort, Time,
    TimedVelocity,
};

// ---------------------------------------------------------------- the pure physics

#[test]
fn params_have_documented_defaults_and_refuse_unknown_keys() {
    let p: PhysicsParams = serde_json::from_str("{}").unwrap();
    assert_eq!(p, PhysicsParams::default());
    assert_eq!(
        (
            p.mass,
            p.yaw_inertia,
            p.wheel_inertia,
            p.wheel_radius,
            p.axle_length
        ),
        (20.0, 1.0, 0.005, 0.1, 0.441)
    );
    assert_eq!(
        (p.viscous_friction, p.max_torque, p.body_radius),
        (0.02, 5.0, 0.45)
    );
    assert_eq!(p.robot_name, "rh0");
    let e = serde_json::from_str::<PhysicsParams>(r#"{"mass": 20.0, "masss": 1.0}"#);
    assert!(e.unwrap_err().to_string().contains("unknown field `masss`"));
    let q: PhysicsParams = serde_json::from_str(r#"{"mass": 30.0}"#).unwrap();
    assert_eq!((q.mass, q.yaw_inertia), (30.0, 1.0));
}

#[test]
fn bad_params_are_refused_with_their_name() {
    for (json, name) in [
        (r#"{"mass": 0.0}"#, "mass"),
        (r#"{"yaw_inertia": -1.0}"#, "yaw_inertia"),
        (r#"{"wheel_inertia": -0.1}"#, "wheel_inertia"),
        (r#"{"viscous_friction": -0.1}"#, "viscous_friction"),
        (r#"{"max_torque": -1.0}"#, "max_torque"),
        (r#"{"axle_length": 0.0}"#, "axle_length"),
    ] {
        let p: PhysicsParams = serde_json::from_str(json).unwrap();
        match Physics::new(p) {
            Err(MotionError::BadParameter { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{json}: {other:?}"),
        }
    }
    let p = PhysicsParams {
        mass: f64::NAN,
        ..PhysicsParams::default()
    };
    assert!(matches!(
        Physics::new(p),
        Err(MotionError::BadParameter { .. })
    ));
}

#[test]
fn mass_matrix_is_the_spec_formula() {
    let p = PhysicsParams::default();
    let m = Physics::new(p.clone()).unwrap().mass_matrix();
    let (r, big_r) = (0.1_f64, 0.2205_f64);
    let a = 20.0 * r * r / 4.0 + 1.0 * r * r / (4.0 * big_r * big_r) + 0.005;
    let c = 20.0 * r * r / 4.0 - 1.0 * r * r / (4.0 * big_r * big_r);
    assert!((m[(0, 0)] - a).abs() < 1e-15 && (m[(1, 1)] - a).abs() < 1e-15);
    assert!((m[(0, 1)] - c).abs() < 1e-15 && (m[(1, 0)] - c).abs() < 1e-15);
}

#[test]
fn equal_torques_drive_straight_and_saturate() {
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    for _ in 0..1000 {
        assert_eq!(ph.step([100.0, 100.0]).unwrap(), None);
    }
    let s = *ph.state();
    assert_eq!(s.torque, [5.0, 5.0], "saturated at max_torque");
    assert_eq!(s.time_ns, 1000 * STEP_NS);
    assert_eq!(s.wheel_rate[0], s.wheel_rate[1]);
    assert_eq!((s.pose.y, s.pose.theta), (0.0, 0.0));
    // Straight: (a + c)·ω̇ = τ − bω; one second at 5 N·m from rest.
    let m = 20.0 * 0.01 / 2.0 + 0.005;
    let b = 0.02;
    let exact = 5.0 / b * (1.0 - (-b / m * 1.0_f64).exp());
    assert!(
        (s.wheel_rate[0] - exact).abs() / exact < 1e-3,
        "{} vs {exact}",
        s.wheel_rate[0]
    );
    assert!((s.pose.x - 0.1 * s.wheel_angle[0]).abs() < 1e-12);
}

#[test]
fn pose_follows_the_wheel_angles_as_exact_arcs() {
    // Whatever the torques, the pose is the arc integration of the wheel-angle increments.
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    let drive = DiffDrive::default();
    let mut pose = Pose::default();
    let mut last = [0.0; 2];
    for k in 0..3000 {
        let t = [
            1.0 + (k as f64 * 0.01).sin(),
            2.0 * (k as f64 * 0.003).cos(),
        ];
        ph.step(t).unwrap();
        let a = ph.state().wheel_angle;
        let (ds, dth) = drive.body_increment([a[0] - last[0], a[1] - last[1]]);
        pose = arc_step(pose, ds, dth);
        last = a;
    }
    let p = ph.pose();
    assert!((p.x - pose.x).abs() < 1e-12 && (p.y - pose.y).abs() < 1e-12);
    assert!((p.theta - pose.theta).abs() < 1e-12);
    assert!(p.x.abs() + p.y.abs() > 1.0, "it moved: {p:?}");
}

#[test]
fn non_finite_torque_is_refused_and_changes_nothing() {
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    ph.step([1.0, 1.0]).unwrap();
    let before = ph.clone();
    for t in [
        [f64::NAN, 0.0],
        [0.0, f64::INFINITY],
        [f64::NEG_INFINITY, 1.0],
    ] {
        assert!(matches!(
            ph.step(t),
            Err(MotionError::NonFinite { port: "torque", .. })
        ));
        assert_eq!(ph, before);
    }
}

#[test]
fn model_transform_is_what_motor_control_converts_back() {
    let ph_params = PhysicsParams::default().with_model_frame(ModelFrame::RH0);
    let mut ph = Physics::new(ph_params).unwrap();
    for pose in [
        Pose::new(1.0, 2.0, 0.3),
        Pose::new(-3.0, 0.5, 2.0),
        Pose::new(-1.5, -2.5, -2.5),
        Pose::new(4.0, -1.0, -0.7),
        Pose::new(0.0, 0.0, core::f64::consts::PI),
    ] {
        ph.set_pose(pose).unwrap();
        let t = ph.model_transform();
        let (back, z) = ModelFrame::RH0.axle_pose(&t, "position").unwrap();
        assert_eq!(z, 0.0);
        assert!((back.x - pose.x).abs() < 1e-12, "{pose:?} → {back:?}");
        assert!((back.y - pose.y).abs() < 1e-12, "{pose:?} → {back:?}");
        assert!(
            rtnav::motion::angle_diff(back.theta, pose.theta).abs() < 1e-12,
            "{pose:?} → {back:?}"
        );
        // The model origin is not the axle centre: the conversion is exercised.
        assert!(((t[0] - pose.x).powi(2) + (t[1] - pose.y).powi(2)).sqrt() > 0.04);
    }
}

// ---------------------------------------------------------------- bump detection

/// A 5 m × 3 m room (0.05 m cells) with a wall of obstacle cells at x ≥ 4 m.
fn room_with_wall() -> GridMap {
    let (w, h) = (100usize, 60usize);
    let cells = (0..w * h).map(|i| u8::from(i % w >= 80)).collect();
    GridMap::new(w, h, 0.05, (0.0, 0.0), cells).unwrap()
}

#[test]
fn bump_stops_the_robot_at_a_wall_and_says_who_hit_what_where() {
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    ph.set_map(Some(room_with_wall()));
    ph.set_pose(Pose::new(2.0, 1.5, 0.0)).unwrap();
    let mut report = None;
    for _ in 0..5000 {
        if let Some(r) = ph.step([1.0, 1.0]).unwrap() {
            assert!(report.is_none(), "one report per contact");
            report = Some(r);
        }
    }
    let r = report.expect("a bump");
    assert_eq!(r.who, "rh0");
    assert_eq!(r.cell.0, 80, "the wall's first column");
    assert!((r.contact.0 - 4.0).abs() < 1e-12 && (r.contact.1 - 1.5).abs() < 0.05);
    assert!(r.speed > 0.1, "it hit at speed: {}", r.speed);
    let p = ph.pose();
    assert!(
        p.x <= 4.0 - 0.45 && p.x > 4.0 - 0.45 - 0.01,
        "stopped at the wall: {p:?}"
    );
    assert_eq!(ph.state().wheel_rate, [0.0, 0.0]);
    assert!(ph.state().in_contact);
    assert_eq!(ph.bump_count(), 1);
    assert!(
        r.to_string()
            .starts_with("rh0 bumped into obstacle cell (80, ")
    );
    // Backing away is allowed and ends the contact.
    for _ in 0..500 {
        assert_eq!(ph.step([-1.0, -1.0]).unwrap(), None);
    }
    assert!(ph.pose().x < 4.0 - 0.46 && !ph.state().in_contact);
}

#[test]
fn an_obstacle_that_appears_on_the_body_is_a_bump_and_the_edge_of_the_map_too() {
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    ph.set_map(Some(room_with_wall()));
    ph.set_pose(Pose::new(2.0, 1.5, 0.0)).unwrap();
    assert_eq!(ph.step([0.0, 0.0]).unwrap(), None);
    // MapUpdate puts an obstacle 0.3 m ahead of the centre.
    ph.map_update(&MapUpdate {
        x: vec![46],
        y: vec![30],
        value: vec![1],
        num: 1,
        tm: Time::from_nanos(5),
    })
    .unwrap();
    let r = ph.step([0.0, 0.0]).unwrap().expect("bump after map update");
    assert_eq!(r.cell, (46, 30));
    // A bad map update is refused, atomically.
    assert!(
        ph.map_update(&MapUpdate {
            x: vec![1, 2],
            y: vec![1],
            value: vec![1],
            num: 2,
            tm: Time::default()
        })
        .is_err()
    );
    // Leaving the map: outside counts as obstacle.
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    ph.set_map(Some(room_with_wall()));
    ph.set_pose(Pose::new(1.0, 1.5, core::f64::consts::PI))
        .unwrap();
    let mut hit = None;
    for _ in 0..5000 {
        if let Some(r) = ph.step([1.0, 1.0]).unwrap() {
            hit = Some(r);
            break;
        }
    }
    let r = hit.expect("bump at the map edge");
    assert_eq!(r.cell.0, -1);
    assert!(ph.pose().x >= 0.45);
}

#[test]
fn a_body_of_millions_of_tiny_cells_is_checked_against_the_map_only() {
    // 40 × 40 free cells of 0.1 mm (the smallest a map may have): the body (radius 0.45 m)
    // spans 9 000 cells each way,
    // and every cell outside the map is an obstacle. The contact scan looks at the map and
    // one ring around it, not at the 8·10⁷ cells of the body's box.
    let map = GridMap::new(40, 40, 1e-4, (0.0, 0.0), vec![0; 1600]).unwrap();
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    ph.set_map(Some(map.clone()));
    ph.set_pose(Pose::new(0.001, 0.00255, 0.0)).unwrap();
    let r = ph
        .step([0.0, 0.0])
        .unwrap()
        .expect("the map's edge is under the body");
    // The nearest outside cell: the ring's column west of the map, in the centre's row.
    assert_eq!(r.cell, (-1, 25));
    assert!((r.contact.0 - 0.0).abs() < 1e-15 && (r.contact.1 - 0.00255).abs() < 1e-15);
    // Placed far outside the map: its own cell (an obstacle) is touched.
    let mut ph = Physics::new(PhysicsParams::default()).unwrap();
    ph.set_map(Some(map));
    ph.set_pose(Pose::new(5.0, 5.0, 0.0)).unwrap();
    let r = ph
        .step([0.0, 0.0])
        .unwrap()
        .expect("outside the map is obstacle");
    assert!(r.cell.0 > 40_000 && r.cell.1 > 40_000, "{r:?}");
    assert_eq!(r.contact, (5.0, 5.0));
}

// ---------------------------------------------------------------- closed loop

/// MotorControl + PhysicsSim in one 1 kHz execution context, wired as `bridge.sh` wires
/// MotorControl to OpenHRP3, with the RH0 model frame on both sides.
struct Rig {
    ec: ExecutionContext,
    physics: ComponentId,
    motor: ComponentId,
    cmd: OutPort<TimedVelocity>,
    bump: InPort<BumpReport>,
}

impl Rig {
    fn new(map: Option<GridMap>, start: Pose) -> Self {
        let params = PhysicsParams::default().with_model_frame(ModelFrame::RH0);
        let mut physics = PhysicsSim::new("PhysicsSim0", params).unwrap();
        physics.set_map(map);
        physics.set_pose(start).unwrap();
        let mut motor = MotorControl::new("MotorControl0");
        motor
            .config_mut()
            .set("SimulatedOffsetY", ModelFrame::RH0.offset_y)
            .unwrap();
        motor
            .config_mut()
            .set("SimulatedOffsetAngle", ModelFrame::RH0.offset_angle)
            .unwrap();
        physics.angle.connect(&motor.in_current_wheel_angle);
        physics.position.connect(&motor.in_simulated_position);
        motor.torque.connect(&physics.torque);
        let mut cmd = OutPort::new("TargetVelocity");
        cmd.connect(&motor.target_velocity);
        let bump = InPort::new("BumpDetection");
        physics.bump.connect(&bump);
        let mut ec = ExecutionContext::new(1000.0).unwrap();
        let physics = ec.attach(Box::new(physics), 1000.0).unwrap();
        let motor = ec.attach(Box::new(motor), 1000.0).unwrap();
        ec.start().unwrap();
        assert_eq!(ec.activate(physics).unwrap(), LifecycleState::Active);
        assert_eq!(ec.activate(motor).unwrap(), LifecycleState::Active);
        Self {
            ec,
            physics,
            motor,
            cmd,
            bump,
        }
    }

    fn command(&mut self, v: f64, w: f64) {
        let tm = Time::from_nanos(self.ec.time_ns());
        self.cmd.write(TimedVelocity {
            tm,
            vx: v,
            w,
            ..TimedVelocity::default()
        });
    }

    fn sim(&self) -> &PhysicsSim {
        self.ec.component::<PhysicsSim>(self.physics).unwrap()
    }

    fn motor(&self) -> &MotorControl {
        self.ec.component::<MotorControl>(self.motor).unwrap()
    }

    /// Runs `ms` ticks, sending the command every 20 ms (DriveControl's 50 Hz).
    fn drive(&mut self, v: f64, w: f64, ms: u64, mut each: impl FnMut(&Self)) {
        for _ in 0..ms {
            if self.ec.tick_count().is_multiple_of(20) {
                self.command(v, w);
            }
            self.ec.tick();
            each(self);
        }
    }
}

#[test]
fn step_of_half_a_metre_per_second_settles_within_2_percent_in_under_a_second() {
    let mut rig = Rig::new(None, Pose::default());
    let mut speeds = Vec::new();
    rig.drive(0.5, 0.0, 3000, |r| {
        speeds.push(r.sim().physics().body_velocity().0)
    });
    // Last time the speed was outside the ±2 % band around the command.
    let outside = speeds
        .iter()
        .rposition(|v| (v - 0.5).abs() > 0.02 * 0.5)
        .map_or(0, |i| i + 1);
    let settle_s = outside as f64 * 1e-3;
    let steady = *speeds.last().unwrap();
    let peak = speeds.iter().cloned().fold(f64::MIN, f64::max);
    eprintln!(
        "step 0.5 m/s: settles within 2 % at {settle_s:.3} s, steady {steady:.5} m/s, peak {peak:.5} m/s"
    );
    assert!(settle_s < 1.0, "settles at {settle_s} s");
    assert!((steady - 0.5).abs() < 0.01, "steady {steady}");
    assert!(peak <= 0.5 * 1.02, "no overshoot beyond 2 %: {peak}");
    assert_eq!(rig.motor().status(), &MotorStatus::Running);
    let p = rig.sim().physics().pose();
    assert!(
        p.y.abs() < 1e-12 && p.theta.abs() < 1e-12,
        "straight: {p:?}"
    );
}

/// Least-squares circle through points (Kåsa): centre and radius.
fn fit_circle(pts: &[(f64, f64)]) -> ((f64, f64), f64) {
    use nalgebra::{Matrix3, Vector3};
    let mut a = Matrix3::zeros();
    let mut b = Vector3::zeros();
    for &(x, y) in pts {
        let row = Vector3::new(x, y, 1.0);
        a += row * row.transpose();
        b += row * (x * x + y * y);
    }
    let s = a.lu().solve(&b).unwrap();
    let (cx, cy) = (s[0] / 2.0, s[1] / 2.0);
    ((cx, cy), (s[2] + cx * cx + cy * cy).sqrt())
}

#[test]
fn half_metre_per_second_at_half_a_radian_per_second_drives_a_unit_circle() {
    let mut rig = Rig::new(None, Pose::default());
    let mut pts = Vec::new();
    let mut tick = 0u64;
    rig.drive(0.5, 0.5, 10_000, |r| {
        tick += 1;
        // After the 0.3 s start-up transient, every 10 ms.
        if tick >= 300 && tick.is_multiple_of(10) {
            let p = r.sim().physics().pose();
            pts.push((p.x, p.y));
        }
    });
    let ((cx, cy), radius) = fit_circle(&pts);
    let spread = pts
        .iter()
        .map(|&(x, y)| (((x - cx).powi(2) + (y - cy).powi(2)).sqrt() - radius).abs())
        .fold(0.0, f64::max);
    let turned = rig.sim().physics().state().wheel_angle;
    eprintln!(
        "circle v 0.5 ω 0.5 over 10 s: radius {radius:.5} m, centre ({cx:.4}, {cy:.4}), \
         max distance from the fitted circle {spread:.2e} m, wheel angles {turned:?}"
    );
    assert!((radius - 1.0).abs() < 0.02, "radius {radius}");
    assert!(spread < 0.005, "it is a circle: {spread}");
    assert!(
        cx.abs() < 0.02 && (cy - 1.0).abs() < 0.02,
        "centre ({cx}, {cy})"
    );
    // More than three-quarters round (0.5 rad/s × 10 s ≈ 5 rad).
    assert!(pts.len() > 900);
}

/// A small deterministic generator (SplitMix64), so the random test is the same everywhere.
struct SplitMix(u64);
impl SplitMix {
    fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }
}

fn random_run(seed: u64) -> (Pose, [f64; 2], f64) {
    let mut rig = Rig::new(None, Pose::default());
    let mut rng = SplitMix(seed);
    let mut max_rate: f64 = 0.0;
    let mut ok = true;
    for _ in 0..120 {
        let (v, w) = (rng.range(-1.0, 1.0), rng.range(-2.0, 2.0));
        rig.drive(v, w, 500, |r| {
            let s = r.sim().physics().state();
            ok &= s.pose.is_finite()
                && s.wheel_rate.iter().all(|x| x.is_finite())
                && r.motor().last_torque().iter().all(|t| t.is_finite());
            max_rate = max_rate
                .max(s.wheel_rate[0].abs())
                .max(s.wheel_rate[1].abs());
        });
    }
    assert!(ok, "every state finite");
    rig.drive(0.0, 0.0, 2000, |_| {});
    let s = *rig.sim().physics().state();
    let (v, w) = rig.sim().physics().body_velocity();
    assert!(
        v.abs() < 1e-3 && w.abs() < 1e-3,
        "it comes to rest: ({v}, {w})"
    );
    assert!(rig.motor().last_error().is_none());
    (s.pose, s.wheel_angle, max_rate)
}

#[test]
fn sixty_seconds_of_random_commands_never_diverge_and_replay_bit_for_bit() {
    let (pose, angles, max_rate) = random_run(0x5EED);
    // |v| ≤ 1 m/s, |ω| ≤ 2 rad/s ask for at most (1 + 0.2205·2)/0.1 = 14.41 rad/s.
    eprintln!("random 60 s: largest wheel rate {max_rate:.3} rad/s, final pose {pose:?}");
    assert!(max_rate < 14.41 * 1.05, "{max_rate}");
    let (pose2, angles2, _) = random_run(0x5EED);
    assert_eq!(
        (pose.x.to_bits(), pose.y.to_bits(), pose.theta.to_bits()),
        (pose2.x.to_bits(), pose2.y.to_bits(), pose2.theta.to_bits())
    );
    assert_eq!(angles.map(f64::to_bits), angles2.map(f64::to_bits));
}

#[test]
fn driving_into_a_wall_stops_the_robot_with_a_bump_report() {
    let mut rig = Rig::new(Some(room_with_wall()), Pose::new(2.0, 1.5, 0.0));
    let mut first = None;
    let mut t = 0u64;
    rig.drive(0.5, 0.0, 6000, |r| {
        t += 1;
        if first.is_none() && r.bump.is_new() {
            first = Some((t, r.bump.read().unwrap()));
        }
    });
    let (when, report) = first.expect("a bump on the `bump` port");
    let when = when as f64 * 1e-3;
    assert_eq!(rig.sim().last_bump(), Some(&report));
    let p = rig.sim().physics().pose();
    eprintln!("bump after {when:.3} s: {report}");
    assert_eq!(report.who, "rh0");
    assert_eq!(report.cell.0, 80);
    assert!(p.x <= 3.55 && p.x > 3.54, "held at the wall: {p:?}");
    assert_eq!(rig.sim().physics().bump_count(), 1);
    // Bump detection calls Stop: the robot stays stopped, the torque goes to zero.
    rig.ec
        .component_mut::<MotorControl>(rig.motor)
        .unwrap()
        .stop();
    rig.drive(0.5, 0.0, 1000, |_| {});
    assert_eq!(rig.motor().status(), &MotorStatus::Stopped);
    assert_eq!(rig.motor().last_torque(), [0.0, 0.0]);
    assert_eq!(rig.sim().physics().body_velocity(), (0.0, 0.0));
}
