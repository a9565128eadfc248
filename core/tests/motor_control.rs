//! MotorControl (seed 002, spec §4): kinematics, target angles, PD torque, services,
//! parameters and their reflection timing, the simulated-pose conversion, and the safe stop.
//!
//! The component is driven through its callbacks with exact simulated time (`Tick`), or in
//! an `ExecutionContext` where the lifecycle matters.

use core::f64::consts::PI;

use rtnav::components::{INPUT_TIMEOUT_NS, MotorControl, MotorControlParams, MotorStatus};
use rtnav::errors::MotionError;
use rtnav::motion::DiffDrive;
use rtnav::rtc::{
    Component, ConfigAccess, ExecutionContext, InPort, LifecycleState, OutPort, ParameterSet,
    Reflection, Tick, Time, TimedDoubleSeq, TimedVelocity,
};

const MS: u64 = 1_000_000;

fn assert_close(got: &[f64], want: &[f64]) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < 1e-12, "{got:?} vs {want:?}");
    }
}

fn tick(ms: u64) -> Tick {
    Tick {
        time_ns: ms * MS,
        period_ns: MS,
        index: ms,
    }
}

/// A MotorControl with every port connected to the test.
struct Bench {
    m: MotorControl,
    vel: OutPort<TimedVelocity>,
    ang: OutPort<TimedDoubleSeq>,
    pos: OutPort<TimedDoubleSeq>,
    torque: InPort<TimedDoubleSeq>,
    wheels_out: InPort<TimedDoubleSeq>,
    gui: InPort<TimedDoubleSeq>,
    loc: InPort<TimedDoubleSeq>,
}

impl Bench {
    fn new(configure: impl FnOnce(&mut MotorControl)) -> Self {
        let mut m = MotorControl::default();
        configure(&mut m);
        let (mut vel, mut ang, mut pos) = (
            OutPort::new("DriveControl.TargetVelocity"),
            OutPort::new("angle"),
            OutPort::new("position"),
        );
        vel.connect(&m.target_velocity);
        ang.connect(&m.in_current_wheel_angle);
        pos.connect(&m.in_simulated_position);
        let torque = InPort::new("torque");
        let wheels_out = InPort::new("Localization.InCurrentWheelAngle");
        let gui = InPort::new("InventGUI");
        let loc = InPort::new("Localization.InSimulatedPosition");
        m.torque.connect(&torque);
        m.out_current_wheel_angle.connect(&wheels_out);
        m.out_simulated_position_to_invent_gui.connect(&gui);
        m.out_simulated_position_to_localization.connect(&loc);
        let mut b = Self {
            m,
            vel,
            ang,
            pos,
            torque,
            wheels_out,
            gui,
            loc,
        };
        b.activate(0);
        b
    }

    /// What the execution context does on activation: apply `on_activation` values, then
    /// `on_activated`.
    fn activate(&mut self, ms: u64) {
        self.m.configuration().unwrap().apply_on_activation();
        self.m.on_activated(&tick(ms)).unwrap();
    }

    fn velocity(&mut self, ms: u64, vx: f64, w: f64) {
        self.vel.write(TimedVelocity {
            tm: Time::from_nanos(ms * MS),
            vx,
            w,
            ..TimedVelocity::default()
        });
    }

    fn angles(&mut self, ms: u64, data: &[f64]) {
        self.ang.write(TimedDoubleSeq {
            tm: Time::from_nanos(ms * MS),
            data: data.to_vec(),
        });
    }

    /// Runs `on_execute` at `ms` and returns the torque sent.
    fn exec(&mut self, ms: u64) -> Vec<f64> {
        self.m.on_execute(&tick(ms)).unwrap();
        assert!(self.torque.is_new(), "torque is sent every tick");
        self.torque.read().unwrap().data
    }
}

// ------------------------------------------------------------ kinematics (002 §5.2.5.4)

/// The seed's formula: ρ = V/ω, ω_L* = (ρ − R)·ω/r_L, ω_R* = (ρ + R)·ω/r_R.
fn seed_formula(d: &DiffDrive, v: f64, w: f64) -> [f64; 2] {
    let rho = v / w;
    let r = d.half_axle();
    [
        (rho - r) * w / d.radius_left(),
        (rho + r) * w / d.radius_right(),
    ]
}

#[test]
fn target_wheel_rates_follow_002_5_2_5_4() {
    let d = DiffDrive::default();
    // (V, ω) → (ω_L*, ω_R*) by hand, R = 0.2205, r = 0.1.
    let cases = [
        ((0.5, 0.5), [3.8975, 6.1025]),
        ((0.3, 0.0), [3.0, 3.0]), // ω = 0: straight, where ρ = V/ω is undefined
        ((-0.2, 0.0), [-2.0, -2.0]),
        ((0.0, 1.0), [-2.205, 2.205]), // turn on the spot
        ((0.0, -0.4), [0.882, -0.882]),
        ((1.0, -2.0), [14.41, 5.59]),
    ];
    for ((v, w), want) in cases {
        let got = d.wheel_rates(v, w);
        for i in 0..2 {
            assert!(
                (got[i] - want[i]).abs() < 1e-12,
                "({v}, {w}): {got:?} vs {want:?}"
            );
        }
        if w != 0.0 {
            let seed = seed_formula(&d, v, w);
            assert!((got[0] - seed[0]).abs() < 1e-12 && (got[1] - seed[1]).abs() < 1e-12);
        }
        // And back.
        let (bv, bw) = d.body_velocity(got);
        assert!((bv - v).abs() < 1e-12 && (bw - w).abs() < 1e-12);
    }
    // Different wheels.
    let d2 = DiffDrive::new(0.1, 0.125, 0.5).unwrap();
    assert_eq!(
        d2.wheel_rates(0.5, 1.0),
        [(0.5 - 0.25) / 0.1, (0.5 + 0.25) / 0.125]
    );
    assert!(DiffDrive::new(0.0, 0.1, 0.4).is_err() && DiffDrive::new(0.1, 0.1, f64::NAN).is_err());
}

#[test]
fn the_component_uses_those_rates_straight_curved_and_on_the_spot() {
    // P = 0, D = 1 and the first wheel sample (rate 0): torque = ω* exactly.
    for (v, w) in [(0.5, 0.5), (0.3, 0.0), (0.0, 1.0), (-0.4, 0.25)] {
        let mut b = Bench::new(|m| m.set_pd_gain(0.0, 0.0, 1.0, 1.0).unwrap());
        b.angles(0, &[0.0, 0.0]);
        b.velocity(0, v, w);
        let t = b.exec(0);
        let want = DiffDrive::default().wheel_rates(v, w);
        assert_eq!(t, want.to_vec(), "({v}, {w})");
        assert_eq!(b.m.target_wheel_rates(), want);
        assert_eq!(b.m.status(), &MotorStatus::Running);
    }
}

#[test]
fn target_angle_is_the_trapezoid_and_rates_come_from_timestamps() {
    // P = 1, D = 0: torque = target angle − angle = (ω* + ω)·Δt/2.
    let mut b = Bench::new(|m| m.set_pd_gain(1.0, 1.0, 0.0, 0.0).unwrap());
    b.angles(0, &[0.0, 0.0]);
    b.velocity(0, 0.3, 0.0); // ω* = 3 rad/s both
    assert_eq!(b.exec(0), vec![0.0, 0.0], "Δt = 0 at the first sample");
    // 10 ms later (the timestamps' difference, not the tick period): rates 1 and 2 rad/s.
    b.angles(10, &[0.01, 0.02]);
    let t = b.exec(1);
    assert_eq!(b.m.wheel_rates(), [1.0, 2.0]);
    let ta = b.m.target_wheel_angles();
    assert!(
        (ta[0] - 0.03).abs() < 1e-15 && (ta[1] - 0.045).abs() < 1e-15,
        "{ta:?}"
    );
    assert!(
        (t[0] - 0.02).abs() < 1e-15 && (t[1] - 0.025).abs() < 1e-15,
        "{t:?}"
    );
}

#[test]
fn pd_torque_restores_the_target() {
    // D only: wheels faster than the target get negative torque, slower positive.
    let mut b = Bench::new(|m| m.set_pd_gain(0.0, 0.0, 2.0, 2.0).unwrap());
    b.velocity(0, 0.3, 0.0); // 3 rad/s
    b.angles(0, &[0.0, 0.0]);
    b.exec(0);
    b.angles(10, &[0.05, 0.01]); // 5 and 1 rad/s
    let t = b.exec(10);
    assert!(
        (t[0] - 2.0 * (3.0 - 5.0)).abs() < 1e-12 && t[0] < 0.0,
        "{t:?}"
    );
    assert!(
        (t[1] - 2.0 * (3.0 - 1.0)).abs() < 1e-12 && t[1] > 0.0,
        "{t:?}"
    );
    // P only: the target angle is ahead when the wheels should turn forward.
    let mut b = Bench::new(|m| m.set_pd_gain(5.0, 5.0, 0.0, 0.0).unwrap());
    b.velocity(0, 0.3, 0.0);
    b.angles(0, &[0.0, 0.0]);
    b.exec(0);
    b.angles(1, &[0.0, 0.0]);
    let t = b.exec(1);
    assert!(t[0] > 0.0 && t[1] > 0.0, "{t:?}");
    b.velocity(1, -0.3, 0.0);
    let t = b.exec(2);
    assert!(t[0] < 0.0 && t[1] < 0.0, "{t:?}");
}

// ------------------------------------------------------------ service Motor

#[test]
fn set_pd_gain_takes_effect_at_the_next_tick_and_refuses_bad_gains() {
    let mut b = Bench::new(|_| {});
    b.velocity(0, 0.3, 0.0);
    b.angles(0, &[0.0, 0.0]);
    // Defaults P 5, D 2; Δt = 0 at the first sample.
    assert_close(&b.exec(0), &[2.0 * 3.0, 2.0 * 3.0]);
    b.m.set_pd_gain(0.0, 0.0, 4.0, 7.0).unwrap();
    assert_close(&b.exec(1), &[4.0 * 3.0, 7.0 * 3.0]);
    let cfg = b.m.config();
    assert_eq!(cfg.effective_value("DGainR").unwrap(), 7.0);
    for bad in [
        (-1.0, 0.0, 1.0, 1.0),
        (0.0, f64::NAN, 1.0, 1.0),
        (0.0, 0.0, f64::INFINITY, 1.0),
    ] {
        assert!(
            b.m.set_pd_gain(bad.0, bad.1, bad.2, bad.3).is_err(),
            "{bad:?}"
        );
    }
    assert_close(&b.exec(2), &[4.0 * 3.0, 7.0 * 3.0]); // nothing changed
}

#[test]
fn start_finish_stop_clear_do_what_spec_4_decides() {
    let mut b = Bench::new(|_| {});
    b.velocity(0, 0.3, 0.0);
    b.angles(0, &[0.0, 0.0]);
    assert_close(&b.exec(0), &[6.0, 6.0]);
    b.m.finish();
    assert_eq!(b.exec(1), vec![0.0, 0.0]);
    assert_eq!(b.m.status(), &MotorStatus::Finished);
    b.m.start();
    assert_close(&b.exec(2), &[6.0, 6.0]);
    // Stop: the target is zero (the PD law brakes the wheels) until Start.
    b.angles(10, &[0.02, 0.02]); // 2 rad/s
    b.m.stop();
    let t = b.exec(10);
    let want = 5.0 * (0.0 + 2.0) * 0.01 / 2.0 + 2.0 * (0.0 - 2.0);
    assert!((t[0] - want).abs() < 1e-12 && t[0] < 0.0, "{t:?} vs {want}");
    assert_eq!(b.m.status(), &MotorStatus::Stopped);
    b.velocity(11, 0.3, 0.0);
    assert!(b.exec(11)[0] < 0.0, "a new target does not release Stop");
    b.m.start();
    assert!(b.exec(12)[0] > 0.0);
    // Clear: held data dropped, waits for new input.
    b.m.clear();
    assert_eq!(b.exec(13), vec![0.0, 0.0]);
    assert_eq!(
        b.m.status(),
        &MotorStatus::WaitingForInput {
            wheel_angle: false,
            target_velocity: false
        }
    );
    assert_eq!(
        b.m.status().to_string(),
        "waiting for InCurrentWheelAngle and TargetVelocity"
    );
}

// ------------------------------------------------------------ parameters (002 §4.2)

#[test]
fn parameters_are_002_table_4_2_1() {
    let want: [(&str, f64, &str, Reflection); 13] = [
        ("PGainL", 5.0, "-", Reflection::Always),
        ("DGainL", 2.0, "-", Reflection::Always),
        ("PGainR", 5.0, "-", Reflection::Always),
        ("DGainR", 2.0, "-", Reflection::Always),
        ("SimulatedOffsetX", 0.0, "m", Reflection::OnActivation),
        ("SimulatedOffsetY", 0.0, "m", Reflection::OnActivation),
        ("SimulatedOffsetAngle", 0.0, "rad", Reflection::OnActivation),
        ("leftWheelID", 0.0, "-", Reflection::OnActivation),
        ("rightWheelID", 1.0, "-", Reflection::OnActivation),
        ("radiusOfLeftWheel", 0.1, "m", Reflection::OnActivation),
        ("radiusOfRightWheel", 0.1, "m", Reflection::OnActivation),
        ("lengthOfAxle", 0.441, "m", Reflection::OnActivation),
        ("radiusOfBodyArea", 0.45, "m", Reflection::OnActivation),
    ];
    let specs = MotorControlParams::SPECS;
    assert_eq!(specs.len(), want.len());
    for (s, (name, default, unit, refl)) in specs.iter().zip(want) {
        assert_eq!(
            (s.name, s.default, s.unit, s.reflection),
            (name, default, unit, refl)
        );
    }
    let mut m = MotorControl::default();
    let cfg = m.configuration().unwrap();
    assert!(cfg.set("PGainL", -0.1).is_err(), "gains are 0.0以上");
    assert!(cfg.set("leftWheelID", 0.5).is_err(), "an int");
    assert!(cfg.set("lengthOfAxle", 0.0).is_err());
    assert!(cfg.set("lengthOfAxle", 0.5).is_ok());
}

/// MotorControl alone in a 1 kHz execution context.
fn in_context(m: MotorControl) -> (ExecutionContext, usize) {
    let mut ec = ExecutionContext::new(1000.0).unwrap();
    let id = ec.attach(Box::new(m), 1000.0).unwrap();
    ec.start().unwrap();
    (ec, id)
}

#[test]
fn an_on_activation_parameter_changed_while_active_waits_for_reactivation() {
    let mut m = MotorControl::default();
    m.set_pd_gain(0.0, 0.0, 1.0, 1.0).unwrap();
    let mut vel = OutPort::new("v");
    let mut ang = OutPort::new("a");
    vel.connect(&m.target_velocity);
    ang.connect(&m.in_current_wheel_angle);
    let (mut ec, id) = in_context(m);
    ec.activate(id).unwrap();
    let feed = |ec: &mut ExecutionContext,
                vel: &mut OutPort<TimedVelocity>,
                ang: &mut OutPort<TimedDoubleSeq>| {
        let tm = Time::from_nanos(ec.time_ns());
        vel.write(TimedVelocity {
            tm,
            vx: 0.2,
            w: 0.0,
            ..TimedVelocity::default()
        });
        ang.write(TimedDoubleSeq {
            tm,
            data: vec![0.0, 0.0],
        });
        ec.tick();
        ec.component::<MotorControl>(id).unwrap().last_torque()
    };
    assert_eq!(feed(&mut ec, &mut vel, &mut ang), [2.0, 2.0]); // 0.2 / 0.1
    let cfg = ec.component_dyn_mut(id).unwrap().configuration().unwrap();
    cfg.set("radiusOfLeftWheel", 0.2).unwrap();
    cfg.set("SimulatedOffsetY", 0.045795).unwrap();
    assert!(cfg.is_pending("radiusOfLeftWheel").unwrap());
    assert_eq!(cfg.effective_value("radiusOfLeftWheel").unwrap(), 0.1);
    ec.run_ticks(3);
    let t = feed(&mut ec, &mut vel, &mut ang);
    assert_eq!(t, [2.0, 2.0], "locked while Active");
    let g = *ec.component::<MotorControl>(id).unwrap().geometry();
    assert_eq!((g.drive.radius_left(), g.frame.offset_y), (0.1, 0.0));
    ec.deactivate(id).unwrap();
    ec.activate(id).unwrap();
    let t = feed(&mut ec, &mut vel, &mut ang);
    assert_eq!(t, [1.0, 2.0], "r_L = 0.2 after re-activation");
    let g = *ec.component::<MotorControl>(id).unwrap().geometry();
    assert_eq!((g.drive.radius_left(), g.frame.offset_y), (0.2, 0.045795));
}

#[test]
fn equal_wheel_ids_fail_the_activation_with_a_reason() {
    let mut m = MotorControl::default();
    m.config_mut().set("rightWheelID", 0.0).unwrap();
    let (mut ec, id) = in_context(m);
    assert_eq!(ec.activate(id).unwrap(), LifecycleState::Error);
    let reason = ec.last_error(id).unwrap().unwrap().to_string();
    assert!(
        reason.contains("leftWheelID and rightWheelID are both 0"),
        "{reason}"
    );
}

#[test]
fn wheel_ids_select_joints_in_angles_and_torque() {
    let mut b = Bench::new(|m| {
        m.set_pd_gain(0.0, 0.0, 1.0, 1.0).unwrap();
        m.config_mut().set("leftWheelID", 2.0).unwrap();
        m.config_mut().set("rightWheelID", 0.0).unwrap();
    });
    b.velocity(0, 0.0, 1.0);
    b.angles(0, &[0.0, 9.0, 0.0]);
    b.exec(0);
    b.angles(10, &[0.01, 9.0, 0.03]); // right 1 rad/s, left 3 rad/s
    let t = b.exec(10);
    assert_eq!(
        b.m.wheel_rates().map(|r| (r * 1e9).round() / 1e9),
        [3.0, 1.0]
    );
    assert_eq!(t.len(), 3);
    assert!((t[2] - (-2.205 - 3.0)).abs() < 1e-9 && (t[0] - (2.205 - 1.0)).abs() < 1e-9);
    assert_eq!(t[1], 0.0);
    // The passed-through angles are the input itself.
    assert_eq!(b.wheels_out.read().unwrap().data, vec![0.01, 9.0, 0.03]);
}

// ------------------------------------------------------------ simulated pose (002 §5.2.5.6)

/// The body transform of a model whose origin is at (xo, yo, zo) with yaw θo, row-major.
fn transform(xo: f64, yo: f64, zo: f64, theta_o: f64) -> Vec<f64> {
    let (s, c) = (theta_o.sin(), theta_o.cos());
    vec![xo, yo, zo, c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0]
}

/// 002's RH0 offset angle as the seed writes it (deliberately not π/2).
#[allow(clippy::approx_constant)]
const RH0_OFFSET_ANGLE: f64 = 1.5708;

#[test]
fn simulated_pose_conversion_reproduces_the_rh0_example_in_all_four_quadrants() {
    // 002 §4.2 [*1][*2]: RH0's axle centre is 0.045795 m along the model's Y axis, and the
    // model's 0 rad is the Y axis: SimulatedOffsetY 0.045795, SimulatedOffsetAngle 1.5708.
    let mut b = Bench::new(|m| {
        m.config_mut().set("SimulatedOffsetY", 0.045795).unwrap();
        m.config_mut()
            .set("SimulatedOffsetAngle", RH0_OFFSET_ANGLE)
            .unwrap();
    });
    let mut quadrants = [false; 4];
    for (k, theta_o) in [0.4, 1.2, 2.0, 3.0, -3.0, -2.2, -1.1, -0.3, 0.0, PI / 2.0]
        .into_iter()
        .enumerate()
    {
        let (xo, yo, zo) = (1.5 - k as f64, -0.75 + 0.5 * k as f64, 0.1);
        b.pos.write(TimedDoubleSeq {
            tm: Time::from_nanos(k as u64 * MS),
            data: transform(xo, yo, zo, theta_o),
        });
        b.exec(k as u64);
        // By hand: Len = 0.045795, φ = π/2, so X = Xo − Len·sin θo, Y = Yo + Len·cos θo.
        let x = xo - 0.045795 * theta_o.sin();
        let y = yo + 0.045795 * theta_o.cos();
        let mut th = theta_o + RH0_OFFSET_ANGLE;
        if th > PI {
            th -= 2.0 * PI;
        }
        let out = b.loc.read().unwrap();
        assert_eq!(out.tm, Time::from_nanos(k as u64 * MS));
        assert_eq!(out.data.len(), 4);
        for (got, want) in out.data.iter().zip([x, y, zo, th]) {
            assert!(
                (got - want).abs() < 1e-9,
                "θo {theta_o}: {:?} vs {:?}",
                out.data,
                [x, y, zo, th]
            );
        }
        assert_eq!(
            b.gui.read().unwrap(),
            out,
            "GUI and Localization get the same pose"
        );
        if theta_o != 0.0 && (theta_o.abs() - PI / 2.0).abs() > 1e-9 {
            quadrants[match (theta_o.cos() > 0.0, theta_o.sin() > 0.0) {
                (true, true) => 0,
                (false, true) => 1,
                (false, false) => 2,
                (true, false) => 3,
            }] = true;
        }
        // The seed's −atan(A12/A11) loses the quadrant where cos θo < 0; atan2 does not.
        let seed = -((-theta_o.sin()) / theta_o.cos()).atan();
        if theta_o.cos() < 0.0 {
            assert!((seed - theta_o).abs() > 3.0);
        }
    }
    assert_eq!(quadrants, [true; 4]);
    // The torque path is independent of the pose input.
    assert_eq!(b.m.last_error(), None);
}

// ------------------------------------------------------------ safe stop (spec §4 Decision)

/// A bench running at 3 rad/s target with valid input up to `ms` = 10.
fn running() -> Bench {
    let mut b = Bench::new(|_| {});
    b.velocity(0, 0.3, 0.0);
    b.angles(0, &[0.0, 0.0]);
    b.exec(0);
    b.angles(10, &[0.01, 0.01]);
    assert!(b.exec(10)[0] > 0.0);
    b
}

fn assert_safe_stop(b: &mut Bench, ms: u64, check: impl Fn(&MotionError) -> bool) {
    assert_eq!(b.exec(ms), vec![0.0, 0.0], "zero torque");
    match b.m.status() {
        MotorStatus::SafeStop(e) => assert!(check(e), "{e:?}"),
        s => panic!("status {s:?}"),
    }
    assert!(check(b.m.last_error().unwrap()));
    assert!(
        b.m.status()
            .to_string()
            .starts_with("safe stop, zero torque: ")
    );
}

#[test]
fn non_finite_velocities_give_zero_torque_and_a_reason() {
    for (vx, w, field) in [
        (f64::NAN, 0.0, "vx"),
        (0.3, f64::INFINITY, "w"),
        (f64::NEG_INFINITY, 0.0, "vx"),
        (0.0, f64::NAN, "w"),
    ] {
        let mut b = running();
        b.velocity(11, vx, w);
        assert_safe_stop(
            &mut b,
            11,
            |e| matches!(e, MotionError::NonFinite { port: "TargetVelocity", field: f, .. } if f == field),
        );
        b.angles(12, &[0.012, 0.012]);
        assert_eq!(
            b.exec(12),
            vec![0.0, 0.0],
            "stays stopped until a valid target"
        );
        b.velocity(13, 0.3, 0.0);
        assert!(b.exec(13)[0] > 0.0, "resumes");
        assert_eq!(b.m.status(), &MotorStatus::Running);
    }
    // vy is ignored (spec §4), even when it is not finite.
    let mut b = running();
    b.vel.write(TimedVelocity {
        tm: Time::from_nanos(11 * MS),
        vx: 0.3,
        vy: f64::NAN,
        ..TimedVelocity::default()
    });
    assert!(b.exec(11)[0] > 0.0);
}

#[test]
fn wrong_length_or_non_finite_wheel_angles_give_zero_torque_and_a_reason() {
    for data in [vec![], vec![0.1]] {
        let mut b = running();
        b.angles(11, &data);
        let len = data.len();
        assert_safe_stop(
            &mut b,
            11,
            |e| matches!(e, MotionError::WrongLength { port: "InCurrentWheelAngle", len: l, .. } if *l == len),
        );
        b.angles(12, &[0.012, 0.012]);
        assert!(b.exec(12)[0] > 0.0, "a valid sample resumes");
    }
    let mut b = running();
    b.angles(11, &[0.011, f64::NAN]);
    assert_safe_stop(
        &mut b,
        11,
        |e| matches!(e, MotionError::NonFinite { port: "InCurrentWheelAngle", field, .. } if field == "data[1]"),
    );
    // The bad sample was not passed through.
    assert_eq!(b.wheels_out.read().unwrap().data, vec![0.01, 0.01]);
}

#[test]
fn time_going_backwards_gives_zero_torque_and_a_reason() {
    let mut b = running();
    b.angles(5, &[0.011, 0.011]);
    assert_safe_stop(&mut b, 11, |e| {
        matches!(e, MotionError::TimeWentBackwards { port: "InCurrentWheelAngle", previous_s, now_s }
            if *previous_s == 0.01 && *now_s == 0.005)
    });
    b.angles(10, &[0.011, 0.011]);
    assert_safe_stop(&mut b, 12, |e| {
        matches!(e, MotionError::TimeWentBackwards { .. })
    });
    b.angles(13, &[0.013, 0.013]);
    b.velocity(13, 0.3, 0.0);
    assert!(b.exec(13)[0] > 0.0);
    assert_eq!(
        b.m.wheel_rates().map(|r| (r * 1e9).round() / 1e9),
        [1.0, 1.0]
    );
    b.velocity(12, 0.3, 0.0);
    assert_safe_stop(&mut b, 14, |e| {
        matches!(
            e,
            MotionError::TimeWentBackwards {
                port: "TargetVelocity",
                ..
            }
        )
    });
}

#[test]
fn half_a_second_without_a_new_target_velocity_is_a_safe_stop() {
    let mut b = running();
    // The last target velocity arrived at tick 0 ms; wheel angles keep coming.
    let mut t = 0.0;
    for ms in 11..500 {
        b.angles(ms, &[0.001 * ms as f64, 0.001 * ms as f64]);
        t = b.exec(ms)[0];
    }
    assert!(t != 0.0, "499 ms: still running");
    b.angles(500, &[0.5, 0.5]);
    assert_safe_stop(&mut b, 500, |e| {
        matches!(e, MotionError::Stale { port: "TargetVelocity", age_s, limit_s }
            if *age_s == 0.5 && *limit_s == INPUT_TIMEOUT_NS as f64 * 1e-9)
    });
    b.velocity(501, 0.3, 0.0);
    b.angles(501, &[0.501, 0.501]);
    assert!(b.exec(501)[0] != 0.0);
    // Wheel angles that stop coming are stale too.
    for ms in 502..1001 {
        b.velocity(ms, 0.3, 0.0);
        b.exec(ms);
    }
    b.velocity(1001, 0.3, 0.0);
    assert_safe_stop(&mut b, 1001, |e| {
        matches!(
            e,
            MotionError::Stale {
                port: "InCurrentWheelAngle",
                ..
            }
        )
    });
}

#[test]
fn a_bad_simulated_pose_is_reported_and_does_not_stop_the_wheels() {
    let mut b = running();
    b.pos.write(TimedDoubleSeq {
        tm: Time::from_nanos(11 * MS),
        data: vec![0.0; 11],
    });
    b.angles(11, &[0.011, 0.011]);
    assert!(b.exec(11)[0] > 0.0);
    assert!(matches!(
        b.m.last_error(),
        Some(MotionError::WrongLength {
            port: "InSimulatedPosition",
            len: 11,
            ..
        })
    ));
    assert!(!b.loc.is_new() && !b.gui.is_new());
    let mut data = transform(0.0, 0.0, 0.0, 0.0);
    data[4] = f64::NAN;
    b.pos.write(TimedDoubleSeq {
        tm: Time::from_nanos(12 * MS),
        data,
    });
    b.exec(12);
    assert!(matches!(
        b.m.last_error(),
        Some(MotionError::NonFinite { .. })
    ));
}

#[test]
fn deactivation_sends_zero_torque() {
    let mut b = running();
    b.m.on_deactivated(&tick(20)).unwrap();
    assert_eq!(b.torque.read().unwrap().data, vec![0.0, 0.0]);
    assert_eq!(b.m.status(), &MotorStatus::Inactive);
    // Re-activation starts from nothing (002 §5.2.3 (1)).
    b.activate(30);
    assert_eq!(b.exec(30), vec![0.0, 0.0]);
    assert!(matches!(b.m.status(), MotorStatus::WaitingForInput { .. }));
}

// ------------------------------------------------------------ nothing panics

mod garbage {
    use super::*;
    use proptest::prelude::*;

    fn value() -> impl Strategy<Value = f64> {
        prop_oneof![
            -20.0..20.0f64,
            Just(f64::NAN),
            Just(f64::INFINITY),
            Just(f64::NEG_INFINITY),
            Just(1e308),
            Just(-1e308),
            Just(0.0),
        ]
    }

    /// One tick's input: maybe a velocity, maybe wheel angles, maybe a pose, each with a
    /// timestamp that may go backwards.
    type Step = (
        Option<(u64, f64, f64)>,
        Option<(u64, Vec<f64>)>,
        Option<(u64, Vec<f64>)>,
    );

    fn step() -> impl Strategy<Value = Step> {
        (
            proptest::option::of((0..2000u64, value(), value())),
            proptest::option::of((0..2000u64, proptest::collection::vec(value(), 0..4))),
            proptest::option::of((0..2000u64, proptest::collection::vec(value(), 10..13))),
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]
        #[test]
        fn any_input_gives_finite_torque_and_never_fails(steps in proptest::collection::vec(step(), 1..60)) {
            let mut b = Bench::new(|_| {});
            for (k, (vel, ang, pos)) in steps.into_iter().enumerate() {
                if let Some((t, vx, w)) = vel {
                    b.velocity(t, vx, w);
                }
                if let Some((t, data)) = ang {
                    b.angles(t, &data);
                }
                if let Some((t, data)) = pos {
                    b.pos.write(TimedDoubleSeq { tm: Time::from_nanos(t * MS), data });
                }
                let torque = b.exec(k as u64);
                prop_assert!(torque.iter().all(|x| x.is_finite()), "{torque:?}");
                if let MotorStatus::SafeStop(_) = b.m.status() {
                    prop_assert_eq!(torque, vec![0.0, 0.0]);
                }
            }
        }
    }
}
